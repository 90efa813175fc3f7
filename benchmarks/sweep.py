"""Sweeps at scale: a 1e7-point pull-off sweep, the overhead at 1e6, Lennard-Jones curves.

    python benchmarks/sweep.py [--only big,overhead,curves,scaling] [--side 3163] [--curves 200]

Issue 23 asks, on 2 cores:

1. ``big``: a 1e7-point closed-form sweep (``linecontact sweep pulloff`` over a 3163 x 3163
   grid of radius x work of adhesion, ``--workers 2``, written to Zarr) in under 60 s with
   peak memory under 1 GB. The command runs as a separate process; the memory is the sum of
   the resident sizes of that process and all its children (the Dask scheduler, nannies and
   workers), sampled every 0.05 s (psutil, installed with dask.distributed).
2. ``overhead``: ``lc.sweep("pulloff", ...)`` in this process (``workers=1``, in memory) over
   1e6 points against the bare vectorised call that gives the same numbers
   (``adhesion_from_work``, ``pull_off`` and the SI scaling), best of 3: under 1.5x. Also
   the same sweep written to Zarr.
3. ``curves``: a sweep of ``--curves`` Lennard-Jones load curves (``linecontact sweep curve
   --law lennard-jones --R-over-h 1000`` over sigma0/E from 0.003 to 1, 200 values: the law's
   mu from 0.09 to 30, the Maugis parameter from 0.1 to 8) with ``--workers 1`` and ``2``:
   the speed-up (issue: 1.7x or better on 2 workers), and the largest relative difference of
   the two datasets (only BLAS round-off may differ).

4. ``scaling``: the wall time of ``--scaling-curves`` Lennard-Jones curves and of the
   ``--scaling-side`` squared closed-form sweep above against ``--workers`` 1, 2, 4, ... up to
   the cores of the machine: the speed-up and the efficiency (speed-up over workers), each
   run a new process writing Zarr (issue 36: parallelism that pays, near-linear on 16 cores
   where a machine has them).

Run with one BLAS thread (``OPENBLAS_NUM_THREADS=1``, set here for the child processes) on
an idle machine: a shared 2-core machine slows every figure.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import warnings

import numpy as np

ENV = {**os.environ, "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"}


def _tree_rss(pid: int) -> int:
    import psutil

    try:
        p = psutil.Process(pid)
        procs = [p, *p.children(recursive=True)]
    except psutil.NoSuchProcess:
        return 0
    total = 0
    for q in procs:
        try:
            total += q.memory_info().rss
        except psutil.NoSuchProcess:
            continue
    return total


def run_measured(cmd: list[str]) -> tuple[float, int, int, str]:
    """Wall time, peak tree memory [bytes], exit status and stderr of ``cmd``."""
    peak = [0]
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, env=ENV, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    done = threading.Event()

    def sample() -> None:
        while not done.is_set():
            peak[0] = max(peak[0], _tree_rss(proc.pid))
            time.sleep(0.05)

    th = threading.Thread(target=sample, daemon=True)
    th.start()
    _, err = proc.communicate()
    wall = time.perf_counter() - t0
    done.set()
    th.join()
    return wall, peak[0], proc.returncode, err.decode()


def big(side: int, tmp: str) -> None:
    out = os.path.join(tmp, "big.zarr")
    cmd = [
        sys.executable, "-m", "linecontact", "sweep", "pulloff",
        "--radius", f"10e-9:200e-9:{side}:log", "--modulus", "1.2e11",
        "--work-of-adhesion", f"0.01:1:{side}:log", "--z0", "3e-10",
        "-o", out, "--workers", "2", "--quiet",
    ]  # fmt: skip
    wall, peak, code, err = run_measured(cmd)
    n = side * side
    print(f"big: {n:.3g} points, pull-off over radius x work of adhesion, 2 workers, Zarr")
    print(
        f"  exit {code}; wall {wall:.1f} s (target < 60 s); peak memory of the process tree "
        f"{peak / 2**30:.2f} GiB (target < 1 GB); store {_du(out) / 2**20:.0f} MiB"
    )
    if code:
        print(err)
    import linecontact as lc

    # the same numbers by the bare vectorised calls in this process (issue 36: the CLI
    # sweep within 2x of them), in blocks of 1e6 points (as the sweep's blocks: memory)
    def bare() -> None:
        R = np.geomspace(10e-9, 200e-9, side)
        w = np.geomspace(0.01, 1, side)
        for k in range(0, side * side, 10**6):
            flat = np.arange(k, min(k + 10**6, side * side))
            s0, h = lc.adhesion_from_work(w[flat % side], 3e-10)
            r = lc.pull_off(R[flat // side] / h, s0 / 1.2e11)
            r.F_pulloff_over_Eh * (1.2e11 * h)

    t_bare, _ = best(bare, repeat=1)
    print(
        f"  the bare vectorised calls in one process: {t_bare:.1f} s; the CLI sweep "
        f"{wall / t_bare:.2f}x of them (target <= 2x)"
    )

    ds = lc.open_sweep(out)
    i, j = side // 3, 2 * side // 3
    point = ds.isel(radius=i, work_of_adhesion=j)
    cyl = lc.Cylinder.from_modulus(
        float(point.radius),
        1.2e11,
        work_of_adhesion=float(point.work_of_adhesion),
        equilibrium_spacing=3e-10,
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ref = cyl.pull_off().pull_off_force
    err_rel = abs(float(point.F_pulloff_N_per_m) / ref - 1)
    print(f"  a sampled point against Cylinder.pull_off: relative difference {err_rel:.1e}")


def _du(path: str) -> int:
    total = 0
    for root, _, files in os.walk(path):
        total += sum(os.path.getsize(os.path.join(root, f)) for f in files)
    return total


def overhead(tmp: str) -> None:
    import linecontact as lc

    side = 1000
    R = np.geomspace(10e-9, 200e-9, side)
    w = np.geomspace(0.01, 1, side)
    kw = dict(radius=f"10e-9:200e-9:{side}:log", modulus=1.2e11,
              work_of_adhesion=f"0.01:1:{side}:log", z0=3e-10)  # fmt: skip

    def bare():
        RR, WW = np.meshgrid(R, w, indexing="ij")
        s0, h = lc.adhesion_from_work(WW.ravel(), 3e-10)
        r = lc.pull_off(RR.ravel() / h, s0 / 1.2e11)
        return r.F_pulloff_over_Eh * (1.2e11 * h)

    def swept():
        return lc.sweep("pulloff", **kw)

    out = os.path.join(tmp, "o.zarr")

    def to_zarr():
        return lc.sweep("pulloff", **kw, output=out, overwrite=True)

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        swept()  # imports (xarray, dask) out of the timing
        tb, F = best(bare)
        ts, ds = best(swept)
        shutil.rmtree(out, ignore_errors=True)
        tz, dz = best(to_zarr, clear=out)
    diff = np.max(np.abs(ds.F_pulloff_N_per_m.values.ravel() / F - 1))
    print("overhead: 1e6 points of pull-off (workers=1, this process), best of 3")
    print(
        f"  bare vectorised call {tb:.2f} s; lc.sweep in memory {ts:.2f} s ({ts / tb:.2f}x, "
        f"target < 1.5x); to Zarr {tz:.2f} s ({tz / tb:.2f}x); largest relative difference "
        f"{diff:.1e}"
    )
    del dz


def best(fn, repeat=3, clear=None):
    t = np.inf
    out = None
    for _ in range(repeat):
        if clear:
            shutil.rmtree(clear, ignore_errors=True)
        t0 = time.perf_counter()
        out = fn()
        t = min(t, time.perf_counter() - t0)
    return t, out


def curves(n: int, tmp: str) -> None:
    import linecontact as lc

    times = {}
    data = {}
    for workers in (1, 2):
        out = os.path.join(tmp, f"curves{workers}.zarr")
        cmd = [
            sys.executable, "-m", "linecontact", "sweep", "curve", "--law", "lennard-jones",
            "--R-over-h", "1000", "--sigma0-over-E", f"0.003:1:{n}:log",
            "-o", out, "--workers", str(workers), "--quiet",
        ]  # fmt: skip
        wall, peak, code, err = run_measured(cmd)
        if code:
            print(err)
        times[workers] = wall
        data[workers] = lc.open_sweep(out).load()
        print(
            f"curves: {n} Lennard-Jones curves, --workers {workers}: {wall:.1f} s "
            f"(peak memory {peak / 2**30:.2f} GiB)"
        )
    a, b = data[1].F_over_Eh.values, data[2].F_over_Eh.values
    with np.errstate(invalid="ignore", divide="ignore"):
        d = np.nanmax(np.abs(a - b) / np.abs(a))
    mu = data[1].attrs["parameters"]
    print(
        f"  speed-up on 2 workers {times[1] / times[2]:.2f}x (target >= 1.7x); largest relative "
        f"difference of the loads {d:.1e}; records per curve {data[1].sizes['record']}; {mu}"
    )


def scaling(n: int, side: int, tmp: str) -> None:
    """The speed-up against workers: 1, 2, 4, ... up to the cores of this machine."""
    cores = os.cpu_count() or 1
    counts = [w for w in (1, 2, 4, 8, 16, 32, 64) if w <= cores]
    jobs = {
        f"{n} Lennard-Jones curves": [
            "curve", "--law", "lennard-jones", "--R-over-h", "1000",
            "--sigma0-over-E", f"0.003:1:{n}:log",
        ],
        f"{side * side:.0e} closed-form pull-offs": [
            "pulloff", "--radius", f"10e-9:200e-9:{side}:log", "--modulus", "1.2e11",
            "--work-of-adhesion", f"0.01:1:{side}:log", "--z0", "3e-10",
        ],
    }  # fmt: skip
    print(f"scaling: wall time against --workers on {cores} cores (each a new process, to Zarr)")
    print(f"  {'sweep':>28} {'workers':>7} {'wall s':>7} {'speed-up':>8} {'efficiency':>10}")
    for name, words in jobs.items():
        first = None
        for w in counts:
            out = os.path.join(tmp, f"scaling{w}.zarr")
            cmd = [sys.executable, "-m", "linecontact", "sweep", *words, "-o", out]
            wall, _, code, err = run_measured([*cmd, "--workers", str(w), "--quiet"])
            if code:
                print(err)
            first = first or wall
            print(f"  {name:>28} {w:7d} {wall:7.1f} {first / wall:7.2f}x {first / wall / w:10.2f}")
            shutil.rmtree(out, ignore_errors=True)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", default="big,overhead,curves,scaling")
    ap.add_argument("--side", type=int, default=3163)
    ap.add_argument("--curves", type=int, default=200)
    ap.add_argument("--scaling-curves", type=int, default=64)
    ap.add_argument("--scaling-side", type=int, default=3163)
    args = ap.parse_args()
    print(f"OPENBLAS_NUM_THREADS={ENV['OPENBLAS_NUM_THREADS']}; {os.cpu_count()} cores")
    tmp = tempfile.mkdtemp(prefix="lc-sweep-bench-")
    try:
        parts = {
            "big": lambda: big(args.side, tmp),
            "overhead": lambda: overhead(tmp),
            "curves": lambda: curves(args.curves, tmp),
            "scaling": lambda: scaling(args.scaling_curves, args.scaling_side, tmp),
        }
        for part in args.only.split(","):
            parts[part]()
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
