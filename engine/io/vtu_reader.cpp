// VTK XML unstructured grid (.vtu) reader. DataArrays may be ascii, inline
// binary (base64 of a UInt32/UInt64 byte count then the values) or appended
// (raw or base64, at an offset past the '_' of <AppendedData>), in either
// byte order, of any VTK scalar type. Compressed files are rejected. Points
// must have 3 components; cells come from connectivity/offsets/types (type
// 10 = tet, 5 = triangle, their quadratic 24 and 22 by their corners, others
// skipped). Several pieces are concatenated.
// Every declared count (NumberOfPoints, NumberOfCells, binary headers) is
// checked against the data before anything is allocated from it.

#include <cmath>

#include "engine/input_error.h"
#include "engine/io/binary_values.h"
#include "engine/io/line_reader.h"
#include "engine/io/mesh_readers.h"
#include "engine/io/xml_scanner.h"

namespace mtcut::engine {
namespace {

enum class Format { kAscii, kBinary, kAppended };

// Where a DataArray's values are, and how they are stored.
struct ArrayRef {
  bool present = false;
  std::string label;  // "Points", "connectivity", "offsets", "types"
  ScalarType type;
  std::string type_name;
  std::size_t components = 1;
  Format format = Format::kAscii;
  std::size_t offset = 0;         // appended: past the '_'
  std::size_t content_begin = 0;  // inline: the text between the tags
  std::size_t content_end = 0;
  std::size_t line = 0;
};

struct PieceRef {
  std::size_t n_points = 0;
  std::size_t n_cells = 0;
  std::size_t line = 0;
  ArrayRef points, connectivity, offsets, types;
};

// A DataArray's values before conversion: tokens (ascii) or bytes.
struct ArrayData {
  std::vector<std::string_view> tokens;
  std::string bytes;
  std::size_t count = 0;
};

class VtuReader {
 public:
  VtuReader(const std::string& path, std::string_view text) : path_(path), text_(text), xml_(path, text) {}

  RawMesh read() {
    scan();
    RawMesh raw;
    for (const PieceRef& piece : pieces_) read_piece(piece, raw);
    return raw;
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& what) const { xml_.fail(line, what); }

  std::size_t to_count(const XmlTag& tag, const char* key, bool required) const {
    const auto value = tag.attribute(key);
    if (!value) {
      if (required) fail(tag.line, "<" + tag.name + "> has no " + key);
      return 0;
    }
    std::int64_t n = 0;
    if (!parse_int(*value, n) || n < 0)
      fail(tag.line, std::string(key) + "=" + quote_token(*value) + " is not a count");
    // Every point, cell, component or offset takes at least one byte of the file.
    if (static_cast<std::uint64_t>(n) > text_.size())
      fail(tag.line,
           std::string(key) + "=" + quote_token(*value) + " is more than the file can hold (truncated or corrupt)");
    return static_cast<std::size_t>(n);
  }

  void read_header(const XmlTag& tag) {
    if (tag.name != "VTKFile")
      fail(tag.line, "not a VTK XML file (the first tag is <" + tag.name + ">, not <VTKFile>)");
    const std::string type = tag.attribute("type").value_or("");
    if (type != "UnstructuredGrid")
      fail(tag.line, "VTKFile type " + quote_token(type) + " is not supported (only UnstructuredGrid, a .vtu file)");
    const std::string version = tag.attribute("version").value_or("0.1");
    if (version != "0.1" && version != "1.0" && version != "2.0" && version != "2.1" && version != "2.2")
      fail(tag.line, "unsupported VTK XML version " + quote_token(version) + " (supported: 0.1 to 2.2)");
    const std::string order = tag.attribute("byte_order").value_or("LittleEndian");
    if (order != "LittleEndian" && order != "BigEndian") fail(tag.line, "unknown byte_order " + quote_token(order));
    big_endian_ = order == "BigEndian";
    const std::string header = tag.attribute("header_type").value_or("UInt32");
    if (header != "UInt32" && header != "UInt64") fail(tag.line, "unsupported header_type " + quote_token(header));
    header_type_ = header == "UInt64" ? ScalarType{8, false, false} : ScalarType{4, false, false};
    if (const auto compressor = tag.attribute("compressor"); compressor && !compressor->empty())
      fail(tag.line, "compressed data (" + *compressor +
                         ") is not supported; write the file uncompressed (ascii, binary or appended raw)");
  }

