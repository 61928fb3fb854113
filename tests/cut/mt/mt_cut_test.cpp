#include "cut/mt/mt_cut.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <tuple>

#include "cut/mt/mt_cut_workspace.h"
#include "cut/mt/mt_pieces.h"
#include "cut/mt/time_critical_cutter.h"
#include "cut/stroke_sweep.h"
#include "tests/cut/mt/mt_cut_test_util.h"
#include "tests/test_size.h"

namespace mtcut::test {
namespace {

using cut::cut_mt;
using cut::CutMtOptions;
using cut::JobOrder;
using cut::MtChangeReport;

// Every check of "Done when" after one cut of a sequence.
void check_after_cut(const Mt& mt, const std::vector<CutPolygon>& cuts, const std::vector<double>& slack,
                     double original_volume,
                     std::mt19937_64& rng, const std::string& where) {
  const auto report = mt.validate();
  ASSERT_TRUE(report.ok()) << where << ": " << report.summary();
  const auto pieces = cut::find_pieces(mt);
  const auto piece_report = cut::validate_pieces(mt, pieces);
  ASSERT_TRUE(piece_report.ok()) << where << ": " << piece_report.summary();
  EXPECT_EQ(cut::count_pieces(mt), pieces.count) << where;
  double pieces_volume = 0;
  for (double v : cut::piece_volumes(mt, pieces)) pieces_volume += v;
  EXPECT_NEAR(pieces_volume, mt.fine_volume(), 1e-9 * mt.fine_volume()) << where;
  // validate() checked the finest and coarsest frontiers; two random ones too.
  for (int i = 0; i < 4; ++i) {
    const Frontier frontier = i == 0 ? Frontier::finest(mt) : i == 1 ? Frontier::coarsest(mt) : random_frontier(mt, rng);
    if (i >= 2) {
      const auto fr = engine::validate_frontier(mt, frontier);
      ASSERT_TRUE(fr.ok()) << where << " frontier " << i << ": " << fr.summary();
    }
    if (mt.boundary_preserved()) {
      EXPECT_NEAR(frontier.volume(mt), original_volume, 1e-9 * original_volume) << where;
    }
    // The last cut exactly; the earlier ones away from their outlines.
    for (std::size_t c = 0; c < cuts.size(); ++c) {
      const double s = c + 1 == cuts.size() ? 0.0 : slack[c];
      EXPECT_EQ(properly_crossed_tets(mt, frontier, cuts[c], s), 0u) << where << " frontier " << i << " cut " << c;
    }
  }
}

void run_sequence(const std::string& name, int cuts, std::uint64_t seed) {
  Mt mt = cut_test_mt(name);
  engine::TetBvh bvh(mt);
  std::mt19937_64 rng(seed);
  const engine::Aabb box = mt_box(mt);
  const double volume = mt.fine_volume();
  std::vector<CutPolygon> polygons;
  std::vector<double> slack;
  cut::SplitTable table;
  std::size_t split = 0, whole = 0;
  // A random frontier followed in place across the cuts, as the World does.
  std::mt19937_64 frontier_rng(seed + 1000);
  Frontier followed = random_frontier(mt, frontier_rng);
  for (int i = 0; i < cuts; ++i) {
    const bool complete = i % 5 == 4;
    polygons.push_back(random_polygon(box, rng, complete));
    slack.push_back(longest_edge_near(mt, bvh, polygons.back()));
    CutMtOptions options;
    options.order = static_cast<JobOrder>(i % 3);
    options.seed = seed + static_cast<std::uint64_t>(i);
    const MtChangeReport r = cut_mt(mt, bvh, polygons.back(), {}, options, &table);
    ASSERT_TRUE(bvh.validate(mt).ok()) << name << " cut " << i << ": " << bvh.validate(mt).summary();
    split += r.counts.split_tets;
    whole += r.counts.whole_fragments;
    EXPECT_EQ(r.counts.new_vertices, r.made_vertices.size());
    // New vertices are numbered in the order of their keys, consecutively.
    const auto key_of = [](const cut::PointKey& k) { return std::tie(k.kind, k.side, k.ids); };
    for (std::size_t k = 1; k < r.made_vertices.size(); ++k) {
      EXPECT_EQ(r.made_vertices[k].id.value, r.made_vertices[k - 1].id.value + 1);
      EXPECT_LT(key_of(r.made_vertices[k - 1].key), key_of(r.made_vertices[k].key)) << "cut " << i << " vertex " << k;
    }
    for (const auto& m : r.made_vertices) {
      Vec3 rest = Vec3::Zero();
      for (int k = 0; k < 4; ++k)
        if (m.parents[k].valid()) rest += m.weights[k] * mt.position(m.parents[k]);
      EXPECT_EQ(rest, mt.position(m.id));
    }
    const Frontier rebuilt = cut::map_frontier(mt, followed, r.fragment_splits);
    cut::follow_cut(mt, followed, r);
    EXPECT_EQ(frontier_difference(followed, rebuilt), "") << name << " cut " << i;
    const auto fr = engine::validate_frontier(mt, followed);
    EXPECT_TRUE(fr.ok()) << name << " cut " << i << ": " << fr.summary();
    check_after_cut(mt, polygons, slack, volume, rng, name + " cut " + std::to_string(i));
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(split, 0u);
  std::printf("%s: %d cuts, %zu tets split, %zu fragments kept whole; MT now %zu live tets, %zu fragments\n",
              name.c_str(), cuts, split, whole, mt.num_live_tets(), mt.num_fragments());
  ::testing::Test::RecordProperty("split_tets", static_cast<int>(split));
  ::testing::Test::RecordProperty("whole_fragments", static_cast<int>(whole));
}

TEST(MtCut, RandomSequenceEllipsoid) { run_sequence("ellipsoid", mtcut::test::scaled(24), 11); }
TEST(MtCut, RandomSequenceLiver) { run_sequence("liver", mtcut::test::scaled(24), 12); }
TEST(MtCut, RandomSequencePaperPreset) { run_sequence("paper", 6, 13); }

TEST(MtCut, OrderOfFragmentsDoesNotMatter) {
  for (const std::string name : {"ellipsoid", "liver"}) {
    std::mt19937_64 rng(21);
    const engine::Aabb box = mt_box(cut_test_mt(name));
    std::vector<CutPolygon> polygons;
    for (int i = 0; i < 6; ++i) polygons.push_back(random_polygon(box, rng, i == 3));
    std::vector<std::vector<std::tuple<TetKey, std::size_t, std::size_t>>> results;
    for (int order = 0; order < 4; ++order) {
      Mt mt = cut_test_mt(name);
      engine::TetBvh bvh(mt);
      for (std::size_t i = 0; i < polygons.size(); ++i) {
        CutMtOptions options;
        options.order = static_cast<JobOrder>(std::min(order, 2));
        options.seed = 100 + static_cast<std::uint64_t>(order) * 7 + i;
        cut_mt(mt, bvh, polygons[i], {}, options);
      }
      ASSERT_TRUE(mt.validate().ok());
      results.push_back(canonical_mt(mt));
    }
    for (std::size_t k = 1; k < results.size(); ++k) EXPECT_TRUE(results[k] == results[0]) << name << " order " << k;
  }
}

TEST(MtCut, ReusedWorkspaceGivesTheSameMtAsFreshOnes) {
  // One workspace through a sequence of cuts (partial, complete, and one on
  // deformed geometry) against a fresh one per cut; the workspace is handed
  // back clean after each, with the MT growing under it.
  for (const std::string name : {"ellipsoid", "liver"}) {
    std::mt19937_64 rng(31);
    Mt reused = cut_test_mt(name), fresh = cut_test_mt(name);
    engine::TetBvh reused_bvh(reused), fresh_bvh(fresh);
    const engine::Aabb box = mt_box(reused);
    cut::MtCutWorkspace workspace;
    cut::SplitTable table;
    for (int i = 0; i < 8; ++i) {
      const CutPolygon polygon = random_polygon(box, rng, i % 4 == 3);
      std::vector<Vec3> geometry;
      if (i == 5) {  // a small shear: deformed positions, the polygon in the same place
        for (const Vec3& p : reused.positions()) geometry.push_back(p + Vec3(0.01 * p.z(), 0, 0));
      }
      const MtChangeReport a = cut_mt(reused, reused_bvh, polygon, geometry, {}, &table, &workspace);
      const MtChangeReport b = cut_mt(fresh, fresh_bvh, polygon, geometry, {}, &table);
      const std::string where = name + " cut " + std::to_string(i);
      const auto clean = workspace.validate();
      ASSERT_TRUE(clean.ok()) << where << ": " << clean.summary();
      ASSERT_TRUE(reused.validate().ok()) << where << ": " << reused.validate().summary();
      EXPECT_EQ(a.counts.split_tets, b.counts.split_tets) << where;
      EXPECT_EQ(a.counts.new_vertices, b.counts.new_vertices) << where;
      ASSERT_TRUE(canonical_mt(reused) == canonical_mt(fresh)) << where;
      ASSERT_EQ(std::vector<Vec3>(reused.positions().begin(), reused.positions().end()),
                std::vector<Vec3>(fresh.positions().begin(), fresh.positions().end()))
          << where;
    }
    EXPECT_GT(reused.num_live_tets(), cut_test_mt(name).num_live_tets()) << name;
  }
}

TEST(MtCut, CandidatesOfTheSamePolygonFindWhatTheWalkFinds) {
  // A cut handed the candidates an earlier cut of its polygon found (with
  // nothing editing the MT between) finds what its own walk of the index
  // finds, over the whole polygon and within a search box around part of
  // it, on an MT that the earlier polygons split (pieces in the index). A
  // part's front after its commit, where the commit's tets are dead, is
  // checked by the part and stroke tests (PartRecord, StrokeCutter).
  for (const std::string name : {"ellipsoid", "liver"}) {
    std::mt19937_64 rng(47);
    Mt mt = cut_test_mt(name);
    engine::TetBvh bvh(mt);
    const engine::Aabb box = mt_box(mt);
    cut::SplitTable table;
    std::size_t compared = 0;
    for (int i = 0; i < 12; ++i) {
      const CutPolygon polygon = random_polygon(box, rng, i % 3 == 2);
      cut::MtCutDef def;
      const cut::MtCut whole(mt, bvh, polygon, {}, def, table);
      const std::string where = name + " cut " + std::to_string(i);
      // A search box: a random corner of the polygon's box.
      engine::Aabb search;
      std::uniform_real_distribution<double> u(0.0, 1.0);
      for (int k = 0; k < 2; ++k) {
        const Vec3 t(u(rng), u(rng), u(rng));
        search.extend(polygon.box_min() + t.cwiseProduct(polygon.box_max() - polygon.box_min()));
      }
      for (const engine::Aabb* within : std::array<const engine::Aabb*, 2>{nullptr, &search}) {
        cut::MtCutDef walked_def, given_def;
        walked_def.search = given_def.search = within;
        given_def.candidates = &whole.candidates();
        const cut::MtCut walked(mt, bvh, polygon, {}, walked_def, table);
        const cut::MtCut given(mt, bvh, polygon, {}, given_def, table);
        EXPECT_EQ(given.candidates(), walked.candidates()) << where << (within ? ", in a search box" : "");
        EXPECT_EQ(given.tets_to_change(), walked.tets_to_change()) << where;
        EXPECT_EQ(given.points_to_make(), walked.points_to_make()) << where;
        compared += walked.candidates().size();
      }
      cut_mt(mt, bvh, polygon, {}, {}, &table);
      ASSERT_TRUE(mt.validate().ok()) << where << ": " << mt.validate().summary();
    }
    EXPECT_GT(compared, 0u) << name << ": no polygon found a tet";
  }
}

// Two tets that share a face are one piece: labels that put them in two
// (each tet's fragments agree with its label: here the root and the drain
// only) are refused for the vertices the pieces share.
TEST(MtPieces, PiecesThatShareAVertexAreRefused) {
  engine::TetMesh mesh;
  mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 1)};
  mesh.tets = {engine::Tet{VertId(0), VertId(1), VertId(2), VertId(3)},
               engine::Tet{VertId(1), VertId(4), VertId(2), VertId(3)}};
  Mt mt = Mt::from_fine_mesh(mesh);
  const FragId drain = mt.add_fragment();
  mt.set_drain(drain);
  for (int t = 0; t < 2; ++t) mt.set_death(engine::TetId(t), drain);
  ASSERT_TRUE(mt.validate().ok()) << mt.validate().summary();
  cut::MtPieces pieces = cut::find_pieces(mt);
  ASSERT_EQ(pieces.count, 1u);
  EXPECT_TRUE(cut::validate_pieces(mt, pieces).ok());
  pieces.count = 2;
  pieces.tet_piece = {0, 1};
  pieces.finest_tets = {1, 1};
  pieces.fragments = {{}, {}};
  const engine::ValidationReport report = cut::validate_pieces(mt, pieces);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.summary().find("is in pieces 0 and 1"), std::string::npos) << report.summary();
}

