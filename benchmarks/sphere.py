"""Benchmark of the Maugis-Dugdale sphere (linecontact.sphere): its times and its limits.

Run: ``python benchmarks/sphere.py [--points 1000] [--seed 0]``.

Prints the time of one sphere pull-off beside the line contact's (:func:`linecontact.pull_off`,
the wire's closed form); the time per point of vectorised batches of pull-offs, of contacts
at given radii and of contacts under loads, beside the line contact's ``normal_contact``;
and the distance of the pull-offs from their closed-form limits: JKR (-3/2 and -5/6 pi w R)
at a large Maugis parameter, DMT (-2 pi w R) at a small one. Then the Lennard-Jones sphere
(linecontact.sphere.lennard_jones): the time of a pull-off and of a whole curve at Tabor
parameters from 0 to the top of the self-consistent range (the issue's bounds: 0.5 s and
2 s), its error estimates, the fit of the limit form's correction reproduced from the
solver, and the limit form against the solver in the overlap beyond. ``--no-lj`` leaves
that part out.
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from _common import best_of
from linecontact import normal_contact, pull_off
from linecontact._threads import on_one_blas_thread
from linecontact.sphere import lennard_jones as lj
from linecontact.sphere import (
    sphere_contact,
    sphere_contact_for_load,
    sphere_lj_curve,
    sphere_lj_pull_off,
    sphere_pull_off,
)


def _s(lam: float, rho: float) -> float:
    return math.sqrt((lam / 2) ** 3 * 16 * math.pi / (9 * rho))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--no-lj", action="store_true", help="leave out the Lennard-Jones sphere")
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)

    t_sphere, p = best_of(lambda: sphere_pull_off(1e4, 0.001))
    t_wire, _ = best_of(lambda: pull_off(1e4, 0.001))
    print("one pull-off (R/h = 1e4, sigma0/E = 1e-3):")
    print(f"  sphere (scan and Illinois) : {t_sphere * 1e3:8.2f} ms  ({p.mechanism})")
    print(f"  wire, closed form          : {t_wire * 1e3:8.2f} ms")

    n = args.points
    rho = 10 ** rng.uniform(0, 10, n)
    s = 10 ** rng.uniform(-5, 0, n)
    t_po, q = best_of(lambda: sphere_pull_off(rho, s), repeat=1)
    t_wpo, _ = best_of(lambda: pull_off(rho, s), repeat=1)
    lam = np.asarray(q.maugis_parameter)
    print(
        f"vectorised, {n} points (R/h in [1, 1e10], sigma0/E in [1e-5, 1]; lambda "
        f"{lam.min():.2g} to {lam.max():.2g}):"
    )
    print(f"  sphere pull-off           : {t_po / n * 1e3:.3f} ms/point")
    print(f"  wire pull-off             : {t_wpo / n * 1e3:.3f} ms/point")
    unit = np.cbrt(3 * np.pi * s / (4 * rho))
    A = 10 ** rng.uniform(-3, 0.5, n) * unit
    t_c, c = best_of(lambda: sphere_contact(A, rho, s))
    t_wc, _ = best_of(lambda: normal_contact(np.minimum(A, 0.2), np.maximum(rho, 1e-3), s))
    print(
        f"  sphere contact at radii   : {t_c / n * 1e3:.4f} ms/point (all converged: "
        f"{bool(np.all(c.converged))})"
    )
    print(f"  wire normal_contact       : {t_wc / n * 1e3:.4f} ms/point")
    F = np.asarray(q.F_pulloff_over_EhR) * rng.uniform(-3, 0.99, n)
    t_l, r = best_of(lambda: sphere_contact_for_load(F, rho, s), repeat=1)
    print(
        f"  sphere contact under loads: {t_l / n * 1e3:.3f} ms/point (stable: "
        f"{bool(np.all(r.stable))})"
    )

    print("the pull-off against its limits, in pi w R:")
    for lam_ in (1e2, 1e3, 1e4, 1e5):
        rr = 1e12
        ss = _s(lam_, rr)
        load = sphere_pull_off(rr, ss).F_pulloff_over_piwR
        disp = sphere_pull_off(rr, ss, control="displacement").F_pulloff_over_piwR
        print(
            f"  lambda = {lam_:7.0e}: load control + 3/2 = {load + 1.5:.1e}, "
            f"displacement control + 5/6 = {disp + 5 / 6:.1e}"
        )
    for lam_ in (1e-3, 1e-5, 1e-7, 1e-9):
        load = sphere_pull_off(1e6, _s(lam_, 1e6)).F_pulloff_over_piwR
        print(f"  lambda = {lam_:7.0e}: load control + 2 = {load + 2:.1e}")
    if not args.no_lj:
        lennard_jones()


def lennard_jones() -> None:
    """The Lennard-Jones sphere: times, estimates, the limit form's fit and its overlap."""
    top = lj.MU_SELF_CONSISTENT
    solver = on_one_blas_thread(lj._self_consistent)  # past the range, for the overlap
    print(f"Lennard-Jones sphere (self-consistent to mu_T = {top:g}; best of 2):")
    print("  mu_T    pull-off [pi w R]  estimate  rings  time      curve: points  time")
    sphere_lj_pull_off(1.0)  # imports
    for mu in (0.0, 0.1, 1.0, 3.0, 5.0, 10.0, 20.0, 35.0, top):
        t_p, p = best_of(lambda mu=mu: sphere_lj_pull_off(mu), repeat=2)
        t_c, c = best_of(lambda mu=mu: sphere_lj_curve(mu), repeat=2)
        print(
            f"  {mu:<6g}  {p.F_pulloff_over_piwR:.9f}  {p.error_estimate:8.1e}  "
            f"{p.n_rings:5d}  {t_p:6.3f} s  {c.F_over_piwR.size:13d}  {t_c:6.3f} s"
        )
    fit = np.array([25.0, 30.0, 35.0, 42.0, 50.0])
    d = np.array([sphere_lj_pull_off(mu).F_pulloff_over_piwR / -1.5 - 1.0 for mu in fit])
    slope, intercept = np.polyfit(np.log(fit), np.log(d), 1)
    print(
        f"  limit form F = -1.5 (1 + C mu^-p), fit on mu = 25 ... 50: "
        f"C = {math.exp(intercept):.7g},"
        f" p = {-slope:.7g} (in the module: C = {lj._C}, p = {lj._P})"
    )
    print("  the overlap (the solver run past its range):")
    for mu in (50.0, 60.0, 70.0, 100.0):
        t_s, sc = best_of(lambda mu=mu: solver(mu), repeat=1)
        lim = lj._limit(mu)
        diff = sc.F_pulloff_over_piwR - lim.F_pulloff_over_piwR
        print(
            f"    mu = {mu:4g}: solver {sc.F_pulloff_over_piwR:.9f} ({t_s:.2f} s), limit "
            f"{lim.F_pulloff_over_piwR:.9f}, difference {diff:+.1e}, the limit's estimate "
            f"{lim.error_estimate:.1e} ({lim.error_estimate / abs(diff):.0f} times it)"
        )
    t_l, _ = best_of(lambda: sphere_lj_pull_off(1e3))
    print(f"  beyond, the limit form: {t_l * 1e6:.1f} us a pull-off")


if __name__ == "__main__":
    main()
