"""The curve ``F(g0)`` of the Lennard-Jones law: continuation, pull-off, contact for a load.

Pseudo-arclength continuation in the central gap, the load and the profile from far away
through the turning points of the load; :func:`lj_curve`, :func:`lj_pull_off`,
:func:`lj_state`, :func:`lj_contact_for_load` and their results.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray

from ..errors import ConvergenceError, NoEquilibriumError
from ..results import Result
from ._matching import maugis_parameter_of_mu
from ._solver import (
    _START,
    _TOL,
    _chord,
    _finish,
    _follow,
    _Grid,
    _grid_for,
    _law,
    _meshes,
    _on,
    _solve,
    _Solved,
)

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
    from .. import domain as _domain

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


def lj_pull_off(mu: float, *, m: int | None = None) -> LJPullOff:
    """The pull-off force (the most tensile load of :func:`lj_curve`) and the jump-in load."""
    mu = _check_mu(mu)
    grid = _grid_for(mu, m)
    states = _march(mu, 1e-3, grid)
    po, jump, _ = _extrema(mu, grid, states)
    return _pull_off_of(mu, po, jump)


def lj_state(central_gap_over_z0: float, mu: float, *, m: int | None = None) -> LJState:
    """The equilibrium state at the central gap ``zeta0`` (continued from far away)."""
    from .. import domain as _domain

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
