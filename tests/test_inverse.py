"""Inverse problems (linecontact.inverse): recovery, consistency with the forward solvers,
coverage of the intervals, and bad input."""

import math
import re

import numpy as np
import pytest

import linecontact as lc
from linecontact import inverse as inv

E_SILICA_SILICON = float(lc.composite_modulus(72e9, 0.17, 163e9, 0.22))
W, Z0 = 0.1, 0.3e-9
RADII = np.array([10e-9, 40e-9, 160e-9, 640e-9, 2560e-9])  # Maugis parameter 0.21 to 1.4


def test_forward_model_is_the_cylinder_pull_off():
    cyl = lc.Cylinder.from_modulus(50e-9, 50e9, work_of_adhesion=W, equilibrium_spacing=Z0)
    F = float(inv.pull_off_force(50e-9, 50e9, W, Z0))
    assert F == pytest.approx(cyl.pull_off().pull_off_force, rel=1e-14)


def test_the_limits_of_the_forward_model_are_jkr_and_dmt():
    E = E_SILICA_SILICON
    small = float(inv.pull_off_force(1e-9, E, 0.001, Z0))  # Maugis parameter ~0.02
    assert small / float(inv.dmt_pull_off_force(1e-9, 0.001, Z0)) == pytest.approx(1, abs=2e-3)
    big = float(inv.pull_off_force(1e-4, E, 1.0, Z0))  # Maugis parameter ~ 100
    assert big / float(inv.jkr_pull_off_force(1e-4, E, 1.0)) == pytest.approx(1, abs=1e-3)


def test_jkr_width_carries_the_load():
    R, E, w = 50e-9, 50e9, 0.1
    a = inv._jkr_width(np.array([0.0, 0.5, 3.0]), R, E, w)
    F = np.pi * E * a**2 / (4 * R) - np.sqrt(2 * np.pi * w * E * a)
    assert np.allclose(F, [0.0, 0.5, 3.0], atol=1e-9)


@pytest.mark.parametrize("w", [1e-3, 0.05, 1.0, 5.0])
def test_work_of_adhesion_from_pull_off_recovers_w(w):
    F = inv.pull_off_force(RADII, E_SILICA_SILICON, w, Z0)
    got = inv.work_of_adhesion_from_pull_off(F, RADII, E_SILICA_SILICON, Z0)
    assert np.allclose(got, w, rtol=1e-12)


def test_work_of_adhesion_from_width_recovers_w():
    cyl = lc.Cylinder.from_modulus(
        80e-9, E_SILICA_SILICON, work_of_adhesion=W, equilibrium_spacing=Z0
    )
    loads = np.array([-0.5, 0.0, 2.0])
    a = cyl.contact(load=loads).contact_half_width
    got = inv.work_of_adhesion_from_width(a, loads, 80e-9, E_SILICA_SILICON, Z0)
    assert np.allclose(got, W, rtol=1e-9)


def test_shear_strength_inverts_the_pushed_fibre_and_the_sliding_contact():
    """tau0 from Q_slide of the forward push (with hysteresis) and from 2 a tau0 (without)."""
    R, E, w2, w1, tau = 50e-9, 50e9, 0.05, 0.1, 2e7
    s0, h2 = lc.adhesion_from_work(w2, Z0)
    F = 0.3
    p = lc.push(R / h2, w1 / w2, s0 / E, tau / E, F / (E * h2), 1.0)
    Q = float(p.Q_slide_over_Eh2) * E * h2
    got = inv.shear_strength_from_friction(Q, F, R, E, w2, Z0, receding_work_of_adhesion=w1)
    assert float(got) == pytest.approx(tau, rel=1e-9)
    cyl = lc.Cylinder.from_modulus(R, E, work_of_adhesion=w2, equilibrium_spacing=Z0)
    a = cyl.contact(load=F).contact_half_width
    got = inv.shear_strength_from_friction(2 * a * tau, F, R, E, w2, Z0)
    assert float(got) == pytest.approx(tau, rel=1e-12)


def test_the_simple_models_differ_from_maugis_dugdale_in_the_transition():
    args = (0.2, 0.5, 50e-9, E_SILICA_SILICON, W, Z0)
    md = float(inv.shear_strength_from_friction(*args))
    for contact in ("jkr", "dmt", "hertz"):
        other = float(inv.shear_strength_from_friction(*args, contact=contact))
        assert other != pytest.approx(md, rel=0.01), contact


# --------------------------------------------------------------------------------------------
# the joint fit


