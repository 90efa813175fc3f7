"""A parameter study: the pull-off of a nanowire against its radius, one sweep
============================================================================

A ZnO nanowire on silica, over 40 radii for three works of adhesion, plotted from the
labelled dataset::

    python examples/sweep_pulloff.py [sweep.png]

The same sweep on the command line (``-o pulloff.zarr`` keeps it, resumable)::

    linecontact sweep pulloff --radius 10e-9:1e-6:40:log --cylinder-material ZnO
        --substrate-material SiO2 --work-of-adhesion 0.05 0.2 1 --z0 3e-10 -o pulloff.zarr

Needs the extra ``[sweep]`` (xarray, dask) and, for the figure, matplotlib.
"""

from __future__ import annotations

import sys
import warnings

import linecontact as lc

# %%
# One sweep, 120 points
# ---------------------
# :func:`linecontact.sweep` runs a subcommand over every combination of its flags' values:
# here 40 radii, logarithmically spaced from 10 nm to 1 µm (``start:stop:count:log``), times
# three works of adhesion. It returns an :class:`xarray.Dataset` labelled by the swept flags.

with warnings.catch_warnings():
    warnings.simplefilter("ignore", lc.CouplingWarning)  # ZnO on silica: |beta| = 0.09
    warnings.simplefilter("ignore", lc.ModelValidityWarning)  # zero widths at pull-off
    ds = lc.sweep(
        "pulloff",
        radius="10e-9:1e-6:40:log",
        cylinder_material="ZnO",
        substrate_material="SiO2",
        work_of_adhesion=[0.05, 0.2, 1.0],
        z0=3e-10,
    )

# %%
# Reading the dataset
# -------------------
# Select by label: the pull-off force per unit length and its mechanism at the smallest and
# the largest radius, for each work of adhesion.

F = ds.F_pulloff_N_per_m
print(f"{dict(ds.sizes)} points; variables: {', '.join(list(ds.data_vars)[:4])}, ...")
for w in ds.work_of_adhesion.values:
    row = F.sel(work_of_adhesion=w)
    mech = ds.mechanism.sel(work_of_adhesion=w).values
    print(
        f"w = {w:g} J/m^2: pull-off {float(row[0]):.3g} N/m at R = 10 nm, "
        f"{float(row[-1]):.3g} N/m at R = 1 um; mechanism {mech[0]} -> {mech[-1]}"
    )

# %%
# The pull-off against the radius
# -------------------------------
# One line per work of adhesion, on logarithmic axes.

if len(sys.argv) > 1:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 3.6), layout="constrained")
    for w in ds.work_of_adhesion.values:
        ax.plot(ds.radius * 1e9, -F.sel(work_of_adhesion=w), label=f"w = {w:g} J/m²")
    ax.set(
        xscale="log",
        yscale="log",
        xlabel="radius R [nm]",
        ylabel="pull-off force −F [N/m]",
        title="ZnO nanowire on SiO2, z0 = 0.3 nm (one sweep)",
    )
    ax.legend()
    fig.savefig(sys.argv[1], dpi=150)
