// add_advice: the lower layers state an input's fault and hint at the
// setting to change; the advice names it as this command line's option and
// as a scenario's [mesh] key.

#include "app/mesh_input_options.h"

#include <gtest/gtest.h>

#include <string>

namespace mtcut::app {
namespace {

using Kind = engine::InputHint::Kind;

TEST(MeshInputOptions, ALineWithoutAHintIsLeftAsItIs) {
  EXPECT_EQ(add_advice("box.obj: repaired (holes filled)", {}), "box.obj: repaired (holes filled)");
}

TEST(MeshInputOptions, AUnitsHintNamesTheUnitAsAnOptionAndAScenarioKey) {
  EXPECT_EQ(add_advice("box.obj: ..., which is not an organ's size; they may be millimetres", {Kind::kUnits, "mm"}),
            "box.obj: ..., which is not an organ's size; they may be millimetres; if so, say --units mm, or [mesh] "
            "units = \"mm\" in a scenario");
  // No unit known: both ways of giving one.
  EXPECT_EQ(add_advice("box.obj: ..., which is not an organ's size", {Kind::kUnits, {}}),
            "box.obj: ..., which is not an organ's size; give the file's unit with --units or --scale, or [mesh] "
            "units or scale in a scenario");
}

TEST(MeshInputOptions, AMaxVolumeHintSaysToRaiseIt) {
  EXPECT_EQ(add_advice("box.obj: TetGen ran out of memory meshing to tets of at most 1e-09 m^3", {Kind::kMaxVolume, {}}),
            "box.obj: TetGen ran out of memory meshing to tets of at most 1e-09 m^3; raise --max-volume, or [mesh] "
            "max_volume in a scenario");
}

}  // namespace
}  // namespace mtcut::app
