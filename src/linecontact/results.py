"""The base of every result object: frozen fields, per-point columns, dicts and records.

Every solver returns a frozen dataclass derived from :class:`Result`. Its fields are the
inputs broadcast together, the outputs and the diagnostics; a scalar call gives Python
scalars, an array call arrays of the points' shape. The output layer
(:mod:`linecontact.output`) reads results through :meth:`Result.columns` only: one 1-D array
per quantity, with no Python object built per point.
"""

from __future__ import annotations

from dataclasses import Field, dataclass, fields
from typing import Any, ClassVar, TypeVar

import numpy as np
from numpy.typing import NDArray

__all__ = ["SI", "Result", "as_output"]


def SI(name: str, scale: str, unit: str) -> dict[str, tuple[str, str, str]]:  # noqa: N802
    """The metadata of a field that has an SI form: its SI name, scale and SI unit.

    Declared beside the field, ``a_over_R: float = field(metadata=SI("contact_half_width",
    "R", "m"))``; the scale is a name of :data:`linecontact.units.SCALES`.
    """
    return {"si": (name, scale, unit)}


def as_output(value: Any, scalar: bool) -> Any:
    """``value`` as returned to the caller: a Python scalar for scalar calls, else an array."""
    if isinstance(value, np.generic):
        return value.item() if scalar else np.asarray(value)
    if isinstance(value, np.ndarray) and scalar and value.size == 1:
        return value.reshape(()).item()
    return value


@dataclass(frozen=True)
class Result:
    """Base of the frozen result dataclasses.

    Subclasses list the fields that are inputs of the problem in ``inputs`` (the output
    layer moves them to its ``parameters`` block when they are the same at every point),
    the derived per-point properties to export in ``derived``, the fields that are not per
    point in ``whole``, and the SI form of a field beside it (``field(metadata=SI(...))``),
    gathered into ``si`` (:mod:`linecontact.units`).
    Fields declared with ``repr=False`` (nested results) are not exported.
    """

    #: Fields that are inputs of the problem (parameters of the points).
    inputs: ClassVar[tuple[str, ...]] = ()
    #: Per-point properties exported as columns after the fields.
    derived: ClassVar[tuple[str, ...]] = ()
    #: Fields that are one value for the whole result, not per point (an interval, a
    #: matrix): in :meth:`to_dict`, not in :meth:`columns`.
    whole: ClassVar[tuple[str, ...]] = ()
    #: The SI form of each field with one: ``{field: (SI name, scale, SI unit)}``, the scale
    #: a name of :data:`linecontact.units.SCALES` (:func:`linecontact.units.to_si` reads it).
    #: Gathered from the fields' :func:`SI` metadata when the class is made: not written.
    si: ClassVar[dict[str, tuple[str, str, str]]] = {}

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        si = dict(cls.si)  # the base's, in its order
        for name, declared in list(vars(cls).items()):  # in the order written
            if isinstance(declared, Field) and "si" in declared.metadata:
                si[name] = declared.metadata["si"]
        cls.si = si

    def _names(self) -> list[str]:
        names = [f.name for f in fields(self) if f.repr and f.name not in self.whole]
        return names + list(self.derived)

    @property
    def shape(self) -> tuple[int, ...]:
        """Shape of the parameter points (``()`` for a scalar call)."""
        return np.broadcast_shapes(*(np.shape(getattr(self, k)) for k in self._names()))

    @property
    def size(self) -> int:
        """The number of parameter points (1 for a scalar call)."""
        return int(np.prod(self.shape))

    def columns(self) -> dict[str, NDArray[Any]]:
        """Each exported quantity as a 1-D array over the points (C order).

        Quantities that are the same for every point (a scalar field such as ``method``)
        are broadcast; no copy is made where none is needed.
        """
        shape = self.shape
        size = int(np.prod(shape))
        return {
            k: np.broadcast_to(np.asarray(getattr(self, k)), shape).reshape(size)
            for k in self._names()
        }

    def to_dict(self) -> dict[str, Any]:
        """The exported fields (not the derived properties), arrays as lists: JSON-ready.

        ``type(result)(**result.to_dict())`` rebuilds a result without nested results.
        """
        out = {}
        for f in fields(self):
            if f.repr:
                v = getattr(self, f.name)
                out[f.name] = v.tolist() if isinstance(v, (np.ndarray, np.generic)) else v
        return out

    def to_records(self) -> list[dict[str, Any]]:
        """One dict per point (the fields and the derived properties), from :meth:`columns`."""
        cols = {k: v.tolist() for k, v in self.columns().items()}
        keys = list(cols)
        return [dict(zip(keys, row, strict=True)) for row in zip(*cols.values(), strict=True)]


_R = TypeVar("_R", bound=Result)


def as_result(
    cls: type[_R], scalar: bool, shape: tuple[int, ...] | None = None, /, **values: Any
) -> _R:
    """``cls(**values)``, each value as returned to the caller (:func:`as_output`).

    ``shape``: the shape of the points, that flat arrays are given back in (reshaped first).
    """
    if shape is not None:
        values = {k: np.reshape(v, shape) for k, v in values.items()}
    return cls(**{k: as_output(v, scalar) for k, v in values.items()})
