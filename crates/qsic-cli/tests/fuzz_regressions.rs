//! Inputs found by the `batch_lines` fuzzer (`fuzz/`, README section "Fuzzing"), replayed
//! through the same invariant: one input per file under `tests/fuzz_regressions/batch_lines/`.

#[path = "../../../fuzz/src/batch.rs"]
mod batch;

#[path = "../../../fuzz/src/replay.rs"]
mod replay;

#[test]
fn batch_lines_regressions() {
    replay::replay(
        env!("CARGO_MANIFEST_DIR"),
        "batch_lines",
        batch::batch_lines,
    );
}
