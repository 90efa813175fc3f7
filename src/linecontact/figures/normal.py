r"""Reproduce the normal-loading figures (Figs. 2--6) of Sari, Adams & Müftü.

The paper's figures are not in its text; only what they show is described. This module
redraws them from the library's solvers with :mod:`matplotlib` (an optional dependency,
imported only when a figure is drawn: ``pip install 'linecontact[plot]'``).

Figures and parameters
----------------------
fig02_load_R100, fig03_load_R200
    Load ``F/(E h)`` versus contact half-width ``a/R`` for ``R/h = 100`` (Fig. 2) and
    ``R/h = 200`` (Fig. 3), the values the paper states. It gives no ``sigma0/E``; we use
    :data:`LOAD_SIGMA0_OVER_E` = 0 (Hertz), 0.001, 0.005, 0.01, 0.02, 0.05, 0.1 over
    ``0 < a/R <= 0.1`` (:data:`A_MAX_OVER_R`). The small values show the approach to Hertz
    (Eq. 13) that the text notes; 0.001--0.01 peel to zero width at the load of Eq. (14);
    0.05 and 0.1 have a load minimum inside the plotted range (snap-off at
    ``a/R ~ 0.02`` and ``~ 0.05``, 1--10 % below Eq. 14), which the text describes "for
    larger values of sigma0/E". The range ``a/R <= 0.1`` keeps the Hertz loads (0.8 and 1.6)
    comparable with the pull-off forces (down to -1.7 and -2.2) so both ends are legible.
    Solid lines: the closed form, dense; dotted: its part with ``dF/da < 0`` (unstable under
    load control); markers: the paper's route, Gauss--Chebyshev collocation of Eq. (9), at
    :data:`N_COLLOCATION_MARKERS` points per curve; dashed black: Hertz (Eq. 13); dashed
    grey: JKR line contact (``w = sigma0 h``) for the largest ``sigma0/E``; open circles:
    pull-off, at the load minimum (for the zero-width mechanism at a width below ``h``,
    indistinguishable from ``a = 0`` on Eq. 14 at this scale). Lines are continued to their
    ``a -> 0`` limit, Eq. (14).
fig04_zone_R100, fig05_zone_R200
    Adhesive-zone half-width ``c/R`` versus ``a/R``, same ``R/h``, ``sigma0/E`` and styles;
    at ``a -> 0`` the lines end on the adhesive zone of the touching state (central gap
    zero). Stronger adhesion gives the smaller ``c/R`` at a given ``a/R``, as the paper
    remarks.
fig06_zero_width
    Eq. (14), the load at vanishing contact width, versus ``sigma0/E`` in ``[0, 0.1]``
    (:data:`ZERO_WIDTH_SIGMA0_MAX`) for ``R/h`` in :data:`ZERO_WIDTH_R_OVER_H` = 10, 50,
    100, 200, 500, 1000 (the paper: "different cylinder radii", values not given; these
    span two decades around the ``R/h`` of Figs. 2--3). Markers: the true pull-off force,
    open where the contact peels to a width below ``h`` (zero-width mechanism: the load is
    then within a small fraction of Eq. 14), filled where it snaps off from a width of at
    least ``h`` at a lower load; the fan of filled markers below the lines shows where
    Eq. (14) stops being the pull-off force. The dotted line is the ``sigma0/E -> inf``
    limit of Eq. (14), ``-pi/(2 ln 2)``, independent of ``R/h``.

All curves depend on ``(R/h, sigma0/E)`` only through
:math:`\kappa = (4/\pi)(\sigma_0/E)\sqrt{2R/h}` once ``a/R`` is scaled by ``sqrt(R/h)``
(see :mod:`linecontact.closed_forms`).
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from .. import closed_forms as _cf
from ..normal import non_contact, normal_contact, pull_off
from ._style import (
    _CITE,
    _COL_KW,
    _FILLED_KW,
    _OPEN_KW,
    _PO_KW,
    Job,
    Margins,
    Run,
    _branch_lines,
    _colors,
    _legends,
    _new_axes,
    _sigma_colors,
    _sigma_labels,
)

__all__ = [
    "A_MAX_OVER_R",
    "LOAD_R_OVER_H",
    "LOAD_SIGMA0_OVER_E",
    "N_COLLOCATION_MARKERS",
    "ZERO_WIDTH_R_OVER_H",
    "ZERO_WIDTH_SIGMA0_MAX",
    "jobs",
]

#: ``R/h`` of Figs. 2/4 and 3/5 (given in the paper).
LOAD_R_OVER_H = (100.0, 200.0)
#: ``sigma0/E`` of the curves of Figs. 2--5 (chosen here; the paper gives none).
LOAD_SIGMA0_OVER_E = (0.0, 0.001, 0.005, 0.01, 0.02, 0.05, 0.1)
#: Largest ``a/R`` drawn in Figs. 2--5.
A_MAX_OVER_R = 0.1
#: Collocation solutions drawn as markers per curve.
N_COLLOCATION_MARKERS = 15
#: ``R/h`` of the curves of Fig. 6 (chosen here).
ZERO_WIDTH_R_OVER_H = (10.0, 50.0, 100.0, 200.0, 500.0, 1000.0)
#: Largest ``sigma0/E`` of Fig. 6.
ZERO_WIDTH_SIGMA0_MAX = 0.1


# --------------------------------------------------------------------------------------------
# data


def _branch_data(rho: float, sigmas: Iterable[float]) -> list[dict]:
    """Closed-form (dense), collocation (sparse) and pull-off data, one dict per sigma0/E.

    Every solver is called once for all the curves (the solvers are vectorised).
    """
    sig = np.asarray(tuple(sigmas), dtype=float)
    rhos = np.full(sig.shape, rho)
    po = pull_off(rhos, sig)
    # the a -> 0 limit of the contact branch is the touching non-contact state (g0 = 0)
    c_touch = np.asarray(non_contact(np.zeros(sig.shape), rhos, sig).c_over_R)
    a_col = np.linspace(A_MAX_OVER_R / N_COLLOCATION_MARKERS, A_MAX_OVER_R, N_COLLOCATION_MARKERS)
    base = np.union1d(
        np.geomspace(A_MAX_OVER_R * 1e-6, A_MAX_OVER_R, 120),
        np.linspace(A_MAX_OVER_R / 500, A_MAX_OVER_R, 500),
    )
    cf = normal_contact(base[None, :], rho, sig[:, None])
    col = normal_contact(a_col[None, :], rho, sig[:, None], method="collocation")
    cfF, cfc = np.asarray(cf.F_over_Eh), np.asarray(cf.c_over_R)
    colF, colc = np.asarray(col.F_over_Eh), np.asarray(col.c_over_R)
    F0s, a_pos = np.asarray(po.F_zero_width_over_Eh), np.asarray(po.a_over_R_at_pulloff)
    F_pos, c_pos = np.asarray(po.F_pulloff_over_Eh), np.asarray(po.c_over_R_at_pulloff)
    mechs = np.asarray(po.mechanism)
    # a curve with an interior load minimum (a snap-off, or a zero-width pull-off below the
    # range h) also gets the point of the minimum, where the dotted (unstable) part ends
    a_min = np.asarray(po.a_over_R_at_minimum, dtype=float)
    interior = a_min > 0
    extra = interior & (a_min < A_MAX_OVER_R) & ~np.isin(a_min, base)
    at_min = normal_contact(a_min[extra], rho, sig[extra]) if extra.any() else None
    at_F = np.atleast_1d(np.asarray(at_min.F_over_Eh)) if at_min is not None else None
    at_c = np.atleast_1d(np.asarray(at_min.c_over_R)) if at_min is not None else None
    out = []
    for i, s in enumerate(sig):
        a, F, c = base, cfF[i], cfc[i]
        if extra[i] and at_F is not None and at_c is not None:
            j, k = int(np.count_nonzero(extra[:i])), int(np.searchsorted(base, a_min[i]))
            a = np.insert(a, k, a_min[i])
            F = np.insert(F, k, at_F[j])
            c = np.insert(c, k, at_c[j])
        out.append(
            dict(
                sigma=float(s),
                # the a -> 0 limit (Eq. 14 and the zero-width adhesive zone) closes each line
                a=np.concatenate([[0.0], a]),
                F=np.concatenate([[float(F0s[i])], F]),
                c=np.concatenate([[float(c_touch[i])], c]),
                unstable=np.concatenate([[interior[i]], interior[i] & (a <= a_min[i])]),
                a_col=a_col,
                F_col=colF[i],
                c_col=colc[i],
                a_po=float(a_pos[i]),
                F_po=float(F_pos[i]),
                c_po=float(c_pos[i]),
                mechanism=str(mechs[i]),
            )
        )
    return out


# --------------------------------------------------------------------------------------------
# the figures


def _lw(sigma: float) -> float:
    return 3.2 if sigma == 0 else 1.8


def _branch_figure(ax, data: list[dict], key: str) -> list:
    """Closed-form lines, collocation markers and pull-off circles of ``key`` ("F" or "c")."""
    colors = _sigma_colors([d["sigma"] for d in data])
    for d, col in zip(data, colors, strict=True):
        _branch_lines(ax, d["a"], d[key], d["unstable"], col, _lw(d["sigma"]))
        ax.plot(d["a_col"], d[f"{key}_col"], color=col, **_COL_KW, zorder=5)
        if d["sigma"] > 0:
            ax.plot(d["a_po"], d[f"{key}_po"], color=col, mec=col, **_PO_KW, zorder=6)
    ax.set_xlim(-0.03 * A_MAX_OVER_R, A_MAX_OVER_R * 1.02)
    return colors


_STYLE_BRANCH = [
    ("closed form", dict(color="0.2", lw=1.8)),
    ("closed form, unstable\n($dF/da<0$, load control)", dict(color="0.2", lw=1.6, ls=":")),
    ("collocation of Eq. 9", dict(color="0.6", **_COL_KW)),
]


def _branch_axes(run: Run, rho: float, margins: Margins, title: str, ylabel: str):
    """The states at ``R/h = rho`` and the axes of Figs. 2 to 5 (against ``a/R``)."""
    data = _data(run, rho)
    fig, ax = _new_axes(
        run, margins, f"{title}, $R/h = {rho:g}$", r"contact half-width $a/R$", ylabel
    )
    return data, fig, ax


def _branch_legends(ax, data: list[dict], colors, styles: list) -> None:
    """The legends of Figs. 2 to 5: the values of sigma0/E, the branches and ``styles``."""
    _legends(
        ax,
        r"$\sigma_0/E$",
        colors,
        _sigma_labels([d["sigma"] for d in data]),
        [*_STYLE_BRANCH, *styles],
    )


def _load_figure(run: Run, number: int, rho: float):
    """Figs. 2, 3: F/(Eh) versus a/R."""
    data, fig, ax = _branch_axes(
        run, rho, Margins(0.813, 2.214), f"Fig. {number} ({_CITE}): normal load", r"load $F/(Eh)$"
    )
    a = data[0]["a"][1:]
    ax.axhline(0.0, color="0.3", lw=0.8)
    ax.plot(
        np.concatenate([[0.0], a]),
        np.concatenate([[0.0], _cf.hertz_load(a, rho)]),
        color="k",
        ls="--",
        lw=1.2,
        zorder=4,
    )
    big = data[-1]
    ax.plot(a, _cf.jkr_load(a, rho, big["sigma"]), color="0.45", ls=(0, (6, 3)), lw=1.0)
    colors = _branch_figure(ax, data, "F")
    lo = min(d["F_po"] for d in data)
    hi = float(_cf.hertz_load(A_MAX_OVER_R, rho))
    ax.set_ylim(lo - 0.06 * (hi - lo), hi + 0.05 * (hi - lo))
    _branch_legends(
        ax,
        data,
        colors,
        [
            ("Hertz (Eq. 13)", dict(color="k", ls="--", lw=1.2)),
            (
                f"JKR line contact, $w=\\sigma_0 h$,\n$\\sigma_0/E={big['sigma']:g}$",
                dict(color="0.45", ls=(0, (6, 3)), lw=1.0),
            ),
            ("pull-off (at $a=0$: Eq. 14)", dict(color="0.2", **_PO_KW)),
        ],
    )
    return fig


def _zone_figure(run: Run, number: int, rho: float):
    """Figs. 4, 5: c/R versus a/R."""
    data, fig, ax = _branch_axes(
        run,
        rho,
        Margins(0.783, 2.144),
        f"Fig. {number} ({_CITE}): adhesive-zone width",
        r"adhesive-zone half-width $c/R$",
    )
    colors = _branch_figure(ax, data, "c")
    _branch_legends(ax, data, colors, [("pull-off", dict(color="0.2", **_PO_KW))])
    return fig


def _zero_width_figure(run: Run):
    """Fig. 6: Eq. (14) versus sigma0/E, with the true pull-off force as markers."""
    fig, ax = _new_axes(
        run,
        Margins(0.813, 2.391, top=0.349),
        f"Fig. 6 ({_CITE}): zero-contact-width force, Eq. (14)",
        r"adhesive stress $\sigma_0/E$",
        r"load $F/(Eh)$",
    )
    rhos = np.asarray(ZERO_WIDTH_R_OVER_H)
    colors = _colors(rhos.size)
    s_line = np.linspace(0.0, ZERO_WIDTH_SIGMA0_MAX, 300)
    s_mark = np.linspace(ZERO_WIDTH_SIGMA0_MAX / 12, ZERO_WIDTH_SIGMA0_MAX, 12)
    F_line = np.asarray(_cf.zero_width_load(rhos[:, None], s_line[None, :]))
    po = pull_off(rhos[:, None], s_mark[None, :])
    ax.axhline(0.0, color="0.3", lw=0.8)
    ax.axhline(-np.pi / (2 * _cf.LN2), color="0.5", ls=":", lw=1.0)
    for i, col in enumerate(colors):
        ax.plot(s_line, F_line[i], color=col, lw=1.8)
        snap = np.asarray(po.mechanism)[i] == "snap-off"
        F = np.asarray(po.F_pulloff_over_Eh)[i]
        ax.plot(s_mark[~snap], F[~snap], color=col, mec=col, **_OPEN_KW)
        ax.plot(s_mark[snap], F[snap], color=col, mec=col, **_FILLED_KW)
    ax.set_xlim(0.0, ZERO_WIDTH_SIGMA0_MAX * 1.02)
    _legends(
        ax,
        "$R/h$",
        colors,
        [f"{r:g}" for r in rhos],
        [
            ("Eq. 14 (zero contact width)", dict(color="0.2", lw=1.8)),
            (
                "pull-off, peels to zero width\n(a < h, Eq. 14 to 1 %)",
                dict(color="0.2", **_OPEN_KW),
            ),
            (
                "pull-off, snap-off\n(a >= h or > 1 % below)",
                dict(color="0.2", **_FILLED_KW),
            ),
            (
                "Eq. 14 as $\\sigma_0/E\\to\\infty$:\n$-\\pi/(2\\ln 2)$, any $R/h$",
                dict(color="0.5", ls=":", lw=1.0),
            ),
        ],
    )
    return fig


def _data(run: Run, rho: float) -> list[dict]:
    """The load curves of ``R/h = rho``, computed once per run for Figs. 2--5."""
    return run.data(
        ("normal", rho),
        lambda: _branch_data(rho, LOAD_SIGMA0_OVER_E),
        f"load curves for R/h = {rho:g} ({len(LOAD_SIGMA0_OVER_E)} values of sigma0/E)",
    )


def jobs() -> list[Job]:
    """The figures of Figs. 2--6; Figs. 2 and 4 (3 and 5) draw the same load curves."""
    rho_a, rho_b = LOAD_R_OVER_H
    return [
        Job("fig02_load_R100", lambda run: _load_figure(run, 2, rho_a), "normal-a", 0.27),
        Job("fig03_load_R200", lambda run: _load_figure(run, 3, rho_b), "normal-b", 0.24),
        Job("fig04_zone_R100", lambda run: _zone_figure(run, 4, rho_a), "normal-a", 0.17),
        Job("fig05_zone_R200", lambda run: _zone_figure(run, 5, rho_b), "normal-b", 0.17),
        Job("fig06_zero_width", _zero_width_figure, "fig06", 0.20),
    ]
