#include "app/hid/keyframes.h"

namespace mtcut::app::hid {

std::vector<sim::ScalpelKeyframe> to_keyframes(std::span<const Sample> samples) {
  std::vector<sim::ScalpelKeyframe> keys;
  if (samples.empty()) return keys;
  const std::int64_t start = samples.front().time_us;
  std::int64_t last = start - 1;
  for (const Sample& s : samples) {
    const sim::ScalpelKeyframe key{static_cast<double>(s.time_us - start) * 1e-6, s.pose};
    if (s.time_us == last) keys.back() = key;
    else keys.push_back(key);
    last = s.time_us;
  }
  return keys;
}

}  // namespace mtcut::app::hid
