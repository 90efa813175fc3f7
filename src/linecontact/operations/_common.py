"""The inputs every operation shares: the groups, the SI materials and adhesion, widths or loads.

Their declarations (:func:`group_parameters`, :func:`si_inputs`, :func:`width_parameters`) and
what they give: ``(R/h, sigma0/E, Cylinder or None)`` (:func:`groups`), the
:class:`~linecontact.cylinder.Cylinder` of the SI inputs (:func:`cylinder`), the contact
half-widths or loads (:func:`half_widths`, :func:`si_loads`), the provenance's SI parameters
(:func:`si_parameters`), the SI columns of a result (:func:`si_columns`). Errors are
:class:`ValueError` whose message names the inputs by their flags (``--radius``); each shell
says them in its own spelling.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from ..cylinder import Body, Cylinder, Sphere
from ..domain import check_si
from ..errors import ParameterError
from ..facet.contact import check_geometry
from ..geometry import NAMED_SIDES, Polygon
from ..laws import LennardJones
from ..output import Table
from ..presets import Material, material_names
from ._declare import Entry, Parameter
from ._widths import check_widths  # noqa: F401 - the shells' name for it
from ._written import made, note

# --------------------------------------------------------------------------------------------
# the declarations

#: The help section of the SI inputs.
SI_GROUP = "SI inputs (instead of the groups)"
#: The help section of the nondimensional groups.
GROUPS_GROUP = "nondimensional groups (the paper's)"


def group_parameters(group: str = GROUPS_GROUP) -> tuple[Parameter, ...]:
    """``R_over_h`` and ``sigma0_over_E``, the paper's groups (in the section ``group``)."""
    return (
        Parameter("R_over_h", "radius over adhesion range, > 0", metavar="R/h", group=group),
        Parameter(
            "sigma0_over_E",
            "adhesive stress over composite modulus, >= 0 (0: Hertz)",
            metavar="S",
            group=group,
        ),
    )


def material_parameters(
    group: str, cylinder: tuple[str, str], substrate: tuple[str, str], presets: tuple[str, str]
) -> tuple[Parameter, ...]:
    """``E1 nu1 E2 nu2`` and the two presets, in the section ``group``, with their help.

    ``cylinder`` and ``substrate`` are the help of a body's Young's modulus [Pa] and Poisson
    ratio; ``presets`` that of ``--cylinder-material`` and ``--substrate-material``.
    """
    moduli = tuple(
        Parameter(name, help, unit=unit, group=group)
        for name, help, unit in zip(
            ("E1", "nu1", "E2", "nu2"), (*cylinder, *substrate), ("Pa", "", "Pa", ""), strict=True
        )
    )
    return (
        *moduli,
        *(
            Parameter(name, help, kind="text", metavar="NAME", group=group)
            for name, help in zip(("cylinder_material", "substrate_material"), presets, strict=True)
        ),
    )


