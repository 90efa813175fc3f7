"""The SI inputs' checks: plausible values, units slips, widths that are no widths."""

from __future__ import annotations

import contextlib
import warnings
from collections.abc import Iterator
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .. import closed_forms as _cf
from .. import domain as _domain
from .._validation import check_array
from ..errors import ModelValidityWarning, ParameterError, UnitsWarning
from ..materials import MAUGIS_STRENGTH

#: Plausible SI values: (low, high, unit, what a value outside suggests). A value outside
#: gives a :class:`~linecontact.errors.ModelValidityWarning` (it is still used): a radius
#: above 1 mm or below 0.1 nm, a modulus outside 1 kPa to 2 TPa, a work of adhesion above
#: 10 J/m^2, an adhesion range above 10 nm are most often a value in the wrong units.
PLAUSIBLE = {
    "radius": (1e-10, 1e-3, "m", "radius"),
    "modulus": (1e3, 2e12, "Pa", "modulus"),
    "work_of_adhesion": (0.0, 10.0, "J/m^2", "work of adhesion"),
    "adhesion_range": (0.0, 10e-9, "m", "adhesion range"),
}


#: A likely slip of units per input: (factor, unit) of the value as it was probably meant,
#: on the side of :data:`PLAUSIBLE` where that slip lands (nm given as m, GPa as Pa, ...).
_UNIT_SLIP = {
    "radius": ("above", 1e-9, "nm"),
    "modulus": ("below", 1e9, "GPa"),
    "work_of_adhesion": ("above", 1e-3, "mJ/m^2"),
    "adhesion_range": ("above", 1e-9, "nm"),
}

#: The narrowest contact half-width [m] that is a width at all (a femtometre, the size of a
#: nucleus): a result below it is round-off of zero width, or of inputs in the wrong units.
WIDTH_MIN = 1e-15

#: sigma0 = S w / z0 and h = z0 / S (the Maugis convention of :mod:`linecontact.materials`)
_S_LJ = MAUGIS_STRENGTH


def _implausible(name: str, value: ArrayLike, key: str | None = None) -> str | None:
    """The warning for the first value of ``name`` outside :data:`PLAUSIBLE` (None: none)."""
    key = key or name
    lo, hi, unit, what = PLAUSIBLE[key]
    if name != key and name.isidentifier():  # as the caller named it (equilibrium_spacing)
        what = name.replace("_", " ")
    v = np.asarray(value, float).reshape(-1)
    with np.errstate(invalid="ignore"):
        out = np.isfinite(v) & ~((v >= lo) & (v <= hi))
    if not np.any(out):
        return None
    x = float(v[np.flatnonzero(out)[0]])
    side = "above" if x > hi else "below"
    bound = hi if x > hi else lo
    hint = ""
    slip = _UNIT_SLIP.get(key)
    if slip is not None and slip[0] == side and lo <= x * slip[1] <= hi:
        hint = f"; {x:g} {slip[2]} is {x * slip[1]:g} {unit}"
    return (
        f"{name} = {x:g} {unit} is {side} {bound:g} {unit}: is the {what} in {unit}? "
        f"(linecontact takes SI units{hint})"
    )


def _plausible(name: str, value: ArrayLike, stacklevel: int = 3, key: str | None = None) -> None:
    """Warn (:class:`ModelValidityWarning`) for a value of ``name`` outside :data:`PLAUSIBLE`."""
    message = _implausible(name, value, key)
    if message is not None:
        warnings.warn(message, UnitsWarning, stacklevel=stacklevel)


def _first(bad: NDArray, *values: ArrayLike) -> list[float]:
    """The values at the first point where ``bad`` (broadcast together), as floats."""
    i = int(np.flatnonzero(np.reshape(bad, -1))[0])
    return [float(np.reshape(np.broadcast_to(v, np.shape(bad)), -1)[i]) for v in values]


