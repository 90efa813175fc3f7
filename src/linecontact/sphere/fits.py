r"""The sphere's fits with intervals: ``(w, z0)`` from pull-offs, ``tau0`` from friction.

The sphere's counterparts of the wire's :func:`linecontact.fits.fit_pull_off` and of its
shear strength from friction, in SI units (m, Pa, N, J/m^2; pull-off forces negative):

* :func:`sphere_fit_pull_off`: ``(w, z0)`` jointly, or ``w`` alone at a fixed ``z0``, from the
  load-control pull-off forces of a sphere at several radii, by weighted least squares in
  :math:`\ln w`, :math:`\ln z_0` (:class:`SphereAdhesionFit`): standard uncertainties from
  the covariance, 95 % intervals linear in the log parameters and by parametric bootstrap
  (the refits batched, :func:`linecontact._least_squares._refit_rows`), the Maugis
  parameter at each radius, and a flag where the data do not determine ``z0``;
* :func:`~linecontact.sphere.sphere_fit_shear_strength` (in
  :mod:`linecontact.sphere.shear_fit`): one ``tau0`` from friction forces against loads;
* :func:`sphere_which_model`: ``w`` from one measured pull-off, then the regime and the
  errors of Hertz, DMT and JKR at the largest load (:func:`~linecontact.sphere.sphere_models`).

The forward model is the Maugis--Dugdale sphere (:func:`~linecontact.sphere.sphere_pull_off`,
:func:`~linecontact.sphere.sphere_contact_for_load`), its Dugdale step matched to the
Lennard-Jones law: :math:`\sigma_0 = 16 w/(9\sqrt3 z_0)`, :math:`h = w/\sigma_0`, so
``R/h = S R/z0`` and ``sigma0/E = S w/(z0 E)`` with ``S = MAUGIS_STRENGTH``; forces are
``F/(E h R)`` times ``E h R`` [N]. The pull-off is :math:`\bar P(\lambda)\, \pi w R` with
:math:`\bar P` from -2 (DMT, :math:`\lambda \to 0`) to -3/2 (JKR, :math:`\lambda \to \infty`);
``z0`` enters only through :math:`\lambda`, so pull-offs all in one limit do not determine it.

References
----------
D. Maugis, "Adhesion of spheres: the JKR-DMT transition using a Dugdale model",
J. Colloid Interface Sci. 150 (1992) 243--269. doi:10.1016/0021-9797(92)90285-T
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._least_squares import _refit_rows, _rows_or_nan, _solve
from .._validation import check_array
from ..closed_forms.sphere import _sphere_maugis_parameter
from ..errors import ParameterError
from ..materials import MAUGIS_STRENGTH
from ..results import Result
from .models import DMT_BELOW, JKR_ABOVE, SphereModels, sphere_models
from .pulloff import sphere_pull_off

__all__ = [
    "SphereAdhesionFit",
    "SphereModelChoice",
    "sphere_fit_pull_off",
    "sphere_which_model",
]

#: The search box of the fit: ``w`` [J/m^2] and ``z0`` [m] (in their logarithms).
WORK_BOUNDS = (1e-8, 1e3)
SPACING_BOUNDS = (1e-12, 1e-7)

#: The ranges ``z0`` [m] whose best ``w`` a joint fit starts from (the best of them), and
#: the Gauss--Newton steps in ``ln w`` (its difference step) that find that ``w``.
_START_SPACINGS = np.geomspace(*SPACING_BOUNDS, 31)
_PROFILE_STEPS = 3
#: The most local minima over that grid a joint fit is started from (the best one kept).
_STARTS = 3
_STEP_W = 1e-6

#: Bootstrap refits with ``bootstrap="auto"`` where a parameter's relative sd is above 10 %.
_AUTO_REFITS = 100

#: The fewest refits that give a bootstrap interval (else the linear one stays).
_MIN_REFITS = 20


def _groups(R, E, w, z0):
    """``(R/h, sigma0/E, h)`` of a sphere whose Dugdale step is matched to ``(w, z0)``."""
    h = z0 / MAUGIS_STRENGTH
    return R / h, MAUGIS_STRENGTH * w / (z0 * E), h


def _pull_offs(R, E, w, z0) -> NDArray:
    """The load-control pull-off forces [N] (arrays broadcast together)."""
    rho, s, h = _groups(R, E, w, z0)
    return np.asarray(sphere_pull_off(rho, s).F_pulloff_over_EhR, float) * (E * h * R)


def _model(
    R: NDArray, E: float, z_fixed: float | None, unit: float
) -> Callable[[NDArray], NDArray]:  # fmt: skip
    """The pull-offs at the radii ``R`` over ``unit`` [N], a row per row of ``(ln w[, ln z0])``."""

    def rows(P: NDArray) -> NDArray:
        w = np.exp(P[:, :1])
        z0 = np.full(w.shape, z_fixed) if z_fixed is not None else np.exp(P[:, 1:2])
        return _pull_offs(R[None, :], E, w, z0) / unit

    return rows


def _one(rows: Callable[[NDArray], NDArray], m: int) -> Callable[[NDArray], NDArray]:
    """``rows`` at one parameter vector; nan out of the sphere's domain (the solver steps back)."""

    def at(p: NDArray) -> NDArray:
        try:
            return rows(np.asarray(p, float)[None, :])[0]
        except ValueError:
            return np.full(m, np.nan)

    return at


