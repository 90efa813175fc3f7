"""The columnar output layer: results to JSON, JSON Lines, CSV or a table, with provenance.

Every subcommand of the command line writes through this module, and so can a script. A
:class:`Table` holds the per-point quantities as 1-D arrays (:meth:`Result.columns
<linecontact.results.Result.columns>`), the inputs that are the same for every point once, in
``parameters``, and the unit of every quantity in ``units``. The writers format whole columns
at a time; no Python dict is built per point.

The provenance block (the output contract of the command line)::

    {"linecontact": {"version": "X.Y.Z"},
     "command": ["linecontact", "normal", ...],
     "parameters": {...},
     "units": {...},
     "results": [{...}, ...]}

- ``json``: that object (compact unless an indent is given);
- ``jsonl``: the block without ``results`` on the first line, then one record per line;
- ``csv``: the block as commented lines (``# linecontact: {...}``, ``# command: [...]``,
  ``# parameters: {...}``, ``# units: {...}``, each a JSON value), then a header row and one
  row per point; booleans as ``true``/``false``, missing values empty;
- ``table``: a human-readable table, numbers to six significant digits; a value below
  ``1e-12`` of its scale (the largest magnitude in its column, or a scale the caller gives,
  such as the size of the terms whose difference a load is) is round-off and prints as ``0``.

Missing values (NaN, a point without a state) are ``null`` in JSON; the files keep full
precision (the shortest ``repr`` that round-trips). Files are written atomically: to a
temporary file in the target directory, then renamed, so a failure leaves no partial file.
"""

from __future__ import annotations

import json
import os
import sys
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import IO, Any

import numpy as np
from numpy.typing import NDArray

from ._files import atomic_file
from ._version import __version__
from .results import Result

__all__ = ["FORMATS", "Table", "render", "table_from_result", "unit_of", "write"]

#: The output formats.
FORMATS = ("table", "json", "jsonl", "csv")

#: Below this fraction of its scale a value prints as 0 in a table (round-off).
ROUND_OFF = 1e-12


@dataclass(frozen=True)
class Table:
    """Per-point columns with their provenance.

    Attributes
    ----------
    columns : dict of str to ndarray
        1-D arrays of one length (floats, integers, booleans or strings), in output order.
    parameters : dict
        Inputs that are the same for every point (JSON-ready scalars or lists).
    units : dict of str to str
        Units that the names do not state (:func:`unit_of` gives the others: ``"m"`` for
        ``a_m``, ``"N/m"`` for ``F_N_per_m``, ``"1"`` for a nondimensional group).
    command : list of str
        The command line that produced the table (``["linecontact", "normal", ...]``).
    title : str
        One line describing the table (the first line of the ``table`` format).
    scales : dict of str to ndarray
        Optional per-point scales for the round-off rule of the ``table`` format.
    show : tuple of str
        The columns of the ``table`` format (all when empty). A ``reason`` column is shown
        as notes under the table, one per point that has one.
    left : tuple of str
        Text columns aligned on the left in the ``table`` format (the others on the right).
    """

    columns: dict[str, NDArray[Any]]
    parameters: dict[str, Any] = field(default_factory=dict)
    units: dict[str, str] = field(default_factory=dict)
    command: list[str] = field(default_factory=list)
    title: str = ""
    scales: dict[str, NDArray[Any]] = field(default_factory=dict)
    show: tuple[str, ...] = ()
    left: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        sizes = {k: np.shape(v) for k, v in self.columns.items()}
        lengths = {s[0] for s in sizes.values() if len(s) == 1}
        if any(len(s) != 1 for s in sizes.values()) or len(lengths) > 1:
            raise ValueError(f"columns must be 1-D arrays of one length, got shapes {sizes}")

    @property
    def size(self) -> int:
        """The number of points (rows)."""
        return len(next(iter(self.columns.values()))) if self.columns else 0

    def provenance(self) -> dict[str, Any]:
        """The block that precedes the results in every format.

        ``units`` has an entry for every number among the parameters and the columns: the
        unit given, or the one its name states (:func:`unit_of`).
        """
        units = {}
        for k, v in self.parameters.items():
            if isinstance(v, (int, float, np.number)) and not isinstance(v, (bool, np.bool_)):
                units[k] = self.units.get(k) or unit_of(k)
        for k, v in self.columns.items():
            # numbers, and lists of numbers whose unit is given or stated by the name
            if v.dtype.kind in "fiu" or (
                v.dtype.kind == "O" and (k in self.units or unit_of(k) != "1")
            ):
                units[k] = self.units.get(k) or unit_of(k)
        return {
            "linecontact": {"version": __version__},
            "command": list(self.command),
            "parameters": _jsonable(self.parameters),
            "units": units,
        }


