//! Subresultants, resultants and discriminants over any integral domain `C`
//! (ℤ, ℚ, ℤ\[t\], ℚ(α), …): only exact division is used, never a gcd of coefficients.
//!
//! | entry point | computes | cost |
//! |---|---|---|
//! | [`Poly::resultant`] | `res(a, b)` by the subresultant PRS (Collins; Cohen, Alg. 3.3.7 without contents) | `O(mn)` ring ops |
//! | [`Poly::discriminant`] | `(−1)^(n(n−1)/2) res(p, p′) / lc(p)` | as the resultant |
//! | [`Poly::gcd_domain`] | a gcd up to a nonzero factor of `C`: the last nonzero term of the subresultant PRS | as the resultant |
//! | [`Poly::subresultant`] | the `j`-th subresultant `S_j(a, b)` as a determinant polynomial (Bareiss) | `O((m+n)³)` ring ops |
//! | [`Poly::principal_subresultant_coefficients`] | `psc_j(a, b)` for `j = 0 … min(m, n)` | `O((m+n)⁴)` ring ops |
//!
//! Definitions (Basu–Pollack–Roy, §4.2): for `deg a = m ≥ deg b = n` and `0 ≤ j ≤ n`,
//! `S_j` is the determinant polynomial of the `(m+n−2j) × (m+n−j)` matrix whose rows are the
//! coefficients of `x^(n−j−1)a, …, a, x^(m−j−1)b, …, b` (highest degree first): the first
//! `m+n−2j−1` columns plus one more column for each power `x^k`, `k ≤ j`. `S_0 = res(a, b)`,
//! `psc_j` is the coefficient of `x^j` in `S_j`, and `deg gcd(a, b)` is the least `j` with
//! `psc_j ≠ 0`.

use super::Poly;
use crate::budget::{Budget, Exhausted};
use crate::linalg::minors::det_bareiss;
use crate::ring::Ring;

impl<C: Ring> Poly<C> {
    /// The resultant `res(self, other)` (Sylvester's determinant), zero iff the two have a
    /// common root or both are zero; `res(a, c) = c^deg a` for a nonzero constant `c`.
    ///
    /// ```
    /// # use qsic_algebra::Poly;
    /// // res((x−1)(x−2), x−3) = (1−3)(2−3) = 2
    /// let r = Poly::from_roots(&[1, 2]).resultant(&Poly::from_roots(&[3]));
    /// assert_eq!(r, 2.into());
    /// ```
    pub fn resultant(&self, other: &Self) -> C {
        let (Some(m), Some(n)) = (self.degree(), other.degree()) else {
            return C::zero();
        };
        // res(a, b) = (−1)^(mn) res(b, a)
        let (a, b, mut negate) = if m >= n {
            (self.clone(), other.clone(), false)
        } else {
            (other.clone(), self.clone(), m % 2 == 1 && n % 2 == 1)
        };
        if b.degree() == Some(0) {
            let r = b.leading().pow(a.degree().unwrap_or(0));
            return if negate { r.neg() } else { r };
        }
        let mut prs = Prs::new(a, b);
        loop {
            let (da, db) = (prs.a.degree().unwrap_or(0), prs.b.degree().unwrap_or(0));
            if da % 2 == 1 && db % 2 == 1 {
                negate = !negate;
            }
            prs.step();
            match prs.b.degree() {
                None => return C::zero(),
                Some(0) => {
                    // h ← lc(b)^deg a / h^(deg a − 1)
                    let da = prs.a.degree().unwrap_or(0);
                    let r = exact(prs.b.leading().pow(da), &prs.h.pow(da - 1));
                    return if negate { r.neg() } else { r };
                }
                Some(_) => {}
            }
        }
    }

    /// The discriminant `(−1)^(n(n−1)/2) res(p, p′) / lc(p)`: zero iff `p` has a repeated
    /// root (over an algebraic closure). Degree 0 and the zero polynomial give zero... except
    /// that a nonzero constant has discriminant one by convention; degree 1 gives one.
    ///
    /// ```
    /// # use qsic_algebra::Poly;
    /// // disc(a x² + b x + c) = b² − 4ac
    /// assert_eq!(Poly::from_i64s(&[3, 5, 2]).discriminant(), (25 - 24).into());
    /// assert_eq!(Poly::from_roots(&[1, 1, 4]).discriminant(), 0.into());
    /// ```
    pub fn discriminant(&self) -> C {
        let Some(n) = self.degree() else {
            return C::zero();
        };
        if n == 0 {
            return C::one();
        }
        let r = self
            .resultant(&self.derivative())
            .div_exact(&self.leading())
            .expect("lc(p) divides res(p, p′)");
        if (n * (n - 1) / 2) % 2 == 1 {
            r.neg()
        } else {
            r
        }
    }

