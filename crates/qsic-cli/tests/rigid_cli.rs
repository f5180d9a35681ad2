//! Runs `qsic motion` and `qsic contact` on quadrics under rigid motions given in the JSON
//! object form, end to end: the contact instant and point known by construction, the object
//! equal to the matrix it stands for, errors named.

use serde_json::Value;
use std::process::Command;

/// Exit code, stdout and stderr of `qsic args…`.
fn qsic(args: &[&str]) -> (Option<i32>, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_qsic"))
        .args(args)
        .output()
        .expect("the qsic binary runs");
    let text = |b: Vec<u8>| String::from_utf8(b).expect("UTF-8 output");
    (out.status.code(), text(out.stdout), text(out.stderr))
}

fn json(args: &[&str]) -> Value {
    let (code, out, err) = qsic(args);
    assert_eq!(code, Some(0), "{args:?}: {err}");
    serde_json::from_str(&out).expect("one JSON object")
}

/// The ellipsoid x²/4 + y² + z² = 1 turning about z (t = tan(θ/2)) first touches the sphere
/// of radius 3 about (3, 4, 0) with a tip, at (6/5, 8/5, 0): at t = −2 from −∞, at t = 1/2
/// on [0, ∞) (`crates/qsic/tests/rigid_contact.rs` has the argument).
#[test]
fn a_turning_ellipsoid_touches_a_sphere() {
    let turning =
        r#"{"quadric": "x^2/4 + y^2 + z^2 - 1", "rotate": {"axis": [0, 0, 1], "cayley": true}}"#;
    let sphere = "(x - 3)^2 + (y - 4)^2 + z^2 - 9";
    let v = json(&["contact", "--json", turning, sphere]);
    assert_eq!(v["first_contact"], "-2");
    let c = &v["contact"];
    assert_eq!(c["t"], "-2");
    assert_eq!(c["at_start"], false);
    assert_eq!(c["locus"], "points");
    assert_eq!(c["curves"], 0);
    assert_eq!(c["points"].as_array().map(Vec::len), Some(1));
    assert_eq!(c["points"][0]["kind"], "isolated");
    assert_eq!(
        c["points"][0]["point"],
        serde_json::json!(["6/5", "8/5", "0", "1"])
    );
    assert_eq!(c["points"][0]["approx"][1].as_f64(), Some(1.6));
    let later = json(&["contact", "--json", "--range", "0", "oo", turning, sphere]);
    assert_eq!(later["contact"]["t"], "1/2");
    assert_eq!(later["contact"]["points"][0]["point"][0], "6/5");
    // the text report gives the point exactly and in decimals
    let (code, text, _) = qsic(&["contact", turning, sphere]);
    assert_eq!(code, Some(0));
    assert!(
        text.contains("isolated point (6/5, 8/5, 0, 1) ≈ (1.2"),
        "{text}"
    );
    // the same motion as a quaternion path about the centre 0, and `motion` reads it too
    let path = r#"{"quadric": [["1/4",0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,-1]], "rotate": {"quaternion": [1, 0, 0, "t"], "center": [0, 0, 0]}}"#;
    assert_eq!(json(&["contact", "--json", path, sphere]), v);
    let m = json(&["motion", "--json", turning, sphere]);
    let instants: Vec<&Value> = m["instants"]
        .as_array()
        .unwrap()
        .iter()
        .map(|i| &i["t"])
        .collect();
    assert!(instants.contains(&&Value::from("-2")) && instants.contains(&&Value::from("1/2")));
}

/// A unit sphere about (2, 0, 0) screwing about z (rise t) touches the sphere of radius 2
/// about (−6/5, 8/5, 5) at t = 2, at (−6/5, 8/5, 3); started later, they already meet.
#[test]
fn a_screw_motion_and_a_range_that_starts_inside() {
    let screw = r#"{"quadric": "(x - 2)^2 + y^2 + z^2 - 1", "rotate": {"axis": [0, 0, 1]}, "translate": [0, 0, "t"]}"#;
    let sphere = "(x + 6/5)^2 + (y - 8/5)^2 + (z - 5)^2 - 4";
    let v = json(&["contact", "--json", screw, sphere]);
    assert_eq!(v["contact"]["t"], "2");
    assert_eq!(
        v["contact"]["points"][0]["point"],
        serde_json::json!(["-6/5", "8/5", "3", "1"])
    );
    let inside = json(&["contact", "--json", "--range", "5/2", "3", screw, sphere]);
    assert_eq!(inside["contact"]["at_start"], true);
    assert_eq!(inside["contact"]["curves"], 1);
    let (_, text, _) = qsic(&["contact", "--range", "5/2", "3", screw, sphere]);
    assert!(
        text.contains("they already meet at the start of the range"),
        "{text}"
    );
}

