"""Benchmark of the tangential solvers: time per point and error against the closed forms.

Run: ``PYTHONPATH=src python benchmarks/tangential.py [--points 10000] [--seed 0]``.

For batches of ``--points`` points spread over tau0/E in [1e-4, 0.1] (log-uniform) and the
stick-zone parameter away from its end points (initiation: d/a in [0, 0.99]; rolling:
d/a in [-0.99, 0.99]), and for the Coulomb counterparts (mu in [0.05, 1], a/R in
[1e-4, 0.1]), it prints the time per point of the closed form and of the collocation at
default settings (given d, and given T with Newton on d), the worst relative error of T, of
the creep and of d against the closed forms, the worst error of the traction and slip
distributions on a subset, and then the convergence as the stick zone approaches its
limits (d/a -> 1 for the initiation, d/a -> -1 for rolling), where the logarithmic source
of the right-hand side approaches the end of the collocation interval.
"""

from __future__ import annotations

import argparse

import numpy as np

from _common import best_of
from linecontact import (
    sliding_initiation,
    sliding_initiation_coulomb,
    steady_rolling,
    steady_rolling_coulomb,
)
from linecontact.tangential import rolling as _rolling


def rel(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    return np.abs(a - b) / np.abs(b)


def batch(name, fn, params, d, load_name, extra_keys=()):
    N = d.size
    t_cf, cf = best_of(lambda: fn(*params, d))
    t_co, co = best_of(lambda: fn(*params, d, method="collocation"), repeat=2)
    load = getattr(cf, load_name)
    t_inv, inv = best_of(lambda: fn(*params, **{load_name: load}, method="collocation"), repeat=1)
    print(f"{name}: {N} points")
    print(f"  closed form            : {t_cf / N * 1e6:8.2f} us/point")
    print(f"  collocation, given d   : {t_co / N * 1e6:8.2f} us/point")
    print(f"  collocation, given T   : {t_inv / N * 1e6:8.2f} us/point (Newton on d)")
    sizes, counts = np.unique(co.n_collocation, return_counts=True)
    print(
        "  collocation sizes n (points): "
        + ", ".join(f"{n_}({c_})" for n_, c_ in zip(sizes, counts, strict=True))
    )
    print(
        f"  worst relative error of T      : {rel(co.T_over_Ea, cf.T_over_Ea).max():.2e}"
        f"   (target <= 1e-8)"
    )
    for key in extra_keys:
        print(
            f"  worst relative error of {key:<7}: "
            f"{rel(getattr(co, key), getattr(cf, key)).max():.2e}"
        )
    print(
        f"  given T: worst |d - d_closed|  : {np.abs(inv.d_over_a - d).max():.2e}, "
        f"worst force residual {inv.residual_force.max():.1e}"
    )
    print(
        f"  all converged: {bool(np.all(co.converged) and np.all(inv.converged))}; worst "
        f"stick residual {co.residual_stick.max():.1e}, worst error estimate "
        f"{co.error_estimate.max():.1e}"
    )
    return cf, co


def distributions(rng):
    x = np.linspace(-1, 1, 401)
    d = rng.uniform(0.0, 0.99, 200)
    cf, co = sliding_initiation(0.01, d), sliding_initiation(0.01, d, method="collocation")
    tq = np.max(np.abs(co.traction(x) - cf.traction(x))) / 0.01
    sl = np.nanmax(np.abs(co.slip(x) - cf.slip(x))) / np.nanmax(cf.slip(x))
    d = rng.uniform(-0.99, 0.99, 200)
    cf, co = steady_rolling(0.01, d), steady_rolling(0.01, d, method="collocation")
    rq = np.max(np.abs(co.traction(x) - cf.traction(x))) / 0.01
    print("distributions, 200 points x 401 positions:")
    print(
        f"  initiation: worst |q - q_closed|/tau0 {tq:.1e}, worst slip error over the "
        f"largest slip {sl:.1e}"
    )
    print(f"  rolling   : worst |q - q_closed|/tau0 {rq:.1e}")


def convergence():
    print("convergence near the limits (collocation at default settings, n='auto'):")
    print("  initiation, d/a -> 1 (full stick):")
    print("      d/a        n   rel. error of T   error estimate")
    for d in (0.9, 0.99, 0.999, 0.9999, 0.99999, 0.999999):
        c = sliding_initiation(0.01, d, method="collocation", on_failure="report")
        f = sliding_initiation(0.01, d)
        print(
            f"  {d:>9}  {c.n_collocation:>5}   {rel(c.T_over_Ea, f.T_over_Ea):.1e}"
            f"           {c.error_estimate:.1e}{'' if c.converged else '  (not converged)'}"
        )
    print("  rolling, d/a -> -1 (full stick), and d/a -> 1 (full slip):")
    print("      d/a        n   rel. error of T   rel. error of creep   error estimate")
    for d in (-0.9, -0.99, -0.999, -0.9999, -0.99999, -0.999999, 0.99, 0.99999, 1 - 1e-9):
        c = steady_rolling(0.01, d, method="collocation", on_failure="report")
        f = steady_rolling(0.01, d)
        print(
            f"  {d:>9.9g}  {c.n_collocation:>5}   {rel(c.T_over_Ea, f.T_over_Ea):.1e}"
            f"           {rel(c.creep_over_V, f.creep_over_V):.1e}"
            f"               {c.error_estimate:.1e}"
            f"{'' if c.converged else '  (not converged)'}"
        )
    print(
        "  fixed n, relative error of T (initiation, d/a = 0.999) and of the creep "
        "(rolling, d/a = -0.999):"
    )
    print("        n   initiation    rolling   rolling, paper's linear split (Eq 25), d/a = 0")
    f_i = sliding_initiation(1.0, 0.999).T_over_Ea
    f_r = steady_rolling(1.0, -0.999).creep_over_V
    f_0 = steady_rolling(1.0, 0.0).creep_over_V
    for n in (16, 64, 256, 1024, 4096):
        ci = sliding_initiation(1.0, 0.999, method="collocation", n=n, on_failure="report")
        cr = steady_rolling(1.0, -0.999, method="collocation", n=n, on_failure="report")
        lin = -2 * _rolling._roll_solve(np.array([0.0]), n, "linear").extra[0]
        print(
            f"  {n:>7}   {rel(ci.T_over_Ea, f_i):.1e}      {rel(cr.creep_over_V, f_r):.1e}"
            f"    {rel(lin, f_0):.1e}"
        )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=10_000)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)
    N = args.points
    t0 = 10 ** rng.uniform(-4, -1, N)
    mu = rng.uniform(0.05, 1.0, N)
    A = 10 ** rng.uniform(-4, -1, N)
    d_init = rng.uniform(0.0, 0.99, N)
    d_roll = rng.uniform(-0.99, 0.99, N)
    print(
        "tau0/E in [1e-4, 0.1]; initiation d/a in [0, 0.99]; rolling d/a in [-0.99, 0.99]; "
        "Coulomb mu in [0.05, 1], a/R in [1e-4, 0.1]\n"
    )
    batch("initiation of sliding, constant tau0", sliding_initiation, (t0,), d_init, "T_over_Ea")
    batch(
        "steady rolling, constant tau0",
        steady_rolling,
        (t0,),
        d_roll,
        "T_over_Ea",
        ("creep_over_V",),
    )
    batch("Cattaneo-Mindlin (Coulomb)", sliding_initiation_coulomb, (mu, A), d_init, "T_over_muF")
    batch(
        "Carter (Coulomb)", steady_rolling_coulomb, (mu, A), d_roll, "T_over_muF", ("creep_over_V",)
    )
    print()
    distributions(rng)
    print()
    convergence()


if __name__ == "__main__":
    main()