def _normal_load(cylinder: Any, name: str, load: ArrayLike) -> tuple[NDArray, float]:
    """``(F, E h)``: the normal ``load`` [N/m] checked under the caller's ``name``, its unit.

    A load beyond the domain of ``F_over_Eh`` is refused in N/m, for this cylinder.
    """
    F = check_array(name, load, low=-np.inf, low_inclusive=True)
    Eh = cylinder.modulus * cylinder.adhesion_range
    _domain.check_si(name, F, Eh, "F_over_Eh", "N/m")
    return F, Eh


def _as_given(F: NDArray, like: ArrayLike) -> Any:
    """The load ``F`` as it was given (not back from ``F/(E h)``), in the shape of ``like``."""
    return F.item() if np.ndim(like) == 0 else np.broadcast_to(F, np.shape(like))


def _too_wide(name: str, Fi: float, e: Any, R: float) -> ValueError:
    """The error for the load ``name`` = ``Fi`` [N/m] whose contact is too wide (``e``).

    ``e`` is the :class:`~linecontact.domain.TooWideError` of the solver; ``R`` [m] the radius.
    """
    return ValueError(
        f"{name}={Fi!r} N/m needs a contact of half-width {e.a_over_R * R:.6g} m, "
        f"{e.a_over_R:.6g} radii: {e.limit}"
    )


def _which(default: str, *candidates: tuple[str, ArrayLike, str | None]) -> str:
    """The input that most likely has the wrong units: the first one outside PLAUSIBLE."""
    for name, value, key in candidates:
        if key is not None and _implausible(name, value, key) is not None:
            return name
    return default


