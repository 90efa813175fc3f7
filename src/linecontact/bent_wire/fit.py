r"""The friction per unit length from the measured profile of a bent wire, with its interval.

A wire dragged at its midpoint on its substrate takes the shape of :func:`.dragged_wire`,
one group :math:`\Lambda = f l^3/EI` and its half-length :math:`l` setting it. Given the
imaged profile (points along the wire, from one end to the other), :func:`fit_bent_wire`
places the model on the points by orthogonal least squares over the whole profile
(:mod:`._placement`): the group, the half-length, the midpoint's position and the wire's
angle; then :math:`f = \Lambda EI/l^3`. Its uncertainty comes two ways:

- **covariance**: :math:`\sigma^2 (J^TJ)^{-1}` at the fit, with the position noise
  :math:`\sigma` estimated from the residuals (or given), the interval Student's ``t``;
- **bootstrap over residuals**: the fitted profile plus residuals drawn again, refitted
  (all the replicates at once), the interval of their percentiles.

The bending stiffness's own uncertainty, where given, adds in quadrature (and is drawn in
the bootstrap). The assumptions are the model's (``docs/bent-wire.md``): a steady drag at
the midpoint, uniform kinetic friction, an elastica (no shear, no stretching), points in
order from one end to the other, the first and last the wire's ends, and isotropic
independent position noise.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import check_array
from ..errors import ConvergenceError, ParameterError
from ..results import Result
from ._curve import Dragged
from ._held import Held, _mode_integral
from ._placement import place
from .elastica import LAMBDA_MAX

__all__ = ["MODELS", "BentWireFit", "fit_bent_wire"]

#: The models a profile is fitted with: the wire dragged at its midpoint (kinetic friction),
#: the wire held at rest by static friction normal to it, its ends free.
MODELS = ("dragged", "held")
#: What each model's wire is, for a message.
_WHAT = {"dragged": "dragged at its midpoint", "held": "held at rest by friction, its ends free"}
#: The held wire's most curvature modes, and the bound of their coefficients.
HELD_MODES = 12
_COEF = 500.0
#: The segments of the coarser polyline of the held wire's first guess.
_COARSE = 40
#: The modes beyond Schwarz's choice (f_n, a second derivative of the shape, is more
#: sensitive to the modes left out than the shape is).
_EXTRA = 1
#: The arc lengths (over l, from the midpoint) of the fitted curve drawn and of f_n, and the
#: trapezoidal rule's weights of a mean over them.
_DENSE = np.linspace(-1.0, 1.0, 401)
_TRAPEZOID = np.full(401, 1.0 / 400)
_TRAPEZOID[[0, -1]] /= 2
#: The fewest points of a profile (five parameters, and the ends count twice).
MIN_POINTS = 8
#: How far back along the wire a point's foot may lie from the one before, in noises (the
#: noise along the wire moves the feet too: two points' feet differ by sqrt(2) noises, so
#: six is five standard deviations; a profile folding back moves them by far more).
_BACK = 6.0
#: The runs test's z below which the residuals are not noise (a chance of 3e-5 for noise).
_RUNS_Z = -4.0
#: The intervals' confidence level.
LEVEL = 0.95
#: The replicates of the bootstrap, by default.
BOOTSTRAP = 200


@dataclass(frozen=True)
class BentWireFit(Result):
    r"""The friction per unit length fitted to a bent wire's profile, with its uncertainty.

    Attributes
    ----------
    friction_per_length : float
        :math:`f` [N/m]: the uniform kinetic friction of the dragged wire; for the held
        wire the mean of :math:`|f_n|` along it, the static friction that holds it,
        averaged (its strength is at least the largest, :attr:`normal_friction_largest`).
    friction_per_length_sd : float
        Its standard uncertainty from the covariance [N/m]: the shape's, and the bending
        stiffness's where given, in quadrature.
    friction_per_length_sd_shape : float
        The shape's part of it alone [N/m].
    friction_per_length_ci95 : (float, float)
        :math:`f \pm t_{0.975}` sd (the low end not below 0) [N/m].
    friction_per_length_bootstrap_sd, friction_per_length_bootstrap_ci95 : float, (float, float)
        The standard deviation and the 2.5 %/97.5 % percentiles of the bootstrap's refits
        [N/m] (nan without a bootstrap).
    friction_group, friction_group_sd : float
        :math:`\Lambda = f l^3/EI` [-] and its standard uncertainty.
    half_length, half_length_sd : float
        :math:`l` [m], half the wire's length along it.
    midpoint : (float, float)
        Where the midpoint is, in the profile's coordinates [m].
    axis_angle : float
        The angle of the wire's axis (the chord of its ends, from the first point's end to
        the last's) to the profile's ``x`` axis [rad].
    drag_angle : float
        The direction of the drag, the midpoint ahead of the ends [rad] (nan for the held
        wire).
    bending_stiffness, bending_stiffness_sd : float
        :math:`EI` [N m^2], as given.
    noise : float
        The position noise used [m]: the given one, or the estimate.
    noise_estimated : float
        :math:`\sqrt{\text{RSS}/\text{dof}}` [m], the residuals' estimate of the noise.
    noise_given : bool
    dof : int
        Degrees of freedom: a point's distance to the curve counts once, an end's two
        coordinates twice, less the five parameters.
    points : int
    determined : bool
        Whether the data determine :math:`f`: its 95 % interval excludes zero and the
        residuals are noise (``residual_runs_z``); ``note`` says why not.
    residual_runs_z : float
        The Wald--Wolfowitz runs test of the residuals' signs along the wire, as a normal
        deviate: near 0 for independent noise, far below for a shape the model does not
        describe (below -4, a chance of 3e-5 for noise, the data are said not to determine
        :math:`f`).
    note : str
    covariance : ndarray, shape (5, 5)
        Of :math:`(\Lambda, l, x_0, y_0, \phi)` [-, m, m, m, rad], from the shape alone.
    residuals : ndarray
        Each point's signed distance to the fitted curve [m] (an end: its distance to the
        curve's end).
    arc_length : ndarray
        Each point's foot on the curve, as arc length from the midpoint [m].
    fitted_x, fitted_y : ndarray
        The feet [m].
    curve_x, curve_y : ndarray
        The fitted wire, 401 points from end to end [m].
    x, y : ndarray
        The profile as given [m].
    normal_friction, normal_friction_sd : ndarray
        The held wire's friction per unit length normal to it, :math:`f_n = EI(\kappa'' +
        \kappa^3/2)`, and its standard uncertainty, at the 401 points of the fitted curve
        [N/m] (empty for the dragged wire, whose friction is uniform).
    modes : int
        The held wire's curvature modes, as Schwarz's criterion chose them, plus one (0 for
        the dragged wire).
    normal_friction_largest : float
        The held wire's largest :math:`|f_n|` [N/m], with no interval: the maximum of a
        noisy second derivative, its scatter large and biased upward (``docs/bent-wire.md``);
        nan for the dragged wire.
    bootstrap, bootstrap_failed, seed : int
        Replicates asked, replicates that did not converge (left out), the seed.
    steps : int
        Levenberg--Marquardt steps of the fit.
    converged : bool
    model : str
    """

    derived: ClassVar[tuple[str, ...]] = ("normal_friction_largest",)
    whole: ClassVar[tuple[str, ...]] = (
        "friction_per_length_ci95",
        "friction_per_length_bootstrap_ci95",
        "midpoint",
        "covariance",
    )

    friction_per_length: float
    friction_per_length_sd: float
    friction_per_length_sd_shape: float
    friction_per_length_ci95: tuple[float, float]
    friction_per_length_bootstrap_sd: float
    friction_per_length_bootstrap_ci95: tuple[float, float]
    friction_group: float
    friction_group_sd: float
    half_length: float
    half_length_sd: float
    midpoint: tuple[float, float]
    axis_angle: float
    drag_angle: float
    bending_stiffness: float
    bending_stiffness_sd: float
    noise: float
    noise_estimated: float
    noise_given: bool
    dof: int
    points: int
    determined: bool
    residual_runs_z: float
    note: str
    covariance: NDArray = field(repr=False)
    residuals: NDArray = field(repr=False)
    arc_length: NDArray = field(repr=False)
    fitted_x: NDArray = field(repr=False)
    fitted_y: NDArray = field(repr=False)
    curve_x: NDArray = field(repr=False)
    curve_y: NDArray = field(repr=False)
    x: NDArray = field(repr=False)
    y: NDArray = field(repr=False)
    normal_friction: NDArray = field(repr=False, default_factory=lambda: np.zeros(0))
    normal_friction_sd: NDArray = field(repr=False, default_factory=lambda: np.zeros(0))
    modes: int = 0
    bootstrap: int = 0
    bootstrap_failed: int = 0
    seed: int = 0
    steps: int = 0
    converged: bool = True
    model: str = "dragged"

    @property
    def normal_friction_largest(self) -> float:
        """The held wire's largest :math:`|f_n|` [N/m] (nan for the dragged wire)."""
        fn = np.asarray(self.normal_friction)
        return float(np.max(np.abs(fn))) if fn.size else math.nan


def _count(name: str, v: Any, lo: int, hi: int) -> int:
    if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or not lo <= v <= hi:
        raise ParameterError(name, f"{name} must be an integer in [{lo}, {hi}], got {v!r}")
    return int(v)


def _profile(x: ArrayLike, y: ArrayLike) -> NDArray:
    """The points as an ``(N, 2)`` array, checked."""
    try:
        X, Y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    except (TypeError, ValueError):
        raise ParameterError("x", "x and y must be arrays of numbers [m]") from None
    if X.ndim != 1 or Y.shape != X.shape:
        raise ParameterError(
            "x", f"x and y must be 1-D arrays of one length, got shapes {X.shape} and {Y.shape}"
        )
    if X.size < MIN_POINTS:
        raise ParameterError(
            "x",
            f"a profile needs at least {MIN_POINTS} points (five parameters are fitted), "
            f"got {X.size}",
        )
    if not (np.all(np.isfinite(X)) and np.all(np.isfinite(Y))):
        i = int(np.flatnonzero(~(np.isfinite(X) & np.isfinite(Y)))[0])
        raise ParameterError("x", f"the profile's point {i} is not finite: ({X[i]!r}, {Y[i]!r})")
    d = np.stack([X, Y], axis=1)
    if not np.all(np.hypot(*(d[1:] - d[:-1]).T) > 0):
        i = int(np.flatnonzero(np.hypot(*(d[1:] - d[:-1]).T) == 0)[0])
        raise ParameterError(
            "x", f"the profile's points {i} and {i + 1} are the same: give each point once"
        )
    return d


def _start(d: NDArray, model: Dragged) -> tuple[NDArray, NDArray]:
    """The first guess from the points (scaled): the chord, the sag, the arc lengths."""
    seg = np.hypot(*(d[1:] - d[:-1]).T)
    arc = np.concatenate([[0.0], np.cumsum(seg)])
    half = arc[-1] / 2.0
    chord = d[-1] - d[0]
    phi = math.atan2(chord[1], chord[0])
    e = chord / np.hypot(*chord)
    mid = (d[0] + d[-1]) / 2.0
    off = (d - mid) @ np.array([-e[1], e[0]])
    sag = off[np.argmax(np.abs(off))]
    lam = float(np.clip(8.0 * sag / half, -0.8 * LAMBDA_MAX, 0.8 * LAMBDA_MAX))
    model.solve(np.array([lam]))
    end = model.at(np.ones((1, 1)), ("y",))["y"][0, 0]
    o = mid - half * end * np.array([-e[1], e[0]])
    s = arc / half - 1.0
    return np.array([[lam, half, o[0], o[1], phi]]), s[None, :]


def fit_bent_wire(
    x: ArrayLike,
    y: ArrayLike,
    bending_stiffness: float,
    *,
    bending_stiffness_sd: float = 0.0,
    noise: float | None = None,
    bootstrap: int = BOOTSTRAP,
    seed: int = 0,
    model: str = "dragged",
) -> BentWireFit:
    r"""The friction per unit length from the profile of a wire dragged at its midpoint.

    Parameters
    ----------
    x, y : array_like
        The profile [m]: points along the wire in order, the first and the last its ends
        (as digitised from an image; :func:`linecontact.read_measurements` reads a CSV of
        ``x_nm,y_nm``). At least 8 points.
    bending_stiffness : float
        :math:`EI` [N m^2] (:func:`linecontact.bent_wire.bending_stiffness` from the
        cross-section and the modulus).
    bending_stiffness_sd : float, optional
        Its standard uncertainty [N m^2], added in quadrature.
    noise : float, optional
        The position noise's standard deviation [m], where known; by default estimated
        from the residuals.
    bootstrap : int, optional
        Replicates of the bootstrap over residuals, in ``[0, 10000]`` (0: none).
    seed : int, optional
        The bootstrap's seed.
    model : {"dragged", "held"}
        ``"dragged"``: the wire dragged at its midpoint, the kinetic case (uniform
        friction). ``"held"``: the wire held at rest by static friction normal to it, its
        ends free (the static case): its curvature as a few free-free modes, as many as
        Schwarz's criterion chooses, plus one; ``f`` the mean of :math:`|f_n|` along it.

    Returns
    -------
    BentWireFit
        ``f`` with its standard uncertainty and intervals, the fitted shape and placement,
        the residuals, and whether the data determine ``f``.

    Raises
    ------
    ParameterError
        Bad input, naming it: too few points, points repeated or not finite, points not in
        order along one curve, a bending beyond the model's range.
    ConvergenceError
        The fit does not converge.

    Examples
    --------
    >>> import numpy as np
    >>> from linecontact.bent_wire import dragged_wire
    >>> EI, l, f = 7e-19, 2.5e-6, 0.012  # N m^2, m, N/m: a ZnO wire 100 nm across
    >>> w = dragged_wire(f * l**3 / EI)
    >>> x = np.concatenate([-w.x_over_l[::-1], w.x_over_l[1:]]) * l
    >>> y = np.concatenate([w.y_over_l[::-1], w.y_over_l[1:]]) * l
    >>> fit = fit_bent_wire(x, y, EI, bootstrap=0)
    >>> print(f"{fit.friction_per_length / f:.6f}")
    1.000000
    """
    if model not in MODELS:
        raise ParameterError("model", f"model must be one of {', '.join(MODELS)}, got {model!r}")
    d = _profile(x, y)
    EI = float(check_array("bending_stiffness", bending_stiffness))
    EI_sd = float(check_array("bending_stiffness_sd", bending_stiffness_sd, low_inclusive=True))
    if noise is not None:
        noise = float(check_array("noise", noise))
    B = _count("bootstrap", bootstrap, 0, 10_000)
    seed = _count("seed", seed, 0, 2**63 - 1)
    # scaled: the centroid at the origin, half the polyline's length one
    centre = d.mean(axis=0)
    scale = float(np.hypot(*(d[1:] - d[:-1]).T).sum() / 2.0)
    dn = (d - centre) / scale
    curve: Any
    if model == "dragged":
        curve = Dragged()
        q0, s0 = _start(dn, curve)
        bounds = np.array(
            [[-LAMBDA_MAX, LAMBDA_MAX], [0.05, 20.0], [-50.0, 50.0], [-50.0, 50.0], [-50.0, 50.0]]
        )
        fit = place(curve, curve.shape_names, dn[None], q0, s0, bounds)
    else:
        curve, fit, bounds = _held(dn)
    k = len(curve.shape_names)
    if not fit.converged[0]:
        raise ConvergenceError(
            f"the bent wire's fit did not converge ({len(d)} points, model {model!r}, after "
            f"{fit.steps[0]} steps): is the profile a wire {_WHAT[model]}, its points in "
            "order from one end to the other?"
        )
    q, s = fit.q[0], fit.s[0]
    if model == "dragged" and abs(q[0]) >= LAMBDA_MAX * (1 - 1e-9):
        raise ParameterError(
            "x",
            f"the profile is bent beyond the model's range (friction group {LAMBDA_MAX:g}, "
            "the ends turned back by 88 degrees)",
        )
    free = fit.free[0]
    n_ends = int((~free).sum())
    dof = int(free.sum()) + 2 * n_ends - (k + 4)
    rss = float(fit.cost[0])
    sigma_hat = math.sqrt(rss / dof) if dof > 0 else math.nan
    # the points must follow the curve in order (a profile folding back does not)
    back = np.flatnonzero(np.diff(s) < -_BACK * max(sigma_hat, 1e-12) / q[k])
    if back.size:
        i = int(back[0]) + 1
        raise ParameterError(
            "x",
            f"the profile's point {i} lies back along the wire from point {i - 1}: the "
            "points must be in order along one curve, from one end to the other",
        )
    sigma = sigma_hat if noise is None else noise / scale
    J = fit.J[0].reshape(-1, k + 4)
    try:
        cov_n = sigma**2 * np.linalg.inv(J.T @ J)
    except np.linalg.LinAlgError:
        cov_n = np.full((k + 4, k + 4), np.nan)
    # the friction's group and its gradient in the parameters; then f = group EI / l^3
    group, ggrad, fn, fn_grad = _friction(model, curve, q)
    half = float(q[k]) * scale
    g = ggrad / q[k] ** 3
    g[k] -= 3.0 * group / q[k] ** 4  # d(group / l^3)/dq (scaled)
    with np.errstate(over="ignore"):  # refused just below
        f = group * EI / half**3
    if not math.isfinite(f):
        raise ParameterError(
            "bending_stiffness",
            f"bending_stiffness {EI!r} N m^2 over the half-length {half!r} m cubed gives no "
            "finite friction: are the profile in m and the stiffness in N m^2?",
        )
    f_sd_shape = math.sqrt(max(g @ cov_n @ g, 0.0)) * EI / scale**3
    f_sd = math.hypot(f_sd_shape, f * EI_sd / EI)
    from scipy.special import ndtri, stdtrit

    tail = 0.5 + LEVEL / 2.0
    quant = float(stdtrit(max(dof, 1), tail) if noise is None else ndtri(tail))
    ci = (max(f - quant * f_sd, 0.0), f + quant * f_sd)
    # the bootstrap over residuals: the fitted profile, residuals drawn again, refitted
    fb_sd, fb_ci, failed = math.nan, (math.nan, math.nan), 0
    if B:
        fb, failed = _bootstrap(model, curve, fit, q, s, dof, B, seed, bounds)
        rng = np.random.default_rng([seed, 1])
        EIb = EI + EI_sd * rng.standard_normal(fb.size) if EI_sd else np.full(fb.size, EI)
        fb = fb * EIb / scale**3
        if fb.size >= 2:
            fb_sd = float(np.std(fb, ddof=1))
            lo_b, hi_b = np.percentile(fb, [50.0 * (1 - LEVEL), 50.0 * (1 + LEVEL)])
            fb_ci = (float(lo_b), float(hi_b))
    unit = np.array([1.0] * k + [scale, scale, scale, 1.0])
    cov = cov_n * unit[:, None] * unit[None, :]
    notes = []
    if not ci[0] > 0:
        notes.append(
            "the data do not determine f: its 95 % interval reaches zero (the bending is "
            "within the position noise)"
        )
    resid = np.einsum("nc,nc->n", fit.r[0], fit.normal[0])
    resid = np.where(free, resid, np.hypot(*fit.r[0].T) * np.sign(resid))
    runs_z = _runs(resid)
    if runs_z < _RUNS_Z:
        notes.append(
            f"the residuals are not noise (runs test z = {runs_z:.1f}): the model does not "
            "describe this profile, so the data do not determine f"
        )
    if B and failed > B // 10:
        notes.append(f"{failed} of {B} bootstrap refits did not converge")
    # the fitted curve and the feet, in the profile's coordinates
    phi, o = float(q[k + 3]), q[k + 1 : k + 3]
    dense = curve_points(curve, q, _DENSE)
    feet = curve_points(curve, q, s)
    if model == "dragged":
        drag = math.remainder(phi + math.copysign(math.pi / 2, q[0]), 2 * math.pi)
        fn_si, fn_sd = np.zeros(0), np.zeros(0)
    else:
        drag = math.nan
        fn_si = fn * EI / half**3
        G = fn_grad / q[k] ** 3
        G[:, k] -= 3.0 * fn / q[k] ** 4
        fn_sd = np.sqrt(np.maximum(np.einsum("ni,ij,nj->n", G, cov_n, G), 0.0)) * EI / scale**3
    return BentWireFit(
        friction_per_length=f,
        friction_per_length_sd=f_sd,
        friction_per_length_sd_shape=f_sd_shape,
        friction_per_length_ci95=ci,
        friction_per_length_bootstrap_sd=fb_sd,
        friction_per_length_bootstrap_ci95=fb_ci,
        friction_group=group,
        friction_group_sd=math.sqrt(max(ggrad @ cov_n @ ggrad, 0.0)),
        half_length=half,
        half_length_sd=math.sqrt(max(cov[k, k], 0.0)),
        midpoint=(float(o[0] * scale + centre[0]), float(o[1] * scale + centre[1])),
        axis_angle=math.remainder(phi, 2 * math.pi),
        drag_angle=drag,
        bending_stiffness=EI,
        bending_stiffness_sd=EI_sd,
        noise=float(sigma * scale),
        noise_estimated=float(sigma_hat * scale),
        noise_given=noise is not None,
        dof=dof,
        points=len(d),
        determined=bool(ci[0] > 0 and runs_z >= _RUNS_Z),
        residual_runs_z=runs_z,
        note="; ".join(notes),
        covariance=cov,
        residuals=resid * scale,
        arc_length=s * half,
        fitted_x=feet[:, 0] * scale + centre[0],
        fitted_y=feet[:, 1] * scale + centre[1],
        curve_x=dense[:, 0] * scale + centre[0],
        curve_y=dense[:, 1] * scale + centre[1],
        x=d[:, 0].copy(),
        y=d[:, 1].copy(),
        normal_friction=fn_si,
        normal_friction_sd=fn_sd,
        modes=k if model == "held" else 0,
        bootstrap=B,
        bootstrap_failed=failed,
        seed=seed,
        steps=int(fit.steps[0]),
        converged=True,
        model=model,
    )


def _friction(model: str, curve: Any, q: NDArray) -> tuple[float, NDArray, NDArray, NDArray]:
    r"""The friction's group and its gradient in ``q``; the held wire's f_n group on the curve.

    Dragged: :math:`|\Lambda|`. Held: the mean of :math:`|f_n| l^3/EI` along the wire
    (the static friction that holds it, averaged; by the trapezoidal rule on
    :data:`_DENSE`); with the group :math:`f_n l^3/EI` at :data:`_DENSE` and its gradient.
    """
    k = len(curve.shape_names)
    grad = np.zeros(k + 4)
    if model == "dragged":
        grad[0] = 1.0 if q[0] >= 0 else -1.0
        return abs(float(q[0])), grad, np.zeros(0), np.zeros((0, k + 4))
    fn, fg = curve.normal_friction(q[:k], _DENSE)
    weight = _TRAPEZOID * np.sign(fn)  # the mean of |f_n| along the wire, and its gradient
    grad[:k] = weight @ fg
    full = np.zeros((fn.size, k + 4))
    full[:, :k] = fg
    return float(_TRAPEZOID @ np.abs(fn)), grad, fn, full


def _runs(resid: NDArray) -> float:
    """The runs test of the residuals' signs (Wald--Wolfowitz), as a normal deviate."""
    sign = resid > 0
    n1, n2 = int(sign.sum()), int((~sign).sum())
    n = n1 + n2
    if n1 == 0 or n2 == 0:
        return -math.inf
    runs = 1 + int(np.count_nonzero(sign[1:] != sign[:-1]))
    mean = 2.0 * n1 * n2 / n + 1.0
    var = (mean - 1.0) * (mean - 2.0) / (n - 1.0)
    return (runs - mean) / math.sqrt(var) if var > 0 else 0.0


def curve_points(curve: Any, q: NDArray, s: NDArray) -> NDArray:
    """The placed curve of the parameters ``q`` at the arc lengths ``s`` (scaled), ``(N, 2)``."""
    k = len(curve.shape_names)
    curve.solve(q[None, :k])
    v = curve.at(s[None, :], ("x", "y"))
    half, o, phi = q[k], q[k + 1 : k + 3], q[k + 3]
    c, sn = math.cos(phi), math.sin(phi)
    cx, cy = v["x"][0], v["y"][0]
    return np.stack([o[0] + half * (c * cx - sn * cy), o[1] + half * (sn * cx + c * cy)], axis=1)


def _bootstrap(
    model: str,
    curve: Any,
    fit: Any,
    q: NDArray,
    s: NDArray,
    dof: int,
    B: int,
    seed: int,
    bounds: NDArray,
) -> tuple[NDArray, int]:
    """The friction's group over ``l^3`` (scaled) of ``B`` refits, and the refits failed.

    The refits are to the fitted profile plus residuals drawn again.
    """
    k = len(curve.shape_names)
    free = fit.free[0]
    r, normal = fit.r[0], fit.normal[0]
    feet = curve_points(curve, q, s)
    pool = np.concatenate([np.einsum("nc,nc->n", r[free], normal[free]), r[~free].ravel()])
    m = pool.size
    pool = (pool - pool.mean()) * math.sqrt(m / max(dof, 1))
    rng = np.random.default_rng(seed)
    N = len(s)
    draw = pool[rng.integers(0, m, size=(B, N, 2))]
    # a free point moves along the fitted curve's normal; an end both ways
    dstar = np.where(
        free[None, :, None],
        feet[None] + draw[..., :1] * normal[None],
        feet[None] + draw,
    )
    qs = np.repeat(q[None], B, axis=0)
    ss = np.repeat(s[None], B, axis=0)
    again = Dragged() if model == "dragged" else Held(k)
    refit = place(
        again, again.shape_names, dstar, qs, ss, bounds, xtol=1e-9, damping=1e-9, projections=1
    )
    ok = refit.converged.copy()
    if model == "dragged":
        ok &= np.abs(refit.q[:, 0]) < LAMBDA_MAX * (1 - 1e-9)
        group = np.abs(refit.q[:, 0])
    else:
        group = np.array([_friction(model, again, row)[0] for row in refit.q])
    out = group[ok] / refit.q[ok, k] ** 3
    return out, int(B - ok.sum())


def _held(dn: NDArray) -> tuple[Held, Any, NDArray]:
    r"""The held wire fitted with the number of modes that the BIC chooses, from 1 up.

    The first guess of each: the modes' angle fitted linearly to the polyline's segment
    angles (the noise averages out over many segments), the wire's angle and midpoint at
    the middle of the polyline. The rule: the least :math:`n \ln(\text{RSS}/n) + p \ln n`
    (Schwarz's criterion, :math:`n` the residuals counted as in ``dof``, :math:`p` the
    parameters), over at most :data:`HELD_MODES` modes and a quarter of the points.
    """
    # a coarser polyline (every w-th point): its angles and length little spoiled by the noise
    w = max(1, len(dn) // _COARSE)
    pick = np.unique(np.r_[np.arange(0, len(dn), w), len(dn) - 1])
    seg = dn[pick[1:]] - dn[pick[:-1]]
    arc = np.concatenate([[0.0], np.cumsum(np.hypot(*seg.T))])
    half = arc[-1] / 2.0
    sc = arc / half - 1.0
    mids = (sc[1:] + sc[:-1]) / 2.0
    angle = np.unwrap(np.arctan2(seg[:, 1], seg[:, 0]))
    phi0 = float(np.interp(0.0, mids, angle))
    o0 = np.array([np.interp(0.0, sc, dn[pick, 0]), np.interp(0.0, sc, dn[pick, 1])])
    s = np.interp(np.arange(len(dn)), pick, sc)  # the points' arc lengths, first guess
    n = len(dn) + 2
    best: tuple[float, Held, Any] | None = None
    fits = {}
    kmax = max(1, min(HELD_MODES, (len(dn) - 5) // 4))
    for K in range(1, kmax + 1):
        if best is not None and K > best[1].K + _EXTRA + 1:
            break  # two past the least criterion and its extra mode: it rises from here
        curve = Held(K)
        psi = np.array([_mode_integral(j, mids) for j in range(K)]).T
        c0, *_ = np.linalg.lstsq(psi, angle - phi0, rcond=None)
        q0 = np.concatenate([c0, [1.0 * half, o0[0], o0[1], phi0]])
        bounds = np.array(
            [[-_COEF, _COEF]] * K + [[0.05, 20.0], [-50.0, 50.0], [-50.0, 50.0], [-50.0, 50.0]]
        )
        fit = place(curve, curve.shape_names, dn[None], q0[None], s[None], bounds)
        if not fit.converged[0]:
            continue
        fits[K] = (curve, fit)
        bic = n * math.log(max(float(fit.cost[0]), 1e-300) / n) + (K + 4) * math.log(n)
        if best is None or bic < best[0]:
            best = (bic, curve, fit)
    if best is None:
        raise ConvergenceError(
            f"the held wire's fit did not converge at any number of modes up to {kmax} "
            f"({len(dn)} points): is the profile a wire held at rest, its points in order "
            "from one end to the other?"
        )
    _, curve, fit = best
    if _EXTRA and curve.K + _EXTRA in fits:
        curve, fit = fits[curve.K + _EXTRA]
    bounds = np.array(
        [[-_COEF, _COEF]] * curve.K + [[0.05, 20.0], [-50.0, 50.0], [-50.0, 50.0], [-50.0, 50.0]]
    )
    return curve, fit, bounds
