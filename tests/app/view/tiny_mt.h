#pragma once
// Tiny hand-built MTs for the viewer's tests (one fragment: the fine mesh).

#include <vector>

#include "engine/mt/frontier.h"
#include "engine/mt/mt.h"
#include "sim/spring_model.h"

namespace mtcut::test {

// Four tets: A = (0,1,2,3) and B share a face; C is apart; E touches A at
// the point of vertex 0 through its own copy of it, vertex 12 (as a cut
// leaves two pieces). So three pieces: {A, B}, {C}, {E}.
engine::TetMesh three_piece_mesh();

// The MT of `mesh` at its finest frontier with a spring model on it.
struct TinyWorld {
  engine::Mt mt;
  engine::Frontier frontier;
  sim::SpringModel model;
};
TinyWorld make_tiny_world(const engine::TetMesh& mesh);

}  // namespace mtcut::test
