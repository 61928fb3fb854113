#include "app/bench_stroke.h"

#include "app/bench_cut.h"

#include <algorithm>
#include <chrono>
#include <functional>

#include "app/mesh_input_options.h"
#include "cut/mt/mt_pieces.h"
#include "cut/mt/stroke_cutter.h"
#include "engine/input_error.h"
#include "engine/mesh_loader.h"
#include "engine/mt/mt_builder.h"
#include "engine/quantiles.h"

namespace mtcut::app {
namespace {

using engine::Vec3;
using Clock = std::chrono::steady_clock;

// A blade pose at s in [0, 1] of a stroke over the box [lo, hi].
using StrokePath = std::function<cut::BladePose(const Vec3& lo, const Vec3& hi, double s)>;

struct StrokeShape {
  const char* name;
  StrokePath pose;
};

// The blade is vertical, from above the top down to `depth` of the height
// (past the bottom: through); it starts and ends outside the box.
cut::BladePose vertical(const Vec3& lo, const Vec3& hi, double x, double y, double depth) {
  const Vec3 size = hi - lo;
  return {Vec3(x, y, hi.z() + 0.05 * size.z()), Vec3(x, y, hi.z() - depth * size.z()), true};
}

const std::vector<StrokeShape>& shapes() {
  static const std::vector<StrokeShape> all = {
      {"straight", [](const Vec3& lo, const Vec3& hi, double s) {
         const Vec3 size = hi - lo;
         return vertical(lo, hi, lo.x() + 0.6137 * size.x(), lo.y() - 0.05 * size.y() + 1.1 * s * size.y(), 1.1);
       }},
      {"curved", [](const Vec3& lo, const Vec3& hi, double s) {
         const Vec3 size = hi - lo;
         return vertical(lo, hi, lo.x() + (0.4137 + 0.3 * s * s) * size.x(), lo.y() - 0.05 * size.y() + 1.1 * s * size.y(), 1.1);
       }},
      {"l_turn", [](const Vec3& lo, const Vec3& hi, double s) {
         const Vec3 size = hi - lo;
         const double y0 = lo.y() - 0.05 * size.y(), x0 = lo.x() + 0.4137 * size.x();
         if (s < 0.5) return vertical(lo, hi, x0, y0 + 2 * s * 0.6 * size.y(), 1.1);
         return vertical(lo, hi, x0 + (2 * s - 1) * 0.7 * size.x(), y0 + 0.6 * size.y(), 1.1);
       }},
      {"tip_inside", [](const Vec3& lo, const Vec3& hi, double s) {
         const Vec3 size = hi - lo;
         return vertical(lo, hi, lo.x() + 0.5137 * size.x(), lo.y() - 0.05 * size.y() + 1.1 * s * size.y(), 0.6);
       }},
  };
  return all;
}

struct StrokeRun {
  std::size_t new_tets = 0, pieces = 0, steps_cut = 0;
  // The MT's storage: tet slots (live and dead) and vertices (used or not),
  // most during the stroke and after it. Every retracted provisional cut
  // leaves its pieces' slots and its vertices behind until the stroke ends
  // and the cutter reclaims them (TimeCriticalCutter::reclaim).
  std::size_t tet_slots = 0, vertices = 0, tet_slots_peak = 0, vertices_peak = 0;
  std::vector<double> step_ms;  // (steps that changed the MT)
};

// Cuts `shape` on a fresh copy of `mt` in `steps` frames of `per_frame`
// poses each, then one frame that disengages the blade.
StrokeRun cut_stroke(const engine::Mt& original, const StrokeShape& shape, int steps, int per_frame) {
  engine::Mt mt = original;
  cut::TimeCriticalCutter cutter;
  cutter.reserve(mt);  // as the World does when it is made: setup, not a step
  engine::TetBvh bvh(mt);
  engine::Frontier frontier = engine::Frontier::coarsest(mt);
  Vec3 lo = mt.position(engine::VertId(0)), hi = lo;
  for (const Vec3& p : mt.positions()) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  cut::StrokeSweep stroke;
  StrokeRun out;
  const std::size_t before = mt.num_live_tets();
  const int samples = steps * per_frame;
  std::vector<cut::BladePose> poses;
  for (int frame = 0; frame <= steps + 1; ++frame) {
    poses.clear();
    if (frame == 0) {
      poses.push_back(shape.pose(lo, hi, 0.0));
    } else if (frame <= steps) {
      for (int k = (frame - 1) * per_frame + 1; k <= frame * per_frame; ++k)
        poses.push_back(shape.pose(lo, hi, static_cast<double>(k) / samples));
    } else {
      cut::BladePose away = shape.pose(lo, hi, 1.0);
      away.engaged = false;
      poses.push_back(away);
    }
    const auto start = Clock::now();
    const cut::StrokeStep step = cut::cut_stroke_step(stroke, cutter, mt, bvh, frontier, poses);
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    if (step.recut) out.step_ms.push_back(ms);
    const std::size_t slots = step.reclaimed ? step.reclaimed->tet_map.size() : mt.num_tets();
    const std::size_t vertices = step.reclaimed ? step.reclaimed->vertex_map.size() : mt.num_vertices();
    out.tet_slots_peak = std::max(out.tet_slots_peak, slots);
    out.vertices_peak = std::max(out.vertices_peak, vertices);
  }
  out.new_tets = mt.num_live_tets() - before;
  out.tet_slots = mt.num_tets();
  out.vertices = mt.num_vertices();
  out.pieces = cut::count_pieces(mt);
  out.steps_cut = out.step_ms.size();
  return out;
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return engine::nearest_rank<double>(v, q);
}

nlohmann::ordered_json bench_organ(const std::string& name, const engine::Mt& mt, const StrokeBenchDef& def) {
  nlohmann::ordered_json organ;
  organ["mesh"] = name;
  organ["mt_live_tets"] = mt.num_live_tets();
  nlohmann::ordered_json strokes = nlohmann::ordered_json::array();
  constexpr int kOnePolygonSamples = 1000;
  for (const StrokeShape& shape : shapes()) {
    if (!def.strokes.empty() && std::find(def.strokes.begin(), def.strokes.end(), shape.name) == def.strokes.end())
      continue;
    const StrokeRun one = cut_stroke(mt, shape, 1, kOnePolygonSamples);
    nlohmann::ordered_json row;
    row["stroke"] = shape.name;
    row["one_polygon"] = {{"new_tets", one.new_tets},
                          {"pieces", one.pieces},
                          {"mt_tet_slots", one.tet_slots},
                          {"mt_vertices", one.vertices},
                          {"mt_tet_slots_peak", one.tet_slots_peak},
                          {"mt_vertices_peak", one.vertices_peak}};
    nlohmann::ordered_json progressive = nlohmann::ordered_json::array();
    for (int steps : def.steps) {
      // The mean and p90 beside the median: a turning stroke's later part
      // can cost ten times its first for half the steps, which the median,
      // falling in the first, does not show.
      std::vector<double> p50, p90, p99, max, mean;
      StrokeRun run;
      for (int r = 0; r < std::max(1, def.runs); ++r) {
        run = cut_stroke(mt, shape, steps, 1);
        p50.push_back(percentile(run.step_ms, 0.5));
        p90.push_back(percentile(run.step_ms, 0.9));
        p99.push_back(percentile(run.step_ms, 0.99));
        max.push_back(percentile(run.step_ms, 1.0));
        double sum = 0;
        for (double ms : run.step_ms) sum += ms;
        mean.push_back(run.step_ms.empty() ? 0.0 : sum / static_cast<double>(run.step_ms.size()));
      }
      progressive.push_back(
          {{"steps", steps},
           {"new_tets", run.new_tets},
           {"tets_ratio_vs_one_polygon", one.new_tets > 0 ? static_cast<double>(run.new_tets) / one.new_tets : 1.0},
           {"steps_cut", run.steps_cut},
           {"step_ms_mean", engine::median(mean)},
           {"step_ms_p50", engine::median(p50)},
           {"step_ms_p90", engine::median(p90)},
           {"step_ms_p99", engine::median(p99)},
           {"step_ms_max", engine::median(max)},
           {"pieces", run.pieces},
           {"mt_tet_slots", run.tet_slots},
           {"mt_vertices", run.vertices},
           {"mt_tet_slots_peak", run.tet_slots_peak},
           {"mt_vertices_peak", run.vertices_peak}});
      std::fprintf(stderr, "bench stroke: %s, %s, %d steps done\n", name.c_str(), shape.name, steps);
    }
    row["progressive"] = progressive;
    strokes.push_back(row);
  }
  organ["strokes"] = strokes;
  return organ;
}

}  // namespace

nlohmann::ordered_json run_stroke_bench(const StrokeBenchDef& def) {
  const std::string liver = def.liver.empty() ? default_liver_mesh() : def.liver;
  engine::MeshLoadDef load;
  load.builtin_tets = def.organ_tets;
  load.builtin_size = Vec3(0.16, 0.10, 0.07);  // the default scenario's organ
  nlohmann::ordered_json out;
  out["bench"] = "stroke";
  out["runs"] = def.runs;
  nlohmann::ordered_json organs = nlohmann::ordered_json::array();
  // Both MTs first: a bad mesh fails before any stroke is cut.
  const std::vector<std::string> specs = {"builtin:ellipsoid", liver};
  std::vector<engine::Mt> mts;
  for (const std::string& spec : specs) mts.push_back(engine::build_mt(load_input_mesh(spec, load).mesh, {}));
  for (std::size_t i = 0; i < specs.size(); ++i) organs.push_back(bench_organ(specs[i], mts[i], def));
  out["organs"] = organs;
  return out;
}

}  // namespace mtcut::app
