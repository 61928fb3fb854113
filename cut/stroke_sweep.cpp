#include "cut/stroke_sweep.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <Eigen/Eigenvalues>

#include "engine/input_error.h"

namespace mtcut::cut {
namespace {

// A heading turned by more than 120 degrees turned back (StrokeAdvance::turned_back).
constexpr double kTurnedBackCos = 0.5;  // cos(60 degrees)

// The motion of the blade's middle from `from` to `to`, across the blade
// at `to` (a blade pushed along itself does not head anywhere).
Vec3 heading(const std::pair<Vec3, Vec3>& from, const std::pair<Vec3, Vec3>& to) {
  const Vec3 move = 0.5 * ((to.first + to.second) - (from.first + from.second));
  const Vec3 axis = to.second - to.first;
  const double length2 = axis.squaredNorm();
  return length2 > 0 ? Vec3(move - axis * (axis.dot(move) / length2)) : move;
}

// The best plane through points: centroid and orthonormal axes (u, v in the
// plane, n its normal), by principal components.
struct Plane {
  Vec3 origin, u, v, n;
};

// The plane through `centroid` whose normal is the direction of least
// spread of `cov` (eigenvalues ascending).
Plane principal_plane(const Vec3& centroid, const Eigen::Matrix3d& cov) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Vec3 n = eig.eigenvectors().col(0).normalized();
  const Vec3 u = eig.eigenvectors().col(2).normalized();
  return {centroid, u, n.cross(u), n};
}

Plane fit_plane(const std::vector<Vec3>& points) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : points) c += p;
  c /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) cov += (p - c) * (p - c).transpose();
  return principal_plane(c, cov);
}

// The same plane from running sums (PartSums), without the points.
Plane moments_plane(const Vec3& shift, const Vec3& sum, const Eigen::Matrix3d& sum_outer, std::size_t n) {
  const Vec3 mean = sum / static_cast<double>(n);
  return principal_plane(shift + mean, sum_outer - static_cast<double>(n) * mean * mean.transpose());
}

