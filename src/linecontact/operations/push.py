"""The ``push`` operation: a fibre pushed sideways, will it stay, roll or slide.

Over :func:`linecontact.push.push`. The records carry at least ``H_over_R``,
``a_rest_over_R``, ``a_slide_over_R``, ``Q_roll_over_Eh2``, ``Q_slide_over_Eh2``,
``H_critical_over_R``, ``first_motion`` and, with a push given, ``state`` (a contract).
"""

from __future__ import annotations

import warnings
from typing import Any

import numpy as np

from ..cylinder import _check_cylinder_si, _plausible, hysteresis_adhesion
from ..domain import SCALE_WORDS, check_si
from ..errors import ModelValidityWarning, NoEquilibriumError, ParameterError
from ..output import Table
from ..push import push
from ..sliding import sliding_pull_off
from ._common import (
    GROUPS_GROUP,
    SI_GROUP,
    cylinder,
    flags,
    positive,
    si_given,
    si_inputs,
    si_parameters,
    sliding_parameters,
)
from ._declare import Entry, Inputs, Operation, Parameter
from ._records import records, si_shown
from ._written import made

__all__ = ["OPERATIONS"]

_DESCRIPTION = (
    "A fibre pushed sideways at height H above the substrate (docs/push.md): rolling resists "
    "Q_roll = R dw / H, sliding Q_slide = 2 a_slide tau0 + dw; the lower one is the first "
    "motion. With a push Q: the state (rest, roll, slide or roll+slide)."
)


