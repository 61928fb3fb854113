// A stroke cut step by step, as a haptic loop feeds the cutter, two ways:
//   - progressively, as the World cuts every frame: a blade pose a step
//     through the stroke's sweep and the time-critical cutter
//     (cut/mt/stroke_cutter.h: the part in progress cut provisionally, its
//     completely crossed tets committed, ended parts cut for good);
//   - as continuations: each step's quad cut as a continuation of the
//     stroke's crack (cut/mt/stroke_crack.h).
#include <gtest/gtest.h>

#include <functional>

#include "cut/mt/mt_pieces.h"
#include "cut/mt/stroke_crack.h"
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

enum class Driver { kProgressive, kContinuations };

struct StrokeDef {
  int steps = 24;
  double depth = 0.6;     // how far below the MT box's top the blade reaches, times its height
  Driver driver = Driver::kProgressive;
};

struct StrokeResult {
  Mt mt;
  std::size_t split = 0, relabeled = 0;
};

// The blade along y = path(x): x across the MT's box in `steps` steps, z
// from above its top down to `depth` of its height.
struct BladePath {
  std::function<double(double)> path;
  engine::Aabb box;
  Vec3 size;
  int steps;
  double top, bottom;
  BladePath(const Mt& mt, const StrokeDef& def, std::function<double(double)> p)
      : path(std::move(p)), box(mt_box(mt)), size(box.hi - box.lo), steps(def.steps),
        top(box.hi.z() + 0.05 * size.z()), bottom(box.hi.z() - def.depth * size.z()) {}
  double x_at(int k) const { return box.lo.x() - 0.02 * size.x() + 1.04 * size.x() * k / steps; }
  double y_at(double x) const { return box.center().y() + size.y() * path((x - box.lo.x()) / size.x()); }
  cut::BladePose pose(int k) const {
    const double x = x_at(k);
    return {Vec3(x, y_at(x), top), Vec3(x, y_at(x), bottom), true};
  }
  // The quad swept from pose k to pose k + 1.
  CutPolygon quad(int k) const {
    const cut::BladePose a = pose(k), b = pose(k + 1);
    return CutPolygon::from_points({a.base, b.base, b.tip, a.tip});
  }
};

// The step's MT, BVH (and frontier, cutter: progressively) are valid, and
// every vertex it made (`made`, ids after the step) is used.
bool expect_valid_step(const Mt& mt, const engine::TetBvh& bvh, const std::vector<engine::ValidationReport>& more,
                       const std::vector<VertId>& made, const std::string& at) {
  std::vector<engine::ValidationReport> reports{mt.validate(), bvh.validate(mt)};
  reports.insert(reports.end(), more.begin(), more.end());
  bool valid = true;
  for (const auto& report : reports) {
    EXPECT_TRUE(report.ok()) << at << ": " << report.summary();
    valid = valid && report.ok();
  }
  if (!valid) return false;
  const std::vector<std::uint8_t> used = used_vertices(mt);
  for (VertId v : made) EXPECT_TRUE(v.valid() && used[v.index()]) << at << ": a made vertex is not used";
  return true;
}

