r"""The self-consistent Lennard-Jones sphere (Greenwood 1997): its load curve and pull-off.

A sphere of radius :math:`R` on a flat, composite modulus :math:`E` (``1/E = (1 - nu1**2)/E1 +
(1 - nu2**2)/E2``), the surface traction everywhere the library's Lennard-Jones law of Eq. 1
(the Derjaguin approximation) at the local gap :math:`z`,

.. math::

    p(z) = -\frac{8 w}{3 z_0}\left[\left(\frac{z_0}{z}\right)^3
        - \left(\frac{z_0}{z}\right)^9\right] \quad\text{(compressive positive)},

with no separate contact and adhesive zones. The gap is

.. math::

    z(r) = -\delta + \frac{r^2}{2R} + u(r), \qquad
    u(r) = \frac{4}{\pi E}\int_0^\infty p(s)\,\frac{s}{r + s}\,
        K\!\left(\frac{2\sqrt{rs}}{r + s}\right) ds,

:math:`\delta` the approach (the far points' displacement towards each other).

**Units and scaling** (Greenwood 1997): radii over :math:`\sqrt{R z_0}`, gaps and the approach
over :math:`z_0`, pressures over :math:`w/z_0`, forces over :math:`\pi w R` (the rigid sphere's
pull-off, Bradley and Derjaguin, is :math:`-2`; JKR's under load control :math:`-3/2`). Then

.. math::

    \zeta(\varrho) = -\Delta + \frac{\varrho^2}{2}
        + \mu_T^{3/2} \int_0^\infty P(\zeta(s))\, D(\varrho, s)\, ds, \qquad
    \frac{F}{\pi w R} = 2 \int_0^\infty P\, \varrho\, d\varrho,

with :math:`P(\zeta) = -\tfrac83(\zeta^{-3} - \zeta^{-9})` and Tabor's parameter
:math:`\mu_T = (R w^2/(E^2 z_0^3))^{1/3}` the one group (:math:`\mu_T = 0`: the rigid sphere).
The Dugdale step matched to the law (same :math:`w`, same peak tension :math:`\sigma_0 = S w/z_0`,
:math:`S = 16/(9\sqrt3)`) has Maugis' :math:`\lambda = 1.1570\,\mu_T`
(:data:`~linecontact.closed_forms.sphere.LAMBDA_OVER_TABOR`).

**Discretisation.** :math:`P` is constant on rings; a ring's displacement is that of its
outer loaded disc less its inner one, exactly (a disc of radius :math:`b` under a unit
pressure displaces the surface by :math:`(4b/\pi) E(r/b)` inside and
:math:`(4r/\pi)[E(b/r) - (1 - b^2/r^2) K(b/r)]` outside, over :math:`E`). Collocation at the
rings' mid-points. The ring edges are a smooth map of a uniform grid: uniform (element
:math:`h`) out to a radius beyond the contact where the curve ends, then growing
geometrically (by 10 % an element of the coarse mesh) to :math:`L \ge 40`; beyond :math:`L` the
attraction of the rigid gap is added to the load in closed form,
:math:`-\tfrac83 \zeta(L)^{-2}` (about :math:`4 \times 10^{-6}` at :math:`L = 40`; its
displacements inside are left out). :math:`h` resolves the edge of the contact, where
the gap rises from :math:`z_0` to a few :math:`z_0` over about :math:`\mu_T^{-3/2}`
(a JKR crack opening).

**The curve** is followed by one monotone parameter :math:`\tau`: far away the gap at the
centre (:math:`\tau = 1.5 - \zeta(0)`, from :math:`-4.5`), then the edge
(:math:`\tau = e`, the radius where the gap is :math:`1.5\, z_0`): the states hold it by a
bordered Newton system (the gaps and :math:`\Delta` unknown). The edge moves one way through
the jump-in, the pull-off and the compressive branch, where neither the load nor the approach
would (as the line solver, :mod:`linecontact.lennard_jones`). The pull-off under load control
is the minimum of the load along the curve, refined by Brent's method in :math:`\tau`, on a
mesh and on the mesh with every ring halved; the result is the Richardson extrapolation of
the two (second order, measured) and its error estimate their difference over three.

References
----------
J. A. Greenwood, "Adhesion of elastic spheres", Proc. R. Soc. Lond. A 453 (1997)
1277--1297. doi:10.1098/rspa.1997.0070
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray

from .._threads import on_one_blas_thread
from ..errors import ConvergenceError, ParameterError
from ..results import Result

__all__ = [
    "MU_MAX",
    "SphereLJCurve",
    "SphereLJPullOff",
    "sphere_lj_curve",
    "sphere_lj_pull_off",
]

#: The largest Tabor parameter solved (the uniform mesh resolves its edge, about
#: :math:`\mu_T^{-3/2}` wide, over the whole contact).
MU_MAX = 5.0
#: The gap over :math:`z_0` that marks the edge the curve follows.
_EDGE_GAP = 1.5
#: The central gap where a curve starts.
_START = 6.0
_N_FAR = 9
#: The element of the uniform part at the default resolution (``m = 1``), at most.
_H = 0.05
#: The element over the edge length :math:`\mu_T^{-3/2}` (``m = 1``).
_H_EDGE = 0.12
#: Growth of the coarse elements beyond the uniform part, and the mesh's end.
_GROWTH = 0.10
_FAR_END = 40.0
_TOL = 1e-11
_MAXIT = 60
#: A chord step is kept while the residual falls at least by this factor.
_CHORD = 0.6


# ---------------------------------------------------------------------------------------
# the rings


def _disc(r: NDArray, b: NDArray) -> NDArray:
    r"""The displacement at ``r`` of a disc of radius ``b`` under a unit pressure, times ``E``.

    :math:`(4b/\pi) E(r/b)` inside, :math:`(4r/\pi)[E - (1 - m) K](m = b^2/r^2)` outside; the
    bracket as :math:`m (K - R_D(0, 1 - m, 1)/3)`, which does not cancel for small ``m``.
    """
    from scipy.special import ellipe, ellipk, elliprd

    out = np.empty(np.broadcast_shapes(r.shape, b.shape))
    rr, bb = np.broadcast_arrays(r, b)
    inside = rr < bb
    ri, bi = rr[inside], bb[inside]
    out[inside] = (4.0 / math.pi) * bi * ellipe((ri / bi) ** 2)
    ro, bo = rr[~inside], bb[~inside]
    m = (bo / ro) ** 2
    out[~inside] = (4.0 / math.pi) * ro * m * (ellipk(m) - elliprd(0.0, 1.0 - m, 1.0) / 3.0)
    return out


@dataclass(frozen=True, eq=False)
class _Mesh:
    """Rings ``[edges[j], edges[j+1]]``, collocation at ``mid``; the influence matrix ``A``."""

    edges: NDArray
    mid: NDArray
    A: NDArray  # gap at mid[i] from a unit P on ring j, over mu^(3/2)
    area: NDArray  # b_(j+1)^2 - b_j^2: F/(pi w R) = area @ P (+ the tail)
    centre: NDArray  # the displacement at r = 0 of a unit P on ring j: 2 (b_(j+1) - b_j)


def _map(t: NDArray, h: float, t_band: float, a: float) -> NDArray:
    """Radius of the grid coordinate ``t``: ``h t`` to ``t_band``, then growing as ``exp(a t)``."""
    rho_b = h * t_band
    beyond = rho_b + h * np.expm1(a * (t - t_band)) / a
    return np.where(t <= t_band, h * t, beyond)


def _rings(mu: float, rho_band: float, m: float, level: int) -> _Mesh:
    r"""The rings at resolution ``m``, ``level`` times bisected in the grid coordinate.

    Uniform elements :math:`h = \min(0.05, 0.12\,\mu_T^{-3/2})/m` out to ``rho_band``, then
    growing by :math:`10/m` % per element to :data:`_FAR_END` (or four times ``rho_band``).
    """
    edge = _H_EDGE * mu**-1.5 if mu > 0 else math.inf
    h = min(_H, edge) / m
    t_band = math.ceil(rho_band / h)
    far = max(_FAR_END, 4.0 * rho_band)
    a = math.log1p(_GROWTH) / m  # the elements beyond scale with 1/m too
    t_end = t_band + math.ceil(math.log1p(a * (far - h * t_band) / h) / a)
    k = 2**level
    t = np.arange(t_end * k + 1) / k
    edges = _map(t, h, t_band, a)
    mid = _map(t[:-1] + 0.5 / k, h, t_band, a)
    D = _disc(mid[:, None], edges[None, 1:])
    A = D.copy()
    A[:, 1:] -= D[:, :-1]
    return _Mesh(edges, mid, A, np.diff(edges**2), 2.0 * np.diff(edges))


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
    gap0 = -delta + c * float(mesh.centre @ P)
    return _State(tau, zeta, delta, F, gap0, _crossing(mesh.mid, zeta, 1.0))


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


def _guess(states: list[_State], tau: float) -> tuple[NDArray, float]:
    """Linear extrapolation in ``tau`` from the two nearest states (no lower than either)."""
    near = sorted(states, key=lambda s: abs(s.tau - tau))
    s = near[0]
    other = [p for p in near[1:] if p.tau != s.tau]
    if not other:
        return s.zeta, s.delta
    p = other[0]
    t = (tau - s.tau) / (s.tau - p.tau)
    z = s.zeta + t * (s.zeta - p.zeta)
    return np.maximum(z, 0.9 * np.minimum(s.zeta, p.zeta)), s.delta + t * (s.delta - p.delta)


def _fail(what: str, mu: float, tau: float) -> ConvergenceError:
    return ConvergenceError(
        f"Lennard-Jones sphere {what} did not converge at tabor_parameter={mu!r}, "
        f"control tau={tau!r} (the central gap 1.5 - tau over z0 below 0, the edge above)"
    )


# ---------------------------------------------------------------------------------------
# the curve


class _Path:
    """The states of one mesh along ``tau``, solved from their nearest neighbours."""

    def __init__(self, mu: float, mesh: _Mesh) -> None:
        self.mu, self.mesh = mu, mesh
        self.states: list[_State] = []
        self.lu: dict = {}  # the chord Newton's factorisation, shared along the path

    def solve(self, tau: float) -> _State | None:
        if self.states:
            z, d = _guess(self.states, tau)
        else:
            g = _EDGE_GAP - tau
            z, d = g + 0.5 * self.mesh.mid**2, -g
        s = _state(self.mu, self.mesh, tau, z, d, self.lu)
        if s is not None:
            self.states.append(s)
        return s

    def far(self) -> list[_State]:
        out: list[_State] = []
        for g in np.geomspace(_START, _EDGE_GAP, _N_FAR):
            s = self._reach(_EDGE_GAP - float(g), out)
            out.append(s)
        return out

    def _reach(self, tau: float, out: list[_State]) -> _State:
        s = self.solve(tau)
        if s is not None:
            return s
        lo = out[-1].tau if out else tau
        step = 0.5 * (tau - lo)
        while True:  # halved steps from the last state
            if abs(step) < 1e-9:
                raise _fail("curve", self.mu, tau)
            t = self.solve(lo + step)
            if t is None:
                step *= 0.5
                continue
            lo = t.tau
            if lo >= tau:
                return t
            step = min(2 * step, tau - lo)
            if abs(tau - lo) < 1e-12:
                return t

    def climb(self, start: list[_State], done, h: float) -> list[_State]:
        """``start`` continued in the edge until ``done(states)``."""
        out = list(start)
        step = h
        while not done(out):
            tau = out[-1].tau
            t = None
            while t is None:
                t = self.solve(tau + step)
                if t is None:
                    step *= 0.5
                    if step < 1e-7 * h:
                        raise _fail("curve", self.mu, tau)
            out.append(t)
            step = min(1.5 * step, max(4.0 * h, 0.08 * t.tau))
        return out

    def minimum(self, a: float, b: float, c: float, sign: float = 1.0) -> _State:
        """The minimum of ``sign`` times the load in ``tau``, bracketed by ``a < b < c`` (Brent)."""
        from scipy.optimize import minimize_scalar

        cache: dict[float, _State] = {}

        def f(tau: float) -> float:
            s = self.solve(float(tau))
            if s is None:
                raise _fail("extremum refinement", self.mu, float(tau))
            cache[float(tau)] = s
            return sign * s.F

        r = minimize_scalar(f, bracket=(a, b, c), method="brent", options={"xtol": 1e-7})
        best = min(cache.values(), key=lambda s: sign * s.F)
        return cache.get(float(r.x), best)


def _band(mu: float, F_max: float) -> float:
    r"""The uniform part's end: beyond the JKR contact at ``F_max`` (and :math:`\varrho = 4`)."""
    a3 = 0.75 * math.pi * mu**1.5 * (F_max + 3.0 + math.sqrt(6.0 * F_max + 9.0))
    return max(4.0, 1.5 * a3 ** (1.0 / 3.0) + 2.0)


