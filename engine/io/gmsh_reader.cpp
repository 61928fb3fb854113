// Gmsh .msh reader, ascii only: format 1 ($NOD/$ELM), 2.x and 4.0/4.1
// ($MeshFormat, $Nodes, $Elements; every other section is skipped). Tets are
// element type 4 (or 11, 10 nodes), triangles type 2 (or 9, 6 nodes); other
// element types are skipped. Node
// tags (any positive numbers, in any order) become 0-based ids in the order
// the nodes appear. Every section is read line by line and its declared
// counts are checked against the lines it holds.

#include <unordered_map>

#include "engine/input_error.h"
#include "engine/io/line_reader.h"
#include "engine/io/mesh_readers.h"

namespace mtcut::engine {
namespace {

enum class Version { kNone, k1, k2, k40, k41 };

// An element kept until all nodes are known: its node tags and its line.
struct PendingElement {
  std::array<std::int64_t, 10> tags{};  // corners first
  CellShape shape;
  std::size_t line = 0;
};

class GmshReader {
 public:
  GmshReader(const std::string& path, std::string_view text) : reader_(path, text), text_size_(text.size()) {}

  RawMesh read() {
    std::vector<std::string_view> tokens;
    while (next_nonblank(tokens)) {
      const std::string_view name = tokens[0];
      if (name.empty() || name[0] != '$')
        reader_.fail("expected a section such as $Nodes, found " + quote_token(name));
      if (name == "$MeshFormat") {
        read_format();
      } else if (name == "$NOD") {
        start_data(Version::k1, "$NOD");
        read_nodes_v1v2("$ENDNOD");
      } else if (name == "$ELM") {
        start_data(Version::k1, "$ELM");
        read_elements_v1v2("$ENDELM");
      } else if (name == "$Nodes") {
        start_data(version_, "$Nodes");
        if (version_ == Version::k2) read_nodes_v1v2("$EndNodes");
        else read_nodes_v4();
      } else if (name == "$Elements") {
        start_data(version_, "$Elements");
        if (version_ == Version::k2) read_elements_v1v2("$EndElements");
        else read_elements_v4();
      } else {
        skip_section(std::string(name));
      }
    }
    if (!seen_nodes_) reader_.fail_file("no $Nodes section (is it a Gmsh mesh file?)");
    return finish();
  }

 private:
  // The tokens of the next line that is not blank; false at the end.
  bool next_nonblank(std::vector<std::string_view>& tokens) {
    std::string_view line;
    while (reader_.next_line(line)) {
      tokens = split_tokens(line);
      if (!tokens.empty()) return true;
    }
    return false;
  }

  // The next data line of a section; the end of the file or of the section
  // before the declared count is reached is a fault.
  std::vector<std::string_view> data_line(const std::string& section, const std::string& progress) {
    std::vector<std::string_view> tokens;
    if (!next_nonblank(tokens)) reader_.fail("the file is truncated in " + section + " (" + progress + ")");
    if (tokens[0][0] == '$') reader_.fail(section + " ends early (" + progress + ")");
    return tokens;
  }

  void expect_end(const std::string& end, const std::string& section, std::size_t declared, const char* items) {
    std::vector<std::string_view> tokens;
    if (!next_nonblank(tokens)) reader_.fail("the file is truncated: no " + end);
    if (tokens[0] != end)
      reader_.fail("expected " + end + " after the " + std::to_string(declared) + " " + items + " that " + section +
                   " declares, found " + quote_token(tokens[0]) + " (counts disagree with the data)");
  }

  void read_format() {
    std::vector<std::string_view> tokens;
    if (!next_nonblank(tokens)) reader_.fail("the file is truncated in $MeshFormat");
    if (tokens.size() < 3) reader_.fail("$MeshFormat needs 'version file-type data-size'");
    const double v = reader_.to_real(tokens[0], "the format version");
    if (v >= 2.0 && v < 3.0) version_ = Version::k2;
    else if (v == 4.0) version_ = Version::k40;
    else if (v == 4.1) version_ = Version::k41;
    else reader_.fail("unsupported Gmsh format version " + std::string(tokens[0]) + " (supported: 1, 2.x, 4.0, 4.1)");
    if (reader_.to_int(tokens[1], "the file type") != 0)
      reader_.fail("binary .msh files are not supported; save the mesh as ascii");
    if (!next_nonblank(tokens) || tokens[0] != "$EndMeshFormat") reader_.fail("expected $EndMeshFormat");
  }

  void start_data(Version version, const char* section) {
    if (version == Version::kNone) reader_.fail(std::string(section) + " comes before $MeshFormat");
    version_ = version;
    const bool nodes = section == std::string("$NOD") || section == std::string("$Nodes");
    if (nodes && seen_nodes_) reader_.fail("a second node section " + std::string(section));
    if (nodes) seen_nodes_ = true;
  }

