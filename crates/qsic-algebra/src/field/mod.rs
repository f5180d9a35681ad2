//! Exact real algebraic extensions of ℚ as [`Field`](crate::Field)s.
//!
//! | type | field | sign |
//! |---|---|---|
//! | [`Quadratic`] | ℚ(√δ), `δ` a non-square integer: `a + b√δ` | exact, by comparing `a²` with `b²δ` |
//! | [`NumberFieldElement`] in a [`NumberField`] | ℚ(α), `α` a real root of a square-free integer polynomial, by dynamic evaluation (D5) | exact, by interval arithmetic on `α`'s shared refinement, a gcd for zero |

pub mod number_field;
pub mod quadratic;

pub use number_field::{NumberField, NumberFieldElement};
pub use quadratic::Quadratic;
