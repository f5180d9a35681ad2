//! `qsic classify --batch` on affine configurations checked by hand
//! (`tests/data/affine.jsonl`: parallel, crossing and tangent cylinders, a hyperboloid and its
//! asymptotic cone, spheres apart, touching, overlapping, nested): every labelled field of the
//! `"affine"` object, as `check_affine.py` judges it, plus invariance under an affine map.

use serde_json::Value;
use std::io::Write;
use std::process::{Command, Stdio};

fn classify_batch(input: &str) -> Vec<Value> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_qsic"))
        .args(["classify", "--batch", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(input.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

const COUNTS: [&str; 6] = [
    "curves_bounded",
    "curves_unbounded",
    "isolated_points",
    "points_at_infinity",
    "singular_finite",
    "singular_at_infinity",
];

#[test]
fn hand_checked_affine_answers() {
    let text = include_str!("data/affine.jsonl");
    let lines: Vec<Value> = text
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let results = classify_batch(text);
    assert_eq!(results.len(), lines.len());
    for (want, got) in lines.iter().zip(&results) {
        let (w, g) = (&want["affine"], &got["affine"]);
        let id = &want["id"];
        assert_eq!(w["surfaces"], g["surfaces"], "{id}");
        assert_eq!(w["solids"], g["solids"], "{id}");
        for k in COUNTS {
            assert_eq!(w[k], g[k], "{id}: {k}");
        }
        assert_eq!(g["chart"], "w");
        assert!(g["summary"].as_str().is_some_and(|s| !s.is_empty()));
    }
}

/// Moving everything by x → x + 2y − 1, y → y + z, z → z + 3 (affine, det 1) changes no
/// count and no solid relation (names may change: a sphere becomes an ellipsoid).
#[test]
fn an_affine_map_changes_no_count() {
    let text = include_str!("data/affine.jsonl");
    let moved: String = text
        .lines()
        .map(|l| {
            let mut v: Value = serde_json::from_str(l).unwrap();
            for q in ["A", "B"] {
                let s = v[q].as_str().unwrap();
                // substitute simultaneously through placeholders
                let t = s
                    .replace('x', "(X+2*Y-1)")
                    .replace('y', "(Y+Z)")
                    .replace('z', "(Z+3)")
                    .to_lowercase();
                v[q] = Value::from(t);
            }
            v.to_string() + "\n"
        })
        .collect();
    let (before, after) = (classify_batch(text), classify_batch(&moved));
    assert_eq!(before.len(), after.len());
    for (b, a) in before.iter().zip(&after) {
        for k in COUNTS {
            assert_eq!(b["affine"][k], a["affine"][k], "{}: {k}", b["id"]);
        }
        assert_eq!(b["affine"]["solids"], a["affine"]["solids"], "{}", b["id"]);
    }
}

/// A degree-1 polynomial is a plane: the section of a sphere by `z = 1/2` is a circle counted
/// twice, bounded; a plane tangent to the sphere touches it at one point; the plane `x*w`
/// (homogeneous) stays a plane pair with the plane at infinity.
#[test]
fn planes_as_input_give_the_section() {
    let lines = concat!(
        r#"{"id": 1, "A": "x^2+y^2+z^2-1", "B": "z - 1/2"}"#,
        "\n",
        r#"{"id": 2, "A": "x^2+y^2+z^2-1", "B": "z - 1"}"#,
        "\n",
        r#"{"id": 3, "A": "x^2+y^2-z^2-1", "B": "y"}"#,
        "\n",
        r#"{"id": 4, "A": "x^2+y^2+z^2-1", "B": "x*w"}"#,
        "\n",
    );
    let r = classify_batch(lines);
    assert_eq!(r.len(), 4);
    assert_eq!(
        (r[0]["case"].as_u64(), r[0]["real_type"].as_str()),
        (Some(19), Some("double_conic"))
    );
    assert_eq!(r[0]["affine"]["surfaces"][1], "plane");
    assert_eq!(r[0]["affine"]["curves_bounded"], 1);
    assert_eq!(r[0]["affine"]["components"][0]["name"], "circle");
    // tangent plane: the two conjugate double lines meet at the point of contact
    assert_eq!(r[1]["affine"]["isolated_points"], 1);
    // a hyperboloid of one sheet cut through its axis: a hyperbola, two unbounded curves
    assert_eq!(r[2]["affine"]["curves_unbounded"], 2);
    assert_eq!(r[2]["affine"]["components"][0]["name"], "hyperbola");
    // x·w: a plane pair, not a plane input; the real conic x = 0 and the conic at infinity
    assert_eq!(r[3]["affine"]["surfaces"][1], "plane");
    assert_ne!(r[3]["case"].as_u64(), Some(19));
}

/// `--chart`: the two loops of the cylinders x² + y² = 1, y² + z² = 4 are bounded with
/// `w = 0` at infinity and cut twice each by the plane `x = 0`; a zero form is a usage error.
#[test]
fn a_chart_moves_the_plane_at_infinity() {
    let run = |chart: &str| {
        Command::new(env!("CARGO_BIN_EXE_qsic"))
            .args([
                "classify",
                "--json",
                "x^2+y^2-1",
                "y^2+z^2-4",
                "--chart",
                chart,
            ])
            .output()
            .unwrap()
    };
    let affine = |chart: &str| -> Value {
        let out = run(chart);
        assert!(out.status.success(), "{chart}");
        serde_json::from_slice::<Value>(&out.stdout).unwrap()["affine"].clone()
    };
    let w = affine("w");
    assert_eq!(
        (w["curves_bounded"].as_u64(), w["curves_unbounded"].as_u64()),
        (Some(2), Some(0))
    );
    let x = affine("x");
    assert_eq!(
        (x["curves_bounded"].as_u64(), x["curves_unbounded"].as_u64()),
        (Some(0), Some(4))
    );
    assert_eq!(
        (x["chart"].as_str(), x["points_at_infinity"].as_u64()),
        (Some("x"), Some(4))
    );
    assert_eq!(run("0").status.code(), Some(2));
}
