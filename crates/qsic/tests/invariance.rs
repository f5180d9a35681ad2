//! Known answers by construction: a projective map `X → PX`, a reparameterization of the
//! pencil `(A, B) → (aA + bB, cA + dB)`, scaling and swapping never change the class; the
//! fast path and the exact path agree.

#![allow(clippy::needless_range_loop)]

#[path = "../benches/inputs/mod.rs"]
mod inputs;

use dashu_ratio::RBig;
use inputs::representatives;
use proptest::prelude::*;
use qsic::test_support::classify_exact;
use qsic::{classify, Quadric};

type M = [[RBig; 4]; 4];

fn transform(m: &M, p: &[[i64; 4]; 4]) -> M {
    // Pᵀ M P
    let mut out: M = Default::default();
    for i in 0..4 {
        for j in 0..4 {
            let mut s = RBig::ZERO;
            for k in 0..4 {
                for l in 0..4 {
                    if p[k][i] != 0 && p[l][j] != 0 {
                        s += RBig::from(i128::from(p[k][i]) * i128::from(p[l][j])) * &m[k][l];
                    }
                }
            }
            out[i][j] = s;
        }
    }
    out
}

fn combine(x: &M, s: i64, y: &M, t: i64) -> M {
    let mut out: M = Default::default();
    for i in 0..4 {
        for j in 0..4 {
            out[i][j] = RBig::from(s) * &x[i][j] + RBig::from(t) * &y[i][j];
        }
    }
    out
}

fn det4(p: &[[i64; 4]; 4]) -> i128 {
    let m: Vec<Vec<i128>> = p
        .iter()
        .map(|r| r.iter().map(|&v| v as i128).collect())
        .collect();
    fn det(m: &[Vec<i128>]) -> i128 {
        if m.len() == 1 {
            return m[0][0];
        }
        (0..m.len())
            .map(|c| {
                let sub: Vec<Vec<i128>> = m[1..]
                    .iter()
                    .map(|r| {
                        r.iter()
                            .enumerate()
                            .filter(|&(j, _)| j != c)
                            .map(|(_, &v)| v)
                            .collect()
                    })
                    .collect();
                let s = if c % 2 == 0 { 1 } else { -1 };
                s * m[0][c] * det(&sub)
            })
            .sum()
    }
    det(&m)
}

/// The matrix (doubled) of the form with coefficients `c` of x², xy, xz, xw, y², yz, yw, z², zw, w².
fn from_polynomial_coefficients(c: &[i64; 10]) -> [[i64; 4]; 4] {
    let mut m = [[0i64; 4]; 4];
    let mut k = 0;
    for i in 0..4 {
        for j in i..4 {
            m[i][j] = if i == j { 2 * c[k] } else { c[k] };
            m[j][i] = m[i][j];
            k += 1;
        }
    }
    m
}

fn invertible_map() -> impl Strategy<Value = [[i64; 4]; 4]> {
    prop::array::uniform4(prop::array::uniform4(-3i64..=3))
        .prop_filter("invertible", |p| det4(p) != 0)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn disguises_keep_the_case(p in invertible_map(), r in prop::array::uniform4(-4i64..=4), swap: bool, k in 1i64..5) {
        prop_assume!(r[0] * r[3] - r[1] * r[2] != 0);
        let reps = representatives();
        prop_assert_eq!(reps.len(), 36);
        for (id, a, b, case) in reps {
            let (ta, tb) = (transform(a.matrix(), &p), transform(b.matrix(), &p));
            let na = combine(&ta, r[0] * k, &tb, r[1] * k);
            let nb = combine(&ta, r[2], &tb, r[3]);
            let (qa, qb) = (Quadric::from_matrix(na).expect("nonzero"), Quadric::from_matrix(nb).expect("nonzero"));
            let (qa, qb) = if swap { (qb, qa) } else { (qa, qb) };
            let c = classify(&qa, &qb);
            prop_assert_eq!(c.case, Some(case), "{} disguised by P={:?}, r={:?}", id, p, r);
            prop_assert_eq!(classify_exact(&qa, &qb), c);
        }
    }

    /// The fast path and the exact path agree on random pairs with coefficients in [−10, 10],
    /// and on pairs pushed towards tangency (a shared factor added to both).
    #[test]
    fn fast_and_exact_paths_agree(v in prop::array::uniform10(-10i64..=10), w in prop::array::uniform10(-10i64..=10), t in -3i64..=3) {
        let (ma, mut mb) = (from_polynomial_coefficients(&v), from_polynomial_coefficients(&w));
        // B − tA makes some pairs share more structure
        for i in 0..4 { for j in 0..4 { mb[i][j] -= t * ma[i][j]; } }
        if let (Ok(a), Ok(b)) = (Quadric::from_integers(ma), Quadric::from_integers(mb)) {
            prop_assert_eq!(classify(&a, &b), classify_exact(&a, &b));
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    /// Tiny entries make tangent and degenerate pencils common: every regular one must land in
    /// one of the 35 cases (Theorem 23), and single/singular ones must be reported as such.
    #[test]
    fn every_regular_pencil_gets_a_case(v in prop::array::uniform10(-2i64..=2), w in prop::array::uniform10(-2i64..=2)) {
        let (ma, mb) = (from_polynomial_coefficients(&v), from_polynomial_coefficients(&w));
        if let (Ok(a), Ok(b)) = (Quadric::from_integers(ma), Quadric::from_integers(mb)) {
            let c = classify(&a, &b);
            if c.pencil == qsic::classify::PencilKind::Regular {
                prop_assert!(c.case.is_some(), "no case for A={:?} B={:?}", a.matrix(), b.matrix());
            }
            prop_assert!(c.morphology.is_some() || c.pencil == qsic::classify::PencilKind::Singular);
        }
    }
}

/// Entries around 10²⁶ (13-digit maps): the exact path still finds every case.
#[test]
fn huge_disguises_keep_the_case() {
    let p: [[i64; 4]; 4] = [
        [3_141_592_653_589, -2_718_281_828_459, 1_414_213_562_373, 7],
        [-1_732_050_807_568, 2_236_067_977_499, 5, -2_645_751_311_064],
        [11, 3_316_624_790_355, -3_605_551_275_463, 1_000_000_000_039],
        [2_449_489_742_783, -13, 2_828_427_124_746, 3_162_277_660_168],
    ];
    for (id, a, b, case) in representatives() {
        let (ta, tb) = (transform(a.matrix(), &p), transform(b.matrix(), &p));
        let na = combine(&ta, 123_456_789, &tb, -987_654_321);
        let nb = combine(&ta, 314_159, &tb, 271_828);
        let qa = Quadric::from_matrix(na).expect("nonzero");
        let qb = Quadric::from_matrix(nb).expect("nonzero");
        assert_eq!(
            classify(&qa, &qb).case,
            Some(case),
            "{id} with huge entries"
        );
    }
}
