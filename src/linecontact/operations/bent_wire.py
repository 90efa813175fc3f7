"""The operation ``fit-bent-wire``: friction per unit length from a bent wire's profile.

Over :func:`linecontact.bent_wire.fit_bent_wire` (the fit, with its covariance and
bootstrap intervals), :func:`linecontact.bent_wire.bending_stiffness` (EI from the
cross-section) and :func:`linecontact.inverse.shear_strength_from_bent_wire` (tau0 with
the contact width, where the interface is given). The profile is a CSV of ``x_<unit>,
y_<unit>`` (``x_nm,y_nm``), the points in order from one end of the wire to the other
(:func:`linecontact.measurements.read_measurements`, kind ``"profile"``).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .. import inverse as inv
from ..bent_wire import MODELS, bending_stiffness, bending_stiffness_sd, fit_bent_wire
from ..cylinder import Cylinder
from ..errors import ParameterError
from ..geometry import NAMED_SIDES, cross_section
from ..materials import composite_modulus
from ..measurements import read_measurements
from ..output import Table
from ..presets import Material
from ._common import positive
from ._declare import Entry, Inputs, Operation, Parameter
from ._fit_common import _Interval, _one_sd

__all__ = ["OPERATIONS"]

_PROFILE = "the profile"
_WIRE = "the wire (its bending stiffness EI)"
_CONTACT = "the contact, for tau0 = f/(2a) (optional)"

#: What the API's names of parameters are on the command line.
_FLAGS = {
    "height": "--push-height",
    "receding_work_of_adhesion": "--work-of-adhesion-receding",
    "x": "--data",
    "y": "--data",
    "noise": "--noise",
    "bootstrap": "--bootstrap",
    "seed": "--seed",
    "model": "--model",
    "modulus": "--modulus",
    "radius": "--radius",
    "inner_radius": "--inner-radius",
    "corner_radius": "--corner-radius",
    "cross_section": "--cross-section",
    "work_of_adhesion": "--work-of-adhesion",
    "equilibrium_spacing": "--z0",
    "contact_modulus": "--contact-modulus",
    "normal_load": "--load",
}


#: The Young's moduli of wires there are [Pa] (a soft gel to beyond diamond's 1.2e12).
_MODULI = (1e2, 1e13)
#: The radii of wires there are [m] (a single-walled nanotube's few angstroms to a mm fibre).
_RADII = (1e-10, 1e-3)


def _flagged(exc: ParameterError) -> ParameterError:
    """The library's refusal, naming the flag of the parameter it names."""
    flag = _FLAGS.get(exc.parameter, exc.parameter)
    message = str(exc)
    if exc.parameter in _FLAGS and not message.startswith(flag):
        message = f"{flag}: {message}"
    return ParameterError(flag, message)


def _plausible(
    flag: str,
    value: float,
    bounds: tuple[float, float],
    unit: str,
    what: str,
    notes: tuple[str, str] = ("", ""),
) -> None:
    """Refuse a value that is not positive or lies outside ``bounds`` (in another unit?).

    ``notes`` follow the lower and the upper bound in the message (what lies there).
    """
    positive(flag, value)
    if not bounds[0] <= value <= bounds[1]:
        raise ParameterError(
            flag,
            f"{flag} {value!r} {unit} is no {what} (from {bounds[0]:g} {unit}{notes[0]} to "
            f"{bounds[1]:g} {unit}{notes[1]}): is it in {unit}?",
        )


def _wire_modulus(args: Inputs) -> tuple[float, float | None, dict[str, Any]]:
    """The wire's Young's modulus [Pa], its Poisson ratio where known, and their record."""
    if args.modulus is not None and args.cylinder_material is not None:
        raise ParameterError(
            "--modulus", "give either --modulus or --cylinder-material (a preset), not both"
        )
    if args.cylinder_material is not None:
        try:
            m = Material.from_name(args.cylinder_material)
        except ValueError as exc:
            raise ParameterError("--cylinder-material", str(exc)) from None
        nu = m.nu if args.nu1 is None else args.nu1
        rec = {"cylinder_material": m.name, "modulus_Pa": m.E, "cylinder_source": m.source}
        return m.E, nu, rec
    if args.modulus is None:
        raise ParameterError(
            "--modulus",
            "the bending stiffness needs the wire's Young's modulus: --modulus [Pa] or "
            "--cylinder-material",
        )
    _plausible(
        "--modulus",
        args.modulus,
        _MODULI,
        "Pa",
        "Young's modulus of a wire",
        (", a gel,", ", beyond diamond"),
    )
    return args.modulus, args.nu1, {"modulus_Pa": args.modulus}


