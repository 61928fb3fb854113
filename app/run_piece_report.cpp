#include "app/run_piece_report.h"

#include <algorithm>
#include <limits>

#include "app/pieces.h"
#include "engine/tet_geometry.h"

namespace mtcut::app {

std::vector<PieceReport> report_pieces(const sim::World& world) {
  std::vector<engine::VertId> mt_vertex;  // of each local vertex of the frontier mesh
  const engine::TetMesh mesh = world.frontier().to_tet_mesh(world.mt(), &mt_vertex);
  const PieceLabels labels = label_pieces(mesh);

  const sim::SpringModel& model = world.model();
  const std::vector<std::int32_t> particle_of = model.particle_of(world.mt().num_vertices());

  std::vector<PieceReport> pieces(labels.piece_tets.size());
  for (auto& piece : pieces) {
    piece.lowest_z = std::numeric_limits<double>::infinity();
    piece.highest_z = -std::numeric_limits<double>::infinity();
  }
  std::vector<std::int32_t> vertex_piece(mesh.positions.size(), -1);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    PieceReport& piece = pieces[labels.tet_piece[t]];
    const engine::Tet& tet = mesh.tets[t];
    ++piece.tets;
    piece.rest_volume += engine::signed_volume(mesh.positions[tet[0].index()], mesh.positions[tet[1].index()],
                                               mesh.positions[tet[2].index()], mesh.positions[tet[3].index()]);
    for (int k = 0; k < 4; ++k) vertex_piece[tet[k].index()] = labels.tet_piece[t];
  }
  std::vector<std::size_t> particles(pieces.size(), 0);
  for (std::size_t v = 0; v < vertex_piece.size(); ++v) {
    const std::int32_t p = particle_of[mt_vertex[v].index()];
    if (vertex_piece[v] < 0 || p < 0) continue;
    PieceReport& piece = pieces[vertex_piece[v]];
    const engine::Vec3& x = world.state().x[p];
    piece.centroid += x;
    piece.lowest_z = std::min(piece.lowest_z, x.z());
    piece.highest_z = std::max(piece.highest_z, x.z());
    if (model.inv_mass[p] == 0) ++piece.held_particles;
    ++particles[vertex_piece[v]];
  }
  for (std::size_t i = 0; i < pieces.size(); ++i)
    if (particles[i] > 0) pieces[i].centroid /= static_cast<double>(particles[i]);
  return pieces;
}

}  // namespace mtcut::app
