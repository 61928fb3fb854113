#include "engine/tet_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

#include "engine/input_error.h"
#include "engine/radix_sort.h"
#include "engine/tet_adjacency.h"
#include "engine/tet_geometry.h"

namespace mtcut::engine {

std::array<Vec3, 4> TetMesh::corners(TetId t) const {
  const Tet& tet = tets[t.index()];
  return {position(tet[0]), position(tet[1]), position(tet[2]), position(tet[3])};
}

double TetMesh::volume(TetId t) const {
  const auto c = corners(t);
  return signed_volume(c[0], c[1], c[2], c[3]);
}

double TetMesh::total_volume() const {
  double sum = 0;
  for (std::size_t t = 0; t < tets.size(); ++t) sum += volume(TetId(t));
  return sum;
}

namespace {

// TetMesh::validate, with the adjacency built here unless `given`.
ValidationReport validate_mesh(const TetMesh& mesh, const TetAdjacency* given) {
  const auto& positions = mesh.positions;
  const auto& tets = mesh.tets;
  const auto corners = [&](TetId t) { return mesh.corners(t); };
  const auto position = [&](VertId v) { return mesh.position(v); };
  ValidationReport report;
  const auto nv = static_cast<std::int32_t>(positions.size());
  for (std::size_t v = 0; v < positions.size(); ++v)
    if (!positions[v].allFinite()) report.add("vertex " + std::to_string(v) + " has a non-finite position");

  bool ids_ok = true;
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const Tet& tet = tets[t];
    for (VertId v : tet) {
      if (v.value < 0 || v.value >= nv) {
        report.add("tet " + std::to_string(t) + " refers to vertex " + std::to_string(v.value) +
                   " (mesh has " + std::to_string(nv) + ")");
        ids_ok = false;
      }
    }
  }
  if (!ids_ok) return report;  // geometry checks would read out of range

  std::vector<std::array<std::int32_t, 4>> sorted(tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const Tet& tet = tets[t];
    const std::array<std::int32_t, 4> ids = {tet[0].value, tet[1].value, tet[2].value, tet[3].value};
    sorted[t] = ids;
    std::sort(sorted[t].begin(), sorted[t].end());
    if (std::adjacent_find(sorted[t].begin(), sorted[t].end()) != sorted[t].end()) {
      report.add("tet " + std::to_string(t) + " repeats a vertex");
      continue;
    }
    const auto c = corners(TetId(t));
    const int sign = orient3d_sign(c[0], c[1], c[2], c[3]);
    if (sign == 0) report.add("tet " + std::to_string(t) + " is degenerate (zero volume)");
    if (sign < 0) report.add("tet " + std::to_string(t) + " is negatively oriented");
  }

