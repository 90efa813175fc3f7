"""The operations of the inverse problems: ``fit-adhesion`` and ``fit-friction``.

Over :mod:`linecontact.inverse`. Data come from a CSV file (``--data``) whose
header names the columns with their units (``radius_m``, ``pull_off_force_N_per_m``, ``sd``
right after a value column for its uncertainty, ...; lines starting with ``#`` are comments;
every column is used or refused; read by :func:`linecontact.measurements.read_measurements`),
or as one measurement on the command line, each value with an optional standard uncertainty
(``--radius 50e-9 --radius-sd 3e-9`` or ``--radius-sd 6%``). The output is one record: the
fitted values, their standard uncertainties, 95 % intervals (two-element lists), the
covariance, and per data point (lists) the residuals and the forward model; what JKR and DMT
alone would have given is beside them.
"""

from __future__ import annotations

import functools
import math
import os
from typing import Any

import numpy as np

from .. import inverse as inv
from ..errors import ParameterError
from ..measurements import per_length
from ..output import Table
from ._common import flags, material_parameters, positive
from ._declare import Entry, Inputs, Operation, Parameter
from ._fit_common import (
    _ESTIMATE,
    _FIT,
    _FIT_DATA,
    _FIT_INPUTS_SD,
    EXACT,
    _check_common,
    _modulus,
    _one_sd,
    _read,
    _record,
    _table,
    _uncertainty,
)
from ._fit_friction import run_friction
from ._written import made

__all__ = ["OPERATIONS"]

_DESCRIPTION = {
    "fit-adhesion": (
        "Work of adhesion w (and the range z0) from measured pull-off forces (negative), "
        "the Maugis-Dugdale line contact the forward model; columns of --data: docs/cli.md."
    ),
    "fit-friction": (
        "Interfacial shear strength tau0 = (f - dw)/(2a) from friction forces f at normal "
        "loads F, a from the Maugis-Dugdale contact; columns of --data: docs/cli.md."
    ),
}
_EXAMPLES = {
    "fit-adhesion": [
        "linecontact fit-adhesion --data pulloff.csv --E1 72e9 --nu1 0.17 --E2 163e9 --nu2 0.22",
        "linecontact fit-adhesion --radius 50e-9 --radius-sd 3e-9 --pull-off-force -3.1 "
        "--pull-off-force-sd 5% --modulus 51.7e9 --z0 0.3e-9",
    ],
    "fit-friction": [
        "linecontact fit-friction --data friction.csv --radius 50e-9 --modulus 51.7e9 "
        "--work-of-adhesion 0.1 --z0 0.3e-9",
        "linecontact fit-friction --load 0.5 --friction-force 0.2 --friction-force-sd "
        "10% --radius 50e-9 --modulus 51.7e9 --work-of-adhesion 0.1 --z0 0.3e-9",
    ],
}


