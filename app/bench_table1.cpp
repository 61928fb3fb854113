#include "app/bench_table1.h"

#include <fstream>
#include <iomanip>
#include <sstream>
#include <thread>

#include "app/mt_command.h"
#include "cut/mt/frame_step_bench.h"
#include "cut/mt/table1_bench.h"
#include "engine/atomic_file.h"

namespace mtcut::app {
namespace {

// The paper's MT (its section 6): what the preset imitates.
constexpr std::size_t kPaperVertices = 2896, kPaperTets = 37062, kPaperFragments = 1542;

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("model name", 0) != 0) continue;
    const std::size_t colon = line.find(':');
    if (colon != std::string::npos) return line.substr(line.find_first_not_of(" \t", colon + 1));
  }
  return "unknown";
}

// The 1-minute load average (other jobs sharing the cores), -1 if unknown.
double load_average() {
  std::ifstream in("/proc/loadavg");
  double load = -1;
  in >> load;
  return in ? load : -1.0;
}

std::string compiler() {
#if defined(__clang__)
  return std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  return std::string("g++ ") + __VERSION__;
#else
  return "unknown";
#endif
}

nlohmann::ordered_json row_json(const cut::Table1Row& row, const cut::PaperTable1Row& paper) {
  return {{"half_size", row.half_size},
          {"split_fragments", row.split_fragments},
          {"split_tets", row.split_tets},
          {"new_tets_bielser17", row.new_tets_bielser17},
          {"new_tets_lut", row.new_tets_lut},
          {"pieces", row.pieces},
          {"split_ms", row.split_ms},
          {"dag_update_ms", row.dag_update_ms},
          {"total_ms", row.total_ms},
          {"paper",
           {{"split_fragments", paper.split_fragments},
            {"split_tets", paper.split_tets},
            {"new_tets_bielser17", paper.new_tets_bielser17},
            {"new_tets_lut", paper.new_tets_lut},
            {"split_ms", paper.split_ms},
            {"dag_update_ms", paper.dag_update_ms},
            {"total_ms", paper.total_ms}}}};
}

// "ours / paper" for one cell.
std::string pair_cell(const nlohmann::ordered_json& row, const char* key, bool ms) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  if (ms) {
    s.precision(2);
    s << row[key].get<double>() << " / " << static_cast<long long>(row["paper"][key].get<double>());
  } else {
    s << row[key].get<std::size_t>() << " / " << row["paper"][key].get<std::size_t>();
  }
  return s.str();
}

}  // namespace

nlohmann::ordered_json describe_machine() {
  return {{"cpu", cpu_model()},
          {"logical_cores", std::thread::hardware_concurrency()},
          {"compiler", compiler()},
          {"build_type", MTCUT_BUILD_TYPE},
          {"load_average", load_average()},
#ifdef NDEBUG
          {"asserts", false}
#else
          {"asserts", true}
#endif
  };
}

nlohmann::ordered_json run_table1_bench(const Table1BenchDef& def) {
  const BuiltMt built = build_preset_mt("paper");
  cut::Table1Def table_def;
  table_def.runs = def.runs;
  const cut::Table1Result result = cut::run_table1(built.mt, table_def);

  nlohmann::ordered_json out;
  out["mt"] = {{"preset", "paper"},
               {"vertices", result.mt_vertices},
               {"tets", result.mt_tets},
               {"fragments", result.mt_fragments},
               {"build_seconds", built.mesh_seconds + built.build_seconds},
               {"paper", {{"vertices", kPaperVertices}, {"tets", kPaperTets}, {"fragments", kPaperFragments}}}};
  out["machine"] = describe_machine();
  out["runs"] = def.runs;
  out["rows"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < result.rows.size(); ++i)
    out["rows"].push_back(row_json(result.rows[i], cut::kPaperTable1[i]));
  cut::FrameStepDef step_def;
  step_def.runs = def.runs;
  const cut::FrameStepResult steps = cut::run_frame_steps(built.mt, step_def);
  out["frame_step"] = {{"steps", steps.steps},
                       {"sweep_width", step_def.sweep_width},
                       {"blade_depth", step_def.blade_depth},
                       {"stride", step_def.stride},
                       {"split_tets_median", steps.split_tets_median},
                       {"split_tets_max", steps.split_tets_max},
                       {"new_tets_median", steps.new_tets_median},
                       {"ms_median", steps.ms_median},
                       {"ms_p90", steps.ms_p90},
                       {"ms_max", steps.ms_max}};
  if (!def.markdown.empty())
    engine::write_stream_atomically(def.markdown, [&](std::ostream& md) { md << table1_markdown(out); });
  return out;
}

