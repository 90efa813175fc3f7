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
from ..measurements import per_length, read_measurements
from ..output import Table
from ._options import (
    add_command,
    add_output_options,
    command_line,
    deprecated_alias,
    emit,
    show_together,
    si_parameters,
    write_failure,
)
from ._options import cylinder as _cylinder

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


#: The largest shear strength [Pa] a measured width may give: a thousand times the stiffest
#: modulus there is (beyond, the inputs are in other units, and the draws would overflow).
_TAU_MAX = 1e15


def _sd(text: str) -> tuple[float, bool]:
    """A standard uncertainty: a number, or a percentage of the value (``5%``)."""
    t = text.strip()
    rel = t.endswith("%")
    body = t[:-1] if rel else t
    if "%" in body or "_" in body:
        raise ValueError(text)
    v = float(body)
    return (v / 100 if rel else v), rel


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
# the modulus


def _check_common(args: argparse.Namespace) -> None:
    """--samples, --seed and --plot, before any work."""
    if not 10 <= args.samples <= 1_000_000:
        raise ValueError(f"--samples must be an integer in [10, 1000000], got {args.samples}")
    if args.seed < 0:
        raise ValueError(f"--seed must be an integer >= 0, got {args.seed}")
    if args.plot:
        parent = os.path.dirname(os.path.abspath(args.plot))
        if not os.path.isdir(parent):
            raise ValueError(f"--plot {args.plot!r}: the directory {parent!r} does not exist")


def _modulus(args: argparse.Namespace) -> tuple[float, dict[str, Any]]:
    """The composite modulus [Pa] from --modulus, the moduli or the presets, and its record."""
    if args.modulus is not None:
        if any(getattr(args, k) is not None for k in ("E1", "nu1", "E2", "nu2")) or (
            args.cylinder_material or args.substrate_material
        ):
            raise ValueError(
                "give either --modulus or the materials (--E1 ... or presets), not both"
            )
        if not (math.isfinite(args.modulus) and args.modulus > 0):
            raise ValueError(f"--modulus must be a finite number > 0, got {args.modulus!r}")
        return args.modulus, {"modulus_Pa": args.modulus}
    # the SI layer's reader of the materials and presets (a radius and a range of its own,
    # unused: the radius given is checked where it is used, with the adhesion given)
    ns = argparse.Namespace(**vars(args))
    ns.radius = 1e-7
    ns.h, ns.sigma0, ns.work_of_adhesion, ns.z0, ns.length = 1e-9, None, None, None, None
    cyl = _cylinder(ns)
    # the moduli as used, with the presets' names and sources (a preset never hides them)
    keep = ("modulus_Pa", "E1_Pa", "nu1", "E2_Pa", "nu2", "dundurs_beta")
    rec = {
        k: v
        for k, v in si_parameters(ns, cyl).items()
        if k in keep or k.endswith(("_material", "_source"))
    }
    return cyl.modulus, rec


def _read(args: argparse.Namespace, kind: Any) -> dict[str, np.ndarray]:
    """The measurements of ``--data`` (:func:`linecontact.measurements.read_measurements`)."""
    return read_measurements(
        args.data, kind, length=args.length, source=f"--data {args.data!r}", length_name="--length"
    )


def _one_sd(args, name: str, value: float | None) -> float:
    text = getattr(args, name + "_sd", None)
    if text is None:
        return 0.0
    flag = "--" + name.replace("_", "-") + "-sd"
    try:
        v, rel = _sd(text)
    except ValueError:
        raise ValueError(f"{flag} must be a number or a percentage (5%), got {text!r}") from None
    if not (math.isfinite(v) and v >= 0):
        raise ValueError(f"{flag} must be finite and >= 0, got {text!r}")
    if value is None:
        raise ValueError(f"{flag} needs --{name.replace('_', '-')}")
    if not math.isfinite(value):  # the value's fault, not its uncertainty's
        raise ValueError(f"--{name.replace('_', '-')} must be a finite number, got {value!r}")
    sd = abs(value) * v if rel else v
    # the Monte Carlo draws around the value: an uncertainty as large as the value itself
    # draws as many non-physical values as physical ones (and 1e300 overflows)
    if not sd <= abs(value):
        raise ValueError(
            f"{flag} must be at most the value itself ({abs(value)!r}, 100%): a larger standard "
            f"uncertainty leaves no physical value to draw, got {text!r}"
        )
    return sd


def _record(result: Any, keys: tuple[tuple[str, str], ...]) -> dict[str, Any]:
    """The fields (and derived properties) of a fit's result under their JSON keys."""
    d = {**result.to_dict(), **{k: getattr(result, k) for k in type(result).derived}}
    return {key: list(d[k]) if isinstance(d[k], tuple) else d[k] for k, key in keys}


