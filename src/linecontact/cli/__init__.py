"""Command-line interface: a thin shell over the public API.

The subcommands of the operations are built from their declarations
(:mod:`linecontact.operations`) by :mod:`~linecontact.cli._build`; the others have a module
each (:mod:`~linecontact.cli.paper`, :mod:`~linecontact.cli.adhesion_map`,
:mod:`~linecontact.cli.materials`, :mod:`~linecontact.cli.sweep`,
:mod:`~linecontact.cli.serve`); the shared options and output are in
:mod:`~linecontact.cli._options`. A module (an operation's declaration) is imported only when
its subcommand runs (:data:`COMMANDS`, :func:`build_parser`). Every subcommand takes the paper's
nondimensional groups or SI inputs, prints a readable table, or with ``--json``
machine-readable JSON. Bad input: one ``error:`` line on stderr and exit status 2. A solver
that misses its tolerance: exit status 1.
"""

from __future__ import annotations

import argparse
import errno
import importlib
import os
import sys
import textwrap
import warnings
from collections.abc import Sequence
from typing import Any

from .._interrupt import EXIT_INTERRUPTED, imports_interruptible

with imports_interruptible():  # Ctrl-C here: status 130, one line (linecontact._interrupt)
    from .._version import __version__
    from ..errors import ConvergenceError, CouplingWarning
    from ._options import (
        NoPointError,
        Parser,
        coupling_effect,
        flag_message,
        is_units_warning,
        record_flags,
    )

__all__ = ["COMMANDS", "build_parser", "main"]

#: Every subcommand, in the order of ``linecontact --help``, and its one-line summary: what
#: ``linecontact --help`` shows (a test keeps it equal to the subcommand's own).
_SUMMARIES: dict[str, str] = {
    "normal": (
        "adhesive-zone width and load for given contact half-widths, or the contact for loads"
    ),
    "pulloff": "pull-off force under load control and its mechanism",
    "curve": "the whole load curve: non-contact branch, contact branch, turning point, pull-off",
    "slide-init": "initiation of sliding under a tangential force (stick zone, T/(Ea))",
    "roll": "steady rolling of a driving cylinder (stick zone, T/(Ea), creep)",
    "cycle": "cyclic tangential loading: energy dissipated per cycle, stick zone",
    "history": "a tangential load history with memory: zones, slip, energy per step",
    "fit-adhesion": "work of adhesion (and range) from pull-off forces, with uncertainty",
    "fit-friction": "interfacial shear strength from friction forces, with uncertainty",
    "fit-bent-wire": "friction per unit length (and tau0) from the profile of a bent wire",
    "slide": (
        "steady sliding: adhesive zones, eccentricity, load and moment (trailing h1, leading h2)"
    ),
    "push": "a fibre pushed sideways: stay, roll or slide, and at what push",
    "paper": "redraw the paper's Figs. 2-14 (PNG by default)",
    "figures": (
        "draw the figures beyond the paper: the pushed fibre's motion maps and force, "
        "load-history loops and loss, the adhesion map, the sphere's curves, map and alpha"
    ),
    "cite": "how to cite linecontact and the paper",
    "map": "the adhesion map of line contact: where Hertz, rigid, JKR, Maugis-Dugdale hold",
    "materials": "the material presets (E, nu, range, source) of --cylinder-material",
    "sweep": "run a subcommand over every combination of its flags' values: labelled arrays out",
    "serve": "a calculator in the browser and an HTTP API (local web server)",
}

#: The subcommands that are no operation of the catalogue, and the module of this package
#: whose ``register(sub)`` adds each (with the module's other subcommands).
_SHELLS: dict[str, str] = {
    "paper": "paper",
    "figures": "paper",
    "cite": "paper",
    "map": "adhesion_map",
    "sweep": "sweep",
    "serve": "serve",
}

#: Every subcommand: its module in this package and its summary. An operation's module is
#: ``_build``, which adds it alone from its declaration (``_build.register(sub, name)``). A
#: module is imported only when one of its subcommands runs or shows its help.
COMMANDS: dict[str, tuple[str, str]] = {
    name: (_SHELLS.get(name, "_build"), summary) for name, summary in _SUMMARIES.items()
}

