#pragma once
// The implicit system's spring blocks laid out for the Gauss-Seidel sweeps:
// each particle's springs in pairs, once.
//
// Why this shape. A sweep visits the particles in order and needs, for
// particle i, the sum of B_s u_o over the springs s = (i, o) on one side of
// i: its "row" (o > i, the backward sweep) or its "column" (o < i, the
// forward sweep). The blocks are stored once, by row: the backward sweep
// pulls a row's sum into registers (pull); the forward sweep, once u_i is
// known, pushes B_s u_i into an accumulator at each later end o of i's row
// (push), so that o's column sum is complete when the sweep reaches o. One
// copy halves what assembly writes (a second copy by column is a scatter
// spring after spring); each sweep still reads the blocks once. Two springs
// go side by side in the two lanes of an SSE2 register (x86-64's baseline,
// so the same code and results on every x86-64 machine): a particle's
// springs are padded to an even count with a zero block whose other end is
// the dummy particle n, which every vector the sweeps pull from keeps at 0
// and every accumulator has as a last entry that is never read.
//
// The layout (starts, other ends, each lane's spring) depends only on the
// springs' ends; it is rebuilt when they change, the blocks every assembly.

#include <cstdint>
#include <vector>

#include "engine/predicates.h"
#include "sim/lanes2.h"

namespace mtcut::sim {

using engine::Vec3;

// Two springs' blocks B = w w^T + across I, lane by lane.
struct BlockPair {
  Lanes2 wx, wy, wz, across;
};

// One side (rows or columns) of the paired layout.
struct PairedSide {
  std::vector<std::int32_t> start;  // (n + 1) particle i's pairs: [start[i], start[i + 1])
  std::vector<std::int32_t> other;  // (2 n_pairs) each lane's other end; n for a pad
  std::vector<BlockPair> blocks;    // (n_pairs) the blocks, lane k % 2 of pair k / 2; pads stay 0
  std::vector<std::int32_t> lane_spring;  // (2 n_pairs) each lane's spring; -1 for a pad

  // Lays out n particles' springs, spring s belonging to particle key[s]
  // with other end other_end[s], each particle's in spring order; blocks all 0.
  void build(std::size_t n, const std::vector<std::int32_t>& key, const std::vector<std::int32_t>& other_end);

  // sum over particle i's springs of B_s u[o_s]. u has n + 1 entries, u[n] = 0.
  Vec3 pull(std::size_t i, const Vec3* u) const {
    Lanes2 sx = {0, 0}, sy = {0, 0}, sz = {0, 0};
    const std::int32_t* o = other.data();
    for (std::int32_t k = start[i]; k < start[i + 1]; ++k) {
      const Vec3 &u0 = u[o[2 * k]], &u1 = u[o[2 * k + 1]];
      const Lanes2 ux = {u0.x(), u1.x()}, uy = {u0.y(), u1.y()}, uz = {u0.z(), u1.z()};
      const BlockPair& b = blocks[static_cast<std::size_t>(k)];
      const Lanes2 dot = b.wx * ux + b.wy * uy + b.wz * uz;
      sx += b.across * ux + dot * b.wx;
      sy += b.across * uy + dot * b.wy;
      sz += b.across * uz + dot * b.wz;
    }
    return {sx[0] + sx[1], sy[0] + sy[1], sz[0] + sz[1]};
  }

  // acc[o_s] += B_s u over particle i's springs. acc has n + 1 entries
  // (acc[n] takes the pads' zeros and is never read).
  void push(std::size_t i, const Vec3& u, Vec3* acc) const {
    const Lanes2 ux = {u.x(), u.x()}, uy = {u.y(), u.y()}, uz = {u.z(), u.z()};
    const std::int32_t* o = other.data();
    for (std::int32_t k = start[i]; k < start[i + 1]; ++k) {
      const BlockPair& b = blocks[static_cast<std::size_t>(k)];
      const Lanes2 dot = b.wx * ux + b.wy * uy + b.wz * uz;
      const Lanes2 cx = b.across * ux + dot * b.wx, cy = b.across * uy + dot * b.wy, cz = b.across * uz + dot * b.wz;
      acc[o[2 * k]] += Vec3(cx[0], cy[0], cz[0]);
      acc[o[2 * k + 1]] += Vec3(cx[1], cy[1], cz[1]);
    }
  }
};

}  // namespace mtcut::sim
