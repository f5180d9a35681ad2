//! Binary forms `F(λ, μ)` of a known degree, so that a root at `λ = ∞` (`μ = 0`) is an
//! ordinary root: stored as the chart `F(λ, 1)` plus the degree `d`; the multiplicity of
//! `(1 : 0)` is `d − deg F(λ, 1)`.

use super::Poly;
use crate::algebraic::AlgebraicReal;
use crate::budget::{Budget, Exhausted};
use crate::roots::isolate_squarefree_real_roots_within;
use dashu_int::IBig;
use std::borrow::Cow;

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
    ///
    /// The factors of the square-free decomposition (and `μ` for a root at ∞) have their
    /// roots isolated together by [`BinaryForm::real_roots_of_coprime`].
    ///
    /// ```
    /// # use qsic_algebra::{Poly, poly::binary::{BinaryForm, ProjectivePoint}};
    /// // (λ² − 2μ²)² μ: ±√2 twice each, ∞ once
    /// let f = BinaryForm::new(&Poly::from_i64s(&[-2, 0, 1]) * &Poly::from_i64s(&[-2, 0, 1]), 5);
    /// let m: Vec<usize> = f.real_roots().iter().map(|(_, m)| *m).collect();
    /// assert_eq!(m, [2, 2, 1]);
    /// assert_eq!(f.real_roots()[2].0, ProjectivePoint::Infinity);
    /// ```
    pub fn real_roots(&self) -> Vec<(ProjectivePoint, usize)> {
        if self.is_zero() {
            return Vec::new();
        }
        let (mut forms, mut multiplicities): (Vec<BinaryForm>, Vec<usize>) = self
            .chart
            .squarefree_decomposition()
            .into_iter()
            .map(|(f, m)| {
                let d = f.degree().unwrap_or(0);
                (BinaryForm::new(f, d), m)
            })
            .unzip();
        let inf = self.multiplicity_at_infinity();
        if inf > 0 {
            forms.push(BinaryForm::new(Poly::constant(IBig::ONE), 1)); // μ
            multiplicities.push(inf);
        }
        BinaryForm::real_roots_of_coprime(&forms)
            .into_iter()
            .map(|(point, j)| (point, multiplicities[j]))
            .collect()
    }

    /// The distinct real roots of nonzero, square-free, pairwise coprime forms, each with
    /// the index in `forms` of the form it is a root of: finite roots in increasing order,
    /// then `(1 : 0)` if one of the forms vanishes there.
    ///
    /// The finite roots are isolated once, from the product of the charts, which is
    /// square-free: their isolating intervals are pairwise disjoint (so a rational lies
    /// between consecutive ones, [`rational_between`](crate::roots::rational_between)), and
    /// no two roots are ever compared. Each root then goes to the one chart that vanishes
    /// on its interval (an exact root) or changes sign across it.
    ///
    /// # Panics
    /// If the forms are not square-free and pairwise coprime (a caller bug).
    ///
    /// ```
    /// # use qsic_algebra::{Poly, RBig, poly::binary::{BinaryForm, ProjectivePoint}};
    /// // λ² − 2μ² and (λ − μ)μ: −√2, 1, √2 and ∞
    /// let forms = [BinaryForm::new(Poly::from_i64s(&[-2, 0, 1]), 2), BinaryForm::new(Poly::from_roots(&[1]), 2)];
    /// let roots = BinaryForm::real_roots_of_coprime(&forms);
    /// let owners: Vec<usize> = roots.iter().map(|(_, j)| *j).collect();
    /// assert_eq!(owners, [0, 1, 0, 1]);
    /// assert_eq!(roots[3].0, ProjectivePoint::Infinity);
    /// let ProjectivePoint::Finite(one) = &roots[1].0 else { panic!("a finite root") };
    /// assert_eq!(one.as_rational(), Some(&RBig::ONE));
    /// ```
    pub fn real_roots_of_coprime(forms: &[BinaryForm]) -> Vec<(ProjectivePoint, usize)> {
        BinaryForm::real_roots_of_coprime_within(forms, &Budget::unlimited())
            .expect("an unlimited budget is never spent")
    }

    /// [`BinaryForm::real_roots_of_coprime`] spending `budget` on the isolation
    /// ([`crate::roots::isolate_squarefree_real_roots_within`]).
    ///
    /// # Errors
    /// [`Exhausted`] when the budget runs out.
    pub fn real_roots_of_coprime_within(
        forms: &[BinaryForm],
        budget: &Budget,
    ) -> Result<Vec<(ProjectivePoint, usize)>, Exhausted> {
        debug_assert!(
            forms.iter().all(|f| !f.is_zero())
                && forms
                    .iter()
                    .map(BinaryForm::multiplicity_at_infinity)
                    .sum::<usize>()
                    <= 1,
            "real_roots_of_coprime: a zero form, or (1 : 0) a multiple or shared root"
        );
        // Forms with a constant chart have no finite root and take no part.
        let charts: Vec<(usize, &Poly)> = forms
            .iter()
            .map(|f| &f.chart)
            .enumerate()
            .filter(|(_, c)| c.degree().unwrap_or(0) > 0)
            .collect();
        let product = match charts.split_first() {
            None => Cow::Owned(Poly::constant(IBig::ONE)),
            Some((&(_, first), rest)) => rest
                .iter()
                .fold(Cow::Borrowed(first), |acc, &(_, c)| Cow::Owned(&*acc * c)),
        };
        let mut roots: Vec<(ProjectivePoint, usize)> =
            isolate_squarefree_real_roots_within(&product, budget)?
                .iter()
                .map(|iv| {
                    charts
                        .iter()
                        .find_map(|&(j, chart)| {
                            let r = AlgebraicReal::from_isolating_interval(chart, iv)?;
                            debug_assert!(r.is_valid(), "{r:?} of {chart}");
                            Some((ProjectivePoint::Finite(r), j))
                        })
                        .expect("a root of the square-free product is a root of one chart")
                })
                .collect();
        if let Some(j) = forms.iter().position(|f| f.multiplicity_at_infinity() > 0) {
            roots.push((ProjectivePoint::Infinity, j));
        }
        Ok(roots)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use dashu_ratio::RBig;
    use proptest::prelude::*;

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

    /// Forms with known roots: rational roots `(p, q)` and irreducible quadratics
    /// `x² − k` (k not a square) or `x² + k`; the form owning ∞ gets one degree more.
    fn form(rationals: &[(i64, i64)], quadratic: Option<i64>, at_infinity: bool) -> BinaryForm {
        let mut chart = Poly::from_rational_roots(rationals);
        if let Some(k) = quadratic {
            chart = &chart * &Poly::from_i64s(&[-k, 0, 1]);
        }
        let d = chart.degree().unwrap_or(0) + usize::from(at_infinity);
        BinaryForm::new(chart, d)
    }

    proptest! {
        /// The roots isolated together are those of each form isolated alone, merged in
        /// increasing order (an independent route: comparisons of algebraic numbers), with ∞
        /// last and owned by the form of higher degree than its chart.
        #[test]
        fn coprime_forms_together_as_one_by_one(
            numerators in prop::collection::btree_set(-30i64..30, 0..7),
            denominators in prop::collection::vec(1i64..5, 7),
            owners in prop::collection::vec(0usize..3, 7),
            quadratic in prop::sample::select(vec![2i64, 3, 5, -1, -7]),
            infinity_owner in 0usize..4,
        ) {
            // n/d may repeat a value (1/2 and 2/4): one root per value, so the forms stay
            // square-free and coprime
            let mut seen = std::collections::BTreeSet::new();
            let mut rationals: [Vec<(i64, i64)>; 3] = Default::default();
            for ((n, d), j) in numerators.iter().zip(&denominators).zip(&owners) {
                if seen.insert(RBig::from_parts_signed((*n).into(), (*d).into())) {
                    rationals[*j].push((*n, *d));
                }
            }
            let forms: Vec<BinaryForm> = (0..3)
                .map(|j| form(&rationals[j], (j == 0).then_some(quadratic), infinity_owner == j))
                .collect();
            let together = BinaryForm::real_roots_of_coprime(&forms);
            let mut alone: Vec<(AlgebraicReal, usize)> = Vec::new();
            for (j, f) in forms.iter().enumerate() {
                if f.chart().degree().unwrap_or(0) > 0 {
                    alone.extend(AlgebraicReal::real_roots_of(f.chart()).into_iter().map(|r| (r, j)));
                }
            }
            alone.sort_by(|a, b| a.0.cmp(&b.0));
            let mut expected: Vec<(ProjectivePoint, usize)> =
                alone.into_iter().map(|(r, j)| (ProjectivePoint::Finite(r), j)).collect();
            if infinity_owner < 3 {
                expected.push((ProjectivePoint::Infinity, infinity_owner));
            }
            prop_assert_eq!(together.len(), expected.len());
            for ((p, j), (q, k)) in together.iter().zip(&expected) {
                prop_assert_eq!(j, k);
                prop_assert_eq!(p, q);
            }
            // the isolating intervals are disjoint and in increasing order
            let intervals: Vec<_> = together
                .iter()
                .filter_map(|(p, _)| match p {
                    ProjectivePoint::Finite(r) => Some(r.interval()),
                    ProjectivePoint::Infinity => None,
                })
                .collect();
            for w in intervals.windows(2) {
                prop_assert!(w[0].hi() <= w[1].lo() && w[0].lo() < w[1].lo());
            }
        }
    }

    /// `real_roots` counts every root of a form with its multiplicity, ∞ included.
    #[test]
    fn real_roots_with_multiplicities_add_up() {
        // (λ + 1)³ (λ² − 3μ²)² μ² · (λ² + μ²): degree 11, real multiplicities 3 + 2 + 2 + 2
        let chart = &(&Poly::from_roots(&[-1, -1, -1]) * &Poly::from_i64s(&[-3, 0, 1]))
            * &(&Poly::from_i64s(&[-3, 0, 1]) * &Poly::from_i64s(&[1, 0, 1]));
        let f = BinaryForm::new(chart, 11);
        let r = f.real_roots();
        let multiplicities: Vec<usize> = r.iter().map(|(_, m)| *m).collect();
        assert_eq!(multiplicities, [2, 3, 2, 2]);
        assert_eq!(r[3].0, ProjectivePoint::Infinity);
        let ProjectivePoint::Finite(minus_one) = &r[1].0 else {
            panic!("a finite root")
        };
        assert_eq!(minus_one.as_rational(), Some(&RBig::from(-1)));
        assert!(BinaryForm::new(Poly::zero(), 3).real_roots().is_empty());
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
