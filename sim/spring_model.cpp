#include "sim/spring_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "engine/input_error.h"
#include "engine/tet_geometry.h"
#include "sim/spring_model_parts.h"

namespace mtcut::sim {
namespace {

// One spring per distinct edge of the tets (particle indices), a < b,
// sorted by (a, b), each with its exact volume sum and use count. The edge
// uses are bucketed by a (a counting sort); each bucket is merged by b
// through slot_of, then sorted by b (a handful of springs per particle).
// O(n + m): a comparison sort of all the uses took most of a model rebuild.
void add_springs(const std::vector<std::array<std::int32_t, 4>>& tets, const std::vector<double>& volumes,
                 SpringModel& model) {
  const std::size_t n = model.rest_position.size();
  std::vector<std::int32_t> bucket_start(n + 1, 0);  // (n + 1) particle a's uses: [start[a], start[a + 1])
  for (const auto& p : tets)
    for (const auto& e : engine::kTetEdges) ++bucket_start[static_cast<std::size_t>(std::min(p[e[0]], p[e[1]])) + 1];
  for (std::size_t i = 0; i < n; ++i) bucket_start[i + 1] += bucket_start[i];
  struct Use {
    std::int32_t b;  // the edge's higher end
    double volume;   // of the tet using it (scaled down for a short edge)
  };
  std::vector<Use> uses(6 * tets.size());  // by lower end, in tet order
  {
    std::vector<std::int32_t> next(bucket_start.begin(), bucket_start.end() - 1);
    for (std::size_t t = 0; t < tets.size(); ++t) {
      std::array<Vec3, 4> corners;
      for (int k = 0; k < 4; ++k) corners[k] = model.rest_position[static_cast<std::size_t>(tets[t][k])];
      const std::array<double, 6> volume = model_parts::edge_use_volumes(corners, volumes[t]);
      for (std::size_t k = 0; k < 6; ++k) {
        const auto& e = engine::kTetEdges[k];
        const auto a = tets[t][e[0]], b = tets[t][e[1]];
        uses[static_cast<std::size_t>(next[static_cast<std::size_t>(std::min(a, b))]++)] = {std::max(a, b), volume[k]};
      }
    }
  }

  model.spring_b.reserve(uses.size() / 3);
  model.spring_volume.reserve(uses.size() / 3);
  model.spring_tets.reserve(uses.size() / 3);
  std::vector<std::int32_t> slot_of(n, -1);  // b's spring in the current bucket, if >= its first
  std::vector<std::uint64_t> row;              // the bucket's springs as b << 32 | index in the bucket
  std::vector<FixedVolume> row_volume;
  std::vector<std::int32_t> row_tets;
  for (std::size_t a = 0; a < n; ++a) {
    const std::size_t first = model.spring_b.size();
    row.clear();
    row_volume.clear();
    row_tets.clear();
    for (auto k = bucket_start[a]; k < bucket_start[a + 1]; ++k) {
      const Use& use = uses[static_cast<std::size_t>(k)];
      std::int32_t& slot = slot_of[static_cast<std::size_t>(use.b)];
      if (slot < static_cast<std::int32_t>(first)) {
        slot = static_cast<std::int32_t>(first + row.size());
        row.push_back(static_cast<std::uint64_t>(use.b) << 32 | row.size());
        row_volume.push_back(0);
        row_tets.push_back(0);
      }
      row_volume[static_cast<std::size_t>(slot) - first] += to_fixed_volume(use.volume);
      ++row_tets[static_cast<std::size_t>(slot) - first];
    }
    // Insertion sort by b of one word per spring (a handful per particle).
    for (std::size_t i = 1; i < row.size(); ++i) {
      const std::uint64_t key = row[i];
      std::size_t j = i;
      for (; j > 0 && row[j - 1] > key; --j) row[j] = row[j - 1];
      row[j] = key;
    }
    for (const std::uint64_t key : row) {
      model.spring_b.push_back(static_cast<std::int32_t>(key >> 32));
      model.spring_volume.push_back(row_volume[key & 0xffffffffu]);
      model.spring_tets.push_back(row_tets[key & 0xffffffffu]);
    }
    model.spring_a.resize(model.spring_b.size(), static_cast<std::int32_t>(a));
  }

  const std::size_t m = model.spring_b.size();
  for (auto* v : {&model.rest_length, &model.stiffness, &model.damping}) v->resize(m);
}

}  // namespace

std::size_t SpringModel::num_fixed() const {
  return static_cast<std::size_t>(std::count(inv_mass.begin(), inv_mass.end(), 0.0));
}

std::vector<std::int32_t> SpringModel::particle_of(std::size_t num_vertices) const {
  std::vector<std::int32_t> out(num_vertices, -1);
  for (std::size_t p = 0; p < particle_vertex.size(); ++p) out[particle_vertex[p].index()] = static_cast<std::int32_t>(p);
  return out;
}

engine::ValidationReport SpringModel::validate() const {
  engine::ValidationReport report;
  const std::size_t n = num_particles();
  if (particle_vertex.size() != n || inv_mass.size() != n || rest_position.size() != n)
    report.add("particle arrays differ in size");
  const std::size_t m = num_springs();
  if (spring_b.size() != m || rest_length.size() != m || stiffness.size() != m || damping.size() != m)
    report.add("spring arrays differ in size");
  if (particle_volume.size() != n || particle_tets.size() != n || spring_volume.size() != m ||
      spring_tets.size() != m)
    report.add("volume sums differ in size from what they sum for");
  if (!report.ok()) return report;

  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(mass[i] > 0)) report.add("particle " + std::to_string(i) + " has mass " + std::to_string(mass[i]));
    if (particle_tets[i] <= 0) report.add("particle " + std::to_string(i) + " is in no tet");
    // Every mass is the same multiple (density / 4) of its volume sum.
    const double volume = to_double(particle_volume[i]), volume0 = to_double(particle_volume[0]);
    if (std::abs(mass[i] * volume0 - mass[0] * volume) > 1e-12 * std::abs(mass[i] * volume0))
      report.add("particle " + std::to_string(i) + "'s mass is not its volume's share");
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
    if (spring_tets[s] <= 0) report.add("spring " + std::to_string(s) + " is in no tet");
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