def test_noise_free_joint_fit_recovers_both_to_1e_6():
    F = inv.pull_off_force(RADII, E_SILICA_SILICON, W, Z0)
    fit = inv.fit_pull_off(RADII, F, E_SILICA_SILICON, bootstrap=0)
    assert fit.work_of_adhesion == pytest.approx(W, rel=1e-6)
    assert fit.equilibrium_spacing == pytest.approx(Z0, rel=1e-6)
    assert fit.identifiable
    assert np.max(np.abs(fit.residuals)) < 1e-9 * np.max(np.abs(F))


def test_fixed_range_fits_w_alone_from_one_point():
    F = inv.pull_off_force(RADII[:1], E_SILICA_SILICON, W, Z0)
    fit = inv.fit_pull_off(RADII[:1], F, E_SILICA_SILICON, equilibrium_spacing=Z0)
    assert fit.work_of_adhesion == pytest.approx(W, rel=1e-9)
    assert fit.fixed_spacing and fit.equilibrium_spacing == Z0 and math.isnan(fit.correlation)


def test_jkr_data_do_not_determine_the_range_and_say_so():
    R = np.array([2e-6, 4e-6, 8e-6])
    F = inv.pull_off_force(R, E_SILICA_SILICON, 1.0, Z0)
    rng = np.random.default_rng(3)
    fit = inv.fit_pull_off(
        R, F * (1 + 0.02 * rng.standard_normal(3)), E_SILICA_SILICON, bootstrap=0
    )
    assert not fit.identifiable
    assert "do not determine z0" in fit.note and "JKR" in fit.note


def test_covariance_matches_the_scatter_of_repeated_fits():
    rng = np.random.default_rng(7)
    F = inv.pull_off_force(RADII, E_SILICA_SILICON, W, Z0)
    sd = 0.02 * np.abs(F)
    ws = [
        inv.fit_pull_off(
            RADII, F + sd * rng.standard_normal(F.size), E_SILICA_SILICON, sd=sd, bootstrap=0
        ).work_of_adhesion
        for _ in range(40)
    ]
    fit = inv.fit_pull_off(RADII, F, E_SILICA_SILICON, sd=sd, bootstrap=0)
    assert np.std(ws, ddof=1) == pytest.approx(fit.work_of_adhesion_sd, rel=0.35)


@pytest.mark.slow
def test_the_95_interval_of_the_joint_fit_covers_the_truth_95_percent():
    rng = np.random.default_rng(2026)
    F = inv.pull_off_force(RADII, E_SILICA_SILICON, W, Z0)
    sd = 0.02 * np.abs(F)
    trials, hits_w, hits_z = 200, 0, 0
    for _ in range(trials):
        fit = inv.fit_pull_off(
            RADII, F + sd * rng.standard_normal(F.size), E_SILICA_SILICON, sd=sd, bootstrap=0
        )
        lo, hi = fit.work_of_adhesion_ci95
        hits_w += lo <= W <= hi
        lo, hi = fit.equilibrium_spacing_ci95
        hits_z += lo <= Z0 <= hi
    # binomial(200, 0.95): sd 1.5 %, so 0.90..0.99 is a 3-sigma band
    assert 0.90 <= hits_w / trials <= 0.99
    assert 0.90 <= hits_z / trials <= 0.99


@pytest.mark.slow
def test_the_monte_carlo_interval_covers_the_truth_95_percent():
    """Inputs measured with noise; the interval from their uncertainties covers the truth."""
    rng = np.random.default_rng(11)
    R_true, E, sd_R, sd_F = 50e-9, E_SILICA_SILICON, 3e-9, 0.05
    F_true = float(inv.pull_off_force(R_true, E, W, Z0))
    hits, trials = 0, 200
    for _ in range(trials):
        R_meas = R_true + sd_R * rng.standard_normal()
        F_meas = F_true + sd_F * rng.standard_normal()
        est = inv.propagate(
            inv.work_of_adhesion_from_pull_off,
            dict(pull_off_force=F_meas, radius=R_meas, modulus=E, equilibrium_spacing=Z0),
            dict(pull_off_force=sd_F, radius=sd_R),
            n_samples=400,
            seed=int(rng.integers(1 << 30)),
        )
        hits += est.ci95[0] <= W <= est.ci95[1]
    assert 0.90 <= hits / trials <= 0.99


