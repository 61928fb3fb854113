#include "engine/tetrahedralize.h"

#include <tetgen.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include "engine/input_error.h"

namespace mtcut::engine {
namespace {

// Sends the process's stdout to a temporary file for the lifetime of the
// object (TetGen writes there with printf), and hands back what was written.
class StdoutCapture {
 public:
  explicit StdoutCapture(bool active) : active_(active) {
    if (!active_) return;
    std::fflush(stdout);
    file_ = std::tmpfile();
    saved_ = ::dup(STDOUT_FILENO);
    if (file_ == nullptr || saved_ < 0 || ::dup2(::fileno(file_), STDOUT_FILENO) < 0) active_ = false;
  }
  ~StdoutCapture() { restore(); }
  StdoutCapture(const StdoutCapture&) = delete;
  StdoutCapture& operator=(const StdoutCapture&) = delete;

  // Restores stdout and returns the captured text.
  std::string restore() {
    if (!active_) return text_;
    std::fflush(stdout);
    ::dup2(saved_, STDOUT_FILENO);
    ::close(saved_);
    active_ = false;
    std::rewind(file_);
    char buffer[4096];
    std::size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, file_)) > 0) text_.append(buffer, n);
    std::fclose(file_);
    return text_;
  }

 private:
  bool active_;
  std::FILE* file_ = nullptr;
  int saved_ = -1;
  std::string text_;
};

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

// Runs TetGen -d on the surface and names the triangles it finds intersecting;
// empty when there are none. This must run before meshing: TetGen 1.5.0
// crashes (freeing its pools) instead of throwing on some self-intersecting
// inputs, so they must never reach the meshing pass.
std::string find_self_intersections(const SurfaceMesh& surface, const TetrahedralizeOptions& options) {
  tetgenio in, out;
  fill_plc(surface, in);
  tetgenbehavior behavior;
  std::string sw = switches_for(options, true);
  if (!behavior.parse_commandline(sw.data())) return {};
  StdoutCapture capture(!options.verbose);
  try {
    tetrahedralize(&behavior, &in, &out);
  } catch (int) {
    return "the surface intersects itself or is degenerate (TetGen's detection failed)";
  }
  capture.restore();
  if (out.numberoftrifaces == 0) return {};
  // With -d TetGen returns the intersecting facets as triangles in out.trifacelist.
  std::set<std::array<int, 3>> faces;
  for (int i = 0; i < out.numberoftrifaces; ++i) {
    std::array<int, 3> f = {out.trifacelist[3 * i], out.trifacelist[3 * i + 1], out.trifacelist[3 * i + 2]};
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

std::string first_error_line(const std::string& chatter) {
  std::istringstream lines(chatter);
  std::string line;
  while (std::getline(lines, line))
    if (line.find("Error") != std::string::npos || line.find("error") != std::string::npos) return line;
  return {};
}

}  // namespace

TetMesh tetrahedralize(const SurfaceMesh& surface, const TetrahedralizeOptions& options, const std::string& source) {
  if (surface.triangles.size() < 4) throw InputError(source + ": the surface has fewer than 4 faces");
  if (const std::size_t open = surface.count_open_edges(); open > 0)
    throw InputError(source + ": the surface is not closed (" + std::to_string(open) +
                     " edges are not shared by exactly two faces: a hole or a non-manifold seam)");
  if (options.max_volume < 0 || options.radius_edge_ratio < 0)
    throw InputError(source + ": max volume and quality bound must not be negative");

  if (const std::string fault = find_self_intersections(surface, options); !fault.empty())
    throw InputError(source + ": " + fault);

  tetgenio in, out;
  fill_plc(surface, in);
  tetgenbehavior behavior;
  std::string sw = switches_for(options, false);
  if (!behavior.parse_commandline(sw.data())) throw InputError(source + ": bad TetGen switches '" + sw + "'");

  int code = 0;
  std::string chatter;
  {
    StdoutCapture capture(!options.verbose);
    try {
      tetrahedralize(&behavior, &in, &out);
    } catch (int c) {
      code = c;
    }
    chatter = capture.restore();
  }
  switch (code) {
    case 0: break;
    case 1: throw InputError(source + ": TetGen ran out of memory (raise --max-volume)");
    case 3: throw InputError(source + ": the surface intersects itself");
    case 4: throw InputError(source + ": the surface has features too small for TetGen's tolerance");
    case 5: throw InputError(source + ": the surface has two facets too close to each other");
    default: {
      const std::string line = first_error_line(chatter);
      throw InputError(source + ": TetGen failed (code " + std::to_string(code) + ")" +
                       (line.empty() ? std::string() : ": " + line));
    }
  }
  if (out.numberoftetrahedra == 0) throw InputError(source + ": TetGen produced no tetrahedra");

  std::vector<Vec3> positions(static_cast<std::size_t>(out.numberofpoints));
  for (std::size_t i = 0; i < positions.size(); ++i)
    positions[i] = Vec3(out.pointlist[3 * i], out.pointlist[3 * i + 1], out.pointlist[3 * i + 2]);
  std::vector<std::array<std::int64_t, 4>> tets(static_cast<std::size_t>(out.numberoftetrahedra));
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (int k = 0; k < 4; ++k) tets[t][k] = out.tetrahedronlist[out.numberofcorners * t + k];
  return make_tet_mesh(std::move(positions), tets, source);
}

}  // namespace mtcut::engine
