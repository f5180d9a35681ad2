//! Exact algebra for qsic, knowing nothing of geometry.
//!
//! | module | owns |
//! |---|---|
//! | [`filter`] | certified floating-point sign filters (error bounds; exact fallback is the caller's) |
//! | [`sign`] | [`Sign`], the result of every exact sign decision |
//! | [`poly`] | dense univariate integer polynomials: arithmetic, gcd, square-free decomposition, Sturm and Descartes counts |
//! | [`mpoly`] | sparse multivariate rational polynomials (up to 8 variables): arithmetic, degrees, coefficients in one variable, quadratic forms |
//! | [`roots`] | real root isolation with rational (dyadic) isolating intervals |
//! | [`algebraic`] | real algebraic numbers and the exact sign of a polynomial at them |
//! | [`matrix`] | small symmetric integer matrices, exact inertia, matrix pencils `λA − μB` |
//!
//! Integers are [`dashu_int::IBig`], rationals [`dashu_ratio::RBig`]: pure Rust,
//! small values inline on the stack.

// Index loops read as the matrix formulas they implement.
#![allow(clippy::needless_range_loop)]

pub mod algebraic;
pub mod filter;
pub mod matrix;
pub mod mpoly;
pub mod poly;
pub mod roots;
pub mod sign;

pub use algebraic::AlgebraicReal;
pub use dashu_int::IBig;
pub use dashu_ratio::RBig;
pub use mpoly::MPoly;
pub use poly::Poly;
pub use sign::Sign;

/// The non-negative gcd of two integers, with `gcd(0, v) = |v|` (dashu panics on two zeros).
pub fn int_gcd(a: &IBig, b: &IBig) -> IBig {
    use dashu_int::ops::{Abs, Gcd};
    if a.is_zero() {
        b.clone().abs()
    } else if b.is_zero() {
        a.clone().abs()
    } else {
        IBig::from(a.gcd(b))
    }
}
