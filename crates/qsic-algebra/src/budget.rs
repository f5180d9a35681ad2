//! A work budget: how much a computation may do before it gives up.
//!
//! The caller makes a [`Budget`] and passes it by reference into the computations that can
//! run long; each loop that can (root isolation and refinement, remainder sequences,
//! determinants of long entries, factoring, sampling, the instants of a motion) spends
//! *work units* on it as it goes and stops with [`Exhausted`] once the budget is spent.
//! Nothing is global: two computations with two budgets never see each other, and the
//! same computation with the same budget spends the same units on every machine, so a
//! budget error is deterministic.
//!
//! **The unit.** One unit is about one machine-word operation of the arithmetic, about
//! one instruction: a loop step that works on a polynomial of degree `d` whose
//! coefficients have `ℓ` limbs spends about `(d + 1)·ℓ` ([`poly_step_units`]), a product of
//! an `ℓ`-limb and an `m ≥ ℓ`-limb number `m·⌈√ℓ⌉` ([`product_units`]: the arithmetic
//! multiplies long numbers by Karatsuba's and Toom's methods). The count is an estimate of
//! the work from the sizes, not a measurement: the README gives the units spent per second
//! on this machine kind (a few 10⁹, within a factor of ten across the computations).
//!
//! [`Budget::unlimited`] never runs out; the plain entry points of the library use it.

use std::sync::atomic::{AtomicU64, Ordering};

/// A budget of work units, spent through a shared reference (so one budget may serve
/// several threads; the count is then the sum of their spending).
#[derive(Debug)]
pub struct Budget {
    limit: u64,
    used: AtomicU64,
}

/// The budget ran out: the computation stopped without an answer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Exhausted {
    /// The budget's limit, in work units.
    pub limit: u64,
}

impl std::fmt::Display for Exhausted {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "the work budget of {} units is spent", self.limit)
    }
}

impl std::error::Error for Exhausted {}

impl Budget {
    /// A budget that never runs out.
    pub const fn unlimited() -> Budget {
        Budget::new(u64::MAX)
    }

    /// A budget of `limit` work units.
    pub const fn new(limit: u64) -> Budget {
        Budget {
            limit,
            used: AtomicU64::new(0),
        }
    }

    /// Spends `units`.
    ///
    /// # Errors
    /// [`Exhausted`] once more than the limit has been spent (and on every later call);
    /// never for [`Budget::unlimited`].
    pub fn spend(&self, units: u64) -> Result<(), Exhausted> {
        let before = self.used.fetch_add(units, Ordering::Relaxed);
        if self.limit == u64::MAX {
            // counted for measurement only: 2⁶⁴ units are centuries of work
            return Ok(());
        }
        match before.checked_add(units) {
            Some(after) if after <= self.limit => Ok(()),
            _ => {
                // keep the count saturated, so that a spent budget stays spent
                self.used.store(u64::MAX, Ordering::Relaxed);
                Err(Exhausted { limit: self.limit })
            }
        }
    }

    /// The units spent so far (`u64::MAX` once exhausted).
    pub fn used(&self) -> u64 {
        self.used.load(Ordering::Relaxed)
    }

    /// The limit; `None` for [`Budget::unlimited`].
    pub fn limit(&self) -> Option<u64> {
        (self.limit != u64::MAX).then_some(self.limit)
    }
}

impl Default for Budget {
    fn default() -> Budget {
        Budget::unlimited()
    }
}

/// Limbs (64-bit words) of a number of `bits` bits, at least one.
pub fn limbs(bits: usize) -> u64 {
    (bits as u64).div_ceil(64).max(1)
}

/// The units of one product of an `a`-bit and a `b`-bit number: `m·⌈√ℓ⌉` for `ℓ ≤ m` limbs,
/// the word products of Karatsuba's and Toom's multiplication (between `ℓ^1.46` and `ℓ^1.58`
/// for two `ℓ`-limb numbers) within a small factor.
pub fn product_units(a: usize, b: usize) -> u64 {
    let (l, m) = (limbs(a).min(limbs(b)), limbs(a).max(limbs(b)));
    m.saturating_mul(l.isqrt() + u64::from(l.isqrt() * l.isqrt() < l))
}

/// The units of one step over a polynomial of degree `degree` with coefficients of at most
/// `bits` bits: `(degree + 1)·limbs(bits)`.
pub fn poly_step_units(degree: usize, bits: usize) -> u64 {
    (degree as u64 + 1).saturating_mul(limbs(bits))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_budget_runs_out_after_its_limit_and_stays_out() {
        let b = Budget::new(10);
        assert_eq!(b.spend(4), Ok(()));
        assert_eq!(b.spend(6), Ok(()));
        assert_eq!(b.used(), 10);
        assert_eq!(b.spend(1), Err(Exhausted { limit: 10 }));
        assert_eq!(b.spend(0), Err(Exhausted { limit: 10 }));
        assert_eq!(b.limit(), Some(10));
    }

    #[test]
    fn the_unlimited_budget_never_runs_out() {
        let b = Budget::unlimited();
        for _ in 0..3 {
            assert_eq!(b.spend(u64::MAX / 4), Ok(()));
        }
        assert_eq!(b.used(), u64::MAX / 4 * 3);
        assert_eq!(b.limit(), None);
    }

    #[test]
    fn an_overflowing_count_is_a_spent_budget_not_a_wrapped_one() {
        let b = Budget::new(u64::MAX - 1);
        assert_eq!(b.spend(u64::MAX - 2), Ok(()));
        assert!(b.spend(u64::MAX / 2).is_err());
        assert!(b.spend(0).is_err());
    }

    #[test]
    fn units_grow_with_sizes() {
        assert_eq!(limbs(0), 1);
        assert_eq!(limbs(64), 1);
        assert_eq!(limbs(65), 2);
        assert_eq!(product_units(640, 128), 20);
        assert_eq!(product_units(64, 64), 1);
        assert_eq!(product_units(64 * 1024, 64 * 1024), 1024 * 32);
        assert_eq!(product_units(64 * 1025, 64 * 2000), 2000 * 33);
        assert_eq!(poly_step_units(4, 200), 20);
    }
}
