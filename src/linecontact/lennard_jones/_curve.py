"""The curve ``F(g0)`` of the Lennard-Jones law: continuation, pull-off, contact for a load.

Pseudo-arclength continuation in the central gap, the load and the profile from far away
through the turning points of the load; :func:`lj_curve`, :func:`lj_pull_off`,
:func:`lj_state`, :func:`lj_contact_for_load` and their results, and
:class:`LJContinuation`, the curve at one ``mu`` that a caller keeps to ask it several
things (the warm start is the caller's: the module keeps no state between calls).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray

from .._threads import on_one_blas_thread
from ..errors import NoEquilibriumError
from ..results import Result
from . import _branch as _b
from ._limit import MU_SELF_CONSISTENT, limit_pull_off
from ._matching import maugis_parameter_of_mu
from ._solver import (
    _EDGE_GAP,
    _check_m,
    _edge_meshes,
    _grid_for,
    _law,
    _solve,
    _Solved,
)

# ---------------------------------------------------------------------------------------
# results


@dataclass(frozen=True)
class LJState(Result):
    r"""One equilibrium state under the Lennard-Jones law (nondimensional).

    Lengths along the surface over :math:`\sqrt{R z_0}`, gaps over :math:`z_0`, pressure over
    :math:`w/z_0`, the load per unit length over :math:`w \sqrt{R/z_0}` (compressive positive).

    Attributes
    ----------
    central_gap_over_z0, mu : float
        The control :math:`\zeta_0 = g_0/z_0` and the group :math:`\mu`.
    F : float
        The load (Richardson extrapolation of the two finer meshes).
    error_estimate : float
        Estimated absolute error of ``F`` (its change from the coarser pair of meshes).
    half_width : float
        Half-width of the repulsive region, 0 where there is none: the outermost place where
        the gap crosses ``z0`` (the cubic through the nodal gaps about it), extrapolated as
        ``F`` (``docs/lennard-jones.md``; its estimate: :attr:`LJCurve.half_width_error_estimate`).
    residual : float
        Largest residual of the gap equation at the nodes, relative to the gap there.
    n : int
        Nodes of the finest mesh.
    converged : bool
        Always ``True`` (a state that does not converge raises ``ConvergenceError``).
    xi, gap_over_z0, pressure : ndarray
        The nodes (half line), the gap and :math:`p z_0/w` there (finest mesh).
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
        central_gap_over_z0=s.central_gap,
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


