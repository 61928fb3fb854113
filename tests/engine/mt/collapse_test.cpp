#include "engine/mt/collapse.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "engine/mt/frontier.h"
#include "engine/tet_adjacency.h"
#include "tests/engine/mt/mt_test_util.h"

namespace mtcut::engine {
namespace {

using mtcut::test::test_mesh;

// Lk(x) as sets of sorted simplices over vertex ids, the surface closed by
// the dummy vertex -1: straight from the definition, for comparison.
using Simplex = std::vector<std::int32_t>;
std::set<Simplex> link_of(const Mt& mt, const SimplificationMesh& mesh, std::vector<std::int32_t> center) {
  std::set<Simplex> link;
  const auto add_faces = [&](std::vector<std::int32_t> simplex) {
    // Every face of `simplex` minus the centre vertices, if it contains them all.
    for (std::int32_t c : center)
      if (std::find(simplex.begin(), simplex.end(), c) == simplex.end()) return;
    Simplex rest;
    for (std::int32_t q : simplex)
      if (std::find(center.begin(), center.end(), q) == center.end()) rest.push_back(q);
    const int n = static_cast<int>(rest.size());
    for (int mask = 1; mask < (1 << n); ++mask) {
      Simplex face;
      for (int i = 0; i < n; ++i)
        if (mask & (1 << i)) face.push_back(rest[static_cast<std::size_t>(i)]);
      std::sort(face.begin(), face.end());
      link.insert(face);
    }
  };
  for (TetId t : mesh.star(VertId(center[0]))) {
    const Tet& v = mt.tet(t);
    add_faces({v[0].value, v[1].value, v[2].value, v[3].value});
    for (int f = 0; f < 4; ++f)
      if (mt.boundary_mask(t) & (1u << f)) {
        const auto face = face_vertices(v, f);
        add_faces({face[0].value, face[1].value, face[2].value, -1});
      }
  }
  return link;
}

bool reference_link_condition(const Mt& mt, const SimplificationMesh& mesh, VertId v, VertId w) {
  const auto lv = link_of(mt, mesh, {v.value}), lw = link_of(mt, mesh, {w.value});
  const auto lvw = link_of(mt, mesh, {v.value, w.value});
  for (const Simplex& s : lv)
    if (lw.count(s) && !lvw.count(s)) return false;
  return true;
}

// Applies `steps` cheapest collapses (one at a time) and compares the link
// condition with the reference on every edge, before and after.
void compare_links(const TetMesh& fine, bool preserve, int steps) {
  Mt mt = Mt::from_fine_mesh(fine);
  SimplificationMesh mesh(mt, {preserve, 0.05});
  std::size_t edges = 0, failing = 0;
  const auto compare_all = [&] {
    std::vector<VertId> ring;
    for (std::size_t i = 0; i < mt.num_vertices(); ++i) {
      const VertId v(i);
      mesh.ring(v, ring);
      for (VertId w : ring) {
        const bool fast = mesh.link_condition(v, w);
        ASSERT_EQ(fast, reference_link_condition(mt, mesh, v, w)) << "edge " << v.value << " -> " << w.value;
        ++edges;
        failing += !fast;
      }
    }
  };
  compare_all();
  std::mt19937 rng(3);
  for (int k = 0; k < steps; ++k) {
    const VertId v(static_cast<std::size_t>(rng() % mt.num_vertices()));
    const CollapseChoice c = mesh.best_collapse(v);
    if (c.valid()) mesh.apply(v, c.target);
  }
  compare_all();
  EXPECT_GT(failing, 0u) << "no edge violates the link condition: the comparison proves little";
  ::testing::Test::RecordProperty("edges", static_cast<int>(edges));
}

TEST(Collapse, LinkConditionMatchesTheDefinitionOnTheLiver) { compare_links(test_mesh("liver"), false, 120); }

TEST(Collapse, LinkConditionMatchesTheDefinitionOnTheBox) { compare_links(test_mesh("box"), true, 300); }

TEST(Collapse, TwoTetsSharingAFaceFailTheLinkCondition) {
  // (0,1,2,3) and (1,2,3,4) sharing the face (1,2,3).
  TetMesh two;
  two.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 1)};
  two.tets = {{VertId(0), VertId(1), VertId(2), VertId(3)}, {VertId(1), VertId(2), VertId(3), VertId(4)}};
  ASSERT_TRUE(two.validate().ok()) << two.validate().summary();
  Mt mt = Mt::from_fine_mesh(two);
  SimplificationMesh mesh(mt, {false, 0.0});
  // Collapsing the cap vertex 0 onto 1 leaves the other tet: fine.
  EXPECT_TRUE(mesh.link_condition(VertId(0), VertId(1)));
  EXPECT_TRUE(reference_link_condition(mt, mesh, VertId(0), VertId(1)));
  // An edge of the shared face: the surface faces (1,3,0) and (2,3,0) would
  // both become (1,3,0)... the two surface loops around the edge pinch.
  EXPECT_FALSE(mesh.link_condition(VertId(1), VertId(2)));
  EXPECT_FALSE(reference_link_condition(mt, mesh, VertId(1), VertId(2)));
}

