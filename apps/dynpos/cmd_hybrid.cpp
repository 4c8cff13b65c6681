// dynpos hybrid first-order|dp [--no-jumps] [--sampled] [--seed N] [--out DIR] [--json FILE|-]:
// the chapter 5 case studies, hybrid and conventional integral action side by side
// (analysis/hybrid_case.hpp). `dynpos hybrid vessel` is in cmd_hybrid_vessel.cpp.

#include <memory>
#include <string>

#include "commands.hpp"
#include "dynpos/analysis/hybrid_case.hpp"
#include "dynpos/core/error.hpp"

namespace dynpos::cli {
namespace {

void add_case(CLI::App& parent, analysis::HybridCase study_case, const std::string& description) {
  auto opt = std::make_shared<AnalysisOptions<analysis::HybridCaseRequest>>();
  analysis::HybridCaseRequest& r = opt->request;
  r.study_case = study_case;
  const bool first_order = study_case == analysis::HybridCase::kFirstOrder;
  CLI::App* sub = parent.add_subcommand(analysis::to_string(study_case), description);
  sub->add_flag("--no-jumps", r.no_jumps, "Run only the conventional (continuous) integral action");
  sub->add_flag("--sampled", r.sampled,
                "Hybrid run with the practical jump set: the integral error estimated from a "
                "sampled, noisy state derivative (default: the ideal jump set of the theorem)");
  add_seed_option(*sub, r.seed, "Seed of the derivative noise (--sampled)");
  output_folder(sub->add_option("--out", opt->outputs.figures,
                                "Folder for the SVG plots (created if needed)"));
  add_json_option(*sub, opt->outputs.json, "Write the results as JSON to FILE, or '-' for stdout");
  sub->add_option("--lambda", r.lambda,
                  first_order ? "Jump gain lambda (default 3, (5.76))"
                              : "Jump gain lambda (default 25, (5.88))");
  sub->add_option("--dwell", r.dwell_s, "Least time between jumps [s] (default 0.1)");
  sub->add_option("--sample-period", r.sample_period_s,
                  "Derivative sampling period T_s [s] (default 0.03)");
  sub->add_option("--noise-power", r.noise_power,
                  first_order ? "Power of the derivative noise (default 0.1)"
                              : "Power of the derivative noise per DOF (default 20)");
  sub->add_option("--end-time", r.end_time_s, "Length of the run [s] (default 60)");
  if (first_order) {
    sub->add_option("--ki", r.ki, "Integral gain k_i (default 1, (5.72))");
    sub->add_flag("--solve-p", r.solve_p,
                  "Use P from the Lyapunov equation A^T P + PA = -I instead of (5.75)");
    sub->footer(
        "Thesis section 5.3.1: z' = -z + d + u with u = -9(z - z_d) - d_hat, k_i = 1, "
        "lambda = 3, epsilon = 0.3, disturbance steps +100 at 5 s and -50 at 30 s, dwell 0.1 s; "
        "sampled: T_s = 0.03 s, noise power 0.1. Plots: <case>_states.svg, "
        "<case>_lyapunov.svg.");
  } else {
    sub->add_option("--heading", r.heading_deg,
                    "Set-point heading [deg] (default 0); the jump acts in NED at any heading");
    sub->footer(
        "Thesis section 5.3.2: M = diag(450, 450, 100), K_p = diag(100, 100, 50), "
        "K_i = diag(10, 10, 5), K_d = diag(500, 500, 200), lambda = 25, epsilon1 = 1e-4, "
        "epsilon2 = 0.01, bias step (3000 N, 2000 N, 1000 N m) at 10 s, dwell 0.1 s, 60 s; "
        "sampled: T_s = 0.03 s, noise power 20. Plots: dp_position.svg, dp_velocity.svg, "
        "dp_integral.svg, dp_lyapunov.svg.");
  }
  sub->callback([opt] { write_and_print(analysis::run_hybrid_case(opt->request), opt->outputs); });
}

}  // namespace

void register_hybrid(CLI::App& app) {
  CLI::App* hybrid = app.add_subcommand(
      "hybrid", "Hybrid integral action case studies: jumps of the integral state (thesis ch. 5)");
  // Not require_subcommand(): CLI11 would then answer an unknown case with "A subcommand is
  // required"; a hidden positional catches the word and the message names it.
  hybrid->require_subcommand(0, 1);
  auto unknown = std::make_shared<std::string>();
  hybrid->add_option("case", *unknown, "The case study: first-order, dp or vessel");
  hybrid->callback([hybrid, unknown] {
    if (!hybrid->get_subcommands().empty()) return;
    throw core::InputError(
        {{}, {}, {}, "dynpos hybrid"},
        unknown->empty() ? std::string("no case given") : "unknown case '" + *unknown + "'",
        "choose one of first-order, dp, vessel (dynpos hybrid --help)");
  });
  add_case(*hybrid, analysis::HybridCase::kFirstOrder,
           "First-order system with hybrid integral action (5.3.1)");
  add_case(*hybrid, analysis::HybridCase::kDp,
           "DP vessel, backstepping with hybrid integral action (5.3.2)");
  add_hybrid_vessel(*hybrid);
}

}  // namespace dynpos::cli
