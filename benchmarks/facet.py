"""Benchmark of the faceted wire (linecontact.facet): the pull-off's time and its agreement.

Run: ``python benchmarks/facet.py [--points 1000] [--seed 0]``.

Prints the time of one faceted pull-off (a hexagon, R/h = 171, sigma0/E = 0.00684: a 50 nm
ZnO-like wire, 5 nm corners) beside the round wire's: its closed form
(:func:`linecontact.pull_off`), and its pull-off by collocation, the minimum over the contact
half-width of :func:`linecontact.normal_contact` with ``method="collocation"`` (Brent's
method, as the faceted scan finds its minimum over the branch); then the time per point of
a vectorised batch of faceted pull-offs over R/h, sigma0/E, the number of sides and the
corner radius; the worst disagreement of the round limit (corner radius = circumradius) with
the closed form of the round wire; and the approach of a sharp facet to the strip's JKR
pull-off.
"""

from __future__ import annotations

import argparse

import numpy as np
from scipy.optimize import minimize_scalar

from _common import best_of
from linecontact import facet_pull_off, normal_contact, pull_off

RHO, S = 171.0, 0.00684


def _round_by_collocation(rho: float, s: float) -> float:
    """The round wire's pull-off as the minimum of the collocation solver's load."""
    a0 = max(pull_off(rho, s).a_over_R_at_pulloff, 1e-6)
    res = minimize_scalar(
        lambda a: normal_contact(a, rho, s, method="collocation").F_over_Eh,
        bounds=(0.5 * a0, 2.0 * a0),
        method="bounded",
        options={"xatol": 1e-10},
    )
    return float(res.fun)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)

    rho_j, s_j = 1e4, 0.01  # a snap-off at a finite width: the collocation has a minimum
    t_facet, p = best_of(lambda: facet_pull_off(RHO, S, sides=6, corner_radius_over_R=0.1))
    t_cf, _ = best_of(lambda: pull_off(RHO, S))
    t_col, F_col = best_of(lambda: _round_by_collocation(rho_j, s_j))
    t_facet_j, _ = best_of(lambda: facet_pull_off(rho_j, s_j, sides=6, corner_radius_over_R=0.1))
    print("one pull-off (a hexagon, 5 nm corners on a 50 nm wire):")
    print(f"  faceted (scan of the branch) : {t_facet * 1e3:8.2f} ms  ({p.mechanism})")
    print(f"  round wire, closed form      : {t_cf * 1e3:8.2f} ms")
    print(
        f"  at R/h = {rho_j:g}, sigma0/E = {s_j}: faceted {t_facet_j * 1e3:.2f} ms, round wire "
        f"by collocation {t_col * 1e3:.2f} ms; ratio {t_facet_j / t_col:.2f} (target <= 3)"
    )
    F_cf = pull_off(rho_j, s_j).F_pulloff_over_Eh
    print(f"    (the collocation minimum {F_col:.12g} against the closed form {F_cf:.12g})")

    n = args.points
    rho = 10 ** rng.uniform(0, 5, n)
    s = 10 ** rng.uniform(-4, -1, n)
    sides = rng.integers(3, 9, n)
    r = rng.uniform(0, 1, n)
    r[: n // 10] = 0.0
    t_vec, q = best_of(
        lambda: facet_pull_off(rho, s, sides=sides, corner_radius_over_R=r), repeat=1
    )
    print(
        f"vectorised, {n} points (R/h in [1, 1e5], sigma0/E in [1e-4, 0.1], 3-8 sides, r_c/R in "
        f"[0, 1]): {t_vec / n * 1e3:.3f} ms/point; all converged: {bool(np.all(q.converged))}"
    )
    mech, counts = np.unique(q.mechanism, return_counts=True)
    print("  mechanisms: " + ", ".join(f"{m} {c}" for m, c in zip(mech, counts, strict=True)))

    rho_r = 10 ** rng.uniform(0, 6, 200)
    s_r = 10 ** rng.uniform(-4, -1, 200)
    got = facet_pull_off(rho_r, s_r, sides=6, corner_radius_over_R=1.0).F_pulloff_over_Eh
    want = pull_off(rho_r, s_r).F_pulloff_over_Eh
    print(
        f"round limit (r_c = R), 200 points: worst relative difference from pull_off "
        f"{np.max(np.abs(got / want - 1)):.1e}"
    )
    print("sharp hexagon against the strip's JKR pull-off (sigma0/E = 0.01):")
    for rr in (1e4, 1e6, 1e8, 1e10):
        h = facet_pull_off(rr, 0.01, sides=6, corner_radius_over_R=0.0)
        gap = h.F_pulloff_over_Eh / h.F_strip_jkr_over_Eh - 1
        print(f"  R/h = {rr:8.0e}: F/F_strip - 1 = {gap:.2e}")


if __name__ == "__main__":
    main()
