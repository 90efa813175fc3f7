"""Reading measurements: CSV files with the units in the header, into SI arrays.

The reader of ``linecontact fit-adhesion --data``, ``linecontact fit-friction --data`` and
``linecontact fit-bent-wire --data`` (a profile, ``x_nm,y_nm``), for Python users:
:func:`read_measurements` reads the same files the command line reads and returns SI
arrays (m, N/m) ready for :func:`linecontact.inverse.fit_pull_off`,
:func:`linecontact.inverse.shear_strength_from_friction` and
:func:`linecontact.bent_wire.fit_bent_wire`.

The format: lines starting with ``#`` are comments (and empty lines are skipped); then a
header and rows of numbers. The header names each column with its unit, ``<quantity>_<unit>``
(``radius_nm``, ``pull_off_force_nN_per_um``); a quantity's standard uncertainty is a column
``sd`` or ``sd_<unit>`` right after its value column, or ``<quantity>_sd_<unit>`` anywhere
(without a unit: that of its value column). Every column is used or refused: an unknown
column, a column twice, a unit of the wrong kind, a field that is not a finite number and a
negative uncertainty raise a ``ValueError`` naming the file, the row (the header's line
counts, comment lines included) and the column. Units: lengths ``m``, ``nm``, ``um``;
forces per length ``N_per_m``, ``nN_per_um``, ``uN_per_m``; total forces of the whole fibre
``N``, ``nN`` (divided by the fibre's ``length``).
"""

from __future__ import annotations

import csv
import math
import os
from collections.abc import Mapping
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from .errors import ParameterError

__all__ = ["KINDS", "per_length", "read_columns", "read_measurements"]

#: the kinds of measurement file: kind -> {quantity: (kind of unit, required, with_sd)}
KINDS: dict[str, dict[str, tuple[str, bool, bool]]] = {
    "pull-off": {
        "radius": ("length", True, False),
        "pull_off_force": ("force", True, True),
    },
    "friction": {
        "normal_load": ("force", True, False),
        "friction_force": ("force", True, True),
    },
    "profile": {
        "x": ("length", True, False),
        "y": ("length", True, False),
    },
}

#: kind of quantity -> (unit suffix -> factor to SI); "N" and "nN" are totals over the length
_UNITS: dict[str, dict[str, float]] = {
    "length": {"m": 1.0, "nm": 1e-9, "um": 1e-6},
    "force": {"N_per_m": 1.0, "nN_per_um": 1e-3, "uN_per_m": 1e-6, "N": 1.0, "nN": 1e-9},
}
_TOTAL = ("N", "nN")


def _accepted(wanted: Mapping[str, tuple[str, bool, bool]]) -> str:
    """The accepted column names of ``wanted``, for an error message."""
    cols = []
    for prefix, (_, _, with_sd) in wanted.items():
        cols.append(f"{prefix}_<unit>")
        if with_sd:
            cols[-1] += (
                f" with its optional uncertainty: sd or sd_<unit> right after it, or "
                f"{prefix}_sd_<unit> anywhere"
            )
    kinds = dict.fromkeys(kind for kind, _, _ in wanted.values())
    units = "; ".join(f"{', '.join(_UNITS[k])} for a {k}" for k in kinds)
    return f"{', '.join(cols)} (<unit>: {units})"