def _cmd_adhesion(args: Inputs) -> Table:
    _check_common(args)
    if args.data is None and args.bootstrap != "auto":
        raise ParameterError("--bootstrap", "--bootstrap is for a joint fit to --data")
    if args.pull_off_force_total is not None and args.pull_off_force_sd is not None:
        raise ParameterError(
            "--pull-off-force-total",
            "with --pull-off-force-total give its uncertainty as --pull-off-force-total-sd",
        )
    E, mat = _modulus(args)
    params: dict[str, Any] = dict(mat)
    positive("--length", args.length)
    if args.data is not None:
        if args.pull_off_force is not None or args.radius is not None:
            raise ParameterError(
                "--data", "give either --data FILE or one measurement (--radius, --pull-off-force)"
            )
        if args.radius_sd is not None:
            raise ParameterError(
                "--radius-sd", "--radius-sd is for one measurement; with --data the radii are exact"
            )
        single = flags(
            args,
            "pull_off_force_sd",
            "pull_off_force_total",
            "pull_off_force_total_sd",
            "half_width",
            "half_width_sd",
            "normal_load",
        )
        if single:
            raise ParameterError(
                single[0],
                f"{', '.join(single)}: for one measurement, not with --data (the uncertainties "
                "of the pull-off forces go into the file: an sd column after them)",
            )
        data = _read(args, "pull-off")
        R, F = data["radius"], data["pull_off_force"]
        sd = data.get("pull_off_force_sd")
        rows = data["line"]
        n = R.size
        if sd is not None:
            weak = (sd < 1e-12 * np.abs(F)) | (sd > 1e6 * np.abs(F))
            if np.any(weak):
                i = int(np.flatnonzero(weak)[0])
                raise ParameterError(
                    "--data",
                    f"--data {args.data!r}, row {int(rows[i])}: the standard uncertainty "
                    f"{float(sd[i])!r} must be between 1e-12 and 1e6 times the force (a weight)",
                )
        boot: Any = args.bootstrap
        if boot != "auto":
            try:
                boot = int(boot)
            except ValueError:
                raise ParameterError(
                    "--bootstrap", f"--bootstrap must be 'auto' or an integer, got {boot!r}"
                ) from None
        E_sd = _one_sd(args, "modulus", E)
        if args.z0 is None and args.z0_sd is not None:
            raise ParameterError("--z0-sd", "--z0-sd needs a fixed --z0 (a joint fit estimates z0)")
        z_sd = _one_sd(args, "z0", args.z0) if args.z0 is not None else 0.0
        # the inputs' uncertainties propagate by refits with them drawn (100, seed + 1)
        fit = made(
            args,
            "result",
            inv.fit_pull_off,
            R,
            F,
            E,
            sd=sd,
            equilibrium_spacing=args.z0,
            bootstrap=boot,
            seed=args.seed,
            modulus_sd=E_sd,
            equilibrium_spacing_sd=z_sd,
            progress=args.progress,  # None: where stderr is a terminal
        )
        z_ref = fit.equilibrium_spacing
        simple = inv.simple_model_work_of_adhesion(R, F, E, z_ref, sd)
        rec: dict[str, Any] = {
            **_record(fit, _FIT),
            "work_of_adhesion_jkr": simple["jkr"],
            "work_of_adhesion_dmt": simple["dmt"],
            **(_record(fit, _FIT_INPUTS_SD) if E_sd or z_sd else {}),
            "radius_m": R.tolist(),
            "pull_off_force_N_per_m": F.tolist(),
            **_record(fit, _FIT_DATA),
        }
        params.update(
            data=os.fspath(args.data),
            n_points=n,
            z0_fixed=args.z0 is not None,
            seed=args.seed,
            model="maugis-dugdale",
        )
        title = f"fit of w{'' if args.z0 is not None else ' and z0'} to {n} pull-off forces"
        hide: tuple[str, ...] = ("z0_sd", "z0_ci95") if args.z0 is not None else ()
        # the figure, drawn by the shell that has a file for it (--plot): the axes in the
        # file's units
        args.drawing = ("draw_adhesion_fit", (fit,), {"units": args.data})
    else:
        rec, title = _adhesion_one(args, E, params)
        hide = ()
        if rec["uncertainty"] == EXACT:  # zero and [w, w] in the JSON: not columns to read
            hide = ("work_of_adhesion_sd", "work_of_adhesion_sd_linear", "work_of_adhesion_ci95")
            hide += ("samples_failed",)
    units = {
        "work_of_adhesion": "J/m^2",
        "work_of_adhesion_sd": "J/m^2",
        "work_of_adhesion_sd_linear": "J/m^2",
        "work_of_adhesion_jkr": "J/m^2",
        "work_of_adhesion_dmt": "J/m^2",
        "z0": "m",
        "z0_sd": "m",
        "chi2": "1",
        "pull_off_force_sd": "N/m",
        "radius_sd": "m",
        "modulus_sd": "Pa",
        "equilibrium_spacing_sd": "m",
        "work_of_adhesion_sd_inputs": "J/m^2",
        "work_of_adhesion_sd_total": "J/m^2",
        "z0_sd_inputs": "m",
        "z0_sd_total": "m",
        "work_of_adhesion_ci95": "J/m^2",
        "work_of_adhesion_ci95_linear": "J/m^2",
        "z0_ci95": "m",
        "z0_ci95_linear": "m",
        "covariance": "J/m^2 and m: [[w w, w z0], [z0 w, z0 z0]]",
    }
    return _table(args, rec, params, title, units, hide)


