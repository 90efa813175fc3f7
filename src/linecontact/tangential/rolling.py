r"""Steady rolling of a driving cylinder (paper Eqs 23--29), and Carter's solution.

The cylinder rolls along ``+x`` and drives; the leading edge :math:`d < x < a` sticks, the
trailing edge slips; the creep (rigid slip) velocity comes from the consistency condition of
the collocation. Constant friction stress :math:`\tau_0` (the paper's nano-scale law) or Coulomb
friction on the Hertz contact (Carter). Units, sign conventions and references:
:mod:`linecontact.tangential`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import FailurePolicy
from ._core import (
    _CHECK_Y,
    _LEADING,
    N_COULOMB,
    _check_matrix,
    _constant_friction,
    _ConstantStress,
    _coulomb_friction,
    _CoulombFriction,
    _Problem,
    _rounding,
    _solver,
    _tail,
    _xlogy,
)

__all__ = [
    "CoulombRolling",
    "SteadyRolling",
    "steady_rolling",
    "steady_rolling_coulomb",
]

# --------------------------------------------------------------------------------------------
# steady rolling, constant tau0 (lengths over a, stresses over tau0)


def _roll_sqrt_beta(delta):
    """T/(2 a tau0) = sqrt((1 + delta)/2)."""
    return np.sqrt((1.0 + delta) / 2.0)


def _roll_u0(delta):
    r"""u0 = arccosh((3a + d)/(a - d)) = 2 artanh(sqrt((1 + delta)/2)), stable at both ends."""
    sb = _roll_sqrt_beta(delta)
    with np.errstate(divide="ignore"):
        big = 2.0 * np.log((1.0 + sb) / np.sqrt((1.0 - delta) / 2.0))
    return np.where(sb < 0.7, 2.0 * np.arctanh(np.minimum(sb, 0.7)), big)


def _roll_creep_unit(delta):
    """creep/V over tau0/E: -(2/pi) u0 (docs/tangential.md)."""
    return -(2.0 / np.pi) * _roll_u0(delta)


def _roll_Y(delta):
    return (3.0 + delta) / (1.0 - delta)


def _roll_rhs(delta, t, split: str = "endpoint"):
    r"""Eq 27 over tau0 for tau-bar on the stick zone, at t in [-1, 1], without the creep term.

    ``"endpoint"``: q = -tau0 arccos(t)/pi + tau-bar (the split used by the library; the
    right-hand side -(1/pi) ln(2 (t + Y)) is smooth on the stick zone). ``"linear"``: the
    paper's Eq 25, q = -tau0 (1 - t)/2 + tau-bar, whose right-hand side (Eq 27, signs as in
    docs/tangential.md) has (1 -+ t) ln(1 -+ t) end-point terms: algebraic convergence.
    """
    Y = _roll_Y(delta)[..., None]
    if split == "endpoint":
        return -(1.0 / np.pi) * np.log(2.0 * (t + Y))
    return (1.0 / np.pi) * (
        _xlogy((1 - t) / 2, 1 - t) + _xlogy((1 + t) / 2, 1 + t) - 1.0 - np.log(t + Y)
    )


def _roll_solve(delta: NDArray, n: int, split: str = "endpoint"):
    s = _solver(n)
    f = _roll_rhs(delta, s.collocation_unit, split)
    return s.solve(f, extra=np.ones_like(f), values=False)


def _roll_coefficients(delta: NDArray, n: int) -> NDArray:
    return _roll_solve(delta, n).coefficients


def _roll_kernel(delta: NDArray, n: int, split: str = "endpoint") -> dict[str, NDArray]:
    sol = _roll_solve(delta, n, split)
    b = sol.coefficients
    h = (1.0 - delta) / 2.0
    # Eq 29 (sign of the integral corrected): T = (3a + d) tau0/2 - int tau-bar
    T = (3.0 + delta) / 2.0 - h * (np.pi / 2) * b[:, 0]
    lam = cast(NDArray, sol.extra)  # = -E creep/(2 tau0 V)
    res = np.max(
        np.abs(-b @ _check_matrix(n) - _roll_rhs(delta, _CHECK_Y, split) - lam[:, None]), axis=-1
    )
    f = _roll_rhs(delta, _solver(n).collocation_unit, split)
    tail = np.maximum(_tail(b), _rounding(f, lam))
    return dict(T=T, creep=-2.0 * lam, tail=tail, stick=res, cons=np.abs(sol.consistency))


def _roll_rate(delta):
    """The log source x = -a sits at t = -(3a + d)/(a - d): rate u0."""
    return _roll_u0(delta)


def _carter_solve(delta: NDArray, n: int):
    """Carter: (1/pi) int tau-bar/(s - x) = -x + lambda on d < x < a (q = -mu p + tau-bar).

    Returns the solution and the collocation points ``xs``.
    """
    s = _solver(n)
    m = (1.0 + delta) / 2.0
    h = (1.0 - delta) / 2.0
    xs = m[:, None] + h[:, None] * s.collocation_unit[None, :]
    return s.solve(-xs, extra=np.ones_like(xs), values=False), xs


def _carter_kernel(delta: NDArray, n: int) -> dict[str, NDArray]:
    sol, xs = _carter_solve(delta, n)
    m = (1.0 + delta) / 2.0
    h = (1.0 - delta) / 2.0
    b = sol.coefficients
    T = 1.0 - h * b[:, 0]
    lam = cast(NDArray, sol.extra)  # = -E creep/(2 mu p0 V); creep/V = -lam mu a/R
    xc = m[:, None] + h[:, None] * _CHECK_Y[None, :]
    res = np.max(np.abs(-b @ _check_matrix(n) + xc - lam[:, None]), axis=-1)
    tail = np.maximum(_tail(b), _rounding(xs, lam))
    return dict(T=T, creep=-lam, tail=tail, stick=res, cons=np.abs(sol.consistency))


def _carter_coefficients(delta: NDArray, n: int) -> NDArray:
    return _carter_solve(delta, n)[0].coefficients


@dataclass(frozen=True)
class SteadyRolling(_ConstantStress):
    r"""Steady rolling of a driving cylinder with constant friction stress (Eqs 23--29).

    Attributes
    ----------
    d_over_a : ndarray or float
        Start of the leading-edge stick zone :math:`d < x < a` over ``a`` (``-1``: full stick
        at :math:`T = 0`; ``nan`` under a load above full slip).
    T_over_Ea : ndarray or float
        Tractive force per unit length over ``E a`` (on the cylinder, along the rolling
        direction).
    T_over_T_full_slip : ndarray or float
        :math:`T/(2 a \tau_0)`.
    creep_over_V : ndarray or float
        :math:`(V - \omega R)/V`, negative (``nan`` when sliding: at full slip the creep is
        not fixed by a stick zone; it diverges logarithmically as :math:`d \to a`).
    tau0_over_E : ndarray or float
    state, method, n_collocation, residual_stick, residual_force, residual_consistency, \
