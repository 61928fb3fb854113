// Scalpel strokes cut progressively (cut/mt/stroke_cutter.h): a blade pose a
// step, the stroke's straight parts cut for good as they end and the part
// in progress cut provisionally, the last step's provisional cut taken back
// first (cut/mt/cut_retraction.h). After every step the MT, its BVH, the
// cutter and a frontier that follows the cuts are valid; after the stroke,
// so is the frontier that shows each fragment the cuts touched.
#include "cut/mt/stroke_cutter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <random>

#include "cut/mt/mt_pieces.h"
#include "engine/surface_mesh.h"
#include "tests/broken_surfaces.h"
#include "tests/cut/mt/stroke_test_util.h"
#include "tests/temp_dir.h"
#include "tests/test_size.h"

namespace mtcut::test {
namespace {

struct StrokeOutcome {
  Mt mt;
  std::size_t pieces = 0;
  std::size_t refused = 0;  // cuts the cutter took back (cut_guard.h)
  std::vector<CutPolygon> swept;  // the quads between consecutive poses
  bool valid = true;
};

// Cuts `path` in `steps` steps (a pose each, then disengaged ones until the
// cutter has nothing left: one with no budget), each step within `budget`,
// validating after every step, and the fragments' frontiers at the end.
StrokeOutcome cut_progressively(const Mt& original, const Path& path, int steps, const std::string& where,
                                const cut::CutBudget& budget = cut::CutBudget::unlimited()) {
  StrokeOutcome out{original, 0, 0, {}, true};
  Mt& mt = out.mt;
  engine::TetBvh bvh(mt);
  Frontier frontier = Frontier::coarsest(mt);
  cut::StrokeSweep stroke;
  cut::TimeCriticalCutter cutter(checked_cutter());
  const bool limited = budget.work != cut::CutBudget::unlimited().work || std::isfinite(budget.milliseconds);
  for (int k = 0; (k <= steps + 1 || cutter.frozen()) && out.valid; ++k) {
    const std::string at = where + " step " + std::to_string(k);
    cut::BladePose pose = path(std::min(1.0, static_cast<double>(k) / steps));
    pose.engaged = k <= steps;
    if (k > 0 && k <= steps) {
      const cut::BladePose last = path(static_cast<double>(k - 1) / steps);
      if ((last.base - pose.base).norm() > 0 || (last.tip - pose.tip).norm() > 0)
        out.swept.push_back(CutPolygon::from_points({last.base, pose.base, pose.tip, last.tip}));
    }
    const cut::StrokeStep step = cut::cut_stroke_step(stroke, cutter, mt, bvh, frontier, std::span(&pose, 1), budget);
    if (!step.recut && !limited) continue;
    if (!limited) {
      EXPECT_FALSE(cutter.frozen()) << at;
    }
    // While a cut is half done the MT mixes split and unsplit tets of its
    // fragments (time_critical_cutter.h); the frontier shows none of them.
    const engine::ValidationReport whole = cutter.frozen() ? engine::ValidationReport{} : mt.validate();
    for (const auto& report : {whole, bvh.validate(mt), engine::validate_frontier(mt, frontier),
                               cutter.validate(mt)}) {
      EXPECT_TRUE(report.ok()) << at << ": " << report.summary();
      out.valid = out.valid && report.ok();
    }
  }
  EXPECT_FALSE(cutter.provisional_held()) << where;
  if (out.valid) {
    const engine::ValidationReport report = validate_cut_fragment_frontiers(mt, original.num_vertices());
    EXPECT_TRUE(report.ok()) << where << ": " << report.summary();
    out.valid = report.ok();
  }
  // The slots the stroke's retracted cuts left are reclaimed once it ends.
  EXPECT_LE(mt.num_dead_tets(), std::max(mt.num_live_tets(), cut::TimeCriticalCutter::kReclaimMin)) << where;
  out.pieces = cut::find_pieces(mt).count;
  out.refused = cutter.cuts_refused();
  return out;
}

// A vertical blade across the box along y at x = box x + `at` of its width,
// from above the top down to `depth` of the height (past the bottom for
// depth > 1), with `wobble` (x = at + wobble(s)).
Path across(const Mt& mt, double at, double depth, std::function<double(double)> wobble = {}) {
  const engine::Aabb box = mt_box(mt);
  return [box, at, depth, wobble](double s) {
    const Vec3 size = box.hi - box.lo;
    const double x = box.lo.x() + (at + (wobble ? wobble(s) : 0.0)) * size.x();
    const double y = box.lo.y() - 0.05 * size.y() + 1.1 * s * size.y();
    return cut::BladePose{Vec3(x, y, box.hi.z() + 0.05 * size.z()), Vec3(x, y, box.hi.z() - depth * size.z()), true};
  };
}

double volume_of_pieces(const Mt& mt) {
  double v = 0;
  for (double p : cut::piece_volumes(mt, cut::find_pieces(mt))) v += p;
  return v;
}

// A straight stroke is one part: cut in any number of steps it ends as the
// one cut of its polygon, tet for tet (each tet split once from its
// original), and a stroke through the whole depth separates the object.
TEST(StrokeCutter, StraightStrokesEndAsTheOneCutOfTheirPolygon) {
  for (const std::string name : {"ellipsoid", "liver", "box"}) {
    const Mt& original = cut_test_mt(name);
    for (const double depth : {0.6, 1.1}) {
      const Path path = across(original, 0.5137, depth);
      for (const int steps : {24, 96}) {
        const auto once = canonical_mt(cut_at_once(original, path, steps));
        const std::string where = name + " depth " + std::to_string(depth) + ", " + std::to_string(steps) + " steps";
        const StrokeOutcome r = cut_progressively(original, path, steps, where);
        if (!r.valid) return;
        EXPECT_TRUE(canonical_mt(r.mt) == once) << where;
        if (depth > 1) {
          EXPECT_EQ(r.pieces, 2u) << where;
          EXPECT_NEAR(volume_of_pieces(r.mt), original.fine_volume(), 1e-9 * original.fine_volume()) << where;
        }
      }
    }
  }
}

// A part's end searches its front and where its polygon grew since its
// last frame, as each frame's commit does (its commits own the rest): a
// straight stroke whose last frame brings half of it at once, then
// lifts the blade, still ends as the one cut of its polygon, tet for tet.
TEST(StrokeCutter, APartsEndCutsWhatItsLastFrameAdds) {
  for (const std::string name : {"ellipsoid", "liver", "box"}) {
    const Mt& original = cut_test_mt(name);
    for (const double depth : {0.6, 1.1}) {
      const std::string where = name + " depth " + std::to_string(depth);
      const Path path = across(original, 0.5137, depth);
      constexpr int kSteps = 60, kLast = 30;  // the last frame's poses
      Mt mt = original;
      engine::TetBvh bvh(mt);
      Frontier frontier = Frontier::coarsest(mt);
      cut::StrokeSweep stroke;
      cut::TimeCriticalCutter cutter(checked_cutter());
      for (int k = 0; k <= kSteps - kLast; ++k) {
        const cut::BladePose pose = path(static_cast<double>(k) / kSteps);
        cut::cut_stroke_step(stroke, cutter, mt, bvh, frontier, std::span(&pose, 1));
      }
      ASSERT_NE(cutter.part_record(), nullptr) << where << ": the part never fixed its plane";
      std::vector<cut::BladePose> last;
      for (int k = kSteps - kLast + 1; k <= kSteps; ++k) last.push_back(path(static_cast<double>(k) / kSteps));
      last.push_back(last.back());
      last.back().engaged = false;
      cut::cut_stroke_step(stroke, cutter, mt, bvh, frontier, last);
      const engine::ValidationReport report = mt.validate();
      ASSERT_TRUE(report.ok()) << where << ": " << report.summary();
      EXPECT_FALSE(cutter.provisional_held()) << where;
      EXPECT_TRUE(canonical_mt(mt) == canonical_mt(cut_at_once(original, path, kSteps))) << where;
    }
  }
}

// Curved, wavy and L-shaped strokes, through and with the tip inside: every
// step leaves the MT valid, in the end no finest tet is properly crossed by
// what the blade swept, and a stroke through the whole depth separates the
// object (one with the tip inside does not): a crack left short where two
// parts of the stroke meet leaves a bridge that no finest tet's split shows.
TEST(StrokeCutter, TurningStrokesKeepTheMtValid) {
  const auto curved = [](double s) { return 0.3 * s * s; };
  const auto wavy = [](double s) { return 0.08 * std::sin(9.0 * s); };
  const auto l_turn = [](double s) { return s < 0.5 ? 0.0 : 0.8 * (s - 0.5); };
  for (const std::string name : {"ellipsoid", "liver", "box"}) {
    const Mt& original = cut_test_mt(name);
    for (const auto& [shape, wobble] : {std::pair<std::string, std::function<double(double)>>{"curved", curved},
                                        {"wavy", wavy}, {"l_turn", l_turn}}) {
      for (const double depth : {0.6, 1.1}) {
        for (const int steps : {24, 96}) {
          const std::string where =
              name + " " + shape + " depth " + std::to_string(depth) + ", " + std::to_string(steps) + " steps";
          const StrokeOutcome r = cut_progressively(original, across(original, 0.4137, depth, wobble), steps, where);
          if (!r.valid) return;
          engine::TetBvh bvh(r.mt);
          const Frontier finest = Frontier::finest(r.mt);
          for (const CutPolygon& quad : r.swept)
            EXPECT_EQ(properly_crossed_tets(r.mt, finest, quad, longest_edge_near(r.mt, bvh, quad)), 0u) << where;
          if (depth > 1)
            EXPECT_GE(r.pieces, 2u) << where;
          else
            EXPECT_EQ(r.pieces, 1u) << where;
        }
      }
    }
  }
}

// A part cut whole each frame (after a gentle turn it pivots about the
// turn's edge; before its plane is fixed, it may turn) is cut again only
// once its polygon has moved TimeCriticalCutter::kRedoReach of a tet: at a
// stylus's rate (1,000 steps) most of those frames keep the last one's cut
// and change nothing, the others take it back and cut the part again. The
// MT is valid after every step, and the curved strokes through the object
// still separate it.
TEST(StrokeCutter, APartCutWholeIsCutAgainOnlyOnceItsPolygonMoves) {
  const auto curved = [](double s) { return 0.3 * s * s; };
  for (const std::string name : {"ellipsoid", "liver"}) {
    const Mt& original = cut_test_mt(name);
    const std::string where = name + " curved, 1000 steps";
    const Path path = across(original, 0.4137, 1.1, curved);
    Mt mt = original;
    engine::TetBvh bvh(mt);
    Frontier frontier = Frontier::coarsest(mt);
    cut::StrokeSweep stroke;
    cut::TimeCriticalCutter cutter(checked_cutter());
    constexpr int kSteps = 1000;
    std::size_t kept = 0, redone = 0;
    for (int k = 0; k <= kSteps + 1; ++k) {
      cut::BladePose pose = path(std::min(1.0, static_cast<double>(k) / kSteps));
      pose.engaged = k <= kSteps;
      const bool whole_before = cutter.provisional_held() && !cutter.part_record();
      const cut::StrokeStep step = cut::cut_stroke_step(stroke, cutter, mt, bvh, frontier, std::span(&pose, 1));
      const bool whole_after = cutter.provisional_held() && !cutter.part_record();
      if (whole_before && whole_after && step.recut) {
        if (!step.retraction && step.run.changes.replaced.empty())
          ++kept;
        else if (step.retraction)
          ++redone;
      }
      if (!step.recut) continue;
      const engine::ValidationReport report = mt.validate();
      ASSERT_TRUE(report.ok()) << where << " step " << k << ": " << report.summary();
    }
    EXPECT_FALSE(cutter.provisional_held()) << where;
    EXPECT_GT(redone, 0u) << where;
    EXPECT_GT(kept, redone) << where << ": " << kept << " frames kept the part's cut, " << redone << " redid it";
    EXPECT_GE(cut::find_pieces(mt).count, 2u) << where;
    std::printf("[ report   ] %s: a part cut whole kept in %zu frames, cut again in %zu\n", where.c_str(), kept,
                redone);
  }
}

// The same turning strokes with a budget that leaves a part's frame for
// later calls (its commit in one, its front in the next frame's, or dropped
// there as the part grows): every step leaves the MT valid, and the tissue
// comes apart as without a budget. A commit is kept before its front with
// only its pieces' orientation checked (cut_guard.h), so one whose front
// never runs is checked with the next frame's front, or the part's end.
TEST(StrokeCutter, TurningStrokesUnderABudgetKeepTheMtValid) {
  const auto curved = [](double s) { return 0.3 * s * s; };
  const auto l_turn = [](double s) { return s < 0.5 ? 0.0 : 0.8 * (s - 0.5); };
  for (const std::string name : {"ellipsoid", "liver", "box"}) {
    const Mt& original = cut_test_mt(name);
    for (const auto& [shape, wobble] :
         {std::pair<std::string, std::function<double(double)>>{"curved", curved}, {"l_turn", l_turn}}) {
      for (const double depth : {0.6, 1.1}) {
        for (const std::size_t units : {std::size_t{1}, std::size_t{40}}) {
          const std::string where = name + " " + shape + " depth " + std::to_string(depth) + ", budget " +
                                    std::to_string(units);
          const StrokeOutcome r =
              cut_progressively(original, across(original, 0.4137, depth, wobble), 48, where, cut::CutBudget::units(units));
          if (!r.valid) return;
          if (depth > 1)
            EXPECT_GE(r.pieces, 2u) << where;
          else
            EXPECT_EQ(r.pieces, 1u) << where;
        }
      }
    }
  }
}

// MTs of eight meshes for the random strokes: the builtin shapes, shared
// surfaces meshed by TetGen, a shared tet mesh, and surfaces repaired before
// they were meshed (two organs that cross, one with holes: repaired_surface).
const Mt& property_mt(const std::string& spec) {
  static std::map<std::string, Mt> cache;
  auto it = cache.find(spec);
  if (it != cache.end()) return it->second;
  engine::MeshLoadDef def;
  def.builtin_tets = 1500;
  const auto mesh = engine::load_mesh(spec, def).mesh;
  return cache.emplace(spec, engine::build_mt(mesh, engine::MtBuildOptions{})).first->second;
}

// A surface as people have them, written to a file for load_mesh to repair.
std::string repaired_surface(const std::string& name) {
  static const TempDir dir;
  const std::string path = dir.file(name + ".obj");
  if (!std::filesystem::exists(path))
    engine::write_surface_file(name == "crossing" ? crossing_organs(1500) : holed_organ(1500), path);
  return path;
}

// How many random strokes: MTCUT_STROKES, else 200 at the build's test size
// (test_size.h); MTCUT_STROKE_FIRST skips to a given one (to replay a
// failure).
int stroke_count() {
  const char* env = std::getenv("MTCUT_STROKES");
  return env ? std::max(1, std::atoi(env)) : mtcut::test::scaled(200);
}

// Random strokes: 1 to 3 straight legs in random directions across the
// object's box, a random depth (the tip inside or through), 20 to 80 steps
// (1,000 for one stroke in 100): valid after every step, a cut refused (taken
// back where it would have pinched the MT, cut_guard.h) in at most one
// stroke in 20. A one-leg stroke through the whole depth ends as the one cut
// of its polygon.
//
// The strokes are dealt to kShards tests (stroke i to shard i % kShards),
// each stroke drawn from its own seed, so that the shards run side by side
// and MTCUT_STROKE_FIRST replays any stroke alone. MTCUT_STROKES is the
// total over the shards.
constexpr int kShards = 4;

class StrokeCutterRandom : public ::testing::TestWithParam<int> {};

TEST_P(StrokeCutterRandom, StrokesKeepTheMtValid) {
  const int shard = GetParam();
  const std::vector<std::string> specs = {"builtin:ellipsoid", "builtin:box", "builtin:cylinder",
                                          shared_mesh("liver.msh"), shared_mesh("torus.obj"),
                                          shared_mesh("Armadillo_Tetra_4406.vtu"), repaired_surface("crossing"),
                                          repaired_surface("holed")};
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int strokes = stroke_count();
  int tried = 0, one_leg_through = 0;
  std::vector<int> invalid;  // strokes that left the MT invalid at some step
  int with_refusals = 0;     // strokes with a cut the cutter refused
  const char* first_env = std::getenv("MTCUT_STROKE_FIRST");
  const int first = first_env ? std::max(0, std::atoi(first_env)) : 0;
  for (int i = shard; i < strokes; i += kShards) {
    if (i < first) continue;  // MTCUT_STROKE_FIRST: start at a given stroke (the same strokes)
    ++tried;
    std::seed_seq seed{2026u, static_cast<unsigned>(i)};
    std::mt19937_64 rng(seed);
    const std::string spec = specs[static_cast<std::size_t>(i / kShards) % specs.size()];
    const Mt& original = property_mt(spec);
    const engine::Aabb box = mt_box(original);
    const Vec3 size = box.hi - box.lo;
    const int legs = 1 + static_cast<int>(u(rng) * 3);
    const double depth = 0.3 + 0.9 * u(rng);
    // One stroke in 100 has 1,000 steps, in every shard in turn; with fewer
    // than 100 strokes (a smaller test size), the last one.
    const bool long_stroke = i % 100 == 100 - kShards + (i / 100) % kShards || (strokes < 100 && i == strokes - 1);
    const int steps = long_stroke ? 1000 : 20 + static_cast<int>(u(rng) * 60);
    // The blade's foot path: a polyline from outside the box across it.
    std::vector<Vec3> corners;
    const double a0 = 2 * M_PI * u(rng);
    Vec3 p = box.center() - 0.75 * size.norm() * Vec3(std::cos(a0), std::sin(a0), 0);
    corners.push_back(p);
    double heading = a0 + (u(rng) - 0.5) * 0.6;
    for (int l = 0; l < legs; ++l) {
      p += 1.5 * size.norm() / legs * Vec3(std::cos(heading), std::sin(heading), 0);
      corners.push_back(p);
      heading += (u(rng) - 0.5) * 2.0;  // up to a turn of one radian either way
    }
    const double top = box.hi.z() + 0.05 * size.z(), bottom = box.hi.z() - depth * size.z();
    const Path path = [corners, top, bottom](double s) {
      const double t = s * static_cast<double>(corners.size() - 1);
      const std::size_t k = std::min(corners.size() - 2, static_cast<std::size_t>(t));
      const Vec3 q = corners[k] + (t - static_cast<double>(k)) * (corners[k + 1] - corners[k]);
      return cut::BladePose{Vec3(q.x(), q.y(), top), Vec3(q.x(), q.y(), bottom), true};
    };
    const std::string where = "stroke " + std::to_string(i) + " on " + spec + ": " + std::to_string(legs) +
                              " legs, depth " + std::to_string(depth) + ", " + std::to_string(steps) + " steps";
    const StrokeOutcome r = cut_progressively(original, path, steps, where);
    if (!r.valid) {
      invalid.push_back(i);
      continue;
    }
    if (r.refused > 0) {
      ++with_refusals;
      std::printf("[ report   ] %s: %zu cuts refused\n", where.c_str(), r.refused);
    }
    if (legs == 1 && depth > 1.0) {
      ++one_leg_through;
      EXPECT_TRUE(canonical_mt(r.mt) == canonical_mt(cut_at_once(original, path, steps))) << where;
    }
  }
  std::printf("[ report   ] shard %d: %d random strokes, %d of one leg through the whole depth, %zu invalid, %d "
              "with a cut refused\n", shard, tried, one_leg_through, invalid.size(), with_refusals);
  // Refusals keep the MT valid at the price of an incision that does not
  // show: they must stay the exception.
  EXPECT_LE(with_refusals * 20, std::max(tried, 20)) << with_refusals << " strokes had a cut refused";
  EXPECT_TRUE(invalid.empty()) << invalid.size() << " strokes left the MT invalid (see above), the first "
                               << (invalid.empty() ? -1 : invalid.front());
}

INSTANTIATE_TEST_SUITE_P(Shards, StrokeCutterRandom, ::testing::Range(0, kShards));

// Random corner cuts on the convex builtin shapes: two legs through the
// whole depth, from outside to a point inside and out again, turning
// sharply there (60 to 165 degrees, either way: V's too), in 20 to 80
// steps and all in one step: valid after every step, and the corner comes off (two
// pieces) with no cut refused, as the two cracks cross where the stroke
// turned, in all but at most one stroke in 20 (a bridge of tets both
// cracks cut partially, a stub that cuts off a third piece:
// time_critical_cutter.h, kCrossingReach; or a cut the guard refused, as
// in the random strokes above). MTCUT_STROKES / 5 strokes (40 by default).
TEST(StrokeCutter, SharpTurnsThroughTheWholeDepthCutOffTheCorner) {
  const std::vector<std::string> specs = {"builtin:ellipsoid", "builtin:box", "builtin:cylinder"};
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int strokes = std::max(1, stroke_count() / 5);
  int missed = 0;  // strokes not in two pieces (progressively or in one step) or with a cut refused
  for (int i = 0; i < strokes; ++i) {
    std::seed_seq seed{2027u, static_cast<unsigned>(i)};
    std::mt19937_64 rng(seed);
    const std::string spec = specs[static_cast<std::size_t>(i) % specs.size()];
    const Mt& original = property_mt(spec);
    const engine::Aabb box = mt_box(original);
    const Vec3 size = box.hi - box.lo;
    // The corner within the middle half of the box (inside the shape's
    // outline seen from above), the legs long enough to start and end outside.
    const Vec3 corner = box.center() + Vec3((u(rng) - 0.5) * 0.5 * size.x(), (u(rng) - 0.5) * 0.5 * size.y(), 0);
    const double heading = 2 * M_PI * u(rng);
    // (A V, a turn back of over 135 degrees, has its planes less than 45
    // degrees apart: the sweep tells it from a gentle turn by the blade's
    // heading, StrokeAdvance::turned_back.)
    const double turn = (u(rng) < 0.5 ? -1 : 1) * (60.0 + 105.0 * u(rng)) * M_PI / 180;
    const double reach = 1.5 * size.norm();
    const Vec3 start = corner - reach * Vec3(std::cos(heading), std::sin(heading), 0);
    const Vec3 end = corner + reach * Vec3(std::cos(heading + turn), std::sin(heading + turn), 0);
    const double top = box.hi.z() + 0.05 * size.z(), bottom = box.lo.z() - 0.05 * size.z();
    const Path path = [start, corner, end, top, bottom](double s) {
      const Vec3 q = s < 0.5 ? start + 2 * s * (corner - start) : corner + (2 * s - 1) * (end - corner);
      return cut::BladePose{Vec3(q.x(), q.y(), top), Vec3(q.x(), q.y(), bottom), true};
    };
    const int steps = 20 + static_cast<int>(u(rng) * 60);
    const std::string where = "corner cut " + std::to_string(i) + " on " + spec + ": turn " +
                              std::to_string(turn * 180 / M_PI) + " degrees, " + std::to_string(steps) + " steps";
    const StrokeOutcome r = cut_progressively(original, path, steps, where);
    if (!r.valid) continue;
    const std::size_t at_once = cut::find_pieces(cut_at_once(original, path, steps)).count;
    if (r.pieces != 2 || at_once != 2 || r.refused > 0) {
      ++missed;
      std::printf("[ report   ] %s: %zu pieces, %zu in one step, %zu cuts refused\n", where.c_str(), r.pieces,
                  at_once, r.refused);
    }
  }
  std::printf("[ report   ] %d random corner cuts, %d not in two pieces or with a cut refused\n", strokes, missed);
  EXPECT_LE(missed * 20, std::max(strokes, 20)) << missed << " corner cuts did not cut the corner off";
}

}  // namespace
}  // namespace mtcut::test
