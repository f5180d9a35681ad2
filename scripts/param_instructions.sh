#!/bin/sh
# Instruction counts of `qsic param --batch -` in the README ("Speed"), with callgrind, one thread.
#
#   scripts/param_instructions.sh
#
# On 201 and on 1 line of `scripts/param_pairs.py` (random symmetric integer matrices, entries in
# [-10, 10]): (Ir(201) − Ir(1)) / 200 is the cost of one pair end to end (reading, the curve, the
# exact expressions, the JSON), with `--projective` and with the affine data (the default); the
# inclusive Ir of `qsic::param::parameterize_within` (the CLI's entry; `parameterize` is inlined into it) in the same profiles, (201 lines − 1 line) / 200,
# is the curve's share.
set -eu
cd "$(dirname "$0")/.."
export RAYON_NUM_THREADS=1
cargo build --release -q -p qsic-cli --bin qsic
target=${CARGO_TARGET_DIR:-target}/release
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

python3 scripts/param_pairs.py 201 > "$tmp/201.jsonl"
head -n 1 "$tmp/201.jsonl" > "$tmp/1.jsonl"

# total Ir and inclusive Ir of `parameterize` of one run: "total parameterize"
run() {
    total=$(valgrind --tool=callgrind --callgrind-out-file="$tmp/cg" "$target/qsic" param "$@" 2>&1 >/dev/null | sed -n 's/.*refs: *//p' | tr -d ,)
    curve=$(callgrind_annotate --inclusive=yes "$tmp/cg" | grep -E ':qsic::param::parameterize(_within)? ' | head -n 1 | awk '{print $1}' | tr -d ,)
    echo "$total ${curve:-0}"
}

for mode in projective affine; do
    flag=""
    [ "$mode" = projective ] && flag=--projective
    # shellcheck disable=SC2086
    set -- $(run $flag --batch - < "$tmp/201.jsonl") $(run $flag --batch - < "$tmp/1.jsonl")
    echo "param --batch ($mode): $(( ($1 - $3) / 200 )) instructions per pair, parameterize $(( ($2 - $4) / 200 ))"
done
