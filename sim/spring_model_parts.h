#pragma once
// The pieces build_spring_model and update_spring_model share, so that an
// update gives the build's bits: the particle order's key, each edge use's
// volume, and what the model derives from its exact sums.

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <tuple>
#include <vector>

#include "sim/spring_model.h"

namespace mtcut::sim::model_parts {

// The order particles are numbered in: along the longest axis of a box (the
// model's order box), ties by Morton (z-order) code in it, then by vertex id.
struct ParticleOrder {
  using Key = std::tuple<double, std::uint64_t, std::int32_t>;

  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
  int axis = 0;

  // The order in the box of all `rest_positions`.
  static ParticleOrder of(std::span<const Vec3> rest_positions);
  // The order in a model's order box.
  static ParticleOrder of(const SpringModel& model);
  Key key(const Vec3& p, VertId v) const;
};

// The volume each of a tet's six edges (kTetEdges order) adds to its
// spring's Van Gelder sum: `volume`, scaled by |e|^2 / (kShortEdgeFloor
// L_T)^2 for an edge shorter than kShortEdgeFloor times the longest, L_T.
std::array<double, 6> edge_use_volumes(const std::array<Vec3, 4>& corners, double volume);

// mass, inv_mass (0 where `fixed`, one flag per particle) and total_mass
// from particle_volume.
void finish_particles(SpringModel& model, const MaterialDef& material, const std::vector<char>& fixed);

// Spring s's rest length, stiffness and damping from its ends and spring_volume[s].
void set_spring_constants(SpringModel& model, std::size_t s, const MaterialDef& material);

// The volume terms of `tets` (tet_particles, rest_volume, volume_modulus)
// when the material has one; particle_of maps MT vertices to particles.
void set_volume_terms(SpringModel& model, std::span<const Tet> tets, const std::vector<std::int32_t>& particle_of,
                      const MaterialDef& material);

}  // namespace mtcut::sim::model_parts