def _check_mu(mu) -> float:
    try:
        x = float(mu)
    except (TypeError, ValueError):
        raise ParameterError(
            "tabor_parameter", f"tabor_parameter must be a number in [0, {MU_MAX}], got {mu!r}"
        ) from None
    if not (0.0 <= x <= MU_MAX):
        raise ParameterError(
            "tabor_parameter", f"tabor_parameter must lie in [0, {MU_MAX}], got {mu!r}"
        )
    return x


def _check_m(m) -> float:
    try:
        x = float(m)
    except (TypeError, ValueError):
        raise ParameterError("m", f"m must be a number in [0.25, 16], got {m!r}") from None
    if not (0.25 <= x <= 16.0):
        raise ParameterError("m", f"m must be a number in [0.25, 16], got {m!r}")
    return x


# ---------------------------------------------------------------------------------------
# the results


@dataclass(frozen=True)
class SphereLJPullOff(Result):
    r"""The load-control pull-off of the self-consistent Lennard-Jones sphere.

    Attributes
    ----------
    tabor_parameter : float
        Tabor's :math:`\mu_T = (R w^2/(E^2 z_0^3))^{1/3}` [-].
    F_pulloff_over_piwR : float
        The most tensile load of the curve [:math:`\pi w R`]: the Richardson extrapolation of
        the minima on a mesh and on the mesh with every ring halved (-2: the rigid sphere,
        -1.5: JKR).
    error_estimate : float
        Its estimated absolute error [:math:`\pi w R`]: the difference of the two meshes'
        minima over three (the Richardson correction).
    F_coarse, F_fine : float
        The minima on the two meshes [:math:`\pi w R`].
    central_gap_over_z0 : float
        The gap at the centre at pull-off [:math:`z_0`] (finer mesh).
    approach_over_z0 : float
        The approach :math:`\delta` at pull-off [:math:`z_0`] (finer mesh).
    contact_radius : float
        Where the gap crosses :math:`z_0` at pull-off [:math:`\sqrt{R z_0}`]; 0 where it
        exceeds :math:`z_0` everywhere.
    edge_radius : float
        Where the gap crosses :math:`1.5\, z_0` (the control) [:math:`\sqrt{R z_0}`].
    maugis_parameter : float
        The matched Dugdale step's :math:`\lambda = 1.1570\,\mu_T` [-].
    n_rings : int
        Rings of the finer mesh.
    converged : bool
        Always ``True`` (a state that does not converge raises ``ConvergenceError``).
    """

    inputs: ClassVar[tuple[str, ...]] = ("tabor_parameter",)

    tabor_parameter: float
    F_pulloff_over_piwR: float
    error_estimate: float
    F_coarse: float
    F_fine: float
    central_gap_over_z0: float
    approach_over_z0: float
    contact_radius: float
    edge_radius: float
    maugis_parameter: float
    n_rings: int
    converged: bool


