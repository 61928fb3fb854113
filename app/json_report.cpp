#include "app/json_report.h"

#include <algorithm>
#include <iomanip>

namespace mtcut::app {

nlohmann::ordered_json to_json(const engine::MeshStats& stats) {
  return {{"vertices", stats.vertices},
          {"tets", stats.tets},
          {"boundary_faces", stats.boundary_faces},
          {"volume", stats.volume},
          {"min_dihedral_deg", stats.min_dihedral_deg},
          {"mean_radius_ratio", stats.mean_radius_ratio},
          {"min_radius_ratio", stats.min_radius_ratio}};
}

void print_human(std::ostream& out, const nlohmann::ordered_json& report) {
  std::size_t width = 0;
  for (const auto& [key, value] : report.items()) width = std::max(width, key.size());
  for (const auto& [key, value] : report.items()) {
    out << std::left << std::setw(static_cast<int>(width) + 2) << (key + ":");
    if (value.is_string()) {
      out << value.get<std::string>();
    } else {
      out << value.dump();
    }
    out << "\n";
  }
}

void print_report(std::ostream& out, const nlohmann::ordered_json& report, bool json) {
  if (json) {
    out << report.dump() << "\n";
  } else {
    print_human(out, report);
  }
}

}  // namespace mtcut::app
