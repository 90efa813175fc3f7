"""The adhesion map's curves: in parallel, resumable.

One row of the map per ``mu`` (:class:`_Row`, from :func:`linecontact.adhesion_map._map_row`),
computed in this process or in worker processes (:func:`_run`), each kept as soon as it is
done in a file of its own in the resume directory, written atomically and keyed by what
determines it (:func:`_row_key`).
"""

from __future__ import annotations

import hashlib
import json
import os
import pathlib
import signal
import warnings
import zipfile
from collections.abc import Callable, Iterator
from contextlib import contextmanager, suppress
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._fingerprint import code_digest


def _check_workers(workers) -> int:
    """``workers`` as a count (``None``: the cores this process may run on)."""
    if workers is None:
        return _cores()
    if isinstance(workers, (bool, np.bool_)) or not isinstance(workers, (int, np.integer)):
        raise ValueError(f"workers must be an integer >= 1, got {workers!r}")
    if workers < 1:
        raise ValueError(f"workers must be an integer >= 1, got {workers!r}")
    return int(workers)


def _cores() -> int:
    """The cores this process may run on."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


@dataclass(frozen=True)
class _Row:
    """What the map keeps of the full law at one ``mu`` (:func:`_map_row`)."""

    F_pulloff: float
    y_onset: float
    half_width: NDArray
    lj_error_estimate: float
    interpolation_error: float
    n_states: int


_ENTRY_FORMAT = 1  # of the files in the resume directory; part of their key
_READ_ERRORS = (OSError, ValueError, KeyError, EOFError, zipfile.BadZipFile)


def _code_digest() -> str:
    """The digest of the code and the entry format (a row depends on the solver's code)."""
    return hashlib.sha256(f"{_ENTRY_FORMAT} {code_digest()}".encode()).hexdigest()


def _row_key(mu: float, y: NDArray) -> str:
    """What determines a row: ``mu``, the loads (and so ``F_max``), the code (its version)."""
    doc = {"mu": float(mu).hex(), "y": [float(v).hex() for v in y], "code": _code_digest()}
    return hashlib.sha256(json.dumps(doc, sort_keys=True).encode()).hexdigest()


def _entry(store: pathlib.Path, mu: float, key: str) -> pathlib.Path:
    return store / f"mu{mu:.6e}-{key[:16]}.npz"


def _read_row(path: pathlib.Path, key: str, n_y: int) -> _Row | None:
    """The row in the file ``path`` if it is one of the key ``key``, else None."""
    try:
        with np.load(path, allow_pickle=False) as d:
            if str(d["key"]) != key:
                return None
            row = _Row(
                F_pulloff=float(d["F_pulloff"]),
                y_onset=float(d["y_onset"]),
                half_width=np.array(d["half_width"], float),
                lj_error_estimate=float(d["lj_error_estimate"]),
                interpolation_error=float(d["interpolation_error"]),
                n_states=int(d["n_states"]),
            )
    except _READ_ERRORS:  # none yet, or not one of ours: computed (again)
        return None
    return row if row.half_width.shape == (n_y,) else None


def _write_row(path: pathlib.Path, key: str, row: _Row) -> None:
    """Write ``row`` to ``path`` atomically (a temporary file, then renamed); best effort.

    A file that cannot be written is left out: the row is then computed again by a rerun.
    """
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")  # never read as an entry
    try:
        with open(tmp, "wb") as f:
            fields: dict[str, Any] = {k: np.asarray(v) for k, v in vars(row).items()}
            np.savez(f, key=np.array(key), **fields)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except OSError:
        with suppress(OSError):
            tmp.unlink()


def _store(resume_dir) -> pathlib.Path | None:
    """The resume directory, created if missing (ValueError naming ``resume_dir``)."""
    if resume_dir is None:
        return None
    try:
        store = pathlib.Path(os.fspath(resume_dir))
    except TypeError:
        raise ValueError(f"resume_dir must be a path, got {resume_dir!r}") from None
    try:
        store.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ValueError(
            f"resume_dir {str(store)!r} cannot be created: {exc.strerror or exc}"
        ) from None
    return store


def _clear(store: pathlib.Path, paths: list[pathlib.Path]) -> None:
    """Remove the map's entries (and their stale temporary files), then ``store`` if empty."""
    for p in paths:
        for f in (p, *store.glob(f".{p.name}.*.tmp")):
            with suppress(OSError):
                f.unlink()
    with suppress(OSError):
        store.rmdir()


#: The function of one row (the package's ``_map_row``), set by :func:`_run` here and in
#: the workers (inherited where they are forked, passed to their initializer where spawned).
_ROW: list[Callable[[float, NDArray], _Row]] = []


def _task(task: tuple[int, float, NDArray, str | None, str]) -> tuple[int, _Row]:
    """One row, kept in its file as soon as it is done (run in a worker, or here)."""
    k, mu, y, path, key = task
    row = _ROW[0](mu, y)
    if path is not None:
        _write_row(pathlib.Path(path), key, row)
    return k, row


def _worker_init(row_of: Callable[[float, NDArray], _Row], blas: int | None) -> None:
    """Ctrl-C stops the map in the parent process, which then ends the workers.

    A worker runs ``blas`` BLAS threads (the cores shared among the workers; None: as the
    user's environment says): a forked one
    inherits the parent's BLAS already started with its threads, which the environment
    (:func:`_blas_threads`, for spawned ones) no longer sets. With two forked workers each
    on the parent's two threads, the map took as long as on one worker.
    """
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    _ROW[:] = [row_of]
    if blas is not None:
        import scipy.linalg  # noqa: F401 - SciPy's BLAS loads lazily: loaded, then limited
        from threadpoolctl import threadpool_limits

        threadpool_limits(blas)


_BLAS_THREADS = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")


@contextmanager
def _blas_threads(n: int) -> Iterator[None]:
    """Processes started inside use ``n`` BLAS threads (where the user has not said)."""
    unset = [v for v in _BLAS_THREADS if v not in os.environ]
    for v in unset:
        os.environ[v] = str(n)
    try:
        yield
    finally:
        for v in unset:
            os.environ.pop(v, None)


def _run(
    tasks: list,
    workers: int,
    done: Callable[[int, _Row], None],
    row_of: Callable[[float, NDArray], _Row],
) -> None:
    """Compute ``tasks`` by ``row_of``, passing each row to ``done`` as it finishes.

    In this process if ``workers`` is 1, else in that many processes, the dearest (largest
    ``mu``) first; ended as soon as one fails or this process is interrupted. The workers
    are forked where the system can (they inherit the imported library, and a script that
    calls the map needs no ``if __name__ == "__main__"`` guard), else spawned: the task is
    a module-level function of picklable arguments.
    """
    _ROW[:] = [row_of]
    if workers <= 1:
        for t in tasks:
            done(*_task(t))
        return
    import multiprocessing

    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
    ctx = multiprocessing.get_context(method)
    blas = max(1, _cores() // workers)
    said = any(v in os.environ for v in _BLAS_THREADS)  # the user's word stands
    with warnings.catch_warnings(), _blas_threads(blas):
        # Python >= 3.12 warns that fork() in a process with threads (BLAS pools) may
        # deadlock the child; the workers only run NumPy and SciPy, as the figures' worker
        warnings.filterwarnings("ignore", message=".*fork.*", category=DeprecationWarning)
        # the row's function reaches forked workers as it is, spawned ones by name
        pool = ctx.Pool(
            workers, initializer=_worker_init, initargs=(row_of, None if said else blas)
        )
    try:
        for k, row in pool.imap_unordered(_task, sorted(tasks, key=lambda t: -t[1])):
            done(k, row)
    except BaseException:
        pool.terminate()
        pool.join()
        raise
    pool.close()
    pool.join()
