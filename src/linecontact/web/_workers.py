"""The computations of the web application: the subcommands' own code in worker processes.

Each request runs ``linecontact COMMAND ... --json`` as the command line would (the same
parser, checks and output), in one of a few long-lived worker processes that import
linecontact once. A computation over its time limit is ended by ending its worker, which is
replaced: the slot is free again, and no thread is left running it. Slow commands (the
Lennard-Jones law, the map, the fits) may hold all but one worker, so that a quick request
always finds one.
"""

from __future__ import annotations

import asyncio
import contextlib
import io
import multiprocessing as mp
import re
import tempfile
import time
import warnings
from dataclasses import dataclass, field
from typing import Any

__all__ = ["Outcome", "Pool", "compute", "is_slow"]

#: Subcommands (and laws) that may take seconds to minutes.
_SLOW_COMMANDS = frozenset({"map", "fit-adhesion", "fit-friction", "history"})


def is_slow(command: str, argv: list[str]) -> bool:
    """True for a computation that may take long (it gets a slow worker)."""
    return command in _SLOW_COMMANDS or "lennard-jones" in argv


@dataclass
class Outcome:
    """What a computation gave: the JSON text, or an error naming its flag."""

    status: int  # 200, 422 (bad input), 500 (a solver failed), 504 (over its time limit)
    body: str = ""
    flag: str | None = None
    message: str = ""
    warnings: list[str] = field(default_factory=list)
    seconds: float = 0.0


class _Progress(io.TextIOBase):
    """stderr of a computation: each ``n/total`` of its progress bar, sent to ``report``."""

    def __init__(self, report: Any) -> None:
        self.report, self.last = report, None

    def write(self, text: str) -> int:
        found = re.findall(r"(\d+)/(\d+)", text)
        if found and found[-1] != self.last:
            self.last = found[-1]
            self.report(int(found[-1][0]), int(found[-1][1]))
        return len(text)


def compute(command: str, argv: list[str], report: Any = None) -> Outcome:
    """``linecontact COMMAND ARGV --json`` in this process (a worker's job).

    ``report(done, total)``, where given, hears the progress of a map (its curves).
    """
    if command == "map":  # its figure and CSV into a directory of its own, one process
        with tempfile.TemporaryDirectory(prefix="linecontact-map-") as tmp:
            words = [*argv, "--outdir", tmp, "--workers", "1"]
            if report is None:
                return _compute(command, words)
            with contextlib.redirect_stderr(_Progress(report)):
                return _compute(command, [*words, "--progress"])
    return _compute(command, argv)


def _compute(command: str, argv: list[str]) -> Outcome:
    from ..cli import build_parser
    from ..cli._options import NoPointError, flag_message, record_flags
    from ..errors import ConvergenceError
    from ..output import render

    start = time.perf_counter()
    words = [command, *argv, "--json"]
    err = io.StringIO()
    try:
        with contextlib.redirect_stderr(err):
            parser = build_parser(words)
            args = parser.parse_args(words)
    except SystemExit:
        text = err.getvalue().strip().splitlines()
        message = (text[-1] if text else "bad arguments").split(": error: ", 1)[-1]
        return Outcome(422, flag=_flag_of(message), message=message)
    record_flags(parser.get_default("_subparsers").choices[command], args)
    args.argv = words
    args._capture = []
    said: list[str] = []
    status, message = 200, ""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            args.func(args)
        except NoPointError:
            pass  # the records say why
        except ConvergenceError as exc:
            status, message = 500, flag_message(str(exc), args)
        except (ValueError, OverflowError) as exc:
            status, message = 422, flag_message(str(exc), args)
    for w in caught:
        note = flag_message(str(w.message), args)
        if note not in said:
            said.append(note)
    seconds = time.perf_counter() - start
    if status != 200:
        return Outcome(status, flag=_flag_of(message), message=message, warnings=said)
    if not args._capture:
        return Outcome(500, message=f"linecontact {command} gave no records", warnings=said)
    body = render(args._capture[0], "json")
    return Outcome(200, body=body, warnings=said, seconds=seconds)


def _flag_of(message: str) -> str | None:
    m = re.search(r"(--[A-Za-z][\w-]*)", message)
    return m.group(1) if m else None


