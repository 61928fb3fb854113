#pragma once
// The cut polygons of a scalpel stroke: the blade's per-frame sweeps merged
// into one planar convex polygon for each straight part of the stroke.
//
// Why merge instead of cutting every frame's thin sweep. Two consecutive
// sweeps share the blade segment of the frame between them exactly, so the
// second cut starts on the outline the first one stopped at: every tet along
// that segment is split partially by the first cut and again, through the
// points the first one made, by the second. Those points lie on the second
// polygon's plane only up to rounding, and the re-split pinches the mesh
// along the junction (an edge with both sides of the crack on it) at some
// resolution of the MT. One polygon per straight part has no junction: the
// MT cut stays a sequence of planar cuts, which the cutter does exactly, and
// it makes fewer tets (no re-split band every frame). The World still opens
// the incision every frame: it cuts the part in progress (current())
// provisionally and takes that cut back when the part grows
// (cut/mt/cut_retraction.h), so each tet is split once from its original.
//
// A part ends when the next blade pose leaves its plane (beyond
// `plane_tolerance` of its diameter) or would make the union of its sweeps
// non-convex (the convex hull larger than the swept area by more than
// `hull_excess`). The next part starts half a sweep back: at the pose midway
// between the part's last two, then its last pose, then the new one, so
// that no sweep between them is left uncut. Until its own sweeps (those
// after that overlap) cover more than `hull_excess` of the overlap, the part
// in progress has no polygon (current()), and a part that ends with no area
// of its own has none at all: a blade drawn out along itself after the turn
// sweeps no area, and its part's hull would be the overlap alone, tissue the
// ended part cut already, which the cutter would split again as a new crack
// meeting the old one. The cutter decides how the
// ended part meets the next one when it ends, from the next part's polygon
// then; a next part whose polygon comes later (its first sweeps under that
// share: a blade slowed forty times at the turn) starts a crack of its own
// there. What the cutter does at the
// turn is its own (TimeCriticalCutter::recut): at a gentle turn the next
// part starts exactly on the ended polygon's last blade edge and continues
// its crack across it (the overlap behind the edge is dropped); at a sharp
// one the two parts' cracks cross near the turn, each taken a little past
// the other.
//
// The part's plane. A part cut progressively commits the tets its polygon
// crosses completely, frame by frame (cut/mt/part_record.h), so its plane
// must not turn as poses are added. Once the part's polygon is
// `plane_width` wide, its plane is fixed: every later polygon of the part
// lies on it (CutPolygon::on_plane_of, the same exact plane), and the part
// also ends when a pose leaves it by more than `fixed_plane_tolerance`
// (looser than `plane_tolerance`: a part ending wherever a curving blade
// leaves the plane of its first poses multiplies the junctions between
// parts, each a bridge at coarse resolutions and a check for the cutter's
// guard). A stroke whose poses all come in one frame has the same parts and
// polygons.

#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "cut/cut_polygon.h"

namespace mtcut::cut {

struct StrokeSweepDef {
  double plane_tolerance = 0.02;  // of the part's diameter
  double hull_excess = 0.05;      // relative area the hull may exceed the sweeps by
  // The part's plane is fixed once its polygon is this wide (area over the
  // squared diameter; see "The part's plane" above).
  double plane_width = 0.05;
  double fixed_plane_tolerance = 0.06;  // of the part's diameter, from its fixed plane
};

// A pose of the scalpel's blade: base, tip, and whether it cuts.
struct BladePose {
  Vec3 base = Vec3::Zero(), tip = Vec3::Zero();
  bool engaged = false;
};

// What a frame's poses did to the stroke.
struct StrokeAdvance {
  std::vector<CutPolygon> ended;  // polygons of the parts that ended, in order
  // (ended) 1 where the blade turned back as that part ended: its heading
  // (the motion of the blade's middle, across the blade) turned by more
  // than 120 degrees, from the part's first pose to its last against the
  // last to the next. A V (over 135 degrees) keeps its two planes under 45
  // degrees apart, so only the heading tells it from a gentle turn
  // (TimeCriticalCutter::recut). Between 45 and 135 degrees a vertical
  // blade's plane turns as much as its heading, so the flag changes nothing
  // there: 120 leaves a V measured a little short (the heading of the last
  // step, not the leg's) flagged, and a small jitter of the blade at a
  // gentle turn's end unflagged.
  std::vector<std::uint8_t> turned_back;
  bool moved = false;             // the part in progress changed, or the stroke ended
  engine::Aabb swept;             // box of the blade's poses this frame and the one before them
};

class StrokeSweep {
 public:
  explicit StrokeSweep(const StrokeSweepDef& def = {}) : def_(def) {}

