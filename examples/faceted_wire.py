r"""Faceted nanowires: a hexagonal ZnO and a pentagonal Ag wire on silica
=====================================================================

Many nanowires are not round: ZnO, GaN and InAs wires grow hexagonal, twinned Ag and Au
wires pentagonal, and they lie on a facet. A 50 nm (circumradius) hexagonal ZnO wire and a
pentagonal Ag wire on silica (work of adhesion 0.1 J/m², :math:`z_0` = 0.3 nm, both
illustrative; the moduli are the presets of :mod:`linecontact.presets`), their corners sharp
or rounded with a radius :math:`r_c`, against the round wire of the same radius: the
pull-off force and the contact width at zero load, from the Maugis–Dugdale contact of a
regular polygon on its facet (:func:`linecontact.facet_pull_off`).

Run: ``python examples/faceted_wire.py [faceted.png]`` (the figure is saved where a path is
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
# The two wires
# -------------
# :meth:`~linecontact.Cylinder.shaped` gives the same wire (radius, modulus, adhesion) a
# cross-section: :class:`~linecontact.Polygon` ``(sides, corner_radius)``, its radius the
# circumradius :math:`R` and the corner radius in metres (0 a sharp corner, :math:`R` the
# round wire). It lies on a facet whose flat part is :math:`2 (R - r_c) \sin(\pi/n)` wide.

# ZnO and Ag on silica couple normal and tangential tractions a little (Dundurs beta 0.19
# and 0.13); linecontact solves the uncoupled case and says so with a CouplingWarning
warnings.simplefilter("ignore", lc.CouplingWarning)
R = 50e-9  # m, the circumradius
ADHESION = dict(work_of_adhesion=0.1, equilibrium_spacing=0.3e-9)  # J/m^2, m (illustrative)
WIRES = {  # name: (the round wire of the two materials, sides)
    "hexagonal ZnO": (lc.Cylinder.from_presets(R, "ZnO", "SiO2", **ADHESION), 6),
    "pentagonal Ag": (lc.Cylinder.from_presets(R, "Ag", "SiO2", **ADHESION), 5),
}
CORNERS = (0.0, 5e-9)  # m: a sharp corner and a corner rounded with 5 nm

# %%
# Pull-off force against the round wire's
# ---------------------------------------
# Each pull-off next to two limits of a flat facet of half-width :math:`f`: the strip's JKR
# pull-off :math:`\sqrt{2\pi f E w}` (a perfectly brittle facet) and the strength cap
# :math:`2\sigma_0 f` (the whole facet at the adhesive stress). A sharp corner stops the
# adhesive zone at the facet's edge, so the wire lets go at the cap; a rounded corner lets
# the zone run onto the corners, beyond the cap (which counts the flat facet only). Here the
# contact peels to a vanishing width before the wire lets go (:math:`a` = 0 at pull-off),
# its adhesive zone still spanning the facet.

for name, (wire, sides) in WIRES.items():
    Eh = wire.scale("Eh")  # N/m, the unit of the nondimensional loads
    round_po = wire.pull_off()
    print(f"{name} on SiO2, R = {R * 1e9:g} nm (Maugis parameter {wire.maugis_parameter:.3f})")
    print(
        f"  round wire              : pull-off {round_po.pull_off_force:8.3f} N/m "
        f"({round_po.mechanism})"
    )
    for r_c in CORNERS:
        shape = lc.Polygon(sides, corner_radius=r_c)
        po = wire.shaped(shape).pull_off()
        nd = po.nondimensional
        print(
            f"  corner radius {r_c * 1e9:3g} nm     : facet width "
            f"{shape.facet_width(R) * 1e9:5.2f} nm, pull-off {po.pull_off_force:8.3f} N/m "
            f"({po.mechanism}, a at pull-off {po.contact_half_width_at_pull_off * 1e9:.2f} nm)"
        )
        print(
            f"    flat-facet limits     : strip JKR {nd.F_strip_jkr_over_Eh * Eh:8.3f} N/m, "
            f"strength cap {nd.F_strength_over_Eh * Eh:8.3f} N/m"
        )

# %%
# Against the corner radius
# -------------------------
# The nondimensional functions take arrays: the corner radius from a sharp polygon
# (:math:`r_c/R = 0`) to the round wire (:math:`r_c/R = 1`) in one call per shape, the
# pull-off force and the contact at zero load (:func:`linecontact.facet_contact_for_load`),
# back in SI units with :math:`E h` and :math:`R`. At zero load a sharp corner holds the
# contact at the facet's edges (:math:`a = f`, the pressure singular there); a rounded one
# lets it spread a little past them, onto the corners. (The model reads a rounded corner as
# a parabola of radius :math:`r_c`; below :math:`r_c \approx` 1 nm the adhesive zone at
# pull-off reaches past the corner's arc, where the real profile is already the next facet,
# and the pull-off there rises by under 1 % above the sharp corner's: a feature of that
# reading, too fine for the grid below.)

rc = np.linspace(0.0, 1.0, 40)  # r_c / R
curves = {}
for name, (wire, sides) in WIRES.items():
    groups = dict(sides=sides, corner_radius_over_R=rc)
    po = lc.facet_pull_off(wire.R_over_h, wire.sigma0_over_E, **groups)
    at_rest = lc.facet_contact_for_load(0.0, wire.R_over_h, wire.sigma0_over_E, **groups)
    curves[name] = dict(
        pull_off=po.F_pulloff_over_Eh * wire.scale("Eh"),  # N/m
        cap=po.F_strength_over_Eh * wire.scale("Eh"),  # N/m
        a=at_rest.a_over_R * R,  # m
        f=po.facet_half_width_over_R * R,  # m
    )
    print(
        f"{name}: pull-off from {curves[name]['pull_off'][0]:.3f} N/m (sharp) to "
        f"{curves[name]['pull_off'][-1]:.3f} N/m (round); contact half-width at zero load from "
        f"{curves[name]['a'][0] * 1e9:.2f} nm to {curves[name]['a'][-1] * 1e9:.2f} nm"
    )

fig, (ax_f, ax_a) = plt.subplots(1, 2, figsize=(9.6, 3.8), layout="constrained")
for (name, c), color in zip(curves.items(), ("C0", "C1"), strict=True):
    ax_f.plot(rc, -c["pull_off"], color=color, label=name)
    ax_f.plot(rc, -c["cap"], color=color, ls=":", lw=1, label=f"{name}: strength cap 2σ₀f")
    ax_a.plot(rc, c["a"] * 1e9, color=color, label=name)
    ax_a.plot(rc, c["f"] * 1e9, color=color, ls=":", lw=1, label=f"{name}: facet half-width f")
    wire = WIRES[name][0]
    material = name.split()[-1]
    ax_f.axhline(
        -wire.pull_off().pull_off_force, color=color, ls="--", label=f"round {material} wire"
    )
    ax_a.axhline(
        wire.contact(load=0.0).contact_half_width * 1e9,
        color=color,
        ls="--",
        label=f"round {material} wire",
    )
ax_f.set(
    xlabel="corner radius r_c / R",
    ylabel="pull-off force |F| [N/m] (tensile)",
    title="(a) pull-off force",
)
ax_a.set(
    xlabel="corner radius r_c / R",
    ylabel="contact half-width a [nm]",
    title="(b) contact at zero load",
)
for ax in (ax_f, ax_a):
    ax.set_xlim(0, 1)
    ax.set_ylim(bottom=0)
    ax.legend(fontsize="small")
fig.suptitle(f"faceted wires on SiO2, circumradius {R * 1e9:g} nm, w = 0.1 J/m², z0 = 0.3 nm")
if len(sys.argv) > 1:
    fig.savefig(sys.argv[1], dpi=150)

# %%
# Why it matters: the shear strength from a friction force
# --------------------------------------------------------
# An interfacial shear strength is often derived from a measured friction force per unit
# length :math:`f_\mathrm{fr}` as :math:`\tau_0 = f_\mathrm{fr} / (2a)`, with the contact
# width of a round wire. A faceted wire's contact is several times wider (ten times or so
# here), so the same friction force means a shear strength as many times lower. Below, an
# illustrative friction force of 0.5 N/m at zero load.

FRICTION = 0.5  # N/m, illustrative
for name, (wire, sides) in WIRES.items():
    a_round = wire.contact(load=0.0).contact_half_width
    print(f"{name}, tau0 = f_fr/(2a) from f_fr = {FRICTION:g} N/m at zero load:")
    print(
        f"  round wire              : a = {a_round * 1e9:5.2f} nm, tau0 = "
        f"{FRICTION / (2 * a_round) / 1e6:6.1f} MPa"
    )
    for r_c in CORNERS:
        a = wire.shaped(lc.Polygon(sides, corner_radius=r_c)).contact(load=0.0).contact_half_width
        print(
            f"  corner radius {r_c * 1e9:3g} nm     : a = {a * 1e9:5.2f} nm, tau0 = "
            f"{FRICTION / (2 * a) / 1e6:6.1f} MPa ({a / a_round:.1f} times the round wire's a)"
        )
