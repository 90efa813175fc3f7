"""linecontact.measurements: the CSV reader of the fits, for Python users."""

import numpy as np
import pytest

import linecontact as lc
from linecontact import inverse as inv
from linecontact.cli import main
from linecontact.measurements import KINDS, read_columns, read_measurements

E = float(lc.composite_modulus(72e9, 0.17, 163e9, 0.22))


def test_a_pull_off_file_in_si_units(tmp_path):
    path = tmp_path / "p.csv"
    path.write_text(
        "\ufeff# AFM, silica on silicon\n\nradius_um,pull_off_force_nN,sd_nN\n"
        "0.01,-8,0.5\n# a comment between rows\n0.04,-12,1\n0.16,-20,2\n"
    )
    m = read_measurements(path, length=2e-6)
    assert sorted(m) == ["line", "pull_off_force", "pull_off_force_sd", "radius"]
    assert m["radius"] == pytest.approx([1e-8, 4e-8, 1.6e-7], rel=1e-15)
    assert m["pull_off_force"] == pytest.approx([-4e-3, -6e-3, -1e-2], rel=1e-15)
    assert m["pull_off_force_sd"] == pytest.approx([2.5e-4, 5e-4, 1e-3], rel=1e-15)
    assert m["line"].tolist() == [4, 6, 7]
    # the same as the lower-level reader with the kind's columns
    cols, n = read_columns(path, KINDS["pull-off"], 2e-6)
    assert n == 3
    for k in ("radius", "pull_off_force", "pull_off_force_sd"):
        assert np.array_equal(cols[k], m[k])


def test_a_friction_file_without_uncertainties(tmp_path):
    path = tmp_path / "f.csv"
    path.write_text("normal_load_N_per_m,friction_force_nN_per_um\n0,200\n0.5,300\n")
    m = read_measurements(str(path), "friction")
    assert sorted(m) == ["friction_force", "line", "normal_load"]
    assert m["normal_load"].tolist() == [0.0, 0.5]
    assert m["friction_force"] == pytest.approx([0.2, 0.3], rel=1e-15)


def test_the_file_feeds_the_fit(tmp_path):
    R = np.array([10e-9, 40e-9, 160e-9, 640e-9, 2560e-9])
    F = inv.pull_off_force(R, E, 0.1, 0.3e-9)
    path = tmp_path / "p.csv"
    rows = "\n".join(f"{float(r)!r},{float(f)!r}" for r, f in zip(R, F, strict=True))
    path.write_text("radius_m,pull_off_force_N_per_m\n" + rows + "\n")
    m = read_measurements(path)
    assert "pull_off_force_sd" not in m
    fit = inv.fit_pull_off(m["radius"], m["pull_off_force"], E, bootstrap=0)
    assert fit.work_of_adhesion == pytest.approx(0.1, rel=1e-6)


@pytest.mark.parametrize(
    ("kind", "text", "message"),
    [
        (
            "pull-off",
            "radius_nm,pull_off_force_N_per_m\n10,-1\n0,-1\n",
            "row 3: the radius is not > 0",
        ),
        (
            "pull-off",
            "radius_nm,pull_off_force_N_per_m\n10,0.5\n",
            "row 2: the pull-off force is 0.5 N/m: pull-off forces are tensile, negative",
        ),
        ("friction", "normal_load_N_per_m,friction_force_N_per_m\n0,0\n", "row 2: the friction"),
        (
            "pull-off",
            "radius_nm,pull_off_force_N_per_m,temperature_K\n10,-1,300\n",
            "column 'temperature_K' is not one the reader knows",
        ),
        (
            "pull-off",
            "radius_nm,pull_off_force_nN\n10,-1\n",
            "forces in nN are totals: give the fibre's length [m]",
        ),
    ],
)
def test_errors_name_the_file_by_default(tmp_path, kind, text, message):
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(ValueError) as info:
        read_measurements(path, kind)
    assert str(info.value).startswith(repr(str(path)))
    assert message in str(info.value)
    with pytest.raises(ValueError, match=r"^my AFM run[,:] "):
        read_measurements(path, kind, source="my AFM run")


def test_the_command_line_names_its_flags(tmp_path, capsys):
    path = tmp_path / "bad.csv"
    path.write_text("radius_nm,pull_off_force_nN\n10,-1\n20,-2\n40,-3\n")
    code = main(["fit-adhesion", "--data", str(path), "--modulus", "5e10", "--quiet"])
    err = capsys.readouterr().err
    assert code == 2
    assert f"--data {str(path)!r}, column 'pull_off_force_nN'" in err
    assert "give the fibre's --length [m]" in err


def test_bad_arguments(tmp_path):
    path = tmp_path / "p.csv"
    path.write_text("radius_nm,pull_off_force_N_per_m\n10,-1\n")
    with pytest.raises(ValueError, match="kind must be one of 'pull-off', 'friction'"):
        read_measurements(path, "width")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="length must be a finite number > 0"):
        read_measurements(path, length=-1.0)
    with pytest.raises(ValueError, match="cannot read it"):
        read_measurements(tmp_path / "missing.csv")
