// identify vessel's logs: one per path, each with the log options the command line gives once.

#include <gtest/gtest.h>

#include "dynpos/analysis/vessel_id.hpp"

namespace dynpos::analysis {
namespace {

TEST(VesselIdLogs, EachPathWithTheSharedOptions) {
  LogSource shared;
  shared.columns = {"u=speed.u"};
  shared.units = {"u=kn"};
  shared.map_file = "map.toml";
  shared.jobs = 3;
  VesselIdRequest q;
  add_logs(q, shared, {"a/log.csv", "b/log.csv"});
  ASSERT_EQ(q.logs.size(), 2u);
  EXPECT_EQ(q.logs[0].log, "a/log.csv");
  EXPECT_EQ(q.logs[1].log, "b/log.csv");
  for (const LogSource& s : q.logs) {
    EXPECT_EQ(s.columns, shared.columns);
    EXPECT_EQ(s.units, shared.units);
    EXPECT_EQ(s.map_file, shared.map_file);
  }
  EXPECT_EQ(q.jobs, 3u);
}

TEST(VesselIdLogs, NoPathsNoLogs) {
  VesselIdRequest q;
  q.jobs = 5;
  LogSource shared;
  shared.jobs = 2;
  add_logs(q, shared, {});
  EXPECT_TRUE(q.logs.empty());
  EXPECT_EQ(q.jobs, 2u);  // the threads are the log options' still
}

}  // namespace
}  // namespace dynpos::analysis
