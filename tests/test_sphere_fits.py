"""The sphere's fits with intervals (linecontact.sphere.fits): (w, z0) from pull-offs, tau0 from
friction, which model; recovery, a second path through the SI body, coverage, flags, refusals."""

import math

import numpy as np
import pytest

import linecontact as lc
from linecontact.errors import ParameterError
from linecontact.sphere import fits as sf
from linecontact.sphere import (
    sphere_fit_pull_off,
    sphere_fit_shear_strength,
    sphere_models,
    sphere_which_model,
)

E = 50e9
W, Z0 = 0.1, 3e-10
RADII = np.array([5e-9, 20e-9, 100e-9, 500e-9, 2e-6])  # Maugis parameter 0.1 to 0.8
S = 16 / (9 * math.sqrt(3))  # sigma0 = S w / z0: the Dugdale step matched to Lennard-Jones


def si_pull_offs(R, w, z0, modulus=E):
    """The pull-offs [N] through the SI body, one Sphere per radius (a second path)."""
    return np.array(
        [
            lc.Sphere.from_modulus(r, modulus, work_of_adhesion=w, equilibrium_spacing=z0)
            .pull_off()
            .pull_off_force
            for r in R
        ]
    )


# --------------------------------------------------------------------------------------------
# (w, z0) from pull-offs


def test_the_forward_model_is_the_si_bodys_pull_off():
    assert np.allclose(sf._pull_offs(RADII, E, W, Z0), si_pull_offs(RADII, W, Z0), rtol=1e-14)


@pytest.mark.parametrize(("w", "z0"), [(W, Z0), (0.03, 3e-10), (0.5, 2e-10), (1.0, 4e-10)])
def test_noise_free_joint_fit_recovers_both_and_reproduces_the_si_pull_offs(w, z0):
    F = si_pull_offs(RADII, w, z0)
    fit = sphere_fit_pull_off(RADII, F, E, bootstrap=0)
    assert fit.work_of_adhesion == pytest.approx(w, rel=1e-8)
    assert fit.equilibrium_spacing == pytest.approx(z0, rel=1e-8)
    assert fit.identifiable and not fit.fixed_spacing and fit.dof == 3
    assert "exactly" in fit.note  # no sd and no scatter: no uncertainty, said
    # the fitted (w, z0) give the pull-offs back through the SI body
    again = si_pull_offs(RADII, fit.work_of_adhesion, fit.equilibrium_spacing)
    assert np.allclose(again, F, rtol=1e-10)
    assert np.allclose(fit.model, again, rtol=1e-12)
    # lambda per radius, from its definition: 2 sigma0 (R / (pi w K^2))^(1/3), K = 4E/3
    sigma0 = S * w / z0
    lam = 2 * sigma0 * np.cbrt(RADII / (np.pi * w * (4 * E / 3) ** 2))
    assert np.allclose(fit.maugis_parameter, lam, rtol=1e-7)


def test_fixed_range_fits_w_from_one_point_as_the_inverse_does():
    F = si_pull_offs(RADII[:1], W, Z0)
    fit = sphere_fit_pull_off(RADII[:1], F, E, equilibrium_spacing=Z0)
    assert fit.work_of_adhesion == pytest.approx(W, rel=1e-10)
    w_inv = lc.sphere_work_of_adhesion_from_pull_off(F[0], RADII[0], E, Z0)
    assert fit.work_of_adhesion == pytest.approx(w_inv, rel=1e-10)
    assert fit.fixed_spacing and fit.equilibrium_spacing == Z0
    assert math.isnan(fit.correlation) and fit.equilibrium_spacing_sd == 0.0


def noisy(seed, rel=0.03, R=RADII, w=W, z0=Z0):
    F = sf._pull_offs(R, E, w, z0)
    sd = rel * np.abs(F)
    return F + sd * np.random.default_rng(seed).standard_normal(F.size), sd


@pytest.mark.slow  # 20 joint fits: ~20 s
def test_the_95_intervals_cover_the_truth_in_most_of_20_repetitions():
    hits_w = hits_z = 0
    for seed in range(20):
        F, sd = noisy(seed, rel=0.01)
        fit = sphere_fit_pull_off(RADII, F, E, sd=sd, bootstrap=0)
        lo, hi = fit.work_of_adhesion_ci95
        hits_w += lo <= W <= hi
        lo, hi = fit.equilibrium_spacing_ci95
        hits_z += lo <= Z0 <= hi
        assert fit.identifiable, fit.note
    # binomial(20, 0.95): 14 or more with probability 0.9997
    assert hits_w >= 14 and hits_z >= 14, (hits_w, hits_z)


