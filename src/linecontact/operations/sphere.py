"""The sphere's computations of ``normal``, ``pulloff`` and ``curve`` (``--body sphere``).

The same operations as the wire's (their declarations are :mod:`.normal`'s, with
``--body``), on the Maugis--Dugdale sphere (:mod:`linecontact.sphere`; in SI units
:class:`~linecontact.Sphere`, forces in N): the groups ``--R-over-h``, ``--sigma0-over-E``
or the SI inputs; the loads of ``normal`` as ``--F-over-EhR`` or ``--force`` [N] (a wire's
``--F-over-Eh``, ``--load`` [N/m] are refused). The records' SI keys state the newton:
``F_pulloff_N``, ``F_N``, with ``a_m`` the contact radius and ``delta_m`` the approach.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..closed_forms.sphere import sphere_tabor_parameter
from ..domain import check_si
from ..errors import ParameterError
from ..output import Table
from ..sphere import sphere_contact, sphere_contact_for_load, sphere_load_curve, sphere_pull_off
from ..sphere.contact import checked
from ._common import half_widths, si_parameters
from ._declare import Inputs
from ._records import records, si_shown
from ._written import made

#: The records' key of each SI field of the sphere's pull-off, contact and curve.
PULL_OFF_KEYS = {
    "pull_off_force": "F_pulloff_N",
    "contact_radius_at_pull_off": "a_at_pulloff_m",
    "adhesive_zone_radius_at_pull_off": "c_at_pulloff_m",
    "approach_at_pull_off": "delta_at_pulloff_m",
}
CONTACT_KEYS = {
    "contact_radius": "a_m",
    "adhesive_zone_radius": "c_m",
    "load": "F_N",
    "approach": "delta_m",
}
LJ_CURVE_KEYS = {
    "load": "F_N",
    "load_error": "F_error_N",
    "approach": "delta_m",
    "central_gap": "central_gap_m",
    "contact_radius": "a_m",
}


def _parameters(args: Inputs, rho: float, s: float, body: Any) -> dict[str, Any]:
    # the Maugis parameter is each result's own field (a record's, per point)
    params: dict[str, Any] = {"body": "sphere", "R_over_h": rho, "sigma0_over_E": s}
    if body is not None:
        params.update(si_parameters(args, body))
    return params


def _table(
    args: Inputs,
    result: Any,
    si: Any,
    keys: dict[str, str],
    shown: list[str],
    where: tuple[float, float, Any],
    title: str,
    show: list[str],
    *,
    whole: dict[str, Any] | None = None,
    **how: Any,
) -> Table:
    """The records of a sphere's ``result``, its SI columns ``keys`` (``shown``) with ``si``.

    ``whole``: numbers of the whole result, written among the parameters.
    """
    extra: dict[str, Any] = {}
    if si is not None:
        cols, more = si_shown(args, si, keys, {}, shown)
        extra.update(cols)
        show = [*show, *more]
    params = {**_parameters(args, *where), **(whole or {})}
    return records(args, result, params, extra, title, show, **how)


def pulloff(args: Inputs, rho: float, s: float, body: Any) -> Table:
    """``pulloff --body sphere``: the load-controlled pull-off, in N with SI inputs."""
    if args.law == "lennard-jones":
        return _pulloff_lj(args, rho, s, body)
    si = None if body is None else made(args, "result", body.pull_off)
    p = sphere_pull_off(rho, s) if si is None else si.nondimensional
    return _table(
        args,
        p,
        si,
        PULL_OFF_KEYS,
        ["F_pulloff_N", "a_at_pulloff_m"],
        (rho, s, body),
        "pull-off of a sphere under load control (Maugis-Dugdale; F/(pi w R): -2 DMT, -1.5 JKR)",
        ["F_pulloff_over_EhR", "F_pulloff_over_piwR", "a_over_R_at_pulloff", "mechanism"],
        drop=("control",),
    )


def _lj_tabor_parameter(rho: float, s: float) -> float:
    """Tabor's parameter of a Lennard-Jones sphere, its groups checked as the Dugdale law's."""
    checked(R_over_h=rho, sigma0_over_E=s)
    if s <= 0:
        raise ParameterError(
            "--sigma0-over-E", "the Lennard-Jones law needs adhesion: --sigma0-over-E > 0"
        )
    return float(sphere_tabor_parameter(rho, s))


def _pulloff_lj(args: Inputs, rho: float, s: float, body: Any) -> Table:
    """The Lennard-Jones sphere's pull-off (self-consistent up to Tabor's parameter 50)."""
    from ..sphere import lennard_jones as _lj

    mu = _lj_tabor_parameter(rho, s)
    si = None if body is None else made(args, "result", body.pull_off)
    p = _lj.sphere_lj_pull_off(mu) if si is None else si.nondimensional
    return _table(
        args,
        p,
        si,
        PULL_OFF_KEYS,
        ["F_pulloff_N"],
        (rho, s, body),
        "pull-off of a sphere under the Lennard-Jones law (self-consistent to Tabor's "
        f"parameter {_lj.MU_SELF_CONSISTENT:g}, Greenwood 1997, beyond it the JKR limit "
        "corrected; load control; F/(pi w R): -2 rigid, -1.5 JKR)",
        ["F_pulloff_over_piwR", "error_estimate", "maugis_parameter", "method"],
        drop=("F_coarse", "F_fine", "converged"),
    )


def _curve_lj(args: Inputs, rho: float, s: float, body: Any) -> Table:
    """The Lennard-Jones sphere's curve, through its S-shape, to the load ``pi w R``."""
    from ..sphere import lennard_jones as _lj

    for name, flag in (
        ("a_max", "--a-max"),
        ("a_max_over_R", "--a-max-over-R"),
        ("num", "--num"),
        ("num_noncontact", "--num-noncontact"),
    ):
        if args.get(name) is not None:
            raise ParameterError(
                flag,
                f"{flag} is the Dugdale curve's: the Lennard-Jones sphere's curve ends at the "
                "load pi w R, its points where its states fall",
            )
    mu = _lj_tabor_parameter(rho, s)
    if mu > _lj.MU_SELF_CONSISTENT:
        q = _lj.MU_SELF_CONSISTENT / mu  # Tabor's parameter goes as R^(1/3) (sigma0/E)^(2/3)
        other = (
            f"--sigma0-over-E below {s * q**1.5:.3g}, or --R-over-h below {rho * q**3:.3g}"
            if body is None
            else f"a --radius below {q**3:.3g} times this one"
        )
        raise ParameterError(
            "--law",
            f"--law lennard-jones: Tabor's parameter (R w^2/(E^2 z0^3))^(1/3) of this sphere "
            f"is {mu:.4g}, over {_lj.MU_SELF_CONSISTENT:g}, the largest the Lennard-Jones "
            "sphere's curve is solved for (its pull-off is given at every value): use --law "
            f"dugdale, or {other}",
        )
    si = None if body is None else made(args, "result", body.load_curve)
    c = _lj.sphere_lj_curve(mu) if si is None else si.nondimensional
    return _table(
        args,
        c,
        si,
        LJ_CURVE_KEYS,
        list(LJ_CURVE_KEYS.values()),
        (rho, s, body),
        f"load curve of a sphere under the Lennard-Jones law (self-consistent, Greenwood "
        f"1997), from a central gap of 6 z0 to the load pi w R; pull-off "
        f"{c.F_pulloff_over_piwR:.6g} pi w R (load control, this curve's mesh)",
        ["central_gap_over_z0", "contact_radius", "F_over_piwR", "stable"],
        whole=_lj_whole(c, si),
    )