# --------------------------------------------------------------------------------------------
# input checks


def _number(name: str, value: ArrayLike, unit: str, **limits: float) -> float:
    """One finite number (positive unless ``limits`` say), or a ParameterError naming it."""
    arr = check_array(name, value, **limits)  # type: ignore[arg-type]
    if arr.ndim != 0:
        raise ParameterError(
            name, f"{name} must be a single number [{unit}], got an array of shape {arr.shape}"
        )
    return float(arr)


def _count(name: str, value: object, low: int) -> int:
    """An integer in ``[low, 1e5]`` (not a bool), or a ParameterError naming ``name``."""
    if (
        isinstance(value, bool)
        or not isinstance(value, (int, np.integer))
        or not (low <= value <= 100_000)
    ):
        raise ParameterError(name, f"{name} must be an integer in [{low}, 100000], got {value!r}")
    return int(value)


def _vector(name: str, value: ArrayLike, size: int | None, **limits: float) -> NDArray:
    """A 1-D array checked by :func:`check_array`, of ``size`` values where given."""
    arr = check_array(name, value, **limits).reshape(-1)  # type: ignore[arg-type]
    if size is not None and arr.size != size:
        raise ParameterError(
            name, f"{name} must have one value per data point ({size}), got {arr.size}"
        )
    return arr


def _standard_deviations(sd: ArrayLike | None, values: NDArray, unit: str) -> NDArray | None:
    """The data's standard deviations (positive, one per point, not absurdly small) or None."""
    if sd is None:
        return None
    sig = _vector("sd", sd, values.size)
    rel = sig / np.abs(values)
    bad = (rel < 1e-12) | (rel > 1e6)
    if np.any(bad):
        i = int(np.flatnonzero(bad)[0])
        raise ParameterError(
            "sd",
            f"sd of data point {i + 1} is {float(sig[i])!r} for a value of {float(values[i])!r} "
            f"{unit}: the weights need sd between 1e-12 and 1e6 times the value",
        )
    return sig


# --------------------------------------------------------------------------------------------
# the joint fit of (w, z0)


