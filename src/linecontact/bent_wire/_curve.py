r"""The dragged wire as a curve to fit: its points, tangents and load derivatives, fast.

The fit of a measured profile (:mod:`.fit`) asks, at every step and for every bootstrap
replicate, where the model wire is at hundreds of arc lengths, which way it points there,
how it bends, and how all that moves with the friction group. Solving the elastica
(:mod:`.elastica`) once per step and per replicate is cheap (a batch of small Newton
solves, warm-started from the last step); evaluating a Chebyshev series at every point is
not. So each solve is tabulated once on a uniform grid of the half's arc length, by one
matrix product per quantity, together with each quantity's derivative (known in closed
form from the equations), and the points are read off by cubic Hermite interpolation: an
error of :math:`h^4/384` times the fourth derivative, below :math:`10^{-10}` of the
half-length at every friction group here, against position noises of :math:`10^{-3}`.

The whole wire, from one end (``s = -1``) to the other (``s = 1``) through the midpoint
(``s = 0``), is the half mirrored: at ``s < 0`` the point :math:`(-x(|s|), y(|s|))`, the
tangent's angle :math:`-\theta(|s|)`. A negative friction group is the wire mirrored in
its axis (dragged the other way), so that a fit passes through the straight wire
continuously.
"""

from __future__ import annotations

import functools

import numpy as np
from numpy.polynomial import chebyshev as _cheb
from numpy.typing import NDArray

from .elastica import LAMBDA_MAX, _grid, _newton

__all__ = ["Dragged"]

#: Collocation points along the half (the shape agrees with 48 to 1e-12 at every group).
_NODES = 32
#: Grid intervals along the half for the Hermite tables.
_CELLS = 512
_RUNG = 2.0


@functools.cache
def _tables(n: int, m: int) -> tuple[NDArray, NDArray, NDArray, NDArray]:
    """Maps from values at the ``n + 1`` Lobatto nodes to the grid of ``m + 1`` points.

    ``(grid, value, derivative, integral)``: the interpolant's value, its derivative in
    ``u`` and its integral from 0, each a ``(m + 1, n + 1)`` matrix.
    """
    u, _, _ = _grid(n)
    t = 2.0 * u - 1.0
    coef = _cheb.chebfit(t, np.eye(n + 1), n)  # (n+1 coefficients, n+1 node values)
    g = np.linspace(0.0, 1.0, m + 1)
    tg = 2.0 * g - 1.0
    value = _cheb.chebval(tg, coef).T
    deriv = 2.0 * _cheb.chebval(tg, _cheb.chebder(coef)).T
    integ = _cheb.chebval(tg, _cheb.chebint(coef, lbnd=-1.0)).T / 2.0
    return g, value, deriv, integ


def _cells(v: NDArray, d: NDArray) -> NDArray:
    """``(B * (m + 1), 4)``: at each grid point its value and slope and the next point's."""
    nxt = (
        np.concatenate([v[:, 1:], v[:, -1:]], axis=1),
        np.concatenate([d[:, 1:], d[:, -1:]], axis=1),
    )
    return np.stack([v, d, *nxt], axis=-1).reshape(-1, 4)


def _hermite(
    tables: dict[str, NDArray], names: tuple[str, ...], u: NDArray, m: int, length: float
) -> dict[str, NDArray]:
    """``names`` of ``tables`` (:func:`_cells`) by cubic Hermite interpolation.

    ``u`` (``(B, N)``) is the position in cells, ``[0, m]``, on a grid of ``m`` cells spanning
    ``length`` of the arc length (the derivatives are per unit arc length).
    """
    j = np.minimum(u.astype(np.intp), m - 1)
    tau = u - j
    h = length / m
    t2, t3 = tau * tau, tau * tau * tau
    h00, h10 = 2 * t3 - 3 * t2 + 1, (t3 - 2 * t2 + tau) * h
    h01, h11 = -2 * t3 + 3 * t2, (t3 - t2) * h
    row = (np.arange(u.shape[0]) * (m + 1))[:, None] + j
    out = {}
    for name in names:
        c = tables[name][row]
        out[name] = h00 * c[..., 0] + h10 * c[..., 1] + h01 * c[..., 2] + h11 * c[..., 3]
    return out


