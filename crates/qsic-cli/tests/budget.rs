//! `--line-budget`: a line over its budget is an error line between answered lines, the same
//! on every run; a single query over it fails with the budget's message; a bad budget is a
//! usage error.

use std::io::Write;
use std::process::{Command, Output, Stdio};

fn qsic(args: &[&str], input: &str) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_qsic"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(input.as_bytes())
        .unwrap();
    child.wait_with_output().unwrap()
}

fn lines(out: &Output) -> Vec<serde_json::Value> {
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

/// Two exact-path pairs (a tangency, a double root) around one whose roots are 10⁻¹⁶⁰⁰
/// apart: its long numbers cost far more than the others.
const BATCH: &str = r#"{"id":1,"A":"x^2+y^2+z^2-1","B":"x^2+2*y^2-1"}
{"id":2,"A":"x^2+y^2+z^2-w^2","B":"x^2+(1+1e-1600)*y^2+2*z^2+3*w^2"}
{"id":3,"A":"x^2+y^2+z^2-1","B":"(x-2)^2+y^2+z^2-1"}
"#;

#[test]
fn a_line_over_its_budget_is_an_error_between_answered_lines() {
    let args = [
        "classify",
        "--projective",
        "--line-budget",
        "1e5",
        "--batch",
        "-",
    ];
    let out = qsic(&args, BATCH);
    assert_eq!(out.status.code(), Some(1), "an error line");
    let got = lines(&out);
    let ids: Vec<i64> = got.iter().map(|v| v["id"].as_i64().unwrap()).collect();
    assert_eq!(ids, [1, 2, 3]);
    assert_eq!(got[0]["case"], 13);
    assert_eq!(got[2]["case"], 25);
    assert_eq!(got[1]["error"]["line"], 2);
    let message = got[1]["error"]["message"].as_str().unwrap();
    assert!(
        message.starts_with("over the work budget: 100000 units"),
        "{message}"
    );
    // deterministic: the same bytes on another run
    assert_eq!(qsic(&args, BATCH).stdout, out.stdout);
    // the default budget answers every line
    let all = lines(&qsic(&["classify", "--projective", "--batch", "-"], BATCH));
    assert!(all.iter().all(|v| v.get("error").is_none()), "{all:?}");
    assert_eq!((&all[0], &all[2]), (&got[0], &got[2]));
}

#[test]
fn param_and_sample_lines_take_the_budget() {
    let line = r#"{"id":"v","A":"x^2+y^2+z^2-4","B":"(x-1)^2+y^2-1"}
"#;
    for over_args in [
        &["param", "--line-budget", "1000", "--batch", "-"][..],
        &[
            "sample",
            "--points",
            "100000",
            "--line-budget",
            "1e6",
            "--batch",
            "-",
        ][..],
    ] {
        let over = lines(&qsic(over_args, line));
        let message = over[0]["error"]["message"].as_str().unwrap();
        assert!(message.starts_with("over the work budget"), "{message}");
        let command = over_args[0];
        let answered = lines(&qsic(
            &[command, "--line-budget", "1e9", "--batch", "-"],
            line,
        ));
        assert_eq!(answered[0]["case"], 5, "{command}: Viviani's curve");
    }
}

#[test]
fn a_single_query_over_its_budget_fails_with_the_message() {
    let out = qsic(
        &[
            "classify",
            "--line-budget",
            "100",
            "x^2+y^2+z^2-1",
            "x^2+2*y^2-1",
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("over the work budget: 100 units"), "{err}");
    let ok = qsic(
        &[
            "classify",
            "--line-budget",
            "1000000",
            "x^2+y^2+z^2-1",
            "x^2+2*y^2-1",
        ],
        "",
    );
    assert_eq!(ok.status.code(), Some(0));
}

#[test]
fn a_bad_budget_is_a_usage_error() {
    for bad in ["0", "-5", "1.5", "1e20", "x", "", "1e"] {
        let out = qsic(&["classify", "--line-budget", bad, "x^2-1", "y^2-1"], "");
        assert_eq!(out.status.code(), Some(2), "{bad}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("--line-budget"), "{bad}: {err}");
    }
    for good in ["250000", "25e8", "18446744073709551615"] {
        let out = qsic(&["classify", "--line-budget", good, "x^2-1", "y^2-1"], "");
        assert_eq!(out.status.code(), Some(0), "{good}");
    }
}
