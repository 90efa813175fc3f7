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
from typing import Any

import numpy as np
from numpy.typing import NDArray

_FAR = 2000.0  # end of the mesh (the attraction there is ~1e-19 of its peak)
_RATIO = 1.3  # growth of the coarse elements beyond the uniform band
_M = 320  # fine elements per 8 edge lengths in the band (a multiple of 4)
_BAND = 8.0  # half-width of the uniform band about the edge, in edge lengths
_EDGE_GAP = 1.5  # the gap over z0 that marks the edge the band follows
_HMAX = 0.1  # largest coarse element inside the contact at m = _M (scales with 1/m)
_START = 6.0  # central gap where a curve starts (the load ~2% of the rigid pull-off)
_SMALL_BAND = 4.0  # the mesh of small edges: uniform on [0, 4 edge lengths]
_SCALED_FROM = 2.0  # edges beyond this many edge lengths: scaled meshes (_Grid.scaled)
_E_RATIO = 2.0  # one scaled mesh per this factor of the edge
_E_BAND = 1.0  # the band a scaled mesh holds about the edge, in edge lengths
_HMAX_FROM = 4.0  # coarse elements inside a contact wider than this grow with it
_TOL = 1e-11  # Newton: largest residual of the gap equation relative to the gap
_CHORD = 0.6  # a chord step is kept while the residual falls at least by this factor
_MAXIT = 80  # Newton iterations at most


# ---------------------------------------------------------------------------------------
# the discrete operators


def _log_terms(s: NDArray) -> tuple[NDArray, NDArray]:
    r""":math:`s \ln|s|` (0 at :math:`s = 0`) and :math:`s`: pieces of the antiderivatives."""
    with np.errstate(divide="ignore"):
        ls = np.log(np.abs(s))
    ls[s == 0] = 0.0
    return s * ls, s


