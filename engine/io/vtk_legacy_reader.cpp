// Legacy VTK .vtk reader (file versions 1.0 to 5.1), ASCII or BINARY (big-
// endian values right after each keyword line). DATASET UNSTRUCTURED_GRID:
// POINTS, CELLS, CELL_TYPES; tets are type 10 (or 24, quadratic), triangles
// type 5 (or 22), other cells are skipped. DATASET POLYDATA: POLYGONS become triangles (polygons
// with more corners are fanned), TRIANGLE_STRIPS are split, VERTICES and
// LINES are skipped. Version 5.x cell blocks (OFFSETS + CONNECTIVITY) are
// read as well as the classic ones. A FIELD block is skipped; POINT_DATA and
// CELL_DATA end the geometry, so the reader stops there.

#include <cmath>

#include "engine/input_error.h"
#include "engine/io/binary_values.h"
#include "engine/io/line_reader.h"
#include "engine/io/mesh_readers.h"

namespace mtcut::engine {
namespace {

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// Cells as offsets into one list of point ids: cell c is ids[offsets[c] .. offsets[c+1]).
struct CellBlock {
  std::vector<std::int64_t> offsets{0};  // (n_cells + 1)
  std::vector<std::int64_t> ids;         // (offsets.back())
  std::size_t size() const { return offsets.size() - 1; }
  std::size_t corners(std::size_t c) const { return static_cast<std::size_t>(offsets[c + 1] - offsets[c]); }
  std::int64_t id(std::size_t c, std::size_t k) const { return ids[static_cast<std::size_t>(offsets[c]) + k]; }
};

class VtkLegacyReader {
 public:
  VtkLegacyReader(const std::string& path, std::string_view text) : reader_(path, text) {}

  RawMesh read() {
    read_header();
    std::string_view token;
    while (reader_.next_token(token)) {
      const std::string key = upper(token);
      if (key == "POINT_DATA" || key == "CELL_DATA") break;  // attributes only from here on
      if (key == "POINTS") read_points();
      else if (key == "CELLS" && unstructured_) cells_ = read_cells("CELLS");
      else if (key == "CELL_TYPES" && unstructured_) read_cell_types();
      else if (!unstructured_ && (key == "POLYGONS" || key == "TRIANGLE_STRIPS" || key == "VERTICES" || key == "LINES"))
        read_poly_cells(key);
      else if (key == "FIELD") skip_field();
      else if (key == "METADATA") skip_metadata();
      else fail_here("expected a keyword after " + last_ + ", found " + quote_token(token) +
                     (binary_ ? " (the counts disagree with the binary data)" : ""));
    }
    return finish();
  }

 private:
  void read_header() {
    std::string_view line;
    if (!reader_.next_line(line)) reader_.fail_file("the file is empty");
    const std::string head = "# VTK DATAFILE VERSION";
    if (upper(line.substr(0, head.size())) != head) reader_.fail("not a legacy VTK file (no '# vtk DataFile Version')");
    const auto words = split_tokens(line.substr(head.size()));
    if (words.empty()) reader_.fail("the file version is missing");
    double v = 0;
    if (!parse_real(words[0], v) || !(v >= 1.0 && v <= 5.1) || (v > 4.2 && v < 5.0))
      reader_.fail("unsupported VTK file version " + quote_token(words[0]) + " (supported: 1.0 to 5.1)");
    new_cells_ = v >= 5.0;
    if (!reader_.next_line(line)) reader_.fail("the file is truncated after the title line");  // the title
    const std::string format = upper(reader_.expect_token("ASCII or BINARY"));
    if (format != "ASCII" && format != "BINARY") reader_.fail("expected ASCII or BINARY, found " + quote_token(format));
    binary_ = format == "BINARY";
    if (upper(reader_.expect_token("DATASET")) != "DATASET") reader_.fail("expected DATASET");
    const std::string type = upper(reader_.expect_token("the dataset type"));
    if (type != "UNSTRUCTURED_GRID" && type != "POLYDATA")
      reader_.fail("DATASET " + type + " is not supported (only UNSTRUCTURED_GRID and POLYDATA hold a mesh)");
    unstructured_ = type == "UNSTRUCTURED_GRID";
    last_ = "DATASET " + type;
  }

