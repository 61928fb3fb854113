#include "sim/fixed_region.h"

#include <algorithm>

namespace mtcut::sim {

bool FixedRegion::contains(engine::VertId v, const Vec3& p) const {
  switch (kind) {
    case Kind::kNone: return false;
    case Kind::kBox: return (p.array() >= box_min.array()).all() && (p.array() <= box_max.array()).all();
    case Kind::kHalfSpace: return normal.dot(p) <= offset;
    case Kind::kList: return std::binary_search(vertices.begin(), vertices.end(), v);
  }
  return false;
}

}  // namespace mtcut::sim
