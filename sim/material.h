#pragma once
// The tissue's material, as a definition struct that config/materials/*.toml
// fill (through app/). SI units throughout: kg, m, s, Pa.

namespace mtcut::sim {

struct MaterialDef {
  double density = 1060.0;          // kg/m^3 (soft tissue, ~water)
  double youngs_modulus = 3000.0;   // Pa; springs get k_e = E * sum vol / |e|^2 (spring_model.h)
  // Rayleigh damping, the same at every resolution because it scales with
  // the stiffness and the mass it damps:
  double stiffness_damping = 0.001; // s;   spring dashpot c_e = beta * k_e (~critical for the finest modes)
  double mass_damping = 1.0;        // 1/s; air drag force -alpha * m * v
  double volume_stiffness = 0.0;    // volume-preserving term, as a multiple of E (0 = off)
};

}  // namespace mtcut::sim
