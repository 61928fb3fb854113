// A stroke cut step by step, as a haptic loop would feed the cutter: each
// step a blade pose, the stroke's straight parts cut for good as they end
// and the part in progress cut provisionally, the last step's provisional
// cut taken back first (cut/mt/cut_retraction.h).
#include <gtest/gtest.h>

#include "cut/mt/mt_pieces.h"
#include "cut/mt/stroke_cutter.h"
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

struct StrokeDef {
  int steps = 24;
  double depth = 0.6;     // how far below the MT box's top the blade reaches, times its height
};

struct StrokeResult {
  Mt mt;
  std::size_t split = 0, relabeled = 0;
};

// Cuts a blade along y = path(x) (x across the MT's box, z from above its
// top down to `depth` of its height), a pose per step. After every step the
// MT, its BVH and a frontier that follows the cuts (from the coarsest) are
// valid, and every vertex the step made is used; at the end no
// finest-frontier tet is properly crossed by any quad the blade swept.
template <class Path>
StrokeResult cut_steps(const std::string& name, const StrokeDef& def, Path&& path) {
  StrokeResult out{cut_test_mt(name)};
  Mt& mt = out.mt;
  engine::TetBvh bvh(mt);
  Frontier frontier = Frontier::coarsest(mt);
  const engine::Aabb box = mt_box(mt);
  const Vec3 size = box.hi - box.lo;
  const double top = box.hi.z() + 0.05 * size.z(), bottom = box.hi.z() - def.depth * size.z();
  const auto x_at = [&](int k) { return box.lo.x() - 0.02 * size.x() + 1.04 * size.x() * k / def.steps; };
  const auto y_at = [&](double x) { return box.center().y() + size.y() * path((x - box.lo.x()) / size.x()); };
  std::vector<CutPolygon> swept;
  cut::StrokeSweep stroke;
  cut::TimeCriticalCutter cutter;
  for (int k = 0; k <= def.steps + 1; ++k) {
    const std::string where = name + " step " + std::to_string(k);
    const double x = x_at(std::min(k, def.steps));
    const cut::BladePose pose{Vec3(x, y_at(x), top), Vec3(x, y_at(x), bottom), k <= def.steps};
    if (k > 0 && k <= def.steps) {
      const double xa = x_at(k - 1);
      swept.push_back(CutPolygon::from_points({Vec3(xa, y_at(xa), top), Vec3(x, y_at(x), top),
                                               Vec3(x, y_at(x), bottom), Vec3(xa, y_at(xa), bottom)}));
    }
    const cut::StrokeStep step = cut::cut_stroke_step(stroke, cutter, mt, bvh, frontier, std::span(&pose, 1));
    if (!step.recut) continue;
    const auto& result = step.run;
    EXPECT_FALSE(cutter.frozen()) << where;
    const auto report = mt.validate();
    EXPECT_TRUE(report.ok()) << where << ": " << report.summary();
    EXPECT_TRUE(bvh.validate(mt).ok()) << where << ": " << bvh.validate(mt).summary();
    EXPECT_TRUE(engine::validate_frontier(mt, frontier).ok()) << where;
    EXPECT_TRUE(cutter.validate(mt).ok()) << where << ": " << cutter.validate(mt).summary();
    if (!report.ok()) return out;
    const std::vector<std::uint8_t> after = used_vertices(mt);
    for (const auto& made : result.changes.made_vertices) EXPECT_TRUE(after[made.id.index()]) << where;
    out.split += result.changes.counts.split_tets;
    out.relabeled += result.changes.counts.relabeled_tets;
  }
  EXPECT_FALSE(cutter.provisional_held()) << name;
  EXPECT_GT(out.split, 0u) << name;
  const Frontier finest = engine::Frontier::finest(mt);
  for (const CutPolygon& quad : swept)
    EXPECT_EQ(properly_crossed_tets(mt, finest, quad, longest_edge_near(mt, bvh, quad)), 0u) << name;
  std::printf("[ report   ] %s: %d steps, %zu tets split, %zu relabelled (provisional cuts included)\n",
              name.c_str(), def.steps, out.split, out.relabeled);
  return out;
}

