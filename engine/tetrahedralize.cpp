#include "engine/tetrahedralize.h"

#include <tetgen.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <iomanip>
#include <set>
#include <sstream>

#include "engine/child_process.h"
#include "engine/input_error.h"

namespace mtcut::engine {
namespace {

void fill_plc(const SurfaceMesh& surface, tetgenio& in) {
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(surface.positions.size());
  in.pointlist = new REAL[3 * surface.positions.size()];
  for (std::size_t i = 0; i < surface.positions.size(); ++i)
    for (int k = 0; k < 3; ++k) in.pointlist[3 * i + k] = surface.positions[i][k];
  in.numberoffacets = static_cast<int>(surface.triangles.size());
  in.facetlist = new tetgenio::facet[surface.triangles.size()];
  for (std::size_t i = 0; i < surface.triangles.size(); ++i) {
    tetgenio::facet& f = in.facetlist[i];
    tetgenio::init(&f);
    f.numberofpolygons = 1;
    f.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&f.polygonlist[0]);
    f.polygonlist[0].numberofvertices = 3;
    f.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k) f.polygonlist[0].vertexlist[k] = surface.triangles[i][k];
  }
}

std::string switches_for(const TetrahedralizeOptions& options, bool diagnose) {
  std::ostringstream s;
  s.precision(17);
  s << (diagnose ? "pdz" : "pz");
  if (!options.verbose) s << "Q";
  if (!diagnose) {
    if (options.radius_edge_ratio > 0) s << "q" << options.radius_edge_ratio << "/" << options.min_dihedral_deg;
    if (options.max_volume > 0) s << "a" << options.max_volume;
  }
  return s.str();
}

// What one TetGen run in a child process gave back.
struct TetgenRun {
  enum class Outcome { kDone, kTetgenError, kCrashed, kTimedOut } outcome = Outcome::kDone;
  int code = 0;            // TetGen's thrown int (kTetgenError) or the signal (kCrashed)
  std::string chatter;     // what TetGen printed
  std::vector<Vec3> positions;
  std::vector<std::array<std::int64_t, 4>> tets;
  std::vector<std::array<int, 3>> faces;  // -d: the intersecting facets
};

constexpr int kChildMeshed = 0, kChildThrew = 3, kChildBadSwitches = 4, kChildCannotWrite = 5;

// The child's work: TetGen on the surface, its output written to `result`
// (counts, then points, tets and faces as TetGen gives them). Returns the
// child's exit code.
int tetgen_in_child(const SurfaceMesh& surface, std::string switches, std::FILE* result) {
  tetgenio in, out;
  fill_plc(surface, in);
  tetgenbehavior behavior;
  if (!behavior.parse_commandline(switches.data())) return kChildBadSwitches;
  std::int32_t code = 0;
  try {
    tetrahedralize(&behavior, &in, &out);
  } catch (int c) {
    code = c;
  }
  if (code != 0) return put_values(result, &code, 1) ? kChildThrew : kChildCannotWrite;
  const std::int64_t counts[3] = {out.numberofpoints, out.numberoftetrahedra, out.numberoftrifaces};
  const bool written =
      put_values(result, counts, 3) && put_values(result, out.pointlist, 3 * static_cast<std::size_t>(counts[0])) &&
      put_values(result, &out.numberofcorners, 1) &&
      put_values(result, out.tetrahedronlist, static_cast<std::size_t>(out.numberofcorners * counts[1])) &&
      put_values(result, out.trifacelist, 3 * static_cast<std::size_t>(counts[2]));
  return written ? kChildMeshed : kChildCannotWrite;
}