def test_the_bootstrap_gives_an_interval_about_the_fit_from_its_refits():
    F, sd = noisy(2026, rel=0.01)
    fit = sphere_fit_pull_off(RADII, F, E, sd=sd, bootstrap=40, seed=1)
    assert fit.identifiable, fit.note
    assert fit.refits == 40
    for name in ("work_of_adhesion", "equilibrium_spacing"):
        lo, hi = getattr(fit, name + "_ci95")
        assert lo < getattr(fit, name) < hi, name
        assert (lo, hi) != getattr(fit, name + "_ci95_linear"), name  # the bootstrap ran
        lin = getattr(fit, name + "_ci95_linear")
        # the bootstrap's and the linear interval: of one size (within a factor of 2)
        assert 0.5 < (hi - lo) / (lin[1] - lin[0]) < 2, name
    # the covariance is that of the sds given: sd from its diagonal
    assert fit.work_of_adhesion_sd == pytest.approx(math.sqrt(fit.covariance[0, 0]))
    assert fit.residuals == pytest.approx(fit.model - F)


JKR_RADII = np.array([20e-6, 50e-6, 200e-6])  # lambda 7.7 to 17 at w = 1 J/m^2
DMT_RADII = np.array([2e-9, 4e-9, 8e-9])  # lambda 0.006 to 0.009 at w = 0.002 J/m^2


@pytest.mark.parametrize(("R", "w", "limit"), [(JKR_RADII, 1.0, "JKR"), (DMT_RADII, 0.002, "DMT")])
def test_data_all_in_one_limit_do_not_determine_z0_and_say_so(R, w, limit):
    lam = sf._sphere_maugis_parameter(*sf._groups(R, E, w, Z0)[:2])
    assert np.all(lam > 5) if limit == "JKR" else np.all(lam < 0.1)
    F, sd = noisy(3, rel=0.01, R=R, w=w)
    fit = sphere_fit_pull_off(R, F, E, sd=sd, bootstrap=0)
    assert not fit.identifiable
    # the fit may land in either limit: pull-offs proportional to R fit both
    assert "do not determine z0" in fit.note and "cannot tell the two limits apart" in fit.note
    assert np.all(fit.maugis_parameter > 5) or np.all(fit.maugis_parameter < 0.1)
    # no fake tight interval: the search box, an infinite sd
    assert fit.equilibrium_spacing_ci95 == sf.SPACING_BOUNDS
    assert fit.equilibrium_spacing_ci95_linear == sf.SPACING_BOUNDS
    assert fit.equilibrium_spacing_sd == math.inf
    # w's interval spans its DMT and JKR readings |F|/(2 pi R) to |F|/(1.5 pi R), and the truth
    lo, hi = fit.work_of_adhesion_ci95
    assert lo <= w <= hi
    assert lo < np.mean(-F / (2 * np.pi * R)) and hi > np.mean(-F / (1.5 * np.pi * R))


def test_noise_free_jkr_data_are_flagged_too():
    fit = sphere_fit_pull_off(JKR_RADII, sf._pull_offs(JKR_RADII, E, 1.0, Z0), E, bootstrap=0)
    assert not fit.identifiable and "cannot tell the two limits apart" in fit.note


def test_two_radii_with_two_exact_solutions_are_flagged():
    R = np.array([1e-8, 1e-6])
    F = sf._pull_offs(R, E, W, Z0)
    fit = sphere_fit_pull_off(R, F, E, bootstrap=0)
    assert not fit.identifiable and "another minimum" in fit.note
    assert np.allclose(fit.model, F, rtol=1e-10)  # whichever it kept fits exactly


# --------------------------------------------------------------------------------------------
# tau0 from friction against load

LOADS = np.array([-5e-9, 0.0, 5e-9, 20e-9, 50e-9])
R_TIP, TAU = 20e-9, 1e8


def contact_areas(loads, w=W, z0=Z0, modulus=E):
    tip = lc.Sphere.from_modulus(R_TIP, modulus, work_of_adhesion=w, equilibrium_spacing=z0)
    return np.pi * np.asarray(tip.contact(load=loads).contact_radius) ** 2


def test_tau0_is_recovered_exactly_from_noise_free_friction():
    f = TAU * contact_areas(LOADS)
    fit = sphere_fit_shear_strength(f, LOADS, R_TIP, E, W, Z0)
    assert fit.shear_strength == pytest.approx(TAU, rel=1e-12)
    assert np.allclose(fit.model, f, rtol=1e-12)
    assert fit.shear_strength_sd < 1e-10 * TAU  # no scatter
    # each point's tau0 from the existing inverse (a second path) is the same
    taus = lc.sphere_shear_strength_from_friction(f, LOADS, R_TIP, E, W, Z0)
    assert np.allclose(taus, TAU, rtol=1e-12)


