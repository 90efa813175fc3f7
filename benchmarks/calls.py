"""Benchmark of the fixed costs: import time, scalar calls and the memory of a large batch.

Run: ``python benchmarks/calls.py [--repeat 10] [--mem-points 1000000] [--no-memory]``.

Prints

- the import time of ``linecontact`` against that of ``numpy`` alone, each in fresh Python
  processes (wall clock of the whole process, and the time of the ``import`` statement
  measured inside it), minimum and median of ``--repeat`` runs;
- the time of one scalar call (minimum over repeats, in microseconds) of the public
  functions: the closed-form and collocation normal contact, pull-off (a zero-width and a
  snap-off case), contact for a load, the sliding closed form, sliding pull-off, initiation
  of sliding and steady rolling;
- the peak resident memory of ``normal_contact(..., method="collocation")`` over
  ``--mem-points`` points of the sample of ``benchmarks/normal.py`` (in a fresh process:
  ``ru_maxrss`` after the call, and its increase over the resident size before it).

Times are noisy on a shared machine: the minimum is the most repeatable figure.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import timeit

HERE = os.path.dirname(os.path.abspath(__file__))


def _run_python(code: str, env: dict | None = None) -> str:
    return subprocess.run(
        [sys.executable, "-c", code], check=True, capture_output=True, text=True, env=env
    ).stdout


def import_times(repeat: int) -> None:
    """Wall clock of ``python -c 'import X'`` and in-process time of the import statement.

    Twice: in this environment as it is, and with Python's bytecode cache in use (with
    ``PYTHONDONTWRITEBYTECODE`` set, an editable install compiles its sources at every
    import, which NumPy's installed, precompiled files do not).
    """
    cached = dict(os.environ)
    cached.pop("PYTHONDONTWRITEBYTECODE", None)
    cached["PYTHONPYCACHEPREFIX"] = tempfile.mkdtemp(prefix="linecontact-pycache-")
    _run_python("import linecontact", cached)  # writes the cache
    label = (
        "as set up (PYTHONDONTWRITEBYTECODE is set: sources compiled at every import)"
        if os.environ.get("PYTHONDONTWRITEBYTECODE")
        else "as set up"
    )
    for title, env in ((label, None), ("with the bytecode cache", cached)):
        _import_rows(title, env, repeat)


def _import_rows(title: str, env: dict | None, repeat: int) -> None:
    inner = "import time; t0 = time.perf_counter(); import {mod}; print(time.perf_counter() - t0)"
    rows = {}
    for mod in ("numpy", "linecontact"):
        wall, stmt = [], []
        for _ in range(repeat):
            t0 = timeit.default_timer()
            out = _run_python(inner.format(mod=mod), env)
            wall.append(timeit.default_timer() - t0)
            stmt.append(float(out))
        rows[mod] = (wall, stmt)
    print(f"import time, fresh processes, {repeat} runs (min / median), {title}:")
    for mod, (wall, stmt) in rows.items():
        print(
            f"  {mod:<12}: process {min(wall) * 1e3:6.1f} / {statistics.median(wall) * 1e3:6.1f}"
            f" ms, import statement {min(stmt) * 1e3:6.1f} / "
            f"{statistics.median(stmt) * 1e3:6.1f} ms"
        )
    d_wall = min(rows["linecontact"][0]) - min(rows["numpy"][0])
    d_stmt = min(rows["linecontact"][1]) - min(rows["numpy"][1])
    print(
        f"  linecontact - numpy: {d_wall * 1e3:.1f} ms (process), {d_stmt * 1e3:.1f} ms "
        f"(import statement)  (target < 100 ms)"
    )


def time_call(fn, repeat: int) -> float:
    """Minimum time of one call of ``fn`` in seconds.

    Loops of ~10 ms, ``3 * repeat`` of them: on a shared machine short loops, many of them,
    catch the quiet moments that the minimum reports.
    """
    fn()  # warm caches (collocation operators, lazy imports)
    timer = timeit.Timer(fn)
    number, _ = timer.autorange()  # number of calls that take >= 0.2 s
    number = max(1, number // 20)
    return min(timer.repeat(repeat=3 * repeat, number=number)) / number


def scalar_calls(repeat: int) -> None:
    import linecontact as lc

    calls = [
        ("normal_contact(0.02, 100, 0.01)", lambda: lc.normal_contact(0.02, 100.0, 0.01), 100),
        (
            "normal_contact(..., method='collocation')",
            lambda: lc.normal_contact(0.02, 100.0, 0.01, method="collocation"),
            None,
        ),
        ("pull_off(100, 0.01)  [zero-width]", lambda: lc.pull_off(100.0, 0.01), 1000),
        ("pull_off(100, 0.2)   [snap-off]", lambda: lc.pull_off(100.0, 0.2), 1000),
        ("contact_for_load(0.1, 100, 0.01)", lambda: lc.contact_for_load(0.1, 100.0, 0.01), 1000),
        (
            "contact_for_load(-2.5, 100, 0.2, branch='unstable')",
            lambda: lc.contact_for_load(-2.5, 100.0, 0.2, branch="unstable"),
            1000,
        ),
        (
            "sliding_contact(0.03, 100, 2, 0.01, closed-form)",
            lambda: lc.sliding_contact(0.03, 100.0, 2.0, 0.01, method="closed-form"),
            1000,
        ),
        ("sliding_pull_off(100, 2, 0.01)", lambda: lc.sliding_pull_off(100.0, 2.0, 0.01), 1000),
        ("sliding_initiation(0.01, 0.5)", lambda: lc.sliding_initiation(0.01, 0.5), None),
        ("steady_rolling(0.01, 0.0)", lambda: lc.steady_rolling(0.01, 0.0), None),
    ]
    print(f"scalar calls, minimum over {3 * repeat} loops of ~10 ms:")
    for label, fn, target in calls:
        t = time_call(fn, repeat)
        tgt = f"  (target < {target} us)" if target else ""
        print(f"  {label:<52}: {t * 1e6:9.1f} us{tgt}")


_MEMORY = """
import resource, sys
import numpy as np
sys.path.insert(0, {here!r})
from _common import sample_normal
import linecontact as lc
A, rho, s = sample_normal({points}, np.random.default_rng(0))
def rss_now():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * resource.getpagesize() / 2**20
before = rss_now()
import time
t0 = time.perf_counter()
r = lc.normal_contact(A, rho, s, method="collocation")
t = time.perf_counter() - t0
peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**10
print(before, peak, t, bool(np.all(r.converged)))
"""


def memory(points: int) -> None:
    out = _run_python(_MEMORY.format(here=HERE, points=points)).split()
    before, peak, t, conv = float(out[0]), float(out[1]), float(out[2]), out[3]
    print(
        f"normal_contact(method='collocation') on {points} points (fresh process): "
        f"peak RSS {peak:.0f} MiB, {peak - before:.0f} MiB above the RSS before the call; "
        f"{t:.1f} s ({t / points * 1e6:.1f} us/point), all converged: {conv}"
    )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=10)
    ap.add_argument("--mem-points", type=int, default=1_000_000)
    ap.add_argument("--no-memory", action="store_true")
    args = ap.parse_args()
    import_times(args.repeat)
    scalar_calls(args.repeat)
    if not args.no_memory:
        memory(args.mem_points)


if __name__ == "__main__":
    main()
