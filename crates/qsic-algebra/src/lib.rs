//! Exact algebra for qsic, knowing nothing of geometry.
//!
//! | module | owns |
//! |---|---|
//! | [`filter`] | certified floating-point sign filters (error bounds; exact fallback is the caller's) |
//! | [`sign`] | [`Sign`], the result of every exact sign decision |
//! | [`ring`] | the [`Ring`] and [`Field`] traits: algorithms written once for ℤ, ℚ, ℤ\[t\], ℚ(α), … |
//! | [`poly`] | dense univariate polynomials `Poly<C>` over a ring: arithmetic, subresultants, resultants, gcd, square-free decomposition; over ℤ also Sturm and Descartes counts |
//! | [`roots`] | real root isolation with rational (dyadic) isolating intervals |
//! | [`field`] | exact real extensions of ℚ: ℚ(√δ) ([`field::Quadratic`]) |
//! | [`algebraic`] | real algebraic numbers and the exact sign of a polynomial at them |
//! | [`linalg`] | matrices over a ring or field: one determinant/minor implementation (expansion for `N ≤ 4`, Bareiss), Gauss–Jordan (rank, kernel, solve, inverse), congruence diagonalization, real points and plane pairs of rational quadratic forms |
//! | [`matrix`] | symmetric 4×4 integer matrices, exact inertia, matrix pencils `λA − μB` over any coefficient ring |
//!
//! Integers are [`dashu_int::IBig`], rationals [`dashu_ratio::RBig`]: pure Rust,
//! small values inline on the stack.

// Index loops read as the matrix formulas they implement.
#![allow(clippy::needless_range_loop)]

pub mod algebraic;
pub mod field;
pub mod filter;
pub mod linalg;
pub mod matrix;
pub mod poly;
pub mod ring;
pub mod roots;
pub mod sign;

pub use algebraic::AlgebraicReal;
pub use dashu_int::IBig;
pub use dashu_ratio::RBig;
pub use poly::Poly;
pub use ring::{Field, RealField, Ring};
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
