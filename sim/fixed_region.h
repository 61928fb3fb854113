#pragma once
// Which vertices are pinned, chosen in rest space so that the choice holds at
// every resolution and survives LOD changes and cuts.

#include <vector>

#include "engine/ids.h"
#include "engine/predicates.h"

namespace mtcut::sim {

using engine::Vec3;

struct FixedRegion {
  enum class Kind { kNone, kBox, kHalfSpace, kList };
  Kind kind = Kind::kNone;
  Vec3 box_min = Vec3::Zero(), box_max = Vec3::Zero();  // kBox: inclusive corners
  Vec3 normal = Vec3::UnitX();                         // kHalfSpace: normal . x <= offset is fixed
  double offset = 0.0;
  std::vector<engine::VertId> vertices;                // kList, sorted ascending

  // True when the vertex v at rest position p is pinned.
  bool contains(engine::VertId v, const Vec3& p) const;
};

}  // namespace mtcut::sim