def read_columns(
    path: str | os.PathLike[str],
    wanted: Mapping[str, tuple[str, bool, bool]],
    length: float | None = None,
    *,
    source: str | None = None,
    length_name: str = "length",
) -> tuple[dict[str, NDArray], int]:
    """Columns of a CSV file, in SI units per unit length; every column used or refused.

    Parameters
    ----------
    path : str or path-like
        The CSV file: ``#`` comment lines, a header, then rows of numbers.
    wanted : dict
        Maps a quantity's name prefix (``"radius"``) to ``(kind, required, with_sd)``:
        ``kind`` a key of the unit table, whether the file must have the column, and whether
        the caller uses the quantity's standard uncertainty.
    length : float or None
        The fibre's length [m], to turn total forces (units ``N``, ``nN``) into forces per
        length.
    source : str, optional
        How the messages name the file (default: the path, quoted); the command line passes
        ``--data '<path>'``.
    length_name : str
        How the messages name ``length`` (the command line: ``--length``).

    Returns
    -------
    columns : dict
        ``{prefix: array}`` for each quantity found, ``{prefix + "_sd": array}`` for each
        uncertainty found, and ``"_line"``: each row's line number in the file.
    n : int
        The number of rows.

    Raises
    ------
    ValueError
        For a column the reader does not use (it never drops one), naming it and the
        accepted names: a quantity's value is ``<prefix>_<unit>``; its uncertainty, where
        ``with_sd``, is ``sd`` or ``sd_<unit>`` right after the value column or
        ``<prefix>_sd_<unit>`` anywhere (no unit: that of the value column); one of each
        per quantity. Also for a missing column, a unit of the wrong kind, a field that is
        not a finite number and a negative uncertainty; the message names the file, the row
        (counting the header as row 1, comment lines included) and the column.
    """
    label = repr(os.fspath(path)) if source is None else source
    try:
        with open(path, newline="", encoding="utf-8-sig") as fh:  # a BOM is dropped
            lines = list(enumerate(fh.read().splitlines(), start=1))
    except OSError as exc:
        raise ValueError(f"{label}: cannot read it ({exc.strerror or exc})") from None
    except UnicodeDecodeError as exc:
        raise ValueError(
            f"{label}: not UTF-8 text (byte {exc.start}): save the file as UTF-8 CSV"
        ) from None
    body = [(n, line) for n, line in lines if line.strip() and not line.lstrip().startswith("#")]
    if not body:
        raise ValueError(f"{label}: no header and no rows (only comments or empty)")
    rows = list(csv.reader(line for _, line in body))
    header = [h.strip() for h in rows[0]]
    if len(rows) < 2:
        raise ValueError(f"{label}: a header and no data rows")
    accepted = _accepted(wanted)
    with_sd = [p for p, (_, _, s) in wanted.items() if s]
    may_carry = " or ".join(f"{p}_<unit>" for p in with_sd) or "no column of this file"

    def unknown(j: int) -> ValueError:
        known = f"column {header[j]!r} is not one the reader knows"
        what = known if header[j] else f"column {j + 1} has no name"
        return ValueError(f"{label}: {what}; the accepted columns are {accepted}")

    def not_read(j: int, prefix: str) -> ValueError:
        return ValueError(
            f"{label}, column {header[j]!r}: the reader does not use an uncertainty "
            f"of the {prefix.replace('_', ' ')} (it is taken as exact); an uncertainty column "
            f"may qualify only {may_carry}"
        )

    # each column is a value ("value", prefix, unit), an uncertainty ("sd", prefix, unit;
    # unit "" for that of the value column) or unknown ("?", "", "")
    role: list[tuple[str, str, str]] = []
    for j, col in enumerate(header):
        if col == "sd" or col.startswith("sd_"):  # the uncertainty of the column before it
            if j == 0:
                raise ValueError(
                    f"{label}, column {col!r}: an sd column qualifies the value column "
                    f"right before it, and it is the first column; an sd column may follow "
                    f"only {may_carry}"
                )
            what, prefix, _ = role[j - 1]
            if what == "?":
                raise unknown(j - 1)
            if what == "sd":
                raise ValueError(
                    f"{label}, column {col!r}: an sd column qualifies the value column "
                    f"right before it, and {header[j - 1]!r} is an uncertainty; an sd column "
                    f"may follow only {may_carry}"
                )
            if prefix not in with_sd:
                raise not_read(j, prefix)
            role.append(("sd", prefix, col[3:]))
            continue
        hits = [p for p in wanted if col == p or col.startswith(p + "_")]
        if not hits:
            role.append(("?", "", ""))
            continue
        prefix = max(hits, key=len)
        rest = col[len(prefix) + 1 :]
        if rest == "sd" or rest.startswith("sd_"):
            if prefix not in with_sd:
                raise not_read(j, prefix)
            role.append(("sd", prefix, rest[3:]))
        elif not rest:
            raise ValueError(
                f"{label}, column {col!r}: no unit: name it {prefix}_<unit> with <unit> "
                f"one of {', '.join(_UNITS[wanted[prefix][0]])}"
            )
        else:
            role.append(("value", prefix, rest))

    found: dict[tuple[str, str], list[int]] = {}
    for j, (what, prefix, _) in enumerate(role):
        if what != "?":
            found.setdefault((what, prefix), []).append(j)
    for (what, prefix), js in found.items():
        if len(js) > 1:
            kind = "uncertainty columns" if what == "sd" else "columns"
            raise ValueError(
                f"{label}: {len(js)} {kind} for {prefix.replace('_', ' ')} "
                f"({', '.join(header[j] for j in js)}): keep one"
            )
    for prefix, (kind, required, _) in wanted.items():
        if required and ("value", prefix) not in found:
            units = ", ".join(f"{prefix}_{u}" for u in _UNITS[kind])
            raise ValueError(
                f"{label}: no column for {prefix.replace('_', ' ')}: expected one "
                f"of {units}; the header is {','.join(header)!r}"
            )
        if ("sd", prefix) in found and ("value", prefix) not in found:
            raise ValueError(
                f"{label}, column {header[found['sd', prefix][0]]!r}: an uncertainty "
                f"and no column for the {prefix.replace('_', ' ')} itself"
            )
    if any(what == "?" for what, _, _ in role):
        raise unknown(next(j for j, (what, _, _) in enumerate(role) if what == "?"))

    for i, row in enumerate(rows[1:]):
        if len(row) != len(header):
            raise ValueError(
                f"{label}, row {body[i + 1][0]}: {len(row)} fields, the header has {len(header)}"
            )
    out: dict[str, NDArray] = {}
    for j, (what, prefix, unit) in enumerate(role):
        col, kind = header[j], wanted[prefix][0]
        if what == "sd" and not unit:
            unit = role[found["value", prefix][0]][2]  # the unit of its value column
        if unit not in _UNITS[kind]:
            other = [k for k in _UNITS if k != kind and unit in _UNITS[k]]
            raise ValueError(
                f"{label}, column {col!r}: the unit {unit!r} is "
                + (f"one of a {other[0]}" if other else "not one the reader knows")
                + f"; the {prefix.replace('_', ' ')}"
                + ("'s uncertainty" if what == "sd" else "")
                + f" takes {', '.join(_UNITS[kind])}"
            )
        if unit in _TOTAL and length is None:
            raise ValueError(
                f"{label}, column {col!r}: forces in {unit} are totals: give the "
                f"fibre's {length_name} [m] to turn them into forces per length"
            )
        per = length if (unit in _TOTAL and length is not None) else 1.0
        factor = _UNITS[kind][unit] / per
        vals = np.empty(len(rows) - 1)
        for i, row in enumerate(rows[1:]):
            line_no = body[i + 1][0]
            try:
                if "_" in row[j]:  # float() reads "2_0" as 20: not a plain number
                    raise ValueError(row[j])
                v = float(row[j])
            except ValueError:
                raise ValueError(
                    f"{label}, row {line_no}, column {col!r}: {row[j]!r} is not a number"
                ) from None
            if not math.isfinite(v):
                raise ValueError(
                    f"{label}, row {line_no}, column {col!r}: {row[j]!r} is not finite"
                )
            if what == "sd" and v < 0:
                raise ValueError(
                    f"{label}, row {line_no}, column {col!r}: a standard uncertainty "
                    f"must be >= 0, got {v!r}"
                )
            vals[i] = v * factor
        out[prefix + "_sd" if what == "sd" else prefix] = vals
    out["_line"] = np.array([body[i + 1][0] for i in range(len(rows) - 1)])
    return out, len(rows) - 1