  ArrayRef describe_array(const XmlTag& tag, const std::string& label) {
    ArrayRef a;
    a.present = true;
    a.label = label;
    a.line = tag.line;
    a.type_name = tag.attribute("type").value_or("");
    const auto type = xml_vtk_type(a.type_name);
    if (!type) fail(tag.line, label + ": unsupported DataArray type " + quote_token(a.type_name));
    a.type = *type;
    if (tag.attribute("NumberOfComponents")) a.components = to_count(tag, "NumberOfComponents", true);
    const std::string format = tag.attribute("format").value_or("ascii");
    if (format == "ascii") a.format = Format::kAscii;
    else if (format == "binary") a.format = Format::kBinary;
    else if (format == "appended") a.format = Format::kAppended;
    else fail(tag.line, label + ": unknown DataArray format " + quote_token(format));
    if (a.format == Format::kAppended) a.offset = to_count(tag, "offset", true);
    return a;
  }

  // Reads the tags up to <AppendedData> (or the end), noting every piece's arrays.
  void scan() {
    XmlTag tag;
    if (!xml_.next_tag(tag)) fail(0, "not a VTK XML file (no tags)");
    read_header(tag);
    std::string section;  // Points, Cells, PointData, ...
    while (xml_.next_tag(tag)) {
      const std::string& name = tag.name;
      if (name == "Piece" && !tag.closing) {
        PieceRef piece;
        piece.line = tag.line;
        piece.n_points = to_count(tag, "NumberOfPoints", true);
        piece.n_cells = to_count(tag, "NumberOfCells", true);
        pieces_.push_back(piece);
      } else if (name == "Points" || name == "Cells" || name == "PointData" || name == "CellData" ||
                 name == "FieldData") {
        section = tag.closing || tag.self_closing ? "" : name;
      } else if (name == "DataArray" && !tag.closing) {
        scan_array(tag, section);
      } else if (name == "AppendedData" && !tag.closing) {
        start_appended(tag);
        return;
      }
    }
    if (pieces_.empty()) fail(0, "no <Piece> in the file");
  }

  void scan_array(const XmlTag& tag, const std::string& section) {
    ArrayRef* slot = nullptr;
    std::string label;
    if (!pieces_.empty()) {
      PieceRef& piece = pieces_.back();
      const std::string name = tag.attribute("Name").value_or("");
      if (section == "Points" && !piece.points.present) slot = &piece.points;
      else if (section == "Cells" && name == "connectivity") slot = &piece.connectivity;
      else if (section == "Cells" && name == "offsets") slot = &piece.offsets;
      else if (section == "Cells" && name == "types") slot = &piece.types;
      label = section == "Points" ? std::string("Points") : name;
    }
    if (slot != nullptr) *slot = describe_array(tag, label);
    if (tag.self_closing) return;
    // The values follow any child elements (VTK writes <InformationKey> first).
    std::size_t begin = tag.end;
    XmlTag child;
    while (true) {
      if (!xml_.next_tag(child)) fail(tag.line, "<DataArray> is never closed");
      if (child.name == "DataArray") {
        if (!child.closing) fail(child.line, "a <DataArray> inside a <DataArray>");
        break;
      }
      begin = child.end;
    }
    if (slot != nullptr) {
      slot->content_begin = begin;
      slot->content_end = child.begin;
    }
  }

  void start_appended(const XmlTag& tag) {
    const std::string encoding = tag.attribute("encoding").value_or("");
    if (encoding != "raw" && encoding != "base64")
      fail(tag.line, "unknown AppendedData encoding " + quote_token(encoding) + " (expected raw or base64)");
    appended_base64_ = encoding == "base64";
    std::size_t p = tag.end;
    while (p < text_.size() && (text_[p] == ' ' || text_[p] == '\t' || text_[p] == '\n' || text_[p] == '\r')) ++p;
    if (p >= text_.size() || text_[p] != '_') fail(tag.line, "the AppendedData does not start with '_'");
    appended_start_ = p + 1;
    has_appended_ = true;
    if (pieces_.empty()) fail(0, "no <Piece> in the file");
  }

  std::uint64_t header_value(const std::string& bytes) const {
    std::int64_t n = 0;
    if (!decode_int(reinterpret_cast<const unsigned char*>(bytes.data()), header_type_, big_endian_, n))
      return UINT64_MAX;
    return static_cast<std::uint64_t>(n);
  }

