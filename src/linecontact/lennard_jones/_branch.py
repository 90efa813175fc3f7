"""The curve of the Lennard-Jones law along its edge: far states, the edge, the extrema.

Far away the states are controlled by the central gap ``zeta0`` (from :data:`_START` down to
:data:`_EDGE_GAP`, on one mesh); from there on by the edge ``e``, where the gap crosses
``_EDGE_GAP z0`` (:func:`_edge_newton`). The edge moves one way along the whole rest of the
curve -- through the jump-in, the pull-off and the compressive branch -- while the central
gap hardly moves along the contact branch of a compliant contact, so the edge is the
control that holds there. The extrema of the load are refined by Brent's method in the
control of their neighbourhood; the pull-off alone (:func:`pull_off_search`) jumps from the
small edges to the Maugis-Dugdale pull-off at the matched parameters and brackets the
minimum about it. Derivation and checks: ``docs/lennard-jones.md``.
"""

from __future__ import annotations

import functools
import math
import operator
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from ..errors import ConvergenceError
from ._solver import (
    _EDGE_GAP,
    _START,
    _edge_meshes,
    _edge_newton,
    _finish,
    _Grid,
    _law,
    _md_guess,
    _Mesh,
    _solve,
    _solve_edge,
    _Solved,
)

#: Central gaps of the far part: geometric from ``_START`` to ``_EDGE_GAP`` (this many).
_N_FAR = 9
#: The step of the edge below ``_SCALED_FROM`` edge lengths, in edge lengths.
_E_SLOW = 0.25
#: Beyond, the edge grows by this fraction per step.
_E_GROWTH = 0.4
#: The pull-off jumps to the Maugis-Dugdale estimate where that is this far beyond the edge.
_JUMP = 2.0
#: Relative half-width of the first bracket about that estimate.
_BRACKET = 0.05
#: The largest error estimate of a pull-off or jump-in, relative to it, taken as resolved.
_RESOLVED = 1e-3
#: The refinement of an extremum: at most this many states, and the control to this
#: (relative).
_REFINE_MAX = 12
_REFINE_XTOL = 1e-5
_REFINE_FTOL = 1e-11


def fail(what: str, mu: float, zeta0: float) -> ConvergenceError:
    """The error of a state that did not converge, naming the point."""
    return ConvergenceError(
        f"Lennard-Jones {what} did not converge at mu={mu!r}, central_gap_over_z0={zeta0!r}"
    )


def first(mu: float, grid: _Grid) -> _Solved:
    """The state at ``_START``: Newton from the rigid profile, continued in ``mu`` if need be."""
    meshes = grid.meshes(grid.small())
    s = _solve(_START, mu, meshes, None)
    if s is not None:
        return s
    done, step, guess = 0.0, mu / 8, None
    while done < mu:
        nxt = min(mu, done + step)
        t = _solve(_START, nxt, meshes, guess)
        if t is None:
            step *= 0.5
            if step < 1e-9 * mu:
                raise fail("curve", mu, _START)
            continue
        done, guess, s, step = nxt, t.zeta, t, 2 * step
    assert s is not None
    return s


def far(mu: float, grid: _Grid) -> list[_Solved]:
    """The states at the central gaps from ``_START`` down to ``_EDGE_GAP`` (one mesh)."""
    out = [first(mu, grid)]
    for z in np.geomspace(_START, _EDGE_GAP, _N_FAR)[1:]:
        s = out[-1]
        t = _solve(float(z), mu, grid.meshes(s.mesh.spec), s.zeta)
        if t is None:
            t = _down(mu, grid, s, float(z))
        out.append(t)
    return out


def _down(mu: float, grid: _Grid, s: _Solved, z: float) -> _Solved:
    """``s`` continued in the central gap down to ``z`` by halved steps (far part only)."""
    dz = 0.5 * (s.zeta0 - z)
    while s.zeta0 > z:
        nxt = max(z, s.zeta0 - dz)
        t = _solve(nxt, mu, grid.meshes(s.mesh.spec), s.zeta)
        if t is None:
            dz *= 0.5
            if dz < 1e-9:
                raise fail("curve", mu, s.zeta0)
            continue
        s, dz = t, 2 * dz
    return s


