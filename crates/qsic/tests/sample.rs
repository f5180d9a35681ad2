//! Real points of the whole curve ([`qsic::param::sample::sample`]) on every corpus line the
//! parameterization covers: every point on both quadrics, consecutive points within 0.1 rad
//! (up to sign), at least the requested count per piece, one sampled piece per real piece,
//! and the affine view consistent with the points (crossings of the plane at infinity on
//! it, affine points that map back to the projective ones).

mod common;

use common::read_form;
use qsic::io::parse_quadric;
use qsic::param::sample::{sample, SampleOptions, SampledPiece, MAX_ANGLE};
use qsic::param::{parameterize, Curve, ParamRange, ParamValue, RealPiece};
use qsic::{Error, Quadric};
use qsic_algebra::RBig;
use serde_json::Value;

/// The corpus pairs whose curve is parameterized, with their ids.
fn curves() -> Vec<(String, Quadric, Quadric, Curve)> {
    let mut out = Vec::new();
    for name in [
        "cases.jsonl",
        "seed_examples.jsonl",
        "qi-quadrics.jsonl",
        "no_rational_ruling.jsonl",
        "wide_coefficients.jsonl",
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
            let id = format!("{name}:{} {}", i + 1, line["id"].as_str().unwrap_or("?"));
            let (a, b) = (read_form(&line["A"]), read_form(&line["B"]));
            match parameterize(&a, &b) {
                Ok(c) => out.push((id, a, b, c)),
                Err(Error::Unsupported(_)) => {}
                Err(e) => panic!("{id}: {e}"),
            }
        }
    }
    out
}

fn float_matrix(q: &Quadric) -> [[f64; 4]; 4] {
    let m = q.matrix();
    std::array::from_fn(|i| std::array::from_fn(|j| m[i][j].to_f64().value()))
}

/// `|XᵀMX| / ‖M‖` for a unit `X`.
fn residual(m: &[[f64; 4]; 4], x: &[f64; 4]) -> f64 {
    let norm = m.iter().flatten().map(|v| v * v).sum::<f64>().sqrt();
    let mut r = 0.0;
    for i in 0..4 {
        for j in 0..4 {
            r += m[i][j] * x[i] * x[j];
        }
    }
    r.abs() / norm
}

fn check_piece(p: &SampledPiece, ms: &[[[f64; 4]; 4]; 2], points: usize) -> Result<(), String> {
    if !p.isolated && p.points.len() < points {
        return Err(format!("{} points, asked for {points}", p.points.len()));
    }
    for (k, x) in p.points.iter().enumerate() {
        let n = x.iter().map(|v| v * v).sum::<f64>();
        if (n - 1.0).abs() > 1e-12 {
            return Err(format!("point {k} is not a unit vector"));
        }
        for m in ms {
            let r = residual(m, x);
            if r > 1e-9 {
                return Err(format!("point {k} off a quadric by {r:e}"));
            }
        }
    }
    for (k, w) in p.points.windows(2).enumerate() {
        let d: f64 = (0..4).map(|i| w[0][i] * w[1][i]).sum();
        if d < 0.0 {
            return Err(format!("points {k}, {} not oriented", k + 1));
        }
        if d < (MAX_ANGLE + 1e-9).cos() {
            return Err(format!("points {k}, {} are {} rad apart", k + 1, d.acos()));
        }
    }
    if p.closed {
        let (f, l) = (p.points[0], p.points[p.points.len() - 1]);
        if (0..4).any(|i| (f[i].abs() - l[i].abs()).abs() > 1e-12) {
            return Err("a closed piece does not end where it starts".into());
        }
    }
    // affine: the chart w; points at infinity have w = 0, affine points are on both quadrics
    for x in &p.affine.points_at_infinity {
        if x[3].abs() > 1e-9 {
            return Err(format!("a point at infinity has w = {}", x[3]));
        }
    }
    if !p.affine.at_infinity && p.affine.bounded != p.affine.points_at_infinity.is_empty() {
        return Err("bounded but with points at infinity".into());
    }
    for branch in &p.affine.branches {
        for a in branch {
            let x = [a[0], a[1], a[2], 1.0];
            let n = x.iter().map(|v| v * v).sum::<f64>().sqrt();
            let x = x.map(|v| v / n);
            for m in ms {
                if residual(m, &x) > 1e-9 {
                    return Err(format!("affine point {a:?} off a quadric"));
                }
            }
        }
    }
    if p.affine.at_infinity
        && !(p.affine.branches.is_empty() && p.affine.points_at_infinity.is_empty() || p.isolated)
    {
        return Err("a piece at infinity with affine points".into());
    }
    let crossings = p.affine.points_at_infinity.len();
    // the affine branches also end at the finite singular points met along the piece
    let finite_breaks = p
        .breaks
        .iter()
        .filter(|&&k| p.points[k][3].abs() > 1e-12)
        .count();
    let cuts = crossings + finite_breaks;
    let want = if p.closed { cuts.max(1) } else { cuts + 1 };
    if !p.isolated && !p.affine.at_infinity && p.affine.branches.len() != want {
        return Err(format!(
            "{} affine branches for {crossings} points at infinity and {finite_breaks} singular points",
            p.affine.branches.len()
        ));
    }
    Ok(())
}

