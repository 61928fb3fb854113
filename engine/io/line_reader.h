#pragma once
// A line-numbered cursor over a whole file held in memory, shared by the
// ascii readers (TetGen, Gmsh, legacy VTK). It hands out lines or
// whitespace-separated tokens, remembers the line of the last one, and turns
// every fault into an InputError "path: line N: what". It also hands out raw
// byte blocks, for the binary sections that legacy VTK embeds between its
// keyword lines. It never reads past the end of the text.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace mtcut::engine {

// The whole file as bytes. InputError if it is missing, a directory,
// unreadable or empty.
std::string read_file_bytes(const std::string& path);

// The whole token as an integer (an optional leading '+' allowed).
bool parse_int(std::string_view token, std::int64_t& value);
// The whole token as a real; "nan" and "inf" parse (the caller checks
// finiteness), an out-of-range magnitude does not.
bool parse_real(std::string_view token, double& value);
// Whitespace-separated tokens of one line.
std::vector<std::string_view> split_tokens(std::string_view line);
// A token as it may appear in a one-line message: quoted, at most 40
// characters, bytes that are not printable shown as \xNN.
std::string quote_token(std::string_view token);

class LineReader {
 public:
  // source names the file in messages; text must outlive the reader.
  LineReader(std::string source, std::string_view text);

  const std::string& source() const { return source_; }
  // Line (1-based) of the last line or token handed out; 0 before any.
  std::size_t line() const { return line_; }
  // Byte position of the cursor in the text.
  std::size_t offset() const { return pos_; }
  // Bytes left after the cursor.
  std::size_t remaining() const { return text_.size() - pos_; }

  // The next line without its line end (\n, \r\n); false at the end.
  bool next_line(std::string_view& line);
  // The next token, crossing line ends; false at the end.
  bool next_token(std::string_view& token);
  // The next token without moving past it; false at the end.
  bool peek_token(std::string_view& token);
  // The same, where the end of the file is a fault: "unexpected end of the
  // file (expected <what>)".
  std::string_view expect_token(const std::string& what);
  std::int64_t expect_int(const std::string& what);
  // A finite real.
  double expect_real(const std::string& what);
  // True when only whitespace is left.
  bool at_end();

  // A token as an integer / finite real; fails naming what it should be.
  std::int64_t to_int(std::string_view token, const std::string& what) const;
  double to_real(std::string_view token, const std::string& what) const;
  // A count: a non-negative integer no larger than limit.
  std::size_t to_count(std::string_view token, const std::string& what, std::size_t limit) const;

  // Moves past the end of the current line (after a keyword line that a
  // binary block follows).
  void skip_rest_of_line();
  // The next n bytes; fails when fewer are left ("truncated").
  std::string_view take_bytes(std::size_t n, const std::string& what);

  // Throws InputError "source: line N: what" (no line before the first one).
  [[noreturn]] void fail(const std::string& what) const;
  // Throws InputError "source: what", for faults that have no line.
  [[noreturn]] void fail_file(const std::string& what) const;

 private:
  std::string source_;
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;       // line of the last item handed out
  std::size_t pos_line_ = 1;   // line the cursor is on
};

}  // namespace mtcut::engine
