#include "dynpos/scenario/trial_truth.hpp"

#include <fstream>
#include <limits>
#include <string_view>
#include <utility>

#include "dynpos/core/error.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/io/text_file.hpp"

namespace dynpos::scenario {
namespace {

using nlohmann::json;

// Fixed texts of the file: how to read its units, and the jump rule of the hybrid block.
constexpr const char* kUnits = "SI unless a key names its unit";
constexpr const char* kHybridRule = "practical (5.64)-(5.67), b_hat += Lambda R(psi) x2";
constexpr const char* kHint =
    "truth.json is written by a virtual sea trial (dynpos simulate); write it again with this "
    "version";

json vector_json(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

json fopdt_json(const model::FopdtTruth& f) {
  return {{"T_s", f.time_constant}, {"delay_s", f.dead_time}};
}

json nomoto_json(const NomotoTruth& n) {
  return {{"T1_s", n.T1_s}, {"T2_s", n.T2_s}, {"T3_s", n.T3_s}, {"Tr_s", n.Tr_s}};
}

json scenario_json(const TrialScenario& s) {
  json j;
  j["name"] = s.name;
  j["description"] = s.description;
  j["duration_s"] = s.duration_s;
  j["dt_s"] = s.dt_s;
  j["log_rate_hz"] = s.log_rate_hz;
  j["initial_heading_deg"] = s.initial_heading_deg;
  j["initial_surge_mps"] = s.initial_surge_mps;
  j["settle_s"] = s.settle_s;
  j["start_utc"] = s.start_utc;
  j["rudder"] = json::array();
  for (const RudderCommand& r : s.rudder) {
    j["rudder"].push_back({{"t_s", r.t_s},
                           {"angle_deg", r.release ? json(nullptr) : json(r.angle_deg)},
                           {"release", r.release}});
  }
  j["loads"] = json::array();
  for (const LoadEvent& e : s.loads) {
    j["loads"].push_back({{"t_on_s", e.t_on_s},
                          {"t_off_s", e.t_off_s < 1e299 ? json(e.t_off_s) : nullptr},
                          {"north_N", e.north_N},
                          {"east_N", e.east_N},
                          {"yaw_Nm", e.yaw_Nm}});
  }
  const EnvironmentSpec& e = s.environment;
  j["environment"] = {{"current_speed_mps", e.current_speed_mps},
                      {"current_to_deg", e.current_to_deg},
                      {"wind_speed_mps", e.wind_speed_mps},
                      {"wind_from_deg", e.wind_from_deg},
                      {"hs_m", e.hs_m},
                      {"tp_s", e.tp_s},
                      {"wave_from_deg", e.wave_from_deg},
                      {"wave_components", e.wave_components}};
  return j;
}

json command_json(const CommandTruth& c) {
  return {{"t_s", c.t_s},
          {"surge_pct", c.surge_pct},
          {"sway_pct", c.sway_pct},
          {"yaw_pct", c.yaw_pct},
          {"demand_surge_N", c.demand_surge_N},
          {"demand_sway_N", c.demand_sway_N},
          {"demand_yaw_Nm", c.demand_yaw_Nm},
          {"n_port_rps", c.n_port_rps},
          {"n_stb_rps", c.n_stb_rps},
          {"rudder_port_deg", c.rudder_port_deg},
          {"rudder_stb_deg", c.rudder_stb_deg},
          {"n_tunnel_rps", c.n_tunnel_rps},
          {"tau_unmet", vector_json(c.tau_unmet)}};
}

json propeller_step_json(const PropellerStepTruth& s) {
  return {{"t_s", s.t_s},
          {"thruster", s.thruster},
          {"n_from_rps", s.n_from_rps},
          {"n_to_rps", s.n_to_rps},
          {"shaft_speed", fopdt_json(s.shaft_speed)},
          {"thrust", fopdt_json(s.thrust)}};
}

json rudder_step_json(const RudderStepTruth& s) {
  json j = {{"t_s", s.t_s},
            {"from_deg", s.from_deg},
            {"to_deg", s.to_deg},
            {"surge_mps", s.surge_mps},
            {"servo", fopdt_json(s.servo)}};
  if (s.nomoto) j["nomoto"] = nomoto_json(*s.nomoto);
  return j;
}

json setpoint_json(const SetpointTruth& s) {
  json j = {{"name", s.name},
            {"t_start_s", s.t_start_s},
            {"north_m", s.north_m},
            {"east_m", s.east_m},
            {"heading_deg", s.heading_deg}};
  if (s.t_end_s) j["t_end_s"] = *s.t_end_s;
  if (s.t_reached_s) j["t_reached_s"] = *s.t_reached_s;
  return j;
}

json hybrid_json(const HybridTruth& h) {
  const hybrid::IntegralJumpParams& p = h.params;
  return {{"rule", kHybridRule},
          {"lambda", vector_json(p.lambda)},
          {"epsilon1", p.epsilon1},
          {"epsilon2", p.epsilon2},
          {"sigma", p.sigma},
          {"dwell_s", p.dwell_s},
          {"jump_times_s", h.jump_times_s}};
}

template <class T, class F>
json array_json(const std::vector<T>& items, F item_json) {
  json out = json::array();
  for (const T& item : items) out.push_back(item_json(item));
  return out;
}

// A value of the document being read and its key path, for messages naming file and key.
class Field {
 public:
  Field(const json& value, const std::string& file, std::string key)
      : value_(value), file_(file), key_(std::move(key)) {}

  Field operator[](const char* name) const {
    if (!value_.is_object()) fail("is not an object");
    const auto it = value_.find(name);
    const std::string key = key_.empty() ? name : key_ + "." + name;
    if (it == value_.end()) Field(value_, file_, key).fail("is missing");
    return {*it, file_, key};
  }
  bool has(const char* name) const { return value_.is_object() && value_.contains(name); }
  bool is_null() const { return value_.is_null(); }

  std::vector<Field> items() const {
    if (!value_.is_array()) fail("is not an array");
    std::vector<Field> out;
    for (std::size_t i = 0; i < value_.size(); ++i) {
      out.emplace_back(value_[i], file_, key_ + "[" + std::to_string(i) + "]");
    }
    return out;
  }
  // A number; null is a missing number (NaN), as the writer writes NaN.
  double number() const {
    if (value_.is_null()) return std::numeric_limits<double>::quiet_NaN();
    if (!value_.is_number()) fail("is not a number");
    return value_.get<double>();
  }
  // A number that may be absent: a missing key or null (e.g. a failure's recovery_s, "never").
  std::optional<double> optional_number(const char* name) const {
    if (!has(name) || (*this)[name].is_null()) return std::nullopt;
    return (*this)[name].number();
  }
  std::string string() const {
    if (!value_.is_string()) fail("is not a string");
    return value_.get<std::string>();
  }
  bool boolean() const {
    if (!value_.is_boolean()) fail("is not true or false");
    return value_.get<bool>();
  }
  template <class Int>
  Int integer() const {
    if (!value_.is_number_integer()) fail("is not an integer");
    if (std::is_unsigned_v<Int> && !value_.is_number_unsigned()) fail("is negative");
    return value_.get<Int>();
  }
  Eigen::Vector3d vector3() const {
    const std::vector<Field> v = items();
    if (v.size() != 3) fail("does not have 3 numbers");
    return {v[0].number(), v[1].number(), v[2].number()};
  }
  const json& value() const { return value_; }
  [[noreturn]] void fail(const std::string& problem) const {
    throw core::InputError({file_, {}, {}, key_}, "truth.json value " + problem, kHint);
  }

 private:
  const json& value_;
  const std::string& file_;
  std::string key_;
};

model::FopdtTruth read_fopdt(const Field& f) { return {f["T_s"].number(), f["delay_s"].number()}; }

NomotoTruth read_nomoto(const Field& f) {
  return {f["T1_s"].number(), f["T2_s"].number(), f["T3_s"].number(), f["Tr_s"].number()};
}

TrialScenario read_scenario(const Field& f) {
  TrialScenario s;
  s.name = f["name"].string();
  s.description = f["description"].string();
  s.duration_s = f["duration_s"].number();
  s.dt_s = f["dt_s"].number();
  s.log_rate_hz = f["log_rate_hz"].number();
  s.initial_heading_deg = f["initial_heading_deg"].number();
  s.initial_surge_mps = f["initial_surge_mps"].number();
  s.settle_s = f["settle_s"].number();
  s.start_utc = f["start_utc"].string();
  for (const Field& r : f["rudder"].items()) {
    RudderCommand c;
    c.t_s = r["t_s"].number();
    c.release = r["release"].boolean();
    if (!c.release) c.angle_deg = r["angle_deg"].number();
    s.rudder.push_back(c);
  }
  for (const Field& l : f["loads"].items()) {
    LoadEvent e;
    e.t_on_s = l["t_on_s"].number();
    if (!l["t_off_s"].is_null()) e.t_off_s = l["t_off_s"].number();
    e.north_N = l["north_N"].number();
    e.east_N = l["east_N"].number();
    e.yaw_Nm = l["yaw_Nm"].number();
    s.loads.push_back(e);
  }
  const Field env = f["environment"];
  EnvironmentSpec& e = s.environment;
  e.current_speed_mps = env["current_speed_mps"].number();
  e.current_to_deg = env["current_to_deg"].number();
  e.wind_speed_mps = env["wind_speed_mps"].number();
  e.wind_from_deg = env["wind_from_deg"].number();
  e.hs_m = env["hs_m"].number();
  e.tp_s = env["tp_s"].number();
  e.wave_from_deg = env["wave_from_deg"].number();
  e.wave_components = env["wave_components"].integer<int>();
  return s;
}

CommandTruth read_command(const Field& f) {
  CommandTruth c;
  c.t_s = f["t_s"].number();
  c.surge_pct = f["surge_pct"].number();
  c.sway_pct = f["sway_pct"].number();
  c.yaw_pct = f["yaw_pct"].number();
  c.demand_surge_N = f["demand_surge_N"].number();
  c.demand_sway_N = f["demand_sway_N"].number();
  c.demand_yaw_Nm = f["demand_yaw_Nm"].number();
  c.n_port_rps = f["n_port_rps"].number();
  c.n_stb_rps = f["n_stb_rps"].number();
  c.rudder_port_deg = f["rudder_port_deg"].number();
  c.rudder_stb_deg = f["rudder_stb_deg"].number();
  c.n_tunnel_rps = f["n_tunnel_rps"].number();
  c.tau_unmet = f["tau_unmet"].vector3();
  return c;
}

PropellerStepTruth read_propeller_step(const Field& f) {
  PropellerStepTruth s;
  s.t_s = f["t_s"].number();
  s.thruster = f["thruster"].string();
  s.n_from_rps = f["n_from_rps"].number();
  s.n_to_rps = f["n_to_rps"].number();
  s.shaft_speed = read_fopdt(f["shaft_speed"]);
  s.thrust = read_fopdt(f["thrust"]);
  return s;
}

RudderStepTruth read_rudder_step(const Field& f) {
  RudderStepTruth s;
  s.t_s = f["t_s"].number();
  s.from_deg = f["from_deg"].number();
  s.to_deg = f["to_deg"].number();
  s.surge_mps = f["surge_mps"].number();
  s.servo = read_fopdt(f["servo"]);
  if (f.has("nomoto")) s.nomoto = read_nomoto(f["nomoto"]);
  return s;
}

SetpointTruth read_setpoint(const Field& f) {
  SetpointTruth s;
  s.name = f["name"].string();
  s.t_start_s = f["t_start_s"].number();
  s.north_m = f["north_m"].number();
  s.east_m = f["east_m"].number();
  s.heading_deg = f["heading_deg"].number();
  s.t_end_s = f.optional_number("t_end_s");
  s.t_reached_s = f.optional_number("t_reached_s");
  return s;
}

HybridTruth read_hybrid(const Field& f) {
  HybridTruth h;
  h.params.lambda = f["lambda"].vector3();
  h.params.epsilon1 = f["epsilon1"].number();
  h.params.epsilon2 = f["epsilon2"].number();
  h.params.sigma = f["sigma"].number();
  h.params.dwell_s = f["dwell_s"].number();
  for (const Field& t : f["jump_times_s"].items()) h.jump_times_s.push_back(t.number());
  return h;
}

json failure_json(const FailureTruth& f) {
  const auto optional = [](const std::optional<double>& v) { return v ? json(*v) : json(); };
  return {{"time_s", f.time_s},
          {"unit", f.unit},
          {"units", f.units},
          {"footprint_m", f.footprint_m},
          {"peak_excursion_m", f.peak_excursion_m},
          {"time_to_peak_s", f.time_to_peak_s},
          {"recovery_s", optional(f.recovery_s)},
          {"peak_heading_deg", f.peak_heading_deg}};
}

FailureTruth read_failure(const Field& f) {
  FailureTruth out;
  out.time_s = f["time_s"].number();
  out.unit = f["unit"].string();
  for (const Field& u : f["units"].items()) out.units.push_back(u.string());
  out.footprint_m = f.optional_number("footprint_m").value_or(core::kMissing);
  out.peak_excursion_m = f.optional_number("peak_excursion_m").value_or(core::kMissing);
  out.time_to_peak_s = f.optional_number("time_to_peak_s").value_or(core::kMissing);
  // null: not back within the footprint before the run ended.
  out.recovery_s = f.optional_number("recovery_s");
  out.peak_heading_deg = f.optional_number("peak_heading_deg").value_or(core::kMissing);
  return out;
}

template <class T, class F>
std::vector<T> read_array(const Field& f, F read_item) {
  std::vector<T> out;
  for (const Field& item : f.items()) out.push_back(read_item(item));
  return out;
}

}  // namespace

TrialScenario trial_scenario(const ScenarioSpec& spec) {
  TrialScenario s;
  s.name = spec.name;
  s.description = spec.description;
  s.duration_s = spec.duration_s;
  s.dt_s = spec.dt_s;
  s.log_rate_hz = spec.log_rate_hz;
  s.initial_heading_deg = spec.initial_heading_deg;
  s.initial_surge_mps = spec.initial_surge_mps;
  s.settle_s = spec.settle_s;
  s.start_utc = spec.start_utc;
  s.rudder = spec.rudder;
  s.loads = spec.loads;
  s.environment = spec.environment;
  return s;
}

NomotoTruth nomoto_truth(const model::Hull::Nomoto& n) { return {n.t1_s, n.t2_s, n.t3_s, n.tr_s}; }

json to_json(const TrialTruth& truth) {
  json j;
  j["seed"] = truth.seed;
  j["scenario"] = scenario_json(truth.scenario);
  j["vessel"] = truth.vessel;
  j["commands"] = array_json(truth.commands, command_json);
  j["propeller_steps"] = array_json(truth.propeller_steps, propeller_step_json);
  j["rudder_steps"] = array_json(truth.rudder_steps, rudder_step_json);
  j["setpoints"] = array_json(truth.setpoints, setpoint_json);
  if (truth.hybrid) j["hybrid"] = hybrid_json(*truth.hybrid);
  if (truth.failure) j["failure"] = failure_json(*truth.failure);
  if (truth.observer != "ideal") j["observer"] = truth.observer;
  j["lever_arms"] = json::object();
  for (const auto& [name, arm_b] : truth.lever_arms) j["lever_arms"][name] = vector_json(arm_b);
  j["mru_acceleration"] = sensors::to_string(truth.mru_acceleration);
  const TimeConstantsTruth& tc = truth.time_constants;
  j["time_constants"] = {{"nomoto_3kn", nomoto_json(tc.nomoto_3kn)},
                         {"nomoto_6kn", nomoto_json(tc.nomoto_6kn)},
                         {"rudder_0_to_20deg", fopdt_json(tc.rudder_0_to_20deg)}};
  j["allocation_unmet_max"] = vector_json(truth.allocation_unmet_max);
  j["units"] = kUnits;
  j["start_utc"] = truth.start_utc;
  return j;
}

TrialTruth from_json(const json& doc, const std::string& file) {
  const Field root(doc, file, "");
  TrialTruth t;
  t.seed = root["seed"].integer<std::uint64_t>();
  t.scenario = read_scenario(root["scenario"]);
  t.vessel = root["vessel"].value();
  t.commands = read_array<CommandTruth>(root["commands"], read_command);
  t.propeller_steps = read_array<PropellerStepTruth>(root["propeller_steps"], read_propeller_step);
  t.rudder_steps = read_array<RudderStepTruth>(root["rudder_steps"], read_rudder_step);
  t.setpoints = read_array<SetpointTruth>(root["setpoints"], read_setpoint);
  if (root.has("hybrid")) t.hybrid = read_hybrid(root["hybrid"]);
  if (root.has("failure")) t.failure = read_failure(root["failure"]);
  if (root.has("observer")) t.observer = root["observer"].string();
  const Field arms = root["lever_arms"];
  if (!arms.value().is_object()) arms.fail("is not an object");
  for (const auto& [name, value] : arms.value().items()) {
    t.lever_arms[name] = arms[name.c_str()].vector3();
  }
  const Field convention = root["mru_acceleration"];
  const std::optional<sensors::AccelerationConvention> c =
      sensors::parse_acceleration_convention(convention.string());
  if (!c) convention.fail("is not \"kinematic\" or \"specific-force\"");
  t.mru_acceleration = *c;
  const Field tc = root["time_constants"];
  t.time_constants.nomoto_3kn = read_nomoto(tc["nomoto_3kn"]);
  t.time_constants.nomoto_6kn = read_nomoto(tc["nomoto_6kn"]);
  t.time_constants.rudder_0_to_20deg = read_fopdt(tc["rudder_0_to_20deg"]);
  t.allocation_unmet_max = root["allocation_unmet_max"].vector3();
  t.start_utc = root["start_utc"].string();
  return t;
}

void write_trial_truth(const TrialTruth& truth, const std::filesystem::path& path) {
  io::write_json(path, to_json(truth));
}

TrialTruth read_trial_truth(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw core::InputError({file, {}, {}, {}}, "cannot open the truth file", kHint);
  const json doc = json::parse(io::read_capped(in, path, io::kMaxJsonBytes, kHint), nullptr, false);
  if (doc.is_discarded()) throw core::InputError({file, {}, {}, {}}, "not valid JSON", kHint);
  return from_json(doc, file);
}

}  // namespace dynpos::scenario
