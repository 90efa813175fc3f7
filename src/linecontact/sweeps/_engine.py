"""Running a sweep: its blocks in this process, or on Dask workers; kept as they finish.

``workers=1`` (and no scheduler) computes the blocks here, one after the other. More workers
start a :class:`dask.distributed.LocalCluster` of processes; ``scheduler="tcp://host:port"``
sends the blocks to a running ``dask.distributed`` cluster (its workers need linecontact
installed; they return the blocks here, so they need no shared disk). Either way the blocks
are the same computations and give the same dataset. A progress bar on stderr (tqdm) counts
the points.
"""

from __future__ import annotations

import logging
import os
import re
import warnings
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from .. import errors as _errors
from .._progress import progress_bar
from ._block import Block, call
from ._dataset import build, open_sweep, write
from ._plan import Plan, blocks
from ._points import evaluate
from ._store import Partial, format_of, need, store_key

__all__ = ["run"]


def _check_output(output: str | os.PathLike[str]) -> None:
    fmt = format_of(output)
    need("zarr" if fmt == "zarr" else "netCDF4")
    parent = Path(output).absolute().parent
    if not parent.is_dir():
        raise ValueError(
            f"cannot write -o/--output {str(output)!r}: {str(parent)!r} is no directory"
        )
    if not os.access(parent, os.W_OK | os.X_OK):
        raise ValueError(
            f"cannot write -o/--output {str(output)!r}: {str(parent)!r} is not writable"
        )


def _usage(p: Plan) -> None:
    """Refuse a sweep whose first and last points are both refused.

    That is a usage error (a missing or conflicting flag), not points outside the domain.
    Only the first point is computed where it passes.
    """
    reasons: list[str] = []
    for at in (0, -1):
        values = {a.dest: a.values[at] for a in p.axes}
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            table, state, reason = call(p, values, [])
        if table is not None or state != "invalid":
            return
        reasons.append(reason)
    raise ValueError(reasons[0])


def _shared(p: Plan, metas: list[dict[str, Any]]) -> dict[str, Any]:
    """The provenance parameters the same at every point.

    Those the blocks' first points share; the corners of the grid (at most 16) where fewer
    than two blocks computed points one by one.
    """
    import itertools

    found = [m["parameters"] for m in metas if m.get("parameters")]
    if len(found) < 2:  # one block, or blocks at once (no table): the corners, at most 16
        ends = [sorted({0, len(a.values) - 1}) for a in p.axes]
        found = []
        for ix in itertools.islice(itertools.product(*ends), 16):
            values = {a.dest: a.values[i] for a, i in zip(p.axes, ix, strict=True)}
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                table, _, _ = call(p, values, [])
            if table is not None:
                found.append(table.provenance()["parameters"])
    if not found:
        return {}
    return {k: v for k, v in found[0].items() if all(t.get(k) == v for t in found[1:])}


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


def _connect(scheduler: str) -> Any:
    """A client of the ``dask.distributed`` scheduler at ``scheduler`` (ValueError: none)."""
    need("distributed")
    from dask.distributed import Client

    try:
        return Client(scheduler, timeout="5s")
    except (OSError, TimeoutError, ValueError) as exc:
        raise ValueError(f"--scheduler {scheduler!r}: cannot connect ({exc})") from None


def _dask(
    p: Plan, todo: list[int], bl: list[tuple[slice, ...]], workers: int, client: Any
) -> Iterator[Block]:
    """The blocks ``todo`` on Dask: on ``client``'s cluster, or a local one of ``workers``."""
    need("distributed")
    import dask
    from dask.distributed import Client, LocalCluster, as_completed

    cluster = None
    if client is None:
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
    """Compute the plan ``p`` (resuming the blocks kept at ``output``); its dataset."""
    need()
    if not (isinstance(workers, int) and workers >= 1):
        raise ValueError(f"--workers must be an integer >= 1, got {workers!r}")
    if output is not None:
        _check_output(output)
        if Path(output).exists():
            if store_key(output) == p.key() and not overwrite:
                return open_sweep(output)  # finished before: nothing to do
            if not overwrite:
                raise ValueError(
                    f"-o/--output {str(output)!r} exists and is not this sweep's store (another "
                    "command, flags or version, or not a sweep): give --overwrite to replace it"
                )
    _usage(p)  # before anything is written
    client = None if scheduler is None else _connect(scheduler)
    partial = Partial(p, output)
    try:
        partial.open(overwrite)
    except BaseException:
        if client is not None:
            client.close()
        raise
    bl = blocks(p.shape, p.chunk_points)
    done = partial.done()
    todo = [k for k in range(len(bl)) if k not in done]
    size = {k: _points(b) for k, b in enumerate(bl)}
    bar = progress_bar(p.size, f"sweep {p.command}", progress, initial=sum(size[k] for k in done))
    try:
        if scheduler is None and (workers == 1 or len(todo) <= 1):
            stream = _local(p, todo, bl)
        else:
            stream = _dask(p, todo, bl, workers, client)
        for block in stream:
            partial.put(block)
            bar.update(size[block.index])
    finally:
        bar.close()
    metas = [partial.meta(k) for k in range(len(bl))]
    _say(metas)
    ds = build(p, partial, _shared(p, metas))
    if output is None:
        return ds
    write(ds, output, overwrite=True)
    partial.remove()
    return open_sweep(output)


def _points(b: tuple[slice, ...]) -> int:
    n = 1
    for s in b:
        n *= s.stop - s.start
    return n
