"""The operations of normal contact: ``normal``, ``pulloff`` and ``curve``."""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

import numpy as np

from ..closed_forms import kappa, maugis_parameter
from ..cylinder import Cylinder, _si_load_curve
from ..errors import ParameterError
from ..facet import facet_contact, facet_contact_for_load, facet_load_curve, facet_pull_off
from ..laws import lennard_jones as _lj
from ..normal import NormalContact, contact_for_load, load_curve, normal_contact, pull_off
from ..output import Table
from . import sphere as _sphere
from ._common import (
    MAX_POINTS,
    body_parameter,
    flags,
    group_parameters,
    groups,
    half_widths,
    is_sphere,
    shape,
    shape_parameters,
    shape_parameters_of,
    si_inputs,
    si_loads,
    si_parameters,
    sphere_inputs,
    width_parameters,
)
from ._declare import Entry, Inputs, Operation, Parameter
from ._records import convergence, records, si_shown
from ._written import made

__all__ = ["OPERATIONS"]


def _force(cyl: Cylinder | None, F_over_Eh: Any) -> str:
    """A force of the groups as the user gave the problem: in N/m (SI inputs) or in E h."""
    if cyl is None:
        return f"{F_over_Eh:.6g} E h"
    return f"{cyl.in_si(F_over_Eh, 'Eh'):.6g} N/m"


def _parameters(args, rho: float, s: float, cyl: Cylinder | None) -> dict[str, Any]:
    params: dict[str, Any] = {"R_over_h": rho, "sigma0_over_E": s}
    params["kappa"] = kappa(rho, s)
    params["maugis_parameter"] = maugis_parameter(rho, s)
    if cyl is not None:
        params.update(si_parameters(args, cyl))
    return params


def _lj_parameters(args, rho: float, s: float, cyl: Cylinder | None) -> dict[str, Any]:
    """The parameters under the Lennard-Jones law (no kappa: the Dugdale law's)."""
    params = _parameters(args, rho, s, cyl)
    params.pop("kappa")
    params["law"] = "lennard-jones"
    return params


# --------------------------------------------------------------------------------------------
# normal


def _cmd_normal(args: Inputs) -> Table:
    rho, s, cyl, g = _wire(args)
    if is_sphere(args):
        return _sphere.normal(args, rho, s, cyl)
    _sphere.refuse_other_loads(args, "wire")
    A = half_widths(args, cyl, "F_over_Eh")
    if g is not None:
        return _cmd_normal_facet(args, A, rho, s, cyl, g)
    if args.law == "lennard-jones":
        return _cmd_normal_lj(args, A, rho, s, cyl)
    c: Any = None  # the SI result (SI inputs)
    if A is not None:
        if args.branch != "stable":
            raise ParameterError(
                "--branch",
                "--branch applies to given loads (--F-over-Eh or --load): a contact half-width "
                "fixes the state",
            )
        if cyl is None:
            r = normal_contact(A, rho, s, method=args.method, on_failure="report")
        else:  # A in m
            c = made(
                args,
                "result",
                cyl.contact,
                contact_half_width=A,
                method=args.method,
                on_failure="report",
            )
            r = c.nondimensional
        state, reason = convergence(r, args.method, estimate=True)
        given = "a_over_R"
    else:
        if args.method != "closed-form":
            raise ParameterError(
                "--method",
                "--method collocation applies to given contact half-widths (--a-over-R, "
                "--a-over-R-range or --a); the contact for a given load is found by the closed "
                "form",
            )
        if cyl is None:
            F = np.asarray(args.F_over_Eh, float)
            r = contact_for_load(F, rho, s, branch=args.branch, on_failure="report")
        else:
            load = si_loads(args, cyl, "F_over_Eh")
            c = made(
                args, "result", cyl.contact, load=load, branch=args.branch, on_failure="report"
            )
            r = c.nondimensional
            F = cyl.over(load, "Eh")
        state = np.asarray(r.state).reshape(-1)
        reason = _load_reasons(F.reshape(-1), state, rho, s, args.branch, cyl)
        given = "F_over_Eh"
    table = _normal_table(args, r, c, rho, s, cyl, state, reason, given)
    return table


