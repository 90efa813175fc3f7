"""The computations of the web application: the subcommands' own code in worker processes.

Each request runs ``linecontact COMMAND ... --json`` as the command line would (the same
parser, checks and output), in one of a few long-lived worker processes that import
linecontact once. A computation over its time limit, or whose job is cancelled, is ended by
ending its worker, which is replaced: the slot is free again, and no thread is left running
it. Slow commands (the Lennard-Jones law, the map, the fits, large requests) may hold all but
one worker, so that a quick request always finds one.

The server waits on the workers' pipes in its event loop (no thread per computation), and a
worker hands over its result as a file in a directory of the server's, one per computation,
that the server removes however the computation ends (done, failed, over time, cancelled, or
its worker killed).
"""

from __future__ import annotations

import asyncio
import contextlib
import io
import json
import multiprocessing as mp
import os
import re
import shutil
import signal
import tempfile
import time
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

__all__ = ["MAX_RESULT_BYTES", "Outcome", "Pool", "compute", "cpus", "is_slow", "max_workers"]

#: Subcommands (and laws) that may take seconds to minutes.
_SLOW_COMMANDS = frozenset({"map", "fit-adhesion", "fit-friction", "history"})

#: The largest result a computation may return [bytes] (16 MiB): 10,000 points of the
#: command with the widest records (the map, about 900 bytes a point) fit in about half.
MAX_RESULT_BYTES = 16 * 1024 * 1024

#: Seconds a new worker may take to import linecontact before it is said to be broken.
_READY_TIMEOUT = 120.0

#: The name of the result file in a computation's directory.
_RESULT = "result.json"


def cpus() -> int:
    """The CPUs this process may run on (its affinity where the system tells it)."""
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):  # pragma: no cover - not Linux
        return os.cpu_count() or 1


def max_workers() -> int:
    """The most worker processes ``serve`` may start: twice the CPUs, and at least 4.

    The computations are CPU-bound: workers beyond the cores only share them, and each costs
    its memory (about 100 MB, numpy and scipy imported). Twice the cores leaves room for the
    workers that wait rather than compute (one being replaced, those held by slow jobs) and
    bounds the memory; at least 4, so that ``--workers 4`` works on a small machine.
    """
    return max(4, 2 * cpus())


def is_slow(command: str, values: dict[str, Any]) -> bool:
    """True for a computation that may take long (it gets a slow worker)."""
    return command in _SLOW_COMMANDS or values.get("law") == "lennard-jones"


@dataclass
class Outcome:
    """What a computation gave: the JSON text, or an error naming its flag."""

    # 200, 413 (a result over its limit), 422 (bad input), 500 (a solver failed, a worker
    # died), 504 (over its time limit)
    status: int
    body: str = ""
    flag: str | None = None
    message: str = ""
    warnings: list[str] = field(default_factory=list)
    seconds: float = 0.0
    body_file: str | None = None  # where a worker left the body (the server reads it)
    python: str = ""  # the Python lines of the library calls that computed it (the pages')


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


def compute(
    command: str,
    values: dict[str, Any],
    report: Any = None,
    workdir: str | None = None,
    max_bytes: int | None = None,
    python: bool = False,
) -> Outcome:
    """The operation ``command`` on typed values, in this process (a worker's job).

    Parameters
    ----------
    command : str
        The operation.
    values : dict
        Its typed values (:func:`linecontact.web._params.values_of`).
    report : callable, optional
        ``report(done, total)`` hears the progress of a map (its curves).
    workdir : str, optional
        The computation's directory (the server names it in no answer).
    max_bytes : int, optional
        The largest JSON text returned: a larger result is refused (413) rather than returned.
    python : bool
        Write the Python lines of the library calls made (``Outcome.python``; a page's).

    Returns
    -------
    Outcome
        The JSON text (status 200) or the error.
    """
    if command == "map":  # its curves in this process, its progress heard
        values = {**values, "workers": 1, "progress": report is not None}
        if report is not None:
            with contextlib.redirect_stderr(_Progress(report)):
                return _sized(_unnamed(_call(command, values, python), workdir), max_bytes)
    return _sized(_unnamed(_call(command, values, python), workdir), max_bytes)


