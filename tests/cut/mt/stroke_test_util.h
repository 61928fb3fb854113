#pragma once
// Scalpel strokes for the stroke tests: a blade path and the stroke cut at
// once (all its poses in one frame: each straight part cut once, at its end).

#include <functional>
#include <vector>

#include "cut/mt/stroke_cutter.h"
#include "tests/cut/mt/mt_cut_test_util.h"

namespace mtcut::test {

// The blade at s in [0, 1] along the stroke.
using Path = std::function<cut::BladePose(double s)>;

// The cutter of the stroke tests: each cut whose search is narrowed to a
// part's front and growth is checked against a walk of its whole polygon
// (MtCutDef::check_search).
inline cut::TimeCriticalCutterDef checked_cutter() {
  cut::TimeCriticalCutterDef def;
  def.cut.check_search = true;
  return def;
}

inline Mt cut_at_once(const Mt& original, const Path& path, int steps) {
  Mt mt = original;
  engine::TetBvh bvh(mt);
  Frontier frontier = Frontier::coarsest(mt);
  cut::StrokeSweep stroke;
  cut::TimeCriticalCutter cutter(checked_cutter());
  std::vector<cut::BladePose> poses;
  for (int k = 0; k <= steps; ++k) poses.push_back(path(static_cast<double>(k) / steps));
  cut::BladePose away = poses.back();
  away.engaged = false;
  poses.push_back(away);
  cut::cut_stroke_step(stroke, cutter, mt, bvh, frontier, poses);
  return mt;
}

}  // namespace mtcut::test
