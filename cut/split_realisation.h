#pragma once
// Positions for the labels of a configuration, without any mesh: a tet, a
// plane through it that puts its vertices on the configuration's sides,
// crossings where the plane meets the edges, face points on their section
// segments. Recipes are oriented in the fixed reference realisation and
// checked (by the piece filler and the tests) in random ones, planar or
// "bent" (crossings and face points anywhere on their edges and faces, as
// snapping makes them), so that no tet's orientation depends on where the
// cut points happen to be.

#include <array>
#include <random>

#include "cut/cut_trace.h"

namespace mtcut::cut {

using LabelPositions = std::array<engine::Vec3, kLabelCount>;

// The fixed generic realisation: a fixed tet, fixed distances to the plane.
LabelPositions reference_positions(const TetConfig& config, const CutTrace& trace);

// A random realisation: a random tet (not too flat); planar as above with
// random distances, or bent.
LabelPositions random_positions(const TetConfig& config, const CutTrace& trace, std::mt19937_64& rng, bool planar);

}  // namespace mtcut::cut