class Dragged:
    """The wire dragged at its midpoint, tabulated for a batch of friction groups.

    ``solve(lam)`` solves and tabulates (warm-started from the last call when the batch has
    the same size); ``at(s)`` reads the points off.
    """

    shape_names = ("lam",)

    def __init__(self) -> None:
        self._theta: NDArray | None = None
        self._lam = np.zeros(0)

    def solve(self, lam: NDArray) -> None:
        """Solve for the friction groups ``lam`` (``(B,)`` or ``(B, 1)``, ``|lam| <= 60``)."""
        n, m = _NODES, _CELLS
        lam = np.asarray(lam, float).reshape(-1)
        mag = np.minimum(np.abs(lam), LAMBDA_MAX)
        u, D, D2 = _grid(n)
        if self._theta is not None and self._theta.shape[0] == mag.size:
            theta, start = self._theta, self._lam
        else:
            theta, start = np.zeros((mag.size, n + 1)), np.zeros(mag.size)
        rungs = max(1, int(np.ceil(np.max(np.abs(mag - start), initial=0.0) / _RUNG)))
        ok = np.ones(mag.size, bool)
        for r in range(1, rungs + 1):
            theta, _, ok = _newton(theta, start + (mag - start) * (r / rungs), n)
        if not np.all(ok):  # far from the last: from the straight wire
            theta = np.zeros((mag.size, n + 1))
            rungs = max(1, int(np.ceil(np.max(mag, initial=0.0) / _RUNG)))
            for r in range(1, rungs + 1):
                theta, _, ok = _newton(theta, mag * (r / rungs), n)
        self._theta, self._lam, self.converged = theta, mag, ok
        # the sensitivity to the group: J theta_lam = (1 - u) cos theta, zero at the ends
        load = mag[:, None] * (1.0 - u)[None, :]
        J = np.broadcast_to(D2, (mag.size, n + 1, n + 1)).copy()
        J += np.einsum("pi,ij->pij", load * np.sin(theta), np.eye(n + 1))
        rhs = (1.0 - u)[None, :] * np.cos(theta)
        J[:, 0, :], rhs[:, 0] = np.eye(n + 1)[0], 0.0
        J[:, -1, :], rhs[:, -1] = D[-1], 0.0
        th_l = np.linalg.solve(J, rhs[..., None])[..., 0]
        g, V, Dv, Iv = _tables(n, m)
        c, s = np.cos(theta), np.sin(theta)
        sign = np.where(lam < 0, -1.0, 1.0)[:, None]
        self.sign = sign
        tg = theta @ V.T  # the angle on the grid
        kg = theta @ Dv.T  # its derivative, the curvature
        lam_col = mag[:, None]
        cg, sg = np.cos(tg), np.sin(tg)
        # (value, derivative) pairs on the grid, the derivative from the equations
        k2 = lam_col * (1.0 - g) * cg  # theta''
        tl = th_l @ V.T
        table = {
            "x": (c @ Iv.T, cg),
            "y": (s @ Iv.T, sg),
            "theta": (tg, kg),
            "kappa": (kg, k2),
            "x_lam": (-(s * th_l) @ Iv.T, -sg * tl),
            "y_lam": ((c * th_l) @ Iv.T, cg * tl),
        }
        # per quantity one array (B * (m + 1), 4): a cell's two ends, each value and
        # derivative, gathered at once (the last row of each batch row a copy, never read)
        self.table = {k: _cells(*pair) for k, pair in table.items()}

    def at(self, s: NDArray, names: tuple[str, ...]) -> dict[str, NDArray]:
        """``names`` of the table at the arc lengths ``s`` (shape ``(B, N)``, in ``[-1, 1]``).

        In the whole wire's frame: ``x`` odd and ``y`` even in ``s``, the angle ``theta``
        odd, the curvature ``kappa`` even; ``y``, ``theta`` and ``kappa`` (and ``x_lam``,
        which is even in the group) mirrored for a negative group.
        """
        side = np.where(s < 0, -1.0, 1.0)
        out = _hermite(self.table, names, np.abs(s) * _CELLS, _CELLS, 1.0)
        for name, val in out.items():
            if name in ("x", "theta"):
                val = val * side
            if name in ("y", "theta", "kappa"):
                val = val * self.sign
            if name == "x_lam":
                val = val * side * self.sign  # x is even in the group: d/dlam is odd
            out[name] = val
        return out
