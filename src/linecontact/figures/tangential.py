r"""Reproduce the tangential-loading figures (Figs. 7, 13, 14) of Sari, Adams & Müftü.

Drawn by ``linecontact paper`` after Figs. 2--6 (:func:`linecontact.figures.paper_figures`
adds :func:`jobs`); the plumbing (Agg canvas, styles, metadata) is that of
:mod:`linecontact.figures._style`, matplotlib is imported only when a figure is drawn.

Figures and parameters
----------------------
The paper plots each figure "for various values of constant shear stress" without giving
them; we use :data:`TAU0_OVER_E` = 0.0025, 0.005, 0.01, 0.02 (friction stresses of the order
of the adhesive stresses ``sigma0/E`` of Figs. 2--5, doubling from curve to curve so that the
proportionality of ``T`` and of the creep to ``tau0/E`` is visible at a glance). Solid lines:
the closed forms (``docs/tangential.md``); square markers: the paper's route, collocation of
Eq 16 (Fig. 7) or Eq 27 with the creep from the consistency equation (Figs. 13--14), at
:data:`N_COLLOCATION_MARKERS` values of ``d/a`` per curve; dashed lines of the same colour:
the macro-scale counterpart with Coulomb friction on the Hertz contact, for the same
full-slip load ``mu F = 2 a tau0`` (that is ``mu a/R = (8/pi) tau0/E``), so that the two
friction laws are compared at equal strength.

fig07_sliding_initiation
    Tangential force ``T/(Ea)`` versus the stick-zone half-width ``d/a`` during the initiation
    of sliding: ``2 (tau0/E) sqrt(1 - (d/a)^2)``, full stick at ``d = a`` (``T = 0``), full
    slip at ``d = 0`` (``T = 2 a tau0``). Dashed: Cattaneo--Mindlin, ``mu F (1 - (d/a)^2)``.
fig13_rolling_force
    Tractive force ``T/(Ea)`` of a driving cylinder in steady rolling versus the start ``d/a``
    of the leading-edge stick zone: ``(tau0/E) sqrt(2 (1 + d/a))``, from full stick
    (``d = -a``) to full slip (``d = a``, ``T = 2 a tau0``). Dashed: Carter,
    ``mu F (1 - ((1 - d/a)/2)^2)``.
fig14_rolling_creep
    Creep velocity over the rolling speed, ``(V - omega R)/V``, versus ``d/a``:
    ``-(2/pi)(tau0/E) arccosh((3 + d/a)/(1 - d/a))``. It is negative (the driving cylinder
    turns faster than it rolls), zero at full stick and diverges logarithmically as the
    stick zone vanishes (``d -> a``), while Carter's creep (dashed, ``-(mu a/R)(1 + d/a)/2``)
    stays finite. The creep equals the slip gradient in the stick zone; as that zone
    shrinks to the leading edge, the traction there tends to ``tau0`` up to the edge and
    then jumps to zero, and a jump makes the slip gradient logarithmically singular (Carter's
    ``mu p`` falls to zero continuously). The axis stops a little below the creep at
    ``d/a = 0.99`` for the largest ``tau0/E``; the lines run on to ``d/a = 1 - 1e-4``.
"""

from __future__ import annotations

import numpy as np

from ..tangential import (
    sliding_initiation,
    sliding_initiation_coulomb,
    steady_rolling,
    steady_rolling_coulomb,
)
from . import _style as _fig
from ._style import Job, Margins, Run

__all__ = ["N_COLLOCATION_MARKERS", "TAU0_OVER_E", "jobs"]

#: ``tau0/E`` of the curves of Figs. 7, 13, 14 (chosen here; the paper gives none).
TAU0_OVER_E = (0.0025, 0.005, 0.01, 0.02)
#: Collocation solutions drawn as markers per curve.
N_COLLOCATION_MARKERS = 13
#: Largest ``d/a`` drawn in Figs. 13--14 (the creep diverges like ``ln(1/(1 - d/a))``).
D_MAX_ROLLING = 1 - 1e-4

_A_OVER_R = 0.01  # a/R of the Coulomb curves: any value, mu is set by mu a/R = (8/pi) tau0/E


def _coulomb_mu(t0: float) -> float:
    """The friction coefficient with mu F = 2 a tau0 on the Hertz contact, a = 0.01 R."""
    return 8 / np.pi * t0 / _A_OVER_R


