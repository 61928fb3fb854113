#include "app/material_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "engine/input_error.h"

namespace mtcut::app {
namespace {
namespace fs = std::filesystem;

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const engine::InputError& e) {
    return e.what();
  }
  return "no error";
}

class MaterialFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mtcut-material-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& text) const {
    const std::string path = (dir_ / "m.toml").string();
    std::ofstream(path) << text;
    return path;
  }
  fs::path dir_;
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
  EXPECT_NE(message_of([&] { load_material(write("density = 1000\nyoungs_modulus = 5\nstiffnes = 3\n")); })
                .find("m.toml:3: unknown key 'stiffnes'"),
            std::string::npos);
  EXPECT_NE(message_of([&] { load_material(write("density = \"heavy\"\n")); }).find("m.toml:1: 'density' must be"),
            std::string::npos);
  EXPECT_NE(message_of([&] { load_material(write("\nyoungs_modulus = -3\n")); }).find("m.toml:2:"),
            std::string::npos);
  EXPECT_NE(message_of([&] { load_material(write("density = [1, \n")); }).find("m.toml:"), std::string::npos);
  EXPECT_NE(message_of([] { load_material("spleen"); }).find("no such preset"), std::string::npos);
}

}  // namespace
}  // namespace mtcut::app