def test_propagate_monte_carlo_and_linear_agree_for_small_uncertainties():
    F = float(inv.pull_off_force(50e-9, E_SILICA_SILICON, W, Z0))
    est = inv.propagate(
        inv.work_of_adhesion_from_pull_off,
        dict(pull_off_force=F, radius=50e-9, modulus=E_SILICA_SILICON, equilibrium_spacing=Z0),
        dict(radius=0.5e-9, modulus=0.5e9, pull_off_force=0.005 * abs(F)),
        n_samples=4000,
        seed=1,
    )
    assert est.value == pytest.approx(W, rel=1e-12)
    assert est.sd == pytest.approx(est.sd_linear, rel=0.05)
    assert est.ci95[0] < W < est.ci95[1] and est.n_failed == 0
    # seeded: the same numbers again
    again = inv.propagate(
        inv.work_of_adhesion_from_pull_off,
        dict(pull_off_force=F, radius=50e-9, modulus=E_SILICA_SILICON, equilibrium_spacing=Z0),
        dict(radius=0.5e-9, modulus=0.5e9, pull_off_force=0.005 * abs(F)),
        n_samples=4000,
        seed=1,
    )
    assert again == est


# --------------------------------------------------------------------------------------------
# bad input


def test_an_unreachable_pull_off_says_which_forces_are_reachable():
    with pytest.raises(ValueError, match=r"reachable pull-off forces are \(.*, .*\) N/m"):
        inv.work_of_adhesion_from_pull_off(0.1, 50e-9, 50e9, Z0)
    with pytest.raises(ValueError, match="reachable half-widths"):
        inv.work_of_adhesion_from_width(1e-10, 1.0, 50e-9, 50e9, Z0)


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: inv.fit_pull_off(RADII[:2], [-1.0, -2.0], 50e9), "at least 3 data points"),
        (lambda: inv.fit_pull_off(RADII, [-1.0] * 4, 50e9), "one length"),
        (lambda: inv.fit_pull_off(RADII, [-1.0] * 5, 50e9, sd=[-1] * 5), "sd"),
        (lambda: inv.fit_pull_off(RADII, [1.0] * 5, 50e9), "pull_off_force"),
        (lambda: inv.fit_pull_off(RADII, [-1.0] * 5, 50e9, bootstrap=-1), "bootstrap"),
        (
            lambda: inv.propagate(inv.pull_off_force, dict(radius=1.0), dict(radius=-1.0)),
            "uncertainty of radius",
        ),
        (lambda: inv.propagate(inv.pull_off_force, dict(radius=1.0), dict(z=1.0)), "'z'"),
        (
            lambda: inv.shear_strength_from_friction(0.1, -10.0, 50e-9, 50e9, W, Z0),
            "below the pull-off",
        ),
        (
            lambda: inv.shear_strength_from_friction(0.1, 1.0, 50e-9, 50e9, W, Z0, contact="x"),
            "contact",
        ),
        (
            lambda: inv.shear_strength_from_friction(
                1e-6, 1.0, 50e-9, 50e9, 0.1, Z0, receding_work_of_adhesion=0.2
            ),
            "hysteresis",
        ),
    ],
)
def test_bad_input_is_a_clear_error(call, message):
    with pytest.raises(ValueError, match=message):
        call()


# --------------------------------------------------------------------------------------------
# found by fuzzing (each failed on the first version)


def test_soft_materials_are_inverted_too():
    """sigma0/E far above 10 (a PDMS-like contact): the search covers the solvers' domain."""
    F = inv.pull_off_force(1e-6, 2e6, 0.04, 0.3e-9)
    assert float(inv.work_of_adhesion_from_pull_off(F, 1e-6, 2e6, 0.3e-9)) == pytest.approx(
        0.04, rel=1e-10
    )


def test_forces_and_widths_below_the_weakest_adhesion_are_refused():
    with pytest.raises(ValueError, match="reachable pull-off forces"):
        inv.work_of_adhesion_from_pull_off(-1e-12, 50e-9, 50e9, Z0)
    with pytest.raises(ValueError, match="narrowest stable contact"):
        inv.work_of_adhesion_from_width(1e-300, -1.0, 50e-9, 50e9, Z0)


def test_width_inversion_when_the_radius_is_below_the_range():
    a, F, R, E, z0 = 3.2892e-13, -1.8729e-4, 2.7273e-10, 5.4535e10, 3.7898e-9
    w = float(inv.work_of_adhesion_from_width(a, F, R, E, z0))
    assert float(
        inv._stable_width(np.array(F), np.array(R), np.array(E), np.array(w), np.array(z0))
    ) == pytest.approx(a, rel=1e-6)


