"""The sphere's inverse problems: w from a pull-off, tau0 from a friction force.

Each is checked against the forward model it inverts (a round trip through
:class:`linecontact.Sphere`) and against a closed form in a limit: deep in JKR the
pull-off is -(3/2) pi w R, deep in DMT -2 pi w R; at a JKR-like tip the contact radius
under the load is JKR's, so tau0 is the friction over JKR's area.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import linecontact as lc
from linecontact.closed_forms.sphere import sphere_jkr_load


@given(
    R=st.floats(5e-9, 1e-4),
    E=st.floats(1e9, 5e11),
    w=st.floats(1e-3, 1.0),
    z0=st.floats(1e-10, 1e-9),
)
@settings(max_examples=30, deadline=None)
def test_the_work_of_adhesion_comes_back_from_its_pull_off(R, E, w, z0):
    tip = lc.Sphere.from_modulus(R, E, work_of_adhesion=w, equilibrium_spacing=z0)
    F = tip.pull_off().pull_off_force
    got = lc.sphere_work_of_adhesion_from_pull_off(F, R, E, z0)
    assert got == pytest.approx(w, rel=1e-12), (R, E, w, z0)


@pytest.mark.parametrize(("R", "E", "limit"), [(1e-2, 1e9, -1.5), (1e-9, 1e12, -2.0)])
def test_in_a_limit_the_work_of_adhesion_is_the_closed_forms(R, E, limit):
    # JKR: a large, compliant sphere (lambda ~ 300); DMT: a small, stiff one (lambda ~ 0.005)
    w, z0 = 0.1, 3e-10
    F = limit * math.pi * w * R
    got = lc.sphere_work_of_adhesion_from_pull_off(F, R, E, z0)
    tip = lc.Sphere.from_modulus(R, E, work_of_adhesion=got, equilibrium_spacing=z0)
    assert got == pytest.approx(w, rel=2e-2), (tip.maugis_parameter, got)
    assert tip.pull_off().pull_off_force == pytest.approx(F, rel=1e-12)


def test_the_shear_strength_is_the_friction_over_the_contact_area():
    R, E, w, z0 = 20e-9, 50e9, 0.1, 3e-10
    loads = np.array([-5e-9, 0.0, 5e-9, 5e-8])
    tau = lc.sphere_shear_strength_from_friction(1e-9, loads, R, E, w, z0)
    a = (
        lc.Sphere.from_modulus(R, E, work_of_adhesion=w, equilibrium_spacing=z0)
        .contact(load=loads)
        .contact_radius
    )
    np.testing.assert_allclose(tau, 1e-9 / (np.pi * a * a), rtol=1e-14)
    assert np.all(np.diff(tau) < 0)  # more load, more area, less stress


def test_at_a_jkr_like_tip_the_area_is_jkrs():
    R, E, w, z0 = 1e-2, 1e9, 0.1, 3e-10  # lambda ~ 180
    tip = lc.Sphere.from_modulus(R, E, work_of_adhesion=w, equilibrium_spacing=z0)
    assert tip.maugis_parameter > 100
    load = 1e-2
    tau = lc.sphere_shear_strength_from_friction(1e-3, load, R, E, w, z0)
    # JKR's radius at that load, from its closed-form load (a root in a)
    from scipy.optimize import brentq

    rho, s = tip.R_over_h, tip.sigma0_over_E
    unit = tip.scale("EhR")
    alpha = brentq(lambda x: sphere_jkr_load(x, rho, s) - load / unit, 1e-6, 1.0, xtol=1e-16)
    assert tau == pytest.approx(1e-3 / (math.pi * (alpha * R) ** 2), rel=2e-2)


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (
            lambda: lc.sphere_work_of_adhesion_from_pull_off(1e-9, 1e-6, 5e10, 3e-10),
            "pull_off_force",
        ),
        (lambda: lc.sphere_work_of_adhesion_from_pull_off(-1e-9, -1e-6, 5e10, 3e-10), "radius"),
        (
            lambda: lc.sphere_shear_strength_from_friction(-1, 0, 1e-6, 5e10, 0.1, 3e-10),
            "friction_force",
        ),
        (
            lambda: lc.sphere_shear_strength_from_friction(1, 0, 1e-6, 5e10, -0.1, 3e-10),
            "work_of_adhesion",
        ),
    ],
)
def test_bad_input_names_the_parameter(call, name):
    with pytest.raises(ValueError, match=name):
        call()
