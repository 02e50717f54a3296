// collision/narrowphase/query_log: the ring buffer keeps the last N queries, oldest first, and
// dumps them as CSV with a header.
#include "rbsim/collision/narrowphase/query_log.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace rbsim {
namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::size_t columns(const std::string& line) { return static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1; }

ContactManifold twoPoints() {
  ContactManifold m;
  m.normal = Vec3::UnitY();
  m.add(Vec3(1, 0, 0), 0.01);
  m.add(Vec3(-1, 0, 0), 0.02);
  return m;
}

TEST(QueryLog, KeepsTheLastCapacityRecordsOldestFirst) {
  QueryLog log(3);
  EXPECT_EQ(log.capacity(), 3u);
  for (std::uint32_t i = 0; i < 5; ++i) log.record(summarize(QueryKind::ConvexConvex, i, i + 10, twoPoints()));
  EXPECT_EQ(log.size(), 3u);
  EXPECT_EQ(log.total(), 5u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(log.at(i).sequence, 2 + i);
    EXPECT_EQ(log.at(i).idA, 2 + i);
    EXPECT_EQ(log.at(i).idB, 12 + i);
  }
  EXPECT_THROW(log.at(3), std::out_of_range);
  log.clear();
  EXPECT_EQ(log.size(), 0u);
}

TEST(QueryLog, SummarizeTakesOverlapDepthAndPoints) {
  QueryRecord r = summarize(QueryKind::BoxBox, 4, 7, twoPoints(), 0.0, 1.5);
  EXPECT_TRUE(r.overlap);
  EXPECT_DOUBLE_EQ(r.depth, 0.02);
  EXPECT_EQ(r.count, 2);
  EXPECT_DOUBLE_EQ(r.time, 1.5);
  EXPECT_DOUBLE_EQ(r.points[1].position.x(), -1.0);
  r = summarize(QueryKind::Distance, 4, 7, ContactManifold{}, 0.25);
  EXPECT_FALSE(r.overlap);
  EXPECT_DOUBLE_EQ(r.distance, 0.25);
}

TEST(QueryLog, DumpsCsvWithAHeaderAndOneRowPerRecord) {
  QueryLog log(2);
  log.record(summarize(QueryKind::PlaneConvex, 0, 1, twoPoints()));
  log.record(summarize(QueryKind::Distance, 2, 3, ContactManifold{}, 0.125));
  log.record(summarize(QueryKind::BoxBox, 5, 6, twoPoints()));
  std::ostringstream os;
  log.dump(os);
  const std::vector<std::string> rows = lines(os.str());
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].rfind("sequence,time,kind,id_a,id_b,overlap,distance,depth,nx,ny,nz,count,p0x", 0), 0u);
  EXPECT_EQ(rows[1].rfind("1,0,distance,2,3,0,0.125,", 0), 0u) << rows[1];
  EXPECT_EQ(rows[2].rfind("2,0,box-box,5,6,1,0,0.02", 0), 0u) << rows[2];
  for (const std::string& row : rows) EXPECT_EQ(columns(row), columns(rows[0])) << row;
}

TEST(QueryLog, ZeroCapacityIsRejected) { EXPECT_THROW(QueryLog(0), std::invalid_argument); }

}  // namespace
}  // namespace rbsim
