"""The ``map`` subcommand: the adhesion map of line contact, drawn, with its data file.

Its parser and its numbers are the operation's (:mod:`linecontact.operations.adhesion_map`);
this shell has the files: it writes ``adhesion_map.<format>`` (each format) and
``adhesion_map.csv`` (one row per cell, the provenance block in its header) into
``--outdir``; it prints the files and a summary per ``mu``, or with ``--json`` (``--format
json|jsonl|csv``, as the other commands) the provenance block and the cells; ``-o FILE``
writes that output to FILE. The figure's formats are ``--image-format``. The curves are
computed in ``--workers`` processes; each finished one is kept in
``OUTDIR/adhesion_map.partial/`` (emptied and removed when the map is written), so that the
same command, rerun after a stop, goes on.
"""

from __future__ import annotations

import argparse
import pathlib
import sys
from contextlib import suppress
from typing import Any

from ..operations import get
from ..operations.adhesion_map import cells, grid
from ..output import FORMATS, write
from ._build import add, inputs_of
from ._options import emit, write_failure

__all__ = ["register"]

#: The directory in ``--outdir`` where the finished curves are kept until the map is done.
PARTIAL = "adhesion_map.partial"


def register(sub: Any) -> None:
    """Add the ``map`` subcommand to the subparsers ``sub``."""
    add(sub, get("map"), _cmd_map)


def _clear_partial(partial: pathlib.Path) -> None:
    """Remove the entries left in ``partial`` (of other grids, other versions), then it."""
    if not partial.is_dir():
        return
    for f in (*partial.glob("mu*.npz"), *partial.glob(".mu*.npz.*.tmp")):
        with suppress(OSError):
            f.unlink()
    with suppress(OSError):
        partial.rmdir()


def _cmd_map(args: argparse.Namespace) -> int:
    from .paper import _formats_arg, _size_arg

    op = get("map")
    formats = _formats_arg(args.image_format)
    size = _size_arg(args.size)
    inputs = inputs_of(args, op)
    grid(inputs)  # checked before the directory is made
    from ..figures._style import _mpl
    from ..figures.adhesion_map import draw

    _mpl()  # matplotlib is there, and the directory, before minutes of computing
    out = pathlib.Path(args.outdir)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise write_failure(f"the map to --outdir {args.outdir!r}", exc) from None

    partial = out / PARTIAL
    inputs.resume_dir = partial
    try:
        op.run(inputs)
    except BaseException:  # the bar is closed: a line of its own
        kept = sorted(partial.glob("*.npz")) if partial.is_dir() else []
        if kept:
            print(
                f"map: {len(kept)} finished curves kept in {partial}/: the same command goes on",
                file=sys.stderr,
            )
        raise
    m = inputs.result
    try:
        paths = draw(m, out, formats, size)
        data = out / "adhesion_map.csv"
        files = [str(p) for p in (*paths, data)]
        table = cells(m, inputs.command_line(), files)
        write(table, "csv", data)
        _clear_partial(partial)
    except OSError as exc:
        raise write_failure(f"the map to --outdir {args.outdir!r}", exc) from None
    fmt = args.format
    if fmt is None and args.output is not None:
        ext = args.output.rsplit(".", 1)[-1].lower()
        fmt = ext if ext in FORMATS and ext != "table" else "table"
    if fmt not in (None, "table") or args.output is not None:  # the data, as the others
        emit(args, inputs.readable if fmt == "table" else table)
        return 0
    print(f"wrote {len(files)} files to {out}/:")
    for f in files:
        print(f"  {f}")
    write(inputs.readable, "table")
    return 0
