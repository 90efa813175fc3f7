"""``lc.read`` on truncated and hostile files: a clear ValueError naming the file, or the data.

Files written by the command line, cut at any point (hypothesis draws the points), give a
:class:`ValueError` that names the file, or, where the cut falls between two lines of a CSV
or JSON Lines file, exactly the records before it; never another exception type and never a
DataFrame with a value the file did not hold. Binary garbage, an empty file, a huge header
line, a provenance that lies, JSON nested thousands deep, a non-number in a column whose
unit (or name) says it holds numbers: a ValueError naming the file (and the line and the
column where there is one). A byte-order mark and CRLF line ends read as the plain file.
"""

from __future__ import annotations

import contextlib
import io
import json
import re
import warnings
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

pd = pytest.importorskip("pandas")

from linecontact import read  # noqa: E402
from linecontact.cli import main  # noqa: E402

#: A curve (floats, a text column, booleans, integers) and a history (per-point lists).
COMMANDS = {
    "curve": ["curve", "--R-over-h", "100", "--sigma0-over-E", "0.05", "--num", "6"],
    "history": ["history", "--tau0-over-E", "0.01", "--T-over-Ea", "0.016", "-0.008", "0.004"],
}
FORMATS = ("csv", "json", "jsonl")
CUTS = settings(max_examples=40, suppress_health_check=[HealthCheck.function_scoped_fixture])


@pytest.fixture(scope="module")
def files(tmp_path_factory) -> dict[tuple[str, str], bytes]:
    """The bytes of each command's file in each format, as the command line writes them."""
    tmp = tmp_path_factory.mktemp("written")
    out = {}
    for name, argv in COMMANDS.items():
        for fmt in FORMATS:
            path = tmp / f"{name}.{fmt}"
            with contextlib.redirect_stderr(io.StringIO()), warnings.catch_warnings():
                warnings.simplefilter("ignore")
                assert main([*argv, "--quiet", "--format", fmt, "-o", str(path)]) == 0
            out[name, fmt] = path.read_bytes()
    return out


def refused(path: Path, *what: str) -> str:
    """The message of the ValueError ``read(path)`` raises: it names the file (and ``what``)."""
    with pytest.raises(ValueError) as exc:
        read(path)
    message = str(exc.value)
    assert message.startswith(f"{path}: not a linecontact"), message
    for w in what:
        assert re.search(w, message), (w, message)
    return message


def _write(tmp: Path, name: str, data: bytes | str) -> Path:
    path = tmp / name
    if isinstance(data, str):
        path.write_bytes(data.encode())
    else:
        path.write_bytes(data)
    return path


# --------------------------------------------------------------------------------------------
# truncated files


@pytest.mark.parametrize("command", sorted(COMMANDS))
@pytest.mark.parametrize("fmt", FORMATS)
@CUTS
@given(cut=st.floats(0.0, 1.0, exclude_max=True))
def test_a_file_cut_anywhere_is_refused_or_read_as_what_it_holds(
    files, tmp_path, command, fmt, cut
):
    whole = files[command, fmt]
    full = read(_write(tmp_path, f"whole.{fmt}", whole))
    k = int(cut * len(whole))
    path = _write(tmp_path, f"cut.{fmt}", whole[:k])
    try:
        df = read(path)
    except ValueError as exc:
        assert str(exc).startswith(f"{path}: not a linecontact"), exc
        return
    # read: only a cut between two lines (a JSON record is whole only with its last brace)
    # reads, and gives the records before it, exactly
    text = whole[:k].decode()
    assert text.endswith("\n") or (fmt != "csv" and whole[k : k + 1] == b"\n"), text[-80:]
    assert list(df.columns) == list(full.columns)
    pd.testing.assert_frame_equal(df, full.iloc[: len(df)], check_exact=True)


@pytest.mark.parametrize("fmt", FORMATS)
def test_a_file_cut_inside_its_last_line_is_refused(files, tmp_path, fmt):
    # the cut the property may miss: inside a number of the last record, which still parses
    whole = files["curve", fmt].decode()
    body = whole.rstrip("\n")
    cut = body[: body.rindex(".") + 2]  # 1.234... -> 1.2: a shorter number, no line end
    path = _write(tmp_path, f"cut.{fmt}", cut)
    message = refused(path)
    assert "cut short" in message or "invalid JSON" in message, message


