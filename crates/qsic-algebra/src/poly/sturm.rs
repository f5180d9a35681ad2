//! Sturm sequences: exact counts of distinct real roots.

use super::Poly;
use crate::sign::Sign;
use dashu_int::IBig;
use dashu_ratio::RBig;

/// The Sturm sequence of a polynomial, each member scaled by a positive factor.
#[derive(Clone, Debug)]
pub struct SturmSequence {
    seq: Vec<Poly>,
}

impl SturmSequence {
    /// `p, p', −rem(p, p'), …` down to a constant (or to the gcd of `p` and `p'`, which
    /// does not change the counts of distinct roots at points where `p ≠ 0`).
    pub fn new(p: &Poly) -> SturmSequence {
        let mut seq = vec![p.clone()];
        if p.degree().unwrap_or(0) == 0 {
            return SturmSequence { seq };
        }
        seq.push(p.derivative());
        loop {
            let n = seq.len();
            let (a, b) = (&seq[n - 2], &seq[n - 1]);
            let delta = a.degree().unwrap_or(0) - b.degree().unwrap_or(0);
            let mut r = a.pseudo_rem(b);
            if r.is_zero() {
                break;
            }
            // prem = lc(b)^(δ+1)·rem: undo a negative factor.
            if b.leading() < IBig::ZERO && delta % 2 == 0 {
                r = -&r;
            }
            let c = r.content();
            let r = Poly::new(r.coeffs().iter().map(|v| -(v / &c)).collect());
            let stop = r.is_constant();
            seq.push(r);
            if stop {
                break;
            }
        }
        SturmSequence { seq }
    }

    fn variations(signs: impl Iterator<Item = Sign>) -> usize {
        let mut last = Sign::Zero;
        let mut v = 0;
        for s in signs {
            if s == Sign::Zero {
                continue;
            }
            if last != Sign::Zero && s != last {
                v += 1;
            }
            last = s;
        }
        v
    }

    /// Sign variations at a rational.
    pub fn variations_at(&self, x: &RBig) -> usize {
        Self::variations(self.seq.iter().map(|p| p.sign_at(x)))
    }

    /// Number of distinct real roots.
    pub fn count_real_roots(&self) -> usize {
        let lo = Self::variations(self.seq.iter().map(|p| p.sign_at_neg_infinity()));
        let hi = Self::variations(self.seq.iter().map(|p| p.sign_at_pos_infinity()));
        lo.saturating_sub(hi)
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
    fn clustered_roots() {
        // roots 1/1000, 2/1000, 3/1000 and a conjugate pair
        let p = &Poly::from_rational_roots(&[(1, 1000), (2, 1000), (3, 1000)])
            * &Poly::from_i64s(&[1, 1, 1]);
        assert_eq!(p.count_real_roots_sturm(), 3);
    }
}
