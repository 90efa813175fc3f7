r"""Initiation of sliding of the line contact (paper Eqs 15--17), and Cattaneo--Mindlin.

A tangential force ``T`` grows on a contact of half-width ``a``; the central zone
``|x| < d`` sticks, the edges slip. Constant friction stress ``tau0`` (the paper's
nano-scale law) or Coulomb friction on the Hertz contact (the macro-scale counterpart).
Units, sign conventions and references: :mod:`linecontact.tangential`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import FailurePolicy
from ..sie import _log_moment_vector
from ._core import (
    _CENTRED,
    _CHECK_Y,
    _SLIDING,
    _STICK,
    N_COULOMB,
    _check_matrix,
    _constant_friction,
    _ConstantStress,
    _coulomb_friction,
    _CoulombFriction,
    _Problem,
    _solver,
    _tail,
    _xlogy,
)

__all__ = [
    "CoulombSlidingInitiation",
    "SlidingInitiation",
    "sliding_initiation",
    "sliding_initiation_coulomb",
]

# --------------------------------------------------------------------------------------------
# initiation of sliding, constant tau0 (lengths over a, stresses over tau0)


def _init_T(delta):
    """T/(a tau0) of Eq 17 in closed form: 2 sqrt(1 - delta^2)."""
    return 2.0 * np.sqrt((1.0 - delta) * (1.0 + delta))


def _init_delta(r):
    """Stick-zone half-width d/a for T/(2 a tau0) = r in [0, 1]."""
    return np.sqrt((1.0 - r) * (1.0 + r))


def _init_rhs(delta, t):
    """Eq 16 over tau0 on the stick zone, at t = x/d: (1/pi) ln((a - x)/(a + x))."""
    return -(2.0 / np.pi) * np.arctanh(delta[..., None] * t)


def _init_solve(delta: NDArray, n: int):
    s = _solver(n)
    return s.solve(_init_rhs(delta, s.collocation_unit), values=False)


def _init_kernel(delta: NDArray, n: int) -> dict[str, NDArray]:
    sol = _init_solve(delta, n)
    b = sol.coefficients
    # Eq 17: T = 2 a tau0 - int tau; the bounded solution's resultant is d (pi/2) b_0
    T = 2.0 - delta * (np.pi / 2) * b[:, 0]
    res = np.max(np.abs(-b @ _check_matrix(n) - _init_rhs(delta, _CHECK_Y)), axis=-1)
    return dict(T=T, tail=_tail(b), stick=res, cons=np.abs(sol.consistency))


def _init_rate(delta):
    """Convergence rate: the log sources x = +-a sit at t = +-a/d."""
    # arccosh(1/delta) = ln((1 + sqrt(1 - delta^2))/delta), without overflow for tiny delta
    k = np.sqrt((1 - delta) * (1 + delta))
    safe = np.where(delta > 0, delta, 1.0)
    return np.where(delta > 0, np.log1p(k) - np.log(safe), np.inf)


def _init_coefficients(delta: NDArray, n: int) -> NDArray:
    return _init_solve(delta, n).coefficients


def _G(x):
    """(1 + x) ln(1 + x) + (1 - x) ln(1 - x): the antiderivative of ln((1+x)/(1-x))."""
    return _xlogy(1 + x, 1 + x) + _xlogy(1 - x, 1 - x)


def _init_slip_closed(x, delta):
    r"""The slip s/a over (4 tau0/(pi E)) for delta <= x <= 1 (docs/tangential.md, Eq T6).

    S = k ln(x + r) - ln(x k + r) + (1 - k) ln(delta) + ((1 - x)/2) ln(1 - x^2) + x ln(k + r)
    with k = sqrt(1 - delta^2), r = sqrt(x^2 - delta^2); written so that delta -> 0 is
    stable (the first three terms then cancel exactly).
    """
    k = np.sqrt((1 - delta) * (1 + delta))
    r = np.sqrt(np.clip((x - delta) * (x + delta), 0.0, None))
    with np.errstate(divide="ignore", invalid="ignore"):
        head = k * np.log(x + r) - np.log(x * k + r) + _xlogy(delta * delta / (1 + k), delta)
    head = np.where(delta > 0, head, 0.0)
    return head + _xlogy((1 - x) / 2, (1 - x) * (1 + x)) + x * np.log(k + r)


# --------------------------------------------------------------------------------------------
# Coulomb counterparts (lengths over a, stresses over mu p0)


def _cm_solve(delta: NDArray, n: int):
    """Cattaneo--Mindlin: (1/pi) int tau/(s - x) = (mu/pi) int p/(s - x) = -x on |x| < d."""
    s = _solver(n)
    return s.solve(-delta[:, None] * s.collocation_unit[None, :], values=False)


def _cm_kernel(delta: NDArray, n: int) -> dict[str, NDArray]:
    sol = _cm_solve(delta, n)
    b = sol.coefficients
    # T/(mu F) = 1 - int tau / (mu p0 a pi/2)
    T = 1.0 - delta * b[:, 0]
    res = np.max(np.abs(-b @ _check_matrix(n) + delta[:, None] * _CHECK_Y), axis=-1)
    return dict(T=T, tail=_tail(b), stick=res, cons=np.abs(sol.consistency))


def _cm_coefficients(delta: NDArray, n: int) -> NDArray:
    return _cm_solve(delta, n).coefficients


@dataclass(frozen=True)
class SlidingInitiation(_ConstantStress):
    r"""Initiation of sliding with constant friction stress ``tau0`` (Eqs 15--17).

    Attributes
    ----------
    d_over_a : ndarray or float
        Half-width of the central stick zone over ``a`` (``nan`` when sliding under a given
        load above full slip; ``1`` at :math:`T = 0`).
    T_over_Ea : ndarray or float
        Tangential force per unit length over ``E a``.
    T_over_T_full_slip : ndarray or float
        :math:`T/(2 a \tau_0)`.
    tau0_over_E : ndarray or float
        Friction stress over the composite modulus.
    state : ndarray of str or str
        ``"stick"`` (:math:`T = 0`), ``"stick-slip"`` or ``"sliding"``
        (:math:`T \ge 2 a \tau_0`).
    method : str
        ``"closed-form"`` or ``"collocation"``.
    n_collocation : ndarray or int
        Nodes used per point (0: closed form, or nothing to solve).
    residual_stick : ndarray or float
        Largest residual of the stick condition (Eq 16) at 16 points of the stick zone other
        than the collocation points, over ``tau0`` (0 for the closed form).
    residual_force : ndarray or float
        :math:`|T(d) - T|/(2 a \tau_0)` for a given ``T`` (Eq 17 solved for ``d``); 0 when ``d``
        is given.
    residual_consistency : ndarray or float
        Collocation consistency residual (zero by symmetry).
    error_estimate : ndarray or float
        Chebyshev tail of the solution over its largest coefficient (or over ``tau0`` when
        the solution is smaller), 0 for the closed form.
    converged : ndarray or bool
        Every tolerance met.
    """

    _zone = _CENTRED

    tau0_over_E: NDArray | float

    def traction(self, x_over_a: ArrayLike) -> NDArray:
        r"""Shear traction :math:`q/E` at :math:`x/a`, positive along ``T``.

        ``x_over_a`` has shape ``(m,)``; the result has shape ``points.shape + (m,)``: the
        stick-zone traction of the method used for :math:`|x| < d`, :math:`\tau_0/E` for
        :math:`d \le |x| \le a` (everywhere when sliding), zero outside the contact.
        """
        return self._traction(x_over_a, self.tau0_over_E)

    def _stick(self, x: NDArray, dlt: NDArray) -> NDArray:
        if self.method == "closed-form":
            k = np.sqrt(np.clip((1 - dlt) * (1 + dlt), 0.0, None))
            return (2 / np.pi) * np.arctan2(k, np.sqrt(np.clip(dlt * dlt - x * x, 0.0, None)))
        return 1.0 - self._series(x, dlt, _init_coefficients)[1]

    def slip(self, x_over_a: ArrayLike) -> NDArray:
        r"""Slip :math:`s/a` at :math:`x/a` (shape ``points.shape + (m,)``).

        The slip is the cylinder's tangential displacement relative to the substrate in the
        slip zones, measured from the nearer end of the stick zone: zero in the stick zone,
        positive (along ``T``) and growing towards the contact edges in the slip zones;
        ``nan`` outside the contact and for sliding points (the slip then grows without
        bound). Closed form (``docs/tangential.md``) or, for the collocation
        method, :math:`s = (2/(\pi E))[\tau_0 \int_d^x \ln\frac{a+x'}{a-x'}dx' -
        \int \tau(\xi)\ln|x-\xi|\,d\xi\,|_d^x]` with the logarithmic moments of the
        collocation solution (exact for its polynomial part).
        """
        x, dlt, st = self._points(x_over_a)
        t0 = np.asarray(self.tau0_over_E, dtype=float)[..., None]
        ax = np.abs(x)
        xs = np.clip(ax, dlt, 1.0)
        if self.method == "closed-form":
            val = (4 / np.pi) * _init_slip_closed(xs, np.where(np.isfinite(dlt), dlt, 0.0))
        else:
            val = self._slip_collocation(xs)
        sl = np.where(ax <= dlt, 0.0, val)
        sl = np.where(ax > 1.0, np.nan, sl)
        sl = np.where(st == _SLIDING, np.nan, sl)
        sl = np.where(st == _STICK, np.where(ax > 1.0, np.nan, 0.0), sl)
        return t0 * sl

    def _slip_collocation(self, xs: NDArray) -> NDArray:
        dshape = np.shape(self.d_over_a)
        dd = np.atleast_1d(np.asarray(self.d_over_a, dtype=float)).reshape(-1)
        nn = np.atleast_1d(np.asarray(self.n_collocation)).reshape(-1)
        X = np.broadcast_to(xs, dshape + xs.shape[-1:]).reshape(dd.size, -1)
        val = np.full(X.shape, np.nan)
        for n in np.unique(nn[nn > 0]):
            sel = nn == n
            d = dd[sel]
            b = _init_coefficients(d, int(n))

            def logmom(y, d=d, b=b, n=n):
                # int_{-d}^{d} tau(s) ln|y - s| ds over tau0, y of shape (p, m)
                mu = _log_moment_vector(y / d[:, None], int(n))
                return d[:, None] * (
                    np.einsum("pj,pmj->pm", b, mu) + np.log(d)[:, None] * (np.pi / 2) * b[:, :1]
                )

            Xs = X[sel]
            dm = np.broadcast_to(d[:, None], Xs.shape)
            lm = logmom(Xs) - logmom(dm)
            val[sel] = (2 / np.pi) * (_G(Xs) - _G(dm) - lm)
        return val.reshape(dshape + xs.shape[-1:])


@dataclass(frozen=True)
class CoulombSlidingInitiation(_CoulombFriction):
    r"""Cattaneo--Mindlin line contact: Hertz pressure, Coulomb friction ``mu``.

    Attributes
    ----------
    d_over_a : ndarray or float
        Half-width of the central stick zone over ``a``.
    T_over_muF : ndarray or float
        :math:`T/(\mu F) = 1 - (d/a)^2` (also in ``T_over_T_full_slip``).
    T_over_Ea : ndarray or float
        :math:`(\pi/4) \mu (a/R) T/(\mu F)`.
    mu, a_over_R : ndarray or float
        Friction coefficient and Hertz half-width over the radius.
    state, method, n_collocation, residual_stick, residual_force, residual_consistency, \
