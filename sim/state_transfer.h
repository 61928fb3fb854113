#pragma once
// Carrying the simulated state across a change of the simulated mesh: a
// refine or coarsen step of the frontier, or a cut that makes vertices.
//
// Why this shape. Before the change, the World takes a DeformationSnapshot:
// the tets that were simulated and each MT vertex's particle state. After
// it, every particle of the new model gets its position and velocity from
// the snapshot:
//  - a vertex that was simulated keeps its own state;
//  - a vertex made by a cut is an affine combination of parent vertices
//    (two for an edge point, three for a face point): it gets the same
//    combination of their states (parents sampled recursively). The cut's
//    made vertices come as the cutter reports them (cut/made_vertex.h), a
//    span in ascending id order, looked up by binary search: the report is
//    already sorted, and a vertex is looked up once per new particle;
//  - any other vertex (one that a refinement brings back, or a hidden one)
//    gets the barycentric interpolation, in rest space, of the corners of the
//    old simulated tet that contains its rest position (TetBvh over all MT
//    tets, filtered by the snapshot's tets).
// Affine deformations are therefore carried exactly. Masses come from the
// new model (volumes x density, so the total is exact), and a uniform
// velocity correction of the free particles makes the linear momentum after
// the change equal to the momentum before it, to round-off.

#include <array>
#include <span>
#include <utility>
#include <vector>

#include "cut/made_vertex.h"
#include "engine/mt/frontier.h"
#include "engine/mt/index_set.h"
#include "engine/mt/mt.h"
#include "engine/mt/tet_bvh.h"
#include "sim/spring_model.h"
#include "sim/spring_state.h"

namespace mtcut::sim {

struct DeformationSnapshot {
  // The simulated tets, over the MT's tets when taken: a lookup per
  // candidate tet, where a sorted list cost a sort of the frontier per change.
  engine::IndexSet<engine::TetId> simulated_tets;
  std::vector<std::int32_t> particle_of;  // (n_mt_vertices) particle index, -1 if not simulated
  std::vector<Vec3> x, v;                 // (n_particles) state of the old model
  Vec3 momentum = Vec3::Zero();           // sum m v before the change
  // At most kMaxCarried more per-particle vectors of the old model, carried
  // to the new one as v is (same weights, no momentum correction): the
  // implicit stepper's warm start. Filled by the caller; may be empty.
  static constexpr std::size_t kMaxCarried = 3;
  std::vector<std::vector<Vec3>> carried;

  // Tet t was simulated (false for a tet made after the snapshot).
  bool simulated(engine::TetId t) const { return simulated_tets.contains(t); }
};

// What the simulator holds now, taken before the MT or the frontier changes.
DeformationSnapshot take_snapshot(const engine::Mt& mt, const engine::Frontier& frontier, const SpringModel& model,
                                  const SpringState& state);
// The same, from the tets that were simulated (the frontier may have moved
// since, as long as the model and state are still the ones built on `tets`).
DeformationSnapshot take_snapshot(const engine::Mt& mt, std::span<const engine::TetId> tets,
                                  const SpringModel& model, const SpringState& state);

// Deformed position and velocity of any MT vertex under the snapshot. `bvh`
// indexes the MT's live tets, which must still include the snapshot's tets
// (true across a frontier change; across a cut, new vertices come through
// `made`: the cut's made vertices, ascending ids). A vertex outside every
// snapshot tet (the builder may move the boundary) follows the nearest
// simulated particle rigidly.
std::pair<Vec3, Vec3> sample_vertex(const engine::Mt& mt, const engine::TetBvh& bvh,
                                    const DeformationSnapshot& snapshot, VertId v,
                                    std::span<const cut::MadeVertex> made = {});

struct TransferReport {
  std::size_t kept = 0;          // particles that existed before
  std::size_t interpolated = 0;  // new particles inside an old tet
  std::size_t walked = 0;        // of those, found through the DAG (the rest by the BVH)
  std::size_t from_cut = 0;      // new particles made by a cut
  std::size_t extrapolated = 0;  // new particles outside every old tet
  Vec3 momentum_correction = Vec3::Zero();  // the uniform dv applied
};

// The state of `model` (the new one) from the snapshot; `carried` (when
// given) gets the snapshot's carried vectors for the new particles; `made`:
// the vertices a cut made since the snapshot, ascending ids (empty across a
// frontier change). Throws std::invalid_argument when the snapshot carries
// more than kMaxCarried vectors or one of the wrong size, or when `made` is
// not in ascending id order.
//
// `model_tets` (optional): the tets the model was built on. A new vertex of
// a frontier move is then found in an old tet through the MT's DAG, from a
// tet around it to the tets covering the same region one fragment finer or
// coarser (those its birth fragment replaced, those its death fragment
// created), keeping to tets that hold it, until a simulated one: a few
// exact tests where the BVH over every resolution tests hundreds of nested
// boxes (~40 us a vertex; 517 new vertices took 19 ms after a cut in the
// stress scenario). Without it, or when the walk finds none, the BVH.
SpringState transfer_state(const engine::Mt& mt, const engine::TetBvh& bvh, const DeformationSnapshot& snapshot,
                           const SpringModel& model, std::span<const cut::MadeVertex> made = {},
                           TransferReport* report = nullptr, std::vector<std::vector<Vec3>>* carried = nullptr,
                           std::span<const engine::TetId> model_tets = {});

}  // namespace mtcut::sim
