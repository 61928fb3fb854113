#include "cut/vertex_factory.h"

#include <stdexcept>

namespace mtcut::cut {

void VertexFactory::apply(engine::TetMesh& mesh) const {
  if (mesh.positions.size() != first_)
    throw std::logic_error("VertexFactory::apply: the mesh has " + std::to_string(mesh.positions.size()) +
                           " vertices, the factory started at " + std::to_string(first_));
  mesh.positions.reserve(first_ + made_.size());
  for (const MadeVertex& v : made_) mesh.positions.push_back(v.position);
}

}  // namespace mtcut::cut