// Runs TetGen with `switches` in a child process and waits for it until
// `deadline`, calling options.progress about once a second.
TetgenRun run_tetgen(const SurfaceMesh& surface, const std::string& switches, const TetrahedralizeOptions& options,
                     std::chrono::steady_clock::time_point deadline, std::chrono::steady_clock::time_point start) {
  ChildOptions child;
  child.deadline = deadline;
  child.quiet = !options.verbose;
  child.progress = options.progress;
  child.start = start;
  const ChildRun c = run_in_child([&](std::FILE* result) { return tetgen_in_child(surface, switches, result); }, child);
  TetgenRun run;
  run.chatter = c.chatter;
  if (c.outcome == ChildRun::Outcome::kTimedOut) {
    run.outcome = TetgenRun::Outcome::kTimedOut;
    return run;
  }
  if (c.outcome == ChildRun::Outcome::kCrashed) {
    run.outcome = TetgenRun::Outcome::kCrashed;
    run.code = c.code;
    return run;
  }
  std::size_t at = 0;
  if (c.code == kChildThrew) {
    std::int32_t code = 0;
    get_values(c.output, at, &code, 1);
    run.outcome = TetgenRun::Outcome::kTetgenError;
    run.code = code;
    return run;
  }
  if (c.code == kChildBadSwitches) throw InputError("TetGen: bad switches '" + switches + "'");
  std::int64_t counts[3] = {0, 0, 0};
  int corners = 4;
  if (c.code != kChildMeshed || !get_values(c.output, at, counts, 3) || counts[0] < 0 || counts[1] < 0 || counts[2] < 0)
    throw InputError("TetGen: its process ended without a mesh (exit " + std::to_string(c.code) + ")");
  std::vector<double> points(3 * static_cast<std::size_t>(counts[0]));
  std::vector<int> corner_ids;
  std::vector<int> faces(3 * static_cast<std::size_t>(counts[2]));
  bool read = get_values(c.output, at, points.data(), points.size()) && get_values(c.output, at, &corners, 1) &&
              corners >= 4;
  if (read) {
    corner_ids.resize(static_cast<std::size_t>(corners) * static_cast<std::size_t>(counts[1]));
    read = get_values(c.output, at, corner_ids.data(), corner_ids.size()) &&
           get_values(c.output, at, faces.data(), faces.size());
  }
  if (!read) throw InputError("TetGen: its process's mesh is cut short");
  run.positions.resize(static_cast<std::size_t>(counts[0]));
  for (std::size_t i = 0; i < run.positions.size(); ++i)
    run.positions[i] = Vec3(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
  run.tets.resize(static_cast<std::size_t>(counts[1]));
  for (std::size_t t = 0; t < run.tets.size(); ++t)
    for (std::size_t k = 0; k < 4; ++k) run.tets[t][k] = corner_ids[static_cast<std::size_t>(corners) * t + k];
  run.faces.resize(static_cast<std::size_t>(counts[2]));
  for (std::size_t f = 0; f < run.faces.size(); ++f) run.faces[f] = {faces[3 * f], faces[3 * f + 1], faces[3 * f + 2]};
  return run;
}

std::string first_error_line(const std::string& chatter) {
  std::istringstream lines(chatter);
  std::string line;
  while (std::getline(lines, line))
    if (line.find("Error") != std::string::npos || line.find("error") != std::string::npos) return line;
  return {};
}

// Names the triangles TetGen -d found intersecting; empty when there are
// none. This must run before meshing: TetGen 1.5.0 crashes on some
// self-intersecting inputs.
std::string self_intersections(const SurfaceMesh& surface, const TetgenRun& run) {
  if (run.faces.empty()) return {};
  std::set<std::array<int, 3>> faces;
  for (std::array<int, 3> f : run.faces) {
    std::sort(f.begin(), f.end());
    faces.insert(f);
  }
  std::vector<std::size_t> names;
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    std::array<int, 3> f = surface.triangles[t];
    std::sort(f.begin(), f.end());
    if (faces.count(f)) names.push_back(t);
  }
  if (names.empty()) return "the surface intersects itself";
  std::string text = "the surface intersects itself (" + std::to_string(names.size()) + " faces, e.g. triangles";
  for (std::size_t i = 0; i < names.size() && i < 6; ++i) text += (i ? ", " : " ") + std::to_string(names[i]);
  return text + ")";
}

std::string tetgen_fault(int code, const std::string& chatter) {
  switch (code) {
    case 1: return "TetGen ran out of memory";
    case 3: return "the surface intersects itself";
    case 4: return "the surface has features too small for TetGen's tolerance";
    case 5: return "the surface has two facets too close to each other";
    default: {
      const std::string line = first_error_line(chatter);
      return "TetGen failed (code " + std::to_string(code) + ")" + (line.empty() ? std::string() : ": " + line);
    }
  }
}

std::string format_number(double value) {
  std::ostringstream s;
  s << std::setprecision(3) << value;
  return s.str();
}

std::string format_seconds(double seconds) { return format_number(seconds) + " s"; }

}  // namespace

long steiner_point_bound(const SurfaceMesh& surface, const TetrahedralizeOptions& options) {
  // TetGen adds a few points per surface point refining near the surface
  // (9 for the shared liver2.obj; 130 for a tube of sliver faces, 1 m long
  // and 2 cm wide), and about one per five tets max_volume asks for inside.
  double bound = 100000.0 + 20.0 * static_cast<double>(surface.positions.size());
  if (options.max_volume > 0) bound += 4.0 * std::abs(surface.enclosed_volume()) / options.max_volume;
  return static_cast<long>(std::min(bound, 1e9));
}