def test_the_closed_form_interval_covers_tau0_in_most_of_20_repetitions():
    A = contact_areas(LOADS)
    sd = 0.05 * TAU * A
    rng = np.random.default_rng(11)
    hits, taus, sds = 0, [], []
    for _ in range(20):
        fit = sphere_fit_shear_strength(
            TAU * A + sd * rng.standard_normal(A.size), LOADS, R_TIP, E, W, Z0, sd=sd
        )
        lo, hi = fit.shear_strength_ci95
        hits += lo <= TAU <= hi
        taus.append(fit.shear_strength)
        sds.append(fit.shear_strength_sd)
    assert hits >= 14
    # the weighted least squares by hand: 1/sum(A^2/sd^2) is its variance (Birge ratio <= 1)
    assert min(sds) == pytest.approx(1 / math.sqrt(np.sum(A * A / sd**2)), rel=1e-12)


def test_without_sds_the_interval_is_students_and_one_point_has_none():
    A = contact_areas(LOADS)
    f = TAU * A * (1 + 0.05 * np.array([1, -1, 0.5, -0.5, 0.2]))
    fit = sphere_fit_shear_strength(f, LOADS, R_TIP, E, W, Z0)
    tau = np.sum(f * A) / np.sum(A * A)
    s2 = np.sum((f - tau * A) ** 2) / 4
    half = 2.7764451051977987 * math.sqrt(s2 / np.sum(A * A))  # t(0.975, 4)
    assert fit.shear_strength == pytest.approx(tau, rel=1e-12)
    assert fit.shear_strength_ci95 == pytest.approx((tau - half, tau + half), rel=1e-9)
    one = sphere_fit_shear_strength(f[:1], LOADS[:1], R_TIP, E, W, Z0)
    assert math.isnan(one.shear_strength_sd) and "no uncertainty" in one.note


def test_the_inputs_uncertainty_matches_the_linear_propagation():
    f = TAU * contact_areas(LOADS)
    w_sd = 0.005
    fit = sphere_fit_shear_strength(
        f, LOADS, R_TIP, E, W, Z0, work_of_adhesion_sd=w_sd, samples=400, seed=5
    )
    # d tau0 / d w by central differences through the SI body's areas, times w's sd
    h = 1e-4
    dtau = (
        np.sum(f * contact_areas(LOADS, w=W + h)) / np.sum(contact_areas(LOADS, w=W + h) ** 2)
        - np.sum(f * contact_areas(LOADS, w=W - h)) / np.sum(contact_areas(LOADS, w=W - h) ** 2)
    ) / (2 * h)
    assert fit.shear_strength_sd_inputs == pytest.approx(abs(dtau) * w_sd, rel=0.15)
    assert fit.shear_strength_sd_total == pytest.approx(
        math.hypot(fit.shear_strength_sd, fit.shear_strength_sd_inputs)
    )


# --------------------------------------------------------------------------------------------
# which model


@pytest.mark.parametrize(("R", "w", "regime"), [(20e-9, 0.1, "transition"), (50e-6, 1.0, "JKR")])
def test_which_model_is_sphere_models_at_the_measured_w(R, w, regime):
    F = si_pull_offs([R], w, Z0)[0]
    load = 50 * abs(F)
    got = sphere_which_model(F, R, E, equilibrium_spacing=Z0, max_load=load)
    assert got.work_of_adhesion == pytest.approx(w, rel=1e-10)
    h = Z0 / S
    ref = sphere_models(load / (E * h * R), R / h, S * w / (Z0 * E))
    assert got.regime == ref.regime == regime
    assert got.best == ref.best
    for k in ("pull_off_error_dmt", "pull_off_error_jkr", "radius_error_hertz", "radius_error_jkr"):
        assert getattr(got, k) == pytest.approx(float(getattr(ref, k)), rel=1e-6, abs=1e-12), k


# --------------------------------------------------------------------------------------------
# refusals, naming the parameter

F5 = [-1e-9, -2e-9, -3e-9, -4e-9, -5e-9]


