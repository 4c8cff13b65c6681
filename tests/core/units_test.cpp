#include "dynpos/core/units.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace dynpos::core {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kEps = std::numeric_limits<double>::epsilon();

std::vector<Quantity> all_quantities() {
  std::vector<Quantity> out;
  for (int q = 0; q <= static_cast<int>(Quantity::kDimensionless); ++q) {
    out.push_back(static_cast<Quantity>(q));
  }
  return out;
}

struct Expected {
  const char* spelling;
  Quantity quantity;
  double scale;  // SI per unit
};

// Every spelling units.hpp promises, with its quantity and factor to SI from first principles.
const std::vector<Expected>& required() {
  static const std::vector<Expected> kRequired{
      {"s", Quantity::kTime, 1.0},
      {"ms", Quantity::kTime, 0.001},
      {"min", Quantity::kTime, 60.0},
      {"h", Quantity::kTime, 3600.0},
      {"m", Quantity::kLength, 1.0},
      {"km", Quantity::kLength, 1000.0},
      {"nmi", Quantity::kLength, 1852.0},
      {"deg", Quantity::kAngle, kDeg},
      {"rad", Quantity::kAngle, 1.0},
      {"deg/s", Quantity::kAngularRate, kDeg},
      {"rad/s", Quantity::kAngularRate, 1.0},
      {"m/s", Quantity::kSpeed, 1.0},
      {"kn", Quantity::kSpeed, 1852.0 / 3600.0},
      {"km/h", Quantity::kSpeed, 1000.0 / 3600.0},
      {"m/s^2", Quantity::kAcceleration, 1.0},
      {"m/s2", Quantity::kAcceleration, 1.0},
      {"g", Quantity::kAcceleration, 9.80665},
      {"N", Quantity::kForce, 1.0},
      {"kN", Quantity::kForce, 1000.0},
      {"N*m", Quantity::kMoment, 1.0},
      {"kNm", Quantity::kMoment, 1000.0},
      {"W", Quantity::kPower, 1.0},
      {"kW", Quantity::kPower, 1000.0},
      {"MW", Quantity::kPower, 1e6},
      {"J", Quantity::kEnergy, 1.0},
      {"kJ", Quantity::kEnergy, 1000.0},
      {"MJ", Quantity::kEnergy, 1e6},
      {"kWh", Quantity::kEnergy, 3.6e6},
      {"Ns", Quantity::kImpulse, 1.0},
      {"kNs", Quantity::kImpulse, 1000.0},
      {"rpm", Quantity::kShaftSpeed, 1.0 / 60.0},
      {"rps", Quantity::kShaftSpeed, 1.0},
      {"Hz", Quantity::kShaftSpeed, 1.0},
      {"%", Quantity::kFraction, 0.01},
      {"1", Quantity::kDimensionless, 1.0},
      {"-", Quantity::kDimensionless, 1.0},
  };
  return kRequired;
}

// Accepted variants and the canonical unit each must resolve to.
const std::vector<std::pair<const char*, const char*>>& variants() {
  static const std::vector<std::pair<const char*, const char*>> kVariants{
      {"\xC2\xB0", "deg"},
      {"\xC2\xBA", "deg"},
      {"degrees", "deg"},
      {"DEG", "deg"},
      {"Deg", "deg"},
      {"radians", "rad"},
      {"\xC2\xB0/s", "deg/s"},
      {"DEG/S", "deg/s"},
      {"deg/min", "deg/min"},
      {"\xC2\xB0/min", "deg/min"},
      {"knots", "kn"},
      {"Knots", "kn"},
      {"kts", "kn"},
      {"m/s\xC2\xB2", "m/s^2"},
      {"rad/s2", "rad/s^2"},
      {"deg/s^2", "deg/s^2"},
      {"N\xC2\xB7m", "N*m"},
      {"N.m", "N*m"},
      {"Nm", "N*m"},
      {"kN*m", "kN*m"},
      {"kN m", "kN*m"},
      {"N*s", "N*s"},
      {"kN\xC2\xB7s", "kN*s"},
      {"RPM", "rpm"},
      {"rev/min", "rpm"},
      {"r/min", "rpm"},
      {"rev/s", "rps"},
      {"1/s", "rps"},
      {"HZ", "rps"},
      {"percent", "%"},
      {"sec", "s"},
      {"Wh", "Wh"},
      {"MN", "MN"},
  };
  return kVariants;
}

TEST(Units, EveryRequiredSpellingResolves) {
  for (const Expected& e : required()) {
    SCOPED_TRACE(e.spelling);
    const std::optional<Unit> unit = find_unit(e.spelling);
    ASSERT_TRUE(unit.has_value());
    EXPECT_EQ(unit->quantity, e.quantity);
    // The table and this list write the same factor, possibly as a different expression.
    EXPECT_NEAR(unit->scale, e.scale, 2 * kEps * e.scale);
    EXPECT_EQ(unit->offset, 0.0);
  }
}

TEST(Units, VariantsResolveToTheirCanonicalUnit) {
  for (const auto& [spelling, canonical] : variants()) {
    SCOPED_TRACE(spelling);
    const std::optional<Unit> unit = find_unit(spelling);
    ASSERT_TRUE(unit.has_value());
    EXPECT_EQ(unit->symbol, canonical);
    const std::optional<Unit> reference = find_unit(canonical);
    ASSERT_TRUE(reference.has_value());
    EXPECT_EQ(unit->quantity, reference->quantity);
    EXPECT_EQ(unit->scale, reference->scale);
  }
}

