"""The operations of tangential loading: ``slide-init`` and ``roll``.

Over :mod:`linecontact.tangential` and the SI functions of
:mod:`linecontact.cylinder`. Records (one per value of the tangential state given) carry
``d_over_a`` and ``T_over_Ea`` (and ``creep_over_V`` for ``roll``), ``state`` (``"stick"``,
``"stick-slip"`` or ``"sliding"``: a load at or above full slip is reported, not an error;
``d_over_a`` and ``creep_over_V`` are then null) and the diagnostics; the friction law and
the normal contact are in ``parameters``.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from .. import tangential as tg
from .._validation import non_negative
from ..cylinder import Cylinder
from ..domain import DOMAIN, check
from ..errors import NoEquilibriumError, ParameterError
from ..facet import facet_contact_for_load, facet_pull_off
from ..normal import contact_for_load, pull_off
from ..output import Table
from ._common import (
    cylinder,
    flag,
    group_parameters,
    shape,
    shape_parameters,
    shape_parameters_of,
    si_given,
    si_inputs,
    si_parameters,
)
from ._declare import Entry, Inputs, Operation, Parameter
from ._records import records

__all__ = ["OPERATIONS"]

_ADHESION_KEYS = ("sigma0", "h", "work_of_adhesion", "z0")

_DESCRIPTION = {
    "slide-init": (
        "Initiation of sliding (paper Eqs 15-17): a tangential force T on a contact of "
        "half-width a; stick zone |x| < d, slip zones d < |x| < a (docs/cli.md)."
    ),
    "roll": (
        "Steady rolling of a driving cylinder (paper Eqs 23-29): stick zone d < x < a at the "
        "leading edge, tractive force T and creep (docs/cli.md)."
    ),
}
_EXAMPLES = {
    "slide-init": [
        "linecontact slide-init --tau0-over-E 0.01 --d-over-a 0.2 0.5",
        "linecontact slide-init --tau0-over-E 0.01 --T-over-Ea 0.01 0.03 --json",
    ],
    "roll": [
        "linecontact roll --tau0-over-E 0.01 --d-over-a -0.5 0.5 --method collocation",
        "linecontact roll --radius 50e-9 --modulus 100e9 --sigma0 1e9 --h 0.5e-9 --load 1 "
        "--tau0 1e8 --tangential-load 0.3",
    ],
}


def _cmd_slide_init(args: Inputs) -> Table:
    return _run(args, rolling=False)


def _cmd_roll(args: Inputs) -> Table:
    return _run(args, rolling=True)


def _given(args: Inputs, *names: str) -> list[str]:
    return [n for n in names if getattr(args, n) is not None]


def _normal_contact(args: Inputs, coulomb: bool):
    """(a_over_R or None, F_over_Eh or None, Cylinder or None) from the normal inputs."""
    si = si_given(args)
    groups = bool(_given(args, "R_over_h", "sigma0_over_E"))
    if si:
        if groups or args.a_over_R is not None or args.F_over_Eh is not None:
            raise ParameterError(
                "--R-over-h",
                "--R-over-h, --sigma0-over-E, --a-over-R and --F-over-Eh are nondimensional: "
                "with SI inputs give the normal load --load [N/m]",
            )
        if args.load is None:
            raise ParameterError("--load", "SI inputs need the normal load --load [N/m]")
        if coulomb and not _given(args, *_ADHESION_KEYS):
            args.h = args.radius  # no adhesion: the range h only sets an unused length scale
        cyl = cylinder(args)
        shape(args, cyl)  # the corner radius given as the SI inputs want it
        return None, None, cyl
    if args.load is not None:
        raise ParameterError(
            "--load", "--load [N/m] is an SI input: give --radius and the materials too"
        )
    if groups:
        if args.a_over_R is not None:
            raise ParameterError(
                "--a-over-R",
                "give either --a-over-R or the normal problem (--R-over-h, --sigma0-over-E, "
                "--F-over-Eh), not both",
            )
        if args.R_over_h is None or args.sigma0_over_E is None:
            raise ParameterError("--R-over-h", "give both --R-over-h and --sigma0-over-E")
        if args.F_over_Eh is None:
            raise ParameterError(
                "--R-over-h", "with --R-over-h and --sigma0-over-E give the normal load --F-over-Eh"
            )
        if coulomb and args.sigma0_over_E != 0:
            raise ParameterError(
                "--sigma0-over-E",
                "Coulomb friction is the counterpart for the non-adhesive Hertz contact: use "
                "--sigma0-over-E 0 (or --friction constant)",
            )
        g = shape(args, None)
        try:
            if g is not None:
                c = facet_contact_for_load(args.F_over_Eh, args.R_over_h, args.sigma0_over_E, **g)
            else:
                c = contact_for_load(args.F_over_Eh, args.R_over_h, args.sigma0_over_E)
        except NoEquilibriumError:  # said with the flags (the minimum load: no flag of its own)
            if g is not None:
                F_min = facet_pull_off(args.R_over_h, args.sigma0_over_E, **g).F_pulloff_over_Eh
            else:
                F_min = pull_off(args.R_over_h, args.sigma0_over_E).F_minimum_over_Eh
            raise NoEquilibriumError(
                f"no contact carries --F-over-Eh={args.F_over_Eh!r}: it is below the pull-off "
                f"force, {F_min + 0.0:.6g} in the units of --F-over-Eh (the minimum load on the "
                "contact branch); the cylinder has pulled off"
            ) from None
        return c.a_over_R, args.F_over_Eh, None
    if args.F_over_Eh is not None:
        raise ParameterError("--F-over-Eh", "--F-over-Eh needs --R-over-h and --sigma0-over-E")
    if shape(args, None) is not None:
        raise ParameterError(
            "--cross-section",
            "--cross-section shapes the normal contact (--R-over-h, --sigma0-over-E, "
            "--F-over-Eh, or SI inputs): with --a-over-R the contact's width is given",
        )
    return args.a_over_R, None, None


def _check_friction(
    args: Inputs,
    coulomb: bool,
    coulomb_load: str = "T_over_muF",
    load: str = "T_over_Ea",
) -> None:
    """The friction flags against the law; ``coulomb_load`` is the Coulomb-only load flag."""
    if coulomb:
        if _given(args, "tau0_over_E", "tau0"):
            raise ParameterError(
                "--tau0-over-E",
                "--tau0-over-E and --tau0 are for --friction constant; Coulomb friction takes --mu",
            )
        if args.mu is None:
            raise ParameterError(
                "--friction", "--friction coulomb needs the friction coefficient --mu"
            )
    else:
        if args.mu is not None:
            raise ParameterError(
                "--mu", "--mu is the Coulomb friction coefficient: add --friction coulomb"
            )
        if getattr(args, coulomb_load) is not None:
            raise ParameterError(
                flag(coulomb_load),
                f"{flag(coulomb_load)} is for --friction coulomb; use {flag(load)}",
            )


def _friction_nd(args: Inputs, coulomb: bool, A) -> dict[str, Any]:
    """The friction of the groups checked: Coulomb's needs ``a/R``, the constant tau0/E."""
    if coulomb:
        if A is None:
            raise ParameterError(
                "--a-over-R",
                "Coulomb friction needs the Hertz half-width: give --a-over-R (or --R-over-h "
                "--sigma0-over-E 0 --F-over-Eh, or SI inputs)",
            )
        return {}
    if args.tau0 is not None:
        raise ParameterError(
            "--tau0",
            "--tau0 [Pa] is an SI input: give --radius, the materials and --load too, or use "
            "--tau0-over-E",
        )
    if args.tau0_over_E is None:
        raise ParameterError(
            "--tau0-over-E", "give the friction stress --tau0-over-E (or --friction coulomb --mu)"
        )
    return {}


