#pragma once
// The paper's Table 1 experiment on an MT (`mtcut bench table1`): planar cuts
// of growing size through the object, the last one separating it, each on a
// fresh copy of the MT, reporting what the paper reports. Plain structs; the
// app wires the command and prints JSON / markdown.
//
// Why these cuts. The paper gives only its counts, not its cuts. The cuts
// here are squares in one fixed, slightly tilted plane through the middle
// of the model (tilted so that it meets no vertex exactly), centred off the
// middle so that the smaller ones stay partial; their sizes are chosen so
// that the numbers of split tets fall near the paper's rows on the "paper"
// preset MT.

#include <array>
#include <cstddef>
#include <vector>

#include "engine/mt/mt.h"

namespace mtcut::cut {

struct Table1Row {
  double half_size = 0;             // of the square cut, fraction of the model box's diagonal
  std::size_t split_fragments = 0;  // fragments decomposed
  std::size_t split_tets = 0;       // tets replaced (every resolution)
  std::size_t new_tets_bielser17 = 0;
  std::size_t new_tets_lut = 0;
  std::size_t pieces = 0;           // after the cut
  double split_ms = 0;              // find + replace (median over runs)
  double dag_update_ms = 0;         // decomposition and arcs (median)
  double total_ms = 0;              // median of the per-run totals
};

// The paper's Table 1, in its order (ms).
struct PaperTable1Row {
  std::size_t split_fragments, split_tets, new_tets_bielser17, new_tets_lut;
  double split_ms, dag_update_ms, total_ms;
};
inline constexpr std::array<PaperTable1Row, 5> kPaperTable1 = {{
    {205, 2520, 42840, 11612, 277, 117, 394},
    {36, 523, 8891, 2394, 63, 156, 312},
    {148, 1813, 30821, 8300, 250, 109, 359},
    {245, 3122, 53074, 14316, 344, 141, 485},  // the paper prints 53,0474
    {528, 6552, 110874, 29918, 531, 344, 875},
}};

struct Table1Def {
  int runs = 5;  // timed runs per row (median), each on a fresh copy
  // Half sizes of the five cuts (fraction of the box diagonal), the paper's row order.
  std::array<double, 5> half_sizes = {0.193, 0.08, 0.163, 0.215, 2.0};
};

struct Table1Result {
  std::size_t mt_vertices = 0, mt_tets = 0, mt_fragments = 0;
  std::vector<Table1Row> rows;
};

Table1Result run_table1(const engine::Mt& mt, const Table1Def& def = {});

}  // namespace mtcut::cut
