"""The subcommand ``sweep``: a subcommand over every combination of its flags' values."""

from __future__ import annotations

import argparse
import sys
import time
from typing import Any

from ._options import add_command, command_line

__all__ = ["register"]

#: The options of the sweep itself (the rest are the subcommand's): flag -> takes a value.
_OWN = {
    "-o": True,
    "--output": True,
    "--workers": True,
    "--scheduler": True,
    "--chunk-points": True,
    "--progress": False,
    "--no-progress": False,
    "--overwrite": False,
    "--quiet": False,
}


def _integer(flag: str, text: str) -> int:
    try:
        value = float(text)
    except ValueError:
        value = float("nan")
    if not (value == value and value.is_integer() and value >= 1):
        raise ValueError(f"{flag} must be an integer >= 1, got {text!r}")
    return int(value)


def _own(args: argparse.Namespace, words: list[str]) -> list[str]:
    """Take the sweep's own options out of ``words`` (into ``args``); the subcommand's rest."""
    rest: list[str] = []
    i = 0
    while i < len(words):
        flag, eq, value = words[i].partition("=")
        if flag not in _OWN:
            rest.append(words[i])
            i += 1
            continue
        if _OWN[flag] and not eq:
            if i + 1 >= len(words):
                raise ValueError(f"{flag} needs a value")
            value = words[i + 1]
            i += 1
        i += 1
        if flag in ("-o", "--output"):
            args.output = value
        elif flag == "--workers":
            args.workers = _integer("--workers", value)
        elif flag == "--chunk-points":
            args.chunk_points = _integer("--chunk-points", value)
        elif flag == "--scheduler":
            args.scheduler = value
        elif flag == "--progress":
            args.progress = True
        elif flag == "--no-progress":
            args.progress = False
        elif flag == "--overwrite":
            args.overwrite = True
        elif flag == "--quiet":
            args.quiet = True
    return rest


def _cmd_sweep(args: argparse.Namespace) -> int:
    import os

    from ..sweeps import _engine
    from ..sweeps._plan import plan

    words = _own(args, list(args.words))
    if any(w in ("-h", "--help") for w in words):
        raise ValueError(
            f"the flags of a sweep are those of its subcommand: linecontact {args.sweep_command} "
            "--help lists them; linecontact sweep --help the sweep's own"
        )
    if args.output is None:
        raise ValueError("a sweep writes its labelled arrays to -o OUT (.zarr or .nc): give -o")
    argv = command_line(args)
    p = plan(args.sweep_command, words, argv, args.chunk_points)
    _engine.need()
    workers = args.workers if args.workers is not None else (os.cpu_count() or 1)
    start = time.perf_counter()
    ds = _engine.run(
        p,
        args.output,
        workers=workers,
        scheduler=args.scheduler,
        progress=args.progress,
        overwrite=args.overwrite,
    )
    if not args.quiet:
        reason = ds["reason"]
        if "record" in reason.dims:
            reason = reason.isel(record=0)
        missing = int((reason != "").sum())
        dims = " x ".join(f"{d} ({n})" for d, n in ds.sizes.items() if d != "record")
        over = f"over {dims}" if dims else "with nothing swept (every flag one value)"
        print(
            f"wrote {args.output}: {args.sweep_command} {over}, {p.size} points "
            f"({missing} without a state: see the variables state and reason) in "
            f"{time.perf_counter() - start:.3g} s",
            file=sys.stderr,
        )
    return 0


def register(sub: Any) -> None:
    """Add ``sweep`` to the subparsers ``sub``."""
    from ..sweeps._plan import SWEEPABLE

    sw = add_command(
        sub,
        "sweep",
        "run a subcommand over every combination of its flags' values: labelled arrays out",
        "Any flag of the subcommand takes several values or a range START:STOP:NUM[:log]; "
        "the points are the outer product of the swept flags, written as an xarray dataset "
        "(Zarr .zarr or netCDF .nc: one dimension per swept flag, one variable per record "
        "key). Blocks are kept as they finish: the same command again resumes. Subcommands: "
        f"{', '.join(SWEEPABLE)}. Needs pip install 'linecontact[sweep]' (docs/sweeps.md).",
        [
            "linecontact sweep pulloff --radius 10e-9:200e-9:40:log --modulus 1.2e11 "
            "--work-of-adhesion 0.1 0.3 1 --z0 3e-10 -o pulloff.zarr",
            "linecontact sweep push --cylinder-material ZnO --substrate-material SiO2 "
            "--radius 50e-9 --work-of-adhesion 0.3 --z0 3e-10 --tau0 1e6:1e8:5:log "
            "--H-over-R 0:2:21 --load 0 -o push.nc",
        ],
    )
    sw.add_argument("sweep_command", metavar="COMMAND", help="the subcommand to sweep")
    sw.add_argument(
        "words", nargs=argparse.REMAINDER, metavar="FLAGS", help="its flags, several values each"
    )
    g = sw.add_argument_group("the sweep's own options (anywhere among the flags)")
    g.add_argument("-o", "--output", metavar="OUT", help="the store: OUT.zarr or OUT.nc (required)")
    g.add_argument("--workers", type=int, metavar="N", help="local processes (default: the cores)")
    g.add_argument("--scheduler", metavar="ADDRESS", help="a dask.distributed scheduler instead")
    g.add_argument("--chunk-points", type=int, metavar="N", help="the most points of a block")
    g.add_argument(
        "--progress",
        action="store_true",
        default=None,
        help="a progress bar on stderr even when not a terminal",
    )
    g.add_argument("--no-progress", dest="progress", action="store_false", help="no progress bar")
    g.add_argument(
        "--overwrite", action="store_true", help="replace a store of another sweep at OUT"
    )
    g.add_argument("--quiet", action="store_true", help="no model notes, no summary")
    sw.set_defaults(func=_cmd_sweep)