def _params(args, coulomb: bool, A, F_over_Eh) -> dict[str, Any]:
    """The friction law and the normal contact of the groups, for the provenance."""
    params: dict[str, Any] = {"friction": "coulomb" if coulomb else "constant"}
    if A is not None:
        params["a_over_R"] = float(A)
    if F_over_Eh is not None:
        params.update(R_over_h=args.R_over_h, sigma0_over_E=args.sigma0_over_E, F_over_Eh=F_over_Eh)
        g = shape(args, None)
        if g is not None:
            params.update(shape_parameters_of(g, None))
    return params


def _si_friction(args: Inputs, coulomb: bool, cyl: Cylinder) -> dict[str, Any]:
    """The SI friction keywords: ``friction_coefficient`` or ``friction_stress`` [Pa]."""
    if coulomb:
        return dict(friction_coefficient=args.mu)
    if len(_given(args, "tau0", "tau0_over_E")) != 1:
        raise ParameterError("--tau0", "give the friction stress as --tau0 [Pa] or --tau0-over-E")
    return dict(
        friction_stress=args.tau0 if args.tau0 is not None else cyl.in_si(args.tau0_over_E, "E")
    )


def _run(args: Inputs, rolling: bool) -> Table:
    coulomb = args.friction == "coulomb"
    _check_friction(args, coulomb)
    if coulomb and (getattr(args, "cross_section", None) or "round") != "round":
        raise ParameterError(
            "--friction",
            "--friction coulomb bounds the shear by the Hertz pressure of a round wire: a "
            f"{args.cross_section} wire takes --friction constant (a friction stress)",
        )
    states = _given(args, "d_over_a", "T_over_Ea", "T_over_muF", "tangential_load")
    if len(states) != 1:
        raise ParameterError(
            "--d-over-a",
            "give exactly one of --d-over-a, --T-over-Ea, --T-over-muF (Coulomb) or "
            "--tangential-load [N/m] (SI)",
        )
    (state,) = states
    A, F_over_Eh, cyl = _normal_contact(args, coulomb)
    if cyl is None and state == "tangential_load":
        raise ParameterError(
            "--tangential-load",
            "--tangential-load [N/m] is an SI input: give --radius, the materials and --load "
            "too, or use --T-over-Ea",
        )
    values = np.asarray(getattr(args, state), float)
    if state != "d_over_a":
        # checked before any conversion (T/(Ea) to T/(mu F), ...), so that the message names
        # the option given and its value
        if state in DOMAIN:
            check(state, values)
        else:
            non_negative(state, values)
    d = values if state == "d_over_a" else None
    if cyl is not None:
        return _run_si(args, rolling, coulomb, cyl, state, values, d)
    _friction_nd(args, coulomb, A)
    if coulomb:
        coulomb_fn = tg.steady_rolling_coulomb if rolling else tg.sliding_initiation_coulomb
        if state == "T_over_Ea":
            values = values / ((np.pi / 4) * args.mu * A)
        T = None if d is not None else values
        # a load at or beyond full slip is a record with state "sliding", not an error
        r: Any = coulomb_fn(args.mu, A, d, T_over_muF=T, method=args.method, on_failure="report")
    else:
        fn = tg.steady_rolling if rolling else tg.sliding_initiation
        T_over_Ea = None if d is not None else values
        r = fn(args.tau0_over_E, d, T_over_Ea=T_over_Ea, method=args.method, on_failure="report")
    table = _table(args, r, rolling, coulomb, _params(args, coulomb, A, F_over_Eh), {})
    return table


