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
