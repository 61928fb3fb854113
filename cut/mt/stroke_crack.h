#pragma once
// The crack a scalpel stroke cut step by step has made so far: its polygons'
// junctions and the side of every vertex its cuts made, so that the next step
// continues it across the junction with the last (cut/stroke_junction.h)
// instead of cutting it again.

#include <optional>
#include <vector>

#include "cut/cut_polygon.h"
#include "cut/mt/mt_change_report.h"
#include "cut/stroke_junction.h"
#include "engine/validation.h"

namespace mtcut::cut {

class StrokeCrack {
 public:
  // What the cut of `next`, the stroke's next step, is given: the junctions
  // when `next` starts at the last recorded polygon's edge (else none: the
  // first step of a crack), the crack's sides and front, and `next`'s
  // leading edge, the blade (base, tip) where this step ends. The result
  // points into this crack: call nothing else while it is in use.
  CutContinuation continuation(const CutPolygon& next, const Vec3& blade_base, const Vec3& blade_tip);
  // A cut of the stroke, with everything it changed (all the reports of its
  // calls, for a cut spread over frames). A polygon that does not continue
  // the last one starts a new crack.
  void record(const CutPolygon& polygon, const MtChangeReport& report);
  // The stroke ended: the next cut starts a new crack.
  void clear();

  std::size_t num_sided() const { return sides_.size(); }         // vertices sided so far
  std::size_t num_junctions() const { return junctions_.size(); }  // recorded ones

  // Sides are +1 / -1, no front point is sided (a split one left the
  // front), and a crack with no recorded cut holds nothing.
  engine::ValidationReport validate() const;

 private:
  std::optional<CutPolygon> last_;
  // Between the stroke's consecutive polygons, oldest first, then (while a
  // continuation is out) the one to the polygon being cut.
  std::vector<StrokeJunction> junctions_;
  bool tentative_ = false;  // junctions_.back() is continuation()'s, not recorded yet
  CrackSides sides_;
  std::vector<CrackFrontPoint> front_;  // the last cut's face points
};

}  // namespace mtcut::cut
