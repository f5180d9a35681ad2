//! Levin's parameterization of nonsingular quartics (cases 1–4) on every labelled corpus line:
//! exact identities as polynomials in `u`, and Theorem 12's component count against the
//! classifier (a second, independent route) and the labels.

// Index loops read as the matrix formulas they implement.
#![allow(clippy::needless_range_loop)]

mod common;

use common::read_form;
use qsic::io::parse_quadric;
use qsic::param::{parameterize_smooth_quartic, LevinParameterization, PolyVector};
use qsic::{classify, Quadric};
use qsic_algebra::field::Quadratic;
use qsic_algebra::{Poly, RBig, Sign};
use serde_json::Value;

/// `(id, A, B, real_type)` of every case 1–4 line of the corpora.
fn smooth_quartic_lines() -> Vec<(String, Quadric, Quadric, String)> {
    let mut out = Vec::new();
    for name in ["cases.jsonl", "seed_examples.jsonl", "qi-quadrics.jsonl"] {
        let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
        for (i, raw) in text.lines().enumerate() {
            let line: Value = serde_json::from_str(raw).unwrap();
            if !matches!(line["case"].as_u64(), Some(1..=4)) {
                continue;
            }
            let id = format!("{name}:{} {}", i + 1, line["id"].as_str().unwrap_or("?"));
            let real_type = line["real_type"].as_str().unwrap().to_owned();
            out.push((id, read_form(&line["A"]), read_form(&line["B"]), real_type));
        }
    }
    out
}

fn matrix(q: &Quadric) -> [[Quadratic; 4]; 4] {
    let m = q.matrix();
    std::array::from_fn(|i| std::array::from_fn(|j| Quadratic::rational(m[i][j].clone())))
}

fn form(m: &[[Quadratic; 4]; 4], x: &PolyVector, y: &PolyVector) -> Poly<Quadratic> {
    let mut acc = Poly::zero();
    for i in 0..4 {
        for j in 0..4 {
            acc = &acc + &(&x[i] * &y[j]).scale(&m[i][j]);
        }
    }
    acc
}

/// The identities of `p = a ± d√s` on `Q` and of the ruling on `S`; panics naming `id`.
fn check_identities(id: &str, p: &LevinParameterization, a: &Quadric, b: &Quadric) {
    for (name, q) in [("A", a), ("B", b)] {
        let m = matrix(q);
        let lhs = &form(&m, &p.a, &p.a) + &(&p.s * &form(&m, &p.d, &p.d));
        assert!(lhs.is_zero(), "{id}: aᵀ{name}a + s·dᵀ{name}d = {lhs}");
        assert!(form(&m, &p.a, &p.d).is_zero(), "{id}: aᵀ{name}d ≠ 0");
    }
    let s: [[Quadratic; 4]; 4] = std::array::from_fn(|i| {
        std::array::from_fn(|j| Quadratic::rational(p.surface.matrix[i][j].clone()))
    });
    let r = &p.surface.ruling;
    for (x, y) in [(&r.b, &r.b), (&r.b, &r.d), (&r.d, &r.d)] {
        assert!(form(&s, x, y).is_zero(), "{id}: q(u, v) is not on S");
    }
    assert!(
        !p.s.is_zero() && p.s.degree().unwrap() <= 4,
        "{id}: s = {}",
        p.s
    );
    assert!(
        p.a.iter().chain(&p.d).any(|x| !x.is_zero()),
        "{id}: a, d zero"
    );
}

/// Real components of a nonsingular quartic from its `real_type` label.
fn components_of_label(real_type: &str) -> u8 {
    match real_type {
        "two_finite_components" | "two_infinite_components" => 2,
        "one_finite_component" | "one_infinite_component" => 1,
        "empty" => 0,
        other => panic!("not a nonsingular quartic type: {other}"),
    }
}

