//! The natural-quadric route (module `qsic::natural`) against the general route, which is its
//! reference: on the CAD configurations of planes, spheres, circular cylinders and cones
//! (crossing, tangent, coaxial, offset, through an apex, near-degenerate at 10⁻⁹–10⁻¹² as
//! exact rationals), in their own position and under rigid motions with rational rotations
//! (Cayley, small and large parameters), in both orders, the classification and the curve in
//! ℝ³ are equal in full wherever the natural route answers — and it answers exactly on the
//! configurations marked for it, so a route that silently declines fails too. Every corpus
//! line gives the same classification through the dispatch as through the exact route.

// Index loops read as the matrix formulas they implement.
#![allow(clippy::needless_range_loop)]

mod common;

#[path = "common/geometry.rs"]
mod geometry;

use common::read_form;
use geometry::moved;
use qsic::affine::{affine_view, AffineCurve, Chart};
use qsic::io::parse_quadric;
use qsic::natural::recognize;
use qsic::param::Number;
use qsic::test_support::{
    classify_exact, general_affine_curve, natural_answer, natural_recognize_exact,
};
use qsic::{classify, Quadric};
use qsic_algebra::testing::SplitMix;
use qsic_algebra::RBig;
use serde_json::Value;

/// `(id, A, B, natural)`: `natural` marks the configurations the natural route answers.
const CONFIGURATIONS: &[(&str, &str, &str, bool)] = &[
    // plane and sphere
    ("plane-sphere-crossing", "z-1/2", "x^2+y^2+z^2-1", true),
    ("plane-sphere-through-centre", "z", "x^2+y^2+z^2-1", true),
    ("plane-sphere-tangent", "z-1", "x^2+y^2+z^2-1", true),
    (
        "plane-sphere-tangent-oblique",
        "3*x+4*y-5",
        "x^2+y^2+z^2-1",
        true,
    ),
    ("plane-sphere-apart", "z-2", "x^2+y^2+z^2-1", true),
    ("plane-sphere-oblique", "x+y+z-1", "(x-1)^2+y^2+z^2-4", true),
    (
        "plane-sphere-near-tangent-in",
        "z-(1-1/10^12)",
        "x^2+y^2+z^2-1",
        true,
    ),
    (
        "plane-sphere-near-tangent-out",
        "z-(1+1/10^9)",
        "x^2+y^2+z^2-1",
        true,
    ),
    // plane and cylinder
    ("plane-cylinder-perpendicular", "z", "x^2+y^2-1", true),
    ("plane-cylinder-oblique", "x+z", "x^2+y^2-1", true),
    ("plane-cylinder-parallel-cut", "x-1/2", "x^2+y^2-1", true),
    ("plane-cylinder-through-axis", "x", "x^2+y^2-1", true),
    ("plane-cylinder-tangent", "x-1", "x^2+y^2-1", true),
    (
        "plane-cylinder-tangent-oblique",
        "3*x+4*y-5",
        "x^2+y^2-1",
        true,
    ),
    ("plane-cylinder-apart", "x-2", "x^2+y^2-1", true),
    (
        "plane-cylinder-near-tangent",
        "x-(1-1/10^9)",
        "x^2+y^2-1",
        true,
    ),
    // plane and cone
    ("plane-cone-circle", "z-1", "x^2+y^2-z^2", true),
    ("plane-cone-ellipse", "x+2*z-1", "x^2+y^2-z^2", true),
    ("plane-cone-parabola", "x+z-1", "x^2+y^2-z^2", true),
    ("plane-cone-hyperbola", "x-1", "x^2+y^2-z^2", true),
    ("plane-cone-hyperbola-steep", "2*x+z-1", "x^2+y^2-z^2", true),
    ("plane-cone-apex-two-lines", "x", "x^2+y^2-z^2", true),
    (
        "plane-cone-apex-oblique-lines",
        "x+y+z",
        "x^2+y^2-z^2",
        true,
    ),
    ("plane-cone-apex-tangent", "x-z", "x^2+y^2-z^2", true),
    ("plane-cone-apex-point", "z", "x^2+y^2-z^2", true),
    (
        "plane-cone-near-parabola",
        "x+(1+1/10^12)*z-1",
        "x^2+y^2-z^2",
        true,
    ),
    (
        "plane-cone-narrow-apex",
        "x+3*z-2",
        "3*x^2+3*y^2-(z-2)^2",
        true,
    ),
    // two spheres
    (
        "sphere-sphere-crossing",
        "x^2+y^2+z^2-4",
        "(x-1)^2+y^2+z^2-4",
        true,
    ),
    (
        "sphere-sphere-tangent-outside",
        "x^2+y^2+z^2-4",
        "(x-4)^2+y^2+z^2-4",
        true,
    ),
    (
        "sphere-sphere-tangent-inside",
        "x^2+y^2+z^2-4",
        "(x-1)^2+y^2+z^2-1",
        true,
    ),
    (
        "sphere-sphere-tangent-irrational-radii",
        "x^2+y^2+z^2-2",
        "(x-3)^2+(y-3)^2+z^2-8",
        true,
    ),
    (
        "sphere-sphere-apart",
        "x^2+y^2+z^2-4",
        "(x-5)^2+y^2+z^2-4",
        true,
    ),
    (
        "sphere-sphere-nested",
        "x^2+y^2+z^2-4",
        "(x-1/2)^2+y^2+z^2-1",
        true,
    ),
    (
        "sphere-sphere-concentric",
        "x^2+y^2+z^2-4",
        "x^2+y^2+z^2-1",
        true,
    ),
    (
        "sphere-sphere-diagonal",
        "(x-1)^2+(y-1)^2+(z-1)^2-4",
        "x^2+y^2+z^2-3",
        true,
    ),
    (
        "sphere-sphere-near-tangent-outside",
        "x^2+y^2+z^2-4",
        "(x-(4+1/10^9))^2+y^2+z^2-4",
        true,
    ),
    (
        "sphere-sphere-near-tangent-inside",
        "x^2+y^2+z^2-4",
        "(x-(1-1/10^12))^2+y^2+z^2-1",
        true,
    ),
    // sphere and cylinder
    (
        "sphere-cylinder-coaxial-two-circles",
        "x^2+y^2+z^2-1",
        "x^2+y^2-1/4",
        true,
    ),
    (
        "sphere-cylinder-coaxial-tangent",
        "x^2+y^2+z^2-1",
        "x^2+y^2-1",
        true,
    ),
    (
        "sphere-cylinder-coaxial-apart",
        "x^2+y^2+z^2-1",
        "x^2+y^2-4",
        true,
    ),
    (
        "sphere-cylinder-coaxial-offset",
        "x^2+y^2+(z-3)^2-1",
        "x^2+y^2-1/4",
        true,
    ),
    (
        "sphere-cylinder-near-tangent",
        "x^2+y^2+z^2-1",
        "x^2+y^2-(1-1/10^12)",
        true,
    ),
    (
        "sphere-cylinder-viviani",
        "x^2+y^2+z^2-4",
        "(x-1)^2+y^2-1",
        false,
    ),
    (
        "sphere-cylinder-tangent-outside",
        "x^2+y^2+z^2-1",
        "(x-2)^2+y^2-1",
        false,
    ),
    (
        "sphere-cylinder-off-axis",
        "x^2+y^2+z^2-4",
        "(x-1/2)^2+y^2-1",
        false,
    ),
    // two cylinders
    (
        "cylinder-cylinder-parallel-crossing",
        "x^2+y^2-1",
        "(x-1)^2+y^2-1",
        true,
    ),
    (
        "cylinder-cylinder-parallel-unequal",
        "x^2+y^2-1",
        "(x-2)^2+y^2-4",
        true,
    ),
    (
        "cylinder-cylinder-parallel-apart",
        "x^2+y^2-1",
        "(x-3)^2+y^2-1",
        true,
    ),
    (
        "cylinder-cylinder-parallel-nested",
        "x^2+y^2-9",
        "(x-1)^2+y^2-1",
        true,
    ),
    (
        "cylinder-cylinder-coaxial",
        "x^2+y^2-1",
        "x^2+y^2-1/4",
        true,
    ),
    (
        "cylinder-cylinder-near-tangent",
        "x^2+y^2-1",
        "(x-(2+1/10^9))^2+y^2-1",
        true,
    ),
    (
        "cylinder-cylinder-tangent-outside",
        "x^2+y^2-1",
        "(x-2)^2+y^2-1",
        true,
    ),
    (
        "cylinder-cylinder-tangent-inside",
        "x^2+y^2-4",
        "(x-1)^2+y^2-1",
        true,
    ),
    (
        "cylinder-cylinder-steinmetz",
        "x^2+y^2-1",
        "x^2+z^2-1",
        false,
    ),
    (
        "cylinder-cylinder-crossing-unequal",
        "x^2+y^2-1",
        "x^2+z^2-4",
        false,
    ),
    (
        "cylinder-cylinder-skew",
        "x^2+y^2-1",
        "x^2+(z-3/2)^2-1",
        false,
    ),
    // a cone and a sphere, cylinder or cone
    (
        "cone-sphere-coaxial",
        "x^2+y^2-z^2",
        "x^2+y^2+(z-2)^2-1",
        false,
    ),
    ("cone-cylinder-coaxial", "x^2+y^2-z^2", "x^2+y^2-1", false),
    ("cone-cone-shared-apex", "x^2+y^2-z^2", "x^2+z^2-y^2", false),
];

