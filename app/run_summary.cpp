#include "app/run_summary.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <sstream>

#include "app/run_piece_report.h"
#include "engine/quantiles.h"

namespace mtcut::app {
namespace {

// mean, median, 95th and 99th percentiles and max of a series (null when empty).
nlohmann::ordered_json distribution(std::vector<double> values) {
  if (values.empty()) return nullptr;
  std::sort(values.begin(), values.end());
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
  return {{"mean", mean},
          {"p50", engine::nearest_rank<double>(values, 0.50)},
          {"p95", engine::nearest_rank<double>(values, 0.95)},
          {"p99", engine::nearest_rank<double>(values, 0.99)},
          {"max", values.back()}};
}

std::string hex(std::uint64_t v) {
  std::ostringstream s;
  s << std::hex << std::setw(16) << std::setfill('0') << v;
  return s.str();
}

// A figure of a distribution, or null.
nlohmann::ordered_json figure(const nlohmann::ordered_json& dist, const char* key) {
  return dist.is_null() ? nlohmann::ordered_json(nullptr) : dist[key];
}

// A number with `digits` decimals, or "n/a" for null.
std::string fixed(const nlohmann::ordered_json& value, int digits) {
  if (!value.is_number()) return "n/a";
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << value.get<double>();
  return s.str();
}

// " (piece 1 free, 0.9 to 2.1 cm above the floor, ...)": where the pieces
// that nothing holds came to rest, or "" when every piece is held.
std::string piece_places(const nlohmann::ordered_json& s) {
  if (!s.contains("piece_details")) return "";
  std::ostringstream p;
  const auto& pieces = s["piece_details"];
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (pieces[i]["held_particles"].get<std::size_t>() > 0) continue;
    p << (p.tellp() == 0 ? " (" : "; ") << "piece " << i << " free, z " << fixed(pieces[i]["lowest_z"], 3) << " to "
      << fixed(pieces[i]["highest_z"], 3) << " m";
  }
  if (p.tellp() > 0) p << ")";
  return p.str();
}

}  // namespace

nlohmann::ordered_json summarize_run(const ScenarioDef& scenario, const RunRecord& record, const sim::World& world) {
  std::vector<double> frame_ms, cut_ms, lod_ms, physics_ms;
  std::size_t min_tets = world.frontier().tets().size(), max_tets = min_tets;
  long cg_iterations = 0;
  for (const MetricsRow& row : record.rows) {
    const sim::FrameMetrics& m = row.frame;
    frame_ms.push_back(m.total_ms);
    cut_ms.push_back(m.cut_ms);
    lod_ms.push_back(m.lod_ms);
    physics_ms.push_back(m.physics_ms);
    min_tets = std::min(min_tets, m.frontier_tets);
    max_tets = std::max(max_tets, m.frontier_tets);
    cg_iterations += m.cg_iterations;
  }
  const auto frames = static_cast<int>(record.rows.size());
  const nlohmann::ordered_json frame_dist = distribution(frame_ms), cut_dist = distribution(cut_ms);
  const engine::ValidationReport valid = world.validate();
  const engine::MtStats& mt = record.mt_stats;

  nlohmann::ordered_json out;
  out["scenario"] = scenario.file;
  out["mesh"] = scenario.mesh;
  if (!scenario.scalpel_trace.empty()) out["scalpel_trace"] = scenario.scalpel_trace;
  out["frames"] = frames;
  out["pieces"] = record.rows.empty() ? 1 : record.rows.back().pieces;
  out["tets_total"] = world.mt().num_live_tets();
  out["frontier_tets_final"] = world.frontier().tets().size();
  out["cut_ms_mean"] = figure(cut_dist, "mean");
  out["cut_ms_max"] = figure(cut_dist, "max");
  out["frame_ms_mean"] = figure(frame_dist, "mean");
  out["frame_ms_p99"] = figure(frame_dist, "p99");
  out["nan_events"] = world.nan_events();
  // Cuts the cutter took back because they would have broken the MT
  // (cut/mt/cut_guard.h): that part of a stroke's incision does not show.
  out["cuts_refused"] = world.cutter().cuts_refused();
  // The first frame (as metrics.csv numbers them) whose frontier shows a cut.
  out["first_cut_frame"] = nullptr;
  for (const MetricsRow& r : record.rows)
    if (r.frame.cut_vertices > 0) {
      out["first_cut_frame"] = r.frame.frame + 1;
      break;
    }
  nlohmann::ordered_json strokes = nlohmann::ordered_json::array();
  for (const sim::StrokeRecord& stroke : world.strokes())
    strokes.push_back({{"first_frame", stroke.first_frame + 1},
                       {"last_frame", stroke.last_frame + 1},
                       {"finished", stroke.finished},
                       {"new_tets", static_cast<std::int64_t>(stroke.live_tets_after) -
                                        static_cast<std::int64_t>(stroke.live_tets_before)},
                       {"tets_growth", stroke.live_tets_before > 0 ? static_cast<double>(stroke.live_tets_after) /
                                                                         static_cast<double>(stroke.live_tets_before)
                                                                   : 1.0}});
  out["strokes"] = strokes;
  out["state_hash"] = hex(world.state_hash());
  out["frames_requested"] = record.frames_requested;
  out["interrupted"] = record.interrupted;
  out["simulated_seconds"] = world.time();
  out["setup_seconds"] = record.setup_seconds;
  out["run_seconds"] = record.run_seconds;
  out["mt"] = {{"vertices", mt.vertices},       {"tets_total", mt.tets_total},
               {"fragments", mt.fragments},     {"dag_depth", mt.dag_depth},
               {"finest_tets", mt.finest_tets}, {"coarsest_tets", mt.coarsest_tets},
               {"coarsest_surface_deviation", mt.coarsest_surface_deviation}};
  out["frame_ms"] = frame_dist;
  out["cut_ms"] = cut_dist;
  out["lod_ms"] = distribution(lod_ms);
  out["physics_ms"] = distribution(physics_ms);
  out["frontier_tets"] = {{"min", min_tets}, {"max", max_tets}, {"final", world.frontier().tets().size()}};
  out["mean_cg_iterations"] = frames > 0 ? static_cast<double>(cg_iterations) / frames : 0.0;
  nlohmann::ordered_json pieces = nlohmann::ordered_json::array();
  for (const PieceReport& piece : report_pieces(world))
    pieces.push_back({{"tets", piece.tets},
                      {"rest_volume", piece.rest_volume},
                      {"centroid", {piece.centroid.x(), piece.centroid.y(), piece.centroid.z()}},
                      {"lowest_z", piece.lowest_z},
                      {"highest_z", piece.highest_z},
                      {"held_particles", piece.held_particles}});
  out["piece_details"] = pieces;
  out["valid"] = valid.ok();
  if (!valid.ok()) out["problems"] = valid.problems;
  return out;
}

