#include "app/run_snapshots.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <ostream>

#include "app/run_format.h"
#include "app/fragment_levels.h"
#include "app/pieces.h"
#include "engine/atomic_file.h"
#include "engine/io/mesh_file.h"
#include "engine/surface_mesh.h"
#include "sim/finest_surface.h"

namespace mtcut::app {

DeformedFrontier deform_frontier(const sim::World& world) {
  const engine::Mt& mt = world.mt();
  DeformedFrontier out;
  out.mesh = world.frontier().to_tet_mesh(mt, &out.vertex_ids);
  out.tet_ids.assign(world.frontier().tets().begin(), world.frontier().tets().end());
  std::sort(out.tet_ids.begin(), out.tet_ids.end());  // the order to_tet_mesh writes them in

  // A frontier vertex is a particle of the spring model: take its simulated
  // position. Should one not be (a model not rebuilt yet), ask the World.
  const std::vector<std::int32_t> particle = world.model().particle_of(mt.num_vertices());
  const bool all_simulated = std::all_of(out.vertex_ids.begin(), out.vertex_ids.end(),
                                         [&](engine::VertId v) { return particle[v.index()] >= 0; });
  if (all_simulated) {
    for (std::size_t i = 0; i < out.vertex_ids.size(); ++i)
      out.mesh.positions[i] = world.state().x[static_cast<std::size_t>(particle[out.vertex_ids[i].index()])];
  } else {
    const std::vector<engine::Vec3> deformed = world.deformed_positions();
    for (std::size_t i = 0; i < out.vertex_ids.size(); ++i) out.mesh.positions[i] = deformed[out.vertex_ids[i].index()];
  }
  return out;
}

SnapshotSeries::SnapshotSeries(std::string dir, std::size_t first_cut_vertex, SurfaceKind surface)
    : dir_(std::move(dir)), first_cut_vertex_(first_cut_vertex), surface_(surface) {}

void SnapshotSeries::write(const sim::World& world) {
  const engine::Mt& mt = world.mt();
  if (levels_.empty() || levels_revision_ != mt.revision()) {
    levels_ = fragment_levels(mt);
    levels_revision_ = mt.revision();
  }
  const DeformedFrontier frontier = deform_frontier(world);
  const PieceLabels pieces = label_pieces(frontier.mesh);
  const std::size_t n = frontier.tet_ids.size();
  engine::CellField piece{"piece", std::vector<double>(n)};
  engine::CellField level{"fragment_level", std::vector<double>(n)};
  engine::CellField made_by_cut{"made_by_cut", std::vector<double>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    const engine::TetId t = frontier.tet_ids[i];
    piece.values[i] = pieces.tet_piece[i];
    level.values[i] = levels_[mt.birth(t).index()];
    const engine::Tet& tet = mt.tet(t);
    made_by_cut.values[i] =
        std::any_of(tet.begin(), tet.end(), [&](engine::VertId v) { return v.index() >= first_cut_vertex_; }) ? 1 : 0;
  }
  char name[40];
  std::snprintf(name, sizeof name, "snapshot_%06llu.vtu", static_cast<unsigned long long>(world.frame()));
  engine::write_vtu(frontier.mesh, (std::filesystem::path(dir_) / name).string(), {piece, level, made_by_cut});
  entries_.emplace_back(world.time(), name);
  last_frame_ = static_cast<std::int64_t>(world.frame());
  write_collection(kCollection, entries_);
  if (writes_surface()) write_surface(world, frontier, pieces.tet_piece);
}

void SnapshotSeries::write_surface(const sim::World& world, const DeformedFrontier& frontier,
                                   const std::vector<std::int32_t>& piece) {
  const engine::Mt& mt = world.mt();
  finest_ = sim::carry_finest_surface(mt, world.frontier(), world.model(), finest_ ? &*finest_ : nullptr);
  const sim::FinestSurface& surface = *finest_;
  const std::size_t n = surface.num_faces();
  engine::CellField face_piece{"piece", std::vector<double>(n)};
  engine::CellField level{"fragment_level", std::vector<double>(n)};
  engine::CellField made_by_cut{"made_by_cut", std::vector<double>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    const std::array<std::int32_t, 3>& face = surface.faces[i];
    const engine::TetId carrier = surface.carrier[static_cast<std::size_t>(face[0])];
    const auto at = std::lower_bound(frontier.tet_ids.begin(), frontier.tet_ids.end(), carrier);
    face_piece.values[i] = piece[static_cast<std::size_t>(at - frontier.tet_ids.begin())];
    level.values[i] = levels_[mt.birth(carrier).index()];
    made_by_cut.values[i] = std::all_of(face.begin(), face.end(), [&](std::int32_t u) {
                              return surface.vertices[static_cast<std::size_t>(u)].index() >= first_cut_vertex_;
                            })
                                ? 1
                                : 0;
  }
  char name[40];
  std::snprintf(name, sizeof name, "surface_%06llu.vtu", static_cast<unsigned long long>(world.frame()));
  engine::write_vtu(sim::deformed_finest_surface(surface, world.state().x), (std::filesystem::path(dir_) / name).string(),
                    {face_piece, level, made_by_cut});
  surface_entries_.emplace_back(world.time(), name);
  write_collection(kSurfaceCollection, surface_entries_);
}

void SnapshotSeries::write_collection(const char* file_name, const Entries& entries) const {
  engine::write_stream_atomically((std::filesystem::path(dir_) / file_name).string(), [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\">\n"
        << "  <Collection>\n";
    for (const auto& [time, file] : entries)
      out << "    <DataSet timestep=\"" << format_real(time) << "\" group=\"\" part=\"0\" file=\"" << file << "\"/>\n";
    out << "  </Collection>\n"
        << "</VTKFile>\n";
  });
}

void write_deformed_surface(const sim::World& world, const std::string& path, SurfaceKind which) {
  if (which == SurfaceKind::kFrontier) {
    engine::write_surface_file(engine::extract_boundary(deform_frontier(world).mesh), path);
    return;
  }
  const sim::FinestSurface surface = sim::carry_finest_surface(world.mt(), world.frontier(), world.model());
  engine::write_surface_file(sim::deformed_finest_surface(surface, world.state().x), path);
}

}  // namespace mtcut::app