@dataclass(frozen=True)
class SphereLJCurve(Result):
    r"""The load curve of the self-consistent Lennard-Jones sphere (one mesh).

    One point per state, in the order of the curve (the approach growing except across an
    S-shape's turns).

    Attributes
    ----------
    approach_over_z0 : ndarray
        The approach :math:`\delta` [:math:`z_0`].
    F_over_piwR : ndarray
        The load [:math:`\pi w R`], compressive positive.
    central_gap_over_z0 : ndarray
        The gap at the centre [:math:`z_0`].
    contact_radius : ndarray
        Where the gap crosses :math:`z_0` [:math:`\sqrt{R z_0}`] (0: none).
    stable : ndarray of bool
        Stable under load control: the load rising along the curve.
    stable_displacement : ndarray of bool
        Stable under displacement control: the approach rising along the curve.
    tabor_parameter : float
        Tabor's :math:`\mu_T` [-].
    F_pulloff_over_piwR : float
        The load-control pull-off (the curve's minimum, refined) [:math:`\pi w R`], on this
        curve's mesh (:func:`sphere_lj_pull_off` extrapolates it over two meshes).
    F_jump_in_over_piwR : float
        The load-control jump-in where the curve is S-shaped (the last local maximum of the
        load before the pull-off) [:math:`\pi w R`]; NaN where there is none.
    n_rings : int
        Rings of the mesh.
    """

    inputs: ClassVar[tuple[str, ...]] = ("tabor_parameter",)
    whole: ClassVar[tuple[str, ...]] = (
        "tabor_parameter",
        "F_pulloff_over_piwR",
        "F_jump_in_over_piwR",
        "n_rings",
    )

    approach_over_z0: NDArray
    F_over_piwR: NDArray
    central_gap_over_z0: NDArray
    contact_radius: NDArray
    stable: NDArray
    stable_displacement: NDArray
    tabor_parameter: float
    F_pulloff_over_piwR: float
    F_jump_in_over_piwR: float
    n_rings: int = field(default=0)


