// Cutting whole meshes: every case and vertex permutation on one tet with
// random geometry, neighbours agreeing on diagonals, and random cuts (with
// near-degenerate contacts) on the real meshes.
#include "cut/mesh_cutter.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <optional>

#include "tests/cut/mesh_checks.h"

namespace mtcut::cut {
namespace {

using engine::Tet;
using engine::VertId;
using test::count_crossed_edges;
using test::expect_clean_cut;

struct CaseSpec {
  CutCase kind;
  std::array<int, 4> side;        // canonical vertex -> -1 / +1
  std::vector<int> covered;       // canonical edges (kTetEdges) inside the polygon
  std::size_t lut, bielser;       // tets per split
  bool complete;
};

const std::vector<CaseSpec>& cases() {
  static const std::vector<CaseSpec> specs = {
      {CutCase::kA, {-1, 1, 1, 1}, {0, 1, 2}, 4, 16, true},
      {CutCase::kB, {-1, -1, 1, 1}, {1, 2, 3, 4}, 6, 20, true},
      {CutCase::kC, {-1, 1, 1, 1}, {0}, 6, 10, false},
      {CutCase::kC, {-1, -1, 1, 1}, {1}, 6, 10, false},
      {CutCase::kD, {-1, 1, 1, 1}, {0, 1}, 8, 14, false},
      {CutCase::kD, {-1, -1, 1, 1}, {1, 2}, 8, 14, false},
      {CutCase::kE, {-1, -1, 1, 1}, {1, 2, 4}, 9, 18, false},
      {CutCase::kO, {-1, -1, 1, 1}, {1, 4}, 18, 16, false},
  };
  return specs;
}

struct OneTet {
  engine::TetMesh mesh;
  CutPolygon polygon;
};

// A random tet whose vertex role[i] plays canonical vertex i of `spec`, and
// a polygon crossing exactly the spec's covered edges, away from vertices.
std::optional<OneTet> realise_case(const CaseSpec& spec, const std::array<int, 4>& role, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  std::array<Vec3, 4> p;
  do {
    for (auto& q : p) q = Vec3(u(rng), u(rng), u(rng));
  } while (std::abs(engine::signed_volume(p[0], p[1], p[2], p[3])) < 0.03);
  // The plane: the affine function with value h at each vertex.
  std::array<double, 4> h{};
  for (int i = 0; i < 4; ++i) h[role[i]] = spec.side[i] * (0.5 + u(rng));
  Eigen::Matrix4d a;
  Eigen::Vector4d rhs;
  for (int m = 0; m < 4; ++m) {
    a.row(m) << p[m].x(), p[m].y(), p[m].z(), 1.0;
    rhs[m] = h[m];
  }
  const Eigen::Vector4d plane = a.fullPivLu().solve(rhs);
  const Vec3 normal = plane.head<3>();
  std::vector<Vec3> in, out;
  for (int k = 0; k < 6; ++k) {
    const int ma = role[engine::kTetEdges[k][0]], mb = role[engine::kTetEdges[k][1]];
    if (h[ma] * h[mb] > 0) continue;
    const Vec3 x = p[ma] + h[ma] / (h[ma] - h[mb]) * (p[mb] - p[ma]);
    (std::find(spec.covered.begin(), spec.covered.end(), k) != spec.covered.end() ? in : out).push_back(x);
  }
  // A polygon around the covered crossings: a small triangle around one, a
  // thin strip around two, their hull grown a little around three or four.
  const Vec3 n = normal.normalized();
  const Vec3 e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  double gap = 1e9;  // from the covered crossings to the others
  for (const Vec3& x : in)
    for (const Vec3& y : out) gap = std::min(gap, (x - y).norm());
  std::vector<Vec3> corners;
  if (in.size() == 1) {
    for (int j = 0; j < 3; ++j) {
      const double t = 2 * std::numbers::pi * j / 3;
      corners.push_back(in[0] + 0.4 * gap * (std::cos(t) * e1 + std::sin(t) * e2));
    }
  } else if (in.size() == 2) {
    const Vec3 d = (in[1] - in[0]).normalized(), side = n.cross(d);
    const double w = 0.05 * gap, l = 0.2 * gap;
    corners = {in[0] - l * d - w * side, in[1] + l * d - w * side, in[1] + l * d + w * side, in[0] - l * d + w * side};
  } else {
    Vec3 c = Vec3::Zero();
    for (const Vec3& x : in) c += x;
    c /= static_cast<double>(in.size());
    // Order around the centre, then grow.
    std::vector<std::pair<double, Vec3>> around;
    for (const Vec3& x : in) around.push_back({std::atan2((x - c).dot(e2), (x - c).dot(e1)), x});
    std::sort(around.begin(), around.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
    for (const auto& [angle, x] : around) corners.push_back(c + 1.1 * (x - c));
  }
  OneTet one{engine::TetMesh{}, CutPolygon::from_points(corners)};
  one.mesh.positions.assign(p.begin(), p.end());
  std::array<int, 4> order = {0, 1, 2, 3};
  std::shuffle(order.begin(), order.end(), rng);
  Tet tet = {VertId(order[0]), VertId(order[1]), VertId(order[2]), VertId(order[3])};
  if (engine::signed_volume(p[order[0]], p[order[1]], p[order[2]], p[order[3]]) < 0) std::swap(tet[2], tet[3]);
  one.mesh.tets.push_back(tet);
  // Keep only realisations where the polygon covers exactly the intended crossings.
  for (int k = 0; k < 6; ++k) {
    const int ma = role[engine::kTetEdges[k][0]], mb = role[engine::kTetEdges[k][1]];
    if (h[ma] * h[mb] > 0) continue;
    const bool want = std::find(spec.covered.begin(), spec.covered.end(), k) != spec.covered.end();
    const VertId lo(std::min(ma, mb)), hi(std::max(ma, mb));
    if ((one.polygon.line_crossing(p[lo.index()], p[hi.index()]) > 0) != want) return std::nullopt;
  }
  return one;
}

TEST(MeshCutter, EveryCaseUnderEveryPermutationOnRandomTets) {
  std::mt19937_64 rng(424242);
  for (const CaseSpec& spec : cases()) {
    std::array<int, 4> role = {0, 1, 2, 3};
    do {
      for (SplitScheme scheme : {SplitScheme::kLut, SplitScheme::kBielser17}) {
        SCOPED_TRACE(std::string(case_name(spec.kind)) + " " + scheme_name(scheme) + " roles " +
                     std::to_string(role[0]) + std::to_string(role[1]) + std::to_string(role[2]) +
                     std::to_string(role[3]));
        std::optional<OneTet> one;
        for (int attempt = 0; attempt < 200 && !one; ++attempt) one = realise_case(spec, role, rng);
        ASSERT_TRUE(one.has_value());
        const double volume = one->mesh.total_volume();
        CutterDef def;
        def.scheme = scheme;
        const MeshCutResult r = cut_mesh(one->mesh, one->polygon, def);
        EXPECT_EQ(r.stats.split_tets, 1u);
        EXPECT_EQ(r.stats.per_case[static_cast<std::size_t>(spec.kind)], 1u);
        EXPECT_EQ(r.stats.new_tets, scheme == SplitScheme::kLut ? spec.lut : spec.bielser);
        EXPECT_EQ(r.stats.snapped_vertices, 0u);
        expect_clean_cut(one->mesh, r, one->polygon, volume, 4, "one tet");
        EXPECT_EQ(r.stats.pieces, spec.complete ? 2u : 1u);
        EXPECT_GT(r.stats.min_dihedral_deg, 0.0);
      }
    } while (std::next_permutation(role.begin(), role.end()));
  }
}

// Two tets sharing a face that the cut splits into a triangle and a quad:
// whatever the ids, both must split the quad the same way.
TEST(MeshCutter, NeighboursChooseTheSameDiagonal) {
  const std::vector<Vec3> base = {Vec3(0, 0, 0), Vec3(1, 0.1, 0), Vec3(0.2, 1, 0.05), Vec3(0.3, 0.3, 1),
                                  Vec3(0.35, 0.25, -1)};
  // The plane x + y + z / 10 = 1/4 leaves vertex 0 alone: both tets are case A.
  std::mt19937_64 rng(1);
  const CutPolygon polygon = test::make_polygon(Vec3(0.25, 0, 0), Vec3(1, 1, 0.1), 10, 1, 3, rng);
  std::array<int, 5> ids = {0, 1, 2, 3, 4};
  int checked = 0;
  do {
    engine::TetMesh mesh;
    mesh.positions.resize(5);
    for (int i = 0; i < 5; ++i) mesh.positions[ids[i]] = base[i];
    // Each tet lists its vertices in its own random order, so the two see
    // the shared face's corners in different local orders.
    auto tet = [&](int a, int b, int c, int d) {
      std::array<int, 4> v = {a, b, c, d};
      std::shuffle(v.begin(), v.end(), rng);
      if (engine::signed_volume(base[v[0]], base[v[1]], base[v[2]], base[v[3]]) < 0) std::swap(v[2], v[3]);
      return Tet{VertId(ids[v[0]]), VertId(ids[v[1]]), VertId(ids[v[2]]), VertId(ids[v[3]])};
    };
    mesh.tets = {tet(0, 1, 2, 3), tet(0, 1, 2, 4)};
    ASSERT_TRUE(mesh.validate().ok());
    const double volume = mesh.total_volume();
    const MeshCutResult r = cut_mesh(mesh, polygon);
    ASSERT_EQ(r.stats.per_case[static_cast<std::size_t>(CutCase::kA)], 2u);
    expect_clean_cut(mesh, r, polygon, volume, 5, "two tets");
    EXPECT_EQ(r.stats.pieces, 2u);
    ++checked;
  } while (std::next_permutation(ids.begin(), ids.end()));
  EXPECT_EQ(checked, 120);
}

TEST(MeshCutter, ReportsWhatChanged) {
  engine::TetMesh mesh = test::liver_mesh();
  const std::size_t tets = mesh.num_tets(), vertices = mesh.num_vertices();
  Vec3 lo, hi;
  test::mesh_box(mesh, lo, hi);
  std::mt19937_64 rng(5);
  const CutPolygon polygon = test::make_polygon(0.5 * (lo + hi), Vec3(1, 0.2, 0.1), 3 * (hi - lo).norm(), 1, 5, rng);
  const MeshCutResult r = cut_mesh(mesh, polygon);
  const CutStats& s = r.stats;
  ASSERT_GT(s.split_tets, 10u);
  EXPECT_EQ(r.split_tets.size(), s.split_tets);
  ASSERT_EQ(r.split_first.size(), s.split_tets + 1);
  EXPECT_EQ(r.replacements.size(), s.new_tets);
  EXPECT_EQ(mesh.num_tets(), tets - s.split_tets + s.new_tets);
  EXPECT_EQ(mesh.num_vertices(), vertices + s.new_vertices);
  std::size_t by_case = 0;
  for (std::size_t c : s.per_case) by_case += c;
  EXPECT_EQ(by_case, s.split_tets);
  // Each split tet's slot holds its first replacement.
  for (std::size_t i = 0; i < r.split_tets.size(); ++i) EXPECT_EQ(r.replacements[r.split_first[i]], r.split_tets[i]);
  // New vertices: ids in order, positions from their parents and weights.
  for (std::size_t i = 0; i < r.new_vertices.size(); ++i) {
    const MadeVertex& v = r.new_vertices[i];
    EXPECT_EQ(v.id.index(), vertices + i);
    Vec3 p = Vec3::Zero();
    double w = 0;
    for (int k = 0; k < 4; ++k)
      if (v.parents[k].valid()) {
        EXPECT_LT(v.parents[k].index(), vertices);
        p += v.weights[k] * mesh.positions[v.parents[k].index()];
        w += v.weights[k];
      }
    EXPECT_NEAR(w, 1.0, 1e-12);
    EXPECT_LT((p - mesh.positions[v.id.index()]).norm(), 1e-12 * (hi - lo).norm());
  }
  // A cut through the whole liver leaves two pieces.
  EXPECT_EQ(s.pieces, 2u);
  EXPECT_GT(s.seconds, 0.0);
  EXPECT_GE(s.new_tets_per_split_tet(), 2.0);
}

}  // namespace
}  // namespace mtcut::cut