  // Fails at the current line, or at the byte offset once binary data has
  // made line numbers meaningless.
  [[noreturn]] void fail_here(const std::string& what) const {
    if (after_binary_) reader_.fail_file("byte " + std::to_string(reader_.offset()) + ": " + what);
    reader_.fail(what);
  }

  std::string_view token(const std::string& what) {
    std::string_view t;
    if (!reader_.next_token(t)) fail_here("unexpected end of the file (expected " + what + ")");
    return t;
  }

  std::int64_t integer(std::string_view t, const std::string& what) const {
    std::int64_t value = 0;
    if (!parse_int(t, value)) fail_here(what + " " + quote_token(t) + " is not an integer");
    return value;
  }

  // A count no larger than the bytes left, so that no corrupt count can
  // make the reader allocate more than the file could fill.
  std::size_t read_count(const std::string& what) {
    const std::string_view t = token(what);
    const std::int64_t n = integer(t, what);
    if (n < 0) fail_here(what + " " + quote_token(t) + " is negative");
    if (static_cast<std::uint64_t>(n) > reader_.remaining())
      fail_here(what + " " + quote_token(t) + " is more than the file can hold (truncated or corrupt file)");
    return static_cast<std::size_t>(n);
  }

  ScalarType read_type(const std::string& what) {
    const std::string_view name = token("the data type of " + what);
    const auto type = legacy_vtk_type(name);
    if (!type) fail_here("unsupported data type " + quote_token(name) + " for " + what);
    return *type;
  }

  // In a binary file, the n values of a block: right after the keyword line.
  const unsigned char* binary_block(std::size_t n, ScalarType type, const std::string& what) {
    reader_.skip_rest_of_line();
    if (n * type.size > reader_.remaining())
      fail_here("the file is truncated: " + what + " needs " + std::to_string(n * type.size) + " bytes, only " +
                std::to_string(reader_.remaining()) + " are left");
    const std::string_view bytes = reader_.take_bytes(n * type.size, what);
    after_binary_ = true;
    return reinterpret_cast<const unsigned char*>(bytes.data());
  }

  // n integers of a type (binary) or n integer tokens (ascii).
  std::vector<std::int64_t> read_ints(std::size_t n, ScalarType type, const std::string& what) {
    if (type.real) reader_.fail(what + " must be integers, not reals");
    std::vector<std::int64_t> values(n);
    if (binary_) {
      const unsigned char* p = binary_block(n, type, what);
      for (std::size_t i = 0; i < n; ++i)
        if (!decode_int(p + i * type.size, type, true, values[i]))
          fail_here(what + ": value " + std::to_string(i) + " is out of range");
      return values;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const std::string where = what + " (value " + std::to_string(i) + " of " + std::to_string(n) + ")";
      values[i] = integer(token(where), where);
    }
    return values;
  }

  void read_points() {
    if (!positions_.empty()) fail_here("a second POINTS section");
    const std::size_t n = read_count("the number of points");
    const ScalarType type = read_type("POINTS");
    positions_.resize(n);
    if (binary_) {
      const unsigned char* p = binary_block(3 * n, type, "POINTS " + std::to_string(n));
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < 3; ++k) {
          positions_[i][static_cast<Eigen::Index>(k)] = decode_real(p + (3 * i + k) * type.size, type, true);
          if (!std::isfinite(positions_[i][static_cast<Eigen::Index>(k)]))
            fail_here("point " + std::to_string(i) + " has a non-finite coordinate");
        }
    } else {
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < 3; ++k) {
          std::string_view token;
          if (!reader_.next_token(token))
            reader_.fail("the file is truncated: POINTS declares " + std::to_string(n) + " points, only " +
                         std::to_string(i) + " found");
          double v = 0;
          if (!parse_real(token, v))
            reader_.fail("point " + std::to_string(i) + ": coordinate " + quote_token(token) + " is not a number");
          if (!std::isfinite(v))
            reader_.fail("point " + std::to_string(i) + " has a non-finite coordinate " + quote_token(token));
          positions_[i][static_cast<Eigen::Index>(k)] = v;
        }
    }
    has_points_ = true;
    last_ = "the " + std::to_string(n) + " points that POINTS declares";
  }

