r"""The Lennard-Jones law of Eq. 1 solved self-consistently for line contact.

A cylinder of radius ``R`` on an elastic half-plane (composite plane-strain modulus ``E``),
the surface traction the Lennard-Jones law (Eq. 1) at the local gap everywhere -- no
separate contact and adhesive zones. In plane strain the displacement has no datum, so the
state is controlled by the gap at the centre ``g0``; the gap elsewhere is

.. math::

    z(x) = g_0 + \frac{x^2}{2R} - \frac{2}{\pi E}\int p(s)\,\bigl(\ln|x - s| - \ln|s|\bigr)\,ds,

the pressure ``p`` (compressive positive) pressing the surface in most under the centre.
With ``x = sqrt(R z0) xi``, ``z = z0 zeta`` and ``p = (w/z0) P(zeta)``,
``P(zeta) = -(8/3)(zeta^-3 - zeta^-9)``, the gap is

.. math::

    \zeta(\xi) = \zeta_0 + \frac{\xi^2}{2}
        - \frac{2\mu}{\pi}\int_0^\infty P(\zeta(\eta))\,\ln\frac{|\xi^2 - \eta^2|}{\eta^2}\,d\eta,
    \qquad \mu = \frac{w\sqrt{R/z_0}}{E z_0},

and the load is ``F/(w sqrt(R/z0)) = 2 int_0^inf P d eta``. ``mu`` is the one group of the
problem (a Tabor parameter for cylinders): ``mu -> 0`` is the rigid limit
(:func:`linecontact.reference.lennard_jones_rigid_load`). With the Maugis matching of the
Dugdale step (``sigma0 = 16 w/(9 sqrt(3) z0)``, ``h = w/sigma0``) the Maugis parameter of
line contact (:func:`linecontact.maugis_parameter`) is a function of ``mu`` alone
(:func:`maugis_parameter_of_mu`). Derivation and mesh study: ``docs/lennard-jones.md``.

Discretisation: ``P`` piecewise linear on a mesh uniform on ``[0, X]`` (the contact and its
edge zones; ``X`` follows the widest contact asked for) and geometric beyond, to
``L = 2000`` where the attraction has decayed like ``xi^-6``; the logarithmic kernel is
integrated exactly on each element (product integration); collocation at the nodes; a
Newton (chord) iteration on the gaps. Every state is solved on that mesh and on the meshes
with every second and every fourth node (their kernels follow from the fine one exactly);
the load returned is the Richardson extrapolation of the two finer loads, and its error
estimate the change of that extrapolation from the coarser pair.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray

from ._validation import first_point
from .errors import ConvergenceError, NoEquilibriumError
from .materials import MAUGIS_H_OVER_Z0, MAUGIS_STRENGTH
from .results import Result

__all__ = [
    "LJCurve",
    "LennardJonesPullOff",
    "LJPullOff",
    "LJState",
    "MAUGIS_MATCH_H_OVER_Z0",
    "MAUGIS_MATCH_SIGMA0",
    "lj_contact_for_load",
    "lj_curve",
    "lj_groups",
    "lj_pull_off",
    "lj_state",
    "maugis_parameter_of_mu",
    "mu_of_dugdale",
    "pull_off_in_dugdale_groups",
    "pull_off_of",
]

#: Peak tension of the law over ``w/z0``: the Maugis matching of the Dugdale stress (an alias
#: of :data:`linecontact.materials.MAUGIS_STRENGTH`).
MAUGIS_MATCH_SIGMA0 = MAUGIS_STRENGTH
#: ``h/z0 = w/(sigma0 z0)`` of the matched Dugdale step (0.974; an alias of
#: :data:`linecontact.materials.MAUGIS_H_OVER_Z0`).
MAUGIS_MATCH_H_OVER_Z0 = MAUGIS_H_OVER_Z0

_FAR = 2000.0  # end of the mesh (the attraction there is ~1e-19 of its peak)
_RATIO = 1.2  # growth of the coarse elements beyond the uniform band
_M = 320  # fine elements per 8 edge lengths in the band (a multiple of 4)
_BAND = 8.0  # half-width of the uniform band about the edge, in edge lengths
_EDGE_GAP = 1.5  # the gap over z0 that marks the edge the band follows
_HMAX = 0.1  # largest coarse element inside the contact at m = _M (scales with 1/m)
_START = 6.0  # central gap where a curve starts (the load ~2% of the rigid pull-off)
_TOL = 1e-11  # Newton: largest residual of the gap equation relative to the gap
_CHORD = 0.25  # a chord step is kept while the residual falls at least by this factor


def mu_of_dugdale(R_over_h, sigma0_over_E):
    """The group ``mu`` of the Lennard-Jones law matched to a Dugdale step ``(sigma0, h)``.

    Same work of adhesion ``w = sigma0 h`` and same peak tension ``sigma0 = S w/z0``
    (``S`` = :data:`MAUGIS_MATCH_SIGMA0`), so ``z0 = S h`` and ``w/(E z0) = (sigma0/E)/S``:
    ``mu = (sigma0/E) sqrt(R/h) S^(-3/2)``. Returns ``(mu, R_over_z0)``.
    """
    R_over_z0 = np.asarray(R_over_h, float) / MAUGIS_MATCH_SIGMA0
    w_over_Ez0 = np.asarray(sigma0_over_E, float) / MAUGIS_MATCH_SIGMA0  # sigma0 h/(E z0)
    return w_over_Ez0 * np.sqrt(R_over_z0), R_over_z0


def maugis_parameter_of_mu(mu):
    """The Maugis parameter of the matched Dugdale step, as :func:`linecontact.maugis_parameter`.

    That parameter is ``(4/pi^(2/3)) (sigma0/E)^(2/3) (R/h)^(1/3)``; with the matching
    (:func:`mu_of_dugdale`), ``(sigma0/E)^(2/3) (R/h)^(1/3) = S mu^(2/3)``.
    """
    mu = np.asarray(mu, float)
    return 4.0 / np.pi ** (2.0 / 3.0) * MAUGIS_MATCH_SIGMA0 * mu ** (2.0 / 3.0)


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


# ---------------------------------------------------------------------------------------
# results


@dataclass(frozen=True)
class LJState(Result):
    """One equilibrium state under the Lennard-Jones law (nondimensional).

    Lengths along the surface over ``sqrt(R z0)``, gaps over ``z0``, pressure over ``w/z0``,
    the load per unit length over ``w sqrt(R/z0)`` (compressive positive).

    Attributes
    ----------
    central_gap_over_z0, mu : float
        The control ``zeta0 = g0/z0`` and the group ``mu``.
    F : float
        The load (Richardson extrapolation of the two finer meshes).
    error_estimate : float
        Estimated absolute error of ``F`` (its change from the coarser pair of meshes).
    half_width : float
        Half-width of the repulsive region (the gap below ``z0``), 0 where there is none.
    residual : float
        Largest residual of the gap equation at the nodes, relative to the gap there.
    n : int
        Nodes of the finest mesh.
    converged : bool
        Always ``True`` (a state that does not converge raises ``ConvergenceError``).
    xi, gap_over_z0, pressure : ndarray
        The nodes (half line), the gap and ``p z0/w`` there (finest mesh).
    """

    inputs: ClassVar[tuple[str, ...]] = ("central_gap_over_z0", "mu")

    central_gap_over_z0: float
    mu: float
    F: float
    error_estimate: float
    half_width: float
    residual: float
    n: int
    converged: bool
    xi: NDArray = field(default_factory=lambda: np.zeros(0), repr=False)
    gap_over_z0: NDArray = field(default_factory=lambda: np.zeros(0), repr=False)
    pressure: NDArray = field(default_factory=lambda: np.zeros(0), repr=False)


def _state_of(s: _Solved, mu: float) -> LJState:
    return LJState(
        central_gap_over_z0=s.zeta0,
        mu=mu,
        F=s.F,
        error_estimate=s.error,
        half_width=s.half_width,
        residual=s.residual,
        n=int(s.mesh.nodes.size),
        converged=True,
        xi=s.mesh.nodes,
        gap_over_z0=s.zeta,
        pressure=_law(s.zeta)[0],
    )


# ---------------------------------------------------------------------------------------
# the curve F(g0): continuation in the central gap


def _check_mu(mu) -> float:
    from . import domain as _domain

    return float(_domain.scalar("mu", mu, key="lj_mu"))


def _fail(what: str, mu: float, zeta0: float) -> ConvergenceError:
    return ConvergenceError(
        f"Lennard-Jones {what} did not converge at mu={mu!r}, central_gap_over_z0={zeta0!r}"
    )


def _first(mu: float, grid: _Grid) -> _Solved:
    """The state at ``_START``: Newton from the rigid profile, continued in ``mu`` if need be."""
    spec = grid.spec(0.0)
    s = _solve(_START, mu, spec, None)
    if s is not None:
        return s
    done, step, guess = 0.0, mu / 8, None
    while done < mu:
        nxt = min(mu, done + step)
        t = _solve(_START, nxt, spec, guess)
        if t is None:
            step *= 0.5
            if step < 1e-9 * mu:
                raise _fail("curve", mu, _START)
            continue
        done, guess, s, step = nxt, t.zeta, t, 2 * step
    assert s is not None
    return s


def _arc_newton(mu, mesh, zeta, zeta0, anchor, tangent, ds, scales, v, tol=_TOL):
    """Corrector of pseudo-arclength continuation in the central gap, the load and the profile.

    Unknowns: the gaps and ``zeta0``. Equations: the gap equation and ``tz (zeta0 - z_a)/sz
    + tF (F - F_a)/sF + sum_i v_i tv_i (ln zeta_i - ln zeta_a,i) = ds``, with ``(tz, tF,
    tv)`` the unit tangent in that metric (weights ``v``). The bordered system is solved by
    block elimination with the (chord) factorisation of the gap equation's Jacobian.
    Returns ``(zeta, zeta0, ok)``.
    """
    import scipy.linalg

    nodes, K, w = mesh.nodes, mesh.K, mesh.w
    z_a, F_a, l_a = anchor
    tz, tF, tv = tangent
    sz, sF = scales
    vt = v * tv
    c = 2.0 * mu / math.pi
    half = 0.5 * nodes * nodes
    ones = np.ones(nodes.size)
    lu = mesh.lu.get(mu)
    res, fresh = math.inf, False
    for _ in range(40):
        P, dP = _law(zeta)
        r = zeta - zeta0 - half + c * (K @ P)
        F = 2.0 * float(w @ P)
        q = tz * (zeta0 - z_a) / sz + tF * (F - F_a) / sF + vt @ (np.log(zeta) - l_a) - ds
        res_new = max(float(np.max(np.abs(r) / zeta)), abs(q) * 1e-3)
        if res_new <= tol:
            return zeta, zeta0, True
        if not np.isfinite(res_new):
            return zeta, zeta0, False
        lu, fresh, failing = _chord(lu, fresh, res_new / res, mu, mesh, dP)
        if failing:
            return zeta, zeta0, False
        res = res_new
        # J dz - dzeta0 = -r ; a.dz + b dzeta0 = -q
        y1 = scipy.linalg.lu_solve(lu, -r, check_finite=False)
        y2 = scipy.linalg.lu_solve(lu, ones, check_finite=False)
        a = (tF / sF) * 2.0 * (w * dP) + vt / zeta
        b = tz / sz
        d0 = (-q - a @ y1) / (a @ y2 + b)
        dz = y1 + d0 * y2
        lam = 1.0
        while np.any(zeta + lam * dz <= 0.05 * zeta) and lam > 1e-6:
            lam *= 0.5
        zeta = zeta + lam * dz
        zeta0 = zeta0 + lam * d0
        if zeta0 <= 0.0:
            return zeta, zeta0, False
    return zeta, zeta0, False


def _march(mu: float, F_stop: float, grid: _Grid) -> list[_Solved]:
    """States from ``_START`` along the curve until the load passes ``F_stop`` (> 0).

    Pseudo-arclength continuation in the central gap (scale 0.1), the load (scale: the
    larger of 0.1, the load and the most tensile load met so far) and the profile (``ln
    zeta`` in the L2 norm over the edge length, so a step moves the edge by about half an
    edge length at most: near the pull-off of a compliant contact the edge travels far
    while the load and the central gap hardly change). The curve is followed through
    turning points in either. A secant predictor; a failed step is halved, and below 1e-9
    it raises ``ConvergenceError``. The band of the meshes follows the edge
    (:func:`_follow`).
    """
    s = _first(mu, grid)
    out = [s]
    ds, sz = 0.5, 0.1
    while not (s.F >= F_stop and s.half_width > 0):
        sF = max(0.1, abs(s.F), -min(p.F for p in out))
        fine = s.mesh
        v = fine.w / grid.ell
        ls = np.log(s.zeta)
        if len(out) > 1:
            prev = out[-2]
            zp = _on(prev, fine)
            dzs, dFs = (s.zeta0 - prev.zeta0) / sz, (s.F_fine - prev.F_fine) / sF
            dls = ls - np.log(zp)
            norm = math.sqrt(dzs * dzs + dFs * dFs + float(v @ (dls * dls)))
            tangent = (dzs / norm, dFs / norm, dls / norm)
            guess = s.zeta + (s.zeta - zp) * (ds / norm)
            g0 = s.zeta0 + (s.zeta0 - prev.zeta0) * (ds / norm)
            if np.any(guess <= 0.1 * s.zeta) or g0 <= 0.0:
                guess, g0 = s.zeta, s.zeta0 + tangent[0] * sz * ds
        else:
            tangent = (-1.0, 0.0, np.zeros(fine.nodes.size))
            guess, g0 = s.zeta - sz * ds, s.zeta0 - sz * ds
        zeta, zeta0, ok = _arc_newton(
            mu, fine, guess, g0, (s.zeta0, s.F_fine, ls), tangent, ds, (sz, sF), v
        )
        t = _finish(zeta0, mu, _meshes(fine.spec), zeta) if ok else None
        if t is None:
            ds *= 0.5
            if ds < 1e-9:
                raise _fail("curve", mu, s.zeta0)
            continue
        t = _follow(mu, grid, t)
        out.append(t)
        s = t
        ds = min(0.5, 1.5 * ds)
    return out


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


def _refine_extremum(mu, grid, states, i, sign) -> _Solved:
    """The extremum of ``sign * F`` between states ``i - 1`` and ``i + 1`` (Brent).

    Each trial state is continued from the nearest state solved so far (Newton, or where
    that fails steps in the central gap, :func:`_march_to`).
    """
    import scipy.optimize

    a, b = states[i + 1], states[i - 1]  # zeta0 decreases along the march
    known = [a, states[i], b]
    cache: list[_Solved] = []

    def f(z: float) -> float:
        near = min(known, key=lambda s: abs(s.zeta0 - z))
        s = _solve(z, mu, near.mesh.spec, near.zeta)
        if s is None:
            try:
                s = _march_to(mu, grid, near, z) if near.zeta0 > z else None
            except ConvergenceError:
                s = None
            if s is None or s.zeta0 != z:
                raise _Unsolved
        known.append(s)
        cache.append(s)
        return sign * s.F

    try:
        scipy.optimize.minimize_scalar(
            f, bounds=(a.zeta0, b.zeta0), method="bounded", options={"xatol": 1e-9}
        )
    except _Unsolved:  # a state between the samples the meshes cannot hold: keep the best
        pass
    return min([states[i], *cache], key=lambda s: sign * s.F)


class _Unsolved(Exception):
    """A state between two samples of the curve that Newton did not solve."""


@dataclass(frozen=True)
class LJCurve(Result):
    """The load curve ``F(g0)`` under the Lennard-Jones law (nondimensional, as :class:`LJState`).

    Columns (one per point, the central gap decreasing): ``central_gap_over_z0``, ``F``,
    ``error_estimate``, ``half_width``, ``stable`` (under load control: ``dF/dg0 < 0``) and
    ``turning`` (the extrema of the load: pull-off and, where the curve is S-shaped, the
    jump-in load and the local minimum before it). ``pull_off`` holds the pull-off point.
    """

    inputs: ClassVar[tuple[str, ...]] = ("mu",)

    central_gap_over_z0: NDArray
    F: NDArray
    error_estimate: NDArray
    half_width: NDArray
    stable: NDArray
    turning: NDArray
    mu: float
    pull_off: LJPullOff = field(repr=False)


@dataclass(frozen=True)
class LJPullOff(Result):
    """Pull-off under the Lennard-Jones law (nondimensional, as :class:`LJState`).

    Attributes
    ----------
    mu : float
    F_pulloff, central_gap_at_pulloff, half_width_at_pulloff, error_estimate : float
        The most tensile load of the curve (jump-out under load control), where it occurs,
        and the estimated error of the load.
    F_jump_in, central_gap_at_jump_in : float
        The local maximum of the load where the curve is S-shaped (under load control a
        loosely held fibre snaps into contact there); ``nan`` where the load has one minimum.
    maugis_parameter : float
        Of the Dugdale step with the Maugis matching (:func:`maugis_parameter_of_mu`).
    n : int
        Nodes of the finest mesh.
    converged : bool
    """

    inputs: ClassVar[tuple[str, ...]] = ("mu",)

    mu: float
    F_pulloff: float
    central_gap_at_pulloff: float
    half_width_at_pulloff: float
    error_estimate: float
    F_jump_in: float
    central_gap_at_jump_in: float
    maugis_parameter: float
    n: int
    converged: bool


def _extrema(mu, grid, states) -> tuple[_Solved, _Solved | None, list[int]]:
    """Pull-off (global minimum) and jump-in (a local maximum, if any) of the marched curve."""
    F = np.array([s.F for s in states])
    idx_min = [i for i in range(1, F.size - 1) if F[i] <= F[i - 1] and F[i] < F[i + 1]]
    idx_max = [i for i in range(1, F.size - 1) if F[i] >= F[i - 1] and F[i] > F[i + 1]]
    if not idx_min:
        raise _fail("pull-off search (no minimum of the load)", mu, states[-1].zeta0)
    i_po = min(idx_min, key=lambda i: F[i])
    po = _refine_extremum(mu, grid, states, i_po, 1.0)
    jump = None
    before = [i for i in idx_max if i < i_po]
    if before:  # the last maximum before the pull-off branch: the snap into contact
        jump = _refine_extremum(mu, grid, states, before[-1], -1.0)
    return po, jump, sorted(idx_min + idx_max)


def _pull_off_of(mu, po, jump) -> LJPullOff:
    return LJPullOff(
        mu=mu,
        F_pulloff=po.F,
        central_gap_at_pulloff=po.zeta0,
        half_width_at_pulloff=po.half_width,
        error_estimate=po.error,
        F_jump_in=math.nan if jump is None else jump.F,
        central_gap_at_jump_in=math.nan if jump is None else jump.zeta0,
        maugis_parameter=float(maugis_parameter_of_mu(mu)),
        n=int(po.mesh.nodes.size),
        converged=True,
    )


#: Default end of a curve: three times the rigid cylinder's pull-off, compressive.
F_MAX_DEFAULT = 7.5


def lj_curve(mu: float, *, F_max: float | None = None, m: int | None = None) -> LJCurve:
    """The load curve ``F(g0)`` from far away through its turning points to ``F_max``.

    Parameters
    ----------
    mu : float
        ``w sqrt(R/z0)/(E z0)``, ``>= 0`` (0: rigid).
    F_max : float, optional
        Compressive load where the curve ends (over ``w sqrt(R/z0)``), default
        :data:`F_MAX_DEFAULT`.
    m : int
        Elements of the uniform core on the finest mesh (multiple of 4).
    """
    mu = _check_mu(mu)
    F_max = F_MAX_DEFAULT if F_max is None else float(F_max)
    if not (np.isfinite(F_max) and F_max > 0):
        raise ValueError(f"F_max must be a finite load > 0, got {F_max!r}")
    grid = _grid_for(mu, m)
    states = _march(mu, F_max, grid)
    po, jump, turns = _extrema(mu, grid, states)
    z = np.array([s.zeta0 for s in states])
    F = np.array([s.F for s in states])
    dF = np.gradient(F, z)
    turning = np.zeros(z.size, bool)
    turning[turns] = True
    return LJCurve(
        central_gap_over_z0=z,
        F=F,
        error_estimate=np.array([s.error for s in states]),
        half_width=np.array([s.half_width for s in states]),
        stable=dF < 0,
        turning=turning,
        mu=mu,
        pull_off=_pull_off_of(mu, po, jump),
    )


def _check_m(m) -> int:
    if not isinstance(m, (int, np.integer)) or m < 16 or m % 4:
        raise ValueError(f"m must be an integer >= 16 and a multiple of 4, got {m!r}")
    return int(m)


def lj_pull_off(mu: float, *, m: int | None = None) -> LJPullOff:
    """The pull-off force (the most tensile load of :func:`lj_curve`) and the jump-in load."""
    mu = _check_mu(mu)
    grid = _grid_for(mu, m)
    states = _march(mu, 1e-3, grid)
    po, jump, _ = _extrema(mu, grid, states)
    return _pull_off_of(mu, po, jump)


def lj_state(central_gap_over_z0: float, mu: float, *, m: int | None = None) -> LJState:
    """The equilibrium state at the central gap ``zeta0`` (continued from far away)."""
    from . import domain as _domain

    z = float(_domain.scalar("central_gap_over_z0", central_gap_over_z0))
    mu = _check_mu(mu)
    grid = _grid_for(mu, m)
    s = _first(mu, grid)
    if z >= _START:
        t = _solve(z, mu, s.mesh.spec, s.zeta)
        if t is None:
            raise _fail("state", mu, z)
        return _state_of(t, mu)
    return _state_of(_march_to(mu, grid, s, z), mu)


def _march_to(mu, grid: _Grid, s: _Solved, z: float) -> _Solved:
    """Continue from ``s`` down to the central gap ``z`` (steps as in :func:`_march`)."""
    dz = 0.1
    prev = None
    while s.zeta0 > z:
        step = min(dz, s.zeta0 - z)
        guess = s.zeta
        if prev is not None:
            guess = s.zeta + (s.zeta - _on(prev, s.mesh)) * (step / (prev.zeta0 - s.zeta0))
            if np.any(guess <= 0.1 * s.zeta):
                guess = s.zeta
        t = _solve(s.zeta0 - step if step < s.zeta0 - z else z, mu, s.mesh.spec, guess)
        if t is None or abs(t.F - s.F) > 0.2 * max(abs(s.F), 0.1):
            dz = 0.5 * step
            if dz < 1e-12:
                raise _fail("state", mu, s.zeta0)
            continue
        prev, s = s, _follow(mu, grid, t)
        dz = min(0.1, 2 * step)
    return s


def lj_contact_for_load(F: float, mu: float, *, m: int | None = None) -> LJState:
    """The state on the stable contact branch (beyond the pull-off) carrying the load ``F``.

    Raises :class:`~linecontact.errors.NoEquilibriumError` for a load below the pull-off.
    """
    import scipy.optimize

    F = float(F)
    if not np.isfinite(F):
        raise ValueError(f"F must be finite, got {F!r}")
    mu = _check_mu(mu)
    grid = _grid_for(mu, m)
    states = _march(mu, max(F, 1e-3), grid)
    po, _, _ = _extrema(mu, grid, states)
    if F < po.F:
        raise NoEquilibriumError(
            f"no equilibrium: the load F={F!r} is below the pull-off force {po.F!r} "
            f"(mu={mu!r}); the contact has already pulled off"
        )
    branch = [s for s in states if s.zeta0 < po.zeta0]
    branch.insert(0, po)
    k = next(i for i in range(1, len(branch)) if branch[i].F >= F)
    a, b = branch[k], branch[k - 1]
    if F == a.F:
        return _state_of(a, mu)
    cache: dict[float, _Solved] = {}

    cache[a.zeta0], cache[b.zeta0] = a, b  # the bracket's ends keep their own loads (a
    # state solved again may land on the other side of F by its round-off)

    def g(z: float) -> float:
        if z in cache:
            return cache[z].F - F
        t = (z - a.zeta0) / (b.zeta0 - a.zeta0)
        s = _solve(z, mu, b.mesh.spec, _on(a, b.mesh) + t * (b.zeta - _on(a, b.mesh)))
        if s is None:  # the samples are far apart: continue from the upper one
            s = _march_to(mu, grid, b, z)
        cache[z] = s
        return s.F - F

    if F == b.F:
        return _state_of(b, mu)
    z = scipy.optimize.brentq(g, a.zeta0, b.zeta0, xtol=1e-14, rtol=1e-13)
    if z not in cache:
        g(z)
    return _state_of(cache[z], mu)


# ---------------------------------------------------------------------------------------
# in the groups of the Dugdale problem (the law="lennard-jones" of linecontact.pull_off)


@dataclass(frozen=True)
class LennardJonesPullOff(Result):
    """Pull-off under the Lennard-Jones law, in the groups of the Maugis-Dugdale problem.

    The law has the work of adhesion ``w = sigma0 h`` of the Dugdale step and its peak
    tension ``sigma0`` (the Maugis matching: ``z0 = h / 0.974``). Loads over ``E h``, widths
    over ``R``, gaps over ``h``: the same units as :class:`linecontact.PullOff`.

    Attributes
    ----------
    F_pulloff_over_Eh, error_estimate_over_Eh : float or ndarray
        The pull-off force (the most tensile load) and its estimated error.
    a_over_R_at_pulloff : float or ndarray
        Half-width of the repulsive region there (0: the pull-off precedes it).
    central_gap_over_h_at_pulloff : float or ndarray
    F_jump_in_over_Eh : float or ndarray
        The jump-in load where the curve is S-shaped, else ``nan``.
    mu, maugis_parameter : float or ndarray
        The group ``w sqrt(R/z0)/(E z0)`` and the Maugis parameter of the step.
    law : str
        ``"lennard-jones"``.
    n : int
        Nodes of the finest mesh.
    converged : bool or ndarray
    """

    inputs: ClassVar[tuple[str, ...]] = ("R_over_h", "sigma0_over_E")

    F_pulloff_over_Eh: NDArray | float
    a_over_R_at_pulloff: NDArray | float
    central_gap_over_h_at_pulloff: NDArray | float
    F_jump_in_over_Eh: NDArray | float
    error_estimate_over_Eh: NDArray | float
    mu: NDArray | float
    maugis_parameter: NDArray | float
    R_over_h: NDArray | float
    sigma0_over_E: NDArray | float
    law: str
    n: NDArray | int
    converged: NDArray | bool


def lj_groups(R_over_h, sigma0_over_E) -> tuple[NDArray, NDArray, NDArray]:
    """``(mu, sqrt(R/z0), load scale w sqrt(R/z0)/(E h))`` at validated Dugdale groups.

    Refuses ``sigma0_over_E = 0`` (no work of adhesion) and ``mu`` beyond the domain
    ``DOMAIN["lj_mu"]``, naming the point. The one conversion of the Dugdale groups to the
    law's own units (:mod:`linecontact.lennard_jones_groups` re-exports it).
    """
    rho = np.asarray(R_over_h, float)
    s = np.asarray(sigma0_over_E, float)
    if np.any(s <= 0):
        raise ValueError(
            "sigma0_over_E must be > 0 for the Lennard-Jones law (it sets the work of "
            f"adhesion w = sigma0 h), got {float(s[s <= 0].flat[0])!r}"
        )
    mu, R_over_z0 = mu_of_dugdale(rho, s)
    hi = _DOMAIN_MU_HIGH()
    if np.any(mu > hi):
        _, at = first_point(mu > hi, rho=rho, s=s, mu=mu)
        raise ValueError(
            f"the Lennard-Jones law is solved for mu = (sigma0/E) sqrt(R/h) * "
            f"{MAUGIS_MATCH_SIGMA0**-1.5:.4f} in [0, {hi:g}] (Maugis parameter up to "
            f"{float(maugis_parameter_of_mu(hi)):.3g}); R_over_h={at['rho']!r}, "
            f"sigma0_over_E={at['s']!r} give mu={at['mu']:.6g}"
        )
    root = np.sqrt(R_over_z0)
    return np.asarray(mu, float), root, s * root


def pull_off_of(po: LJPullOff, R_over_h: float, sigma0_over_E: float) -> LennardJonesPullOff:
    """The native pull-off ``po`` in the Dugdale groups (scalars): the one conversion."""
    mu, root, scale = (float(v) for v in lj_groups(R_over_h, sigma0_over_E))
    return LennardJonesPullOff(
        F_pulloff_over_Eh=po.F_pulloff * scale,
        a_over_R_at_pulloff=po.half_width_at_pulloff / root,
        central_gap_over_h_at_pulloff=po.central_gap_at_pulloff * MAUGIS_MATCH_SIGMA0,
        F_jump_in_over_Eh=po.F_jump_in * scale,
        error_estimate_over_Eh=po.error_estimate * scale,
        mu=po.mu,
        maugis_parameter=po.maugis_parameter,
        R_over_h=float(R_over_h),
        sigma0_over_E=float(sigma0_over_E),
        law="lennard-jones",
        n=po.n,
        converged=po.converged,
    )


def pull_off_in_dugdale_groups(R_over_h, sigma0_over_E) -> LennardJonesPullOff:
    """:func:`lj_pull_off` at Dugdale groups (validated arrays of one shape, or scalars).

    Each point is :func:`pull_off_of` its native pull-off; the public entry point is
    :func:`linecontact.laws.lennard_jones.pull_off`.
    """
    from .results import as_output

    rho = np.asarray(R_over_h, float)
    s = np.asarray(sigma0_over_E, float)
    scalar = rho.ndim == 0 and s.ndim == 0
    rho, s = np.broadcast_arrays(rho, s)
    mu = lj_groups(rho, s)[0]
    fields = {
        "F_pulloff_over_Eh": float,
        "a_over_R_at_pulloff": float,
        "central_gap_over_h_at_pulloff": float,
        "F_jump_in_over_Eh": float,
        "error_estimate_over_Eh": float,
        "n": int,
    }
    vals: dict[str, NDArray] = {k: np.empty(rho.shape, dt) for k, dt in fields.items()}
    for i in np.ndindex(rho.shape):
        q = pull_off_of(lj_pull_off(float(mu[i])), float(rho[i]), float(s[i]))
        for k in fields:
            vals[k][i] = getattr(q, k)

    def o(v):
        return as_output(v, scalar)

    return LennardJonesPullOff(
        **{k: o(v) for k, v in vals.items()},
        mu=o(mu),
        maugis_parameter=o(maugis_parameter_of_mu(mu)),
        R_over_h=o(rho),
        sigma0_over_E=o(s),
        law="lennard-jones",
        converged=o(np.ones(rho.shape, bool)),
    )


def _DOMAIN_MU_HIGH() -> float:  # noqa: N802
    from .domain import DOMAIN

    return DOMAIN["lj_mu"][2]
