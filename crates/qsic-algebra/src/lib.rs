//! Exact algebra for qsic, knowing nothing of geometry.
//!
//! | module | owns |
//! |---|---|
//! | [`filter`] | certified floating-point sign filters (error bounds; exact fallback is the caller's) |
//! | [`sign`] | [`Sign`], the result of every exact sign decision |
//! | [`ring`] | the [`Ring`] and [`Field`] traits: algorithms written once for ℤ, ℚ, ℤ\[t\], ℚ(α), … |
//! | [`poly`] | dense univariate polynomials `Poly<C>` over a ring: arithmetic, subresultants, resultants, gcd, square-free decomposition; over ℤ also Sturm and Descartes counts |
//! | [`mpoly`] | sparse multivariate rational polynomials (up to 8 variables): arithmetic, degrees, coefficients in one variable, quadratic forms |
//! | [`roots`] | real root isolation with rational (dyadic) isolating intervals |
//! | [`field`] | exact real extensions of ℚ: ℚ(√δ) ([`field::Quadratic`]), ℚ(α) by dynamic evaluation ([`field::NumberField`]) |
//! | [`budget`] | [`Budget`]: work units spent by the loops that can run long, explicit and deterministic |
//! | [`algebraic`] | real algebraic numbers (refinement shared across calls) and the exact sign of a polynomial at them |
//! | [`linalg`] | matrices over a ring or field: one determinant/minor implementation (expansion for `N ≤ 4`, Bareiss), Gauss–Jordan (rank, kernel, solve, inverse), congruence diagonalization, real points and plane pairs of rational quadratic forms |
//! | [`matrix`] | symmetric 4×4 integer matrices, exact inertia, matrix pencils `λA − μB` over any coefficient ring |
//! | [`factor`] | factorization of integers with a 128-bit cofactor bound, primality, Jacobi symbols, square roots modulo primes |
//! | [`conic`] | rational points on conics: Legendre's theorem, a point or a point over ℚ(√δ), parameterization through a point |
//!
//! Integers are [`dashu_int::IBig`], rationals [`dashu_ratio::RBig`]: pure Rust,
//! small values inline on the stack.

// Index loops read as the matrix formulas they implement.
#![allow(clippy::needless_range_loop)]

pub mod algebraic;
pub mod budget;
pub mod conic;
pub mod factor;
pub mod field;
pub mod filter;
pub mod linalg;
pub mod matrix;
pub mod mpoly;
pub mod poly;
pub mod ring;
pub mod roots;
pub mod sign;
// Test and bench support shared by the crates (not part of the API).
#[doc(hidden)]
pub mod testing;

pub use algebraic::AlgebraicReal;
pub use budget::{Budget, Exhausted};
pub use dashu_int::IBig;
pub use dashu_int::UBig;
pub use dashu_ratio::RBig;
pub use mpoly::MPoly;
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
