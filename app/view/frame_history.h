#pragma once
// The last few hundred values of a per-frame figure, oldest first, for the
// panel's live plots.

#include <cstddef>
#include <vector>

namespace mtcut::app::view {

class FrameHistory {
 public:
  explicit FrameHistory(std::size_t capacity = 240) : values_(capacity, 0.0f) {}

  void push(double value) {
    values_[next_] = static_cast<float>(value);
    next_ = (next_ + 1) % values_.size();
    if (size_ < values_.size()) ++size_;
  }
  // The ring as stored and the index of its oldest value (ImGui::PlotLines' offset).
  const float* data() const { return values_.data(); }
  int capacity() const { return static_cast<int>(values_.size()); }
  int offset() const { return static_cast<int>(size_ < values_.size() ? 0 : next_); }
  std::size_t size() const { return size_; }
  // The most recent value (0 when empty).
  float last() const { return size_ == 0 ? 0.0f : values_[(next_ + values_.size() - 1) % values_.size()]; }
  float max() const {
    float m = 0.0f;
    for (std::size_t i = 0; i < size_; ++i) m = values_[i] > m ? values_[i] : m;
    return m;
  }
  void clear() { size_ = next_ = 0; }

 private:
  std::vector<float> values_;
  std::size_t next_ = 0;
  std::size_t size_ = 0;
};

}  // namespace mtcut::app::view