#: Unit suffixes of the SI names, longest first (``F_N_per_m``, ``M_total_N_m``, ``a_m``).
UNIT_SUFFIXES = (
    ("_J_per_m2", "J/m^2"),
    ("_J_per_m", "J/m"),
    ("_N_per_m", "N/m"),
    ("_N_m", "N m"),
    ("_Pa", "Pa"),
    ("_N", "N"),
    ("_J", "J"),
    ("_m", "m"),
)


def unit_of(name: str) -> str:
    """The unit a quantity's name states: an SI suffix, else ``"1"`` (a nondimensional group).

    >>> unit_of("F_N_per_m"), unit_of("M_total_N_m"), unit_of("a_m"), unit_of("a_over_R")
    ('N/m', 'N m', 'm', '1')
    """
    for suffix, unit in UNIT_SUFFIXES:
        if name.endswith(suffix):
            return unit
    return "1"


def table_from_result(
    result: Result,
    *,
    columns: Mapping[str, Any] | None = None,
    drop: Iterable[str] = (),
    parameters: Mapping[str, Any] | None = None,
    units: Mapping[str, str] | None = None,
    command: Sequence[str] = (),
    title: str = "",
    scales: Mapping[str, Any] | None = None,
    show: Sequence[str] = (),
) -> Table:
    """A :class:`Table` of ``result``: its inputs that are the same everywhere move to parameters.

    Parameters
    ----------
    result : Result
        Any result of the library.
    columns : mapping, optional
        Extra per-point columns (arrays broadcasting to the points), appended in order.
    drop : iterable of str
        Columns of ``result`` to leave out.
    parameters : mapping, optional
        Further parameters (given before the ones taken from ``result``).
    units : mapping, optional
        The unit of each column and parameter.
    command, title, scales, show
        As in :class:`Table`.
    """
    cols = result.columns()
    n = result.size
    params: dict[str, Any] = dict(parameters or {})
    dropped = set(drop)
    out: dict[str, NDArray[Any]] = {}
    for k, v in cols.items():
        if k in dropped:
            continue
        if k in result.inputs and n > 0 and _constant(v):
            params.setdefault(k, v[0].item() if isinstance(v[0], np.generic) else v[0])
            continue
        out[k] = v
    for k, v in (columns or {}).items():
        out[k] = np.broadcast_to(np.asarray(v), result.shape).reshape(n)
    sc = {
        k: np.broadcast_to(np.asarray(v, float), result.shape).reshape(n)
        for k, v in (scales or {}).items()
    }
    return Table(out, params, dict(units or {}), list(command), title, sc, tuple(show))


def _constant(v: NDArray[Any]) -> bool:
    if v.dtype.kind == "f":
        return bool(np.all((v == v[0]) | (np.isnan(v) & np.isnan(v[0]))))
    return bool(np.all(v == v[0]))


def _jsonable(value: Any) -> Any:
    """Numpy scalars and arrays as Python objects; non-finite floats as None."""
    if isinstance(value, Mapping):
        return {str(k): _jsonable(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_jsonable(v) for v in value]
    if isinstance(value, np.ndarray):
        return _jsonable(value.tolist())
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, float) and not np.isfinite(value):
        return None
    return value


# --------------------------------------------------------------------------------------------
# column encoders: one list of strings per column, built with whole-array operations


def _encode(v: NDArray[Any], missing: str, text: Any, as_list: Any) -> list[str]:
    """One column as strings, for the JSON and the CSV writers.

    Booleans ``true``/``false``, numbers in full precision (the shortest ``repr`` that
    round-trips), non-finite numbers as ``missing``, strings and None by ``text``, lists
    (a column of per-point lists, such as the zones of a history) by ``as_list``.
    """
    kind = v.dtype.kind
    if kind == "b":
        return np.where(v, "true", "false").tolist()
    if kind in "iu":
        return list(map(repr, v.tolist()))
    if kind == "f":
        vals = v.astype(float, copy=False)
        out = list(map(float.__repr__, vals.tolist()))
        for i in np.flatnonzero(~np.isfinite(vals)):
            out[i] = missing
        return out
    vals = v.tolist()
    if any(isinstance(x, (list, tuple)) for x in vals):
        return [
            as_list(json.dumps(_jsonable(x))) if isinstance(x, (list, tuple)) else text(x)
            for x in vals
        ]
    return _by_value(vals, text)


