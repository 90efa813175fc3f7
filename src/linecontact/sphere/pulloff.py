r"""The adhesive sphere's pull-off, and its contact under a load.

Under load control the sphere lets go at the most tensile load its contact branch carries:
the minimum of :math:`F(a)`, inside the branch (``mechanism="contact"``: Maugis' JKR-like
side) or at its ``a -> 0`` end (``"zero-radius"``: the DMT-like side, where the zone then
separates, the load growing less tensile). Under displacement control it jumps out at the
minimum of the approach :math:`\delta(a)` (``"jump-out"``), or peels continuously to
``a = 0`` where the approach has none (``"zero-radius"``). Each minimum is found from the
sign of the branch's slope (:func:`linecontact.sphere._branch.slopes`) on a grid of radii
in Maugis' unit (:data:`GRID`), then by bisection to rounding.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import domain as _domain
from .._validation import failure_policy
from ..closed_forms.sphere import _sphere_maugis_parameter
from ..errors import NoEquilibriumError, ParameterError
from ..results import SI, Result, as_result
from . import _branch as _b
from .contact import INPUTS, RESIDUAL_TOL, SphereContact, checked, over_piwR, states

#: Contact radii in Maugis' unit :math:`(\pi w R^2/K)^{1/3}` where a minimum is looked for.
GRID = np.geomspace(1e-7, 20.0, 31)

#: The most steps that refine a minimum on the logarithm of the radius (to rounding).
_STEPS = 100

Control = Literal["load", "displacement"]


@dataclass(frozen=True)
class SpherePullOff(Result):
    r"""The pull-off of an adhesive sphere.

    Attributes
    ----------
    F_pulloff_over_EhR : ndarray or float
        The pull-off force over ``E h R`` (negative: tensile; 0 without adhesion).
    a_over_R_at_pulloff, c_over_R_at_pulloff : ndarray or float
        The contact and adhesive-zone radii it lets go from (``a = 0``: zero radius).
    delta_over_h_at_pulloff : ndarray or float
        The approach there over ``h``.
    mechanism : ndarray of str or str
        ``"contact"`` (the load's minimum inside the branch), ``"jump-out"`` (the approach's
        minimum, displacement control), ``"zero-radius"`` (at ``a -> 0``) or
        ``"no-adhesion"`` (``sigma0 = 0``: Hertz, no tensile load).
    control : str
        ``"load"`` or ``"displacement"``.
    R_over_h, sigma0_over_E, maugis_parameter : ndarray or float
        The parameters and Maugis' :math:`\lambda`.
    residual_separation : ndarray or float
        The logarithm of the gap at ``c`` over ``h`` in the state let go from (0 at the
        solution; the ``a -> 0`` end's quadratic, else the branch's).
    converged : ndarray or bool
        The gap condition met to :data:`~linecontact.sphere.contact.RESIDUAL_TOL`.
    """

    inputs: ClassVar[tuple[str, ...]] = INPUTS
    derived: ClassVar[tuple[str, ...]] = ("F_pulloff_over_piwR",)

    F_pulloff_over_EhR: NDArray | float = field(metadata=SI("pull_off_force", "EhR", "N"))
    a_over_R_at_pulloff: NDArray | float = field(
        metadata=SI("contact_radius_at_pull_off", "R", "m")
    )
    c_over_R_at_pulloff: NDArray | float = field(
        metadata=SI("adhesive_zone_radius_at_pull_off", "R", "m")
    )
    delta_over_h_at_pulloff: NDArray | float = field(metadata=SI("approach_at_pull_off", "h", "m"))
    mechanism: NDArray | str
    control: str
    R_over_h: NDArray | float
    sigma0_over_E: NDArray | float
    maugis_parameter: NDArray | float
    residual_separation: NDArray | float
    converged: NDArray | bool

    @property
    def F_pulloff_over_piwR(self):  # noqa: N802 - Maugis' unit of force
        r"""The pull-off in Maugis' unit :math:`\pi w R` (-3/2: JKR, -2: DMT)."""
        return over_piwR(self.F_pulloff_over_EhR, self.sigma0_over_E)