@dataclass(frozen=True)
class LJCurve(Result):
    r"""The load curve ``F(g0)`` under the Lennard-Jones law (nondimensional, as :class:`LJState`).

    Columns (one per point, the central gap decreasing): ``central_gap_over_z0``, ``F``,
    ``error_estimate``, ``half_width``, ``stable`` (under load control: :math:`dF/dg_0 < 0`) and
    ``turning`` (the extrema of the load: pull-off and, where the curve is S-shaped, the
    jump-in load and the local minimum before it). The extrema are located (a bracketed
    search on the solver, not the nearest sample) and are points of the curve; ``turning``
    marks them. ``error_estimate`` bounds the error of ``F`` at the point's central gap:
    the largest Richardson estimate of the point and its two neighbours, plus
    :math:`|dF/dg_0|` times the estimated error of the central gap (a state held at its edge
    has its central gap extrapolated too). ``half_width`` is the outermost place where
    the gap crosses :math:`z_0` (the cubic through the nodal gaps about it; 0 where the gap
    exceeds :math:`z_0` everywhere), extrapolated as the load; ``half_width_error_estimate``
    is, as the load's, the largest Richardson estimate of the point and its two neighbours
    plus :math:`|d(\text{half-width})/dg_0|` times the central gap's estimate. ``pull_off``
    holds the pull-off point.

    Attributes
    ----------
    F_local_minimum, central_gap_at_local_minimum : float
        The local minimum of the S-shaped curve (before the jump-in, the central gap
        decreasing) and where it occurs; ``nan`` where the curve has one minimum.
    F_local_minimum_error_estimate, central_gap_at_local_minimum_error_estimate : float
        Their estimated errors. The central gap of an extremum is ill-conditioned: its
        estimate is :math:`\sqrt{4 \epsilon/|F''|}` (where the load lies within :math:`2\epsilon`
        of the extremum), :math:`\epsilon` the load's estimate plus the spread of the fine
        mesh's error about it (the state found is the fine load's extremum), plus the
        central gap's own estimate. It bounds, and overstates (see the docs).
    F_jump_in_error_estimate, central_gap_at_jump_in_error_estimate : float
        The same for the jump-in (``pull_off.F_jump_in``); ``nan`` where there is none.
    central_gap_at_pulloff_error_estimate : float
        The same for the pull-off's central gap (its load's estimate is
        ``pull_off.error_estimate``).
    """

    inputs: ClassVar[tuple[str, ...]] = ("mu",)
    whole: ClassVar[tuple[str, ...]] = (
        "F_local_minimum",
        "central_gap_at_local_minimum",
        "F_local_minimum_error_estimate",
        "central_gap_at_local_minimum_error_estimate",
        "F_jump_in_error_estimate",
        "central_gap_at_jump_in_error_estimate",
        "central_gap_at_pulloff_error_estimate",
    )

    central_gap_over_z0: NDArray
    F: NDArray
    error_estimate: NDArray
    half_width: NDArray
    half_width_error_estimate: NDArray
    stable: NDArray
    turning: NDArray
    mu: float
    pull_off: LJPullOff = field(repr=False)
    F_local_minimum: float = math.nan
    central_gap_at_local_minimum: float = math.nan
    F_local_minimum_error_estimate: float = math.nan
    central_gap_at_local_minimum_error_estimate: float = math.nan
    F_jump_in_error_estimate: float = math.nan
    central_gap_at_jump_in_error_estimate: float = math.nan
    central_gap_at_pulloff_error_estimate: float = math.nan


