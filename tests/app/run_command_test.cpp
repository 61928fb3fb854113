// End-to-end tests of `mtcut run` and the scenario reader.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/run_summary.h"
#include "engine/surface_mesh.h"
#include "tests/app/run_fixture.h"
#include "tests/app/run_mtcut.h"
#include "tests/broken_surfaces.h"
#include "tests/test_paths.h"
#include "tests/touching_cubes.h"

namespace mtcut::test {
namespace {

class RunCommand : public RunFixture {
 protected:
  void expect_rejected(const std::string& scenario_text, const std::string& what) {
    const std::string file = write("bad.toml", scenario_text);
    const CommandResult r = run_mtcut("run " + quoted(file) + " --frames 2 --out " + quoted(path("out")));
    EXPECT_EQ(r.exit_code, 1) << what << "\n" << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }

  // `mtcut run ARGS --json --out OUT`: its summary, once checked that it
  // exited 0, ends valid and met no NaN; `err` receives what it printed on
  // stderr. An empty object when the run failed: the figures a test then
  // reads are null, and reading them fails it.
  nlohmann::json expect_valid_run(const std::string& args, const std::string& out_dir, std::string* err = nullptr) {
    const CommandResult r = run_mtcut("run " + args + " --json --out " + quoted(out_dir));
    if (err) *err = r.err;
    EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
    if (r.exit_code != 0) return nlohmann::json::object();
    nlohmann::json out = nlohmann::json::parse(r.out);
    EXPECT_TRUE(out.value("valid", false)) << args << "\n" << out.dump(1);
    EXPECT_EQ(out.value("nan_events", -1), 0) << args;
    return out;
  }
};

TEST_F(RunCommand, DefaultScenarioRunsValidAndWritesItsSummary) {
  const std::string summary = path("summary.json");
  nlohmann::json out = expect_valid_run(
      quoted(source_path("config/scenarios/default.toml")) + " --frames 30 --summary " + quoted(summary), path("out"));
  EXPECT_EQ(out["frames"].get<int>(), 30);
  EXPECT_EQ(nlohmann::json::parse(read_text(summary)), out);
  EXPECT_EQ(nlohmann::json::parse(read_text(path("out/summary.json"))), out);
}

// Refused steps are counted, and the paragraph says what they mean and what
// to change; a run without any says nothing of it.
TEST_F(RunCommand, RefusedStepsAreExplainedInTheParagraph) {
  const std::string unstable = write("unstable.toml", variant("kind = \"implicit\"", "kind = \"symplectic\""));
  const CommandResult bad = run_mtcut("run " + quoted(unstable) + " --frames 10 --out " + quoted(path("bad")));
  ASSERT_EQ(bad.exit_code, 0) << bad.err;
  EXPECT_EQ(bad.out.find(" 0 NaN events"), std::string::npos) << bad.out;
  EXPECT_NE(bad.out.find("steps refused"), std::string::npos) << bad.out;
  EXPECT_NE(bad.out.find("raise [integrator] substeps"), std::string::npos) << bad.out;
  const CommandResult good = run_mtcut("run " + quoted(source_path("config/scenarios/default.toml")) +
                                       " --frames 3 --out " + quoted(path("good")));
  ASSERT_EQ(good.exit_code, 0) << good.err;
  EXPECT_NE(good.out.find(" 0 NaN events;"), std::string::npos) << good.out;
  EXPECT_EQ(good.out.find("steps refused"), std::string::npos) << good.out;
}

TEST_F(RunCommand, SameScenarioTwiceGivesTheSameStateHash) {
  const std::string args = "run " + quoted(source_path("config/scenarios/default.toml")) + " --frames 40 --json" +
                           " --out " + quoted(path("out"));
  const CommandResult a = run_mtcut(args), b = run_mtcut(args);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(nlohmann::json::parse(a.out)["state_hash"], nlohmann::json::parse(b.out)["state_hash"]);
}

// The golden state hash of the whole default scenario. A change that moves
// any particle by one bit changes it: when that is intended (a new LUT, a
// new integrator, a new scenario), run
//   build/test/mtcut run config/scenarios/default.toml --json
// and put its state_hash here in the same commit, saying why. (x86-64 with
// SSE2 and no FMA contraction, as Debian's g++ builds by default; the AVX2
// copies of the spring loops give the same bits.) 7f65975465b62ad4: the
// World is told the scripted blade's first pose and starts on the frontier
// the LOD stage asks for around it (sim/world.h), where it started at the
// coarsest level and took that move at frame 3: the first two frames
// simulate the tissue near the blade finely; the stroke ends in 22,341
// tets, 2 pieces. Before that, 49b54fc5798d3934: the scenario's blade starts just off the organ's edge (y = -4.8 cm, at the
// same 12 cm/s), so it enters the tissue in the first frame and the
// incision shows from frame 2 (it started 1.4 cm away, in the air, and cut
// from frame 7 on); the stroke ends in 22,329 tets, 2 pieces. Before that,
// 019a400df66dc935: a part's frame keeps the splits of its front that its grown polygon
// leaves in the configuration they were made from
// (TimeCriticalCutter::recut, kept_front_splits), so their face points
// stay where the blade crossed the tets' faces when they were split, less
// than a tet behind it, and the tissue deforms around those points while
// the blade is in it; the stroke still ends as the one cut of its polygon
// (22,349 tets, 2 pieces, as before). Before that, ff3f85b6ebd7e33e: a
// stroke's part keeps a cut record once its plane is fixed
// (cut/mt/part_record.h): each frame commits the tets its polygon crosses
// completely and holds only its front provisionally, on one plane for the
// whole part, and the World grows the part by the rest-space sweep since its
// last cut, so the incision's points and the frames that cut them differ.
// Before that, 79e647d7debcbe4d: the
// World reclaims the slots retracted cuts leave whenever they outnumber the
// live tets (TimeCriticalCutter::reclaim, during the stroke too): the MT's
// vertices are renumbered and fewer, which the hash mixes in; the physics
// is the same to the bit (the kinetic energy of all 180 frames unchanged).
// Before that, cc236832a93ee149: the
// stroke is cut progressively (cut/mt/cut_retraction.h): the incision opens
// from frame 7, as the blade enters, where the whole cut landed at frame 64,
// so the tissue deforms around an opening incision for 57 more frames.
// Before that, 53d84a121de3e248: the
// level of detail follows the whole blade (base to tip), not its tip alone
// (engine/mt/segment_distance.h): the default stroke's tip is in the floor,
// out of every tet's reach, so the tissue at the incision had stayed coarse.
// Before that, 07583821151a7275: the spring model sums its volumes exactly in fixed point (fixed_volume.h; the
// masses and stiffnesses change in their last bits) and keys its particle
// order in the box of all the MT's rest positions, not only the used ones'
// (spring_model_update.h says why). Before that, 67abd17df8853882: the
// spring model numbers its particles along the rest shape's longest axis
// (spring_model.cpp), not in Morton order. Before that, 74ab1470ff4139d0: Van
// Gelder's formula counts an edge below a tenth of its tet's longest as
// that long (the cut's slivers; spring_model.h). Before that,
// 54b757ed05d5ff17: the
// implicit step's assembly sums the residual at the warm start, b - A dv0,
// spring by spring, where the solver summed A dv0 in a pass of its own (the
// same sums, added in another order). Before that, e0e23fda7f373733: the
// World follows its frontier through a cut in place (follow_cut) instead of
// rebuilding it, so after the cut the same tets come in another order and
// build_spring_model sums each spring's tet volumes in another order (with
// the tets sorted by id before the build, both ways give one hash,
// 5d8ac5d339c495b3). Before that, 4e81d327c40984f9: the volumes summed in
// tet order (they were summed in std::sort's unspecified order of equal keys).
constexpr const char* kDefaultScenarioGoldenHash = "7f65975465b62ad4";

// The pieces column of a run's metrics.csv at `frame` (-1: no such row).
int pieces_at_frame(const std::string& metrics_csv, int frame) {
  const std::vector<std::string> lines = lines_of(metrics_csv);
  if (lines.empty()) return -1;
  const std::vector<std::string> header = fields_of(lines.front());
  const auto column = static_cast<std::size_t>(std::find(header.begin(), header.end(), "pieces") - header.begin());
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::vector<std::string> fields = fields_of(lines[i]);
    if (column < fields.size() && std::stoi(fields[0]) == frame) return std::stoi(fields[column]);
  }
  return -1;
}

// The other shipped scenarios run valid to their end with no NaN and no cut
// refused. The stress scenario's first stroke goes across its front end
// through the whole organ, down below the floor the organ sags onto, in
// frames 1 to 27: the front end comes off then, and pieces never join
// again. (It asserts the cut of tissue the blade went through: a cut
// carried wrongly to rest space leaves the front end on.)
TEST_F(RunCommand, TheStressAndLiverScenariosRunValid) {
  for (const std::string name : {"stress", "liver"}) {
    nlohmann::json out = expect_valid_run(quoted(source_path("config/scenarios/" + name + ".toml")), path(name));
    EXPECT_EQ(out["cuts_refused"].get<int>(), 0) << name;
    EXPECT_FALSE(out["first_cut_frame"].is_null()) << name << ": nothing was cut";
    if (name == "stress") {
      EXPECT_EQ(pieces_at_frame(read_text(path(name) + "/metrics.csv"), 30), 2) << "the front end did not come off";
      EXPECT_GE(out["pieces"].get<int>(), 2);
    }
  }
}

TEST_F(RunCommand, DefaultScenarioCutsAFlapThatSettlesOnTheFloorWithTheGoldenHash) {
  nlohmann::json out = expect_valid_run(quoted(source_path("config/scenarios/default.toml")), path("out"));
  ASSERT_EQ(out["pieces"].get<int>(), 2);
  const auto& pieces = out["piece_details"];
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_GT(pieces[0]["held_particles"].get<int>(), 0) << "the organ is held at its back";
  EXPECT_EQ(pieces[1]["held_particles"].get<int>(), 0) << "the flap is free";
  // The flap is a real part of the front end (the cap beyond x = 3 cm of
  // the ellipsoid is about a fifth of it), not a sliver.
  const double organ = pieces[0]["rest_volume"].get<double>(), flap = pieces[1]["rest_volume"].get<double>();
  EXPECT_GT(flap, 0.05 * (organ + flap));
  // It lies on the floor (z = -3.6 cm), below the organ's top, in front.
  EXPECT_NEAR(pieces[1]["lowest_z"].get<double>(), -0.036, 1e-3);
  EXPECT_LT(pieces[1]["highest_z"].get<double>(), 0.0);
  EXPECT_GT(pieces[1]["centroid"][0].get<double>(), pieces[0]["centroid"][0].get<double>());
  EXPECT_EQ(out["state_hash"].get<std::string>(), kDefaultScenarioGoldenHash)
      << "the default scenario's outcome changed: if intended, update kDefaultScenarioGoldenHash (see above)";
}

TEST_F(RunCommand, BadScenariosGiveOneLineWithFileAndLine) {
  expect_rejected(variant("[lod]\n", "[lod]\nnear_radiu = 0.01\n"), "bad.toml:");
  expect_rejected(variant("[lod]\n", "[lod]\nnear_radiu = 0.01\n"), "unknown key 'lod.near_radiu'");
  expect_rejected(variant("[lod]\n", "[lod]\nbackground_build = 1\n"),
                  "'lod.background_build' must be true or false");
  expect_rejected(variant("[lod]\n", "[lod]\nbuild_frames = 0\n"), "'lod.build_frames' must be at least 1");
  expect_rejected(variant("[lod]\n", "[lod]\nbuild_frames = 1.5\n"), "'lod.build_frames' must be an integer");
  expect_rejected(variant("tets = 8000", "tets = \"many\""), "'mesh.tets' must be an integer");
  expect_rejected(variant("source = \"builtin:ellipsoid\"", "source = \"no_such_organ.obj\""), "does not exist");
  expect_rejected(variant("dt = 0.016666666666666666", "dt = -0.01"), "'run.dt' must be positive");
  expect_rejected(variant("[mt]\n", "[mt]\nmax_surface_deviation = 0.0\n"),
                  "'mt.max_surface_deviation' must be a positive fraction");
  expect_rejected(variant("surface = \"finest\"", "surface = \"coarse\""),
                  "'output.surface' must be \"finest\" or \"frontier\"");
  expect_rejected("[mesh]\nsource = \"builtin:box\"\n[scalpel]\n", "needs at least one [[scalpel.keyframes]]");
  expect_rejected(variant("source = \"builtin:ellipsoid\"",
                          "source = \"" + shared_mesh("liver_for_test_broken.vtk") + "\""),
                  "liver_for_test_broken.vtk");
  expect_rejected("[mesh\n", "bad.toml:1");
  const CommandResult missing = run_mtcut("run " + quoted(path("nothing.toml")));
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("nothing.toml: no such file"), std::string::npos) << missing.err;
}

