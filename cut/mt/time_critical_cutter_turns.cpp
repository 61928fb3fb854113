// TimeCriticalCutter (time_critical_cutter.h): where a stroke's parts
// meet at a turn. A gentle turn's next part pivots about the ended
// polygon's edge; a sharp turn's two cracks cross, each taken past the
// other; and how far a part cut whole has moved since it was cut.
#include "cut/mt/time_critical_cutter.h"

#include "engine/input_error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include <Eigen/Eigenvalues>

namespace mtcut::cut {
namespace {

// The unit direction in `polygon`'s plane across the line a-b, away from
// the polygon: from its corner farthest from the line (a part that starts
// half a sweep behind its turn's edge lies mostly ahead of it).
Vec3 outward(const CutPolygon& polygon, const Vec3& a, const Vec3& b) {
  const Vec3 e = (b - a).normalized();
  const Vec3 across = polygon.normal().cross(e).normalized();
  double farthest = 0;
  for (const Vec3& x : polygon.corners())
    if (std::abs((x - a).dot(across)) > std::abs(farthest)) farthest = (x - a).dot(across);
  return farthest > 0 ? Vec3(-across) : across;
}

// How far x lies from `polygon` (approximately).
double distance_to(const CutPolygon& polygon, const Vec3& x) {
  return std::hypot(polygon.signed_distance(x), polygon.distance_outside(x));
}

// How far past the line a-b, along each of `out`, the tets reach that hold
// a point of the segment, at every resolution of the MT (0 when the segment
// misses it): a crack's outline that far past the line leaves every such
// tet crossed completely. The points are spaced along the segment's part in
// the MT's box; one pass serves both directions.
std::array<double, 2> tets_reach_past(const Mt& mt, const engine::TetBvh& bvh, Vec3 a, Vec3 b,
                                      const std::array<Vec3, 2>& out) {
  const engine::Aabb box = bvh.bounds();
  double t0 = 0, t1 = 1;  // the segment clipped to the box (slabs)
  for (int k = 0; k < 3 && t0 <= t1; ++k) {
    const double d = b[k] - a[k];
    if (d == 0) {
      if (a[k] < box.lo[k] || a[k] > box.hi[k]) t1 = -1;
      continue;
    }
    const double u = (box.lo[k] - a[k]) / d, v = (box.hi[k] - a[k]) / d;
    t0 = std::max(t0, std::min(u, v));
    t1 = std::min(t1, std::max(u, v));
  }
  std::array<double, 2> reach{0, 0};
  if (t0 > t1) return reach;
  constexpr int kSamples = 128;
  for (int k = 0; k <= kSamples; ++k) {
    const double t = t0 + (t1 - t0) * k / kSamples;
    const Vec3 p = a + t * (b - a);
    bvh.for_each_containing(mt, p, [&](engine::TetId tet) {
      for (engine::VertId v : mt.tet(tet))
        for (int d = 0; d < 2; ++d) reach[d] = std::max(reach[d], (mt.position(v) - p).dot(out[d]));
      return true;
    });
  }
  return reach;
}

}  // namespace

// The Hausdorff distance between two convex polygons: the distance to a
// convex set is convex, so its largest on a polygon is at a corner.
double TimeCriticalCutter::hausdorff(const CutPolygon& a, const CutPolygon& b) {
  double d = 0;
  for (const Vec3& x : a.corners()) d = std::max(d, distance_to(b, x));
  for (const Vec3& x : b.corners()) d = std::max(d, distance_to(a, x));
  return d;
}

std::optional<CutPolygon> TimeCriticalCutter::cross_at_turn(const Mt& mt, const TetBvh& bvh, const CutPolygon& polygon,
                                                          const CutPolygon& next) {
  const std::optional<Pivot> turn = turn_edge(polygon, next);
  if (!turn) return std::nullopt;
  const auto [ahead, behind] =
      tets_reach_past(mt, bvh, turn->a, turn->b, {turn->forward, outward(next, turn->a, turn->b)});
  crossing_ = Crossing{turn->a, turn->b, kCrossingReach * behind};
  return past(polygon, Crossing{turn->a, turn->b, kCrossingReach * ahead});
}

CutPolygon TimeCriticalCutter::whole_polygon(const CutPolygon& current) const {
  std::optional<CutPolygon> polygon;
  if (pivot_) polygon = pivoted(*pivot_, current.corners());
  if (!polygon && crossing_) polygon = past(current, *crossing_);
  return polygon ? *polygon : current;
}

std::optional<TimeCriticalCutter::Pivot> TimeCriticalCutter::pivot_between(const CutPolygon& previous,
                                                                            const CutPolygon& next) {
  // A turn of the stroke's planes up to kMaxContinuedTurn goes on across
  // an edge; a sharper one starts a new crack.
  if (std::abs(previous.normal().dot(next.normal())) < std::cos(kMaxContinuedTurn * std::numbers::pi / 180))
    return std::nullopt;
  return turn_edge(previous, next);
}

std::optional<TimeCriticalCutter::Pivot> TimeCriticalCutter::turn_edge(const CutPolygon& previous,
                                                                        const CutPolygon& next) {
  // The edge of `previous` whose ends lie nearest `next` among its long
  // ones, if they lie on it to a small fraction of the polygons' size: the
  // blade where the stroke turned is a corner pair of both, up to their
  // maps to rest space. A short edge of the hull beside it (where the
  // blade's last poses, projected on the part's plane, make a corner) can
  // lie as near, and pivoting about it turns the part's plane off the
  // blade; so the edges within reach that are under half the longest of
  // them are passed over.
  const std::vector<Vec3>& c = previous.corners();
  const std::size_t n = c.size();
  const auto off = [&](const Vec3& x) { return distance_to(next, x); };
  const double tolerance = 0.1 * previous.diameter();
  std::vector<double> cost(n);
  double longest = 0;
  for (std::size_t i = 0; i < n; ++i) {
    cost[i] = std::max(off(c[i]), off(c[(i + 1) % n]));
    if (cost[i] <= tolerance) longest = std::max(longest, (c[(i + 1) % n] - c[i]).norm());
  }
  std::size_t at = n;
  for (std::size_t i = 0; i < n; ++i)
    if (cost[i] <= tolerance && (c[(i + 1) % n] - c[i]).norm() >= 0.5 * longest && (at == n || cost[i] < cost[at]))
      at = i;
  if (at == n) return std::nullopt;
  Pivot p;
  p.a = c[at];
  p.b = c[(at + 1) % n];
  p.normal = previous.normal();
  p.forward = outward(previous, p.a, p.b);
  return p;
}

std::optional<CutPolygon> TimeCriticalCutter::pivoted(const Pivot& pivot, const std::vector<Vec3>& corners) {
  const double length = (pivot.b - pivot.a).norm();
  const Vec3 e = (pivot.b - pivot.a) / length;
  // The direction away from the edge that fits the corners ahead of it
  // best (least squares about the edge's line): the plane is the edge's,
  // turned about it as the blade goes on.
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (const Vec3& x : corners) {
    const Vec3 w = (x - pivot.a) - e * e.dot(x - pivot.a);
    if (w.dot(pivot.forward) > 0) spread += w * w.transpose();
  }
  Vec3 along = pivot.forward;
  if (spread.trace() > 0) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(spread);
    along = eig.eigenvectors().col(2).normalized();
    if (along.dot(pivot.forward) < 0) along = -along;
  }
  // Facing the way the last polygon does (a junction joins polygons whose
  // normals agree, stroke_junction.h).
  std::vector<Vec3> plane{pivot.a, pivot.b, pivot.b + length * along, pivot.a + length * along};
  if ((pivot.b - pivot.a).cross(along).dot(pivot.normal) < 0) std::reverse(plane.begin(), plane.end());
  std::vector<Vec3> points{pivot.a, pivot.b};
  for (const Vec3& x : corners)
    if ((x - pivot.a).dot(along) > 1e-6 * length) points.push_back(x);
  if (points.size() < 3) return std::nullopt;
  try {
    return CutPolygon::on_plane_of(CutPolygon::from_points(plane, "scalpel stroke"), points, "scalpel stroke");
  } catch (const engine::InputError&) {
    return std::nullopt;
  }
}

CutPolygon TimeCriticalCutter::past(const CutPolygon& polygon, const Crossing& crossing) {
  if (crossing.reach <= 0) return polygon;
  const Vec3 out = outward(polygon, crossing.a, crossing.b);
  std::vector<Vec3> points = polygon.corners();
  points.push_back(crossing.a + crossing.reach * out);
  points.push_back(crossing.b + crossing.reach * out);
  try {
    return CutPolygon::on_plane_of(polygon, points, "scalpel stroke");
  } catch (const engine::InputError&) {
    return polygon;
  }
}

}  // namespace mtcut::cut