def _run_si(args, rolling, coulomb, cyl: Cylinder, state, values, d) -> Table:
    fr = _si_friction(args, coulomb, cyl)
    fn = cyl.steady_rolling if rolling else cyl.sliding_initiation
    contact = cyl.contact(load=args.load, on_failure="report")
    params: dict[str, Any] = {"friction": "coulomb" if coulomb else "constant"}
    params.update(si_parameters(args, cyl))
    g = shape(args, cyl)
    if g is not None:
        params.update(shape_parameters_of(g, cyl))
    params["F_N_per_m"] = args.load
    if contact.state != "contact":
        # the normal load is below the pull-off force: no tangential state exists
        return _pulled_off(args, rolling, values, state, params, cyl)
    a_m = contact.contact_half_width
    how: dict[str, Any] = dict(**fr, method=args.method, on_failure="report")
    if state in ("T_over_Ea", "T_over_muF"):
        over = "Ea" if state == "T_over_Ea" else "muF"
        mu = dict(friction_coefficient=args.mu)
        T = cyl.tangential_load(args.load, values, over=over, **mu)  # type: ignore[arg-type]
        res = fn(args.load, tangential_load=T, **how)
    elif state == "tangential_load":
        res = fn(args.load, tangential_load=values, **how)
    else:
        res = fn(args.load, d_over_a=d, **how)
    params.update(
        a_over_R=cyl.over(a_m, "R"),
        a_m=a_m,
        T_full_slip_N_per_m=float(np.reshape(res.full_slip_load, -1)[0]),
    )
    if coulomb:
        params["mu"] = args.mu
    else:
        params["tau0_Pa"] = fr["friction_stress"]
    extra: dict[str, Any] = {
        "d_m": res.stick_zone_end,
        "T_N_per_m": res.tangential_load,
    }
    if args.length is not None:
        extra["T_total_N"] = cyl.total(res.tangential_load, args.length)
        params["F_total_N"] = cyl.total(args.load, args.length)
        params["T_full_slip_total_N"] = cyl.total(params["T_full_slip_N_per_m"], args.length)
    table = _table(args, res.nondimensional, rolling, coulomb, params, extra)
    return table


