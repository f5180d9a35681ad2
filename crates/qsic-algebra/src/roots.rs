//! Real root isolation with rational isolating intervals (Descartes' method with bisection).
//!
//! Postconditions of [`isolate_real_roots`]: the result lists every distinct real root
//! once, in increasing order; each is either an exact rational or an open interval
//! `(lo, hi)` with rational (dyadic) ends that are not roots, containing exactly one root;
//! the intervals are pairwise disjoint.

use crate::poly::Poly;
use crate::sign::Sign;
use dashu_int::ops::{BitTest, UnsignedAbs};
use dashu_int::IBig;
use dashu_ratio::RBig;

/// An isolated real root.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RootInterval {
    /// A rational root, found exactly.
    Exact(RBig),
    /// Exactly one root in the open interval `(lo, hi)`; `lo` and `hi` are not roots.
    Open(RBig, RBig),
}

impl RootInterval {
    /// Lower end (the value itself for an exact root).
    pub fn lo(&self) -> &RBig {
        match self {
            RootInterval::Exact(v) => v,
            RootInterval::Open(l, _) => l,
        }
    }
    /// Upper end (the value itself for an exact root).
    pub fn hi(&self) -> &RBig {
        match self {
            RootInterval::Exact(v) => v,
            RootInterval::Open(_, h) => h,
        }
    }
}

/// A power of two strictly larger than the absolute value of every root (Cauchy's bound).
pub fn root_bound_log2(p: &Poly) -> usize {
    let lead_bits = p.leading().unsigned_abs().bit_len();
    let max_bits = p.coeffs()[..p.coeffs().len().saturating_sub(1)]
        .iter()
        .map(|v| v.unsigned_abs().bit_len())
        .max()
        .unwrap_or(0);
    // |root| < 1 + max|aᵢ|/|aₙ| ≤ 1 + 2^(max_bits − lead_bits + 1)
    (max_bits + 2).saturating_sub(lead_bits).max(1)
}

/// Isolates the real roots of a polynomial (multiple roots are reported once).
///
/// ```
/// # use qsic_algebra::{Poly, roots::{isolate_real_roots, RootInterval}};
/// # use qsic_algebra::RBig;
/// let p = &Poly::from_roots(&[0, 3]) * &Poly::from_i64s(&[-2, 0, 1]); // x(x−3)(x²−2)
/// let r = isolate_real_roots(&p);
/// assert_eq!(r.len(), 4);
/// assert_eq!(r[1], RootInterval::Exact(RBig::ZERO));
/// assert!(r[0].hi() < &RBig::ZERO && r[2].lo() > &RBig::ZERO);
/// ```
pub fn isolate_real_roots(p: &Poly) -> Vec<RootInterval> {
    if p.degree().unwrap_or(0) == 0 {
        return Vec::new();
    }
    let sf = p.squarefree_part();
    let mut out = Vec::new();
    let q = &sf;
    let k = root_bound_log2(q);
    // x = 2^k (2t − 1), t ∈ (0, 1) covers (−2^k, 2^k).
    let two_k = IBig::ONE << k;
    let unit = q.shift(&-&two_k).scale_var(&(&two_k * IBig::from(2)));
    let mut found: Vec<(IBig, usize, bool)> = Vec::new(); // (c, level, exact): t ∈ (c/2^level, (c+1)/2^level) or t = c/2^level
    bisect(unit, IBig::ZERO, 0, &mut found);
    for (c, level, exact) in found {
        let to_x = |num: &IBig| -> RBig {
            // t = num / 2^level, x = 2^k (2t − 1) = (2^(k+1) num − 2^(k+level)) / 2^level
            let n = (num << (k + 1)) - (IBig::ONE << (k + level));
            RBig::from_parts_signed(n, IBig::ONE << level)
        };
        if exact {
            out.push(RootInterval::Exact(to_x(&c)));
        } else {
            out.push(fix_ends(&sf, to_x(&c), to_x(&(&c + IBig::ONE))));
        }
    }
    out.sort_by(|a, b| a.lo().cmp(b.lo()));
    out
}

