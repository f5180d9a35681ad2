//! Runs the built `qsic` binary: single queries, errors, exit codes and batches.

use serde_json::Value;
use std::io::{Read, Write};
use std::process::{Command, Stdio};
use std::thread;
use std::time::{Duration, Instant};

/// What a run of the binary gave.
struct Run {
    code: Option<i32>,
    stdout: String,
    stderr: String,
}

/// Runs `qsic args…` with `stdin` as input; fails the test if it takes longer than `limit`.
fn qsic_with(args: &[&str], stdin: Vec<u8>, limit: Duration) -> Run {
    let mut child = Command::new(env!("CARGO_BIN_EXE_qsic"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the qsic binary starts");
    let mut input = child.stdin.take().expect("piped stdin");
    // Feed and drain on threads so that neither pipe can fill up and block the child.
    let feeder = thread::spawn(move || {
        // The child may exit before reading everything (usage errors): ignore EPIPE.
        let _ = input.write_all(&stdin);
    });
    let mut out = child.stdout.take().expect("piped stdout");
    let mut err = child.stderr.take().expect("piped stderr");
    let out_reader = thread::spawn(move || {
        let mut s = Vec::new();
        out.read_to_end(&mut s).map(|_| s)
    });
    let err_reader = thread::spawn(move || {
        let mut s = Vec::new();
        err.read_to_end(&mut s).map(|_| s)
    });
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("waiting on the child") {
            break status;
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            panic!("qsic {args:?} did not finish within {limit:?}");
        }
        thread::sleep(Duration::from_millis(20));
    };
    feeder.join().expect("feeder thread");
    let text = |bytes: Vec<u8>| String::from_utf8(bytes).expect("qsic writes UTF-8");
    Run {
        code: status.code(),
        stdout: text(
            out_reader
                .join()
                .expect("stdout thread")
                .expect("read stdout"),
        ),
        stderr: text(
            err_reader
                .join()
                .expect("stderr thread")
                .expect("read stderr"),
        ),
    }
}

fn qsic(args: &[&str]) -> Run {
    qsic_with(args, Vec::new(), Duration::from_secs(120))
}

fn json_lines(text: &str) -> Vec<Value> {
    text.lines()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("output line {l:?}: {e}")))
        .collect()
}

const CASE_1_A: &str = "x^2+y^2+z^2-w^2";
const CASE_1_B: &str = "2*x^2+4*y^2-w^2";

#[test]
fn single_query_human_report() {
    let run = qsic(&["classify", CASE_1_A, CASE_1_B]);
    assert_eq!(run.code, Some(0), "stderr: {}", run.stderr);
    for needle in [
        "pencil:           regular\n",
        "case:             1\n",
        "Segre:            [1111]_4\n",
        "index sequence:   <1|2|1|2|3>\n",
        "complex type:     smooth_quartic\n",
        "real type:        two_finite_components\n",
        "components:\n",
    ] {
        assert!(
            run.stdout.contains(needle),
            "missing {needle:?} in\n{}",
            run.stdout
        );
    }
}

#[test]
fn single_query_json() {
    let run = qsic(&["classify", "--json", CASE_1_A, CASE_1_B]);
    assert_eq!(run.code, Some(0), "stderr: {}", run.stderr);
    let lines = json_lines(&run.stdout);
    assert_eq!(lines.len(), 1);
    let v = &lines[0];
    assert_eq!(v["pencil"], "regular");
    assert_eq!(v["case"], 1);
    assert_eq!(v["complex_type"], "smooth_quartic");
    assert_eq!(v["real_type"], "two_finite_components");
    assert!(v["components"].is_array() && v["singular_points"].is_array());
    assert!(v.get("id").is_none());
}

#[test]
fn matrix_argument_and_zero_form() {
    let matrix = "[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,-1]]";
    let run = qsic(&[
        "classify",
        "--json",
        matrix,
        "[[2,0,0,0],[0,4,0,0],[0,0,0,0],[0,0,0,-1]]",
    ]);
    assert_eq!(run.code, Some(0), "stderr: {}", run.stderr);
    assert_eq!(json_lines(&run.stdout)[0]["case"], 1);
    let run = qsic(&["classify", "--json", "0", "x^2+y^2-z^2"]);
    assert_eq!(run.code, Some(0), "stderr: {}", run.stderr);
    assert_eq!(json_lines(&run.stdout)[0]["pencil"], "single");
}

#[test]
fn bad_single_queries_exit_1_with_the_argument_named() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["classify", CASE_1_A, "x^2+*y"],
            "error: B: syntax error at column 5",
        ),
        (
            &["classify", "x^2+q", CASE_1_B],
            "error: A: unknown variable 'q'",
        ),
        (&["classify", "0", "0"], "error: A and B"),
        (
            &["classify", "--json", "[[1,2],[3]]", CASE_1_B],
            "error: A: a quadric matrix must be 4x4",
        ),
        (
            &["classify", CASE_1_A, "[[1,0,0,0],"],
            "error: B: invalid JSON matrix",
        ),
    ];
    for (args, needle) in cases {
        let run = qsic(args);
        assert_eq!(run.code, Some(1), "{args:?}");
        assert!(run.stdout.is_empty(), "{args:?}: stdout {:?}", run.stdout);
        assert!(
            run.stderr.starts_with(needle),
            "{args:?}: stderr {:?}",
            run.stderr
        );
    }
}