def _pulled_off(args, rolling, values, state, params, cyl) -> Table:
    """Every record without a state: the normal load is below the pull-off force."""
    po = cyl.pull_off()
    n = values.size
    why = (
        f"no contact carries the normal load {args.load!r} N/m: it is below the pull-off force "
        f"{po.pull_off_force:.6g} N/m (the cylinder has pulled off)"
    )
    cols: dict[str, Any] = {"d_over_a": np.full(n, np.nan), "T_over_Ea": np.full(n, np.nan)}
    if rolling:
        cols["creep_over_V"] = np.full(n, np.nan)
    cols[state] = values.reshape(-1)
    cols["state"] = np.full(n, "no-equilibrium")
    cols["reason"] = np.full(n, why, dtype=object)
    table = Table(
        cols,
        params,
        {},
        args.command_line(),
        "the normal load is below the pull-off force: no contact, no tangential state",
        show=(*cols,),
    )
    return table


def _table(args, r, rolling: bool, coulomb: bool, params, extra):
    show = ["d_over_a", "T_over_Ea", "T_over_T_full_slip"]
    show += ["creep_over_V"] if rolling else []
    show += ["state"]
    show += ["T_N_per_m"] if "T_N_per_m" in extra else []
    show += ["T_total_N"] if "T_total_N" in extra else []
    what = "steady rolling (driving cylinder)" if rolling else "initiation of sliding"
    law = "Coulomb friction" if coulomb else "constant friction stress"
    return records(args, r, params, extra, f"{what}, {law} ({r.method})", show)


# --------------------------------------------------------------------------------------------
# the declarations

_FRICTION = (
    Parameter(
        "friction",
        "constant stress tau0, or Coulomb mu on Hertz",
        kind="text",
        choices=("constant", "coulomb"),
        default="constant",
    ),
    Parameter("tau0_over_E", "friction stress over E, > 0", metavar="T"),
    Parameter("tau0", "friction stress tau0 [Pa] (SI inputs)", unit="Pa", metavar="T"),
    Parameter("mu", "friction coefficient, > 0 (--friction coulomb)"),
)
_FRICTION_ENTRIES = (
    Entry(("tau0_over_E", "tau0"), "friction stress tau0/E, > 0; or tau0 [Pa] (SI)"),
)
_NORMAL = "normal contact (the contact half-width a)"
_SI, _SI_ENTRIES = si_inputs()