  // A cell block after its keyword: classic "n size" then size ints
  // (each cell: its corner count, then its point ids), or, in version 5.x,
  // "n_offsets n_ids" then OFFSETS and CONNECTIVITY arrays.
  CellBlock read_cells(const std::string& key) {
    const std::size_t n = read_count("the number of " + key);
    const std::size_t size = read_count("the size of " + key);
    CellBlock block;
    if (new_cells_) {
      if (n == 0) reader_.fail(key + " declares 0 offsets (at least 1 is needed)");
      expect_keyword("OFFSETS");
      block.offsets = read_ints(n, read_type("OFFSETS"), key + " OFFSETS");
      expect_keyword("CONNECTIVITY");
      block.ids = read_ints(size, read_type("CONNECTIVITY"), key + " CONNECTIVITY");
      if (block.offsets.front() != 0) fail_here(key + ": the first offset is not 0");
      for (std::size_t c = 0; c + 1 < n; ++c)
        if (block.offsets[c + 1] < block.offsets[c])
          fail_here(key + ": the offsets decrease at cell " + std::to_string(c));
      if (block.offsets.back() != static_cast<std::int64_t>(size))
        fail_here(key + ": the last offset is " + std::to_string(block.offsets.back()) + " but CONNECTIVITY has " +
                  std::to_string(size) + " ids");
    } else {
      const std::vector<std::int64_t> flat = read_ints(size, ScalarType{4, false, true}, key);
      block.offsets.reserve(n + 1);
      std::size_t at = 0;
      for (std::size_t c = 0; c < n; ++c) {
        if (at >= size)
          fail_here(key + " declares " + std::to_string(n) + " cells in " + std::to_string(size) +
                    " values, but they run out at cell " + std::to_string(c));
        const std::int64_t count = flat[at];
        if (count < 0 || static_cast<std::uint64_t>(count) > size - at - 1)
          fail_here(key + ": cell " + std::to_string(c) + " has a bad corner count " + std::to_string(count) +
                    " (the counts disagree with the size " + std::to_string(size) + ")");
        block.ids.insert(block.ids.end(), flat.begin() + static_cast<std::ptrdiff_t>(at + 1),
                         flat.begin() + static_cast<std::ptrdiff_t>(at + 1 + static_cast<std::size_t>(count)));
        block.offsets.push_back(static_cast<std::int64_t>(block.ids.size()));
        at += 1 + static_cast<std::size_t>(count);
      }
      if (at != size)
        fail_here(key + " declares size " + std::to_string(size) + " but its " + std::to_string(n) + " cells use " +
                  std::to_string(at) + " values");
    }
    check_ids(block, key);
    last_ = "the " + std::to_string(block.size()) + " cells of " + key;
    return block;
  }

  void expect_keyword(const std::string& key) {
    const std::string_view t = token(key);
    if (upper(t) != key) fail_here("expected " + key + ", found " + quote_token(t));
  }

  void check_ids(const CellBlock& block, const std::string& key) {
    if (!has_points_) fail_here(key + " comes before POINTS");
    const auto n = static_cast<std::int64_t>(positions_.size());
    for (std::size_t c = 0; c < block.size(); ++c)
      for (std::size_t k = 0; k < block.corners(c); ++k)
        if (block.id(c, k) < 0 || block.id(c, k) >= n)
          fail_here(key + ": cell " + std::to_string(c) + " refers to point " + std::to_string(block.id(c, k)) +
                    ", but there are " + std::to_string(n) + " points");
  }

  void read_cell_types() {
    const std::size_t n = read_count("the number of CELL_TYPES");
    types_ = read_ints(n, ScalarType{4, false, true}, "CELL_TYPES");
    has_types_ = true;
    last_ = "the " + std::to_string(n) + " values of CELL_TYPES";
  }

  void read_poly_cells(const std::string& key) {
    const CellBlock block = read_cells(key);
    if (key == "POLYGONS") {
      for (std::size_t c = 0; c < block.size(); ++c) {
        if (block.corners(c) < 3)
          fail_here("POLYGONS: polygon " + std::to_string(c) + " has " + std::to_string(block.corners(c)) + " corners");
        for (std::size_t k = 1; k + 1 < block.corners(c); ++k)
          triangles_.push_back({block.id(c, 0), block.id(c, k), block.id(c, k + 1)});
      }
    } else if (key == "TRIANGLE_STRIPS") {
      for (std::size_t c = 0; c < block.size(); ++c)
        for (std::size_t k = 0; k + 2 < block.corners(c); ++k) {
          // Every other triangle of a strip is flipped to keep one orientation.
          if (k % 2 == 0) triangles_.push_back({block.id(c, k), block.id(c, k + 1), block.id(c, k + 2)});
          else triangles_.push_back({block.id(c, k + 1), block.id(c, k), block.id(c, k + 2)});
        }
    }
  }

