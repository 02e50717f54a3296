#pragma once
// Disjoint sets over indices (union-find): the World's islands, sets of dynamic bodies linked by
// contacts, which fall asleep together (as Box2D's b2Island), so that a stack never sleeps in part
// and is woken again by its own awake half; and the exact LCP solver's islands, its independent
// problems. Static bodies and planes link nothing: every box on the ground is its own island.
#include <cstddef>
#include <numeric>
#include <vector>

namespace rbsim {

// Disjoint sets over body indices, with path halving and union by size.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t count) : parent_(count), size_(count, 1) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void link(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }

 private:
  std::vector<std::size_t> parent_;
  std::vector<std::size_t> size_;
};

}  // namespace rbsim