#: The JSON keys of an AdhesionFit's fields, in the output's order.
_FIT = (
    ("work_of_adhesion", "work_of_adhesion"),
    ("work_of_adhesion_sd", "work_of_adhesion_sd"),
    ("work_of_adhesion_ci95", "work_of_adhesion_ci95"),
    ("work_of_adhesion_ci95_linear", "work_of_adhesion_ci95_linear"),
    ("equilibrium_spacing", "z0"),
    ("equilibrium_spacing_sd", "z0_sd"),
    ("equilibrium_spacing_ci95", "z0_ci95"),
    ("equilibrium_spacing_ci95_linear", "z0_ci95_linear"),
    ("correlation", "correlation"),
    ("covariance", "covariance"),
    ("identifiable", "identifiable"),
    ("note", "note"),
    ("chi2", "chi2"),
    ("dof", "dof"),
)
_FIT_INPUTS_SD = (
    ("work_of_adhesion_sd_inputs", "work_of_adhesion_sd_inputs"),
    ("equilibrium_spacing_sd_inputs", "z0_sd_inputs"),
    ("work_of_adhesion_sd_total", "work_of_adhesion_sd_total"),
    ("equilibrium_spacing_sd_total", "z0_sd_total"),
)
_FIT_DATA = (("model", "model_N_per_m"), ("residuals", "residuals_N_per_m"))
#: An Estimate's fields, ``{}`` the quantity's JSON name.
_ESTIMATE = (
    ("value", "{}"),
    ("sd", "{}_sd"),
    ("ci95", "{}_ci95"),
    ("sd_linear", "{}_sd_linear"),
    ("ci95_linear", "{}_ci95_linear"),
)


#: What a fit of one measurement with no standard uncertainty given says of its uncertainty.
EXACT = "exact (one measurement, no uncertainty given)"


class _Interval(list):
    """A 95 % interval ``[lo, hi]``: the table prints it at six digits, JSON and CSV in full."""

    def __str__(self) -> str:
        return "[" + ", ".join("-" if x is None else f"{x:.6g}" for x in self) + "]"


def _table(
    args,
    record: dict[str, Any],
    params: dict[str, Any],
    title: str,
    units,
    hide: tuple[str, ...] = (),
) -> Table:
    """One record as a table: its numbers and its 95 % intervals shown (not those in ``hide``).

    The per-point lists and the linearised intervals are in the JSON and CSV only.
    """
    cols = {}
    show = []
    for k, v in record.items():
        if isinstance(v, (list, tuple, np.ndarray)):
            arr = np.empty(1, dtype=object)
            items = [
                None if (isinstance(x, float) and not math.isfinite(x)) else x
                for x in np.asarray(v, dtype=object).tolist()
            ]
            interval = "_ci95" in k and "linear" not in k and "per_point" not in k
            arr[0] = _Interval(items) if interval else items
            cols[k] = arr
            if interval and k not in hide:
                show.append(k)
        else:
            cols[k] = np.asarray([v])
            if k not in hide:
                show.append(k)
    return Table(cols, params, units, command_line(args), title, show=tuple(show))


# --------------------------------------------------------------------------------------------
# fit-adhesion


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


def _uncertainty(given: list[str], samples: int) -> str:
    """Where the uncertainty of one measurement comes from: the sds ``given`` (flags), or none."""
    if not given:
        return EXACT
    return f"propagated from {', '.join(given)} (Monte Carlo, {samples} samples)"


# --------------------------------------------------------------------------------------------
# fit-friction


