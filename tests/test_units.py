"""The scaling declared once (linecontact.units): the declarations, to_si, the SI results.

to_si against the hand conversions for every result class that declares its scales; every
declared field is a field of its class; every SI result and every fit result is a Result
whose columns round-trip.
"""

import dataclasses
import math

import numpy as np
import pytest

import linecontact as lc
from linecontact import inverse as inv
from linecontact.cylinder import (
    Cylinder,
    CylinderLennardJonesLoadCurve,
    CylinderLoadCurve,
    CylinderSliding,
)
from linecontact.laws import LennardJones
from linecontact.lennard_jones._groups import LennardJonesPullOff
from linecontact.lennard_jones_groups import LennardJonesContact, LennardJonesLoadCurve
from linecontact.normal import LoadCurve, NormalContact, PullOff
from linecontact.push import Push
from linecontact.results import Result
from linecontact.sliding import SlidingContact
from linecontact.tangential import (
    CoulombRolling,
    CoulombSlidingInitiation,
    SlidingInitiation,
    SteadyRolling,
)
from linecontact.tangential.history import (
    CoulombCyclicLoss,
    CoulombTangentialHistory,
    CyclicLoss,
    TangentialHistory,
)
from linecontact.uncertainty import Estimate
from linecontact.units import SCALES, Scales, si_units, to_si

DECLARED = [
    NormalContact,
    PullOff,
    LennardJonesContact,
    LennardJonesPullOff,
    LoadCurve,
    LennardJonesLoadCurve,
    SlidingContact,
    Push,
    SlidingInitiation,
    CoulombSlidingInitiation,
    SteadyRolling,
    CoulombRolling,
    TangentialHistory,
    CoulombTangentialHistory,
    CyclicLoss,
    CoulombCyclicLoss,
]

R, E, W, Z0 = 50e-9, 100e9, 0.1, 0.3e-9


@pytest.fixture(scope="module")
def cyl():
    return Cylinder.from_modulus(R, E, cohesive_stress=1e9, adhesion_range=0.5e-9)


@pytest.mark.parametrize("cls", DECLARED, ids=lambda c: c.__name__)
def test_every_declared_field_is_a_field(cls):
    names = {f.name for f in dataclasses.fields(cls)}
    assert cls.si, f"{cls.__name__} declares no scales"
    for field, (si_name, scale, unit) in cls.si.items():
        assert field in names, f"{cls.__name__}.si names {field!r}, not a field"
        assert scale in SCALES, f"{cls.__name__}.si: scale {scale!r} is not in SCALES"
        assert unit == SCALES[scale][0], f"{cls.__name__}.{field}: {unit} is not {scale}'s"
        assert si_name and si_name not in names
    assert len({v[0] for v in cls.si.values()}) == len(cls.si)
    assert set(si_units(cls)) == {v[0] for v in cls.si.values()}


def test_scales():
    s = Scales(R=2.0, E=3.0, h=5.0, a=7.0)
    assert (s["1"], s["R"], s["E"], s["h"], s["a"]) == (1.0, 2.0, 3.0, 5.0, 7.0)
    assert (s["Eh"], s["ER"], s["Ea"], s["EhR"], s["Ea2"]) == (15.0, 6.0, 21.0, 30.0, 147.0)
    assert set(SCALES) == {"1", "R", "h", "a", "E", "Eh", "ER", "Ea", "EhR", "Ea2"}
    with pytest.raises(KeyError, match="no scale"):
        s["nope"]
    c = Cylinder.from_modulus(R, E, cohesive_stress=1e9, adhesion_range=0.5e-9)
    assert Scales.of(c) == Scales(R, E, 0.5e-9)
    assert Scales.of(c, h=1e-9, a=3e-9) == Scales(R, E, 1e-9, 3e-9)
    assert math.isnan(Scales.of(c).a)


def test_to_si_needs_a_declaration():
    with pytest.raises(TypeError, match="declares no SI scales"):
        to_si(inv.ShearStrengthFit(1.0, 0.1, (0.8, 1.2), math.nan), Scales(R, E, 1e-9))


