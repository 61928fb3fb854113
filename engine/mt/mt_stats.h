#pragma once
// The figures `mtcut mt` prints about an MT, and the paper preset that
// reproduces the size of the paper's MT (Table 1).

#include <cstddef>
#include <optional>
#include <string>

#include "engine/mesh_loader.h"
#include "engine/mt/mt.h"
#include "engine/mt/mt_builder.h"

namespace mtcut::engine {

struct MtStats {
  std::size_t vertices = 0;       // shared by all resolutions
  std::size_t tets_total = 0;     // live tets of all resolutions
  std::size_t fragments = 0;      // DAG nodes, root and drain included
  std::size_t dag_depth = 0;      // arcs on the longest root -> drain path
  std::size_t finest_tets = 0;    // tets the root creates
  std::size_t coarsest_tets = 0;  // tets the drain replaces
  std::size_t bytes = 0;          // heap memory of the MT
};

MtStats compute_mt_stats(const Mt& mt);

// A named way to make an MT: which mesh, which build options.
//
// "paper": the paper's MT (Table 1) has 2,896 vertices, 37,062 tets and
// 1,542 fragments. With half-edge collapses the vertices are the fine
// mesh's, and simplifying a fine mesh of ~3k vertices all the way down
// creates ~12-13 tets per vertex: ~37k tets in all, the paper's ratio. Its
// fragments, though, are about half the collapses, so the preset groups
// two neighbouring collapses per fragment (collapses_per_fragment = 2: one
// connected region re-tessellated per fragment, as a paper fragment is;
// independent collapses would make disconnected fragments). The surface is
// simplified too (preserve_boundary off; a curved organ with a frozen
// surface cannot lose half its vertices). builtin:ellipsoid meshed at
// 12,500 tets gives 3,087 vertices, ~34.9k tets, 1,550 fragments: within
// 7% of each figure.
struct MtPreset {
  std::string name;
  std::string mesh_spec;  // for load_mesh
  MeshLoadDef mesh;
  MtBuildOptions build;
};

// nullopt for an unknown name. Known: "paper".
std::optional<MtPreset> find_mt_preset(const std::string& name);

}  // namespace mtcut::engine
