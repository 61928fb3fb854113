#include "app/material_file.h"

#include <gtest/gtest.h>

#include "engine/input_error.h"
#include "tests/temp_dir.h"

namespace mtcut::app {
namespace {

using test::input_error_of;

class MaterialFile : public ::testing::Test {
 protected:
  std::string write(const std::string& text) const { return dir_.write("m.toml", text); }
  test::TempDir dir_;
};

TEST_F(MaterialFile, EveryShippedPresetLoads) {
  for (const std::string name : {"liver", "kidney", "stiff_test"}) {
    const sim::MaterialDef m = load_material(name);
    EXPECT_GT(m.density, 0) << name;
    EXPECT_GT(m.youngs_modulus, 0) << name;
  }
  EXPECT_DOUBLE_EQ(load_material("liver").youngs_modulus, 3000.0);
  EXPECT_DOUBLE_EQ(load_material("stiff_test").youngs_modulus, 1e5);
}

TEST_F(MaterialFile, FaultsNameTheFileAndLine) {
  EXPECT_NE(input_error_of([&] { load_material(write("density = 1000\nyoungs_modulus = 5\nstiffnes = 3\n")); })
                .find("m.toml:3: unknown key 'stiffnes'"),
            std::string::npos);
  EXPECT_NE(input_error_of([&] { load_material(write("density = \"heavy\"\n")); }).find("m.toml:1: 'density' must be"),
            std::string::npos);
  EXPECT_NE(input_error_of([&] { load_material(write("\nyoungs_modulus = -3\n")); }).find("m.toml:2:"),
            std::string::npos);
  EXPECT_NE(input_error_of([&] { load_material(write("density = [1, \n")); }).find("m.toml:"), std::string::npos);
  EXPECT_NE(input_error_of([] { load_material("spleen"); }).find("no such preset"), std::string::npos);
}

}  // namespace
}  // namespace mtcut::app
