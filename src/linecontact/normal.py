r"""Normal contact of a cylinder with Maugis--Dugdale adhesion (paper Eqs. 5--14).

Units as in :mod:`linecontact.reference`: ``a/R``, ``c/R``, ``F/(E h)``, ``sigma0/E``,
``R/h``; compressive pressure and load positive.

Two solvers give the same :class:`NormalContact`:

``method="closed-form"`` (default)
    The Maugis--Dugdale line-contact solution (Baney & Hui 1997; Johnson & Greenwood
    2008), one scalar root per point.
``method="collocation"``
    The paper's route: the singular integral equation (Eq. 9) for the bounded pressure
    :math:`\bar p = p + \sigma_0` on :math:`|x| < a`, solved by Gauss--Chebyshev collocation
    (:class:`linecontact.sie.BoundedSolver`), with the separation condition (Eq. 11) for the
    end ``c`` of the adhesive zone and equilibrium (Eq. 12) for the load. The log kernel of
    Eq. 11, singular at :math:`\xi = a`, is integrated by product integration. The number of
    collocation points adapts per point to the distance between ``c`` and ``a`` (the log
    source at ``x = c`` limits the convergence rate to :math:`(c/a + \sqrt{c^2/a^2-1})^{-n}`).

In plane strain the rigid approach of remote points is defined only up to a logarithmic
constant, so no approach is reported: the load is controlled by ``F`` or by ``a``.
"""

from __future__ import annotations

import functools
import warnings
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import domain as _domain
from . import reference as _ref
from ._validation import (
    RAISE,
    FailurePolicy,
    broadcast,
    check_array,
    check_solver_options,
    failure_policy,
    first_point,
    point_text,
    positions,
    scalar_or_array,
)
from .errors import ConvergenceError, NoEquilibriumError
from .results import Result, as_output
from .sie import SIZES, BoundedSolver, _chunks, log_end_moments

__all__ = [
    "Equilibrium",
    "LoadCurve",
    "NonContact",
    "NormalContact",
    "PullOff",
    "SNAP_OFF_MIN_WIDTH_OVER_H",
    "ZERO_WIDTH_LOAD_RTOL",
    "contact_for_load",
    "equilibria",
    "load_curve",
    "non_contact",
    "normal_contact",
    "pull_off",
]

#: The pull-off is called a snap-off when the contact half-width at the load minimum is at
#: least this many ranges ``h`` of the adhesive stress (``h = 0.97 z0``, about one atomic
#: spacing); a contact that shrinks below that width before it lets go peels to zero width
#: (docs/derivations.md, Sec. 4). The label only: the pull-off force is always the minimum.
SNAP_OFF_MIN_WIDTH_OVER_H = 1.0

#: ... and the pull-off is called a snap-off too when it lies more than this fraction of
#: Eq. (14) below Eq. (14), however narrow the contact it lets go from: ``"zero-width"``
#: promises a pull-off force that is Eq. (14) to within 1 % (at small ``R/h`` a contact
#: narrower than ``h`` can let go far below it, e.g. 39 % at ``R/h = 1``, ``sigma0/E = 2``).
ZERO_WIDTH_LOAD_RTOL = 1e-2

#: Relative load residual (over the larger of |F|, |Eq. 14| and the Hertz term) that
#: contact_for_load must meet; it reaches ~1e-15 wherever the solver's bracket holds the state.
_LOAD_RTOL = 1e-9

#: Collocation sizes tried by ``n="auto"``.
_SIZES = SIZES[: SIZES.index(2048) + 1]


@dataclass(frozen=True)
class NormalContact(Result):
    """Adhesive normal contact at given contact half-widths.

    Attributes
    ----------
    a_over_R, c_over_R : ndarray or float
        Contact and adhesive-zone half-widths over the radius.
    F_over_Eh : ndarray or float
        Load per unit length over ``E h`` (compressive positive).
    R_over_h, sigma0_over_E : ndarray or float
        The parameters, broadcast.
    method : str
        ``"closed-form"`` or ``"collocation"``.
    n_collocation : ndarray or int
        Collocation nodes used at each point (0 for the closed form).
    residual_separation : ndarray or float
        Residual of the separation condition (gap at ``c`` minus ``h``) over ``h``.
    residual_consistency : ndarray or float
        Residual of the collocation consistency condition (0 for the closed form).
    error_estimate : ndarray or float
        Estimated discretisation error (Chebyshev tail over the largest coefficient; 0 for
        the closed form).
    converged : ndarray or bool
        All tolerances met.
    stable : ndarray or bool
        ``dF/da > 0``: the state is stable under load control.
    state : ndarray of str or str
        ``"contact"``; ``"no-equilibrium"`` for a load no contact carries, reported by
        :func:`contact_for_load` with ``on_failure="report"`` (its values are NaN).
    """

    inputs: ClassVar[tuple[str, ...]] = ("R_over_h", "sigma0_over_E", "method")
    derived: ClassVar[tuple[str, ...]] = ("c_over_a",)

    a_over_R: NDArray | float
    c_over_R: NDArray | float
    F_over_Eh: NDArray | float
    R_over_h: NDArray | float
    sigma0_over_E: NDArray | float
    method: str
    n_collocation: NDArray | int
    residual_separation: NDArray | float
    residual_consistency: NDArray | float
    error_estimate: NDArray | float
    converged: NDArray | bool
    stable: NDArray | bool
    state: NDArray | str

    @property
    def c_over_a(self):
        """Adhesive-zone to contact half-width ratio ``c/a`` (>= 1)."""
        return np.asarray(self.c_over_R) / np.asarray(self.a_over_R)

    def pressure(self, x_over_R: ArrayLike) -> NDArray:
        r"""Contact pressure ``p/E`` (compressive positive) at ``x/R``.

        ``x_over_R`` has shape ``(m,)`` (or broadcasts against the points plus one trailing
        axis); the result has shape ``points.shape + (m,)``. Inside the contact it is the
        solution of the method used; ``-sigma0/E`` in the adhesive zones; zero beyond.
        """
        x = positions("x_over_R", x_over_R, np.shape(self.a_over_R))
        A = np.asarray(self.a_over_R, dtype=float)[..., None]
        C = np.asarray(self.c_over_R, dtype=float)[..., None]
        s = np.asarray(self.sigma0_over_E, dtype=float)[..., None]
        ax = np.abs(x)
        if self.method == "closed-form":
            with np.errstate(divide="ignore", invalid="ignore", over="ignore"):  # x*x, |x| >> a
                inner = 0.5 * np.sqrt(np.clip(A * A - x * x, 0, None)) - (
                    2 * s / np.pi
                ) * np.arctan(np.sqrt((C * C - A * A) / np.clip(A * A - x * x, 1e-300, None)))
        else:
            inner = self._collocation_pressure(x)
        p = np.where(ax < A, inner, np.where(ax <= C, -s, 0.0))
        return p

    def _collocation_pressure(self, x: NDArray) -> NDArray:
        """Bounded pressure minus sigma0 inside the contact, re-solved at the stored c/a."""
        A = np.atleast_1d(np.asarray(self.a_over_R, dtype=float))
        C = np.atleast_1d(np.asarray(self.c_over_R, dtype=float))
        s = np.broadcast_to(np.asarray(self.sigma0_over_E, float), A.shape)
        nn = np.broadcast_to(np.asarray(self.n_collocation), A.shape)
        u = np.arccosh(np.maximum(C / A, 1.0))
        xx = np.broadcast_to(x, A.shape + x.shape[-1:])
        result = np.zeros(A.shape + x.shape[-1:])
        for n in np.unique(nn):
            sel = nn == n
            solver = BoundedSolver(int(n))
            sol = solver.solve(_rhs(solver, A[sel], s[sel], u[sel])[0], values=False)
            result[sel] = solver.evaluate(sol, xx[sel] / A[sel, None]) - s[sel, None]
        return result.reshape(np.shape(self.a_over_R) + x.shape[-1:])


