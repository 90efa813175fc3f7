"""The SI methods the command line reads (issue 21): ``Cylinder.sliding``, ``load_curve``,
``lennard_jones_load_curve`` (each an SI result, ``units.to_si`` of the nondimensional one),
the results' ``total(length)``, ``Cylinder.total``, ``tangential_load``, and
``hysteresis_adhesion``: each the nondimensional problem in the cylinder's units.
"""

import numpy as np
import pytest

from linecontact import load_curve
from linecontact.cylinder import (
    Cylinder,
    CylinderLoadCurve,
    CylinderSliding,
    hysteresis_adhesion,
)
from linecontact.laws import LennardJones
from linecontact.materials import adhesion_from_work
from linecontact.results import Result
from linecontact.sliding import sliding_contact, sliding_contact_for_load

CYL = Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)


def test_scales_and_conversions():
    R, E, h = CYL.radius, CYL.modulus, CYL.adhesion_range
    assert CYL.scale("R") == R and CYL.scale("h") == h and CYL.scale("E") == E
    assert CYL.scale("Eh") == E * h and CYL.scale("EhR") == E * h * R
    assert CYL.in_si(0.5, "Eh") == 0.5 * (E * h)
    assert CYL.over(1.0, "R") == 1.0 / R
    assert CYL.total(2.0, None) is None
    assert CYL.total(2.0, 1e-6) == 2.0 * 1e-6
    with pytest.raises(ValueError, match="scale must be one of"):
        CYL.scale("Q")
    with pytest.raises(ValueError, match="length"):
        CYL.total(1.0, -1.0)


def test_totals_over_a_fibre():
    c = CYL.contact(load=[0.0, 1.0])
    nd = c.nondimensional
    np.testing.assert_array_equal(c.contact_half_width, np.multiply(nd.a_over_R, CYL.radius))
    # the group times the scale's total over the fibre (E h L), as the command line wrote it
    np.testing.assert_array_equal(c.total(1e-6)["load"], np.multiply(nd.F_over_Eh, 50.0 * 1e-6))
    assert list(c.total(1e-6)) == ["load"]
    with pytest.raises(ValueError, match="length"):
        c.total(-1.0)
    p = CYL.pull_off()  # no scales kept: the SI value times the length
    assert p.total(2e-6) == {"pull_off_force": p.pull_off_force * 2e-6}
    assert not hasattr(Cylinder, "columns")


def test_sliding_is_the_nondimensional_problem():
    r = CYL.sliding(receding_range=1e-9, contact_half_width=[2e-9, 4e-9], friction_stress=5e8)
    nd = sliding_contact(
        np.array([2e-9, 4e-9]) / CYL.radius,
        CYL.R_over_h,
        2.0,
        0.01,
        tau0_over_E=5e8 / 1e11,
        method="collocation",
    )
    assert isinstance(r, CylinderSliding) and isinstance(r, Result)
    np.testing.assert_array_equal(r.nondimensional.F_over_Eh2, nd.F_over_Eh2)
    np.testing.assert_array_equal(r.load, nd.F_over_Eh2 * (1e11 * 0.5e-9))
    np.testing.assert_array_equal(r.moment, nd.M_over_Eh2R * (1e11 * 0.5e-9 * 50e-9))
    np.testing.assert_array_equal(r.friction_force, nd.T_over_Eh2 * (1e11 * 0.5e-9))
    assert r.receding_range == 2.0 * 0.5e-9
    np.testing.assert_array_equal(
        r.total(1e-6)["moment"], nd.M_over_Eh2R * (1e11 * 0.5e-9 * 50e-9 * 1e-6)
    )
    f = CYL.sliding(h1_over_h2=2.0, load=0.5, method="closed-form")
    g = sliding_contact_for_load(0.5 / 50.0, CYL.R_over_h, 2.0, 0.01, method="closed-form")
    assert float(f.nondimensional.a_over_R) == float(g.a_over_R)
    assert f.contact_half_width == float(g.a_over_R) * 50e-9
    assert CYL.sliding(h1_over_h2=2.0, load=0.5, method="closed-form").state == "contact"


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(contact_half_width=1e-9), "receding_range"),
        (dict(receding_range=1e-9), "contact_half_width"),
        (dict(receding_range=1e-9, load=1e7), "load=10000000.0 N/m needs a contact"),
    ],
)
def test_sliding_refuses(kwargs, match):
    with pytest.raises(ValueError, match=match):
        CYL.sliding(**kwargs)


def test_load_curve_in_si():
    c = CYL.load_curve(max_half_width=5e-9, num=10, num_noncontact=4)
    nd = load_curve(
        CYL.R_over_h, CYL.sigma0_over_E, a_max_over_R=5e-9 / 50e-9, num=10, num_noncontact=4
    )
    assert isinstance(c, CylinderLoadCurve)
    np.testing.assert_array_equal(c.nondimensional.F_over_Eh, nd.F_over_Eh)
    np.testing.assert_array_equal(c.load, nd.F_over_Eh * (1e11 * 0.5e-9))
    np.testing.assert_array_equal(c.central_gap, nd.central_gap_over_h * 0.5e-9)
    np.testing.assert_array_equal(c.branch, nd.branch)


def test_lennard_jones_load_curve_refuses_a_load_beyond_the_solver():
    lj = Cylinder.from_modulus(50e-9, 100e9, work_of_adhesion=0.1, equilibrium_spacing=0.3e-9)
    with pytest.raises(ValueError, match="max_load=1000000.0 N/m is beyond"):
        lj.under(LennardJones).load_curve(max_load=1e6)


def test_tangential_load():
    a = CYL.contact(load=1.0).contact_half_width
    assert CYL.tangential_load(1.0, 0.5) == 0.5 * (1e11 * a)
    assert CYL.tangential_load(1.0, 0.5, over="muF", friction_coefficient=0.3) == 0.5 * 0.3 * 1.0
    with pytest.raises(ValueError, match="friction_coefficient"):
        CYL.tangential_load(1.0, 0.5, over="muF")


def test_hysteresis_adhesion():
    s0, h2, h1 = hysteresis_adhesion(0.05, 0.025, 0.3e-9)
    assert (s0, h1) == tuple(float(v) for v in adhesion_from_work(0.05, 0.3e-9))
    assert h2 == 0.025 / s0


@pytest.mark.parametrize("value", [-1.0, 0.0, 1.0])
def test_load_curve_names_max_half_width_in_metres(value):
    # the SI argument and its SI range, not the group a_max_over_R alone (issue 20)
    with pytest.raises(ValueError, match=r"^max_half_width must be in \[.*\] m"):
        CYL.load_curve(max_half_width=value)


def test_scales_of_wants_a_cylinder():
    from linecontact.units import Scales

    with pytest.raises(TypeError, match="Scales.of takes a Cylinder"):
        Scales.of("x")
    assert Scales.of(CYL)["R"] == CYL.radius
