//! Pencils whose roots are clustered, tiny or huge: known answers by construction.
//!
//! Reparameterizing the pencil (`(A, B) → (aA + bB, cA + dB)`) or congruence never changes
//! the class, but it moves the roots of `det(λA − B)` anywhere:
//! - `(A + K·B, B)` maps a root `r` to `r/(1 + K·r)`: every root within about `1/K²` of
//!   the others near `1/K` (for `K = 10³⁰⁰⁰`, roots `10⁻⁶⁰⁰⁰` apart);
//! - `(K·A, B)` divides the roots by `K`, `(A, B + K·A)` adds `K` to them.
//!
//! For diagonal pencils a monotone change of the roots keeps the signature sequence, so two
//! roots can be pushed `δ` apart, and a 2×2 block `λσI − σM` (congruent to a diagonal pair
//! with the eigenvalues of `M`) gives two irrational roots `δ√5` apart.

#[path = "../benches/inputs/mod.rs"]
mod inputs;

use dashu_int::IBig;
use dashu_ratio::RBig;
use inputs::representatives;
use qsic::{classify, Quadric};

type M = [[RBig; 4]; 4];
/// A labelled representative: id, A, B, case.
type Rep = (String, Quadric, Quadric, u8);
/// `(sign aᵢ, rᵢ)` of a diagonal pencil.
type Diagonal = [(RBig, RBig); 4];

fn ten_pow(k: usize) -> RBig {
    RBig::from(IBig::from(10).pow(k))
}

/// `s·x + t·y`.
fn combine(x: &M, s: &RBig, y: &M, t: &RBig) -> M {
    std::array::from_fn(|i| std::array::from_fn(|j| s * &x[i][j] + t * &y[i][j]))
}

fn quadric(m: M) -> Quadric {
    Quadric::from_matrix(m).expect("nonzero")
}

/// Checks that the pair gets the representative's case and real type.
fn assert_same_class(what: &str, a: M, b: M, rep: &Rep) {
    let (id, ra, rb, case) = rep;
    let expected = classify(ra, rb);
    assert_eq!(expected.case, Some(*case), "{id}");
    let got = classify(&quadric(a), &quadric(b));
    assert_eq!(got.case, Some(*case), "{id} {what}");
    assert_eq!(got.real_type(), expected.real_type(), "{id} {what}");
}

#[test]
fn roots_squeezed_together_keep_the_class() {
    let (one, zero) = (RBig::ONE, RBig::ZERO);
    for k in [3, 40, 400, 3000] {
        let big = ten_pow(k);
        for rep in &representatives() {
            let (a, b) = (rep.1.matrix(), rep.2.matrix());
            let what = format!("with (A + 10^{k} B, B)");
            assert_same_class(&what, combine(a, &one, b, &big), b.clone(), rep);
            if k <= 400 {
                let what = format!("with (10^{k} A, B)");
                assert_same_class(&what, combine(a, &big, b, &zero), b.clone(), rep);
                let what = format!("with (A, B + 10^{k} A)");
                assert_same_class(&what, a.clone(), combine(a, &big, b, &one), rep);
            }
        }
    }
}

/// A diagonal pencil given by `(aᵢ, rᵢ)`: entries `aᵢ` of A and `aᵢ·rᵢ` of B (`rᵢ` = root).
fn diagonal(entries: &Diagonal) -> (M, M) {
    let mut a: M = Default::default();
    let mut b: M = Default::default();
    for (i, (ai, ri)) in entries.iter().enumerate() {
        a[i][i] = ai.clone();
        b[i][i] = ai * ri;
    }
    (a, b)
}

/// Representatives that are diagonal with four finite roots, as `(sign aᵢ, rᵢ)` after the
/// real rescaling `xᵢ → xᵢ/√|aᵢ|`.
fn diagonal_representatives() -> Vec<(Rep, Diagonal)> {
    representatives()
        .into_iter()
        .filter_map(|rep| {
            let (a, b) = (rep.1.matrix(), rep.2.matrix());
            let off_diagonal_zero =
                (0..4).all(|i| (0..4).all(|j| i == j || (a[i][j].is_zero() && b[i][j].is_zero())));
            let finite = (0..4).all(|i| !a[i][i].is_zero());
            let e: [(RBig, RBig); 4] = std::array::from_fn(|i| {
                let ai = &a[i][i];
                let sign = if ai > &RBig::ZERO {
                    RBig::ONE
                } else {
                    -RBig::ONE
                };
                let root = if ai.is_zero() {
                    RBig::ZERO
                } else {
                    &b[i][i] / ai
                };
                (sign, root)
            });
            (off_diagonal_zero && finite).then_some((rep, e))
        })
        .collect()
}

/// Two consecutive distinct simple roots moved `δ = 10^−k` apart (rationally), and turned
/// into a pair of irrational roots `δ√5` apart when their signs agree.
#[test]
fn two_roots_pushed_together_keep_the_class() {
    let reps = diagonal_representatives();
    assert!(reps.len() >= 7, "{} diagonal representatives", reps.len());
    let mut irrational = 0;
    for k in [8, 300, 1600, 6000] {
        let delta = RBig::ONE / ten_pow(k);
        for (rep, e) in &reps {
            let mut roots: Vec<RBig> = e.iter().map(|(_, r)| r.clone()).collect();
            roots.sort();
            roots.dedup();
            let simple = |r: &RBig| e.iter().filter(|(_, x)| x == r).count() == 1;
            for w in roots.windows(2) {
                let (u, v) = (&w[0], &w[1]);
                if !simple(u) || !simple(v) {
                    continue;
                }
                // x ↦ x for x ≤ u, x − (v − u − δ) for x ≥ v: monotone, v lands on u + δ
                let gap = v - u - &delta;
                let moved: [(RBig, RBig); 4] = std::array::from_fn(|i| {
                    let (s, r) = &e[i];
                    (s.clone(), if r >= v { r - &gap } else { r.clone() })
                });
                let (a, b) = diagonal(&moved);
                assert_same_class(&format!("roots {u}, {v} 10^-{k} apart"), a, b, rep);
                let i = e.iter().position(|(_, r)| r == u).expect("u is a root");
                let j = e.iter().position(|(_, r)| r == v).expect("v is a root");
                if e[i].0 != e[j].0 {
                    continue;
                }
                // block σ·[[c, δ], [δ, c + δ]] on coordinates i, j: eigenvalues
                // c + δ/2 ± δ√5/2, both between the neighbours of u and v
                let (a, mut b) = diagonal(&moved);
                let sigma = e[i].0.clone();
                let c = u.clone();
                b[i][i] = &sigma * &c;
                b[j][j] = &sigma * (&c + &delta);
                b[i][j] = &sigma * &delta;
                b[j][i] = b[i][j].clone();
                let what = format!("irrational roots near {u}, δ√5 = √5·10^-{k} apart");
                assert_same_class(&what, a, b, rep);
                irrational += 1;
            }
        }
    }
    assert!(irrational >= 8, "{irrational} irrational clusters");
}
