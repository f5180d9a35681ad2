//! Runs the built `qsic motion`: single queries (text and JSON), ranges, batches with the
//! corpus of moving quadrics, errors and exit codes.

use serde_json::Value;
use std::io::Write;
use std::process::{Command, Stdio};

/// Exit code, stdout and stderr of `qsic args…` fed `stdin` (small inputs only).
fn qsic(args: &[&str], stdin: &str) -> (Option<i32>, String, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_qsic"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the qsic binary starts");
    // The child may exit before reading (usage errors): ignore a broken pipe.
    let _ = child
        .stdin
        .take()
        .expect("piped")
        .write_all(stdin.as_bytes());
    let out = child.wait_with_output().expect("qsic runs");
    let text = |b: Vec<u8>| String::from_utf8(b).expect("UTF-8");
    (out.status.code(), text(out.stdout), text(out.stderr))
}

fn json(line: &str) -> Value {
    serde_json::from_str(line).unwrap_or_else(|e| panic!("{line:?}: {e}"))
}

const FIXED: &str = "x^2+y^2+z^2-4";
const MOVING: &str = "(x-t)^2+y^2+z^2-1";

/// The type of a JSON instant or interval.
fn kind(v: &Value) -> (Value, Value, Value, Value) {
    (
        v["pencil"].clone(),
        v["case"].clone(),
        v["complex_type"].clone(),
        v["real_type"].clone(),
    )
}

#[test]
fn single_motion_text_and_json_agree() {
    let (code, text, err) = qsic(&["motion", FIXED, MOVING], "");
    assert_eq!(code, Some(0), "{err}");
    let (code, out, err) = qsic(&["motion", "--json", FIXED, MOVING], "");
    assert_eq!(code, Some(0), "{err}");
    let v = json(out.trim());
    assert!(v.get("id").is_none());
    let instants = v["instants"].as_array().unwrap();
    let ts: Vec<&str> = instants.iter().map(|i| i["t"].as_str().unwrap()).collect();
    assert_eq!(ts, ["-3", "-1", "0", "1", "3"]);
    let intervals = v["intervals"].as_array().unwrap();
    assert_eq!(intervals.len(), 6);
    assert!(intervals[0]["from"].is_null() && intervals[5]["to"].is_null());
    assert_eq!(intervals[4]["real_type"], "one_conic");
    // the text timeline: a header, then intervals and instants alternating
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 1 + 6 + 5, "{text}");
    for (k, i) in instants.iter().enumerate() {
        let line = lines[2 + 2 * k];
        assert!(line.contains(&format!("t = {}", ts[k])), "{line}");
        assert!(line.contains(i["complex_type"].as_str().unwrap()), "{line}");
    }
    assert!(lines[1].starts_with("  t in (-oo, -3)"), "{}", lines[1]);
}

#[test]
fn range_restricts_and_reports_the_ends() {
    let (code, out, err) = qsic(
        &["motion", "--json", "--range", "-1", "2", FIXED, MOVING],
        "",
    );
    assert_eq!(code, Some(0), "{err}");
    let v = json(out.trim());
    let ts: Vec<&str> = v["instants"]
        .as_array()
        .unwrap()
        .iter()
        .map(|i| i["t"].as_str().unwrap())
        .collect();
    // -1 (inner tangency) is an end whose type differs; 2 is inside a circle interval
    assert_eq!(ts, ["-1", "0", "1"]);
    let intervals = v["intervals"].as_array().unwrap();
    assert_eq!(intervals.len(), 3);
    assert_eq!(intervals[0]["from"], "-1");
    assert_eq!(intervals[2]["to"], "2");
    for (args, needle) in [
        (
            ["2", "1"],
            "--range: invalid time range: the start 2 is above the end 1",
        ),
        (
            ["a", "1"],
            "--range: invalid time range: the start is not a number",
        ),
    ] {
        let (code, _, err) = qsic(&["motion", "--range", args[0], args[1], FIXED, MOVING], "");
        assert_eq!(code, Some(2), "{args:?}");
        assert!(err.contains(needle), "{err}");
    }
    let (code, out, _) = qsic(
        &["motion", "--json", "--range", "-oo", "oo", FIXED, MOVING],
        "",
    );
    assert_eq!(code, Some(0));
    assert_eq!(json(out.trim())["intervals"].as_array().unwrap().len(), 6);
}