def si_inputs(range_flag: str = "--h") -> tuple[tuple[Parameter, ...], tuple[Entry, ...]]:
    """The SI inputs: radius, moduli or presets, adhesion, the fibre's length; their entries.

    ``range_flag`` is the adhesion range's flag (``--h``; ``--h2``, the leading edge's, for
    sliding and the pushed fibre, whose one work of adhesion is then the advancing one).
    """
    g = SI_GROUP
    name = "leading-edge adhesion range h2" if range_flag == "--h2" else "adhesion range h"
    work = _work_flag(range_flag)
    params = (
        Parameter("radius", "cylinder radius R [m]", unit="m", metavar="R", group=g),
        Parameter(
            "modulus",
            "composite plane-strain modulus [Pa], or the materials:",
            unit="Pa",
            metavar="E",
            group=g,
        ),
        *material_parameters(
            g,
            (
                "cylinder's Young's modulus [Pa] (with --nu1 ...)",
                "cylinder's Poisson ratio, in (-1, 0.5]",
            ),
            ("substrate's Young's modulus [Pa]", "substrate's Poisson ratio, in (-1, 0.5]"),
            (
                "cylinder's material preset, instead of --E1 --nu1 (case-insensitive; names: "
                "`linecontact materials`)",
                "substrate's material preset, instead of --E2 --nu2 (names as for "
                "--cylinder-material)",
            ),
        ),
        Parameter(
            "sigma0", "adhesive (Dugdale) stress sigma0 [Pa]", unit="Pa", metavar="S", group=g
        ),
        Parameter(
            "h",
            f"{name} [m] (sets R/h even without adhesion)",
            unit="m",
            metavar="H",
            flag=range_flag,
            group=g,
        ),
        Parameter(
            "work_of_adhesion",
            f"{'advancing ' if work != '--work-of-adhesion' else ''}work of adhesion w "
            f"[J/m^2] (with --z0, instead of --sigma0 and "
            f"{range_flag}: sigma0 = 16 w/(9 sqrt(3) z0), {range_flag} = 0.974 z0)",
            unit="J/m^2",
            metavar="W",
            flag=work,
            aliases=("--work-of-adhesion",) if work != "--work-of-adhesion" else (),
            group=g,
        ),
        Parameter(
            "z0", "equilibrium spacing of the surfaces z0 [m]", unit="m", metavar="Z", group=g
        ),
        Parameter(
            "length",
            "length of the fibre [m]: adds total forces [N] and moments [N m]",
            unit="m",
            metavar="L",
            group=g,
        ),
    )
    rng = range_flag[2:]
    entries = (
        Entry(
            ("radius", "length"), "cylinder radius R [m]; fibre length [m] (adds totals [N], [N m])"
        ),
        Entry(("E1", "nu1", "E2", "nu2"), "Young's moduli [Pa], Poisson ratios (1: cylinder)"),
        Entry(
            ("cylinder_material", "substrate_material"),
            "or presets (names: `linecontact materials`)",
        ),
        Entry(
            ("sigma0", "h", "work_of_adhesion", "z0"),
            f"sigma0 [Pa], {rng} [m]; or w [J/m^2], z0 [m]",
        ),
    )
    return params, entries


#: The help section of the wire's cross-section.
SHAPE_GROUP = "cross-section (a faceted wire lying on a facet; docs/faceted.md)"


def shape_parameters(
    group: str = SHAPE_GROUP,
) -> tuple[tuple[Parameter, ...], tuple[Entry, ...]]:
    """``cross_section`` and a polygon's corner radius, in metres (SI) or over ``R`` (groups).

    In the help section ``group``, with the entry that says the three in one line of help.
    """
    params = (
        Parameter(
            "cross_section",
            f"round, or a regular polygon lying on a facet: {', '.join(NAMED_SIDES)} "
            "(--radius or R: its circumradius)",
            kind="text",
            choices=("round", *NAMED_SIDES),
            default="round",
            metavar="SHAPE",
            group=group,
        ),
        Parameter(
            "corner_radius",
            "a polygon's corner radius r_c [m] (SI), 0 (sharp, the default) to the circumradius",
            unit="m",
            metavar="RC",
            group=group,
        ),
        Parameter(
            "corner_radius_over_R",
            "a polygon's corner radius over the circumradius, in [0, 1] (groups; 1: round)",
            metavar="RC/R",
            group=group,
        ),
    )
    entries = (
        Entry(
            ("cross_section", "corner_radius", "corner_radius_over_R"),
            "%(default)s, or a polygon on a facet; its corner radius [m], or over R",
        ),
    )
    return params, entries


#: The bodies (``--body``): a wire, or a sphere (an AFM tip, a colloidal probe).
BODIES: dict[str, type[Body]] = {"wire": Cylinder, "sphere": Sphere}


def body_parameter(group: str = SHAPE_GROUP) -> Parameter:
    """``body``: a wire (forces per unit length) or a sphere (forces in N)."""
    return Parameter(
        "body",
        "wire (forces per unit length) or sphere (an AFM tip or a colloidal probe: forces "
        "in N, docs/sphere.md)",
        kind="text",
        choices=tuple(BODIES),
        default="wire",
        metavar="BODY",
        group=group,
    )


def is_sphere(args: Any) -> bool:
    """Whether the call's body is a sphere (``--body sphere``)."""
    return getattr(args, "body", None) == "sphere"


