#include "engine/mt/segment_distance.h"

#include <algorithm>
#include <array>
#include <limits>

namespace mtcut::engine {

double min_distance(const Aabb& box, const Segment& s) {
  const Vec3 d = s.b - s.a;
  // The parameters where the squared distance changes its quadratic: the
  // ends and the crossings of the six slab planes in between.
  std::array<double, 8> breaks{};  // sorted as they are inserted
  int n = 0;
  const auto insert = [&](double t) {
    int i = n++;
    for (; i > 0 && breaks[static_cast<std::size_t>(i - 1)] > t; --i)
      breaks[static_cast<std::size_t>(i)] = breaks[static_cast<std::size_t>(i - 1)];
    breaks[static_cast<std::size_t>(i)] = t;
  };
  insert(0.0);
  insert(1.0);
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) continue;
    for (const double plane : {box.lo[k], box.hi[k]}) {
      const double t = (plane - s.a[k]) / d[k];
      if (t > 0.0 && t < 1.0) insert(t);
    }
  }
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i + 1 < n; ++i) {
    const double t0 = breaks[static_cast<std::size_t>(i)], t1 = breaks[static_cast<std::size_t>(i + 1)];
    // Within [t0, t1] each axis is below, inside or above the box
    // throughout: the squared distance is A t^2 + B t + C there.
    const double t_mid = 0.5 * (t0 + t1);
    const Vec3 mid = s.a + t_mid * d;
    double qa = 0.0, qb = 0.0;
    for (int k = 0; k < 3; ++k) {
      double gap0 = 0.0, slope = 0.0;  // gap(t) = gap0 + slope t
      if (mid[k] < box.lo[k]) {
        gap0 = box.lo[k] - s.a[k], slope = -d[k];
      } else if (mid[k] > box.hi[k]) {
        gap0 = s.a[k] - box.hi[k], slope = d[k];
      }
      qa += slope * slope;
      qb += 2.0 * gap0 * slope;
    }
    // Constant (qa = 0) on the piece: its value at the midpoint, which is
    // exactly 0 where the segment runs inside the box.
    const double t = qa > 0.0 ? std::clamp(-qb / (2.0 * qa), t0, t1) : t_mid;
    best = std::min(best, box.min_distance(Vec3(s.a + t * d)));
  }
  return best;
}

double distance(const Segment& s, const Vec3& p) {
  const Vec3 d = s.b - s.a;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - s.a).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (p - (s.a + t * d)).norm();
}

double max_distance(const Aabb& box, const Segment& s) {
  double far = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p((corner & 1) ? box.hi.x() : box.lo.x(), (corner & 2) ? box.hi.y() : box.lo.y(),
                 (corner & 4) ? box.hi.z() : box.lo.z());
    far = std::max(far, distance(s, p));
  }
  return far;
}

}  // namespace mtcut::engine
