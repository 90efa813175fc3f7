r"""The contact for a load (:func:`contact_for_load`) and every equilibrium (:func:`equilibria`).

The inverse of :func:`linecontact.normal.normal_contact`: the half-width that carries a load
on the stable (or unstable) side of the load minimum, solved per point on the closed form.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _numerics as _num
from .. import closed_forms as _cf
from .. import domain as _domain
from .._validation import (
    FailurePolicy,
    broadcast,
    failure_policy,
    first_point,
    point_text,
    scalar_or_array,
)
from ..errors import ConvergenceError, NoEquilibriumError
from ..results import as_result
from ..sie import _in_chunks
from .contact import NormalContact, _closed_form_from_u
from .pulloff import _pulloff_arrays, pull_off

#: Relative load residual (over the larger of |F|, |Eq. 14| and the Hertz term) that
#: contact_for_load must meet; it reaches ~1e-15 wherever the solver's bracket holds the state.
_LOAD_RTOL = 1e-9


def _z_of_u(u):
    """The variable of the load iteration: ``u`` from ``u = 1`` on, ``1 + ln u`` below.

    The load is nearly linear in ``ln u`` near full contact (``Phi ~ u^-3``) and its distance
    from its limit nearly exponential in ``u`` towards zero width (``~ e^{-2u}``): in ``z``
    and on the logarithms of :func:`_load_step` Newton's method sees nearly straight lines.
    """
    return _num._where(u >= 1.0, u, 1.0 + np.log(u))


def _u_of_z(z):
    return _num._where(z >= 1.0, z, np.exp(z - 1.0))


def _load_step(z, lo, hi, dz_prev, target, kap, lt, pmin, p0, stable):
    """One safeguarded Newton step of the load equation on one branch, in ``z``.

    Stable branch (the load falls from infinity to its minimum ``pmin`` as ``u`` grows):
    ``g = ln(Phi - pmin) - lt``; unstable branch (the load rises from ``pmin`` to the
    zero-width load ``p0``): ``g = ln(p0 - Phi) - lt``; ``g`` decreases in ``z`` either way
    (nan, from rounding at a bracket end, counts as negative: the root lies before ``z``).
    The step is Newton's unless it leaves the bracket or does not halve the previous one
    (then bisection). Converged when ``Phi - target`` is at the rounding level of the load's
    two terms, or the Newton step at the rounding level of ``z``.
    """
    u = _u_of_z(z)
    bp = _cf._branch_point(u, kap)
    phi = bp["phi"]
    dphi = bp["dphi"] * _num._where(z >= 1.0, 1.0, u)  # dPhi/dz
    d = phi - pmin if stable else p0 - phi
    g = np.log(d) - lt
    dg = (dphi if stable else -dphi) / d
    up = g > 0
    lo = _num._where(up, z, lo)
    hi = _num._where(up, hi, z)
    dn = g / dg
    zn = z - dn
    zmax = _num._maximum(abs(z), 1.0)
    at_noise = abs(phi - target) <= 1e-15 * (
        bp["abar"] * bp["abar"] + abs(kap * bp["X"] * bp["St"])
    )
    conv = at_noise | (g == 0) | (abs(dn) <= 1e-15 * zmax)
    zn = _num._where(at_noise, z, zn)
    ok = conv | ((abs(zn) < np.inf) & (zn > lo) & (zn < hi) & (abs(dn) <= 0.5 * abs(dz_prev)))
    zn = _num._where(ok, zn, 0.5 * (lo + hi))
    stop = conv | (hi - lo <= 1e-15 * zmax)
    return (zn, lo, hi, zn - z), stop


def _solve_u_for_phi(target, kap, pmin, p0, us, stable: bool):
    """The u on one monotone piece of the branch where Phi(u) = target (flat or scalars).

    Stable: ``u`` in ``[1e-12, us]`` (``745`` for ``kappa = 0``), unstable: ``[us, 745]``.
    """
    where = _num._where
    with np.errstate(over="ignore", invalid="ignore", divide="ignore", under="ignore"):
        fin = abs(us) < np.inf
        if stable:
            lo = _num._full(target, _z_of_u(1e-12))
            hi = _z_of_u(where(fin, us, 745.0))
            lt = np.log(_num._maximum(target - pmin, 0.0))
            # start from the Hertz-like width of the load (at the pull-off load: its end)
            z0 = _z_of_u(_cf._u_guess(np.sqrt(_num._maximum(target, 0.0) + 1.0), kap))
            z0 = where(target <= pmin, hi, _num._minimum(_num._maximum(z0, lo), hi))
        else:
            lo = _z_of_u(us)
            hi = _num._full(target, 745.0)
            lt = np.log(_num._maximum(p0 - target, 0.0))
            z0 = _num._minimum(lo + 1.0, 0.5 * (lo + hi))
        (z, _, _, _), _ = _num._iterate(
            functools.partial(_load_step, stable=stable),
            (z0, lo, hi, hi - lo),
            (target, kap, lt, pmin, p0),
            200,
        )
        return _u_of_z(z)


def contact_for_load(
    F_over_Eh: ArrayLike,
    R_over_h: ArrayLike,
    sigma0_over_E: ArrayLike,
    *,
    branch: str = "stable",
    on_failure: FailurePolicy = "raise",
) -> Any:
    r"""The contact state(s) carrying a given load (closed form).

    Parameters
    ----------
    F_over_Eh : array_like
        Load over ``E h`` (compressive positive).
    R_over_h, sigma0_over_E : array_like
        As in :func:`normal_contact`.
    branch : {"stable", "unstable"}
        ``"stable"``: the state with :math:`dF/da > 0` (exists for :math:`F \ge F_\text{pull-off}`);
        ``"unstable"``: the narrower state with :math:`dF/da < 0` (exists only between the load
        minimum and Eq. 14).
    on_failure : {"raise", "report"}
        For a load that no contact of the branch carries: raise (``"raise"``, default), or
        report the point with ``state == "no-equilibrium"``, NaN widths (the load kept),
        ``converged`` and ``stable`` False (``"report"``; the other points are solved as
        usual); README, "Conventions".

    Returns
    -------
    NormalContact
        ``F_over_Eh`` is the load asked for (the state carries it to within
        ``error_estimate``, relative to the larger of the load, Eq. 14 and the Hertz term);
        ``state`` is ``"contact"``, or ``"no-equilibrium"`` for the points reported.

    Raises
    ------
    NoEquilibriumError
        If no contact of the requested branch carries the load, naming the pull-off force.
    """
    F = _domain.check("F_over_Eh", F_over_Eh)
    rho = _domain.check("R_over_h", R_over_h)
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    if branch not in ("stable", "unstable"):
        raise ValueError(f"branch must be 'stable' or 'unstable', got {branch!r}")
    policy = failure_policy(on_failure)
    scalar = scalar_or_array(F, rho, s)
    F, rho, s = (
        np.asarray(v, float) for v in broadcast(F_over_Eh=F, R_over_h=rho, sigma0_over_E=s)
    )
    _cf._check_kappa(rho, s)
    return _contact_for_load(F, rho, s, branch, policy, scalar)


def _solve_on_branch(F, kap, phi_min, F0, us_solve, rho, us, stable: bool):
    """a/R, c/R, the load found and the stability at the loads ``F`` on a branch.

    Flat arrays (a chunk of the points, :func:`linecontact.sie._in_chunks`) or NumPy
    scalars.
    """
    u = _solve_u_for_phi(F * (2 / np.pi), kap, phi_min, F0 * (2 / np.pi), us_solve, stable=stable)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore", under="ignore"):
        return _closed_form_from_u(u, kap, rho, us)


#: The parts of the pull-off that the inverse needs (:func:`_pulloff_arrays`).
_PULLOFF_KEYS = ("F_minimum_over_Eh", "F_zero_width_over_Eh", "us", "kappa", "phi_min")


def _contact_for_load(F, rho, s, branch: str, policy: str, scalar: bool, d=None):
    """The kernel of :func:`contact_for_load` (Dugdale): checked inputs, no check again.

    Float arrays of one shape (0-d with ``scalar``), kappa within range; ``d`` the pull-off
    of these points (:func:`_pulloff_arrays`, indexed like them) where the caller has it,
    else it is computed here. Returns the :class:`NormalContact`.
    """
    report = policy == "report"
    if d is None:
        d = _pulloff_arrays(rho, s, scalar, _PULLOFF_KEYS)
    Fmin, F0, us, kap = d["F_minimum_over_Eh"], d["F_zero_width_over_Eh"], d["us"], d["kappa"]
    F_asked = F
    if branch == "stable":
        # without adhesion a contact needs a compressive load (F = 0 touches at zero width),
        # as in sliding_contact_for_load
        nonpos = (s == 0) & (F <= 0)
        bad = (F < Fmin) | nonpos
        if np.any(nonpos) and not report:
            _, at = first_point(nonpos, F_over_Eh=F, R_over_h=rho)
            raise NoEquilibriumError(
                f"no contact carries F_over_Eh={at['F_over_Eh']!r} without adhesion "
                f"(sigma0_over_E=0, R_over_h={at['R_over_h']!r}): the pull-off force is 0 and "
                "the load must be > 0"
            )
        if np.any(bad) and not report:
            _, at = first_point(bad, F_over_Eh=F, Fmin=Fmin, R_over_h=rho, sigma0_over_E=s)
            raise NoEquilibriumError(
                f"no contact carries F_over_Eh={at.pop('F_over_Eh')!r}: it is below the "
                f"pull-off force, the minimum load on the contact branch F_minimum_over_Eh="
                f"{at.pop('Fmin')!r} ({point_text(at)}); the cylinder has pulled off"
            )
        # a load that exists stands in for the ones reported (their values are NaN below)
        F = np.where(bad, Fmin, F)
    else:
        bad = ~((F > Fmin) & (F < F0))
        if np.any(bad) and not report:
            _, at = first_point(bad, F_over_Eh=F, Fmin=Fmin, F0=F0, R_over_h=rho, sigma0_over_E=s)
            raise NoEquilibriumError(
                f"no unstable contact carries F_over_Eh={at.pop('F_over_Eh')!r}: that "
                f"branch exists only for F_minimum_over_Eh={at.pop('Fmin')!r} < "
                f"F_over_Eh < F_zero_width_over_Eh={at.pop('F0')!r} ({point_text(at)})"
            )
        F = np.where(bad, 0.5 * (Fmin + F0), F)
    # no unstable branch (kappa = 0): any finite end stands in for the points reported
    us_solve = np.where(bad & ~np.isfinite(us), 1.0, us) if branch == "unstable" else us
    Fs, rs = _num._scalars(F, rho) if scalar else (F.reshape(-1), rho.reshape(-1))
    flat = (lambda v: np.float64(v)) if scalar else (lambda v: np.reshape(v, -1))
    args = (Fs, flat(kap), flat(d["phi_min"]), flat(F0), flat(us_solve), rs, flat(us))
    solve = functools.partial(_solve_on_branch, stable=branch == "stable")
    # in chunks of points: bounded memory for any number of them
    A, C, Fc, stable = solve(*args) if scalar else _in_chunks(solve, Fs.size, *args)
    if not scalar:
        A, C, Fc, stable = (v.reshape(F.shape) for v in (A, C, Fc, stable))
    Fv, rv = (Fs, rs) if scalar else (F, rho)
    scale = _num._maximum(_num._maximum(abs(Fv), abs(F0)), np.pi / 4 * A * A * rv)
    res = abs(Fc - Fv) / _num._maximum(scale, 1e-300)
    converged = ((abs(Fc) < np.inf) & (res <= _LOAD_RTOL)) | bad
    if not (bool(converged) if scalar else converged.all()):
        _, at = first_point(
            ~np.asarray(converged, bool), F_over_Eh=F, R_over_h=rho, sigma0_over_E=s, Fc=Fc
        )
        Fci = at.pop("Fc")
        raise ConvergenceError(
            f"contact_for_load did not converge at {point_text(at)}: the closest contact "
            f"carries F_over_Eh={Fci!r} (the load is outside the range of the solver)"
        )
    _domain.check_widths(np.where(bad, np.nan, A), F_asked, "F_over_Eh")
    _cf._warn_wide(np.where(bad, np.nan, A))
    z: NDArray | float = 0.0 if scalar else np.zeros(F.shape)
    nan = np.where(bad, np.nan, 1.0)
    return as_result(
        NormalContact,
        scalar,
        method="closed-form",
        a_over_R=A * nan,
        c_over_R=C * nan,
        F_over_Eh=F_asked,  # the load asked for; its residual is the error_estimate
        R_over_h=rho,
        sigma0_over_E=s,
        n_collocation=0 if scalar else np.zeros(F.shape, dtype=int),
        residual_separation=z,
        residual_consistency=z,
        error_estimate=res * nan,
        converged=converged & ~bad,
        stable=stable & ~bad,
        state=np.where(bad, "no-equilibrium", "contact"),
    )


@dataclass(frozen=True)
class Equilibrium:
    """One equilibrium state at a given load.

    ``branch`` is ``"contact"`` or ``"non-contact"``; ``stable`` refers to load control.
    """

    branch: str
    stable: bool
    F_over_Eh: float
    a_over_R: float
    c_over_R: float
    central_gap_over_h: float


#: Below this a/R a contact root at the zero-width load (within round-off) is touch-down.
_TOUCHDOWN_WIDTH = 1e-6


def equilibria(F_over_Eh: float, R_over_h: float, sigma0_over_E: float) -> tuple[Equilibrium, ...]:
    r"""Every equilibrium state carrying the load ``F_over_Eh`` (scalar parameters).

    Stable contact (:math:`F \ge F_\text{pull-off}`), unstable narrow contact (between the load
    minimum and Eq. 14), and the non-contact state (between Eq. 14 and 0). Empty below the pull-off
    force; the caller says so. A contact has a positive width: at the zero-width load (Eq. 14,
    within round-off) the narrow end of the contact branch is the touch-down state, listed once, as
    the non-contact state (:math:`a = 0`, gap 0).
    """
    F = _domain.scalar("F_over_Eh", F_over_Eh)
    rho = _domain.scalar("R_over_h", R_over_h)
    s = _domain.scalar("sigma0_over_E", sigma0_over_E)
    po = pull_off(rho, s)
    states: list[Equilibrium] = []
    # At the zero-width load the contact branch ends at a = 0: the touch-down state, which
    # the non-contact state at that load is (a = 0, gap 0). Within round-off of that load
    # the branch's root is not resolved (F - F_zero_width ~ a^2: a falls to 0, or to 5e-299
    # a ulp away); such a root is that state, not a contact, and is listed once, as it.
    F_zw = float(po.F_zero_width_over_Eh)
    at_touchdown = s > 0 and abs(F - F_zw) <= 8 * np.finfo(float).eps * abs(F_zw)

    def contact(branch: str, stable: bool) -> None:
        r = contact_for_load(F, rho, s, branch=branch)
        a = float(r.a_over_R)
        if a > 0 and not (at_touchdown and a < _TOUCHDOWN_WIDTH):
            states.append(Equilibrium("contact", stable, F, a, float(r.c_over_R), 0.0))

    if F >= po.F_minimum_over_Eh:
        contact("stable", True)
    if po.F_minimum_over_Eh < F < po.F_zero_width_over_Eh:
        contact("unstable", False)
    if s > 0 and po.F_zero_width_over_Eh <= F < 0:
        # invert F = -2 s rho C for C, then the gap
        C = -F / (2 * s * rho)
        k = 4 * _cf.LN2 * s / np.pi
        g = 1 - rho * (C * C / 2 + k * C)
        states.append(Equilibrium("non-contact", False, F, 0.0, C, float(np.clip(g, 0, 1))))
    return tuple(states)