def sphere_inputs(args: Any) -> None:
    """Refuse what a sphere has not: ``--length``, a cross-section, a law but Dugdale's.

    Under the Lennard-Jones law its pull-off and load curve are written, not its contact.
    """
    if getattr(args, "law", None) == "lennard-jones" and args.command == "normal":
        raise ParameterError(
            "--law",
            "--law lennard-jones is not written for a sphere's normal (--body sphere): its "
            "pull-off and load curve are; its contact is the Dugdale law's (--law dugdale)",
        )
    if getattr(args, "length", None) is not None:
        raise ParameterError(
            "--length", "--length is a wire's (its totals): a sphere's forces are in N"
        )
    shape(args, None)  # a sphere is round


def shape(args: Any, cyl: Body | None) -> dict[str, Any] | None:
    """A polygon's groups (``sides``, ``corner_radius_over_R``), or None for the round wire.

    With SI inputs the cylinder of :func:`cylinder` already carries the polygon.
    """
    name = getattr(args, "cross_section", None) or "round"
    rc = getattr(args, "corner_radius", None)
    rcR = getattr(args, "corner_radius_over_R", None)
    if is_sphere(args):
        flags = (("--corner-radius", rc), ("--corner-radius-over-R", rcR))
        given = [f for f, v in flags if v is not None]
        if name != "round" or given:
            flag = "--cross-section" if name != "round" else given[0]
            raise ParameterError(flag, f"{flag} is a wire's: a sphere (--body sphere) is round")
        return None
    if name == "round":
        for value, f in ((rc, "--corner-radius"), (rcR, "--corner-radius-over-R")):
            if value is not None:
                raise ParameterError(
                    f, f"{f} is a polygon's: give --cross-section {' or '.join(NAMED_SIDES)}"
                )
        return None
    if cyl is not None:
        if rcR is not None:
            raise ParameterError(
                "--corner-radius-over-R",
                "with SI inputs give the corner radius as --corner-radius [m]",
            )
        return cyl.cross_section.groups(cyl.radius)  # type: ignore[attr-defined]
    if rc is not None:
        raise ParameterError(
            "--corner-radius",
            "--corner-radius [m] goes with SI inputs (--radius, ...): with the groups give "
            "--corner-radius-over-R",
        )
    try:
        n, r = check_geometry(NAMED_SIDES[name], 0.0 if rcR is None else rcR)
    except ParameterError as e:
        raise ParameterError(
            "--corner-radius-over-R",
            str(e).replace("corner_radius_over_R", "--corner-radius-over-R"),
        ) from None
    return {"sides": int(n), "corner_radius_over_R": float(r)}


def shape_parameters_of(g: dict[str, Any], cyl: Cylinder | None) -> dict[str, Any]:
    """The provenance of a polygon: its name, sides, corner radius over R (and in metres)."""
    name = next(k for k, n in NAMED_SIDES.items() if n == g["sides"])
    out: dict[str, Any] = {"cross_section": name, **g}
    if cyl is not None:
        out["corner_radius_m"] = cyl.cross_section.parameters()["corner_radius_m"]
    return out


def sliding_parameters(
    groups: tuple[str, str, str, str], si: tuple[str, str]
) -> tuple[tuple[Parameter, ...], tuple[Parameter, ...]]:
    """The inputs of the sliding contact (``slide``, ``push``), with their help.

    Its groups, R/h2, h1/h2, sigma0/E and tau0/E (``groups``, their help); and its SI inputs
    beside :func:`si_inputs`, the receding range h1 [m] and the friction stress tau0 [Pa]
    (``si``).
    """
    names = ("R_over_h2", "h1_over_h2", "sigma0_over_E", "tau0_over_E")
    return (
        tuple(
            Parameter(name, help, metavar=metavar, group=GROUPS_GROUP)
            for name, help, metavar in zip(names, groups, ("R/h2", "H", "S", "T"), strict=True)
        ),
        (
            Parameter("h1", si[0], unit="m", group=SI_GROUP),
            Parameter("tau0", si[1], unit="Pa", metavar="T", group=SI_GROUP),
        ),
    )


