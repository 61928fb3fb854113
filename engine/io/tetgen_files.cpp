// TetGen .node and .ele files: the pair read together, and written together.
// Format (TetGen manual, section 5.2): '#' starts a comment, blank lines are
// ignored. .node: "<points> 3 <attributes> <0|1 markers>", then one line per
// point "<number> x y z [attributes] [marker]". .ele: "<tets> <4|10>
// <0|1 region>", then "<number> n1 n2 n3 n4 [6 more] [region]". Numbers
// start at 0 or 1 (the first point's number) and run consecutively.

#include <charconv>
#include <filesystem>
#include <locale>
#include <ostream>

#include "engine/atomic_file.h"
#include "engine/input_error.h"
#include "engine/io/line_reader.h"
#include "engine/io/mesh_file.h"
#include "engine/io/mesh_readers.h"
#include "engine/text.h"

namespace mtcut::engine {
namespace {

// The tokens of the next line that holds data (comments stripped); empty at
// the end of the file.
std::vector<std::string_view> next_data_line(LineReader& reader) {
  std::string_view line;
  while (reader.next_line(line)) {
    const std::size_t hash = line.find('#');
    if (hash != std::string_view::npos) line = line.substr(0, hash);
    auto tokens = split_tokens(line);
    if (!tokens.empty()) return tokens;
  }
  return {};
}

void expect_no_more_lines(LineReader& reader, std::size_t declared, const std::string& items) {
  if (!next_data_line(reader).empty())
    reader.fail("more " + items + " than the " + std::to_string(declared) + " declared in the first line");
}

struct NodeFile {
  std::vector<Vec3> positions;
  std::int64_t first_number = 0;  // number of the first point (0 or 1 in practice)
};

NodeFile read_node_file(const std::string& path) {
  const std::string text = read_file_bytes(path);
  LineReader reader(path, text);
  const auto header = next_data_line(reader);
  if (header.empty()) reader.fail_file("no data (expected '<points> 3 <attributes> <markers>')");
  if (header.size() > 4)
    reader.fail("the first line has " + std::to_string(header.size()) + " values, expected at most 4");
  const std::size_t n = reader.to_count(header[0], "the number of points", text.size());
  if (n == 0) reader.fail("the file declares no points (points in a .poly file are not supported)");
  if (header.size() > 1 && reader.to_int(header[1], "the dimension") != 3)
    reader.fail("the dimension is " + std::string(header[1]) + ", only 3 is supported");
  const std::size_t attributes = header.size() > 2 ? reader.to_count(header[2], "the number of attributes", 1000) : 0;
  std::size_t markers = 0;
  if (header.size() > 3) {
    const std::int64_t m = reader.to_int(header[3], "the boundary marker flag");
    if (m != 0 && m != 1) reader.fail("the boundary marker flag is " + std::to_string(m) + ", expected 0 or 1");
    markers = static_cast<std::size_t>(m);
  }
  const std::size_t per_line = 4 + attributes + markers;

  NodeFile node;
  node.positions.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto tokens = next_data_line(reader);
    if (tokens.empty())
      reader.fail("the file is truncated: " + std::to_string(n) + " points declared, only " + std::to_string(i) +
                  " found");
    if (tokens.size() != per_line)
      reader.fail("point line has " + std::to_string(tokens.size()) + " values, expected " +
                  std::to_string(per_line) + " (number, x y z, " + std::to_string(attributes) + " attributes, " +
                  std::to_string(markers) + " marker)");
    const std::int64_t number = reader.to_int(tokens[0], "the point number");
    if (i == 0) {
      if (number < 0) reader.fail("the first point number is negative");
      node.first_number = number;
    } else if (number != node.first_number + static_cast<std::int64_t>(i)) {
      reader.fail("point numbers must be consecutive: expected " +
                  std::to_string(node.first_number + static_cast<std::int64_t>(i)) + ", found " +
                  std::to_string(number));
    }
    const std::string what = "point " + std::to_string(number) + " coordinate";
    node.positions.emplace_back(reader.to_real(tokens[1], what), reader.to_real(tokens[2], what),
                                reader.to_real(tokens[3], what));
  }
  expect_no_more_lines(reader, n, "points");
  return node;
}

std::vector<std::array<std::int64_t, 4>> read_ele_file(const std::string& path, const NodeFile& node) {
  const std::string text = read_file_bytes(path);
  LineReader reader(path, text);
  const auto header = next_data_line(reader);
  if (header.empty()) reader.fail_file("no data (expected '<tets> <4|10> <region flag>')");
  if (header.size() > 3)
    reader.fail("the first line has " + std::to_string(header.size()) + " values, expected at most 3");
  const std::size_t n = reader.to_count(header[0], "the number of tets", text.size());
  const std::int64_t corners = header.size() > 1 ? reader.to_int(header[1], "the number of nodes per tet") : 4;
  if (corners != 4 && corners != 10)
    reader.fail("a tet has " + std::to_string(corners) + " nodes, expected 4 or 10");
  std::size_t regions = 0;
  if (header.size() > 2) {
    const std::int64_t r = reader.to_int(header[2], "the region attribute flag");
    if (r != 0 && r != 1) reader.fail("the region attribute flag is " + std::to_string(r) + ", expected 0 or 1");
    regions = static_cast<std::size_t>(r);
  }
  const std::size_t per_line = 1 + static_cast<std::size_t>(corners) + regions;
  const std::int64_t lo = node.first_number;
  const std::int64_t hi = lo + static_cast<std::int64_t>(node.positions.size()) - 1;

  std::vector<std::array<std::int64_t, 4>> tets;
  tets.reserve(n);
  std::int64_t first_tet = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto tokens = next_data_line(reader);
    if (tokens.empty())
      reader.fail("the file is truncated: " + std::to_string(n) + " tets declared, only " + std::to_string(i) +
                  " found");
    if (tokens.size() != per_line)
      reader.fail("tet line has " + std::to_string(tokens.size()) + " values, expected " + std::to_string(per_line));
    const std::int64_t number = reader.to_int(tokens[0], "the tet number");
    if (i == 0) {
      first_tet = number;
    } else if (number != first_tet + static_cast<std::int64_t>(i)) {
      reader.fail("tet numbers must be consecutive: expected " +
                  std::to_string(first_tet + static_cast<std::int64_t>(i)) + ", found " + std::to_string(number));
    }
    std::array<std::int64_t, 4> tet{};
    for (std::size_t k = 0; k < 4; ++k) {
      const std::int64_t id = reader.to_int(tokens[1 + k], "a point number");
      if (id < lo || id > hi)
        reader.fail("tet " + std::to_string(number) + " refers to point " + std::to_string(id) +
                    ", but the points are numbered " + std::to_string(lo) + ".." + std::to_string(hi));
      tet[k] = id - lo;
    }
    for (std::size_t k = 5; k <= static_cast<std::size_t>(corners); ++k) {
      const std::int64_t id = reader.to_int(tokens[k], "a point number");
      if (id < lo || id > hi)
        reader.fail("tet " + std::to_string(number) + " refers to point " + std::to_string(id) +
                    ", but the points are numbered " + std::to_string(lo) + ".." + std::to_string(hi));
    }
    if (regions != 0) reader.to_real(tokens.back(), "the region attribute");
    tets.push_back(tet);
  }
  expect_no_more_lines(reader, n, "tets");
  return tets;
}

