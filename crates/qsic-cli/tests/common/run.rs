//! Runs the built `qsic` binary with arguments and standard input.

use std::io::Write;
use std::process::{Command, Output, Stdio};

/// The output of `qsic ARGS < stdin` (a broken pipe on stdin is ignored: the binary may exit
/// before reading it all).
pub fn qsic(args: &[&str], stdin: &str) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_qsic"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the qsic binary starts");
    let mut input = child.stdin.take().expect("stdin");
    let _ = input.write_all(stdin.as_bytes());
    drop(input);
    child.wait_with_output().expect("qsic runs")
}