TEST(MtCut, SeparatingCutGivesTwoValidPieces) {
  for (const std::string name : {"ellipsoid", "liver", "paper"}) {
    Mt mt = cut_test_mt(name);
    engine::TetBvh bvh(mt);
    const engine::Aabb box = mt_box(mt);
    const Vec3 c = box.center(), s = box.hi - box.lo;
    // A plane through the middle, slightly tilted so it meets no vertex exactly.
    const double h = s.norm();
    const Vec3 a = Vec3(0.0137, 1, 0.0071).normalized(), b = Vec3(0.0093, -0.0111, 1).normalized();
    const auto polygon = CutPolygon::from_points({c + h * (a + b), c + h * (b - a), c - h * (a + b), c + h * (a - b)});
    const MtChangeReport r = cut_mt(mt, bvh, polygon);
    ASSERT_TRUE(mt.validate().ok()) << name << ": " << mt.validate().summary();
    EXPECT_GT(r.counts.split_fragments, 0u) << name;
    EXPECT_EQ(r.counts.whole_fragments, 0u) << name;
    const auto pieces = cut::find_pieces(mt);
    ASSERT_TRUE(cut::validate_pieces(mt, pieces).ok()) << name;
    ASSERT_EQ(pieces.count, 2u) << name;
    EXPECT_EQ(cut::count_pieces(mt), 2u) << name;
    const std::vector<double> volumes = cut::piece_volumes(mt, pieces);
    double sum = 0;
    for (std::size_t p = 0; p < pieces.count; ++p) {
      const Mt piece = cut::extract_piece_mt(mt, pieces, p);
      const auto pr = piece.validate();
      EXPECT_TRUE(pr.ok()) << name << " piece " << p << ": " << pr.summary();
      EXPECT_NEAR(piece.fine_volume(), volumes[p], 1e-12 * mt.fine_volume());
      EXPECT_EQ(piece.num_fragments(), pieces.fragments[p].size() + 2);
      sum += piece.fine_volume();
      EXPECT_GT(piece.fine_volume(), 0.05 * mt.fine_volume());
    }
    EXPECT_NEAR(sum, mt.fine_volume(), 1e-9 * mt.fine_volume()) << name;
  }
}