def test_an_exact_fit_without_sds_is_not_called_unidentifiable():
    E, w, z0 = 19784449390.735683, 0.06063137497754147, 3.510217223842954e-10
    R = np.array([5.254e-9, 2.034e-8, 3.163e-8, 6.655e-8, 9.883e-8, 2.467e-6, 5.501e-6, 1.773e-5])
    fit = inv.fit_pull_off(R, inv.pull_off_force(R, E, w, z0), E)
    assert fit.identifiable and math.isfinite(fit.correlation)
    assert "no scatter" in fit.note


def test_the_monte_carlo_survives_failing_draws_in_a_few_calls():
    """Unreachable draws are nan in one batch (it once solved every sample alone).

    The inversion is asked to report them (``on_failure="report"``): an argument, not a
    context that :func:`propagate` sets around the call.
    """
    import functools

    calls = []

    @functools.wraps(inv.work_of_adhesion_from_pull_off)
    def counted(*args, **kwargs):
        calls.append(1)
        return inv.work_of_adhesion_from_pull_off(*args, **kwargs, on_failure="report")

    F = float(inv.pull_off_force(50e-9, 50e9, W, Z0))
    est = inv.propagate(
        counted,
        dict(pull_off_force=F, radius=50e-9, modulus=50e9, equilibrium_spacing=Z0),
        dict(pull_off_force=2 * abs(F)),
        n_samples=2000,
    )
    assert est.n_failed > 100 and math.isfinite(est.sd)
    assert len(calls) <= 4  # the value, the batch, two for the linear estimate


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: inv.fit_pull_off([2e-8] * 3, [-1.0] * 3, 50e9), "3 distinct radii"),
        (lambda: inv.fit_pull_off(RADII, [-1.0] * 5, [50e9, 50e9]), "single number"),
        (lambda: inv.fit_pull_off(RADII, [-1.0] * 5, 50e9, seed=1.5), "seed"),
        (lambda: inv.fit_pull_off(RADII, [-1.0] * 5, 50e9, sd=[1e-300] * 5), "between 1e-12"),
        (
            lambda: inv.propagate(inv.pull_off_force, dict(radius=1.0), dict(radius="1")),
            "uncertainty of radius",
        ),
        (
            lambda: inv.propagate(inv.work_of_adhesion_from_pull_off, dict(radius=1.0), {}),
            "fn does not take",
        ),
        (
            lambda: inv.shear_strength_from_friction(0.2, 1e8, 50e-9, 50e9, W, Z0),
            r"radii at radius=5e-08 m: beyond the domain of the solvers \(at most 10 radii\)",
        ),
        (
            lambda: inv.shear_strength_from_friction(
                0.2, 0.5, 50e-9, 50e9, W, Z0, receding_work_of_adhesion=1000.0
            ),
            "1000 times",
        ),
        (lambda: inv.shear_strength_from_friction(1e300, 0.5, 50e-9, 50e9, W, Z0), "finite"),
        (lambda: inv.jkr_pull_off_force(-1.0, 50e9, W), "radius"),
        (lambda: inv.dmt_pull_off_force(1e-8, -W, Z0), "work_of_adhesion"),
        (
            lambda: inv.shear_strength_from_friction(
                [0.1, 0.2], [1.0, 2.0, 3.0], 50e-9, 50e9, W, Z0
            ),
            "friction_force has shape",
        ),
        (
            lambda: lc.Cylinder.from_presets(
                5e-8, "ZnO", "Unobtainium", work_of_adhesion=W, equilibrium_spacing=Z0
            ),
            "substrate_material",
        ),
    ],
)
def test_fuzz_findings_are_clear_errors(call, message):
    """Each was an unclear error, a wrong type of error, or no error at all."""
    with pytest.raises(ValueError, match=message):
        call()


def test_one_point_without_sd_says_no_uncertainty_can_be_estimated():
    F = inv.pull_off_force(RADII[:1], E_SILICA_SILICON, W, Z0)
    fit = inv.fit_pull_off(RADII[:1], F, E_SILICA_SILICON, equilibrium_spacing=Z0)
    assert "no uncertainty can be estimated" in fit.note


