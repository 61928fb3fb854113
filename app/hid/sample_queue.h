#pragma once
// The hand-over from the input thread to the frame loop: the thread pushes
// every decoded sample; the frame loop takes all samples up to its frame time,
// in order, so a fast stroke between two frames arrives as a polyline of
// poses rather than one jump. Bounded: when nobody drains it, the oldest
// samples are dropped and counted.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <mutex>
#include <vector>

#include "app/hid/sample.h"

namespace mtcut::app::hid {

class SampleQueue {
 public:
  explicit SampleQueue(std::size_t capacity = 65536) : capacity_(capacity) {}

  // Samples must be pushed in time order.
  void push(const Sample& sample);
  // Removes and returns the samples with time_us <= time_us, oldest first.
  std::vector<Sample> take_until(std::int64_t time_us);
  std::vector<Sample> take_all();
  std::size_t size() const;
  // Samples dropped because the queue was full.
  long dropped() const;

 private:
  mutable std::mutex mutex_;
  std::deque<Sample> samples_;
  std::size_t capacity_;
  long dropped_ = 0;
};

}  // namespace mtcut::app::hid
