#include "dynpos/io/input_report.hpp"

#include <gtest/gtest.h>

#include <string>

namespace dynpos::io {
namespace {

TEST(LineCounts, CountsByKindAndInTotal) {
  LineCounts c;
  EXPECT_TRUE(c.empty());
  c.add("bad checksum");
  c.add("truncated", 2);
  c.add("bad checksum", 3);
  c.add("comment", 0);  // nothing counted, no empty kind listed
  EXPECT_EQ(c.count("bad checksum"), 4u);
  EXPECT_EQ(c.count("truncated"), 2u);
  EXPECT_EQ(c.count("comment"), 0u);
  EXPECT_EQ(c.total(), 6u);
  EXPECT_EQ(c.by_kind().size(), 2u);
}

InputReport two_files() {
  InputReport r;
  FileReport main;
  main.path = "trial.csv";
  main.format = "csv";
  main.time_format = "seconds";
  main.records = 100;
  r.files.push_back(main);
  r.roles.push_back({"north", "trial.csv", 10.0});
  InputReport other;
  FileReport nmea;
  nmea.path = "gnss.nmea";
  nmea.format = "nmea";
  nmea.time_format = "UTC time of day";
  nmea.records = 20;
  nmea.skipped.add("bad checksum", 2);
  nmea.accepted.add("no checksum");
  nmea.notes.push_back("empty geoid separation read as 0 m");
  other.files.push_back(nmea);
  other.roles.push_back({"heading", "gnss.nmea", std::nullopt});
  other.origin = "2030-01-01T00:00:00Z";  // not taken over by append()
  r.append(other);
  return r;
}

TEST(InputReport, AppendKeepsOrderAndOrigin) {
  const InputReport r = two_files();
  ASSERT_EQ(r.files.size(), 2u);
  EXPECT_EQ(r.files[1].path, "gnss.nmea");
  ASSERT_EQ(r.roles.size(), 2u);
  EXPECT_EQ(r.roles[1].role, "heading");
  EXPECT_FALSE(r.origin);
  ASSERT_NE(r.file("gnss.nmea"), nullptr);
  EXPECT_EQ(r.file("gnss.nmea")->records, 20u);
  EXPECT_EQ(r.file("other.csv"), nullptr);
}

TEST(InputReport, JsonHasTheDocumentedKeys) {
  InputReport r = two_files();
  r.origin = "2024-05-01T10:00:00.250Z";
  r.origin_zone = "UTC";
  const nlohmann::json j = to_json(r);
  EXPECT_EQ(j.at("files").size(), 2u);
  EXPECT_EQ(j.at("files").at(1).at("skipped").at("bad checksum"), 2);
  EXPECT_EQ(j.at("files").at(1).at("accepted").at("no checksum"), 1);
  EXPECT_EQ(j.at("files").at(1).at("notes").at(0), "empty geoid separation read as 0 m");
  EXPECT_EQ(j.at("roles").at(0).at("rate_hz"), 10.0);
  EXPECT_TRUE(j.at("roles").at(1).at("rate_hz").is_null());  // missing, never zero
  EXPECT_EQ(j.at("origin"), "2024-05-01T10:00:00.250Z");
  EXPECT_EQ(j.at("origin_zone"), "UTC");
}

TEST(InputReport, TextHasOneLinePerFileWithItsRoles) {
  const std::string text = to_text(two_files());
  EXPECT_NE(text.find("input: trial.csv (csv, time stamps: seconds, 100 records): north 10 Hz\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("input: gnss.nmea (nmea, time stamps: UTC time of day, 20 records, "
                      "skipped: 2 bad checksum, accepted: 1 no checksum): heading\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("  note: empty geoid separation read as 0 m\n"), std::string::npos);
  EXPECT_EQ(text.find("t = 0 s"), std::string::npos);  // no origin, no origin line
}

}  // namespace
}  // namespace dynpos::io