def _check_cylinder_si(
    radius: ArrayLike,
    modulus: ArrayLike | None,
    adhesion: dict[str, ArrayLike | None],
    *,
    modulus_name: str = "modulus",
    stacklevel: int = 4,
) -> None:
    """Warn for implausible SI inputs, refuse those whose groups leave the solvers' domain.

    ``adhesion`` is ``{"work_of_adhesion": w, "equilibrium_spacing": z0}`` (``w`` may be
    None where it is unknown, as in an inversion), or ``{"cohesive_stress": sigma0,
    "adhesion_range": h}``, as the caller gave them: the messages name these, the radius
    and the modulus, and the ranges in SI units, never the nondimensional groups. Without
    the modulus (None) only the radius and the range are checked.
    """
    R = np.asarray(radius, float)
    E = np.asarray(np.nan if modulus is None else modulus, float)
    by_work = "equilibrium_spacing" in adhesion
    a_name, l_name = (
        ("work_of_adhesion", "equilibrium_spacing")
        if by_work
        else ("cohesive_stress", "adhesion_range")
    )
    a_val, l_val = adhesion[a_name], adhesion[l_name]
    length = np.asarray(l_val, float)
    conv = _S_LJ if by_work else 1.0  # R/h = conv R / length
    if a_val is None:
        stress = None
    elif by_work:
        with np.errstate(over="ignore", divide="ignore", invalid="ignore"):  # refused below
            stress = _S_LJ * np.asarray(a_val, float) / length  # sigma0 of (w, z0)
    else:
        stress = np.asarray(a_val, float)
    adhesive = stress is None or bool(np.any(stress > 0))
    # the warnings first: a value in the wrong units is said before what it breaks
    _plausible("radius", R, stacklevel)
    if modulus_name == "modulus":
        _plausible("modulus", E, stacklevel)
    if adhesive:  # without adhesion the range only sets a length scale
        _plausible(l_name, length, stacklevel, key="adhesion_range")
        if by_work and a_val is not None:
            _plausible("work_of_adhesion", a_val, stacklevel)
        elif stress is not None and _implausible(l_name, length, "adhesion_range") is None:
            # sigma0 h: said where the range is not already the suspect, as the product of
            # the inputs given (no work of adhesion was given)
            with np.errstate(over="ignore"):
                work = stress * length
            _plausible(f"{a_name} * {l_name}", work, stacklevel, key="work_of_adhesion")
    unit = {"work_of_adhesion": "J/m^2", "cohesive_stress": "Pa"}[a_name]
    cands_l = ((l_name, length, "adhesion_range"), ("radius", R, "radius"))
    # the ratio of the radius to the range
    lo, _, hi, _ = _domain.DOMAIN["R_over_h"]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        ratio = conv * R / length
    bad = ~((ratio >= lo) & (ratio <= hi))
    if np.any(bad):
        r, z = _first(bad, R, length)
        guess = _which(l_name, *cands_l)
        raise _refused(
            guess,
            modulus_name,
            f"radius / {l_name} must be in [{lo / conv:.3g}, {hi / conv:.3g}] (the domain of "
            f"the solvers), got radius={r!r} m, {l_name}={z!r} m; "
            f"{_units_question(guess, modulus_name, 'm')}",
        )
    if stress is None or modulus is None or a_val is None:
        return
    a_val = np.asarray(a_val, float)
    # the adhesive stress over the modulus
    s_hi = _domain.DOMAIN["sigma0_over_E"][2]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        s = stress / E
    bad = ~(s <= s_hi)
    m_key = "modulus" if modulus_name == "modulus" else None
    cands_s = (
        (modulus_name, E, m_key),
        (a_name, a_val if by_work else stress, "work_of_adhesion" if by_work else None),
        (l_name, length, "adhesion_range"),
    )
    if np.any(bad):
        sv, ev, av, zv = _first(bad, stress, E, a_val, length)
        guess = _which(modulus_name, *cands_s)
        what = (
            f"the adhesive stress 16 w/(9 sqrt(3) z0) = {sv:.3g} Pa of {a_name}={av!r} "
            f"J/m^2 and {l_name}={zv!r} m"
            if by_work
            else f"{a_name}={av!r} Pa"
        )
        raise _refused(
            guess,
            modulus_name,
            f"{what} must be at most {s_hi:g} times the {modulus_name.replace('_', ' ')}, "
            f"{s_hi * ev:.3g} Pa here, got {modulus_name}={ev!r} Pa (the domain of the "
            f"solvers); {_units_question(guess, modulus_name, unit)}",
        )
    # kappa = (4/pi) (sigma0/E) sqrt(2 R/h), the single group of the Maugis-Dugdale contact
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        kap = _cf._kappa(ratio, s)
    bad = ~(kap <= _cf.KAPPA_MAX)
    if np.any(bad):
        k, r, ev, av, zv = _first(bad, kap, R, E, a_val, length)
        guess = _which(modulus_name, *cands_s, ("radius", R, "radius"))
        raise _refused(
            guess,
            modulus_name,
            f"the adhesion of this cylinder is beyond the range of the solvers: kappa = "
            f"(4/pi) sigma0 sqrt(2 R) / (E sqrt(h)) = {k:.3g} must be at most "
            f"{_cf.KAPPA_MAX:g}, got radius={r!r} m, {modulus_name}={ev!r} Pa, {a_name}="
            f"{av!r} {unit}, {l_name}={zv!r} m; {_units_question(guess, modulus_name, unit)}",
        )


#: The SI inputs an error of :func:`_check_cylinder_si` may name (a ParameterError's name).
_SI_INPUTS = frozenset(
    {"radius", "modulus", "work_of_adhesion", "equilibrium_spacing", "cohesive_stress",
     "adhesion_range"}
)  # fmt: skip


def _refused(guess: str, modulus_name: str, message: str) -> ValueError:
    """The error for inputs outside the solvers' domain, naming the likeliest culprit.

    A ParameterError where that is one SI input (its field on a page, its flag), else a
    ValueError (the two moduli of a composite one, say).
    """
    for name in (guess, modulus_name):
        if name in _SI_INPUTS:
            return ParameterError(name, message)
    return ValueError(message)


def _units_question(guess: str, modulus_name: str, unit: str) -> str:
    """``is <input> in <unit>?`` for the input that most likely has the wrong units."""
    if guess == "composite modulus":
        return "are E1 and E2 in Pa?"
    the = "the " if "_" not in guess else ""  # a word (radius), or a parameter's name
    if guess == "radius" or guess.endswith(("range", "spacing")):
        return f"is {the}{guess} in metres?"
    return f"is {the}{guess} in {'Pa' if guess == modulus_name else unit}?"


