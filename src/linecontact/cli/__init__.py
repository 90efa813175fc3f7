"""Command-line interface: a thin shell over the public API.

One module per family of subcommands (:mod:`~linecontact.cli.normal`,
:mod:`~linecontact.cli.tangential`, :mod:`~linecontact.cli.history`,
:mod:`~linecontact.cli.sliding`,
:mod:`~linecontact.cli.paper`, :mod:`~linecontact.cli.adhesion_map`,
:mod:`~linecontact.cli.materials`), the shared options and
output in :mod:`~linecontact.cli._options`. Every subcommand takes the paper's
nondimensional groups or SI inputs, prints a readable table, or with ``--json``
machine-readable JSON. Bad input: one ``error:`` line on stderr and exit status 2. A solver
that misses its tolerance: exit status 1.
"""

from __future__ import annotations

import argparse
import errno
import os
import sys
import textwrap
import warnings
from collections.abc import Sequence

from .._interrupt import EXIT_INTERRUPTED, imports_interruptible

with imports_interruptible():  # Ctrl-C here: status 130, one line (linecontact._interrupt)
    from .._version import __version__
    from ..errors import ConvergenceError
    from . import adhesion_map as _adhesion_map
    from . import fit as _fit
    from . import history as _history
    from . import materials as _materials
    from . import normal as _normal
    from . import paper as _paper
    from . import push as _push
    from . import sliding as _sliding
    from . import tangential as _tangential
    from ._options import NoPointError, Parser, flag_message, record_flags

__all__ = ["build_parser", "main"]

_COMMANDS = (
    "normal, pulloff, curve, slide-init, roll, cycle, history, slide, push, fit-adhesion, "
    "fit-friction, paper, figures, map, materials or cite"
)


def build_parser() -> argparse.ArgumentParser:
    """The argparse parser of the ``linecontact`` command."""
    p = Parser(
        prog="linecontact",
        description=textwrap.fill(
            "Adhesive (Maugis-Dugdale) contact mechanics of a cylinder - a nanofibre, "
            "nanowire, nanotube - on an elastic substrate, in plane strain. Every subcommand "
            "takes the paper's nondimensional groups or SI inputs; `linecontact COMMAND "
            "--help` says which.",
            88,
        ),
        epilog=textwrap.fill(
            "Conventions: compressive load positive (pull-off forces are negative); forces "
            "per unit length of cylinder unless --length is given. Output: a table, or with "
            "--format json|jsonl|csv the provenance block (version, command, parameters, "
            "units) and the results.",
            88,
        ),
        allow_abbrev=False,
    )
    p.add_argument(
        "--version",
        action="version",
        version=f"linecontact {__version__}",
        help="print the version and exit",
    )
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=Parser)
    _normal.register(sub)
    _tangential.register(sub)
    _history.register(sub)
    _fit.register(sub)
    _sliding.register(sub)
    _push.register(sub)
    _paper.register(sub)
    _adhesion_map.register(sub)
    _materials.register(sub)
    for sp in sub.choices.values():
        sp.allow_abbrev = False
    p.set_defaults(_subparsers=sub)
    return p


