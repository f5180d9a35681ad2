//! The invariants the fuzz targets assert, one cheap invariant per target. Each function
//! panics when its invariant fails; the saved regressions under `crates/*/tests/fuzz_regressions`
//! replay them in the ordinary test suite, which includes these files by path.

pub mod batch;
pub mod library;