@dataclass(frozen=True)
class SphereAdhesionFit(Result):
    r"""``(w, z0)`` (or ``w`` at a fixed ``z0``) fitted to a sphere's pull-offs at several radii.

    Attributes
    ----------
    work_of_adhesion : float
        ``w`` [J/m^2]; ``work_of_adhesion_sd`` its standard uncertainty from the
        covariance, ``work_of_adhesion_ci95`` its 95 % interval by parametric bootstrap
        (the linear one where no bootstrap ran), ``work_of_adhesion_ci95_linear`` the one
        linear in ``ln w``.
    equilibrium_spacing : float
        ``z0`` [m] (as given where it was fixed), with ``equilibrium_spacing_sd`` (``0`` for
        a fixed ``z0``, ``inf`` for one the data do not determine), ``*_ci95`` and
        ``*_ci95_linear`` as for ``w`` (the search box :data:`SPACING_BOUNDS` for a ``z0``
        the data do not determine).
    covariance : ndarray, shape (2, 2)
        Of ``(w, z0)`` [J/m^2, m], linearised at the fit (zero row and column for a fixed
        ``z0``); ``correlation`` between them (nan for a fixed ``z0``).
    maugis_parameter : ndarray
        Maugis' :math:`\lambda` of the fit at each radius.
    model, residuals : ndarray
        The fitted pull-offs [N] at the data's radii, and those less the data [N].
    chi2, dof : float, int
        The sum of the squared weighted residuals (in N^2 without sds), the degrees of
        freedom.
    identifiable : bool
        Whether the data determine ``z0``: not where every :math:`\lambda` lies in the JKR
        (above 5) or the DMT (below 0.1) limit, where the pull-off does not depend on
        ``z0``, nor where another minimum fits the data as well, nor where its relative
        uncertainty is above 50 %; ``note`` says why. (The correlation of ``w`` and ``z0``
        is high, about -0.99, even where the data determine them: both move the pull-off
        through :math:`\lambda`.)
    fixed_spacing : bool
        ``z0`` was given, not fitted.
    refits : int
        The bootstrap refits behind the ``*_ci95`` (0: the linear intervals).
    note : str
    radius, pull_off_force, sd : ndarray
        The data [m], [N], [N] (sd nan where none was given); ``modulus`` [Pa].
    """

    inputs: ClassVar[tuple[str, ...]] = ("fixed_spacing",)
    whole: ClassVar[tuple[str, ...]] = (
        "covariance",
        "work_of_adhesion_ci95",
        "work_of_adhesion_ci95_linear",
        "equilibrium_spacing_ci95",
        "equilibrium_spacing_ci95_linear",
    )

    work_of_adhesion: float
    work_of_adhesion_sd: float
    work_of_adhesion_ci95: tuple[float, float]
    work_of_adhesion_ci95_linear: tuple[float, float]
    equilibrium_spacing: float
    equilibrium_spacing_sd: float
    equilibrium_spacing_ci95: tuple[float, float]
    equilibrium_spacing_ci95_linear: tuple[float, float]
    covariance: NDArray
    correlation: float
    maugis_parameter: NDArray
    model: NDArray
    residuals: NDArray
    chi2: float
    dof: int
    identifiable: bool
    fixed_spacing: bool
    refits: int
    note: str
    radius: NDArray = field(repr=False)
    pull_off_force: NDArray = field(repr=False)
    sd: NDArray = field(repr=False)
    modulus: float = field(repr=False, default=math.nan)


def _start(
    w0: float, F: NDArray, rows: Callable[[NDArray], NDArray], sig: NDArray,
    z_fixed: float | None,
) -> NDArray:  # fmt: skip
    r"""The starting points: the lowest dips of the cost over a grid of ranges, ``w`` best at each.

    The cost of a joint fit may have several minima (the pull-off's :math:`\bar P(\lambda)`
    turns from convex to concave near :math:`\lambda = 0.2`): at each of
    :data:`_START_SPACINGS` ``ln w`` takes :data:`_PROFILE_STEPS` Gauss--Newton steps from
    ``w0`` [J/m^2] (all ranges at once through ``rows``); the fit starts at each of the
    lowest :data:`_STARTS` local minima over the grid (a row each, lowest first).
    """
    w0 = min(max(w0, WORK_BOUNDS[0] * 10), WORK_BOUNDS[1] / 10)
    z = np.array([z_fixed]) if z_fixed is not None else _START_SPACINGS
    P = np.column_stack([np.full(z.size, math.log(w0)), np.log(z)])
    P = P[:, :1] if z_fixed is not None else P
    m = F.size
    with np.errstate(all="ignore"):
        for _ in range(_PROFILE_STEPS):
            both = _rows_or_nan(rows, np.concatenate([P, P + [_STEP_W, 0.0][: P.shape[1]]]), m)
            y, slope = both[: z.size], (both[z.size :] - both[: z.size]) / _STEP_W
            step = np.sum(slope * (y - F) / sig**2, axis=1) / np.sum((slope / sig) ** 2, axis=1)
            P[:, 0] = np.clip(P[:, 0] - np.nan_to_num(step), *np.log(WORK_BOUNDS))
        cost = np.sum(((_rows_or_nan(rows, P, m) - F) / sig) ** 2, axis=1)
    if not np.any(np.isfinite(cost)):
        raise ParameterError(
            "pull_off_force",
            "no sphere in the search box (w in [1e-8, 1e3] J/m^2, z0 in [1e-12, 1e-7] m) "
            "reproduces these pull-off forces at the modulus given: check their units (N) "
            "and the modulus (Pa)",
        )
    cost = np.where(np.isfinite(cost), cost, np.inf)
    pad = np.concatenate([[np.inf], cost, [np.inf]])
    dips = np.flatnonzero((cost <= pad[:-2]) & (cost <= pad[2:]) & np.isfinite(cost))
    return P[dips[np.argsort(cost[dips])][:_STARTS]]


