"""Benchmark of the command line: a 200,000-point run against a plain NumPy script, and paper.

Run: ``python benchmarks/cli.py [--points 200000] [--repeat 3] [--no-paper]``.

Prints, each as the minimum and the median over ``--repeat`` runs of a fresh process (stdout
to a temporary file):

- ``linecontact normal --R-over-h 100 --sigma0-over-E 0.01 --a-over-R-range 1e-4 0.2 N
  --json`` against ``benchmarks/plain_normal.py`` (the same closed form and the same JSON
  document, written with NumPy and ``json`` alone), run in turn in the same loop, and their
  ratio (target: the CLI within 2x of the plain script);
- the import time of ``linecontact`` against ``numpy`` and the scalar call times
  (``benchmarks/calls.py``);
- ``linecontact paper`` into a temporary directory (target: under 3 s).
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent


def _cli() -> list[str]:
    exe = shutil.which("linecontact")
    return [exe] if exe else [sys.executable, "-m", "linecontact"]


def timed(cmd: list[str], cwd: str) -> float:
    """Wall time of one run of ``cmd`` (stdout to a file in ``cwd``), in seconds."""
    with open(os.path.join(cwd, "out"), "w") as out:
        t0 = time.perf_counter()
        subprocess.run(cmd, stdout=out, stderr=subprocess.DEVNULL, check=True, cwd=cwd)
        return time.perf_counter() - t0


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=200_000)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--no-paper", action="store_true", help="skip linecontact paper")
    args = ap.parse_args()
    n = str(args.points)
    cli = [
        *_cli(),
        "normal",
        "--R-over-h",
        "100",
        "--sigma0-over-E",
        "0.01",
        "--a-over-R-range",
        "1e-4",
        "0.2",
        n,
        "--json",
    ]
    plain = [sys.executable, str(HERE / "plain_normal.py"), "100", "0.01", "1e-4", "0.2", n]
    with tempfile.TemporaryDirectory() as tmp:
        t_cli, t_plain = [], []
        for _ in range(args.repeat):  # in turn, so that drift of the machine hits both
            t_cli.append(timed(cli, tmp))
            t_plain.append(timed(plain, tmp))
        size = os.path.getsize(os.path.join(tmp, "out"))
        ratios = [a / b for a, b in zip(t_cli, t_plain, strict=True)]
        print(f"normal --json, {args.points} points ({size / 1e6:.0f} MB of JSON):")
        print(
            f"  linecontact CLI   : min {min(t_cli):6.2f} s, median "
            f"{statistics.median(t_cli):6.2f} s"
        )
        print(
            f"  plain NumPy script: min {min(t_plain):6.2f} s, median "
            f"{statistics.median(t_plain):6.2f} s"
        )
        print(f"  ratio CLI/plain   : median {statistics.median(ratios):.2f} (target <= 2)")
        calls = HERE / "calls.py"
        if calls.exists():
            print(
                subprocess.run(
                    [sys.executable, str(calls)], capture_output=True, text=True, check=True
                ).stdout.rstrip()
            )
        if not args.no_paper:
            t_paper = [
                timed([*_cli(), "paper", "--outdir", os.path.join(tmp, "figs")], tmp)
                for _ in range(args.repeat)
            ]
            files = len(os.listdir(os.path.join(tmp, "figs")))
            print(
                f"linecontact paper ({files} files): min {min(t_paper):.2f} s, median "
                f"{statistics.median(t_paper):.2f} s (target < 3 s)"
            )


if __name__ == "__main__":
    main()
