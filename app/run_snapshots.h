#pragma once
// The geometric outputs of `mtcut run`: .vtu snapshots of the frontier at
// its deformed positions with per-tet data and of the finest surface it
// carries, the .pvd collections that list them with their times (ParaView
// plays each as a time series), and the final surface. Every file is written atomically, and the collection is
// rewritten after each snapshot, so an interrupted run leaves a valid series.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/scenario.h"
#include "engine/tet_mesh.h"
#include "sim/finest_surface.h"
#include "sim/world.h"

namespace mtcut::app {

// A World's frontier as a compact tet mesh at the deformed positions.
struct DeformedFrontier {
  engine::TetMesh mesh;                    // deformed positions, tets in ascending MT tet id
  std::vector<engine::VertId> vertex_ids;  // (n_vertices) the MT vertex of each
  std::vector<engine::TetId> tet_ids;      // (n_tets) the MT tet of each
};

DeformedFrontier deform_frontier(const sim::World& world);

class SnapshotSeries {
 public:
  // Files go into dir (which exists). MT vertices with ids >= first_cut_vertex
  // (the MT's vertex count when the run started) were made by cuts.
  // `surface`: kFinest adds the finest surface's series.
  SnapshotSeries(std::string dir, std::size_t first_cut_vertex, SurfaceKind surface);

  // Writes snapshot_<frames done, 6 digits>.vtu (the frontier's tets) with
  // cell data piece, fragment_level and made_by_cut, then rewrites
  // snapshots.pvd; with the finest surface, also surface_<frames>.vtu (its
  // triangles, the same cell data: the level of the tet carrying a face's
  // first corner) and surface.pvd.
  void write(const sim::World& world);

  std::size_t count() const { return entries_.size(); }
  // The frame count of the last snapshot written (none: -1).
  std::int64_t last_frame() const { return last_frame_; }
  static constexpr const char* kCollection = "snapshots.pvd";
  static constexpr const char* kSurfaceCollection = "surface.pvd";
  bool writes_surface() const { return surface_ == SurfaceKind::kFinest; }

 private:
  using Entries = std::vector<std::pair<double, std::string>>;  // (simulated time, file name) per snapshot
  void write_collection(const char* name, const Entries& entries) const;
  void write_surface(const sim::World& world, const DeformedFrontier& frontier, const std::vector<std::int32_t>& piece);

  std::string dir_;
  std::size_t first_cut_vertex_;
  SurfaceKind surface_;
  std::optional<sim::FinestSurface> finest_;  // the last one carried (its carriers are kept while they hold)
  Entries entries_, surface_entries_;
  std::vector<std::int32_t> levels_;                     // fragment_levels at levels_revision_
  std::uint64_t levels_revision_ = 0;
  std::int64_t last_frame_ = -1;
};

// The deformed surface of every piece as a surface file (.obj),
// atomically: the finest surface carried by the frontier, or the
// frontier's own (SurfaceKind).
void write_deformed_surface(const sim::World& world, const std::string& path, SurfaceKind which);

}  // namespace mtcut::app