def _log_covariance(J: NDArray, scale: float) -> tuple[NDArray, float]:
    """The covariance of the log parameters, ``scale (J^T J)^-1``, and their correlation.

    The correlation is that of ``(J^T J)^-1`` (independent of the scale: defined even for an
    exact fit without sds); nan for one parameter, inf where ``J^T J`` is singular.
    """
    n = J.shape[1]
    with np.errstate(all="ignore"):
        try:
            inv = np.linalg.inv(J.T @ J)
        except np.linalg.LinAlgError:
            return np.full((n, n), np.inf), math.nan
        corr = math.nan if n == 1 else float(inv[0, 1] / math.sqrt(inv[0, 0] * inv[1, 1]))
    return inv * scale, corr


def _covariance(cov_log: NDArray, w: float, z0: float) -> NDArray:
    """The covariance of ``(w, z0)`` [J/m^2, m] from that of their logarithms.

    ``cov_log`` is of ``ln w`` alone (a fixed ``z0``: zero row and column) or of both.
    """
    n = cov_log.shape[0]
    scales = np.array([w, z0])[:n]
    cov = np.zeros((2, 2))
    cov[:n, :n] = cov_log * np.outer(scales, scales)
    return cov


def _on_bounds(p: NDArray, lo: NDArray, hi: NDArray) -> NDArray:
    """Where the log parameters ``p`` lie on the search box ``[lo, hi]`` (to 1e-6)."""
    return np.isclose(p, lo, rtol=0, atol=1e-6) | np.isclose(p, hi, rtol=0, atol=1e-6)


def _around(value: float, sd_log: float) -> tuple[float, float]:
    """The 95 % interval of a value whose logarithm has the standard deviation ``sd_log``."""
    with np.errstate(over="ignore"):  # a parameter the data do not bound: inf
        half = np.exp(1.96 * sd_log)
    return float(value / half), float(value * half)


def _why_not_identifiable(
    lam: NDArray, rel_sd: float, corr: float, exact: bool
) -> tuple[str, bool]:  # fmt: skip
    """Why the data do not determine ``z0`` ('' where they do), and whether all in one limit."""
    span = f"Maugis parameter {float(np.min(lam)):.3g} to {float(np.max(lam)):.3g}"
    if np.all(lam > JKR_ABOVE) or np.all(lam < DMT_BELOW):
        limit = "JKR" if np.all(lam > JKR_ABOVE) else "DMT"
        return (
            f"the data do not determine z0: at the fit every radius is in the {limit} limit "
            f"({span}), where the pull-off is proportional to R and does not depend on z0 "
            "(-1.5 pi w R in JKR, -2 pi w R in DMT), so such data cannot tell the two "
            "limits apart: z0's interval is the search box, w's spans its DMT and JKR "
            f"readings. Fix equilibrium_spacing, or add radii where the parameter is between "
            f"{DMT_BELOW:g} and {JKR_ABOVE:g}"
        ), True
    if not exact and not rel_sd < 0.5:
        return (
            f"the data do not determine z0 (relative uncertainty {rel_sd:.2g}, correlation "
            f"with w {corr:.4f}; {span}): its interval is the search box. Fix "
            "equilibrium_spacing, or add radii where the parameter is near 1"
        ), False
    return "", False


