#pragma once
// What the user sees of the tissue: the outer faces of the MT's finest level
// (the organ's own surface and the finest faces of every cut), each vertex
// carried by a tet of the frontier the springs are simulated on.
//
// Why. With a free boundary (MtBuildOptions::max_surface_deviation) the
// coarse levels' surface lies up to that bound off the organ's, so a coarse
// frontier's own surface, drawn, shows a coarse outline away from the blade.
// The finest surface is the organ the user loaded and the incision at full
// detail; the simulation moves it through the frontier tets, as an embedded
// (visual) mesh follows a coarse simulation mesh in SOFA's barycentric
// mapping. A vertex's carrier and weights change only when the MT or the
// frontier does, so they are found then (a short walk up the DAG per
// vertex), and a frame only blends particle positions.
//
// The carrier. A surface vertex v is a corner of a live finest tet T (the
// tet of a face it is on). Up the DAG from T: while T is not in the
// frontier, its death fragment is in S, and of the live tets that fragment
// creates, the walk takes the one holding a point just inside T next to v
// (so a vertex on a crack goes to its own side's tets) or, where none holds
// it (a free boundary leaves the finer surface outside the coarser one), the
// one it lies least outside of. The walk stays in T's piece: every fragment
// lies in one piece (cut/mt/mt_pieces.h). The weights are v's barycentric
// coordinates in its carrier; outside it, the same affine map extended: the
// vertex moves with its carrier as a point of a linear element does.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/mt/frontier.h"
#include "engine/mt/mt.h"
#include "engine/surface_mesh.h"
#include "engine/validation.h"
#include "sim/spring_model.h"

namespace mtcut::sim {

struct FinestSurface {
  std::vector<std::array<std::int32_t, 3>> faces;  // outward oriented, over `vertices`
  std::vector<engine::TetId> face_tet;             // (faces) the live finest tet each face bounds
  std::vector<engine::VertId> vertices;            // the MT vertex of each surface vertex, ascending
  std::vector<engine::TetId> carrier;              // (vertices) the frontier tet carrying it
  std::vector<std::array<std::int32_t, 4>> particle;  // (vertices) the carrier's corners as particles
  std::vector<std::array<double, 4>> weight;          // (vertices) barycentric, summing to 1
  std::size_t outside = 0;  // vertices outside their carrier (weights extrapolated)
  std::size_t walked = 0;   // vertices whose carrier was found anew (not kept from `previous`)
  std::uint64_t mt_instance = 0;  // Mt::instance() it was carried on
  std::uint64_t mt_revision = 0;  // and its Mt::revision()

  std::size_t num_faces() const { return faces.size(); }
  std::size_t num_vertices() const { return vertices.size(); }
};

// The finest surface of `mt`, carried by the tets of `frontier`, whose
// vertices `model` simulates (a model built on the frontier; else
// std::invalid_argument). With `previous` (the surface carried on the same
// MT object, before its last cuts or frontier moves), a vertex whose
// carrier is still a live frontier tet keeps it and its weights (after a
// cut, if the vertex lies strictly inside it): only the others walk, a few
// hundred when the frontier moves around the blade.
FinestSurface carry_finest_surface(const engine::Mt& mt, const engine::Frontier& frontier, const SpringModel& model,
                                   const FinestSurface* previous = nullptr);

// The surface vertices' positions from the particles' `x` (out: num_vertices()).
void place_finest_surface(const FinestSurface& surface, std::span<const Vec3> x, std::vector<Vec3>& out);

// The surface at the particles' `x`, as a surface mesh.
engine::SurfaceMesh deformed_finest_surface(const FinestSurface& surface, std::span<const Vec3> x);

// Every face is a finest tet's surface face and every such face is one; each
// carrier is a frontier tet, its corners' particles and the weights say
// where the vertex lies in rest space (the weighted rest positions of the
// carrier's corners are the vertex's, to 1e-9 of the MT's size), and the
// weights of a vertex inside its carrier are not negative.
engine::ValidationReport validate_finest_surface(const FinestSurface& surface, const engine::Mt& mt,
                                                 const engine::Frontier& frontier, const SpringModel& model);

}  // namespace mtcut::sim