# --------------------------------------------------------------------------------------------
# closed form


def _closed_form_from_u(u, kap, rho, ustar):
    bp = _ref._branch_point(u, kap)
    sq = np.sqrt(2 / rho)
    A = bp["abar"] * sq
    C = np.maximum(bp["X"] * bp["Ct"] * sq, A)  # c >= a despite rounding
    F = (np.pi / 2) * bp["phi"]
    stable = u <= ustar
    return A, C, F, stable


def _stable(u, kap, bp):
    """Stable under load control: wider than the load minimum, ``u <= u*`` (one definition).

    ``dF/da > 0`` decides where its sign is clear; where the derivative is lost in
    round-off (near the minimum, or at widths so small that the load is flat to the last
    digit) ``u`` is compared with the ``u*`` of the minimum (:func:`_ustar`), as
    :func:`contact_for_load` and :func:`equilibria` do. Arrays or NumPy scalars.
    """
    d = bp["dphi"]
    terms = (
        abs(2 * bp["abar"] * bp["abar"] * bp["dln"])
        + abs(kap * bp["X"] * bp["dln"] * bp["St"])
        + abs(kap * bp["X"] * bp["Ct"])
    )
    clear = abs(d) > 1e-8 * terms
    if not isinstance(u, np.ndarray):
        return bool(d < 0) if clear else bool(u <= _ustar(kap))
    out = np.asarray(d < 0)
    unclear = ~clear
    if np.any(unclear):
        out = out.copy()
        out[unclear] = u[unclear] <= _ustar(kap[unclear])
    return out


def _ustar(kap: NDArray | np.float64) -> NDArray | np.float64:
    """U of the load minimum (inf where the minimum sits at vanishing width, kappa = 0).

    Arrays or NumPy scalars (the scalar fast path, see :func:`linecontact.reference._where`).
    """
    if np.ndim(kap) == 0:
        return _ref._u_stationary(kap) if kap > 0 else np.float64(np.inf)
    kap = np.asarray(kap, dtype=float)
    us = np.full(kap.shape, np.inf)
    pos = kap > 0
    if pos.any():
        us[pos] = _ref._u_stationary(kap[pos])
    return us


def _closed_form(A, rho, s):
    """u, c/R, F/(Eh), separation residual, stability: flat arrays or NumPy scalars.

    Called inside the ``np.errstate`` of :func:`normal_contact` (see ``_ref._solve_abar``).
    """
    kap = _ref._kappa(rho, s)
    abar = A * np.sqrt(rho / 2)
    u, res, _, bp = _ref._solve_abar(abar, kap)
    # c >= a exactly (coth u >= 1), which the product's rounding can miss by an ulp or two
    C = np.maximum(bp["X"] * bp["Ct"] * np.sqrt(2 / rho), A)
    F = (np.pi / 2) * bp["phi"]
    return u, C, F, res, _stable(u, kap, bp)


# --------------------------------------------------------------------------------------------
# collocation


def _rhs(solver: BoundedSolver, A, s, u):
    """Right-hand side of Eq. 9 on [-1, 1] (x/a) and its derivative in u = arccosh(c/a)."""
    x = solver.collocation_unit
    A = A[..., None]
    s = s[..., None]
    u = u[..., None]
    m1 = 2 * np.sinh(u / 2) ** 2  # m - 1 without cancellation, m = cosh u
    mmx = m1 + (1 - x)  # m - x
    mpx = m1 + (1 + x)  # m + x
    # ln((m-x)/(m+x)): as log1p for wide adhesive zones (m > 2, the ratio is near 1 and the
    # values are O(1/m)), as log of the ratio otherwise (it may be small near x = 1)
    wide = (m1 > 1.0).reshape(-1)
    mmx2 = mmx.reshape(-1, x.size)
    mpx2 = mpx.reshape(-1, x.size)
    lg = np.empty(mmx2.shape)
    lg[wide] = np.log1p(-2 * x / mpx2[wide])
    lg[~wide] = np.log(mmx2[~wide] / mpx2[~wide])
    lg = lg.reshape(mmx.shape)
    f = -0.5 * A * x + (s / np.pi) * lg
    df = (2 * s / np.pi) * np.sinh(u) * x / (mmx * mpx)
    return f, df


def _I(u: NDArray) -> tuple[NDArray, NDArray]:
    """I(m) = int_1^m ln((m-t)/(m+t)) dt and dI/du, m = cosh u (the last term of Eq. 11)."""
    small = u < 1.0
    us = np.where(small, u, 1.0)
    mm1 = 2 * np.sinh(us / 2) ** 2
    mp1 = 2 * np.cosh(us / 2) ** 2
    ms = np.cosh(us)
    with np.errstate(divide="ignore", invalid="ignore"):
        i_small = (
            np.where(mm1 > 0, mm1 * np.log(mm1), 0.0) + mp1 * np.log(mp1) - 2 * ms * np.log(2 * ms)
        )
    # large u: I = 2m ln(tanh(u)/2) + 2 ln coth(u/2)
    ul = np.where(small, 1.0, u)
    q = np.exp(-2 * ul)
    ln_tanh = np.log1p(-q) - np.log1p(q)
    ln_tanh_half = np.log1p(-np.exp(-ul)) - np.log1p(np.exp(-ul))
    i_large = 2 * np.cosh(np.minimum(ul, 700)) * (ln_tanh - np.log(2.0)) - 2 * ln_tanh_half
    val = np.where(small, i_small, i_large)
    # dI/du = I'(m) sinh u = 2 sinh u ln(tanh(u)/2)
    qq = np.exp(-2 * u)
    with np.errstate(divide="ignore", invalid="ignore"):
        dval = (
            2
            * np.sinh(np.minimum(u, 700))
            * (np.log(-np.expm1(-2 * u)) - np.log1p(qq) - np.log(2.0))
        )
    dval = np.where(u > 0, dval, 0.0)
    return val, dval


