#include "cut/mt/cut_guard.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "tests/cut/mt/mt_cut_test_util.h"

namespace mtcut::test {
namespace {

// The fragments a cut touched (not root or drain, none it decomposed) that
// validate_fragment finds broken.
std::vector<FragId> broken_fragments(const Mt& mt, const cut::MtChangeReport& report) {
  const std::vector<FragId> decomposed = cut::decomposed_fragments(report);
  std::vector<FragId> touched;
  for (const cut::TetReplacement& r : report.replaced)
    for (FragId f : {r.birth, r.death})
      if (f.valid() && f != mt.root() && f != mt.drain() &&
          !std::binary_search(decomposed.begin(), decomposed.end(), f))
        touched.push_back(f);
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  std::vector<FragId> out;
  for (FragId f : touched)
    if (!engine::validate_fragment(mt, f).ok()) out.push_back(f);
  return out;
}

// A planar cut keeps every fragment in balance; a piece swapped for a tet
// that does not fill its place puts exactly the fragments that hold it out
// of balance, the ones validate_fragment finds broken, and check_cut
// refuses the cut.
TEST(CutGuard, AFragmentIsOutOfBalanceExactlyWhereItsTessellationsDiffer) {
  std::mt19937_64 rng(11);
  std::size_t tampered = 0;
  for (const std::string name : {"ellipsoid", "liver"}) {
    const Mt& original = cut_test_mt(name);
    const engine::Aabb box = mt_box(original);
    for (int i = 0; i < 8; ++i) {
      const std::string where = name + " cut " + std::to_string(i);
      Mt mt = original;
      engine::TetBvh bvh(mt);
      const std::size_t first_vertex = mt.num_vertices();
      cut::MtChangeReport report = cut::cut_mt(mt, bvh, random_polygon(box, rng, i % 2 == 0));
      ASSERT_GT(report.counts.split_tets, 0u) << where;
      EXPECT_TRUE(cut::fragments_out_of_balance(mt, report).empty()) << where;
      EXPECT_TRUE(broken_fragments(mt, report).empty()) << where;
      EXPECT_TRUE(cut::check_cut(mt, bvh, report, first_vertex, first_vertex, nullptr, cut::CutSelect::kAll).ok()) << where;

      // The first split of a tet in a fragment that is neither root, drain
      // nor decomposed: its first piece becomes the whole tet again, which
      // overlaps the other pieces.
      const std::vector<FragId> decomposed = cut::decomposed_fragments(report);
      const auto inner = [&](FragId f) {
        return f.valid() && f != mt.root() && f != mt.drain() &&
               !std::binary_search(decomposed.begin(), decomposed.end(), f);
      };
      const auto r = std::find_if(report.replaced.begin(), report.replaced.end(), [&](const cut::TetReplacement& x) {
        return x.count > 1 && (inner(x.birth) || inner(x.death)) && mt.alive(report.made_tets[x.first]);
      });
      if (r == report.replaced.end()) continue;
      const TetId piece = report.made_tets[r->first];
      const engine::Tet whole = mt.tet(r->old);  // (add_tet may move the MT's storage)
      mt.kill_tet(piece);
      report.made_tets[r->first] = mt.add_tet(whole, r->birth, r->death, mt.boundary_mask(r->old));
      std::vector<FragId> expected;
      for (FragId f : {r->birth, r->death})
        if (inner(f)) expected.push_back(f);
      std::sort(expected.begin(), expected.end());
      EXPECT_EQ(cut::fragments_out_of_balance(mt, report), expected) << where;
      EXPECT_EQ(broken_fragments(mt, report), expected) << where;
      EXPECT_FALSE(cut::check_cut(mt, bvh, report, first_vertex, first_vertex, nullptr, cut::CutSelect::kAll).ok()) << where;
      ++tampered;
    }
  }
  EXPECT_GE(tampered, 6u);  // (a cut through the object decomposes most fragments it crosses)
}

}  // namespace
}  // namespace mtcut::test
