// End-to-end test of `mtcut bench table1` (builds the paper preset MT: some
// seconds): it runs, reports every key beside the paper's, and its figures
// relate sanely. No time bounds.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/app/run_mtcut.h"

namespace mtcut::test {
namespace {

TEST(BenchTable1, ReportsEveryRowBesideThePapers) {
  const auto md = std::filesystem::temp_directory_path() / ("mtcut-table1-" + std::to_string(::getpid()) + ".md");
  const CommandResult r = run_mtcut("bench table1 --runs 1 --json --markdown " + quoted(md.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto out = nlohmann::json::parse(r.out);
  EXPECT_GT(out["mt"]["tets"].get<int>(), 0);
  EXPECT_GT(out["mt"]["fragments"].get<int>(), 0);
  const auto& rows = out["rows"];
  ASSERT_EQ(rows.size(), 5u);
  for (const auto& row : rows) {
    for (const char* key : {"split_fragments", "split_tets", "new_tets_bielser17", "new_tets_lut", "split_ms",
                            "dag_update_ms", "total_ms"}) {
      EXPECT_TRUE(row.contains(key)) << key;
      EXPECT_TRUE(row["paper"].contains(key)) << key;
    }
    EXPECT_GT(row["split_tets"].get<int>(), 0);
    EXPECT_GT(row["split_fragments"].get<int>(), 0);
    EXPECT_GT(row["new_tets_bielser17"].get<int>(), row["new_tets_lut"].get<int>());
    EXPECT_GE(row["new_tets_lut"].get<int>(), row["split_tets"].get<int>());
  }
  // Partial cuts keep the object whole; the last, largest cut separates it.
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) EXPECT_EQ(rows[i]["pieces"].get<int>(), 1) << i;
  EXPECT_EQ(rows.back()["pieces"].get<int>(), 2);
  EXPECT_GT(rows.back()["split_tets"].get<int>(), rows.front()["split_tets"].get<int>());

  std::ifstream in(md);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::filesystem::remove(md);
  EXPECT_NE(text.find("| row |"), std::string::npos) << text;
  EXPECT_NE(text.find("Machine:"), std::string::npos) << text;
  // A header row, its rule and one line per row.
  EXPECT_EQ(std::count(text.begin(), text.end(), '|') % 10, 0) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '|') / 10, 7) << text;
}

}  // namespace
}  // namespace mtcut::test
