#pragma once
// `mtcut bench table1`: the paper's Table 1 (cut/mt/table1_bench.h) on the
// `--preset paper` MT, our row beside the paper's, as JSON and optionally as
// a markdown table with the machine it ran on (docs/table1.md).

#include <nlohmann/json.hpp>
#include <string>

namespace mtcut::app {

struct Table1BenchDef {
  int runs = 5;          // timed runs per row (median), each on a fresh copy of the MT
  std::string markdown;  // write the markdown table here (empty: none)
};

// {"mt": {...}, "machine": {...}, "runs": N, "rows": [{split_fragments,
// split_tets, new_tets_bielser17, new_tets_lut, pieces, split_ms,
// dag_update_ms, total_ms, "paper": {...}}, ...]}. Throws InputError when
// the markdown file cannot be written.
nlohmann::ordered_json run_table1_bench(const Table1BenchDef& def);

// Where a benchmark ran: cpu (model name from /proc/cpuinfo), logical_cores,
// compiler, build_type, load_average (1 minute, at the call), asserts.
nlohmann::ordered_json describe_machine();

// The markdown page of a run_table1_bench() report.
std::string table1_markdown(const nlohmann::ordered_json& report);

}  // namespace mtcut::app
