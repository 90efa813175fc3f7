"""linecontact.reading.read: the CLI's CSV / JSON / JSON Lines files back as DataFrames."""

import json
import math
import sys
from pathlib import Path

import numpy as np
import pytest

pd = pytest.importorskip("pandas")

from linecontact.cli import main  # noqa: E402
from linecontact.reading import read  # noqa: E402

COMMANDS = {
    "pulloff": ["pulloff", "--R-over-h", "100", "--sigma0-over-E", "0.01"],
    # the load -10 is below pull-off: a point without a state, nulls in its record
    "normal": ["normal", "--R-over-h", "100", "--sigma0-over-E", "0.2", "--F-over-Eh", "-10"]
    + ["-1", "0", "1"],
    "pulloff-si": ["pulloff", "--radius", "50e-9", "--modulus", "1.2e11"]
    + ["--work-of-adhesion", "0.3", "--z0", "3e-10"],
    "curve": ["curve", "--R-over-h", "100", "--sigma0-over-E", "0.05"],
    "push": ["push", "--R-over-h2", "100", "--h1-over-h2", "2", "--sigma0-over-E", "0.04"]
    + ["--tau0-over-E", "0.01", "--H-over-R", "0.5", "1"],
    "slide": ["slide", "--R-over-h2", "100", "--h1-over-h2", "2", "--sigma0-over-E", "0.04"]
    + ["--F-over-Eh2", "0", "1"],
    # per-point lists (the zones): a JSON array in JSON, its quoted JSON text in CSV
    "history": ["history", "--tau0-over-E", "0.01", "--T-over-Ea", "0.016", "-0.008", "0.004"],
}
FORMATS = ("csv", "json", "jsonl")


def _write(tmp_path: Path, args: list[str], fmt: str, *extra: str) -> Path:
    path = tmp_path / f"x.{fmt}"
    assert main([*args, "--quiet", "--format", fmt, "-o", str(path), *extra]) == 0
    return path


def _same(value, expected) -> bool:
    if expected is None:
        return value is None or (isinstance(value, float) and math.isnan(value))
    if isinstance(expected, bool):
        return isinstance(value, (bool, np.bool_)) and bool(value) == expected
    return value == expected  # floats exactly: the files hold the shortest round-trip repr


@pytest.fixture(scope="module", params=sorted(COMMANDS))
def written(request, tmp_path_factory):
    tmp = tmp_path_factory.mktemp(request.param)
    args = COMMANDS[request.param]
    return request.param, {fmt: _write(tmp, args, fmt) for fmt in FORMATS}


@pytest.mark.filterwarnings("ignore")
def test_round_trip(written):
    name, paths = written
    doc = json.loads(paths["json"].read_text())
    records = doc["results"]
    keys = list(records[0])
    frames = {fmt: read(p) for fmt, p in paths.items()}
    for fmt, df in frames.items():
        assert list(df.columns) == keys, fmt
        assert len(df) == len(records), fmt
        for k in keys:
            for i, rec in enumerate(records):
                assert _same(df[k].iloc[i], rec[k]), (name, fmt, k, i, df[k].iloc[i], rec[k])
        assert set(df.attrs) == {"linecontact", "command", "parameters", "units"}
        assert df.attrs["linecontact"] == doc["linecontact"]
        assert df.attrs["parameters"] == doc["parameters"]
        assert df.attrs["units"] == doc["units"]
        assert df.attrs["command"][:-3] == doc["command"][:-3]  # all but "--format FMT -o"
        assert df.attrs["command"][-4:-2] == ["--format", fmt]
        pd.testing.assert_frame_equal(df, frames["json"], check_exact=True)


@pytest.mark.filterwarnings("ignore")
def test_nulls_and_dtypes(tmp_path):
    df = read(_write(tmp_path, COMMANDS["normal"], "csv"))
    assert math.isnan(df["a_over_R"].iloc[0]) and df["a_over_R"].dtype == float
    assert df["reason"].iloc[1] is None and df["reason"].iloc[0].startswith("no contact")
    assert df["n_collocation"].dtype == "int64" and df["converged"].dtype == bool
    hist = read(_write(tmp_path, COMMANDS["history"], "csv"))
    assert hist["zones"].iloc[0] == [[0.0, 0.6, "stick"], [0.6, 1.0, "slip+"]]


