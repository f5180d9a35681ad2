//! Polynomials over a field `F` (ℚ, ℚ(√δ), ℚ(α)): division with remainder, monic gcd,
//! Bézout coefficients, inverses modulo a polynomial, square-free decomposition (Yun).
//!
//! Over ℤ prefer the integer routines ([`Poly::gcd`](super::Poly::gcd), …): they avoid
//! rational coefficients. These are for the extension fields and for ℚ\[x\].

use super::Poly;
use crate::ring::Field;

impl<F: Field> Poly<F> {
    /// Division with remainder: `(q, r)` with `self = q·d + r`, `deg r < deg d`.
    ///
    /// # Panics
    /// If `d` is zero.
    pub fn div_rem(&self, d: &Self) -> (Self, Self) {
        let dn = d.degree().expect("division by the zero polynomial");
        let inv = d.c[dn].inv().expect("a nonzero leading coefficient");
        let Some(n) = self.degree().filter(|&n| n >= dn) else {
            return (Poly::zero(), self.clone());
        };
        let mut r = self.c.clone();
        let mut q = vec![F::zero(); n - dn + 1];
        for k in (0..=n - dn).rev() {
            let f = r[k + dn].mul(&inv);
            if f.is_zero() {
                continue;
            }
            for (j, dj) in d.c.iter().enumerate() {
                r[k + j].sub_mul_assign(&f, dj);
            }
            q[k] = f;
        }
        r.truncate(dn);
        (Poly::new(q), Poly::new(r))
    }

    /// The remainder of the division by `d`.
    ///
    /// # Panics
    /// If `d` is zero.
    pub fn rem(&self, d: &Self) -> Self {
        self.div_rem(d).1
    }

    /// The monic associate (zero stays zero).
    pub fn monic(&self) -> Self {
        match self.c.last() {
            None => Poly::zero(),
            Some(l) => self.scale(&l.inv().expect("a nonzero leading coefficient")),
        }
    }

    /// The monic gcd (`gcd(0, 0) = 0`), by Euclid's algorithm.
    pub fn gcd_monic(&self, other: &Self) -> Self {
        let (mut a, mut b) = (self.clone(), other.clone());
        while !b.is_zero() {
            let r = a.rem(&b);
            a = b;
            b = r;
        }
        a.monic()
    }

    /// The extended gcd `(g, s, t)` with `g = s·self + t·other` monic (`g = 0` only for
    /// two zeros).
    pub fn gcd_ext(&self, other: &Self) -> (Self, Self, Self) {
        let (mut r0, mut r1) = (self.clone(), other.clone());
        let (mut s0, mut s1) = (Poly::constant(F::one()), Poly::zero());
        let (mut t0, mut t1) = (Poly::zero(), Poly::constant(F::one()));
        while !r1.is_zero() {
            let (q, r) = r0.div_rem(&r1);
            let s = &s0 - &(&q * &s1);
            let t = &t0 - &(&q * &t1);
            (r0, r1) = (r1, r);
            (s0, s1) = (s1, s);
            (t0, t1) = (t1, t);
        }
        match r0.c.last() {
            None => (r0, s0, t0),
            Some(l) => {
                let inv = l.inv().expect("a nonzero leading coefficient");
                (r0.scale(&inv), s0.scale(&inv), t0.scale(&inv))
            }
        }
    }

    /// The inverse of `self` modulo `m`, or `Err(g)` with `g = gcd(self, m)` monic of
    /// positive degree when there is none (then `g` splits `m`: the D5 step).
    ///
    /// # Panics
    /// If `m` is zero.
    pub fn inverse_mod(&self, m: &Self) -> Result<Self, Self> {
        let (g, s, _) = self.rem(m).gcd_ext(m);
        if g.degree() == Some(0) {
            Ok(s.rem(m))
        } else {
            Err(if g.is_zero() { m.monic() } else { g })
        }
    }

