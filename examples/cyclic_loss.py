"""The energy a nanowire contact loses per cycle of a tangential load
===================================================================

A 50 nm ZnO wire on silica under 1 N/m, loaded back and forth: the energy dissipated per cycle
in the slip zones against the amplitude, with the nano-scale friction law (constant shear
stress 10 MPa in the slip zones), up to full slip.

Run: ``python examples/cyclic_loss.py [loss.png]`` (the figure is saved where a path is
given).
"""

import sys
import warnings

import matplotlib

matplotlib.use("Agg")  # files only, never a window
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import linecontact as lc  # noqa: E402

# %%
# The wire and its full-slip load
# -------------------------------
# ZnO on silica couples the normal and the tangential tractions a little (Dundurs
# :math:`\beta = -0.19`); linecontact solves the uncoupled problem and says so with a
# :class:`~linecontact.CouplingWarning`, silenced here. The tangential load that makes the
# whole contact slip, :math:`T^*_{\mathrm{full}}`, bounds the amplitudes.

warnings.simplefilter("ignore", lc.CouplingWarning)  # ZnO on silica: |beta| = 0.19
cyl = lc.Cylinder.from_presets(
    50e-9, "ZnO", "SiO2", work_of_adhesion=0.3, equilibrium_spacing=3e-10
)
full = cyl.cyclic_loss(1.0, [1e-3], friction_stress=1e7).full_slip_load
print(f"full slip at T* = {float(np.ravel(full)[0]):.4g} N/m")

# %%
# The energy lost per cycle
# -------------------------
# Thirty amplitudes from a thousandth of the full-slip load to 95 % of it, in one
# vectorised call: between :math:`-T^*` and :math:`+T^*` the slip zones grow inwards from
# the contact's edges and dissipate :math:`W` per cycle and per unit length of the wire.

amplitude = np.geomspace(1e-3, 0.95, 30) * float(np.ravel(full)[0])
c = cyl.cyclic_loss(1.0, amplitude, friction_stress=1e7)
for t, w in zip(amplitude[::10], c.energy_per_cycle[::10], strict=True):
    print(f"T* = {t:.3g} N/m: {w:.3g} J/m per cycle")

# %%
# The figure
# ----------
# At these amplitudes a tenfold amplitude loses about ten thousand times the energy (the
# printed rows): the slip zones and the slip in them grow together.

fig, ax = plt.subplots(figsize=(6.4, 3.6), layout="constrained")
ax.loglog(amplitude, c.energy_per_cycle, "o-", ms=3)
ax.set(
    xlabel="amplitude T* [N/m]",
    ylabel="energy lost per cycle W [J/m]",
    title="ZnO wire (R = 50 nm) on SiO2 under 1 N/m, tau0 = 10 MPa",
)
if len(sys.argv) > 1:
    fig.savefig(sys.argv[1], dpi=150)
