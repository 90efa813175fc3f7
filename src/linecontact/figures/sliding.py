r"""Reproduce the steady-sliding figures (Figs. 8--12) of Sari, Adams & Müftü.

Drawn by :func:`linecontact.figures.paper_figures` (``linecontact paper``) with the helpers
of :mod:`linecontact.figures._style`; matplotlib is imported only when a figure is drawn.

Figures and parameters
----------------------
fig08_sliding_schematic
    The paper's Fig. 8 (a sketch in the paper) drawn from a computed state:
    ``R/h2 = 100``, ``sigma0/E = 0.02``, ``h1/h2 = 3``, ``a/R = 0.08``
    (:data:`SCHEMATIC`), chosen so that the asymmetry is plain to see and the centre of the
    contact is in compression. Top: the gap
    between the surfaces over ``h2``, computed from the pressure, reaching ``h1`` at
    ``-c1`` and ``h2`` at ``c2`` (the separation conditions, Eqs. 21--22). Bottom: the
    pressure ``p/E`` (closed form; collocation markers), the apex at ``x = e``, the
    sliding direction, and the load and moments.
fig09_zone_difference_s001, fig10_zone_difference_s004
    Difference of the adhesive-zone widths, ``(c1 - c2)/R`` (trailing minus leading,
    both measured from the contact centre, so it is also ``(c1 - a) - (c2 - a)``), versus
    ``a/R`` for ``R/h2 = 100`` and ``sigma0/E = 0.01`` (Fig. 9) and ``0.04`` (Fig. 10), the
    values the paper states, and ``h1/h2`` in :data:`H1_OVER_H2` = 1, 1.5, 2, 3 (the paper
    gives no values; 1 shows the symmetric limit, zero difference).
fig11_moment_s001, fig12_moment_s004
    The moment about the contact centre ``M/(E h2 R)`` (clockwise positive, see
    :mod:`linecontact.sliding`) for the same parameters. Dashed: the moment about the
    cylinder's axis, ``M - e F``, which is exactly ``(sigma0/E)(h1/h2 - 1)``, i.e.
    ``(w1 - w2) R`` with ``w_i = sigma0 h_i``, at every contact width.

In Figs. 9--12 solid lines are the closed form (dense), dotted their part with
``dF/da < 0`` (unstable under load control; listed in the key only where it is visible, not
at ``sigma0/E = 0.01``, Figs. 9 and 11, where it lies below ``a/R = 4e-6``), square markers
the paper's route (Gauss--Chebyshev collocation of Eqs. 20--22) at
:data:`N_COLLOCATION_MARKERS` widths, open circles the pull-off state under load control;
lines are continued to their ``a -> 0`` limit. ``a/R`` runs up to :data:`A_MAX_OVER_R` = 0.1,
as in Figs. 2--5.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from ..sliding import SlidingContact, sliding_contact, sliding_pull_off
from ._style import (
    _CITE,
    _COL_KW,
    _PO_KW,
    Job,
    Margins,
    Run,
    _branch_lines,
    _colors,
    _legends,
    _new_axes,
    _new_figure,
)

__all__ = [
    "A_MAX_OVER_R",
    "H1_OVER_H2",
    "N_COLLOCATION_MARKERS",
    "R_OVER_H2",
    "SCHEMATIC",
    "SIGMA0_OVER_E",
    "jobs",
]

#: ``R/h2`` of Figs. 9--12 (given in the paper).
R_OVER_H2 = 100.0
#: ``sigma0/E`` of Figs. 9/11 and 10/12 (given in the paper).
SIGMA0_OVER_E = (0.01, 0.04)
#: ``h1/h2`` of the curves (chosen here; the paper gives none).
H1_OVER_H2 = (1.0, 1.5, 2.0, 3.0)
#: Largest ``a/R`` drawn.
A_MAX_OVER_R = 0.1
#: Collocation solutions drawn as markers per curve.
N_COLLOCATION_MARKERS = 12
#: The state drawn in Fig. 8.
SCHEMATIC = dict(a_over_R=0.08, R_over_h2=100.0, h1_over_h2=3.0, sigma0_over_E=0.02)


def _pull_off(run: Run, s: float) -> SimpleNamespace:
    """The pull-off of every h1/h2 at ``sigma0/E = s``.

    One call for every curve of Figs. 9--12 (both values of sigma0/E: the solver is
    vectorised), computed once per run; the columns of ``s`` are returned.
    """

    def compute():
        r = np.asarray(H1_OVER_H2)[:, None]
        return sliding_pull_off(R_OVER_H2, r, np.asarray(SIGMA0_OVER_E)[None, :])

    po = run.data("sliding-pulloff", compute, "steady-sliding pull-off")
    j = SIGMA0_OVER_E.index(s)
    keys = (
        "mechanism",
        "a_over_R_at_pulloff",
        "c1_over_R_zero_width",
        "c2_over_R_zero_width",
        "F_zero_width_over_Eh2",
    )
    return SimpleNamespace(**{k: np.asarray(getattr(po, k))[:, j] for k in keys})


def _data(run: Run, s: float) -> list[dict]:
    """The curves of ``sigma0/E = s``, computed once per run for Figs. 9--12."""
    return run.data(
        ("sliding", s),
        lambda: _curves(s, _pull_off(run, s)),
        f"steady-sliding curves (R/h2 = {R_OVER_H2:g}, sigma0/E = {s:g}, "
        f"{len(H1_OVER_H2)} values of h1/h2)",
    )


def _curves(s: float, po) -> list[dict]:
    """Closed-form lines, collocation markers, limits and pull-off, one dict per h1/h2."""
    r = np.asarray(H1_OVER_H2)
    base = np.union1d(
        np.geomspace(A_MAX_OVER_R * 1e-5, A_MAX_OVER_R, 100),
        np.linspace(A_MAX_OVER_R / 300, A_MAX_OVER_R, 300),
    )
    cf = sliding_contact(base[None, :], R_OVER_H2, r[:, None], s, method="closed-form")
    a_col = np.linspace(A_MAX_OVER_R / N_COLLOCATION_MARKERS, A_MAX_OVER_R, N_COLLOCATION_MARKERS)
    col = sliding_contact(a_col[None, :], R_OVER_H2, r[:, None], s, method="collocation")
    # at the pull-off state itself: the load minimum at an interior width (a snap-off, or a
    # zero-width pull-off below the range h), or else the a -> 0 limit
    a_po = np.asarray(po.a_over_R_at_pulloff)
    interior = a_po > 0
    at_po = sliding_contact(np.where(interior, a_po, 1.0), R_OVER_H2, r, s, method="closed-form")
    at_d = np.asarray(at_po.c1_over_R) - np.asarray(at_po.c2_over_R)
    at_M = np.asarray(at_po.M_over_Eh2R)
    cf_d = np.asarray(cf.c1_over_R) - np.asarray(cf.c2_over_R)
    cf_M, cf_stable = np.asarray(cf.M_over_Eh2R), np.asarray(cf.stable)
    col_d = np.asarray(col.c1_over_R) - np.asarray(col.c2_over_R)
    col_M = np.asarray(col.M_over_Eh2R)
    out = []
    for i, ri in enumerate(r):
        C1_0, C2_0 = po.c1_over_R_zero_width[i], po.c2_over_R_zero_width[i]
        F0 = po.F_zero_width_over_Eh2[i]
        e0 = (2 * s / np.pi) * np.log(C1_0 / C2_0)  # e = (2 sigma0 R/(pi E))(u1 - u2)
        M0 = s * (ri - 1) + e0 * F0
        d_lim = C1_0 - C2_0
        if interior[i]:
            po_xy = (a_po[i], at_d[i], at_M[i])
        else:
            po_xy = (0.0, d_lim, M0)
        out.append(
            dict(
                r=float(ri),
                a=np.concatenate([[0.0], base]),
                d=np.concatenate([[d_lim], cf_d[i]]),
                M=np.concatenate([[M0], cf_M[i]]),
                unstable=np.concatenate([[interior[i]], ~cf_stable[i]]),
                a_col=a_col,
                d_col=col_d[i],
                M_col=col_M[i],
                po=po_xy,
                M_axis=s * (ri - 1),
            )
        )
    return out


def _r_colors(n: int) -> list:
    return _colors(n)


#: Shortest unstable part (dotted) that the line-style key lists, as a fraction of the
#: ``a/R`` range drawn: at ``sigma0/E = 0.01`` the load minimum lies below ``a/R = 4e-6``,
#: a dotted part far under a pixel wide, which the key then does not list.
_MIN_DOTTED = 0.01


def _unstable_visible(d: dict) -> bool:
    """Whether the dotted (unstable) part of the curve ``d`` spans a visible width."""
    unstable = np.asarray(d["unstable"])
    if not unstable.any():
        return False
    k = int(np.flatnonzero(unstable)[-1])  # as in _branch_lines: the dotted part is [:k + 1]
    return bool(d["a"][k] - d["a"][0] >= _MIN_DOTTED * A_MAX_OVER_R)


def _curve_figure(run: Run, number: int, s: float, key: str):
    data = _data(run, s)
    # the moment's label takes two lines (Figs. 11, 12), and Fig. 11's ticks are wider
    margins = Margins(1.08 if key == "M" else 0.783, 2.214)
    if key == "d":
        fig, ax = _new_axes(
            run,
            margins,
            f"Fig. {number} ({_CITE}): difference of the adhesive zones in steady sliding, "
            f"$R/h_2 = {R_OVER_H2:g}$, $\\sigma_0/E = {s:g}$",
            r"contact half-width $a/R$",
            r"$(c_1 - c_2)/R$  (trailing minus leading)",
        )
    else:
        fig, ax = _new_axes(
            run,
            margins,
            f"Fig. {number} ({_CITE}): moment in steady sliding, "
            f"$R/h_2 = {R_OVER_H2:g}$, $\\sigma_0/E = {s:g}$",
            r"contact half-width $a/R$",
            "moment $M/(E h_2 R)$ about the\ncontact centre, clockwise $+$",
        )
    colors = _r_colors(len(data))
    ax.axhline(0.0, color="0.3", lw=0.8)
    for d, col in zip(data, colors, strict=True):
        if key == "M":
            ax.axhline(d["M_axis"], color=col, ls="--", lw=1.0)
        _branch_lines(ax, d["a"], d[key], d["unstable"], col, 1.8)
        ax.plot(d["a_col"], d[f"{key}_col"], color=col, **_COL_KW, zorder=5)
        a_po, d_po, M_po = d["po"]
        ax.plot(a_po, d_po if key == "d" else M_po, color=col, mec=col, **_PO_KW, zorder=6)
    ax.set_xlim(-0.03 * A_MAX_OVER_R, A_MAX_OVER_R * 1.02)
    entries = [("closed form", dict(color="0.2", lw=1.8))]
    if any(_unstable_visible(d) for d in data):
        entries.append(
            ("closed form, unstable\n($dF/da<0$, load control)", dict(color="0.2", lw=1.6, ls=":"))
        )
    entries += [
        ("collocation of Eqs. 20-22", dict(color="0.6", **_COL_KW)),
        ("pull-off (load control)", dict(color="0.2", **_PO_KW)),
    ]
    if key == "M":
        entries.append(
            (
                "about the axis: $M - eF$\n$= (\\sigma_0/E)(h_1/h_2 - 1)$",
                dict(color="0.2", ls="--", lw=1.0),
            )
        )
    _legends(ax, "$h_1/h_2$", colors, [f"{d['r']:g}" for d in data], entries)
    return fig


def _schematic(run: Run):
    """Fig. 8 drawn from a computed state: the gap (top) and the pressure (bottom)."""
    par = SCHEMATIC
    st: SlidingContact = sliding_contact(**par, method="closed-form")  # type: ignore[arg-type]
    col = sliding_contact(**par, method="collocation")  # type: ignore[arg-type]
    a, c1, c2, e = st.a_over_R, st.c1_over_R, st.c2_over_R, st.e_over_R
    r, s = par["h1_over_h2"], par["sigma0_over_E"]
    lo, hi = -1.35 * c1, 1.35 * c2
    x = np.union1d(np.linspace(lo, hi, 1601), [-c1, -a, a, c2])
    x = np.union1d(x, np.linspace(-a, a, 401))
    gap = st.gap(x)
    p = st.pressure(x)

    # two panels, the size of the other figures
    fig = _new_figure(run, Margins(1.07, 0.15, bottom=0.756, top=0.42))
    ax1, ax2 = fig.subplots(
        2, 1, sharex=True, gridspec_kw=dict(height_ratios=(1.0, 1.25), hspace=0.07)
    )
    fig.suptitle(
        f"Fig. 8 ({_CITE}): steady sliding, computed  —  $R/h_2 = {par['R_over_h2']:g}$, "
        f"$h_1/h_2 = {r:g}$, $\\sigma_0/E = {s:g}$, $a/R = {a:g}$",
        fontsize=11,
    )
    zone_kw = dict(color="tab:orange", alpha=0.15, lw=0)
    for ax in (ax1, ax2):
        ax.axvspan(-c1, -a, **zone_kw)
        ax.axvspan(a, c2, **zone_kw)
        ax.axvspan(-a, a, color="tab:blue", alpha=0.08, lw=0)
        ax.grid(True, color="0.9", linewidth=0.6)
        ax.tick_params(labelsize=10)
        for xv in (-c1, -a, a, c2):
            ax.axvline(xv, color="0.55", lw=0.7, ls=":")
    # top: the gap
    ax1.plot(x, gap, color="k", lw=1.8)
    ax1.plot([-c1, -a], [r, r], color="tab:red", ls="--", lw=1.2)
    ax1.plot([a, c2], [1, 1], color="tab:green", ls="--", lw=1.2)
    ax1.plot([-c1], [r], "o", color="tab:red", ms=6)
    ax1.plot([c2], [1], "o", color="tab:green", ms=6)
    ax1.text(
        -0.5 * (c1 + a),
        r * 1.04,
        "$h_1$: trailing range",
        ha="center",
        va="bottom",
        color="tab:red",
        fontsize=10,
    )
    ax1.text(
        0.5 * (c2 + a),
        1.06,
        "$h_2$: leading range",
        ha="center",
        va="bottom",
        color="tab:green",
        fontsize=10,
    )
    ax1.set_ylabel("gap $g/h_2$", fontsize=12)
    ax1.set_ylim(-0.15 * r, 1.45 * r)
    ax1.annotate(
        "",
        xy=(hi * 0.95, 0.84 * 1.45 * r),
        xytext=(hi * 0.55, 0.84 * 1.45 * r),
        arrowprops=dict(arrowstyle="-|>", color="k", lw=1.5),
    )
    ax1.text(hi * 0.75, 0.87 * 1.45 * r, "sliding", ha="center", va="bottom", fontsize=10)
    ax1.text(
        -0.5 * (c1 + a), -0.1 * r, "trailing zone", ha="center", fontsize=9, color="tab:orange"
    )
    ax1.text(0.5 * (c2 + a), -0.1 * r, "leading zone", ha="center", fontsize=9, color="tab:orange")
    ax1.text(0.0, -0.1 * r, "contact", ha="center", fontsize=9, color="tab:blue")
    # bottom: the pressure
    ax2.axhline(0.0, color="0.3", lw=0.8)
    ax2.fill_between(x, 0.0, p, where=p >= 0, color="tab:blue", alpha=0.35, lw=0)
    ax2.fill_between(x, 0.0, p, where=p < 0, color="tab:orange", alpha=0.45, lw=0)
    ax2.plot(x, p, color="k", lw=1.6)
    xc = np.linspace(-a, a, 15)[1:-1]
    ax2.plot(
        xc,
        col.pressure(xc),
        "s",
        ms=4.5,
        mec="k",
        mew=0.5,
        color="0.6",
        label="collocation (Eq. 20)",
    )
    ax2.axvline(0.0, color="0.3", lw=0.8)
    ax2.axvline(e, color="tab:purple", lw=1.4, ls="-.")
    top = max(float(np.max(p)), 0.3 * s)
    ax2.annotate(
        f"apex (axis)\n$x = e = {e:.4f}R$",
        xy=(e, 0.5 * top),
        xytext=(a + 0.25 * (c2 - a), 0.75 * top),
        fontsize=10,
        color="tab:purple",
        va="center",
        arrowprops=dict(arrowstyle="->", color="tab:purple"),
    )
    txt = (
        f"$c_1/R = {c1:.4f}$, $c_2/R = {c2:.4f}$\n"
        f"$F/(Eh_2) = {st.F_over_Eh2:.4f}$\n"
        f"$M/(Eh_2R) = {st.M_over_Eh2R:.4f}$ (about the contact centre, clockwise $+$)\n"
        f"$(M - eF)/(Eh_2R) = {st.M_axis_over_Eh2R:.4f} = (\\sigma_0/E)(h_1/h_2-1)$"
    )
    ax2.text(
        0.01,
        0.97,
        txt,
        transform=ax2.transAxes,
        va="top",
        ha="left",
        fontsize=9,
        bbox=dict(boxstyle="round", fc="white", ec="0.7"),
    )
    ax2.set_ylabel("pressure $p/E$\n(compressive $+$)", fontsize=12)
    fig.align_ylabels((ax1, ax2))
    ax2.set_xlabel("$x/R$ (origin at the contact centre; the cylinder moves to $+x$)", fontsize=12)
    ax2.set_ylim(-1.6 * s, 1.35 * top)
    ax2.set_xlim(lo, hi)
    ax2.legend(loc="upper right", fontsize=9)
    for xv, lab in ((-c1, "$-c_1$"), (-a, "$-a$"), (a, "$a$"), (c2, "$c_2$")):
        ax2.text(xv, -1.5 * s, lab, ha="center", va="bottom", fontsize=10)
    return fig


def jobs() -> list[Job]:
    """The figures of Figs. 8--12; Figs. 9--12 draw the curves of one pull-off computation."""
    s_a, s_b = SIGMA0_OVER_E
    return [
        Job("fig08_sliding_schematic", _schematic, "fig08", 0.38),
        Job("fig09_zone_difference_s001", lambda r: _curve_figure(r, 9, s_a, "d"), "sliding", 0.4),
        Job("fig10_zone_difference_s004", lambda r: _curve_figure(r, 10, s_b, "d"), "sliding", 0.2),
        Job("fig11_moment_s001", lambda r: _curve_figure(r, 11, s_a, "M"), "sliding", 0.21),
        Job("fig12_moment_s004", lambda r: _curve_figure(r, 12, s_b, "M"), "sliding", 0.19),
    ]
