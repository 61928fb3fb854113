// StrokeCrack's bookkeeping: the junctions, sides and front a stroke's next
// step is given, from the change reports of its earlier steps.
#include "cut/mt/stroke_crack.h"

#include <gtest/gtest.h>

namespace mtcut::cut {
namespace {

CutPolygon blade_quad(double x0, double x1) {
  return CutPolygon::from_points({Vec3(x0, 0, 1), Vec3(x1, 0, 1), Vec3(x1, 0, -1), Vec3(x0, 0, -1)});
}

MadeVertex made(std::int32_t id, PointKind kind, std::int8_t side, std::array<std::int32_t, 4> ids) {
  MadeVertex v;
  v.rest = Vec3::Zero();
  v.id = VertId(id);
  v.key.kind = kind;
  v.key.side = side;
  v.key.ids = ids;
  return v;
}

TEST(StrokeCrack, StepsSharingAnEdgeContinueTheCrackAndOthersStartANewOne) {
  StrokeCrack crack;
  const CutPolygon q0 = blade_quad(0, 1), q1 = blade_quad(1, 2), far = blade_quad(5, 6);
  // The first step: no junction, its leading edge found by the blade's ends.
  const CutContinuation first = crack.continuation(q0, Vec3(1, 0, 1), Vec3(1, 0, -1));
  EXPECT_TRUE(first.junctions.empty());
  EXPECT_EQ(first.leading_edge, q0.edge_between(Vec3(1, 0, 1), Vec3(1, 0, -1)));
  EXPECT_GE(first.leading_edge, 0);
  MtChangeReport r0;
  r0.made_vertices = {made(10, PointKind::kEdgePoint, -1, {1, 2, -1, -1}),
                      made(11, PointKind::kEdgePoint, 1, {1, 2, -1, -1}),
                      made(12, PointKind::kVertexCopy, -1, {3, -1, -1, -1}),
                      made(13, PointKind::kFacePoint, 0, {4, 5, 6, -1})};
  crack.record(q0, r0.made_vertices);
  EXPECT_TRUE(crack.validate().ok()) << crack.validate().summary();
  EXPECT_EQ(crack.num_sided(), 4u);  // 10, 11, the copy 12 and vertex 3, which kept its id on the + side
  EXPECT_EQ(crack.num_junctions(), 0u);

  // The next step starts at q0's edge: one junction, the sides, the front.
  const CutContinuation next = crack.continuation(q1, Vec3(2, 0, 1), Vec3(2, 0, -1));
  ASSERT_EQ(next.junctions.size(), 1u);
  ASSERT_NE(next.sides, nullptr);
  EXPECT_EQ(next.sides->at(10), -1);
  EXPECT_EQ(next.sides->at(11), 1);
  EXPECT_EQ(next.sides->at(12), -1);
  EXPECT_EQ(next.sides->at(3), 1);
  ASSERT_EQ(next.front.size(), 1u);
  EXPECT_EQ(next.front[0].id, VertId(13));
  EXPECT_EQ(next.front[0].face[2], VertId(6));
  // It splits the front point 13: no longer front, now sided.
  MtChangeReport r1;
  r1.made_vertices = {made(20, PointKind::kVertexCopy, -1, {13, -1, -1, -1})};
  crack.record(q1, r1.made_vertices);
  EXPECT_TRUE(crack.validate().ok()) << crack.validate().summary();
  EXPECT_EQ(crack.num_junctions(), 1u);
  EXPECT_EQ(crack.num_sided(), 6u);
  EXPECT_TRUE(crack.continuation(q1, Vec3(1, 0, 1), Vec3(1, 0, -1)).front.empty());

  // A polygon away from the last one starts a new crack: nothing of the old
  // one (its sides, its front) is carried over.
  MtChangeReport r2;
  r2.made_vertices = {made(21, PointKind::kFacePoint, 0, {7, 8, 9, -1})};
  crack.record(q1, r2.made_vertices);
  EXPECT_EQ(crack.continuation(q1, Vec3(1, 0, 1), Vec3(1, 0, -1)).front.size(), 1u);
  EXPECT_TRUE(crack.continuation(far, Vec3(6, 0, 1), Vec3(6, 0, -1)).junctions.empty());
  crack.record(far, {});
  EXPECT_TRUE(crack.validate().ok()) << crack.validate().summary();
  EXPECT_EQ(crack.num_sided(), 0u);
  EXPECT_EQ(crack.num_junctions(), 0u);
  EXPECT_TRUE(crack.continuation(blade_quad(6, 7), Vec3(7, 0, 1), Vec3(7, 0, -1)).front.empty());
  crack.clear();
  EXPECT_TRUE(crack.validate().ok()) << crack.validate().summary();
  EXPECT_EQ(crack.num_junctions(), 0u);
}

// The MT was compacted (the cutter reclaims retracted cuts' slots between a
// stroke's frames): the crack's sides and front follow the vertices' new
// ids, and what the compaction dropped leaves the crack.
TEST(StrokeCrack, RenumberingFollowsTheCompaction) {
  StrokeCrack crack;
  const CutPolygon q0 = blade_quad(0, 1), q1 = blade_quad(1, 2);
  const std::vector<MadeVertex> made0 = {made(10, PointKind::kEdgePoint, -1, {1, 2, -1, -1}),
                                         made(11, PointKind::kEdgePoint, 1, {1, 2, -1, -1}),
                                         made(12, PointKind::kFacePoint, 0, {4, 5, 6, -1}),
                                         made(13, PointKind::kFacePoint, 0, {4, 5, 7, -1})};
  crack.record(q0, made0);
  engine::Mt::Compaction compaction;
  compaction.vertex_map.assign(14, -1);
  for (std::int32_t v = 0; v < 14; ++v) compaction.vertex_map[v] = v < 7 ? v : v - 3;  // 7, 8, 9 dropped
  compaction.vertex_map[11] = -1;  // an edge point no live tet uses any more
  compaction.vertex_map[7] = -1;   // a corner of face point 13's face
  crack.renumber(compaction);
  EXPECT_TRUE(crack.validate().ok()) << crack.validate().summary();
  EXPECT_EQ(crack.num_sided(), 1u);
  const CutContinuation next = crack.continuation(q1, Vec3(2, 0, 1), Vec3(2, 0, -1));
  ASSERT_EQ(next.junctions.size(), 1u);
  EXPECT_EQ(next.sides->at(7), -1);  // 10, now 7
  EXPECT_FALSE(next.sides->contains(8));
  ASSERT_EQ(next.front.size(), 1u);  // 12, now 9, on the face (4, 5, 6)
  EXPECT_EQ(next.front[0].id, VertId(9));
  EXPECT_EQ(next.front[0].face[2], VertId(6));
}

}  // namespace
}  // namespace mtcut::cut
