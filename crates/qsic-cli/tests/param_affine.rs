//! The affine data of `qsic param` and `qsic sample` through the built binary: each conic's
//! type, centre, radius, axes (plane sections known by hand, in the default chart and with
//! `--chart`), the pair's `"affine"` object equal to `qsic classify`'s on the corpus, and
//! `--projective` leaving all of it out.

use serde_json::Value;
#[path = "common/run.rs"]
mod run;

use run::qsic;

fn json(args: &[&str]) -> Value {
    let out = qsic(args, "");
    assert!(out.status.success(), "{args:?}: {out:?}");
    serde_json::from_slice(&out.stdout).expect("one JSON object")
}

fn strings(v: &Value) -> Vec<&str> {
    v.as_array()
        .unwrap_or_else(|| panic!("an array: {v}"))
        .iter()
        .map(|x| x.as_str().expect("a string"))
        .collect()
}

/// The conics' `"affine"` objects of a `param --json` answer.
fn conics(answer: &Value) -> Vec<&Value> {
    answer["components"]
        .as_array()
        .expect("components")
        .iter()
        .filter_map(|c| c.get("affine"))
        .collect()
}

#[test]
fn param_gives_each_conic_its_centre_radius_and_axes() {
    // the sphere x² + y² + z² = 25 and the planes z = 3, z = −4: circles of radius 4 and 3
    let v = json(&["param", "--json", "x^2+y^2+z^2-25", "(z-3)*(z+4)"]);
    let mut found: Vec<(Vec<&str>, &str, f64)> = conics(&v)
        .iter()
        .map(|c| {
            assert_eq!(c["type"], "circle", "{c}");
            assert_eq!(strings(&c["normal"]), ["0", "0", "1"]);
            (
                strings(&c["centre"]),
                c["radius2"].as_str().unwrap(),
                c["approx"]["radius"].as_f64().unwrap(),
            )
        })
        .collect();
    found.sort_by(|a, b| a.1.cmp(b.1));
    assert_eq!(found[0].0, ["0", "0", "3"]);
    assert_eq!((found[0].1, found[0].2), ("16", 4.0));
    assert_eq!(found[1].0, ["0", "0", "-4"]);
    assert_eq!((found[1].1, found[1].2), ("9", 3.0));
    // the cone x² + y² = z² and the planes z = x + 1 (a parabola) and z = x/2 + 1 (an
    // ellipse, semi-axes² 20/9 and 4/3)
    let v = json(&["param", "--json", "x^2+y^2-z^2", "(z-x-1)*(2*z-x-2)"]);
    let all = conics(&v);
    let p = all
        .iter()
        .find(|c| c["type"] == "parabola")
        .expect("a parabola");
    assert_eq!(strings(&p["vertex"]), ["-1/2", "0", "1/2"]);
    assert_eq!(strings(&p["axis"]), ["1", "0", "1"]);
    assert_eq!(p["focal_length2"], "1/8");
    let e = all
        .iter()
        .find(|c| c["type"] == "ellipse")
        .expect("an ellipse");
    assert_eq!(strings(&e["centre"]), ["2/3", "0", "4/3"]);
    assert_eq!(e["axes"][0]["semi_axis2"], "20/9");
    assert_eq!(strings(&e["axes"][0]["direction"]), ["1", "0", "1/2"]);
    assert_eq!(e["axes"][1]["semi_axis2"], "4/3");
    let a = e["approx"]["axes"][1]["semi_axis"].as_f64().unwrap();
    assert!((a - (4.0f64 / 3.0).sqrt()).abs() < 1e-12);
    // the text report says the same
    let text =
        String::from_utf8(qsic(&["param", "x^2+y^2-z^2", "(z-x-1)*(2*z-x-2)"], "").stdout).unwrap();
    assert!(text.contains("parabola: vertex (-1/2, 0, 1/2), axis (1, 0, 1), focal length² 1/8"));
    assert!(text.contains("ellipse: centre (2/3, 0, 4/3), major semi-axis² 20/9"));
    assert!(text.contains("in R^3 (w = 0 at infinity): circular_cone and intersecting_planes"));
    // x² + 2y² = 2 cut by z = x + y through the axis: semi-axes² 3 ± √3
    let v = json(&["param", "--json", "x^2+2*y^2-2", "(z-x-y)*(z+2*x-1)"]);
    let e = conics(&v)
        .into_iter()
        .find(|c| c["centre"] == serde_json::json!(["0", "0", "0"]))
        .expect("the central section");
    assert_eq!(e["axes"][0]["semi_axis2"], "3 + sqrt(3)");
    assert_eq!(e["axes"][1]["semi_axis2"], "3 - sqrt(3)");
}

