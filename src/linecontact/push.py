r"""A fibre pushed sideways: will it stay, roll or slide (the paper's future work).

A push ``Q`` per unit length acts horizontally at height ``H`` above the substrate on a
cylinder under the normal load ``F``, held by Maugis--Dugdale adhesion with the receding
range ``h1`` (trailing edge) and the advancing range ``h2`` (leading edge), ``h1 >= h2``,
and by a friction stress ``tau0``. The derivation is ``docs/push.md``:

- the contact of steady motion, rolling or sliding, is the steady sliding contact at the
  load (half-width ``a_slide``); its pressure's moment about the axis is ``R dw``, with the
  adhesion hysteresis ``dw = sigma0 (h1 - h2)``;
- rolling resistance ``Q_roll = R dw / H`` (moment balance; energy gives the same), with the
  contact shear ``S = Q_roll (H - R)/R`` that the steady rolling solution carries (its creep
  is reported);
- sliding resistance ``Q_slide = 2 a_slide tau0 + dw`` (friction, and the horizontal pull of
  the adhesive zones on the curved surface, which the energy balance requires);
- the first motion is the one with the lower resistance: rolling iff ``H > H* = R dw /
  Q_slide``; gross slip of the contact at rest (half-width ``a_rest``, the normal contact
  with the advancing range) starts at ``Q_onset = 2 a_rest tau0``, and the resistance rises
  to ``Q_slide`` as the trailing edge stretches: the static peak is the kinetic value.

Groups as in steady sliding: lengths over ``R`` (``H_over_R``) or ``h2``, forces per unit
length over ``E h2``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import domain as _domain
from ._validation import broadcast, check_array, first_point, point_text, scalar_or_array
from .errors import ConvergenceError
from .normal import contact_for_load, pull_off
from .results import Result, as_output
from .sliding import sliding_contact_for_load
from .tangential import sliding_initiation, steady_rolling

__all__ = ["Push", "TipPush", "push", "tip_push"]

#: The states of a pushed fibre (``Push.state``) and its first motions.
STATES = ("rest", "roll", "slide", "roll+slide", "lift-off")


@dataclass(frozen=True)
class Push(Result):
    """Rolling and sliding resistance of a pushed fibre, its first motion and its state.

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
        Steady rolling resistance ``R dw / H`` (``inf`` at ``H = 0``): the moment of the
        sliding contact's pressure about the axis, ``M - e F = R dw``, over the arm.
    Q_slide_over_Eh2 : ndarray or float
        Steady sliding resistance ``2 a_slide tau0 + dw``; the static (peak) value too.
    friction_over_Eh2, hysteresis_over_Eh2 : ndarray or float
        Its two parts: ``2 a_slide tau0`` and ``dw = sigma0 (h1 - h2)``.
    Q_onset_over_Eh2 : ndarray or float
        ``2 a_rest tau0``: gross slip of the contact at rest begins (the resistance then
        rises to ``Q_slide`` as the trailing edge stretches).
    H_critical_over_R : ndarray or float
        ``H* = R dw / Q_slide``: rolling comes first for a moment arm above it.
    first_motion : ndarray of str or str
        ``"roll"``, ``"slide"``, or ``"roll+slide"`` (rolling comes first but needs more
        shear than the contact holds, ``|S_roll| >= 2 a_slide tau0``); with a tip below the
        axis also ``"lift-off"`` (its vertical pull takes the load to the pull-off force of
        the contact at rest before either resistance is reached).
    S_roll_over_Eh2 : ndarray or float
        The contact's shear on the fibre while rolling, ``Q_roll (H - R)/R`` (negative:
        resisting, below the axis; positive: driving, above it).
    creep_over_V : ndarray or float
        Creep while rolling, ``(V - omega R)/V`` (negative when the shear drives); NaN
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

    H_over_R: NDArray | float
    H_arm_over_R: NDArray | float
    tip_friction: NDArray | float
    a_rest_over_R: NDArray | float
    a_slide_over_R: NDArray | float
    Q_roll_over_Eh2: NDArray | float
    Q_slide_over_Eh2: NDArray | float
    friction_over_Eh2: NDArray | float
    hysteresis_over_Eh2: NDArray | float
    Q_onset_over_Eh2: NDArray | float
    H_critical_over_R: NDArray | float
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
        Receding over advancing range, in ``[1, 1000]`` (``h1 >= h2``: the adhesion
        hysteresis ``dw = sigma0 (h1 - h2)`` is not negative).
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
    rho = _domain.check("R_over_h2", R_over_h2)
    r = check_array(
        "h1_over_h2",
        h1_over_h2,
        low=1.0,
        low_inclusive=True,
        high=_domain.DOMAIN["h1_over_h2"][2],
        high_inclusive=True,
    )
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    tau = _domain.check("tau0_over_E", tau0_over_E)
    F = _domain.check("F_over_Eh2", F_over_Eh2)
    H = check_array(
        "H_over_R", H_over_R, low=0.0, low_inclusive=True, high=2.0, high_inclusive=True
    )
    Q = (
        np.full((), np.nan)
        if Q_over_Eh2 is None
        else check_array(
            "Q_over_Eh2", Q_over_Eh2, low=0.0, low_inclusive=True, high=1e12, high_inclusive=True
        )
    )
    tip = tip_friction is not None
    mu = (
        np.full((), np.nan)
        if tip_friction is None
        else check_array(
            "tip_friction",
            tip_friction,
            low=0.0,
            low_inclusive=True,
            high=10.0,
            high_inclusive=True,
        )
    )
    scalar = scalar_or_array(rho, r, s, tau, F, H, Q, mu)
    rho, r, s, tau, F, H, Q, mu = (
        np.asarray(v, float)
        for v in broadcast(
            R_over_h2=rho,
            h1_over_h2=r,
            sigma0_over_E=s,
            tau0_over_E=tau,
            F_over_Eh2=F,
            H_over_R=H,
            Q_over_Eh2=Q,
            tip_friction=mu,
        )
    )
    shape = rho.shape
    rho, r, s, tau, F, H, Q, mu = (np.reshape(v, -1) for v in (rho, r, s, tau, F, H, Q, mu))
    if tip:  # the moment arm and the load the tip adds per unit horizontal push
        tp = tip_push(H, mu)
        arm = np.asarray(tp.H_effective_over_R, float)
        k = np.asarray(tp.dF_per_P, float) / np.asarray(tp.Q_per_P, float)
    else:
        arm, k = H, np.zeros(H.shape)

    # a scalar call takes the inverses' scalar fast paths
    one = (lambda v: float(v[0])) if scalar else (lambda v: v)
    flat = (lambda v: np.reshape(np.asarray(v, float), -1)) if scalar else np.asarray

    def slide_at(load, report=False):
        """The steady contact carrying ``load``: its a/R and F, converged; NaN where none.

        The load given raises below the pull-off force of steady sliding; where the load a
        tip adds takes it beyond (``report``), NaN: the fibre lifts off first.
        """
        # (a tip's load beyond the domain's ends is held there: far beyond any pull-off
        # force, or a contact far wider than the domain of widths, which the inverse says)
        lo, _, hi, _ = _domain.DOMAIN["F_over_Eh2"]
        load = np.clip(load, lo, hi)
        res = sliding_contact_for_load(
            one(load),
            one(rho),
            one(r),
            one(s),
            method="closed-form",
            on_failure="report" if report else "raise",
        )
        return flat(res.a_over_R), flat(res.F_over_Eh2), np.reshape(np.asarray(res.converged), -1)

    def rest_at(load):
        lo, _, hi, _ = _domain.DOMAIN["F_over_Eh"]
        load = np.clip(load, lo, hi)
        res = contact_for_load(one(load), one(rho), one(s), on_failure="report")
        return flat(res.a_over_R), np.reshape(np.asarray(res.converged), -1)

    dw = s * (r - 1.0)
    # the contact of steady sliding (raises below the sliding pull-off force) and at rest;
    # with a tip, each at the load the tip adds at its threshold (fixed point: the tip's
    # load changes the width by a part of order tau0/E, a few iterations)
    a_slide, F_slide, conv = slide_at(F)
    a_rest, conv_rest = rest_at(F)
    Q_slide = 2.0 * a_slide * rho * tau + dw
    Q_onset = 2.0 * a_rest * rho * tau
    settled = np.ones(F.shape, bool)  # the fixed points of a tip converged
    if tip and np.any(k != 0):
        # Q = g(Q) = 2 a(F + k Q) tau0 + dw by secant steps on g(Q) - Q (plain iteration
        # converges only linearly where the contact is wide: a ~ sqrt(load))
        Q_prev, f_prev = Q_slide, np.zeros(F.shape)
        for it in range(60):
            a_slide, F_slide, conv = slide_at(F + k * Q_slide, report=True)
            g = 2.0 * a_slide * rho * tau + dw  # NaN: the tip lifts the fibre first
            f = g - Q_slide
            with np.errstate(divide="ignore", invalid="ignore"):
                secant = Q_slide - f * (Q_slide - Q_prev) / (f - f_prev)
            usable = (it > 0) & np.isfinite(secant) & (secant > 0)
            Q_next = np.where(usable, secant, g)
            done = np.abs(np.nan_to_num(f)) <= 1e-14 * np.nan_to_num(np.abs(g), nan=1.0)
            Q_prev, f_prev = Q_slide, f
            if np.all(done):
                Q_slide = g
                break
            Q_slide = np.where(done, g, Q_next)
        settled &= done
        conv |= ~np.isfinite(a_slide)  # a lifted fibre is a state, not a failure
        F_slide = np.where(np.isfinite(a_slide), F_slide - k * Q_slide, F)  # the load given
        for _ in range(60):
            a_new, conv_rest = rest_at(F + k * np.nan_to_num(Q_onset))  # NaN: lifted
            Q_new = 2.0 * a_new * rho * tau
            step = np.abs(np.nan_to_num(Q_new - Q_onset))
            a_rest, Q_onset = a_new, Q_new
            if np.all(step <= 1e-14 * np.nan_to_num(Q_new, nan=1.0)):
                break
        settled &= step <= 1e-14 * np.nan_to_num(Q_onset, nan=1.0)
    capacity = Q_slide - dw  # 2 a_slide tau0: full slip of the steady contact
    conv = conv & (conv_rest | ~np.isfinite(a_rest)) & settled
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        # Q_roll = M_axis / H: 0 without hysteresis (H > 0); inf for a push at the contact
        # line (H = 0, or so close to it that M_axis / H overflows)
        # (the identity M_axis = R dw of the sliding contact, eq. (1), tested at every width,
        # taken exactly: M - e F loses digits when the adhesion is tiny beside the load)
        Q_roll = np.where(arm > 0, dw / np.where(arm > 0, arm, 1.0), np.inf)
        S_roll = np.where(arm > 0, Q_roll * (arm - 1.0), -np.inf)
    # the rolling contact: the steady contact at the load while rolling
    a_roll = a_slide
    if tip and np.any(k != 0):
        a_roll, _, _ = slide_at(F + k * np.where(np.isfinite(Q_roll), Q_roll, 0.0), True)
    # a tip that lifts (k < 0) pulls the fibre off at rest when F + k Q falls to the pull-off
    # force of the contact at rest; a threshold beyond that push is not reached (NaN -> inf)
    Q_lift = np.full(F.shape, np.inf)
    if np.any(k < 0):
        with np.errstate(divide="ignore", invalid="ignore"):
            F_po = flat(pull_off(one(rho), one(s)).F_pulloff_over_Eh)
            Q_lift = np.where(k < 0, (F - F_po) / np.where(k < 0, -k, 1.0), np.inf)
    Q_slide = np.where(np.isnan(Q_slide), np.inf, Q_slide)
    Q_roll = np.where(np.isnan(a_roll) & np.isfinite(Q_roll), np.inf, Q_roll)
    H_crit = dw / Q_slide
    holds = np.abs(S_roll) < 2.0 * a_roll * rho * tau
    roll_first = Q_roll < Q_slide
    first = np.where(roll_first, np.where(holds, "roll", "roll+slide"), "slide")
    first = np.where(Q_lift < np.minimum(Q_roll, Q_slide), "lift-off", first)

    creep = np.full(rho.shape, np.nan)
    if np.any(holds):
        T = np.abs(S_roll[holds]) / (rho[holds] * a_roll[holds])  # T over E a_roll
        # at full slip (T = 2 tau0): the sliding state, reported
        roll = steady_rolling(
            tau[holds], T_over_Ea=np.minimum(T, 2 * tau[holds]), on_failure="report"
        )
        creep[holds] = np.sign(S_roll[holds]) * np.asarray(roll.creep_over_V, float)
        creep[holds] = np.where(S_roll[holds] == 0, 0.0, creep[holds])

    given = np.isfinite(Q)
    state = np.full(rho.shape, "", dtype="<U10")
    d_rest = np.full(rho.shape, np.nan)
    if np.any(given):
        over_roll = Q >= Q_roll
        over_slide = Q >= Q_slide
        moving = np.where(
            over_roll & over_slide,
            "roll+slide",
            np.where(over_roll, np.where(holds, "roll", "roll+slide"), "slide"),
        )
        state = np.where(given, np.where(over_roll | over_slide, moving, "rest"), "")
        state = np.where(given & (Q >= Q_lift), "lift-off", state)
        at_rest = given & (state == "rest")
        a_here = a_rest
        if tip and np.any(at_rest & (k != 0)):  # the contact at rest under the tip's load
            a_here, _ = rest_at(F + k * np.where(given, Q, 0.0))
        at_rest &= np.isfinite(a_here)
        if np.any(at_rest):
            T = Q[at_rest] / (rho[at_rest] * a_here[at_rest])
            init = sliding_initiation(tau[at_rest], T_over_Ea=T, on_failure="report")
            d_rest[at_rest] = np.where(
                np.asarray(init.state) == "sliding", 0.0, np.asarray(init.d_over_a, float)
            )

    with np.errstate(invalid="ignore"):
        # the load's scale: the Hertz load of the contact (its adhesive part is of that order)
        scale = np.abs(F) + (np.pi / 4) * rho * a_slide * a_slide + 1e-300
        res = np.abs(F_slide - F) / scale
    if not np.all(conv):
        named = dict(
            R_over_h2=rho, h1_over_h2=r, sigma0_over_E=s, tau0_over_E=tau, F_over_Eh2=F, H_over_R=H
        )
        if Q_over_Eh2 is not None:
            named["Q_over_Eh2"] = Q
        if tip:
            named["tip_friction"] = mu
        _, at = first_point(~np.asarray(conv, bool), **named)
        raise ConvergenceError(
            f"push did not converge at {point_text(at)}"
            + ": a contact or the tip's load could not be solved to round-off"
        )
    vals = dict(
        H_over_R=H,
        H_arm_over_R=arm,
        tip_friction=mu,
        a_rest_over_R=a_rest,
        a_slide_over_R=a_slide,
        Q_roll_over_Eh2=Q_roll,
        Q_slide_over_Eh2=Q_slide,
        friction_over_Eh2=capacity,
        hysteresis_over_Eh2=dw,
        Q_onset_over_Eh2=Q_onset,
        H_critical_over_R=H_crit,
        first_motion=first,
        S_roll_over_Eh2=S_roll,
        creep_over_V=creep,
        Q_over_Eh2=Q,
        state=state,
        d_over_a_rest=d_rest,
        R_over_h2=rho,
        h1_over_h2=r,
        sigma0_over_E=s,
        tau0_over_E=tau,
        F_over_Eh2=F,
        residual_load=res,
        converged=conv,
    )
    return Push(**{k: as_output(np.reshape(v, shape), scalar) for k, v in vals.items()})


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
    through the axis, ``sin(theta) = H/R - 1``, and presses along the surface normal
    (through the axis) with the force ``P``; its friction ``mu_tip``, at its limit, opposes
    the rotation of a forward-rolling fibre. Then (``docs/push.md`` section 6)
    ``Q/P = cos(theta) - mu_tip sin(theta)``, ``dF/P = sin(theta) + mu_tip cos(theta)`` and
    ``H_eff = R [cos(theta) - mu_tip (1 + sin(theta))] / (cos(theta) - mu_tip sin(theta))``;
    a frictionless tip acts at ``H_eff = R`` at any height.

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
        no longer pushes forward (``cos(theta) <= mu_tip sin(theta)``).

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
    vals = dict(
        Q_per_P=qx,
        dF_per_P=sin + mu * cos,
        H_effective_over_R=(cos - mu * H) / qx,
        H_over_R=H,
        tip_friction=mu,
    )
    return TipPush(**{k: as_output(v, scalar) for k, v in vals.items()})
