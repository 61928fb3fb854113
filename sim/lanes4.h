#pragma once
// Four doubles side by side (GCC/Clang vector extension): four springs in
// the lanes of one register, or one particle's x, y, z and a zero pad, which
// a single 32-byte load reads. In code built for AVX2 (MTCUT_SPRING_LOOP's
// clone) each operation is one instruction; in the SSE2 baseline, two.

#include <cstdint>

namespace mtcut::sim {

// Aligned to 32 bytes in every build: the baseline alone would align it to
// 16, and the AVX2 clone's aligned loads would fault on such an address.
using Lanes4 = double __attribute__((vector_size(32), aligned(32)));
using LaneIndex4 = std::int64_t __attribute__((vector_size(32)));  // shuffle masks

// A particle's (x, y, z, 0) in one aligned 32-byte slot. A struct, so that
// it can be a std::vector's element (the vector type's attribute would be
// dropped from a template argument); it takes Lanes4's alignment.
struct Slot4 {
  Lanes4 p;
};
static_assert(alignof(Slot4) == 32 && sizeof(Slot4) == 32);

}  // namespace mtcut::sim
