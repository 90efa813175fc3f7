"""Benchmark of the normal (Maugis-Dugdale) solvers: time per point and agreement.

Run: ``python benchmarks/normal.py [--points 100000] [--seed 0]``.

Prints, for a batch spread over sigma0/E in [1e-4, 0.3], R/h in [10, 1e4] and a/R in (0, 0.2]
(log-uniform, with a tenth of the batch pushed to the thin-zone, JKR-like end), the time per
point of the collocation solver and of the closed form, their ratio, the worst disagreement
of F and c between them, and the time of the pull-off search for 1,000 parameter pairs.
"""

from __future__ import annotations

import argparse

import numpy as np

from _common import best_of, sample_normal
from linecontact import normal_contact, pull_off, zero_width_load


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=100_000)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)
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
