"""The tangential problems, the pushed fibre and the load histories in SI units.

Each public function here is a method of :class:`~linecontact.Cylinder` (the class binds it:
``Cylinder.push = push``), written here so that ``_cylinder.py`` stays one room; ``self`` is
the cylinder. The engines they share (``_cylinder_tangential``, ``_history_solve``) take
checked values.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import domain as _domain
from .. import push as _push
from .. import tangential as _tangential
from .._validation import (
    FailurePolicy,
    broadcast,
    check_array,
    failure_policy,
    non_negative,
    positive,
    scalar,
)
from ..errors import NoEquilibriumError
from ..tangential import (
    sliding_initiation_coulomb,
    steady_rolling_coulomb,
)
from ..tangential._core import _one_of
from ..tangential.initiation import _CATTANEO_MINDLIN, _INITIATION
from ..tangential.rolling import _CARTER, _ROLLING
from ..units import Scales, to_si
from ._checks import (
    _first,
    _plausible,
    _small_strain_in_si,
    _too_wide,
    _warn_widths,
)
from ._results import (
    CylinderCyclicLoss,
    CylinderPush,
    CylinderTangential,
    CylinderTangentialHistory,
)

# --------------------------------------------------------------------------------------------
# tangential problems in SI units


def _cylinder_tangential(
    problem,
    cylinder,
    normal_load,
    friction_stress,
    friction_coefficient,
    d_over_a,
    tangential_load,
    method,
    on_failure,
) -> CylinderTangential:
    """The tangential ``problem`` (``"sliding initiation"`` or ``"steady rolling"``) in SI units.

    The engine of both methods, from their arguments as given: refused where the problem is
    not written for the cylinder's law, every input checked before any solve.
    """
    cylinder._written(problem.replace(" ", "_"))
    policy = failure_policy(on_failure)
    coulomb = _is_coulomb(friction_stress, friction_coefficient)
    _one_of(d_over_a, tangential_load, "tangential_load [N/m]")
    E = cylinder.modulus
    rolling = problem == "steady rolling"
    pb = (
        (_CARTER if coulomb else _ROLLING)
        if rolling
        else (_CATTANEO_MINDLIN if coulomb else _INITIATION)
    )
    # every input checked, and the shapes against each other, before any solve
    if coulomb:
        F = check_array("normal_load", normal_load)
        fr_name, fr = (
            "friction_coefficient",
            _domain.check("friction_coefficient", friction_coefficient, "mu"),
        )
    else:
        F = check_array("normal_load", normal_load, low=-np.inf)
        fr_name, fr = "friction_stress", positive("friction_stress", friction_stress)
        _domain.check_si("friction_stress", fr, E, "tau0_over_E", "Pa")
    if d_over_a is not None:
        st_name = "d_over_a"
        st = check_array(
            "d_over_a", d_over_a, low=pb.d_low, low_inclusive=pb.d_low_inclusive, high=1.0
        )
    else:
        st_name, st = "tangential_load", non_negative("tangential_load", tangential_load)
    broadcast(normal_load=F, **{fr_name: fr, st_name: st})
    d = st if d_over_a is not None else None
    if coulomb:
        _refuse_adhesion_with_coulomb(cylinder)
        if cylinder.cross_section.kind != "round":  # its shear bound is the Hertz pressure's
            cylinder._not_written(f"{problem} with friction_coefficient (Coulomb friction)")
    contact, a = _normal_contact(cylinder, F, coulomb)
    unit, group, full = _tangential_scales(coulomb, fr, F, a, E)
    if d is None:
        _domain.check_si("tangential_load", st, unit, group, "N/m")
    T = None if d is not None else st / unit
    try:
        with _small_strain_in_si():  # the contact's width: said by _for_load
            if coulomb:
                coulomb_fn = steady_rolling_coulomb if rolling else sliding_initiation_coulomb
                A = a / cylinder.radius
                r: Any = coulomb_fn(fr, A, d, T_over_muF=T, method=method, on_failure=policy)
            else:
                fn = _tangential.steady_rolling if rolling else _tangential.sliding_initiation
                # broadcast with a so that every field has the shape of the points
                r = fn(fr / E + 0 * a, d, T_over_Ea=T, method=method, on_failure=policy)
    except NoEquilibriumError:
        raise _full_slip(st, full, "mu F" if coulomb else "2 a tau0", st_name) from None
    friction = "coulomb" if coulomb else "constant"
    si = to_si(r, Scales.of(cylinder, a=a))
    creep = r.creep_over_V if rolling else None
    return CylinderTangential(
        problem,
        friction,
        _scalar(F + 0 * a),
        _scalar(a),
        si["stick_zone_end"],
        si["tangential_load"],
        _scalar(full),
        creep,
        r.state,
        r,
        contact,
    )


def _normal_contact(cylinder: Any, F: Any, coulomb: bool) -> tuple[Any, NDArray]:
    """``(contact, a)``: the stable normal contact under ``F`` [N/m] and its half-width [m].

    Under Coulomb friction the (Hertz) contact must be as wide as the solvers' domain.
    """
    contact = cylinder._for_load("normal_load", F)
    a = np.asarray(contact.contact_half_width)
    if coulomb:
        _check_hertz_width("normal_load", F, a / cylinder.radius, cylinder.radius)
    return contact, a


def _tangential_scales(coulomb: bool, fr: Any, F: Any, a: Any, E: float) -> tuple[Any, str, Any]:
    """``(unit, group, full)``: the tangential load's unit [N/m], its group, the full-slip load.

    With the friction ``fr``, the normal load ``F`` [N/m] and the half-width ``a`` [m]:
    Coulomb friction (``fr`` is ``mu``) ``(mu F, "T_over_muF", mu F)``; a constant friction
    stress (``fr`` is ``tau0`` [Pa]) ``(E a, "T_over_Ea", 2 a tau0)``.
    """
    if coulomb:
        return fr * F, "T_over_muF", fr * F
    return E * a, "T_over_Ea", 2 * a * fr


def _is_coulomb(friction_stress: Any, friction_coefficient: Any) -> bool:
    """Whether the friction given is Coulomb's (``friction_coefficient``): exactly one given."""
    if (friction_stress is None) == (friction_coefficient is None):
        raise ValueError(
            "give exactly one of friction_stress (constant tau0 [Pa]) or "
            "friction_coefficient (Coulomb mu)"
        )
    return friction_coefficient is not None


