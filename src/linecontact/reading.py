"""Read the CSV, JSON and JSON Lines files of the command line back into a pandas DataFrame.

:mod:`linecontact.output` writes every file (its docstring is the format contract); :func:`read`
inverts it: one row per record, the provenance block in ``DataFrame.attrs``.
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
import re
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    import pandas as pd  # type: ignore[import-untyped,unused-ignore]

__all__ = ["read"]

#: File name extensions and ``format=`` values, and the format each one means.
_FORMATS = {"csv": "csv", "json": "json", "jsonl": "jsonl", "ndjson": "jsonl"}
_NAMES = {"csv": "CSV", "json": "JSON", "jsonl": "JSON Lines"}
_INT = re.compile(r"-?[0-9]+")


def read(path: str | os.PathLike[str], *, format: str | None = None) -> pd.DataFrame:
    """Read a file written by any ``linecontact`` subcommand into a DataFrame.

    Parameters
    ----------
    path : str or path-like
        A file written with ``--format csv|json|jsonl`` or ``-o FILE.csv|.json|.jsonl``.
    format : {"csv", "json", "jsonl", "ndjson"}, optional
        The format; by default the extension's (``.ndjson`` is JSON Lines), else the content's.

    Returns
    -------
    pandas.DataFrame
        One row per record, the columns in record order. Numbers are floats (NaN where the
        file has null or an empty CSV field) or integers, flags booleans, text objects (None
        where missing). ``attrs`` holds the provenance as written: ``"linecontact"`` (the
        version), ``"command"``, ``"parameters"`` and ``"units"``.

    Raises
    ------
    FileNotFoundError
        If ``path`` does not exist.
    ValueError
        If the file is not one that linecontact writes, whole: not UTF-8 text, binary data,
        invalid or truncated JSON, a CSV or JSON Lines file cut inside a line, a provenance
        that is not what the writer writes, a record without the columns of the others, or
        a value that is no number in a column whose unit (or name: ``a_m``, ``F_N_per_m``)
        says it holds numbers. The message names the file, and the line (or record) and
        the column at fault.
    ImportError
        If pandas is not installed.

    Examples
    --------
    After ``linecontact curve --R-over-h 100 --sigma0-over-E 0.05 -o curve.csv``:

    >>> df = read("curve.csv")  # doctest: +SKIP
    >>> df.attrs["parameters"]["R_over_h"], df["F_over_Eh"].min()  # doctest: +SKIP
    """
    try:
        import pandas as pd  # type: ignore[import-untyped,unused-ignore]
    except ImportError:
        raise ImportError("lc.read needs pandas: pip install 'linecontact[sweep]'") from None
    name = os.fspath(path)
    fmt = _format_of(name, format)
    with open(name, encoding="utf-8-sig", newline="") as fh:
        try:
            text = fh.read()
        except UnicodeDecodeError as exc:
            raise ValueError(f"{name}: not a linecontact file: not UTF-8 text ({exc})") from None
    if "\x00" in text:
        line = text.count("\n", 0, text.index("\x00")) + 1
        raise ValueError(f"{name}: not a linecontact file: binary data (a NUL byte on line {line})")
    if fmt is None:
        fmt = _sniff(name, text)
    try:
        head, columns = (_csv if fmt == "csv" else _json)(name, text, fmt)
    except RecursionError:  # JSON nested thousands deep
        raise _fail(name, fmt, "JSON nested too deeply") from None
    data = {k: pd.Series(a, dtype=a.dtype, copy=False) for k, a in columns.items()}
    size = len(next(iter(columns.values()))) if columns else 0
    df = pd.DataFrame(data, index=pd.RangeIndex(size))
    df.attrs.update(head)
    return df


def _format_of(name: str, given: str | None) -> str | None:
    """The format ``given``, else the extension's; None when neither says."""
    if given is not None:
        if given.lower() not in _FORMATS:
            raise ValueError(f"format must be one of {', '.join(_FORMATS)}, got {given!r}")
        return _FORMATS[given.lower()]
    return _FORMATS.get(os.path.splitext(name)[1].lower().lstrip("."))


def _sniff(name: str, text: str) -> str:
    start = text.lstrip()[:1]
    if start == "#":
        return "csv"
    if start == "{":
        try:
            _loads(text)
        except ValueError:
            return "jsonl"
        return "json"
    raise ValueError(f"{name}: not a linecontact file: neither CSV, JSON nor JSON Lines")


def _fail(name: str, fmt: str, what: str) -> ValueError:
    return ValueError(f"{name}: not a linecontact {_NAMES[fmt]} file: {what}")


def _strict(token: str) -> Any:
    raise ValueError(f"{token} is not JSON (the writer writes a missing number as null)")


