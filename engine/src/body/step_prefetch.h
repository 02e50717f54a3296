#pragma once
// Starts fetching the cache lines of a body that a step reads and writes, for a pass over many
// bodies to call a few bodies ahead: the hardware prefetcher alone left the step waiting on memory
// (bench/throughput_bench at 1e5 bodies ran 1.6x faster with it, issue 3). A friend of RigidBody
// in a private header (issue 57), so the public headers name no compiler builtin and the pass
// still inlines it.
#include <cstddef>

#include "math/portable.h"
#include "rbsim/body/rigid_body.h"

namespace rbsim {

struct StepPrefetch {
  static void fetch(const RigidBody& body) {
    const char* line = reinterpret_cast<const char*>(&body);
    const char* end = reinterpret_cast<const char*>(&body.inputs_ + 1);
    for (; line < end; line += RigidBody::kCacheLineBytes) prefetchForWriting(line);
  }
};

}  // namespace rbsim