/// The Cayley rotation of `s`: `((1 − |s|²)I + 2ssᵀ + 2[s]×)/(1 + |s|²)`, rational, with the
/// translation `t`: the rigid map `X ↦ [[R, t], [0, 1]]X`.
fn rigid(s: [RBig; 3], t: [RBig; 3]) -> [[RBig; 4]; 4] {
    let n = &s[0] * &s[0] + &s[1] * &s[1] + &s[2] * &s[2];
    let den = RBig::ONE + &n;
    let skew = [
        [RBig::ZERO, -s[2].clone(), s[1].clone()],
        [s[2].clone(), RBig::ZERO, -s[0].clone()],
        [-s[1].clone(), s[0].clone(), RBig::ZERO],
    ];
    std::array::from_fn(|i| {
        std::array::from_fn(|j| match (i, j) {
            (3, 3) => RBig::ONE,
            (3, _) => RBig::ZERO,
            (_, 3) => t[i].clone(),
            _ => {
                let diagonal = if i == j { RBig::ONE - &n } else { RBig::ZERO };
                (diagonal + RBig::from(2) * &s[i] * &s[j] + RBig::from(2) * &skew[i][j]) / &den
            }
        })
    })
}

fn ratio(n: i64, d: i64) -> RBig {
    RBig::from(n) / RBig::from(d)
}

