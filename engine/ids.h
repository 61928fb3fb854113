#pragma once
// Typed index handles. Every element of the engine is named by a 32-bit index
// into a struct-of-arrays, never by a pointer: handles stay valid when arrays
// grow, serialize trivially, and cannot be mixed up across element kinds.

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>

namespace mtcut::engine {

template <class Tag>
struct Id {
  std::int32_t value = -1;  // -1 = none

  constexpr Id() = default;
  constexpr explicit Id(std::int32_t v) : value(v) {}
  constexpr explicit Id(std::size_t v) : value(static_cast<std::int32_t>(v)) {}

  constexpr bool valid() const { return value >= 0; }
  constexpr std::size_t index() const { return static_cast<std::size_t>(value); }
  constexpr auto operator<=>(const Id&) const = default;
};

using VertId = Id<struct VertTag>;
using TetId = Id<struct TetTag>;
using FragId = Id<struct FragTag>;

}  // namespace mtcut::engine

template <class Tag>
struct std::hash<mtcut::engine::Id<Tag>> {
  std::size_t operator()(mtcut::engine::Id<Tag> id) const noexcept {
    return std::hash<std::int32_t>{}(id.value);
  }
};
