#include "engine/builtin_shapes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "engine/input_error.h"

namespace mtcut::engine {
namespace {

constexpr double kPi = std::numbers::pi;

// Edge length of a regular tet of volume v.
double regular_edge_for_volume(double v) { return std::cbrt(v * 6.0 * std::numbers::sqrt2); }

// The icosahedron refined `levels` times by midpoint subdivision (20 * 4^levels
// triangles), projected onto the unit sphere.
SurfaceMesh unit_icosphere(int levels) {
  const double p = (1.0 + std::sqrt(5.0)) / 2.0;
  SurfaceMesh s;
  s.positions = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
                 {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
  for (auto& v : s.positions) v.normalize();
  s.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      auto [it, inserted] = midpoint.emplace(std::make_pair(std::min(a, b), std::max(a, b)), 0);
      if (inserted) {
        it->second = static_cast<int>(s.positions.size());
        s.positions.push_back((s.positions[a] + s.positions[b]).normalized());
      }
      return it->second;
    };
    std::vector<std::array<std::int32_t, 3>> next;
    next.reserve(4 * s.triangles.size());
    for (const auto& t : s.triangles) {
      const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({t[1], bc, ab});
      next.push_back({t[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    s.triangles = std::move(next);
  }
  return s;
}

SurfaceMesh box_surface(const Vec3& size) {
  SurfaceMesh s;
  const Vec3 h = size / 2;
  for (int i = 0; i < 8; ++i) s.positions.emplace_back(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(), i & 4 ? h.z() : -h.z());
  // Two outward triangles per side.
  s.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return s;
}

// Joins two concentric loops of vertex ids (angles ascending from 0, each
// closed) by triangles, advancing on whichever loop's next vertex comes first
// in angle; a one-point inner loop (the centre) becomes a fan. `flip`
// reverses the winding (the bottom cap faces down).
void zip_loops(const std::vector<std::int32_t>& inner, const std::vector<double>& inner_angle,
               const std::vector<std::int32_t>& outer, const std::vector<double>& outer_angle, bool flip,
               SurfaceMesh& s) {
  auto add = [&](std::int32_t p, std::int32_t q, std::int32_t r) {
    s.triangles.push_back(flip ? std::array<std::int32_t, 3>{p, r, q} : std::array<std::int32_t, 3>{p, q, r});
  };
  const std::size_t ni = inner.size(), no = outer.size();
  if (ni == 1) {
    for (std::size_t b = 0; b < no; ++b) add(inner[0], outer[b], outer[(b + 1) % no]);
    return;
  }
  // The angle of the k-th vertex after the start, unwrapped past 2 pi.
  auto angle = [](const std::vector<double>& angles, std::size_t k) {
    return k < angles.size() ? angles[k] : angles[k - angles.size()] + 2 * kPi;
  };
  std::size_t a = 0, b = 0;
  while (a < ni || b < no) {
    const bool advance_inner = b == no || (a < ni && angle(inner_angle, a + 1) < angle(outer_angle, b + 1));
    if (advance_inner) {
      add(inner[a % ni], outer[b % no], inner[(a + 1) % ni]);
      ++a;
    } else {
      add(inner[a % ni], outer[b % no], outer[(b + 1) % no]);
      ++b;
    }
  }
}

SurfaceMesh cylinder_surface(const Vec3& size, double edge) {
  const double rx = size.x() / 2, ry = size.y() / 2, hz = size.z() / 2;
  const double perimeter = 2 * kPi * std::max(rx, ry);
  const int segments = std::max(12, static_cast<int>(std::ceil(perimeter / edge)));
  const int rings = std::max(1, static_cast<int>(std::ceil(size.z() / edge)));
  const int cap_rings = std::max(1, static_cast<int>(std::ceil(std::max(rx, ry) / edge)));
  SurfaceMesh s;
  // One loop of n points at fraction `radial` of the radii, height z.
  auto add_loop = [&](int n, double radial, double z, std::vector<std::int32_t>& ids, std::vector<double>& angles) {
    ids.clear();
    angles.clear();
    for (int k = 0; k < n; ++k) {
      const double a = 2 * kPi * k / n;
      ids.push_back(static_cast<std::int32_t>(s.positions.size()));
      angles.push_back(a);
      s.positions.emplace_back(radial * rx * std::cos(a), radial * ry * std::sin(a), z);
    }
  };
  // The side: rings of `segments` points from bottom to top.
  std::vector<std::vector<std::int32_t>> side(static_cast<std::size_t>(rings) + 1);
  std::vector<double> side_angles;
  for (int r = 0; r <= rings; ++r) add_loop(segments, 1.0, -hz + size.z() * r / rings, side[static_cast<std::size_t>(r)], side_angles);
  for (int r = 0; r < rings; ++r) {
    const auto& lo = side[static_cast<std::size_t>(r)];
    const auto& hi = side[static_cast<std::size_t>(r) + 1];
    for (int k = 0; k < segments; ++k) {
      const int k1 = (k + 1) % segments;
      s.triangles.push_back({lo[k], lo[k1], hi[k1]});
      s.triangles.push_back({lo[k], hi[k1], hi[k]});
    }
  }
  // The caps: concentric loops with about as many points as their perimeter
  // needs, zipped together; the centre is a single point.
  for (const bool top : {false, true}) {
    const double z = top ? hz : -hz;
    std::vector<std::int32_t> inner = {static_cast<std::int32_t>(s.positions.size())};
    std::vector<double> inner_angle = {0.0};
    s.positions.emplace_back(0, 0, z);
    for (int c = 1; c <= cap_rings; ++c) {
      std::vector<std::int32_t> outer;
      std::vector<double> outer_angle;
      if (c == cap_rings) {
        outer = side[top ? static_cast<std::size_t>(rings) : 0];
        outer_angle = side_angles;
      } else {
        const int n = std::max(6, segments * c / cap_rings);
        add_loop(n, static_cast<double>(c) / cap_rings, z, outer, outer_angle);
      }
      zip_loops(inner, inner_angle, outer, outer_angle, !top, s);
      inner = std::move(outer);
      inner_angle = std::move(outer_angle);
    }
  }
  return s;
}

double target_edge(const BuiltinShapeDef& def) {
  return regular_edge_for_volume(analytic_volume(def) / std::max(1, def.target_tets));
}

}  // namespace

std::optional<BuiltinShape> parse_builtin(const std::string& spec) {
  const std::string prefix = "builtin:";
  if (spec.rfind(prefix, 0) != 0) return std::nullopt;
  const std::string name = spec.substr(prefix.size());
  if (name == "box") return BuiltinShape::kBox;
  if (name == "ellipsoid") return BuiltinShape::kEllipsoid;
  if (name == "cylinder") return BuiltinShape::kCylinder;
  throw InputError(spec + ": unknown built-in shape (use builtin:box, builtin:ellipsoid or builtin:cylinder)");
}

double analytic_volume(const BuiltinShapeDef& def) {
  const Vec3& s = def.size;
  switch (def.shape) {
    case BuiltinShape::kBox: return s.x() * s.y() * s.z();
    case BuiltinShape::kEllipsoid: return kPi / 6.0 * s.x() * s.y() * s.z();
    case BuiltinShape::kCylinder: return kPi / 4.0 * s.x() * s.y() * s.z();
  }
  return 0;
}

SurfaceMesh make_builtin_surface(const BuiltinShapeDef& def) {
  if (!(def.size.minCoeff() > 0) || !def.size.allFinite())
    throw InputError("builtin shape: every size must be positive and finite");
  if (def.target_tets < 1) throw InputError("builtin shape: the target tet count must be at least 1");
  SurfaceMesh s;
  double lateral_scale = 1.0;  // radial correction that makes the volume exact
  switch (def.shape) {
    case BuiltinShape::kBox: return box_surface(def.size);
    case BuiltinShape::kEllipsoid: {
      // About N^(2/3) triangles, under the boundary share of a quality mesh of N
      // tets; a finer surface would force more tets than asked for, and
      // TetGen splits surface triangles wherever quality needs it.
      const double max_faces = std::pow(def.target_tets, 2.0 / 3.0);
      int levels = 1;
      while (20.0 * std::pow(4.0, levels + 1) <= max_faces) ++levels;
      s = unit_icosphere(levels);
      for (auto& p : s.positions) p = p.cwiseProduct(def.size / 2);
      lateral_scale = std::cbrt(analytic_volume(def) / s.enclosed_volume());
      for (auto& p : s.positions) p *= lateral_scale;
      return s;
    }
    case BuiltinShape::kCylinder: {
      s = cylinder_surface(def.size, 2.0 * target_edge(def));
      lateral_scale = std::sqrt(analytic_volume(def) / s.enclosed_volume());
      for (auto& p : s.positions) p.head<2>() *= lateral_scale;
      return s;
    }
  }
  return s;
}

TetMesh make_builtin_mesh(const BuiltinShapeDef& def, const TetrahedralizeOptions& quality) {
  const SurfaceMesh surface = make_builtin_surface(def);
  const double volume = analytic_volume(def);
  // The count TetGen makes falls as the -a bound grows, but not smoothly:
  // the surface and the quality refinement both force tets. Aim at the
  // proportional guess; once the target is bracketed, bisect the bound in
  // log space. The mesh closest to the target wins.
  constexpr double kTolerance = 0.1;
  constexpr int kAttempts = 8;
  const double target = def.target_tets;
  TetrahedralizeOptions options = quality;
  options.max_volume = 1.2 * volume / target;
  double too_small = 0, too_large = 0;  // bounds known to give too many / too few tets
  TetMesh best;
  double best_error = std::numeric_limits<double>::infinity();
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    TetMesh mesh = tetrahedralize(surface, options, "builtin shape");
    const double count = static_cast<double>(mesh.num_tets());
    const double error = std::abs(count / target - 1.0);
    if (error < best_error) {
      best_error = error;
      best = std::move(mesh);
    }
    if (error < kTolerance) break;
    (count > target ? too_small : too_large) = options.max_volume;
    if (too_small > 0 && too_large > 0) {
      options.max_volume = std::sqrt(too_small * too_large);
    } else {
      options.max_volume *= count / target;
    }
  }
  return best;
}

}  // namespace mtcut::engine
