#include "app/cli_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "tests/app/run_mtcut.h"

namespace mtcut::test {
namespace {

// What the check of `input` says (empty: the value passes).
std::string checked(const CLI::Validator& check, std::string input) { return check(input); }

TEST(CliChecks, APositiveNumberIsGreaterThanZero) {
  const CLI::Validator& check = app::positive_number();
  for (const std::string good : {"1", "0.5", "1e-9", "8000"}) EXPECT_EQ(checked(check, good), "") << good;
  EXPECT_EQ(checked(check, "0"), "'0' must be greater than 0");
  EXPECT_EQ(checked(check, "-2.5"), "'-2.5' must be greater than 0");
  for (const std::string bad : {"abc", "inf", "nan", ""})
    EXPECT_EQ(checked(check, bad), "'" + bad + "' is not a number") << bad;
}

TEST(CliChecks, ANonNegativeNumberIsZeroOrMore) {
  const CLI::Validator& check = app::non_negative_number();
  for (const std::string good : {"0", "0.25", "3"}) EXPECT_EQ(checked(check, good), "") << good;
  EXPECT_EQ(checked(check, "-1"), "'-1' must be 0 or more");
  EXPECT_EQ(checked(check, "x1"), "'x1' is not a number");
}

// A command's bad number is a usage error (exit 2) that names the option
// and says what it must be, in a line a user reads.
TEST(CliChecks, ACommandsBadNumberSaysWhatItMustBe) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"bench sim --tets 0", "--tets: '0' must be greater than 0"},
      {"mesh builtin:box --max-volume -1", "--max-volume: '-1' must be 0 or more"},
      {"mt builtin:box --tets 3000 --no-preserve-boundary --max-surface-deviation abc",
       "--max-surface-deviation: 'abc' is not a number"}};
  for (const auto& [args, line] : cases) {
    const CommandResult r = run_mtcut(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_NE(r.err.find(line + "\n"), std::string::npos) << args << "\n" << r.err;
    const std::size_t longest = [&] {
      std::size_t most = 0, start = 0;
      for (std::size_t end = r.err.find('\n'); end != std::string::npos; start = end + 1, end = r.err.find('\n', start))
        most = std::max(most, end - start);
      return most;
    }();
    EXPECT_LT(longest, 120u) << args << "\n" << r.err;
  }
}

}  // namespace
}  // namespace mtcut::test
