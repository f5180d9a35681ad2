//! The exports of `qsic sample` (`--format csv`, `--format obj`) against its JSON and against
//! independent routes: the points at infinity are the exact ones (the count of `qsic
//! classify`'s affine view; no affine coordinates for them, none huge for a finite point
//! that floats would put at infinity), a point near infinity but exactly finite keeps its
//! coordinates, the CSV's branches are the JSON's (same pieces, branches, order and points,
//! on every corpus curve) and never jump, and `--tolerance` outside its range is a usage
//! error that says so.

#[path = "common/run.rs"]
mod run;

use qsic_cli::sample::{sample_of, to_csv, to_obj, SampleJson, Sampling};
use run::qsic;
use serde_json::Value;

/// One CSV row.
#[derive(Clone, Debug)]
struct Row {
    x: [f64; 4],
    a: Option<[f64; 3]>,
}

/// The rows of a CSV as `pieces[k][b]`, the numbering checked (header, consecutive pieces,
/// branches and indices from 0).
fn read_csv(text: &str) -> Vec<Vec<Vec<Row>>> {
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("piece,branch,index,x,y,z,w,ax,ay,az"));
    let mut pieces: Vec<Vec<Vec<Row>>> = Vec::new();
    for line in lines {
        let f: Vec<&str> = line.split(',').collect();
        assert_eq!(f.len(), 10, "{line}");
        let n = |i: usize| f[i].parse::<usize>().unwrap();
        let v = |i: usize| f[i].parse::<f64>().unwrap();
        let (k, b, i) = (n(0), n(1), n(2));
        let a = match [f[7], f[8], f[9]] {
            ["", "", ""] => None,
            _ => Some([v(7), v(8), v(9)]),
        };
        if k == pieces.len() {
            pieces.push(Vec::new());
        }
        assert_eq!(k + 1, pieces.len(), "pieces in order: {line}");
        let branches = &mut pieces[k];
        if b == branches.len() {
            branches.push(Vec::new());
        }
        assert_eq!(b + 1, branches.len(), "branches in order: {line}");
        assert_eq!(i, branches[b].len(), "indices in order: {line}");
        branches[b].push(Row {
            x: [v(3), v(4), v(5), v(6)],
            a,
        });
    }
    pieces
}

