#include "sim/spring_model_update.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "absl/container/flat_hash_map.h"
#include "engine/tet_geometry.h"
#include "sim/spring_model_parts.h"

namespace mtcut::sim {
namespace {

using model_parts::ParticleOrder;

// What a change does to one model: the old particles' and springs' sums
// and counts, and the particles and springs it brings.
class ChangeSums {
 public:
  ChangeSums(const SpringModel& old, std::size_t n_vertices)
      : old_(old),
        particle_volume_(old.particle_volume),
        particle_tets_(old.particle_tets),
        spring_volume_(old.spring_volume),
        spring_tets_(old.spring_tets),
        row_start_(old.num_particles() + 1, 0),
        slot_(n_vertices, -1) {
    for (const std::int32_t a : old.spring_a) ++row_start_[static_cast<std::size_t>(a) + 1];
    for (std::size_t i = 0; i < old.num_particles(); ++i) row_start_[i + 1] += row_start_[i];
    for (std::size_t i = 0; i < old.num_particles(); ++i) {
      const VertId v = old.particle_vertex[i];
      if (v.index() >= n_vertices)
        throw std::invalid_argument("update_spring_model: the model has a vertex the rest positions do not");
      slot_[v.index()] = static_cast<std::int32_t>(i);
    }
  }

  // Takes the tet's terms out (sign -1) or puts them in (+1).
  void apply(const Tet& tet, std::span<const Vec3> rest_positions, int sign) {
    std::array<Vec3, 4> corners;
    for (int k = 0; k < 4; ++k) {
      if (tet[k].index() >= rest_positions.size())  // checked before it is read
        throw std::invalid_argument("update_spring_model: a tet has a vertex the rest positions do not");
      corners[k] = rest_positions[tet[k].index()];
    }
    const double volume = engine::signed_volume(corners[0], corners[1], corners[2], corners[3]);
    const FixedVolume fixed = sign * to_fixed_volume(volume);
    for (const VertId v : tet) {
      const std::int32_t slot = slot_of(v, sign);
      if (slot >= 0) {
        particle_volume_[static_cast<std::size_t>(slot)] += fixed;
        count(particle_tets_[static_cast<std::size_t>(slot)], sign);
      } else {
        NewParticle& p = new_particles_[static_cast<std::size_t>(-slot - 2)];
        p.volume += fixed;
        ++p.tets;
      }
    }
    const std::array<double, 6> uses = model_parts::edge_use_volumes(corners, volume);
    for (std::size_t k = 0; k < 6; ++k) {
      const auto& e = engine::kTetEdges[k];
      const VertId u = tet[e[0]], v = tet[e[1]];
      const FixedVolume use = sign * to_fixed_volume(uses[k]);
      const std::int32_t su = slot_[u.index()], sv = slot_[v.index()];
      const std::int64_t s = su >= 0 && sv >= 0 ? old_spring(std::min(su, sv), std::max(su, sv)) : -1;
      if (s >= 0) {
        spring_volume_[static_cast<std::size_t>(s)] += use;
        count(spring_tets_[static_cast<std::size_t>(s)], sign);
        continue;
      }
      if (sign < 0) throw std::invalid_argument("update_spring_model: a removed tet's edge is not a spring");
      const std::uint64_t key = static_cast<std::uint64_t>(std::min(u.value, v.value)) << 32 |
                                static_cast<std::uint32_t>(std::max(u.value, v.value));
      const auto [it, inserted] = new_spring_of_.try_emplace(key, new_springs_.size());
      if (inserted) new_springs_.push_back({std::min(u, v), std::max(u, v)});
      new_springs_[it->second].volume += use;
      ++new_springs_[it->second].tets;
    }
  }

  // The updated model's particles and springs. Old ones that no tet uses
  // any more are dropped; the new ones are merged in order. `to_set`: the
  // springs whose constants are left to compute (new, or with a new sum);
  // `fixed`: each particle's (add_particles).
  SpringModel finish(const ParticleOrder& order, std::span<const Vec3> rest_positions,
                     const std::function<bool(VertId)>& is_fixed, std::vector<char>& fixed,
                     std::vector<std::size_t>& to_set) const {
    SpringModel model;
    const std::vector<std::int32_t> renumbered = add_particles(order, rest_positions, is_fixed, model, fixed);
    add_springs(renumbered, model, to_set);
    return model;
  }

 private:
  struct NewParticle {
    VertId vertex;
    FixedVolume volume = 0;
    std::int32_t tets = 0;
  };
  struct NewSpring {
    VertId u, v;  // MT vertices, u < v
    FixedVolume volume = 0;
    std::int32_t tets = 0;
  };

  static void count(std::int32_t& tets, int sign) {
    tets += sign;
    if (tets < 0) throw std::invalid_argument("update_spring_model: a tet was removed twice or never added");
  }