def _refits_by_hand(R, F, E, sd, z0, E_sd, z_sd, seed, n):
    """The command line's former loop (cli/fit.py before issue 21): the reference numbers."""
    rng = np.random.default_rng(seed + 1)
    ws, zs = [], []
    for _ in range(n):
        Ei = E + E_sd * rng.standard_normal()
        zi = (z0 + z_sd * rng.standard_normal()) if z0 is not None else None
        if Ei <= 0 or (zi is not None and zi <= 0):
            continue
        try:
            fi = inv.fit_pull_off(R, F, Ei, sd=sd, equilibrium_spacing=zi, bootstrap=0)
        except ValueError:
            continue
        ws.append(fi.work_of_adhesion)
        zs.append(fi.equilibrium_spacing)
    return float(np.std(ws, ddof=1)), (float(np.std(zs, ddof=1)) if z0 is None else z_sd)


@pytest.mark.parametrize(
    ("z0", "E_rel", "z_sd", "seed"),
    [(None, 0.05, 0.0, 7), (Z0, 0.05, 0.1 * Z0, 0), (Z0, 0.0, 3e-11, 2)],
)
def test_the_inputs_uncertainties_propagate_by_refits(z0, E_rel, z_sd, seed):
    rng = np.random.default_rng(3)
    F = inv.pull_off_force(RADII, E_SILICA_SILICON, W, Z0)
    F = F * (1 + 0.05 * rng.standard_normal(F.size))
    sd = 0.05 * np.abs(F)
    E_sd = E_rel * E_SILICA_SILICON
    fit = inv.fit_pull_off(
        RADII,
        F,
        E_SILICA_SILICON,
        sd=sd,
        equilibrium_spacing=z0,
        bootstrap=0,
        seed=seed,
        modulus_sd=E_sd,
        equilibrium_spacing_sd=z_sd,
        samples=20,
    )
    w_in, z_in = _refits_by_hand(RADII, F, E_SILICA_SILICON, sd, z0, E_sd, z_sd, seed, 20)
    # the same draws: equal to rounding (the README's rule: no bit-for-bit comparison of two
    # code paths)
    assert fit.work_of_adhesion_sd_inputs == pytest.approx(w_in, rel=1e-12)
    assert fit.equilibrium_spacing_sd_inputs == pytest.approx(z_in, rel=1e-12)
    assert fit.work_of_adhesion_sd_total == pytest.approx(
        math.hypot(fit.work_of_adhesion_sd, w_in), rel=1e-12
    )
    assert fit.equilibrium_spacing_sd_total == pytest.approx(
        math.hypot(fit.equilibrium_spacing_sd, z_in), rel=1e-12
    )
    plain = inv.fit_pull_off(
        RADII, F, E_SILICA_SILICON, sd=sd, equilibrium_spacing=z0, bootstrap=0, seed=seed
    )
    assert plain.work_of_adhesion == fit.work_of_adhesion  # the fit itself is unchanged
    assert plain.work_of_adhesion_sd_inputs == 0 == plain.equilibrium_spacing_sd_inputs
    assert plain.work_of_adhesion_sd_total == plain.work_of_adhesion_sd


def test_the_modulus_uncertainty_scales_w_as_expected():
    # fixed z0, exact data: w from a pull-off scales with the modulus to a power between 0
    # (rigid-like, DMT) and 1/2 (JKR: F ~ (w^2 E R)^(1/3)); the inputs' sd follows
    F = inv.pull_off_force(RADII, E_SILICA_SILICON, W, Z0)
    fit = inv.fit_pull_off(
        RADII,
        F,
        E_SILICA_SILICON,
        equilibrium_spacing=Z0,
        bootstrap=0,
        modulus_sd=0.01 * E_SILICA_SILICON,
        samples=40,
    )
    assert 0.1 * 0.01 < fit.work_of_adhesion_sd_inputs / W < 0.5 * 0.01 * 1.2


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        (dict(modulus_sd=-1.0), "modulus_sd must be a finite number >= 0"),
        (dict(modulus_sd=math.nan), "modulus_sd must be a finite number >= 0"),
        (dict(equilibrium_spacing_sd="1e-11"), "equilibrium_spacing_sd must be"),
        (dict(equilibrium_spacing_sd=1e-11), "needs a fixed equilibrium_spacing"),
        (dict(modulus_sd=1e9, samples=1), "samples must be an integer in [2, 1e5]"),
        (dict(modulus_sd=1e9, samples=2.5), "samples must be an integer"),
    ],
)
def test_bad_input_uncertainties(kwargs, message):
    F = inv.pull_off_force(RADII, E_SILICA_SILICON, W, Z0)
    with pytest.raises(ValueError, match=re.escape(message)):
        inv.fit_pull_off(RADII, F, E_SILICA_SILICON, bootstrap=0, **kwargs)
