"""The adhesion map of line contact (linecontact.adhesion_map, ``linecontact map``).

Each model's inversion against its forward formula; the Maugis-Dugdale mapping against
``pull_off`` and the JKR limit; the full law's interpolated widths against
``lj_contact_for_load``; the limits of the map; bad input; the command line. The
Lennard-Jones curves are kept at small ``mu`` and moderate loads (about a second each).
"""

from __future__ import annotations

import csv
import dataclasses
import io
import json
import math
from contextlib import redirect_stderr, redirect_stdout

import numpy as np
import pytest
from numpy.testing import assert_allclose

import linecontact.adhesion_map as am
from linecontact import contact_for_load, jkr_load, pull_off
from linecontact.adhesion_map import _runs
from linecontact.cli import main
from linecontact.closed_forms import lennard_jones_rigid_load, lennard_jones_rigid_pull_off
from linecontact.domain import DOMAIN
from linecontact.lennard_jones import lj_contact_for_load, maugis_parameter_of_mu, mu_of_dugdale

RNG = np.random.default_rng(11)


# --------------------------------------------------------------------------------------------
# the models: inversions against the forward formulas


def test_hertz_inverts_its_load():
    mu = 10 ** RNG.uniform(-2, 1, 50)
    xi = 10 ** RNG.uniform(-2, 1, 50)
    F = np.pi / (4 * mu) * xi**2  # Hertz line contact, F = pi E a^2/(4R), in the law's units
    assert_allclose(am.hertz_half_width(F, mu), xi, rtol=1e-14)
    assert np.all(am.hertz_half_width([-1.0, 0.0], 0.3) == 0)


def test_jkr_load_is_the_reference_in_the_law_units():
    # linecontact.jkr_load in the Dugdale groups, with w = sigma0 h and the Maugis matching
    rho, s = 1e5, 3e-3
    mu, R_over_z0 = mu_of_dugdale(rho, s)
    xi = np.array([0.05, 0.4, 2.0, 7.0])
    F_ref = jkr_load(xi / np.sqrt(R_over_z0), rho, s)  # over E h
    assert_allclose(am.jkr_load(xi, mu) * s * np.sqrt(R_over_z0), F_ref, rtol=1e-12)


@pytest.mark.parametrize("mu", [0.01, 0.3, 1.0, 10.0])
def test_jkr_inverts_its_load_on_the_stable_branch(mu):
    F_po, xi_po = am.jkr_pull_off(mu)
    xi = xi_po * np.array([1.0, 1.0 + 1e-6, 1.01, 1.5, 3.0, 10.0, 100.0])
    F = am.jkr_load(xi, mu)
    assert F[0] == pytest.approx(F_po, rel=1e-14)  # the pull-off is the minimum
    assert np.all(np.diff(F) > 0)
    assert_allclose(am.jkr_half_width(F[1:], mu), xi[1:], rtol=1e-9)
    assert am.jkr_half_width(F[0], mu) == pytest.approx(xi_po, rel=1e-6)  # a double root
    # the minimum over a fine grid is the closed form
    grid = xi_po * np.linspace(0.5, 2.0, 20001)
    assert am.jkr_load(grid, mu).min() == pytest.approx(F_po, rel=1e-8)
    assert np.isnan(am.jkr_half_width(F_po * 1.001, mu))  # below the pull-off: none


def test_rigid_inverts_the_rigid_load():
    F_po, z_po = lennard_jones_rigid_pull_off()
    zeta = np.concatenate([np.linspace(0.6, z_po, 60, endpoint=False), [0.05, 0.999, 1.0]])
    F = lennard_jones_rigid_load(zeta)
    assert_allclose(am.rigid_central_gap(F), zeta, rtol=1e-13)
    want = np.sqrt(2 * np.clip(1 - zeta, 0, None))
    assert_allclose(am.rigid_half_width(F), want, rtol=1e-12, atol=1e-6)
    assert am.rigid_half_width(F_po + 1e-9) == 0  # the rigid pull-off: no repulsive region
    assert np.isnan(am.rigid_half_width(F_po - 1e-6))