def test_a_json_lines_file_cut_mid_line_names_the_line(files, tmp_path):
    lines = files["curve", "jsonl"].decode().splitlines(keepends=True)
    text = "".join(lines[:3]) + lines[3][: len(lines[3]) // 2]
    refused(_write(tmp_path, "cut.jsonl", text), r"line 4: invalid JSON")


# --------------------------------------------------------------------------------------------
# garbage and odd files


@settings(max_examples=60, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.binary(max_size=400), fmt=st.sampled_from(("csv", "json", "jsonl", "dat")))
def test_binary_garbage_is_a_value_error_naming_the_file(tmp_path, data, fmt):
    path = _write(tmp_path, f"garbage.{fmt}", data)
    try:
        df = read(path)
    except ValueError as exc:
        assert str(exc).startswith(f"{path}: not a linecontact"), exc
    else:  # only a file that is one: its provenance first
        assert "linecontact" in df.attrs


@settings(max_examples=60, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(text=st.text(alphabet='#{}[]",:\n\r 0123456789.-eanlinecontact_ursmt', max_size=200))
def test_text_garbage_is_a_value_error_naming_the_file(tmp_path, text):
    for fmt in ("csv", "json", "jsonl"):
        path = _write(tmp_path, f"garbage.{fmt}", text)
        try:
            read(path)
        except ValueError as exc:
            assert str(exc).startswith(f"{path}: not a linecontact"), exc


@pytest.mark.parametrize("fmt", [*FORMATS, "ndjson", "txt"])
def test_an_empty_file_is_refused(tmp_path, fmt):
    refused(_write(tmp_path, f"empty.{fmt}", b""))
    refused(_write(tmp_path, f"blank.{fmt}", b"\n\n  \n"))


def test_nul_bytes_are_refused_with_their_line(files, tmp_path):
    text = files["curve", "csv"].replace(b"\n", b"\n\x00", 3)  # a NUL starts line 2
    refused(_write(tmp_path, "nul.csv", text), r"binary data \(a NUL byte on line 2\)")


def test_a_huge_header_line_is_refused(files, tmp_path):
    head, _, rest = files["curve", "csv"].decode().partition("\nR_over_h")
    lines = files["curve", "csv"].decode().splitlines(keepends=True)
    header = next(i for i, line in enumerate(lines) if not line.startswith("#"))
    lines[header] = lines[header].rstrip("\n") + ',"' + "x" * 300_000 + '"\n'
    refused(_write(tmp_path, "wide.csv", "".join(lines)), rf"line {header + 1}: field larger")


def test_json_nested_thousands_deep_is_refused(tmp_path):
    deep = '{"linecontact": {}, "results": ' + "[" * 100_000 + "]" * 100_000 + "}"
    refused(_write(tmp_path, "deep.json", deep), "nested too deeply|invalid JSON")
    cell = '# linecontact: {}\n# units: {}\nzones\n"' + "[" * 60_000 + "]" * 60_000 + '"\n'
    refused(_write(tmp_path, "deep.csv", cell), "nested too deeply")


def test_a_byte_order_mark_and_crlf_read_as_the_plain_file(files, tmp_path):
    for (command, fmt), data in files.items():
        plain = read(_write(tmp_path, f"plain.{fmt}", data))
        for name, variant in (
            ("bom", b"\xef\xbb\xbf" + data),
            ("crlf", data.replace(b"\n", b"\r\n")),
            ("both", b"\xef\xbb\xbf" + data.replace(b"\n", b"\r\n")),
        ):
            df = read(_write(tmp_path, f"{name}.{fmt}", variant))
            pd.testing.assert_frame_equal(df, plain, check_exact=True, obj=(command, fmt, name))
            assert df.attrs == plain.attrs


# --------------------------------------------------------------------------------------------
# a provenance that lies, and values that are no numbers


def _csv_with(files, **head) -> str:
    """The curve's CSV with its provenance lines replaced by ``head`` (JSON values)."""
    lines = files["curve", "csv"].decode().splitlines(keepends=True)
    body = [line for line in lines if not line.startswith("#")]
    return "".join(f"# {k}: {json.dumps(v)}\n" for k, v in head.items()) + "".join(body)


@pytest.mark.parametrize(
    ("head", "what", "what_json"),
    [
        ({"linecontact": "0.4"}, "'linecontact' provenance is not an object", None),
        ({"linecontact": {}, "command": "curve"}, "'command' is not a list of words", None),
        ({"linecontact": {}, "parameters": [1, 2]}, "'parameters' are not an object", None),
        ({"linecontact": {}, "units": ["m"]}, "'units' are not an object of unit names", None),
        ({"linecontact": {}, "units": {"a_over_R": 1}}, "'units' are not an object", None),
        # a unit for a column of text, of flags (two provenance lines, the header: line 4 is
        # the first record): their values are no numbers
        (
            {"linecontact": {}, "units": {"branch": "1"}},
            r"line 4, column 'branch': 'non-contact' is not a number",
            r"results\[0\], column 'branch': 'non-contact' is not a number",
        ),
        (
            {"linecontact": {}, "units": {"stable": "1"}},
            r"line 4, column 'stable': 'false' is not a number",
            r"results\[0\], column 'stable': False is not a number",
        ),
    ],
)
def test_a_provenance_that_lies_is_refused(files, tmp_path, head, what, what_json):
    refused(_write(tmp_path, "lies.csv", _csv_with(files, **head)), what)
    doc = json.loads(files["curve", "json"])
    doc.update(head)
    if isinstance(head.get("units"), dict):
        doc["units"] = {**json.loads(files["curve", "json"])["units"], **head["units"]}
    refused(_write(tmp_path, "lies.json", json.dumps(doc)), what_json or what)


@pytest.mark.parametrize("fmt", FORMATS)
def test_a_non_number_in_a_numeric_column_names_the_column_and_the_line(files, tmp_path, fmt):
    text = files["curve", fmt].decode()
    if fmt == "csv":
        lines = text.splitlines(keepends=True)
        header = next(i for i, line in enumerate(lines) if not line.startswith("#"))
        names = lines[header].rstrip("\n").split(",")
        j = names.index("F_over_Eh")
        row = lines[header + 3].rstrip("\n").split(",")
        row[j] = "abc"
        lines[header + 3] = ",".join(row) + "\n"
        where = f"line {header + 4}"
        text = "".join(lines)
    elif fmt == "json":
        doc = json.loads(text)
        doc["results"][2]["F_over_Eh"] = "abc"
        text, where = json.dumps(doc), r"results\[2\]"
    else:
        lines = text.splitlines(keepends=True)
        rec = json.loads(lines[3])
        rec["F_over_Eh"] = "abc"
        lines[3] = json.dumps(rec) + "\n"
        text, where = "".join(lines), "line 4"
    path = _write(tmp_path, f"text.{fmt}", text)
    refused(path, rf"{where}, column 'F_over_Eh': 'abc' is not a number \(its unit is '1'\)")


@pytest.mark.parametrize(
    "cell", ["abc", "1_0", " 1.0", "nan", "inf", "0x10", "1e999", "true", '[1, "a"]', "{}"]
)
def test_a_numeric_column_refuses_what_the_writer_never_writes(tmp_path, cell):
    # the unit of a_m is stated by its name: numbers, as the writer writes them, or nothing
    quoted = '"' + cell.replace('"', '""') + '"'
    text = f"# linecontact: {{}}\n# units: {{}}\nstep,a_m\n1,1e-9\n2,{quoted}\n3,\n"
    refused(
        _write(tmp_path, "a.csv", text),
        r"line 5, column 'a_m': .* is not a number \(its unit is 'm'\)",
    )


@pytest.mark.parametrize("value", ["abc", True, "NaN", 1e999, 10**400, [1, "a"], {"a": 1}])
def test_a_numeric_json_value_that_is_no_number_is_refused(tmp_path, value):
    rec = json.dumps({"a_m": value}) if value != 1e999 else '{"a_m": 1e999}'
    text = '{"linecontact": {}, "units": {"a_m": "m"}, "results": [{"a_m": 1.0}, ' + rec + "]}"
    refused(_write(tmp_path, "a.json", text), r"results\[1\], column 'a_m'|invalid JSON")


def test_strict_json_and_whole_records(files, tmp_path):
    base = '{"linecontact": {}, "units": {}, "results": '
    refused(_write(tmp_path, "nan.json", base + '[{"x": NaN}]}'), "NaN is not JSON")
    refused(_write(tmp_path, "twice.json", base + '[{"x": 1, "x": 2}]}'), "'x' appears twice")
    refused(
        _write(tmp_path, "ragged.json", base + '[{"x": 1, "y": 2}, {"x": 1}]}'),
        r"results\[1\] has not the columns of the first record \('y'\)",
    )
    refused(
        _write(tmp_path, "twice.csv", "# linecontact: {}\nx,x\n1,2\n"),
        r"header \(line 2\) has the column 'x' twice",
    )
    refused(_write(tmp_path, "blank.csv", "# linecontact: {}\nx,\n1,2\n"), "empty column name")


def test_a_column_without_a_unit_is_read_as_the_writer_wrote_it(tmp_path):
    # no unit, no SI name: the writer's text (a number-like name too) or flags, not refused
    text = "# linecontact: {}\nname,flag,word\n1,true,a\n2,false,\n"
    df = read(_write(tmp_path, "own.csv", text))
    assert df["name"].tolist() == ["1", "2"] and df["flag"].dtype == bool
    assert df["word"].tolist() == ["a", None]