def _silence_stdout() -> None:
    """Send whatever stdout still holds to the null device (after a broken pipe)."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError, AttributeError):  # not a file descriptor (a test's buffer)
        pass


def _flush_stdout() -> None:
    """Flush stdout (where it can be flushed): a failed write raises here, in :func:`main`."""
    flush = getattr(sys.stdout, "flush", None)
    if flush is not None:
        flush()


#: The errors of a write that could not be done (a full disk or quota, a file too large,
#: an I/O error, a closed descriptor): with no file name, a write to stdout, the only file
#: the commands write to without naming it (``-o`` names its file).
_WRITE_ERRNOS = frozenset(
    getattr(errno, name)
    for name in ("ENOSPC", "EDQUOT", "EFBIG", "EIO", "EBADF", "EROFS")
    if hasattr(errno, name)
)


def _stdout_broken(exc: OSError) -> bool:
    """True when ``exc`` is a failed write to stdout."""
    return exc.filename is None and exc.errno in _WRITE_ERRNOS


def _stdout_failed(prefix: str, exc: OSError) -> int:
    """Report a failed write to stdout on stderr; exit status 2."""
    _silence_stdout()  # the interpreter's final flush must not fail again
    reason = exc.strerror or str(exc)
    print(f"{prefix}: error: cannot write to standard output: {reason}", file=sys.stderr)
    return 2


def _help_not_written(err: OSError) -> int:
    """``--help``/``--version`` output that could not be written: as :func:`main` says."""
    if isinstance(err, BrokenPipeError):
        _silence_stdout()
        return 0
    if _stdout_broken(err):
        return _stdout_failed("linecontact", err)
    raise err


def main(argv: Sequence[str] | None = None) -> int:
    """Run the CLI; returns the exit status (also usable in-process by tests).

    Exit status: 0 when the run produced its output (points without a state are records
    with ``state`` and ``reason``), 1 when no point could be computed or a solver failed,
    2 for bad input (one ``error:`` line on stderr naming the flag, no traceback), 130 when
    interrupted (Ctrl-C: one line on stderr, also while the command line starts: see
    :mod:`linecontact._interrupt`). Output piped into a reader that stops early (``| head``,
    EPIPE) ends quietly with status 0, as ``cat`` and ``seq`` do under a shell that ignores
    SIGPIPE; any other failed write to standard output (a full disk, ``> /dev/full``) is one
    ``error: cannot write to standard output: ...`` line on stderr and status 2. A file
    written with ``-o`` appears whole or not at all.
    """
    try:
        parser = build_parser()
        args = parser.parse_args(argv)
    except KeyboardInterrupt:
        print("linecontact: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except SystemExit as exc:  # --help, --version (0) or a usage error (2), already printed
        if exc.code == 0:
            try:
                _flush_stdout()  # the help text to a full disk is an error, as any output
            except OSError as err:
                return _help_not_written(err)
        raise
    except OSError as err:  # the help text failed as it was written (Parser._print_message)
        return _help_not_written(err)
    args.argv = list(argv) if argv is not None else None
    if args.command is None:
        print(
            f"linecontact: error: give a command: {_COMMANDS} (linecontact --help lists them)",
            file=sys.stderr,
        )
        return 2
    record_flags(args._subparsers.choices[args.command], args)
    prefix = f"linecontact {args.command}"
    seen: set[str] = set()

    def once(message, category, filename, lineno, file=None, line=None):
        text = str(message)
        if text not in seen:  # a warning is printed once per run
            seen.add(text)
            print(f"{prefix}: warning: {flag_message(text, args)}", file=sys.stderr)

    try:
        with warnings.catch_warnings():
            if getattr(args, "quiet", False):
                warnings.simplefilter("ignore")
            else:
                warnings.simplefilter("always")
                warnings.showwarning = once
            status = int(args.func(args))
        _flush_stdout()  # a write error surfaces here, not in the interpreter's last flush
        return status
    except BrokenPipeError:
        # the reader went away (``linecontact ... | head``): nothing more to say to it. Point
        # stdout at the null device so that the interpreter's final flush is quiet too.
        _silence_stdout()
        return 0
    except KeyboardInterrupt:
        print(f"{prefix}: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except NoPointError as exc:
        print(f"{prefix}: error: no point could be computed: {exc}", file=sys.stderr)
        return 1
    except ConvergenceError as exc:
        print(f"{prefix}: error: {flag_message(str(exc), args)}", file=sys.stderr)
        return 1
    except (ValueError, OverflowError) as exc:
        print(f"{prefix}: error: {flag_message(str(exc), args)}", file=sys.stderr)
        return 2
    except ImportError as exc:
        print(f"{prefix}: error: {exc}", file=sys.stderr)
        return 1
    except OSError as exc:
        if not _stdout_broken(exc):  # not a write to stdout: an internal error
            print(
                f"{prefix}: error: internal error ({type(exc).__name__}: {exc}); please report it",
                file=sys.stderr,
            )
            return 1
        return _stdout_failed(prefix, exc)
    except Exception as exc:  # noqa: BLE001 - the CLI never shows a traceback
        print(
            f"{prefix}: error: internal error ({type(exc).__name__}: {exc}); please report it",
            file=sys.stderr,
        )
        return 1
