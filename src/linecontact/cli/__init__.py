"""Command-line interface: a thin shell over the public API.

One module per family of subcommands (:mod:`~linecontact.cli.normal`,
:mod:`~linecontact.cli.tangential`, :mod:`~linecontact.cli.sliding`,
:mod:`~linecontact.cli.paper`), the shared options and output in
:mod:`~linecontact.cli._options`. Every subcommand takes the paper's nondimensional groups or
SI inputs, prints a readable table, or with ``--json`` machine-readable JSON. Bad input: one
``error:`` line on stderr and exit status 2. A solver that misses its tolerance: exit
status 1.
"""

from __future__ import annotations

import argparse
import sys
import warnings
from collections.abc import Sequence

from ..errors import ConvergenceError
from . import normal as _normal
from . import paper as _paper
from . import sliding as _sliding
from . import tangential as _tangential
from ._options import _Parser
from .paper import CITATION

__all__ = ["build_parser", "main"]


def build_parser() -> argparse.ArgumentParser:
    """The argparse parser of the ``linecontact`` command."""
    p = _Parser(
        prog="linecontact",
        description="Adhesive (Maugis-Dugdale) contact of a cylinder on a substrate.",
        epilog="Conventions: compressive load positive (pull-off forces are negative); "
        "forces per unit length.",
    )
    p.add_argument("--version", action="version", version=CITATION.rstrip("\n"))
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    _normal.register(sub)
    _tangential.register(sub)
    _sliding.register(sub)
    _paper.register(sub)
    return p


def main(argv: Sequence[str] | None = None) -> int:
    """Run the CLI; returns the exit status (also usable in-process by tests)."""
    parser = build_parser()
    args = parser.parse_args(argv)
    args.argv = list(argv) if argv is not None else None
    if args.command is None:
        print(
            "linecontact: error: give a command: normal, pulloff, curve, slide-init, roll, "
            "slide, paper or cite (linecontact --help lists them)",
            file=sys.stderr,
        )
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
        print(
            f"linecontact {args.command}: error: internal error "
            f"({type(exc).__name__}: {exc}); please report it",
            file=sys.stderr,
        )
        return 1