def test_md_groups_invert_the_mapping_of_the_law():
    mu = np.array([0.01, 0.5, 3.0, 10.0])
    for rho in (1e4, 1e6):
        s, root = am.md_groups(mu, rho)
        mu_back, R_over_z0 = mu_of_dugdale(rho, s)
        assert_allclose(mu_back, mu, rtol=1e-14)
        assert_allclose(np.sqrt(R_over_z0), root, rtol=1e-14)
    assert_allclose(
        maugis_parameter_of_mu(mu), pull_off(1e6, am.md_groups(mu)[0]).maugis_parameter, rtol=1e-12
    )


def _md_pull_off_native(mu: float, rho: float = am.MD_R_OVER_H) -> float:
    s, root = am.md_groups(mu, rho)
    return float(pull_off(rho, s).F_pulloff_over_Eh) / float(s * root)


def test_md_pull_off_tends_to_jkr():
    dev = [abs(_md_pull_off_native(mu) / float(am.jkr_pull_off(mu)[0]) - 1) for mu in (1, 10, 100)]
    assert dev[1] < 1e-4  # mu = 10: 3.5e-5
    assert dev[0] > dev[1] > dev[2]
    # the small-mu end: the rigid Maugis-Dugdale pull-off 2 w sqrt(2R/h) in the law's units
    rigid = -2 * math.sqrt(2 * am.MAUGIS_MATCH_SIGMA0)
    assert _md_pull_off_native(1e-6) == pytest.approx(rigid, rel=1e-3)


def test_md_widths_do_not_depend_on_R_over_h():
    mu = np.array([[0.02], [0.4], [5.0]])
    F = np.array([-1.0, 0.3, 4.0, 40.0])
    ref = am.md_half_width(F, mu)
    assert np.all(np.isfinite(ref) & (ref > 0))
    for rho in (1e4, 1e8):
        assert_allclose(am.md_half_width(F, mu, rho), ref, rtol=1e-9)
    # one point against contact_for_load directly
    s, root = am.md_groups(0.4)
    a = contact_for_load(4.0 * s * root, am.MD_R_OVER_H, s).a_over_R
    assert ref[1, 2] == pytest.approx(a * root, rel=1e-14)
    # below the Maugis-Dugdale pull-off there is no contact
    assert np.isnan(am.md_half_width(1.001 * _md_pull_off_native(0.4), 0.4))
    # the JKR limit
    big = am.md_half_width(F[1:], 1e3)
    assert_allclose(big, am.jkr_half_width(F[1:], 1e3), rtol=2e-3)


# --------------------------------------------------------------------------------------------
# the full law


@pytest.fixture(scope="module")
def branch():
    return am.full_law_branch(0.05, 4.0)


def test_branch_is_the_stable_part_of_the_curve(branch):
    c = branch.curve
    assert branch.F[0] == c.pull_off.F_pulloff and np.all(np.diff(branch.F) > 0)
    assert branch.F[-1] >= 4.0
    # no repulsive region at pull-off at this mu; it appears at the central gap z0
    assert branch.onset > 0 and branch.central_gap_over_z0[branch.onset] == 1.0
    assert np.all(branch.half_width[: branch.onset + 1] == 0)
    assert np.all(branch.half_width[branch.onset + 1 :] > 0)
    assert 0.1 < branch.y_onset < 0.2
    assert am.interpolation_error(branch) < 0.01


def test_full_law_widths_are_lj_contact_for_load(branch):
    # interpolated between the curve's states against the state solved at the load
    F = np.array([-1.8, 0.0, 3.5])
    xi = am.lj_half_width(branch, F)
    want = [lj_contact_for_load(f, 0.05).half_width for f in F]
    assert_allclose(xi, want, rtol=3e-3)  # measured: 0.03 % to 0.2 %
    # and zero between the pull-off and the onset, NaN outside the branch
    F_on = branch.F[branch.onset]
    near = np.array([branch.F_pulloff, 0.5 * (branch.F_pulloff + F_on), F_on])
    assert np.all(am.lj_half_width(branch, near) == 0)
    assert lj_contact_for_load(float(near[1]), 0.05).half_width == 0
    assert np.all(np.isnan(am.lj_half_width(branch, [branch.F_pulloff - 0.01, 1e3])))