def test_normal_contact_and_pull_off(cyl):
    Eh = E * cyl.adhesion_range
    r = lc.normal_contact([0.01, 0.05], R_over_h=cyl.R_over_h, sigma0_over_E=cyl.sigma0_over_E)
    si = to_si(r, Scales.of(cyl))
    assert list(si) == ["contact_half_width", "adhesive_zone_half_width", "load"]
    np.testing.assert_array_equal(si["contact_half_width"], np.multiply(r.a_over_R, R))
    np.testing.assert_array_equal(si["adhesive_zone_half_width"], np.multiply(r.c_over_R, R))
    np.testing.assert_array_equal(si["load"], np.multiply(r.F_over_Eh, Eh))
    c = cyl.contact(load=[0.5, 1.0])
    n = c.nondimensional
    np.testing.assert_array_equal(c.contact_half_width, np.multiply(n.a_over_R, R))
    np.testing.assert_array_equal(c.load, np.multiply(n.F_over_Eh, Eh))
    s = cyl.contact(load=1.0)
    assert isinstance(s.contact_half_width, float)
    p = cyl.pull_off()
    q = p.nondimensional
    assert p.pull_off_force == q.F_pulloff_over_Eh * Eh
    assert p.contact_half_width_at_pull_off == q.a_over_R_at_pulloff * R
    assert p.zero_width_force == q.F_zero_width_over_Eh * Eh
    assert to_si(q, Scales.of(cyl)) == {
        k: getattr(p, k)
        for k in ("pull_off_force", "contact_half_width_at_pull_off", "zero_width_force")
    }


def test_lennard_jones():
    pytest.importorskip("scipy")
    c = Cylinder.from_modulus(R, 50e9, work_of_adhesion=W, equilibrium_spacing=Z0)
    h, Eh = c.adhesion_range, c.modulus * c.adhesion_range
    p = c.under(LennardJones).pull_off()
    q = p.nondimensional
    assert p.pull_off_force == float(q.F_pulloff_over_Eh) * Eh
    assert p.error_estimate == float(q.error_estimate_over_Eh) * Eh
    assert p.contact_half_width_at_pull_off == float(q.a_over_R_at_pulloff) * R
    assert p.central_gap_at_pull_off == float(q.central_gap_over_h_at_pulloff) * h
    assert p.jump_in_force == float(q.F_jump_in_over_Eh) * Eh or math.isnan(p.jump_in_force)
    k = c.under(LennardJones).contact(load=[0.5, 1.0])
    n = k.nondimensional
    np.testing.assert_array_equal(k.contact_half_width, np.multiply(n.a_over_R, R))
    np.testing.assert_array_equal(k.central_gap, np.multiply(n.central_gap_over_h, h))
    np.testing.assert_array_equal(k.error_estimate, np.multiply(n.error_estimate_over_Eh, Eh))
    np.testing.assert_array_equal(k.load, [0.5, 1.0])  # as given
    np.testing.assert_allclose(to_si(n, Scales.of(c))["load"], [0.5, 1.0], rtol=1e-12)
    assert isinstance(k, Result) and isinstance(p, Result)
    u = c.under(LennardJones).load_curve()
    m = u.nondimensional
    assert isinstance(u, CylinderLennardJonesLoadCurve) and isinstance(u, Result)
    np.testing.assert_array_equal(u.load, np.multiply(m.F_over_Eh, Eh))
    np.testing.assert_array_equal(u.error_estimate, np.multiply(m.error_estimate_over_Eh, Eh))
    np.testing.assert_array_equal(u.contact_half_width, np.multiply(m.a_over_R, R))
    np.testing.assert_array_equal(u.central_gap, np.multiply(m.central_gap_over_h, h))
    np.testing.assert_array_equal(u.turning_point, m.turning_point)
    np.testing.assert_array_equal(u.total(1e-6)["load"], u.load * 1e-6)
    _round_trip(u)


def test_tangential(cyl):
    for fn in (cyl.sliding_initiation, cyl.steady_rolling):
        t = fn([0.5, 1.0], friction_stress=1e9, tangential_load=0.5)
        r = t.nondimensional
        a = np.asarray(t.contact_half_width)
        np.testing.assert_array_equal(t.stick_zone_end, np.multiply(r.d_over_a, a))
        np.testing.assert_array_equal(t.tangential_load, np.multiply(r.T_over_Ea, E * a))
        si = to_si(r, Scales.of(cyl, a=a))
        np.testing.assert_array_equal(si["tangential_load"], t.tangential_load)
        assert isinstance(t, Result)
        assert set(t.columns()) >= {"normal_load", "stick_zone_end", "tangential_load"}