TEST(MtCut, DeformedGeometryCutsWhereTheDeformedTissueIs) {
  // A rigid shift: cutting the shifted object by the shifted polygon is the
  // same as cutting the rest object by the polygon.
  Mt rest_mt = cut_test_mt("ellipsoid");
  Mt moved_mt = rest_mt;
  engine::TetBvh rest_bvh(rest_mt), moved_bvh(moved_mt);
  std::mt19937_64 rng(5);
  const auto polygon = random_polygon(mt_box(rest_mt), rng, false);
  const Vec3 shift(0.25, -0.5, 0.125);  // exact in binary: no rounding in the shift
  std::vector<Vec3> deformed(moved_mt.positions().begin(), moved_mt.positions().end());
  for (Vec3& p : deformed) p += shift;
  std::vector<Vec3> shifted_corners;
  for (const Vec3& p : polygon.corners()) shifted_corners.push_back(p + shift);
  const auto shifted = CutPolygon::from_points(shifted_corners);
  const auto r1 = cut_mt(rest_mt, rest_bvh, polygon);
  const auto r2 = cut_mt(moved_mt, moved_bvh, shifted, deformed);
  ASSERT_TRUE(moved_mt.validate().ok());
  EXPECT_EQ(r1.counts.split_tets, r2.counts.split_tets);
  EXPECT_EQ(r1.counts.new_tets, r2.counts.new_tets);
  ASSERT_EQ(r1.made_vertices.size(), r2.made_vertices.size());
  for (std::size_t i = 0; i < r1.made_vertices.size(); ++i) {
    EXPECT_LT((r1.made_vertices[i].rest - r2.made_vertices[i].rest).norm(), 1e-12);
    EXPECT_LT((r2.made_vertices[i].position - r2.made_vertices[i].rest - shift).norm(), 1e-12);
  }
}

