#include "cut/cut_polygon.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <optional>
#include <sstream>

#include "engine/input_error.h"

namespace mtcut::cut {
namespace {

using engine::InputError;
using engine::orient3d_sign;

double cross2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

std::string format_point(const Vec3& p) {
  std::ostringstream out;
  out.precision(9);
  out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return out.str();
}

// The three corners spanning the largest triangle: the best conditioned
// plane through the input. O(n^3) for small polygons, a spread fan otherwise.
std::array<std::size_t, 3> widest_triangle(const std::vector<Vec3>& p) {
  const std::size_t n = p.size();
  if (n > 24) return {0, n / 3, (2 * n) / 3};
  std::array<std::size_t, 3> best = {0, 1, 2};
  double best_area = -1;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        const double area = (p[j] - p[i]).cross(p[k] - p[i]).squaredNorm();
        if (area > best_area) {
          best_area = area;
          best = {i, j, k};
        }
      }
  return best;
}

}  // namespace

std::vector<Eigen::Vector2d> convex_hull_2d(std::vector<Eigen::Vector2d> p, double eps) {
  std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Eigen::Vector2d> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross2d(hull[k - 1] - hull[k - 2], p[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross2d(hull[k - 1] - hull[k - 2], p[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = p[i];
  }
  hull.resize(k - 1);
  for (bool removed = true; removed && hull.size() > 3;) {
    removed = false;
    for (std::size_t i = 0; i < hull.size() && hull.size() > 3; ++i) {
      const std::size_t n = hull.size();
      if (cross2d(hull[i] - hull[(i + n - 1) % n], hull[(i + 1) % n] - hull[(i + n - 1) % n]) <= eps) {
        hull.erase(hull.begin() + static_cast<std::ptrdiff_t>(i));
        removed = true;
      }
    }
  }
  return hull;
}

CutPolygon CutPolygon::from_points(const std::vector<Vec3>& points, const std::string& source,
                                   const CutPolygonDef& def) {
  const std::size_t n = points.size();
  if (n < 3) throw InputError(source + ": a cut polygon needs at least 3 corners, got " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i)
    if (!points[i].allFinite()) throw InputError(source + ": corner " + std::to_string(i + 1) + " is not finite");

  CutPolygon poly;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) poly.diameter_ = std::max(poly.diameter_, (points[i] - points[j]).norm());
  if (poly.diameter_ == 0) throw InputError(source + ": all corners coincide");
  const double d = poly.diameter_;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if ((points[i] - points[j]).norm() <= 1e-12 * d)
      throw InputError(source + ": corners " + std::to_string(i + 1) + " and " + std::to_string(j + 1) +
                       " coincide");
  }

  // Newell's normal: its length is twice the area, its direction follows the order.
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& p : points) centroid += p;
  centroid /= static_cast<double>(n);
  Vec3 newell = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) newell += (points[i] - centroid).cross(points[(i + 1) % n] - centroid);
  if (0.5 * newell.norm() < def.min_relative_area * d * d)
    throw InputError(source + ": the corners are collinear (zero area)");
  const Vec3 fitted = newell.normalized();
  for (std::size_t i = 0; i < n; ++i) {
    const double off = std::abs((points[i] - centroid).dot(fitted));
    if (off > def.planarity_tolerance * d)
      throw InputError(source + ": not planar: corner " + std::to_string(i + 1) + " " + format_point(points[i]) +
                       " is " + std::to_string(off) + " off the plane of the others");
  }

  // Freeze three corners as the exact plane, oriented like the outline.
  auto tri = widest_triangle(points);
  if ((points[tri[1]] - points[tri[0]]).cross(points[tri[2]] - points[tri[0]]).dot(fitted) < 0)
    std::swap(tri[1], tri[2]);
  poly.plane_ = {points[tri[0]], points[tri[1]], points[tri[2]]};
  poly.normal_ = (poly.plane_[1] - poly.plane_[0]).cross(poly.plane_[2] - poly.plane_[0]).normalized();
  poly.origin_ = poly.plane_[0];
  poly.corners_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool frozen = i == tri[0] || i == tri[1] || i == tri[2];
    const Vec3& p = points[i];
    poly.corners_.push_back(frozen ? p : Vec3(p - (p - poly.origin_).dot(poly.normal_) * poly.normal_));
  }

  poly.axis_u_ = (poly.plane_[1] - poly.plane_[0]).normalized();
  poly.axis_v_ = poly.normal_.cross(poly.axis_u_);
  poly.finish(points, source);
  return poly;
}

