r"""An AFM tip on silica: which model, and the pull-off of a sharp and a blunt tip
==============================================================================

A silicon AFM tip (radius 10 nm to 1 µm) on silica, work of adhesion 0.1 J/m²,
:math:`z_0` = 0.3 nm (illustrative; the moduli are the presets of :mod:`linecontact.presets`):
its Maugis parameter, its pull-off from the Maugis–Dugdale sphere against JKR's
:math:`-\tfrac32\pi w R` and DMT's :math:`-2\pi w R`, the self-consistent Lennard-Jones
sphere's where Tabor's parameter allows (:func:`linecontact.sphere_lj_pull_off`), and the
contact radius against the load for a sharp and a blunt tip.

Run: ``python examples/afm_tip.py [tip.png]`` (the figure is saved where a path is given).
"""

import sys
import warnings

import matplotlib

matplotlib.use("Agg")  # files only, never a window
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import linecontact as lc  # noqa: E402

# %%
# The tips
# --------
# :class:`~linecontact.Sphere` is built as a wire is: here from presets (its material is
# the first). Si on SiO2 couples normal and tangential tractions a little (Dundurs beta
# 0.17); linecontact solves the uncoupled case and says so with a CouplingWarning.
warnings.simplefilter("ignore", lc.CouplingWarning)
ADHESION = dict(work_of_adhesion=0.1, equilibrium_spacing=0.3e-9)  # J/m^2, m (illustrative)
RADII = np.geomspace(10e-9, 1e-6, 9)  # m
w = ADHESION["work_of_adhesion"]

# %%
# Which model, and the pull-off
# -----------------------------
# :func:`~linecontact.sphere_models` names the regime and gives each simple model's error
# against the Maugis–Dugdale sphere; the pull-off is in units of :math:`\pi w R`.
print("R [nm]  lambda   mu_T   regime      best  MD pull-off  JKR err  DMT err  LJ pull-off")
pulls, lj_pulls = [], []
for R in RADII:
    tip = lc.Sphere.from_presets(R, "Si", "SiO2", **ADHESION)
    p = tip.pull_off()
    P = p.pull_off_force / (np.pi * w * R)
    m = lc.sphere_models(0.0, tip.R_over_h, tip.sigma0_over_E)
    lj, P_lj = "  (mu_T > 5)", np.nan
    if tip.tabor_parameter <= 5:
        P_lj = tip.under(lc.LennardJones).pull_off().pull_off_force / (np.pi * w * R)
        lj = f"{P_lj:11.4f}"
    print(
        f"{R * 1e9:6.0f}  {tip.maugis_parameter:6.3f}  {tip.tabor_parameter:5.3f}  "
        f"{m.regime:10s}  {m.best:4s}  {P:11.4f}  {m.pull_off_error_jkr:+7.3f}  "
        f"{m.pull_off_error_dmt:+7.3f}  {lj}"
    )
    pulls.append(P)
    lj_pulls.append(P_lj)

# %%
# The contact radius against the load
# ------------------------------------
# A sharp (10 nm) and a blunt (1 µm) tip, from their pull-off up to ten times its size in
# compression: the Maugis–Dugdale sphere, in units of the pull-off and of the radius at zero
# load (the sharper tip, nearer DMT, lets go from a smaller share of its contact).
fig, (ax_p, ax_a) = plt.subplots(1, 2, figsize=(10, 4), layout="constrained")
ax_p.semilogx(RADII * 1e9, pulls, "o-", label="Maugis-Dugdale")
ax_p.semilogx(RADII * 1e9, lj_pulls, "s-", label="Lennard-Jones (self-consistent)")
ax_p.axhline(-1.5, ls="--", color="grey", label="JKR")
ax_p.axhline(-2.0, ls=":", color="grey", label="DMT")
ax_p.set(xlabel="tip radius R [nm]", ylabel="pull-off F / (pi w R)", title="(a) pull-off")
ax_p.legend(fontsize="small")
for R, style in ((10e-9, "-"), (1e-6, "--")):
    tip = lc.Sphere.from_presets(R, "Si", "SiO2", **ADHESION)
    Fc = tip.pull_off().pull_off_force
    loads = np.linspace(Fc, -10 * Fc, 80)
    a = tip.contact(load=loads).contact_radius
    a0 = tip.contact(load=0.0).contact_radius
    lam = tip.maugis_parameter
    ax_a.plot(loads / -Fc, a / a0, style, label=f"R = {R * 1e9:g} nm (lambda {lam:.2f})")
ax_a.set(
    xlabel="load F / |F_pull-off|",
    ylabel="contact radius a / a(F = 0)",
    title="(b) contact radius against load",
)
ax_a.legend(fontsize="small")
fig.suptitle("a Si tip on SiO2, w = 0.1 J/m², z0 = 0.3 nm")
if len(sys.argv) > 1:
    fig.savefig(sys.argv[1], dpi=150)