  // Duplicates: equal sorted ids, each reported against the first tet with them.
  std::vector<std::uint32_t> by_ids(tets.size());
  std::iota(by_ids.begin(), by_ids.end(), 0u);
  {
    std::vector<std::uint32_t> scratch;
    radix_sort<2>(by_ids, scratch, [&](std::uint32_t t) {
      const auto id = [&](int k) { return static_cast<std::uint64_t>(static_cast<std::uint32_t>(sorted[t][k])); };
      return std::array<std::uint64_t, 2>{id(0) << 32 | id(1), id(2) << 32 | id(3)};
    });
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicates;  // (later tet, first tet)
  for (std::size_t i = 1, first = 0; i < by_ids.size(); ++i) {
    if (sorted[by_ids[i]] != sorted[by_ids[first]]) first = i;
    else duplicates.emplace_back(by_ids[i], by_ids[first]);
  }
  std::sort(duplicates.begin(), duplicates.end());
  for (const auto& [t, first] : duplicates)
    report.add("tets " + std::to_string(first) + " and " + std::to_string(t) + " are duplicates");

  const TetAdjacency built = given ? TetAdjacency{} : build_adjacency(mesh);
  const TetAdjacency& adj = given ? *given : built;
  if (adj.non_manifold_faces > 0)
    report.add(std::to_string(adj.non_manifold_faces) + " faces are shared by more than two tets");
  // Two tets across a face must see it with opposite orientations.
  for (std::size_t t = 0; t < tets.size(); ++t) {
    for (int f = 0; f < 4; ++f) {
      const TetId u = adj.neighbors[t][f];
      if (!u.valid() || u.index() < t) continue;
      const auto mine = face_vertices(tets[t], f);
      const Tet& other = tets[u.index()];
      const VertId opposite = *std::find_if(other.begin(), other.end(), [&](VertId v) {
        return v != mine[0] && v != mine[1] && v != mine[2];
      });
      const auto c = std::array<Vec3, 4>{position(mine[0]), position(mine[1]), position(mine[2]), position(opposite)};
      if (orient3d_sign(c[0], c[1], c[2], c[3]) <= 0)
        report.add("tets " + std::to_string(t) + " and " + std::to_string(u.value) + " overlap across their shared face");
    }
  }
  // Manifold boundary: every boundary edge is used by exactly two boundary
  // faces, once in each direction.
  // The directed edges and, beside them, the same edges reversed, both
  // sorted: one walk counts each edge's uses in either direction.
  using Edge = std::pair<std::int32_t, std::int32_t>;
  std::vector<Edge> directed, reversed, scratch;
  directed.reserve(3 * adj.boundary.size());
  for (const auto& bf : adj.boundary)
    for (int k = 0; k < 3; ++k) directed.emplace_back(bf.verts[k].value, bf.verts[(k + 1) % 3].value);
  reversed.reserve(directed.size());
  for (const Edge& e : directed) reversed.emplace_back(e.second, e.first);
  const auto key = [](const Edge& e) {
    return std::array<std::uint64_t, 1>{static_cast<std::uint64_t>(static_cast<std::uint32_t>(e.first)) << 32 |
                                        static_cast<std::uint32_t>(e.second)};
  };
  radix_sort<1>(directed, scratch, key);
  radix_sort<1>(reversed, scratch, key);
  auto back = reversed.begin();
  for (auto it = directed.begin(); it != directed.end();) {
    const Edge edge = *it;
    const auto next = std::find_if(it, directed.end(), [&](const Edge& e) { return e != edge; });
    const auto count = next - it;
    it = next;
    // Uses of (second, first): the reversed list's entries equal to `edge`.
    while (back != reversed.end() && *back < edge) ++back;
    const auto reverse = std::find_if(back, reversed.end(), [&](const Edge& e) { return e != edge; }) - back;
    if (count != 1 || reverse != 1) {
      if (edge.first < edge.second || reverse == 0)
        report.add("boundary edge (" + std::to_string(edge.first) + ", " + std::to_string(edge.second) +
                   ") is not manifold (" + std::to_string(count) + " + " + std::to_string(reverse) + " faces)");
    }
  }
  return report;
}

}  // namespace

ValidationReport TetMesh::validate() const { return validate_mesh(*this, nullptr); }

ValidationReport TetMesh::validate(const TetAdjacency& adjacency) const { return validate_mesh(*this, &adjacency); }

TetMesh make_tet_mesh(std::vector<Vec3> positions, const std::vector<std::array<std::int64_t, 4>>& tets,
                      const std::string& source) {
  TetMesh mesh;
  mesh.positions = std::move(positions);
  const auto nv = static_cast<std::int64_t>(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    if (!mesh.positions[v].allFinite())
      throw InputError(source + ": vertex " + std::to_string(v) + " has a non-finite coordinate");
  mesh.tets.reserve(tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t) {
    Tet tet;
    for (int k = 0; k < 4; ++k) {
      const std::int64_t id = tets[t][k];
      if (id < 0 || id >= nv)
        throw InputError(source + ": tet " + std::to_string(t) + " refers to vertex " + std::to_string(id) +
                         ", but there are " + std::to_string(nv) + " vertices");
      tet[k] = VertId(static_cast<std::int32_t>(id));
    }
    const int sign = orient3d_sign(mesh.position(tet[0]), mesh.position(tet[1]), mesh.position(tet[2]),
                                   mesh.position(tet[3]));
    if (sign == 0) throw InputError(source + ": tet " + std::to_string(t) + " is degenerate (zero volume)");
    if (sign < 0) std::swap(tet[2], tet[3]);
    mesh.tets.push_back(tet);
  }
  return mesh;
}

std::size_t split_pinched_vertices(TetMesh& mesh) {
  const TetAdjacency adj = build_adjacency(mesh);
  // The tets around each vertex (CSR).
  std::vector<std::size_t> first(mesh.num_vertices() + 1, 0);
  for (const Tet& tet : mesh.tets)
    for (VertId v : tet) ++first[v.index() + 1];
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) first[v + 1] += first[v];
  std::vector<std::uint32_t> around(first.back());
  std::vector<std::size_t> fill(first.begin(), first.end() - 1);
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    for (VertId v : mesh.tets[t]) around[fill[v.index()]++] = static_cast<std::uint32_t>(t);

  std::size_t split = 0;
  std::vector<int> fan_of(mesh.num_tets(), -1);
  std::vector<std::uint32_t> stack;
  const std::size_t original_vertices = mesh.num_vertices();
  for (std::size_t v = 0; v < original_vertices; ++v) {
    const VertId vertex(static_cast<std::int32_t>(v));
    int fans = 0;
    // Fans: the tets around v joined across their faces through v.
    for (std::size_t i = first[v]; i < first[v + 1]; ++i) {
      if (fan_of[around[i]] >= 0) continue;
      const int fan = fans++;
      fan_of[around[i]] = fan;
      stack.push_back(around[i]);
      while (!stack.empty()) {
        const std::uint32_t t = stack.back();
        stack.pop_back();
        for (int f = 0; f < 4; ++f) {
          if (mesh.tets[t][f] == vertex) continue;  // the face opposite v does not hold it
          const TetId u = adj.neighbors[t][f];
          if (u.valid() && fan_of[u.index()] < 0) {
            fan_of[u.index()] = fan;
            stack.push_back(static_cast<std::uint32_t>(u.index()));
          }
        }
      }
    }
    // Every fan after the first takes a copy of v.
    if (fans > 1) ++split;
    std::vector<VertId> copy(static_cast<std::size_t>(fans), vertex);
    for (int fan = 1; fan < fans; ++fan) {
      copy[static_cast<std::size_t>(fan)] = VertId(static_cast<std::int32_t>(mesh.positions.size()));
      mesh.positions.push_back(mesh.positions[v]);
    }
    for (std::size_t i = first[v]; i < first[v + 1]; ++i) {
      const std::uint32_t t = around[i];
      for (VertId& w : mesh.tets[t])
        if (w == vertex) w = copy[static_cast<std::size_t>(fan_of[t])];
      fan_of[t] = -1;
    }
  }
  return split;
}

}  // namespace mtcut::engine
