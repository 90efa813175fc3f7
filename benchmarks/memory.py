"""Memory and time per point of the vectorised closed forms, from 1e4 to 1e7 points.

    python benchmarks/memory.py                      # every call, 1e4 ... 1e7 points
    python benchmarks/memory.py --sizes 1e4,1e6 --calls normal_contact,pull_off

Each call at each size runs in a fresh process (``subprocess``): the inputs are drawn in
place, the call is made once on 1,000 points (imports, caches), then on all of them.
Printed per call and size: the time per point (the mean of enough calls to fill 0.2 s, at
least one: on a busy machine a mean compares with the single call of a large size) and,
from another process, the extra memory per point, what the call holds while it works
beyond its inputs and its result: the peak resident set size during the call
(``resource.getrusage``, ``ru_maxrss``) less the resident set size after it, with the
result alive (Linux, ``/proc/self/statm``; glibc's ``MALLOC_MMAP_THRESHOLD_`` is fixed so
that freed arrays leave the resident set; an upper bound: the peak includes the process
before the call). The closed forms work on chunks of points (``linecontact.sie._in_chunks``),
so the extra memory per point falls with the number of points and the time per point stays
flat. Beside it, the peak per point that ``tracemalloc`` traces during the call, over the
inputs (the result included: what the call allocates at its highest; ``pull_off``'s target,
issue 36, is under 100 bytes at 1e7 points). A 1e7-point run of the sliding calls takes
minutes.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import time
import warnings

import numpy as np

CALLS = (
    "normal_contact",
    "contact_for_load",
    "pull_off",
    "sliding_contact",
    "sliding_contact_for_load",
    "sliding_pull_off",
)


def _inputs(n: int):
    """The parameters of ``n`` points, drawn in place (no temporaries: a low peak before)."""
    rng = np.random.default_rng(1)

    def log_uniform(lo: float, hi: float) -> np.ndarray:
        x = np.empty(n)
        rng.random(out=x)
        x *= hi - lo
        x += lo
        return np.power(10.0, x, out=x)

    F = np.empty(n)
    rng.random(out=F)
    F *= 2.99
    F += 0.01
    return dict(
        A=log_uniform(-4, np.log10(0.2)),
        rho=log_uniform(1, 4),
        r=log_uniform(0, 1),
        s=log_uniform(-3, -1),
        F=F,
    )


def _call(name: str, x: dict):
    import linecontact as lc

    return {
        "normal_contact": lambda: lc.normal_contact(x["A"], x["rho"], x["s"]),
        "contact_for_load": lambda: lc.contact_for_load(x["F"], x["rho"], x["s"]),
        "pull_off": lambda: lc.pull_off(x["rho"], x["s"]),
        "sliding_contact": lambda: lc.sliding_contact(x["A"], x["rho"], x["r"], x["s"]),
        "sliding_contact_for_load": lambda: lc.sliding_contact_for_load(
            x["F"], x["rho"], x["r"], x["s"]
        ),
        "sliding_pull_off": lambda: lc.sliding_pull_off(x["rho"], x["r"], x["s"]),
    }[name]


def _peak() -> int:
    """Peak resident set size of this process so far, bytes (Linux: ru_maxrss in KiB)."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024


def _now() -> int:
    """Resident set size of this process now, bytes (Linux)."""
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * resource.getpagesize()


def child(name: str, n: int, what: str) -> None:
    """Measure one call at one size in this (fresh) process; print a JSON line.

    ``what``: ``"time"`` (the mean of enough calls to fill 0.2 s), ``"memory"`` (the
    first call's peak less what it keeps) or ``"traced"`` (the peak that ``tracemalloc``
    traces during the first call, the result included).
    """
    import linecontact as lc

    warnings.simplefilter("ignore", lc.ModelValidityWarning)
    _call(name, _inputs(1000))()
    x = _inputs(n)
    if what == "memory":
        res = _call(name, x)()
        print(json.dumps(dict(extra=(_peak() - _now()) / n)))
        del res
        return
    if what == "traced":
        import tracemalloc

        tracemalloc.start()
        res = _call(name, x)()
        print(json.dumps(dict(traced=tracemalloc.get_traced_memory()[1] / n)))
        del res
        return
    total, reps = 0.0, 0
    while total < 0.2:
        t0 = time.perf_counter()
        _call(name, x)()
        total, reps = total + time.perf_counter() - t0, reps + 1
    print(json.dumps(dict(us=1e6 * total / (reps * n))))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="1e4,1e5,1e6,1e7")
    ap.add_argument("--calls", default=",".join(CALLS))
    ap.add_argument("--child", nargs=3, metavar=("CALL", "N", "WHAT"), help=argparse.SUPPRESS)
    a = ap.parse_args()
    if a.child:
        child(a.child[0], int(float(a.child[1])), a.child[2])
        return
    sizes = [int(float(v)) for v in a.sizes.split(",")]
    # the memory in a process where glibc maps every array on its own and hands it back
    # when freed (the resident set after a call is then what it keeps); the time in one
    # with the usual allocator (mapping each array costs page faults)
    env = dict(os.environ, MALLOC_MMAP_THRESHOLD_="131072")

    def run(name: str, n: int, what: str) -> dict:
        cmd = [sys.executable, __file__, "--child", name, str(n), what]
        kw = dict(env=env) if what == "memory" else {}
        out = subprocess.run(cmd, capture_output=True, text=True, check=True, **kw).stdout
        return json.loads(out.strip().splitlines()[-1])

    print(f"{'call':<26}{'points':>10}{'us/point':>10}{'extra B/point':>15}{'peak B/point':>14}")
    for name in a.calls.split(","):
        first = None
        for n in sizes:
            us, extra = run(name, n, "time")["us"], run(name, n, "memory")["extra"]
            traced = run(name, n, "traced")["traced"]
            first = us if first is None else first
            print(
                f"{name:<26}{n:>10.0e}{us:>10.3f}{extra:>15.0f}{traced:>14.0f}"
                f"   (time x{us / first:.2f} of the first size)",
                flush=True,
            )


if __name__ == "__main__":
    main()
