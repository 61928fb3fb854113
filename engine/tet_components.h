#pragma once
// The pieces of a tet mesh: its connected components, two tets connected
// when they share a vertex. Why vertices, not faces: the spring model has
// one particle per vertex, so tets that share only an edge or a vertex move
// as one body. A cut separates pieces by giving each side its own copies of
// the cut's vertices (and the cutters refuse a cut that would leave two
// sides on one edge); a mesh whose parts touch only at vertices is split
// there when it is loaded. The MT's pieces (cut/mt/mt_pieces.h) are the
// same components of its finest mesh.

#include <cstdint>
#include <span>
#include <vector>

#include "engine/tet_mesh.h"

namespace mtcut::engine {

struct TetComponents {
  std::vector<std::int32_t> tet_component;  // (n_tets) numbered in order of their first tet
  std::vector<std::size_t> tets;            // (count) tets in each
  std::size_t count() const { return tets.size(); }
};

// Components of `tets` over vertex ids below `num_vertices`.
TetComponents tet_components(std::span<const Tet> tets, std::size_t num_vertices);

}  // namespace mtcut::engine