    /// A gcd of `self` and `other` in `Frac(C)[x]`, scaled into `C[x]`: the last nonzero
    /// polynomial of the subresultant PRS. It is a gcd up to a nonzero factor of `C`;
    /// `gcd_domain(0, 0) = 0`, and a constant when the two are coprime.
    pub fn gcd_domain(&self, other: &Self) -> Self {
        self.gcd_domain_within(other, |_, _| 0, &Budget::unlimited())
            .expect("an unlimited budget is never spent")
    }

    /// [`Self::gcd_domain`] spending `step_units(a, b)` on `budget` before each step of the
    /// remainder sequence on the pair `(a, b)` (the caller prices a pseudo-remainder by the
    /// sizes of its coefficients).
    ///
    /// # Errors
    /// [`Exhausted`] when the budget runs out.
    pub fn gcd_domain_within(
        &self,
        other: &Self,
        step_units: impl Fn(&Self, &Self) -> u64,
        budget: &Budget,
    ) -> Result<Self, Exhausted> {
        let (a, b) = match (self.degree(), other.degree()) {
            (None, _) => return Ok(other.clone()),
            (_, None) => return Ok(self.clone()),
            (Some(m), Some(n)) if m >= n => (self.clone(), other.clone()),
            _ => (other.clone(), self.clone()),
        };
        let mut prs = Prs::new(a, b);
        while prs.b.degree().unwrap_or(0) > 0 {
            budget.spend(step_units(&prs.a, &prs.b))?;
            prs.step();
            if prs.b.is_zero() {
                return Ok(prs.a);
            }
        }
        Ok(prs.b)
    }

    /// The `j`-th subresultant `S_j(self, other)` (module docs), for
    /// `j ≤ min(deg self, deg other)`; the order of the arguments is the caller's (for
    /// `deg self < deg other` the rows of `other` come second all the same).
    ///
    /// # Panics
    /// If either polynomial is zero or `j > min(deg self, deg other)`.
    pub fn subresultant(&self, other: &Self, j: usize) -> Self {
        let m = self.degree().expect("subresultant of the zero polynomial");
        let n = other.degree().expect("subresultant of the zero polynomial");
        assert!(j <= m.min(n), "subresultant index {j} above min({m}, {n})");
        let rows = m + n - 2 * j;
        if rows == 0 {
            // j = m = n: S_j is defined as the second polynomial's... both sizes zero;
            // by convention S_n = b for m = n (BPR 4.2) — return `other`.
            return other.clone();
        }
        let width = m + n - j; // columns: x^(m+n−j−1) … x^0
        let mut sylvester: Vec<Vec<C>> = Vec::with_capacity(rows);
        // row of x^s·p, highest degree first over `width` columns
        let push_rows = |p: &Self, count: usize, out: &mut Vec<Vec<C>>| {
            for s in (0..count).rev() {
                let mut row = vec![C::zero(); width];
                for (i, v) in p.c.iter().enumerate() {
                    row[width - 1 - (i + s)] = v.clone();
                }
                out.push(row);
            }
        };
        push_rows(self, n - j, &mut sylvester);
        push_rows(other, m - j, &mut sylvester);
        let lead_cols = rows - 1;
        let coeffs = (0..=j)
            .map(|k| {
                let column = width - 1 - k;
                let square: Vec<Vec<C>> = sylvester
                    .iter()
                    .map(|row| {
                        let mut r: Vec<C> = row[..lead_cols].to_vec();
                        r.push(row[column].clone());
                        r
                    })
                    .collect();
                det_bareiss(square)
            })
            .collect();
        Poly::new(coeffs)
    }

    /// The principal subresultant coefficients `psc_j(self, other)`, `j = 0 … min(m, n)`:
    /// `psc_0` is the resultant and `deg gcd` is the least `j` with `psc_j ≠ 0`.
    ///
    /// # Panics
    /// If either polynomial is zero.
    pub fn principal_subresultant_coefficients(&self, other: &Self) -> Vec<C> {
        let m = self.degree().expect("psc of the zero polynomial");
        let n = other.degree().expect("psc of the zero polynomial");
        (0..=m.min(n))
            .map(|j| self.subresultant(other, j).coeff(j))
            .collect()
    }
}

