#pragma once
// Where each piece of the object is at the end of a run: what a user reads
// to see that a flap the scalpel cut off fell onto the floor while the held
// part stayed, without opening the snapshots.

#include <vector>

#include "sim/world.h"

namespace mtcut::app {

struct PieceReport {
  std::size_t tets = 0;              // frontier tets in the piece
  double rest_volume = 0;            // m^3, from rest positions
  engine::Vec3 centroid{0, 0, 0};    // mean deformed position of its particles
  double lowest_z = 0, highest_z = 0;  // deformed extent along z (the floor's normal)
  std::size_t held_particles = 0;    // fixed by the scenario's region
};

// The pieces of the World's frontier (app/run_pieces.h order: largest first).
std::vector<PieceReport> report_pieces(const sim::World& world);

}  // namespace mtcut::app