def _colloc_eval(solver: BoundedSolver, A, s, rho, u):
    """Separation residual (Eq. 11 times R/h; 1 at u = 0), its u-derivative and extras."""
    n = solver.n
    f, df = _rhs(solver, A, s, u)
    sol = solver.solve(f, values=False)
    dsol = solver.solve(df, values=False)
    b, db = sol.coefficients, dsol.coefficients
    dmu, dmu_du = log_end_moments(n, u)
    J = np.einsum("...j,...j->...", b, dmu)
    dJ = np.einsum("...j,...j->...", db, dmu) + np.einsum("...j,...j->...", b, dmu_du)
    Iv, dI = _I(u)
    sh = np.sinh(u)
    ch = np.cosh(u)
    Rv = 1 + rho * ((2 * A / np.pi) * J + (2 * s * A / np.pi) * Iv - 0.5 * A * A * sh * sh)
    dR = rho * ((2 * A / np.pi) * dJ + (2 * s * A / np.pi) * dI - A * A * sh * ch)
    resultant = (np.pi / 2) * b[..., 0]
    # coefficients of the even g: the last two non-zero ones estimate the truncation error
    tail = np.max(np.abs(b[..., -3:]), axis=-1) / np.maximum(np.max(np.abs(b), axis=-1), 1e-300)
    return Rv, dR, resultant, sol.consistency, tail


def _newton_u(solver, A, s, rho, u0, maxiter=80, tol=1e-14):
    """Bracketed Newton on the decreasing residual R(u) (R(0) = 1 > 0).

    Returns u, converged, and the last evaluation (R, resultant, consistency, tail).
    """
    P = u0.size
    u = u0.copy()
    lo = np.zeros(P)
    hi = np.full(P, np.inf)
    active = np.ones(P, bool)
    last = [np.ones(P), np.zeros(P), np.zeros(P), np.full(P, np.inf)]
    for _ in range(maxiter):
        idx = np.nonzero(active)[0]
        if idx.size == 0:
            break
        ui = u[idx]
        Ri, dRi, res_, cons, tail = _colloc_eval(solver, A[idx], s[idx], rho[idx], ui)
        for arr, v in zip(last, (Ri, res_, cons, tail), strict=True):
            arr[idx] = v
        lo[idx] = np.where(Ri > 0, ui, lo[idx])
        hi[idx] = np.where(Ri <= 0, ui, hi[idx])
        with np.errstate(divide="ignore", invalid="ignore"):
            un = ui - Ri / dRi
        mid = np.where(np.isfinite(hi[idx]), 0.5 * (lo[idx] + hi[idx]), 2 * ui + 1)
        bad = ~np.isfinite(un) | (un <= lo[idx]) | (un >= hi[idx])
        un = np.where(bad, mid, un)
        done = np.abs(Ri) <= tol
        un = np.where(done, ui, un)
        u[idx] = un
        active[idx] = ~done & (np.abs(un - ui) > 4e-16 * np.maximum(ui, 1e-3))
    converged = ~active & (np.abs(last[0]) <= 1e-10)
    return u, converged, last


def _stable_at(u, kap):
    """``dF/da > 0`` at ``u`` on the branch, over chunks of points (bounded memory)."""
    shape = np.shape(u)
    u = np.reshape(u, -1)
    kap = np.broadcast_to(kap, shape).reshape(-1)
    out = np.empty(u.size, bool)
    for c in _chunks(u.size, 0):
        out[c] = _stable(u[c], kap[c], _ref._branch_point(u[c], kap[c]))
    return out.reshape(shape)


def _newton_u_chunked(n, A, s, rho, u0):
    """:func:`_newton_u` at ``n`` nodes over the points, in chunks of bounded memory."""
    P = u0.size
    u, conv = np.empty(P), np.empty(P, bool)
    last = [np.empty(P) for _ in range(4)]
    solver = BoundedSolver(int(n))
    for c in _chunks(P, int(n)):
        uc, cc, lc = _newton_u(solver, A[c], s[c], rho[c], u0[c])
        u[c], conv[c] = uc, cc
        for o, v in zip(last, lc, strict=True):
            o[c] = v
    return u, conv, last


def _collocation(A, rho, s, n, tol):
    A, rho, s = np.broadcast_arrays(A, rho, s)
    shape = A.shape
    A, rho, s = (np.ascontiguousarray(v, dtype=float).reshape(-1) for v in (A, rho, s))
    sizes = np.asarray(_SIZES)
    # first pass: n0 nodes (or the n asked for) locate c/a
    n0 = 16 if n == "auto" else int(n)
    u0 = np.arccosh(np.sqrt(1 + 2 / (rho * A * A)))  # rigid-cylinder estimate
    u, conv, (Rv, res_, cons, tail) = _newton_u_chunked(n0, A, s, rho, u0)
    nsel = np.full(A.size, n0)
    if n == "auto":
        # the log source at x = c limits convergence to about exp(-1.5 u n): pick n for tol,
        # then move points whose error estimate still exceeds tol one size up
        need = np.log(1 / tol) / (1.5 * np.maximum(u, 1e-300))
        pending = tail > tol
        target = sizes[np.minimum(np.searchsorted(sizes, need), sizes.size - 1)]
        nsel = np.where(pending, np.maximum(target, sizes[1]), nsel)
        while pending.any():
            for nn in np.unique(nsel[pending]):
                idx = np.nonzero(pending & (nsel == nn))[0]
                ui, ci, (Ri, ri, co, ti) = _newton_u_chunked(nn, A[idx], s[idx], rho[idx], u[idx])
                u[idx], conv[idx], Rv[idx], res_[idx], cons[idx], tail[idx] = ui, ci, Ri, ri, co, ti
            pending = pending & (tail > tol) & (nsel < sizes[-1])
            nsel = np.where(
                pending, sizes[np.minimum(np.searchsorted(sizes, nsel) + 1, sizes.size - 1)], nsel
            )
    F = rho * A * (res_ - 2 * np.cosh(u) * s)
    C = A * np.cosh(u)
    converged = conv & (tail <= 10 * tol) & np.isfinite(F)
    out = dict(
        u=u, C=C, F=F, res=np.abs(Rv), cons=np.abs(cons), tail=tail, n=nsel, converged=converged
    )
    return {k: v.reshape(shape) for k, v in out.items()}


