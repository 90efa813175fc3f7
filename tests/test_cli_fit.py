"""CLI fit-adhesion and fit-friction: the data reader, the records, the errors."""

import json
import re

import numpy as np
import pytest

import linecontact as lc
from linecontact import inverse as inv
from linecontact.cli import main
from linecontact.measurements import read_columns

E = float(lc.composite_modulus(72e9, 0.17, 163e9, 0.22))
MATS = ["--E1", "72e9", "--nu1", "0.17", "--E2", "163e9", "--nu2", "0.22", "--quiet"]
R = np.array([10e-9, 40e-9, 160e-9, 640e-9, 2560e-9])
W, Z0 = 0.1, 0.3e-9


def run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def record(text):
    doc = json.loads(text)
    assert set(doc) == {"linecontact", "command", "parameters", "units", "results"}
    (rec,) = doc["results"]
    return doc["parameters"], rec, doc["units"]


def write(path, header, rows, comment="# synthetic pull-off data"):
    lines = [comment, ",".join(header)] + [",".join(repr(float(v)) for v in r) for r in rows]
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.fixture
def pulloff_csv(tmp_path):
    F = inv.pull_off_force(R, E, W, Z0)
    return write(
        tmp_path / "pulloff.csv",
        ["radius_m", "pull_off_force_N_per_m", "pull_off_force_sd_N_per_m"],
        zip(R, F, 0.03 * np.abs(F), strict=True),
    )


def test_fit_adhesion_recovers_noise_free_data_and_prints_the_contract(capsys, pulloff_csv):
    code, out, err = run(capsys, "fit-adhesion", "--data", pulloff_csv, *MATS, "--json")
    assert code == 0, err
    params, rec, units = record(out)
    assert rec["work_of_adhesion"] == pytest.approx(W, rel=1e-6)
    assert rec["z0"] == pytest.approx(Z0, rel=1e-6)
    for key in ("work_of_adhesion", "z0"):
        assert rec[key + "_sd"] > 0
        lo, hi = rec[key + "_ci95"]
        assert lo < rec[key] < hi
    assert np.shape(rec["covariance"]) == (2, 2)
    assert len(rec["residuals_N_per_m"]) == len(rec["model_N_per_m"]) == 5
    assert rec["identifiable"] is True
    assert params["n_points"] == 5 and params["modulus_Pa"] == pytest.approx(E, rel=1e-15)
    assert units["work_of_adhesion"] == "J/m^2" and units["z0_ci95"] == "m"
    # what the simple models would have said, beside it
    assert abs(rec["work_of_adhesion_jkr"] / W - 1) > 0.05
    assert abs(rec["work_of_adhesion_dmt"] / W - 1) > 0.05


def test_fit_adhesion_with_a_fixed_range_and_other_units(capsys, tmp_path):
    F = inv.pull_off_force(R[:2], E, W, Z0)
    path = write(
        tmp_path / "p.csv",
        ["radius_nm", "pull_off_force_nN_per_um"],
        zip(R[:2] * 1e9, F * 1e3, strict=True),
    )
    code, out, err = run(capsys, "fit-adhesion", "--data", path, *MATS, "--z0", Z0, "--json")
    assert code == 0, err
    params, rec, _ = record(out)
    assert rec["work_of_adhesion"] == pytest.approx(W, rel=1e-9)
    assert rec["z0"] == Z0 and params["z0_fixed"] is True


def test_fit_adhesion_totals_need_the_length(capsys, tmp_path):
    F = inv.pull_off_force(R, E, W, Z0)
    path = write(
        tmp_path / "t.csv", ["radius_m", "pull_off_force_N"], zip(R, F * 5e-6, strict=True)
    )
    code, _, err = run(capsys, "fit-adhesion", "--data", path, *MATS)
    assert code == 2 and "--length" in err
    code, out, err = run(capsys, "fit-adhesion", "--data", path, *MATS, "--length", 5e-6, "--json")
    assert code == 0, err
    assert record(out)[1]["work_of_adhesion"] == pytest.approx(W, rel=1e-6)


