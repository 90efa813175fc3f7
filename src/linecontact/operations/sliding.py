"""The ``slide`` operation: steady sliding with different trailing and leading adhesion.

Over :func:`linecontact.sliding.sliding_contact` and
:func:`linecontact.sliding.sliding_contact_for_load`. The records carry at least
``a_over_R``, ``c1_over_R``, ``c2_over_R``, ``e_over_R``, ``F_over_Eh2``, ``M_over_Eh2R``
(a contract).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..cylinder import sliding_pull_off_force
from ..domain import check_si
from ..errors import ParameterError
from ..output import Table
from ..sliding import sliding_contact, sliding_contact_for_load, sliding_pull_off
from ._common import (
    cylinder,
    group_parameters,
    half_widths,
    positive,
    si_given,
    si_inputs,
    si_loads,
    si_parameters,
    sliding_parameters,
    width_parameters,
)
from ._declare import Entry, Inputs, Operation, Parameter
from ._records import convergence, records, si_shown

__all__ = ["OPERATIONS"]

_DESCRIPTION = (
    "Steady sliding (paper Eqs 18-22): the trailing edge adheres over a longer range h1 than "
    "the leading edge h2; the adhesive zones, apex position e, load F and moment M about the "
    "contact centre, clockwise positive (axes: docs/cli.md)."
)


def _setup(args: Inputs):
    """(R/h2, h1/h2, sigma0/E, tau0/E or None, Cylinder or None) from the arguments.

    With SI inputs h1/h2 and tau0/E are None: the cylinder's method takes ``--h1`` [m] (or
    ``--h1-over-h2``) and ``--tau0`` [Pa].
    """
    si = si_given(args, extra=("h1", "tau0"))
    nd = any(v is not None for v in (args.R_over_h2, args.sigma0_over_E, args.tau0_over_E))
    if si and nd:
        raise ParameterError(
            "--R-over-h2",
            "give either the nondimensional groups (--R-over-h2, --sigma0-over-E, "
            "--tau0-over-E) or SI inputs (--radius, ...), not both",
        )
    if args.h1_over_h2 is not None and args.h1 is not None:
        raise ParameterError(
            "--h1", "give the trailing range as --h1 [m] or as --h1-over-h2, not both"
        )
    if args.h1_over_h2 is None and args.h1 is None:  # asked in the spelling of the others
        raise ParameterError(
            "--h1" if si else "--h1-over-h2",
            "give the trailing (receding) range --h1 [m] (or --h1-over-h2)"
            if si
            else "give --h1-over-h2, the trailing over the leading range",
        )
    if not si:
        if args.R_over_h2 is None or args.sigma0_over_E is None:
            raise ParameterError(
                "--R-over-h2",
                "give --R-over-h2, --h1-over-h2 and --sigma0-over-E (or SI inputs with --radius)",
            )
        return args.R_over_h2, args.h1_over_h2, args.sigma0_over_E, args.tau0_over_E, None
    cyl = cylinder(args, range_flag="--h2")
    positive("--h1", args.h1)
    if args.tau0 is not None and not (np.isfinite(args.tau0) and args.tau0 >= 0):
        raise ParameterError("--tau0", f"--tau0 must be a finite number >= 0, got {args.tau0!r}")
    if args.h1 is not None:
        check_si("--h1", args.h1, cyl.scale("h"), "h1_over_h2", "m")
    if args.tau0 is not None:
        check_si("--tau0", args.tau0, cyl.scale("E"), "friction_tau0_over_E", "Pa")
    return cyl.R_over_h, None, cyl.sigma0_over_E, None, cyl


def _ratio(res) -> float:
    """The one h1/h2 of a result."""
    return float(np.reshape(res.h1_over_h2, -1)[0])


def _cmd_slide(args: Inputs) -> Table:
    rho, r, s, tau, cyl = _setup(args)
    A = half_widths(args, cyl, "F_over_Eh2")
    how: dict[str, Any] = dict(method=args.method, on_failure="report")
    if cyl is not None:  # the SI layer: h1 [m] or h1/h2, tau0 [Pa]
        how.update(receding_range=args.h1, h1_over_h2=args.h1_over_h2, friction_stress=args.tau0)
    if A is not None:
        if cyl is None:
            res = sliding_contact(A, rho, r, s, tau0_over_E=tau, **how)
        else:  # A in m
            si = cyl.sliding(contact_half_width=A, **how)
            res = si.nondimensional
        state, reason = convergence(res, args.method)
        given = "a_over_R"
    else:
        if cyl is None:
            F = np.asarray(args.F_over_Eh2, float)
            res = sliding_contact_for_load(F, rho, r, s, tau0_over_E=tau, **how)
        else:
            load = si_loads(args, cyl, "F_over_Eh2")
            si = cyl.sliding(load=load, **how)
            res = si.nondimensional
            F = cyl.over(load, "Eh")
        state = np.asarray(res.state).reshape(-1)
        reason = np.full(state.shape, None, dtype=object)
        # a state that misses its tolerance is marked, as for given widths
        missed = (state == "contact") & ~np.asarray(res.converged, bool).reshape(-1)
        for i in np.flatnonzero(missed):
            Fi = float(np.reshape(F, -1)[i])
            reason[i] = f"the {args.method} solver did not converge at F_over_Eh2={Fi!r}"
        state = np.where(missed, "not-converged", state)
        if np.any(state == "no-equilibrium"):
            if s == 0:
                force = None
            elif cyl is None:
                force = f"{sliding_pull_off(rho, r, s).F_pulloff_over_Eh2:.6g} E h2"
            else:
                force = f"{sliding_pull_off_force(cyl, _ratio(res)):.6g} N/m"
            for i in np.flatnonzero(state == "no-equilibrium"):
                reason[i] = (
                    "no steadily sliding contact carries this load: it is below the pull-off "
                    f"force {force}"
                    if force is not None
                    else "without adhesion (sigma0 = 0) the load must be > 0"
                )
        given = "F_over_Eh2"
    params: dict[str, Any] = {}
    extra: dict[str, Any] = {"c1_minus_c2_over_R": np.subtract(res.c1_over_R, res.c2_over_R)}
    show = ["a_over_R", "c1_over_R", "c2_over_R", "e_over_R", "F_over_Eh2", "M_over_Eh2R"]
    drop = ["state"]
    if tau is None and args.tau0 is None:
        drop += ["tau0_over_E", "T_over_Eh2"]
    else:
        show.append("T_over_Eh2")
    show.append("stable")
    if cyl is not None:
        params.update(si_parameters(args, cyl))
        params["h1_m"] = cyl.in_si(_ratio(res), "h")
        names = {"contact_half_width": "a_m", "trailing_zone_end": "c1_m"}
        names.update(leading_zone_end="c2_m", eccentricity="e_m", load="F_N_per_m")
        names["moment"] = "M_N"
        totals = {"load": "F_total_N", "moment": "M_total_N_m"}
        shown = ["a_m", "F_N_per_m", "M_N"]
        if args.tau0 is not None:
            params["tau0_Pa"] = args.tau0
            names["friction_force"] = "T_N_per_m"
            totals["friction_force"] = "T_total_N"
            shown.append("T_N_per_m")
        cols, shown = si_shown(args, si, names, totals, shown)
        extra.update(cols)
        show += shown
    return records(
        args,
        res,
        params,
        extra,
        (
            f"steady sliding ({res.method}); M clockwise positive about the contact centre, "
            "compressive load positive"
        ),
        show,
        contact=(state, reason, given),
        drop=drop,
    )


# --------------------------------------------------------------------------------------------
# the declaration

_SI, _SI_ENTRIES = si_inputs(range_flag="--h2")
_GROUPS, _SLIDING_SI = sliding_parameters(
    (
        "radius over the leading-edge adhesion range h2, > 0",
        "trailing over leading range, > 0 (1: the normal contact)",
        group_parameters()[1].help,  # sigma0_over_E's
        "shear strength over E, >= 0: adds the friction force 2 a tau0",
    ),
    (
        "trailing-edge adhesion range h1 [m] (or give --h1-over-h2)",
        "interface shear strength tau0 [Pa]",
    ),
)
_WIDTHS = "contact half-widths or loads (exactly one)"

OPERATIONS = {
    "slide": Operation(
        "slide",
        "steady sliding: adhesive zones, eccentricity, load and moment (trailing h1, leading h2)",
        _DESCRIPTION,
        (
            "linecontact slide --R-over-h2 100 --h1-over-h2 2 --sigma0-over-E 0.04 "
            "--a-over-R 0.01 0.05",
            "linecontact slide --radius 50e-9 --modulus 100e9 --sigma0 1e9 --h2 0.5e-9 --h1 1e-9 "
            "--load 0.05 --tau0 5e8",
        ),
        (
            *_GROUPS,
            *_SI,
            *_SLIDING_SI,
            *width_parameters(
                "F_over_Eh2", "normal loads over E h2 (the stable sliding contact)", _WIDTHS
            ),
            Parameter(
                "method",
                "collocation or the closed form",
                kind="text",
                choices=("collocation", "closed-form"),
                default="collocation",
            ),
        ),
        _cmd_slide,
        good=("contact",),
        entries=(
            *_SI_ENTRIES,
            Entry(("h1", "tau0"), "trailing range h1 [m] (or --h1-over-h2); shear strength [Pa]"),
        ),
        api_names={"adhesion_range": "h", "work_of_adhesion": "work_of_adhesion"},
        rows=("a_over_R", "F_over_Eh2", "a", "load"),
    ),
}
