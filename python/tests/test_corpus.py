"""Known answers on the public corpora through `classify_many`, equal to the labels and to the
CLI's batch output (`qsic classify --batch`), field by field."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import AFFINE_CORPUS, CORPUS, as_matrix, cli_batch, read_jsonl, row

import qsic

LABELS = ("pencil", "case", "segre", "signature", "index_sequence", "complex_type", "real_type")


@pytest.mark.parametrize("name", ["cases.jsonl", "seed_examples.jsonl", "qi-quadrics.jsonl"])
def test_corpus_through_classify_many_equals_labels_and_cli(cli, name):
    lines = [r for r in read_jsonl(CORPUS / name) if not r.get("expect_error")]
    assert len(lines) >= 20
    A = np.array([as_matrix(r["A"]) for r in lines], dtype=object)
    B = np.array([as_matrix(r["B"]) for r in lines], dtype=object)
    cols = qsic.classify_many(A, B)
    answers = cli_batch(cli, [{"id": r["id"], "A": r["A"], "B": r["B"]} for r in lines], "--projective")
    for k, (line, answer) in enumerate(zip(lines, answers)):
        got = row(cols, k)
        assert got["pencil"] is not None, (line["id"], cols["error"][k])
        for key in LABELS:
            if key in line:
                assert got[key] == line[key], (line["id"], key)
        answer.pop("id")
        assert got == answer, line["id"]


def test_matrix_corpus_in_every_array_kind(cli):
    """The integer matrices of `cases.jsonl` as int64, float64 and object arrays agree."""
    lines = [
        line
        for line in read_jsonl(CORPUS / "cases.jsonl")
        if all(x.lstrip("-").isdigit() for m in (line["A"], line["B"]) for r in m for x in r)
    ]
    A = np.array([[[int(x) for x in r] for r in line["A"]] for line in lines], dtype=np.int64)
    B = np.array([[[int(x) for x in r] for r in line["B"]] for line in lines], dtype=np.int64)
    by_int = qsic.classify_many(A, B)
    for other in (
        qsic.classify_many(A.astype(np.float64), B.astype(np.float64)),
        qsic.classify_many(A.astype(object), B.astype(str)),
        qsic.classify_many(A, B, threads=1),
    ):
        for key in (*qsic.FIELDS, "error"):
            assert list(other[key]) == list(by_int[key]), key
    assert all(e is None for e in by_int["error"])
    assert by_int["case"].dtype == np.int8
    assert len(lines) > 150 and len(set(by_int["case"].tolist())) > 30
    assert list(by_int["case"]) == [line["case"] for line in lines]


def test_affine_corpus_equals_cli_and_labels(cli):
    lines = read_jsonl(AFFINE_CORPUS)
    answers = cli_batch(cli, [{"id": r["id"], "A": r["A"], "B": r["B"]} for r in lines])
    for line, answer in zip(lines, answers):
        got = qsic.classify(line["A"], line["B"]).to_dict()
        answer.pop("id")
        assert got == answer, line["id"]
        for key, value in line["affine"].items():
            assert got["affine"][key] == value, (line["id"], key)


def test_classify_many_rows_equal_classify_with_the_affine_view(cli):
    lines = read_jsonl(CORPUS / "seed_examples.jsonl")[:8]
    A = np.array([as_matrix(r["A"]) for r in lines], dtype=object)
    B = np.array([as_matrix(r["B"]) for r in lines], dtype=object)
    cols = qsic.classify_many(A, B, affine=True)
    answers = cli_batch(cli, [{"id": r["id"], "A": r["A"], "B": r["B"]} for r in lines])
    for k, line in enumerate(lines):
        single = qsic.classify(A[k], B[k])
        assert row(cols, k) == single.to_dict(), line["id"]
        answers[k].pop("id")
        assert single.to_dict() == answers[k], line["id"]
        assert isinstance(single.affine, dict) and single.affine["chart"] == "w"


def test_chart_and_projective_options_equal_cli(cli):
    lines = read_jsonl(AFFINE_CORPUS)[:6]
    records = [{"id": r["id"], "A": r["A"], "B": r["B"]} for r in lines]
    charted = cli_batch(cli, records, "--chart", "x+w")
    projective = cli_batch(cli, records, "--projective")
    A = np.array([as_matrix(r["A"]) for r in lines], dtype=object)
    B = np.array([as_matrix(r["B"]) for r in lines], dtype=object)
    cols = qsic.classify_many(A, B, affine=True, chart="x+w")
    for k, line in enumerate(lines):
        charted[k].pop("id")
        projective[k].pop("id")
        assert qsic.classify(line["A"], line["B"], chart="x+w").to_dict() == charted[k]
        assert qsic.classify(line["A"], line["B"], affine=False).to_dict() == projective[k]
        if not (qsic.Quadric(line["A"]).is_plane or qsic.Quadric(line["B"]).is_plane):
            assert row(cols, k) == charted[k], line["id"]
        assert charted[k]["affine"]["chart"] == "x+w"
    with pytest.raises(qsic.QsicError, match="chart"):
        qsic.classify(lines[0]["A"], lines[0]["B"], chart="x^2")