fn stdout_of(args: &[&str]) -> String {
    let out = qsic(args, "");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

fn json_of(args: &[&str]) -> Value {
    serde_json::from_str(stdout_of(args).trim()).unwrap()
}

fn floats<const N: usize>(v: &Value) -> [f64; N] {
    std::array::from_fn(|i| v[i].as_f64().unwrap())
}

/// The symmetric matrix of a quadric text, as floats.
fn matrix(text: &str) -> [[f64; 4]; 4] {
    let m = qsic_cli::input::surface_from_arg(text)
        .unwrap()
        .quadric
        .unwrap();
    let m = m.matrix();
    std::array::from_fn(|i| std::array::from_fn(|j| m[i][j].to_f64().value()))
}

/// `|XᵀMX| / (‖M‖·|X|²)`.
fn residual(m: &[[f64; 4]; 4], x: &[f64; 4]) -> f64 {
    let norm = m.iter().flatten().map(|v| v * v).sum::<f64>().sqrt();
    let n2: f64 = x.iter().map(|v| v * v).sum();
    let r: f64 = (0..4)
        .flat_map(|i| (0..4).map(move |j| (i, j)))
        .map(|(i, j)| m[i][j] * x[i] * x[j])
        .sum();
    r.abs() / (norm * n2)
}

/// The same projective point: equal up to sign (`tol = 0`: exactly).
fn same_point(x: &[f64; 4], y: &[f64; 4], tol: f64) -> bool {
    let near = |s: f64| (0..4).all(|i| (x[i] - s * y[i]).abs() <= tol);
    near(1.0) || near(-1.0)
}

/// The JSON's real pieces: its components but the common surfaces (named, without points),
/// which the CSV and OBJ have no rows for.
fn pieces(json: &Value) -> Vec<Value> {
    json["components"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|c| c.get("name").is_none())
        .cloned()
        .collect()
}

/// The CSV of one curve is its JSON: for a piece in the chart one CSV branch per affine branch
/// whose affine cells are that branch's points, exactly and in order, with at most its first
/// and last rows at infinity, each one of the JSON's points at infinity (all of them used);
/// for a piece in the plane at infinity or an isolated point, the projective branches (up to
/// sign). Along every CSV branch the signs are continuous and consecutive points within
/// 0.1 rad: a polyline drawn per (piece, branch) never jumps.
fn check_csv_is_the_json(csv: &[Vec<Vec<Row>>], json: &Value) -> Result<(), String> {
    let comps = pieces(json);
    if csv.len() != comps.len() {
        return Err(format!(
            "{} pieces in the CSV, {} in the JSON",
            csv.len(),
            comps.len()
        ));
    }
    for (k, (branches, comp)) in csv.iter().zip(comps).enumerate() {
        let affine = &comp["affine"];
        let aff_branches = affine["branches"].as_array().unwrap();
        let at_inf: Vec<[f64; 4]> = affine["points_at_infinity"]
            .as_array()
            .unwrap()
            .iter()
            .map(floats::<4>)
            .collect();
        let in_plane = aff_branches.is_empty() && at_inf.is_empty();
        if comp["kind"] == "point" || in_plane {
            let proj = comp["branches"].as_array().unwrap();
            let point = aff_branches.first().map(|b| floats::<3>(&b[0]));
            if branches.len() != proj.len() {
                return Err(format!(
                    "piece {k}: {} branches, JSON {}",
                    branches.len(),
                    proj.len()
                ));
            }
            for (rows, want) in branches.iter().zip(proj) {
                let want: Vec<[f64; 4]> = want.as_array().unwrap().iter().map(floats).collect();
                let same = rows.len() == want.len()
                    && rows
                        .iter()
                        .zip(&want)
                        .all(|(r, w)| same_point(&r.x, w, 0.0));
                if !same || rows.iter().any(|r| r.a != point) {
                    return Err(format!("piece {k}: not the JSON's projective branch"));
                }
            }
        } else {
            if branches.len() != aff_branches.len() {
                return Err(format!(
                    "piece {k}: {} CSV branches, {} affine branches in the JSON",
                    branches.len(),
                    aff_branches.len()
                ));
            }
            let mut used = vec![false; at_inf.len()];
            for (b, (rows, want)) in branches.iter().zip(aff_branches).enumerate() {
                let want: Vec<[f64; 3]> = want.as_array().unwrap().iter().map(floats).collect();
                let cells: Vec<[f64; 3]> = rows.iter().filter_map(|r| r.a).collect();
                if cells != want {
                    return Err(format!(
                        "piece {k} branch {b}: not the JSON's affine points"
                    ));
                }
                for (i, r) in rows.iter().enumerate() {
                    if r.a.is_some() {
                        continue;
                    }
                    if i != 0 && i + 1 != rows.len() {
                        return Err(format!("piece {k} branch {b}: a point at infinity inside"));
                    }
                    // (a point met twice along the piece is listed twice)
                    let mut found = false;
                    for (j, y) in at_inf.iter().enumerate() {
                        if same_point(&r.x, y, 0.0) {
                            (used[j], found) = (true, true);
                        }
                    }
                    if !found {
                        return Err(format!("piece {k} branch {b}: {:?} not at infinity", r.x));
                    }
                }
            }
            if used.contains(&false) {
                return Err(format!("piece {k}: a point at infinity in no CSV row"));
            }
        }
        for (b, rows) in branches.iter().enumerate() {
            for w in rows.windows(2) {
                let d: f64 = (0..4).map(|i| w[0].x[i] * w[1].x[i]).sum();
                if d < (0.1f64 + 1e-9).cos() {
                    return Err(format!("piece {k} branch {b}: a jump (dot product {d})"));
                }
            }
        }
    }
    Ok(())
}

/// The cone and the plane `z = 2x + 1` (a hyperbola): the two points at infinity of the exact
/// affine view are rows without affine coordinates, each branch runs from one to the other,
/// and every affine row is a finite point of both quadrics; OBJ and JSON agree.
#[test]
fn the_cone_and_plane_csv_has_no_affine_point_at_infinity_and_two_branches() {
    let (a, b) = ("x^2+y^2-z^2", "z-2*x-1");
    let view = json_of(&["classify", "--json", a, b])["affine"].clone();
    let csv = read_csv(&stdout_of(&["sample", "--format", "csv", a, b]));
    let json = json_of(&["sample", a, b]);
    check_csv_is_the_json(&csv, &json).unwrap();
    let ms = [matrix(a), matrix(b)];
    assert_eq!(csv.len(), 1);
    let branches = &csv[0];
    assert_eq!(
        branches.len(),
        view["curves_unbounded"].as_u64().unwrap() as usize
    );
    let mut at_infinity: Vec<[f64; 4]> = Vec::new();
    for rows in branches {
        let (first, last) = (&rows[0], &rows[rows.len() - 1]);
        assert!(
            first.a.is_none() && last.a.is_none(),
            "a branch of a hyperbola ends at infinity"
        );
        for r in &rows[1..rows.len() - 1] {
            let a = r.a.expect("a finite point between the ends");
            // not at infinity to float precision: w well above its rounding
            assert!(r.x[3].abs() > 1e-13, "{:?} -> {a:?}", r.x);
            for m in &ms {
                assert!(
                    residual(m, &[a[0], a[1], a[2], 1.0]) < 1e-9,
                    "{a:?} off a quadric"
                );
            }
        }
        for r in [first, last] {
            for m in &ms {
                assert!(residual(m, &r.x) < 1e-9);
            }
            if !at_infinity.iter().any(|y| same_point(&r.x, y, 1e-9)) {
                at_infinity.push(r.x);
            }
        }
    }
    assert_eq!(
        at_infinity.len(),
        view["points_at_infinity"].as_u64().unwrap() as usize
    );
    // OBJ: the JSON's affine branches as polylines, no vertex at infinity
    let obj = stdout_of(&["sample", "--format", "obj", a, b]);
    let vertices: Vec<[f64; 3]> = obj
        .lines()
        .filter_map(|l| l.strip_prefix("v "))
        .map(|l| {
            let v: Vec<f64> = l.split(' ').map(|t| t.parse().unwrap()).collect();
            [v[0], v[1], v[2]]
        })
        .collect();
    let affine: Vec<[f64; 3]> = csv[0].iter().flatten().filter_map(|r| r.a).collect();
    assert_eq!(vertices, affine);
    assert_eq!(obj.lines().filter(|l| l.starts_with("l ")).count(), 2);
}

/// Viviani's curve (a sphere and a cylinder through its centre): one piece, a figure eight
/// through its crunode; the CSV has the JSON's two loops, each from the crunode back to it
/// (the node of `qsic param`, exact), with no singular point inside.
#[test]
fn viviani_csv_has_the_json_branches() {
    let (a, b) = ("x^2+y^2+z^2-1", "x^2+y^2-x");
    let csv = read_csv(&stdout_of(&["sample", "--format", "csv", a, b]));
    let json = json_of(&["sample", a, b]);
    check_csv_is_the_json(&csv, &json).unwrap();
    let param = json_of(&["param", "--json", a, b]);
    let nodes: Vec<[f64; 3]> = param["singular_points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| {
            assert_eq!(s["kind"], "crunode");
            let c: Vec<f64> = (0..4)
                .map(|i| {
                    let text = s["point"][i].as_str().unwrap();
                    qsic::io::parse_number(text).unwrap().to_f64().value()
                })
                .collect();
            [c[0] / c[3], c[1] / c[3], c[2] / c[3]]
        })
        .collect();
    assert_eq!(nodes.len(), 1);
    let node = nodes[0];
    let dist = |p: &[f64; 3]| (0..3).map(|i| (p[i] - node[i]).powi(2)).sum::<f64>().sqrt();
    assert_eq!(csv.len(), 1);
    // a closed piece through one crunode: two loops
    assert_eq!(csv[0].len(), 2 * nodes.len());
    for rows in &csv[0] {
        let ends = [rows[0].a.unwrap(), rows[rows.len() - 1].a.unwrap()];
        assert!(
            ends.iter().all(|p| dist(p) < 1e-12),
            "a loop from the node to it"
        );
        assert!(rows[1..rows.len() - 1]
            .iter()
            .all(|r| dist(&r.a.unwrap()) > 1e-6));
    }
}

