#include "cut/vertex_unpinch.h"

#include <algorithm>
#include <numeric>
#include <unordered_map>

#include "engine/union_find.h"

namespace mtcut::cut {

PinchFix find_pinches(const engine::TetMesh& mesh, const CutClassifier& cls, const std::vector<std::uint32_t>& nearby) {
  std::vector<std::uint8_t> split(mesh.num_vertices(), 0);
  bool any = false;
  for (VertId v : cls.on_vertices())
    if (cls.state(v) == VertexState::kOnActive) split[v.index()] = 1, any = true;
  PinchFix fix;
  if (!any) return fix;
  // Tets around each edge whose two ends are split.
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> around;
  for (std::uint32_t t : nearby) {
    const engine::Tet& tet = mesh.tets[t];
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (split[tet[a].index()] && split[tet[b].index()]) {
          const auto lo = static_cast<std::uint64_t>(std::min(tet[a], tet[b]).value);
          const auto hi = static_cast<std::uint64_t>(std::max(tet[a], tet[b]).value);
          around[lo << 32 | hi].push_back(t);
        }
  }
  for (const auto& [key, tets] : around) {
    const VertId a(static_cast<std::int32_t>(key >> 32)), b(static_cast<std::int32_t>(key & 0xffffffffu));
    // Each tet reaches the negative and/or positive side near the edge; tets
    // sharing a face (a, b, x) are neighbours around it.
    std::vector<std::array<VertId, 2>> others;
    std::vector<std::array<bool, 2>> reach;  // (negative, positive)
    for (std::uint32_t t : tets) {
      std::array<VertId, 2> o{};
      int n = 0;
      for (VertId v : mesh.tets[t])
        if (v != a && v != b) o[n++] = v;
      std::array<bool, 2> r = {false, false};
      double lean = 0;
      for (VertId v : o) {
        const VertexState s = cls.state(v);
        r[0] |= s == VertexState::kNeg;
        r[1] |= s == VertexState::kPos;
        lean += cls.polygon().signed_distance(cls.positions()[v.index()]);
      }
      if (!r[0] && !r[1]) r[lean < 0 ? 0 : 1] = true;
      others.push_back(o);
      reach.push_back(r);
    }
    for (int side = 0; side < 2; ++side) {
      const VertexState state = side == 0 ? VertexState::kNeg : VertexState::kPos;
      engine::UnionFind parts(tets.size());
      const auto find = [&](std::size_t x) { return static_cast<std::size_t>(parts.find(static_cast<std::int32_t>(x))); };
      // Two tets around the edge share a face (a, b, x). It joins their parts
      // on this side when x is on this side, or on the cut with both tets on
      // this side (then neither straddles, and both keep this side's copies).
      for (std::size_t i = 0; i < tets.size(); ++i)
        for (std::size_t j = i + 1; j < tets.size(); ++j)
          for (VertId x : others[i]) {
            if (x != others[j][0] && x != others[j][1]) continue;
            if (!reach[i][side] || !reach[j][side]) continue;
            if (cls.state(x) == state || is_on(cls.state(x)))
              parts.unite(static_cast<std::int32_t>(i), static_cast<std::int32_t>(j));
          }
      std::unordered_map<std::size_t, std::size_t> size;  // component -> tets
      for (std::size_t i = 0; i < tets.size(); ++i)
        if (reach[i][side]) ++size[find(i)];
      if (size.size() < 2) continue;
      // Keep the largest part on this side; the tets of the others reach it
      // through vertices near the plane: pull those onto the cut if they are
      // near enough, else keep the edge's ends off it.
      std::size_t keep = size.begin()->first;  // the largest, ties to the smallest root (not the map's order)
      for (const auto& [root, n] : size)
        if (n > size[keep] || (n == size[keep] && root < keep)) keep = root;
      std::vector<VertId> pull;
      bool near = true;
      for (std::size_t i = 0; i < tets.size() && near; ++i) {
        if (!reach[i][side] || find(i) == keep) continue;
        for (VertId x : others[i]) {
          if (cls.state(x) != state) continue;
          const engine::Vec3& px = cls.positions()[x.index()];
          const double gap = std::abs(cls.polygon().signed_distance(px));
          near &= gap <= 4 * cls.snap() * (px - cls.positions()[a.index()]).norm() && !cls.veto_requested(x);
          pull.push_back(x);
        }
      }
      if (near && !pull.empty()) {
        fix.pull_in.insert(fix.pull_in.end(), pull.begin(), pull.end());
      } else {
        fix.veto.push_back(a);
        fix.veto.push_back(b);
      }
      break;
    }
  }
  return fix;
}

std::size_t unpinch_vertices(engine::TetMesh& mesh, std::span<const VertId> candidates,
                             const std::vector<std::uint32_t>& nearby, std::vector<MadeVertex>& made,
                             std::vector<engine::TetId>& changed) {
  const std::size_t first_made = made.empty() ? mesh.num_vertices() : made.front().id.index();
  std::vector<std::int32_t> slot(mesh.num_vertices(), -1);
  std::vector<VertId> vertices;
  for (VertId v : candidates)
    if (slot[v.index()] < 0) {
      slot[v.index()] = static_cast<std::int32_t>(vertices.size());
      vertices.push_back(v);
    }
  std::vector<std::vector<std::uint32_t>> star(vertices.size());
  for (std::uint32_t t : nearby)
    for (VertId v : mesh.tets[t])
      if (slot[v.index()] >= 0) star[static_cast<std::size_t>(slot[v.index()])].push_back(t);

  std::size_t copies = 0;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const VertId v = vertices[i];
    const auto& tets = star[i];
    if (tets.size() < 2) continue;
    // Tets around v are joined through faces holding v: key them by the
    // face's two other vertices.
    engine::UnionFind parts(tets.size());
    const auto find = [&](std::size_t x) { return static_cast<std::size_t>(parts.find(static_cast<std::int32_t>(x))); };
    std::unordered_map<std::uint64_t, std::size_t> first_with;
    for (std::size_t j = 0; j < tets.size(); ++j) {
      const engine::Tet& tet = mesh.tets[tets[j]];
      for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b) {
          if (tet[a] == v || tet[b] == v) continue;
          const auto lo = static_cast<std::uint64_t>(std::min(tet[a], tet[b]).value);
          const auto hi = static_cast<std::uint64_t>(std::max(tet[a], tet[b]).value);
          const auto [it, fresh] = first_with.emplace(lo << 32 | hi, j);
          if (!fresh) parts.unite(static_cast<std::int32_t>(j), static_cast<std::int32_t>(it->second));
        }
    }
    // The part of the first tet keeps v; every other part gets a copy.
    std::unordered_map<std::size_t, VertId> copy_of;
    const std::size_t keep = find(0);
    for (std::size_t j = 0; j < tets.size(); ++j) {
      const std::size_t root = find(j);
      if (root == keep) continue;
      auto [it, fresh] = copy_of.emplace(root, VertId());
      if (fresh) {
        const bool of_made = v.index() >= first_made && v.index() - first_made < made.size();
        MadeVertex copy = of_made ? made[v.index() - first_made]  // a copy of a new vertex: its parents
                                  : MadeVertex::at_vertex(v, mesh.positions[v.index()]);
        copy.id = VertId(mesh.num_vertices());
        copy.key = PointKey{PointKind::kVertexCopy, 0, {v.value, static_cast<std::int32_t>(copy_of.size()), -1, -1}};
        copy.rest = copy.position;
        mesh.positions.push_back(mesh.positions[v.index()]);
        made.push_back(copy);
        it->second = copy.id;
        ++copies;
      }
      for (VertId& w : mesh.tets[tets[j]])
        if (w == v) w = it->second;
      changed.push_back(engine::TetId(static_cast<std::size_t>(tets[j])));
    }
  }
  return copies;
}

}  // namespace mtcut::cut
