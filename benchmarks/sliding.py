"""Benchmark of the steady-sliding solvers: time per point, residuals and agreement.

Run: ``PYTHONPATH=src python benchmarks/sliding.py [--points 10000] [--seed 0]``.

Prints, for a batch spread over sigma0/E in [1e-4, 0.3], R/h2 in [10, 1e4], h1/h2 in
[0.1, 10] and a/R in (0, 0.2] (log-uniform, with a tenth of the batch pushed to the thin-zone,
JKR-like end), the time per point of the sliding collocation solver, of the sliding closed
form and of the symmetric (normal) collocation solver on the same a/R, R/h, sigma0/E; the
worst residuals; the agreement between the two sliding solvers; at h1 = h2 the agreement
with the symmetric normal solution; the identity M - e F = (sigma0/E)(h1/h2 - 1); the
convergence with the number of nodes at a thin-zone point; and the time of the inverse
(contact for a given load) and of the pull-off search.
"""

from __future__ import annotations

import argparse

import numpy as np

from _common import best_of, sample_normal
from linecontact import normal_contact
from linecontact.sliding import sliding_contact, sliding_contact_for_load, sliding_pull_off


def sample(n: int, rng: np.random.Generator):
    A, rho, s = sample_normal(n, rng)
    ratio = 10 ** rng.uniform(-1, 1, n)
    return A, rho, ratio, s