/// The corpus pairs of `crates/qsic/tests/data` (every class the parameterization covers:
/// conics and lines over number fields, cubics, nodal quartics, Levin's quartics, isolated
/// points, curves in the plane at infinity) and a few more, in two charts: the CSV is the
/// JSON (in-process, through the CLI crate's own producers), and the OBJ's polylines are
/// the JSON's affine branches with no vertex at infinity to float precision.
#[test]
fn csv_and_obj_are_the_json_on_the_corpus() {
    let mut pairs: Vec<(String, Value, Value)> = Vec::new();
    for name in ["cases.jsonl", "seed_examples.jsonl", "qi-quadrics.jsonl"] {
        let path = format!("{}/../qsic/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).unwrap();
        for (i, raw) in text
            .lines()
            .enumerate()
            .filter(|(_, l)| !l.trim().is_empty())
        {
            let line: Value = serde_json::from_str(raw).unwrap();
            pairs.push((
                format!("{name}:{}", i + 1),
                line["A"].clone(),
                line["B"].clone(),
            ));
        }
    }
    for (a, b) in [
        ("x^2+y^2-z^2", "w^2"),
        ("x^2+y^2-z*w", "y^2"),
        ("x^2-y^2", "z^2"),
        ("x^2+y^2+z^2", "x^2+y^2-z^2"),
    ] {
        pairs.push((format!("{a} | {b}"), Value::from(a), Value::from(b)));
    }
    let charts = [
        ("w", qsic::param::sample::SampleOptions::default().chart),
        ("x - 2*w", qsic_cli::sample::parse_chart("x - 2*w").unwrap()),
    ];
    let (mut failures, mut compared) = (Vec::new(), 0);
    for (id, a, b) in &pairs {
        let read = |v: &Value| qsic_cli::input::quadric_from_json(v).unwrap();
        let (qa, qb) = (read(a), read(b));
        for (chart_text, chart) in &charts {
            let options = qsic::param::sample::SampleOptions {
                chart: chart.clone(),
                ..Default::default()
            };
            let Ok(Sampling {
                curve,
                sampled,
                surfaces,
            }) = sample_of(qa.as_ref(), qb.as_ref(), &options)
            else {
                continue;
            };
            compared += 1;
            let json = serde_json::to_value(SampleJson::new(&curve, &sampled, &surfaces)).unwrap();
            let csv = read_csv(&to_csv(&sampled));
            if let Err(why) = check_csv_is_the_json(&csv, &json) {
                failures.push(format!("{id} (chart {chart_text}): {why}"));
            }
            // OBJ: `v` lines in the order of the affine branches; none at infinity in floats
            let obj = to_obj(&sampled);
            let vertices: Vec<[f64; 3]> = obj
                .lines()
                .filter_map(|l| l.strip_prefix("v "))
                .map(|l| {
                    let v: Vec<f64> = l.split(' ').map(|t| t.parse().unwrap()).collect();
                    [v[0], v[1], v[2]]
                })
                .collect();
            let affine: Vec<[f64; 3]> = pieces(&json)
                .iter()
                .flat_map(|c| c["affine"]["branches"].as_array().unwrap().clone())
                .flat_map(|b| b.as_array().unwrap().clone())
                .map(|p| floats::<3>(&p))
                .collect();
            if vertices != affine {
                failures.push(format!("{id} (chart {chart_text}): OBJ vertices"));
            }
            if let Some(v) = vertices.iter().find(|v| v.iter().any(|c| c.abs() >= 1e13)) {
                failures.push(format!(
                    "{id} (chart {chart_text}): a vertex at infinity {v:?}"
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(compared > 400, "{compared} curves compared");
}

/// A circle of radius 10²⁰ is exactly finite: every row keeps its affine coordinates (on the
/// circle), though `w` is 10⁻²⁰ on every unit vector, and the piece is bounded.
#[test]
fn a_point_near_infinity_but_finite_keeps_its_coordinates() {
    let (a, b) = ("x^2+y^2-10^40", "z");
    let csv = read_csv(&stdout_of(&["sample", "--format", "csv", a, b]));
    let json = json_of(&["sample", a, b]);
    check_csv_is_the_json(&csv, &json).unwrap();
    assert_eq!(json["components"][0]["affine"]["bounded"], true);
    assert_eq!(json["affine"]["points_at_infinity"], 0);
    for r in csv.iter().flatten().flatten() {
        assert!(r.x[3].abs() < 1e-19, "w ≈ 10⁻²⁰: {:?}", r.x);
        let p = r.a.expect("a finite point has affine coordinates");
        let radius2 = p[0] * p[0] + p[1] * p[1];
        assert!((radius2 / 1e40 - 1.0).abs() < 1e-9 && p[2] == 0.0, "{p:?}");
    }
}

/// `--tolerance` outside (0, ∞) — zero, negative, NaN, infinite, not a number — is a usage
/// error (exit 2) naming the flag and the range, for single queries and batches; a positive
/// tolerance is taken.
#[test]
fn tolerance_outside_its_range_is_a_usage_error_that_says_so() {
    let (a, b) = ("x^2+y^2+z^2-1", "x^2+y^2-x");
    for t in ["0", "-1", "-0", "nan", "NaN", "inf", "-inf", "1e999", "abc"] {
        for args in [
            vec!["sample", "--tolerance", t, a, b],
            vec!["sample", "--format", "csv", "--tolerance", t, a, b],
            vec!["sample", "--batch", "-", "--tolerance", t],
        ] {
            let out = qsic(&args, "{\"A\": \"x^2+y^2-1\", \"B\": \"z\"}\n");
            let err = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
            assert!(out.stdout.is_empty(), "{args:?}");
            assert!(
                err.contains("--tolerance") && err.contains("positive finite number"),
                "{args:?}: {err}"
            );
        }
    }
    let out = qsic(&["sample", "--tolerance", "0.001", a, b], "");
    assert_eq!(out.status.code(), Some(0));
}