def read_measurements(
    path: str | os.PathLike[str],
    kind: Literal["pull-off", "friction", "profile"] = "pull-off",
    *,
    length: float | None = None,
    source: str | None = None,
    length_name: str = "length",
) -> dict[str, NDArray]:
    r"""Measurements from a CSV file with the units in its header, in SI units.

    Parameters
    ----------
    path : str or path-like
        The CSV file (the format: the module's docstring, ``docs/cli.md``).
    kind : {"pull-off", "friction"}
        ``"pull-off"``: columns ``radius_<unit>`` and ``pull_off_force_<unit>`` (negative,
        tensile) with an optional uncertainty of the force; ``"friction"``:
        ``normal_load_<unit>`` and ``friction_force_<unit>`` (> 0) with an optional
        uncertainty of the friction force.
    length : float, optional
        The fibre's length [m], for forces given as totals (units ``N``, ``nN``).
    source : str, optional
        How error messages name the file (default: the path, quoted).
    length_name : str
        How error messages name ``length``.

    Returns
    -------
    dict of ndarray
        One 1-D array per quantity in SI units (``"radius"`` [m], ``"pull_off_force"``
        [N/m]; or ``"normal_load"``, ``"friction_force"`` [N/m]; or a bent wire's profile,
        ``"x"``, ``"y"`` [m], in the file's order), ``"pull_off_force_sd"`` or
        ``"friction_force_sd"`` [N/m] where the file has the uncertainty (absent otherwise:
        :func:`linecontact.inverse.fit_pull_off` then weighs the points equally), and
        ``"line"``: each row's line number in the file.

    Raises
    ------
    ValueError
        For a file that cannot be read or a column the reader does not use (see
        :func:`read_columns`), a radius not > 0, a pull-off force not < 0, a friction force
        not > 0; the message names the file (``source``) and the row.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> d = pathlib.Path(tempfile.mkdtemp())
    >>> _ = (d / "p.csv").write_text("# AFM\nradius_nm,pull_off_force_nN_per_um,sd\n"
    ...                            "20,-40,2\n40,-60,3\n")
    >>> m = read_measurements(d / "p.csv")
    >>> m["radius"].tolist(), m["pull_off_force"].tolist(), m["pull_off_force_sd"].tolist()
    ([2e-08, 4e-08], [-0.04, -0.06], [0.002, 0.003])
    >>> m["line"].tolist()
    [3, 4]
    """
    if kind not in KINDS:
        raise ValueError(f"kind must be one of {', '.join(map(repr, KINDS))}, got {kind!r}")
    if length is not None and not (
        isinstance(length, (int, float, np.integer, np.floating))
        and not isinstance(length, bool)
        and math.isfinite(length)
        and length > 0
    ):
        raise ParameterError(
            length_name, f"{length_name} must be a finite number > 0, got {length!r}"
        )
    label = repr(os.fspath(path)) if source is None else source
    cols, _ = read_columns(path, KINDS[kind], length, source=label, length_name=length_name)
    lines = cols.pop("_line")
    if kind == "pull-off":
        R, F = cols["radius"], cols["pull_off_force"]
        if np.any(R <= 0):
            i = int(np.flatnonzero(R <= 0)[0])
            raise ValueError(f"{label}, row {int(lines[i])}: the radius is not > 0")
        if np.any(F >= 0):
            i = int(np.flatnonzero(F >= 0)[0])
            raise ValueError(
                f"{label}, row {int(lines[i])}: the pull-off force is "
                f"{float(F[i])!r} N/m: pull-off forces are tensile, negative"
            )
    elif kind == "friction":
        f = cols["friction_force"]
        if np.any(f <= 0):
            i = int(np.flatnonzero(f <= 0)[0])
            raise ValueError(f"{label}, row {int(lines[i])}: the friction force is not > 0")
    cols["line"] = lines
    return cols


def per_length(total: float, length: float, *, length_name: str = "length") -> float:
    """A force of the whole fibre [N] as a force per unit length [N/m].

    Parameters
    ----------
    total : float
        The force on the whole fibre [N] (or its standard uncertainty).
    length : float
        The fibre's length [m], ``> 0``.
    length_name : str
        How the message names ``length`` (the command line: ``--length``).

    Examples
    --------
    >>> per_length(-3e-6, 2e-6)
    -1.5
    """
    if not (math.isfinite(length) and length > 0):
        raise ParameterError(
            length_name, f"{length_name} must be a finite length > 0 [m], got {length!r}"
        )
    return total / length
