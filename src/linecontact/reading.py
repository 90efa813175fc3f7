"""Read the CSV, JSON and JSON Lines files of the command line back into a pandas DataFrame.

:mod:`linecontact.output` writes every file (its docstring is the format contract); :func:`read`
inverts it: one row per record, the provenance block in ``DataFrame.attrs``.
"""

from __future__ import annotations

import csv
import io
import json
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
        If the file is not one that linecontact writes (the message names it and the fault).
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
    if fmt is None:
        fmt = _sniff(name, text)
    head, columns = (_csv if fmt == "csv" else _json)(name, text, fmt)
    units = head.get("units")
    numeric = set(units) if isinstance(units, dict) else set()
    arrays = {k: _column(v, k in numeric) for k, v in columns.items()}
    data = {k: pd.Series(a, dtype=a.dtype, copy=False) for k, a in arrays.items()}
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
            json.loads(text)
        except json.JSONDecodeError:
            return "jsonl"
        return "json"
    raise ValueError(f"{name}: not a linecontact file: neither CSV, JSON nor JSON Lines")


def _fail(name: str, fmt: str, what: str) -> ValueError:
    return ValueError(f"{name}: not a linecontact {_NAMES[fmt]} file: {what}")


def _json(name: str, text: str, fmt: str) -> tuple[dict[str, Any], dict[str, list[Any]]]:
    """The provenance and the columns of a JSON or a JSON Lines file."""
    lines = text.splitlines()
    try:
        if fmt == "json":
            obj = json.loads(text)
        else:
            first = next((i for i, s in enumerate(lines) if s.strip()), len(lines))
            obj = json.loads(lines[first]) if first < len(lines) else None
    except json.JSONDecodeError as exc:
        raise _fail(name, fmt, f"invalid JSON ({exc})") from None
    if not isinstance(obj, dict) or "linecontact" not in obj:
        raise _fail(name, fmt, "no 'linecontact' provenance object")
    head = {k: v for k, v in obj.items() if k != "results"}
    if fmt == "json" or "results" in obj:  # a compact JSON file named .jsonl reads as JSON
        records = obj.get("results")
        if not isinstance(records, list):
            raise _fail(name, "json", "no 'results' list")
        where = [f"results[{i}]" for i in range(len(records))]
    else:
        records, where = [], []
        for i in range(first + 1, len(lines)):
            if lines[i].strip():
                try:
                    records.append(json.loads(lines[i]))
                except json.JSONDecodeError as exc:
                    raise _fail(name, fmt, f"line {i + 1}: invalid JSON ({exc})") from None
                where.append(f"line {i + 1}")
    keys: dict[str, None] = {}
    for rec, at in zip(records, where, strict=True):
        if not isinstance(rec, dict):
            raise _fail(name, fmt, f"{at} is not a JSON object")
        keys.update(dict.fromkeys(rec))
    return head, {k: [rec.get(k) for rec in records] for k in keys}


def _csv(name: str, text: str, fmt: str) -> tuple[dict[str, Any], dict[str, list[Any]]]:
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
            head[key] = json.loads(value)
        except ValueError:
            raise _fail(name, fmt, f"line {lineno} is not '# key: JSON': {line[:60]!r}") from None
        pos = end
    if "linecontact" not in head:
        raise _fail(name, fmt, "no '# linecontact: ...' provenance line before the header")
    units = head.get("units")
    rows = list(csv.reader(io.StringIO(text[pos:], newline="")))
    if not rows:
        raise _fail(name, fmt, "no header row")
    header = rows[0]
    for i, row in enumerate(rows[1:]):
        if len(row) != len(header):
            what = f"row {i + 1} has {len(row)} fields, the header {len(header)}"
            raise _fail(name, fmt, what)
    cells = dict(zip(header, zip(*rows[1:], strict=True), strict=False))
    return head, {
        k: _from_csv(list(cells.get(k, ())), isinstance(units, dict) and k in units) for k in header
    }


def _from_csv(cells: list[str], numeric: bool) -> list[Any]:
    """CSV fields as the values the JSON writer gives: numbers, booleans, text, lists, None."""
    if numeric:
        try:
            return [_number(c) for c in cells]
        except ValueError:
            pass  # a column of text that has a unit: as text
    if cells and all(c in ("true", "false") for c in cells):
        return [c == "true" for c in cells]
    return [_text(c) for c in cells]


def _number(cell: str) -> Any:
    if not cell or cell.startswith("["):
        return _text(cell)
    return int(cell) if _INT.fullmatch(cell) else float(cell)


def _text(cell: str) -> Any:
    """A field as text, None when empty, a list when it is a list's JSON text."""
    if cell.startswith("["):  # a per-point list, written as its JSON text
        try:
            value = json.loads(cell)
        except json.JSONDecodeError:
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
