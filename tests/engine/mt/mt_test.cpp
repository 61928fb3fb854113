#include "engine/mt/mt.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "engine/mt/frontier.h"
#include "engine/mt/tet_error.h"
#include "engine/tet_geometry.h"

namespace mtcut::engine {
namespace {

// A tet split at its centroid into four (the fine mesh), and one fragment
// that collapses the centroid onto corner 0 (the big tet back).
struct StarMt {
  Mt mt;
  TetId big;
  FragId collapse;
};

TetMesh centroid_split() {
  TetMesh mesh;
  mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(0.25, 0.25, 0.25)};
  const VertId c(4);
  const Tet big = {VertId(0), VertId(1), VertId(2), VertId(3)};
  for (int i = 0; i < 4; ++i) {
    Tet t = big;
    t[i] = c;
    mesh.tets.push_back(t);
  }
  return mesh;
}

StarMt make_star_mt() {
  StarMt s{Mt::from_fine_mesh(centroid_split()), TetId(), FragId()};
  Mt& mt = s.mt;
  s.collapse = mt.add_fragment();
  for (std::size_t i = 0; i < 4; ++i) mt.set_death(TetId(i), s.collapse);
  s.big = mt.add_tet({VertId(0), VertId(1), VertId(2), VertId(3)}, s.collapse, FragId(), 0xF);
  const FragId drain = mt.add_fragment();
  mt.set_drain(drain);
  mt.set_death(s.big, drain);
  return s;
}

TEST(Mt, FromFineMeshMarksTheSurface) {
  const Mt mt = Mt::from_fine_mesh(centroid_split());
  EXPECT_EQ(mt.num_fragments(), 1u);
  EXPECT_EQ(mt.created(mt.root()).size(), 4u);
  for (std::size_t t = 0; t < 4; ++t) {
    // Only the face opposite the centroid (local index t) is on the surface.
    EXPECT_EQ(mt.boundary_mask(TetId(t)), 1u << t);
    EXPECT_FALSE(mt.death(TetId(t)).valid());
  }
  EXPECT_NEAR(mt.fine_volume(), 1.0 / 6.0, 1e-15);
}

TEST(Mt, HandBuiltMtIsValidWithDerivedArcs) {
  const StarMt s = make_star_mt();
  const ValidationReport report = s.mt.validate();
  EXPECT_TRUE(report.ok()) << report.summary();
  EXPECT_EQ(s.mt.parents(s.collapse), std::vector<FragId>{s.mt.root()});
  EXPECT_EQ(s.mt.children(s.collapse), std::vector<FragId>{s.mt.drain()});
  EXPECT_EQ(s.mt.children(s.mt.root()), std::vector<FragId>{s.collapse});
  EXPECT_EQ(s.mt.topological_order(), (std::vector<FragId>{s.mt.root(), s.collapse, s.mt.drain()}));
  EXPECT_FLOAT_EQ(s.mt.fragment_error(s.collapse), s.mt.error(s.big));
  EXPECT_LE(s.mt.fragment_error(s.mt.root()), s.mt.error(s.big));
  EXPECT_EQ(s.mt.num_live_tets(), 5u);
}

TEST(Mt, ListsFollowBirthDeathAndKill) {
  StarMt s = make_star_mt();
  Mt& mt = s.mt;
  // Re-attach the big tet's death to a new fragment and back.
  const FragId extra = mt.add_fragment();
  mt.set_death(s.big, extra);
  EXPECT_TRUE(mt.replaced(mt.drain()).empty());
  EXPECT_EQ(mt.replaced(extra).size(), 1u);
  mt.set_death(s.big, mt.drain());
  EXPECT_TRUE(mt.replaced(extra).empty());
  // Killing a tet in the middle of root's list keeps the other slots right.
  mt.kill_tet(TetId(1));
  EXPECT_FALSE(mt.alive(TetId(1)));
  EXPECT_EQ(mt.num_live_tets(), 4u);
  auto created = std::vector<TetId>(mt.created(mt.root()).begin(), mt.created(mt.root()).end());
  std::sort(created.begin(), created.end());
  EXPECT_EQ(created, (std::vector<TetId>{TetId(0), TetId(2), TetId(3)}));
  mt.set_birth(TetId(3), extra);
  EXPECT_EQ(mt.created(extra).size(), 1u);
  EXPECT_EQ(mt.created(mt.root()).size(), 2u);
}

TEST(Mt, ValidateCatchesABrokenFragment) {
  StarMt s = make_star_mt();
  // A tet of the fine mesh now survives into the coarsest mesh: it overlaps
  // the big tet there, and the fragment no longer fills what it replaces.
  s.mt.set_death(TetId(2), s.mt.drain());
  const ValidationReport report = s.mt.validate();
  EXPECT_FALSE(report.ok());
  EXPECT_NE(report.summary().find("fragment"), std::string::npos) << report.summary();
}

TEST(Mt, ValidateCatchesAMissingTet) {
  StarMt s = make_star_mt();
  s.mt.kill_tet(TetId(0));
  EXPECT_FALSE(s.mt.validate().ok());
}

TEST(Mt, ValidateCatchesAWrongSurfaceMark) {
  StarMt s = make_star_mt();
  s.mt.set_boundary_mask(TetId(0), 0);  // its outer face is unmarked: looks like a hanging face
  const ValidationReport report = s.mt.validate();
  EXPECT_FALSE(report.ok());
  EXPECT_NE(report.summary().find("hanging"), std::string::npos) << report.summary();
}

TEST(Mt, ValidateCatchesACycle) {
  StarMt s = make_star_mt();
  // The drain now also creates a tet that the collapse replaces.
  const TetId t = s.mt.add_tet({VertId(0), VertId(1), VertId(2), VertId(4)}, s.mt.drain(), s.collapse, 0);
  (void)t;
  EXPECT_FALSE(s.mt.validate().ok());
}

// A cut's pieces (add_piece) live in the fragments of the tet they split and
// carry its error, so the fragment's error does not move.
TEST(Mt, PiecesInheritTheirSplitTetsFragmentsAndError) {
  StarMt s = make_star_mt();
  const float before = s.mt.fragment_error(s.collapse);
  const Tet big = s.mt.tet(s.big);
  std::vector<TetId> pieces;
  for (int i = 0; i < 4; ++i) {
    Tet t = big;
    t[static_cast<std::size_t>(i)] = VertId(4);  // the centroid
    pieces.push_back(s.mt.add_piece(t, s.big, static_cast<FaceMask>(1u << i)));
  }
  const float whole_error = s.mt.error(s.big);
  s.mt.kill_tet(s.big);
  const ValidationReport report = s.mt.validate();
  ASSERT_TRUE(report.ok()) << report.summary();
  for (TetId p : pieces) {
    EXPECT_EQ(s.mt.birth(p), s.collapse);
    EXPECT_EQ(s.mt.death(p), s.mt.drain());
    EXPECT_TRUE(s.mt.error_inherited(p));
    EXPECT_EQ(s.mt.error(p), whole_error);
    const auto c = s.mt.corners(p);
    EXPECT_LE(tet_error(c[0], c[1], c[2], c[3]), whole_error);  // its own is no larger
  }
  EXPECT_EQ(s.mt.fragment_error(s.collapse), before);
  // A copy keeps the error and where it came from.
  Mt copy = s.mt;
  const TetId c = copy.add_copy(s.mt, pieces[0], s.mt.tet(pieces[0]), s.collapse, s.mt.drain());
  EXPECT_TRUE(copy.error_inherited(c));
  EXPECT_EQ(copy.error(c), whole_error);
}

// A batch of pieces (add_pieces) is what the pieces one at a time
// (add_piece) make: the same tets, fragments, errors, masks, list order and
// slots (validate() and kill_tet read them). Both with a replacing fragment
// and without one (an MT still being built).
TEST(Mt, AddPiecesDoesWhatAddPieceDoesOneByOne) {
  const auto same = [](const Mt& a, const Mt& b) {
    ASSERT_EQ(a.num_tets(), b.num_tets());
    for (std::size_t i = 0; i < a.num_tets(); ++i) {
      const TetId t(i);
      EXPECT_EQ(a.tet(t), b.tet(t)) << i;
      EXPECT_EQ(a.birth(t), b.birth(t)) << i;
      EXPECT_EQ(a.death(t), b.death(t)) << i;
      EXPECT_EQ(a.error(t), b.error(t)) << i;
      EXPECT_EQ(a.error_inherited(t), b.error_inherited(t)) << i;
      EXPECT_EQ(a.boundary_mask(t), b.boundary_mask(t)) << i;
    }
    ASSERT_EQ(a.num_fragments(), b.num_fragments());
    for (std::size_t f = 0; f < a.num_fragments(); ++f) {
      EXPECT_TRUE(std::ranges::equal(a.created(FragId(f)), b.created(FragId(f)))) << f;
      EXPECT_TRUE(std::ranges::equal(a.replaced(FragId(f)), b.replaced(FragId(f)))) << f;
    }
    EXPECT_EQ(a.num_live_tets(), b.num_live_tets());
  };
  const auto pieces_of = [](const Tet& whole) {
    std::vector<Tet> out;
    for (int i = 0; i < 4; ++i) {
      Tet t = whole;
      t[static_cast<std::size_t>(i)] = VertId(4);  // the centroid
      out.push_back(t);
    }
    return out;
  };
  const std::vector<FaceMask> masks = {1, 2, 4, 8};
  {  // the big tet: created by the collapse, replaced by the drain
    StarMt one = make_star_mt(), all = make_star_mt();
    const std::vector<Tet> pieces = pieces_of(one.mt.tet(one.big));
    for (std::size_t i = 0; i < pieces.size(); ++i) one.mt.add_piece(pieces[i], one.big, masks[i]);
    EXPECT_EQ(all.mt.add_pieces(pieces, all.big, masks), TetId(one.mt.num_tets() - 4));
    same(one.mt, all.mt);
    one.mt.kill_tet(one.big);
    all.mt.kill_tet(all.big);
    same(one.mt, all.mt);
    const ValidationReport report = all.mt.validate();
    EXPECT_TRUE(report.ok()) << report.summary();
  }
  {  // a fine tet of an MT being built: no replacing fragment yet
    Mt one = Mt::from_fine_mesh(centroid_split()), all = one;
    const Tet whole = one.tet(TetId(2));
    const std::vector<Tet> pieces = {whole, whole};  // the content is not checked here
    for (std::size_t i = 0; i < pieces.size(); ++i) one.add_piece(pieces[i], TetId(2), masks[i]);
    all.add_pieces(pieces, TetId(2), std::span<const FaceMask>(masks).first(2));
    same(one, all);
    EXPECT_FALSE(all.death(TetId(all.num_tets() - 1)).valid());
  }
}

// validate() catches a "piece" that does not lie in the tet it claims to
// split: its inherited error is below its own.
TEST(Mt, ValidateRejectsAnInheritedErrorBelowTheTetsOwn) {
  StarMt s = make_star_mt();
  const TetId small(1);  // the fine tet without the big one's face (1, 2, 3): a smaller sphere
  const Tet big = s.mt.tet(s.big);
  s.mt.kill_tet(s.big);
  // The big tet again, in the collapse fragment, claiming a small fine tet as its whole.
  const TetId wrong = s.mt.add_piece(big, small, 0xF);
  s.mt.set_birth(wrong, s.collapse);
  s.mt.set_death(wrong, s.mt.drain());
  const ValidationReport report = s.mt.validate();
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.summary().find("inherited error below its own"), std::string::npos) << report.summary();
}

}  // namespace
}  // namespace mtcut::engine
