#include "cut/mt/mt_cut_workspace.h"

#include <string>

namespace mtcut::cut {

void MtCutWorkspace::reserve(std::size_t vertices, std::size_t tets, std::size_t fragments) {
  classifier.reserve(vertices);
  if (separating.size() < vertices) separating.resize(vertices, 0);
  if (decomposition.vertex_owner.size() < vertices) decomposition.vertex_owner.resize(vertices, -1);
  if (pending_of.size() < tets) pending_of.resize(tets, -1);
  if (id_bits.size() < tets / 64 + 1) id_bits.resize(tets / 64 + 1, 0);
  if (job_of_fragment.size() < fragments) job_of_fragment.resize(fragments, -1);
}

engine::ValidationReport MtCutWorkspace::validate() const {
  engine::ValidationReport report = classifier.validate();
  for (std::size_t v = 0; v < separating.size(); ++v)
    if (separating[v] != 0) report.add("MtCutWorkspace: vertex " + std::to_string(v) + " left marked separating");
  for (std::size_t v = 0; v < decomposition.vertex_owner.size(); ++v)
    if (decomposition.vertex_owner[v] != -1)
      report.add("MtCutWorkspace: vertex " + std::to_string(v) + " left owned by the decomposition");
  for (std::size_t t = 0; t < pending_of.size(); ++t)
    if (pending_of[t] != -1) report.add("MtCutWorkspace: tet " + std::to_string(t) + " left marked pending");
  for (std::size_t f = 0; f < job_of_fragment.size(); ++f)
    if (job_of_fragment[f] != -1) report.add("MtCutWorkspace: fragment " + std::to_string(f) + " left mapped to a job");
  for (std::size_t w = 0; w < id_bits.size(); ++w)
    if (id_bits[w] != 0) report.add("MtCutWorkspace: id bits left set in word " + std::to_string(w));
  return report;
}

}  // namespace mtcut::cut