def _contact_modulus(args: Inputs, E1: float, nu1: float | None) -> tuple[float, dict[str, Any]]:
    """The composite modulus of the wire on its substrate [Pa], and its record."""
    if args.contact_modulus is not None:
        if args.substrate_material is not None or args.E2 is not None:
            raise ParameterError(
                "--contact-modulus",
                "give either --contact-modulus or the substrate (--E2 --nu2 or "
                "--substrate-material), not both",
            )
        positive("--contact-modulus", args.contact_modulus)
        return args.contact_modulus, {"contact_modulus_Pa": args.contact_modulus}
    if args.substrate_material is not None:
        try:
            s = Material.from_name(args.substrate_material)
        except ValueError as exc:
            raise ParameterError("--substrate-material", str(exc)) from None
        E2, nu2, rec = s.E, s.nu, {"substrate_material": s.name, "substrate_source": s.source}
    elif args.E2 is not None and args.nu2 is not None:
        E2, nu2, rec = args.E2, args.nu2, {}
    else:
        raise ParameterError(
            "--contact-modulus",
            "tau0 needs the contact's modulus: --contact-modulus [Pa], or the substrate "
            "(--substrate-material, or --E2 and --nu2) with the wire's --nu1",
        )
    if nu1 is None:
        raise ParameterError(
            "--nu1", "the composite modulus needs the wire's Poisson ratio: --nu1 (or a preset)"
        )
    try:
        E = float(composite_modulus(E1, nu1, E2, nu2))
    except ValueError as exc:
        raise ParameterError("--nu1", str(exc)) from None
    return E, {**rec, "E2_Pa": E2, "nu1": nu1, "nu2": nu2, "contact_modulus_Pa": E}


