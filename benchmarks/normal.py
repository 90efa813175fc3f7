"""Benchmark of the normal (Maugis-Dugdale) solvers: time per point and agreement.

Run: ``python benchmarks/normal.py [--points 100000] [--seed 0]``.

Prints, for a batch spread over sigma0/E in [1e-4, 0.3], R/h in [10, 1e4] and a/R in (0, 0.2]
(log-uniform, with a tenth of the batch pushed to the thin-zone, JKR-like end), the time per
point of the collocation solver and of the closed form, their ratio, the worst disagreement
of F and c between them, and the time of the pull-off search for 1,000 parameter pairs.

Then the closed-form pull-off at its floor (issue 36): ``pull_off`` against
:func:`plain_pull_off`, the same Newton iteration written plainly over NumPy arrays (four
steps from the same asymptotes, no bracket, no check, no result object), on ``--floor-points``
parameter pairs (sigma0/E in [1e-4, 0.3], R/h in [10, 1e4]): the best-of-5 time per point of
each, their ratio (target <= 1.5) and the largest relative difference of the pull-off force
and of the half-widths at pull-off between them.
"""

from __future__ import annotations

import argparse

import numpy as np

from _common import best_of, sample_normal
from linecontact import normal_contact, pull_off, zero_width_load

LN2 = float(np.log(2.0))


def plain_pull_off(rho, s):
    """The pull-off force and half-widths a/R, c/R by a plain vectorised Newton iteration.

    The load minimum along the contact branch (``docs/derivations.md``; the scaled pieces of
    ``linecontact.closed_forms.maugis_dugdale``): Newton on ln kappa_s(u) = ln kappa in
    w = ln u, four steps from the asymptotes of the two ends, then the state at u. Written
    as a user would without linecontact: no validation, no bracket, no convergence check, no
    chunks, no result object. For kappa > 0.
    """
    kap = 4 / np.pi * s * np.sqrt(2 * rho)
    u_small = (2 * np.sqrt(2) / kap) ** (2 / 3)
    u_large = np.sqrt(4 / (kap * kap) + LN2 * LN2)
    w = np.log(np.where(u_small < 1, u_small, u_large))
    lk = np.log(kap)

    def pieces(u):
        q = np.exp(-2 * u)
        St = -np.expm1(-2 * u)
        Ct = 1 + q
        sh = np.sinh(u / 2)
        L = np.where(u < 1, np.log1p(2 * sh * sh), u + np.log1p(q) - LN2)
        return q, St, Ct, L, St * Ct - 4 * u * q, u * St - Ct * L

    with np.errstate(over="ignore", invalid="ignore"):
        for _ in range(4):
            u = np.exp(w)
            q, St, Ct, L, F1, F2 = pieces(u)
            D = L * L * F1 + 2 * L * St * F2
            g = np.log(2 * St / np.sqrt(D)) - lk
            dL = St / Ct
            dD = (
                2 * L * dL * F1
                + L * L * (2 * St * St - 2 * F1)
                + 2 * (dL * St + 2 * q * L) * F2
                + 4 * L * St * q * (u + L)
            )
            w = w - g / (u * (2 * q / St - dD / (2 * D)))
        u = np.exp(w)
        q, St, Ct, L, F1, F2 = pieces(u)
    kF2 = kap * F2
    X = 2 / (kF2 + np.sqrt(kF2 * kF2 + 4 * F1))
    e = np.exp(-u)
    phi = 4 * X * X * e * e - kap * X * St
    sq = np.sqrt(2 / rho)
    return np.pi / 2 * phi, 2 * X * e * sq, X * Ct * sq


