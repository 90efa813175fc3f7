"""Propagating standard uncertainties: Monte Carlo and linear, through any vectorised function.

:func:`propagate` draws the inputs that have a standard uncertainty from normal
distributions (a positive input's draws truncated at zero), runs the function on all of
them at once (a batch that raises is split, so a failing draw costs a few calls) and gives
an :class:`Estimate`: the value, the Monte Carlo standard deviation and 95 % interval, and
the linearised ones beside them. The inverse problems of :mod:`linecontact.inverse`
re-export both; given ``on_failure="report"``, its inversions give nan for a draw no
solution reaches, so that :func:`propagate` runs each batch once instead of splitting it.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np
from numpy.typing import NDArray

from .errors import ModelValidityWarning
from .results import Result

__all__ = ["Estimate", "propagate"]


@dataclass(frozen=True)
class Estimate(Result):
    """A derived quantity with its standard uncertainty and 95 % interval.

    Attributes
    ----------
    value : float
        At the inputs' values.
    sd, ci95 : float, (float, float)
        By Monte Carlo: the standard deviation and the 2.5 %/97.5 % percentiles of the
        samples that have a solution.
    sd_linear, ci95_linear : float, (float, float)
        Linearised: ``sqrt(sum (df/dx_i sd_i)^2)`` by central differences, ``value +- 1.96 sd``.
    n_samples, n_failed, seed : int
        Samples drawn, samples without a solution (a pull-off no ``w`` reaches, a load below
        pull-off), the seed.
    """

    inputs: ClassVar[tuple[str, ...]] = ("n_samples", "seed")
    whole: ClassVar[tuple[str, ...]] = ("ci95", "ci95_linear")

    value: float
    sd: float
    ci95: tuple[float, float]
    sd_linear: float
    ci95_linear: tuple[float, float]
    n_samples: int
    n_failed: int
    seed: int


def propagate(
    fn: Callable[..., NDArray],
    values: Mapping[str, float],
    sds: Mapping[str, float],
    *,
    n_samples: int = 4000,
    seed: int = 0,
) -> Estimate:
    """Propagate standard uncertainties of the inputs through ``fn`` (Monte Carlo and linear).

    ``fn(**inputs)`` must accept arrays (every function of this module does). Inputs with a
    standard uncertainty are drawn from normal distributions (samples of a positive input
    that fall at or below zero are redrawn: the distribution is truncated); a sample for
    which ``fn`` raises or returns a non-finite value counts in ``n_failed``. A batch that
    raises is split until the failing samples are found; a function that gives NaN where it
    has no solution (the inversions of :mod:`linecontact.inverse` with
    ``on_failure="report"``) runs once per batch, with the same result.

    Examples
    --------
    >>> from linecontact.inverse import pull_off_force, work_of_adhesion_from_pull_off
    >>> F = float(pull_off_force(50e-9, 50e9, 0.1, 0.3e-9))
    >>> x = dict(pull_off_force=F, radius=50e-9, modulus=50e9, equilibrium_spacing=0.3e-9)
    >>> from functools import partial
    >>> fn = partial(work_of_adhesion_from_pull_off, on_failure="report")
    >>> e = propagate(fn, x, dict(radius=2e-9), n_samples=2000)
    >>> round(e.value, 10), bool(0.001 < e.sd < 0.01), bool(abs(e.sd / e.sd_linear - 1) < 0.1)
    (0.1, True, True)
    """
    if (
        not isinstance(n_samples, (int, np.integer))
        or isinstance(n_samples, bool)
        or not (10 <= n_samples <= 10_000_000)
    ):
        raise ValueError(f"n_samples must be an integer in [10, 1e7], got {n_samples!r}")
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise ValueError(f"seed must be an integer >= 0, got {seed!r}")
    for k, v in sds.items():
        if k not in values:
            raise ValueError(f"an uncertainty is given for {k!r}, which is not an input")
        if isinstance(v, (bool, str)) or not (
            isinstance(v, (int, float, np.integer, np.floating)) and np.isfinite(v) and v >= 0
        ):
            raise ValueError(f"the standard uncertainty of {k} must be finite and >= 0, got {v!r}")
    try:
        x0 = {k: float(v) for k, v in values.items()}
    except (TypeError, ValueError):
        raise ValueError(f"values must be numbers, got {dict(values)!r}") from None
    try:
        value = float(np.asarray(fn(**x0)))
    except TypeError as exc:
        raise ValueError(f"fn does not take these inputs ({', '.join(x0)}): {exc}") from None
    if not any(sd > 0 for sd in sds.values()):  # nothing drawn: exact, not round-off
        return Estimate(
            value, 0.0, (value, value), 0.0, (value, value), int(n_samples), 0, int(seed)
        )
    rng = np.random.default_rng(seed)
    samples: dict[str, Any] = dict(x0)
    for k, sd in sds.items():
        if sd == 0:
            continue
        draw = rng.normal(x0[k], sd, n_samples)
        if x0[k] > 0:  # a positive quantity: truncate at zero
            for _ in range(100):
                bad = draw <= 0
                if not bad.any():
                    break
                draw[bad] = rng.normal(x0[k], sd, int(bad.sum()))
        samples[k] = draw
    with warnings.catch_warnings():  # a draw outside small strain: said once for the value
        warnings.simplefilter("ignore", ModelValidityWarning)
        out = _robust(fn, samples, np.arange(n_samples))
    ok = np.isfinite(out)
    n_failed = int(n_samples - ok.sum())
    good = out[ok]
    if good.size >= 2:
        sd_mc = float(np.std(good, ddof=1))
        lo, hi = (float(v) for v in np.percentile(good, [2.5, 97.5]))
    else:
        sd_mc, lo, hi = math.nan, math.nan, math.nan
    var = 0.0
    for k, sd in sds.items():
        if sd == 0:
            continue
        step = 1e-6 * (abs(x0[k]) or sd)  # inside a positive input's range
        up, dn = dict(x0), dict(x0)
        up[k], dn[k] = x0[k] + step, x0[k] - step
        try:
            g = (float(np.asarray(fn(**up))) - float(np.asarray(fn(**dn)))) / (2 * step)
        except ValueError:
            g = math.nan
        var += (g * sd) ** 2
    sd_lin = math.sqrt(var)
    return Estimate(
        value,
        sd_mc,
        (lo, hi),
        sd_lin,
        (value - 1.96 * sd_lin, value + 1.96 * sd_lin),
        int(n_samples),
        n_failed,
        int(seed),
    )


def _robust(fn, samples: dict[str, Any], idx: NDArray) -> NDArray:
    """``fn`` on the samples ``idx``, nan where a sample fails.

    A batch that raises is split in halves, so a few failing draws cost a few calls, not one
    per sample.
    """
    batch = {k: (v[idx] if np.ndim(v) else v) for k, v in samples.items()}
    try:
        out = np.asarray(fn(**batch), float)
        return np.broadcast_to(out, idx.shape).copy()
    except ValueError:
        if idx.size == 1:
            return np.full(1, np.nan)
    half = idx.size // 2
    return np.concatenate([_robust(fn, samples, idx[:half]), _robust(fn, samples, idx[half:])])
