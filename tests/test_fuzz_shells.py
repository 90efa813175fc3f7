"""Fuzz the shells around the solvers (issue 30): the HTTP API, resumed sweeps, ``lc.read``.

``tests/test_fuzz.py`` fuzzes the functions and the command line's argument lists; this file
fuzzes what wraps them, each draw with its oracle:

- **HTTP** (an in-process ASGI client, and a real ``linecontact serve`` on 127.0.0.1 for a
  concurrent burst and raw, malformed requests): random query keys and values (the commands'
  own parameters, from the OpenAPI document, mixed with junk: unknown and repeated keys,
  empty values, huge numbers, nan and inf, unicode, bad percent-encoding, long values, values
  that look like flags or paths), random methods, content types, bodies (JSON of random
  shapes, forms, multipart with odd parts, invalid UTF-8) and paths; jobs. The oracle: a
  status of the documented set; a 500 only where a solver missed its tolerance or a worker
  died, said so; every error of ``/api/`` the JSON ``{"error": {"parameter", "message"}}``;
  every response with the security headers; a 200 the provenance object; no response naming
  a path of the server (its temporary directory, the package) or showing a traceback.
- **Sweeps** stopped and resumed: random subsets of the blocks kept (by the internal API, as
  ``tests/test_sweep_abuse.py`` does, or a run stopped by an exception after some blocks),
  stray files in ``OUT.partial/``, then ``lc.sweep(..., output=OUT)``: the dataset equals an
  uninterrupted run (numbers to 1e-12, text equal) and ``OUT.partial/`` is gone. A damaged
  block is computed again or refused with a ValueError naming it, never another exception
  or other numbers. Random ``linecontact sweep`` argument lists: exit status 0 or 2, one
  ``error:`` line, never an internal error, nothing left at the output after an error.
- **lc.read** on the command line's files truncated, with bytes flipped, junk appended, a
  byte-order mark, CRLF line ends, empty, binary, 10 MB lines, deep nesting: a DataFrame equal
  to the original (where the format allows the change) or a ValueError naming the file, never
  another exception; a truncation that still parses gives at most the original's first rows,
  never a row with other values (a CSV or JSON Lines file cut at a line end cannot say it was
  cut: fewer rows are all the format can promise there).

Everything is derandomized (Hypothesis's profile in ``conftest.py``, fixed seeds elsewhere),
bounded in examples and requests, and on the loopback interface only;
``LINECONTACT_FUZZ_EXAMPLES=400 pytest tests/test_fuzz_shells.py`` runs a longer campaign.
Cases that find a fault not yet fixed are marked ``xfail(strict=True)`` with the fault said.
"""

from __future__ import annotations

import contextlib
import http.client
import io
import json
import math
import os
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.parse
import warnings
from concurrent.futures import ThreadPoolExecutor
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path
from unittest import mock

import numpy as np
import pytest
from hypothesis import HealthCheck, Phase, assume, event, given, settings
from hypothesis import strategies as st

import linecontact as lc
from linecontact.cli import main

