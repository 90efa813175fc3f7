r"""A wire dragged at its midpoint on its substrate: the elastica under friction.

A straight wire of length :math:`2l` and bending stiffness :math:`EI` lies on a substrate
and is dragged at its midpoint, sideways, at a steady speed. Every element moves with the
midpoint (a rigid translation in the steady state), so kinetic friction acts on each as the
same dead load, :math:`f` per unit length against the motion. By symmetry each half is a
cantilever clamped at the midpoint (its tangent there along the wire's axis) and free at
its end.

**Equations.** With :math:`\sigma` the arc length from the midpoint and :math:`\theta` the
angle of the tangent to the axis, the loads on the part beyond :math:`\sigma` are the
friction :math:`-f(l - \sigma)\hat y` (the drag is along :math:`+\hat y`), so the bending
moment :math:`M = EI\theta'` obeys :math:`M' = f(l - \sigma)\cos\theta` and, over the
groups :math:`u = \sigma/l`, :math:`\Lambda = f l^3/EI`,

.. math::

    \theta''(u) = \Lambda\,(1 - u)\cos\theta, \qquad \theta(0) = 0, \quad \theta'(1) = 0,

:math:`x' = \cos\theta`, :math:`y' = \sin\theta` (over :math:`l`). At small :math:`\Lambda`
(small slopes): :math:`\theta'(0) = -\Lambda/2` (the curvature at the midpoint
:math:`f l^2/(2EI)`) and the end lags behind the midpoint by :math:`\Lambda/8`
(:math:`f l^4/(8EI)`, the cantilever under a uniform load).

**Solution.** Shooting from the midpoint on its curvature :math:`\kappa_0 = \theta'(0)`:
the equation and its sensitivity to :math:`\kappa_0` integrated together by the classical
Runge--Kutta method on a uniform grid (error :math:`O(h^4)`; 2048 steps by default), Newton
on :math:`\theta'(1) = 0`, all points at once (arrays of :math:`\Lambda`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import check_array
from ..errors import ConvergenceError, ParameterError
from ..results import Result

__all__ = ["DraggedWire", "dragged_wire"]

#: The friction group's largest value solved (the free end then turned by about 80 degrees).
LAMBDA_MAX = 60.0
_TOL = 1e-13
_MAXIT = 40
#: The continuation's step in the friction group.
_RUNG = 2.0


@dataclass(frozen=True)
class DraggedWire(Result):
    r"""The shape of a wire dragged at its midpoint (one half, from the midpoint out).

    Attributes
    ----------
    friction_group : ndarray
        :math:`\Lambda = f l^3/EI` [-].
    end_lag_over_l : ndarray
        How far the free end lags behind the midpoint, along the drag [:math:`l`].
    end_shortening_over_l : ndarray
        How much nearer the midpoint the free end is along the wire's axis, :math:`1 - x(1)`
        [:math:`l`].
    end_angle : ndarray
        The tangent's angle at the free end [rad] (negative: turned back, against the drag).
    midpoint_curvature : ndarray
        :math:`\theta'(0)` [:math:`1/l`] (negative).
    u, x_over_l, y_over_l, theta : ndarray, shape (..., steps + 1)
        The arc length over :math:`l` from the midpoint, the shape and the tangent's angle.
    residual : ndarray
        :math:`|\theta'(1)|`, the free end's moment left [:math:`EI/l`].
    steps : int
        Runge--Kutta steps along the half.
    converged : ndarray of bool
    """

    inputs: ClassVar[tuple[str, ...]] = ("friction_group",)
    whole: ClassVar[tuple[str, ...]] = ("steps",)

    friction_group: NDArray | float
    end_lag_over_l: NDArray | float
    end_shortening_over_l: NDArray | float
    end_angle: NDArray | float
    midpoint_curvature: NDArray | float
    residual: NDArray | float
    converged: NDArray | bool
    u: NDArray
    x_over_l: NDArray
    y_over_l: NDArray
    theta: NDArray
    steps: int


def _rhs(u: float, s: NDArray, lam: NDArray) -> NDArray:
    """The state ``(theta, theta', x, y, d theta/d k0, d theta'/d k0)`` differentiated."""
    th, dth, _, _, g, dg = s
    c, sn = np.cos(th), np.sin(th)
    a = lam * (1.0 - u)
    return np.stack([dth, a * c, c, sn, dg, -a * sn * g])


def _shoot(k0: NDArray, lam: NDArray, steps: int, keep: bool = False):
    """The state along the half from the midpoint curvature ``k0`` (RK4, ``steps`` steps)."""
    h = 1.0 / steps
    s = np.stack([np.zeros_like(k0), k0, np.zeros_like(k0), np.zeros_like(k0)])
    s = np.concatenate([s, np.stack([np.zeros_like(k0), np.ones_like(k0)])])
    path = [s] if keep else None
    for i in range(steps):
        u = i * h
        k1 = _rhs(u, s, lam)
        k2 = _rhs(u + 0.5 * h, s + 0.5 * h * k1, lam)
        k3 = _rhs(u + 0.5 * h, s + 0.5 * h * k2, lam)
        k4 = _rhs(u + h, s + h * k3, lam)
        s = s + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
        if keep:
            path.append(s)
    return s, (np.stack(path, axis=-1) if keep else None)


def _newton(k0: NDArray, lam: NDArray, steps: int) -> tuple[NDArray, NDArray, NDArray]:
    """Newton on the free end's moment from the midpoint curvatures ``k0``."""
    res = np.full(lam.shape, np.inf)
    tol = _TOL * np.maximum(1.0, lam)
    for _ in range(_MAXIT):
        end, _ = _shoot(k0, lam, steps)
        res = np.abs(end[1])
        if np.all(res <= tol):
            break
        with np.errstate(divide="ignore", invalid="ignore"):
            dk = np.where(end[5] != 0.0, -end[1] / end[5], 0.0)
        k0 = k0 + dk
    return k0, res, res <= tol


