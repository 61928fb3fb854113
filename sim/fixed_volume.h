#pragma once
// Exact, order-independent sums of tet volumes.
//
// Why. A spring model's masses and stiffnesses are sums over the tets
// around a particle or an edge. Summed in doubles, the result depends on
// the order of the tets, so a model updated by the few tets an LOD move or
// a cut changes (spring_model_update.h) would drift from the model built
// from scratch, and its total mass would stop being exact. Each term is
// instead rounded once, on its own, to an integer count of 2^-110 m^3 and
// summed in 128 bits: integer sums are exact and commute, so adding and
// removing terms in any order gives the same bits as summing the final set,
// and a term removed leaves nothing behind. The rounding step is far below
// double precision for any real tet (1e-20 m^3 keeps 13 digits); the range
// holds bodies of up to 2^16 m^3.

#include <cmath>
#include <stdexcept>
#include <string>

namespace mtcut::sim {

__extension__ typedef __int128 FixedVolume;  // a count of 2^-110 m^3

// The largest |term| to_fixed_volume accepts, m^3: with the sums of a body
// below 2^17 m^3 the 128 bits never overflow.
inline constexpr double kMaxFixedVolumeTerm = 0x1p16;

// v rounded toward 0 to a multiple of 2^-110 m^3. Throws on a term that is
// not finite or beyond kMaxFixedVolumeTerm.
inline FixedVolume to_fixed_volume(double v) {
  if (!(std::abs(v) < kMaxFixedVolumeTerm))
    throw std::invalid_argument("tet volume " + std::to_string(v) + " m^3 is out of range for the spring model");
  return static_cast<FixedVolume>(v * 0x1p110);
}

// The sum back in m^3 (rounded to nearest).
inline double to_double(FixedVolume sum) { return static_cast<double>(sum) * 0x1p-110; }

}  // namespace mtcut::sim
