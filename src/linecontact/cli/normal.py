"""The subcommands of normal contact: ``normal``, ``pulloff`` and ``curve``."""

from __future__ import annotations

import csv
import io
import sys

import numpy as np

from .._version import __version__
from ..normal import contact_for_load, load_curve, normal_contact, pull_off
from ._options import (
    _MAX_POINTS,
    _add_groups,
    _add_width_options,
    _dump_json,
    _groups,
    _half_widths,
    _table,
)


def _cmd_normal(args) -> int:
    rho, s, cyl = _groups(args)
    A = _half_widths(args, cyl, "F_over_Eh")
    if A is not None:
        if args.branch != "stable":
            raise ValueError(
                "--branch applies to given loads (--F-over-Eh or --load): a "
                "contact half-width fixes the state"
            )
        r = normal_contact(A, rho, s, method=args.method)
    else:
        if args.method != "closed-form":
            raise ValueError(
                "--method collocation applies to given contact half-widths "
                "(--a-over-R, --a-over-R-range or --a); the contact for a given "
                "load is found by the closed form"
            )
        if args.F_over_Eh is not None:
            r = contact_for_load(np.asarray(args.F_over_Eh, float), rho, s, branch=args.branch)
        else:  # through the Cylinder, which speaks of a load below pull-off in N/m
            r = cyl.contact(load=np.asarray(args.load, float), branch=args.branch).nondimensional
    recs = []
    for i in range(np.size(r.a_over_R)):

        def g(name, i=i):
            return np.atleast_1d(getattr(r, name))[i]

        rec = {
            "a_over_R": float(g("a_over_R")),
            "c_over_R": float(g("c_over_R")),
            "F_over_Eh": float(g("F_over_Eh")),
            "c_over_a": float(g("c_over_R") / g("a_over_R")),
            "stable": bool(g("stable")),
            "R_over_h": float(rho),
            "sigma0_over_E": float(s),
            "method": r.method,
            "n_collocation": int(g("n_collocation")),
            "residual_separation": float(g("residual_separation")),
            "error_estimate": float(g("error_estimate")),
            "converged": bool(g("converged")),
        }
        if cyl is not None:
            rec.update(
                a_m=rec["a_over_R"] * cyl.radius,
                c_m=rec["c_over_R"] * cyl.radius,
                F_N_per_m=rec["F_over_Eh"] * cyl.modulus * cyl.adhesion_range,
            )
        recs.append(rec)
    if args.json:
        print(_dump_json(recs))
    else:
        keys = ["a_over_R", "c_over_R", "F_over_Eh", "c_over_a", "stable"]
        if cyl is not None:
            keys += ["a_m", "c_m", "F_N_per_m"]
        print(f"# normal contact, R/h = {rho:g}, sigma0/E = {s:g} ({r.method})")
        print(_table(recs, keys))
    return 0


def _cmd_pulloff(args) -> int:
    rho, s, cyl = _groups(args)
    p = pull_off(rho, s)
    rec = p.to_dict()
    if cyl is not None:
        Eh = cyl.modulus * cyl.adhesion_range
        rec.update(
            F_pulloff_N_per_m=rec["F_pulloff_over_Eh"] * Eh,
            a_at_pulloff_m=rec["a_over_R_at_pulloff"] * cyl.radius,
            F_zero_width_N_per_m=rec["F_zero_width_over_Eh"] * Eh,
        )
    if args.json:
        print(_dump_json(rec))
    else:
        print(f"# pull-off under load control, R/h = {rho:g}, sigma0/E = {s:g}")
        w = max(len(k) for k in rec)
        for k, v in rec.items():
            print(f"{k.ljust(w)}  {v:.10g}" if isinstance(v, float) else f"{k.ljust(w)}  {v}")
    return 0


