"""The side-by-side figures of docs/performance.md: `dynpos identify step` on the 24 h benchmark
log against the pandas + scipy script a user would write instead (identify_step_reference.py),
each a whole process, run in turn so that drift of the machine's speed hits both alike. Prints
wall time and peak memory (min / median / max) of each and the paired ratio reference/dynpos.

    DYNPOS_BENCH_KEEP_CSV=1 build/release/bench/log24h_bench --benchmark_filter=BM_Day24hCsv/0
    python3 bench/python/side_by_side.py --bin build/release/bin/dynpos --runs 5 [--jobs 1]

Not run by the tests: a run takes about 20 s and wants a quiet machine.
"""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def run(command):
    """Wall time [s] and peak resident memory [MB] of one whole process."""
    start = time.perf_counter()
    child = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - start
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"failed: {' '.join(command)}")
    return wall, usage.ru_maxrss / 1024.0


def line(name, values, unit):
    return (f"{name:<28} min {min(values):8.2f}  median {statistics.median(values):8.2f}  "
            f"max {max(values):8.2f} {unit}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("log", nargs="?", default=os.path.join(tempfile.gettempdir(),
                                                               "dynpos_bench_day_4cols.csv"))
    parser.add_argument("--bin", default="dynpos")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--jobs", type=int, default=0, help="dynpos --jobs (0: every core)")
    args = parser.parse_args()
    out = os.path.join(tempfile.gettempdir(), "dynpos_side_by_side.json")
    dynpos = [args.bin, "identify", "step", args.log, "--col", "input=command", "--col",
              "output=fast", "--jobs", str(args.jobs), "--json", out]
    reference = [sys.executable, os.path.join(HERE, "identify_step_reference.py"), args.log]
    run(dynpos)  # warm-up: the file in the page cache
    a, b = [], []
    for _ in range(args.runs):
        a.append(run(dynpos))
        b.append(run(reference))
    print(line("dynpos identify step", [w for w, _ in a], "s"))
    print(line("pandas + scipy", [w for w, _ in b], "s"))
    print(line("ratio (pandas+scipy)/dynpos", [y[0] / x[0] for x, y in zip(a, b)], "x"))
    print(line("dynpos peak memory", [m for _, m in a], "MB"))
    print(line("pandas + scipy peak memory", [m for _, m in b], "MB"))


if __name__ == "__main__":
    main()