def width_parameters(load_name: str, load_help: str, group: str) -> tuple[Parameter, ...]:
    """The inputs read by :func:`half_widths`: widths or loads, nondimensional or SI."""
    return (
        Parameter(
            "a_over_R", "contact half-widths a/R, > 0", many="several", metavar="A", group=group
        ),
        Parameter(
            "a_over_R_range",
            "NUM linearly spaced contact half-widths a/R from START to STOP",
            many="triple",
            metavar=("START", "STOP", "NUM"),
            group=group,
        ),
        Parameter(load_name, load_help, many="several", metavar="F", group=group),
        Parameter(
            "a",
            "contact half-widths a [m] (SI inputs)",
            many="several",
            unit="m",
            metavar="A",
            flag="--half-width",
            aliases=("--a",),
            group=group,
        ),
        Parameter(
            "load",
            "normal loads per unit length F [N/m] (SI inputs)",
            many="several",
            unit="N/m",
            group=group,
        ),
    )


# --------------------------------------------------------------------------------------------
# what they give

#: Most points a range option may ask for (1e9 exhausted the memory instead of failing).
MAX_POINTS = 1_000_000


#: The SI inputs of the materials and adhesion (their presence switches to SI mode).
SI_KEYS = (
    "radius",
    "modulus",
    "E1",
    "nu1",
    "E2",
    "nu2",
    "cylinder_material",
    "substrate_material",
    "sigma0",
    "h",
    "work_of_adhesion",
    "z0",
)


def positive(flag: str, value: float | None) -> None:
    """``value`` given as ``flag`` a finite number > 0, or not given (ParameterError)."""
    if value is not None and not (math.isfinite(value) and value > 0):
        raise ParameterError(flag, f"{flag} must be a finite number > 0, got {value!r}")


def _work_flag(range_flag: str) -> str:
    """The flag of the one work of adhesion (with ``--z0``): advancing where h2 is the range."""
    return "--work-of-adhesion-advancing" if range_flag == "--h2" else "--work-of-adhesion"


def flag(name: str) -> str:
    """The command line's flag of the parameter ``name``: ``--`` and ``-`` for ``_``."""
    return "--" + name.replace("_", "-")


def flags(args: Any, *names: str, given: bool = True) -> list[str]:
    """The flags of those of ``names`` given in ``args`` (``given=False``: not given)."""
    return [flag(n) for n in names if (getattr(args, n) is not None) == given]


def si_given(args: Any, extra: Sequence[str] = ()) -> bool:
    """Whether any SI input (or one of ``extra``) was given.

    ``--length`` alone is refused: it scales SI forces and means nothing without them.
    """
    si = any(getattr(args, k, None) is not None for k in (*SI_KEYS, *extra))
    if not si and getattr(args, "length", None) is not None:
        raise ParameterError(
            "--length",
            "--length [m] gives the totals of SI forces: give --radius and the materials too",
        )
    return si


def cylinder(args: Any, range_flag: str = "--h") -> Any:
    """The body of the SI inputs under ``--law``, with errors that name the flags.

    ``--body``: a :class:`Cylinder` (a wire, the default) or a :class:`Sphere`.
    """
    if is_sphere(args):
        sphere_inputs(args)
    body = _cylinder(args, range_flag)
    if not isinstance(body, Cylinder):  # a sphere
        if getattr(args, "law", None) == "lennard-jones":
            return made(args, "sphere", body.under, LennardJones)  # type: ignore[attr-defined]
        return body
    cyl = body
    name = getattr(args, "cross_section", None) or "round"
    if name != "round":
        rc = getattr(args, "corner_radius", None)
        try:
            polygon = Polygon(NAMED_SIDES[name], 0.0 if rc is None else rc)
            cyl = made(args, "cyl", cyl.shaped, polygon)
        except ParameterError as e:
            message = (
                str(e).replace("corner_radius", "--corner-radius").replace("radius =", "--radius")
            )
            raise ParameterError("--corner-radius", message) from None
    if getattr(args, "law", None) == "lennard-jones":
        return made(args, "cyl", cyl.under, LennardJones)
    return cyl