def _on(s: _Solved, mesh: _Mesh, e: float, stretch: bool) -> NDArray:
    """The gaps of ``s`` at the nodes of ``mesh`` (stretched from its edge to ``e``)."""
    x = mesh.nodes * (s.edge / e) if stretch else mesh.nodes
    return np.interp(x, s.mesh.nodes, s.zeta)


def predict(states: list[_Solved], e: float, mesh: _Mesh, ell: float) -> tuple[NDArray, float]:
    """First guess of the state with its edge at ``e`` from the two nearest states.

    Each profile is first stretched so that its edge falls on ``e`` (near the edge the
    profile moves with it; inside the contact it is nearly flat, and far away Newton
    corrects the parabola in a step), then extrapolated linearly in ``e``, no lower than
    the lower of the two (an undershoot into the repulsive range costs many iterations).
    """
    near = sorted(states, key=lambda s: abs(s.edge - e))[:2]
    s = near[0]
    if len(near) < 2 or near[1].edge == s.edge:
        return _on(s, mesh, e, s.edge > 0.0), s.zeta0
    p = near[1]
    zs, zp = _on(s, mesh, e, s.edge > 0.0), _on(p, mesh, e, p.edge > 0.0)
    t = (e - s.edge) / (s.edge - p.edge)
    return np.maximum(zs + t * (zs - zp), np.minimum(zs, zp)), s.zeta0 + t * (s.zeta0 - p.zeta0)


def at_edge(mu: float, grid: _Grid, states: list[_Solved], e: float) -> _Solved | None:
    """The state with its edge at ``e``, from the nearest of ``states``; ``None`` on failure."""
    meshes = _edge_meshes(grid, e)
    guess, g0 = predict(states, e, meshes[0], grid.ell)
    return _solve_edge(e, mu, meshes, guess, g0)


def _step(e: float, grid: _Grid) -> float:
    """The next step of the edge.

    One coarse element of the small mesh first, then :data:`_E_SLOW` edge lengths (whole
    elements) up to its end, then :data:`_E_GROWTH` of the edge.
    """
    if e <= 0.0:
        return grid.hb
    if e < grid.small_end():
        return grid.hb * max(1, round(_E_SLOW * grid.ell / grid.hb))
    return _E_GROWTH * e


def _next(e: float, step: float, grid: _Grid) -> float:
    """``e + step``, on the small mesh's coarse nodes (and its end) while it holds them."""
    end = grid.small_end()
    x = e + step
    if e < end and step >= grid.hb:
        x = min(grid.hb * round(x / grid.hb), end)
    return x if x > e else e + step


def climb(
    mu: float, grid: _Grid, states: list[_Solved], done: Callable[[list[_Solved]], bool]
) -> list[_Solved]:
    """``states`` continued along the edge until ``done(states)``.

    Steps of :func:`_step`; a failed step is halved, and below a millionth of an edge length
    it raises ``ConvergenceError``.
    """
    out = list(states)
    e = out[-1].edge
    step = _step(e, grid)
    while not done(out):
        t, step = _advance(
            mu, grid, out[-2:], functools.partial(_next, e, grid=grid), step, "curve"
        )
        out.append(t)
        e = t.edge
        step = min(2.0 * step, _step(e, grid))
    return out


def _advance(
    mu: float,
    grid: _Grid,
    near: list[_Solved],
    edge_at: Callable[[float], float],
    step: float,
    what: str,
) -> tuple[_Solved, float]:
    """The state at the edge ``edge_at(step)`` from ``near``, and the step that reached it.

    A step whose state Newton does not solve is halved; below a millionth of an edge length
    it raises ``ConvergenceError`` naming ``what``.
    """
    while True:
        t = at_edge(mu, grid, near, edge_at(step))
        if t is not None:
            return t, step
        step *= 0.5
        if step < 1e-6 * grid.ell:
            raise fail(what, mu, near[-1].zeta0)


# ---------------------------------------------------------------------------------------
# the extrema


class _Unsolved(Exception):
    """A state between two samples of the curve that Newton did not solve."""


def _fine(mu: float, grid: _Grid, known: list[_Solved], e: float) -> _Solved:
    """The state at the edge ``e`` on the fine mesh alone (its load unextrapolated)."""
    meshes = _edge_meshes(grid, e)
    guess, g0 = predict(known, e, meshes[0], grid.ell)
    z, z0, ok = _edge_newton(e, mu, meshes[0], guess, g0)
    if not ok:
        raise _Unsolved
    F = 2.0 * float(meshes[0].w @ _law(z)[0])
    return _Solved(z0, F, 0.0, F, 0.0, 0.0, z, meshes[0], e)


