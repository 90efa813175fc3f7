"""The joint pull-off fit: its time with and without the bootstrap, the refits batched or not.

    python benchmarks/fits.py

On the worked example of ``docs/inverse.md`` (``examples/fit_pull_off.py``: silica on
silicon, five radii, w = 0.1 J/m^2 and z0 = 0.3 nm with 3 % noise, seed 2026; the stated
uncertainties make the relative sd of z0 14 %, so ``bootstrap="auto"`` draws 100 refits)
and on a second draw with 5 % noise and no stated uncertainties, prints the best-of-3 wall
time of ``fit_pull_off`` without the bootstrap, with its 100 refits solved all at once (the
library), and with them one by one (``_refit_rows`` replaced here, as before the batch: each
refit by :func:`scipy.optimize.least_squares`), the ratio, and the largest relative
difference of the 95 % intervals between the two.

Measured on the 2-core development machine, shared (load 2 to 6), one BLAS thread (noisy:
ratios hold better than times), the example with ``bootstrap="auto"``: main before the batch
(f3aa003) 0.05-0.07 s without the bootstrap, 2.5-2.7 s with it; batched 0.05-0.07 s and
0.07-0.10 s (one by one 25-40x the batch; the issue, on a quieter machine, 1.05 s against
24 ms before). The intervals agree with the one-by-one ones to 1e-8.
"""

from __future__ import annotations

import numpy as np

import linecontact as lc
from _common import best_of
from linecontact import fits

RADII = np.array([10e-9, 40e-9, 160e-9, 640e-9, 2560e-9])  # m
E = float(lc.composite_modulus(72e9, 0.17, 163e9, 0.22))  # SiO2 on Si [Pa]


def one_by_one(fun, Fd, sig, start, lo, hi):
    """No batch: every refit left to ``fits._solve``, as the bootstrap was before."""
    return np.full((len(Fd), start.size), np.nan)


def case(name: str, F: np.ndarray, sd: np.ndarray | None) -> None:
    t0, _ = best_of(lambda: fits.fit_pull_off(RADII, F, E, sd=sd, bootstrap=0))
    t1, fast = best_of(lambda: fits.fit_pull_off(RADII, F, E, sd=sd, bootstrap=100))
    batched = fits._refit_rows
    fits._refit_rows = one_by_one
    try:
        t2, slow = best_of(lambda: fits.fit_pull_off(RADII, F, E, sd=sd, bootstrap=100))
    finally:
        fits._refit_rows = batched
    keys = ("work_of_adhesion_ci95", "equilibrium_spacing_ci95")
    diff = max(
        float(np.max(np.abs(np.subtract(getattr(fast, k), getattr(slow, k))) / getattr(slow, k)))
        for k in keys
    )
    print(f"{name}:")
    print(f"  fit without the bootstrap:             {t0:.3f} s")
    print(f"  fit with 100 refits, batched:          {t1:.3f} s")
    print(f"  fit with 100 refits, one by one:       {t2:.3f} s ({t2 / t1:.1f}x the batch)")
    print(f"  largest relative difference of the 95 % intervals: {diff:.1e}")


def main() -> None:
    F_true = fits.pull_off_force(RADII, E, 0.1, 0.3e-9)
    F = F_true * (1 + 0.03 * np.random.default_rng(2026).standard_normal(RADII.size))
    fits.fit_pull_off(RADII, F, E, bootstrap=0)  # the imports and caches, outside the times
    case("worked example (3 % noise, stated sd)", F, 0.03 * np.abs(F))
    F = F_true * (1 + 0.05 * np.random.default_rng(1).standard_normal(RADII.size))
    case("5 % noise, no stated sd", F, None)


if __name__ == "__main__":
    main()
