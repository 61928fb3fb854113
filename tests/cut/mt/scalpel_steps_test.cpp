// A stroke cut step by step, as a haptic loop would feed the cutter: each
// step the quad the blade swept since the last.
#include <gtest/gtest.h>

#include "tests/cut/mt/mt_cut_test_util.h"

namespace mtcut::test {
namespace {

// Vertices some live tet uses.
std::vector<std::uint8_t> used_vertices(const Mt& mt) {
  std::vector<std::uint8_t> used(mt.num_vertices(), 0);
  for (std::size_t t = 0; t < mt.num_tets(); ++t)
    if (mt.alive(TetId(t)))
      for (VertId v : mt.tet(TetId(t))) used[v.index()] = 1;
  return used;
}

// Cuts `steps` quads of a blade along y = path(x) (x across the MT's box,
// z from above its top down to 0.6 of its height). After every step the MT
// is valid and every vertex the step made is used; at the end no
// finest-frontier tet is properly crossed by any quad.
template <class Path>
void cut_steps(const std::string& name, int steps, Path&& path) {
  Mt mt = cut_test_mt(name);
  engine::TetBvh bvh(mt);
  const engine::Aabb box = mt_box(mt);
  const Vec3 size = box.hi - box.lo;
  const double top = box.hi.z() + 0.05 * size.z(), bottom = box.hi.z() - 0.6 * size.z();
  const auto x_at = [&](int k) { return box.lo.x() - 0.02 * size.x() + 1.04 * size.x() * k / steps; };
  const auto y_at = [&](double x) { return box.center().y() + size.y() * path((x - box.lo.x()) / size.x()); };
  std::vector<CutPolygon> cut_so_far;
  std::size_t split = 0, relabeled = 0;
  for (int k = 0; k < steps; ++k) {
    const double xa = x_at(k), xb = x_at(k + 1);
    const CutPolygon quad = CutPolygon::from_points(
        {Vec3(xa, y_at(xa), top), Vec3(xb, y_at(xb), top), Vec3(xb, y_at(xb), bottom), Vec3(xa, y_at(xa), bottom)});
    const cut::MtChangeReport r = cut::cut_mt(mt, bvh, quad);
    const auto report = mt.validate();
    ASSERT_TRUE(report.ok()) << name << " step " << k << ": " << report.summary();
    const std::vector<std::uint8_t> after = used_vertices(mt);
    for (const auto& made : r.made_vertices) ASSERT_TRUE(after[made.id.index()]) << name << " step " << k;
    split += r.counts.split_tets;
    relabeled += r.counts.relabeled_tets;
    cut_so_far.push_back(quad);
  }
  EXPECT_GT(split, 0u) << name;
  const Frontier finest = engine::Frontier::finest(mt);
  for (const CutPolygon& quad : cut_so_far)
    EXPECT_EQ(properly_crossed_tets(mt, finest, quad, longest_edge_near(mt, bvh, quad)), 0u) << name;
  std::printf("[ report   ] %s: %d steps, %zu tets split, %zu relabelled\n", name.c_str(), steps, split, relabeled);
}

// Known defect (found this session, left for the cutter's next issue): a
// stroke cut step by step, each step the quad the blade swept since the
// last, leaves the MT invalid within a few steps. On a curved path (each
// quad turning a little from the last) the finest frontier gets a
// non-manifold boundary edge where two quads meet, from the second step on.
// On a straight one each quad lies in the plane of the last, whose cut points
// then lie on the new plane up to rounding and snap onto it: the cut surface
// bends through them only in the resolutions that hold them, and a
// fragment's two tessellations stop covering the same region. Traced on the
// ellipsoid (step 5): the vertices earlier steps made lie on the plane with
// sides decided by rounding (or by their neighbours' lean, when kept off the
// cut), so an edge between two of them can "straddle"; its cut point (at the
// 1e-6 snap floor) and the face points beside it land on the plane with its
// ends, and the LUT makes a flat tet.
// Making such vertices kOnInactive is wrong (a crack copy belongs to one
// side: step 6 then joins a - and a + copy); a vertex would have to carry
// the plane and side it was made on, for a later cut in that plane. The World
// does not cut per step: it merges a stroke into one polygon per straight
// part (cut/stroke_sweep.h), cut when the part ends; see also
// MeshCutterProperties.DISABLED_ManyStrokesSeparateLikeOneCut.
TEST(ScalpelSteps, DISABLED_CurvedStrokeCutStepByStepKeepsTheMtValid) {
  for (const std::string name : {"ellipsoid", "liver"})
    cut_steps(name, 24, [](double u) { return 0.0137 + 0.3 * u * u; });
}

TEST(ScalpelSteps, DISABLED_StraightStrokeCutStepByStepKeepsTheMtValid) {
  for (const std::string name : {"ellipsoid", "liver"})
    cut_steps(name, 24, [](double u) { return 0.0137 + 0.013 * u; });
}

}  // namespace
}  // namespace mtcut::test