def _cmd_push(args: Inputs) -> Table:
    # --work-of-adhesion-advancing (dest work_of_adhesion) alone: with --z0 and --h1, as
    # --sigma0 --h2; with --work-of-adhesion-receding: the pair (one sigma0, from W1)
    args.work_of_adhesion_advancing = None
    if args.work_of_adhesion_receding is not None:
        args.work_of_adhesion_advancing, args.work_of_adhesion = args.work_of_adhesion, None
    works = (args.work_of_adhesion_receding, args.work_of_adhesion_advancing)
    si = si_given(args, extra=("h1", "tau0", "load", "height", "tip_height", "push")) or any(
        w is not None for w in works
    )
    nd_flags = (args.R_over_h2, args.sigma0_over_E, args.tau0_over_E, args.F_over_Eh2)
    nd = any(v is not None for v in (*nd_flags, args.H_over_R, args.Q_over_Eh2))
    if si and nd:
        raise ParameterError(
            "--R-over-h2",
            "give either the nondimensional groups (--R-over-h2, ...) or SI inputs "
            "(--radius, ...), not both",
        )
    cyl = None
    if not si:
        missing = flags(
            args, "R_over_h2", "h1_over_h2", "sigma0_over_E", "tau0_over_E", "H_over_R", given=False
        )
        if missing:
            raise ParameterError(
                missing[0], f"give {', '.join(missing)} (or SI inputs with --radius)"
            )
        rho, r, s, tau = args.R_over_h2, args.h1_over_h2, args.sigma0_over_E, args.tau0_over_E
        F = 0.0 if args.F_over_Eh2 is None else args.F_over_Eh2
        H = np.asarray(args.H_over_R, float)
        Q = args.Q_over_Eh2
    else:
        if any(w is not None for w in works):
            _works_to_ranges(args)
        _check_receding(args)
        if args.tau0 is None:
            raise ParameterError("--tau0", "give the friction stress --tau0 [Pa]")
        if (args.height is None) == (args.tip_height is None):
            raise ParameterError("--height", "give exactly one of --height or --tip-height [m]")
        if args.tip_height is not None and args.tip_friction is None:
            args.tip_friction = 0.0
        if args.tip_height is None and args.tip_friction is not None:
            raise ParameterError(
                "--tip-friction", "--tip-friction goes with --tip-height (a tip), not --height"
            )
        with warnings.catch_warnings():
            if any(w is not None for w in works):  # said for --z0 and the works already
                warnings.filterwarnings(
                    "ignore", "(adhesion_range|work_of_adhesion) = ", ModelValidityWarning
                )
            cyl = cylinder(args, range_flag="--h2")
        Eh = cyl.scale("Eh")
        if args.h1 is not None:
            check_si("--h1", args.h1, cyl.scale("h"), "h1_over_h2", "m")
        check_si("--tau0", args.tau0, cyl.scale("E"), "tau0_over_E", "Pa")
        tip = args.tip_height is not None
        flag = "--tip-height" if tip else "--height"
        heights = np.asarray(args.tip_height if tip else args.height, float)
        diameter = float(cyl.in_si(2.0, "R"))
        ok = (heights > 0) & (heights < diameter) if tip else (heights >= 0)
        ok &= heights <= diameter
        if not np.all(ok):
            bad = float(heights[~ok][0])
            rng = f"(0, {diameter:g})" if tip else f"[0, {diameter:g}]"
            raise ParameterError(flag, f"{flag} must be in {rng} m (2R), got {bad!r}")
        load = 0.0 if args.load is None else args.load
        check_si("--load", load, Eh, "F_over_Eh2", "N/m")
        if args.push is not None:
            check_si("--push", args.push, Eh, "T_over_Ea", "N/m", SCALE_WORDS["F_over_Eh2"])
        h1 = args.h1 if args.h1 is not None else cyl.in_si(args.h1_over_h2, "h")
        Q = args.push
        pushed: Any = made(
            args,
            "result",
            cyl.push,
            friction_stress=args.tau0,
            height=heights,
            receding_range=h1,
            normal_load=load,
            push=args.push,
            tip_friction=args.tip_friction,
            length=args.length,
        )
        res: Any = pushed.nondimensional
    if cyl is None:
        try:
            res = push(rho, r, s, tau, F, H, Q, tip_friction=args.tip_friction)
        except NoEquilibriumError:  # said with the flags (the pull-off: no flag of its own)
            if s == 0:
                raise NoEquilibriumError(
                    f"no contact carries --F-over-Eh2={F!r} without adhesion (--sigma0-over-E "
                    "0): the load must be > 0"
                ) from None
            F_po = sliding_pull_off(rho, r, s).F_pulloff_over_Eh2
            raise NoEquilibriumError(
                f"no steadily sliding contact carries --F-over-Eh2={F!r}: it is below the "
                f"pull-off force, {F_po:.6g} in the units of --F-over-Eh2; the cylinder has "
                "pulled off"
            ) from None
    show = [
        "H_over_R",
        "a_rest_over_R",
        "a_slide_over_R",
        "Q_roll_over_Eh2",
        "Q_slide_over_Eh2",
        "H_critical_over_R",
        "first_motion",
        "creep_over_V",
    ]
    drop = []
    if args.tip_friction is None:
        drop += ["H_arm_over_R", "tip_friction"]
    else:
        show.insert(1, "H_arm_over_R")
    if Q is None:
        drop += ["Q_over_Eh2", "state", "d_over_a_rest"]
    else:
        show += ["state"]
    params: dict[str, Any] = {}
    extra: dict[str, Any] = {}
    if cyl is not None:
        params.update(si_parameters(args, cyl))
        h1_m, load_N_per_m = (
            cyl.in_si(float(np.reshape(v, -1)[0]), unit)
            for v, unit in ((res.h1_over_h2, "h"), (res.F_over_Eh2, "Eh"))
        )
        params.update(h1_m=h1_m, tau0_Pa=args.tau0, load_N_per_m=load_N_per_m)
        if Q is not None:
            params["push_N_per_m"] = args.push
        for key, name in (
            ("work_of_adhesion_receding", "work_of_adhesion_receding_J_per_m2"),
            ("work_of_adhesion_advancing", "work_of_adhesion_advancing_J_per_m2"),
        ):
            if getattr(args, key) is not None:
                params[name] = getattr(args, key)
        names = {"height": "H_m", "rest_half_width": "a_rest_m"}
        names.update(slide_half_width="a_slide_m", rolling_resistance="Q_roll_N_per_m")
        names.update(sliding_resistance="Q_slide_N_per_m", slip_onset="Q_onset_N_per_m")
        names["critical_height"] = "H_critical_m"
        totals = {"rolling_resistance": "Q_roll_total_N", "sliding_resistance": "Q_slide_total_N"}
        show = ["H_m", "a_slide_m", "Q_roll_N_per_m", "Q_slide_N_per_m", "H_critical_m"]
        if args.tip_friction is not None:
            names["moment_arm"] = "H_arm_m"
            show.insert(1, "H_arm_m")
        show += ["first_motion"] + (["state"] if Q is not None else [])
        cols, show = si_shown(args, pushed, names, totals, show)
        extra.update(cols)
    table = records(
        args,
        res,
        params,
        extra,
        "a fibre pushed sideways: rolling and sliding resistance, first motion",
        show,
        drop=drop,
    )
    return table


