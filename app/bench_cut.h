#pragma once
// `mtcut bench cut`: the single-resolution cutter (cut/mesh_cutter.h) on the
// real liver (../shared/meshes/liver2.obj meshed by TetGen) and the builtin
// organ, with a fixed set of planar cuts placed in each mesh's bounding box:
// two complete ones and three partial ones (a slit from the side, a slit from
// the top, a pocket inside). Both schemes, LUT and the 1:17 reference, cut
// the same polygons in the same run, each cut on a fresh copy of the mesh;
// timings are medians over runs after a warm-up run.

#include <nlohmann/json.hpp>
#include <string>

namespace mtcut::app {

struct CutBenchDef {
  std::string liver;            // the real mesh (empty: liver2.obj among the shared meshes)
  std::string organ = "builtin:ellipsoid";
  int organ_tets = 20000;       // target tet count of the builtin organ
  int runs = 5;                 // timed runs (median reported), after one warm-up run
};

// Per scheme: split_tets, new_tets, new_tets_per_split_tet, ns_per_split_tet
// (the whole cut_mesh call, median over runs) and split_ns_per_split_tet
// (classify and split only); per cut the counts and pieces; and
// ratio_new_tets_bielser17_over_lut. Throws InputError for a bad mesh.
nlohmann::ordered_json run_cut_bench(const CutBenchDef& def);

// ../shared/meshes/liver2.obj, the real mesh the benches cut; throws
// InputError when it is not there.
std::string default_liver_mesh();

}  // namespace mtcut::app
