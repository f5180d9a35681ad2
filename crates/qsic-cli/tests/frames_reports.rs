//! Frames and reports in the user's words through the built binary: every `"frame"` of `qsic
//! param --json`, rebuilt as the curve OpenCASCADE would draw from it (`gp_Circ`, `gp_Elips`,
//! `gp_Hypr`, `gp_Parab`, `gp_Lin`), lies on both quadrics; the hand-computed frames of
//! known sections; `qsic classify`'s text leading with ℝ³; `qsic param`'s points as
//! `(x, y, z)`.

use serde_json::Value;
#[path = "common/run.rs"]
mod run;

use run::qsic;

fn stdout(args: &[&str]) -> String {
    let out = qsic(args, "");
    assert!(out.status.success(), "{args:?}: {out:?}");
    String::from_utf8(out.stdout).expect("UTF-8")
}

fn frames(a: &str, b: &str) -> Vec<Value> {
    let v: Value = serde_json::from_str(&stdout(&["param", "--json", a, b])).expect("JSON");
    v["components"]
        .as_array()
        .expect("components")
        .iter()
        .filter_map(|c| c.get("frame").cloned())
        .collect()
}

fn vec3(v: &Value) -> [f64; 3] {
    let a = v.as_array().unwrap_or_else(|| panic!("an array: {v}"));
    std::array::from_fn(|i| a[i].as_f64().expect("a number"))
}

fn strings(v: &Value) -> Vec<&str> {
    v.as_array()
        .unwrap_or_else(|| panic!("an array: {v}"))
        .iter()
        .map(|x| x.as_str().expect("a string"))
        .collect()
}

type Surface = fn([f64; 3]) -> f64;

/// Points of the curve a CAD kernel draws from the frame's decimals.
fn cad_points(f: &Value) -> Vec<[f64; 3]> {
    let a = &f["approx"];
    let get = |k: &str| vec3(&a[k]);
    let num = |k: &str| a[k].as_f64().expect(k);
    let at = |p: [f64; 3], terms: &[(f64, [f64; 3])]| -> [f64; 3] {
        std::array::from_fn(|i| p[i] + terms.iter().map(|(c, v)| c * v[i]).sum::<f64>())
    };
    let ts: Vec<f64> = (0..12).map(|k| -2.5 + 0.45 * f64::from(k)).collect();
    match f["type"].as_str().unwrap() {
        "circle" | "ellipse" => {
            let (r1, r2) = if f["type"] == "circle" {
                (num("radius"), num("radius"))
            } else {
                (num("major_radius"), num("minor_radius"))
            };
            ts.iter()
                .map(|t| {
                    at(
                        get("location"),
                        &[
                            (r1 * t.cos(), get("x_direction")),
                            (r2 * t.sin(), get("y_direction")),
                        ],
                    )
                })
                .collect()
        }
        "hyperbola" => ts
            .iter()
            .flat_map(|t| {
                [1.0, -1.0].map(|branch| {
                    at(
                        get("location"),
                        &[
                            (branch * num("major_radius") * t.cosh(), get("x_direction")),
                            (num("minor_radius") * t.sinh(), get("y_direction")),
                        ],
                    )
                })
            })
            .collect(),
        "parabola" => ts
            .iter()
            .map(|u| {
                at(
                    get("location"),
                    &[
                        (u * u / (4.0 * num("focal")), get("x_direction")),
                        (*u, get("y_direction")),
                    ],
                )
            })
            .collect(),
        "line" => ts
            .iter()
            .map(|t| at(get("location"), &[(*t, get("direction"))]))
            .collect(),
        "point" => vec![get("location")],
        other => panic!("no points for a {other}"),
    }
}

