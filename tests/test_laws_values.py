"""The adhesion laws as values (issue 32): a cylinder is a geometry and a law.

``Dugdale`` and ``LennardJones`` hold their SI parameters and convert themselves to the groups
their kernels take; a ``Cylinder`` built with one solves its problems under it, and a problem
not written for the law is refused in one place, naming both.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import linecontact as lc
from linecontact import Cylinder, Dugdale, LennardJones
from linecontact.laws import lennard_jones as lj_groups
from linecontact.materials import MAUGIS_STRENGTH

R, E, W, Z0 = 50e-9, 100e9, 0.1, 0.3e-9


def test_a_law_takes_either_spelling_and_matches_maugis():
    by_work = Dugdale(work_of_adhesion=W, equilibrium_spacing=Z0)
    s0 = MAUGIS_STRENGTH * W / Z0  # Maugis: the peak tension of the Lennard-Jones law
    assert by_work.cohesive_stress == pytest.approx(s0, rel=1e-15)
    assert by_work.adhesion_range == pytest.approx(W / s0, rel=1e-15)
    by_stress = Dugdale(
        cohesive_stress=by_work.cohesive_stress, adhesion_range=by_work.adhesion_range
    )
    assert by_stress.work_of_adhesion == pytest.approx(W, rel=1e-15)
    assert by_stress.equilibrium_spacing == pytest.approx(Z0, rel=1e-15)
    lj = LennardJones(W, Z0)
    assert (lj.cohesive_stress, lj.adhesion_range) == (
        by_work.cohesive_stress,
        by_work.adhesion_range,
    )
    assert lj != by_work  # the same numbers under another law are another value
    assert lj == LennardJones(work_of_adhesion=W, equilibrium_spacing=Z0)
    assert hash(lj) == hash(LennardJones(W, Z0))
    assert repr(lj) == "LennardJones(work_of_adhesion=0.1, equilibrium_spacing=3e-10)"
    with pytest.raises(AttributeError):
        lj.cohesive_stress = 1.0  # type: ignore[misc]


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"work_of_adhesion": W}, "give both work_of_adhesion and equilibrium_spacing"),
        ({"work_of_adhesion": W, "equilibrium_spacing": Z0, "adhesion_range": 1e-9}, "not both"),
        ({"cohesive_stress": 1e9}, "give adhesion_range h"),
        ({"work_of_adhesion": -0.1, "equilibrium_spacing": Z0}, "work_of_adhesion"),
        ({"cohesive_stress": "x", "adhesion_range": 1e-9}, "cohesive_stress must be a real number"),
    ],
)
def test_a_law_refuses_bad_parameters_by_name(kwargs, message):
    with pytest.raises(TypeError):
        Dugdale(W, Z0)  # type: ignore[misc]  # (w, h) or (w, z0)? keywords say which
    for law in (Dugdale, LennardJones):
        with pytest.raises(ValueError, match=message):
            law(**kwargs)


def test_the_cylinder_solves_under_its_law():
    cyl = Cylinder.from_modulus(R, E, adhesion=LennardJones(W, Z0))
    assert cyl.adhesion.name == "lennard-jones"
    p = cyl.pull_off()
    # the same pull-off the law's nondimensional function gives, in SI units
    q = lj_groups.pull_off(cyl.R_over_h, cyl.sigma0_over_E)
    assert p.pull_off_force == pytest.approx(
        q.F_pulloff_over_Eh * E * cyl.adhesion_range, rel=1e-12
    )
    # and the one of the Dugdale cylinder of the same adhesion, put under the law
    dug = Cylinder.from_modulus(R, E, work_of_adhesion=W, equilibrium_spacing=Z0)
    assert dug.adhesion == Dugdale(work_of_adhesion=W, equilibrium_spacing=Z0)
    assert dug.under(LennardJones).pull_off().pull_off_force == p.pull_off_force
    assert dug.under(LennardJones).under(Dugdale) == dug
    # the Dugdale pull-off is another number (the laws differ at this Maugis parameter)
    assert not math.isclose(dug.pull_off().pull_off_force, p.pull_off_force, rel_tol=1e-3)
    # a contact under load: the law's stable contact, carrying the load asked for
    c = cyl.contact(load=[0.5, 1.0])
    np.testing.assert_array_equal(c.load, [0.5, 1.0])
    assert np.all(np.diff(c.contact_half_width) > 0)
    curve = cyl.load_curve(max_load=1.0)
    assert type(curve).__name__ == "CylinderLennardJonesLoadCurve"


@pytest.mark.parametrize(
    ("problem", "call"),
    [
        (
            "sliding_initiation",
            lambda c: c.sliding_initiation(1.0, friction_stress=1e9, d_over_a=0.5),
        ),
        ("steady_rolling", lambda c: c.steady_rolling(1.0, friction_stress=1e9, d_over_a=0.5)),
        ("push", lambda c: c.push(friction_stress=1e6, height=25e-9, receding_range=1e-9)),
        ("tangential_history", lambda c: c.tangential_history(1.0, [0.1], friction_stress=1e9)),
        ("cyclic_loss", lambda c: c.cyclic_loss(1.0, [0.1], friction_stress=1e9)),
        ("sliding", lambda c: c.sliding(h1_over_h2=2.0, load=0.05)),
        ("the contact with contact_half_width", lambda c: c.contact(contact_half_width=5e-9)),
        (
            "the contact with contact_half_width",
            lambda c: c.contact(contact_half_width=[5e-9, 6e-9]),  # an array: refused too
        ),
        (
            "the contact with contact_half_width, method",
            lambda c: c.contact(contact_half_width=5e-9, method="collocation"),
        ),
        ("the load curve with max_half_width", lambda c: c.load_curve(max_half_width=1e-8)),
    ],
)
def test_a_problem_not_written_for_the_law_is_refused_naming_both(problem, call):
    cyl = Cylinder.from_modulus(R, E, adhesion=LennardJones(W, Z0))
    with pytest.raises(
        ValueError,
        match=rf"^{problem} is not written for a cylinder under the lennard-jones law "
        r"\(adhesion=LennardJones\(",
    ):
        call(cyl)
    # the same call under the Dugdale law is answered
    call(cyl.under(Dugdale))


def test_the_table_of_problems_is_the_cylinders_methods():
    for problem, kinds in Cylinder.WRITTEN.items():
        assert callable(getattr(Cylinder, problem))
        assert Dugdale in kinds["round"]
        assert set(kinds) <= {"round", "polygon"}


def test_a_law_is_given_once():
    with pytest.raises(ValueError, match="give adhesion either as a law"):
        Cylinder.from_modulus(
            R, E, adhesion=Dugdale(work_of_adhesion=W, equilibrium_spacing=Z0), work_of_adhesion=W
        )
    with pytest.raises(ValueError, match="adhesion must be a law"):
        Cylinder.from_modulus(R, E, adhesion=(W, Z0))  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="adhesion must be a law"):
        Cylinder(R, E, 1e9)  # type: ignore[arg-type]
    cyl = Cylinder.from_modulus(R, E, work_of_adhesion=W, equilibrium_spacing=Z0)
    for bad in ("lennard-jones", LennardJones(W, Z0), float):
        with pytest.raises(ValueError, match=r"^law must be a law's class"):
            cyl.under(bad)  # type: ignore[arg-type]
    with pytest.raises(TypeError):
        LennardJones(W, Z0, range=1e-9)  # type: ignore[call-arg]  # no such parameter
    assert LennardJones(cohesive_stress=1e9, adhesion_range=1e-9).work_of_adhesion == 1.0
    with pytest.raises(ValueError, match="max_load ends the load curve of the Lennard-Jones law"):
        Cylinder.from_modulus(
            R, E, adhesion=Dugdale(work_of_adhesion=W, equilibrium_spacing=Z0)
        ).load_curve(max_load=1.0)


def test_the_presets_take_a_law():
    cyl = lc.Cylinder.from_presets(R, "ZnO", "SiO2", adhesion=LennardJones(W, Z0))
    assert cyl.adhesion == LennardJones(W, Z0)
    assert cyl.pull_off().pull_off_force < 0
