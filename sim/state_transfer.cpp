#include "sim/state_transfer.h"

#include <algorithm>
#include <cassert>
#include <limits>
#include <stdexcept>
#include <utility>

#include "engine/tet_geometry.h"

namespace mtcut::sim {
namespace {

using engine::TetId;
using engine::barycentric;

enum class Source { kKept, kInterpolated, kWalked, kCut, kExtrapolated };

// A vertex's position, velocity and carried vectors under the snapshot.
struct Sample {
  Vec3 x = Vec3::Zero(), v = Vec3::Zero();
  std::array<Vec3, DeformationSnapshot::kMaxCarried> carried;

  Sample() { carried.fill(Vec3::Zero()); }
  // = particle p's state in the snapshot.
  void set_particle(const DeformationSnapshot& snap, std::size_t p) {
    x = snap.x[p];
    v = snap.v[p];
    for (std::size_t c = 0; c < snap.carried.size(); ++c) carried[c] = snap.carried[c][p];
  }
  // += w (particle p's state in the snapshot).
  void add_particle(const DeformationSnapshot& snap, std::size_t p, double w) {
    x += w * snap.x[p];
    v += w * snap.v[p];
    for (std::size_t c = 0; c < snap.carried.size(); ++c) carried[c] += w * snap.carried[c][p];
  }
  // += w s, over the snapshot's `channels` carried vectors.
  void add_sample(const Sample& s, double w, std::size_t channels) {
    x += w * s.x;
    v += w * s.v;
    for (std::size_t c = 0; c < channels; ++c) carried[c] += w * s.carried[c];
  }
};

// Scratch of the walks below: a mark per MT tet (the walk's generation when
// it looked at the tet) and the stack of tets to go on from.
struct WalkScratch {
  std::vector<std::uint32_t> mark;
  std::uint32_t generation = 0;
  std::vector<TetId> stack;