#: What the map's answer says in place of the server's directory (its files are not served).
SERVER_FILES = "server-files"


def _unnamed(out: Outcome, workdir: str | None) -> Outcome:
    """``out`` with the server's directory named :data:`SERVER_FILES` (never its path)."""
    if workdir is None:
        return out
    for text in (workdir, json.dumps(workdir)[1:-1]):
        out.body = out.body.replace(text, SERVER_FILES)
        out.message = out.message.replace(text, SERVER_FILES)
    return out


def _sized(out: Outcome, max_bytes: int | None) -> Outcome:
    """``out``, or a 413 where its JSON text is over ``max_bytes``."""
    if max_bytes is None or out.status != 200:
        return out
    size = len(out.body.encode())
    if size <= max_bytes:
        return out
    return Outcome(
        413,
        message=f"the result is {size:,} bytes, over the limit of {max_bytes:,} bytes of a "
        "response: ask for fewer points, or run a larger study on the command line "
        "(`linecontact sweep ...`, docs/sweeps.md)",
        warnings=out.warnings,
        seconds=out.seconds,
    )


def _call(command: str, values: dict[str, Any], python: bool = False) -> Outcome:
    """The operation ``command`` on the typed ``values``: its JSON, or the error."""
    from .. import operations
    from ..operations._messages import spell
    from ..operations._written import python as written
    from ..output import render

    start = time.perf_counter()
    op = operations.get(command)
    words = operations.command_words(op, values)
    inputs = operations.Inputs(op, values, words=[*words, "--json"])
    got: list[Any] = []
    refused: list[str] = []  # the parameter an error names (a ParameterError's own)
    status, message, said = _guarded(
        lambda: got.append(op.run(inputs)), lambda t: spell(t, inputs), refused
    )
    seconds = time.perf_counter() - start
    if status != 200 or not got:
        flag = _flag(op, inputs.said_as, refused)
        return Outcome(status, flag=flag, message=message, warnings=said)
    body = render(got[0], "json")
    lines = written(inputs) if python else ""  # asked for: a large call's are long
    return Outcome(200, body=body, warnings=said, seconds=seconds, python=lines)


def _guarded(work: Any, say: Any, refused: list[str]) -> tuple[int, str, list[str]]:
    """Run ``work()``: its status (200; 422 refused; 500 not converged), message and notes.

    The message and each note (a warning, said once) in the words ``say`` gives them; the
    parameter a :class:`~linecontact.errors.ParameterError` names goes into ``refused``.
    """
    from ..errors import ConvergenceError, ParameterError

    said: list[str] = []
    status, message = 200, ""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            work()
        except ConvergenceError as exc:
            status, message = 500, say(str(exc))
        except (ValueError, OverflowError) as exc:
            status, message = 422, say(str(exc))
            if isinstance(exc, ParameterError):
                refused.append(exc.parameter)
    for w in caught:
        note = say(str(w.message))
        if note not in said:
            said.append(note)
    return status, message, said


def _flag(op: Any, said_as: dict[str, str], refused: list[str]) -> str | None:
    """The flag of the parameter an error names (a ParameterError's own), or None.

    The library's name (``normal_load``) is the operation's parameter it stands for in this
    call (``said_as``: a name, or the flags that make it, the first of which is the field:
    ``--pull-off-force-total / --length``), or of the same name, or of the flag the command
    line gives it. An error that names none is said without a field: no flag is guessed
    from its words.
    """
    from ..operations._messages import API_FLAGS

    for name in refused:
        key = name.lstrip("-").replace("-", "_")
        said = said_as.get(key) or ""
        if said.startswith("--"):  # said as flags: the first is the one given
            said = said.split()[0][2:].replace("-", "_")
        for candidate in (said, key, API_FLAGS.get(key, "")[2:].replace("-", "_")):
            if not candidate:
                continue
            try:
                return str(op.parameter(candidate).option)
            except ValueError:  # no parameter of the operation
                continue
    return None  # an error that names no parameter: its message stands alone, no field


