"""Reading 3 of the 12 columns of the wide benchmark log with pandas (`usecols`), the reference
for csv_read_bench's figures in docs/performance.md. Prints the wall time and MB/s of the file.

    DYNPOS_BENCH_KEEP_CSV=1 build/release/bench/csv_read_bench   # writes the file once
    python3 bench/python/read_columns_reference.py [FILE] [--runs 3]
"""

import argparse
import os
import statistics
import tempfile
import time

import pandas as pd


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("file", nargs="?", default=os.path.join(tempfile.gettempdir(),
                                                                "dynpos_bench_wide_12cols.csv"))
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    size_mb = os.path.getsize(args.file) / 1e6
    times = []
    for _ in range(args.runs):
        start = time.perf_counter()
        df = pd.read_csv(args.file, usecols=["time [s]", "sensor3 [1]", "sensor8 [1]"])
        times.append(time.perf_counter() - start)
        rows = len(df)
        del df
    print(f"pandas usecols, {rows} rows, {size_mb:.0f} MB: "
          f"min {min(times):.2f} / median {statistics.median(times):.2f} / "
          f"max {max(times):.2f} s; {size_mb / statistics.median(times):.0f} MB/s (median)")


if __name__ == "__main__":
    main()
