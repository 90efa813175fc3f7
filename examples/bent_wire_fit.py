r"""Friction per unit length of a ZnO nanowire, fitted to the shape it is dragged in
==================================================================================

The data are SYNTHETIC: the profile of a ZnO nanowire (diameter D = 100 nm, length
L = 5 um, Young's modulus E = 140 GPa) dragged sideways at its midpoint on its substrate
against a kinetic friction of f = 12 nN/um (= 12 mN/m), computed with the library's forward
model (:func:`linecontact.bent_wire.dragged_wire`, the elastica of each half under the
uniform friction), sampled at 250 points equally spaced along the wire (20 nm apart, the
pixels of an SEM image), turned and moved as an image would place it, and perturbed by
2 nm Gaussian position noise in x and y (numpy default_rng seed 2026).

The script writes the profile to ``profile.csv`` in the current directory (``x_nm,y_nm``,
the format that ``linecontact.read_measurements(..., "profile")`` reads), reads it back,
fits f with :func:`linecontact.bent_wire.fit_bent_wire` (orthogonal least squares over the
whole profile, its 95 % intervals from the covariance and from a bootstrap of 200 refits)
and prints it against the truth; then the interfacial shear strength tau0 = f/(2a) with the
contact width of the wire on silica under adhesion (w = 0.2 J/m^2, z0 = 0.3 nm, 2 % on the
radius). With a path argument it also draws the fit (matplotlib).

Run: ``python examples/bent_wire_fit.py [fit.png]``
"""

import math
import sys

import numpy as np
from numpy.polynomial import chebyshev as C

from linecontact import composite_modulus, read_measurements, shear_strength_from_bent_wire
from linecontact.bent_wire import bending_stiffness, dragged_wire, fit_bent_wire

# %%
# The wire
# --------
# The bending stiffness of a solid round wire, :math:`EI = E \pi r^4/4`
# (:func:`linecontact.bent_wire.bending_stiffness`, which also takes a tube or a faceted
# wire); each half
# (:math:`l` = 2.5 µm) is a cantilever under the friction's uniform load, so the shape
# depends on the one group :math:`\Lambda = f l^3/EI`.

DIAMETER, LENGTH, MODULUS = 100e-9, 5e-6, 140e9  # m, m, Pa
F_TRUE = 12e-3  # N/m (12 nN/um)
POINTS, NOISE, SEED = 250, 2e-9, 2026  # -, m, -

EI = bending_stiffness(MODULUS, DIAMETER / 2)  # N m^2
half = LENGTH / 2
group = F_TRUE * half**3 / EI
print(
    f"ZnO wire: D = {DIAMETER * 1e9:g} nm, L = {LENGTH * 1e6:g} um, E = {MODULUS / 1e9:g} GPa, "
    f"EI = {EI:.4g} N m^2"
)
print(f"friction f = {F_TRUE * 1e3:g} nN/um: the group f l^3/EI = {group:.4f}")

# %%
# A synthetic profile
# -------------------
# The model's half shape is known on its Chebyshev nodes (the arc length :math:`u = s/l`
# from the midpoint); its interpolant gives the points at equal arc lengths along the whole
# wire, one half mirrored. Then the wire is turned by 25° and moved, as it lies in an
# image, and each coordinate gets 2 nm of noise.

shape = dragged_wire(group)
t = 2 * shape.u - 1  # the nodes on [-1, 1]
cx = C.chebfit(t, shape.x_over_l, shape.nodes)  # interpolants: degree = nodes (the points - 1)
cy = C.chebfit(t, shape.y_over_l, shape.nodes)
s = np.linspace(-1.0, 1.0, POINTS)  # arc length over l, from end to end
x0 = np.sign(s) * C.chebval(2 * np.abs(s) - 1, cx) * half
y0 = C.chebval(2 * np.abs(s) - 1, cy) * half
print(
    f"the ends lag behind the midpoint by {shape.end_lag_over_l * half * 1e9:.1f} nm "
    f"(small slopes: f l^4/(8 EI) = {F_TRUE * half**4 / (8 * EI) * 1e9:.1f} nm)"
)