# ---------------------------------------------------------------------------------------
# the pull-off and the curve


def _past_minimum(states: list[_State], a_end: float) -> bool:
    """The load has risen over three states past its lowest, with the edge beyond ``a_end``."""
    F = [s.F for s in states]
    i = int(np.argmin(F))
    return len(states) - i > 3 and states[-1].tau > a_end and states[i].tau > 0.0


def _first_step(mesh: _Mesh) -> float:
    return float(mesh.edges[1] - mesh.edges[0])


def _coarse_minimum(path: _Path, states: list[_State]) -> _State:
    F = np.array([s.F for s in states])
    i = int(np.argmin(F))
    if i == 0 or i == len(states) - 1:
        raise _fail("pull-off search (no minimum of the load)", path.mu, states[i].tau)
    return path.minimum(states[i - 1].tau, states[i].tau, states[i + 1].tau)


def _vertex(path: _Path, tau: float, d: float) -> _State:
    """The minimum of the load near ``tau`` on ``path``'s mesh.

    Bracketed from ``tau - d, tau, tau + d`` (steps growing by 1.6 downhill until the load
    rises), then Brent's method (:meth:`_Path.minimum`).
    """

    def at(x: float) -> _State:
        t = path.solve(x)
        if t is None:
            raise _fail("pull-off on the finer mesh", path.mu, x)
        return t

    a, b, c = at(tau - d), at(tau), at(tau + d)
    for _ in range(60):
        if b.F < a.F and b.F < c.F:
            return path.minimum(a.tau, b.tau, c.tau)
        if a.F < c.F:  # downhill towards smaller tau
            a, b, c = at(a.tau - 1.6 * (b.tau - a.tau)), a, b
        else:
            a, b, c = b, c, at(c.tau + 1.6 * (c.tau - b.tau))
    raise _fail("pull-off on the finer mesh (no minimum)", path.mu, tau)