TetMesh tetrahedralize(const SurfaceMesh& surface, const TetrahedralizeOptions& options, const std::string& source,
                       std::vector<InputNote>* notes) {
  using Clock = std::chrono::steady_clock;
  if (surface.triangles.size() < 4) throw InputError(source + ": the surface has fewer than 4 faces");
  if (const std::size_t open = surface.count_open_edges(); open > 0)
    throw SurfaceRefused(source + ": the surface is not closed (" + std::to_string(open) +
                     " edges are not shared by exactly two faces: a hole or a non-manifold seam)");
  if (options.max_volume < 0 || options.radius_edge_ratio < 0)
    throw InputError(source + ": max volume and quality bound must not be negative");
  if (!(options.time_limit_seconds > 0)) throw InputError(source + ": the meshing time limit must be positive");

  const auto start = Clock::now();
  const auto limit = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.time_limit_seconds));
  const TetgenRun check = run_tetgen(surface, switches_for(options, true), options, start + limit, start);
  switch (check.outcome) {
    case TetgenRun::Outcome::kDone: break;
    case TetgenRun::Outcome::kTetgenError:
      throw SurfaceRefused(source + ": the surface intersects itself or is degenerate (TetGen's detection failed)");
    case TetgenRun::Outcome::kCrashed:
      throw SurfaceRefused(source + ": TetGen crashed (" + signal_name(check.code) +
                           ") checking the surface for self-intersections");
    case TetgenRun::Outcome::kTimedOut:
      throw InputError(source + ": TetGen did not finish checking the surface within " +
                       format_seconds(options.time_limit_seconds));
  }
  if (const std::string fault = self_intersections(surface, check); !fault.empty())
    throw SurfaceRefused(source + ": " + fault);

  // The quality asked for, then a looser bound (kept even if it too stops
  // at the points' bound), then, after a crash, none; each try runs until
  // its share of the time limit is spent.
  const long bound = options.max_added_points > 0 ? options.max_added_points : steiner_point_bound(surface, options);
  std::vector<TetrahedralizeOptions> tries = {options};
  if (options.radius_edge_ratio > 0) {
    TetrahedralizeOptions looser = options;
    looser.radius_edge_ratio = std::max(2.0, 1.5 * options.radius_edge_ratio);
    looser.min_dihedral_deg = 0;
    tries.push_back(looser);
    TetrahedralizeOptions none = options;
    none.radius_edge_ratio = 0;
    tries.push_back(none);
  }
  std::string why;         // why the last try was not kept
  bool timed_out = false;  // the last try ran out of time
  for (std::size_t i = 0; i < tries.size(); ++i) {
    constexpr double kShare[] = {0.6, 0.85, 1.0};  // of the time limit, by the end of each try
    const auto deadline = start + std::chrono::duration_cast<Clock::duration>(
                                      limit * (i + 1 == tries.size() ? 1.0 : kShare[i]));
    TetgenRun run = run_tetgen(surface, switches_for(tries[i], false) + "S" + std::to_string(bound), tries[i],
                               deadline, start);
    if (run.outcome == TetgenRun::Outcome::kTetgenError) {
      if (run.code == 1) {
        // Out of memory: larger tets take less, when a largest is asked for.
        const std::string fault = source + ": " + tetgen_fault(run.code, run.chatter);
        if (!(options.max_volume > 0)) throw InputError(fault);
        throw InputError(fault + " meshing to tets of at most " + format_number(options.max_volume) + " m^3",
                         {InputHint::Kind::kMaxVolume, {}});
      }
      throw SurfaceRefused(source + ": " + tetgen_fault(run.code, run.chatter));
    }
    if (run.outcome == TetgenRun::Outcome::kDone && run.tets.empty())
      throw InputError(source + ": TetGen produced no tetrahedra");
    const long added = static_cast<long>(run.positions.size()) - static_cast<long>(surface.positions.size());
    const bool at_bound = run.outcome == TetgenRun::Outcome::kDone && added >= bound;
    const bool keep_at_bound = i + 1 >= tries.size() - 1;  // the looser try, or the last
    if (run.outcome == TetgenRun::Outcome::kDone && (!at_bound || keep_at_bound)) {
      const std::string kept = tries[i].radius_edge_ratio > 0
                                   ? "the looser quality bound " + format_number(tries[i].radius_edge_ratio)
                                   : std::string("no quality refinement");
      if (notes && i > 0 && !at_bound)
        notes->push_back({source + ": TetGen " + why + "; meshed with " + kept + " instead"});
      if (notes && i > 0 && at_bound)
        notes->push_back({source + ": TetGen " + why + "; with " + kept + " it reached its bound of " +
                          std::to_string(bound) +
                          " added points, and that mesh is kept: its quality is below what was asked for"});
      if (notes && i == 0 && at_bound)
        notes->push_back({source + ": TetGen stopped at its bound of " + std::to_string(bound) + " added points"});
      return make_tet_mesh(std::move(run.positions), run.tets, source);
    }
    timed_out = run.outcome == TetgenRun::Outcome::kTimedOut;
    switch (run.outcome) {
      case TetgenRun::Outcome::kDone: why = "reached its bound of " + std::to_string(bound) + " added points"; break;
      case TetgenRun::Outcome::kCrashed: why = "crashed (" + signal_name(run.code) + ") refining the mesh"; break;
      case TetgenRun::Outcome::kTimedOut:
        why = "did not finish within " + format_seconds(std::chrono::duration<double>(deadline - start).count());
        break;
      case TetgenRun::Outcome::kTetgenError: break;
    }
  }
  if (timed_out) throw InputError(source + ": TetGen " + why);
  throw SurfaceRefused(source + ": TetGen " + why + ", also without quality refinement");
}

}  // namespace mtcut::engine
