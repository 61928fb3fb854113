#pragma once
// The Multi-Tessellation (paper, section 3): every resolution of a tet mesh
// in one structure.
//
// Why this shape. The paper's MT is a DAG whose nodes are fragments (the tets
// one simplification step creates) and whose arcs are labelled with the tets
// a step replaces. mtcut stores the paper's *expanded* arc list (section 4):
// each tet t is the arc (birth(t), death(t)) -- the fragment that creates it
// and the fragment that replaces it. Everything else is derived:
//   created(f)  = { t : birth(t) == f }   replaced(f) = { t : death(t) == f }
//   parents(f)  = births of replaced(f)   children(f) = deaths of created(f)
// The root creates the finest mesh and replaces nothing; the drain replaces
// the coarsest mesh and creates nothing.
//
// The cutter (cut/) edits the MT at every resolution: it appends vertices and
// tets (a cut tet's pieces are born and die in the same fragments as the tet),
// kills the tet they replace, appends fragments when a fragment falls apart,
// and moves tets between fragments (set_birth / set_death) to re-attach arcs.
// So: vertices, tets and fragments are appendable arrays addressed by handles;
// a tet is never erased, only killed (birth = none); and the per-fragment
// lists are kept in step with birth/death in O(1) per change by storing each
// tet's slot in both lists (swap-remove with a back-index fix).
//
// Hot per-tet data (vertices, birth, death, error) is struct-of-arrays: the
// frontier and the cutter stream through it.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/ids.h"
#include "engine/tet_mesh.h"
#include "engine/validation.h"

namespace mtcut::engine {

// Bit i set: face i of the tet (opposite vertex i, kTetFaces) lies on the
// surface of the object, in every frontier that holds the tet. Faces made by
// a cut are surface faces too.
using FaceMask = std::uint8_t;

class Frontier;

class Mt {
 public:
  // An MT holding only the root fragment, which creates `fine` (boundary masks
  // derived from its face adjacency), with no death yet: the state the builder
  // starts from. `boundary_preserved` records a promise of the builder: every
  // frontier covers exactly the fine mesh's domain.
  static Mt from_fine_mesh(const TetMesh& fine);

  // --- vertices: shared by all resolutions, rest positions
  std::size_t num_vertices() const { return positions_.size(); }
  const Vec3& position(VertId v) const { return positions_[v.index()]; }
  std::span<const Vec3> positions() const { return positions_; }
  VertId add_vertex(const Vec3& rest_position);
  // Room for this many vertices and tets in all, so that a cut that knows
  // how much it adds appends without reallocating.
  void reserve(std::size_t vertices, std::size_t tets);

  // --- tets: slots 0..num_tets()-1, dead ones included
  std::size_t num_tets() const { return tet_verts_.size(); }
  std::size_t num_live_tets() const { return live_tets_; }
  const Tet& tet(TetId t) const { return tet_verts_[t.index()]; }
  FragId birth(TetId t) const { return tet_birth_[t.index()]; }
  FragId death(TetId t) const { return tet_death_[t.index()]; }
  // Where t is in created(birth(t)).
  std::size_t birth_slot(TetId t) const { return static_cast<std::size_t>(tet_birth_slot_[t.index()]); }
  float error(TetId t) const { return tet_error_[t.index()]; }
  // The error was given (a cut piece's is its split tet's), not computed from the corners.
  bool error_inherited(TetId t) const { return tet_error_inherited_[t.index()] != 0; }
  FaceMask boundary_mask(TetId t) const { return tet_boundary_[t.index()]; }
  bool alive(TetId t) const { return tet_birth_[t.index()].valid(); }
  std::array<Vec3, 4> corners(TetId t) const;
  double volume(TetId t) const;

