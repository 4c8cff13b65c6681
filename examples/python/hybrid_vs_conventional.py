"""Hybrid against conventional integral action (thesis chapter 5) on the virtual R/V Gunnerus
in DP when a sudden load hits: a 20 kN ice load sets in, or a mooring line holding 20 kN snaps.
Both designs see the same sea (same seed); the table gives the figures after the load.

    python3 hybrid_vs_conventional.py [--seed N] [--out DIR]

--out writes each load case's plots and JSON there.
"""

import argparse
import os

import dynpos

FIGURES = [("peak_offset_m", "peak offset [m]"), ("back_within_s", "back within 1 m [s]"),
           ("iae_m_s", "IAE [m s]"), ("energy_kJ", "energy [kJ]"), ("jumps", "jumps")]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", help="folder for the plots and JSON")
    args = parser.parse_args()

    for load in ("ice", "mooring"):
        out = os.path.join(args.out, load) if args.out else None
        r = dynpos.hybrid_vessel(load, seed=args.seed, out=out,
                                 json=os.path.join(out, "result.json") if out else None)
        print(f"\n{load}: load at {r.load_time_s:.0f} s ({r.scenario_file}, seed {r.seed})")
        print(f"{'':22} {'conventional':>13} {'hybrid':>10}")
        for key, label in FIGURES:
            a, b = r.conventional[key], r.hybrid[key]
            fmt = (lambda v: "—" if v is None else f"{v:.1f}") if key != "jumps" else str
            print(f"{label:22} {fmt(a):>13} {fmt(b):>10}")


if __name__ == "__main__":
    main()
