// Ctrl-C during `mtcut run`: SIGINT sent to a running child stops it after
// the current frame, with every output valid for the frames done, exit 130.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fcntl.h>
#include <nlohmann/json.hpp>
#include <thread>

#include "tests/app/run_fixture.h"

namespace mtcut::test {
namespace {
namespace fs = std::filesystem;

// Starts mtcut with `args`, stdout and stderr to files; returns its pid.
pid_t spawn_mtcut(const std::vector<std::string>& args, const std::string& out, const std::string& err) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int out_fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err_fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out_fd, STDOUT_FILENO);
    ::dup2(err_fd, STDERR_FILENO);
    std::vector<char*> argv;
    const std::string binary = mtcut_binary();
    argv.push_back(const_cast<char*>(binary.c_str()));
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(binary.c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

class RunInterrupt : public RunFixture {};

TEST_F(RunInterrupt, SigintStopsAfterTheCurrentFrameAndLeavesValidFiles) {
  const std::string out = path("out");
  const std::string scenario = write("long.toml", with_snapshots(1));
  const pid_t pid = spawn_mtcut({"run", scenario, "--frames", "1000000", "--out", out, "--json", "--record",
                                 path("trace.csv")},
                                path("stdout"), path("stderr"));
  ASSERT_GT(pid, 0);
  // Wait until a few frames are done (snapshot 3 exists), or the child ended.
  int status = 0;
  bool exited = false;
  while (!fs::exists(out + "/snapshot_000003.vtu")) {
    if (::waitpid(pid, &status, WNOHANG) == pid) {
      exited = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_FALSE(exited) << "mtcut ended early: " << read_text(path("stderr"));
  ASSERT_EQ(::kill(pid, SIGINT), 0);
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 130) << read_text(path("stderr"));

  const auto summary = nlohmann::json::parse(read_text(out + "/summary.json"));
  EXPECT_EQ(nlohmann::json::parse(read_text(path("stdout"))), summary);
  const int frames = summary["frames"].get<int>();
  EXPECT_GE(frames, 3);
  EXPECT_LT(frames, 1000000);
  EXPECT_EQ(summary["interrupted"], true);
  EXPECT_EQ(summary["frames_requested"], 1000000);
  EXPECT_EQ(summary["valid"], true);

  const std::string metrics = read_text(out + "/metrics.csv");
  EXPECT_EQ(std::count(metrics.begin(), metrics.end(), '\n'), frames + 1);
  const std::string trace = read_text(path("trace.csv"));
  EXPECT_EQ(std::count(trace.begin(), trace.end(), '\n'), frames + 1);
  // A snapshot per frame, 0 to the last, all listed, none half-written.
  const std::string pvd = read_text(out + "/snapshots.pvd");
  EXPECT_TRUE(pvd.ends_with("</VTKFile>\n"));
  EXPECT_EQ(std::count(pvd.begin(), pvd.end(), '\n'), 5 + frames + 1);
  char last[40];
  std::snprintf(last, sizeof last, "snapshot_%06d.vtu", frames);
  EXPECT_NE(pvd.find(last), std::string::npos) << pvd;
  EXPECT_TRUE(fs::exists(out + "/" + last));
  EXPECT_TRUE(fs::exists(out + "/surface.obj"));
  for (const auto& entry : fs::directory_iterator(out))
    EXPECT_FALSE(entry.path().filename().string().starts_with(".tmp-")) << entry.path();
}

}  // namespace
}  // namespace mtcut::test
