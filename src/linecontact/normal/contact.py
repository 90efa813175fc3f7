r"""Normal contact at given contact half-widths (paper Eqs. 5--13): :func:`normal_contact`.

Both solvers of :class:`NormalContact`: the Maugis--Dugdale closed form (Baney & Hui 1997;
Johnson & Greenwood 2008, one scalar root per point) and the paper's Gauss--Chebyshev
collocation of Eq. 9 with the separation condition (Eq. 11) and equilibrium (Eq. 12); the
stability test under load control, and the closed form in ``u = arccosh(c/a)`` and the ``u``
of the load minimum that the pull-off and the inverse solve on.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _numerics as _num
from .. import closed_forms as _cf
from .. import domain as _domain
from .._docs import shared_docs
from .._validation import (
    FailurePolicy,
    broadcast,
    check_solver_options,
    failure_policy,
    first_point,
    point_text,
    positions,
    scalar_or_array,
)
from ..errors import ConvergenceError
from ..results import SI, Result, as_output
from ..sie import SIZES, BoundedSolver, _chunks, _in_chunks, log_end_moments

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
        :math:`dF/da > 0`: the state is stable under load control.
    state : ndarray of str or str
        ``"contact"``; ``"no-equilibrium"`` for a load no contact carries, reported by
        :func:`contact_for_load` with ``on_failure="report"`` (its values are NaN).
    """

    inputs: ClassVar[tuple[str, ...]] = ("R_over_h", "sigma0_over_E", "method")
    derived: ClassVar[tuple[str, ...]] = ("c_over_a",)

    a_over_R: NDArray | float = field(metadata=SI("contact_half_width", "R", "m"))
    c_over_R: NDArray | float = field(metadata=SI("adhesive_zone_half_width", "R", "m"))
    F_over_Eh: NDArray | float = field(metadata=SI("load", "Eh", "N/m"))
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
        r"""Adhesive-zone to contact half-width ratio :math:`c/a` (:math:`\ge 1`)."""
        return np.asarray(self.c_over_R) / np.asarray(self.a_over_R)

    def pressure(self, x_over_R: ArrayLike) -> NDArray:
        r"""Contact pressure :math:`p/E` (compressive positive) at :math:`x/R`.

        ``x_over_R`` has shape ``(m,)`` (or broadcasts against the points plus one trailing
        axis); the result has shape ``points.shape + (m,)``. Inside the contact it is the
        solution of the method used; :math:`-\sigma_0/E` in the adhesive zones; zero beyond.
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


def _closed_form_from_u(u, kap, rho, ustar):
    bp = _cf._branch_point(u, kap)
    sq = np.sqrt(2 / rho)
    A = bp["abar"] * sq
    C = np.maximum(bp["X"] * bp["Ct"] * sq, A)  # c >= a despite rounding
    F = (np.pi / 2) * bp["phi"]
    stable = u <= ustar
    return A, C, F, stable


def _stable(u, kap, bp):
    r"""Stable under load control: wider than the load minimum, :math:`u \le u^*` (one definition).

    :math:`dF/da > 0` decides where its sign is clear; where the derivative is lost in
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

    Arrays or NumPy scalars (the scalar fast path, see :func:`linecontact._numerics._where`).
    """
    if np.ndim(kap) == 0:
        return _cf._u_stationary(kap) if kap > 0 else np.float64(np.inf)
    kap = np.asarray(kap, dtype=float)
    us = np.full(kap.shape, np.inf)
    pos = kap > 0
    if pos.any():
        us[pos] = _cf._u_stationary(kap[pos])
    return us


def _closed_form(A, rho, s):
    """u, c/R, F/(Eh), separation residual, stability: flat arrays or NumPy scalars.

    Called inside the ``np.errstate`` of :func:`normal_contact` (see ``_cf._solve_abar``).
    """
    kap = _cf._kappa(rho, s)
    abar = A * np.sqrt(rho / 2)
    u, res, _, bp = _cf._solve_abar(abar, kap)
    # c >= a exactly (coth u >= 1), which the product's rounding can miss by an ulp or two
    C = np.maximum(bp["X"] * bp["Ct"] * np.sqrt(2 / rho), A)
    F = (np.pi / 2) * bp["phi"]
    return u, C, F, res, _stable(u, kap, bp)


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
    """:math:`dF/da > 0` at ``u`` on the branch, over chunks of points (bounded memory)."""
    shape = np.shape(u)
    u = np.reshape(u, -1)
    kap = np.broadcast_to(kap, shape).reshape(-1)
    out = np.empty(u.size, bool)
    for c in _chunks(u.size, 0):
        out[c] = _stable(u[c], kap[c], _cf._branch_point(u[c], kap[c]))
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
    if n == "auto":  # the log source at x = c sets the size (_numerics._auto_sizes)

        def solve(nn, idx):
            ui, ci, (Ri, ri, co, ti) = _newton_u_chunked(nn, A[idx], s[idx], rho[idx], u[idx])
            u[idx], conv[idx], Rv[idx], res_[idx], cons[idx], tail[idx] = ui, ci, Ri, ri, co, ti

        nsel = _num._auto_sizes(sizes, u, tail, tol, nsel, solve)
    F = rho * A * (res_ - 2 * np.cosh(u) * s)
    C = A * np.cosh(u)
    converged = conv & (tail <= 10 * tol) & np.isfinite(F)
    out = dict(
        u=u, C=C, F=F, res=np.abs(Rv), cons=np.abs(cons), tail=tail, n=nsel, converged=converged
    )
    return {k: v.reshape(shape) for k, v in out.items()}


@shared_docs
def normal_contact(
    a_over_R: ArrayLike,
    R_over_h: ArrayLike,
    sigma0_over_E: ArrayLike,
    *,
    method: str = "closed-form",
    n: int | str = "auto",
    tol: float = 1e-12,
    on_failure: FailurePolicy = "raise",
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
        :math:`\kappa = (4/\pi) (\sigma_0/E) \sqrt{2 R/h}` at most
        :data:`~linecontact.closed_forms.KAPPA_MAX` (1e12) here and in every normal and sliding
        solver.
    method : {"closed-form", "collocation"}
        Solver (see the module docstring).
    %(COLLOCATION)s

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
    policy = failure_policy(on_failure)
    scalar = scalar_or_array(A, rho, s)
    A, rho, s = broadcast(a_over_R=A, R_over_h=rho, sigma0_over_E=s)
    _cf._check_kappa(rho, s)
    _cf._warn_wide(A)
    # a contact half-width far outside the solvers' range (a/R ~ 1e-200 or 1e20) overflows
    # on the way; the residual and finiteness checks below turn that into non-convergence
    with np.errstate(over="ignore", invalid="ignore", divide="ignore", under="ignore"):
        if method == "closed-form":
            ncol: NDArray | int
            cons: NDArray | float
            err: NDArray | float
            if scalar:  # the same kernels on NumPy scalars (see _numerics._where)
                u, C, F, res, stable = _closed_form(*_num._scalars(A, rho, s))
                ncol, cons, err = 0, 0.0, 0.0
            else:
                shape = A.shape
                flat = (np.reshape(v, -1) for v in (A, rho, s))
                # in chunks of points: bounded memory for any number of them
                u, C, F, res, stable = (
                    v.reshape(shape) for v in _in_chunks(_closed_form, A.size, *flat)
                )
                ncol = np.zeros(shape, dtype=int)
                cons = np.zeros(shape)
                err = np.zeros(shape)
            converged = (res < 1e-12) & (abs(C) < np.inf) & (abs(F) < np.inf)  # isfinite
        else:
            kap = _cf._kappa(rho, s)
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
