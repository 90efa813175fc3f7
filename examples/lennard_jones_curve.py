"""The Lennard-Jones law against the Maugis-Dugdale step: two load curves, one contact
====================================================================================

The paper's groups (R/h = 100, sigma0/E = 0.01): the load against the contact half-width
under the Dugdale step (closed form) and under the Lennard-Jones law of Eq 1 solved
self-consistently (matched: the same work of adhesion and peak tension), with their pull-off
forces.

Run: ``python examples/lennard_jones_curve.py [lj.png]`` (the figure is saved where a path
is given).
"""

import sys

import matplotlib

matplotlib.use("Agg")  # files only, never a window
import matplotlib.pyplot as plt  # noqa: E402

from linecontact.laws import dugdale, lennard_jones  # noqa: E402

# %%
# The two laws, matched
# ---------------------
# Each adhesion law is a module of :mod:`linecontact.laws` with the same functions in the
# paper's groups: :math:`R/h` and :math:`\sigma_0/E`. The Dugdale step has a closed form;
# the Lennard-Jones law is solved self-consistently, with the same work of adhesion and the
# same peak tension.

R_OVER_H, S = 100.0, 0.01
md = dugdale.load_curve(R_OVER_H, S, a_max_over_R=0.1)
lj = lennard_jones.load_curve(R_OVER_H, S)

# %%
# Their pull-off forces
# ---------------------
# The pull-off is the most tensile load on the contact branch, :math:`F/(Eh)`.

po_md = dugdale.pull_off(R_OVER_H, S).F_pulloff_over_Eh
po_lj = lennard_jones.pull_off(R_OVER_H, S).F_pulloff_over_Eh
print(f"pull-off F/(Eh): Maugis-Dugdale {po_md:.4f}, Lennard-Jones {po_lj:.4f}")

# %%
# The two load curves
# -------------------
# The load against the contact half-width :math:`a/R`, each law's pull-off as a thin line.

fig, ax = plt.subplots(figsize=(6.4, 3.6), layout="constrained")
contact = md.branch == "contact"
ax.plot(md.a_over_R[contact], md.F_over_Eh[contact], label="Maugis-Dugdale (Dugdale step)")
ax.plot(lj.a_over_R, lj.F_over_Eh, "--", label="Lennard-Jones law (Eq 1)")
ax.axhline(po_md, color="C0", lw=0.6)
ax.axhline(po_lj, color="C1", lw=0.6)
ax.set(
    xlabel="contact half-width a/R",
    ylabel="load F/(E h)",
    xlim=(0, 0.1),
    title="R/h = 100, sigma0/E = 0.01",
)
ax.legend()
if len(sys.argv) > 1:
    fig.savefig(sys.argv[1], dpi=150)
