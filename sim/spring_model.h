#pragma once
// The mass-spring model of the tissue on one set of tets (the MT frontier in
// use): one particle per vertex, one spring per tet edge.
//
// Why this shape. It is the constant "model" of a step (MuJoCo's mjModel):
// rebuilt when the frontier changes or a cut lands, read-only while the
// integrator runs, struct-of-arrays so the spring loop streams through it.
// Particles are numbered densely 0..n-1 and carry the MT vertex they stand
// for, so state can be carried across rebuilds by vertex id.
//
// Stiffness: Van Gelder's formula ("Approximate simulation of elastic
// membranes by triangulated spring meshes", JGT 1998), in 3D:
//   k_e = E * sum_{T around e} vol(T) / |e|^2
// which makes a coarse and a fine tessellation of the same body about as
// stiff as each other (the sum of edge stiffnesses scales with volume / h^2).
// An edge shorter than kShortEdgeFloor times its tet's longest edge L_T
// counts as that long in its tet's term: k_e = E * sum vol(T) /
// max(|e|, kShortEdgeFloor * L_T)^2. Why: the MT cutter does not snap (see
// cut/mt/mt_cut.h), so a cut passing a hair from a vertex leaves slivers
// with a sub-micron edge (0.75 um in the default scenario), whose stiffness
// grows as 1 / |e| while their particles' mass shrinks as |e|: h^2 k / m
// reached 2e9, and CG took 100 iterations a frame after the cut. With the
// floor, a sliver's stiffness shrinks with its volume as its mass does.
// TetGen's quality meshes have no edge below the floor (the builtin box and
// ellipsoid, the shared liver.msh); an MT's coarser frontiers have a few
// (the liver scenario's first: 21 of 152,136 edge uses).
// Masses are lumped: each tet gives a quarter of density * vol(T) to each of
// its corners, so the total mass is exactly density * total volume.
// Both sums are exact and order-independent (sim/fixed_volume.h): the model
// keeps them, with how many tets make each, so that it can be updated by the
// tets a move or a cut changes (sim/spring_model_update.h) to the same bits
// as a build from scratch.

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "engine/tet_mesh.h"
#include "engine/validation.h"
#include "sim/fixed_volume.h"
#include "sim/material.h"

namespace mtcut::sim {

using engine::Tet;
using engine::Vec3;
using engine::VertId;

// The shortest an edge counts in Van Gelder's formula, as a fraction of its
// tet's longest edge (see above).
inline constexpr double kShortEdgeFloor = 0.1;

struct SpringModel {
  // --- particles (n_particles)
  std::vector<VertId> particle_vertex;  // the MT vertex each particle stands for
  std::vector<double> mass;             // lumped mass, kg
  std::vector<double> inv_mass;         // 1 / mass; 0 for a fixed particle
  std::vector<Vec3> rest_position;      // rest positions, m

  // --- springs (n_springs), one per distinct tet edge, sorted by (a, b):
  // the implicit solver's Gauss-Seidel sweeps walk them grouped by a
  std::vector<std::int32_t> spring_a;   // particle index, a < b
  std::vector<std::int32_t> spring_b;
  std::vector<double> rest_length;      // m
  std::vector<double> stiffness;        // N/m (Van Gelder)
  std::vector<double> damping;          // N s/m (beta * stiffness)

  // --- volume terms (n_tets when material.volume_stiffness > 0, else empty)
  std::vector<std::array<std::int32_t, 4>> tet_particles;
  std::vector<double> rest_volume;      // m^3
  // Energy 1/2 * volume_modulus * (V - V0)^2 / V0 per tet, Pa.
  double volume_modulus = 0.0;

  double mass_damping = 0.0;            // 1/s, from the material
  double total_mass = 0.0;              // kg

  // --- the exact sums the masses and stiffnesses come from
  std::vector<FixedVolume> particle_volume;  // (n_particles) sum of vol(T) over the tets around
  std::vector<std::int32_t> particle_tets;   // (n_particles) how many tets are around
  std::vector<FixedVolume> spring_volume;    // (n_springs) Van Gelder's sum (short edges scaled)
  std::vector<std::int32_t> spring_tets;     // (n_springs) how many tets use the edge
  // The box the particle order is keyed in: all the rest positions' (not
  // only the used ones', so that a change of tets keeps the survivors' order).
  Vec3 order_lo = Vec3::Zero(), order_hi = Vec3::Zero();

  std::size_t num_particles() const { return mass.size(); }
  std::size_t num_springs() const { return spring_a.size(); }
  std::size_t num_fixed() const;
  // (num_vertices) the particle of each vertex, -1 where none stands for it.
  std::vector<std::int32_t> particle_of(std::size_t num_vertices) const;

  // Sizes agree, ids in range, masses positive and summing to total_mass
  // and agreeing with their volume sums, springs positive and distinct and
  // used by a tet, a fixed particle has inv_mass 0.
  engine::ValidationReport validate() const;
};

// Builds the model on `tets` (vertex ids into rest_positions, positively
// oriented). `is_fixed(v)` pins the particle of MT vertex v. Throws
// engine::InputError, with a kUnits hint, when the body is too large for the
// model's fixed-point volume sums (a mesh in millimetres read as metres).
SpringModel build_spring_model(std::span<const Tet> tets, std::span<const Vec3> rest_positions,
                               const MaterialDef& material, const std::function<bool(VertId)>& is_fixed = {});

}  // namespace mtcut::sim
