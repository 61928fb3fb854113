#include "cut/mt/cut_guard.h"

#include <algorithm>
#include <array>
#include <span>
#include <string>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "cut/mt/time_critical_cutter.h"
#include "engine/predicates.h"
#include "engine/tet_adjacency.h"
#include "engine/tet_geometry.h"

namespace mtcut::cut {
namespace {

using engine::Mt;
using engine::VertId;

// The live tets around each vertex of the checked edges, at every
// resolution: one query per vertex, where a box query per edge and
// resolution cost nine in ten of a turning stroke's steps.
struct Stars {
  std::vector<std::int32_t> vertices;  // sorted
  std::vector<std::uint32_t> first;    // (vertices + 1) offsets into tets
  std::vector<TetId> tets;
  std::vector<std::uint8_t> levels;    // per entry of tets: 1 finest, 2 coarsest, 0 neither

  std::size_t index_of(std::int32_t v) const {
    return static_cast<std::size_t>(std::lower_bound(vertices.begin(), vertices.end(), v) - vertices.begin());
  }
};

Stars stars_of(const Mt& mt, const engine::TetBvh& bvh, std::vector<std::int32_t> vertices) {
  Stars out;
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  out.vertices = std::move(vertices);
  out.first.reserve(out.vertices.size() + 1);
  for (const std::int32_t value : out.vertices) {
    out.first.push_back(static_cast<std::uint32_t>(out.tets.size()));
    const VertId v(value);
    // A box query at the point, not for_each_containing: a tet's own corner
    // is a degenerate case for its exact inside test, and every tet here has v
    // as a corner.
    engine::Aabb at;
    at.extend(mt.position(v));
    bvh.for_each_overlapping(mt, at, [&](TetId t) {
      if (!mt.alive(t)) return true;
      const engine::Tet& corners = mt.tet(t);
      if (std::find(corners.begin(), corners.end(), v) == corners.end()) return true;
      out.tets.push_back(t);
      out.levels.push_back(
          static_cast<std::uint8_t>((mt.birth(t) == mt.root() ? 1 : 0) | (mt.death(t) == mt.drain() ? 2 : 0)));
      return true;
    });
  }
  out.first.push_back(static_cast<std::uint32_t>(out.tets.size()));
  return out;
}

// Faces around the edge (a, b) that no other tet of the resolution `level`
// shares: the third vertices that occur once. More than two: the boundary
// is pinched along the edge.
int boundary_faces_around(const Mt& mt, const Stars& stars, VertId a, VertId b, std::uint8_t level,
                          std::vector<std::int32_t>& thirds) {
  thirds.clear();
  const std::size_t star = stars.index_of(a.value);
  for (std::uint32_t k = stars.first[star]; k < stars.first[star + 1]; ++k) {
    if (!(stars.levels[k] & level)) continue;
    const engine::Tet& v = mt.tet(stars.tets[k]);
    if (std::find(v.begin(), v.end(), b) == v.end()) continue;
    for (VertId x : v)
      if (x != a && x != b) thirds.push_back(x.value);
  }
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

// A fragment whose tets (those it creates) hold more than two faces of the
// object's surface around the edge (a, b), or none. Every frontier that
// holds them (one does: the fragment applied and none after it) has the
// edge on more than two surface faces, two wedges of tissue joined along
// it, whichever fragments hold the rest of the tets around it: the
// resolutions between the finest and the coarsest, as a mixed-resolution
// frontier shows them.
FragId pinching_fragment(const Mt& mt, const Stars& stars, VertId a, VertId b,
                         std::vector<std::pair<std::int32_t, int>>& faces) {
  faces.clear();  // (fragment, surface faces around the edge in one of its tets)
  const std::size_t star = stars.index_of(a.value);
  for (std::uint32_t k = stars.first[star]; k < stars.first[star + 1]; ++k) {
    const TetId t = stars.tets[k];
    const engine::Tet& v = mt.tet(t);
    if (std::find(v.begin(), v.end(), b) == v.end()) continue;
    int on_surface = 0;  // the faces through a and b are those opposite the other two corners
    for (int c = 0; c < 4; ++c)
      if (v[c] != a && v[c] != b && (mt.boundary_mask(t) & (1u << c))) ++on_surface;
    if (on_surface > 0) faces.emplace_back(mt.birth(t).value, on_surface);
  }
  std::sort(faces.begin(), faces.end());
  for (std::size_t i = 0; i < faces.size();) {
    int sum = 0;
    std::size_t j = i;
    for (; j < faces.size() && faces[j].first == faces[i].first; ++j) sum += faces[j].second;
    if (sum > 2) return FragId(faces[i].first);
    i = j;
  }
  return FragId();
}

// fragments_out_of_balance, with the cut's decomposed fragments (sorted)
// given: the sum, per fragment, of its changed tets' unmasked faces with
// their orientation's sign (+ pieces, - killed tets; created side minus
// replaced).
std::vector<FragId> out_of_balance(const Mt& mt, const MtChangeReport& cut, std::span<const FragId> skip) {
  // (fragment, the face's ascending ids) -> coefficient
  absl::flat_hash_map<std::array<std::int32_t, 4>, int> sums;
  sums.reserve(16 * cut.replaced.size());
  const auto add = [&](const engine::Tet& v, engine::FaceMask mask, FragId birth, FragId death, int sign) {
    for (int f = 0; f < 4; ++f) {
      if (mask & (1u << f)) continue;
      const std::array<VertId, 3> outward = engine::face_vertices(v, f);
      std::array<std::int32_t, 4> key{0, outward[0].value, outward[1].value, outward[2].value};
      // The orientation's sign: the parity of the sort.
      int parity = 1;
      for (int i = 1; i < 4; ++i)
        for (int j = 1; j < 4 - i; ++j)
          if (key[j] > key[j + 1]) {
            std::swap(key[j], key[j + 1]);
            parity = -parity;
          }
      for (const auto& [fragment, side] : {std::pair{birth, 1}, std::pair{death, -1}})
        if (fragment.valid() && fragment != mt.root() && fragment != mt.drain() &&
            !std::binary_search(skip.begin(), skip.end(), fragment)) {
          key[0] = fragment.value;
          sums[key] += sign * side * parity;
        }
    }
  };
  for (const TetReplacement& r : cut.replaced) {
    // A killed tet's fragments are the replacement's; its pieces were born
    // and died in the same ones (only a decomposition, skipped, moves them).
    add(mt.tet(r.old), mt.boundary_mask(r.old), r.birth, r.death, -1);
    for (std::uint32_t i = r.first; i < r.first + r.count; ++i) {
      const TetId t = cut.made_tets[i];
      add(mt.tet(t), mt.boundary_mask(t), r.birth, r.death, 1);
    }
  }
  std::vector<FragId> out;
  for (const auto& [key, sum] : sums)
    if (sum != 0) out.push_back(FragId(key[0]));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

std::vector<FragId> decomposed_fragments(const MtChangeReport& cut) {
  std::vector<FragId> out;
  for (const FragmentSplit& s : cut.fragment_splits) {
    out.push_back(s.old);
    out.insert(out.end(), s.parts.begin(), s.parts.end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<FragId> fragments_out_of_balance(const Mt& mt, const MtChangeReport& cut) {
  return out_of_balance(mt, cut, decomposed_fragments(cut));
}

engine::ValidationReport check_cut(const Mt& mt, const engine::TetBvh& bvh, const MtChangeReport& cut,
                                   std::size_t first_cut_vertex, std::size_t first_new_vertex, const PartRecord* part,
                                   bool fragments_valid) {
  engine::ValidationReport report;
  const auto earlier = [&](VertId v) {
    return v.index() >= first_cut_vertex && v.index() < first_new_vertex && !(part && part->made(v));
  };
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
  // Every fragment the cut changed still replaces the same region: where
  // the new crack meets an old one it may bend differently in a fragment's
  // two tessellations. When every fragment was valid before the cut, a
  // fragment it did not decompose is checked by what it changed there
  // (fragments_out_of_balance). A part's commits leave fragments invalid
  // until its front or end is cut (a commit splits the finer tets of a
  // fragment that the polygon crosses completely, the coarser ones only
  // the front or the end do: part_record.h). So there, and where the cut
  // decomposed a fragment (its parts did not exist before), the fragments
  // where the new crack meets an old one (they hold a piece of an earlier
  // cut that this one split or relabelled) are checked whole, with their
  // parts.
  const std::vector<FragId> decomposed = decomposed_fragments(cut);
  if (fragments_valid)
    for (FragId f : out_of_balance(mt, cut, decomposed))
      report.add("cut: fragment " + std::to_string(f.value) +
                 ": its tets do not fill the region of the tets it replaces");
  for (const TetReplacement& r : cut.replaced) {
    if (!mt.error_inherited(r.old) && r.count != 1) continue;
    for (FragId f : {r.birth, r.death})
      if (f.valid() && f != mt.root() && f != mt.drain() &&
          (!fragments_valid || std::binary_search(decomposed.begin(), decomposed.end(), f)))
        fragments.push_back(f);
  }
  fragments = map_fragment_set(fragments, cut.fragment_splits);
  for (FragId f : fragments)
    for (auto& problem : engine::validate_fragment(mt, f).problems) report.add("cut: " + problem);
  std::vector<std::int32_t> thirds;
  std::vector<std::pair<std::int32_t, int>> faces;
  std::vector<std::int32_t> ends;
  ends.reserve(2 * edges.size());
  for (const auto& [a, b] : edges) ends.push_back(a);  // the star of a holds every tet of the edge
  const Stars stars = stars_of(mt, bvh, std::move(ends));
  for (const auto& [a, b] : edges) {
    for (const auto& [name, boundary] :
         {std::pair<const char*, int>{"finest", boundary_faces_around(mt, stars, VertId(a), VertId(b), 1, thirds)},
          {"coarsest", boundary_faces_around(mt, stars, VertId(a), VertId(b), 2, thirds)}})
      if (boundary > 2)
        report.add(std::string("cut: the ") + name + " resolution's boundary is pinched along edge (" +
                   std::to_string(a) + ", " + std::to_string(b) + ")");
    if (const FragId f = pinching_fragment(mt, stars, VertId(a), VertId(b), faces); f.valid())
      report.add("cut: fragment " + std::to_string(f.value) + "'s tets pinch the boundary along edge (" +
                 std::to_string(a) + ", " + std::to_string(b) + ")");
  }
  return report;
}

}  // namespace mtcut::cut
