#include "cut/mt/stroke_crack.h"

#include <string>

namespace mtcut::cut {

CutContinuation StrokeCrack::continuation(const CutPolygon& next, const Vec3& blade_base, const Vec3& blade_tip) {
  return continuation_with(next, next.edge_between(blade_base, blade_tip));
}

CutContinuation StrokeCrack::continuation(const CutPolygon& next) { return continuation_with(next, -1); }

CutContinuation StrokeCrack::continuation_with(const CutPolygon& next, const int leading) {
  if (tentative_) junctions_.pop_back();
  tentative_ = false;
  std::optional<StrokeJunction> junction;
  if (last_) junction = StrokeJunction::between(*last_, next);
  if (!junction) return CutContinuation{{}, nullptr, {}, leading};  // the first step of a crack
  junctions_.push_back(*junction);
  tentative_ = true;
  return CutContinuation{junctions_, &sides_, front_, leading};
}

void StrokeCrack::record(const CutPolygon& polygon, std::span<const MadeVertex> made_vertices) {
  if (tentative_) junctions_.pop_back();
  tentative_ = false;
  std::optional<StrokeJunction> junction;
  if (last_) junction = StrokeJunction::between(*last_, polygon);
  if (junction) {
    junctions_.push_back(*junction);
  } else {  // a new crack
    junctions_.clear();
    sides_.clear();
    front_.clear();
  }
  last_ = polygon;
  for (const MadeVertex& made : made_vertices) {
    if (made.key.kind == PointKind::kFacePoint) {  // where the crack ends, on no side
      front_.push_back({made.id, {VertId(made.key.ids[0]), VertId(made.key.ids[1]), VertId(made.key.ids[2])}});
      continue;
    }
    if (made.key.side == 0) continue;
    sides_[made.id.value] = made.key.side;
    // A vertex the cut passed through keeps its id on the positive side.
    if (made.key.kind == PointKind::kVertexCopy) sides_[made.key.ids[0]] = 1;
  }
  // A face point this or an earlier cut of the stroke split is part of the
  // crack now, no longer its front.
  std::erase_if(front_, [&](const CrackFrontPoint& f) { return sides_.contains(f.id.value); });
}

engine::ValidationReport StrokeCrack::validate() const {
  engine::ValidationReport report;
  for (const auto& [id, side] : sides_)
    if (side != 1 && side != -1)
      report.add("StrokeCrack: vertex " + std::to_string(id) + " has side " + std::to_string(side));
  for (const CrackFrontPoint& f : front_)
    if (sides_.contains(f.id.value))
      report.add("StrokeCrack: front point " + std::to_string(f.id.value) + " is sided (it was split)");
  if (tentative_ && junctions_.empty()) report.add("StrokeCrack: a continuation is out with no junction");
  if (!last_ && (!junctions_.empty() || !sides_.empty() || !front_.empty()))
    report.add("StrokeCrack: no cut recorded, but junctions, sides or a front are held");
  return report;
}

void StrokeCrack::renumber(const engine::Mt::Compaction& compaction) {
  const auto map = [&](std::int32_t id) {
    return id >= 0 && static_cast<std::size_t>(id) < compaction.vertex_map.size() ? compaction.vertex_map[id] : -1;
  };
  CrackSides sides;
  sides.reserve(sides_.size());
  for (const auto& [id, side] : sides_)
    if (const std::int32_t to = map(id); to >= 0) sides.emplace(to, side);
  sides_ = std::move(sides);
  std::vector<CrackFrontPoint> front;
  for (const CrackFrontPoint& f : front_) {
    CrackFrontPoint g{VertId(map(f.id.value)), {}};
    bool kept = g.id.valid();
    for (int i = 0; i < 3; ++i) {
      g.face[i] = VertId(map(f.face[i].value));
      kept = kept && g.face[i].valid();
    }
    if (kept) front.push_back(g);
  }
  front_ = std::move(front);
}

void StrokeCrack::clear() {
  last_.reset();
  junctions_.clear();
  tentative_ = false;
  sides_.clear();
  front_.clear();
}

}  // namespace mtcut::cut
