"""Ctrl-C while the command line starts: one line and exit status 130, no traceback.

The console script (``linecontact = "linecontact.cli:main"``) and ``python -m linecontact``
import the package, NumPy and SciPy before :func:`linecontact.cli.main` runs: about a
second in which a ``KeyboardInterrupt`` would end in a traceback. The package's and the
CLI's imports run inside :func:`imports_interruptible`, which turns it into
``SystemExit(130)`` after one line on stderr, when (and only when) the process is the
command line; a library user's ``import linecontact`` keeps the plain ``KeyboardInterrupt``.
Standard library only: it runs before anything heavy is imported.
"""

from __future__ import annotations

import contextlib
import os
import signal
import sys
from collections.abc import Iterator

#: The exit status of a run interrupted by Ctrl-C (128 + SIGINT), as shells report it.
EXIT_INTERRUPTED = 130


def launched_as_cli() -> bool:
    """True when this process is the ``linecontact`` command line.

    The console script runs as ``.../linecontact`` (``sys.argv[0]``); ``python -m
    linecontact`` has ``-m linecontact`` in its original arguments (``sys.orig_argv``).
    """
    argv0 = os.path.basename(sys.argv[0]) if sys.argv else ""
    if os.path.splitext(argv0)[0] in ("linecontact", "linecontact-script"):
        return True
    args = list(getattr(sys, "orig_argv", ()))[1:]  # after the interpreter
    i = 0
    while i < len(args):
        arg = args[i]
        if arg.startswith("-m"):
            module = arg[2:] or (args[i + 1] if i + 1 < len(args) else "")
            return module in ("linecontact", "linecontact.cli")
        if arg == "-c" or arg == "-" or not arg.startswith("-"):  # a command or a script
            return False
        i += 2 if arg in ("-X", "-W", "--check-hash-based-pycs") else 1
    return False


def _interrupted(exc: BaseException) -> bool:
    """True when ``exc`` is a ``KeyboardInterrupt`` or was raised while handling one.

    Ctrl-C inside a C extension's initialisation (NumPy's ``_multiarray_umath``) surfaces
    as an ``ImportError`` (or ``SystemError``) whose context is the ``KeyboardInterrupt``.
    """
    seen: set[int] = set()
    e: BaseException | None = exc
    while e is not None and id(e) not in seen:
        if isinstance(e, KeyboardInterrupt):
            return True
        seen.add(id(e))
        e = e.__cause__ or e.__context__
    return False


@contextlib.contextmanager
def imports_interruptible() -> Iterator[None]:
    """Turn a ``KeyboardInterrupt`` in the block into exit status 130 on the command line.

    On the command line the block runs under a SIGINT handler that notes the interrupt
    before it raises ``KeyboardInterrupt``: a C extension's initialisation can swallow that
    exception and fail with an unrelated ``ImportError`` (NumPy: "PyCapsule_Import could not
    import module 'datetime'"), which is then known to be the interrupt's doing. A library
    user's handler is left alone.
    """
    cli = launched_as_cli()
    seen: list[int] = []
    previous = None
    if cli:

        def note(signum: int, frame: object) -> None:
            seen.append(signum)
            raise KeyboardInterrupt

        with contextlib.suppress(ValueError):  # not the main thread: keep the handler
            previous = signal.signal(signal.SIGINT, note)
    try:
        yield
    except BaseException as exc:
        if not (cli and (seen or _interrupted(exc))):
            raise
        with contextlib.suppress(OSError, ValueError):
            print("linecontact: interrupted", file=sys.stderr)
        raise SystemExit(EXIT_INTERRUPTED) from None
    finally:
        if previous is not None:
            signal.signal(signal.SIGINT, previous)