@on_one_blas_thread
def sphere_lj_pull_off(tabor_parameter: float, *, m: float = 1.0) -> SphereLJPullOff:
    r"""The load-control pull-off of the self-consistent Lennard-Jones sphere.

    Parameters
    ----------
    tabor_parameter : float
        Tabor's :math:`\mu_T = (R w^2/(E^2 z_0^3))^{1/3}` [-], in ``[0, MU_MAX]`` (0: the
        rigid sphere).
    m : float, optional
        The resolution: the rings' width over the default's, inverted, in ``[0.25, 16]``.

    Returns
    -------
    SphereLJPullOff
        The pull-off [:math:`\pi w R`], its error estimate and the state there.

    Raises
    ------
    ParameterError
        ``tabor_parameter`` or ``m`` out of range (a ``ValueError`` naming it).
    ConvergenceError
        A state that Newton does not solve, naming ``tabor_parameter``.

    Examples
    --------
    >>> p = sphere_lj_pull_off(0.0)  # the rigid sphere: -2 pi w R
    >>> print(f"{p.F_pulloff_over_piwR:.6f}")
    -2.000000
    """
    mu = _check_mu(tabor_parameter)
    m = _check_m(m)
    band = _band(mu, -1.5)
    coarse = _Path(mu, _rings(mu, band, m, 0))
    h = _first_step(coarse.mesh)
    states = coarse.climb(coarse.far(), lambda st: _past_minimum(st, 0.5), h)
    lo = _coarse_minimum(coarse, states)
    fine = _Path(mu, _rings(mu, band, m, 1))
    fine.states.append(_on(lo, coarse.mesh, fine.mesh))
    hi = _vertex(fine, lo.tau, 0.1 * h)
    F0, F1 = lo.F, hi.F
    return SphereLJPullOff(
        tabor_parameter=mu,
        F_pulloff_over_piwR=F1 + (F1 - F0) / 3.0,
        error_estimate=abs(F1 - F0) / 3.0,
        F_coarse=F0,
        F_fine=F1,
        central_gap_over_z0=hi.central_gap,
        approach_over_z0=hi.delta,
        contact_radius=hi.contact_radius,
        edge_radius=max(hi.tau, 0.0),
        maugis_parameter=_lambda(mu),
        n_rings=int(fine.mesh.mid.size),
        converged=True,
    )


