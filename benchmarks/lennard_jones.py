"""The Lennard-Jones law solved for line contact: time, mesh refinement and limits.

    python benchmarks/lennard_jones.py [--quick]

Prints (loads over ``w sqrt(R/z0)``, compressive positive)

1. the time of ``lj_curve(mu)`` for mu = 0.1, 0.3, 1: points, seconds, ms per point and the
   largest error estimate along the curve;
2. a refinement study at mu = 1: ``lj_state(1.05, 1, m=m)`` and ``lj_pull_off(1, m=m)`` for
   m = 80 ... 1280 (640 with ``--quick``): the load, its error estimate and its actual error
   against the finest mesh, the nodes and the time;
3. the rigid limit mu = 0 against the closed forms of ``linecontact.closed_forms``;
4. the pull-off against Maugis-Dugdale with the Maugis matching (same work of adhesion and
   peak tension) and against the JKR line-contact pull-off -(3/4)(4 pi/mu)^(1/3) (the limit
   of large mu), for mu = 0.01 ... 10 (to 3 with ``--quick``), and whether the Dugdale
   ratio depends on R/h.
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

import linecontact as lc
from linecontact.closed_forms import lennard_jones_rigid_load, lennard_jones_rigid_pull_off
from linecontact.lennard_jones import (
    MAUGIS_MATCH_SIGMA0,
    lj_curve,
    lj_pull_off,
    lj_state,
    maugis_parameter_of_mu,
    mu_of_dugdale,
)


def timed(fn):
    t0 = time.perf_counter()
    out = fn()
    return time.perf_counter() - t0, out


def curves() -> None:
    print("1. lj_curve(mu): time per curve and per point")
    print(f"  {'mu':>5} {'points':>6} {'seconds':>8} {'ms/point':>9} {'max err est':>12}")
    for mu in (0.1, 0.3, 1.0):
        t, c = timed(lambda mu=mu: lj_curve(mu))
        n = c.F.size
        err = float(np.max(c.error_estimate))
        print(f"  {mu:5.2f} {n:6d} {t:8.2f} {1e3 * t / n:9.2f} {err:12.2e}")


def refinement(quick: bool) -> None:
    ms = (80, 160, 320, 640) if quick else (80, 160, 320, 640, 1280)
    print(f"2. refinement at mu = 1 (actual error against m = {ms[-1]})")
    rows = []
    for m in ms:
        ts, s = timed(lambda m=m: lj_state(1.05, 1.0, m=m))
        tp, p = timed(lambda m=m: lj_pull_off(1.0, m=m))
        rows.append((m, s, ts, p, tp))
    s_ref, p_ref = rows[-1][1].F, rows[-1][3].F_pulloff
    print("  lj_state(1.05, 1.0, m=m)")
    head = f"  {'m':>5} {'n':>5} {'F':>18} {'err est':>9} {'actual':>9} {'seconds':>8}"
    print(head)
    for m, s, ts, _, _ in rows:
        print(
            f"  {m:5d} {s.n:5d} {s.F:18.12f} {s.error_estimate:9.2e} "
            f"{abs(s.F - s_ref):9.2e} {ts:8.2f}"
        )
    print("  lj_pull_off(1.0, m=m)")
    print(head)
    for m, _, _, p, tp in rows:
        print(
            f"  {m:5d} {p.n:5d} {p.F_pulloff:18.12f} {p.error_estimate:9.2e} "
            f"{abs(p.F_pulloff - p_ref):9.2e} {tp:8.2f}"
        )
    print("  (actual error of the finest row is 0 by construction)")


def rigid() -> None:
    print("3. rigid limit mu = 0 against linecontact.closed_forms")
    F_ref, z_ref = lennard_jones_rigid_pull_off()
    t, p = timed(lambda: lj_pull_off(0.0))
    rel = abs(p.F_pulloff / F_ref - 1)
    print(
        f"  pull-off: {p.F_pulloff:.12f} (closed form {F_ref:.12f}), rel. error {rel:.2e}, "
        f"err est {p.error_estimate:.2e}, gap {p.central_gap_at_pulloff:.6f} "
        f"(closed form {z_ref:.6f}), {t:.2f} s"
    )
    print(
        f"  {'zeta0':>6} {'lj_state F':>18} {'closed form':>18} {'rel. error':>10} {'err est':>9}"
    )
    for z in (0.95, 1.1, 2.0):
        s = lj_state(z, 0.0)
        F = float(lennard_jones_rigid_load(z))
        print(
            f"  {z:6.2f} {s.F:18.12f} {F:18.12f} {abs(s.F / F - 1):10.2e} {s.error_estimate:9.2e}"
        )


def md_pull_off(mu: float, R_over_h: float) -> tuple[float, float, str]:
    """The matched Maugis-Dugdale pull-off over ``w sqrt(R/z0)``, the recovered ``mu`` and
    the mechanism."""
    s = mu * MAUGIS_MATCH_SIGMA0**1.5 / math.sqrt(R_over_h)
    mu_back, R_over_z0 = mu_of_dugdale(R_over_h, s)
    po = lc.pull_off(R_over_h, s)
    F = float(po.F_pulloff_over_Eh / (s * np.sqrt(R_over_z0)))
    return F, float(mu_back), str(po.mechanism)


def maugis_dugdale(quick: bool) -> None:
    R_over_h = 1e4
    print(f"4. pull-off against Maugis-Dugdale, Maugis matching, R/h = {R_over_h:g}")
    print("   (F_jkr = -0.75 (4 pi/mu)^(1/3): the JKR line-contact pull-off)")
    print(
        f"  {'mu':>5} {'lambda':>7} {'F_lj':>10} {'err est':>9} {'F_md':>10} "
        f"{'F_md/F_lj-1':>11} {'F_jkr':>10} {'F_lj/F_jkr-1':>12} {'mu back - mu':>12} "
        f"{'MD mechanism':>12} {'s':>5}"
    )
    F_lj = {}
    for mu in (0.01, 0.1, 0.3, 1.0, 3.0) + (() if quick else (10.0,)):
        F_md, mu_back, mech = md_pull_off(mu, R_over_h)
        jkr = -0.75 * (4 * math.pi / mu) ** (1 / 3)
        lam = float(maugis_parameter_of_mu(mu))
        try:
            t, p = timed(lambda mu=mu: lj_pull_off(mu))
        except ValueError as e:  # mu outside the solver's domain
            print(
                f"  {mu:5.2f} {lam:7.4f} {'-':>10} {'-':>9} {F_md:10.6f} {'-':>11} "
                f"{jkr:10.6f} {'-':>12} {mu_back - mu:12.1e} {mech:>12}   ({e})"
            )
            continue
        F_lj[mu] = p.F_pulloff
        print(
            f"  {mu:5.2f} {lam:7.4f} {p.F_pulloff:10.6f} {p.error_estimate:9.2e} {F_md:10.6f} "
            f"{F_md / p.F_pulloff - 1:11.4%} {jkr:10.6f} {p.F_pulloff / jkr - 1:12.4%} "
            f"{mu_back - mu:12.1e} {mech:>12} {t:5.1f}"
        )
    mu = 0.3
    F_ref = md_pull_off(mu, R_over_h)[0]
    print(f"  dependence on R/h at mu = {mu}:")
    print(
        f"  {'R/h':>7} {'F_md':>16} {'F_md/F_lj-1':>11} {'change vs 1e4':>13} {'MD mechanism':>12}"
    )
    for rh in (1e3, 1e4, 1e6):
        F_md, _, mech = md_pull_off(mu, rh)
        print(
            f"  {rh:7.0e} {F_md:16.12f} {F_md / F_lj[mu] - 1:11.4%} {F_md / F_ref - 1:13.1e} "
            f"{mech:>12}"
        )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="stop the refinement at m = 640")
    args = parser.parse_args()
    t0 = time.perf_counter()
    curves()
    refinement(args.quick)
    rigid()
    maugis_dugdale(args.quick)
    print(f"total {time.perf_counter() - t0:.1f} s")


if __name__ == "__main__":
    main()