/// The placements of each configuration: the identity, three small rational rigid motions
/// and one with 10-digit parameters (big coefficients).
fn placements(rng: &mut SplitMix) -> Vec<[[RBig; 4]; 4]> {
    let mut out = vec![rigid([0, 0, 0].map(RBig::from), [0, 0, 0].map(RBig::from))];
    for _ in 0..3 {
        let s = std::array::from_fn(|_| ratio(rng.int(-5, 5), rng.int(1, 4)));
        let t = std::array::from_fn(|_| ratio(rng.int(-9, 9), rng.int(1, 3)));
        out.push(rigid(s, t));
    }
    let big = |rng: &mut SplitMix| {
        ratio(
            rng.int(-9_999_999_999, 9_999_999_999),
            rng.int(1, 999_999_937),
        )
    };
    let s = std::array::from_fn(|_| big(rng));
    let t = std::array::from_fn(|_| big(rng));
    out.push(rigid(s, t));
    out
}

const IDENTITY: [[RBig; 4]; 4] = {
    const O: RBig = RBig::ZERO;
    const I: RBig = RBig::ONE;
    [[I, O, O, O], [O, I, O, O], [O, O, I, O], [O, O, O, I]]
};

/// The affine image `T·p` of a point given in the moved coordinates (`X_old = T·X_new`).
fn to_original(t: &[[RBig; 4]; 4], p: &[Number; 3]) -> [Number; 3] {
    std::array::from_fn(|i| {
        let mut acc = Number::rational(t[i][3].clone());
        for j in 0..3 {
            acc = &acc + &(&p[j] * &Number::rational(t[i][j].clone()));
        }
        acc
    })
}

/// The curve with its finite singular points carried back to the original coordinates, and
/// its components in a fixed order (the general route's order depends on the position).
fn in_original(curve: &AffineCurve, t: &[[RBig; 4]; 4]) -> AffineCurve {
    let mut out = curve.clone();
    for p in &mut out.singular_points {
        p.point = p.point.as_ref().map(|x| to_original(t, x));
    }
    out.components.sort_by_key(|c| format!("{c:?}"));
    out
}