def _adhesion_one(args, E: float, params: dict[str, Any]):
    """The work of adhesion from one pull-off force (per length or total) or one width."""
    if args.plot:
        raise ParameterError("--plot", "--plot draws a fit to --data")
    if args.radius is None or args.z0 is None:
        raise ParameterError(
            "--data",
            "give --data FILE, or one measurement: --radius, --z0 and --pull-off-force (or "
            "--pull-off-force-total with --length, or --half-width with --load)",
        )
    given = [
        k
        for k in ("pull_off_force", "pull_off_force_total", "half_width")
        if getattr(args, k) is not None
    ]
    if len(given) != 1:
        raise ParameterError(
            "--pull-off-force",
            "give one of --pull-off-force [N/m], --pull-off-force-total [N] (with --length) "
            "or --half-width [m] (with --load)",
        )
    common = {"radius": args.radius, "modulus": E, "equilibrium_spacing": args.z0}
    flags = {"radius": "--radius-sd", "modulus": "--modulus-sd", "equilibrium_spacing": "--z0-sd"}
    flags.update(half_width="--half-width-sd", pull_off_force="--pull-off-force-sd")
    if args.pull_off_force_total is not None:
        flags["pull_off_force"] = "--pull-off-force-total-sd"
    sds = {
        "radius": _one_sd(args, "radius", args.radius),
        "modulus": _one_sd(args, "modulus", E),
        "equilibrium_spacing": _one_sd(args, "z0", args.z0),
    }
    if given == ["half_width"]:
        if args.normal_load is None:
            raise ParameterError(
                "--half-width", "--half-width needs the normal load it was measured at: --load"
            )
        fn: Any = inv.work_of_adhesion_from_width
        values = dict(half_width=args.half_width, normal_load=args.normal_load, **common)
        sds["half_width"] = _one_sd(args, "half_width", args.half_width)
        params.update(half_width_m=args.half_width, normal_load_N_per_m=args.normal_load)
        what = "one contact width"
    else:
        if args.normal_load is not None:
            raise ParameterError(
                "--load", "--load goes with --half-width, not with a pull-off force"
            )
        if given == ["pull_off_force_total"]:
            if args.length is None:
                raise ParameterError(
                    "--pull-off-force-total",
                    "--pull-off-force-total [N] needs the fibre's --length [m]",
                )
            if not math.isfinite(args.pull_off_force_total):
                raise ParameterError(
                    "--pull-off-force-total",
                    "--pull-off-force-total must be a finite number [N], got "
                    f"{args.pull_off_force_total!r}",
                )
            total_sd = _one_sd(args, "pull_off_force_total", args.pull_off_force_total)
            F = per_length(args.pull_off_force_total, args.length, length_name="--length")
            # the force per length the inversion is given, said as the flags that make it
            args.said_as["pull_off_force"] = "--pull-off-force-total / --length"
            F_sd = per_length(total_sd, args.length, length_name="--length")
            params.update(pull_off_force_total_N=args.pull_off_force_total, length_m=args.length)
        else:
            F = args.pull_off_force
            F_sd = _one_sd(args, "pull_off_force", args.pull_off_force)
        fn = inv.work_of_adhesion_from_pull_off
        values = dict(pull_off_force=F, **common)
        sds["pull_off_force"] = F_sd
        params["pull_off_force_N_per_m"] = F
        what = "one pull-off force"
    fn(**values)  # a clear error for a measurement no w can produce
    # nan for a draw that no w reaches: a batch of draws is not split around it
    drawn = functools.partial(fn, on_failure="report")
    est = inv.propagate(drawn, values, sds, n_samples=args.samples, seed=args.seed)
    rec: dict[str, Any] = {
        **_record(est, tuple((k, key.format("work_of_adhesion")) for k, key in _ESTIMATE)),
        "uncertainty": _uncertainty([flags[k] for k, v in sds.items() if v], args.samples),
        "z0": args.z0,
    }
    if "pull_off_force" in values:
        simple = inv.simple_model_work_of_adhesion(
            args.radius, values["pull_off_force"], E, args.z0
        )
        rec.update(work_of_adhesion_jkr=simple["jkr"], work_of_adhesion_dmt=simple["dmt"])
    rec["samples_failed"] = est.n_failed
    params.update(
        radius_m=args.radius,
        z0_m=args.z0,
        samples=args.samples,
        seed=args.seed,
        model="maugis-dugdale",
        **{f"{k}_sd": v for k, v in sds.items() if v},
    )
    return rec, f"work of adhesion from {what}" + (
        "" if rec["uncertainty"] == EXACT else " (Monte Carlo)"
    )


