"""What a user would write instead of `dynpos identify step`: pandas reads the three columns,
a threshold on the command's changes finds the steps, and scipy's curve_fit (MINPACK
Levenberg-Marquardt) fits the first-order-plus-dead-time response (3.7) of each step. The
reference for the side-by-side figures in docs/performance.md; run by side_by_side.py, not by
the tests.

    python3 bench/python/identify_step_reference.py LOG.csv --input "command [1]" \\
        --output "fast [1]" [--json OUT.json]
"""

import argparse
import json
import sys
import time

import numpy as np
import pandas as pd
from scipy.optimize import curve_fit


def fopdt(t, y0, amplitude, T, delay):
    x = np.maximum(t - delay, 0.0)
    return y0 + amplitude * (1.0 - np.exp(-x / T))


def steps(u, threshold):
    """Indices where the command jumps by more than the threshold (one per jump)."""
    jumps = np.flatnonzero(np.abs(np.diff(u)) > threshold) + 1
    return jumps[np.concatenate(([True], np.diff(jumps) > 1))] if len(jumps) else jumps


def fit_step(t, u, y, i0, i1):
    tau, yy = t[i0:i1] - t[i0], y[i0:i1]
    y0 = float(np.median(y[max(0, i0 - 100):i0]))
    y_end = float(np.median(yy[-len(yy) // 10:]))
    amplitude = y_end - y0
    crossed = np.flatnonzero(np.abs(yy - y0) >= 0.632 * abs(amplitude))
    t63 = tau[crossed[0]] if len(crossed) else 0.2 * tau[-1]
    p0 = [y0, amplitude, max(0.5 * t63, 1e-2), 0.5 * t63]
    p, _ = curve_fit(fopdt, tau, yy, p0=p0, method="lm")  # MINPACK, numerical Jacobian
    du = float(u[i0] - u[i0 - 1])
    return {"t_step": float(t[i0]), "K": p[1] / du if du else None, "T": p[2], "delay": p[3]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("log")
    parser.add_argument("--time", default="time [s]")
    parser.add_argument("--input", default="command [1]")
    parser.add_argument("--output", default="fast [1]")
    parser.add_argument("--json")
    args = parser.parse_args()
    start = time.perf_counter()
    df = pd.read_csv(args.log, usecols=[args.time, args.input, args.output])
    t = df[args.time].to_numpy()
    u = df[args.input].to_numpy()
    y = df[args.output].to_numpy()
    read_s = time.perf_counter() - start
    threshold = max(10.0 * np.median(np.abs(np.diff(u))), 0.05 * (u.max() - u.min()))
    at = steps(u, threshold)
    ends = list(at[1:]) + [len(t)]
    fits = [fit_step(t, u, y, i0, i1) for i0, i1 in zip(at, ends) if i1 - i0 > 10]
    total_s = time.perf_counter() - start
    print(f"{len(fits)} steps; read {read_s:.2f} s, total {total_s:.2f} s", file=sys.stderr)
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump({"steps": fits, "read_s": read_s, "total_s": total_s}, f)


if __name__ == "__main__":
    main()