def _ends(ax, xy, ha: str, *lines: str, va: str = "top") -> None:
    """A small note on what the ends of the d/a axis mean, in axes coordinates."""
    ax.text(
        *xy,
        "\n".join(lines),
        transform=ax.transAxes,
        ha=ha,
        va=va,
        fontsize=9,
        bbox=dict(boxstyle="round,pad=0.4", fc="white", ec="0.7"),
    )


def _styles(eq: str, coulomb: str) -> list:
    return [
        ("closed form", dict(color="0.2", lw=1.8)),
        (f"collocation of {eq}", dict(color="0.6", **_fig._COL_KW)),
        (
            f"Coulomb friction ({coulomb}),\nsame full-slip load $\\mu F = 2a\\tau_0$",
            dict(color="0.2", lw=1.3, ls="--"),
        ),
    ]


def _fig07(run: Run):
    fig, ax = _fig._new_axes(
        run,
        Margins(0.873, 2.924, top=0.349),
        f"Fig. 7 ({_fig._CITE}): initiation of sliding",
        r"stick-zone half-width $d/a$",
        r"tangential force $T/(Ea)$",
    )
    colors = _fig._colors(len(TAU0_OVER_E))
    d = np.linspace(0.0, 1.0, 401)[:-1]
    d_col = np.linspace(0.04, 0.96, N_COLLOCATION_MARKERS)
    for t0, col in zip(TAU0_OVER_E, colors, strict=True):
        ax.plot(
            np.append(d, 1.0),
            np.append(sliding_initiation(t0, d, on_failure="report").T_over_Ea, 0.0),
            color=col,
            lw=1.8,
        )
        c = sliding_initiation(t0, d_col, method="collocation")
        ax.plot(d_col, c.T_over_Ea, color=col, **_fig._COL_KW, zorder=5)
        cm = sliding_initiation_coulomb(_coulomb_mu(t0), _A_OVER_R, d, on_failure="report")
        ax.plot(np.append(d, 1.0), np.append(cm.T_over_Ea, 0.0), color=col, lw=1.3, ls="--")
    ax.set_xlim(0, 1.0)
    ax.set_ylim(0, 2 * TAU0_OVER_E[-1] * 1.05)
    _ends(
        ax,
        (0.97, 0.96),
        "right",
        r"$d = 0$: full slip, $T = 2a\tau_0$",
        r"$d = a$: full stick, $T = 0$",
    )
    _fig._legends(
        ax,
        r"$\tau_0/E$",
        colors,
        [f"{t:g}" for t in TAU0_OVER_E],
        _styles("Eq. 16", "Cattaneo–Mindlin"),
    )
    return fig


def _rolling_d():
    """d/a from full stick to D_MAX_ROLLING, dense near both ends."""
    near = 1 - np.geomspace(1e-1, 1 - D_MAX_ROLLING, 60)
    return np.unique(
        np.concatenate([np.linspace(-1 + 1e-6, 0.9, 400), near, -1 + np.geomspace(1e-8, 1e-2, 40)])
    )


def _rolling_data(run: Run) -> dict:
    """Closed form, collocation and Coulomb (Carter) rolling, drawn by Figs. 13 and 14."""

    def compute():
        d = _rolling_d()
        d_col = np.linspace(-0.92, 0.92, N_COLLOCATION_MARKERS)
        t0 = np.asarray(TAU0_OVER_E)[:, None]
        return dict(
            d=d,
            d_col=d_col,
            closed=steady_rolling(t0, d[None, :]),
            col=steady_rolling(t0, d_col[None, :], method="collocation"),
            coulomb=[steady_rolling_coulomb(_coulomb_mu(t), _A_OVER_R, d) for t in TAU0_OVER_E],
        )

    return run.data("rolling", compute, f"steady rolling ({len(TAU0_OVER_E)} values of tau0/E)")


def _rolling_axes(run: Run, number: int, left: float, what: str, ylabel: str):
    """The axes of Fig. 13 or 14 (``what`` against the start of the stick zone), and colours."""
    fig, ax = _fig._new_axes(
        run,
        Margins(left, 2.404, top=0.349),
        f"Fig. {number} ({_fig._CITE}): steady rolling of a driving cylinder, {what}",
        r"start of the leading-edge stick zone $d/a$ (stick: $d < x < a$)",
        ylabel,
    )
    return fig, ax, _fig._colors(len(TAU0_OVER_E))


