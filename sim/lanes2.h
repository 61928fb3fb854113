#pragma once
// Two doubles side by side, for the spring loops that handle two springs at
// a time (the explicit pass and the implicit system's assembly and sweeps).
// SSE2 is x86-64's baseline, so the same code and the same results on every
// x86-64 machine; elsewhere the vector extension's generic code.

#include <cmath>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace mtcut::sim {

// On a hot spring loop: also compiled for AVX2, chosen at load time when the
// CPU has it (an ifunc; x86-64 Linux). Not FMA: the AVX2 copy does the same
// two-lane operations in the same order, only VEX-encoded (three operands,
// fewer register copies), so its results are bit for bit the SSE2 ones.
// The bench box's assembly and SSOR solve: about 5% less time.
// -DMTCUT_SPRING_LOOP= builds the SSE2 code alone (to compare).
#if !defined(MTCUT_SPRING_LOOP)
#if defined(__x86_64__) && defined(__linux__) && defined(__GNUC__)
#define MTCUT_SPRING_LOOP __attribute__((target_clones("avx2", "default")))
#else
#define MTCUT_SPRING_LOOP
#endif
#endif

// Two lanes of doubles (GCC/Clang vector extension: SSE2 on x86-64).
using Lanes2 = double __attribute__((vector_size(16)));

// Added to a squared spring length before its root: exact for any real
// spring (m^2, below any), and a zero-length one gets a finite direction.
inline constexpr double kTinyLength2 = 1e-300;

// Lane-wise square root (SSE2's sqrtpd on x86-64).
inline Lanes2 sqrt_lanes(Lanes2 u) {
#if defined(__SSE2__)
  return _mm_sqrt_pd(u);
#else
  return Lanes2{std::sqrt(u[0]), std::sqrt(u[1])};
#endif
}

// Lane-wise max(0, u).
inline Lanes2 positive_part(Lanes2 u) {
#if defined(__SSE2__)
  return _mm_max_pd(u, Lanes2{0.0, 0.0});
#else
  return Lanes2{u[0] > 0 ? u[0] : 0.0, u[1] > 0 ? u[1] : 0.0};
#endif
}

}  // namespace mtcut::sim
