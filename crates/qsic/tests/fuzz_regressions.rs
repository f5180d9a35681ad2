//! Inputs found by the fuzzers (`fuzz/`, README section "Fuzzing"), replayed through the
//! same invariants: one input per file under `tests/fuzz_regressions/<target>/`, named
//! after what broke (or `seed-…` for a starting input).

#[path = "../../../fuzz/src/library.rs"]
mod library;

#[path = "../../../fuzz/src/replay.rs"]
mod replay;

fn replay(target: &str, check: fn(&[u8])) {
    replay::replay(env!("CARGO_MANIFEST_DIR"), target, check);
}

#[test]
fn parse_polynomial_regressions() {
    replay("parse_polynomial", library::parse_polynomial);
}

#[test]
fn parse_expression_regressions() {
    replay("parse_expression", library::parse_expression);
}

#[test]
fn parse_number_regressions() {
    replay("parse_number", library::parse_number);
}

#[test]
fn classify_invariance_regressions() {
    replay("classify_invariance", library::classify_invariance);
}
