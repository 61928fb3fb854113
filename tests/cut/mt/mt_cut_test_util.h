#pragma once
// MTs, random cut polygons and checks shared by the MT cut tests.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "cut/cut_polygon.h"
#include "cut/mt/mt_cut.h"
#include "engine/mesh_loader.h"
#include "engine/mt/frontier.h"
#include "engine/mt/mt.h"
#include "engine/mt/mt_builder.h"
#include "engine/mt/mt_presets.h"
#include "engine/mt/selective_refinement.h"
#include "engine/tet_geometry.h"
#include "tests/test_paths.h"

namespace mtcut::test {

using cut::CutPolygon;
using engine::FragId;
using engine::Frontier;
using engine::Mt;
using engine::TetId;
using engine::Vec3;
using engine::VertId;

// "ellipsoid" (builtin, ~1.5k tets, boundary preserved), "liver"
// (liver.msh, boundary preserved), "paper" (the paper preset, ~35k tets,
// surface simplified). Built once per test binary run.
inline const Mt& cut_test_mt(const std::string& name) {
  static std::map<std::string, Mt> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  if (name == "paper") {
    const auto preset = engine::find_mt_preset("paper");
    const auto mesh = engine::load_mesh(preset->mesh_spec, preset->mesh).mesh;
    return cache.emplace(name, engine::build_mt(mesh, preset->build)).first->second;
  }
  engine::MeshLoadDef def;
  def.builtin_tets = 1500;
  const std::string spec = name == "liver" ? shared_mesh("liver.msh") : "builtin:" + name;
  const auto mesh = engine::load_mesh(spec, def).mesh;
  return cache.emplace(name, engine::build_mt(mesh, engine::MtBuildOptions{})).first->second;
}

inline engine::Aabb mt_box(const Mt& mt) {
  engine::Aabb box;
  for (const Vec3& p : mt.positions()) box.extend(p);
  return box;
}

// A square in a random plane through a random point of the middle of the
// box; `complete` makes it larger than the object (the cut goes right
// through), else its side is 15-60% of the box's diagonal.
inline CutPolygon random_polygon(const engine::Aabb& box, std::mt19937_64& rng, bool complete) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Vec3 size = box.hi - box.lo;
  const Vec3 centre = box.lo + Vec3(0.25 + 0.5 * u(rng), 0.25 + 0.5 * u(rng), 0.25 + 0.5 * u(rng)).cwiseProduct(size);
  Vec3 n(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
  if (n.norm() < 1e-3) n = Vec3(0.3, 0.5, 0.8);
  n.normalize();
  Vec3 a = n.cross(std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).normalized();
  const double angle = 6.283185307179586 * u(rng);
  a = std::cos(angle) * a + std::sin(angle) * n.cross(a);
  const Vec3 b = n.cross(a);
  const double half = 0.5 * size.norm() * (complete ? 1.5 : 0.15 + 0.45 * u(rng));
  return CutPolygon::from_points({centre + half * (a + b), centre + half * (b - a), centre - half * (a + b),
                                  centre + half * (a - b)});
}

// A random frontier: a random error field around a random focus.
inline Frontier random_frontier(const Mt& mt, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const engine::Aabb box = mt_box(mt);
  float max_error = 0;
  for (std::size_t f = 0; f < mt.num_fragments(); ++f) max_error = std::max(max_error, mt.fragment_error(FragId(f)));
  engine::ErrorField field;
  field.focus = engine::Segment::point(box.lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(box.hi - box.lo));
  field.radius = u(rng) * 0.3 * (box.hi - box.lo).norm();
  field.near_error = u(rng) < 0.3 ? 0.0 : u(rng) * max_error;
  field.growth = u(rng) * 2.0 * max_error / (box.hi - box.lo).norm();
  return engine::extract_frontier(mt, field);
}

// Distance from a point of the polygon's plane to its outline.
// Where two frontiers of one MT differ (set, mesh tets, vertices, visible
// fragments, compared as sets); empty when they agree.
inline std::string frontier_difference(const Frontier& a, const Frontier& b) {
  const auto same = [](auto x, auto y) {
    std::vector<std::int32_t> u, v;
    for (auto h : x) u.push_back(h.value);
    for (auto h : y) v.push_back(h.value);
    std::sort(u.begin(), u.end());
    std::sort(v.begin(), v.end());
    return u == v;
  };
  std::string out;
  if (!same(a.fragments(), b.fragments())) out += " fragments";
  if (!same(a.tets(), b.tets())) out += " tets";
  if (!same(a.vertices(), b.vertices())) out += " vertices";
  if (!same(a.visible_fragments(), b.visible_fragments())) out += " visible";
  return out;
}

inline double distance_to_outline(const CutPolygon& polygon, const Vec3& x) {
  double best = std::numeric_limits<double>::infinity();
  const auto& c = polygon.corners();
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Vec3& a = c[i];
    const Vec3& b = c[(i + 1) % c.size()];
    const double s = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + s * (b - a) - x).norm());
  }
  return best;
}

