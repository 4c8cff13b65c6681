"""Fit a step test from a CSV log and plot the data with the fitted first-order-plus-dead-time
response (thesis (3.7)): y = y₀ + K·Δu·(1 − e^{−(t − t₀ − δ)/T}) after each step.

    python3 fit_step_plot.py [LOG.csv] [--input COLUMN] [--output COLUMN] [--out DIR]

The default log is examples/data/propeller_steps.csv: a propeller lever [%] stepping
0 → 40 → 80 → 20 % and the shaft speed [rpm] following with K = 1.5 rpm/%, T = 1.6, 2.4,
2.0 s and δ = 1.0, 1.2, 0.8 s, plus noise. Writes step_fit.png into --out (default: here).
"""

import argparse
import os

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import dynpos  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def fopdt(t, step):
    """The fitted response of one step on the times t (NaN before the step's dead time ends
    is replaced by the level before)."""
    du = step.u_after - step.u_before
    rise = 1.0 - np.exp(-np.clip(t - step.t_step - step.delay, 0.0, None) / step.T)
    return step.y_before + step.K * du * rise


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("log", nargs="?",
                        default=os.path.join(HERE, "..", "data", "propeller_steps.csv"))
    parser.add_argument("--input", default="lever_pct")
    parser.add_argument("--output", default="shaft_rpm")
    parser.add_argument("--out", default=".")
    args = parser.parse_args()

    result = dynpos.identify_step(args.log, col={"input": args.input, "output": args.output})
    log = dynpos.read_log(args.log, col={"input": args.input, "output": args.output})
    t, y = log.time, log["output"]

    fig, ax = plt.subplots(figsize=(9, 4))
    ax.plot(t, y, ".", ms=2, color="0.6", label="logged")
    for i, step in enumerate(result.steps):
        if step.status != "ok":
            continue
        window = (t >= step.t_step) & (t <= step.t_end)
        ax.plot(t[window], fopdt(t[window], step), color="C3", lw=1.5,
                label="FOPDT fit" if i == 0 else None)
        ax.annotate(f"K={step.K:.2f}\nT={step.T:.2f} s\nδ={step.delay:.2f} s",
                    (step.t_step, step.y_after), fontsize=8)
        print(f"step at {step.t_step:6.1f} s: K = {step.K:.3f}, T = {step.T:.2f} s, "
              f"δ = {step.delay:.2f} s, R² = {step.r_squared:.4f}")
    ax.set_xlabel("time [s]")
    ax.set_ylabel(f"{args.output} [{log.unit('output') or '-'}]")
    ax.legend()
    os.makedirs(args.out, exist_ok=True)
    path = os.path.join(args.out, "step_fit.png")
    fig.savefig(path, dpi=120, bbox_inches="tight")
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
