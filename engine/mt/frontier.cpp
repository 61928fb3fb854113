#include "engine/mt/frontier.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cassert>
#include <cmath>
#include <string>

#include "engine/tet_adjacency.h"
#include "engine/tet_geometry.h"

namespace mtcut::engine {
namespace {

// Versions are unique across all frontiers, so that a version names one
// state of one frontier (a copy shares it only while it is identical).
std::uint64_t next_version() {
  static std::atomic<std::uint64_t> counter{0};
  return ++counter;
}

}  // namespace

Frontier Frontier::finest(const Mt& mt) {
  const FragId root = mt.root();
  return from_fragments(mt, std::span<const FragId>(&root, 1));
}

Frontier Frontier::coarsest(const Mt& mt) {
  std::vector<FragId> all;
  all.reserve(mt.num_fragments());
  for (std::size_t f = 0; f < mt.num_fragments(); ++f)
    if (FragId(f) != mt.drain()) all.emplace_back(f);
  return from_fragments(mt, all);
}

Frontier Frontier::from_fragments(const Mt& mt, std::span<const FragId> fragments) {
  Frontier frontier;
  frontier.sync(mt);
  for (FragId f : fragments)
    if (!frontier.in_set_.contains(f)) frontier.in_set_.insert(f);
  for (FragId f : frontier.in_set_.members())
    for (TetId t : mt.created(f))
      if (!mt.death(t).valid() || !frontier.in_set_.contains(mt.death(t))) frontier.add_tet(mt, t);
  frontier.version_ = next_version();
  return frontier;
}

void Frontier::sync(const Mt& mt) {
  in_set_.grow(mt.num_fragments());
  visible_.grow(mt.num_fragments());
  tets_.grow(mt.num_tets());
  verts_.grow(mt.num_vertices());
  vert_uses_.resize(std::max(vert_uses_.size(), mt.num_vertices()), 0);
  frag_uses_.resize(std::max(frag_uses_.size(), mt.num_fragments()), 0);
  if (counted_in_.size() < mt.num_tets()) counted_in_.resize(mt.num_tets());
}

void Frontier::follow_edit(const Mt& mt, std::span<const FragId> joined, std::span<const TetId> changed_tets,
                           std::span<const FragId> regrouped) {
  sync(mt);
  for (FragId f : joined)
    if (!in_set_.contains(f)) in_set_.insert(f);
  for (TetId t : changed_tets) {
    const bool wanted = mt.alive(t) && in_set_.contains(mt.birth(t)) &&
                        !(mt.death(t).valid() && in_set_.contains(mt.death(t)));
    if (wanted && !tets_.contains(t))
      add_tet(mt, t);
    else if (!wanted && tets_.contains(t))
      remove_tet(mt, t);
  }
  for (FragId f : regrouped) {
    if (!f.valid()) continue;
    std::int32_t uses = 0;
    for (TetId t : mt.created(f)) {
      if (!tets_.contains(t)) continue;
      counted_in_[t.index()] = f;
      ++uses;
    }
    frag_uses_[f.index()] = uses;
    if (uses > 0 && !visible_.contains(f)) visible_.insert(f);
    if (uses == 0 && visible_.contains(f)) visible_.erase(f);
  }
  version_ = next_version();
}

void Frontier::add_tet(const Mt& mt, TetId t) {
  tets_.insert(t);
  for (VertId v : mt.tet(t))
    if (vert_uses_[v.index()]++ == 0) verts_.insert(v);
  const FragId b = mt.birth(t);
  counted_in_[t.index()] = b;
  if (frag_uses_[b.index()]++ == 0) visible_.insert(b);
}

void Frontier::remove_tet(const Mt& mt, TetId t) {
  tets_.erase(t);
  for (VertId v : mt.tet(t))
    if (--vert_uses_[v.index()] == 0) verts_.erase(v);
  const FragId b = counted_in_[t.index()];
  if (--frag_uses_[b.index()] == 0) visible_.erase(b);
}

bool Frontier::can_coarsen(const Mt& mt, FragId f) const {
  if (!f.valid() || f.index() >= mt.num_fragments() || contains(f) || f == mt.drain() || f == mt.root()) return false;
  if (mt.replaced(f).empty()) return false;
  for (TetId t : mt.replaced(f))
    if (!contains(mt.birth(t))) return false;
  return true;
}

bool Frontier::can_refine(const Mt& mt, FragId f) const {
  if (!f.valid() || !contains(f) || f == mt.root()) return false;
  for (TetId t : mt.created(f))
    if (mt.death(t).valid() && contains(mt.death(t))) return false;
  return true;
}

void Frontier::coarsen(const Mt& mt, FragId f) {
  assert(can_coarsen(mt, f));
  for (TetId t : mt.replaced(f)) remove_tet(mt, t);
  in_set_.insert(f);
  for (TetId t : mt.created(f)) add_tet(mt, t);
  version_ = next_version();
}

void Frontier::refine(const Mt& mt, FragId f) {
  assert(can_refine(mt, f));
  for (TetId t : mt.created(f)) remove_tet(mt, t);
  in_set_.erase(f);
  for (TetId t : mt.replaced(f)) add_tet(mt, t);
  version_ = next_version();
}

std::vector<FragId> Frontier::coarsenable(const Mt& mt) const {
  // A fragment that can be added replaces only mesh tets: it is the death
  // of at least one of them.
  std::vector<FragId> out;
  for (TetId t : tets()) {
    const FragId d = mt.death(t);
    if (d.valid() && can_coarsen(mt, d)) out.push_back(d);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<FragId> Frontier::refinable(const Mt& mt) const {
  // A fragment that can be removed has all its created tets in the mesh, so
  // it is visible (unless it creates nothing).
  std::vector<FragId> out;
  for (FragId f : fragments())
    if (can_refine(mt, f)) out.push_back(f);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::array<VertId, 3>> Frontier::boundary_faces(const Mt& mt) const {
  std::vector<std::array<VertId, 3>> faces;
  for (TetId t : tets()) {
    const FaceMask mask = mt.boundary_mask(t);
    if (mask == 0) continue;
    for (int f = 0; f < 4; ++f)
      if (mask & (1u << f)) faces.push_back(face_vertices(mt.tet(t), f));
  }
  return faces;
}

double Frontier::volume(const Mt& mt) const {
  double sum = 0.0;
  for (TetId t : tets()) sum += mt.volume(t);
  return sum;
}

TetMesh Frontier::to_tet_mesh(const Mt& mt, std::vector<VertId>* vertex_ids) const {
  TetMesh mesh;
  std::vector<VertId> ids(vertices().begin(), vertices().end());
  std::sort(ids.begin(), ids.end());
  std::vector<std::int32_t> local(mt.num_vertices(), -1);
  mesh.positions.reserve(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) {
    local[ids[i].index()] = static_cast<std::int32_t>(i);
    mesh.positions.push_back(mt.position(ids[i]));
  }
  std::vector<TetId> order(tets().begin(), tets().end());
  std::sort(order.begin(), order.end());
  mesh.tets.reserve(order.size());
  for (TetId t : order) {
    Tet tet;
    for (int k = 0; k < 4; ++k) tet[k] = VertId(local[mt.tet(t)[k].index()]);
    mesh.tets.push_back(tet);
  }
  if (vertex_ids) *vertex_ids = std::move(ids);
  return mesh;
}

std::size_t Frontier::bytes() const {
  return in_set_.bytes() + tets_.bytes() + verts_.bytes() + visible_.bytes() +
         vert_uses_.capacity() * sizeof(std::int32_t) + frag_uses_.capacity() * sizeof(std::int32_t) +
         counted_in_.capacity() * sizeof(FragId);
}

ValidationReport validate_frontier(const Mt& mt, const Frontier& frontier) {
  ValidationReport report;
  const auto name = [](auto id) { return std::to_string(id.value); };
  if (!frontier.contains(mt.root())) report.add("frontier: the root is not in the fragment set");
  if (mt.drain().valid() && frontier.contains(mt.drain())) report.add("frontier: the drain is in the fragment set");
  for (FragId f : frontier.fragments()) {
    if (f.index() >= mt.num_fragments()) {
      report.add("frontier: fragment " + name(f) + " does not exist");
      return report;
    }
    for (TetId t : mt.replaced(f))
      if (!frontier.contains(mt.birth(t)))
        report.add("frontier: fragment " + name(f) + " is in the set but its parent " + name(mt.birth(t)) + " is not");
  }

  // The mesh is exactly what S defines.
  std::size_t expected = 0;
  std::vector<std::int32_t> uses(mt.num_vertices(), 0);
  std::vector<TetId> tets;  // the mesh's, by id
  tets.reserve(frontier.tets().size());
  for (std::size_t i = 0; i < mt.num_tets(); ++i) {
    const TetId t(i);
    const bool in_mesh = mt.alive(t) && frontier.contains(mt.birth(t)) &&
                         !(mt.death(t).valid() && frontier.contains(mt.death(t)));
    if (in_mesh) {
      ++expected;
      for (VertId v : mt.tet(t)) ++uses[v.index()];
    }
    if (frontier.has_tet(t)) tets.push_back(t);
    if (in_mesh != frontier.has_tet(t))
      report.add("frontier: tet " + name(t) + (in_mesh ? " is missing from the mesh" : " is in the mesh but should not be"));
  }
  if (expected != frontier.tets().size())
    report.add("frontier: " + std::to_string(frontier.tets().size()) + " tets listed, " + std::to_string(expected) +
               " expected");
  std::vector<char> listed(mt.num_vertices(), 0);
  for (VertId v : frontier.vertices()) {
    if (v.index() >= listed.size() || listed[v.index()]) {
      report.add("frontier: vertex " + name(v) + " listed twice or out of range");
      return report;
    }
    listed[v.index()] = 1;
  }
  for (std::size_t v = 0; v < uses.size(); ++v)
    if ((uses[v] > 0) != (listed[v] != 0))
      report.add("frontier: vertex " + std::to_string(v) + (listed[v] ? " is listed but unused" : " is used but not listed"));
  for (TetId t : frontier.tets())
    if (!frontier.is_visible(mt.birth(t))) report.add("frontier: fragment " + name(mt.birth(t)) + " is not listed visible");
  std::vector<std::int32_t> shown(mt.num_fragments(), 0);
  for (TetId t : frontier.tets()) ++shown[mt.birth(t).index()];
  for (std::size_t f = 0; f < shown.size(); ++f)
    if (frontier.shown_tets(FragId(f)) != shown[f])
      report.add("frontier: fragment " + std::to_string(f) + " is counted with " +
                 std::to_string(frontier.shown_tets(FragId(f))) + " tets of the mesh, it has " +
                 std::to_string(shown[f]));
  for (FragId f : frontier.visible_fragments()) {
    const auto created = mt.created(f);
    if (std::none_of(created.begin(), created.end(), [&](TetId t) { return frontier.has_tet(t); }))
      report.add("frontier: fragment " + name(f) + " is listed visible but no tet of it is shown");
  }
  if (!report.ok()) return report;

  // A conforming tessellation: the TetMesh checks, then surface marks, then volume.
  // The mesh's tet i is the frontier's i-th tet by id (to_tet_mesh), with
  // its vertices in the same order: one adjacency serves the mesh's checks
  // and the faces without a neighbour.
  const TetMesh mesh = frontier.to_tet_mesh(mt);
  const TetAdjacency adjacency = build_adjacency(mesh);
  for (const auto& problem : mesh.validate(adjacency).problems) report.add("frontier mesh: " + problem);
  for (const BoundaryFace& face : adjacency.boundary) {
    const TetId t = tets[face.tet.index()];
    if (!(mt.boundary_mask(t) & (1u << face.local_face)))
      report.add("frontier: face " + std::to_string(face.local_face) + " of tet " + name(t) +
                 " has no neighbour but is not on the surface (a hanging face)");
  }
  std::size_t marked = 0;
  for (TetId t : tets) marked += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(mt.boundary_mask(t))));
  if (marked != adjacency.boundary.size())
    report.add("frontier: " + std::to_string(marked) + " faces marked as surface, " +
               std::to_string(adjacency.boundary.size()) + " without a neighbour");

  double expected_volume = mt.fine_volume();
  if (!mt.boundary_preserved()) {
    for (FragId f : frontier.fragments()) {
      if (f == mt.root()) continue;
      for (TetId t : mt.created(f)) expected_volume += mt.volume(t);
      for (TetId t : mt.replaced(f)) expected_volume -= mt.volume(t);
    }
  }
  const double volume = frontier.volume(mt);
  if (!(std::abs(volume - expected_volume) <= 1e-9 * std::abs(expected_volume)))
    report.add("frontier: volume " + std::to_string(volume) + " differs from the domain's " +
               std::to_string(expected_volume) + " by more than 1e-9 relative");
  return report;
}

}  // namespace mtcut::engine
