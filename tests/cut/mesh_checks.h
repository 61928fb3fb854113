#pragma once
// Checks of a mesh after a cut, and random cut polygons for property tests.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <map>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <unordered_set>
#include <vector>

#include "cut/mesh_cutter.h"
#include "engine/mesh_loader.h"
#include "engine/tet_geometry.h"
#include "tests/test_paths.h"

namespace mtcut::cut::test {

using engine::TetMesh;
using engine::Vec3;

// The meshes the property tests run on, loaded once.
inline const TetMesh& liver_mesh() {
  static const TetMesh mesh = engine::load_mesh(mtcut::test::shared_mesh("liver.msh"), {}).mesh;
  return mesh;
}
inline const TetMesh& armadillo_mesh() {
  static const TetMesh mesh = engine::load_mesh(mtcut::test::shared_mesh("Armadillo_Tetra_4406.vtu"), {}).mesh;
  return mesh;
}
inline const TetMesh& builtin_mesh(const std::string& name) {
  static std::map<std::string, TetMesh> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    engine::MeshLoadDef def;
    def.builtin_tets = 800;
    it = cache.emplace(name, engine::load_mesh("builtin:" + name, def).mesh).first;
  }
  return it->second;
}

// One split table per scheme for the whole test binary: recipes are
// generated once (generation is the slow part in a debug build).
inline SplitTable& shared_table(SplitScheme scheme = SplitScheme::kLut) {
  static SplitTable lut(SplitScheme::kLut), bielser(SplitScheme::kBielser17);
  return scheme == SplitScheme::kLut ? lut : bielser;
}

// Edges of the mesh that the polygon crosses properly: ends strictly on
// opposite sides and the crossing strictly inside the polygon. Vertices the
// cut made (ids from `first_new`) or moved onto itself (`on_cut`) count as on
// the plane: snapping is the cut passing through them (and the cutter counts
// vertices within rounding of the plane as on it); so does an end within
// rounding (1e-9 of the edge) of the plane.
inline std::size_t count_crossed_edges(const TetMesh& mesh, const CutPolygon& polygon, std::size_t first_new,
                                       const std::vector<engine::VertId>& on_cut) {
  std::vector<int> side(mesh.num_vertices());
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) side[v] = v >= first_new ? 0 : polygon.side(mesh.positions[v]);
  for (engine::VertId v : on_cut) side[v.index()] = 0;
  std::unordered_set<std::uint64_t> seen;
  std::size_t crossed = 0;
  for (const auto& tet : mesh.tets)
    for (const auto& e : engine::kTetEdges) {
      const engine::VertId a = tet[e[0]], b = tet[e[1]];
      if (side[a.index()] * side[b.index()] >= 0) continue;
      const auto lo = static_cast<std::uint64_t>(std::min(a, b).value), hi = static_cast<std::uint64_t>(std::max(a, b).value);
      if (!seen.insert(lo << 32 | hi).second) continue;
      const double length = (mesh.positions[lo] - mesh.positions[hi]).norm();
      if (std::abs(polygon.signed_distance(mesh.positions[lo])) <= 1e-9 * length ||
          std::abs(polygon.signed_distance(mesh.positions[hi])) <= 1e-9 * length)
        continue;
      crossed += polygon.line_crossing(mesh.positions[lo], mesh.positions[hi]) > 0;
    }
  return crossed;
}

// validate(), volume, no crossed edge, and the smallest dihedral angle of the
// new tets; failures name `what`.
inline void expect_clean_cut(const TetMesh& mesh, const MeshCutResult& result, const CutPolygon& polygon,
                             double volume_before, std::size_t vertices_before, const std::string& what) {
  const auto report = mesh.validate();
  EXPECT_TRUE(report.ok()) << what << ": " << report.summary();
  EXPECT_NEAR(mesh.total_volume(), volume_before, 1e-12 * volume_before) << what;
  std::vector<engine::VertId> on_cut = result.snapped_vertices;
  on_cut.insert(on_cut.end(), result.resided_vertices.begin(), result.resided_vertices.end());
  EXPECT_EQ(count_crossed_edges(mesh, polygon, vertices_before, on_cut), 0u) << what;
  EXPECT_EQ(mesh.num_vertices(), vertices_before + result.new_vertices.size()) << what;
}

