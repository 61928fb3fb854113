#include "engine/io/binary_values.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>

#include "engine/text.h"

namespace mtcut::engine {
namespace {

// The value's bytes in the machine's order.
std::array<unsigned char, 8> native_bytes(const unsigned char* bytes, std::size_t size, bool big_endian) {
  std::array<unsigned char, 8> b{};
  std::memcpy(b.data(), bytes, size);
  const bool swap = big_endian != (std::endian::native == std::endian::big);
  if (swap) std::reverse(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(size));
  return b;
}

template <class T>
T load(const std::array<unsigned char, 8>& b) {
  T value;
  std::memcpy(&value, b.data(), sizeof(T));
  return value;
}

int base64_digit(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

}  // namespace

std::optional<ScalarType> legacy_vtk_type(std::string_view name) {
  const std::string n = lower(name);
  if (n == "float" || n == "vtktypefloat32") return ScalarType{4, true, true};
  if (n == "double" || n == "vtktypefloat64") return ScalarType{8, true, true};
  if (n == "char" || n == "signed_char" || n == "vtktypeint8") return ScalarType{1, false, true};
  if (n == "unsigned_char" || n == "vtktypeuint8") return ScalarType{1, false, false};
  if (n == "short" || n == "vtktypeint16") return ScalarType{2, false, true};
  if (n == "unsigned_short" || n == "vtktypeuint16") return ScalarType{2, false, false};
  if (n == "int" || n == "vtktypeint32") return ScalarType{4, false, true};
  if (n == "unsigned_int" || n == "vtktypeuint32") return ScalarType{4, false, false};
  if (n == "long" || n == "vtktypeint64" || n == "vtkidtype") return ScalarType{8, false, true};
  if (n == "unsigned_long" || n == "vtktypeuint64") return ScalarType{8, false, false};
  return std::nullopt;
}

std::optional<ScalarType> xml_vtk_type(std::string_view name) {
  if (name == "Float32" || name == "Float") return ScalarType{4, true, true};
  if (name == "Float64" || name == "Double") return ScalarType{8, true, true};
  if (name == "Int8" || name == "Char") return ScalarType{1, false, true};
  if (name == "UInt8" || name == "UChar") return ScalarType{1, false, false};
  if (name == "Int16" || name == "Short") return ScalarType{2, false, true};
  if (name == "UInt16" || name == "UShort") return ScalarType{2, false, false};
  if (name == "Int32" || name == "Int") return ScalarType{4, false, true};
  if (name == "UInt32" || name == "UInt") return ScalarType{4, false, false};
  if (name == "Int64" || name == "Long" || name == "IdType") return ScalarType{8, false, true};
  if (name == "UInt64" || name == "ULong") return ScalarType{8, false, false};
  return std::nullopt;
}

double decode_real(const unsigned char* bytes, ScalarType type, bool big_endian) {
  const auto b = native_bytes(bytes, type.size, big_endian);
  if (type.real) return type.size == 4 ? static_cast<double>(load<float>(b)) : load<double>(b);
  std::int64_t value = 0;
  if (decode_int(bytes, type, big_endian, value)) return static_cast<double>(value);
  return static_cast<double>(load<std::uint64_t>(b));
}

bool decode_int(const unsigned char* bytes, ScalarType type, bool big_endian, std::int64_t& value) {
  if (type.real) return false;
  const auto b = native_bytes(bytes, type.size, big_endian);
  switch (type.size) {
    case 1: value = type.is_signed ? load<std::int8_t>(b) : load<std::uint8_t>(b); return true;
    case 2: value = type.is_signed ? load<std::int16_t>(b) : load<std::uint16_t>(b); return true;
    case 4: value = type.is_signed ? load<std::int32_t>(b) : load<std::uint32_t>(b); return true;
    case 8:
      if (type.is_signed) {
        value = load<std::int64_t>(b);
        return true;
      } else {
        const auto u = load<std::uint64_t>(b);
        if (u > static_cast<std::uint64_t>(INT64_MAX)) return false;
        value = static_cast<std::int64_t>(u);
        return true;
      }
    default: return false;
  }
}

std::optional<std::string> decode_base64(std::string_view text, std::size_t max_bytes, std::size_t* used) {
  std::string out;
  out.reserve(std::min(max_bytes, text.size() / 4 * 3 + 3));
  std::array<int, 4> group{};
  std::size_t filled = 0;  // digits in group
  std::size_t padding = 0;
  std::size_t i = 0;
  auto flush = [&](std::size_t digits) {
    std::uint32_t bits = 0;
    for (int g : group) bits = (bits << 6) | static_cast<std::uint32_t>(g);
    const std::size_t n = digits == 4 ? 3 : digits - 1;  // 2 digits -> 1 byte, 3 -> 2
    for (std::size_t k = 0; k < n; ++k) out += static_cast<char>((bits >> (16 - 8 * k)) & 0xff);
    group = {};
    filled = 0;
  };
  for (; i < text.size() && out.size() < max_bytes; ++i) {
    const char c = text[i];
    if (is_space(c)) continue;
    if (c == '=') {
      // Padding closes a chunk: "xx==" or "xxx=".
      if (filled < 2) return std::nullopt;
      ++padding;
      if (filled + padding == 4) {
        flush(filled);
        padding = 0;
      }
      continue;
    }
    if (padding != 0) return std::nullopt;  // a digit inside the padding
    const int d = base64_digit(c);
    if (d < 0) return std::nullopt;
    group[filled++] = d;
    if (filled == 4) flush(4);
  }
  if (out.size() < max_bytes && filled >= 2) flush(filled);  // an unpadded tail
  if (used != nullptr) *used = i;
  if (out.size() > max_bytes) out.resize(max_bytes);
  return out;
}

}  // namespace mtcut::engine
