"""Start-up time of the command line against ``import linecontact``.

Run: ``python benchmarks/startup.py [--repeat 7]``.

Times, as the median over ``--repeat`` fresh processes (run in turn, so that drift of the
machine hits all three alike):

- ``python -c "import linecontact"`` (the floor: the package and NumPy/SciPy);
- ``python -m linecontact --help``;
- ``python -m linecontact normal --a-over-R 0.02 --R-over-h 100 --sigma0-over-E 0.01``
  (one point);

and prints the seconds and the ratios of the two commands to the import (target: within
1.3x). The CLI imports a subcommand's module only when that subcommand runs
(:mod:`linecontact.cli`). ``PYTHONPATH`` chooses the source tree to time.
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import time

CASES = {
    "import linecontact": [sys.executable, "-c", "import linecontact"],
    "linecontact --help": [sys.executable, "-m", "linecontact", "--help"],
    "linecontact normal (one point)": [
        sys.executable,
        "-m",
        "linecontact",
        "normal",
        "--a-over-R",
        "0.02",
        "--R-over-h",
        "100",
        "--sigma0-over-E",
        "0.01",
    ],
}


def timed(cmd: list[str]) -> float:
    """Wall time of one run of ``cmd`` (output discarded), in seconds."""
    t0 = time.perf_counter()
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    return time.perf_counter() - t0


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=7, help="runs of each (default: 7)")
    args = ap.parse_args()
    for cmd in CASES.values():  # warm the file cache and the bytecode
        timed(cmd)
    times: dict[str, list[float]] = {name: [] for name in CASES}
    for _ in range(args.repeat):
        for name, cmd in CASES.items():
            times[name].append(timed(cmd))
    base = statistics.median(times["import linecontact"])
    print(f"start-up, median of {args.repeat} runs ({sys.executable}):")
    for name, t in times.items():
        med = statistics.median(t)
        print(f"  {name:32s}: {med:6.3f} s  ({med / base:.2f}x the import)")
    print("target: the commands within 1.3x of the import")


if __name__ == "__main__":
    main()