  // Appends a tet (positively oriented) created by `birth` and replaced by
  // `death` (none while the builder has not decided yet). Its error is
  // computed from the positions (tet_error.h).
  TetId add_tet(const Tet& verts, FragId birth, FragId death, FaceMask boundary);
  // Appends a piece of `whole` (alive; a cut's R(t), paper section 4): born
  // and dying in the same fragments, its error is `whole`'s. That is an upper
  // bound of its own error (the piece lies in the whole's enclosing sphere),
  // and the right value: the error says how far this level is from the fine
  // mesh, which a cut does not change. So a cut leaves every fragment's error,
  // and the frontiers selective refinement picks, as they were.
  TetId add_piece(const Tet& verts, TetId whole, FaceMask boundary);
  // add_piece for each of `verts` (with boundary[i]), in one go: each array
  // grows once. The pieces get consecutive ids, from the one returned.
  TetId add_pieces(std::span<const Tet> verts, TetId whole, std::span<const FaceMask> boundary);
  // Appends a copy of `source`'s tet `t` over `verts` in fragments `birth`,
  // `death` of this MT, with t's error (computed or inherited) kept.
  TetId add_copy(const Mt& source, TetId t, const Tet& verts, FragId birth, FragId death);
  // Removes t from the MT: it leaves its fragments' lists; the slot stays.
  void kill_tet(TetId t);
  // Brings a killed tet back, created by `birth` and replaced by `death`
  // (none allowed): what retracting a provisional cut does to the tets it
  // split (cut/mt/cut_retraction.h).
  void revive_tet(TetId t, FragId birth, FragId death);
  // Moves t to another creating / replacing fragment (re-attaching an arc).
  void set_birth(TetId t, FragId f);
  void set_death(TetId t, FragId f);
  // Splits f's arcs among `parts` (parts[0] == f): the i-th tet of
  // created(f), then of replaced(f), moves to parts[group[i]]. One pass per
  // list, where set_birth / set_death would swap each tet out one by one;
  // the tets f keeps stay in their order.
  void move_groups(FragId f, std::span<const FragId> parts, std::span<const std::int32_t> group);
  void set_boundary_mask(TetId t, FaceMask mask) {
    tet_boundary_[t.index()] = mask;
    ++revision_;
  }

  // --- fragments
  std::size_t num_fragments() const { return frag_created_.size(); }
  FragId root() const { return root_; }
  FragId drain() const { return drain_; }
  std::span<const TetId> created(FragId f) const { return frag_created_[f.index()]; }
  std::span<const TetId> replaced(FragId f) const { return frag_replaced_[f.index()]; }
  // The revision() at which created(f) last changed (a tet born in f added,
  // killed or moved): what data derived per fragment compares, with
  // instance(), to know it is stale (selective refinement re-indexes only
  // the fragments a cut changed).
  std::uint64_t created_revision(FragId f) const { return frag_created_revision_[f.index()]; }
  // Largest error of the tets f creates (0 when it creates none).
  float fragment_error(FragId f) const;
  FragId add_fragment();
  // Removes the last fragment, which must create and replace nothing (the
  // part a retracted cut made, its tets moved back).
  void remove_last_fragment();
  // Room for f's lists to grow to `created` and `replaced` tets without reallocating.
  void reserve_fragment(FragId f, std::size_t created, std::size_t replaced);
  void set_drain(FragId f) { drain_ = f; }
  // Distinct births of replaced(f) / deaths of created(f), ascending.
  std::vector<FragId> parents(FragId f) const;
  std::vector<FragId> children(FragId f) const;

  // --- storage
  // Drops the dead tets but those in `keep_dead`, and the vertices from
  // `first_droppable_vertex` on that no live or kept tet uses, renumbering
  // the rest in their order (fragments keep their ids; every created(f) and
  // replaced(f) keeps its order). What reclaims the slots that cuts taken
  // back leave (cut/mt/cut_retraction.h): everything that holds tet or
  // vertex ids of this MT must follow the returned maps or be rebuilt.
  // instance() is renewed. The arrays keep their capacity (what follows a
  // compaction, a stroke going on, grows them again).
  struct Compaction {
    std::vector<std::int32_t> tet_map;     // (old n_tets) new index, -1 dropped
    std::vector<std::int32_t> vertex_map;  // (old n_vertices) new index, -1 dropped
    std::size_t tets_dropped = 0, vertices_dropped = 0;
    TetId tet(TetId t) const { return TetId(tet_map[t.index()]); }
    VertId vertex(VertId v) const { return VertId(vertex_map[v.index()]); }
  };
  Compaction compact(std::size_t first_droppable_vertex, std::span<const TetId> keep_dead = {});
  // Dead tet slots, and vertices no live tet uses (a pass over the tets).
  std::size_t num_dead_tets() const { return num_tets() - live_tets_; }
  std::size_t num_unused_vertices() const;

