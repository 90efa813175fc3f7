"""The pull-off of a sweep over whole blocks at once: the vectorised API, not point by point.

``linecontact pulloff`` under the Dugdale law is a closed form: a block of a million points
is one call of :func:`linecontact.pull_off`. Each value of each swept flag is first checked
as the command line checks it (the cylinder built with that value alone, its warnings kept);
the records are then built as ``linecontact pulloff`` builds them: the SI values by the
scales the result declares (:func:`linecontact.units.to_si`), under the keys the operation
writes (``PULL_OFF_KEYS``), which ``tests/test_sweep.py`` checks against the point-by-point
path. (The composite modulus and the Dugdale step of ``(w, z0)`` are the library's
functions; a body whose parameters are arrays of points would make this module one call of
the SI layer, issue 32.) A polygon (``--cross-section``) takes the same path through
:func:`linecontact.facet_pull_off`, its scan of the branch vectorised over the block.
"""

from __future__ import annotations

import functools
import math
import warnings
from typing import Any

import numpy as np

from .. import materials as _materials
from ..cylinder import _ZERO_WIDTH, _warn_widths
from ..domain import DOMAIN
from ..facet import facet_pull_off
from ..geometry import NAMED_SIDES
from ..normal import pull_off
from ..operations._common import _presets, groups
from ..operations._messages import spell
from ..operations.normal import PULL_OFF_KEYS, PULL_OFF_TOTALS
from ..output import table_from_result, unit_of
from ..units import Scales, to_si
from ._plan import Plan
from ._plan import template as _template

__all__ = ["pulloff_block"]

#: The SI flags whose values the fast path sweeps (words, such as presets: point by point).
_SI = ("radius", "modulus", "E1", "nu1", "E2", "nu2", "sigma0", "h", "work_of_adhesion", "z0")
_GROUPS = ("R_over_h", "sigma0_over_E")
#: A polygon's corner radius, in SI units or over R (with --cross-section).
_SHAPE = ("corner_radius", "corner_radius_over_R")


@functools.lru_cache(maxsize=4)
def _checked(p: Plan) -> tuple[Any, dict[str, np.ndarray], list[tuple[str, str]]]:
    """The template, each axis's values refused (their messages), the warnings said.

    Each axis is checked with the other axes at a value that passes (found in a first round
    at their first values). Every check of a single input, the others fixed, is an interval
    (a range, a bound, a threshold of a monotone group such as R/h or Dundurs' beta): where
    the smallest and the largest value of an axis pass, so do those between. Only an axis
    whose ends do not is checked value by value.
    """
    template = _template(p)
    base = {a.dest: a.values[0] for a in p.axes}
    bad: dict[str, np.ndarray] = {}
    said: list[tuple[str, str]] = []
    for _ in range(2):
        said.clear()
        for a in p.axes:
            msgs = np.full(len(a.values), "", dtype=object)
            vals = np.asarray(a.values, float)
            ends = sorted({int(np.argmin(vals)), int(np.argmax(vals))})
            for i in ends:
                msgs[i] = _check_one(p, template, base, a, a.values[i], said)
            if any(msgs[i] for i in ends):
                for i, v in enumerate(a.values):
                    if i not in ends:
                        msgs[i] = _check_one(p, template, base, a, v, said)
            bad[a.dest] = msgs
        good = {a.dest: a.values[int(np.argmax(bad[a.dest] == ""))] for a in p.axes}
        if good == base:
            break
        base = good
    return template, bad, said


def _check_one(
    p: Plan, template: Any, base: dict[str, Any], a: Any, v: Any, said: list[tuple[str, str]]
) -> str:
    """The message refusing the value ``v`` of the axis ``a`` ("" where it passes)."""
    words = list(p.fixed)
    at: dict[str, Any] = {}
    for b in p.axes:
        value = v if b is a else base[b.dest]
        at[b.dest] = value
        words += [b.flag, repr(value)]
    args = template.replace(words=[p.command, *words], **at)
    msg = ""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            groups(args)
        except (ValueError, OverflowError) as exc:
            msg = spell(str(exc), args)
    for w in caught:
        item = (w.category.__name__, spell(str(w.message), args))
        if item not in said:
            said.append(item)
    return msg