def _unit(rho: NDArray | float, s: NDArray | float) -> NDArray:
    r"""Maugis' unit of length over ``R``: :math:`(3\pi s/(4\rho))^{1/3}`."""
    return np.cbrt(3 * np.pi * s / (4 * rho))


def _slope(alpha, rho, s, of: int) -> NDArray:
    _, _, _, q, _ = _b.branch(alpha, rho, s)
    return _b.slopes(alpha, rho, s, q)[of]


def _minimum(rho: NDArray, s: NDArray, of: int) -> tuple[NDArray, NDArray]:
    """The lowest interior minimum of the load (``of=0``) or the approach (``of=1``).

    At each point its radius and its value; NaN where the branch has none.
    """
    n = rho.size
    alpha = GRID[None, :] * _unit(rho, s)[:, None]
    R = np.broadcast_to(rho[:, None], alpha.shape)
    S = np.broadcast_to(s[:, None], alpha.shape)
    x, F, delta, q, _ = _b.branch(alpha, R, S)
    slope = _b.slopes(alpha, R, S, q)[of]
    turns = (slope[:, :-1] < 0) & (slope[:, 1:] >= 0)
    point, k = np.nonzero(turns)
    lo, hi = np.log(alpha[point, k]), np.log(alpha[point, k + 1])
    f_lo, f_hi = slope[point, k], slope[point, k + 1]
    r, t = rho[point], s[point]
    # the Illinois method on the slope's sign change (false position, the stale end's value
    # halved): superlinear, and the bracket always holds the root; a bracket stops once it
    # is rounding wide or its next point is one of its ends
    side = np.zeros(lo.shape, int)
    act = np.arange(lo.size)
    for _ in range(_STEPS):
        if act.size == 0:
            break
        L, H, FL, FH, S = lo[act], hi[act], f_lo[act], f_hi[act], side[act]
        with np.errstate(divide="ignore", invalid="ignore"):
            mid = (L * FH - H * FL) / (FH - FL)
        mid = np.where(np.isfinite(mid) & (mid > L) & (mid < H), mid, 0.5 * (L + H))
        f = _slope(np.exp(mid), r[act], t[act], of)
        down = f < 0
        f_lo[act] = np.where(down, f, np.where(S == 1, 0.5 * FL, FL))
        f_hi[act] = np.where(~down, f, np.where(S == -1, 0.5 * FH, FH))
        side[act] = np.where(down, -1, 1)
        lo[act], hi[act] = np.where(down, mid, L), np.where(down, H, mid)
        width = hi[act] - lo[act]
        stuck = (mid <= L) | (mid >= H) | (f == 0)
        act = act[~(stuck | (width <= 4e-16 * np.maximum(1.0, np.abs(mid))))]
    a = np.exp(np.where(np.abs(f_lo) < np.abs(f_hi), lo, hi))
    value = _b.branch(a, r, t)[1 + of]
    best_a = np.full(n, np.nan)
    best_v = np.full(n, np.inf)
    for i in np.argsort(-value):  # the lowest minimum last, so it stays
        if value[i] <= best_v[point[i]]:
            best_v[point[i]], best_a[point[i]] = value[i], a[i]
    return best_a, np.where(np.isfinite(best_v), best_v, np.nan)


