"""The subcommands of the inverse problems: ``fit-adhesion`` and ``fit-friction``.

A thin shell over :mod:`linecontact.inverse`. Data come from a CSV file (``--data``) whose
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

import argparse
import math
import os
from typing import Any

import numpy as np

from .. import inverse as inv
from ..measurements import per_length
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
from ._options import (
    add_command,
    add_output_options,
    deprecated_alias,
    emit,
    show_together,
    write_failure,
)

__all__ = ["register"]

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


def register(sub: Any) -> None:
    """Add ``fit-adhesion`` and ``fit-friction`` to the subparsers ``sub``."""
    for name, summary in (
        ("fit-adhesion", "work of adhesion (and range) from pull-off forces, with uncertainty"),
        ("fit-friction", "interfacial shear strength from friction forces, with uncertainty"),
    ):
        p = add_command(sub, name, summary, _DESCRIPTION[name], _EXAMPLES[name])
        one = p.add_argument_group("measurements: --data, or one (instead)")
        one.add_argument(
            "--data",
            metavar="FILE",
            help="CSV file, a header of columns with units (docs/cli.md)",
        )
        si = p.add_argument_group("the cylinder and the materials (SI)")
        si.add_argument("--radius", type=float, metavar="R", help="radius [m]")
        si.add_argument("--radius-sd", metavar="SD", help="its standard uncertainty [m] or N%%")
        si.add_argument("--modulus", type=float, metavar="E", help="composite modulus [Pa]")
        si.add_argument("--modulus-sd", metavar="SD", help="its standard uncertainty [Pa] or N%%")
        si.add_argument("--E1", type=float, help="cylinder's Young's modulus [Pa]")
        si.add_argument("--nu1", type=float, help="cylinder's Poisson ratio")
        si.add_argument("--E2", type=float, help="substrate's Young's modulus [Pa]")
        si.add_argument("--nu2", type=float, help="substrate's Poisson ratio")
        si.add_argument(
            "--cylinder-material", metavar="NAME", help="a preset (linecontact materials)"
        )
        si.add_argument(
            "--substrate-material", metavar="NAME", help="a preset (linecontact materials)"
        )
        si.add_argument("--z0", type=float, help="range of adhesion z0 [m] (fixed if given)")
        si.add_argument("--z0-sd", metavar="SD", help="its standard uncertainty [m] or N%%")
        si.add_argument(
            "--length", type=float, metavar="L", help="fibre length [m], for forces given in N"
        )
        if name == "fit-adhesion":
            one.add_argument(
                "--pull-off-force", type=float, metavar="F", help="pull-off force [N/m], < 0"
            )
            one.add_argument("--pull-off-force-sd", metavar="SD", help="[N/m] or N%%")
            one.add_argument(
                "--pull-off-force-total",
                type=float,
                metavar="F",
                help="pull-off force of the whole fibre [N], < 0, with --length",
            )
            one.add_argument("--pull-off-force-total-sd", metavar="SD", help="[N] or N%%")
            one.add_argument(
                "--half-width",
                type=float,
                metavar="A",
                help="a measured contact half-width [m] at --load (instead of a "
                "pull-off force): w from the width",
            )
            one.add_argument("--half-width-sd", metavar="SD", help="[m] or N%%")
            one.add_argument(
                "--load",
                dest="normal_load",
                type=float,
                metavar="F",
                help="normal load [N/m] of --half-width",
            )
            p.add_argument(
                "--bootstrap",
                default="auto",
                metavar="N",
                help="bootstrap refits of a joint fit, or auto (default: %(default)s)",
            )
            p.add_argument(
                "--progress",
                action="store_true",
                default=None,
                help="a bar of the refits on stderr (default: where it is a terminal)",
            )
        else:
            si.add_argument("--work-of-adhesion", type=float, metavar="W", help="w [J/m^2]")
            si.add_argument("--work-of-adhesion-sd", metavar="SD", help="[J/m^2] or N%%")
            si.add_argument(
                "--work-of-adhesion-receding",
                dest="receding_work_of_adhesion",
                type=float,
                metavar="W1",
                help="receding w [J/m^2]: the steady-sliding contact and dw = w1 - w",
            )
            one.add_argument(
                "--load", dest="normal_load", type=float, metavar="F", help="normal load [N/m]"
            )
            one.add_argument("--friction-force", type=float, metavar="f", help="[N/m], > 0")
            one.add_argument("--friction-force-sd", metavar="SD", help="[N/m] or N%%")
            one.add_argument(
                "--half-width",
                type=float,
                metavar="A",
                help="a measured contact half-width [m]: tau0 = (f - dw)/(2 A), no contact model",
            )
            one.add_argument("--half-width-sd", metavar="SD", help="[m] or N%%")
            p.add_argument(
                "--contact",
                choices=("maugis-dugdale", "jkr", "dmt", "hertz"),
                default="maugis-dugdale",
                help="contact model of the width (default: %(default)s)",
            )
        p.add_argument(
            "--samples", type=int, default=4000, help="Monte Carlo samples (default: %(default)s)"
        )
        p.add_argument(
            "--seed", type=int, default=0, help="seed of the random draws (default: %(default)s)"
        )
        p.add_argument("--plot", metavar="FILE", help="draw the fit into FILE (.png, .svg, .pdf)")
        add_output_options(p)
        deprecated_alias(p, "--normal-load", "--load", one)
        if name == "fit-friction":
            deprecated_alias(p, "--receding-work-of-adhesion", "--work-of-adhesion-receding", si)
        _show_pairs(p, name)
        p.set_defaults(func=_cmd_adhesion if name == "fit-adhesion" else _cmd_friction)


def _show_pairs(p: argparse.ArgumentParser, name: str) -> None:
    """Each value with its uncertainty (and the like) as one entry of the help."""
    sd = " (sd: [{}] or N%%)"
    for flag, unit, what in (
        ("--radius", "m", "radius [m]"),
        ("--modulus", "Pa", "composite modulus [Pa]"),
        ("--z0", "m", "range of adhesion z0 [m], fixed if given"),
        ("--pull-off-force", "N/m", "pull-off force [N/m], < 0"),
        ("--pull-off-force-total", "N", "the whole fibre's [N], < 0, with --length"),
        ("--half-width", "m", "a measured contact half-width [m]"),
        ("--work-of-adhesion", "J/m^2", "w [J/m^2]"),
        ("--friction-force", "N/m", "friction force [N/m], > 0"),
    ):
        if flag in p._option_string_actions:
            show_together(p, flag, flag + "-sd", help=what + sd.format(unit))
    show_together(p, "--E1", "--nu1", "--E2", "--nu2", help="Young's moduli [Pa], Poisson ratios")
    show_together(
        p, "--cylinder-material", "--substrate-material", help="presets (`linecontact materials`)"
    )
    show_together(
        p,
        "--samples",
        "--seed",
        help="Monte Carlo samples, seed of the draws (default: %(default)s, 0)",
    )


# --------------------------------------------------------------------------------------------
# fit-adhesion


def _cmd_friction(args: argparse.Namespace) -> int:
    """``fit-friction``, registered here; its work is :func:`._fit_friction.run_friction`."""
    return run_friction(args)


def _cmd_adhesion(args: argparse.Namespace) -> int:
    _check_common(args)
    if args.data is None and args.bootstrap != "auto":
        raise ValueError("--bootstrap is for a joint fit to --data")
    if args.pull_off_force_total is not None and args.pull_off_force_sd is not None:
        raise ValueError(
            "with --pull-off-force-total give its uncertainty as --pull-off-force-total-sd"
        )
    E, mat = _modulus(args)
    params: dict[str, Any] = dict(mat)
    if args.length is not None and not (math.isfinite(args.length) and args.length > 0):
        raise ValueError(f"--length must be a finite number > 0, got {args.length!r}")
    if args.data is not None:
        if args.pull_off_force is not None or args.radius is not None:
            raise ValueError(
                "give either --data FILE or one measurement (--radius, --pull-off-force)"
            )
        if args.radius_sd is not None:
            raise ValueError("--radius-sd is for one measurement; with --data the radii are exact")
        single = [
            "--" + k.replace("_", "-")
            for k in (
                "pull_off_force_sd",
                "pull_off_force_total",
                "pull_off_force_total_sd",
                "half_width",
                "half_width_sd",
                "normal_load",
            )
            if getattr(args, k) is not None
        ]
        if single:
            raise ValueError(
                f"{', '.join(single)}: for one measurement, not with --data (the uncertainties "
                "of the pull-off forces go into the file: an sd column after them)"
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
                raise ValueError(
                    f"--data {args.data!r}, row {int(rows[i])}: the standard uncertainty "
                    f"{float(sd[i])!r} must be between 1e-12 and 1e6 times the force (a weight)"
                )
        boot: Any = args.bootstrap
        if boot != "auto":
            try:
                boot = int(boot)
            except ValueError:
                raise ValueError(
                    f"--bootstrap must be 'auto' or an integer, got {boot!r}"
                ) from None
        E_sd = _one_sd(args, "modulus", E)
        if args.z0 is None and args.z0_sd is not None:
            raise ValueError("--z0-sd needs a fixed --z0 (a joint fit estimates z0)")
        z_sd = _one_sd(args, "z0", args.z0) if args.z0 is not None else 0.0
        # the inputs' uncertainties propagate by refits with them drawn (100, seed + 1)
        fit = inv.fit_pull_off(
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
        if args.plot:
            from ..figures.fit import draw_adhesion_fit

            try:
                draw_adhesion_fit(fit, args.plot, units=args.data)  # the axes in the file's units
            except OSError as exc:
                raise write_failure(f"--plot {args.plot!r}", exc) from None
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
    emit(args, _table(args, rec, params, title, units, hide))
    return 0


def _adhesion_one(args, E: float, params: dict[str, Any]):
    """The work of adhesion from one pull-off force (per length or total) or one width."""
    if args.plot:
        raise ValueError("--plot draws a fit to --data")
    if args.radius is None or args.z0 is None:
        raise ValueError(
            "give --data FILE, or one measurement: --radius, --z0 and --pull-off-force (or "
            "--pull-off-force-total with --length, or --half-width with --load)"
        )
    given = [
        k
        for k in ("pull_off_force", "pull_off_force_total", "half_width")
        if getattr(args, k) is not None
    ]
    if len(given) != 1:
        raise ValueError(
            "give one of --pull-off-force [N/m], --pull-off-force-total [N] (with --length) "
            "or --half-width [m] (with --load)"
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
            raise ValueError("--half-width needs the normal load it was measured at: --load")
        fn: Any = inv.work_of_adhesion_from_width
        values = dict(half_width=args.half_width, normal_load=args.normal_load, **common)
        sds["half_width"] = _one_sd(args, "half_width", args.half_width)
        params.update(half_width_m=args.half_width, normal_load_N_per_m=args.normal_load)
        what = "one contact width"
    else:
        if args.normal_load is not None:
            raise ValueError("--load goes with --half-width, not with a pull-off force")
        if given == ["pull_off_force_total"]:
            if args.length is None:
                raise ValueError("--pull-off-force-total [N] needs the fibre's --length [m]")
            if not math.isfinite(args.pull_off_force_total):
                raise ValueError(
                    "--pull-off-force-total must be a finite number [N], got "
                    f"{args.pull_off_force_total!r}"
                )
            total_sd = _one_sd(args, "pull_off_force_total", args.pull_off_force_total)
            F = per_length(args.pull_off_force_total, args.length, length_name="--length")
            # the force per length the inversion is given, said as the flags that make it
            args._api_flags = {
                **getattr(args, "_api_flags", {}),
                "pull_off_force": "--pull-off-force-total / --length",
            }
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
    est = inv.propagate(fn, values, sds, n_samples=args.samples, seed=args.seed)
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
