#include "engine/mt/tet_error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace mtcut::engine {
namespace {

// Squared radius of the candidate sphere (centre c, squared radius r2), or
// +inf when it does not contain all four points (with a relative tolerance so
// that the points defining it are always inside).
double if_encloses(const std::array<Vec3, 4>& p, const Vec3& c, double r2) {
  const double limit = r2 * (1.0 + 1e-10);
  for (const Vec3& q : p)
    if ((q - c).squaredNorm() > limit) return std::numeric_limits<double>::infinity();
  return r2;
}

}  // namespace

double enclosing_radius(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // 0. The circumsphere, when its centre lies in the tet (the common case
  // for decent tets): then it is the smallest enclosing sphere.
  {
    const Vec3 u = b - a, v = c - a, w = d - a;
    const Vec3 vw = v.cross(w), wu = w.cross(u), uv = u.cross(v);
    const double det = u.dot(vw);
    if (det != 0.0) {
      const Vec3 offset = (u.squaredNorm() * vw + v.squaredNorm() * wu + w.squaredNorm() * uv) / (2.0 * det);
      const double l1 = offset.dot(vw) / det, l2 = offset.dot(wu) / det, l3 = offset.dot(uv) / det;
      if (l1 >= 0 && l2 >= 0 && l3 >= 0 && l1 + l2 + l3 <= 1) return offset.norm();
    }
  }
  const std::array<Vec3, 4> p = {a, b, c, d};
  // 1. The longest edge's diametral sphere: no enclosing sphere is smaller,
  // so when it holds the other two points it is the answer.
  static constexpr int kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  int longest = 0;
  double longest2 = -1;
  for (int k = 0; k < 6; ++k) {
    const double l2 = (p[kEdges[k][0]] - p[kEdges[k][1]]).squaredNorm();
    if (l2 > longest2) longest2 = l2, longest = k;
  }
  const Vec3 mid = 0.5 * (p[kEdges[longest][0]] + p[kEdges[longest][1]]);
  double best = if_encloses(p, mid, 0.25 * longest2);
  if (std::isfinite(best)) return std::sqrt(best);

  // 2. Each face's circumcircle (the smallest sphere through its corners).
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  for (const auto& f : kFaces) {
    const Vec3 u = p[f[1]] - p[f[0]], v = p[f[2]] - p[f[0]];
    const Vec3 n = u.cross(v);
    const double n2 = n.squaredNorm();
    if (n2 == 0.0) continue;
    const Vec3 offset = (u.squaredNorm() * v - v.squaredNorm() * u).cross(n) / (2.0 * n2);
    best = std::min(best, if_encloses(p, p[f[0]] + offset, offset.squaredNorm()));
  }
  // 3. The circumsphere always encloses all four.
  const Vec3 u = b - a, v = c - a, w = d - a;
  const double det = u.dot(v.cross(w));
  if (det != 0.0) {
    const Vec3 offset = (u.squaredNorm() * v.cross(w) + v.squaredNorm() * w.cross(u) + w.squaredNorm() * u.cross(v)) /
                        (2.0 * det);
    best = std::min(best, offset.squaredNorm());
  }
  if (!std::isfinite(best)) {
    // Flat and no face circle fits (collinear points): half the longest edge
    // is then exact.
    best = 0.25 * longest2;
  }
  return std::sqrt(best);
}

double tet_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double l2 = std::max({(a - b).squaredNorm(), (a - c).squaredNorm(), (a - d).squaredNorm(),
                              (b - c).squaredNorm(), (b - d).squaredNorm(), (c - d).squaredNorm()});
  if (l2 == 0.0) return 0.0;
  const double volume = (b - a).cross(c - a).dot(d - a) / 6.0;
  return 6.0 * std::numbers::sqrt2 * volume / (l2 * std::sqrt(l2));
}

double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Ericson, Real-Time Collision Detection, 5.1.5: closest point by regions.
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.norm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

}  // namespace mtcut::engine
