#pragma once
// The crack a scalpel stroke has made so far: its polygons' junctions and
// the side of every vertex its cuts made, so that the next polygon continues
// it across the junction with the last (cut/stroke_junction.h) instead of
// cutting it again. The time-critical cutter keeps one for the stroke in
// progress: a stroke's straight parts meet at a gentle turn on a shared edge
// (TimeCriticalCutter::recut); a test cuts each step's quad this way.

#include <optional>
#include <span>
#include <vector>

#include "cut/cut_polygon.h"
#include "cut/mt/mt_change_report.h"
#include "cut/stroke_junction.h"
#include "engine/mt/mt.h"
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
  // The same where the blade does not end on `next`'s outline (no leading
  // edge): a part's cut in progress, a stroke's last polygon.
  CutContinuation continuation(const CutPolygon& next);
  // A cut of the stroke, with every vertex it made (all the reports of its
  // calls, for a cut spread over frames or committed frame by frame). A
  // polygon that does not continue the last one starts a new crack.
  void record(const CutPolygon& polygon, std::span<const MadeVertex> made);
  // The MT was compacted (Mt::compact): ids follow; dropped vertices leave.
  void renumber(const engine::Mt::Compaction& compaction);
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

  CutContinuation continuation_with(const CutPolygon& next, int leading_edge);
};

}  // namespace mtcut::cut
