"""Shared pieces of the subcommands: the parser class, the common options, the output."""

from __future__ import annotations

import argparse
import json
import math
import re
from collections.abc import Sequence

import numpy as np

from ..cylinder import Cylinder

#: Values that are numbers even though they start with "-": argparse (before Python 3.13)
#: knows only -5 and -0.5, so "--load -1e-3" failed with "expected one argument".
_NEGATIVE_NUMBER = re.compile(
    r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^-(inf|infinity|nan)$", re.IGNORECASE
)


class _Parser(argparse.ArgumentParser):
    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = _NEGATIVE_NUMBER

    def error(self, message: str):  # argparse's own errors: one line, exit 2
        self.exit(2, f"{self.prog}: error: {message}\n")


def _finite(v):
    if isinstance(v, float) and not math.isfinite(v):
        return None
    return v


def _dump_json(obj) -> str:
    def clean(o):
        if isinstance(o, dict):
            return {k: clean(v) for k, v in o.items()}
        if isinstance(o, (list, tuple)):
            return [clean(v) for v in o]
        if isinstance(o, np.generic):
            o = o.item()
        return _finite(o)

    return json.dumps(clean(obj), indent=2, allow_nan=False)


def _table(records: list[dict], keys: Sequence[str]) -> str:
    def fmt(v):
        if isinstance(v, bool):
            return "yes" if v else "no"
        if isinstance(v, float):
            return f"{v:.10g}"
        return str(v)

    rows = [[fmt(r[k]) for k in keys] for r in records]
    widths = [max(len(k), *(len(row[i]) for row in rows)) for i, k in enumerate(keys)]
    lines = ["  ".join(k.rjust(w) for k, w in zip(keys, widths, strict=True))]
    lines += ["  ".join(c.rjust(w) for c, w in zip(row, widths, strict=True)) for row in rows]
    return "\n".join(lines)


#: Most points a range option may ask for (1e9 exhausted the memory instead of failing).
_MAX_POINTS = 1_000_000


# --- shared arguments ---------------------------------------------------------------------


def _add_si_materials(p: argparse.ArgumentParser):
    """The SI group with radius, moduli and adhesive stress; the caller adds the ranges."""
    si = p.add_argument_group("SI inputs (instead of the groups)")
    si.add_argument("--radius", type=float, help="R [m]")
    si.add_argument("--modulus", type=float, help="composite plane-strain modulus E [Pa]")
    si.add_argument("--E1", type=float, help="cylinder Young's modulus [Pa]")
    si.add_argument("--nu1", type=float, help="cylinder Poisson ratio, in (-1, 0.5]")
    si.add_argument("--E2", type=float, help="substrate Young's modulus [Pa]")
    si.add_argument("--nu2", type=float, help="substrate Poisson ratio, in (-1, 0.5]")
    si.add_argument("--sigma0", type=float, help="adhesive (Dugdale) stress [Pa]")
    return si


def _add_groups(p: argparse.ArgumentParser) -> None:
    g = p.add_argument_group("nondimensional groups (the paper's)")
    g.add_argument("--R-over-h", type=float, help="cylinder radius over adhesion range, > 0")
    g.add_argument(
        "--sigma0-over-E",
        type=float,
        help="adhesive stress over composite modulus, >= 0 (0: Hertz)",
    )
    si = _add_si_materials(p)
    si.add_argument("--h", type=float, help="range of the adhesive stress [m]")
    si.add_argument("--work-of-adhesion", type=float, help="w [J/m^2] (with --z0)")
    si.add_argument("--z0", type=float, help="equilibrium spacing [m] (Maugis: h = 0.974 z0)")


