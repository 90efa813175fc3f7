"""Creep of a rolling nanowire against the normal load, with constant interfacial shear
====================================================================================

The silica wire on silicon of ``nanowire_pull_off.py`` is driven in steady rolling (a torque
turns it) by a fixed tractive force T = 0.03 N/m, at normal loads from near the pull-off
force up to three times its magnitude. With the nano-scale friction law (constant shear
stress tau0 in the slip zone) the full-slip load 2 a tau0 grows with the contact width, so
the stick zone grows and the creep falls as the load rises; adhesion alone (zero load)
already holds a contact that can transmit T. Carter's solution for Coulomb friction on the
same wire without adhesion is shown for contrast (mu chosen so that mu F = 2 a tau0 at the
middle load): without adhesion it needs a normal load above T/mu to roll at all (below it,
linecontact reports the state "sliding").

The shear strength tau0 = 50 MPa is illustrative.

Run: ``python examples/rolling_creep.py [creep.png]`` (with a path, the creep against the
load is drawn there; matplotlib).
"""

import sys
import warnings

import numpy as np

import linecontact as lc

# %%
# The wire and the loads
# ----------------------
# The silica wire on silicon, a shear strength :math:`\tau_0` = 50 MPa, a tractive force
# :math:`T` = 0.03 N/m, and eight normal loads from near the pull-off force up to three times
# its magnitude.

with warnings.catch_warnings():
    warnings.simplefilter("ignore", lc.CouplingWarning)
    wire = lc.Cylinder.from_materials(
        50e-9, 72.7e9, 0.16, 130e9, 0.28, work_of_adhesion=0.1, equilibrium_spacing=0.3e-9
    )
TAU0 = 50e6  # Pa
T = 0.03  # N/m, the tractive force
F_po = wire.pull_off().pull_off_force  # N/m, negative
loads = np.linspace(0.9 * F_po, 3 * abs(F_po), 8)  # N/m, vectorised over the loads

# %%
# Steady rolling with adhesion
# ----------------------------
# :meth:`~linecontact.Cylinder.steady_rolling`, vectorised over the loads: the contact
# half-width, the share :math:`T/(2 a \tau_0)` of the full-slip load, where the stick zone
# starts, and the creep :math:`(V - \omega R)/V`.

# a load whose full-slip force 2 a tau0 is below T slides: reported, not raised
roll = wire.steady_rolling(loads, friction_stress=TAU0, tangential_load=T, on_failure="report")
a = roll.contact_half_width
print(f"steady rolling with adhesion, tau0 = {TAU0 / 1e6:g} MPa, T = {T} N/m")
print("  F [N/m]    a [nm]   T/(2 a tau0)   stick zone from d/a   creep (V - wR)/V")
for F, ai, full, d, cr in zip(
    loads, a, roll.full_slip_load, roll.stick_zone_end / a, roll.creep_ratio, strict=True
):
    print(f"  {F:7.3f}   {ai * 1e9:7.3f}   {T / full:12.4f}   {d:19.4f}   {cr:16.4e}")

# %%
# Carter's solution without adhesion
# ----------------------------------
# Coulomb friction on the Hertz contact of the same wire, :math:`\mu` chosen so that
# :math:`\mu F = 2 a \tau_0` at the middle load: it rolls only above :math:`F = T/\mu`.

# Carter: Coulomb friction on the Hertz contact of the same wire without adhesion
hertz = lc.Cylinder.from_modulus(
    wire.radius, wire.modulus, cohesive_stress=0.0, adhesion_range=wire.adhesion_range
)
positive = loads[loads > 0]
F_mid = positive[len(positive) // 2]
mu = 2 * hertz.contact(load=F_mid).contact_half_width * TAU0 / F_mid
carter = hertz.steady_rolling(
    positive, friction_coefficient=mu, tangential_load=T, on_failure="report"
)
print(
    f"\nCarter (Coulomb friction mu = {mu:.3f}, no adhesion), T = {T} N/m: rolls for F > "
    f"T/mu = {T / mu:.3f} N/m"
)
print("  F [N/m]    a [nm]   state        creep (V - wR)/V")
for F, ai, st, cr in zip(
    positive, carter.contact_half_width, carter.state, carter.creep_ratio, strict=True
):
    print(f"  {F:7.3f}   {ai * 1e9:7.3f}   {st:10s}   {cr:16.4e}")

# %%
# The creep against the load
# --------------------------
# With a path argument: the magnitude of the creep of both, on a logarithmic axis.

if len(sys.argv) > 1:
    import matplotlib

    matplotlib.use("Agg")  # files only, never a window
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 3.6), layout="constrained")
    ax.semilogy(loads, np.abs(roll.creep_ratio), "o-", label=f"adhesion, tau0 = {TAU0 / 1e6:g} MPa")
    rolls = np.isfinite(carter.creep_ratio)  # "sliding" below T/mu has no creep
    ax.semilogy(
        positive[rolls], np.abs(carter.creep_ratio[rolls]), "s--", label=f"Carter, mu = {mu:.3f}"
    )
    ax.axvline(T / mu, color="0.4", lw=0.8, ls=":", label="T/mu")
    ax.set(
        xlabel="normal load F [N/m]",
        ylabel="creep |V - wR|/V",
        title=f"SiO2 wire (R = 50 nm) on Si rolling, T = {T} N/m",
    )
    ax.legend()
    fig.savefig(sys.argv[1], dpi=150)