def _json_column(v: NDArray[Any]) -> list[str]:
    # a list is written as a JSON array
    return _encode(v, "null", lambda x: "null" if x is None else json.dumps(str(x)), str)


def _csv_column(v: NDArray[Any]) -> list[str]:
    # a list is written as its JSON text, quoted
    return _encode(v, "", lambda x: "" if x is None else _csv_quote(str(x)), _csv_quote)


def _by_value(vals: list[Any], encode: Any) -> list[str]:
    """Strings (and None) encoded once per distinct value: such columns have few of them."""
    cache = {x: encode(x) for x in set(vals)}
    return [cache[x] for x in vals]


def _csv_quote(s: str) -> str:
    if any(c in s for c in ',"\n\r'):
        return '"' + s.replace('"', '""') + '"'
    return s


def _records_json(table: Table, indent: int | None, level: int) -> list[str]:
    """One JSON object per row, as strings, indented for ``level`` when ``indent`` is set."""
    keys = list(table.columns)
    if not keys:
        return ["{}"] * table.size
    enc = [_json_column(v) for v in table.columns.values()]
    names = [json.dumps(k) for k in keys]
    if indent is None:
        parts = [("{" if i == 0 else ",") + f"{n}:" for i, n in enumerate(names)]
        template = "".join(p + "%s" for p in parts) + "}"
    else:
        pad = " " * (indent * (level + 1))
        close = " " * (indent * level)
        template = "{\n" + ",\n".join(f"{pad}{n}: %s" for n in names) + f"\n{close}}}"
    return [template % row for row in zip(*enc, strict=True)]


def _dumps(obj: Any, indent: int | None) -> str:
    if indent is None:
        return json.dumps(obj, separators=(",", ":"), allow_nan=False)
    return json.dumps(obj, indent=indent, allow_nan=False)


def render(table: Table, fmt: str, *, indent: int | None = None) -> str:
    """The text of ``table`` in format ``fmt`` (one of :data:`FORMATS`), ending in a newline.

    Parameters
    ----------
    table : Table
    fmt : {"table", "json", "jsonl", "csv"}
    indent : int, optional
        Indentation of the ``json`` format (compact when None).
    """
    return "".join(_chunks(table, fmt, indent))


def _chunks(table: Table, fmt: str, indent: int | None) -> Iterable[str]:
    if fmt not in FORMATS:
        raise ValueError(f"format must be one of {', '.join(FORMATS)}, got {fmt!r}")
    if indent is not None and (
        isinstance(indent, bool) or not isinstance(indent, int) or not 0 <= indent <= 16
    ):
        raise ValueError(f"indent must be an integer in [0, 16], got {indent!r}")
    head = table.provenance()
    if fmt == "json":
        body = _dumps(head, indent)
        if indent is None:
            recs = _records_json(table, None, 0)
            yield body[:-1] + ',"results":[' + ",".join(recs) + "]}\n"
        else:
            # the provenance object reopened (its closing "\n}" cut) to append the results
            pad = " " * indent
            recs = _records_json(table, indent, 2)
            res = "[]"
            if recs:
                res = "[\n" + ",\n".join(pad * 2 + r for r in recs) + "\n" + pad + "]"
            yield body[:-2] + ",\n" + pad + '"results": ' + res + "\n}\n"
    elif fmt == "jsonl":
        yield _dumps(head, None) + "\n"
        recs = _records_json(table, None, 0)
        if recs:
            yield "\n".join(recs) + "\n"
    elif fmt == "csv":
        for k, v in head.items():
            yield f"# {k}: {_dumps(v, None)}\n"
        yield ",".join(_csv_quote(k) for k in table.columns) + "\n"
        enc = [_csv_column(v) for v in table.columns.values()]
        if enc and table.size:
            yield "\n".join(",".join(row) for row in zip(*enc, strict=True)) + "\n"
    else:
        yield _format_table(table)


# --------------------------------------------------------------------------------------------
# the human-readable table


def _table_column(v: NDArray[Any], scale: NDArray[Any] | None) -> list[str]:
    kind = v.dtype.kind
    if kind == "b":
        return np.where(v, "yes", "no").tolist()
    if kind in "iu":
        return list(map(str, v.tolist()))
    if kind == "f":
        vals = v.astype(float, copy=False)
        fin = np.isfinite(vals)
        big = float(np.max(np.abs(vals[fin]))) if fin.any() else 0.0
        ref = np.full(vals.shape, big) if scale is None else np.abs(scale)
        with np.errstate(invalid="ignore"):
            zero = fin & (np.abs(vals) <= ROUND_OFF * ref)
        text = [f"{x:.6g}" for x in vals.tolist()]
        for i in np.flatnonzero(zero):
            text[i] = "0"
        for i in np.flatnonzero(np.isnan(vals)):
            text[i] = "-"
        return text
    return ["-" if x is None else str(x) for x in v.tolist()]


