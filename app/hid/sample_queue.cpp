#include "app/hid/sample_queue.h"

namespace mtcut::app::hid {

void SampleQueue::push(const Sample& sample) {
  std::lock_guard lock(mutex_);
  if (samples_.size() >= capacity_) {
    samples_.pop_front();
    ++dropped_;
  }
  samples_.push_back(sample);
}

std::vector<Sample> SampleQueue::take_until(std::int64_t time_us) {
  std::lock_guard lock(mutex_);
  std::vector<Sample> out;
  while (!samples_.empty() && samples_.front().time_us <= time_us) {
    out.push_back(samples_.front());
    samples_.pop_front();
  }
  return out;
}

std::vector<Sample> SampleQueue::take_all() {
  std::lock_guard lock(mutex_);
  std::vector<Sample> out(samples_.begin(), samples_.end());
  samples_.clear();
  return out;
}

std::size_t SampleQueue::size() const {
  std::lock_guard lock(mutex_);
  return samples_.size();
}

long SampleQueue::dropped() const {
  std::lock_guard lock(mutex_);
  return dropped_;
}

}  // namespace mtcut::app::hid