def sphere_pull_off(
    R_over_h: ArrayLike, sigma0_over_E: ArrayLike, control: Control = "load"
) -> SpherePullOff:
    r"""The pull-off of an adhesive sphere under load or displacement control.

    Parameters
    ----------
    R_over_h : array_like
        Radius over the adhesion range, in ``[1e-3, 1e12]``.
    sigma0_over_E : array_like
        Adhesive stress over the composite modulus, in ``[0, 1e6]``.
    control : {"load", "displacement"}
        What the apparatus holds fixed as it pulls.

    Returns
    -------
    SpherePullOff

    Notes
    -----
    Its limits: :math:`-(3/2)\pi w R` (JKR, load control) and :math:`-(5/6)\pi w R`
    (displacement control) as :math:`\lambda \to \infty`, :math:`-2\pi w R` (DMT) as
    :math:`\lambda \to 0`.

    Examples
    --------
    >>> p = sphere_pull_off(1e8, 0.01)  # lambda = 24: near JKR
    >>> print(f"{p.F_pulloff_over_piwR:.4f} {p.mechanism}")
    -1.5003 contact
    """
    if control not in ("load", "displacement"):
        raise ParameterError(
            "control", f"control must be 'load' or 'displacement', got {control!r}"
        )
    scalar, (rho, s) = checked(R_over_h=R_over_h, sigma0_over_E=sigma0_over_E)
    shape = rho.shape
    rho, s = rho.reshape(-1), s.reshape(-1)
    of = 0 if control == "load" else 1
    A = np.zeros(rho.shape)
    F = np.zeros(rho.shape)
    mech = np.full(rho.shape, "no-adhesion", dtype=object)
    adhesive = s > 0
    x0, F0, d0 = _b.separated(np.zeros(rho.shape), rho, s)  # the a -> 0 end
    C, D = x0.copy(), d0.copy()
    # the gap condition at the state let go from: the a -> 0 end's quadratic, its residual
    with np.errstate(divide="ignore"):
        res = np.log(rho * x0 * x0 / 2 + 2 * (1 - 2 / np.pi) * s * rho * x0)
    if np.any(adhesive):
        r, t = rho[adhesive], s[adhesive]
        a_min, v_min = _minimum(r, t, of)
        x, Fm, dm, _, res_m = _b.branch(np.nan_to_num(a_min, nan=1.0), r, t)
        # the end is the pull-off where the branch has no minimum, or a higher one (load
        # control: the zone then separates with less tension; displacement: it peels on)
        end_value = (F0 if of == 0 else d0)[adhesive]
        inner = np.isfinite(a_min) & (v_min < end_value)
        A[adhesive] = np.where(inner, a_min, 0.0)
        F[adhesive] = np.where(inner, Fm, F0[adhesive])
        C[adhesive] = np.where(inner, x, x0[adhesive])
        D[adhesive] = np.where(inner, dm, d0[adhesive])
        res[adhesive] = np.where(inner, res_m, res[adhesive])
        name = "contact" if of == 0 else "jump-out"
        mech[adhesive] = np.where(inner, name, "zero-radius")
    return as_result(
        SpherePullOff,
        scalar,
        shape,
        F_pulloff_over_EhR=F,
        a_over_R_at_pulloff=A,
        c_over_R_at_pulloff=C,
        delta_over_h_at_pulloff=D,
        mechanism=mech.astype(str),
        control=np.full(rho.shape, control),
        R_over_h=rho,
        sigma0_over_E=s,
        maugis_parameter=_sphere_maugis_parameter(rho, s),
        residual_separation=res,
        converged=np.abs(res) <= RESIDUAL_TOL,
    )


