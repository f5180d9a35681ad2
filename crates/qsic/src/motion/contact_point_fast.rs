//! The accelerator of module `contact_point` at an irrational instant `t = α`: the tangency
//! member without a gcd over `K = ℚ(α)`.
//!
//! # Mathematics
//! Where `f(λ; α) = det(λA(α) − B(α))` has degree 4 and exactly one double root
//! (`psc₀(α) = 0 ≠ S₁[1](α)`, the shape of almost every instant of a motion no one
//! designed), that root is the root of the first subresultant `S₁ = v·λ − u` of `f` and
//! `∂f/∂λ` over `ℤ[t]` (module `irrational_fast`): `λ₀ = u(α)/v(α)`, two reductions into
//! `K` and one inverse, where the reference takes `gcd(f, f′)` over `K` and splits it by
//! the square-free factors of `f` over `ℚ(t)`. The member `λ₀A − B` is then the only
//! tangency member (no root at `λ = ∞`: `det A(α) ≠ 0`), and its kernel is found as the
//! reference finds it. Another shape: `None`, and the caller runs the reference.
//!
//! **Work units**: the zero tests ([`PencilPolys::one_double_root_at`]) and the two
//! reductions into `K` and the inverse as products in `K` ([`Spend::products`]).
//!
//! **Gain** (callgrind, one `qsic contact --batch -` line, against the reference alone):
//! `ellipsoids_translation` 59 M → 40 M, `ellipsoids_screw` 1.05 G → 0.94 G.

use super::irrational::Spend;
use super::irrational_fast::PencilPolys;
use super::MovingPencil;
use qsic_algebra::budget::{Budget, Exhausted};
use qsic_algebra::field::number_field::{NumberField, NumberFieldElement as K};
use qsic_algebra::{AlgebraicReal, Field, Ring};

/// The one double root `λ₀ ∈ K` of `f(λ; α)` (module docs), or `None` where `f(λ; α)` has
/// another shape.
///
/// # Errors
/// [`Exhausted`] when the budget runs out.
pub(super) fn double_root(
    pencil: &MovingPencil,
    alpha: &AlgebraicReal,
    field: &NumberField,
    budget: &Budget,
) -> Result<Option<K>, Exhausted> {
    let polys: &PencilPolys = pencil.fast_polys(budget)?;
    if !polys.one_double_root_at(alpha, budget)? {
        return Ok(None);
    }
    let (u, v) = polys.double_root_fraction();
    let degree = |p: &qsic_algebra::Poly| p.degree().unwrap_or(0);
    // Horner in α over each degree in t, and the inverse (about a degree of products)
    let n = alpha.poly().degree().unwrap_or(0);
    Spend::new(budget, alpha).products(degree(&u) + degree(&v) + 2 + 4 * n)?;
    let (u, v) = (field.integer_element(&u), field.integer_element(&v));
    Ok(v.inv().map(|w| u.mul(&w)))
}