def _cmd_normal_facet(
    args: Inputs, A, rho: float, s: float, cyl: Cylinder | None, g: dict[str, Any]
) -> Table:
    """The contact of a polygonal wire on its facet at given half-widths or loads."""
    for name, value, default in (
        ("branch", args.branch, "stable"),
        ("method", args.method, "closed-form"),
    ):
        if value != default:
            raise ParameterError(
                f"--{name}",
                f"--{name} {value} is not written for a {args.cross_section} wire: its contact "
                "is the closed form's, the stable state for a load",
            )
    c: Any = None  # the SI result (SI inputs)
    if A is not None:
        if cyl is None:
            r = facet_contact(A, rho, s, **g)
        else:  # A in m
            c = made(args, "result", cyl.contact, contact_half_width=A)
            r = c.nondimensional
        given = "a_over_R"
    else:
        if cyl is None:
            F = np.asarray(args.F_over_Eh, float)
            r = facet_contact_for_load(F, rho, s, on_failure="report", **g)
        else:
            c = made(
                args,
                "result",
                cyl.contact,
                load=si_loads(args, cyl, "F_over_Eh"),
                on_failure="report",
            )
            r = c.nondimensional
        given = "F_over_Eh"
    bad = np.asarray(r.region).reshape(-1) == "no-equilibrium"
    state = np.where(bad, "no-equilibrium", "contact")
    reason = np.full(state.shape, None, dtype=object)
    if bad.any():
        po = facet_pull_off(rho, s, **g).F_pulloff_over_Eh
        reason[bad] = (
            f"no contact carries this load: it is below the pull-off force {_force(cyl, po)} "
            f"of this {args.cross_section} wire (it has pulled off)"
        )
    params = _parameters(args, rho, s, cyl)
    params.update(shape_parameters_of(g, cyl))
    extra, show = _contact_columns(args, c, cyl, ["a_over_R", "c_over_R", "F_over_Eh", "region"])
    return records(
        args,
        r,
        params,
        extra,
        f"normal contact of a {args.cross_section} wire on its facet (closed form), "
        "compressive load positive",
        show,
        contact=(state, reason, given),
    )


def _cmd_normal_lj(args: Inputs, A, rho: float, s: float, cyl: Cylinder | None) -> Table:
    if A is not None:
        raise ParameterError(
            "--law",
            "--law lennard-jones finds the contact for given loads (--F-over-Eh or --load): "
            "give loads, not contact half-widths",
        )
    if args.branch != "stable" or args.method != "closed-form":
        raise ParameterError(
            "--branch",
            "--branch and --method apply to --law dugdale: under the Lennard-Jones law the "
            "contact for a load is the stable state beyond the pull-off",
        )
    c: Any = None  # the SI result (SI inputs)
    if cyl is None:
        F = np.asarray(args.F_over_Eh, float)
        r = _lj.contact_for_load(F, rho, s, on_failure="report")
    else:
        c = made(args, "result", cyl.contact, load=args.load, on_failure="report")
        r = c.nondimensional
        F = np.asarray(r.F_over_Eh, float)
    state = np.asarray(r.state).reshape(-1)
    reason = np.full(state.shape, None, dtype=object)
    if np.any(state != "contact"):
        po = _lj.pull_off(rho, s)
        reason[state != "contact"] = (
            f"no contact carries this load: it is below the pull-off force "
            f"{_force(cyl, po.F_pulloff_over_Eh)} under the Lennard-Jones law (the "
            "contact has pulled off)"
        )
    params = _lj_parameters(args, rho, s, cyl)
    extra: dict[str, Any] = {}
    show = ["a_over_R", "central_gap_over_h", "F_over_Eh", "error_estimate_over_Eh"]
    if cyl is not None:
        names = {"contact_half_width": "a_m", "central_gap": "central_gap_m"}
        names.update(load="F_N_per_m", error_estimate="error_estimate_N_per_m")
        cols, shown = si_shown(args, c, names, {"load": "F_total_N"}, ["a_m", "F_N_per_m"])
        extra.update(cols)
        show += shown
    return records(
        args,
        r,
        params,
        extra,
        "contact for a load under the Lennard-Jones law (matched to the Dugdale step: "
        "same w, same peak tension), compressive load positive",
        show,
        contact=(state, reason, "F_over_Eh"),
        drop=("state",),
    )


