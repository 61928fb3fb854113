#pragma once
// Ctrl-C during `mtcut run`: the first SIGINT asks the run to stop after the
// frame in progress (so the outputs hold every frame done, complete); a
// second one, should writing them hang, ends the process as usual.

namespace mtcut::app {

// While alive, SIGINT sets a flag instead of ending the process. One at a time.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // A SIGINT arrived since the guard was made.
  bool requested() const;
};

// The exit code of a run stopped by SIGINT (128 + SIGINT, as shells report it).
inline constexpr int kInterruptedExitCode = 130;

}  // namespace mtcut::app