#[test]
fn every_sampled_point_is_on_both_quadrics_and_branches_are_continuous() {
    let curves = curves();
    assert!(curves.len() >= 37, "{} curves", curves.len());
    let mut failures = Vec::new();
    let (mut through_infinity, mut unbounded) = (0, 0);
    for (id, a, b, curve) in &curves {
        let ms = [float_matrix(a), float_matrix(b)];
        for points in [5, 100] {
            let options = SampleOptions {
                points,
                ..SampleOptions::default()
            };
            let s = match sample(curve, &options) {
                Ok(s) => s,
                Err(e) => {
                    failures.push(format!("{id}: {e}"));
                    continue;
                }
            };
            if s.pieces.len() != curve.pieces.len() {
                failures.push(format!("{id}: {} pieces sampled", s.pieces.len()));
            }
            for (k, p) in s.pieces.iter().enumerate() {
                if let Err(why) = check_piece(p, &ms, points) {
                    failures.push(format!("{id} piece {k} ({points} points): {why}"));
                }
                unbounded += usize::from(!p.affine.bounded);
            }
        }
        through_infinity += curve
            .pieces
            .iter()
            .filter(|p| match p {
                RealPiece::Curve { arcs, .. } => arcs.iter().any(|a| match &a.range {
                    ParamRange::All => true,
                    ParamRange::Between(ParamValue::Finite(l), ParamValue::Finite(h)) => h <= l,
                    ParamRange::Between(..) => true,
                }),
                RealPiece::Point { .. } => false,
            })
            .count();
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    // the corpus exercises ranges through u = ∞ and unbounded pieces
    assert!(
        through_infinity > 0 && unbounded > 0,
        "{through_infinity} {unbounded}"
    );
}

/// The points at infinity are the exact crossings of the plane at infinity, never a float `w`
/// near zero: on every corpus curve (rational components over ℚ and over number fields
/// included) the marked points of each component are the exact points at infinity of
/// [`qsic::affine::affine_curve`] (an independent route: roots of `w(u)` by the norm), no
/// affine point is at infinity to float precision (`|w| ≤ 10⁻¹³`: `w`'s rounding), and each
/// affine point is `X/w` of the point its index names. (A pair of conics over ℚ(α), α of
/// degree 4, once had a point with `w ≈ 4·10⁻¹⁸` at affine distance 5·10¹⁵.)
#[test]
fn points_at_infinity_are_the_exact_crossings_of_the_plane() {
    let chart = qsic::affine::Chart::default();
    let mut failures = Vec::new();
    let mut crossed = 0;
    for (id, a, b, curve) in &curves() {
        let Ok(view) = qsic::affine::affine_curve(curve, a, b, &chart) else {
            continue;
        };
        let s = sample(curve, &SampleOptions::default()).unwrap_or_else(|e| panic!("{id}: {e}"));
        // per component: the distinct projective points marked at infinity
        let mut marked: Vec<Vec<[f64; 4]>> = vec![Vec::new(); curve.components.len()];
        for (k, p) in s.pieces.iter().enumerate() {
            let mut fail = |why: String| failures.push(format!("{id} piece {k}: {why}"));
            let at: Vec<[f64; 4]> = p.infinity.iter().map(|&i| p.points[i]).collect();
            if at != p.affine.points_at_infinity {
                fail("the marks are not the points at infinity".into());
            }
            // the count of `affine_curve` is of the curve pieces (an acnode is a point)
            for x in at.into_iter().filter(|_| !p.isolated) {
                let seen = &mut marked[p.component];
                let near =
                    |y: &[f64; 4], sign: f64| (0..4).all(|i| (x[i] - sign * y[i]).abs() < 1e-9);
                let same = |y: &[f64; 4]| near(y, 1.0) || near(y, -1.0);
                if !seen.iter().any(same) {
                    seen.push(x);
                }
            }
            if p.affine.indices.len() != p.affine.branches.len() {
                fail("one index list per affine branch".into());
            }
            for (branch, indices) in p.affine.branches.iter().zip(&p.affine.indices) {
                if branch.len() != indices.len() {
                    fail("one index per affine point".into());
                }
                for (v, &i) in branch.iter().zip(indices) {
                    let x = p.points[i];
                    let a = [x[0] / x[3], x[1] / x[3], x[2] / x[3]];
                    // an isolated point's are exact, rounded once
                    let off = |k: usize| (v[k] - a[k]).abs() > 1e-12 * (1.0 + a[k].abs());
                    if if p.isolated { (0..3).any(off) } else { v != &a } {
                        fail(format!("affine point {v:?} is not X/w of point {i}"));
                    }
                    if x[3].abs() <= 1e-13 {
                        fail(format!(
                            "affine point {v:?} (w = {:e}) is at infinity",
                            x[3]
                        ));
                    }
                }
            }
        }
        for (c, comp) in view.components.iter().enumerate() {
            if comp.at_infinity || comp.name.is_none() {
                continue;
            }
            crossed += usize::from(comp.points_at_infinity > 0);
            if marked[c].len() != comp.points_at_infinity {
                failures.push(format!(
                    "{id} component {c}: {} points at infinity marked, {} exactly",
                    marked[c].len(),
                    comp.points_at_infinity
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(crossed > 20, "{crossed} components through infinity");
}

#[test]
fn tolerance_bounds_the_affine_chord_deviation() {
    // two ellipses (a sphere and an elliptic cylinder): bounded, so every chord counts
    let a = parse_quadric("x^2+y^2+z^2-1").unwrap();
    let b = parse_quadric("2*x^2+4*y^2-1").unwrap();
    let curve = parameterize(&a, &b).unwrap();
    let coarse = sample(&curve, &SampleOptions::default()).unwrap();
    let tol = 1e-4;
    let fine = sample(
        &curve,
        &SampleOptions {
            tolerance: Some(tol),
            ..SampleOptions::default()
        },
    )
    .unwrap();
    for (c, f) in coarse.pieces.iter().zip(&fine.pieces) {
        assert!(f.points.len() > c.points.len());
        // the midpoint of each chord is within about tol of the curve (a unit sphere here):
        // |mid| ≥ 1 − tol
        for branch in &f.affine.branches {
            for w in branch.windows(2) {
                let mid: Vec<f64> = (0..3).map(|i| 0.5 * (w[0][i] + w[1][i])).collect();
                let r = mid.iter().map(|v| v * v).sum::<f64>().sqrt();
                assert!(r >= 1.0 - 2.0 * tol, "chord midpoint at radius {r}");
            }
        }
    }
}

#[test]
fn a_user_chart_moves_the_points_at_infinity() {
    // the plane x = 2w (h = x − 2w) never meets the ellipses of the sphere (|x| ≤ 1), the
    // plane x = w/2 (h = 2x − w) cuts each of them twice
    let a = parse_quadric("x^2+y^2+z^2-1").unwrap();
    let b = parse_quadric("2*x^2+4*y^2-1").unwrap();
    let curve = parameterize(&a, &b).unwrap();
    let r = |v: i64| RBig::from(v);
    for (chart, crossings) in [
        ([r(1), r(0), r(0), r(-2)], 0),
        ([r(2), r(0), r(0), r(-1)], 2),
    ] {
        let s = sample(
            &curve,
            &SampleOptions {
                chart: chart.clone(),
                ..SampleOptions::default()
            },
        )
        .unwrap();
        for p in &s.pieces {
            assert_eq!(p.affine.points_at_infinity.len(), crossings, "{chart:?}");
            assert_eq!(p.affine.bounded, crossings == 0);
            assert_eq!(p.affine.branches.len(), crossings.max(1));
            for x in &p.affine.points_at_infinity {
                // on the plane: x = w/2
                assert!((2.0 * x[0] - x[3]).abs() < 1e-12, "{x:?}");
            }
        }
    }
    let zero = SampleOptions {
        chart: [r(0), r(0), r(0), r(0)],
        ..SampleOptions::default()
    };
    assert!(sample(&curve, &zero).is_err());
    let none = SampleOptions {
        points: 0,
        ..SampleOptions::default()
    };
    assert!(matches!(
        sample(&curve, &none),
        Err(Error::InvalidOption(_))
    ));
}

/// A tolerance that is not a positive finite number is an invalid option whose message says
/// which option, the range and the value (the Python binding shows it as it is).
#[test]
fn a_tolerance_outside_its_range_is_an_invalid_option() {
    let a = parse_quadric("x^2+y^2+z^2-1").unwrap();
    let b = parse_quadric("2*x^2+4*y^2-1").unwrap();
    let curve = parameterize(&a, &b).unwrap();
    for t in [0.0, -0.0, -1.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let options = SampleOptions {
            tolerance: Some(t),
            ..SampleOptions::default()
        };
        match sample(&curve, &options) {
            Err(e @ Error::InvalidOption(_)) => {
                let m = e.to_string();
                assert!(
                    m.contains("tolerance") && m.contains("positive finite"),
                    "{m}"
                );
                assert!(m.ends_with(&format!("not {t}")), "{m}");
            }
            other => panic!("tolerance {t}: {other:?}"),
        }
    }
}

/// A line over ℚ(√5) of a disguised skew quadrilateral (QI entry 67 under an integer change of
/// coordinates and of pencil basis): its direction term is ~4000 times its point term, so the
/// vector turns half round within |θ| < 0.03 and two samples there are nearly opposite, one
/// projective point to a test up to sign — the sampler must still go round between them.
#[test]
fn a_line_dominated_by_its_direction_is_sampled_without_a_jump() {
    let form = |text: &str| read_form(&serde_json::from_str(text).unwrap());
    let a = form("[[-19,75,-119,103],[75,-180,525,-285],[-119,525,-719,703],[103,-285,703,-431]]");
    let b = form(
        "[[-1121,1401,-1918,2178],[1401,-1695,2856,-2773],[-1918,2856,-3655,4209],[2178,-2773,4209,-4359]]",
    );
    let curve = parameterize(&a, &b).unwrap();
    let ms = [float_matrix(&a), float_matrix(&b)];
    for points in [5, 64] {
        let options = SampleOptions {
            points,
            ..SampleOptions::default()
        };
        let s = sample(&curve, &options).unwrap();
        assert_eq!(s.pieces.len(), 4);
        for p in &s.pieces {
            check_piece(p, &ms, points).unwrap();
        }
    }
}

/// Rotated and shifted CAD shapes with decimal data (a cylinder and a cone, an ellipsoid and a
/// hyperboloid): Levin's `s(u)` came out with coefficients 10⁸⁶ apart, its real roots near
/// 10⁻²¹, where floats in θ cannot follow the curve; the parameter is now scaled by a power of
/// two so that the roots of `s` are near 1.
#[test]
fn real_world_pairs_with_unbalanced_levin_forms_are_sampled() {
    let pairs = [
        (
            "5*x^2/9 + 8*x*y/9 + 4*x*z/9 - 21*x/5 + 5*y^2/9 - 4*y*z/9 - 2*y + 8*z^2/9 - z/2 + 162/25",
            "9961*x^2/10609 + 4752*x*y/10609 + 5544*x*z/10609 - 95595*x/10609 + 1897*y^2/10609 - 20328*y*z/10609 + 256706*y/53045 - 1249*z^2/10609 - 17194*z/10609 + 19998053/1060900",
        ),
        (
            "85*x^2/121 + 72*x*y/121 - 84*x*z/121 + 174*x/121 + 85*y^2/121 + 84*y*z/121 - 1233*y/605 + 72*z^2/121 - 8739*z/1210 + 8001/1210",
            "49*x^2/121 + 1008*x*y/605 - 456*x*z/605 + 9027*x/3025 - 503*y^2/3025 + 3192*y*z/3025 - 49274*y/15125 + 2303*z^2/3025 + 108143*z/15125 - 670348/75625",
        ),
    ];
    for (a, b) in pairs {
        let (a, b) = (parse_quadric(a).unwrap(), parse_quadric(b).unwrap());
        let curve = parameterize(&a, &b).unwrap();
        let ms = [float_matrix(&a), float_matrix(&b)];
        let s = sample(&curve, &SampleOptions::default()).unwrap();
        assert_eq!(s.pieces.len(), curve.pieces.len());
        for p in &s.pieces {
            check_piece(p, &ms, 64).unwrap();
        }
    }
}

/// A CAD pair (rotated and shifted) whose `s(u)` has two real roots `10⁻⁴` apart: the float `s`
/// cannot place its arc ends (Newton on it lands `10⁻⁷` off, and the ends were `10⁻⁴` off
/// the quadrics); the exact refinement must take over there.
#[test]
fn arc_ends_at_a_near_double_root_of_s_stay_on_the_quadrics() {
    let a = parse_quadric("49*x^2/81 - 128*x*y/81 + 16*x*z/81 - 3064*x/405 - 47*y^2/81 + 32*y*z/81 - 458*y/405 + 79*z^2/81 + 1981*z/405 + 917/162").unwrap();
    let b = parse_quadric("10649*x^2/22201 + 36480*x*y/22201 + 13680*x*z/22201 - 121591*x/22201 - 6599*y^2/22201 - 21600*y*z/22201 + 313763*y/111005 + 18151*z^2/22201 + 470102*z/111005 - 14796651/2220100").unwrap();
    let curve = parameterize(&a, &b).unwrap();
    let ms = [float_matrix(&a), float_matrix(&b)];
    for points in [5, 64, 1000] {
        let options = SampleOptions {
            points,
            ..SampleOptions::default()
        };
        let s = sample(&curve, &options).unwrap();
        assert_eq!(s.pieces.len(), 1);
        for p in &s.pieces {
            check_piece(p, &ms, points).unwrap();
        }
    }
}

#[path = "../benches/inputs/mod.rs"]
mod inputs;

/// Random generic pairs (cases 1–4, the `param_cost` family, irrational Levin forms): about
/// 1000 points per curve, every piece checked as on the corpus; in the default chart and in an
/// oblique one the points at infinity (located along the polyline) lie on the plane, and
/// their number is the exact count of `affine_view_of_curve`; with a tolerance the chords
/// near the origin stay within it.
#[test]
fn random_generic_pairs_are_sampled_densely_on_both_quadrics() {
    use qsic::affine::{affine_view_of_curve, Chart};
    let mut rng = inputs::SplitMix(0x5a_3b_1e);
    let pairs: Vec<(Quadric, Quadric)> = inputs::random_pairs(&mut rng, 120)
        .into_iter()
        .filter(|(a, b)| matches!(qsic::classify(a, b).case, Some(1..=4)))
        .take(10)
        .collect();
    assert_eq!(pairs.len(), 10);
    let r = |v: i64| RBig::from(v);
    let charts = [[r(0), r(0), r(0), r(1)], [r(1), r(-2), r(3), r(5)]];
    let (mut crossings_seen, mut pieces_seen) = (0, 0);
    for (k, (a, b)) in pairs.iter().enumerate() {
        let curve = parameterize(a, b).unwrap();
        let ms = [float_matrix(a), float_matrix(b)];
        let points = 1000usize.div_ceil(curve.pieces.len().max(1));
        let options = SampleOptions {
            points,
            ..SampleOptions::default()
        };
        let s = sample(&curve, &options).unwrap();
        assert_eq!(s.pieces.len(), curve.pieces.len(), "pair {k}");
        for p in &s.pieces {
            check_piece(p, &ms, points).unwrap_or_else(|e| panic!("pair {k}: {e}"));
        }
        for chart in &charts {
            let options = SampleOptions {
                points: 40,
                chart: chart.clone(),
                ..SampleOptions::default()
            };
            let s = sample(&curve, &options).unwrap();
            let norm = chart.iter().map(|c| c.to_f64().value().abs()).sum::<f64>();
            let mut at_infinity = 0;
            for p in &s.pieces {
                for x in &p.affine.points_at_infinity {
                    let h: f64 = (0..4).map(|i| chart[i].to_f64().value() * x[i]).sum();
                    assert!(h.abs() <= 1e-12 * norm, "pair {k}: h = {h} at infinity");
                }
                at_infinity += p.affine.points_at_infinity.len();
                let want = if p.closed {
                    p.affine.points_at_infinity.len().max(1)
                } else {
                    p.affine.points_at_infinity.len() + 1
                };
                assert_eq!(p.affine.branches.len(), want, "pair {k}");
            }
            let exact = affine_view_of_curve(
                Some(a),
                Some(b),
                Some(&curve),
                &Chart::new(chart.clone()).unwrap(),
                [false; 2],
            )
            .curve
            .unwrap()
            .points_at_infinity;
            assert_eq!(at_infinity, exact, "pair {k}, chart {chart:?}");
            crossings_seen += at_infinity;
        }
        // a chord tolerance refines the polyline (every curve has affine extent ≫ 10⁻³)
        let with = |tolerance: Option<f64>| {
            sample(
                &curve,
                &SampleOptions {
                    points: 16,
                    tolerance,
                    ..SampleOptions::default()
                },
            )
            .unwrap()
        };
        let (coarse, fine) = (with(None), with(Some(1e-3)));
        let count = |s: &qsic::param::sample::Sampled| -> usize {
            s.pieces.iter().map(|p| p.points.len()).sum()
        };
        // (a curve with no real point has no piece)
        assert!(
            coarse.pieces.is_empty() || count(&fine) > count(&coarse),
            "pair {k}"
        );
        pieces_seen += coarse.pieces.len();
        for p in &fine.pieces {
            check_piece(p, &ms, 16).unwrap_or_else(|e| panic!("pair {k}, tolerance: {e}"));
        }
    }
    // the family crosses the planes: the located crossings were exercised
    assert!(
        crossings_seen > 0 && pieces_seen >= 8,
        "{crossings_seen} {pieces_seen}"
    );
}

/// The last guard: the points of a curve pass against its own quadrics and fail against
/// another one.
#[test]
fn points_are_verified_against_the_quadrics() {
    use qsic::param::sample::verify_on_quadrics;
    let a = parse_quadric("x^2+y^2+z^2-w^2").unwrap();
    let b = parse_quadric("2*x^2+4*y^2-w^2").unwrap();
    let s = sample(&parameterize(&a, &b).unwrap(), &SampleOptions::default()).unwrap();
    assert!(verify_on_quadrics(&s, &a, &b).is_ok());
    let other = parse_quadric("x^2+y^2+2*z^2-w^2").unwrap();
    assert!(verify_on_quadrics(&s, &a, &other).is_err());
}

/// The turn guard: every branch of a sampled curve (a smooth quartic, a nodal one with its
/// branches cut at the node, a conic pair) keeps consecutive points within `MAX_ANGLE`,
/// and a gap made by dropping points from a branch is caught, naming the piece.
#[test]
fn turns_are_verified_along_every_branch() {
    use qsic::param::sample::{verify_turns, MAX_ANGLE};
    for (a, b) in [
        ("x^2+y^2+z^2-w^2", "2*x^2+4*y^2-w^2"),
        ("x^2+y^2+z^2-4*w^2", "x^2+y^2-2*x*w"),
        ("x^2+y^2-z^2", "x^2+4*y^2-4*w^2"),
    ] {
        let (a, b) = (parse_quadric(a).unwrap(), parse_quadric(b).unwrap());
        let s = sample(&parameterize(&a, &b).unwrap(), &SampleOptions::default()).unwrap();
        verify_turns(&s).unwrap();
        let mut gapped = s.clone();
        let piece = &mut gapped.pieces[0];
        let n = piece.points.len();
        // drop a run of points from the middle of the first branch: a step of well over 0.1 rad
        let (from, to) = (1, (n / 3).max(3).min(n - 1));
        piece.points.drain(from..to);
        for b in piece.breaks.iter_mut().chain(piece.infinity.iter_mut()) {
            if *b >= to {
                *b -= to - from;
            }
        }
        let err = verify_turns(&gapped).expect_err("a gap").to_string();
        assert!(
            err.contains("piece 0") && err.contains(&MAX_ANGLE.to_string()),
            "{err}"
        );
    }
}

/// Two random pairs whose Levin forms are over ℚ(√δ), where the float sign changes of `h`
/// once missed crossings of the plane at infinity: one piece (case 4) said bounded with two
/// of the curve's points at infinity on it, and a pair (case 1) with no point at infinity
/// where the curve has two. The points at infinity of `sample` are now the exact crossings,
/// the same count and boundedness as [`qsic::affine::affine_curve`] (an independent route).
#[test]
fn crossings_of_levin_forms_over_a_quadratic_field_are_exact() {
    let q = |m: [[i64; 4]; 4]| Quadric::from_integers(m).unwrap();
    let pairs = [
        (
            q([
                [-6, 0, -4, -1],
                [0, 5, 8, 0],
                [-4, 8, 1, -10],
                [-1, 0, -10, 7],
            ]),
            q([
                [-9, 9, -4, 3],
                [9, 3, -5, 8],
                [-4, -5, -8, -3],
                [3, 8, -3, 8],
            ]),
        ),
        (
            q([
                [8, -9, 8, 8],
                [-9, -10, -3, -1],
                [8, -3, -1, -9],
                [8, -1, -9, -2],
            ]),
            q([[6, 2, 0, 5], [2, 3, 8, 9], [0, 8, -2, -7], [5, 9, -7, 0]]),
        ),
    ];
    for (a, b) in &pairs {
        let curve = parameterize(a, b).unwrap();
        let view =
            qsic::affine::affine_curve(&curve, a, b, &qsic::affine::Chart::default()).unwrap();
        let s = sample(&curve, &SampleOptions::default()).unwrap();
        let marked: usize = s
            .pieces
            .iter()
            .map(|p| p.affine.points_at_infinity.len())
            .sum();
        assert_eq!(marked, view.points_at_infinity);
        assert!(view.points_at_infinity > 0);
        let unbounded = s.pieces.iter().filter(|p| !p.affine.bounded).count();
        assert_eq!(unbounded > 0, view.curves_unbounded > 0);
    }
}