def test_push(cyl):
    h2 = 2 * cyl.adhesion_range
    p = cyl.push(friction_stress=1e9, height=[0.5 * R, 1.5 * R], receding_range=h2, normal_load=1.0)
    n = p.nondimensional
    Eh = E * cyl.adhesion_range  # the groups of a push are over E h2, h2 the advancing range
    for si_name, field, scale in (
        ("height", "H_over_R", R),
        ("moment_arm", "H_arm_over_R", R),
        ("rest_half_width", "a_rest_over_R", R),
        ("slide_half_width", "a_slide_over_R", R),
        ("rolling_resistance", "Q_roll_over_Eh2", Eh),
        ("sliding_resistance", "Q_slide_over_Eh2", Eh),
        ("slip_onset", "Q_onset_over_Eh2", Eh),
        ("critical_height", "H_critical_over_R", R),
    ):
        np.testing.assert_array_equal(getattr(p, si_name), np.multiply(getattr(n, field), scale))
    assert to_si(n, Scales.of(cyl)).keys() == {v[0] for v in Push.si.values()}


def test_sliding(cyl):
    h2 = cyl.adhesion_range
    s = cyl.sliding(receding_range=2 * h2, contact_half_width=[2e-9, 4e-9], friction_stress=1e8)
    n = s.nondimensional
    Eh = E * h2  # the groups of sliding are over h = h2, the cylinder's (advancing) range
    for si_name, field, scale in (
        ("contact_half_width", "a_over_R", R),
        ("trailing_zone_end", "c1_over_R", R),
        ("leading_zone_end", "c2_over_R", R),
        ("eccentricity", "e_over_R", R),
        ("load", "F_over_Eh2", Eh),
        ("moment", "M_over_Eh2R", Eh * R),
        ("moment_about_axis", "M_axis_over_Eh2R", Eh * R),
        ("friction_force", "T_over_Eh2", Eh),
    ):
        np.testing.assert_array_equal(getattr(s, si_name), np.multiply(getattr(n, field), scale))
    assert s.receding_range == 2 * h2
    assert isinstance(s, CylinderSliding) and isinstance(s, Result)
    assert to_si(n, Scales.of(cyl)).keys() == {v[0] for v in SlidingContact.si.values()}
    t = s.total(1e-6)  # the group times the scale's total (E h2 L), as the command line's
    assert list(t) == ["load", "moment", "friction_force"]
    np.testing.assert_array_equal(t["moment"], np.multiply(n.M_over_Eh2R, Eh * R * 1e-6))


def test_load_curve(cyl):
    c = cyl.load_curve(max_half_width=5e-9, num=10, num_noncontact=4)
    n = c.nondimensional
    h, Eh = cyl.adhesion_range, E * cyl.adhesion_range
    assert isinstance(c, CylinderLoadCurve) and isinstance(c, Result)
    np.testing.assert_array_equal(c.central_gap, np.multiply(n.central_gap_over_h, h))
    np.testing.assert_array_equal(c.contact_half_width, np.multiply(n.a_over_R, R))
    np.testing.assert_array_equal(c.adhesive_zone_half_width, np.multiply(n.c_over_R, R))
    np.testing.assert_array_equal(c.load, np.multiply(n.F_over_Eh, Eh))
    np.testing.assert_array_equal(c.branch, n.branch)
    np.testing.assert_array_equal(c.total(2e-6)["load"], c.load * 2e-6)
    assert to_si(n, Scales.of(cyl)).keys() == {v[0] for v in LoadCurve.si.values()}