def test_one_measurement_monte_carlo(capsys):
    F = float(inv.pull_off_force(50e-9, E, W, Z0))
    code, out, err = run(
        capsys,
        "fit-adhesion",
        "--radius",
        50e-9,
        "--radius-sd",
        3e-9,
        "--pull-off-force",
        F,
        "--pull-off-force-sd",
        "5%",
        "--z0",
        Z0,
        *MATS,
        "--json",
    )
    assert code == 0, err
    params, rec, _ = record(out)
    assert rec["work_of_adhesion"] == pytest.approx(W, rel=1e-12)
    assert rec["work_of_adhesion_sd"] == pytest.approx(rec["work_of_adhesion_sd_linear"], rel=0.1)
    assert params["pull_off_force_sd"] == pytest.approx(0.05 * abs(F))
    assert params["radius_sd"] == 3e-9


def test_fit_friction_agrees_with_the_api(capsys, tmp_path):
    cyl = lc.Cylinder.from_modulus(50e-9, E, work_of_adhesion=W, equilibrium_spacing=Z0)
    loads = np.array([0.0, 0.5, 2.0])
    tau = 3e7
    f = 2 * np.asarray(cyl.contact(load=loads).contact_half_width) * tau
    path = write(
        tmp_path / "f.csv",
        ["normal_load_N_per_m", "friction_force_N_per_m", "friction_force_sd_N_per_m"],
        zip(loads, f, 0.05 * f, strict=True),
    )
    args = [
        "fit-friction",
        "--data",
        path,
        "--radius",
        50e-9,
        "--modulus",
        E,
        "--work-of-adhesion",
        W,
        "--z0",
        Z0,
        "--json",
    ]
    code, out, err = run(capsys, *args)
    assert code == 0, err
    params, rec, _ = record(out)
    assert np.allclose(rec["tau0_per_point_Pa"], tau, rtol=1e-9)
    assert rec["tau0_Pa"] == pytest.approx(tau, rel=1e-9)
    assert len(rec["tau0_per_point_ci95_Pa"]) == 3
    assert rec["tau0_hertz_Pa"][0] is None and rec["tau0_hertz_Pa"][2] > 0  # no Hertz width at 0
    assert params["contact"] == "maugis-dugdale"


@pytest.mark.parametrize(
    ("header", "rows", "extra", "message"),
    [
        (["r_m", "pull_off_force_N_per_m"], [[1e-8, -1.0]], [], "no column for radius"),
        (
            ["radius_ft", "pull_off_force_N_per_m"],
            [[1e-8, -1.0]],
            [],
            "column 'radius_ft': the unit 'ft'",
        ),
        (
            ["radius_m", "pull_off_force_N_per_m"],
            [[1e-8, -1.0], [2e-8, "x"]],
            [],
            "row 4, column 'pull_off_force_N_per_m': 'x' is not a number",
        ),
        (
            ["radius_m", "pull_off_force_N_per_m", "pull_off_force_sd_N_per_m"],
            [[1e-8, -1.0, -0.1], [2e-8, -1.2, 0.1], [4e-8, -1.5, 0.1]],
            [],
            "row 3, column 'pull_off_force_sd_N_per_m': a standard uncertainty must be >= 0",
        ),
        (
            ["radius_m", "pull_off_force_N_per_m"],
            [[1e-8, -1.0], [2e-8, -1.2]],
            [],
            "at least 3 data points",
        ),
        (
            ["radius_m", "pull_off_force_N_per_m"],
            [[1e-8, 1.0], [2e-8, -1.2], [3e-8, -1.3]],
            [],
            "row 3: the pull-off force is 1.0 N/m: pull-off forces are tensile, negative",
        ),
    ],
)
def test_bad_data_names_the_file_row_and_column(capsys, tmp_path, header, rows, extra, message):
    path = tmp_path / "bad.csv"
    path.write_text(
        "# c\n" + ",".join(header) + "\n" + "\n".join(",".join(map(str, r)) for r in rows)
    )
    code, out, err = run(capsys, "fit-adhesion", "--data", path, *MATS, *extra)
    assert code == 2, err
    assert err.count("\n") == 1 and "error:" in err and message in err, err
    assert "Traceback" not in err


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--data", "/nonexistent/p.csv", *MATS], "cannot read it"),
        (
            ["--radius", "50e-9", "--pull-off-force", "0.5", "--z0", "3e-10", *MATS],
            "reachable pull-off forces",
        ),
        (["--radius", "50e-9", "--pull-off-force", "-1", *MATS], "--z0"),
        (
            [
                "--radius",
                "50e-9",
                "--pull-off-force",
                "-1",
                "--z0",
                "3e-10",
                "--radius-sd",
                "-1",
                *MATS,
            ],
            "--radius-sd must be finite and >= 0",
        ),
        (
            [
                "--radius",
                "50e-9",
                "--pull-off-force",
                "-1",
                "--z0",
                "3e-10",
                "--modulus",
                "5e10",
                *MATS,
            ],
            "either --modulus or the materials",
        ),
    ],
)
def test_bad_input_exit_2(capsys, argv, message):
    code, out, err = run(capsys, "fit-adhesion", *argv)
    assert code == 2
    assert err.count("\n") == 1 and message in err, err


