"""The Lennard-Jones law solved for line contact: time, refinement, limits, the limit form.

    python benchmarks/lennard_jones.py [--quick]

Prints (loads over ``w sqrt(R/z0)``, compressive positive)

1. the time of ``lj_pull_off(mu)`` and ``lj_curve(mu)`` for mu = 0.1 ... 400, each the first
   call in a fresh process (one BLAS thread) after ``import linecontact, scipy.linalg``, the
   curve's points and its largest error estimate; and the first call with the lazy import
   of scipy counted;
2. refinement studies at mu = 1, 10, 30, 100: the pull-off for m = 160 ... 1280 (640 with
   ``--quick``), its error estimate and its actual error against the finest mesh;
3. the rigid limit mu = 0 against the closed forms of ``linecontact.closed_forms``;
4. the pull-off against Maugis-Dugdale (Maugis matching) and JKR for mu = 0.01 ... 700, and
   the rate at which it approaches JKR;
5. the limit form beyond mu = 400: the fit of its correction, reproduced from the
   self-consistent pull-offs at mu = 100 ... 400, and the form against the self-consistent
   solver in the overlap mu = 400 ... 700 (the latter forced past its domain).

Before issue 22 (the issue's figures, first call in a fresh process, one BLAS thread, this
2-core machine): pull-off 0.26 / 0.35 / 0.54 / 2.22 s and curve 0.29 / 0.45 / 1.19 / 8.80 s at
mu = 0.1 / 0.3 / 1 / 3; mu = 10 took 700 s; mu beyond 3 was refused.
"""

from __future__ import annotations

import argparse
import math
import os
import subprocess
import sys
import time

import numpy as np

import linecontact as lc
from linecontact.closed_forms import lennard_jones_rigid_load, lennard_jones_rigid_pull_off
from linecontact.lennard_jones import (
    MAUGIS_MATCH_SIGMA0,
    _branch,
    _limit,
    _solver,
    lj_pull_off,
    lj_state,
    maugis_parameter_of_mu,
)

MUS = (0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 400.0)

_TIMER = """
import sys, time
t0 = time.perf_counter()
import linecontact
from linecontact.lennard_jones import lj_curve, lj_pull_off
if sys.argv[3] == "warm":
    import scipy.linalg
t = time.perf_counter()
r = (lj_pull_off if sys.argv[1] == "po" else lj_curve)(float(sys.argv[2]))
t = time.perf_counter() - t
if sys.argv[1] == "po":
    print(t, r.F_pulloff, r.error_estimate, 0)
else:
    print(t, r.pull_off.F_pulloff, float(r.error_estimate.max()), r.F.size)
"""


def fresh(what: str, mu: float, warm: bool = True) -> tuple[float, float, float, int]:
    """``(seconds, F_pulloff, error estimate, points)`` of the first call in a new process."""
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1", MKL_NUM_THREADS="1")
    out = subprocess.run(
        [sys.executable, "-c", _TIMER, what, repr(mu), "warm" if warm else "cold"],
        capture_output=True,
        text=True,
        check=True,
        env=env,
    ).stdout.split()
    return float(out[0]), float(out[1]), float(out[2]), int(out[3])


def speed(repeat: int) -> None:
    print(f"1. time of the first call in a fresh process (best of {repeat}), one BLAS thread")
    print(
        f"  {'mu':>6} {'lambda':>7} {'pull-off s':>10} {'F_pulloff':>13} {'err est':>8} "
        f"{'curve s':>8} {'points':>6} {'max err':>8} {'po cold s':>9}"
    )
    for mu in MUS:
        po = min((fresh("po", mu) for _ in range(repeat)), key=lambda r: r[0])
        cu = min((fresh("curve", mu) for _ in range(repeat)), key=lambda r: r[0])
        cold = fresh("po", mu, warm=False)
        lam = float(maugis_parameter_of_mu(mu))
        print(
            f"  {mu:6g} {lam:7.3f} {po[0]:10.3f} {po[1]:13.9f} {po[2]:8.1e} "
            f"{cu[0]:8.3f} {cu[3]:6d} {cu[2]:8.1e} {cold[0]:9.3f}"
        )
    print("  (targets: pull-off < 0.3 s, curve < 1 s; 'po cold' counts the import of scipy)")


def refinement(quick: bool) -> None:
    ms = (160, 320, 640) if quick else (160, 320, 640, 1280)
    print(f"2. refinement of the pull-off (actual error against m = {ms[-1]})")
    print(f"  {'mu':>5} {'m':>5} {'n':>5} {'F_pulloff':>18} {'err est':>9} {'actual':>9} {'s':>6}")
    for mu in (1.0, 10.0, 30.0, 100.0):
        rows = []
        for m in ms:
            t0 = time.perf_counter()
            p = lj_pull_off(mu, m=m)
            rows.append((m, p, time.perf_counter() - t0))
        ref = rows[-1][1].F_pulloff
        for m, p, t in rows:
            print(
                f"  {mu:5g} {m:5d} {p.n:5d} {p.F_pulloff:18.12f} {p.error_estimate:9.2e} "
                f"{abs(p.F_pulloff - ref):9.2e} {t:6.2f}"
            )
    print("  (the finest row's actual error is 0 by construction)")