def test_histories(cyl):
    w = cyl.cyclic_loss(1.0, [0.5, 1.0], friction_stress=1e9)
    n, a = w.nondimensional, w.contact_half_width
    np.testing.assert_array_equal(w.energy_per_cycle, np.multiply(n.W_over_Ea2, E * a * a))
    np.testing.assert_array_equal(w.stick_zone_half_width, np.multiply(n.c_over_a, a))
    np.testing.assert_allclose(to_si(n, Scales.of(cyl, a=a))["amplitude"], [0.5, 1.0], rtol=1e-12)
    h = cyl.tangential_history(1.0, [1.0, -1.0, 1.0], friction_stress=1e9)
    m, a = h.nondimensional, h.contact_half_width
    np.testing.assert_array_equal(h.stick_zone_half_width, np.asarray(m.c_over_a) * a)
    np.testing.assert_array_equal(h.displacement, np.asarray(m.displacement_over_a) * a)
    np.testing.assert_allclose(
        h.dissipation, np.asarray(m.dissipation_over_Ea2) * E * a * a, rtol=1e-15
    )
    np.testing.assert_allclose(
        to_si(m, Scales.of(cyl, a=a))["tangential_load"], [1.0, -1.0, 1.0], rtol=1e-12
    )


def _round_trip(r: Result) -> None:
    assert isinstance(r, Result)
    cols = r.columns()
    assert all(np.ndim(v) == 1 and len(v) == r.size for v in cols.values())
    recs = r.to_records()
    assert len(recs) == r.size
    for k, v in cols.items():
        assert [rec[k] for rec in recs] == v.tolist()
    d = r.to_dict()
    assert set(d) >= set(cols) - set(type(r).derived)
    assert set(d) >= set(type(r).whole)


def test_si_results_are_results(cyl):
    results = [
        cyl.contact(load=[0.5, 1.0]),
        cyl.contact(load=1.0),
        cyl.pull_off(),
        cyl.sliding_initiation([0.5, 1.0], friction_stress=1e9, tangential_load=0.5),
        cyl.steady_rolling(1.0, friction_stress=1e9, tangential_load=0.5),
        cyl.push(friction_stress=1e9, height=[0.5 * R, R], receding_range=1e-9, normal_load=1.0),
        cyl.cyclic_loss(1.0, [0.5, 1.0], friction_stress=1e9),
        cyl.tangential_history(1.0, [1.0, -1.0, 1.0], friction_stress=1e9),
        cyl.sliding(h1_over_h2=2.0, load=[0.5, 1.0], friction_stress=1e8, method="closed-form"),
        cyl.load_curve(num=10, num_noncontact=4),
    ]
    for r in results:
        _round_trip(r)
    c = results[0]
    rebuilt = type(c)(**c.to_dict(), nondimensional=c.nondimensional)
    np.testing.assert_array_equal(rebuilt.contact_half_width, c.contact_half_width)
    assert results[6].columns()["friction"].tolist() == ["constant", "constant"]


def test_fit_results_are_results():
    Rs = np.array([50e-9, 100e-9, 200e-9, 400e-9])
    F = inv.pull_off_force(Rs, 50e9, W, Z0)
    fit = inv.fit_pull_off(Rs, F * (1 + 0.01 * np.array([1, -1, 1, -1])), 50e9, bootstrap=0)
    _round_trip(fit)
    assert fit.shape == (4,)
    d = fit.to_dict()
    assert d["covariance"] == fit.covariance.tolist()
    assert d["work_of_adhesion_ci95"] == fit.work_of_adhesion_ci95
    assert "covariance" not in fit.columns() and "radius" not in d
    assert fit.columns()["work_of_adhesion_sd_total"][0] == fit.work_of_adhesion_sd_total
    est = inv.propagate(
        inv.work_of_adhesion_from_pull_off,
        dict(pull_off_force=float(F[0]), radius=Rs[0], modulus=50e9, equilibrium_spacing=Z0),
        dict(pull_off_force=0.05, radius=0.0, modulus=0.0, equilibrium_spacing=0.0),
        n_samples=200,
    )
    assert isinstance(est, Estimate)
    _round_trip(est)
    assert est.shape == () and est.to_dict()["ci95"] == est.ci95
    f = np.array([1.0, 1.1])
    s = inv.fit_shear_strength(
        lambda friction_force, normal_load, k: friction_force * k,
        f,
        np.array([0.5, 0.6]),
        np.array([0.01, 0.01]),
        {"k": 2.0},
        {"k": 0.0},
        100,
        0,
    )
    assert isinstance(s, inv.ShearStrengthFit)
    _round_trip(s)
    assert s.tau0 == pytest.approx(2.1) and len(s.to_dict()["tau0_ci95"]) == 2