/// Spheres along a line through (0, 1/2, 0): the contact at t = −√35/2 is irrational, its
/// point (−√35/3, 1/3, 0) exact in ℚ(t₀), named `a1` with its polynomial.
#[test]
fn an_irrational_contact_names_its_number() {
    let v = json(&[
        "contact",
        "--json",
        "x^2 + y^2 + z^2 - 4",
        "(x - t)^2 + (y - 1/2)^2 + z^2 - 1",
    ]);
    let c = &v["contact"];
    assert!(c["t"]["poly"].is_string());
    let p = &c["points"][0];
    let approx: Vec<f64> = p["approx"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    assert!((approx[0] + 35f64.sqrt() / 3.0).abs() < 1e-12, "{approx:?}");
    assert!((approx[1] - 1.0 / 3.0).abs() < 1e-12 && approx[2] == 0.0);
    assert_eq!(c["numbers"][0]["name"], "a1");
    assert!(p["point"][0].as_str().unwrap().contains("a1"));
}

#[test]
fn errors_name_the_part_of_the_motion() {
    let cases = [
        (
            r#"{"quadric": "x^2 + y^2 - 1", "rotate": {"axis": [0, 0, 0]}}"#,
            "error: A: invalid rigid motion: the rotation axis is zero",
        ),
        (
            r#"{"quadric": "x^2 + y^2 - 1", "translate": ["1/t", 0, 0]}"#,
            "error: A: invalid rigid motion: \"translate\"[0]",
        ),
        (
            r#"{"quadric": "x^2 + y^2 - 1", "rotate": {"axis": [0, 0, 1]}"#,
            "error: A: invalid JSON",
        ),
    ];
    for (a, want) in cases {
        for command in ["motion", "contact"] {
            let (code, _, err) = qsic(&[command, a, "x^2 + y^2 + z^2 - 4"]);
            assert_eq!(code, Some(1), "{command} {a}");
            assert!(err.starts_with(want), "{command} {a}: {err}");
        }
    }
}

/// A batch line takes the object form as its `A` or `B`, with the answer of the argument; a
/// bad object is that line's error, an object where a quadric is expected names its type.
#[test]
fn batch_lines_read_rigid_motion_objects() {
    let turning = r#"{"quadric": "x^2/4 + y^2 + z^2 - 1", "rotate": {"axis": [0, 0, 1]}}"#;
    let sphere = "(x - 3)^2 + (y - 4)^2 + z^2 - 9";
    let input = format!(
        "{{\"id\": 1, \"A\": {turning}, \"B\": \"{sphere}\"}}\n\
         {{\"id\": 2, \"A\": {{\"quadric\": \"x^2 - 1\", \"rotate\": {{\"axis\": [0, 0, 0]}}}}, \"B\": \"x^2 - 4\"}}\n"
    );
    let path = std::env::temp_dir().join(format!("qsic-rigid-batch-{}.jsonl", std::process::id()));
    std::fs::write(&path, input).unwrap();
    let (code, out, _) = qsic(&["motion", "--batch", path.to_str().unwrap()]);
    let _ = std::fs::remove_file(&path);
    assert_eq!(code, Some(1), "{out}");
    let lines: Vec<Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let single = json(&["motion", "--json", turning, sphere]);
    assert_eq!(lines[0]["instants"], single["instants"]);
    assert_eq!(lines[0]["intervals"], single["intervals"]);
    let message = lines[1]["error"]["message"].as_str().unwrap();
    assert_eq!(
        message,
        "A: invalid rigid motion: the rotation axis is zero"
    );
    // classify takes quadrics, not motions
    let (_, out, _) = qsic_stdin(
        &["classify", "--batch", "-"],
        &format!("{{\"id\": 3, \"A\": {turning}, \"B\": \"x^2 - 1\"}}\n"),
    );
    assert!(out.contains("found an object"), "{out}");
}

/// Exit code, stdout and stderr of `qsic args…` with `input` on standard input.
fn qsic_stdin(args: &[&str], input: &str) -> (Option<i32>, String, String) {
    use std::io::Write;
    let mut child = Command::new(env!("CARGO_BIN_EXE_qsic"))
        .args(args)
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("the qsic binary runs");
    child
        .stdin
        .take()
        .unwrap()
        .write_all(input.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    let text = |b: Vec<u8>| String::from_utf8(b).expect("UTF-8 output");
    (out.status.code(), text(out.stdout), text(out.stderr))
}
