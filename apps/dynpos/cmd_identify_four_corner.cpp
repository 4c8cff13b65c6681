// dynpos identify four-corner: the DP 4-corner maneuver cut into legs, with duration,
// accumulated thrust and energy per thruster per leg and in total (thesis table 3.6), and the
// NE plot of the track (figure 3.5).

#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "dynpos/analysis/four_corner.hpp"
#include "log_input.hpp"

namespace dynpos::cli {
namespace {

struct FourCornerCliOptions {
  std::string segment;        ///< a name of analysis::leg_segmentation_names()
  std::vector<double> arm_m;  ///< X,Y [m]
  std::string plot;
  analysis::FourCornerRequest request;  ///< the typed options; segment and arm are added
  analysis::Outputs outputs;
};

}  // namespace

void add_identify_four_corner(CLI::App& identify) {
  auto o = std::make_shared<FourCornerCliOptions>();
  CLI::App* sub = identify.add_subcommand(
      "four-corner", "DP 4-corner: legs, durations, accumulated thrust and energy");
  add_log_options(*sub, o->request.source,
                  "time, north, east (m, any offset) or lat, lon; heading; "
                  "setpoint.north/east/heading; thrust.NAME, power.NAME");
  sub->add_option("--radius", o->request.radius_m, "Operating circle radius [m]")
      ->capture_default_str();
  sub->add_option("--heading-tol", o->request.heading_tol_deg,
                  "Operating circle heading tolerance [deg]")
      ->capture_default_str();
  o->segment = analysis::to_string(o->request.segmentation);
  sub->add_option("--segment", o->segment, "Leg segmentation: auto, setpoints or track")
      ->capture_default_str();
  sub->add_option("--arm", o->arm_m,
                  "Horizontal lever arm X,Y [m] (BODY: forward, starboard) of the antenna whose "
                  "position is logged; the position is moved to the control origin")
      ->expected(2)
      ->delimiter(',');
  sub->add_option("--from", o->request.t_from_s, "Analyse from this time [s]");
  sub->add_option("--to", o->request.t_to_s, "Analyse up to this time [s]");
  add_json_option(*sub, o->outputs.json, "Write the results as JSON to FILE, or '-' for stdout");
  output_file(sub->add_option("--plot", o->plot, "Write the NE plot of the track to FILE.svg"));
  sub->footer(
      "Legs start at each setpoint change and end when the position is within --radius and "
      "the heading within --heading-tol of the setpoint (auto, when setpoints are logged), or "
      "are the stretches of motion of the track (track). Accumulated thrust ∫|T|dt [kNs] and "
      "energy ∫P dt [kJ] per thruster; a channel that is not logged is '—' / null. Example on "
      "a virtual trial log: dynpos identify four-corner DIR/log.csv --col north=gnss1.north "
      "--col east=gnss1.east --plot ne.svg");
  sub->callback([o] {
    // The library's parser, so that a bad name reads as in the Python API: "(--segment): …".
    o->request.segmentation = analysis::parse_leg_segmentation(o->segment);
    if (!o->arm_m.empty()) o->request.arm_m = Eigen::Vector2d(o->arm_m[0], o->arm_m[1]);
    o->outputs.figures = o->plot;
    write_and_print(analysis::run_four_corner(o->request), o->outputs);
  });
}

}  // namespace dynpos::cli
