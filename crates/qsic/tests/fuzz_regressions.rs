//! Inputs found by the fuzzers (`fuzz/`, README section "Fuzzing"), replayed through the
//! same invariants: one input per file under `tests/fuzz_regressions/<target>/`, named
//! after what broke (or `seed-…` for a starting input).

#[path = "../../../fuzz/src/library.rs"]
mod library;

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

/// Runs `check` on every file of the target's directory; fails naming every file that panics.
fn replay(target: &str, check: fn(&[u8])) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fuzz_regressions")
        .join(target);
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .expect("the regression directory exists")
        .map(|entry| entry.expect("a directory entry").path())
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no inputs in {}", dir.display());
    let failed: Vec<String> = files
        .iter()
        .filter(|file| {
            let data = std::fs::read(file).expect("a readable input");
            catch_unwind(AssertUnwindSafe(|| check(&data))).is_err()
        })
        .map(|file| file.display().to_string())
        .collect();
    assert!(failed.is_empty(), "invariant broken on {failed:#?}");
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
