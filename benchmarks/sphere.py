"""Benchmark of the Maugis-Dugdale sphere (linecontact.sphere): its times and its limits.

Run: ``python benchmarks/sphere.py [--points 1000] [--seed 0]``.

Prints the time of one sphere pull-off beside the line contact's (:func:`linecontact.pull_off`,
the wire's closed form); the time per point of vectorised batches of pull-offs, of contacts
at given radii and of contacts under loads, beside the line contact's ``normal_contact``;
and the distance of the pull-offs from their closed-form limits: JKR (-3/2 and -5/6 pi w R)
at a large Maugis parameter, DMT (-2 pi w R) at a small one.
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from _common import best_of
from linecontact import normal_contact, pull_off
from linecontact.sphere import sphere_contact, sphere_contact_for_load, sphere_pull_off


def _s(lam: float, rho: float) -> float:
    return math.sqrt((lam / 2) ** 3 * 16 * math.pi / (9 * rho))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=0)
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


if __name__ == "__main__":
    main()