def _run(args: Inputs) -> Table:
    if args.data is None:
        raise ParameterError("--data", "give the profile: --data FILE (a CSV of x_nm,y_nm)")
    if args.radius is None:
        raise ParameterError("--radius", "the bending stiffness needs the wire's --radius [m]")
    _plausible("--radius", args.radius, _RADII, "m", "wire's radius")
    positive("--noise", args.noise)
    E1, nu1, mat = _wire_modulus(args)
    shape: Any = None
    if (args.cross_section or "round") != "round":
        try:
            shape = cross_section(args.cross_section, args.corner_radius)
        except ParameterError as exc:
            raise _flagged(exc) from None
    elif args.corner_radius is not None:
        raise ParameterError("--corner-radius", "--corner-radius is a polygon's (--cross-section)")
    inner = 0.0 if args.inner_radius is None else args.inner_radius
    R_sd = _one_sd(args, "radius", args.radius)
    E_sd = _one_sd(args, "modulus", E1)
    kw: dict[str, Any] = dict(inner_radius=inner)
    if shape is not None:
        kw["cross_section"] = shape
    if not 10 <= args.samples <= 1_000_000:
        raise ParameterError(
            "--samples", f"--samples must be an integer in [10, 1000000], got {args.samples}"
        )
    try:
        with np.errstate(over="ignore", invalid="ignore", under="ignore"):  # refused below
            EI = float(bending_stiffness(E1, args.radius, **kw))
            EI_sd = bending_stiffness_sd(E1, args.radius, **kw, modulus_sd=E_sd, radius_sd=R_sd)
        if not (math.isfinite(EI) and math.isfinite(EI_sd) and EI > 0):
            raise ParameterError(
                "--radius",
                f"--radius {args.radius!r} m and --modulus {E1!r} Pa give no bending stiffness "
                "(zero or not finite): are they in m and Pa?",
            )
    except ParameterError as exc:
        raise _flagged(exc) from None
    try:
        data = read_measurements(args.data, "profile", source=f"--data {args.data!r}")
    except ParameterError:
        raise
    except ValueError as exc:
        raise ParameterError("--data", str(exc)) from None
    try:
        fit = fit_bent_wire(
            data["x"],
            data["y"],
            EI,
            bending_stiffness_sd=EI_sd,
            noise=args.noise,
            bootstrap=args.bootstrap,
            seed=args.seed,
            model=args.model,
        )
    except ParameterError as exc:
        raise _flagged(exc) from None
    params: dict[str, Any] = dict(
        model=args.model,
        radius_m=args.radius,
        **mat,
        cross_section=args.cross_section or "round",
        bending_stiffness_N_m2=EI,
        bending_stiffness_sd_N_m2=EI_sd,
        bootstrap=args.bootstrap,
        seed=args.seed,
    )
    if inner:
        params["inner_radius_m"] = inner
    rec: dict[str, Any] = {
        "friction_per_length_N_per_m": fit.friction_per_length,
        "friction_per_length_sd_N_per_m": fit.friction_per_length_sd,
        "friction_per_length_ci95_N_per_m": _Interval(fit.friction_per_length_ci95),
        "friction_per_length_bootstrap_sd_N_per_m": fit.friction_per_length_bootstrap_sd,
        "friction_per_length_bootstrap_ci95_N_per_m": _Interval(
            fit.friction_per_length_bootstrap_ci95
        ),
        "friction_group": fit.friction_group,
        "friction_group_sd": fit.friction_group_sd,
        "half_length_m": fit.half_length,
        "half_length_sd_m": fit.half_length_sd,
        "noise_m": fit.noise,
        "noise_estimated_m": fit.noise_estimated,
        "points": fit.points,
        "dof": fit.dof,
        "determined": fit.determined,
    }
    contact = [args.work_of_adhesion, args.z0]
    if any(v is not None for v in contact) or args.contact_modulus or args.substrate_material:
        if args.work_of_adhesion is None or args.z0 is None:
            raise ParameterError(
                "--work-of-adhesion",
                "tau0 needs the interface: --work-of-adhesion and --z0 (and the substrate)",
            )
        Ec, crec = _contact_modulus(args, E1, nu1)
        params.update(crec)
        params.update(work_of_adhesion_J_per_m2=args.work_of_adhesion, z0_m=args.z0)
        sds: dict[str, Any] = dict(
            radius_sd=R_sd,
            modulus_sd=E_sd,
            work_of_adhesion_sd=_one_sd(args, "work_of_adhesion", args.work_of_adhesion),
            equilibrium_spacing_sd=_one_sd(args, "z0", args.z0),
        )
        load = 0.0 if args.normal_load is None else args.normal_load
        try:
            tau = inv.shear_strength_from_bent_wire(
                fit,
                args.radius,
                E1,
                Ec,
                args.work_of_adhesion,
                args.z0,
                normal_load=load,
                **kw,
                **sds,
                n_samples=args.samples,
                seed=args.seed,
            )
        except ParameterError as exc:
            raise _flagged(exc) from None
        except ValueError as exc:
            raise ParameterError("--work-of-adhesion", str(exc)) from None
        if args.push_height is not None:
            rec.update(_push(args, shape, Ec, tau.value, load))
        rec.update(
            tau0_Pa=tau.value,
            tau0_sd_Pa=tau.sd,
            tau0_ci95_Pa=_Interval(tau.ci95),
            contact_half_width_m=fit.friction_per_length / (2 * tau.value),
        )
        params.update(normal_load_N_per_m=load, samples=args.samples)
    else:
        if args.push_height is not None or args.work_of_adhesion_receding is not None:
            flag = (
                "--push-height" if args.push_height is not None else "--work-of-adhesion-receding"
            )
            raise ParameterError(
                flag,
                f"{flag}: the push needs tau0: give --work-of-adhesion, --z0 and the substrate",
            )
        rec.update(tau0_Pa=None, tau0_sd_Pa=None, tau0_ci95_Pa=None, contact_half_width_m=None)
    rec.update(
        midpoint_m=list(fit.midpoint),
        axis_angle=fit.axis_angle,
        drag_angle=fit.drag_angle,
        note=fit.note
        or (
            ""
            if rec["tau0_Pa"] is not None
            else "tau0 needs the interface: give --work-of-adhesion, --z0 and the substrate"
        ),
        x_m=fit.x.tolist(),
        y_m=fit.y.tolist(),
        residuals_m=fit.residuals.tolist(),
        arc_length_m=fit.arc_length.tolist(),
        curve_x_m=fit.curve_x.tolist(),
        curve_y_m=fit.curve_y.tolist(),
    )
    if args.model == "held":
        rec.update(
            modes=fit.modes,
            normal_friction_largest_N_per_m=fit.normal_friction_largest,
            curve_arc_length_m=np.linspace(-fit.half_length, fit.half_length, 401).tolist(),
            normal_friction_N_per_m=fit.normal_friction.tolist(),
            normal_friction_sd_N_per_m=fit.normal_friction_sd.tolist(),
        )
    args.drawing = ("bent_wire_fit", (fit,), {})
    return _table(args, rec, params)


#: The table's title of each model.
_TITLES = {
    "dragged": "friction per unit length from the profile of a wire dragged at its midpoint",
    "held": "static friction per unit length (averaged along the wire) holding a bent wire",
}

