r"""The held wire as a curve to fit: a free-free shape of a few curvature modes, fast.

A wire held at rest by static friction normal to it, its ends free (``docs/bent-wire.md``):
its curvature and the curvature's slope vanish at both ends (no moment, no shear), and the
friction that holds it is :math:`f_n = EI(\kappa'' + \kappa^3/2)`. The fit (:mod:`.fit`,
``model="held"``) takes the curvature as a few modes,

.. math::

    l\kappa(s) = \sum_{k<K} c_k\,\varphi_k(s), \qquad
    \varphi_k(s) = (1 - s^2)^2 P_k(s), \qquad s \in [-1, 1],

the arc length :math:`s` over the half-length :math:`l` from the midpoint and :math:`P_k` the
Legendre polynomials: each mode free at both ends. The angle
:math:`\theta(s) = \int_0^s l\kappa` is exact (polynomials); the point
:math:`(x, y) = \int_0^s (\cos\theta, \sin\theta)` is integrated on a uniform grid by the
corrected trapezoidal rule (each integrand's derivative known: fourth order), and both,
with their derivatives in the :math:`c_k`, are read off by cubic Hermite interpolation, as
for the dragged wire (:mod:`._curve`).
"""

from __future__ import annotations

import functools

import numpy as np
from numpy.polynomial import legendre as _leg
from numpy.polynomial import polynomial as _poly
from numpy.typing import NDArray

from ._curve import _cells, _hermite

__all__ = ["Held"]

#: Grid intervals along the whole wire.
_CELLS = 1024


@functools.cache
def _modes(K: int, m: int) -> dict[str, NDArray]:
    """Each mode (rows) on the grid: its value, slope, second derivative and integral from 0."""
    g = np.linspace(-1.0, 1.0, m + 1)
    bump = np.array([1.0, 0.0, -2.0, 0.0, 1.0])  # (1 - s^2)^2, power series
    out: dict[str, list[NDArray]] = {"phi": [], "d1": [], "d2": [], "d3": [], "int": []}
    for k in range(K):
        pk = _leg.leg2poly(np.eye(K)[k])
        c = _poly.polymul(bump, pk)
        out["phi"].append(_poly.polyval(g, c))
        out["d1"].append(_poly.polyval(g, _poly.polyder(c)))
        out["d2"].append(_poly.polyval(g, _poly.polyder(c, 2)))
        out["d3"].append(_poly.polyval(g, _poly.polyder(c, 3)))
        out["int"].append(_poly.polyval(g, _poly.polyint(c, lbnd=0.0)))
    return {"grid": g, **{k: np.array(v) for k, v in out.items()}}


def _cumulative(v: NDArray, d: NDArray, h: float, mid: int) -> NDArray:
    """The integral from the grid's middle of ``v`` (its derivative ``d``), along the last axis.

    The corrected trapezoidal rule, exact for cubics: a cell adds
    :math:`h(v_j + v_{j+1})/2 + h^2(d_j - d_{j+1})/12`.
    """
    cell = h * (v[..., :-1] + v[..., 1:]) / 2 + h * h * (d[..., :-1] - d[..., 1:]) / 12
    total = np.concatenate([np.zeros(v.shape[:-1] + (1,)), np.cumsum(cell, axis=-1)], axis=-1)
    return total - total[..., mid : mid + 1]


class Held:
    """The held wire of ``K`` curvature modes, tabulated for a batch of coefficient rows."""

    def __init__(self, modes: int) -> None:
        self.K = int(modes)
        self.shape_names = tuple(f"c{k}" for k in range(self.K))

    def solve(self, coef: NDArray) -> None:
        """Tabulate the shapes of the rows of ``coef`` (``(B, K)``)."""
        m = _CELLS
        h = 2.0 / m
        M = _modes(self.K, m)
        c = np.asarray(coef, float).reshape(-1, self.K)
        kap = c @ M["phi"]  # l kappa
        dk = c @ M["d1"]
        th = c @ M["int"]
        cs, sn = np.cos(th), np.sin(th)
        mid = m // 2
        table = {
            "x": (_cumulative(cs, -sn * kap, h, mid), cs),
            "y": (_cumulative(sn, cs * kap, h, mid), sn),
            "theta": (th, kap),
            "kappa": (kap, dk),
        }
        for k in range(self.K):
            psi, phi = M["int"][k], M["phi"][k]
            # d/dc_k of x = int cos(theta) is -int sin(theta) psi_k, of y int cos(theta) psi_k
            gx, gy = -sn * psi, cs * psi
            dgx = -cs * kap * psi - sn * phi
            dgy = -sn * kap * psi + cs * phi
            table[f"x_c{k}"] = (_cumulative(gx, dgx, h, mid), gx)
            table[f"y_c{k}"] = (_cumulative(gy, dgy, h, mid), gy)
        self.table = {k: _cells(*pair) for k, pair in table.items()}
        self.rows = c.shape[0]
        self.converged = np.ones(c.shape[0], bool)

    def at(self, s: NDArray, names: tuple[str, ...]) -> dict[str, NDArray]:
        """``names`` of the table at the arc lengths ``s`` (``(B, N)``, in ``[-1, 1]``)."""
        u = (np.clip(s, -1.0, 1.0) + 1.0) * (_CELLS / 2.0)
        return _hermite(self.table, names, u, _CELLS, 2.0)

    def normal_friction(self, coef: NDArray, s: NDArray) -> tuple[NDArray, NDArray]:
        r"""The group :math:`f_n l^3/EI = \kappa'' + \kappa^3/2` at ``s``, and its gradient.

        In the coefficients: ``(N,)`` and ``(N, K)``, exact (polynomials; lengths over l).
        """
        c = np.asarray(coef, float)
        phi = np.array([_mode_values(k, s, 0) for k in range(self.K)]).T  # (N, K)
        d2 = np.array([_mode_values(k, s, 2) for k in range(self.K)]).T
        kap = phi @ c
        fn = d2 @ c + kap**3 / 2
        grad = d2 + 1.5 * (kap**2)[:, None] * phi
        return fn, grad


def _mode_values(k: int, s: NDArray, der: int) -> NDArray:
    bump = np.array([1.0, 0.0, -2.0, 0.0, 1.0])
    c = _poly.polymul(bump, _leg.leg2poly(np.eye(k + 1)[k]))
    return _poly.polyval(s, _poly.polyder(c, der) if der else c)


def _mode_integral(k: int, s: NDArray) -> NDArray:
    """The integral from 0 of the mode ``k`` at ``s`` (its angle per unit coefficient)."""
    bump = np.array([1.0, 0.0, -2.0, 0.0, 1.0])
    c = _poly.polymul(bump, _leg.leg2poly(np.eye(k + 1)[k]))
    return _poly.polyval(s, _poly.polyint(c, lbnd=0.0))