double curved(double u) { return 0.0137 + 0.3 * u * u; }
double straight(double u) { return 0.0137 + 0.013 * u; }
double wavy(double u) { return 0.0137 + 0.08 * std::sin(9.0 * u); }

// Each quad turns a little from the last. Cut as lone polygons, the second
// step already made the finest frontier non-manifold where two quads meet (a
// tet on the crack's negative side re-split through the junction's face
// points).
TEST(ScalpelSteps, CurvedStrokeCutStepByStepKeepsTheMtValid) {
  for (const std::string name : {"ellipsoid", "liver"}) cut_steps(name, {}, curved);
}

// Each quad lies in the plane of the last, so the points a lone cut of the
// last made would lie on the new plane up to rounding (cut so, their sides
// fell by rounding and the LUT made a flat tet: ellipsoid, step 5).
TEST(ScalpelSteps, StraightStrokeCutStepByStepKeepsTheMtValid) {
  for (const std::string name : {"ellipsoid", "liver"}) cut_steps(name, {}, straight);
}

// A stroke through the whole depth, in steps far shorter than the coarse
// tets (as a haptic loop gives them), straight, curved and turning both
// ways: the MT stays valid after every step and falls into two pieces whose
// volumes add up to the object's, as one cut would leave it. Cut as lone
// polygons, the steps leave bridges between their fronts (one piece) or
// break the MT.
TEST(ScalpelSteps, ShortStepsThroughTheWholeDepthSeparateTheObject) {
  // (The box's MT is finer: 24 steps there are as short against its tets.)
  for (const auto& [name, step_counts] : {std::pair<std::string, std::vector<int>>{"ellipsoid", {48, 96}},
                                          {"liver", {48, 96}}, {"box", {24}}}) {
    for (const auto path : {straight, curved, wavy}) {
      for (const int steps : step_counts) {
        const StrokeResult r = cut_steps(name, {.steps = steps, .depth = 1.1}, path);
        const cut::MtPieces pieces = cut::find_pieces(r.mt);
        EXPECT_EQ(pieces.count, 2u) << name << ", " << steps << " steps";
        EXPECT_TRUE(cut::validate_pieces(r.mt, pieces).ok()) << name;
        double volume = 0;
        for (double v : cut::piece_volumes(r.mt, pieces)) volume += v;
        const double original = cut_test_mt(name).fine_volume();
        EXPECT_NEAR(volume, original, 1e-9 * original) << name << ", " << steps << " steps";
      }
    }
  }
}

// The blade's tip inside the tissue, in short steps: the crack's outline
// along the tip's line is the provisional cuts' front, which is taken back
// and cut again at every step.
TEST(ScalpelSteps, ShortStepsWithTheTipInsideKeepTheMtValid) {
  for (const auto path : {straight, curved, wavy}) cut_steps("liver", {.steps = 96}, path);
  for (const auto path : {curved, wavy}) cut_steps("ellipsoid", {.steps = 96}, path);
  for (const auto path : {straight, curved}) cut_steps("box", {.steps = 48}, path);
}

// The same strokes elsewhere. Cut as continuations of lone quads, the
// ellipsoid's coarsest frontier got a non-manifold edge (48 straight steps:
// step 20; 96: step 41) and the box a flat tet (96 curved steps: step 28),
// where a new step met the front an older one had left in a coarse tet.
TEST(ScalpelSteps, MoreShortStepsWithTheTipInsideKeepTheMtValid) {
  for (const int steps : {48, 96}) cut_steps("ellipsoid", {.steps = steps}, straight);
  cut_steps("box", {.steps = 96}, curved);
}

// Turns of tens of degrees per step: each straight part is short, and the
// next overlaps it (cut/stroke_sweep.h). Cut as continuations of lone quads,
// tets near a junction straddled the sheet behind it and not the new plane
// (ellipsoid, 12 wavy steps: fragments changed volume at step 6; box, 12 to
// 48 wavy steps with the tip inside: a non-manifold edge or a flat tet).
TEST(ScalpelSteps, SharpTurnsKeepTheMtValid) {
  for (const int steps : {12, 24}) cut_steps("ellipsoid", {.steps = steps, .depth = 1.1}, wavy);
  for (const int steps : {12, 24, 48}) cut_steps("box", {.steps = steps}, wavy);
}

}  // namespace
}  // namespace mtcut::test
