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
:math:`(4r/\pi)[E(m) - (1 - m) K(m)]`, :math:`m = b^2/r^2`, outside, over :math:`E`; the
bracket by its series for :math:`m \le 1/4`, where it cancels). Collocation at the rings'
mid-points. The rings are graded about the edge of the contact: a smooth map of a uniform
grid gives elements :math:`h = \min(0.05, 0.12\,\mu_T^{-3/2})` (``m = 1``) over 40
elements either side of the edge, where the gap rises from :math:`z_0` to a few
:math:`z_0` over about :math:`\mu_T^{-3/2}` (a JKR crack opening), growing by 10 % an
element away from it up to :math:`\max(0.05, 0.02\,e)` (inwards to the centre, outwards
over 4 more units) and beyond that growing again to :math:`L \ge 40`; beyond :math:`L` the
attraction of the rigid gap is added to the load in closed form,
:math:`-\tfrac83 \zeta(L)^{-2}` (about :math:`4 \times 10^{-6}` at :math:`L = 40`; its
displacements inside are left out). A few hundred rings at every :math:`\mu_T`, where a
uniform mesh over the contact would need :math:`\mu_T^2` times more.

**The curve** is followed by one monotone parameter :math:`\tau`: far away the gap at the
centre (:math:`\tau = 1.5 - \zeta(0)`, from :math:`-4.5`), then the edge
(:math:`\tau = e`, the radius where the gap is :math:`1.5\, z_0`): the states hold it by a
bordered Newton system (the gaps and :math:`\Delta` unknown), each on rings graded about
its own edge (made anew when the edge has moved half the fine band), its first guess a
neighbour's gaps with radii scaled by the ratio of the edges. The edge moves one way through
the jump-in, the pull-off and the compressive branch, where neither the load nor the approach
would (as the line solver, :mod:`linecontact.lennard_jones`). The pull-off under load control
is the minimum of the load along the curve (followed at half the resolution), refined by
Brent's method in :math:`\tau` on rings that follow the edge, then within the fine band of
one mesh about it (made again until the minimum lies inside) and of the same mesh with every
ring halved; the result is the Richardson extrapolation of the two (second order, measured)
and its error estimate their difference over three. Beyond
:data:`MU_SELF_CONSISTENT` the pull-off is the JKR limit with a fitted correction, its
error estimate the whole correction (:func:`sphere_lj_pull_off`).

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
from ..closed_forms.sphere import sphere_jkr_approach as _jkr_approach
from ..errors import ParameterError
from ..results import Result
from ._lj_discrete import (
    _EDGE_GAP,
    _FAR_END,
    _N_FAR,
    _START,
    _coarser,
    _element,
    _fail,
    _guess,
    _Mesh,
    _rings,
    _State,
    _state,
)

__all__ = [
    "MU_LARGEST",
    "MU_SELF_CONSISTENT",
    "SphereLJCurve",
    "SphereLJPullOff",
    "sphere_lj_curve",
    "sphere_lj_pull_off",
]

#: The largest Tabor parameter taken (beyond, JKR's -1.5 to far below rounding; the state's
#: numbers would overflow).
MU_LARGEST = 1e100
#: The largest Tabor parameter solved self-consistently; beyond, the pull-off is the JKR
#: limit with a fitted correction (:func:`sphere_lj_pull_off`) and the curve is refused.
MU_SELF_CONSISTENT = 50.0
#: :math:`F/F_\text{JKR} - 1 = C \mu_T^{-p}` (:math:`F_\text{JKR} = -1.5`): least squares in
#: ``ln`` on the self-consistent pull-offs at :math:`\mu_T` = 25, 30, 35, 42, 50 (default
#: mesh; ``benchmarks/sphere.py`` reproduces the fit).
_C = 0.3107257
_P = 1.6671276


# ---------------------------------------------------------------------------------------
# the curve