#[test]
fn every_smooth_quartic_of_the_corpora_is_parameterized_exactly() {
    let lines = smooth_quartic_lines();
    assert!(lines.len() >= 30, "{} lines", lines.len());
    let mut failures = Vec::new();
    let mut over_q = 0;
    for (id, a, b, real_type) in &lines {
        let p = match parameterize_smooth_quartic(a, b) {
            Ok(p) => p,
            Err(e) => {
                failures.push(format!("{id}: {e}"));
                continue;
            }
        };
        check_identities(id, &p, a, b);
        over_q += usize::from(p.delta.is_none());
        let by_s = p.real_components().unwrap_or_else(|e| panic!("{id}: {e}"));
        let by_signature = components_of_label(classify(a, b).real_type().unwrap());
        let by_label = components_of_label(real_type);
        if by_s != by_signature || by_s != by_label {
            failures.push(format!(
                "{id}: Theorem 12 {by_s}, classifier {by_signature}, label {by_label}"
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(over_q > 0, "no parameterization over ℚ at all");
}

/// A small deterministic generator (xorshift), so that failures reproduce.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn small(&mut self) -> i64 {
        (self.next() % 5) as i64 - 2
    }
}

fn det(m: &[[RBig; 4]; 4]) -> RBig {
    // Gaussian elimination over ℚ
    let mut m = m.clone();
    let mut d = RBig::ONE;
    for c in 0..4 {
        let Some(p) = (c..4).find(|&r| !m[r][c].is_zero()) else {
            return RBig::ZERO;
        };
        if p != c {
            m.swap(p, c);
            d = -d;
        }
        d *= &m[c][c];
        for r in c + 1..4 {
            let f = &m[r][c] / &m[c][c];
            for k in c..4 {
                let v = &f * &m[c][k];
                m[r][k] -= v;
            }
        }
    }
    d
}

/// `Mᵀ(αA + βB)M` and `Mᵀ(γA + δB)M` for random small invertible `M` and `(α β; γ δ)`.
fn disguise(a: &Quadric, b: &Quadric, rng: &mut Rng) -> (Quadric, Quadric) {
    let m = loop {
        let m: [[RBig; 4]; 4] =
            std::array::from_fn(|_| std::array::from_fn(|_| RBig::from(rng.small())));
        if !det(&m).is_zero() {
            break m;
        }
    };
    let [al, be, ga, de] = loop {
        let c = [rng.small(), rng.small(), rng.small(), rng.small()];
        if c[0] * c[3] != c[1] * c[2] {
            break c.map(RBig::from);
        }
    };
    let (ma, mb) = (a.matrix(), b.matrix());
    let congruent = |x: &RBig, y: &RBig| {
        let n: [[RBig; 4]; 4] =
            std::array::from_fn(|i| std::array::from_fn(|j| x * &ma[i][j] + y * &mb[i][j]));
        let out: [[RBig; 4]; 4] = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let mut acc = RBig::ZERO;
                for k in 0..4 {
                    for l in 0..4 {
                        acc += &m[k][i] * &n[k][l] * &m[l][j];
                    }
                }
                acc
            })
        });
        Quadric::from_matrix(out).unwrap()
    };
    (congruent(&al, &be), congruent(&ga, &de))
}

#[test]
fn disguised_pencils_keep_their_component_count() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let mut failures = Vec::new();
    for (id, a, b, real_type) in smooth_quartic_lines() {
        let want = components_of_label(&real_type);
        for k in 0..2 {
            let (da, db) = disguise(&a, &b, &mut rng);
            let tag = format!("{id} disguise {k}");
            match parameterize_smooth_quartic(&da, &db) {
                Ok(p) => {
                    check_identities(&tag, &p, &da, &db);
                    let got = p.real_components().unwrap_or_else(|e| panic!("{tag}: {e}"));
                    if got != want {
                        failures.push(format!("{tag}: {got} components, want {want}"));
                    }
                }
                Err(e) => failures.push(format!("{tag}: {e}")),
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn sphere_and_ellipsoidal_cylinder_give_two_components() {
    let a = parse_quadric("x^2+y^2+z^2-w^2").unwrap();
    let b = parse_quadric("2*x^2+4*y^2-w^2").unwrap();
    let p = parameterize_smooth_quartic(&a, &b).unwrap();
    check_identities("sphere-cylinder", &p, &a, &b);
    assert_eq!(p.real_components().unwrap(), 2);
    // two components: either four real roots of s (two positive arcs) or s > 0 throughout
    let positive = p
        .discriminant
        .arcs
        .iter()
        .filter(|(_, s)| *s == Sign::Positive)
        .count();
    assert!(positive >= 1);
}

#[test]
fn other_classes_are_refused_with_a_reason() {
    // two spheres meeting in a circle (case 17), a tangent pair, a singular pencil
    for (a, b) in [
        ("x^2+y^2+z^2-4", "(x-1)^2+y^2+z^2-4"),
        ("x^2+y^2+z^2-1", "x^2+y^2+z^2-2*z"),
        ("2*x*y+w^2", "2*y*z+w^2"),
    ] {
        let (a, b) = (parse_quadric(a).unwrap(), parse_quadric(b).unwrap());
        let e = parameterize_smooth_quartic(&a, &b).unwrap_err();
        assert!(matches!(e, qsic::Error::Unsupported(_)), "{e}");
    }
}
