//! Binary forms `F(λ, μ)` of a known degree, so that a root at `λ = ∞` (`μ = 0`) is an
//! ordinary root: stored as the chart `F(λ, 1)` plus the degree `d`; the multiplicity of
//! `(1 : 0)` is `d − deg F(λ, 1)`.

use super::Poly;
use crate::algebraic::AlgebraicReal;

/// A point of the real projective line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ProjectivePoint {
    /// `(α : 1)`.
    Finite(AlgebraicReal),
    /// `(1 : 0)`.
    Infinity,
}

/// A binary form of degree `degree` (the zero form has every point as a root).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BinaryForm {
    chart: Poly,
    degree: usize,
}

impl BinaryForm {
    /// The form of degree `degree` whose chart `μ = 1` is `chart`.
    ///
    /// # Panics
    /// If `chart` has a degree above `degree` (a caller bug).
    pub fn new(chart: Poly, degree: usize) -> BinaryForm {
        assert!(
            chart.degree().unwrap_or(0) <= degree,
            "chart degree above the form degree"
        );
        BinaryForm { chart, degree }
    }

    /// `F(λ, 1)`.
    pub fn chart(&self) -> &Poly {
        &self.chart
    }

    /// The degree of the form.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// `true` for the zero form.
    pub fn is_zero(&self) -> bool {
        self.chart.is_zero()
    }

    /// Multiplicity of the root `(1 : 0)` (0 if it is not a root; the degree for the zero form).
    pub fn multiplicity_at_infinity(&self) -> usize {
        match self.chart.degree() {
            None => self.degree,
            Some(d) => self.degree - d,
        }
    }

    /// The gcd of two forms (primitive chart): the chart gcd, times `μ` to the smaller
    /// multiplicity at infinity. The gcd with the zero form is the other form.
    ///
    /// ```
    /// # use qsic_algebra::{Poly, poly::binary::BinaryForm};
    /// // λμ² and λ²μ (charts λ and λ², degree 3): gcd λμ
    /// let g = BinaryForm::new(Poly::from_i64s(&[0, 1]), 3).gcd(&BinaryForm::new(Poly::from_i64s(&[0, 0, 1]), 3));
    /// assert_eq!((g.chart().clone(), g.degree(), g.multiplicity_at_infinity()), (Poly::from_i64s(&[0, 1]), 2, 1));
    /// ```
    pub fn gcd(&self, other: &BinaryForm) -> BinaryForm {
        if self.is_zero() {
            return other.clone();
        }
        if other.is_zero() {
            return self.clone();
        }
        let chart = self.chart.gcd(&other.chart);
        let inf = self
            .multiplicity_at_infinity()
            .min(other.multiplicity_at_infinity());
        let degree = chart.degree().unwrap_or(0) + inf;
        BinaryForm { chart, degree }
    }

    /// The distinct real roots with their multiplicities: finite ones in increasing order,
    /// then `(1 : 0)` if it is a root. Empty for the zero form.
    pub fn real_roots(&self) -> Vec<(ProjectivePoint, usize)> {
        if self.is_zero() {
            return Vec::new();
        }
        let mut out: Vec<(ProjectivePoint, usize)> = Vec::new();
        for (f, m) in self.chart.squarefree_decomposition() {
            for r in AlgebraicReal::real_roots_of(&f) {
                out.push((ProjectivePoint::Finite(r), m));
            }
        }
        out.sort_by(|a, b| match (&a.0, &b.0) {
            (ProjectivePoint::Finite(x), ProjectivePoint::Finite(y)) => x.cmp(y),
            _ => std::cmp::Ordering::Equal,
        });
        let inf = self.multiplicity_at_infinity();
        if inf > 0 {
            out.push((ProjectivePoint::Infinity, inf));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use dashu_ratio::RBig;

    #[test]
    fn roots_with_infinity() {
        // (λ − 2μ)² λ μ: chart (λ − 2)² λ, degree 4
        let f = BinaryForm::new(&Poly::from_roots(&[2, 2]) * &Poly::from_i64s(&[0, 1]), 4);
        let r = f.real_roots();
        assert_eq!(r.len(), 3);
        assert_eq!(
            r[0],
            (
                ProjectivePoint::Finite(AlgebraicReal::from_rational(RBig::ZERO)),
                1
            )
        );
        assert_eq!(
            r[1],
            (
                ProjectivePoint::Finite(AlgebraicReal::from_rational(RBig::from(2))),
                2
            )
        );
        assert_eq!(r[2], (ProjectivePoint::Infinity, 1));
        let total: usize = r.iter().map(|(_, m)| m).sum();
        assert_eq!(total, 4);
    }

    #[test]
    fn gcd_keeps_common_infinity() {
        let a = BinaryForm::new(Poly::from_roots(&[1]), 3); // (λ − μ) μ²
        let b = BinaryForm::new(Poly::from_roots(&[1, 5]), 3); // (λ − μ)(λ − 5μ) μ
        let g = a.gcd(&b);
        assert_eq!(g.chart(), &Poly::from_roots(&[1]));
        assert_eq!(g.multiplicity_at_infinity(), 1);
        assert_eq!(g.degree(), 2);
    }
}
