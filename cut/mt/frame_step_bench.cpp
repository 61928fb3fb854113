#include "cut/mt/frame_step_bench.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "cut/mt/mt_cut.h"

namespace mtcut::cut {
namespace {

// The value at fraction q of the sorted values (nearest rank).
template <class T>
T quantile(std::vector<T> v, double q) {
  std::sort(v.begin(), v.end());
  return v.empty() ? T{} : v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))];
}

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
  const auto steps = static_cast<std::size_t>(def.steps);
  std::vector<std::size_t> split(steps), made(steps);
  std::vector<std::vector<double>> runs(steps);
  for (int run = 0; run <= def.runs; ++run) {  // run 0 warms up and counts
    engine::Mt copy = mt;
    engine::TetBvh bvh(copy);
    for (std::size_t step = 0; step < steps; ++step) {
      const MtChangeReport r = cut_mt(copy, bvh, frame_quad(box, def, static_cast<int>(step)), {}, {}, &lut);
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
  for (const auto& r : runs) ms.push_back(quantile(r, 0.5));
  FrameStepResult result;
  result.steps = steps;
  result.split_tets_median = quantile(split, 0.5);
  result.split_tets_max = quantile(split, 1.0);
  result.new_tets_median = quantile(made, 0.5);
  result.ms_median = quantile(ms, 0.5);
  result.ms_p90 = quantile(ms, 0.9);
  result.ms_max = quantile(ms, 1.0);
  return result;
}

}  // namespace mtcut::cut