def test_the_modulus_uncertainty_is_propagated_into_a_joint_fit(capsys, pulloff_csv):
    code, out, err = run(
        capsys,
        "fit-adhesion",
        "--data",
        pulloff_csv,
        "--modulus",
        E,
        "--modulus-sd",
        "10%",
        "--quiet",
        "--json",
    )
    assert code == 0, err
    _, rec, units = record(out)
    assert rec["work_of_adhesion_sd_inputs"] > 0
    assert rec["work_of_adhesion_sd_total"] > rec["work_of_adhesion_sd"]
    assert units["work_of_adhesion_sd_total"] == "J/m^2"
    code, _, err = run(capsys, "fit-adhesion", "--data", pulloff_csv, *MATS, "--radius-sd", "1e-9")
    assert code == 2 and "--radius-sd is for one measurement" in err


def test_friction_points_that_disagree_widen_the_combined_interval(capsys, tmp_path):
    cyl = lc.Cylinder.from_modulus(50e-9, E, work_of_adhesion=W, equilibrium_spacing=Z0)
    loads = np.array([0.0, 0.5, 2.0])
    a = np.asarray(cyl.contact(load=loads).contact_half_width)
    common = ["--radius", 50e-9, "--modulus", E, "--work-of-adhesion", W, "--z0", Z0, "--json"]
    recs = []
    for taus in ([3e7, 3e7, 3e7], [2e7, 3e7, 4.5e7]):
        f = 2 * a * np.array(taus)
        path = write(
            tmp_path / "f.csv",
            ["normal_load_N_per_m", "friction_force_N_per_m", "friction_force_sd_N_per_m"],
            zip(loads, f, 0.03 * f, strict=True),
        )
        code, out, err = run(capsys, "fit-friction", "--data", path, *common)
        assert code == 0, err
        recs.append(record(out)[1])
    agree, disagree = recs
    assert agree["birge_ratio"] < 1e-20
    assert disagree["birge_ratio"] > 10
    width = lambda r: r["tau0_ci95_Pa"][1] - r["tau0_ci95_Pa"][0]  # noqa: E731
    assert width(disagree) > 3 * width(agree)


def test_one_total_force_and_one_width(capsys):
    F = float(inv.pull_off_force(50e-9, E, W, Z0))
    base = ["fit-adhesion", "--radius", 50e-9, "--z0", Z0, *MATS, "--json"]
    code, out, err = run(capsys, *base, "--pull-off-force-total", F * 5e-6, "--length", 5e-6)
    assert code == 0, err
    assert record(out)[1]["work_of_adhesion"] == pytest.approx(W, rel=1e-9)
    code, _, err = run(capsys, *base, "--pull-off-force-total", F * 5e-6)
    assert code == 2 and "--length" in err
    cyl = lc.Cylinder.from_modulus(50e-9, E, work_of_adhesion=W, equilibrium_spacing=Z0)
    a = float(cyl.contact(load=0.5).contact_half_width)
    code, out, err = run(capsys, *base, "--half-width", a, "--load", 0.5, "--half-width-sd", "2%")
    assert code == 0, err
    rec = record(out)[1]
    assert rec["work_of_adhesion"] == pytest.approx(W, rel=1e-8)
    assert rec["work_of_adhesion_sd"] > 0


def test_presets_show_their_numbers_and_sources_in_a_fit(capsys, pulloff_csv):
    code, out, err = run(
        capsys,
        "fit-adhesion",
        "--data",
        pulloff_csv,
        "--cylinder-material",
        "SiO2",
        "--substrate-material",
        "Si",
        "--quiet",
        "--json",
    )
    assert code == 0, err
    params = record(out)[0]
    assert params["cylinder_material"] == "SiO2" and "Petersen" in params["cylinder_source"]
    assert params["E1_Pa"] == 72e9 and params["nu2"] == 0.22