  // FIELD name n, then n arrays "name components tuples type" and their values.
  void skip_field() {
    token("the FIELD name");
    const std::size_t arrays = read_count("the number of FIELD arrays");
    for (std::size_t a = 0; a < arrays; ++a) {
      std::string_view next;
      while (reader_.peek_token(next) && upper(next) == "METADATA") {
        reader_.next_token(next);
        skip_metadata();
      }
      const std::string name(token("a FIELD array name"));
      if (name == "NULL_ARRAY") continue;
      const std::size_t components = read_count("the number of components of " + name);
      const std::size_t tuples = read_count("the number of tuples of " + name);
      const ScalarType type = read_type("FIELD array " + name);
      if (components != 0 && tuples > reader_.remaining() / components)
        fail_here("FIELD array " + name + " is larger than the file");
      const std::size_t n = components * tuples;
      if (binary_) {
        binary_block(n, type, "FIELD array " + name);
      } else {
        for (std::size_t i = 0; i < n; ++i) {
          const std::string_view value = token("a value of FIELD array " + name);
          double v = 0;
          if (!parse_real(value, v))
            reader_.fail("FIELD array " + name + ": " + quote_token(value) + " is not a number");
        }
      }
      last_ = "FIELD array " + name;
    }
  }

  // METADATA: text lines up to a blank line.
  void skip_metadata() {
    reader_.skip_rest_of_line();
    std::string_view line;
    while (reader_.next_line(line))
      if (split_tokens(line).empty()) break;
  }

  RawMesh finish() {
    if (!has_points_) reader_.fail_file("no POINTS section");
    RawMesh raw;
    if (unstructured_) {
      if (cells_.size() > 0 && !has_types_) reader_.fail_file("CELLS without CELL_TYPES");
      if (has_types_ && types_.size() != cells_.size())
        reader_.fail_file("CELL_TYPES has " + std::to_string(types_.size()) + " values but CELLS has " +
                          std::to_string(cells_.size()) + " cells");
      for (std::size_t c = 0; c < cells_.size(); ++c) {
        const CellShape shape = vtk_cell_shape(types_[c]);
        if (shape.points == 0) continue;
        if (cells_.corners(c) != shape.points)
          reader_.fail_file("cell " + std::to_string(c) + " has type " + std::to_string(types_[c]) + " but " +
                            std::to_string(cells_.corners(c)) + " points (expected " +
                            std::to_string(shape.points) + ")");
        if (shape.corners == 4)
          raw.tets.push_back({cells_.id(c, 0), cells_.id(c, 1), cells_.id(c, 2), cells_.id(c, 3)});
        else raw.triangles.push_back({cells_.id(c, 0), cells_.id(c, 1), cells_.id(c, 2)});
      }
    } else {
      raw.triangles = std::move(triangles_);
    }
    raw.positions = std::move(positions_);
    return raw;
  }

  LineReader reader_;
  bool binary_ = false;
  bool new_cells_ = false;     // version 5.x: OFFSETS + CONNECTIVITY
  bool unstructured_ = false;  // else POLYDATA
  bool after_binary_ = false;  // line numbers no longer mean anything
  bool has_points_ = false;
  bool has_types_ = false;
  std::string last_;           // what was read last, for messages
  std::vector<Vec3> positions_;                              // (n_points)
  CellBlock cells_;                                          // UNSTRUCTURED_GRID
  std::vector<std::int64_t> types_;                          // (n_cells)
  std::vector<std::array<std::int64_t, 3>> triangles_;      // POLYDATA
};

}  // namespace

RawMesh read_vtk_legacy(const std::string& path) {
  const std::string text = read_file_bytes(path);
  return VtkLegacyReader(path, text).read();
}

}  // namespace mtcut::engine