void CutPolygon::finish(const std::vector<Vec3>& points, const std::string& source) {
  const std::size_t n = corners_.size();
  const double d = diameter_;
  for (const Vec3& c : corners_) corners2d_.push_back(project(c));

  // Convex and simple: every turn is to the left (collinear allowed) and the
  // outline turns once around.
  double turning = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d e0 = corners2d_[(i + 1) % n] - corners2d_[i];
    const Eigen::Vector2d e1 = corners2d_[(i + 2) % n] - corners2d_[(i + 1) % n];
    const double c = cross2d(e0, e1);
    if (c < -1e-12 * d * d)
      throw InputError(source + ": not convex at corner " + std::to_string((i + 1) % n + 1) + " " +
                       format_point(points[(i + 1) % n]));
    turning += std::atan2(c, e0.dot(e1));
  }
  if (std::abs(turning - 2 * std::numbers::pi) > 1e-6)
    throw InputError(source + ": the outline crosses itself (not a simple convex polygon)");

  box_min_ = box_max_ = corners_[0];
  for (const Vec3& c : corners_) {
    box_min_ = box_min_.cwiseMin(c);
    box_max_ = box_max_.cwiseMax(c);
  }
}

CutPolygon CutPolygon::on_plane_of(const CutPolygon& plane, const std::vector<Vec3>& points,
                                   const std::string& source, const CutPolygonDef& def) {
  for (const Vec3& p : points)
    if (!p.allFinite()) throw InputError(source + ": a corner is not finite");
  CutPolygon poly;
  poly.plane_ = plane.plane_;
  poly.normal_ = plane.normal_;
  poly.origin_ = plane.origin_;
  poly.axis_u_ = plane.axis_u_;
  poly.axis_v_ = plane.axis_v_;
  std::vector<Eigen::Vector2d> flat;
  flat.reserve(points.size());
  double extent = 0;
  for (const Vec3& p : points) {
    flat.push_back(poly.project(p));
    extent = std::max(extent, (flat.back() - flat.front()).norm());
  }
  // The hull, counter-clockwise about the normal (axis_v_ = normal x axis_u_).
  flat = convex_hull_2d(std::move(flat), 1e-12 * extent * extent);
  const std::size_t n = flat.size();
  if (n < 3) throw InputError(source + ": fewer than 3 corners on the plane");
  for (const Eigen::Vector2d& q : flat) poly.corners_.push_back(poly.origin_ + q.x() * poly.axis_u_ + q.y() * poly.axis_v_);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      poly.diameter_ = std::max(poly.diameter_, (poly.corners_[i] - poly.corners_[j]).norm());
  double twice_area = 0;
  for (std::size_t i = 0; i < n; ++i) twice_area += cross2d(flat[i] - flat[0], flat[(i + 1) % n] - flat[0]);
  if (0.5 * twice_area < def.min_relative_area * poly.diameter_ * poly.diameter_)
    throw InputError(source + ": the corners are collinear on the plane (zero area)");
  poly.finish(poly.corners_, source);
  return poly;
}

Eigen::Vector2d CutPolygon::project(const Vec3& x) const {
  const Vec3 r = x - origin_;
  return {r.dot(axis_u_), r.dot(axis_v_)};
}

int CutPolygon::side(const Vec3& x) const { return orient3d_sign(plane_[0], plane_[1], plane_[2], x); }

double CutPolygon::signed_distance(const Vec3& x) const { return (x - origin_).dot(normal_); }

bool CutPolygon::box_may_touch_plane(const engine::Aabb& box, double slack) const {
  const Vec3 centre = box.center();
  const Vec3 half = 0.5 * (box.hi - box.lo) + Vec3::Constant(slack);
  const double reach = half.dot(normal_.cwiseAbs());  // the box's half-width along the normal
  // signed_distance and side() disagree by rounding only (normal_ is the
  // exact plane's, from the same corners): orders of magnitude below this.
  const double rounding = 1e-9 * ((centre - origin_).norm() + half.norm());
  return std::abs(signed_distance(centre)) <= reach + rounding;  // false for an empty box (NaN centre)
}

