#!/bin/sh
# Instruction counts of the ingest figures in the README ("Speed"), with callgrind, one thread.
#
#   scripts/ingest_instructions.sh
#
# Batch: `qsic classify --projective --batch -` (JSON out) on 201 and on 1 line of each random corpus of
# the `random_corpus` example; (Ir(201) − Ir(1)) / 200 is the cost of one pair end to end.
# Library: inclusive Ir of `construct_and_classify` in the `ingest_cost` example (two
# `Quadric::from_integers`, or `from_f64`, and `classify` per pair) divided by the number of pairs.
set -eu
cd "$(dirname "$0")/.."
export RAYON_NUM_THREADS=1
cargo build --release -q -p qsic-cli -p qsic --bin qsic --example random_corpus --example ingest_cost
target=${CARGO_TARGET_DIR:-target}/release
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT


for family in matrix poly matrix-wide poly-fractions; do
    "$target/examples/random_corpus" 201 "$family" > "$tmp/$family.jsonl"
    head -n 1 "$tmp/$family.jsonl" > "$tmp/$family-1.jsonl"
    many=$(valgrind --tool=callgrind --callgrind-out-file="$tmp/cg" "$target/qsic" classify --projective --batch - < "$tmp/$family.jsonl" 2>&1 >/dev/null | sed -n 's/.*refs: *//p' | tr -d ,)
    one=$(valgrind --tool=callgrind --callgrind-out-file="$tmp/cg" "$target/qsic" classify --projective --batch - < "$tmp/$family-1.jsonl" 2>&1 >/dev/null | sed -n 's/.*refs: *//p' | tr -d ,)
    echo "batch, $family lines: $(( (many - one) / 200 )) instructions per pair"
done

n=2000
for kind in int f64; do
    valgrind --tool=callgrind --callgrind-out-file="$tmp/lib.cg" "$target/examples/ingest_cost" "$n" "$kind" >/dev/null 2>&1
    inclusive=$(callgrind_annotate --inclusive=yes "$tmp/lib.cg" | grep 'ingest_cost::construct_and_classify' | head -n 1 | awk '{print $1}' | tr -d ,)
    echo "library, $kind matrices: construction + classify: $(( inclusive / n )) instructions per pair"
done