TEST(Units, KnownConversions) {
  // Each is one multiplication (or division) by a table constant: a few eps relative.
  EXPECT_NEAR(find_unit("kn")->to_si(1.0), 0.514444444444444, 1e-15);
  EXPECT_NEAR(find_unit("rpm")->to_si(60.0), 1.0, 2 * kEps);
  EXPECT_NEAR(find_unit("%")->to_si(50.0), 0.5, 2 * kEps);
  EXPECT_NEAR(find_unit("deg")->to_si(180.0), std::numbers::pi, 4 * kEps);
  EXPECT_NEAR(find_unit("kN")->to_si(8.13), 8130.0, 8130.0 * 2 * kEps);
  EXPECT_NEAR(find_unit("deg/min")->to_si(60.0), kDeg, 2 * kEps);
  // 10 kn in km/h is 18.52 exactly in decimal; two roundings of values ≈ 18.
  EXPECT_NEAR(find_unit("km/h")->from_si(find_unit("kn")->to_si(10.0)), 18.52, 1e-13);
}

TEST(Units, ConversionsRoundTrip) {
  for (Quantity q : all_quantities()) {
    for (const std::string& spelling : unit_spellings(q)) {
      SCOPED_TRACE(spelling);
      const std::optional<Unit> unit = find_unit(spelling);
      ASSERT_TRUE(unit.has_value());
      EXPECT_EQ(unit->quantity, q);
      for (double x : {0.0, 1.0, -37.25, 1e6}) {
        // Multiply then divide by the same factor: two roundings, 2 eps relative.
        EXPECT_NEAR(unit->from_si(unit->to_si(x)), x, 2 * kEps * std::abs(x));
      }
    }
  }
}

TEST(Units, BracketsAndSpacesAreIgnored) {
  for (const char* spelling : {"[deg]", "(deg)", "  deg ", " [ deg ] ", "( deg)"}) {
    SCOPED_TRACE(spelling);
    ASSERT_TRUE(find_unit(spelling).has_value());
    EXPECT_EQ(find_unit(spelling)->symbol, "deg");
  }
  EXPECT_EQ(find_unit("[m/s]")->symbol, "m/s");
  EXPECT_EQ(find_unit("(%)")->symbol, "%");
  EXPECT_EQ(find_unit("deg / s")->symbol, "deg/s");
  // Only one pair is stripped, and only a matched one.
  EXPECT_FALSE(find_unit("[[deg]]").has_value());
  EXPECT_FALSE(find_unit("[deg)").has_value());
  EXPECT_FALSE(find_unit("[deg").has_value());
}

TEST(Units, CaseMattersWhereItChangesTheMeaning) {
  EXPECT_EQ(find_unit("kn")->quantity, Quantity::kSpeed);
  EXPECT_EQ(find_unit("kN")->quantity, Quantity::kForce);
  EXPECT_FALSE(find_unit("KN").has_value());  // neither knots nor kilonewton: not guessed
  EXPECT_FALSE(find_unit("M").has_value());
  EXPECT_FALSE(find_unit("mW").has_value());
  EXPECT_FALSE(find_unit("S").has_value());
  EXPECT_FALSE(find_unit("n").has_value());
}

TEST(Units, CaseFoldingNeverReachesAnotherUnit) {
  // For every spelling, a case variant that is not itself a listed spelling either fails or
  // gives exactly the same unit.
  std::vector<std::string> listed;
  for (Quantity q : all_quantities()) {
    for (const std::string& s : unit_spellings(q)) listed.push_back(s);
  }
  for (const std::string& s : listed) {
    std::string upper = s;
    std::string lower = s;
    std::transform(upper.begin(), upper.end(), upper.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const std::string& v : {upper, lower}) {
      if (std::find(listed.begin(), listed.end(), v) != listed.end()) continue;
      std::string trace = s;
      trace += " -> ";
      trace += v;
      SCOPED_TRACE(trace);
      const std::optional<Unit> folded = find_unit(v);
      if (!folded) continue;
      EXPECT_EQ(folded->symbol, find_unit(s)->symbol);
      EXPECT_EQ(folded->scale, find_unit(s)->scale);
    }
  }
}

TEST(Units, UnknownSpellingsAreRejected) {
  for (const char* spelling : {"", "  ", "[]", "furlong", "m/s^3", "degC", "kgf", "kn/s", "%%"}) {
    SCOPED_TRACE(spelling);
    EXPECT_FALSE(find_unit(spelling).has_value());
  }
}

TEST(Units, SiUnitsAndNames) {
  for (Quantity q : all_quantities()) {
    const Unit& si = si_unit(q);
    EXPECT_EQ(si.quantity, q);
    EXPECT_EQ(si.scale, 1.0);
    EXPECT_EQ(si.offset, 0.0);
    SCOPED_TRACE(si.symbol);
    // The SI symbol is itself an accepted spelling with factor 1.
    ASSERT_TRUE(find_unit(si.symbol).has_value());
    EXPECT_EQ(find_unit(si.symbol)->scale, 1.0);
    EXPECT_FALSE(quantity_name(q).empty());
    EXPECT_FALSE(unit_spellings(q).empty());
  }
  EXPECT_EQ(quantity_name(Quantity::kShaftSpeed), "shaft speed");
  EXPECT_EQ(si_unit(Quantity::kShaftSpeed).symbol, "rps");
}

TEST(Units, SpellingListsContainTheRequiredSpellings) {
  for (const Expected& e : required()) {
    SCOPED_TRACE(e.spelling);
    const std::vector<std::string> list = unit_spellings(e.quantity);
    EXPECT_NE(std::find(list.begin(), list.end(), e.spelling), list.end());
  }
}

}  // namespace
}  // namespace dynpos::core
