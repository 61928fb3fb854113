// Property tests of cut_mesh on the real meshes: 1,000 random cuts, partial
// and complete, with near-degenerate contacts, in sequences on the same mesh
// (so later cuts also cut tets made by earlier ones); progressive strokes;
// LUT vs 1:17 on the same cuts.
#include <gtest/gtest.h>

#include <cstdio>

#include "cut/mesh_cutter.h"
#include "tests/cut/mesh_checks.h"

namespace mtcut::cut {
namespace {

using engine::TetMesh;
using test::Contact;
using test::contact_name;
using test::expect_clean_cut;
using test::random_cut;

// The quality bounds of the LUT split with the default snap (0.15 of an
// edge), measured by RandomCutsOnRealMeshes (1000 cuts; inputs with 6.2
// (liver), 0.6 (armadillo) and about 7-10 (builtin) degrees):
//  - the first cut of an input mesh makes no tet with a dihedral angle under
//    kFirstCutMinDihedral degrees (measured: 0.48 on the liver);
//  - any cut, also of tets earlier cuts made, makes no tet whose smallest
//    dihedral angle is under kMinDihedralRatio times that of the tet it
//    replaces (measured: 0.004). Snapping keeps every new edge at least
//    0.15 of its parent edge, so a new tet is at worst about that much
//    thinner than its parent, and its angles shrink with the thickness;
//    quality therefore compounds over repeated cuts of the same tets, which
//    is why the bound is relative (no fixed-topology split can promise an
//    absolute bound there without remeshing).
constexpr double kFirstCutMinDihedral = 0.3;
constexpr double kMinDihedralRatio = 0.002;

struct Tally {
  std::size_t cuts = 0, split = 0, lut_tets = 0, snapped = 0;
  double min_dihedral = 180;
  double first_cut_min_dihedral = 180;  // over the first cut of each sequence
  double min_ratio = 1;
  std::array<std::size_t, kCaseCount> per_case{};
};

// `sequences` runs of `length` cuts, each run on a fresh copy of `mesh`.
void random_sequences(const std::string& name, const TetMesh& mesh, int sequences, int length, std::uint64_t seed,
                      Tally& tally) {
  std::mt19937_64 rng(seed);
  SplitTable& table = test::shared_table();
  for (int s = 0; s < sequences; ++s) {
    TetMesh work = mesh;
    for (int i = 0; i < length; ++i) {
      // Half of the cuts touch the mesh in a near-degenerate way.
      const Contact contact = rng() % 2 ? Contact::kRandom : static_cast<Contact>(1 + rng() % 5);
      const CutPolygon polygon = random_cut(work, contact, rng);
      const double volume = work.total_volume();
      const std::size_t vertices = work.num_vertices();
      CutterDef def;
      def.count_pieces = false;
      const MeshCutResult r = cut_mesh(work, polygon, def, &table);
      const std::string what = name + " sequence " + std::to_string(s) + " cut " + std::to_string(i) + " (" +
                               contact_name(contact) + ")";
      expect_clean_cut(work, r, polygon, volume, vertices, what);
      tally.min_ratio = std::min(tally.min_ratio, r.stats.min_dihedral_ratio);
      if (i == 0) tally.first_cut_min_dihedral = std::min(tally.first_cut_min_dihedral, r.stats.min_dihedral_deg);
      EXPECT_GE(r.stats.min_dihedral_ratio, kMinDihedralRatio) << what;
      if (i == 0) {
        EXPECT_GE(r.stats.min_dihedral_deg, kFirstCutMinDihedral) << what;
      }
      ++tally.cuts;
      tally.split += r.stats.split_tets;
      tally.lut_tets += r.stats.new_tets;
      tally.snapped += r.stats.snapped_vertices;
      tally.min_dihedral = std::min(tally.min_dihedral, r.stats.min_dihedral_deg);
      for (std::size_t k = 0; k < kCaseCount; ++k) tally.per_case[k] += r.stats.per_case[k];
      if (::testing::Test::HasFailure()) return;
    }
  }
}

TEST(MeshCutterProperties, RandomCutsOnRealMeshes) {
  Tally tally;
  random_sequences("liver.msh", test::liver_mesh(), 35, 12, 1, tally);
  random_sequences("Armadillo_Tetra_4406.vtu", test::armadillo_mesh(), 10, 10, 2, tally);
  random_sequences("builtin:box", test::builtin_mesh("box"), 20, 12, 3, tally);
  random_sequences("builtin:ellipsoid", test::builtin_mesh("ellipsoid"), 20, 12, 4, tally);
  EXPECT_EQ(tally.cuts, 1000u);
  std::printf("[ report   ] %zu cuts, %zu split tets, %.2f new tets each, %zu snapped vertices, min dihedral %.3f deg "
              "(first cuts %.3f deg), min ratio to parent %.4f\n",
              tally.cuts, tally.split, double(tally.lut_tets) / double(tally.split), tally.snapped, tally.min_dihedral,
              tally.first_cut_min_dihedral, tally.min_ratio);
  std::printf("[ report   ] per case:");
  for (std::size_t k = 0; k < kCaseCount; ++k) std::printf(" %s %zu", case_name(static_cast<CutCase>(k)), tally.per_case[k]);
  std::printf("\n");
  // Every case occurs on real meshes.
  for (CutCase c : {CutCase::kA, CutCase::kB, CutCase::kC, CutCase::kD, CutCase::kE, CutCase::kVertex})
    EXPECT_GT(tally.per_case[static_cast<std::size_t>(c)], 0u) << case_name(c);
}

}  // namespace
}  // namespace mtcut::cut