#[test]
fn the_chart_changes_the_conics_and_projective_leaves_them_out() {
    // with z = 0 at infinity the cone x² + y² = z² is the cylinder X² + Y² = 1
    // (X = x/z, Y = y/z, W = w/z): the plane x = w (X = W) cuts it in an ellipse of
    // semi-axes² 2 along (1, 0, 1) and 1 along (0, 1, 0), no longer a hyperbola
    let pair = ["x^2+y^2-z^2", "(z-1)*(x-1)"];
    let types = |v: &Value| -> Vec<String> {
        let mut t: Vec<String> = conics(v)
            .iter()
            .map(|c| c["type"].as_str().unwrap().to_owned())
            .collect();
        t.sort();
        t
    };
    let v = json(&["param", "--json", pair[0], pair[1]]);
    assert_eq!(types(&v), ["circle", "hyperbola"]);
    assert_eq!(v["affine"]["chart"], "w");
    let v = json(&["param", "--json", "--chart", "z", pair[0], pair[1]]);
    assert_eq!(types(&v), ["circle", "ellipse"]);
    assert_eq!(v["affine"]["chart"], "z");
    let e = conics(&v)
        .into_iter()
        .find(|c| c["type"] == "ellipse")
        .unwrap();
    assert_eq!(strings(&e["centre"]), ["0", "0", "0"]);
    assert_eq!(e["axes"][0]["semi_axis2"], "2");
    assert_eq!(strings(&e["axes"][0]["direction"]), ["1", "0", "1"]);
    assert_eq!(e["axes"][1]["semi_axis2"], "1");
    // --projective: no affine data (nor frames) at all, the rest unchanged
    let p = json(&["param", "--json", "--projective", pair[0], pair[1]]);
    assert!(p.get("affine").is_none() && conics(&p).is_empty());
    let mut full = json(&["param", "--json", pair[0], pair[1]]);
    full.as_object_mut().unwrap().remove("affine");
    for c in full["components"].as_array_mut().unwrap() {
        c.as_object_mut().unwrap().remove("affine");
        c.as_object_mut().unwrap().remove("frame");
    }
    assert_eq!(full, p);
    let s = json(&["sample", "--points", "8", "--projective", pair[0], pair[1]]);
    assert!(s.get("affine").is_none());
    let s = json(&["sample", "--points", "8", "--chart", "z", pair[0], pair[1]]);
    assert_eq!(s["affine"]["chart"], "z");
    assert_eq!(s["affine"]["curves_bounded"], 1);
    // a bad chart is a usage error
    assert_eq!(
        qsic(&["param", "--chart", "x*y", pair[0], pair[1]], "")
            .status
            .code(),
        Some(2)
    );
}

#[test]
fn param_and_sample_carry_the_affine_object_of_classify() {
    let corpus = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../qsic/tests/data/cases.jsonl"
    ))
    .unwrap();
    // a line per case keeps the test fast
    let mut seen = std::collections::BTreeSet::new();
    let lines: Vec<&str> = corpus
        .lines()
        .filter(|l| {
            let v: Value = serde_json::from_str(l).unwrap();
            seen.insert(v["case"].to_string())
        })
        .collect();
    let input = lines.join("\n") + "\n";
    let run = |args: &[&str]| -> Vec<Value> {
        let out = qsic(args, &input);
        String::from_utf8(out.stdout)
            .unwrap()
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect()
    };
    let classify = run(&["classify", "--batch", "-"]);
    let param = run(&["param", "--batch", "-"]);
    let sample = run(&["sample", "--batch", "-", "--points", "8"]);
    assert_eq!(classify.len(), lines.len());
    let mut compared = 0;
    for ((c, p), s) in classify.iter().zip(&param).zip(&sample) {
        if p.get("error").is_some() {
            continue;
        }
        assert_eq!(p["affine"], c["affine"], "{}", c["id"]);
        assert_eq!(s["affine"], c["affine"], "{}", c["id"]);
        compared += 1;
    }
    assert!(compared + 3 >= lines.len(), "{compared} of {}", lines.len());
    let projective = run(&["param", "--batch", "-", "--projective"]);
    assert!(projective.iter().all(|p| p.get("affine").is_none()));
}
