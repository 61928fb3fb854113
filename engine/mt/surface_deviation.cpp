#include "engine/mt/surface_deviation.h"

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include "engine/mt/triangle_index.h"

namespace mtcut::engine {
namespace {

// The outer surface of a level: the faces of its live tets no other of them shares.
std::vector<Triangle> surface_of(const Mt& mt, std::span<const TetId> level) {
  std::vector<TetId> live;
  live.reserve(level.size());
  for (TetId t : level)
    if (mt.alive(t)) live.push_back(t);
  std::vector<Triangle> out;
  for (const OrientedFace& f : outer_faces(mt, live))
    out.push_back({mt.position(f.verts[0]), mt.position(f.verts[1]), mt.position(f.verts[2])});
  return out;
}

// The largest distance from a sample of `from` to the surface `to`.
double one_sided(const std::vector<Triangle>& from, const TriangleIndex& to) {
  double worst = 0.0;
  for (const Triangle& t : from) {
    const std::array<Vec3, 7> samples{t[0], t[1], t[2], 0.5 * (t[0] + t[1]), 0.5 * (t[1] + t[2]),
                                      0.5 * (t[2] + t[0]), (t[0] + t[1] + t[2]) / 3.0};
    for (const Vec3& p : samples) worst = std::max(worst, to.distance(p, std::numeric_limits<double>::infinity(), worst));
  }
  return worst;
}

}  // namespace

double coarsest_surface_deviation(const Mt& mt) {
  if (!mt.root().valid() || !mt.drain().valid() || mt.boundary_preserved()) return 0.0;
  std::vector<Triangle> finest = surface_of(mt, mt.created(mt.root()));
  std::vector<Triangle> coarsest = surface_of(mt, mt.replaced(mt.drain()));
  if (finest.empty() || coarsest.empty()) return 0.0;
  const double to_finest = one_sided(coarsest, TriangleIndex(finest));
  return std::max(to_finest, one_sided(finest, TriangleIndex(coarsest)));
}

}  // namespace mtcut::engine