def _parabola(
    x: Callable[[_Solved], float],
    solve: Callable[[float], _Solved],
    a: _Solved,
    b: _Solved,
    c: _Solved,
    sign: float,
) -> _Solved:
    """The extremum of ``sign * F_fine`` in the control ``x`` bracketed by ``a < b < c``.

    Successive parabolic interpolation through the best state and its neighbours (a
    golden-section step into the wider side where the vertex falls outside the bracket or
    on its best point), until the control moves by less than :data:`_REFINE_XTOL` of itself
    (the load then within ``~1e-10`` of the extremum, relative) or after
    :data:`_REFINE_MAX` states. A state that does not converge ends it with the best so far.
    """
    for _ in range(_REFINE_MAX):
        xa, xb, xc = x(a), x(b), x(c)
        fa, fb, fc = sign * a.F_fine, sign * b.F_fine, sign * c.F_fine
        p, q = (xb - xa) * (fb - fc), (xb - xc) * (fb - fa)
        v = xb - ((xb - xa) * p - (xb - xc) * q) / (2.0 * (p - q)) if p != q else xb
        golden = not (xa < v < xc) or abs(v - xb) <= 1e-9 * abs(xb)
        if golden:
            v = xb + 0.381966 * ((xc if xc - xb > xb - xa else xa) - xb)
        try:
            t = solve(v)
        except _Unsolved:
            break
        if sign * t.F_fine < fb:
            a, b, c = (a, t, b) if v < xb else (b, t, c)
        elif v < xb:
            a = t
        else:
            c = t
        if not golden and (
            abs(v - xb) <= _REFINE_XTOL * abs(xb)
            or abs(t.F_fine - fb * sign) <= _REFINE_FTOL * abs(fb)
        ):
            break
    return b


def _refine_gap(mu: float, grid: _Grid, states: list[_Solved], i: int, sign: float) -> _Solved:
    """The extremum of ``sign * F`` about sample ``i`` in the central gap, on the small mesh.

    The central gap decreases along the curve, so the bracket is ``i + 1, i, i - 1``; states
    on other meshes among them are solved again there at their central gaps.
    """
    meshes = grid.meshes(grid.small())
    small = meshes[0]
    nodes = small.nodes
    known = [s for s in states[i - 1 : i + 2] if s.mesh is small]

    def solve(z: float) -> _Solved:
        near = min(known or states[i - 1 : i + 2], key=lambda s: abs(s.zeta0 - z))
        t = _solve(z, mu, meshes, np.interp(nodes, near.mesh.nodes, near.zeta))
        if t is None:
            raise _Unsolved
        known.append(t)
        return t

    bracket = (states[i + 1], states[i], states[i - 1])
    a, b, c = (s if s.mesh is small else solve(s.zeta0) for s in bracket)
    return _parabola(lambda s: s.zeta0, solve, a, b, c, sign)


def refine_edge(mu: float, grid: _Grid, states: list[_Solved], i: int, sign: float) -> _Solved:
    """The extremum of ``sign * F`` about sample ``i`` in the edge.

    :func:`_parabola` on the fine mesh's load, then the state there on the three meshes
    (Richardson and the estimate, :func:`_finish`).
    """
    pool = list(states)

    def solve(e: float) -> _Solved:
        t = _fine(mu, grid, pool, e)
        pool.append(t)
        return t

    a, b, c = states[i - 1 : i + 2]
    best = _parabola(lambda s: s.edge, solve, a, b, c, sign)
    if any(best is s for s in states):
        return best
    s = _finish(best.zeta0, mu, _edge_meshes(grid, best.edge), best.zeta, edge=best.edge)
    if s is None:
        raise fail("extremum of the load", mu, best.zeta0)
    return s


def refine(mu: float, grid: _Grid, states: list[_Solved], i: int, sign: float) -> _Solved:
    """The extremum of ``sign * F`` about sample ``i`` (by its control)."""
    if states[i + 1].edge <= grid.small_end() * (1.0 + 1e-12):  # on the small mesh
        return _refine_gap(mu, grid, states, i, sign)
    return refine_edge(mu, grid, states, i, sign)


