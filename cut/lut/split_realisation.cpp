#include "cut/lut/split_realisation.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "engine/tet_geometry.h"

namespace mtcut::cut {
namespace {

using engine::kTetEdges;
using engine::kTetFaces;
using engine::Vec3;

struct Choices {
  std::array<Vec3, 4> corners;
  std::array<double, 4> distance;        // to the plane, signed by side (0 on it)
  bool bent = false;                     // crossings and face points anywhere
  std::array<double, 6> edge_parameter;  // bent: where each crossing sits
  std::array<double, 4> face_parameter;  // planar: along each face's section segment
  std::array<std::array<double, 3>, 4> face_weights;  // bent: where each face point sits
};

LabelPositions realise(const TetConfig& c, const CutTrace& tr, const Choices& ch) {
  LabelPositions pos;
  pos.fill(Vec3::Constant(std::nan("")));
  auto set = [&](LabelKind kind, int index, const Vec3& p) {
    for (LabelSide s : {LabelSide::kNone, LabelSide::kNeg, LabelSide::kPos}) pos[make_label(kind, index, s)] = p;
  };
  const auto& p = ch.corners;
  std::array<Vec3, 6> crossing;
  for (int i = 0; i < 4; ++i) set(LabelKind::kVertex, i, p[i]);
  for (int k = 0; k < 6; ++k) {
    if (!c.straddles(k)) continue;
    const int a = kTetEdges[k][0], b = kTetEdges[k][1];
    const double t = ch.bent ? ch.edge_parameter[k] : ch.distance[a] / (ch.distance[a] - ch.distance[b]);
    crossing[k] = p[a] + t * (p[b] - p[a]);
    set(LabelKind::kEdge, k, crossing[k]);
  }
  for (int f = 0; f < 4; ++f) {
    if (!tr.face_point[f] && !tr.face_node[f]) continue;
    const auto& fv = kTetFaces[f];
    if (ch.bent) {
      const auto& w = ch.face_weights[f];
      set(LabelKind::kFace, f, w[0] * p[fv[0]] + w[1] * p[fv[1]] + w[2] * p[fv[2]]);
      continue;
    }
    std::vector<std::pair<Vec3, bool>> ends;  // (point, cut)
    for (int v : fv)
      if (is_on(c.vertex[v])) ends.push_back({p[v], c.vertex[v] == VertexState::kOnActive});
    for (int j = 0; j < 3; ++j) {
      const int k = edge_between(fv[j], fv[(j + 1) % 3]);
      if (c.straddles(k)) ends.push_back({crossing[k], c.edge_active(k)});
    }
    if (ends.size() != 2) throw std::logic_error("realise: a face point on a face the plane misses");
    if (!ends[0].second) std::swap(ends[0], ends[1]);
    const double s = tr.face_node[f] ? 0.5 : ch.face_parameter[f];
    set(LabelKind::kFace, f, ends[0].first + s * (ends[1].first - ends[0].first));
  }
  Vec3 centre = Vec3::Zero();
  for (Label l : tr.surface) centre += pos[l];
  set(LabelKind::kCentre, 0, centre / static_cast<double>(tr.surface.size()));
  return pos;
}

}  // namespace

LabelPositions reference_positions(const TetConfig& c, const CutTrace& tr) {
  Choices ch;
  ch.corners = {Vec3(0, 0, 0), Vec3(1.0, 0.1, 0.05), Vec3(0.15, 1.1, 0.1), Vec3(0.05, 0.2, 0.9)};
  for (int i = 0; i < 4; ++i)
    ch.distance[i] = c.vertex[i] == VertexState::kNeg ? -(0.8 + 0.17 * i)
                     : c.vertex[i] == VertexState::kPos ? 0.9 + 0.23 * i
                                                        : 0.0;
  ch.face_parameter.fill(0.4);
  return realise(c, tr, ch);
}

LabelPositions random_positions(const TetConfig& c, const CutTrace& tr, std::mt19937_64& rng, bool planar) {
  std::uniform_real_distribution<double> u(0, 1);
  Choices ch;
  do {
    for (auto& q : ch.corners) q = Vec3(u(rng), u(rng), u(rng));
  } while (engine::signed_volume(ch.corners[0], ch.corners[1], ch.corners[2], ch.corners[3]) < 0.02);
  for (int i = 0; i < 4; ++i)
    ch.distance[i] = c.vertex[i] == VertexState::kNeg ? -(0.05 + u(rng))
                     : c.vertex[i] == VertexState::kPos ? 0.05 + u(rng)
                                                        : 0.0;
  // Parameters anywhere in (0, 1), often near its ends, where a tet whose
  // orientation depends on them flips.
  auto parameter = [&] {
    const double r = u(rng);
    return r < 0.25 ? 0.001 * u(rng) + 1e-4 : r < 0.5 ? 1 - 1e-4 - 0.001 * u(rng) : 0.02 + 0.96 * u(rng);
  };
  if (planar) {
    // Face points sit at least face_clamp (>= 0.05) from their segment's ends.
    for (double& s : ch.face_parameter) s = 0.05 + 0.9 * u(rng);
  } else {
    ch.bent = true;
    for (double& t : ch.edge_parameter) t = parameter();
    for (auto& w : ch.face_weights) {
      double sum = 0;
      for (double& x : w) sum += x = parameter();
      for (double& x : w) x /= sum;
    }
  }
  return realise(c, tr, ch);
}

}  // namespace mtcut::cut