def _refuse_adhesion_with_coulomb(cylinder: Any) -> None:
    """Refuse Coulomb friction on an adhesive cylinder: it is the Hertz contact's friction."""
    if cylinder.cohesive_stress != 0:
        raise ValueError(
            "Coulomb friction is the macro-scale counterpart for the non-adhesive Hertz "
            "contact: use a Cylinder without adhesion (cohesive_stress = 0), or give "
            "friction_stress"
        )


def _full_slip(
    T: NDArray, full: ArrayLike, what: str, given: str = "tangential_load"
) -> NoEquilibriumError:
    """The error for a tangential load [N/m] at or above full slip, said in N/m.

    With ``given == "d_over_a"``, ``T`` is the stick zone given: full slip is ``d_over_a = 0``.
    """
    if given == "d_over_a":
        d, full = np.broadcast_arrays(np.asarray(T, float), np.asarray(full, float))
        di, fi = _first(d == 0, d, full) if np.any(d == 0) else (0.0, float(full.flat[0]))
        return NoEquilibriumError(
            f"d_over_a={di!r} is full slip (the tangential load is the full-slip load "
            f"{fi:.6g} N/m, {what}): the whole contact slips (sliding), there is no stick zone"
        )
    T, full = np.broadcast_arrays(np.asarray(T, float), np.asarray(full, float))
    Ti, fi = (
        _first(T >= full, T, full) if np.any(T >= full) else (float(T.flat[0]), float(full.flat[0]))
    )
    return NoEquilibriumError(
        f"tangential_load={Ti!r} N/m is at or above the full-slip load {fi:.6g} N/m ({what}): "
        "the whole contact slips (sliding), there is no stick zone"
    )


def _scalar(v):
    v = np.asarray(v)
    return v.item() if v.ndim == 0 else v


def _check_hertz_width(name: str, F: ArrayLike, a_over_R: ArrayLike, R: float) -> None:
    """Refuse a normal load whose Hertz contact is narrower than the solvers' domain.

    Coulomb friction takes the contact's half-width over the radius, which must be at least
    the lower end of the domain of ``a/R`` (said in radii, for the load ``name`` [N/m]).
    """
    lo = _domain.DOMAIN["a_over_R"][0]
    A = np.asarray(a_over_R, float)
    bad = ~(A >= lo)
    if np.any(bad):
        Fi, Ai = _first(bad, F, A)
        raise ValueError(
            f"{name}={Fi!r} N/m gives a contact of half-width {Ai * R:.3g} m, {Ai:.3g} radii: "
            f"below the domain of the solvers (at least {lo:g} radii)"
        )