#: The columns of the readable table (the lists are in the JSON and CSV only).
_SHOWN = (
    "friction_per_length_N_per_m",
    "friction_per_length_sd_N_per_m",
    "friction_per_length_ci95_N_per_m",
    "friction_per_length_bootstrap_ci95_N_per_m",
    "friction_group",
    "half_length_m",
    "noise_m",
    "determined",
    "tau0_Pa",
    "tau0_ci95_Pa",
    "note",
)


def _table(args: Inputs, rec: dict[str, Any], params: dict[str, Any]) -> Table:
    cols: dict[str, Any] = {}
    for k, v in rec.items():
        if isinstance(v, list):
            arr = np.empty(1, dtype=object)
            arr[0] = (
                _Interval(None if not math.isfinite(x) else x for x in v)
                if (isinstance(v, _Interval))
                else v
            )
            cols[k] = arr
        elif v is None:
            arr = np.empty(1, dtype=object)
            arr[0] = None
            cols[k] = arr
        else:
            cols[k] = np.asarray([v])
    units = {
        "axis_angle": "rad",
        "drag_angle": "rad",
        "bending_stiffness_N_m2": "N m^2",
        "bending_stiffness_sd_N_m2": "N m^2",
        "tau0_Pa": "Pa",
        "tau0_sd_Pa": "Pa",
        "contact_half_width_m": "m",
    }
    shown = tuple(k for k in _SHOWN if k in cols)
    title = _TITLES[args.model]
    return Table(cols, params, units, args.command_line(), title, show=shown)


def _push(args: Inputs, shape: Any, Ec: float, tau0: float, load: float) -> dict[str, Any]:
    """What a push at ``--push-height`` does to the wire, with the fitted tau0 (docs/push.md)."""
    if shape is not None:
        raise ParameterError(
            "--push-height", "--push-height: the push of a faceted wire is not written (round only)"
        )
    positive("--push-height", args.push_height)
    w1 = args.work_of_adhesion_receding
    if w1 is None:
        w1 = args.work_of_adhesion
    try:
        cyl = Cylinder.from_modulus(
            args.radius, Ec, work_of_adhesion=args.work_of_adhesion, equilibrium_spacing=args.z0
        )
        push = cyl.push(
            friction_stress=tau0,
            height=args.push_height,
            receding_work_of_adhesion=w1,
            normal_load=load,
        )
    except ParameterError as exc:
        raise _flagged(exc) from None
    except ValueError as exc:
        raise ParameterError("--push-height", f"--push-height: {exc}") from None
    return {
        "push_height_m": args.push_height,
        "push_first_motion": str(push.first_motion),
        "push_rolling_resistance_N_per_m": float(push.rolling_resistance),
        "push_sliding_resistance_N_per_m": float(push.sliding_resistance),
        "push_critical_height_m": float(push.critical_height),
    }


def _sd(p: Parameter) -> Parameter:
    return Parameter(
        f"{p.name}_sd", "its standard uncertainty", kind="text", metavar="SD", group=p.group
    )


_RADIUS = Parameter(
    "radius", "radius [m] (a polygon's circumradius)", unit="m", metavar="R", group=_WIRE
)
_MODULUS = Parameter(
    "modulus", "the wire's Young's modulus [Pa]", unit="Pa", metavar="E", group=_WIRE
)
_W = Parameter("work_of_adhesion", "w [J/m^2]", unit="J/m^2", metavar="W", group=_CONTACT)
_Z0 = Parameter("z0", "range of adhesion z0 [m]", unit="m", group=_CONTACT)

