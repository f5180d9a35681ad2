"""The documented examples run: the module's doctests and the README's one-liner."""

from __future__ import annotations

import doctest
import subprocess
import sys

import qsic


def test_module_doctests_pass():
    result = doctest.testmod(qsic)
    assert result.attempted >= 2 and result.failed == 0


def test_readme_one_liner_prints_the_report():
    code = "import qsic; print(qsic.classify('x^2+y^2+z^2-1', 'x^2+y^2-z^2'))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    lines = out.stdout.splitlines()
    assert lines[0].split() == ["pencil:", "regular"]
    assert lines[1].split() == ["case:", "14"]
    assert lines[-1].startswith("in R^3 (w = 0 at infinity): sphere and circular_cone")
