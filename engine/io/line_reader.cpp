#include "engine/io/line_reader.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

#include "engine/input_error.h"
#include "engine/text.h"

namespace mtcut::engine {
namespace {

// from_chars takes no leading '+'; files written by Fortran or printf("%+g") have one.
std::string_view drop_plus(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+') token.remove_prefix(1);
  return token;
}

}  // namespace

std::string read_file_bytes(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw InputError(path + ": no such file");
  if (fs::is_directory(status)) throw InputError(path + ": is a directory, not a mesh file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the file for reading");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(path + ": cannot read the file");
  if (bytes.empty()) throw InputError(path + ": the file is empty");
  return bytes;
}

bool parse_int(std::string_view token, std::int64_t& value) {
  token = drop_plus(token);
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && ptr == end;
}

bool parse_real(std::string_view token, double& value) {
  token = drop_plus(token);
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value, std::chars_format::general);
  return ec == std::errc() && ptr == end;
}

std::vector<std::string_view> split_tokens(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

std::string quote_token(std::string_view token) {
  constexpr std::size_t kMax = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < kMax; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      static const char* hex = "0123456789ABCDEF";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (token.size() > kMax) out += "...";
  return out + "'";
}

LineReader::LineReader(std::string source, std::string_view text) : source_(std::move(source)), text_(text) {}

bool LineReader::next_line(std::string_view& line) {
  if (pos_ >= text_.size()) {
    line_ = pos_line_;  // faults at the end point past the last line
    return false;
  }
  const std::size_t newline = text_.find('\n', pos_);
  const std::size_t end = newline == std::string_view::npos ? text_.size() : newline;
  line = text_.substr(pos_, end - pos_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  line_ = pos_line_;
  pos_ = newline == std::string_view::npos ? text_.size() : newline + 1;
  if (newline != std::string_view::npos) ++pos_line_;
  return true;
}

bool LineReader::next_token(std::string_view& token) {
  while (pos_ < text_.size() && is_space(text_[pos_])) {
    if (text_[pos_] == '\n') ++pos_line_;
    ++pos_;
  }
  if (pos_ >= text_.size()) {
    line_ = pos_line_;
    return false;
  }
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
  token = text_.substr(start, pos_ - start);
  line_ = pos_line_;
  return true;
}

bool LineReader::peek_token(std::string_view& token) {
  const std::size_t pos = pos_, pos_line = pos_line_, line = line_;
  const bool found = next_token(token);
  pos_ = pos;
  pos_line_ = pos_line;
  line_ = line;
  return found;
}

std::string_view LineReader::expect_token(const std::string& what) {
  std::string_view token;
  if (!next_token(token)) {
    line_ = pos_line_;
    fail("unexpected end of the file (expected " + what + ")");
  }
  return token;
}

std::int64_t LineReader::expect_int(const std::string& what) { return to_int(expect_token(what), what); }

double LineReader::expect_real(const std::string& what) { return to_real(expect_token(what), what); }

bool LineReader::at_end() {
  std::size_t p = pos_;
  while (p < text_.size() && is_space(text_[p])) ++p;
  return p >= text_.size();
}

std::int64_t LineReader::to_int(std::string_view token, const std::string& what) const {
  std::int64_t value = 0;
  if (!parse_int(token, value)) fail(what + " " + quote_token(token) + " is not an integer");
  return value;
}

double LineReader::to_real(std::string_view token, const std::string& what) const {
  double value = 0;
  if (!parse_real(token, value)) fail(what + " " + quote_token(token) + " is not a number");
  if (!std::isfinite(value)) fail(what + " " + quote_token(token) + " is not finite");
  return value;
}

std::size_t LineReader::to_count(std::string_view token, const std::string& what, std::size_t limit) const {
  const std::int64_t value = to_int(token, what);
  if (value < 0) fail(what + " " + quote_token(token) + " is negative");
  if (static_cast<std::uint64_t>(value) > limit)
    fail(what + " " + quote_token(token) + " is more than the file can hold (truncated or corrupt file)");
  return static_cast<std::size_t>(value);
}

void LineReader::skip_rest_of_line() {
  const std::size_t newline = text_.find('\n', pos_);
  if (newline == std::string_view::npos) {
    pos_ = text_.size();
    return;
  }
  pos_ = newline + 1;
  ++pos_line_;
}

std::string_view LineReader::take_bytes(std::size_t n, const std::string& what) {
  if (n > remaining())
    fail("the file is truncated: " + what + " needs " + std::to_string(n) + " bytes, only " +
         std::to_string(remaining()) + " are left");
  const std::string_view bytes = text_.substr(pos_, n);
  for (char c : bytes)
    if (c == '\n') ++pos_line_;
  pos_ += n;
  return bytes;
}

void LineReader::fail(const std::string& what) const { throw InputError(describe_at(source_, line_, what)); }

void LineReader::fail_file(const std::string& what) const { throw InputError(describe_at(source_, 0, what)); }

}  // namespace mtcut::engine