/// The subresultant pseudo-remainder sequence (Collins; Brown–Traub): the state `(a, b)` with
/// `deg a ≥ deg b` and the running scalars `g`, `h` that keep every division exact.
struct Prs<C> {
    a: Poly<C>,
    b: Poly<C>,
    g: C,
    h: C,
}

impl<C: Ring> Prs<C> {
    fn new(a: Poly<C>, b: Poly<C>) -> Self {
        Prs {
            a,
            b,
            g: C::one(),
            h: C::one(),
        }
    }

    /// `(a, b) ← (b, prem(a, b) / (g·h^δ))`, `g ← lc(b)`, `h ← g^δ / h^(δ−1)`, with
    /// `δ = deg a − deg b` (`b` nonzero).
    fn step(&mut self) {
        let delta = self.a.degree().unwrap_or(0) - self.b.degree().unwrap_or(0);
        let r = self.a.pseudo_rem(&self.b);
        let divisor = self.g.mul(&self.h.pow(delta));
        let next = Poly::new(r.c.iter().map(|v| exact(v.clone(), &divisor)).collect());
        self.a = std::mem::replace(&mut self.b, next);
        self.g = self.a.leading();
        if delta > 0 {
            self.h = exact(self.g.pow(delta), &self.h.pow(delta - 1));
        }
    }
}

/// A division the subresultant theory proves exact.
fn exact<C: Ring>(v: C, d: &C) -> C {
    v.div_exact(d).expect("subresultant PRS divides exactly")
}

#[cfg(test)]
mod tests {
    use super::*;
    use dashu_int::IBig;
    use dashu_ratio::RBig;
    use proptest::prelude::*;

    fn z(v: i64) -> IBig {
        IBig::from(v)
    }

    /// `∏ (x − rᵢ)` over ℤ[t] with roots given as polynomials in t.
    fn from_poly_roots(roots: &[Poly]) -> Poly<Poly> {
        roots.iter().fold(Poly::<Poly>::one(), |acc, r| {
            &acc * &Poly::new(vec![-r, Poly::one()])
        })
    }

    #[test]
    fn resultant_from_known_roots() {
        // res(lc_a ∏(x − aᵢ), lc_b ∏(x − bⱼ)) = lc_a^n lc_b^m ∏ (aᵢ − bⱼ)
        let cases: &[(&[i64], i64, &[i64], i64)] = &[
            (&[1, 2], 1, &[3], 1),
            (&[1, -2, 5], 3, &[0, 4], -2),
            (&[7], 2, &[1, 2, 3, 4], 5),
            (&[1, 1, 2], 1, &[3, 3], 1),
            (&[2, 3], 1, &[3], 1),
        ];
        for &(ra, la, rb, lb) in cases {
            let a = Poly::from_roots(ra).scale(&z(la));
            let b = Poly::from_roots(rb).scale(&z(lb));
            let mut expect = z(la).pow(rb.len()) * z(lb).pow(ra.len());
            for x in ra {
                for y in rb {
                    expect *= z(x - y);
                }
            }
            assert_eq!(a.resultant(&b), expect, "{ra:?} {rb:?}");
            let sign = if ra.len() * rb.len() % 2 == 1 { -1 } else { 1 };
            assert_eq!(b.resultant(&a), expect * z(sign), "swapped {ra:?} {rb:?}");
            assert_eq!(a.subresultant(&b, 0).coeff(0), a.resultant(&b));
        }
        let c = Poly::constant(z(3));
        assert_eq!(Poly::from_roots(&[1, 2]).resultant(&c), z(9));
        assert_eq!(Poly::<IBig>::zero().resultant(&c), z(0));
    }

    #[test]
    fn discriminant_from_known_roots() {
        // disc(lc ∏(x − rᵢ)) = lc^(2n−2) ∏_{i<j} (rᵢ − rⱼ)²
        let cases: &[(&[i64], i64)] = &[
            (&[1, 2], 1),
            (&[0, 3, -4], 2),
            (&[1, 2, 3, 5], -3),
            (&[2, 2, 7], 1),
            (&[6], 4),
        ];
        for &(r, lc) in cases {
            let p = Poly::from_roots(r).scale(&z(lc));
            let n = r.len();
            let mut expect = z(lc).pow(2 * n - 2);
            for i in 0..n {
                for j in i + 1..n {
                    expect *= z(r[i] - r[j]).pow(2);
                }
            }
            assert_eq!(p.discriminant(), expect, "{r:?} lc {lc}");
        }
        assert_eq!(Poly::constant(z(5)).discriminant(), z(1));
        assert_eq!(Poly::<IBig>::zero().discriminant(), z(0));
    }

