r"""A fibre pushed sideways: will it stay, roll or slide (the paper's future work).

A push ``Q`` per unit length acts horizontally at height ``H`` above the substrate on a
cylinder under the normal load ``F``, held by Maugis--Dugdale adhesion with the receding
range ``h1`` (trailing edge) and the advancing range ``h2`` (leading edge), :math:`h_1 \ge h_2`,
and by a friction stress ``tau0``. The derivation is ``docs/push.md``:

- the contact of steady motion, rolling or sliding, is the steady sliding contact at the load
  (half-width ``a_slide``); its pressure's moment about the axis is :math:`R\,\Delta w`, with the
  adhesion hysteresis :math:`\Delta w = \sigma_0 (h_1 - h_2)`;
- rolling resistance :math:`Q_\text{roll} = R\,\Delta w / H` (moment balance; energy gives the
  same), with the contact shear :math:`S = Q_\text{roll} (H - R)/R` that the steady rolling solution
  carries (its creep is reported);
- sliding resistance :math:`Q_\text{slide} = 2 a_\text{slide} \tau_0 + \Delta w` (friction, and the
  horizontal pull of the adhesive zones on the curved surface, which the energy balance requires);
- the first motion is the one with the lower resistance: rolling iff
  :math:`H > H^* = R\,\Delta w / Q_\text{slide}`; gross slip of the contact at rest (half-width
  ``a_rest``, the normal contact with the advancing range) starts at
  :math:`Q_\text{onset} = 2 a_\text{rest} \tau_0`, and the resistance rises to
  :math:`Q_\text{slide}` as the trailing edge stretches: the static peak is the kinetic value.

Groups as in steady sliding: lengths over ``R`` (``H_over_R``) or ``h2``, forces per unit
length over ``E h2``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import domain as _domain
from ._validation import broadcast, check_array, first_point, point_text, scalar_or_array
from .errors import ConvergenceError
from .normal import pull_off
from .normal.inverse import _contact_for_load
from .normal.pulloff import _pulloff_arrays
from .results import SI, Result, as_output
from .sliding.inverse import _sliding_ends, _sliding_for_load
from .tangential import sliding_initiation, steady_rolling

__all__ = ["Push", "TipPush", "push", "tip_push"]

#: The states of a pushed fibre (``Push.state``) and its first motions.
STATES = ("rest", "roll", "slide", "roll+slide", "lift-off")


@dataclass(frozen=True)
class Push(Result):
    r"""Rolling and sliding resistance of a pushed fibre, its first motion and its state.

    Attributes
    ----------
    H_over_R : ndarray or float
        Height of the push above the substrate over ``R`` (1 at the axis); for a tip, the
        height where it touches the fibre.
    H_arm_over_R : ndarray or float
        The moment arm of the push about the contact: ``H``, or the tip's ``H_eff``
        (:func:`tip_push`).
    tip_friction : ndarray or float
        The tip's friction coefficient (NaN for a horizontal push).
    a_rest_over_R : ndarray or float
        Contact half-width at rest (the normal contact at the load with the advancing
        range ``h2``); NaN where no contact at rest carries the load (it is below the
        pull-off force of the contact at rest, though not below that of steady sliding).
    a_slide_over_R : ndarray or float
        Contact half-width of steady motion (the steady sliding contact at the load).
    Q_roll_over_Eh2 : ndarray or float
        Steady rolling resistance :math:`R\,\Delta w / H` (``inf`` at :math:`H = 0`): the moment of
        the sliding contact's pressure about the axis, :math:`M - e F = R\,\Delta w`, over the
        arm.
    Q_slide_over_Eh2 : ndarray or float
        Steady sliding resistance :math:`2 a_\text{slide} \tau_0 + \Delta w`; the static (peak)
        value too.
    friction_over_Eh2, hysteresis_over_Eh2 : ndarray or float
        Its two parts: :math:`2 a_\text{slide} \tau_0` and :math:`\Delta w = \sigma_0 (h_1 - h_2)`.
    Q_onset_over_Eh2 : ndarray or float
        :math:`2 a_\text{rest} \tau_0`: gross slip of the contact at rest begins (the resistance
        then rises to :math:`Q_\text{slide}` as the trailing edge stretches).
    H_critical_over_R : ndarray or float
        :math:`H^* = R\,\Delta w / Q_\text{slide}`: rolling comes first for a moment arm above it.
    first_motion : ndarray of str or str
        ``"roll"``, ``"slide"``, or ``"roll+slide"`` (rolling comes first but needs more shear than
        the contact holds, :math:`|S_\text{roll}| \ge 2 a_\text{slide} \tau_0`); with a tip below
        the axis also ``"lift-off"`` (its vertical pull takes the load to the pull-off force of the
        contact at rest before either resistance is reached).
    S_roll_over_Eh2 : ndarray or float
        The contact's shear on the fibre while rolling, :math:`Q_\text{roll} (H - R)/R` (negative:
        resisting, below the axis; positive: driving, above it).
    creep_over_V : ndarray or float
        Creep while rolling, :math:`(V - \omega R)/V` (negative when the shear drives); NaN
        where the contact cannot hold ``S_roll``. Also the relative size of the
        difference between the energy and moment balances (``docs/push.md`` section 2).
    Q_over_Eh2 : ndarray or float
        The push given (NaN without one).
    state : ndarray of str or str
        For a push given: ``"rest"``, ``"roll"``, ``"slide"``, ``"roll+slide"`` (above
        both resistances) or ``"lift-off"`` (a tip); ``""`` without one.
    d_over_a_rest : ndarray or float
        Stick-zone half-width over ``a_rest`` at rest under the push given (0 from
        ``Q_onset`` on: the fibre has slipped and stopped, the trailing edge stretched);
        NaN when moving or without a push.
    residual_load : ndarray or float
        Relative residual of the two load inversions (the contacts carry ``F``).
    converged : ndarray or bool
        Every sub-solution converged (always True in a result: push raises otherwise).
    """

    inputs: ClassVar[tuple[str, ...]] = (
        "R_over_h2",
        "h1_over_h2",
        "sigma0_over_E",
        "tau0_over_E",
        "F_over_Eh2",
    )

    H_over_R: NDArray | float = field(metadata=SI("height", "R", "m"))
    H_arm_over_R: NDArray | float = field(metadata=SI("moment_arm", "R", "m"))
    tip_friction: NDArray | float
    a_rest_over_R: NDArray | float = field(metadata=SI("rest_half_width", "R", "m"))
    a_slide_over_R: NDArray | float = field(metadata=SI("slide_half_width", "R", "m"))
    Q_roll_over_Eh2: NDArray | float = field(metadata=SI("rolling_resistance", "Eh", "N/m"))
    Q_slide_over_Eh2: NDArray | float = field(metadata=SI("sliding_resistance", "Eh", "N/m"))
    friction_over_Eh2: NDArray | float
    hysteresis_over_Eh2: NDArray | float
    Q_onset_over_Eh2: NDArray | float = field(metadata=SI("slip_onset", "Eh", "N/m"))
    H_critical_over_R: NDArray | float = field(metadata=SI("critical_height", "R", "m"))
    first_motion: NDArray | str
    S_roll_over_Eh2: NDArray | float
    creep_over_V: NDArray | float
    Q_over_Eh2: NDArray | float
    state: NDArray | str
    d_over_a_rest: NDArray | float
    R_over_h2: NDArray | float
    h1_over_h2: NDArray | float
    sigma0_over_E: NDArray | float
    tau0_over_E: NDArray | float
    F_over_Eh2: NDArray | float
    residual_load: NDArray | float
    converged: NDArray | bool


def push(
    R_over_h2: ArrayLike,
    h1_over_h2: ArrayLike,
    sigma0_over_E: ArrayLike,
    tau0_over_E: ArrayLike,
    F_over_Eh2: ArrayLike,
    H_over_R: ArrayLike,
    Q_over_Eh2: ArrayLike | None = None,
    *,
    tip_friction: ArrayLike | None = None,
) -> Push:
    r"""Will a fibre pushed sideways at height ``H`` stay, roll or slide, and at what push.

    Vectorised: the inputs broadcast together. The contacts come from the closed forms
    (:func:`~linecontact.sliding_contact_for_load`, :func:`~linecontact.contact_for_load`),
    the creep from :func:`~linecontact.steady_rolling`, the stick zone at rest from
    :func:`~linecontact.sliding_initiation`. Derivation: ``docs/push.md``.

    Parameters
    ----------
    R_over_h2 : array_like
        Radius over the advancing (leading-edge) adhesion range ``h2``.
    h1_over_h2 : array_like
        Receding over advancing range, in ``[1, 1000]`` (:math:`h_1 \ge h_2`: the adhesion
        hysteresis :math:`\Delta w = \sigma_0 (h_1 - h_2)` is not negative).
    sigma0_over_E, tau0_over_E : array_like
        Adhesive stress and friction stress over the composite modulus.
    F_over_Eh2 : array_like
        Normal load per unit length over ``E h2`` (compressive positive), at or above the
        pull-off force of steady sliding.
    H_over_R : array_like
        Height of the push above the substrate over ``R``, in ``[0, 2]``.
    Q_over_Eh2 : array_like, optional
        A push (``>= 0``, its horizontal part for a tip) whose state is wanted.
    tip_friction : array_like, optional
        The push comes from a tip touching the fibre at the height ``H`` (in ``(0, 2)``)
        with this friction coefficient (:func:`tip_push`): the moment arm is the tip's
        ``H_eff`` and each threshold's contact carries the load ``F + dF`` the tip adds
        at that push (solved by fixed-point iteration for sliding). Without it the push is
        horizontal at ``H``.

    Returns
    -------
    Push

    Raises
    ------
    ValueError
        For inputs outside their domain, naming the parameter and its range.
    NoEquilibriumError
        For a load below the pull-off force of steady sliding (the fibre has pulled off).
    ConvergenceError
        Where a contact, or the load a tip adds at its threshold, is not solved to
        round-off (naming the point).

    Examples
    --------
    >>> p = push(100.0, 2.0, 0.01, 1e-3, 0.0, [0.25, 1.0, 2.0])
    >>> [str(m) for m in p.first_motion], round(float(p.H_critical_over_R[0]), 4)
    (['slide', 'roll', 'roll'], 0.4255)
    >>> bool(abs(p.Q_roll_over_Eh2[1] * 1.0 - 0.01 * (2.0 - 1.0)) < 1e-12)
    True
    """
    p = _checked(R_over_h2, h1_over_h2, sigma0_over_E, tau0_over_E, F_over_Eh2, H_over_R,
                 Q_over_Eh2, tip_friction)  # fmt: skip
    slide = _steady_sliding_contact(p)
    rest = _contact_at_rest(p)
    Q_roll, S_roll = _rolling_resistance(p.dw, p.arm)
    a_roll = _rolling_contact(p, slide.a, Q_roll)
    Q_lift = _lift_off(p)
    first, holds, Q_roll, Q_slide = _first_motion(p, slide.Q, Q_roll, S_roll, a_roll, Q_lift)
    creep = _creep(p, S_roll, a_roll, holds)
    state, d_rest = _state_under_push(p, Q_roll, Q_slide, Q_lift, holds, rest.a)
    with np.errstate(invalid="ignore"):
        # the load's scale: the Hertz load of the contact (its adhesive part is of that order)
        scale = np.abs(p.F) + (np.pi / 4) * p.rho * slide.a * slide.a + 1e-300
        res = np.abs(slide.F - p.F) / scale
    conv = slide.converged & (rest.converged | ~np.isfinite(rest.a))
    _raise_unconverged(p, conv, Q_over_Eh2 is not None)
    vals = dict(
        **p.named(),
        H_arm_over_R=p.arm,
        tip_friction=p.mu,
        a_rest_over_R=rest.a,
        a_slide_over_R=slide.a,
        Q_roll_over_Eh2=Q_roll,
        Q_slide_over_Eh2=Q_slide,
        friction_over_Eh2=slide.Q - p.dw,  # 2 a_slide tau0: full slip of the steady contact
        hysteresis_over_Eh2=p.dw,
        Q_onset_over_Eh2=rest.Q,
        H_critical_over_R=p.dw / Q_slide,
        first_motion=first,
        S_roll_over_Eh2=S_roll,
        creep_over_V=creep,
        Q_over_Eh2=p.Q,
        state=state,
        d_over_a_rest=d_rest,
        residual_load=res,
        converged=conv,
    )
    return Push(**{k: as_output(np.reshape(v, p.shape), p.scalar) for k, v in vals.items()})


# --------------------------------------------------------------------------------------------
# the steps of push: flat arrays of checked inputs in, plain arrays out; no step checks again


@dataclass(frozen=True)
class _Inputs:
    """The checked inputs of :func:`push`, broadcast and flat, and the tip's reduction.

    ``arm`` is the moment arm of the push over ``R`` (``H``, or the tip's ``H_eff``) and
    ``k`` the load the tip adds per unit horizontal push (0 for a horizontal push).
    ``dw`` is the adhesion hysteresis ``sigma0 (h1 - h2)`` over ``E h2``. ``scalar`` says
    that every input was a scalar: the inverses then take their scalar fast paths.
    ``slide_ends`` and ``rest_ends`` are the lower ends of the stable branches of the
    sliding contact and of the contact at rest at every point (the pull-off searches,
    which depend on ``(R/h2, h1/h2, sigma0/E)`` only): computed once per call, and handed
    to the inverses' kernels by :func:`_slide_at` and :func:`_rest_at`.
    """

    rho: NDArray
    r: NDArray
    s: NDArray
    tau: NDArray
    F: NDArray
    H: NDArray
    Q: NDArray
    mu: NDArray
    arm: NDArray
    k: NDArray
    dw: NDArray
    tip: bool
    scalar: bool
    shape: tuple[int, ...]
    slide_ends: tuple[NDArray, NDArray]
    rest_ends: dict[str, NDArray]

    def named(self) -> dict[str, NDArray]:
        """The inputs of :func:`push` but the push and the tip, under its parameters' names."""
        return dict(R_over_h2=self.rho, h1_over_h2=self.r, sigma0_over_E=self.s,
                    tau0_over_E=self.tau, F_over_Eh2=self.F, H_over_R=self.H)  # fmt: skip


@dataclass(frozen=True)
class _Contact:
    """A contact found by a step, and the threshold push it gives.

    Its half-width ``a`` over ``R``, the load it carries ``F`` (NaN where not solved for
    one), the threshold push ``Q`` and ``converged``.
    """

    a: NDArray
    F: NDArray
    Q: NDArray
    converged: NDArray


def _checked(rho, r, s, tau, F, H, Q, mu) -> _Inputs:
    """Check every input of :func:`push` once (domain, broadcast, the tip), flatten them."""
    tip = mu is not None
    checked = dict(
        R_over_h2=_domain.check("R_over_h2", rho),
        h1_over_h2=check_array("h1_over_h2", r, low=1.0, low_inclusive=True,
                               high=_domain.DOMAIN["h1_over_h2"][2], high_inclusive=True),
        sigma0_over_E=_domain.check("sigma0_over_E", s),
        tau0_over_E=_domain.check("tau0_over_E", tau),
        F_over_Eh2=_domain.check("F_over_Eh2", F),
        # a tip pushes sideways strictly between the ends (tip_push's range)
        H_over_R=check_array("H_over_R", H, low=0.0, low_inclusive=not tip, high=2.0,
                             high_inclusive=not tip),
        Q_over_Eh2=np.full((), np.nan) if Q is None else check_array(
            "Q_over_Eh2", Q, low=0.0, low_inclusive=True, high=1e12, high_inclusive=True),
        tip_friction=np.full((), np.nan) if mu is None else check_array(
            "tip_friction", mu, low=0.0, low_inclusive=True, high=10.0, high_inclusive=True),
    )  # fmt: skip
    scalar = scalar_or_array(*checked.values())
    flat = [np.asarray(v, float) for v in broadcast(**checked)]
    shape = flat[0].shape
    rho, r, s, tau, F, H, Q, mu = (np.reshape(v, -1) for v in flat)
    if tip:  # the moment arm and the load the tip adds per unit horizontal push
        q_per_P, dF_per_P, arm = _tip_forces(H, mu)
        k = dF_per_P / q_per_P
    else:
        arm, k = H, np.zeros(H.shape)
    # without a tip the sliding contact is asked for at the load given only (with one, at
    # the loads it adds too: NaN, any load)
    only = np.where(k == 0, F, np.nan)
    return _Inputs(rho, r, s, tau, F, H, Q, mu, arm, k, s * (r - 1.0), tip, scalar, shape,
                   *_branch_ends(rho, r, s, only, scalar))  # fmt: skip


def _branch_ends(rho, r, s, F, scalar: bool):
    """The lower ends of the stable branches (sliding, at rest) at every point, once.

    The pull-off searches of :func:`~linecontact.sliding_contact_for_load` and
    :func:`~linecontact.contact_for_load`, on NumPy scalars for a scalar call (their fast
    paths) kept as arrays of one point; kappa is checked here (as the inverses would). The
    sliding one only where the load ``F`` (NaN: any) asks for it (:func:`_sliding_ends`).
    """
    if not scalar:
        return _sliding_ends(rho, r, s, F), _pulloff_arrays(rho, s)
    rho0, r0, s0, F0 = (np.float64(v[0]) for v in (rho, r, s, F))
    slide = tuple(np.reshape(e, 1) for e in _sliding_ends(rho0, r0, s0, F0))
    rest = {k: np.reshape(v, 1) for k, v in _pulloff_arrays(rho0, s0, True).items()}
    return slide, rest


def _solved(v, dtype=float) -> NDArray:
    """A result's column as a flat array of its own (the steps write into it)."""
    return np.array(v, dtype).reshape(-1)


def _slide_at(p: _Inputs, at, load, report: bool = False):
    """The steady sliding contact carrying ``load``: its a/R, F and converged (flat arrays).

    At the points ``at`` (an index array, or ``slice(None)``: all) of ``p``, by the kernel
    of :func:`~linecontact.sliding_contact_for_load` with the lower ends found once.

    The load given raises below the pull-off force of steady sliding; with ``report`` (a
    tip's load) NaN there instead: the fibre lifts off first. A tip's load beyond the
    domain's ends is held there (far beyond any pull-off force, or a contact far wider than
    the domain of widths, which the inverse says).
    """
    lo, _, hi, _ = _domain.DOMAIN["F_over_Eh2"]
    load = np.clip(load, lo, hi)
    F, rho, r, s, tau = load, p.rho[at], p.r[at], p.s[at], np.full(load.shape, np.nan)
    ends = tuple(e[at] for e in p.slide_ends)
    shape = () if p.scalar else load.shape
    if p.scalar:  # the scalar fast path
        F, rho, r, s, tau = (np.float64(v[0]) for v in (F, rho, r, s, tau))
        ends = tuple(e[0] for e in ends)
    policy = "report" if report else "raise"
    res = _sliding_for_load(F, rho, r, s, tau, "closed-form", "auto", 1e-12, policy, shape,
                            p.scalar, ends)  # fmt: skip
    return _solved(res.a_over_R), _solved(res.F_over_Eh2), _solved(res.converged, bool)


def _rest_at(p: _Inputs, at, load):
    """The contact at rest carrying ``load``: a/R (NaN where none carries it), converged.

    The normal contact with the advancing range at the points ``at`` of ``p`` (as in
    :func:`_slide_at`), by the kernel of :func:`~linecontact.contact_for_load` with the
    pull-off found once; a load beyond the domain is held there.
    """
    lo, _, hi, _ = _domain.DOMAIN["F_over_Eh"]
    F, rho, s = np.clip(load, lo, hi), p.rho[at], p.s[at]
    d = {k: v[at] for k, v in p.rest_ends.items()}
    if p.scalar:  # the scalar fast path
        F, rho, s = (np.asarray(float(v[0])) for v in (F, rho, s))
        d = {k: v[0] for k, v in d.items()}
    res = _contact_for_load(F, rho, s, "stable", "report", p.scalar, d)
    return _solved(res.a_over_R), _solved(res.converged, bool)


def _steady_sliding_contact(p: _Inputs) -> _Contact:
    """The steady contact of motion and the sliding resistance ``2 a_slide tau0 + dw``.

    At the load given (raises below the pull-off force of steady sliding); with a tip, at
    the load it adds at the threshold, ``F + k Q_slide`` (:func:`_tip_sliding_threshold`).
    ``F`` is the load given that the contact carries (its residual is push's).
    """
    a, F_found, conv = _slide_at(p, slice(None), p.F)
    Q = 2.0 * a * p.rho * p.tau + p.dw
    if not p.tip or not np.any(p.k != 0):
        return _Contact(a, F_found, Q, conv)
    tip = _tip_sliding_threshold(p, Q, a, F_found, conv)
    conv = tip.converged | ~np.isfinite(tip.a)  # a lifted fibre is a state, not a failure
    F_given = np.where(np.isfinite(tip.a), tip.F - p.k * tip.Q, p.F)
    return _Contact(tip.a, F_given, tip.Q, conv)


def _tip_sliding_threshold(p: _Inputs, Q0, a0, F0, conv0) -> _Contact:
    r"""Solve :math:`Q = g(Q) = 2 a(F + k Q) \tau_0 + \Delta w` from ``Q0``.

    ``Q0`` is the threshold at ``F``. Secant steps on ``g(Q) - Q`` (plain iteration converges only
    linearly where the contact is wide: :math:`a \propto \sqrt{F}`); a point leaves the loop when
    :math:`|g - Q| \le 10^{-14} g`, with :math:`Q = g` and the contact at :math:`F + k Q`; ``g``
    NaN: the tip lifts the fibre first (it leaves as NaN). ``converged`` is False where 60 steps do
    not settle a point.
    """
    Q, a, F, conv = Q0.copy(), a0.copy(), F0.copy(), conv0.copy()
    act = np.flatnonzero(p.k != 0)  # where k = 0 the threshold is the one at F
    conv[act] = False
    Q_now, Q_prev, f_prev = Q0[act], Q0[act], np.zeros(act.size)
    for it in range(60):
        a_i, F_i, c_i = _slide_at(p, act, p.F[act] + p.k[act] * Q_now, report=True)
        g = 2.0 * a_i * p.rho[act] * p.tau[act] + p.dw[act]  # NaN: the tip lifts the fibre first
        f = g - Q_now
        with np.errstate(divide="ignore", invalid="ignore"):
            secant = Q_now - f * (Q_now - Q_prev) / (f - f_prev)
        usable = (it > 0) & np.isfinite(secant) & (secant > 0)
        done = np.abs(np.nan_to_num(f)) <= 1e-14 * np.nan_to_num(np.abs(g), nan=1.0)
        last = done | (it == 59)  # unsettled after 60 steps: reported unconverged
        at = act[last]
        Q[at] = np.where(done, g, np.where(usable, secant, g))[last]
        a[at], F[at], conv[at] = a_i[last], F_i[last], (c_i & done)[last]
        Q_prev, f_prev = Q_now[~last], f[~last]
        Q_now, act = np.where(usable, secant, g)[~last], act[~last]
        if act.size == 0:
            break
    return _Contact(a, F, Q, conv)


def _contact_at_rest(p: _Inputs) -> _Contact:
    r"""The contact at rest and the slip onset :math:`Q_\text{onset} = 2 a_\text{rest}\tau_0`.

    The normal contact at the load with the advancing range (NaN where none carries it:
    below the pull-off force at rest); with a tip, at ``F + k Q_onset`` by plain iteration
    (the tip's load changes the width by a part of order :math:`\tau_0/E`: a few steps to 1e-14).
    ``F`` is NaN: the load is not reported.
    """
    a, conv = _rest_at(p, slice(None), p.F)
    Q = 2.0 * a * p.rho * p.tau
    act = np.flatnonzero(p.k != 0) if p.tip else np.zeros(0, int)
    conv[act] = False
    change = np.full(act.size, np.inf)
    for _ in range(60 if act.size else 0):  # (no contact at rest, NaN: retried at F)
        a_i, c_i = _rest_at(p, act, p.F[act] + p.k[act] * np.nan_to_num(Q[act]))
        Q_i = 2.0 * a_i * p.rho[act] * p.tau[act]
        new = np.abs(np.nan_to_num(Q_i - Q[act]))
        scale = np.nan_to_num(Q_i, nan=1.0)
        # settled at 1e-14 of the onset, or where the iteration has reached the round-off of
        # the width it inverts: close to the pull-off the width is ill-conditioned in the
        # load, and the steps cycle there (seen at 3.8e-14 of the onset: 60 steps never
        # reached 1e-14, and push raised for a state that it had found). A step that no
        # longer halves and is below 1e-12 of the onset stops it there: to about that step
        # (the steps shrank by 20 times each before the cycle)
        stalled = (new >= 0.5 * change) & (new <= 1e-12 * scale)
        done = (new <= 1e-14 * scale) | stalled
        a[act], Q[act], conv[act] = a_i, Q_i, c_i & done
        act, change = act[~done], new[~done]
        if act.size == 0:
            break
    return _Contact(a, np.full(a.shape, np.nan), Q, conv)


def _rolling_resistance(dw, arm):
    r"""Steady rolling: push :math:`Q_\text{roll} = R\,\Delta w / H`, contact shear ``S_roll``.

    The moment balance about the axis with the moment :math:`M_\text{axis} = R\,\Delta w` of the
    steady contact's pressure (``docs/push.md`` eq. 1, taken exactly: :math:`M - e F` loses digits
    when the adhesion is tiny beside the load), and the force balance :math:`Q + S = \Delta w`:
    :math:`S_\text{roll} = Q_\text{roll} (H - R)/R`. ``Q_roll`` is 0 without hysteresis
    (:math:`H > 0`) and ``inf`` for a push at the contact line (:math:`H = 0`, or so close that
    :math:`\Delta w / H` overflows; ``S_roll`` is then ``-inf``). Kendall's energy balance gives the
    same.
    """
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        Q_roll = np.where(arm > 0, dw / np.where(arm > 0, arm, 1.0), np.inf)
        S_roll = np.where(arm > 0, Q_roll * (arm - 1.0), -np.inf)
    return Q_roll, S_roll


def _rolling_contact(p: _Inputs, a_slide, Q_roll):
    """The contact that holds the shear while rolling: its half-width over ``R``.

    The steady contact at the load; with a tip at ``F + k Q_roll`` (NaN where that lifts
    the fibre).
    """
    a_roll = a_slide.copy()
    act = np.flatnonzero(p.k != 0) if p.tip else np.zeros(0, int)
    if act.size:
        Q = np.where(np.isfinite(Q_roll[act]), Q_roll[act], 0.0)
        a_roll[act], _, _ = _slide_at(p, act, p.F[act] + p.k[act] * Q, report=True)
    return a_roll


def _lift_off(p: _Inputs):
    r"""The push at which a tip that lifts (:math:`k < 0`) pulls the fibre off at rest.

    :math:`Q_\text{lift} = (F - F_\text{po})/(-k)`, where the load reaches the pull-off force
    ``F_po`` of the contact at rest; ``inf`` where the tip does not lift.
    """
    Q_lift = np.full(p.F.shape, np.inf)
    lifts = np.flatnonzero(p.k < 0)
    if lifts.size:
        args = (p.rho[lifts], p.s[lifts])
        po = pull_off(*((float(v[0]) for v in args) if p.scalar else args))
        with np.errstate(divide="ignore", invalid="ignore"):
            Q_lift[lifts] = (p.F[lifts] - _solved(po.F_pulloff_over_Eh)) / -p.k[lifts]
    return Q_lift


def _first_motion(p: _Inputs, Q_slide, Q_roll, S_roll, a_roll, Q_lift):
    r"""The first motion under a growing push, and whether the rolling contact holds.

    The lower steady resistance (``docs/push.md`` section 4), ``"roll+slide"`` where rolling needs
    more shear than its contact holds (:math:`|S_\text{roll}| \ge 2 a_\text{roll} \tau_0`),
    ``"lift-off"`` where a tip lifts the fibre first.

    Returns ``(first, holds, Q_roll, Q_slide)``, the thresholds that a lifted contact does
    not reach set to ``inf``.
    """
    Q_slide = np.where(np.isnan(Q_slide), np.inf, Q_slide)
    Q_roll = np.where(np.isnan(a_roll) & np.isfinite(Q_roll), np.inf, Q_roll)
    holds = np.abs(S_roll) < 2.0 * a_roll * p.rho * p.tau
    first = np.where(Q_roll < Q_slide, np.where(holds, "roll", "roll+slide"), "slide")
    first = np.where(Q_lift < np.minimum(Q_roll, Q_slide), "lift-off", first)
    return first, holds, Q_roll, Q_slide


def _creep(p: _Inputs, S_roll, a_roll, holds):
    r"""The creep :math:`(V - \omega R)/V` of steady rolling under the shear ``S_roll``.

    Where the contact holds it (:func:`~linecontact.steady_rolling`, once), NaN elsewhere;
    negative where the shear drives, 0 without shear.
    """
    creep = np.full(p.rho.shape, np.nan)
    if np.any(holds):
        tau, S = p.tau[holds], S_roll[holds]
        T = np.abs(S) / (p.rho[holds] * a_roll[holds])  # T over E a_roll
        # at full slip (T = 2 tau0): the sliding state, reported
        roll = steady_rolling(tau, T_over_Ea=np.minimum(T, 2 * tau), on_failure="report")
        c = np.sign(S) * np.asarray(roll.creep_over_V, float)
        creep[holds] = np.where(S == 0, 0.0, c)
    return creep


def _state_under_push(p: _Inputs, Q_roll, Q_slide, Q_lift, holds, a_rest):
    """The state under the push given (``""`` without one) and the stick zone at rest.

    ``"rest"`` below both resistances, ``"roll"``/``"slide"`` above one, ``"roll+slide"``
    above both (or rolling needs more shear than the contact holds), ``"lift-off"`` at or
    beyond ``Q_lift``. At rest the stick zone ``d/a_rest`` of the initiation problem
    (:func:`~linecontact.sliding_initiation`, once) on the contact at the load (with a tip,
    ``F + k Q``); 0 from gross slip on, NaN when moving or without a push.
    """
    given = np.isfinite(p.Q)
    state = np.full(p.rho.shape, "", dtype="<U10")
    d_rest = np.full(p.rho.shape, np.nan)
    if not np.any(given):
        return state, d_rest
    over_roll, over_slide = p.Q >= Q_roll, p.Q >= Q_slide
    rolls = np.where(holds, "roll", "roll+slide")
    moving = np.where(over_roll, np.where(over_slide, "roll+slide", rolls), "slide")
    state = np.where(given, np.where(over_roll | over_slide, moving, "rest"), "")
    state = np.where(given & (p.Q >= Q_lift), "lift-off", state)
    at_rest = given & (state == "rest")
    a_here = a_rest.copy()
    loaded = np.flatnonzero(at_rest & (p.k != 0)) if p.tip else np.zeros(0, int)
    if loaded.size:  # the contact at rest under the tip's load
        load = p.F[loaded] + p.k[loaded] * p.Q[loaded]
        a_here[loaded], _ = _rest_at(p, loaded, load)
    at_rest &= np.isfinite(a_here)
    if np.any(at_rest):
        T = p.Q[at_rest] / (p.rho[at_rest] * a_here[at_rest])
        init = sliding_initiation(p.tau[at_rest], T_over_Ea=T, on_failure="report")
        d = np.asarray(init.d_over_a, float)
        d_rest[at_rest] = np.where(np.asarray(init.state) == "sliding", 0.0, d)
    return state, d_rest


def _raise_unconverged(p: _Inputs, conv, given: bool) -> None:
    """Raise :class:`ConvergenceError` naming the first point not solved to round-off."""
    if np.all(conv):
        return
    named = p.named()
    if given:
        named["Q_over_Eh2"] = p.Q
    if p.tip:
        named["tip_friction"] = p.mu
    _, at = first_point(~np.asarray(conv, bool), **named)
    raise ConvergenceError(
        f"push did not converge at {point_text(at)}"
        + ": a contact or the tip's load could not be solved to round-off"
    )


@dataclass(frozen=True)
class TipPush(Result):
    """A tip's push reduced to a horizontal push, a load change and a moment arm.

    Attributes
    ----------
    Q_per_P : ndarray or float
        Horizontal push per unit tip force ``P`` (along +x).
    dF_per_P : ndarray or float
        Added compressive normal load per unit tip force (negative: the tip lifts).
    H_effective_over_R : ndarray or float
        Height of the horizontal push with the same moment about the contact point.
    """

    inputs: ClassVar[tuple[str, ...]] = ("H_over_R", "tip_friction")

    Q_per_P: NDArray | float
    dF_per_P: NDArray | float
    H_effective_over_R: NDArray | float
    H_over_R: NDArray | float
    tip_friction: NDArray | float


def tip_push(H_over_R: ArrayLike, tip_friction: ArrayLike = 0.0) -> TipPush:
    r"""Reduce a tip touching the fibre at height ``H`` to the push it exerts.

    The tip touches the rear of the fibre at the angle ``theta`` above the horizontal
    through the axis, :math:`\sin\theta = H/R - 1`, and presses along the surface normal
    (through the axis) with the force ``P``; its friction ``mu_tip``, at its limit, opposes
    the rotation of a forward-rolling fibre. Then (``docs/push.md`` section 6)

    .. math::

        \frac{Q}{P} = \cos\theta - \mu_\text{tip} \sin\theta, \qquad
        \frac{\Delta F}{P} = \sin\theta + \mu_\text{tip} \cos\theta, \qquad
        H_\text{eff} = R\, \frac{\cos\theta - \mu_\text{tip} (1 + \sin\theta)}
        {\cos\theta - \mu_\text{tip} \sin\theta};

    a frictionless tip acts at :math:`H_\text{eff} = R` at any height.

    Parameters
    ----------
    H_over_R : array_like
        Height of the tip's contact over ``R``, in ``(0, 2)`` (at 0 and 2 the normal is
        vertical: the tip does not push sideways).
    tip_friction : array_like
        Friction coefficient of the tip on the fibre, in ``[0, 10]``.

    Returns
    -------
    TipPush

    Raises
    ------
    ValueError
        For a height outside ``(0, 2)`` or a friction outside ``[0, 10]``, or where the tip
        no longer pushes forward (:math:`\cos\theta \le \mu_\text{tip} \sin\theta`).

    Examples
    --------
    >>> t = tip_push(1.5)
    >>> round(t.H_effective_over_R, 12), round(t.dF_per_P, 12)
    (1.0, 0.5)
    """
    H = check_array("H_over_R", H_over_R, low=0.0, high=2.0)
    mu = check_array(
        "tip_friction", tip_friction, low=0.0, low_inclusive=True, high=10.0, high_inclusive=True
    )
    scalar = scalar_or_array(H, mu)
    H, mu = (np.asarray(v, float) for v in broadcast(H_over_R=H, tip_friction=mu))
    qx, dF, H_eff = _tip_forces(H, mu)
    vals = dict(
        Q_per_P=qx,
        dF_per_P=dF,
        H_effective_over_R=H_eff,
        H_over_R=H,
        tip_friction=mu,
    )
    return TipPush(**{k: as_output(v, scalar) for k, v in vals.items()})


def _tip_forces(H, mu):
    r"""A tip's ``(Q/P, dF/P, H_eff/R)`` at checked heights and frictions.

    ``docs/push.md`` section 6; raises where the tip does not push forward
    (:math:`\cos\theta \le \mu \sin\theta`).
    """
    # 1 + sin(theta) = H and 1 - sin(theta) = 2 - H (exact for H >= 1, correctly rounded
    # below): cos(theta) = sqrt(H (2 - H)) keeps its relative accuracy at both ends, where
    # forming 1 -+ sin(theta) from sin(theta) = H - 1 cancels (H = 1e-15 came out 4e-4 off)
    sin = H - 1.0
    cos = np.sqrt(H * (2.0 - H))
    qx = cos - mu * sin
    if np.any(qx <= 0):
        _, at = first_point(qx <= 0, tip_friction=mu, H_over_R=H)
        raise ValueError(
            f"tip_friction={at['tip_friction']!r} at H_over_R={at['H_over_R']!r} turns the "
            "tip's force backwards or vertical "
            f"(cos(theta) <= tip_friction sin(theta)): the tip does not push the fibre"
        )
    return qx, sin + mu * cos, (cos - mu * H) / qx