def test_friction_from_a_measured_width(capsys):
    code, out, err = run(
        capsys,
        "fit-friction",
        "--friction-force",
        0.2,
        "--half-width",
        5e-9,
        "--half-width-sd",
        "10%",
        "--json",
    )
    assert code == 0, err
    rec = record(out)[1]
    assert rec["tau0_Pa"] == pytest.approx(0.2 / (2 * 5e-9), rel=1e-12)
    assert rec["tau0_sd_Pa"] == pytest.approx(rec["tau0_sd_linear_Pa"], rel=0.15)
    code, _, err = run(capsys, "fit-friction", "--half-width", 5e-9)
    assert code == 2 and "--friction-force" in err


@pytest.mark.parametrize("command", ["fit-adhesion", "fit-friction"])
def test_help_shows_percent_signs_once(capsys, command):
    with pytest.raises(SystemExit):
        main([command, "--help"])
    out = capsys.readouterr().out
    assert "%%" not in out and "N%" in out


@pytest.mark.parametrize(
    ("content", "extra", "message"),
    [
        ("\ufeffradius_m,pull_off_force_N_per_m\n1e-8,-1.6\n4e-8,-3.2\n1.6e-7,-6.0\n", [], None),
        ("radius_m,pull_off_force_N_per_m\n", [], "a header and no data rows"),
        (
            "radius_m,pull_off_force_N_per_m\n1e-8,-1.6\n2_0e-9,-3.2\n4e-8,-4\n",
            [],
            "row 3, column 'radius_m'",
        ),
        (
            "radius_m,pull_off_force_N_per_m,pull_off_force_sd_N_per_m\n1e-8,-1.6,1e-300\n"
            "4e-8,-3.2,0.1\n1.6e-7,-6.0,0.1\n",
            [],
            "row 2: the standard uncertainty",
        ),
        (
            "radius_m,pull_off_force_N_per_m\n1e-8,-1.6\n4e-8,-3.2\n1.6e-7,-6.0\n",
            ["--plot", "/nonexistent-dir/fit.png"],
            "--plot",
        ),
        (
            "radius_m,pull_off_force_N_per_m\n1e-8,-1.6\n4e-8,-3.2\n1.6e-7,-6.0\n",
            ["--seed", "-1"],
            "--seed must be",
        ),
        (
            "radius_m,pull_off_force_N_per_m\n1e-8,-1.6\n4e-8,-3.2\n1.6e-7,-6.0\n",
            ["--samples", "10000000"],
            "--samples must be",
        ),
    ],
)
def test_fuzz_findings_in_the_data_reader(capsys, tmp_path, content, extra, message):
    path = tmp_path / "d.csv"
    path.write_text(content, encoding="utf-8")
    code, out, err = run(capsys, "fit-adhesion", "--data", path, "--modulus", E, "--quiet", *extra)
    if message is None:
        assert code == 0, err
    else:
        assert code == 2 and err.count("\n") == 1 and message in err, err


def test_fuzz_findings_in_fit_friction(capsys, tmp_path):
    path = tmp_path / "f.csv"
    path.write_text("normal_load_N_per_m,friction_force_N_per_m\n0.5,0.2\n-100,0.2\n")
    common = ["--radius", 50e-9, "--modulus", 50e9, "--work-of-adhesion", W, "--z0", Z0]
    code, _, err = run(capsys, "fit-friction", "--data", path, *common)
    assert code == 2 and "row 3" in err and "below the pull-off" in err
    # a Monte Carlo draw below pull-off does not erase the interval
    code, out, err = run(
        capsys,
        "fit-friction",
        *common,
        "--load",
        -3.4,
        "--friction-force",
        0.2,
        "--friction-force-sd",
        "10%",
        "--work-of-adhesion-sd",
        "10%",
        "--quiet",
        "--json",
    )
    assert code == 0, err
    rec = record(out)[1]
    assert rec["tau0_sd_Pa"] is not None and None not in rec["tau0_ci95_Pa"]
    # a measured width with a negative hysteresis, or with model flags, is refused
    code, _, err = run(
        capsys,
        "fit-friction",
        "--half-width",
        5e-9,
        "--friction-force",
        0.2,
        "--work-of-adhesion",
        0.1,
        "--work-of-adhesion-receding",
        0.05,
    )
    assert code == 2 and "at least --work-of-adhesion" in err
    code, _, err = run(
        capsys, "fit-friction", "--half-width", 5e-9, "--friction-force", 0.2, "--modulus", -5
    )
    assert code == 2 and "not used with --half-width" in err


