#include "sim/model_build.h"

#include <optional>
#include <utility>

#include "sim/spring_model_update.h"

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

ModelInputs ModelInputs::change_from(const SpringModel& base, std::span<const engine::TetId> base_tets,
                                     const std::function<bool(engine::TetId)>& in_base, const engine::Mt& mt,
                                     const engine::Frontier& frontier, const MaterialDef& material,
                                     const FixedRegion& fixed) {
  ModelInputs in = of(mt, frontier, material, fixed);
  in.base = &base;
  for (const engine::TetId t : base_tets)
    if (!frontier.has_tet(t)) in.removed.push_back(mt.tet(t));  // a dead tet keeps its vertices
  for (const engine::TetId t : frontier.tets())
    if (!in_base(t)) in.added.push_back(mt.tet(t));
  return in;
}

SpringModel ModelInputs::build() const {
  const auto is_fixed = [this](VertId v) { return fixed.contains(v, rest_positions[v.index()]); };
  if (base) {
    if (std::optional<SpringModel> updated =
            update_spring_model(*base, removed, added, tets, rest_positions, material, is_fixed))
      return std::move(*updated);
  }
  return build_spring_model(tets, rest_positions, material, is_fixed);
}

ModelBuild::ModelBuild(ModelInputs inputs, WorkerThread* worker)
    : model_(worker ? worker->submit([in = std::move(inputs)] { return in.build(); })
                    : std::async(std::launch::deferred, [in = std::move(inputs)] { return in.build(); })) {}

ModelBuild::ModelBuild(std::function<ModelInputs()> gather, WorkerThread* worker)
    : model_(worker ? worker->submit([gather = std::move(gather)] { return gather().build(); })
                    : std::async(std::launch::deferred, [gather = std::move(gather)] { return gather().build(); })) {}

}  // namespace mtcut::sim