def _load_reasons(F, state, rho, s, branch, cyl) -> np.ndarray:
    reason = np.full(state.shape, None, dtype=object)
    bad = np.flatnonzero(state != "contact")
    if bad.size == 0:
        return reason
    po = pull_off(rho, s)
    for i in bad:
        if F[i] < po.F_minimum_over_Eh or branch == "stable":
            reason[i] = (
                f"no contact carries this load: it is below the pull-off force "
                f"{_force(cyl, po.F_minimum_over_Eh)} (the cylinder has pulled off)"
            )
        else:
            reason[i] = (
                f"no unstable contact carries this load: that branch exists only between the "
                f"load minimum {_force(cyl, po.F_minimum_over_Eh)} and the zero-width "
                f"load {_force(cyl, po.F_zero_width_over_Eh)}"
            )
    return reason


def _contact_columns(args, c, cyl, show: list[str]) -> tuple[dict[str, Any], list[str]]:
    """A contact's SI columns (``a_m``, ``c_m``, ``F_N_per_m``, the total) and those to show.

    ``show``: the groups' columns shown before ``stable`` and the SI ones.
    """
    extra: dict[str, Any] = {}
    show = [*show, "stable"]
    if cyl is not None:
        names = {"contact_half_width": "a_m", "adhesive_zone_half_width": "c_m"}
        names["load"] = "F_N_per_m"
        cols, shown = si_shown(args, c, names, {"load": "F_total_N"}, ["a_m", "c_m", "F_N_per_m"])
        extra.update(cols)
        show += shown
    return extra, show


def _normal_table(args, r: NormalContact, c, rho, s, cyl, state, reason, given) -> Table:
    params = _parameters(args, rho, s, cyl)
    if args.branch != "stable":
        params["branch"] = args.branch
    extra, show = _contact_columns(args, c, cyl, ["a_over_R", "c_over_R", "F_over_Eh", "c_over_a"])
    # the load is the difference of the Hertz and the adhesive terms: round-off is relative
    # to them, not to the load
    a = np.asarray(r.a_over_R, float)
    c = np.asarray(r.c_over_R, float)
    with np.errstate(invalid="ignore"):
        terms = np.pi / 4 * a * a * rho + 2 * s * rho * np.sqrt(np.maximum(c * c - a * a, 0.0))
    scales = {"F_over_Eh": terms}
    if cyl is not None:
        scales["F_N_per_m"] = cyl.in_si(terms, "Eh")
        if args.length is not None:
            scales["F_total_N"] = cyl.total(scales["F_N_per_m"], args.length)
    return records(
        args,
        r,
        params,
        extra,
        f"normal contact ({r.method}), compressive load positive",
        show,
        contact=(state, reason, given),
        drop=("state",),
        scales=scales,
    )


# --------------------------------------------------------------------------------------------
# pulloff


def _cmd_pulloff_lj(args: Inputs, rho: float, s: float, cyl: Cylinder | None) -> Table:
    si = None if cyl is None else made(args, "result", cyl.pull_off)
    p = _lj.pull_off(rho, s) if si is None else si.nondimensional
    params = _lj_parameters(args, rho, s, cyl)
    extra: dict[str, Any] = {}
    show = [
        "F_pulloff_over_Eh",
        "error_estimate_over_Eh",
        "central_gap_over_h_at_pulloff",
        "F_jump_in_over_Eh",
        "mu",
        "method",
    ]
    if cyl is not None:
        names = {"pull_off_force": "F_pulloff_N_per_m"}
        names["contact_half_width_at_pull_off"] = "a_at_pulloff_m"
        names["central_gap_at_pull_off"] = "central_gap_at_pulloff_m"
        totals = {"pull_off_force": "F_pulloff_total_N"}
        cols, shown = si_shown(args, si, names, totals, ["F_pulloff_N_per_m"])
        extra.update(cols)
        show += shown
    table = records(
        args,
        p,
        params,
        extra,
        "pull-off under the Lennard-Jones law (matched to the Dugdale step: same w, "
        "same peak tension)",
        show,
    )
    return table


