r"""The cross-sections of a wire as values: :class:`Round` and :class:`Polygon`, in SI units.

A body is a geometry and a law (:class:`~linecontact.Cylinder`: ``cross_section=`` and
``adhesion=``). A cross-section says what its shape fixes: its ``kind`` (the key under
which a body looks up the problems written for it), its SI parameters, and the groups its
kernels take beside the paper's (``R/h``, ``sigma0/E``), each length over the radius ``R``
(the circumradius of a polygon). Both are wires: their forces are per unit length [N/m].

- :class:`Round`: the round wire of radius ``R`` (the paper's cylinder).
- :class:`Polygon`: a regular polygon of ``sides`` sides, circumradius ``R``, corners
  rounded with ``corner_radius`` ``r_c`` (``0 <= r_c <= R``; ``r_c = R`` is the round
  wire), lying on a facet (:mod:`linecontact.facet`, ``docs/faceted.md``).
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass
from typing import Any, ClassVar

from .errors import ParameterError

__all__ = ["NAMED_SIDES", "ROUND", "CrossSection", "Polygon", "Round", "cross_section"]

#: The cross-sections by name (``--cross-section``): the number of sides of each polygon.
NAMED_SIDES: dict[str, int] = {
    "triangle": 3,
    "square": 4,
    "pentagon": 5,
    "hexagon": 6,
    "heptagon": 7,
    "octagon": 8,
}


@dataclass(frozen=True)
class CrossSection:
    """A wire's cross-section (the base of :class:`Round` and :class:`Polygon`)."""

    #: The key of the problems written for the shape (``Cylinder.WRITTEN``).
    kind: ClassVar[str] = ""
    #: The unit of its forces: a wire's are per unit length.
    force_unit: ClassVar[str] = "N/m"

    @property
    def name(self) -> str:
        """The name of ``--cross-section`` (``"round"``, ``"hexagon"``, ...)."""
        raise NotImplementedError

    def checked(self, radius: float) -> CrossSection:
        """The cross-section checked against the wire's ``radius`` [m] (itself)."""
        return self

    def groups(self, radius: Any) -> dict[str, Any]:
        """The groups the kernels take beside ``R/h`` and ``sigma0/E`` (lengths over ``R``).

        ``radius`` [m] a number or an array of them (the groups then per radius).
        """
        return {}

    def parameters(self) -> dict[str, Any]:
        """The SI parameters as given, for the provenance block (units in the names)."""
        return {"cross_section": self.name}


@dataclass(frozen=True)
class Round(CrossSection):
    """The round wire: a circle of the body's radius."""

    kind: ClassVar[str] = "round"

    @property
    def name(self) -> str:
        """``"round"``."""
        return "round"


@dataclass(frozen=True)
class Polygon(CrossSection):
    r"""A regular polygon lying on a facet, its corners rounded.

    Parameters
    ----------
    sides : int
        The number of sides, ``>= 3`` (6: hexagonal ZnO, GaN, InAs wires; 5: twinned Ag, Au
        wires).
    corner_radius : float
        The corners' radius ``r_c`` [m], ``0 <= r_c <=`` the circumradius (checked against it
        by the body); ``0`` is a sharp corner.

    Examples
    --------
    >>> round(Polygon(6, 5e-9).facet_width(50e-9), 15)  # (R - r_c) 2 sin(pi/6)
    4.5e-08
    """

    kind: ClassVar[str] = "polygon"
    sides: int = 6
    corner_radius: float = 0.0

    def __post_init__(self) -> None:
        n = self.sides  # any real number type (a NumPy integer too) with an integer value
        if (
            isinstance(n, bool)
            or not isinstance(n, numbers.Real)
            or not math.isfinite(n)
            or n < 3
            or n != int(n)
        ):
            raise ParameterError("sides", f"sides must be an integer >= 3, got {n!r}")
        object.__setattr__(self, "sides", int(n))
        r = self.corner_radius
        if isinstance(r, bool) or not isinstance(r, numbers.Real) or not (0 <= r < math.inf):
            raise ParameterError(
                "corner_radius", f"corner_radius must be a finite number >= 0 [m], got {r!r}"
            )
        object.__setattr__(self, "corner_radius", float(r))

    @property
    def name(self) -> str:
        """The polygon's name (``"hexagon"``), or ``"polygon-<n>"`` beyond the octagon."""
        for name, n in NAMED_SIDES.items():
            if n == self.sides:
                return name
        return f"polygon-{self.sides}"

    def checked(self, radius: float) -> Polygon:
        """Refuse a corner radius above the circumradius ``radius`` [m]."""
        if self.corner_radius > radius:
            raise ParameterError(
                "corner_radius",
                f"corner_radius must be at most the circumradius (radius = {radius!r} m; equal "
                f"to it is the round wire), got {self.corner_radius!r} m",
            )
        if 0 < self.corner_radius < 1e-12 * radius:  # facet.contact.ROUND_CORNER_MIN
            raise ParameterError(
                "corner_radius",
                f"corner_radius must be 0 (a sharp corner) or at least 1e-12 times the "
                f"circumradius (radius = {radius!r} m), got {self.corner_radius!r} m",
            )
        return self

    def facet_width(self, radius: float) -> float:
        """The width of the flat facet [m]: ``2 (R - r_c) sin(pi/n)``."""
        return 2 * (radius - self.corner_radius) * math.sin(math.pi / self.sides)

    def groups(self, radius: Any) -> dict[str, Any]:
        """``sides`` and ``corner_radius_over_R`` (an array for an array of radii)."""
        return {"sides": self.sides, "corner_radius_over_R": self.corner_radius / radius}

    def parameters(self) -> dict[str, Any]:
        """The name, the sides and the corner radius [m]."""
        return {
            "cross_section": self.name,
            "sides": self.sides,
            "corner_radius_m": self.corner_radius,
        }


#: The round wire (the default cross-section of a body).
ROUND = Round()


def cross_section(name: str, corner_radius: float | None = None) -> CrossSection:
    """The cross-section called ``name`` (``"round"``, ``"hexagon"``, ...; NAMED_SIDES).

    ``corner_radius`` [m] is a polygon's (default 0, sharp); a round wire takes none.
    """
    key = str(name).strip().lower()
    if key == "round":
        if corner_radius is not None:
            raise ParameterError(
                "corner_radius",
                "corner_radius is a polygon's: a round wire has none (give cross_section = "
                f"{' or '.join(NAMED_SIDES)})",
            )
        return ROUND
    if key not in NAMED_SIDES:
        raise ParameterError(
            "cross_section",
            f"cross_section must be one of round, {', '.join(NAMED_SIDES)}, got {name!r}",
        )
    return Polygon(NAMED_SIDES[key], 0.0 if corner_radius is None else corner_radius)
