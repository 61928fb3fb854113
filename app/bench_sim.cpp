#include "app/bench_sim.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "app/bench_timer.h"
#include "engine/mesh_loader.h"
#include "engine/mt/bvh.h"
#include "engine/quantiles.h"
#include "engine/stopwatch.h"
#include "sim/fixed_region.h"
#include "sim/forces.h"
#include "sim/spring_model_update.h"
#include "sim/spring_system.h"
#include "sim/stepper.h"

namespace mtcut::app {
namespace {

using sim::Vec3;

// The ceiling: the plainest spring loop, struct of arrays, no damping terms
// beyond air drag, no guard, no contacts. Same springs, same masses.
struct ReferenceLoop {
  std::vector<double> x, y, z, vx, vy, vz, fx, fy, fz, inv_mass;  // (n_particles)
  std::vector<std::int32_t> a, b;                                  // (n_springs)
  std::vector<double> k, rest;                                     // (n_springs)

  explicit ReferenceLoop(const sim::SpringModel& m) {
    const std::size_t n = m.num_particles();
    for (auto* v : {&x, &y, &z, &vx, &vy, &vz, &fx, &fy, &fz}) v->assign(n, 0.0);
    inv_mass = m.inv_mass;
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = m.rest_position[i].x();
      y[i] = m.rest_position[i].y();
      z[i] = m.rest_position[i].z();
    }
    a = m.spring_a;
    b = m.spring_b;
    k = m.stiffness;
    rest = m.rest_length;
  }