def _cylinder(args: Any, range_flag: str) -> Body:
    kind = BODIES[getattr(args, "body", None) or "wire"]
    name = "sphere" if kind is Sphere else "cyl"  # the variable of the Python lines
    work = _work_flag(range_flag)
    if args.radius is None:
        raise ParameterError("--radius", "SI inputs need --radius [m]")
    if args.h is None and args.work_of_adhesion is None and args.z0 is None:
        raise ParameterError(
            range_flag,
            f"SI inputs need the adhesion range {range_flag} [m] (it sets R/h even without "
            f"adhesion), or {work} with --z0",
        )
    if (args.sigma0 is not None or args.h is not None) and (
        args.work_of_adhesion is not None or args.z0 is not None
    ):
        raise ParameterError(
            "--sigma0",
            f"give adhesion either as --sigma0 and {range_flag}, or as {work} and --z0, not both",
        )
    if (args.work_of_adhesion is None) != (args.z0 is None):
        raise ParameterError(work, f"give both {work} and --z0")
    positive("--length", args.length)
    adh = dict(
        cohesive_stress=args.sigma0,
        adhesion_range=args.h,
        work_of_adhesion=args.work_of_adhesion,
        equilibrium_spacing=args.z0,
    )
    mats = (args.E1, args.nu1, args.E2, args.nu2)
    presets = _presets(args)
    if args.modulus is not None:
        if any(m is not None for m in presets):
            raise ParameterError(
                "--modulus",
                "give either --modulus or the materials (--cylinder-material, "
                "--substrate-material), not both",
            )
        if any(v is not None for v in mats):
            raise ParameterError(
                "--modulus", "give either --modulus or --E1 --nu1 --E2 --nu2, not both"
            )
        return made(args, name, kind.from_modulus, args.radius, args.modulus, **adh)
    for m, E, nu, flags, body in (
        (presets[0], args.E1, args.nu1, "--E1 --nu1", "cylinder"),
        (presets[1], args.E2, args.nu2, "--E2 --nu2", "substrate"),
    ):
        if m is not None and (E is not None or nu is not None):
            raise ParameterError(
                f"--{body}-material",
                f"give the {body} either as --{body}-material or as {flags}, not both",
            )
    E1, nu1 = (args.E1, args.nu1) if presets[0] is None else (presets[0].E, presets[0].nu)
    E2, nu2 = (args.E2, args.nu2) if presets[1] is None else (presets[1].E, presets[1].nu)
    if any(v is None for v in (E1, nu1, E2, nu2)):
        raise ParameterError(
            "--modulus",
            "SI inputs need --modulus, or the materials: --cylinder-material or --E1 --nu1, "
            "and --substrate-material or --E2 --nu2",
        )
    cyl = made(args, name, kind.from_materials, args.radius, E1, nu1, E2, nu2, **adh)
    pairs = zip(presets, ("E1, nu1", "E2, nu2"), strict=True)
    named = [f"{m.name} ({w})" for m, w in pairs if m is not None]
    if named:
        note(args, f"the presets' moduli: {', '.join(named)}")
    return cyl


def _presets(args: Any) -> tuple[Material | None, Material | None]:
    """The presets of ``--cylinder-material`` and ``--substrate-material`` (None: not given)."""
    out: list[Material | None] = []
    for key, flag in (
        ("cylinder_material", "--cylinder-material"),
        ("substrate_material", "--substrate-material"),
    ):
        name = getattr(args, key, None)
        if name is None:
            out.append(None)
            continue
        try:
            out.append(Material.from_name(name))
        except ValueError:
            raise ParameterError(
                flag,
                f"{flag} {name!r} is not a material preset: one of "
                f"{', '.join(material_names())} (linecontact materials lists them)",
            ) from None
    return out[0], out[1]