#: The record's key of each SI field of the pull-off (``Cylinder.pull_off``), in their order,
#: and of its total over the fibre (with ``--length``): the sweep's blocks write the same.
PULL_OFF_KEYS = {
    "pull_off_force": "F_pulloff_N_per_m",
    "contact_half_width_at_pull_off": "a_at_pulloff_m",
    "zero_width_force": "F_zero_width_N_per_m",
}
PULL_OFF_TOTALS = {"pull_off_force": "F_pulloff_total_N"}


def _wire(args: Inputs) -> tuple[float, float, Any, dict[str, Any] | None]:
    """``(R/h, sigma0/E, the body or None, a polygon's groups or None)`` of a normal problem.

    The Lennard-Jones law is refused for a polygon: its problems are written for Dugdale's;
    and for a sphere (``--body sphere``), whose own refusals :func:`sphere_inputs` says.
    """
    if is_sphere(args):
        sphere_inputs(args)
    rho, s, cyl = groups(args)
    g = shape(args, cyl)
    if g is not None and args.law == "lennard-jones":
        raise ParameterError(
            "--law",
            f"--law lennard-jones is not written for a {args.cross_section} wire: a polygon's "
            "contact and pull-off are the Dugdale law's (--law dugdale)",
        )
    return rho, s, cyl, g


def _sphere_or_law(
    sphere: Callable[..., Table], lennard_jones: Callable[..., Table]
) -> Callable[[Callable[..., Table]], Callable[[Inputs], Table]]:
    """A command whose sphere (``--body sphere``) and Lennard-Jones law are their own.

    The decorated function answers for the Dugdale law's wire, given
    ``(args, R/h, sigma0/E, the body or None, a polygon's groups or None)``.
    """

    def decorate(dugdale: Callable[..., Table]) -> Callable[[Inputs], Table]:
        @functools.wraps(dugdale)
        def command(args: Inputs) -> Table:
            rho, s, cyl, g = _wire(args)
            if is_sphere(args):
                return sphere(args, rho, s, cyl)
            if args.law == "lennard-jones":
                return lennard_jones(args, rho, s, cyl)
            return dugdale(args, rho, s, cyl, g)

        return command

    return decorate


@_sphere_or_law(_sphere.pulloff, _cmd_pulloff_lj)
def _cmd_pulloff(args: Inputs, rho: float, s: float, cyl: Cylinder | None, g) -> Table:
    si = None if cyl is None else made(args, "result", cyl.pull_off)
    if si is not None:
        p = si.nondimensional
    else:
        p = pull_off(rho, s) if g is None else facet_pull_off(rho, s, **g)
    params = _parameters(args, rho, s, cyl)
    params.pop("kappa")
    params.pop("maugis_parameter")
    extra: dict[str, Any] = {}
    show = ["F_pulloff_over_Eh", "a_over_R_at_pulloff", "mechanism", "F_zero_width_over_Eh"]
    if g is not None:
        params.update(shape_parameters_of(g, cyl))
        show += ["facet_half_width_over_R", "F_strip_jkr_over_Eh", "F_strength_over_Eh"]
    if cyl is not None:
        shown_si = ["F_pulloff_N_per_m", "a_at_pulloff_m"]
        cols, shown = si_shown(args, si, PULL_OFF_KEYS, PULL_OFF_TOTALS, shown_si)
        extra.update(cols)
        show += shown
    # a width below 1e-12 R (a zero-width pull-off's, 1e-24 R and less) prints as 0 in a
    # table, as round-off does; JSON and CSV keep the number
    scales = {"a_over_R_at_pulloff": 1.0}
    if cyl is not None:
        scales["a_at_pulloff_m"] = cyl.radius
    table = records(
        args,
        p,
        params,
        extra,
        "pull-off under load control (the most tensile load a contact carries)",
        show,
        scales=scales,
    )
    return table