void print_run_paragraph(std::ostream& out, const nlohmann::ordered_json& s) {
  const int frames = s["frames"].get<int>();
  std::ostringstream p;
  if (s["interrupted"].get<bool>()) {
    p << "Interrupted after " << frames << " of " << s["frames_requested"].get<int>() << " frames";
  } else {
    p << "Ran " << frames << " frames";
  }
  p << " of " << s["scenario"].get<std::string>() << " (" << fixed(s["simulated_seconds"], 2)
    << " s simulated) in " << fixed(s["run_seconds"], 2) << " s, after " << fixed(s["setup_seconds"], 2)
    << " s to mesh the organ and build its MT (" << s["mt"]["tets_total"].get<std::size_t>() << " tets in "
    << s["mt"]["fragments"].get<std::size_t>() << " fragments). The frontier held "
    << s["frontier_tets"]["min"].get<std::size_t>() << " to " << s["frontier_tets"]["max"].get<std::size_t>()
    << " tets and ended with " << s["frontier_tets_final"].get<std::size_t>() << " in " << s["pieces"].get<int>()
    << (s["pieces"].get<int>() == 1 ? " piece" : " pieces") << piece_places(s) << "; a frame took " << fixed(s["frame_ms_mean"], 2)
    << " ms on average (p99 " << fixed(s["frame_ms_p99"], 2) << " ms), cutting " << fixed(s["cut_ms_mean"], 3)
    << " ms (max " << fixed(s["cut_ms_max"], 3) << " ms). " << s["nan_events"].get<std::uint64_t>()
    << " NaN events";
  if (s["nan_events"].get<std::uint64_t>() > 0)
    p << " (steps refused for a NaN or a runaway speed: the state before each was kept, so the tissue stood still"
         " in those frames; an explicit step too long for the smallest elements, which a cut can make, does this:"
         " raise [integrator] substeps or use the implicit integrator)";
  if (s["cuts_refused"].get<std::size_t>() > 0)
    p << "; " << s["cuts_refused"].get<std::size_t>()
      << " cuts taken back where a stroke's new crack would have pinched the MT against an older one (that part of"
         " the incision does not show)";
  if (!s["first_cut_frame"].is_null())
    p << "; the first cut showed at frame " << s["first_cut_frame"].get<std::uint64_t>();
  p << "; the MT, frontier and springs are " << (s["valid"].get<bool>() ? "valid" : "NOT valid");
  if (s.contains("problems") && !s["problems"].empty()) {
    p << " (" << s["problems"].front().get<std::string>();
    if (s["problems"].size() > 1) p << "; " << s["problems"].size() - 1 << " more in summary.json";
    p << ")";
  }
  p << "; state hash " << s["state_hash"].get<std::string>() << ".";
  if (s.contains("outputs")) {
    const auto& o = s["outputs"];
    p << " Outputs in " << o["dir"].get<std::string>() << ": metrics.csv, summary.json";
    if (o["snapshots"].get<int>() > 0)
      p << ", " << o["snapshots"].get<int>() << " snapshots (" << o["pvd"].get<std::string>()
        << (o.value("surface_pvd", "").empty() ? "" : ", " + o["surface_pvd"].get<std::string>()) << ")";
    p << ", " << o["surface"].get<std::string>();
    if (o.contains("trace")) p << "; scalpel trace " << o["trace"].get<std::string>();
    p << ".";
  }
  out << p.str() << "\n";
}

}  // namespace mtcut::app
