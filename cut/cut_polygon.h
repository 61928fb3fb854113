#pragma once
// The cut polygon: a planar convex polygon that one scalpel stroke sweeps
// (DESIGN.md, "Cutting"). It answers the cutter's geometric questions: on
// which side of its plane a point lies and whether a line passes through
// its inside, both exactly (orient3d on fixed corners), plus the
// floating-point measures that only place new points (distances, the exit
// of a segment from the polygon).
//
// Why corners are frozen at construction: every exact answer must be the
// same for every tet that asks (two tets sharing an edge must agree that it
// is cut), so the predicates use one fixed set of doubles. The plane is
// spanned by three corners kept bit-exact; the remaining corners are
// projected onto it once.

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/mt/bvh.h"
#include "engine/predicates.h"

namespace mtcut::cut {

using engine::Vec3;

struct CutPolygonDef {
  // Largest distance of a corner from the fitted plane, relative to the
  // polygon's diameter, before the input is rejected as not planar.
  double planarity_tolerance = 1e-6;
  // Area below this fraction of diameter^2 is "zero area".
  double min_relative_area = 1e-10;
};

class CutPolygon {
 public:
  // `points`: the corners in order (either orientation), at least 3. Throws
  // engine::InputError naming `source` for NaN/inf, fewer than 3 corners,
  // repeated corners, collinear corners (zero area), corners off the plane
  // beyond the tolerance, or a non-convex outline.
  static CutPolygon from_points(const std::vector<Vec3>& points, const std::string& source = "cut polygon",
                                const CutPolygonDef& def = {});
  // The convex hull of `points` projected onto `plane`'s plane, whose three
  // frozen corners it keeps bit-exact: every exact side() is `plane`'s (a
  // stroke's part cut progressively keeps one plane, cut/mt/part_record.h).
  // Throws engine::InputError when the hull has no area there.
  static CutPolygon on_plane_of(const CutPolygon& plane, const std::vector<Vec3>& points,
                                const std::string& source = "cut polygon", const CutPolygonDef& def = {});

  // (n) corners, counter-clockwise seen from the tip of normal().
  const std::vector<Vec3>& corners() const { return corners_; }
  std::size_t size() const { return corners_.size(); }
  const Vec3& normal() const { return normal_; }  // unit, from the corners' order
  // Both decide side() with the same three frozen corners, bit for bit.
  bool same_plane(const CutPolygon& o) const { return plane_ == o.plane_; }
  double diameter() const { return diameter_; }
  Vec3 box_min() const { return box_min_; }
  Vec3 box_max() const { return box_max_; }

  // Exact side of x: +1 on the side normal() points to, -1 behind, 0 on the plane.
  int side(const Vec3& x) const;
  // Approximate signed distance of x to the plane (positive on the normal's side).
  double signed_distance(const Vec3& x) const;
  // False only when every point within `slack` (along each axis) of `box`
  // lies on one side of the plane by far more than rounding, so that side()
  // is the same, nonzero, for all of them.
  bool box_may_touch_plane(const engine::Aabb& box, double slack = 0) const;
  // True only when every point within `slack` (along each axis) of `box`
  // projects strictly inside the outline by far more than rounding, so that
  // projects_inside() is +1 for all of them.
  bool box_projects_inside(const engine::Aabb& box, double slack = 0) const;
  // A box holding every point of this polygon that `inner`, a polygon of
  // the same plane, does not cover, up to rounding (empty when it covers
  // them all): where a grown polygon cuts what its former one did not.
  engine::Aabb box_beyond(const CutPolygon& inner) const;

  // Exact: does the line through a and b pass through the polygon?
  // +1 strictly inside, 0 through its outline, -1 outside (or parallel).
  int line_crossing(const Vec3& a, const Vec3& b) const;
  // line_crossing(a, b) for a segment whose ends lie at signed distances
  // da and db (signed_distance's, of opposite signs) from the plane: decided
  // in floating point when the crossing point lies inside or outside the
  // outline by far more than its rounding (the common case: no orient3d),
  // else exactly. The same answer as line_crossing (a filtered predicate).
  int segment_crossing(const Vec3& a, const Vec3& b, double da, double db) const;
  // Exact: +1 when x projects strictly inside, 0 onto the outline, -1 outside.
  int projects_inside(const Vec3& x) const;

  // Approximate distance from x's projection onto the plane to the polygon
  // (0 when it projects inside).
  double distance_outside(const Vec3& x) const;
  // Approximate: the largest s in [0, 1] with p + s (q - p) (projected) inside
  // the polygon, or 0 when p projects outside.
  double exit_parameter(const Vec3& p, const Vec3& q) const;
  // Approximate: the largest s in [0, 1] with p + s (q - p) (projected)
  // inside the polygon, wherever p projects, or 0 when the segment misses
  // it. `edge` (if given) receives the outline edge it leaves through (i:
  // corners i to i + 1), -1 when it does not leave.
  double last_inside_parameter(const Vec3& p, const Vec3& q, int* edge = nullptr) const;
  // The outline edge from corner i to i + 1 whose ends are a and b (either
  // order, within 1e-9 of the diameter), or -1.
  int edge_between(const Vec3& a, const Vec3& b) const;

 private:
  // The segment p -> q (projected) clipped to the polygon: its parameters
  // run inside over [entry, exit] (exit across outline edge exit_edge, -1
  // when it ends inside) unless it misses the polygon.
  struct Clip {
    double entry = 0.0, exit = 1.0;
    int exit_edge = -1;
    bool starts_outside = false;  // p projects outside
    bool misses = false;
  };
  Clip clip(const Vec3& p, const Vec3& q) const;
  Eigen::Vector2d project(const Vec3& x) const;
  // From the corners and the frame: the 2D outline (checked convex and
  // simple, `points` naming the corners in messages) and the box.
  void finish(const std::vector<Vec3>& points, const std::string& source);

  std::vector<Vec3> corners_;
  std::array<Vec3, 3> plane_;  // three corners, bit-exact, positively oriented with normal_
  Vec3 normal_ = Vec3::UnitZ();
  Vec3 origin_ = Vec3::Zero();
  Vec3 axis_u_ = Vec3::UnitX(), axis_v_ = Vec3::UnitY();  // in-plane frame
  std::vector<Eigen::Vector2d> corners2d_;                // (n) projected, counter-clockwise
  double diameter_ = 0;
  Vec3 box_min_ = Vec3::Zero(), box_max_ = Vec3::Zero();
};

// The surface a blade segment sweeps from pose 0 (a0-b0) to pose 1 (a1-b1):
// the quad (a0, b0, b1, a1) when it is planar and convex, else the two
// triangles (a0, b0, b1) and (a0, b1, a1); degenerate pieces (a blade that did
// not move, or moved along itself) are dropped, so the result may be empty.
std::vector<CutPolygon> sweep_blade(const Vec3& a0, const Vec3& b0, const Vec3& a1, const Vec3& b1,
                                    const CutPolygonDef& def = {});

// Counter-clockwise convex hull (monotone chain, exact on the given
// doubles), then without corners that are collinear with their neighbours
// to within `eps` (twice an area): the blade's poses along a straight
// stroke are collinear only up to rounding.
std::vector<Eigen::Vector2d> convex_hull_2d(std::vector<Eigen::Vector2d> points, double eps);

// Parses "x,y,z;x,y,z;..." into a polygon. Throws engine::InputError naming
// `source` (where the text came from: an option, a file, a scenario key) and
// the offending corner.
CutPolygon parse_cut_polygon(const std::string& text, const std::string& source, const CutPolygonDef& def = {});

}  // namespace mtcut::cut