def sliding_initiation(
    self: Any,
    normal_load: ArrayLike,
    *,
    friction_stress: ArrayLike | None = None,
    friction_coefficient: ArrayLike | None = None,
    d_over_a: ArrayLike | None = None,
    tangential_load: ArrayLike | None = None,
    method: str = "closed-form",
    on_failure: FailurePolicy = "raise",
) -> CylinderTangential:
    """Initiation of sliding under ``normal_load`` [N/m] (Eqs 15-17, SI units).

    Parameters
    ----------
    normal_load : array_like
        ``F`` [N/m]; the contact half-width ``a`` is that of the stable normal contact
        (:meth:`Cylinder.contact`). A load below the pull-off force raises
        :class:`~linecontact.errors.NoEquilibriumError`.
    friction_stress : array_like, optional
        ``tau0`` [Pa], ``> 0``: the nano-scale law
        (:func:`linecontact.tangential.sliding_initiation`).
    friction_coefficient : array_like, optional
        ``mu``, ``> 0``: Coulomb friction on the Hertz contact
        (:func:`linecontact.tangential.sliding_initiation_coulomb`); the cylinder must have
        no adhesion and ``F > 0``. Give exactly one of ``friction_stress`` and
        ``friction_coefficient``.
    d_over_a : array_like, optional
        Stick-zone half-width over ``a`` in ``[0, 1)``.
    tangential_load : array_like, optional
        ``T`` [N/m], ``>= 0`` (exactly one of ``d_over_a`` and ``tangential_load``).
    method : {"closed-form", "collocation"}
        As in :func:`linecontact.tangential.sliding_initiation`.
    on_failure : {"raise", "report"}
        As in :func:`linecontact.tangential.sliding_initiation`: a tangential load at or
        above full slip raises :class:`~linecontact.errors.NoEquilibriumError` (``"raise"``,
        default), or gives
        ``state == "sliding"`` (``"report"``); README, "Conventions". **Changed** after
        0.2.0: the keyword ``on_sliding`` (deleted) defaulted to ``"report"``. A normal load
        below the pull-off force raises either way.

    Returns
    -------
    CylinderTangential

    Examples
    --------
    >>> from linecontact import Cylinder
    >>> cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    >>> s = cyl.sliding_initiation(1.0, friction_stress=1e9, tangential_load=1.0)
    >>> s.state, s.stick_zone_end < s.contact_half_width
    ('stick-slip', True)
    """
    return _cylinder_tangential(
        "sliding initiation",
        self,
        normal_load,
        friction_stress,
        friction_coefficient,
        d_over_a,
        tangential_load,
        method,
        on_failure,
    )


def steady_rolling(
    self: Any,
    normal_load: ArrayLike,
    *,
    friction_stress: ArrayLike | None = None,
    friction_coefficient: ArrayLike | None = None,
    d_over_a: ArrayLike | None = None,
    tangential_load: ArrayLike | None = None,
    method: str = "closed-form",
    on_failure: FailurePolicy = "raise",
) -> CylinderTangential:
    r"""Steady rolling of a driving cylinder under ``normal_load`` [N/m] (Eqs 23-29).

    Parameters as in :meth:`sliding_initiation`, with ``d_over_a`` in ``(-1, 1)``
    the start of the leading-edge stick zone; ``tangential_load`` is the tractive force
    [N/m]. The result's ``creep_ratio`` is :math:`(V - \omega R)/V` (negative).

    Examples
    --------
    >>> from linecontact import Cylinder
    >>> cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    >>> r = cyl.steady_rolling(1.0, friction_stress=1e9, d_over_a=0.0)
    >>> r.creep_ratio < 0
    True
    """
    return _cylinder_tangential(
        "steady rolling",
        self,
        normal_load,
        friction_stress,
        friction_coefficient,
        d_over_a,
        tangential_load,
        method,
        on_failure,
    )


# --------------------------------------------------------------------------------------------
# the pushed fibre in SI units


