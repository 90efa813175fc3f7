"""The validated domain of every input of the public API, in one table.

Inside its domain a function returns finite numbers that meet the accuracy the README
states, or a documented error (:class:`~linecontact.errors.NoEquilibriumError` for a state
that does not exist, :class:`~linecontact.errors.ConvergenceError` where a collocation
solver cannot reach its tolerance); outside it, a :class:`ValueError` names the parameter,
the value and the range. ``tests/test_fuzz.py`` checks both over the whole table, and the
README prints it.

Each entry is ``(low, low_inclusive, high, high_inclusive)``; the bounds are those of the
physics where it has some (``d/a`` in the stick-zone range, ``h1/h2`` where steady sliding is
verified) and otherwise generous ranges that keep every intermediate quantity within the
floating-point range (``R/h`` from 1e-3 to 1e12, ``a/R`` from 1e-150 to 10).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._validation import check_array, first_point

__all__ = ["DOMAIN", "SCALE_WORDS", "TooWideError", "check", "check_si", "check_widths", "scalar"]

#: name -> (low, low inclusive, high, high inclusive)
DOMAIN: dict[str, tuple[float, bool, float, bool]] = {
    # groups of the normal and sliding problems
    "R_over_h": (1e-3, True, 1e12, True),
    "R_over_h2": (1e-3, True, 1e12, True),
    "sigma0_over_E": (0.0, True, 1e6, True),
    "h1_over_h2": (1e-3, True, 1e3, True),
    "a_over_R": (1e-150, True, 10.0, True),
    "sliding_a_over_R": (1e-20, True, 10.0, True),  # the closed form of sliding converges
    "a_max_over_R": (1e-100, True, 10.0, True),  # the largest width of a load curve
    "F_over_Eh": (-1e12, True, 1e12, True),
    "F_over_Eh2": (-1e12, True, 1e12, True),
    "central_gap_over_h": (0.0, True, 1.0, True),
    # the faceted wire (linecontact.facet): widths over the circumradius, its corner radius
    "facet_a_over_R": (1e-12, True, 10.0, True),
    "corner_radius_over_R": (0.0, True, 1.0, True),
    "push_H_over_R": (0.0, False, 2.0, True),  # a push's height: up to the wire's top
    # the sphere (linecontact.sphere): its force [N] over E h R
    "F_over_EhR": (-1e12, True, 1e12, True),
    "F_max_over_piwR": (0.0, True, 10.0, True),  # the Lennard-Jones sphere's curve end [pi w R]
    "central_gap_over_z0": (0.01, True, 1e6, True),  # the Lennard-Jones law on a rigid cylinder
    # w sqrt(R/z0)/(E z0), the group of the Lennard-Jones law: its curves, states and contacts
    # are solved self-consistently up to lennard_jones._limit.MU_SELF_CONSISTENT; its pull-off
    # at every mu (beyond, the corrected JKR limit)
    "lj_mu": (0.0, True, 400.0, True),
    "lj_mu_pull_off": (0.0, True, np.inf, False),
    # tangential problems
    "tau0_over_E": (1e-12, True, 1.0, True),
    "friction_tau0_over_E": (0.0, True, 1.0, True),  # the optional shear strength of sliding
    "T_over_Ea": (0.0, True, 1e12, True),
    "mu": (1e-6, True, 100.0, True),
    "T_over_muF": (0.0, True, 1e12, True),
    # the material constants (Pa) and the adhesion in SI units
    "E1": (1e-30, True, 1e30, True),
    "E2": (1e-30, True, 1e30, True),
    "work_of_adhesion": (1e-100, True, 1e100, True),
    "equilibrium_spacing": (1e-100, True, 1e100, True),
}


def check(name: str, value: ArrayLike, key: str | None = None) -> NDArray:
    """``value`` as a float array, refused with a ValueError outside the domain of ``key``.

    ``key`` defaults to ``name`` (the parameter as the caller's signature calls it).
    """
    low, lo_inc, high, hi_inc = DOMAIN[key or name]
    return check_array(name, value, low=low, low_inclusive=lo_inc, high=high, high_inclusive=hi_inc)


def scalar(name: str, value: ArrayLike, key: str | None = None) -> float:
    """A single number inside the domain of ``key`` (default ``name``), as a Python float."""
    arr = check(name, value, key)
    if arr.ndim != 0:
        raise ValueError(f"{name} must be a single number, got an array of shape {arr.shape}")
    return float(arr)


class TooWideError(ValueError):
    """A load whose contact half-width lies outside the domain of ``a/R`` of the solvers.

    Mostly a contact wider than ``a/R = 10``; for steady sliding also one narrower than
    ``a/R = 1e-20``. ``index``, ``a_over_R`` and ``limit`` (``"beyond the domain of the
    solvers (at most 10 radii)"``) say which point, how wide and which bound, in words that
    name no group, so that the SI layer can say it in its own units.
    """

    def __init__(self, message: str, index: int, a_over_R: float, limit: str = "") -> None:
        super().__init__(message)
        self.index = index
        self.a_over_R = a_over_R
        self.limit = limit


def check_widths(A, F, F_name: str, key: str = "a_over_R", narrow: bool = False) -> None:
    """Refuse the loads whose contact half-width lies outside the domain of ``key``.

    Wider than its upper end always; narrower than its lower end with ``narrow`` (where the
    state at the width is then computed by a solver validated only down to that end). The
    message says the width in radii (``12.5 radii``, ``at most 10 radii``).
    """
    a_min, _, a_max, _ = DOMAIN[key]
    with np.errstate(invalid="ignore"):
        over = np.asarray(A > a_max)
        under = np.asarray(A < a_min) if narrow else np.zeros_like(over)
    for bad, limit in (
        (over, f"beyond the domain of the solvers (at most {a_max:g} radii)"),
        (under, f"below the domain of the solvers (at least {a_min:g} radii)"),
    ):
        if np.any(bad):
            i, at = first_point(bad, F=F, A=A)
            Fi, Ai = at["F"], at["A"]
            width = f"{Ai:.6g} radii" if Ai > 0 else f"below {a_min:g} radii"
            raise TooWideError(
                f"{F_name}={Fi!r} needs a contact of half-width {width}, {limit}",
                i,
                Ai,
                limit,
            )


#: What the unit of each group is, in words (:func:`check_si`): the SI range of a value is
#: the group's range times this. No group is named: the message is for SI inputs.
SCALE_WORDS: dict[str, str] = {
    "a_over_R": "radii",
    "sliding_a_over_R": "radii",
    "a_max_over_R": "radii",
    "F_over_Eh": "times the modulus times the adhesion range",
    "F_over_Eh2": "times the modulus times the adhesion range",
    "F_over_EhR": "times the modulus times the adhesion range times the radius",
    "F_max_over_piwR": "times pi w R",
    "tau0_over_E": "times the modulus",
    "friction_tau0_over_E": "times the modulus",
    "T_over_Ea": "times the modulus times the contact half-width",
    "T_over_muF": "times the friction coefficient times the normal load",
    "h1_over_h2": "times the adhesion range",
}


def check_si(
    name: str,
    value: ArrayLike,
    unit_value: ArrayLike,
    key: str,
    unit: str,
    scale: str | None = None,
) -> None:
    """Refuse SI values whose group ``value/unit_value`` lies outside the domain of ``key``.

    The message names the SI parameter ``name`` and its range in SI units at that point,
    and says the range relative to the other inputs in words (:data:`SCALE_WORDS`, or
    ``scale``), never the group: ``contact_half_width must be in [5e-158, 5e-07] m (1e-150
    to 10 radii, the domain of the solvers), got 1e-06``.

    Parameters
    ----------
    name : str
        The parameter (or flag) as the caller knows it.
    value, unit_value : array_like
        The SI values and the unit of the group at each (broadcast together).
    key : str
        The entry of :data:`DOMAIN`.
    unit : str
        The SI unit of ``value`` (``"m"``, ``"N/m"``, ``"Pa"``).
    scale : str, optional
        What ``unit_value`` is, in words (default: :data:`SCALE_WORDS` of ``key``).
    """
    v, u = np.broadcast_arrays(np.asarray(value, float), np.asarray(unit_value, float))
    low, lo_inc, high, hi_inc = DOMAIN[key]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore", under="ignore"):
        g = v / u
    bad = ~((g >= low if lo_inc else g > low) & (g <= high if hi_inc else g < high))
    if np.any(bad):
        _, at = first_point(bad, v=v, u=u)
        ui = at["u"]
        lo_br, hi_br = "[" if lo_inc else "(", "]" if hi_inc else ")"
        words = SCALE_WORDS[key] if scale is None else scale
        raise ValueError(
            f"{name} must be in {lo_br}{low * ui:.6g}, {high * ui:.6g}{hi_br} {unit} ({low:g} "
            f"to {high:g} {words}, the domain of the solvers), got {at['v']!r}"
        )
