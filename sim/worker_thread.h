#pragma once
// One long-lived thread that runs the jobs given to it, in order.
//
// Why. The World builds spring models on the second core (model_build.h).
// It used to start a thread per build (std::async): a fresh thread gets a
// malloc arena with nothing free in it, so every build page-faulted its
// ~6 MB of arrays anew, and a 26k-tet build took twice as long as inline.
// One thread kept for all builds reuses the memory the models it made
// leave behind.
//
// Jobs run one at a time, in submission order; a job's result or exception
// comes through its future. The destructor runs the jobs already queued,
// then joins.

#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>

namespace mtcut::sim {

class WorkerThread {
 public:
  WorkerThread();
  ~WorkerThread();
  WorkerThread(const WorkerThread&) = delete;
  WorkerThread& operator=(const WorkerThread&) = delete;

  // Queues `job`; its future gives what it returns or rethrows what it throws.
  template <class Job>
  std::future<std::invoke_result_t<Job&>> submit(Job job) {
    using Result = std::invoke_result_t<Job&>;
    auto task = std::make_shared<std::packaged_task<Result()>>(std::move(job));
    std::future<Result> result = task->get_future();
    push([task] { (*task)(); });
    return result;
  }

  // The worker's thread, for tests.
  std::thread::id id() const { return thread_.get_id(); }

 private:
  void push(std::function<void()> job);
  void run();

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;  // queued, not started
  bool stopping_ = false;
  std::thread thread_;  // last: it starts once the members above exist
};

}  // namespace mtcut::sim
