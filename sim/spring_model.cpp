#include "sim/spring_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "engine/tet_geometry.h"

namespace mtcut::sim {
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

// The Morton code of p quantised to 21 bits per axis in the box [lo, hi].
std::uint64_t morton_key(const engine::Vec3& p, const engine::Vec3& lo, const engine::Vec3& hi) {
  std::uint64_t key = 0;
  for (int k = 0; k < 3; ++k) {
    const double extent = hi[k] - lo[k];
    const double unit = extent > 0 ? (p[k] - lo[k]) / extent : 0.0;
    key |= spread_bits(static_cast<std::uint64_t>(std::clamp(unit, 0.0, 1.0) * 2097151.0)) << k;
  }
  return key;
}

}  // namespace

std::size_t SpringModel::num_fixed() const {
  return static_cast<std::size_t>(std::count(inv_mass.begin(), inv_mass.end(), 0.0));
}

engine::ValidationReport SpringModel::validate() const {
  engine::ValidationReport report;
  const std::size_t n = num_particles();
  if (particle_vertex.size() != n || inv_mass.size() != n || rest_position.size() != n)
    report.add("particle arrays differ in size");
  const std::size_t m = num_springs();
  if (spring_b.size() != m || rest_length.size() != m || stiffness.size() != m || damping.size() != m)
    report.add("spring arrays differ in size");
  if (!report.ok()) return report;

  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(mass[i] > 0)) report.add("particle " + std::to_string(i) + " has mass " + std::to_string(mass[i]));
    if (inv_mass[i] != 0 && std::abs(inv_mass[i] * mass[i] - 1) > 1e-12)
      report.add("particle " + std::to_string(i) + ": inv_mass is not 1 / mass");
    sum += mass[i];
  }
  if (std::abs(sum - total_mass) > 1e-12 * std::max(1.0, total_mass))
    report.add("masses sum to " + std::to_string(sum) + ", total_mass is " + std::to_string(total_mass));
  std::vector<std::pair<std::int32_t, std::int32_t>> edges;
  edges.reserve(m);
  for (std::size_t s = 0; s < m; ++s) {
    const auto a = spring_a[s], b = spring_b[s];
    if (a < 0 || b < 0 || static_cast<std::size_t>(a) >= n || static_cast<std::size_t>(b) >= n || a >= b) {
      report.add("spring " + std::to_string(s) + " joins particles " + std::to_string(a) + ", " + std::to_string(b));
      continue;
    }
    if (!(rest_length[s] > 0) || !(stiffness[s] > 0) || damping[s] < 0)
      report.add("spring " + std::to_string(s) + " has a non-positive length or stiffness");
    edges.emplace_back(a, b);
  }
  std::sort(edges.begin(), edges.end());
  if (std::adjacent_find(edges.begin(), edges.end()) != edges.end()) report.add("two springs join the same particles");
  for (std::size_t t = 0; t < tet_particles.size(); ++t)
    for (auto p : tet_particles[t])
      if (p < 0 || static_cast<std::size_t>(p) >= n) report.add("volume term " + std::to_string(t) + " is out of range");
  return report;
}

SpringModel build_spring_model(std::span<const Tet> tets, std::span<const Vec3> rest_positions,
                               const MaterialDef& material, const std::function<bool(VertId)>& is_fixed) {
  SpringModel model;
  model.mass_damping = material.mass_damping;

  // Dense particle numbering in Morton (z-order) of the rest positions, so
  // that the particles a spring joins sit close in memory: the spring loops
  // gather and scatter within cache lines.
  std::vector<VertId> used;
  {
    std::vector<char> seen(rest_positions.size(), 0);
    for (const Tet& tet : tets)
      for (const VertId v : tet)
        if (!seen[v.index()]) {
          seen[v.index()] = 1;
          used.push_back(v);
        }
  }
  engine::Vec3 lo = engine::Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const VertId v : used) {
    lo = lo.cwiseMin(rest_positions[v.index()]);
    hi = hi.cwiseMax(rest_positions[v.index()]);
  }
  std::vector<std::pair<std::uint64_t, VertId>> keyed;
  keyed.reserve(used.size());
  for (const VertId v : used) keyed.emplace_back(morton_key(rest_positions[v.index()], lo, hi), v);
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::int32_t> particle_of(rest_positions.size(), -1);
  for (const auto& [key, v] : keyed) {
    particle_of[v.index()] = static_cast<std::int32_t>(model.particle_vertex.size());
    model.particle_vertex.push_back(v);
    model.rest_position.push_back(rest_positions[v.index()]);
  }
  std::vector<std::array<std::int32_t, 4>> local(tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (int k = 0; k < 4; ++k) local[t][k] = particle_of[tets[t][k].index()];
  const std::size_t n = model.particle_vertex.size();
  model.mass.assign(n, 0.0);

  // Each tet edge once per tet, with that tet's volume: sort and merge.
  struct EdgeUse {
    std::int32_t a, b;
    double volume;
  };
  std::vector<EdgeUse> uses;
  uses.reserve(6 * tets.size());
  std::vector<double> volumes(tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const auto& p = local[t];
    const double vol = engine::signed_volume(model.rest_position[p[0]], model.rest_position[p[1]],
                                             model.rest_position[p[2]], model.rest_position[p[3]]);
    volumes[t] = vol;
    for (int k = 0; k < 4; ++k) model.mass[p[k]] += 0.25 * material.density * vol;
    for (const auto& e : engine::kTetEdges) {
      const auto a = p[e[0]], b = p[e[1]];
      uses.push_back({std::min(a, b), std::max(a, b), vol});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.a < y.a || (x.a == y.a && x.b < y.b);
  });
  for (std::size_t i = 0; i < uses.size();) {
    double volume_sum = 0;
    std::size_t j = i;
    for (; j < uses.size() && uses[j].a == uses[i].a && uses[j].b == uses[i].b; ++j) volume_sum += uses[j].volume;
    const double length = (model.rest_position[uses[i].b] - model.rest_position[uses[i].a]).norm();
    const double k = material.youngs_modulus * volume_sum / (length * length);
    model.spring_a.push_back(uses[i].a);
    model.spring_b.push_back(uses[i].b);
    model.rest_length.push_back(length);
    model.stiffness.push_back(k);
    model.damping.push_back(material.stiffness_damping * k);
    i = j;
  }

  model.inv_mass.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    model.inv_mass[i] = is_fixed && is_fixed(model.particle_vertex[i]) ? 0.0 : 1.0 / model.mass[i];
  model.total_mass = std::accumulate(model.mass.begin(), model.mass.end(), 0.0);

  if (material.volume_stiffness > 0) {
    model.tet_particles = std::move(local);
    model.rest_volume = std::move(volumes);
    model.volume_modulus = material.volume_stiffness * material.youngs_modulus;
  }
  return model;
}

}  // namespace mtcut::sim
