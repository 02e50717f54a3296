#pragma once
// Removing element i of an array whose order does not matter: the last element moves into its
// place (Box2D's b2RemoveBody does the same with its body array), so removal is O(1) and the
// arrays indexed alike stay aligned when each is swap-removed at the same index.
#include <cstddef>
#include <utility>
#include <vector>

namespace rbsim {

template <typename T>
void swapRemove(std::vector<T>& items, std::size_t index) {
  if (index + 1 != items.size()) items[index] = std::move(items.back());
  items.pop_back();
}

}  // namespace rbsim
