"""A block of a sweep's records: the arrays of its points, their units and warnings.

:class:`Block` is what a worker returns; :func:`assemble` puts the records of the points
(or rows of points) computed into arrays of the block's shape, a point without a state a
record of NaN with its ``state`` and ``reason``.
"""

from __future__ import annotations

import json
import math
import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import ConvergenceError
from ..operations._messages import spell
from ..output import unit_of
from ._plan import Plan, template

__all__ = ["TEXT", "Block", "assemble", "call", "codes", "is_text", "template", "to_text"]

#: The dtype of text in a store: NumPy's variable-width strings (NumPy 2), else objects.
#: In a block, text is an array of Python strings (objects): cheap to fill and to compare.
_STRINGS: Any = getattr(np.dtypes, "StringDType", None)
TEXT: Any = np.dtype(object) if _STRINGS is None else _STRINGS()


def is_text(dtype: Any) -> bool:
    """True for a dtype of text (objects, NumPy strings)."""
    return np.dtype(dtype).kind in "OTUS"


def to_text(v: np.ndarray) -> np.ndarray:
    """``v`` as text of a store (:data:`TEXT`)."""
    if v.dtype == TEXT:
        return v
    if TEXT.kind == "O":  # NumPy 1: objects that are str
        return v.astype(str).astype(object)
    return v.astype(TEXT)


