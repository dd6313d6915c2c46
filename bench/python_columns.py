"""How long a 10^6-row sweep result takes to reach pandas, beyond the sweep itself.

A real sweep over a rendered trace (builtin:bunny, 128x128) gives 480 rows; its rows are repeated
to 10^6 and then timed through the two steps a user pays after the sweep: the conversion to
numpy columns (rastrace.Columns, the C++ side) and the DataFrame: pandas.DataFrame(columns), which
copies the columns into one block per dtype, or Columns.to_pandas() = DataFrame(columns,
copy=False), which keeps the arrays. Best of 7 runs, wall and CPU time.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_columns.py
"""

import pathlib
import sys
import tempfile
import time

import pandas as pd

import rastrace
from rastrace import _rastrace

ROWS = 1_000_000
SPEC = "size=1KiB..64KiB,line=16B/32B/64B/128B,assoc=1/2/4/full,policy=fifo/lru/random,layout=linear/morton"


def best(function, runs=7):
    """The fastest of `runs` calls: (wall seconds, CPU seconds of this process, result). On a
    loaded machine the CPU time is the better estimate of the work."""
    times = []
    for _ in range(runs):
        wall, cpu = time.perf_counter(), time.process_time()
        result = function()
        times.append((time.perf_counter() - wall, time.process_time() - cpu))
    wall, cpu = min(times)
    return wall, min(t[1] for t in times), result


def main():
    with tempfile.TemporaryDirectory() as folder:
        trace = str(pathlib.Path(folder) / "bunny.rtrace")
        rastrace.render("builtin:bunny", trace=trace, size="128x128")
        one = _rastrace._sweep_rows(trace, SPEC, 1)
        repeat = -(-ROWS // len(one))
        rows = _rastrace._sweep_rows(trace, SPEC, repeat)
    convert = best(rows.columns)
    columns = convert[2]
    frame = best(lambda: pd.DataFrame(columns))
    no_copy = best(lambda: pd.DataFrame(columns, copy=False))
    both = best(lambda: rows.columns().to_pandas())
    print(f"python {sys.version.split()[0]}, pandas {pd.__version__}")
    print(f"rows: {len(rows)} ({len(one)} swept, repeated {repeat} times), columns: {len(columns)}")
    for name, (wall, cpu, _) in (("columns()", convert), ("pandas.DataFrame()", frame),
                                ("DataFrame(copy=False)", no_copy), ("columns().to_pandas()", both)):
        print(f"{name:20s} {wall * 1e3:8.1f} ms wall {cpu * 1e3:8.1f} ms CPU")


if __name__ == "__main__":
    main()
