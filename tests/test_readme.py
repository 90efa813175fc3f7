"""The Python examples of the README run as printed (in a fresh process, a temporary folder)."""

import re
import subprocess
import sys
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[1] / "README.md"
BLOCKS = (
    re.findall(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), re.S)
    if README.exists()
    else []
)


@pytest.mark.skipif(not README.exists(), reason="README.md is not beside the tests")
def test_the_readme_has_python_examples():
    assert len(BLOCKS) >= 3


@pytest.mark.parametrize("block", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_readme_python_block_runs(block, tmp_path):
    p = subprocess.run(
        [sys.executable, "-c", block], capture_output=True, text=True, cwd=tmp_path, timeout=120
    )
    assert p.returncode == 0, p.stderr
    assert "Traceback" not in p.stderr


@pytest.mark.skipif(not README.exists(), reason="README.md is not beside the tests")
def test_the_readme_domain_table_is_the_code_s():
    from linecontact.domain import DOMAIN

    text = README.read_text(encoding="utf-8")
    section = text[text.index("## Validated domain") :]
    section = section[: section.index("\n## ", 5)]
    num = r"([-+.e\d]+|inf)"
    rows = re.findall(rf"^\| `(\w+)` \| ([\[(]){num}, {num}([\])]) \|", section, re.M)
    table = {k: (float(lo), b1 == "[", float(hi), b2 == "]") for k, b1, lo, hi, b2 in rows}
    assert table == DOMAIN