// surface.obj shows the organ's finest surface, carried by the simulated
// frontier, unless [output] asks for the frontier's own: with a free
// boundary the coarse frontier far from the blade has fewer surface
// vertices, and lies off the fine surface; both are closed.
TEST_F(RunCommand, TheSurfaceWrittenIsTheFinestUnlessTheFrontiersIsAskedFor) {
  const std::string free_boundary = variant("preserve_boundary = true", "preserve_boundary = false");
  const auto surface_of = [&](const std::string& name, const std::string& text) {
    const std::string scenario = write(name + ".toml", text);
    expect_valid_run(quoted(scenario) + " --frames 3", path(name));
    return engine::read_surface_file(path(name + "/surface.obj"));
  };
  const engine::SurfaceMesh finest = surface_of("finest", free_boundary);
  std::string frontier_text = free_boundary;
  const std::string finest_key = "surface = \"finest\"";
  frontier_text.replace(frontier_text.find(finest_key), finest_key.size(), "surface = \"frontier\"");
  const engine::SurfaceMesh frontier = surface_of("frontier", frontier_text);
  EXPECT_EQ(finest.count_open_edges(), 0u);
  EXPECT_EQ(frontier.count_open_edges(), 0u);
  EXPECT_GT(finest.positions.size(), 2 * frontier.positions.size());
  // The snapshots' series of the finest surface comes with it.
  EXPECT_TRUE(std::filesystem::exists(path("finest/surface.pvd")));
  EXPECT_FALSE(std::filesystem::exists(path("frontier/surface.pvd")));
  EXPECT_TRUE(std::filesystem::exists(path("frontier/snapshots.pvd")));
}

