"""The Python API's overhead over the C++ engine on the 24 h identification benchmark: the same
`identify step` (287 steps, least squares) on the 216 MB CSV written by log24h_bench, timed as

  A  the command line, `dynpos identify step LOG --col input=command --col output=fast`, a whole
     process (wall clock);
  B  `dynpos.identify_step(LOG, col=...)` inside one Python process (wall clock of the call);
  C  a whole Python process that imports dynpos and makes the call (interpreter start included);

alternating A, B, C so that drift of the machine's speed hits all three alike. Prints min /
median / max of each and of the ratios B/A and C/A pair by pair.

    DYNPOS_BENCH_KEEP_CSV=1 build/release/bench/log24h_bench --benchmark_filter=BM_Day24hCsv/0
    PYTHONPATH=build/release/python python3 bench/python/api_overhead.py \\
        --bin build/release/bin/dynpos --runs 5   # the CSV in the temporary folder

Not run by the tests: it takes about a minute per run and wants a quiet machine.
"""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

import dynpos

COL = {"input": "command", "output": "fast"}


def wall(f):
    start = time.perf_counter()
    f()
    return time.perf_counter() - start


def summary(name, values, unit="s"):
    return (f"{name:<34} min {min(values):7.3f}  median {statistics.median(values):7.3f}  "
            f"max {max(values):7.3f} {unit}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("log", nargs="?", default=os.path.join(tempfile.gettempdir(),
                                                               "dynpos_bench_day_4cols.csv"))
    parser.add_argument("--bin", default="dynpos")
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()

    cli = [args.bin, "identify", "step", args.log, "--col", "input=command", "--col",
           "output=fast", "--json", os.devnull]
    script = ("import dynpos; dynpos.identify_step(%r, col=%r)" % (args.log, COL))
    env = dict(os.environ)
    a, b, c = [], [], []
    steps = None
    dynpos.identify_step(args.log, col=COL)  # warm-up: the file in the page cache
    for _ in range(args.runs):
        a.append(wall(lambda: subprocess.run(cli, check=True, stdout=subprocess.DEVNULL)))
        result = []
        b.append(wall(lambda: result.append(dynpos.identify_step(args.log, col=COL))))
        steps = len(result[0].steps)
        c.append(wall(lambda: subprocess.run([sys.executable, "-c", script], check=True,
                                             env=env)))
    print(f"{args.log}: {steps} steps, {args.runs} runs each, alternating")
    print(summary("A command line (process)", a))
    print(summary("B dynpos.identify_step (call)", b))
    print(summary("C python3 -c 'import dynpos; ...'", c))
    print(summary("B/A", [y / x for x, y in zip(a, b)], "×"))
    print(summary("C/A", [y / x for x, y in zip(a, c)], "×"))


if __name__ == "__main__":
    main()
