"""The documentation site as a reader gets it: built once per test session (warnings as errors),
then read as HTML and, where Chromium is installed, in a browser with no internet.

The build takes the docs extra (``python -m pip install '.[docs]'``); without it these tests
are skipped and say so. ``LINECONTACT_SITE=DIR`` tests a site already built in ``DIR``
instead (CI builds it just before). The checker ``.ci/check-site`` (internal links and
anchors, nothing loaded from another host) is run on the build and on small sites made to
fail it.
"""

from __future__ import annotations

import functools
import html.parser
import http.server
import importlib.util
import os
import re
import shutil
import subprocess
import sys
import threading
import time
from pathlib import Path
from urllib.parse import urlsplit

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS, EXAMPLES, CHECK_SITE = ROOT / "docs", ROOT / "examples", ROOT / ".ci" / "check-site"
THEORY = [
    "derivations",
    "nomenclature",
    "sliding",
    "tangential",
    "load-histories",
    "push",
    "lennard-jones",
    "adhesion-map",
    "inverse",
]
DOCS_EXTRA = {
    "sphinx": "sphinx",
    "pydata_sphinx_theme": "pydata-sphinx-theme",
    "numpydoc": "numpydoc",
    "sphinx_gallery": "sphinx-gallery",
    "myst_parser": "myst-parser",
    "sphinx-mathjax-offline": "sphinx-mathjax-offline",
    "matplotlib": "matplotlib",
    "xarray": "xarray (the extra [sweep])",
}
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")


@pytest.fixture(scope="session")
def site(tmp_path_factory) -> Path:
    """The built site: ``LINECONTACT_SITE``, or built here once per session."""
    given = os.environ.get("LINECONTACT_SITE")
    if given:
        path = Path(given)
        assert (path / "index.html").is_file(), f"LINECONTACT_SITE={given}: no index.html"
        return path
    if not DOCS.is_dir():
        pytest.skip("docs/ is not beside tests/")
    missing = [pkg for mod, pkg in DOCS_EXTRA.items() if importlib.util.find_spec(mod) is None]
    if missing:
        pytest.skip(
            f"the docs extra is not installed (python -m pip install '.[docs]'): "
            f"missing {', '.join(missing)}"
        )
    out = tmp_path_factory.mktemp("site")
    t0 = time.monotonic()
    p = subprocess.run(
        [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html",
         "-d", str(out / "doctrees"), str(DOCS), str(out / "html")],
        capture_output=True, text=True, cwd=ROOT, timeout=1200,
    )  # fmt: skip
    assert p.returncode == 0, f"the site's build failed:\n{p.stdout[-3000:]}\n{p.stderr[-6000:]}"
    print(f"site built in {time.monotonic() - t0:.0f} s")
    return out / "html"