  // v's old particle (>= 0) or new particle (-2 - index), made on addition
  // (v has a rest position: apply() checked).
  std::int32_t slot_of(VertId v, int sign) {
    std::int32_t& slot = slot_[v.index()];
    if (slot == -1) {
      if (sign < 0) throw std::invalid_argument("update_spring_model: a removed tet's vertex is not a particle");
      slot = -2 - static_cast<std::int32_t>(new_particles_.size());
      new_particles_.push_back({v});
    }
    return slot;
  }

  // Old spring (a, b), a < b, or -1: a scan of a's row (a handful).
  std::int64_t old_spring(std::int32_t a, std::int32_t b) const {
    const auto row = static_cast<std::size_t>(a);
    for (std::int32_t s = row_start_[row]; s < row_start_[row + 1]; ++s)
      if (old_.spring_b[static_cast<std::size_t>(s)] == b) return s;
    return -1;
  }

  // The particles that stay, in their order, with the new ones merged in by
  // key. Returns each slot's new index (old particles, then new ones; -1 for
  // one dropped).
  // `fixed`: each particle's, old ones' as they were (their vertex and rest
  // position are), new ones' from is_fixed_vertex.
  std::vector<std::int32_t> add_particles(const ParticleOrder& order, std::span<const Vec3> rest_positions,
                                          const std::function<bool(VertId)>& is_fixed_vertex, SpringModel& model,
                                          std::vector<char>& fixed) const {
    const std::size_t n_old = old_.num_particles(), n_new = new_particles_.size();
    std::vector<std::pair<ParticleOrder::Key, std::size_t>> fresh(n_new);
    for (std::size_t j = 0; j < n_new; ++j) {
      const VertId v = new_particles_[j].vertex;
      fresh[j] = {order.key(rest_positions[v.index()], v), j};
    }
    std::sort(fresh.begin(), fresh.end());
    // Where each new particle goes among the old ones (they are in key order).
    std::vector<std::size_t> before(n_new);
    for (std::size_t j = 0; j < n_new; ++j) {
      std::size_t lo = 0, hi = n_old;
      while (lo < hi) {
        const std::size_t mid = (lo + hi) / 2;
        const VertId v = old_.particle_vertex[mid];
        if (order.key(old_.rest_position[mid], v) < fresh[j].first)
          lo = mid + 1;
        else
          hi = mid;
      }
      before[j] = lo;
    }
    // Sized once and written by index: a push_back per array per particle
    // cost more than the rest of the pass.
    std::vector<std::int32_t> renumbered(n_old + n_new, -1);
    const auto kept = static_cast<std::size_t>(
        std::count_if(particle_tets_.begin(), particle_tets_.end(), [](std::int32_t t) { return t > 0; }));
    const std::size_t n = kept + n_new;
    model.particle_vertex.resize(n);
    model.rest_position.resize(n);
    model.particle_volume.resize(n);
    model.particle_tets.resize(n);
    fixed.resize(n);
    std::size_t out = 0;
    const auto emit = [&](std::size_t slot, VertId v, FixedVolume volume, std::int32_t tets, char is_fixed) {
      renumbered[slot] = static_cast<std::int32_t>(out);
      model.particle_vertex[out] = v;
      model.rest_position[out] = rest_positions[v.index()];
      model.particle_volume[out] = volume;
      model.particle_tets[out] = tets;
      fixed[out] = is_fixed;
      ++out;
    };
    std::size_t j = 0;
    const auto emit_new_before = [&](std::size_t i) {
      for (; j < n_new && before[j] == i; ++j) {
        const NewParticle& p = new_particles_[fresh[j].second];
        emit(n_old + fresh[j].second, p.vertex, p.volume, p.tets, is_fixed_vertex && is_fixed_vertex(p.vertex));
      }
    };
    for (std::size_t i = 0; i < n_old; ++i) {
      if (j < n_new) emit_new_before(i);
      if (particle_tets_[i] > 0)
        emit(i, old_.particle_vertex[i], particle_volume_[i], particle_tets_[i], old_.inv_mass[i] == 0);
    }
    emit_new_before(n_old);
    return renumbered;
  }

