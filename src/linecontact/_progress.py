"""Progress bars on stderr for long work: tqdm where installed, else a plain line.

Shown where stderr is a terminal, or where the caller forces it (``progress=True``, the
command line's ``--progress``); never on stdout, so that piped output stays clean.
"""

from __future__ import annotations

import sys
from typing import Any

__all__ = ["progress_bar"]


class _Line:
    """A progress line of counts, where tqdm is not installed."""

    def __init__(self, total: int, initial: int, desc: str, unit: str, show: bool) -> None:
        self.total, self.n, self.desc, self.unit, self.show = total, initial, desc, unit, show

    def update(self, n: int = 1) -> None:
        self.n += n
        if self.show:
            line = f"\r{self.desc}: {self.n}/{self.total}{self.unit}"
            print(line, end="", file=sys.stderr, flush=True)

    def close(self) -> None:
        if self.show:
            print(file=sys.stderr, flush=True)

    def __enter__(self) -> _Line:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def progress_bar(
    total: int, desc: str, progress: bool | None = None, *, initial: int = 0, unit: str = ""
) -> Any:
    """A progress bar of ``total`` steps on stderr (a context manager; ``update(n)``).

    Parameters
    ----------
    total : int
        The number of steps.
    desc : str
        What is counted, shown before the counts.
    progress : bool or None
        Show it (True), hide it (False), or show it where stderr is a terminal (None).
    initial : int
        Steps already done (a resumed run).
    unit : str
        The unit of a step, with its leading space (``" points"``).
    """
    show = _isatty() if progress is None else bool(progress)
    try:
        from tqdm import tqdm  # type: ignore[import-untyped,unused-ignore]
    except ImportError:
        return _Line(total, initial, desc, unit, show)
    return tqdm(
        total=total,
        initial=initial,
        desc=desc,
        disable=not show,
        file=sys.stderr,
        unit=unit.strip() or "it",
        dynamic_ncols=True,
        mininterval=0.5,
    )


def _isatty() -> bool:
    isatty = getattr(sys.stderr, "isatty", None)
    try:
        return bool(isatty and isatty())
    except (ValueError, OSError):  # a closed stream
        return False