def _lj_whole(c: Any, si: Any) -> dict[str, Any]:
    """The Lennard-Jones curve's numbers of the whole: Tabor's parameter, the pull-offs."""
    out = {k: getattr(c, k) for k in ("tabor_parameter", "F_pulloff_over_piwR")}
    out["F_jump_in_over_piwR"] = c.F_jump_in_over_piwR
    if si is not None:
        out["F_pulloff_N"], out["F_jump_in_N"] = si.pull_off_force, si.jump_in_force
    return out


#: Each body's loads of ``normal``: the parameter, its flag, and the other body's spelling.
_LOADS = {
    "wire": (("F_over_Eh", "--F-over-Eh", "--F-over-EhR"), ("load", "--load", "--force [N]")),
    "sphere": (
        ("F_over_EhR", "--F-over-EhR", "--F-over-Eh"),
        ("force", "--force", "--load [N/m]"),
    ),
}


def refuse_other_loads(args: Inputs, body: str) -> None:
    """Refuse the other body's loads of ``normal`` (``body``: the body of the call)."""
    other = "sphere" if body == "wire" else "wire"
    for name, flag, instead in _LOADS[other]:
        if args.get(name) is not None:
            raise ParameterError(flag, f"{flag} is a {other}'s load: a {body}'s is {instead}")


def _above_pull_off(flag: str, loads: np.ndarray, rho, s, scale: float, unit: str) -> None:
    """Refuse a load below the pull-off (no contact carries it), in the flag's unit."""
    po = float(sphere_pull_off(rho, s).F_pulloff_over_EhR) * scale
    low = loads[loads < po]
    if low.size:
        raise ParameterError(
            flag,
            f"{flag} {float(low[0])!r}{unit} is below the pull-off force {po:.6g}{unit}: no "
            "contact carries it (the sphere has come off)",
        )


