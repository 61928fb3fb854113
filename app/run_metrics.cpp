#include "app/run_metrics.h"

#include <ostream>

#include "app/run_format.h"
#include "engine/atomic_file.h"

namespace mtcut::app {

double kinetic_energy(const sim::SpringModel& model, const sim::SpringState& state) {
  double energy = 0;
  for (std::size_t p = 0; p < model.num_particles() && p < state.v.size(); ++p)
    energy += model.mass[p] * state.v[p].squaredNorm();
  return 0.5 * energy;
}

MetricsRow record_frame(const sim::World& world) {
  MetricsRow row;
  row.frame = world.last_frame();
  row.cut_jobs_pending = world.last_frame().cut_jobs_pending;
  row.kinetic_energy = kinetic_energy(world.model(), world.state());
  row.pieces = static_cast<int>(world.pieces());
  return row;
}

void write_metrics_csv(const std::string& path, std::span<const MetricsRow> rows) {
  engine::write_stream_atomically(path, [&](std::ostream& out) {
    out << "frame,sim_time,frontier_tets,frontier_vertices,cut_jobs_pending,cut_ms,lod_ms,sim_ms,frame_ms,"
           "kinetic_energy,pieces,cut_vertices,provisional_tets\n";
    for (const MetricsRow& r : rows) {
      const sim::FrameMetrics& m = r.frame;
      out << m.frame + 1 << ',' << format_real(m.time) << ',' << m.frontier_tets << ',' << m.frontier_vertices << ','
          << r.cut_jobs_pending << ',' << format_real(m.cut_ms) << ',' << format_real(m.lod_ms) << ','
          << format_real(m.physics_ms) << ',' << format_real(m.total_ms) << ',' << format_real(r.kinetic_energy)
          << ',' << r.pieces << ',' << m.cut_vertices << ',' << m.provisional_tets << '\n';
    }
  });
}

void write_stage_csv(const std::string& path, std::span<const MetricsRow> rows) {
  engine::write_stream_atomically(path, [&](std::ostream& out) {
    out << "frame,time,cut_ms,lod_ms,physics_ms,total_ms,frontier_tets,frontier_vertices,springs,lod_changes,"
           "cg_iterations,refused\n";
    for (const MetricsRow& r : rows) {
      const sim::FrameMetrics& m = r.frame;
      out << m.frame << ',' << format_real(m.time) << ',' << format_real(m.cut_ms) << ',' << format_real(m.lod_ms)
          << ',' << format_real(m.physics_ms) << ',' << format_real(m.total_ms) << ',' << m.frontier_tets << ','
          << m.frontier_vertices << ',' << m.springs << ',' << m.lod_changes << ',' << m.cg_iterations << ','
          << (m.step_refused ? 1 : 0) << '\n';
    }
  });
}

}  // namespace mtcut::app