@dataclass(frozen=True)
class LJPullOff(Result):
    r"""Pull-off under the Lennard-Jones law (nondimensional, as :class:`LJState`).

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
        Nodes of the finest mesh (0 for the limit form).
    converged : bool
    method : str
        ``"self-consistent"`` (:math:`\mu \le` ``MU_SELF_CONSISTENT``) or ``"limit"``: the JKR limit
        with its fitted correction (:mod:`linecontact.lennard_jones._limit`), its error
        estimate the whole correction; the jump-in is then ``nan`` (not computed).
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
    method: str = "self-consistent"


def _pull_off_of(mu, po, jump) -> LJPullOff:
    return LJPullOff(
        mu=mu,
        F_pulloff=po.F,
        central_gap_at_pulloff=po.central_gap,
        half_width_at_pulloff=po.half_width,
        error_estimate=po.error,
        F_jump_in=math.nan if jump is None else jump.F,
        central_gap_at_jump_in=math.nan if jump is None else jump.central_gap,
        maugis_parameter=float(maugis_parameter_of_mu(mu)),
        n=int(po.mesh.nodes.size),
        converged=True,
    )


def _with_neighbours(own: NDArray) -> NDArray:
    """The largest of each point's estimate and its two neighbours'.

    A Richardson estimate is the difference of two extrapolations; where they happen to
    agree it falls far below the error (to 4e-8 among neighbours of 1e-6, at mu = 10),
    while the error varies smoothly along the curve.
    """
    return np.maximum(own, np.maximum(np.r_[own[1:], 0.0], np.r_[0.0, own[:-1]]))


def _gap_of_extremum(z: NDArray, F: NDArray, k: int, error: float) -> float:
    r"""The uncertainty of the central gap of the extremum ``k`` of the curve ``(z, F)``.

    A load known to :math:`\pm\epsilon` (``error``) fixes its extremum only to where the load
    lies within :math:`2\epsilon` of it: :math:`|\Delta g_0| \le \sqrt{4\epsilon/|F''|}`, with
    :math:`F''` of the parabola through the point and its two neighbours.
    """
    if k == 0 or k == z.size - 1:
        return math.nan
    x, y = z[k - 1 : k + 2], F[k - 1 : k + 2]
    d2 = 2.0 * ((y[2] - y[1]) / (x[2] - x[1]) - (y[1] - y[0]) / (x[1] - x[0])) / (x[2] - x[0])
    return math.sqrt(4.0 * error / abs(d2)) if d2 != 0.0 else math.inf


#: Default end of a curve: three times the rigid cylinder's pull-off, compressive.
F_MAX_DEFAULT = 7.5


class LJContinuation:
    r"""The load curve at one :math:`\mu`, followed once: a warm start its caller owns.

    The states found along the curve (the far part, the edges) and the pull-off are kept
    on the object: a curve and then states between its points (the adhesion map), or the
    contacts for several loads, go on from them instead of from far away. Only speed
    depends on it (a state continued from a neighbour agrees with a fresh one within the
    solver's tolerance). A result depends on the calls made on its object alone, never on
    what other calls met before: :func:`lj_curve`, :func:`lj_pull_off`, :func:`lj_state`
    and :func:`lj_contact_for_load` each make a fresh one.

    Parameters
    ----------
    mu : float
        :math:`w \sqrt{R/z_0}/(E z_0)`, in ``[0, 400]`` (0: rigid).
    m : int, optional
        Elements of the uniform core on the finest mesh (multiple of 4).
    """

    def __init__(self, mu: float, m: int | None = None) -> None:
        self.mu = _check_mu(mu)
        self.m = m
        self._grid = _grid_for(self.mu, m)
        self._states: list[_Solved] = []  # along the curve, from far away
        self._found: tuple[_Solved, _Solved | None] | None = None  # pull-off, jump-in

    def _pull_off_states(self) -> tuple[_Solved, _Solved | None]:
        """:func:`~._branch.pull_off_search`, once per object."""
        if self._found is None:
            self._found = _b.pull_off_search(self.mu, self._grid)
        return self._found

    def _along(self, done) -> list[_Solved]:
        """The states along the curve until ``done`` holds of one (from those found)."""
        states = self._states or _b.far(self.mu, self._grid)
        if not any(done(states[: i + 1]) for i in range(len(states))):
            states = _b.climb(self.mu, self._grid, states, done)
        self._states = states
        return states

    @on_one_blas_thread
    def curve(self, F_max: float | None = None) -> LJCurve:
        """The load curve from far away through its turning points to ``F_max``.

        As :func:`lj_curve`.
        """
        mu, grid = self.mu, self._grid
        F_max = F_MAX_DEFAULT if F_max is None else float(F_max)
        if not (np.isfinite(F_max) and F_max > 0):
            raise ValueError(f"F_max must be a finite load > 0, got {F_max!r}")
        states = self._along(lambda st: st[-1].F >= F_max and st[-1].half_width > 0)
        states = states[
            : 1 + next(i for i, s in enumerate(states) if s.F >= F_max and s.half_width > 0)
        ]
        po, jump, low, _ = _b.turning_points(mu, grid, states)
        located = [t for t in (po, jump, low) if t is not None]
        extra = [t for t in located if not any(t is s for s in states)]
        # a sample solved again at its own central gap (the search found nothing better)
        # gives way to the located state: the central gap stays strictly decreasing
        kept = [
            s
            for s in states
            if not any(abs(s.central_gap - t.central_gap) <= 1e-5 * t.central_gap for t in extra)
        ]
        points = sorted(kept + extra, key=lambda s: -s.central_gap)
        z = np.array([s.central_gap for s in points])
        F = np.array([s.F for s in points])
        with np.errstate(divide="ignore", invalid="ignore"):
            dF = np.gradient(F, z)
        near = _with_neighbours(np.array([s.error for s in points]))
        gap_error = np.array([s.gap_error for s in points])
        width = np.array([s.half_width for s in points])
        with np.errstate(divide="ignore", invalid="ignore"):
            dw = np.abs(np.nan_to_num(np.gradient(width, z)))
        width_error = _with_neighbours(np.array([s.half_width_error for s in points]))
        turning = np.zeros(z.size, bool)
        at = {id(s): i for i, s in enumerate(points)}
        for t in located:
            turning[at[id(t)]] = True

        def where(t: _Solved | None) -> tuple[float, float]:
            """The estimates of an extremum's load and central gap."""
            if t is None:
                return math.nan, math.nan
            k = at[id(t)]
            # the state found is the extremum of the fine mesh's load: its place is off by
            # what the fine mesh's error varies across it, plus the load's own error
            fine_error = np.array([s.F - s.F_fine for s in points[max(0, k - 1) : k + 2]])
            error = float(near[k]) + float(np.ptp(fine_error))
            return float(near[k]), _gap_of_extremum(z, F, k, error) + t.gap_error

        lo, jp, pk = where(low), where(jump), where(po)
        return LJCurve(
            central_gap_over_z0=z,
            F=F,
            error_estimate=near + np.abs(np.nan_to_num(dF)) * gap_error,
            half_width=width,
            half_width_error_estimate=width_error + dw * gap_error,
            stable=dF < 0,
            turning=turning,
            mu=mu,
            pull_off=_pull_off_of(mu, po, jump),
            F_local_minimum=math.nan if low is None else low.F,
            central_gap_at_local_minimum=math.nan if low is None else low.central_gap,
            F_local_minimum_error_estimate=lo[0],
            central_gap_at_local_minimum_error_estimate=lo[1],
            F_jump_in_error_estimate=jp[0],
            central_gap_at_jump_in_error_estimate=jp[1],
            central_gap_at_pulloff_error_estimate=pk[1],
        )

    @on_one_blas_thread
    def pull_off(self) -> LJPullOff:
        """The pull-off force and the jump-in load (as :func:`lj_pull_off`)."""
        if self.mu > MU_SELF_CONSISTENT:
            return _limit_of(self.mu)
        po, jump = self._pull_off_states()
        return _pull_off_of(self.mu, po, jump)

    @on_one_blas_thread
    def state(self, central_gap_over_z0: float) -> LJState:
        """The equilibrium state at the central gap ``zeta0`` (as :func:`lj_state`)."""
        from .. import domain as _domain

        z = float(_domain.scalar("central_gap_over_z0", central_gap_over_z0))
        mu, grid = self.mu, self._grid
        s = _b.first(mu, grid)
        if z >= _EDGE_GAP:
            t = _solve(z, mu, grid.meshes(s.mesh.spec), s.zeta)
            if t is None:
                t = _b._down(mu, grid, s, z) if z < s.zeta0 else None
            if t is None:
                raise _b.fail("state", mu, z)
            return _state_of(t, mu)
        states = self._along(lambda st: st[-1].central_gap <= z)
        k = next(i for i, s in enumerate(states) if s.central_gap <= z)
        a, b = states[k - 1], states[k]
        pool = list(states[: k + 1])
        if a.edge == 0.0:  # between the far part and the first edge: in the central gap
            t = _solve(z, mu, grid.meshes(a.mesh.spec), a.zeta)
            if t is None:
                raise _b.fail("state", mu, z)
            return _state_of(t, mu)

        def g(e: float) -> float:
            t = _b.at_edge(mu, grid, pool, e)
            if t is None:
                raise _b.fail("state", mu, z)
            pool.append(t)
            return t.central_gap - z

        ga, gb = a.central_gap - z, b.central_gap - z
        e = a.edge if ga == 0.0 else _b.root(g, a.edge, b.edge, ga, gb, 1e-12 * b.edge, 1e-13 * z)
        near = min(pool, key=lambda t: abs(t.edge - e))
        # the state found holds its edge; where it can, the one returned holds the central
        # gap on all three meshes, so that its load's estimate is the error at that central
        # gap (on the contact branch of a compliant contact the central gap hardly moves, and
        # a coarse mesh may hold no state at it: then the state at the edge whose
        # extrapolated gap is zeta0)
        t = _solve(z, mu, _edge_meshes(grid, near.edge), near.zeta)
        return _state_of(near if t is None else t, mu)

    @on_one_blas_thread
    def contact_for_load(self, F: float) -> LJState:
        """The state on the stable contact branch carrying the load ``F``.

        As :func:`lj_contact_for_load`.
        """
        F = float(F)
        if not np.isfinite(F):
            raise ValueError(f"F must be finite, got {F!r}")
        mu, grid = self.mu, self._grid
        po, _ = self._pull_off_states()
        if F < po.F:
            raise NoEquilibriumError(
                f"no equilibrium: the load F={F!r} is below the pull-off force {po.F!r} "
                f"(mu={mu!r}); the contact has already pulled off"
            )
        if F == po.F:
            return _state_of(po, mu)
        branch = _b.climb(mu, grid, [po], lambda st: st[-1].F >= F)
        a, b = branch[-2], branch[-1]
        if F == b.F:
            return _state_of(b, mu)
        pool = list(branch)

        def g(e: float) -> float:
            for known in pool:
                if known.edge == e:
                    return known.F - F
            t = _b.at_edge(mu, grid, pool, e)
            if t is None:
                raise _b.fail("contact for a load", mu, b.zeta0)
            pool.append(t)
            return t.F - F

        ftol = 1e-12 * max(1.0, abs(F))
        e = _b.root(g, a.edge, b.edge, a.F - F, b.F - F, 1e-13 * b.edge, ftol)
        return _state_of(min(pool, key=lambda t: abs(t.edge - e)), mu)


def lj_curve(mu: float, *, F_max: float | None = None, m: int | None = None) -> LJCurve:
    r"""The load curve ``F(g0)`` from far away through its turning points to ``F_max``.

    Parameters
    ----------
    mu : float
        :math:`w \sqrt{R/z_0}/(E z_0)`, ``>= 0`` (0: rigid).
    F_max : float, optional
        Compressive load where the curve ends (over :math:`w \sqrt{R/z_0}`), default
        :data:`F_MAX_DEFAULT`.
    m : int
        Elements of the uniform core on the finest mesh (multiple of 4).
    """
    return LJContinuation(mu, m).curve(F_max)


def _limit_of(mu: float) -> LJPullOff:
    """The pull-off beyond the self-consistent domain: the corrected JKR limit."""
    F, err, gap = limit_pull_off(mu)
    return LJPullOff(
        mu=mu,
        F_pulloff=F,
        central_gap_at_pulloff=gap,
        half_width_at_pulloff=0.0,
        error_estimate=err,
        F_jump_in=math.nan,
        central_gap_at_jump_in=math.nan,
        maugis_parameter=float(maugis_parameter_of_mu(mu)),
        n=0,
        converged=True,
        method="limit",
    )


def lj_pull_off(mu: float, *, m: int | None = None) -> LJPullOff:
    r"""The pull-off force (the most tensile load of :func:`lj_curve`) and the jump-in load.

    Every :math:`\mu \ge 0`: self-consistent up to :data:`MU_SELF_CONSISTENT`, beyond by the
    corrected JKR limit (``method == "limit"``, :func:`limit_pull_off`).
    """
    from .. import domain as _domain

    mu = float(_domain.scalar("mu", mu, key="lj_mu_pull_off"))
    if mu > MU_SELF_CONSISTENT:
        if m is not None:
            _check_m(m)
        return _limit_of(mu)
    return LJContinuation(mu, m).pull_off()


def lj_state(central_gap_over_z0: float, mu: float, *, m: int | None = None) -> LJState:
    """The equilibrium state at the central gap ``zeta0`` (continued from far away).

    Beyond :data:`_START` by Newton from the first state; down to ``_EDGE_GAP`` on the far
    part's mesh; below, along the edge until the central gap falls below ``zeta0``, then a
    root search in the edge (the central gap falls monotonically along the curve) and the
    state held at ``zeta0`` on all three meshes where they hold it.
    """
    from .. import domain as _domain

    z = float(_domain.scalar("central_gap_over_z0", central_gap_over_z0))
    return LJContinuation(mu, m).state(z)


def lj_contact_for_load(F: float, mu: float, *, m: int | None = None) -> LJState:
    """The state on the stable contact branch (beyond the pull-off) carrying the load ``F``.

    Raises :class:`~linecontact.errors.NoEquilibriumError` for a load below the pull-off.
    """
    F = float(F)
    if not np.isfinite(F):
        raise ValueError(f"F must be finite, got {F!r}")
    return LJContinuation(mu, m).contact_for_load(F)