def _kernel(nodes: NDArray) -> NDArray:
    r""":math:`K_{ij} = \int \phi_j(\eta) \ln(|\xi_i^2 - \eta^2|/\eta^2)\,d\eta` on the mesh.

    :math:`\phi_j` the hat functions of ``nodes``; the kernel is
    :math:`\ln|\xi - \eta| + \ln|\xi + \eta| - 2 \ln|\eta|`, each term integrated exactly against
    the linear pieces: with :math:`s = t - c`,

    .. math::

        A_0 = \int \ln|s|\, dt = s \ln|s| - s, \qquad
        A_1 = \int t \ln|s|\, dt = \tfrac12 s^2 \ln|s| - \tfrac14 s^2 + c A_0,

    summed over the three terms at every node (one logarithm per node pair and term,
    in place: the cost is the passes over :math:`n^2` numbers) and differenced over the elements.
    """
    n = nodes.size
    t, xi = nodes[None, :], nodes[:, None]
    A0, A1, s, sl = (np.empty((n, n)) for _ in range(4))
    for c in (xi, -xi):
        np.subtract(t, c, out=s)
        np.abs(s, out=sl)
        with np.errstate(divide="ignore"):
            np.log(sl, out=sl)
        sl[s == 0] = 0.0
        sl *= s  # s ln|s|
        if c is xi:
            np.subtract(sl, s, out=A0)
            np.multiply(sl, 0.5, out=A1)
            A1 -= 0.25 * s
            A1 *= s
            A1 += c * A0
        else:
            sl -= s  # its A0
            A0 += sl
            A1 += c * sl
            sl += s
            sl *= 0.5
            sl -= 0.25 * s
            sl *= s
            A1 += sl
    s0l, s0 = _log_terms(nodes)  # c = 0, weight -2 (the same in every row)
    A0 -= 2.0 * (s0l - s0)
    A1 -= 2.0 * (0.5 * s0l - 0.25 * s0) * s0
    i0 = np.diff(A0, axis=1)  # int ln over each element, (nodes, elements)
    i1 = np.diff(A1, axis=1)  # int t ln
    a, b = nodes[:-1], nodes[1:]
    K = np.zeros((n, n))
    left = K[:, :-1]
    np.multiply(b, i0, out=left)
    left -= i1
    left /= b - a  # phi_left = (b - t)/h
    i0 -= left
    K[:, 1:] += i0  # phi_right = 1 - phi_left
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
    coarse kernel is ``K[::2] @ T`` (taken by slices); no logarithm is evaluated again.
    """
    rows = K[::2]
    Kc = rows[:, ::2].copy()
    Kc[:, :-1] += 0.5 * rows[:, 1::2]
    Kc[:, 1:] += 0.5 * rows[:, 1::2]
    return nodes[::2], Kc


@dataclass(frozen=True, eq=False)
class _Mesh:
    nodes: NDArray
    K: NDArray
    w: NDArray
    spec: tuple[float, ...]
    #: the last factorised Jacobian ``(mu, lu)``: a chord Newton reuses it from one state
    #: to the next (it only speeds convergence; the residual decides, so a stale one is
    #: never wrong). Each solve's own: the meshes of :meth:`_Grid.meshes`.
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


_Arrays = tuple[NDArray, NDArray, NDArray]

#: The meshes kept, by spec: by the process (their arrays) and by each solve (with its
#: factorisations); the edges pinned between nodes make a spec each.
_MESHES_KEPT = 12


@functools.lru_cache(maxsize=_MESHES_KEPT)
def _mesh_arrays(spec: tuple[float, ...]) -> tuple[_Arrays, _Arrays, _Arrays]:
    """The nodes, kernel and weights of the fine, middle and coarse meshes of ``spec``.

    ``spec = (lo, hi, hb, hmax[, pin])``. The coarse mesh is :func:`_graded_nodes`, with the
    node ``pin`` added where given (an edge held between its nodes); the others bisect it
    once and twice. The kernel is computed on the fine mesh and derived exactly for the
    coarser ones. Cached: they are a function of ``spec`` alone, and read-only.
    """
    fine = _graded_nodes(*spec[:4])
    if len(spec) > 4:
        j = int(np.argmin(np.abs(fine - spec[4])))
        if abs(fine[j] - spec[4]) <= 1e-9 * spec[2]:
            fine[j] = spec[4]
        else:
            fine = np.sort(np.append(fine, spec[4]))
    for _ in range(2):
        fine = np.sort(np.concatenate([fine, 0.5 * (fine[1:] + fine[:-1])]))
    K = _kernel(fine)
    out = [(fine, K, _trapezoid(fine))]
    nodes = fine
    for _ in range(2):
        nodes, K = _coarsen(nodes, K)
        out.append((nodes, K, _trapezoid(nodes)))
    for arrays in out:
        for a in arrays:
            a.setflags(write=False)
    return out[0], out[1], out[2]


@dataclass(frozen=True)
class _Grid:
    r"""The family of meshes of one solve: the band follows the edge of the contact.

    ``ell`` is the length of the edge zone (1 for :math:`\mu \le 1`, :math:`1/\mu` beyond: the gap
    rises from :math:`z_0` to a few :math:`z_0` over about :math:`1/\mu` outside a JKR-like edge);
    the band is :math:`[e - 8\ell, e + 8\ell]` about the edge :math:`e` (from 0 while ``e`` is
    small) with coarse elements ``hb``; a state whose edge comes within :math:`4\ell` of the band's
    end is solved again on a band about it.
    """

    ell: float
    hb: float
    hmax: float
    #: the meshes of this solve, by spec (:meth:`meshes`)
    store: dict = field(default_factory=dict, compare=False, repr=False)

    def meshes(self, spec: tuple[float, ...]) -> tuple[_Mesh, _Mesh, _Mesh]:
        """The fine, middle and coarse meshes of ``spec`` in this solve.

        Their arrays are shared by every solve (:func:`_mesh_arrays`); their chord
        factorisation (``lu``) is this solve's own, so that a result depends on the calls
        made with this grid only, never on what another solve met before. The last
        :data:`_MESHES_KEPT` specs are kept (each holds a dense kernel).
        """
        got = self.store.pop(spec, None)  # the most recent last: the store is an LRU
        if got is None:
            f, m, c = (_Mesh(n, K, w, spec) for n, K, w in _mesh_arrays(spec))
            got = (f, m, c)
            if len(self.store) >= _MESHES_KEPT:  # a kernel each: the oldest goes
                del self.store[next(iter(self.store))]
        self.store[spec] = got
        return got

    def spec(self, e: float) -> tuple[float, float, float, float]:
        c = self.ell * round(e / self.ell)
        lo = c - _BAND * self.ell
        lo = 0.0 if lo < 2.0 * self.ell else lo
        return (round(lo, 12), round(c + _BAND * self.ell, 12), self.hb, self.hmax)

    def small(self) -> tuple[float, float, float, float]:
        r"""The small mesh, uniform from 0 and graded beyond.

        Uniform over :data:`_SMALL_BAND` edge lengths (twice that for :math:`\mu \le 1`, where the
        whole curve to its pull-off lies within a few units and the attraction out there
        carries the load), then graded.

        It holds the far part and the edges up to :meth:`small_end`.
        """
        band = _SMALL_BAND * self.ell * (2.0 if self.ell == 1.0 else 1.0)
        return (0.0, round(band, 12), self.hb, self.hmax)

    def small_end(self) -> float:
        """The largest edge held on the small mesh.

        ``_SCALED_FROM`` edge lengths, a whole number of its coarse elements (the edges it
        holds are its coarse nodes).
        """
        return self.hb * round(_SCALED_FROM * self.ell / self.hb)

    def scaled(self, e: float) -> tuple[tuple[float, float, float, float], float]:
        r"""``(spec, k)``: the meshes of the edge ``e`` are those of ``spec`` scaled by ``k``.

        One mesh per factor :data:`_E_RATIO` of the edge, built about ``e_ref`` (``e/e_ref`` within
        :math:`\rho^{\pm 1/2}`, :math:`\rho` = ``_E_RATIO``), with ``e_ref`` a node of all three
        meshes (so the edge held is a node, and the loads of the three meshes differ smoothly): a
        band of elements at most :math:`1/\sqrt\rho` of the usual, ``_E_BAND`` :math:`\sqrt\rho`
        edge lengths either side (from 0 where that comes within 2 edge lengths of it). Scaled by
        :math:`k = e/e_\text{ref}` it holds :math:`e \pm` ``_E_BAND`` edge lengths at the usual
        resolution or finer. The kernel scales with the mesh exactly (:func:`_scaled_mesh`).
        """
        r = math.sqrt(_E_RATIO)
        e_ref = _E_RATIO ** round(math.log(e) / math.log(_E_RATIO))
        hb = e_ref / math.ceil(e_ref * r / self.hb)  # e_ref is a whole number of elements
        n = math.ceil(_E_BAND * self.ell * r / hb)
        lo = e_ref - n * hb
        lo = 0.0 if lo < 2.0 * self.ell else lo
        hmax = self.hmax * max(1.0, e_ref / _HMAX_FROM)
        return (lo, e_ref + n * hb, hb, hmax), e / e_ref

    def holds(self, spec: tuple[float, ...], e: float) -> bool:
        lo, hi = spec[0], spec[1]
        half = 0.5 * _BAND * self.ell
        return (lo == 0.0 or e - half >= lo) and e + half <= hi


def _law(zeta: NDArray) -> tuple[NDArray, NDArray]:
    """P(zeta) = -(8/3)(zeta^-3 - zeta^-9) and its derivative."""
    z3 = zeta**-3
    z9 = z3 * z3 * z3
    return -(8.0 / 3.0) * (z3 - z9), (8.0 / 3.0) * (3.0 * z3 - 9.0 * z9) / zeta


@functools.lru_cache(maxsize=1)
def _lapack() -> tuple[Any, Any]:
    """LAPACK's ``dgetrf`` and ``dgetrs``, called directly.

    The thousands of small solves of a curve spent a tenth of their time in the checks of
    ``scipy.linalg.lu_factor`` and ``lu_solve`` around the same two routines (issue 37).
    """
    from scipy.linalg import lapack  # here: ``import linecontact`` does not import scipy

    return lapack.dgetrf, lapack.dgetrs


def _lu_factor(J: NDArray) -> tuple[NDArray, NDArray]:
    """The LU factors of ``J`` (overwritten), as ``scipy.linalg.lu_factor`` gives them.

    A singular ``J`` gives factors whose solves are not finite: the chord Newton's residual
    then says so (:func:`_iterate`).
    """
    lu, piv, info = _lapack()[0](J, overwrite_a=True)
    if info < 0:  # pragma: no cover - an argument LAPACK refuses: a bug here, not the input's
        raise ValueError(f"dgetrf: argument {-info} is illegal")
    return lu, piv


def _lu_solve(factors: tuple[NDArray, NDArray], b: NDArray) -> NDArray:
    """``J^-1 b`` from :func:`_lu_factor`'s factors (``scipy.linalg.lu_solve``'s routine)."""
    x, info = _lapack()[1](factors[0], factors[1], b)
    if info < 0:  # pragma: no cover - as in _lu_factor
        raise ValueError(f"dgetrs: argument {-info} is illegal")
    return x


def _factor(mu: float, mesh: _Mesh, dP: NDArray) -> tuple:
    r"""``(lu, J^-1 1)`` of :math:`J = I + (2\mu/\pi) K \mathrm{diag}(P')`, cached on the mesh.

    The next state reuses it (a neighbour's Jacobian only speeds convergence; the residual
    decides).
    """
    J = (2.0 * mu / math.pi) * mesh.K * dP[None, :]
    J[np.diag_indices_from(J)] += 1.0
    lu = _lu_factor(J)
    out = (lu, _lu_solve(lu, np.ones(J.shape[0])))
    mesh.lu.clear()
    mesh.lu[mu] = out
    return out


def _iterate(
    mu: float, mesh: _Mesh, zeta: NDArray, zeta0: float, edge: float | None, tol: float
) -> tuple[NDArray, float, float, bool]:
    r"""Chord Newton on the discrete gap equation, the central gap or the edge held.

    With ``edge`` the unknowns are the gaps and ``zeta0`` and the extra equation
    :math:`\zeta(\text{edge})` = ``_EDGE_GAP`` (the bordered system by block elimination). A
    factorisation is reused while each step lowers the residual by :data:`_CHORD`; a step that
    raises it is taken back and, with a fresh factorisation, halved (up to four times) -- so a poor
    first guess or a neighbour's factorisation costs iterations, never the solve. Returns
    ``(zeta, zeta0, residual, ok)``; the residual is the largest of the gap equation's relative to
    the gap (and of the edge condition).
    """
    nodes, K = mesh.nodes, mesh.K
    half = 0.5 * nodes * nodes
    c = 2.0 * mu / math.pi
    i, t = _edge_row(nodes, edge) if edge is not None else (0, 0.0)

    def residual(z: NDArray, z0: float):
        P, dP = _law(z)
        r = z - z0 - half + c * (K @ P)
        q = (1.0 - t) * z[i] + t * z[i + 1] - _EDGE_GAP if edge is not None else 0.0
        return r, q, dP, max(float(np.max(np.abs(r) / z)), abs(q))

    r, q, dP, res = residual(zeta, zeta0)
    cached = mesh.lu.get(mu)
    fresh = False
    for _ in range(_MAXIT):
        if res <= tol:
            return zeta, zeta0, res, True
        if not np.isfinite(res):
            return zeta, zeta0, math.inf, False
        if cached is None:
            cached, fresh = _factor(mu, mesh, dP), True
        lu, y2 = cached
        y1 = _lu_solve(lu, -r)
        if edge is None:
            dz, d0 = y1, 0.0
        else:  # J dz - d0 = -r ; (1 - t) dz_i + t dz_(i+1) = -q
            d0 = (-q - ((1.0 - t) * y1[i] + t * y1[i + 1])) / ((1.0 - t) * y2[i] + t * y2[i + 1])
            dz = y1 + d0 * y2
        lam = 1.0  # the law is singular at contact: keep the gaps positive
        while np.any(zeta + lam * dz <= 0.05 * zeta) and lam > 1e-6:
            lam *= 0.5
        for _ in range(5 if fresh else 1):
            trial = zeta + lam * dz, zeta0 + lam * d0
            new = residual(*trial)
            if new[3] < res:
                break
            lam *= 0.5
        else:  # no descent: refactorise here, or fail with a fresh factorisation
            if fresh:
                return zeta, zeta0, res, False
            cached = None
            continue
        ratio = new[3] / res
        (zeta, zeta0), (r, q, dP, res) = trial, new
        fresh = False
        if ratio > _CHORD:
            cached = None
    return zeta, zeta0, res, res <= tol


def _newton(
    zeta0: float, mu: float, mesh: _Mesh, guess: NDArray, tol: float = _TOL
) -> tuple[NDArray, float, bool]:
    """Gaps at the nodes at the central gap ``zeta0`` (:func:`_iterate`): ``(zeta, res, ok)``."""
    zeta, _, res, ok = _iterate(mu, mesh, guess.copy(), zeta0, None, tol)
    zeta[0] = zeta0  # the centre's equation is exactly this (the kernel's row there is 0)
    return zeta, res, ok


def _half_width(nodes: NDArray, zeta: NDArray, level: float = 1.0) -> float:
    """The outermost ``xi`` where the gap crosses ``level z0``, linear between the nodes.

    The edge the meshes follow (``level`` :data:`_EDGE_GAP`, :func:`_follow`); the reported
    half-width is :func:`_width`'s.
    """
    i = _last_below(zeta, level)
    if i < 0:
        return 0.0
    if i + 1 >= nodes.size:
        return float(nodes[-1])
    t = (level - zeta[i]) / (zeta[i + 1] - zeta[i])
    return float(nodes[i] + t * (nodes[i + 1] - nodes[i]))


def _width(nodes: NDArray, zeta: NDArray) -> float:
    r"""The half-width of the repulsive region: the outermost ``xi`` where the gap crosses ``z0``.

    The crossing of the cubic through the four nodal gaps about it (the two nodes either side
    of the outermost node below ``z0``; three one side at the ends of the mesh), by Newton
    from the linear interpolation. The nodal gaps converge with the mesh as the load does;
    the error of a linear interpolation between them depends on where in its element the
    crossing falls, which no extrapolation in the element size removes (the cubic's is
    fourth order). 0 where every nodal gap exceeds ``z0``; the end of the mesh where none does.
    """
    i = _last_below(zeta, 1.0)
    if i < 0:
        return 0.0
    if i + 1 >= nodes.size:
        return float(nodes[-1])
    j = min(max(i - 1, 0), nodes.size - 4)
    x = [float(v - nodes[i]) for v in nodes[j : j + 4]]
    y = [float(v) - 1.0 for v in zeta[j : j + 4]]
    b = x[i + 1 - j]
    t = -y[i - j] * b / (y[i + 1 - j] - y[i - j])
    for _ in range(30):  # p(t) and p'(t) of the Lagrange cubic
        p = dp = 0.0
        for k in range(4):
            num, dnum = 1.0, 0.0
            den = 1.0
            for m in range(4):
                if m != k:
                    dnum = dnum * (t - x[m]) + num
                    num *= t - x[m]
                    den *= x[k] - x[m]
            p += y[k] * num / den
            dp += y[k] * dnum / den
        step = p / dp if dp != 0.0 else 0.0
        t -= step
        if not 0.0 <= t <= b:  # not monotone here: the linear crossing
            return _half_width(nodes, zeta)
        if abs(step) <= 1e-15 * b:
            break
    return float(nodes[i] + t)


def _last_below(zeta: NDArray, level: float) -> int:
    """The last node whose gap is below ``level`` ``z0`` (-1 where there is none)."""
    inside = np.nonzero(zeta < level)[0]
    return int(inside[-1]) if inside.size else -1


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
    edge: float = 0.0  # where the gap crosses _EDGE_GAP z0 (the edge held, or found)
    central_gap: float = math.nan  # reported: zeta0, or its extrapolation at an edge held
    #: estimated error of ``central_gap`` (0 where it is the control held): the change of its
    #: extrapolation from the coarser pair of meshes, as the load's ``error``
    gap_error: float = 0.0
    #: estimated error of ``half_width``: its change from the middle mesh (:func:`_finish`)
    half_width_error: float = 0.0


def _solve(zeta0: float, mu: float, meshes: tuple[_Mesh, _Mesh, _Mesh], guess) -> _Solved | None:
    """One state at the central gap ``zeta0`` on three meshes; ``None`` where Newton fails."""
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
    meshes = grid.meshes(grid.spec(e))
    t = _solve(s.zeta0, mu, meshes, _on(s, meshes[0]))
    return s if t is None else t


def _finish(
    zeta0: float, mu: float, meshes, zeta: NDArray, edge: float | None = None
) -> _Solved | None:
    """The state from its fine gaps: the two coarser meshes, Richardson and the estimate.

    The coarser meshes hold the same central gap, or with ``edge`` the same edge
    (:func:`_edge_newton`); then the central gap too is the Richardson extrapolation of the
    two finer ones (``central_gap``): in contact the load is so stiff in the central gap
    that the fine mesh's own would not carry the extrapolated load.
    """
    fine = meshes[0]
    loads = [2.0 * float(fine.w @ _law(zeta)[0])]
    gaps = [zeta0]
    widths = [_width(fine.nodes, zeta)]
    for k, mesh in enumerate(meshes[1:], start=1):
        if edge is None:
            zk, _, okk = _newton(zeta0, mu, mesh, zeta[:: 2**k])
            z0k = zeta0
        else:
            zk, z0k, okk = _edge_newton(edge, mu, mesh, zeta[:: 2**k], zeta0)
        if not okk:
            break
        loads.append(2.0 * float(mesh.w @ _law(zk)[0]))
        gaps.append(z0k)
        widths.append(_width(mesh.nodes, zk))
    if len(loads) == 1:  # the middle mesh cannot hold the state: no estimate
        return None
    f, m = loads[:2]
    r_fine = f + (f - m) / 3.0
    gap = gaps[0] + (gaps[0] - gaps[1]) / 3.0
    if len(loads) == 3:
        c = loads[2]
        error = max(abs(r_fine - (m + (m - c) / 3.0)), 1e-15 * abs(r_fine))
        gap_error = abs(gap - (gaps[1] + (gaps[1] - gaps[2]) / 3.0))
    else:  # the coarsest mesh cannot hold the state: the whole change of the load
        error = abs(f - m)
        gap_error = abs(gaps[0] - gaps[1])
    P = _law(zeta)[0]
    rigid = zeta0 + 0.5 * fine.nodes**2
    res = float(np.max(np.abs(zeta - rigid + (2 * mu / math.pi) * (fine.K @ P)) / zeta))
    hw, hw_error = _width_and_estimate(widths)
    e = _half_width(fine.nodes, zeta, _EDGE_GAP) if edge is None else edge
    return _Solved(zeta0, r_fine, error, f, hw, res, zeta, fine, e, gap, gap_error, hw_error)


def _width_and_estimate(widths: list[float]) -> tuple[float, float]:
    """The half-width of the repulsive region and its estimate from the meshes' widths.

    Each mesh's width is :func:`_width`'s; extrapolated and estimated as the load is (the
    Richardson extrapolation of the two finer, its change from the coarser pair's; with two
    meshes, the whole change). Where a mesh finds no contact and another does (a contact
    forming between them), the fine mesh's width and the largest change as its estimate.
    """
    w = widths
    if len(w) < 2:
        return w[0], math.inf
    r = w[0] + (w[0] - w[1]) / 3.0
    if min(w) <= 0.0:
        return w[0], max(abs(v - w[0]) for v in w[1:])
    if len(w) == 2:
        return r, abs(w[0] - w[1])
    return r, max(abs(r - (w[1] + (w[1] - w[2]) / 3.0)), 1e-15 * r)


def _check_m(m) -> int:
    if not isinstance(m, (int, np.integer)) or m < 16 or m % 4:
        raise ValueError(f"m must be an integer >= 16 and a multiple of 4, got {m!r}")
    return int(m)


# ---------------------------------------------------------------------------------------
# states controlled by the edge


def _edge_row(nodes: NDArray, e: float) -> tuple[int, float]:
    """``(i, t)``: the gap at ``e`` is ``(1 - t) zeta_i + t zeta_(i+1)`` (linear pieces)."""
    i = int(np.clip(np.searchsorted(nodes, e) - 1, 0, nodes.size - 2))
    return i, float((e - nodes[i]) / (nodes[i + 1] - nodes[i]))


def _edge_newton(
    e: float, mu: float, mesh: _Mesh, zeta: NDArray, zeta0: float, tol: float = _TOL
) -> tuple[NDArray, float, bool]:
    r"""Gaps and central gap of the state whose gap is ``_EDGE_GAP`` :math:`z_0` at :math:`\xi = e`.

    Along the contact branch of a compliant contact the central gap hardly changes while
    the edge travels: ``zeta0`` is a poor control there, ``e`` a good one
    (:func:`_iterate`). Returns ``(zeta, zeta0, ok)``.
    """
    z, z0, _, ok = _iterate(mu, mesh, zeta, zeta0, e, tol)
    return z, z0, ok


def _scaled_mesh(mesh: _Mesh, k: float) -> _Mesh:
    r"""``mesh`` with its nodes times ``k``.

    :math:`\ln(|\xi^2 - \eta^2|/\eta^2)` is invariant, so the kernel and the weights scale by
    :math:`k` exactly. The copies share the chord factorisation
    (a neighbour's Jacobian speeds convergence; the residual decides).
    """
    if k == 1.0:
        return mesh
    return _Mesh(mesh.nodes * k, mesh.K * k, mesh.w * k, mesh.spec, mesh.lu)


def _edge_meshes(grid: _Grid, e: float) -> tuple[_Mesh, _Mesh, _Mesh]:
    """The fine, middle and coarse meshes of the state with its edge at ``e``.

    Up to :meth:`_Grid.small_end` the small mesh (``e`` one of its coarse nodes: the states
    of the far part and of the small edges share one kernel), or the small mesh with ``e``
    added; beyond, a scaled one.
    """
    if e <= grid.small_end() * (1.0 + 1e-12):
        j = e / grid.hb
        on_node = abs(j - round(j)) <= 1e-9 * max(1.0, j)
        return grid.meshes(grid.small() if on_node else (*grid.small(), e))
    spec, k = grid.scaled(e)
    f, m, c = grid.meshes(spec)
    return _scaled_mesh(f, k), _scaled_mesh(m, k), _scaled_mesh(c, k)


def _solve_edge(
    e: float, mu: float, meshes: tuple[_Mesh, _Mesh, _Mesh], zeta: NDArray, zeta0: float
) -> _Solved | None:
    """The state with its edge at ``e`` on ``meshes``; ``None`` on failure.

    ``meshes`` from :func:`_edge_meshes`; ``zeta`` (on the fine mesh) and ``zeta0`` are the
    first guess.
    """
    z, z0, ok = _edge_newton(e, mu, meshes[0], zeta, zeta0)
    if not ok:
        return None
    return _finish(z0, mu, meshes, z, edge=e)


def _md_guess(a: float, mu: float, mesh: _Mesh) -> tuple[NDArray, float]:
    r"""A first guess of the state whose contact half-width is about ``a`` (:math:`\mu > 0`).

    The gap of the Maugis-Dugdale pressure with the Maugis matching (Hertz and the bounded
    crack term inside ``a``, the step :math:`-S w/z_0` out to ``c``, the :math:`c/a` of the closed
    form :func:`linecontact.normal_contact` at the matched groups), through the same kernel,
    lifted so that the gap is :math:`z_0` at ``a``; at least :math:`0.95\, z_0`. Returns ``(zeta,
    zeta0)``.
    """
    from ..normal.contact import normal_contact
    from ._matching import MAUGIS_MATCH_SIGMA0 as S

    rho = 1e6  # the matched groups depend on mu alone in these units (docs/lennard-jones.md)
    st = normal_contact(a * math.sqrt(S / rho), rho, mu * S**1.5 / math.sqrt(rho))
    c = a * float(st.c_over_R) / float(st.a_over_R)
    xi = mesh.nodes
    P = np.where((xi >= a) & (xi < c), -S, 0.0)
    inside = xi < a
    d = np.sqrt(a * a - xi[inside] ** 2)
    with np.errstate(divide="ignore"):
        P[inside] = d / (2.0 * mu) - (2.0 * S / math.pi) * np.arctan(np.sqrt(c * c - a * a) / d)
    g = 0.5 * xi * xi - (2.0 * mu / math.pi) * (mesh.K @ P)
    lift = 1.0 - float(np.interp(a, xi, g))
    return np.maximum(g + lift, 0.95), lift