# --------------------------------------------------------------------------------------------
# the declarations

_ONE = "measurements: --data, or one (instead)"
_SI = "the cylinder and the materials (SI)"


def _measured(p: Parameter, its: bool = False) -> tuple[Parameter, Parameter]:
    """A measured value and its standard uncertainty ``<name>_sd`` ([its unit] or N%)."""
    help = f"{'its standard uncertainty ' if its else ''}[{p.unit}] or N%%"
    return p, Parameter(f"{p.name}_sd", help, kind="text", metavar="SD", group=p.group)


def _normal_load(help: str) -> Parameter:
    """The normal load [N/m] of one measurement (``--load``)."""
    return Parameter(
        "normal_load",
        help,
        unit="N/m",
        metavar="F",
        flag="--load",
        aliases=("--normal-load",),
        group=_ONE,
    )


def _half_width(help: str) -> tuple[Parameter, Parameter]:
    """A measured contact half-width [m] and its uncertainty."""
    return _measured(Parameter("half_width", help, unit="m", metavar="A", group=_ONE))


def _parameters(name: str) -> tuple[Parameter, ...]:
    preset = "a preset (linecontact materials)"
    common = (
        Parameter(
            "data",
            "CSV file, a header of columns with units (docs/cli.md)",
            kind="text",
            metavar="FILE",
            group=_ONE,
        ),
        *_measured(Parameter("radius", "radius [m]", unit="m", metavar="R", group=_SI), its=True),
        *_measured(
            Parameter("modulus", "composite modulus [Pa]", unit="Pa", metavar="E", group=_SI),
            its=True,
        ),
        *material_parameters(
            _SI,
            ("cylinder's Young's modulus [Pa]", "cylinder's Poisson ratio"),
            ("substrate's Young's modulus [Pa]", "substrate's Poisson ratio"),
            (preset, preset),
        ),
        *_measured(
            Parameter("z0", "range of adhesion z0 [m] (fixed if given)", unit="m", group=_SI),
            its=True,
        ),
        Parameter(
            "length", "fibre length [m], for forces given in N", unit="m", metavar="L", group=_SI
        ),
    )
    if name == "fit-adhesion":
        force = "pull-off force [N/m], < 0"
        own: tuple[Parameter, ...] = (
            *_measured(Parameter("pull_off_force", force, unit="N/m", metavar="F", group=_ONE)),
            *_measured(
                Parameter(
                    "pull_off_force_total",
                    "pull-off force of the whole fibre [N], < 0, with --length",
                    unit="N",
                    metavar="F",
                    group=_ONE,
                )
            ),
            *_half_width(
                "a measured contact half-width [m] at --load (instead of a pull-off force): w "
                "from the width"
            ),
            _normal_load("normal load [N/m] of --half-width"),
            Parameter(
                "bootstrap",
                "bootstrap refits of a joint fit, or auto (default: %(default)s)",
                kind="text",
                metavar="N",
                default="auto",
            ),
            Parameter(
                "progress",
                "a bar of the refits on stderr (default: where it is a terminal)",
                kind="switch",
                shell_only=True,
            ),
        )
    else:
        own = (
            *_measured(
                Parameter("work_of_adhesion", "w [J/m^2]", unit="J/m^2", metavar="W", group=_SI)
            ),
            Parameter(
                "receding_work_of_adhesion",
                "receding w [J/m^2]: the steady-sliding contact and dw = w1 - w",
                unit="J/m^2",
                metavar="W1",
                flag="--work-of-adhesion-receding",
                aliases=("--receding-work-of-adhesion",),
                group=_SI,
            ),
            _normal_load("normal load [N/m]"),
            *_measured(
                Parameter("friction_force", "[N/m], > 0", unit="N/m", metavar="f", group=_ONE)
            ),
            *_half_width(
                "a measured contact half-width [m]: tau0 = (f - dw)/(2 A), no contact model"
            ),
            Parameter(
                "contact",
                "contact model of the width (default: %(default)s)",
                kind="text",
                choices=("maugis-dugdale", "jkr", "dmt", "hertz"),
                default="maugis-dugdale",
            ),
        )
    tail = (
        Parameter(
            "samples",
            "Monte Carlo samples (default: %(default)s)",
            kind="integer",
            default=4000,
        ),
        Parameter(
            "seed", "seed of the random draws (default: %(default)s)", kind="integer", default=0
        ),
        Parameter(
            "plot",
            "draw the fit into FILE (.png, .svg, .pdf)",
            kind="text",
            metavar="FILE",
            shell_only=True,
        ),
    )
    return (*common, *own, *tail)


