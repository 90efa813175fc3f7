r"""A faceted wire on its facet at given contact half-widths: :func:`facet_contact`.

The Maugis--Dugdale contact of a regular ``n``-sided wire with rounded corners lying on one
facet (``docs/faceted.md``); units and the closed forms in :mod:`linecontact.facet._branch`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import domain as _domain
from .._validation import broadcast, first_point, point_text, scalar_or_array
from ..errors import ConvergenceError, ParameterError
from ..results import SI, Result, as_result
from . import _branch as _b

#: The finest rounded corner over the circumradius (below it, a corner is sharp: 0).
ROUND_CORNER_MIN = 1e-12

#: The relative step of the finite difference that decides the stability (dF/da > 0).
_STEP = 1e-4

#: The inputs of the faceted wire's results (:attr:`linecontact.results.Result.inputs`).
INPUTS = ("R_over_h", "sigma0_over_E", "sides", "corner_radius_over_R")


@dataclass(frozen=True)
class FacetContact(Result):
    r"""Adhesive contact of a faceted wire on its facet at given contact half-widths.

    Attributes
    ----------
    a_over_R, c_over_R : ndarray or float
        Contact and adhesive-zone half-widths over the circumradius.
    F_over_Eh : ndarray or float
        Load per unit length over ``E h`` (compressive positive).
    R_over_h, sigma0_over_E, sides, corner_radius_over_R : ndarray or float
        The parameters, broadcast.
    facet_half_width_over_R : ndarray or float
        The flat half-width :math:`f = (1 - r_c/R)\sin(\pi/n)` of the facet.
    region : ndarray of str or str
        ``"inside-facet"`` (the contact on the flat, ``a < f``), ``"corner-pinned"`` (a
        sharp corner stops the adhesive zone, ``c = f``) or ``"whole-facet"`` (the contact
        covers the facet, ``a >= f``, onto the rounded corners).
    residual_separation : ndarray or float
        The logarithm of the separation at ``c`` over ``h`` (0 at the solution; 0 where a
        sharp corner pins the zone).
    converged : ndarray or bool
        The separation condition met to rounding.
    stable : ndarray or bool
        :math:`dF/da > 0`: stable under load control (where the load is flat to rounding,
        at vanishing widths: a free adhesive zone is not, one pinned at a corner is).
    """

    inputs: ClassVar[tuple[str, ...]] = INPUTS

    a_over_R: NDArray | float = field(metadata=SI("contact_half_width", "R", "m"))
    c_over_R: NDArray | float = field(metadata=SI("adhesive_zone_half_width", "R", "m"))
    F_over_Eh: NDArray | float = field(metadata=SI("load", "Eh", "N/m"))
    R_over_h: NDArray | float
    sigma0_over_E: NDArray | float
    sides: NDArray | int
    corner_radius_over_R: NDArray | float
    facet_half_width_over_R: NDArray | float
    region: NDArray | str
    residual_separation: NDArray | float
    converged: NDArray | bool
    stable: NDArray | bool


def check_geometry(sides: ArrayLike, corner_radius_over_R: ArrayLike) -> tuple[NDArray, NDArray]:
    """The checked number of sides (an integer >= 3) and corner radius over ``R`` in [0, 1]."""
    n = np.asarray(sides)
    if n.dtype.kind not in "iuf" or n.size == 0:
        raise ParameterError("sides", f"sides must be an integer >= 3, got {sides!r}")
    nf = n.astype(float)
    # at most 2**53 (the integers a float holds exactly; a polygon that fine is round)
    with np.errstate(invalid="ignore"):
        ok = np.isfinite(nf) & (nf == np.round(nf)) & (nf >= 3) & (nf <= 2.0**53)
    if not np.all(ok):
        bad = nf[~ok].reshape(-1)[0]
        raise ParameterError("sides", f"sides must be an integer >= 3 (at most 2**53), got {bad!r}")
    r = _domain.check("corner_radius_over_R", corner_radius_over_R)
    # a rounded corner at least 1e-12 R (a finer one is sharper than any atom, and its
    # parabola's loads leave the floating-point range): 0 is the sharp corner
    fine = (r > 0) & (r < ROUND_CORNER_MIN)
    if np.any(fine):
        raise ParameterError(
            "corner_radius_over_R",
            f"corner_radius_over_R must be 0 (a sharp corner) or in [{ROUND_CORNER_MIN:g}, 1], "
            f"got {float(r[fine].reshape(-1)[0])!r}",
        )
    return nf.astype(int), r


def _flat(*arrays):
    return [np.ascontiguousarray(v, dtype=float).reshape(-1) for v in arrays]


def checked(R_over_h, sigma0_over_E, sides, corner_radius_over_R, **first):
    """The parameters checked and broadcast with ``first`` (checked arrays, by name, first).

    Returns whether every input is a scalar, the points' shape and the flat float arrays,
    ``first``'s then ``rho, s, n, r``.
    """
    rho = _domain.check("R_over_h", R_over_h)
    s = _domain.check("sigma0_over_E", sigma0_over_E)
    n, r = check_geometry(sides, corner_radius_over_R)
    named = dict(first, R_over_h=rho, sigma0_over_E=s, sides=n, corner_radius_over_R=r)
    scalar = scalar_or_array(*named.values())
    arrays = broadcast(**named)
    return scalar, arrays[0].shape, *_flat(*arrays)


def regions(pinned, A, f):
    """The region of each contact: ``"corner-pinned"``, ``"inside-facet"`` or ``"whole-facet"``."""
    return np.where(pinned, "corner-pinned", np.where(A < f, "inside-facet", "whole-facet"))


def contact_result(
    shape, scalar, A, C, F, region, res, conv, stable, rho, s, n, r, f
) -> FacetContact:
    """The :class:`FacetContact` of flat arrays, in the points' ``shape``."""
    return as_result(
        FacetContact,
        scalar,
        shape,
        a_over_R=A,
        c_over_R=C,
        F_over_Eh=F,
        R_over_h=rho,
        sigma0_over_E=s,
        sides=n.astype(int),
        corner_radius_over_R=r,
        facet_half_width_over_R=f,
        region=region,
        residual_separation=res,
        converged=conv,
        stable=stable,
    )


