"""The output layer: columns to JSON, JSON Lines, CSV and tables; atomic files. Format only."""

import csv
import io
import json
import os

import numpy as np
import pytest

import linecontact as lc
from linecontact.output import Table, render, table_from_result, unit_of, write


def small_table(**kw):
    cols = {
        "x": np.array([0.5, np.nan, -1.25e-300]),
        "n": np.array([1, 2, 3]),
        "ok": np.array([True, False, True]),
        "label": np.array(["a", 'b,"c"', "d"]),
        "why": np.array([None, "no state", None], dtype=object),
    }
    return Table(cols, {"p": 2.0, "name": "test"}, {}, ["linecontact", "t"], "title", **kw)


def test_json_is_the_object_json_would_write():
    t = small_table()
    doc = json.loads(render(t, "json"))
    assert doc == {
        "linecontact": {"version": lc.__version__},
        "command": ["linecontact", "t"],
        "parameters": {"p": 2.0, "name": "test"},
        "units": {"p": "1", "x": "1", "n": "1"},
        "results": [
            {"x": 0.5, "n": 1, "ok": True, "label": "a", "why": None},
            {"x": None, "n": 2, "ok": False, "label": 'b,"c"', "why": "no state"},
            {"x": -1.25e-300, "n": 3, "ok": True, "label": "d", "why": None},
        ],
    }
    for indent in (0, 1, 4):
        text = render(t, "json", indent=indent)
        assert text == json.dumps(doc, indent=indent) + "\n"
    assert render(t, "json") == json.dumps(doc, separators=(",", ":")) + "\n"


def test_floats_keep_full_precision():
    x = np.array([0.1 + 0.2, np.pi, 1e-310, -1.5e308])
    t = Table({"x": x})
    assert [r["x"] for r in json.loads(render(t, "json"))["results"]] == x.tolist()
    rows = [r for r in render(t, "csv").splitlines() if not r.startswith("#")][1:]
    assert [float(r) for r in rows] == x.tolist()


def test_jsonl_is_the_block_then_one_record_per_line():
    t = small_table()
    lines = render(t, "jsonl").splitlines()
    doc = json.loads(render(t, "json"))
    assert json.loads(lines[0]) == {k: v for k, v in doc.items() if k != "results"}
    assert [json.loads(s) for s in lines[1:]] == doc["results"]


def test_csv_reads_back_with_the_csv_module():
    t = small_table()
    text = render(t, "csv")
    head = [s for s in text.splitlines() if s.startswith("# ")]
    assert [s.split(":")[0] for s in head] == [
        "# linecontact",
        "# command",
        "# parameters",
        "# units",
    ]
    assert json.loads(head[2].split(": ", 1)[1]) == {"p": 2.0, "name": "test"}
    body = "\n".join(s for s in text.splitlines() if not s.startswith("#"))
    rows = list(csv.DictReader(io.StringIO(body)))
    assert rows[1] == {"x": "", "n": "2", "ok": "false", "label": 'b,"c"', "why": "no state"}
    assert rows[0]["why"] == "" and rows[2]["x"] == "-1.25e-300"


def test_table_rounds_and_shows_notes():
    t = Table(
        {"F": np.array([1.0, -1.3e-15, 2.5]), "reason": np.array([None, "why", None], object)},
        title="t",
    )
    lines = render(t, "table").splitlines()
    assert lines[0] == "# t" and lines[1].split() == ["F"]
    assert [s.strip() for s in lines[2:5]] == ["1", "0", "2.5"]
    assert lines[5] == "# point 2: why"
    # a scale of the terms makes a lone value of round-off size print as zero
    t = Table({"F": np.array([-1.3e-15])}, scales={"F": np.array([2.0])})
    assert render(t, "table").splitlines()[-1].strip() == "0"
    t = Table({"F": np.array([-1.3e-15])})
    assert render(t, "table").splitlines()[-1].strip() == "-1.3e-15"


def test_units_follow_the_names():
    assert unit_of("F_N_per_m") == "N/m" and unit_of("F_total_N") == "N"
    assert unit_of("M_total_N_m") == "N m" and unit_of("radius_m") == "m"
    assert unit_of("sigma0_Pa") == "Pa" and unit_of("work_of_adhesion_J_per_m2") == "J/m^2"
    assert unit_of("a_over_R") == unit_of("mu") == "1"
    t = Table({"a_m": np.array([1.0]), "s": np.array(["x"])}, {"E_Pa": 1.0}, {"a_m": "nm"})
    assert t.provenance()["units"] == {"E_Pa": "Pa", "a_m": "nm"}


def test_table_from_result_moves_constant_inputs():
    r = lc.normal_contact([0.01, 0.02], 100.0, [0.01, 0.02])
    t = table_from_result(r)
    assert t.parameters == {"R_over_h": 100.0, "method": "closed-form"}
    assert "sigma0_over_E" in t.columns and "R_over_h" not in t.columns
    assert t.columns["c_over_a"].tolist() == (np.asarray(r.c_over_R) / [0.01, 0.02]).tolist()
    one = table_from_result(lc.pull_off(100.0, 0.2))
    assert one.size == 1 and one.parameters == {"R_over_h": 100.0, "sigma0_over_E": 0.2}


def test_bad_format_and_columns():
    with pytest.raises(ValueError, match="format must be one of table, json, jsonl, csv"):
        render(small_table(), "xml")
    with pytest.raises(ValueError, match="indent must be an integer in \\[0, 16\\]"):
        render(small_table(), "json", indent=-1)
    with pytest.raises(ValueError, match="columns must be 1-D arrays of one length"):
        Table({"a": np.zeros(2), "b": np.zeros(3)})


def test_write_is_atomic(tmp_path, monkeypatch):
    t = small_table()
    target = tmp_path / "out.json"
    target.write_text("old")
    calls = {"n": 0}
    real = os.replace

    def failing_replace(src, dst):
        calls["n"] += 1
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", failing_replace)
    with pytest.raises(OSError):
        write(t, "json", target)
    assert calls["n"] == 1
    assert target.read_text() == "old" and sorted(p.name for p in tmp_path.iterdir()) == [
        "out.json"
    ]
    monkeypatch.setattr(os, "replace", real)
    write(t, "json", target)
    assert json.loads(target.read_text())["parameters"]["p"] == 2.0
    with pytest.raises(FileNotFoundError):
        write(t, "csv", tmp_path / "missing" / "x.csv")


def test_a_large_table_is_written_from_columns_only():
    n = 50_000
    t = Table({"a": np.linspace(0, 1, n), "ok": np.ones(n, bool), "m": np.full(n, "x")})
    doc = json.loads(render(t, "json"))
    assert len(doc["results"]) == n and doc["results"][-1] == {"a": 1.0, "ok": True, "m": "x"}