def _rival(tries: list, best, scale: float) -> str:
    """A second minimum whose cost is within Delta chi^2 = 5.99 (95 %, 2 parameters), or ''.

    ``tries``: the fits from each start (:func:`scipy.optimize.least_squares` results, cost
    half the weighted sum of squares); ``scale``: the weights' variance factor.
    """
    for t in tries:
        far = abs(float(t.x[1] - best.x[1])) > 0.1  # another z0, not the same minimum again
        if far and 2 * (t.cost - best.cost) <= 5.99 * scale:
            w, z0 = np.exp(t.x)
            return (
                f"the data do not determine z0: another minimum fits them as well (w {w:.4g} "
                f"J/m^2, z0 {z0:.4g} m); its interval is the search box. Add radii, or fix "
                "equilibrium_spacing"
            )
    return ""


def _bootstrap(
    rows: Callable[[NDArray], NDArray],
    one_fit: Callable[[NDArray], NDArray],
    model: NDArray,
    noise: NDArray,
    p: NDArray,
    box: tuple[NDArray, NDArray],
    count: int,
    seed: int,
    redo_edges: bool,
) -> NDArray:
    """Parametric-bootstrap refits: the model plus normal noise, refitted all at once.

    One resample a row (``seed``); a resample with a force at or above zero is skipped. The
    batch (:func:`_refit_rows`) leaves to ``one_fit`` (one fit by :func:`_solve`) the rows it
    does not finish, and, with ``redo_edges``, those that end on a bound of the box.
    Returns the refitted log parameters, one row each.
    """
    rng = np.random.default_rng(seed)
    data = model + noise * rng.standard_normal((count, model.size))
    data = data[np.all(data < 0, axis=1)]
    if data.shape[0] == 0:
        return np.empty((0, p.size))
    lo, hi = box
    out = _refit_rows(rows, data, noise, p, lo, hi)
    if redo_edges:
        edge = _on_bounds(out, lo, hi)
        out[np.any(edge, axis=1)] = np.nan
    for i in np.flatnonzero(np.any(np.isnan(out), axis=1)):
        out[i] = one_fit(data[i])
    return out