def _lambda(mu: float) -> float:
    from ..closed_forms.sphere import LAMBDA_OVER_TABOR

    return LAMBDA_OVER_TABOR * mu


def _on(s: _State, a: _Mesh, b: _Mesh) -> _State:
    """``s`` interpolated onto the mesh ``b`` (a first guess there)."""
    return _State(s.tau, np.interp(b.mid, a.mid, s.zeta), s.delta, s.F, s.central_gap, 0.0)


def _extrema(F: NDArray) -> tuple[list[int], list[int]]:
    """Indices of the interior local minima and maxima of the sampled load."""
    n = F.size
    lo = [i for i in range(1, n - 1) if F[i] <= F[i - 1] and F[i] < F[i + 1]]
    hi = [i for i in range(1, n - 1) if F[i] >= F[i - 1] and F[i] > F[i + 1]]
    return lo, hi


@on_one_blas_thread
def sphere_lj_curve(tabor_parameter: float, *, F_max: float = 1.0, m: float = 1.0) -> SphereLJCurve:
    r"""The load curve of the self-consistent Lennard-Jones sphere, through its S-shape.

    From a central gap of :math:`6 z_0` through the jump-in (where the curve is S-shaped),
    the pull-off and the compressive branch to the load ``F_max``, on one mesh (the pull-off
    extrapolated over two meshes is :func:`sphere_lj_pull_off`).

    Parameters
    ----------
    tabor_parameter : float
        Tabor's :math:`\mu_T` [-], in ``[0, MU_MAX]``.
    F_max : float, optional
        The compressive load where the curve ends [:math:`\pi w R`], in ``[0, 10]``.
    m : float, optional
        The resolution, as in :func:`sphere_lj_pull_off`.

    Returns
    -------
    SphereLJCurve

    Raises
    ------
    ParameterError
        An argument out of range, naming it.
    ConvergenceError
        A state that Newton does not solve, naming ``tabor_parameter``.
    """
    mu = _check_mu(tabor_parameter)
    m = _check_m(m)
    try:
        F_end = float(F_max)
    except (TypeError, ValueError):
        raise ParameterError("F_max", f"F_max must be a number in [0, 10], got {F_max!r}") from None
    if not (0.0 <= F_end <= 10.0):
        raise ParameterError("F_max", f"F_max must be a number in [0, 10], got {F_max!r}")
    path = _Path(mu, _rings(mu, _band(mu, F_end), m, 0))
    h = _first_step(path.mesh)
    states = path.climb(path.far(), lambda st: _past_minimum(st, 0.5) and st[-1].F >= F_end, h)
    F = np.array([s.F for s in states])
    po = _coarse_minimum(path, states)
    i_po = int(np.argmin(F))
    jump = math.nan
    before = [i for i in _extrema(F)[1] if i < i_po]
    if before:
        i = before[-1]
        jump = path.minimum(states[i - 1].tau, states[i].tau, states[i + 1].tau, -1.0).F
    delta = np.array([s.delta for s in states])
    dF, dd = np.gradient(F), np.gradient(delta)
    return SphereLJCurve(
        approach_over_z0=delta,
        F_over_piwR=F,
        central_gap_over_z0=np.array([s.central_gap for s in states]),
        contact_radius=np.array([s.contact_radius for s in states]),
        stable=dF > 0.0,
        stable_displacement=dd > 0.0,
        tabor_parameter=mu,
        F_pulloff_over_piwR=po.F,
        F_jump_in_over_piwR=jump,
        n_rings=int(path.mesh.mid.size),
    )
