#include "sim/finest_surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "engine/mt/bvh.h"
#include "engine/tet_adjacency.h"
#include "engine/tet_geometry.h"

namespace mtcut::sim {
namespace {

using engine::FragId;
using engine::Mt;
using engine::TetId;
using engine::VertId;

// How far toward its tet's centroid the point is taken that chooses a
// vertex's tet one fragment coarser: inside the tet it comes from, off
// every face through the vertex (a crack's among them).
constexpr double kInward = 1e-3;
// Below this weight a vertex counts as outside its carrier (rounding of a
// vertex on the carrier's face); above kInside, strictly inside it.
constexpr double kOutside = -1e-9;
constexpr double kInside = 1e-9;

double least_weight(const std::array<double, 4>& w) { return *std::min_element(w.begin(), w.end()); }

// The frontier tet carrying point p of finest tet `t`, up the DAG
// (finest_surface.h).
TetId walk_to_frontier(const Mt& mt, const engine::Frontier& frontier, TetId t, const Vec3& p) {
  while (!frontier.has_tet(t)) {
    const FragId f = mt.death(t);
    if (!f.valid() || f == mt.drain())
      throw std::logic_error("carry_finest_surface: a tet outside the frontier dies in no fragment of it");
    const std::array<Vec3, 4> from = mt.corners(t);
    const Vec3 centroid = 0.25 * (from[0] + from[1] + from[2] + from[3]);
    const Vec3 q = p + kInward * (centroid - p);
    TetId best;
    double best_weight = -std::numeric_limits<double>::infinity();
    for (TetId c : mt.created(f)) {
      if (!mt.alive(c)) continue;
      const double w = least_weight(engine::barycentric(mt.corners(c), q));
      if (w > best_weight) best_weight = w, best = c;
    }
    if (!best.valid()) throw std::logic_error("carry_finest_surface: a fragment of the frontier creates no live tet");
    t = best;
  }
  return t;
}

}  // namespace

FinestSurface carry_finest_surface(const Mt& mt, const engine::Frontier& frontier, const SpringModel& model,
                                   const FinestSurface* previous) {
  FinestSurface out;
  out.mt_instance = mt.instance();
  // The faces: every surface face of a live finest tet.
  constexpr std::int32_t kOnSurface = -2;  // not numbered yet
  std::vector<std::int32_t> local(mt.num_vertices(), -1);
  std::vector<std::array<VertId, 3>> faces;
  for (TetId t : mt.created(mt.root())) {
    if (!mt.alive(t)) continue;
    const engine::FaceMask mask = mt.boundary_mask(t);
    if (mask == 0) continue;
    for (int f = 0; f < 4; ++f) {
      if (!(mask & (1u << f))) continue;
      faces.push_back(engine::face_vertices(mt.tet(t), f));
      out.face_tet.push_back(t);
      for (VertId v : faces.back()) local[v.index()] = kOnSurface;
    }
  }
  for (std::size_t v = 0; v < local.size(); ++v)
    if (local[v] == kOnSurface) {
      local[v] = static_cast<std::int32_t>(out.vertices.size());
      out.vertices.emplace_back(v);
    }
  out.faces.reserve(faces.size());
  for (const auto& face : faces)
    out.faces.push_back({local[face[0].index()], local[face[1].index()], local[face[2].index()]});

  // The carriers: kept where the previous one still is a live frontier
  // tet, else walked from a finest tet of the vertex. After a cut, only
  // those that hold their vertex strictly inside: a crack that separates a
  // vertex from its carrier goes through the carrier, which it then splits
  // (killing it), when the vertex is inside; a vertex on the carrier's
  // surface or outside it (a free boundary) may be cut off from it by a
  // crack that leaves the carrier whole.
  const std::size_t n = out.vertices.size();
  out.carrier.assign(n, TetId());
  out.weight.resize(n);
  out.mt_revision = mt.revision();
  const bool reuse = previous && previous->mt_instance == mt.instance();
  const bool cut_since = reuse && previous->mt_revision != mt.revision();
  if (reuse)
    for (std::size_t i = 0; i < previous->vertices.size(); ++i) {
      const VertId v = previous->vertices[i];
      const TetId c = previous->carrier[i];
      if (v.index() >= local.size() || local[v.index()] < 0 || !mt.alive(c) || !frontier.has_tet(c)) continue;
      if (cut_since && !(least_weight(previous->weight[i]) > kInside)) continue;
      const auto k = static_cast<std::size_t>(local[v.index()]);
      out.carrier[k] = c;
      out.weight[k] = previous->weight[i];
    }
  for (std::size_t i = 0; i < out.faces.size(); ++i)
    for (std::int32_t k : out.faces[i]) {
      const auto u = static_cast<std::size_t>(k);
      if (out.carrier[u].valid()) continue;
      const Vec3& p = mt.position(out.vertices[u]);
      out.carrier[u] = walk_to_frontier(mt, frontier, out.face_tet[i], p);
      out.weight[u] = engine::barycentric(mt.corners(out.carrier[u]), p);
      ++out.walked;
    }

  // The carriers' corners as particles (numbered anew with every model).
  const std::vector<std::int32_t> particle_of = model.particle_of(mt.num_vertices());
  out.particle.resize(n);
  for (std::size_t u = 0; u < n; ++u) {
    const engine::Tet& tet = mt.tet(out.carrier[u]);
    for (int k = 0; k < 4; ++k) {
      out.particle[u][static_cast<std::size_t>(k)] = particle_of[tet[static_cast<std::size_t>(k)].index()];
      if (out.particle[u][static_cast<std::size_t>(k)] < 0)
        throw std::invalid_argument("carry_finest_surface: the model does not simulate frontier vertex " +
                                    std::to_string(tet[static_cast<std::size_t>(k)].index()));
    }
    out.outside += least_weight(out.weight[u]) < kOutside;
  }
  return out;
}

void place_finest_surface(const FinestSurface& surface, std::span<const Vec3> x, std::vector<Vec3>& out) {
  out.resize(surface.num_vertices());
  for (std::size_t u = 0; u < out.size(); ++u) {
    const auto& p = surface.particle[u];
    const auto& w = surface.weight[u];
    out[u] = w[0] * x[static_cast<std::size_t>(p[0])] + w[1] * x[static_cast<std::size_t>(p[1])] +
             w[2] * x[static_cast<std::size_t>(p[2])] + w[3] * x[static_cast<std::size_t>(p[3])];
  }
}

engine::SurfaceMesh deformed_finest_surface(const FinestSurface& surface, std::span<const Vec3> x) {
  engine::SurfaceMesh mesh;
  place_finest_surface(surface, x, mesh.positions);
  mesh.triangles = surface.faces;
  return mesh;
}

engine::ValidationReport validate_finest_surface(const FinestSurface& surface, const Mt& mt,
                                                 const engine::Frontier& frontier, const SpringModel& model) {
  engine::ValidationReport report;
  const std::size_t n = surface.num_vertices();
  if (surface.face_tet.size() != surface.num_faces() || surface.carrier.size() != n ||
      surface.particle.size() != n || surface.weight.size() != n) {
    report.add("finest surface: its arrays are sized for other counts");
    return report;
  }
  if (surface.mt_instance != mt.instance()) report.add("finest surface: carried on another MT object");
  // The faces: exactly the surface faces of the live finest tets.
  std::vector<std::array<std::int32_t, 4>> expected, found;  // (tet, sorted face)
  const auto sorted = [](TetId t, std::array<std::int32_t, 3> f) {
    std::sort(f.begin(), f.end());
    return std::array<std::int32_t, 4>{t.value, f[0], f[1], f[2]};
  };
  for (TetId t : mt.created(mt.root())) {
    if (!mt.alive(t)) continue;
    for (int f = 0; f < 4; ++f)
      if (mt.boundary_mask(t) & (1u << f)) {
        const auto face = engine::face_vertices(mt.tet(t), f);
        expected.push_back(sorted(t, {face[0].value, face[1].value, face[2].value}));
      }
  }
  for (std::size_t i = 0; i < surface.num_faces(); ++i) {
    std::array<std::int32_t, 3> ids{};
    for (int k = 0; k < 3; ++k) {
      const std::int32_t u = surface.faces[i][static_cast<std::size_t>(k)];
      if (u < 0 || static_cast<std::size_t>(u) >= n) {
        report.add("finest surface: face " + std::to_string(i) + " names no surface vertex");
        return report;
      }
      ids[static_cast<std::size_t>(k)] = surface.vertices[static_cast<std::size_t>(u)].value;
    }
    found.push_back(sorted(surface.face_tet[i], ids));
  }
  std::sort(expected.begin(), expected.end());
  std::sort(found.begin(), found.end());
  if (expected != found) report.add("finest surface: its faces are not the finest tets' surface faces");
  // The carriers and weights.
  engine::Aabb box;
  for (const Vec3& p : mt.positions()) box.extend(p);
  const double tolerance = 1e-9 * std::max(box.diagonal(), 1e-300);
  std::size_t outside = 0;
  for (std::size_t u = 0; u < n; ++u) {
    const TetId c = surface.carrier[u];
    const std::string which = "finest surface: vertex " + std::to_string(surface.vertices[u].index());
    if (!c.valid() || c.index() >= mt.num_tets() || !mt.alive(c) || !frontier.has_tet(c)) {
      report.add(which + " is carried by no live frontier tet");
      continue;
    }
    const engine::Tet& tet = mt.tet(c);
    Vec3 placed = Vec3::Zero();
    double sum = 0;
    for (std::size_t k = 0; k < 4; ++k) {
      const std::int32_t p = surface.particle[u][k];
      if (p < 0 || static_cast<std::size_t>(p) >= model.num_particles() || model.particle_vertex[static_cast<std::size_t>(p)] != tet[k]) {
        report.add(which + ": its carrier's corner " + std::to_string(k) + " is not its particle");
        break;
      }
      placed += surface.weight[u][k] * mt.position(tet[k]);
      sum += surface.weight[u][k];
    }
    if (!std::isfinite(sum) || std::abs(sum - 1.0) > 1e-9 || (placed - mt.position(surface.vertices[u])).norm() > tolerance)
      report.add(which + ": its weights do not place it where it rests");
    outside += least_weight(surface.weight[u]) < kOutside;
  }
  if (outside != surface.outside) report.add("finest surface: the count of vertices outside their carriers is wrong");
  return report;
}

}  // namespace mtcut::sim
