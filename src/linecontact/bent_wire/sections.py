r"""The bending stiffness of a wire from its cross-section: round, a tube, a regular polygon.

A wire bent in the substrate's plane bends about the axis normal to the substrate through
the centroid of its cross-section; its bending stiffness is :math:`EI`, the Young's modulus
times the second moment of area about that axis, :math:`I = \iint y^2\,dA` (:math:`y` the
distance from the axis in the substrate's plane).

- **Round** (:data:`~linecontact.geometry.ROUND`), radius :math:`R`:
  :math:`I = \pi R^4/4`; a **tube** of inner radius :math:`R_i`:
  :math:`I = \pi (R^4 - R_i^4)/4`.
- **A regular polygon** (:class:`~linecontact.geometry.Polygon`) of :math:`n \ge 3` sides,
  circumradius :math:`R`, corners rounded with radius :math:`r_c`: the Minkowski sum of the
  sharp polygon of circumradius :math:`p = R - r_c` and the disc of radius :math:`r_c`
  (``docs/faceted.md``). Its moments are invariant under the rotation by :math:`2\pi/n`,
  and for :math:`n \ge 3` a symmetric 2x2 tensor with that invariance is a multiple of the
  identity: :math:`I` is the same about every axis through the centroid, half the polar
  moment :math:`J`. The section is the polygon, a rectangle :math:`L \times r_c` on each
  side (:math:`L = 2p\sin(\pi/n)`, at the apothem :math:`h = p\cos(\pi/n)`), and a sector
  of angle :math:`\alpha = 2\pi/n` at each corner; their polar moments about the centroid
  add up to

  .. math::

      J = n\Bigl[\tfrac{1}{12}\,p^4\sin\alpha\,(2 + \cos\alpha)
          + \tfrac{1}{12}\,r_c L^3 + \tfrac{1}{3} L\bigl((h + r_c)^3 - h^3\bigr)
          + \tfrac{1}{4}\alpha r_c^4 + \tfrac{4}{3} p\, r_c^3 \sin\tfrac{\alpha}{2}
          + \tfrac{1}{2}\alpha\, p^2 r_c^2\Bigr],

  exact (the triangle of a side about its apex, :math:`A_t (a^2 + b^2 + a\cdot b)/6`; the
  rectangle; the sector shifted to its corner by the parallel-axis theorem). At
  :math:`r_c = R` it is the disc, at :math:`r_c = 0` the sharp polygon (the hexagon of side
  :math:`a`: :math:`5\sqrt 3\,a^4/16`).

Lengths in metres, the modulus in pascals: :math:`I` in m^4, :math:`EI` in N m^2.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import check_array
from ..errors import ParameterError
from ..geometry import ROUND, CrossSection, Polygon, Round

__all__ = ["bending_stiffness", "bending_stiffness_sd", "second_moment_of_area"]


def _out(v: NDArray) -> Any:
    return v.item() if v.ndim == 0 else v


def _polygon_moment(radius: NDArray, sides: int, corner_radius: float) -> NDArray:
    """The second moment of the rounded regular polygon about any centroidal axis [m^4]."""
    n, r = sides, corner_radius
    p = radius - r  # the sharp polygon's circumradius
    alpha = 2.0 * math.pi / n
    h = p * math.cos(math.pi / n)  # its apothem
    side = 2.0 * p * math.sin(math.pi / n)
    polar = n * (
        p**4 * math.sin(alpha) * (2.0 + math.cos(alpha)) / 12.0  # the n triangles
        + r * side**3 / 12.0
        + side * ((h + r) ** 3 - h**3) / 3.0  # the n rectangles on the sides
        + alpha * r**4 / 4.0
        + 4.0 / 3.0 * p * r**3 * math.sin(alpha / 2.0)
        + alpha * p**2 * r**2 / 2.0  # the n corner sectors, moved to the corners
    )
    return polar / 2.0  # isotropic: I = J/2


def second_moment_of_area(
    radius: ArrayLike,
    cross_section: CrossSection = ROUND,
    *,
    inner_radius: ArrayLike = 0.0,
) -> Any:
    r"""The second moment of area of a wire's cross-section about a centroidal axis.

    Parameters
    ----------
    radius : array_like
        The radius [m] (the circumradius of a polygon), ``> 0``.
    cross_section : Round or Polygon, optional
        The shape (:mod:`linecontact.geometry`); a polygon's ``corner_radius`` [m] at most
        ``radius`` (equal: the round wire).
    inner_radius : array_like, optional
        The bore of a tube [m], in ``[0, radius)``; round wires only.

    Returns
    -------
    float or ndarray
        :math:`I` [m^4], about the axis normal to the substrate (the same about every
        centroidal axis for these shapes); arrays broadcast.

    Raises
    ------
    ParameterError
        An argument out of range, naming it.

    Notes
    -----
    Round: :math:`\pi (R^4 - R_i^4)/4`; a rounded regular polygon: the module's formula.

    Examples
    --------
    >>> from linecontact.geometry import Polygon
    >>> a = 50e-9  # a sharp hexagon of side a: 5 sqrt(3) a^4 / 16
    >>> print(f"{second_moment_of_area(a, Polygon(6)) / (5 * 3**0.5 * a**4 / 16):.12f}")
    1.000000000000
    """
    r = check_array("radius", radius)
    if not isinstance(cross_section, (Round, Polygon)):
        raise ParameterError(
            "cross_section",
            "cross_section must be Round() or Polygon(sides, corner_radius), got "
            f"{cross_section!r}",
        )
    ri = check_array("inner_radius", inner_radius, low_inclusive=True)
    if isinstance(cross_section, Polygon):
        if np.any(ri != 0.0):
            raise ParameterError(
                "inner_radius",
                "inner_radius is a round tube's: a polygon takes none (give inner_radius = 0)",
            )
        rc = cross_section.corner_radius
        if np.any(r < rc):
            raise ParameterError(
                "corner_radius",
                f"corner_radius must be at most the circumradius (radius = "
                f"{float(np.min(r))!r} m), got {rc!r} m",
            )
        return _out(_polygon_moment(r, cross_section.sides, rc))
    r, ri = np.broadcast_arrays(r, ri)
    if np.any(ri >= r):
        bad = int(np.flatnonzero((ri >= r).ravel())[0])
        raise ParameterError(
            "inner_radius",
            f"inner_radius must be in [0, radius), got {float(ri.flat[bad])!r} m with radius "
            f"{float(r.flat[bad])!r} m",
        )
    return _out(math.pi * (r**4 - ri**4) / 4.0)


def bending_stiffness(
    modulus: ArrayLike,
    radius: ArrayLike,
    cross_section: CrossSection = ROUND,
    *,
    inner_radius: ArrayLike = 0.0,
) -> Any:
    r"""The bending stiffness :math:`EI` of a wire, bent in the substrate's plane.

    Parameters
    ----------
    modulus : array_like
        Young's modulus of the wire :math:`E` [Pa], ``> 0`` (not the composite modulus of
        the contact).
    radius, cross_section, inner_radius
        As in :func:`second_moment_of_area`.

    Returns
    -------
    float or ndarray
        :math:`EI` [N m^2]; arrays broadcast.

    Raises
    ------
    ParameterError
        An argument out of range, naming it.

    Examples
    --------
    >>> print(f"{bending_stiffness(140e9, 50e-9):.4e}")  # a ZnO wire, D = 100 nm
    6.8722e-19
    """
    e = check_array("modulus", modulus)
    return _out(
        np.asarray(e * second_moment_of_area(radius, cross_section, inner_radius=inner_radius))
    )


def bending_stiffness_sd(
    modulus: float,
    radius: float,
    cross_section: CrossSection = ROUND,
    *,
    inner_radius: float = 0.0,
    modulus_sd: float = 0.0,
    radius_sd: float = 0.0,
) -> float:
    r"""The standard uncertainty of :math:`EI` [N m^2] from those of the modulus and radius.

    Linearised, the two independent: :math:`EI\,\sigma_E/E` in quadrature with
    :math:`\partial(EI)/\partial R\;\sigma_R`, the derivative by a forward difference
    (:math:`4EI/R` for a solid section; a tube's bore or a polygon's corners held).

    Examples
    --------
    >>> ei = bending_stiffness(140e9, 50e-9)
    >>> print(f"{bending_stiffness_sd(140e9, 50e-9, radius_sd=0.5e-9) / ei:.6f}")  # 4 %
    0.040000
    """
    ei = float(bending_stiffness(modulus, radius, cross_section, inner_radius=inner_radius))
    E_sd = float(check_array("modulus_sd", modulus_sd, low_inclusive=True))
    R_sd = float(check_array("radius_sd", radius_sd, low_inclusive=True))
    # a forward difference: a smaller radius may fall below a polygon's corner radius
    step = 1e-6 * float(radius)
    up = float(bending_stiffness(modulus, radius + step, cross_section, inner_radius=inner_radius))
    return math.hypot(ei * E_sd / float(modulus), (up - ei) / step * R_sd)
