//! Runs `qsic contact`: reports known by hand, JSON and text, ranges, and errors.

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

/// The ellipsoid `x²/4 + y² + z² ≤ 1` and a thin one moving along the x axis (extents
/// `[−2, 2]` and `[t − 1, t + 1]`): contact at `−3`, inside for `|t| < 1` (touching at
/// `±1`); the relation of the solids is given on the range asked only.
#[test]
fn ellipsoids_approaching_json() {
    let (a, b) = ("x^2/4 + y^2 + z^2 - 1", "(x - t)^2 + 4*y^2 + 4*z^2 - 1");
    let all: &[&str] = &["-3", "-1", "1", "3"];
    // (range, first contact of the surfaces, of the solids, the solids' instants, their
    // intervals' relations)
    type Case<'a> = (&'a [&'a str], Value, Value, &'a [&'a str], &'a [&'a str]);
    let whole = [
        "separated",
        "overlapping",
        "inside",
        "overlapping",
        "separated",
    ];
    let cases: [Case; 5] = [
        (&[], "-3".into(), "-3".into(), all, &whole),
        (
            &["--range", "-2", "inf"],
            "-2".into(),
            "-2".into(),
            &all[1..],
            &whole[1..],
        ),
        // nested at 0: the surfaces meet first at the internal touch t = 1
        (
            &["--range", "0", "5"],
            "1".into(),
            "0".into(),
            &all[2..],
            &whole[2..],
        ),
        (
            &["--range", "7/2", "10"],
            Value::Null,
            Value::Null,
            &[],
            &["separated"],
        ),
        // a range starting at an instant reports it first
        (
            &["--range", "-1", "0"],
            "-1".into(),
            "-1".into(),
            &["-1"],
            &["inside"],
        ),
    ];
    let touching = |t: &str| match t {
        "-3" | "3" => "touching_externally",
        _ => "touching_internally",
    };
    for (range, surfaces, solids, instants_in_range, intervals) in cases {
        let mut args = vec!["contact", "--json", a, b];
        args.extend_from_slice(range);
        let (code, out, err) = qsic(&args);
        assert_eq!(code, Some(0), "{range:?}: {err}");
        let v: Value = serde_json::from_str(&out).expect("one JSON object");
        assert_eq!(v["first_contact"], surfaces, "{range:?}");
        assert_eq!(v["solids"]["first_meeting"], solids, "{range:?}");
        let instants: Vec<(String, String)> = v["solids"]["instants"]
            .as_array()
            .unwrap()
            .iter()
            .map(|i| {
                (
                    i["t"].to_string(),
                    i["relation"].as_str().unwrap().to_string(),
                )
            })
            .collect();
        let want: Vec<(String, String)> = instants_in_range
            .iter()
            .map(|t| (format!("\"{t}\""), touching(t).to_string()))
            .collect();
        assert_eq!(instants, want, "{range:?}");
        let relations: Vec<&str> = v["solids"]["intervals"]
            .as_array()
            .unwrap()
            .iter()
            .map(|i| i["relation"].as_str().unwrap())
            .collect();
        assert_eq!(relations, intervals, "{range:?}");
        if let [_, t0, t1] = range {
            let ends = &v["solids"]["intervals"];
            assert_eq!(ends[0]["from"], *t0, "{range:?}");
            let last = ends.as_array().unwrap().last().unwrap();
            assert_eq!(
                last["to"],
                if *t1 == "inf" {
                    Value::Null
                } else {
                    (*t1).into()
                }
            );
        }
    }
}

/// The text report names the first contact and the timeline; a 4×4 matrix argument works.
#[test]
fn text_report_and_matrix_argument() {
    let b = r#"[["1","0","0","-t"],["0","1","0","-1"],["0","0","1","0"],["-t","-1","0","t^2"]]"#;
    // (x − t)² + (y − 1)² + z² − 1: contact where t² + 1 = 9
    let (code, out, err) = qsic(&["contact", "x^2 + y^2 + z^2 - 4", b]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.contains("first contact (real common point): t = root of t^2 - 8 ≈ -2.828427124746"),
        "{out}"
    );
    assert!(
        out.contains(": touching_internally (B inside the other)"),
        "{out}"
    );
}

/// Bad input exits 1 naming the argument; usage errors (a bad or empty range too) exit 2.
#[test]
fn errors_name_the_argument() {
    let cases: [(&[&str], i32, &str); 4] = [
        (&["contact", "x^2 + u", "y^2"], 1, "A:"),
        (&["contact", "x^2", "y^2 + x^3*t"], 1, "B:"),
        (
            &[
                "contact",
                "x^2+y^2+z^2-1",
                "x^2+y^2+z^2-t",
                "--range",
                "2",
                "1",
            ],
            2,
            "--range: invalid time range: the start 2 is above the end 1",
        ),
        (&["contact", "x^2"], 2, "B"),
    ];
    for (args, want, named) in cases {
        let (code, _, err) = qsic(args);
        assert_eq!(code, Some(want), "{args:?}: {err}");
        assert!(err.contains(named), "{args:?}: {err}");
    }
}

/// `--first-only` gives the full report's first contact and nothing else, in JSON, in a
/// batch and as text, on motions with a rational, an irrational and no first contact.
#[test]
fn first_only_is_the_reports_first_contact_alone() {
    let motions = [
        ("x^2/4 + y^2 + z^2 - 1", "(x - t)^2 + 4*y^2 + 4*z^2 - 1"),
        (
            "x^2/4 + y^2 + z^2/9 - 1",
            "(x - 2*t + 6)^2/9 + (y - t)^2/4 + (z - 1)^2 - 1",
        ),
        (
            "x^2/4 + y^2 + z^2/9 - 1",
            "(x - t)^2 + (y - 5)^2/4 + z^2/4 - 1",
        ),
    ];
    let mut batch = String::new();
    let mut firsts = Vec::new();
    for (k, (a, b)) in motions.iter().enumerate() {
        let (code, full, _) = qsic(&["contact", "--json", a, b]);
        assert_eq!(code, Some(0));
        let full: Value = serde_json::from_str(&full).expect("JSON");
        let (code, only, _) = qsic(&["contact", "--json", "--first-only", a, b]);
        assert_eq!(code, Some(0));
        let only: Value = serde_json::from_str(&only).expect("JSON");
        let mut keys: Vec<&String> = only.as_object().expect("an object").keys().collect();
        keys.sort();
        assert_eq!(keys, ["first_contact", "range"], "{a} | {b}");
        // the same instant (its printed interval is as refined as the work before left it)
        let same = |x: &Value, y: &Value| {
            x == y || (x["poly"] == y["poly"] && x["approx"] == y["approx"] && x.is_object())
        };
        assert!(
            same(&only["first_contact"], &full["first_contact"]),
            "{a} | {b}"
        );
        firsts.push(full["first_contact"].clone());
        batch.push_str(&format!(
            "{{\"id\": {k}, \"A\": \"{a}\", \"B\": \"{b}\"}}\n"
        ));
        let (_, text, _) = qsic(&["contact", "--first-only", a, b]);
        assert!(text.contains("first contact (real common point)") && !text.contains("solids"));
    }
    assert!(firsts[1].is_object() && firsts[2].is_null(), "{firsts:?}");
    let path = std::env::temp_dir().join(format!("qsic-first-only-{}.jsonl", std::process::id()));
    std::fs::write(&path, batch).expect("a temporary file");
    let (code, out, _) = qsic(&["contact", "--first-only", "--batch", path.to_str().unwrap()]);
    std::fs::remove_file(&path).ok();
    assert_eq!(code, Some(0));
    for (line, first) in out.lines().zip(&firsts) {
        let v: Value = serde_json::from_str(line).expect("JSON");
        let f = &v["first_contact"];
        assert!(f == first || (f["poly"] == first["poly"] && f["approx"] == first["approx"]));
        assert!(v.get("solids").is_none() && v.get("contact").is_none());
    }
}