def codes(v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(categories, codes)`` of text ``v``: ``categories[codes] == v``."""
    flat = v.ravel()
    if flat.dtype.kind in "TUS" and flat.size:  # NumPy strings: compared in C, a pass a value
        at = np.full(flat.shape, -1, np.int32)
        found: list[str] = []
        rest = np.arange(flat.size)
        while rest.size and len(found) < 32:
            word = flat[rest[0]]
            same = flat[rest] == word
            at[rest[same]] = len(found)
            found.append(str(word))
            rest = rest[~same]
        if not rest.size:
            return np.array(found, dtype=object), at.reshape(v.shape)
    cats = list(dict.fromkeys(str(x) for x in set(flat.tolist())))
    if len(cats) <= 32:  # a few labels (state, mechanism): one comparison each
        at = np.zeros(flat.shape, np.int32)
        for i, c in enumerate(cats[1:], 1):
            at[flat == c] = i
    else:  # many (reasons with numbers in them)
        index = {c: i for i, c in enumerate(cats)}
        at = np.fromiter((index[str(x)] for x in flat.tolist()), np.int32, count=flat.size)
    return np.array(cats, dtype=object), at.reshape(v.shape)


def _objects(v: np.ndarray) -> np.ndarray:
    """NumPy strings as an array of Python strings, each distinct one made once."""
    return _from_codes(*codes(v))


def _from_codes(cats: np.ndarray, at: np.ndarray) -> np.ndarray:
    """``cats[at]``, an array of Python strings (also 0-d; empty where there are none)."""
    if not cats.size:
        return np.empty(at.shape, dtype=object)
    out = cats[at]
    return out if isinstance(out, np.ndarray) else np.array(out, dtype=object)  # 0-d: a str


@dataclass
class Block:
    """The records of one block: arrays of the block's shape (and records, where many).

    Attributes
    ----------
    index : int
        The block's number in the plan.
    data : dict of str to ndarray
        One array per record key, shape ``block shape`` or ``block shape + (records,)``.
    units : dict of str to str
        The unit of each record key.
    parameters : dict
        The provenance parameters of the block's first computed point.
    warnings : list of (str, str)
        The distinct warnings its points gave: the category's name and the message.
    at : dict
        The values of the axes (dest: value, or the list of a row's values) at the point
        whose provenance is ``parameters``.
    code : str
        The digest of the build that computed it (:func:`linecontact._fingerprint
        .code_digest`).
    kept : bool
        Whether the worker kept it already (its ``data`` then empty).
    """

    index: int
    data: dict[str, np.ndarray]
    units: dict[str, str] = field(default_factory=dict)
    parameters: dict[str, Any] = field(default_factory=dict)
    warnings: list[tuple[str, str]] = field(default_factory=list)
    at: dict[str, Any] = field(default_factory=dict)
    code: str = ""
    kept: bool = False
    #: ``(categories, codes)`` of text columns, where known (:meth:`coded` makes the rest)
    coded_text: dict[str, tuple[np.ndarray, np.ndarray]] = field(
        default_factory=dict, repr=False, compare=False
    )

    def coded(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        """``(categories, codes)`` of the text column ``name`` (:func:`codes`), made once."""
        if name not in self.coded_text:
            self.coded_text[name] = codes(self.data[name])
        return self.coded_text[name]

    def __getstate__(self) -> dict[str, Any]:
        """A block sent from a worker: its text as codes into its few distinct values.

        Pickling a million Python strings, and reading them back, took a quarter of a
        1e7-point sweep's time on two workers (issue 36); the codes are also what the
        kept block stores (:meth:`linecontact.sweeps._store.Partial.put`).
        """
        state = dict(self.__dict__)
        text = [k for k, v in self.data.items() if v.dtype.kind == "O"]
        state["coded_text"] = {k: self.coded(k) for k in text}
        state["data"] = {k: v for k, v in self.data.items() if k not in text}
        state["_order"] = list(self.data)
        return state

    def __setstate__(self, state: dict[str, Any]) -> None:
        order = state.pop("_order")
        coded = state["coded_text"]
        data = state["data"]
        state["data"] = {k: data[k] if k in data else coded[k][0][coded[k][1]] for k in order}
        self.__dict__.update(state)


def _words(p: Plan, values: dict[str, Any]) -> list[str]:
    words = list(p.fixed)
    for a in p.axes:
        v = values[a.dest]
        if isinstance(v, list):
            words += [a.flag, *(repr(x) for x in v)]
        else:
            words += [a.flag, repr(v) if a.unit else str(v)]
    return words


def call(p: Plan, values: dict[str, Any], said: list[tuple[str, str]]) -> tuple[Any, str, str]:
    """Run the operation at ``values`` (name: value): (its table or None, state, reason)."""
    base = template(p)
    at = {
        a.dest: v if isinstance(v, list) or not a.many else [v]
        for a in p.axes
        for v in (values[a.dest],)
    }
    inputs = base.replace(words=[p.command, *_words(p, values)], **at)
    state, reason = "", ""
    table = None
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            table = inputs.operation.run(inputs)
        except ConvergenceError as exc:
            state, reason = "not-converged", spell(str(exc), inputs)
        except (ValueError, OverflowError, ZeroDivisionError) as exc:
            state, reason = "invalid", spell(str(exc), inputs)
    for w in caught:
        item = (w.category.__name__, spell(str(w.message), inputs))
        if item not in said:
            said.append(item)
    return (table if not state else None), state, reason


def _column(v: np.ndarray) -> np.ndarray:
    """A record column as a sweep stores it: float, bool, or text (:data:`TEXT`)."""
    kind = v.dtype.kind
    if kind == "b":
        return np.asarray(v, bool)
    if kind in "fiu":
        return np.asarray(v, float)  # no copy of floats
    if kind in "TUS":
        return _objects(v)
    try:
        kinds = {type(x) for x in set(v.tolist())}  # few distinct values: cheap
    except TypeError:  # lists (unhashable): JSON text
        kinds = {list}
    none = v == np.array(None)
    if kinds <= {str, type(None)}:
        out = v.copy()
        out[none] = ""
        return out
    if kinds <= {int, float, type(None)}:
        return np.where(none, math.nan, v).astype(float)
    text = ["" if x is None else x if isinstance(x, str) else json.dumps(x) for x in v.tolist()]
    return np.array(text, dtype=object)


def _fill(kind: str) -> Any:
    return {"b": False, "f": math.nan}.get(kind, "")


def meta(table: Any, units: dict[str, str], parameters: dict[str, Any]) -> None:
    for k in table.columns:
        if k not in units:
            units[k] = table.units.get(k) or unit_of(k)
    if not parameters:
        parameters.update(table.provenance()["parameters"])


def assemble(
    shape: tuple[int, ...],
    n: int,
    pieces: list[tuple[np.ndarray, dict[str, np.ndarray], int]],
    failed: dict[int, tuple[str, str]],
    coded: dict[str, tuple[np.ndarray, np.ndarray]] | None = None,
) -> dict[str, np.ndarray]:
    """The columns of a block from its pieces (flat indices, columns, records) and failures.

    ``coded``, where given, receives ``(categories, codes)`` of the text columns made from
    codes (a block at once: :attr:`Block.coded_text`, no text compared again).
    """
    recs = max([r for _, _, r in pieces], default=1)
    cols: dict[str, np.ndarray] = {}
    if len(pieces) == 1 and not failed and recs == 1 and np.array_equal(pieces[0][0], np.arange(n)):
        # one call gave every point in order (a block at once): its columns, not copies
        made = {} if coded is None else coded
        out = {}
        for k, v in pieces[0][1].items():
            v = np.asarray(v)
            if v.dtype.kind in "TUS":  # NumPy strings: Python strings made from their codes
                cats, at = codes(v)
                made[k] = cats, at.reshape(shape)
                out[k] = _from_codes(cats, made[k][1])
            else:
                out[k] = _column(v).reshape(shape)
        for k, fill in (("state", "ok"), ("reason", "")):
            if k not in out:  # (a view of one word: filling a million took 5 ms a block)
                made[k] = np.array([fill], dtype=object), np.zeros(shape, np.int32)
                out[k] = np.broadcast_to(np.array(fill, dtype=object), shape)
            elif k not in made:
                out[k] = _objects(out[k])
        return out
    for idx, columns, r in pieces:
        for k, v in columns.items():
            v = _column(np.asarray(v))
            if k not in cols:
                cols[k] = np.full((n, recs), _fill(v.dtype.kind), dtype=v.dtype)
            target = cols[k]
            if target.dtype != v.dtype:
                if is_text(v.dtype) or is_text(target.dtype):
                    cols[k] = target = target.astype(str).astype(object)
                    v = v.astype(str).astype(object)
                else:
                    v = v.astype(target.dtype)
            if r == 1:
                target[idx, 0] = v
            else:
                target[idx[0], : len(v)] = v
    for k in ("state", "reason"):
        if k not in cols:
            fill = "ok" if k == "state" else ""
            cols[k] = np.full((n, recs), fill, dtype=object)
        if cols[k].dtype.kind != "O":
            cols[k] = cols[k].astype(str).astype(object)
    for i, (state, reason) in failed.items():
        for v in cols.values():
            v[i, :] = _fill(v.dtype.kind)
        cols["state"][i, :] = state
        cols["reason"][i, :] = reason
    out = {}
    for k, v in cols.items():
        out[k] = v.reshape(*shape, recs) if recs > 1 else v.reshape(shape)
    return out