// Cuts the blade's stroke along y = path(x) step by step (then lifts it,
// progressively). After every step the MT and its BVH are valid (and the
// frontier and the cutter, progressively) and every vertex the step made
// is used; at the end no finest-frontier tet is properly crossed by any
// step's quad.
StrokeResult cut_steps(const std::string& name, const StrokeDef& def, std::function<double(double)> path) {
  StrokeResult out{cut_test_mt(name)};
  Mt& mt = out.mt;
  engine::TetBvh bvh(mt);
  const BladePath blade(mt, def, std::move(path));
  std::string how;
  if (def.driver == Driver::kProgressive) {
    Frontier frontier = Frontier::coarsest(mt);
    cut::StrokeSweep stroke;
    cut::TimeCriticalCutter cutter;
    for (int k = 0; k <= def.steps + 1; ++k) {
      cut::BladePose pose = blade.pose(std::min(k, def.steps));
      pose.engaged = k <= def.steps;
      const cut::StrokeStep step = cut::cut_stroke_step(stroke, cutter, mt, bvh, frontier, std::span(&pose, 1));
      EXPECT_FALSE(cutter.frozen()) << name << " step " << k;
      std::vector<VertId> made;
      for (const auto& m : step.run.changes.made_vertices)
        made.push_back(step.reclaimed ? step.reclaimed->vertex(m.id) : m.id);
      if (!expect_valid_step(mt, bvh, {engine::validate_frontier(mt, frontier), cutter.validate(mt)}, made,
                             name + " step " + std::to_string(k)))
        return out;
      out.split += step.run.changes.counts.split_tets;
      out.relabeled += step.run.changes.counts.relabeled_tets;
    }
    EXPECT_FALSE(cutter.provisional_held()) << name;
    how = "progressively, " + std::to_string(cutter.cuts_refused()) + " cuts refused";
  } else {
    cut::StrokeCrack crack;
    for (int k = 0; k < def.steps; ++k) {
      const CutPolygon quad = blade.quad(k);
      const cut::BladePose next = blade.pose(k + 1);
      const cut::CutContinuation continuation = crack.continuation(quad, next.base, next.tip);
      EXPECT_EQ(continuation.junctions.empty(), k == 0) << name << " step " << k;
      EXPECT_GE(continuation.leading_edge, 0) << name << " step " << k;
      cut::CutMtOptions options;
      options.def.continuation = &continuation;
      const cut::MtChangeReport r = cut::cut_mt(mt, bvh, quad, {}, options);
      crack.record(quad, r.made_vertices);
      std::vector<VertId> made;
      for (const auto& m : r.made_vertices) made.push_back(m.id);
      if (!expect_valid_step(mt, bvh, {crack.validate()}, made, name + " step " + std::to_string(k))) return out;
      out.split += r.counts.split_tets;
      out.relabeled += r.counts.relabeled_tets;
    }
    how = "as continuations, " + std::to_string(crack.num_sided()) + " vertices sided";
  }
  EXPECT_GT(out.split, 0u) << name;
  const Frontier finest = engine::Frontier::finest(mt);
  for (int k = 0; k < def.steps; ++k) {
    const CutPolygon quad = blade.quad(k);
    EXPECT_EQ(properly_crossed_tets(mt, finest, quad, longest_edge_near(mt, bvh, quad)), 0u) << name << " quad " << k;
  }
  std::printf("[ report   ] %s: %d steps %s, %zu tets split, %zu relabelled\n", name.c_str(), def.steps, how.c_str(),
              out.split, out.relabeled);
  return out;
}

double curved(double u) { return 0.0137 + 0.3 * u * u; }
double straight(double u) { return 0.0137 + 0.013 * u; }
double wavy(double u) { return 0.0137 + 0.08 * std::sin(9.0 * u); }

constexpr Driver kBoth[] = {Driver::kProgressive, Driver::kContinuations};

// Each quad turns a little from the last: the next plane passes off the
// vertices the last cut made, on the side of the turn. Cut as lone polygons,
// the second step already makes the finest frontier non-manifold where two
// quads meet (a tet on the crack's negative side re-split through the
// junction's face points).
TEST(ScalpelSteps, CurvedStrokeCutStepByStepKeepsTheMtValid) {
  for (const Driver driver : kBoth)
    for (const std::string name : {"ellipsoid", "liver"}) cut_steps(name, {.driver = driver}, curved);
}

// Each quad lies in the plane of the last, so the points the last cut made
// lie on the new plane up to rounding: cut as lone polygons, their sides
// fall by rounding and the LUT makes a flat tet (ellipsoid, step 5).
TEST(ScalpelSteps, StraightStrokeCutStepByStepKeepsTheMtValid) {
  for (const Driver driver : kBoth)
    for (const std::string name : {"ellipsoid", "liver"}) cut_steps(name, {.driver = driver}, straight);
}

