#include "sim/spring_model_parts.h"

#include <algorithm>
#include <numeric>

#include "engine/mt/bvh.h"
#include "engine/tet_geometry.h"

namespace mtcut::sim::model_parts {
namespace {

// Spreads the low 21 bits of x to every third bit.
std::uint64_t spread_bits(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

ParticleOrder order_in(const Vec3& lo, const Vec3& hi) {
  ParticleOrder order;
  order.lo = lo;
  order.hi = hi;
  (hi - lo).maxCoeff(&order.axis);
  return order;
}

}  // namespace

ParticleOrder ParticleOrder::of(std::span<const Vec3> rest_positions) {
  if (rest_positions.empty()) return order_in(Vec3::Zero(), Vec3::Zero());
  engine::Aabb box;
  for (const Vec3& p : rest_positions) box.extend(p);
  return order_in(box.lo, box.hi);
}

ParticleOrder ParticleOrder::of(const SpringModel& model) { return order_in(model.order_lo, model.order_hi); }

ParticleOrder::Key ParticleOrder::key(const Vec3& p, VertId v) const {
  // The Morton code of p quantised to 21 bits per axis in the box.
  std::uint64_t morton = 0;
  for (int k = 0; k < 3; ++k) {
    const double extent = hi[k] - lo[k];
    const double unit = extent > 0 ? (p[k] - lo[k]) / extent : 0.0;
    morton |= spread_bits(static_cast<std::uint64_t>(std::clamp(unit, 0.0, 1.0) * 2097151.0)) << k;
  }
  return {p[axis], morton, v.value};
}

std::array<double, 6> edge_use_volumes(const std::array<Vec3, 4>& corners, double volume) {
  std::array<double, 6> length2{};
  double longest2 = 0;
  for (std::size_t k = 0; k < 6; ++k) {
    const auto& e = engine::kTetEdges[k];
    length2[k] = (corners[static_cast<std::size_t>(e[0])] - corners[static_cast<std::size_t>(e[1])]).squaredNorm();
    longest2 = std::max(longest2, length2[k]);
  }
  // The sum over |e|^2 is then sum vol(T) / max(|e|, kShortEdgeFloor L_T)^2.
  const double shortest2 = kShortEdgeFloor * kShortEdgeFloor * longest2;
  std::array<double, 6> out;
  for (std::size_t k = 0; k < 6; ++k) out[k] = length2[k] < shortest2 ? volume * (length2[k] / shortest2) : volume;
  return out;
}

void finish_particles(SpringModel& model, const MaterialDef& material, const std::vector<char>& fixed) {
  const std::size_t n = model.particle_volume.size();
  const double quarter_density = 0.25 * material.density;  // each tet gives a quarter of its mass to each corner
  model.mass.resize(n);
  model.inv_mass.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    model.mass[i] = quarter_density * to_double(model.particle_volume[i]);
    model.inv_mass[i] = fixed[i] ? 0.0 : 1.0 / model.mass[i];
  }
  model.total_mass = std::accumulate(model.mass.begin(), model.mass.end(), 0.0);
  model.mass_damping = material.mass_damping;
}

void set_spring_constants(SpringModel& model, std::size_t s, const MaterialDef& material) {
  const Vec3& pa = model.rest_position[static_cast<std::size_t>(model.spring_a[s])];
  const Vec3& pb = model.rest_position[static_cast<std::size_t>(model.spring_b[s])];
  const double length = (pb - pa).norm();
  const double k = material.youngs_modulus * to_double(model.spring_volume[s]) / (length * length);
  model.rest_length[s] = length;
  model.stiffness[s] = k;
  model.damping[s] = material.stiffness_damping * k;
}

void set_volume_terms(SpringModel& model, std::span<const Tet> tets, const std::vector<std::int32_t>& particle_of,
                      const MaterialDef& material) {
  model.tet_particles.clear();
  model.rest_volume.clear();
  model.volume_modulus = 0;
  if (!(material.volume_stiffness > 0)) return;
  model.tet_particles.resize(tets.size());
  model.rest_volume.resize(tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t) {
    auto& p = model.tet_particles[t];
    for (int k = 0; k < 4; ++k) p[k] = particle_of[tets[t][k].index()];
    model.rest_volume[t] = engine::signed_volume(model.rest_position[p[0]], model.rest_position[p[1]],
                                                 model.rest_position[p[2]], model.rest_position[p[3]]);
  }
  model.volume_modulus = material.volume_stiffness * material.youngs_modulus;
}

}  // namespace mtcut::sim::model_parts