def si_parameters(args: Any, cyl: Cylinder) -> dict[str, Any]:
    """The SI inputs as given and as used, for the provenance block (units in the names)."""
    params: dict[str, Any] = {"radius_m": cyl.radius, "modulus_Pa": cyl.modulus}
    m1, m2 = _presets(args)
    for m, body, E, nu in ((m1, "cylinder", "E1", "nu1"), (m2, "substrate", "E2", "nu2")):
        if m is not None:  # a preset never hides its numbers
            params[f"{body}_material"] = m.name
            params[f"{body}_source"] = m.source
            params[f"{E}_Pa"] = m.E
            params[nu] = m.nu
        else:
            for key, name in ((E, f"{E}_Pa"), (nu, nu)):
                v = getattr(args, key, None)
                if v is not None:
                    params[name] = v
    for key, name in (
        ("work_of_adhesion", "work_of_adhesion_J_per_m2"),
        ("z0", "z0_m"),
    ):
        v = getattr(args, key, None)
        if v is not None:
            params[name] = v
    params.update(
        sigma0_Pa=cyl.cohesive_stress, h_m=cyl.adhesion_range, dundurs_beta=cyl.dundurs_beta
    )
    if args.length is not None:
        params["length_m"] = args.length
    return params


def groups(args: Any) -> tuple[float, float, Cylinder | None]:
    """``(R/h, sigma0/E, Cylinder or None)`` from the groups or the SI inputs."""
    si = si_given(args)
    nd = args.R_over_h is not None or args.sigma0_over_E is not None
    if si and nd:
        raise ParameterError(
            "--R-over-h",
            "give either the nondimensional groups (--R-over-h, --sigma0-over-E) or SI inputs "
            "(--radius, ...), not both",
        )
    if not si:
        if args.R_over_h is None or args.sigma0_over_E is None:
            raise ParameterError(
                "--R-over-h", "give --R-over-h and --sigma0-over-E (or SI inputs with --radius)"
            )
        if (
            getattr(args, "law", None) == "lennard-jones"
            and args.command != "pulloff"
            and not is_sphere(args)  # a sphere's own range is said by its operation
        ):
            _check_lennard_jones_groups(args.R_over_h, args.sigma0_over_E)
        return args.R_over_h, args.sigma0_over_E, None
    cyl = cylinder(args)
    if getattr(args, "law", None) == "lennard-jones" and isinstance(cyl, Cylinder):
        # its domain said for this cylinder, in SI units (the pull-off: every mu)
        cyl._check_lennard_jones(pull_off=getattr(args, "command", None) == "pulloff")
    return cyl.R_over_h, cyl.sigma0_over_E, cyl


def _check_lennard_jones_groups(rho: float, s: float) -> None:
    """The groups inside the domain of the Lennard-Jones solver, said in the flags' terms.

    Its own group ``w sqrt(R/z0)/(E z0)`` is ``--sigma0-over-E sqrt(--R-over-h)`` over
    ``S^(3/2)`` (``S = 16/(9 sqrt 3)``, the Maugis matching): up to 400 for contacts and load
    curves (the pull-off at any value).
    """
    from ..domain import DOMAIN, check
    from ..lennard_jones import maugis_parameter_of_mu
    from ..materials import MAUGIS_STRENGTH

    check("--R-over-h", rho, "R_over_h")
    check("--sigma0-over-E", s, "sigma0_over_E")
    hi = DOMAIN["lj_mu"][2]
    k = MAUGIS_STRENGTH**1.5
    value = s * math.sqrt(rho) / k
    if value > hi:
        lam = float(maugis_parameter_of_mu(hi))
        raise ParameterError(
            "--sigma0-over-E",
            f"under the Lennard-Jones law --sigma0-over-E sqrt(--R-over-h) / {k:.4g} = "
            f"{value:.4g} must be at most {hi:g} for contacts and load curves (a Tabor-Maugis "
            f"parameter up to {lam:.3g}; the pull-off at any value): use --law dugdale, or "
            f"--sigma0-over-E below {s * hi / value:.3g}, or --R-over-h below "
            f"{rho * (hi / value) ** 2:.3g}",
        )


