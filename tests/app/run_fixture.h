#pragma once
// A fixture for the end-to-end tests of `mtcut run`: a temporary folder per
// test, and scenario files made from config/scenarios/default.toml.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/app/run_mtcut.h"
#include "tests/test_paths.h"

namespace mtcut::test {

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The fields of a CSV line (the run's outputs quote none).
inline std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
  return fields;
}

class RunFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("mtcut-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    base_ = read_text(source_path("config/scenarios/default.toml"));
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Runs `mtcut ARGS --json` and returns the summary, failing the test on a non-zero exit.
  nlohmann::json run_json(const std::string& args) {
    const CommandResult r = run_mtcut(args + " --json");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
  }
  // A path in the test's folder.
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name), std::ios::binary) << text;
    return path(name);
  }
  // The default scenario with `from` replaced by `to` (which must occur).
  std::string variant(const std::string& from, const std::string& to) const {
    const auto at = base_.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    std::string text = base_;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
  }
  // The default scenario with its keyframes replaced by `[scalpel] trace = "<trace>"`.
  std::string replay_of(const std::string& trace) const {
    const auto keys = base_.find("[[scalpel.keyframes]]");
    const auto output = base_.find("[output]");
    EXPECT_LT(keys, output);
    return base_.substr(0, keys) + "[scalpel]\ntrace = \"" + trace + "\"\n\n" + base_.substr(output);
  }
  // The default scenario, with a snapshot every `every` frames.
  std::string with_snapshots(int every) const {
    const std::string key = "snapshot_every = ";
    const auto at = base_.find(key);
    if (at == std::string::npos)
      return variant("[output]\n", "[output]\n" + key + std::to_string(every) + "\n");
    std::string text = base_;
    const auto value = at + key.size();
    text.replace(value, text.find_first_not_of("0123456789", value) - value, std::to_string(every));
    return text;
  }

  std::filesystem::path dir_;
  std::string base_;
};

}  // namespace mtcut::test