_PARAMETERS = (
    Parameter(
        "data",
        "CSV of the profile: x_<unit>,y_<unit> (nm, um, m), in order from end to end",
        kind="text",
        metavar="FILE",
        group=_PROFILE,
    ),
    Parameter(
        "model",
        "dragged: at its midpoint (kinetic); held: at rest by static friction (default: "
        "%(default)s)",
        kind="text",
        choices=MODELS,
        default="dragged",
        group=_PROFILE,
    ),
    Parameter(
        "noise",
        "the position noise's sd [m], where known (default: from the residuals)",
        unit="m",
        metavar="SD",
        group=_PROFILE,
    ),
    Parameter(
        "bootstrap",
        "bootstrap refits, 0 to 10000 (default: %(default)s)",
        kind="integer",
        default=200,
        metavar="N",
        group=_PROFILE,
    ),
    _RADIUS,
    _sd(_RADIUS),
    _MODULUS,
    _sd(_MODULUS),
    Parameter(
        "cylinder_material",
        "the wire's preset instead of --modulus (linecontact materials)",
        kind="text",
        metavar="NAME",
        group=_WIRE,
    ),
    Parameter(
        "cross_section",
        f"round, or a polygon: {', '.join(NAMED_SIDES)} (default: %(default)s)",
        kind="text",
        choices=("round", *NAMED_SIDES),
        default="round",
        metavar="SHAPE",
        group=_WIRE,
    ),
    Parameter(
        "corner_radius", "a polygon's corner radius [m]", unit="m", metavar="RC", group=_WIRE
    ),
    Parameter("inner_radius", "a tube's inner radius [m]", unit="m", metavar="RI", group=_WIRE),
    _W,
    _sd(_W),
    _Z0,
    _sd(_Z0),
    Parameter(
        "contact_modulus",
        "composite modulus of the contact [Pa], or the substrate:",
        unit="Pa",
        metavar="E",
        group=_CONTACT,
    ),
    Parameter("nu1", "the wire's Poisson ratio", metavar="NU", group=_CONTACT),
    Parameter("E2", "the substrate's Young's modulus [Pa]", unit="Pa", metavar="E", group=_CONTACT),
    Parameter("nu2", "the substrate's Poisson ratio", metavar="NU", group=_CONTACT),
    Parameter(
        "substrate_material", "the substrate's preset", kind="text", metavar="NAME", group=_CONTACT
    ),
    Parameter(
        "normal_load",
        "load on the wire besides adhesion, its weight [N/m] (default: 0)",
        unit="N/m",
        metavar="F",
        flag="--load",
        group=_CONTACT,
    ),
    Parameter(
        "push_height",
        "then a push at this height [m]: stay, roll or slide (docs/push.md)",
        unit="m",
        metavar="H",
        group=_CONTACT,
    ),
    Parameter(
        "work_of_adhesion_receding",
        "the push's receding w [J/m^2] (default: w, no hysteresis)",
        unit="J/m^2",
        metavar="W1",
        group=_CONTACT,
    ),
    Parameter(
        "samples",
        "Monte Carlo samples of tau0 (default: %(default)s)",
        kind="integer",
        default=4000,
    ),
    Parameter("seed", "seed of the draws (default: %(default)s)", kind="integer", default=0),
    Parameter(
        "plot",
        "draw the profile, its fit and residuals into FILE",
        kind="text",
        metavar="FILE",
        shell_only=True,
    ),
)

_ENTRIES = (
    Entry(("data", "model"), "CSV of x_<unit>,y_<unit>, end to end; dragged (default) or held"),
    Entry(("noise", "bootstrap"), "noise sd [m] (default: the residuals'); refits (default: 200)"),
    Entry(("radius", "radius_sd"), "radius [m] (a polygon's circumradius) (sd: [m] or N%%)"),
    Entry(
        ("modulus", "modulus_sd", "cylinder_material"),
        "the wire's Young's modulus [Pa] (sd), or its preset",
    ),
    Entry(
        ("cross_section", "corner_radius", "inner_radius"),
        "%(default)s or a polygon; its corner radius [m]; a tube's bore [m]",
    ),
    Entry(
        ("work_of_adhesion", "work_of_adhesion_sd", "z0", "z0_sd"),
        "w [J/m^2], z0 [m] (sd: in their units or N%%)",
    ),
    Entry(
        ("contact_modulus", "nu1", "E2", "nu2", "substrate_material"),
        "composite E* [Pa], or nu1 and the substrate's E2 [Pa], nu2 or preset",
    ),
    Entry(("samples", "seed"), "Monte Carlo samples of tau0, seed (default: %(default)s, 0)"),
    Entry(
        ("push_height", "work_of_adhesion_receding"),
        "then a push at H [m]; its receding w [J/m^2] (default: w)",
    ),
)

OPERATIONS = {
    "fit-bent-wire": Operation(
        "fit-bent-wire",
        "friction per unit length (and tau0) from the profile of a bent wire",
        "Friction per unit length f of a wire dragged at its midpoint (or held at rest: "
        "--model held) from its imaged profile, with intervals; tau0 = f/(2a).",
        (
            "linecontact fit-bent-wire --data profile.csv --radius 50e-9 --modulus 140e9",
            "linecontact fit-bent-wire --data profile.csv --radius 50e-9 --modulus 140e9 "
            "--work-of-adhesion 0.2 --z0 0.3e-9 --nu1 0.36 --substrate-material SiO2",
        ),
        _PARAMETERS,
        _run,
        entries=_ENTRIES,
        figures="bent_wire",
    )
}
