#pragma once
// What the viewer draws of the tissue: the organ's finest surface carried by
// the frontier (sim/finest_surface.h), or the boundary faces of the current
// frontier, each with its piece, whether a cut made it, and its LOD level,
// laid out as corners (3 per face) that index the points placed each frame:
// the finest surface's vertices, or the spring model's particles.
//
// Why this shape. Positions move every frame but the faces change only
// when the frontier or the MT does. So the topology is extracted once per
// change (here) and each frame only gathers particle positions into the
// corners (surface_geometry.h); colours are uploaded with the topology.
// Corners are not shared between faces so that flat shading, per-face
// colours and the sharp rim between a cut face and the old surface need no
// vertex splitting.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "app/pieces.h"
#include "engine/mt/frontier.h"
#include "engine/mt/mt.h"
#include "sim/finest_surface.h"
#include "sim/spring_model.h"

namespace mtcut::app::view {

struct SurfaceTopology {
  std::vector<std::array<engine::VertId, 3>> faces;  // (n_faces) outward oriented
  // (n_faces) the frontier tet the face bounds; on the finest surface, the
  // one carrying the face's first corner (its piece and level are the face's)
  std::vector<engine::TetId> face_tet;
  std::vector<std::int32_t> face_piece;              // (n_faces) label_frontier_pieces numbering
  std::vector<std::uint8_t> face_cut;                // (n_faces) 1: made by a cut
  std::vector<std::int32_t> face_level;              // (n_faces) level of face_tet's creating fragment
  // The finest surface the corners index (nullopt: they index particles).
  std::optional<sim::FinestSurface> finest;
  std::vector<std::int32_t> corner_point;            // (3 n_faces) finest-surface vertex or particle of each corner
  // (3 n_faces) smooth-normal group of each corner: one per (point, cut
  // or not), so normals are averaged over the old surface and over cut
  // faces separately and the rim of a cut stays sharp.
  std::vector<std::int32_t> corner_group;
  std::int32_t groups = 0;
  int pieces = 0;
  std::int32_t max_level = 0;

  std::size_t num_faces() const { return faces.size(); }
};

// A face is a cut face when all its vertices were made by a cut, i.e. have
// ids >= first_cut_vertex (the MT's vertex count when it was loaded).
// `pieces` from label_frontier_pieces, `fragment_levels` from fragment_levels().
// `model` must be built on `frontier` (every frontier vertex a particle).
SurfaceTopology extract_surface(const engine::Mt& mt, const engine::Frontier& frontier,
                                const sim::SpringModel& model, const PieceLabels& pieces,
                                const std::vector<std::int32_t>& fragment_levels, std::size_t first_cut_vertex);
// The finest surface, carried by the frontier (its carriers kept from
// `previous` where they still hold: sim::carry_finest_surface); the same
// arguments otherwise.
SurfaceTopology extract_finest_surface(const engine::Mt& mt, const engine::Frontier& frontier,
                                       const sim::SpringModel& model, const PieceLabels& pieces,
                                       const std::vector<std::int32_t>& fragment_levels, std::size_t first_cut_vertex,
                                       const sim::FinestSurface* previous = nullptr);

}  // namespace mtcut::app::view