def half_widths(args: Any, cyl: Cylinder | None, load_attr: str):
    """Contact half-widths: a/R (``--a-over-R``, ``--a-over-R-range``) or a [m] (``--half-width``).

    None for loads. The SI half-widths are for the cylinder's methods.

    Exactly one of those, ``--<load_attr>`` or ``--load`` [N/m] must be given.
    """
    load_flag = flag(load_attr)
    given = [
        args.a_over_R is not None,
        args.a_over_R_range is not None,
        getattr(args, load_attr) is not None,
        args.a is not None,
        args.load is not None,
    ]
    if sum(given) != 1:
        raise ParameterError(
            "--a-over-R",
            f"give exactly one of --a-over-R, --a-over-R-range, {load_flag}, --half-width [m] or "
            "--load [N/m]",
        )
    if (args.a is not None or args.load is not None) and cyl is None:
        raise ParameterError(
            "--half-width",
            "--half-width and --load are SI inputs: give --radius and the materials too",
        )
    if cyl is not None and (given[0] or given[1] or given[2]):
        raise ParameterError(
            "--a-over-R",
            f"--a-over-R, --a-over-R-range and {load_flag} are nondimensional: with SI inputs "
            "give "
            "--half-width [m] or --load [N/m]",
        )
    if args.a_over_R_range is not None:
        start, stop, num = args.a_over_R_range
        for name, v in (("START", start), ("STOP", stop)):
            if not (math.isfinite(v) and v > 0):
                raise ParameterError(
                    "--a-over-R-range",
                    f"--a-over-R-range {name} must be a finite number > 0, got {v!r}",
                )
        if not (math.isfinite(num) and float(num).is_integer() and 1 <= num <= MAX_POINTS):
            raise ParameterError(
                "--a-over-R-range",
                f"--a-over-R-range NUM must be an integer in [1, {MAX_POINTS}], got {num!r}",
            )
        return np.linspace(start, stop, int(num))
    if args.a_over_R is not None:
        return np.asarray(args.a_over_R, float)
    if args.a is not None:
        a = np.asarray(args.a, float)
        if not np.all(np.isfinite(a) & (a > 0)):
            bad = a[~(np.isfinite(a) & (a > 0))][0]
            raise ParameterError(
                "--half-width", f"--half-width must be a finite number > 0, got {bad!r}"
            )
        key = "sliding_a_over_R" if load_attr == "F_over_Eh2" else "a_over_R"
        check_si("--half-width", a, cyl.radius, key, "m")  # type: ignore[union-attr]
        return a
    return None


def si_loads(args: Any, cyl: Cylinder, key: str) -> np.ndarray:
    """``--load`` [N/m], inside ``key``'s domain (in units of ``E h``; ``E h2`` for sliding)."""
    load = np.asarray(args.load, float)
    check_si("--load", load, cyl.scale("Eh"), key, "N/m")
    return load


def si_columns(
    result: Any,
    names: dict[str, str],
    *,
    totals: dict[str, str] | None = None,
    length: float | None = None,
) -> dict[str, Any]:
    """The SI columns of an SI ``result`` of :class:`Cylinder`, under the record's keys.

    ``names`` maps each SI field of ``result`` (``"load"``, ...) to its key (``"F_N_per_m"``),
    in that order; with ``length`` [m] then ``totals`` maps each field of ``result.total``
    (the field over the fibre) to its key (``"F_total_N"``). No arithmetic: a rename.
    """
    out = {key: getattr(result, name) for name, key in names.items()}
    if length is not None and totals:
        over = result.total(length)
        out.update({key: over[name] for name, key in totals.items()})
    return out


def null_missing(table: Table, missing: np.ndarray, keep: Sequence[str]) -> Table:
    """The points without a state with missing values: floats NaN (JSON null), flags False.

    The columns in ``keep`` (the point's own input, its state and reason) are kept.
    """
    if not np.any(missing):
        return table
    cols = {}
    for k, v in table.columns.items():
        if k in keep:
            cols[k] = v
        elif v.dtype.kind == "f":
            cols[k] = np.where(missing, np.nan, v)
        elif v.dtype.kind == "b":
            cols[k] = np.where(missing, False, v)
        else:
            cols[k] = v
    return Table(
        cols, table.parameters, table.units, table.command, table.title, table.scales, table.show
    )