# --------------------------------------------------------------------------------------------
# the map


MU = [0.02, 0.1]
Y = [0.2, 1.0, 3.0, 10.0]


@pytest.fixture(scope="module")
def small_map():
    return am.adhesion_map(MU, Y, workers=1)


def test_map_shapes_and_columns(small_map):
    m = small_map
    assert m.mu.shape == (2, 1) and m.y.shape == (4,) and m.shape == (2, 4)
    for name in ("F", "half_width_lj", "error_md", "half_width_jkr"):
        assert np.shape(getattr(m, name)) == (2, 4)
    assert_allclose(m.F, m.F_pulloff + np.multiply(Y, np.abs(m.F_pulloff)), rtol=1e-14)
    assert_allclose(m.maugis_parameter.ravel(), maugis_parameter_of_mu(MU), rtol=1e-14)
    assert np.all(m.F_pulloff < 0) and np.all(m.F_pulloff > -2.4661)
    cols = m.columns()
    assert all(v.shape == (8,) for v in cols.values())
    assert cols["tol"][0] == 0.05 and "agrees_rigid" in cols and "repulsive" in cols
    assert np.all(m.repulsive)  # y = 0.2 is beyond the onset at these mu
    assert np.all(m.lj_error_estimate < 1e-3) and np.all(m.interpolation_error < 0.02)
    # the errors are the widths' relative differences
    for name in am.MODELS:
        w = np.asarray(getattr(m, f"half_width_{name}"))
        assert_allclose(m.error(name), np.abs(w / m.half_width_lj - 1), rtol=1e-12)
        assert np.array_equal(m.agrees(name), m.error(name) <= 0.05)


def test_map_limits(small_map):
    m = small_map
    hertz = m.error("hertz")
    # Hertz approaches the full law as the load grows, at each mu
    assert np.all(np.diff(hertz[:, 1:], axis=1) < 0)
    assert np.all(hertz[:, -1] < 0.5 * hertz[:, 1])
    assert hertz[1, -1] < 0.15  # mu = 0.1, 10 pull-offs above pull-off: 13 %
    # the rigid cylinder holds at small mu and small loads, not at larger mu
    rigid = m.error("rigid")
    assert rigid[0, 0] < 0.05 and rigid[0, 0] < rigid[1, 0]
    assert np.all(np.diff(rigid[0]) > 0)


def test_no_repulsive_region_is_marked_not_divided_by():
    m = am.adhesion_map([0.01], [0.05, 0.5])
    assert m.half_width_lj[0, 0] == 0 and not m.repulsive[0, 0]
    for name in am.MODELS:
        assert np.isnan(m.error(name)[0, 0]) and not m.agrees(name)[0, 0]
        assert np.isfinite(m.error(name)[0, 1])
    assert 0.05 < m.y_onset[0, 0] < 0.5


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"mu": [0.1, -0.1]}, "mu"),
        ({"mu": [0.0]}, "mu"),
        ({"mu": [math.nan]}, "mu"),
        ({"mu": [math.inf]}, "mu"),
        ({"mu": [[0.1, 0.2]]}, "mu"),
        ({"mu": [2 * DOMAIN["lj_mu"][2]]}, "mu"),
        ({"y": [0.0, 1.0]}, "y"),
        ({"y": [math.nan]}, "y"),
        ({"y": [-1.0]}, "y"),
        ({"tol": 0.0}, "tol"),
        ({"tol": 1.0}, "tol"),
        ({"tol": math.nan}, "tol"),
        ({"tol": True}, "tol"),
        ({"tol": "0.1"}, "tol"),
    ],
)
def test_bad_input_names_the_parameter(kwargs, name):
    args = {"mu": [0.1], "y": [1.0], **kwargs}
    with pytest.raises(ValueError, match=rf"^{name} "):
        am.adhesion_map(args.pop("mu"), args.pop("y"), **args)


def test_the_domain_end_is_read_at_run_time(monkeypatch):
    monkeypatch.setitem(DOMAIN, "lj_mu", (0.0, True, 0.5, True))
    assert am.default_mu()[-1] == pytest.approx(0.5)
    with pytest.raises(ValueError, match=r"^mu must be in \(0, 0.5\]"):
        am.adhesion_map([0.6], [1.0])