error_estimate, converged
        As in :class:`SlidingInitiation`; ``residual_stick`` refers to Eq 27 (the slip
        gradient in the stick zone equal to the creep ratio), ``residual_consistency`` to
        the extra collocation equation that fixes the creep.
    """

    _zone = _LEADING

    creep_over_V: NDArray | float
    tau0_over_E: NDArray | float

    def traction(self, x_over_a: ArrayLike) -> NDArray:
        r"""Shear traction :math:`q/E` on the cylinder at :math:`x/a`.

        Positive along the rolling direction: :math:`\tau_0/E` in the trailing slip zone, falling
        to 0 at the leading edge. ``x_over_a`` has shape ``(m,)``; the result has shape
        ``points.shape + (m,)``.
        """
        return self._traction(x_over_a, self.tau0_over_E)

    def _stick(self, x: NDArray, dlt: NDArray) -> NDArray:
        if self.method == "closed-form":
            beta = (1 + dlt) / 2
            return (2 / np.pi) * np.arctan2(
                np.sqrt(np.clip(beta * (1 - x), 0.0, None)), np.sqrt(np.clip(x - dlt, 0.0, None))
            )
        tt, tau_bar = self._series(x, dlt, _roll_coefficients)
        # q on the cylinder = -(q on the substrate) = tau0 arccos(t)/pi - tau-bar
        return np.arccos(np.clip(tt, -1, 1)) / np.pi - tau_bar


@dataclass(frozen=True)
class CoulombRolling(_CoulombFriction):
    r"""Carter's steady rolling: Hertz pressure, Coulomb friction, driving cylinder.

    Attributes
    ----------
    d_over_a : ndarray or float
        Start of the leading-edge stick zone over ``a``; its half-width is
        :math:`a' = (a - d)/2`.
    T_over_muF : ndarray or float
        :math:`1 - (a'/a)^2`.
    T_over_Ea : ndarray or float
        :math:`(\pi/4) \mu (a/R) T/(\mu F)`.
    creep_over_V : ndarray or float
        :math:`(V - \omega R)/V = -(\mu a/R)(1 - a'/a)` (Carter), negative.
    mu, a_over_R : ndarray or float
    state, method, n_collocation, residual_stick, residual_force, residual_consistency, \
