#include "engine/mt/mt_builder.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "engine/mt/bvh.h"
#include "engine/stopwatch.h"

namespace mtcut::engine {
namespace {

// The rounds of simplification over one working mesh.
class Builder {
 public:
  Builder(Mt& mt, const MtBuildOptions& options)
      : options_(options),
        mesh_(mt, {options.preserve_boundary, options.min_quality,
                   options.max_surface_deviation * box_of(mt.positions()).diagonal()}),
        choice_(mt.num_vertices()),
        dirty_(mt.num_vertices(), 1),
        stale_(mt.num_vertices(), 0),
        owner_(mt.num_vertices(), -1) {
    for (std::size_t v = 0; v < mt.num_vertices(); ++v) dirty_list_.emplace_back(v);
  }

  void run() {
    while (!done()) {
      evaluate_dirty();
      if (!draw_pool()) break;
      std::size_t made = 0;
      for (const auto& [cost, id] : pool_) {
        if (done()) break;
        made += grow_cluster(VertId(id), static_cast<std::int32_t>(made));
      }
      for (VertId v : locked_) owner_[v.index()] = -1;
      locked_.clear();
      ++rounds_;
      if (made == 0 && refreshed_ == 0 && dirty_list_.empty()) break;  // nothing left to change
      refreshed_ = 0;
    }
  }

  SimplificationMesh& mesh() { return mesh_; }
  std::size_t rounds() const { return rounds_; }
  std::size_t collapses() const { return collapses_; }

 private:
  bool done() const {
    return (options_.target_coarsest_tets > 0 && mesh_.live_tets() <= options_.target_coarsest_tets) ||
           (options_.max_collapses > 0 && collapses_ >= options_.max_collapses);
  }

  void mark_dirty(VertId v) {
    if (!dirty_[v.index()]) dirty_[v.index()] = 1, dirty_list_.push_back(v);
  }

  // Vertices whose star changed. One with a valid collapse is only marked
  // stale (its old cost still places it in the pool; it is re-evaluated
  // when drawn): most are touched several times before their turn. One
  // without must be evaluated now, or it would never return to the pool.
  void evaluate_dirty() {
    for (VertId v : dirty_list_) {
      dirty_[v.index()] = 0;
      if (choice_[v.index()].valid()) {
        stale_[v.index()] = 1;
      } else {
        choice_[v.index()] = mesh_.best_collapse(v, false);
      }
    }
    dirty_list_.clear();
  }

  // The round's candidates: the cheapest fraction, in order (ties by vertex
  // id, so the build is deterministic). False when there is none.
  bool draw_pool() {
    pool_.clear();
    round_bound_ = std::numeric_limits<float>::infinity();
    for (std::size_t v = 0; v < choice_.size(); ++v)
      if (choice_[v].valid()) pool_.emplace_back(choice_[v].cost, static_cast<std::int32_t>(v));
    if (pool_.empty()) return false;
    const auto take = std::max<std::size_t>(
        1, static_cast<std::size_t>(std::ceil(options_.round_fraction * static_cast<double>(pool_.size()))));
    if (take < pool_.size()) {
      std::nth_element(pool_.begin(), pool_.begin() + static_cast<std::ptrdiff_t>(take - 1), pool_.end());
      const float bound = pool_[take - 1].first;
      round_bound_ = bound;
      pool_.erase(std::partition(pool_.begin(), pool_.end(), [&](const auto& c) { return c.first <= bound; }),
                  pool_.end());
    }
    std::sort(pool_.begin(), pool_.end());
    return true;
  }

  // v and its ring are free, or already this cluster's.
  bool can_take(VertId v, std::int32_t cluster) {
    mesh_.ring(v, ring_);
    const auto mine = [&](VertId a) { return owner_[a.index()] == -1 || owner_[a.index()] == cluster; };
    return mine(v) && std::all_of(ring_.begin(), ring_.end(), mine);
  }

