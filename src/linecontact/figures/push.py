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
    the motion is steady (beyond 1). Each intermediate state is the steady sliding contact
    with the trailing range ``h'`` in ``[h2, h1]`` (``docs/push.md`` section 5), and the
    abscissa is ``(h' - h2)/(h1 - h2)``; the plane-strain contact has no tangential
    stiffness (its displacement has no datum), so no distance is drawn.
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
    code = np.select([p.first_motion == m for m in _MOTIONS], [0, 1, 2], default=-1)
    fig, ax = _new_axes(run, _MARGINS, title, r"push height $H/R$", ylabel)
    colors = ["#d9843b", "#4c8bbf", "#9b6fb0"]
    from matplotlib.colors import ListedColormap

    ax.pcolormesh(Hg, Yg, code, cmap=ListedColormap(colors), vmin=-0.5, vmax=2.5, shading="auto")
    hstar = np.asarray(p.H_critical_over_R)[:, 0]
    ax.plot(hstar, ys, color="k", lw=1.6, label=r"$H^* = R\,\Delta w / Q_{slide}$")
    ax.axvline(1.0, color="0.3", lw=0.8, ls=":", label="the axis")
    if log:
        ax.set_yscale("log")
    ax.set_xlim(0, 2)
    for m, c in zip(_MOTIONS, colors, strict=True):
        ax.fill_between([], [], color=c, label=f"first motion: {m}")
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
        r"push progress: trailing edge stretched $(h' - h_2)/(h_1 - h_2)$, then steady",
        r"lateral force $Q/(E h_2)$",
    )
    c_slide, c_roll = _colors(2)
    xs = np.concatenate([x, [1.5]])
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
    ax.set_xlim(0, 1.5)
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
