"""Model-validity warnings: a named class, issued where the model or the units are doubtful."""

import warnings

import numpy as np
import pytest

import linecontact as lc
from linecontact.cli import main
from linecontact.closed_forms import A_OVER_R_SMALL_STRAIN

WIDE = "beyond the small-strain range of the half-plane theory"


@pytest.mark.parametrize(
    "call",
    [
        lambda: lc.normal_contact([0.1, 0.25], 100.0, 0.01),
        lambda: lc.normal_contact(0.25, 100.0, 0.01, method="collocation"),
        lambda: lc.contact_for_load(20.0, 100.0, 0.01),
        lambda: lc.sliding_contact(0.3, 100.0, 2.0, 0.01, method="closed-form"),
        lambda: lc.sliding_contact_for_load(20.0, 100.0, 2.0, 0.01, method="closed-form"),
        lambda: lc.sliding_initiation_coulomb(0.3, 0.25, 0.5),
        lambda: lc.steady_rolling_coulomb(0.3, 0.25, 0.5),
    ],
)
def test_wide_contacts_warn(call):
    with pytest.warns(lc.ModelValidityWarning, match=WIDE):
        call()


def test_contacts_in_range_do_not_warn():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        lc.normal_contact(np.linspace(0.01, A_OVER_R_SMALL_STRAIN, 5), 100.0, 0.01)
        lc.contact_for_load(1.0, 100.0, 0.01)
        lc.load_curve(100.0, 0.2)  # the default range stays within the small-strain range
        lc.Cylinder.from_modulus(50e-9, 100e9, work_of_adhesion=0.1, equilibrium_spacing=3e-10)


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(radius=50.0, modulus=1e11), "radius = 50 m is above 0.001 m"),
        (dict(radius=5e-12, modulus=1e11), "radius = 5e-12 m is below 1e-10 m"),
        (dict(radius=5e-8, modulus=500.0), "modulus = 500 Pa is below 1000 Pa"),
        (dict(radius=5e-8, modulus=1e14), "modulus = 1e\\+14 Pa is above 2e\\+12 Pa"),
    ],
)
def test_implausible_si_inputs_warn(kwargs, match):
    with pytest.warns(lc.ModelValidityWarning, match=match):
        lc.Cylinder.from_modulus(**kwargs, cohesive_stress=1e8, adhesion_range=0.5e-9)


def test_implausible_adhesion_warns():
    with pytest.warns(lc.ModelValidityWarning, match="work_of_adhesion = 50 J/m\\^2"):
        lc.Cylinder.from_modulus(5e-8, 1e11, work_of_adhesion=50.0, equilibrium_spacing=3e-10)
    with pytest.warns(lc.ModelValidityWarning, match="adhesion_range = 5e-08 m is above 1e-08 m"):
        lc.Cylinder.from_modulus(5e-8, 1e11, cohesive_stress=1e6, adhesion_range=5e-8)
    with (
        pytest.warns(lc.ModelValidityWarning, match="E1 = 7e\\+19 Pa is outside"),
        pytest.warns(lc.CouplingWarning),
    ):
        lc.Cylinder.from_materials(
            5e-8, 70e18, 0.2, 70e9, 0.2, cohesive_stress=1e9, adhesion_range=5e-10
        )
    # without adhesion the range only sets a length scale: no warning
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        lc.Cylinder.from_modulus(5e-3 / 10, 1e11, cohesive_stress=0.0, adhesion_range=1e-3)


def test_cli_prints_a_warning_once_and_quiet_silences_it(capsys):
    argv = [
        "normal",
        "--radius",
        "50",
        "--modulus",
        "100e9",
        "--sigma0",
        "1e9",
        "--h",
        "5e-10",
        "--load",
        "1",
        "2",
        "3",
    ]
    assert main(argv) == 0
    err = capsys.readouterr().err
    assert err.count("warning:") == 1
    assert err.startswith("linecontact normal: warning: --radius = 50 m is above 0.001 m")
    assert main([*argv, "--quiet"]) == 0  # --quiet silences model notes, never units
    assert capsys.readouterr().err == err
