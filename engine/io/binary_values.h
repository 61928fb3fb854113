#pragma once
// Numbers stored as raw bytes, as the binary VTK formats hold them: the
// scalar types by their names in either format, decoding one value of a
// type from bytes in a given byte order, and base64 (VTK XML "binary" and
// appended base64 data). Nothing here reads past the bytes it is given.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace mtcut::engine {

// One scalar type: its width in bytes and how to read it.
struct ScalarType {
  std::size_t size = 0;  // 1, 2, 4 or 8
  bool real = false;     // IEEE float / double
  bool is_signed = false;
};

// Legacy VTK names (float, double, int, unsigned_char, vtktypeint64, ...),
// case-insensitive; nullopt for unknown ones (and for "bit").
std::optional<ScalarType> legacy_vtk_type(std::string_view name);
// VTK XML names (Float32, Float64, Int8 ... UInt64, and the old Int, Float
// spellings); nullopt for unknown ones.
std::optional<ScalarType> xml_vtk_type(std::string_view name);

// The value at bytes[0 .. type.size) as a double (integers converted).
double decode_real(const unsigned char* bytes, ScalarType type, bool big_endian);
// The value as an integer; false for a real type or an unsigned value
// beyond the int64 range.
bool decode_int(const unsigned char* bytes, ScalarType type, bool big_endian, std::int64_t& value);

// Decodes base64 text, skipping whitespace. Padded chunks may follow each
// other ("header==" "data"), as some writers encode the VTK header on its
// own. Stops once max_bytes are out (the rest of the text is not checked).
// Returns nullopt on a character outside the base64 alphabet; *used is set
// to the number of characters consumed.
std::optional<std::string> decode_base64(std::string_view text, std::size_t max_bytes, std::size_t* used = nullptr);

}  // namespace mtcut::engine
