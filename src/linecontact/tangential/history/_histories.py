"""Tangential load histories: the results and the two public functions.

:func:`tangential_history` (constant friction stress) and
:func:`tangential_history_coulomb` (Coulomb friction on the Hertz contact), by the Masing
rules (``_masing_rules.py``) or the incremental solver (``_collocation.py``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ... import domain as _domain
from ..._validation import FailurePolicy, check_array, check_solver_options, failure_policy
from ...errors import ConvergenceError
from ...results import SI, Result
from ._collocation import N_INCREMENTAL, N_MAX_INCREMENTAL, _Incremental, _incremental
from ._laws import _LAWS, _Law
from ._masing_rules import _Masing, _masing

_T_LIMIT = 1e12  # |T| over the scale: keeps every intermediate quantity finite

#: A step of the incremental solver that opens a new stick zone (from rest, or reversing the
#: load) by at most this fraction of the full-slip load, under a constant friction stress,
#: puts the zone's edge within round-off of the contact's: at every size up to
#: N_MAX_INCREMENTAL its stick residual stays at 2.9e-5 (5.8e-5 after a reversal) and its
#: error estimate at 2.2e-7, whatever the step, tau0 or n (measured). Coulomb friction,
#: whose traction vanishes at the edge, resolves such steps.
_TINY_STEP = 1e-4
#: The smallest stick residual of such a step: a tolerance below it is missed for certain.
_TINY_STEP_RESIDUAL = 2.5e-5

_STICK = "stick"
_STICK_SLIP = "stick-slip"
_SLIDING = "sliding"


@dataclass(frozen=True)
class _History(Result):
    """Shared fields and methods of the two history results (one point per step)."""

    step: NDArray
    T_over_Ea: NDArray = field(metadata=SI("tangential_load", "Ea", "N/m"))
    T_over_T_full_slip: NDArray
    c_over_a: NDArray = field(metadata=SI("stick_zone_half_width", "a", "m"))
    slip_direction: NDArray
    state: NDArray
    memory: NDArray
    displacement_over_a: NDArray = field(metadata=SI("displacement", "a", "m"))
    dissipation_over_Ea2: NDArray = field(metadata=SI("dissipation", "Ea2", "J/m"))
    method: str
    n_collocation: NDArray
    residual_stick: NDArray
    residual_admissible: NDArray
    error_estimate: NDArray
    converged: NDArray
    _states: Any = field(repr=False)
    _scale: float = field(repr=False)

    def _steps(self, steps) -> NDArray:
        n = self.step.size
        idx = np.arange(n) if steps is None else np.asarray(steps)
        if idx.dtype.kind not in "iu" or np.any((idx < -n) | (idx >= n)):
            raise ValueError(
                f"steps must be integer indices in [-{n}, {n - 1}] (as for a NumPy array), "
                f"got {steps!r}"
            )
        return np.where(idx < 0, idx + n, idx)

    def traction(self, x_over_a: ArrayLike, steps: ArrayLike | None = None) -> NDArray:
        """Shear traction :math:`q/E` at :math:`x/a` after each step: shape ``(steps, m)``.

        ``steps`` (indices into the history, default all) selects the steps.
        """
        x = check_array("x_over_a", x_over_a, low=-np.inf).reshape(-1)
        return self._scale * self._states.traction(x, self._steps(steps))

    def slip(self, x_over_a: ArrayLike, steps: ArrayLike | None = None) -> NDArray:
        """Accumulated slip :math:`s/a` at :math:`x/a` after each step (relative to the centre).

        Zero in the part of the stick zone that never slipped, constant in time wherever
        the surfaces stick, ``nan`` outside the contact; shape ``(steps, m)``.
        """
        x = check_array("x_over_a", x_over_a, low=-np.inf).reshape(-1)
        return self._scale * self._states.slip(x, self._steps(steps))

    def zones(self) -> list[list[tuple[float, float, str]]]:
        r"""The zones of :math:`0 \le x/a \le 1` after each step (the contact is symmetric).

        Each zone is ``(from, to, kind)``: ``"stick"`` (never slipped), ``"locked+"`` /
        ``"locked-"`` (slipped earlier, last along ``+x`` / ``-x``, stuck now), ``"slip+"``
        / ``"slip-"`` (slipping at the end of the step), ``"sliding"`` (the whole contact).
        Only the closed-form (Masing) states know the frozen zones; for the incremental
        solver the stick zone is reported as one zone ``"stick"``.
        """
        out = []
        for j in range(self.step.size):
            if self.state[j] == _SLIDING:
                out.append([(0.0, 1.0, _SLIDING)])
                continue
            if self.state[j] == _STICK:
                out.append([(0.0, 1.0, _STICK)])
                continue
            zs: list[tuple[float, float, str]] = []
            if isinstance(self._states, _Masing):
                coef, r = self._states.coef[j], self._states.r[j]
                keep = coef != 0
                coef, r = coef[keep], r[keep]
                # the stick zones nest; round-off must not turn two equal ones round
                d = np.minimum(np.maximum.accumulate(self._states.law.stick(r)), 1.0)
                bounds = [0.0, *d.tolist(), 1.0]
                kinds = [_STICK] + [("locked+" if c > 0 else "locked-") for c in coef[:-1]]
                kinds.append("slip+" if coef[-1] > 0 else "slip-")
                for lo, hi, kind in zip(bounds[:-1], bounds[1:], kinds, strict=True):
                    if hi > lo:
                        zs.append((lo, hi, kind))
            else:
                cj = float(self.c_over_a[j])
                zs.append((0.0, cj, _STICK))
                if cj < 1.0:
                    zs.append((cj, 1.0, "slip+" if self.slip_direction[j] > 0 else "slip-"))
            out.append(zs)
        return out


@dataclass(frozen=True)
class TangentialHistory(_History):
    r"""A tangential load history with constant friction stress ``tau0`` (one point per step).

    Attributes
    ----------
    step : ndarray of int
        1, 2, ... (the state before step 1 is unloaded and has never slipped).
    T_over_Ea : ndarray
        The load at the end of the step, :math:`T/(E a)` (either sign).
    T_over_T_full_slip : ndarray
        :math:`T/(2 a \tau_0)`.
    c_over_a : ndarray
        Half-width of the stick zone :math:`|x| < c` at the end of the step (``1`` unloaded or at
        a turning point just reached from rest; ``nan`` when sliding).
    slip_direction : ndarray of int
        ``+1`` / ``-1``: the direction of the slip in the step's slip zones (the direction
        the load moved); ``0`` before any load.
    state : ndarray of str
        ``"stick"`` (unloaded), ``"stick-slip"`` or ``"sliding"`` (the load reached
        :math:`2 a \tau_0` on the virgin branch: gross sliding).
    memory : ndarray of int
        Turning points held in memory (the closed-form states; ``-1`` for the incremental
        solver, which keeps none).
    displacement_over_a : ndarray
        :math:`D/a`, the cylinder's displacement relative to the substrate with the datum at
        depth ``a`` (``nan`` when sliding; after a slide it excludes the sliding distance,
        which a force-controlled history does not determine).
    dissipation_over_Ea2 : ndarray
        Energy dissipated by friction in the step, per unit length over :math:`E a^2` (``nan``
        for a step that slides).
    tau0_over_E : float
    method : str
        ``"closed-form"`` (Masing rules) or ``"incremental"`` (collocation, step by step).
    n_collocation : int
        Nodes of the incremental solver (0 for the closed form).
    residual_stick : ndarray
        Largest residual of the stick condition at 16 points other than the collocation
        points, over ``tau0`` (0 for the closed form).
    residual_admissible : ndarray
        Largest violation of the friction law: :math:`|q|` above :math:`\tau_0` in the stick zone,
        or slip against the traction in the slip zone (over :math:`\tau_0` and :math:`a \tau_0/E`; 0
        for the closed form).
    error_estimate : ndarray
        Chebyshev tail of the step's stick-zone solution over its largest coefficient.
    converged : ndarray of bool
    """

    inputs: ClassVar[tuple[str, ...]] = ("tau0_over_E", "method", "n_collocation")

    tau0_over_E: float = 0.0


@dataclass(frozen=True)
class CoulombTangentialHistory(_History):
    r"""A tangential load history of a Hertz line contact with Coulomb friction ``mu``.

    As :class:`TangentialHistory`, with ``T_over_T_full_slip`` = ``T_over_muF`` = :math:`T/(\mu F)`
    and the stresses of the diagnostics over :math:`\mu p_0`.
    """

    inputs: ClassVar[tuple[str, ...]] = ("mu", "a_over_R", "method", "n_collocation")

    T_over_muF: NDArray = field(default_factory=lambda: np.zeros(0))
    mu: float = 0.0
    a_over_R: float = 0.0


def _check_method(method: str, n: int, tol: float) -> None:
    if method not in ("closed-form", "incremental"):
        raise ValueError(f"method must be 'closed-form' or 'incremental', got {method!r}")
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 4 <= n <= 4096:
        raise ValueError(f"n must be an integer in [4, 4096], got {n!r}")
    check_solver_options(n, tol, n_max=N_MAX_INCREMENTAL)


def _loads(name: str, value: ArrayLike) -> NDArray:
    arr = check_array(
        name, value, low=-_T_LIMIT, low_inclusive=True, high=_T_LIMIT, high_inclusive=True
    )
    if arr.ndim > 1:
        raise ValueError(f"{name} must be a sequence of loads (1-D), got shape {arr.shape}")
    arr = arr.reshape(-1)
    if arr.size == 0:
        raise ValueError(f"{name} must hold at least one load, got an empty sequence")
    return arr


def _unresolvable_step(law: _Law, r: NDArray, tol: float) -> str | None:
    """Why the incremental solver would miss ``tol`` for certain (None: it may not).

    A step that opens a new stick zone by at most :data:`_TINY_STEP` of the full-slip load,
    under a constant friction stress, at a tolerance below :data:`_TINY_STEP_RESIDUAL`
    (the solver would try every size, seconds per such step, to raise the same error). The
    loads ``r`` are over the full-slip load; the steps are followed as the solver takes
    them (an equal load is no step, a slide restarts from the full-slip load).
    """
    if law.name != "constant" or not tol < _TINY_STEP_RESIDUAL:
        return None
    r_prev, d_prev = 0.0, 0
    for j, rj in enumerate(r.tolist()):
        if rj == r_prev:
            continue
        s = 1 if rj > r_prev else -1
        slid = abs(rj) >= 1.0 and np.sign(rj) == s
        change = abs(rj - r_prev)
        if s != d_prev and not slid and change <= _TINY_STEP:
            how = "from rest" if d_prev == 0 else "reversing the load"
            return (
                f"the incremental solver cannot resolve step {j + 1}: {how} by {change:.3g} "
                f"of the full-slip load (at most {_TINY_STEP:g}) puts the new stick zone "
                f"within round-off of the contact edge, and no size up to "
                f"{N_MAX_INCREMENTAL} nodes reaches tol={tol:g} (its residual stays above "
                f"{_TINY_STEP_RESIDUAL:g}); use method='closed-form'"
            )
        r_prev = math.copysign(1.0, rj) if slid else rj
        d_prev = s
    return None


def _history(
    law: _Law, r: NDArray, scale: float, method: str, n: int, tol: float, policy: FailurePolicy
) -> dict[str, Any]:
    """The fields shared by both results, for loads r over the full-slip load."""
    steps = r.size
    if method != "closed-form" and policy == "raise":
        why = _unresolvable_step(law, r, tol)
        if why is not None:  # said at once, not after seconds of trying every size
            raise ConvergenceError(why)
    if method == "closed-form":
        m = _masing(law, r)
        states: Any = _Masing(law, m["coef"], m["r"])
        last = np.take_along_axis(
            m["r"], (np.count_nonzero(m["coef"], axis=1) - 1)[:, None].clip(0), axis=1
        )[:, 0]
        c = law.stick(last)
        D = np.sum(m["coef"] * law.displacement(m["r"]), axis=1)
        zeros = np.zeros(steps)
        diag = dict(
            n_collocation=np.zeros(steps, int),
            residual_stick=zeros,
            residual_admissible=zeros,
            error_estimate=zeros,
            converged=np.ones(steps, bool),
        )
        depth = m["depth"]
    else:
        # to raise: stop at the first step that misses tol (the others are not needed)
        m = _incremental(law, r, n, stop_tol=tol if policy == "raise" else None)
        conv = (
            (m["error_estimate"] <= tol)
            & (m["residual_stick"] <= max(tol, 1e-10))
            & (m["residual_admissible"] <= max(tol, 1e-10))
        )
        if policy == "raise" and not conv.all():
            j = int(np.flatnonzero(~conv)[0])
            raise ConvergenceError(
                f"the incremental solver missed tol={tol:g} at step {j + 1} (T/T_full = "
                f"{float(r[j])!r}: error estimate {m['error_estimate'][j]:.2e}, stick residual "
                f"{m['residual_stick'][j]:.2e}, friction-law violation "
                f"{m['residual_admissible'][j]:.2e}, n={int(m['n_collocation'][j])}): a load "
                "change this small (or this close to the previous turning point) needs more "
                f"than {N_MAX_INCREMENTAL} nodes; use method='closed-form'"
            )
        states = _Incremental(law, m["sign"], m["parts"])
        c = m["c"].copy()
        D = states.displacement()
        diag = dict(
            n_collocation=m["n_collocation"],
            residual_stick=m["residual_stick"],
            residual_admissible=m["residual_admissible"],
            error_estimate=m["error_estimate"],
            converged=conv,
        )
        depth = np.full(steps, -1)
    sliding = m["sliding"]
    unloaded = (m["direction"] == 0) & ~sliding
    state = np.where(sliding, _SLIDING, np.where(unloaded, _STICK, _STICK_SLIP))
    c = np.where(sliding, np.nan, np.where(unloaded, 1.0, c))
    D = np.where(sliding, np.nan, D)
    return dict(
        step=np.arange(1, steps + 1),
        c_over_a=c,
        slip_direction=m["direction"],
        state=state,
        memory=depth,
        displacement_over_a=scale * D,
        dissipation_over_Ea2=scale * scale * m["loss"],
        method=method,
        _states=states,
        _scale=scale,
        **diag,
    )


def tangential_history(
    tau0_over_E: float,
    T_over_Ea: ArrayLike,
    *,
    method: str = "closed-form",
    n: int = N_INCREMENTAL,
    tol: float = 1e-6,
    on_failure: FailurePolicy = "raise",
) -> TangentialHistory:
    r"""States of the contact along a tangential load history, constant friction stress ``tau0``.

    The load starts from zero on a contact that has never slipped and moves monotonically
    from each value of ``T_over_Ea`` to the next; a change of direction is a reversal.

    Parameters
    ----------
    tau0_over_E : float
        Friction stress over the composite modulus, in ``[1e-12, 1]``.
    T_over_Ea : array_like, 1-D
        The loads :math:`T/(E a)` at the ends of the steps, either sign. Full slip is
        :math:`|T| = 2 a \tau_0`: a load that reaches it slides (``state == "sliding"``); the
        history then continues from the full-slip load.
    method : {"closed-form", "incremental"}
        Masing memory rules with closed forms (exact), or the stick condition solved
        step by step by collocation (``docs/load-histories.md``).
    n : int
        Collocation nodes of the incremental solver.
    tol : float
        Tolerance of the incremental solver on its error estimate and residuals.
    on_failure : {"raise", "report"}
        An incremental step that misses ``tol`` raises
        :class:`~linecontact.errors.ConvergenceError` (``"raise"``, default), or is flagged
        in ``converged`` (``"report"``); README, "Conventions". A load at or beyond full
        slip is no failure here: the step slides (``state == "sliding"``) under either
        policy.

    Returns
    -------
    TangentialHistory
        One point per step; :meth:`~TangentialHistory.traction`,
        :meth:`~TangentialHistory.slip` and :meth:`~TangentialHistory.zones` give the
        distributions.

    Examples
    --------
    Load to 0.8 of full slip, reverse to -0.4, load again beyond 0.8 to 0.9: the loop closes
    at 0.8 and is erased, and the state at 0.9 is the virgin one:

    >>> h = tangential_history(0.01, [0.016, -0.008, 0.018])
    >>> [round(c, 6) for c in h.c_over_a]
    [0.6, 0.8, 0.43589]
    >>> h.memory.tolist()
    [0, 1, 0]
    >>> virgin = tangential_history(0.01, [0.018])
    >>> bool(abs(h.displacement_over_a[2] - virgin.displacement_over_a[0]) < 1e-15)
    True
    """
    t0 = _domain.scalar("tau0_over_E", tau0_over_E)
    _check_method(method, n, tol)
    policy = failure_policy(on_failure)
    T = _loads("T_over_Ea", T_over_Ea)
    r = T / (2 * t0)
    fields_ = _history(_LAWS["constant"], r, t0, method, n, tol, policy)
    return TangentialHistory(T_over_Ea=T, T_over_T_full_slip=r, tau0_over_E=t0, **fields_)


def tangential_history_coulomb(
    mu: float,
    a_over_R: float,
    T_over_muF: ArrayLike,
    *,
    method: str = "closed-form",
    n: int = N_INCREMENTAL,
    tol: float = 1e-6,
    on_failure: FailurePolicy = "raise",
) -> CoulombTangentialHistory:
    r"""States of a Hertz line contact with Coulomb friction along a tangential load history.

    The Mindlin--Deresiewicz rules for the line contact (Cattaneo--Mindlin for each
    branch). Parameters as in :func:`tangential_history`, with

    Parameters
    ----------
    mu : float
        Coefficient of friction.
    a_over_R : float
        Hertz half-width over the radius (:math:`p_0 = E a/(2R)`, :math:`F = \pi E a^2/(4R)`).
    T_over_muF : array_like, 1-D
        The loads over :math:`\mu F`, either sign; :math:`|T| \ge \mu F` slides.
    method, n, tol, on_failure
        As in :func:`tangential_history`.

    Returns
    -------
    CoulombTangentialHistory

    Examples
    --------
    >>> h = tangential_history_coulomb(0.3, 0.01, [0.5, -0.5])
    >>> [round(c, 12) for c in h.c_over_a]
    [0.707106781187, 0.707106781187]
    """
    m = _domain.scalar("mu", mu)
    A = _domain.scalar("a_over_R", a_over_R)
    _check_method(method, n, tol)
    policy = failure_policy(on_failure)
    Q = _loads("T_over_muF", T_over_muF)
    scale = m * A / 2  # mu p0 / E
    fields_ = _history(_LAWS["coulomb"], Q, scale, method, n, tol, policy)
    return CoulombTangentialHistory(
        T_over_Ea=(np.pi / 4) * m * A * Q,
        T_over_T_full_slip=Q,
        T_over_muF=Q,
        mu=m,
        a_over_R=A,
        **fields_,
    )
