r"""Steady sliding with different trailing and leading adhesion (paper Eqs. 18--22).

A cylinder slides steadily over the substrate. Sliding wipes the surface ahead of it, so the
adhesion at the trailing edge has a longer range ``h1`` than at the leading edge ``h2``
(the Dugdale stress ``sigma0`` is the same at both); the contact, its adhesive zones and the
pressure lose their symmetry, the cylinder's apex is offset from the contact centre and the
pressure has a resultant moment. Any positive ``h1/h2`` is accepted (``h1 < h2`` is the
mirror image).

Axes and signs
--------------
``x`` runs along the sliding direction (the cylinder moves towards ``+x``), with its origin
at the centre of the contact ``-a < x < a``; ``y`` is normal to the substrate, pointing up
into the cylinder, which lies above the substrate. Figures are drawn with ``x`` to the right
and ``y`` up, so the cylinder moves to the right and "clockwise" is as seen in them.

- Trailing adhesive zone ``-c1 < x < -a`` (range ``h1``), leading zone ``a < x < c2``
  (range ``h2``); the apex of the cylinder (its axis) is at ``x = e`` (eccentricity).
- The pressure ``p`` is compressive positive: ``p = pbar - sigma0`` on ``[-c1, c2]`` with
  ``pbar`` supported on the contact and bounded (zero) at both of its ends (Eq. 8).
- The load ``F = int p dx`` is compressive positive (Eq. 12 with two zones).
- The moment ``M = int x p(x) dx`` about the contact centre is **clockwise positive**: it is
  the clockwise moment of the contact pressure on the substrate, equivalently the clockwise
  moment about the contact centre that must act on the cylinder, together with the load, to
  hold it in equilibrium. The pressure's own moment on the cylinder is ``M``
  counterclockwise: with ``h1 > h2`` it opposes forward (clockwise) rolling -- the resisting
  moment. ``M_axis = M - e F`` is the same moment taken about the cylinder's axis.

Units (as in :mod:`linecontact.reference`, with ``h2`` as the unit of gap): lengths over
``R`` (``a/R``, ``c1/R``, ``c2/R``, ``e/R``), force per unit length over ``E h2``, moment per
unit length over ``E h2 R``, stresses over ``E``, ``R/h2`` and ``h1/h2``.

Equations
---------
Eq. (20), the bounded pressure on the contact,

.. math::

    \frac{1}{\pi E}\int_{-a}^{a}\frac{\bar p(\xi)}{\xi - x}\,d\xi = -\frac{x - e}{2R}
    + \frac{\sigma_0}{\pi E}\ln\frac{c_2 - x}{c_1 + x}, \qquad |x| < a,

is not odd, so its consistency condition (the extra collocation equation) does not hold by
itself: it fixes the eccentricity, which enters linearly through :math:`e/(2R)`. The two
separation conditions are the gap ``h2`` at ``x = c2`` (Eq. 21) and ``h1`` at ``x = -c1``
(Eq. 22, corrupted in the text; derived in ``docs/sliding.md``):

.. math::

    \frac{2}{\pi E}\int_{-a}^{a}\bar p\ln\frac{c_2-\xi}{a-\xi}\,d\xi
    = \frac{(c_2-e)^2-(a-e)^2}{2R} - h_2 - \frac{2\sigma_0}{\pi E}\int_a^{c_2}
      \ln\frac{c_2-x}{c_1+x}\,dx,

    \frac{2}{\pi E}\int_{-a}^{a}\bar p\ln\frac{c_1+\xi}{a+\xi}\,d\xi
    = \frac{(c_1+e)^2-(a+e)^2}{2R} - h_1 + \frac{2\sigma_0}{\pi E}\int_{-c_1}^{-a}
      \ln\frac{c_2-x}{c_1+x}\,dx.

Two solvers give the same :class:`SlidingContact`:

``method="collocation"``
    The paper's route: Eq. (20) by Gauss--Chebyshev collocation
    (:class:`linecontact.sie.BoundedSolver` with the eccentricity as the extra unknown of the
    consistency condition), Eqs. (21)--(22) by product integration of their logarithmic
    kernels (singular at the contact edges), Newton's method in
    :math:`u_i = \operatorname{arccosh}(c_i/a)`, an adaptive number of nodes with a
    Chebyshev-tail error estimate (as :func:`linecontact.normal.normal_contact`).
``method="closed-form"`` (default, as for every other problem)
    The asymmetric Maugis--Dugdale solution derived in ``docs/sliding.md``. With
    :math:`c_i = a\cosh u_i`, :math:`\sigma = (u_1+u_2)/2`, :math:`\delta = (u_1-u_2)/2`,
    :math:`t = x/a = \cos\theta`, :math:`q_i = e^{-u_i}`:

    .. math::

        \bar p/E = \frac{a}{2R}\sin\theta + \frac{2\sigma_0}{\pi E}\left[
            \arctan\frac{q_2\sin\theta}{1 - q_2\cos\theta}
            + \arctan\frac{q_1\sin\theta}{1 + q_1\cos\theta}\right],

        e = \frac{2\sigma_0 R}{\pi E}(u_1 - u_2),\qquad
        F = \frac{\pi E a^2}{4R} - \sigma_0\left(\sqrt{c_1^2-a^2} + \sqrt{c_2^2-a^2}\right),

        M = \frac{\sigma_0}{2}\left(c_1\sqrt{c_1^2-a^2} - c_2\sqrt{c_2^2-a^2}\right),

        h_i = \frac{a^2}{2R}f_1(u_i) + \frac{4\sigma_0 a}{\pi E}\cosh\delta\left[
            u_i\sinh\sigma - \cosh\sigma\ln\frac{\cosh\sigma}{\cosh\delta}\right],

    :math:`f_1 = \sinh u\cosh u - u`; at ``u1 = u2`` the last bracket is Baney & Hui's
    :math:`f_2`, so everything reduces to :mod:`linecontact.normal`. Two algebraic
    equations in :math:`(u_1, u_2)` per point, solved by a safeguarded Newton iteration.

With :math:`\bar a = (a/R)\sqrt{R/(2h_2)}` and :math:`\kappa = (4/\pi)(\sigma_0/E)\sqrt{2R/h_2}`
the separation conditions read :math:`\bar a^2 f_1(u_2) + \kappa\bar a\,G_2 = 1`,
:math:`\bar a^2 f_1(u_1) + \kappa\bar a\,G_1 = h_1/h_2`, and
:math:`F/(Eh_2) = (\pi/2)(\bar a^2 - \kappa\bar a\sinh\sigma\cosh\delta)`: the family depends
on ``kappa`` and ``h1/h2`` once ``a`` is scaled.

References
----------
I. Sari, G. G. Adams, S. Müftü, "Nano-scale effects in the adherence, sliding and rolling of
a cylinder on a substrate" (Eqs. 18--22, Figs. 8--12).
J. M. Baney, C.-Y. Hui, "A cohesive zone model for the adhesion of cylinders",
J. Adhesion Sci. Technol. 11 (1997) 393--406. doi:10.1163/156856197X00796
F. Erdogan, G. D. Gupta, T. S. Cook, "Numerical solution of singular integral equations"
(1973). doi:10.1007/978-94-017-2260-5_7
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar, Literal, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import domain as _domain
from . import reference as _ref
from ._validation import (
    RAISE,
    FailurePolicy,
    broadcast,
    check_solver_options,
    failure_policy,
    first_point,
    point_text,
    positions,
    scalar_or_array,
)
from .errors import ConvergenceError, NoEquilibriumError
from .normal import ZERO_WIDTH_LOAD_RTOL
from .results import Result, as_output
from .sie import SIZES, BoundedSolution, BoundedSolver, _chunks, log_end_moments

__all__ = [
    "SlidingContact",
    "SlidingPullOff",
    "sliding_contact",
    "sliding_contact_for_load",
    "sliding_pull_off",
]

#: As :data:`linecontact.normal.SNAP_OFF_MIN_WIDTH_OVER_H`: the pull-off is a snap-off when
#: the contact half-width at the load minimum is at least this many times the shorter of the
#: two adhesion ranges.
SNAP_OFF_MIN_WIDTH_OVER_H = 1.0

#: Collocation sizes tried by ``n="auto"``.
_SIZES = SIZES[: SIZES.index(2048) + 1]


# --------------------------------------------------------------------------------------------
# results


@dataclass(frozen=True)
class SlidingContact(Result):
    """Steady sliding at given contact half-widths (or loads).

    Attributes
    ----------
    a_over_R : ndarray or float
        Contact half-width ``a/R``.
    c1_over_R, c2_over_R : ndarray or float
        Ends of the trailing (``-c1 < x < -a``) and leading (``a < x < c2``) adhesive zones,
        measured from the contact centre, over ``R``.
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
        ``dF/da > 0``: stable under load control.
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

    a_over_R: NDArray | float
    c1_over_R: NDArray | float
    c2_over_R: NDArray | float
    e_over_R: NDArray | float
    F_over_Eh2: NDArray | float
    M_over_Eh2R: NDArray | float
    M_axis_over_Eh2R: NDArray | float
    R_over_h2: NDArray | float
    h1_over_h2: NDArray | float
    sigma0_over_E: NDArray | float
    tau0_over_E: NDArray | float
    T_over_Eh2: NDArray | float
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
        """``c1/a`` (>= 1)."""
        return np.asarray(self.c1_over_R) / np.asarray(self.a_over_R)

    @property
    def c2_over_a(self):
        """``c2/a`` (>= 1)."""
        return np.asarray(self.c2_over_R) / np.asarray(self.a_over_R)

    def friction_force(self, tau0_over_E: ArrayLike) -> NDArray | float:
        """Friction force per unit length ``2 a tau0`` over ``E h2``, for ``tau0/E >= 0``."""
        t = _domain.check("tau0_over_E", tau0_over_E, "friction_tau0_over_E")
        val = 2 * np.asarray(self.a_over_R) * np.asarray(self.R_over_h2) * t
        return val.item() if np.ndim(val) == 0 else val

    def _coefficients(self, n: int | None = None):
        """Chebyshev-U coefficients of ``pbar/E`` on ``t = x/a`` (closed form, truncated).

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
        r"""Contact pressure ``p/E`` (compressive positive) at ``x/R``.

        ``x_over_R`` has shape ``(m,)``; the result has shape ``points.shape + (m,)``.
        Inside the contact: the closed-form bounded solution of Eq. (20) at the computed
        ``c1``, ``c2`` (the collocation solution is the same function to its tolerance);
        ``-sigma0/E`` in the adhesive zones; zero beyond.
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
        r"""The gap between the surfaces over ``h2`` at ``x/R`` (zero in the contact).

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


@dataclass(frozen=True)
class SlidingPullOff(Result):
    """The most tensile load a steadily sliding contact carries (load control).

    Attributes
    ----------
    F_pulloff_over_Eh2 : ndarray or float
        Pull-off force over ``E h2`` (negative).
    a_over_R_at_pulloff : ndarray or float
        Contact half-width at pull-off (0 for the zero-width mechanism).
    mechanism : ndarray of str or str
        ``"snap-off"`` (the contact lets go from a half-width of at least the shorter
        adhesion range) or ``"zero-width"`` (it peels below it first).
    F_zero_width_over_Eh2 : ndarray or float
        The load as the contact width vanishes (the two-zone analogue of Eq. 14).
    c1_over_R_zero_width, c2_over_R_zero_width : ndarray or float
        The adhesive zones of that limit state.
    """

    inputs: ClassVar[tuple[str, ...]] = ("R_over_h2", "h1_over_h2", "sigma0_over_E")

    F_pulloff_over_Eh2: NDArray | float
    a_over_R_at_pulloff: NDArray | float
    mechanism: NDArray | str
    F_zero_width_over_Eh2: NDArray | float
    c1_over_R_zero_width: NDArray | float
    c2_over_R_zero_width: NDArray | float
    R_over_h2: NDArray | float
    h1_over_h2: NDArray | float
    sigma0_over_E: NDArray | float


# --------------------------------------------------------------------------------------------
# closed form


def _f1(u):
    """f1 = sinh u cosh u - u (Baney & Hui), by its series below u = 0.5.

    Arrays or NumPy scalars (a scalar evaluates only the branch it takes).
    """
    small = u < 0.5
    if isinstance(small, np.ndarray):
        us = np.where(small, u, 0.0)
        ub = np.where(small, 1.0, u)
        with np.errstate(over="ignore"):
            return np.where(small, _ref._f1_series(us), 0.5 * np.sinh(2 * ub) - ub)
    if small:
        return _ref._f1_series(u)
    if u < 350.0:  # sinh(2u) is finite (and no errstate is needed, ~1.5 us each)
        return 0.5 * np.sinh(2 * u) - u
    with np.errstate(over="ignore"):
        return 0.5 * np.sinh(2 * u) - u


def _cf_parts(u1, u2):
    """G1, G2 (the brackets of the separation conditions) and their u-derivatives."""
    sh1, sh2 = np.sinh(u1), np.sinh(u2)
    ch1, ch2 = np.cosh(u1), np.cosh(u2)
    cd = np.cosh(0.5 * (u1 - u2))
    # ell = ln(cosh sigma / cosh delta), cosh sigma - cosh delta = 2 sinh(u1/2) sinh(u2/2)
    ell = np.log1p(2 * np.sinh(0.5 * u1) * np.sinh(0.5 * u2) / cd)
    Sb = 0.5 * (sh1 + sh2)  # cosh(delta) sinh(sigma)
    Cb = 0.5 * (ch1 + ch2)  # cosh(delta) cosh(sigma)
    G1 = u1 * Sb - Cb * ell
    G2 = u2 * Sb - Cb * ell
    # d ell/du1 = (tanh sigma - tanh delta)/2, so Cb d ell/du1 = sinh(u2)/2 (and mirror)
    w1 = -0.5 * (sh1 * ell + sh2)
    w2 = -0.5 * (sh2 * ell + sh1)
    dG1 = (Sb + 0.5 * u1 * ch1 + w1, 0.5 * u1 * ch2 + w2)
    dG2 = (0.5 * u2 * ch1 + w1, Sb + 0.5 * u2 * ch2 + w2)
    return G1, G2, dG1, dG2, Sb


def _cf_eval(ab, kap, r, u1, u2):
    """Residuals E1 (over h1), E2 (over h2) and the 2x2 Jacobian in (u1, u2)."""
    G1, G2, dG1, dG2, _ = _cf_parts(u1, u2)
    a2 = ab * ab
    E1 = (a2 * _f1(u1) + kap * ab * G1) / r - 1
    E2 = a2 * _f1(u2) + kap * ab * G2 - 1
    # (sh * sh, not sh ** 2: a NumPy scalar's power is pow(), not always the product)
    sh1, sh2 = np.sinh(u1), np.sinh(u2)
    J11 = (a2 * 2 * (sh1 * sh1) + kap * ab * dG1[0]) / r
    J12 = kap * ab * dG1[1] / r
    J21 = kap * ab * dG2[0]
    J22 = a2 * 2 * (sh2 * sh2) + kap * ab * dG2[1]
    return E1, E2, J11, J12, J21, J22


def _initial_u(ab, kap, r):
    """Each edge as if the contact were symmetric with its own range (normal closed form)."""
    sr = np.sqrt(r)
    if not isinstance(ab, np.ndarray):
        u2, _, _ = _ref._u_of_abar(ab, kap)
        u1, _, _ = _ref._u_of_abar(ab / sr, kap / sr)
        return u1, u2
    # both edges as one batch (the points are independent; fewer calls on small batches)
    u, _, _ = _ref._u_of_abar(np.concatenate([ab / sr, ab]), np.concatenate([kap / sr, kap]))
    return u[: ab.size], u[ab.size :]


_BIG = float(np.finfo(float).max)


def _nan_to_num(x):
    """``np.nan_to_num`` (nan to 0, infinities to the largest floats), also for NumPy scalars."""
    if isinstance(x, np.ndarray):
        return np.nan_to_num(x)
    if x != x:
        return np.float64(0.0)
    return _ref._minimum(_ref._maximum(x, -_BIG), _BIG)


def _direction(u1, u2, E1, E2, J11, J12, J21, J22, tol, umax):
    """The damped Newton step of :func:`_newton2` from an accepted point (elementwise).

    Returns the direction, the largest step length that keeps ``u`` positive (at most 3/4 of
    the way to 0) and below ``umax``, and whether the point is done: its residual is below
    ``tol`` or the step is at rounding level.
    """
    where = _ref._where
    det = J11 * J22 - J12 * J21
    d1 = (-E1 * J22 + E2 * J12) / det
    d2 = (-E2 * J11 + E1 * J21) / det
    # fall back to the diagonal (each residual is monotone in its own u) if singular (the
    # `if`s skip work that would change nothing: the rare cases are rare in a batch too)
    bad = ~((abs(d1) < np.inf) & (abs(d2) < np.inf))
    if bad.any():
        d1 = _nan_to_num(where(bad, -E1 / J11, d1))
        d2 = _nan_to_num(where(bad, -E2 / J22, d2))
    lam = 1.0
    for d, u in ((d1, u1), (d2, u2)):
        neg = d < -0.75 * u
        if neg.any():
            lam = where(neg, _ref._minimum(lam, 0.75 * u / where(neg, -d, 1.0)), lam)
        big = u + d > umax
        if big.any():
            lam = where(big, _ref._minimum(lam, (umax - u) / where(big, d, 1.0)), lam)
    tiny = (abs(d1) <= 4e-16 * _ref._maximum(u1, 1e-3)) & (
        abs(d2) <= 4e-16 * _ref._maximum(u2, 1e-3)
    )
    done = ~(_ref._maximum(abs(E1), abs(E2)) > tol) | tiny
    return d1, d2, lam + 0.0 * u1, done


def _newton2(evaluate, u1, u2, params, *, nextra=0, maxiter=60, tol=1e-15, floor=2e-14, umax=300.0):
    """Damped Newton for two residuals in (u1, u2) > 0, per point (flat arrays or scalars).

    ``evaluate(u1, u2, *params)`` returns ``(E1, E2, J11, J12, J21, J22, *extra)`` with
    ``nextra`` extra quantities. Steps are limited to keep ``u`` positive and halved (at most
    12 times) while they do not reduce the larger residual; below ``floor`` (rounding level)
    any step is accepted. A point stops when its residual is below ``tol``, its step is at
    rounding level or no step reduces its residual, or after ``maxiter`` Newton steps.

    Each iteration evaluates one trial point (a full step or a halved one) of every point
    still active; a point that stops leaves the loop (:func:`linecontact.reference._iterate`),
    so one slow point does not keep the batch iterating. Returns ``u1, u2, |E1|, |E2|`` and
    the extras of the last evaluation at the returned ``u``.
    """
    where = _ref._where
    ev = tuple(evaluate(u1, u2, *params))
    d1, d2, lam, done = _direction(u1, u2, *ev[:6], tol, umax)
    zero = 0.0 * lam
    ncur = 6 + nextra
    nstate = 2 + ncur + 5

    def step(*args):
        u1, u2 = args[0], args[1]
        cur = args[2 : 2 + ncur]
        d1, d2, lam, tries, steps = args[2 + ncur : nstate]
        n1 = u1 + lam * d1
        n2 = u2 + lam * d2
        r = evaluate(n1, n2, *args[nstate:])
        nrm = _ref._maximum(abs(cur[0]), abs(cur[1]))
        nn = _ref._maximum(abs(r[0]), abs(r[1]))
        ok = (abs(nn) < np.inf) & ((nn < nrm) | (nn <= floor))
        cur = tuple(where(ok, a, b) for a, b in zip(r, cur, strict=True))
        u1, u2 = where(ok, n1, u1), where(ok, n2, u2)
        # a step at rounding level: quadratic convergence leaves nothing to gain
        small = (abs(lam * d1) <= 1e-12 * _ref._maximum(u1, 1e-3)) & (
            abs(lam * d2) <= 1e-12 * _ref._maximum(u2, 1e-3)
        )
        nd1, nd2, nlam, converged = _direction(u1, u2, *cur[:6], tol, umax)
        # thirteen trials that do not reduce the residual: it is at its rounding floor
        give_up = ~ok & (tries >= 12)
        steps = steps + where(ok, 1.0, 0.0)
        stop = (ok & (small | converged | (steps >= maxiter))) | give_up
        d1, d2 = where(ok, nd1, d1), where(ok, nd2, d2)
        lam = where(ok, nlam, 0.5 * lam)
        tries = where(ok, 0.0, tries + 1)
        return (u1, u2, *cur, d1, d2, lam, tries, steps), stop

    state = (u1, u2, *ev, d1, d2, lam, zero, zero)
    (u1, u2, E1, E2, *rest), _ = _ref._iterate(step, state, tuple(params), 13 * maxiter, done)
    return u1, u2, abs(E1), abs(E2), tuple(rest[4 : 4 + nextra])


def _closed_form(A, rho, r, s, u1=None, u2=None):
    """u1, u2 and residuals of the closed-form separation conditions, flat arrays."""
    ab = A * np.sqrt(rho / 2)
    kap = _ref._kappa(rho, s)
    if u1 is None or u2 is None:
        u1, u2 = _initial_u(ab, kap, r)
    u1, u2, e1, e2, _ = _newton2(_cf_evaluate, u1, u2, (ab, kap, r))
    return u1, u2, e1, e2


def _cf_evaluate(u1, u2, ab, kap, r):
    """:func:`_cf_eval` in the argument order of :func:`_newton2`."""
    return _cf_eval(ab, kap, r, u1, u2)


def _cf_outputs(A, rho, r, s, u1, u2):
    """e, F, M, dF/da from u1, u2 (closed form; also used for the stability of any method)."""
    ab = A * np.sqrt(rho / 2)
    kap = _ref._kappa(rho, s)
    ecc = (2 * s / np.pi) * (u1 - u2)
    sh1, sh2 = np.sinh(u1), np.sinh(u2)
    F = (np.pi / 2) * (ab * ab - kap * ab * 0.5 * (sh1 + sh2))
    # M = (sigma0 a^2 / 4)(sinh 2u1 - sinh 2u2) = sigma0 a^2 cosh(2 sigma) sinh(2 delta) / 2
    M = 0.5 * s * A * A * rho * np.cosh(u1 + u2) * np.sinh(u1 - u2)
    # dF/d(abar) along the branch: implicit differentiation of the separation conditions
    G1, G2, dG1, dG2, Sb = _cf_parts(u1, u2)
    _, _, J11, J12, J21, J22 = _cf_eval(ab, kap, r, u1, u2)
    b1 = (2 * ab * _f1(u1) + kap * G1) / r
    b2 = 2 * ab * _f1(u2) + kap * G2
    det = J11 * J22 - J12 * J21
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        du1 = -(b1 * J22 - b2 * J12) / det
        du2 = -(b2 * J11 - b1 * J21) / det
        dPhi = 2 * ab - kap * Sb - kap * ab * 0.5 * (np.cosh(u1) * du1 + np.cosh(u2) * du2)
    return ecc, F, M, dPhi


def _stable(A, rho, r, s, u1, u2, dphi):
    """Stable under load control: ``dF/da > 0`` where its sign is clear (one definition).

    Where the derivative is lost in round-off (near the load minimum, or at widths so small
    that the load is flat to the last digit, next to a zero-width minimum) the width is
    compared with that of the minimum (:func:`_pulloff_flat`), as :func:`sliding_pull_off`
    and :func:`sliding_contact_for_load` locate it: stable iff wider than an interior
    minimum, always next to a zero-width one. Flat arrays or NumPy scalars.
    """
    ab = A * np.sqrt(rho / 2)
    kap = _ref._kappa(rho, s)
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


def _cf_coefficients(A, s, u1, u2, n):
    """Chebyshev-U coefficients b_j (j < n) of pbar/E on [-1, 1] (closed form)."""
    k = np.arange(1, n + 1)
    q1 = np.exp(-u1)[:, None]
    q2 = np.exp(-u2)[:, None]
    with np.errstate(under="ignore"):
        b = (2 * s[:, None] / np.pi) * (q2**k - (-q1) ** k) / k
    b[:, 0] += 0.5 * A
    return b


# --------------------------------------------------------------------------------------------
# collocation


def _colloc_rhs(x, A, s, u1, u2):
    """Eq. 20 on t = x/a (without the e/(2R) term) and its derivatives in u1, u2."""
    A, s, u1, u2 = (v[:, None] for v in (A, s, u1, u2))
    m1m1 = 2 * np.sinh(u1 / 2) ** 2
    m2m1 = 2 * np.sinh(u2 / 2) ** 2
    m2mx = m2m1 + (1 - x)  # m2 - x
    m1px = m1m1 + (1 + x)  # m1 + x
    c = s / np.pi
    f = -0.5 * A * x + c * np.log(m2mx / m1px)
    df1 = -c * np.sinh(u1) / m1px
    df2 = c * np.sinh(u2) / m2mx
    return np.stack([f, df1, df2], axis=1)  # (P, 3, n + 1)


def _K(mm1_own, m_own, m_other):
    """(1/a) int over the own zone of ln((c_own - x)/(c_other + x)) and its d/dm's.

    K = (m-1) ln((m-1)/(m+m')) + (m'+1) ln((m'+1)/(m+m')); dK/dm = ln((m-1)/(m+m')),
    dK/dm' = ln((m'+1)/(m+m')).
    """
    tot = m_own + m_other
    with np.errstate(divide="ignore", invalid="ignore"):
        l_own = np.log(mm1_own / tot)
        l_oth = np.log((m_other + 1) / tot)
    K = np.where(mm1_own > 0, mm1_own * l_own, 0.0) + (m_other + 1) * l_oth
    return K, np.where(mm1_own > 0, l_own, -np.inf), l_oth


def _colloc_eval(solver: BoundedSolver, A, s, rho, r, u1, u2):
    """Residuals of Eqs. 22 (trailing, over h1) and 21 (leading, over h2), Jacobian, extras."""
    n = solver.n
    x = solver.collocation_unit
    f = _colloc_rhs(x, A, s, u1, u2)
    sol = solver.solve(f, extra=np.full(n + 1, 0.5), values=False)
    B = sol.coefficients  # (P, 3, n): b, db/du1, db/du2
    lam = cast(NDArray, sol.extra)  # (P, 3): e/R and its derivatives
    b, db1, db2 = B[:, 0], B[:, 1], B[:, 2]
    ecc, de1, de2 = lam[:, 0], lam[:, 1], lam[:, 2]
    sg = (-1.0) ** np.arange(n)
    mu2, dmu2 = log_end_moments(n, u2)  # ln((m2 - t)/(1 - t)) moments
    mu1, dmu1 = log_end_moments(n, u1)  # ln((m1 + t)/(1 + t)) moments of g(-t)
    mu1s, dmu1s = mu1 * sg, dmu1 * sg
    J2 = np.einsum("pj,pj->p", b, mu2)
    J1 = np.einsum("pj,pj->p", b, mu1s)
    dJ2 = (
        np.einsum("pj,pj->p", db1, mu2),
        np.einsum("pj,pj->p", db2, mu2) + np.einsum("pj,pj->p", b, dmu2),
    )
    dJ1 = (
        np.einsum("pj,pj->p", db1, mu1s) + np.einsum("pj,pj->p", b, dmu1s),
        np.einsum("pj,pj->p", db2, mu1s),
    )
    sh1, sh2 = np.sinh(u1), np.sinh(u2)
    m1, m2 = np.cosh(u1), np.cosh(u2)
    mm1_1 = 2 * np.sinh(u1 / 2) ** 2
    mm1_2 = 2 * np.sinh(u2 / 2) ** 2
    K2, dK2_own, dK2_oth = _K(mm1_2, m2, m1)
    K1, dK1_own, dK1_oth = _K(mm1_1, m1, m2)
    with np.errstate(invalid="ignore"):
        dK2 = (dK2_oth * sh1, np.where(sh2 > 0, dK2_own * sh2, 0.0))
        dK1 = (np.where(sh1 > 0, dK1_own * sh1, 0.0), dK1_oth * sh2)
    c = 2 * A / np.pi
    rho1 = rho / r
    # leading: 1 + (R/h2)[(2A/pi) J2 + (2 s A/pi) K2 - A^2 sh2^2/2 + A e (m2 - 1)]
    R2 = 1 + rho * (c * J2 + c * s * K2 - 0.5 * A * A * sh2 * sh2 + A * ecc * mm1_2)
    R1 = 1 + rho1 * (c * J1 + c * s * K1 - 0.5 * A * A * sh1 * sh1 - A * ecc * mm1_1)
    J21 = rho * (c * dJ2[0] + c * s * dK2[0] + A * de1 * mm1_2)
    J22 = rho * (c * dJ2[1] + c * s * dK2[1] - A * A * sh2 * m2 + A * de2 * mm1_2 + A * ecc * sh2)
    J11 = rho1 * (c * dJ1[0] + c * s * dK1[0] - A * A * sh1 * m1 - A * de1 * mm1_1 - A * ecc * sh1)
    J12 = rho1 * (c * dJ1[1] + c * s * dK1[1] - A * de2 * mm1_1)
    res = (np.pi / 2) * b[:, 0]
    mom = (np.pi / 4) * b[:, 1] if n > 1 else np.zeros_like(res)
    tail = np.max(np.abs(b[:, -3:]), axis=-1) / np.maximum(np.max(np.abs(b), axis=-1), 1e-300)
    # residuals as (gap - h)/h, the sign of the closed-form ones; the extras as in _EXTRA
    return (
        *(-R1, -R2, -J11, -J12, -J21, -J22),
        *(ecc, res, mom, np.abs(sol.consistency[:, 0]), tail),
    )


#: The extra quantities of :func:`_colloc_eval`, in its order.
_EXTRA = ("ecc", "resultant", "moment", "consistency", "tail")


def _collocation(A, rho, r, s, n, tol):
    """Flat arrays in, dict of flat arrays out."""
    sizes = np.asarray(_SIZES)
    ab = A * np.sqrt(rho / 2)
    kap = _ref._kappa(rho, s)
    u1, u2 = _initial_u(ab, kap, r)  # each edge from the symmetric solution with its range

    def run(nn, idx, v1, v2):
        """Newton at nn nodes on the points idx, in chunks of bounded memory."""
        solver = BoundedSolver(int(nn))

        def evaluate(w1, w2, A_, s_, rho_, r_):
            return _colloc_eval(solver, A_, s_, rho_, r_, w1, w2)

        out = [np.empty(idx.size) for _ in range(4 + len(_EXTRA))]
        for c in _chunks(idx.size, int(nn)):
            g = idx[c]
            w1, w2, f1, f2, ex_ = _newton2(
                evaluate, v1[c], v2[c], (A[g], s[g], rho[g], r[g]), nextra=len(_EXTRA)
            )
            for o, v in zip(out, (w1, w2, f1, f2, *ex_), strict=True):
                o[c] = v
        return (*out[:4], dict(zip(_EXTRA, out[4:], strict=True)))

    n0 = 16 if n == "auto" else int(n)
    P = A.size
    idx = np.arange(P)
    u1, u2, e1, e2, ex = run(n0, idx, u1, u2)
    nsel = np.full(P, n0)
    if n == "auto":
        need = np.log(1 / tol) / (1.5 * np.maximum(np.minimum(u1, u2), 1e-300))
        pending = ex["tail"] > tol
        target = sizes[np.minimum(np.searchsorted(sizes, need), sizes.size - 1)]
        nsel = np.where(pending, np.maximum(target, sizes[1]), nsel)
        while pending.any():
            for nn in np.unique(nsel[pending]):
                sel = np.nonzero(pending & (nsel == nn))[0]
                v1, v2, f1, f2, x2 = run(nn, sel, u1[sel], u2[sel])
                u1[sel], u2[sel], e1[sel], e2[sel] = v1, v2, f1, f2
                for k in ex:
                    ex[k][sel] = x2[k]
            pending = pending & (ex["tail"] > tol) & (nsel < sizes[-1])
            nsel = np.where(
                pending, sizes[np.minimum(np.searchsorted(sizes, nsel) + 1, sizes.size - 1)], nsel
            )
    m1, m2 = np.cosh(u1), np.cosh(u2)
    F = rho * A * (ex["resultant"] - s * (m1 + m2))
    # strips: -sigma0 (int_a^c2 x + int_-c1^-a x) = sigma0 (c1^2 - c2^2)/2,
    # (m1^2 - m2^2) = sinh(u1 + u2) sinh(u1 - u2)
    M = rho * A * A * (ex["moment"] + 0.5 * s * np.sinh(u1 + u2) * np.sinh(u1 - u2))
    converged = (np.maximum(e1, e2) <= 1e-10) & (ex["tail"] <= 10 * tol) & np.isfinite(F)
    return dict(
        u1=u1,
        u2=u2,
        ecc=ex["ecc"],
        F=F,
        M=M,
        res1=e1,
        res2=e2,
        cons=ex["consistency"],
        tail=ex["tail"],
        n=nsel,
        converged=converged,
    )


# --------------------------------------------------------------------------------------------
# public: direct problem


def _check_common(R_over_h2, h1_over_h2, sigma0_over_E):
    rho = _domain.check("R_over_h2", R_over_h2)
    r = _domain.check("h1_over_h2", h1_over_h2)
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    return rho, r, s


def _check_method(method, n, tol):
    if method not in ("closed-form", "collocation"):
        raise ValueError(f"method must be 'closed-form' or 'collocation', got {method!r}")
    check_solver_options(n, tol, n_max=8192)


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
            converged=(_ref._maximum(e1, e2) <= 1e-12) & (abs(F) < np.inf),
        )
    else:
        d = _collocation(A, rho, r, s, n, tol)
        _, _, _, dphi = _cf_outputs(A, rho, r, s, d["u1"], d["u2"])
    d["stable"] = _stable(A, rho, r, s, d["u1"], d["u2"], dphi)
    return d


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
    on_failure: FailurePolicy = RAISE,
    **deprecated: Any,
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
    rho, r, s = _check_common(R_over_h2, h1_over_h2, sigma0_over_E)
    tau = (
        np.full((), np.nan)
        if tau0_over_E is None
        else _domain.check("tau0_over_E", tau0_over_E, "friction_tau0_over_E")
    )
    _check_method(method, n, tol)
    policy = failure_policy(on_failure, where="sliding_contact", **deprecated)
    scalar = scalar_or_array(A, rho, r, s, tau)
    A, rho, r, s, tau = broadcast(
        a_over_R=A, R_over_h2=rho, h1_over_h2=r, sigma0_over_E=s, tau0_over_E=tau
    )
    _ref._check_kappa(rho, s, "R_over_h2")
    _ref._warn_wide(A)
    shape = A.shape
    if scalar and method == "closed-form":  # the same kernels on NumPy scalars
        A, rho, r, s, tau = _ref._scalars(A, rho, r, s, tau)
    else:
        A, rho, r, s, tau = (
            np.ascontiguousarray(v, dtype=float).reshape(-1) for v in (A, rho, r, s, tau)
        )
    # a contact half-width far outside the solvers' range overflows on the way; _pack's
    # convergence check reports it
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        d = _solve_flat(A, rho, r, s, method, n, tol)
        return _pack(d, A, rho, r, s, tau, method, shape, scalar, policy, "sliding_contact")


# --------------------------------------------------------------------------------------------
# zero width, pull-off and the inverse


def _zero_width(kap, r):
    """The a -> 0 limit, X_i = (c_i/R) sqrt(R/(2 h2)).

    X2^2 + kappa S/2 ln(S/X1) = 1 and X1^2 + kappa S/2 ln(S/X2) = h1/h2 with S = X1 + X2
    (the separation conditions as u1, u2 -> inf at fixed c_i).
    """
    ln2 = _ref.LN2
    X2 = 2.0 / (kap * ln2 + np.sqrt(kap * kap * ln2 * ln2 + 4))
    X1 = 2.0 * r / (kap * ln2 + np.sqrt(kap * kap * ln2 * ln2 + 4 * r))

    def evaluate(x1, x2, k, r):
        S = x1 + x2
        L2 = np.log(S / x1)
        L1 = np.log(S / x2)
        E1 = (x1 * x1 + 0.5 * k * S * L1) / r - 1
        E2 = x2 * x2 + 0.5 * k * S * L2 - 1
        J11 = (2 * x1 + 0.5 * k * (L1 + 1)) / r
        J12 = 0.5 * k * (L1 - x1 / x2) / r
        J21 = 0.5 * k * (L2 - x2 / x1)
        J22 = 2 * x2 + 0.5 * k * (L2 + 1)
        return E1, E2, J11, J12, J21, J22

    X1, X2, e1, e2, _ = _newton2(evaluate, X1, X2, (kap, r))
    return X1, X2, np.maximum(e1, e2)


def _phi_at(lab, kap, r):
    """Phi = (2/pi) F/(E h2), dPhi/dabar, u1, u2 at abar = exp(lab) (closed form).

    Flat arrays or NumPy scalars. Each call starts from the symmetric guesses (robust; warm
    starts from a distant abar can lead Newton astray).
    """
    ab = np.exp(lab)
    one = _ref._full(ab, 1.0)  # the closed form depends on abar and kappa only: R/h2 = 1
    A = ab * np.sqrt(2.0)
    s = kap * (np.pi / 4) / np.sqrt(2.0)
    u1, u2, _, _ = _closed_form(A, one, r, s)
    _, F, _, dphi = _cf_outputs(A, one, r, s, u1, u2)
    return F * (2 / np.pi), dphi, u1, u2


_LAB_LO = np.log(1e-9)  # abar below which the load is indistinguishable from its a -> 0 limit
_LAB_DEEP = -300.0  # the lower end of a contact-for-load bracket at a zero-width minimum
_GRID = np.linspace(0.0, 1.0, 41)  # the grid in ln abar that brackets the load minimum


def _phi_grid(labs, kap, r):
    """Phi and dPhi/dabar on the grid ``labs`` (grid, points), as one batch per chunk.

    The grid values of a few points at a time are solved together (a scalar call evaluates
    its 41 grid values in one vectorised solve instead of 41 scalar ones).
    """
    G, P = labs.shape
    phis = np.empty((G, P))
    dphis = np.empty((G, P))
    step = max(1, (1 << 16) // G)
    for c in range(0, P, step):
        sl = slice(c, min(c + step, P))
        m = sl.stop - sl.start
        ph, dph, _, _ = _phi_at(
            labs[:, sl].reshape(-1),
            np.broadcast_to(kap[sl], (G, m)).reshape(-1),
            np.broadcast_to(r[sl], (G, m)).reshape(-1),
        )
        phis[:, sl] = ph.reshape(G, m)
        dphis[:, sl] = dph.reshape(G, m)
    return phis, dphis


def _secant_step(xp, fp, x, fx, lo, hi, ph, kap, r):
    """One step of the secant on dPhi inside its bracket (bisection otherwise), per point."""
    where = _ref._where
    nx = x - fx * (x - xp) / (fx - fp)
    ok = (abs(nx) < np.inf) & (nx > lo) & (nx < hi)
    nx = where(ok, nx, 0.5 * (lo + hi))
    ph, fn, _, _ = _phi_at(nx, kap, r)
    xp, fp, x, fx = x, fx, nx, fn
    up = fx > 0
    hi = where(up, x, hi)
    lo = where(up, lo, x)
    stop = ~(abs(x - xp) > 1e-10 * _ref._maximum(1.0, abs(x))) | (fx == 0)
    return (xp, fp, x, fx, lo, hi, ph), stop


def _pulloff_flat(kap, r):
    """Minimum of Phi(abar) along the branch: grid in ln abar, then a secant on dPhi.

    Flat arrays or NumPy scalars (the grid is solved as a batch either way).
    """
    scalar = not isinstance(kap, np.ndarray)
    X1, X2, _ = _zero_width(kap, r)
    phi0 = -0.5 * kap * (X1 + X2)
    # upper end: Hertz dominates beyond abar ~ 1 + kappa
    lab_hi = np.log(3.0 + 3.0 * kap)
    kv, rv = np.atleast_1d(kap), np.atleast_1d(r)
    labs = _LAB_LO + _GRID[:, None] * (np.atleast_1d(lab_hi) - _LAB_LO)[None, :]
    phis, dphis = _phi_grid(labs, kv, rv)
    # interior minimum: bracket the smallest grid value
    k = np.argmin(phis, axis=0)
    cols = np.arange(kv.size)
    interior = (k > 0) & (k < _GRID.size - 1)
    kk = np.clip(k, 1, _GRID.size - 2)
    # the secant on dPhi starts from the grid values at the bracket's ends (kept inside the
    # bracket, bisection otherwise); the load is flat at its minimum, so locating it to
    # 1e-10 in ln(abar) gives the load to rounding
    start = (
        labs[kk - 1, cols],
        dphis[kk - 1, cols],
        labs[kk + 1, cols],
        dphis[kk + 1, cols],
        labs[kk - 1, cols],
        labs[kk + 1, cols],
        phis[kk + 1, cols],
    )
    if scalar:
        start, interior = _ref._scalars(*(v[0] for v in start)), bool(interior[0])
    (_, _, lab_min, _, _, _, ph), _ = _ref._iterate(
        _secant_step, start, (kap, r), 100, done=not interior if scalar else ~interior
    )
    interior = interior & (ph < phi0)
    phi_min = _ref._where(interior, ph, phi0)
    lab_min = _ref._where(interior, lab_min, -np.inf)
    return dict(
        X1=X1,
        X2=X2,
        phi0=phi0,
        phi_min=phi_min,
        lab_min=lab_min,
        interior=interior,
        lab_hi=lab_hi,
    )


def sliding_pull_off(
    R_over_h2: ArrayLike, h1_over_h2: ArrayLike, sigma0_over_E: ArrayLike
) -> SlidingPullOff:
    r"""The most tensile load a steadily sliding contact carries (closed form).

    The load along the branch of sliding contacts has a minimum either inside the branch
    (``"snap-off"``) or as the contact width vanishes (``"zero-width"``), where the two
    adhesive zones ``-c1 < x < c2`` of the touching state carry
    ``F = -sigma0 (c1 + c2)``; the pull-off force is that minimum, and the rule for the
    label is that of :func:`linecontact.pull_off` (a snap-off lets go from a contact
    half-width of at least the shorter adhesion range, :data:`SNAP_OFF_MIN_WIDTH_OVER_H`,
    or more than 1 % below the zero-width load,
    :data:`linecontact.normal.ZERO_WIDTH_LOAD_RTOL`).
    At ``h1 = h2`` this is the pull-off of :func:`linecontact.pull_off`.

    Parameters
    ----------
    R_over_h2, h1_over_h2, sigma0_over_E : array_like
        As in :func:`sliding_contact`. Without adhesion (``sigma0_over_E = 0``) the
        pull-off force is 0, at zero width, as in :func:`linecontact.pull_off`.

    Returns
    -------
    SlidingPullOff
    """
    rho, r, s = _check_common(R_over_h2, h1_over_h2, sigma0_over_E)
    scalar = scalar_or_array(rho, r, s)
    rho, r, s = broadcast(R_over_h2=rho, h1_over_h2=r, sigma0_over_E=s)
    _ref._check_kappa(rho, s, "R_over_h2")
    shape = rho.shape
    if scalar:  # the same kernels on NumPy scalars (the grid is a batch of 41 either way)
        rho, r, s = _ref._scalars(rho, r, s)
    else:
        rho, r, s = (np.ascontiguousarray(v, float).reshape(-1) for v in (rho, r, s))
    kap = _ref._kappa(rho, s)
    where = _ref._where
    # h1/h2 far from 1 (1e-300, 1e12) overflows on the way to a finite answer; a result that
    # is not finite is reported below
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        d = _pulloff_flat(kap, r)
        sq = np.sqrt(2 / rho)
        F0 = (np.pi / 2) * d["phi0"]
        Fmin = (np.pi / 2) * d["phi_min"]
        a_min = where(d["interior"], np.exp(d["lab_min"]) * sq, 0.0)
        # a snap-off lets go from a width of at least the shorter adhesion range, or more
        # than 1 % below the zero-width load (as in normal.pull_off)
        snap = d["interior"] & (
            (a_min >= SNAP_OFF_MIN_WIDTH_OVER_H * _ref._minimum(1.0, r) / rho)
            | (F0 - Fmin > ZERO_WIDTH_LOAD_RTOL * abs(F0))
        )
    bad = ~((abs(F0) < np.inf) & (abs(Fmin) < np.inf) & (abs(a_min) < np.inf))
    if np.any(bad):
        _, at = first_point(bad, R_over_h2=rho, h1_over_h2=r, sigma0_over_E=s)
        raise ConvergenceError(
            f"sliding_pull_off did not converge at {point_text(at)}: the point is outside the "
            f"solver's range"
        )
    vals = dict(
        F_pulloff_over_Eh2=Fmin,
        a_over_R_at_pulloff=a_min,
        mechanism=where(snap, "snap-off", "zero-width"),
        F_zero_width_over_Eh2=F0,
        c1_over_R_zero_width=d["X1"] * sq,
        c2_over_R_zero_width=d["X2"] * sq,
        R_over_h2=rho,
        h1_over_h2=r,
        sigma0_over_E=s,
    )
    vals = {
        k: as_output(v if scalar else np.asarray(v).reshape(shape), scalar) for k, v in vals.items()
    }
    return SlidingPullOff(**vals)


def _lower_end(F, rho, r, s, kap, phi_t, report: bool = False):
    """Lower end (ln abar) of the stable branch; below the pull-off, NoEquilibriumError.

    Flat arrays or NumPy scalars; the pull-off search runs on the adhesive points only.
    With ``report`` the points below the pull-off force (or at a load <= 0 without
    adhesion) are not an error: they are marked ``missing`` and their target load is moved
    to one that a contact carries. Returns ``(lab_lo, phi_t, missing, phi_po)``, the last
    the load at the lower end (the pull-off load; 0 without adhesion).

    Where the minimum sits at zero width the branch starts at ``abar -> 0``: the bracket
    starts at ``abar = e**-300`` (a load within round-off of the zero-width one); without
    adhesion just below the width that carries the target (``Phi = abar^2``).
    """
    adh = s > 0
    if not isinstance(F, np.ndarray):
        phi_po, lab_lo = np.float64(0.0), np.float64(_LAB_DEEP)
        if adh:
            d = _pulloff_flat(kap, r)
            phi_po = d["phi_min"]
            lab_lo = _ref._where(d["interior"], d["lab_min"], lab_lo)
    else:
        lab_lo = np.full(F.shape, _LAB_DEEP)
        phi_po = np.zeros(F.shape)
        if adh.any():
            d = _pulloff_flat(kap[adh], r[adh])
            phi_po[adh] = d["phi_min"]
            lab_lo[adh] = np.where(d["interior"], d["lab_min"], _LAB_DEEP)
    below = adh & (F < (np.pi / 2) * phi_po)  # as the pull-off force is reported
    nonpos = ~adh & (phi_t <= 0)
    missing = below | nonpos
    # without adhesion the load is Hertz's, Phi = abar^2, down to any width: start the
    # bracket below the width that carries the target (F = 1e-300 needs abar ~ 1e-150)
    hertz_lo = 0.5 * np.log(_ref._maximum(phi_t, 1e-300)) - 1.0
    lab_lo = _ref._where(~adh, hertz_lo, lab_lo)
    if report:
        # a load that a contact carries stands in (the values are NaN in the result)
        phi_t = _ref._where(below, phi_po, _ref._where(nonpos, 1.0, phi_t))
        return lab_lo, phi_t, missing, phi_po
    if np.any(below):
        _, at = first_point(
            below,
            F_over_Eh2=F,
            F_po=np.pi / 2 * phi_po,
            R_over_h2=rho,
            h1_over_h2=r,
            sigma0_over_E=s,
        )
        raise NoEquilibriumError(
            f"no steadily sliding contact carries F_over_Eh2={at.pop('F_over_Eh2')!r}: it is "
            f"below the pull-off force F_pulloff_over_Eh2={at.pop('F_po')!r} "
            f"({point_text(at)}); the cylinder has pulled off"
        )
    if np.any(nonpos):
        _, at = first_point(nonpos, F_over_Eh2=F, R_over_h2=rho, h1_over_h2=r)
        raise NoEquilibriumError(
            f"no contact carries F_over_Eh2={at.pop('F_over_Eh2')!r} without adhesion "
            f"(sigma0_over_E=0, {point_text(at)}): the pull-off force is 0 and the load must "
            "be > 0"
        )
    return lab_lo, phi_t, missing, phi_po


def _double_step(lab, ph, phi_t, kap, r):
    """Double abar until the load at it exceeds the target (the upper end of the bracket)."""
    lab = lab + np.log(2.0)
    ph, _, _, _ = _phi_at(lab, kap, r)
    return (lab, ph), ~(ph < phi_t)


def _load_step(lab, lo, hi, u1, u2, phi_t, pmin, kap, r):
    """One bracketed Newton step in ln abar of Phi(abar) = phi_t along the stable branch.

    Newton on ``ln(Phi - pmin) = ln(phi_t - pmin)`` (``pmin`` the load at the lower end),
    which is exact for Hertz (``Phi = abar^2``) and takes loads many decades above the
    lower end in a few steps; on ``Phi - phi_t`` where a difference is not positive.
    Also returns the u1, u2 of the closed form at the point evaluated (a done point keeps
    that point, so they belong to the returned ln abar).
    """
    where = _ref._where
    mx = _ref._maximum
    ph, dph, u1, u2 = _phi_at(lab, kap, r)
    fx = ph - phi_t
    up = fx > 0
    hi = where(up, lab, hi)
    lo = where(up, lo, lab)
    ab = np.exp(lab)
    d, dt = ph - pmin, phi_t - pmin
    logs = (d > 0) & (dt > 0)
    nxt = where(
        logs,
        lab - np.log(where(logs, d / dt, 1.0)) * d / (dph * ab),
        lab - fx / (dph * ab),
    )
    nxt = where((abs(nxt) < np.inf) & (nxt > lo) & (nxt < hi), nxt, 0.5 * (lo + hi))
    # at the noise of Phi's terms (Hertz's abar^2, the adhesive rest), relative at any scale
    ab2 = np.exp(2 * lab)
    done = (
        (abs(fx) <= 4e-16 * mx(mx(abs(phi_t), ab2), abs(ph - ab2)))
        | (abs(nxt - lab) <= 1e-15 * mx(1.0, abs(lab)))
        | (hi - lo <= 1e-15 * mx(1.0, abs(hi)))
    )
    return (where(done, lab, nxt), lo, hi, u1, u2), done


def sliding_contact_for_load(
    F_over_Eh2: ArrayLike,
    R_over_h2: ArrayLike,
    h1_over_h2: ArrayLike,
    sigma0_over_E: ArrayLike,
    *,
    tau0_over_E: ArrayLike | None = None,
    method: Literal["closed-form", "collocation"] = "closed-form",
    n: int | str = "auto",
    tol: float = 1e-12,
    on_failure: FailurePolicy = RAISE,
    **deprecated: Any,
) -> SlidingContact:
    r"""The steadily sliding contact carrying a given normal load (stable branch).

    Solves ``F(a) = F`` for the contact half-width on the branch with ``dF/da > 0`` (stable
    under load control) with the closed form, then computes the state at that width with
    ``method``; with ``tau0_over_E`` the friction force ``2 a tau0`` is reported as
    ``T_over_Eh2``. A load within 1e-12 of the zero-width load, where the stable branch
    starts at zero width, gives the zero-width state at the domain's end ``a/R = 1e-20``
    (every narrower width carries it to round-off), by the closed form under either method
    (``n_collocation`` 0; docs/sliding.md, "Loads at the zero-width end").

    Parameters
    ----------
    F_over_Eh2 : array_like
        Normal load per unit length over ``E h2``, compressive positive.
    R_over_h2, h1_over_h2, sigma0_over_E, tau0_over_E, method, n, tol
        As in :func:`sliding_contact` (the closed form by default).
    on_failure : {"raise", "report"}
        For a load below the pull-off force, or a state that misses its tolerance: raise
        :class:`~linecontact.errors.NoEquilibriumError` or
        :class:`~linecontact.errors.ConvergenceError` (``"raise"``, default), or report the
        point (``"report"``: below the pull-off force ``state == "no-equilibrium"``, NaN
        values (the load kept), ``converged`` and ``stable`` False; a miss flagged in
        ``converged``); README, "Conventions". Replaces both deprecated keywords,
        ``raise_on_failure`` (``False`` is ``"report"``) and ``on_no_equilibrium``.

    Returns
    -------
    SlidingContact

    Raises
    ------
    NoEquilibriumError
        If the load is below the pull-off force of steady sliding (:func:`sliding_pull_off`),
        naming it.

    Examples
    --------
    >>> r = sliding_contact_for_load(0.5, 100.0, 2.0, 0.01, tau0_over_E=0.005)
    >>> abs(r.F_over_Eh2 - 0.5) < 1e-10, bool(r.stable)
    (True, True)
    """
    F = _domain.check("F_over_Eh2", F_over_Eh2)
    rho, r, s = _check_common(R_over_h2, h1_over_h2, sigma0_over_E)
    tau = (
        np.full((), np.nan)
        if tau0_over_E is None
        else _domain.check("tau0_over_E", tau0_over_E, "friction_tau0_over_E")
    )
    _check_method(method, n, tol)
    policy = failure_policy(
        on_failure,
        where="sliding_contact_for_load",
        accepts=("raise_on_failure", "on_no_equilibrium"),
        **deprecated,
    )
    report = policy == "report"
    scalar = scalar_or_array(F, rho, r, s, tau)
    F, rho, r, s, tau = broadcast(
        F_over_Eh2=F, R_over_h2=rho, h1_over_h2=r, sigma0_over_E=s, tau0_over_E=tau
    )
    _ref._check_kappa(rho, s, "R_over_h2")
    shape = F.shape
    if scalar:  # the search runs on NumPy scalars (see reference._where)
        F, rho, r, s, tau = _ref._scalars(F, rho, r, s, tau)
    else:
        F, rho, r, s, tau = (
            np.ascontiguousarray(v, dtype=float).reshape(-1) for v in (F, rho, r, s, tau)
        )
    kap = _ref._kappa(rho, s)
    phi_t = F * (2 / np.pi)
    # as in sliding_pull_off: far from h1 = h2 the search overflows on the way; the
    # convergence check of the state found reports a failure
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        # lower end of the stable branch and its load
        lab_lo, phi_t, missing, phi_lo = _lower_end(F, rho, r, s, kap, phi_t, report)
        # upper end: where Phi exceeds the target (Hertz: Phi >= abar^2 - kappa abar sinh ...)
        lab_hi = np.log(np.sqrt(_ref._maximum(phi_t, 0.0)) + 2.0 + 2.0 * kap)
        ph_hi, _, _, _ = _phi_at(lab_hi, kap, r)
        (lab_hi, _), _ = _ref._iterate(
            _double_step, (lab_hi, ph_hi), (phi_t, kap, r), 60, done=~(ph_hi < phi_t)
        )
        # bracketed Newton in ln abar on [lab_lo, lab_hi], where Phi increases
        lab = 0.5 * (lab_lo + lab_hi)
        zero = 0.0 * lab
        (lab, _, _, u1, u2), _ = _ref._iterate(
            _load_step, (lab, lab_lo, lab_hi, zero, zero), (phi_t, phi_lo, kap, r), 200
        )
        A = np.exp(lab) * np.sqrt(2 / rho)
        # narrower than the domain of sliding_contact: the load there is the zero-width one
        # to round-off (kept at the domain's end), or the point is refused (A = 0 below).
        # Where the stable branch starts at zero width (or at a minimum within 1e-12 of the
        # zero-width load), a load that the domain's end already carries to 1e-12 is the
        # zero-width state too: the load rises like a^2 from there, so the width that Newton
        # finds for it (anywhere below ~1e-7 R) is set by the last bits of the load, which
        # differ between machines, and the collocation cannot resolve such widths. The state
        # at the domain's end is the answer on every machine (docs/sliding.md, "Loads at the
        # zero-width end").
        a_min = _domain.DOMAIN["sliding_a_over_R"][0]
        ph_f, _, u1f, u2f = _phi_at(np.log(a_min * np.sqrt(rho / 2)), kap, r)
        scale = _ref._maximum(abs(phi_t), abs(phi_lo))
        ok = abs(ph_f - phi_t) <= 1e-12 * scale
        zero_end = (s > 0) & (abs(ph_f - phi_lo) <= 1e-12 * scale)
        narrow = ((A < a_min) | (ok & zero_end)) & ~missing
        if np.any(narrow):
            where = _ref._where
            # (without adhesion the width found is Hertz's and is said; else it is < a_min)
            A = where(narrow, where(ok, a_min, where(s == 0, A, 0.0)), A)
            u1, u2 = where(narrow, u1f, u1), where(narrow, u2f, u2)
        if not scalar or method != "closed-form":  # the collocation works on arrays
            A, rho, r, s, tau, u1, u2, F, missing = (
                np.reshape(v, -1) for v in (A, rho, r, s, tau, u1, u2, F, missing)
            )
    _domain.check_widths(
        np.where(missing, np.nan, A), F, "F_over_Eh2", "sliding_a_over_R", narrow=True
    )
    _ref._warn_wide(np.where(missing, np.nan, A))
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # see sliding_contact
        if method == "closed-form":
            dd = _solve_flat(A, rho, r, s, method, n, tol, u_guess=(u1, u2))
        else:
            # the zero-width states (A at the domain's end, above) are the closed form's:
            # no collocation resolves a contact 1e20 times narrower than its adhesive zones
            dd = _solve_split(A, rho, r, s, n, tol, (A <= a_min) & (s > 0), (u1, u2))
        return _pack(
            dd,
            A,
            rho,
            r,
            s,
            tau,
            method,
            shape,
            scalar,
            policy,
            "sliding_contact_for_load",
            missing,
            F,
        )
