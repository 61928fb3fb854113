#pragma once
// Work that may crash or run away, done in a child process: the library
// code behind it (TetGen, CGAL's experimental repairs) aborts, faults or
// loops on some inputs, which must end as one line, not a signal or a hang.
// The child writes its result to a temporary file the parent reads back.

#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>

namespace mtcut::engine {

struct ChildRun {
  enum class Outcome { kExited, kCrashed, kTimedOut };
  Outcome outcome = Outcome::kExited;
  int code = 0;         // the exit code (kExited) or the signal (kCrashed)
  std::string output;   // what the child wrote to its result file
  std::string chatter;  // what it printed on stdout and stderr (when quiet)
};

struct ChildOptions {
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  bool quiet = true;         // the child's stdout and stderr go to ChildRun::chatter ...
  bool keep_chatter = true;  // ... or, when false, nowhere (a reader that loops printing)
  // Called about once a second while the child runs, with the seconds since `start`.
  std::function<void(double seconds)> progress;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
};

// Runs work(result) in a forked child, whose return value is its exit code,
// and waits for it, killing it at the deadline. Throws InputError when no
// child can be started.
//
// A process that runs other threads is not forked: the child of such a
// process may only call async-signal-safe functions (a lock another thread
// held at the fork, in the allocator for instance, stays held in the child
// for ever). There the work runs in the calling thread, without the
// deadline, the crash isolation or the quiet (ChildRun::chatter is empty). The commands load their meshes
// before they start threads, so they keep all three.
ChildRun run_in_child(const std::function<int(std::FILE* result)>& work, const ChildOptions& options);

// Whether a fork now would copy a process that runs more than this thread.
bool process_runs_other_threads();

// "Aborted", "Segmentation fault", ...
std::string signal_name(int signal);

// Reads and writes of plain values in a child's result.
template <typename T>
bool put_values(std::FILE* f, const T* data, std::size_t n) {
  return n == 0 || std::fwrite(data, sizeof(T), n, f) == n;
}
// Reads n values from text at `at`, moving it on; false when too few are left.
template <typename T>
bool get_values(const std::string& text, std::size_t& at, T* data, std::size_t n) {
  if (text.size() - at < n * sizeof(T) || at > text.size()) return false;
  if (n > 0) std::memcpy(static_cast<void*>(data), text.data() + at, n * sizeof(T));
  at += n * sizeof(T);
  return true;
}

}  // namespace mtcut::engine
