#pragma once
// A ring buffer of the last N collision queries (seed 004 "Tips for debugging a collision
// detection system" after Ericson: keep a buffer of the last n collision queries and output the
// data for further analysis). The narrow-phase functions stay pure; their caller records here.
#include <array>
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <vector>

#include "rbsim/collision/contact.h"
#include "rbsim/math/types.h"

namespace rbsim {

enum class QueryKind : std::uint8_t { PlaneConvex, ConvexConvex, BoxBox, Distance, TriangleTriangle, Sdf, PlaneRound, Round };

const char* queryKindName(QueryKind kind);

// One query and a summary of its answer. Fixed size (Eigen's fixed-size vectors hold their
// coefficients inline), so copying one into a preallocated slot never allocates.
struct QueryRecord {
  std::uint64_t sequence = 0;  // set by QueryLog::record: 0 for the first query ever recorded
  double time = 0.0;           // simulation time of the query [s], as the caller knows it
  QueryKind kind = QueryKind::ConvexConvex;
  std::uint32_t idA = 0, idB = 0;  // the caller's ids of the two bodies or proxies
  bool overlap = false;
  double distance = 0.0;  // [m] when apart (for box pairs the SAT separation: ConvexContact)
  double depth = 0.0;     // [m] largest penetration when overlapping
  Vec3 normal = Vec3::Zero();  // from A to B
  int count = 0;          // contact points
  std::array<ContactPoint, kMaxManifoldPoints> points{};
};

// The summary of a manifold query (kind PlaneConvex, ConvexConvex or BoxBox).
QueryRecord summarize(QueryKind kind, std::uint32_t idA, std::uint32_t idB, const ContactManifold& manifold,
                      double distance = 0.0, double time = 0.0);

class QueryLog {
 public:
  explicit QueryLog(std::size_t capacity);  // capacity >= 1 records, allocated here once

  void record(const QueryRecord& r);  // overwrites the oldest when full
  void clear();

  std::size_t size() const { return size_; }
  std::size_t capacity() const { return slots_.size(); }
  std::uint64_t total() const { return next_; }  // queries recorded since construction or clear
  const QueryRecord& at(std::size_t i) const;    // i = 0 is the oldest kept

  // CSV with a header line, one row per kept record, oldest first, full precision.
  void dump(std::ostream& os) const;

 private:
  std::vector<QueryRecord> slots_;
  std::size_t head_ = 0;  // slot the next record goes to
  std::size_t size_ = 0;
  std::uint64_t next_ = 0;
};

}  // namespace rbsim
