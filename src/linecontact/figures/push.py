r"""Figures of the pushed fibre (``docs/push.md``): motion maps and the lateral force.

Drawn by :func:`linecontact.figures.push_figures` (``linecontact figures``) with the
helpers of :mod:`linecontact.figures._style`; every number comes from
:func:`linecontact.push`.

Figures and parameters
----------------------
push01_motion_map_hysteresis
    The first motion over the push height ``H/R`` (0 to 2) and the hysteresis ``h1/h2``
    (1 to 4), at zero load, ``R/h2 = 100``, ``sigma0/E = 0.01``, ``tau0/E = 1e-3``
    (:data:`BASE`): regions slide / roll / roll+slide, and the boundary ``H*`` (rolling
    first above it).
push02_motion_map_friction
    The same over ``H/R`` and the friction stress ``tau0/E`` (1e-6 to 1e-2, log) at
    ``h1/h2 = 2``.
push03_lateral_force
    The lateral force a slowly pushed fibre resists, against the push's progress, for a
    push below ``H*`` (it slides) and above (it rolls): as the trailing edge stretches
    from the advancing state (0) to the receding one (1) the resistance rises, sliding
    from ``Q_onset = 2 a_rest tau0`` to ``Q_slide``, rolling from 0 to ``R dw / H``; then
    the motion is steady (beyond it). Each intermediate state is the steady sliding contact
    with the trailing range ``h'`` in ``[h2, h1]`` (``docs/push.md`` section 5). The tip's
    displacement an AFM records is not available: the plane-strain contact has no
    tangential stiffness (its displacement has no datum) and :func:`linecontact.tip_push`
    gives forces and a moment arm only. The abscissa is the nearest length the model has,
    the trailing edge's stretch ``(h' - h2)/h2`` (0 to ``h1/h2 - 1``), labelled as such.
"""

from __future__ import annotations

import numpy as np

from ..push import push
from ..sliding import sliding_contact_for_load
from ._style import Job, Margins, Run, _colors, _new_axes

__all__ = ["BASE", "jobs"]

#: R/h2, h1/h2, sigma0/E, tau0/E, F/(E h2) of the figures (a ZnO-like wire at zero load)
BASE = (100.0, 2.0, 0.01, 1e-3, 0.0)
_MARGINS = Margins(left=0.9, right=2.4)
_MOTIONS = ("slide", "roll", "roll+slide")
_REGION_COLORS = ("#d9843b", "#4c8bbf", "#9b6fb0")


def _boundaries(p):
    """The computed region boundaries of a map row by row: ``(H*, H_hold)`` over ``R``.

    ``H* = R dw / Q_slide`` (rolling first above it, :attr:`Push.H_critical_over_R`); above
    the axis the rolling contact holds its shear ``|S_roll| = dw (H - R)/H`` while it is
    below ``2 a_slide tau0``, up to ``H_hold = R dw / (dw - 2 a_slide tau0)`` (``inf`` where
    ``dw`` is not larger: it always holds). Below the axis it holds wherever rolling comes
    first (``dw (R - H)/H < 2 a_slide tau0`` iff ``H > H*``). The parts are the API's.
    """
    hstar = np.asarray(p.H_critical_over_R, float)[:, 0]
    dw = np.asarray(p.hysteresis_over_Eh2, float)[:, 0]
    fr = np.asarray(p.friction_over_Eh2, float)[:, 0]
    with np.errstate(divide="ignore", invalid="ignore"):
        hold = np.where(dw > fr, dw / (dw - fr), np.inf)
    return hstar, hold


def _map(run: Run, y_name: str, ys, ylabel: str, log: bool, title: str):
    rho, r, s, tau, F = BASE
    H = np.linspace(0.0, 2.0, 101)
    Hg, Yg = np.meshgrid(H, ys)
    args = {"h1_over_h2": r, "tau0_over_E": tau, y_name: Yg}
    p = run.data(
        ("push-map", y_name),
        lambda: push(rho, args["h1_over_h2"], s, args["tau0_over_E"], F, Hg),
        f"the motion map over H/R and {y_name}",
    )
    fig, ax = _new_axes(run, _MARGINS, title, r"push height $H/R$", ylabel)
    hstar, hold = _boundaries(p)
    x_max = 2.0
    top = np.minimum(hold, x_max)
    # the regions, filled between the computed boundaries (no pixels): slide below H*, roll
    # from H* to H_hold, roll+slide above H_hold; one legend entry per region drawn
    spans = {
        "slide": (np.zeros_like(hstar), np.minimum(hstar, x_max)),
        "roll": (np.minimum(hstar, x_max), top),
        "roll+slide": (top, np.full_like(top, x_max)),
    }
    for m, c in zip(_MOTIONS, _REGION_COLORS, strict=True):
        lo, hi = spans[m]
        if np.any(hi > lo):
            ax.fill_betweenx(
                ys,
                lo,
                hi,
                where=hi > lo,
                interpolate=True,
                color=c,
                lw=0,
                label=f"first motion: {m}",
            )
    ax.plot(hstar, ys, color="k", lw=1.6, label=r"$H^* = R\,\Delta w / Q_{slide}$")
    if np.any(hold < x_max):
        held = hold < x_max
        ax.plot(
            np.where(held, hold, np.nan),
            ys,
            color="k",
            lw=1.2,
            ls="--",
            label=r"$|S_{roll}| = 2 a_{slide} \tau_0$",
        )
    ax.axvline(1.0, color="0.3", lw=0.8, ls=":", label="the axis")
    if log:
        ax.set_yscale("log")
    ax.set_xlim(0, x_max)
    ax.set_ylim(ys[0], ys[-1])
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=9, frameon=False)
    return fig


