// decompose_fragment on MTs made by hand, where each outcome is known:
// a fragment over two regions that share no vertex falls into two parts,
// each creating and replacing its own region's tets; one whose tets share
// vertices stays connected; a grouping that would leave a part creating
// nothing keeps the fragment whole.

#include "cut/mt/fragment_decomposition.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace mtcut::cut {
namespace {

using engine::Tet;
using engine::Vec3;
using engine::VertId;

Tet tet(int a, int b, int c, int d) { return Tet{VertId(a), VertId(b), VertId(c), VertId(d)}; }

// The finest mesh `fine` (positively oriented tets over `positions`), then
// one fragment f replacing the finest tets `replaced` and creating `created`,
// which the drain replaces; the other finest tets die in the drain.
struct HandMt {
  Mt mt;
  FragId f;
};

HandMt hand_mt(const std::vector<Vec3>& positions, const std::vector<Tet>& fine, const std::vector<int>& replaced,
               const std::vector<Tet>& created) {
  engine::TetMesh mesh;
  mesh.positions = positions;
  mesh.tets = fine;
  HandMt out{Mt::from_fine_mesh(mesh), FragId()};
  out.f = out.mt.add_fragment();
  const FragId drain = out.mt.add_fragment();
  out.mt.set_drain(drain);
  for (std::size_t t = 0; t < fine.size(); ++t)
    out.mt.set_death(TetId(static_cast<std::int32_t>(t)),
                     std::find(replaced.begin(), replaced.end(), static_cast<int>(t)) != replaced.end() ? out.f
                                                                                                        : drain);
  // A created tet is a copy of a finest one: its faces on the surface are that one's.
  for (const Tet& t : created) {
    const auto same = std::find(fine.begin(), fine.end(), t);
    if (same == fine.end()) ADD_FAILURE() << "a created tet that is no finest one";
    const engine::FaceMask mask =
        same == fine.end() ? 0 : out.mt.boundary_mask(TetId(static_cast<std::int32_t>(same - fine.begin())));
    out.mt.add_tet(t, out.f, drain, mask);
  }
  return out;
}

// Two unit corners far apart: vertices 0-3 and 4-7.
std::vector<Vec3> two_corners() {
  return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1),
          Vec3(5, 0, 0), Vec3(6, 0, 0), Vec3(5, 1, 0), Vec3(5, 0, 1)};
}

std::vector<TetId> sorted(std::span<const TetId> tets) {
  std::vector<TetId> out(tets.begin(), tets.end());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(FragmentDecomposition, RegionsThatShareNoVertexBecomeTwoParts) {
  // f replaces the two finest tets (0, 1) and creates a copy of each (2, 3).
  HandMt h = hand_mt(two_corners(), {tet(0, 1, 2, 3), tet(4, 5, 6, 7)}, {0, 1}, {tet(0, 1, 2, 3), tet(4, 5, 6, 7)});
  ASSERT_TRUE(h.mt.validate().ok()) << h.mt.validate().summary();
  const std::size_t fragments = h.mt.num_fragments();
  DecompositionScratch scratch;
  const Decomposition d = decompose_fragment(h.mt, h.f, scratch);
  ASSERT_EQ(d.outcome, DecomposeOutcome::kSplit);
  ASSERT_EQ(d.parts.size(), 2u);
  EXPECT_EQ(d.parts[0], h.f);
  EXPECT_EQ(h.mt.num_fragments(), fragments + 1);
  // Each part creates and replaces the tets of its own corner.
  for (const FragId part : d.parts) {
    ASSERT_EQ(h.mt.created(part).size(), 1u);
    ASSERT_EQ(h.mt.replaced(part).size(), 1u);
    EXPECT_EQ(h.mt.tet(h.mt.created(part)[0]), h.mt.tet(h.mt.replaced(part)[0]));
  }
  EXPECT_NE(h.mt.tet(h.mt.created(d.parts[0])[0]), h.mt.tet(h.mt.created(d.parts[1])[0]));
  const auto report = h.mt.validate();
  EXPECT_TRUE(report.ok()) << report.summary();
  // The same scratch serves again: a part (one corner) decomposes as connected.
  EXPECT_EQ(decompose_fragment(h.mt, d.parts[1], scratch).outcome, DecomposeOutcome::kConnected);
}

TEST(FragmentDecomposition, TetsThatShareAVertexStayOneFragment) {
  // Two tets sharing the face (1, 2, 3), replaced and created again.
  const std::vector<Vec3> positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 1)};
  const std::vector<Tet> fine = {tet(0, 1, 2, 3), tet(1, 4, 2, 3)};
  HandMt h = hand_mt(positions, fine, {0, 1}, fine);
  ASSERT_TRUE(h.mt.validate().ok()) << h.mt.validate().summary();
  const std::vector<TetId> created = sorted(h.mt.created(h.f)), replaced = sorted(h.mt.replaced(h.f));
  DecompositionScratch scratch;
  const Decomposition d = decompose_fragment(h.mt, h.f, scratch);
  EXPECT_EQ(d.outcome, DecomposeOutcome::kConnected);
  EXPECT_TRUE(d.parts.empty());
  EXPECT_EQ(sorted(h.mt.created(h.f)), created);
  EXPECT_EQ(sorted(h.mt.replaced(h.f)), replaced);
}

TEST(FragmentDecomposition, APartThatWouldCreateNothingKeepsTheFragmentWhole) {
  // f replaces both corners but creates only the first one's tet again: the
  // second corner's group would replace a tet and create none.
  HandMt h = hand_mt(two_corners(), {tet(0, 1, 2, 3), tet(4, 5, 6, 7)}, {0, 1}, {tet(0, 1, 2, 3)});
  const std::size_t fragments = h.mt.num_fragments();
  DecompositionScratch scratch;
  const Decomposition d = decompose_fragment(h.mt, h.f, scratch);
  EXPECT_EQ(d.outcome, DecomposeOutcome::kKeptWhole);
  EXPECT_EQ(h.mt.num_fragments(), fragments);
  EXPECT_EQ(h.mt.created(h.f).size(), 1u);
  EXPECT_EQ(h.mt.replaced(h.f).size(), 2u);
}

}  // namespace
}  // namespace mtcut::cut
