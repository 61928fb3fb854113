#pragma once
// A small forward scanner over the tags of an XML file, enough for VTK XML:
// it hands out start, end and empty-element tags with their attributes and
// line, skips text, comments, processing instructions and CDATA, and stops
// wherever the caller stops asking (VTK's appended raw data is not XML, so
// the reader stops at <AppendedData>). Faults are InputError with the line.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mtcut::engine {

struct XmlTag {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;  // values with entities replaced
  bool closing = false;       // </name>
  bool self_closing = false;  // <name ... />
  std::size_t begin = 0;      // offset of '<'
  std::size_t end = 0;        // offset just past '>'
  std::size_t line = 0;       // line of '<'

  // The attribute's value, if present.
  std::optional<std::string> attribute(std::string_view key) const;
};

class XmlScanner {
 public:
  // source names the file in messages; text must outlive the scanner.
  XmlScanner(std::string source, std::string_view text);

  // The next tag after the previous one; false at the end of the text.
  bool next_tag(XmlTag& tag);
  // Line (1-based) of a byte offset at or after the last tag's start.
  std::size_t line_at(std::size_t offset);

  [[noreturn]] void fail(std::size_t line, const std::string& what) const;

 private:
  void skip_past(std::string_view terminator, const char* construct);
  std::string read_name();
  void skip_space();

  std::string source_;
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t counted_pos_ = 0;   // line_at has counted newlines up to here
  std::size_t counted_line_ = 1;
  std::size_t tag_line_ = 0;      // line of the construct being scanned
};

}  // namespace mtcut::engine