def normal(args: Inputs, rho: float, s: float, body: Any) -> Table:
    """``normal --body sphere``: the states at contact radii, or the contacts under loads."""
    refuse_other_loads(args, "sphere")
    for name, flag, word in (
        ("branch", "--branch", "stable"),
        ("method", "--method", "closed-form"),
    ):
        if args.get(name) != word:
            raise ParameterError(flag, f"{flag} is a wire's: a sphere's contact is {word}")
    loads = [v for v in (args.F_over_EhR, args.force) if v is not None]
    widths = [v for v in (args.a_over_R, args.a_over_R_range, args.a) if v is not None]
    if len(loads) + len(widths) != 1:
        raise ParameterError(
            "--a-over-R",
            "give exactly one of --a-over-R, --a-over-R-range, --F-over-EhR, --half-width [m] "
            "(a sphere's contact radius) or --force [N]",
        )
    if args.force is not None and body is None:
        raise ParameterError("--force", "--force [N] is an SI input: give --radius and the rest")
    if args.F_over_EhR is not None and body is not None:
        raise ParameterError(
            "--F-over-EhR", "--F-over-EhR is nondimensional: with SI inputs give --force [N]"
        )
    c: Any = None
    if widths:
        args.load = None  # the wire's check of the widths, none of its loads given
        A = half_widths(args, body, "F_over_Eh")
        if body is None:
            r = sphere_contact(A, rho, s)
        else:
            c = made(args, "result", body.contact, contact_radius=A)
            r = c.nondimensional
    else:
        if body is None:
            F = np.asarray(args.F_over_EhR, float)
            _above_pull_off("--F-over-EhR", F, rho, s, 1.0, "")
            r = sphere_contact_for_load(F, rho, s)
        else:
            force = np.asarray(args.force, float)
            check_si("--force", force, body.scale("EhR"), "F_over_EhR", "N")
            _above_pull_off("--force", force, rho, s, body.scale("EhR"), " N")
            args.said_as["load"] = "force"  # the SI layer's name of --force
            c = made(args, "result", body.contact, load=force)
            r = c.nondimensional
    return _table(
        args,
        r,
        c,
        CONTACT_KEYS,
        list(CONTACT_KEYS.values()),
        (rho, s, body),
        "normal contact of a sphere (Maugis-Dugdale), compressive load positive",
        ["a_over_R", "c_over_R", "F_over_EhR", "delta_over_h", "stable"],
    )


def curve(args: Inputs, rho: float, s: float, body: Any) -> Table:
    """``curve --body sphere``: both branches, the pull-offs under load and displacement."""
    for name, flag in (("F_max_over_Eh", "--F-max-over-Eh"), ("F_max", "--F-max")):
        if args.get(name) is not None:
            raise ParameterError(
                flag,
                f"{flag} is the Lennard-Jones wire's: a sphere's ends at --a-max (under the "
                "Lennard-Jones law, at the load pi w R)",
            )
    if args.law == "lennard-jones":
        return _curve_lj(args, rho, s, body)
    n = {"num": 200 if args.num is None else args.num}
    n["num_noncontact"] = 40 if args.num_noncontact is None else args.num_noncontact
    if args.a_max is not None and args.a_max_over_R is not None:
        raise ParameterError(
            "--a-max", "give the largest contact radius as --a-max [m] or --a-max-over-R, not both"
        )
    if args.a_max is not None and body is None:
        raise ParameterError(
            "--a-max", "--a-max [m] is an SI input: give --radius and the rest, or --a-max-over-R"
        )
    if args.a_max is not None:
        check_si("--a-max", args.a_max, body.radius, "a_max_over_R", "m")
    si: Any = None
    if body is None or args.a_max_over_R is not None:
        c = sphere_load_curve(rho, s, a_max_over_R=args.a_max_over_R, **n)
    else:
        si = made(args, "result", body.load_curve, max_radius=args.a_max, **n)
        c = si.nondimensional
    show = ["branch", "central_gap_over_h", "a_over_R", "c_over_R", "F_over_EhR", "delta_over_h"]
    po, pd = c.pulloff, c.pulloff_displacement
    return _table(
        args,
        c,
        si,
        CONTACT_KEYS,
        list(CONTACT_KEYS.values()),
        (rho, s, body),
        f"load curve of a sphere: non-contact branch, then contact; pull-off "
        f"{po.F_pulloff_over_EhR:.6g} (load control, {po.mechanism}), "
        f"{pd.F_pulloff_over_EhR:.6g} (displacement control, {pd.mechanism})",
        [*show, "stable", "pull_off_load", "pull_off_displacement"],
    )
