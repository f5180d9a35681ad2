//! Square-free decomposition (Yun's algorithm): over ℤ here, over a field in [`super::field`],
//! one implementation (`yun`).

use super::Poly;
use crate::budget::{Budget, Exhausted};

impl Poly {
    /// Square-free decomposition `p = c · ∏ fᵢ^mᵢ`: the list of `(fᵢ, mᵢ)`, each `fᵢ`
    /// primitive, square-free, of positive degree and leading coefficient, pairwise coprime,
    /// with increasing multiplicities. Constants give an empty list.
    ///
    /// ```
    /// # use qsic_algebra::Poly;
    /// let p = &Poly::from_roots(&[1, 1, 1, 2]) * &Poly::from_i64s(&[1, 0, 1]);
    /// let d = p.squarefree_decomposition();
    /// assert_eq!(d, vec![(&Poly::from_roots(&[2]) * &Poly::from_i64s(&[1, 0, 1]), 1), (Poly::from_roots(&[1]), 3)]);
    /// ```
    pub fn squarefree_decomposition(&self) -> Vec<(Poly, usize)> {
        if self.degree().unwrap_or(0) == 0 {
            return Vec::new();
        }
        yun(self.primitive_part(), Poly::gcd, exact)
    }

    /// The square-free part: the product of the distinct irreducible factors, primitive.
    pub fn squarefree_part(&self) -> Poly {
        self.squarefree_part_within(&Budget::unlimited())
            .expect("an unlimited budget is never spent")
    }

    /// [`Self::squarefree_part`] spending `budget` on its gcd ([`Poly::gcd_within`]) and
    /// division (one pseudo-remainder's units).
    ///
    /// # Errors
    /// [`Exhausted`] when the budget runs out.
    pub fn squarefree_part_within(&self, budget: &Budget) -> Result<Poly, Exhausted> {
        if self.degree().unwrap_or(0) == 0 {
            return Ok(Poly::constant(dashu_int::IBig::ONE));
        }
        let f = self.primitive_part();
        let g = f.gcd_within(&f.derivative(), budget)?;
        if g.is_constant() {
            return Ok(f);
        }
        budget.spend(super::gcd::prem_units(&f, &g))?;
        Ok(exact(&f, &g).primitive_part())
    }

    /// `true` if the polynomial has no repeated factor (constants are square-free).
    pub fn is_squarefree(&self) -> bool {
        self.gcd(&self.derivative()).degree().unwrap_or(0) == 0
    }
}

/// Yun's algorithm on `f` (degree ≥ 1) with the ring's gcd and exact division: the
/// square-free factors `(aᵢ, i)` of positive degree, increasing `i`; `f` alone when `f` and
/// `f′` are coprime. Shared by ℤ\[x\] (primitive gcds) and fields (monic gcds).
pub(crate) fn yun<C: crate::ring::Ring>(
    f: Poly<C>,
    gcd: impl Fn(&Poly<C>, &Poly<C>) -> Poly<C>,
    div: impl Fn(&Poly<C>, &Poly<C>) -> Poly<C>,
) -> Vec<(Poly<C>, usize)> {
    let df = f.derivative();
    let a0 = gcd(&f, &df);
    if a0.is_constant() {
        return vec![(f, 1)];
    }
    let mut out = Vec::new();
    let mut b = div(&f, &a0);
    let c = div(&df, &a0);
    let mut d = &c - &b.derivative();
    let mut i = 1;
    while b.degree().unwrap_or(0) > 0 {
        let a = gcd(&b, &d);
        let nb = div(&b, &a);
        let nc = div(&d, &a);
        if a.degree().unwrap_or(0) > 0 {
            out.push((a, i));
        }
        d = &nc - &nb.derivative();
        b = nb;
        i += 1;
    }
    out
}

/// Division known to be exact in ℤ\[x\] by Gauss's lemma (the divisor is primitive).
fn exact(a: &Poly, d: &Poly) -> Poly {
    a.div_exact(d)
        .expect("division by a primitive gcd factor is exact (Gauss's lemma)")
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #[test]
        fn decomposition_rebuilds_the_polynomial(roots in prop::collection::vec((-6i64..6, 1i64..4), 1..7), k in 1i64..5) {
            let p = Poly::from_rational_roots(&roots).scale(&dashu_int::IBig::from(k));
            let d = p.squarefree_decomposition();
            let rebuilt = d.iter().fold(Poly::from_i64s(&[1]), |acc, (f, m)| {
                (0..*m).fold(acc, |a, _| &a * f)
            });
            prop_assert_eq!(rebuilt, p.primitive_part());
            for (f, _) in &d {
                prop_assert!(f.is_squarefree());
            }
            // multiplicity of each root equals the number of times it was drawn
            for &(r, q) in &roots {
                let count = roots.iter().filter(|&&(r2, q2)| r2 * q == r * q2).count();
                let m = d.iter().find(|(f, _)| f.div_exact(&Poly::from_i64s(&[-r, q]).primitive_part()).is_some()).map(|(_, m)| *m);
                prop_assert_eq!(m, Some(count));
            }
        }
    }
}
