#include "app/view/surface_topology.h"

#include <stdexcept>
#include <string>
#include <unordered_map>

#include "engine/tet_geometry.h"

namespace mtcut::app::view {
namespace {

// Appends a face with its corners on `points` (particles or finest-surface
// vertices), its smooth-normal groups keyed by (point, cut).
void add_face(SurfaceTopology& s, std::unordered_map<std::int64_t, std::int32_t>& group_of,
              const std::array<engine::VertId, 3>& face, const std::array<std::int32_t, 3>& points, engine::TetId tet,
              std::int32_t piece, std::int32_t level, std::size_t first_cut_vertex) {
  bool cut = true;
  for (engine::VertId v : face) cut = cut && v.index() >= first_cut_vertex;
  s.faces.push_back(face);
  s.face_tet.push_back(tet);
  s.face_piece.push_back(piece);
  s.face_cut.push_back(cut ? 1 : 0);
  s.face_level.push_back(level);
  s.max_level = std::max(s.max_level, level);
  for (std::int32_t point : points) {
    s.corner_point.push_back(point);
    const auto [it, inserted] = group_of.try_emplace(std::int64_t{point} * 2 + (cut ? 1 : 0), s.groups);
    if (inserted) ++s.groups;
    s.corner_group.push_back(it->second);
  }
}

}  // namespace

SurfaceTopology extract_surface(const engine::Mt& mt, const engine::Frontier& frontier,
                                const sim::SpringModel& model, const PieceLabels& pieces,
                                const std::vector<std::int32_t>& fragment_levels, std::size_t first_cut_vertex) {
  const std::vector<std::int32_t> particle_of = model.particle_of(mt.num_vertices());

  SurfaceTopology s;
  s.pieces = pieces.count();
  std::unordered_map<std::int64_t, std::int32_t> group_of;  // particle * 2 + cut -> group
  for (engine::TetId t : frontier.tets()) {
    const engine::FaceMask mask = mt.boundary_mask(t);
    if (mask == 0) continue;
    const engine::Tet& tet = mt.tet(t);
    const engine::FragId birth = mt.birth(t);
    const std::int32_t level = fragment_levels.at(birth.index());
    for (int f = 0; f < 4; ++f) {
      if (!(mask & (1u << f))) continue;
      const std::array<engine::VertId, 3> face = {tet[engine::kTetFaces[f][0]], tet[engine::kTetFaces[f][1]],
                                                  tet[engine::kTetFaces[f][2]]};
      std::array<std::int32_t, 3> points{};
      for (std::size_t k = 0; k < 3; ++k) {
        points[k] = particle_of[face[k].index()];
        // An invariant of the World (its model is rebuilt with the frontier):
        // fail loudly rather than index with -1.
        if (points[k] < 0)
          throw std::logic_error("extract_surface: frontier vertex " + std::to_string(face[k].value) +
                                 " has no particle (the spring model is not built on this frontier)");
      }
      add_face(s, group_of, face, points, t, pieces.tet_piece[t.index()], level, first_cut_vertex);
    }
  }
  return s;
}

SurfaceTopology extract_finest_surface(const engine::Mt& mt, const engine::Frontier& frontier,
                                       const sim::SpringModel& model, const PieceLabels& pieces,
                                       const std::vector<std::int32_t>& fragment_levels, std::size_t first_cut_vertex,
                                       const sim::FinestSurface* previous) {
  SurfaceTopology s;
  s.pieces = pieces.count();
  s.finest = sim::carry_finest_surface(mt, frontier, model, previous);
  const sim::FinestSurface& finest = *s.finest;
  std::unordered_map<std::int64_t, std::int32_t> group_of;  // point * 2 + cut -> group
  for (const std::array<std::int32_t, 3>& points : finest.faces) {
    std::array<engine::VertId, 3> face;
    for (std::size_t k = 0; k < 3; ++k) face[k] = finest.vertices[static_cast<std::size_t>(points[k])];
    const engine::TetId carrier = finest.carrier[static_cast<std::size_t>(points[0])];
    add_face(s, group_of, face, points, carrier, pieces.tet_piece[carrier.index()],
             fragment_levels.at(mt.birth(carrier).index()), first_cut_vertex);
  }
  return s;
}

}  // namespace mtcut::app::view
