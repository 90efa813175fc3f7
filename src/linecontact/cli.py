"""Command-line interface: a thin shell over the public API.

Every subcommand takes the paper's nondimensional groups or SI inputs, prints a readable
table, or with ``--json`` machine-readable JSON. Bad input: one ``error:`` line on stderr and
exit status 2. A solver that misses its tolerance: exit status 1.
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import math
import re
import sys
import warnings
from collections.abc import Sequence

import numpy as np

from . import __version__
from .cli_sliding import register_slide
from .errors import ConvergenceError

CITATION = f"""linecontact {__version__}: adhesive contact mechanics of a cylinder on a substrate.

If you use it, please cite the paper it implements:
  I. Sari, G. G. Adams, S. Muftu, "Nano-scale effects in the adherence, sliding and rolling
  of a cylinder on a substrate", and the closed forms used (see the README, "References"):
  J. M. Baney, C.-Y. Hui, J. Adhesion Sci. Technol. 11 (1997) 393, doi:10.1163/156856197X00796
  K. L. Johnson, J. A. Greenwood, J. Phys. D 41 (2008) 155315, doi:10.1088/0022-3727/41/15/155315
"""


#: Values that are numbers even though they start with "-": argparse (before Python 3.13)
#: knows only -5 and -0.5, so "--load -1e-3" failed with "expected one argument".
_NEGATIVE_NUMBER = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^-(inf|infinity|nan)$",
                              re.IGNORECASE)


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
    g.add_argument("--sigma0-over-E", type=float,
                   help="adhesive stress over composite modulus, >= 0 (0: Hertz)")
    si = _add_si_materials(p)
    si.add_argument("--h", type=float, help="range of the adhesive stress [m]")
    si.add_argument("--work-of-adhesion", type=float, help="w [J/m^2] (with --z0)")
    si.add_argument("--z0", type=float, help="equilibrium spacing [m] (Maugis: h = 0.974 z0)")


def _cylinder(args, h_flag: str = "--h"):
    """A Cylinder for SI mode, or None in nondimensional mode."""
    from .materials import Cylinder

    si_given = any(getattr(args, k) is not None for k in
                   ("radius", "modulus", "E1", "nu1", "E2", "nu2", "sigma0", "h",
                    "work_of_adhesion", "z0"))
    groups_given = args.R_over_h is not None or args.sigma0_over_E is not None
    if si_given and groups_given:
        raise ValueError("give either the nondimensional groups (--R-over-h, --sigma0-over-E) "
                         "or SI inputs (--radius, ...), not both")
    if not si_given:
        if args.R_over_h is None or args.sigma0_over_E is None:
            raise ValueError("give --R-over-h and --sigma0-over-E (or SI inputs with --radius)")
        return None
    if args.radius is None:
        raise ValueError("SI inputs need --radius [m]")
    if args.h is None and args.work_of_adhesion is None and args.z0 is None:
        raise ValueError(f"SI inputs need the adhesion range {h_flag} [m] (it sets R/h even "
                         f"without adhesion), or --work-of-adhesion with --z0")
    adh = dict(cohesive_stress=args.sigma0, adhesion_range=args.h,
               work_of_adhesion=args.work_of_adhesion, equilibrium_spacing=args.z0)
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
    p.add_argument("--a-over-R-range", type=float, nargs=3, metavar=("START", "STOP", "NUM"),
                   help="linearly spaced contact half-widths")
    p.add_argument(load_flag, type=float, nargs="+", metavar="F", help=load_help)
    p.add_argument("--a", type=float, nargs="+", help="contact half-widths [m] (SI mode)")
    p.add_argument("--load", type=float, nargs="+", help="normal loads [N/m] (SI mode)")


def _half_widths(args, cyl, load_attr: str):
    """Contact half-widths a/R from --a-over-R, --a-over-R-range or --a [m]; None for loads.

    Exactly one of those, ``--<load_attr>`` or ``--load`` [N/m] must be given.
    """
    flag = "--" + load_attr.replace("_", "-")
    given = [args.a_over_R is not None, args.a_over_R_range is not None,
             getattr(args, load_attr) is not None, args.a is not None, args.load is not None]
    if sum(given) != 1:
        raise ValueError(f"give exactly one of --a-over-R, --a-over-R-range, {flag}, "
                         "--a [m] or --load [N/m]")
    if (args.a is not None or args.load is not None) and cyl is None:
        raise ValueError("--a and --load are SI inputs: give --radius and the materials too")
    if args.a_over_R_range is not None:
        start, stop, num = args.a_over_R_range
        for name, v in (("START", start), ("STOP", stop)):
            if not (math.isfinite(v) and v > 0):
                raise ValueError(f"--a-over-R-range {name} must be a finite number > 0, got "
                                 f"{v!r}")
        if not (math.isfinite(num) and float(num).is_integer() and 1 <= num <= _MAX_POINTS):
            raise ValueError(f"--a-over-R-range NUM must be an integer in [1, {_MAX_POINTS}], "
                             f"got {num!r}")
        return np.linspace(start, stop, int(num))
    if args.a_over_R is not None:
        return np.asarray(args.a_over_R, float)
    if args.a is not None:
        return np.asarray(args.a, float) / cyl.radius
    return None


# --- subcommands --------------------------------------------------------------------------


def _cmd_normal(args) -> int:
    from .normal import contact_for_load, normal_contact

    rho, s, cyl = _groups(args)
    A = _half_widths(args, cyl, "F_over_Eh")
    if A is not None:
        if args.branch != "stable":
            raise ValueError("--branch applies to given loads (--F-over-Eh or --load): a "
                             "contact half-width fixes the state")
        r = normal_contact(A, rho, s, method=args.method)
    else:
        if args.method != "closed-form":
            raise ValueError("--method collocation applies to given contact half-widths "
                             "(--a-over-R, --a-over-R-range or --a); the contact for a given "
                             "load is found by the closed form")
        if args.F_over_Eh is not None:
            r = contact_for_load(np.asarray(args.F_over_Eh, float), rho, s, branch=args.branch)
        else:  # through the Cylinder, which speaks of a load below pull-off in N/m
            r = cyl.contact(load=np.asarray(args.load, float), branch=args.branch).nondimensional
    recs = []
    for i in range(np.size(r.a_over_R)):
        def g(name, i=i):
            return np.atleast_1d(getattr(r, name))[i]

        rec = {"a_over_R": float(g("a_over_R")), "c_over_R": float(g("c_over_R")),
               "F_over_Eh": float(g("F_over_Eh")),
               "c_over_a": float(g("c_over_R") / g("a_over_R")),
               "stable": bool(g("stable")), "R_over_h": float(rho), "sigma0_over_E": float(s),
               "method": r.method, "n_collocation": int(g("n_collocation")),
               "residual_separation": float(g("residual_separation")),
               "error_estimate": float(g("error_estimate")), "converged": bool(g("converged"))}
        if cyl is not None:
            rec.update(a_m=rec["a_over_R"] * cyl.radius, c_m=rec["c_over_R"] * cyl.radius,
                       F_N_per_m=rec["F_over_Eh"] * cyl.modulus * cyl.adhesion_range)
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
    from .normal import pull_off

    rho, s, cyl = _groups(args)
    p = pull_off(rho, s)
    rec = p.to_dict()
    if cyl is not None:
        Eh = cyl.modulus * cyl.adhesion_range
        rec.update(F_pulloff_N_per_m=rec["F_pulloff_over_Eh"] * Eh,
                   a_at_pulloff_m=rec["a_over_R_at_pulloff"] * cyl.radius,
                   F_zero_width_N_per_m=rec["F_zero_width_over_Eh"] * Eh)
    if args.json:
        print(_dump_json(rec))
    else:
        print(f"# pull-off under load control, R/h = {rho:g}, sigma0/E = {s:g}")
        w = max(len(k) for k in rec)
        for k, v in rec.items():
            print(f"{k.ljust(w)}  {v:.10g}" if isinstance(v, float) else f"{k.ljust(w)}  {v}")
    return 0


def _cmd_curve(args) -> int:
    from .normal import load_curve

    rho, s, _ = _groups(args)
    for flag, v in (("--num", args.num), ("--num-noncontact", args.num_noncontact)):
        if not 2 <= v <= _MAX_POINTS:
            raise ValueError(f"{flag} must be an integer in [2, {_MAX_POINTS}], got {v!r}")
    c = load_curve(rho, s, a_max_over_R=args.a_max_over_R, num=args.num,
                   num_noncontact=args.num_noncontact)
    keys = ["branch", "central_gap_over_h", "a_over_R", "c_over_R", "F_over_Eh", "stable",
            "turning_point", "pulloff"]
    po = c.pulloff
    recs = []
    for i in range(c.a_over_R.size):
        is_po = (c.branch[i] == "contact" and
                 ((po.mechanism == "zero-width" and i == int(np.argmax(c.branch == "contact")))
                  or (po.mechanism == "snap-off" and bool(c.turning_point[i]))))
        recs.append({"branch": str(c.branch[i]),
                     "central_gap_over_h": float(c.central_gap_over_h[i]),
                     "a_over_R": float(c.a_over_R[i]), "c_over_R": float(c.c_over_R[i]),
                     "F_over_Eh": float(c.F_over_Eh[i]), "stable": bool(c.stable[i]),
                     "turning_point": bool(c.turning_point[i]), "pulloff": bool(is_po)})
    if args.format == "json":
        text = _dump_json({"R_over_h": rho, "sigma0_over_E": s, "pulloff": po.to_dict(),
                           "points": recs})
    else:
        buf = io.StringIO()
        buf.write(f"# linecontact {__version__} load curve\n# command: linecontact "
                  f"{' '.join(sys.argv[1:]) if args.argv is None else ' '.join(args.argv)}\n"
                  f"# R_over_h = {rho!r}, sigma0_over_E = {s!r}\n"
                  f"# units: lengths over R, gap over h, force per unit length over E h\n"
                  f"# pull-off: F_over_Eh = {po.F_pulloff_over_Eh!r} ({po.mechanism}) at "
                  f"a_over_R = {po.a_over_R_at_pulloff!r}\n")
        w = csv.DictWriter(buf, fieldnames=keys, lineterminator="\n")
        w.writeheader()
        w.writerows(recs)
        text = buf.getvalue()
    if args.output:
        try:
            with open(args.output, "w", encoding="utf-8") as fh:
                fh.write(text if text.endswith("\n") else text + "\n")
        except OSError as exc:
            raise ValueError(f"cannot write -o/--output {args.output!r}: "
                             f"{exc.strerror or exc}") from None
        print(f"wrote {args.output}", file=sys.stderr)
    else:
        print(text.rstrip("\n"))
    return 0


def _cmd_paper(args) -> int:
    from .figures import paper_figures

    def progress(msg: str) -> None:
        print(msg, file=sys.stderr)

    try:
        paths = paper_figures(args.outdir, progress=progress)
    except OSError as exc:
        raise ValueError(f"cannot write the figures to --outdir {args.outdir!r}: "
                         f"{exc.strerror or exc}") from None
    print(f"wrote {len(paths)} files to {args.outdir}/:")
    for p in paths:
        print(f"  {p}")
    return 0


def _cmd_cite(args) -> int:
    print(CITATION.rstrip("\n"))
    return 0


def build_parser() -> argparse.ArgumentParser:
    """The argparse parser of the ``linecontact`` command."""
    p = _Parser(prog="linecontact",
                description="Adhesive (Maugis-Dugdale) contact of a cylinder on a substrate.",
                epilog="Conventions: compressive load positive (pull-off forces are negative); "
                       "forces per unit length.")
    p.add_argument("--version", action="version", version=CITATION.rstrip("\n"))
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)

    n = sub.add_parser("normal", help="adhesive-zone width and load for given contact widths "
                                      "(or the contact for given loads)")
    _add_groups(n)
    _add_width_options(n, "--F-over-Eh", "loads (inverse problem)")
    n.add_argument("--branch", choices=("stable", "unstable"), default="stable",
                   help="for given loads: the stable (default) or unstable contact")
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
    cu.add_argument("--json", action="store_const", dest="format", const="json",
                    help="same as --format json")
    cu.add_argument("-o", "--output", help="write to this file instead of stdout")
    cu.set_defaults(func=_cmd_curve)

    from .cli_tangential import add_subcommands as _add_tangential  # slide-init, roll
    _add_tangential(sub)
    register_slide(sub)

    pa = sub.add_parser("paper", help="reproduce the paper's figures (PNG and SVG)")
    pa.add_argument("--outdir", default="paper-figures")
    pa.set_defaults(func=_cmd_paper)

    ci = sub.add_parser("cite", help="how to cite linecontact and the paper")
    ci.set_defaults(func=_cmd_cite)
    return p


def main(argv: Sequence[str] | None = None) -> int:
    """Run the CLI; returns the exit status (also usable in-process by tests)."""
    parser = build_parser()
    args = parser.parse_args(argv)
    args.argv = list(argv) if argv is not None else None
    if args.command is None:
        print("linecontact: error: give a command: normal, pulloff, curve, slide-init, roll, "
              "slide, paper or cite (linecontact --help lists them)", file=sys.stderr)
        return 2
    def one_line_warning(message, category, filename, lineno, file=None, line=None):
        print(f"linecontact {args.command}: warning: {message}", file=sys.stderr)

    try:
        with warnings.catch_warnings():
            warnings.showwarning = one_line_warning
            return int(args.func(args))
    except ConvergenceError as exc:
        print(f"linecontact {args.command}: error: {exc}", file=sys.stderr)
        return 1
    except (ValueError, OverflowError) as exc:
        print(f"linecontact {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except ImportError as exc:
        print(f"linecontact {args.command}: error: {exc}", file=sys.stderr)
        return 1
    except Exception as exc:  # noqa: BLE001 - the CLI never shows a traceback
        print(f"linecontact {args.command}: error: internal error "
              f"({type(exc).__name__}: {exc}); please report it", file=sys.stderr)
        return 1


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
