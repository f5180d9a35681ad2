//! Certified floating-point sign filters: a float computation with a rigorous error
//! bound decides a sign only when the value is farther from zero than the bound; otherwise
//! the caller falls back to exact arithmetic.
//!
//! Bounds (Higham, *Accuracy and Stability of Numerical Algorithms*, §3.1): with the unit
//! roundoff `u = 2⁻⁵³`, a sum of `m` products of `k` floats, whose inputs are themselves
//! rounded once from exact values, has an absolute error below `γ_{k+m+1} · Σ|termᵢ|`,
//! `γ_n = n·u/(1 − n·u)`. We use `2(k + m + 2)·u·Σ|termᵢ|`, a safe over-estimate for the
//! small `n` here, and refuse to decide when any value is not finite.

use crate::sign::Sign;

const U: f64 = f64::EPSILON / 2.0;

/// The sign of `value`, known to be within `bound` of the exact value; `None` if the bound
/// does not separate it from zero or a value is not finite.
pub fn certified_sign(value: f64, bound: f64) -> Option<Sign> {
    if !value.is_finite() || !bound.is_finite() {
        return None;
    }
    if value > bound {
        Some(Sign::Positive)
    } else if value < -bound {
        Some(Sign::Negative)
    } else {
        None
    }
}

/// Error bound for a sum of `terms` products of `factors` rounded inputs, whose absolute
/// values add up to `magnitude`.
pub fn sum_of_products_bound(factors: usize, terms: usize, magnitude: f64) -> f64 {
    2.0 * (factors + terms + 2) as f64 * U * magnitude
}

/// The certified sign of `p(x) = Σ cᵢ xⁱ` at the float `x` (taken as the exact dyadic
/// rational it is), from coefficients `cᵢ` each rounded once from exact values.
///
/// ```
/// # use qsic_algebra::{filter::certified_sign_poly, Sign};
/// assert_eq!(certified_sign_poly(&[-2.0, 0.0, 1.0], 1.5), Some(Sign::Positive));
/// assert_eq!(certified_sign_poly(&[-1.0, 1.0], 1.0), None); // exactly zero: undecided
/// ```
pub fn certified_sign_poly(c: &[f64], x: f64) -> Option<Sign> {
    let mut acc = 0.0;
    let mut mag = 0.0;
    let ax = x.abs();
    for &ci in c.iter().rev() {
        acc = acc * x + ci;
        mag = mag * ax + ci.abs();
    }
    certified_sign(acc, sum_of_products_bound(c.len(), c.len(), mag))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::Poly;
    use dashu_ratio::RBig;
    use proptest::prelude::*;

    proptest! {
        /// A certified sign is never wrong: compare with the exact sign at the same dyadic point.
        #[test]
        fn certified_signs_are_exact(c in prop::collection::vec(-1_000_000i64..1_000_000, 1..6), num in -4000i64..4000) {
            let x = num as f64 / 64.0;
            let cf: Vec<f64> = c.iter().map(|&v| v as f64).collect();
            if let Some(s) = certified_sign_poly(&cf, x) {
                let exact = Poly::from_i64s(&c).sign_at(&RBig::try_from(x).expect("finite"));
                prop_assert_eq!(s, exact);
            }
        }
    }

    #[test]
    fn refuses_non_finite() {
        assert_eq!(certified_sign(f64::NAN, 0.0), None);
        assert_eq!(certified_sign_poly(&[1.0, f64::INFINITY], 2.0), None);
    }
}