def _cmd_curve(args) -> int:
    rho, s, _ = _groups(args)
    for flag, v in (("--num", args.num), ("--num-noncontact", args.num_noncontact)):
        if not 2 <= v <= _MAX_POINTS:
            raise ValueError(f"{flag} must be an integer in [2, {_MAX_POINTS}], got {v!r}")
    c = load_curve(
        rho, s, a_max_over_R=args.a_max_over_R, num=args.num, num_noncontact=args.num_noncontact
    )
    keys = [
        "branch",
        "central_gap_over_h",
        "a_over_R",
        "c_over_R",
        "F_over_Eh",
        "stable",
        "turning_point",
        "pulloff",
    ]
    po = c.pulloff
    recs = []
    for i in range(c.a_over_R.size):
        is_po = c.branch[i] == "contact" and (
            (po.mechanism == "zero-width" and i == int(np.argmax(c.branch == "contact")))
            or (po.mechanism == "snap-off" and bool(c.turning_point[i]))
        )
        recs.append(
            {
                "branch": str(c.branch[i]),
                "central_gap_over_h": float(c.central_gap_over_h[i]),
                "a_over_R": float(c.a_over_R[i]),
                "c_over_R": float(c.c_over_R[i]),
                "F_over_Eh": float(c.F_over_Eh[i]),
                "stable": bool(c.stable[i]),
                "turning_point": bool(c.turning_point[i]),
                "pulloff": bool(is_po),
            }
        )
    if args.format == "json":
        text = _dump_json(
            {"R_over_h": rho, "sigma0_over_E": s, "pulloff": po.to_dict(), "points": recs}
        )
    else:
        buf = io.StringIO()
        buf.write(
            f"# linecontact {__version__} load curve\n# command: linecontact "
            f"{' '.join(sys.argv[1:]) if args.argv is None else ' '.join(args.argv)}\n"
            f"# R_over_h = {rho!r}, sigma0_over_E = {s!r}\n"
            f"# units: lengths over R, gap over h, force per unit length over E h\n"
            f"# pull-off: F_over_Eh = {po.F_pulloff_over_Eh!r} ({po.mechanism}) at "
            f"a_over_R = {po.a_over_R_at_pulloff!r}\n"
        )
        w = csv.DictWriter(buf, fieldnames=keys, lineterminator="\n")
        w.writeheader()
        w.writerows(recs)
        text = buf.getvalue()
    if args.output:
        try:
            with open(args.output, "w", encoding="utf-8") as fh:
                fh.write(text if text.endswith("\n") else text + "\n")
        except OSError as exc:
            raise ValueError(
                f"cannot write -o/--output {args.output!r}: {exc.strerror or exc}"
            ) from None
        print(f"wrote {args.output}", file=sys.stderr)
    else:
        print(text.rstrip("\n"))
    return 0


def register(sub) -> None:
    """Add ``normal``, ``pulloff`` and ``curve`` to the subparsers ``sub``."""
    n = sub.add_parser(
        "normal",
        help="adhesive-zone width and load for given contact widths "
        "(or the contact for given loads)",
    )
    _add_groups(n)
    _add_width_options(n, "--F-over-Eh", "loads (inverse problem)")
    n.add_argument(
        "--branch",
        choices=("stable", "unstable"),
        default="stable",
        help="for given loads: the stable (default) or unstable contact",
    )
    n.add_argument("--method", choices=("closed-form", "collocation"), default="closed-form")
    n.add_argument("--json", action="store_true", help="JSON array of records on stdout")
    n.set_defaults(func=_cmd_normal)

    po = sub.add_parser("pulloff", help="pull-off force under load control")
    _add_groups(po)
    po.add_argument("--json", action="store_true", help="one JSON object on stdout")
    po.set_defaults(func=_cmd_pulloff)

    cu = sub.add_parser("curve", help="the whole load curve (non-contact branch included)")
    _add_groups(cu)
    cu.add_argument("--a-max-over-R", type=float, default=None)
    cu.add_argument("--num", type=int, default=200, help="points on the contact branch")
    cu.add_argument("--num-noncontact", type=int, default=40)
    cu.add_argument("--format", choices=("csv", "json"), default="csv")
    cu.add_argument(
        "--json", action="store_const", dest="format", const="json", help="same as --format json"
    )
    cu.add_argument("-o", "--output", help="write to this file instead of stdout")
    cu.set_defaults(func=_cmd_curve)
