//! Inputs found by the `batch_lines` fuzzer (`fuzz/`, README section "Fuzzing"), replayed
//! through the same invariant: one input per file under `tests/fuzz_regressions/batch_lines/`.

#[path = "../../../fuzz/src/batch.rs"]
mod batch;

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

#[test]
fn batch_lines_regressions() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fuzz_regressions/batch_lines");
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
            catch_unwind(AssertUnwindSafe(|| batch::batch_lines(&data))).is_err()
        })
        .map(|file| file.display().to_string())
        .collect();
    assert!(failed.is_empty(), "invariant broken on {failed:#?}");
}
