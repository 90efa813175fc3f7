"""Running a sweep: its blocks in this process, or on Dask workers; kept as they finish.

``workers=1`` (and no scheduler) computes the blocks here, one after the other. More workers
compute them in a pool of that many local processes (forked where the system can, one BLAS
thread each): the cheapest executor on one machine, which a local Dask cluster is not (its
scheduler, nannies and serialisation made a 2-worker sweep slower than one). ``scheduler=
"tcp://host:port"`` sends the blocks to a running ``dask.distributed`` cluster (its workers
need linecontact installed; they return the blocks here, so they need no shared disk). Either
way the blocks are the same computations and give the same dataset. A progress bar on
stderr (tqdm) counts the points.
"""

from __future__ import annotations

import gc
import logging
import os
import re
import shutil
import socket
import stat
import threading
import warnings
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np

from .. import errors as _errors
from .._files import file_kind, regular_target
from .._fingerprint import code_digest
from .._progress import progress_bar
from ._block import Block, call
from ._dataset import build, open_sweep, write
from ._plan import Plan, blocks
from ._points import evaluate
from ._store import Partial, format_of, need, real_output, store_identity, store_key

__all__ = ["run"]


def _check_output(output: str | os.PathLike[str]) -> None:
    """Refuse an output that is not a store's kind of path, or cannot be written.

    A netCDF store is a regular file and a Zarr store a directory: anything else at the path
    (a FIFO, a device, a socket, a file for ``.zarr``) is refused before it is opened; a
    symbolic link is followed (the store is written where it points).
    """
    fmt = format_of(output)
    need("zarr" if fmt == "zarr" else "netCDF4")
    real = real_output(output)
    try:
        st = os.stat(real)
    except OSError:
        st = None
    if st is not None:
        if fmt == "netcdf":
            regular_target(real, "-o/--output")
        elif not stat.S_ISDIR(st.st_mode):
            raise ValueError(
                f"-o/--output {str(output)!r} is {file_kind(st.st_mode)}, not a Zarr store (a "
                "directory): linecontact replaces only a sweep's store (give another path)"
            )
    parent = Path(real).absolute().parent
    if not parent.is_dir():
        raise ValueError(
            f"cannot write -o/--output {str(output)!r}: {str(parent)!r} is no directory"
        )
    if not os.access(parent, os.W_OK | os.X_OK):
        raise ValueError(
            f"cannot write -o/--output {str(output)!r}: {str(parent)!r} is not writable"
        )


def _usage(p: Plan) -> Any:
    """Refuse a sweep whose first and last points are both refused; a table of one that passes.

    Both refused is a usage error (a missing or conflicting flag), not points outside the
    domain. Only the first point is computed where it passes.
    """
    reasons: list[str] = []
    for at in (0, -1):
        values = {a.dest: a.values[at] for a in p.axes}
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            table, state, reason = call(p, values, [])
        if table is not None:
            return table
        if state != "invalid":
            return None
        reasons.append(reason)
    raise ValueError(reasons[0])


def _bytes_per_point(p: Plan, table: Any) -> tuple[int, int]:
    """Bytes a point takes (in a block on disk, in memory), from the table of one point.

    A table of one call holds one point's records, or a row of points where the innermost
    axis is one the subcommand takes at once (then one record each).
    """
    per_record_disk = per_record_memory = 0
    for v in table.columns.values():
        kind = np.asarray(v).dtype.kind
        per_record_disk += 1 if kind == "b" else 8 if kind in "fiuc" else 4  # text: codes
        per_record_memory += 1 if kind == "b" else 8  # text: a pointer each
    per_record_disk += 8  # state and reason, as codes
    per_record_memory += 16
    records = 1 if p.vector is not None else max(1, int(table.size))
    return per_record_disk * records, per_record_memory * records


