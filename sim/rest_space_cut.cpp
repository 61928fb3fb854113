#include "sim/rest_space_cut.h"

#include <cmath>
#include <vector>

#include <Eigen/Dense>

namespace mtcut::sim {

cut::CutPolygon rest_space_polygon(const cut::CutPolygon& polygon, std::span<const Vec3> rest,
                                   std::span<const Vec3> deformed, const RestSpaceCutDef& def) {
  const double diameter = polygon.diameter();
  std::vector<std::size_t> near;
  for (double reach = def.reach * diameter;; reach *= 2) {
    near.clear();
    for (std::size_t i = 0; i < deformed.size(); ++i) {
      const Vec3& x = deformed[i];
      if (std::abs(polygon.signed_distance(x)) <= reach && polygon.distance_outside(x) <= reach) near.push_back(i);
    }
    if (near.size() >= def.min_points || near.size() == deformed.size() || reach > 8 * diameter) break;
  }
  if (near.size() < 4) return polygon;

  // rest ~ [deformed 1] * M, M (4 x 3), by least squares about the centroid
  // (better conditioned than raw coordinates).
  Vec3 centre = Vec3::Zero();
  for (std::size_t i : near) centre += deformed[i];
  centre /= static_cast<double>(near.size());
  Eigen::MatrixXd a(near.size(), 4);
  Eigen::MatrixXd b(near.size(), 3);
  for (std::size_t k = 0; k < near.size(); ++k) {
    a.row(static_cast<Eigen::Index>(k)) << (deformed[near[k]] - centre).transpose(), 1.0;
    b.row(static_cast<Eigen::Index>(k)) = rest[near[k]].transpose();
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  if (qr.rank() < 4) return polygon;
  const Eigen::MatrixXd m = qr.solve(b);
  const Eigen::Matrix3d linear = m.topRows(3).transpose();
  const Vec3 offset = m.row(3).transpose();
  if (!(linear.determinant() > 1e-6)) return polygon;  // inverted or collapsed: not a deformation

  std::vector<Vec3> corners;
  corners.reserve(polygon.size());
  for (const Vec3& c : polygon.corners()) corners.push_back(linear * (c - centre) + offset);
  return cut::CutPolygon::from_points(corners, "cut polygon in rest space");
}

}  // namespace mtcut::sim
