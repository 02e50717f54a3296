#pragma once
// The soft step's constraints split into islands: sets of contacts and joints linked through the
// bodies they move (the ground, slot 0, links nothing). No impulse crosses from one island to
// another, so islands are solved at the same time on several threads, each island's constraints
// one after another in the order the solver was given them: the result is bit for bit the
// sequential solve's, whatever the thread count. (Graph colouring, Box2D v3's constraint_graph.c,
// solves one island on several threads, but reorders its Gauss-Seidel sweeps, and in colour order
// soft contacts stay at rest only up to about a tenth of the substep rate where this order holds a
// fifth: Box3D caps them at an eighth for that. docs/speed.md, "Graph colouring", has the
// measurements. Bullet and PhysX split by islands the same way.)
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rbsim {

class SolverIslands {
 public:
  // Constraint sets A (contacts) and B (joints), constraint i of a set joining solver slots
  // bodyA(i) and bodyB(i); `slots` solver slots, slot 0 the ground. Islands are numbered by size,
  // the largest first (so that the largest start first on the threads).
  template <typename A0, typename A1, typename B0, typename B1>
  void build(std::size_t slots, std::size_t contacts, A0 contactA, A1 contactB, std::size_t joints, B0 jointA,
             B1 jointB) {
    parent_.resize(slots);
    for (std::size_t s = 0; s < slots; ++s) parent_[s] = static_cast<std::uint32_t>(s);
    const auto link = [&](int a, int b) {
      if (a == 0 || b == 0) return;
      const std::uint32_t ra = find(static_cast<std::uint32_t>(a)), rb = find(static_cast<std::uint32_t>(b));
      if (ra != rb) parent_[std::max(ra, rb)] = std::min(ra, rb);
    };
    for (std::size_t i = 0; i < contacts; ++i) link(contactA(i), contactB(i));
    for (std::size_t i = 0; i < joints; ++i) link(jointA(i), jointB(i));
    // Each root's island number, by first appearance, then the islands sorted by size.
    islandOfRoot_.assign(slots, kNone);
    sizes_.clear();
    const auto islandOf = [&](int a, int b) {
      const std::uint32_t root = find(static_cast<std::uint32_t>(a != 0 ? a : b));
      if (islandOfRoot_[root] == kNone) {
        islandOfRoot_[root] = static_cast<std::uint32_t>(sizes_.size());
        sizes_.push_back(0);
      }
      ++sizes_[islandOfRoot_[root]];
      return islandOfRoot_[root];
    };
    contactIsland_.resize(contacts);
    jointIsland_.resize(joints);
    for (std::size_t i = 0; i < contacts; ++i) contactIsland_[i] = islandOf(contactA(i), contactB(i));
    for (std::size_t i = 0; i < joints; ++i) jointIsland_[i] = islandOf(jointA(i), jointB(i));
    rank_.resize(sizes_.size());
    for (std::size_t k = 0; k < rank_.size(); ++k) rank_[k] = static_cast<std::uint32_t>(k);
    // Largest first, ties in island order: a stable sort's order, without its buffer.
    std::sort(rank_.begin(), rank_.end(), [&](std::uint32_t x, std::uint32_t y) {
      return sizes_[x] > sizes_[y] || (sizes_[x] == sizes_[y] && x < y);
    });
    position_.resize(rank_.size());
    for (std::size_t k = 0; k < rank_.size(); ++k) position_[rank_[k]] = static_cast<std::uint32_t>(k);
    bucket(contactIsland_, contactStart_, contactOrder_);
    bucket(jointIsland_, jointStart_, jointOrder_);
  }

  std::size_t count() const { return rank_.size(); }
  // Island k's contacts (joints) in the order given: order[start(k)] .. order[start(k + 1) - 1].
  template <typename F>
  void forContacts(std::size_t k, F&& f) const {
    for (std::size_t j = contactStart_[k]; j < contactStart_[k + 1]; ++j) f(contactOrder_[j]);
  }
  template <typename F>
  void forJoints(std::size_t k, F&& f) const {
    for (std::size_t j = jointStart_[k]; j < jointStart_[k + 1]; ++j) f(jointOrder_[j]);
  }
  std::size_t constraints(std::size_t k) const { return sizes_[rank_[k]]; }

 private:
  static constexpr std::uint32_t kNone = 0xffffffffu;

  std::uint32_t find(std::uint32_t s) {
    while (parent_[s] != s) {
      parent_[s] = parent_[parent_[s]];  // path halving
      s = parent_[s];
    }
    return s;
  }
  // Counting sort of constraints by island position, stable.
  void bucket(const std::vector<std::uint32_t>& island, std::vector<std::size_t>& start, std::vector<std::uint32_t>& order) {
    start.assign(rank_.size() + 1, 0);
    for (std::uint32_t k : island) ++start[position_[k] + 1];
    for (std::size_t k = 0; k < rank_.size(); ++k) start[k + 1] += start[k];
    order.resize(island.size());
    next_.assign(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < island.size(); ++i) order[next_[position_[island[i]]]++] = static_cast<std::uint32_t>(i);
  }

  std::vector<std::uint32_t> parent_, islandOfRoot_, contactIsland_, jointIsland_, rank_, position_;
  std::vector<std::size_t> sizes_, contactStart_, jointStart_, next_;
  std::vector<std::uint32_t> contactOrder_, jointOrder_;
};

}  // namespace rbsim