def push(
    self: Any,
    *,
    friction_stress: float,
    height: ArrayLike,
    receding_range: float | None = None,
    receding_work_of_adhesion: float | None = None,
    normal_load: ArrayLike = 0.0,
    push: ArrayLike | None = None,
    tip_friction: ArrayLike | None = None,
    length: float | None = None,
) -> CylinderPush:
    r"""Will the cylinder, pushed at ``height`` [m], stay, roll or slide (``docs/push.md``).

    The cylinder's adhesion is the advancing one (its ``cohesive_stress`` and
    ``adhesion_range`` ``h2``, e.g. from the advancing work of adhesion); the receding edge
    has the same ``sigma0`` and the range ``h1``, given as ``receding_range`` [m] or as
    ``receding_work_of_adhesion`` [J/m^2] (:math:`h_1 = w_1 / \sigma_0`), :math:`h_1 \ge h_2`.

    Parameters
    ----------
    friction_stress : float
        ``tau0`` [Pa].
    height : array_like
        ``H`` [m] of the push, in ``[0, 2R]`` (of the tip's contact, in ``(0, 2R)``).
    receding_range, receding_work_of_adhesion : float
        Exactly one.
    normal_load : array_like
        ``F`` [N/m] (default 0).
    push : array_like, optional
        A horizontal push [N/m] whose state is wanted.
    tip_friction : array_like, optional
        A tip at ``height`` with this friction coefficient (:func:`linecontact.push`).
    length : float, optional
        The fibre's length [m], for the totals.

    Returns
    -------
    CylinderPush

    Examples
    --------
    >>> from linecontact import Cylinder, adhesion_from_work
    >>> s0, h1 = adhesion_from_work(0.05, 0.3e-9)        # receding work of adhesion
    >>> cyl = Cylinder.from_modulus(50e-9, 48.4e9, cohesive_stress=s0, adhesion_range=0.025 / s0)
    >>> p = cyl.push(friction_stress=1e6, height=[25e-9, 50e-9], receding_range=h1)
    >>> [str(m) for m in p.first_motion]
    ['slide', 'roll']
    """
    self._written("push")
    if (receding_range is None) == (receding_work_of_adhesion is None):
        raise ValueError("give exactly one of receding_range [m] or receding_work_of_adhesion")
    s0, h2, R, E = (self.cohesive_stress, self.adhesion_range, self.radius, self.modulus)
    if receding_range is not None:
        # h1 >= h2 (the hysteresis is not negative), as push's h1/h2 in [1, 1000]
        h1 = scalar(
            "receding_range",
            receding_range,
            low=h2,
            low_inclusive=True,
            high=1e3 * h2,
            high_inclusive=True,
        )
    elif receding_work_of_adhesion is not None:
        w1 = scalar("receding_work_of_adhesion", receding_work_of_adhesion)
        if not (np.isfinite(w1) and w1 > 0 and s0 > 0):
            raise ValueError(
                "receding_work_of_adhesion must be a finite number > 0, with a cylinder that "
                f"has adhesion (cohesive_stress > 0), got {w1!r}"
            )
        scalar(
            "receding_work_of_adhesion",
            w1,
            low=s0 * h2,
            low_inclusive=True,
            high=1e3 * s0 * h2,
            high_inclusive=True,
        )
        h1 = w1 / s0
        _plausible("receding_work_of_adhesion", w1, key="work_of_adhesion")
    if receding_range is not None:
        _plausible("receding_range", h1, key="adhesion_range")
    tau = scalar("friction_stress", friction_stress)
    _domain.check_si("friction_stress", tau, E, "tau0_over_E", "Pa")
    # a tip pushes strictly between the ends (0, 2R); a flat push anywhere on [0, 2R]
    on_ends = tip_friction is None
    H = check_array(
        "height", height, low=0.0, low_inclusive=on_ends, high=2 * R, high_inclusive=on_ends
    )
    Eh = E * h2
    # the SI inputs are checked (and named) here, not as the groups they form
    load = check_array("normal_load", normal_load, low=-np.inf, high=np.inf)
    _domain.check_si("normal_load", load, Eh, "F_over_Eh2", "N/m")
    F = load / Eh
    Q = None
    if push is not None:
        P = check_array("push", push, low=0.0, low_inclusive=True)
        _domain.check_si("push", P, Eh, "T_over_Ea", "N/m", _domain.SCALE_WORDS["F_over_Eh2"])
        Q = P / Eh
    if length is not None:
        positive("length", length)
    try:
        with _small_strain_in_si():  # the widths at rest and sliding: said below, in metres
            p = _push.push(
                R / h2,
                h1 / h2,
                self.sigma0_over_E,
                tau / E,
                F,
                np.asarray(H, float) / R,
                Q,
                tip_friction=tip_friction,
            )
    except NoEquilibriumError:
        # below the pull-off force of steady sliding: said in N/m, for this cylinder
        from ..sliding import sliding_pull_off

        if s0 == 0:  # no adhesion: no tension, and no contact without a compressive load
            Fi = float(np.min(load))
            raise NoEquilibriumError(
                f"normal_load={Fi!r} N/m holds no contact: without adhesion (cohesive_stress "
                "= 0) the fibre needs a compressive normal load (> 0)"
            ) from None
        F_po = float(sliding_pull_off(R / h2, h1 / h2, self.sigma0_over_E).F_pulloff_over_Eh2)
        F_po *= Eh
        below = np.asarray(load < F_po)
        Fi = float(load[below].flat[0]) if np.any(below) else float(np.min(load))
        raise NoEquilibriumError(
            f"normal_load={Fi!r} N/m is below the sliding pull-off force {F_po:.6g} N/m of "
            f"this cylinder (receding range {h1:.6g} m): it has pulled off"
        ) from None
    except _domain.TooWideError as e:
        # e.index counts the points of push, over the shape all its inputs broadcast to
        points = np.broadcast_shapes(
            *(np.shape(v) for v in (F, H, Q, tip_friction) if v is not None)
        )
        Fi = float(np.broadcast_to(load, points).reshape(-1)[e.index])
        raise _too_wide("normal_load", Fi, e, R) from None

    si = to_si(p, Scales.of(self))  # h2: the cylinder's (advancing) range
    _warn_widths(si["rest_half_width"], R, "the contact half-width at rest")
    _warn_widths(si["slide_half_width"], R, "the contact half-width while sliding")
    return CylinderPush(
        **si,
        first_motion=p.first_motion,
        creep_ratio=p.creep_over_V,
        state=p.state,
        length=length,
        nondimensional=p,
        scales=Scales.of(self),
    )


