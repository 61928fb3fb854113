#include "app/view/surface_topology.h"

#include <stdexcept>
#include <string>
#include <unordered_map>

#include "engine/tet_geometry.h"

namespace mtcut::app::view {

SurfaceTopology extract_surface(const engine::Mt& mt, const engine::Frontier& frontier,
                                const sim::SpringModel& model, const PieceLabels& pieces,
                                const std::vector<std::int32_t>& fragment_levels, std::size_t first_cut_vertex) {
  std::vector<std::int32_t> particle_of(mt.num_vertices(), -1);
  for (std::size_t p = 0; p < model.particle_vertex.size(); ++p)
    particle_of[model.particle_vertex[p].index()] = static_cast<std::int32_t>(p);

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
      bool cut = true;
      for (engine::VertId v : face) cut = cut && v.index() >= first_cut_vertex;
      s.faces.push_back(face);
      s.face_tet.push_back(t);
      s.face_piece.push_back(pieces.tet_piece[t.index()]);
      s.face_cut.push_back(cut ? 1 : 0);
      s.face_level.push_back(level);
      s.max_level = std::max(s.max_level, level);
      for (engine::VertId v : face) {
        const std::int32_t particle = particle_of[v.index()];
        // An invariant of the World (its model is rebuilt with the frontier):
        // fail loudly rather than index with -1.
        if (particle < 0)
          throw std::logic_error("extract_surface: frontier vertex " + std::to_string(v.value) +
                                 " has no particle (the spring model is not built on this frontier)");
        s.corner_particle.push_back(particle);
        const auto [it, inserted] = group_of.try_emplace(std::int64_t{particle} * 2 + (cut ? 1 : 0), s.groups);
        if (inserted) ++s.groups;
        s.corner_group.push_back(it->second);
      }
    }
  }
  return s;
}

}  // namespace mtcut::app::view