# --------------------------------------------------------------------------------------------
# curve

#: The points of a Dugdale load curve on each branch (the parameter, the branch, the default).
_POINTS = {"num": ("contact", 200), "num_noncontact": ("non-contact", 40)}


def _check_lj_end(F_max: float | None, rho: float, s: float) -> None:
    """``--F-max-over-Eh`` within the loads the Lennard-Jones solver is asked for (said so).

    The solver's own message names its groups; the end of the curve is said here in the
    units of the flag. A value that is no load (nan, <= 0) is left to the solver's check.
    """
    from ..lennard_jones_groups import LJ_LOAD_MAX, load_max_over_Eh

    if F_max is None or not (np.isfinite(F_max) and F_max > 0):
        return
    with np.errstate(all="ignore"):
        limit = float(load_max_over_Eh(rho, s))
    if F_max > limit:
        raise ParameterError(
            "--F-max-over-Eh",
            f"--F-max-over-Eh={F_max!r} is beyond the loads the Lennard-Jones solver is asked "
            f"for, up to {limit:.6g} here (in its units; {LJ_LOAD_MAX:g} w sqrt(R/z0), ten "
            "times the rigid cylinder's pull-off); at such loads both laws approach Hertz, "
            "and the Dugdale law (the default) gives the contact",
        )


def _cmd_curve_lj(args: Inputs, rho: float, s: float, cyl: Cylinder | None) -> Table:
    given = flags(args, "a_max_over_R", "a_max", "num", "num_noncontact")
    if given:
        raise ParameterError(
            given[0],
            f"{', '.join(given)} {'applies' if len(given) == 1 else 'apply'} to --law dugdale: "
            "the Lennard-Jones curve has the states of its continuation; give --F-max-over-Eh "
            "(or --F-max [N/m]) for its end",
        )
    F_max = args.F_max_over_Eh
    if args.F_max is not None:
        if cyl is None:
            raise ParameterError(
                "--F-max", "--F-max [N/m] is an SI input: give --radius and the materials too"
            )
        if args.F_max_over_Eh is not None:
            raise ParameterError(
                "--F-max-over-Eh", "give either --F-max-over-Eh or --F-max [N/m], not both"
            )
        if not (np.isfinite(args.F_max) and args.F_max > 0):
            raise ParameterError(
                "--F-max", f"--F-max must be a finite load > 0 [N/m], got {args.F_max!r}"
            )
    elif cyl is not None and F_max is not None:
        raise ParameterError(
            "--F-max-over-Eh",
            "--F-max-over-Eh is nondimensional: with SI inputs give --F-max [N/m]",
        )
    si: Any = None
    if cyl is None:
        _check_lj_end(F_max, rho, s)
        c = _lj.load_curve(rho, s, F_max_over_Eh=F_max)
    else:
        si = made(args, "result", cyl.load_curve, max_load=args.F_max)
        c = si.nondimensional
    po = c.pulloff
    is_po = np.zeros(c.F_over_Eh.shape, bool)
    is_po[int(np.argmin(c.F_over_Eh))] = True  # the sample nearest the refined pull-off
    return _curve_table(
        args,
        c,
        _lj_parameters(args, rho, s, cyl),
        is_po,
        ["central_gap_over_h", "a_over_R", "F_over_Eh", "error_estimate_over_Eh", "stable"],
        (
            "load curve under the Lennard-Jones law (matched to the Dugdale step: same w, same "
            "peak tension), the central gap decreasing; pull-off "
            f"{po.F_pulloff_over_Eh:.6g} (error estimate {po.error_estimate_over_Eh:.2g})"
        ),
        si,
        {"load": "F_N_per_m", "error_estimate": "error_estimate_N_per_m"},
    )


