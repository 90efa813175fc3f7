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

**Solution.** Chebyshev collocation on the Lobatto points of :math:`[0, 1]` (the solution
is smooth: spectral convergence), Newton's method with the exact Jacobian, continued in
:math:`\Lambda` by steps of at most 2 from the straight wire; all points at once (batched
linear solves). The shape by integrating the interpolant of :math:`\cos\theta`,
:math:`\sin\theta` exactly.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np
from numpy.polynomial import chebyshev as _cheb
from numpy.typing import ArrayLike, NDArray

from .._validation import check_array
from ..errors import ConvergenceError, ParameterError
from ..results import Result

__all__ = ["LAMBDA_MAX", "DraggedWire", "dragged_wire"]

#: The friction group's largest value solved (the free end then turned back by about 88
#: degrees).
LAMBDA_MAX = 60.0
_TOL = 1e-12
_MAXIT = 30
#: The continuation's largest step in the friction group.
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
    residual : ndarray
        The largest collocation residual [:math:`1`] (the rounding of the differentiation
        matrices, about :math:`10^{-16}` times the nodes to the fourth power).
    converged : ndarray of bool
    u, x_over_l, y_over_l, theta : ndarray, shape (..., nodes)
        The arc length over :math:`l` from the midpoint (the collocation points), the shape
        and the tangent's angle there.
    nodes : int
        Collocation points along the half.
    """

    inputs: ClassVar[tuple[str, ...]] = ("friction_group",)
    whole: ClassVar[tuple[str, ...]] = ("nodes",)

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
    nodes: int


@functools.cache
def _grid(n: int) -> tuple[NDArray, NDArray, NDArray]:
    """Lobatto points of ``[0, 1]`` (``n + 1``, from 0) and the first and second derivative."""
    k = np.arange(n + 1)
    t = -np.cos(np.pi * k / n)  # -1 .. 1
    c = np.where((k == 0) | (k == n), 2.0, 1.0) * (-1.0) ** k
    dt = t[:, None] - t[None, :]
    D = np.outer(c, 1.0 / c) / (dt + np.eye(n + 1))
    D -= np.diag(D.sum(axis=1))
    D *= 2.0  # d/du = 2 d/dt on u = (t + 1)/2
    return (t + 1.0) / 2.0, D, D @ D


def _newton(theta: NDArray, lam: NDArray, n: int) -> tuple[NDArray, NDArray, NDArray]:
    """Newton on the collocation equations from ``theta`` (rows: points).

    ``(theta, residual, converged)``: converged where the last step moved no angle by more
    than :data:`_TOL` (the residual itself carries the differentiation matrices' rounding,
    about :math:`10^{-16} n^4`).
    """
    u, D, D2 = _grid(n)
    load = lam[:, None] * (1.0 - u)[None, :]
    step = np.full(lam.shape, np.inf)
    for _ in range(_MAXIT):
        r = theta @ D2.T - load * np.cos(theta)
        J = np.broadcast_to(D2, (lam.size, n + 1, n + 1)).copy()
        J += np.einsum("pi,ij->pij", load * np.sin(theta), np.eye(n + 1))
        r[:, 0], J[:, 0, :] = theta[:, 0], np.eye(n + 1)[0]  # theta(0) = 0
        r[:, -1], J[:, -1, :] = theta @ D[-1], D[-1]  # theta'(1) = 0
        d = np.linalg.solve(J, r[..., None])[..., 0]
        theta = theta - d
        step = np.max(np.abs(d), axis=1)
        if np.all(step <= _TOL):
            break
    r = theta @ D2.T - load * np.cos(theta)
    r[:, 0], r[:, -1] = theta[:, 0], theta @ D[-1]
    return theta, np.max(np.abs(r), axis=1), step <= _TOL


def dragged_wire(friction_group: ArrayLike, *, nodes: int = 48) -> DraggedWire:
    r"""The shape of a wire dragged at its midpoint under uniform kinetic friction.

    Parameters
    ----------
    friction_group : array_like
        :math:`\Lambda = f l^3/EI` [-] in ``[0, LAMBDA_MAX]``: the friction per unit length
        :math:`f`, the half length :math:`l`, the bending stiffness :math:`EI`.
    nodes : int, optional
        Collocation points along the half, in ``[8, 512]``.

    Returns
    -------
    DraggedWire
        The end's lag and shortening, the angles, the shape; arrays in, arrays out.

    Raises
    ------
    ParameterError
        An argument out of range, naming it.
    ConvergenceError
        Newton's method does not meet the equations, naming the group.

    Examples
    --------
    >>> w = dragged_wire(1e-3)  # small: the cantilever's f l^4/(8 EI)
    >>> print(f"{w.end_lag_over_l / (1e-3 / 8):.6f}")
    1.000000
    """
    lam = check_array(
        "friction_group", friction_group, low_inclusive=True, high=LAMBDA_MAX, high_inclusive=True
    )
    if isinstance(nodes, bool) or not isinstance(nodes, (int, np.integer)) or not 8 <= nodes <= 512:
        raise ParameterError("nodes", f"nodes must be an integer in [8, 512], got {nodes!r}")
    n = int(nodes)
    u, D, _ = _grid(n)
    flat = lam.reshape(-1)
    rungs = max(1, int(np.ceil(np.max(flat, initial=0.0) / _RUNG)))
    theta = np.zeros((flat.size, n + 1))
    res, ok = np.zeros(flat.shape), np.ones(flat.shape, bool)
    for r in range(1, rungs + 1):
        theta, res, ok = _newton(theta, flat * (r / rungs), n)
    if not np.all(ok):
        bad = int(np.flatnonzero(~ok)[0])
        raise ConvergenceError(
            f"the dragged wire's shape did not converge at friction_group={float(flat[bad])!r} "
            f"(residual {float(res[bad]):.3g})"
        )
    # the shape: the interpolants of cos and sin integrated from the midpoint
    t = 2.0 * u - 1.0
    cs = _cheb.chebfit(t, np.concatenate([np.cos(theta), np.sin(theta)]).T, n)
    ints = _cheb.chebint(cs, lbnd=-1.0) / 2.0  # du = dt/2
    xy = _cheb.chebval(t, ints)  # (2 points, nodes)
    x, y = xy[: flat.size], xy[flat.size :]
    shape = (*lam.shape, n + 1)

    def out(v: NDArray) -> Any:
        v = v.reshape(lam.shape)
        return v.item() if v.ndim == 0 else v

    return DraggedWire(
        friction_group=out(flat),
        end_lag_over_l=out(0.0 - y[:, -1]),
        end_shortening_over_l=out(1.0 - x[:, -1]),
        end_angle=out(theta[:, -1]),
        midpoint_curvature=out(theta @ D[0]),
        residual=out(res),
        converged=out(ok),
        u=u,
        x_over_l=x.reshape(shape),
        y_over_l=y.reshape(shape),
        theta=theta.reshape(shape),
        nodes=n,
    )