def _unique(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    keys = [k for k, _ in pairs]
    if len(set(keys)) != len(keys):
        twice = next(k for k in keys if keys.count(k) > 1)
        raise ValueError(f"the key {twice!r} appears twice in one object")
    return dict(pairs)


def _loads(text: str) -> Any:
    """Strict JSON, as the writer writes it: no NaN or Infinity, no key twice in an object."""
    return json.loads(text, parse_constant=_strict, object_pairs_hook=_unique)


def _provenance(name: str, fmt: str, head: dict[str, Any]) -> None:
    """Refuse a provenance block that is not what the writer writes (a file that lies)."""
    if not isinstance(head.get("linecontact"), dict):
        raise _fail(name, fmt, "its 'linecontact' provenance is not an object")
    command = head.get("command", [])
    if not (isinstance(command, list) and all(isinstance(w, str) for w in command)):
        raise _fail(name, fmt, "its 'command' is not a list of words")
    if not isinstance(head.get("parameters", {}), dict):
        raise _fail(name, fmt, "its 'parameters' are not an object")
    units = head.get("units", {})
    if not (isinstance(units, dict) and all(isinstance(u, str) for u in units.values())):
        raise _fail(name, fmt, "its 'units' are not an object of unit names")


def _numeric(head: dict[str, Any], key: str) -> str | None:
    """The unit that says column ``key`` holds numbers: the provenance's, or its name's."""
    from .output import unit_of

    units = head.get("units", {})
    if key in units:
        return str(units[key])
    unit = unit_of(key)
    return None if unit == "1" else unit


def _json(name: str, text: str, fmt: str) -> tuple[dict[str, Any], dict[str, np.ndarray]]:
    """The provenance and the columns of a JSON or a JSON Lines file."""
    lines = text.splitlines()
    try:
        if fmt == "json":
            obj = _loads(text)
        else:
            first = next((i for i, s in enumerate(lines) if s.strip()), len(lines))
            obj = _loads(lines[first]) if first < len(lines) else None
    except ValueError as exc:
        raise _fail(name, fmt, f"invalid JSON ({exc})") from None
    if not isinstance(obj, dict) or "linecontact" not in obj:
        raise _fail(name, fmt, "no 'linecontact' provenance object")
    head = {k: v for k, v in obj.items() if k != "results"}
    if fmt == "json" or "results" in obj:  # a compact JSON file named .jsonl reads as JSON
        fmt = "json"
        records = obj.get("results")
        if not isinstance(records, list):
            raise _fail(name, fmt, "no 'results' list")
        where = [f"results[{i}]" for i in range(len(records))]
    else:
        records, where = [], []
        for i in range(first + 1, len(lines)):
            if lines[i].strip():
                try:
                    records.append(_loads(lines[i]))
                except ValueError as exc:
                    raise _fail(name, fmt, f"line {i + 1}: invalid JSON ({exc})") from None
                where.append(f"line {i + 1}")
    _provenance(name, fmt, head)
    keys: list[str] = []
    for rec, at in zip(records, where, strict=True):
        if not isinstance(rec, dict):
            raise _fail(name, fmt, f"{at} is not a JSON object")
        if not keys:
            keys = list(rec)
        elif list(rec) != keys:  # the writer writes every column in every record
            missing = [k for k in keys if k not in rec] or [k for k in rec if k not in keys]
            raise _fail(name, fmt, f"{at} has not the columns of the first record ({missing[0]!r})")
    columns = {}
    for k in keys:
        values = [rec[k] for rec in records]
        unit = _numeric(head, k)
        if unit is not None:
            _check_numbers(name, fmt, k, unit, values, where)
        columns[k] = _column(values, unit is not None)
    return head, columns


def _check_numbers(
    name: str, fmt: str, key: str, unit: str, values: list[Any], where: list[str]
) -> None:
    """Refuse a value of a numeric column that is no number (nor null, nor a list of them)."""
    for v, at in zip(values, where, strict=True):
        bad = _not_a_number(v)
        if bad is not None:
            raise _fail(
                name, fmt, f"{at}, column {key!r}: {bad!r} is not a number (its unit is {unit!r})"
            )


def _not_a_number(v: Any) -> Any:
    """The first part of ``v`` that is no finite number (None: ``v`` is numbers or nulls)."""
    if v is None or (type(v) is float and math.isfinite(v)):
        return None
    if type(v) is int:
        return None if abs(v) < 2**1023 else v  # beyond the floating-point range
    if isinstance(v, list):
        return next((b for b in map(_not_a_number, v) if b is not None), None)
    return v


def _csv(name: str, text: str, fmt: str) -> tuple[dict[str, Any], dict[str, np.ndarray]]:
    """The provenance (the ``# key: JSON`` lines) and the columns of a CSV file."""
    head: dict[str, Any] = {}
    pos, lineno = 0, 0
    while text.startswith("#", pos):
        end = text.find("\n", pos)
        end = len(text) if end < 0 else end + 1
        line = text[pos:end].rstrip("\r\n")
        key, sep, value = line[1:].strip().partition(": ")
        lineno += 1
        try:
            if not sep or not key:
                raise ValueError
            head[key] = _loads(value)
        except ValueError:
            raise _fail(name, fmt, f"line {lineno} is not '# key: JSON': {line[:60]!r}") from None
        pos = end
    if "linecontact" not in head:
        raise _fail(name, fmt, "no '# linecontact: ...' provenance line before the header")
    _provenance(name, fmt, head)
    if text[pos:] and not text.endswith("\n"):  # the writer ends every line
        last = text.count("\n") + 1
        raise _fail(name, fmt, f"it ends inside line {last} (no line end): it was cut short")
    reader = csv.reader(io.StringIO(text[pos:], newline=""))
    rows, ends = [], []
    try:
        for row in reader:
            rows.append(row)
            ends.append(lineno + reader.line_num)
    except csv.Error as exc:
        raise _fail(name, fmt, f"line {lineno + reader.line_num}: {exc}") from None
    if not rows:
        raise _fail(name, fmt, "no header row")
    header = rows[0]
    if len(set(header)) != len(header) or "" in header:
        bad = next(h for h in header if not h or header.count(h) > 1)
        what = "an empty column name" if not bad else f"the column {bad!r} twice"
        raise _fail(name, fmt, f"its header (line {ends[0]}) has {what}")
    for i, (row, end) in enumerate(zip(rows[1:], ends[1:], strict=True)):
        if len(row) != len(header):
            what = f"row {i + 1} has {len(row)} fields, the header {len(header)} (line {end})"
            raise _fail(name, fmt, what)
    where = [f"line {end}" for end in ends[1:]]
    columns = {}
    for j, k in enumerate(header):
        cells = [row[j] for row in rows[1:]]
        unit = _numeric(head, k)
        if unit is not None:
            values = []
            for c, at in zip(cells, where, strict=True):
                v = _number(c)
                if v is _NOT_A_NUMBER or _not_a_number(v) is not None:
                    raise _fail(
                        name,
                        fmt,
                        f"{at}, column {k!r}: {c!r} is not a number (its unit is {unit!r})",
                    )
                values.append(v)
            columns[k] = _column(values, True)
        else:
            columns[k] = _column(_from_csv(cells), False)
    return head, columns


def _from_csv(cells: list[str]) -> list[Any]:
    """CSV fields of a column without a unit (no number): booleans, or text, lists, None."""
    if cells and all(c in ("true", "false") for c in cells):
        return [c == "true" for c in cells]
    return [_text(c) for c in cells]


#: What :func:`_number` gives for a field that is no number.
_NOT_A_NUMBER = object()
#: A number as the writer writes it (the shortest repr: no blank, no underscore, no nan/inf).
_NUMBER = re.compile(r"-?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][-+]?[0-9]+)?")


def _number(cell: str) -> Any:
    """A field of a numeric column: int, float, None (empty), a list, or _NOT_A_NUMBER."""
    if not cell:
        return None
    if cell.startswith("["):
        value = _text(cell)
        return value if isinstance(value, list) else _NOT_A_NUMBER
    if not _NUMBER.fullmatch(cell):
        return _NOT_A_NUMBER
    try:
        return int(cell) if _INT.fullmatch(cell) else float(cell)
    except ValueError:  # an integer of more digits than Python converts: none of ours
        return _NOT_A_NUMBER


def _text(cell: str) -> Any:
    """A field as text, None when empty, a list when it is a list's JSON text."""
    if cell.startswith("["):  # a per-point list, written as its JSON text
        try:
            value = _loads(cell)
        except ValueError:
            return cell
        return value if isinstance(value, list) else cell
    return cell or None


def _column(values: list[Any], numeric: bool) -> np.ndarray[Any, Any]:
    """One column as an array: int, float (NaN for None), bool, else object (None kept)."""
    given = [v for v in values if v is not None]
    full = bool(given) and len(given) == len(values)
    if full and all(isinstance(v, bool) for v in given):
        return np.array(values, dtype=bool)
    if (given or numeric) and all(type(v) in (int, float) for v in given):
        if full and all(type(v) is int and -(2**63) <= v < 2**63 for v in given):
            return np.array(values, dtype=np.int64)
        if not any(type(v) is int and abs(v) > 2**53 for v in given):
            return np.array([np.nan if v is None else v for v in values], dtype=float)
    out = np.empty(len(values), dtype=object)
    for i, v in enumerate(values):
        out[i] = v
    return out