  // --- whole-MT facts
  double fine_volume() const { return fine_volume_; }
  bool boundary_preserved() const { return boundary_preserved_; }
  void set_boundary_preserved(bool preserved) { boundary_preserved_ = preserved; }
  // Incremented by every mutation: derived indexes (BVHs, cached orders)
  // compare it to know they are stale.
  std::uint64_t revision() const { return revision_; }
  // The revision() at which the fragments' DAG last changed: a fragment
  // added or removed, a tet moved to other fragments, a tet added other than
  // as a piece, a compaction. While it stays, parents(f) and children(f) of
  // every fragment are as they were: a cut that decomposes no fragment
  // replaces tets by pieces born and dying in the same fragments, and a
  // retraction revives them where their pieces were (selective refinement
  // then follows a cut without a pass over the DAG).
  std::uint64_t structure_revision() const { return structure_revision_; }
  // Unique to this object in the process, and renewed when it is copied or
  // assigned: two MTs with the same instance() are one object whose
  // revisions can be compared.
  std::uint64_t instance() const { return instance_.value; }
  // Heap bytes held by the MT's arrays.
  std::size_t bytes() const;

  // Fragments in an order where every parent precedes its children (Kahn's
  // algorithm from the root); fragments unreachable from the root, or on a
  // cycle, are missing from it (validate() reports them).
  std::vector<FragId> topological_order() const;

  // The structure and every fragment (mt_validate.cpp): the DAG is acyclic
  // with one root and one drain; lists agree with birth/death; every live
  // tet is positive, born before it dies; every fragment replaces a region
  // by a conforming tessellation of the same region (same outer faces, same
  // volume when the boundary is preserved); and the finest and coarsest
  // frontiers are conforming tessellations of the domain (validate_frontier).
  ValidationReport validate() const;

 private:
  TetId append_tet(const Tet& verts, FragId birth, FragId death, FaceMask boundary, float error, bool inherited);
  // set_death without changing structure_revision() (revive_tet: the tet
  // goes back where its pieces were).
  void link_death(TetId t, FragId f);
  static void erase_from(std::vector<std::vector<TetId>>& lists, std::vector<std::int32_t>& slots, FragId f,
                         TetId t);

  std::vector<Vec3> positions_;  // (n_vertices) rest positions

  std::vector<Tet> tet_verts_;                  // (n_tets) positively oriented
  std::vector<FragId> tet_birth_;               // (n_tets) creating fragment; none = dead tet
  std::vector<FragId> tet_death_;               // (n_tets) replacing fragment; none while building
  std::vector<float> tet_error_;                // (n_tets) e(t), tet_error.h
  std::vector<std::uint8_t> tet_error_inherited_;  // (n_tets) 1: error given by add_piece / add_copy
  std::vector<FaceMask> tet_boundary_;          // (n_tets) surface faces
  std::vector<std::int32_t> tet_birth_slot_;    // (n_tets) index of t in created(birth(t))
  std::vector<std::int32_t> tet_death_slot_;    // (n_tets) index of t in replaced(death(t)), -1 if none

  std::vector<std::vector<TetId>> frag_created_;   // (n_fragments) tets each fragment creates
  std::vector<std::uint64_t> frag_created_revision_;  // (n_fragments) see created_revision()
  std::vector<std::vector<TetId>> frag_replaced_;  // (n_fragments) tets each fragment replaces

  FragId root_;
  FragId drain_;
  std::size_t live_tets_ = 0;
  double fine_volume_ = 0.0;
  bool boundary_preserved_ = true;
  std::uint64_t revision_ = 0;
  std::uint64_t structure_revision_ = 0;
  // A process-wide unique number that a copy does not share.
  struct InstanceId {
    std::uint64_t value = next();
    InstanceId() = default;
    InstanceId(const InstanceId&) : value(next()) {}
    InstanceId& operator=(const InstanceId&) {
      value = next();
      return *this;
    }
    static std::uint64_t next();
  };
  InstanceId instance_;
};

// One fragment's part of Mt::validate(): it replaces a region by a
// tessellation of the same region (the faces of the region's outer surface
// inside the object the same, with the same orientation; with a preserved
// boundary the volume too). Nothing for the root and the drain.
ValidationReport validate_fragment(const Mt& mt, FragId f);

// The faces of a set of tets that no other tet of the set shares, each as
// (sorted vertex ids) with the orientation seen from its tet: the outer
// surface of a region. Used by validation (a fragment's outer surface must
// equal that of the region it replaces) and by the frontier.
struct OrientedFace {
  std::array<VertId, 3> sorted;  // ascending ids: the key
  std::array<VertId, 3> verts;   // outward orientation
  TetId tet;
  int local_face;
};
std::vector<OrientedFace> outer_faces(const Mt& mt, std::span<const TetId> tets);

}  // namespace mtcut::engine
