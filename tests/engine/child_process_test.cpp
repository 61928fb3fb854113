#include "engine/child_process.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <condition_variable>
#include <csignal>
#include <cstdlib>
#include <mutex>
#include <thread>

namespace mtcut::engine {
namespace {

using namespace std::chrono_literals;

// A thread that waits, holding nothing, until the object is destroyed.
class IdleThread {
 public:
  IdleThread()
      : thread_([this] {
          std::unique_lock lock(mutex_);
          wake_.wait(lock, [this] { return done_; });
        }) {}
  ~IdleThread() {
    {
      std::lock_guard lock(mutex_);
      done_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }

 private:
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::thread thread_;
};

int write_pid_and_value(std::FILE* result) {
  const pid_t pid = ::getpid();
  const double value = 2.5;
  return put_values(result, &pid, 1) && put_values(result, &value, 1) ? 7 : 1;
}

TEST(ChildProcess, TheWorkRunsInAnotherProcessAndItsResultComesBack) {
  ASSERT_FALSE(process_runs_other_threads()) << "each test runs in a process of its own (ctest)";
  const ChildRun run = run_in_child(write_pid_and_value, {});
  ASSERT_EQ(run.outcome, ChildRun::Outcome::kExited);
  EXPECT_EQ(run.code, 7);
  std::size_t at = 0;
  pid_t pid = 0;
  double value = 0;
  ASSERT_TRUE(get_values(run.output, at, &pid, 1));
  ASSERT_TRUE(get_values(run.output, at, &value, 1));
  EXPECT_NE(pid, ::getpid());
  EXPECT_EQ(value, 2.5);
  EXPECT_FALSE(get_values(run.output, at, &value, 1)) << "nothing more was written";
}

// (An abort, not a fault: the sanitizers' builds catch faults themselves.)
TEST(ChildProcess, ACrashIsReportedWithItsSignal) {
  ASSERT_FALSE(process_runs_other_threads());
  const ChildRun run = run_in_child([](std::FILE*) -> int { std::abort(); }, {});
  ASSERT_EQ(run.outcome, ChildRun::Outcome::kCrashed);
  EXPECT_EQ(run.code, SIGABRT);
  EXPECT_EQ(signal_name(run.code), "Aborted");
}

TEST(ChildProcess, AChildPastItsDeadlineIsStopped) {
  ASSERT_FALSE(process_runs_other_threads());
  ChildOptions options;
  options.deadline = std::chrono::steady_clock::now() + 200ms;
  const ChildRun run = run_in_child(
      [](std::FILE*) {
        for (;;) ::pause();
        return 0;
      },
      options);
  EXPECT_EQ(run.outcome, ChildRun::Outcome::kTimedOut);
}

TEST(ChildProcess, WhatTheChildPrintsIsKeptApart) {
  ASSERT_FALSE(process_runs_other_threads());
  const ChildRun run = run_in_child(
      [](std::FILE*) {
        std::printf("chatter\n");
        return 0;
      },
      {});
  ASSERT_EQ(run.outcome, ChildRun::Outcome::kExited);
  EXPECT_EQ(run.chatter, "chatter\n");
}

TEST(ChildProcess, AProcessWithOtherThreadsRunsTheWorkItself) {
  IdleThread other;
  ASSERT_TRUE(process_runs_other_threads());
  const ChildRun run = run_in_child(write_pid_and_value, {});
  ASSERT_EQ(run.outcome, ChildRun::Outcome::kExited);
  EXPECT_EQ(run.code, 7);
  std::size_t at = 0;
  pid_t pid = 0;
  ASSERT_TRUE(get_values(run.output, at, &pid, 1));
  EXPECT_EQ(pid, ::getpid()) << "no fork while another thread may hold a lock";
}

TEST(ChildProcess, WorkThatThrowsExitsWithOne) {
  const auto throws = [](std::FILE*) -> int { throw std::runtime_error("no"); };
  EXPECT_EQ(run_in_child(throws, {}).code, 1);
  IdleThread other;
  EXPECT_EQ(run_in_child(throws, {}).code, 1);
}

}  // namespace
}  // namespace mtcut::engine
