r"""A wire held in a bent shape by static friction normal to it: the Kirchhoff rod.

A wire lies bent on its substrate, at rest, with no external load and free ends. Only
friction holds it: a distributed load :math:`q(s)` per unit length, normal to the wire
(static friction can take any value up to its limit; the part of it along the wire is
left out here). With :math:`s` the arc length, :math:`\theta` the tangent's angle,
:math:`\kappa = \theta'` the curvature, the internal force :math:`N\hat t + Q\hat n` (its
components along the tangent and the normal :math:`\hat n = \hat z\times\hat t`) and the
moment :math:`M`, the balances of force and moment of an element are (Kirchhoff; Antman,
*Nonlinear Problems of Elasticity*, ch. 4, doi:10.1007/0-387-27649-1)

.. math::

    N' = \kappa Q, \qquad Q' + \kappa N + q = 0, \qquad M' + Q = 0, \qquad M = EI\kappa .

Then :math:`Q = -EI\kappa'`, :math:`N' = -EI\kappa\kappa'`, and with a free end
(:math:`N = M = 0`) the first integral :math:`N = -EI\kappa^2/2`; the normal balance gives
the exact inversion of a shape to the friction that holds it,

.. math::

    q = EI\,\bigl(\kappa'' + \tfrac12 \kappa^3\bigr),

and its small-slope form :math:`q \approx EI\kappa''` (:math:`\approx EI\,y''''`).

- :func:`normal_friction_from_curvature` -- the inversion, exact and small-slope.
- :func:`static_wire` -- the forward problem: given :math:`q(s)` and :math:`EI`, the rod
  integrated from a free end (:math:`N = Q = M = 0` at :math:`s = 0`) by an adaptive
  Runge--Kutta method of order 8 (SciPy's DOP853, imported when called), in the groups
  :math:`u = s/L`, :math:`qL^3/EI`, :math:`N L^2/EI`, :math:`M L/EI`; the force and moment
  left at the far end say whether the given load holds a wire free at both ends.

SI units throughout: lengths [m], :math:`q` [N/m], :math:`EI` [N m^2].
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import check_array, scalar
from ..errors import ConvergenceError, ParameterError
from ..results import Result

__all__ = [
    "NormalFriction",
    "StaticWire",
    "normal_friction_from_curvature",
    "static_wire",
]


def _out(v: NDArray) -> Any:
    return v.item() if v.ndim == 0 else v


@dataclass(frozen=True)
class NormalFriction(Result):
    r"""The friction normal to a wire that holds it in its shape.

    Attributes
    ----------
    curvature : float or ndarray
        :math:`\kappa` [1/m].
    curvature_second_derivative : float or ndarray
        :math:`\kappa''` along the arc length [1/m^3].
    bending_stiffness : float or ndarray
        :math:`EI` [N m^2].
    normal_friction : float or ndarray
        :math:`q = EI(\kappa'' + \kappa^3/2)` [N/m], along the normal
        :math:`\hat z\times\hat t` (exact, free ends).
    small_slope_normal_friction : float or ndarray
        :math:`EI\kappa''` [N/m].
    """

    inputs: ClassVar[tuple[str, ...]] = (
        "curvature",
        "curvature_second_derivative",
        "bending_stiffness",
    )

    curvature: NDArray | float
    curvature_second_derivative: NDArray | float
    bending_stiffness: NDArray | float
    normal_friction: NDArray | float
    small_slope_normal_friction: NDArray | float


def normal_friction_from_curvature(
    curvature: ArrayLike, curvature_second_derivative: ArrayLike, bending_stiffness: ArrayLike
) -> NormalFriction:
    r"""The normal friction that holds a free wire in its shape, from its curvature.

    Parameters
    ----------
    curvature : array_like
        :math:`\kappa` [1/m], any sign (positive turning towards :math:`\hat z\times\hat t`).
    curvature_second_derivative : array_like
        :math:`d^2\kappa/ds^2` [1/m^3] at the same points.
    bending_stiffness : array_like
        :math:`EI` [N m^2], ``> 0`` (:func:`~linecontact.bent_wire.bending_stiffness`).

    Returns
    -------
    NormalFriction
        The exact :math:`q = EI(\kappa'' + \kappa^3/2)` and the small-slope
        :math:`EI\kappa''` [N/m]; arrays broadcast.

    Raises
    ------
    ParameterError
        A value not finite, or :math:`EI \le 0`, naming it.

    Notes
    -----
    Exact for a wire free of external loads at one end at least (the first integral
    :math:`N = -EI\kappa^2/2` takes :math:`N = \kappa = 0` there) under a load normal to
    it only; the module's docstring derives it.

    Examples
    --------
    >>> r = normal_friction_from_curvature(2.0, 0.0, 1.0)  # an arc: only the cube is left
    >>> print(r.normal_friction, r.small_slope_normal_friction)
    4.0 0.0
    """
    k = check_array("curvature", curvature, low=-np.inf, low_inclusive=True)
    k2 = check_array(
        "curvature_second_derivative", curvature_second_derivative, low=-np.inf, low_inclusive=True
    )
    ei = check_array("bending_stiffness", bending_stiffness)
    k, k2, ei = np.broadcast_arrays(k, k2, ei)
    return NormalFriction(
        curvature=_out(k),
        curvature_second_derivative=_out(k2),
        bending_stiffness=_out(ei),
        normal_friction=_out(ei * (k2 + 0.5 * k**3)),
        small_slope_normal_friction=_out(ei * k2),
    )


@dataclass(frozen=True)
class StaticWire(Result):
    r"""A wire under a normal load, integrated from its free end at :math:`s = 0`.

    The wire starts at the origin along :math:`+x`. Every per-point field is sampled at
    ``arc_length``.

    Attributes
    ----------
    length : float
        :math:`L` [m].
    bending_stiffness : float
        :math:`EI` [N m^2].
    arc_length : ndarray
        :math:`s` [m] from the free end.
    x, y : ndarray
        The centreline [m].
    angle : ndarray
        The tangent's angle :math:`\theta` to :math:`+x` [rad].
    curvature : ndarray
        :math:`\kappa = \theta' = M/EI` [1/m].
    axial_force, shear_force : ndarray
        :math:`N`, :math:`Q` [N]: the internal force on the part :math:`[0, s]` along the
        tangent and the normal.
    bending_moment : ndarray
        :math:`M` [N m].
    normal_load : ndarray
        :math:`q(s)` [N/m] (a piecewise-constant load: its value on the segment that starts
        at or before the point).
    end_force : float
        :math:`\sqrt{N^2 + Q^2}` at :math:`s = L` [N]: zero when the load holds a wire free
        at both ends.
    end_moment : float
        :math:`M(L)` [N m]: zero likewise.
    steps : int
        The integrator's steps over the whole length.
    rtol : float
        Its relative tolerance.
    """

    inputs: ClassVar[tuple[str, ...]] = ("length", "bending_stiffness")
    whole: ClassVar[tuple[str, ...]] = ("steps", "rtol")

    length: float
    bending_stiffness: float
    arc_length: NDArray
    x: NDArray
    y: NDArray
    angle: NDArray
    curvature: NDArray
    axial_force: NDArray
    shear_force: NDArray
    bending_moment: NDArray
    normal_load: NDArray
    end_force: float
    end_moment: float
    steps: int
    rtol: float


def _rhs(p: float, z: NDArray) -> list[float]:
    """The rod in the groups: ``z = (theta, x, y, n, q, m)``, ``p`` the load ``q L^3/EI``."""
    theta, _, _, n, qn, m = z
    return [m, np.cos(theta), np.sin(theta), m * qn, -m * n - p, -qn]


def _segments(
    normal_load: Callable[[float], float] | ArrayLike,
    length: float,
    breakpoints: ArrayLike | None,
) -> tuple[NDArray, Callable[[float], float]]:
    """The segment ends ``[0, ..., L]`` and the load as a function of ``s`` [m]."""
    if callable(normal_load):
        if breakpoints is not None:
            raise ParameterError(
                "breakpoints",
                "breakpoints are a piecewise-constant load's: give normal_load as its values",
            )
        func = normal_load

        def load(s: float) -> float:
            v = func(s)
            try:
                out = float(v)
            except (TypeError, ValueError):
                raise ParameterError(
                    "normal_load", f"normal_load(s) must return a number [N/m], got {v!r}"
                ) from None
            if not np.isfinite(out):
                raise ParameterError(
                    "normal_load", f"normal_load(s) must be finite [N/m], got {out!r} at s={s!r}"
                )
            return out

        return np.array([0.0, length]), load
    values = np.atleast_1d(check_array("normal_load", normal_load, low=-np.inf, low_inclusive=True))
    if values.ndim != 1:
        raise ParameterError(
            "normal_load",
            f"normal_load must be a callable, a number or a 1-D array of the segments' values, "
            f"got shape {values.shape}",
        )
    m = values.size
    if breakpoints is None:
        ends = np.linspace(0.0, length, m + 1)
    else:
        inner = np.atleast_1d(check_array("breakpoints", breakpoints, high=length))
        if inner.ndim != 1 or inner.size != m - 1 or np.any(np.diff(inner) <= 0):
            raise ParameterError(
                "breakpoints",
                f"breakpoints must be {m - 1} increasing arc lengths in (0, length) (one fewer "
                f"than the values of normal_load), got {inner.tolist()!r}",
            )
        ends = np.concatenate([[0.0], inner, [length]])

    def piecewise(s: float) -> float:
        i = int(np.clip(np.searchsorted(ends, s, side="right") - 1, 0, m - 1))
        return float(values[i])

    return ends, piecewise


def static_wire(
    normal_load: Callable[[float], float] | ArrayLike,
    length: float,
    bending_stiffness: float,
    *,
    breakpoints: ArrayLike | None = None,
    arc_length: ArrayLike | None = None,
    rtol: float = 1e-12,
) -> StaticWire:
    r"""The shape of a wire under a normal load, from a free end.

    Parameters
    ----------
    normal_load : callable or array_like
        :math:`q` [N/m] along the normal :math:`\hat z\times\hat t`: a function of the arc
        length ``s`` [m] (one float in, one out; smooth between the ``breakpoints``), a
        number (uniform), or the values of a piecewise-constant load on the segments
        between ``breakpoints``.
    length : float
        :math:`L` [m], ``> 0``.
    bending_stiffness : float
        :math:`EI` [N m^2], ``> 0``.
    breakpoints : array_like, optional
        The piecewise-constant load's inner segment ends [m], increasing in
        ``(0, length)``, one fewer than its values; equal segments when not given.
    arc_length : array_like, optional
        Where to sample the solution [m], in ``[0, length]``; 201 equal steps by default.
    rtol : float, optional
        The integrator's relative tolerance, in ``[1e-13, 1e-3]`` (its absolute tolerance
        a hundredth of it, in the groups).

    Returns
    -------
    StaticWire
        The shape, the curvature, the internal force and moment at ``arc_length``, and the
        force and moment left at the far end.

    Raises
    ------
    ParameterError
        An argument out of range, naming it.
    ConvergenceError
        The integrator failing.

    Notes
    -----
    The balances of the module's docstring with :math:`N = Q = M = 0` at :math:`s = 0`,
    integrated on each segment of the load (a jump of :math:`q` restarts the integrator).
    At small loads, :math:`EI y'''' = q` with :math:`y(0) = y'(0) = 0`: a uniform load
    gives :math:`y = q s^4/(24 EI)`.

    Examples
    --------
    >>> w = static_wire(1e-6, 1.0, 1.0)  # small: y(L) = q L^4 / (24 EI)
    >>> print(f"{w.y[-1] / (1e-6 / 24):.8f}")
    1.00000000
    """
    from scipy.integrate import solve_ivp

    L = scalar("length", length)
    ei = scalar("bending_stiffness", bending_stiffness)
    tol = scalar("rtol", rtol, low=1e-13, low_inclusive=True, high=1e-3, high_inclusive=True)
    ends, load = _segments(normal_load, L, breakpoints)
    if arc_length is None:
        s = np.linspace(0.0, L, 201)
    else:
        s = np.atleast_1d(
            check_array("arc_length", arc_length, low_inclusive=True, high=L, high_inclusive=True)
        )
        if s.ndim != 1:
            raise ParameterError("arc_length", f"arc_length must be 1-D, got shape {s.shape}")
    scale = L**3 / ei  # q -> p
    u_ends, u = ends / L, s / L
    z = np.zeros(6)
    out = np.empty((6, u.size))
    steps = 0
    for k in range(u_ends.size - 1):
        a, b = float(u_ends[k]), float(u_ends[k + 1])
        sol = solve_ivp(
            lambda t, y: _rhs(scale * load(t * L), y),
            (a, b),
            z,
            method="DOP853",
            rtol=tol,
            atol=tol / 100,
            dense_output=True,
        )
        if not sol.success:
            raise ConvergenceError(f"the static wire's integration failed: {sol.message}")
        steps += int(sol.t.size - 1)
        last = k == u_ends.size - 2
        here = (u >= a) & ((u <= b) if last else (u < b))
        if np.any(here):
            out[:, here] = sol.sol(u[here])
        z = sol.y[:, -1]
    theta, x, y, n, qn, m = out
    return StaticWire(
        length=L,
        bending_stiffness=ei,
        arc_length=s,
        x=x * L,
        y=y * L,
        angle=theta,
        curvature=m / L,
        axial_force=n * ei / L**2,
        shear_force=qn * ei / L**2,
        bending_moment=m * ei / L,
        normal_load=np.array([load(float(v)) for v in s]),
        end_force=float(np.hypot(z[3], z[4]) * ei / L**2),
        end_moment=float(z[5] * ei / L),
        steps=steps,
        rtol=tol,
    )