    #[test]
    fn resultant_over_polynomials_in_t_matches_evaluation() {
        // a = (x − t)(x − t² − 1), b = (x + 2t)(x − 3): res = ∏ (aᵢ − bⱼ), a polynomial in t
        let t = Poly::from_i64s(&[0, 1]);
        let ra = [t.clone(), Poly::from_i64s(&[1, 0, 1])];
        let rb = [Poly::from_i64s(&[0, -2]), Poly::from_i64s(&[3])];
        let a = from_poly_roots(&ra);
        let b = from_poly_roots(&rb);
        let mut expect = Poly::one();
        for x in &ra {
            for y in &rb {
                expect = &expect * &(x - y);
            }
        }
        let res = a.resultant(&b);
        assert_eq!(res, expect);
        // evaluation at many t commutes with the resultant
        for tv in -6..7 {
            let at = |p: &Poly<Poly>| p.map(|c| c.eval(&z(tv)));
            assert_eq!(at(&a).resultant(&at(&b)), res.eval(&z(tv)), "t = {tv}");
        }
        // the discriminant in x vanishes exactly where two roots meet: t = t² + 1 never
        // (over ℝ), −2t = 3 at t = −3/2, t = 3 …
        let d = a.discriminant();
        let expect_d = (&ra[0] - &ra[1]).pow(2);
        assert_eq!(d, expect_d);
    }

    #[test]
    fn gcd_degree_from_principal_subresultants() {
        let cases: &[(&[i64], &[i64], usize)] = &[
            (&[1, 2, 3], &[2, 3, 5], 2),
            (&[1, 2, 3, 4], &[5, 6], 0),
            (&[1, 1, 2], &[1, 1, 3], 2),
            (&[1, 2, 3, 4], &[1, 2, 3], 3),
        ];
        for &(ra, rb, g) in cases {
            let (a, b) = (Poly::from_roots(ra), Poly::from_roots(rb));
            let psc = a.principal_subresultant_coefficients(&b);
            let least = psc.iter().position(|v| !v.is_zero()).unwrap();
            assert_eq!(least, g, "{ra:?} {rb:?}");
            let gd = a.gcd_domain(&b);
            assert_eq!(gd.degree(), Some(g));
            assert_eq!(gd.primitive_part(), a.gcd(&b), "{ra:?} {rb:?}");
            // S_g is a gcd too
            assert_eq!(a.subresultant(&b, g).primitive_part(), a.gcd(&b));
        }
    }

    #[test]
    fn gcd_domain_over_polynomials_in_t() {
        // common factor (x − t) over ℤ[t]
        let t = Poly::from_i64s(&[0, 1]);
        let a = from_poly_roots(&[t.clone(), Poly::from_i64s(&[2])]);
        let b = from_poly_roots(&[t.clone(), Poly::from_i64s(&[0, 0, 1])]);
        let g = a.gcd_domain(&b);
        assert_eq!(g.degree(), Some(1));
        // g ∝ x − t: g(t) = 0
        let at_t = g.eval(&t);
        assert!(at_t.is_zero(), "{g}");
        assert_eq!(a.resultant(&b), Poly::zero());
    }

    proptest! {
        #[test]
        fn resultant_prs_equals_sylvester_determinant(
            a in prop::collection::vec(-20i64..20, 1..7),
            b in prop::collection::vec(-20i64..20, 1..6),
        ) {
            let (a, b) = (Poly::from_i64s(&a), Poly::from_i64s(&b));
            prop_assume!(!a.is_zero() && !b.is_zero());
            let (m, n) = (a.degree().unwrap(), b.degree().unwrap());
            prop_assume!(m + n > 0);
            let syl = a.subresultant(&b, 0).coeff(0);
            prop_assert_eq!(a.resultant(&b), syl.clone());
            // over ℚ the same numbers
            let (qa, qb) = (a.to_rational(), b.to_rational());
            prop_assert_eq!(qa.resultant(&qb), RBig::from(syl));
            // zero iff a common factor
            prop_assert_eq!(a.resultant(&b).is_zero(), a.gcd(&b).degree().unwrap_or(0) > 0);
        }
    }
}