def _friction_from_width(args: argparse.Namespace) -> int:
    """tau0 = (f - dw)/(2 a) from one friction force and one measured half-width (no model)."""
    if args.data is not None:
        raise ValueError("--half-width is one measured width: give it without --data")
    if args.friction_force is None:
        raise ValueError("--half-width needs the friction force measured with it: --friction-force")
    if not (math.isfinite(args.friction_force) and args.friction_force > 0):
        raise ValueError(
            f"--friction-force must be a finite number > 0, got {args.friction_force!r}"
        )
    if not (math.isfinite(args.half_width) and args.half_width > 0):
        raise ValueError(f"--half-width must be a finite number > 0, got {args.half_width!r}")
    if args.receding_work_of_adhesion is not None and args.work_of_adhesion is None:
        raise ValueError("--work-of-adhesion-receding needs the advancing --work-of-adhesion")
    model = [
        f
        for f, v in (
            ("--radius", args.radius),
            ("--modulus", args.modulus),
            ("--E1", args.E1),
            ("--E2", args.E2),
            ("--z0", args.z0),
            ("--cylinder-material", args.cylinder_material),
            ("--substrate-material", args.substrate_material),
        )
        if v is not None
    ] + (["--contact"] if args.contact != "maugis-dugdale" else [])
    if model:
        raise ValueError(
            f"{', '.join(model)}: not used with --half-width (a measured width needs no contact "
            "model)"
        )
    if (
        args.receding_work_of_adhesion is not None
        and args.receding_work_of_adhesion < args.work_of_adhesion
    ):
        raise ValueError(
            "--work-of-adhesion-receding must be at least --work-of-adhesion (the hysteresis "
            "is not negative)"
        )
    dw = (
        args.receding_work_of_adhesion - args.work_of_adhesion
        if args.receding_work_of_adhesion is not None
        else 0.0
    )
    values = dict(friction_force=args.friction_force, half_width=args.half_width)
    tau = (args.friction_force - dw) / (2 * args.half_width)
    if not tau <= _TAU_MAX:  # drawing around it would overflow; no material is that strong
        raise ValueError(
            f"--friction-force {args.friction_force!r} N/m over --half-width "
            f"{args.half_width!r} m gives a shear strength of {tau:.3g} Pa, beyond any "
            f"material (above {_TAU_MAX:g} Pa): are they in N/m and m?"
        )
    sds = dict(
        friction_force=_one_sd(args, "friction_force", args.friction_force),
        half_width=_one_sd(args, "half_width", args.half_width),
    )
    est = inv.propagate(
        lambda friction_force, half_width: (friction_force - dw) / (2 * half_width),
        values,
        sds,
        n_samples=args.samples,
        seed=args.seed,
    )
    if est.value <= 0:
        raise ValueError(
            f"--friction-force {args.friction_force!r} N/m does not exceed the adhesion "
            f"hysteresis {dw:.6g} J/m^2: no positive shear strength"
        )
    given = [f"--{k.replace('_', '-')}-sd" for k, v in sds.items() if v]
    rec = {
        **_record(est, tuple((k, key.format("tau0") + "_Pa") for k, key in _ESTIMATE[:4])),
        "uncertainty": _uncertainty(given, args.samples),
        "half_width_m": args.half_width,
    }
    hide = ("tau0_sd_Pa", "tau0_ci95_Pa", "tau0_sd_linear_Pa") if not given else ()
    params: dict[str, Any] = dict(
        friction_force_N_per_m=args.friction_force,
        half_width_m=args.half_width,
        hysteresis_J_per_m2=dw,
        contact="measured width",
        samples=args.samples,
        seed=args.seed,
    )
    title = "interfacial shear strength from a measured contact width"
    emit(args, _table(args, rec, params, title, {"tau0_ci95_Pa": "Pa"}, hide))
    return 0


