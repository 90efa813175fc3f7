r"""A nanowire pushed sideways: the push that rolls it and the push that slides it
===============================================================================

A 50 nm ZnO wire on silica (work of adhesion 0.3 J/m², :math:`z_0` = 0.3 nm, the receding
range twice the advancing one, shear strength 10 MPa), pushed at heights from its foot to its
top: rolling resists :math:`Q_{\mathrm{roll}} = R\,\Delta w / H`, sliding
:math:`Q_{\mathrm{slide}} = 2 a \tau_0 + \Delta w`; the lower one is its first motion, and
the critical height :math:`H^*` parts them.

Run: ``python examples/push_resistance.py [push.png]`` (the figure is saved where a path is
given).
"""

import sys
import warnings

import matplotlib

matplotlib.use("Agg")  # files only, never a window
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.ticker import FormatStrFormatter  # noqa: E402

import linecontact as lc  # noqa: E402

# %%
# The wire and the heights
# ------------------------
# The push acts at a height :math:`H` above the substrate, from near the wire's foot to its
# top (:math:`2R`). A receding range twice the advancing one makes the adhesion hysteretic:
# :math:`\Delta w = w_1 - w_2` is the difference of the two works of adhesion, receding minus
# advancing.

warnings.simplefilter("ignore", lc.CouplingWarning)  # ZnO on silica: |beta| = 0.19
R = 50e-9
cyl = lc.Cylinder.from_presets(R, "ZnO", "SiO2", work_of_adhesion=0.3, equilibrium_spacing=3e-10)
H = np.linspace(5e-9, 2 * R, 40)

# %%
# Rolling or sliding
# ------------------
# Rolling resists :math:`Q_{\mathrm{roll}} = R\,\Delta w / H`, sliding
# :math:`Q_{\mathrm{slide}} = 2 a \tau_0 + \Delta w`; the lower one is the first motion, and
# the critical height :math:`H^*` is where they are equal.

p = cyl.push(friction_stress=1e7, height=H, receding_range=2 * cyl.adhesion_range)
print(f"critical height H* = {float(np.ravel(p.critical_height)[0]) * 1e9:.1f} nm")
for h, motion, q_roll, q_slide in zip(
    H[::13],
    p.first_motion[::13],
    p.rolling_resistance[::13],
    p.sliding_resistance[::13],
    strict=True,
):
    print(f"H = {h * 1e9:5.1f} nm: {motion:5s}  Q_roll {q_roll:.3g} N/m, Q_slide {q_slide:.3g} N/m")

# %%
# The two resistances against the push height
# -------------------------------------------
# Below :math:`H^*` the push slides the wire first, above it the push rolls it first; near
# its top, ``roll+slide``: rolling comes first but needs more shear than the contact holds.

fig, ax = plt.subplots(figsize=(6.4, 3.6), layout="constrained")
ax.plot(H * 1e9, p.rolling_resistance, label="rolling resistance Q_roll")
ax.plot(H * 1e9, np.broadcast_to(p.sliding_resistance, H.shape), label="sliding resistance Q_slide")
ax.axvline(float(np.ravel(p.critical_height)[0]) * 1e9, color="0.4", ls="--", label="H*")
ax.set(
    xlabel="push height H [nm]",
    ylabel="push per length Q [N/m]",
    yscale="log",
    title="ZnO wire (R = 50 nm) on SiO2",
)
ax.yaxis.set_major_formatter(FormatStrFormatter("%g"))  # 0.4, not 4x10^-1
ax.yaxis.set_minor_formatter(FormatStrFormatter("%g"))
ax.legend()
if len(sys.argv) > 1:
    fig.savefig(sys.argv[1], dpi=150)
