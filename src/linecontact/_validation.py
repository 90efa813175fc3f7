"""Input checks at the public boundary: every message names the parameter and its range.

A refused value raises :class:`~linecontact.errors.ParameterError` (a ``ValueError``) that
carries the parameter's name as the caller gave it: each shell says it in its spelling.
"""

from __future__ import annotations

import math
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .errors import ParameterError


def _first_bad(arr: NDArray, bad: NDArray) -> object:
    v = arr[bad].flat[0]
    return float(v)


def _real_array(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """``value`` as a float array; bools, strings, complex numbers and None are refused.

    ``np.asarray(value, dtype=float)`` alone would read ``True`` as 1, ``"0.5"`` as 0.5,
    ``None`` as nan and drop the imaginary part of a complex number.
    """
    # the common cases first, at no cost: a Python float, an array of floats
    if value.__class__ is float:
        return np.asarray(value)
    if value.__class__ is np.ndarray and value.dtype == np.float64:
        return value
    if value is None or isinstance(value, (bool, np.bool_, str, bytes)):
        raise ParameterError(name, _not_real(name, value))
    if isinstance(value, np.ma.MaskedArray):  # np.asarray would drop the mask silently
        raise ParameterError(
            name,
            f"{name} is a masked array: masked arrays are not supported: fill or compress "
            "them first (numpy.ma.filled, numpy.ma.compressed)",
        )
    try:
        raw = np.asarray(value)
    except (TypeError, ValueError):  # ragged nested sequences
        raise ParameterError(name, _not_real(name, value)) from None
    if raw.dtype.kind not in "iuf":
        # object arrays of plain numbers (e.g. [1, 2.5] of mixed Python types) are fine
        if raw.dtype.kind != "O" or not all(
            isinstance(v, (int, float, np.integer, np.floating))
            and not isinstance(v, (bool, np.bool_))
            for v in raw.flat
        ):
            raise ParameterError(name, _not_real(name, value))
    try:
        return np.asarray(raw, dtype=float)
    except OverflowError:  # a Python integer beyond the float range (10**400)
        raise ParameterError(
            name,
            f"{name} must be a real number within the floating-point range, got an integer "
            "beyond it",
        ) from None


def _not_real(name: str, value: object) -> str:
    """The message for a value that is not real (built only when it is raised)."""
    return f"{name} must be a real number or an array of them, got {value!r}"


def _in_range(
    arr: NDArray,
    low: float,
    low_inclusive: bool,
    high: float,
    high_inclusive: bool,
    allow_inf: bool,
) -> bool:
    """True when ``arr`` is non-empty and certainly passes every check of :func:`check_array`.

    The smallest and the largest value decide (nan propagates through both and fails every
    comparison); a scalar is read as a Python float. False sends the caller to the detailed
    checks, which name the first offending value.
    """
    if arr.ndim == 0:
        lo = hi = float(arr)
    elif arr.size:
        lo, hi = float(arr.min()), float(arr.max())
    else:
        return False
    return (
        (lo >= low if low_inclusive else lo > low)
        and (hi <= high if high_inclusive else hi < high)
        and (allow_inf or (math.isfinite(lo) and math.isfinite(hi)))
    )


def check_array(
    name: str,
    value: ArrayLike,
    *,
    low: float = 0.0,
    low_inclusive: bool = False,
    high: float = np.inf,
    high_inclusive: bool = False,
    allow_inf: bool = False,
) -> NDArray[np.float64]:
    """Return ``value`` as a float array after checking that it lies in the stated range.

    Raises
    ------
    ValueError
        Naming ``name``, the valid range and the first offending value.
    """
    arr = _real_array(name, value)
    if _in_range(arr, low, low_inclusive, high, high_inclusive, allow_inf):
        return arr
    # something is wrong (or the array is empty): find what, and say it
    lo_br = "[" if low_inclusive else "("
    hi_br = "]" if high_inclusive else ")"
    hi_txt = "inf" if np.isinf(high) else f"{high:g}"
    rng = f"{lo_br}{low:g}, {hi_txt}{hi_br}"
    # "a finite number in (-inf, inf)" says no more than "a finite number"
    in_rng = "" if np.isinf(low) and np.isinf(high) else f" in {rng}"
    if arr.size == 0:
        raise ParameterError(name, f"{name} must not be empty")
    nan = np.isnan(arr)
    if nan.any():
        raise ParameterError(name, f"{name} must be a finite number{in_rng}, got nan")
    if not allow_inf and np.isinf(arr).any():
        raise ParameterError(
            name, f"{name} must be a finite number{in_rng}, got {_first_bad(arr, np.isinf(arr))}"
        )
    too_low = arr < low if low_inclusive else arr <= low
    too_high = arr > high if high_inclusive else arr >= high
    if np.isinf(high) and allow_inf:
        too_high = np.zeros_like(too_low)
    bad = too_low | too_high
    if bad.any():
        raise ParameterError(name, f"{name} must be in {rng}, got {_first_bad(arr, bad)}")
    return arr


def positions(name: str, value: ArrayLike, points_shape: tuple) -> NDArray[np.float64]:
    """Finite positions for the distribution methods of a result with ``points_shape``.

    The results have shape ``points_shape + (m,)``: ``value`` is one position (``m = 1``),
    ``m`` of them, or an array broadcasting to ``points_shape + (m,)`` (one row per point).
    """
    x = np.atleast_1d(check_array(name, value, low=-np.inf, low_inclusive=True))
    want = tuple(points_shape) + x.shape[-1:]
    try:
        ok = x.ndim <= len(want) and np.broadcast_shapes(want, x.shape) == want
    except ValueError:
        ok = False
    if not ok:
        raise ParameterError(
            name,
            f"{name} must have shape (m,) or broadcast to the points' shape plus "
            f"one axis, {want}, got shape {x.shape}",
        )
    return x


def scalar(name: str, value: ArrayLike, **limits) -> float:
    """A single number checked as by :func:`check_array` (same keywords), as a Python float.

    For the functions that take scalar parameters only; an array gets a plain message
    instead of ``TypeError: only 0-dimensional arrays can be converted to Python scalars``.
    """
    arr = check_array(name, value, **limits)
    if arr.ndim != 0:
        raise ParameterError(
            name, f"{name} must be a single number, got an array of shape {arr.shape}"
        )
    return float(arr)


def positive(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """Finite and strictly positive."""
    return check_array(name, value)


def non_negative(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """Finite and >= 0."""
    return check_array(name, value, low_inclusive=True)


def finite(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """Any finite real number."""
    return check_array(name, value, low=-np.inf, low_inclusive=True)


def broadcast(**named: NDArray) -> list[NDArray]:
    """``np.broadcast_arrays`` of the named inputs; shapes that do not broadcast are named.

    NumPy's own message ("shape mismatch: ... arg 0 with shape (3,) and arg 1 ...") does
    not say which parameters disagree.
    """
    arrays = [np.asarray(v) for v in named.values()]
    shape = arrays[0].shape
    if all(a.shape == shape for a in arrays):  # nothing to broadcast (scalar calls)
        return arrays
    try:
        return list(np.broadcast_arrays(*arrays))
    except ValueError:
        shapes = ", ".join(
            f"{k} has shape {np.shape(v)}" for k, v in named.items() if np.ndim(v) > 0
        )
        raise ValueError(f"the array arguments must broadcast together: {shapes}") from None


def first_point(bad: ArrayLike, **named: ArrayLike) -> tuple[int, dict[str, float]]:
    """The first point where ``bad`` holds, and the named inputs' values at it.

    ``bad`` and the named inputs are broadcast to their common shape first, so that an
    input that was broadcast (a scalar, a row, a column) gives its value at that point:
    indexing each input with the flat index of ``bad`` would miss it, or raise
    ``IndexError``, where an input has fewer elements than the points.

    Parameters
    ----------
    bad : array_like of bool
        Where the points fail; it must hold somewhere.
    **named : array_like
        The inputs to report, under the names the caller used.

    Returns
    -------
    i : int
        The flat (C-order) index of the first failing point in the common shape, for the
        flat arrays of the points' diagnostics.
    values : dict
        ``name -> float`` at that point, in the order given.
    """
    b = np.asarray(bad, dtype=bool)
    arrays = [np.asarray(v) for v in named.values()]
    shape = np.broadcast_shapes(b.shape, *(a.shape for a in arrays))
    i = int(np.argmax(np.broadcast_to(b, shape).reshape(-1)))
    at = np.unravel_index(i, shape)
    values = {k: float(np.broadcast_to(a, shape)[at]) for k, a in zip(named, arrays, strict=True)}
    return i, values


def point_text(values: dict[str, float]) -> str:
    """``values`` of :func:`first_point` as ``"name=value, ..."`` (each value by ``repr``)."""
    return ", ".join(f"{k}={v!r}" for k, v in values.items())


def check_solver_options(n: object, tol: object, *, n_max: int) -> None:
    """The collocation options shared by the solvers: ``n`` and ``tol``.

    ``tol`` may be any real number type (a ``numpy.float32`` was refused as out of range).
    The failure policy is checked by :func:`failure_policy`.
    """
    if not (
        isinstance(n, str)
        and n == "auto"
        or (isinstance(n, (int, np.integer)) and not isinstance(n, bool) and 2 <= n <= n_max)
    ):
        raise ValueError(f"n must be 'auto' or an integer in [2, {n_max}], got {n!r}")
    if not (
        isinstance(tol, (int, float, np.integer, np.floating))
        and not isinstance(tol, (bool, np.bool_))
        and 1e-15 <= tol < 1e-2
    ):
        raise ValueError(f"tol must be in [1e-15, 1e-2), got {tol!r}")


# --------------------------------------------------------------------------------------------
# the failure policy: one keyword, on_failure

#: The values of ``on_failure``.
FailurePolicy = Literal["raise", "report"]


def failure_policy(on_failure: object) -> FailurePolicy:
    """The checked value of ``on_failure``.

    Parameters
    ----------
    on_failure : object
        The caller's ``on_failure`` (``"raise"`` by default everywhere).

    Returns
    -------
    {"raise", "report"}

    Raises
    ------
    ValueError
        For a value outside ``{"raise", "report"}``.
    """
    if not (isinstance(on_failure, str) and on_failure in ("raise", "report")):
        raise ValueError(f"on_failure must be 'raise' or 'report', got {on_failure!r}")
    return "raise" if on_failure == "raise" else "report"


def scalar_or_array(*arrays: NDArray) -> bool:
    """True when every input is 0-d (results are then returned as scalars)."""
    return all(np.ndim(a) == 0 for a in arrays)


def out(value: NDArray, scalar: bool):
    """Return a Python float (or bool/int) for scalar calls, the array otherwise."""
    if scalar:
        return value.item() if isinstance(value, (np.ndarray, np.generic)) else value
    return value