// A stroke through the whole depth, in steps far shorter than the coarse
// tets (as a haptic loop gives them), straight, curved and turning both
// ways: the MT stays valid after every step and falls into two pieces whose
// volumes add up to the object's, as one cut would leave it. Cut as lone
// polygons, the steps leave bridges between their fronts (one piece) or
// break the MT. Progressively, a curved stroke is cut as straight parts,
// each going on from the last one's crack across its last blade edge
// (TimeCriticalCutter::recut): two parts that each cut the tets at a turn
// partially would leave a bridge there.
TEST(ScalpelSteps, ShortStepsThroughTheWholeDepthSeparateTheObject) {
  // (The box's MT is finer: 24 steps there are as short against its tets.)
  for (const auto& [name, step_counts] : {std::pair<std::string, std::vector<int>>{"ellipsoid", {48, 96}},
                                          {"liver", {48, 96}}, {"box", {24}}}) {
    for (const auto path : {straight, curved, wavy}) {
      for (const int steps : step_counts) {
        for (const Driver driver : kBoth) {
          const StrokeResult r = cut_steps(name, {.steps = steps, .depth = 1.1, .driver = driver}, path);
          const std::string what = name + ", " + std::to_string(steps) + " steps" +
                                   (driver == Driver::kProgressive ? ", progressively" : ", as continuations");
          const cut::MtPieces pieces = cut::find_pieces(r.mt);
          EXPECT_EQ(pieces.count, 2u) << what;
          EXPECT_TRUE(cut::validate_pieces(r.mt, pieces).ok()) << what;
          double volume = 0;
          for (double v : cut::piece_volumes(r.mt, pieces)) volume += v;
          const double original = cut_test_mt(name).fine_volume();
          EXPECT_NEAR(volume, original, 1e-9 * original) << what;
        }
      }
    }
  }
}

// The blade's tip inside the tissue, in short steps: the crack's outline
// along the tip's line is the steps' fronts, which later steps meet in the
// coarse tets (as continuations, on the sheet, they are where the crack
// ends: kOnInactive).
TEST(ScalpelSteps, ShortStepsWithTheTipInsideKeepTheMtValid) {
  for (const Driver driver : kBoth) {
    for (const auto path : {straight, curved, wavy}) cut_steps("liver", {.steps = 96, .driver = driver}, path);
    for (const auto path : {curved, wavy}) cut_steps("ellipsoid", {.steps = 96, .driver = driver}, path);
    for (const auto path : {straight, curved}) cut_steps("box", {.steps = 48, .driver = driver}, path);
  }
}

// The same strokes as above elsewhere, progressively. As continuations
// they break the MT (cut/stroke_junction.h, known limit): the ellipsoid's
// coarsest frontier gets a non-manifold edge (48 straight steps: step 20;
// 96: step 41), the box a flat tet (96 curved steps: step 28). The
// ellipsoid's, traced: a coarse tet five steps long holds the front of the
// last step's crack, face points below the tip's line and three to four
// steps behind the new one; the new step crosses an edge of that tet just
// above the tip's line and splits the front's piece through the front's
// edge, so the old crack and the new one meet at an edge neither divides.
// Progressively no step's quad is cut on its own: the part in progress is
// one polygon, taken back and cut afresh every step.
TEST(ScalpelSteps, MoreShortStepsWithTheTipInsideKeepTheMtValid) {
  for (const int steps : {48, 96}) cut_steps("ellipsoid", {.steps = steps}, straight);
  cut_steps("box", {.steps = 96}, curved);
}

// Turns of tens of degrees per step, progressively. As continuations they
// break the MT (cut/stroke_junction.h, known limit): tets near the junction
// straddle the sheet behind it and not the new plane, and their cut differs
// between resolutions (ellipsoid, 12 wavy steps: fragments change volume at
// step 6; box, 12 to 48 wavy steps with the tip inside: a non-manifold edge
// or a flat tet).
TEST(ScalpelSteps, SharpTurnsKeepTheMtValid) {
  for (const int steps : {12, 24}) cut_steps("ellipsoid", {.steps = steps, .depth = 1.1}, wavy);
  for (const int steps : {12, 24, 48}) cut_steps("box", {.steps = steps}, wavy);
}

}  // namespace
}  // namespace mtcut::test