def _serve(conn: Any) -> None:  # pragma: no cover - runs in the worker process
    import os

    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    while True:
        try:
            job = conn.recv()
        except (EOFError, KeyboardInterrupt):
            return
        if job is None:
            return
        try:
            command, argv = job
            report = lambda n, total: conn.send(("progress", n, total))  # noqa: E731
            conn.send(compute(command, argv, report=report))
        except Exception as exc:  # noqa: BLE001 - the server never shows a traceback
            conn.send(Outcome(500, message=f"internal error ({type(exc).__name__}: {exc})"))


class _Worker:
    def __init__(self, ctx: Any) -> None:
        self.conn, theirs = ctx.Pipe()
        self.proc = ctx.Process(target=_serve, args=(theirs,), daemon=True)
        self.proc.start()
        theirs.close()

    def stop(self) -> None:
        with contextlib.suppress(OSError, ValueError):
            self.conn.send(None)
        self.proc.join(0.5)
        if self.proc.is_alive():
            self.proc.kill()
            self.proc.join()

    def kill(self) -> None:
        self.proc.kill()
        self.proc.join()
        self.conn.close()


class Pool:
    """``workers`` long-lived processes; slow jobs may hold ``workers - 1`` of them.

    Parameters
    ----------
    workers : int
        Processes (at least 2: one is always left to quick requests).
    time_limit : float
        Seconds a computation may take; beyond it its worker is ended and replaced.
    """

    def __init__(self, workers: int = 2, time_limit: float = 60.0) -> None:
        if workers < 2:
            raise ValueError(
                f"--workers must be at least 2 (one kept for quick requests), got {workers}"
            )
        self.size, self.time_limit = workers, time_limit
        self._ctx = mp.get_context("spawn")
        self._idle: list[_Worker] = []
        self._all: asyncio.Semaphore | None = None
        self._slow: asyncio.Semaphore | None = None
        self._lock: asyncio.Lock | None = None

    async def start(self) -> None:
        """Start the workers (in the server's event loop)."""
        self._all = asyncio.Semaphore(self.size)
        self._slow = asyncio.Semaphore(self.size - 1)
        self._lock = asyncio.Lock()
        self._idle = await asyncio.to_thread(lambda: [_Worker(self._ctx) for _ in range(self.size)])

    async def stop(self) -> None:
        """Stop the workers."""
        for w in self._idle:
            await asyncio.to_thread(w.stop)
        self._idle.clear()

    async def run(
        self, command: str, argv: list[str], time_limit: float | None = None, job: Any = None
    ) -> Outcome:
        """``command argv`` on a worker, within the time limit (504 beyond it)."""
        assert self._all is not None and self._slow is not None and self._lock is not None
        limit = self.time_limit if time_limit is None else time_limit
        slow = is_slow(command, argv)
        async with contextlib.AsyncExitStack() as stack:
            if slow:
                await stack.enter_async_context(self._slow)
            await stack.enter_async_context(self._all)
            async with self._lock:
                worker = self._idle.pop()
            if job is not None:
                job.worker = worker
            ok = False
            try:
                worker.conn.send((command, argv))
                ready = await asyncio.to_thread(worker.conn.poll, limit)
                if not ready:
                    return Outcome(
                        504,
                        message=f"the computation took longer than its limit of {limit:g} s and "
                        "was stopped",
                    )
                deadline = time.monotonic() + limit
                while True:  # progress reports, then the outcome
                    out: Any = await asyncio.to_thread(worker.conn.recv)
                    if not (isinstance(out, tuple) and out[:1] == ("progress",)):
                        break
                    if job is not None:
                        job.progress = out[1:]
                    left = deadline - time.monotonic()
                    if left <= 0 or not await asyncio.to_thread(worker.conn.poll, left):
                        return Outcome(
                            504,
                            message=f"the computation took longer than its limit of {limit:g} s "
                            "and was stopped",
                        )
                ok = True
                return out
            except (EOFError, OSError):  # the worker was ended (a cancelled job)
                return Outcome(499, message="the computation was cancelled")
            finally:
                if not ok:  # ended, over time or broken: replace it
                    await asyncio.to_thread(_end, worker)
                    worker = await asyncio.to_thread(_Worker, self._ctx)
                if job is not None:
                    job.worker = None
                async with self._lock:
                    self._idle.append(worker)


def _end(worker: _Worker) -> None:
    with contextlib.suppress(OSError, ValueError):
        worker.kill()
