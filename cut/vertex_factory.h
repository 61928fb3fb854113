#pragma once
// Numbers the vertices one single-resolution cut makes (cut_mesh): a key
// (cut/made_vertex.h) asked for again gets the vertex made for it, whatever
// tet asks. One factory serves one cut (its keys are the cut's). Its list of
// made vertices, in id order, is the cut's change report for vertices.

#include <unordered_map>
#include <vector>

#include "cut/made_vertex.h"
#include "engine/tet_mesh.h"

namespace mtcut::cut {

class VertexFactory {
 public:
  // Ids are handed out from `first_id` on (the mesh's vertex count).
  explicit VertexFactory(std::size_t first_id) : next_(first_id), first_(first_id) {}

  // The vertex of `key`; `make()` (returning a MadeVertex's position,
  // parents and weights) is called only when a new vertex is needed; its
  // id, key and rest (its position: the mesh has one geometry) are set here.
  // Originals and positive vertex copies are the original vertex (ids[0]).
  template <class Make>
  VertId get(const PointKey& key, Make&& make) {
    if (key.kind == PointKind::kOriginal || (key.kind == PointKind::kVertexCopy && key.side > 0))
      return VertId(key.ids[0]);
    const auto it = index_.find(key);
    if (it != index_.end()) return it->second;
    const VertId id(static_cast<std::int32_t>(next_++));
    index_.emplace(key, id);
    MadeVertex& made = made_.emplace_back(make());
    made.id = id;
    made.key = key;
    made.rest = made.position;
    return id;
  }

  const std::vector<MadeVertex>& made() const { return made_; }
  std::size_t first_id() const { return first_; }
  // Appends the positions of the vertices made; the mesh must hold exactly
  // first_id() vertices.
  void apply(engine::TetMesh& mesh) const;

 private:
  std::size_t next_;
  std::size_t first_;
  std::unordered_map<PointKey, VertId, PointKeyHash> index_;
  std::vector<MadeVertex> made_;
};

}  // namespace mtcut::cut