def _curve_table(
    args: Inputs,
    c: Any,
    params: dict[str, Any],
    is_po: np.ndarray,
    show: list[str],
    title: str,
    si: Any,
    names: dict[str, str],
) -> Table:
    """The records of a load curve ``c``, its pull-off marked by ``is_po``.

    With SI inputs (``si``, the curve in SI units) its gap and width, then the fields
    ``names`` (in that order, the load among them), and the load's total.
    """
    extra: dict[str, Any] = {"pulloff": is_po}
    if si is not None:
        names = {"central_gap": "central_gap_m", "contact_half_width": "a_m", **names}
        cols, shown = si_shown(args, si, names, {"load": "F_total_N"}, ["a_m", "F_N_per_m"])
        extra.update(cols)
        show += shown
    show.append("pulloff")
    return records(args, c, params, extra, title, show)


@_sphere_or_law(_sphere.curve, _cmd_curve_lj)
def _cmd_curve(args: Inputs, rho: float, s: float, cyl: Cylinder | None, g) -> Table:
    if args.F_max_over_Eh is not None or args.F_max is not None:
        raise ParameterError(
            "--F-max-over-Eh" if args.F_max_over_Eh is not None else "--F-max",
            "--F-max-over-Eh and --F-max apply to --law lennard-jones: the Dugdale curve ends "
            "at --a-max-over-R (or --a-max [m])",
        )
    for name, (_, default) in _POINTS.items():
        if args.get(name) is None:
            setattr(args, name, default)
    for flag, v in (("--num", args.num), ("--num-noncontact", args.num_noncontact)):
        if not 2 <= v <= MAX_POINTS:
            raise ParameterError(flag, f"{flag} must be an integer in [2, {MAX_POINTS}], got {v!r}")
    if cyl is None and args.a_max is not None:
        raise ParameterError(
            "--a-max", "--a-max [m] is an SI input: give --radius and the materials too"
        )
    n = dict(num=args.num, num_noncontact=args.num_noncontact)
    si: Any = None
    if g is not None:
        return _cmd_curve_facet(args, rho, s, cyl, g)
    if cyl is None or (args.a_max is None and args.a_max_over_R is not None):
        c = load_curve(rho, s, a_max_over_R=args.a_max_over_R, **n)
        if cyl is not None:  # the limit in radii: the same curve, in SI units
            si = _si_load_curve(cyl, c)
    else:
        si = made(args, "result", cyl.load_curve, max_half_width=args.a_max, **n)
        c = si.nondimensional
    po = c.pulloff
    # the pull-off state is the one `pulloff` reports, whatever its label: the load minimum
    # (a point of the curve), or the touching state where the minimum is narrower than the
    # domain of a/R (its load is Eq. 14 to round-off)
    is_po = np.zeros(c.a_over_R.shape, bool)
    if c.turning_point.any():
        is_po |= c.turning_point
    elif s > 0:
        touch = np.flatnonzero((c.branch == "non-contact") & (c.central_gap_over_h == 0))
        is_po[touch[-1:]] = True
    return _curve_table(
        args,
        c,
        _parameters(args, rho, s, cyl),
        is_po,
        ["branch", "central_gap_over_h", "a_over_R", "c_over_R", "F_over_Eh", "stable"],
        (
            f"load curve: non-contact branch (gap g0 from h to 0), then the contact branch; "
            f"pull-off {po.F_pulloff_over_Eh:.6g} ({po.mechanism})"
        ),
        si,
        {"adhesive_zone_half_width": "c_m", "load": "F_N_per_m"},
    )