EXAMPLES = int(os.environ.get("LINECONTACT_FUZZ_EXAMPLES", "40"))
FUZZ = settings(
    derandomize=True,
    database=None,
    deadline=None,
    max_examples=EXAMPLES,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much],
)
#: The costly draws (a sweep each): a failure is reported as found, not shrunk for minutes.
COSTLY = settings(FUZZ, phases=[Phase.explicit, Phase.reuse, Phase.generate])
#: Scale of the seeded (non-Hypothesis) draws: 1 at the default number of examples.
SCALE = max(1, EXAMPLES // 40)

BASE = "http://127.0.0.1:8000"  # a Host the server takes
PACKAGE = str(Path(lc.__file__).resolve().parent)
WIRE = "radius=50e-9&modulus=1.2e11&work_of_adhesion=0.3&z0=3e-10"

#: Statuses the API documents (``/api/v1/openapi.json``), jobs' 202 and 503 included.
ALLOWED = {200, 202, 400, 403, 404, 405, 413, 415, 422, 500, 503, 504}

#: What a 500 may say: a solver that missed its tolerance, or a worker that ended.
SOLVER_OR_WORKER = re.compile(
    r"converge|tolerance|missed tol|not monotone|vanishes|could not be solved|solver|"
    r"worker computing this request ended unexpectedly"
)


# ============================================================================================
# HTTP: the oracle


def _security_headers(r) -> None:
    from linecontact.web._app import HEADERS

    for k, v in HEADERS.items():
        assert r.headers.get(k) == v, (k, r.status_code, r.request.url)


def _no_server_path(text: str, root: str | None) -> None:
    """No path of the server in a response: its directory, the package, a traceback."""
    assert "Traceback (most recent call last)" not in text, text[:2000]
    assert PACKAGE not in text, text[:2000]
    assert "linecontact-web-" not in text, text[:2000]  # the pool's temporary directory
    if root:
        assert root not in text, text[:2000]


def _error_shape(doc) -> dict:
    assert isinstance(doc, dict) and set(doc) == {"error"}, doc
    err = doc["error"]
    assert isinstance(err, dict) and set(err) == {"parameter", "message"}, err
    assert isinstance(err["message"], str) and err["message"].strip(), err
    assert err["parameter"] is None or isinstance(err["parameter"], str), err
    return err


def _check(r, root: str | None = None):
    """The oracle of every response; its JSON document where it has one."""
    method = r.request.method.upper()
    path = r.request.url.path
    status = r.status_code
    assert status in ALLOWED or (status == 200 and not path.startswith("/api/")), (
        status,
        method,
        str(r.request.url)[:300],
        r.text[:500],
    )
    _security_headers(r)
    _no_server_path(r.text, root)
    if method == "HEAD" or (status < 400 and not path.startswith("/api/")):
        return None
    ctype = r.headers.get("content-type", "")
    if status >= 400 and not path.startswith("/api/") and ctype.startswith("text/html"):
        assert status == 404, (status, path)  # a page that is none: the index, said so
        return None
    assert ctype.startswith("application/json"), (status, path, ctype, r.text[:300])
    doc = r.json()
    if status >= 400:
        err = _error_shape(doc)
        if status == 500:
            msg = err["message"]
            assert "internal error" not in msg and SOLVER_OR_WORKER.search(msg), msg
        return doc
    m = re.fullmatch(r"/api/v1/([^/]+)", path)
    if status == 200 and m and m.group(1) != "openapi.json":
        assert isinstance(doc, dict), doc
        assert {"linecontact", "command", "parameters", "units", "results"} <= set(doc), doc
        assert doc["command"][:2] == ["linecontact", m.group(1)], doc["command"]
        assert isinstance(doc["results"], list) and isinstance(doc["units"], dict)
    if path.startswith("/api/v1/jobs/"):
        _check_job(doc, root)
    return doc


def _check_job(doc, root: str | None) -> None:
    assert {"id", "command", "state", "elapsed_s"} <= set(doc), doc
    assert doc["state"] in ("queued", "running", "done", "failed", "cancelled"), doc
    if doc["state"] in ("done", "failed", "cancelled"):
        assert doc["status"] in ALLOWED | {499}, doc
    if doc["state"] == "done":
        assert doc["status"] == 200
        assert {"linecontact", "command", "parameters", "units", "results"} <= set(doc["result"])
    elif doc["state"] in ("failed", "cancelled"):
        _error_shape({"error": doc["error"]})
        if doc["status"] == 500:
            msg = doc["error"]["message"]
            assert "internal error" not in msg and SOLVER_OR_WORKER.search(msg), msg


# ============================================================================================
# HTTP: the in-process application


@pytest.fixture(scope="module")
def client():
    pytest.importorskip("starlette")
    pytest.importorskip("httpx")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # starlette's note on httpx versions
        from starlette.testclient import TestClient
    from linecontact.web import create_app

    # few points a request (every draw stays cheap), a short time limit; the server's errors
    # as responses (its 500 is what the oracle reads), not re-raised here
    app = create_app(workers=2, time_limit=20, max_points=100)
    with TestClient(app, base_url=BASE, raise_server_exceptions=False) as c:
        yield c


class _Parameters(dict):
    """The commands' parameters (a short repr in Hypothesis's reports)."""

    def __repr__(self) -> str:
        return "<the parameters of /api/v1/openapi.json>"


@pytest.fixture(scope="module")
def api_parameters(client):
    """The parameters of each command, as the OpenAPI document lists them."""
    spec = client.get("/api/v1/openapi.json").json()
    out = _Parameters()
    for path, item in spec["paths"].items():
        m = re.fullmatch(r"/api/v1/([^/{}]+)", path)
        if m and "get" in item:
            out[m.group(1)] = item["get"]["parameters"]
    return out


def _root(client) -> str | None:
    return client.app.pool.root


#: Commands of the random requests: every one but the map (seconds a request, and its
#: own test below: its result names the server's directory).
def _fuzzed_commands(api_parameters) -> list[str]:
    return sorted(c for c in api_parameters if c != "map")


JUNK_KEYS = [
    "", " ", "output", "o", "json", "format", "help", "data", "outdir", "plot", "workers",
    "progress", "indent", "R-over-h", "r_over_h", "R_over_h[]", "__proto__", "x" * 300, "σ",
    "R_over_h\x00", "--json", "-o", "radius ", "quick", "n_mu",
]  # fmt: skip
JUNK_VALUES = [
    "", " ", "nan", "NaN", "inf", "-inf", "Infinity", "1e400", "-1e400", "1e-400", "0", "-0",
    "1", "-1", "2", "abc", "true", "false", "yes", "--json", "-o", "--output=/tmp/x",
    "-o /tmp/x", "../../etc/passwd", "/etc/passwd", "1,2,3", "1 2", ",,,", "1;2", "0x10",
    "1_000", "١٢٣", "½", "%", "%zz", "%00", "\x00", "\n-o\n/tmp/x", "😀", "9" * 5000,
    "1," * 150, "-1e-3", "-.5", "1e", "e1", "--", "-", "None", "null", "[1]", "{}", "'1'",
    '"1"', "0.01", "100", "1e-9", "5e-8", "3e-10", "0.3", "1.2e11", "ZnO", "SiO2", "Si",
]  # fmt: skip


def _value(schema: dict) -> st.SearchStrategy[str]:
    inner = schema.get("items", schema)
    options = [
        st.sampled_from(JUNK_VALUES),
        st.floats(allow_nan=True, allow_infinity=True).map(repr),
        st.integers(-10, 60).map(str),
        st.floats(-12, 12).map(lambda e: f"{10**e:.6g}"),
    ]
    if inner.get("enum"):
        options += [st.sampled_from(inner["enum"])] * 3
    if inner.get("type") == "boolean":
        options += [st.sampled_from(["true", "false", "1", "0", "", "on", "maybe"])] * 2
    return st.one_of(options)


#: A request each command answers (200), the start of most draws, which then change it.
API_BASES = {
    "pulloff": WIRE,
    "normal": "R_over_h=100&sigma0_over_E=0.2&F_over_Eh=-1,0,1",
    "curve": "R_over_h=100&sigma0_over_E=0.05&num=20&num_noncontact=5",
    "slide": "R_over_h2=100&h1_over_h2=2&sigma0_over_E=0.04&F_over_Eh2=0,1",
    "slide-init": "a_over_R=0.05&tau0_over_E=0.01&T_over_Ea=0.005",
    "roll": "a_over_R=0.05&tau0_over_E=0.01&T_over_Ea=0.005",
    "cycle": "tau0_over_E=0.01&T_amplitude_over_Ea=0.01",
    "history": "tau0_over_E=0.01&T_over_Ea=0.016,-0.008,0.004",
    "push": "R_over_h2=100&h1_over_h2=2&sigma0_over_E=0.04&tau0_over_E=0.01&H_over_R=0.5,1",
    "fit-adhesion": "radius=50e-9&radius_sd=3e-9&pull_off_force=-3.1&pull_off_force_sd=5%25"
    "&modulus=51.7e9&z0=0.3e-9&samples=100",
    "fit-friction": "radius=50e-9&modulus=51.7e9&z0=0.3e-9&work_of_adhesion=0.3&load=1"
    "&friction_force=0.5&samples=100",
    "materials": "",
}


@st.composite
def _items(draw, api_parameters, command: str) -> list[tuple[str, str]]:
    """Query items for ``command``: a request it answers, changed (its own parameters given
    other values, some dropped, others', junk and repeated keys added), or none of it."""
    own = api_parameters.get(command, [])
    others = [p for c in sorted(api_parameters) for p in api_parameters[c]]
    items = []
    if command in API_BASES and draw(st.integers(0, 9)) < 7:
        items = urllib.parse.parse_qsl(API_BASES[command])
        for _ in range(draw(st.integers(0, 2))):  # another value, or none
            if items:
                i = draw(st.integers(0, len(items) - 1))
                named = next((p for p in own if p["name"] == items[i][0]), None)
                if named is not None and draw(st.booleans()):
                    items[i] = (items[i][0], draw(_value(named["schema"])))
                else:
                    del items[i]
    for _ in range(draw(st.integers(0, 3 if items else 7))):
        kind = draw(st.sampled_from(["own"] * 6 + ["other", "junk"])) if own else "junk"
        if kind == "junk":
            key = draw(st.sampled_from(JUNK_KEYS))
            value = draw(st.one_of(st.sampled_from(JUNK_VALUES), st.text(max_size=20)))
        else:
            p = draw(st.sampled_from(own if kind == "own" else others))
            key, value = p["name"], draw(_value(p["schema"]))
        items.append((key, value))
        if draw(st.integers(0, 9)) == 0:  # the same key again
            items.append((key, draw(st.sampled_from(JUNK_VALUES))))
    return items


def _raw_query(items: list[tuple[str, str]]) -> str:
    """A query string as a careless client writes it: '%' kept, only '#', '&', '=' escaped."""

    def esc(s: str) -> str:
        s = s.replace("#", "%23").replace("&", "%26").replace("=", "%3D").replace(" ", "+")
        return "".join(f"%{ord(c):02X}" if ord(c) < 0x20 or ord(c) == 0x7F else c for c in s)

    return "&".join(f"{esc(k)}={esc(v)}" for k, v in items)


def _multipart(fields: list[tuple[str, str]], odd: list[bytes], boundary: str) -> bytes:
    out = b""
    for k, v in fields:
        out += f'--{boundary}\r\nContent-Disposition: form-data; name="{k}"\r\n\r\n'.encode()
        out += v.encode("utf-8", "surrogatepass") + b"\r\n"
    for part in odd:
        out += f"--{boundary}\r\n".encode() + part + b"\r\n"
    return out + f"--{boundary}--\r\n".encode()


#: Odd parts of a multipart body (an uploaded ``data`` file among them: the server's
#: temporary copy of it must never be named in the answer).
ODD_PARTS = [
    b'Content-Disposition: form-data; name="data"; filename="../../m.csv"\r\n'
    b"Content-Type: text/csv\r\n\r\nradius_nm,pull_off_force_N_per_m\n20,-2.9\n50,-4.6\n",
    b'Content-Disposition: form-data; name="data"; filename="x"\r\n\r\n\xff\x00garbage',
    b"Content-Disposition: form-data\r\n\r\nno name",
    b'Content-Disposition: form-data; name="f"; filename="../../etc/passwd"\r\n'
    b"Content-Type: application/octet-stream\r\n\r\n\x00\xff\xfe",
    b'Content-Disposition: form-data; name="R_over_h"; filename="x.csv"\r\n\r\n100',
    b'Content-Disposition: form-data; name="\xff\xfe"\r\n\r\n1',
    b"no headers at all",
    b'Content-Disposition: form-data; name="R_over_h"\r\nContent-Type: text/plain; '
    b"charset=utf-16\r\n\r\n\xff\xfe1\x000\x000\x00",
    b'Content-Disposition: attachment; name="sigma0_over_E"\r\n\r\n0.01',
    b'Content-Disposition: form-data; name="' + b"n" * 5000 + b'"\r\n\r\n1',
]


@settings(FUZZ, max_examples=3 * EXAMPLES)
@given(data=st.data())
def test_random_requests_get_a_documented_answer(client, api_parameters, data):
    commands = _fuzzed_commands(api_parameters)
    command = data.draw(
        st.sampled_from(
            commands * 6
            + ["", "paper", "sweep", "serve", "cite", "figures", "PULLOFF", "pulloff.json",
               "pulloff%00", "..", "%2e%2e", "openapi.json"]
        ),
        label="command",
    )  # fmt: skip
    items = data.draw(_items(api_parameters, command), label="items")
    how = data.draw(
        st.sampled_from(["get", "get-raw", "post-query", "post-json", "post-form", "post-multi"]),
        label="how",
    )
    path = f"/api/v1/{command}"
    headers: dict[str, str] = {}
    content = None
    odd: list[bytes] = []
    if how in ("get", "post-query"):
        url = f"{path}?{urllib.parse.urlencode(items)}"
    elif how == "get-raw":
        url = f"{path}?{_raw_query(items)}"
    else:
        url = path
    if how == "post-json":
        doc: dict = {}
        for k, v in items:
            number = data.draw(st.booleans(), label="as a number")
            try:
                x = float(v) if number else v
                v = int(x) if number and x.is_integer() and abs(x) < 1e15 else x
            except (ValueError, OverflowError):
                pass
            doc.setdefault(k, []).append(v)
        doc = {k: v[0] if len(v) == 1 else v for k, v in doc.items()}
        content = json.dumps(doc, allow_nan=True).encode()
        headers["content-type"] = "application/json"
    elif how == "post-form":
        content = urllib.parse.urlencode(items).encode()
        headers["content-type"] = "application/x-www-form-urlencoded"
    elif how == "post-multi":
        odd = data.draw(st.lists(st.sampled_from(ODD_PARTS), max_size=2), label="odd parts")
        boundary = data.draw(st.sampled_from(["xyz", "a" * 70, "--", "b\tc"]), label="boundary")
        content = _multipart(items, odd, boundary)
        headers["content-type"] = f"multipart/form-data; boundary={boundary}"
    method = "GET" if how.startswith("get") else "POST"
    r = client.request(method, url, content=content, headers=headers)
    event(f"status {r.status_code}")
    doc = _check(r, _root(client))
    if r.status_code == 200 and doc is not None and "command" in doc:
        assert doc["command"][-1] == "--json"
    if r.status_code >= 400 and doc is not None:
        # the parameter named is the request's, the command's, or the part of the request
        err = doc["error"]
        names = {p["name"] for p in api_parameters.get(command, [])}
        keys = {k for k, _ in items}
        for part in odd if how == "post-multi" else []:  # the odd parts' names, as decoded
            for name in re.findall(rb'name="([^"]*)"', part):
                keys |= {name.decode("latin-1"), name.decode("utf-8", "replace")}
        known = {None, "body", "command", "Host", "Origin", "id"}
        assert err["parameter"] in known | names | keys, (err, items)


BODY_TYPES = [
    "application/json", "application/json; charset=utf-8", "APPLICATION/JSON",
    "application/json; charset=utf-16", "application/x-www-form-urlencoded",
    "multipart/form-data", "multipart/form-data; boundary=", "multipart/form-data; boundary=x",
    'multipart/form-data; boundary="x y"', "text/plain", "application/xml", "", "*/*",
    "application/octet-stream", "image/png", "application/json, text/html", ";;;", "json",
]  # fmt: skip
HOSTILE_BODIES = [
    b"", b"{}", b"[]", b"null", b"1", b'"x"', b"{", b'{"R_over_h": }', b"\xef\xbb\xbf{}",
    b"\xff\xfe{\x00}\x00", b'{"R_over_h": 1e999}', b'{"R_over_h": NaN, "sigma0_over_E": -Infinity}',
    b'{"R_over_h": ' + b"9" * 5000 + b"}", b'{"R_over_h": [[1]]}', b'{"R_over_h": {"$gt": 1}}',
    b'{"R_over_h": 100, "R_over_h": 200, "sigma0_over_E": 0.01}', b"[" * 3000 + b"]" * 3000,
    b'{"a":' * 3000 + b"1" + b"}" * 3000, b"R_over_h=100&sigma0_over_E=0.01",
    b"R_over_h=%zz&sigma0_over_E=%ff%fe", b"=&=&&==", b"\x00" * 100, b"x" * 70_000,
    b"&".join(b"k%d=1" % i for i in range(1500)), b"--x\r\n\r\n--x--",
    b'--x\r\nContent-Disposition: form-data; name="R_over_h"\r\n\r\n100\r\n--x--\r\n',
]  # fmt: skip


@settings(FUZZ, max_examples=2 * EXAMPLES)
@given(
    command=st.sampled_from(["pulloff", "normal", "curve", "nosuch"]),
    ctype=st.one_of(
        st.sampled_from(BODY_TYPES),
        st.sampled_from(["application/json", "application/x-www-form-urlencoded"]),
        st.just("multipart/form-data; boundary=x"),
        st.text(st.characters(min_codepoint=0x20, max_codepoint=0x7E), max_size=30),
    ),
    body=st.one_of(st.sampled_from(HOSTILE_BODIES), st.binary(max_size=2000)),
    job=st.booleans(),
)
def test_random_bodies_are_answered_or_refused_in_json(client, command, ctype, body, job):
    path = f"/api/v1/jobs/{command}" if job else f"/api/v1/{command}"
    headers = {"content-type": ctype} if ctype else {}
    try:
        r = client.post(f"{path}?{WIRE}" if command == "pulloff" else path, content=body,
                        headers=headers)  # fmt: skip
    except UnicodeEncodeError:  # httpx's own refusal of a header it cannot send
        return
    event(f"status {r.status_code}")
    _check(r, _root(client))
    if r.status_code == 202:  # a job: it ends, with an answer of the same oracle
        _finish_job(client, r.json()["id"])


PAGES = ["", "pulloff", "contact", "curve", "push", "index.html", "favicon.ico", "robots.txt"]


@settings(FUZZ, max_examples=2 * EXAMPLES)
@given(
    method=st.sampled_from(
        ["GET", "POST", "PUT", "DELETE", "PATCH", "HEAD", "OPTIONS", "TRACE", "FOO", "PROPFIND"]
    ),
    path=st.one_of(
        st.sampled_from(
            [
                "/api/v1/openapi.json",
                "/api/v1/",
                "/api/v1",
                "/api",
                "/api/v2/pulloff",
                f"/api/v1/pulloff?{WIRE}",
                "/api/v1/pulloff/",
                "//api/v1/pulloff",
                "/api/v1/pulloff/extra",
                "/api/v1/jobs",
                "/api/v1/jobs/",
                "/api/v1/jobs/id",
                "/api/v1/jobs/id/",
                "/api/v1/jobs/id/../../../etc/passwd",
                "/api/v1/jobs/pulloff/x",
                "/static/",
                "/static",
                "/static/../../../etc/passwd",
                "/static/%2e%2e/%2e%2e/etc/passwd",
                "/static/app.js",
                "/static/nothing.css",
                "/%00",
                "/" + "a" * 10_000,
                "/api/v1/" + "é" * 50,
                "/api/v1/%ff%fe",
                "/..%2f..%2fetc%2fpasswd",
                "/api/v1/pulloff;jsessionid=1",
            ]
        ),  # fmt: skip
        st.sampled_from(PAGES).map(lambda p: "/" + p),
        st.text(max_size=40).map(lambda s: "/" + urllib.parse.quote(s)),
        st.text(max_size=40).map(lambda s: "/api/v1/" + urllib.parse.quote(s, safe="/")),
        st.text(min_size=1, max_size=40).map(
            lambda s: "/api/v1/jobs/id/" + urllib.parse.quote(s, safe="")
        ),
    ),
)
def test_random_paths_and_methods_are_answered_or_refused(client, method, path):
    r = client.request(method, path)
    _check(r, _root(client))
    if method in ("PUT", "PATCH", "TRACE", "FOO", "PROPFIND") and path.startswith("/api/"):
        assert r.status_code in (403, 404, 405), (method, path, r.status_code)


def _finish_job(client, job_id: str) -> dict:
    """Wait (bounded) for a job to end; its document, checked."""
    for _ in range(600):
        r = client.get(f"/api/v1/jobs/id/{job_id}")
        doc = _check(r, _root(client))
        if doc["state"] not in ("queued", "running"):
            return doc
        time.sleep(0.05)
    raise AssertionError(f"job {job_id} never ended")


@settings(FUZZ, max_examples=max(EXAMPLES // 2, 8))
@given(data=st.data())
def test_random_jobs_end_in_a_documented_state(client, api_parameters, data):
    command = data.draw(st.sampled_from(["pulloff", "normal", "slide-init", "roll", "push"]))
    items = data.draw(_items(api_parameters, command), label="items")
    r = client.post(f"/api/v1/jobs/{command}?{urllib.parse.urlencode(items)}")
    doc = _check(r, _root(client))
    if r.status_code != 202:
        return
    assert doc["state"] in ("queued", "running") and re.fullmatch(r"[0-9a-f]{32}", doc["id"])
    done = _finish_job(client, doc["id"])
    # a DELETE of a finished job changes nothing; an unknown id is a 404 naming "id"
    again = client.delete(f"/api/v1/jobs/id/{doc['id']}")
    assert _check(again, _root(client)) == done
    junk = data.draw(st.text(min_size=1, max_size=50), label="id")
    r = client.get(f"/api/v1/jobs/id/{urllib.parse.quote(junk, safe='')}")
    _check(r, _root(client))
    if r.status_code == 404 and r.request.url.path.count("/") == 5:
        assert r.json()["error"]["parameter"] == "id"


def test_an_upload_never_names_the_servers_directory(client):
    mats = {"cylinder_material": "SiO2", "substrate_material": "Si", "z0": "3e-10"}
    good = b"radius_nm,pull_off_force_N_per_m\n20,-2.9\n50,-4.6\n100,-6.4\n"
    texts = []
    for command, fields, body in [
        ("fit-adhesion", mats, b"radius_furlong,force\n1,2\n"),  # no such column
        ("fit-adhesion", mats, b"\xff\xfe\x00"),  # not UTF-8
        ("fit-adhesion", mats, b""),  # nothing
        ("fit-adhesion", mats, b"radius_nm,pull_off_force_N_per_m\n20,abc\n"),  # not a number
        ("pulloff", {"R_over_h": "100", "sigma0_over_E": "0.01"}, b"x"),  # no --data there
        ("fit-adhesion", mats, good),  # a fit: its provenance
    ]:
        r = client.post(
            f"/api/v1/{command}", data=fields, files={"data": ("m.csv", body, "text/csv")}
        )
        assert r.status_code in (200, 422), r.text
        texts.append(r.text)
    for text in texts:
        _no_server_path(text, _root(client))


def test_the_map_never_names_the_servers_directory(client):
    r = client.get("/api/v1/map?n_mu=2&n_y=3")  # the smallest map: a few seconds
    assert r.status_code == 200, r.text
    _no_server_path(r.text, _root(client))


# ============================================================================================
# HTTP: a real server on 127.0.0.1


@pytest.fixture(scope="module")
def server():
    """``linecontact serve --port 0`` (its own workers): its URL."""
    pytest.importorskip("uvicorn")
    pytest.importorskip("starlette")
    env = {**os.environ, "OPENBLAS_NUM_THREADS": "1"}
    proc = subprocess.Popen(
        [sys.executable, "-m", "linecontact", "serve", "--port", "0", "--time-limit", "30"],
        env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
    )  # fmt: skip
    assert proc.stderr is not None
    line = proc.stderr.readline()
    assert "http://127.0.0.1:" in line, line
    url = line.split()[2].rstrip("/")
    host, port = url.removeprefix("http://").split(":")
    try:
        yield proc, host, int(port)
    finally:
        proc.terminate()
        try:
            proc.wait(30)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait(30)


class _Headers(dict):
    """Response headers, read whatever the case of the name."""

    def get(self, key, default=None):
        return super().get(key.lower(), default)


class _Wire:
    """A response read off the wire, shaped as the oracle reads an httpx response."""

    def __init__(self, method: str, path: str, status: int, headers, body: bytes) -> None:
        self.status_code = status
        self.headers = _Headers((k.lower(), v) for k, v in headers)
        self.content = body
        self.text = body.decode("utf-8", "replace")
        self.request = type(
            "R", (), {"method": method, "url": urllib.parse.urlsplit(path)}
        )()  # .method, .url.path

    def json(self):
        return json.loads(self.content)


def _http(host: str, port: int, method: str, path: str, body: bytes | None = None,
          headers: dict | None = None) -> _Wire:  # fmt: skip
    conn = http.client.HTTPConnection(host, port, timeout=60)
    try:
        conn.request(method, path, body=body, headers=headers or {})
        r = conn.getresponse()
        data = r.read()
        return _Wire(method, path, r.status, r.getheaders(), data)
    finally:
        conn.close()


def test_a_concurrent_burst_is_answered_and_identical_requests_agree(server):
    proc, host, port = server
    same = "/api/v1/normal?R_over_h=100&sigma0_over_E=0.2&F_over_Eh=-1,0,1"
    many = "/api/v1/normal?R_over_h=100&sigma0_over_E=0.01&a_over_R_range=0.001,0.1,1000000"
    mix = [
        ("GET", same, None, {}),
        ("GET", f"/api/v1/pulloff?{WIRE}", None, {}),
        ("GET", "/api/v1/pulloff?R_over_h=abc&sigma0_over_E=0.01", None, {}),
        ("GET", many, None, {}),  # refused before it costs
        ("POST", "/api/v1/normal", b'{"R_over_h": 100, "sigma0_over_E": 0.2, "F_over_Eh": '
         b"[-1, 0, 1]}", {"Content-Type": "application/json"}),
        ("POST", "/api/v1/pulloff", b"{" + b" " * 70_000 + b"}",
         {"Content-Type": "application/json"}),
        ("POST", "/api/v1/pulloff", b"\xff\xfe", {"Content-Type": "application/json"}),
        ("POST", f"/api/v1/jobs/pulloff?{WIRE}", None, {}),
        ("GET", "/api/v1/jobs/id/" + "0" * 32, None, {}),
        ("GET", "/api/v1/nosuch", None, {}),
    ]  # fmt: skip
    calls = [mix[i % len(mix)] for i in range(40)]  # 40 requests
    with ThreadPoolExecutor(8) as pool:
        answers = list(pool.map(lambda c: _http(host, port, *c), calls))
    results = []
    for (method, path, _, _), r in zip(calls, answers, strict=True):
        doc = _check(r)
        if path == same or (method == "POST" and path == "/api/v1/normal"):
            assert r.status_code == 200, r.text
            results.append(doc["results"])
        if path == many:
            assert r.status_code == 413
    assert results and all(x == results[0] for x in results)  # the same numbers each time
    assert proc.poll() is None
    assert _http(host, port, "GET", f"/api/v1/pulloff?{WIRE}").status_code == 200


def _parse_wire(data: bytes):
    """The first final response in ``data``: (status, headers, body), or None (no answer)."""
    while data:
        head, sep, rest = data.partition(b"\r\n\r\n")
        assert sep, data[:500]
        lines = head.split(b"\r\n")
        m = re.fullmatch(rb"HTTP/1\.[01] (\d{3})(?: .*)?", lines[0])
        assert m, lines[0]
        status = int(m.group(1))
        headers = []
        for ln in lines[1:]:
            k, _, v = ln.partition(b":")
            headers.append((k.strip().decode("latin-1"), v.strip().decode("latin-1")))
        if 100 <= status < 200:  # informational (100 Continue): the answer follows
            data = rest
            continue
        length = next((int(v) for k, v in headers if k.lower() == "content-length"), None)
        body = rest if length is None else rest[:length]
        return status, headers, body
    return None


RAW_METHODS = [b"GET", b"POST", b"HEAD", b"DELETE", b"PUT", b"get", b"G\x00T", b"", b"GET GET",
               b"\xff", b"CONNECT", b"OPTIONS"]  # fmt: skip
RAW_TARGETS = [
    b"/api/v1/pulloff?" + WIRE.encode(), b"/api/v1/normal?F_over_Eh=1", b"/", b"*",
    b"http://evil.example/api/v1/pulloff", b"/api/v1/pulloff?%zz=%ff", b"/api v1", b"",
    b"/\x00", b"/\xc3\x28", b"/api/v1/jobs/id/x", b"//", b"/" + b"a" * 20_000,
    b"/api/v1/pulloff?R_over_h=" + b"1," * 3000,
]  # fmt: skip
RAW_VERSIONS = [b"HTTP/1.1", b"HTTP/1.0", b"HTTP/2.0", b"HTTP/9.9", b"http/1.1", b"", b"HTTP/1.1 x"]
RAW_HEADERS = [
    b"Host: 127.0.0.1", b"Host: evil.example", b"Host:", b"Host: 127.0.0.1\r\nHost: localhost",
    b"Content-Type: application/json", b"Content-Type: multipart/form-data; boundary=x",
    b"Content-Length: 5", b"Content-Length: -1", b"Content-Length: 99999999999999999999",
    b"Content-Length: 2\r\nContent-Length: 3", b"Transfer-Encoding: chunked",
    b"Transfer-Encoding: gzip, chunked", b"Transfer-Encoding: chunked\r\nContent-Length: 3",
    b"Origin: null", b"Origin: http://evil.example", b"Expect: 100-continue",
    b"Connection: close", b"Connection: keep-alive", b"Upgrade: websocket\r\nConnection: Upgrade",
    b"X-Junk: " + b"v" * 9000, b"Bad Header: x", b"NoColon", b" folded: continuation",
    b"X\x00: y", b"X: \xff\xfe", b":empty-name",
]  # fmt: skip
RAW_BODIES = [b"", b"{}", b"hello", b"5\r\nhello\r\n0\r\n\r\n", b"zz\r\nx\r\n", b"0\r\n\r\n",
              b'{"R_over_h": 100}', b"\xff" * 64, b"1\r\nx\r\n"]  # fmt: skip


@settings(FUZZ, max_examples=max(2 * EXAMPLES, 10))
@given(
    method=st.sampled_from(RAW_METHODS),
    target=st.sampled_from(RAW_TARGETS),
    version=st.sampled_from(RAW_VERSIONS),
    headers=st.lists(st.sampled_from(RAW_HEADERS), max_size=4),
    body=st.one_of(st.sampled_from(RAW_BODIES), st.binary(max_size=300)),
    line_end=st.sampled_from([b"\r\n", b"\r\n", b"\n"]),
)
def test_raw_malformed_requests_get_a_json_answer_or_none(server, method, target, version,
                                                          headers, body, line_end):  # fmt: skip
    proc, host, port = server
    request = method + b" " + target + (b" " + version if version else b"") + line_end
    if not any(h.lower().startswith(b"host:") for h in headers):
        headers = [b"Host: 127.0.0.1", *headers]
    for h in headers:
        request += h.replace(b"\r\n", line_end) + line_end
    request += line_end + body
    data = b""
    with socket.create_connection((host, port), timeout=30) as s:
        s.sendall(request)
        s.shutdown(socket.SHUT_WR)  # the whole request: the server sees its end
        with contextlib.suppress(ConnectionResetError):
            while chunk := s.recv(65536):
                data += chunk
    got = _parse_wire(data)
    event("no answer" if got is None else f"status {got[0]}")
    if got is not None:  # a request cut short (or one HTTP gives up on) may get no answer
        status, hdrs, payload = got
        path = target.decode("latin-1") if target.startswith(b"/") else "/api/"
        meth = method.decode("latin-1").upper()
        w = _Wire(meth, path, status, hdrs, b"" if meth == "HEAD" else payload)
        if status == 400 and not path.startswith("/api/"):  # h11's refusals are the API's
            w.request.url = urllib.parse.urlsplit("/api/")
        _check(w)
    assert proc.poll() is None, "the server ended"


def test_the_server_still_answers_after_the_raw_requests(server):
    proc, host, port = server
    r = _http(host, port, "GET", f"/api/v1/pulloff?{WIRE}")
    assert r.status_code == 200 and proc.poll() is None


# ============================================================================================
# sweeps stopped and resumed


def _xarray():
    pytest.importorskip("xarray")
    pytest.importorskip("zarr")
    pytest.importorskip("netCDF4")
    pytest.importorskip("dask")


#: Small sweeps cut into several blocks: (command, flags, chunk_points).
RESUME = {
    # the Dugdale pull-off, a block at a time (its closed forms)
    "pulloff": ("pulloff", dict(R_over_h="10:1000:9:log", sigma0_over_E=[0.01, 0.05, 0.2]), 4),
    # words for coordinates (the materials), SI inputs
    "pulloff-si": (
        "pulloff",
        dict(
            cylinder_material=["ZnO", "SiO2"],
            substrate_material="Si",
            radius=[20e-9, 80e-9],
            work_of_adhesion="0.1:0.5:3",
            z0=3e-10,
        ),
        2,
    ),
    # a flag the subcommand takes several values of: a row a call; loads below the pull-off
    "normal": ("normal", dict(R_over_h=[50.0, 200.0], sigma0_over_E=0.2, F_over_Eh="-4:2:7"), 3),
    # several records a point: the dimension "record"
    "curve": ("curve", dict(R_over_h=100, sigma0_over_E=[0.01, 0.1, 0.3], num=8), 1),
}

_REFERENCES: dict[str, object] = {}


def _reference(name: str):
    """The uninterrupted run, in memory (computed once)."""
    if name not in _REFERENCES:
        command, kw, chunk = RESUME[name]
        _REFERENCES[name] = lc.sweep(command, chunk_points=chunk, **kw)
    return _REFERENCES[name]


def _plan_of(name: str):
    from linecontact.sweeps import _words
    from linecontact.sweeps._plan import blocks, plan

    command, kw, chunk = RESUME[name]
    p = plan(command, _words(kw), None, chunk)
    return p, blocks(p.shape, p.chunk_points)


def _keep(name: str, out: Path, which) -> None:
    """Keep the blocks ``which`` of the sweep ``name`` in ``out.partial/`` (a stopped run)."""
    from linecontact.sweeps._points import evaluate
    from linecontact.sweeps._store import Partial

    p, bl = _plan_of(name)
    part = Partial(p, out)
    with part.locked():
        part.open(False)
        for k in which:
            part.put(evaluate(p, k, bl[k]))


def _texts(a) -> list[str]:
    """An array of words (object, fixed width or NumPy's StringDType) as a list of str."""
    return [str(x) for x in np.asarray(a).astype(object).ravel()]


def _assert_same_dataset(got, want) -> None:
    """Equal dims, coordinates, text and flags; numbers to 1e-12; the provenance."""
    got = got.load()
    assert list(got.data_vars) == list(want.data_vars)
    assert dict(got.sizes) == dict(want.sizes)
    for name in want.coords:
        a, b = np.asarray(got[name].values), np.asarray(want[name].values)
        if b.dtype.kind == "f":
            np.testing.assert_allclose(a, b, rtol=1e-12, atol=0, err_msg=name)
        else:
            assert _texts(a) == _texts(b), name
    for name in want.data_vars:
        a, b = np.asarray(got[name].values), np.asarray(want[name].values)
        if b.dtype.kind == "f":
            np.testing.assert_allclose(a, b, rtol=1e-12, atol=0, equal_nan=True, err_msg=name)
        elif b.dtype.kind == "b":
            assert (a == b).all(), name
        else:
            assert _texts(a) == _texts(b), name
    for key in ("linecontact", "command", "parameters", "units", "swept"):
        assert got.attrs[key] == want.attrs[key], key


class _Stop(Exception):
    """A run stopped part way (as Ctrl-C or a killed process would stop it)."""


#: Files a stopped run or a user may leave in OUT.partial/ that are no block of it.
STRAYS = {
    "temporary": ".block-000003.npz.x1y2z3.part",  # a block being written when it stopped
    "notes": "notes.txt",
    "not-a-number": "block-abc.npz",
    "no-number": "block-.npz",
    "backup": "block-000001.npz.bak",
}


@pytest.mark.parametrize("name", sorted(RESUME))
@settings(COSTLY, max_examples=max(EXAMPLES // 6, 6))
@given(how=st.sampled_from(["blocks kept", "stopped"]), data=st.data())
def test_a_resumed_sweep_equals_an_uninterrupted_one(name, how, data):
    _xarray()
    from linecontact.sweeps import _engine

    command, kw, chunk = RESUME[name]
    _, bl = _plan_of(name)
    ext = data.draw(st.sampled_from([".zarr", ".nc"]), label="store")
    strays = data.draw(st.lists(st.sampled_from(sorted(STRAYS)), unique=True), label="strays")
    event(how)
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / f"s{ext}"
        partial = Path(f"{out}.partial")
        if how == "blocks kept":
            which = data.draw(
                st.lists(st.integers(0, len(bl) - 1), unique=True, max_size=len(bl)),
                label="blocks",
            )
            _keep(name, out, which)
        else:  # a run stopped by an exception after some blocks
            stop = data.draw(st.integers(0, len(bl) - 1), label="stopped after")
            real, calls = _engine.evaluate, []

            def flaky(*a, **k):
                if len(calls) >= stop:
                    raise _Stop
                calls.append(1)
                return real(*a, **k)

            with mock.patch.object(_engine, "evaluate", flaky), pytest.raises(_Stop):
                lc.sweep(command, output=out, chunk_points=chunk, **kw)
            assert not out.exists()
            which = list(range(stop))
            assert len(list(partial.glob("block-*.npz"))) == stop
        for s in strays:
            partial.mkdir(exist_ok=True)
            (partial / STRAYS[s]).write_bytes(b"\x00stray")
        got = lc.sweep(command, output=out, chunk_points=chunk, **kw)
        want = _reference(name)
        _assert_same_dataset(got, want)
        _assert_same_dataset(lc.open_sweep(out), want)
        assert not partial.exists(), sorted(p.name for p in partial.iterdir())
        assert sorted(p.name for p in Path(tmp).iterdir()) == [out.name]


def _flip(f: Path) -> None:
    b = bytearray(f.read_bytes())
    b[len(b) // 2] ^= 0xFF
    f.write_bytes(bytes(b))


def _replace(f: Path, make) -> None:
    f.unlink()
    make(f)


#: Damage to block 1 of three kept (of nine): each is computed again (with a warning) or
#: refused naming it (``Partial.check`` reads every kept block whole before a run goes on).
DAMAGE = {
    "truncated": lambda f: f.write_bytes(f.read_bytes()[:100]),
    "empty": lambda f: f.write_bytes(b""),
    "a byte flipped": _flip,
    "garbage": lambda f: f.write_bytes(b"hello, not a block"),
    "another npz": lambda f: np.savez(f, x=np.arange(3)),
    "a directory": lambda f: _replace(f, lambda g: g.mkdir()),
    "a link to /dev/null": lambda f: _replace(f, lambda g: g.symlink_to("/dev/null")),
    "another block's copy": lambda f: shutil.copyfile(f.with_name("block-000000.npz"), f),
    "a block beyond the grid": lambda f: shutil.copyfile(f, f.with_name("block-000999.npz")),
    "a name not zero-padded": lambda f: shutil.copyfile(
        f.with_name("block-000000.npz"), f.with_name("block-5.npz")
    ),
    "a sub-directory": lambda f: (f.parent / "sub").mkdir(),
    "a stray temporary": lambda f: (f.parent / ".block-000004.npz.abc123.part").write_bytes(
        b"half a block"
    ),
}


@pytest.mark.parametrize("damage", list(DAMAGE))
@pytest.mark.filterwarnings("ignore:.*computed again:UserWarning")
def test_a_damaged_block_is_computed_again_or_refused_naming_it(tmp_path, damage):
    _xarray()
    out = tmp_path / "s.zarr"
    _keep("pulloff", out, [0, 1, 2])
    DAMAGE[damage](Path(f"{out}.partial") / "block-000001.npz")
    command, kw, chunk = RESUME["pulloff"]
    try:
        got = lc.sweep(command, output=out, chunk_points=chunk, **kw)
    except ValueError as exc:  # refused: said of the block or of the directory
        assert ".partial" in str(exc) or "block" in str(exc), exc
        return
    _assert_same_dataset(got, _reference("pulloff"))
    assert not Path(f"{out}.partial").exists()


# --------------------------------------------------------------------------------------------
# the command line of a sweep


SWEEP_COMMANDS = ["pulloff", "normal", "slide-init", "roll"]
NUMBERS = ["0.01", "0.1", "1", "10", "100", "1e-9", "5e-8", "1.2e11", "0.3", "3e-10", "-1", "0",
           "nan", "inf", "-inf", "1e400", "abc", "", "0.2", "-0.5", "2"]  # fmt: skip
BAD_RANGES = ["1:2:0", "1:2:-3", "1:2:2.5", "0:1:3:log", "-1:1:3:log", "a:b:c", "1:2", "1:2:3:4:5",
              "1e400:1:2", "nan:1:2", "1:inf:3", "::", "1:2:3:lin", "1:2:1e12",
              "1:2:99999999999999999999", "1:1e3:40000:log"]  # fmt: skip


@st.composite
def _flag_values(draw, action) -> tuple[list[str], int]:
    """Words for one flag and how many points they make (a refused word counts one)."""
    if action.nargs == 0:
        return [], 1
    many = action.nargs in ("+", "*")
    if action.choices:
        pool = [str(c) for c in action.choices if c != "lennard-jones"] + ["foo", ""]
        vals = draw(st.lists(st.sampled_from(pool), min_size=1, max_size=2 if many else 1))
        return vals, len(vals)
    if action.type not in (float, int):
        vals = draw(st.lists(st.sampled_from(["ZnO", "SiO2", "Si", "unobtainium", "", "-x"]),
                             min_size=1, max_size=2))  # fmt: skip
        return vals, len(vals)
    kind = draw(st.sampled_from(["one", "list", "range", "bad range"]))
    if kind == "range":
        a = draw(st.sampled_from(["0.01", "1", "10", "100", "1e-9", "-1", "0", "0.2"]))
        b = draw(st.sampled_from(["0.1", "1000", "1e-8", "2", "0", "0.5"]))
        n = draw(st.integers(1, 4))
        return [f"{a}:{b}:{n}" + draw(st.sampled_from(["", ":log"]))], n
    if kind == "bad range":
        return [draw(st.sampled_from(BAD_RANGES))], 1
    vals = draw(st.lists(st.sampled_from(NUMBERS), min_size=1, max_size=3 if kind == "list" else 1))
    return vals, len(vals)


#: A sweep each command runs, with values to choose from, before its flags are changed.
SWEEP_BASES = {
    "pulloff": {
        "--R-over-h": ["10", "100", "10:1000:3:log", "30", "300"],
        "--sigma0-over-E": ["0.01", "0.2", "0.01:0.2:2", "0"],
    },
    "normal": {
        "--R-over-h": ["100", "30", "100", "1000"],
        "--sigma0-over-E": ["0.2", "0.01", "0.05:0.2:2"],
        "--F-over-Eh": ["1", "-1:2:4", "-10", "0", "1"],
    },
    "slide-init": {
        "--a-over-R": ["0.05"],
        "--tau0-over-E": ["0.01", "0.001:0.01:3"],
        "--T-over-Ea": ["0.005", "0:0.02:4", "0.05"],
    },
    "roll": {
        "--R-over-h": ["100"],
        "--sigma0-over-E": ["0.02"],
        "--F-over-Eh": ["0", "1", "0:1:2"],
        "--tau0-over-E": ["0.005"],
        "--T-over-Ea": ["0:0.004:4", "0.002"],
    },
}
SWEEP_OWN = [["--chunk-points", "1"], ["--chunk-points", "3"], ["--chunk-points", "0"],
             ["--chunk-points", "1.5"], ["--chunk-points", "abc"], ["--chunk-points"],
             ["--overwrite"], ["--quiet"], ["--progress"], ["--no-progress"],
             ["--workers", "0"], ["--workers", "-2"], ["--workers=x"], ["--chunk-points=2"],
             ["--help"], ["-h"], ["--"]]  # fmt: skip
OUTPUTS = ["s.zarr", "s.nc", "s.nc4", "s.ZARR", "s.csv", "s", "no/such/dir/s.zarr", ".zarr"]


@settings(COSTLY, max_examples=max(3 * EXAMPLES // 2, 10))
@given(data=st.data())
def test_random_sweep_command_lines_exit_0_or_2_and_leave_nothing_on_error(data):
    _xarray()
    from linecontact.cli import build_parser

    command = data.draw(st.sampled_from(SWEEP_COMMANDS), label="command")
    sub = build_parser([command]).get_default("_subparsers").choices[command]
    actions = {
        f: a
        for f, a in sub._option_string_actions.items()
        if f.startswith("--") and f not in ("--help", "--output")
    }
    words: list[str] = []
    points = 1
    if data.draw(st.integers(0, 9), label="base") < 7:  # a sweep that runs, then changed
        for f, good in SWEEP_BASES[command].items():
            if data.draw(st.integers(0, 9), label=f"keep {f}") == 0:
                continue  # left out
            if data.draw(st.integers(0, 4), label=f"change {f}") == 0:
                vals, n = data.draw(_flag_values(actions[f]), label=f)
            else:
                vals = [data.draw(st.sampled_from(good), label=f)]
                n = int(vals[0].split(":")[2]) if ":" in vals[0] else 1
            words += [f, *vals]
            points *= n
        extra = data.draw(st.lists(st.sampled_from(sorted(actions)), max_size=2), label="flags")
    else:
        extra = data.draw(st.lists(st.sampled_from(sorted(actions)), max_size=4), label="flags")
    for f in extra:
        vals, n = data.draw(_flag_values(actions[f]), label=f)
        words += [f, *vals]
        points *= n
    assume(points <= 24)  # a few dozen points at most: each draw stays cheap
    for own in data.draw(st.lists(st.sampled_from(SWEEP_OWN), max_size=2), label="own"):
        words[data.draw(st.integers(0, len(words)), label="at") : 0] = own
    name = data.draw(st.sampled_from(OUTPUTS), label="output")
    with tempfile.TemporaryDirectory() as tmp:
        cwd = os.getcwd()
        os.chdir(tmp)  # anything written by mistake lands here, and is seen
        try:
            argv = ["sweep", command, *words, "-o", os.path.join(tmp, name), "--workers", "1"]
            out, err = io.StringIO(), io.StringIO()
            with warnings.catch_warnings(), redirect_stdout(out), redirect_stderr(err):
                warnings.simplefilter("ignore")
                try:
                    code = main(argv)
                except SystemExit as e:  # argparse's own usage errors
                    code = e.code if isinstance(e.code, int) else 2
            left = sorted(p.name for p in Path(tmp).iterdir())
        finally:
            os.chdir(cwd)
    text = err.getvalue()
    event(f"exit status {code}")
    assert code in (0, 2), (argv, code, text)
    assert "Traceback" not in text and "internal error" not in text, (argv, text)
    assert out.getvalue() == "", (argv, out.getvalue()[:300])
    if code == 2:
        errors = [ln for ln in text.splitlines() if "error:" in ln]
        assert len(errors) == 1 and errors[0].startswith("linecontact sweep: error:"), (argv, text)
        assert text.rstrip().splitlines()[-1] == errors[0], (argv, text)
        assert left == [], (argv, left)  # nothing written, no blocks, no temporary
    else:
        store = Path(name).name
        assert left == [store], (argv, left)
        assert "wrote " in text or "--quiet" in words, (argv, text)


# ============================================================================================
# lc.read on truncated and hostile files


READ_COMMANDS = {
    "pulloff": ["pulloff", "--R-over-h", "100", "--sigma0-over-E", "0.01"],
    # a load below the pull-off: nulls, a reason
    "normal": [
        "normal",
        "--R-over-h",
        "100",
        "--sigma0-over-E",
        "0.2",
        "--F-over-Eh",
        "-10",
        "-1",
        "0",
        "1",
    ],  # fmt: skip
    "curve": ["curve", "--R-over-h", "100", "--sigma0-over-E", "0.05", "--num", "30"],
    # per-point lists (quoted JSON text in CSV)
    "history": ["history", "--tau0-over-E", "0.01", "--T-over-Ea", "0.016", "-0.008", "0.004"],
}
READ_FORMATS = {
    "csv": ("csv", []),
    "json": ("json", []),
    "json-indented": ("json", ["--indent", "2"]),
    "jsonl": ("jsonl", []),
}


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    """Each command's file in each format, and what lc.read gives for it."""
    pytest.importorskip("pandas")
    from linecontact.reading import read

    tmp = tmp_path_factory.mktemp("read")
    out = {}
    for name, args in READ_COMMANDS.items():
        for fmt, (ext, extra) in READ_FORMATS.items():
            path = tmp / f"{name}-{fmt}.{ext}"
            with warnings.catch_warnings(), redirect_stderr(io.StringIO()):
                warnings.simplefilter("ignore")
                assert main([*args, "--quiet", *extra, "-o", str(path)]) == 0
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                out[name, fmt] = (path.read_bytes(), read(path), ext)
    return out


def _read(path: Path):
    """lc.read's DataFrame, or None where it refuses with a ValueError naming the file.

    Any other exception propagates (the oracle: never another type).
    """
    from linecontact.reading import read

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return read(path)
    except ValueError as exc:
        assert str(path) in str(exc), f"a ValueError that does not name the file: {exc}"
        return None


def _missing(v) -> bool:
    return v is None or (isinstance(v, float | np.floating) and math.isnan(v))


def _cell_same(a, b) -> bool:
    if _missing(b):
        return _missing(a)
    if isinstance(a, list) or isinstance(b, list):
        return isinstance(a, list) and isinstance(b, list) and a == b
    return bool(a == b)


def _equal(df, ref) -> bool:
    import pandas as pd

    try:
        pd.testing.assert_frame_equal(df, ref, check_exact=True)
    except AssertionError:
        return False
    return df.attrs == ref.attrs


def _row_prefix(df, ref) -> bool:
    """``df`` holds the first rows of ``ref``, each with the same values (dtypes aside)."""
    if len(df) == 0 and list(df.columns) == []:  # JSON Lines without a record: no columns
        return True
    if list(df.columns) != list(ref.columns) or len(df) > len(ref):
        return False
    return all(
        _cell_same(df[k].iloc[i], ref[k].iloc[i]) for k in ref.columns for i in range(len(df))
    )


def _cuts(data: bytes, where: str, rng) -> list[int]:
    """Offsets to cut ``data`` at: just after a line's end, or inside a line."""
    ends = [i + 1 for i, c in enumerate(data) if c == 0x0A and i + 1 < len(data)]
    if where == "line end":
        picked = set(ends[:3] + ends[-3:])
        picked |= set(rng.choice(ends, min(len(ends), 12 * SCALE), replace=False).tolist())
        return sorted(picked)
    inside = sorted(set(range(len(data))) - set(ends))
    picked = {len(data) - 1, 0, 1}  # the last newline alone; nothing; one byte
    picked |= set(rng.choice(inside, min(len(inside), 40 * SCALE), replace=False).tolist())
    return sorted(picked)


@pytest.mark.parametrize(
    ("fmt", "where"),
    [
        ("csv", "line end"),
        ("csv", "inside a line"),
        ("json", "inside a line"),  # compact: one line
        ("json-indented", "line end"),
        ("json-indented", "inside a line"),
        ("jsonl", "line end"),
        ("jsonl", "inside a line"),
    ],
)
def test_a_truncated_file_is_refused_or_its_first_rows(written, tmp_path, fmt, where):
    rng = np.random.default_rng(30)
    bad = []
    for name in READ_COMMANDS:
        data, ref, ext = written[name, fmt]
        cuts = _cuts(data, where, rng)
        assert cuts
        for cut in cuts:
            path = tmp_path / f"cut.{ext}"
            path.write_bytes(data[:cut])
            df = _read(path)
            if df is None:
                continue
            whole = data[cut:].strip() == b""  # only the last line end cut
            if whole and _equal(df, ref):
                continue
            if ext == "json":  # a JSON document cut is no JSON: refused, always
                bad.append((name, cut, "read"))
            elif not _row_prefix(df, ref):
                bad.append((name, cut, f"{len(df)} rows, not the first of {len(ref)}"))
    assert not bad, bad[:10]


@pytest.mark.parametrize("fmt", sorted(READ_FORMATS))
def test_flipped_bytes_are_read_or_refused_naming_the_file(written, tmp_path, fmt):
    """A flipped byte (no checksum: a digit may change unseen) is never another exception."""
    rng = np.random.default_rng(31)
    for name in READ_COMMANDS:
        data, ref, ext = written[name, fmt]
        for _ in range(25 * SCALE):
            b = bytearray(data)
            at = int(rng.integers(len(b)))
            b[at] ^= int(rng.integers(1, 256))
            path = tmp_path / f"flip.{ext}"
            path.write_bytes(bytes(b))
            df = _read(path)
            if df is not None and not bytes(b).isascii() and data.isascii():
                pytest.fail(f"{name} {fmt}: a byte not UTF-8 at {at} read as a DataFrame")


TEN_MB = 10 * 1024 * 1024


def _deep(data: bytes, ext: str) -> bytes:
    """``data`` with a value nested 50,000 lists deep in its first record."""
    deep = b"[" * 50_000 + b"]" * 50_000
    if ext == "csv":
        lines = data.split(b"\n")
        i = next(k for k, ln in enumerate(lines) if not ln.startswith(b"#")) + 1
        lines[i] = deep + lines[i][lines[i].index(b",") :]
        return b"\n".join(lines)
    if ext == "jsonl":
        first, sep, rest = data.partition(b"\n")
        return first + sep + b'{"deep":' + deep + b"," + rest[1:]
    return re.sub(rb'"results":\s*\[\s*\{', lambda m: m.group(0) + b'"deep":' + deep + b",",
                  data, count=1)  # fmt: skip


def _huge_int(data: bytes, ext: str) -> bytes:
    """``data`` with a 5,000-digit integer as a value of its first record."""
    big = b"7" * 5000
    if ext == "csv":
        lines = data.split(b"\n")
        i = next(k for k, ln in enumerate(lines) if not ln.startswith(b"#")) + 1
        lines[i] = big + lines[i][lines[i].index(b",") :]
        return b"\n".join(lines)
    if ext == "jsonl":
        first, sep, rest = data.partition(b"\n")
        return first + sep + b'{"big":' + big + b"," + rest[1:]
    return re.sub(rb'"results":\s*\[\s*\{', lambda m: m.group(0) + b'"big":' + big + b",",
                  data, count=1)  # fmt: skip


def _dup_column(data: bytes, ext: str) -> bytes:
    """A CSV whose header names its second column as its first."""
    lines = data.split(b"\n")
    i = next(k for k, ln in enumerate(lines) if not ln.startswith(b"#"))
    cols = lines[i].split(b",")
    lines[i] = b",".join([cols[0], cols[0], *cols[2:]])
    return b"\n".join(lines)


#: name -> (the file from the original's bytes and extension, what lc.read must do):
#: "equal" (the same DataFrame), "refused" (a ValueError naming the file), "either",
#: "read or refused" (any DataFrame, or that ValueError).
HOSTILE = {
    "a byte-order mark": (lambda d, e: b"\xef\xbb\xbf" + d, "equal"),
    "CRLF line ends": (lambda d, e: d.replace(b"\n", b"\r\n"), "equal"),
    "CR line ends": (lambda d, e: d.replace(b"\n", b"\r"), "either"),
    "empty": (lambda d, e: b"", "refused"),
    "NUL bytes": (lambda d, e: b"\x00" * 1000, "refused"),
    "binary": (
        lambda d, e: bytes(np.random.default_rng(32).integers(0, 256, 4096).astype(np.uint8)),
        "refused",
    ),  # fmt: skip
    "junk appended": (lambda d, e: d + b"garbage ; { [ \x01", "refused"),
    "blank lines appended": (lambda d, e: d + b"\n\n   \n", "either"),
    "a 10 MB line appended": (lambda d, e: d + b"x" * TEN_MB + b"\n", "refused"),
    "a 10 MB file of one line": (lambda d, e: b"1" * TEN_MB, "refused"),
    "nested 50,000 deep": (_deep, "read or refused"),
    "a 5,000-digit integer": (_huge_int, "read or refused"),
    "a header naming a column twice": (_dup_column, "refused"),
}

_XFAIL: dict[tuple[str, str], str] = {}  # (case, format): a fault not yet fixed


def _hostile_cases():
    for case in HOSTILE:
        for fmt in sorted(READ_FORMATS):
            if case == "a header naming a column twice" and fmt != "csv":
                continue
            why = _XFAIL.get((case, fmt))
            marks = [pytest.mark.xfail(strict=True, reason=why)] if why else []
            yield pytest.param(case, fmt, marks=marks, id=f"{case}-{fmt}")


@pytest.mark.parametrize(("case", "fmt"), list(_hostile_cases()))
def test_a_hostile_file_is_read_as_the_original_or_refused(written, tmp_path, case, fmt):
    make, want = HOSTILE[case]
    for name in ("normal", "history"):
        data, ref, ext = written[name, fmt]
        path = tmp_path / f"hostile.{ext}"
        path.write_bytes(make(data, ext))
        df = _read(path)
        if want == "equal":
            assert df is not None and _equal(df, ref), (name, case)
        elif want == "refused":
            assert df is None, (name, case, None if df is None else df.head())
        elif want == "either":
            assert df is None or _equal(df, ref), (name, case)
