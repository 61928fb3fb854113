#include "engine/surface_repair.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair_self_intersections.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/alpha_wrap_3.h>
#include <CGAL/assertions_behaviour.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <optional>
#include <type_traits>
#include <vector>

#include "engine/child_process.h"
#include "engine/input_error.h"

namespace mtcut::engine {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
namespace NP = CGAL::parameters;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Polygon = std::vector<std::size_t>;
using Halfedge = boost::graph_traits<Mesh>::halfedge_descriptor;
using Face = boost::graph_traits<Mesh>::face_descriptor;
using Vertex = boost::graph_traits<Mesh>::vertex_descriptor;

// The alpha wrap's size and distance from the input, as fractions of the
// bounding box's diagonal: organ-sized detail, 10k to 16k faces, 1% more volume.
constexpr double kWrapAlpha = 1.0 / 75, kWrapOffset = 1.0 / 2250;
// The most a local self-intersection repair may change the volume.
constexpr double kMaxLocalVolumeChange = 0.05;
// The most a wrap may change it (a wrap that went through a hole wider than
// alpha is a thin shell of almost no volume).
constexpr double kMaxWrapVolumeChange = 0.25;
// The most one repair may take (its child process is stopped then).
constexpr int kRepairSeconds = 120;

struct Soup {
  std::vector<Point> points;
  std::vector<Polygon> polygons;
};

Soup soup_of(const SurfaceMesh& surface) {
  Soup soup;
  for (const Vec3& p : surface.positions) soup.points.emplace_back(p.x(), p.y(), p.z());
  for (const auto& t : surface.triangles)
    soup.polygons.push_back({static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]), static_cast<std::size_t>(t[2])});
  return soup;
}

SurfaceMesh surface_of(const Mesh& mesh) {
  std::vector<Point> points;
  std::vector<Polygon> polygons;
  PMP::polygon_mesh_to_polygon_soup(mesh, points, polygons);
  SurfaceMesh surface;
  for (const Point& p : points) surface.positions.emplace_back(p.x(), p.y(), p.z());
  for (const Polygon& p : polygons)
    for (std::size_t k = 1; k + 1 < p.size(); ++k)
      surface.triangles.push_back({static_cast<std::int32_t>(p[0]), static_cast<std::int32_t>(p[k]),
                                   static_cast<std::int32_t>(p[k + 1])});
  return surface;
}

std::vector<Triangle> triangles_of(const SurfaceMesh& surface) {
  std::vector<Triangle> triangles;
  for (const auto& t : surface.triangles) {
    const Vec3 &a = surface.positions[t[0]], &b = surface.positions[t[1]], &c = surface.positions[t[2]];
    Triangle tri(Point(a.x(), a.y(), a.z()), Point(b.x(), b.y(), b.z()), Point(c.x(), c.y(), c.z()));
    if (!tri.is_degenerate()) triangles.push_back(tri);
  }
  return triangles;
}

// Closed, manifold, triangles, not crossing itself: what TetGen meshes.
bool fit_to_mesh(const Mesh& mesh) {
  if (mesh.is_empty() || !CGAL::is_valid_polygon_mesh(mesh) || !CGAL::is_triangle_mesh(mesh) || !CGAL::is_closed(mesh))
    return false;
  // One pass over the mesh (is_non_manifold_vertex walks every halfedge for each vertex it is asked of).
  std::vector<Halfedge> pinched;
  PMP::non_manifold_vertices(mesh, std::back_inserter(pinched));
  return pinched.empty() && !PMP::does_self_intersect(mesh);
}

// Turns a fit mesh outward; false when its volume is not positive then.
bool orient_outward(Mesh& mesh) {
  PMP::orient_to_bound_a_volume(mesh);
  return PMP::volume(mesh) > 0;
}

std::size_t fill_holes(Mesh& mesh) {
  std::vector<Halfedge> cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  std::size_t closed = 0;
  for (Halfedge h : cycles) {
    if (!mesh.is_border(h)) continue;  // a previous patch took it
    std::vector<Face> patch;
    std::vector<Vertex> added;
    try {
      PMP::triangulate_refine_and_fair_hole(mesh, h, std::back_inserter(patch), std::back_inserter(added),
                                            NP::use_delaunay_triangulation(true));
    } catch (const std::exception&) {
      patch.clear();
    }
    if (patch.empty()) {
      try {
        PMP::triangulate_hole(mesh, h, std::back_inserter(patch));
      } catch (const std::exception&) {
      }
    }
    if (!patch.empty()) ++closed;
  }
  return closed;
}