def sphere_fit_pull_off(
    radius: ArrayLike,
    pull_off_force: ArrayLike,
    modulus: float,
    *,
    equilibrium_spacing: float | None = None,
    sd: ArrayLike | None = None,
    bootstrap: int | str = "auto",
    seed: int = 0,
) -> SphereAdhesionFit:
    r"""Fit the work of adhesion (and the range) to a sphere's pull-off forces at several radii.

    Weighted least squares on the Maugis--Dugdale sphere's load-control pull-off in
    :math:`\ln w` and :math:`\ln z_0`, within :data:`WORK_BOUNDS` and :data:`SPACING_BOUNDS`.
    The pull-off is :math:`\bar P(\lambda)\,\pi w R`: the radii separate ``w`` from ``z0``
    only through the Maugis parameter :math:`\lambda \propto R^{1/3} w^{1/3}/z_0`, between
    the DMT (-2) and JKR (-3/2) limits. Data all in one limit do not determine ``z0`` (nor
    which limit: ``w``'s interval then spans its DMT and JKR readings); nor do data with a
    second minimum that fits them as well (within :math:`\Delta\chi^2 = 5.99`; two radii
    often have two exact solutions), nor a relative uncertainty of ``z0`` above 50 %:
    ``identifiable`` is False, ``note`` says why, and ``z0``'s intervals are the search box.
    The fit starts from the lowest dips of a profile of the cost over 31 ranges
    since the cost may have several minima.

    Parameters
    ----------
    radius : array_like, 1-D
        The tips' radii [m] (at least two distinct for a joint fit).
    pull_off_force : array_like, 1-D
        The measured pull-off forces [N], negative (tensile), one per radius.
    modulus : float
        The composite modulus ``E`` [Pa], :math:`1/E = (1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2`.
    equilibrium_spacing : float, optional
        Fix ``z0`` [m] and fit ``w`` alone (one point suffices).
    sd : array_like, optional
        Standard deviations of the forces [N]; without them the weights are equal and the
        residuals' scatter sets the uncertainty (none for an exact fit).
    bootstrap : int or "auto"
        Parametric-bootstrap refits for the 95 % intervals (0: none, the linear intervals
        are kept; ``"auto"``: 100 where a parameter's relative standard uncertainty is
        above 10 %, else none).
    seed : int
        Of the bootstrap's resamples.

    Returns
    -------
    SphereAdhesionFit

    Examples
    --------
    Pull-offs of tips from 5 nm to 2 um (Maugis parameter 0.1 to 0.8), then the fit:

    >>> from linecontact import Sphere
    >>> R = np.array([5e-9, 20e-9, 100e-9, 500e-9, 2e-6])
    >>> F = [Sphere.from_modulus(r, 50e9, work_of_adhesion=0.1, equilibrium_spacing=3e-10)
    ...      .pull_off().pull_off_force for r in R]
    >>> fit = sphere_fit_pull_off(R, F, 50e9, bootstrap=0)
    >>> print(fit.identifiable, f"{fit.work_of_adhesion:.9f} {fit.equilibrium_spacing:.6e}")
    True 0.100000000 3.000000e-10
    """
    F = _vector("pull_off_force", pull_off_force, None, low=-np.inf, high=0.0)
    R = _vector("radius", radius, F.size)
    E = _number("modulus", modulus, "Pa")
    fixed = equilibrium_spacing is not None
    z_fixed = None
    if equilibrium_spacing is not None:
        z_fixed = _number("equilibrium_spacing", equilibrium_spacing, "m")
    if not fixed and np.unique(R).size < 2:
        raise ParameterError(
            "radius",
            f"a joint fit of (w, z0) needs at least 2 distinct radii, got {np.unique(R).size}: "
            "the radius dependence is what separates w from z0 (or fix equilibrium_spacing)",
        )
    sig_given = _standard_deviations(sd, F, "N")
    if bootstrap != "auto":
        _count("bootstrap", bootstrap, 0)
    seed = _count("seed", seed, 0)
    # in units of the largest force (the solver's tolerances are absolute in the residuals)
    fs = float(np.max(np.abs(F)))
    Fn = F / fs
    sig = np.ones_like(F) if sig_given is None else sig_given / fs
    n = 1 if fixed else 2
    lo = np.log([WORK_BOUNDS[0], SPACING_BOUNDS[0]])[:n]
    hi = np.log([WORK_BOUNDS[1], SPACING_BOUNDS[1]])[:n]
    rows = _model(R, E, z_fixed, fs)
    one = _one(rows, F.size)
    # w between the pull-off's DMT (2 pi w R) and JKR (1.5 pi w R) values: their middle
    w0 = float(np.median(-F / (1.75 * np.pi * R)))
    try:
        tries = [_solve(one, Fn, sig, p0, lo, hi) for p0 in _start(w0, Fn, rows, sig, z_fixed)]
    except ValueError as err:  # the model out of its domain along the way (not finite)
        if isinstance(err, ParameterError):
            raise
        raise ParameterError(
            "pull_off_force",
            "no sphere in the search box (w in [1e-8, 1e3] J/m^2, z0 in [1e-12, 1e-7] m) gives "
            "pull-offs of this size at these radii: check the units (N, m, Pa)",
        ) from None
    fit = min(tries, key=lambda t: t.cost)
    p = fit.x

    def one_fit(data: NDArray) -> NDArray:  # a bootstrap refit the batch leaves
        return _solve(one, data, sig, p, lo, hi).x

    model = one(p)
    if not np.all(np.isfinite(model)):
        raise ParameterError(
            "pull_off_force", "the fit left the sphere's domain: check the units (N, m, Pa)"
        )
    chi2 = float(np.sum(((model - Fn) / sig) ** 2))
    dof = F.size - n
    exact = sig_given is None and chi2 <= 1e-24 * float(np.sum(Fn * Fn))
    scale = 1.0 if sig_given is not None else (chi2 / dof if dof > 0 else math.nan)
    cov_log, corr = _log_covariance(fit.jac, scale)
    sd_log = np.sqrt(np.clip(np.diag(cov_log), 0.0, None))
    w = math.exp(p[0])
    z0 = z_fixed if z_fixed is not None else math.exp(p[1])
    cov = _covariance(cov_log, w, z0)
    lam = np.asarray(_sphere_maugis_parameter(*_groups(R, E, w, z0)[:2]), float)
    w_lin = _around(w, float(sd_log[0]))
    z_lin = (z0, z0) if fixed else _around(z0, float(sd_log[1]))
    z_sd = 0.0 if fixed else float(math.sqrt(cov[1, 1]))
    note, one_limit = ("", False) if fixed else _why_not_identifiable(lam, z_sd / z0, corr, exact)
    if not note and not fixed:
        note = _rival(tries, fit, scale if scale > 0 else 1e-24 * float(np.sum(Fn * Fn)))
    identifiable = not note
    notes = [note] if note else []
    if dof == 0 and sig_given is None:
        notes.append(
            "as many parameters as data points and no sd: no uncertainty can be estimated "
            "(give the forces' standard deviations, or more points)"
        )
    elif exact:
        notes.append(
            "the model fits the data exactly and no sd was given: no scatter to estimate an "
            "uncertainty from (give the forces' standard deviations)"
        )
    if np.any(_on_bounds(p, lo, hi)):
        notes.append(
            "the fit ended on the search box (w in [1e-8, 1e3] J/m^2, z0 in [1e-12, 1e-7] "
            "m): these may not be pull-offs of this model (check the units)"
        )
    if bootstrap == "auto":
        count = _AUTO_REFITS if np.any(sd_log > 0.1) else 0
    else:
        count = int(bootstrap)
    count = count if math.isfinite(scale) and scale > 0 else 0
    w_ci, z_ci, used = w_lin, z_lin, 0
    if count:
        noise = sig * (1.0 if sig_given is not None else math.sqrt(scale))
        refit = _bootstrap(rows, one_fit, model, noise, p, (lo, hi), count, seed, identifiable)
        used = refit.shape[0]
        if used >= _MIN_REFITS:
            w_ci = _percentiles(np.exp(refit[:, 0]))
            z_ci = (z0, z0) if fixed else _percentiles(np.exp(refit[:, 1]))
        else:
            used = 0
    if not identifiable:  # the data do not bound z0: no fake tight interval
        z_sd, z_ci = math.inf, SPACING_BOUNDS
        z_lin = SPACING_BOUNDS
    if one_limit:  # the same data at any P(lambda) in [-2, -1.5]: w = w_fit P_fit / P
        bar = float(np.mean(model * fs / (np.pi * w * R)))  # the fit's P(lambda), < 0
        # without scatter to size them (no sd, no degree of freedom) the intervals are w's
        # readings alone
        w_ci = w_ci if np.all(np.isfinite(w_ci)) else (w, w)
        w_lin = w_lin if np.all(np.isfinite(w_lin)) else (w, w)
        w_ci = (w_ci[0] * -bar / 2, w_ci[1] * -bar / 1.5)
        w_lin = (w_lin[0] * -bar / 2, w_lin[1] * -bar / 1.5)
    return SphereAdhesionFit(
        work_of_adhesion=w,
        equilibrium_spacing=z0,
        work_of_adhesion_sd=float(math.sqrt(cov[0, 0])),
        equilibrium_spacing_sd=z_sd,
        work_of_adhesion_ci95=w_ci,
        equilibrium_spacing_ci95=z_ci,
        work_of_adhesion_ci95_linear=w_lin,
        equilibrium_spacing_ci95_linear=z_lin,
        covariance=cov,
        correlation=corr,
        residuals=(model - Fn) * fs,
        model=model * fs,
        maugis_parameter=lam,
        chi2=chi2 if sig_given is not None else chi2 * fs * fs,
        dof=dof,
        fixed_spacing=fixed,
        identifiable=identifiable,
        refits=used,
        note="; ".join(notes),
        radius=R,
        pull_off_force=F,
        sd=np.full(F.shape, math.nan) if sig_given is None else sig_given,
        modulus=E,
    )