#: The widest contact of the small-strain range, in radii (the half-plane theory's limit).
SMALL_STRAIN = _cf.A_OVER_R_SMALL_STRAIN


@contextlib.contextmanager
def _small_strain_in_si() -> Iterator[None]:
    """Silence the nondimensional solvers' small-strain note inside the SI layer.

    The note names their group (``a_over_R = 0.5 is beyond ...``); the SI layer says it of
    the widths it returns, in metres (:func:`_warn_small_strain`). Every other warning, and
    the caller's own filters for the SI note, are left as they are.
    """
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", r"a_over_R = .* small-strain range", ModelValidityWarning)
        yield


def _warn_small_strain(
    a: ArrayLike,
    radius: ArrayLike,
    what: str = "the contact half-width",
    stacklevel: int = 3,
    body: str = "cylinder",
) -> None:
    """Warn (ModelValidityWarning) for contact half-widths [m] beyond the small-strain range."""
    v, Rv = (np.reshape(x, -1) for x in np.broadcast_arrays(np.asarray(a, float), radius))
    with np.errstate(invalid="ignore"):
        wide = v > SMALL_STRAIN * Rv
    if np.any(wide):
        i = int(np.argmax(np.where(wide, v / Rv, -np.inf)))  # the widest, as the solvers say
        warnings.warn(
            f"{what} {float(v[i]):.3g} m is {float(v[i] / Rv[i]):.3g} times the radius, beyond "
            f"the small-strain range of the {'half-space' if body == 'sphere' else 'half-plane'} "
            f"theory (at most {SMALL_STRAIN:g} times "
            f"the radius, a strain of {SMALL_STRAIN / 2:g}): the results are those of linear "
            "elasticity",
            ModelValidityWarning,
            stacklevel=stacklevel,
        )


#: Why a zero-width pull-off reports a width below :data:`WIDTH_MIN` (then not warned for:
#: :func:`_warn_widths`).
_ZERO_WIDTH = (
    "the contact peels to zero width before it pulls off (mechanism 'zero-width'): read it as 0"
)


def _warn_widths(
    a: ArrayLike,
    radius: ArrayLike,
    what: str = "the contact half-width",
    why: str = "",
    stacklevel=3,
    body: str = "cylinder",
) -> None:
    """Warn for contact half-widths [m] that are no physical width: below WIDTH_MIN or above R.

    A width beyond the small-strain range (but within the radius) is said as a model note
    (:func:`_warn_small_strain`). ``why``: the mechanism that makes a width below
    WIDTH_MIN (a zero-width pull-off, :data:`_ZERO_WIDTH`): such a width is then the
    model's answer for valid inputs (its label says it), no sign of wrong units, and is
    not said.
    """
    v, Rv = (np.reshape(x, -1) for x in np.broadcast_arrays(np.asarray(a, float), radius))
    with np.errstate(invalid="ignore"):
        tiny = (v > 0) & (v < WIDTH_MIN)
        wide = v > Rv
    if not np.any(wide):
        _warn_small_strain(v, Rv, what, stacklevel + 1, body)
    if np.any(tiny) and not why:
        x = float(v[np.flatnonzero(tiny)[0]])
        warnings.warn(
            f"{what} {x:.3g} m is below {WIDTH_MIN:g} m, the size of a nucleus: it is no "
            "physical width (round-off of a zero width, or an input in the wrong units: "
            "linecontact takes SI units)",
            UnitsWarning,
            stacklevel=stacklevel,
        )
    if np.any(wide):
        i = np.flatnonzero(wide)[0]
        x = float(v[i])
        warnings.warn(
            f"{what} {x:.3g} m is above the radius {float(Rv[i]):g} m: the contact is wider than "
            f"the {body} (an input in the wrong units? linecontact takes SI units)",
            UnitsWarning,
            stacklevel=stacklevel,
        )