def _available_memory() -> int | None:
    """The memory the system can give [bytes] (``MemAvailable``), where it says it."""
    try:
        with open("/proc/meminfo", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    try:
        return int(os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE"))
    except (ValueError, OSError, AttributeError):
        return None


def _gb(n: float) -> str:
    return f"{n / 1e9:.3g} GB"


def _check_fits(p: Plan, table: Any, output: str | os.PathLike[str] | None) -> None:
    """Refuse a sweep whose estimated memory or disk is more than the machine has.

    In memory, the dataset and the blocks it is built from; on disk, the kept blocks and then
    the store beside them (the store's compression not counted: an upper bound).
    """
    if table is None:
        return
    disk, memory = _bytes_per_point(p, table)
    points = " x ".join(f"{a.name} ({len(a.values)})" for a in p.axes) or "one point"
    size = f"the sweep has {p.size} points ({points})"
    if output is None:
        need_mem = 2 * memory * p.size
        have = _available_memory()
        if have is not None and need_mem > 0.8 * have:
            raise ValueError(
                f"{size}: about {_gb(need_mem)} in memory, more than the {_gb(have)} this "
                "machine has free; write it to a store (-o OUT / output=) or sweep fewer points"
            )
        return
    need_disk = 2 * disk * p.size
    parent = Path(output).absolute().parent
    try:
        free = shutil.disk_usage(parent).free
    except OSError:
        return
    if need_disk > free:
        raise ValueError(
            f"{size}: about {_gb(need_disk)} on disk (its blocks, then the store), more than "
            f"the {_gb(free)} free at {str(parent)!r}; sweep fewer points or write elsewhere"
        )


def _names(key: str, name: str) -> bool:
    """True where the provenance key ``key`` is the flag ``name`` (``radius_m``: ``radius``)."""
    return key == name or (key.startswith(name + "_") and "over" not in key[len(name) + 1 :])


def _covers(p: Plan, ats: list[dict[str, Any]]) -> bool:
    """True where the points ``ats`` take two values or more of every axis."""
    for a in p.axes:
        seen: set[str] = set()
        for at in ats:
            v = at.get(a.dest)
            seen.update(repr(x) for x in (v if isinstance(v, list) else [v]) if x is not None)
        if len(seen) < 2:
            return False
    return True


def _shared(p: Plan, metas: list[dict[str, Any]]) -> dict[str, Any]:
    """The provenance parameters the same at every point.

    Those that the blocks' first points share, where those points take two values or more of
    every swept flag; else those that the corners of the grid (at most 16) share. A parameter
    that is a swept flag is never among them; where the points computed do not vary every
    swept flag (points refused), only the fixed flags are.
    """
    import itertools

    found = [(m["parameters"], m.get("at") or {}) for m in metas if m.get("parameters")]
    if not _covers(p, [at for _, at in found]):
        ends = [sorted({0, len(a.values) - 1}) for a in p.axes]
        found = []
        for ix in itertools.islice(itertools.product(*ends), 16):
            values = {a.dest: a.values[i] for a, i in zip(p.axes, ix, strict=True)}
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                table, _, _ = call(p, values, [])
            if table is not None:
                found.append((table.provenance()["parameters"], values))
    if not found:
        return {}
    first = found[0][0]
    out = {k: v for k, v in first.items() if all(t.get(k) == v for t, _ in found[1:])}
    out = {k: v for k, v in out.items() if not any(_names(k, a.name) for a in p.axes)}
    if not _covers(p, [at for _, at in found]):
        fixed = [w.lstrip("-").replace("-", "_") for w in p.fixed if w.startswith("--")]
        out = {k: v for k, v in out.items() if any(_names(k, n) for n in fixed)}
    return out


def _say(metas: list[dict[str, Any]]) -> None:
    """The blocks' warnings, each kind once (numbers aside), with how many points gave it."""
    kinds: dict[str, tuple[str, str, int]] = {}
    for m in metas:
        for cat, text in m.get("warnings", []):
            shape = re.sub(r"[-+]?\d[\d.]*(e[-+]?\d+)?", "#", text)
            c, t, n = kinds.get(shape, (cat, text, 0))
            kinds[shape] = (c, t, n + 1)
    for cat, text, n in kinds.values():
        category = getattr(_errors, cat, UserWarning)
        if not (isinstance(category, type) and issubclass(category, Warning)):
            category = UserWarning
        more = f" [and {n - 1} more like it in this sweep]" if n > 1 else ""
        warnings.warn(text + more, category, stacklevel=3)


#: The local cluster's workers: one thread each, no statistical profiler (a block is one
#: task), and glibc's own malloc thresholds. Dask sets ``MALLOC_TRIM_THRESHOLD_`` for its
#: workers, which fixes glibc's mmap threshold too: every array over 128 kB is then mapped and
#: unmapped, and the Lennard-Jones curves took 30 % longer in system time (2.2 s against
#: 0.45 s for 30 curves; ``benchmarks/sweep.py``).
_WORKER_CONFIG = {
    "distributed.worker.profile.enabled": False,
    "distributed.nanny.pre-spawn-environ": {
        "OMP_NUM_THREADS": 1,
        "MKL_NUM_THREADS": 1,
        "OPENBLAS_NUM_THREADS": 1,
    },
}


def _local(p: Plan, todo: list[int], bl: list[tuple[slice, ...]]) -> Iterator[Block]:
    for k in todo:
        yield evaluate(p, k, bl[k])


def _one_thread() -> None:
    """A pool worker's start: one BLAS thread (the workers share the cores among them)."""
    from threadpoolctl import threadpool_limits

    threadpool_limits(1)


def _kept_by_worker(p: Plan, index: int, block: tuple[slice, ...], partial: Partial) -> Block:
    """Block ``index`` computed and kept (``partial.put``) by the worker: its record, no data.

    A local worker writes to the same disk: sending a block's arrays here to be written by
    one process took a third of a 1e7-point sweep on two workers (issue 36).
    """
    done = evaluate(p, index, block)
    partial.put(done)
    return Block(
        done.index, {}, done.units, done.parameters, done.warnings, done.at, done.code, kept=True
    )


def _processes(
    p: Plan, todo: list[int], bl: list[tuple[slice, ...]], workers: int, partial: Partial
) -> Iterator[Block]:
    """The blocks ``todo`` in a pool of ``workers`` local processes, as they finish.

    Forked where the system can (the workers inherit the imported library: no start-up, and
    a script needs no ``if __name__ == "__main__"`` guard), else spawned; at most two blocks
    a worker in flight, the rest queued here; ended at the first failure or interrupt. With
    a store the workers keep their blocks themselves (:func:`_kept_by_worker`).
    """
    import multiprocessing
    from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait

    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
    with warnings.catch_warnings():
        # Python >= 3.12 warns that fork() in a process with threads (BLAS pools) may
        # deadlock the child; the workers run NumPy and SciPy only, as the map's
        warnings.filterwarnings("ignore", message=".*fork.*", category=DeprecationWarning)
        pool = ProcessPoolExecutor(
            workers, mp_context=multiprocessing.get_context(method), initializer=_one_thread
        )
    queue = list(todo)
    running: set[Future[Block]] = set()

    def submit(k: int) -> Future[Block]:
        if partial.dir is None:
            return pool.submit(evaluate, p, k, bl[k])
        return pool.submit(_kept_by_worker, p, k, bl[k], partial)

    try:
        with warnings.catch_warnings():
            warnings.filterwarnings("ignore", message=".*fork.*", category=DeprecationWarning)
            while queue and len(running) < 2 * workers:
                running.add(submit(queue.pop(0)))
        while running:
            finished, running = wait(running, return_when=FIRST_COMPLETED)
            for fut in finished:
                block = fut.result()
                if queue:
                    running.add(submit(queue.pop(0)))
                yield block
    except BaseException:
        pool.shutdown(wait=False, cancel_futures=True)
        raise
    pool.shutdown(wait=True)


#: Seconds to wait for a scheduler to answer (a TCP connection, then Dask's handshake).
CONNECT_TIMEOUT = 10.0


def _address(scheduler: str) -> tuple[str, str | None, int | None]:
    """``scheduler`` as Dask's address, and its host and port where it is TCP or TLS."""
    address = scheduler if "://" in scheduler else f"tcp://{scheduler}"
    scheme, _, rest = address.partition("://")
    if scheme not in ("tcp", "tls"):
        return address, None, None
    host, colon, port = rest.rpartition(":")
    host = host.strip("[]")
    if not (colon and host and port.isdigit() and 0 < int(port) < 65536):
        raise ValueError(
            f"--scheduler {scheduler!r}: give the scheduler's address as tcp://HOST:PORT "
            "(the port in 1-65535)"
        )
    return address, host, int(port)


def _collect_clients() -> None:
    """Collect the Dask clients no longer used before a new one starts its event loop.

    A client that failed to connect (a server that is not a scheduler) is left in a reference
    cycle; collected while ``distributed`` starts another one's loop, its ``__del__`` waits on
    the lock that start holds, and every later client or cluster of the process waits too (a
    sweep after a refused ``--scheduler``, in one Python session). Collected here, first, it
    cannot be.
    """
    gc.collect()


def _connect(scheduler: str, timeout: float = CONNECT_TIMEOUT) -> Any:
    """A client of the ``dask.distributed`` scheduler at ``scheduler`` (ValueError: none).

    Bounded: nothing listening, a server that is not a Dask scheduler (which Dask may read as
    a message of exabytes, or wait on past its own timeout) and a scheduler that does not
    answer within ``timeout`` seconds are each one ValueError naming the flag.
    """
    need("distributed")
    from dask.distributed import Client

    address, host, port = _address(scheduler)
    if host is not None and port is not None:
        try:
            socket.create_connection((host, port), timeout=timeout).close()
        except OSError as exc:
            why = exc.strerror or str(exc) or type(exc).__name__
            raise ValueError(f"--scheduler {scheduler!r}: cannot connect ({why})") from None
    found: dict[str, Any] = {}

    def connect() -> None:
        try:
            _collect_clients()
            found["client"] = Client(address, timeout=f"{timeout}s")
        except BaseException as exc:  # noqa: BLE001 - anything is: no scheduler there
            found["error"] = exc

    thread = threading.Thread(target=connect, name="linecontact-scheduler", daemon=True)
    thread.start()
    thread.join(timeout + 2.0)
    if "client" in found:
        return found["client"]
    if thread.is_alive():
        raise ValueError(
            f"--scheduler {scheduler!r}: no dask.distributed scheduler answered within "
            f"{timeout:g} s (is it one?)"
        )
    err = found.get("error")
    why = f"{type(err).__name__}: {str(err)[:200]}" if err is not None else "no answer"
    raise ValueError(
        f"--scheduler {scheduler!r}: no dask.distributed scheduler answered there ({why})"
    )


def _dask(
    p: Plan, todo: list[int], bl: list[tuple[slice, ...]], workers: int, client: Any
) -> Iterator[Block]:
    """The blocks ``todo`` on Dask: on ``client``'s cluster, or a local one of ``workers``."""
    need("distributed")
    import dask
    from dask.distributed import Client, LocalCluster, as_completed

    cluster = None
    if client is None:
        _collect_clients()
        with dask.config.set(_WORKER_CONFIG):
            cluster = LocalCluster(
                n_workers=workers,
                threads_per_worker=1,
                processes=True,
                dashboard_address=None,
                silence_logs=logging.ERROR,
                memory_limit=0,  # a block's memory is bounded; no monitor polling the workers
            )
        client = Client(cluster)
    try:
        nworkers = max(1, len(client.scheduler_info().get("workers", {})) or workers)
        queue = list(todo)
        running = as_completed()
        for _ in range(min(len(queue), 2 * nworkers)):
            k = queue.pop(0)
            running.add(client.submit(evaluate, p, k, bl[k], pure=False))
        for fut in running:
            block = fut.result()
            fut.release()
            if queue:
                k = queue.pop(0)
                running.add(client.submit(evaluate, p, k, bl[k], pure=False))
            yield block
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def run(
    p: Plan,
    output: str | os.PathLike[str] | None = None,
    *,
    workers: int = 1,
    scheduler: str | None = None,
    progress: bool | None = None,
    overwrite: bool = False,
) -> Any:
    """Compute the plan ``p`` (resuming the blocks kept at ``output``); its dataset.

    Before anything is written: the output's path, the first (or last) point, the memory or
    disk the sweep needs, and the scheduler. Then, holding the lock of ``output``: a
    finished store of this sweep and this build is read back; the kept blocks of this build
    are reused, the rest computed; each block from a Dask worker must come from this build.
    """
    need()
    if isinstance(workers, bool) or not (isinstance(workers, int) and workers >= 1):
        raise ValueError(f"--workers must be an integer >= 1, got {workers!r}")
    if output is not None:
        _check_output(output)
        _check_store(p, output, overwrite)
    _check_fits(p, _usage(p), output)  # before anything is written
    client = None if scheduler is None else _connect(scheduler)
    partial = Partial(p, output)
    try:
        with partial.locked():
            if output is not None:
                if _check_store(p, output, overwrite):  # done by a run that held the lock
                    partial.remove()
                    return open_sweep(output)
            partial.open(overwrite)
            partial.check()
            _compute(p, partial, workers, client, scheduler, progress)
            client = None  # closed by _dask
            metas = [partial.meta(k) for k in range(len(blocks(p.shape, p.chunk_points)))]
            _say(metas)
            ds = build(p, partial, _shared(p, metas))
            if output is None:
                return ds
            write(ds, output, overwrite=True)
            partial.remove()
    finally:
        if client is not None:
            client.close()
    return open_sweep(output)


def _check_store(p: Plan, output: str | os.PathLike[str], overwrite: bool) -> bool:
    """True where ``output`` is this sweep's finished store (of this build); else a check.

    A store of another sweep, or of this sweep computed by another build, or anything else
    at the path, is refused unless ``overwrite``; even then only a store is replaced.
    """
    out = Path(output)
    if not (out.exists() or out.is_symlink()):
        return False
    key = store_key(output)
    if key == p.key() and not overwrite:
        return True  # finished before: nothing to do
    if key is None:
        what = "is not the store of a linecontact sweep"
        if out.is_symlink() or not (out.is_dir() if format_of(output) == "zarr" else out.is_file()):
            raise ValueError(
                f"-o/--output {str(output)!r} {what}: linecontact replaces only a sweep's store "
                "(give another path)"
            )
        if not overwrite:
            raise ValueError(f"-o/--output {str(output)!r} {what}: give --overwrite to replace it")
        return False
    if overwrite:
        return False
    ours = p.identity() == store_identity(output)
    raise ValueError(
        f"-o/--output {str(output)!r} holds "
        + (
            "this sweep computed by another build of linecontact (another version, an edited "
            "module, or another NumPy or SciPy): give --overwrite to compute it again"
            if ours
            else "the store of another sweep (another command or flags)"
            ": give --overwrite to replace it"
        )
    )


def _compute(
    p: Plan,
    partial: Partial,
    workers: int,
    client: Any,
    scheduler: str | None,
    progress: bool | None,
) -> None:
    """Compute the blocks not yet kept, keeping each as it finishes."""
    bl = blocks(p.shape, p.chunk_points)
    done = partial.done()
    todo = [k for k in range(len(bl)) if k not in done]
    size = {k: _points(b) for k, b in enumerate(bl)}
    bar = progress_bar(p.size, f"sweep {p.command}", progress, initial=sum(size[k] for k in done))
    code = code_digest()
    try:
        if scheduler is None and (workers == 1 or len(todo) <= 1):
            if client is not None:
                client.close()
            stream = _local(p, todo, bl)
        elif scheduler is None:
            stream = _processes(p, todo, bl, min(workers, len(todo)), partial)
        else:
            stream = _dask(p, todo, bl, workers, client)
        for block in stream:
            if block.code != code:
                raise ValueError(
                    f"--scheduler {scheduler!r}: a worker computed block {block.index} with "
                    "another build of linecontact (another version, an edited module, or "
                    "another NumPy or SciPy): install this build on the workers (nothing of "
                    "theirs was kept)"
                )
            if not block.kept:
                partial.put(block)
            bar.update(size[block.index])
    finally:
        bar.close()


def _points(b: tuple[slice, ...]) -> int:
    n = 1
    for s in b:
        n *= s.stop - s.start
    return n