@pytest.mark.filterwarnings("ignore")
def test_indent_str_path_ndjson_and_format_keyword(tmp_path):
    args = COMMANDS["pulloff-si"]
    ref = read(_write(tmp_path, args, "json"))
    indented = read(str(_write(tmp_path, args, "json", "--indent", "2")))
    pd.testing.assert_frame_equal(indented, ref, check_exact=True)
    nd = tmp_path / "x.ndjson"
    nd.write_bytes(_write(tmp_path, args, "jsonl").read_bytes())
    pd.testing.assert_frame_equal(read(nd), ref, check_exact=True)
    for fmt in FORMATS:
        plain = tmp_path / f"{fmt}.out"
        plain.write_bytes(_write(tmp_path, args, fmt).read_bytes())
        pd.testing.assert_frame_equal(read(plain, format=fmt), ref, check_exact=True)
        pd.testing.assert_frame_equal(read(plain), ref, check_exact=True)  # by content
    assert ref.attrs["units"]["F_pulloff_N_per_m"] == "N/m"
    assert ref.attrs["parameters"]["radius_m"] == 5e-8


def test_plain_csv_without_provenance_is_refused(tmp_path):
    path = tmp_path / "plain.csv"
    pd.DataFrame({"a": [1.0, 2.0]}).to_csv(path, index=False)
    with pytest.raises(ValueError, match=r"plain\.csv.*not a linecontact CSV file.*provenance"):
        read(path)


def test_bad_comment_line_is_refused(tmp_path):
    path = tmp_path / "table.csv"
    path.write_text("# pull-off of a cylinder\nF\n1\n")
    with pytest.raises(ValueError, match=r"table\.csv.*not a linecontact CSV file.*line 1"):
        read(path)
    path.write_text('# linecontact: {"version": "0"}\na,b\n1.0\n')
    with pytest.raises(ValueError, match=r"table\.csv.*row 1 has 1 fields, the header 2"):
        read(path)


@pytest.mark.parametrize(
    ("text", "what"),
    [
        ('{"linecontact": {"version": "0"}, "units": {}}', "no 'results' list"),
        ('{"linecontact": {"version": "0"}, "results": 3}', "no 'results' list"),
        ('{"results": []}', "no 'linecontact' provenance"),
        ('{"linecontact": {}, "results": [1]}', r"results\[0\] is not a JSON object"),
        ('{"linecontact": ', "invalid JSON"),
        ("[]", "no 'linecontact' provenance"),
    ],
)
def test_bad_json_is_refused(tmp_path, text, what):
    path = tmp_path / "bad.json"
    path.write_text(text)
    with pytest.raises(ValueError, match=rf"bad\.json: not a linecontact JSON file: {what}"):
        read(path)


def test_bad_jsonl_is_refused(tmp_path):
    path = tmp_path / "bad.jsonl"
    path.write_text('{"linecontact": {}}\n{"a": 1}\n{"a": \n')
    with pytest.raises(ValueError, match=r"bad\.jsonl: .*JSON Lines file: line 3"):
        read(path)
    path.write_text("")
    with pytest.raises(ValueError, match="no 'linecontact' provenance"):
        read(path)


def test_other_refusals(tmp_path):
    with pytest.raises(FileNotFoundError):
        read(tmp_path / "missing.csv")
    text = tmp_path / "x.txt"
    text.write_text("hello\n")
    with pytest.raises(ValueError, match=r"x\.txt: not a linecontact file"):
        read(text)
    with pytest.raises(ValueError, match="format must be one of"):
        read(text, format="table")
    binary = tmp_path / "x.json"
    binary.write_bytes(b"\xff\xfe\x00")
    with pytest.raises(ValueError, match=r"x\.json: not a linecontact file: not UTF-8"):
        read(binary)


def test_empty_results(tmp_path):
    path = tmp_path / "e.json"
    path.write_text('{"linecontact": {"version": "0"}, "command": [], "results": []}')
    df = read(path)
    assert df.empty and df.attrs["command"] == []


def test_without_pandas(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(ImportError, match=r"pip install 'linecontact\[sweep\]'"):
        read(tmp_path / "x.csv")
