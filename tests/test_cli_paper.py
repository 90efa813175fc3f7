"""The CLI of the figures and the citation: ``linecontact paper`` (options, checks, help)
and ``linecontact cite`` (text and BibTeX). Wiring only; the figures themselves are tested in
test_figures.py."""

import re
from pathlib import Path

import pytest

import linecontact.figures as figs
from linecontact._version import __version__
from linecontact.cli import main
from linecontact.cli.paper import CITATION, CLOSED_FORMS, PAPER, citation_text

ROOT = Path(__file__).resolve().parents[1]
FEW = ("fig06_zero_width", "fig08_sliding_schematic")


def run_cli(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture
def few(monkeypatch):
    """``paper`` draws only the figures FEW (the wiring is the same)."""
    pytest.importorskip("matplotlib")
    jobs = [j for j in figs._jobs() if j.stem in FEW]
    monkeypatch.setattr(figs, "_jobs", lambda: jobs)
    return [j.stem for j in jobs]


def test_cli_formats_and_size(capsys, tmp_path, few):
    code, out, err = run_cli(
        capsys, "paper", "--outdir", str(tmp_path), "--image-format", "svg,png", "--size", "12x6"
    )
    assert code == 0, err
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        f"{s}.{ext}" for s in few for ext in ("svg", "png")
    )
    assert out.startswith(f"wrote 4 files to {tmp_path}/:")
    from PIL import Image

    with Image.open(tmp_path / "fig06_zero_width.png") as im:
        assert im.size == (1800, 900)


def test_cli_as_the_command_freezes_the_objects(capsys, tmp_path, few, monkeypatch):
    """main() without argv (the console script) freezes the objects for a faster exit."""
    import gc

    monkeypatch.setattr("sys.argv", ["linecontact", "paper", "--outdir", str(tmp_path)])
    frozen = gc.get_freeze_count()
    try:
        assert main() == 0
        assert gc.get_freeze_count() > frozen
    finally:
        gc.unfreeze()
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(f"{s}.png" for s in few)
    assert capsys.readouterr().out.startswith("wrote 2 files")


@pytest.mark.parametrize(
    "argv, option",
    [
        (["--image-format", "png,jpg"], "--image-format"),
        (["--image-format", ""], "--image-format"),
        (["--image-format", "png,,svg"], "--image-format"),
        (["--size", "9.6"], "--size"),
        (["--size", "9.6x"], "--size"),
        (["--size", "axb"], "--size"),
        (["--size", "2x2"], "--size"),
        (["--size", "100x5"], "--size"),
        (["--size", "infxnan"], "--size"),
    ],
)
def test_cli_bad_option_one_error_line_exit_2(capsys, tmp_path, argv, option):
    code, out, err = run_cli(capsys, "paper", "--outdir", str(tmp_path / "out"), *argv)
    assert code == 2
    assert err.count("\n") == 1 and err.startswith("linecontact paper: error: "), err
    assert option in err and "Traceback" not in err and "internal error" not in err
    assert out == "" and not (tmp_path / "out").exists()


def test_cli_paper_help_states_units_and_defaults(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["paper", "--help"])
    assert exc.value.code == 0
    text = " ".join(capsys.readouterr().out.split())
    for piece in (
        "(default: paper-figures)",
        "any of png, svg, pdf",
        "(default: png)",
        "in inches",
        "(default: 9.6x5.4)",
        "examples: linecontact paper",
    ):
        assert piece in text, piece


# --------------------------------------------------------------------------------------------
# linecontact cite


def test_cite_text(capsys):
    code, out, err = run_cli(capsys, "cite")
    assert code == 0 and err == ""
    assert out == citation_text() + "\n" == CITATION  # CITATION stays importable
    assert f"linecontact {__version__}, software" in out
    # the paper (Sari, Adams & Muftu), written out here rather than read from PAPER
    assert (
        "Nano-scale effects in the adherence, sliding and rolling of a cylinder on a substrate"
        in out
    )
    assert "I. Sari, G. G. Adams, S. Müftü" in out
    assert PAPER["title"] in out
    assert len(CLOSED_FORMS) == 2
    for ref in CLOSED_FORMS:
        assert ref in out
    assert "doi:10.1163/156856197X00796" in out and "doi:10.1088/0022-3727/41/15/155315" in out
    # every confirmed detail of the paper is printed; the pages and DOI are said to be missing
    for key in ("booktitle", "publisher", "year", "url", "pages", "doi"):
        if PAPER[key]:
            assert str(PAPER[key]) in out, key
        else:
            assert re.search(rf"\b{key}\b[^\n]*not confirmed", out), key
    assert "TRIB2004" in out and "(2004)" in out