class _Html(html.parser.HTMLParser):
    """The tags of a page with their attributes, and its title."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.tags: list[tuple[str, dict[str, str]]] = []
        self.title, self._in_title = "", False

    def handle_starttag(self, tag, attrs):
        self.tags.append((tag, {k: v or "" for k, v in attrs}))
        self._in_title = tag == "title"

    def handle_endtag(self, tag):
        self._in_title = False if tag == "title" else self._in_title

    def handle_data(self, data):
        if self._in_title:
            self.title += data


def _page(path: Path) -> _Html:
    parsed = _Html()
    parsed.feed(path.read_text(encoding="utf-8"))
    return parsed


def _pages(site: Path) -> list[Path]:
    return [p for p in site.rglob("*.html") if p.relative_to(site).parts[0] != "_static"]


def test_the_gallery_has_a_title_and_is_in_the_home_pages_contents(site):
    gallery = site / "auto_examples" / "index.html"
    title = _page(gallery).title
    assert title.startswith("Gallery") and "no title" not in title, title
    # the page's own text is reStructuredText rendered, not Markdown shown as text
    text = gallery.read_text(encoding="utf-8")
    assert "<h1>Gallery" in text and "**" not in text and "# Examples" not in text
    home = site / "index.html"
    toctree = home.read_text(encoding="utf-8").split('class="toctree-wrapper', 1)
    assert len(toctree) == 2, "the home page has no contents (toctree)"
    assert 'href="auto_examples/index.html">Gallery</a>' in toctree[1]
    # and in the navbar, named
    nav = [a for t, a in _page(home).tags if t == "a" and "nav-link" in a.get("class", "")]
    assert any(a["href"] == "auto_examples/index.html" for a in nav)


def test_every_card_of_the_gallery_has_its_figure(site):
    parsed = _page(site / "auto_examples" / "index.html")
    cards, in_card = [], False
    for tag, a in parsed.tags:
        if tag == "div" and "sphx-glr-thumbcontainer" in a.get("class", ""):
            cards.append([])
            in_card = True
        elif in_card and tag == "img":
            cards[-1].append(a["src"])
    examples = sorted(EXAMPLES.glob("*.py"))
    assert len(cards) == len(examples) == 11, (len(cards), [e.name for e in examples])
    for images in cards:
        assert images, "a card without an image"
        src = images[0]
        assert "no_image" not in src, f"a placeholder thumbnail: {src}"
        image = (site / "auto_examples" / src).resolve()
        assert image.is_file() and image.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", src
    for example in examples:  # each page shows the figure the example drew
        page = site / "auto_examples" / f"{example.stem}.html"
        assert f"sphx_glr_{example.stem}_001.png" in page.read_text(encoding="utf-8"), example


def test_the_examples_pages_show_prose_and_no_path_of_the_build_machine(site):
    for example in sorted(EXAMPLES.glob("*.py")):
        text = (site / "auto_examples" / f"{example.stem}.html").read_text(encoding="utf-8")
        assert "linecontact-gallery-" not in text, example.name
        assert not re.search(r"/tmp/|/var/folders/|\\AppData\\Local\\Temp", text), example.name
        # text between the steps: a section per cell, more than the title's
        assert text.count("<h2>") >= 2, f"{example.name}: no text between its steps"


def test_the_api_reference_is_grouped_by_task_with_short_signatures(site):
    import linecontact

    api = (site / "api.html").read_text(encoding="utf-8")
    assert api.count("<h2>") >= 8, "the API reference is not grouped by task"
    for name in (n for n in linecontact.__all__ if not n.startswith("_")):
        assert f'href="generated/linecontact.{name}.html' in api, name
    assert not re.search(r"\bEqs?\.</(p|td)>", api), "a summary cut at 'Eq.'"
    for page in (site / "generated").glob("*.html"):
        text = page.read_text(encoding="utf-8")
        assert "_SupportsArray" not in text and "_Buffer" not in text, page.name
    cylinder = (site / "generated" / "linecontact.Cylinder.html").read_text(encoding="utf-8")
    for method in ("contact", "pull_off", "push", "sliding", "steady_rolling", "cyclic_loss"):
        assert f'id="linecontact.Cylinder.{method}"' in cylinder, method


def test_no_page_loads_a_script_or_stylesheet_from_another_host(site):
    for path in _pages(site):
        for tag, a in _page(path).tags:
            url = a.get("src", "") if tag == "script" else ""
            if tag == "link" and "stylesheet" in a.get("rel", "").split():
                url = a.get("href", "")
            parts = urlsplit(url)
            assert not (parts.netloc or parts.scheme), f"{path.relative_to(site)}: {tag} {url}"


def test_the_site_passes_check_site(site):
    p = subprocess.run(
        [sys.executable, str(CHECK_SITE), str(site)], capture_output=True, text=True, timeout=300
    )
    assert p.returncode == 0, p.stdout[-4000:] + p.stderr


def test_maths_is_typeset_by_mathjax_served_with_the_site(site):
    # every theory page has equations as maths (not code): MathJax's input elements
    for name in THEORY:
        text = (site / f"{name}.html").read_text(encoding="utf-8")
        assert text.count('class="math') >= 3, f"{name}: no typeset equations"
    # the docstrings' .. math:: too
    assert 'class="math' in (site / "generated" / "linecontact.hertz_load.html").read_text()
    # MathJax from the site itself
    scripts = [a.get("src", "") for t, a in _page(site / "derivations.html").tags if t == "script"]
    mathjax = [s for s in scripts if "mathjax" in s.lower()]
    assert mathjax and all(not urlsplit(s).netloc for s in mathjax), mathjax
    assert (site / "_static" / "mathjax" / "tex-chtml.js").is_file()
    assert (site / "_static" / "mathjax" / "output" / "chtml" / "fonts" / "woff-v2").is_dir()


def _write(root: Path, files: dict[str, str]) -> Path:
    for name, text in files.items():
        (root / name).parent.mkdir(parents=True, exist_ok=True)
        (root / name).write_text(text, encoding="utf-8")
    return root


def _check_site(root: Path) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, str(CHECK_SITE), str(root)], capture_output=True, text=True, timeout=60
    )


GOOD = {
    "index.html": '<h1 id="top">x</h1><a href="a/b.html#s">b</a><a href="https://x.org/">ok</a>'
    '<link rel="stylesheet" href="_static/s.css"><script src="_static/m.js"></script>'
    '<link rel="canonical" href="https://x.org/index.html">',
    "a/b.html": '<section id="s"></section><a href="../index.html#top">up</a>'
    '<img src="../_static/i.png">',
    "_static/s.css": "@font-face { src: url(f.woff2) } body { background: url('i.png') }",
    "_static/m.js": "",
    "_static/i.png": "",
    "_static/f.woff2": "",
}


def test_check_site_passes_a_sound_site(tmp_path):
    p = _check_site(_write(tmp_path, GOOD))
    assert p.returncode == 0, p.stdout + p.stderr


@pytest.mark.parametrize(
    ("name", "text", "says"),
    [
        ("c.html", '<a href="missing.html">x</a>', "no file missing.html"),
        ("c.html", '<a href="index.html#nowhere">x</a>', "no anchor #nowhere"),
        ("c.html", '<script src="https://cdn.example.org/m.js"></script>', "another host"),
        ("c.html", '<script src="//cdn.example.org/m.js"></script>', "another host"),
        ("c.html", '<link rel="stylesheet" href="http://x.org/s.css">', "another host"),
        ("c.html", '<img srcset="a.png 1x, https://x.org/b.png 2x">', "another host"),
        ("c.html", '<div style="background:url(https://x.org/b.png)"></div>', "another host"),
        ("c.html", "<style>@import 'https://fonts.example.org/f.css';</style>", "another host"),
        ("_static/t.css", "@font-face { src: url(https://x.org/f.woff2) }", "another host"),
        ("_static/t.css", "body { background: url(gone.png) }", "no file"),
    ],
)
def test_check_site_fails_a_broken_link_or_a_resource_from_another_host(tmp_path, name, text, says):
    p = _check_site(_write(tmp_path, {**GOOD, name: text}))
    assert p.returncode == 1 and says in p.stdout, p.stdout + p.stderr


@pytest.fixture(scope="module")
def served(site):
    handler = functools.partial(_Quiet, directory=str(site))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{server.server_address[1]}"
    server.shutdown()
    server.server_close()


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def test_in_a_browser_without_internet_every_equation_is_typeset(served):
    pw = pytest.importorskip("playwright.sync_api")
    if CHROMIUM is None:
        pytest.skip("no chromium (apt-get install chromium)")
    pages = [*(f"{n}.html" for n in THEORY), "index.html", "generated/linecontact.hertz_load.html"]
    with pw.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox"])
        try:
            page = browser.new_page(viewport={"width": 1280, "height": 900})
            elsewhere: list[str] = []

            def route(r):
                if r.request.url.startswith(served):
                    r.continue_()
                else:  # no internet: what would have gone out is refused, and noted
                    elsewhere.append(r.request.url)
                    r.abort()

            page.route("**/*", route)
            for name in pages:
                page.goto(f"{served}/{name}")
                page.wait_for_function(
                    "window.MathJax && MathJax.startup && MathJax.startup.promise"
                )
                counts = page.evaluate(
                    """() => MathJax.startup.promise.then(() => ({
                        math: document.querySelectorAll('.math').length,
                        typeset: document.querySelectorAll('mjx-container').length,
                        errors: [...document.querySelectorAll('mjx-merror')]
                            .map(e => e.getAttribute('data-mjx-error') || e.textContent),
                    }))"""
                )
                assert counts["math"] > 0, name
                assert counts["typeset"] >= counts["math"], (name, counts)
                assert not counts["errors"], (name, counts["errors"][:5])
                # no display equation cut off: inside its column, or scrolling sideways
                cut = page.evaluate(
                    """() => [...document.querySelectorAll('mjx-container[display="true"]')]
                        .filter(m => {
                            const box = (m.closest('div.math') || m).getBoundingClientRect();
                            const scrolls = m.scrollWidth > m.clientWidth;
                            return [...m.querySelectorAll('mjx-c')].some(c => {
                                const r = c.getBoundingClientRect();
                                return r.width > 0 && (r.left < box.left - 1
                                    || (r.right > box.right + 1 && !scrolls));
                            });
                        }).map(m => m.textContent.slice(0, 60))"""
                )
                assert not cut, (name, cut[:3])
                # the header: one row at 1280 px (its links, the search, the theme switch)
                tops = page.evaluate(
                    "() => [...document.querySelectorAll('.bd-header .navbar-nav > li,"
                    " .bd-header .search-button, .bd-header .theme-switch-button')]"
                    ".filter(e => e.offsetParent).map(e => e.getBoundingClientRect().top)"
                )
                assert len(tops) >= 8 and max(tops) - min(tops) < 10, (name, tops)
            assert not elsewhere, elsewhere[:5]
        finally:
            browser.close()


def test_in_a_browser_the_header_is_one_row_and_the_tables_fit(served):
    pw = pytest.importorskip("playwright.sync_api")
    if CHROMIUM is None:
        pytest.skip("no chromium (apt-get install chromium)")
    pages = [
        "index.html",
        "install.html",
        "api.html",
        "auto_examples/index.html",
        "changelog.html",
        "citing.html",
        "generated/linecontact.Cylinder.html",
    ]
    with pw.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox"])
        try:
            page = browser.new_page(viewport={"width": 1280, "height": 900})
            for name in pages:
                page.goto(f"{served}/{name}")
                tops = page.evaluate(
                    "() => [...document.querySelectorAll('.bd-header .navbar-nav > li,"
                    " .bd-header .search-button, .bd-header .theme-switch-button')]"
                    ".filter(e => e.offsetParent).map(e => e.getBoundingClientRect().top)"
                )
                assert len(tops) >= 8 and max(tops) - min(tops) < 10, (name, tops)
                wide = page.evaluate(
                    "() => [...document.querySelectorAll('article table')].filter(t =>"
                    " t.getBoundingClientRect().right > document.querySelector('article')"
                    ".getBoundingClientRect().right + 1).map(t => t.textContent.slice(0, 60))"
                )
                assert not wide, (name, wide[:3])
        finally:
            browser.close()
