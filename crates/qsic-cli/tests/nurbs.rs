//! `qsic nurbs`: the JSON object, the STEP text, the text summary, `--box` and batch lines.

#[path = "common/run.rs"]
mod run;

use run::qsic;
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    let out = qsic(args, "");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("one JSON object")
}

/// A curve's knot multiplicities.
fn multiplicities(c: &Value) -> Vec<u64> {
    c["multiplicities"]
        .as_array()
        .expect("multiplicities")
        .iter()
        .map(|v| v.as_u64().expect("an integer"))
        .collect()
}

/// Viviani's curve: two exact quartic loops, rational control points, clamped knots.
#[test]
fn viviani_json_has_two_exact_quartics() {
    let v = json(&["nurbs", "--json", "x^2+y^2+z^2-4", "x^2+y^2-2*x"]);
    let curves = v["curves"].as_array().expect("curves");
    assert_eq!(curves.len(), 2);
    for c in curves {
        assert_eq!(c["degree"], 4);
        assert_eq!(c["exact"], true);
        assert_eq!(c["bound"], 0.0);
        let m = multiplicities(c);
        assert_eq!((m[0], m[m.len() - 1]), (5, 5));
        let poles = c["control_points"].as_array().expect("points").len() as u64;
        assert_eq!(poles, m.iter().sum::<u64>() - 5);
        assert_eq!(
            c["weights"].as_array().expect("weights").len() as u64,
            poles
        );
        // exact rationals: no name, no root in any control point
        for p in c["control_points"].as_array().expect("points") {
            for v in p.as_array().expect("a point") {
                let s = v.as_str().expect("a string");
                assert!(!s.contains("sqrt") && !s.contains('a'), "{s}");
            }
        }
    }
}

/// STEP: one B-spline per curve, rational where the weights differ, the file's frame.
#[test]
fn step_has_one_b_spline_curve_per_curve() {
    let out = qsic(&["nurbs", "--format", "step", "x^2+y^2-1", "x^2+z^2-1"], "");
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).expect("ASCII");
    assert!(text.starts_with("ISO-10303-21;\nHEADER;"));
    assert!(text.ends_with("ENDSEC;\nEND-ISO-10303-21;\n"));
    assert_eq!(text.matches("B_SPLINE_CURVE_WITH_KNOTS(").count(), 4);
    assert_eq!(text.matches("RATIONAL_B_SPLINE_CURVE((").count(), 4);
    assert!(text.contains("GEOMETRIC_CURVE_SET('',(#"));
    let v = json(&["nurbs", "--json", "x^2+y^2-1", "x^2+z^2-1"]);
    let points: usize = v["curves"]
        .as_array()
        .expect("curves")
        .iter()
        .map(|c| c["control_points"].as_array().expect("points").len())
        .sum();
    assert_eq!(text.matches("CARTESIAN_POINT(").count(), points);
}

/// `--box`: the hyperbola's ends just outside the box given; a bad box is a usage error.
#[test]
fn a_box_of_the_users_clips_unbounded_pieces() {
    let v = json(&[
        "nurbs",
        "--json",
        "--box",
        "-3,-3,-3,3,3,3",
        "x^2+y^2-z^2",
        "y-1",
    ]);
    assert_eq!(v["bounds"]["hi"], serde_json::json!(["3", "3", "3"]));
    for c in v["curves"].as_array().expect("curves") {
        assert_eq!(c["clipped"], serde_json::json!([true, true]));
        let pts = c["approx"]["control_points"].as_array().expect("points");
        for end in [&pts[0], &pts[pts.len() - 1]] {
            let m = end
                .as_array()
                .expect("a point")
                .iter()
                .map(|v| v.as_f64().expect("a float").abs())
                .fold(0.0, f64::max);
            // just outside, exactly (the library's tests decide it): on the face in floats
            assert!((m - 3.0).abs() < 1e-6, "{end}");
        }
    }
    for bad in ["1,2,3", "0,0,0,1,1,x", "1,0,0,0,1,1"] {
        let out = qsic(&["nurbs", "--box", bad, "x^2+y^2-z^2", "y-1"], "");
        assert_eq!(out.status.code(), Some(2), "{bad}");
        assert!(String::from_utf8_lossy(&out.stderr).contains("--box"));
    }
}