def _cmd_curve_facet(args: Inputs, rho: float, s: float, cyl: Cylinder | None, g) -> Table:
    """The load curve of a polygonal wire: its contact branch from touch-down."""
    if args.get("num_noncontact") not in (None, _POINTS["num_noncontact"][1]):
        raise ParameterError(
            "--num-noncontact",
            f"--num-noncontact: a {args.cross_section} wire's curve begins at touch-down (its "
            "non-contact branch is not sampled)",
        )
    si: Any = None
    if cyl is None:
        if args.a_max is not None:
            raise ParameterError(
                "--a-max", "--a-max [m] is an SI input: give --radius and the materials too"
            )
        c = facet_load_curve(rho, s, a_max_over_R=args.a_max_over_R, num=args.num, **g)
    else:
        a_max = args.a_max
        if a_max is None and args.a_max_over_R is not None:
            a_max = cyl.in_si(args.a_max_over_R, "R")
        si = made(args, "result", cyl.load_curve, max_half_width=a_max, num=args.num)
        c = si.nondimensional
    po = c.pulloff
    params = _parameters(args, rho, s, cyl)
    params.update(shape_parameters_of(g, cyl))
    return _curve_table(
        args,
        c,
        params,
        c.turning_point,
        ["a_over_R", "c_over_R", "F_over_Eh", "region", "stable"],
        (
            f"load curve of a {args.cross_section} wire on its facet: the contact branch from "
            f"touch-down; pull-off {po.F_pulloff_over_Eh:.6g} ({po.mechanism})"
        ),
        si,
        {"adhesive_zone_half_width": "c_m", "load": "F_N_per_m"},
    )


# --------------------------------------------------------------------------------------------
# the declarations

_LAW = Parameter(
    "law",
    "Dugdale step or the Lennard-Jones law (Eq 1)",
    kind="text",
    choices=("dugdale", "lennard-jones"),
    default="dugdale",
)
_SI, _SI_ENTRIES = si_inputs()
_SHAPE, _SHAPE_ENTRIES = shape_parameters()
_WIDTHS = "contact half-widths or loads (exactly one)"
_SHAPE_OPTIONS, _ = shape_parameters("")  # among the options: normal's help fits a screen
#: --body and the wire's cross-section, one entry of the help
_BODY_ENTRY = Entry(
    ("body", *_SHAPE_ENTRIES[0].names),
    "%(default)s or sphere [N]; a wire's section, r_c [m], r_c/R",
)
#: a sphere's loads, beside the wire's (one entry each: the help fits a screen)
_SPHERE_LOADS = (
    Parameter(
        "F_over_EhR", "a sphere's loads over E h R", many="several", metavar="F", group=_WIDTHS
    ),
    Parameter("force", "a sphere's loads F [N] (SI)", many="several", unit="N", group=_WIDTHS),
)
_LOAD_ENTRIES = (
    Entry(("F_over_Eh", "F_over_EhR"), "loads over E h (a wire, per length) or E h R (a sphere)"),
    Entry(("load", "force"), "loads F [N/m] (a wire) or [N] (a sphere) (SI inputs)"),
)
_SAMPLING = "sampling"

