#include "engine/mt/tet_bvh.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

#include "engine/mt/frontier.h"
#include "engine/mt/selective_refinement.h"
#include "tests/engine/mt/mt_test_util.h"

namespace mtcut::engine {
namespace {

using mtcut::test::test_mt;

std::vector<TetId> brute_force_containing(const Mt& mt, const Vec3& p) {
  std::vector<TetId> out;
  for (std::size_t t = 0; t < mt.num_tets(); ++t)
    if (mt.alive(TetId(t)) && tet_contains(mt, TetId(t), p)) out.emplace_back(t);
  return out;
}

std::vector<TetId> bvh_containing(const Mt& mt, const TetBvh& bvh, const Vec3& p) {
  std::vector<TetId> out;
  bvh.for_each_containing(mt, p, [&](TetId t) {
    out.push_back(t);
    return true;
  });
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Vec3> random_points(const Mt& mt, int n, unsigned seed) {
  Aabb box;
  for (const Vec3& p : mt.positions()) box.extend(p);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-0.05, 1.05);
  std::vector<Vec3> points;
  for (int i = 0; i < n; ++i)
    points.push_back(box.lo + (box.hi - box.lo).cwiseProduct(Vec3(unit(rng), unit(rng), unit(rng))));
  // Vertices too: points on many tets at once.
  for (std::size_t v = 0; v < mt.num_vertices(); v += 37) points.push_back(mt.position(VertId(v)));
  return points;
}

TEST(TetBvh, FindsEveryTetHoldingAPointAtEveryResolution) {
  for (const char* name : {"liver", "box"}) {
    const Mt& mt = test_mt(name);
    const TetBvh bvh(mt);
    EXPECT_EQ(bvh.size(), mt.num_live_tets());
    EXPECT_TRUE(bvh.validate(mt).ok()) << name << ": " << bvh.validate(mt).summary();
    std::size_t inside = 0;
    for (const Vec3& p : random_points(mt, 300, 1)) {
      const auto expected = brute_force_containing(mt, p);
      ASSERT_EQ(bvh_containing(mt, bvh, p), expected) << name;
      inside += !expected.empty();
      EXPECT_EQ(bvh.locate(mt, p).valid(), !expected.empty());
    }
    EXPECT_GT(inside, 50u);
  }
}

TEST(TetBvh, LocatesInAFrontier) {
  const Mt& mt = test_mt("ellipsoid");
  const TetBvh bvh(mt);
  Aabb box;
  for (const Vec3& p : mt.positions()) box.extend(p);
  ErrorField field;
  field.focus = Segment::point(box.lo);
  field.near_error = 0.0;
  field.growth = 0.3;
  const Frontier frontier = extract_frontier(mt, field);
  for (const Vec3& p : random_points(mt, 300, 2)) {
    const TetId found = bvh.locate_in(mt, frontier, p);
    bool any = false;
    for (TetId t : frontier.tets()) any = any || tet_contains(mt, t, p);
    ASSERT_EQ(found.valid(), any);
    if (found.valid()) {
      EXPECT_TRUE(frontier.has_tet(found));
      EXPECT_TRUE(tet_contains(mt, found, p));
    }
  }
}

TEST(TetBvh, ARefinedVertexLiesInTheTetsItsFragmentCreated) {
  const Mt& mt = test_mt("ellipsoid");
  for (std::size_t i = 0; i < mt.num_fragments(); ++i) {
    const FragId f(i);
    if (f == mt.root() || f == mt.drain()) continue;
    // The vertex the collapse removed: in replaced(f), not in created(f).
    std::set<VertId> before, after;
    for (TetId t : mt.replaced(f)) before.insert(mt.tet(t).begin(), mt.tet(t).end());
    for (TetId t : mt.created(f)) after.insert(mt.tet(t).begin(), mt.tet(t).end());
    for (VertId v : before)
      if (!after.count(v)) {
        const TetId t = locate_among(mt, mt.created(f), mt.position(v));
        ASSERT_TRUE(t.valid()) << "fragment " << i;
        EXPECT_TRUE(tet_contains(mt, t, mt.position(v)));
      }
  }
  EXPECT_FALSE(locate_among(mt, mt.created(mt.root()), Vec3(10, 10, 10)).valid());
}

// What the cutter will do: replace a tet by pieces with the same birth and
// death (here: four tets around its centroid).
std::vector<TetId> split_at_centroid(Mt& mt, TetId t) {
  const Tet v = mt.tet(t);
  const auto c = mt.corners(t);
  const VertId m = mt.add_vertex((c[0] + c[1] + c[2] + c[3]) / 4.0);
  const FragId birth = mt.birth(t), death = mt.death(t);
  mt.kill_tet(t);
  std::vector<TetId> pieces;
  for (int i = 0; i < 4; ++i) {
    Tet piece = v;
    piece[i] = m;
    pieces.push_back(mt.add_tet(piece, birth, death, 0));
  }
  return pieces;
}

TEST(TetBvh, FollowsReplacedTets) {
  Mt mt = test_mt("box");  // a copy to edit
  TetBvh bvh(mt);
  std::mt19937 rng(9);
  for (int round = 0; round < 3; ++round) {
    // Few edits: applied in place; then many: a rebuild.
    const int edits = round == 0 ? 10 : 400;
    for (int k = 0; k < edits; ++k) {
      TetId t(static_cast<std::size_t>(rng() % mt.num_tets()));
      while (!mt.alive(t)) t = TetId(static_cast<std::size_t>(rng() % mt.num_tets()));
      const auto pieces = split_at_centroid(mt, t);
      bvh.replace(mt, t, pieces);
      ASSERT_TRUE(bvh.validate(mt).ok()) << bvh.validate(mt).summary();
    }
    EXPECT_EQ(bvh.size(), mt.num_live_tets());
    for (const Vec3& p : random_points(mt, 150, 3 + static_cast<unsigned>(round)))
      ASSERT_EQ(bvh_containing(mt, bvh, p), brute_force_containing(mt, p));
  }
}

// A cut reserves room for what it adds (TetBvh::reserve): the edits then
// grow no array, and the index stays exact.
TEST(TetBvh, ReservedRoomTakesTheEditsWithoutGrowing) {
  Mt mt = test_mt("box");  // a copy to edit
  TetBvh bvh(mt);
  constexpr std::size_t kEdits = 200;  // four pieces each (split_at_centroid)
  mt.reserve(mt.num_vertices() + kEdits, mt.num_tets() + 4 * kEdits);
  bvh.reserve(mt.num_tets() + 4 * kEdits, 4 * kEdits);
  const std::size_t bytes = bvh.bytes();
  std::mt19937 rng(11);
  for (std::size_t k = 0; k < kEdits; ++k) {
    TetId t(static_cast<std::size_t>(rng() % mt.num_tets()));
    while (!mt.alive(t)) t = TetId(static_cast<std::size_t>(rng() % mt.num_tets()));
    bvh.replace(mt, t, split_at_centroid(mt, t));
  }
  ASSERT_TRUE(bvh.validate(mt).ok()) << bvh.validate(mt).summary();
  EXPECT_EQ(bvh.bytes(), bytes) << "an array grew past the reserved room";
  EXPECT_EQ(bvh.size(), mt.num_live_tets());
  for (const Vec3& p : random_points(mt, 150, 21)) ASSERT_EQ(bvh_containing(mt, bvh, p), brute_force_containing(mt, p));
}

// Edits after a mark, the MT then restored (the pieces killed, the split
// tets revived), and the index rolled back: exact again, and no wear left.
TEST(TetBvh, RollBackUndoesTheEditsSinceTheMark) {
  Mt mt = test_mt("box");  // a copy to edit
  TetBvh bvh(mt);
  std::mt19937 rng(5);
  for (int round = 0; round < 3; ++round) {
    const std::size_t tets_before = mt.num_tets();
    const TetBvh::Mark mark = bvh.mark();
    std::vector<std::pair<TetId, std::array<FragId, 2>>> split;
    std::vector<TetId> made;
    for (int k = 0; k < 60; ++k) {
      TetId t(static_cast<std::size_t>(rng() % tets_before));  // tets of before the mark
      while (!mt.alive(t)) t = TetId(static_cast<std::size_t>(rng() % tets_before));
      const std::array<FragId, 2> fragments{mt.birth(t), mt.death(t)};
      const auto pieces = split_at_centroid(mt, t);
      bvh.replace(mt, t, pieces);
      split.emplace_back(t, fragments);
      made.insert(made.end(), pieces.begin(), pieces.end());
    }
    ASSERT_TRUE(bvh.validate(mt).ok()) << bvh.validate(mt).summary();
    for (TetId t : made)
      if (mt.alive(t)) mt.kill_tet(t);
    for (auto it = split.rbegin(); it != split.rend(); ++it)
      if (!mt.alive(it->first)) mt.revive_tet(it->first, it->second[0], it->second[1]);
    bvh.roll_back(mark);
    ASSERT_TRUE(bvh.validate(mt).ok()) << "round " << round << ": " << bvh.validate(mt).summary();
    EXPECT_FALSE(bvh.worn());
    EXPECT_FALSE(bvh.marked());
    EXPECT_THROW(bvh.roll_back(mark), std::logic_error);
    for (const Vec3& p : random_points(mt, 100, 40 + static_cast<unsigned>(round)))
      ASSERT_EQ(bvh_containing(mt, bvh, p), brute_force_containing(mt, p));
  }
}

// A stroke's front, split and taken back frame after frame in the same
// tets (cut/mt/cut_retraction.h, retract_replacements): a tet put back
// takes its slot again, the pieces of its next split the entries its last
// pieces left. Fifty rounds over sixty tets wear the index no more than
// one (without either, 27,000 edits: a rebuild's worth), grow none of its
// arrays, and leave it exact.
TEST(TetBvh, SplitsTakenBackAndMadeAgainWearNothing) {
  Mt mt = test_mt("box");  // a copy to edit
  TetBvh bvh(mt);
  std::mt19937 rng(13);
  std::vector<TetId> tets;
  while (tets.size() < 60) {
    const TetId t(static_cast<std::size_t>(rng() % mt.num_tets()));
    if (std::find(tets.begin(), tets.end(), t) == tets.end()) tets.push_back(t);
  }
  mt.reserve(mt.num_vertices() + 50 * tets.size(), mt.num_tets() + 200 * tets.size());
  bvh.reserve(mt.num_tets() + 200 * tets.size(), 0);
  std::size_t bytes = 0, edits = 0;
  for (int round = 0; round < 50; ++round) {
    std::vector<std::vector<TetId>> pieces;
    for (TetId t : tets) {
      pieces.push_back(split_at_centroid(mt, t));
      bvh.replace(mt, t, pieces.back());
    }
    ASSERT_TRUE(bvh.validate(mt).ok()) << "round " << round << ": " << bvh.validate(mt).summary();
    for (std::size_t i = 0; i < tets.size(); ++i) {
      const FragId birth = mt.birth(pieces[i][0]), death = mt.death(pieces[i][0]);
      for (TetId piece : pieces[i]) {
        bvh.remove(piece);
        mt.kill_tet(piece);
      }
      mt.revive_tet(tets[i], birth, death);
      bvh.insert(mt, tets[i]);
    }
    ASSERT_TRUE(bvh.validate(mt).ok()) << "round " << round << ": " << bvh.validate(mt).summary();
    if (round == 0) bytes = bvh.bytes(), edits = bvh.edits();
    EXPECT_EQ(bvh.bytes(), bytes) << "round " << round << ": an array grew";
    EXPECT_EQ(bvh.edits(), edits) << "round " << round;
    EXPECT_FALSE(bvh.worn()) << "round " << round;
  }
  EXPECT_FALSE(bvh.refresh(mt));
  EXPECT_EQ(bvh.size(), mt.num_live_tets());
  for (const Vec3& p : random_points(mt, 150, 17)) ASSERT_EQ(bvh_containing(mt, bvh, p), brute_force_containing(mt, p));
}

// Rolled back over edits that put a tet back in its slot and gave a
// removed tet's entry to another: the index as it was at the mark.
TEST(TetBvh, RollBackUndoesSlotsRetakenAndEntriesReused) {
  Mt mt = test_mt("box");  // a copy to edit
  TetBvh bvh(mt);
  const TetId t(23), u(41);
  ASSERT_TRUE(mt.alive(t) && mt.alive(u));
  const FragId birth = mt.birth(t), death = mt.death(t);
  const std::vector<TetId> first = split_at_centroid(mt, t);
  bvh.replace(mt, t, first);  // t's slot empty, its pieces listed
  const FragId u_birth = mt.birth(u), u_death = mt.death(u);
  const std::vector<TetId> u_first = split_at_centroid(mt, u);
  bvh.replace(mt, u, u_first);
  for (TetId piece : u_first) {  // u's leaf left with removed entries
    bvh.remove(piece);
    mt.kill_tet(piece);
  }
  mt.revive_tet(u, u_birth, u_death);
  bvh.insert(mt, u);
  ASSERT_TRUE(bvh.validate(mt).ok()) << bvh.validate(mt).summary();
  const TetBvh::Mark mark = bvh.mark();
  const std::vector<TetId> u_pieces = split_at_centroid(mt, u);  // taking the entries u's last pieces left
  bvh.replace(mt, u, u_pieces);
  ASSERT_TRUE(bvh.validate(mt).ok()) << bvh.validate(mt).summary();
  for (TetId piece : first) {  // the split taken back ...
    bvh.remove(piece);
    mt.kill_tet(piece);
  }
  mt.revive_tet(t, birth, death);
  bvh.insert(mt, t);
  ASSERT_TRUE(bvh.validate(mt).ok()) << bvh.validate(mt).summary();
  const std::vector<TetId> second = split_at_centroid(mt, t);  // ... and made again
  bvh.replace(mt, t, second);
  ASSERT_TRUE(bvh.validate(mt).ok()) << bvh.validate(mt).summary();
  // The MT as at the mark, and the index rolled back to it.
  for (TetId piece : second) mt.kill_tet(piece);
  for (TetId piece : u_pieces) mt.kill_tet(piece);
  mt.revive_tet(u, u_birth, u_death);
  for (TetId piece : first) mt.revive_tet(piece, birth, death);
  bvh.roll_back(mark);
  ASSERT_TRUE(bvh.validate(mt).ok()) << bvh.validate(mt).summary();
  for (const Vec3& p : random_points(mt, 100, 29)) ASSERT_EQ(bvh_containing(mt, bvh, p), brute_force_containing(mt, p));
  // And t put back once more takes its slot: no slot is empty and no tet
  // listed, as in a fresh index.
  for (TetId piece : first) {
    bvh.remove(piece);
    mt.kill_tet(piece);
  }
  mt.revive_tet(t, birth, death);
  bvh.insert(mt, t);
  ASSERT_TRUE(bvh.validate(mt).ok()) << bvh.validate(mt).summary();
  EXPECT_EQ(bvh.edits(), 0u) << "a slot left empty or a tet listed";
}

TEST(TetBvh, ValidateFindsAnIndexThatMissedAnEdit) {
  Mt mt = test_mt("box");
  TetBvh bvh(mt);
  ASSERT_TRUE(bvh.validate(mt).ok()) << bvh.validate(mt).summary();
  // Pieces added to the MT but not to the index: live tets it misses, and a
  // killed tet it still lists.
  const TetId t(17);
  ASSERT_TRUE(mt.alive(t));
  const auto pieces = split_at_centroid(mt, t);
  const std::string summary = bvh.validate(mt).summary();
  EXPECT_NE(summary.find("tet 17 is indexed but not a live tet"), std::string::npos) << summary;
  EXPECT_NE(summary.find("tet " + std::to_string(pieces[0].value) + " is live but not indexed"), std::string::npos)
      << summary;
  bvh.replace(mt, t, pieces);
  EXPECT_TRUE(bvh.validate(mt).ok()) << bvh.validate(mt).summary();
}

TEST(TetBvh, OverlapQueryReturnsEveryCandidate) {
  const Mt& mt = test_mt("liver");
  const TetBvh bvh(mt);
  Aabb query;
  query.extend(mt.position(VertId(0)));
  query.extend(mt.position(VertId(50)));
  std::vector<TetId> found;
  bvh.for_each_overlapping(mt, query, [&](TetId t) {
    found.push_back(t);
    return true;
  });
  std::sort(found.begin(), found.end());
  std::vector<TetId> expected;
  for (std::size_t t = 0; t < mt.num_tets(); ++t)
    if (mt.alive(TetId(t)) && tet_box(mt, TetId(t)).overlaps(query)) expected.emplace_back(t);
  EXPECT_EQ(found, expected);
  EXPECT_FALSE(expected.empty());
}

}  // namespace
}  // namespace mtcut::engine
