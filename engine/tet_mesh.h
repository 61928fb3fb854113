#pragma once
// A single-resolution tetrahedral mesh: rest positions and positively oriented
// tets, struct of arrays. It is the input of the MT builder and of the
// single-resolution cutter, and what every reader produces. Connectivity
// (face adjacency, boundary) is derived on demand by build_adjacency, so the
// mesh itself holds no state that could go stale after an edit.

#include <array>
#include <string>
#include <vector>

#include "engine/ids.h"
#include "engine/predicates.h"
#include "engine/validation.h"

namespace mtcut::engine {

struct TetAdjacency;

using Tet = std::array<VertId, 4>;

struct TetMesh {
  std::vector<Vec3> positions;  // (n_vertices) rest positions
  std::vector<Tet> tets;        // (n_tets) vertex ids, positively oriented

  std::size_t num_vertices() const { return positions.size(); }
  std::size_t num_tets() const { return tets.size(); }

  const Vec3& position(VertId v) const { return positions[v.index()]; }
  // The four corners of tet t.
  std::array<Vec3, 4> corners(TetId t) const;

  double volume(TetId t) const;
  double total_volume() const;

  // Orientation (exact), no degenerate or duplicate tets, vertex ids in range,
  // every face shared by at most two tets with opposite orientation, and a
  // manifold boundary (each boundary edge on exactly two boundary faces).
  ValidationReport validate() const;
  // The same with the mesh's adjacency built already (build_adjacency), for
  // a caller that reads it too.
  ValidationReport validate(const TetAdjacency& adjacency) const;
};

// Builds a TetMesh from raw vertex-index tets: checks ids, turns negatively
// oriented tets positive, rejects degenerate ones. `source` names the input in
// errors (InputError, with the element index).
TetMesh make_tet_mesh(std::vector<Vec3> positions, const std::vector<std::array<std::int64_t, 4>>& tets,
                      const std::string& source);

// Gives each fan of tets around a vertex that no face joins to the others
// (parts of the mesh that touch only at that vertex, or along an edge
// through it) its own copy of the vertex, so the boundary is manifold where
// parts of the mesh only touched. Returns how many vertices it split.
std::size_t split_pinched_vertices(TetMesh& mesh);

}  // namespace mtcut::engine