def root(
    g: Callable[[float], float], a: float, b: float, ga: float, gb: float, xtol: float, ftol: float
) -> float:
    """A root of ``g`` in ``[a, b]`` (``ga``, ``gb`` of opposite signs).

    The Illinois method (regula falsi with the stale end's value halved), until ``|g| <=
    ftol`` or the bracket is within ``xtol``.
    """
    side = 0
    x = a
    for _ in range(100):
        x = b - gb * (b - a) / (gb - ga)
        gx = g(x)
        if abs(gx) <= ftol or abs(b - a) <= xtol:
            return x
        if (gx > 0) == (gb > 0):
            b, gb = x, gx
            if side == -1:
                ga *= 0.5
            side = -1
        else:
            a, ga = x, gx
            if side == 1:
                gb *= 0.5
            side = 1
        if abs(b - a) <= xtol:
            return x
    return x


def extrema(F: NDArray) -> tuple[list[int], list[int]]:
    """Indices of the interior local minima and maxima of the sampled load."""
    n = F.size
    lo = [i for i in range(1, n - 1) if F[i] <= F[i - 1] and F[i] < F[i + 1]]
    hi = [i for i in range(1, n - 1) if F[i] >= F[i - 1] and F[i] > F[i + 1]]
    return lo, hi


def turning_points(
    mu: float, grid: _Grid, states: list[_Solved], local_minimum: bool = True
) -> tuple[_Solved, _Solved | None, _Solved | None, list[int]]:
    """The extrema of sampled states, each located by :func:`refine`.

    ``(pull-off, jump-in, local minimum, indices)``: the pull-off is the global minimum;
    the jump-in the last maximum before it and the local minimum the last minimum before
    that, where the curve is S-shaped (``None`` otherwise, or without ``local_minimum``);
    ``indices`` those of the samples nearest each extremum of the sampled load. Each is
    found by the same bracketed search (:func:`_parabola` on the curve's own solver), a
    maximum with the opposite sign. Raises ``ConvergenceError`` where the estimate of any
    exceeds :data:`_RESOLVED` of it (the meshes do not resolve it: never a number that
    looks converged).
    """
    F = np.array([s.F for s in states])
    idx_min, idx_max = extrema(F)
    if not idx_min:
        raise fail("pull-off search (no minimum of the load)", mu, states[-1].zeta0)
    i_po = min(idx_min, key=lambda i: F[i])
    po = refine(mu, grid, states, i_po, 1.0)
    jump = low = None
    before = [i for i in idx_max if i < i_po]
    if before:  # the last maximum before the pull-off branch: the snap into contact
        jump = refine(mu, grid, states, before[-1], -1.0)
        lows = [i for i in idx_min if i < before[-1]]
        if lows and local_minimum:  # the local minimum of the S before it
            low = refine(mu, grid, states, lows[-1], 1.0)
    for what, t in (("pull-off", po), ("jump-in", jump), ("local minimum", low)):
        if t is not None and not t.error <= _RESOLVED * abs(t.F):
            raise ConvergenceError(
                f"Lennard-Jones {what} not resolved at mu={mu!r}: its error estimate "
                f"{t.error:.3g} exceeds {_RESOLVED:g} of the load {t.F:.6g}"
            )
    return po, jump, low, sorted(idx_min + idx_max)


# ---------------------------------------------------------------------------------------
# the pull-off alone


def _md_edge(mu: float) -> float:
    """The half-width of the Maugis-Dugdale load minimum at the matched parameters.

    The closed form's single stationary point of the load along the contact branch
    (:func:`~linecontact.closed_forms.maugis_dugdale._u_stationary`), whose ``abar =
    (a/R) sqrt(R/(2h))`` is ``a sqrt(S/2)`` in these units (``z0 = S h``): the start of
    the pull-off search where the contact is wide.
    """
    from ..closed_forms.groups import _kappa
    from ..closed_forms.maugis_dugdale import _branch_point, _u_stationary
    from ._matching import MAUGIS_MATCH_SIGMA0 as S

    rho = 1e6  # the matched groups depend on mu alone in these units
    kap = np.float64(_kappa(rho, mu * S**1.5 / math.sqrt(rho)))
    abar = float(_branch_point(np.asarray(_u_stationary(kap)), np.asarray(kap))["abar"])
    return abar * math.sqrt(2.0 / S)


