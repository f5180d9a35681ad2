//! The whole curve ([`qsic::param::parameterize`]) on every labelled corpus line: each
//! component's parameterization lies on both quadrics identically (exact polynomial
//! identities in `u`), every real component has one, degree × multiplicity sums to 4 for a
//! regular pencil, and the connected real components (curves, isolated points) are those
//! the class has (the table of issue 8 / `check_sample.py`).

// Index loops read as the matrix formulas they implement.
#![allow(clippy::needless_range_loop)]

mod common;

#[path = "common/geometry.rs"]
mod geometry;

use common::read_form;
use geometry::moved;
use qsic::affine::{affine_curve, surface_name, AffineCurve, Chart};
use qsic::classify::PencilKind;
use qsic::param::{parameterize, Curve, RealPiece};
use qsic::{Error, Quadric};
use qsic_algebra::testing::SplitMix;
use qsic_algebra::RBig;
use serde_json::Value;

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
    for name in [
        "cases.jsonl",
        "seed_examples.jsonl",
        "qi-quadrics.jsonl",
        "no_rational_ruling.jsonl",
    ] {
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
                Err(Error::Unsupported(why)) => unsupported.push(format!("{id} ({why})")),
                Err(e) => failures.push(format!("{id}: {e}")),
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    eprintln!(
        "{done}/{total} curves checked, {} not supported yet",
        unsupported.len()
    );
    for id in &unsupported {
        eprintln!("  not supported: {id}");
    }
    // the supported classes grow: this bound only ever rises
    assert!(done >= 350, "{done} curves checked");
}

/// A random invertible affine map: small integer `M` with `det M = ±1` (a product of
/// elementary shears), translation `t`; with `similar`, a signed permutation instead of the
/// shears (a Euclidean motion: circles stay circles, spheres spheres).
fn affine_map(rng: &mut SplitMix, similar: bool) -> [[RBig; 4]; 4] {
    let mut m = [[0i64; 4]; 4];
    m[3][3] = 1;
    if similar {
        let mut perm = [0usize, 1, 2];
        for i in (1..3).rev() {
            perm.swap(i, rng.int(0, i as i64) as usize);
        }
        for i in 0..3 {
            m[i][perm[i]] = if rng.int(0, 1) == 0 { 1 } else { -1 };
        }
    } else {
        for i in 0..3 {
            m[i][i] = 1;
        }
        for _ in 0..4 {
            let (i, j) = (rng.int(0, 2) as usize, rng.int(0, 2) as usize);
            if i != j {
                let k = rng.int(-2, 2);
                for c in 0..3 {
                    m[i][c] += k * m[j][c];
                }
            }
        }
    }
    for i in 0..3 {
        m[i][3] = rng.int(-3, 3);
    }
    m.map(|r| r.map(RBig::from))
}

fn summary(v: &AffineCurve) -> Vec<String> {
    let mut out = vec![format!(
        "{} {} {} {} {} {}",
        v.curves_bounded,
        v.curves_unbounded,
        v.isolated_points,
        v.points_at_infinity,
        v.singular_finite,
        v.singular_at_infinity
    )];
    // the components' order is not part of the answer
    let mut components: Vec<String> = v
        .components
        .iter()
        .map(|c| {
            format!(
                "{:?} {} {:?} {}",
                c.name, c.at_infinity, c.bounded, c.points_at_infinity
            )
        })
        .collect();
    components.sort();
    out.extend(components);
    out
}

/// [`summary`] with the Euclidean words (circle) replaced by the affine ones (ellipse).
fn affine_summary(v: &AffineCurve) -> Vec<String> {
    summary(v)
        .into_iter()
        .map(|s| s.replace("circle", "ellipse"))
        .collect()
}

/// An affine map (fixing the plane at infinity) changes no affine answer, on every corpus
/// line whose curve is available.
#[test]
fn affine_answers_are_invariant_under_affine_maps() {
    let mut rng = SplitMix(0x5eed_affe);
    let (mut checked, mut failures) = (0, Vec::new());
    let chart = Chart::default();
    for name in ["cases.jsonl", "seed_examples.jsonl", "qi-quadrics.jsonl"] {
        let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).unwrap();
        for (i, raw) in text.lines().enumerate() {
            let line: Value = serde_json::from_str(raw).unwrap();
            if line.get("A").is_none()
                || !matches!(line["pencil"].as_str(), Some("regular" | "singular"))
            {
                continue;
            }
            let (a, b) = (read_form(&line["A"]), read_form(&line["B"]));
            let Ok(curve) = parameterize(&a, &b) else {
                continue;
            };
            let Ok(before) = affine_curve(&curve, &a, &b, &chart) else {
                continue;
            };
            for similar in [false, true] {
                let t = affine_map(&mut rng, similar);
                let (a2, b2) = (moved(&a, &t), moved(&b, &t));
                let after = parameterize(&a2, &b2).and_then(|c| affine_curve(&c, &a2, &b2, &chart));
                let names =
                    |a: &Quadric, b: &Quadric| [surface_name(a, &chart), surface_name(b, &chart)];
                let same = |after: &AffineCurve| {
                    if similar {
                        summary(after) == summary(&before) && names(&a, &b) == names(&a2, &b2)
                    } else {
                        affine_summary(after) == affine_summary(&before)
                    }
                };
                match after {
                    Ok(after) if same(&after) => checked += 1,
                    Ok(after) => failures.push(format!(
                        "{name}:{} ({}): {:?} became {:?}",
                        i + 1,
                        if similar { "similarity" } else { "affine" },
                        summary(&before),
                        summary(&after)
                    )),
                    Err(e) => failures.push(format!("{name}:{}: after the map: {e}", i + 1)),
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(checked >= 30, "{checked} checked");
}
