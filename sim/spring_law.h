#pragma once
// The spring law, in one place: Hooke plus a dashpot along the spring.
// Spring (a, b) of stiffness k, rest length L and damping c, with
// d = x_b - x_a (length l, direction n = d / l) and u = v_b - v_a, pulls a by
//
//   f_a = (k (l - L) + c n . u) n = (k + (c d . u - k L l) / l^2) d
//
// and b by -f_a. Both arrangements are here because they round differently:
// each integrator keeps the one its golden state hashes were taken with.
// Templates over the scalar: double for one spring, Lanes2 or Lanes4 for two
// or four springs lane by lane (the same operations in the same order in
// every lane, so a lane's result is the scalar one).

namespace mtcut::sim {

// k (l - L) + c n . u: f_a's component along n (N).
template <class T>
inline T spring_tension(const T& stiffness, const T& rest_length, const T& damping, const T& length,
                        const T& n_dot_u) {
  return stiffness * (length - rest_length) + damping * n_dot_u;
}

// coef = k + (c d . u - k L l) / l^2: f_a as a multiple of d (N/m), from
// k L and 1 / l^2 precomputed. The square root (l) and the division
// (1 / l^2) both take l^2 and run side by side, where n = d / l chains
// them. Written to `coef`, not returned: a Lanes4 returned by value changes
// the calling convention of code built without AVX, which GCC warns of.
template <class T>
inline void spring_coefficient(const T& stiffness, const T& stiffness_rest, const T& damping, const T& d_dot_u,
                               const T& length, const T& inv_length2, T& coef) {
  coef = stiffness + (damping * d_dot_u - stiffness_rest * length) * inv_length2;
}

}  // namespace mtcut::sim