/// Every frame of each pair, drawn as OpenCASCADE draws it, lies on both surfaces; the frame
/// is orthonormal and right-handed; each exact direction's norm² is its vector's.
#[test]
fn every_frame_drawn_as_a_cad_curve_lies_on_both_surfaces() {
    let pairs: [(&str, &str, Surface, Surface, usize); 10] = [
        (
            "x^2+y^2-1",
            "x^2+z^2-1",
            |p| p[0] * p[0] + p[1] * p[1] - 1.0,
            |p| p[0] * p[0] + p[2] * p[2] - 1.0,
            2,
        ),
        (
            "x^2+y^2-z^2",
            "z-1-x",
            |p| p[0] * p[0] + p[1] * p[1] - p[2] * p[2],
            |p| p[2] - 1.0 - p[0],
            1,
        ),
        (
            "x^2+y^2-z^2",
            "z-1-2*x",
            |p| p[0] * p[0] + p[1] * p[1] - p[2] * p[2],
            |p| p[2] - 1.0 - 2.0 * p[0],
            1,
        ),
        (
            "x^2+y^2-z^2",
            "2*z-2-x",
            |p| p[0] * p[0] + p[1] * p[1] - p[2] * p[2],
            |p| 2.0 * p[2] - 2.0 - p[0],
            1,
        ),
        (
            "x^2+y^2+z^2-25",
            "x^2+y^2-16",
            |p| p[0] * p[0] + p[1] * p[1] + p[2] * p[2] - 25.0,
            |p| p[0] * p[0] + p[1] * p[1] - 16.0,
            2,
        ),
        (
            "(x+y-2)*(x+y+5)",
            "(z-x-1)*(z-x+7)",
            |p| (p[0] + p[1] - 2.0) * (p[0] + p[1] + 5.0),
            |p| (p[2] - p[0] - 1.0) * (p[2] - p[0] + 7.0),
            4,
        ),
        // an oblique section of an elliptic cylinder: axes over Q(sqrt 3)
        (
            "x^2+2*y^2-2",
            "(z-x-y)*(z+2*x-1)",
            |p| p[0] * p[0] + 2.0 * p[1] * p[1] - 2.0,
            |p| (p[2] - p[0] - p[1]) * (p[2] + 2.0 * p[0] - 1.0),
            2,
        ),
        // a sphere and a tilted plane: a circle with an irrational radius, off-axis
        (
            "x^2+y^2+z^2-3",
            "x+y+z-1",
            |p| p[0] * p[0] + p[1] * p[1] + p[2] * p[2] - 3.0,
            |p| p[0] + p[1] + p[2] - 1.0,
            1,
        ),
        // two cylinders tangent along the line x = 1, y = 0
        (
            "x^2+y^2-1",
            "(x-2)^2+y^2-1",
            |p| p[0] * p[0] + p[1] * p[1] - 1.0,
            |p| (p[0] - 2.0).powi(2) + p[1] * p[1] - 1.0,
            1,
        ),
        // a hyperboloid of one sheet and a tangent plane: the lines y = ±z of x = 1
        (
            "x^2+y^2-z^2-1",
            "x-1",
            |p| p[0] * p[0] + p[1] * p[1] - p[2] * p[2] - 1.0,
            |p| p[0] - 1.0,
            2,
        ),
    ];
    for (a, b, fa, fb, want) in pairs {
        let fs = frames(a, b);
        assert_eq!(fs.len(), want, "{a} ∩ {b}: {fs:?}");
        for f in &fs {
            for p in cad_points(f) {
                let scale = 1.0 + p.iter().map(|c| c * c).sum::<f64>();
                for (name, g) in [("A", fa), ("B", fb)] {
                    assert!(
                        g(p).abs() < 1e-9 * scale,
                        "{a} ∩ {b}: {p:?} off {name}: {f}"
                    );
                }
            }
            if f.get("normal").is_some() {
                let (n, x, y) = (
                    vec3(&f["approx"]["normal"]),
                    vec3(&f["approx"]["x_direction"]),
                    vec3(&f["approx"]["y_direction"]),
                );
                let cross = [
                    x[1] * y[2] - x[2] * y[1],
                    x[2] * y[0] - x[0] * y[2],
                    x[0] * y[1] - x[1] * y[0],
                ];
                for i in 0..3 {
                    assert!((cross[i] - n[i]).abs() < 1e-12, "X × Y = N: {f}");
                }
            }
        }
    }
}

