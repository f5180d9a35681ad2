"""The Dask example end to end: a CSV of pairs in several partitions, classified on a
LocalCluster of two worker processes, equals `classify_many` on the whole set; the README's
install line and command for it, as written."""

from __future__ import annotations

import ast
import importlib.util
import shlex
import subprocess
import sys
from pathlib import Path
from typing import List, Set

import numpy as np
import pandas as pd
import distributed

import qsic

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "python" / "examples"
sys.path.insert(0, str(EXAMPLES))
import dask_classify  # noqa: E402


def random_pairs(n: int, seed: int) -> tuple:
    rng = np.random.default_rng(seed)
    m = rng.integers(-6, 7, size=(2, n, 4, 4))
    m = m + m.transpose(0, 1, 3, 2)
    m[0, 5, 0, 1] += 1  # not symmetric: an error row
    m[1, 9] = 0  # the zero form on one side: a single quadric
    return m[0], m[1]


def test_dask_example_on_two_local_workers_equals_classify_many(tmp_path):
    A, B = random_pairs(600, seed=11)
    frame = pd.DataFrame(A.reshape(-1, 16), columns=dask_classify.A_COLUMNS)
    frame[dask_classify.B_COLUMNS] = B.reshape(-1, 16)
    frame.insert(0, "id", np.arange(len(frame)) * 7)
    csv = tmp_path / "pairs.csv"
    frame.to_csv(csv, index=False)

    cluster = distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    )
    with cluster, distributed.Client(cluster) as client:
        assert len(client.scheduler_info()["workers"]) == 2
        lazy = dask_classify.classify_dataset(str(csv), blocksize="16KB")
        assert lazy.npartitions >= 3
        answers = dask_classify.run(str(csv), client, blocksize="16KB")

    expected = qsic.classify_many(A, B)
    answers = answers.sort_values("id")
    assert list(answers["id"]) == list(frame["id"])
    assert list(answers.columns) == dask_classify.OUTPUT
    for key in dask_classify.OUTPUT[1:]:
        assert list(answers[key]) == list(expected[key]), key
    assert answers["error"].iloc[5].startswith("A: matrix is not symmetric")
    assert answers["pencil"].iloc[9] == "single"
    assert answers["error"].notna().sum() == 1


def dask_section() -> str:
    readme = (ROOT / "README.md").read_text()
    start = readme.index("### Dask")
    return readme[start : readme.index("\n## ", start)]


def readme_install_line() -> List[str]:
    """The requirements of the Dask section's `pip install` line."""
    lines = [l for l in dask_section().splitlines() if l.startswith("pip install ")]
    assert len(lines) == 1, "the Dask section gives one `pip install` line"
    return shlex.split(lines[0].split("#")[0])[2:]


def example_imports() -> Set[str]:
    """The modules the example imports (`dask.dataframe`, `pandas`, …), anywhere in it."""
    tree = ast.parse((EXAMPLES / "dask_classify.py").read_text())
    names: Set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names.add(node.module)
    return names


def test_readme_dask_install_line_installs_what_the_example_imports():
    reqs = readme_install_line()
    wanted = {}  # distribution name -> extras
    for r in reqs:
        name, _, extras = r.partition("[")
        wanted[name.lower()] = {e.strip() for e in extras.rstrip("]").split(",") if e.strip()}
    for module in example_imports():
        top = module.split(".")[0]
        if top == "qsic":
            assert "./python" in wanted or "qsic" in wanted, "the line installs qsic itself"
            continue
        spec = importlib.util.find_spec(top)
        if spec is None or "-packages" not in (spec.origin or ""):
            continue  # the standard library
        assert top in wanted, f"the example imports {module}: the pip line must install {top}"
        if top == "dask" and "." in module:
            extra = module.split(".")[1]
            assert extra in wanted["dask"], f"the example imports {module}: dask[{extra}]"
    # the test venv is made with the same requirements, so the example below runs as written
    script = (ROOT / "scripts" / "test-python").read_text()
    for r in reqs:
        if r not in ("./python", "qsic"):
            assert r in script or f'"{r}"' in script, f"scripts/test-python installs {r}"


def test_readme_dask_command_runs_as_written(tmp_path):
    """The first command of the Dask section, in a directory holding `pairs.csv`."""
    commands = [l for l in dask_section().splitlines() if l.startswith("python python/examples/")]
    args = shlex.split(commands[0])
    assert args[2:] == ["pairs.csv", "answers.csv"]
    A, B = random_pairs(60, seed=12)
    frame = pd.DataFrame(A.reshape(-1, 16), columns=dask_classify.A_COLUMNS)
    frame[dask_classify.B_COLUMNS] = B.reshape(-1, 16)
    frame.insert(0, "id", np.arange(len(frame)))
    frame.to_csv(tmp_path / "pairs.csv", index=False)
    run = subprocess.run(
        [sys.executable, str(ROOT / args[1]), *args[2:]],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert run.returncode == 0, run.stderr
    answers = pd.read_csv(tmp_path / "answers.csv")
    expected = qsic.classify_many(A, B)
    answers = answers.sort_values("id")
    assert list(answers.columns) == dask_classify.OUTPUT
    assert list(answers["case"]) == list(expected["case"])

    def column(key: str) -> list:  # the CSV's empty cells are NaN
        return [v if isinstance(v, str) else None for v in answers[key]]

    for key in ("pencil", "complex_type", "real_type", "error"):
        assert column(key) == list(expected[key]), key
    assert column("error")[5].startswith("A: matrix is not symmetric")
