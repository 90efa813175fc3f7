"""The scales of a body and the SI form of a nondimensional result, declared once.

A nondimensional result class declares, for each field that has an SI form, its SI name, the
scale that multiplies it and the SI unit, beside the field (:func:`linecontact.results.SI`)::

    a_over_R: float = field(metadata=SI("contact_half_width", "R", "m"))
    F_over_Eh: float = field(metadata=SI("load", "Eh", "N/m"))

and the class gathers them into its class variable ``si``
(``{"a_over_R": ("contact_half_width", "R", "m"), ...}``).

The scales are those of a body (:class:`Scales`: the radius ``R``, the composite modulus
``E``, the adhesion range ``h`` and, for the tangential problems at a fixed contact, its
half-width ``a``), by name (:data:`SCALES`). :func:`to_si` builds the SI values of a result
from its declaration; the SI layer (:mod:`linecontact.cylinder`) calls it wherever it
converts a nondimensional result.

>>> from linecontact import normal_contact
>>> r = normal_contact(0.01, R_over_h=100.0, sigma0_over_E=0.01)
>>> si = to_si(r, Scales(R=50e-9, E=100e9, h=0.5e-9))
>>> sorted(si)
['adhesive_zone_half_width', 'contact_half_width', 'load']
>>> si["contact_half_width"] == 0.01 * 50e-9
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["SCALES", "Scales", "to_si", "si_units"]

#: Each scale by name: its unit and its product of the body's ``R``, ``E``, ``h``, ``a``.
SCALES: dict[str, tuple[str, str]] = {
    "1": ("1", "1"),
    "R": ("m", "R"),
    "h": ("m", "h"),
    "a": ("m", "a"),
    "E": ("Pa", "E"),
    "Eh": ("N/m", "E h"),
    "ER": ("N/m", "E R"),
    "Ea": ("N/m", "E a"),
    "EhR": ("N", "E h R"),
    "Ea2": ("J/m", "E a a"),
}


@dataclass(frozen=True)
class Scales:
    """The scales of a body: ``R`` [m], ``E`` [Pa], ``h`` [m], ``a`` [m].

    ``a`` is the contact half-width where a problem's groups are at a fixed contact
    (``nan`` where none is).

    Index it by a scale's name (:data:`SCALES`): ``Scales(R, E, h)["Eh"] == E * h``.
    """

    R: float
    E: float
    h: float
    a: Any = math.nan

    @classmethod
    def of(cls, body: Any, *, h: float | None = None, a: Any = math.nan) -> Scales:
        """The scales of a :class:`~linecontact.cylinder.Cylinder`.

        Its ``radius``, ``modulus`` and ``adhesion_range`` (or the range ``h`` given).
        """
        if not all(hasattr(body, k) for k in ("radius", "modulus", "adhesion_range")):
            raise TypeError(
                f"Scales.of takes a Cylinder (radius, modulus, adhesion_range), got "
                f"{type(body).__name__}"
            )
        return cls(body.radius, body.modulus, body.adhesion_range if h is None else h, a)

    def __getitem__(self, name: str) -> Any:
        R, E, h, a = self.R, self.E, self.h, self.a
        if name == "1":
            return 1.0
        if name in ("R", "E", "h", "a"):
            return getattr(self, name)
        if name == "Eh":
            return E * h
        if name == "ER":
            return E * R
        if name == "Ea":
            return np.multiply(E, a)
        if name == "EhR":
            return E * h * R
        if name == "Ea2":
            return np.multiply(E, a) * a
        raise KeyError(f"no scale {name!r}: the scales are {', '.join(SCALES)}")


def _out(v: Any) -> Any:
    return v.item() if np.ndim(v) == 0 else v


def to_si(result: Any, scales: Scales) -> dict[str, Any]:
    """The SI values of ``result`` from its class's declaration ``si``.

    A dict from each SI name to the field times its scale (a Python scalar for a 0-d value),
    in the declared order.
    """
    decl = getattr(type(result), "si", None)
    if not decl:
        raise TypeError(f"{type(result).__name__} declares no SI scales (its class's 'si')")
    return {
        name: _out(np.multiply(getattr(result, field), scales[scale]))
        for field, (name, scale, _) in decl.items()
    }


def si_units(cls: type) -> dict[str, str]:
    """The SI name of each field that ``cls`` declares, to its unit."""
    return {name: unit for name, _, unit in getattr(cls, "si", {}).values()}
