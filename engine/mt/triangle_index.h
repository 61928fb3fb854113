#pragma once
// The distance from a point to a fixed triangle surface, through a bounding
// volume hierarchy over its triangles (bvh.h): the builder's check of how far
// a collapse moves the surface from the fine one (collapse.h), and the
// measure of how far a level's surface lies from it (surface_deviation.h).

#include <array>
#include <limits>
#include <vector>

#include "engine/mt/bvh.h"

namespace mtcut::engine {

using Triangle = std::array<Vec3, 3>;

class TriangleIndex {
 public:
  explicit TriangleIndex(std::vector<Triangle> triangles);
  // The distance from p to the nearest triangle when it is below `within`
  // (+infinity otherwise, and with no triangle). With `enough`, any distance
  // at most `enough` may be returned in its place, as soon as one is found:
  // what a largest-of-nearest-distances needs (a sample at most the largest
  // so far cannot change it).
  double distance(const Vec3& p, double within = std::numeric_limits<double>::infinity(),
                  double enough = -1.0) const;
  std::size_t size() const { return triangles_.size(); }

 private:
  std::vector<Triangle> triangles_;
  Bvh bvh_;
};

}  // namespace mtcut::engine