// The volume of each connected part of a closed mesh, largest first.
std::vector<double> part_volumes(const Mesh& mesh) {
  std::vector<std::size_t> part(mesh.number_of_faces());
  const std::size_t parts =
      PMP::connected_components(mesh, CGAL::make_property_map(part), NP::face_index_map(get(CGAL::face_index, mesh)));
  std::vector<double> volume(parts, 0.0);
  const Point origin = CGAL::ORIGIN;
  for (Face f : mesh.faces()) {
    const Halfedge h = mesh.halfedge(f);
    volume[part[static_cast<std::size_t>(f.idx())]] +=
        CGAL::volume(origin, mesh.point(mesh.source(h)), mesh.point(mesh.target(h)), mesh.point(mesh.target(mesh.next(h))));
  }
  for (double& v : volume) v = std::abs(v);
  std::sort(volume.rbegin(), volume.rend());
  return volume;
}

// Quiets CGAL's warnings (the experimental repairs print them) and turns its
// failed checks into exceptions, for the lifetime of the object.
class QuietCgal {
 public:
  QuietCgal()
      : warning_(CGAL::set_warning_handler([](const char*, const char*, const char*, int, const char*) {})),
        error_(CGAL::set_error_behaviour(CGAL::THROW_EXCEPTION)) {}
  ~QuietCgal() {
    CGAL::set_warning_handler(warning_);
    CGAL::set_error_behaviour(error_);
  }
  QuietCgal(const QuietCgal&) = delete;
  QuietCgal& operator=(const QuietCgal&) = delete;

 private:
  CGAL::Failure_function warning_;
  CGAL::Failure_behaviour error_;
};

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%+.1f%%", 100 * fraction);
  return text;
}

std::string length(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g mm", 1000 * metres);
  return text;
}