def sphere_contact_for_load(
    F_over_EhR: ArrayLike,
    R_over_h: ArrayLike,
    sigma0_over_E: ArrayLike,
    *,
    on_failure: str = "raise",
) -> SphereContact:
    r"""The stable contact of an adhesive sphere under a load ``F/(E h R)``.

    The contact branch beyond the load-control pull-off, where the load grows with the
    radius; a load below the pull-off has no contact.

    Parameters
    ----------
    F_over_EhR : array_like
        The load over ``E h R`` (compressive positive), in ``[-1e12, 1e12]``.
    R_over_h, sigma0_over_E : array_like
        As in :func:`sphere_contact`.
    on_failure : {"raise", "report"}
        A load below the pull-off raises :class:`~linecontact.errors.NoEquilibriumError`
        (``"raise"``) or gives NaN at that point (``"report"``).

    Returns
    -------
    SphereContact

    Examples
    --------
    >>> r = sphere_contact_for_load(0.0, 1e4, 0.001)
    >>> print(f"{r.a_over_R:.8f} {r.stable}")
    0.00874276 True
    """
    policy = failure_policy(on_failure)
    scalar, (F, rho, s) = checked(
        F_over_EhR=F_over_EhR, R_over_h=R_over_h, sigma0_over_E=sigma0_over_E
    )
    shape = F.shape
    F, rho, s = F.reshape(-1), rho.reshape(-1), s.reshape(-1)
    po = sphere_pull_off(rho, s)
    F_po = np.asarray(po.F_pulloff_over_EhR, float).reshape(-1)
    a_po = np.asarray(po.a_over_R_at_pulloff, float).reshape(-1)
    below = F < F_po
    if policy == "raise" and np.any(below):
        i = int(np.flatnonzero(below)[0])
        raise NoEquilibriumError(
            f"F_over_EhR = {float(F[i])!r} is below the pull-off force {float(F_po[i])!r} "
            f"(R_over_h = {float(rho[i])!r}, sigma0_over_E = {float(s[i])!r}): the sphere "
            "has come off"
        )
    # the root of F(a) = F on [a_po, hi]: Newton's steps on log a, safeguarded (rtsafe): a
    # step that leaves the bracket, or does not halve the one before last, is a bisection;
    # it starts at Hertz's radius for the load, where that is inside the bracket
    unit = np.where(s > 0, _unit(rho, s), 1.0)
    lo = np.log(np.maximum(a_po, 1e-200 * unit))
    hi = np.log(np.maximum(np.cbrt(np.maximum(F, 0.0) / rho) * 4, 40 * unit))
    for _ in range(200):  # widen until F(hi) >= F
        short = _b.branch(np.exp(hi), rho, s)[1] < F
        if not np.any(short):
            break
        hi = np.where(short, hi + 2.0, hi)
    with np.errstate(divide="ignore"):
        hertz = np.log(np.cbrt(0.75 * np.maximum(F, 0.0) / rho))
    v = np.where((hertz > lo) & (hertz < hi), hertz, 0.5 * (lo + hi))
    dx_old = dx = hi - lo
    for _ in range(400):
        a = np.exp(v)
        _, Fa, _, q, _ = _b.branch(a, rho, s)
        dF = _b.slopes(a, rho, s, q)[0]
        over = Fa > F
        hi, lo = np.where(over, v, hi), np.where(over, lo, v)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            step = (Fa - F) / (dF * a)
        new = v - step
        slow = np.abs(step) > 0.5 * np.abs(dx_old)
        bisect = ~np.isfinite(new) | (new < lo) | (new > hi) | slow
        new = np.where(bisect, 0.5 * (lo + hi), new)
        # a point whose load is met, or whose Newton step is below rounding, stays
        done = (Fa == F) | (~bisect & (np.abs(step) <= 4e-16 * np.maximum(1.0, np.abs(v))))
        new = np.where(done, v, new)
        dx_old, dx = dx, np.abs(new - v)
        v = new
        if np.all(done | below):
            break
    alpha = np.where(below, np.nan, np.exp(v))
    wide = ~below & (alpha > _domain.DOMAIN["a_over_R"][2])
    if np.any(wide):  # a load beyond the radii the sphere is solved for
        i = int(np.flatnonzero(wide)[0])
        raise ParameterError(
            "F_over_EhR",
            f"F_over_EhR = {float(F[i])!r} needs a contact radius a/R = {float(alpha[i]):.6g}, "
            f"beyond {_domain.DOMAIN['a_over_R'][2]:g} (R_over_h = {float(rho[i])!r}, "
            f"sigma0_over_E = {float(s[i])!r}): the sphere is solved for a/R up to it",
        )
    vals = states(np.where(below, 1.0, alpha), rho, s)
    vals["stable"] = ~below  # the branch beyond the pull-off, its end included
    for key in ("a_over_R", "c_over_R", "F_over_EhR", "delta_over_h", "residual_separation"):
        vals[key] = np.where(below, np.nan, vals[key])
    for key in ("converged", "stable_displacement"):  # no state: none of these
        vals[key] = np.where(below, False, vals[key])
    return as_result(SphereContact, scalar, shape, **vals)
