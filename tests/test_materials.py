"""SI layer: conversions, conventions and the wiring to the nondimensional solvers."""

import math
import warnings

import numpy as np
import pytest

import linecontact as lc
from linecontact.errors import CouplingWarning


def test_composite_modulus_and_constants():
    E1, n1, E2, n2 = 70e9, 0.17, 160e9, 0.22
    E = lc.composite_modulus(E1, n1, E2, n2)
    assert math.isclose(1 / E, (1 - n1**2) / E1 + (1 - n2**2) / E2, rel_tol=1e-15)
    A, B = lc.compliance_constants(E1, n1, E2, n2)
    assert math.isclose(A, 8 / E, rel_tol=1e-14)  # Eq 7: A = 8/E
    assert lc.dundurs_beta(E1, n1, E1, n1) == 0.0
    assert lc.dundurs_beta(E1, n1, E2, n2) == pytest.approx(-B / A)
    # the standard form, cylinder = body 1
    G1, G2 = E1 / (2 * (1 + n1)), E2 / (2 * (1 + n2))
    beta = (G1 * (1 - 2 * n2) - G2 * (1 - 2 * n1)) / (2 * (G1 * (1 - n2) + G2 * (1 - n1)))
    assert lc.dundurs_beta(E1, n1, E2, n2) == pytest.approx(beta, rel=1e-13)
    assert beta < 0  # silica (softer) on silicon
    # rigid substrate
    assert math.isclose(lc.composite_modulus(E1, n1, np.inf, 0.3), E1 / (1 - n1**2))


def test_maugis_convention():
    w, z0 = 0.05, 0.25e-9
    s0, h = lc.adhesion_from_work(w, z0)
    assert math.isclose(s0, 16 * w / (9 * math.sqrt(3) * z0), rel_tol=1e-15)
    assert math.isclose(s0 * h, w, rel_tol=1e-15)
    assert math.isclose(h / z0, 9 * math.sqrt(3) / 16, rel_tol=1e-15)  # ~0.974, paper: 0.97
    # the strength is the maximum of the Lennard-Jones law of Eq 1
    z = np.linspace(z0, 3 * z0, 200001)
    p = 8 * w / (3 * z0) * ((z0 / z) ** 9 - (z0 / z) ** 3)
    assert math.isclose(-p.min(), s0, rel_tol=1e-8)


def test_cylinder_groups_and_results():
    cyl = lc.Cylinder.from_modulus(50e-9, 100e9, cohesive_stress=1e9, adhesion_range=0.5e-9)
    assert cyl.R_over_h == pytest.approx(100, rel=1e-15) and cyl.sigma0_over_E == 0.01
    assert math.isclose(cyl.work_of_adhesion, 0.5)
    po = cyl.pull_off()
    ref = lc.pull_off(cyl.R_over_h, 0.01)
    assert po.pull_off_force == ref.F_pulloff_over_Eh * 100e9 * 0.5e-9
    a = np.array([1e-9, 2e-9])
    c = cyl.contact(contact_half_width=a)
    r = lc.normal_contact(a / 50e-9, cyl.R_over_h, 0.01)
    np.testing.assert_allclose(c.load, r.F_over_Eh * 50.0, rtol=1e-15)
    np.testing.assert_allclose(c.adhesive_zone_half_width, r.c_over_R * 50e-9, rtol=1e-15)
    back = cyl.contact(load=c.load)
    np.testing.assert_allclose(back.contact_half_width, a, rtol=1e-10)
    assert lc.Cylinder.from_modulus(1e-6, 1e9, adhesion_range=1e-9).sigma0_over_E == 0.0


def test_coupling_warning():
    with pytest.warns(CouplingWarning, match="Dundurs beta"):
        lc.Cylinder.from_materials(
            50e-9, 70e9, 0.17, 160e9, 0.22, cohesive_stress=1e8, adhesion_range=1e-9
        )
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        cyl = lc.Cylinder.from_materials(
            50e-9, 70e9, 0.2, 70e9, 0.2, cohesive_stress=1e8, adhesion_range=1e-9
        )
    assert cyl.dundurs_beta == 0.0


BAD = [
    (lambda: lc.composite_modulus(-1, 0.3, 1e9, 0.3), "E1 must be in"),
    (lambda: lc.composite_modulus(1e9, 0.6, 1e9, 0.3), r"nu1 must be in \(-1, 0.5\]"),
    (lambda: lc.composite_modulus(1e9, 0.3, 1e9, -1.0), "nu2 must be in"),
    (lambda: lc.composite_modulus(np.inf, 0.3, np.inf, 0.3), "both be infinite"),
    (lambda: lc.adhesion_from_work(0, 1e-9), "work_of_adhesion must be in"),
    (lambda: lc.adhesion_from_work(0.1, np.nan), "equilibrium_spacing"),
    (lambda: lc.Cylinder.from_modulus(0, 1e9, adhesion_range=1e-9), "radius must be in"),
    (lambda: lc.Cylinder.from_modulus(1e-6, 1e9, cohesive_stress=1e8), "adhesion_range"),
    (
        lambda: lc.Cylinder.from_modulus(
            1e-6, 1e9, cohesive_stress=1e8, adhesion_range=1e-9, work_of_adhesion=0.1
        ),
        "not both",
    ),
    (lambda: lc.Cylinder.from_modulus(1e-6, 1e9, work_of_adhesion=0.1), "both work_of_adhesion"),
    (lambda: lc.Cylinder.from_modulus(1e-6, 1e9, adhesion_range=1e-9).contact(), "exactly one of"),
    (
        lambda: lc.Cylinder.from_modulus(1e-6, 1e9, adhesion_range=1e-9).contact(
            contact_half_width=-1.0
        ),
        "contact_half_width must be in",
    ),
]


@pytest.mark.parametrize(("call", "message"), BAD)
def test_bad_input(call, message):
    with pytest.raises(ValueError, match=message):
        call()
