"""Thesis table 3.23 from a virtual sea trial: the surge step tests at forward speed, the
starboard propeller's shaft speed and thrust time constants and delays, identified from the
trial's log and set beside the simulator's truth and the thesis' values (R/V Gunnerus, 2014).

    python3 thesis_table.py [--seed N] [--out DIR]

--out keeps the run's files and writes the table as table_3_23.csv.
"""

import argparse
import csv
import os

import dynpos

# Thesis table 3.23: lever step [%] → T_n, δ_n, T_thrust, δ_thrust [s].
THESIS = {(0, 80): (5.5, 2.9, 4.7, 5.6), (25, 40): (1.1, 2.0, 2.2, 1.5),
          (15, 25): (1.0, 1.9, 1.4, 1.8), (10, 15): (1.4, 11.6, 0.3, 12.7)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", help="keep the run and write the table here")
    args = parser.parse_args()

    run = dynpos.simulate("surge-steps-forward", seed=args.seed,
                          out=os.path.join(args.out, "run") if args.out else None)
    lever = {c["t_s"]: c["surge_pct"] for c in run.truth["commands"]}
    truth = {s["t_s"]: s for s in run.truth["propeller_steps"] if s["thruster"] == "stb"}
    # The joystick demand is logged as a fraction; the small steps need a small threshold.
    fits = {name: dynpos.identify_step(run.log, col={"input": "command.surge", "output": name},
                                       min_step=0.001).steps
            for name in ("rpm.stb", "thrust.stb")}

    rows = []
    previous = 0
    for shaft, thrust in zip(fits["rpm.stb"], fits["thrust.stb"]):
        t = shaft.t_step
        step = (previous, lever[t])
        previous = lever[t]
        true = truth[t]
        rows.append({"step_pct": f"{step[0]:g}-{step[1]:g}", "t_s": t,
                     "T_n": shaft.T, "delay_n": shaft.delay,
                     "T_thrust": thrust.T, "delay_thrust": thrust.delay,
                     "true_T_n": true["shaft_speed"]["T_s"],
                     "true_delay_n": true["shaft_speed"]["delay_s"],
                     "thesis": THESIS.get(step)})

    print(f"Table 3.23 (virtual trial, seed {args.seed}): starboard propeller, times in s")
    print(f"{'step %':>8} {'T_n':>6} {'δ_n':>6} {'T_thr':>6} {'δ_thr':>6}   "
          f"{'true T_n':>8} {'true δ_n':>8}   thesis T_n/δ_n/T_thr/δ_thr")
    for r in rows:
        thesis = "/".join(f"{v:.1f}" for v in r["thesis"]) if r["thesis"] else "—"
        print(f"{r['step_pct']:>8} {r['T_n']:6.2f} {r['delay_n']:6.2f} {r['T_thrust']:6.2f} "
              f"{r['delay_thrust']:6.2f}   {r['true_T_n']:8.2f} {r['true_delay_n']:8.2f}   "
              f"{thesis}")
    if args.out:
        path = os.path.join(args.out, "table_3_23.csv")
        with open(path, "w", newline="", encoding="utf-8") as f:
            writer = csv.DictWriter(f, fieldnames=[k for k in rows[0] if k != "thesis"],
                                    extrasaction="ignore")
            writer.writeheader()
            writer.writerows(rows)
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
