// `mtcut run --record` and scenarios that replay a trace.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/app/run_fixture.h"

namespace mtcut::test {
namespace {

class RunRecord : public RunFixture {
 protected:
  void expect_one_line_error(const CommandResult& r, const std::string& what) {
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
};

TEST_F(RunRecord, ReplayingTheRecordedTraceGivesTheSameStateHash) {
  const std::string scenario = source_path("config/scenarios/default.toml");
  const auto original = run_json("run " + quoted(scenario) + " --frames 40 --out " + quoted(path("a")) + " --record " +
                                 quoted(path("trace.csv")));
  const std::string trace = read_text(path("trace.csv"));
  EXPECT_EQ(std::count(trace.begin(), trace.end(), '\n'), 41);  // the header and one sample per frame

  const std::string replay = write("replay.toml", replay_of("trace.csv"));  // relative to the scenario
  const auto replayed = run_json("run " + quoted(replay) + " --frames 40 --out " + quoted(path("b")));
  ASSERT_FALSE(original.is_null());
  ASSERT_FALSE(replayed.is_null());
  EXPECT_EQ(replayed["state_hash"], original["state_hash"]);
  EXPECT_EQ(replayed["scalpel_trace"], path("trace.csv"));

  // Recording the replay gives the same trace again, byte for byte.
  run_json("run " + quoted(replay) + " --frames 40 --out " + quoted(path("c")) + " --record " +
           quoted(path("again.csv")));
  EXPECT_EQ(read_text(path("again.csv")), trace);
}

TEST_F(RunRecord, AMalformedTraceRowFailsWithFileLineAndExit1) {
  write("trace.csv",
        "time,base_x,base_y,base_z,tip_x,tip_y,tip_z,engaged\n"
        "0,0.04,-0.06,0.06,0.04,-0.06,-0.045,1\n"
        "0.5,0.04,0.0,0.06,0.04,zero,-0.045,1\n");
  const CommandResult r = run_mtcut("run " + quoted(write("replay.toml", replay_of("trace.csv"))) +
                                    " --frames 2 --out " + quoted(path("out")));
  expect_one_line_error(r, path("trace.csv") + ":3: tip_y must be a finite number, not 'zero'");
  EXPECT_FALSE(std::filesystem::exists(path("out")));
}

TEST_F(RunRecord, TraceKeyFaultsAreOneLineAndExit1) {
  const std::string run = " --frames 2 --out " + quoted(path("out"));
  expect_one_line_error(run_mtcut("run " + quoted(write("a.toml", replay_of("missing.csv"))) + run), "a.toml:");
  expect_one_line_error(run_mtcut("run " + quoted(write("a.toml", replay_of("missing.csv"))) + run),
                        "trace file '" + path("missing.csv") + "' does not exist");
  write("t.csv", "time,base_x,base_y,base_z,tip_x,tip_y,tip_z,engaged\n0,0,0,1,0,0,0,1\n");
  const std::string both =
      variant("[[scalpel.keyframes]]", "[scalpel]\ntrace = \"t.csv\"\n\n[[scalpel.keyframes]]");
  expect_one_line_error(run_mtcut("run " + quoted(write("b.toml", both)) + run), "give keyframes or a trace, not both");
  expect_one_line_error(run_mtcut("run " + quoted(write("c.toml", with_snapshots(-1))) + run),
                        "'output.snapshot_every' must be >= 0");
}

}  // namespace
}  // namespace mtcut::test