def dragged_wire(friction_group: ArrayLike, *, steps: int = 2048) -> DraggedWire:
    r"""The shape of a wire dragged at its midpoint under uniform kinetic friction.

    Parameters
    ----------
    friction_group : array_like
        :math:`\Lambda = f l^3/EI` [-] in ``[0, LAMBDA_MAX]``: the friction per unit length
        :math:`f`, the half length :math:`l`, the bending stiffness :math:`EI`.
    steps : int, optional
        Runge--Kutta steps along the half, in ``[16, 65536]``.

    Returns
    -------
    DraggedWire
        The end's lag and shortening, the angles, the shape; arrays in, arrays out.

    Raises
    ------
    ParameterError
        An argument out of range, naming it.
    ConvergenceError
        Newton's method does not meet the free end's condition, naming the group.

    Examples
    --------
    >>> w = dragged_wire(1e-3)  # small: the cantilever's f l^4/(8 EI)
    >>> print(f"{w.end_lag_over_l / (1e-3 / 8):.6f}")
    1.000000
    """
    lam = check_array(
        "friction_group", friction_group, low_inclusive=True, high=LAMBDA_MAX, high_inclusive=True
    )
    if isinstance(steps, bool) or not isinstance(steps, (int, np.integer)):
        raise ParameterError("steps", f"steps must be an integer in [16, 65536], got {steps!r}")
    if not 16 <= steps <= 65536:
        raise ParameterError("steps", f"steps must be an integer in [16, 65536], got {steps!r}")
    flat = lam.reshape(-1)
    # continuation in the load: Newton at each of `rungs` fractions of it, from the last
    rungs = max(1, int(np.ceil(np.max(flat, initial=0.0) / _RUNG)))
    k0 = np.zeros_like(flat)
    for r in range(1, rungs + 1):
        k0, res, ok = _newton(
            k0 * r / max(r - 1, 1) if r > 1 else -flat / (2 * rungs), flat * r / rungs, steps
        )
    if not np.all(ok):
        bad = float(flat[np.flatnonzero(~ok)[0]])
        raise ConvergenceError(
            f"the dragged wire's shape did not converge at friction_group={bad!r} "
            f"(residual {float(res[~ok][0]):.3g})"
        )
    _, path = _shoot(k0, flat, steps, keep=True)
    shape = (*lam.shape, steps + 1)
    theta = path[0].reshape(shape)
    x, y = path[2].reshape(shape), path[3].reshape(shape)

    def out(v: NDArray) -> NDArray | float:
        v = v.reshape(lam.shape)
        return v.item() if v.ndim == 0 else v

    return DraggedWire(
        friction_group=out(flat),
        end_lag_over_l=out(-path[3][:, -1]),
        end_shortening_over_l=out(1.0 - path[2][:, -1]),
        end_angle=out(path[0][:, -1]),
        midpoint_curvature=out(k0),
        residual=out(res),
        converged=out(ok),
        u=np.linspace(0.0, 1.0, steps + 1),
        x_over_l=x,
        y_over_l=y,
        theta=theta,
        steps=int(steps),
    )