# --------------------------------------------------------------------------------------------
# every column used or refused: the uncertainty columns


REL = np.array([0.02, 0.2, 0.02, 0.2, 0.02])  # uneven uncertainties: the weights matter


def noisy_pulloff(path, header, sd_scale=1e3):
    """Pull-off forces with 2 % and 20 % noise, in nm and nN/um, and their sds (scaled)."""
    F = inv.pull_off_force(R, E, W, Z0)
    F = F * (1 + REL * np.random.default_rng(2026).standard_normal(R.size))
    sd = REL * np.abs(F)
    columns = {"radius_nm": R * 1e9, "pull_off_force_nN_per_um": F * 1e3}
    rows = [[columns.get(h, sd * sd_scale)[i] for h in header] for i in range(R.size)]
    return write(path, header, rows)


def fit_record(capsys, path, *extra):
    code, out, err = run(
        capsys, "fit-adhesion", "--data", path, *MATS, "--bootstrap", 0, "--json", *extra
    )
    assert code == 0, err
    return record(out)[1]


@pytest.mark.parametrize(
    ("header", "sd_scale"),
    [
        (["radius_nm", "pull_off_force_nN_per_um", "sd"], 1e3),
        (["radius_nm", "pull_off_force_nN_per_um", "sd_nN_per_um"], 1e3),
        (["radius_nm", "pull_off_force_nN_per_um", "sd_uN_per_m"], 1e6),
        (["pull_off_force_nN_per_um", "sd", "radius_nm"], 1e3),
        (["radius_nm", "pull_off_force_nN_per_um", "pull_off_force_sd"], 1e3),
        (["pull_off_force_sd_N_per_m", "radius_nm", "pull_off_force_nN_per_um"], 1.0),
    ],
)
def test_an_sd_column_weights_the_fit(capsys, tmp_path, header, sd_scale):
    ref = fit_record(
        capsys,
        noisy_pulloff(
            tmp_path / "ref.csv",
            ["radius_nm", "pull_off_force_nN_per_um", "pull_off_force_sd_nN_per_um"],
        ),
    )
    plain = fit_record(
        capsys, noisy_pulloff(tmp_path / "plain.csv", ["radius_nm", "pull_off_force_nN_per_um"])
    )
    rec = fit_record(capsys, noisy_pulloff(tmp_path / "sd.csv", header, sd_scale))
    for key in ("work_of_adhesion", "work_of_adhesion_sd", "z0", "z0_sd", "chi2"):
        assert rec[key] == pytest.approx(ref[key], rel=1e-6), key
    assert rec["work_of_adhesion_ci95"] == pytest.approx(ref["work_of_adhesion_ci95"], rel=1e-6)
    # the weights change the answer: the unweighted fit is another one
    assert abs(plain["work_of_adhesion_sd"] / rec["work_of_adhesion_sd"] - 1) > 0.5
    assert abs(plain["work_of_adhesion"] / rec["work_of_adhesion"] - 1) > 0.01


def test_an_sd_column_weights_the_friction_mean(capsys, tmp_path):
    cyl = lc.Cylinder.from_modulus(50e-9, E, work_of_adhesion=W, equilibrium_spacing=Z0)
    loads = np.array([0.0, 0.5, 2.0])
    f = 2 * np.asarray(cyl.contact(load=loads).contact_half_width) * np.array([2e7, 3e7, 4e7])
    common = ["--radius", 50e-9, "--modulus", E, "--work-of-adhesion", W, "--z0", Z0]
    rows = np.column_stack([loads, f, [0.5, 0.02, 0.02] * f])
    recs = []
    for header in (
        ["normal_load_N_per_m", "friction_force_N_per_m", "friction_force_sd_N_per_m"],
        ["normal_load_N_per_m", "friction_force_N_per_m", "sd"],
        ["normal_load_N_per_m", "friction_force_N_per_m"],
    ):
        path = write(tmp_path / "f.csv", header, rows[:, : len(header)])
        code, out, err = run(capsys, "fit-friction", "--data", path, *common, "--json")
        assert code == 0, err
        recs.append(record(out)[1])
    ref, rec, plain = recs
    for key in ("tau0_Pa", "tau0_sd_Pa", "birge_ratio"):
        assert rec[key] == pytest.approx(ref[key], rel=1e-9), key
    assert plain["birge_ratio"] is None and plain["tau0_Pa"] != pytest.approx(rec["tau0_Pa"])


