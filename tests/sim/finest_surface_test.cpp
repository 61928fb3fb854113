#include "sim/finest_surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "cut/mt/mt_pieces.h"
#include "engine/mesh_loader.h"
#include "engine/mt/mt_builder.h"
#include "sim/world.h"
#include "tests/sim/organ_world.h"

namespace mtcut::sim {
namespace {

using engine::Frontier;
using engine::Mt;

Mt organ_mt(bool preserve_boundary) {
  engine::MeshLoadDef load;
  load.builtin_tets = 3000;
  engine::MtBuildOptions options;
  options.preserve_boundary = preserve_boundary;
  return engine::build_mt(engine::load_mesh("builtin:ellipsoid", load).mesh, options);
}

SpringModel model_on(const Mt& mt, const Frontier& frontier) {
  std::vector<engine::Tet> tets;
  for (const engine::TetId t : frontier.tets()) tets.push_back(mt.tet(t));
  return build_spring_model(tets, mt.positions(), MaterialDef{}, [](VertId) { return false; });
}

// A frontier between the finest and the coarsest: the coarsest, with
// random fragments refined.
Frontier mixed_frontier(const Mt& mt, std::uint64_t seed) {
  Frontier frontier = Frontier::coarsest(mt);
  std::mt19937_64 rng(seed);
  for (int i = 0; i < 200; ++i) {
    const std::vector<engine::FragId> refinable = frontier.refinable(mt);
    if (refinable.empty()) break;
    frontier.refine(mt, refinable[rng() % refinable.size()]);
  }
  return frontier;
}

// An affine motion of the particles moves every surface vertex by the same
// motion, whether it lies inside its carrier or, on a free boundary,
// outside it: the carriers are linear elements.
void expect_affine(const Mt& mt, const Frontier& frontier, const std::string& what) {
  SCOPED_TRACE(what);
  const SpringModel model = model_on(mt, frontier);
  const FinestSurface surface = carry_finest_surface(mt, frontier, model);
  const engine::ValidationReport report = validate_finest_surface(surface, mt, frontier, model);
  ASSERT_TRUE(report.ok()) << report.summary();
  ASSERT_GT(surface.num_faces(), 0u);
  EXPECT_EQ(surface.walked, surface.num_vertices());
  Eigen::Matrix3d a;
  a << 1.1, 0.2, -0.1, 0.05, 0.9, 0.3, -0.2, 0.1, 1.2;
  const Vec3 b(0.01, -0.02, 0.03);
  std::vector<Vec3> x;
  for (const Vec3& rest : model.rest_position) x.push_back(a * rest + b);
  std::vector<Vec3> placed;
  place_finest_surface(surface, x, placed);
  double worst = 0;
  for (std::size_t u = 0; u < surface.num_vertices(); ++u)
    worst = std::max(worst, (placed[u] - (a * mt.position(surface.vertices[u]) + b)).norm());
  EXPECT_LT(worst, 1e-12);
  const engine::SurfaceMesh mesh = deformed_finest_surface(surface, x);
  EXPECT_EQ(mesh.count_open_edges(), 0u);
  EXPECT_NEAR(mesh.enclosed_volume(), a.determinant() * mt.fine_volume(), 1e-9 * mt.fine_volume());
}

TEST(FinestSurface, AffineMotionsMoveItAffinelyOnEveryFrontier) {
  for (const bool preserve : {true, false}) {
    const Mt mt = organ_mt(preserve);
    const std::string name = preserve ? "boundary preserved" : "free boundary";
    expect_affine(mt, Frontier::finest(mt), name + ", finest");
    expect_affine(mt, Frontier::coarsest(mt), name + ", coarsest");
    expect_affine(mt, mixed_frontier(mt, 7), name + ", mixed");
  }
}

TEST(FinestSurface, OnTheFinestFrontierEveryVertexIsItsOwnParticle) {
  const Mt mt = organ_mt(false);
  const Frontier frontier = Frontier::finest(mt);
  const SpringModel model = model_on(mt, frontier);
  const FinestSurface surface = carry_finest_surface(mt, frontier, model);
  EXPECT_EQ(surface.outside, 0u);
  for (std::size_t u = 0; u < surface.num_vertices(); ++u) {
    int own = -1;
    for (std::size_t k = 0; k < 4; ++k)
      if (model.particle_vertex[static_cast<std::size_t>(surface.particle[u][k])] == surface.vertices[u])
        own = static_cast<int>(k);
    ASSERT_GE(own, 0) << "vertex " << surface.vertices[u].index();
    EXPECT_NEAR(surface.weight[u][static_cast<std::size_t>(own)], 1.0, 1e-12);
  }
}

TEST(FinestSurface, AFreeBoundaryLeavesSomeOfItOutsideTheCoarsestTets) {
  // What the walk's nearest carrier is for: without it those vertices
  // would have no carrier at all.
  const Mt mt = organ_mt(false);
  const Frontier frontier = Frontier::coarsest(mt);
  const FinestSurface surface = carry_finest_surface(mt, frontier, model_on(mt, frontier));
  EXPECT_GT(surface.outside, 0u);
  EXPECT_LT(surface.outside, surface.num_vertices());
}

TEST(FinestSurface, AModelOnAnotherFrontierIsRefused) {
  const Mt mt = organ_mt(true);
  const Frontier coarsest = Frontier::coarsest(mt);
  EXPECT_THROW(carry_finest_surface(mt, Frontier::finest(mt), model_on(mt, coarsest)), std::invalid_argument);
}

TEST(FinestSurface, FollowsAWorldThroughAStrokeAndEachSideOfTheCrackFollowsItsOwnPiece) {
  // The World's flap stroke (tests/sim/organ_world.h) on an organ with a
  // free boundary.
  const ScalpelPath path = test::flap_stroke(0.5);
  Mt organ = organ_mt(false);
  const std::size_t loaded_vertices = organ.num_vertices();
  World world(std::move(organ), test::flap_def(), path.pose_at(0));
  FinestSurface surface;
  std::size_t kept_frames = 0, crack_corners = 0;
  for (int f = 0; f < 120; ++f) {
    world.step(path.pose_at(world.time()));
    const FinestSurface next = carry_finest_surface(world.mt(), world.frontier(), world.model(), &surface);
    const engine::ValidationReport report = validate_finest_surface(next, world.mt(), world.frontier(), world.model());
    ASSERT_TRUE(report.ok()) << "frame " << f << ": " << report.summary();
    // While the crack is open in one piece, a vertex on a crack face is
    // carried by a tet on the face's own side of it, behind the face.
    // (A vertex of its carrier is its own particle: on a crack's front, where
    // both sides share it, as anywhere.)
    const Mt& mt = world.mt();
    for (std::size_t i = 0; i < next.num_faces(); ++i) {
      const auto& face = next.faces[i];
      const auto vertex = [&](int k) { return next.vertices[static_cast<std::size_t>(face[static_cast<std::size_t>(k)])]; };
      if (vertex(0).index() < loaded_vertices || vertex(1).index() < loaded_vertices ||
          vertex(2).index() < loaded_vertices)
        continue;
      const Vec3 &a = mt.position(vertex(0)), &b = mt.position(vertex(1)), &c = mt.position(vertex(2));
      const Vec3 normal = (b - a).cross(c - a).normalized();
      for (int k = 0; k < 3; ++k) {
        const engine::TetId carrier = next.carrier[static_cast<std::size_t>(face[static_cast<std::size_t>(k)])];
        const engine::Tet& tet = mt.tet(carrier);
        if (std::find(tet.begin(), tet.end(), vertex(k)) != tet.end()) continue;
        const auto corners = mt.corners(carrier);
        const Vec3 centroid = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
        EXPECT_LT((centroid - mt.position(vertex(k))).dot(normal), 0.0) << "frame " << f << ", face " << i;
        ++crack_corners;
      }
    }
    // Without a cut since the last carry, the carriers a frontier move left
    // are kept: most vertices do not walk.
    if (f > 0 && next.mt_revision == surface.mt_revision) {
      EXPECT_LT(next.walked, next.num_vertices() / 2) << "frame " << f;
      ++kept_frames;
    }
    surface = next;
  }
  EXPECT_GT(crack_corners, 0u);
  EXPECT_GT(kept_frames, 60u);
  ASSERT_EQ(world.pieces(), 2u);

  // Every vertex is carried by a tet of its own piece (the piece of the
  // finest tets it bounds): moving one piece's particles moves exactly that
  // piece's surface, the flap's crack side with it.
  const Mt& mt = world.mt();
  const cut::MtPieces pieces = cut::find_pieces(mt);
  std::vector<std::int32_t> vertex_piece(mt.num_vertices(), -1);
  for (const engine::TetId t : world.frontier().tets())
    for (const VertId v : mt.tet(t)) vertex_piece[v.index()] = pieces.tet_piece[t.index()];
  const SpringModel& model = world.model();
  std::vector<Vec3> x = world.state().x, moved = x;
  const Vec3 shift(0.5, 0.25, -1.0);
  for (std::size_t p = 0; p < model.num_particles(); ++p)
    if (vertex_piece[model.particle_vertex[p].index()] == 1) moved[p] += shift;
  std::vector<Vec3> before, after;
  place_finest_surface(surface, x, before);
  place_finest_surface(surface, moved, after);
  std::size_t crack_vertices = 0;
  std::vector<std::int32_t> own(surface.num_vertices(), -1);  // the piece of the finest tets it bounds
  for (std::size_t i = 0; i < surface.num_faces(); ++i)
    for (const std::int32_t u : surface.faces[i]) own[static_cast<std::size_t>(u)] = pieces.tet_piece[surface.face_tet[i].index()];
  for (std::size_t u = 0; u < surface.num_vertices(); ++u) {
    ASSERT_GE(own[u], 0);
    const Vec3 expected = before[u] + (own[u] == 1 ? shift : Vec3::Zero());
    EXPECT_LT((after[u] - expected).norm(), 1e-12) << "vertex " << surface.vertices[u].index();
    crack_vertices += surface.vertices[u].index() >= loaded_vertices;
  }
  EXPECT_GT(crack_vertices, 0u);
}

}  // namespace
}  // namespace mtcut::sim