TEST(MtCut, SplitTetsKeepBirthDeathAndNewTetsPerSplitTet) {
  Mt mt = cut_test_mt("ellipsoid");
  engine::TetBvh bvh(mt);
  std::mt19937_64 rng(9);
  const Mt before = mt;
  const auto r = cut_mt(mt, bvh, random_polygon(mt_box(mt), rng, true));
  ASSERT_GT(r.counts.split_tets, 0u);
  std::map<std::int32_t, std::vector<FragId>> parts;
  for (const auto& s : r.fragment_splits) parts[s.old.value] = s.parts;
  const auto same_or_part = [&](FragId old, FragId now) {
    if (old == now) return true;
    const auto it = parts.find(old.value);
    return it != parts.end() && std::find(it->second.begin(), it->second.end(), now) != it->second.end();
  };
  for (const auto& rep : r.replaced) {
    EXPECT_FALSE(mt.alive(rep.old));
    for (std::uint32_t k = 0; k < rep.count; ++k) {
      const TetId t = r.made_tets[rep.first + k];
      EXPECT_TRUE(same_or_part(before.birth(rep.old), mt.birth(t)));
      EXPECT_TRUE(same_or_part(before.death(rep.old), mt.death(t)));
    }
  }
  const double per = static_cast<double>(r.counts.new_tets) / static_cast<double>(r.counts.split_tets);
  EXPECT_LT(per, 6.0);
  // The BVH follows: every live tet is found where it is.
  EXPECT_EQ(bvh.size(), mt.num_live_tets());
}

}  // namespace
}  // namespace mtcut::test

