// A stroke cut step by step, as a haptic loop would feed the cutter: each
// step the quad the blade swept since the last, cut as a continuation of the
// stroke's crack (cut/mt/stroke_crack.h).
#include <gtest/gtest.h>

#include "cut/mt/mt_pieces.h"
#include "cut/mt/stroke_crack.h"
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

// Cuts the quads of a blade along y = path(x) (x across the MT's box, z from
// above its top down to `depth` of its height). After every step the MT is
// valid and every vertex the step made is used; at the end no
// finest-frontier tet is properly crossed by any quad.
template <class Path>
StrokeResult cut_steps(const std::string& name, const StrokeDef& def, Path&& path) {
  StrokeResult out{cut_test_mt(name)};
  Mt& mt = out.mt;
  engine::TetBvh bvh(mt);
  const engine::Aabb box = mt_box(mt);
  const Vec3 size = box.hi - box.lo;
  const double top = box.hi.z() + 0.05 * size.z(), bottom = box.hi.z() - def.depth * size.z();
  const auto x_at = [&](int k) { return box.lo.x() - 0.02 * size.x() + 1.04 * size.x() * k / def.steps; };
  const auto y_at = [&](double x) { return box.center().y() + size.y() * path((x - box.lo.x()) / size.x()); };
  std::vector<CutPolygon> cut_so_far;
  cut::StrokeCrack crack;
  for (int k = 0; k < def.steps; ++k) {
    const double xa = x_at(k), xb = x_at(k + 1);
    const CutPolygon quad = CutPolygon::from_points(
        {Vec3(xa, y_at(xa), top), Vec3(xb, y_at(xb), top), Vec3(xb, y_at(xb), bottom), Vec3(xa, y_at(xa), bottom)});
    const cut::CutContinuation continuation =
        crack.continuation(quad, Vec3(xb, y_at(xb), top), Vec3(xb, y_at(xb), bottom));
    EXPECT_EQ(continuation.junctions.empty(), k == 0) << name << " step " << k;
    EXPECT_GE(continuation.leading_edge, 0) << name << " step " << k;
    cut::CutMtOptions options;
    options.def.continuation = &continuation;
    const cut::MtChangeReport r = cut::cut_mt(mt, bvh, quad, {}, options);
    crack.record(quad, r);
    EXPECT_TRUE(crack.validate().ok()) << name << " step " << k << ": " << crack.validate().summary();
    const auto report = mt.validate();
    EXPECT_TRUE(report.ok()) << name << " step " << k << ": " << report.summary();
    EXPECT_TRUE(bvh.validate(mt).ok()) << name << " step " << k << ": " << bvh.validate(mt).summary();
    if (!report.ok()) return out;
    const std::vector<std::uint8_t> after = used_vertices(mt);
    for (const auto& made : r.made_vertices) EXPECT_TRUE(after[made.id.index()]) << name << " step " << k;
    out.split += r.counts.split_tets;
    out.relabeled += r.counts.relabeled_tets;
    cut_so_far.push_back(quad);
  }
  EXPECT_GT(out.split, 0u) << name;
  const Frontier finest = engine::Frontier::finest(mt);
  for (const CutPolygon& quad : cut_so_far)
    EXPECT_EQ(properly_crossed_tets(mt, finest, quad, longest_edge_near(mt, bvh, quad)), 0u) << name;
  std::printf("[ report   ] %s: %d steps, %zu tets split, %zu relabelled, %zu vertices sided\n", name.c_str(),
              def.steps, out.split, out.relabeled, crack.num_sided());
  return out;
}

double curved(double u) { return 0.0137 + 0.3 * u * u; }
double straight(double u) { return 0.0137 + 0.013 * u; }
double wavy(double u) { return 0.0137 + 0.08 * std::sin(9.0 * u); }

// Each quad turns a little from the last: the next plane passes off the
// vertices the last cut made, on the side of the turn. Cut as lone polygons,
// the second step already makes the finest frontier non-manifold where two
// quads meet (a tet on the crack's negative side re-split through the
// junction's face points).
TEST(ScalpelSteps, CurvedStrokeCutStepByStepKeepsTheMtValid) {
  for (const std::string name : {"ellipsoid", "liver"}) cut_steps(name, {}, curved);
}

// Each quad lies in the plane of the last, so the points the last cut made
// lie on the new plane up to rounding: cut as lone polygons, their sides
// fall by rounding and the LUT makes a flat tet (ellipsoid, step 5).
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
// along the tip's line is the steps' fronts, which later steps meet in the
// coarse tets (on the sheet, they are where the crack ends: kOnInactive).
TEST(ScalpelSteps, ShortStepsWithTheTipInsideKeepTheMtValid) {
  for (const auto path : {straight, curved, wavy}) cut_steps("liver", {.steps = 96}, path);
  for (const auto path : {curved, wavy}) cut_steps("ellipsoid", {.steps = 96}, path);
  for (const auto path : {straight, curved}) cut_steps("box", {.steps = 48}, path);
}

// Known limit (cut/stroke_junction.h), the same strokes elsewhere: the
// ellipsoid's coarsest frontier gets a non-manifold edge (48 straight steps:
// step 20; 96: step 41), the box a flat tet (96 curved steps: step 28).
// The ellipsoid's, traced: a coarse tet (267, 269, ...) five steps long
// holds the front of the last step's crack, face points that the face
// clamp put below the tip's line (z -0.009 to -0.012 against -0.0073) and
// three to four steps behind the new one. They are on the plane and the
// crack ends there (kOnInactive). The new step crosses edge (267, 269)
// just above the tip's line, inside its polygon, and splits the piece
// (267, 269, f1, f2) through the front's edge (f1, f2): the old crack and
// the new one meet at an edge neither divides, which two pairs of faces
// then share (the same tet and points at both step counts).
TEST(ScalpelSteps, DISABLED_MoreShortStepsWithTheTipInsideKeepTheMtValid) {
  for (const int steps : {48, 96}) cut_steps("ellipsoid", {.steps = steps}, straight);
  cut_steps("box", {.steps = 96}, curved);
}

// Known limit (cut/stroke_junction.h): turns of tens of degrees per step.
// Tets near the junction straddle the sheet behind it and not the new plane;
// their cut differs between resolutions (ellipsoid, 12 wavy steps: fragments
// change volume at step 6; box, 12 to 48 wavy steps with the tip inside:
// a non-manifold edge or a flat tet).
TEST(ScalpelSteps, DISABLED_SharpTurnsKeepTheMtValid) {
  for (const int steps : {12, 24}) cut_steps("ellipsoid", {.steps = steps, .depth = 1.1}, wavy);
  for (const int steps : {12, 24, 48}) cut_steps("box", {.steps = steps}, wavy);
}

}  // namespace
}  // namespace mtcut::test
