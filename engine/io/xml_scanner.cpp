#include "engine/io/xml_scanner.h"

#include <algorithm>

#include "engine/input_error.h"
#include "engine/io/line_reader.h"

namespace mtcut::engine {
namespace {

bool is_xml_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

bool is_name_char(char c) {
  return !is_xml_space(c) && c != '>' && c != '/' && c != '=' && c != '<' && c != '"' && c != '\'';
}

// Replaces the five predefined entities and numeric character references
// below 128 (all that VTK writes); anything else is kept as written.
std::string unescape(std::string_view raw) {
  std::string out;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] != '&') {
      out += raw[i];
      continue;
    }
    const std::size_t semi = raw.find(';', i);
    if (semi == std::string_view::npos) {
      out += raw[i];
      continue;
    }
    const std::string_view entity = raw.substr(i + 1, semi - i - 1);
    char c = 0;
    if (entity == "amp") c = '&';
    else if (entity == "lt") c = '<';
    else if (entity == "gt") c = '>';
    else if (entity == "quot") c = '"';
    else if (entity == "apos") c = '\'';
    else if (entity.size() > 1 && entity[0] == '#') {
      std::int64_t code = 0;
      if (entity[1] != 'x' && parse_int(entity.substr(1), code) && code > 0 && code < 128) c = static_cast<char>(code);
    }
    if (c == 0) {
      out += raw[i];
      continue;
    }
    out += c;
    i = semi;
  }
  return out;
}

}  // namespace

std::optional<std::string> XmlTag::attribute(std::string_view key) const {
  for (const auto& [k, v] : attributes)
    if (k == key) return v;
  return std::nullopt;
}

XmlScanner::XmlScanner(std::string source, std::string_view text) : source_(std::move(source)), text_(text) {}

std::size_t XmlScanner::line_at(std::size_t offset) {
  offset = std::min(offset, text_.size());
  if (offset < counted_pos_) {  // backwards: count afresh
    counted_pos_ = 0;
    counted_line_ = 1;
  }
  const auto from = text_.begin() + static_cast<std::ptrdiff_t>(counted_pos_);
  const auto to = text_.begin() + static_cast<std::ptrdiff_t>(offset);
  counted_line_ += static_cast<std::size_t>(std::count(from, to, '\n'));
  counted_pos_ = offset;
  return counted_line_;
}

void XmlScanner::fail(std::size_t line, const std::string& what) const {
  throw InputError(describe_at(source_, line, what));
}

void XmlScanner::skip_past(std::string_view terminator, const char* construct) {
  const std::size_t at = text_.find(terminator, pos_);
  if (at == std::string_view::npos) fail(tag_line_, std::string("unterminated ") + construct);
  pos_ = at + terminator.size();
}

void XmlScanner::skip_space() {
  while (pos_ < text_.size() && is_xml_space(text_[pos_])) ++pos_;
}

std::string XmlScanner::read_name() {
  const std::size_t start = pos_;
  while (pos_ < text_.size() && is_name_char(text_[pos_])) ++pos_;
  return std::string(text_.substr(start, pos_ - start));
}

bool XmlScanner::next_tag(XmlTag& tag) {
  while (true) {
    const std::size_t open = text_.find('<', pos_);
    if (open == std::string_view::npos) {
      pos_ = text_.size();
      return false;
    }
    pos_ = open;
    tag_line_ = line_at(open);
    const std::string_view rest = text_.substr(open);
    if (rest.starts_with("<!--")) {
      skip_past("-->", "comment");
    } else if (rest.starts_with("<![CDATA[")) {
      skip_past("]]>", "CDATA section");
    } else if (rest.starts_with("<?")) {
      skip_past("?>", "processing instruction <?...?>");
    } else if (rest.starts_with("<!")) {
      skip_past(">", "declaration <!...>");
    } else {
      break;
    }
  }

  tag = XmlTag{};
  tag.begin = pos_;
  tag.line = tag_line_;
  ++pos_;  // '<'
  if (pos_ < text_.size() && text_[pos_] == '/') {
    tag.closing = true;
    ++pos_;
  }
  tag.name = read_name();
  if (tag.name.empty()) fail(tag.line, "a '<' that does not start a tag");
  while (true) {
    skip_space();
    if (pos_ >= text_.size()) fail(tag.line, "the file ends inside the tag <" + tag.name + ">");
    const char c = text_[pos_];
    if (c == '>') {
      ++pos_;
      break;
    }
    if (c == '/' && !tag.closing) {
      if (pos_ + 1 >= text_.size() || text_[pos_ + 1] != '>')
        fail(tag.line, "a stray '/' in the tag <" + tag.name + ">");
      tag.self_closing = true;
      pos_ += 2;
      break;
    }
    if (tag.closing) fail(tag.line, "the end tag </" + tag.name + "> has attributes");
    std::string key = read_name();
    if (key.empty()) fail(tag.line, "a malformed attribute in the tag <" + tag.name + ">");
    skip_space();
    if (pos_ >= text_.size() || text_[pos_] != '=')
      fail(tag.line, "the attribute " + key + " of <" + tag.name + "> has no value");
    ++pos_;
    skip_space();
    if (pos_ >= text_.size() || (text_[pos_] != '"' && text_[pos_] != '\''))
      fail(tag.line, "the value of the attribute " + key + " of <" + tag.name + "> is not quoted");
    const char quote = text_[pos_++];
    const std::size_t close = text_.find(quote, pos_);
    if (close == std::string_view::npos) fail(tag.line, "the value of the attribute " + key + " is never closed");
    if (tag.attribute(key)) fail(tag.line, "the attribute " + key + " appears twice in <" + tag.name + ">");
    tag.attributes.emplace_back(std::move(key), unescape(text_.substr(pos_, close - pos_)));
    pos_ = close + 1;
  }
  tag.end = pos_;
  return true;
}

}  // namespace mtcut::engine
