"""SI layer: conversions, conventions and the wiring to the nondimensional solvers."""

import math
import warnings

import numpy as np
import pytest

import linecontact as lc
from linecontact.errors import CouplingWarning


def test_composite_modulus_limits_and_hand_values():
    E = lc.composite_modulus
    # identical bodies: half the plane-strain modulus, E1/(2 (1 - nu^2))
    assert E(100e9, 0.0, 100e9, 0.0) == pytest.approx(50e9, rel=1e-15)
    assert E(100e9, 0.5, 100e9, 0.5) == pytest.approx(66.666666666666667e9, rel=1e-15)
    assert E(70e9, 0.17, 70e9, 0.17) == pytest.approx(36.041602306662548e9, rel=1e-15)
    # a rigid substrate (or cylinder): the plane-strain modulus of the other, E1/(1 - nu1^2)
    assert E(70e9, 0.17, np.inf, 0.3) == pytest.approx(72.083204613325095e9, rel=1e-15)
    assert E(np.inf, 0.3, 70e9, 0.17) == pytest.approx(72.083204613325095e9, rel=1e-15)
    # silica (70 GPa, 0.17) on silicon (160 GPa, 0.22), by hand:
    # 0.9711/70e9 + 0.9516/160e9 = 1.3872857142857143e-11 + 5.9475e-12 = 1.9820357142857143e-11
    assert E(70e9, 0.17, 160e9, 0.22) == pytest.approx(50.453177649242301e9, rel=1e-15)
    # the same for either body as the cylinder; softer than either body alone
    assert E(160e9, 0.22, 70e9, 0.17) == pytest.approx(E(70e9, 0.17, 160e9, 0.22), rel=1e-15)
    assert E(70e9, 0.17, 160e9, 0.22) < 70e9 / (1 - 0.17**2)


def test_compliance_constants():
    E1, n1, E2, n2 = 70e9, 0.17, 160e9, 0.22
    A, B = lc.compliance_constants(E1, n1, E2, n2)
    # Eq 7: A is written with the shear moduli, the composite modulus with E and nu
    assert math.isclose(A, 8 / lc.composite_modulus(E1, n1, E2, n2), rel_tol=1e-14)
    assert lc.compliance_constants(E1, n1, E1, n1)[1] == 0.0  # identical bodies: B = 0
    assert B > 0  # the softer, more compressible silica is body 1


def dundurs(E1, n1, E2, n2):
    """Dundurs' alpha, beta (plane strain) in the convention of Hutchinson & Suo (1992,
    Adv. Appl. Mech. 29, 63), with the Kolosov constants k = 3 - 4 nu and the shear moduli:
    alpha = (m1 (k2 + 1) - m2 (k1 + 1)) / D, beta = (m1 (k2 - 1) - m2 (k1 - 1)) / D,
    D = m1 (k2 + 1) + m2 (k1 + 1); alpha > 0 when body 1 (the cylinder) is the stiffer."""
    m1, m2 = E1 / (2 * (1 + n1)), E2 / (2 * (1 + n2))
    k1, k2 = 3 - 4 * n1, 3 - 4 * n2
    D = m1 * (k2 + 1) + m2 * (k1 + 1)
    return (m1 * (k2 + 1) - m2 * (k1 + 1)) / D, (m1 * (k2 - 1) - m2 * (k1 - 1)) / D


def test_dundurs_beta():
    beta = lc.dundurs_beta
    E1, n1, E2, n2 = 70e9, 0.17, 160e9, 0.22
    assert beta(E1, n1, E1, n1) == 0.0  # identical bodies
    assert beta(E1, n1, E2, n2) == pytest.approx(dundurs(E1, n1, E2, n2)[1], rel=1e-13)
    # silica on silicon, by hand: m1 = 29.914529914529915 GPa, m2 = 65.573770491803279 GPa,
    # k1 - 1 = 1.32, k1 + 1 = 3.32, k2 - 1 = 1.12, k2 + 1 = 3.12
    assert beta(E1, n1, E2, n2) == pytest.approx(-0.17056777843847415, rel=1e-13)
    # exchanging the bodies changes the sign
    assert beta(E2, n2, E1, n1) == pytest.approx(-beta(E1, n1, E2, n2), rel=1e-14)
    # a rigid cylinder: (1 - 2 nu2)/(2 (1 - nu2)), 2/7 for nu2 = 0.3, 0 on an incompressible
    # substrate, 1/2 for nu2 = 0
    assert beta(np.inf, 0.3, 100e9, 0.3) == pytest.approx(2 / 7, rel=1e-15)
    assert beta(np.inf, 0.3, 100e9, 0.5) == 0.0
    assert beta(np.inf, 0.3, 100e9, 0.0) == pytest.approx(0.5, rel=1e-15)
    # for Poisson's ratios in [0, 1/2] (alpha, beta) lie in Dundurs' parallelogram
    # |alpha| <= 1, |alpha - 4 beta| <= 1
    rng = np.random.default_rng(20240101)
    Ea, Eb = 10 ** rng.uniform(8, 12, (2, 500))
    na, nb = rng.uniform(0, 0.5, (2, 500))
    alpha = dundurs(Ea, na, Eb, nb)[0]
    b = beta(Ea, na, Eb, nb)
    assert np.all(np.abs(alpha - 4 * b) <= 1 + 1e-12)
    assert np.abs(alpha - 4 * b).max() > 0.9  # the sample reaches the edges


def test_maugis_convention():
    w, z0 = 0.05, 0.25e-9
    s0, h = lc.adhesion_from_work(w, z0)
    # 16 (0.05)/(9 sqrt(3) (0.25e-9)) = 0.8/3.8971143170299740e-9 Pa
    assert math.isclose(s0, 205.28009571186694e6, rel_tol=1e-15)
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
