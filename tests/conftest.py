"""Settings shared by the whole suite.

Hypothesis draws the same examples on every machine and every run (``derandomize``), keeps
no example database between runs (``database=None``: a failure found once on one machine is
not replayed only there) and sets no deadline (timings belong in ``benchmarks/``). A test
that needs other settings states them with ``@settings(...)``, which inherit the rest from
this profile. A failing example is then a property of the code and of the machine's floating
point alone, and the README's rule holds: no test compares two code paths bit for bit
(README, "Same answers on every machine").

The calculator's browser tests (``test_web_pages.py``, ``test_web_bent_wire.py``) share
their fixtures here: ``server`` (``linecontact serve`` on a free port, for the module),
``browser`` (the system's Chromium driven by Playwright; skipped without either) and
``page`` (a new tab that fails its test on any script error).

The Lennard-Jones solver keeps the last curve and pull-off it found at a ``mu`` (speed only);
each test starts without them, so that no test depends on which ran before it in the same
process (a test that makes the solver fail must reach the solver).
"""

from __future__ import annotations

import os
import shutil
import socket
import subprocess
import sys
import time
import urllib.request

import pytest
from hypothesis import settings

settings.register_profile("linecontact", derandomize=True, database=None, deadline=None)
settings.load_profile("linecontact")


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


@pytest.fixture(scope="module")
def server():
    """``linecontact serve`` on a free port: its base URL."""
    pytest.importorskip("starlette")
    port = _free_port()
    env = {**os.environ, "OPENBLAS_NUM_THREADS": "1"}
    proc = subprocess.Popen(
        [sys.executable, "-m", "linecontact", "serve", "--port", str(port)],
        env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
    )  # fmt: skip
    url = f"http://127.0.0.1:{port}"
    for _ in range(300):
        try:
            urllib.request.urlopen(url + "/", timeout=1)
            break
        except OSError:
            time.sleep(0.1)
    yield url
    proc.terminate()
    proc.wait(10)


@pytest.fixture(scope="module")
def browser():
    """The system's Chromium, headless, driven by Playwright."""
    pw = pytest.importorskip("playwright.sync_api")
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        pytest.skip("no chromium (apt-get install chromium)")
    with pw.sync_playwright() as p:
        b = p.chromium.launch(executable_path=chromium, args=["--no-sandbox"])
        yield b
        b.close()


@pytest.fixture
def page(browser):
    """A desktop-sized tab; its test fails on any script error on the page."""
    pg = browser.new_page(viewport={"width": 1280, "height": 900})
    errors: list[str] = []
    pg.on("pageerror", lambda e: errors.append(str(e)))
    yield pg
    pg.close()
    assert errors == []  # no script error on the page