def normal_contact(
    a_over_R: ArrayLike,
    R_over_h: ArrayLike,
    sigma0_over_E: ArrayLike,
    *,
    method: str = "closed-form",
    n: int | str = "auto",
    tol: float = 1e-12,
    on_failure: FailurePolicy = RAISE,
    **deprecated: Any,
) -> NormalContact:
    r"""Adhesive-zone width and load for given contact half-widths (Eqs. 9, 11, 12).

    Parameters
    ----------
    a_over_R : array_like
        Contact half-width over the radius, ``> 0``.
    R_over_h : array_like
        Radius over the range of the adhesive stress, ``> 0``.
    sigma0_over_E : array_like
        Adhesive (Dugdale) stress over the composite modulus, ``>= 0`` (0 gives Hertz);
        ``kappa = (4/pi) sigma0_over_E sqrt(2 R_over_h)`` at most
        :data:`~linecontact.reference.KAPPA_MAX` (1e12) here and in every normal and sliding
        solver.
    method : {"closed-form", "collocation"}
        Solver (see the module docstring).
    n : int or "auto"
        Collocation nodes (``"auto"``: chosen per point for ``tol``).
    tol : float
        Target discretisation error of the collocation solver.
    on_failure : {"raise", "report"}
        A point that misses its tolerance raises
        :class:`~linecontact.errors.ConvergenceError` (``"raise"``, default), or is
        flagged in ``converged`` (``"report"``); README, "Conventions". Replaces the
        deprecated ``raise_on_failure`` (``False`` is ``"report"``).

    Returns
    -------
    NormalContact
        The inputs broadcast together; scalars in, scalars out.

    Examples
    --------
    >>> r = normal_contact(0.05, 100.0, 0.0)        # Hertz: F/(Eh) = (pi/4)(a/R)^2 R/h
    >>> round(r.F_over_Eh, 12) == round(3.141592653589793 / 4 * 0.05**2 * 100, 12)
    True
    >>> r2 = normal_contact(0.05, 100.0, 0.01, method="collocation")
    >>> abs(r2.F_over_Eh - normal_contact(0.05, 100.0, 0.01).F_over_Eh) < 1e-10
    True
    """
    A = _domain.check("a_over_R", a_over_R)
    rho = _domain.check("R_over_h", R_over_h)
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    if method not in ("closed-form", "collocation"):
        raise ValueError(f"method must be 'closed-form' or 'collocation', got {method!r}")
    check_solver_options(n, tol, n_max=8192)
    policy = failure_policy(on_failure, where="normal_contact", **deprecated)
    scalar = scalar_or_array(A, rho, s)
    A, rho, s = broadcast(a_over_R=A, R_over_h=rho, sigma0_over_E=s)
    _ref._check_kappa(rho, s)
    _ref._warn_wide(A)
    # a contact half-width far outside the solvers' range (a/R ~ 1e-200 or 1e20) overflows
    # on the way; the residual and finiteness checks below turn that into non-convergence
    with np.errstate(over="ignore", invalid="ignore", divide="ignore", under="ignore"):
        if method == "closed-form":
            ncol: NDArray | int
            cons: NDArray | float
            err: NDArray | float
            if scalar:  # the same kernels on NumPy scalars (see reference._where)
                u, C, F, res, stable = _closed_form(*_ref._scalars(A, rho, s))
                ncol, cons, err = 0, 0.0, 0.0
            else:
                shape = A.shape
                flat = (np.reshape(v, -1) for v in (A, rho, s))
                u, C, F, res, stable = (v.reshape(shape) for v in _closed_form(*flat))
                ncol = np.zeros(shape, dtype=int)
                cons = np.zeros(shape)
                err = np.zeros(shape)
            converged = (res < 1e-12) & (abs(C) < np.inf) & (abs(F) < np.inf)  # isfinite
        else:
            kap = _ref._kappa(rho, s)
            r = _collocation(A, rho, s, n, tol)
            u, C, F = r["u"], r["C"], r["F"]
            res, cons, err, ncol = r["res"], r["cons"], r["tail"], r["n"]
            converged = r["converged"] & np.isfinite(C)
            # residual R is scaled so that 1 <-> h; it is the separation residual over h
            stable = _stable_at(u, kap)
    if policy == "raise" and not (bool(converged) if scalar else converged.all()):
        i, at = first_point(~np.asarray(converged, bool), a_over_R=A, R_over_h=rho, sigma0_over_E=s)
        nn = int(np.reshape(ncol, -1)[i])
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            ca = np.reshape(C / A, -1)
        if not (np.isfinite(ca[i]) and ca[i] >= 1):
            hint = "the contact half-width is outside the solver's range"
        elif n == "auto":
            hint = f"the adhesive zone is too thin (c/a = {ca[i]:.6g}) for n <= {_SIZES[-1]} nodes"
        else:
            hint = f"n = {nn} nodes are too few for tol = {tol:g}; try n='auto'"
        raise ConvergenceError(
            f"normal_contact ({method}) did not converge at {point_text(at)} (separation residual "
            f"{float(np.reshape(res, -1)[i]):.3g}, error estimate "
            f"{float(np.reshape(err, -1)[i]):.3g}): {hint}"
        )
    vals = dict(
        a_over_R=A,
        c_over_R=C,
        F_over_Eh=F,
        R_over_h=rho,
        sigma0_over_E=s,
        n_collocation=ncol,
        residual_separation=res,
        residual_consistency=cons,
        error_estimate=err,
        converged=converged,
        stable=stable,
        state=np.full(A.shape, "contact"),
    )
    if scalar:  # as_output(v, True), inline: this is a fair part of a scalar call
        vals = {
            k: v.item() if isinstance(v, np.generic | np.ndarray) else v for k, v in vals.items()
        }
    else:
        vals = {k: as_output(np.asarray(v), scalar) for k, v in vals.items()}
    return NormalContact(method=method, **vals)


# --------------------------------------------------------------------------------------------
# pull-off, inverse, non-contact branch


