// The files `mtcut run` writes into its output folder: metrics.csv,
// summary.json, the .vtu snapshots and their .pvd collection, surface.obj.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "engine/io/mesh_file.h"
#include "engine/io/xml_scanner.h"
#include "engine/surface_mesh.h"
#include "tests/app/run_fixture.h"

namespace mtcut::test {
namespace {
namespace fs = std::filesystem;

// The .vtu's XML part (up to its appended block), checked to be well formed
// (tags balanced), with its cell data arrays decoded from the appended block.
struct VtuFile {
  std::size_t cells = 0;
  std::map<std::string, std::vector<double>> cell_data;  // Float64 arrays by name
};

VtuFile read_vtu_file(const std::string& path) {
  const std::string text = read_text(path);
  engine::XmlScanner scanner(path, text);
  std::vector<std::string> open;
  std::map<std::string, std::size_t> offsets;
  VtuFile vtu;
  bool in_cell_data = false;
  std::size_t data_start = 0;
  for (engine::XmlTag tag; scanner.next_tag(tag);) {
    if (tag.closing) {
      EXPECT_FALSE(open.empty()) << path;
      if (open.empty()) break;
      EXPECT_EQ(open.back(), tag.name) << path;
      open.pop_back();
      if (tag.name == "CellData") in_cell_data = false;
      continue;
    }
    if (tag.name == "Piece") vtu.cells = std::stoul(tag.attribute("NumberOfCells").value_or("0"));
    if (tag.name == "CellData") in_cell_data = true;
    if (tag.name == "DataArray" && in_cell_data) {
      EXPECT_EQ(tag.attribute("type"), "Float64");
      offsets[tag.attribute("Name").value()] = std::stoul(tag.attribute("offset").value());
    }
    if (tag.name == "AppendedData") {
      data_start = text.find('_', tag.end) + 1;  // raw data after the '_' marker
      break;
    }
    if (!tag.self_closing) open.push_back(tag.name);
  }
  EXPECT_EQ(open, (std::vector<std::string>{"VTKFile"})) << path;
  EXPECT_TRUE(text.ends_with("\n  </AppendedData>\n</VTKFile>\n")) << path;
  for (const auto& [name, offset] : offsets) {
    std::uint64_t bytes = 0;
    std::memcpy(&bytes, text.data() + data_start + offset, sizeof bytes);
    std::vector<double> values(bytes / sizeof(double));
    std::memcpy(values.data(), text.data() + data_start + offset + sizeof bytes, bytes);
    vtu.cell_data[name] = std::move(values);
  }
  return vtu;
}

// (timestep, file) of each DataSet of a .pvd.
std::vector<std::pair<double, std::string>> read_pvd(const std::string& path) {
  const std::string text = read_text(path);
  engine::XmlScanner scanner(path, text);
  std::vector<std::pair<double, std::string>> sets;
  for (engine::XmlTag tag; scanner.next_tag(tag);) {
    if (tag.name == "VTKFile" && !tag.closing) {
      EXPECT_EQ(tag.attribute("type"), "Collection");
    }
    if (tag.name == "DataSet")
      sets.emplace_back(std::stod(tag.attribute("timestep").value()), tag.attribute("file").value());
  }
  return sets;
}

class RunOutputs : public RunFixture {};

TEST_F(RunOutputs, EveryOutputExistsAndParses) {
  const std::string scenario = write("snap.toml", with_snapshots(4));
  const std::string out = path("out");
  const CommandResult r = run_mtcut("run " + quoted(scenario) + " --frames 10 --json --out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto summary = nlohmann::json::parse(r.out);
  EXPECT_EQ(nlohmann::json::parse(read_text(out + "/summary.json")), summary);
  for (const char* key : {"frames", "pieces", "tets_total", "frontier_tets_final", "cut_ms_mean", "cut_ms_max",
                          "frame_ms_mean", "frame_ms_p99", "nan_events", "state_hash"})
    EXPECT_TRUE(summary.contains(key)) << key;
  EXPECT_EQ(summary["frames"], 10);
  EXPECT_EQ(summary["interrupted"], false);
  EXPECT_GE(summary["pieces"].get<int>(), 1);

  // metrics.csv: the header, then one row of 13 fields per frame.
  const auto lines = lines_of(read_text(out + "/metrics.csv"));
  ASSERT_EQ(lines.size(), 11u);
  EXPECT_EQ(lines[0],
            "frame,sim_time,frontier_tets,frontier_vertices,cut_jobs_pending,cut_ms,lod_ms,sim_ms,frame_ms,"
            "kinetic_energy,pieces,cut_vertices,provisional_tets");
  double last_time = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto f = fields_of(lines[i]);
    ASSERT_EQ(f.size(), 13u) << lines[i];
    EXPECT_EQ(std::stoi(f[0]), static_cast<int>(i));
    EXPECT_GT(std::stod(f[1]), last_time);
    last_time = std::stod(f[1]);
    EXPECT_GT(std::stoi(f[2]), 0);
    EXPECT_GE(std::stod(f[9]), 0.0);
    EXPECT_GE(std::stoi(f[10]), 1);
  }
  EXPECT_EQ(fields_of(lines.back())[2], std::to_string(summary["frontier_tets_final"].get<int>()));
  EXPECT_EQ(std::stoi(fields_of(lines.back())[10]), summary["pieces"].get<int>());

  // The collection lists frames 0, 4, 8 and the last (10), in time order,
  // and exactly the .vtu files of the folder.
  const auto sets = read_pvd(out + "/snapshots.pvd");
  std::vector<std::string> listed, present;
  for (const auto& [time, file] : sets) listed.push_back(file);
  EXPECT_EQ(listed, (std::vector<std::string>{"snapshot_000000.vtu", "snapshot_000004.vtu", "snapshot_000008.vtu",
                                              "snapshot_000010.vtu"}));
  EXPECT_TRUE(std::is_sorted(sets.begin(), sets.end()));
  EXPECT_EQ(sets.front().first, 0.0);
  EXPECT_DOUBLE_EQ(sets.back().first, summary["simulated_seconds"].get<double>());
  std::vector<std::string> surfaces_present;
  for (const auto& entry : fs::directory_iterator(out)) {
    const std::string file = entry.path().filename().string();
    if (entry.path().extension() != ".vtu") continue;
    (file.starts_with("surface_") ? surfaces_present : present).push_back(file);
  }
  std::sort(present.begin(), present.end());
  std::sort(surfaces_present.begin(), surfaces_present.end());
  EXPECT_EQ(present, listed);
  // The finest surface's series: the same frames and times, its own files.
  const auto surface_sets = read_pvd(out + "/surface.pvd");
  std::vector<std::string> surfaces_listed;
  for (std::size_t i = 0; i < surface_sets.size(); ++i) {
    surfaces_listed.push_back(surface_sets[i].second);
    ASSERT_LT(i, sets.size());
    EXPECT_EQ(surface_sets[i].first, sets[i].first);
    EXPECT_EQ(surface_sets[i].second, "surface_" + sets[i].second.substr(std::strlen("snapshot_")));
  }
  EXPECT_EQ(surface_sets.size(), sets.size());
  EXPECT_EQ(surfaces_present, surfaces_listed);

  // Each .vtu: well-formed, with the three cell arrays, readable as a mesh.
  for (const std::string& file : listed) {
    const VtuFile vtu = read_vtu_file(out + "/" + file);
    EXPECT_GT(vtu.cells, 0u);
    EXPECT_EQ(engine::read_volume_file(out + "/" + file).tets.size(), vtu.cells);
    for (const char* name : {"piece", "fragment_level", "made_by_cut"}) {
      ASSERT_EQ(vtu.cell_data.count(name), 1u) << file << " " << name;
      EXPECT_EQ(vtu.cell_data.at(name).size(), vtu.cells) << file << " " << name;
    }
    for (double p : vtu.cell_data.at("piece")) EXPECT_TRUE(p >= 0 && p == std::floor(p)) << p;
    for (double l : vtu.cell_data.at("fragment_level")) EXPECT_TRUE(l >= 0 && l == std::floor(l)) << l;
    for (double m : vtu.cell_data.at("made_by_cut")) EXPECT_TRUE(m == 0 || m == 1) << m;
  }
  // Each surface .vtu: triangles, a closed surface, the same three arrays.
  for (const std::string& file : surfaces_listed) {
    const VtuFile vtu = read_vtu_file(out + "/" + file);
    const engine::RawMesh raw = engine::read_volume_file(out + "/" + file);
    EXPECT_TRUE(raw.tets.empty()) << file;
    EXPECT_EQ(raw.triangles.size(), vtu.cells) << file;
    engine::SurfaceMesh mesh;
    mesh.positions = raw.positions;
    for (const auto& t : raw.triangles)
      mesh.triangles.push_back({static_cast<std::int32_t>(t[0]), static_cast<std::int32_t>(t[1]), static_cast<std::int32_t>(t[2])});
    EXPECT_EQ(mesh.count_open_edges(), 0u) << file;
    for (const char* name : {"piece", "fragment_level", "made_by_cut"}) {
      ASSERT_EQ(vtu.cell_data.count(name), 1u) << file << " " << name;
      EXPECT_EQ(vtu.cell_data.at(name).size(), vtu.cells) << file << " " << name;
    }
  }
  const VtuFile last = read_vtu_file(out + "/snapshot_000010.vtu");
  EXPECT_EQ(last.cells, summary["frontier_tets_final"].get<std::size_t>());
  const auto pieces = last.cell_data.at("piece");
  EXPECT_EQ(*std::max_element(pieces.begin(), pieces.end()) + 1, summary["pieces"].get<double>());

  // The final surface: a closed triangle surface.
  const engine::SurfaceMesh surface = engine::read_surface_file(out + "/surface.obj");
  EXPECT_GT(surface.triangles.size(), 0u);
  EXPECT_EQ(surface.count_open_edges(), 0u);

  // Nothing half-written is left behind.
  for (const auto& entry : fs::directory_iterator(out))
    EXPECT_FALSE(entry.path().filename().string().starts_with(".tmp-")) << entry.path();
}

TEST_F(RunOutputs, NoSnapshotsWhenTheScenarioAsksForNone) {
  const std::string out = path("out");
  const CommandResult r = run_mtcut("run " + quoted(write("none.toml", with_snapshots(0))) + " --frames 2 --out " +
                                    quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(out + "/snapshots.pvd"));
  EXPECT_TRUE(fs::exists(out + "/metrics.csv"));
  EXPECT_TRUE(fs::exists(out + "/surface.obj"));
  // Without --json: one paragraph for people.
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  EXPECT_NE(r.out.find("Ran 2 frames"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("state hash"), std::string::npos) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;  // no progress bar when stderr is not a terminal
}

TEST_F(RunOutputs, WithoutAScenarioItPlaysTheDefault) {
  const CommandResult implicit = run_mtcut("run --frames 3 --json --out " + quoted(path("a")));
  const CommandResult named = run_mtcut("run " + quoted(source_path("config/scenarios/default.toml")) +
                                        " --frames 3 --json --out " + quoted(path("b")));
  ASSERT_EQ(implicit.exit_code, 0) << implicit.err;
  ASSERT_EQ(named.exit_code, 0) << named.err;
  const auto a = nlohmann::json::parse(implicit.out), b = nlohmann::json::parse(named.out);
  EXPECT_TRUE(a["scenario"].get<std::string>().ends_with("scenarios/default.toml")) << a["scenario"];
  EXPECT_EQ(a["state_hash"], b["state_hash"]);
  EXPECT_TRUE(fs::exists(path("a/metrics.csv")));
}

TEST_F(RunOutputs, TheOutputFolderDefaultsToOutAndTheScenarioName) {
  const std::string scenario = write("my_case.toml", base_);
  const fs::path previous = fs::current_path();
  fs::current_path(dir_);
  const CommandResult r = run_mtcut("run " + quoted(scenario) + " --frames 2");
  fs::current_path(previous);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("out/my_case/summary.json")));
  EXPECT_TRUE(fs::exists(path("out/my_case/metrics.csv")));
}

TEST_F(RunOutputs, AnOutputFolderThatCannotBeMadeIsOneLineAndExit1) {
  write("file", "not a folder");
  const CommandResult r = run_mtcut("run --frames 2 --out " + quoted(path("file/out")));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("cannot create the output folder"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;

  const CommandResult trace = run_mtcut("run --frames 2 --out " + quoted(path("out")) + " --record " +
                                        quoted(path("no_folder/trace.csv")));
  EXPECT_EQ(trace.exit_code, 1);
  EXPECT_NE(trace.err.find("no_folder/trace.csv: cannot record the trace there"), std::string::npos) << trace.err;
  EXPECT_FALSE(fs::exists(path("out")));
}

}  // namespace
}  // namespace mtcut::test
