"""Shared helpers: the repository's corpora and the `qsic` binary to compare with.

The binary is `$QSIC_CLI`, else `target/debug/qsic` or `target/release/qsic` under
`$CARGO_TARGET_DIR` (default: the repository's `target/`); `scripts/test-python` builds it.
"""

from __future__ import annotations

import json
import os
import subprocess
from fractions import Fraction
from pathlib import Path
from typing import Any, Dict, List

import numpy as np
import pytest

import qsic

ROOT = Path(__file__).resolve().parents[2]
CORPUS = ROOT / "crates" / "qsic" / "tests" / "data"
AFFINE_CORPUS = ROOT / "crates" / "qsic-cli" / "tests" / "data" / "affine.jsonl"


def read_jsonl(path: Path) -> List[Dict[str, Any]]:
    return [json.loads(line) for line in path.read_text().splitlines() if line.strip()]


def cli_path() -> Path:
    if os.environ.get("QSIC_CLI"):
        return Path(os.environ["QSIC_CLI"])
    target = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    for profile in ("debug", "release"):
        p = target / profile / "qsic"
        if p.exists():
            return p
    raise RuntimeError(f"no qsic binary under {target}: run scripts/test-python or set QSIC_CLI")


@pytest.fixture(scope="session")
def cli() -> Path:
    return cli_path()


def run_cli(cli: Path, *args: str, stdin: str = "") -> subprocess.CompletedProcess:
    return subprocess.run(
        [str(cli), *args], input=stdin.encode(), capture_output=True, check=False
    )


def cli_batch(cli: Path, records: List[Dict[str, Any]], *args: str) -> List[Dict[str, Any]]:
    """`qsic classify --batch -` (plus `args`) on `records`, one answer per record, in order."""
    text = "".join(json.dumps(r) + "\n" for r in records)
    out = run_cli(cli, "classify", *args, "--batch", "-", stdin=text)
    answers = [json.loads(line) for line in out.stdout.decode().splitlines()]
    assert len(answers) == len(records), out.stderr.decode()
    return answers


def as_matrix(form: Any) -> np.ndarray:
    """A corpus field as a 4×4 object array: number strings kept, polynomial strings read by
    `qsic.Quadric` and given as `Fraction`s (the zero form as zeros)."""
    if isinstance(form, str):
        if form.strip() == "0":
            return np.full((4, 4), Fraction(0), dtype=object)
        return qsic.Quadric(form).matrix
    return np.array(form, dtype=object)


def row(columns: Dict[str, np.ndarray], k: int) -> Dict[str, Any]:
    """Row `k` of `classify_many` as the JSON result object (`case` 0 read as None)."""
    out: Dict[str, Any] = {}
    for key in qsic.FIELDS:
        v = columns[key][k]
        if key == "case":
            v = None if v == 0 else int(v)
        out[key] = v
    if "affine" in columns:
        out["affine"] = columns["affine"][k]
    return out
