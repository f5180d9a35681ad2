//! Polynomial gcd over ℤ by the subresultant pseudo-remainder sequence.
//!
//! The subresultant PRS (Collins 1967, Brown–Traub 1971) keeps coefficient growth
//! linear in the degree without computing contents at each step; the primitive PRS
//! ([`gcd_primitive_prs`]) is the simpler second route the tests compare it with.

use super::Poly;
use dashu_int::IBig;

impl Poly {
    /// The primitive gcd with positive leading coefficient; `gcd(0, 0) = 0`.
    ///
    /// ```
    /// # use qsic_algebra::Poly;
    /// let a = Poly::from_roots(&[1, 2, 3]);
    /// let b = Poly::from_roots(&[2, 3, 5]);
    /// assert_eq!(a.gcd(&b), Poly::from_roots(&[2, 3]));
    /// ```
    pub fn gcd(&self, other: &Poly) -> Poly {
        gcd_subresultant(self, other)
    }
}

/// Gcd by the subresultant PRS.
pub fn gcd_subresultant(a: &Poly, b: &Poly) -> Poly {
    let (mut f, mut g) = match (a.degree(), b.degree()) {
        (None, _) => return b.primitive_part(),
        (_, None) => return a.primitive_part(),
        (Some(da), Some(db)) if da >= db => (a.primitive_part(), b.primitive_part()),
        _ => (b.primitive_part(), a.primitive_part()),
    };
    if g.is_constant() {
        return Poly::constant(IBig::ONE);
    }
    let mut lead_g = IBig::ONE; // the paper's g
    let mut h = IBig::ONE;
    loop {
        let delta = f.degree().unwrap_or(0) - g.degree().unwrap_or(0);
        let r = f.pseudo_rem(&g);
        match r.degree() {
            None => return g.primitive_part(),
            Some(0) => return Poly::constant(IBig::ONE),
            Some(_) => {}
        }
        let divisor = &lead_g * h.pow(delta);
        f = g;
        g = Poly::new(r.coeffs().iter().map(|v| v / &divisor).collect());
        lead_g = f.leading();
        // h ← lead_g^δ / h^(δ−1)
        h = if delta == 0 {
            h
        } else {
            lead_g.pow(delta) / h.pow(delta - 1)
        };
    }
}

/// Gcd by the primitive PRS (contents removed at every step).
pub fn gcd_primitive_prs(a: &Poly, b: &Poly) -> Poly {
    let (mut f, mut g) = match (a.degree(), b.degree()) {
        (None, _) => return b.primitive_part(),
        (_, None) => return a.primitive_part(),
        (Some(da), Some(db)) if da >= db => (a.primitive_part(), b.primitive_part()),
        _ => (b.primitive_part(), a.primitive_part()),
    };
    loop {
        if g.is_zero() {
            return f.primitive_part();
        }
        if g.is_constant() {
            return Poly::constant(IBig::ONE);
        }
        let r = f.pseudo_rem(&g).primitive_part();
        f = g;
        g = r;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn known_gcds() {
        let c = Poly::from_rational_roots(&[(1, 2), (-3, 7)]);
        let a = &c * &Poly::from_i64s(&[1, 0, 1]);
        let b = &c * &Poly::from_roots(&[4, 4, -9]);
        assert_eq!(a.gcd(&b), c.primitive_part());
        assert_eq!(
            Poly::from_roots(&[1]).gcd(&Poly::from_roots(&[2])),
            Poly::from_i64s(&[1])
        );
        assert_eq!(
            Poly::zero().gcd(&Poly::from_i64s(&[-4, -2])),
            Poly::from_i64s(&[2, 1])
        );
    }

    #[test]
    fn huge_coefficients() {
        let big = IBig::from(10).pow(40) + IBig::from(7);
        let common = Poly::new(vec![big.clone(), IBig::from(3), IBig::ONE]);
        let a = &common * &Poly::new(vec![IBig::from(5), big.clone()]);
        let b = &common * &Poly::new(vec![-big, IBig::ONE, IBig::from(2)]);
        assert_eq!(a.gcd(&b), common);
    }

    fn small_poly() -> impl Strategy<Value = Poly> {
        prop::collection::vec(-20i64..20, 1..6).prop_map(|v| Poly::from_i64s(&v))
    }

    proptest! {
        #[test]
        fn subresultant_agrees_with_primitive_prs(a in small_poly(), b in small_poly(), c in small_poly()) {
            let a = &a * &c;
            let b = &b * &c;
            let g = gcd_subresultant(&a, &b);
            prop_assert_eq!(&g, &gcd_primitive_prs(&a, &b));
            if !g.is_zero() {
                prop_assert!(a.div_exact(&g).is_some());
                prop_assert!(b.div_exact(&g).is_some());
                if !c.is_zero() {
                    prop_assert!(g.div_exact(&c.primitive_part()).is_some());
                }
            }
        }
    }
}
