#include "engine/mt/triangle_index.h"

#include <algorithm>
#include <limits>

#include "engine/mt/tet_error.h"

namespace mtcut::engine {

TriangleIndex::TriangleIndex(std::vector<Triangle> triangles) : triangles_(std::move(triangles)) {
  std::vector<Aabb> boxes(triangles_.size());
  for (std::size_t i = 0; i < triangles_.size(); ++i) boxes[i] = box_of(triangles_[i]);
  bvh_.build(boxes);
}

double TriangleIndex::distance(const Vec3& p, double within, double enough) const {
  double best = within;
  bool found = false;
  const auto nodes = bvh_.nodes();
  const auto items = bvh_.items();
  bvh_.walk([&](std::int32_t n) { return nodes[static_cast<std::size_t>(n)].box.min_distance(p) < best; },
            [&](std::int32_t n) {
              const BvhNode& node = nodes[static_cast<std::size_t>(n)];
              for (std::int32_t i = node.first; i < node.first + node.count; ++i) {
                const Triangle& t = triangles_[static_cast<std::size_t>(items[static_cast<std::size_t>(i)])];
                const double d = point_triangle_distance(p, t[0], t[1], t[2]);
                if (d < best) best = d, found = true;
                if (best <= enough) return false;
              }
              return true;
            });
  return found ? best : std::numeric_limits<double>::infinity();
}

}  // namespace mtcut::engine
