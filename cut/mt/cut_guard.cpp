#include "cut/mt/cut_guard.h"

#include <algorithm>
#include <string>
#include <vector>

#include "engine/predicates.h"
#include "engine/tet_geometry.h"

namespace mtcut::cut {
namespace {

using engine::Mt;
using engine::VertId;

// Faces around the edge (a, b) that no other tet of the resolution shares,
// among the live tets `in_resolution` accepts: the third vertices that
// occur once. More than two: the boundary is pinched along the edge.
template <class InResolution>
int boundary_faces_around(const Mt& mt, const engine::TetBvh& bvh, VertId a, VertId b, InResolution&& in_resolution,
                          std::vector<std::int32_t>& thirds) {
  thirds.clear();
  engine::Aabb box;
  box.extend(mt.position(a));
  box.extend(mt.position(b));
  bvh.for_each_overlapping(mt, box, [&](TetId t) {
    if (!in_resolution(t)) return true;
    const engine::Tet& v = mt.tet(t);
    if (std::find(v.begin(), v.end(), a) == v.end() || std::find(v.begin(), v.end(), b) == v.end()) return true;
    for (VertId x : v)
      if (x != a && x != b) thirds.push_back(x.value);
    return true;
  });
  std::sort(thirds.begin(), thirds.end());
  int once = 0;
  for (std::size_t i = 0; i < thirds.size();) {
    std::size_t j = i;
    while (j < thirds.size() && thirds[j] == thirds[i]) ++j;
    if (j - i == 1) ++once;
    if (j - i > 2) return 3;  // a face shared by three tets: as bad
    i = j;
  }
  return once;
}

}  // namespace

engine::ValidationReport check_cut(const Mt& mt, const engine::TetBvh& bvh, const MtChangeReport& cut,
                                   std::size_t first_cut_vertex, std::size_t first_new_vertex) {
  engine::ValidationReport report;
  const auto earlier = [&](VertId v) { return v.index() >= first_cut_vertex && v.index() < first_new_vertex; };
  const auto by_cuts = [&](VertId v) { return v.index() >= first_cut_vertex; };
  std::vector<std::pair<std::int32_t, std::int32_t>> edges;
  std::vector<FragId> fragments;
  const auto add_edges = [&](const engine::Tet& v, auto&& both) {
    for (const auto& e : engine::kTetEdges)
      if (both(v[e[0]]) && both(v[e[1]]))
        edges.emplace_back(std::min(v[e[0]].value, v[e[1]].value), std::max(v[e[0]].value, v[e[1]].value));
  };
  for (const TetReplacement& r : cut.replaced) {
    // A piece of an earlier cut split again: the new crack meets the old
    // one here, and any edge between cut vertices may be pinched.
    const bool meets_old_crack = mt.error_inherited(r.old);
    for (std::uint32_t i = r.first; i < r.first + r.count; ++i) {
      const TetId t = cut.made_tets[i];
      if (!mt.alive(t)) continue;
      const auto c = mt.corners(t);
      if (engine::orient3d_sign(c[0], c[1], c[2], c[3]) <= 0)
        report.add("cut: piece " + std::to_string(t.value) + " is not positively oriented");
      if (meets_old_crack) {
        add_edges(mt.tet(t), by_cuts);
      } else {
        add_edges(mt.tet(t), earlier);
      }
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  const auto finest = [&](TetId t) { return mt.alive(t) && mt.birth(t) == mt.root(); };
  const auto coarsest = [&](TetId t) { return mt.alive(t) && mt.death(t) == mt.drain(); };
  // Every fragment the cut processed (and the parts it made) still replaces
  // the same region: where two cracks meet, the cut may bend differently in
  // a fragment's two tessellations.
  fragments.assign(cut.processed.begin(), cut.processed.end());
  for (const FragmentSplit& split : cut.fragment_splits)
    fragments.insert(fragments.end(), split.parts.begin(), split.parts.end());
  std::sort(fragments.begin(), fragments.end());
  fragments.erase(std::unique(fragments.begin(), fragments.end()), fragments.end());
  for (FragId f : fragments)
    for (auto& problem : engine::validate_fragment(mt, f).problems) report.add("cut: " + problem);
  std::vector<std::int32_t> thirds;
  for (const auto& [a, b] : edges) {
    for (const auto& [name, boundary] :
         {std::pair<const char*, int>{"finest", boundary_faces_around(mt, bvh, VertId(a), VertId(b), finest, thirds)},
          {"coarsest", boundary_faces_around(mt, bvh, VertId(a), VertId(b), coarsest, thirds)}})
      if (boundary > 2)
        report.add(std::string("cut: the ") + name + " resolution's boundary is pinched along edge (" +
                   std::to_string(a) + ", " + std::to_string(b) + ")");
  }
  return report;
}

}  // namespace mtcut::cut