def branch(A, f, r, rho, s, u0=None):
    """``u``, ``c/R``, ``F/(Eh)``, residual, converged, pinned at ``a/R`` (flat arrays).

    ``u0``: a starting ``u`` per point (a neighbour's on the branch), or None.
    """
    u = np.zeros(A.size)
    res = np.zeros(A.size)
    conv = np.ones(A.size, bool)
    pinned = np.zeros(A.size, bool)
    adh = s > 0
    if np.any(adh):
        u[adh], res[adh], conv[adh], pinned[adh] = _b.solve_u(
            A[adh], f[adh], r[adh], rho[adh], s[adh], None if u0 is None else u0[adh]
        )
    with np.errstate(over="ignore", invalid="ignore"):
        C = np.maximum(A * np.cosh(u), A)
        C = np.where(pinned, f, C)
        F = _b.load(A, u, f, r, rho, s)
    conv &= np.isfinite(F) & np.isfinite(C)
    return u, C, F, res, conv, pinned


def facet_contact(
    a_over_R: ArrayLike,
    R_over_h: ArrayLike,
    sigma0_over_E: ArrayLike,
    *,
    sides: ArrayLike = 6,
    corner_radius_over_R: ArrayLike = 0.0,
) -> FacetContact:
    r"""Adhesive-zone width and load of a faceted wire at given contact half-widths.

    Parameters
    ----------
    a_over_R : array_like
        Contact half-width over the circumradius ``R``, in ``[1e-12, 10]``; at most the
        facet's half-width for a sharp corner (``corner_radius_over_R = 0``).
    R_over_h : array_like
        Circumradius over the range of the adhesive stress, ``[1e-3, 1e12]``.
    sigma0_over_E : array_like
        Adhesive (Dugdale) stress over the composite modulus, ``[0, 1e6]`` (0: no adhesion).
    sides : array_like of int
        Number of sides of the cross-section, ``>= 3`` (6 a hexagon, 5 a pentagon).
    corner_radius_over_R : array_like
        Corner radius over the circumradius, ``[0, 1]`` (1 is the round wire of radius ``R``).

    Returns
    -------
    FacetContact
        The inputs broadcast together; scalars in, scalars out.

    Examples
    --------
    >>> import linecontact as lc
    >>> round_wire = lc.facet_contact(0.05, 100.0, 0.01, corner_radius_over_R=1.0)
    >>> abs(round_wire.F_over_Eh - lc.normal_contact(0.05, 100.0, 0.01).F_over_Eh) < 1e-12
    True
    """
    A = _domain.check("a_over_R", a_over_R, "facet_a_over_R")
    scalar, shape, Af, rhof, sf, nf, rf = checked(
        R_over_h, sigma0_over_E, sides, corner_radius_over_R, a_over_R=A
    )
    f = _b.facet_half_width(nf, rf)
    sharp_wide = (rf == 0) & (Af > f)
    if np.any(sharp_wide):
        _, at = first_point(sharp_wide, a_over_R=Af, sides=nf.astype(int), corner_radius_over_R=rf)
        raise ParameterError(
            "a_over_R",
            f"a_over_R must be at most the facet's half-width (1 - r_c/R) sin(pi/n) for a "
            f"sharp corner (corner_radius_over_R = 0): a contact wider than the facet needs "
            f"a rounded corner, got {point_text(at)}",
        )
    u, C, F, res, conv, pinned = branch(Af, f, rf, rhof, sf)
    huge = ~np.isfinite(F) & (Af > f)
    if np.any(huge):
        # the Hertz part rho (a^2 alpha - f S) / (2 r) of a contact over a corner of radius
        # r << 1e-100 R: a joint limit of a_over_R, R_over_h and corner_radius_over_R
        _, at = first_point(huge, a_over_R=Af, R_over_h=rhof, corner_radius_over_R=rf)
        raise ParameterError(
            "corner_radius_over_R",
            f"the load of a contact over a corner this sharp is beyond the floating-point "
            f"range at {point_text(at)}: take a wider corner or a contact on the facet",
        )
    if not conv.all():
        _, at = first_point(~conv, a_over_R=Af, R_over_h=rhof, sigma0_over_E=sf)
        raise ConvergenceError(f"facet_contact did not converge at {point_text(at)}")
    h = _STEP * Af
    hi = np.where((rf == 0) & (Af + h > f), Af, Af + h)  # stay on the facet at a sharp corner
    lo = Af - h
    Fh = branch(hi, f, rf, rhof, sf)[2]
    Fl = branch(lo, f, rf, rhof, sf)[2]
    # where the load is flat to rounding (a vanishing contact) a free adhesive zone peels
    # (unstable, as the round wire's narrowest states) and one pinned at a corner holds
    clear = np.abs(Fh - Fl) > 1e-12 * np.maximum(np.abs(F), 1e-300)
    stable = np.where(clear, Fh > Fl, pinned)
    region = regions(pinned, Af, f)
    return contact_result(shape, scalar, Af, C, F, region, res, conv, stable, rhof, sf, nf, rf, f)