@dataclass(frozen=True)
class PullOff(Result):
    """Pull-off under load control: the global minimum of the load on the contact branch.

    Attributes
    ----------
    F_pulloff_over_Eh : ndarray or float
        The pull-off force over ``E h`` (negative).
    a_over_R_at_pulloff, c_over_R_at_pulloff : ndarray or float
        Half-widths at pull-off, the state of the minimum (``a = 0``, the touching state,
        when the minimum is Eq. 14 itself: no adhesion, or a width below the floating-point
        range).
    mechanism : ndarray of str or str
        ``"snap-off"``: the contact lets go from a half-width of at least the adhesion range
        ``h`` (:data:`SNAP_OFF_MIN_WIDTH_OVER_H`), or at a load more than 1 % below Eq.
        (14) (:data:`ZERO_WIDTH_LOAD_RTOL`); ``"zero-width"``: it first peels to a width
        below ``h`` and lets go at a load within 1 % of Eq. (14).
    F_zero_width_over_Eh : ndarray or float
        Eq. (14), the load at vanishing contact width.
    F_minimum_over_Eh, a_over_R_at_minimum : ndarray or float
        The minimum of the load on the contact branch and its width (equal to the pull-off
        force and width; kept under these names for existing callers).
    kappa, maugis_parameter : ndarray or float
        The group that fixes the shape of the load curve, and Baney & Hui's lambda.
    """

    inputs: ClassVar[tuple[str, ...]] = ("R_over_h", "sigma0_over_E")

    F_pulloff_over_Eh: NDArray | float
    a_over_R_at_pulloff: NDArray | float
    c_over_R_at_pulloff: NDArray | float
    mechanism: NDArray | str
    F_zero_width_over_Eh: NDArray | float
    F_minimum_over_Eh: NDArray | float
    a_over_R_at_minimum: NDArray | float
    R_over_h: NDArray | float
    sigma0_over_E: NDArray | float
    kappa: NDArray | float
    maugis_parameter: NDArray | float


def _pulloff_arrays(rho: NDArray, s: NDArray, scalar: bool = False):
    """:func:`_pulloff_flat` at arrays of any shape, or at NumPy scalars (``scalar``)."""
    if scalar:
        return _pulloff_flat(*_ref._scalars(rho, s))
    shape = np.shape(rho)
    rho = np.atleast_1d(rho).astype(float).reshape(-1)
    s = np.atleast_1d(s).astype(float).reshape(-1)
    d = _pulloff_flat(rho, s)
    return {k: np.reshape(v, shape) for k, v in d.items()}


def _pulloff_flat(rho: NDArray, s: NDArray):
    """Pull-off at flat arrays or NumPy scalars (elementwise; see reference._where)."""
    where = _ref._where
    kap = _ref._kappa(rho, s)
    F0 = _ref._zero_width(rho, s)
    us = _ustar(kap)
    fin = np.isfinite(us)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore", under="ignore"):
        uf = where(fin, us, 1.0)  # kappa = 0: no interior minimum (any finite u will do)
        bp = _ref._branch_point(uf, kap)
        sq = np.sqrt(2 / rho)
        A_min = where(fin, bp["abar"] * sq, 0.0)
        C_min = where(fin, bp["X"] * bp["Ct"] * sq, 0.0)
        F_min = where(fin, _ref._minimum((np.pi / 2) * bp["phi"], F0), F0)
        # the load minimum along the branch in units of Phi = (2/pi) F/(Eh) (contact_for_load)
        phi_min = where(fin, _ref._minimum(bp["phi"], F0 * (2 / np.pi)), F0 * (2 / np.pi))
    zero_c = sq * 2 / (kap * _ref.LN2 + np.sqrt(kap * kap * _ref.LN2**2 + 4))
    # the pull-off force is the minimum of the load, at the width of u* (however small: the
    # stability of every state is judged against it); the label says whether the contact
    # lets go from a width the continuum model resolves (at least the range h) or peels
    # below it
    snap = (F_min < F0) & (
        (A_min >= SNAP_OFF_MIN_WIDTH_OVER_H / rho) | (F0 - F_min > ZERO_WIDTH_LOAD_RTOL * abs(F0))
    )
    return dict(
        F_pulloff_over_Eh=F_min,
        a_over_R_at_pulloff=A_min,
        c_over_R_at_pulloff=where(A_min > 0, C_min, zero_c),
        mechanism=where(snap, "snap-off", "zero-width"),
        F_zero_width_over_Eh=F0,
        F_minimum_over_Eh=F_min,
        a_over_R_at_minimum=A_min,
        kappa=kap,
        us=us,
        phi_min=phi_min,
    )


def _check_law(law: object, where: str, instead: str | None = None, stacklevel: int = 3) -> None:
    """The deprecated ``law=`` of ``where``: a law is a module (:mod:`linecontact.laws`).

    ``"dugdale"`` (the default) is accepted silently; ``"lennard-jones"`` gives a
    ``DeprecationWarning`` naming ``instead`` (default
    ``linecontact.laws.lennard_jones.<where>``); any other value is a ``ValueError``.
    ``stacklevel`` 3 points at the caller of a public function that calls this one.
    """
    if law not in ("dugdale", "lennard-jones"):
        raise ValueError(f"law must be 'dugdale' or 'lennard-jones', got {law!r}")
    if law == "lennard-jones":
        instead = instead or f"linecontact.laws.lennard_jones.{where}"
        warnings.warn(
            f"{where}(law='lennard-jones') is deprecated: use {instead} (a law is a module, "
            "linecontact.laws)",
            DeprecationWarning,
            stacklevel=stacklevel,
        )


def pull_off(R_over_h: ArrayLike, sigma0_over_E: ArrayLike, *, law: str = "dugdale") -> Any:
    r"""Pull-off force under load control, vectorised over parameter points.

    The load along the contact branch has exactly one stationary point, a minimum, for every
    :math:`\sigma_0 > 0` (``docs/derivations.md``); it is found as the root of a monotone
    function of :math:`u = \operatorname{arccosh}(c/a)`, so no grid can miss it. The
    pull-off force is that minimum. The mechanism is ``"snap-off"`` when the contact
    half-width there is at least the range ``h`` of the adhesive stress
    (:data:`SNAP_OFF_MIN_WIDTH_OVER_H`) or the force more than 1 % below Eq. (14)
    (:data:`ZERO_WIDTH_LOAD_RTOL`), ``"zero-width"`` otherwise: the contact then peels
    below the range of the surface forces and lets go at a load within 1 % of Eq. (14)
    (at most 2e-3 of it for ``R/h >= 100``, 2e-5 for ``R/h >= 1e4``; see
    ``docs/derivations.md``). The pull-off state is the minimum in either case, and it is
    the one the load curve marks (:func:`load_curve`, ``linecontact curve``).

    Parameters
    ----------
    R_over_h : array_like
        ``> 0``.
    sigma0_over_E : array_like
        ``>= 0`` (0: Hertz, pull-off force 0 at zero width).
    law : {"dugdale", "lennard-jones"}
        Deprecated for ``"lennard-jones"`` (a ``DeprecationWarning``): use
        :func:`linecontact.laws.lennard_jones.pull_off`. The Dugdale step (default; also
        accepted explicitly, silently), or the Lennard-Jones law of Eq. (1) with the same work
        of adhesion ``sigma0 h`` and peak tension ``sigma0``, solved self-consistently
        (:mod:`linecontact.lennard_jones`; ``sigma0_over_E > 0``, and ``mu = 0.974^(3/2)
        (sigma0/E) sqrt(R/h)`` within ``domain.DOMAIN["lj_mu"]``).

    Returns
    -------
    PullOff or linecontact.lennard_jones.LennardJonesPullOff

    Examples
    --------
    >>> po = pull_off(100.0, 0.01)       # peels to a width far below h, at Eq. (14)
    >>> po.mechanism, po.a_over_R_at_pulloff < 1e-3 / 100
    ('zero-width', True)
    >>> abs(po.F_pulloff_over_Eh / po.F_zero_width_over_Eh - 1) < 1e-8
    True
    >>> po = pull_off(100.0, 0.2)        # lets go at a/R = 0.087, far above h/R = 0.01
    >>> po.mechanism, round(po.a_over_R_at_pulloff, 4)
    ('snap-off', 0.0869)
    """
    _check_law(law, "pull_off")
    rho = _domain.check("R_over_h", R_over_h)
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    scalar = scalar_or_array(rho, s)
    rho, s = broadcast(R_over_h=rho, sigma0_over_E=s)
    if law == "lennard-jones":
        from .lennard_jones import pull_off_in_dugdale_groups

        return pull_off_in_dugdale_groups(
            rho.reshape(()) if scalar else rho, s.reshape(()) if scalar else s
        )
    _ref._check_kappa(rho, s)
    d = _pulloff_arrays(rho, s, scalar)
    del d["us"], d["phi_min"]
    lam = _ref._maugis_parameter(rho, s)
    vals = {k: as_output(v if scalar else np.asarray(v), scalar) for k, v in d.items()}
    return PullOff(
        R_over_h=as_output(rho, scalar),
        sigma0_over_E=as_output(s, scalar),
        maugis_parameter=as_output(lam, scalar),
        **vals,
    )


