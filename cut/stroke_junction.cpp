#include "cut/stroke_junction.h"

#include <utility>

#include "engine/predicates.h"

namespace mtcut::cut {

using engine::Vec3;

std::optional<StrokeJunction> StrokeJunction::between(const CutPolygon& previous, const CutPolygon& next) {
  if (previous.normal().dot(next.normal()) <= 0) return std::nullopt;
  const std::vector<Vec3>& corners = next.corners();
  const std::size_t n = corners.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 &a = corners[i], &b = corners[(i + 1) % n];
    if (previous.edge_between(a, b) < 0) continue;
    // The dividing plane holds the edge and the bisector of the two normals;
    // it is oriented so that the next polygon's centre is ahead.
    const Vec3 up = (previous.normal() + next.normal()).normalized();
    std::array<Vec3, 3> divider{a, b, Vec3(a + (b - a).norm() * up)};
    Vec3 centre = Vec3::Zero();
    for (const Vec3& c : corners) centre += c;
    centre /= static_cast<double>(n);
    const int side = engine::orient3d_sign(divider[0], divider[1], divider[2], centre);
    if (side == 0) return std::nullopt;
    if (side < 0) std::swap(divider[0], divider[1]);
    return StrokeJunction(previous, divider);
  }
  return std::nullopt;
}

int StrokeJunction::ahead(const Vec3& x) const {
  return engine::orient3d_sign(divider_[0], divider_[1], divider_[2], x);
}

const CutPolygon& CutContinuation::polygon_behind(const engine::Vec3& x) const {
  // junctions[j] joins polygon j (its previous()) to polygon j + 1.
  for (std::size_t j = junctions.size() - 1; j > 0; --j)
    if (junctions[j - 1].ahead(x) >= 0) return junctions[j].previous();
  return junctions[0].previous();
}

}  // namespace mtcut::cut
