#pragma once
// A vertex a cut makes and where it comes from: the one record of it that
// both cutters write (cut_mesh through VertexFactory, the MT cutter through
// MtCut), the change reports carry (MeshCutResult::new_vertices,
// MtChangeReport::made_vertices) and the simulator reads to carry a
// particle's state across the cut (sim/state_transfer.h takes the made
// vertices as a span sorted by id).
//
// Why one record. A made vertex is an affine combination of its parents:
// its rest position, its deformed position, its velocity and any carried
// per-particle vector follow from theirs at the same weights. The key names
// it so that every tet asking for "the point on edge (a, b), negative side"
// gets the same vertex, whatever tet, fragment or resolution asks (DESIGN.md,
// "Vertices of the MT"):
//   edge point   (sorted global edge, side)     two per cut edge;
//   face point   (sorted global face)           where the cut ends in a face;
//   face node    (sorted global face, side)     1:17 only;
//   vertex copy  (vertex, side)                 a vertex the cut passes through:
//                                               the positive side keeps the
//                                               vertex, the negative gets a copy;
//   centre       (sorted global tet, side)      1:17 only, inside one tet.
// A split computes a point's position and parents before it knows whether
// the point is new; the factory that numbers it fills its id, key and rest.

#include <array>
#include <cstdint>

#include "engine/tet_mesh.h"

namespace mtcut::cut {

using engine::Vec3;
using engine::VertId;

enum class PointKind : std::uint8_t { kOriginal, kVertexCopy, kEdgePoint, kFacePoint, kFaceNode, kCentre };

struct PointKey {
  PointKind kind = PointKind::kOriginal;
  std::int8_t side = 0;                       // -1 / +1 for per-side points, 0 for single ones
  std::array<std::int32_t, 4> ids{-1, -1, -1, -1};  // sorted global ids of the vertex / edge / face / tet

  // Field by field (the defaulted == compares the ids through memcmp, a
  // call per probe of the cut's point map).
  bool operator==(const PointKey& o) const {
    return kind == o.kind && side == o.side && ids[0] == o.ids[0] && ids[1] == o.ids[1] && ids[2] == o.ids[2] &&
           ids[3] == o.ids[3];
  }
};

struct PointKeyHash {
  // Two multiplies over the ids packed in two words, then a mix (the hash
  // map takes its probe position and tag from different bits).
  std::size_t operator()(const PointKey& k) const noexcept {
    const auto word = [&](int i, int j) {
      return static_cast<std::uint64_t>(static_cast<std::uint32_t>(k.ids[i])) << 32 |
             static_cast<std::uint32_t>(k.ids[j]);
    };
    const std::uint64_t tag = static_cast<std::uint64_t>(k.kind) << 8 | static_cast<std::uint8_t>(k.side);
    std::uint64_t h = word(0, 1) * 0x9E3779B97F4A7C15ull ^ (word(2, 3) + tag) * 0xC2B2AE3D27D4EB4Full;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    return static_cast<std::size_t>(h ^ h >> 32);
  }
};

// position = sum weights[i] * position(parents[i]) over the valid parents,
// in the geometry the cut was computed on; rest likewise in rest space.
struct MadeVertex {
  VertId id;
  PointKey key;                       // what it is: edge point (edge, side), face point, vertex copy, ...
  std::array<VertId, 4> parents{};    // unused entries are none
  std::array<double, 4> weights{};
  Vec3 position = Vec3::Zero();       // where the cut put it (deformed when the MT cutter is given a geometry)
  Vec3 rest = Vec3::Zero();           // its rest position (the single-resolution cutter's one geometry: position)

  // The point at vertex v itself: one parent, weight 1.
  static MadeVertex at_vertex(VertId v, const Vec3& position) {
    MadeVertex m;
    m.parents[0] = v;
    m.weights[0] = 1;
    m.position = position;
    return m;
  }
  // sum weights[i] * at(parents[i]) over the valid parents, in that order.
  template <class At>
  Vec3 blend(At&& at) const {
    Vec3 p = Vec3::Zero();
    for (int i = 0; i < 4; ++i)
      if (parents[i].valid()) p += weights[i] * at(parents[i]);
    return p;
  }
};

}  // namespace mtcut::cut