    /// Square-free decomposition over the field (Yun): monic, square-free, pairwise coprime
    /// `fᵢ` of positive degree with `self = lc · ∏ fᵢ^mᵢ`, increasing `mᵢ`. Constants give
    /// an empty list.
    pub fn squarefree_decomposition_field(&self) -> Vec<(Self, usize)> {
        if self.degree().unwrap_or(0) == 0 {
            return Vec::new();
        }
        super::squarefree::yun(self.monic(), Poly::gcd_monic, |a, d| a.div_rem(d).0)
    }

    /// The monic square-free part (the product of the distinct irreducible factors).
    pub fn squarefree_part_field(&self) -> Self {
        if self.degree().unwrap_or(0) == 0 {
            return Poly::constant(F::one());
        }
        let g = self.gcd_monic(&self.derivative());
        self.div_rem(&g).0.monic()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use dashu_int::IBig;
    use dashu_ratio::RBig;
    use proptest::prelude::*;

    fn q(c: &[i64]) -> Poly<RBig> {
        Poly::from_i64s(c).to_rational()
    }

    #[test]
    fn division_identity_and_remainders() {
        let a = q(&[5, -3, 0, 2, 7]);
        let d = q(&[1, 0, 3]);
        let (qu, r) = a.div_rem(&d);
        assert_eq!(&(&qu * &d) + &r, a);
        assert!(r.degree().unwrap() < 2);
        let (qu, r) = d.div_rem(&a);
        assert!(qu.is_zero());
        assert_eq!(r, d);
    }

    #[test]
    fn gcds_and_inverses() {
        let a = Poly::from_roots(&[1, 2, 3]).to_rational();
        let b = Poly::from_roots(&[2, 3, 5])
            .scale(&IBig::from(4))
            .to_rational();
        assert_eq!(a.gcd_monic(&b), Poly::from_roots(&[2, 3]).to_rational());
        let (g, s, t) = a.gcd_ext(&b);
        assert_eq!(&(&s * &a) + &(&t * &b), g);
        // x has an inverse modulo x² − 2: x/2
        let m = q(&[-2, 0, 1]);
        let inv = q(&[0, 1]).inverse_mod(&m).unwrap();
        assert_eq!((&inv * &q(&[0, 1])).rem(&m), Poly::constant(RBig::ONE));
        // x − 1 has none modulo (x − 1)(x + 3): the split factor comes back
        let m = Poly::from_roots(&[1, -3]).to_rational();
        assert_eq!(
            q(&[-2, 2]).inverse_mod(&m),
            Err(Poly::from_roots(&[1]).to_rational())
        );
        assert_eq!(m.inverse_mod(&m), Err(m.monic()));
    }

    #[test]
    fn squarefree_over_the_rationals() {
        let p = &Poly::from_roots(&[1, 1, 1, 2]) * &Poly::from_i64s(&[1, 0, 1]);
        let d = p
            .scale(&IBig::from(3))
            .to_rational()
            .squarefree_decomposition_field();
        let expect: Vec<(Poly<RBig>, usize)> = p
            .squarefree_decomposition()
            .into_iter()
            .map(|(f, m)| (f.to_rational().monic(), m))
            .collect();
        assert_eq!(d, expect);
        assert_eq!(
            p.to_rational().squarefree_part_field(),
            p.squarefree_part().to_rational().monic()
        );
        assert!(q(&[4]).squarefree_decomposition_field().is_empty());
    }

    proptest! {
        #[test]
        fn bezout_identity(a in prop::collection::vec(-9i64..9, 0..6), b in prop::collection::vec(-9i64..9, 0..6)) {
            let (a, b) = (q(&a), q(&b));
            let (g, s, t) = a.gcd_ext(&b);
            prop_assert_eq!(&(&s * &a) + &(&t * &b), g.clone());
            if !g.is_zero() {
                prop_assert!(a.rem(&g).is_zero() && b.rem(&g).is_zero());
                prop_assert!(g.leading().is_one());
            }
            // the field gcd agrees with the integer gcd
            let ia = Poly::from_rational(&a).0;
            let ib = Poly::from_rational(&b).0;
            prop_assert_eq!(g, ia.gcd(&ib).to_rational().monic());
        }
    }
}