// A mesh file's unit: named or in metres, never both, never with a builtin
// shape; a mesh too large for the spring model is named, with the units to give.
TEST_F(RunCommand, MeshUnitsAreCheckedAndAMeshInMillimetresIsToldWhatToSay) {
  const std::string builtin = "source = \"builtin:ellipsoid\"";
  expect_rejected(variant(builtin, builtin + "\nunits = \"mm\""), "a unit applies to mesh files only");
  const CommandResult made = run_mtcut("mesh builtin:ellipsoid --tets 2000 --size 0.12,0.08,0.06 -o " +
                                       quoted(path("organ.obj")));
  ASSERT_EQ(made.exit_code, 0) << made.err;
  const std::string organ = "source = \"" + path("organ.obj") + "\"";
  expect_rejected(variant(builtin, organ + "\nunits = \"parsec\""), "'mesh.units' 'parsec': unknown unit");
  expect_rejected(variant(builtin, organ + "\nunits = \"m\"\nscale = 1.0"), "not both");
  expect_rejected(variant(builtin, organ + "\nscale = -1.0"), "'mesh.scale' must be a positive");
  // The organ in millimetres, read as metres, is beyond the spring model.
  const CommandResult mm = run_mtcut("mesh " + quoted(path("organ.obj")) + " --scale 1000 -o " + quoted(path("mm.obj")));
  ASSERT_EQ(mm.exit_code, 0) << mm.err;
  const std::string scenario = write("mm.toml", variant(builtin, "source = \"" + path("mm.obj") + "\""));
  const CommandResult r = run_mtcut("run " + quoted(scenario) + " --frames 2 --out " + quoted(path("out")));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("--units mm"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("beyond what the spring model holds"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("mtcut: " + path("mm.obj") + ": the tets' volume"), std::string::npos) << r.err;
  // Said in millimetres, it runs.
  const std::string said = write("said.toml", variant(builtin, "source = \"" + path("mm.obj") + "\"\nunits = \"mm\""));
  const CommandResult ok = run_mtcut("run " + quoted(said) + " --frames 2 --out " + quoted(path("ok")));
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(ok.err, "");
}

// A tet mesh whose two parts touch only along an edge loads (its pinched
// vertices split, said on stderr), builds an MT, and is cut and simulated.
TEST_F(RunCommand, ATetMeshWhosePartsTouchAlongAnEdgeIsCut) {
  const auto [node, ele] = tetgen_text(touching_cubes(0.05, 0));
  write("cubes.node", node);
  write("cubes.ele", ele);
  std::string scenario = "[mesh]\nsource = \"" + path("cubes.node") + "\"\n";
  scenario += base_.substr(base_.find("[mt]"), base_.find("[[scalpel.keyframes]]") - base_.find("[mt]"));
  scenario += R"([[scalpel.keyframes]]
time = 0.0
base = [0.025, -0.01, 0.08]
tip = [0.025, -0.01, -0.02]
engaged = true

[[scalpel.keyframes]]
time = 0.5
base = [0.025, 0.06, 0.08]
tip = [0.025, 0.06, -0.02]
engaged = true
)";
  const auto fixed = scenario.find("offset = -0.06");
  ASSERT_NE(fixed, std::string::npos);
  scenario.replace(fixed, std::string("offset = -0.06").size(), "offset = -0.01");  // x <= 1 cm is held
  const auto floor = scenario.find("floor_height = -0.036");
  ASSERT_NE(floor, std::string::npos);
  scenario.replace(floor, std::string("floor_height = -0.036").size(), "floor_height = -0.001");
  const std::string file = write("cubes.toml", scenario);
  std::string err;
  nlohmann::json out = expect_valid_run(quoted(file) + " --frames 40", path("out"), &err);
  EXPECT_NE(err.find("parts of the mesh touch only at 2 vertices"), std::string::npos) << err;
  EXPECT_GT(out["tets_total"].get<int>(), 12);  // the cut split tets
  EXPECT_EQ(out["pieces"].get<int>(), 3) << out.dump();  // the first cube in two, and the second
}