def floor(n: int, rng: np.random.Generator) -> None:
    """``pull_off`` against :func:`plain_pull_off` on ``n`` parameter pairs."""
    s = 10 ** rng.uniform(-4, np.log10(0.3), n)
    rho = 10 ** rng.uniform(1, 4, n)
    pull_off(rho[:1000], s[:1000])  # imports and caches
    t_lib, po = best_of(lambda: pull_off(rho, s), repeat=5)
    t_plain, (F, A, C) = best_of(lambda: plain_pull_off(rho, s), repeat=5)
    # the widths compared where they are normal numbers: a/R is 0 where the minimum is Eq. 14
    # itself, and subnormal (a few digits) just above that (e^-u underflows for kappa < 3e-3)
    wide = po.a_over_R_at_pulloff > 1e-290
    dF = np.max(np.abs(F / po.F_pulloff_over_Eh - 1))
    dA = np.max(np.abs(A[wide] / po.a_over_R_at_pulloff[wide] - 1))
    dC = np.max(np.abs(C[wide] / po.c_over_R_at_pulloff[wide] - 1))
    print(
        f"pull-off at its floor, {n} parameter pairs (sigma0/E in [1e-4, 0.3], R/h in [10, 1e4]):"
    )
    print(f"  pull_off             : {t_lib / n * 1e6:6.3f} us/point (best of 5)")
    print(f"  plain Newton (floor) : {t_plain / n * 1e6:6.3f} us/point (best of 5)")
    print(f"  ratio pull_off/floor : {t_lib / t_plain:.2f}  (target <= 1.5)")
    print(
        f"  largest relative difference: F {dF:.1e}, a {dA:.1e}, c {dC:.1e} "
        f"({wide.sum()} points with a/R > 1e-290)"
    )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=100_000)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--floor-points", type=int, default=1_000_000)
    ap.add_argument("--floor-only", action="store_true", help="only the floor comparison")
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)
    floor(args.floor_points, np.random.default_rng(args.seed))
    if args.floor_only:
        return
    A, rho, s = sample_normal(args.points, rng)
    N = A.size

    t_cf, cf = best_of(lambda: normal_contact(A, rho, s))
    t_co, co = best_of(lambda: normal_contact(A, rho, s, method="collocation"), repeat=1)

    scale = np.pi / 4 * A * A * rho + 2 * s * rho * np.sqrt(cf.c_over_R**2 - A**2)
    dF = np.abs(co.F_over_Eh - cf.F_over_Eh)
    rel_F = dF / np.abs(cf.F_over_Eh)
    away = np.abs(cf.F_over_Eh) >= 1e-3 * scale
    rel_c = np.abs(co.c_over_R / cf.c_over_R - 1)
    zone = cf.c_over_a - 1

    print(f"normal contact, {N} points: sigma0/E in [1e-4, 0.3], R/h in [10, 1e4], a/R in (0, 0.2]")
    print(
        f"  c/a - 1 from {zone.min():.3e} to {zone.max():.3e} "
        f"({np.mean(zone < 1e-2) * 100:.1f}% of points below 1e-2)"
    )
    print(f"  closed form : {t_cf / N * 1e6:8.2f} us/point  ({t_cf:.3f} s)")
    print(f"  collocation : {t_co / N * 1e6:8.2f} us/point  ({t_co:.3f} s)")
    print(f"  ratio collocation/closed form: {t_co / t_cf:.1f}  (target <= 50)")
    sizes, counts = np.unique(co.n_collocation, return_counts=True)
    print(
        "  collocation sizes n (points): "
        + ", ".join(f"{n_}({c_})" for n_, c_ in zip(sizes, counts, strict=True))
    )
    print(f"  worst relative error of c       : {rel_c.max():.2e}  (target <= 1e-8)")
    print(
        f"  worst relative error of F       : {rel_F[away].max():.2e}  over the "
        f"{away.sum()} points with |F| >= 1e-3 of its terms (target <= 1e-8)"
    )
    print(f"  worst |dF| / (|Hertz| + |adhesive| term): {(dF / scale).max():.2e}  over all points")
    print(
        f"  all converged: {bool(np.all(co.converged))}; "
        f"worst separation residual {np.max(co.residual_separation):.1e}, "
        f"worst error estimate {np.max(co.error_estimate):.1e}"
    )

    # convergence with n at a thin-zone point
    a0, r0, s0 = 0.15, 5000.0, 0.2
    ref = normal_contact(a0, r0, s0)
    print(
        f"  convergence at a/R={a0}, R/h={r0:g}, sigma0/E={s0} (c/a - 1 = {ref.c_over_a - 1:.2e}):"
    )
    for n in (32, 64, 128, 256, 512):
        r = normal_contact(a0, r0, s0, method="collocation", n=n, on_failure="report")
        print(
            f"    n = {n:4d}: |dF/F| = {abs(r.F_over_Eh / ref.F_over_Eh - 1):.2e}, "
            f"error estimate {r.error_estimate:.1e}"
        )

    # pull-off for 1000 parameter pairs
    m = 1000
    ps = 10 ** rng.uniform(-4, np.log10(0.3), m)
    pr = 10 ** rng.uniform(1, 4, m)
    t_po, po = best_of(lambda: pull_off(pr, ps))
    F0 = zero_width_load(pr, ps)
    snap = np.asarray(po.mechanism) == "snap-off"
    print(
        f"pull-off, {m} parameter pairs: {t_po:.3f} s in total (target < 2 s); "
        f"{snap.sum()} snap-off, {m - snap.sum()} zero-width; "
        f"all <= Eq. 14: {bool(np.all(po.F_pulloff_over_Eh <= F0))}"
    )


if __name__ == "__main__":
    main()