angle, shift = math.radians(25.0), (4.0e-6, 3.0e-6)  # rad, m
rng = np.random.default_rng(SEED)
x = math.cos(angle) * x0 - math.sin(angle) * y0 + shift[0] + NOISE * rng.standard_normal(POINTS)
y = math.sin(angle) * x0 + math.cos(angle) * y0 + shift[1] + NOISE * rng.standard_normal(POINTS)
with open("profile.csv", "w", encoding="utf-8") as fh:
    fh.write(
        f"# synthetic: ZnO wire D = {DIAMETER * 1e9:g} nm, L = {LENGTH * 1e6:g} um, "
        f"E = {MODULUS / 1e9:g} GPa dragged at its midpoint, f = {F_TRUE * 1e3:g} nN/um, "
        f"{NOISE * 1e9:g} nm noise (seed {SEED}; examples/bent_wire_fit.py)\n"
    )
    fh.write("x_nm,y_nm\n")
    for a, b in zip(x, y, strict=True):
        fh.write(f"{a * 1e9:.4f},{b * 1e9:.4f}\n")
print(f"{POINTS} points, {NOISE * 1e9:g} nm noise, written to profile.csv")

# %%
# The fit
# -------
# :func:`linecontact.bent_wire.fit_bent_wire` places the model on the points (the group,
# the half-length, the midpoint and the wire's angle) by orthogonal least squares, the noise
# estimated from the residuals; then :math:`f = \Lambda EI/l^3`.

profile = read_measurements("profile.csv", "profile")
fit = fit_bent_wire(profile["x"], profile["y"], EI, bootstrap=200, seed=0)
f, sd = fit.friction_per_length * 1e3, fit.friction_per_length_sd * 1e3  # nN/um
(lo, hi), (b_lo, b_hi) = fit.friction_per_length_ci95, fit.friction_per_length_bootstrap_ci95
print("\nfitted (wire dragged at its midpoint, whole-profile least squares):")
print(
    f"  f = {f:.3f} nN/um  sd {sd:.3f}   (truth {F_TRUE * 1e3:g}, error "
    f"{100 * (fit.friction_per_length / F_TRUE - 1):+.2f} %)"
)
print(f"  95 % interval, covariance: [{lo * 1e3:.3f}, {hi * 1e3:.3f}] nN/um")
print(f"  95 % interval, bootstrap ({fit.bootstrap} refits): [{b_lo * 1e3:.3f}, {b_hi * 1e3:.3f}]")
print(f"  the truth inside them: {lo <= F_TRUE <= hi} and {b_lo <= F_TRUE <= b_hi}")
print(
    f"  half-length {fit.half_length * 1e6:.4f} um (truth {half * 1e6:g}); midpoint "
    f"({fit.midpoint[0] * 1e9:.1f}, {fit.midpoint[1] * 1e9:.1f}) nm (truth "
    f"({shift[0] * 1e9:g}, {shift[1] * 1e9:g}))"
)
print(
    f"  noise from the residuals {fit.noise_estimated * 1e9:.2f} nm (truth {NOISE * 1e9:g}); "
    f"runs test z = {fit.residual_runs_z:+.2f}; determined: {fit.determined}"
)

# %%
# The figure
# ----------
# :func:`linecontact.figures.bent_wire.bent_wire_fit` draws the points with the fitted wire
# over them, the midpoint and the drag, and below the residuals along the wire with the band
# of ±2 noises (the figure of ``linecontact fit-bent-wire --plot``).

if len(sys.argv) > 1:
    from linecontact.figures.bent_wire import bent_wire_fit

    bent_wire_fit(fit, sys.argv[1])

# %%
# The shear strength
# ------------------
# :math:`\tau_0 = f/(2a)`, with :math:`a` the half-width of the wire's Maugis--Dugdale
# contact on silica under adhesion alone (its weight is a thousand times smaller). The
# uncertainties of the shape, of the radius (in both :math:`EI` and :math:`a`: 2 % here)
# and of the work of adhesion (10 %) propagate by Monte Carlo.

contact = composite_modulus(MODULUS, 0.36, 72e9, 0.17)  # ZnO on silica [Pa]
tau = shear_strength_from_bent_wire(
    fit,
    DIAMETER / 2,
    MODULUS,
    contact,
    0.2,
    0.3e-9,
    radius_sd=0.02 * DIAMETER / 2,
    work_of_adhesion_sd=0.02,
)
print(
    f"\ntau0 = f/(2a) = {tau.value / 1e6:.3f} MPa, sd {tau.sd / 1e6:.3f}, 95 % interval "
    f"[{tau.ci95[0] / 1e6:.3f}, {tau.ci95[1] / 1e6:.3f}] MPa (a = "
    f"{fit.friction_per_length / (2 * tau.value) * 1e9:.2f} nm)"
)
