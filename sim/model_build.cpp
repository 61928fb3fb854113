#include "sim/model_build.h"

namespace mtcut::sim {

ModelInputs ModelInputs::of(const engine::Mt& mt, const engine::Frontier& frontier, const MaterialDef& material,
                            const FixedRegion& fixed) {
  ModelInputs in;
  in.tets.reserve(frontier.tets().size());
  for (const auto t : frontier.tets()) in.tets.push_back(mt.tet(t));
  in.rest_positions.assign(mt.positions().begin(), mt.positions().end());
  in.material = material;
  in.fixed = fixed;
  return in;
}

SpringModel ModelInputs::build() const {
  return build_spring_model(tets, rest_positions, material,
                            [this](VertId v) { return fixed.contains(v, rest_positions[v.index()]); });
}

ModelBuild::ModelBuild(ModelInputs inputs, WorkerThread* worker)
    : model_(worker ? worker->submit([in = std::move(inputs)] { return in.build(); })
                    : std::async(std::launch::deferred, [in = std::move(inputs)] { return in.build(); })) {}

}  // namespace mtcut::sim