// A surface of two organs that cross each other is repaired into their
// union (one line says so), meshed, and cut through by the default stroke.
TEST_F(RunCommand, ASurfaceThatCrossesItselfIsRepairedAndCut) {
  const std::string organ = path("organ.obj");
  ASSERT_EQ(run_mtcut("mesh builtin:ellipsoid --tets 3000 --size 0.16,0.1,0.07 -o " + quoted(organ)).exit_code, 0);
  // The organ twice, the second moved 3 cm along x and 1 cm along y and z.
  std::istringstream lines(read_text(organ));
  std::string line, points, faces, moved;
  int count = 0;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "v") {
      double x = 0, y = 0, z = 0;
      words >> x >> y >> z;
      points += line + "\n";
      moved += "v " + std::to_string(x + 0.03) + " " + std::to_string(y + 0.01) + " " + std::to_string(z + 0.01) + "\n";
      ++count;
    } else if (tag == "f") {
      faces += line + "\n";
    }
  }
  std::string shifted;
  std::istringstream face_lines(faces);
  while (std::getline(face_lines, line)) {
    std::istringstream words(line.substr(1));
    std::string corner;
    shifted += "f";
    while (words >> corner) shifted += " " + std::to_string(std::stoi(corner) + count);
    shifted += "\n";
  }
  const std::string two = write("two.obj", points + moved + faces + shifted);
  const std::string scenario = write("two.toml", variant("source = \"builtin:ellipsoid\"", "source = \"" + two + "\""));
  std::string err;
  nlohmann::json out = expect_valid_run(quoted(scenario) + " --frames 70", path("out"), &err);
  EXPECT_NE(err.find("two.obj: repaired (self-intersections resolved)"), std::string::npos) << err;
  EXPECT_EQ(out["cuts_refused"].get<int>(), 0);
  EXPECT_FALSE(out["first_cut_frame"].is_null());
  EXPECT_EQ(out["pieces"].get<int>(), 2) << out.dump();  // the stroke cuts the union through
}

