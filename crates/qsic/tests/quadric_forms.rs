//! Exact linear algebra on every quadric of the corpora (tests/data, with provenance in each
//! line's `source`): congruence diagonalization, kernels, real points, plane pairs.

use qsic::io::{parse_quadric, quadric_from_rows};
use qsic::{Error, Quadric};
use qsic_algebra::field::Quadratic;
use qsic_algebra::linalg::forms::{plane_pair, real_point, PlanePairKind};
use qsic_algebra::linalg::Matrix;
use qsic_algebra::{RBig, Ring};
use serde_json::Value;

fn read_form(v: &Value) -> Result<Quadric, Error> {
    match v {
        Value::String(s) => parse_quadric(s),
        Value::Array(rows) => {
            let rows: Vec<Vec<String>> = rows
                .iter()
                .map(|r| {
                    r.as_array()
                        .expect("a row")
                        .iter()
                        .map(|x| x.as_str().map_or_else(|| x.to_string(), str::to_owned))
                        .collect()
                })
                .collect();
            quadric_from_rows(&rows)
        }
        _ => panic!("unexpected quadric value {v}"),
    }
}

/// Every valid quadric `A` and `B` of a corpus file, named `file:line id A|B`.
fn quadrics(name: &str) -> Vec<(String, Quadric)> {
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut out = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line: Value =
            serde_json::from_str(raw).unwrap_or_else(|e| panic!("{name}:{}: {e}", i + 1));
        let id = line["id"].as_str().unwrap_or("?");
        for key in ["A", "B"] {
            if let Ok(q) = read_form(&line[key]) {
                out.push((format!("{name}:{} {id} {key}", i + 1), q));
            }
        }
    }
    out
}

fn rational(q: &Quadric) -> Matrix<RBig> {
    q.integer_matrix()
        .to_matrix()
        .map(|v| RBig::from(v.clone()))
}

fn lift(s: &Matrix<RBig>) -> Matrix<Quadratic> {
    s.map(|v| Quadratic::rational(v.clone()))
}

/// Counts of what was checked, so that the test cannot pass on an empty corpus.
#[derive(Default, Debug)]
struct Seen {
    quadrics: usize,
    mixed: usize,
    irrational_points: usize,
    singular: usize,
    plane_pairs: usize,
}

fn check(name: &str, q: &Quadric, seen: &mut Seen) {
    let s = rational(q);
    let dg = s
        .diagonalize_congruent()
        .expect("a quadric matrix is symmetric");
    seen.quadrics += 1;
    // PᵀSP = D exactly, P invertible
    let d = &(&dg.p.transpose() * &s) * &dg.p;
    let diagonal = Matrix::from_fn(
        4,
        4,
        |i, j| if i == j { dg.d[i].clone() } else { RBig::ZERO },
    );
    assert_eq!(d, diagonal, "{name}");
    assert!(!dg.p.det().is_zero(), "{name}");
    // the inertia by Sylvester equals the one by Descartes on the principal minors
    let inertia = dg.inertia();
    assert_eq!(inertia, q.integer_matrix().inertia(), "{name}");
    // the singular points: S·k = 0, dimension 4 − rank
    let kernel = dg.kernel();
    assert_eq!(kernel.len(), 4 - usize::from(inertia.rank()), "{name}");
    for k in &kernel {
        assert!(s.mul_vec(k).iter().all(Ring::is_zero), "{name}: {k:?}");
    }
    seen.singular += usize::from(!kernel.is_empty());
    // a real point exactly on every quadric with one, none on a definite one
    let point = real_point(&s);
    let definite = inertia.zero == 0 && !inertia.is_indefinite();
    assert_eq!(point.is_none(), definite, "{name}: {inertia:?}");
    if let Some(x) = point {
        assert!(
            x.iter().any(|v| !v.is_zero()) && x.iter().all(Quadratic::is_real),
            "{name}"
        );
        assert!(lift(&s).quadratic_form(&x).is_zero(), "{name}: {x:?}");
        seen.mixed += usize::from(inertia.is_indefinite());
        seen.irrational_points += usize::from(x.iter().any(|v| v.as_rational().is_none()));
    }
    // plane pairs multiply back: c·(l₁l₂ᵀ + l₂l₁ᵀ)/2 = S
    if inertia.rank() <= 2 {
        let pair = plane_pair(&s).unwrap_or_else(|| panic!("{name}: rank {}", inertia.rank()));
        let [l1, l2] = &pair.planes;
        let half = Quadratic::rational(&pair.factor / RBig::from(2));
        let product = Matrix::from_fn(4, 4, |i, j| {
            l1[i].mul(&l2[j]).add(&l1[j].mul(&l2[i])).mul(&half)
        });
        assert_eq!(product, lift(&s), "{name}: {pair:?}");
        let expect = match (inertia.positive, inertia.negative) {
            (1, 1) => [PlanePairKind::Rational, PlanePairKind::RealConjugate].contains(&pair.kind),
            (2, 0) | (0, 2) => pair.kind == PlanePairKind::ComplexConjugate,
            _ => pair.kind == PlanePairKind::Double,
        };
        assert!(expect, "{name}: {inertia:?} {:?}", pair.kind);
        seen.plane_pairs += 1;
    }
}

#[test]
fn every_corpus_quadric_diagonalizes_and_has_its_real_point() {
    let mut seen = Seen::default();
    for file in ["cases.jsonl", "qi-quadrics.jsonl", "seed_examples.jsonl"] {
        for (name, q) in quadrics(file) {
            check(&name, &q, &mut seen);
        }
    }
    // the corpora hold many of each kind (at the time of writing: 707 quadrics, 621 of mixed
    // inertia, 118 points needing a square root, 287 singular, 141 of rank ≤ 2)
    assert!(seen.quadrics > 650 && seen.mixed > 500, "{seen:?}");
    assert!(
        seen.irrational_points > 80 && seen.singular > 200 && seen.plane_pairs > 100,
        "{seen:?}"
    );
}