def _hysteresis_map(run: Run):
    rho, r, s, tau, F = BASE
    return _map(
        run,
        "h1_over_h2",
        np.linspace(1.0, 4.0, 61),
        r"receding over advancing range $h_1/h_2$",
        False,
        rf"pushed fibre: first motion ($R/h_2$ = {rho:g}, $\sigma_0/E$ = {s:g}, "
        rf"$\tau_0/E$ = {tau:g}, $F$ = 0)",
    )


def _friction_map(run: Run):
    rho, r, s, tau, F = BASE
    return _map(
        run,
        "tau0_over_E",
        np.geomspace(1e-6, 1e-2, 61),
        r"friction stress $\tau_0/E$",
        True,
        rf"pushed fibre: first motion ($R/h_2$ = {rho:g}, $h_1/h_2$ = {r:g}, "
        rf"$\sigma_0/E$ = {s:g}, $F$ = 0)",
    )


def transition(n: int = 41):
    """The resistance of the stretching trailing edge: progress, Q_slide(h'), dw(h').

    Returns ``(x, friction, hysteresis)`` over the progress ``x = (h' - h2)/(h1 - h2)``:
    ``friction = 2 a(h') tau0`` and ``hysteresis = sigma0 (h' - h2)``, forces over
    ``E h2`` (the sliding contact with the trailing range ``h'`` at the load of
    :data:`BASE`).
    """
    rho, r, s, tau, F = BASE
    x = np.linspace(0.0, 1.0, n)
    ratios = 1.0 + x * (r - 1.0)
    a = sliding_contact_for_load(F, rho, ratios, s, method="closed-form").a_over_R
    return x, 2 * np.asarray(a) * rho * tau, s * (ratios - 1.0)


def _lateral_force(run: Run):
    rho, r, s, tau, F = BASE
    x, friction, hyst = run.data("push-transition", transition, "the trailing edge's stretch")
    steady = push(rho, r, s, tau, F, [0.3, 1.5])
    H_slide, H_roll = 0.3, 1.5
    fig, ax = _new_axes(
        run,
        _MARGINS,
        rf"lateral force of a slowly pushed fibre ($R/h_2$ = {rho:g}, $h_1/h_2$ = {r:g}, "
        rf"$\sigma_0/E$ = {s:g}, $\tau_0/E$ = {tau:g})",
        r"trailing edge's stretch $(h' - h_2)/h_2$, then steady (not the tip's travel)",
        r"lateral force $Q/(E h_2)$",
    )
    c_slide, c_roll = _colors(2)
    # the stretch over h2 (the nearest length to the tip's travel), then steady motion
    xs = np.concatenate([x, [1.5]]) * (r - 1.0)
    q_slide = np.concatenate([friction + hyst, [friction[-1] + hyst[-1]]])
    q_roll = np.concatenate([hyst / H_roll, [hyst[-1] / H_roll]])
    ax.plot(xs, q_slide, color=c_slide, lw=2, label=f"$H$ = {H_slide:g} R: slides")
    ax.plot(xs, q_roll, color=c_roll, lw=2, label=f"$H$ = {H_roll:g} R: rolls")
    for value, color, ls, label in (
        (steady.Q_slide_over_Eh2, c_slide, "--", r"$Q_{slide}$"),
        (steady.Q_roll_over_Eh2, c_roll, "--", r"$Q_{roll}$"),
        (steady.Q_onset_over_Eh2, "0.4", ":", r"$Q_{onset} = 2 a_{rest} \tau_0$"),
    ):
        i_case = 1 if label == r"$Q_{roll}$" else 0  # the rolling case is the second point
        ax.axhline(float(np.asarray(value)[i_case]), color=color, lw=0.8, ls=ls, label=label)
    ax.set_xlim(0, 1.5 * (r - 1.0))
    ax.set_ylim(0, 1.1 * float(q_slide.max()))
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=9, frameon=False)
    return fig


def jobs() -> list[Job]:
    """The pushed-fibre figures."""
    return [
        Job("push01_motion_map_hysteresis", _hysteresis_map, "push-maps", 0.6),
        Job("push02_motion_map_friction", _friction_map, "push-maps", 0.6),
        Job("push03_lateral_force", _lateral_force, "push-force", 0.3),
    ]