# --------------------------------------------------------------------------------------------
# tangential load histories and cyclic loading in SI units


def _history_contact(cylinder, normal_load, friction_stress, friction_coefficient):
    """(F, a [m], friction scale, coulomb?) for the SI history functions, every input checked."""
    coulomb = _is_coulomb(friction_stress, friction_coefficient)
    if coulomb:
        F = scalar("normal_load", normal_load)
        fr = _domain.scalar("friction_coefficient", friction_coefficient, "mu")
        _refuse_adhesion_with_coulomb(cylinder)
    else:
        F = scalar("normal_load", normal_load, low=-np.inf)
        fr = scalar("friction_stress", friction_stress)
        _domain.check_si("friction_stress", fr, cylinder.modulus, "tau0_over_E", "Pa")
    contact, a = _normal_contact(cylinder, F, coulomb)
    return F, float(a), fr, coulomb, contact


def _history_solve(
    cylinder, normal_load, stress, coefficient, name, loads, constant, coulomb, method
) -> tuple[tuple[str, float, float, float], Any, dict[str, Any]]:
    """``(head, result, SI fields)``: ``loads`` [N/m] solved.

    Through the nondimensional call ``constant(tau0/E, loads/(E a))`` or
    ``coulomb(mu, a/R, loads/(mu F))``; ``head`` is ``(law, F, a, full-slip load)``, the
    fields that both SI history results begin with (:class:`._results._HistoryResult`),
    ``law`` ``"constant"`` or ``"coulomb"``. The loads are refused beyond the solvers' domain
    here, as ``name`` [N/m] (the nondimensional call would name its group).
    """
    from ..tangential.history import _T_LIMIT

    F, a, fr, is_coulomb, _ = _history_contact(cylinder, normal_load, stress, coefficient)
    E = cylinder.modulus
    unit, group, full = _tangential_scales(is_coulomb, fr, F, a, E)
    words = _domain.SCALE_WORDS[group]
    with np.errstate(over="ignore"):
        bad = ~(np.abs(loads) <= _T_LIMIT * unit)
    if np.any(bad):
        raise ValueError(
            f"{name} must be at most {_T_LIMIT * unit:.6g} N/m in magnitude ({_T_LIMIT:g} "
            f"{words}, the domain of the solvers), got {float(loads[bad].flat[0])!r}"
        )
    with _small_strain_in_si():  # the contact's width: said by _for_load
        if is_coulomb:
            r = coulomb(fr, a / cylinder.radius, loads / unit, method=method)
        else:
            r = constant(fr / E, loads / unit, method=method)
    si = to_si(r, Scales.of(cylinder, a=a))
    return ("coulomb" if is_coulomb else "constant", F, a, full), r, si


