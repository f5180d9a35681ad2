//! Sampling at every scale: circles of radius 2⁻¹⁷ to 10⁵ come out as round as the unit
//! circle, and pairs under big integer disguises (20-digit maps `A ↦ PᵀAP`) give balanced
//! rational parameterizations and points on both quadrics, with no step larger than the
//! promised angle.

mod common;

use qsic::param::curve::ComponentParam;
use qsic::param::parameterize;
use qsic::param::sample::{sample, verify_on_quadrics, SampleOptions, MAX_ANGLE};
use qsic::Quadric;
use qsic_algebra::{IBig, RBig};
use serde_json::Value;

/// A sphere and a cylinder meeting in two circles of radius `r` at heights `±r`.
fn two_circles(r: &RBig) -> (Quadric, Quadric) {
    let r2 = r * r;
    let m = |diag: [RBig; 4]| {
        Quadric::from_matrix(std::array::from_fn(|i| {
            std::array::from_fn(|j| if i == j { diag[i].clone() } else { RBig::ZERO })
        }))
        .unwrap()
    };
    let (one, zero) = (RBig::ONE, RBig::ZERO);
    let sphere = m([one.clone(), one.clone(), one.clone(), -(&r2 + &r2)]);
    let cylinder = m([one.clone(), one, zero, -r2]);
    (sphere, cylinder)
}

/// The length and the largest turn (angle between consecutive chords) of a polyline.
fn length_and_turn(p: &[[f64; 3]]) -> (f64, f64) {
    let sub = |a: &[f64; 3], b: &[f64; 3]| [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let norm = |v: &[f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let chords: Vec<[f64; 3]> = p.windows(2).map(|w| sub(&w[0], &w[1])).collect();
    let length = chords.iter().map(norm).sum();
    let turn = chords
        .windows(2)
        .map(|w| {
            let c = (w[0][0] * w[1][0] + w[0][1] * w[1][1] + w[0][2] * w[1][2])
                / (norm(&w[0]) * norm(&w[1]));
            c.clamp(-1.0, 1.0).acos()
        })
        .fold(0.0, f64::max);
    (length, turn)
}

/// Circles of radius 2⁻¹⁷ (about 10⁻⁵), 1 and 10⁵ (their parameterizations unbalanced by
/// the radius before balancing): the default polyline of each is within 0.1 % of the
/// circumference and turns by at most 0.15 rad at a vertex (64 points, one turn each).
#[test]
fn circles_of_every_radius_are_sampled_alike() {
    let radii = [
        RBig::ONE / RBig::from(IBig::ONE << 17),
        RBig::ONE,
        RBig::from(100_000),
    ];
    for r in radii {
        let (a, b) = two_circles(&r);
        let curve = parameterize(&a, &b).unwrap();
        let s = sample(&curve, &SampleOptions::default()).unwrap();
        verify_on_quadrics(&s, &a, &b).unwrap();
        let exact = 2.0 * std::f64::consts::PI * r.to_f64().value();
        assert_eq!(s.pieces.len(), 2);
        for piece in &s.pieces {
            let [branch] = piece.affine.branches.as_slice() else {
                panic!("one closed branch per circle, radius {r}");
            };
            let (length, turn) = length_and_turn(branch);
            assert!(
                (length / exact - 1.0).abs() < 1e-3,
                "radius {r}: {length} of {exact}"
            );
            assert!(turn < 0.15, "radius {r}: a turn of {turn} rad");
        }
    }
}

/// `PᵀMP` for the rational matrix `m` and the integer matrix `p`.
fn disguised(m: &[[RBig; 4]; 4], p: &[[IBig; 4]; 4]) -> Quadric {
    let p: [[RBig; 4]; 4] = p.clone().map(|r| r.map(RBig::from));
    let mp: [[RBig; 4]; 4] = std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..4).fold(RBig::ZERO, |s, k| s + &m[i][k] * &p[k][j]))
    });
    Quadric::from_matrix(std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..4).fold(RBig::ZERO, |s, k| s + &p[k][i] * &mp[k][j]))
    }))
    .unwrap()
}

/// A fixed invertible integer matrix with entries of about 20 digits (an LCG; its
/// determinant is checked nonzero through the quadric's rank not dropping).
fn twenty_digit_map(seed: u64) -> [[IBig; 4]; 4] {
    let mut state = seed;
    let mut next = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        // 20 digits: a 64-bit value times 10⁰…10¹ and a sign
        let v = IBig::from(state >> 1) * IBig::from(1 + (state & 7));
        if state & 8 == 0 {
            v
        } else {
            -v
        }
    };
    std::array::from_fn(|_| std::array::from_fn(|_| next()))
}

/// `log₂|c|`: from the numerator and denominator of a rational (exact to a few bits at
/// any size), from the float of an element of a number field (these are small).
fn log2_abs(c: &qsic::param::curve::Number) -> Option<f64> {
    use dashu_int::ops::BitTest;
    if c.field().is_some() {
        let v = c.to_f64();
        assert!(v.is_finite());
        return (v != 0.0).then(|| v.abs().log2());
    }
    let n = c.numerator().first()?;
    if *n == IBig::ZERO {
        return None;
    }
    let d = c.denominator();
    let log = |bits: usize, f: f64| {
        if bits < 1000 {
            f.abs().log2()
        } else {
            bits as f64
        }
    };
    Some(log(n.bit_len(), n.to_f64().value()) - log(d.bit_len(), d.to_f64().value()))
}

/// `log₂` of the Euclidean norm of a vector, from the logarithms of its entries.
fn log2_norm(v: &[qsic::param::curve::Number]) -> Option<f64> {
    let logs: Vec<f64> = v.iter().filter_map(log2_abs).collect();
    let top = logs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    top.is_finite().then(|| {
        top + 0.5
            * logs
                .iter()
                .map(|l| 2f64.powf(2.0 * (l - top)))
                .sum::<f64>()
                .log2()
    })
}

