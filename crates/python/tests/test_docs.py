"""Every Python example of docs/python.md runs as a user runs it, from the repository's
root, against the installed package: the page cannot drift from the package."""

import re
import subprocess
import sys

import pytest

from conftest import REPO

PAGE = REPO / "docs" / "python.md"
BLOCK = re.compile(r"^```python\n(.*?)^```$", re.S | re.M)


def examples():
    return BLOCK.findall(PAGE.read_text())


def test_the_page_has_examples():
    assert len(examples()) >= 2


@pytest.mark.parametrize("k", range(len(examples())))
def test_every_example_runs(k):
    proc = subprocess.run([sys.executable, "-"], input=examples()[k], cwd=REPO,
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, f"docs/python.md example {k + 1}:\n{proc.stderr}"