def test_the_sd_column_takes_the_unit_of_its_value_column(tmp_path):
    path = tmp_path / "t.csv"
    path.write_text("radius_um,pull_off_force_nN,sd\n0.01,-8,0.5\n0.04,-12,1\n0.16,-20,2\n")
    cols, n = read_columns(
        str(path),
        {"radius": ("length", True, False), "pull_off_force": ("force", True, True)},
        2e-6,
    )
    assert n == 3 and sorted(cols) == ["_line", "pull_off_force", "pull_off_force_sd", "radius"]
    assert cols["radius"] == pytest.approx([1e-8, 4e-8, 1.6e-7], rel=1e-15)
    assert cols["pull_off_force"] == pytest.approx([-4e-3, -6e-3, -1e-2], rel=1e-15)
    assert cols["pull_off_force_sd"] == pytest.approx([2.5e-4, 5e-4, 1e-3], rel=1e-15)
    assert cols["_line"].tolist() == [2, 3, 4]


ACCEPTED_ADHESION = (
    "the accepted columns are radius_<unit>, pull_off_force_<unit> with its optional "
    "uncertainty: sd or sd_<unit> right after it, or pull_off_force_sd_<unit> anywhere "
    "(<unit>: m, nm, um for a length; N_per_m, nN_per_um, uN_per_m, N, nN for a force)"
)


@pytest.mark.parametrize(
    ("command", "header", "message"),
    [
        (
            "fit-adhesion",
            "radius_nm,pull_off_force_nN_per_um,temperature_K",
            f"column 'temperature_K' is not one the reader knows; {ACCEPTED_ADHESION}",
        ),
        (
            "fit-adhesion",
            "radius_nm,normal_load_N_per_m,pull_off_force_nN_per_um",
            "column 'normal_load_N_per_m' is not one the reader knows; the accepted columns",
        ),
        (
            "fit-adhesion",
            "radius_nm,pull_off_force_nN_per_um,",
            f"column 3 has no name; {ACCEPTED_ADHESION}",
        ),
        (
            "fit-adhesion",
            "sd,radius_nm,pull_off_force_nN_per_um",
            "column 'sd': an sd column qualifies the value column right before it, and it is "
            "the first column; an sd column may follow only pull_off_force_<unit>",
        ),
        (
            "fit-adhesion",
            "radius_nm,sd,pull_off_force_nN_per_um",
            "column 'sd': the reader does not use an uncertainty of the radius (it is taken as "
            "exact); an uncertainty column may qualify only pull_off_force_<unit>",
        ),
        (
            "fit-adhesion",
            "radius_nm,sd_nm,pull_off_force_nN_per_um",
            "column 'sd_nm': the reader does not use an uncertainty of the radius",
        ),
        (
            "fit-adhesion",
            "radius_nm,pull_off_force_nN_per_um,radius_sd_nm",
            "column 'radius_sd_nm': the reader does not use an uncertainty of the radius",
        ),
        (
            "fit-adhesion",
            "radius_nm,pull_off_force_nN_per_um,sd_nm",
            "column 'sd_nm': the unit 'nm' is one of a length; the pull off force's "
            "uncertainty takes N_per_m, nN_per_um, uN_per_m, N, nN",
        ),
        (
            "fit-adhesion",
            "radius_nm,pull_off_force_nN_per_um,pull_off_force_sd_um",
            "column 'pull_off_force_sd_um': the unit 'um' is one of a length",
        ),
        (
            "fit-adhesion",
            "radius_nm,pull_off_force_nN_per_um,sd_kg",
            "column 'sd_kg': the unit 'kg' is not one the reader knows",
        ),
        (
            "fit-adhesion",
            "radius_nm,pull_off_force_nN_per_um,sd,pull_off_force_sd_nN_per_um",
            "2 uncertainty columns for pull off force (sd, pull_off_force_sd_nN_per_um): keep one",
        ),
        (
            "fit-adhesion",
            "radius_nm,pull_off_force_nN_per_um,sd,sd_nN_per_um",
            "column 'sd_nN_per_um': an sd column qualifies the value column right before it, "
            "and 'sd' is an uncertainty",
        ),
        (
            "fit-adhesion",
            "radius_nm,pull_off_force,sd",
            "column 'pull_off_force': no unit: name it pull_off_force_<unit>",
        ),
        (
            "fit-adhesion",
            "radius_nm,sd_nN_per_um",
            "column 'sd_nN_per_um': the reader does not use an uncertainty of the radius",
        ),
        (
            "fit-friction",
            "normal_load_N_per_m,sd,friction_force_N_per_m",
            "column 'sd': the reader does not use an uncertainty of the normal load (it is "
            "taken as exact); an uncertainty column may qualify only friction_force_<unit>",
        ),
        (
            "fit-friction",
            "normal_load_N_per_m,friction_force_N_per_m,normal_load_sd_N_per_m",
            "column 'normal_load_sd_N_per_m': the reader does not use an uncertainty of the "
            "normal load",
        ),
        (
            "fit-friction",
            "normal_load_N_per_m,friction_force_N_per_m,sd,temperature_K",
            "column 'temperature_K' is not one the reader knows; the accepted columns are "
            "normal_load_<unit>, friction_force_<unit> with its optional uncertainty: sd or "
            "sd_<unit> right after it, or friction_force_sd_<unit> anywhere",
        ),
    ],
)
def test_a_column_the_reader_does_not_use_is_refused(capsys, tmp_path, command, header, message):
    path = tmp_path / "cols.csv"
    n = header.count(",") + 1
    path.write_text(header + "\n" + "\n".join(",".join(["1"] * n) for _ in range(3)) + "\n")
    friction = ["--radius", 50e-9, "--work-of-adhesion", W, "--z0", Z0]
    common = friction if command == "fit-friction" else []
    code, out, err = run(capsys, command, "--data", path, *MATS, *common)
    assert code == 2, err
    assert err.count("\n") == 1 and "error:" in err and "Traceback" not in err, err
    assert f"--data {str(path)!r}" in err and message in err, err


