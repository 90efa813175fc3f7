"""Smoke tests of the paper figures (Figs. 2-7, 13, 14): files, formats, no printing, lazy
import."""

import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

from linecontact.figures import paper_figures  # noqa: E402

STEMS = (
    "fig02_load_R100",
    "fig03_load_R200",
    "fig04_zone_R100",
    "fig05_zone_R200",
    "fig06_zero_width",
    "fig07_sliding_initiation",
    "fig13_rolling_force",
    "fig14_rolling_creep",
)
STEMS += (
    "fig08_sliding_schematic",
    "fig09_zone_difference_s001",  # steady sliding
    "fig10_zone_difference_s004",
    "fig11_moment_s001",
    "fig12_moment_s004",
)
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    outdir = tmp_path_factory.mktemp("figs") / "nested" / "out"  # created by paper_figures
    messages = []
    paths = paper_figures(outdir, progress=messages.append)
    return outdir, paths, messages


def test_writes_every_figure_in_every_format(written):
    outdir, paths, _ = written
    expected = [outdir / f"{s}.{ext}" for s in STEMS for ext in ("png", "svg")]
    assert paths == expected
    assert sorted(p.name for p in outdir.iterdir()) == sorted(p.name for p in expected)


def test_png_files_are_png(written):
    _, paths, _ = written
    for p in paths:
        if p.suffix == ".png":
            data = p.read_bytes()
            assert len(data) > 10_000
            assert data.startswith(PNG_SIGNATURE)
            assert b"linecontact" in data  # Creator metadata


def test_svg_files_parse(written):
    _, paths, _ = written
    for p in paths:
        if p.suffix == ".svg":
            root = ET.parse(p).getroot()
            assert root.tag.endswith("svg")
            assert "linecontact" in p.read_text()


def test_progress_instead_of_printing(written, capsys):
    _, _, messages = written
    assert messages and all(isinstance(m, str) for m in messages)
    assert any("fig06_zero_width" in m for m in messages)
    out = capsys.readouterr()
    assert out.out == "" and out.err == ""


def test_empty_formats_rejected(tmp_path):
    with pytest.raises(ValueError, match="formats"):
        paper_figures(tmp_path, formats=())


def test_missing_matplotlib_message(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    with pytest.raises(ImportError, match=r"pip install 'linecontact\[plot\]'"):
        paper_figures(tmp_path)


def test_import_does_not_load_matplotlib():
    code = "import sys, linecontact, linecontact.figures; assert 'matplotlib' not in sys.modules"
    subprocess.run([sys.executable, "-c", code], check=True)
