"""The operation ``map``: the adhesion map of line contact (:mod:`linecontact.adhesion_map`).

Its records are the map's cells (one per ``mu`` and load), the keys naming their units; the
readable table is the summary per ``mu`` (left as ``inputs.readable``) and the map itself as
``inputs.result``. The figure and the data file are the command line's (``--outdir``), which
also gives the directory where finished curves are kept (``inputs.resume_dir``).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from .._progress import _isatty
from ..errors import ParameterError
from ..output import Table, table_from_result
from ._declare import Entry, Inputs, Operation, Parameter

if TYPE_CHECKING:  # linecontact.adhesion_map imports SciPy's linalg: imported where used
    from ..adhesion_map import AdhesionMap

__all__ = ["OPERATIONS", "cells", "columns", "grid", "summary"]

_DESCRIPTION = (
    "The adhesion map of line contact: over the Maugis parameter and the load above "
    "pull-off, where Hertz, the rigid cylinder, JKR and Maugis-Dugdale give the half-width "
    "of the full Lennard-Jones law within --tol. A stopped run keeps its finished curves: "
    "the same command goes on (docs/cli.md)."
)


def columns() -> dict[str, str]:
    """The columns: the result's field -> the column's name (the name states the unit)."""
    from ..adhesion_map import MODELS

    return {
        "mu": "mu",
        "maugis_parameter": "maugis_parameter",
        "y": "load_above_pulloff_over_abs_pulloff",
        "F": "F_over_w_sqrt_R_over_z0",
        "F_pulloff": "F_pulloff_over_w_sqrt_R_over_z0",
        "y_onset": "onset_load_above_pulloff_over_abs_pulloff",
        "repulsive": "lj_repulsive",
        "half_width_lj": "half_width_lj_over_sqrt_R_z0",
        **{f"half_width_{m}": f"half_width_{m}_over_sqrt_R_z0" for m in MODELS},
        **{f"error_{m}": f"relative_error_{m}" for m in MODELS},
        **{f"agrees_{m}": f"agrees_{m}" for m in MODELS},
        "lj_error_estimate": "lj_error_estimate_over_w_sqrt_R_over_z0",
        "interpolation_error": "lj_interpolation_error_relative",
        "n_states": "lj_states",
    }


def cells(m: AdhesionMap, command: list[str], files: list[str] | None = None) -> Table:
    """The cells of the map ``m`` as records (``files``: the files written, a parameter)."""
    t = table_from_result(
        m,
        parameters=None if files is None else {"files": files},
        command=command,
        title="the adhesion map of line contact (units of the Lennard-Jones law)",
    )
    names = columns()
    cols = {names.get(k, k): v for k, v in t.columns.items()}
    params = {names.get(k, k): v for k, v in t.parameters.items()}
    return Table(cols, params, {}, t.command, t.title)


def _ranges(y: np.ndarray, ok: np.ndarray) -> str:
    """The runs of ``ok`` along ``y`` as ``lo-hi`` ranges (``-`` for none)."""
    runs = []
    i = 0
    while i < ok.size:
        if ok[i]:
            j = i
            while j + 1 < ok.size and ok[j + 1]:
                j += 1
            runs.append(f"{y[i]:.3g}-{y[j]:.3g}" if j > i else f"{y[i]:.3g}")
            i = j + 1
        else:
            i += 1
    return ", ".join(runs) if runs else "-"


def summary(m: AdhesionMap) -> Table:
    """One row per mu: the pull-off, the onset of repulsion, each model's range of y."""
    from ..adhesion_map import MODELS

    mu = np.asarray(m.mu).ravel()
    y = np.asarray(m.y)
    cols: dict[str, np.ndarray] = {
        "mu": mu,
        "maugis_parameter": np.asarray(m.maugis_parameter).ravel(),
        "F_pulloff": np.asarray(m.F_pulloff).ravel(),
        "y_onset": np.asarray(m.y_onset).ravel(),
    }
    for name in MODELS:
        ok = m.agrees(name)
        cols[f"{name}_holds_at_y"] = np.array([_ranges(y, row) for row in ok], dtype=object)
    return Table(
        cols,
        {"tol": m.tol},
        title=f"the adhesion map: loads above pull-off over |F_pulloff| where each model is "
        f"within {100 * m.tol:g} % of the full law",
    )


def grid(args: Inputs) -> tuple[np.ndarray, np.ndarray]:
    """The values of mu and of y the parameters ask for (ValueError naming the flag)."""
    from ..adhesion_map import (
        COARSE,
        MU_MAX,
        MU_MIN,
        N_Y,
        Y_RANGE,
        default_mu,
        default_y,
        domain_mu_max,
    )

    hi = domain_mu_max()
    if not (0.0 < args.tol < 1.0):  # also refuses nan
        raise ParameterError("--tol", f"--tol must be a number in (0, 1), got {args.tol!r}")
    if args.workers is not None and args.workers < 1:
        raise ParameterError(
            "--workers", f"--workers must be an integer >= 1, got {args.workers!r}"
        )
    lo = MU_MIN if args.mu_min is None else args.mu_min
    top = min(MU_MAX, hi) if args.mu_max is None else args.mu_max
    if args.quick and args.mu_min is None:
        lo = COARSE["mu_min"]
    if args.quick and args.mu_max is None:
        top = min(COARSE["mu_max"], hi)
    for flag, v in (("--mu-min", lo), ("--mu-max", top)):
        if not (math.isfinite(v) and 0.0 < v <= hi):
            raise ParameterError(
                flag,
                f"{flag} must be a finite number in (0, {hi:g}] (the domain of the "
                f"Lennard-Jones solver), got {v!r}",
            )
    if not lo < top:
        raise ParameterError("--mu-min", f"--mu-min must be below --mu-max, got {lo!r} >= {top!r}")
    for flag, v in (("--n-mu", args.n_mu), ("--n-y", args.n_y)):
        if args.quick and v is not None:
            raise ParameterError("--quick", f"give either --quick or {flag}, not both")
    n = args.n_mu
    if n is not None and not 2 <= n <= 64:
        raise ParameterError("--n-mu", f"--n-mu must be an integer in [2, 64], got {n!r}")
    if args.n_y is not None and not 2 <= args.n_y <= 1000:
        raise ParameterError("--n-y", f"--n-y must be an integer in [2, 1000], got {args.n_y!r}")
    y_max = args.y_max
    if y_max is not None and not (math.isfinite(y_max) and Y_RANGE[0] < y_max <= 1e3):
        raise ParameterError(
            "--y-max",
            f"--y-max must be a finite number in ({Y_RANGE[0]:g}, 1000] (pull-offs above "
            f"pull-off), got {y_max!r}",
        )
    if args.quick:
        return (
            default_mu(COARSE["n_mu"], lo, top),  # the flags' ends, the coarse count
            default_y(COARSE["n_y"], COARSE["y_max"] if y_max is None else y_max),
        )
    return (
        default_mu(n, lo, top),
        default_y(N_Y if args.n_y is None else args.n_y, Y_RANGE[1] if y_max is None else y_max),
    )