double diameter(const std::vector<Vec3>& points) {
  Vec3 lo = points.front(), hi = points.front();
  for (const Vec3& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (hi - lo).norm();
}

double cross2(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

double polygon_area(const std::vector<Eigen::Vector2d>& p) {
  double twice = 0;
  for (std::size_t i = 0; i < p.size(); ++i) twice += cross2(Eigen::Vector2d::Zero(), p[i], p[(i + 1) % p.size()]);
  return 0.5 * std::abs(twice);
}

std::vector<Vec3> corner_points(const std::vector<std::pair<Vec3, Vec3>>& blades) {
  std::vector<Vec3> points;
  points.reserve(2 * blades.size());
  for (const auto& [base, tip] : blades) {
    points.push_back(base);
    points.push_back(tip);
  }
  return points;
}

// The hull of the points on their plane, and its area.
struct Hull {
  Plane plane;
  std::vector<Eigen::Vector2d> corners;
  double area = 0, diameter = 0;
};

// The hull of `points` projected on `plane`; `diameter` sets the tolerance
// for collinear corners.
Hull hull_on(const Plane& plane, const std::vector<Vec3>& points, double diameter) {
  Hull h;
  h.plane = plane;
  h.diameter = diameter;
  std::vector<Eigen::Vector2d> flat;
  flat.reserve(points.size());
  for (const Vec3& p : points) {
    const Vec3 d = p - plane.origin;
    flat.emplace_back(d.dot(plane.u), d.dot(plane.v));
  }
  h.corners = convex_hull_2d(std::move(flat), 1e-12 * diameter * diameter);
  h.area = h.corners.size() >= 3 ? polygon_area(h.corners) : 0.0;
  return h;
}

// The hull of `points` on their best plane.
Hull hull_of(const std::vector<Vec3>& points) { return hull_on(fit_plane(points), points, diameter(points)); }

}  // namespace

double sweep_area(const Vec3& a0, const Vec3& b0, const Vec3& a1, const Vec3& b1) {
  return 0.5 * ((b0 - a0).cross(b1 - a0).norm() + (b1 - a0).cross(a1 - a0).norm());
}

void StrokeSweep::PartSums::add(const Vec3& p) {
  if (n == 0) {
    shift = p;
    lo = hi = p;
  }
  const Vec3 q = p - shift;
  sum += q;
  sum_outer += q * q.transpose();
  lo = lo.cwiseMin(p);
  hi = hi.cwiseMax(p);
  ++n;
}

bool StrokeSweep::extends(const Blade& next, std::vector<Vec3>& corners) const {
  corners = hull_corners_;
  corners.push_back(next.first);
  corners.push_back(next.second);
  if (blades_.size() < 2) return true;  // two poses always span one sweep
  PartSums sums = sums_;
  sums.add(next.first);
  sums.add(next.second);
  const Plane plane = moments_plane(sums.shift, sums.sum, sums.sum_outer, sums.n);
  const double diameter = (sums.hi - sums.lo).norm();
  // Every pose, the new one too, near the plane.
  double off_plane = 0;
  const auto off = [&](const Vec3& p) { off_plane = std::max(off_plane, std::abs((p - plane.origin).dot(plane.n))); };
  for (const Blade& b : blades_) off(b.first), off(b.second);
  off(next.first), off(next.second);
  if (off_plane > def_.plane_tolerance * diameter) return false;
  // The part's fixed plane (once it has one) may lie a little further: it
  // was fitted to the part's first poses.
  if (plane_ && std::max(std::abs(plane_->signed_distance(next.first)), std::abs(plane_->signed_distance(next.second))) >
                    def_.fixed_plane_tolerance * diameter)
    return false;
  // The hull of all poses is the hull of the last one's corners and the new
  // pose: exactly so while the plane stays; as it turns a little, a pose once
  // inside may end up a sliver outside, which only the area test here skips
  // (close_part() takes the hull of every pose).
  const Hull h = hull_on(plane, corners, diameter);
  corners.clear();
  for (const auto& c : h.corners) corners.push_back(plane.origin + c.x() * plane.u + c.y() * plane.v);
  const Blade& last = blades_.back();
  const double swept = swept_area_ + sweep_area(last.first, last.second, next.first, next.second);
  return h.area <= (1 + def_.hull_excess) * swept;
}

std::vector<CutPolygon> StrokeSweep::add(const Vec3& base, const Vec3& tip) {
  std::vector<CutPolygon> out;
  const Blade next(base, tip);
  std::vector<Vec3> corners;
  if (!extends(next, corners)) {
    // The next part overlaps this one by half a sweep (see the header): it
    // starts midway between the last two poses, then the last pose.
    out = close_part();
    const Vec3 was = heading(blades_.front(), blades_.back()), goes = heading(blades_.back(), next);
    turned_back_ = was.dot(goes) < -kTurnedBackCos * was.norm() * goes.norm();
    const Blade last = blades_.back();
    const Blade before = blades_[blades_.size() - 2];
    clear_part();
    start_with(Blade(0.5 * (before.first + last.first), 0.5 * (before.second + last.second)));
    start_with(last);
    overlap_area_ = swept_area_;
    extends(next, corners);  // the hull corners with `next` (the part may not be planar: it starts anyway)
  }
  if (!blades_.empty()) {
    const Blade& last = blades_.back();
    swept_area_ += sweep_area(last.first, last.second, next.first, next.second);
  }
  blades_.push_back(next);
  sums_.add(base);
  sums_.add(tip);
  hull_corners_ = std::move(corners);
  if (!plane_ && blades_.size() >= 2) {
    const Hull h = hull_of(hull_corners_);
    if (h.area >= def_.plane_width * h.diameter * h.diameter) {
      std::vector<CutPolygon> polygon = polygon_of(hull_corners_);
      if (!polygon.empty()) plane_ = std::move(polygon.front());
    }
  }
  return out;
}

std::vector<CutPolygon> StrokeSweep::part_polygon(const std::vector<Vec3>& points) const {
  if (!plane_) return polygon_of(points);
  // The hull on the poses' best plane, then on the fixed one: the best
  // plane's hull drops the corners that are collinear to rounding there.
  std::vector<CutPolygon> on = polygon_of(points);
  if (on.empty()) return on;
  try {
    return {CutPolygon::on_plane_of(*plane_, on.front().corners(), "scalpel stroke")};
  } catch (const engine::InputError&) {
    return {};  // no area on the plane
  }
}

StrokeAdvance StrokeSweep::advance(std::span<const BladePose> poses) {
  StrokeAdvance out;
  if (!blades_.empty()) out.swept.extend(blades_.back().first), out.swept.extend(blades_.back().second);
  for (const BladePose& pose : poses) {
    std::vector<CutPolygon> ended;
    out.swept.extend(pose.base);
    out.swept.extend(pose.tip);
    bool turned_back = false;
    if (pose.engaged) {
      out.moved = out.moved || blades_.empty() || pose.base != blades_.back().first || pose.tip != blades_.back().second;
      ended = add(pose.base, pose.tip);
      turned_back = turned_back_;
    } else if (active()) {
      ended = finish();
      out.moved = true;
    }
    out.turned_back.insert(out.turned_back.end(), ended.size(), turned_back ? 1 : 0);
    out.ended.insert(out.ended.end(), std::make_move_iterator(ended.begin()), std::make_move_iterator(ended.end()));
  }
  return out;
}

void StrokeSweep::start_with(const Blade& blade) {
  if (!blades_.empty()) {
    const Blade& last = blades_.back();
    swept_area_ += sweep_area(last.first, last.second, blade.first, blade.second);
  }
  blades_.push_back(blade);
  sums_.add(blade.first);
  sums_.add(blade.second);
  hull_corners_.push_back(blade.first);
  hull_corners_.push_back(blade.second);
}

void StrokeSweep::clear_part() {
  blades_.clear();
  swept_area_ = 0;
  overlap_area_ = 0;
  sums_ = {};
  hull_corners_.clear();
  plane_.reset();
}

std::vector<CutPolygon> StrokeSweep::finish() {
  std::vector<CutPolygon> out = close_part();
  clear_part();
  return out;
}

double StrokeSweep::own_area() const { return swept_area_ - overlap_area_; }

std::vector<CutPolygon> StrokeSweep::close_part() {
  // Any area of its own: its sweeps are cut, the overlap with them.
  const double diameter = blades_.empty() ? 0.0 : (sums_.hi - sums_.lo).norm();
  if (blades_.size() < 2 || own_area() <= CutPolygonDef{}.min_relative_area * diameter * diameter) return {};
  return part_polygon(corner_points(blades_));
}

std::optional<CutPolygon> StrokeSweep::current() const {
  if (blades_.size() < 2 || own_area() <= def_.hull_excess * overlap_area_) return std::nullopt;
  std::vector<CutPolygon> p = part_polygon(hull_corners_);
  if (p.empty()) return std::nullopt;
  return std::move(p.front());
}

std::vector<CutPolygon> StrokeSweep::polygon_of(const std::vector<Vec3>& points) {
  const Hull h = hull_of(points);
  if (h.corners.size() < 3 || h.area <= CutPolygonDef{}.min_relative_area * h.diameter * h.diameter) return {};
  std::vector<Vec3> corners;
  corners.reserve(h.corners.size());
  for (const auto& c : h.corners) corners.push_back(h.plane.origin + c.x() * h.plane.u + c.y() * h.plane.v);
  return {CutPolygon::from_points(corners, "scalpel stroke")};
}

}  // namespace mtcut::cut
