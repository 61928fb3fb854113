#pragma once
// A cut that continues the previous cut of the same stroke across the edge
// they share (the junction): a scalpel stroke cut step by step, each step the
// polygon the blade swept since the last, as a haptic loop feeds the cutter.
//
// Why a step cannot be cut as a lone polygon. Three things go wrong where
// two steps meet (each seen on the builtin ellipsoid and the liver):
//  1. Sides. The vertices the last step made lie in its plane. When the
//     stroke turns, the next plane passes a little off them, on the side of
//     the turn, not on the side of the crack they belong to; when it goes
//     straight, on the plane, sided by rounding. A tet on one side of the
//     crack then looks crossed by the next cut and is split again, and the
//     two sides of the crack end up sharing an edge (a non-manifold
//     boundary) or a flat tet.
//  2. Fronts. Where a cut's outline crosses a tet, the crack ends at face
//     points, which the classifier keeps at least face_clamp (1/4) of their
//     face's section from its ends: up to a quarter of a coarse tet behind
//     or ahead of the outline. The next step, starting on the outline, passes
//     by them and leaves a bridge.
//  3. Resolutions. Every resolution of the MT must cut the same surface. A
//     front off the junction line is on the last plane, not the next one, so
//     continuing the crack from it bends the surface differently in each
//     resolution (a fragment's parts change volume).
// So a step that continues a stroke is classified against the stroke's
// sheet, not its own plane alone:
//  - ahead of the junction (the side of a dividing plane through it that
//    bisects the two polygons' angle, where the two planes agree up to
//    rounding near the junction) vertices are sided by its own plane;
//  - behind it, a vertex an earlier step made (an edge point's copy, a
//    vertex copy, and the vertex that kept its id) is on the side of the
//    crack it was made for, and is never snapped onto the cut; any other
//    vertex is sided by the plane of the stroke's polygon it lies behind
//    (the one between the two junctions it lies between);
//  - the front the earlier steps left on the junction is split (pulled onto
//    the cut), and the crack goes on from it through the polygon;
//  - face points on the polygon's leading edge (where the blade ends this
//    step, where the next one starts) are put exactly where the outline
//    leaves their faces, on the line both planes hold, in every resolution
//    alike; elsewhere (the blade's tip inside the tissue) they keep the
//    clamp, as the crack's lasting outline;
//  - the rest of the front that lies on the sheet is where the crack ends:
//    on the cut but not split (kOnInactive), so no cut point is made beside
//    it (rounding would side it, and a split among such points on the sheet
//    made flat tets).
// What is covered (cut) is still the polygon's alone: an edge must cross its
// plane inside it. Behind the junction nothing is cut again.
//
// Known limits (tests/cut/mt/scalpel_steps_test.cpp, the DISABLED tests):
// turns of tens of degrees per step leave tets straddling the sheet behind
// the junction and not the new plane, whose cut differs between resolutions;
// and some strokes with the tip inside the tissue in steps far shorter than
// the coarse tets still break the coarsest frontier (ellipsoid) or make a
// flat tet (box).

#include <array>
#include <cstdint>
#include <optional>
#include <span>

#include "absl/container/flat_hash_map.h"
#include "cut/cut_polygon.h"
#include "engine/ids.h"

namespace mtcut::cut {

// The side of the stroke's crack each vertex its cuts made is on (+1 / -1),
// keyed by vertex id: filled by the caller from each cut's change report.
using CrackSides = absl::flat_hash_map<std::int32_t, std::int8_t>;

class StrokeJunction {
 public:
  // The junction of `previous` and `next` when an edge of `next` is an edge
  // of `previous` (CutPolygon::edge_between) and the two face the same way
  // (their normals' dot product positive: the stroke goes on, it does not
  // fold back); else nothing.
  static std::optional<StrokeJunction> between(const CutPolygon& previous, const CutPolygon& next);

  // Exact: +1 when x is on the next polygon's side of the dividing plane, -1
  // on the previous one's, 0 on it.
  int ahead(const engine::Vec3& x) const;
  const CutPolygon& previous() const { return previous_; }

 private:
  StrokeJunction(const CutPolygon& previous, const std::array<engine::Vec3, 3>& divider)
      : previous_(previous), divider_(divider) {}

  CutPolygon previous_;
  std::array<engine::Vec3, 3> divider_;  // the dividing plane, positively oriented toward `next`
};

// A face point an earlier step of the stroke made and no step split yet:
// where its crack ends, inside `face`.
struct CrackFrontPoint {
  engine::VertId id;
  std::array<engine::VertId, 3> face;
};

// What a step of a stroke is cut with (cut/mt/stroke_crack.h makes it; it
// must outlive the cut's search).
struct CutContinuation {
  // The stroke's junctions, oldest first, the last one between the previous
  // polygon and this step's; empty for the first step of a crack.
  std::span<const StrokeJunction> junctions;
  const CrackSides* sides = nullptr;  // the sides of the vertices the earlier steps made
  // The earlier steps' front. Those on the junction (on this step's
  // polygon, to kMinSnap of their face's longest edge) are split.
  std::span<const CrackFrontPoint> front;
  // This step's leading edge: the outline edge of its polygon where the
  // blade ends (CutPolygon::edge_between), -1 when none.
  int leading_edge = -1;

  const StrokeJunction& last() const { return junctions.back(); }
  // The polygon of the stroke that sides x when x is behind the last
  // junction: the one between the two junctions x lies between (the first
  // polygon when x is behind them all).
  const CutPolygon& polygon_behind(const engine::Vec3& x) const;
};

}  // namespace mtcut::cut
