#include "cut/vertex_factory.h"

#include <stdexcept>

namespace mtcut::cut {

std::size_t PointKeyHash::operator()(const PointKey& k) const noexcept {
  std::uint64_t h = static_cast<std::uint64_t>(k.kind) * 0x9E3779B97F4A7C15ull ^
                    static_cast<std::uint64_t>(static_cast<std::uint8_t>(k.side));
  for (std::int32_t id : k.ids) {
    h ^= static_cast<std::uint32_t>(id) + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    h *= 0xBF58476D1CE4E5B9ull;
  }
  return static_cast<std::size_t>(h ^ (h >> 31));
}

void VertexFactory::apply(engine::TetMesh& mesh) const {
  if (mesh.positions.size() != first_)
    throw std::logic_error("VertexFactory::apply: the mesh has " + std::to_string(mesh.positions.size()) +
                           " vertices, the factory started at " + std::to_string(first_));
  mesh.positions.reserve(first_ + made_.size());
  for (const NewVertex& v : made_) mesh.positions.push_back(v.source.position);
}

}  // namespace mtcut::cut
