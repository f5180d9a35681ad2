//! Descartes' rule of signs on an interval (the Möbius transform to (0, ∞)).

use super::Poly;
use dashu_int::IBig;
use dashu_ratio::RBig;

impl Poly {
    /// `(x+1)ⁿ p((a·x + b)/(x + 1))` scaled to integers, whose positive roots correspond
    /// to the roots of `p` in `(b, a)`… arranged so that the result's positive roots
    /// are exactly the roots of `p` in the open interval `(lo, hi)`.
    pub fn to_interval_zero_infinity(&self, lo: &RBig, hi: &RBig) -> Poly {
        // x = lo + (hi − lo)·t, t ∈ (0,1); with common denominator d: x = (l + (h−l)t)/d.
        let d = IBig::from(lo.denominator() * hi.denominator());
        let l = lo.numerator() * IBig::from(hi.denominator().clone());
        let h = hi.numerator() * IBig::from(lo.denominator().clone());
        let on_unit = self.scale_var_inverse(&d).shift(&l).scale_var(&(h - &l));
        // t = 1/(1+s), s ∈ (0, ∞)
        on_unit.reverse().shift(&IBig::ONE)
    }

    /// Descartes' bound on the number of roots in the open interval `(lo, hi)`,
    /// counted with multiplicity: exact when it is 0 or 1, otherwise an upper bound
    /// of the same parity.
    pub fn count_roots_in_descartes(&self, lo: &RBig, hi: &RBig) -> usize {
        self.to_interval_zero_infinity(lo, hi).sign_variations()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_on_intervals() {
        let p = Poly::from_roots(&[-3, 1, 2, 7]);
        let r = |a: i64, b: i64| p.count_roots_in_descartes(&RBig::from(a), &RBig::from(b));
        assert_eq!(r(0, 3), 2);
        assert_eq!(r(3, 6), 0);
        assert_eq!(r(-5, 0), 1);
        assert_eq!(r(-10, 10), 4);
    }
}