namespace mtcut::test {
namespace {

// A blade spanning the object in z, drawn across it in y over `steps`
// frames at x = x0 (rolling by `turn` radians about y per frame), merged
// into cut polygons as the World does (stroke_sweep.h): after every cut the
// MT is valid. Returns the pieces at the end.
std::size_t stroke_through(const std::string& name, int steps, double turn) {
  Mt mt = cut_test_mt(name);
  engine::TetBvh bvh(mt);
  cut::SplitTable table;
  const engine::Aabb box = mt_box(mt);
  const Vec3 size = box.hi - box.lo, centre = box.center();
  const auto blade = [&](int i) {
    const double y = box.lo.y() - 0.1 * size.y() + 1.2 * size.y() * i / steps;
    const double a = turn * i;
    const Vec3 half = 0.7 * size.z() * Vec3(std::sin(a), 0, std::cos(a));
    const Vec3 mid(centre.x() + 0.23 * size.x(), y, centre.z());
    return std::pair<Vec3, Vec3>(mid + half, mid - half);
  };
  cut::StrokeSweep stroke;
  std::size_t cuts = 0;
  const auto cut_all = [&](const std::vector<CutPolygon>& polygons, int frame) {
    for (const CutPolygon& polygon : polygons) {
      cut_mt(mt, bvh, polygon, {}, CutMtOptions{}, &table);
      ++cuts;
      const auto report = mt.validate();
      EXPECT_TRUE(report.ok()) << name << " frame " << frame << ": " << report.summary();
    }
  };
  for (int i = 0; i <= steps; ++i) {
    const auto [base, tip] = blade(i);
    cut_all(stroke.add(base, tip), i);
  }
  cut_all(stroke.finish(), steps + 1);
  EXPECT_GT(cuts, 0u);
  return cut::find_pieces(mt).count;
}

TEST(MtCut, StraightStrokeSeparatesAndKeepsTheMtValid) {
  EXPECT_EQ(stroke_through("ellipsoid", 30, 0.0), 2u);
  EXPECT_EQ(stroke_through("liver", 30, 0.0), 2u);
}

TEST(MtCut, TurningStrokeKeepsTheMtValid) {
  // Each turn ends a part; parts do not share a blade segment.
  stroke_through("ellipsoid", 20, 0.03);
  stroke_through("liver", 20, 0.03);
}

// A polygon lying in the object's surface passes through that surface's
// vertices, with every tet around them on one side: nothing is separated, so
// nothing changes (no vertex is split into an unused original and a copy).
// Every face of the box MT, both orientations, a polygon inside the face and
// one larger than it (whose outline leaves the object).
TEST(MtCut, PolygonLyingInTheSurfaceChangesNothing) {
  Mt mt = cut_test_mt("box");
  const auto before = canonical_mt(mt);
  engine::TetBvh bvh(mt);
  const engine::Aabb box = mt_box(mt);
  const Vec3 c = box.center(), half = 0.5 * (box.hi - box.lo);
  for (int axis = 0; axis < 3; ++axis)
    for (const double end : {-1.0, 1.0})
      for (const double extent : {0.6, 1.3})
        for (const bool flip : {false, true}) {
          const int u = (axis + 1) % 3, v = (axis + 2) % 3;
          std::vector<Vec3> corners;
          for (const auto& [su, sv] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
            Vec3 p = c;
            p[axis] = end < 0 ? box.lo[axis] : box.hi[axis];
            p[u] += su * extent * half[u];
            p[v] += sv * extent * half[v];
            corners.push_back(p);
          }
          if (flip) std::reverse(corners.begin(), corners.end());
          const std::string what = "axis " + std::to_string(axis) + " end " + std::to_string(end) + " extent " +
                                   std::to_string(extent) + (flip ? " flipped" : "");
          const cut::MtChangeReport r = cut::cut_mt(mt, bvh, CutPolygon::from_points(corners));
          EXPECT_EQ(r.counts.split_tets, 0u) << what;
          EXPECT_EQ(r.counts.relabeled_tets, 0u) << what;
          EXPECT_EQ(r.counts.new_vertices, 0u) << what;
          const auto report = mt.validate();
          ASSERT_TRUE(report.ok()) << what << ": " << report.summary();
        }
  EXPECT_TRUE(canonical_mt(mt) == before);
}

}  // namespace
}  // namespace mtcut::test
