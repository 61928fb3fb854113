#include "app/bench_cut.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <filesystem>

#include "app/mesh_input_options.h"
#include "cut/lut/split_table.h"
#include "cut/mesh_cutter.h"
#include "engine/input_error.h"
#include "engine/mesh_loader.h"
#include "engine/quantiles.h"
#include "engine/stopwatch.h"

namespace mtcut::app {
namespace {

using engine::Vec3;

constexpr std::array<cut::SplitScheme, 2> kSchemes = {cut::SplitScheme::kLut, cut::SplitScheme::kBielser17};

// A rectangle in the mesh's box: centre and half extents as fractions of the
// box (centre 0 = the box centre, 0.5 = a face), spanned by u and v.
struct CutShape {
  const char* name;
  bool complete;  // meant to go right through the object
  Vec3 centre;    // fraction of the box size, from its centre
  Vec3 u, v;      // in-plane directions (v is made orthogonal to u)
  double half_u, half_v;  // fraction of the box diagonal
};

// Slightly tilted so that no plane meets the regular vertices of a builtin
// mesh exactly; fixed so that every run and every scheme cuts the same.
const std::array<CutShape, 5> kCuts = {{
    {"complete_transverse", true, Vec3(0.031, 0.017, 0.009), Vec3(0.021, 1, 0.013), Vec3(-0.017, 0.011, 1), 2, 2},
    {"complete_oblique", true, Vec3(-0.013, 0.083, 0.021), Vec3(1, -0.35, 0.027), Vec3(0.019, 0.25, 1), 2, 2},
    {"partial_side_slit", false, Vec3(-0.5, 0.023, 0.011), Vec3(1, 0.015, -0.012), Vec3(0.013, 0.021, 1), 0.25, 2},
    {"partial_top_slit", false, Vec3(0.012, 0.019, 0.5), Vec3(0.017, 1, 0.021), Vec3(-0.023, 0.014, 1), 2, 0.2},
    {"partial_pocket", false, Vec3(0.043, -0.027, 0.033), Vec3(1, 0.12, 0.031), Vec3(-0.2, 1, 0.3), 0.12, 0.08},
}};

cut::CutPolygon make_cut(const engine::TetMesh& mesh, const CutShape& shape) {
  Vec3 lo = mesh.positions.front(), hi = lo;
  for (const Vec3& p : mesh.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const Vec3 size = hi - lo;
  const Vec3 c = 0.5 * (lo + hi) + shape.centre.cwiseProduct(size);
  const Vec3 u = shape.u.normalized();
  const Vec3 v = (shape.v - shape.v.dot(u) * u).normalized();
  const Vec3 a = shape.half_u * size.norm() * u, b = shape.half_v * size.norm() * v;
  return cut::CutPolygon::from_points({c - a - b, c + a - b, c + a + b, c - a + b}, shape.name);
}

struct BenchMesh {
  std::string name;
  std::string input;
  engine::TetMesh mesh;
  std::vector<cut::CutPolygon> cuts;  // (kCuts.size())
};

BenchMesh load_bench_mesh(const std::string& name, const std::string& spec, const engine::MeshLoadDef& load) {
  BenchMesh out{name, spec, load_input_mesh(spec, load).mesh, {}};
  for (const CutShape& shape : kCuts) out.cuts.push_back(make_cut(out.mesh, shape));
  return out;
}


// Counts of one scheme over every cut (taken in the warm-up run) and its
// timings per run.
struct SchemeTally {
  std::size_t split_tets = 0, new_tets = 0;
  std::vector<double> ns_per_split_tet, split_ns_per_split_tet;  // (runs)
};

}  // namespace

std::string default_liver_mesh() {
  const std::string path =
      (std::filesystem::path(MTCUT_SHARED_MESHES) / "liver2.obj").lexically_normal().string();
  if (!std::filesystem::exists(path))
    throw engine::InputError(path + ": the real liver mesh is not there (give --mesh PATH)");
  return path;
}

nlohmann::ordered_json run_cut_bench(const CutBenchDef& def) {
  engine::MeshLoadDef organ_load;
  organ_load.builtin_tets = def.organ_tets;
  std::vector<BenchMesh> meshes;
  meshes.push_back(load_bench_mesh("liver", def.liver.empty() ? default_liver_mesh() : def.liver, {}));
  meshes.push_back(load_bench_mesh("organ", def.organ, organ_load));

  std::array<cut::SplitTable, 2> tables = {cut::SplitTable(kSchemes[0]), cut::SplitTable(kSchemes[1])};
  std::array<SchemeTally, 2> tally;
  nlohmann::ordered_json cuts = nlohmann::ordered_json::array();
  for (int run = 0; run <= def.runs; ++run) {  // run 0 warms up and counts
    std::array<double, 2> seconds{}, split_seconds{};
    std::array<std::size_t, 2> split{};
    for (const BenchMesh& m : meshes) {
      for (std::size_t c = 0; c < kCuts.size(); ++c) {
        nlohmann::ordered_json row = {{"mesh", m.name}, {"cut", kCuts[c].name}, {"complete", kCuts[c].complete}};
        for (std::size_t s = 0; s < kSchemes.size(); ++s) {
          engine::TetMesh copy = m.mesh;
          cut::CutterDef cutter;
          cutter.scheme = kSchemes[s];
          cutter.count_pieces = run == 0;  // an adjacency build: not part of the timed cut
          const auto start = std::chrono::steady_clock::now();
          const cut::MeshCutResult r = cut::cut_mesh(copy, m.cuts[c], cutter, &tables[s]);
          seconds[s] += engine::seconds_since(start);
          split_seconds[s] += r.stats.split_seconds;
          split[s] += r.stats.split_tets;
          if (run == 0) {
            tally[s].split_tets += r.stats.split_tets;
            tally[s].new_tets += r.stats.new_tets;
            row[cut::scheme_name(kSchemes[s])] = {{"split_tets", r.stats.split_tets},
                                                 {"new_tets", r.stats.new_tets},
                                                 {"pieces", r.stats.pieces}};
          }
        }
        if (run == 0) cuts.push_back(row);
      }
    }
    if (run == 0) continue;
    for (std::size_t s = 0; s < kSchemes.size(); ++s) {
      const double n = static_cast<double>(std::max<std::size_t>(split[s], 1));
      tally[s].ns_per_split_tet.push_back(1e9 * seconds[s] / n);
      tally[s].split_ns_per_split_tet.push_back(1e9 * split_seconds[s] / n);
    }
  }

  nlohmann::ordered_json out;
  out["runs"] = def.runs;
  out["meshes"] = nlohmann::ordered_json::array();
  for (const BenchMesh& m : meshes)
    out["meshes"].push_back({{"name", m.name}, {"input", m.input}, {"vertices", m.mesh.num_vertices()},
                             {"tets", m.mesh.num_tets()}});
  out["cuts"] = cuts;
  for (std::size_t s = 0; s < kSchemes.size(); ++s) {
    const SchemeTally& t = tally[s];
    out[cut::scheme_name(kSchemes[s])] = {
        {"split_tets", t.split_tets},
        {"new_tets", t.new_tets},
        {"new_tets_per_split_tet", t.split_tets ? static_cast<double>(t.new_tets) / t.split_tets : 0.0},
        {"ns_per_split_tet", engine::median(t.ns_per_split_tet)},
        {"split_ns_per_split_tet", engine::median(t.split_ns_per_split_tet)}};
  }
  out["ratio_new_tets_bielser17_over_lut"] =
      tally[0].new_tets ? static_cast<double>(tally[1].new_tets) / static_cast<double>(tally[0].new_tets) : 0.0;
  out["paper_ratio"] = 110874.0 / 29918.0;  // the paper's largest Table 1 row
  return out;
}

}  // namespace mtcut::app
