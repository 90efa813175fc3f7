"""The discrete Lennard-Jones problem: meshes, kernels, Newton, one state on three meshes.

``P`` piecewise linear on a mesh uniform about the edge and geometric beyond, the
logarithmic kernel integrated exactly on each element, collocation at the nodes and a
Newton (chord) iteration on the gaps; every state on the fine mesh and on the meshes with
every second and every fourth node, the load their Richardson extrapolation.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

_FAR = 2000.0  # end of the mesh (the attraction there is ~1e-19 of its peak)
_RATIO = 1.2  # growth of the coarse elements beyond the uniform band
_M = 320  # fine elements per 8 edge lengths in the band (a multiple of 4)
_BAND = 8.0  # half-width of the uniform band about the edge, in edge lengths
_EDGE_GAP = 1.5  # the gap over z0 that marks the edge the band follows
_HMAX = 0.1  # largest coarse element inside the contact at m = _M (scales with 1/m)
_START = 6.0  # central gap where a curve starts (the load ~2% of the rigid pull-off)
_TOL = 1e-11  # Newton: largest residual of the gap equation relative to the gap
_CHORD = 0.25  # a chord step is kept while the residual falls at least by this factor


# ---------------------------------------------------------------------------------------
# the discrete operators


def _log_antiderivatives(t: NDArray, c: NDArray) -> tuple[NDArray, NDArray]:
    """``int ln|t - c| dt`` and ``int t ln|t - c| dt`` at ``t`` (0 log 0 = 0)."""
    s = t - c
    with np.errstate(divide="ignore", invalid="ignore"):
        ls = np.where(s == 0, 0.0, np.log(np.abs(s)))
    a0 = s * ls - s
    a1 = 0.5 * s * s * ls - 0.25 * s * s + c * (s * ls - s)
    return a0, a1


def _kernel(nodes: NDArray) -> NDArray:
    """``K[i, j] = int phi_j(eta) ln(|xi_i^2 - eta^2| / eta^2) d eta`` on the mesh.

    ``phi_j`` the hat functions of ``nodes``; the kernel is ``ln|xi - eta| + ln|xi + eta| -
    2 ln|eta|``, each term integrated exactly against the linear pieces.
    """
    xi = nodes[:, None]
    a, b = nodes[None, :-1], nodes[None, 1:]
    h = b - a
    K = np.zeros((nodes.size, nodes.size))
    for c, weight in ((xi, 1.0), (-xi, 1.0), (np.zeros_like(xi), -2.0)):
        A0b, A1b = _log_antiderivatives(b, c)
        A0a, A1a = _log_antiderivatives(a, c)
        i0, i1 = A0b - A0a, A1b - A1a  # (nodes, elements)
        K[:, :-1] += weight * (b * i0 - i1) / h  # phi_left = (b - t)/h
        K[:, 1:] += weight * (i1 - a * i0) / h  # phi_right = (t - a)/h
    return K


def _trapezoid(nodes: NDArray) -> NDArray:
    h = np.diff(nodes)
    w = np.zeros(nodes.size)
    w[:-1] += 0.5 * h
    w[1:] += 0.5 * h
    return w


def _coarsen(nodes: NDArray, K: NDArray) -> tuple[NDArray, NDArray]:
    """The mesh of every second node and its kernel, exactly, from the fine one.

    A coarse hat function is the fine one at its node plus half its two neighbours, so the
    coarse kernel is ``K[::2] @ T``; no logarithm is evaluated again.
    """
    m = (nodes.size - 1) // 2
    T = np.zeros((nodes.size, m + 1))
    j = np.arange(m + 1)
    T[2 * j, j] = 1.0
    T[2 * j[1:] - 1, j[1:]] = 0.5
    T[2 * j[:-1] + 1, j[:-1]] = 0.5
    return nodes[::2], K[::2] @ T


@dataclass(frozen=True, eq=False)
class _Mesh:
    nodes: NDArray
    K: NDArray
    w: NDArray
    spec: tuple[float, float, float, float]
    #: the last factorised Jacobian ``(mu, lu)``: a chord Newton reuses it from one state
    #: to the next (it only speeds convergence; the residual decides, so a stale one is
    #: never wrong)
    lu: dict = field(default_factory=dict, repr=False)


def _graded_nodes(lo: float, hi: float, hb: float, hmax: float) -> NDArray:
    """The coarse mesh: uniform elements ``hb`` on ``[lo, hi]``, graded on both sides.

    Towards the centre the elements grow by :data:`_RATIO` up to ``hmax`` and are scaled to
    end at 0; beyond ``hi`` they grow by :data:`_RATIO` to :data:`_FAR`.
    """
    band = np.linspace(lo, hi, max(1, round((hi - lo) / hb)) + 1)
    parts = []
    if lo > 0.0:
        sizes, d, s = [], 0.0, hb
        while d < lo:
            s = min(s * _RATIO, max(hmax, hb))
            sizes.append(s)
            d += s
        inner = lo - np.cumsum(np.array(sizes) * (lo / d))
        inner[-1] = 0.0
        parts.append(inner[::-1])
    outer = [hi]
    step = hb
    while outer[-1] < _FAR:
        step *= _RATIO
        outer.append(outer[-1] + step)
    parts += [band, np.array(outer[1:])]
    return np.concatenate(parts)


@functools.lru_cache(maxsize=4)
def _meshes(spec: tuple[float, float, float, float]) -> tuple[_Mesh, _Mesh, _Mesh]:
    """The fine, middle and coarse meshes of ``spec = (lo, hi, hb, hmax)`` (cached).

    The coarse mesh is :func:`_graded_nodes`; the others bisect it once and twice. The
    kernel is computed on the fine mesh and derived exactly for the coarser ones.
    """
    fine = _graded_nodes(*spec)
    for _ in range(2):
        fine = np.sort(np.concatenate([fine, 0.5 * (fine[1:] + fine[:-1])]))
    K = _kernel(fine)
    out = [_Mesh(fine, K, _trapezoid(fine), spec)]
    nodes = fine
    for _ in range(2):
        nodes, K = _coarsen(nodes, K)
        out.append(_Mesh(nodes, K, _trapezoid(nodes), spec))
    return out[0], out[1], out[2]


@dataclass(frozen=True)
class _Grid:
    """The family of meshes of one solve: the band follows the edge of the contact.

    ``ell`` is the length of the edge zone (``1`` for ``mu <= 1``, ``1/mu`` beyond: the
    gap rises from ``z0`` to a few ``z0`` over about ``1/mu`` outside a JKR-like edge);
    the band is ``[e - 8 ell, e + 8 ell]`` about the edge ``e`` (from 0 while ``e`` is
    small) with coarse elements ``hb``; a state whose edge comes within ``4 ell`` of the
    band's end is solved again on a band about it.
    """

    ell: float
    hb: float
    hmax: float

    def spec(self, e: float) -> tuple[float, float, float, float]:
        c = self.ell * round(e / self.ell)
        lo = c - _BAND * self.ell
        lo = 0.0 if lo < 2.0 * self.ell else lo
        return (round(lo, 12), round(c + _BAND * self.ell, 12), self.hb, self.hmax)

    def holds(self, spec: tuple[float, ...], e: float) -> bool:
        lo, hi = spec[0], spec[1]
        half = 0.5 * _BAND * self.ell
        return (lo == 0.0 or e - half >= lo) and e + half <= hi


def _law(zeta: NDArray) -> tuple[NDArray, NDArray]:
    """P(zeta) = -(8/3)(zeta^-3 - zeta^-9) and its derivative."""
    z3 = zeta**-3
    z9 = z3 * z3 * z3
    return -(8.0 / 3.0) * (z3 - z9), (8.0 / 3.0) * (3.0 * z3 - 9.0 * z9) / zeta


def _chord(lu, fresh: bool, ratio: float, mu: float, mesh: _Mesh, dP: NDArray):
    """The chord step's factorisation: kept while the residual falls by 4 per step.

    Refactorises ``I + (2 mu/pi) K diag(P')`` otherwise (and caches it for the next state).
    Returns ``(lu, fresh, failing)``; failing when a fresh Jacobian did not lower the
    residual.
    """
    if lu is not None and ratio <= _CHORD:
        return lu, False, False
    if fresh and ratio >= 1.0:
        return lu, fresh, True
    import scipy.linalg  # here: ``import linecontact`` does not import scipy

    J = (2.0 * mu / math.pi) * mesh.K * dP[None, :]
    J[np.diag_indices_from(J)] += 1.0
    lu = scipy.linalg.lu_factor(J, check_finite=False)
    mesh.lu.clear()
    mesh.lu[mu] = lu
    return lu, True, False


def _newton(
    zeta0: float, mu: float, mesh: _Mesh, guess: NDArray, tol: float = _TOL
) -> tuple[NDArray, float, bool]:
    """Gaps at the nodes solving the discrete gap equation (chord Newton, refactored).

    The Jacobian is factorised again only when the residual falls by less than a factor 4
    per step. Returns the gaps, the largest residual relative to the gap and whether it met
    ``tol``.
    """
    import scipy.linalg

    nodes, K = mesh.nodes, mesh.K
    rigid = zeta0 + 0.5 * nodes * nodes
    zeta = guess.copy()
    c = 2.0 * mu / math.pi
    lu = mesh.lu.get(mu)
    res, fresh = math.inf, False
    for _ in range(60):
        P, dP = _law(zeta)
        r = zeta - rigid + c * (K @ P)
        res_new = float(np.max(np.abs(r) / zeta))
        if res_new <= tol:
            return zeta, res_new, True
        if not np.isfinite(res_new):
            return zeta, math.inf, False
        lu, fresh, failing = _chord(lu, fresh, res_new / res, mu, mesh, dP)
        if failing:
            return zeta, res_new, False
        res = res_new
        step = scipy.linalg.lu_solve(lu, r, check_finite=False)
        lam = 1.0  # the law is singular at contact: keep the gaps positive
        while np.any(zeta - lam * step <= 0.05 * zeta) and lam > 1e-6:
            lam *= 0.5
        zeta = zeta - lam * step
    return zeta, res, False


def _half_width(nodes: NDArray, zeta: NDArray, level: float = 1.0) -> float:
    """Half-width of the repulsive region: the outermost ``xi`` where the gap crosses ``z0``.

    (Or where it crosses ``level z0``: the edge the meshes follow, :func:`_follow`.)
    """
    inside = np.nonzero(zeta < level)[0]
    if inside.size == 0:
        return 0.0
    i = int(inside[-1])
    if i + 1 >= nodes.size:
        return float(nodes[-1])
    t = (level - zeta[i]) / (zeta[i + 1] - zeta[i])
    return float(nodes[i] + t * (nodes[i + 1] - nodes[i]))


@dataclass(frozen=True)
class _Solved:
    zeta0: float
    F: float  # Richardson extrapolation of the two finer loads
    error: float
    F_fine: float
    half_width: float
    residual: float
    zeta: NDArray  # on the fine mesh
    mesh: _Mesh


def _solve(
    zeta0: float, mu: float, spec: tuple[float, float, float, float], guess: NDArray | None
) -> _Solved | None:
    """One state on the three meshes of ``spec``; ``None`` where Newton fails."""
    meshes = _meshes(spec)
    fine = meshes[0]
    g = zeta0 + 0.5 * fine.nodes**2 if guess is None else guess
    zeta, res, ok = _newton(zeta0, mu, fine, g)
    if not ok:
        return None
    return _finish(zeta0, mu, meshes, zeta)


def _grid_for(mu: float, m: int | None) -> _Grid:
    """The meshes of a solve at ``mu``.

    ``m`` (default :data:`_M`) fine elements per 8 edge lengths in the band; the coarse
    elements inside the contact at most ``_HMAX _M/m``.
    """
    m = _M if m is None else _check_m(m)
    ell = 1.0 if mu <= 1.0 else 1.0 / mu
    return _Grid(ell, 32.0 * ell / m, _HMAX * _M / m)


def _on(s: _Solved, mesh: _Mesh) -> NDArray:
    """The gaps of ``s`` at the nodes of ``mesh`` (interpolated where the meshes differ)."""
    if s.mesh is mesh:
        return s.zeta
    return np.interp(mesh.nodes, s.mesh.nodes, s.zeta)


def _follow(mu: float, grid: _Grid, s: _Solved) -> _Solved:
    """``s``, solved again on a band about its edge where it has left its own band.

    The edge: where the gap crosses :data:`_EDGE_GAP` ``z0`` (it rises from ``z0`` to there
    within a few edge lengths outside a contact, and it follows the flat zone that forms
    before one).
    """
    e = _half_width(s.mesh.nodes, s.zeta, _EDGE_GAP)
    if grid.holds(s.mesh.spec, e):
        return s
    spec = grid.spec(e)
    t = _solve(s.zeta0, mu, spec, _on(s, _meshes(spec)[0]))
    return s if t is None else t


def _finish(zeta0: float, mu: float, meshes, zeta: NDArray) -> _Solved | None:
    """The state from its fine gaps: the two coarser meshes, Richardson and the estimate."""
    fine = meshes[0]
    loads = [2.0 * float(fine.w @ _law(zeta)[0])]
    for k, mesh in enumerate(meshes[1:], start=1):
        zk, _, okk = _newton(zeta0, mu, mesh, zeta[:: 2**k])
        if not okk:
            break
        loads.append(2.0 * float(mesh.w @ _law(zk)[0]))
    if len(loads) == 1:  # the middle mesh cannot hold the state: no estimate
        return None
    f, m = loads[:2]
    r_fine = f + (f - m) / 3.0
    if len(loads) == 3:
        c = loads[2]
        error = max(abs(r_fine - (m + (m - c) / 3.0)), 1e-15 * abs(r_fine))
    else:  # the coarsest mesh cannot hold the state: the whole change of the load
        error = abs(f - m)
    P = _law(zeta)[0]
    rigid = zeta0 + 0.5 * fine.nodes**2
    res = float(np.max(np.abs(zeta - rigid + (2 * mu / math.pi) * (fine.K @ P)) / zeta))
    return _Solved(zeta0, r_fine, error, f, _half_width(fine.nodes, zeta), res, zeta, fine)


def _check_m(m) -> int:
    if not isinstance(m, (int, np.integer)) or m < 16 or m % 4:
        raise ValueError(f"m must be an integer >= 16 and a multiple of 4, got {m!r}")
    return int(m)