// Tets of the frontier with an edge that crosses a polygon properly (the
// ends on opposite sides of its plane, farther from it than round-off: the
// points a cut makes on its plane are there only up to rounding; the
// crossing strictly inside it) at more than `slack` from its outline. The
// paper ignores crossings of a tet's faces only, so near the outline of an
// earlier cut a tet that was not cut then may be split by a later cut into
// pieces that cross it: `slack` (a tet's size there) allows those.
inline std::size_t properly_crossed_tets(const Mt& mt, const Frontier& frontier, const CutPolygon& polygon,
                                         double slack = 0) {
  std::size_t crossed = 0;
  const double eps = 1e-9 * polygon.diameter();
  for (TetId t : frontier.tets()) {
    const auto& tet = mt.tet(t);
    bool hit = false;
    for (const auto& e : engine::kTetEdges) {
      const Vec3& a = mt.position(tet[e[0]]);
      const Vec3& b = mt.position(tet[e[1]]);
      const double da = polygon.signed_distance(a), db = polygon.signed_distance(b);
      if (!((da > eps && db < -eps) || (da < -eps && db > eps)) || polygon.line_crossing(a, b) <= 0) continue;
      const Vec3 x = a + da / (da - db) * (b - a);
      if (distance_to_outline(polygon, x) > slack) hit = true;
    }
    crossed += hit;
  }
  return crossed;
}

// The longest edge of the live tets near a polygon (its box).
inline double longest_edge_near(const Mt& mt, const engine::TetBvh& bvh, const CutPolygon& polygon) {
  engine::Aabb box;
  box.lo = polygon.box_min();
  box.hi = polygon.box_max();
  double longest = 0;
  bvh.for_each_overlapping(mt, box, [&](TetId t) {
    for (const auto& e : engine::kTetEdges)
      longest = std::max(longest, (mt.position(mt.tet(t)[e[0]]) - mt.position(mt.tet(t)[e[1]])).norm());
    return true;
  });
  return longest;
}

// The MT up to the numbering of vertices, tets and fragments: each live tet
// as its sorted corner positions with the created sets of its birth and
// death (each as its sorted tets' corners).
using TetKey = std::array<double, 12>;
inline TetKey tet_key(const Mt& mt, TetId t) {
  std::array<std::array<double, 3>, 4> c;
  for (int i = 0; i < 4; ++i) {
    const Vec3& p = mt.position(mt.tet(t)[i]);
    c[i] = {p.x(), p.y(), p.z()};
  }
  std::sort(c.begin(), c.end());
  TetKey key;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) key[3 * i + j] = c[i][j];
  return key;
}
inline std::vector<std::tuple<TetKey, std::size_t, std::size_t>> canonical_mt(const Mt& mt) {
  std::vector<std::vector<TetKey>> created(mt.num_fragments());
  for (std::size_t f = 0; f < mt.num_fragments(); ++f) {
    for (TetId t : mt.created(FragId(f))) created[f].push_back(tet_key(mt, t));
    std::sort(created[f].begin(), created[f].end());
  }
  // Fragment signatures: rank of the created set (the drain creates nothing).
  std::vector<std::vector<TetKey>> sorted = created;
  std::sort(sorted.begin(), sorted.end());
  const auto sig = [&](FragId f) {
    return static_cast<std::size_t>(std::lower_bound(sorted.begin(), sorted.end(), created[f.index()]) - sorted.begin());
  };
  std::vector<std::tuple<TetKey, std::size_t, std::size_t>> out;
  for (std::size_t i = 0; i < mt.num_tets(); ++i)
    if (mt.alive(TetId(i))) out.emplace_back(tet_key(mt, TetId(i)), sig(mt.birth(TetId(i))), sig(mt.death(TetId(i))));
  std::sort(out.begin(), out.end());
  return out;
}

// The frontiers that show each fragment a cut touched (one with a live tet
// on a vertex from `first_cut_vertex` on): the fragment's closure (it and
// its ancestors), so none after it; each must be a conforming tessellation
// with a manifold boundary. Mt::validate checks only the finest and the
// coarsest frontier, and a mixed-resolution frontier (the World's) can show
// any fragment between them.
inline engine::ValidationReport validate_cut_fragment_frontiers(const Mt& mt, std::size_t first_cut_vertex) {
  engine::ValidationReport out;
  std::vector<char> in(mt.num_fragments());
  std::vector<FragId> closure, todo;
  for (std::size_t i = 0; i < mt.num_fragments(); ++i) {
    const FragId f(i);
    if (f == mt.drain()) continue;
    const auto made = [&](VertId x) { return x.index() >= first_cut_vertex; };
    const auto created = mt.created(f);
    if (std::none_of(created.begin(), created.end(), [&](TetId t) {
          return mt.alive(t) && std::any_of(mt.tet(t).begin(), mt.tet(t).end(), made);
        }))
      continue;
    std::fill(in.begin(), in.end(), 0);
    closure.clear();
    todo.assign(1, f);
    in[f.index()] = 1;
    while (!todo.empty()) {
      const FragId g = todo.back();
      todo.pop_back();
      closure.push_back(g);
      for (FragId p : mt.parents(g))
        if (!in[p.index()]) {
          in[p.index()] = 1;
          todo.push_back(p);
        }
    }
    for (const std::string& problem : engine::validate_frontier(mt, Frontier::from_fragments(mt, closure)).problems)
      out.add("the frontier of fragment " + std::to_string(i) + " and its ancestors: " + problem);
  }
  return out;
}

}  // namespace mtcut::test
