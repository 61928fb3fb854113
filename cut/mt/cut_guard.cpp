#include "cut/mt/cut_guard.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "cut/mt/follow_cut.h"
#include "engine/predicates.h"
#include "engine/radix_sort.h"
#include "engine/tet_adjacency.h"
#include "engine/tet_geometry.h"

namespace mtcut::cut {
namespace {

using engine::Mt;
using engine::VertId;

// The live tets around each vertex of the checked edges, at every
// resolution. A vertex the cut made (from `first_new_vertex` on) is used by
// the cut's pieces only, so its star comes from them (one pass over them);
// an older one's from the index, one box query per group of neighbouring
// vertices (below): a query per edge and resolution, or per vertex, was
// most of a step where a part's front meets an older crack.
struct Stars {
  std::vector<std::int32_t> vertices;  // sorted
  std::vector<std::uint32_t> first;    // (vertices + 1) offsets into tets
  std::vector<TetId> tets;
  std::vector<std::uint8_t> levels;    // per entry of tets: 1 finest, 2 coarsest, 0 neither

  std::size_t index_of(std::int32_t v) const {
    return static_cast<std::size_t>(std::lower_bound(vertices.begin(), vertices.end(), v) - vertices.begin());
  }
};

Stars stars_of(const Mt& mt, const engine::TetBvh& bvh, std::span<const MtChangeReport* const> cuts,
               std::size_t first_new_vertex, std::vector<std::int32_t> vertices) {
  Stars out;
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  out.vertices = std::move(vertices);
  std::vector<std::pair<std::int32_t, TetId>> around;  // (vertex, tet)
  const auto first_new = std::lower_bound(out.vertices.begin(), out.vertices.end(),
                                          static_cast<std::int32_t>(first_new_vertex));
  if (first_new != out.vertices.end())
    for (const MtChangeReport* cut : cuts)
      for (TetId t : cut->made_tets) {
        if (!mt.alive(t)) continue;
        for (VertId v : mt.tet(t))
          if (v.value >= *first_new && std::binary_search(first_new, out.vertices.end(), v.value))
            around.emplace_back(v.value, t);
      }
  // Older vertices are queried in groups of neighbours (halving their set
  // along its box's longest axis down to kGroup), one box query per group:
  // each tet around a vertex has the vertex in its box, so the group's box
  // finds them all, and neighbours share most of the walk.
  std::vector<std::int32_t> older(out.vertices.begin(), first_new);
  constexpr std::size_t kGroup = 8;
  const auto group = [&](auto&& self, std::span<std::int32_t> g) -> void {
    engine::Aabb box;
    for (std::int32_t v : g) box.extend(mt.position(VertId(v)));
    if (g.size() > kGroup) {
      const Vec3 size = box.hi - box.lo;
      int axis = 0;
      for (int k = 1; k < 3; ++k)
        if (size[k] > size[axis]) axis = k;
      const auto mid = g.begin() + static_cast<std::ptrdiff_t>(g.size() / 2);
      std::nth_element(g.begin(), mid, g.end(), [&](std::int32_t a, std::int32_t b) {
        return mt.position(VertId(a))[axis] < mt.position(VertId(b))[axis];
      });
      self(self, g.first(g.size() / 2));
      self(self, g.subspan(g.size() / 2));
      return;
    }
    bvh.for_each_overlapping(mt, box, [&](TetId t) {
      if (!mt.alive(t)) return true;
      for (VertId c : mt.tet(t))
        if (std::find(g.begin(), g.end(), c.value) != g.end()) around.emplace_back(c.value, t);
      return true;
    });
  };
  if (!older.empty()) group(group, older);
  std::sort(around.begin(), around.end());
  out.first.assign(out.vertices.size() + 1, 0);
  out.tets.reserve(around.size());
  out.levels.reserve(around.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < out.vertices.size(); ++i) {
    out.first[i] = static_cast<std::uint32_t>(out.tets.size());
    for (; k < around.size() && around[k].first == out.vertices[i]; ++k) {
      const TetId t = around[k].second;
      out.tets.push_back(t);
      out.levels.push_back(
          static_cast<std::uint8_t>((mt.birth(t) == mt.root() ? 1 : 0) | (mt.death(t) == mt.drain() ? 2 : 0)));
    }
  }
  out.first.back() = static_cast<std::uint32_t>(out.tets.size());
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

// Edges (a, b) of vertex ids in ascending order: a radix sort on the two
// ids as one word, since a part's frame checks every edge between cut
// vertices of its front, each frame (a comparison sort was a quarter of
// the guard on a turning stroke).
void sort_edges(std::vector<std::pair<std::int32_t, std::int32_t>>& edges) {
  if (edges.size() < 2048) {
    std::sort(edges.begin(), edges.end());
    return;
  }
  std::vector<std::pair<std::int32_t, std::int32_t>> scratch;
  engine::radix_sort<1>(edges, scratch, [](const std::pair<std::int32_t, std::int32_t>& e) {
    return std::array<std::uint64_t, 1>{std::uint64_t{static_cast<std::uint32_t>(e.first)} << 32 |
                                        static_cast<std::uint32_t>(e.second)};
  });
}

}  // namespace

const FragmentLedger* ledger_checked(const PartRecord* part) {
  static const FragmentLedger kNothingOwed;
  return !part || part->num_owned() == 0 ? &kNothingOwed : part->met_old_crack() ? &part->owed() : nullptr;
}

engine::ValidationReport check_cut(const Mt& mt, const engine::TetBvh& bvh, const MtChangeReport& cut,
                                   std::size_t first_cut_vertex, std::size_t first_new_vertex, const PartRecord* part,
                                   CutSelect select, const FrameCommit* commit, const MtChangeReport* kept,
                                   const FragmentLedger* taken) {
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
  // A piece of an earlier cut split again: the new crack meets the old one
  // there, and any edge between cut vertices may be pinched. A part's
  // commit leaves the tets its polygon's outline passes through whole, so
  // around the edges of its pieces the surface is checked with its
  // front's (the frame's commit, `commit`), when every tet there is split.
  // The kept front's pieces were checked when they were made, those split
  // from an earlier cut's pieces around every edge between cut vertices: a
  // new piece split from untouched tissue beside one checks such a shared
  // edge again (its own rule would pass over an edge between the part's
  // points).
  std::vector<std::pair<std::int32_t, std::int32_t>> kept_edges;
  if (kept) {
    for (const TetReplacement& r : kept->replaced)
      if (mt.error_inherited(r.old))
        for (std::uint32_t i = r.first; i < r.first + r.count; ++i)
          if (mt.alive(kept->made_tets[i])) add_edges(mt.tet(kept->made_tets[i]), by_cuts);
    kept_edges.swap(edges);
    sort_edges(kept_edges);
  }
  const auto add_edges_of = [&](const MtChangeReport& changes) {
    for (const TetReplacement& r : changes.replaced)
      for (std::uint32_t i = r.first; i < r.first + r.count; ++i) {
        const TetId t = changes.made_tets[i];
        if (!mt.alive(t)) continue;
        if (mt.error_inherited(r.old)) {
          add_edges(mt.tet(t), by_cuts);
        } else {
          add_edges(mt.tet(t), earlier);
          if (kept_edges.empty()) continue;
          const std::size_t before = edges.size();
          add_edges(mt.tet(t), by_cuts);
          const auto shared = [&](const auto& e) { return !std::binary_search(kept_edges.begin(), kept_edges.end(), e); };
          edges.erase(std::remove_if(edges.begin() + static_cast<std::ptrdiff_t>(before), edges.end(), shared),
                      edges.end());
        }
      }
  };
  for (const TetReplacement& r : cut.replaced)
    for (std::uint32_t i = r.first; i < r.first + r.count; ++i) {
      const TetId t = cut.made_tets[i];
      if (!mt.alive(t)) continue;
      const auto c = mt.corners(t);
      if (engine::orient3d_sign(c[0], c[1], c[2], c[3]) <= 0)
        report.add("cut: piece " + std::to_string(t.value) + " is not positively oriented");
    }
  if (select != CutSelect::kComplete) add_edges_of(cut);
  if (commit) add_edges_of(*commit->changes);
  sort_edges(edges);
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  // Every fragment the cut changed still replaces the same region: where
  // the new crack meets an old one it may bend differently in a fragment's
  // two tessellations. A fragment the cut did not decompose is checked by
  // what the cut changed there, with what the part's commits owe it
  // (fragment_ledger.h; a part that has met no older crack owes nothing
  // that needs a check, part_record.h). The fragments where the new crack meets an old one
  // (they hold a piece of an earlier cut that this one split or
  // relabelled) and that the cut decomposed (their parts did not exist
  // before) are checked whole, with their parts. A part's commit leaves
  // its fragments, and the parts of those it decomposed, owing what its
  // front splits (the ledger enters the parts by what their tets sum to),
  // so its front's check is theirs.
  const std::vector<FragId> decomposed = decomposed_fragments(cut);
  const FragmentLedger* owed = ledger_checked(part);
  if (select != CutSelect::kComplete && owed) {
    // The ledger (with the commit) and the whole front: zero on every face.
    const auto with_whole_front = [&] {
      MtChangeReport whole;
      if (kept) {
        whole = *kept;
        whole.append(cut);
      }
      return owed->unbalanced_with(mt, kept ? whole : cut, decomposed);
    };
    // Before the frame that sum was zero, so it is zero now exactly when
    // what the frame added to it is: its commit, the splits it took back
    // (`taken`) and this cut.
    const auto by_the_frame = [&] {
      MtChangeReport frame;
      if (commit) frame = *commit->changes;
      frame.append(cut);
      return taken->unbalanced_with(mt, frame, decomposed);
    };
    const std::vector<FragId> out_of_balance = taken ? by_the_frame() : with_whole_front();
    assert(!taken || out_of_balance == with_whole_front());
    for (FragId f : out_of_balance)
      report.add("cut: fragment " + std::to_string(f.value) +
                 ": its tets do not fill the region of the tets it replaces");
  }
  // A fragment that owes the part's ledger and that the cut decomposed is
  // out of the balance check above: it is checked whole.
  if (select != CutSelect::kComplete && owed && part)
    for (FragId f : decomposed)
      if (owed->owes(f)) fragments.push_back(f);
  for (const TetReplacement& r : cut.replaced) {
    if (select == CutSelect::kComplete || (!mt.error_inherited(r.old) && r.count != 1)) continue;
    for (FragId f : {r.birth, r.death})
      if (f.valid() && f != mt.root() && f != mt.drain() && std::binary_search(decomposed.begin(), decomposed.end(), f))
        fragments.push_back(f);
  }
  fragments = map_fragment_set(fragments, cut.fragment_splits);
  for (FragId f : fragments)
    for (auto& problem : engine::validate_fragment(mt, f).problems) report.add("cut: " + problem);
  std::vector<std::int32_t> thirds;
  std::vector<std::pair<std::int32_t, int>> faces;
  std::vector<std::int32_t> ends;
  ends.reserve(2 * edges.size());
  // The star of either end holds every tet of the edge: the end the cut
  // made, if one is, costs no query.
  const std::size_t first_made_here = commit ? std::min(commit->first_new_vertex, first_new_vertex) : first_new_vertex;
  const auto made_here = [&](std::int32_t v) { return static_cast<std::size_t>(v) >= first_made_here; };
  for (auto& [a, b] : edges)
    if (made_here(b) && !made_here(a)) std::swap(a, b);
  for (const auto& [a, b] : edges) ends.push_back(a);
  std::vector<const MtChangeReport*> made{&cut};
  if (commit) made.push_back(commit->changes);
  const Stars stars = stars_of(mt, bvh, made, first_made_here, std::move(ends));
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
