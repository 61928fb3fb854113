// The spring builds' worker thread: order, thread, results, exceptions, shutdown.
#include "sim/worker_thread.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <vector>

namespace mtcut::sim {
namespace {

TEST(WorkerThread, RunsJobsInOrderOnItsOwnThread) {
  WorkerThread worker;
  std::vector<int> order;  // written by the worker only, one job at a time
  std::vector<std::future<std::thread::id>> ran_on;
  for (int k = 0; k < 50; ++k)
    ran_on.push_back(worker.submit([&order, k] {
      order.push_back(k);
      return std::this_thread::get_id();
    }));
  for (auto& id : ran_on) {
    const std::thread::id ran = id.get();
    EXPECT_EQ(ran, worker.id());
    EXPECT_NE(ran, std::this_thread::get_id());
  }
  ASSERT_EQ(order.size(), 50u);
  for (int k = 0; k < 50; ++k) EXPECT_EQ(order[static_cast<std::size_t>(k)], k);
}

TEST(WorkerThread, GivesResultsAndRethrowsWhatAJobThrows) {
  WorkerThread worker;
  auto value = worker.submit([] { return std::vector<double>(1000, 2.5); });
  auto failure = worker.submit([]() -> int { throw std::runtime_error("bad mesh"); });
  auto after = worker.submit([] { return 7; });
  EXPECT_EQ(value.get(), std::vector<double>(1000, 2.5));
  EXPECT_THROW(failure.get(), std::runtime_error);
  EXPECT_EQ(after.get(), 7) << "a job that threw stops nothing after it";
}

TEST(WorkerThread, RunsTheQueuedJobsBeforeItJoins) {
  std::atomic<int> done{0};
  {
    WorkerThread worker;
    for (int k = 0; k < 20; ++k)
      (void)worker.submit([&done] {
        std::this_thread::sleep_for(std::chrono::microseconds(200));
        ++done;
      });
  }  // nobody waited on a future
  EXPECT_EQ(done.load(), 20);
}

}  // namespace
}  // namespace mtcut::sim