#: The width the parameter lines of a table are wrapped to (a longer item stays whole).
TABLE_WIDTH = 100


def _comment_lines(items: list[str]) -> list[str]:
    """``items`` joined by ``, `` into ``# `` lines of at most :data:`TABLE_WIDTH`."""
    lines: list[str] = []
    line = ""
    for item in items:
        if line and len(line) + len(item) + 3 > TABLE_WIDTH:  # "# " before, "," after
            lines.append(f"# {line},")
            line = item
        else:
            line = f"{line}, {item}" if line else item
    lines.append(f"# {line}")
    return lines


def _left(cells: list[str]) -> list[str]:
    """``cells`` padded on the right to one width (so that they stand aligned on the left)."""
    width = max((len(s) for s in cells), default=0)
    return [s.ljust(width) for s in cells]


def _format_table(table: Table) -> str:
    lines = []
    units = table.provenance()["units"]
    if table.title:
        lines.append(f"# {table.title}")
    if table.parameters:
        items = []
        for k, v in table.parameters.items():
            if k.endswith("_source") and f"{k[: -len('_source')]}_material" in table.parameters:
                continue  # a preset's citation: the material's name says it (JSON/CSV keep it)
            unit = units.get(k)
            txt = f"{v:.6g}" if isinstance(v, float) else str(v)
            items.append(f"{k} = {txt}" + (f" {unit}" if unit and unit != "1" else ""))
        lines.extend(_comment_lines(items))
    keys = [k for k in (table.show or tuple(table.columns)) if k != "reason"]
    if keys:
        cols = [_table_column(table.columns[k], table.scales.get(k)) for k in keys]
        cols = [_left(c) if k in table.left else c for k, c in zip(keys, cols, strict=True)]
        heads = [k if units.get(k) in (None, "1") else f"{k} [{units[k]}]" for k in keys]
        widths = [
            max(len(h), *(len(s) for s in c)) if c else len(h)
            for h, c in zip(heads, cols, strict=True)
        ]
        lines.append("  ".join(h.rjust(w) for h, w in zip(heads, widths, strict=True)))
        for row in zip(*cols, strict=True):
            lines.append("  ".join(s.rjust(w) for s, w in zip(row, widths, strict=True)))
    if "reason" in table.columns:
        for i, why in enumerate(table.columns["reason"].tolist()):
            if why:
                lines.append(f"# point {i + 1}: {why}")
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------------------------
# writing


def write(
    table: Table,
    fmt: str,
    path: str | os.PathLike[str] | None = None,
    *,
    indent: int | None = None,
    stream: IO[str] | None = None,
    name: str = "output",
) -> None:
    """Write ``table`` in format ``fmt`` to the file ``path``, or to ``stream`` (stdout).

    A file is written atomically: to a temporary file in its directory, then renamed over
    ``path``; on any failure the temporary file is removed and nothing is left behind. Only
    a regular file is replaced (a symbolic link is written through); a directory, FIFO,
    device or socket at ``path`` is refused (:mod:`linecontact._files`).

    Parameters
    ----------
    table : Table
        The records and their provenance.
    fmt : str
        ``"table"``, ``"csv"``, ``"json"`` or ``"jsonl"``.
    path : str or path-like, optional
        The file to write; None: ``stream``.
    indent : int, optional
        The indentation of JSON.
    stream : file object, optional
        Where to write without ``path`` (default: standard output).
    name : str
        How messages name ``path`` (``"-o/--output"`` on the command line).

    Raises
    ------
    ValueError
        If ``fmt`` or ``indent`` is invalid, or ``path`` is not a regular file.
    OSError
        If the file cannot be written (missing directory, no permission, ...).
    """
    if path is None:
        out = sys.stdout if stream is None else stream
        for chunk in _chunks(table, fmt, indent):
            out.write(chunk)
        out.flush()
        return
    chunks = list(_chunks(table, fmt, indent))  # format errors before touching the disk
    with atomic_file(path, "w", name=name, encoding="utf-8", newline="") as fh:
        for chunk in chunks:
            fh.write(chunk)
