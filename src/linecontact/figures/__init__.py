"""The paper's figures (Figs. 2--14), redrawn from the library's solvers.

One module per family of figures, each with the parameters it draws and why:
:mod:`linecontact.figures.normal` (Figs. 2--6), :mod:`linecontact.figures.tangential`
(Figs. 7, 13, 14), :mod:`linecontact.figures.sliding` (Figs. 8--12); the shared plumbing in
:mod:`linecontact.figures._style`. matplotlib is imported only when a figure is drawn.
"""

from __future__ import annotations

import os
import pathlib
from collections.abc import Callable, Iterable

from . import normal as _normal
from . import sliding as _sliding
from . import tangential as _tangential
from ._style import _mpl, _save

__all__ = ["paper_figures"]


def paper_figures(
    outdir: str | os.PathLike = "paper-figures",
    *,
    formats: Iterable[str] = ("png", "svg"),
    progress: Callable[[str], object] | None = None,
) -> list[pathlib.Path]:
    """Draw the figures of the paper (Figs. 2--14) into ``outdir``.

    Parameters
    ----------
    outdir : str or os.PathLike
        Output directory, created if missing; existing files of the same names are
        overwritten.
    formats : iterable of str
        File formats understood by matplotlib (a single string is one format). PNG is
        written at 150 dpi; PNG, SVG and PDF carry ``Creator: linecontact <version>``.
    progress : callable, optional
        Called with a short message before each step; nothing is printed otherwise.

    Returns
    -------
    list of pathlib.Path
        The files written, figure by figure, in the order of ``formats``.

    Raises
    ------
    ImportError
        If matplotlib is not installed.
    ValueError
        If ``formats`` is empty.

    Notes
    -----
    The parameters of each figure and the reasons for them are in the docstrings of
    :mod:`linecontact.figures.normal`, :mod:`~linecontact.figures.tangential` and
    :mod:`~linecontact.figures.sliding`.
    """
    _mpl()
    fmts = (formats,) if isinstance(formats, str) else tuple(formats)
    if not fmts or not all(isinstance(f, str) and f for f in fmts):
        raise ValueError(f"formats must be a non-empty sequence of format names, got {formats!r}")
    fmts = tuple(f.lower().lstrip(".") for f in fmts)
    say = progress if progress is not None else (lambda msg: None)
    out = pathlib.Path(outdir)
    out.mkdir(parents=True, exist_ok=True)

    written: list[pathlib.Path] = []
    jobs = _normal.jobs(say) + _tangential.jobs() + _sliding.jobs(say)
    for stem, build in jobs:
        say(f"drawing {stem} ({', '.join(fmts)})")
        written += _save(build(), out, stem, fmts)
    say(f"wrote {len(written)} files to {out}")
    return written