error_estimate, converged
        As in :class:`SteadyRolling` (stresses over :math:`\mu p_0`).
    """

    _zone = _LEADING

    creep_over_V: NDArray | float
    mu: NDArray | float
    a_over_R: NDArray | float

    def traction(self, x_over_a: ArrayLike) -> NDArray:
        r"""Shear traction :math:`q/E` on the cylinder at :math:`x/a` (along the rolling direction).

        :math:`\mu p_0[\sqrt{1-x^2/a^2} - (a'/a)\sqrt{1-(x-x_0)^2/a'^2}]` in the stick
        zone, :math:`x_0 = a - a'`; :math:`\mu p` in the slip zone. Shape ``points.shape + (m,)``.
        """
        return self._traction(x_over_a, self.mu, self.a_over_R)

    def _stick(self, x: NDArray, dlt: NDArray) -> NDArray:
        if self.method == "closed-form":
            xq = np.clip(x, -2.0, 2.0)  # no overflow of x*x
            m = (1 + dlt) / 2
            h = (1 - dlt) / 2
            return np.sqrt(np.clip(h * h - (xq - m) ** 2, 0.0, None))
        return self._series(x, dlt, _carter_coefficients)[1]


_ROLLING = _Problem(
    "steady_rolling",
    SteadyRolling,
    _roll_kernel,
    _roll_rate,
    lambda d: 2 * _roll_sqrt_beta(d),
    lambda d: 1 / (2 * _roll_sqrt_beta(d)),
    lambda r: 2 * r * r - 1,
    2.0,
    _LEADING,
    creep_closed=_roll_creep_unit,
    # creep/V over tau0/E = -(2/pi) u0 = -(4/pi) artanh(T/(2 a tau0)), with r = T/(2 a tau0)
    creep_of_r=lambda r: -(4 / np.pi) * np.arctanh(r),
)
_CARTER = _Problem(
    "steady_rolling_coulomb",
    CoulombRolling,
    _carter_kernel,
    lambda d: np.full(d.shape, np.inf),
    # 1 - ((1 - d)/2)^2 and its inverse, in forms that keep their relative precision at full
    # stick (d -> -1, T -> 0)
    lambda d: (1 + d) * (3 - d) / 4,
    lambda d: (1 - d) / 2,
    lambda r: -1 + 2 * r / (1 + np.sqrt(1 - r)),
    1.0,
    _LEADING,
    constant=False,
    creep_closed=lambda d: -(1 + d) / 2,
    creep_of_r=lambda r: -r / (1 + np.sqrt(1 - r)),
    n_auto=N_COULOMB,
)


def steady_rolling(
    tau0_over_E: ArrayLike,
    d_over_a: ArrayLike | None = None,
    *,
    T_over_Ea: ArrayLike | None = None,
    method: str = "closed-form",
    n: int | str = "auto",
    tol: float = 1e-12,
    on_failure: FailurePolicy = "raise",
) -> SteadyRolling:
    r"""Steady rolling of a driving cylinder with constant friction stress (Eqs 23--29).

    Conventions (module docstring): rolling along ``+x`` (leading edge :math:`x = a`), the
    cylinder drives, ``T`` is the tractive force on it; stick zone :math:`d < x < a` at the
    leading edge, slip zone :math:`-a < x < d` at the trailing edge with shear :math:`\tau_0`.

    Parameters
    ----------
    tau0_over_E : array_like
        Friction stress over the composite modulus, ``> 0``.
    d_over_a : array_like, optional
        Start of the stick zone over ``a``, in ``(-1, 1)`` (``-1``: full stick, ``1``: full
        slip).
    T_over_Ea : array_like, optional
        Tractive force per unit length over ``E a``, ``>= 0`` (exactly one of the two); at
        or above :math:`2 \tau_0/E` the contact slips entirely: a
        :class:`~linecontact.errors.NoEquilibriumError`, or ``state == "sliding"`` with
        ``on_failure="report"``.
    method, n, tol, on_failure
        As in :func:`sliding_initiation` (a load at or beyond full slip raises by default;
        ``on_failure="report"`` gives ``state == "sliding"``); the collocation solves Eq 27
        on ``(d, a)`` with the creep as the extra unknown of the consistency equation.

    Returns
    -------
    SteadyRolling

    Notes
    -----
    The stick condition (Eq 24) makes the slip gradient
    :math:`\partial(u_x^{(1)} - u_x^{(2)})/\partial x` equal to the creep ratio
    :math:`\dot C/V` in the stick zone. Writing the stick-zone traction on the substrate as
    :math:`q = -\tau_0 L(x) + \bar\tau(x)` with :math:`L(d) = 1`, :math:`L(a) = 0`
    (:math:`\bar\tau` bounded, zero at both ends), Eq 15 gives a singular integral equation
    for :math:`\bar\tau` whose consistency condition fixes :math:`\dot C/V`. Closed form:
    :math:`T = \tau_0\sqrt{2a(a + d)}`,
    :math:`\dot C/V = -(2\tau_0/(\pi E))\operatorname{arccosh}((3a + d)/(a - d))`.

    Examples
    --------
    >>> r = steady_rolling(0.01, 0.0)
    >>> round(r.T_over_Ea / 0.01, 12)      # sqrt(2 (1 + d/a))
    1.414213562373
    >>> r.creep_over_V < 0                 # the driving cylinder turns faster than it rolls
    True
    >>> abs(steady_rolling(0.01, 0.0, method="collocation").creep_over_V - r.creep_over_V) < 1e-14
    True
    """
    return _constant_friction(
        _ROLLING, tau0_over_E, d_over_a, T_over_Ea, method, n, tol, on_failure
    )


def steady_rolling_coulomb(
    mu: ArrayLike,
    a_over_R: ArrayLike,
    d_over_a: ArrayLike | None = None,
    *,
    T_over_muF: ArrayLike | None = None,
    method: str = "closed-form",
    n: int | str = "auto",
    tol: float = 1e-12,
    on_failure: FailurePolicy = "raise",
) -> CoulombRolling:
    r"""Carter's steady rolling of a driving cylinder (Hertz pressure, Coulomb friction).

    Conventions as in :func:`steady_rolling`. Stick zone :math:`d < x < a` of half-width
    :math:`a' = (a - d)/2` centred at :math:`x_0 = a - a'`.

    Parameters
    ----------
    mu, a_over_R : array_like
        As in :func:`sliding_initiation_coulomb`.
    d_over_a : array_like, optional
        Start of the stick zone over ``a``, in ``(-1, 1)``.
    T_over_muF : array_like, optional
        Tractive force over :math:`\mu F`, :math:`\ge 0` (exactly one of the two); at
        :math:`\ge 1` it slides.
    method, n, tol, on_failure
        As in :func:`steady_rolling`; with :math:`q = -\mu p + \bar\tau` on the stick zone
        the equation for :math:`\bar\tau` is
        :math:`\frac1\pi\int_d^a\frac{\bar\tau\,d\xi}{\xi - x} = -\mu p_0 x/a
        - E\dot C/(2V)`, its consistency condition giving the creep.

    Returns
    -------
    CoulombRolling

    Examples
    --------
    >>> r = steady_rolling_coulomb(0.3, 0.01, 0.0)   # a' = a/2
    >>> round(r.T_over_muF, 12), round(r.creep_over_V / (0.3 * 0.01), 12)
    (0.75, -0.5)
    """
    return _coulomb_friction(
        _CARTER, mu, a_over_R, d_over_a, T_over_muF, method, n, tol, on_failure
    )