/// The frames of sections known by hand, exact: Steinmetz's ellipses, a cone's parabola and
/// hyperbola, the circles of a sphere and a cylinder, the line of two planes.
#[test]
fn hand_computed_frames_exactly() {
    // x² + y² = 1, x² + z² = 1: ellipses in y = ±z, major semi-axis √2 along (0, 1, ±1)
    for f in frames("x^2+y^2-1", "x^2+z^2-1") {
        assert_eq!(f["type"], "ellipse");
        assert_eq!(strings(&f["location"]), ["0", "0", "0"]);
        assert_eq!(f["major_radius"]["exact"], "sqrt(2)");
        assert_eq!(f["major_radius"]["square"], "2");
        assert_eq!(f["minor_radius"]["exact"], "1");
        let x = strings(&f["x_direction"]["vector"]);
        assert!(x == ["0", "1", "1"] || x == ["0", "1", "-1"], "{x:?}");
        assert_eq!(f["x_direction"]["norm2"], "2");
        assert_eq!(strings(&f["x_direction"]["unit"])[0], "0");
        assert_eq!(strings(&f["x_direction"]["unit"])[1], "1/2*sqrt(2)");
    }
    // the cone x² + y² = z² and z = 1 + x: the parabola y² = 1 + 2x, vertex (−1/2, 0, 1/2),
    // axis (1, 0, 1) towards the focus, focal length √2/4
    let [f] = &frames("x^2+y^2-z^2", "z-1-x")[..] else {
        panic!("one conic")
    };
    assert_eq!(f["type"], "parabola");
    assert_eq!(strings(&f["location"]), ["-1/2", "0", "1/2"]);
    assert_eq!(strings(&f["x_direction"]["vector"]), ["1", "0", "1"]);
    assert_eq!(f["focal"]["square"], "1/8");
    assert_eq!(f["focal"]["exact"], "1/4*sqrt(2)");
    // and z = 1 + 2x: the hyperbola 3(x + 2/3)² − y² = 1/3, a² = 5/9 along (1, 0, 2)
    let [f] = &frames("x^2+y^2-z^2", "z-1-2*x")[..] else {
        panic!("one conic")
    };
    assert_eq!(f["type"], "hyperbola");
    assert_eq!(strings(&f["location"]), ["-2/3", "0", "-1/3"]);
    assert_eq!(strings(&f["x_direction"]["vector"]), ["1", "0", "2"]);
    assert_eq!(f["major_radius"]["exact"], "1/3*sqrt(5)");
    assert_eq!(f["minor_radius"]["square"], "1/3");
    // the sphere of radius 5 and the cylinder of radius 4: circles z = ±3 of radius 4
    let mut heights = Vec::new();
    for f in frames("x^2+y^2+z^2-25", "x^2+y^2-16") {
        assert_eq!(f["type"], "circle");
        assert_eq!(f["radius"]["exact"], "4");
        assert_eq!(strings(&f["normal"]["unit"]), ["0", "0", "1"]);
        assert_eq!(strings(&f["x_direction"]["unit"]), ["1", "0", "0"]);
        assert_eq!(strings(&f["y_direction"]["unit"]), ["0", "1", "0"]);
        heights.push(strings(&f["location"])[2].to_owned());
    }
    heights.sort();
    assert_eq!(heights, ["-3", "3"]);
    // x + y = 2 and z = x + 1: the line through (1/3, 5/3, 4/3) along (1, −1, 1)
    let fs = frames("(x+y-2)*(x+y+5)", "(z-x-1)*(z-x+7)");
    let line = fs
        .iter()
        .find(|f| strings(&f["location"]) == ["1/3", "5/3", "4/3"])
        .expect("the line x + y = 2, z = x + 1");
    assert_eq!(line["type"], "line");
    assert_eq!(strings(&line["direction"]["vector"]), ["1", "-1", "1"]);
    assert_eq!(line["direction"]["norm2"], "3");
    // --projective leaves the frames out
    let v: Value = serde_json::from_str(&stdout(&[
        "param",
        "--json",
        "--projective",
        "x^2+y^2-1",
        "x^2+z^2-1",
    ]))
    .unwrap();
    assert!(v["components"][0].get("frame").is_none());
}