// A random convex polygon: `corners` points on an ellipse of radii (r, r *
// aspect) around `centre` in the plane with normal `normal`.
inline CutPolygon make_polygon(const Vec3& centre, const Vec3& normal, double r, double aspect, int corners,
                               std::mt19937_64& rng) {
  const Vec3 n = normal.normalized();
  Vec3 u = n.unitOrthogonal();
  std::uniform_real_distribution<double> unit(0, 1);
  const double spin = 2 * std::numbers::pi * unit(rng);
  u = Eigen::AngleAxisd(spin, n) * u;
  const Vec3 w = n.cross(u);
  std::vector<double> angles;
  for (int i = 0; i < corners; ++i) angles.push_back(2 * std::numbers::pi * unit(rng));
  std::sort(angles.begin(), angles.end());
  // Spread the corners enough that the polygon is not a sliver of itself.
  for (int i = 0; i < corners; ++i) angles[i] = 0.5 * angles[i] + std::numbers::pi * i / corners;
  std::vector<Vec3> pts;
  for (double a : angles) pts.push_back(centre + r * std::cos(a) * u + r * aspect * std::sin(a) * w);
  return CutPolygon::from_points(pts);
}

inline Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0, 1);
  Vec3 v(g(rng), g(rng), g(rng));
  return v.normalized();
}

inline void mesh_box(const TetMesh& mesh, Vec3& lo, Vec3& hi) {
  lo = hi = mesh.positions[0];
  for (const Vec3& p : mesh.positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
}

enum class Contact { kRandom, kThroughVertex, kAlongEdge, kInFace, kNearEdgeEnd, kExactPlane };

inline const char* contact_name(Contact c) {
  switch (c) {
    case Contact::kRandom: return "random";
    case Contact::kThroughVertex: return "through a vertex";
    case Contact::kAlongEdge: return "along an edge";
    case Contact::kInFace: return "in a face";
    case Contact::kNearEdgeEnd: return "1e-9 from an edge end";
    case Contact::kExactPlane: return "exactly through vertices";
  }
  return "?";
}

// A random cut polygon for `mesh`, of the given kind of contact.
inline CutPolygon random_cut(const TetMesh& mesh, Contact contact, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  Vec3 lo, hi;
  test::mesh_box(mesh, lo, hi);
  const double diag = (hi - lo).norm();
  const auto& tet = mesh.tets[rng() % mesh.num_tets()];
  const Vec3 a = mesh.position(tet[0]), b = mesh.position(tet[1]), c = mesh.position(tet[2]);
  const int corners = 3 + static_cast<int>(rng() % 5);
  const double aspect = 0.3 + 0.7 * u(rng);
  const double edge = (b - a).norm();
  switch (contact) {
    case Contact::kRandom: {
      // Small (partial) to larger than the mesh (complete).
      const double r = diag * (u(rng) < 0.3 ? 1.5 : 0.03 + 0.4 * u(rng));
      return test::make_polygon(a + 0.3 * edge * test::random_unit(rng), test::random_unit(rng), r, aspect, corners, rng);
    }
    case Contact::kThroughVertex:
      return test::make_polygon(a, test::random_unit(rng), edge * (0.5 + 3 * u(rng)), aspect, corners, rng);
    case Contact::kAlongEdge: {
      const Vec3 normal = (b - a).cross(test::random_unit(rng));
      return test::make_polygon(0.5 * (a + b), normal, edge * (0.6 + 2 * u(rng)), aspect, corners, rng);
    }
    case Contact::kInFace: {
      const Vec3 normal = (b - a).cross(c - a);
      return test::make_polygon((a + b + c) / 3, normal, edge * (0.5 + 2 * u(rng)), aspect, corners, rng);
    }
    case Contact::kNearEdgeEnd: {
      Vec3 normal;
      do normal = test::random_unit(rng);
      while (std::abs(normal.dot((b - a).normalized())) < 0.3);
      return test::make_polygon(a + 1e-9 * (b - a), normal, diag * (0.05 + 0.3 * u(rng)), aspect, corners, rng);
    }
    case Contact::kExactPlane: {
      // An axis-aligned plane through a vertex's coordinate: every corner has
      // it exactly, so the vertex (and any other with it) is exactly on it.
      const int axis = static_cast<int>(rng() % 3);
      const double r = edge * (1 + 4 * u(rng));
      std::vector<Vec3> pts;
      for (int j = 0; j < corners; ++j) {
        const double t = 2 * std::numbers::pi * (j + 0.3 * u(rng)) / corners;
        Vec3 p = a;
        p[(axis + 1) % 3] += r * std::cos(t);
        p[(axis + 2) % 3] += r * aspect * std::sin(t);
        pts.push_back(p);
      }
      return CutPolygon::from_points(pts);
    }
  }
  return test::make_polygon(a, Vec3::UnitZ(), edge, 1, 3, rng);
}

}  // namespace mtcut::cut::test