// The repair of a surface that is not fit to mesh (steps 1 to 4 above).
// CGAL's experimental repairs crash on some inputs: this runs in a child.
SurfaceRepair repair_steps(SurfaceMesh& surface, const std::string& source, bool wrap) {
  QuietCgal quiet;
  SurfaceRepair report;
  report.faces_in = surface.triangles.size();
  const Soup soup = soup_of(surface);

  const std::vector<Triangle> input = triangles_of(surface);
  // The input's volume, once step 1 has turned its faces one way: none
  // when it has holes.
  bool input_closed = false;
  double input_volume = 0;
  CGAL::Bbox_3 box;
  for (const Point& p : soup.points) box += p.bbox();
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));

  // Keeps `mesh` as the result of `step` when it is fit to mesh and outward.
  const auto finish = [&](Mesh& mesh, SurfaceRepair::Step step) {
    SurfaceRepair done = report;
    done.step = step;
    SurfaceMesh result = surface_of(mesh);
    done.faces_out = result.triangles.size();
    const double volume = std::abs(result.enclosed_volume());
    done.input_closed = input_closed;
    done.volume_change = input_closed && input_volume > 0 ? volume / input_volume - 1 : 0;
    CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>>>
        tree(input.begin(), input.end());
    for (const Vec3& p : result.positions)
      done.max_distance = std::max(done.max_distance, std::sqrt(tree.squared_distance(Point(p.x(), p.y(), p.z()))));
    surface = std::move(result);
    return done;
  };

  // 1. The soup's own repair.
  std::vector<Point> points = soup.points;
  std::vector<Polygon> polygons = soup.polygons;
  PMP::repair_polygon_soup(points, polygons, NP::require_same_orientation(true));
  // What is still given twice is given both ways round: a wall of no thickness.
  PMP::repair_polygon_soup(points, polygons, NP::erase_all_duplicates(true));
  report.points_merged = soup.points.size() - points.size();
  report.faces_dropped = soup.polygons.size() - polygons.size();
  const std::vector<Polygon> before_orienting = polygons;
  PMP::orient_polygon_soup(points, polygons);
  for (std::size_t i = 0; i < polygons.size() && i < before_orienting.size(); ++i)
    report.faces_flipped += polygons[i] != before_orienting[i];
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  PMP::triangulate_faces(mesh);
  PMP::stitch_borders(mesh);
  try {
    PMP::remove_degenerate_faces(mesh);
  } catch (const std::exception&) {
  }
  PMP::duplicate_non_manifold_vertices(mesh);
  PMP::remove_isolated_vertices(mesh);
  mesh.collect_garbage();
  if (CGAL::is_closed(mesh) && CGAL::is_triangle_mesh(mesh)) {
    input_closed = true;
    input_volume = std::abs(PMP::volume(mesh));
  }
  if (!wrap && fit_to_mesh(mesh) && orient_outward(mesh)) return finish(mesh, SurfaceRepair::Step::kSoup);

  // 2. Holes.
  Mesh filled = mesh;
  report.holes_closed = fill_holes(filled);
  if (!wrap && report.holes_closed > 0 && fit_to_mesh(filled) && orient_outward(filled))
    return finish(filled, SurfaceRepair::Step::kHoles);

  // 3. Self-intersections: the exact union of overlapping parts, kept when
  // nothing moved and it holds at least the largest part; else local removal.
  if (!wrap && CGAL::is_closed(filled) && CGAL::is_triangle_mesh(filled)) {
    const std::vector<double> parts = part_volumes(filled);
    double whole = 0;
    for (double v : parts) whole += v;
    Mesh united = filled;
    try {
      if (PMP::experimental::autorefine_and_remove_self_intersections(united)) {
        united.collect_garbage();
        PMP::remove_isolated_vertices(united);
        united.collect_garbage();
        if (fit_to_mesh(united) && orient_outward(united)) {
          const double volume = PMP::volume(united);
          if (!parts.empty() && volume >= 0.9 * parts.front() && volume <= 1.001 * whole)
            return finish(united, SurfaceRepair::Step::kSelfIntersections);
        }
      }
    } catch (const std::exception&) {
    }
    Mesh local = filled;
    try {
      PMP::experimental::remove_self_intersections(local, NP::preserve_genus(false));
      local.collect_garbage();
      fill_holes(local);
      if (fit_to_mesh(local) && orient_outward(local) &&
          std::abs(PMP::volume(local) / whole - 1) <= kMaxLocalVolumeChange)
        return finish(local, SurfaceRepair::Step::kSelfIntersections);
    } catch (const std::exception&) {
    }
  }

  // 4. The wrap, of the hole-filled surface where that closed it (a wrap
  // goes through holes wider than alpha), else of the soup.
  std::vector<Point> wrap_points;
  std::vector<std::array<std::size_t, 3>> wrap_faces;
  const bool from_filled = CGAL::is_closed(filled) && CGAL::is_triangle_mesh(filled);
  if (from_filled) {
    std::vector<Polygon> faces;
    PMP::polygon_mesh_to_polygon_soup(filled, wrap_points, faces);
    for (const Polygon& f : faces) wrap_faces.push_back({f[0], f[1], f[2]});
  } else {
    wrap_points = soup.points;
    for (const Polygon& f : soup.polygons) wrap_faces.push_back({f[0], f[1], f[2]});
  }
  const double reference = from_filled ? std::abs(PMP::volume(filled)) : (input_closed ? input_volume : 0);
  const double offset = kWrapOffset * diagonal;
  Mesh wrapped;
  try {
    CGAL::alpha_wrap_3(wrap_points, wrap_faces, kWrapAlpha * diagonal, offset, wrapped);
  } catch (const std::exception&) {
    wrapped.clear();
  }
  // A wrap around a sheet (an open surface, or holes wider than alpha) is a
  // shell about two offsets thick, not the solid: refused.
  if (fit_to_mesh(wrapped) && orient_outward(wrapped) && PMP::volume(wrapped) > 4 * offset * PMP::area(wrapped) &&
      (reference <= 0 || std::abs(PMP::volume(wrapped) / reference - 1) <= kMaxWrapVolumeChange))
    return finish(wrapped, SurfaceRepair::Step::kWrap);
  throw InputError(source + ": the surface could not be repaired into a closed one (" +
                   std::to_string(report.faces_in) + " faces; its wrap " +
                   (wrapped.is_empty() ? std::string("failed") : "lost its volume: an open sheet, not a solid?") + ")");
}

bool fit_as_it_is(const SurfaceMesh& surface) {
  QuietCgal quiet;
  Soup soup = soup_of(surface);
  if (!PMP::is_polygon_soup_a_polygon_mesh(soup.polygons)) return false;
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
  return fit_to_mesh(mesh);
}