def _serve(conn: Any) -> None:  # pragma: no cover - runs in the worker process
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C stops the server, which stops us
    from .. import operations  # noqa: F401 - imported once, before the first request
    from ..output import render  # noqa: F401

    conn.send(("ready",))
    while True:
        try:
            job = conn.recv()
        except (EOFError, OSError):  # the server ended
            return
        if job is None:
            return
        try:
            command, values, workdir, max_bytes, python = job
            report = lambda n, total: conn.send(("progress", n, total))  # noqa: E731
            out = compute(
                command, values, report=report, workdir=workdir, max_bytes=max_bytes, python=python
            )
            if out.status == 200:  # the body as a file: no large message on the pipe
                out.body_file = os.path.join(workdir, _RESULT)
                with open(out.body_file, "w", encoding="utf-8") as f:
                    f.write(out.body)
                out.body = ""
            conn.send(out)
        except Exception as exc:  # noqa: BLE001 - the server never shows a traceback
            conn.send(Outcome(500, message=f"internal error ({type(exc).__name__}: {exc})"))


def _reason(exitcode: int | None) -> str:
    """How a process ended, in words (``signal 9 (SIGKILL)``, ``exit code 1``)."""
    if exitcode is None:
        return "its pipe closed"
    if exitcode < 0:
        try:
            return f"signal {-exitcode} ({signal.Signals(-exitcode).name})"
        except ValueError:
            return f"signal {-exitcode}"
    return f"exit code {exitcode}"


class _Worker:
    def __init__(self, ctx: Any) -> None:
        self.conn, theirs = ctx.Pipe()
        self.proc = ctx.Process(target=_serve, args=(theirs,), daemon=True)
        self.proc.start()
        theirs.close()
        self.ready = False

    def stop(self) -> None:
        with contextlib.suppress(OSError, ValueError):
            self.conn.send(None)
        self.proc.join(0.5)
        self.kill()

    def kill(self) -> None:
        """End the process (SIGKILL where it still runs) and close its pipe."""
        with contextlib.suppress(OSError, ValueError, AttributeError):
            if self.proc.is_alive():
                self.proc.kill()
            self.proc.join(5)
        with contextlib.suppress(OSError):
            self.conn.close()


async def _readable(conn: Any, timeout: float) -> bool:
    """Wait (in the event loop, no thread) until ``conn`` has data or ends: False at timeout."""
    loop = asyncio.get_running_loop()
    ready: asyncio.Future[None] = loop.create_future()

    def wake() -> None:
        if not ready.done():
            ready.set_result(None)

    fd = conn.fileno()
    loop.add_reader(fd, wake)
    try:
        await asyncio.wait_for(ready, timeout)
        return True
    except asyncio.TimeoutError:
        return False
    finally:
        loop.remove_reader(fd)


class _Died(Exception):
    """The worker ended while this computation needed it."""