#[test]
fn usage_errors_exit_2_and_help_exits_0() {
    for args in [
        &["classify", CASE_1_A][..],
        &["classify", "--batch", "-", CASE_1_A, CASE_1_B],
        &["frobnicate"],
    ] {
        assert_eq!(qsic(args).code, Some(2), "{args:?}");
    }
    let missing = qsic(&["classify", "--batch", "/nonexistent/qsic/input.jsonl"]);
    assert_eq!(missing.code, Some(2));
    assert!(
        missing.stderr.starts_with("error: cannot open"),
        "{}",
        missing.stderr
    );
    let help = qsic(&["classify", "--help"]);
    assert_eq!(help.code, Some(0));
    assert!(help.stdout.contains("--batch") && help.stdout.contains("EXIT STATUS"));
    let top = qsic(&["--help"]);
    assert_eq!(top.code, Some(0));
    assert!(top.stdout.contains("classify"));
    let version = qsic(&["--version"]);
    assert_eq!(version.code, Some(0));
    assert!(version.stdout.starts_with("qsic "), "{}", version.stdout);
}

#[test]
fn batch_mixes_results_and_errors_in_order() {
    let identity = "[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,-1]]";
    let lines = [
        format!(r#"{{"id": "good", "A": "{CASE_1_A}", "B": "{CASE_1_B}"}}"#),
        r#"{"id": "broken", "A": "x^2""#.to_string(),
        format!(
            r#"{{"id": "asym", "A": [[1,2,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]], "B": {identity}}}"#
        ),
        "   ".to_string(),
        format!(
            r#"{{"id": "nan", "A": [["nan",0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]], "B": {identity}}}"#
        ),
        format!(
            r#"{{"id": "bare-nan", "A": [[NaN,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]], "B": {identity}}}"#
        ),
        String::new(),
        format!(r#"{{"id": 42, "A": {identity}, "B": "2*x^2+4*y^2-w^2"}}"#),
        format!(r#"{{"id": {{"run": 3, "tags": ["a"]}}, "A": "0", "B": "{CASE_1_A}"}}"#),
        format!(r#"{{"id": 123456789012345678901234567890, "A": ["1/2"], "B": "{CASE_1_A}"}}"#),
        format!(r#"{{"B": "{CASE_1_A}"}}"#),
    ];
    let input = lines.join("\n") + "\n";
    let run = qsic_with(
        &["classify", "--batch", "-"],
        input.into_bytes(),
        Duration::from_secs(120),
    );
    assert_eq!(run.code, Some(1), "stderr: {}", run.stderr);
    assert!(
        run.stderr.is_empty(),
        "batch errors go to stdout: {}",
        run.stderr
    );
    let out = json_lines(&run.stdout);
    // (id, Some(input line) for an error / None for a result, text in the error message)
    let expected: &[(Value, Option<u64>, &str)] = &[
        ("good".into(), None, ""),
        (Value::Null, Some(2), "invalid JSON"),
        ("asym".into(), Some(3), "A: matrix is not symmetric"),
        ("nan".into(), Some(5), "A: entry (0,0): bad number 'nan'"),
        (Value::Null, Some(6), "invalid JSON"),
        (42.into(), None, ""),
        (serde_json::json!({"run": 3, "tags": ["a"]}), None, ""),
        (
            serde_json::from_str("123456789012345678901234567890").expect("a JSON number"),
            Some(10),
            "A: row 0 of the matrix must be an array",
        ),
        (Value::Null, Some(11), "missing field \"A\""),
    ];
    assert_eq!(
        out.len(),
        expected.len(),
        "one output per non-blank line:\n{}",
        run.stdout
    );
    for (i, ((id, error_line, needle), v)) in expected.iter().zip(&out).enumerate() {
        assert_eq!(&v["id"], id, "output {i}");
        match error_line {
            None => assert!(
                v.get("error").is_none() && v["pencil"].is_string(),
                "output {i}: {v}"
            ),
            Some(line) => {
                assert_eq!(v["error"]["line"], *line, "output {i}");
                let message = v["error"]["message"].as_str().unwrap_or_default();
                assert!(
                    message.contains(needle),
                    "output {i}: {message:?} lacks {needle:?}"
                );
            }
        }
    }
    assert_eq!(out[0]["case"], 1);
    assert_eq!(out[5]["case"], 1);
    assert_eq!(out[6]["pencil"], "single");
    // The big id is copied digit for digit.
    let raw_ids: Vec<&str> = run.stdout.lines().collect();
    assert!(
        raw_ids[7].starts_with(r#"{"id":123456789012345678901234567890,"#),
        "{}",
        raw_ids[7]
    );
}

#[test]
fn batch_survives_over_long_and_non_utf8_lines() {
    let mut input = vec![b' '; 3 << 20]; // 3 MiB without a newline, then more lines
    input.extend_from_slice(b"x\n{\"id\": 1, \"A\": \"x\xff\"}\n");
    input.extend_from_slice(
        format!(r#"{{"id": 2, "A": "{CASE_1_A}", "B": "{CASE_1_B}"}}"#).as_bytes(),
    );
    let run = qsic_with(
        &["classify", "--batch", "-"],
        input,
        Duration::from_secs(120),
    );
    assert_eq!(run.code, Some(1), "stderr: {}", run.stderr);
    let out = json_lines(&run.stdout);
    assert_eq!(out.len(), 3);
    assert_eq!(out[0]["error"]["line"], 1);
    assert!(out[0]["error"]["message"]
        .as_str()
        .is_some_and(|m| m.contains("exceeds the limit")));
    assert_eq!(out[1]["error"]["line"], 2);
    assert!(out[1]["error"]["message"]
        .as_str()
        .is_some_and(|m| m.contains("UTF-8")));
    assert_eq!(out[2]["id"], 2);
    assert_eq!(out[2]["case"], 1);
}

/// Every labelled line of the case corpus, labels left in: the CLI must read only id, A
/// and B, and give the labelled case.
#[test]
fn case_corpus_through_batch_gives_every_labelled_case() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../qsic/tests/data/cases.jsonl"
    );
    let input = std::fs::read_to_string(path).expect("the case corpus is readable");
    let run = qsic_with(
        &["classify", "--batch", "-"],
        input.clone().into_bytes(),
        Duration::from_secs(300),
    );
    let inputs: Vec<(usize, Value)> = input
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
        .map(|(i, l)| {
            (
                i + 1,
                serde_json::from_str(l).expect("corpus lines are JSON"),
            )
        })
        .collect();
    let out = json_lines(&run.stdout);
    assert_eq!(out.len(), inputs.len(), "one output per corpus line");
    let mismatches: Vec<String> = inputs
        .iter()
        .zip(&out)
        .filter(|((_, i), o)| i["id"] != o["id"] || i["case"] != o["case"])
        .map(|((line, i), o)| {
            format!(
                "line {line} ({}): expected case {}, got {}",
                i["id"], i["case"], o
            )
        })
        .collect();
    assert!(mismatches.is_empty(), "{}", mismatches.join("\n"));
    assert_eq!(run.code, Some(0), "stderr: {}", run.stderr);
}

/// The pairs that once aborted a whole batch (roots 10⁻¹⁶⁰⁰ and 10⁻⁶⁰⁰⁰ apart, all roots
/// squeezed below 4·10⁻⁶⁰⁰⁰, 2 000-digit coefficients), between ordinary lines and a line
/// over a limit: every line is answered, in order, with the right case.
#[test]
fn batch_answers_clustered_and_huge_lines() {
    let digits = |seed: u64| -> String {
        // 2 000 pseudo-random digits, leading digit nonzero
        let mut x = seed;
        (0..2000)
            .map(|i| {
                x = x
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                let d = (x >> 60) % 10;
                char::from(b'0' + if i == 0 { d.max(1) as u8 } else { d as u8 })
            })
            .collect()
    };
    let sphere = "x^2+y^2+z^2-w^2";
    let lines = [
        (
            sphere.to_string(),
            "x^2+(1+1e-1600)*y^2+2*z^2+3*w^2".to_string(),
            Some(2),
        ),
        (CASE_1_A.to_string(), CASE_1_B.to_string(), Some(1)),
        (
            format!("{sphere}+1e-6000*x^2"),
            "2*x^2+4*y^2-w^2".to_string(),
            Some(1),
        ),
        ("1e99999*x^2".to_string(), sphere.to_string(), None),
        (
            sphere.to_string(),
            "x^2+(1+1e-6000)*y^2+2*z^2+3*w^2".to_string(),
            Some(2),
        ),
        (
            format!(
                "{}*x^2+{}*y^2-z^2+{}*w^2+x*y",
                digits(1),
                digits(2),
                digits(3)
            ),
            format!("x^2+2*y^2+{}*z^2-3*w^2+y*z", digits(4)),
            Some(2),
        ),
        (CASE_1_A.to_string(), CASE_1_B.to_string(), Some(1)),
    ];
    let input: String = lines
        .iter()
        .enumerate()
        .map(|(i, (a, b, _))| format!("{{\"id\": {i}, \"A\": \"{a}\", \"B\": \"{b}\"}}\n"))
        .collect();
    let run = qsic_with(
        &["classify", "--batch", "-"],
        input.into_bytes(),
        Duration::from_secs(300),
    );
    let out = json_lines(&run.stdout);
    assert_eq!(out.len(), lines.len(), "stderr: {}", run.stderr);
    for (i, ((_, _, case), o)) in lines.iter().zip(&out).enumerate() {
        assert_eq!(o["id"], i, "{o}");
        match case {
            Some(c) => assert_eq!(o["case"], *c, "line {i}: {o}"),
            None => assert!(
                o["error"]["message"]
                    .as_str()
                    .is_some_and(|e| e.contains("exceeds a limit")),
                "line {i}: {o}"
            ),
        }
    }
}