def _percentiles(values: NDArray) -> tuple[float, float]:
    """The 2.5 % and 97.5 % percentiles."""
    lo, hi = np.percentile(values, [2.5, 97.5])
    return float(lo), float(hi)


# --------------------------------------------------------------------------------------------
# which model, from a measurement


@dataclass(frozen=True)
class SphereModelChoice(Result):
    r"""Which model holds for a measured tip: its ``w``, :math:`\lambda`, each model's errors.

    Attributes
    ----------
    work_of_adhesion : float
        ``w`` [J/m^2] whose Maugis--Dugdale sphere pulls off at the force measured.
    maugis_parameter : float
    regime : str
        ``"DMT"``, ``"transition"`` or ``"JKR"`` (Johnson & Greenwood's bounds 0.1 and 5).
    best : str
        The model (``"hertz"``, ``"dmt"``, ``"jkr"``) with the smallest error in the contact
        radius at the largest load.
    pull_off_error_hertz, pull_off_error_dmt, pull_off_error_jkr : float
        Each model's pull-off less the Maugis--Dugdale one, over its size.
    radius_error_hertz, radius_error_dmt, radius_error_jkr : float
        Each model's contact radius at the largest load less the Maugis--Dugdale one, over
        it (nan where the model has no contact there).
    max_load : float
        The largest load [N].
    models : SphereModels
        The nondimensional comparison.
    """

    work_of_adhesion: float
    maugis_parameter: float
    regime: str
    best: str
    pull_off_error_hertz: float
    pull_off_error_dmt: float
    pull_off_error_jkr: float
    radius_error_hertz: float
    radius_error_dmt: float
    radius_error_jkr: float
    max_load: float
    models: SphereModels = field(repr=False)


