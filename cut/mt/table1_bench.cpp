#include "cut/mt/table1_bench.h"

#include <algorithm>

#include "cut/mt/mt_cut.h"
#include "cut/mt/mt_pieces.h"
#include "engine/quantiles.h"

namespace mtcut::cut {
namespace {

CutPolygon table1_polygon(const engine::Mt& mt, double half_size) {
  engine::Aabb box;
  for (const Vec3& p : mt.positions()) box.extend(p);
  const Vec3 size = box.hi - box.lo;
  const Vec3 centre = box.center() + Vec3(0.0131, 0.0, 0.0077).cwiseProduct(size) + Vec3(0, 0, 0.1 * size.z());
  const Vec3 a = Vec3(1, 0.0113, 0.0171).normalized();
  const Vec3 b = Vec3(-0.0089, 1, 0.0123).normalized();
  const double h = half_size * size.norm();
  // Partial cuts reach in from one side: the square's centre is shifted
  // along a so that it covers the model's edge there.
  const Vec3 c = half_size < 1 ? Vec3(centre - (0.5 * size.x() - h) * a) : centre;
  return CutPolygon::from_points({c + h * (a + b), c + h * (b - a), c - h * (a + b), c + h * (a - b)});
}

}  // namespace

Table1Result run_table1(const engine::Mt& mt, const Table1Def& def) {
  Table1Result result;
  result.mt_vertices = mt.num_vertices();
  result.mt_tets = mt.num_live_tets();
  result.mt_fragments = mt.num_fragments();
  SplitTable lut(SplitScheme::kLut), b17(SplitScheme::kBielser17);
  MtCutWorkspace workspace;
  for (double half : def.half_sizes) {
    const CutPolygon polygon = table1_polygon(mt, half);
    Table1Row row;
    row.half_size = half;
    {  // the 1:17 reference: counts only (also warms the LUT's generator)
      engine::Mt copy = mt;
      engine::TetBvh bvh(copy);
      CutMtOptions options;
      options.def.scheme = SplitScheme::kBielser17;
      row.new_tets_bielser17 = cut_mt(copy, bvh, polygon, {}, options, &b17).counts.new_tets;
    }
    std::vector<double> split_ms, dag_ms, total_ms;
    for (int run = 0; run <= def.runs; ++run) {  // run 0 warms up
      engine::Mt copy = mt;
      engine::TetBvh bvh(copy);
      const MtChangeReport r = cut_mt(copy, bvh, polygon, {}, {}, &lut, &workspace);
      if (run == 0) {
        row.split_fragments = r.counts.split_fragments;
        row.split_tets = r.counts.split_tets + r.counts.relabeled_tets;
        row.new_tets_lut = r.counts.new_tets;
        row.pieces = count_pieces(copy);
        continue;
      }
      const double split = 1e3 * (r.counts.find_seconds + r.counts.split_seconds);
      const double dag = 1e3 * r.counts.dag_seconds;
      split_ms.push_back(split);
      dag_ms.push_back(dag);
      total_ms.push_back(split + dag);
    }
    row.split_ms = engine::median(split_ms);
    row.dag_update_ms = engine::median(dag_ms);
    row.total_ms = engine::median(total_ms);
    result.rows.push_back(row);
  }
  return result;
}

}  // namespace mtcut::cut