def _works_to_ranges(args: Inputs) -> None:
    """The receding and advancing works of adhesion as sigma0, h2 and h1 (one sigma0)."""
    w1, w2 = args.work_of_adhesion_receding, args.work_of_adhesion_advancing
    if any(v is not None for v in (args.sigma0, args.h, args.h1)):
        raise ParameterError(
            "--z0",
            "give adhesion either as the two works of adhesion with --z0, or as --sigma0, "
            "--h2 and --h1, not both",
        )
    missing = [
        flag
        for flag, v in (
            ("--work-of-adhesion-advancing [J/m^2] (W2 <= W1)", w2),
            ("--z0 [m]", args.z0),
        )
        if v is None
    ]
    if missing:  # the receding work is given (else this is not called)
        raise ParameterError(
            "--work-of-adhesion-receding",
            f"--work-of-adhesion-receding (W1) needs {' and '.join(missing)}",
        )
    for flag, v in (
        ("--work-of-adhesion-receding", w1),
        ("--work-of-adhesion-advancing", w2),
        ("--z0", args.z0),
        ("--radius", args.radius),
        ("--modulus", args.modulus),
    ):  # each by itself before they are combined (a radius nan: not a bad ratio)
        positive(flag, v)
    if w2 > w1:
        raise ParameterError(
            "--work-of-adhesion-advancing",
            f"--work-of-adhesion-advancing must be <= --work-of-adhesion-receding (the "
            f"hysteresis is not negative), got {w2!r} > {w1!r}",
        )
    # said for the flags typed (the cylinder is built from sigma0, h2 and h1)
    _plausible("--work-of-adhesion-receding", w1, key="work_of_adhesion")
    _plausible("--work-of-adhesion-advancing", w2, key="work_of_adhesion")
    if args.radius is not None:  # sigma0 is that of the receding work of adhesion
        args.said_as["work_of_adhesion"] = "work_of_adhesion_receding"
        _check_cylinder_si(
            args.radius, args.modulus, {"work_of_adhesion": w1, "equilibrium_spacing": args.z0}
        )
    args.sigma0, args.h, args.h1 = hysteresis_adhesion(w1, w2, args.z0)
    args.z0 = None


def _check_receding(args: Inputs) -> None:
    """The receding side given once; missing, it is asked for in the spelling the user chose.

    The works of adhesion (``--work-of-adhesion-advancing`` with ``--z0``) ask for the
    receding work (or ``--h1``), the ranges (``--sigma0 --h2``) for ``--h1``.
    """
    if args.h1 is not None and args.h1_over_h2 is not None:
        raise ParameterError(
            "--h1", "give the receding range as --h1 [m] or as --h1-over-h2, not both"
        )
    if args.h1 is not None or args.h1_over_h2 is not None:
        return
    if args.work_of_adhesion is not None or args.z0 is not None:
        z0 = " and --z0 [m]" if args.z0 is None else ""
        raise ParameterError(
            "--work-of-adhesion-receding",
            "give the receding work of adhesion --work-of-adhesion-receding [J/m^2] (at least "
            f"--work-of-adhesion-advancing){z0}, or the receding range --h1 [m]",
        )
    if args.sigma0 is not None or args.h is not None:
        raise ParameterError(
            "--h1",
            "give the receding (trailing-edge) range --h1 [m], at least --h2 (or --h1-over-h2)",
        )
    raise ParameterError(
        "--sigma0",
        "give the adhesion: --sigma0 [Pa], --h2 and --h1 [m], or --work-of-adhesion-advancing, "
        "--work-of-adhesion-receding [J/m^2] and --z0 [m]",
    )


