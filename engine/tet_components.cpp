#include "engine/tet_components.h"

#include "engine/union_find.h"

namespace mtcut::engine {

TetComponents tet_components(std::span<const Tet> tets, std::size_t num_vertices) {
  UnionFind sets(tets.size());
  std::vector<std::int32_t> owner(num_vertices, -1);  // the first tet using each vertex
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (VertId v : tets[t]) {
      std::int32_t& first = owner[v.index()];
      if (first < 0)
        first = static_cast<std::int32_t>(t);
      else
        sets.unite(first, static_cast<std::int32_t>(t));
    }
  // A set's representative is its first tet: numbering the roots in order
  // numbers the components by their first tet.
  TetComponents out;
  out.tet_component.resize(tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const std::int32_t root = sets.find(static_cast<std::int32_t>(t));
    if (root == static_cast<std::int32_t>(t)) {
      out.tet_component[t] = static_cast<std::int32_t>(out.tets.size());
      out.tets.push_back(0);
    } else {
      out.tet_component[t] = out.tet_component[static_cast<std::size_t>(root)];
    }
    ++out.tets[static_cast<std::size_t>(out.tet_component[t])];
  }
  return out;
}

}  // namespace mtcut::engine