  // The blade (base, tip) at the next pose of an engaged stroke (the first
  // call starts the stroke). Returns the polygon of the part that ended, if
  // this pose turned the stroke.
  std::vector<CutPolygon> add(const Vec3& base, const Vec3& tip);
  // The stroke ended (the blade disengaged): the polygon of the last part.
  std::vector<CutPolygon> finish();
  // The poses of a frame in time order: engaged ones add to the stroke (the
  // first starts it), a disengaged one finishes an active stroke.
  StrokeAdvance advance(std::span<const BladePose> poses);
  // A stroke has begun and not finished.
  bool active() const { return !blades_.empty(); }
  // The polygon of the part in progress, its poses so far (nothing while
  // they sweep no area): what progressive cutting cuts provisionally every
  // frame until the part ends (cut/mt/cut_retraction.h).
  std::optional<CutPolygon> current() const;
  // The part in progress has its plane fixed: current() lies on it, now and
  // until the part ends.
  bool plane_fixed() const { return plane_.has_value(); }
  // Poses in the part in progress.
  std::size_t part_poses() const { return blades_.size(); }

 private:
  using Blade = std::pair<Vec3, Vec3>;
  // The part's polygon (the convex hull of its blades, on their plane), or
  // nothing when it sweeps no area.
  std::vector<CutPolygon> close_part();
  // The hull of `points` on their best plane, as a polygon (nothing when it
  // has no area).
  static std::vector<CutPolygon> polygon_of(const std::vector<Vec3>& points);
  // Would the part stay one planar convex polygon with `next` added?
  // `corners` receives the hull corners it would then have.
  bool extends(const Blade& next, std::vector<Vec3>& corners) const;
  void clear_part();
  // The area the part's sweeps cover after its overlap with the last part
  // (see the header).
  double own_area() const;
  // Adds a pose to an empty or two-pose part, no questions asked.
  void start_with(const Blade& blade);

  // Running sums over the part's blade ends (shifted by the first, against
  // cancellation): its best plane and its box in O(1) per pose.
  struct PartSums {
    Vec3 shift = Vec3::Zero(), sum = Vec3::Zero(), lo = Vec3::Zero(), hi = Vec3::Zero();
    Eigen::Matrix3d sum_outer = Eigen::Matrix3d::Zero();
    std::size_t n = 0;
    void add(const Vec3& p);
  };

  StrokeSweepDef def_;
  std::vector<Blade> blades_;  // the poses of the current part
  double swept_area_ = 0;      // sum of the areas its consecutive sweeps cover
  double overlap_area_ = 0;    // of those, the half sweep it starts with after a turn
  // Why these: a haptic stylus gives a pose per millisecond, so a part can
  // hold thousands; fitting and hulling all of them at every pose made a
  // stroke quadratic (0.15 ms per pose after 2,000). The plane comes from
  // the sums, the hull from its last corners and the new pose; only the
  // distance check and close_part() visit every pose.
  PartSums sums_;
  std::vector<Vec3> hull_corners_;  // the part's hull corners (its poses until a hull is taken)
  std::optional<CutPolygon> plane_;  // the part's fixed plane (its first polygon wide enough)
  bool turned_back_ = false;         // the blade turned back where add() last ended a part
  // The part's polygon over `points`, on its fixed plane once there is one.
  std::vector<CutPolygon> part_polygon(const std::vector<Vec3>& points) const;
};

// Area of the quad a blade sweeps between two poses (two triangles).
double sweep_area(const Vec3& a0, const Vec3& b0, const Vec3& a1, const Vec3& b1);

}  // namespace mtcut::cut