# --------------------------------------------------------------------------------------------
# the declaration

_SI, _SI_ENTRIES = si_inputs(range_flag="--h2")
_GROUPS, _SLIDING_SI = sliding_parameters(
    (
        "radius over the advancing range h2",
        "receding over advancing range, in [1, 1000] (1: no hysteresis)",
        "adhesive stress over modulus, >= 0",
        "friction stress over modulus, > 0",
    ),
    ("receding (trailing-edge) adhesion range h1 [m]", "friction stress tau0 [Pa]"),
)
_G, _S = GROUPS_GROUP, SI_GROUP

OPERATIONS = {
    "push": Operation(
        "push",
        "a fibre pushed sideways: stay, roll or slide, and at what push",
        _DESCRIPTION,
        (
            "linecontact push --R-over-h2 100 --h1-over-h2 2 --sigma0-over-E 0.01 "
            "--tau0-over-E 1e-3 --H-over-R 0.25 1 2",
            "linecontact push --radius 50e-9 --modulus 48e9 --sigma0 1e8 --h2 0.3e-9 "
            "--h1 0.6e-9 --tau0 1e6 --height 25e-9 50e-9 100e-9",
        ),
        (
            *_GROUPS,
            Parameter(
                "F_over_Eh2",
                "normal load over E h2 (default 0: adhesion alone)",
                metavar="F",
                group=_G,
            ),
            Parameter(
                "H_over_R",
                "push heights over R, in [0, 2] (1: at the axis)",
                many="several",
                metavar="H",
                group=_G,
            ),
            Parameter("Q_over_Eh2", "a push over E h2: report the state", metavar="Q", group=_G),
            Parameter(
                "tip_friction",
                "a tip pushes at that height, friction coefficient in [0, 10]",
                metavar="MU",
                group=_G,
            ),
            *_SI,
            *_SLIDING_SI,
            Parameter("load", "normal load [N/m] (default 0)", unit="N/m", metavar="F", group=_S),
            Parameter(
                "height",
                "push heights H [m], in [0, 2R]",
                many="several",
                unit="m",
                metavar="H",
                group=_S,
            ),
            Parameter(
                "tip_height",
                "heights [m] where a tip touches the fibre, in (0, 2R) (with --tip-friction, "
                "default 0), instead of --height",
                many="several",
                unit="m",
                metavar="H",
                group=_S,
            ),
            Parameter("push", "a push [N/m]: report the state", unit="N/m", metavar="Q", group=_S),
            Parameter(
                "work_of_adhesion_receding",
                "receding W1 [J/m^2], with the advancing W2 <= W1: one sigma0, from W1",
                unit="J/m^2",
                metavar="W1",
                group=_S,
            ),
        ),
        _cmd_push,
        good=("rest", "roll", "slide", "roll+slide"),
        entries=(
            *_SI_ENTRIES[:3],  # the adhesion in two spellings, each an entry (below)
            Entry(
                ("R_over_h2", "h1_over_h2"), "R/h2; h1/h2 (receding over advancing) in [1, 1000]"
            ),
            Entry(
                ("sigma0_over_E", "tau0_over_E"), "adhesive (>= 0), friction (> 0) stress over E"
            ),
            Entry(
                ("sigma0", "h", "h1"),
                "sigma0 [Pa]; advancing (leading-edge) h2, receding (trailing-edge) h1 >= h2 [m]",
            ),
            Entry(
                ("work_of_adhesion", "work_of_adhesion_receding", "z0"),
                "or the advancing W2 <= receding W1 [J/m^2] and z0 [m] (one sigma0, from W1; or "
                "W2 and z0 with --h1)",
            ),
            Entry(("tau0",), "friction stress tau0 [Pa]"),
            Entry(("load", "push"), "normal load [N/m] (default 0); a push [N/m]: its state"),
            Entry(("height", "tip_height"), "push heights [m] in [0, 2R], or a tip's"),
        ),
        api_names={"adhesion_range": "h", "work_of_adhesion": "work_of_adhesion"},
        rows=("H_over_R", "height", "tip_height"),
    ),
}
