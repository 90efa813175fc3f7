"""The web calculator under abuse (issue 30): it stays fair and says why it refuses.

Bounded workers; requests over their points or their result's bytes refused before they cost;
a job store bounded in size and age whose documents are never parsed again; cancellation that
stops queued and running jobs; a worker killed from outside reported as such and replaced;
the computations' directories removed however they end; Host and Origin checked; every
malformed body a JSON error with the security headers; ``serve`` saying its URL once it
answers, and one ``error:`` line for a port in use.
"""

from __future__ import annotations

import http.client
import json
import multiprocessing as mp
import os
import signal
import socket
import subprocess
import sys
import threading
import time
import types
import urllib.request
import warnings
from pathlib import Path

import pytest

pytest.importorskip("starlette")
pytest.importorskip("httpx")
with warnings.catch_warnings():
    warnings.simplefilter("ignore")  # starlette's note on httpx versions
    from starlette.testclient import TestClient

from linecontact.cli import main  # noqa: E402
from linecontact.web import _app, create_app  # noqa: E402
from linecontact.web._workers import Pool, compute, max_workers  # noqa: E402

WIRE = "radius=50e-9&modulus=1.2e11&work_of_adhesion=0.3&z0=3e-10"
BASE = "http://127.0.0.1:8000"
MILLION = "R_over_h=100&sigma0_over_E=0.01&a_over_R_range=0.001,0.1,1000000"


def _security(r) -> None:
    """A JSON error of the API's shape, with the security headers."""
    assert r.headers["content-type"].startswith("application/json"), r.text
    err = r.json()["error"]
    assert set(err) == {"parameter", "message"} and err["message"]
    assert "script-src 'self'" in r.headers["content-security-policy"]
    assert r.headers["x-content-type-options"] == "nosniff"
    assert r.headers["x-frame-options"] == "DENY"
    assert "Traceback" not in r.text


def _wait(cond, what: str, tries: int = 600, pause: float = 0.1):
    """Wait for ``cond()`` to be true (a bounded wait, not a timed assertion)."""
    for _ in range(tries):
        got = cond()
        if got:
            return got
        time.sleep(pause)
    raise AssertionError(f"never: {what}")


def _job(c, job_id: str) -> dict:
    return c.get(f"/api/v1/jobs/id/{job_id}").json()


def _ended(c, job_id: str) -> dict:
    return _wait(
        lambda: (d := _job(c, job_id))["state"] not in ("queued", "running") and d,
        f"job {job_id} ended",
    )


def _cpu(pid: int) -> int:
    """CPU ticks of process ``pid`` so far (0 once it is gone)."""
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    except OSError:
        return 0
    return int(fields[11]) + int(fields[12])


def _dead(pid: int) -> bool:
    """Whether process ``pid`` has ended (a zombie, or reaped)."""
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0] in "ZX"
    except OSError:
        return True


def _busy(pids: list[int]) -> int:
    """The one of ``pids`` that computes: its CPU time grows (the idle ones' does not)."""
    start = {p: _cpu(p) for p in pids}
    return _wait(
        lambda: next((p for p in pids if _cpu(p) - start[p] >= 20), None),
        "a worker computing",
    )


@pytest.fixture
def app_client():
    """A fresh app (its own workers) and its client, and the pids of its workers."""
    made = []

    def make(**kw):
        before = {p.pid for p in mp.active_children()}
        app = create_app(**{"workers": 2, "time_limit": 60, **kw})
        c = TestClient(app, base_url=BASE)
        c.__enter__()
        made.append(c)
        pids = lambda: sorted(p.pid for p in mp.active_children() if p.pid not in before)  # noqa: E731
        return app, c, pids

    yield make
    for c in made:
        c.__exit__(None, None, None)


# ------------------------------------------------------------------------------------------
# bounded workers


