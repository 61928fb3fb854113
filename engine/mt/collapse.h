#pragma once
// Half-edge collapse on the mesh being simplified into an MT.
//
// Why this shape. The builder needs, for any vertex v, the cheapest valid
// collapse v -> w, and then to apply it as one MT fragment: the star of v
// (F_i, the tets around v) is replaced by Sigma_i (the same tets with v moved
// to w, those holding both dropped). So the working mesh is the MT's live
// tets (created, not yet replaced) plus one star list per vertex; the MT
// itself receives every tet ever made, and nothing is copied at the end.
//
// A collapse v -> w is valid when
//  - no tet of Sigma_i is inverted or flat (exact orient3d),
//  - the link condition holds (Dey et al.: Lk(v) n Lk(w) = Lk(vw), the
//    boundary closed by a dummy vertex so that surface topology is kept too),
//  - the boundary does not move beyond the error: with preserve_boundary a
//    surface vertex only slides within its flat face region or along a
//    straight crease (exact coplanarity), so every frontier covers exactly
//    the fine domain; without it, the surface the collapse makes must lie
//    within the error of the collapse and max_surface_deviation of the fine
//    surface, both ways (below),
//  - no tet of Sigma_i has a worse shape than min_quality (or than the worst
//    tet it replaces, if that is already worse).
// Its cost is the error of the fragment it makes: the largest e(t) of
// Sigma_i (tet_error.h).
//
// How far a surface move goes, measured against the fine surface (not summed
// over moves, which bounds one way only: a coarse face can pass farther from
// the fine surface than the vertices it lost). Both ways are checked at
// samples, the same ones surface_deviation.h measures a level by: the new
// faces' edge midpoints and centroids (their corners are fine vertices) to
// the fine surface, through an index over its triangles; and every sample
// of the fine surface (its vertices, edge midpoints and centroids) to the
// current face it was last checked against, each sample held by one face,
// so a collapse checks the samples of the faces it removes against the
// faces it makes, and each goes to the nearest of them. So every level's
// surface lies within max_surface_deviation of the fine surface, both ways,
// at those samples.

#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "engine/mt/mt.h"

namespace mtcut::engine {

struct CollapseOptions {
  bool preserve_boundary = true;
  double min_quality = 0.05;  // tet_quality of the tets a collapse makes
  // Metres the surface may move in all (preserve_boundary off).
  double max_surface_deviation = std::numeric_limits<double>::infinity();
};

// Why candidate collapses were turned down (diagnostics; a candidate can be
// counted more than once over a build).
struct CollapseRejections {
  std::size_t inversion = 0;
  std::size_t link = 0;
  std::size_t boundary = 0;
  std::size_t quality = 0;
};

struct CollapseChoice {
  VertId target;  // none: no valid collapse
  float cost = std::numeric_limits<float>::infinity();
  bool valid() const { return target.valid(); }
};

class SimplificationMesh {
 public:
  // Takes the MT's live tets that have no death yet (the builder's start: the
  // fine mesh under the root).
  SimplificationMesh(Mt& mt, const CollapseOptions& options);
  ~SimplificationMesh();

  std::size_t live_tets() const { return live_tets_; }
  bool on_boundary(VertId v) const { return on_boundary_[v.index()] != 0; }
  std::span<const TetId> star(VertId v) const { return star_[v.index()]; }
  // The vertices sharing a tet with v.
  void ring(VertId v, std::vector<VertId>& out) const;

  // The valid collapse out of v with the least cost. Without check_link the
  // link condition is left out (the caller checks it before applying, with
  // check_collapse): it is the dearest rule and rarely decides.
  CollapseChoice best_collapse(VertId v, bool check_link = true);
  // The cost of v -> target if valid (target none otherwise): same rules.
  CollapseChoice check_collapse(VertId v, VertId target);
  // Applies v -> target as a new fragment of the MT (its replaced tets get
  // the fragment as death) and returns the fragment. With `into`, the
  // collapse joins that fragment instead: tets `into` itself created and
  // this collapse replaces never existed outside it, so they are killed.
  FragId apply(VertId v, VertId target, FragId into = FragId());
  // The link condition for collapsing the edge vw (either direction).
  bool link_condition(VertId v, VertId w);
  // Gives the remaining live tets the drain as their death.
  void finish(FragId drain);

  const CollapseRejections& rejections() const { return rejections_; }

 private:
  // What the rules need to know about the star of the vertex that moves.
  struct StarInfo {
    std::vector<std::array<VertId, 3>> surface;  // surface faces holding v, outward
    std::array<std::array<Vec3, 3>, 2> planes;   // distinct planes of those faces
    int num_planes = 0;
    bool corner = false;       // three or more planes: v may not move (preserve_boundary)
    double worst_quality = -1;  // of the star's tets; < 0 until worst_quality() computes it
  };
  void describe_star(VertId v, StarInfo& info);
  float cost_of(VertId v, VertId target, StarInfo& info, float bound);
  double worst_quality(VertId v, StarInfo& info) const;
  // The surface faces v -> w makes (the faces of v's star on the surface,
  // v moved to w, those already holding w dropped), into `out`.
  void moved_faces(VertId v, VertId w, const StarInfo& info, std::vector<std::array<VertId, 3>>& out) const;
  // How far the surface v -> w makes lies from the fine surface, both ways
  // (at the samples above), stopping early past `limit` (+inf when no face
  // is made).
  double surface_moved_by(VertId v, VertId w, const StarInfo& info, double limit);

  Mt& mt_;
  CollapseOptions options_;
  std::vector<std::vector<TetId>> star_;  // (n_vertices) live tets holding the vertex
  std::vector<char> on_boundary_;         // (n_vertices) on the surface of the fine mesh
  // The fine surface and its samples (preserve_boundary off: surface_moved_by).
  struct FineSurface;
  std::unique_ptr<FineSurface> fine_;
  std::size_t live_tets_ = 0;
  CollapseRejections rejections_;

  // Scratch, reused between calls so that a collapse allocates nothing.
  StarInfo info_;
  std::vector<VertId> ring_, candidates_, excluded_;
  std::vector<std::int32_t> link_vw_;
  std::vector<std::uint64_t> link_e_[1], link_ew_;
  std::vector<std::array<std::int32_t, 3>> link_t_[1];
  mutable std::vector<std::uint32_t> mark_;  // (n_vertices) == stamp_: in the set being built
  mutable std::uint32_t stamp_ = 0;
  std::vector<TetId> old_star_, new_tets_;
  std::vector<std::array<VertId, 3>> moved_;
  std::vector<std::int32_t> loose_;
  struct MadeTet {
    Tet verts;
    double longest;  // longest edge
  };
  std::vector<MadeTet> made_;
};

}  // namespace mtcut::engine
