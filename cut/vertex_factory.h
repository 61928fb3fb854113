#pragma once
// The vertices a cut makes, keyed so that every tet asking for "the point on
// edge (a, b), negative side" gets the same vertex, whatever tet, fragment or
// resolution asks (DESIGN.md, "Vertices of the MT"):
//   edge point   (sorted global edge, side)     two per cut edge;
//   face point   (sorted global face)           where the cut ends in a face;
//   face node    (sorted global face, side)     1:17 only;
//   vertex copy  (vertex, side)                 a vertex the cut passes through:
//                                               the positive side keeps the
//                                               vertex, the negative gets a copy;
//   centre       (sorted global tet, side)      1:17 only, inside one tet.
// One factory serves one cut (its keys are the cut's). Each vertex made is
// recorded with the vertices it interpolates and the weights, so rest and
// deformed positions, masses and velocities can follow: that list is the
// cut's change report for vertices.

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

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

// Where a new point is: position = sum weights[i] * position(parents[i]).
struct PointSource {
  Vec3 position = Vec3::Zero();
  std::array<VertId, 4> parents{};  // unused entries are none
  std::array<double, 4> weights{};
};

struct NewVertex {
  VertId id;
  PointKey key;
  PointSource source;
};

class VertexFactory {
 public:
  // Ids are handed out from `first_id` on (the mesh's vertex count).
  explicit VertexFactory(std::size_t first_id) : next_(first_id), first_(first_id) {}

  // The vertex of `key`; `make()` (returning a PointSource) is called only
  // when a new vertex is needed. Originals and positive vertex copies are
  // the original vertex (ids[0]).
  template <class Make>
  VertId get(const PointKey& key, Make&& make) {
    if (key.kind == PointKind::kOriginal || (key.kind == PointKind::kVertexCopy && key.side > 0))
      return VertId(key.ids[0]);
    const auto it = index_.find(key);
    if (it != index_.end()) return it->second;
    const VertId id(static_cast<std::int32_t>(next_++));
    index_.emplace(key, id);
    made_.push_back({id, key, make()});
    return id;
  }

  const std::vector<NewVertex>& made() const { return made_; }
  std::size_t first_id() const { return first_; }
  // Appends the positions of the vertices made; the mesh must hold exactly
  // first_id() vertices.
  void apply(engine::TetMesh& mesh) const;

 private:
  std::size_t next_;
  std::size_t first_;
  std::unordered_map<PointKey, VertId, PointKeyHash> index_;
  std::vector<NewVertex> made_;
};

}  // namespace mtcut::cut
