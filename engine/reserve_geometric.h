#pragma once
// Room for at least n entries in a vector that is reserved for again and
// again (once per cut): growing to exactly n each time would copy the whole
// array every time, so capacity grows by half at least, as push_back's does.

#include <algorithm>
#include <cstddef>
#include <vector>

namespace mtcut::engine {

template <class T, class Allocator>
void reserve_geometric(std::vector<T, Allocator>& v, std::size_t n) {
  if (n > v.capacity()) v.reserve(std::max(n, v.capacity() + v.capacity() / 2));
}

}  // namespace mtcut::engine
