r"""Figures of tangential load histories (``docs/load-histories.md``): loops, loss, memory.

Drawn by :func:`linecontact.figures.extra_figures` (``linecontact figures``) with the
helpers of :mod:`linecontact.figures._style`; every number comes from
:mod:`linecontact.tangential.history`. The two friction laws are compared at equal
strength: the constant friction stress ``tau0/E`` = :data:`TAU0_OVER_E` and Coulomb friction
on a Hertz contact of ``a/R = 0.01`` with the same full-slip load, ``mu F = 2 a tau0``
(``mu a/R = (8/pi) tau0/E``). Lines: the closed forms (Masing rules); markers: the
incremental collocation solver, which knows no memory rule.

Figures and parameters
----------------------
history01_loops
    The steady hysteresis loops ``T/(E a)`` against the displacement ``D/a`` (datum at depth
    ``a``) for cyclic loading at :data:`AMPLITUDE` of full slip, both laws. The loop area is
    the energy dissipated per cycle; a different datum shears the loop (adds ``kappa T`` to
    ``D``) without changing its area.
history02_loss_amplitude
    The energy dissipated per cycle ``W/(E a^2)`` against the amplitude over the full-slip
    load, log axes: slope 4 at small amplitude for the constant friction stress, 3 for
    Coulomb friction; the full-slip limits dotted.
history03_traction_after_reversal
    The traction ``q/tau0`` over the contact along the history 0 -> 0.8 -> 0.2 -> -0.4 of
    the full-slip load: the reversal starts new slip zones at the edges (``q = -tau0``)
    while the old ones stay stuck, at ``+tau0``.
history04_slip_after_reversal
    The accumulated slip ``s/(a tau0/E)`` (relative to the centre) along the same history:
    it is locked in where the surfaces stick and changes only in the current slip zones.
"""

from __future__ import annotations

from functools import partial

import numpy as np

from ..tangential.history import (
    cyclic_loss,
    cyclic_loss_coulomb,
    tangential_history,
    tangential_history_coulomb,
)
from ._style import Job, Margins, Run, _colors, _new_axes

__all__ = ["AMPLITUDE", "HISTORY", "TAU0_OVER_E", "jobs"]

#: Friction stress over E of the figures.
TAU0_OVER_E = 0.01
#: Amplitude of the loops of history01, over the full-slip load.
AMPLITUDE = 0.8
#: The loads of history03/04, over the full-slip load.
HISTORY = (0.8, 0.2, -0.4)
_A_OVER_R = 0.01
_MU = 8 / np.pi * TAU0_OVER_E / _A_OVER_R  # mu F = 2 a tau0
_MARGINS = Margins(left=0.95, right=2.9)
_MARK = dict(ls="none", marker="s", ms=5, mfc="white", mew=1.2)


def _laws():
    """(label, cyclic loss, history) of the two friction laws, loads over full slip."""
    return (
        (
            r"constant $\tau_0$",
            lambda r, **k: cyclic_loss(TAU0_OVER_E, 2 * TAU0_OVER_E * np.asarray(r), **k),
            lambda r, **k: tangential_history(TAU0_OVER_E, 2 * TAU0_OVER_E * np.asarray(r), **k),
        ),
        (
            r"Coulomb $\mu p$ (Hertz)",
            lambda r, **k: cyclic_loss_coulomb(_MU, _A_OVER_R, r, **k),
            lambda r, **k: tangential_history_coulomb(_MU, _A_OVER_R, r, **k),
        ),
    )


def _title(what: str) -> str:
    return (
        rf"{what} ($\tau_0/E$ = {TAU0_OVER_E:g}; Coulomb: $a/R$ = {_A_OVER_R:g}, "
        rf"$\mu F = 2a\tau_0$)"
    )


_INC = "incremental collocation"
_LIMIT = "full-slip limit"


def _legend(ax) -> None:
    """The legend: each curve, then one entry for the markers and one for the limits.

    Every entry's handle is an artist drawn with data (the first of its kind), not an
    empty stand-in; the curves keep their order, the shared entries come last.
    """
    handles, labels = ax.get_legend_handles_labels()
    first: dict[str, object] = {}
    for hnd, lab in zip(handles, labels, strict=True):
        first.setdefault(lab, hnd)
    order = [k for k in first if k not in (_INC, _LIMIT)] + [
        k for k in (_INC, _LIMIT) if k in first
    ]
    ax.legend(
        [first[k] for k in order],
        order,
        loc="upper left",
        bbox_to_anchor=(1.01, 1.0),
        fontsize=9,
        frameon=False,
    )


