#include "vessel_thrusters.hpp"

#include <set>

#include <fmt/format.h>

#include "dynpos/core/error.hpp"

namespace dynpos::scenario::detail {
namespace {

// Defaults scaled from the rated thrust, each with its source.
// Astern over ahead thrust of a fixed-pitch propeller: the Gunnerus propellers' bollard
// coefficients, 5.8 / 8.13 kN/rps² (table 3.2).
constexpr double kPropellerAsternRatio = 5.8 / 8.13;
// Port over starboard thrust of a tunnel thruster: the Gunnerus tunnel model's, 0.9.
constexpr double kTunnelPortRatio = 0.9;
// A rudder's side force per newton of thrust in its slipstream: the Gunnerus rudder model at
// its 30° allocation limit, 0.653.
constexpr double kRudderLiftPerThrust = 0.65;

std::optional<model::UnitType> unit_type(std::string_view name) {
  for (const model::UnitType t : {model::UnitType::kAzimuth, model::UnitType::kTunnel,
                                  model::UnitType::kPropeller, model::UnitType::kPropellerRudder}) {
    if (model::unit_type_name(t) == name) return t;
  }
  return std::nullopt;
}

// What a key of pairs of numbers says when it is wrong: its hint, and the problems of an
// array that is not one (or is empty), of an item that is not a pair and of a pair not of
// numbers.
struct PairWords {
  const char* hint;
  const char* not_an_array;
  const char* not_a_pair;
  const char* not_numbers;
};

// key = [[a, b], …]: the pairs, none when the key is absent; an error at the key otherwise.
std::vector<std::pair<double, double>> read_pairs(const TomlTable& t, const char* key,
                                                  const PairWords& words, bool may_be_empty) {
  std::vector<std::pair<double, double>> out;
  const toml::node* node = t.raw().get(key);
  if (node == nullptr) return out;
  const auto bad = [&](const char* what) {
    throw core::InputError(t.where(key), what, words.hint);
  };
  const toml::array* items = node->as_array();
  if (items == nullptr || (!may_be_empty && items->empty())) bad(words.not_an_array);
  for (const toml::node& item : *items) {
    const toml::array* pair = item.as_array();
    if (pair == nullptr || pair->size() != 2) bad(words.not_a_pair);
    const std::optional<double> a = (*pair)[0].value<double>();
    const std::optional<double> b = (*pair)[1].value<double>();
    if (!a || !b) bad(words.not_numbers);
    out.emplace_back(*a, *b);
  }
  return out;
}

// loss = [[angle_deg, factor], …]: angles in [0, 360) increasing, factors in [0, 1]; the
// unit's validate() checks the rules.
std::vector<model::LossPoint> read_loss(const TomlTable& t) {
  const PairWords words{
      "write loss = [[angle_deg, factor], …], angles in [0, 360) clockwise "
      "from ahead in increasing order, factors in [0, 1], e.g. "
      "[[0.0, 1.0], [80.0, 1.0], [90.0, 0.6], [100.0, 1.0]]",
      "expected a non-empty array of [angle, factor]", "each point is a pair [angle_deg, factor]",
      "a point's angle and factor are numbers"};
  std::vector<model::LossPoint> out;
  for (const auto& [angle, factor] : read_pairs(t, "loss", words, false)) {
    out.push_back({angle, factor});
  }
  return out;
}

// forbidden_deg = [[from, to], …], each in [0, 360).
std::vector<model::AngleSector> read_sectors(const TomlTable& t) {
  const PairWords words{
      "write forbidden_deg = [[from, to], …], degrees in [0, 360) clockwise "
      "from ahead, e.g. [[250.0, 290.0]]",
      "expected an array of [from, to] pairs", "each sector is a pair [from, to]",
      "a sector's ends are numbers"};
  std::vector<model::AngleSector> out;
  for (const auto& [from, to] : read_pairs(t, "forbidden_deg", words, true)) {
    const auto bad = [&](const std::string& what) {
      throw core::InputError(t.where("forbidden_deg"), what, words.hint);
    };
    if (from < 0.0 || from >= 360.0 || to < 0.0 || to >= 360.0) {
      bad(fmt::format("the sector [{}, {}] leaves [0, 360)", from, to));
    }
    if (from == to) bad(fmt::format("the sector [{}, {}] is empty", from, to));
    out.push_back({from, to});
  }
  return out;
}

model::ThrusterUnit read_unit(const TomlTable& t) {
  t.reject_unknown({"name", "type", "x_m", "y_m", "max_thrust_N", "max_reverse_thrust_N",
                    "forbidden_deg", "rate_deg_per_s", "loss", "group", "weight",
                    "rudder_lift_per_thrust", "rudder_lift_at_zero_N", "rudder_max_force_N",
                    "rudder_x_m", "time_constant_s", "dead_time_s", "thrust_rate_N_per_s"});
  model::ThrusterUnit u;
  u.name = t.string("name");
  if (u.name.empty()) throw core::InputError(t.where("name"), "a unit's name is empty");
  if (u.name == "none" || u.name == "worst" || u.name.rfind("group:", 0) == 0) {
    throw core::InputError(t.where("name"),
                           fmt::format("'{}' is a failure case's name, not a unit's", u.name),
                           "none, worst and group:… name the cases of --failure");
  }
  const std::string type = t.string("type");
  const std::optional<model::UnitType> parsed = unit_type(type);
  if (!parsed) {
    throw core::InputError(t.where("type"), fmt::format("unknown thruster type '{}'", type),
                           "use azimuth, tunnel, propeller or propeller_rudder");
  }
  u.type = *parsed;
  const auto only_for = [&](std::string_view key, model::UnitType allowed) {
    if (t.has(key) && u.type != allowed) {
      throw core::InputError(t.where(key), fmt::format("the {} unit has no {}", type, key),
                             fmt::format("only a {} takes it", model::unit_type_name(allowed)));
    }
  };
  for (const char* key : {"forbidden_deg", "rate_deg_per_s", "loss"}) {
    only_for(key, model::UnitType::kAzimuth);
  }
  for (const char* key :
       {"rudder_lift_per_thrust", "rudder_lift_at_zero_N", "rudder_max_force_N", "rudder_x_m"}) {
    only_for(key, model::UnitType::kPropellerRudder);
  }
  u.x_m = t.number({"x_m", "m", -500.0, 500.0});
  u.y_m = t.number({"y_m", "m", -100.0, 100.0});
  u.max_thrust_N = t.number({"max_thrust_N", "N", 0.0, 1e8, true});
  const double reverse = u.type == model::UnitType::kTunnel    ? kTunnelPortRatio
                         : u.type == model::UnitType::kAzimuth ? 0.0
                                                               : kPropellerAsternRatio;
  u.max_reverse_thrust_N =
      t.number_or(reverse * u.max_thrust_N, {"max_reverse_thrust_N", "N", 0.0, 1e8});
  u.forbidden_deg = read_sectors(t);
  u.loss = read_loss(t);
  u.rate_deg_per_s = t.number_or(u.rate_deg_per_s, {"rate_deg_per_s", "deg/s", 0.0, 360.0, true});
  if (t.has("time_constant_s")) {
    u.time_constant_s = t.number({"time_constant_s", "s", 0.0, 60.0, true});
  }
  u.dead_time_s = t.number_or(u.dead_time_s, {"dead_time_s", "s", 0.0, 10.0});
  if (t.has("thrust_rate_N_per_s")) {
    u.thrust_rate_N_per_s = t.number({"thrust_rate_N_per_s", "N/s", 0.0, 1e9, true});
  }
  u.group = t.string_or("group", "");
  u.weight = t.number_or(u.weight, {"weight", "1", 0.0, 100.0, true});
  if (u.type == model::UnitType::kPropellerRudder) {
    u.rudder_lift_per_thrust =
        t.number_or(kRudderLiftPerThrust, {"rudder_lift_per_thrust", "1", 0.0, 2.0});
    u.rudder_lift_at_zero_N = t.number_or(0.0, {"rudder_lift_at_zero_N", "N", 0.0, 1e8});
    u.rudder_max_force_N = t.number_or(0.0, {"rudder_max_force_N", "N", 0.0, 1e8});
    if (t.has("rudder_x_m")) u.rudder_x_m = t.number({"rudder_x_m", "m", -500.0, 500.0});
  }
  try {
    u.validate();
  } catch (const core::InputError& e) {  // e.g. sectors that forbid every direction
    const bool loss = e.where().column_name.find(".loss") != std::string::npos;
    throw core::InputError(t.where(loss ? "loss" : "forbidden_deg"), e.problem(), e.hint());
  }
  return u;
}

}  // namespace

std::vector<model::ThrusterUnit> read_thruster_units(const toml::table& doc,
                                                     const TomlTable& root) {
  std::vector<model::ThrusterUnit> out;
  const toml::node* node = doc.get("thruster");
  if (node == nullptr) return out;
  const toml::array* rows = node->as_array();
  if (rows == nullptr || !rows->is_array_of_tables()) {
    throw core::InputError(root.where("thruster"), "expected an array of tables",
                           "write each unit as a [[thruster]] table");
  }
  std::set<std::string> names;
  for (std::size_t i = 0; i < rows->size(); ++i) {
    const TomlTable t(*(*rows)[i].as_table(), root.file(), fmt::format("thruster[{}]", i + 1));
    model::ThrusterUnit u = read_unit(t);
    if (!names.insert(u.name).second) {
      throw core::InputError(t.where("name"), fmt::format("a second unit named '{}'", u.name),
                             "give every unit its own name");
    }
    out.push_back(std::move(u));
  }
  return out;
}

}  // namespace dynpos::scenario::detail