def tangential_history(
    self: Any,
    normal_load: float,
    tangential_load: ArrayLike,
    *,
    friction_stress: float | None = None,
    friction_coefficient: float | None = None,
    method: str = "closed-form",
) -> CylinderTangentialHistory:
    """The states along a history of ``tangential_load`` [N/m] at a fixed ``normal_load``.

    Parameters
    ----------
    normal_load : float
        ``F`` [N/m], fixed; ``a`` is that of the stable normal contact.
    tangential_load : array_like, 1-D
        ``T`` [N/m] at the end of each step, either sign, starting from 0.
    friction_stress, friction_coefficient : float
        Exactly one: ``tau0`` [Pa] (constant friction stress) or ``mu`` (Coulomb, Hertz).
    method : {"closed-form", "incremental"}
        As in :func:`linecontact.tangential_history`.

    Returns
    -------
    CylinderTangentialHistory

    Examples
    --------
    >>> from linecontact import Cylinder
    >>> cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    >>> h = cyl.tangential_history(1.0, [1.0, -1.0, 1.0], friction_stress=1e9)
    >>> h.state.tolist()
    ['stick-slip', 'stick-slip', 'stick-slip']
    >>> bool(h.dissipation[1] > 0)
    True
    """
    from ..tangential.history import tangential_history, tangential_history_coulomb

    self._written("tangential_history")
    T = check_array("tangential_load", tangential_load, low=-np.inf)
    solvers = (tangential_history, tangential_history_coulomb)
    head, h, si = _history_solve(
        self,
        normal_load,
        friction_stress,
        friction_coefficient,
        "tangential_load",
        T,
        *solvers,
        method,
    )
    return CylinderTangentialHistory(
        *head,
        T.reshape(-1),  # as given (not back from T/(E a))
        si["stick_zone_half_width"],
        si["displacement"],
        si["dissipation"],
        h.state,
        h,
    )


def cyclic_loss(
    self: Any,
    normal_load: float,
    amplitude: ArrayLike,
    *,
    friction_stress: float | None = None,
    friction_coefficient: float | None = None,
    method: str = "closed-form",
) -> CylinderCyclicLoss:
    """The energy dissipated per cycle between ``-amplitude`` and ``+amplitude`` [N/m].

    Parameters
    ----------
    normal_load : float
        ``F`` [N/m], fixed.
    amplitude : array_like
        ``T*`` [N/m], ``> 0``; at or above full slip the state is ``"sliding"``.
    friction_stress, friction_coefficient : float
        Exactly one: ``tau0`` [Pa] or Coulomb ``mu``.
    method : {"closed-form", "incremental"}
        As in :func:`linecontact.cyclic_loss`.

    Returns
    -------
    CylinderCyclicLoss

    Examples
    --------
    >>> from linecontact import Cylinder
    >>> cyl = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    >>> w = cyl.cyclic_loss(1.0, [0.5, 1.0], friction_stress=1e9)
    >>> bool(w.energy_per_cycle[1] > w.energy_per_cycle[0] > 0)
    True
    """
    from ..tangential.history import cyclic_loss, cyclic_loss_coulomb

    self._written("cyclic_loss")
    A = check_array("amplitude", amplitude, low=0.0, low_inclusive=False)
    solvers = (cyclic_loss, cyclic_loss_coulomb)
    head, w, si = _history_solve(
        self, normal_load, friction_stress, friction_coefficient, "amplitude", A, *solvers, method
    )
    return CylinderCyclicLoss(
        *head,
        _scalar(A + 0 * np.asarray(w.W_over_Ea2)),  # as given, in the result's shape
        si["energy_per_cycle"],
        si["stick_zone_half_width"],
        w.state,
        w,
    )