class _Path:
    """States along ``tau``, each solved from its nearest neighbours.

    On one mesh about the edge ``centre``, or (``centre=None``) on meshes that follow the
    edge: made anew about it wherever it has left the inner half of the fine band.
    """

    def __init__(
        self,
        mu: float,
        m: float,
        far: float,
        *,
        centre: float | None = None,
        level: int = 0,
        estimate: bool = False,
    ) -> None:
        self.mu, self.m, self.far_end, self.level = mu, m, far, level
        self.follow = centre is None
        self.mesh = _rings(mu, 0.0 if centre is None else centre, m, level, far)
        self.states: list[_State] = []
        self.lu: dict = {}  # the chord Newton's factorisation, shared along a mesh
        self.known: dict[float, _State] = {}
        self.meshes = 1
        #: each state's error estimate from the nested mesh of half the rings
        self.estimate = estimate
        self.errors: dict[float, float] = {}
        self._coarse: tuple[_Mesh, _Mesh, dict] | None = None

    def _mesh_for(self, tau: float) -> _Mesh:
        e = max(tau, 0.0)
        if self.follow and abs(e - self.mesh.centre) > 0.5 * self.mesh.band:
            self.mesh = _rings(self.mu, e, self.m, self.level, self.far_end)
            self.lu.clear()
            self.meshes += 1
        return self.mesh

    def solve(self, tau: float) -> _State | None:
        """The state at ``tau``, from the nearest ones; else reached in halved steps.

        ``None`` where neither converges.
        """
        known = self.known.get(tau)
        if known is not None:
            return known
        s = self._direct(tau)
        return self._walk(tau) if s is None and self.states else s

    def _direct(self, tau: float) -> _State | None:
        mesh = self._mesh_for(tau)
        if self.states:
            z, d = _guess(self.states, tau, mesh.mid)
        else:
            g = _EDGE_GAP - tau
            z, d = g + 0.5 * mesh.mid**2, -g
        s = _state(self.mu, mesh, tau, z, d, self.lu)
        if s is not None:
            self.states.append(s)
            self.known[tau] = s
            if self.estimate:
                self.errors[tau] = self._error(mesh, s)
        return s

    def _error(self, mesh: _Mesh, s: _State) -> float:
        """The state's load less that of the same state on the mesh it halves.

        NaN where the coarser mesh's state does not converge.
        """
        if self._coarse is None or self._coarse[0] is not mesh:
            self._coarse = (mesh, _coarser(mesh), {})
        _, coarse, lu = self._coarse
        c = _state(self.mu, coarse, s.tau, np.interp(coarse.mid, mesh.mid, s.zeta), s.delta, lu)
        return math.nan if c is None else abs(s.F - c.F)

    def _walk(self, tau: float) -> _State | None:
        lo = min(self.states, key=lambda p: abs(p.tau - tau)).tau
        step = 0.5 * (tau - lo)
        while abs(step) > 1e-9 * max(1.0, abs(tau)):
            t = self._direct(lo + step)
            if t is None:
                step *= 0.5
                continue
            lo, left = t.tau, tau - t.tau
            if abs(left) < 1e-12 * max(1.0, abs(tau)):
                return t
            step = math.copysign(min(2.0 * abs(step), abs(left)), left)
        return None

    def far(self) -> list[_State]:
        out: list[_State] = []
        for g in np.geomspace(_START, _EDGE_GAP, _N_FAR):
            tau = _EDGE_GAP - float(g)
            s = self.solve(tau)
            if s is None:
                raise _fail("curve", self.mu, tau)
            out.append(s)
        return out

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

    def minimum(
        self, a: float, b: float, c: float, sign: float = 1.0, *, bounded: bool = False
    ) -> _State:
        """The minimum of ``sign`` times the load in ``tau``, bracketed by ``a < b < c`` (Brent).

        ``bounded``: searched within ``[a, c]`` only (``b`` unused).
        """
        from scipy.optimize import minimize_scalar

        cache: dict[float, _State] = {}

        def f(tau: float) -> float:
            s = self.solve(float(tau))
            if s is None:
                raise _fail("extremum refinement", self.mu, float(tau))
            cache[float(tau)] = s
            return sign * s.F

        if bounded:
            tol = 1e-4 * (c - a)
            r = minimize_scalar(f, bounds=(a, c), method="bounded", options={"xatol": tol})
        else:
            r = minimize_scalar(f, bracket=(a, b, c), method="brent", options={"xtol": 1e-7})
        best = min(cache.values(), key=lambda s: sign * s.F)
        return cache.get(float(r.x), best)


def _far(mu: float, F_max: float) -> float:
    r"""The mesh's end: :data:`_FAR_END`, or four times the JKR contact at ``F_max``."""
    a3 = 0.75 * math.pi * mu**1.5 * (F_max + 3.0 + math.sqrt(6.0 * F_max + 9.0))
    return max(_FAR_END, 4.0 * (1.5 * a3 ** (1.0 / 3.0) + 2.0))


