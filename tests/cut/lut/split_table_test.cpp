// The LUT: every configuration a tet can be in, both schemes, random
// geometry; DESIGN.md's table entries; counts per case.
#include "cut/lut/split_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "cut/lut/baked_lut.h"
#include "cut/lut/split_configs.h"
#include "cut/lut/split_lut.h"
#include "tests/cut/lut/recipe_checks.h"

namespace mtcut::cut {
namespace {

using test::all_cut_configs;
using test::check_recipe;
using test::random_realisation;

std::string describe(const TetConfig& c) {
  static const char* names[] = {"-", "+", "on", "off"};
  std::string s = "states";
  for (VertexState v : c.vertex) s += std::string(" ") + names[static_cast<int>(v)];
  s += " cut edges";
  for (int k = 0; k < 6; ++k)
    if (c.edge_active(k)) s += " " + std::to_string(engine::kTetEdges[k][0]) + std::to_string(engine::kTetEdges[k][1]);
  s += " ranks";
  for (int r : c.rank) s += " " + std::to_string(r);
  return s;
}

// Tets per split tet for each case, as DESIGN.md's table (and O, 1:17).
const std::map<CutCase, std::size_t> kLutCounts = {{CutCase::kA, 4}, {CutCase::kB, 6},  {CutCase::kC, 6},
                                                   {CutCase::kD, 8}, {CutCase::kE, 9},  {CutCase::kO, 18}};
const std::map<CutCase, std::size_t> kBielserCounts = {{CutCase::kA, 16}, {CutCase::kB, 20}, {CutCase::kC, 10},
                                                       {CutCase::kD, 14}, {CutCase::kE, 18}, {CutCase::kO, 16}};

void check_all(SplitScheme scheme, const std::map<CutCase, std::size_t>& counts) {
  std::mt19937_64 rng(20240611);
  std::size_t checked = 0;
  std::map<std::pair<CutCase, std::size_t>, int> bent_sizes;
  for (const TetConfig& c : all_cut_configs()) {
    SCOPED_TRACE(describe(c));
    SplitRecipe recipe;
    ASSERT_NO_THROW(recipe = make_recipe(c, scheme));
    ASSERT_EQ(recipe.kind, c.cut_case());
    if (recipe.kind != CutCase::kVertex && !c.bent) {
      EXPECT_EQ(recipe.tets.size(), counts.at(recipe.kind));
    }
    if (recipe.kind != CutCase::kVertex && c.bent) ++bent_sizes[{recipe.kind, recipe.tets.size()}];
    TraceOptions options;
    options.split_face_nodes = scheme == SplitScheme::kBielser17;
    const CutTrace tr = trace_cut(c, options);
    // Bent realisations (cut points anywhere on their edges and faces) are
    // what a snapped vertex makes; without a vertex on the cut every cut
    // point lies on the plane.
    const bool bends = c.bent;
    for (bool planar : {true, false}) {
      if (!planar && !bends) continue;
      {
        const auto check = check_recipe(c, recipe, random_realisation(c, tr, rng, planar));
        ASSERT_TRUE(check.ok()) << (planar ? "planar: " : "bent: ") << check.problems.front();
        // A cut through the whole tet separates it (touching at most at
        // unsplit vertices); a cut ending inside it does not.
        bool joined = false;
        for (const SectionPoint& p : tr.section) joined |= !p.active && !p.is_vertex;
        EXPECT_EQ(check.components, joined ? 1 : 2);
      }
    }
    ++checked;
  }
  EXPECT_GT(checked, 1000u);
  for (const auto& [kind_size, n] : bent_sizes)
    std::printf("[ report   ] %s %s bent: %zu tets in %d configurations\n", scheme_name(scheme), case_name(kind_size.first),
                kind_size.second, n);
}

TEST(SplitTable, EveryLutConfigurationTilesConformsAndSeparates) { check_all(SplitScheme::kLut, kLutCounts); }

TEST(SplitTable, EveryBielserConfigurationTilesConformsAndSeparates) {
  check_all(SplitScheme::kBielser17, kBielserCounts);
}

TEST(SplitTable, LutIsNeverLargerThanBielser) {
  // Except in case O, where the reference leaves part of the strip uncut
  // (its centre ends both cut fronts) and the LUT pays 2 tets to cut it all.
  for (const TetConfig& c : all_cut_configs(1)) {
    SCOPED_TRACE(describe(c));
    if (c.cut_case() == CutCase::kO) continue;
    EXPECT_LE(make_recipe(c, SplitScheme::kLut).tets.size(), make_recipe(c, SplitScheme::kBielser17).tets.size());
  }
}

TEST(SplitTable, CachesOneRecipePerConfiguration) {
  SplitTable table;
  TetConfig c;
  c.vertex = {VertexState::kNeg, VertexState::kPos, VertexState::kPos, VertexState::kPos};
  c.covered = 0b000111;
  const std::size_t before = table.generated();
  const SplitRecipe& a = table.recipe(c);
  const std::size_t after = table.generated();
  EXPECT_LE(after, before + 1);
  const SplitRecipe& b = table.recipe(c);
  EXPECT_EQ(&a, &b);
  EXPECT_EQ(table.generated(), after);
  // Tables of one scheme share the recipes.
  SplitTable other;
  EXPECT_EQ(&other.recipe(c), &a);
  EXPECT_EQ(a.tets.size(), 4u);
}

TEST(SplitTable, BakedLutHoldsWhatTheRuleMakesForEveryConfiguration) {
  // The table compiled into mtcut (baked when it was built) has one entry per
  // configuration, the rule's recipe exactly; the table serves it, faces and all.
  const BakedLut lut = baked_lut();
  SplitTable table;
  std::size_t configs = 0;
  for (const TetConfig& c : all_cut_configs()) {
    SCOPED_TRACE(describe(c));
    ++configs;
    const SplitRecipe made = make_recipe(c, SplitScheme::kLut);
    const auto it = std::lower_bound(lut.entries.begin(), lut.entries.end(), table_key(c),
                                     [](const BakedLutEntry& e, std::uint32_t k) { return e.key < k; });
    ASSERT_TRUE(it != lut.entries.end() && it->key == table_key(c)) << "not baked";
    EXPECT_EQ(static_cast<CutCase>(it->kind), made.kind);
    const auto baked = lut.tets.subspan(it->first, it->count);
    EXPECT_TRUE(std::equal(baked.begin(), baked.end(), made.tets.begin(), made.tets.end()));
    const auto centre = lut.centres.subspan(it->centre_first, it->centre_count);
    EXPECT_TRUE(std::equal(centre.begin(), centre.end(), made.centre_of.begin(), made.centre_of.end()));
    const SplitRecipe& served = table.recipe(c);
    EXPECT_EQ(served.kind, made.kind);
    EXPECT_EQ(served.tets, made.tets);
    EXPECT_EQ(served.centre_of, made.centre_of);
    ASSERT_EQ(served.faces.size(), made.faces.size());
    for (std::size_t t = 0; t < made.faces.size(); ++t) EXPECT_EQ(served.faces[t].mask_for, made.faces[t].mask_for);
  }
  EXPECT_EQ(lut.entries.size(), configs);
}

TEST(SplitTable, IdOrderChangesTheLutOnlyWhereAFaceHasAQuad) {
  // What lets the table key such configurations by the identity order.
  std::vector<std::array<std::uint8_t, 4>> ranks;
  std::array<std::uint8_t, 4> r = {0, 1, 2, 3};
  do ranks.push_back(r);
  while (std::next_permutation(r.begin(), r.end()));
  SplitTable table;
  std::size_t checked = 0;
  for (TetConfig c : all_cut_configs(1)) {
    if (order_matters(c)) continue;
    const SplitRecipe identity = make_recipe(c, SplitScheme::kLut);
    const SplitRecipe* served = &table.recipe(c);
    for (const auto& rank : ranks) {
      c.rank = rank;
      SCOPED_TRACE(describe(c));
      const SplitRecipe ordered = make_recipe(c, SplitScheme::kLut);
      EXPECT_EQ(ordered.tets, identity.tets);
      EXPECT_EQ(ordered.centre_of, identity.centre_of);
      EXPECT_EQ(&table.recipe(c), served);
    }
    ++checked;
  }
  EXPECT_GT(checked, 100u);
}

// The label index a split resolves corners by (index_labels) names each
// corner's own label, lists each label once, and is filled on every path a
// recipe takes into the table: the baked LUT and the generated 1:17.
TEST(SplitTable, LabelIndexNamesEveryCornerOnce) {
  for (SplitScheme scheme : {SplitScheme::kLut, SplitScheme::kBielser17}) {
    SplitTable table(scheme);
    std::size_t checked = 0;
    for (const TetConfig& c : all_cut_configs(1)) {
      SCOPED_TRACE(describe(c));
      const SplitRecipe& recipe = table.recipe(c);
      ASSERT_EQ(recipe.corner_slots.size(), recipe.tets.size());
      std::vector<Label> sorted = recipe.labels;
      std::sort(sorted.begin(), sorted.end());
      EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "a label listed twice";
      std::vector<std::uint8_t> used(recipe.labels.size(), 0);
      for (std::size_t j = 0; j < recipe.tets.size(); ++j)
        for (int c4 = 0; c4 < 4; ++c4) {
          const std::size_t slot = recipe.corner_slots[j][c4];
          ASSERT_LT(slot, recipe.labels.size());
          EXPECT_EQ(recipe.labels[slot], recipe.tets[j][c4]);
          used[slot] = 1;
        }
      EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0) << "a label no corner uses";
      ++checked;
    }
    EXPECT_GT(checked, 100u);
  }
}

TEST(SplitTable, SchemeNamesRoundTrip) {
  for (SplitScheme s : {SplitScheme::kLut, SplitScheme::kBielser17}) EXPECT_EQ(parse_scheme(scheme_name(s)), s);
  EXPECT_FALSE(parse_scheme("1:17").has_value());
}

// DESIGN.md's table, in its encoding: 4+2k / 5+2k are edge k's copies on the
// side of its lower / higher endpoint, 16+i the point on the face opposite i.
struct DesignEntry {
  CutCase kind;
  std::array<VertexState, 4> states;
  std::uint8_t covered;
  std::vector<std::array<int, 4>> tets;
};

const std::vector<DesignEntry>& design_table() {
  using V = VertexState;
  static const std::vector<DesignEntry> table = {
      {CutCase::kA, {V::kNeg, V::kPos, V::kPos, V::kPos}, 0b000111,
       {{0, 4, 6, 8}, {5, 1, 7, 9}, {1, 3, 7, 9}, {1, 3, 2, 7}}},
      {CutCase::kB, {V::kNeg, V::kNeg, V::kPos, V::kPos}, 0b011110,
       {{0, 1, 6, 8}, {1, 6, 8, 10}, {1, 10, 8, 12}, {3, 9, 11, 13}, {2, 9, 7, 11}, {2, 3, 9, 11}}},
      {CutCase::kC, {V::kNeg, V::kPos, V::kPos, V::kPos}, 0b000001,
       {{0, 18, 4, 19}, {1, 5, 18, 19}, {0, 2, 3, 18}, {1, 3, 2, 18}, {0, 2, 18, 19}, {1, 18, 2, 19}}},
      {CutCase::kD, {V::kNeg, V::kPos, V::kPos, V::kPos}, 0b000011,
       {{0, 4, 6, 18}, {0, 6, 17, 18}, {0, 17, 3, 18}, {2, 3, 17, 18}, {1, 3, 2, 18}, {1, 2, 5, 18}, {2, 7, 5, 18},
        {2, 17, 7, 18}}},
      {CutCase::kE, {V::kNeg, V::kNeg, V::kPos, V::kPos}, 0b010110,
       {{0, 6, 8, 19}, {0, 8, 1, 19}, {1, 8, 16, 19}, {1, 8, 12, 16}, {1, 16, 2, 19}, {2, 9, 7, 19}, {2, 16, 9, 19},
        {2, 3, 9, 16}, {3, 13, 9, 16}}},
  };
  return table;
}

SplitRecipe from_design(const DesignEntry& e, const TetConfig& c) {
  SplitRecipe r;
  r.kind = e.kind;
  for (const auto& t : e.tets) {
    std::array<Label, 4> q;
    for (int j = 0; j < 4; ++j) {
      const int code = t[j];
      if (code < 4) {
        q[j] = make_label(LabelKind::kVertex, code);
      } else if (code < 16) {
        const int k = (code - 4) / 2;
        const int end = engine::kTetEdges[k][(code - 4) % 2];
        q[j] = make_label(LabelKind::kEdge, k, side_of(c.vertex[end]));
      } else {
        q[j] = make_label(LabelKind::kFace, code - 16);
      }
    }
    r.tets.push_back(q);
  }
  return r;
}

TEST(SplitTable, DesignTableEntriesPassTheSameChecks) {
  // Both the DESIGN.md entries and ours are checked by check_recipe; this
  // also shows the checker accepts a known-good table.
  std::mt19937_64 rng(7);
  for (const DesignEntry& e : design_table()) {
    TetConfig c;
    c.vertex = e.states;
    c.covered = e.covered;
    SCOPED_TRACE(case_name(e.kind));
    ASSERT_EQ(c.cut_case(), e.kind);
    const SplitRecipe design = from_design(e, c);
    const CutTrace tr = trace_cut(c);
    for (int trial = 0; trial < 20; ++trial) {
      const auto pos = random_realisation(c, tr, rng, true);
      const auto check = check_recipe(c, design, pos);
      EXPECT_TRUE(check.ok()) << check.problems.front();
    }
    // Our split of the same configuration has DESIGN.md's size.
    EXPECT_EQ(make_recipe(c, SplitScheme::kLut).tets.size(), e.tets.size());
  }
}

TEST(SplitTable, CheckerRejectsBrokenRecipes) {
  // A test that cannot fail is a defect: break a good recipe in the ways the
  // traps describe and expect the checker to notice.
  std::mt19937_64 rng(3);
  const DesignEntry& a = design_table()[0];
  TetConfig c;
  c.vertex = a.states;
  c.covered = a.covered;
  const CutTrace tr = trace_cut(c);
  const auto pos = random_realisation(c, tr, rng, true);
  SplitRecipe good = make_recipe(c, SplitScheme::kLut);
  ASSERT_TRUE(check_recipe(c, good, pos).ok());

  SplitRecipe flipped = good;  // orientation not fixed
  std::swap(flipped.tets[0][0], flipped.tets[0][1]);
  EXPECT_FALSE(check_recipe(c, flipped, pos).ok());

  SplitRecipe missing = good;  // a hole
  missing.tets.pop_back();
  EXPECT_FALSE(check_recipe(c, missing, pos).ok());

  SplitRecipe glued = good;  // one side uses the other side's copy: not separated
  for (auto& t : glued.tets)
    for (Label& l : t)
      if (label_kind(l) == LabelKind::kEdge) l = with_side(l, LabelSide::kPos);
  const auto check = check_recipe(c, glued, pos);
  EXPECT_EQ(check.components, 1);

  SplitRecipe uncut;  // the whole tet: keeps its cut edges
  uncut.tets.push_back({make_label(LabelKind::kVertex, 0), make_label(LabelKind::kVertex, 1),
                        make_label(LabelKind::kVertex, 2), make_label(LabelKind::kVertex, 3)});
  EXPECT_FALSE(check_recipe(c, uncut, pos).ok());
}

TEST(SplitTable, EveryCaseUnderAll24PermutationsHasItsSize) {
  // The canonical entries relabelled by each vertex permutation: the split
  // keeps its size and passes the checks (odd permutations included).
  std::mt19937_64 rng(11);
  for (const DesignEntry& e : design_table()) {
    std::array<int, 4> perm = {0, 1, 2, 3};
    do {
      TetConfig c;
      for (int i = 0; i < 4; ++i) c.vertex[perm[i]] = e.states[i];
      for (int k = 0; k < 6; ++k)
        if (e.covered >> k & 1)
          c.covered |= static_cast<std::uint8_t>(
              1u << edge_between(perm[engine::kTetEdges[k][0]], perm[engine::kTetEdges[k][1]]));
      for (int i = 0; i < 4; ++i) c.rank[i] = static_cast<std::uint8_t>(perm[i]);
      SCOPED_TRACE(describe(c));
      const SplitRecipe r = make_recipe(c, SplitScheme::kLut);
      EXPECT_EQ(r.kind, e.kind);
      EXPECT_EQ(r.tets.size(), e.tets.size());
      const auto check = check_recipe(c, r, random_realisation(c, trace_cut(c), rng, true));
      EXPECT_TRUE(check.ok()) << check.problems.front();
    } while (std::next_permutation(perm.begin(), perm.end()));
  }
}

}  // namespace
}  // namespace mtcut::cut
