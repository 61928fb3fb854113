// Mt::validate(): the structure, the DAG, every fragment, and the finest and
// coarsest frontiers. Run in tests after every mutation.

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/mt/frontier.h"
#include "engine/mt/mt.h"
#include "engine/mt/tet_error.h"

namespace mtcut::engine {
namespace {

std::string str(std::int32_t v) { return std::to_string(v); }

// Tets and lists agree; every live tet is positive and born before it dies.
void check_tets(const Mt& mt, ValidationReport& report) {
  const auto nf = static_cast<std::int32_t>(mt.num_fragments());
  const auto nv = static_cast<std::int32_t>(mt.num_vertices());
  std::size_t alive = 0;
  for (std::size_t i = 0; i < mt.num_tets(); ++i) {
    const TetId t(i);
    if (!mt.alive(t)) continue;
    ++alive;
    const std::string tn = "tet " + str(t.value);
    const FragId b = mt.birth(t), d = mt.death(t);
    if (b.value >= nf || d.value >= nf || !d.valid()) {
      report.add(tn + " has birth " + str(b.value) + " and death " + str(d.value) + " (" + str(nf) + " fragments)");
      continue;
    }
    if (b == d) report.add(tn + " is born and dies in fragment " + str(b.value));
    const Tet& v = mt.tet(t);
    bool ids_ok = true;
    for (VertId id : v) ids_ok = ids_ok && id.valid() && id.value < nv;
    if (!ids_ok) {
      report.add(tn + " refers to a vertex out of range");
      continue;
    }
    if (v[0] == v[1] || v[0] == v[2] || v[0] == v[3] || v[1] == v[2] || v[1] == v[3] || v[2] == v[3])
      report.add(tn + " repeats a vertex");
    const auto c = mt.corners(t);
    if (orient3d_sign(c[0], c[1], c[2], c[3]) <= 0) report.add(tn + " is not positively oriented");
    const float own = tet_error(c[0], c[1], c[2], c[3]);
    if (!mt.error_inherited(t) && mt.error(t) != own) report.add(tn + " has a stale error");
    // An inherited error is its split tet's: never below the piece's own
    // (up to the rounding of two enclosing-sphere computations).
    if (mt.error_inherited(t) && !(mt.error(t) >= own * (1 - 1e-6f)))
      report.add(tn + " has an inherited error below its own");
  }
  // Every live tet once in created(birth) and once in replaced(death), nothing else listed.
  std::vector<char> in_created(mt.num_tets(), 0), in_replaced(mt.num_tets(), 0);
  for (std::size_t f = 0; f < mt.num_fragments(); ++f) {
    for (TetId t : mt.created(FragId(f))) {
      if (t.index() >= mt.num_tets() || !mt.alive(t) || mt.birth(t) != FragId(f) || in_created[t.index()]++)
        report.add("created(" + std::to_string(f) + ") lists tet " + str(t.value) + " which it does not create");
    }
    for (TetId t : mt.replaced(FragId(f))) {
      if (t.index() >= mt.num_tets() || !mt.alive(t) || mt.death(t) != FragId(f) || in_replaced[t.index()]++)
        report.add("replaced(" + std::to_string(f) + ") lists tet " + str(t.value) + " which it does not replace");
    }
  }
  for (std::size_t i = 0; i < mt.num_tets(); ++i) {
    if (!mt.alive(TetId(i))) continue;
    if (!in_created[i]) report.add("tet " + std::to_string(i) + " is missing from created(" + str(mt.birth(TetId(i)).value) + ")");
    if (!in_replaced[i]) report.add("tet " + std::to_string(i) + " is missing from replaced(" + str(mt.death(TetId(i)).value) + ")");
  }
  if (alive != mt.num_live_tets())
    report.add(std::to_string(alive) + " live tets, " + std::to_string(mt.num_live_tets()) + " counted");
}

// One root, one drain, acyclic, every fragment on a path root -> drain.
void check_dag(const Mt& mt, ValidationReport& report) {
  const FragId root = mt.root(), drain = mt.drain();
  if (!root.valid() || root.index() >= mt.num_fragments() || !drain.valid() || drain.index() >= mt.num_fragments() ||
      root == drain) {
    report.add("the MT has no distinct root and drain (root " + str(root.value) + ", drain " + str(drain.value) + ")");
    return;
  }
  if (!mt.replaced(root).empty()) report.add("the root replaces tets");
  if (!mt.created(drain).empty()) report.add("the drain creates tets");
  for (std::size_t i = 0; i < mt.num_fragments(); ++i) {
    const FragId f(i);
    if (f != root && mt.replaced(f).empty())
      report.add("fragment " + str(f.value) + " replaces nothing (a second root)");
    if (f != drain && mt.created(f).empty())
      report.add("fragment " + str(f.value) + " creates nothing (a second drain)");
  }
  const std::vector<FragId> order = mt.topological_order();
  if (order.size() != mt.num_fragments())
    report.add(str(static_cast<std::int32_t>(mt.num_fragments() - order.size())) +
               " fragments are on a cycle or not reachable from the root");
}

void check_fragments(const Mt& mt, ValidationReport& report) {
  for (std::size_t i = 0; i < mt.num_fragments(); ++i)
    for (auto& problem : validate_fragment(mt, FragId(i)).problems) report.add(std::move(problem));
}

}  // namespace

ValidationReport validate_fragment(const Mt& mt, FragId f) {
  ValidationReport report;
  if (f == mt.root() || f == mt.drain()) return report;
  // The outer faces off the surface, each as its ids ascending and whether
  // its orientation is an odd permutation of them: two faces are the same
  // oriented face when both agree. outer_faces gives them in the order of
  // their ids, each once, so the lists compare as they are.
  const auto inner = [&](std::span<const TetId> tets) {
    std::vector<std::pair<std::array<VertId, 3>, bool>> faces;
    for (const OrientedFace& face : outer_faces(mt, tets))
      if (!(mt.boundary_mask(face.tet) & (1u << face.local_face))) {
        const auto& v = face.verts;
        const bool odd = ((v[0] > v[1]) + (v[0] > v[2]) + (v[1] > v[2])) % 2 != 0;
        faces.emplace_back(face.sorted, odd);
      }
    return faces;
  };
  if (inner(mt.created(f)) != inner(mt.replaced(f)))
    report.add("fragment " + str(f.value) + ": its tets do not fill the region of the tets it replaces");
  if (mt.boundary_preserved()) {
    double before = 0, after = 0;
    for (TetId t : mt.replaced(f)) before += mt.volume(t);
    for (TetId t : mt.created(f)) after += mt.volume(t);
    if (!(std::abs(after - before) <= 1e-9 * before))
      report.add("fragment " + str(f.value) + " changes the volume from " + std::to_string(before) + " to " +
                 std::to_string(after));
  }
  return report;
}

ValidationReport Mt::validate() const {
  ValidationReport report;
  check_tets(*this, report);
  if (!report.ok()) return report;
  // Each live tet's slots say where its fragments list it (kill_tet,
  // set_birth and move_groups find it there).
  for (std::size_t i = 0; i < num_tets(); ++i) {
    const TetId t(static_cast<std::int32_t>(i));
    if (!alive(t)) continue;
    const auto listed = [t](std::span<const TetId> list, std::int32_t slot) {
      return slot >= 0 && static_cast<std::size_t>(slot) < list.size() && list[static_cast<std::size_t>(slot)] == t;
    };
    if (!listed(created(birth(t)), tet_birth_slot_[i])) report.add("tet " + str(t.value) + " has a wrong birth slot");
    if (death(t).valid() ? !listed(replaced(death(t)), tet_death_slot_[i]) : tet_death_slot_[i] != -1)
      report.add("tet " + str(t.value) + " has a wrong death slot");
  }
  if (!report.ok()) return report;
  check_dag(*this, report);
  if (!report.ok()) return report;
  check_fragments(*this, report);
  for (const auto& problem : validate_frontier(*this, Frontier::finest(*this)).problems)
    report.add("finest " + problem);
  for (const auto& problem : validate_frontier(*this, Frontier::coarsest(*this)).problems)
    report.add("coarsest " + problem);
  return report;
}

}  // namespace mtcut::engine
