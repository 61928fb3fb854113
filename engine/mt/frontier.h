#pragma once
// A frontier of the MT: one level of detail, possibly variable in space.
//
// Why this shape. A frontier is a set S of fragments closed under parents
// (the root always in, the drain never). Its mesh is every live tet born in S
// and replaced outside S (DESIGN.md, "Data model"). Adding a fragment whose
// parents are all in S coarsens (its replaced tets leave, its created tets
// enter); removing one whose children are all outside S refines. The
// simulator and the cutter read the mesh every frame, and selective
// refinement moves S a little every frame, so the frontier keeps S, its
// tets, its vertices and its visible fragments as IndexSets: a refine or
// coarsen step costs the tets it swaps, never a pass over the mesh.
//
// Calls take the MT as an argument (a constant model, a mutable state, as
// MuJoCo passes mjModel and mjData); the frontier holds no pointer to it.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/mt/index_set.h"
#include "engine/mt/mt.h"

namespace mtcut::engine {

class Frontier {
 public:
  Frontier() = default;
  // S = {root}: the fine mesh.
  static Frontier finest(const Mt& mt);
  // S = every fragment but the drain: the coarsest mesh.
  static Frontier coarsest(const Mt& mt);
  // S = `fragments` (must hold the root and be closed under parents:
  // validate_frontier says when it is not).
  static Frontier from_fragments(const Mt& mt, std::span<const FragId> fragments);

  // --- the fragment set S
  bool contains(FragId f) const { return in_set_.contains(f); }
  std::span<const FragId> fragments() const { return in_set_.members(); }
  // f is outside S, not the drain, and all its parents are in S.
  bool can_coarsen(const Mt& mt, FragId f) const;
  // f is in S, not the root, and none of its children is in S.
  bool can_refine(const Mt& mt, FragId f) const;
  void coarsen(const Mt& mt, FragId f);  // requires can_coarsen
  void refine(const Mt& mt, FragId f);   // requires can_refine
  // Every fragment that can be added / removed right now.
  std::vector<FragId> coarsenable(const Mt& mt) const;
  std::vector<FragId> refinable(const Mt& mt) const;

  // --- the mesh
  std::span<const TetId> tets() const { return tets_.members(); }
  bool has_tet(TetId t) const { return tets_.contains(t); }
  std::span<const VertId> vertices() const { return verts_.members(); }
  // Fragments that created at least one tet of the mesh: the ones the
  // time-critical cutter must process first for the visible mesh to show a cut.
  std::span<const FragId> visible_fragments() const { return visible_.members(); }
  bool is_visible(FragId f) const { return visible_.contains(f); }
  // The surface of the mesh, outward oriented (faces whose boundary bit is set).
  std::vector<std::array<VertId, 3>> boundary_faces(const Mt& mt) const;
  double volume(const Mt& mt) const;
  // The mesh as a compact TetMesh; vertex_ids (optional) receives, for each
  // of its vertices, the MT vertex it is.
  TetMesh to_tet_mesh(const Mt& mt, std::vector<VertId>* vertex_ids = nullptr) const;

  // Grows the per-element arrays after the MT grew (new fragments are outside S).
  void sync(const Mt& mt);
  // Follows an edit of the MT that kept every fragment's region (a cut:
  // tets replaced by pieces, fragments split into parts) without a pass over
  // the mesh: `joined` enter S (parts of members); `changed_tets` are the
  // tets killed, revived or made by the edit, each in the mesh afterwards
  // when alive, born in S and not replaced in S; `regrouped` holds every
  // fragment that tets left or joined without being killed or made (a
  // fragment split into parts: it and its parts), recounted for the visible
  // set. Other tets keep their membership, so the result is from_fragments()
  // of the new S. Costs the edit plus the created tets of `regrouped`.
  void follow_edit(const Mt& mt, std::span<const FragId> joined, std::span<const TetId> changed_tets,
                   std::span<const FragId> regrouped);
  // Tets of the mesh that f created (f is visible when there are any).
  std::int32_t shown_tets(FragId f) const { return f.index() < frag_uses_.size() ? frag_uses_[f.index()] : 0; }
  // Changed by every refine / coarsen to a value no other frontier state has:
  // selective refinement checks it.
  std::uint64_t version() const { return version_; }
  std::size_t bytes() const;

 private:
  void add_tet(const Mt& mt, TetId t);
  void remove_tet(const Mt& mt, TetId t);

  IndexSet<FragId> in_set_;              // S
  IndexSet<TetId> tets_;                 // the mesh
  IndexSet<VertId> verts_;               // vertices of the mesh
  IndexSet<FragId> visible_;             // births of the mesh's tets
  std::vector<std::int32_t> vert_uses_;  // (n_vertices) mesh tets holding the vertex
  std::vector<std::int32_t> frag_uses_;  // (n_fragments) mesh tets each fragment created
  // (n_tets) The fragment a mesh tet is counted in by frag_uses_: its birth
  // when it entered the mesh or its fragment was recounted. A tet an edit
  // killed has no birth any more, and this says which count it leaves.
  std::vector<FragId> counted_in_;
  std::uint64_t version_ = 0;
};

// S contains the root, not the drain, is closed under parents; the tets,
// vertices and visible fragments are exactly what S defines; and the mesh
// is a conforming tessellation of the domain: positive tets, every face
// shared by at most two tets with opposite orientations, a manifold surface,
// faces without a neighbour exactly the faces marked as surface, and the
// fine mesh's volume within 1e-9 relative (or, when the MT's builder moved
// the boundary, the volume that S's fragments account for).
ValidationReport validate_frontier(const Mt& mt, const Frontier& frontier);

}  // namespace mtcut::engine