  void step(double h, double gz) {
    const std::size_t n = x.size(), m = a.size();
    for (std::size_t i = 0; i < n; ++i) {
      fx[i] = 0;
      fy[i] = 0;
      fz[i] = inv_mass[i] > 0 ? gz / inv_mass[i] : 0.0;
    }
    for (std::size_t s = 0; s < m; ++s) {
      const auto i = a[s], j = b[s];
      const double dx = x[j] - x[i], dy = y[j] - y[i], dz = z[j] - z[i];
      const double len = std::sqrt(dx * dx + dy * dy + dz * dz);
      const double f = k[s] * (len - rest[s]) / len;
      fx[i] += f * dx, fy[i] += f * dy, fz[i] += f * dz;
      fx[j] -= f * dx, fy[j] -= f * dy, fz[j] -= f * dz;
    }
    for (std::size_t i = 0; i < n; ++i) {
      vx[i] += h * inv_mass[i] * fx[i];
      vy[i] += h * inv_mass[i] * fy[i];
      vz[i] += h * inv_mass[i] * fz[i];
      x[i] += h * vx[i];
      y[i] += h * vy[i];
      z[i] += h * vz[i];
    }
  }
};

nlohmann::ordered_json rates(const BatchTiming& t, int steps, std::size_t springs) {
  const double per_step = t.median_seconds / steps;
  return {{"steps_per_s", 1.0 / per_step},
          {"ns_per_spring", 1e9 * per_step / static_cast<double>(springs)},
          {"spring_steps_per_s", static_cast<double>(springs) / per_step}};
}

// The parts of one implicit frame at a fixed state (the box at `state`),
// each the minimum over `repeats` timings: the assembly of A and of the
// residual at a start, the CG's start (its first preconditioned residual)
// and one CG iteration (the difference of
// two solves of fixed lengths over their difference). A frame costs about
// assemble + start + (mean iterations + 1/2) x iteration: the true-residual
// check that ends a solve is about half an iteration. Minima, not medians:
// on a shared host a part's time swings with the other jobs (1.7x between
// minutes on ours), its minimum much less, so these figures compare across
// runs where the frame times do not.
nlohmann::ordered_json implicit_frame_parts(const sim::SpringModel& model, const sim::Environment& env,
                                            const sim::SpringState& state, int repeats) {
  using Clock = std::chrono::steady_clock;
  const std::size_t n = model.num_particles();
  const double h = 1.0 / 60.0;
  const auto kind = sim::IntegratorDef{}.preconditioner;
  sim::SpringSystem system;
  // The start 0 (a warm start costs the assembly the same): r = b.
  std::vector<Vec3> f(n), residual(n), x(n, Vec3::Zero());
  const std::vector<Vec3> zero_start(n, Vec3::Zero());
  sim::compute_body_forces(model, env, state, f);
  const auto timed = [](const auto& work) {
    const auto start = Clock::now();
    work();
    return engine::seconds_since(start);
  };
  // The solve from 0 with a fixed iteration count (tolerance 0: no early
  // stop; infinite: stops before the first iteration, with no check).
  const auto solve = [&](double tolerance2, int iterations) {
    std::fill(x.begin(), x.end(), Vec3::Zero());
    return timed([&] { system.solve_from_residual(kind, residual, tolerance2, iterations, x); });
  };
  constexpr int kShort = 5, kLong = 15;
  double assemble = 1e300, start = 1e300, short_solve = 1e300, long_solve = 1e300;
  for (int r = 0; r < repeats; ++r) {
    assemble = std::min(assemble, timed([&] { system.assemble(model, state, f, h, zero_start, residual); }));
    start = std::min(start, solve(std::numeric_limits<double>::infinity(), kLong));
    short_solve = std::min(short_solve, solve(0.0, kShort));
    long_solve = std::min(long_solve, solve(0.0, kLong));
  }
  return {{"assemble_ms", 1e3 * assemble},
          {"cg_start_ms", 1e3 * start},
          {"cg_iteration_ms", 1e3 * (long_solve - short_solve) / (kLong - kShort)},
          {"repeats", repeats}};
}

// What the World pays after a cut instead of a build: the model updated by
// the tets that changed (sim/spring_model_update.h). The change is a cut's
// in kind: the tets in a ball at the box's centre (about 1% of them) split
// at a new vertex each, into four.
nlohmann::ordered_json time_model_update(const engine::TetMesh& mesh, const sim::SpringModel& model,
                                         const sim::MaterialDef& material, const sim::FixedRegion& fixed,
                                         int runs) {
  std::vector<Vec3> positions(mesh.positions.begin(), mesh.positions.end());
  // Over the positions with the new vertices: the update asks about those.
  const auto is_fixed = [&](engine::VertId v) { return fixed.contains(v, positions[v.index()]); };
  engine::Aabb box;
  for (const Vec3& p : positions) box.extend(p);
  const Vec3 centre = box.center();
  const double radius = 0.17 * (box.hi - box.lo).minCoeff();
  std::vector<engine::Tet> removed, added, tets;
  for (const engine::Tet& t : mesh.tets) {
    if ((positions[t[0].index()] - centre).norm() >= radius) {
      tets.push_back(t);
      continue;
    }
    removed.push_back(t);
    const engine::VertId c(static_cast<std::int32_t>(positions.size()));
    positions.push_back(0.25 * (positions[t[0].index()] + positions[t[1].index()] + positions[t[2].index()] +
                                positions[t[3].index()]));
    for (const engine::Tet& piece : {engine::Tet{c, t[1], t[2], t[3]}, engine::Tet{t[0], c, t[2], t[3]},
                                     engine::Tet{t[0], t[1], c, t[3]}, engine::Tet{t[0], t[1], t[2], c}}) {
      added.push_back(piece);
      tets.push_back(piece);
    }
  }
  const BatchTiming update = time_batches(runs, [&] {
    const std::optional<sim::SpringModel> updated =
        sim::update_spring_model(model, removed, added, tets, positions, material, is_fixed);
    if (!updated || updated->num_particles() != model.num_particles() + removed.size())
      throw std::logic_error("bench sim: the updated model differs");
  });
  return {{"model_update_ms", 1e3 * update.median_seconds},
          {"removed_tets", removed.size()},
          {"added_tets", added.size()}};
}

}  // namespace