@pytest.mark.parametrize(("end", "n", "last"), [(3.0, 11, 3.0), (math.inf, 17, 378.0)])
def test_the_default_range_is_the_maugis_parameter_capped_by_the_domain(monkeypatch, end, n, last):
    # Maugis parameters 0.01 ... 100, or to the end of the solver's domain where it is sooner
    assert maugis_parameter_of_mu(am.MU_MIN) == pytest.approx(am.MAUGIS_RANGE[0], rel=1e-12)
    assert maugis_parameter_of_mu(am.MU_MAX) == pytest.approx(am.MAUGIS_RANGE[1], rel=1e-12)
    monkeypatch.setitem(DOMAIN, "lj_mu", (0.0, True, end, True))
    mu = am.default_mu()
    assert mu.size == n and mu[0] == am.MU_MIN and mu[-1] == pytest.approx(last, rel=1e-3)
    lam = maugis_parameter_of_mu(mu)
    assert lam[0] == pytest.approx(0.01) and np.all(lam <= 100 * (1 + 1e-12))
    assert_allclose(np.diff(np.log10(lam)), np.log10(lam[-1] / lam[0]) / (n - 1), rtol=1e-9)


# --------------------------------------------------------------------------------------------
# in parallel, resumable, with progress


#: Columns that are error estimates: computed again, they agree to fewer digits.
_ESTIMATES = ("interpolation_error", "lj_error_estimate")


def test_workers_give_the_map_computed_here(small_map):
    msgs = []
    m = am.adhesion_map(MU, Y, workers=2, progress=msgs.append)
    for name, want in small_map.columns().items():
        got = m.columns()[name]
        if np.asarray(want).dtype.kind == "f":
            rtol = 1e-6 if name in _ESTIMATES else 1e-9  # other BLAS threads
            assert_allclose(got, want, rtol=rtol, atol=1e-12, err_msg=name)
        else:
            assert np.array_equal(got, want), name
    assert msgs[0].startswith("0/2 curves, ") and msgs[-1].startswith("2/2 curves, ")
    assert len(msgs) == 3 and all(msg.endswith(" s") for msg in msgs)


def _counting(monkeypatch, stop_after=None):
    """Count the curves computed (``am._map_row``); Ctrl-C after ``stop_after`` of them."""
    calls = []
    row = am._map_row

    def counted(mu, y):
        if stop_after is not None and len(calls) == stop_after:
            raise KeyboardInterrupt
        calls.append(mu)
        return row(mu, y)

    monkeypatch.setattr(am, "_map_row", counted)
    return calls


MU3 = [0.01, 0.02, 0.04]
Y3 = [0.5, 2.0]


@pytest.fixture(scope="module")
def whole_map():
    return am.adhesion_map(MU3, Y3, workers=1)


def test_a_stopped_map_goes_on_where_it_stopped(tmp_path, monkeypatch, whole_map):
    store = tmp_path / "partial"
    calls = _counting(monkeypatch, stop_after=2)
    with pytest.raises(KeyboardInterrupt):
        am.adhesion_map(MU3, Y3, workers=1, resume_dir=store)
    assert calls == MU3[:2] and len(list(store.glob("*.npz"))) == 2
    assert not list(store.glob(".*"))  # no temporary file left, whatever the moment
    monkeypatch.undo()
    calls = _counting(monkeypatch)
    msgs = []
    m = am.adhesion_map(MU3, Y3, workers=1, resume_dir=store, progress=msgs.append)
    assert calls == MU3[2:]  # only the curve not done yet
    assert msgs[0].startswith("2/3 curves (2 resumed), ") and msgs[-1].startswith("3/3 curves")
    for name, want in whole_map.columns().items():
        got = m.columns()[name]
        if np.asarray(want).dtype.kind == "f":
            # the solver iterates to a relative residual of 1e-11 from whatever it
            # factorised last: a curve computed again agrees to that, not bit for bit (and
            # the error estimates, differences of nearly equal numbers, to less)
            rtol = 1e-6 if name in _ESTIMATES else 1e-9
            assert_allclose(got, want, rtol=rtol, atol=1e-12, err_msg=name)
        else:
            assert np.array_equal(got, want), name
    assert not store.exists()  # removed when the map is done