// The other surfaces people have: one with holes, one with a non-manifold
// seam (a fin on an edge of the organ: three faces on that edge). Each is
// repaired (one line says so), meshed and cut through by the default
// stroke.
TEST_F(RunCommand, SurfacesWithHolesOrANonManifoldSeamAreRepairedAndCut) {
  engine::SurfaceMesh seam = ellipsoid_surface(organ_size(), Vec3::Zero(), 3000);
  const std::array<std::int32_t, 3> face = seam.triangles.front();
  const Vec3 a = seam.positions[static_cast<std::size_t>(face[0])], b = seam.positions[static_cast<std::size_t>(face[1])];
  seam.positions.push_back(0.5 * (a + b) + 0.01 * (a + b).normalized());
  seam.triangles.push_back({face[1], face[0], static_cast<std::int32_t>(seam.positions.size() - 1)});
  ASSERT_GT(seam.count_open_edges(), 0u);
  const std::pair<const char*, engine::SurfaceMesh> surfaces[] = {{"holed.obj", holed_organ(3000)},
                                                                  {"seam.obj", seam}};
  for (const auto& [name, surface] : surfaces) {
    SCOPED_TRACE(name);
    // As text: the project's writer would put the fin over copies of its
    // corners (every face kept, none non-manifold), and the file would
    // hold no seam.
    std::ostringstream obj;
    obj.precision(17);
    for (const Vec3& p : surface.positions) obj << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    for (const auto& t : surface.triangles) obj << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    const std::string file = write(name, obj.str());
    const std::string scenario =
        write(std::string(name) + ".toml", variant("source = \"builtin:ellipsoid\"", "source = \"" + file + "\""));
    std::string err;
    nlohmann::json out = expect_valid_run(quoted(scenario) + " --frames 70", path(std::string("out_") + name), &err);
    EXPECT_NE(err.find(std::string(name) + ": repaired"), std::string::npos) << err;
    EXPECT_EQ(out["cuts_refused"].get<int>(), 0);
    EXPECT_FALSE(out["first_cut_frame"].is_null());
    EXPECT_EQ(out["pieces"].get<int>(), 2) << out.dump();  // the stroke cuts the organ through
  }
}