def _from_stick(d, y, end):
    """The curve from full stick (``d = -a``, 0) along ``d``, to full slip (``d = a``, ``end``).

    Without the full-slip point when ``end`` is None.
    """
    if end is None:
        return np.concatenate([[-1], d]), np.concatenate([[0], y])
    return np.concatenate([[-1], d, [1]]), np.concatenate([[0], y, [end]])


def _rolling_curves(ax, r: dict, colors, field: str, closed_end, coulomb_end) -> None:
    """Per ``tau0/E``: ``field`` of the closed form, the collocation and Carter's rolling.

    ``closed_end(t0)`` and ``coulomb_end(t0)`` are the values at full slip (``closed_end``
    None: the closed form is drawn without that point).
    """
    d, d_col = r["d"], r["d_col"]
    for i, (t0, col) in enumerate(zip(TAU0_OVER_E, colors, strict=True)):
        end = None if closed_end is None else closed_end(t0)
        ax.plot(*_from_stick(d, getattr(r["closed"], field)[i], end), color=col, lw=1.8)
        ax.plot(d_col, getattr(r["col"], field)[i], color=col, **_fig._COL_KW, zorder=5)
        cm = r["coulomb"][i]
        ax.plot(*_from_stick(d, getattr(cm, field), coulomb_end(t0)), color=col, lw=1.3, ls="--")


def _rolling_legend(ax, colors) -> None:
    _fig._legends(
        ax, r"$\tau_0/E$", colors, [f"{t:g}" for t in TAU0_OVER_E], _styles("Eq. 27", "Carter")
    )


def _fig13(run: Run):
    r = _rolling_data(run)
    fig, ax, colors = _rolling_axes(run, 13, 0.873, "tractive force", r"tractive force $T/(Ea)$")
    _rolling_curves(ax, r, colors, "T_over_Ea", lambda t0: 2 * t0, lambda t0: 2 * t0)
    ax.set_xlim(-1, 1)
    ax.set_ylim(0, 2 * TAU0_OVER_E[-1] * 1.05)
    _ends(
        ax,
        (0.03, 0.96),
        "left",
        r"$d = -a$: full stick, $T = 0$",
        r"$d = a$: full slip, $T = 2a\tau_0$",
    )
    _rolling_legend(ax, colors)
    return fig


def _fig14(run: Run):
    r = _rolling_data(run)
    fig, ax, colors = _rolling_axes(
        run, 14, 0.953, "creep", r"creep velocity $\dot C/V = (V - \omega R)/V$"
    )
    _rolling_curves(ax, r, colors, "creep_over_V", None, lambda t0: -_coulomb_mu(t0) * _A_OVER_R)
    ax.axhline(0.0, color="0.3", lw=0.8)
    ax.set_xlim(-1, 1)
    # the creep diverges at d -> a: show the range down to its value at d/a = 0.99
    ymin = 1.15 * float(steady_rolling(TAU0_OVER_E[-1], 0.99).creep_over_V)
    ax.set_ylim(ymin, -0.03 * ymin)
    ax.annotate(
        "$\\to -\\infty$ like $\\ln\\frac{1}{1 - d/a}$\nas the stick zone vanishes",
        xy=(0.993, 0.97 * ymin),
        xytext=(0.3, 0.85 * ymin),
        fontsize=9,
        arrowprops=dict(arrowstyle="->", color="0.3"),
    )
    _ends(
        ax,
        (0.03, 0.04),
        "left",
        r"$d = -a$: full stick, no creep",
        r"$d \to a$: full slip, $\omega R > V$",
        va="bottom",
    )
    _rolling_legend(ax, colors)
    return fig


def jobs() -> list[Job]:
    """The figures of Figs. 7, 13 and 14; Figs. 13 and 14 draw the same rolling states."""
    return [
        Job("fig07_sliding_initiation", _fig07, "fig07", 0.20),
        Job("fig13_rolling_force", _fig13, "rolling", 0.24),
        Job("fig14_rolling_creep", _fig14, "rolling", 0.21),
    ]