  // Locks v's ring (ring_ must hold it) for the cluster and applies v -> target.
  FragId collapse(VertId v, VertId target, std::int32_t cluster, FragId into) {
    for (VertId a : ring_) {
      if (owner_[a.index()] == -1) owner_[a.index()] = cluster, locked_.push_back(a);
      mark_dirty(a);
    }
    if (owner_[v.index()] == -1) owner_[v.index()] = cluster, locked_.push_back(v);
    choice_[v.index()] = {};
    ++collapses_;
    return mesh_.apply(v, target, into);
  }

  // A fragment seeded by the collapse out of `seed`: 1 when made, else 0.
  // Clusters lock the vertices whose stars they change, so the fragments of
  // a round never touch each other's tets.
  std::size_t grow_cluster(VertId seed, std::int32_t cluster) {
    if (!can_take(seed, cluster)) return 0;
    CollapseChoice& choice = choice_[seed.index()];
    if (stale_[seed.index()]) {
      stale_[seed.index()] = 0;
      ++refreshed_;
      choice = mesh_.best_collapse(seed, false);
      if (!choice.valid() || choice.cost > round_bound_) return 0;  // its turn has not come
    }
    // The full rules, the link condition included (it also depends on the
    // target's star, which earlier rounds may have changed).
    const CollapseChoice now = mesh_.check_collapse(seed, choice.target);
    if (!now.valid()) {
      choice = mesh_.best_collapse(seed, true);  // another target, for a later round
      ++refreshed_;
      return 0;
    }
    mesh_.ring(seed, ring_);
    region_.assign(ring_.begin(), ring_.end());
    const FragId fragment = collapse(seed, now.target, cluster, FragId());
    for (int k = 1; k < options_.collapses_per_fragment && !done(); ++k) {
      CollapseChoice best;
      VertId from;
      for (VertId u : region_) {
        if (mesh_.star(u).empty() || !can_take(u, cluster)) continue;
        const CollapseChoice c = mesh_.best_collapse(u, true);
        if (c.valid() && (c.cost < best.cost || (c.cost == best.cost && u < from))) best = c, from = u;
      }
      if (!best.valid()) break;
      mesh_.ring(from, ring_);
      for (VertId a : ring_)
        if (std::find(region_.begin(), region_.end(), a) == region_.end()) region_.push_back(a);
      collapse(from, best.target, cluster, fragment);
    }
    return 1;
  }

  const MtBuildOptions& options_;
  SimplificationMesh mesh_;
  std::vector<CollapseChoice> choice_;  // (n_vertices) best collapse out of each vertex, if evaluated
  std::vector<char> dirty_;             // (n_vertices) star changed, not yet handled
  std::vector<char> stale_;             // (n_vertices) choice_ predates a change of the star
  std::vector<std::int32_t> owner_;     // (n_vertices) cluster of this round that locked it, -1 = free
  std::vector<VertId> dirty_list_, locked_, ring_, region_;
  std::vector<std::pair<float, std::int32_t>> pool_;  // (cost, vertex) of this round's candidates
  float round_bound_ = 0.0f;  // largest cost drawn into this round
  std::size_t rounds_ = 0, collapses_ = 0;
  std::size_t refreshed_ = 0;  // choices recomputed in this round
};

}  // namespace

Mt build_mt(const TetMesh& fine, const MtBuildOptions& options, MtBuildReport* report) {
  const auto start = std::chrono::steady_clock::now();
  Mt mt = Mt::from_fine_mesh(fine);
  mt.set_boundary_preserved(options.preserve_boundary);
  Builder builder(mt, options);
  builder.run();
  const FragId drain = mt.add_fragment();
  mt.set_drain(drain);
  builder.mesh().finish(drain);
  if (report) {
    report->rounds = builder.rounds();
    report->collapses = builder.collapses();
    report->rejections = builder.mesh().rejections();
    report->seconds = seconds_since(start);
  }
  return mt;
}

}  // namespace mtcut::engine