nlohmann::ordered_json run_sim_bench(const SimBenchDef& def) {
  engine::MeshLoadDef load;
  load.builtin_tets = def.tets;
  load.builtin_size = Vec3(0.2, 0.1, 0.1);
  const engine::TetMesh mesh = engine::load_mesh("builtin:box", load).mesh;
  sim::FixedRegion fixed;
  fixed.kind = sim::FixedRegion::Kind::kHalfSpace;
  fixed.normal = Vec3(-1, 0, 0);
  fixed.offset = -(0.1 - 1e-9);  // the face x = +0.1
  sim::MaterialDef material;     // liver-like defaults
  const auto is_fixed = [&](engine::VertId v) { return fixed.contains(v, mesh.position(v)); };
  const sim::SpringModel model = sim::build_spring_model(mesh.tets, mesh.positions, material, is_fixed);
  sim::Environment env;

  nlohmann::ordered_json out;
  out["mesh"] = {{"vertices", model.num_particles()}, {"springs", model.num_springs()}, {"tets", mesh.num_tets()}};
  // The spring model built from the tets, as the World rebuilds it after
  // every cut and LOD change (a frame that pays it besides its step).
  const BatchTiming build = time_batches(def.runs, [&] {
    const sim::SpringModel rebuilt = sim::build_spring_model(mesh.tets, mesh.positions, material, is_fixed);
    if (rebuilt.num_springs() != model.num_springs()) throw std::logic_error("bench sim: the rebuilt model differs");
  });
  out["model_build_ms"] = 1e3 * build.median_seconds;
  out["model_update"] = time_model_update(mesh, model, material, fixed, def.runs);
  const double h_explicit = 0.5 * sim::critical_time_step(model);
  out["explicit_dt"] = h_explicit;

  // The reference and the stepper's sub-steps in alternation, so that
  // vs_reference compares them under the same load (time_batch_pair).
  ReferenceLoop reference(model);
  sim::Stepper stepper;
  sim::SpringState state = sim::rest_state(model);
  // As in a frame: one guarded step of many sub-steps.
  sim::IntegratorDef explicit_def;
  explicit_def.kind = sim::IntegratorKind::kSymplecticEuler;
  explicit_def.substeps = def.steps;
  const PairedTiming paired = time_batch_pair(
      def.runs, [&] { for (int s = 0; s < def.steps; ++s) reference.step(h_explicit, env.gravity.z()); },
      [&] { stepper.step(model, env, explicit_def, state, h_explicit * def.steps); });
  out["reference_loop"] = rates(paired.a, def.steps, model.num_springs());
  out["symplectic_euler"] = rates(paired.b, def.steps, model.num_springs());
  out["symplectic_euler"]["vs_reference"] = paired.a_over_b;

  // The implicit step at dt = 1/60 s, at the default CG tolerance and at a
  // looser one (the cost / accuracy trade-off a user can make). Every run
  // replays the same trajectory: `frames` frames from rest with a fresh
  // stepper (the box falls, swings and starts to settle; CG needs fewer
  // iterations as it does). So every run does the same work whatever
  // --runs is, and the time per frame and the mean iterations describe the
  // same frames.
  std::uint64_t implicit_refused = 0;
  // The box one second in (swinging) at the default tolerance, taken in the
  // untimed warm-up run, for the frame's parts.
  sim::SpringState parts_state;
  for (const double tolerance : {sim::IntegratorDef{}.cg_tolerance, 1e-2}) {
    sim::IntegratorDef implicit_def;
    implicit_def.cg_tolerance = tolerance;
    long cg_iterations = 0;  // in one run: every run takes the same steps
    // Each run's first frame: the solver's layout and scratch built for a
    // model it has not seen, with no warm start (what follows a cut or an
    // LOD change, at worst).
    std::vector<double> first_frame_seconds;
    const BatchTiming impl = time_batches(def.runs, [&] {
      sim::SpringState implicit_state = sim::rest_state(model);
      sim::Stepper implicit_stepper;
      cg_iterations = 0;
      for (int s = 0; s < def.frames; ++s) {
        const auto start = std::chrono::steady_clock::now();
        cg_iterations += implicit_stepper.step(model, env, implicit_def, implicit_state, 1.0 / 60.0).cg_iterations;
        if (s == 0)
          first_frame_seconds.push_back(engine::seconds_since(start));
        if (s == std::min(60, def.frames) - 1 && parts_state.x.empty()) parts_state = implicit_state;
      }
      implicit_refused += implicit_stepper.refused_steps();
    });
    first_frame_seconds.erase(first_frame_seconds.begin());  // the warm-up run's
    const std::string key = tolerance == sim::IntegratorDef{}.cg_tolerance ? "implicit_euler" : "implicit_euler_loose";
    out[key] = rates(impl, def.frames, model.num_springs());
    out[key]["ms_per_frame_60hz"] = 1e3 * impl.median_seconds / def.frames;
    out[key]["mean_cg_iterations"] = static_cast<double>(cg_iterations) / def.frames;
    out[key]["cg_tolerance"] = tolerance;
    out[key]["frames_per_run"] = def.frames;
    out[key]["first_frame_ms"] = 1e3 * engine::median(first_frame_seconds);
  }
  out["implicit_euler"]["frame_parts"] = implicit_frame_parts(model, env, parts_state, 10 * def.runs);
  out["refused_steps"] = stepper.refused_steps() + implicit_refused;
  out["runs"] = def.runs;
  return out;
}

}  // namespace mtcut::app
