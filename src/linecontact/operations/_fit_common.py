"""The checks, the modulus and the tables shared by ``fit-adhesion`` and ``fit-friction``.

Beside :mod:`linecontact.operations.fit` (the declarations and ``fit-adhesion``);
``fit-friction`` is in :mod:`linecontact.operations._fit_friction`.
"""

from __future__ import annotations

import math
import os
from typing import Any

import numpy as np

from ..errors import ParameterError
from ..measurements import read_measurements
from ..output import Table
from ._common import cylinder as _cylinder
from ._common import positive, si_parameters


def _sd(text: str) -> tuple[float, bool]:
    """A standard uncertainty: a number, or a percentage of the value (``5%``)."""
    t = text.strip()
    rel = t.endswith("%")
    body = t[:-1] if rel else t
    if "%" in body or "_" in body:
        raise ValueError(text)
    v = float(body)
    return (v / 100 if rel else v), rel


# --------------------------------------------------------------------------------------------
# the modulus


def _check_common(args: Any) -> None:
    """--samples, --seed and --plot, before any work."""
    if not 10 <= args.samples <= 1_000_000:
        raise ParameterError(
            "--samples", f"--samples must be an integer in [10, 1000000], got {args.samples}"
        )
    if args.seed < 0:
        raise ParameterError("--seed", f"--seed must be an integer >= 0, got {args.seed}")
    if args.plot:
        parent = os.path.dirname(os.path.abspath(args.plot))
        if not os.path.isdir(parent):
            raise ParameterError(
                "--plot", f"--plot {args.plot!r}: the directory {parent!r} does not exist"
            )


def _modulus(args: Any) -> tuple[float, dict[str, Any]]:
    """The composite modulus [Pa] from --modulus, the moduli or the presets, and its record."""
    if args.modulus is not None:
        if any(getattr(args, k) is not None for k in ("E1", "nu1", "E2", "nu2")) or (
            args.cylinder_material or args.substrate_material
        ):
            raise ParameterError(
                "--modulus",
                "give either --modulus or the materials (--E1 ... or presets), not both",
            )
        positive("--modulus", args.modulus)
        return args.modulus, {"modulus_Pa": args.modulus}
    # the SI layer's reader of the materials and presets (a radius and a range of its own,
    # unused: the radius given is checked where it is used, with the adhesion given)
    ns = args.replace(radius=1e-7, h=1e-9, sigma0=None, work_of_adhesion=None, z0=None, length=None)
    cyl = _cylinder(ns)
    # the moduli as used, with the presets' names and sources (a preset never hides them)
    keep = ("modulus_Pa", "E1_Pa", "nu1", "E2_Pa", "nu2", "dundurs_beta")
    rec = {
        k: v
        for k, v in si_parameters(ns, cyl).items()
        if k in keep or k.endswith(("_material", "_source"))
    }
    return cyl.modulus, rec


def _read(args: Any, kind: Any) -> dict[str, np.ndarray]:
    """The measurements of ``--data`` (:func:`linecontact.measurements.read_measurements`).

    A file that cannot be read or is refused is the fault of ``--data`` (the message names
    the file, the row and the column); a bad ``--length`` names itself.
    """
    try:
        return read_measurements(
            args.data,
            kind,
            length=args.length,
            source=f"--data {args.data!r}",
            length_name="--length",
        )
    except ParameterError:
        raise
    except ValueError as exc:
        raise ParameterError("--data", str(exc)) from None


def _one_sd(args, name: str, value: float | None) -> float:
    text = getattr(args, name + "_sd", None)
    if text is None:
        return 0.0
    flag = "--" + name.replace("_", "-") + "-sd"
    try:
        v, rel = _sd(text)
    except ValueError:
        raise ParameterError(
            flag, f"{flag} must be a number or a percentage (5%), got {text!r}"
        ) from None
    if not (math.isfinite(v) and v >= 0):
        raise ParameterError(flag, f"{flag} must be finite and >= 0, got {text!r}")
    if value is None:
        raise ParameterError(flag, f"{flag} needs --{name.replace('_', '-')}")
    if not math.isfinite(value):  # the value's fault, not its uncertainty's
        option = f"--{name.replace('_', '-')}"
        raise ParameterError(option, f"{option} must be a finite number, got {value!r}")
    sd = abs(value) * v if rel else v
    # the Monte Carlo draws around the value: an uncertainty as large as the value itself
    # draws as many non-physical values as physical ones (and 1e300 overflows)
    if not sd <= abs(value):
        raise ParameterError(
            flag,
            f"{flag} must be at most the value itself ({abs(value)!r}, 100%): a larger standard "
            f"uncertainty leaves no physical value to draw, got {text!r}",
        )
    return sd