def rigid() -> None:
    print("3. rigid limit mu = 0 against linecontact.closed_forms")
    F_ref, z_ref = lennard_jones_rigid_pull_off()
    p = lj_pull_off(0.0)
    print(
        f"  pull-off {p.F_pulloff:.12f} (closed form {F_ref:.12f}), rel. error "
        f"{abs(p.F_pulloff / F_ref - 1):.2e}, err est {p.error_estimate:.2e}; central gap "
        f"{p.central_gap_at_pulloff:.7f} (closed form {z_ref:.7f})"
    )
    print(
        f"  {'zeta0':>6} {'lj_state F':>18} {'closed form':>18} {'rel. error':>10} {'err est':>9}"
    )
    for z in (0.95, 1.1, 2.0, 8.0):
        s = lj_state(z, 0.0)
        F = float(lennard_jones_rigid_load(z))
        print(
            f"  {z:6.2f} {s.F:18.12f} {F:18.12f} {abs(s.F / F - 1):10.2e} {s.error_estimate:9.2e}"
        )


def md_pull_off(mu: float, R_over_h: float = 1e6) -> float:
    """The matched Maugis-Dugdale pull-off over ``w sqrt(R/z0)``."""
    s = mu * MAUGIS_MATCH_SIGMA0**1.5 / math.sqrt(R_over_h)
    po = lc.pull_off(R_over_h, s)
    return float(po.F_pulloff_over_Eh / (s * math.sqrt(R_over_h / MAUGIS_MATCH_SIGMA0)))


def self_consistent(mu: float):
    """The self-consistent pull-off at any ``mu`` (past the public domain for the overlap)."""
    po, _ = _branch.pull_off_search(mu, _solver._grid_for(mu, None))
    return po


def limits(quick: bool) -> None:
    print("4. pull-off against Maugis-Dugdale (matched) and JKR, F_jkr = -0.75 (4 pi/mu)^(1/3)")
    print(
        f"  {'mu':>6} {'lambda':>8} {'F_lj':>12} {'err est':>8} {'F_md/F_lj-1':>11} "
        f"{'F_lj/F_jkr-1':>12} {'rate':>6} {'jump-in':>10} {'gap-1':>9} {'JKR gap-1':>9}"
    )
    prev = None
    mus = (0.01, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 200.0, 400.0)
    for mu in mus if quick else (*mus, 700.0):
        p = self_consistent(mu) if mu > _limit.MU_SELF_CONSISTENT else None
        q = lj_pull_off(mu) if p is None else None
        F = p.F if p is not None else q.F_pulloff
        err = p.error if p is not None else q.error_estimate
        gap = p.central_gap if p is not None else q.central_gap_at_pulloff
        jump = "-" if q is None else f"{q.F_jump_in:10.6f}"
        jkr = _limit.jkr_pull_off(mu)
        d = F / jkr - 1
        rate = "" if prev is None else f"{-math.log(d / prev[1]) / math.log(mu / prev[0]):6.3f}"
        prev = (mu, d)
        print(
            f"  {mu:6g} {float(maugis_parameter_of_mu(mu)):8.3f} {F:12.9f} {err:8.1e} "
            f"{md_pull_off(mu) / F - 1:11.3e} {d:12.3e} {rate:>6} {jump:>10} {gap - 1:9.3e} "
            f"{_limit._GAP * mu ** (-2 / 3):9.3e}"
        )
    print("  rate: -d ln|F/F_jkr - 1| / d ln mu between rows (the edge zone over the contact: 4/3)")


def limit_form() -> None:
    print("5. the limit form beyond mu = 400: F_jkr (1 - C mu^-p)")
    fit = np.array([100.0, 140.0, 200.0, 280.0, 400.0])
    d = np.array([self_consistent(mu).F / _limit.jkr_pull_off(mu) - 1 for mu in fit])
    A = np.vstack([np.ones(fit.size), np.log(fit)]).T
    c = np.linalg.lstsq(A, np.log(-d), rcond=None)[0]
    print(
        f"  fit on mu = 100 ... 400: C = {math.exp(c[0]):.6g}, p = {-c[1]:.6g} "
        f"(in linecontact.lennard_jones._limit: C = {_limit._C}, p = {_limit._P})"
    )
    print(
        f"  {'mu':>6} {'self-consistent':>16} {'err est':>8} {'limit form':>14} "
        f"{'estimate':>9} {'|diff|':>9}"
    )
    for mu in (400.0, 560.0, 700.0):
        p = self_consistent(mu)
        F, est, _ = _limit.limit_pull_off(mu)
        print(f"  {mu:6g} {p.F:16.10f} {p.error:8.1e} {F:14.10f} {est:9.2e} {abs(F - p.F):9.2e}")
    for mu in (1e3, 1e4, 1e6):
        q = lj_pull_off(mu)
        print(
            f"  {mu:6g} {'(limit form)':>16} {'':>8} {q.F_pulloff:14.10f} {q.error_estimate:9.2e}"
        )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="coarser studies, one timing each")
    args = parser.parse_args()
    t0 = time.perf_counter()
    speed(1 if args.quick else 3)
    refinement(args.quick)
    rigid()
    limits(args.quick)
    limit_form()
    print(f"total {time.perf_counter() - t0:.1f} s")


if __name__ == "__main__":
    main()
