"""Shared pieces of the subcommands: the parser, the common options, the SI inputs, the output.

Every subcommand module builds its parser with :class:`Parser` and the option groups here,
computes its results through the public API, and hands a :class:`~linecontact.output.Table`
to :func:`emit`. Errors are :class:`ValueError` (exit status 2) whose message names the
flags; :func:`flag_message` turns the API's parameter names into the flags the user typed.
"""

from __future__ import annotations

import argparse
import sys
import textwrap
from collections.abc import Sequence
from typing import Any

import numpy as np

from ..operations._common import (  # noqa: F401 - the subcommands' names for them, kept here
    MAX_POINTS,
    SI_KEYS,
    _check_lennard_jones_groups,
    _presets,
    _work_flag,
    check_widths,
    cylinder,
    groups,
    half_widths,
    null_missing,
    si_columns,
    si_given,
    si_loads,
    si_parameters,
)
from ..operations._messages import (  # noqa: F401 - the subcommands' names for them, kept here
    _NEGATIVE_NUMBER,
    API_FLAGS,
    COUPLING_EFFECT,
    coupling_effect,
    flag_message,
    is_units_warning,
    write_failure,
)
from ..output import FORMATS, Table, write


class HelpFormatter(argparse.RawDescriptionHelpFormatter):
    """Keeps the line breaks of descriptions and examples; appends every real default.

    Options joined by :func:`show_together` share one entry (the first one's help), so that
    a subcommand's help fits one screen.
    """

    def __init__(self, prog: str, **kwargs: Any) -> None:
        kwargs.setdefault("max_help_position", 34)
        super().__init__(prog, **kwargs)

    def add_argument(self, action: argparse.Action) -> None:
        if getattr(action, "shown_with", None) is None:  # else in its partner's entry
            super().add_argument(action)

    def _format_action(self, action: argparse.Action) -> str:
        # an entry too long for the column: its help on the same line where it fits
        help_position = min(self._action_max_length + 2, self._max_help_position)
        invocation = self._format_action_invocation(action)
        if action.help and len(invocation) > help_position - self._current_indent - 2:
            text = " ".join(self._expand_help(action).split())
            line = f"{' ' * self._current_indent}{invocation}  {text}"
            if len(line) <= self._width:
                return line + "\n"
        return super()._format_action(action)

    def _format_action_invocation(self, action: argparse.Action) -> str:
        return ", ".join(
            super(HelpFormatter, self)._format_action_invocation(a)
            for a in (action, *getattr(action, "partners", ()))
        )

    def _get_help_string(self, action: argparse.Action) -> str:
        text = action.help or ""
        default = action.default
        if (
            "%(default)" not in text
            and action.option_strings
            and default not in (None, False, argparse.SUPPRESS)
            and not isinstance(action, argparse._HelpAction | argparse._VersionAction)
        ):
            text += " (default: %(default)s)"
        return text


