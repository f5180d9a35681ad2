//! The whole curve ([`qsic::param::parameterize`]) on every labelled corpus line: each
//! component's parameterization lies on both quadrics identically (exact polynomial
//! identities in `u`), every real component has one, degree × multiplicity sums to 4 for a
//! regular pencil, and the connected real components (curves, isolated points) are those
//! the class has (the table of issue 8 / `check_sample.py`).

use qsic::classify::PencilKind;
use qsic::io::{parse_quadric, quadric_from_rows};
use qsic::param::{parameterize, Curve, RealPiece};
use qsic::{Error, Quadric};
use serde_json::Value;

fn read_form(v: &Value) -> Quadric {
    match v {
        Value::String(s) => parse_quadric(s).unwrap(),
        Value::Array(rows) => {
            let rows: Vec<Vec<String>> = rows
                .iter()
                .map(|r| {
                    r.as_array()
                        .unwrap()
                        .iter()
                        .map(|x| x.as_str().map_or_else(|| x.to_string(), str::to_owned))
                        .collect()
                })
                .collect();
            quadric_from_rows(&rows).unwrap()
        }
        _ => panic!("unexpected quadric value {v}"),
    }
}

/// Connected components of the real locus in ℝP³, `(curves, isolated points)`, per case.
fn expected_regular(case: u8) -> (usize, usize) {
    const CC: [(usize, usize); 35] = [
        (2, 0),
        (0, 0),
        (1, 0),
        (2, 0),
        (1, 0),
        (1, 1),
        (0, 1),
        (1, 0),
        (1, 0),
        (2, 0),
        (1, 0),
        (1, 0),
        (1, 0),
        (2, 0),
        (0, 2),
        (0, 0),
        (1, 0),
        (1, 0),
        (1, 0),
        (0, 0),
        (1, 0),
        (0, 1),
        (1, 0),
        (1, 1),
        (0, 1),
        (1, 0),
        (1, 0),
        (1, 0),
        (0, 0),
        (0, 2),
        (2, 0),
        (1, 0),
        (0, 1),
        (1, 0),
        (1, 0),
    ];
    CC[usize::from(case) - 1]
}

/// The same for singular pencils, by `(complex_type, real_type)`.
fn expected_singular(complex: &str, real: &str) -> Option<(usize, usize)> {
    Some(match (complex, real) {
        ("conic_and_double_line", "conic_and_double_line") => (1, 0),
        ("four_concurrent_lines", "point") => (0, 1),
        ("four_concurrent_lines", _) => (1, 0),
        ("two_concurrent_lines_and_double_line", _) => (1, 0),
        ("line_and_triple_line", _) => (1, 0),
        ("two_concurrent_double_lines", "point") => (0, 1),
        ("two_concurrent_double_lines", _) => (1, 0),
        ("quadruple_line", _) | ("quadruple_line_of_plane_pairs", _) => (1, 0),
        _ => return None,
    })
}

/// Checks `curve` for `a`, `b`; the reason it is wrong, if it is.
fn check(curve: &Curve, a: &Quadric, b: &Quadric) -> Result<(), String> {
    let c = &curve.classification;
    let mut degree = 0;
    for (i, comp) in curve.components.iter().enumerate() {
        let on_both =
            |p: &qsic::param::ComponentParam| p.lies_on(a.matrix()) && p.lies_on(b.matrix());
        match &comp.param {
            Some(p) if !on_both(p) => {
                return Err(format!(
                    "component {i} ({}) is not on both quadrics",
                    comp.kind.key()
                ));
            }
            // a plane or a whole quadric is a surface: no curve parameterization
            None if comp.real && comp.kind.degree().is_some() => {
                return Err(format!("real component {i} without parameterization"))
            }
            _ => {}
        }
        degree += comp.kind.degree().unwrap_or(0) * comp.multiplicity;
    }
    if c.pencil == PencilKind::Regular && degree != 4 {
        return Err(format!("degree × multiplicity sums to {degree}"));
    }
    for piece in &curve.pieces {
        if piece.component() >= curve.components.len() {
            return Err("a piece of no component".into());
        }
    }
    let mut seen = vec![0; curve.pieces.len()];
    for group in &curve.connected {
        for &i in group {
            *seen.get_mut(i).ok_or("a group names no piece")? += 1;
        }
    }
    if seen.iter().any(|&n| n != 1) {
        return Err("connected groups do not partition the pieces".into());
    }
    let is_point = |g: &Vec<usize>| {
        g.iter()
            .all(|&i| matches!(curve.pieces[i], RealPiece::Point { .. }))
    };
    let points = curve.connected.iter().filter(|g| is_point(g)).count();
    let got = (curve.connected.len() - points, points);
    let want = match c.case {
        Some(case) => Some(expected_regular(case)),
        None => expected_singular(c.complex_type().unwrap_or(""), c.real_type().unwrap_or("")),
    };
    match want {
        Some(want) if want != got => {
            Err(format!("(curves, points) {got:?}, the class has {want:?}"))
        }
        _ => Ok(()),
    }
}

#[test]
fn every_curve_of_the_corpora_lies_on_both_quadrics_and_has_the_class_topology() {
    let mut failures = Vec::new();
    let (mut done, mut unsupported, mut total) = (0, Vec::new(), 0);
    for name in ["cases.jsonl", "seed_examples.jsonl", "qi-quadrics.jsonl"] {
        let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
        for (i, raw) in text.lines().enumerate() {
            let line: Value = serde_json::from_str(raw).unwrap();
            if line.get("A").is_none()
                || !matches!(line["pencil"].as_str(), Some("regular" | "singular"))
            {
                continue;
            }
            total += 1;
            let id = format!("{name}:{} {}", i + 1, line["id"].as_str().unwrap_or("?"));
            let (a, b) = (read_form(&line["A"]), read_form(&line["B"]));
            match parameterize(&a, &b) {
                Ok(curve) => match check(&curve, &a, &b) {
                    Ok(()) => done += 1,
                    Err(why) => failures.push(format!("{id}: {why}")),
                },
                Err(Error::Unsupported(_)) => unsupported.push(id),
                Err(e) => failures.push(format!("{id}: {e}")),
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    eprintln!(
        "{done}/{total} curves checked, {} not supported yet",
        unsupported.len()
    );
    // the supported classes grow: this bound only ever rises
    assert!(done >= 262, "{done} curves checked");
}
