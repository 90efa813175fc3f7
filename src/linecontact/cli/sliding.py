"""The ``slide`` subcommand: steady sliding with different trailing and leading adhesion.

Registered on the main parser by :func:`linecontact.cli.build_parser`; a thin shell over
:func:`linecontact.sliding.sliding_contact` and
:func:`linecontact.sliding.sliding_contact_for_load`. The ``--json`` records carry at least
``a_over_R``, ``c1_over_R``, ``c2_over_R``, ``e_over_R``, ``F_over_Eh2``, ``M_over_Eh2R``
(a contract).
"""

from __future__ import annotations

import argparse

import numpy as np

from ..sliding import sliding_contact, sliding_contact_for_load
from ._options import (
    _add_si_materials,
    _add_width_options,
    _cylinder,
    _dump_json,
    _half_widths,
    _table,
)

__all__ = ["register"]

_SI_KEYS = ("radius", "modulus", "E1", "nu1", "E2", "nu2", "sigma0", "h", "work_of_adhesion", "z0")

_EPILOG = (
    "Axes: x along the sliding direction (the cylinder moves to +x), origin at the "
    "contact centre; trailing zone -c1 < x < -a, leading zone a < x < c2; e is the "
    "apex (axis) position. M = int x p dx about the contact centre, clockwise positive "
    "(x right, y up): the moment that must act on the cylinder with the load; the "
    "pressure's own moment on it is M counterclockwise. Compressive load positive."
)


def register(sub) -> argparse.ArgumentParser:
    """Add the ``slide`` subcommand to the subparsers ``sub``; returns its parser."""
    p = sub.add_parser(
        "slide",
        help="steady sliding: adhesive zones, eccentricity, load and "
        "moment with different trailing/leading adhesion",
        epilog=_EPILOG,
    )
    g = p.add_argument_group("nondimensional groups (the paper's)")
    g.add_argument(
        "--R-over-h2", type=float, help="radius over the leading-edge adhesion range h2, > 0"
    )
    g.add_argument(
        "--h1-over-h2",
        type=float,
        help="trailing over leading adhesion range, > 0 (1: normal contact)",
    )
    g.add_argument(
        "--sigma0-over-E",
        type=float,
        help="adhesive stress over composite modulus, >= 0 (0: Hertz)",
    )
    g.add_argument(
        "--tau0-over-E",
        type=float,
        help="interface shear strength over E, >= 0: adds the friction force 2 a tau0",
    )
    si = _add_si_materials(p)
    si.add_argument("--h2", dest="h", type=float, help="leading-edge adhesion range h2 [m]")
    si.add_argument(
        "--h1", type=float, help="trailing-edge adhesion range h1 [m] (or give --h1-over-h2)"
    )
    si.add_argument(
        "--work-of-adhesion", type=float, help="leading-edge w [J/m^2] (with --z0; h2 = 0.974 z0)"
    )
    si.add_argument("--z0", type=float, help="equilibrium spacing [m]")
    si.add_argument("--tau0", type=float, help="interface shear strength [Pa]")
    w = p.add_argument_group("contact widths or loads (exactly one)")
    _add_width_options(w, "--F-over-Eh2", "normal loads (inverse problem, stable branch)")
    p.add_argument(
        "--method",
        choices=("collocation", "closed-form"),
        default="collocation",
        help="the paper's Gauss-Chebyshev collocation (default) or the closed form",
    )
    p.add_argument("--json", action="store_true", help="JSON array of records on stdout")
    p.set_defaults(func=_cmd_slide)
    return p


def _setup(args):
    """(R/h2, h1/h2, sigma0/E, tau0/E or None, Cylinder or None) from the arguments."""
    si_given = (
        any(getattr(args, k) is not None for k in _SI_KEYS)
        or args.h1 is not None
        or args.tau0 is not None
    )
    groups_given = any(
        v is not None for v in (args.R_over_h2, args.sigma0_over_E, args.tau0_over_E)
    )
    if si_given and groups_given:
        raise ValueError(
            "give either the nondimensional groups (--R-over-h2, --sigma0-over-E, "
            "--tau0-over-E) or SI inputs (--radius, ...), not both"
        )
    if (args.h1_over_h2 is None) == (args.h1 is None):
        raise ValueError("give exactly one of --h1-over-h2 or --h1 [m]")
    if not si_given:
        if args.R_over_h2 is None or args.sigma0_over_E is None:
            raise ValueError(
                "give --R-over-h2, --h1-over-h2 and --sigma0-over-E (or SI inputs with --radius)"
            )
        return args.R_over_h2, args.h1_over_h2, args.sigma0_over_E, args.tau0_over_E, None
    if args.radius is None:
        raise ValueError("SI inputs need --radius [m]")
    args.R_over_h = None  # what the shared SI builder reads
    args.sigma0_over_E = None
    cyl = _cylinder(args, h_flag="--h2")
    r = args.h1_over_h2 if args.h1 is None else args.h1 / cyl.adhesion_range
    tau = None if args.tau0 is None else args.tau0 / cyl.modulus
    return cyl.R_over_h, r, cyl.sigma0_over_E, tau, cyl


def _cmd_slide(args) -> int:
    rho, r, s, tau, cyl = _setup(args)
    A = _half_widths(args, cyl, "F_over_Eh2")
    if A is not None:
        res = sliding_contact(A, rho, r, s, tau0_over_E=tau, method=args.method)
    else:
        F = (
            np.asarray(args.F_over_Eh2, float)
            if args.F_over_Eh2 is not None
            else np.asarray(args.load, float) / (cyl.modulus * cyl.adhesion_range)
        )
        res = sliding_contact_for_load(F, rho, r, s, tau0_over_E=tau, method=args.method)
    recs = []
    for rec in res.to_records():
        rec["c1_minus_c2_over_R"] = rec["c1_over_R"] - rec["c2_over_R"]
        if tau is None:
            rec.pop("tau0_over_E")
            rec.pop("T_over_Eh2")
        if cyl is not None:
            R, Eh = cyl.radius, cyl.modulus * cyl.adhesion_range
            rec.update(
                a_m=rec["a_over_R"] * R,
                c1_m=rec["c1_over_R"] * R,
                c2_m=rec["c2_over_R"] * R,
                e_m=rec["e_over_R"] * R,
                F_N_per_m=rec["F_over_Eh2"] * Eh,
                M_N=rec["M_over_Eh2R"] * Eh * R,
            )
            if tau is not None:
                rec["T_N_per_m"] = rec["T_over_Eh2"] * Eh
        recs.append(rec)
    if args.json:
        print(_dump_json(recs))
    else:
        keys = [
            "a_over_R",
            "c1_over_R",
            "c2_over_R",
            "e_over_R",
            "F_over_Eh2",
            "M_over_Eh2R",
            "stable",
        ]
        if tau is not None:
            keys.insert(-1, "T_over_Eh2")
        if cyl is not None:
            keys += ["a_m", "F_N_per_m", "M_N"]
        print(
            f"# steady sliding, R/h2 = {rho:g}, h1/h2 = {r:g}, sigma0/E = {s:g} "
            f"({res.method}); M clockwise positive about the contact centre"
        )
        print(_table(recs, keys))
    return 0
