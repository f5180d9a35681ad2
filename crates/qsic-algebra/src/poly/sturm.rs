//! Sturm sequences: exact counts of distinct real roots.

use super::Poly;
use crate::sign::count_variations;
use dashu_int::IBig;
use dashu_ratio::RBig;

/// The Sturm sequence of a polynomial, each member scaled by a positive factor.
#[derive(Clone, Debug)]
pub struct SturmSequence {
    seq: Vec<Poly>,
}

/// A positive multiple of `−rem(a, b)` (`b ≠ 0`), made primitive: the next member of a
/// signed remainder sequence.
fn neg_rem(a: &Poly, b: &Poly) -> Poly {
    let (Some(da), Some(db)) = (a.degree(), b.degree()) else {
        return Poly::zero();
    };
    let r = if da < db {
        -a
    } else {
        // prem = lc(b)^(δ+1)·rem: undo a negative factor.
        let prem = a.pseudo_rem(b);
        if b.leading() < IBig::ZERO && (da - db) % 2 == 0 {
            prem
        } else {
            -&prem
        }
    };
    let c = r.content();
    if c.is_zero() || c.is_one() {
        r
    } else {
        Poly::new(r.coeffs().iter().map(|v| v / &c).collect())
    }
}

/// The signed remainder sequence `a, b, −rem(a, b), …` until a remainder vanishes, each
/// member scaled by a positive factor.
fn signed_remainder_sequence(a: Poly, b: Poly) -> Vec<Poly> {
    let mut seq = vec![a];
    if b.is_zero() {
        return seq;
    }
    seq.push(b);
    loop {
        let n = seq.len();
        let r = neg_rem(&seq[n - 2], &seq[n - 1]);
        if r.is_zero() {
            return seq;
        }
        seq.push(r);
    }
}

/// Sign variations at −∞ minus at +∞.
fn variations_across_the_line(seq: &[Poly]) -> i64 {
    let lo = count_variations(seq.iter().map(Poly::sign_at_neg_infinity));
    let hi = count_variations(seq.iter().map(Poly::sign_at_pos_infinity));
    lo as i64 - hi as i64
}

/// The Tarski query `Σ sign q(α)` over the distinct real roots `α` of `p` (`p` of positive
/// degree), by the Sturm–Tarski theorem: the variations of the signed remainder sequence
/// of `(p, p'·q)` at −∞ minus at +∞. With `q = 1` it counts the real roots.
///
/// ```
/// # use qsic_algebra::{Poly, poly::sturm::tarski_query};
/// // roots −1, 0, 2 of p; q = x − 1 is negative at two of them, positive at one
/// assert_eq!(tarski_query(&Poly::from_roots(&[-1, 0, 2]), &Poly::from_roots(&[1])), -1);
/// ```
pub fn tarski_query(p: &Poly, q: &Poly) -> i64 {
    variations_across_the_line(&tarski_sequence(p, q))
}

/// The signed remainder sequence of `(p, p'·q)` (Sturm–Tarski).
fn tarski_sequence(p: &Poly, q: &Poly) -> Vec<Poly> {
    // p'q may be replaced by a positive multiple of its remainder mod p: the Cauchy index
    // of p'q/p does not change when a multiple of p is added.
    let mut pq = &p.derivative() * q;
    if pq.degree() >= p.degree() {
        pq = -&neg_rem(&pq, p);
    }
    signed_remainder_sequence(p.clone(), pq)
}

/// The Tarski query on an interval: `Σ sign q(α)` over the distinct roots `α` of `p` in
/// `(a, b]`, for `a < b` that are not roots of `p` (the variations of the same sequence as
/// [`tarski_query`] at `a` minus at `b`). With one root of `p` inside, it is the sign of
/// `q` there, decided without refinement.
///
/// ```
/// # use qsic_algebra::{Poly, RBig, poly::sturm::tarski_query_in};
/// // √2 is the one root of x² − 2 in (1, 2]; x² − 3 is negative there
/// let (p, q) = (Poly::from_i64s(&[-2, 0, 1]), Poly::from_i64s(&[-3, 0, 1]));
/// assert_eq!(tarski_query_in(&p, &q, &RBig::ONE, &RBig::from(2)), -1);
/// ```
pub fn tarski_query_in(p: &Poly, q: &Poly, a: &RBig, b: &RBig) -> i64 {
    let seq = tarski_sequence(p, q);
    let at = |x: &RBig| count_variations(seq.iter().map(|s| s.sign_at(x))) as i64;
    at(a) - at(b)
}

