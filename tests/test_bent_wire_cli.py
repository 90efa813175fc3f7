"""``linecontact fit-bent-wire``: the command line gives the Python API's numbers (issue 35).

A synthetic profile with a known friction (a ZnO wire dragged at its midpoint, made by the
test's own shooting solver, in nm in its CSV): the command line's JSON against
:func:`linecontact.bent_wire.fit_bent_wire` and
:func:`linecontact.inverse.shear_strength_from_bent_wire`; the contract's keys; the push of
the fitted wire (with no hysteresis its sliding resistance is the friction itself, 2 a tau0:
a round trip through the contact width); the figure; the refusals.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from linecontact import composite_modulus, read_measurements, shear_strength_from_bent_wire
from linecontact.bent_wire import bending_stiffness, fit_bent_wire
from linecontact.cli import main
from test_bent_wire_fit import L_HALF, profile

RADIUS, MODULUS = 50e-9, 140e9
EI = float(bending_stiffness(MODULUS, RADIUS))
F_TRUE = 0.012  # N/m


@pytest.fixture(scope="module")
def csv(tmp_path_factory):
    rng = np.random.default_rng(2027)
    x, y = profile(F_TRUE * L_HALF**3 / EI, 250, 2e-9, angle=-0.4, shift=(3e-6, 1e-6), rng=rng)
    path = tmp_path_factory.mktemp("bent") / "profile.csv"
    path.write_text(
        "# a ZnO wire\nx_nm,y_nm\n"
        + "".join(f"{float(a)!r},{float(b)!r}\n" for a, b in zip(x * 1e9, y * 1e9, strict=True))
    )
    read = read_measurements(path, "profile")  # the file's numbers, as the command reads them
    return path, read["x"], read["y"]


def _json(capsys, *argv):
    code = main([*argv, "--json"])
    out = capsys.readouterr()
    assert code == 0, out.err
    return json.loads(out.out)


def test_the_command_line_gives_the_apis_friction_and_its_interval(capsys, csv):
    path, x, y = csv
    doc = _json(
        capsys, "fit-bent-wire", "--data", str(path), "--radius", "50e-9", "--modulus", "140e9"
    )
    r = doc["results"][0]
    fit = fit_bent_wire(x, y, EI)
    assert r["friction_per_length_N_per_m"] == pytest.approx(fit.friction_per_length, rel=1e-9)
    assert r["friction_per_length_sd_N_per_m"] == pytest.approx(
        fit.friction_per_length_sd, rel=1e-6
    )
    assert r["friction_per_length_ci95_N_per_m"] == pytest.approx(
        fit.friction_per_length_ci95, rel=1e-9
    )
    assert r["friction_per_length_bootstrap_ci95_N_per_m"] == pytest.approx(
        fit.friction_per_length_bootstrap_ci95, rel=1e-6
    )
    lo, hi = r["friction_per_length_ci95_N_per_m"]
    assert lo < F_TRUE < hi
    assert r["determined"] is True and r["tau0_Pa"] is None and "tau0 needs" in r["note"]
    assert doc["units"]["friction_per_length_N_per_m"] == "N/m"
    assert doc["parameters"]["bending_stiffness_N_m2"] == pytest.approx(EI, rel=1e-12)
    assert len(r["curve_x_m"]) == 401 and len(r["residuals_m"]) == 250


def test_tau0_and_a_push_with_the_apis_numbers(capsys, csv):
    path, x, y = csv
    doc = _json(
        capsys, "fit-bent-wire", "--data", str(path), "--radius", "50e-9", "--modulus", "140e9",
        "--work-of-adhesion", "0.2", "--z0", "0.3e-9", "--nu1", "0.36", "--substrate-material",
        "SiO2", "--radius-sd", "2%", "--push-height", "30e-9", "--bootstrap", "0",
    )  # fmt: skip
    r = doc["results"][0]
    E_c = composite_modulus(MODULUS, 0.36, 72e9, 0.17)
    assert doc["parameters"]["contact_modulus_Pa"] == pytest.approx(E_c, rel=1e-12)
    fit = fit_bent_wire(x, y, EI, bending_stiffness_sd=4 * 0.02 * EI, bootstrap=0)
    tau = shear_strength_from_bent_wire(
        fit, RADIUS, MODULUS, E_c, 0.2, 0.3e-9, radius_sd=0.02 * RADIUS
    )
    assert r["tau0_Pa"] == pytest.approx(tau.value, rel=1e-9)
    assert r["tau0_ci95_Pa"] == pytest.approx(tau.ci95, rel=1e-6)
    # with the radius's 2 % in EI (~R^4) and in a: f's sd about 8 %, tau0's less (partly
    # cancelling: a grows with R)
    assert r["friction_per_length_sd_N_per_m"] / r["friction_per_length_N_per_m"] == pytest.approx(
        0.08, rel=0.05
    )
    assert r["tau0_sd_Pa"] / r["tau0_Pa"] < 0.08
    # no hysteresis: the wire rolls at any push, and slides at 2 a tau0 = f
    assert r["push_first_motion"] == "roll"
    assert r["push_sliding_resistance_N_per_m"] == pytest.approx(
        r["friction_per_length_N_per_m"], rel=1e-9
    )
    a = r["contact_half_width_m"]
    assert 2 * a * r["tau0_Pa"] == pytest.approx(r["friction_per_length_N_per_m"], rel=1e-12)


def test_a_push_with_hysteresis_can_slide_first(capsys, csv):
    path, _, _ = csv
    doc = _json(
        capsys, "fit-bent-wire", "--data", str(path), "--radius", "50e-9", "--modulus", "140e9",
        "--work-of-adhesion", "0.2", "--z0", "0.3e-9", "--contact-modulus", "5e10",
        "--push-height", "30e-9", "--work-of-adhesion-receding", "0.25", "--bootstrap", "0",
    )  # fmt: skip
    r = doc["results"][0]
    # rolling: R dw/H; sliding: 2 a_slide tau0 + dw; first the lesser
    assert r["push_rolling_resistance_N_per_m"] == pytest.approx(50e-9 * 0.05 / 30e-9, rel=1e-9)
    assert r["push_first_motion"] == (
        "slide"
        if r["push_sliding_resistance_N_per_m"] < r["push_rolling_resistance_N_per_m"]
        else "roll"
    )


def test_the_held_model_and_the_figure(capsys, csv, tmp_path):
    path, x, y = csv
    png = tmp_path / "fit.png"
    doc = _json(
        capsys, "fit-bent-wire", "--data", str(path), "--radius", "50e-9", "--modulus", "140e9",
        "--model", "held", "--bootstrap", "0", "--plot", str(png),
    )  # fmt: skip
    r = doc["results"][0]
    fit = fit_bent_wire(x, y, EI, model="held", bootstrap=0)
    assert r["friction_per_length_N_per_m"] == pytest.approx(fit.friction_per_length, rel=1e-9)
    assert r["modes"] == fit.modes and len(r["normal_friction_N_per_m"]) == 401
    assert r["drag_angle"] is None
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize(
    ("extra", "flag"),
    [
        (["--modulus", "140e9", "--push-height", "3e-8"], "--push-height"),
        (["--modulus", "140e9", "--work-of-adhesion", "0.2"], "--work-of-adhesion"),
        (["--modulus", "140e9", "--bootstrap", "-1"], "--bootstrap"),
        (["--modulus", "140e9", "--noise", "-1e-9"], "--noise"),
        (["--modulus", "1.4e20"], "--modulus"),
        ([], "--modulus"),
    ],
)
def test_bad_input_names_its_flag(capsys, csv, extra, flag):
    path, _, _ = csv
    code = main(["fit-bent-wire", "--data", str(path), "--radius", "50e-9", *extra])
    err = capsys.readouterr().err
    assert code == 2
    assert err.count("\n") == 1 and "error:" in err and flag in err, err