def _loops(run: Run):
    fig, ax = _new_axes(
        run,
        _MARGINS,
        _title(f"hysteresis loops at {AMPLITUDE:g} of full slip"),
        r"displacement $D/a$ (datum at depth $a$)",
        r"tangential force $T/(Ea)$",
    )
    # the incremental solver along the loop: up to +A, down to -A, up to +A
    u = np.linspace(-1, 1, 9)
    path = AMPLITUDE * np.concatenate([[1.0], -u[1:], u[1:]])
    for (label, loss, history), col in zip(_laws(), _colors(2), strict=True):
        w = loss(AMPLITUDE)
        lp = w.loop(201)
        ax.plot(
            lp["displacement_over_a"],
            lp["T_over_Ea"],
            color=col,
            lw=2,
            label=f"{label}\n$W/(Ea^2)$ = {w.W_over_Ea2:.3g}",
        )
        h = run.data(("history-loop", label), partial(history, path, method="incremental"))
        ax.plot(h.displacement_over_a[1:], h.T_over_Ea[1:], color=col, **_MARK, label=_INC)
    ax.axhline(0, color="0.6", lw=0.6)
    ax.axvline(0, color="0.6", lw=0.6)
    _legend(ax)
    return fig


def _loss(run: Run):
    fig, ax = _new_axes(
        run,
        _MARGINS,
        _title("energy dissipated per cycle"),
        r"amplitude over the full-slip load $T^*/T_{full}$",
        r"energy per cycle and length $W/(Ea^2)$",
    )
    r = np.geomspace(1e-3, 1 - 1e-9, 300)
    r_marks = np.array([0.03, 0.1, 0.3, 0.6, 0.9])
    limits = (
        32 / np.pi * (np.log(2) - 0.5) * TAU0_OVER_E**2,
        np.pi / 8 * _MU**2 * _A_OVER_R**2,
    )
    for (label, loss, _), col, slope, lim in zip(_laws(), _colors(2), (4, 3), limits, strict=True):
        ax.plot(r, loss(r).W_over_Ea2, color=col, lw=2, label=f"{label}: slope {slope}")
        marks = run.data(("history-loss", label), partial(loss, r_marks, method="incremental"))
        ax.plot(r_marks, marks.W_over_Ea2, color=col, **_MARK, label=_INC)
        ax.axhline(lim, color=col, lw=0.8, ls=":", label=_LIMIT)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(1e-3, 1)
    _legend(ax)
    return fig


def _reversal(run: Run, what: str):
    label, _, history = _laws()[0]
    x = np.linspace(-1, 1, 801)
    h = run.data("history-reversal", lambda: history(list(HISTORY)))
    hi = run.data("history-reversal-inc", lambda: history(list(HISTORY), method="incremental"))
    if what == "traction":
        ylabel, vals, vals_i = r"traction $q/\tau_0$", h.traction(x), hi.traction(x[::40])
        scale = TAU0_OVER_E
        title = "traction after reversals (constant friction stress)"
    else:
        ylabel = r"slip $s/(a\tau_0/E)$ (relative to the centre)"
        vals, vals_i = h.slip(x), hi.slip(x[::40])
        scale = TAU0_OVER_E
        title = "accumulated slip after reversals (constant friction stress)"
    fig, ax = _new_axes(
        run, _MARGINS, rf"{title}, $\tau_0/E$ = {TAU0_OVER_E:g}", r"position $x/a$", ylabel
    )
    cols = _colors(len(HISTORY))
    for j, (T, col) in enumerate(zip(HISTORY, cols, strict=True)):
        lab = "loaded to" if j == 0 else "then to"
        ax.plot(x, vals[j] / scale, color=col, lw=2, label=f"{lab} $T/T_{{full}}$ = {T:g}")
        ax.plot(x[::40], vals_i[j] / scale, color=col, **_MARK, label=_INC)
    for zs, col in zip(h.zones(), cols, strict=True):
        for _, hi_end, _ in zs[:-1]:
            ax.axvline(hi_end, color=col, lw=0.6, ls=":")
            ax.axvline(-hi_end, color=col, lw=0.6, ls=":")
    ax.axhline(0, color="0.6", lw=0.6)
    ax.set_xlim(-1, 1)
    _legend(ax)
    return fig


def jobs() -> list[Job]:
    """The load-history figures."""
    return [
        Job("history01_loops", _loops, "history", 1.0),
        Job("history02_loss_amplitude", _loss, "history", 1.0),
        Job(
            "history03_traction_after_reversal",
            lambda run: _reversal(run, "traction"),
            "history",
            0.5,
        ),
        Job("history04_slip_after_reversal", lambda run: _reversal(run, "slip"), "history", 0.5),
    ]
