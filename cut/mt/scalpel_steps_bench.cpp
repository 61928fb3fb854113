#include "cut/mt/scalpel_steps_bench.h"

#include <algorithm>
#include <chrono>

#include "cut/mt/mt_cut.h"

namespace mtcut::cut {
namespace {

using Clock = std::chrono::steady_clock;

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))];
}

}  // namespace

ScalpelStepsResult run_scalpel_steps(const engine::Mt& mt, const ScalpelStepsDef& def) {
  engine::Aabb box;
  for (const Vec3& p : mt.positions()) box.extend(p);
  const Vec3 size = box.hi - box.lo;
  // The blade: a segment along z, from above the top down to `depth`, moved
  // along x at a slightly slanted y (so that it meets no vertex exactly).
  const double x0 = box.lo.x() - 0.02 * size.x(), x1 = box.hi.x() + 0.02 * size.x();
  const double top = box.hi.z() + 0.05 * size.z(), bottom = box.hi.z() - def.depth * size.z();
  const auto blade_y = [&](double x) { return box.center().y() + 0.0137 * size.y() + 0.013 * (x - x0); };
  const auto at = [&](int k) { return x0 + (x1 - x0) * static_cast<double>(k) / def.steps; };

  ScalpelStepsResult result;
  result.steps = def.steps;
  result.step_length = (x1 - x0) / def.steps;
  std::vector<double> ms;
  std::vector<double> split_tets;
  SplitTable lut(SplitScheme::kLut);
  for (int run = 0; run <= def.runs; ++run) {  // run 0 warms up (recipes, caches)
    engine::Mt copy = mt;
    engine::TetBvh bvh(copy);
    for (int k = 0; k < def.steps; ++k) {
      const double xa = at(k), xb = at(k + 1);
      const CutPolygon quad = CutPolygon::from_points({Vec3(xa, blade_y(xa), top), Vec3(xb, blade_y(xb), top),
                                                       Vec3(xb, blade_y(xb), bottom), Vec3(xa, blade_y(xa), bottom)});
      const bool rebuild = bvh.worn();
      const auto start = Clock::now();
      const MtChangeReport r = cut_mt(copy, bvh, quad, {}, {}, &lut);
      const double step_ms = 1e3 * std::chrono::duration<double>(Clock::now() - start).count();
      const std::size_t changed = r.counts.split_tets + r.counts.relabeled_tets;
      if (run == 1) {
        result.total_split_tets += changed;
        result.total_new_tets += r.counts.new_tets;
        result.total_relabeled_tets += r.counts.relabeled_tets;
        result.index_rebuilds += rebuild;
      }
      if (run == 0 || changed == 0) continue;
      ms.push_back(step_ms);
      split_tets.push_back(static_cast<double>(changed));
    }
  }
  result.median_ms = quantile(ms, 0.5);
  result.p95_ms = quantile(ms, 0.95);
  result.max_ms = quantile(ms, 1.0);
  result.median_split_tets = static_cast<std::size_t>(quantile(split_tets, 0.5));
  result.max_split_tets = static_cast<std::size_t>(quantile(split_tets, 1.0));
  return result;
}

}  // namespace mtcut::cut
