r"""The pull-off inverse problems: the forward model, ``w`` from one pull-off, ``(w, z0)`` fitted.

Split from :mod:`linecontact.inverse`, which re-exports every public name (``from
linecontact.inverse import fit_pull_off`` keeps working); the forward model and ``w`` from one
pull-off live in :mod:`linecontact._pull_off_model`, re-exported here:

* :func:`pull_off_force`: the Maugis--Dugdale pull-off force of a cylinder in SI units, with the
  adhesion given as ``(w, z0)`` (:math:`\sigma_0 = 16 w/(9 \sqrt{3} z_0)`, :math:`h = w/\sigma_0`);
  the JKR and rigid (DMT) limits :func:`jkr_pull_off_force`, :func:`dmt_pull_off_force` and the work
  of adhesion they alone would give (:func:`simple_model_work_of_adhesion`);
* :func:`work_of_adhesion_from_pull_off`: the model solved for ``w`` at a known radius,
  modulus and range;
* :func:`fit_pull_off`: ``(w, z0)`` jointly, or ``w`` alone at a fixed ``z0``, from pull-off
  forces at several radii (:class:`AdhesionFit`, a :class:`~linecontact.results.Result`).

Units: SI throughout (m, Pa, N/m, J/m^2); pull-off forces are negative (tensile).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import closed_forms as _cf
from ._least_squares import _refit_rows, _solve
from ._progress import progress_bar
from ._pull_off_model import (
    S_LJ,
    _work_from_pull_off,
    dmt_pull_off_force,
    jkr_pull_off_force,
    pull_off_force,
    pull_off_force_at,
    simple_model_work_of_adhesion,
    work_of_adhesion_from_pull_off,
)
from ._validation import check_array
from .cylinder import _check_cylinder_si, _plausible
from .results import Result
from .sphere.fits import _covariance, _log_covariance, _on_bounds

__all__ = [
    "AdhesionFit",
    "ShearStrengthFit",
    "dmt_pull_off_force",
    "fit_pull_off",
    "fit_shear_strength",
    "jkr_pull_off_force",
    "pull_off_force",
    "simple_model_work_of_adhesion",
    "work_of_adhesion_from_pull_off",
]

# --------------------------------------------------------------------------------------------
# joint fit of (w, z0) to pull-off forces at several radii


@dataclass(frozen=True)
class AdhesionFit(Result):
    """``(w, z0)`` (or ``w`` at a fixed ``z0``) fitted to pull-off forces at several radii.

    Attributes
    ----------
    work_of_adhesion, equilibrium_spacing : float
        The fit [J/m^2], [m] (``equilibrium_spacing`` as given when it was fixed).
    work_of_adhesion_sd, equilibrium_spacing_sd : float
        Standard uncertainties from the covariance (``0`` for a fixed ``z0``).
    work_of_adhesion_ci95, equilibrium_spacing_ci95 : (float, float)
        95 % intervals by parametric bootstrap (refits to the model plus noise of the
        data's standard deviations); ``*_ci95_linear`` from the covariance in the log
        parameters.
    covariance : ndarray, shape (2, 2)
        Of ``(w, z0)`` [J/m^2, m] (linearised at the fit; zero row and column for a fixed
        ``z0``).
    correlation : float
        Between ``w`` and ``z0`` (nan for a fixed ``z0``).
    residuals : ndarray
        ``F_model - F_measured`` [N/m] at the data points.
    model : ndarray
        The fitted pull-off forces at the data's radii [N/m].
    chi2 : float
        Sum of squared weighted residuals; ``dof`` the degrees of freedom.
    identifiable : bool
        Whether the data determine ``z0`` (its relative uncertainty below 50 % and the
        correlation below 0.999 in magnitude); ``note`` says why not.
    work_of_adhesion_sd_inputs, equilibrium_spacing_sd_inputs : float
        The standard uncertainties that the inputs' uncertainties (``modulus_sd``, and
        ``equilibrium_spacing_sd`` of a fixed ``z0``) add, by refits with the inputs drawn
        (``0`` without them; for a fixed ``z0``, its own ``equilibrium_spacing_sd``);
        ``*_sd_total`` (properties) combine them with the data's, in quadrature.
    """

    inputs: ClassVar[tuple[str, ...]] = ("fixed_spacing",)
    whole: ClassVar[tuple[str, ...]] = (
        "work_of_adhesion_ci95",
        "equilibrium_spacing_ci95",
        "work_of_adhesion_ci95_linear",
        "equilibrium_spacing_ci95_linear",
        "covariance",
    )
    derived: ClassVar[tuple[str, ...]] = (
        "work_of_adhesion_sd_total",
        "equilibrium_spacing_sd_total",
    )

    work_of_adhesion: float
    equilibrium_spacing: float
    work_of_adhesion_sd: float
    equilibrium_spacing_sd: float
    work_of_adhesion_ci95: tuple[float, float]
    equilibrium_spacing_ci95: tuple[float, float]
    work_of_adhesion_ci95_linear: tuple[float, float]
    equilibrium_spacing_ci95_linear: tuple[float, float]
    covariance: NDArray
    correlation: float
    residuals: NDArray
    model: NDArray
    chi2: float
    dof: int
    fixed_spacing: bool
    identifiable: bool
    note: str
    radius: NDArray = field(repr=False)
    pull_off_force: NDArray = field(repr=False)
    sd: NDArray = field(repr=False)
    modulus: float = field(repr=False, default=math.nan)
    work_of_adhesion_sd_inputs: float = 0.0
    equilibrium_spacing_sd_inputs: float = 0.0

    @property
    def work_of_adhesion_sd_total(self) -> float:
        """The standard uncertainty of ``w`` from the data and the inputs [J/m^2]."""
        return math.hypot(self.work_of_adhesion_sd, self.work_of_adhesion_sd_inputs)

    @property
    def equilibrium_spacing_sd_total(self) -> float:
        """The standard uncertainty of ``z0`` from the data and the inputs [m]."""
        return math.hypot(self.equilibrium_spacing_sd, self.equilibrium_spacing_sd_inputs)


def fit_pull_off(
    radius: ArrayLike,
    pull_off_force: ArrayLike,
    modulus: float,
    *,
    sd: ArrayLike | None = None,
    equilibrium_spacing: float | None = None,
    bootstrap: int | str = "auto",
    seed: int = 0,
    modulus_sd: float = 0.0,
    equilibrium_spacing_sd: float = 0.0,
    samples: int = 100,
    progress: bool | None = False,
) -> AdhesionFit:
    r"""Fit the work of adhesion (and the range) to pull-off forces at several radii.

    Weighted least squares on the Maugis--Dugdale pull-off (:func:`pull_off_force`) in the
    parameters :math:`\ln w` and :math:`\ln z_0`. The radius dependence separates them in the
    transition regime: :math:`F \sim w \sqrt{R/z_0}` for a rigid-like contact (small Maugis
    parameter), :math:`F \sim (w^2 E R)^{1/3}`, independent of :math:`z_0`, in the JKR limit; data
    all in the JKR regime do not determine ``z0`` (``identifiable`` is False and ``note`` says so:
    fix ``equilibrium_spacing``).

    Parameters
    ----------
    radius, pull_off_force : array_like, 1-D
        The data [m], [N/m] (negative).
    modulus : float
        Composite plane-strain modulus ``E`` [Pa].
    sd : array_like, optional
        Standard uncertainties of the forces [N/m]; without them the weights are equal and
        the scatter of the residuals sets the uncertainty.
    equilibrium_spacing : float, optional
        Fix ``z0`` [m] and fit ``w`` alone (one point suffices).
    bootstrap : int or "auto"
        Parametric-bootstrap refits for the 95 % intervals (0: none, the linear ones are
        copied; ``"auto"``: 100 where the linear interval is poor, a relative standard
        uncertainty of a parameter above 10 %, else none). Solved all at once (batched
        damped Newton steps through the vectorised model, :func:`_refit_rows`) where the data
        determine ``(w, z0)``; one by one, as the fit itself, where they do not (the cost
        may have several minima), and for a refit the batch leaves or ends on a bound.
    seed : int
        Of the bootstrap (``seed + 1``: of the inputs' draws).
    modulus_sd : float
        The standard uncertainty of ``modulus`` [Pa].
    equilibrium_spacing_sd : float
        The standard uncertainty of a fixed ``equilibrium_spacing`` [m].
    samples : int
        Refits with the modulus (and a fixed ``z0``) drawn from normal distributions, for
        the uncertainty they add (``work_of_adhesion_sd_inputs``, ...; draws at or below
        zero and refits without a solution are skipped). Only with ``modulus_sd`` or
        ``equilibrium_spacing_sd``.
    progress : bool or None, default False
        A progress bar of the refits (bootstrap and ``samples``) on stderr: shown (True),
        not (False), or where stderr is a terminal (None).

    Returns
    -------
    AdhesionFit

    Examples
    --------
    >>> R = np.array([20e-9, 50e-9, 100e-9, 200e-9, 500e-9])
    >>> F = pull_off_force(R, 50e9, 0.1, 0.3e-9)
    >>> fit = fit_pull_off(R, F, 50e9, bootstrap=0)
    >>> round(fit.work_of_adhesion, 8), round(fit.equilibrium_spacing * 1e9, 6)
    (0.1, 0.3)

    A 5 % uncertainty of the modulus, propagated by refits:

    >>> fit = fit_pull_off(R, F, 50e9, bootstrap=0, modulus_sd=2.5e9)
    >>> bool(0 < fit.work_of_adhesion_sd_inputs < 0.01), fit.work_of_adhesion_sd_total > 0
    (True, True)
    """
    R = check_array("radius", radius).reshape(-1)
    F = check_array("pull_off_force", pull_off_force, low=-np.inf, high=0.0).reshape(-1)
    if R.size != F.size:
        raise ValueError(
            f"radius and pull_off_force must have one length, got {R.size} and {F.size}"
        )
    E_arr = check_array("modulus", modulus)
    if E_arr.ndim != 0:
        raise ValueError(
            f"modulus must be a single number [Pa], got an array of shape {E_arr.shape}"
        )
    E = float(E_arr)
    _plausible("radius", R)
    _plausible("modulus", E)
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise ValueError(f"seed must be an integer >= 0, got {seed!r}")
    fixed = equilibrium_spacing is not None
    for name, v in (("modulus_sd", modulus_sd), ("equilibrium_spacing_sd", equilibrium_spacing_sd)):
        if isinstance(v, (bool, str)) or not (
            isinstance(v, (int, float, np.integer, np.floating)) and math.isfinite(v) and v >= 0
        ):
            raise ValueError(f"{name} must be a finite number >= 0, got {v!r}")
    if equilibrium_spacing_sd and not fixed:
        raise ValueError(
            "equilibrium_spacing_sd needs a fixed equilibrium_spacing (a joint fit estimates z0)"
        )
    if not _is_count(samples, 2):
        raise ValueError(f"samples must be an integer in [2, 1e5], got {samples!r}")
    n_par = 1 if fixed else 2
    if R.size < n_par + (0 if fixed else 1):
        raise ValueError(
            f"a joint fit of (w, z0) needs at least 3 data points, got {R.size}: give more "
            "radii, or fix equilibrium_spacing"
            if not fixed
            else "give at least one data point"
        )
    if not fixed and np.unique(R).size < 3:
        raise ValueError(
            f"a joint fit of (w, z0) needs at least 3 distinct radii, got {np.unique(R).size}: "
            "the radius dependence is what separates w from z0 (or fix equilibrium_spacing)"
        )
    if sd is None:
        sig = np.ones_like(F)
        have_sd = False
    else:
        sig = check_array("sd", sd).reshape(-1)
        if sig.size != F.size:
            raise ValueError(f"sd must have one value per data point ({F.size}), got {sig.size}")
        rel = sig / np.abs(F)
        if np.any((rel < 1e-12) | (rel > 1e6)):
            i = int(np.flatnonzero((rel < 1e-12) | (rel > 1e6))[0])
            raise ValueError(
                f"sd of data point {i + 1} is {float(sig[i])!r} for a force of {float(F[i])!r} "
                "N/m: the weights need sd between 1e-12 and 1e6 times the force"
            )
        have_sd = True
    if bootstrap != "auto" and not _is_count(bootstrap, 0):
        raise ValueError(f"bootstrap must be 'auto' or an integer in [0, 1e5], got {bootstrap!r}")
    z_fixed = 0.0
    if equilibrium_spacing is not None:
        z_arr = check_array("equilibrium_spacing", equilibrium_spacing)
        if z_arr.ndim != 0:
            raise ValueError("equilibrium_spacing must be a single number [m] (or None to fit it)")
        z_fixed = float(z_arr)
        _check_cylinder_si(R, E, {"work_of_adhesion": None, "equilibrium_spacing": z_fixed})

    def model(p, R=R):
        w = math.exp(p[0])
        z0 = z_fixed if fixed else math.exp(p[1])
        return pull_off_force_at(R, np.full(R.shape, E), np.full(R.shape, w), np.full(R.shape, z0))

    # ln w in [ln 1e-8, ln 1e3] J/m^2, ln z0 in [ln 1e-12, ln 1e-7] m
    lo = np.log([1e-8, 1e-12])[:n_par]
    hi = np.log([1e3, 1e-7])[:n_par]

    def solve(Fd, start):
        return _solve(model, Fd, sig, start, lo, hi)

    # start: per point w at trial ranges, the best median
    best = None
    for z_try in [z_fixed] if fixed else [0.15e-9, 0.4e-9, 1.5e-9]:
        try:
            w_pts = _work_from_pull_off(F, R, E, z_try, rtol=1e-4)
        except ValueError:
            continue
        p0 = np.log([float(np.median(w_pts))] + ([] if fixed else [z_try]))
        cost = float(np.sum(((model(p0) - F) / sig) ** 2))
        if best is None or cost < best[0]:
            best = (cost, p0)
    if best is None:
        raise ValueError(
            "no work of adhesion reproduces these pull-off forces at any trial range: check "
            "their sign (tensile pull-off forces are negative) and units (N/m)"
        )
    res = solve(F, best[1])
    p = res.x
    J = res.jac
    resid = model(p) - F
    chi2 = float(np.sum((resid / sig) ** 2))
    dof = F.size - n_par
    scale = 1.0 if have_sd else (chi2 / dof if dof > 0 else math.nan)
    # the correlation does not depend on the scale (zero for an exact fit without sds)
    cov_log, corr = _log_covariance(J, scale)
    w = math.exp(p[0])
    z0 = z_fixed if fixed else math.exp(p[1])
    cov = _covariance(cov_log, w, z0)
    sd_log = np.sqrt(np.clip(np.diag(cov_log), 0, None))
    w_sd = float(np.sqrt(cov[0, 0]))
    z_sd = float(np.sqrt(cov[1, 1]))
    with np.errstate(over="ignore"):  # a parameter the data do not determine: inf
        ci_lin_w = (float(w * np.exp(-1.96 * sd_log[0])), float(w * np.exp(1.96 * sd_log[0])))
        ci_lin_z = (
            (z0, z0)
            if fixed
            else (float(z0 * np.exp(-1.96 * sd_log[1])), float(z0 * np.exp(1.96 * sd_log[1])))
        )
    ci_w, ci_z = ci_lin_w, ci_lin_z
    identifiable = True
    note = ""
    exact = not have_sd and chi2 <= 1e-24 * float(np.sum(F * F))
    if not fixed:
        lam = _cf.maugis_parameter(R / (z0 / S_LJ), S_LJ * w / (z0 * E))
        loose = not exact and not z_sd / z0 < 0.5
        if loose or not abs(corr) < 0.999:
            identifiable = False
            note = (
                f"the data do not determine z0 (relative uncertainty {z_sd / z0:.2g}, "
                f"correlation with w {corr:.4f}): Maugis parameter {float(np.min(lam)):.3g} to "
                f"{float(np.max(lam)):.3g}; in the JKR regime the pull-off does not depend on "
                "z0. Fix equilibrium_spacing, or add radii where the parameter is below ~1"
            )
    if dof == 0 and not have_sd:
        note = (note + "; " if note else "") + (
            "as many parameters as data points and no sd: no uncertainty can be estimated "
            "(give the forces' standard deviations, or more points)"
        )
    elif exact:
        note = (note + "; " if note else "") + (
            "the model fits the data exactly and no sd was given: there is no scatter to "
            "estimate an uncertainty from (give the forces' standard deviations)"
        )
    at_bound = _on_bounds(p, lo, hi)
    if np.any(at_bound):
        note = (note + "; " if note else "") + (
            "the fit ended on the bounds of the search (w in [1e-8, 1e3] J/m^2, z0 in "
            "[1e-12, 1e-7] m): these data may not be pull-offs of this model (check units)"
        )
    n_boot = (0 if np.all(sd_log <= 0.1) else 100) if bootstrap == "auto" else int(bootstrap)
    n_boot = n_boot if np.isfinite(scale) else 0
    n_in = int(samples) if modulus_sd or equilibrium_spacing_sd else 0
    bar = progress_bar(n_boot + n_in, "fit", progress if n_boot + n_in else False, unit=" refits")
    if n_boot > 0:
        rng = np.random.default_rng(seed)
        noise = sig * (1.0 if have_sd else math.sqrt(scale))
        Fb = model(p) + noise * rng.standard_normal((n_boot, F.size))  # one resample a row
        Fb = Fb[np.all(Fb < 0, axis=1)]  # a resample with a force >= 0 is skipped
        pb = np.full((len(Fb), n_par), np.nan)
        if identifiable and len(Fb):  # all at once; else the cost may have several minima
            pb = _refit_rows(
                lambda P: _model_rows(P, R, E, z_fixed if fixed else None), Fb, sig, p, lo, hi
            )
            # a refit on a bound: one by one, which may stop inside (where the cost is flat)
            edge = _on_bounds(pb, lo, hi)
            pb[np.any(edge, axis=1)] = np.nan
        left = np.flatnonzero(np.isnan(pb[:, 0]))
        bar.update(n_boot - left.size)  # the skipped and the batched ones
        for row in left:  # the refits left: one by one
            pb[row] = solve(Fb[row], p).x
            bar.update(1)
        if len(pb) >= 20:
            ws = np.exp(pb[:, 0])
            zs = np.full(len(pb), z0) if fixed else np.exp(pb[:, 1])
            ci_w = tuple(float(v) for v in np.percentile(ws, [2.5, 97.5]))  # type: ignore[assignment]
            ci_z = tuple(float(v) for v in np.percentile(zs, [2.5, 97.5]))  # type: ignore[assignment]
    w_sd_in, z_sd_in = 0.0, 0.0
    if n_in:
        sds = (float(modulus_sd), float(equilibrium_spacing_sd))
        z_in = z_fixed if fixed else None
        w_sd_in, z_sd_in = _input_refits(R, F, E, sd, z_in, *sds, n_in, int(seed) + 1, bar)
    bar.close()
    return AdhesionFit(
        w,
        z0,
        w_sd,
        0.0 if fixed else z_sd,
        ci_w,
        ci_z,
        ci_lin_w,
        ci_lin_z,
        cov,
        corr,
        resid,
        model(p),
        chi2,
        dof,
        fixed,
        identifiable,
        note,
        R,
        F,
        sig if have_sd else np.full(F.shape, math.nan),
        E,
        w_sd_in,
        z_sd_in,
    )


def _is_count(v: object, lo: int) -> bool:
    """Whether ``v`` is an integer (not a bool) in ``[lo, 1e5]``."""
    return not isinstance(v, bool) and isinstance(v, (int, np.integer)) and bool(lo <= v <= 1e5)


def _model_rows(P: NDArray, R: NDArray, E: float, z0: float | None) -> NDArray:
    """The pull-off forces [N/m] at the radii ``R``, one row per row of log parameters ``P``.

    ``P[:, 0]`` is ``ln w``, ``P[:, 1]`` ``ln z0`` (or ``z0`` is the fixed one given).
    """
    shape = (P.shape[0], R.size)
    w = np.broadcast_to(np.exp(P[:, :1]), shape)
    z = np.full(shape, z0) if z0 is not None else np.broadcast_to(np.exp(P[:, 1:2]), shape)
    return pull_off_force_at(np.broadcast_to(R, shape), np.full(shape, E), w, z)


def _input_refits(
    R: NDArray,
    F: NDArray,
    E: float,
    sd: ArrayLike | None,
    z0: float | None,
    E_sd: float,
    z0_sd: float,
    samples: int,
    seed: int,
    bar: Any,
) -> tuple[float, float]:
    """The standard uncertainties of ``(w, z0)`` from the modulus (and a fixed ``z0``) drawn.

    ``samples`` refits without bootstrap, each with ``E`` (and a fixed ``z0``) drawn from
    normal distributions; a draw at or below zero, or one no fit reproduces, is skipped. For
    a fixed ``z0`` the second value is ``z0_sd`` itself. ``bar`` counts the refits.
    """
    rng = np.random.default_rng(seed)
    ws, zs = [], []
    for _ in range(samples):  # the draws in this order: E, then a fixed z0, per refit
        Ei = E + E_sd * rng.standard_normal()
        zi = (z0 + z0_sd * rng.standard_normal()) if z0 is not None else None
        try:
            if Ei <= 0 or (zi is not None and zi <= 0):
                continue
            fi = fit_pull_off(R, F, Ei, sd=sd, equilibrium_spacing=zi, bootstrap=0)
        except ValueError:
            continue
        finally:
            bar.update(1)
        ws.append(fi.work_of_adhesion)
        zs.append(fi.equilibrium_spacing)
    if len(ws) < 2:
        return math.nan, (z0_sd if z0 is not None else math.nan)
    w_sd = float(np.std(ws, ddof=1))
    return w_sd, (z0_sd if z0 is not None else float(np.std(zs, ddof=1)))


# --------------------------------------------------------------------------------------------
# one shear strength for several friction forces


@dataclass(frozen=True)
class ShearStrengthFit(Result):
    """One ``tau0`` for several friction forces (:func:`fit_shear_strength`).

    Attributes
    ----------
    tau0, tau0_sd : float
        The mean weighted by the friction forces' uncertainties [Pa], its standard
        uncertainty by Monte Carlo (widened by the square root of a Birge ratio above 1).
    tau0_ci95 : (float, float)
        Its 95 % interval [Pa].
    birge_ratio : float
        The points' chi^2 per degree of freedom about the mean (``nan`` for one point or
        without the friction forces' uncertainties).
    """

    whole: ClassVar[tuple[str, ...]] = ("tau0_ci95",)

    tau0: float
    tau0_sd: float
    tau0_ci95: tuple[float, float]
    birge_ratio: float


def fit_shear_strength(
    fn: Callable[..., NDArray],
    f: NDArray,
    F: NDArray,
    f_sd: NDArray,
    common: dict[str, float],
    shared_sd: dict[str, float],
    n_samples: int,
    seed: int,
) -> ShearStrengthFit:
    """One tau0 for all points: the mean weighted by the friction forces' uncertainties.

    Its uncertainty by Monte Carlo over everything at once: the friction forces
    independently, the cylinder's inputs (shared by every point, so not averaged away)
    once per sample; widened by the square root of the Birge ratio (the points' chi^2 per
    degree of freedom about the mean) when they scatter more than their uncertainties say.
    ``fn(friction_force, normal_load, **common)`` gives ``tau0`` per point (vectorised);
    ``f``, ``F``, ``f_sd`` are the friction forces, normal loads and the friction forces'
    standard uncertainties [N/m]; ``shared_sd`` the standard uncertainties of ``common``.
    """
    # the weights 1/sd^2 relative to the largest (the mean is the same; 1e-300 N/m squared
    # would underflow), the sums over tau/scale (tau near the float range would overflow)
    wt = (np.min(f_sd) / f_sd) ** 2 if np.all(f_sd > 0) else np.ones_like(f)
    tau = np.asarray(fn(f, F, **common), float)
    scale = float(np.max(np.abs(tau))) or 1.0
    value = scale * float(np.sum(wt * (tau / scale)) / np.sum(wt))
    if not (np.any(f_sd > 0) or any(shared_sd.values())):
        if f.size < 2:  # one point, no uncertainty given: exact
            return ShearStrengthFit(value, 0.0, (value, value), math.nan)
        # no uncertainty given: the points' scatter, the standard error of their mean and
        # Student's t interval (the points disagree: not zero)
        from scipy.stats import t as student

        sd0 = scale * float(np.std(tau / scale, ddof=1)) / math.sqrt(f.size)
        half = float(student.ppf(1 - 0.05 / 2, f.size - 1)) * sd0
        return ShearStrengthFit(value, sd0, (value - half, value + half), math.nan)
    rng = np.random.default_rng(seed + 7919)
    draw = {}
    for k, v in common.items():
        s = shared_sd.get(k, 0.0)
        x = v + s * rng.standard_normal((n_samples, 1)) if s else np.full((n_samples, 1), v)
        draw[k] = np.where(x > 0, x, v)  # a positive input: no non-physical draw
    ff = f + f_sd * rng.standard_normal((n_samples, f.size))
    ok = np.all(ff > 0, axis=1)
    taus = np.full((n_samples, f.size), np.nan)

    def rows(idx):  # a batch that raises is split in halves: nan only where a draw fails
        try:
            taus[idx] = fn(
                ff[idx], np.broadcast_to(F, ff[idx].shape), **{k: v[idx] for k, v in draw.items()}
            )
        except ValueError:
            if idx.size > 1:
                rows(idx[: idx.size // 2])
                rows(idx[idx.size // 2 :])

    rows(np.flatnonzero(ok))
    with np.errstate(over="ignore", invalid="ignore"):  # a draw beyond the range: dropped
        comb = scale * (np.sum(wt * (taus / scale), axis=1) / np.sum(wt))
    comb = comb[np.isfinite(comb)]
    if comb.size < 2:
        return ShearStrengthFit(value, math.nan, (math.nan, math.nan), math.nan)
    lo, hi = (float(v) for v in np.percentile(comb, [2.5, 97.5]))
    sd = float(np.std(comb, ddof=1))
    # the points' scatter about the mean against their measurement uncertainty (tau0 is
    # proportional to f): a Birge ratio above 1 widens the interval by its square root
    birge = math.nan
    if f.size > 1 and np.all(f_sd > 0):
        sd_i = tau * f_sd / f
        with np.errstate(over="ignore"):  # a scatter far beyond the uncertainties: inf
            birge = float(np.sum(((tau - value) / sd_i) ** 2) / (f.size - 1))
        if birge > 1:
            g = math.sqrt(birge)
            sd, lo, hi = sd * g, value - g * (value - lo), value + g * (hi - value)
    return ShearStrengthFit(value, sd, (lo, hi), birge)