  void start(std::size_t num_tets, TetId from) {
    if (mark.size() < num_tets) mark.resize(num_tets, 0);
    if (++generation == 0) {  // wrapped: forget every mark
      std::fill(mark.begin(), mark.end(), 0);
      generation = 1;
    }
    mark[from.index()] = generation;
    stack.assign(1, from);
  }
  // First look at t in this walk.
  bool first_look(TetId t) { return std::exchange(mark[t.index()], generation) != generation; }
};

// A simulated tet holding p, walked to from `start` (a tet holding p)
// through tets that hold p and cover the same region one fragment coarser
// (those the death fragment created: where the old frontier was coarser, a
// refinement), else one fragment finer (those the birth fragment replaced:
// a coarsening). Each chain of fragments that the old frontier's set holds
// ends at one of its tets; a walk gives up after kMaxHolding tets holding p
// (none: the caller asks the BVH).
TetId simulated_holder(const engine::Mt& mt, const DeformationSnapshot& snap, TetId start, const Vec3& p,
                       WalkScratch& walk) {
  constexpr std::size_t kMaxHolding = 256;
  for (const bool coarser : {true, false}) {
    walk.start(mt.num_tets(), start);
    std::size_t holding = 1;
    while (!walk.stack.empty() && holding < kMaxHolding) {
      const TetId t = walk.stack.back();
      walk.stack.pop_back();
      if (snap.simulated(t)) return t;
      const engine::FragId f = coarser ? mt.death(t) : mt.birth(t);
      if (!f.valid()) continue;
      for (const TetId next : coarser ? mt.created(f) : mt.replaced(f)) {
        if (!mt.alive(next) || !walk.first_look(next) || !engine::tet_contains(mt, next, p)) continue;
        walk.stack.push_back(next);
        ++holding;
      }
    }
  }
  return TetId();
}

// The record of v among the made vertices (ascending ids), nullptr if a cut did not make v.
const cut::MadeVertex* find_made(std::span<const cut::MadeVertex> made, VertId v) {
  const auto it = std::lower_bound(made.begin(), made.end(), v,
                                   [](const cut::MadeVertex& m, VertId id) { return m.id < id; });
  return it != made.end() && it->id == v ? &*it : nullptr;
}

bool ascending_ids(std::span<const cut::MadeVertex> made) {
  return std::adjacent_find(made.begin(), made.end(), [](const cut::MadeVertex& a, const cut::MadeVertex& b) {
           return !(a.id < b.id);
         }) == made.end();
}

Sample sample(const engine::Mt& mt, const engine::TetBvh& bvh, const DeformationSnapshot& snap, VertId v,
              std::span<const cut::MadeVertex> made, Source& source, int depth, TetId around = TetId()) {
  Sample out;
  if (v.index() < snap.particle_of.size() && snap.particle_of[v.index()] >= 0) {
    source = Source::kKept;
    out.set_particle(snap, static_cast<std::size_t>(snap.particle_of[v.index()]));
    return out;
  }
  if (!made.empty() && depth < 64) {
    if (const cut::MadeVertex* origin = find_made(made, v)) {
      Source ignored;
      for (int k = 0; k < 4; ++k) {
        if (!origin->parents[k].valid()) continue;
        out.add_sample(sample(mt, bvh, snap, origin->parents[k], made, ignored, depth + 1), origin->weights[k],
                       snap.carried.size());
      }
      source = Source::kCut;
      return out;
    }
  }
  const Vec3& rest = mt.position(v);
  TetId holder;
  if (around.valid()) {
    thread_local WalkScratch walk;  // kept between vertices and transfers
    holder = simulated_holder(mt, snap, around, rest, walk);
  }
  const bool walked = holder.valid();
  if (!holder.valid())
    bvh.for_each_containing(mt, rest, [&](TetId t) {
      if (!snap.simulated(t)) return true;
      holder = t;
      return false;
    });
  if (holder.valid()) {
    source = walked ? Source::kWalked : Source::kInterpolated;
    const auto w = barycentric(mt.corners(holder), rest);
    for (int k = 0; k < 4; ++k)
      out.add_particle(snap, static_cast<std::size_t>(snap.particle_of[mt.tet(holder)[k].index()]), w[k]);
    return out;
  }
  // Outside the simulated mesh: follow the nearest simulated vertex rigidly.
  source = Source::kExtrapolated;
  double best = std::numeric_limits<double>::infinity();
  std::size_t nearest = 0;
  VertId nearest_vertex;
  for (std::size_t u = 0; u < snap.particle_of.size(); ++u) {
    if (snap.particle_of[u] < 0) continue;
    const double d = (mt.position(VertId(u)) - rest).squaredNorm();
    if (d < best) {
      best = d;
      nearest = static_cast<std::size_t>(snap.particle_of[u]);
      nearest_vertex = VertId(u);
    }
  }
  if (!nearest_vertex.valid()) {
    out.x = rest;
    return out;
  }
  out.set_particle(snap, nearest);
  out.x += rest - mt.position(nearest_vertex);
  return out;
}

}  // namespace

DeformationSnapshot take_snapshot(const engine::Mt& mt, const engine::Frontier& frontier, const SpringModel& model,
                                  const SpringState& state) {
  return take_snapshot(mt, frontier.tets(), model, state);
}

DeformationSnapshot take_snapshot(const engine::Mt& mt, std::span<const engine::TetId> tets,
                                  const SpringModel& model, const SpringState& state) {
  DeformationSnapshot snap;
  snap.simulated_tets.grow(mt.num_tets());
  for (const engine::TetId t : tets) snap.simulated_tets.insert(t);
  snap.particle_of = model.particle_of(mt.num_vertices());
  snap.x = state.x;
  snap.v = state.v;
  for (std::size_t p = 0; p < model.num_particles(); ++p) snap.momentum += model.mass[p] * state.v[p];
  return snap;
}

std::pair<Vec3, Vec3> sample_vertex(const engine::Mt& mt, const engine::TetBvh& bvh,
                                    const DeformationSnapshot& snapshot, VertId v,
                                    std::span<const cut::MadeVertex> made) {
  assert(ascending_ids(made));
  Source ignored;
  const Sample s = sample(mt, bvh, snapshot, v, made, ignored, 0);
  return {s.x, s.v};
}

SpringState transfer_state(const engine::Mt& mt, const engine::TetBvh& bvh, const DeformationSnapshot& snapshot,
                           const SpringModel& model, std::span<const cut::MadeVertex> made, TransferReport* report,
                           std::vector<std::vector<Vec3>>* carried, std::span<const engine::TetId> model_tets) {
  if (snapshot.carried.size() > DeformationSnapshot::kMaxCarried)
    throw std::invalid_argument("transfer_state: more carried vectors than DeformationSnapshot::kMaxCarried");
  for (const auto& field : snapshot.carried)
    if (field.size() != snapshot.x.size())
      throw std::invalid_argument("transfer_state: a carried vector's size is not the snapshot's particle count");
  if (!ascending_ids(made)) throw std::invalid_argument("transfer_state: the made vertices' ids are not ascending");
  TransferReport local;
  SpringState state;
  const std::size_t n = model.num_particles();
  state.x.resize(n);
  state.v.resize(n);
  if (carried) carried->assign(snapshot.carried.size(), std::vector<Vec3>(n));
  // A model tet around each vertex the snapshot does not simulate, where
  // one of them is to be found in an old tet (not made by a cut), which a
  // cut or a coarsening move does not need. Only the tets the snapshot did
  // not simulate can hold such a vertex (a simulated tet's vertices all
  // were particles), so the others are skipped by a bit test: a refinement
  // brings a few hundred tets into a frontier of ~27k (liver: the pass
  // 0.23 -> ~0.05 ms), and the tet found for a vertex is the same.
  const auto simulated = [&](VertId u) {
    return u.index() < snapshot.particle_of.size() && snapshot.particle_of[u.index()] >= 0;
  };
  const bool some_to_find =
      !model_tets.empty() && std::any_of(model.particle_vertex.begin(), model.particle_vertex.end(),
                                         [&](VertId u) { return !simulated(u) && !find_made(made, u); });
  std::vector<TetId> around;
  if (some_to_find) {
    around.resize(mt.num_vertices());
    for (const TetId t : model_tets) {
      if (snapshot.simulated(t)) continue;
      for (const VertId u : mt.tet(t))
        if (!simulated(u)) around[u.index()] = t;
    }
  }
  Vec3 momentum = Vec3::Zero();
  double free_mass = 0;
  for (std::size_t p = 0; p < n; ++p) {
    const VertId u = model.particle_vertex[p];
    Source source = Source::kKept;
    if (simulated(u)) {  // the common case: sample()'s first branch, without a Sample in between
      const auto q = static_cast<std::size_t>(snapshot.particle_of[u.index()]);
      state.x[p] = snapshot.x[q];
      state.v[p] = snapshot.v[q];
      if (carried)
        for (std::size_t c = 0; c < carried->size(); ++c) (*carried)[c][p] = snapshot.carried[c][q];
    } else {
      const Sample s = sample(mt, bvh, snapshot, u, made, source, 0, around.empty() ? TetId() : around[u.index()]);
      state.x[p] = s.x;
      state.v[p] = s.v;
      if (carried)
        for (std::size_t c = 0; c < carried->size(); ++c) (*carried)[c][p] = s.carried[c];
    }
    switch (source) {
      case Source::kKept: ++local.kept; break;
      case Source::kInterpolated: ++local.interpolated; break;
      case Source::kWalked: ++local.interpolated, ++local.walked; break;
      case Source::kCut: ++local.from_cut; break;
      case Source::kExtrapolated: ++local.extrapolated; break;
    }
    if (model.inv_mass[p] == 0) {
      state.v[p].setZero();
    } else {
      free_mass += model.mass[p];
    }
    momentum += model.mass[p] * state.v[p];
  }
  if (free_mass > 0) {
    local.momentum_correction = (snapshot.momentum - momentum) / free_mass;
    for (std::size_t p = 0; p < n; ++p)
      if (model.inv_mass[p] != 0) state.v[p] += local.momentum_correction;
  }
  if (report) *report = local;
  return state;
}

}  // namespace mtcut::sim
