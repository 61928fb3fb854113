#pragma once
// A spring model built on a frontier's tets, now or on another core while
// the frame goes on, and taken when the frame loop needs it. After a move
// or a cut it is an update of the current model by the tets that changed
// (spring_model_update.h): the liver scenario's median 1.5 ms beside the
// physics instead of ~6 ms for a build from every tet.
//
// Why. Rebuilding the springs is most of an LOD change (the liver scenario:
// a 26k-tet frontier's model takes ~5.7 ms, its physics ~3.6 ms), and a
// frontier that follows the scalpel moves every other frame, so those frames
// ran past a 60 Hz budget (lod_ms p99 ~12 ms, frames ~21 ms). A build reads
// only its inputs, which it owns (copies of the tets, the rest positions,
// the material and the fixed region: the MT may be read, cut or grown
// meanwhile), and it is a pure function of them. So it can run while the
// frame's physics does and be taken at a point the frame loop fixes: taking
// waits for it, and a run gives the same bits with the build in the
// background or inline (World's LOD stage and its test). Background builds
// run on one long-lived WorkerThread (worker_thread.h says why not a thread
// per build).

#include <chrono>
#include <functional>
#include <future>
#include <span>
#include <vector>

#include "engine/mt/frontier.h"
#include "engine/mt/mt.h"
#include "sim/fixed_region.h"
#include "sim/material.h"
#include "sim/spring_model.h"
#include "sim/worker_thread.h"

namespace mtcut::sim {

// What a model is built from, owned but for the base of an update.
struct ModelInputs {
  std::vector<engine::Tet> tets;    // MT vertex ids
  std::vector<Vec3> rest_positions;  // (n_mt_vertices) at the time of the copy
  MaterialDef material;
  FixedRegion fixed;
  // When set, the model on the tets that `tets` held before `removed` left
  // and `added` joined, with the same material and fixed region: build()
  // updates it (sim/spring_model_update.h: the same bits, a fraction of the
  // time). Not owned: it must stay as it is until the build is taken.
  const SpringModel* base = nullptr;
  std::vector<engine::Tet> removed, added;

  // The frontier's tets and the MT's positions, copied.
  static ModelInputs of(const engine::Mt& mt, const engine::Frontier& frontier, const MaterialDef& material,
                        const FixedRegion& fixed);
  // The same, with the change from `base`, the model on the tets `base_tets`
  // (in_base tells them): the tets of base_tets not in the frontier left,
  // the frontier's not in base_tets joined.
  static ModelInputs change_from(const SpringModel& base, std::span<const engine::TetId> base_tets,
                                 const std::function<bool(engine::TetId)>& in_base, const engine::Mt& mt,
                                 const engine::Frontier& frontier, const MaterialDef& material,
                                 const FixedRegion& fixed);
  SpringModel build() const;
};

class ModelBuild {
 public:
  // No build (nothing to take).
  ModelBuild() = default;
  // Starts building on `worker`, or, without one, when taken, on the taker's thread.
  ModelBuild(ModelInputs inputs, WorkerThread* worker);
  // The same, gathering the inputs there too: `gather` runs on the worker
  // (or when taken), so what it reads must stay as it is until the build is
  // taken or waited for.
  ModelBuild(std::function<ModelInputs()> gather, WorkerThread* worker);
  // Waits for the model; rethrows what the build threw. Once.
  SpringModel take() { return model_.get(); }
  // Waits until a build started on a worker has run, without taking it (a
  // build left for the taker's thread does not run).
  void wait() const {
    if (model_.valid() && model_.wait_for(std::chrono::seconds(0)) != std::future_status::deferred) model_.wait();
  }

 private:
  std::future<SpringModel> model_;
};

}  // namespace mtcut::sim