def _entries(params: tuple[Parameter, ...]) -> tuple[Entry, ...]:
    """Each value with its uncertainty (and the like) as one entry of the help."""
    names = {p.name for p in params}
    sd = " (sd: [{}] or N%%)"
    out = [
        Entry((name, name + "_sd"), what + sd.format(unit))
        for name, unit, what in (
            ("radius", "m", "radius [m]"),
            ("modulus", "Pa", "composite modulus [Pa]"),
            ("z0", "m", "range of adhesion z0 [m], fixed if given"),
            ("pull_off_force", "N/m", "pull-off force [N/m], < 0"),
            ("pull_off_force_total", "N", "the whole fibre's [N], < 0, with --length"),
            ("half_width", "m", "a measured contact half-width [m]"),
            ("work_of_adhesion", "J/m^2", "w [J/m^2]"),
            ("friction_force", "N/m", "friction force [N/m], > 0"),
        )
        if name in names
    ]
    out += [
        Entry(("E1", "nu1", "E2", "nu2"), "Young's moduli [Pa], Poisson ratios"),
        Entry(("cylinder_material", "substrate_material"), "presets (`linecontact materials`)"),
        Entry(
            ("samples", "seed"),
            "Monte Carlo samples, seed of the draws (default: %(default)s, 0)",
        ),
    ]
    return tuple(out)


def _operation(name: str, summary: str, compute: Any) -> Operation:
    params = _parameters(name)
    return Operation(
        name,
        summary,
        _DESCRIPTION[name],
        tuple(_EXAMPLES[name]),
        params,
        compute,
        entries=_entries(params),
        figures="fit",
    )


OPERATIONS = {
    "fit-adhesion": _operation(
        "fit-adhesion",
        "work of adhesion (and range) from pull-off forces, with uncertainty",
        _cmd_adhesion,
    ),
    "fit-friction": _operation(
        "fit-friction",
        "interfacial shear strength from friction forces, with uncertainty",
        run_friction,
    ),
}