bool CutPolygon::box_projects_inside(const engine::Aabb& box, double slack) const {
  if (!(box.lo.array() <= box.hi.array()).all()) return false;  // empty
  const Vec3 lo = box.lo - Vec3::Constant(slack), hi = box.hi + Vec3::Constant(slack);
  // The box's projection is the hull of its corners' (the outline is
  // convex); each corner inside every edge's line by far more than the
  // rounding of project() and cross2d.
  const double rounding = 1e-9 * diameter_ * ((box.center() - origin_).norm() + (hi - lo).norm() + diameter_);
  const std::size_t n = corners2d_.size();
  for (int c = 0; c < 8; ++c) {
    const Vec3 x((c & 1) ? hi.x() : lo.x(), (c & 2) ? hi.y() : lo.y(), (c & 4) ? hi.z() : lo.z());
    const Eigen::Vector2d q = project(x);
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector2d& a = corners2d_[i];
      const Eigen::Vector2d& b = corners2d_[(i + 1) % n];
      if (cross2d(b - a, q - a) <= rounding) return false;
    }
  }
  return true;
}

engine::Aabb CutPolygon::box_beyond(const CutPolygon& inner) const {
  // The points inner does not cover are the union, over inner's edges, of
  // this polygon's part on the outer side of the edge's line. A part none
  // of whose corners lies beyond the line by more than rounding is passed
  // over: the edges the two outlines share (a part grown at its front
  // only) widen nothing.
  std::vector<Eigen::Vector2d> in;
  in.reserve(inner.corners_.size());
  for (const Vec3& x : inner.corners_) in.push_back(project(x));
  const std::size_t m = in.size(), n = corners2d_.size();
  double twice = 0;
  for (std::size_t i = 0; i < m; ++i) twice += cross2d(in[i], in[(i + 1) % m]);
  if (twice < 0) std::reverse(in.begin(), in.end());  // counter-clockwise in this frame
  engine::Aabb box;
  const auto extend = [&](const Eigen::Vector2d& q) { box.extend(origin_ + q.x() * axis_u_ + q.y() * axis_v_); };
  std::vector<double> d(n);  // (n) each corner's distance inside the edge's line, times its length
  for (std::size_t k = 0; k < m; ++k) {
    const Eigen::Vector2d& a = in[k];
    const Eigen::Vector2d e = in[(k + 1) % m] - a;
    double beyond = 0;
    for (std::size_t i = 0; i < n; ++i) beyond = std::min(beyond, d[i] = cross2d(e, corners2d_[i] - a));
    if (beyond >= -1e-9 * diameter_ * e.norm()) continue;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      if (d[i] <= 0) extend(corners2d_[i]);
      if ((d[i] < 0 && d[j] > 0) || (d[i] > 0 && d[j] < 0))
        extend(corners2d_[i] + (d[i] / (d[i] - d[j])) * (corners2d_[j] - corners2d_[i]));
    }
  }
  return box;
}

int CutPolygon::line_crossing(const Vec3& a, const Vec3& b) const {
  bool pos = false, neg = false, zero = false;
  const std::size_t n = corners_.size();
  for (std::size_t i = 0; i < n; ++i) {
    const int s = orient3d_sign(a, b, corners_[i], corners_[(i + 1) % n]);
    pos |= s > 0;
    neg |= s < 0;
    zero |= s == 0;
    if (pos && neg) return -1;
  }
  if (zero) return (pos || neg) ? 0 : -1;  // all zero: the line lies in the plane
  return 1;
}

int CutPolygon::segment_crossing(const Vec3& a, const Vec3& b, double da, double db) const {
  // The crossing point's error: the distances' (a few ulps of the ends'
  // offsets from the origin) over their gap, along the segment. Decide
  // only when the point clears the outline by 1e-8 of the scene's size and
  // the gap is not tiny, orders of magnitude above that error.
  const double gap = std::abs(da - db);
  const double offsets = (a - origin_).norm() + (b - origin_).norm();
  if ((da < 0) == (db < 0) || !(gap > 1e-6 * offsets)) return line_crossing(a, b);
  const Vec3 x = a + (da / (da - db)) * (b - a);
  const Eigen::Vector2d p = project(x);
  const double margin = 1e-8 * (diameter_ + (b - a).norm() + offsets);
  bool inside = true, outside = false;
  const std::size_t n = corners2d_.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& c = corners2d_[i];
    const Eigen::Vector2d e = corners2d_[(i + 1) % n] - c;
    const double distance = cross2d(e, p - c) / e.norm();  // positive inside (counter-clockwise)
    inside &= distance > margin;
    outside |= distance < -margin;
  }
  if (inside) return 1;
  if (outside) return -1;
  return line_crossing(a, b);
}

int CutPolygon::projects_inside(const Vec3& x) const {
  const Vec3 above = x + diameter_ * normal_;
  return line_crossing(x, above);
}

