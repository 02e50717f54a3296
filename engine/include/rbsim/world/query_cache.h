#pragma once
// Where a World keeps the hierarchy its scene queries go through (world/world_queries.h): built
// on demand, shared by the queries that follow until the World changes. A copy of a World starts
// without one (it builds its own on its first query); a move takes it along.
#include <memory>

namespace rbsim {

struct QueryTreeCache;  // world/query_tree.h (private)

class QueryCacheSlot {
 public:
  QueryCacheSlot();
  QueryCacheSlot(const QueryCacheSlot&);
  QueryCacheSlot& operator=(const QueryCacheSlot&);
  QueryCacheSlot(QueryCacheSlot&&) noexcept = default;
  QueryCacheSlot& operator=(QueryCacheSlot&&) noexcept = default;
  ~QueryCacheSlot();
  QueryTreeCache& cache() const { return *cache_; }

 private:
  std::shared_ptr<QueryTreeCache> cache_;
};

}  // namespace rbsim