class Parser(argparse.ArgumentParser):
    """argparse with negative numbers as values and one-line errors (exit status 2)."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        kwargs.setdefault("formatter_class", HelpFormatter)
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = _NEGATIVE_NUMBER

    def error(self, message: str):  # argparse's own errors: one line, exit 2
        self.exit(2, f"{self.prog}: error: {message}\n")

    def _print_message(self, message: str, file: Any = None) -> None:
        # argparse swallows a failed write; --help or --version to a full disk is an error
        # (linecontact.cli.main reports it), as any other output is
        if message:
            (file or sys.stderr).write(message)


class _Deprecated(argparse.Action):
    """An old spelling of an option: does what the new one does, and says the new name.

    The note (one ``warning:`` line, :func:`linecontact.cli.main` prints it) is kept in the
    namespace's ``_deprecated``; the value goes through the new option's own action.
    """

    def __init__(self, option_strings: Any, dest: str, target: argparse.Action, **kw: Any):
        self.target = target
        super().__init__(option_strings, dest, **kw)

    def __call__(self, parser: Any, namespace: Any, values: Any, option_string: Any = None):
        new = self.target.option_strings[-1]
        notes = list(getattr(namespace, "_deprecated", None) or [])
        note = f"{option_string} is deprecated: use {new} (same meaning)"
        if note not in notes:
            notes.append(note)
        namespace._deprecated = notes
        namespace._typed_as = {**(getattr(namespace, "_typed_as", None) or {}), new: option_string}
        self.target(parser, namespace, values, new)


def deprecated_alias(p: argparse.ArgumentParser, old: str, new: str, g: Any = None) -> None:
    """Accept ``old`` as a hidden, deprecated spelling of the option ``new`` of ``p``.

    It takes the same values (same type, count and choices) and stores them where ``new``
    does; the run prints one ``warning:`` line that names ``new``. Not in the help.
    """
    target = p._option_string_actions[new]
    # the target's own dest, count, choices and metavar (and type, where it has one)
    kw = {k: getattr(target, k) for k in ("dest", "nargs", "choices", "metavar")}
    if target.type is not None:
        kw["type"] = target.type
    (g or p).add_argument(
        old,
        action=_Deprecated,
        target=target,
        **kw,
        default=argparse.SUPPRESS,
        help=argparse.SUPPRESS,
    )


def add_command(sub: Any, name: str, summary: str, description: str, examples: Sequence[str]):
    """A subcommand parser with a one-line summary, a description and examples in its help.

    Its help fits one screen (under 40 lines at 100 columns, a test keeps it so): a short
    description, two or three examples, a one-line usage; the details are in docs/cli.md.
    """
    epilog = "examples:\n" + "\n".join(f"  {e}" for e in examples)
    return sub.add_parser(
        name,
        help=summary,
        description=textwrap.fill(description, 88),
        epilog=epilog,
        usage="%(prog)s [options]",
    )


def show_together(p: argparse.ArgumentParser, *flags: str, help: str) -> None:
    """Show the options ``flags`` as one entry of ``p``'s help, with ``help``.

    Each option keeps its own ``help`` (for the record); the first one's is replaced. The
    entry stands where the first option stands.
    """
    first, *rest = (p._option_string_actions[f] for f in flags)
    first.help = help
    first.partners = tuple(rest)  # type: ignore[attr-defined]
    for a in rest:
        a.shown_with = first  # type: ignore[attr-defined]


# --------------------------------------------------------------------------------------------
# output and warnings


class _DataOrImageFormat(argparse.Action):
    """``--format`` of a command that also draws (``map``): a data format, or the figure's.

    The figure's formats (deprecated here) now go to ``--image-format``.
    """

    def __call__(self, parser: Any, namespace: Any, values: Any, option_string: Any = None):
        if values in FORMATS:
            setattr(namespace, self.dest, values)
            return
        images = ("png", "svg", "pdf")  # linecontact.figures._style.FORMATS (no matplotlib)
        names = [t.strip().lower().lstrip(".") for t in str(values).split(",")]
        if not names or not all(n in images for n in names):
            parser.error(
                f"argument --format: invalid choice: {values!r} (choose from "
                f"{', '.join(FORMATS)}; the figure's formats go to --image-format)"
            )
        notes = list(getattr(namespace, "_deprecated", None) or [])
        notes.append(
            f"--format {values} (image formats) is deprecated: use --image-format {values} "
            "(--format is the format of the data)"
        )
        namespace._deprecated = notes
        namespace.image_format = values


def add_output_options(p: argparse.ArgumentParser, image_alias: bool = False) -> None:
    """``--format``, ``--json``, ``-o``, ``--indent`` and ``--quiet`` (with the command's own).

    ``image_alias``: ``--format`` also takes, deprecated, the image formats of
    ``--image-format`` (which the command has), as it did before it took data formats.
    """
    g = p
    g.add_argument(
        "--format",
        **(
            {"action": _DataOrImageFormat, "default": None} if image_alias else {"choices": FORMATS}
        ),
        metavar="FORMAT",
        help="table (readable), json (one object: provenance and results), jsonl (provenance "
        "line, then one record per line) or csv (commented provenance header) (default: from "
        "the extension of -o FILE, else table)",
    )
    g.add_argument(
        "--json",
        action="store_const",
        dest="format",
        const="json",
        help="same as --format json",
    )
    g.add_argument("-o", "--output", metavar="FILE", help="write to FILE (atomically), not stdout")
    g.add_argument(
        "--indent", type=int, metavar="N", help="indent JSON by N spaces (compact without)"
    )
    g.add_argument(
        "--quiet",
        action="store_true",
        help="do not print the model notes (coupling, small strain); units warnings still print",
    )
    show_together(
        p,
        "--format",
        "--json",
        help="table, json, jsonl, csv (default: -o's extension, else table)",
    )
    show_together(
        p, "--indent", "--quiet", help="indent JSON by N spaces (else compact); no model notes"
    )


def emit(args: argparse.Namespace, table: Table, checked: bool = False) -> None:
    """Write ``table`` as asked (stdout or ``-o FILE``).

    ``checked``: its SI widths were checked by the operation that computed it.
    """
    if args.indent is not None and not 0 <= args.indent <= 16:
        raise ValueError(f"--indent must be an integer in [0, 16], got {args.indent}")
    if not checked:
        check_widths(table)
    ext = "" if args.output is None else args.output.rsplit(".", 1)[-1].lower()
    fmt = args.format or (ext if ext in FORMATS and ext != "table" else "table")
    if args.output is None:
        try:
            write(table, fmt, indent=args.indent)
        except BrokenPipeError:
            raise
        except OSError as exc:  # a write to standard output: said so (linecontact.cli.main)
            exc.stream = "stdout"  # type: ignore[attr-defined]
            raise
    else:
        try:
            write(table, fmt, args.output, indent=args.indent, name="-o/--output")
        except OSError as exc:
            raise write_failure(f"-o/--output {args.output!r}", exc) from None
        if not args.quiet:
            print(f"wrote {args.output}", file=sys.stderr)


class NoPointError(Exception):
    """No point of a run could be computed: the output is written, the exit status is 1."""


def finish(table: Table, good: str | tuple[str, ...]) -> int:
    """Exit status 0 when a point has a state in ``good``; else raise :class:`NoPointError`.

    A multi-point run never fails as a whole because some points have no state: they carry
    ``state`` and ``reason`` and null values (:func:`null_missing`).
    """
    state = table.columns.get("state")
    good = (good,) if isinstance(good, str) else good
    if state is None or table.size == 0 or np.isin(state, good).any():
        return 0
    reasons = (
        [r for r in table.columns["reason"].tolist() if r] if "reason" in table.columns else []
    )
    raise NoPointError(reasons[0] if reasons else "no point could be computed")


def command_line(args: argparse.Namespace) -> list[str]:
    """The command line as given (for the provenance block)."""
    argv = args.argv if args.argv is not None else sys.argv[1:]
    return ["linecontact", *argv]


# --------------------------------------------------------------------------------------------
# material, adhesion and geometry in SI units


def add_si_materials(p: argparse.ArgumentParser, range_flag: str = "--h") -> Any:
    """The SI group: radius, moduli, adhesion (the caller may add more to it) and ``--length``."""
    si = p.add_argument_group("SI inputs (instead of the groups)")
    si.add_argument("--radius", type=float, metavar="R", help="cylinder radius R [m]")
    si.add_argument(
        "--modulus", type=float, metavar="E", help="composite plane-strain modulus E [Pa]"
    )
    si.add_argument("--E1", type=float, help="cylinder's Young's modulus [Pa] (with --nu1 ...)")
    si.add_argument("--nu1", type=float, help="cylinder's Poisson ratio, in (-1, 0.5]")
    si.add_argument("--E2", type=float, help="substrate's Young's modulus [Pa]")
    si.add_argument("--nu2", type=float, help="substrate's Poisson ratio, in (-1, 0.5]")
    si.add_argument(
        "--cylinder-material",
        metavar="NAME",
        help="cylinder's material preset, instead of --E1 --nu1 (case-insensitive; names: "
        "`linecontact materials`)",
    )
    si.add_argument(
        "--substrate-material",
        metavar="NAME",
        help="substrate's material preset, instead of --E2 --nu2 (names as for "
        "--cylinder-material)",
    )
    si.add_argument(
        "--sigma0", type=float, metavar="S", help="adhesive (Dugdale) stress sigma0 [Pa]"
    )
    name = "leading-edge adhesion range h2" if range_flag == "--h2" else "adhesion range h"
    work = _work_flag(range_flag)
    si.add_argument(
        range_flag,
        dest="h",
        type=float,
        metavar="H",
        help=f"{name} [m] (sets R/h even without adhesion)",
    )
    si.add_argument(
        work,
        dest="work_of_adhesion",
        type=float,
        metavar="W",
        help=f"{'advancing ' if work != '--work-of-adhesion' else ''}work of adhesion w "
        f"[J/m^2] (with --z0, instead of --sigma0 and "
        f"{range_flag}: sigma0 = 16 w/(9 sqrt(3) z0), {range_flag} = 0.974 z0)",
    )
    si.add_argument(
        "--z0", type=float, metavar="Z", help="equilibrium spacing of the surfaces z0 [m]"
    )
    si.add_argument(
        "--length",
        type=float,
        metavar="L",
        help="length of the fibre [m]: adds total forces [N] and moments [N m]",
    )
    rng = range_flag[2:]
    show_together(
        p,
        "--radius",
        "--length",
        help="cylinder radius R [m]; fibre length [m] (adds totals [N], [N m])",
    )
    p._option_string_actions[
        "--modulus"
    ].help = "composite plane-strain modulus [Pa], or the materials:"
    show_together(
        p,
        "--E1",
        "--nu1",
        "--E2",
        "--nu2",
        help="Young's moduli [Pa], Poisson ratios (1: cylinder)",
    )
    show_together(
        p,
        "--cylinder-material",
        "--substrate-material",
        help="or presets (names: `linecontact materials`)",
    )
    show_together(
        p,
        "--sigma0",
        range_flag,
        work,
        "--z0",
        help=f"sigma0 [Pa], {rng} [m]; or w [J/m^2], z0 [m]",
    )
    if work != "--work-of-adhesion":  # it was --work-of-adhesion, which meant this one
        deprecated_alias(p, "--work-of-adhesion", work, si)
    return si


def add_groups(p: argparse.ArgumentParser, g: Any = None) -> None:
    """The groups ``--R-over-h``, ``--sigma0-over-E`` and the SI inputs that replace them.

    The groups go into the argument group ``g`` (default: a group of their own).
    """
    g = g or p.add_argument_group("nondimensional groups (the paper's)")
    g.add_argument("--R-over-h", type=float, metavar="R/h", help="radius over adhesion range, > 0")
    g.add_argument(
        "--sigma0-over-E",
        type=float,
        metavar="S",
        help="adhesive stress over composite modulus, >= 0 (0: Hertz)",
    )
    add_si_materials(p)


# --------------------------------------------------------------------------------------------
# contact widths or loads


def add_width_options(p: Any, load_flag: str, load_help: str) -> None:
    """The options read by :func:`half_widths`: widths or loads, nondimensional or SI."""
    p.add_argument(
        "--a-over-R", type=float, nargs="+", metavar="A", help="contact half-widths a/R, > 0"
    )
    p.add_argument(
        "--a-over-R-range",
        type=float,
        nargs=3,
        metavar=("START", "STOP", "NUM"),
        help="NUM linearly spaced contact half-widths a/R from START to STOP",
    )
    p.add_argument(load_flag, type=float, nargs="+", metavar="F", help=load_help)
    p.add_argument(
        "--half-width",
        dest="a",
        type=float,
        nargs="+",
        metavar="A",
        help="contact half-widths a [m] (SI inputs)",
    )
    p.add_argument(
        "--load", type=float, nargs="+", help="normal loads per unit length F [N/m] (SI inputs)"
    )
    deprecated_alias(p, "--a", "--half-width")


def record_flags(parser: argparse.ArgumentParser, args: argparse.Namespace) -> None:
    """Remember the flag of every option (by its dest), and which take choices.

    For :func:`flag_message`.
    """
    flags: dict[str, str] = {}
    choices: set[str] = set()
    for action in parser._actions:
        longs = [s for s in action.option_strings if s.startswith("--")]
        if longs and action.dest not in flags:
            flags[action.dest] = longs[0]
        if longs and action.choices is not None:
            choices.update(longs)
    args._flags = flags
    args._choice_flags = choices
