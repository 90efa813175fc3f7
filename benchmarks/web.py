"""The calculator's API under load and under abuse, on a real server on loopback.

    python benchmarks/web.py [--only load,fair,lookups] [--requests 500] [--clients 20]
                             [--workers 2] [--rounds 10] [--lookups 200]

Starts ``linecontact serve`` on a free loopback port (``--workers`` processes) and runs:

1. ``load`` (issue 24): one slow request (the quick adhesion map, a few seconds, through the
   jobs API), then ``--requests`` GET ``/api/v1/pulloff`` requests (a nanowire, the radius
   varied) from ``--clients`` concurrent clients (threads); it prints the throughput, the
   median and 95th percentile latency, and the errors (zero). A slow computation may hold
   all but one worker, so the quick requests keep going while it runs.
2. ``fair`` (issue 30): two requests of ``normal`` over 1,000,000 points (``a_over_R_range=
   0.001,0.1,1000000``: the fuzz's request, 297 MB of JSON before the limit) and a quick
   pull-off in flight together, ``--rounds`` times; it prints what the big requests got
   (status, bytes, seconds) and the pull-off's latency (target: under 1 s). Then the same
   with two requests at the limit, 10,000 points (about 3 MB each, computed).
3. ``lookups`` (issue 30): a finished job of 10,000 points (3 MB of result), read back
   ``--lookups`` times by 4 clients while pull-offs go on: the lookups are the document
   written once when the job ended (never parsed again), so the pull-offs do not wait.

Everything goes to 127.0.0.1, bounded in count (``--requests``, ``--rounds``, ``--lookups``)
and time (60 s a request). Run with one BLAS thread on an idle machine: a shared 2-core
machine slows every figure.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import os
import statistics
import subprocess
import sys
import threading
import time
import urllib.error
import urllib.request
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor

WIRE = "modulus=1.2e11&work_of_adhesion=0.3&z0=3e-10"
MILLION = "R_over_h=100&sigma0_over_E=0.01&a_over_R_range=0.001,0.1,1000000"
AT_LIMIT = "R_over_h=100&sigma0_over_E=0.01&a_over_R_range=0.001,0.1,10000"


@contextlib.contextmanager
def serve(workers: int) -> Iterator[str]:
    """``linecontact serve --port 0`` and its URL (said once it answers)."""
    env = {**os.environ, "OPENBLAS_NUM_THREADS": "1"}
    cmd = [sys.executable, "-m", "linecontact", "serve", "--port", "0", "--workers", str(workers)]
    proc = subprocess.Popen(cmd, env=env, stderr=subprocess.PIPE, text=True)
    try:
        assert proc.stderr is not None
        line = proc.stderr.readline()
        if "http://" not in line:
            raise SystemExit(f"the server did not start: {line}{proc.stderr.read()}")
        threading.Thread(target=proc.stderr.read, daemon=True).start()  # drain it
        yield line.split()[2].rstrip("/")
    finally:
        proc.terminate()
        proc.wait(30)


def get(url: str) -> tuple[float, int, int]:
    """Seconds, status and bytes of a GET."""
    t = time.perf_counter()
    try:
        with urllib.request.urlopen(url, timeout=60) as resp:
            n = len(resp.read())
            code = resp.status
    except urllib.error.HTTPError as exc:
        n = len(exc.read())
        code = exc.code
    except OSError:
        n, code = 0, 0
    return time.perf_counter() - t, code, n


def load(url: str, requests: int, clients: int, workers: int) -> None:
    req = urllib.request.Request(url + "/api/v1/jobs/map?quick=true", method="POST")
    job = json.load(urllib.request.urlopen(req))

    def one(i: int) -> tuple[float, int, int]:
        return get(f"{url}/api/v1/pulloff?radius={20e-9 * (1 + i % 50)!r}&{WIRE}")

    t0 = time.perf_counter()
    with ThreadPoolExecutor(clients) as ex:
        out = list(ex.map(one, range(requests)))
    wall = time.perf_counter() - t0
    state = json.load(urllib.request.urlopen(f"{url}/api/v1/jobs/id/{job['id']}"))
    lat = sorted(t for t, _, _ in out)
    errors = sum(1 for _, c, _ in out if c != 200)
    p95 = lat[int(0.95 * (len(lat) - 1))]
    print(
        f"load: {requests} requests from {clients} clients, {workers} workers, the quick map "
        f"in flight (its state after: {state['state']}, {state['elapsed_s']:.1f} s)"
    )
    print(
        f"  throughput {requests / wall:.0f} requests/s ({wall:.2f} s); latency median "
        f"{statistics.median(lat) * 1e3:.0f} ms, p95 {p95 * 1e3:.0f} ms; errors {errors}"
    )


def fair(url: str, rounds: int) -> None:
    spec = json.load(urllib.request.urlopen(f"{url}/api/v1/openapi.json"))
    print(f"fair: the server's limits {spec['info']['x-limits']}")
    for name, query in (("1,000,000 points", MILLION), ("10,000 points (the limit)", AT_LIMIT)):
        quick: list[float] = []
        big: list[tuple[float, int, int]] = []
        for i in range(rounds):
            with ThreadPoolExecutor(2) as ex:
                heavy = [ex.submit(get, f"{url}/api/v1/normal?{query}") for _ in range(2)]
                time.sleep(0.02)  # the two big ones first
                t, code, _ = get(f"{url}/api/v1/pulloff?radius={30e-9 + i * 1e-9!r}&{WIRE}")
                if code != 200:
                    raise SystemExit(f"the pull-off got {code}")
                quick.append(t)
                big += [f.result() for f in heavy]
        codes = sorted({c for _, c, _ in big})
        size = statistics.median(n for _, _, n in big)
        print(
            f"fair: two GET normal over {name} with a pull-off in flight, {rounds} rounds: the "
            f"big ones got {codes}, {size:,.0f} bytes, median "
            f"{statistics.median(t for t, _, _ in big) * 1e3:.0f} ms, max "
            f"{max(t for t, _, _ in big) * 1e3:.0f} ms"
        )
        print(
            f"  the pull-off's latency: median {statistics.median(quick) * 1e3:.0f} ms, max "
            f"{max(quick) * 1e3:.0f} ms (target: under 1000 ms)"
        )


def lookups(url: str, count: int) -> None:
    req = urllib.request.Request(f"{url}/api/v1/jobs/normal?{AT_LIMIT}", method="POST")
    job = json.load(urllib.request.urlopen(req))["id"]
    for _ in range(600):
        if json.load(urllib.request.urlopen(f"{url}/api/v1/jobs/id/{job}"))["state"] == "done":
            break
        time.sleep(0.1)
    quick: list[float] = []
    with ThreadPoolExecutor(4) as ex:
        heavy = [ex.submit(get, f"{url}/api/v1/jobs/id/{job}") for _ in range(count)]
        i = 0
        while not all(f.done() for f in heavy):
            t, code, _ = get(f"{url}/api/v1/pulloff?radius={30e-9 + i * 1e-9!r}&{WIRE}")
            quick.append(t)
            i += 1
        got = [f.result() for f in heavy]
    print(
        f"lookups: {count} GETs of a finished 10,000-point job ({got[0][2]:,} bytes) from 4 "
        f"clients: median {statistics.median(t for t, _, _ in got) * 1e3:.0f} ms; "
        f"{len(quick)} pull-offs meanwhile, latency median {statistics.median(quick) * 1e3:.0f}"
        f" ms, max {max(quick) * 1e3:.0f} ms"
    )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", default="load,fair,lookups", help="scenarios: load, fair, lookups")
    ap.add_argument("--requests", type=int, default=500)
    ap.add_argument("--clients", type=int, default=20)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--rounds", type=int, default=10, help="rounds of the fair scenario")
    ap.add_argument("--lookups", type=int, default=200, help="GETs of the lookups scenario")
    args = ap.parse_args()
    only = set(args.only.split(","))
    with serve(args.workers) as url:
        for i in range(args.workers):  # every worker has answered once
            get(f"{url}/api/v1/pulloff?radius={(i + 1) * 1e-8!r}&{WIRE}")
        if "fair" in only:
            fair(url, args.rounds)
        if "lookups" in only:
            lookups(url, args.lookups)
        if "load" in only:
            load(url, args.requests, args.clients, args.workers)


if __name__ == "__main__":
    main()