namespace mtcut::cut {
namespace {

// A blade (segment a-b) swept across `mesh` in `steps` strokes, each cut as
// soon as it is made; `turn` rotates the blade a little each stroke, so that
// consecutive strokes are not coplanar.
struct Stroke {
  TetMesh mesh;
  std::size_t new_tets = 0, split_tets = 0, vetoed = 0, pulled = 0;
};

Stroke sweep(const TetMesh& start, int steps, double turn, SplitScheme scheme = SplitScheme::kLut) {
  Stroke out{start};
  Vec3 lo, hi;
  test::mesh_box(start, lo, hi);
  const Vec3 centre = 0.5 * (lo + hi), size = hi - lo;
  // The blade spans the mesh in y and moves along x in a plane slightly off
  // z = const; with `turn` it also rolls about x by `turn` per stroke.
  const Vec3 tilt(0.013, 0.021, 1);
  auto blade = [&](int i) {
    const double x = -0.6 * size.x() + 1.2 * size.x() * i / steps;
    const Eigen::AngleAxisd roll(turn * i, Vec3::UnitX());
    const Vec3 half = roll * Vec3(0, 0.8 * size.y(), 0);
    Vec3 mid = centre + Vec3(x, 0, 0);
    mid.z() -= (tilt.x() * (mid.x() - centre.x())) / tilt.z();
    return std::pair<Vec3, Vec3>(mid - half, mid + half);
  };
  CutterDef def;
  def.scheme = scheme;
  def.count_pieces = false;
  SplitTable& table = test::shared_table(scheme);
  for (int i = 0; i < steps; ++i) {
    const auto [a, b] = blade(i);
    const auto [a1, b1] = blade(i + 1);
    for (const CutPolygon& polygon : sweep_blade(a, b, a1, b1)) {
      const double volume = out.mesh.total_volume();
      const std::size_t vertices = out.mesh.num_vertices();
      const MeshCutResult r = cut_mesh(out.mesh, polygon, def, &table);
      expect_clean_cut(out.mesh, r, polygon, volume, vertices, "stroke " + std::to_string(i));
      out.new_tets += r.stats.new_tets;
      out.split_tets += r.stats.split_tets;
      out.vetoed += r.stats.vetoed_vertices;
      out.pulled += r.stats.pulled_vertices;
    }
  }
  return out;
}

TEST(MeshCutterProperties, ProgressiveStrokesSeparateLikeOneCut) {
  for (const char* name : {"box", "ellipsoid"}) {
    SCOPED_TRACE(name);
    const TetMesh& mesh = test::builtin_mesh(name);
    // One stroke through everything, then the same sweep in two strokes: the
    // second continues the incision through the first one's outline.
    const Stroke one = sweep(mesh, 1, 0.0);
    EXPECT_EQ(count_pieces(one.mesh), 2u);
    const Stroke two = sweep(mesh, 2, 0.0);
    EXPECT_EQ(count_pieces(two.mesh), 2u) << two.vetoed << " vetoed, " << two.pulled << " pulled";
    // Continuing re-splits only the tets along the junction.
    EXPECT_LT(two.mesh.num_tets(), one.mesh.num_tets() * 13 / 10);
  }
}

TEST(MeshCutterProperties, LongAndTurningStrokesStayValid) {
  // Every stroke of a long or turning sweep leaves a valid mesh that no
  // stroke crosses (checked inside sweep()).
  for (const char* name : {"box", "ellipsoid"}) {
    SCOPED_TRACE(name);
    sweep(test::builtin_mesh(name), 12, 0.0);
    sweep(test::builtin_mesh(name), 8, 0.02);
  }
}

// Known limitation: over many polygons a junction between two of them
// leaves a bridge of material, whatever the snap (0, 0.05 and 0.15 all
// leave one piece on the box and the ellipsoid). The single-resolution
// cutter pulls vertices onto the cut and keeps others off it
// (vertex_unpinch.h), but it does not continue a crack from the last
// polygon's front as the MT cutter's strokes do (stroke_junction.h). The
// sweep above stays valid, but is not always separated. Enable when
// cut_mesh continues a crack; remove with cut_mesh if `mtcut cut` comes to
// run the MT cutter on a one-level MT.
TEST(MeshCutterProperties, DISABLED_ManyStrokesSeparateLikeOneCut) {
  for (const char* name : {"box", "ellipsoid"}) {
    SCOPED_TRACE(name);
    EXPECT_EQ(count_pieces(sweep(test::builtin_mesh(name), 12, 0.0).mesh), 2u);
    EXPECT_EQ(count_pieces(sweep(test::builtin_mesh(name), 8, 0.02).mesh), 2u);
  }
}

}  // namespace
}  // namespace mtcut::cut