/// The natural route against the general route on one pair moved by `t`: equal in full
/// where it answers; the dispatch (`classify`, `affine_view`) equal to the general route.
/// Where the general route fails on the moved pair (its conics' coefficients too large to
/// factor), the natural curve carried back by `t` must be `original`, the general route's
/// curve of the pair in its own position. Returns whether the natural route answered.
fn compare(id: &str, a: &Quadric, b: &Quadric, t: &[[RBig; 4]; 4], original: &AffineCurve) -> bool {
    let chart = Chart::default();
    let exact = classify_exact(a, b);
    let general = general_affine_curve(a, b, &chart);
    assert_eq!(classify(a, b), exact, "{id}: dispatch classification");
    let view = affine_view(Some(a), Some(b), &chart, [false; 2]);
    let natural = natural_answer(a, b);
    match (&general, &natural) {
        (Ok(g), _) => assert_eq!(view.curve.as_ref().ok(), Some(g), "{id}: dispatch curve"),
        (Err(_), Some((_, curve))) => {
            assert_eq!(
                view.curve.as_ref().ok(),
                Some(curve),
                "{id}: dispatch curve"
            )
        }
        // the dispatch is the general route: the same failure
        (Err(_), None) => assert!(view.curve.is_err(), "{id}: dispatch curve"),
    }
    match natural {
        Some((c, curve)) => {
            assert_eq!(c, exact, "{id}: natural classification");
            match &general {
                Ok(g) => assert_eq!(&curve, g, "{id}: natural curve"),
                Err(_) => assert_eq!(
                    in_original(&curve, t),
                    in_original(original, &IDENTITY),
                    "{id}: natural curve"
                ),
            }
            true
        }
        None => false,
    }
}

#[test]
fn natural_route_equals_the_general_route_on_cad_configurations() {
    let mut rng = SplitMix(0x006e_6174_7572_616c);
    let (mut answered, mut general_failed) = (0, 0);
    for &(id, a, b, natural) in CONFIGURATIONS {
        let (a, b) = (parse_quadric(a).unwrap(), parse_quadric(b).unwrap());
        let chart = Chart::default();
        let original = [
            general_affine_curve(&a, &b, &chart).unwrap(),
            general_affine_curve(&b, &a, &chart).unwrap(),
        ];
        for (k, t) in placements(&mut rng).iter().enumerate() {
            let (ma, mb) = (moved(&a, t), moved(&b, t));
            for q in [&ma, &mb] {
                assert_eq!(recognize(q), natural_recognize_exact(q), "{id}: the filter");
            }
            for (x, y, order, o) in [
                (&ma, &mb, "AB", &original[0]),
                (&mb, &ma, "BA", &original[1]),
            ] {
                let label = format!("{id} placement {k} {order}");
                let got = compare(&label, x, y, t, o);
                assert_eq!(got, natural, "{label}: the natural route answers");
                answered += usize::from(got);
                if got && general_affine_curve(x, y, &chart).is_err() {
                    general_failed += 1;
                }
            }
        }
    }
    let expected = CONFIGURATIONS.iter().filter(|c| c.3).count() * 5 * 2;
    assert_eq!(answered, expected);
    eprintln!("the general route failed on {general_failed} moved pairs the natural route answers");
}

/// Every labelled corpus line: the dispatch's classification is the exact route's, and
/// where the natural route answers, its curve is the general route's.
#[test]
fn corpus_lines_answer_the_same_through_the_dispatch() {
    let root = env!("CARGO_MANIFEST_DIR");
    let mut lines = 0;
    for file in [
        format!("{root}/tests/data/cases.jsonl"),
        format!("{root}/tests/data/seed_examples.jsonl"),
        format!("{root}/tests/data/qi-quadrics.jsonl"),
        format!("{root}/../qsic-cli/tests/data/affine.jsonl"),
    ] {
        let text = std::fs::read_to_string(&file).unwrap();
        for line in text.lines().filter(|l| !l.trim().is_empty()) {
            let v: Value = serde_json::from_str(line).unwrap();
            let id = format!("{file}: {}", v["id"]);
            // moving quadrics (strings in t, matrices of them) and planes are not pairs of
            // quadrics: they do not parse
            let read = |v: &Value| match v {
                Value::String(s) => parse_quadric(s).ok(),
                Value::Array(_) if !v.to_string().contains('t') => Some(read_form(v)),
                _ => None,
            };
            let (Some(a), Some(b)) = (read(&v["A"]), read(&v["B"])) else {
                continue;
            };
            assert_eq!(classify(&a, &b), classify_exact(&a, &b), "{id}");
            for q in [&a, &b] {
                assert_eq!(recognize(q), natural_recognize_exact(q), "{id}: the filter");
            }
            if let Some((c, curve)) = natural_answer(&a, &b) {
                assert_eq!(c, classify_exact(&a, &b), "{id}");
                let general = general_affine_curve(&a, &b, &Chart::default());
                assert_eq!(Ok(&curve), general.as_ref(), "{id}");
            }
            lines += 1;
        }
    }
    assert!(lines > 300, "{lines} corpus lines");
}
