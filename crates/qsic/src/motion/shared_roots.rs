//! Work shared between the instants that are roots of one polynomial: the zero tests
//! `q(α) = 0` of the classification, and the refinement of `α` charged as it runs.
//!
//! The irrational instants of a motion no one designed are, most of them, the real roots of
//! one factor `p` of the discriminant, and the polynomials tested at them (`psc₀`, the
//! generic condition `G`) are multiples of `p`. A zero test by `gcd(p, q)` costs a remainder
//! sequence on polynomials of degree in the hundreds with coefficients of thousands of bits,
//! per instant; instead [`ZeroTests::is_root`] asks once per pair `(p, q)` whether `p`
//! divides `q` (one exact division: `p` primitive, so by Gauss' lemma over `ℤ`), and only
//! where it does not, `g = gcd(p, q)` (also once per pair), whose sign change across `α`'s
//! isolating interval says whether `α` is one of its roots (`p` square-free: its roots in
//! that interval are `α` alone).

use qsic_algebra::budget::{product_units, Budget, Exhausted};
use qsic_algebra::roots::RootInterval;
use qsic_algebra::Sign;
use qsic_algebra::{AlgebraicReal, IBig, Poly, RBig};
use std::sync::{Arc, Mutex};

/// Divisibility of tested polynomials by defining polynomials, remembered between instants
/// (and between the copies of one motion's polynomials: clones share it).
#[derive(Debug, Default, Clone)]
pub(crate) struct ZeroTests {
    /// `(p, q, g)` for the primitive defining polynomials `p` and the tested `q` seen:
    /// `g = p` where `p | q`, else `gcd(p, q)`.
    known: Arc<Mutex<Vec<(Poly, Poly, Poly)>>>,
}

/// The units of `q / p` by exact division: `(deg q − deg p + 1)(deg p + 1)` products.
fn division_units(q: &Poly, p: &Poly) -> u64 {
    let (n, m) = (q.degree().unwrap_or(0), p.degree().unwrap_or(0));
    ((n.saturating_sub(m) + 1) as u64 * (m + 1) as u64)
        .saturating_mul(product_units(q.max_bits(), p.max_bits()))
}

/// The units of an exact zero test by a gcd (about the product of the sizes).
fn gcd_units(q: &Poly, alpha: &AlgebraicReal) -> u64 {
    let d = alpha.poly().degree().unwrap_or(0) as u64 + 1;
    qsic_algebra::budget::poly_step_units(q.degree().unwrap_or(0), q.max_bits()).saturating_mul(d)
}

impl ZeroTests {
    /// Whether `q(α) = 0`, exactly: `true` at once where `α`'s primitive defining polynomial
    /// `p` divides `q`, else from `g = gcd(p, q)` (both decided once for all the roots of
    /// `p`): `g` is square-free with roots among those of `p`, so `α` is a root of `g` iff
    /// `g` changes sign across `α`'s isolating interval (an end where `g` vanishes: the
    /// exact sign of `q(α)`).
    ///
    /// # Errors
    /// [`Exhausted`] when the budget runs out.
    pub(crate) fn is_root(
        &self,
        alpha: &AlgebraicReal,
        q: &Poly,
        budget: &Budget,
    ) -> Result<bool, Exhausted> {
        if q.is_zero() {
            return Ok(true);
        }
        if let Some(v) = alpha.as_rational() {
            return Ok(q.sign_at(v).is_zero());
        }
        let p = alpha.poly().primitive_part();
        let known = {
            let k = self.known.lock().unwrap_or_else(|e| e.into_inner());
            k.iter()
                .find(|(kp, kq, _)| kp == &p && kq == q)
                .map(|(_, _, g)| g.clone())
        };
        let g = match known {
            Some(g) => g,
            None => {
                budget.spend(division_units(q, &p))?;
                let g = if q.div_exact(&p).is_some() {
                    p.clone()
                } else {
                    budget.spend(gcd_units(q, alpha))?;
                    p.gcd_within(q, budget)?
                };
                self.known.lock().unwrap_or_else(|e| e.into_inner()).push((
                    p.clone(),
                    q.clone(),
                    g.clone(),
                ));
                g
            }
        };
        if g == p {
            return Ok(true);
        }
        if g.degree().unwrap_or(0) == 0 {
            return Ok(false);
        }
        let iv = alpha.interval();
        match g.sign_at(iv.lo()) * g.sign_at(iv.hi()) {
            Sign::Negative => Ok(true),
            Sign::Positive => Ok(false),
            Sign::Zero => Ok(alpha.is_root_of(q)),
        }
    }
}

/// The bits of precision of an open interval: `k` with `width ≤ 2^−k` (0 for a width of at
/// least 1 half).
fn precision_of(iv: &RootInterval) -> usize {
    let w = iv.hi() - iv.lo();
    let (num, den) = (
        dashu_int::ops::BitTest::bit_len(&dashu_int::ops::UnsignedAbs::unsigned_abs(w.numerator())),
        dashu_int::ops::BitTest::bit_len(w.denominator()),
    );
    den.saturating_sub(num + 1)
}

/// `α`'s interval refined to a width of at most `2^−prec`, in rounds whose steps are charged
/// before they run (at most `target − reached` steps a round, each an evaluation of `α`'s polynomial (degree `n`) at a
/// point of about `prec` bits, `n + 1` products of numbers growing to `n·prec` bits). The
/// refinement is `α`'s own (shared by its clones), so a later test starts from it.
///
/// # Errors
/// [`Exhausted`] when the budget runs out.
pub(crate) fn refined_within(
    alpha: &AlgebraicReal,
    prec: usize,
    budget: &Budget,
) -> Result<RootInterval, Exhausted> {
    let width = RBig::from_parts(IBig::ONE, dashu_int::UBig::ONE << prec);
    let p = alpha.poly();
    let n = p.degree().unwrap_or(1);
    let step = (n as u64 + 1).saturating_mul(product_units(p.max_bits() + n * prec, prec));
    // the steps run on α's shared refinement, in rounds that at most double the precision
    // reached, each round's steps charged before it runs
    let mut reached = 0usize;
    loop {
        let iv = alpha.refined_interval(&RBig::ONE);
        if matches!(iv, RootInterval::Exact(_)) || iv.hi() - iv.lo() <= width {
            return Ok(iv);
        }
        let have = precision_of(&iv);
        let target = prec.min((2 * have.max(reached)).max(have + 8));
        reached = target;
        // quadratic refinement doubles the precision a step, bisection adds a bit: charge
        // the bisection count of the round, an upper bound
        budget.spend(step.saturating_mul((target - have) as u64))?;
        alpha.refined_interval(&RBig::from_parts(IBig::ONE, dashu_int::UBig::ONE << target));
    }
}
