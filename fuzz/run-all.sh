#!/usr/bin/env bash
# Runs every fuzz target in turn: ./run-all.sh [seconds per target] (default 600).
set -u
cd "$(dirname "$0")"
secs=${1:-600}
for t in parse_polynomial parse_expression parse_number classify_invariance batch_lines; do
  case $t in
    parse_polynomial) extra=(-dict=dict/polynomial.dict -max_len=256) ;;
    parse_expression) extra=(-dict=dict/polynomial.dict -max_len=256) ;;
    parse_number) extra=(-dict=dict/polynomial.dict -max_len=128) ;;
    classify_invariance) extra=(-max_len=256) ;;
    batch_lines) extra=(-dict=dict/batch.dict -max_len=512) ;;
  esac
  mkdir -p corpus/$t
  RUSTC_BOOTSTRAP=1 nice -n 10 cargo fuzz run -O --debug-assertions "$t" corpus/$t seeds/$t -- \
    -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 \
    -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 "${extra[@]}"
done