def test_resume_reads_only_whole_entries_of_the_same_inputs(tmp_path, monkeypatch, whole_map):
    store = tmp_path / "partial"
    store.mkdir()
    y = np.unique(Y3)
    # an entry of other loads (another command), a damaged one, a temporary file
    other = am._row_key(MU3[0], np.array([0.5, 3.0]))
    _runs._write_row(am._entry(store, MU3[0], other), other, am._map_row(MU3[0], y))
    damaged = am._entry(store, MU3[1], am._row_key(MU3[1], y))
    damaged.write_bytes(b"PK\x03\x04 cut off")
    right = am._row_key(MU3[2], y)
    tmp = store / f".{am._entry(store, MU3[2], right).name}.999.tmp"
    _runs._write_row(am._entry(store, MU3[2], right), right, am._map_row(MU3[2], y))
    am._entry(store, MU3[2], right).rename(tmp)  # a write stopped before its rename
    calls = _counting(monkeypatch)
    m = am.adhesion_map(MU3, Y3, workers=1, resume_dir=store)
    assert calls == MU3  # none of them counts as done
    assert_allclose(m.half_width_lj, whole_map.half_width_lj, rtol=1e-9)
    # the other command's entry stays; this map's files (and their stale temporaries) go
    assert sorted(p.name for p in store.iterdir()) == [am._entry(store, MU3[0], other).name]


def test_a_key_names_mu_the_loads_and_the_code(monkeypatch):
    y = np.array([0.5, 2.0])
    k = am._row_key(0.01, y)
    assert k == am._row_key(0.01, y.copy())
    assert k != am._row_key(0.01 * (1 + 1e-15), y) and k != am._row_key(0.01, y[:1])
    assert len(_runs._code_digest()) == 64
    monkeypatch.setattr(_runs, "_code_digest", lambda: "0" * 64)  # another version, or a change
    assert am._row_key(0.01, y) != k


@pytest.mark.parametrize("workers", [0, -1, 1.5, True, "2"])
def test_workers_must_be_a_positive_integer(workers):
    with pytest.raises(ValueError, match=r"^workers must be an integer >= 1"):
        am.adhesion_map([0.1], [1.0], workers=workers)


def test_a_resume_dir_that_cannot_be_made_is_named(tmp_path):
    blocker = tmp_path / "a-file"
    blocker.write_text("x")
    with pytest.raises(ValueError, match=r"^resume_dir "):
        am.adhesion_map([0.1], [1.0], resume_dir=blocker / "sub")


def test_the_figure_clips_nothing_and_keys_every_model(small_map):
    pytest.importorskip("matplotlib")
    from linecontact.figures import MIN_SIZE
    from linecontact.figures import adhesion_map as map_figs
    from linecontact.figures._style import Run

    fig = map_figs.figure(small_map, Run(size=MIN_SIZE))
    box = fig.get_tightbbox(fig.canvas.get_renderer())
    w, h = fig.get_size_inches()
    assert box.x0 >= -0.02 and box.y0 >= -0.02 and box.x1 <= w + 0.02 and box.y1 <= h + 0.02
    ax = fig.axes[0]
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    # a model is keyed where it has a region on the map (tests/test_figure_quality_map.py)
    names = {"hertz": "Hertz", "rigid": "rigid cylinder", "jkr": "JKR", "md": "Maugis-Dugdale"}
    for model, name in names.items():
        assert (name in labels) == bool(np.any(small_map.agrees(model))), (name, labels)
    assert "error 5 % (tol)" in labels and "5 %" in ax.get_title()
    assert ax.get_xlim() == pytest.approx(tuple(small_map.maugis_parameter.ravel()))
    with pytest.raises(ValueError, match="at least two values of mu"):
        one = dataclasses.replace(small_map, maugis_parameter=small_map.maugis_parameter[:1])
        map_figs.figure(one, Run())


