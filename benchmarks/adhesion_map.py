"""The default adhesion map: its time with one worker and with two, and whether they agree.

    python benchmarks/adhesion_map.py [--workers 1,2] [--mu-min MU] [--mu-max MU] [--n-mu N]

Prints the grid (``linecontact.adhesion_map.default_mu``: the Maugis parameters 0.01 to 100,
or to the end of the Lennard-Jones solver's domain where it is sooner; 81 loads to 30
pull-offs above pull-off), then for each worker count the wall time of ``adhesion_map``
(``workers=1``: the curves one after another in this process; ``workers=2``: two processes)
and the largest relative difference of the full law's widths from the first run (each curve
is computed independently, so only round-off of other BLAS thread counts may differ). Each
run starts afresh (no resume directory; the solver's own caches are cleared by running each
count in a fresh process); a run that fails prints its error and the next one runs. The flags
change the grid of ``mu`` (``--mu-min 0.01 --mu-max 3 --n-mu 13``: the default before issue 22,
56 s one curve after another). Issue 22 asks for the default map in under 15 s on 2 cores.
Its times are with one BLAS thread (``OPENBLAS_NUM_THREADS=1``, printed): on a shared 2-core
machine the solver's small dense factorisations with two BLAS threads were 20 times slower
in one process (170 s against 8.3 s for the 13 curves above).
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time

import numpy as np


def grid(args: argparse.Namespace) -> np.ndarray:
    """The values of ``mu`` of the flags (the default map's without them)."""
    from linecontact.adhesion_map import MU_MIN, default_mu

    return default_mu(args.n_mu, MU_MIN if args.mu_min is None else args.mu_min, args.mu_max)


def one(workers: int, mu: np.ndarray, out: str) -> None:
    """Compute the map over ``mu`` with ``workers``; save its widths and time to ``out``."""
    from linecontact.adhesion_map import adhesion_map

    t0 = time.perf_counter()
    m = adhesion_map(mu, workers=workers)
    t = time.perf_counter() - t0
    np.savez(out, t=t, mu=mu, xi=m.half_width_lj, F_pulloff=m.F_pulloff)


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--workers", default="1,2", help="worker counts, comma-separated")
    p.add_argument("--mu-min", type=float, default=None, help="smallest mu (default: the map's)")
    p.add_argument("--mu-max", type=float, default=None, help="largest mu (default: the map's)")
    p.add_argument("--n-mu", type=int, default=None, help="values of mu (default: the map's)")
    p.add_argument("--one", nargs=2, metavar=("WORKERS", "OUT"), help=argparse.SUPPRESS)
    args = p.parse_args()
    if args.one:
        one(int(args.one[0]), grid(args), args.one[1])
        return
    from linecontact.adhesion_map import default_y
    from linecontact.domain import DOMAIN
    from linecontact.lennard_jones import maugis_parameter_of_mu

    mu = grid(args)
    lam = maugis_parameter_of_mu(mu)
    blas = os.environ.get("OPENBLAS_NUM_THREADS", "unset")
    print(
        f"cores: {os.cpu_count()}, OPENBLAS_NUM_THREADS: {blas}, solver's domain: "
        f"mu <= {DOMAIN['lj_mu'][2]:g}"
    )
    print(
        f"grid: {mu.size} values of mu from {mu[0]:.3g} to {mu[-1]:.3g} (Maugis parameter "
        f"{lam[0]:.3g} to {lam[-1]:.3g}), {default_y().size} loads"
    )
    print(f"  {'workers':>7} {'seconds':>8} {'max rel diff of widths':>23}")
    first = None
    for w in (int(v) for v in args.workers.split(",")):
        out = f"/tmp/linecontact-bench-map-{os.getpid()}-{w}.npz"
        cmd = [sys.executable, __file__, "--one", str(w), out]
        for flag in ("mu_min", "mu_max", "n_mu"):
            if getattr(args, flag) is not None:
                cmd += [f"--{flag.replace('_', '-')}", str(getattr(args, flag))]
        run = subprocess.run(cmd, capture_output=True, text=True)
        if run.returncode != 0:
            last = (run.stderr.strip().splitlines() or ["?"])[-1]
            print(f"  {w:7d}   failed: {last}")
            continue
        with np.load(out) as d:
            t, xi = float(d["t"]), np.array(d["xi"])
        os.unlink(out)
        if first is None:
            first = xi
        with np.errstate(invalid="ignore", divide="ignore"):
            rel = np.abs(xi - first) / np.where(first > 0, first, np.nan)
        diff = float(np.nanmax(rel)) if np.any(np.isfinite(rel)) else 0.0
        print(f"  {w:7d} {t:8.1f} {diff:23.1e}")


if __name__ == "__main__":
    main()
