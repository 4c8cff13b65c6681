// The options of leverarm gnss given as text: antenna files as gnssK=FILE, gains and arms as
// X,Y,Z, the UTC of the log's start; each error naming its request key with an example.

#include "dynpos/analysis/leverarm_gnss_text.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "dynpos/analysis/option_spelling.hpp"
#include "input_error_capture.hpp"

namespace dynpos::analysis {
namespace {

using testing::input_error;

// The error parse_text() throws on `t`.
core::InputError parse_error(const LeverarmGnssText& t) {
  return input_error([&] {
    LeverarmGnssRequest q;
    parse_text(t, q);
  });
}

LeverarmGnssText every_option() {
  LeverarmGnssText t;
  t.gnss_log = {"gnss1=a.csv", "gnss2=b.csv"};
  t.nmea = {"gnss3=c.nmea"};
  t.utc_at_zero = "12:30:15.5";
  t.init = {"gnss1=0.2,-0.6,-13.9"};
  t.w1 = "1,2,3";
  t.w2 = "4,5,6";
  t.gamma = "0.1,0.2,0.3";
  t.L = "7,8,9";
  t.init_p0 = "10,-20,0";
  t.imu_arm = "0.358,0.804,-4.321";
  return t;
}

TEST(LeverarmGnssText, EveryOptionBecomesItsTypedField) {
  LeverarmGnssRequest q;
  parse_text(every_option(), q);
  EXPECT_EQ(q.gnss_log,
            (std::map<std::string, std::filesystem::path>{{"gnss1", "a.csv"}, {"gnss2", "b.csv"}}));
  EXPECT_EQ(q.nmea, (std::map<std::string, std::filesystem::path>{{"gnss3", "c.nmea"}}));
  ASSERT_TRUE(q.utc_at_zero.has_value());
  EXPECT_DOUBLE_EQ(*q.utc_at_zero, 12 * 3600.0 + 30 * 60.0 + 15.5);
  ASSERT_EQ(q.init.size(), 1u);
  EXPECT_EQ(q.init.at("gnss1"), Eigen::Vector3d(0.2, -0.6, -13.9));
  EXPECT_EQ(q.w1, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(q.w2, Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(q.gamma, Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_EQ(q.L, Eigen::Vector3d(7, 8, 9));
  EXPECT_EQ(q.init_p0, Eigen::Vector3d(10, -20, 0));
  EXPECT_EQ(q.imu_arm, Eigen::Vector3d(0.358, 0.804, -4.321));
}

TEST(LeverarmGnssText, EmptyTextLeavesTheRequestsValues) {
  LeverarmGnssRequest q;
  q.w1 = Eigen::Vector3d(1, 1, 1);
  q.utc_at_zero = 10.0;
  parse_text(LeverarmGnssText{}, q);
  EXPECT_EQ(q.w1, Eigen::Vector3d(1, 1, 1));
  EXPECT_EQ(q.utc_at_zero, 10.0);
  EXPECT_FALSE(q.w2.has_value());
  EXPECT_FALSE(q.imu_arm.has_value());
  EXPECT_TRUE(q.gnss_log.empty());
  EXPECT_TRUE(q.init.empty());
}

TEST(LeverarmGnssText, AFileWithoutItsAntennaNamesTheOptionAndAnExample) {
  LeverarmGnssText t;
  t.gnss_log = {"gnss1"};
  const core::InputError e = parse_error(t);
  EXPECT_EQ(e.option(), "gnss_log");
  EXPECT_EQ(e.problem(), "malformed argument 'gnss1': expected gnss1=FILE.csv");
  EXPECT_EQ(e.hint(), "for example --gnss-log gnss1=FILE.csv");
  EXPECT_EQ(cli_message(e),
            "(--gnss-log): malformed argument 'gnss1': expected gnss1=FILE.csv; for example "
            "--gnss-log gnss1=FILE.csv");
}

TEST(LeverarmGnssText, AnEmptyNameOrValueIsMalformed) {
  for (const char* spec : {"gnss1=", "=log.nmea", "="}) {
    LeverarmGnssText t;
    t.nmea = {spec};
    const core::InputError e = parse_error(t);
    EXPECT_EQ(e.option(), "nmea") << spec;
    EXPECT_EQ(e.problem(),
              "malformed argument '" + std::string(spec) + "': expected gnss1=FILE.nmea");
    EXPECT_EQ(e.hint(), "for example --nmea gnss1=FILE.nmea");
  }
  LeverarmGnssText t;
  t.init = {"0.2,-0.6,-13.9"};
  const core::InputError e = parse_error(t);
  EXPECT_EQ(e.option(), "init");
  EXPECT_EQ(e.problem(), "malformed argument '0.2,-0.6,-13.9': expected gnss1=0.2,-0.6,-13.9");
}

TEST(LeverarmGnssText, ABadVectorNamesItsKeyAndTheExample) {
  struct Case {
    void (*set)(LeverarmGnssText&);
    const char* key;
    const char* problem;
    const char* hint;
  };
  const Case cases[] = {
      {[](LeverarmGnssText& t) { t.w1 = "1,2"; }, "w1", "'1,2' is not three numbers X,Y,Z",
       "for example --w1 0.02,0.02,20"},
      {[](LeverarmGnssText& t) { t.L = "1,x,3"; }, "L", "'1,x,3' is not three numbers X,Y,Z",
       "for example --L 0.02,0.02,20"},
      {[](LeverarmGnssText& t) { t.init = {"gnss2=1,2,3,4"}; }, "init",
       "'1,2,3,4' is not three numbers X,Y,Z", "for example --init 0.02,0.02,20"},
      {[](LeverarmGnssText& t) { t.imu_arm = "0.3;0.8;-4"; }, "imu_arm",
       "'0.3;0.8;-4' is not three numbers X,Y,Z", "for example --imu-arm 0.358,0.804,-4.321"},
  };
  for (const Case& c : cases) {
    LeverarmGnssText t;
    c.set(t);
    const core::InputError e = parse_error(t);
    EXPECT_EQ(e.option(), c.key);
    EXPECT_EQ(e.problem(), c.problem);
    EXPECT_EQ(e.hint(), c.hint);
  }
}

TEST(LeverarmGnssText, ATimeThatIsNotUtcNamesUtcAtZero) {
  LeverarmGnssText t;
  t.utc_at_zero = "noon";
  const core::InputError e = parse_error(t);
  EXPECT_EQ(e.option(), "utc_at_zero");
  EXPECT_THAT(e.problem(), ::testing::HasSubstr("noon"));
}

}  // namespace
}  // namespace dynpos::analysis