double CutPolygon::distance_outside(const Vec3& x) const {
  const Eigen::Vector2d p = project(x);
  const std::size_t n = corners2d_.size();
  bool inside = true;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = corners2d_[i];
    const Eigen::Vector2d& b = corners2d_[(i + 1) % n];
    const Eigen::Vector2d e = b - a;
    if (cross2d(e, p - a) < 0) inside = false;
    const double s = std::clamp((p - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + s * e - p).norm());
  }
  return inside ? 0.0 : best;
}

CutPolygon::Clip CutPolygon::clip(const Vec3& p, const Vec3& q) const {
  // Each edge's inner half-plane bounds the parameter from below (the
  // segment enters across it) or above (it leaves): Cyrus-Beck.
  const Eigen::Vector2d a = project(p);
  const Eigen::Vector2d dir = project(q) - a;
  const std::size_t n = corners2d_.size();
  Clip out;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& c = corners2d_[i];
    const Eigen::Vector2d e = corners2d_[(i + 1) % n] - c;
    const Eigen::Vector2d inward(-e.y(), e.x());
    const double f0 = inward.dot(a - c), slope = inward.dot(dir);
    out.starts_outside |= f0 < 0;
    if (slope > 0) {
      out.entry = std::max(out.entry, -f0 / slope);
    } else if (slope < 0) {
      if (f0 / -slope < out.exit) {
        out.exit = f0 / -slope;
        out.exit_edge = static_cast<int>(i);
      }
    } else if (f0 < 0) {
      out.misses = true;
    }
  }
  out.misses |= out.entry > out.exit;
  return out;
}

double CutPolygon::exit_parameter(const Vec3& p, const Vec3& q) const {
  const Clip c = clip(p, q);
  return c.starts_outside ? 0.0 : std::clamp(c.exit, 0.0, 1.0);
}

double CutPolygon::last_inside_parameter(const Vec3& p, const Vec3& q, int* edge) const {
  const Clip c = clip(p, q);
  if (edge) *edge = c.misses ? -1 : c.exit_edge;
  return c.misses ? 0.0 : std::clamp(c.exit, 0.0, 1.0);
}

int CutPolygon::edge_between(const Vec3& a, const Vec3& b) const {
  const double tolerance = 1e-9 * diameter_;
  const std::size_t n = corners_.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 &c = corners_[i], &d = corners_[(i + 1) % n];
    if (((c - a).norm() <= tolerance && (d - b).norm() <= tolerance) ||
        ((c - b).norm() <= tolerance && (d - a).norm() <= tolerance))
      return static_cast<int>(i);
  }
  return -1;
}

std::vector<CutPolygon> sweep_blade(const Vec3& a0, const Vec3& b0, const Vec3& a1, const Vec3& b1,
                                    const CutPolygonDef& def) {
  auto attempt = [&](const std::vector<Vec3>& pts) -> std::optional<CutPolygon> {
    try {
      return CutPolygon::from_points(pts, "blade sweep", def);
    } catch (const InputError&) {
      return std::nullopt;
    }
  };
  if (auto quad = attempt({a0, b0, b1, a1})) return {*quad};
  std::vector<CutPolygon> out;
  if (auto t = attempt({a0, b0, b1})) out.push_back(*t);
  if (auto t = attempt({a0, b1, a1})) out.push_back(*t);
  return out;
}

CutPolygon parse_cut_polygon(const std::string& text, const std::string& source, const CutPolygonDef& def) {
  std::vector<Vec3> corners;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(';', start), text.size());
    const std::string item = text.substr(start, end - start);
    const std::string where = source + ": corner " + std::to_string(corners.size() + 1) + " (\"" + item + "\")";
    if (std::count(item.begin(), item.end(), ',') != 2)
      throw InputError(where + " needs exactly 3 comma-separated coordinates");
    Vec3 p;
    std::size_t pos = 0;
    for (int k = 0; k < 3; ++k) {
      const std::size_t comma = k < 2 ? item.find(',', pos) : item.size();
      const std::string number = item.substr(pos, comma - pos);
      char* stop = nullptr;
      p[k] = std::strtod(number.c_str(), &stop);
      const bool blank_tail = std::string(stop).find_first_not_of(" \t") == std::string::npos;
      if (number.find_first_not_of(" \t") == std::string::npos || !blank_tail)
        throw InputError(where + ": \"" + number + "\" is not a number");
      pos = comma + 1;
    }
    corners.push_back(p);
    if (end == text.size()) break;
    start = end + 1;
  }
  return CutPolygon::from_points(corners, source, def);
}

}  // namespace mtcut::cut
