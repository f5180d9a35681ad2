//! Invariant of the batch reader. Also compiled into
//! `crates/qsic-cli/tests/fuzz_regressions.rs`, so it uses nothing but `qsic_cli` and
//! `serde_json`.

use serde_json::Value;

/// `qsic classify --batch` answers every line: one output line per non-blank input line
/// (blank: only ASCII whitespace, after a byte-order mark at the start), each a JSON object
/// with an `id`.
pub fn batch_lines(data: &[u8]) {
    let mut out = Vec::new();
    if let Err(e) = qsic_cli::batch::run(data, &mut out, false) {
        panic!("a batch from memory into memory failed: {e:?}");
    }
    // a byte-order mark at the very start is skipped
    let lines = data.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(data);
    let non_blank = lines
        .split(|&b| b == b'\n')
        .filter(|line| !line.iter().all(u8::is_ascii_whitespace))
        .count();
    let text = String::from_utf8(out).expect("the output is UTF-8");
    let answers: Vec<&str> = text.lines().collect();
    assert_eq!(answers.len(), non_blank, "output:\n{text}");
    for answer in answers {
        let value: Value = serde_json::from_str(answer).expect("each answer is JSON");
        assert!(value.get("id").is_some(), "no id in {answer}");
    }
}