  // Base64 text holding a byte-count header then that many bytes.
  std::string decode_counted_base64(const ArrayRef& a, std::string_view encoded) const {
    const std::size_t h = header_type_.size;
    const auto head = decode_base64(encoded, h);
    if (!head) fail(a.line, a.label + ": the base64 data holds a character outside the base64 alphabet");
    if (head->size() < h) fail(a.line, a.label + ": the binary data is truncated (no complete header)");
    const std::uint64_t n = header_value(*head);
    if (n > encoded.size())
      fail(a.line, a.label + ": the header claims " + std::to_string(n) +
                       " bytes, more than the data holds (truncated)");
    const auto all = decode_base64(encoded, h + n);
    if (!all) fail(a.line, a.label + ": the base64 data holds a character outside the base64 alphabet");
    if (all->size() < h + n)
      fail(a.line, a.label + ": the binary data is truncated: the header says " + std::to_string(n) + " bytes, only " +
                       std::to_string(all->size() - h) + " follow");
    return all->substr(h);
  }

  ArrayData load(const ArrayRef& a) const {
    ArrayData data;
    if (a.format == Format::kAscii) {
      data.tokens = split_tokens(text_.substr(a.content_begin, a.content_end - a.content_begin));
      data.count = data.tokens.size();
      return data;
    }
    if (a.format == Format::kBinary) {
      data.bytes = decode_counted_base64(a, text_.substr(a.content_begin, a.content_end - a.content_begin));
    } else {
      if (!has_appended_) fail(a.line, a.label + ": format=\"appended\" but the file has no <AppendedData>");
      if (a.offset > text_.size() - appended_start_)
        fail(a.line, a.label + ": offset " + std::to_string(a.offset) + " is past the end of the file (truncated)");
      const std::string_view rest = text_.substr(appended_start_ + a.offset);
      if (appended_base64_) {
        data.bytes = decode_counted_base64(a, rest);
      } else {
        const std::size_t h = header_type_.size;
        if (rest.size() < h) fail(a.line, a.label + ": the appended data is truncated (no complete header)");
        const std::uint64_t n = header_value(std::string(rest.substr(0, h)));
        if (n > rest.size() - h)
          fail(a.line, a.label + ": the appended data is truncated: the header says " + std::to_string(n) +
                           " bytes, only " + std::to_string(rest.size() - h) + " follow");
        data.bytes = std::string(rest.substr(h, n));
      }
    }
    if (data.bytes.size() % a.type.size != 0)
      fail(a.line, a.label + ": " + std::to_string(data.bytes.size()) + " bytes is not a whole number of " +
                       a.type_name + " values");
    data.count = data.bytes.size() / a.type.size;
    return data;
  }

  void expect_count(const ArrayRef& a, const ArrayData& data, std::size_t expected, const std::string& why) const {
    if (data.count != expected)
      fail(a.line, a.label + ": the DataArray holds " + std::to_string(data.count) + " values, but " + why + " needs " +
                       std::to_string(expected) + " (counts disagree with the data)");
  }

  std::size_t line_of(const ArrayRef& a, const ArrayData& data, std::size_t i) {
    if (a.format != Format::kAscii) return a.line;
    return xml_.line_at(static_cast<std::size_t>(data.tokens[i].data() - text_.data()));
  }

  std::vector<Vec3> read_points(const PieceRef& piece) {
    const ArrayRef& a = piece.points;
    if (!a.present) fail(piece.line, "the <Piece> has no Points DataArray");
    if (a.components != 3)
      fail(a.line, "Points: NumberOfComponents is " + std::to_string(a.components) + ", expected 3");
    const ArrayData data = load(a);
    expect_count(a, data, 3 * piece.n_points, "NumberOfPoints=\"" + std::to_string(piece.n_points) + "\" x 3");
    const auto* bytes = reinterpret_cast<const unsigned char*>(data.bytes.data());
    std::vector<Vec3> points(piece.n_points);
    for (std::size_t i = 0; i < data.count; ++i) {
      double v = 0;
      if (a.format != Format::kAscii) {
        v = decode_real(bytes + i * a.type.size, a.type, big_endian_);
      } else if (!parse_real(data.tokens[i], v)) {
        fail(line_of(a, data, i),
             "point " + std::to_string(i / 3) + ": coordinate " + quote_token(data.tokens[i]) + " is not a number");
      }
      if (!std::isfinite(v))
        fail(line_of(a, data, i), "point " + std::to_string(i / 3) + " has a non-finite coordinate");
      points[i / 3][static_cast<Eigen::Index>(i % 3)] = v;
    }
    return points;
  }