_COMMANDS = (
    "normal, pulloff, curve, slide-init, roll, cycle, history, slide, push, fit-adhesion, "
    "fit-friction, fit-bent-wire, paper, figures, map, materials, sweep, serve or cite"
)


def _command_of(argv: Sequence[str]) -> str | None:
    """The subcommand that ``argv`` names: its first word that is no option (None: none).

    ``linecontact`` itself has no option that takes a value (``-h``, ``--version``), so the
    first word that does not start with ``-`` is the subcommand (or the word after ``--``).
    """
    for i, arg in enumerate(argv):
        if arg == "--":
            return argv[i + 1] if i + 1 < len(argv) else None
        if not arg.startswith("-"):
            return arg
    return None


def build_parser(argv: Sequence[str] | None = None) -> argparse.ArgumentParser:
    """The argparse parser of the ``linecontact`` command.

    Without ``argv``: every subcommand's full parser (every subcommand module imported).
    With ``argv`` (the command line, as :func:`main` has it): only the subcommand it names
    gets its full parser, from its module; the others are stubs that carry their summary
    for ``linecontact --help`` (and the choices of an unknown command's error), so that a
    run imports only the module of its own subcommand.
    """
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
    command = None if argv is None else _command_of(argv) or ""
    wanted = COMMANDS.get(command or "", ("",))[0]
    for name, (module, summary) in COMMANDS.items():
        if name in sub.choices:  # added with an earlier subcommand of its module
            continue
        if module == "_build" and (argv is None or name == command):
            with imports_interruptible():  # an operation: built from its declaration
                importlib.import_module(f"{__name__}._build").register(sub, name)
        elif module != "_build" and (argv is None or module == wanted):
            with imports_interruptible():
                importlib.import_module(f"{__name__}.{module}").register(sub)
        else:
            sub.add_parser(name, help=summary, add_help=False)
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
#: an I/O error, a closed descriptor).
_WRITE_ERRNOS = frozenset(
    getattr(errno, name)
    for name in ("ENOSPC", "EDQUOT", "EFBIG", "EIO", "EBADF", "EROFS")
    if hasattr(errno, name)
)


def _stdout_broken(exc: OSError) -> bool:
    """True when ``exc`` is a failed write to stdout, not to a file.

    A write error names no file: it is stdout's when it was raised by a write to stdout
    (marked by :class:`_MarkedStdout`); otherwise a file's (a figure, a plot: a full disk
    while stdout is fine).
    """
    return getattr(exc, "stream", None) == "stdout" and exc.errno in _WRITE_ERRNOS


class _MarkedStdout:
    """Standard output while a command runs: a failed write says it was standard output.

    Every other attribute is the stream's own. An :class:`OSError` of ``write`` or ``flush``
    gets ``stream = "stdout"``, which :func:`main` reads to tell a full disk under stdout
    (``> /dev/full``) from one under a file the command writes (its figures).
    """

    def __init__(self, stream: Any) -> None:
        self._stream = stream

    def write(self, text: str) -> Any:
        try:
            return self._stream.write(text)
        except OSError as exc:
            exc.stream = "stdout"  # type: ignore[attr-defined]
            raise

    def flush(self) -> None:
        try:
            self._stream.flush()
        except OSError as exc:
            exc.stream = "stdout"  # type: ignore[attr-defined]
            raise

    def __getattr__(self, name: str) -> object:
        return getattr(self._stream, name)


def _write_failed(prefix: str, exc: OSError) -> int:
    """Report a failed write to a file (not stdout) on stderr: its cause; exit status 2."""
    what = repr(exc.filename) if exc.filename is not None else "a file (not standard output)"
    if exc.errno == errno.ENOSPC:
        text = f"no space left on the device writing {what}"
    elif exc.errno == getattr(errno, "EDQUOT", None):
        text = f"disk quota exceeded writing {what}"
    else:
        text = f"cannot write {what}: {exc.strerror or exc}"
    print(f"{prefix}: error: {text}", file=sys.stderr)
    return 2