  void add_node(std::string_view tag_token, std::string_view x, std::string_view y, std::string_view z) {
    const std::int64_t tag = reader_.to_int(tag_token, "the node tag");
    const auto [it, fresh] = index_of_tag_.emplace(tag, static_cast<std::int64_t>(positions_.size()));
    if (!fresh) reader_.fail("node " + std::to_string(tag) + " is defined twice");
    const std::string what = "node " + std::to_string(tag) + " coordinate";
    positions_.emplace_back(reader_.to_real(x, what), reader_.to_real(y, what), reader_.to_real(z, what));
  }

  // An element of a kept type whose node tags are tokens[first..].
  void add_element(CellShape shape, const std::vector<std::string_view>& tokens, std::size_t first,
                   std::string_view id) {
    if (tokens.size() - first != shape.points)
      reader_.fail("element " + std::string(id) + " (" + (shape.corners == 4 ? "a tet" : "a triangle") + ") has " +
                   std::to_string(tokens.size() - first) + " nodes, expected " + std::to_string(shape.points));
    PendingElement e;
    e.shape = shape;
    e.line = reader_.line();
    for (std::size_t k = 0; k < shape.points; ++k) e.tags[k] = reader_.to_int(tokens[first + k], "the node tag");
    elements_.push_back(e);
  }

  void read_nodes_v1v2(const std::string& end) {
    const std::string section = end == "$ENDNOD" ? "$NOD" : "$Nodes";
    const std::size_t n = count_line(section, "the number of nodes");
    for (std::size_t i = 0; i < n; ++i) {
      const auto tokens = data_line(section, node_progress(n, i));
      if (tokens.size() != 4)
        reader_.fail("a node line needs 'tag x y z', found " + std::to_string(tokens.size()) + " values");
      add_node(tokens[0], tokens[1], tokens[2], tokens[3]);
    }
    expect_end(end, section, n, "nodes");
  }

  void read_elements_v1v2(const std::string& end) {
    const std::string section = end == "$ENDELM" ? "$ELM" : "$Elements";
    const std::size_t n = count_line(section, "the number of elements");
    for (std::size_t i = 0; i < n; ++i) {
      const auto tokens = data_line(section, element_progress(n, i));
      if (tokens.size() < 3) reader_.fail("an element line is too short");
      const std::int64_t type = reader_.to_int(tokens[1], "the element type");
      std::size_t first = 0;
      if (version_ == Version::k1) {
        // number type physical elementary node-count nodes...
        if (tokens.size() < 5) reader_.fail("an element line is too short");
        const std::size_t count = reader_.to_count(tokens[4], "the node count", tokens.size());
        if (tokens.size() != 5 + count)
          reader_.fail("element " + std::string(tokens[0]) + " declares " + std::to_string(count) +
                       " nodes but lists " + std::to_string(tokens.size() - 5));
        first = 5;
      } else {
        // number type tag-count tags... nodes...
        const std::size_t tags = reader_.to_count(tokens[2], "the tag count", tokens.size());
        if (tokens.size() < 3 + tags)
          reader_.fail("element " + std::string(tokens[0]) + " has fewer tags than it declares");
        first = 3 + tags;
      }
      if (const CellShape shape = gmsh_cell_shape(type); shape.points != 0)
        add_element(shape, tokens, first, tokens[0]);
    }
    expect_end(end, section, n, "elements");
  }

  void read_nodes_v4() {
    const auto header = data_line("$Nodes", "header");
    const std::size_t need = version_ == Version::k41 ? 4 : 2;
    if (header.size() != need) reader_.fail("the $Nodes header needs " + std::to_string(need) + " values");
    const std::size_t blocks = reader_.to_count(header[0], "the number of node blocks", text_size_);
    const std::size_t n = reader_.to_count(header[1], "the number of nodes", text_size_);
    std::size_t read = 0;
    for (std::size_t b = 0; b < blocks; ++b) {
      const auto block = data_line("$Nodes", "block " + std::to_string(b) + " of " + std::to_string(blocks));
      if (block.size() != 4) reader_.fail("a node block header needs 4 values");
      const std::size_t count = reader_.to_count(block[3], "the number of nodes in the block", text_size_);
      if (count > n - read) reader_.fail("the node blocks hold more nodes than the " + std::to_string(n) + " declared");
      if (version_ == Version::k40) {
        for (std::size_t i = 0; i < count; ++i) {
          const auto tokens = data_line("$Nodes", node_progress(n, read + i));
          if (tokens.size() < 4) reader_.fail("a node line needs 'tag x y z'");
          add_node(tokens[0], tokens[1], tokens[2], tokens[3]);
        }
      } else {
        std::vector<std::vector<std::string_view>> tags(count);
        for (std::size_t i = 0; i < count; ++i) {
          tags[i] = data_line("$Nodes", node_progress(n, read + i));
          if (tags[i].size() != 1)
            reader_.fail("expected one node tag, found " + std::to_string(tags[i].size()) + " values");
        }
        for (std::size_t i = 0; i < count; ++i) {
          const auto tokens = data_line("$Nodes", "coordinates of " + node_progress(n, read + i));
          if (tokens.size() < 3) reader_.fail("a coordinate line needs 'x y z'");
          add_node(tags[i][0], tokens[0], tokens[1], tokens[2]);
        }
      }
      read += count;
    }
    if (read != n)
      reader_.fail("$Nodes declares " + std::to_string(n) + " nodes, its blocks hold " + std::to_string(read));
    expect_end("$EndNodes", "$Nodes", n, "nodes");
  }