def _cmd_friction(args: argparse.Namespace) -> int:
    _check_common(args)
    if args.half_width is not None:
        return _friction_from_width(args)
    if args.data is not None and args.friction_force_sd is not None:
        raise ValueError(
            "--friction-force-sd is for one measurement: with --data give the uncertainties "
            "in the file, an sd column right after the friction forces"
        )
    E, mat = _modulus(args)
    params: dict[str, Any] = dict(mat)
    if args.radius is None or args.work_of_adhesion is None or args.z0 is None:
        raise ValueError(
            "the contact width needs the cylinder: give --radius, --work-of-adhesion and --z0 "
            "(with the modulus or the materials)"
        )
    if args.length is not None and not (math.isfinite(args.length) and args.length > 0):
        raise ValueError(f"--length must be a finite number > 0, got {args.length!r}")
    if args.data is not None:
        if args.friction_force is not None or args.normal_load is not None:
            raise ValueError("give either --data FILE or one measurement (--load, ...)")
        data = _read(args, "friction")
        F, f = data["normal_load"], data["friction_force"]
        f_sd = data.get("friction_force_sd", np.zeros_like(f))
        lines = data["line"]
        n = F.size
    else:
        if args.friction_force is None or args.normal_load is None:
            raise ValueError("give --data FILE, or one measurement: --load and --friction-force")
        F, f = np.array([args.normal_load]), np.array([args.friction_force])
        lines = np.array([0])
        f_sd = np.array([_one_sd(args, "friction_force", args.friction_force)])
        n = 1
    w_sd = _one_sd(args, "work_of_adhesion", args.work_of_adhesion)
    R_sd = _one_sd(args, "radius", args.radius)
    E_sd = _one_sd(args, "modulus", E)
    z_sd = _one_sd(args, "z0", args.z0)
    common = dict(
        radius=args.radius,
        modulus=E,
        work_of_adhesion=args.work_of_adhesion,
        equilibrium_spacing=args.z0,
    )

    def tau_fn(contact, **kw):
        def fn(friction_force, normal_load, radius, modulus, work_of_adhesion, equilibrium_spacing):
            return inv.shear_strength_from_friction(
                friction_force,
                normal_load,
                radius,
                modulus,
                work_of_adhesion,
                equilibrium_spacing,
                contact=contact,
                **kw,
            )

        return fn

    kw = {}
    if args.receding_work_of_adhesion is not None:
        kw["receding_work_of_adhesion"] = args.receding_work_of_adhesion
    fn = tau_fn(args.contact, **kw)
    try:
        tau = np.asarray(fn(f, F, **common), float)
    except ValueError as exc:
        if args.data is None:
            raise
        for i in range(n):  # name the row that fails
            try:
                fn(f[i], F[i], **common)
            except ValueError as one:
                raise ValueError(f"--data {args.data!r}, row {int(lines[i])}: {one}") from None
        raise exc
    ests = [
        inv.propagate(
            fn,
            dict(friction_force=f[i], normal_load=F[i], **common),
            dict(
                friction_force=f_sd[i],
                radius=R_sd,
                modulus=E_sd,
                work_of_adhesion=w_sd,
                equilibrium_spacing=z_sd,
            ),
            n_samples=args.samples,
            seed=args.seed + i,
        )
        for i in range(n)
    ]
    sd = np.array([e.sd for e in ests])
    combined = inv.fit_shear_strength(
        fn,
        f,
        F,
        f_sd,
        common,
        dict(radius=R_sd, modulus=E_sd, work_of_adhesion=w_sd, equilibrium_spacing=z_sd),
        args.samples,
        args.seed,
    )
    others: dict[str, list[float]] = {}
    for c in ("jkr", "dmt", "hertz"):  # point by point: a model may have no contact at one
        others[c] = []
        for i in range(n):
            try:
                others[c].append(float(tau_fn(c)(f[i], F[i], **common)))
            except ValueError:
                others[c].append(math.nan)
    rec: dict[str, Any] = {
        **_record(
            combined,
            (
                ("tau0", "tau0_Pa"),
                ("tau0_sd", "tau0_sd_Pa"),
                ("tau0_ci95", "tau0_ci95_Pa"),
                ("birge_ratio", "birge_ratio"),
            ),
        ),
        "uncertainty": _friction_uncertainty(args, f_sd, n, (R_sd, E_sd, w_sd, z_sd)),
        "n_points": n,
        "normal_load_N_per_m": F.tolist(),
        "friction_force_N_per_m": f.tolist(),
        "tau0_per_point_Pa": tau.tolist(),
        "tau0_per_point_sd_Pa": sd.tolist(),
        "tau0_per_point_ci95_Pa": [list(e.ci95) for e in ests],
        "tau0_jkr_Pa": others["jkr"],
        "tau0_dmt_Pa": others["dmt"],
        "tau0_hertz_Pa": others["hertz"],
    }
    params.update(
        radius_m=args.radius,
        work_of_adhesion_J_per_m2=args.work_of_adhesion,
        z0_m=args.z0,
        contact=args.contact,
        samples=args.samples,
        seed=args.seed,
    )
    if args.data is not None:
        params["data"] = os.fspath(args.data)
    if args.receding_work_of_adhesion is not None:
        params["receding_work_of_adhesion_J_per_m2"] = args.receding_work_of_adhesion
    if args.plot:
        from ..figures.fit import draw_friction_fit

        try:
            draw_friction_fit(
                F,
                f,
                tau,
                np.array([e.ci95 for e in ests]),
                {k.upper() if k != "hertz" else "Hertz": np.asarray(v) for k, v in others.items()},
                args.plot,
                friction_sd=f_sd,
                combined=(combined.tau0, combined.tau0_ci95),
            )
        except OSError as exc:
            raise write_failure(f"--plot {args.plot!r}", exc) from None
    units = {"n_points": "1", "birge_ratio": "1", "tau0_per_point_ci95_Pa": "Pa"}
    hide = ("tau0_sd_Pa", "tau0_ci95_Pa", "birge_ratio") if rec["uncertainty"] == EXACT else ()
    emit(
        args,
        _table(
            args,
            rec,
            params,
            f"interfacial shear strength from {n} friction force(s) ({args.contact} contact)",
            units,
            hide,
        ),
    )
    return 0


def _friction_uncertainty(args, f_sd: np.ndarray, n: int, shared: tuple[float, ...]) -> str:
    """Where the uncertainty of a fitted tau0 comes from: the sds given, the scatter, or none."""
    given = [
        flag
        for flag, v in (
            ("--friction-force-sd" if args.data is None else "the friction forces' sd", f_sd),
            ("--radius-sd", shared[0]),
            ("--modulus-sd", shared[1]),
            ("--work-of-adhesion-sd", shared[2]),
            ("--z0-sd", shared[3]),
        )
        if np.any(np.asarray(v) > 0)
    ]
    if given:
        return _uncertainty(given, args.samples)
    if n < 2:
        return EXACT
    return f"the scatter of the {n} points (no uncertainty given): Student's t"