def _stdout_failed(prefix: str, exc: OSError) -> int:
    """Report a failed write to stdout on stderr; exit status 2."""
    _silence_stdout()  # the interpreter's final flush must not fail again
    reason = exc.strerror or str(exc)
    print(f"{prefix}: error: cannot write to standard output: {reason}", file=sys.stderr)
    return 2


def _error_text(exc: BaseException) -> str:
    """The text of a refusal: the message, or for a bare floating-point overflow what it is.

    ``math`` says ``(34, 'Numerical result out of range')`` for an overflow: said as a
    number beyond the floating-point range (an input far out of scale, or in wrong units).
    """
    args: tuple[Any, ...] = tuple(getattr(exc, "args", ()))
    if isinstance(exc, OverflowError) and (len(args) != 1 or not isinstance(args[0], str)):
        why = args[-1] if args else "overflow"
        return (
            f"a result beyond the floating-point range ({why}): an input is far out of "
            "scale (in the wrong units?)"
        )
    return str(exc)


def _check_output_directory(args: argparse.Namespace) -> None:
    """Refuse ``-o FILE`` in a directory that does not exist before any work is done."""
    out = getattr(args, "output", None)
    if isinstance(out, str) and out:
        parent = os.path.dirname(os.path.abspath(out))
        if not os.path.isdir(parent):
            what = "is not a directory" if os.path.exists(parent) else "does not exist"
            raise ValueError(f"cannot write -o/--output {out!r}: the directory {parent!r} {what}")


def _help_not_written(err: OSError) -> int:
    """``--help``/``--version`` output that could not be written: as :func:`main` says."""
    if isinstance(err, BrokenPipeError):
        _silence_stdout()
        return 0
    if err.errno in _WRITE_ERRNOS:  # the help and the version go to stdout only
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
        words = list(argv) if argv is not None else sys.argv[1:]
        parser = build_parser(words)
        args, extra = parser.parse_known_args(words)
        if extra:  # said by the command's own parser: "linecontact pulloff: error: ..."
            command = getattr(args, "command", None)
            said_by = args._subparsers.choices[command] if command else parser
            said_by.error(f"unrecognized arguments: {' '.join(extra)}")
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
    for note in getattr(args, "_deprecated", None) or ():  # old spellings: always said
        print(f"{prefix}: warning: {note}", file=sys.stderr)
    seen: set[str] = set()
    said: list[str] = []

    def once(message, category, filename, lineno, file=None, line=None):
        quiet = bool(getattr(args, "quiet", False))  # read when said (sweep sets it late)
        if quiet and not is_units_warning(message, category):  # --quiet: model notes only
            return
        text = flag_message(str(message), args)
        if text not in seen:  # a warning is printed once per run (as the user reads it)
            seen.add(text)
            if issubclass(category, CouplingWarning) and not said:  # its effect: once
                said.append(text)
                text += coupling_effect(text)
            print(f"{prefix}: warning: {text}", file=sys.stderr)

    stdout = sys.stdout
    try:
        if stdout is not None:  # a failed write to it says so (a full disk: which file)
            sys.stdout = _MarkedStdout(stdout)
        with warnings.catch_warnings():
            warnings.simplefilter("always")
            warnings.showwarning = once
            _check_output_directory(args)  # before the work, not after it
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
        print(f"{prefix}: error: {flag_message(_error_text(exc), args)}", file=sys.stderr)
        return 2
    except ImportError as exc:
        print(f"{prefix}: error: {exc}", file=sys.stderr)
        return 1
    except OSError as exc:
        if _stdout_broken(exc):
            return _stdout_failed(prefix, exc)
        if exc.errno in _WRITE_ERRNOS:  # a file of the command: a full disk, a quota
            return _write_failed(prefix, exc)
        print(  # anything else: an internal error
            f"{prefix}: error: internal error ({type(exc).__name__}: {exc}); please report it",
            file=sys.stderr,
        )
        return 1
    except Exception as exc:  # noqa: BLE001 - the CLI never shows a traceback
        print(
            f"{prefix}: error: internal error ({type(exc).__name__}: {exc}); please report it",
            file=sys.stderr,
        )
        return 1
    finally:
        if isinstance(sys.stdout, _MarkedStdout):  # as it was (unless the command changed it)
            sys.stdout = stdout