std::string table1_markdown(const nlohmann::ordered_json& report) {
  const auto& mt = report["mt"];
  const auto& machine = report["machine"];
  std::ostringstream md;
  md << "# Table 1: cutting the paper's MT\n\n"
     << "Written by `mtcut bench table1 --runs " << report["runs"].get<int>()
     << " --markdown docs/table1.md`. Each cell is ours / the paper's (Ganovelli et al., Table 1, on 1999 "
        "hardware). Times are medians over "
     << report["runs"].get<int>()
     << " runs, each on a fresh copy of the MT, one core; split = finding the crossed tets of every resolution and "
        "replacing them by their LUT split; DAG update = decomposing the fragments the cut separates and "
        "re-attaching their arcs. The 1:17 column is the tets Bielser's reference split would make on the same "
        "cut. Split tets counts every MT tet the cut replaces or moves onto a split vertex's copy.\n\n"
     << "MT (`--preset paper`): " << mt["vertices"].get<std::size_t>() << " vertices, "
     << mt["tets"].get<std::size_t>() << " tets, " << mt["fragments"].get<std::size_t>()
     << " fragments (the paper's: " << kPaperVertices << ", " << kPaperTets << ", " << kPaperFragments << ").\n\n"
     << "| row | split fragments | split tets | new tets 1:17 | new tets LUT | split ms | DAG update ms | total ms "
        "| pieces |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  int index = 1;
  for (const auto& row : report["rows"]) {
    md << "| " << index++ << " | " << pair_cell(row, "split_fragments", false) << " | "
       << pair_cell(row, "split_tets", false) << " | " << pair_cell(row, "new_tets_bielser17", false) << " | "
       << pair_cell(row, "new_tets_lut", false) << " | " << pair_cell(row, "split_ms", true) << " | "
       << pair_cell(row, "dag_update_ms", true) << " | " << pair_cell(row, "total_ms", true) << " | "
       << row["pieces"].get<std::size_t>() << " |\n";
  }
  if (report.contains("frame_step")) {
    const auto& step = report["frame_step"];
    md << "\nOne frame of a scalpel stroke (the quad a blade sweeps in a frame, cut at "
       << step["steps"].get<std::size_t>()
       << " places along a stroke across the model, in order, on one MT, every few frames so that no two cuts "
          "share a segment; median over runs of each step; see cut/mt/frame_step_bench.h): "
       << step["split_tets_median"].get<std::size_t>() << " split tets (median; at most "
       << step["split_tets_max"].get<std::size_t>() << "), " << std::fixed << std::setprecision(3)
       << step["ms_median"].get<double>() << " ms median, " << step["ms_p90"].get<double>() << " ms at the 90th percentile, "
       << step["ms_max"].get<double>() << " ms at most.\n";
  }
  md << "\nMachine: " << machine["cpu"].get<std::string>() << ", " << machine["logical_cores"].get<unsigned>()
     << " logical cores (shared with other jobs: load average " << machine["load_average"].get<double>()
     << " when the run began); " << machine["compiler"].get<std::string>() << ", "
     << machine["build_type"].get<std::string>() << " build, asserts "
     << (machine["asserts"].get<bool>() ? "on" : "off") << ".\n";
  return md.str();
}

}  // namespace mtcut::app
