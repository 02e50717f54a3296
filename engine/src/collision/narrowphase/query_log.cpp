#include "rbsim/collision/narrowphase/query_log.h"

#include <algorithm>
#include <ios>
#include <limits>
#include <stdexcept>

namespace rbsim {

const char* queryKindName(QueryKind kind) {
  switch (kind) {
    case QueryKind::PlaneConvex: return "plane-convex";
    case QueryKind::ConvexConvex: return "convex-convex";
    case QueryKind::BoxBox: return "box-box";
    case QueryKind::Distance: return "distance";
    case QueryKind::TriangleTriangle: return "triangle-triangle";
    case QueryKind::Sdf: return "surface-points-vs-sdf";
    case QueryKind::PlaneRound: return "plane-round";
    case QueryKind::Round: return "round-pair";
  }
  return "unknown";
}

QueryRecord summarize(QueryKind kind, std::uint32_t idA, std::uint32_t idB, const ContactManifold& manifold,
                      double distance, double time) {
  QueryRecord r;
  r.time = time;
  r.kind = kind;
  r.idA = idA;
  r.idB = idB;
  r.count = manifold.count;
  r.overlap = manifold.count > 0 && manifold.maxDepth() >= 0.0;
  r.depth = manifold.count > 0 ? std::max(0.0, manifold.maxDepth()) : 0.0;
  r.distance = distance;
  r.normal = manifold.normal;
  r.points = manifold.points;
  return r;
}

QueryLog::QueryLog(std::size_t capacity) {
  if (capacity == 0) throw std::invalid_argument("QueryLog capacity must be at least 1");
  slots_.resize(capacity);
}

void QueryLog::record(const QueryRecord& r) {
  QueryRecord& slot = slots_[head_];
  slot = r;
  slot.sequence = next_++;
  head_ = (head_ + 1) % slots_.size();
  size_ = std::min(size_ + 1, slots_.size());
}

void QueryLog::clear() {
  head_ = 0;
  size_ = 0;
  next_ = 0;
}

const QueryRecord& QueryLog::at(std::size_t i) const {
  if (i >= size_) throw std::out_of_range("QueryLog::at: index past the kept records");
  return slots_[(head_ + slots_.size() - size_ + i) % slots_.size()];
}

void QueryLog::dump(std::ostream& os) const {
  const std::streamsize oldPrecision = os.precision(std::numeric_limits<double>::max_digits10);
  os << "sequence,time,kind,id_a,id_b,overlap,distance,depth,nx,ny,nz,count";
  for (int k = 0; k < kMaxManifoldPoints; ++k) os << ",p" << k << "x,p" << k << "y,p" << k << "z,d" << k;
  os << '\n';
  for (std::size_t i = 0; i < size_; ++i) {
    const QueryRecord& r = at(i);
    os << r.sequence << ',' << r.time << ',' << queryKindName(r.kind) << ',' << r.idA << ',' << r.idB << ','
       << (r.overlap ? 1 : 0) << ',' << r.distance << ',' << r.depth << ',' << r.normal.x() << ','
       << r.normal.y() << ',' << r.normal.z() << ',' << r.count;
    for (int k = 0; k < kMaxManifoldPoints; ++k) {
      if (k < r.count) {
        const ContactPoint& p = r.points[k];
        os << ',' << p.position.x() << ',' << p.position.y() << ',' << p.position.z() << ',' << p.depth;
      } else {
        os << ",,,,";
      }
    }
    os << '\n';
  }
  os.precision(oldPrecision);
}

}  // namespace rbsim