// Runs repair_steps in a child process; nullopt when the child crashed or
// overran the time limit.
std::optional<SurfaceRepair> repair_in_child(SurfaceMesh& surface, const std::string& source, bool wrap) {
  static_assert(std::is_trivially_copyable_v<SurfaceRepair>);
  constexpr int kRepaired = 0, kRefused = 2;
  ChildOptions options;
  options.deadline = options.start + std::chrono::seconds(kRepairSeconds);
  const ChildRun run = run_in_child(
      [&](std::FILE* result) {
        try {
          SurfaceMesh repaired = surface;
          const SurfaceRepair report = repair_steps(repaired, source, wrap);
          return put_values(result, &report, 1) && put_surface(result, repaired) ? kRepaired : 1;
        } catch (const InputError& e) {
          const std::string what = e.what();
          return put_values(result, what.data(), what.size()) ? kRefused : 1;
        }
      },
      options);
  if (run.outcome != ChildRun::Outcome::kExited) return std::nullopt;
  if (run.code == kRefused) throw InputError(run.output);
  SurfaceRepair report;
  SurfaceMesh repaired;
  std::size_t at = 0;
  if (run.code != kRepaired || !get_values(run.output, at, &report, 1) || !get_surface(run.output, at, repaired))
    return std::nullopt;
  surface = std::move(repaired);
  return report;
}

}  // namespace

std::string SurfaceRepair::describe(const std::string& source) const {
  std::string text = source + ": repaired (";
  switch (step) {
    case Step::kNone: return source + ": fit to mesh as it is";
    case Step::kSoup: text += "duplicates and orientation"; break;
    case Step::kHoles: text += "holes closed"; break;
    case Step::kSelfIntersections: text += "self-intersections resolved"; break;
    case Step::kWrap: text += "wrapped whole"; break;
  }
  text += "): " + std::to_string(faces_in) + " faces in, " + std::to_string(faces_out) + " out";
  if (step != Step::kWrap) {
    if (points_merged) text += ", " + std::to_string(points_merged) + " duplicate points merged";
    if (faces_dropped) text += ", " + std::to_string(faces_dropped) + " degenerate or repeated faces dropped";
    if (faces_flipped) text += ", " + std::to_string(faces_flipped) + " faces turned";
    if (holes_closed) text += ", " + std::to_string(holes_closed) + " holes closed";
  }
  if (!input_closed)
    text += ", the input was open";
  else if (std::abs(volume_change) < 5e-4)
    text += ", volume within 0.05%";
  else
    text += ", volume " + percent(volume_change);
  text += max_distance < 1e-9 ? std::string(", every point on the input")
                              : ", every point within " + length(max_distance) + " of the input";
  return text;
}

namespace {

// Whether every point lies within the wrap's offset of one plane (the
// plane through their mean across their least spread): a sheet, which no
// step can make a solid, and whose steps up to the wrap's refusal take
// seconds (minutes in a sanitizer's build).
bool is_flat(const SurfaceMesh& surface) {
  if (surface.positions.empty()) return false;
  Vec3 mean = Vec3::Zero(), lo = surface.positions.front(), hi = lo;
  for (const Vec3& p : surface.positions) {
    mean += p;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  mean /= static_cast<double>(surface.positions.size());
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (const Vec3& p : surface.positions) spread += (p - mean) * (p - mean).transpose();
  const Vec3 normal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(spread).eigenvectors().col(0);
  double thickness = 0;
  for (const Vec3& p : surface.positions) thickness = std::max(thickness, std::abs((p - mean).dot(normal)));
  return thickness <= kWrapOffset * (hi - lo).norm();
}

}  // namespace

SurfaceRepair repair_surface(SurfaceMesh& surface, const std::string& source, bool wrap) {
  if (surface.triangles.empty()) throw InputError(source + ": the surface has no faces");
  if (is_flat(surface))
    throw InputError(source + ": the surface could not be repaired into a closed one (" +
                     std::to_string(surface.triangles.size()) + " faces, all in one plane: an open sheet, not a solid)");
  // Fit as it is: left untouched (not even renumbered).
  if (!wrap && fit_as_it_is(surface)) {
    SurfaceRepair report;
    report.faces_in = report.faces_out = surface.triangles.size();
    return report;
  }
  if (auto report = repair_in_child(surface, source, wrap)) return *report;
  // A crash or overrun in the lighter repairs: the wrap alone.
  if (!wrap)
    if (auto report = repair_in_child(surface, source, true)) return *report;
  throw InputError(source + ": the surface's repair failed (CGAL crashed or ran over " +
                   std::to_string(kRepairSeconds) + " s)");
}

}  // namespace mtcut::engine
