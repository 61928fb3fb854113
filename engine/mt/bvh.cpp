#include "engine/mt/bvh.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mtcut::engine {

double Aabb::min_distance(const Vec3& p) const {
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double gap = std::max({lo[k] - p[k], p[k] - hi[k], 0.0});
    sum += gap * gap;
  }
  return std::sqrt(sum);
}

double Aabb::max_distance(const Vec3& p) const {
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double far = std::max(std::abs(p[k] - lo[k]), std::abs(p[k] - hi[k]));
    sum += far * far;
  }
  return std::sqrt(sum);
}

void Bvh::build(std::span<const Aabb> boxes, std::span<const std::int32_t> levels, int leaf_size) {
  nodes_.clear();
  items_.resize(boxes.size());
  std::iota(items_.begin(), items_.end(), 0);
  if (boxes.empty()) return;
  std::vector<Vec3> centre(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) centre[i] = boxes[i].center();
  nodes_.reserve(2 * (boxes.size() / static_cast<std::size_t>(std::max(1, leaf_size)) + 1));

  struct Job {
    std::int32_t node, begin, end;
  };
  std::vector<Job> jobs;
  nodes_.emplace_back();
  jobs.push_back({0, 0, static_cast<std::int32_t>(boxes.size())});
  while (!jobs.empty()) {
    const Job job = jobs.back();
    jobs.pop_back();
    Aabb box, centres;
    for (std::int32_t i = job.begin; i < job.end; ++i) {
      const auto item = static_cast<std::size_t>(items_[static_cast<std::size_t>(i)]);
      box.extend(boxes[item]);
      centres.extend(centre[item]);
    }
    BvhNode& node = nodes_[static_cast<std::size_t>(job.node)];
    node.box = box;
    const std::int32_t count = job.end - job.begin;
    if (count <= leaf_size) {
      node.first = job.begin;
      node.count = count;
      continue;
    }
    const auto first = items_.begin() + job.begin, last = items_.begin() + job.end;
    if (!levels.empty()) {
      const auto [lo, hi] = std::minmax_element(first, last, [&](std::int32_t a, std::int32_t b) {
        return levels[static_cast<std::size_t>(a)] < levels[static_cast<std::size_t>(b)];
      });
      const std::int32_t lo_level = levels[static_cast<std::size_t>(*lo)];
      const std::int32_t hi_level = levels[static_cast<std::size_t>(*hi)];
      if (lo_level != hi_level) {
        const std::int32_t pivot = lo_level + (hi_level - lo_level) / 2;  // both sides non-empty
        const auto mid = std::stable_partition(
            first, last, [&](std::int32_t a) { return levels[static_cast<std::size_t>(a)] <= pivot; });
        const auto split = static_cast<std::int32_t>(mid - items_.begin());
        const auto left = static_cast<std::int32_t>(nodes_.size());
        node.first = left;
        node.count = 0;
        nodes_.emplace_back();
        nodes_.emplace_back();
        jobs.push_back({left, job.begin, split});
        jobs.push_back({left + 1, split, job.end});
        continue;
      }
    }
    int axis = 0;
    const Vec3 extent = centres.hi - centres.lo;
    if (extent[1] > extent[axis]) axis = 1;
    if (extent[2] > extent[axis]) axis = 2;
    const std::int32_t mid = job.begin + count / 2;
    std::nth_element(items_.begin() + job.begin, items_.begin() + mid, items_.begin() + job.end,
                     [&](std::int32_t a, std::int32_t b) {
                       const double ca = centre[static_cast<std::size_t>(a)][axis];
                       const double cb = centre[static_cast<std::size_t>(b)][axis];
                       return ca < cb || (ca == cb && a < b);
                     });
    const auto left = static_cast<std::int32_t>(nodes_.size());
    node.first = left;
    node.count = 0;
    nodes_.emplace_back();
    nodes_.emplace_back();
    jobs.push_back({left, job.begin, mid});
    jobs.push_back({left + 1, mid, job.end});
  }
}

}  // namespace mtcut::engine