error_estimate, converged
        As in :class:`SlidingInitiation` (stresses over :math:`\mu p_0`).
    """

    _zone = _CENTRED

    mu: NDArray | float
    a_over_R: NDArray | float

    def traction(self, x_over_a: ArrayLike) -> NDArray:
        r"""Shear traction :math:`q/E` at :math:`x/a` (shape ``points.shape + (m,)``).

        :math:`\mu p` in the slip zones,
        :math:`\mu p_0[\sqrt{1-x^2/a^2} - (d/a)\sqrt{1-x^2/d^2}]` in the stick zone.
        """
        return self._traction(x_over_a, self.mu, self.a_over_R)

    def _stick(self, x: NDArray, dlt: NDArray) -> NDArray:
        if self.method == "closed-form":
            xq = np.clip(x, -2.0, 2.0)  # no overflow of x*x
            return np.sqrt(np.clip(dlt * dlt - xq * xq, 0.0, None))
        return self._series(x, dlt, _cm_coefficients)[1]


_INITIATION = _Problem(
    "sliding_initiation",
    SlidingInitiation,
    _init_kernel,
    _init_rate,
    _init_T,
    lambda d: -2 * d / np.sqrt((1 - d) * (1 + d)),
    _init_delta,
    2.0,
    _CENTRED,
)
_CATTANEO_MINDLIN = _Problem(
    "sliding_initiation_coulomb",
    CoulombSlidingInitiation,
    _cm_kernel,
    lambda d: np.full(d.shape, np.inf),
    lambda d: (1 - d) * (1 + d),  # 1 - d^2, without cancellation as d -> 1 (T -> 0)
    lambda d: -2 * d,
    lambda r: np.sqrt(1 - r),
    1.0,
    _CENTRED,
    constant=False,
    n_auto=N_COULOMB,
)


def sliding_initiation(
    tau0_over_E: ArrayLike,
    d_over_a: ArrayLike | None = None,
    *,
    T_over_Ea: ArrayLike | None = None,
    method: str = "closed-form",
    n: int | str = "auto",
    tol: float = 1e-12,
    on_failure: FailurePolicy = "raise",
) -> SlidingInitiation:
    r"""Initiation of sliding with constant friction stress ``tau0`` (paper Eqs 15--17).

    A tangential force ``T`` grows on a contact of half-width ``a`` (from the normal
    problem, unchanged by ``T`` since :math:`B = 0`); the central zone :math:`|x| < d` sticks, the
    edges :math:`d < |x| < a` slip under the shear stress :math:`\tau_0`.

    Parameters
    ----------
    tau0_over_E : array_like
        Friction stress over the composite modulus, ``> 0``.
    d_over_a : array_like, optional
        Stick-zone half-width over ``a``, in ``[0, 1)`` (``0``: onset of full sliding).
    T_over_Ea : array_like, optional
        Tangential force per unit length over ``E a``, ``>= 0``; give exactly one of
        ``d_over_a`` and ``T_over_Ea``. At or above :math:`2 \tau_0/E` the cylinder slides.
    method : {"closed-form", "collocation"}
        Closed form, or Gauss--Chebyshev collocation of Eq 16 (for a given ``T``, Eq 17 is
        then solved for ``d`` by Newton's method on the collocation solution).
    n : int or "auto"
        Collocation nodes (``"auto"``: chosen per point for ``tol``).
    tol : float
        Target discretisation error of the collocation solution.
    on_failure : {"raise", "report"}
        For a given ``T`` at or above full slip, and a collocation point that misses its
        tolerance: raise :class:`~linecontact.errors.NoEquilibriumError` and
        :class:`~linecontact.errors.ConvergenceError` (``"raise"``, default), or report
        the point, ``state == "sliding"`` (``d_over_a`` NaN, or 0 for ``d_over_a=0``) and
        ``converged`` False for a miss (``"report"``); README, "Conventions". **Changed**
        after 0.2.0: a load at or beyond full slip raises by default (the deleted
        ``on_sliding`` defaulted to ``"report"``); pass ``on_failure="report"`` for the
        sliding state.

    Returns
    -------
    SlidingInitiation
        Inputs broadcast together; scalars in, scalars out.

    Notes
    -----
    With :math:`p_x = \tau_0 - \tau(x)` and zero relative slip gradient in the stick zone,
    Eq 15 gives Eq 16, :math:`\frac{1}{\pi}\int_{-d}^{d}\frac{\tau(\xi)\,d\xi}{\xi - x}
    = \frac{\tau_0}{\pi}\ln\frac{a-x}{a+x}`, bounded at :math:`\pm d`: the Dugdale pair of
    the normal problem, :math:`\tau = (2\tau_0/\pi)\arctan\sqrt{(d^2-x^2)/(a^2-d^2)}`, and
    Eq 17 gives :math:`T = 2\tau_0\sqrt{a^2 - d^2}`.

    Examples
    --------
    >>> r = sliding_initiation(0.01, 0.6)
    >>> round(r.T_over_Ea, 12)          # 2 (tau0/E) sqrt(1 - 0.36)
    0.016
    >>> c = sliding_initiation(0.01, 0.6, method="collocation")
    >>> abs(c.T_over_Ea - r.T_over_Ea) < 1e-14
    True
    >>> sliding_initiation(0.01, T_over_Ea=0.03, on_failure="report").state
    'sliding'
    """
    return _constant_friction(
        _INITIATION, tau0_over_E, d_over_a, T_over_Ea, method, n, tol, on_failure
    )


def sliding_initiation_coulomb(
    mu: ArrayLike,
    a_over_R: ArrayLike,
    d_over_a: ArrayLike | None = None,
    *,
    T_over_muF: ArrayLike | None = None,
    method: str = "closed-form",
    n: int | str = "auto",
    tol: float = 1e-12,
    on_failure: FailurePolicy = "raise",
) -> CoulombSlidingInitiation:
    r"""Cattaneo--Mindlin initiation of sliding of a Hertz line contact (Coulomb friction).

    The macro-scale counterpart of :func:`sliding_initiation`: Hertz pressure
    :math:`p = p_0\sqrt{1 - x^2/a^2}`, :math:`p_0 = E a/(2R)`, shear :math:`\mu p` in the slip
    zones :math:`d < |x| < a`.

    Parameters
    ----------
    mu : array_like
        Coefficient of friction, ``> 0``.
    a_over_R : array_like
        Hertz contact half-width over the radius, ``> 0`` (it sets ``p0`` and ``F``).
    d_over_a : array_like, optional
        Stick-zone half-width over ``a``, in ``[0, 1)``.
    T_over_muF : array_like, optional
        Tangential force over :math:`\mu F`, :math:`\ge 0` (exactly one of the two); at
        :math:`\ge 1` it slides.
    method, n, tol, on_failure
        As in :func:`sliding_initiation` (a load at or beyond full slip raises by default);
        the collocation solves
        :math:`\frac1\pi\int_{-d}^{d}\frac{\tau\,d\xi}{\xi-x} = \frac{\mu}{\pi}
        \int_{-a}^{a}\frac{p\,d\xi}{\xi-x} = -\mu p_0 x/a` for the correction ``tau`` with
        :math:`q = \mu p - \tau` in the stick zone (``n`` defaults to :data:`N_COULOMB`).

    Returns
    -------
    CoulombSlidingInitiation

    Examples
    --------
    >>> r = sliding_initiation_coulomb(0.3, 0.01, 0.5)
    >>> round(r.T_over_muF, 12)
    0.75
    """
    return _coulomb_friction(
        _CATTANEO_MINDLIN, mu, a_over_R, d_over_a, T_over_muF, method, n, tol, on_failure
    )