def pulloff_block(p: Plan, index: int, block: tuple[slice, ...]) -> Any:
    """The block of a ``pulloff`` sweep, or None where it must go point by point."""
    from ._block import Block, assemble

    if p.command != "pulloff" or not p.axes:
        return None
    if any(a.dest not in _SI + _GROUPS + _SHAPE + ("length",) or not a.unit for a in p.axes):
        return None
    template, bad, said = _checked(p)
    if template.law != "dugdale" or getattr(template, "body", "wire") != "wire":
        return None  # the Lennard-Jones law, a sphere: point by point through the operation
    polygon = NAMED_SIDES.get(getattr(template, "cross_section", None) or "round")
    shape = tuple(sl.stop - sl.start for sl in block)
    grids = np.meshgrid(
        *(np.asarray(a.values[s], float) for a, s in zip(p.axes, block, strict=True)), indexing="ij"
    )
    v = {a.dest: g.reshape(-1) for a, g in zip(p.axes, grids, strict=True)}
    n = math.prod(shape)
    ok = np.ones(n, bool)
    reasons: dict[int, str] = {}  # the points an axis's value refuses: the first reason
    for a, sl in zip(p.axes, block, strict=True):
        msgs = bad[a.dest][sl]
        if np.any(msgs != ""):
            lookup = dict(zip(a.values[sl], msgs, strict=True))
            m = np.array([lookup[x] for x in v[a.dest]], dtype=object)
            refused = m != ""
            for i in np.flatnonzero(refused & ok):
                reasons[int(i)] = str(m[i])
            ok &= ~refused

    def get(dest: str) -> Any:
        return v[dest][ok] if dest in v else getattr(template, dest)

    si = template.R_over_h is None
    if si:
        try:
            R, E, s0, h = _si_inputs(get, template)
        except (ValueError, OverflowError):
            return None
        # one value a point, also where only other inputs are swept (a corner radius, a length)
        R, E, s0, h = (np.broadcast_to(x, (int(ok.sum()),)) for x in (R, E, s0, h))
        rho, s = R / h, s0 / E
    else:
        rho = np.broadcast_to(get("R_over_h"), (int(ok.sum()),)).astype(float)
        s = np.broadcast_to(get("sigma0_over_E"), rho.shape).astype(float)
    inside = _inside(rho, s)
    if not inside.all():  # outside the solvers' domain (R/h, sigma0/E): said as the CLI says
        at = np.flatnonzero(ok)[~inside]
        reasons.update(_outside(p, v, at, rho[~inside], s[~inside]))
        ok[at] = False
        rho, s = rho[inside], s[inside]
        if si:
            R, E, s0, h = R[inside], E[inside], s0[inside], h[inside]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            r: Any
            if polygon is None:
                r = pull_off(rho, s)
            else:  # its scan of the branch, vectorised over the block
                rc = get("corner_radius") if si else get("corner_radius_over_R")
                rc = np.broadcast_to(np.asarray(0.0 if rc is None else rc, float), inside.shape)
                rc = rc[inside]
                r = facet_pull_off(rho, s, sides=polygon, corner_radius_over_R=rc / R if si else rc)
        except (ValueError, OverflowError):
            return None  # refused otherwise: the points one by one say which
    for w in caught:
        item = (w.category.__name__, str(w.message))
        if item not in said:
            said.append(item)
    extra: dict[str, Any] = {}
    if si:  # the SI form the result declares, under the keys the operation writes
        in_si = to_si(r, Scales(R=R, E=E, h=h))
        extra.update({key: in_si[name] for name, key in PULL_OFF_KEYS.items()})
        zero = np.asarray(r.mechanism) == "zero-width"
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            # (a polygon's contact lies on its facet: its widths are not checked, as the
            # operation's records do not check them)
            for m, why in ((zero, _ZERO_WIDTH), (~zero, "")) if polygon is None else ():
                _warn_widths(
                    extra["a_at_pulloff_m"][m], R[m], "the contact half-width at pull-off", why
                )
        for w in caught:
            item = (w.category.__name__, str(w.message))
            if item not in said:
                said.append(item)
        length = get("length")
        if length is not None:  # each field over the fibre, as Cylinder's results give it
            extra.update(
                {key: np.multiply(in_si[name], length) for name, key in PULL_OFF_TOTALS.items()}
            )
    table = table_from_result(r, columns=extra, drop=r.inputs)  # inputs: parameters
    cols = {k: np.asarray(c) for k, c in table.columns.items()}
    idx = np.flatnonzero(ok)
    failed = {i: ("invalid", why) for i, why in reasons.items()}
    coded: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    data = assemble(shape, n, [(idx, cols, 1)], failed, coded) if idx.size else None
    if data is None:
        return None
    units = {k: table.units.get(k) or unit_of(k) for k in cols}
    return Block(index, data, units, {}, list(said), coded_text=coded)