def _number(name: str, value, lo: float, hi: float) -> float:
    """A real number (not a bool or a string) in ``[lo, hi]``, or a ParameterError naming it."""
    span = f"[{lo:g}, {hi:g}]"
    try:
        if isinstance(value, (bool, str, bytes)):
            raise TypeError
        x = float(value)
    except (TypeError, ValueError):
        raise ParameterError(name, f"{name} must be a number in {span}, got {value!r}") from None
    if not (lo <= x <= hi):
        raise ParameterError(name, f"{name} must lie in {span}, got {value!r}")
    return x + 0.0  # -0.0 as 0.0


def _check_mu(mu, hi: float = MU_LARGEST) -> float:
    """Tabor's parameter, a number in ``[0, hi]``."""
    return _number("tabor_parameter", mu, 0.0, hi)


def _check_m(m) -> float:
    return _number("m", m, 1.0, 16.0)


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
        Rings of the finer mesh (0 for the limit form).
    converged : bool
        Always ``True`` (a state that does not converge raises ``ConvergenceError``).
    method : str
        ``"self-consistent"`` (:math:`\mu_T \le` :data:`MU_SELF_CONSISTENT`) or ``"limit"``:
        the JKR limit with its fitted correction, whose error estimate is the whole
        correction (``F_coarse`` and ``F_fine`` NaN; the state that of JKR's sphere, the
        central gap from the law linearised about :math:`z_0`).
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
    method: str = "self-consistent"


@dataclass(frozen=True)
class SphereLJCurve(Result):
    r"""The load curve of the self-consistent Lennard-Jones sphere.

    One point per state, in the order of the curve (the approach growing except across an
    S-shape's turns), each on rings graded about its own edge.

    Attributes
    ----------
    approach_over_z0 : ndarray
        The approach :math:`\delta` [:math:`z_0`].
    F_over_piwR : ndarray
        The load [:math:`\pi w R`], compressive positive.
    error_estimate : ndarray
        Each load's estimated error [:math:`\pi w R`]: the largest, over it and its two
        neighbours on the curve, of the difference between a state's load and that of the
        same state on the nested mesh of half the rings. Three times the Richardson
        correction of a second-order method, and taken over neighbours, where the
        correction alone falls short (near a change of the error's sign, or where the edge
        sits off its mesh's centre); NaN where no such state converges.
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
        Rings of the last state's mesh (each state's is graded about its own edge).
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
    error_estimate: NDArray
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


def _lowest(mu: float, states: list[_State], sign: float = 1.0) -> int:
    """The index of the lowest ``sign`` times the load, not at either end."""
    i = int(np.argmin([sign * s.F for s in states]))
    if i == 0 or i == len(states) - 1:
        raise _fail("pull-off search (no minimum of the load)", mu, states[i].tau)
    return i


def _vertex(path: _Path, tau: float, d: float, sign: float = 1.0) -> _State:
    """The minimum of ``sign`` times the load near ``tau`` on ``path``'s mesh.

    Bracketed from ``tau - d, tau, tau + d`` (steps growing by 1.6 downhill until the load
    rises), then Brent's method (:meth:`_Path.minimum`).
    """

    def at(x: float) -> _State:
        t = path.solve(x)
        if t is None:
            raise _fail("extremum refinement", path.mu, x)
        return t

    a, b, c = at(tau - d), at(tau), at(tau + d)
    for _ in range(60):
        fa, fb, fc = sign * a.F, sign * b.F, sign * c.F
        if fb < fa and fb < fc:
            return path.minimum(a.tau, b.tau, c.tau, sign)
        if fa < fc:  # downhill towards smaller tau
            a, b, c = at(a.tau - 1.6 * (b.tau - a.tau)), a, b
        else:
            a, b, c = b, c, at(c.tau + 1.6 * (c.tau - b.tau))
    raise _fail("extremum refinement (no extremum)", path.mu, tau)


def _refined(
    path: _Path, states: list[_State], i: int, sign: float = 1.0
) -> tuple[_State, float, bool]:
    r"""The extremum near ``states[i]`` on one mesh about it: ``(state, centre, flat)``.

    Found first on meshes that follow the edge (``path``), then within the fine band of one
    mesh about it, made again about the extremum found there until that lies inside the
    band's ends (at most six times). Where the load is so flat that the mesh's own error
    decides (the extremum on each of two meshes lies at the other's centre, at large
    :math:`\mu_T`), the state at the centre between them (``flat``).
    """
    best = _vertex(path, states[i].tau, 0.25 * (states[i + 1].tau - states[i - 1].tau), sign)
    centres: list[float] = []
    for _ in range(6):
        centre = max(best.tau, 0.0)
        fixed = _Path(path.mu, path.m, path.far_end, centre=centre, level=path.level)
        fixed.states = [best]
        best = _in_band(fixed, sign)
        e = max(best.tau, 0.0)
        if abs(e - centre) <= 0.45 * fixed.mesh.band:
            return best, centre, False
        if any(abs(e - c) < 0.1 * fixed.mesh.band for c in centres):
            mid = 0.5 * (centre + e)
            flat = _Path(path.mu, path.m, path.far_end, centre=mid, level=path.level)
            flat.states = [best]
            return _in_band(flat, sign, flat=True), mid, True
        centres.append(centre)
    raise _fail("extremum refinement (the mesh does not settle)", path.mu, best.tau)


def _in_band(path: _Path, sign: float = 1.0, *, flat: bool = False) -> _State:
    """The extremum within half the fine band of ``path``'s (one) mesh (``flat``: its centre)."""
    c, B = path.mesh.centre, 0.5 * path.mesh.band
    if flat:
        s = path.solve(c)
        if s is None:
            raise _fail("extremum refinement", path.mu, c)
        return s
    return path.minimum(c - B, c, c + B, sign, bounded=True)