def sphere_which_model(
    pull_off_force: float,
    radius: float,
    modulus: float,
    *,
    equilibrium_spacing: float,
    max_load: float,
) -> SphereModelChoice:
    r"""Which model (Hertz, DMT, JKR) describes a tip, from its pull-off and the largest load.

    ``w`` from the pull-off (:func:`sphere_fit_pull_off` at the fixed ``z0``, one point:
    exact), then :func:`~linecontact.sphere.sphere_models` at the largest load: the Maugis
    parameter, the regime, and each simple model's error against the Maugis--Dugdale
    sphere in the pull-off and in the contact radius at that load.

    Parameters
    ----------
    pull_off_force : float
        The measured pull-off [N], negative.
    radius, modulus : float
        ``R`` [m] and the composite modulus ``E`` [Pa].
    equilibrium_spacing : float
        The range ``z0`` [m] (an assumption: ``w`` hardly depends on it, :math:`\lambda` does).
    max_load : float
        The largest load of the measurement [N] (compressive positive), above the pull-off.

    Returns
    -------
    SphereModelChoice

    Examples
    --------
    >>> m = sphere_which_model(-12e-9, 20e-9, 50e9, equilibrium_spacing=3e-10, max_load=50e-9)
    >>> print(m.regime, f"{m.maugis_parameter:.2f}")
    transition 0.17
    """
    F = -_number("pull_off_force", pull_off_force, "N", low=-np.inf, high=0.0)
    R = _number("radius", radius, "m")
    E = _number("modulus", modulus, "Pa")
    z0 = _number("equilibrium_spacing", equilibrium_spacing, "m")
    load = _number("max_load", max_load, "N", low=-np.inf)
    fit = sphere_fit_pull_off([R], [-F], E, equilibrium_spacing=z0, bootstrap=0)
    w = fit.work_of_adhesion
    if abs(float(fit.residuals[0])) > 1e-9 * F:  # the search box's end: no w gives it
        raise ParameterError(
            "pull_off_force",
            f"no work of adhesion in [1e-8, 1e3] J/m^2 gives a pull-off of {-F!r} N for a "
            f"sphere of radius {R!r} m, modulus {E!r} Pa and range {z0!r} m: check the units "
            "(N, m, Pa)",
        )
    rho, s, h = _groups(R, E, w, z0)
    if load < -F:
        raise ParameterError(
            "max_load",
            f"max_load {load!r} N is below the pull-off {-F!r} N: the tip is off the surface",
        )
    try:
        m = sphere_models(load / (E * h * R), rho, s)
    except ParameterError as err:  # a load too large for the sphere's domain: as the caller's
        if err.parameter != "F_over_EhR":
            raise
        raise ParameterError(
            "max_load", f"max_load is beyond the contacts the sphere is solved for: {err}"
        ) from err
    keys = [f"{q}_error_{k}" for q in ("pull_off", "radius") for k in ("hertz", "dmt", "jkr")]
    return SphereModelChoice(
        work_of_adhesion=w,
        maugis_parameter=float(m.maugis_parameter),
        regime=str(m.regime),
        best=str(m.best),
        **{k: float(getattr(m, k)) for k in keys},
        max_load=load,
        models=m,
    )
