"""Work of adhesion and range of silica-on-silicon nanowires, fitted to pull-off forces
====================================================================================

The data are SYNTHETIC: pull-off forces per unit length of silica (SiO2) nanowires on
silicon at five radii, 10 nm to 2.56 um, computed with the library's forward model
(the Maugis--Dugdale pull-off, ``linecontact.inverse.pull_off_force``) for a work of
adhesion w = 0.1 J/m^2 and an equilibrium spacing z0 = 0.3 nm, then perturbed by 3 %
Gaussian noise (numpy default_rng seed 2026); the standard uncertainty of each force is
stated as 3 % of its magnitude. The moduli are the presets "SiO2" and "Si"
(``linecontact.presets``). Over these radii the Maugis parameter runs from 0.2 to 1.4, the
transition between the rigid (DMT-like) and the JKR regimes, where the radius dependence of
the pull-off separates w from z0.

The script writes the data to ``pulloff.csv`` in the current directory (the format that
``linecontact fit-adhesion --data pulloff.csv`` reads), fits (w, z0) back with their
uncertainties, and prints what JKR or DMT alone would have reported. With a path argument
it also draws the fit (matplotlib).

Run: ``python examples/fit_pull_off.py [fit.png]``
"""

import math
import sys

import numpy as np

import linecontact as lc
from linecontact.inverse import S_LJ, fit_pull_off, pull_off_force
from linecontact.presets import Material

# %%
# The materials
# -------------
# The composite plane-strain modulus :math:`E` of the wire and the wafer,
# :math:`1/E = (1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2`, from the presets.

W_TRUE, Z0_TRUE = 0.1, 0.3e-9  # J/m^2, m
RADII = np.array([10e-9, 40e-9, 160e-9, 640e-9, 2560e-9])  # m
NOISE, SEED = 0.03, 2026

silica, silicon = Material.from_name("SiO2"), Material.from_name("Si")
E = lc.composite_modulus(silica.E, silica.nu, silicon.E, silicon.nu)
print(
    f"SiO2 wire (E = {silica.E / 1e9:g} GPa, nu = {silica.nu:g}) on Si (E = "
    f"{silicon.E / 1e9:g} GPa, nu = {silicon.nu:g}): composite modulus {E / 1e9:.2f} GPa"
)

# %%
# A synthetic measurement
# -----------------------
# The forward model's pull-off forces at five radii for :math:`w = 0.1` J/m² and
# :math:`z_0 = 0.3` nm, with 3 % noise, written to ``pulloff.csv`` as a measurement would be:
# a CSV file whose header names its units. Over these radii the Maugis parameter
# :math:`\lambda` crosses from the rigid (DMT-like) to the JKR regime.

rng = np.random.default_rng(SEED)
F_true = pull_off_force(RADII, E, W_TRUE, Z0_TRUE)
F = F_true * (1 + NOISE * rng.standard_normal(RADII.size))
sd = NOISE * np.abs(F)
h = Z0_TRUE / S_LJ  # the Dugdale range of (w, z0)
maugis = [
    lc.Cylinder.from_modulus(
        R, E, work_of_adhesion=W_TRUE, equilibrium_spacing=Z0_TRUE
    ).maugis_parameter
    for R in RADII
]
with open("pulloff.csv", "w", encoding="utf-8") as fh:
    fh.write(
        f"# synthetic: SiO2 wire on Si (E = {E:.6g} Pa), Maugis-Dugdale pull-off for "
        f"w = {W_TRUE:g} J/m^2, z0 = {Z0_TRUE:g} m, {NOISE:.0%} Gaussian noise (seed {SEED}); "
        f"sd = {NOISE:.0%} of |F| (examples/fit_pull_off.py)\n"
    )
    fh.write("radius_m,pull_off_force_N_per_m,pull_off_force_sd_N_per_m\n")
    for R, f, s in zip(RADII, F, sd, strict=True):
        fh.write(f"{R:.6g},{f:.8g},{s:.4g}\n")

