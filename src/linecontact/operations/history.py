"""The operations of tangential load histories: ``cycle`` and ``history``.

Over :mod:`linecontact.tangential.history` and the SI functions of
:mod:`linecontact.cylinder`. ``cycle`` prints one record per amplitude (``W_over_Ea2``, the
energy dissipated per cycle per unit length over ``E a^2``, and ``c_over_a``, the stick zone
at the peaks; ``state`` ``"sliding"`` at or above full slip, with the loss null);
``history`` one record per step (the stick zone, the slip direction, the turning points
held, the displacement, the energy dissipated in the step and the ``zones``). The friction
law and the contact are in ``parameters``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import domain as _domain
from .. import tangential as tg
from .._validation import check_array
from ..cylinder import Cylinder
from ..domain import check_si
from ..errors import ParameterError
from ..output import Table
from ..tangential.history import _T_LIMIT
from ._common import flag, si_columns, si_parameters
from ._declare import Inputs, Operation
from ._records import records
from ._written import made
from .tangential import (
    _check_friction,
    _friction_nd,
    _given,
    _loads,
    _normal_contact,
    _params,
    _si_friction,
    tangential_operation,
)

__all__ = ["OPERATIONS"]

_DESCRIPTION = {
    "cycle": (
        "Cyclic tangential loading between -T* and +T* at a fixed normal load: the energy "
        "dissipated per cycle W/(E a^2) and the stick zone at the peaks (docs/cli.md)."
    ),
    "history": (
        "A tangential load history from rest, one load per step: per step the stick zone, "
        "slip, turning points in memory (Masing), displacement and energy (docs/cli.md)."
    ),
}
_EXAMPLES = {
    "cycle": [
        "linecontact cycle --tau0-over-E 0.01 --T-amplitude-over-Ea 0.005 0.015",
        "linecontact cycle --friction coulomb --mu 0.3 --a-over-R 0.01 "
        "--T-amplitude-over-muF 0.1 0.5 --json",
    ],
    "history": [
        "linecontact history --tau0-over-E 0.01 --T-over-Ea 0.016 -0.008 0.004 0.018",
        "linecontact history --radius 50e-9 --modulus 100e9 --sigma0 1e9 --h 0.5e-9 --load 1 "
        "--tau0 1e9 --tangential-load 1 -1 1",
    ],
}


def _inputs(args: Inputs, nd: str, coulomb_nd: str, si: str):
    """(law, state flag, values, a_over_R, F_over_Eh, Cylinder or None), every flag checked."""
    coulomb = args.friction == "coulomb"
    _check_friction(args, coulomb, coulomb_nd, nd)
    given = _given(args, nd, coulomb_nd, si)
    flags = flag(nd), flag(coulomb_nd)
    si_flag = flag(si)
    if len(given) != 1:
        raise ParameterError(
            flags[0], f"give exactly one of {flags[0]}, {flags[1]} (Coulomb) or {si_flag} [N/m]"
        )
    (state,) = given
    A, F_over_Eh, cyl = _normal_contact(args, coulomb)
    if cyl is None and state == si:
        raise ParameterError(
            si_flag,
            f"{si_flag} [N/m] is an SI input: give --radius, the materials and --load too, or "
            f"use {flags[0]}",
        )
    # checked as given, before any conversion, so that a message names the flag typed
    if state in (nd, coulomb_nd) or state == "tangential_amplitude" or state == si:
        amplitude = state.startswith("T_amplitude") or state == "tangential_amplitude"
        values = check_array(
            state,
            getattr(args, state),
            # SI loads in N/m: their bound over E a or mu F is checked after conversion
            low=0.0 if amplitude else (-np.inf if state == si else -_T_LIMIT),
            low_inclusive=not amplitude and state != si,
            high=np.inf if state == si else _T_LIMIT,
            high_inclusive=state != si,
        )
    return coulomb, state, values, A, F_over_Eh, cyl


def _si_loads(args: Inputs, cyl: Cylinder, state: str, values, coulomb) -> np.ndarray:
    """Tangential loads [N/m] from the flag given: over E a, over mu F, or in N/m.

    What scales them is checked first (``--mu``, ``--load``, each named); loads in N/m are
    checked against the solvers' domain by the SI layer (as ``--tangential-load`` or
    ``--tangential-amplitude``).
    """
    if coulomb:
        _domain.scalar("--mu", args.mu, "mu")
    if state.endswith("over_Ea"):
        return cyl.tangential_load(args.load, values, over="Ea")
    if state.endswith("over_muF"):
        load = check_array("--load", args.load, low=-np.inf)
        check_si("--load", load, cyl.scale("Eh"), "F_over_Eh", "N/m")
        return cyl.tangential_load(args.load, values, over="muF", friction_coefficient=args.mu)
    return values


def _si_params(args, cyl, res, fr) -> dict[str, Any]:
    params: dict[str, Any] = {"friction": res.friction}
    params.update(si_parameters(args, cyl))
    params.update(
        F_N_per_m=args.load,
        a_m=res.contact_half_width,
        a_over_R=cyl.over(res.contact_half_width, "R"),
        T_full_slip_N_per_m=res.full_slip_load,
    )
    if "friction_coefficient" in fr:
        params["mu"] = fr["friction_coefficient"]
    else:
        params["tau0_Pa"] = fr["friction_stress"]
    if args.length is not None:
        params["F_total_N"] = cyl.total(args.load, args.length)
    return params


@dataclass(frozen=True)
class _Loading:
    """What differs between ``cycle`` and ``history``: their flags, solver, columns, table."""

    nd: str  # the loads over E a
    coulomb_nd: str  # over mu F
    si: str  # in N/m
    solver: str  # the name of the SI method and of the nondimensional functions (+ _coulomb)
    columns: dict[str, str]  # the SI fields of the result and their keys
    total: tuple[str, str]  # the SI field whose total over --length is given, and its key
    table: Callable[..., Table]


def _compute(args: Inputs, how: _Loading) -> Table:
    coulomb, state, values, A, F_over_Eh, cyl = _inputs(args, how.nd, how.coulomb_nd, how.si)
    if cyl is not None:
        fr = _si_friction(args, coulomb, cyl)
        loads = _si_loads(args, cyl, state, values, coulomb)
        res = made(
            args, "result", getattr(cyl, how.solver), args.load, loads, **fr, method=args.method
        )
        extra: dict[str, Any] = si_columns(res, how.columns)
        if args.length is not None:
            field, key = how.total
            extra[key] = cyl.total(getattr(res, field), args.length)
        return how.table(args, res.nondimensional, _si_params(args, cyl, res, fr), extra)
    _friction_nd(args, coulomb, A)
    if coulomb:
        Q = values if state == how.coulomb_nd else values / ((np.pi / 4) * args.mu * A)
        r: Any = getattr(tg, how.solver + "_coulomb")(args.mu, A, Q, method=args.method)
    else:
        r = getattr(tg, how.solver)(args.tau0_over_E, values, method=args.method)
    return how.table(args, r, _params(args, coulomb, A, F_over_Eh), {})


def _cycle_table(args, r, params, extra):
    show = ["T_amplitude_over_Ea", "T_amplitude_over_T_full_slip", "W_over_Ea2", "c_over_a"]
    show += ["state", *extra]
    law = "Coulomb friction" if params["friction"] == "coulomb" else "constant friction stress"
    return records(
        args,
        r,
        params,
        extra,
        f"cyclic tangential loading, {law} ({r.method}): energy dissipated per cycle",
        show,
    )


def _history_table(args, h, params, extra):
    zones = np.empty(h.step.size, dtype=object)
    zones[:] = [[list(z) for z in zs] for zs in h.zones()]
    cols = {**extra, "zones": zones}
    show = ["step", "T_over_Ea", "T_over_T_full_slip", "state", "c_over_a", "slip_direction"]
    show += ["memory", "displacement_over_a", "dissipation_over_Ea2", *extra]
    law = "Coulomb friction" if params["friction"] == "coulomb" else "constant friction stress"
    return records(args, h, params, cols, f"tangential load history, {law} ({h.method})", show)


_CYCLE = _Loading(
    "T_amplitude_over_Ea",
    "T_amplitude_over_muF",
    "tangential_amplitude",
    "cyclic_loss",
    {
        "amplitude": "T_amplitude_N_per_m",
        "energy_per_cycle": "W_J_per_m",
        "stick_zone_half_width": "c_m",
    },
    ("energy_per_cycle", "W_total_J"),
    _cycle_table,
)
_HISTORY = _Loading(
    "T_over_Ea",
    "T_over_muF",
    "tangential_load",
    "tangential_history",
    {
        "tangential_load": "T_N_per_m",
        "stick_zone_half_width": "c_m",
        "displacement": "displacement_m",
        "dissipation": "dissipation_J_per_m",
    },
    ("dissipation", "dissipation_total_J"),
    _history_table,
)


def _cmd_cycle(args: Inputs) -> Table:
    return _compute(args, _CYCLE)


def _cmd_history(args: Inputs) -> Table:
    return _compute(args, _HISTORY)


# --------------------------------------------------------------------------------------------
# the declarations

_LOADS = "tangential loads (exactly one)"


def _operation(name: str, summary: str, how: _Loading, helps: tuple[str, str, str]) -> Operation:
    metavars = ("A", "Q", "T") if name == "cycle" else ("T", "T", "T")
    loads = _loads(_LOADS, *zip((how.nd, how.coulomb_nd, how.si), helps, metavars, strict=True))
    return tangential_operation(
        name,
        summary,
        (_DESCRIPTION[name], _EXAMPLES[name]),
        loads,
        ("Masing rules, or a stepwise check", ("closed-form", "incremental")),
        _cmd_cycle if name == "cycle" else _cmd_history,
        rows=tuple(p.name for p in loads) if name == "cycle" else (),
    )


OPERATIONS = {
    "cycle": _operation(
        "cycle",
        "cyclic tangential loading: energy dissipated per cycle, stick zone",
        _CYCLE,
        (
            "amplitude T*/(E a), > 0",
            "amplitude T*/(mu F), > 0 (Coulomb)",
            "amplitude T* [N/m] (SI inputs)",
        ),
    ),
    "history": _operation(
        "history",
        "a tangential load history with memory: zones, slip, energy per step",
        _HISTORY,
        (
            "the loads T/(E a) at the ends of the steps, either sign",
            "the loads T/(mu F), either sign (Coulomb)",
            "the loads T [N/m] (SI inputs)",
        ),
    ),
}