def scales(r):
    """Natural sizes of the errors of F, e and M (their terms), per point."""
    A, rho, s = r.a_over_R, r.R_over_h2, r.sigma0_over_E
    u1, u2 = np.arccosh(r.c1_over_a), np.arccosh(r.c2_over_a)
    F = np.pi / 4 * A * A * rho + s * rho * A * (np.sinh(u1) + np.sinh(u2))
    e = 2 * s / np.pi * (u1 + u2)
    M = 0.25 * s * A * A * rho * (np.sinh(2 * u1) + np.sinh(2 * u2))
    return F, e, M


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=10_000)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)
    A, rho, ratio, s = sample(args.points, rng)
    N = A.size

    t_co, co = best_of(lambda: sliding_contact(A, rho, ratio, s, method="collocation"), repeat=2)
    t_cf, cf = best_of(lambda: sliding_contact(A, rho, ratio, s, method="closed-form"))
    t_nc, _ = best_of(lambda: normal_contact(A, rho, s, method="collocation"), repeat=2)

    zone = np.minimum(cf.c1_over_a, cf.c2_over_a) - 1
    print(
        f"steady sliding, {N} points: sigma0/E in [1e-4, 0.3], R/h2 in [10, 1e4], "
        f"h1/h2 in [0.1, 10], a/R in (0, 0.2]"
    )
    print(
        f"  min(c1, c2)/a - 1 from {zone.min():.3e} to {zone.max():.3e} "
        f"({np.mean(zone < 1e-2) * 100:.1f}% of points below 1e-2)"
    )
    print(f"  sliding collocation : {t_co / N * 1e6:8.2f} us/point  ({t_co:.3f} s)")
    print(f"  sliding closed form : {t_cf / N * 1e6:8.2f} us/point  ({t_cf:.3f} s)")
    print(f"  normal collocation  : {t_nc / N * 1e6:8.2f} us/point  (same a/R, R/h, sigma0/E)")
    print(f"  ratio sliding/normal collocation: {t_co / t_nc:.2f}  (target <= 5)")
    sizes, counts = np.unique(co.n_collocation, return_counts=True)
    print(
        "  collocation sizes n (points): "
        + ", ".join(f"{n_}({c_})" for n_, c_ in zip(sizes, counts, strict=True))
    )
    print(
        f"  all converged: {bool(np.all(co.converged))}; worst residuals: trailing "
        f"{np.max(co.residual_trailing):.1e}, leading {np.max(co.residual_leading):.1e}, "
        f"consistency {np.max(co.residual_consistency):.1e}; worst error estimate "
        f"{np.max(co.error_estimate):.1e}"
    )
    sF, se, sM = scales(cf)
    rel_c = max(
        np.max(np.abs(co.c1_over_R / cf.c1_over_R - 1)),
        np.max(np.abs(co.c2_over_R / cf.c2_over_R - 1)),
    )
    print("  collocation vs closed form (worst over all points):")
    print(f"    relative c1, c2             : {rel_c:.2e}")
    dF = np.max(np.abs(co.F_over_Eh2 - cf.F_over_Eh2) / sF)
    de = np.max(np.abs(co.e_over_R - cf.e_over_R) / se)
    dM = np.max(np.abs(co.M_over_Eh2R - cf.M_over_Eh2R) / sM)
    print(f"    |dF| / (|Hertz| + |adhesive|): {dF:.2e}")
    print(f"    |de| / (2 sigma0 (u1+u2)/pi) : {de:.2e}")
    print(f"    |dM| / (its two terms)       : {dM:.2e}")
    hyst = np.abs(co.M_axis_over_Eh2R - s * (ratio - 1)) / (s * np.maximum(ratio, 1))
    print(f"  M - e F = (sigma0/E)(h1/h2 - 1): worst relative deviation {np.max(hyst):.2e}")

    # the symmetric limit against the normal solution (closed form, independent code)
    sym = sliding_contact(A, rho, 1.0, s, method="collocation")
    ref = normal_contact(A, rho, s)
    rel_c = max(
        np.max(np.abs(sym.c1_over_R / ref.c_over_R - 1)),
        np.max(np.abs(sym.c2_over_R / ref.c_over_R - 1)),
    )
    sF, _, _ = scales(sym)
    away = np.abs(ref.F_over_Eh) >= 1e-3 * sF
    rel_F = np.abs(sym.F_over_Eh2 / ref.F_over_Eh - 1)[away]
    print("  h1 = h2 (collocation) vs the normal closed form:")
    print(
        f"    relative c1, c2: {rel_c:.2e}; relative F: {rel_F.max():.2e} over the "
        f"{away.sum()} points with |F| >= 1e-3 of its terms (target <= 1e-8); "
        f"|dF| / terms: {np.max(np.abs(sym.F_over_Eh2 - ref.F_over_Eh) / sF):.2e}"
    )
    print(
        f"    max |e/R| = {np.max(np.abs(sym.e_over_R)):.1e}, "
        f"max |M|/(E h2 R) = {np.max(np.abs(sym.M_over_Eh2R)):.1e}, "
        f"stability flags equal: {bool(np.all(sym.stable == ref.stable))}"
    )

    # convergence with n at a thin-zone point
    a0, r0, q0, s0 = 0.15, 5000.0, 2.0, 0.2
    cref = sliding_contact(a0, r0, q0, s0, method="closed-form")
    print(
        f"  convergence at a/R={a0}, R/h2={r0:g}, h1/h2={q0}, sigma0/E={s0} "
        f"(c2/a - 1 = {cref.c2_over_a - 1:.2e}):"
    )
    for n in (32, 64, 128, 256, 512):
        r = sliding_contact(a0, r0, q0, s0, method="collocation", n=n, on_failure="report")
        print(
            f"    n = {n:4d}: |dF/F| = {abs(r.F_over_Eh2 / cref.F_over_Eh2 - 1):.2e}, "
            f"|dc2/c2| = {abs(r.c2_over_R / cref.c2_over_R - 1):.2e}, "
            f"error estimate {r.error_estimate:.1e}"
        )

    # inverse and pull-off
    m = 100
    pr = 10 ** rng.uniform(1, 4, m)
    pq = 10 ** rng.uniform(-1, 1, m)
    ps = 10 ** rng.uniform(-3, np.log10(0.3), m)
    t_po, po = best_of(lambda: sliding_pull_off(pr, pq, ps), repeat=1)
    F = np.abs(po.F_pulloff_over_Eh2) * rng.uniform(-0.9, 3.0, m)
    t_inv, inv = best_of(
        lambda: sliding_contact_for_load(F, pr, pq, ps, method="collocation"), repeat=1
    )
    snap = np.asarray(po.mechanism) == "snap-off"
    print(
        f"pull-off, {m} parameter triples: {t_po:.2f} s ({snap.sum()} snap-off, "
        f"{m - snap.sum()} zero-width); contact for {m} loads (collocation): {t_inv:.2f} s, "
        f"worst |F - target| / |F_pulloff| = "
        f"{np.max(np.abs(inv.F_over_Eh2 - F) / np.abs(po.F_pulloff_over_Eh2)):.1e}, "
        f"all stable: {bool(np.all(inv.stable))}"
    )


if __name__ == "__main__":
    main()