def _z_of_u(u):
    """The variable of the load iteration: ``u`` from ``u = 1`` on, ``1 + ln u`` below.

    The load is nearly linear in ``ln u`` near full contact (``Phi ~ u^-3``) and its distance
    from its limit nearly exponential in ``u`` towards zero width (``~ e^{-2u}``): in ``z``
    and on the logarithms of :func:`_load_step` Newton's method sees nearly straight lines.
    """
    return _ref._where(u >= 1.0, u, 1.0 + np.log(u))


def _u_of_z(z):
    return _ref._where(z >= 1.0, z, np.exp(z - 1.0))


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
    bp = _ref._branch_point(u, kap)
    phi = bp["phi"]
    dphi = bp["dphi"] * _ref._where(z >= 1.0, 1.0, u)  # dPhi/dz
    d = phi - pmin if stable else p0 - phi
    g = np.log(d) - lt
    dg = (dphi if stable else -dphi) / d
    up = g > 0
    lo = _ref._where(up, z, lo)
    hi = _ref._where(up, hi, z)
    dn = g / dg
    zn = z - dn
    zmax = _ref._maximum(abs(z), 1.0)
    at_noise = abs(phi - target) <= 1e-15 * (
        bp["abar"] * bp["abar"] + abs(kap * bp["X"] * bp["St"])
    )
    conv = at_noise | (g == 0) | (abs(dn) <= 1e-15 * zmax)
    zn = _ref._where(at_noise, z, zn)
    ok = conv | ((abs(zn) < np.inf) & (zn > lo) & (zn < hi) & (abs(dn) <= 0.5 * abs(dz_prev)))
    zn = _ref._where(ok, zn, 0.5 * (lo + hi))
    stop = conv | (hi - lo <= 1e-15 * zmax)
    return (zn, lo, hi, zn - z), stop