  void read_elements_v4() {
    const auto header = data_line("$Elements", "header");
    const std::size_t need = version_ == Version::k41 ? 4 : 2;
    if (header.size() != need) reader_.fail("the $Elements header needs " + std::to_string(need) + " values");
    const std::size_t blocks = reader_.to_count(header[0], "the number of element blocks", text_size_);
    const std::size_t n = reader_.to_count(header[1], "the number of elements", text_size_);
    std::size_t read = 0;
    for (std::size_t b = 0; b < blocks; ++b) {
      const auto block = data_line("$Elements", "block " + std::to_string(b) + " of " + std::to_string(blocks));
      if (block.size() != 4) reader_.fail("an element block header needs 4 values");
      const CellShape shape = gmsh_cell_shape(reader_.to_int(block[2], "the element type"));
      const std::size_t count = reader_.to_count(block[3], "the number of elements in the block", text_size_);
      if (count > n - read)
        reader_.fail("the element blocks hold more elements than the " + std::to_string(n) + " declared");
      for (std::size_t i = 0; i < count; ++i) {
        const auto tokens = data_line("$Elements", element_progress(n, read + i));
        if (shape.points != 0) add_element(shape, tokens, 1, tokens[0]);
      }
      read += count;
    }
    if (read != n)
      reader_.fail("$Elements declares " + std::to_string(n) + " elements, its blocks hold " + std::to_string(read));
    expect_end("$EndElements", "$Elements", n, "elements");
  }

  std::size_t count_line(const std::string& section, const std::string& what) {
    const auto tokens = data_line(section, what);
    if (tokens.size() != 1) reader_.fail("expected " + what + " alone on the line");
    return reader_.to_count(tokens[0], what, text_size_);
  }

  static std::string node_progress(std::size_t n, std::size_t i) {
    return std::to_string(n) + " nodes declared, " + std::to_string(i) + " read";
  }
  static std::string element_progress(std::size_t n, std::size_t i) {
    return std::to_string(n) + " elements declared, " + std::to_string(i) + " read";
  }

  // Skips an unknown section up to its $End line.
  void skip_section(const std::string& name) {
    const std::size_t start = reader_.line();
    std::string end = "$End" + name.substr(1);
    std::string_view line;
    while (reader_.next_line(line)) {
      const auto tokens = split_tokens(line);
      if (!tokens.empty() && equal_ignoring_case(tokens[0], end)) return;
    }
    throw InputError(describe_at(reader_.source(), start, "section " + name + " is never closed (no " + end + ")"));
  }

  static bool equal_ignoring_case(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
        return false;
    return true;
  }

  RawMesh finish() {
    RawMesh raw;
    for (const PendingElement& e : elements_) {
      std::array<std::int64_t, 10> ids{};
      for (std::size_t k = 0; k < e.shape.points; ++k) {
        const auto it = index_of_tag_.find(e.tags[k]);
        if (it == index_of_tag_.end())
          throw InputError(describe_at(reader_.source(), e.line,
                                       "the element refers to node " + std::to_string(e.tags[k]) +
                                           ", which the node section does not define"));
        ids[k] = it->second;
      }
      if (e.shape.corners == 4) raw.tets.push_back({ids[0], ids[1], ids[2], ids[3]});
      else raw.triangles.push_back({ids[0], ids[1], ids[2]});
    }
    raw.positions = std::move(positions_);
    return raw;
  }

  LineReader reader_;
  std::size_t text_size_;  // bounds every declared count
  Version version_ = Version::kNone;
  bool seen_nodes_ = false;
  std::vector<Vec3> positions_;                            // (n_nodes)
  std::unordered_map<std::int64_t, std::int64_t> index_of_tag_;  // node tag -> 0-based id
  std::vector<PendingElement> elements_;                   // tets and triangles, in file order
};

}  // namespace

RawMesh read_gmsh(const std::string& path) {
  const std::string text = read_file_bytes(path);
  return GmshReader(path, text).read();
}

}  // namespace mtcut::engine