@on_one_blas_thread
def sphere_lj_pull_off(tabor_parameter: float, *, m: float = 1.0) -> SphereLJPullOff:
    r"""The load-control pull-off of the Lennard-Jones sphere, at every Tabor parameter.

    Self-consistent (the module's solver, over two meshes) for :math:`\mu_T \le`
    :data:`MU_SELF_CONSISTENT`; beyond, the JKR limit with a fitted correction,

    .. math::

        \frac{F}{\pi w R} = -\frac32\left(1 + C\mu_T^{-p}\right), \qquad
        C = 0.3107,\; p = 1.667,

    fitted to the self-consistent pull-offs at :math:`\mu_T = 25 \ldots 50`; its error
    estimate is the whole correction (in the overlap :math:`\mu_T = 50 \ldots 100` the
    self-consistent pull-off differs from it by far less: ``docs/sphere.md``).

    Parameters
    ----------
    tabor_parameter : float
        Tabor's :math:`\mu_T = (R w^2/(E^2 z_0^3))^{1/3}` [-], in ``[0, MU_LARGEST]`` (0: the
        rigid sphere; :data:`MU_LARGEST` is :math:`10^{100}`).
    m : float, optional
        The resolution: the rings' width over the default's, inverted, in ``[1, 16]``
        (coarser rings do not resolve the edge of the contact at large :math:`\mu_T`).

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
    if mu > MU_SELF_CONSISTENT:
        return _limit(mu)
    return _self_consistent(mu, m)


def _limit(mu: float) -> SphereLJPullOff:
    r"""The JKR limit, corrected (:func:`sphere_lj_pull_off` beyond the self-consistent range).

    The state is JKR's sphere at its load-control pull-off, in the module's units: the
    contact radius :math:`a^3 = (9\pi/8)\,\mu_T^{3/2}`, the approach
    :math:`a^2 - \sqrt{2\pi a \mu_T^{3/2}}` less the gap :math:`z_0` where the surfaces
    touch, and the pressure at the centre :math:`2a/(\pi\mu_T^{3/2}) - \sqrt{2/(\pi a
    \mu_T^{3/2})}` turned into a gap by the law linearised about :math:`z_0`,
    :math:`P = -16(\zeta - 1)`; the contact radius (the gap at :math:`z_0`) where that
    pressure changes sign, :math:`a\sqrt{1 - B/A}` for :math:`P = A\sqrt{1 - r^2/a^2} -
    B/\sqrt{1 - r^2/a^2}`, the edge JKR's :math:`a`.
    """
    correction = _C * mu**-_P
    c = mu**1.5
    a = (9.0 * math.pi / 8.0 * c) ** (1.0 / 3.0)
    hertz, crack = 2.0 * a / (math.pi * c), math.sqrt(2.0 / (math.pi * a * c))
    P0 = hertz - crack
    return SphereLJPullOff(
        tabor_parameter=mu,
        F_pulloff_over_piwR=-1.5 * (1.0 + correction),
        error_estimate=1.5 * correction,
        F_coarse=math.nan,
        F_fine=math.nan,
        central_gap_over_z0=1.0 - P0 / 16.0,
        approach_over_z0=float(_jkr_approach(a, 1.0, c)) - 1.0,  # groups: R/h = 1, z0 = h
        contact_radius=a * math.sqrt(max(1.0 - crack / hertz, 0.0)),
        edge_radius=a,
        maugis_parameter=_lambda(mu),
        n_rings=0,
        converged=True,
        method="limit",
    )


def _self_consistent(mu: float, m: float = 1.0) -> SphereLJPullOff:
    """The self-consistent pull-off (any ``mu`` the solver reaches; the overlap's checks)."""
    far = _far(mu, -1.5)
    scout = _Path(mu, 0.5 * m, far)  # the curve to past its minimum at half the resolution
    states = scout.climb(scout.far(), lambda st: _past_minimum(st, 0.5), _element(mu, 0.5 * m))
    i = _lowest(mu, states)
    path = _Path(mu, m, far)
    path.states = states[i - 1 : i + 2]
    lo, centre, flat = _refined(path, states, i)
    fine = _Path(mu, m, far, centre=centre, level=1)
    fine.states.append(lo)
    hi = _in_band(fine, flat=flat)
    F0, F1 = lo.F, hi.F
    return SphereLJPullOff(
        tabor_parameter=mu,
        F_pulloff_over_piwR=float(F1 + (F1 - F0) / 3.0),
        error_estimate=float(abs(F1 - F0) / 3.0),
        F_coarse=float(F0),
        F_fine=float(F1),
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


def _ended(path: _Path, states: list[_State], F_end: float) -> list[_State]:
    """The curve ended at its first state past the pull-off with a load of ``F_end`` or more.

    Near a stiff sphere's repulsive wall one step in the edge can take the load from below
    ``F_end`` to orders of magnitude above it: that state is moved back, by bisection in
    the edge, until its load is at most ``2 F_end + 1``.
    """
    i = int(np.argmin([s.F for s in states]))
    j = next(k for k in range(i + 1, len(states)) if states[k].F >= F_end)
    lo, hi = states[j - 1], states[j]
    top = 2.0 * F_end + 1.0
    for _ in range(60):
        if hi.F <= top:
            break
        mid = path.solve(0.5 * (lo.tau + hi.tau))
        if mid is None:
            break
        if mid.F >= F_end:
            hi = mid
        else:
            lo = mid
    kept = states[:j] + ([lo] if lo is not states[j - 1] else [])
    return [*kept, hi]


def _over_neighbours(e: NDArray) -> NDArray:
    """The largest of each value and its two neighbours (NaN only where all three are)."""
    nan = np.full(1, np.nan)
    with np.errstate(invalid="ignore"):
        return np.fmax(np.fmax(e, np.r_[e[1:], nan]), np.r_[nan, e[:-1]])


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
        Tabor's :math:`\mu_T` [-], in ``[0, MU_SELF_CONSISTENT]``.
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
    mu = _check_mu(tabor_parameter, MU_SELF_CONSISTENT)
    m = _check_m(m)
    try:
        F_end = float(F_max)
    except (TypeError, ValueError):
        raise ParameterError("F_max", f"F_max must be a number in [0, 10], got {F_max!r}") from None
    if not (0.0 <= F_end <= 10.0):
        raise ParameterError("F_max", f"F_max must be a number in [0, 10], got {F_max!r}")
    path = _Path(mu, m, _far(mu, F_end), estimate=True)
    h = _element(mu, m)
    states = path.climb(path.far(), lambda st: _past_minimum(st, 0.5) and st[-1].F >= F_end, h)
    states = _ended(path, states, F_end)
    F = np.array([s.F for s in states])
    path.estimate = False  # the states of the extrema's refinement are not the curve's
    i_po = _lowest(mu, states)
    po = _refined(path, states, i_po)[0]
    jump = math.nan
    before = [i for i in _extrema(F)[1] if i < i_po]
    if before:
        jump = _refined(path, states, before[-1], -1.0)[0].F
    delta = np.array([s.delta for s in states])
    dF, dd = np.gradient(F), np.gradient(delta)
    return SphereLJCurve(
        approach_over_z0=delta,
        F_over_piwR=F,
        error_estimate=_over_neighbours(
            np.array([path.errors.get(s.tau, math.nan) for s in states])
        ),
        central_gap_over_z0=np.array([s.central_gap for s in states]),
        contact_radius=np.array([s.contact_radius for s in states]),
        stable=dF > 0.0,
        stable_displacement=dd > 0.0,
        tabor_parameter=mu,
        F_pulloff_over_piwR=po.F,
        F_jump_in_over_piwR=jump,
        n_rings=int(path.mesh.mid.size),
    )