  // Integers; expected == SIZE_MAX takes any count.
  std::vector<std::int64_t> read_ints(const ArrayRef& a, std::size_t expected, const std::string& why) {
    if (a.type.real) fail(a.line, a.label + ": the DataArray type is " + a.type_name + ", expected an integer type");
    if (a.components != 1)
      fail(a.line, a.label + ": NumberOfComponents is " + std::to_string(a.components) + ", expected 1");
    const ArrayData data = load(a);
    if (expected != SIZE_MAX) expect_count(a, data, expected, why);
    const bool binary = a.format != Format::kAscii;
    const auto* bytes = reinterpret_cast<const unsigned char*>(data.bytes.data());
    std::vector<std::int64_t> values(data.count);
    for (std::size_t i = 0; i < data.count; ++i) {
      if (binary && !decode_int(bytes + i * a.type.size, a.type, big_endian_, values[i]))
        fail(a.line, a.label + ": value " + std::to_string(i) + " is out of range");
      if (!binary && !parse_int(data.tokens[i], values[i]))
        fail(line_of(a, data, i),
             a.label + ": value " + std::to_string(i) + " " + quote_token(data.tokens[i]) + " is not an integer");
    }
    return values;
  }

  void read_piece(const PieceRef& piece, RawMesh& raw) {
    const auto base = static_cast<std::int64_t>(raw.positions.size());
    std::vector<Vec3> points = read_points(piece);
    raw.positions.insert(raw.positions.end(), points.begin(), points.end());
    if (piece.n_cells == 0 && !piece.connectivity.present) return;
    for (const ArrayRef* a : {&piece.connectivity, &piece.offsets, &piece.types})
      if (!a->present) fail(piece.line, "the <Piece> has no connectivity, offsets and types DataArrays in <Cells>");
    const std::string cells = "NumberOfCells=\"" + std::to_string(piece.n_cells) + "\"";
    const auto offsets = read_ints(piece.offsets, piece.n_cells, cells);
    const auto types = read_ints(piece.types, piece.n_cells, cells);
    const auto connectivity = read_ints(piece.connectivity, SIZE_MAX, "");
    const auto n_ids = static_cast<std::int64_t>(connectivity.size());
    const auto n_points = static_cast<std::int64_t>(piece.n_points);
    std::int64_t start = 0;
    for (std::size_t c = 0; c < piece.n_cells; ++c) {
      const std::int64_t end = offsets[c];
      if (end < start || end > n_ids)
        fail(piece.offsets.line, "offsets: cell " + std::to_string(c) + " ends at " + std::to_string(end) +
                                     ", outside " + std::to_string(start) + ".." + std::to_string(n_ids) +
                                     " (connectivity holds " + std::to_string(n_ids) + " ids)");
      for (std::int64_t k = start; k < end; ++k) {
        const std::int64_t id = connectivity[static_cast<std::size_t>(k)];
        if (id < 0 || id >= n_points)
          fail(piece.connectivity.line, "cell " + std::to_string(c) + " refers to point " + std::to_string(id) +
                                            ", but the piece has " + std::to_string(n_points) + " points");
      }
      const std::int64_t corners = end - start;
      const CellShape shape = vtk_cell_shape(types[c]);
      const auto need = static_cast<std::int64_t>(shape.points);
      if (need != 0 && corners != need)
        fail(piece.types.line, "cell " + std::to_string(c) + " has type " + std::to_string(types[c]) + " but " +
                                   std::to_string(corners) + " points (expected " + std::to_string(need) + ")");
      const auto id = [&](std::int64_t k) { return base + connectivity[static_cast<std::size_t>(start + k)]; };
      if (shape.corners == 4) raw.tets.push_back({id(0), id(1), id(2), id(3)});
      else if (shape.corners == 3) raw.triangles.push_back({id(0), id(1), id(2)});
      start = end;
    }
    if (start != n_ids)
      fail(piece.connectivity.line, "connectivity holds " + std::to_string(n_ids) + " ids, but the " +
                                        std::to_string(piece.n_cells) + " cells use " + std::to_string(start) +
                                        " (counts disagree with the data)");
  }

  std::string path_;
  std::string_view text_;
  XmlScanner xml_;
  bool big_endian_ = false;
  ScalarType header_type_{4, false, false};
  bool has_appended_ = false;
  bool appended_base64_ = false;
  std::size_t appended_start_ = 0;  // offset of the byte after '_'
  std::vector<PieceRef> pieces_;
};

}  // namespace

RawMesh read_vtu(const std::string& path) {
  const std::string text = read_file_bytes(path);
  return VtuReader(path, text).read();
}

}  // namespace mtcut::engine
