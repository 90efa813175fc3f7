"""Shared pieces of the benchmark scripts: the timer and the normal-contact parameter sample."""

from __future__ import annotations

import time
import warnings

import numpy as np

from linecontact import ModelValidityWarning

# the benchmark domains reach past the small-strain range (a/R > 0.2) on purpose
warnings.simplefilter("ignore", ModelValidityWarning)


def best_of(fn, repeat=3):
    """Best wall time of ``repeat`` calls of ``fn`` and the last result."""
    best = np.inf
    out = None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def sample_normal(n: int, rng: np.random.Generator):
    """a/R, R/h, sigma0/E over the benchmark domain, a tenth pushed to thin adhesive zones.

    sigma0/E in [1e-4, 0.3], R/h in [10, 1e4], a/R in (1e-4, 0.2], log-uniform; the first
    n // 10 points have strong adhesion, large radius and wide contact (c/a -> 1).
    """
    s = 10 ** rng.uniform(-4, np.log10(0.3), n)
    rho = 10 ** rng.uniform(1, 4, n)
    A = 10 ** rng.uniform(-4, np.log10(0.2), n)
    k = n // 10
    s[:k] = 10 ** rng.uniform(-1, np.log10(0.3), k)
    rho[:k] = 10 ** rng.uniform(3, 4, k)
    A[:k] = rng.uniform(0.1, 0.2, k)
    return A, rho, s
