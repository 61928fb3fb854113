#pragma once
// A spring model updated by the tets a frontier move or a cut changed,
// instead of built again from every tet.
//
// Why. A move or a cut changes a few hundred of a frontier's tens of
// thousands of tets, but build_spring_model visits them all and sorts the
// particles: ~3.5 ms for the liver's 26k tets alone, 5-7 ms beside the
// physics, and a cut's frame waited for it. The update visits only the
// changed tets, then copies the model's arrays once, merging in what is new
// (O(changed log n + n + m), no sort of the whole).
//
// It gives build_spring_model's bits exactly (its test compares them over
// random sequences of moves and cuts): the sums are exact whatever the
// order of their terms (fixed_volume.h); the particle order's key depends
// only on a vertex's rest position, its id and the order box of all rest
// positions, so the particles a change keeps stay in their order and the
// new ones are merged in by key; the springs that stay keep their order
// under that renumbering and the new ones are merged in by (a, b); a
// spring's constants come from its ends and its sum only, and are copied
// when neither changed.

#include <optional>

#include "sim/spring_model.h"

namespace mtcut::sim {

// What build_spring_model(tets, rest_positions, material, is_fixed) gives,
// from `old`: built (or updated) with the same material and fixed region
// on the tets that `tets` held before `removed` left them and `added`
// joined. `tets` orders only the volume terms. nullopt when the box of the
// rest positions is not old's order box (the MT grew past it): build
// instead. Throws std::invalid_argument when a removed tet is not in old.
std::optional<SpringModel> update_spring_model(const SpringModel& old, std::span<const Tet> removed,
                                               std::span<const Tet> added, std::span<const Tet> tets,
                                               std::span<const Vec3> rest_positions, const MaterialDef& material,
                                               const std::function<bool(VertId)>& is_fixed = {});

}  // namespace mtcut::sim
