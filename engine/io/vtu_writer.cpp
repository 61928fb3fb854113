// VTK XML unstructured grid writer: the XML header names every array and its
// offset into one appended raw block (each array: a UInt64 byte count, then
// the values in the machine's byte order, which the header declares).
// Points Float64, connectivity/offsets Int64, types UInt8 (10 = tet,
// 5 = triangle), cell data Float64. ParaView and meshio read it; so does read_vtu.

#include <array>
#include <bit>
#include <cstring>
#include <locale>
#include <ostream>
#include <span>
#include <sstream>
#include <type_traits>

#include "engine/atomic_file.h"
#include "engine/input_error.h"
#include "engine/io/mesh_file.h"
#include "engine/surface_mesh.h"

namespace mtcut::engine {
namespace {

constexpr std::uint8_t kVtkTetra = 10;
constexpr std::uint8_t kVtkTriangle = 5;

std::string escape_xml(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

// The appended block under construction, and the offset of each array in it.
class AppendedBlock {
 public:
  // Starts an array of n values of T; returns its offset.
  template <class T>
  std::size_t add(const std::vector<T>& values) {
    const std::size_t offset = bytes_.size();
    const std::uint64_t count = values.size() * sizeof(T);
    append(&count, sizeof count);
    if (!values.empty()) append(values.data(), count);
    return offset;
  }
  const std::string& bytes() const { return bytes_; }

 private:
  void append(const void* data, std::size_t n) {
    const std::size_t at = bytes_.size();
    bytes_.resize(at + n);
    std::memcpy(bytes_.data() + at, data, n);
  }
  std::string bytes_;
};

// Writes cells of one VTK type, each a range of `corners` vertex ids.
template <class Cell>
void write_cells(std::span<const Vec3> positions, std::span<const Cell> cells, std::uint8_t type,
                 const char* cell_name, const std::string& path, const std::vector<CellField>& cell_data) {
  for (const CellField& field : cell_data)
    if (field.values.size() != cells.size())
      throw InputError(path + ": cell field '" + field.name + "' has " + std::to_string(field.values.size()) +
                       " values for " + std::to_string(cells.size()) + " " + cell_name);

  AppendedBlock block;
  std::vector<double> points;  // (3 n_vertices)
  points.reserve(3 * positions.size());
  for (const Vec3& p : positions) points.insert(points.end(), {p.x(), p.y(), p.z()});
  std::vector<std::int64_t> connectivity;  // (corners per cell * n_cells)
  std::vector<std::int64_t> offsets;       // (n_cells) end of each cell in connectivity
  offsets.reserve(cells.size());
  for (const Cell& cell : cells) {
    for (const auto& v : cell) {
      if constexpr (std::is_integral_v<std::decay_t<decltype(v)>>)
        connectivity.push_back(v);
      else
        connectivity.push_back(v.value);
    }
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
  }
  const std::vector<std::uint8_t> types(cells.size(), type);

  const std::size_t points_at = block.add(points);
  const std::size_t connectivity_at = block.add(connectivity);
  const std::size_t offsets_at = block.add(offsets);
  const std::size_t types_at = block.add(types);
  std::vector<std::size_t> fields_at;
  for (const CellField& field : cell_data) fields_at.push_back(block.add(field.values));

  std::ostringstream xml;
  xml.imbue(std::locale::classic());  // no digit grouping in counts and offsets
  const char* order = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  xml << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"" << order
      << "\" header_type=\"UInt64\">\n"
      << "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << positions.size() << "\" NumberOfCells=\"" << cells.size()
      << "\">\n"
      << "      <Points>\n"
      << "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"appended\" offset=\""
      << points_at << "\"/>\n"
      << "      </Points>\n"
      << "      <Cells>\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" offset=\"" << connectivity_at
      << "\"/>\n"
      << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" offset=\"" << offsets_at << "\"/>\n"
      << "        <DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"" << types_at << "\"/>\n"
      << "      </Cells>\n";
  if (!cell_data.empty()) {
    xml << "      <CellData>\n";
    for (std::size_t f = 0; f < cell_data.size(); ++f)
      xml << "        <DataArray type=\"Float64\" Name=\"" << escape_xml(cell_data[f].name)
          << "\" format=\"appended\" offset=\"" << fields_at[f] << "\"/>\n";
    xml << "      </CellData>\n";
  }
  xml << "    </Piece>\n"
      << "  </UnstructuredGrid>\n"
      << "  <AppendedData encoding=\"raw\">\n"
      << "   _";
  const std::string head = xml.str();

  write_stream_atomically(path, [&](std::ostream& out) {
    out.write(head.data(), static_cast<std::streamsize>(head.size()));
    out.write(block.bytes().data(), static_cast<std::streamsize>(block.bytes().size()));
    out << "\n  </AppendedData>\n</VTKFile>\n";
  });
}

}  // namespace

void write_vtu(const TetMesh& mesh, const std::string& path, const std::vector<CellField>& cell_data) {
  write_cells<Tet>(mesh.positions, mesh.tets, kVtkTetra, "tets", path, cell_data);
}

void write_vtu(const SurfaceMesh& mesh, const std::string& path, const std::vector<CellField>& cell_data) {
  write_cells<std::array<std::int32_t, 3>>(mesh.positions, mesh.triangles, kVtkTriangle, "triangles", path,
                                           cell_data);
}

}  // namespace mtcut::engine
