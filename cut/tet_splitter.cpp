#include "cut/tet_splitter.h"

#include <algorithm>
#include <bitset>
#include <stdexcept>

#include "engine/tet_geometry.h"

namespace mtcut::cut {
namespace {

using engine::kTetEdges;
using engine::kTetFaces;

std::int8_t key_side(Label l) {
  switch (label_side(l)) {
    case LabelSide::kNeg: return -1;
    case LabelSide::kPos: return 1;
    default: return 0;
  }
}

std::array<VertId, 3> sorted_face(const Tet& tet, int f) {
  std::array<VertId, 3> face = {tet[kTetFaces[f][0]], tet[kTetFaces[f][1]], tet[kTetFaces[f][2]]};
  std::sort(face.begin(), face.end());
  return face;
}

MadeVertex from_face(const std::array<VertId, 3>& face, const CutClassifier::FacePoint& p) {
  MadeVertex s;
  s.position = p.position;
  for (int i = 0; i < 3; ++i) {
    s.parents[i] = face[i];
    s.weights[i] = p.weights[i];
  }
  return s;
}

}  // namespace

PointKey point_key(const Tet& tet, Label label) {
  PointKey key;
  const int i = label_index(label);
  switch (label_kind(label)) {
    case LabelKind::kVertex:
      key.kind = label_side(label) == LabelSide::kNeg ? PointKind::kVertexCopy : PointKind::kOriginal;
      key.side = key.kind == PointKind::kVertexCopy ? -1 : 0;
      key.ids[0] = tet[i].value;
      break;
    case LabelKind::kEdge: {
      const VertId a = tet[kTetEdges[i][0]], b = tet[kTetEdges[i][1]];
      key.kind = PointKind::kEdgePoint;
      key.side = key_side(label);
      key.ids[0] = std::min(a, b).value;
      key.ids[1] = std::max(a, b).value;
      break;
    }
    case LabelKind::kFace: {
      const auto face = sorted_face(tet, i);
      key.kind = label_side(label) == LabelSide::kNone ? PointKind::kFacePoint : PointKind::kFaceNode;
      key.side = key_side(label);
      for (int j = 0; j < 3; ++j) key.ids[j] = face[j].value;
      break;
    }
    case LabelKind::kCentre: {
      Tet sorted = tet;
      std::sort(sorted.begin(), sorted.end());
      key.kind = PointKind::kCentre;
      key.side = key_side(label);
      for (int j = 0; j < 4; ++j) key.ids[j] = sorted[j].value;
      break;
    }
  }
  return key;
}

MadeVertex edge_point_source(const Tet& tet, int edge, double t, std::span<const Vec3> positions) {
  const VertId lo = std::min(tet[kTetEdges[edge][0]], tet[kTetEdges[edge][1]]);
  const VertId hi = std::max(tet[kTetEdges[edge][0]], tet[kTetEdges[edge][1]]);
  MadeVertex s;
  const Vec3& plo = positions[lo.index()];
  s.position = plo + t * (positions[hi.index()] - plo);
  s.parents[0] = lo;
  s.parents[1] = hi;
  s.weights[0] = 1 - t;
  s.weights[1] = t;
  return s;
}

MadeVertex point_source(const Tet& tet, Label label, const CutClassifier& classifier, const SplitRecipe& recipe) {
  const auto positions = classifier.positions();
  const int i = label_index(label);
  MadeVertex s;
  switch (label_kind(label)) {
    case LabelKind::kVertex:
      return MadeVertex::at_vertex(tet[i], positions[tet[i].index()]);
    case LabelKind::kEdge:
      return edge_point_source(tet, i, classifier.crossing_parameter(tet[kTetEdges[i][0]], tet[kTetEdges[i][1]]),
                               positions);
    case LabelKind::kFace: {
      const auto face = sorted_face(tet, i);
      return from_face(face, label_side(label) == LabelSide::kNone ? classifier.face_point(face)
                                                                   : classifier.face_node(face));
    }
    case LabelKind::kCentre: {
      // The centroid of the cut surface's points, as weights on the tet.
      Tet sorted = tet;
      std::sort(sorted.begin(), sorted.end());
      for (int j = 0; j < 4; ++j) s.parents[j] = sorted[j];
      if (recipe.centre_of.empty()) throw std::logic_error("point_source: a centre without a cut surface");
      const double w = 1.0 / static_cast<double>(recipe.centre_of.size());
      for (Label l : recipe.centre_of) {
        const MadeVertex p = point_source(tet, l, classifier, recipe);
        s.position += w * p.position;
        for (int j = 0; j < 4; ++j)
          for (int k = 0; k < 4; ++k)
            if (p.parents[k].valid() && p.parents[k] == sorted[j]) s.weights[j] += w * p.weights[k];
      }
      return s;
    }
  }
  return s;
}

CutCase split_tet(const Tet& tet, const TetConfig& config, const CutClassifier& classifier, SplitTable& table,
                  VertexFactory& factory, std::vector<Tet>& out) {
  const SplitRecipe& recipe = table.recipe(config);
  std::array<VertId, kLabelCount> ids;
  std::bitset<kLabelCount> known;
  for (const auto& t : recipe.tets) {
    Tet made;
    for (int j = 0; j < 4; ++j) {
      const Label l = t[j];
      if (!known[l]) {
        ids[l] = factory.get(point_key(tet, l), [&] { return point_source(tet, l, classifier, recipe); });
        known[l] = true;
      }
      made[j] = ids[l];
    }
    out.push_back(made);
  }
  return recipe.kind;
}

}  // namespace mtcut::cut