@pytest.mark.parametrize(
    ("call", "name", "match"),
    [
        (lambda: sphere_fit_pull_off(RADII[:4], F5, E), "radius", "one value per data point"),
        (lambda: sphere_fit_pull_off(RADII[:1], F5[:1], E), "radius", "at least 2 distinct"),
        (lambda: sphere_fit_pull_off([1e-8, 1e-8], F5[:2], E), "radius", "at least 2 distinct"),
        (lambda: sphere_fit_pull_off(RADII, [1e-9] + F5[1:], E), "pull_off_force", r"\(-inf, 0\)"),
        (lambda: sphere_fit_pull_off(RADII, [0.0] + F5[1:], E), "pull_off_force", "got 0"),
        (lambda: sphere_fit_pull_off(RADII, [math.nan] + F5[1:], E), "pull_off_force", "nan"),
        (lambda: sphere_fit_pull_off([math.nan, *RADII[1:]], F5, E), "radius", "nan"),
        (lambda: sphere_fit_pull_off(RADII, F5, [E, E]), "modulus", "single number"),
        (lambda: sphere_fit_pull_off(RADII, F5, E, sd=[1e-10] * 4), "sd", "one value"),
        (lambda: sphere_fit_pull_off(RADII, F5, E, sd=[0.0] * 5), "sd", "sd"),
        (lambda: sphere_fit_pull_off(RADII, F5, E, bootstrap=-1), "bootstrap", "integer"),
        (lambda: sphere_fit_pull_off(RADII, F5, E, seed=True), "seed", "integer"),
        (
            lambda: sphere_fit_pull_off(RADII, F5, E, equilibrium_spacing=-1.0),
            "equilibrium_spacing",
            r"\(0, inf\)",
        ),
        (
            lambda: sphere_fit_shear_strength([1e-9] * 3, [0.0] * 2, R_TIP, E, W, Z0),
            "normal_load",
            "one value per data point",
        ),
        (
            lambda: sphere_fit_shear_strength([1e-9, -1e-9], [0.0] * 2, R_TIP, E, W, Z0),
            "friction_force",
            r"\(0, inf\)",
        ),
        (
            lambda: sphere_fit_shear_strength([1e-9], [-1e-6], R_TIP, E, W, Z0),
            "normal_load",
            "below the pull-off",
        ),
        (
            lambda: sphere_fit_shear_strength([1e-9], [1.0], R_TIP, E, W, Z0),
            "normal_load",
            "beyond the contacts",
        ),
        (
            lambda: sphere_fit_shear_strength([1e-9], [0.0], R_TIP, E, W, math.nan),
            "equilibrium_spacing",
            "nan",
        ),
        (
            lambda: sphere_which_model(1e-9, R_TIP, E, equilibrium_spacing=Z0, max_load=1e-8),
            "pull_off_force",
            r"\(-inf, 0\)",
        ),
        (
            lambda: sphere_which_model(-1e-8, R_TIP, E, equilibrium_spacing=Z0, max_load=-1e-6),
            "max_load",
            "below the pull-off",
        ),
        (
            lambda: sphere_which_model(-1e-8, R_TIP, E, equilibrium_spacing=Z0, max_load=1.0),
            "max_load",
            "beyond the contacts",
        ),
    ],
)
def test_bad_input_is_refused_naming_the_parameter(call, name, match):
    with pytest.raises(ParameterError, match=match) as err:
        call()
    assert err.value.parameter == name
    assert name in str(err.value)


# ---------------------------------------------------------------------------------------
# found by fuzzing (a second hand): wrong units said, not a scipy error or a silent bound


@pytest.mark.parametrize(("F", "R"), [(-11.96, 20e-9), (-1.196e-8, 20.0), (-1.196e-17, 20e-9)])
def test_which_model_refuses_a_pull_off_no_work_of_adhesion_gives(F, R):
    with pytest.raises(ParameterError, match=r"check the units \(N, m, Pa\)") as err:
        sphere_which_model(F, R, E, equilibrium_spacing=Z0, max_load=50e-9)
    assert err.value.parameter == "pull_off_force"


def test_which_model_takes_one_largest_load():
    with pytest.raises(ParameterError, match="max_load must be a single number"):
        sphere_which_model(-1.2e-8, 20e-9, E, equilibrium_spacing=Z0, max_load=[5e-8, 6e-8])


def test_radii_in_nanometres_are_refused_naming_the_units():
    F = sf._pull_offs(RADII, E, W, Z0)
    with pytest.raises(ParameterError, match=r"check the units \(N, m, Pa\)"):
        sphere_fit_pull_off(np.asarray(RADII) * 1e9, F, E)


def test_two_radii_in_one_limit_give_an_interval_spanning_both_readings():
    R = np.geomspace(5e-9, 2e-6, 2)
    F = sf._pull_offs(R, 1e9, 0.1, 1e-10)  # DMT-like at the fit: lambda 0.005 to 0.04
    fit = sphere_fit_pull_off(R, F, 1e9, bootstrap=0)
    assert not fit.identifiable
    lo, hi = fit.work_of_adhesion_ci95
    assert lo <= 0.1 <= hi and hi / lo == pytest.approx(4 / 3, rel=1e-9)