def test_one_measurement_uncertainties_are_refused_with_data(capsys, pulloff_csv):
    code, _, err = run(
        capsys, "fit-adhesion", "--data", pulloff_csv, *MATS, "--pull-off-force-sd", "5%"
    )
    assert code == 2 and err.count("\n") == 1
    assert "--pull-off-force-sd: for one measurement, not with --data" in err, err


# --------------------------------------------------------------------------------------------
# the uncertainty said as it is: exact, propagated or from the scatter; the intervals in tables

ONE = ["fit-adhesion", "--radius", "50e-9", "--pull-off-force", "-3.1", "--modulus", "51.7e9"]
ONE += ["--z0", "0.3e-9"]
FRICTION = ["--radius", "50e-9", "--modulus", "51.7e9", "--work-of-adhesion", "0.1"]
FRICTION += ["--z0", "0.3e-9"]


def _row(table: str) -> dict[str, str]:
    """The one record of a ``table`` output: {column: text} (an empty text: a blank)."""
    head, row = [line for line in table.splitlines() if not line.startswith("#")]
    spans = [m.span() for m in re.finditer(r"\S+(?: \S+)*", head)]  # right-aligned columns
    starts = [0, *(end for _, end in spans[:-1])]
    return {
        head[a:b].split(" [")[0]: row[start:b].strip()
        for (a, b), start in zip(spans, starts, strict=True)
    }


def test_one_pull_off_without_sds_is_exact_not_round_off(capsys):
    code, out, err = run(capsys, *ONE, "--json")
    assert code == 0, err
    _, rec, _ = record(out)
    w = rec["work_of_adhesion"]
    assert rec["work_of_adhesion_sd"] == 0.0 and rec["work_of_adhesion_ci95"] == [w, w]
    assert rec["uncertainty"] == "exact (one measurement, no uncertainty given)"
    code, out, _ = run(capsys, *ONE)
    row = _row(out)
    assert row["uncertainty"] == "exact (one measurement, no uncertainty given)"
    assert "work_of_adhesion_sd" not in row and "(Monte Carlo)" not in out


