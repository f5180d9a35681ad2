//! What every `--batch` command reads, through the binary: a byte-order mark at the start of
//! the input (standard input or a file), repeated fields, and the line limit at its boundary
//! with either terminator.

#[path = "common/run.rs"]
mod run;

use qsic_cli::batch::MAX_LINE_BYTES;
use run::qsic;
use serde_json::Value;

const SPHERE: &str = "x^2+y^2+z^2-w^2";
const CYLINDER: &str = "2*x^2+4*y^2-w^2";

fn answers(stdout: &[u8]) -> Vec<Value> {
    String::from_utf8(stdout.to_vec())
        .expect("UTF-8 output")
        .lines()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{l:?}: {e}")))
        .collect()
}

/// Each `--batch` command with a line it answers.
fn commands() -> [(&'static str, String); 4] {
    let pair = format!(r#"{{"id": 1, "A": "{SPHERE}", "B": "{CYLINDER}"}}"#);
    let moving = r#"{"id": 1, "A": "x^2+y^2+z^2-4", "B": "(x-t)^2+y^2+z^2-1"}"#;
    [
        ("classify", pair.clone()),
        ("param", pair.clone()),
        ("sample", pair),
        ("motion", moving.to_string()),
    ]
}

#[test]
fn a_byte_order_mark_at_the_start_is_skipped_on_stdin_and_in_files() {
    let dir = std::env::temp_dir().join(format!("qsic-batch-input-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    for (command, line) in commands() {
        let input = format!("\u{feff}{line}\r\n{line}\n");
        let file = dir.join(format!("{command}.jsonl"));
        std::fs::write(&file, &input).expect("the batch file is written");
        let path = file.to_str().expect("a UTF-8 path");
        for (source, stdin) in [("-", input.as_str()), (path, "")] {
            let out = qsic(&[command, "--batch", source], stdin);
            let lines = answers(&out.stdout);
            assert_eq!(lines.len(), 2, "{command} {source}");
            assert_eq!(out.status.code(), Some(0), "{command} {source}: {lines:?}");
            assert_eq!(lines[0], lines[1], "{command} {source}: line 1 as line 2");
            assert!(
                lines[0].get("error").is_none(),
                "{command} {source}: {}",
                lines[0]
            );
        }
        // a mark elsewhere is not skipped: the line is not JSON
        let out = qsic(
            &[command, "--batch", "-"],
            &format!("{line}\n\u{feff}{line}\n"),
        );
        let lines = answers(&out.stdout);
        assert_eq!(out.status.code(), Some(1), "{command}");
        assert_eq!(lines[1]["error"]["line"], 2, "{command}");
        let message = lines[1]["error"]["message"].as_str().expect("a message");
        assert!(message.starts_with("invalid JSON"), "{command}: {message}");
    }
    std::fs::remove_dir_all(&dir).expect("the temporary directory is removed");
}

#[test]
fn repeated_fields_are_error_lines_for_every_batch_command() {
    for (command, line) in commands() {
        let twice_b = line.replacen(r#""B""#, r#""B": "x^2", "B""#, 1);
        let twice_id = line.replacen(r#""id": 1"#, r#""id": 1, "id": 2"#, 1);
        let out = qsic(
            &[command, "--batch", "-"],
            &format!("{twice_b}\n{twice_id}\n{line}\n"),
        );
        let lines = answers(&out.stdout);
        assert_eq!(out.status.code(), Some(1), "{command}");
        assert_eq!(lines.len(), 3, "{command}");
        let want = |id: Value, line: u64, key: &str| serde_json::json!({"id": id, "error": {"line": line, "message": format!("duplicate field \"{key}\"")}});
        assert_eq!(lines[0], want(1.into(), 1, "B"), "{command}");
        assert_eq!(lines[1], want(Value::Null, 2, "id"), "{command}");
        assert!(lines[2].get("error").is_none(), "{command}: {}", lines[2]);
    }
}

/// A batch line of exactly `len` bytes: the pair, padded with spaces inside the object.
fn line_of(len: usize) -> String {
    let body = format!(r#""id": 1, "A": "{SPHERE}", "B": "{CYLINDER}"}}"#);
    let pad = len - body.len() - 1;
    format!("{{{}{body}", " ".repeat(pad))
}

#[test]
fn the_line_limit_counts_neither_the_terminator_nor_a_byte_order_mark() {
    let at_limit = line_of(MAX_LINE_BYTES);
    let over = line_of(MAX_LINE_BYTES + 1);
    assert_eq!(
        (at_limit.len(), over.len()),
        (MAX_LINE_BYTES, MAX_LINE_BYTES + 1)
    );
    for end in ["\n", "\r\n"] {
        let input = format!("\u{feff}{at_limit}{end}{at_limit}{end}{over}{end}{over}");
        let out = qsic(&["classify", "--projective", "--batch", "-"], &input);
        let lines = answers(&out.stdout);
        assert_eq!(lines.len(), 4, "{end:?}");
        assert_eq!(out.status.code(), Some(1), "{end:?}");
        let message = format!(
            "line of {} bytes exceeds the limit of {MAX_LINE_BYTES} bytes",
            MAX_LINE_BYTES + 1
        );
        for (k, answer) in lines.iter().enumerate() {
            let number = k + 1;
            if number <= 2 {
                assert_eq!(answer["case"], 1, "{end:?}: line {number}: {answer}");
            } else {
                let want =
                    serde_json::json!({"id": null, "error": {"line": number, "message": message}});
                assert_eq!(*answer, want, "{end:?}: line {number}");
            }
        }
    }
}