# --------------------------------------------------------------------------------------------
# the command line

CHEAP = ["--mu-min", "0.01", "--mu-max", "0.02", "--n-mu", "2", "--y-max", "2", "--n-y", "6"]


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["--tol", "1.5"], "--tol"),
        (["--tol", "nan"], "--tol"),
        (["--mu-min", "0"], "--mu-min"),
        (["--mu-max", "1e3"], "--mu-max"),
        (["--mu-min", "0.5", "--mu-max", "0.1"], "--mu-min"),
        (["--n-mu", "1"], "--n-mu"),
        (["--n-y", "1"], "--n-y"),
        (["--y-max", "0.001"], "--y-max"),
        (["--quick", "--n-mu", "5"], "--quick"),
        (["--format", "gif"], "--format"),
        (["--size", "3x2"], "--size"),
        (["--n-mu", "two"], "--n-mu"),
        (["--workers", "0"], "--workers"),
        (["--workers", "two"], "--workers"),
    ],
)
def test_cli_bad_flags_one_error_line_exit_2(capsys, tmp_path, monkeypatch, argv, flag):
    monkeypatch.setitem(DOMAIN, "lj_mu", (0.0, True, 3.0, True))  # --mu-max 1e3 beyond it
    try:
        code = main(["map", "--outdir", str(tmp_path), *argv])
    except SystemExit as exc:  # argparse's own errors (not an integer)
        code = exc.code
    assert code == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "error:" in err[0] and flag in err[0], err
    assert not any(tmp_path.iterdir())  # nothing computed, nothing written


