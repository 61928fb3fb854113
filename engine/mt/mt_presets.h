#pragma once
// Named ways to make an MT (`mtcut mt --preset NAME`): which mesh, which
// build options.

#include <optional>
#include <string>

#include "engine/mesh_loader.h"
#include "engine/mt/mt_builder.h"

namespace mtcut::engine {

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