def _past_hump(states: list[_Solved], grid: _Grid, a_md: float) -> bool:
    """Whether the small edges are done.

    The load compressive and rising (the pull-off behind); rising twice past a minimum of
    the edge states where the Maugis-Dugdale pull-off ``a_md`` is no further out (no deeper
    minimum ahead); or beyond the small mesh's end with the load falling (the pull-off
    ahead) or rising past a minimum.
    """
    s = states[-1]
    if len(states) < 3:
        return False
    rising = s.F > states[-2].F
    if rising and s.F > 0.0:
        return True
    if rising and states[-2].F > states[-3].F and a_md <= s.edge and _has_min(states):
        return True
    if s.edge < grid.small_end():
        return False
    return not rising or _has_min(states)


def _has_min(states: list[_Solved]) -> bool:
    F = np.array([s.F for s in states if s.edge > 0.0])
    return bool(extrema(F)[0])


def pull_off_search(mu: float, grid: _Grid) -> tuple[_Solved, _Solved | None]:
    """The pull-off and the jump-in without the whole curve.

    The far part and the small edges as on the curve (where the jump-in lies); then, where
    the load still falls, the Maugis-Dugdale pull-off at the matched parameters (its state
    from :func:`_md_guess`) where that lies more than :data:`_JUMP` times beyond, else
    further steps; the minimum bracketed about it and refined (:func:`refine_edge`).
    """
    a = _md_edge(mu) if mu > 0.0 else 0.0
    states = climb(mu, grid, far(mu, grid), lambda st: _past_hump(st, grid, a))
    F = np.array([s.F for s in states])
    if F[-1] < F[-2]:  # the pull-off lies ahead
        if a > _JUMP * states[-1].edge:
            states.append(_md_state(mu, grid, a))
        states = _bracket(mu, grid, states)
    po, jump, _, _ = turning_points(mu, grid, states, local_minimum=False)
    return po, jump


def _md_state(mu: float, grid: _Grid, a: float) -> _Solved:
    """The state near the Maugis-Dugdale contact of half-width ``a`` (its edge held)."""
    from ._solver import _half_width

    meshes = _edge_meshes(grid, a)
    zeta, zeta0 = _md_guess(a, mu, meshes[0])
    e = _half_width(meshes[0].nodes, zeta, _EDGE_GAP)
    meshes = _edge_meshes(grid, e)
    zeta, zeta0 = _md_guess(a, mu, meshes[0])
    s = _solve_edge(e, mu, meshes, zeta, zeta0)
    if s is None:
        raise fail("pull-off search (from the Maugis-Dugdale state)", mu, zeta0)
    return s


def _bracket(mu: float, grid: _Grid, states: list[_Solved]) -> list[_Solved]:
    """States on from the last one until the load rises.

    Growing steps (``_BRACKET`` of the edge first); the minimum is then bracketed by the last
    three.
    """
    out = list(states)
    step = max(_BRACKET * out[-1].edge, 0.25 * grid.ell)
    while out[-1].F <= out[-2].F:
        e = out[-1].edge
        t, step = _advance(
            mu, grid, out[-2:], functools.partial(operator.add, e), step, "pull-off search"
        )
        out.append(t)
        step *= 1.6
    if _jumped(out):  # the estimate overshot: bracket from below
        out = _below(mu, grid, out)
    return out


def _jumped(states: list[_Solved]) -> bool:
    """The first state after a jump already has the load rising from it."""
    n = len(states)
    return n >= 3 and states[-2].edge > _JUMP * states[-3].edge and states[-1].F > states[-2].F


def _below(mu: float, grid: _Grid, states: list[_Solved]) -> list[_Solved]:
    """After an overshooting jump: states below the jumped one until the load rises again."""
    jumped = states[-2]
    low = [jumped]
    step = _BRACKET * jumped.edge
    while True:
        e = low[0].edge
        near = [low[0], states[-1]]
        t, step = _advance(
            mu, grid, near, functools.partial(operator.sub, e), step, "pull-off search"
        )
        low.insert(0, t)
        if t.F > low[1].F or t.edge - step <= states[-3].edge:
            break
        step = min(1.6 * step, 0.5 * (t.edge - states[-3].edge))
    return states[:-2] + low + [states[-1]]


__all__ = [
    "at_edge",
    "climb",
    "extrema",
    "fail",
    "far",
    "first",
    "predict",
    "pull_off_search",
    "refine",
    "refine_edge",
    "root",
    "turning_points",
]