// The base name shared by the pair: path without a .node or .ele ending.
std::string tetgen_base(const std::string& path) {
  const std::filesystem::path p(path);
  const std::string ext = lower_extension(path);
  if (ext == ".node" || ext == ".ele") return (p.parent_path() / p.stem()).string();
  return path;
}

// Shortest text that reads back as exactly the same double.
void put_real(std::ostream& out, double value) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.write(buffer, ec == std::errc() ? end - buffer : 0);
}

}  // namespace

RawMesh read_tetgen(const std::string& node_path, const std::string& ele_path) {
  NodeFile node = read_node_file(node_path);
  RawMesh raw;
  raw.tets = read_ele_file(ele_path, node);
  raw.positions = std::move(node.positions);
  return raw;
}

// The .node/.ele pair that a path names (either file, or the base name).
std::pair<std::string, std::string> tetgen_pair(const std::string& path) {
  const std::string base = tetgen_base(path);
  return {base + ".node", base + ".ele"};
}

void write_tetgen(const TetMesh& mesh, const std::string& path) {
  const auto [node_path, ele_path] = tetgen_pair(path);
  write_stream_atomically(node_path, [&](std::ostream& out) {
    out.imbue(std::locale::classic());  // no digit grouping, whatever the global locale
    out << "# mtcut tet mesh: points, numbered from 0\n";
    out << mesh.num_vertices() << " 3 0 0\n";
    for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
      out << v;
      for (int k = 0; k < 3; ++k) {
        out << ' ';
        put_real(out, mesh.positions[v][k]);
      }
      out << '\n';
    }
  });
  write_stream_atomically(ele_path, [&](std::ostream& out) {
    out.imbue(std::locale::classic());
    out << "# mtcut tet mesh: positively oriented tets, points numbered from 0\n";
    out << mesh.num_tets() << " 4 0\n";
    for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
      const Tet& tet = mesh.tets[t];
      out << t << ' ' << tet[0].value << ' ' << tet[1].value << ' ' << tet[2].value << ' ' << tet[3].value << '\n';
    }
  });
}

}  // namespace mtcut::engine