def _cylinder(args, h_flag: str = "--h"):
    """A Cylinder for SI mode, or None in nondimensional mode."""
    si_given = any(
        getattr(args, k) is not None
        for k in (
            "radius",
            "modulus",
            "E1",
            "nu1",
            "E2",
            "nu2",
            "sigma0",
            "h",
            "work_of_adhesion",
            "z0",
        )
    )
    groups_given = args.R_over_h is not None or args.sigma0_over_E is not None
    if si_given and groups_given:
        raise ValueError(
            "give either the nondimensional groups (--R-over-h, --sigma0-over-E) "
            "or SI inputs (--radius, ...), not both"
        )
    if not si_given:
        if args.R_over_h is None or args.sigma0_over_E is None:
            raise ValueError("give --R-over-h and --sigma0-over-E (or SI inputs with --radius)")
        return None
    if args.radius is None:
        raise ValueError("SI inputs need --radius [m]")
    if args.h is None and args.work_of_adhesion is None and args.z0 is None:
        raise ValueError(
            f"SI inputs need the adhesion range {h_flag} [m] (it sets R/h even "
            f"without adhesion), or --work-of-adhesion with --z0"
        )
    adh = dict(
        cohesive_stress=args.sigma0,
        adhesion_range=args.h,
        work_of_adhesion=args.work_of_adhesion,
        equilibrium_spacing=args.z0,
    )
    mats = (args.E1, args.nu1, args.E2, args.nu2)
    if args.modulus is not None:
        if any(v is not None for v in mats):
            raise ValueError("give either --modulus or --E1 --nu1 --E2 --nu2, not both")
        return Cylinder.from_modulus(args.radius, args.modulus, **adh)
    if any(v is None for v in mats):
        raise ValueError("SI inputs need --modulus, or all of --E1 --nu1 --E2 --nu2")
    return Cylinder.from_materials(args.radius, *mats, **adh)


def _groups(args):
    cyl = _cylinder(args)
    if cyl is None:
        return args.R_over_h, args.sigma0_over_E, None
    return cyl.R_over_h, cyl.sigma0_over_E, cyl


def _add_width_options(p, load_flag: str, load_help: str) -> None:
    """The options read by :func:`_half_widths`: widths or loads, nondimensional or SI."""
    p.add_argument("--a-over-R", type=float, nargs="+", metavar="A", help="contact half-widths")
    p.add_argument(
        "--a-over-R-range",
        type=float,
        nargs=3,
        metavar=("START", "STOP", "NUM"),
        help="linearly spaced contact half-widths",
    )
    p.add_argument(load_flag, type=float, nargs="+", metavar="F", help=load_help)
    p.add_argument("--a", type=float, nargs="+", help="contact half-widths [m] (SI mode)")
    p.add_argument("--load", type=float, nargs="+", help="normal loads [N/m] (SI mode)")


def _half_widths(args, cyl, load_attr: str):
    """Contact half-widths a/R from --a-over-R, --a-over-R-range or --a [m]; None for loads.

    Exactly one of those, ``--<load_attr>`` or ``--load`` [N/m] must be given.
    """
    flag = "--" + load_attr.replace("_", "-")
    given = [
        args.a_over_R is not None,
        args.a_over_R_range is not None,
        getattr(args, load_attr) is not None,
        args.a is not None,
        args.load is not None,
    ]
    if sum(given) != 1:
        raise ValueError(
            f"give exactly one of --a-over-R, --a-over-R-range, {flag}, --a [m] or --load [N/m]"
        )
    if (args.a is not None or args.load is not None) and cyl is None:
        raise ValueError("--a and --load are SI inputs: give --radius and the materials too")
    if args.a_over_R_range is not None:
        start, stop, num = args.a_over_R_range
        for name, v in (("START", start), ("STOP", stop)):
            if not (math.isfinite(v) and v > 0):
                raise ValueError(f"--a-over-R-range {name} must be a finite number > 0, got {v!r}")
        if not (math.isfinite(num) and float(num).is_integer() and 1 <= num <= _MAX_POINTS):
            raise ValueError(
                f"--a-over-R-range NUM must be an integer in [1, {_MAX_POINTS}], got {num!r}"
            )
        return np.linspace(start, stop, int(num))
    if args.a_over_R is not None:
        return np.asarray(args.a_over_R, float)
    if args.a is not None:
        return np.asarray(args.a, float) / cyl.radius
    return None
