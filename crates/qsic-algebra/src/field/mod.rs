//! Exact real algebraic extensions of ℚ as [`Field`](crate::Field)s.
//!
//! | type | field | sign |
//! |---|---|---|
//! | [`Quadratic`] | ℚ(√δ), `δ` a non-square integer: `a + b√δ` | exact, by comparing `a²` with `b²δ` |

pub mod quadratic;

pub use quadratic::Quadratic;
