"""The calculator's API under load: many quick requests while a slow one is in flight.

    python benchmarks/web.py [--requests 500] [--clients 20] [--workers 2]

Starts ``linecontact serve`` on a free loopback port (``--workers`` processes), starts one slow
request (the quick adhesion map, about ten seconds, through the jobs API), then sends
``--requests`` GET ``/api/v1/pulloff`` requests (a nanowire, the radius varied) from
``--clients`` concurrent clients (threads), and prints the throughput, the median and 95th
percentile latency, and the errors (issue 24: zero). A slow computation may hold all but one
worker, so the quick requests keep going while it runs.
"""

from __future__ import annotations

import argparse
import json
import os
import socket
import statistics
import subprocess
import sys
import time
import urllib.error
import urllib.request
from concurrent.futures import ThreadPoolExecutor


def _port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--requests", type=int, default=500)
    ap.add_argument("--clients", type=int, default=20)
    ap.add_argument("--workers", type=int, default=2)
    args = ap.parse_args()
    port = _port()
    env = {**os.environ, "OPENBLAS_NUM_THREADS": "1"}
    cmd = [sys.executable, "-m", "linecontact", "serve", "--port", str(port)]
    proc = subprocess.Popen(
        [*cmd, "--workers", str(args.workers)], env=env, stderr=subprocess.DEVNULL
    )
    url = f"http://127.0.0.1:{port}"
    try:
        for _ in range(300):
            try:
                urllib.request.urlopen(url + "/", timeout=1)
                break
            except OSError:
                time.sleep(0.1)
        req = urllib.request.Request(url + "/api/v1/jobs/map?quick=true", method="POST")
        job = json.load(urllib.request.urlopen(req))

        def one(i: int) -> tuple[float, int]:
            r = 20e-9 * (1 + i % 50)
            q = f"radius={r!r}&modulus=1.2e11&work_of_adhesion=0.3&z0=3e-10"
            t = time.perf_counter()
            try:
                with urllib.request.urlopen(f"{url}/api/v1/pulloff?{q}", timeout=60) as resp:
                    resp.read()
                    code = resp.status
            except urllib.error.HTTPError as exc:
                code = exc.code
            except OSError:
                code = 0
            return time.perf_counter() - t, code

        t0 = time.perf_counter()
        with ThreadPoolExecutor(args.clients) as ex:
            out = list(ex.map(one, range(args.requests)))
        wall = time.perf_counter() - t0
        state = json.load(urllib.request.urlopen(f"{url}/api/v1/jobs/id/{job['id']}"))
        lat = sorted(t for t, _ in out)
        errors = sum(1 for _, c in out if c != 200)
        p95 = lat[int(0.95 * (len(lat) - 1))]
        print(
            f"{args.requests} requests from {args.clients} clients, {args.workers} workers, "
            f"the quick map in flight (its state after: {state['state']}, "
            f"{state['elapsed_s']:.1f} s)"
        )
        print(
            f"  throughput {args.requests / wall:.0f} requests/s ({wall:.2f} s); latency median "
            f"{statistics.median(lat) * 1e3:.0f} ms, p95 {p95 * 1e3:.0f} ms; errors {errors}"
        )
    finally:
        proc.terminate()
        proc.wait(10)


if __name__ == "__main__":
    main()