def test_every_file_and_section_cite_names_exists(capsys):
    code, out, _ = run_cli(capsys, "cite")
    assert code == 0
    named = re.findall(r"\b(README|[\w/.-]+\.(?:md|cff))(?:, (?:section )?([A-Z][\w ]*))?", out)
    assert {name for name, _ in named} >= {"docs/derivations.md", "docs/citing.md", "CITATION.cff"}
    for name, section in named:
        path = ROOT / ("README.md" if name == "README" else name)
        assert path.is_file(), name
        if section:
            headings = re.findall(r"^#+ (.+)$", path.read_text(encoding="utf-8"), re.M)
            assert section in headings, (name, section)


def _bib_entries(text):
    """{key: (type, {field: value})} of a BibTeX text with brace-delimited values."""
    entries = {}
    for m in re.finditer(r"@(\w+)\{([^,\s]+),\n(.*?)\n\}", text, re.S):
        fields = dict(re.findall(r"^\s+(\w+)\s*=\s*\{(.*)\},?$", m.group(3), re.M))
        entries[m.group(2)] = (m.group(1), fields)
    return entries


def test_cite_bibtex(capsys):
    code, out, err = run_cli(capsys, "cite", "--bibtex")
    assert code == 0 and err == ""
    # balanced braces, overall and per entry; nothing outside the entries
    depth = 0
    for ch in out:
        depth += {"{": 1, "}": -1}.get(ch, 0)
        assert depth >= 0
    assert depth == 0
    chunks = [c for c in out.strip().split("\n\n")]
    assert len(chunks) == 2 and all(c.startswith("@") and c.endswith("}") for c in chunks)
    entries = _bib_entries(out)
    kind, paper = entries["sari_adams_muftu"]
    assert kind == "inproceedings"  # TRIB2004; no journal version confirmed
    assert paper["author"] == r"Sari, I. and Adams, G. G. and M{\"u}ft{\"u}, S."
    assert PAPER["title"] in paper["title"]
    for key in ("booktitle", "publisher", "year", "pages", "doi"):
        assert (key in paper) == bool(PAPER[key]), key
    assert paper["url"] == PAPER["url"] and paper["note"] == "pages, doi not confirmed"
    kind, lib = entries["linecontact"]
    assert kind == "software"
    assert lib["version"] == __version__ and lib["year"] == "2026"
    assert {"author", "title"} <= set(lib)


def test_citation_cff_version_and_title():
    """CITATION.cff carries this version and the paper's title (read as text)."""
    text = (ROOT / "CITATION.cff").read_text(encoding="utf-8")
    assert text.startswith("cff-version: 1.2.0\n")
    assert re.search(rf"^version: {re.escape(__version__)}$", text, re.M)
    assert f'  title: "{PAPER["title"]}"' in text


def test_citation_cff_matches():
    """CITATION.cff (Citation File Format 1.2.0) says what ``cite`` says (read as YAML)."""
    yaml = pytest.importorskip("yaml")
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text(encoding="utf-8"))
    assert cff["cff-version"] == "1.2.0"
    assert str(cff["version"]) == __version__
    assert cff["license"] == "MIT" and cff["authors"] == [{"name": "linecontact developers"}]
    pref = cff["preferred-citation"]
    assert pref["type"] == "conference-paper" and pref["title"] == PAPER["title"]
    assert [(a["family-names"], a["given-names"]) for a in pref["authors"]] == list(
        PAPER["authors"]
    )
    for key, cff_key in (("journal", "journal"), ("year", "year"), ("doi", "doi")):
        assert pref.get(cff_key) == PAPER[key], key
    assert pref["url"] == PAPER["url"] and "TRIB2004" in pref["conference"]["name"]
    assert PAPER["booktitle"].endswith("(TRIB2004)") and pref["publisher"]["name"] == "ASME"


def test_cite_once_the_details_are_confirmed(capsys, monkeypatch):
    """Filling in the paper's details (PAPER) puts them in both outputs."""
    details = dict(journal="J. Test", year=2005, volume=18, pages="215-222", doi="10.1/x_y")
    for key, value in details.items():
        monkeypatch.setitem(PAPER, key, value)
    code, out, _ = run_cli(capsys, "cite")
    assert code == 0
    assert '", J. Test 18 (2005) 215-222, doi:10.1/x_y' in out and "not confirmed" not in out
    code, out, _ = run_cli(capsys, "cite", "--bibtex")
    kind, fields = _bib_entries(out)["sari_adams_muftu"]
    assert kind == "article" and "note" not in fields
    assert fields["journal"] == "J. Test" and fields["year"] == "2005"
    assert fields["pages"] == "215--222" and fields["doi"] == "10.1/x_y"