/// Every case whose curve needs no conic point from factoring (the classes of lines, cubics,
/// nodal quartics and rational conics), under a 20-digit disguise: parameterized, each
/// rational component's lowest and highest coefficient vectors within 2²⁰ of each other in
/// norm, and sampled with every point on both quadrics and consecutive points within
/// [`MAX_ANGLE`] (up to sign) along every branch. Before balancing and the scaling of the
/// coefficients to about 1, cases 9, 10 and 12 did not converge (their floats overflowed
/// in `‖X‖²`) and their lines came out 2⁻¹³⁰ unbalanced.
#[test]
fn disguised_pairs_are_balanced_and_sampled() {
    let cases = [
        7, 9, 10, 12, 13, 14, 15, 16, 17, 18, 20, 22, 25, 28, 29, 30, 32, 33, 34, 35,
    ];
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/cases.jsonl"
    ))
    .unwrap();
    let mut seen = 0;
    for (n, line) in text.lines().enumerate() {
        let v: Value = serde_json::from_str(line).unwrap();
        let case = v["case"].as_u64().unwrap_or(0) as usize;
        let id = v["id"].as_str().unwrap_or("");
        if !cases.contains(&case) || !id.ends_with("-rep") {
            continue;
        }
        seen += 1;
        let p = twenty_digit_map(n as u64 + 1);
        let a = disguised(common::read_form(&v["A"]).matrix(), &p);
        let b = disguised(common::read_form(&v["B"]).matrix(), &p);
        let curve = parameterize(&a, &b).unwrap_or_else(|e| panic!("{id}: {e}"));
        for c in &curve.components {
            let Some(ComponentParam::Rational { x, degree }) = &c.param else {
                continue;
            };
            let vector = |i: usize| -> Vec<_> { x.iter().map(|p| p.coeff(i)).collect() };
            let (lo, hi) = (
                log2_norm(&vector(0)).unwrap(),
                log2_norm(&vector(*degree)).unwrap(),
            );
            assert!((lo - hi).abs() <= 20.0, "{id}: 2^{lo} against 2^{hi}");
        }
        let s = sample(&curve, &SampleOptions::default()).unwrap_or_else(|e| panic!("{id}: {e}"));
        verify_on_quadrics(&s, &a, &b).unwrap_or_else(|e| panic!("{id}: {e}"));
        for piece in &s.pieces {
            for branch in piece.branches() {
                for w in branch.windows(2) {
                    let d: f64 = (0..4).map(|i| w[0][i] * w[1][i]).sum();
                    assert!(
                        d.abs() >= (MAX_ANGLE * 1.01).cos(),
                        "{id}: a step of {} rad",
                        d.abs().acos()
                    );
                }
            }
        }
    }
    assert_eq!(seen, cases.len());
}

/// Steinmetz's cylinders `x² + y² = k²`, `(x − εk)² + z² = k²` with axes `εk` apart
/// (`ε = 10⁻⁵, 10⁻¹⁰, 10⁻²⁰`, `k = 1, 10⁵, 10⁻⁵`): a smooth quartic within `√ε` of the two ellipses
/// `z = ±y` it degenerates to, each of perimeter `4k·E(1/√2)·√2`. The near-nodes lie far below
/// the floats' resolution in `u`, so the walk goes on in a local parameter there; the
/// polyline is one closed branch, on both quadrics, every step within [`MAX_ANGLE`], and for
/// `k ≥ 1` its length within 1 % of the two ellipses' (computed here by Simpson's rule).
#[test]
fn near_nodes_far_below_the_floats_are_sampled() {
    use qsic::param::sample::verify_turns;
    // the perimeter of the ellipse with semi-axes 1 and √2: ∫₀^{2π} √(1 + cos²φ) dφ
    let n = 2000;
    let h = 2.0 * std::f64::consts::PI / n as f64;
    let f = |phi: f64| (1.0 + phi.cos() * phi.cos()).sqrt();
    let simpson: f64 = (0..=n)
        .map(|i| {
            let w = if i == 0 || i == n {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            w * f(i as f64 * h)
        })
        .sum::<f64>()
        * h
        / 3.0;
    for eps in ["1/100000", "1/10000000000", "1/100000000000000000000"] {
        for (k, size) in [("1", 1.0), ("100000", 1e5), ("1/100000", 1e-5)] {
            let a = qsic::io::parse_quadric(&format!("x^2+y^2-({k})^2")).unwrap();
            let b = qsic::io::parse_quadric(&format!("(x-{eps}*{k})^2+z^2-({k})^2")).unwrap();
            let curve = parameterize(&a, &b).unwrap();
            let s = sample(&curve, &SampleOptions::default())
                .unwrap_or_else(|e| panic!("ε = {eps}, k = {k}: {e}"));
            verify_on_quadrics(&s, &a, &b).unwrap();
            verify_turns(&s).unwrap();
            let [piece] = s.pieces.as_slice() else {
                panic!("one piece");
            };
            let [branch] = piece.affine.branches.as_slice() else {
                panic!("one closed branch");
            };
            let (length, _) = length_and_turn(branch);
            let want = 2.0 * simpson * size;
            // a piece 10⁻⁵ across is not yet walked at its own scale (the turn is measured
            // between unit vectors of ℝ⁴): its points are checked, not its length
            if size < 1.0 {
                continue;
            }
            assert!(
                (length / want - 1.0).abs() < 0.01,
                "ε = {eps}, k = {k}: {length} against {want}"
            );
        }
    }
}