/// `qsic classify`'s text starts with the pair in ℝ³, the projective class after it.
#[test]
fn the_classify_report_leads_with_r3() {
    let cases = [
        // a cone cut by a plane: a hyperbola (projectively a double conic, "closed")
        (
            "x^2+y^2-z^2",
            "z-1-2*x",
            "in R^3:           a hyperbola: 2 unbounded curves; 2 points at infinity",
            "surfaces:         circular cone and plane",
        ),
        // two parallel cylinders: nothing in ℝ³, one point at infinity (real type "point")
        (
            "x^2+y^2-1",
            "(x-3)^2+y^2-1",
            "in R^3:           no common point in ℝ³; 1 point at infinity",
            "surfaces:         circular cylinder and circular cylinder",
        ),
        // Viviani's curve: a quartic crossing itself at (2, 0, 0)
        (
            "x^2+y^2+z^2-4",
            "(x-1)^2+y^2-1",
            "in R^3:           a quartic curve with a crunode at (2, 0, 0): 1 bounded curve; no point at infinity",
            "surfaces:         sphere and circular cylinder",
        ),
    ];
    for (a, b, first, second) in cases {
        let text = stdout(&["classify", a, b]);
        let lines: Vec<&str> = text.lines().collect();
        assert!(lines[0].starts_with(first), "{a} ∩ {b}:\n{text}");
        assert_eq!(lines[1], second, "{a} ∩ {b}:\n{text}");
        let projective = lines
            .iter()
            .position(|l| l.starts_with("pencil:"))
            .expect("the projective class");
        assert!(projective > 1, "{text}");
        assert!(
            lines[projective - 1].starts_with("projective class"),
            "{text}"
        );
    }
    // --projective: the class alone, as before
    let text = stdout(&["classify", "--projective", "x^2+y^2-z^2", "z-1-2*x"]);
    assert!(text.starts_with("pencil:"), "{text}");
}

/// `qsic param`'s text prints finite points as `(x, y, z)`, points at infinity marked so, and
/// homogeneous coordinates with `--projective`.
#[test]
fn param_text_prints_points_in_r3() {
    let text = stdout(&["param", "x^2+y^2+z^2-1", "x+1"]);
    assert!(
        text.contains("singular point (multiple): (-1, 0, 0)\n"),
        "{text}"
    );
    let text = stdout(&["param", "x^2+y^2-1", "(x-3)^2+y^2-1"]);
    assert!(
        text.contains("singular point (multiple): (0 : 0 : 1 : 0), at infinity\n"),
        "{text}"
    );
    let text = stdout(&["param", "--projective", "x^2+y^2+z^2-1", "x+1"]);
    assert!(text.contains("(multiple): (1 : 0 : 0 : -1)\n"), "{text}");
    // a line's frame in the text
    let text = stdout(&["param", "(x+y-2)*(x+y+5)", "(z-x-1)*(z-x+7)"]);
    assert!(
        text.contains("frame: line: location (1/3, 5/3, 4/3), direction (1/3*sqrt(3), -1/3*sqrt(3), 1/3*sqrt(3))"),
        "{text}"
    );
}

/// The longest run of digits in `v` (a string, or every string inside).
fn longest_digits(v: &Value) -> usize {
    match v {
        Value::String(s) => s
            .split(|c: char| !c.is_ascii_digit())
            .map(str::len)
            .max()
            .unwrap_or(0),
        Value::Array(a) => a.iter().map(longest_digits).max().unwrap_or(0),
        Value::Object(o) => o.values().map(longest_digits).max().unwrap_or(0),
        _ => 0,
    }
}

#[test]
fn frames_and_conic_data_of_big_disguises_are_no_longer_than_the_curve() {
    // a conic of case 17 in a plane over ℚ(√δ), parameterized over a field of degree 4, and
    // four concurrent lines over a field of degree 4, under 450-bit disguises: the frame and
    // the affine data are read in the plane's field and at the line's own point, so they are
    // at most twice as long as the parameterization (they were 6 and 4 times)
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/big_disguises.jsonl"
    ))
    .unwrap();
    let mut checked = 0;
    for line in text.lines() {
        let pair: Value = serde_json::from_str(line).unwrap();
        let input = serde_json::json!({"id": pair["id"], "A": pair["A"], "B": pair["B"]});
        let out = qsic(&["param", "--batch", "-"], &format!("{input}\n"));
        let v: Value = serde_json::from_slice(&out.stdout).expect("one JSON answer");
        let comps = v["components"].as_array().expect("components");
        for c in comps.iter().filter(|c| c["real"] == Value::Bool(true)) {
            let curve = longest_digits(&c["param"]);
            for key in ["frame", "affine"] {
                let n = longest_digits(&c[key]);
                assert!(
                    n <= 2 * curve,
                    "{}: {key} has {n} digits, the curve {curve}",
                    pair["id"]
                );
            }
            checked += 1;
        }
    }
    assert_eq!(checked, 3);
}