def test_one_pull_off_with_sds_shows_the_propagated_interval(capsys):
    argv = [*ONE, "--radius-sd", "3e-9", "--pull-off-force-sd", "5%"]
    code, out, err = run(capsys, *argv, "--json")
    assert code == 0, err
    _, rec, _ = record(out)
    lo, hi = rec["work_of_adhesion_ci95"]
    assert rec["work_of_adhesion_sd"] > 0.01 * rec["work_of_adhesion"] and lo < hi
    assert rec["uncertainty"] == (
        "propagated from --radius-sd, --pull-off-force-sd (Monte Carlo, 4000 samples)"
    )
    code, out, _ = run(capsys, *argv)
    row = _row(out)
    assert row["work_of_adhesion_ci95"] == f"[{lo:.6g}, {hi:.6g}]"
    assert row["uncertainty"].startswith("propagated from --radius-sd")


def test_a_joint_fit_s_table_shows_both_intervals(capsys, pulloff_csv):
    code, out, err = run(capsys, "fit-adhesion", "--data", pulloff_csv, *MATS, "--json")
    assert code == 0, err
    _, rec, _ = record(out)
    code, out, _ = run(capsys, "fit-adhesion", "--data", pulloff_csv, *MATS)
    row = _row(out)
    for key in ("work_of_adhesion_ci95", "z0_ci95"):
        lo, hi = rec[key]
        assert row[key] == f"[{lo:.6g}, {hi:.6g}]", key
    # z0 fixed: its interval [z0, z0] is not shown
    code, out, _ = run(capsys, "fit-adhesion", "--data", pulloff_csv, *MATS, "--z0", Z0)
    row = _row(out)
    assert "work_of_adhesion_ci95" in row and "z0_ci95" not in row and "z0_sd" not in row


def test_fit_friction_shows_its_interval_and_says_where_it_comes_from(capsys, tmp_path):
    base = ["fit-friction", "--load", "0.5", "--friction-force", "0.2", *FRICTION]
    code, out, _ = run(capsys, *base)
    row = _row(out)
    assert code == 0 and row["uncertainty"] == "exact (one measurement, no uncertainty given)"
    assert "tau0_sd_Pa" not in row and "tau0_ci95_Pa" not in row
    code, out, _ = run(capsys, *base, "--friction-force-sd", "10%", "--json")
    _, rec, _ = record(out)
    lo, hi = rec["tau0_ci95_Pa"]
    code, out, _ = run(capsys, *base, "--friction-force-sd", "10%")
    row = _row(out)
    assert row["tau0_ci95_Pa"] == f"[{lo:.6g}, {hi:.6g}]" and lo < rec["tau0_Pa"] < hi
    assert row["uncertainty"].startswith("propagated from --friction-force-sd")
    # a measured width, exact without sds
    code, out, _ = run(capsys, "fit-friction", "--friction-force", "0.2", "--half-width", "5e-9")
    assert code == 0 and _row(out)["uncertainty"].startswith("exact")


def test_friction_points_without_sds_give_the_scatter_not_zero(capsys, tmp_path):
    path = write(
        tmp_path / "f.csv",
        ["normal_load_N_per_m", "friction_force_N_per_m"],
        [(0.1, 0.15), (0.5, 0.21), (1.0, 0.3)],
    )
    code, out, err = run(capsys, "fit-friction", "--data", path, *FRICTION, "--json")
    assert code == 0, err
    _, rec, _ = record(out)
    taus = np.array(rec["tau0_per_point_Pa"])
    sd = np.std(taus, ddof=1) / np.sqrt(3)
    assert rec["tau0_sd_Pa"] == pytest.approx(sd, rel=1e-12)
    lo, hi = rec["tau0_ci95_Pa"]
    assert (hi - lo) / 2 == pytest.approx(4.302652729911275 * sd, rel=1e-9)  # t(0.975, 2)
    assert rec["uncertainty"] == "the scatter of the 3 points (no uncertainty given): Student's t"


def test_propagate_without_sds_is_exactly_the_value():
    x = dict(pull_off_force=-3.1, radius=50e-9, modulus=51.7e9, equilibrium_spacing=0.3e-9)
    e = inv.propagate(inv.work_of_adhesion_from_pull_off, x, dict(radius=0.0))
    assert e.sd == 0.0 and e.ci95 == (e.value, e.value) and e.sd_linear == 0.0