/// The corpus through `--batch -`: every recorded instant and type; then a batch mixing
/// results and errors keeps order, ids and line numbers, and exits 1.
#[test]
fn batch_answers_the_corpus_and_reports_errors_in_order() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../qsic/tests/data/moving.jsonl"
    );
    let corpus: Vec<Value> = std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(json)
        .collect();
    let feed: String = corpus
        .iter()
        .map(|d| serde_json::json!({"id": d["id"], "A": d["A"], "B": d["B"]}).to_string() + "\n")
        .collect();
    let (code, out, err) = qsic(&["motion", "--batch", "-"], &feed);
    assert_eq!(code, Some(0), "{err}");
    let answers: Vec<Value> = out.lines().map(json).collect();
    assert_eq!(answers.len(), corpus.len());
    for (want, got) in corpus.iter().zip(&answers) {
        assert_eq!(want["id"], got["id"]);
        let (wi, gi) = (
            want["instants"].as_array().unwrap(),
            got["instants"].as_array().unwrap(),
        );
        assert_eq!(wi.len(), gi.len(), "{}", got["id"]);
        for (w, g) in wi.iter().zip(gi) {
            assert_eq!(kind(w), kind(g), "{}", got["id"]);
            match (&w["t"], &g["t"]) {
                (Value::String(a), Value::String(b)) => assert_eq!(a, b),
                (a, b) => {
                    let x = |v: &Value| v["approx"].as_str().unwrap().parse::<f64>().unwrap();
                    assert!((x(a) - x(b)).abs() < 1e-9, "{a} vs {b}");
                    assert_eq!(a["poly"].as_str().unwrap().replace("**", "^"), b["poly"]);
                }
            }
        }
        let types = |v: &Value| -> Vec<_> {
            v["intervals"]
                .as_array()
                .unwrap()
                .iter()
                .map(kind)
                .collect()
        };
        assert_eq!(types(want), types(got), "{}", got["id"]);
    }
    let lines = [
        format!(r#"{{"id": "ok", "A": "{FIXED}", "B": "{MOVING}"}}"#),
        String::new(),
        r#"{"id": 2, "A": [["t",0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,"t^2"]], "B": "x^2 + sin(t)*y^2"}"#.into(),
        r#"{"id": 3, "A": [["1","t",0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]], "B": "x^2"}"#.into(),
        r#"{"id": 4, "A": "(t-t)*x^2", "B": "x^2"}"#.into(),
        r#"{"id": 5, "A": "t^40*x^2 + y^2", "B": "x^2"}"#.into(),
        r#"{"id": 6, "A": "x^2"}"#.into(),
        "not json".into(),
    ];
    let (code, out, _) = qsic(&["motion", "--batch", "-"], &(lines.join("\n") + "\n"));
    assert_eq!(code, Some(1));
    let answers: Vec<Value> = out.lines().map(json).collect();
    assert_eq!(answers.len(), 7);
    assert_eq!(answers[0]["id"], "ok");
    assert_eq!(answers[0]["instants"].as_array().unwrap().len(), 5);
    let errors = [
        (2, 3, "B: unknown variable 'sin'"),
        (3, 4, "A: matrix is not symmetric"),
        (4, 5, "A: "),
        (5, 6, "A and B: input exceeds a limit"),
        (6, 7, "missing field \"B\""),
    ];
    for (k, (id, line, needle)) in errors.iter().enumerate() {
        let e = &answers[k + 1];
        assert_eq!(e["id"], *id);
        assert_eq!(e["error"]["line"], *line);
        let message = e["error"]["message"].as_str().unwrap();
        assert!(message.starts_with(needle), "{message}");
    }
    assert!(answers[6]["id"].is_null() && answers[6]["error"]["line"] == 8);
}

#[test]
fn bad_single_motions_exit_1_and_usage_errors_2() {
    for (a, b, needle) in [
        ("x^2 + q*t", MOVING, "error: A: unknown variable 'q'"),
        (FIXED, "[[1,0],[0,1]]", "error: B: "),
        (FIXED, "[[1,0,0,0],", "error: B: invalid JSON matrix"),
        ("(t^2 - t^2)*x^2", MOVING, "error: A: "),
    ] {
        let (code, out, err) = qsic(&["motion", a, b], "");
        assert_eq!(code, Some(1), "{a}, {b}");
        assert!(out.is_empty());
        assert!(err.starts_with(needle), "{err}");
    }
    assert_eq!(qsic(&["motion", FIXED], "").0, Some(2));
    assert_eq!(
        qsic(&["motion", "--batch", "-", FIXED, MOVING], "").0,
        Some(2)
    );
    let (code, help, _) = qsic(&["motion", "--help"], "");
    assert_eq!(code, Some(0));
    assert!(help.contains("--range") && help.contains("RANGE") && help.contains("EXIT STATUS"));
}

/// `--plot FILE` writes an SVG with one band per interval and one tick per instant and keeps
/// the usual output; an unwritable path exits 2; `--plot` with `--batch` is a usage error.
#[test]
fn plot_writes_an_svg_and_reports_errors() {
    let dir = std::env::temp_dir().join(format!("qsic-motion-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("out.svg");
    let p = path.to_str().unwrap();
    let (code, out, err) = qsic(&["motion", "--json", "--plot", p, FIXED, MOVING], "");
    assert_eq!(code, Some(0), "{err}");
    let v = json(out.trim());
    let svg = std::fs::read_to_string(&path).unwrap();
    assert!(svg.starts_with("<?xml") && svg.trim_end().ends_with("</svg>"));
    assert_eq!(
        svg.matches("<rect class=\"band\"").count(),
        v["intervals"].as_array().unwrap().len()
    );
    assert_eq!(
        svg.matches("<line class=\"tick\"").count(),
        v["instants"].as_array().unwrap().len()
    );
    // one snapshot of the curve per interval
    assert_eq!(
        svg.matches("<g class=\"snapshot\"").count(),
        v["intervals"].as_array().unwrap().len()
    );
    for i in v["instants"].as_array().unwrap() {
        assert!(svg.contains(&format!(">t = {}<", i["t"].as_str().unwrap())));
        assert!(svg.contains(i["real_type"].as_str().unwrap()));
    }
    // an unwritable path (a missing directory): exit 2, nothing on stdout
    let bad = dir.join("missing").join("out.svg");
    let (code, out, err) = qsic(
        &["motion", "--plot", bad.to_str().unwrap(), FIXED, MOVING],
        "",
    );
    assert_eq!(code, Some(2));
    assert!(out.is_empty() && err.contains("writing the plot"), "{err}");
    // bad input: exit 1 and no file
    let none = dir.join("none.svg");
    let (code, _, _) = qsic(
        &["motion", "--plot", none.to_str().unwrap(), "x^2+q", MOVING],
        "",
    );
    assert_eq!(code, Some(1));
    assert!(!none.exists());
    assert_eq!(
        qsic(&["motion", "--batch", "-", "--plot", p], "").0,
        Some(2)
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