print(f"\nsynthetic data (w = {W_TRUE:g} J/m^2, z0 = {Z0_TRUE * 1e9:g} nm, {NOISE:.0%} noise):")
print("  radius [nm]   Maugis lambda   F [N/m]    sd [N/m]   noise-free F [N/m]")
for R, lam, f, s, f0 in zip(RADII, maugis, F, sd, F_true, strict=True):
    print(f"  {R * 1e9:11.0f}   {lam:13.3f}   {f:8.4f}   {s:8.4f}   {f0:18.4f}")
print("  (written to pulloff.csv)")

# %%
# The fit
# -------
# :func:`linecontact.inverse.fit_pull_off` fits :math:`w` and :math:`z_0` jointly, weighted
# by the stated standard uncertainties, with 95 % intervals and their correlation.

# the fit: w and z0 jointly, weighted by the stated standard uncertainties
fit = fit_pull_off(RADII, F, E, sd=sd, seed=0)
w, z0 = fit.work_of_adhesion, fit.equilibrium_spacing
(w_lo, w_hi), (z_lo, z_hi) = fit.work_of_adhesion_ci95, fit.equilibrium_spacing_ci95
print("\nfitted (Maugis-Dugdale, weighted least squares):")
print(
    f"  w  = {w:.4f} J/m^2  sd {fit.work_of_adhesion_sd:.4f}  95 % [{w_lo:.4f}, {w_hi:.4f}]"
    f"   (truth {W_TRUE:g}, error {100 * (w / W_TRUE - 1):+.1f} %)"
)
print(
    f"  z0 = {z0 * 1e9:.4f} nm     sd {fit.equilibrium_spacing_sd * 1e9:.4f}  95 % "
    f"[{z_lo * 1e9:.4f}, {z_hi * 1e9:.4f}]   (truth {Z0_TRUE * 1e9:g}, error "
    f"{100 * (z0 / Z0_TRUE - 1):+.1f} %)"
)
print(
    f"  correlation of w and z0: {fit.correlation:.3f}; chi2 = {fit.chi2:.2f} on {fit.dof} "
    f"degrees of freedom; identifiable: {fit.identifiable}"
)

# %%
# What a simple model alone would report
# --------------------------------------
# JKR (:math:`|F| \propto (w^2 E R)^{1/3}`) or the rigid/DMT limit
# (:math:`|F| = 2\sqrt{2}\, w \sqrt{R/h}`), inverted point by point: each is right only
# at one end of the radii, and wrong by tens of percent at the other.

# what a simple model alone would have reported, point by point
# JKR: |F| = (3/4)(4 pi w^2 E R)^(1/3)  ->  w = sqrt((4|F|/3)^3 / (4 pi E R))
w_jkr = np.sqrt((4 * np.abs(F) / 3) ** 3 / (4 * math.pi * E * RADII))
# rigid/DMT: |F| = 2 sqrt(2) w sqrt(R/h)  ->  w = |F| / (2 sqrt(2) sqrt(R/h)), h = z0/S_LJ,
# at the true z0 (known exactly) and at the fitted one
w_dmt_true = np.abs(F) / (2 * math.sqrt(2) * np.sqrt(RADII * S_LJ / Z0_TRUE))
w_dmt_fit = np.abs(F) / (2 * math.sqrt(2) * np.sqrt(RADII * S_LJ / z0))


def err(x):
    """A work of adhesion and its error against the truth."""
    return f"{x:.4f} ({100 * (x / W_TRUE - 1):+6.1f} %)"


print("\nwhat the simple models alone give, w [J/m^2] from each point (error vs the truth):")
print("  radius [nm]   JKR                  DMT at the true z0   DMT at the fitted z0")
for R, a, b, c in zip(RADII, w_jkr, w_dmt_true, w_dmt_fit, strict=True):
    print(f"  {R * 1e9:11.0f}   {err(a)}   {err(b)}    {err(c)}")
print(f"  mean          {err(w_jkr.mean())}   {err(w_dmt_true.mean())}    {err(w_dmt_fit.mean())}")

# %%
# The figure
# ----------
# :func:`linecontact.figures.fit.draw_adhesion_fit` draws the data with their standard
# uncertainties, the fitted Maugis–Dugdale curve with its 95 % band, and JKR and DMT with
# the fitted values (the figure of ``linecontact fit-adhesion --plot``).

if len(sys.argv) > 1:
    from linecontact.figures.fit import draw_adhesion_fit

    draw_adhesion_fit(fit, sys.argv[1])