// An XML VTK file (.vtu) saved with a legacy VTK name is read by its
// content, meshed and cut through by the default stroke.
TEST_F(RunCommand, AnXmlVtkFileNamedVtkIsReadByItsContentAndCut) {
  const std::string vtu = path("organ.vtu"), vtk = path("organ.vtk");
  ASSERT_EQ(run_mtcut("mesh builtin:ellipsoid --tets 3000 --size 0.16,0.1,0.07 -o " + quoted(vtu)).exit_code, 0);
  std::filesystem::rename(vtu, vtk);
  const std::string scenario = write("vtk.toml", variant("source = \"builtin:ellipsoid\"", "source = \"" + vtk + "\""));
  nlohmann::json out = expect_valid_run(quoted(scenario) + " --frames 70", path("out"));
  EXPECT_EQ(out["cuts_refused"].get<int>(), 0);
  EXPECT_FALSE(out["first_cut_frame"].is_null());
  EXPECT_EQ(out["pieces"].get<int>(), 2) << out.dump();
}

// An end state that fails validation names the first failing check.
TEST_F(RunCommand, AnInvalidEndStateIsNamedInTheParagraph) {
  nlohmann::ordered_json summary = nlohmann::ordered_json::parse(
      run_mtcut("run " + quoted(source_path("config/scenarios/default.toml")) + " --frames 2 --json --out " +
                quoted(path("out")))
          .out);
  std::ostringstream valid;
  app::print_run_paragraph(valid, summary);
  EXPECT_NE(valid.str().find("are valid;"), std::string::npos) << valid.str();
  summary["valid"] = false;
  summary["problems"] = {"spring 12 has zero rest length", "tet 4 is flat"};
  std::ostringstream invalid;
  app::print_run_paragraph(invalid, summary);
  EXPECT_NE(invalid.str().find("NOT valid (spring 12 has zero rest length; 1 more in summary.json)"),
            std::string::npos)
      << invalid.str();
}

TEST_F(RunCommand, LineNumbersPointAtTheFault) {
  const std::string text = variant("frames = 180", "frames = 0");
  // The line that holds "frames = 0".
  const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(text.find("frames = 0")), '\n');
  expect_rejected(text, "bad.toml:" + std::to_string(line) + ": 'run.frames' must be at least 1");
}

}  // namespace
}  // namespace mtcut::test