def test_cli_outdir_that_is_a_file_fails_before_computing(capsys, tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    target = tmp_path / "a-file"
    target.write_text("x")

    def refuse(*args, **kwargs):
        raise AssertionError("computed the map before checking --outdir")

    monkeypatch.setattr(am, "adhesion_map", refuse)
    assert main(["map", "--outdir", str(target), *CHEAP]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "cannot write the map to --outdir" in err[0]


@pytest.fixture(scope="module")
def cli_run(tmp_path_factory):
    """One run of ``linecontact map --json`` on a cheap grid: (exit code, outdir, stdout)."""
    pytest.importorskip("matplotlib")
    out = tmp_path_factory.mktemp("map") / "maps"
    argv = ["map", "--outdir", str(out), "--image-format", "png,svg", "--json", "--tol", "0.1"]
    stdout, stderr = io.StringIO(), io.StringIO()
    with redirect_stdout(stdout), redirect_stderr(stderr):
        code = main([*argv, *CHEAP])
    return code, out, stdout.getvalue()


def test_cli_writes_the_figure_and_the_data(cli_run):
    code, out, _ = cli_run
    assert code == 0
    assert sorted(p.name for p in out.iterdir()) == [
        "adhesion_map.csv",
        "adhesion_map.png",
        "adhesion_map.svg",
    ]
    assert (out / "adhesion_map.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    lines = (out / "adhesion_map.csv").read_text().splitlines()
    assert lines[0].startswith("# linecontact:") and lines[1].startswith("# command:")
    rows = list(csv.DictReader(ln for ln in lines if not ln.startswith("#")))
    assert len(rows) == 12
    col = {k: np.array([r[k] for r in rows]) for k in rows[0]}
    for name in (
        "mu",
        "maugis_parameter",
        "load_above_pulloff_over_abs_pulloff",
        "F_over_w_sqrt_R_over_z0",
        "F_pulloff_over_w_sqrt_R_over_z0",
        "half_width_lj_over_sqrt_R_z0",
        "half_width_md_over_sqrt_R_z0",
        "relative_error_hertz",
        "agrees_rigid",
        "lj_repulsive",
    ):
        assert name in col, name
    mu = col["mu"].astype(float)
    F = col["F_over_w_sqrt_R_over_z0"].astype(float)
    y = col["load_above_pulloff_over_abs_pulloff"].astype(float)
    F_po = col["F_pulloff_over_w_sqrt_R_over_z0"].astype(float)
    assert_allclose(F, F_po + y * np.abs(F_po), rtol=1e-14)
    assert_allclose(y[:6], am.default_y(6, 2.0), rtol=1e-14)
    # the columns are the models' widths at the cells' loads (full precision in the file)
    for name, want in (
        ("hertz", am.hertz_half_width(F, mu)),
        ("jkr", am.jkr_half_width(F, mu)),
        ("md", am.md_half_width(F, mu)),
        ("rigid", am.rigid_half_width(F)),
    ):
        got = np.array(
            [float(v) if v else np.nan for v in col[f"half_width_{name}_over_sqrt_R_z0"]]
        )
        assert_allclose(got, want, rtol=1e-15)
    xi = col["half_width_lj_over_sqrt_R_z0"].astype(float)
    assert np.array_equal(col["lj_repulsive"] == "true", xi > 0)


def test_cli_json_is_the_provenance_and_the_cells(cli_run):
    code, out, text = cli_run
    doc = json.loads(text)
    assert doc["command"][:2] == ["linecontact", "map"]
    assert doc["parameters"]["tol"] == 0.1
    assert doc["parameters"]["files"] == [
        str(out / f"adhesion_map.{e}") for e in ("png", "svg", "csv")
    ]
    assert len(doc["results"]) == 12 and doc["units"]["relative_error_jkr"] == "1"
    assert {r["mu"] for r in doc["results"]} == {0.01, 0.02}
    ok = [r["agrees_md"] for r in doc["results"]]
    err = [r["relative_error_md"] for r in doc["results"]]
    assert ok == [e is not None and e <= 0.1 for e in err]


def test_cli_stopped_keeps_its_curves_and_the_rerun_goes_on(capsys, tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    out = tmp_path / "maps"
    argv = ["map", "--outdir", str(out), "--image-format", "svg", "--workers", "1", *CHEAP]
    calls = _counting(monkeypatch, stop_after=1)
    assert main(argv) == 130  # Ctrl-C after the first curve
    err = capsys.readouterr().err
    assert "map: 1 finished curves kept in" in err and "adhesion_map.partial" in err
    assert [p.name for p in out.iterdir()] == ["adhesion_map.partial"]
    stale = out / "adhesion_map.partial" / "mu5.000000e-01-0123456789abcdef.npz"
    stale.write_bytes(b"an entry of another grid or version")
    monkeypatch.undo()
    calls = _counting(monkeypatch)
    assert main([*argv, "--progress"]) == 0
    assert calls == [0.02]  # the second curve only
    err = capsys.readouterr().err  # the bar of the curves, from the resumed one (tqdm: 1/2)
    assert err.startswith("\rmap: ") and "2/2" in err and err.endswith("\n")
    assert sorted(p.name for p in out.iterdir()) == ["adhesion_map.csv", "adhesion_map.svg"]


def test_cli_progress_is_off_where_stderr_is_not_a_terminal(capsys, tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    monkeypatch.setattr(am, "_map_row", lambda mu, y: _fake_row(y))
    assert main(["map", "--outdir", str(tmp_path), "--image-format", "svg", *CHEAP]) == 0
    assert capsys.readouterr().err == ""


def _fake_row(y):
    y = np.asarray(y)
    return am._Row(-2.0, 0.0, np.sqrt(y), 1e-9, 1e-4, 20)


def test_cli_summary_names_the_files_and_each_models_range(
    capsys, tmp_path, monkeypatch, small_map
):
    pytest.importorskip("matplotlib")
    monkeypatch.setattr(am, "adhesion_map", lambda *args, **kwargs: small_map)
    assert main(["map", "--outdir", str(tmp_path), "--quick"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("wrote 2 files to") and "adhesion_map.csv" in out
    for name in am.MODELS:
        assert f"{name}_holds_at_y" in out
    # mu = 0.02: the rigid cylinder holds at y = 0.2 only, Hertz nowhere, JKR at y = 3
    from linecontact.operations.adhesion_map import summary as _summary

    cols = _summary(small_map).columns
    assert cols["rigid_holds_at_y"][0] == "0.2" and cols["hertz_holds_at_y"][0] == "-"
    assert cols["jkr_holds_at_y"][0] == "3"
    assert all(f" {v} " in f" {out} " for v in ("0.2", "-", "3"))
