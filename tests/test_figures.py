"""The paper figures (Figs. 2-14): files, formats, size, layout, atomic writes, no printing,
lazy import. Wiring and format only; no timings."""

import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

from PIL import Image  # noqa: E402  (a dependency of matplotlib)

import linecontact.figures as figs  # noqa: E402
from linecontact._version import __version__  # noqa: E402
from linecontact.figures import paper_figures  # noqa: E402
from linecontact.figures._style import Run  # noqa: E402

STEMS = (
    "fig02_load_R100",
    "fig03_load_R200",
    "fig04_zone_R100",
    "fig05_zone_R200",
    "fig06_zero_width",
    "fig07_sliding_initiation",
    "fig13_rolling_force",
    "fig14_rolling_creep",
    "fig08_sliding_schematic",  # steady sliding
    "fig09_zone_difference_s001",
    "fig10_zone_difference_s004",
    "fig11_moment_s001",
    "fig12_moment_s004",
)
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
TAG = f"linecontact {__version__}".encode()
# two cheap figures of two groups (so that two processes draw), one of them two-panel
FEW = ("fig06_zero_width", "fig08_sliding_schematic")


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    outdir = tmp_path_factory.mktemp("figs") / "nested" / "out"  # created by paper_figures
    messages = []
    paths = paper_figures(outdir, progress=messages.append)
    return outdir, paths, messages


@pytest.fixture
def few(monkeypatch):
    """paper_figures draws only the figures FEW (the wiring is the same)."""
    jobs = [j for j in figs._jobs() if j.stem in FEW]
    monkeypatch.setattr(figs, "_jobs", lambda: jobs)
    return [j.stem for j in jobs]


def png_size(path):
    with Image.open(path) as im:
        return im.size


def test_default_is_every_figure_as_png(written):
    outdir, paths, _ = written
    expected = [outdir / f"{s}.png" for s in STEMS]
    assert paths == expected
    assert sorted(p.name for p in outdir.iterdir()) == sorted(p.name for p in expected)


def test_png_files_are_png_with_the_version(written):
    _, paths, _ = written
    for p in paths:
        data = p.read_bytes()
        assert len(data) > 10_000
        assert data.startswith(PNG_SIGNATURE)
        assert TAG in data  # Creator metadata
        with Image.open(p) as im:
            assert im.info["Creator"] == TAG.decode()
            assert round(im.info["dpi"][0]) == 150
        assert png_size(p) == ((1440, 1080) if "fig08" in p.name else (1440, 810))


def test_progress_instead_of_printing(written, capsys):
    _, _, messages = written
    assert messages and all(isinstance(m, str) for m in messages)
    for stem in STEMS:  # also those drawn by the second process
        assert any(stem in m for m in messages), stem
    assert messages[-1].startswith("wrote 13 files")
    out = capsys.readouterr()
    assert out.out == "" and out.err == ""


def test_every_format_and_the_size(tmp_path, few):
    paths = paper_figures(tmp_path, formats=("PNG", "svg", ".pdf", "png"), size=(12, 6))
    assert paths == [tmp_path / f"{s}.{ext}" for s in few for ext in ("png", "svg", "pdf")]
    for p in paths:
        data = p.read_bytes()
        assert TAG in data, p
        if p.suffix == ".png":
            assert png_size(p) == ((1800, 1200) if "fig08" in p.name else (1800, 900))
        elif p.suffix == ".svg":
            root = ET.fromstring(data)
            assert root.tag.endswith("svg")
            assert root.get("width") == "864pt"  # 12 in
        else:
            assert data.startswith(b"%PDF-") and data.rstrip().endswith(b"%%EOF")
    assert sorted(tmp_path.iterdir()) == sorted(paths)  # no temporary files left


def test_one_process_writes_the_same_files(tmp_path, few):
    one = paper_figures(tmp_path / "one", processes=1)
    two = paper_figures(tmp_path / "two", processes=2)
    assert [p.name for p in one] == [p.name for p in two] == [f"{s}.png" for s in few]
    for a, b in zip(one, two, strict=True):
        assert a.read_bytes() == b.read_bytes()


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(formats=()), "formats"),
        (dict(formats=("png", "jpg")), "unknown format 'jpg'"),
        (dict(formats="eps"), "unknown format 'eps'"),
        (dict(size=(3, 2)), "size"),
        (dict(size=(9.6, 5.0)), "size"),
        (dict(size=(9.6, float("nan"))), "size"),
        (dict(size="9.6x5.4"), "size"),
        (dict(processes=0), "processes"),
    ],
)
def test_bad_arguments_rejected_before_anything_is_written(tmp_path, kwargs, match):
    with pytest.raises(ValueError, match=match):
        paper_figures(tmp_path / "out", **kwargs)
    assert not (tmp_path / "out").exists()


def test_a_failed_write_leaves_no_partial_file(tmp_path, few, monkeypatch):
    target = tmp_path / f"{few[0]}.png"
    target.write_bytes(b"old")

    def broken(fig, fh, tag):
        fh.write(b"partial")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(figs._style, "_write_png", broken)
    with pytest.raises(OSError, match="No space left"):
        paper_figures(tmp_path, processes=1)
    assert [p.name for p in tmp_path.iterdir()] == [target.name]
    assert target.read_bytes() == b"old"


def test_a_failure_in_the_second_process_is_raised_here(tmp_path, few, monkeypatch):
    drawn_there = figs._share(figs._jobs(), 2)[1][0].stem

    def fail_there(fig, out, stem, fmts):
        if stem == drawn_there:
            raise RuntimeError("boom in the worker")
        return [out / f"{stem}.png"]

    monkeypatch.setattr(figs, "_save", fail_there)
    with pytest.raises(RuntimeError, match="boom in the worker"):
        paper_figures(tmp_path, processes=2)


def test_fixed_layout_clips_nothing():
    """The margins (inches) leave room for every title, label and legend at the smallest
    accepted size (so at the default size too: the fonts do not change with the size)."""
    run = Run(size=figs.MIN_SIZE)
    for job in figs._jobs():
        fig = job.build(run)
        renderer = fig.canvas.get_renderer()
        box = fig.get_tightbbox(renderer)  # inches
        w, h = fig.get_size_inches()
        tol = 0.02
        assert box.x0 >= -tol and box.y0 >= -tol, (job.stem, box)
        assert box.x1 <= w + tol and box.y1 <= h + tol, (job.stem, box)


def test_import_does_not_load_matplotlib():
    code = "import sys, linecontact, linecontact.figures; assert 'matplotlib' not in sys.modules"
    subprocess.run([sys.executable, "-c", code], check=True)


def test_missing_matplotlib_message(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    with pytest.raises(ImportError, match=r"pip install 'linecontact\[plot\]'"):
        paper_figures(tmp_path)


def test_a_worker_that_dies_is_reported(tmp_path, few, monkeypatch):
    import os

    drawn_there = figs._share(figs._jobs(), 2)[1][0].stem
    real_save = figs._save

    def die_there(fig, out, stem, fmts):
        if stem == drawn_there:
            os._exit(3)
        return real_save(fig, out, stem, fmts)

    monkeypatch.setattr(figs, "_save", die_there)
    with pytest.raises(RuntimeError, match=r"stopped without a result \(exit code 3\)"):
        paper_figures(tmp_path, processes=2)
