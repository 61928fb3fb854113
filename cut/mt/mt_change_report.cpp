#include "cut/mt/mt_change_report.h"

#include <algorithm>

namespace mtcut::cut {

void MtCutCounts::add(const MtCutCounts& o) {
  split_tets += o.split_tets;
  relabeled_tets += o.relabeled_tets;
  new_tets += o.new_tets;
  new_vertices += o.new_vertices;
  split_fragments += o.split_fragments;
  new_fragments += o.new_fragments;
  whole_fragments += o.whole_fragments;
  jobs += o.jobs;
  find_seconds += o.find_seconds;
  split_seconds += o.split_seconds;
  dag_seconds += o.dag_seconds;
}

void MtChangeReport::append(const MtChangeReport& later) {
  const auto offset = static_cast<std::uint32_t>(made_tets.size());
  for (TetReplacement r : later.replaced) {
    r.first += offset;
    replaced.push_back(r);
  }
  made_tets.insert(made_tets.end(), later.made_tets.begin(), later.made_tets.end());
  made_vertices.insert(made_vertices.end(), later.made_vertices.begin(), later.made_vertices.end());
  fragment_splits.insert(fragment_splits.end(), later.fragment_splits.begin(), later.fragment_splits.end());
  processed.insert(processed.end(), later.processed.begin(), later.processed.end());
  counts.add(later.counts);
}

void MtChangeReport::truncate(const Length& to) {
  replaced.resize(std::min(replaced.size(), to.replaced));
  made_tets.resize(std::min(made_tets.size(), to.made_tets));
  made_vertices.resize(std::min(made_vertices.size(), to.made_vertices));
  fragment_splits.resize(std::min(fragment_splits.size(), to.fragment_splits));
  processed.resize(std::min(processed.size(), to.processed));
}

void MtChangeReport::renumber(const engine::Mt::Compaction& compaction) {
  for (TetReplacement& r : replaced) r.old = compaction.tet(r.old);
  for (TetId& t : made_tets) t = compaction.tet(t);
  for (MadeVertex& m : made_vertices) {
    m.id = compaction.vertex(m.id);
    for (VertId& parent : m.parents)
      if (parent.valid()) parent = compaction.vertex(parent);
    // Keys name vertices by id (sorted; the renumbering keeps their order).
    for (std::int32_t& id : m.key.ids)
      if (id >= 0) id = compaction.vertex_map[static_cast<std::size_t>(id)];
  }
}

}  // namespace mtcut::cut