TEST(Collapse, AppliedCollapseIsAValidFragmentWithItsCost) {
  const TetMesh& fine = test_mesh("ellipsoid");
  Mt mt = Mt::from_fine_mesh(fine);
  SimplificationMesh mesh(mt, {true, 0.05});
  std::size_t applied = 0;
  for (std::size_t i = 0; i < mt.num_vertices() && applied < 20; ++i) {
    const VertId v(i);
    const CollapseChoice c = mesh.best_collapse(v);
    if (!c.valid()) continue;
    const std::size_t before = mesh.live_tets();
    const std::size_t star = mesh.star(v).size();
    const FragId f = mesh.apply(v, c.target);
    ++applied;
    EXPECT_EQ(mt.replaced(f).size(), star);
    EXPECT_EQ(mesh.live_tets(), before - star + mt.created(f).size());
    EXPECT_EQ(mt.fragment_error(f), c.cost);
    EXPECT_TRUE(mesh.star(v).empty());
    for (TetId t : mt.created(f)) EXPECT_GT(mt.volume(t), 0.0);
  }
  EXPECT_EQ(applied, 20u);
  const FragId drain = mt.add_fragment();
  mt.set_drain(drain);
  mesh.finish(drain);
  const ValidationReport report = mt.validate();
  EXPECT_TRUE(report.ok()) << report.summary();
}

TEST(Collapse, PreservedSurfaceVerticesMoveOnlyWithinFlatPatches) {
  // The ellipsoid's surface is curved, except where TetGen split a surface
  // triangle: only vertices inside such a flat patch, or on a straight
  // edge between two, may move, and only within it.
  const TetMesh& fine = test_mesh("ellipsoid");
  Mt mt = Mt::from_fine_mesh(fine);
  SimplificationMesh mesh(mt, {true, 0.05});
  std::size_t surface = 0, movable = 0;
  for (std::size_t i = 0; i < mt.num_vertices(); ++i) {
    const VertId v(i);
    if (!mesh.on_boundary(v)) continue;
    ++surface;
    const CollapseChoice c = mesh.best_collapse(v);
    if (!c.valid()) continue;
    ++movable;
    // Every surface face around v is in one plane, which holds the target too.
    std::vector<std::array<VertId, 3>> faces;
    for (TetId t : mesh.star(v))
      for (int f = 0; f < 4; ++f)
        if (mt.boundary_mask(t) & (1u << f)) {
          const auto face = face_vertices(mt.tet(t), f);
          if (std::find(face.begin(), face.end(), v) != face.end()) faces.push_back(face);
        }
    ASSERT_FALSE(faces.empty());
    // The faces lie in at most two planes (a flat patch, or two along a
    // straight crease), and the target lies in each of them.
    std::vector<std::array<VertId, 3>> planes;
    const auto on = [&](const std::array<VertId, 3>& p, VertId q) {
      return orient3d_sign(mt.position(p[0]), mt.position(p[1]), mt.position(p[2]), mt.position(q)) == 0;
    };
    for (const auto& face : faces) {
      const bool known = std::any_of(planes.begin(), planes.end(), [&](const auto& p) {
        return on(p, face[0]) && on(p, face[1]) && on(p, face[2]);
      });
      if (!known) planes.push_back(face);
    }
    EXPECT_LE(planes.size(), 2u) << "vertex " << i;
    for (const auto& p : planes) EXPECT_TRUE(on(p, c.target)) << "vertex " << i;
  }
  EXPECT_GT(surface, 100u);
  EXPECT_LT(movable, surface / 10);
}

TEST(Collapse, PreservedFlatFacesStillSimplify) {
  const TetMesh& fine = test_mesh("box");
  Mt mt = Mt::from_fine_mesh(fine);
  SimplificationMesh mesh(mt, {true, 0.05});
  std::size_t movable = 0;
  for (std::size_t i = 0; i < mt.num_vertices(); ++i)
    if (mesh.on_boundary(VertId(i)) && mesh.best_collapse(VertId(i)).valid()) ++movable;
  EXPECT_GT(movable, 20u);
  // The 8 corners never move.
  for (std::size_t i = 0; i < mt.num_vertices(); ++i) {
    const Vec3& p = mt.position(VertId(i));
    const Vec3 h = Vec3(0.16, 0.10, 0.07) / 2;
    if ((p.cwiseAbs() - h).cwiseAbs().maxCoeff() < 1e-12) {
      EXPECT_FALSE(mesh.best_collapse(VertId(i)).valid());
    }
  }
}

}  // namespace
}  // namespace mtcut::engine
