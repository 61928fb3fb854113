#pragma once
// Physics at its fixed dt, decoupled from the display rate: wall-clock time
// accumulates and is spent in whole steps. When the simulation falls behind
// (a step costs more than dt of real time), at most `max_steps` run per
// displayed frame and the rest of the debt is dropped and counted, so the
// window keeps drawing and answering the mouse (the simulation then runs
// slower than real time, and the panel says so).

#include <cstdint>

namespace mtcut::app::view {

class StepClock {
 public:
  explicit StepClock(double dt, int max_steps = 2) : dt_(dt), max_steps_(max_steps) {}

  // Adds `elapsed` seconds of wall-clock time; returns how many steps to run now.
  int advance(double elapsed);
  // Counts steps that were due but not run (the caller ran out of time).
  void drop(int steps) { dropped_ += static_cast<std::uint64_t>(steps > 0 ? steps : 0); }
  // Forgets the accumulated time (after a pause or a reset).
  void clear() { accumulated_ = 0.0; }

  double dt() const { return dt_; }
  void set_dt(double dt) { dt_ = dt; }
  std::uint64_t dropped_steps() const { return dropped_; }
  std::uint64_t steps() const { return steps_; }

 private:
  double dt_;
  int max_steps_;
  double accumulated_ = 0.0;
  std::uint64_t dropped_ = 0;
  std::uint64_t steps_ = 0;
};

}  // namespace mtcut::app::view
