#include "cut/mt/frame_step_bench.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "cut/mt/mt_cut.h"
#include "engine/quantiles.h"

namespace mtcut::cut {
namespace {

// The quad the blade sweeps in frame `step`: the blade reaches from above
// the model's top down into it, and moves along a gentle curve across the
// model's length (each quad in its own plane, none through a vertex exactly).
CutPolygon frame_quad(const engine::Aabb& box, const FrameStepDef& def, int step) {
  const Vec3 size = box.hi - box.lo;
  const double x0 = box.lo.x() + size.x() * (0.02 + def.stride * step);
  const double x1 = x0 + def.sweep_width * size.x();
  const auto y_at = [&](double x) {
    const double u = (x - box.lo.x()) / size.x();
    return box.center().y() + size.y() * (0.0137 + 0.2 * u * u);
  };
  const double top = box.hi.z() + 0.05 * size.z(), bottom = box.hi.z() - def.blade_depth * size.z();
  return CutPolygon::from_points({Vec3(x0, y_at(x0), top), Vec3(x1, y_at(x1), top + 0.0071 * size.z()),
                                  Vec3(x1, y_at(x1), bottom), Vec3(x0, y_at(x0), bottom)});
}

}  // namespace

FrameStepResult run_frame_steps(const engine::Mt& mt, const FrameStepDef& def, engine::Mt* after) {
  if (def.steps < 1 || def.runs < 1) throw std::invalid_argument("run_frame_steps: steps and runs must be positive");
  if (!(def.stride > def.sweep_width && def.sweep_width > 0))
    throw std::invalid_argument("run_frame_steps: the stride must exceed the sweep width (steps must not touch)");
  engine::Aabb box;
  for (const Vec3& p : mt.positions()) box.extend(p);
  SplitTable lut(SplitScheme::kLut);
  MtCutWorkspace workspace;  // as the time-critical cutter reuses its own
  const auto steps = static_cast<std::size_t>(def.steps);
  std::vector<std::size_t> split(steps), made(steps);
  std::vector<std::vector<double>> runs(steps);
  for (int run = 0; run <= def.runs; ++run) {  // run 0 warms up and counts
    engine::Mt copy = mt;
    engine::TetBvh bvh(copy);
    for (std::size_t step = 0; step < steps; ++step) {
      const MtChangeReport r = cut_mt(copy, bvh, frame_quad(box, def, static_cast<int>(step)), {}, {}, &lut, &workspace);
      if (run == 0) {
        split[step] = r.counts.split_tets + r.counts.relabeled_tets;
        made[step] = r.counts.new_tets;
      } else {
        runs[step].push_back(1e3 * (r.counts.find_seconds + r.counts.split_seconds + r.counts.dag_seconds));
      }
    }
    if (after && run == def.runs) *after = std::move(copy);
  }
  std::vector<double> ms;
  for (const auto& r : runs) ms.push_back(engine::median(r));
  std::sort(ms.begin(), ms.end());
  std::sort(split.begin(), split.end());
  std::sort(made.begin(), made.end());
  FrameStepResult result;
  result.steps = steps;
  result.split_tets_median = engine::nearest_rank<std::size_t>(split, 0.5);
  result.split_tets_max = split.back();
  result.new_tets_median = engine::nearest_rank<std::size_t>(made, 0.5);
  result.ms_median = engine::median(ms);
  result.ms_p90 = engine::nearest_rank<double>(ms, 0.9);
  result.ms_max = ms.back();
  return result;
}

}  // namespace mtcut::cut