impl SturmSequence {
    /// `p, p', −rem(p, p'), …` down to the gcd of `p` and `p'` (which does not change the
    /// counts of distinct roots at points where `p ≠ 0`).
    pub fn new(p: &Poly) -> SturmSequence {
        SturmSequence {
            seq: signed_remainder_sequence(p.clone(), p.derivative()),
        }
    }

    /// Sign variations at a rational.
    pub fn variations_at(&self, x: &RBig) -> usize {
        count_variations(self.seq.iter().map(|p| p.sign_at(x)))
    }

    /// Number of distinct real roots.
    pub fn count_real_roots(&self) -> usize {
        variations_across_the_line(&self.seq).max(0) as usize
    }

    /// Number of distinct real roots in the half-open interval `(a, b]`, `a < b`.
    pub fn count_roots_in(&self, a: &RBig, b: &RBig) -> usize {
        self.variations_at(a).saturating_sub(self.variations_at(b))
    }
}

impl Poly {
    /// Number of distinct real roots, by a Sturm sequence.
    ///
    /// ```
    /// # use qsic_algebra::Poly;
    /// assert_eq!(Poly::from_roots(&[-1, 0, 0, 5]).count_real_roots_sturm(), 3);
    /// assert_eq!(Poly::from_i64s(&[1, 0, 1]).count_real_roots_sturm(), 0);
    /// ```
    pub fn count_real_roots_sturm(&self) -> usize {
        SturmSequence::new(self).count_real_roots()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wilkinson_20() {
        let roots: Vec<i64> = (1..=20).collect();
        let w = Poly::from_roots(&roots);
        let s = SturmSequence::new(&w);
        assert_eq!(s.count_real_roots(), 20);
        assert_eq!(s.count_roots_in(&RBig::from(5), &RBig::from(10)), 5);
        let half = RBig::from_parts_signed(IBig::from(21), IBig::from(2));
        assert_eq!(s.count_roots_in(&half, &RBig::from(100)), 10);
    }

    #[test]
    fn tarski_query_counts_signs_at_roots() {
        // roots −1, 0, 2 of x³ − x² − 2x; q = x − 1: signs −, −, +
        let p = Poly::from_roots(&[-1, 0, 2]);
        assert_eq!(tarski_query(&p, &Poly::from_roots(&[1])), -1);
        assert_eq!(tarski_query(&p, &Poly::constant(IBig::ONE)), 3);
        // q = x² + 1 > 0 everywhere; q = −(x − 3)(x + 3): positive at all three roots
        assert_eq!(tarski_query(&p, &Poly::from_i64s(&[1, 0, 1])), 3);
        assert_eq!(tarski_query(&p, &Poly::from_i64s(&[9, 0, -1])), 3);
        assert_eq!(tarski_query(&p, &Poly::from_i64s(&[-9, 0, 1])), -3);
        // a root of q: sign zero there
        assert_eq!(tarski_query(&p, &Poly::from_roots(&[0])), 0);
        // one real root (x³ − 2), q = x: positive
        assert_eq!(
            tarski_query(&Poly::from_i64s(&[-2, 0, 0, 1]), &Poly::from_i64s(&[0, 1])),
            1
        );
    }

    #[test]
    fn clustered_roots() {
        // roots 1/1000, 2/1000, 3/1000 and a conjugate pair
        let p = &Poly::from_rational_roots(&[(1, 1000), (2, 1000), (3, 1000)])
            * &Poly::from_i64s(&[1, 1, 1]);
        assert_eq!(p.count_real_roots_sturm(), 3);
    }
}