#: The points outside the domain of a block that are said as the command line says them (each
#: one run of the subcommand); the others name the groups and the first one's message.
_SAID_ONE_BY_ONE = 256


def _inside(rho: np.ndarray, s: np.ndarray) -> np.ndarray:
    """The points whose ``R/h`` and ``sigma0/E`` are inside the domain of the solvers."""
    out = np.ones(rho.shape, bool)
    for key, x in (("R_over_h", rho), ("sigma0_over_E", s)):
        lo, lo_in, hi, hi_in = DOMAIN[key]
        with np.errstate(invalid="ignore"):
            out &= (x >= lo if lo_in else x > lo) & (x <= hi if hi_in else x < hi)
    return out


def _outside(
    p: Plan, v: dict[str, np.ndarray], at: np.ndarray, rho: np.ndarray, s: np.ndarray
) -> dict[int, str]:
    """The reasons of the points ``at`` (flat indices) outside the domain of the solvers."""
    from ._block import call

    out: dict[int, str] = {}
    first = ""
    for j, i in enumerate(at.tolist()):
        if j < _SAID_ONE_BY_ONE:
            values = {a.dest: float(v[a.dest][i]) for a in p.axes}
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                _, _, reason = call(p, values, [])
            out[i] = reason or "outside the domain of the solvers"
            first = first or out[i]
        else:
            (lo1, _, hi1, _), (lo2, _, hi2, _) = DOMAIN["R_over_h"], DOMAIN["sigma0_over_E"]
            out[i] = (
                f"R/h = {rho[j]:.6g}, sigma0/E = {s[j]:.6g}: outside the domain of the solvers "
                f"(R/h in [{lo1:g}, {hi1:g}], sigma0/E in [{lo2:g}, {hi2:g}]), as the first such "
                f"point of its block: {first}"
            )
    return out


def _si_inputs(get: Any, t: Any) -> tuple[Any, Any, Any, Any]:
    """Radius, composite modulus, sigma0 and h [SI] of the valid points, as arrays."""
    R = np.asarray(get("radius"), float)
    if t.modulus is not None or get("modulus") is not None and t.E1 is None:
        E = np.asarray(get("modulus"), float)
    else:
        m1, m2 = _presets(t)
        E1 = get("E1") if m1 is None else m1.E
        nu1 = get("nu1") if m1 is None else m1.nu
        E2 = get("E2") if m2 is None else m2.E
        nu2 = get("nu2") if m2 is None else m2.nu
        E = np.asarray(_materials.composite_modulus(E1, nu1, E2, nu2), float)
    if t.work_of_adhesion is not None or t.z0 is not None:
        s0, h = _materials.adhesion_from_work(get("work_of_adhesion"), get("z0"))
    else:
        s0, h = get("sigma0"), get("h")
    R, E, s0, h = np.broadcast_arrays(R, E, np.asarray(s0, float), np.asarray(h, float))
    return R, E, s0, h