/// Descartes bisection of `p` on `(0, 1)`, which stands for the interval `(c/2^l, (c+1)/2^l)`.
/// `p` has no root at 0 or 1.
fn bisect(p: Poly, c: IBig, level: usize, out: &mut Vec<(IBig, usize, bool)>) {
    match p.reverse().shift(&IBig::ONE).sign_variations() {
        0 => {}
        1 => out.push((c, level, false)),
        _ => {
            // left half: 2ⁿ p(x/2); right half: that shifted by 1; the midpoint is right(0).
            let mut left = p.scale_var_inverse(&IBig::from(2));
            let mut right = left.shift(&IBig::ONE);
            let c2 = &c << 1;
            if right.coeff(0).is_zero() {
                out.push((&c2 + IBig::ONE, level + 1, true));
                right = right.shift_down(1);
                left = left
                    .div_exact(&Poly::from_i64s(&[-1, 1]))
                    .expect("left(1) = right(0) = 0, so x − 1 divides left");
            }
            bisect(left, c2.clone(), level + 1, out);
            bisect(right, c2 + IBig::ONE, level + 1, out);
        }
    }
}

/// Moves the ends of an interval holding exactly one root of the square-free `p` in its
/// interior off the roots of `p` (ends of bisection intervals can fall on exact rational
/// roots found beside them). The search uses `p` with its roots at the ends divided out,
/// which changes sign across the interior root.
fn fix_ends(p: &Poly, lo: RBig, hi: RBig) -> RootInterval {
    let mut q = p.clone();
    for end in [&lo, &hi] {
        if q.sign_at(end).is_zero() {
            q = q
                .div_exact(&Poly::vanishing_at(end))
                .expect("a rational root gives a primitive linear factor");
        }
    }
    let two = RBig::from(2);
    let (mut lo, mut hi) = (lo, hi);
    let s_lo = q.sign_at(&lo);
    while p.sign_at(&lo).is_zero() || p.sign_at(&hi).is_zero() {
        let mid = (&lo + &hi) / &two;
        match q.sign_at(&mid) {
            Sign::Zero => return RootInterval::Exact(mid),
            s if s == s_lo => lo = mid,
            _ => hi = mid,
        }
    }
    RootInterval::Open(lo, hi)
}

/// Narrows an isolating interval of a root of the square-free `p` by bisection until it is
/// shorter than `width` (or the root is found exactly).
pub fn refine(p: &Poly, root: &RootInterval, width: &RBig) -> RootInterval {
    let (mut lo, mut hi) = match root {
        RootInterval::Exact(_) => return root.clone(),
        RootInterval::Open(l, h) => (l.clone(), h.clone()),
    };
    let s_lo = p.sign_at(&lo);
    let two = RBig::from(2);
    while &(&hi - &lo) >= width {
        let mid = (&lo + &hi) / &two;
        match p.sign_at(&mid) {
            Sign::Zero => return RootInterval::Exact(mid),
            s if s == s_lo => lo = mid,
            _ => hi = mid,
        }
    }
    RootInterval::Open(lo, hi)
}

