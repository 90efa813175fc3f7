r"""Steady sliding at given contact half-widths (:func:`sliding_contact`), both solvers.

:class:`SlidingContact`, the stability test under load control and the assembly of a result
from the solvers of :mod:`~linecontact.sliding.closed_form` and
:mod:`~linecontact.sliding.collocation`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import _numerics as _num
from .. import closed_forms as _cf
from .. import domain as _domain
from .._docs import shared_docs
from .._validation import (
    FailurePolicy,
    first_point,
    point_text,
    positions,
)
from ..errors import ConvergenceError
from ..results import SI, Result, as_output
from ..sie import BoundedSolution, BoundedSolver, _in_chunks
from ._checks import _broadcast_state, _check_state_inputs, _flat_points
from .closed_form import _cf_coefficients, _cf_outputs, _closed_form
from .collocation import _SIZES, _collocation
from .pulloff import _pulloff_flat


@dataclass(frozen=True)
class SlidingContact(Result):
    """Steady sliding at given contact half-widths (or loads).

    Attributes
    ----------
    a_over_R : ndarray or float
        Contact half-width :math:`a/R`.
    c1_over_R, c2_over_R : ndarray or float
        Ends of the trailing (:math:`-c_1 < x < -a`) and leading (:math:`a < x < c_2`) adhesive
        zones, measured from the contact centre, over ``R``.
    e_over_R : ndarray or float
        Eccentricity: position of the cylinder's apex (axis) relative to the contact centre,
        along the sliding direction, over ``R``.
    F_over_Eh2 : ndarray or float
        Load per unit length over ``E h2`` (compressive positive).
    M_over_Eh2R : ndarray or float
        Moment about the contact centre per unit length over ``E h2 R``, clockwise positive
        (see the module docstring): ``int x p dx``.
    M_axis_over_Eh2R : ndarray or float
        The same about the cylinder's axis, ``M - e F``.
    R_over_h2, h1_over_h2, sigma0_over_E : ndarray or float
        The parameters, broadcast.
    tau0_over_E : ndarray or float
        Shear (friction) stress over ``E`` if given, else nan.
    T_over_Eh2 : ndarray or float
        Friction force per unit length ``2 a tau0`` over ``E h2`` if ``tau0`` was given,
        else nan.
    method : str
        ``"collocation"`` or ``"closed-form"``.
    n_collocation : ndarray or int
        Collocation nodes used at each point (0 for the closed form).
    residual_trailing, residual_leading : ndarray or float
        Residuals of the separation conditions: gap at ``-c1`` minus ``h1`` over ``h1``, gap
        at ``c2`` minus ``h2`` over ``h2`` (Eqs. 22, 21), up to sign.
    residual_consistency : ndarray or float
        Residual of the consistency condition after the eccentricity was fixed by it.
    error_estimate : ndarray or float
        Chebyshev tail of the collocation solution over its largest coefficient (0 for the
        closed form).
    converged : ndarray or bool
        All tolerances met.
    stable : ndarray or bool
        :math:`dF/da > 0`: stable under load control.
    state : ndarray of str or str
        ``"contact"``; ``"no-equilibrium"`` for a load below the pull-off force reported by
        :func:`sliding_contact_for_load` with ``on_failure="report"`` (values NaN).
    """

    inputs: ClassVar[tuple[str, ...]] = (
        "R_over_h2",
        "h1_over_h2",
        "sigma0_over_E",
        "tau0_over_E",
        "method",
    )

    a_over_R: NDArray | float = field(metadata=SI("contact_half_width", "R", "m"))
    c1_over_R: NDArray | float = field(metadata=SI("trailing_zone_end", "R", "m"))
    c2_over_R: NDArray | float = field(metadata=SI("leading_zone_end", "R", "m"))
    e_over_R: NDArray | float = field(metadata=SI("eccentricity", "R", "m"))
    F_over_Eh2: NDArray | float = field(metadata=SI("load", "Eh", "N/m"))
    M_over_Eh2R: NDArray | float = field(metadata=SI("moment", "EhR", "N"))
    M_axis_over_Eh2R: NDArray | float = field(metadata=SI("moment_about_axis", "EhR", "N"))
    R_over_h2: NDArray | float
    h1_over_h2: NDArray | float
    sigma0_over_E: NDArray | float
    tau0_over_E: NDArray | float
    T_over_Eh2: NDArray | float = field(metadata=SI("friction_force", "Eh", "N/m"))
    method: str
    n_collocation: NDArray | int
    residual_trailing: NDArray | float
    residual_leading: NDArray | float
    residual_consistency: NDArray | float
    error_estimate: NDArray | float
    converged: NDArray | bool
    stable: NDArray | bool
    state: NDArray | str

    @property
    def c1_over_a(self):
        r""":math:`c_1/a` (:math:`\ge 1`)."""
        return np.asarray(self.c1_over_R) / np.asarray(self.a_over_R)

    @property
    def c2_over_a(self):
        r""":math:`c_2/a` (:math:`\ge 1`)."""
        return np.asarray(self.c2_over_R) / np.asarray(self.a_over_R)

    def friction_force(self, tau0_over_E: ArrayLike) -> NDArray | float:
        r"""Friction force per length, :math:`2 a \tau_0`, over :math:`E h_2` (``tau0/E >= 0``)."""
        t = _domain.check("tau0_over_E", tau0_over_E, "friction_tau0_over_E")
        val = 2 * np.asarray(self.a_over_R) * np.asarray(self.R_over_h2) * t
        return val.item() if np.ndim(val) == 0 else val

    def _coefficients(self, n: int | None = None):
        r"""Chebyshev-U coefficients of :math:`\bar p/E` on :math:`t = x/a` (closed form, cut).

        Returns (A, s, coefficients) flattened over the points.
        """
        A = np.atleast_1d(np.asarray(self.a_over_R, float)).reshape(-1)
        s = np.broadcast_to(np.asarray(self.sigma0_over_E, float), np.shape(self.a_over_R))
        s = np.atleast_1d(s).reshape(-1)
        u1 = np.arccosh(np.maximum(np.atleast_1d(self.c1_over_a).reshape(-1), 1.0))
        u2 = np.arccosh(np.maximum(np.atleast_1d(self.c2_over_a).reshape(-1), 1.0))
        if n is None:
            umin = max(float(np.min(np.minimum(u1, u2))), 1e-3)
            n = int(np.clip(np.ceil(40.0 / umin), 16, 4096))
        return A, s, _cf_coefficients(A, s, u1, u2, n)

    def pressure(self, x_over_R: ArrayLike) -> NDArray:
        r"""Contact pressure :math:`p/E` (compressive positive) at :math:`x/R`.

        ``x_over_R`` has shape ``(m,)``; the result has shape ``points.shape + (m,)``.
        Inside the contact: the closed-form bounded solution of Eq. (20) at the computed
        ``c1``, ``c2`` (the collocation solution is the same function to its tolerance);
        :math:`-\sigma_0/E` in the adhesive zones; zero beyond.
        """
        x = positions("x_over_R", x_over_R, np.shape(self.a_over_R))
        A = np.asarray(self.a_over_R, dtype=float)[..., None]
        C1 = np.asarray(self.c1_over_R, dtype=float)[..., None]
        C2 = np.asarray(self.c2_over_R, dtype=float)[..., None]
        s = np.asarray(self.sigma0_over_E, dtype=float)[..., None]
        q1 = np.exp(-np.arccosh(np.maximum(C1 / A, 1.0)))
        q2 = np.exp(-np.arccosh(np.maximum(C2 / A, 1.0)))
        t = np.clip(x / A, -1.0, 1.0)
        sn = np.sqrt(np.clip(1 - t * t, 0.0, None))
        inner = (
            0.5 * A * sn
            + (2 * s / np.pi) * (np.arctan2(q2 * sn, 1 - q2 * t) + np.arctan2(q1 * sn, 1 + q1 * t))
            - s
        )
        return np.where(np.abs(x) < A, inner, np.where((x >= -C1) & (x <= C2), -s, 0.0))

    def gap(self, x_over_R: ArrayLike) -> NDArray:
        r"""The gap between the surfaces over :math:`h_2` at :math:`x/R` (zero in the contact).

        Outside the contact
        :math:`g(x) = \frac{(x-e)^2-(x_0-e)^2}{2R} - \frac{2}{\pi E}\int p(\xi)
        \ln\left|\frac{x-\xi}{x_0-\xi}\right|d\xi` with :math:`x_0 = \pm a` the nearer contact
        edge; by the separation conditions it equals ``h1`` at ``-c1`` and ``h2`` at ``c2``.
        The pressure is the closed-form solution of Eq. (20) at the computed ``c1``, ``c2``
        (integrated by product integration). ``x_over_R`` has shape ``(m,)`` (or one row
        per point); the result has shape ``points.shape + (m,)``.
        """
        x = positions("x_over_R", x_over_R, np.shape(self.a_over_R))
        shape = np.shape(self.a_over_R)
        A, s, b = self._coefficients()
        n = b.shape[-1]
        C1 = np.atleast_1d(np.asarray(self.c1_over_R, float)).reshape(-1)
        C2 = np.atleast_1d(np.asarray(self.c2_over_R, float)).reshape(-1)
        ecc = np.atleast_1d(np.asarray(self.e_over_R, float)).reshape(-1)
        rho = np.broadcast_to(np.asarray(self.R_over_h2, float), shape)
        rho = np.atleast_1d(rho).reshape(-1)
        xs = np.broadcast_to(x, (A.size,) + x.shape[-1:])
        t = xs / A[:, None]
        x0 = np.where(t >= 0, 1.0, -1.0)
        solver = BoundedSolver(n)
        sol = BoundedSolution(b[:, None, :], None, np.zeros((A.size, 1)))
        with np.errstate(divide="ignore", invalid="ignore"):
            lm = solver.log_moment(sol, np.where(np.abs(t) <= 1, x0, t)) - solver.log_moment(
                sol, x0
            )
        # int_{-c1}^{c2} ln|(x - xi)/(x0 - xi)| dxi for the constant -sigma0 (unit: a)
        m1 = (C1 / A)[:, None]
        m2 = (C2 / A)[:, None]
        strip = _log_strip(t, m1, m2) - _log_strip(x0, m1, m2)
        with np.errstate(over="ignore", invalid="ignore"):
            elastic = (2 / np.pi) * A[:, None] * (lm - s[:, None] * strip)  # over R
            geom = ((xs - ecc[:, None]) ** 2 - (x0 * A[:, None] - ecc[:, None]) ** 2) / 2
            g = rho[:, None] * (geom - elastic)
        g = np.where(np.abs(t) < 1, 0.0, g)
        if not np.all(np.isfinite(g)):
            i = np.unravel_index(int(np.flatnonzero(~np.isfinite(g))[0]), g.shape)
            raise ValueError(
                f"the gap is beyond the floating-point range at x_over_R={float(xs[i])!r}"
            )
        return g.reshape(shape + x.shape[-1:])


def _xlogx(x):
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(x > 0, x * np.log(np.where(x > 0, x, 1.0)), 0.0)


def _log_strip(y, m1, m2):
    """int_{-m1}^{m2} ln|y - t| dt."""
    return (
        _xlogx(np.abs(m2 - y)) * np.sign(m2 - y)
        + _xlogx(np.abs(y + m1)) * np.sign(y + m1)
        - (m1 + m2)
    )


def _stable(A, rho, r, s, u1, u2, dphi):
    """Stable under load control: :math:`dF/da > 0` where its sign is clear (one definition).

    Where the derivative is lost in round-off (near the load minimum, or at widths so small
    that the load is flat to the last digit, next to a zero-width minimum) the width is
    compared with that of the minimum (:func:`_pulloff_flat`), as :func:`sliding_pull_off`
    and :func:`sliding_contact_for_load` locate it: stable iff wider than an interior
    minimum, always next to a zero-width one. Flat arrays or NumPy scalars.
    """
    ab = A * np.sqrt(rho / 2)
    kap = _cf._kappa(rho, s)
    with np.errstate(over="ignore", invalid="ignore"):
        c1, c2 = np.cosh(u1), np.cosh(u2)
        scale = 2 * ab + kap * (c1 + c2) + kap * ab * (c1 + c2)
    clear = abs(dphi) > 1e-8 * scale
    if not isinstance(A, np.ndarray):
        if clear or not s > 0:
            return bool(dphi > 0)
        d = _pulloff_flat(kap, r)
        return bool(not d["interior"] or np.log(ab) >= d["lab_min"])
    out = np.asarray(dphi > 0)
    unclear = ~clear & (s > 0)
    if np.any(unclear):
        out = out.copy()
        d = _pulloff_flat(kap[unclear], r[unclear])
        out[unclear] = ~d["interior"] | (np.log(ab[unclear]) >= d["lab_min"])
    return out


def _solve_flat(A, rho, r, s, method, n, tol, u_guess=None):
    """Solve at flat arrays; returns a dict of flat arrays (both methods).

    The closed form also takes NumPy scalars (the scalar fast path of the public functions).
    """
    if method == "closed-form":
        g1, g2 = (None, None) if u_guess is None else u_guess
        u1, u2, e1, e2 = _closed_form(A, rho, r, s, g1, g2)
        ecc, F, M, dphi = _cf_outputs(A, rho, r, s, u1, u2)
        flat = isinstance(A, np.ndarray)
        z = np.zeros(A.shape) if flat else 0.0
        d = dict(
            u1=u1,
            u2=u2,
            ecc=ecc,
            F=F,
            M=M,
            res1=e1,
            res2=e2,
            cons=z,
            tail=z,
            n=np.zeros(A.shape, int) if flat else 0,
            converged=(_num._maximum(e1, e2) <= 1e-12) & (abs(F) < np.inf),
        )
    else:
        d = _collocation(A, rho, r, s, n, tol)
        _, _, _, dphi = _cf_outputs(A, rho, r, s, d["u1"], d["u2"])
    d["stable"] = _stable(A, rho, r, s, d["u1"], d["u2"], dphi)
    return d


def _solve_closed_form(A, rho, r, s, u1=None, u2=None):
    """:func:`_solve_flat` by the closed form, Newton started from ``u1, u2`` if given.

    A kernel for :func:`linecontact.sie._in_chunks` (flat arrays of the points, or NumPy
    scalars).
    """
    guess = None if u1 is None or u2 is None else (u1, u2)
    return _solve_flat(A, rho, r, s, "closed-form", "auto", 1e-12, u_guess=guess)


def _solve_split(A, rho, r, s, n, tol, closed, u_guess):
    """Collocation at flat arrays, but the closed form at the points ``closed``.

    The closed form's points keep ``n = 0`` (no collocation) in the result.
    """
    if not np.any(closed):
        return _solve_flat(A, rho, r, s, "collocation", n, tol)
    parts = []
    for mask, method in ((closed, "closed-form"), (~closed, "collocation")):
        idx = np.flatnonzero(mask)
        if idx.size:
            guess = (u_guess[0][idx], u_guess[1][idx]) if method == "closed-form" else None
            d = _solve_flat(A[idx], rho[idx], r[idx], s[idx], method, n, tol, u_guess=guess)
            parts.append((idx, d))
    out = {}
    for k in parts[0][1]:
        vals = [np.asarray(d[k]) for _, d in parts]
        arr = np.empty(A.shape, dtype=np.result_type(*vals))
        for (idx, _), v in zip(parts, vals, strict=True):
            arr[idx] = v
        out[k] = arr
    return out


def _pack(d, A, rho, r, s, tau, method, shape, scalar, policy, where, missing=None, F_asked=None):
    """Assemble the result; ``missing`` marks the points reported without a state.

    Their values are NaN but for the load ``F_asked`` that no contact carries.
    """
    missing = np.zeros(A.shape, bool) if missing is None else missing
    conv = d["converged"] | missing
    if policy == "raise" and not np.all(conv):
        # the inputs at the first failing point, after broadcasting (and the load asked for)
        asked = {} if F_asked is None else {"F_over_Eh2": F_asked}
        i, at = first_point(
            ~np.asarray(conv, bool),
            **asked,
            a_over_R=A,
            R_over_h2=rho,
            h1_over_h2=r,
            sigma0_over_E=s,
        )
        d = {k: np.reshape(v, -1) for k, v in d.items()}
        raise ConvergenceError(
            f"{where} ({method}) did not converge at {point_text(at)} (separation residuals "
            f"{d['res1'][i]:.3g}, {d['res2'][i]:.3g}, error estimate {d['tail'][i]:.3g}); an "
            f"adhesive zone is too thin for n <= {_SIZES[-1]} or the point is outside the "
            f"solver's range"
        )
    nan = np.where(missing, np.nan, 1.0)
    A = A * nan
    C1 = A * np.cosh(d["u1"])
    C2 = A * np.cosh(d["u2"])
    T = 2 * A * rho * tau
    vals = dict(
        a_over_R=A,
        c1_over_R=C1,
        c2_over_R=C2,
        e_over_R=d["ecc"] * nan,
        F_over_Eh2=d["F"] if F_asked is None else np.where(missing, F_asked, d["F"]),
        M_over_Eh2R=d["M"] * nan,
        M_axis_over_Eh2R=(d["M"] - d["ecc"] * d["F"]) * nan,
        R_over_h2=rho,
        h1_over_h2=r,
        sigma0_over_E=s,
        tau0_over_E=tau,
        T_over_Eh2=T,
        n_collocation=d["n"],
        residual_trailing=d["res1"],
        residual_leading=d["res2"],
        residual_consistency=d["cons"],
        error_estimate=d["tail"] * nan,
        converged=conv & ~missing,
        stable=d["stable"] & ~missing,
        state=np.where(missing, "no-equilibrium", "contact"),
    )
    if isinstance(A, np.ndarray):
        vals = {k: as_output(np.asarray(v).reshape(shape), scalar) for k, v in vals.items()}
    else:  # NumPy scalars from the scalar fast path
        vals = {k: as_output(v, True) for k, v in vals.items()}
    return SlidingContact(method=method, **vals)


@shared_docs
def sliding_contact(
    a_over_R: ArrayLike,
    R_over_h2: ArrayLike,
    h1_over_h2: ArrayLike,
    sigma0_over_E: ArrayLike,
    *,
    tau0_over_E: ArrayLike | None = None,
    method: Literal["closed-form", "collocation"] = "closed-form",
    n: int | str = "auto",
    tol: float = 1e-12,
    on_failure: FailurePolicy = "raise",
) -> SlidingContact:
    r"""Zones, eccentricity, load and moment of steady sliding at given ``a`` (Eqs. 20--22).

    Parameters
    ----------
    a_over_R : array_like
        Contact half-width over the radius, ``> 0``.
    R_over_h2 : array_like
        Radius over the range of adhesion at the leading edge, ``> 0``.
    h1_over_h2 : array_like
        Trailing over leading range of adhesion, ``> 0`` (``>= 1`` in the paper; 1 gives
        the symmetric normal contact).
    sigma0_over_E : array_like
        Adhesive (Dugdale) stress over the composite modulus, ``>= 0`` (0 gives Hertz).
    tau0_over_E : array_like, optional
        Shear strength of the interface over ``E``, ``>= 0``: adds the friction force
        ``2 a tau0`` (``T_over_Eh2``).
    method : {"closed-form", "collocation"}
        Solver (see the module docstring); both give the same state to about 1e-12. The
        default is the closed form, as for every other problem (up to 0.2.0 it was the
        collocation: pass ``method="collocation"`` for the paper's route).
    %(COLLOCATION)s

    Returns
    -------
    SlidingContact
        The inputs broadcast together; scalars in, scalars out.

    Examples
    --------
    >>> import linecontact as lc
    >>> r = sliding_contact(0.03, 100.0, 2.0, 0.01)
    >>> bool(r.c1_over_R > r.c2_over_R and r.e_over_R > 0 and r.M_over_Eh2R > 0)
    True
    >>> s = sliding_contact(0.03, 100.0, 1.0, 0.01)          # h1 = h2: the normal contact
    >>> abs(s.F_over_Eh2 - lc.normal_contact(0.03, 100.0, 0.01).F_over_Eh) < 1e-10
    True
    """
    A = _domain.check("a_over_R", a_over_R, "sliding_a_over_R")
    rho, r, s, tau, policy = _check_state_inputs(
        R_over_h2, h1_over_h2, sigma0_over_E, tau0_over_E, method, n, tol, on_failure
    )
    scalar, A, rho, r, s, tau = _broadcast_state("a_over_R", A, rho, r, s, tau)
    _cf._warn_wide(A)
    shape = A.shape
    # the closed form runs the same kernels on NumPy scalars
    A, rho, r, s, tau = _flat_points(scalar and method == "closed-form", A, rho, r, s, tau)
    # a contact half-width far outside the solvers' range overflows on the way; _pack's
    # convergence check reports it
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        if method == "closed-form":  # in chunks of points: bounded memory for any number
            d = _in_chunks(_solve_closed_form, np.size(A), A, rho, r, s)
        else:
            d = _solve_flat(A, rho, r, s, method, n, tol)
        return _pack(d, A, rho, r, s, tau, method, shape, scalar, policy, "sliding_contact")
