"""Small dense linear algebra on one BLAS thread: around the solve, not for the process.

The dense systems of the Lennard-Jones solver (450 to 650 unknowns) are too small to gain
from BLAS threads, and with another job on the machine the threads fight it for the cores:
measured on 2 cores with a busy loop on one, a pull-off and a curve took about 2x their
quiet time with OpenBLAS's default threads (issue 37; ``benchmarks/busy_core.py``).
:func:`one_blas_thread` limits every BLAS library loaded (NumPy's and SciPy's) to one thread
while its block runs and gives back whatever the caller had set when it ends
(:mod:`threadpoolctl`), so that a caller's own settings are never changed.

The limit is the process's while a block runs (the BLAS libraries have no other): BLAS
calls of other Python threads meanwhile run on one thread too. Blocks of several threads
at once share one limit: the first to enter sets it, the last to leave gives back the
counts from before the first, so that overlapping solves cannot leave the process on one
thread.
"""

from __future__ import annotations

import functools
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any, TypeVar

__all__ = ["one_blas_thread", "on_one_blas_thread"]

F = TypeVar("F", bound=Callable[..., Any])


@functools.lru_cache(maxsize=1)
def _controller() -> Any:
    """The BLAS libraries of the process, found once (after SciPy's linear algebra loads)."""
    import scipy.linalg  # noqa: F401 - its BLAS is loaded lazily: load it before the search
    from threadpoolctl import ThreadpoolController

    return ThreadpoolController()


class _Limit:
    """The one limit of the process: set by the first block to enter, lifted by the last."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._depth = 0
        self._limiter: Any = None

    def enter(self) -> None:
        with self._lock:
            if self._depth == 0:
                self._limiter = _controller().limit(limits=1, user_api="blas")
            self._depth += 1

    def leave(self) -> None:
        with self._lock:
            self._depth -= 1
            if self._depth == 0:
                self._limiter.restore_original_limits()
                self._limiter = None


_LIMIT = _Limit()


@contextmanager
def one_blas_thread() -> Iterator[None]:
    """Run the block with every BLAS library on one thread; restore the caller's after."""
    _LIMIT.enter()
    try:
        yield
    finally:
        _LIMIT.leave()


def on_one_blas_thread(fn: F) -> F:
    """``fn`` run inside :func:`one_blas_thread`."""

    @functools.wraps(fn)
    def wrapped(*args: Any, **kwargs: Any) -> Any:
        with one_blas_thread():
            return fn(*args, **kwargs)

    return wrapped  # type: ignore[return-value]