/// Halves an isolating interval once (see [`refine`]).
pub fn bisect_once(p: &Poly, root: &RootInterval) -> RootInterval {
    match root {
        RootInterval::Exact(_) => root.clone(),
        RootInterval::Open(lo, hi) => {
            let mid = (lo + hi) / RBig::from(2);
            match p.sign_at(&mid) {
                Sign::Zero => RootInterval::Exact(mid),
                s if s == p.sign_at(lo) => RootInterval::Open(mid, hi.clone()),
                _ => RootInterval::Open(lo.clone(), mid),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn check_isolation(p: &Poly, expected: usize) {
        let r = isolate_real_roots(p);
        assert_eq!(r.len(), expected, "{p}");
        let sf = p.squarefree_part();
        for w in r.windows(2) {
            assert!(
                w[0].hi() <= w[1].lo() && w[0].lo() < w[1].lo(),
                "{p}: {w:?}"
            );
        }
        for iv in &r {
            match iv {
                RootInterval::Exact(v) => assert_eq!(sf.sign_at(v), Sign::Zero),
                RootInterval::Open(l, h) => {
                    assert!(l < h);
                    assert_eq!(
                        sf.sign_at(l) * sf.sign_at(h),
                        Sign::Negative,
                        "{p} on ({l}, {h})"
                    );
                }
            }
        }
    }

    #[test]
    fn wilkinson_and_clustered() {
        let roots: Vec<i64> = (1..=20).collect();
        check_isolation(&Poly::from_roots(&roots), 20);
        check_isolation(
            &Poly::from_rational_roots(&[(1, 1000), (2, 1000), (1, 999), (-1, 1)]),
            4,
        );
        // Mignotte-like: x^4 − 2(100x − 1)² has two roots very close to 1/100
        let m = &Poly::from_i64s(&[0, 0, 0, 0, 1])
            - &(&Poly::from_i64s(&[-1, 100]) * &Poly::from_i64s(&[-2, 200]));
        check_isolation(&m, 4);
    }

    #[test]
    fn multiple_and_irrational_roots() {
        let p = &(&Poly::from_roots(&[2, 2, 2]) * &Poly::from_i64s(&[-2, 0, 1]))
            * &Poly::from_i64s(&[-2, 0, 1]);
        check_isolation(&p, 3);
        check_isolation(&Poly::from_i64s(&[1, 0, 1]), 0);
        check_isolation(&Poly::from_i64s(&[0, 0, 5]), 1);
    }

    #[test]
    fn huge_coefficients() {
        let big = IBig::from(10).pow(45);
        // (x − 10^45)(x + 1)(10^45 x − 1)
        let p = &(&Poly::new(vec![-big.clone(), IBig::ONE]) * &Poly::from_i64s(&[1, 1]))
            * &Poly::new(vec![IBig::from(-1), big]);
        check_isolation(&p, 3);
    }

    proptest! {
        #[test]
        fn sturm_and_descartes_agree(c in prop::collection::vec(-30i64..30, 2..8)) {
            let p = Poly::from_i64s(&c);
            prop_assume!(p.degree().unwrap_or(0) >= 1);
            let n = p.count_real_roots_sturm();
            check_isolation(&p, n);
        }

        #[test]
        fn known_rational_roots_are_found(roots in prop::collection::vec((-50i64..50, 1i64..20), 1..6)) {
            let p = &Poly::from_rational_roots(&roots) * &Poly::from_i64s(&[3, 1, 1]);
            let mut distinct: Vec<RBig> = roots.iter().map(|&(a, b)| RBig::from_parts_signed(IBig::from(a), IBig::from(b))).collect();
            distinct.sort();
            distinct.dedup();
            let r = isolate_real_roots(&p);
            prop_assert_eq!(r.len(), distinct.len());
            for (iv, v) in r.iter().zip(&distinct) {
                prop_assert!(iv.lo() <= v && v <= iv.hi());
            }
        }
    }
}

#[cfg(test)]
mod regression_tests {
    use super::*;

    /// Regression: the interval around −4/3 had both ends on the exact roots −3/2 and −5/4.
    #[test]
    fn interval_ends_on_exact_neighbour_roots() {
        let p = Poly::from_rational_roots(&[(-3, 2), (-4, 3), (-5, 4), (-1, 1)]);
        let r = isolate_real_roots(&p);
        assert_eq!(r.len(), 4);
        for iv in &r {
            if let RootInterval::Open(lo, hi) = iv {
                assert_eq!(p.sign_at(lo) * p.sign_at(hi), Sign::Negative);
            }
        }
    }
}

#[cfg(test)]
mod regression_zero_root {
    use super::*;

    /// Regression: with the root 0 pulled out first, the interval of the root 2 of
    /// x² − 2x was reported as (−8, 8), which also holds 0.
    #[test]
    fn root_at_zero_and_another() {
        let r = isolate_real_roots(&Poly::from_i64s(&[0, -2, 1]));
        assert_eq!(r.len(), 2);
        assert_eq!(r[0], RootInterval::Exact(RBig::ZERO));
        assert!(r[1].lo() >= &RBig::ZERO && r[1].hi() <= &RBig::from(8));
        assert!(!(r[1].lo() < &RBig::ZERO && r[1].hi() > &RBig::ZERO));
    }
}
