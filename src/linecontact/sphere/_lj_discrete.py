r"""The Lennard-Jones sphere's discretisation: its rings and one state by Newton's method.

The rings graded about the edge of the contact, their influence matrix (the exact
displacement of loaded discs), the law, and one state of the curve with its control held (a
bordered chord Newton iteration): the pieces :mod:`linecontact.sphere.lennard_jones` follows
the curve with. Units and equations as stated there.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..errors import ConvergenceError

#: The gap over :math:`z_0` that marks the edge the curve follows.
_EDGE_GAP = 1.5
#: The central gap where a curve starts.
_START = 6.0
_N_FAR = 9
#: The element of the uniform part at the default resolution (``m = 1``), at most.
_H = 0.05
#: The element over the edge length :math:`\mu_T^{-3/2}` (``m = 1``).
_H_EDGE = 0.12
#: The fine band's half-width about the edge, in elements.
_BAND = 40
#: How far beyond the band the elements stay no larger than the cap (the attraction's tail).
_REACH = 4.0
#: The largest element, over the radius of the edge (at least 0.05, at ``m = 1``).
_CAP = 0.02
#: Growth of the coarse elements beyond the uniform part, and the mesh's end.
_GROWTH = 0.10
_FAR_END = 40.0
_TOL = 1e-11
_MAXIT = 60
#: A chord step is kept while the residual falls at least by this factor.
_CHORD = 0.6


# ---------------------------------------------------------------------------------------
# the rings


#: :math:`E(m) - (1 - m)K(m) = (\pi/2)\sum_{n \ge 1} a_{n-1} m^n/(2n)`,
#: :math:`a_n = \binom{2n}{n}^2/16^n`: the series' coefficients, for :math:`m \le 1/4`
#: (30 terms: the next below :math:`10^{-19}`).
_SERIES = np.cumprod(np.r_[1.0, [((2 * n - 1) / (2 * n)) ** 2 for n in range(1, 30)]]) / (
    2.0 * np.arange(1, 31)
)


def _e_less_k(m: NDArray) -> NDArray:
    r""":math:`E(m) - (1 - m)K(m)`, without cancellation at small ``m`` (the series there)."""
    from scipy.special import ellipe, ellipk

    out = np.empty_like(m)
    small = m <= 0.25
    x = m[small]
    acc = np.zeros_like(x)
    for c in _SERIES[::-1]:
        acc = (acc + c) * x
    out[small] = 0.5 * math.pi * acc
    y = m[~small]
    out[~small] = ellipe(y) - (1.0 - y) * ellipk(y)
    return out


def _disc(r: NDArray, b: NDArray) -> NDArray:
    r"""The displacement at ``r`` of a disc of radius ``b`` under a unit pressure, times ``E``.

    :math:`(4b/\pi) E(r/b)` inside, :math:`(4r/\pi)[E - (1 - m) K](m = b^2/r^2)` outside
    (:func:`_e_less_k`).
    """
    from scipy.special import ellipe

    out = np.empty(np.broadcast_shapes(r.shape, b.shape))
    rr, bb = np.broadcast_arrays(r, b)
    inside = rr < bb
    ri, bi = rr[inside], bb[inside]
    out[inside] = (4.0 / math.pi) * bi * ellipe((ri / bi) ** 2)
    ro, bo = rr[~inside], bb[~inside]
    out[~inside] = (4.0 / math.pi) * ro * _e_less_k((bo / ro) ** 2)
    return out


@dataclass(frozen=True, eq=False)
class _Mesh:
    """Rings ``[edges[j], edges[j+1]]``, collocation at ``mid``; the influence matrix ``A``.

    Fine (element ``h``) over ``centre +- band``, the edge of the contact it is made for.
    """

    edges: NDArray
    mid: NDArray
    A: NDArray  # gap at mid[i] from a unit P on ring j, over mu^(3/2)
    area: NDArray  # b_(j+1)^2 - b_j^2: F/(pi w R) = area @ P (+ the tail)
    centre_disp: NDArray  # the displacement at r = 0 of a unit P on ring j: 2 (b_(j+1) - b_j)
    centre: float
    band: float
    h: float


class _Grading:
    r"""The map from the grid coordinate :math:`t` to the radius: the rings' sizes.

    The element is ``h`` over ``[c - B, c + B]``; away from it, at a distance :math:`d`,
    it grows as :math:`h + a d` (by the factor :math:`e^{a}` an element) up to ``cap``,
    inwards to the centre, outwards over the distance ``reach``, and beyond that grows
    again from ``cap``. :math:`t(\varrho) = \int_0^\varrho d\varrho'/s(\varrho')` in closed
    form, and its inverse.
    """

    def __init__(self, h: float, c: float, B: float, a: float, cap: float, reach: float) -> None:
        self.h, self.a, self.cap, self.reach = h, a, max(cap, h), reach
        self.lo, self.hi = max(c - B, 0.0), c + B
        self.t_lo = float(self._t_in(self.lo))
        self.t_hi = self.t_lo + (self.hi - self.lo) / h
        self.t_reach = self.t_hi + float(self._t_in(reach))

    def _t_in(self, d: float | NDArray) -> NDArray:
        """Elements over the distance ``d`` graded from ``h`` (capped)."""
        h, a, cap = self.h, self.a, self.cap
        d_cap = (cap - h) / a
        d = np.asarray(d, float)
        return np.where(
            d <= d_cap, np.log1p(a * d / h) / a, math.log(cap / h) / a + (d - d_cap) / cap
        )

    def _d_in(self, t: NDArray) -> NDArray:
        h, a, cap = self.h, self.a, self.cap
        t_cap = math.log(cap / h) / a
        return np.where(t <= t_cap, h * np.expm1(a * t) / a, (cap - h) / a + (t - t_cap) * cap)

    def t(self, rho: float) -> float:
        if rho <= self.lo:
            return self.t_lo - float(self._t_in(self.lo - rho))
        if rho <= self.hi:
            return self.t_lo + (rho - self.lo) / self.h
        d = rho - self.hi
        if d <= self.reach:
            return self.t_hi + float(self._t_in(d))
        return self.t_reach + math.log1p(self.a * (d - self.reach) / self.cap) / self.a

    def rho(self, t: NDArray) -> NDArray:
        a = self.a
        inner = self.lo - self._d_in(np.maximum(self.t_lo - t, 0.0))
        band = self.lo + (t - self.t_lo) * self.h
        outer = self.hi + self._d_in(np.clip(t - self.t_hi, 0.0, self.t_reach - self.t_hi))
        beyond = self.cap * np.expm1(a * np.maximum(t - self.t_reach, 0.0)) / a
        return np.select(
            [t < self.t_lo, t <= self.t_hi, t <= self.t_reach],
            [inner, band, outer],
            outer + beyond,
        )


def _element(mu: float, m: float) -> float:
    r"""The element at the edge: :math:`\min(0.05, 0.12\,\mu_T^{-3/2})/m`."""
    edge = _H_EDGE * mu**-1.5 if mu > 1e-100 else math.inf  # rigid to rounding below
    return min(_H, edge) / m


def _rings(mu: float, centre: float, m: float, level: int, far: float) -> _Mesh:
    r"""The rings at resolution ``m`` about the edge ``centre``, ``level`` times bisected.

    Elements :math:`h = \min(0.05, 0.12\,\mu_T^{-3/2})/m` over ``centre`` :math:`\pm`
    :data:`_BAND` elements of the default resolution, growing away from it by
    :math:`10/m` % an element up to :math:`\max(0.05, 0.02\,c)/m` (inwards to the centre,
    outwards over :data:`_REACH`, beyond which they grow again) to ``far``. The same map for
    every ``level``: a level's rings are the previous level's, halved.
    """
    h = _element(mu, m)
    a = math.log1p(_GROWTH) / m
    band = _BAND * _element(mu, 1.0)  # the same at every resolution
    g = _Grading(h, centre, band, a, max(_H, _CAP * centre) / m, _REACH)
    T = g.t(far)
    n = math.ceil(T)
    k = 2**level
    t = np.arange(n * k + 1) * (T / (n * k))
    edges = g.rho(t)
    edges[0] = 0.0
    mid = g.rho(t[:-1] + 0.5 * T / (n * k))
    return _mesh(edges, mid, centre, band, h)


def _mesh(edges: NDArray, mid: NDArray, centre: float, band: float, h: float) -> _Mesh:
    """The rings ``edges`` with collocation at ``mid``: their influence matrix and sums."""
    D = _disc(mid[:, None], edges[None, 1:])
    A = D.copy()
    A[:, 1:] -= D[:, :-1]
    return _Mesh(edges, mid, A, np.diff(edges**2), 2.0 * np.diff(edges), centre, band, h)


def _coarser(mesh: _Mesh) -> _Mesh:
    """The rings of ``mesh`` joined in pairs: the mesh it halves (nested exactly).

    The pairs' mid-points in the grid coordinate are the odd edges; an odd last ring stays.
    """
    e = mesh.edges
    if (e.size - 1) % 2:
        edges, mid = np.r_[e[:-1:2], e[-1]], np.r_[e[1:-1:2], mesh.mid[-1]]
    else:
        edges, mid = e[::2], e[1::2]
    return _mesh(edges, mid, mesh.centre, mesh.band, 2.0 * mesh.h)


def _law(z: NDArray) -> tuple[NDArray, NDArray]:
    z3 = z**-3
    z9 = z3 * z3 * z3
    return -(8.0 / 3.0) * (z3 - z9), (8.0 / 3.0) * (3.0 * z3 - 9.0 * z9) / z


# ---------------------------------------------------------------------------------------
# one state


@dataclass(frozen=True)
class _State:
    tau: float
    zeta: NDArray
    delta: float  # the approach over z0
    F: float  # over pi w R
    central_gap: float
    contact_radius: float  # where the gap crosses z0 (0 where it exceeds z0 everywhere)
    x: NDArray  # the collocation radii of the mesh it was solved on


def _constraint(mesh: _Mesh, tau: float) -> tuple[int, float, float]:
    r"""``(i, w, g)``: the control :math:`(1 - w)\zeta_i + w\zeta_{i+1} = g`.

    The gap at the edge :math:`e = \tau` (or at the centre, :math:`g = 1.5 - \tau`, for
    :math:`\tau < 0`), interpolated linearly in :math:`\varrho^2` (the gap is even in
    :math:`\varrho`; extrapolated from the first two mid-points inside the first one).
    """
    e, g = (tau, _EDGE_GAP) if tau > 0 else (0.0, _EDGE_GAP - tau)
    x = mesh.mid**2
    i = int(np.clip(np.searchsorted(x, e * e) - 1, 0, x.size - 2))
    return i, float((e * e - x[i]) / (x[i + 1] - x[i])), g


def _state(
    mu: float, mesh: _Mesh, tau: float, zeta: NDArray, delta: float, lu: dict | None = None
) -> _State | None:
    """Newton on the gaps and the approach with ``tau`` held; ``None`` where it fails.

    A chord iteration: the factorised Jacobian in ``lu`` (a neighbour's) is reused while
    each step lowers the residual at least by :data:`_CHORD`, and refactorised here where it
    does not; with a fresh one a step that does not lower the residual is halved (up to
    eight times) before the solve gives up.
    """
    from scipy.linalg import lu_factor, lu_solve

    c = mu**1.5
    half = 0.5 * mesh.mid**2
    i, w, g = _constraint(mesh, tau)
    zeta = zeta.copy()
    lu = {} if lu is None else lu

    def residual(z: NDArray, d: float):
        P, dP = _law(z)
        r = z + d - half - c * (mesh.A @ P)
        q = (1.0 - w) * z[i] + w * z[i + 1] - g
        return r, q, dP, max(float(np.max(np.abs(r) / z)), abs(q))

    r, q, dP, res = residual(zeta, delta)
    fresh = False
    for _ in range(_MAXIT):
        if res <= _TOL:
            break
        if not np.isfinite(res):
            return None
        if "f" not in lu:
            J = -c * mesh.A * dP[None, :]
            J[np.diag_indices_from(J)] += 1.0
            f = lu_factor(J, overwrite_a=True, check_finite=False)
            lu["f"], lu["y2"] = f, lu_solve(f, np.ones(zeta.size), check_finite=False)
            fresh = True
        y1 = lu_solve(lu["f"], -r, check_finite=False)
        y2 = lu["y2"]
        dd = ((1.0 - w) * y1[i] + w * y1[i + 1] + q) / ((1.0 - w) * y2[i] + w * y2[i + 1])
        dz = y1 - dd * y2
        lam = 1.0
        while np.any(zeta + lam * dz <= 0.3 * zeta) and lam > 1e-4:
            lam *= 0.5
        for _ in range(8 if fresh else 1):
            new = residual(zeta + lam * dz, delta + lam * dd)
            if new[3] < res:
                break
            lam *= 0.5
        else:
            if fresh:
                return None
            lu.clear()  # a neighbour's Jacobian: factorise here
            continue
        ratio = new[3] / res
        zeta, delta = zeta + lam * dz, delta + lam * dd
        r, q, dP, res = new
        fresh = False
        if ratio > _CHORD:
            lu.clear()
    else:
        return None
    P = _law(zeta)[0]
    z_far = zeta[-1] + 0.5 * (mesh.edges[-1] ** 2 - mesh.mid[-1] ** 2)
    F = float(mesh.area @ P) - (8.0 / 3.0) / z_far**2
    gap0 = -delta + c * float(mesh.centre_disp @ P)
    return _State(tau, zeta, delta, F, gap0, _crossing(mesh.mid, zeta, 1.0), mesh.mid)


def _crossing(x: NDArray, zeta: NDArray, level: float) -> float:
    """The outermost radius where the gap crosses ``level`` (0 where it never falls below)."""
    inside = np.nonzero(zeta < level)[0]
    if inside.size == 0:
        return 0.0
    i = int(inside[-1])
    if i + 1 >= x.size:
        return float(x[-1])
    t = (level - zeta[i]) / (zeta[i + 1] - zeta[i])
    return float(x[i] + t * (x[i + 1] - x[i]))


def _on(s: _State, x: NDArray, tau: float) -> NDArray:
    r"""``s``'s gaps at the radii ``x``, its edge moved to ``tau`` (radii scaled by the ratio).

    Beyond its last radius the rigid gap's growth :math:`\varrho^2/2` is added.
    """
    y = x * (s.tau / tau) if (tau > 0.0 and s.tau > 0.0) else x
    z = np.interp(y, s.x, s.zeta)
    out = y > s.x[-1]
    z[out] += 0.5 * (y[out] ** 2 - s.x[-1] ** 2)
    return z


def _guess(states: list[_State], tau: float, x: NDArray) -> tuple[NDArray, float]:
    """Linear extrapolation in ``tau`` from the two nearest states (no lower than either).

    Each on the radii ``x`` with its edge moved to ``tau`` (:func:`_on`).
    """
    near = sorted(states, key=lambda s: abs(s.tau - tau))
    s = near[0]
    other = [p for p in near[1:] if p.tau != s.tau]
    zs = _on(s, x, tau)
    if not other:
        return zs, s.delta
    p = other[0]
    zp = _on(p, x, tau)
    t = (tau - s.tau) / (s.tau - p.tau)
    z = zs + t * (zs - zp)
    return np.maximum(z, 0.9 * np.minimum(zs, zp)), s.delta + t * (s.delta - p.delta)


def _fail(what: str, mu: float, tau: float) -> ConvergenceError:
    return ConvergenceError(
        f"Lennard-Jones sphere {what} did not converge at tabor_parameter={mu!r}, "
        f"control tau={tau!r} (the central gap 1.5 - tau over z0 below 0, the edge above)"
    )
