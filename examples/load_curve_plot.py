"""The whole load curve of an adhesive line contact, plotted: stable, unstable, pull-off
======================================================================================

Two parameter sets of the paper's groups (R/h = 100): weak adhesion, which peels to zero
width at the load of Eq 14, and strong adhesion, which snaps off at a finite width. Solid:
stable under load control; dotted: unstable; circles:
pull-off; dashed: Hertz.

Run: ``python examples/load_curve_plot.py [out.png]`` (default ``load_curve.png``).
"""

import sys

import matplotlib

matplotlib.use("Agg")  # files only, never a window
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import linecontact as lc  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "load_curve.png"
R_OVER_H = 100.0

# %%
# Two adhesions, one call each
# ----------------------------
# :func:`linecontact.load_curve` samples the whole curve of the load :math:`F/(Eh)` against
# the contact half-width :math:`a/R`, with its stability under load control and its
# pull-off. The weak adhesion (:math:`\sigma_0/E = 0.02`) peels to zero width at the load of
# Eq 14; the strong one (:math:`\sigma_0/E = 0.2`) snaps off at a finite width.

fig, ax = plt.subplots(figsize=(7.5, 4.8))
for s, color in ((0.02, "tab:blue"), (0.2, "tab:red")):
    c = lc.load_curve(R_OVER_H, s, a_max_over_R=0.2)
    contact = c.branch == "contact"
    a, F, stable = c.a_over_R[contact], c.F_over_Eh[contact], c.stable[contact]
    ax.plot(a[stable], F[stable], color=color, lw=2, label=f"sigma0/E = {s:g}")
    ax.plot(a[~stable], F[~stable], color=color, lw=2, ls=":")
    po = c.pulloff
    ax.plot(po.a_over_R_at_pulloff, po.F_pulloff_over_Eh, "o", mfc="none", ms=9, color=color)
    print(
        f"sigma0/E = {s:g}: pull-off F/(Eh) = {po.F_pulloff_over_Eh:.4f} ({po.mechanism}) "
        f"at a/R = {po.a_over_R_at_pulloff:.3g}; Eq 14 gives {po.F_zero_width_over_Eh:.4f}"
    )

# %%
# Hertz for reference
# -------------------
# Without adhesion the load is Hertz's, :math:`F/(Eh) = (\pi/4)(a/R)^2 (R/h)` (Eq 13).

a = np.linspace(0, 0.2, 200)
ax.plot(a, lc.hertz_load(np.maximum(a, 1e-12), R_OVER_H), "k--", lw=1, label="Hertz (Eq 13)")
ax.axhline(0, color="0.5", lw=0.6)
ax.set_xlabel("contact half-width a/R")
ax.set_ylabel("load F/(E h)")
ax.set_ylim(-3.2, 4)
ax.set_title(f"Maugis-Dugdale line contact, R/h = {R_OVER_H:g}")
ax.legend(loc="upper left")
fig.tight_layout()
fig.savefig(out, dpi=120)