def _normal_contact_parameters() -> tuple[Parameter, ...]:
    """The groups or SI inputs and the normal contact that gives the half-width ``a``."""
    return (
        *group_parameters(_NORMAL),
        *_SI,
        Parameter("load", "normal load per unit length F [N/m] (SI)", unit="N/m", group=_NORMAL),
        Parameter(
            "F_over_Eh",
            "normal load over E h (with --R-over-h and --sigma0-over-E)",
            metavar="F",
            group=_NORMAL,
        ),
        Parameter(
            "a_over_R",
            "contact half-width over R (Coulomb: the Hertz half-width)",
            metavar="A",
            group=_NORMAL,
        ),
    )


def _loads(group: str, *loads: tuple[str, str, str]) -> tuple[Parameter, ...]:
    """The tangential states ``(name, help, metavar)``, several values each, in ``group``.

    The last is the SI one, in N/m.
    """
    *nd, (name, help, metavar) = loads
    return (
        *(Parameter(n, h, many="several", metavar=m, group=group) for n, h, m in nd),
        Parameter(name, help, many="several", unit="N/m", metavar=metavar, group=group),
    )


def tangential_operation(
    name: str,
    summary: str,
    text: tuple[str, Sequence[str]],
    loads: tuple[Parameter, ...],
    method: tuple[str, tuple[str, ...]],
    compute: Any,
    shapes: tuple[tuple[Parameter, ...], tuple[Entry, ...]] = ((), ()),
    **how: Any,
) -> Operation:
    """A tangential loading of the normal contact (``slide-init``, ``roll``, ``cycle``, ...).

    Its parameters: the friction, the ``loads``, the normal contact and ``--method`` (its
    help and choices, ``closed-form`` by default), and ``shapes`` (the wire's cross-section
    and their entries, where the problem is written for a polygon); ``text`` is its
    description and examples, ``how`` the rest of the :class:`Operation`.
    """
    return Operation(
        name,
        summary,
        text[0],
        tuple(text[1]),
        (
            *_FRICTION,
            *loads,
            *_normal_contact_parameters(),
            Parameter("method", method[0], kind="text", choices=method[1], default="closed-form"),
            *shapes[0],
        ),
        compute,
        entries=(
            *_FRICTION_ENTRIES,
            *_SI_ENTRIES,
            Entry(("F_over_Eh", "load"), "normal load F/(E h), or F [N/m] (SI)"),
            *shapes[1],
        ),
        **how,
    )


def _operation(name: str, summary: str, compute: Any) -> Operation:
    lo = "[0, 1)" if name == "slide-init" else "(-1, 1)"
    return tangential_operation(
        name,
        summary,
        (_DESCRIPTION[name], _EXAMPLES[name]),
        _loads(
            "tangential state (exactly one)",
            ("d_over_a", f"stick-zone end d/a, in {lo}", "D"),
            ("T_over_Ea", "tangential force per unit length over E a, >= 0", "T"),
            ("T_over_muF", "tangential force over mu F, >= 0 (Coulomb)", "T"),
            ("tangential_load", "tangential force per unit length T [N/m] (SI inputs)", "T"),
        ),
        ("the closed forms or collocation", ("closed-form", "collocation")),
        compute,
        # a polygon's initiation of sliding: the constant friction stress at its contact
        shapes=shape_parameters(_NORMAL) if name == "slide-init" else ((), ()),
        good=("stick", "stick-slip", "sliding"),
        rows=("d_over_a", "T_over_Ea", "T_over_muF", "tangential_load"),
    )


OPERATIONS = {
    "slide-init": _operation(
        "slide-init",
        "initiation of sliding under a tangential force (stick zone, T/(Ea))",
        _cmd_slide_init,
    ),
    "roll": _operation(
        "roll",
        "steady rolling of a driving cylinder (stick zone, T/(Ea), creep)",
        _cmd_roll,
    ),
}
