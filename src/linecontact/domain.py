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

from ._validation import check_array

__all__ = ["DOMAIN", "check", "check_widths", "scalar"]

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


def check_widths(A, F, F_name: str) -> None:
    """Refuse the loads whose contact is wider than the domain of ``a/R`` allows."""
    a_max = DOMAIN["a_over_R"][2]
    over = np.asarray(A > a_max)
    if np.any(over):
        i = int(np.flatnonzero(over.reshape(-1))[0])
        Fi = float(np.reshape(np.broadcast_to(F, over.shape), -1)[i])
        Ai = float(np.reshape(A, -1)[i])
        raise ValueError(
            f"{F_name}={Fi!r} needs a contact of half-width a_over_R = {Ai:.6g}, beyond the "
            f"domain of the solvers (a_over_R <= {a_max:g})"
        )
