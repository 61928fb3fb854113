#include "engine/tet_geometry.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace mtcut::engine {
namespace {

struct Sphere {
  Vec3 center;
  double radius;
};

bool contains(const Sphere& s, const Vec3& p) {
  return (p - s.center).norm() <= s.radius * (1 + 1e-12) + 1e-300;
}

// The smallest sphere through the given 1..4 points (circumsphere of the
// simplex they span, restricted to its affine hull). Returns radius +inf when
// the points are affinely dependent.
Sphere circumsphere_of(const std::array<Vec3, 4>& p, int n) {
  if (n == 1) return {p[0], 0.0};
  // Centre c = p0 + sum_j l_j (pj - p0) with |c - pj| = |c - p0| for all j.
  Eigen::MatrixXd a(n - 1, n - 1);
  Eigen::VectorXd rhs(n - 1);
  for (int i = 1; i < n; ++i) {
    const Vec3 ui = p[i] - p[0];
    for (int j = 1; j < n; ++j) a(i - 1, j - 1) = 2.0 * ui.dot(p[j] - p[0]);
    rhs(i - 1) = ui.squaredNorm();
  }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(a);
  if (!lu.isInvertible()) return {p[0], std::numeric_limits<double>::infinity()};
  const Eigen::VectorXd l = lu.solve(rhs);
  Vec3 c = p[0];
  for (int j = 1; j < n; ++j) c += l(j - 1) * (p[j] - p[0]);
  return {c, (c - p[0]).norm()};
}

}  // namespace

double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).cross(c - a).dot(d - a) / 6.0;
}

std::array<double, 4> barycentric(const std::array<Vec3, 4>& c, const Vec3& p) {
  const double total = signed_volume(c[0], c[1], c[2], c[3]);
  std::array<double, 4> w{};
  w[0] = signed_volume(p, c[1], c[2], c[3]) / total;
  w[1] = signed_volume(c[0], p, c[2], c[3]) / total;
  w[2] = signed_volume(c[0], c[1], p, c[3]) / total;
  w[3] = 1.0 - w[0] - w[1] - w[2];
  return w;
}

std::array<double, 6> dihedral_angles(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const std::array<Vec3, 4> p = {a, b, c, d};
  // Outward face normals (unnormalised), face i opposite vertex i.
  std::array<Vec3, 4> n;
  for (int i = 0; i < 4; ++i) {
    const auto& f = kTetFaces[i];
    n[i] = (p[f[1]] - p[f[0]]).cross(p[f[2]] - p[f[0]]);
    const double len = n[i].norm();
    n[i] = len > 0 ? Vec3(n[i] / len) : Vec3::Zero();
  }
  std::array<double, 6> out{};
  for (int k = 0; k < 6; ++k) {
    // The edge (i, j) is shared by the faces opposite the two other vertices.
    int others[2], m = 0;
    for (int v = 0; v < 4; ++v)
      if (v != kTetEdges[k][0] && v != kTetEdges[k][1]) others[m++] = v;
    const double cosine = std::clamp(-n[others[0]].dot(n[others[1]]), -1.0, 1.0);
    out[k] = std::acos(cosine);
  }
  return out;
}

double min_dihedral_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (signed_volume(a, b, c, d) == 0.0) return 0.0;
  const auto angles = dihedral_angles(a, b, c, d);
  return *std::min_element(angles.begin(), angles.end()) * 180.0 / std::numbers::pi;
}

double radius_ratio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double volume = std::abs(signed_volume(a, b, c, d));
  if (volume == 0.0) return 0.0;
  const double area = 0.5 * ((b - a).cross(c - a).norm() + (b - a).cross(d - a).norm() +
                             (c - a).cross(d - a).norm() + (c - b).cross(d - b).norm());
  const double inradius = 3.0 * volume / area;
  const double circumradius = circumsphere_of({a, b, c, d}, 4).radius;
  return std::clamp(3.0 * inradius / circumradius, 0.0, 1.0);
}

double min_enclosing_radius(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // Four points: try every support subset, smallest first; the first sphere
  // that contains all points is the minimum one (Welzl by enumeration).
  const std::array<Vec3, 4> p = {a, b, c, d};
  double best = std::numeric_limits<double>::infinity();
  for (int mask = 1; mask < 16; ++mask) {
    std::array<Vec3, 4> support;
    int n = 0;
    for (int i = 0; i < 4; ++i)
      if (mask & (1 << i)) support[n++] = p[i];
    if (n < 2) continue;
    const Sphere s = circumsphere_of(support, n);
    if (s.radius >= best) continue;
    if (std::all_of(p.begin(), p.end(), [&](const Vec3& q) { return contains(s, q); }))
      best = s.radius;
  }
  return best;
}

}  // namespace mtcut::engine
