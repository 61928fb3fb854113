#include "engine/mt/mt_presets.h"

#include <gtest/gtest.h>

#include "engine/mt/mt_stats.h"

namespace mtcut::engine {
namespace {

TEST(MtPresets, PaperPresetHasThePapersSize) {
  const auto preset = find_mt_preset("paper");
  ASSERT_TRUE(preset.has_value());
  EXPECT_FALSE(find_mt_preset("nonsense").has_value());
  const Mt mt = build_mt(load_mesh(preset->mesh_spec, preset->mesh).mesh, preset->build);
  const MtStats stats = compute_mt_stats(mt);
  // The paper: 2,896 vertices, 37,062 tets, 1,542 fragments.
  EXPECT_NEAR(static_cast<double>(stats.vertices), 2896.0, 0.10 * 2896.0);
  EXPECT_NEAR(static_cast<double>(stats.tets_total), 37062.0, 0.10 * 37062.0);
  EXPECT_NEAR(static_cast<double>(stats.fragments), 1542.0, 0.10 * 1542.0);
  EXPECT_FALSE(mt.boundary_preserved());
  // (Its validity: MtBuilder.GroupsNeighbouringCollapsesIntoOneFragment
  // checks the same options on a smaller mesh.)
}

}  // namespace
}  // namespace mtcut::engine
