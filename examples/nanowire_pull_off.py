"""Pull-off force and contact width of a silica nanowire on a silicon wafer, in SI units
=====================================================================================

A 50 nm fused-silica wire lies on a (100) silicon wafer, adhesion by van der Waals forces.
The moduli are handbook values: fused silica E = 72.7 GPa, nu = 0.16 (Corning HPFS 7980
product information); silicon in the [100] direction E = 130 GPa, nu = 0.28 (M. A. Hopcroft,
W. D. Nix, T. W. Kenny, "What is the Young's modulus of silicon?", J. Microelectromech. Syst.
19 (2010) 229, doi:10.1109/JMEMS.2009.2039697). The work of adhesion (0.1 J/m^2) and the
equilibrium spacing (0.3 nm) are illustrative.

Run: ``python examples/nanowire_pull_off.py [width.png]`` (with a path, the contact
half-width against the load is drawn there; matplotlib).
"""

import sys
import warnings

import numpy as np

import linecontact as lc

# %%
# The wire
# --------
# :meth:`linecontact.Cylinder.from_materials` takes the radius, both bodies' Young's moduli
# and Poisson's ratios, and the adhesion as a work of adhesion :math:`w` and an equilibrium
# spacing :math:`z_0`; it derives the composite modulus, the Dugdale stress
# :math:`\sigma_0` and range :math:`h` (:math:`w = \sigma_0 h`) and the Maugis parameter
# :math:`\lambda`, which names the regime.

RADIUS = 50e-9  # m
LENGTH = 5e-6  # m, the wire's length (forces below are per unit length, then totals)

# silica on silicon couples normal and tangential tractions a little (Dundurs beta ~ -0.2);
# linecontact solves the uncoupled case and says so with a CouplingWarning
with warnings.catch_warnings():
    warnings.simplefilter("ignore", lc.CouplingWarning)
    wire = lc.Cylinder.from_materials(
        RADIUS, 72.7e9, 0.16, 130e9, 0.28, work_of_adhesion=0.1, equilibrium_spacing=0.3e-9
    )

print(f"composite modulus E*        : {wire.modulus / 1e9:.2f} GPa")
print(
    f"Dugdale stress, range       : {wire.cohesive_stress / 1e9:.3f} GPa, "
    f"{wire.adhesion_range * 1e9:.3f} nm"
)
print(f"Maugis parameter (lambda)   : {wire.maugis_parameter:.3f}  (DMT-like << 1 << JKR-like)")
print(f"Dundurs beta                : {wire.dundurs_beta:.3f}")

# %%
# The pull-off
# ------------
# The most tensile load the contact carries under load control, per unit length of the wire
# and on the whole wire, and how it lets go: peeling to zero width or snapping off at a
# finite one.

po = wire.pull_off()
print(
    f"pull-off force              : {po.pull_off_force:.4g} N/m, "
    f"{po.pull_off_force * LENGTH * 1e6:.4g} uN on a {LENGTH * 1e6:g} um wire"
)
print(
    f"mechanism                   : {po.mechanism} "
    f"(contact half-width there {po.contact_half_width_at_pull_off * 1e9:.3g} nm)"
)
print(f"zero-width load (Eq 14)     : {po.zero_width_force:.4g} N/m")

# %%
# The contact width under a load
# ------------------------------
# :meth:`~linecontact.Cylinder.contact` takes loads in N/m (vectorised): the contact
# half-width :math:`a` and the end :math:`c` of the adhesive zone around it.

# contact half-width from just above pull-off up to a load of a few times its magnitude
loads = np.array([-0.95, -0.5, 0.0, 1.0, 3.0]) * abs(po.pull_off_force)  # N/m
contact = wire.contact(load=loads)
print("\n  load [N/m]   total [uN]   contact half-width a [nm]   adhesive zone c [nm]")
for F, a, c in zip(
    loads, contact.contact_half_width, contact.adhesive_zone_half_width, strict=True
):
    print(f"  {F:10.4g}   {F * LENGTH * 1e6:10.4g}   {a * 1e9:25.4f}   {c * 1e9:20.4f}")

# %%
# The contact width against the load
# ----------------------------------
# With a path argument, the stable contact from just above the pull-off force to three times
# its magnitude, drawn with matplotlib.

if len(sys.argv) > 1:
    import matplotlib

    matplotlib.use("Agg")  # files only, never a window
    import matplotlib.pyplot as plt

    F = np.linspace(0.99, -3.0, 200) * po.pull_off_force  # N/m, from the pull-off upwards
    a = wire.contact(load=F).contact_half_width
    fig, ax = plt.subplots(figsize=(6.4, 3.6), layout="constrained")
    ax.plot(F, a * 1e9, label="stable contact")
    ax.plot(loads, contact.contact_half_width * 1e9, "o", label="the loads printed")
    ax.axvline(po.pull_off_force, color="0.4", ls="--", label="pull-off force")
    ax.set(
        xlabel="load F [N/m] (compressive positive)",
        ylabel="contact half-width a [nm]",
        title="SiO2 wire (R = 50 nm) on Si, w = 0.1 J/m², z0 = 0.3 nm",
    )
    ax.legend()
    fig.savefig(sys.argv[1], dpi=150)