OPERATIONS = {
    "normal": Operation(
        "normal",
        "adhesive-zone width and load for given contact half-widths, or the contact for loads",
        "Maugis-Dugdale normal contact (paper Eqs 5-14): for each half-width a the end c of "
        "the adhesive zone and the load F; or for each load its contact (docs/cli.md).",
        (
            "linecontact normal --R-over-h 100 --sigma0-over-E 0.01 --a-over-R 0.01 0.05",
            "linecontact normal --radius 50e-9 --modulus 100e9 --sigma0 1e9 --h 0.5e-9 --load 0 1",
        ),
        (
            *group_parameters(),
            *_SI,
            *width_parameters(
                "F_over_Eh", "loads per unit length over E h (the contact for them)", _WIDTHS
            ),
            Parameter(
                "branch",
                "stable or narrower unstable contact (loads)",
                kind="text",
                choices=("stable", "unstable"),
                default="stable",
            ),
            Parameter(
                "method",
                "closed form or collocation (widths)",
                kind="text",
                choices=("closed-form", "collocation"),
                default="closed-form",
            ),
            *_SPHERE_LOADS,
            _LAW,
            body_parameter(""),
            *_SHAPE_OPTIONS,
        ),
        _cmd_normal,
        good=("contact",),
        rows=("a_over_R", "F_over_Eh", "a", "load", "F_over_EhR", "force"),
        entries=(*_SI_ENTRIES, _BODY_ENTRY, *_LOAD_ENTRIES),
    ),
    "pulloff": Operation(
        "pulloff",
        "pull-off force under load control and its mechanism",
        "The most tensile load a contact carries (paper Eq 14 and the snap-off) and its "
        "mechanism, zero-width or snap-off; of a faceted wire (--cross-section hexagon) on "
        "its facet, with the facet's limits (docs/faceted.md); of a sphere (--body sphere: "
        "an AFM tip, in N; docs/sphere.md). One record.",
        (
            "linecontact pulloff --R-over-h 100 --sigma0-over-E 0.01",
            "linecontact pulloff --radius 50e-9 --cylinder-material SiO2 --substrate-material Si "
            "--work-of-adhesion 0.1 --z0 0.3e-9 --json",
            "linecontact pulloff --R-over-h 100 --sigma0-over-E 0.01 --law lennard-jones",
            "linecontact pulloff --cross-section hexagon --corner-radius 5e-9 --radius 50e-9 "
            "--modulus 50e9 --work-of-adhesion 0.1 --z0 0.3e-9 --json",
            "linecontact pulloff --body sphere --radius 20e-9 --cylinder-material Si "
            "--substrate-material SiO2 --work-of-adhesion 0.1 --z0 0.3e-9",
        ),
        (*group_parameters(), *_SI, _LAW, body_parameter(), *_SHAPE),
        _cmd_pulloff,
        entries=(*_SI_ENTRIES, _BODY_ENTRY),
    ),
    "curve": Operation(
        "curve",
        "the whole load curve: non-contact branch, contact branch, turning point, pull-off",
        "The load F along the non-contact branch (central gap g0 from h to 0), then the "
        "contact branch (a from 0 up), turning point and pull-off marked (docs/cli.md).",
        (
            "linecontact curve --R-over-h 100 --sigma0-over-E 0.05 --format csv -o curve.csv",
            "linecontact curve --radius 50e-9 --modulus 100e9 --sigma0 1e9 --h 0.5e-9 --json",
        ),
        (
            *group_parameters(),
            *_SI,
            _LAW,
            body_parameter(""),
            *_SHAPE_OPTIONS,
            Parameter(
                "a_max_over_R",
                "largest contact half-width a/R (default: three times the width at pull-off, "
                "at least the Hertz width at ten times the pull-off force and 0.02, at most 0.2)",
                metavar="A",
                group=_SAMPLING,
            ),
            Parameter(
                "a_max", "largest half-width a [m] (SI)", unit="m", metavar="A", group=_SAMPLING
            ),
            *(
                Parameter(
                    name,
                    f"points on the {branch} branch (default: {n}; --law dugdale)",
                    kind="integer",
                    metavar="N",
                    group=_SAMPLING,
                )
                for name, (branch, n) in _POINTS.items()
            ),
            Parameter(
                "F_max_over_Eh",
                "--law lennard-jones: the compressive load F/(E h) where the curve ends "
                "(default: 7.5 w sqrt(R/z0), three times the rigid cylinder's pull-off)",
                metavar="F",
                group=_SAMPLING,
            ),
            Parameter(
                "F_max",
                "--law lennard-jones: the end load F [N/m] (SI)",
                unit="N/m",
                metavar="F",
                group=_SAMPLING,
            ),
        ),
        _cmd_curve,
        entries=(
            *_SI_ENTRIES,
            _BODY_ENTRY,
            Entry(("a_max_over_R", "a_max"), "largest half-width a/R, or a [m] (docs/cli.md)"),
            Entry(
                ("num", "num_noncontact"),
                "points on the contact, non-contact branch (default: "
                f"{', '.join(str(n) for _, n in _POINTS.values())})",
            ),
            Entry(
                ("F_max_over_Eh", "F_max"),
                "lennard-jones: end load F/(E h), or F [N/m] (docs/cli.md)",
            ),
        ),
        api_names={"max_load": "F_max"},
    ),
}