  // Dense particle numbering along the longest axis of the rest positions'
  // box, ties by Morton (z-order) code: a sweep-plane order. The particles
  // a spring joins sit within about one cross-section of each other, so the
  // spring loops gather and scatter within a band that stays in cache, and
  // the implicit solver's Gauss-Seidel sweeps carry a change along the
  // body's length in one sweep. Against Morton order alone: the bench box's
  // CG 7.60 -> 6.98 iterations a frame and its frames 5-13% faster
  // (per-frame minima, alternated with a build in Morton order). The box is
  // all the positions', not only the used ones', so that the particles a
  // change of tets keeps stay in order (spring_model_update.h).
  const auto order = model_parts::ParticleOrder::of(rest_positions);
  model.order_lo = order.lo;
  model.order_hi = order.hi;
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
  std::vector<std::pair<model_parts::ParticleOrder::Key, VertId>> keyed;
  keyed.reserve(used.size());
  for (const VertId v : used) keyed.emplace_back(order.key(rest_positions[v.index()], v), v);
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
  model.particle_volume.assign(n, 0);
  model.particle_tets.assign(n, 0);

  std::vector<double> volumes(tets.size());
  double total_volume = 0;
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const auto& p = local[t];
    volumes[t] = engine::signed_volume(model.rest_position[p[0]], model.rest_position[p[1]],
                                       model.rest_position[p[2]], model.rest_position[p[3]]);
    total_volume += std::abs(volumes[t]);
  }
  // The sums stay in range (fixed_volume.h) while the body does: checked
  // before any is taken, since a larger body would overflow them.
  if (!(total_volume < kMaxFixedVolumeTerm))
    throw engine::InputError("the tets' volume, " + std::to_string(total_volume) +
                                 " m^3, is beyond what the spring model holds; the mesh's coordinates may be "
                                 "millimetres or centimetres",
                             {engine::InputHint::Kind::kUnits, {}});
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const FixedVolume volume = to_fixed_volume(volumes[t]);
    for (int k = 0; k < 4; ++k) {
      model.particle_volume[local[t][k]] += volume;
      ++model.particle_tets[local[t][k]];
    }
  }
  add_springs(local, volumes, model);
  for (std::size_t s = 0; s < model.num_springs(); ++s) model_parts::set_spring_constants(model, s, material);
  std::vector<char> fixed(n, 0);
  if (is_fixed)
    for (std::size_t i = 0; i < n; ++i) fixed[i] = is_fixed(model.particle_vertex[i]);
  model_parts::finish_particles(model, material, fixed);
  model_parts::set_volume_terms(model, tets, particle_of, material);
  return model;
}

}  // namespace mtcut::sim