class Pool:
    """``workers`` long-lived processes; slow jobs may hold ``workers - 1`` of them.

    Parameters
    ----------
    workers : int
        Processes, from 2 (one is always left to quick requests) to :func:`max_workers`.
    time_limit : float
        Seconds a computation may take; beyond it its worker is ended and replaced (504).
    max_result_bytes : int
        The largest result a computation may return (413 beyond it, never shipped).

    Attributes
    ----------
    started : int
        Computations handed to a worker so far (a cancelled queued job is never one).
    """

    def __init__(
        self, workers: int = 2, time_limit: float = 60.0, max_result_bytes: int = MAX_RESULT_BYTES
    ) -> None:
        top = max_workers()
        if not isinstance(workers, int) or not 2 <= workers <= top:
            raise ValueError(
                f"workers must be an integer from 2 (one kept for quick requests) to {top} "
                f"(twice the {cpus()} CPUs, at least 4), got {workers!r}"
            )
        if not (isinstance(time_limit, int | float) and 0 < time_limit < float("inf")):
            raise ValueError(
                f"time_limit must be a finite number of seconds > 0, got {time_limit!r}"
            )
        if not (isinstance(max_result_bytes, int) and max_result_bytes > 0):
            raise ValueError(f"max_result_bytes must be an integer > 0, got {max_result_bytes!r}")
        self.size, self.time_limit, self.max_result_bytes = (
            workers,
            float(time_limit),
            max_result_bytes,
        )
        self.started = 0
        self._ctx = mp.get_context("spawn")
        self._workers: set[_Worker] = set()
        self._idle: asyncio.Queue[_Worker] | None = None
        self._slow: asyncio.Semaphore | None = None
        self._pending: set[asyncio.Task[None]] = set()
        self._root: str | None = None
        self._closing = False

    @property
    def root(self) -> str | None:
        """The directory of the computations' own directories (None before :meth:`start`)."""
        return self._root

    async def start(self) -> None:
        """Start the workers (in the server's event loop)."""
        self._closing = False
        self._idle = asyncio.Queue()
        self._slow = asyncio.Semaphore(self.size - 1)
        self._root = tempfile.mkdtemp(prefix="linecontact-web-")
        made = await asyncio.to_thread(lambda: [_Worker(self._ctx) for _ in range(self.size)])
        self._workers.update(made)
        for w in made:  # ready (linecontact imported) before the server says it is up
            await self._ready(w)
            self._idle.put_nowait(w)

    async def _ready(self, worker: _Worker) -> None:
        """Wait for a new worker's imports (RuntimeError if it ends or never gets there)."""
        if await _readable(worker.conn, _READY_TIMEOUT):
            with contextlib.suppress(EOFError, OSError):
                worker.conn.recv()
                worker.ready = True
                return
        code = await asyncio.to_thread(_exitcode, worker)
        raise RuntimeError(f"a worker did not start ({_reason(code)})")

    async def stop(self) -> None:
        """Stop the workers, those computing too, and remove the computations' directories."""
        self._closing = True
        if self._pending:
            await asyncio.gather(*self._pending, return_exceptions=True)
        workers, self._workers = list(self._workers), set()
        await asyncio.to_thread(_stop_all, workers)
        if self._root is not None:
            await asyncio.to_thread(shutil.rmtree, self._root, True)
            self._root = None

    async def run(
        self,
        command: str,
        values: dict[str, Any],
        time_limit: float | None = None,
        *,
        slow: bool | None = None,
        on_start: Callable[[], None] | None = None,
        on_progress: Callable[[int, int], None] | None = None,
        python: bool = False,
    ) -> Outcome:
        """The operation ``command`` on ``values`` on a worker, within the time limit (504 after).

        Cancelling the task that awaits this stops the computation: before it has a worker it
        never runs; after, its worker is ended and replaced. Its directory is removed however
        it ends.

        Parameters
        ----------
        command : str
            The operation.
        values : dict
            Its typed values.
        time_limit : float, optional
            Seconds it may take (the pool's limit without it), from when a ready worker has it.
        slow : bool, optional
            Whether it may hold only a slow worker (:func:`is_slow` without it).
        on_start : callable, optional
            Called when it gets its worker.
        on_progress : callable, optional
            ``on_progress(done, total)`` where the computation reports its progress.
        python : bool
            Write the Python lines of the calls made (``Outcome.python``).

        Returns
        -------
        Outcome
            Its result, or a 413, 422, 500 (a solver failed, or its worker died: the worker is
            replaced) or 504.
        """
        if self._idle is None or self._slow is None or self._closing:
            raise RuntimeError("the pool is not running (Pool.start)")
        limit = self.time_limit if time_limit is None else time_limit
        slow = is_slow(command, values) if slow is None else slow
        held_slow = False
        worker: _Worker | None = None
        workdir: str | None = None
        ok = False
        try:
            if slow:
                await self._slow.acquire()
                held_slow = True
            while True:
                worker = await self._idle.get()
                if worker.proc.is_alive():
                    break
                dead, worker = worker, None  # ended while idle (killed from outside)
                await self._release_shielded(dead, False, None, False)
            workdir = tempfile.mkdtemp(prefix="run-", dir=self._root)
            self.started += 1
            if on_start is not None:
                on_start()
            try:
                out = await self._exchange(
                    worker, command, values, workdir, limit, on_progress, python
                )
            except _Died:
                code = await asyncio.to_thread(_exitcode, worker)
                return Outcome(
                    500,
                    message=f"the worker computing this request ended unexpectedly "
                    f"({_reason(code)}); it was replaced",
                )
            ok = out.status != 504
            return out
        finally:
            if worker is not None or held_slow:
                await self._release_shielded(worker, ok, workdir, held_slow)

    async def _release_shielded(
        self, worker: _Worker | None, ok: bool, workdir: str | None, held_slow: bool
    ) -> None:
        """:meth:`_release` as a task of its own: it goes on if the caller is cancelled."""
        task = asyncio.get_running_loop().create_task(self._release(worker, ok, workdir, held_slow))
        self._pending.add(task)
        task.add_done_callback(self._pending.discard)
        await asyncio.shield(task)

    async def _exchange(
        self,
        worker: _Worker,
        command: str,
        values: dict[str, Any],
        workdir: str,
        limit: float,
        on_progress: Callable[[int, int], None] | None,
        python: bool = False,
    ) -> Outcome:
        """Send the computation, hear its progress, and take its outcome."""
        if not worker.ready:  # a new worker: its imports are not the computation's time
            try:
                await self._ready(worker)
            except RuntimeError:
                raise _Died from None
        try:
            worker.conn.send((command, values, workdir, self.max_result_bytes, python))
        except (BrokenPipeError, OSError):
            raise _Died from None
        loop = asyncio.get_running_loop()
        deadline = loop.time() + limit
        while True:
            left = deadline - loop.time()
            if left <= 0 or not await _readable(worker.conn, left):
                return Outcome(
                    504,
                    message=f"the computation took longer than its limit of {limit:g} s and "
                    "was stopped",
                )
            try:
                out: Any = worker.conn.recv()  # small: the body comes as a file
            except (EOFError, OSError):
                raise _Died from None
            if isinstance(out, tuple) and out[:1] == ("progress",):
                if on_progress is not None:
                    on_progress(int(out[1]), int(out[2]))
                continue
            break
        if not isinstance(out, Outcome):
            return Outcome(500, message="internal error (a worker's answer was not an outcome)")
        if out.body_file is not None:
            out.body = await asyncio.to_thread(_read, out.body_file)
            out.body_file = None
        return out

    async def _release(
        self, worker: _Worker | None, ok: bool, workdir: str | None, held_slow: bool
    ) -> None:
        """Give the worker back (a new one where it was ended), remove the directory."""
        assert self._idle is not None and self._slow is not None
        try:
            if worker is not None and not ok:  # over time, cancelled or dead: replace it
                await asyncio.to_thread(worker.kill)
                self._workers.discard(worker)
                worker = None if self._closing else await asyncio.to_thread(_Worker, self._ctx)
                if worker is not None:
                    self._workers.add(worker)
            if workdir is not None:  # after the worker ended: nothing writes there any more
                await asyncio.to_thread(shutil.rmtree, workdir, True)
            if worker is not None:
                self._idle.put_nowait(worker)
        finally:
            if held_slow:
                self._slow.release()


def _stop_all(workers: list[_Worker]) -> None:
    for w in workers:
        w.stop()


def _exitcode(worker: _Worker) -> int | None:
    with contextlib.suppress(OSError, ValueError, AssertionError):
        worker.proc.join(5)
    return worker.proc.exitcode


def _read(path: str) -> str:
    with open(path, encoding="utf-8") as f:
        return f.read()
