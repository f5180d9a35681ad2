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
    # the pair in R^3 first, the projective class after it
    assert lines[0].split() == ["in", "R^3:", "2", "circles:", "2", "bounded", "curves;", "no", "point", "at", "infinity"]
    assert lines[1].split(":", 1)[1].strip() == "sphere and circular cone"
    assert lines[2].startswith("projective class")
    assert lines[3].split() == ["pencil:", "regular"]
    assert lines[4].split() == ["case:", "14"]
