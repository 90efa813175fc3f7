"""The bent wire's fit (linecontact.bent_wire.fit_bent_wire): its time, its error, its intervals.

    python benchmarks/bent_wire.py [--draws 20] [--boot-draws 5]

On the ZnO wire of issue 35 (D = 100 nm, L = 5 um, E = 140 GPa, so EI = E pi r^4/4 =
6.87e-19 N m^2; dragged at its midpoint against f = 12 nN/um), with profiles made here by a
second solver (shooting with SciPy's ``solve_ivp`` and ``brentq``, as in
``tests/test_bent_wire_fit.py``, not the library's collocation), sampled at equal arc
lengths, turned and moved, prints:

- the best-of-3 wall time of a 500-point fit with its intervals (the covariance and a
  bootstrap of 200 refits; the issue asks under 1 s) and of the fit alone (``bootstrap=0``);
- the relative error of f for noiseless profiles at several loads (500 points);
- at 2 nm and 10 nm of position noise (500 points, and 250 points: the issue's 20 nm
  pixels), over ``--draws`` noise draws: the mean error of f (its bias), the scatter of f
  from draw to draw, the median width of the covariance's 95 % interval (and how often it
  covered the truth), all relative to f; and over ``--boot-draws`` draws the median width of
  the bootstrap's 95 % interval (200 refits).

Measured on the 2-core development machine: the fit with its intervals 0.535 s (best of
3, load 0.8, after a cell's two ends were gathered at once and the refits' feet moved by one
Newton step; 0.64-1.00 s before, at c988a3d, on a shared machine), the fit alone 0.008 s;
the noiseless errors of f below 1e-11 for groups 0.03 to 27 (end lags 0.3 % to 86 % of l); at
2 nm noise and 500 points the scatter of f 0.33 % and the 95 % intervals 1.4 % wide
(covariance and bootstrap alike), at 10 nm 1.7 % and 7.1-7.3 %; at 250 points 0.31 % and
1.9 %, 2.4 % and 9.2-9.6 %; the covariance's intervals covered the truth in 79 of 80 draws
(c988a3d).
``--draws 0`` prints the times and the noiseless errors alone.
"""

from __future__ import annotations

import argparse
import functools
import math

import numpy as np

from _common import best_of
from linecontact.bent_wire import fit_bent_wire

MODULUS, RADIUS = 140e9, 50e-9  # Pa, m
EI = MODULUS * math.pi * RADIUS**4 / 4  # N m^2
HALF = 2.5e-6  # m
F_TRUE = 12e-3  # N/m (12 nN/um)


@functools.cache
def _half(lam: float):
    """The half wire at the group ``lam`` by shooting: (theta, kappa, x, y) of u in [0, 1]."""
    from scipy.integrate import solve_ivp
    from scipy.optimize import brentq

    def rhs(u, z):
        th, k, _, _ = z
        return [k, lam * (1 - u) * np.cos(th), np.cos(th), np.sin(th)]

    def end_curvature(k0):
        return solve_ivp(rhs, (0, 1), [0.0, k0, 0.0, 0.0], rtol=1e-12, atol=1e-13).y[1, -1]

    k0 = brentq(end_curvature, -lam - 1e-9, 1e-12, xtol=1e-15) if lam > 0 else 0.0
    return solve_ivp(
        rhs, (0, 1), [0.0, k0, 0.0, 0.0], rtol=1e-12, atol=1e-13, dense_output=True
    ).sol


def profile(f: float, n: int, noise: float = 0.0, rng=None, angle: float = 0.4):
    """``n`` points at equal arc lengths along the wire [m], turned by ``angle``, noisy."""
    s = np.linspace(-1.0, 1.0, n)
    z = _half(f * HALF**3 / EI)(np.abs(s))
    x, y = np.sign(s) * z[2] * HALF, z[3] * HALF
    c, sn = math.cos(angle), math.sin(angle)
    X, Y = c * x - sn * y + 3e-6, sn * x + c * y - 1e-6
    if noise:
        X = X + noise * rng.standard_normal(n)
        Y = Y + noise * rng.standard_normal(n)
    return X, Y


def timing() -> None:
    x, y = profile(F_TRUE, 500, 2e-9, np.random.default_rng(0))
    fit_bent_wire(x, y, EI, bootstrap=20)  # the imports and caches, outside the times
    t_full, full = best_of(lambda: fit_bent_wire(x, y, EI, bootstrap=200))
    t_fit, _ = best_of(lambda: fit_bent_wire(x, y, EI, bootstrap=0))
    print("time, 500 points, 2 nm noise (best of 3):")
    print(f"  fit with its intervals (covariance, 200 bootstrap refits): {t_full:.3f} s")
    print(f"  fit alone (bootstrap=0):                                   {t_fit:.3f} s")
    print(f"  bootstrap refits that did not converge: {full.bootstrap_failed} of 200")


def noiseless() -> None:
    print("\nnoiseless profiles, 500 points: f against the truth")
    print("  f [nN/um]   f l^3/EI   end lag/l   relative error of f")
    for f in (1.2e-3, 12e-3, 60e-3, 240e-3, 1.2):
        lam = f * HALF**3 / EI
        fit = fit_bent_wire(*profile(f, 500), EI, bootstrap=0)
        lag = -_half(lam)(1.0)[3]
        print(
            f"  {f * 1e3:9.4g}   {lam:8.4g}   {lag:9.4f}   {fit.friction_per_length / f - 1:+.2e}"
        )


def noisy(draws: int, boot_draws: int) -> None:
    print(
        f"\nf = {F_TRUE * 1e3:g} nN/um with position noise: relative to f, over {draws} draws "
        f"(bootstrap: {boot_draws} draws of 200 refits)"
    )
    print(
        "  points  noise   bias of f   scatter of f   95 % width, covariance (covered)   "
        "95 % width, bootstrap"
    )
    for n in (500, 250):
        for noise in (2e-9, 10e-9):
            rng = np.random.default_rng([n, round(noise * 1e10)])
            f, width, hit = [], [], 0
            boot = []
            for k in range(draws):
                x, y = profile(F_TRUE, n, noise, rng, angle=rng.uniform(-math.pi, math.pi))
                b = 200 if k < boot_draws else 0
                fit = fit_bent_wire(x, y, EI, bootstrap=b, seed=k)
                lo, hi = fit.friction_per_length_ci95
                f.append(fit.friction_per_length)
                width.append((hi - lo) / F_TRUE)
                hit += lo <= F_TRUE <= hi
                if b:
                    b_lo, b_hi = fit.friction_per_length_bootstrap_ci95
                    boot.append((b_hi - b_lo) / F_TRUE)
            rel = np.array(f) / F_TRUE - 1
            bias, scatter = np.mean(rel), np.std(rel, ddof=1)
            print(
                f"  {n:6d}  {noise * 1e9:3.0f} nm  {bias:+9.2%}   {scatter:10.2%}"
                f"     {np.median(width):10.2%} ({hit:2d} of {draws})"
                f"                {np.median(boot) if boot else math.nan:8.2%}"
            )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--draws", type=int, default=20, help="noise draws per case")
    parser.add_argument("--boot-draws", type=int, default=5, help="of them with a bootstrap")
    args = parser.parse_args()
    print(f"ZnO wire: EI = {EI:.4g} N m^2, l = {HALF * 1e6:g} um\n")
    timing()
    noiseless()
    if args.draws > 0:
        noisy(args.draws, min(args.boot_draws, args.draws))


if __name__ == "__main__":
    main()
