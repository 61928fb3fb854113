#pragma once
// Cutting a single-resolution TetMesh by one polygon: find the tets the
// polygon may cut, classify them (with snapping), replace each cut tet by
// its split, give the tets around a split vertex the copy of their side, and
// report what changed. The MT cutter does the same per resolution; this is
// also what `mtcut cut` runs.
//
// The mesh is edited in place: a split tet's slot holds its first new tet,
// the others are appended; new vertices are appended. Tets that are not cut
// keep their ids.

#include <array>
#include <cstdint>
#include <vector>

#include "cut/cut_polygon.h"
#include "cut/lut/split_table.h"
#include "cut/vertex_factory.h"
#include "engine/tet_mesh.h"

namespace mtcut::cut {

using engine::TetId;

struct CutterDef {
  SplitScheme scheme = SplitScheme::kLut;
  double snap = 0.15;         // cut points nearer a vertex than this fraction of the edge snap onto it
  bool count_pieces = true;   // connected components after the cut (costs an adjacency build)
};

inline constexpr std::size_t kCaseCount = static_cast<std::size_t>(CutCase::kCount);

struct CutStats {
  std::size_t candidate_tets = 0;    // tets the plane touches near the polygon
  std::size_t split_tets = 0;        // tets replaced
  std::size_t new_tets = 0;          // tets replacing them
  std::size_t relabeled_tets = 0;    // not split, but moved onto a split vertex's copy
  std::size_t new_vertices = 0;
  std::size_t split_vertices = 0;    // vertices the cut passes through (a copy was made)
  std::size_t snapped_vertices = 0;  // vertices the cut was moved onto
  std::size_t vetoed_vertices = 0;   // kept off the cut to avoid pinching (vertex_unpinch.h)
  std::size_t pulled_vertices = 0;   // pulled onto the cut to avoid pinching (vertex_unpinch.h)
  std::size_t unpinched_vertices = 0;  // extra copies where a star fell apart (vertex_unpinch.h)
  std::array<std::size_t, kCaseCount> per_case{};  // split tets per CutCase
  std::size_t pieces = 0;            // connected components after the cut (0: not counted)
  double min_dihedral_deg = 180;     // smallest dihedral angle of the new tets (180: none)
  double min_dihedral_ratio = 1;     // smallest (new tet's angle / its parent's smallest angle), capped at 1
  double seconds = 0;                // wall time of the whole cut
  double split_seconds = 0;          // of which classifying and splitting the candidates

  double new_tets_per_split_tet() const {
    return split_tets ? static_cast<double>(new_tets) / static_cast<double>(split_tets) : 0.0;
  }
};

// What the cut changed, as data.
struct MeshCutResult {
  CutStats stats;
  std::vector<TetId> split_tets;           // (n_split) ids of the tets replaced
  std::vector<std::uint32_t> split_first;  // (n_split + 1) offsets into `replacements`
  std::vector<TetId> replacements;         // the tets replacing them; the old id comes first
  std::vector<TetId> relabeled_tets;       // tets given a vertex copy (may repeat)
  std::vector<MadeVertex> new_vertices;    // in id order, from the old vertex count on
  std::vector<VertId> snapped_vertices;    // vertices the cut was moved onto (and split)
  std::vector<VertId> resided_vertices;    // on the plane to rounding, kept off the cut on their neighbours' side
};

// Cuts `mesh` by `polygon`. `table` may be shared between cuts (it caches
// the recipes) and must have def.scheme; nullptr uses a fresh one.
MeshCutResult cut_mesh(engine::TetMesh& mesh, const CutPolygon& polygon, const CutterDef& def = {},
                       SplitTable* table = nullptr);

// Connected components of a tet mesh through shared faces.
std::size_t count_pieces(const engine::TetMesh& mesh);

}  // namespace mtcut::cut
