// CutClassifier on one tet, the unit corner (0,0,0) (1,0,0) (0,1,0) (0,0,1),
// against planes x = const, where every side, crossing and case is known by
// hand: a plane through the middle, a polygon that covers one crossing
// only, a plane near three corners (snapped onto them), the same with one
// corner vetoed (kept off, its cut point held `snap` away).

#include "cut/tet_classifier.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace mtcut::cut {
namespace {

using engine::Vec3;

const std::vector<Vec3> kCorner = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
const Tet kTet{VertId(0), VertId(1), VertId(2), VertId(3)};

// The square of the plane x = `x` over y, z in [lo, hi].
CutPolygon square_at(double x, double lo, double hi) {
  return CutPolygon::from_points({Vec3(x, lo, lo), Vec3(x, hi, lo), Vec3(x, hi, hi), Vec3(x, lo, hi)});
}

TEST(TetClassifier, APlaneThroughTheMiddleCutsOffOneCorner) {
  const CutPolygon square = square_at(0.3, -1, 2);  // the classifier holds it by reference
  CutClassifier c(square, kCorner);
  ASSERT_TRUE(c.add_candidate(kTet));
  EXPECT_TRUE(c.take_new_on_vertices().empty());
  c.finalize();
  const VertexState far = c.state(VertId(1));
  ASSERT_TRUE(is_strict(far));
  for (int v : {0, 2, 3}) {
    EXPECT_TRUE(is_strict(c.state(VertId(v))));
    EXPECT_NE(c.state(VertId(v)), far) << "vertex " << v;
  }
  // From the lower id: x = t on (0, 1), x = 1 - t on (1, 2) and (1, 3).
  EXPECT_NEAR(c.crossing_parameter(VertId(0), VertId(1)), 0.3, 1e-15);
  EXPECT_NEAR(c.crossing_parameter(VertId(1), VertId(2)), 0.7, 1e-15);
  EXPECT_NEAR(c.crossing_parameter(VertId(1), VertId(3)), 0.7, 1e-15);
  const TetConfig config = c.configure(kTet);
  EXPECT_TRUE(config.is_cut());
  EXPECT_EQ(config.cut_case(), CutCase::kA);
  EXPECT_FALSE(config.bent);
  // A tet wholly on one side is no candidate.
  const std::vector<Vec3> beyond = {Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(2, 1, 0), Vec3(2, 0, 1)};
  CutClassifier away(square, beyond);
  EXPECT_FALSE(away.add_candidate(kTet));
}

TEST(TetClassifier, APolygonThatCoversOneCrossingCutsTheTetPartially) {
  // The square spans y, z in [-1, 0.1]: it covers the crossing on (0, 1) at
  // (0.3, 0, 0), not those on (1, 2) at (0.3, 0.7, 0) and (1, 3) at (0.3, 0, 0.7).
  const CutPolygon square = square_at(0.3, -1, 0.1);
  CutClassifier c(square, kCorner);
  ASSERT_TRUE(c.add_candidate(kTet));
  c.finalize();
  EXPECT_TRUE(c.crossing_covered(VertId(0), VertId(1)));
  EXPECT_FALSE(c.crossing_covered(VertId(1), VertId(2)));
  EXPECT_FALSE(c.crossing_covered(VertId(1), VertId(3)));
  const TetConfig config = c.configure(kTet);
  EXPECT_TRUE(config.is_cut());
  EXPECT_EQ(config.cut_case(), CutCase::kC);
}

TEST(TetClassifier, APlaneNearThreeCornersSnapsOntoThem) {
  // x = 0.05 meets the three edges at 0.05 of their length from the x = 0
  // corners, within snap = 0.15: those corners are on the cut, split, and
  // the tet is cut through them.
  const CutPolygon square = square_at(0.05, -1, 2);
  CutClassifier c(square, kCorner, ClassifierDef{.snap = 0.15});
  ASSERT_TRUE(c.add_candidate(kTet));
  std::vector<VertId> on = c.take_new_on_vertices();
  std::sort(on.begin(), on.end());
  EXPECT_EQ(on, (std::vector<VertId>{VertId(0), VertId(2), VertId(3)}));
  c.finalize();
  for (int v : {0, 2, 3}) {
    EXPECT_EQ(c.state(VertId(v)), VertexState::kOnActive) << "vertex " << v;
    EXPECT_TRUE(c.snapped(VertId(v))) << "vertex " << v;
  }
  EXPECT_TRUE(is_strict(c.state(VertId(1))));
  EXPECT_EQ(c.configure(kTet).cut_case(), CutCase::kVertex);
}

TEST(TetClassifier, AVetoedCornerIsKeptOffAndItsCutPointHeldAway) {
  const CutPolygon square = square_at(0.05, -1, 2);
  CutClassifier c(square, kCorner, ClassifierDef{.snap = 0.15});
  c.veto(VertId(0));
  ASSERT_TRUE(c.add_candidate(kTet));
  c.finalize();
  EXPECT_TRUE(is_strict(c.state(VertId(0))));
  EXPECT_NE(c.state(VertId(0)), c.state(VertId(1)));
  EXPECT_TRUE(c.vetoed(VertId(0)));
  EXPECT_TRUE(c.veto_requested(VertId(0)));
  // Held `snap` from the vetoed corner, not at 0.05.
  EXPECT_DOUBLE_EQ(c.crossing_parameter(VertId(0), VertId(1)), 0.15);
  for (int v : {2, 3}) EXPECT_EQ(c.state(VertId(v)), VertexState::kOnActive) << "vertex " << v;
}

}  // namespace
}  // namespace mtcut::cut