def test_workers_above_the_ceiling_are_refused(capsys):
    top = max_workers()
    assert top == max(4, 2 * len(os.sched_getaffinity(0)))
    with pytest.raises(ValueError, match="workers must be an integer from 2"):
        create_app(workers=top + 1)
    with pytest.raises(ValueError, match="workers"):
        Pool(1)
    assert main(["serve", "--workers", str(top + 1)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "error: --workers must be from 2" in err and str(top) in err
    with pytest.raises(SystemExit):
        main(["serve", "--help"])
    assert "twice the CPUs" in " ".join(capsys.readouterr().out.split())


# ------------------------------------------------------------------------------------------
# points and bytes


@pytest.mark.parametrize(
    ("method", "path", "kw", "parameter", "size", "hint"),
    [
        ("get", f"/api/v1/normal?{MILLION}", {}, "a_over_R_range", "1,000,000", "sweep normal"),
        (
            "post",
            "/api/v1/normal",
            {"json": {"R_over_h": 100, "sigma0_over_E": 0.01, "F_over_Eh": [1] * 20000}},
            "F_over_Eh",
            "20,000",
            "sweep normal",
        ),
        ("get", "/api/v1/curve?R_over_h=100&sigma0_over_E=0.05&num=100000", {}, "num", "100,040",
         "sweep curve"),
        ("get", "/api/v1/map?n_y=1000", {}, "n_y", "17,000", "linecontact map"),
        ("post", f"/api/v1/jobs/normal?{MILLION}", {}, "a_over_R_range", "1,000,000", "sweep"),
    ],
)  # fmt: skip
def test_a_request_over_its_points_is_refused_before_it_is_computed(
    app_client, method, path, kw, parameter, size, hint
):
    app, c, _ = app_client()
    r = getattr(c, method)(path, **kw)
    assert r.status_code == 413, r.text
    _security(r)
    err = r.json()["error"]
    assert err["parameter"] == parameter
    assert size in err["message"] and "10,000" in err["message"] and hint in err["message"]
    assert app.pool.started == 0  # no worker saw it
    ok = c.get("/api/v1/normal?R_over_h=100&sigma0_over_E=0.01&a_over_R_range=0.001,0.1,10000")
    assert ok.status_code == 200 and len(ok.json()["results"]) == 10_000  # the limit itself
    spec = c.get("/api/v1/openapi.json").json()
    assert spec["info"]["x-limits"]["max_points"] == 10_000
    assert "413" in spec["paths"]["/api/v1/normal"]["get"]["responses"]


def test_a_result_over_its_bytes_is_refused_not_shipped(app_client):
    app, c, _ = app_client(max_result_bytes=20_000)
    r = c.get("/api/v1/normal?R_over_h=100&sigma0_over_E=0.01&a_over_R_range=0.001,0.1,100")
    assert r.status_code == 413
    _security(r)
    message = r.json()["error"]["message"]
    assert "20,000 bytes" in message and "fewer points" in message and "sweep" in message
    assert c.get(f"/api/v1/pulloff?{WIRE}").status_code == 200  # a small one still goes
    values = {"R_over_h": 100.0, "sigma0_over_E": 0.01, "F_over_Eh": [1.0, 2.0]}
    assert compute("normal", values).status == 200
    assert compute("normal", values, max_bytes=100).status == 413


# ------------------------------------------------------------------------------------------
# the job store


def test_finished_jobs_are_evicted_oldest_first_and_a_running_one_never(app_client):
    _, c, _ = app_client(max_jobs=2)
    first = c.post(f"/api/v1/jobs/pulloff?{WIRE}").json()["id"]
    assert _ended(c, first)["state"] == "done"
    second = c.post(f"/api/v1/jobs/pulloff?{WIRE}").json()["id"]
    assert _ended(c, second)["state"] == "done"
    third = c.post("/api/v1/jobs/map?quick=true")  # the oldest finished one goes
    assert third.status_code == 202
    gone = c.get(f"/api/v1/jobs/id/{first}")
    assert gone.status_code == 404
    _security(gone)
    assert "expired" in gone.json()["error"]["message"]
    assert "never existed" in gone.json()["error"]["message"]
    assert _job(c, second)["state"] == "done"
    running = c.post("/api/v1/jobs/map?quick=true")  # evicts the second; two in progress
    assert running.status_code == 202
    full = c.post(f"/api/v1/jobs/pulloff?{WIRE}")  # nothing finished to evict
    assert full.status_code == 503 and "in progress" in full.json()["error"]["message"]
    _security(full)
    for job in (third.json()["id"], running.json()["id"]):
        assert _job(c, job)["state"] in ("queued", "running")  # never evicted
        c.delete(f"/api/v1/jobs/id/{job}")


def test_finished_jobs_expire(app_client):
    _, c, _ = app_client(job_max_age=0.5)
    job = c.post(f"/api/v1/jobs/pulloff?{WIRE}").json()["id"]
    assert _ended(c, job)["state"] == "done"
    time.sleep(0.6)  # past its age
    r = c.get(f"/api/v1/jobs/id/{job}")
    assert r.status_code == 404 and "expired" in r.json()["error"]["message"]


def test_a_finished_job_is_not_parsed_again_and_its_time_stops(app_client, monkeypatch):
    _, c, _ = app_client()
    q = "R_over_h=100&sigma0_over_E=0.01&a_over_R_range=0.001,0.1,2000"
    want = c.get(f"/api/v1/normal?{q}").json()
    job = c.post(f"/api/v1/jobs/normal?{q}").json()["id"]
    first = _ended(c, job)
    # the application's json has no loads: a GET that parsed the result would fail
    monkeypatch.setattr(_app, "json", types.SimpleNamespace(dumps=json.dumps))
    time.sleep(0.3)
    again = c.get(f"/api/v1/jobs/id/{job}")
    assert again.status_code == 200
    doc = again.json()
    assert doc["state"] == "done" and doc["status"] == 200
    assert doc["elapsed_s"] == first["elapsed_s"]  # it stopped when the job ended
    assert doc["result"]["results"] == want["results"]


# ------------------------------------------------------------------------------------------
# cancellation, dead workers, temporary directories


def test_a_queued_job_cancelled_never_runs(app_client):
    app, c, _ = app_client()
    running = c.post("/api/v1/jobs/map?quick=true").json()["id"]  # the one slow worker
    _wait(lambda: _job(c, running)["state"] == "running", "the first map running")
    queued = c.post("/api/v1/jobs/map?quick=true").json()["id"]
    assert _job(c, queued)["state"] == "queued"
    started = app.pool.started
    cancelled = c.delete(f"/api/v1/jobs/id/{queued}").json()
    assert cancelled["state"] == "cancelled" and cancelled["status"] == 499
    c.delete(f"/api/v1/jobs/id/{running}")  # its slot frees: the cancelled one must not take it
    assert c.get(f"/api/v1/pulloff?{WIRE}").status_code == 200
    big = c.get("/api/v1/normal?R_over_h=100&sigma0_over_E=0.01&a_over_R_range=0.001,0.1,2000")
    assert big.status_code == 200  # a slow worker again (2,000 points)
    assert app.pool.started == started + 2  # those two: never the cancelled job
    doc = _job(c, queued)
    assert doc["state"] == "cancelled" and "progress" not in doc
    assert doc["elapsed_s"] == cancelled["elapsed_s"]


def test_a_running_job_cancelled_ends_its_worker_and_its_directory(app_client):
    app, c, pids = app_client()
    workers = pids()
    job = c.post("/api/v1/jobs/map?quick=true").json()["id"]
    _wait(lambda: "progress" in _job(c, job), "the map reporting")
    root = Path(app.pool.root)
    assert any(root.rglob("*")), "the map writes into its directory"
    busy = _busy(workers)
    doc = c.delete(f"/api/v1/jobs/id/{job}").json()
    assert doc["state"] == "cancelled" and doc["status"] == 499
    _wait(lambda: not Path(f"/proc/{busy}").exists(), "its worker ended")
    _wait(lambda: not any(root.iterdir()), "its directory removed")
    assert busy not in pids() and len(pids()) == 2  # replaced
    assert c.get(f"/api/v1/pulloff?{WIRE}").status_code == 200


@pytest.mark.parametrize("ending", ["done", "timed out", "worker killed"])
def test_the_map_leaves_no_directory_however_it_ends(app_client, ending):
    app, c, pids = app_client(time_limit=1.0 if ending == "timed out" else 60)
    workers = pids()
    job = c.post("/api/v1/jobs/map?quick=true").json()["id"]
    root = Path(app.pool.root)
    if ending == "worker killed":
        _wait(lambda: "progress" in _job(c, job), "the map reporting")
        os.kill(_busy(workers), signal.SIGKILL)
    doc = _ended(c, job)
    want = {"done": 200, "timed out": 504, "worker killed": 500}[ending]
    assert doc["status"] == want, doc
    _wait(lambda: not any(root.iterdir()), "the map's directory removed")
    assert c.get(f"/api/v1/pulloff?{WIRE}").status_code == 200


def test_the_server_removes_its_directory_when_it_stops():
    with TestClient(create_app(workers=2), base_url=BASE) as c:
        root = Path(c.app.pool.root)
        assert root.is_dir() and c.get(f"/api/v1/pulloff?{WIRE}").status_code == 200
    assert not root.exists()


def test_a_worker_killed_mid_computation_is_a_500_naming_it_and_is_replaced(app_client):
    _, c, pids = app_client()
    workers = pids()
    got: dict = {}

    def slow_request() -> None:
        got["r"] = c.get("/api/v1/map?quick=true")

    t = threading.Thread(target=slow_request)
    t.start()
    busy = _busy(workers)
    os.kill(busy, signal.SIGKILL)
    t.join(120)
    r = got["r"]
    assert r.status_code == 500, r.text
    _security(r)
    message = r.json()["error"]["message"]
    assert "ended unexpectedly" in message and "signal 9" in message and "replaced" in message
    assert c.get(f"/api/v1/pulloff?{WIRE}").status_code == 200  # the next one succeeds
    _wait(lambda: busy not in pids() and len(pids()) == 2, "the worker replaced")
    idle = [p for p in pids() if p != busy]
    os.kill(idle[0], signal.SIGKILL)  # killed while idle: the next request takes a new one
    _wait(lambda: _dead(idle[0]), "the idle worker gone")
    for _ in range(3):
        assert c.get(f"/api/v1/pulloff?{WIRE}").status_code == 200


# ------------------------------------------------------------------------------------------
# Host, Origin and bodies


@pytest.mark.parametrize(
    ("method", "headers", "status"),
    [
        ("post", {"origin": "http://evil.example"}, 403),
        ("post", {"origin": "null"}, 403),
        ("post", {"origin": "http://127.0.0.1:9999"}, 403),  # another port: another origin
        ("post", {"origin": "https://127.0.0.1:8000"}, 403),
        ("post", {"sec-fetch-site": "cross-site"}, 403),
        ("post", {"host": "evil.example"}, 403),  # DNS rebinding
        ("get", {"host": "evil.example:8000"}, 403),
        ("get", {"host": "127.0.0.1.evil.example"}, 403),
        ("post", {"origin": BASE}, 200),
        ("post", {"origin": BASE, "sec-fetch-site": "same-origin"}, 200),
        ("post", {}, 200),  # not from a browser: no Origin
        ("post", {"host": "localhost:8000", "origin": "http://localhost:8000"}, 200),
        ("get", {"host": "[::1]:8000"}, 200),
        ("get", {"host": "127.0.0.2"}, 200),
    ],
)
def test_host_and_origin_are_checked(app_client, method, headers, status):
    _, c, _ = app_client()
    if method == "get":
        r = c.get(f"/api/v1/pulloff?{WIRE}", headers=headers)
    else:
        doc = {"radius": 5e-8, "modulus": 1.2e11, "work_of_adhesion": 0.3, "z0": 3e-10}
        r = c.post("/api/v1/pulloff", json=doc, headers=headers)
    assert r.status_code == status, r.text
    if status == 403:
        _security(r)
        assert r.json()["error"]["parameter"] in ("Host", "Origin")


def test_a_job_is_not_cancelled_from_another_site(app_client):
    _, c, _ = app_client()
    job = c.post("/api/v1/jobs/map?quick=true").json()["id"]
    r = c.delete(f"/api/v1/jobs/id/{job}", headers={"origin": "http://evil.example"})
    assert r.status_code == 403
    _security(r)
    assert _job(c, job)["state"] in ("queued", "running")
    assert c.delete(f"/api/v1/jobs/id/{job}", headers={"origin": BASE}).json()["state"] == (
        "cancelled"
    )
    r = c.post(f"/api/v1/jobs/pulloff?{WIRE}", headers={"origin": "http://evil.example"})
    assert r.status_code == 403


def test_a_server_on_every_address_takes_ip_addresses_not_other_names(app_client):
    _, c, _ = app_client(host="0.0.0.0")
    assert c.get(f"/api/v1/pulloff?{WIRE}", headers={"host": "192.0.2.7:8000"}).status_code == 200
    assert c.get(f"/api/v1/pulloff?{WIRE}", headers={"host": "evil.example"}).status_code == 403


def _chunks(n: int = 16, size: int = 8192):
    for _ in range(n):
        yield b"x" * size


@pytest.mark.parametrize(
    ("content", "ctype", "status", "words"),
    [
        (b"{" + b" " * 70000 + b"}", "application/json", 413, "65,536"),  # Content-Length
        (_chunks, "application/json", 413, "over the limit"),  # chunked, no length
        (b"[" * 50000 + b"]" * 50000, "application/json", 413, "over"),  # over the limit too
        (b'{"a":' * 5000 + b"1" + b"}" * 5000, "application/json", 400, "nested too deeply"),
        (b"\xff\xfe\x00{", "application/json", 400, "UTF-8"),
        (b"{radius: 1}", "application/json", 400, "not JSON"),
        (b'{"radius": {"a": 1}}', "application/json", 422, "radius"),
        (b'{"radius": null}', "application/json", 422, "null"),
        (b"[1, 2]", "application/json", 422, "object"),
        (b"radius=1", "text/plain", 415, "text/plain"),
        (b"<radius>1</radius>", "application/xml", 415, "application/json"),
        (b"--xx\r\nbad", "multipart/form-data", 400, "malformed"),  # no boundary
        (b"garbage", "multipart/form-data; boundary=xx", 400, "malformed"),
        (b"&".join(b"a%d=1" % i for i in range(2000)), "application/x-www-form-urlencoded",
         400, "fields"),
    ],
)  # fmt: skip
def test_every_bad_body_is_a_json_error(client, content, ctype, status, words):
    body = content() if callable(content) else content
    r = client.post("/api/v1/pulloff", content=body, headers={"content-type": ctype})
    assert r.status_code == status, r.text
    _security(r)
    assert words in r.json()["error"]["message"]


@pytest.fixture(scope="module")
def client():
    with TestClient(create_app(workers=2, time_limit=60), base_url=BASE) as c:
        yield c


def test_other_errors_are_json_too(client):
    for r, status in (
        (client.get("/api/v2/normal"), 404),
        (client.put("/api/v1/normal"), 405),
        (client.get("/static/nothing.js"), 404),
        (client.get("/api/v1/jobs/id/0123"), 404),
        (client.get("/api/v1/paper"), 404),
    ):
        assert r.status_code == status
        _security(r)


# ------------------------------------------------------------------------------------------
# a real server


def _serve(*args: str) -> tuple[subprocess.Popen, str]:
    """``linecontact serve --port 0 ARGS`` and its URL, read from its first line."""
    env = {**os.environ, "OPENBLAS_NUM_THREADS": "1"}
    proc = subprocess.Popen(
        [sys.executable, "-m", "linecontact", "serve", "--port", "0", *args],
        env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
    )  # fmt: skip
    assert proc.stderr is not None
    line = proc.stderr.readline()
    assert "http://" in line, line
    return proc, line.split()[2].rstrip("/")


@pytest.fixture(scope="module")
def server():
    proc, url = _serve()
    yield url
    proc.terminate()
    proc.wait(30)


def test_serve_says_its_url_once_it_answers():
    proc, url = _serve()
    try:
        # no retry: the URL is printed once the port is bound and the workers are up
        with urllib.request.urlopen(f"{url}/api/v1/pulloff?{WIRE}", timeout=60) as r:
            assert r.status == 200
        assert url.startswith("http://127.0.0.1:") and not url.endswith(":0")
    finally:
        proc.terminate()
        proc.wait(30)


def test_a_port_in_use_is_one_error_line():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        s.listen()
        port = s.getsockname()[1]
        p = subprocess.run(
            [sys.executable, "-m", "linecontact", "serve", "--port", str(port)],
            capture_output=True, text=True, timeout=120,
        )  # fmt: skip
    assert p.returncode == 2, p.stderr
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("linecontact serve: error: ")
    assert str(port) in lines[0] and "in use" in lines[0] and "http://" not in p.stderr


def test_an_oversized_chunked_body_is_a_413_on_the_wire(server):
    host, port = server.removeprefix("http://").split(":")
    conn = http.client.HTTPConnection(host, int(port), timeout=60)
    conn.request(
        "POST", "/api/v1/pulloff", body=_chunks(32), encode_chunked=True,
        headers={"Content-Type": "application/json", "Transfer-Encoding": "chunked"},
    )  # fmt: skip
    r = conn.getresponse()
    body = r.read()
    conn.close()
    assert r.status == 413 and r.getheader("Content-Type") == "application/json"
    assert r.getheader("X-Frame-Options") == "DENY"
    assert "over the limit" in json.loads(body)["error"]["message"]


def test_a_rebinding_host_is_refused_on_the_wire(server):
    host, port = server.removeprefix("http://").split(":")
    conn = http.client.HTTPConnection(host, int(port), timeout=60)
    conn.request("POST", f"/api/v1/jobs/pulloff?{WIRE}", headers={"Host": f"evil.example:{port}"})
    r = conn.getresponse()
    doc = json.loads(r.read())
    conn.close()
    assert r.status == 403 and doc["error"]["parameter"] == "Host"


def test_a_million_points_are_refused_on_the_wire(server):
    try:
        urllib.request.urlopen(f"{server}/api/v1/normal?{MILLION}", timeout=60)
    except urllib.error.HTTPError as exc:
        doc = json.loads(exc.read())
        assert exc.code == 413 and "1,000,000 points" in doc["error"]["message"]
    else:
        raise AssertionError("a million points were computed")


@pytest.mark.parametrize(
    "request_bytes",
    [
        b"GET /api/v1/normal?F_over_Eh=" + b"1," * 50000 + b"1 HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n",
        b"GARBAGE\r\n\r\n",
        b"POST /api/v1/pulloff HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: x\r\n\r\n",
    ],
    ids=["a URL over 16 KiB", "no request line", "a Content-Length that is no number"],
)
def test_a_request_http_cannot_parse_is_a_json_400(server, request_bytes):
    host, port = server.removeprefix("http://").split(":")
    with socket.create_connection((host, int(port)), timeout=60) as s:
        s.sendall(request_bytes)
        data = b""
        while chunk := s.recv(65536):
            data += chunk
    head, _, body = data.partition(b"\r\n\r\n")
    assert b"content-type: application/json" in head.lower()
    assert b"x-frame-options: deny" in head.lower()
    message = json.loads(body)["error"]["message"]
    if head.startswith(b"HTTP/1.1 413"):  # the long URL read at once: its 50,001 points
        assert b"F_over_Eh" in request_bytes and "50,001 points" in message
    else:
        assert head.startswith(b"HTTP/1.1 400"), head
        assert message.startswith("a malformed HTTP request")