def _record(result: Any, keys: tuple[tuple[str, str], ...]) -> dict[str, Any]:
    """The fields (and derived properties) of a fit's result under their JSON keys."""
    d = {**result.to_dict(), **{k: getattr(result, k) for k in type(result).derived}}
    return {key: list(d[k]) if isinstance(d[k], tuple) else d[k] for k, key in keys}


#: The JSON keys of an AdhesionFit's fields, in the output's order.
_FIT = (
    ("work_of_adhesion", "work_of_adhesion"),
    ("work_of_adhesion_sd", "work_of_adhesion_sd"),
    ("work_of_adhesion_ci95", "work_of_adhesion_ci95"),
    ("work_of_adhesion_ci95_linear", "work_of_adhesion_ci95_linear"),
    ("equilibrium_spacing", "z0"),
    ("equilibrium_spacing_sd", "z0_sd"),
    ("equilibrium_spacing_ci95", "z0_ci95"),
    ("equilibrium_spacing_ci95_linear", "z0_ci95_linear"),
    ("correlation", "correlation"),
    ("covariance", "covariance"),
    ("identifiable", "identifiable"),
    ("note", "note"),
    ("chi2", "chi2"),
    ("dof", "dof"),
)
_FIT_INPUTS_SD = (
    ("work_of_adhesion_sd_inputs", "work_of_adhesion_sd_inputs"),
    ("equilibrium_spacing_sd_inputs", "z0_sd_inputs"),
    ("work_of_adhesion_sd_total", "work_of_adhesion_sd_total"),
    ("equilibrium_spacing_sd_total", "z0_sd_total"),
)
_FIT_DATA = (("model", "model_N_per_m"), ("residuals", "residuals_N_per_m"))
#: An Estimate's fields, ``{}`` the quantity's JSON name.
_ESTIMATE = (
    ("value", "{}"),
    ("sd", "{}_sd"),
    ("ci95", "{}_ci95"),
    ("sd_linear", "{}_sd_linear"),
    ("ci95_linear", "{}_ci95_linear"),
)


#: What a fit of one measurement with no standard uncertainty given says of its uncertainty.
EXACT = "exact (one measurement, no uncertainty given)"


class _Interval(list):
    """A 95 % interval ``[lo, hi]``: the table prints it at six digits, JSON and CSV in full."""

    def __str__(self) -> str:
        return "[" + ", ".join("-" if x is None else f"{x:.6g}" for x in self) + "]"


def _table(
    args,
    record: dict[str, Any],
    params: dict[str, Any],
    title: str,
    units,
    hide: tuple[str, ...] = (),
) -> Table:
    """One record as a table: its numbers and its 95 % intervals shown (not those in ``hide``).

    The per-point lists and the linearised intervals are in the JSON and CSV only.
    """
    cols = {}
    show = []
    for k, v in record.items():
        if isinstance(v, (list, tuple, np.ndarray)):
            arr = np.empty(1, dtype=object)
            items = [
                None if (isinstance(x, float) and not math.isfinite(x)) else x
                for x in np.asarray(v, dtype=object).tolist()
            ]
            interval = "_ci95" in k and "linear" not in k and "per_point" not in k
            arr[0] = _Interval(items) if interval else items
            cols[k] = arr
            if interval and k not in hide:
                show.append(k)
        else:
            cols[k] = np.asarray([v])
            if k not in hide:
                show.append(k)
    return Table(cols, params, units, args.command_line(), title, show=tuple(show))


def _uncertainty(given: list[str], samples: int) -> str:
    """Where the uncertainty of one measurement comes from: the sds ``given`` (flags), or none."""
    if not given:
        return EXACT
    return f"propagated from {', '.join(given)} (Monte Carlo, {samples} samples)"