def _compute(args: Inputs) -> Table:
    from ..adhesion_map import adhesion_map

    mu, y = grid(args)
    bar = bool(args.progress) or _isatty()  # the bar of the curves done, resumed ones too
    m = adhesion_map(
        mu,
        y,
        tol=args.tol,
        progress=bar,
        workers=args.workers,
        resume_dir=args.get("resume_dir"),  # the command line's: OUTDIR/adhesion_map.partial
    )
    args.result = m
    args.readable = summary(m)
    return cells(m, args.command_line())


def _parameters() -> tuple[Parameter, ...]:
    from ..adhesion_map import MAUGIS_RANGE, MU_MAX, MU_MIN, Y_RANGE

    return (
        Parameter(
            "outdir",
            "directory to write the figure and adhesion_map.csv into, created if missing; "
            "files of the same names are replaced (default: %(default)s)",
            kind="text",
            metavar="DIR",
            default="figures",
            shell_only=True,
        ),
        Parameter(
            "image_format",
            "comma-separated file formats of the figure, any of png, svg, pdf; PNG at 150 "
            "dpi (default: %(default)s)",
            kind="text",
            metavar="LIST",
            default="png",
            shell_only=True,
        ),
        Parameter(
            "size",
            "width x height of the figure in inches, from 9.5x5.2 to 30x20 (default: %(default)s)",
            kind="text",
            metavar="WxH",
            default="9.6x5.4",
            shell_only=True,
        ),
        Parameter(
            "tol",
            "a model holds where the relative error of its half-width is at most TOL, in "
            "(0, 1) (default: %(default)s)",
            metavar="TOL",
            default=0.05,
        ),
        Parameter(
            "mu_min",
            f"smallest mu = w sqrt(R/z0)/(E z0), > 0 (default: {MU_MIN:.2g}, the Maugis "
            f"parameter {MAUGIS_RANGE[0]:g}; --quick: 0.01)",
            metavar="MU",
        ),
        Parameter(
            "mu_max",
            f"largest mu, in the Lennard-Jones solver's domain (default: {MU_MAX:.3g}, the "
            f"Maugis parameter {MAUGIS_RANGE[1]:g}, or the domain's end; --quick: 1)",
            metavar="MU",
        ),
        Parameter(
            "n_mu",
            "values of mu, geometric, 2 to 64 (default: four per decade of the Maugis "
            "parameter and one, 10 to 17; --quick: 4)",
            kind="integer",
            metavar="N",
        ),
        Parameter(
            "y_max",
            f"largest load above pull-off, in pull-offs, > 0.01 (default: {Y_RANGE[1]:g}; "
            "--quick: 10)",
            metavar="Y",
        ),
        Parameter(
            "n_y",
            "loads, geometric from 0.01 pull-offs above pull-off, 2 to 1000 (default: 81; "
            "--quick: 41)",
            kind="integer",
            metavar="N",
        ),
        Parameter(
            "quick",
            "a coarse grid: 4 values of mu from 0.01 to 1 (or --mu-min, --mu-max), 41 loads "
            "from 0.01 to 10 pull-offs (the map of `linecontact figures`)",
            kind="switch",
            default=False,
        ),
        Parameter(
            "workers",
            "processes computing the curves, >= 1 (1: none; default: the cores)",
            kind="integer",
            metavar="N",
            shell_only=True,
        ),
        Parameter(
            "progress",
            "a progress bar on stderr even where it is not a terminal",
            kind="switch",
            default=False,
            shell_only=True,
        ),
    )


def _operation() -> Operation:
    return Operation(
        name="map",
        summary="the adhesion map of line contact: where Hertz, rigid, JKR, Maugis-Dugdale hold",
        description=_DESCRIPTION,
        examples=(
            "linecontact map --quick",
            "linecontact map --outdir maps --image-format png,pdf --tol 0.02",
        ),
        parameters=_parameters(),
        compute=_compute,
        entries=(
            Entry(
                ("workers", "progress"),
                "processes computing the curves, >= 1 (default: the cores); a progress bar "
                "on stderr also where it is not a terminal (there it is by default)",
            ),
        ),
        format_help="the data: table (the summary per mu), json, jsonl, csv (the cells) "
        "(default: -o's extension, else table)",
        image_formats=True,
    )


OPERATIONS: dict[str, Any] = {"map": _operation()}