/// The text summary and the pieces left out.
#[test]
fn text_names_curves_and_pieces_left_out() {
    // a sphere and a tangent plane: one isolated point
    let out = qsic(&["nurbs", "x^2+y^2+z^2-1", "z-1"], "");
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    assert!(text.starts_with("0 NURBS curve(s)"), "{text}");
    assert!(
        text.contains("left out: piece 0: an isolated point"),
        "{text}"
    );
    let out = qsic(&["nurbs", "x^2+y^2+z^2-4", "x^2+y^2-2*x+1/2"], "");
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    assert!(text.starts_with("2 NURBS curve(s)"), "{text}");
    assert_eq!(text.matches("within ").count(), 2, "{text}");
    let out = qsic(&["nurbs", "x^2+y^2-z^2", "x"], "");
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    assert_eq!(text.matches("exact").count(), 4, "{text}");
}

/// A smooth quartic: approximated loops, their bound within the tolerance asked for, no
/// parameters at the ends; plain (non-rational) B-splines in STEP; a bad tolerance refused.
#[test]
fn quartic_loops_are_approximated_within_the_tolerance() {
    let (a, b) = ("x^2+y^2+z^2-4", "x^2+y^2-2*x+1/2");
    for tolerance in ["1e-6", "1e-10"] {
        let v = json(&["nurbs", "--json", "--tolerance", tolerance, a, b]);
        let curves = v["curves"].as_array().expect("curves");
        assert_eq!(curves.len(), 2);
        for c in curves {
            assert_eq!(c["exact"], false);
            assert_eq!(c["degree"], 7);
            assert_eq!(c["closed"], true);
            assert!(c["u"].is_null());
            let bound = c["bound"].as_f64().expect("a bound");
            let t: f64 = tolerance.parse().unwrap();
            assert!(bound > 0.0 && bound <= t, "{bound} > {t}");
            let m = multiplicities(c);
            assert_eq!((m[0], m[m.len() - 1]), (8, 8));
            assert!(m[1..m.len() - 1].iter().all(|k| *k == 7));
            assert!(c["weights"].as_array().unwrap().iter().all(|w| w == "1"));
        }
    }
    let out = qsic(&["nurbs", "--format", "step", a, b], "");
    let text = String::from_utf8(out.stdout).expect("ASCII");
    assert_eq!(text.matches("B_SPLINE_CURVE_WITH_KNOTS(").count(), 2);
    assert_eq!(text.matches("RATIONAL_B_SPLINE_CURVE((").count(), 0);
    for bad in ["0", "-1e-9", "nan", "inf"] {
        let out = qsic(&["nurbs", "--tolerance", bad, a, b], "");
        assert_eq!(out.status.code(), Some(2), "{bad}");
        assert!(String::from_utf8_lossy(&out.stderr).contains("--tolerance"));
    }
}

/// A batch line answers with the --json object's fields after the id.
#[test]
fn batch_lines_answer_with_the_json_fields() {
    let input =
        "{\"id\":1,\"A\":\"x^2+y^2-1\",\"B\":\"z-x\"}\n{\"id\":2,\"A\":\"x^2\",\"B\":\"oops(\"}\n";
    let out = qsic(&["nurbs", "--batch", "-"], input);
    let lines: Vec<Value> = String::from_utf8(out.stdout)
        .expect("UTF-8")
        .lines()
        .map(|l| serde_json::from_str(l).expect("JSON"))
        .collect();
    assert_eq!(lines.len(), 2);
    assert_eq!(lines[0]["id"], 1);
    let alone = json(&["nurbs", "--json", "x^2+y^2-1", "z-x"]);
    assert_eq!(lines[0]["curves"], alone["curves"]);
    assert!(lines[1].get("error").is_some(), "{}", lines[1]);
}