  // The springs that stay, renumbered (their order holds), merged with the
  // new ones by (a, b); constants copied for a spring whose sum is unchanged.
  void add_springs(const std::vector<std::int32_t>& renumbered, SpringModel& model,
                   std::vector<std::size_t>& to_set) const {
    const std::size_t n_old = old_.num_particles();
    const auto new_index = [&](VertId v) {
      const std::int32_t slot = slot_[v.index()];
      return renumbered[slot >= 0 ? static_cast<std::size_t>(slot) : n_old + static_cast<std::size_t>(-slot - 2)];
    };
    struct Ends {
      std::int32_t a, b;
      std::size_t index;
      bool operator<(const Ends& o) const { return std::tie(a, b) < std::tie(o.a, o.b); }
    };
    std::vector<Ends> fresh;
    fresh.reserve(new_springs_.size());
    for (std::size_t k = 0; k < new_springs_.size(); ++k) {
      const std::int32_t a = new_index(new_springs_[k].u), b = new_index(new_springs_[k].v);
      fresh.push_back({std::min(a, b), std::max(a, b), k});
    }
    std::sort(fresh.begin(), fresh.end());
    const auto kept = static_cast<std::size_t>(
        std::count_if(spring_tets_.begin(), spring_tets_.end(), [](std::int32_t t) { return t > 0; }));
    const std::size_t m = kept + fresh.size();
    for (auto* v : {&model.spring_a, &model.spring_b, &model.spring_tets}) v->resize(m);
    for (auto* v : {&model.rest_length, &model.stiffness, &model.damping}) v->resize(m);
    model.spring_volume.resize(m);
    // Raw pointers, hoisted: through the vectors, each write made the
    // compiler reload every array's start (they might alias), which doubled
    // the pass.
    std::int32_t *out_a = model.spring_a.data(), *out_b = model.spring_b.data(), *out_tets = model.spring_tets.data();
    FixedVolume* out_volume = model.spring_volume.data();
    double *out_length = model.rest_length.data(), *out_stiffness = model.stiffness.data(),
           *out_damping = model.damping.data();
    const std::int32_t *old_a = old_.spring_a.data(), *old_b = old_.spring_b.data(), *tets = spring_tets_.data(),
                       *index = renumbered.data();
    const FixedVolume *volume = spring_volume_.data(), *old_volume = old_.spring_volume.data();
    const double *old_length = old_.rest_length.data(), *old_stiffness = old_.stiffness.data(),
                 *old_damping = old_.damping.data();
    std::size_t out = 0;
    const auto emit = [&](std::int32_t a, std::int32_t b, FixedVolume sum, std::int32_t count) {
      out_a[out] = a;
      out_b[out] = b;
      out_volume[out] = sum;
      out_tets[out] = count;
      ++out;
    };
    std::size_t j = 0;
    const auto emit_new_before = [&](const Ends* next) {
      for (; j < fresh.size() && (next == nullptr || fresh[j] < *next); ++j) {
        const NewSpring& s = new_springs_[fresh[j].index];
        to_set.push_back(out);
        emit(fresh[j].a, fresh[j].b, s.volume, s.tets);
      }
    };
    for (std::size_t s = 0, m_old = old_.num_springs(); s < m_old; ++s) {
      if (tets[s] == 0) continue;
      const Ends ends{index[static_cast<std::size_t>(old_a[s])], index[static_cast<std::size_t>(old_b[s])], s};
      if (j < fresh.size()) emit_new_before(&ends);
      if (volume[s] != old_volume[s]) {
        to_set.push_back(out);
      } else {
        out_length[out] = old_length[s];
        out_stiffness[out] = old_stiffness[s];
        out_damping[out] = old_damping[s];
      }
      emit(ends.a, ends.b, volume[s], tets[s]);
    }
    emit_new_before(nullptr);
  }

  const SpringModel& old_;
  std::vector<FixedVolume> particle_volume_;
  std::vector<std::int32_t> particle_tets_;
  std::vector<FixedVolume> spring_volume_;
  std::vector<std::int32_t> spring_tets_;
  std::vector<std::int32_t> row_start_;  // (n_old + 1) old particle a's springs: [row_start_[a], row_start_[a + 1])
  std::vector<std::int32_t> slot_;       // (n_vertices) old particle, -2 - new particle, -1 none
  std::vector<NewParticle> new_particles_;
  std::vector<NewSpring> new_springs_;
  absl::flat_hash_map<std::uint64_t, std::size_t> new_spring_of_;  // by (u, v) MT vertex pair
};

}  // namespace

std::optional<SpringModel> update_spring_model(const SpringModel& old, std::span<const Tet> removed,
                                               std::span<const Tet> added, std::span<const Tet> tets,
                                               std::span<const Vec3> rest_positions, const MaterialDef& material,
                                               const std::function<bool(VertId)>& is_fixed) {
  const ParticleOrder order = ParticleOrder::of(rest_positions);
  if (order.lo != old.order_lo || order.hi != old.order_hi) return std::nullopt;
  ChangeSums sums(old, rest_positions.size());
  for (const Tet& tet : removed) sums.apply(tet, rest_positions, -1);
  for (const Tet& tet : added) sums.apply(tet, rest_positions, +1);
  std::vector<std::size_t> to_set;
  std::vector<char> fixed;
  SpringModel model = sums.finish(order, rest_positions, is_fixed, fixed, to_set);
  model.order_lo = order.lo;
  model.order_hi = order.hi;
  for (const std::size_t s : to_set) model_parts::set_spring_constants(model, s, material);
  model_parts::finish_particles(model, material, fixed);
  if (material.volume_stiffness > 0) {
    model_parts::set_volume_terms(model, tets, model.particle_of(rest_positions.size()), material);
  }
  return model;
}

}  // namespace mtcut::sim