def _solve_u_for_phi(target, kap, pmin, p0, us, stable: bool):
    """The u on one monotone piece of the branch where Phi(u) = target (flat or scalars).

    Stable: ``u`` in ``[1e-12, us]`` (``745`` for ``kappa = 0``), unstable: ``[us, 745]``.
    """
    where = _ref._where
    with np.errstate(over="ignore", invalid="ignore", divide="ignore", under="ignore"):
        fin = abs(us) < np.inf
        if stable:
            lo = _ref._full(target, _z_of_u(1e-12))
            hi = _z_of_u(where(fin, us, 745.0))
            lt = np.log(_ref._maximum(target - pmin, 0.0))
            # start from the Hertz-like width of the load (at the pull-off load: its end)
            z0 = _z_of_u(_ref._u_guess(np.sqrt(_ref._maximum(target, 0.0) + 1.0), kap))
            z0 = where(target <= pmin, hi, _ref._minimum(_ref._maximum(z0, lo), hi))
        else:
            lo = _z_of_u(us)
            hi = _ref._full(target, 745.0)
            lt = np.log(_ref._maximum(p0 - target, 0.0))
            z0 = _ref._minimum(lo + 1.0, 0.5 * (lo + hi))
        (z, _, _, _), _ = _ref._iterate(
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
    on_failure: FailurePolicy = RAISE,
    law: str = "dugdale",
    **deprecated: Any,
) -> Any:
    r"""The contact state(s) carrying a given load (closed form).

    Parameters
    ----------
    F_over_Eh : array_like
        Load over ``E h`` (compressive positive).
    R_over_h, sigma0_over_E : array_like
        As in :func:`normal_contact`.
    branch : {"stable", "unstable"}
        ``"stable"``: the state with ``dF/da > 0`` (exists for ``F >= F_pulloff``);
        ``"unstable"``: the narrower state with ``dF/da < 0`` (exists only between the load
        minimum and Eq. 14).
    on_failure : {"raise", "report"}
        For a load that no contact of the branch carries: raise (``"raise"``, default), or
        report the point with ``state == "no-equilibrium"``, NaN widths (the load kept),
        ``converged`` and ``stable`` False (``"report"``; the other points are solved as
        usual); README, "Conventions". Replaces the deprecated ``on_no_equilibrium``.
    law : {"dugdale", "lennard-jones"}
        Deprecated for ``"lennard-jones"`` (a ``DeprecationWarning``): use
        :func:`linecontact.laws.lennard_jones.contact_for_load`. The Dugdale step (default;
        also accepted explicitly, silently), or the Lennard-Jones law of Eq. (1) with the same
        work of adhesion and peak tension, solved self-consistently
        (:mod:`linecontact.lennard_jones_groups`; ``sigma0_over_E > 0``, ``mu`` within its
        domain as in :func:`pull_off`, loads up to
        :data:`~linecontact.lennard_jones_groups.LJ_LOAD_MAX` ``w sqrt(R/z0)``, the stable
        branch only). Each point costs a continuation of the curve: seconds at ``mu <= 0.3``,
        minutes at ``mu = 3``.

    Returns
    -------
    NormalContact or linecontact.lennard_jones_groups.LennardJonesContact
        ``F_over_Eh`` is the load asked for (the state carries it to within
        ``error_estimate``, relative to the larger of the load, Eq. 14 and the Hertz term;
        under the Lennard-Jones law its discretisation error is ``error_estimate_over_Eh``);
        ``state`` is ``"contact"``, or ``"no-equilibrium"`` for the points reported.

    Raises
    ------
    NoEquilibriumError
        If no contact of the requested branch carries the load, naming the pull-off force.
    """
    _check_law(law, "contact_for_load")
    F = _domain.check("F_over_Eh", F_over_Eh)
    rho = _domain.check("R_over_h", R_over_h)
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    if branch not in ("stable", "unstable"):
        raise ValueError(f"branch must be 'stable' or 'unstable', got {branch!r}")
    policy = failure_policy(
        on_failure, where="contact_for_load", accepts=("on_no_equilibrium",), **deprecated
    )
    if law == "lennard-jones":
        if branch != "stable":
            raise ValueError(
                "branch='unstable' applies to law='dugdale': under the Lennard-Jones law the "
                "contact for a load is the stable state beyond the pull-off"
            )
        from .lennard_jones_groups import contact_for_load_in_dugdale_groups

        scalar = scalar_or_array(F, rho, s)
        F, rho, s = broadcast(F_over_Eh=F, R_over_h=rho, sigma0_over_E=s)
        return contact_for_load_in_dugdale_groups(F, rho, s, scalar=scalar, on_failure=policy)
    report = policy == "report"
    scalar = scalar_or_array(F, rho, s)
    F, rho, s = (
        np.asarray(v, float) for v in broadcast(F_over_Eh=F, R_over_h=rho, sigma0_over_E=s)
    )
    _ref._check_kappa(rho, s)
    d = _pulloff_arrays(rho, s, scalar)
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
    Fs, rs = _ref._scalars(F, rho) if scalar else (F.reshape(-1), rho.reshape(-1))
    flat = (lambda v: np.float64(v)) if scalar else (lambda v: np.reshape(v, -1))
    u = _solve_u_for_phi(
        Fs * (2 / np.pi),
        flat(kap),
        flat(d["phi_min"]),
        flat(F0) * (2 / np.pi),
        flat(us_solve),
        stable=branch == "stable",
    )
    with np.errstate(over="ignore", invalid="ignore", divide="ignore", under="ignore"):
        A, C, Fc, stable = _closed_form_from_u(u, flat(kap), rs, flat(us))
    if not scalar:
        A, C, Fc, stable = (v.reshape(F.shape) for v in (A, C, Fc, stable))
    Fv, rv = (Fs, rs) if scalar else (F, rho)
    scale = _ref._maximum(_ref._maximum(abs(Fv), abs(F0)), np.pi / 4 * A * A * rv)
    res = abs(Fc - Fv) / _ref._maximum(scale, 1e-300)
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
    _ref._warn_wide(np.where(bad, np.nan, A))
    z: NDArray | float = 0.0 if scalar else np.zeros(F.shape)
    nan = np.where(bad, np.nan, 1.0)
    vals = dict(
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
    vals = {k: as_output(v if scalar else np.asarray(v), scalar) for k, v in vals.items()}
    return NormalContact(method="closed-form", **vals)


@dataclass(frozen=True)
class NonContact(Result):
    """Equilibrium without contact: the adhesive zone ``|x| < c`` only, central gap ``g0``.

    Attributes
    ----------
    central_gap_over_h : ndarray or float
        ``g0/h`` in ``[0, 1]``.
    c_over_R : ndarray or float
        Half-width of the adhesive zone.
    F_over_Eh : ndarray or float
        ``-2 sigma0 c / (E h)``; Eq. (14) at ``g0 = 0``.
    stable : ndarray or bool
        Always False: unstable under load control (stable under displacement control).
    """

    inputs: ClassVar[tuple[str, ...]] = ("R_over_h", "sigma0_over_E")

    central_gap_over_h: NDArray | float
    c_over_R: NDArray | float
    F_over_Eh: NDArray | float
    R_over_h: NDArray | float
    sigma0_over_E: NDArray | float
    stable: NDArray | bool


def non_contact(
    central_gap_over_h: ArrayLike, R_over_h: ArrayLike, sigma0_over_E: ArrayLike
) -> NonContact:
    r"""The non-contact branch: attractive force versus the central gap ``g0`` in ``[0, h]``.

    With a uniform tensile stress on :math:`|x| < c` the gap rises from ``g0`` at the centre
    to ``h`` at ``c``: :math:`h - g_0 = c^2/(2R) + 4\ln 2\,\sigma_0 c/(\pi E)`, and
    :math:`F = -2\sigma_0 c`. At ``g0 = 0`` this is Eq. (14).
    """
    g = check_array(
        "central_gap_over_h",
        central_gap_over_h,
        low=0.0,
        low_inclusive=True,
        high=1.0,
        high_inclusive=True,
    )
    rho = _domain.check("R_over_h", R_over_h)
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    scalar = scalar_or_array(g, rho, s)
    g, rho, s = (
        np.asarray(v, float) for v in broadcast(central_gap_over_h=g, R_over_h=rho, sigma0_over_E=s)
    )
    k = 4 * _ref.LN2 * s / np.pi
    rhs = 2 * (1 - g) / rho
    # the root of C^2 + 2 k C = rhs without overflow of k^2; C = 0 at g0 = h (also 0/0 at s = 0)
    den = k + np.hypot(k, np.sqrt(rhs))
    C = rhs / np.where(rhs > 0, den, 1.0)
    F = -2 * s * rho * C
    vals = dict(
        central_gap_over_h=g,
        c_over_R=C,
        F_over_Eh=F,
        R_over_h=rho,
        sigma0_over_E=s,
        stable=np.zeros(g.shape, bool),
    )
    return NonContact(**{k_: as_output(v, scalar) for k_, v in vals.items()})


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
    """Every equilibrium state carrying the load ``F_over_Eh`` (scalar parameters).

    Stable contact (``F >= F_pulloff``), unstable narrow contact (between the load minimum and
    Eq. 14), and the non-contact state (between Eq. 14 and 0). Empty below the pull-off
    force; the caller says so. A contact has a positive width: at the zero-width load
    (Eq. 14, within round-off) the narrow end of the contact branch is the touch-down
    state, listed once, as the non-contact state (``a = 0``, gap 0).
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
        k = 4 * _ref.LN2 * s / np.pi
        g = 1 - rho * (C * C / 2 + k * C)
        states.append(Equilibrium("non-contact", False, F, 0.0, C, float(np.clip(g, 0, 1))))
    return tuple(states)


#: The most points :func:`load_curve` samples on either branch.
NUM_MAX = 10**7


@dataclass(frozen=True)
class LoadCurve(Result):
    """The whole load curve: non-contact branch then the contact branch.

    Arrays are ordered from the largest central gap (``g0 = h``, ``F = 0``) through
    touch-down (``a = 0``, Eq. 14) to the largest contact width.

    Attributes
    ----------
    branch : ndarray of str
        ``"non-contact"`` or ``"contact"``.
    central_gap_over_h, a_over_R, c_over_R, F_over_Eh : ndarray
        The states (``a = 0`` off contact, ``g0 = 0`` in contact).
    stable : ndarray of bool
        Stability under load control.
    turning_point : ndarray of bool
        Marks the load minimum (the single turning point of the contact branch).
    pulloff : PullOff
        The pull-off result.
    """

    inputs: ClassVar[tuple[str, ...]] = ("R_over_h", "sigma0_over_E")

    branch: NDArray
    central_gap_over_h: NDArray
    a_over_R: NDArray
    c_over_R: NDArray
    F_over_Eh: NDArray
    stable: NDArray
    turning_point: NDArray
    R_over_h: float
    sigma0_over_E: float
    pulloff: PullOff = field(repr=False)


def load_curve(
    R_over_h: float,
    sigma0_over_E: float,
    *,
    a_max_over_R: float | None = None,
    num: int = 200,
    num_noncontact: int = 40,
    law: str = "dugdale",
    F_max_over_Eh: float | None = None,
) -> Any:
    """Sample the load curve (scalar parameters), pull-off and turning point included.

    Parameters
    ----------
    R_over_h, sigma0_over_E : float
        Parameters (scalars).
    a_max_over_R : float, optional
        Largest contact half-width; default: three times the width at pull-off, at least
        the Hertz width at ``F = 10 |F_pulloff|`` and at least ``0.02``, but at most the
        small-strain limit :data:`~linecontact.reference.A_OVER_R_SMALL_STRAIN` (or 1.5
        times the width at pull-off, if that is larger), and never beyond ``a/R = 10``, the
        end of the domain (where the pull-off is wider still, the curve stops short of it).
    num, num_noncontact : int
        Points on the contact and the non-contact branches, each in ``[2, NUM_MAX]``
        (``NUM_MAX = 10**7``: a few hundred MB of samples; more is refused up front rather
        than failing in NumPy's allocator).
    law : {"dugdale", "lennard-jones"}
        Deprecated for ``"lennard-jones"`` (a ``DeprecationWarning``): use
        :func:`linecontact.laws.lennard_jones.load_curve`. The Dugdale step (default; also
        accepted explicitly, silently), or the Lennard-Jones law of Eq. (1) with the same work
        of adhesion and peak tension (as in :func:`pull_off`): the states of the solver's
        continuation in the central gap, from far away through the pull-off to
        ``F_max_over_Eh`` (``a_max_over_R``, ``num`` and ``num_noncontact`` are the Dugdale
        law's; seconds at ``mu <= 0.3``, minutes at ``mu = 3``).
    F_max_over_Eh : float, optional
        Under the Lennard-Jones law, the compressive load where the curve ends (default:
        7.5 ``w sqrt(R/z0)``, three times the rigid cylinder's pull-off).

    Returns
    -------
    LoadCurve or linecontact.lennard_jones_groups.LennardJonesLoadCurve
    """
    _check_law(law, "load_curve")
    rho = _domain.scalar("R_over_h", R_over_h)
    s = _domain.scalar("sigma0_over_E", sigma0_over_E)
    if law == "lennard-jones":
        if a_max_over_R is not None or num != 200 or num_noncontact != 40:
            raise ValueError(
                "a_max_over_R, num and num_noncontact apply to law='dugdale': the "
                "Lennard-Jones curve has the states of its continuation; give F_max_over_Eh "
                "for its end"
            )
        from .lennard_jones_groups import load_curve_in_dugdale_groups

        return load_curve_in_dugdale_groups(rho, s, F_max_over_Eh)
    if F_max_over_Eh is not None:
        raise ValueError(
            "F_max_over_Eh applies to law='lennard-jones': the Dugdale curve ends at a_max_over_R"
        )
    for name, v in (("num", num), ("num_noncontact", num_noncontact)):
        if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or not 2 <= v <= NUM_MAX:
            raise ValueError(f"{name} must be an integer in [2, {NUM_MAX}], got {v!r}")
    po = pull_off(rho, s)
    if a_max_over_R is None:
        a_po = float(po.a_over_R_at_minimum)
        a_h = float(np.sqrt(4 * 10 * abs(float(po.F_pulloff_over_Eh)) / (np.pi * rho)))
        # within the small-strain range unless the pull-off itself is close to its end
        # and never beyond the domain of the solvers (a pull-off wider than that is cut off)
        cap = min(max(_ref.A_OVER_R_SMALL_STRAIN, 1.5 * a_po), _domain.DOMAIN["a_over_R"][2])
        a_max_over_R = min(max(3 * a_po, a_h, 0.02), cap)
    amax = _domain.scalar("a_max_over_R", a_max_over_R)
    A = np.unique(
        np.concatenate(
            [
                np.geomspace(amax * 1e-4, amax, num // 2),
                np.linspace(amax / num, amax, num - num // 2),
            ]
        )
    )
    # the minimum is a point of the curve (unless narrower than the domain: for small kappa
    # it sits at widths like 1e-152 R, its load within round-off of the zero-width load)
    at_min = _domain.DOMAIN["a_over_R"][0] <= po.a_over_R_at_minimum < amax
    if at_min:
        A = np.unique(np.append(A, po.a_over_R_at_minimum))
    nc = normal_contact(A, rho, s)
    parts_branch = []
    gaps = np.linspace(1.0, 0.0, num_noncontact) if s > 0 else np.array([])
    if gaps.size:
        ncb = non_contact(gaps, rho, s)
        parts_branch = ["non-contact"] * gaps.size
        g_nc, c_nc, F_nc = ncb.central_gap_over_h, ncb.c_over_R, ncb.F_over_Eh
    else:
        g_nc = c_nc = F_nc = np.array([])
    branch = np.array(parts_branch + ["contact"] * A.size)
    gap = np.concatenate([g_nc, np.zeros(A.size)])
    a = np.concatenate([np.zeros(gaps.size), A])
    c = np.concatenate([c_nc, nc.c_over_R])
    F = np.concatenate([F_nc, nc.F_over_Eh])
    stable = np.concatenate([np.zeros(gaps.size, bool), nc.stable])
    turning = np.zeros(a.size, bool)
    if at_min:
        turning[gaps.size + int(np.argmin(np.abs(A - po.a_over_R_at_minimum)))] = True
    return LoadCurve(branch, gap, a, c, F, stable, turning, rho, s, po)
