//! Rings and fields as types: algorithms are written once over [`Ring`] / [`Field`].
//!
//! | ring | type |
//! |---|---|
//! | ℤ | [`IBig`] |
//! | ℚ | [`RBig`] (a [`Field`]) |
//! | ℤ\[t\], ℤ\[t\]\[λ\], ℚ\[x\], … | [`Poly<C>`](crate::Poly) over any of these |
//! | ℚ(√δ) | [`Quadratic`](crate::field::Quadratic) (a [`Field`]) |
//! | ℚ(α) | [`NumberFieldElement`](crate::field::NumberFieldElement) (a [`Field`], D5 splitting) |
//! | ℤ in machine words | `i128`, for fast paths that bound their inputs (see its impl) |
//!
//! [`RealField`] adds an exact sign (ℚ, real ℚ(√δ); ℚ(α) where α is real).
//!
//! Every ring here is a commutative integral domain of characteristic zero (or, for ℚ(α)
//! with a reducible defining polynomial, is treated as one by dynamic evaluation).
//! The operations are methods rather than `std::ops` bounds so that generic code reads
//! `a.mul(&b)` without higher-ranked bounds on references; concrete code keeps the operators.

use dashu_int::IBig;
use dashu_ratio::RBig;
use std::fmt;

/// A commutative integral domain of characteristic zero.
///
/// Contract: the usual ring axioms; [`Ring::is_zero`] is exact; [`Ring::div_exact`] returns
/// `Some(q)` with `q·d = self` whenever such `q` exists and `d ≠ 0` (it may be `None` otherwise).
pub trait Ring: Clone + PartialEq + fmt::Debug + fmt::Display {
    /// The additive identity.
    fn zero() -> Self;
    /// The multiplicative identity.
    fn one() -> Self;
    /// The image of an integer.
    fn from_int(v: &IBig) -> Self;
    /// `true` for zero, decided exactly.
    fn is_zero(&self) -> bool;
    /// `self + rhs`.
    fn add(&self, rhs: &Self) -> Self;
    /// `self − rhs`.
    fn sub(&self, rhs: &Self) -> Self;
    /// `self · rhs`.
    fn mul(&self, rhs: &Self) -> Self;
    /// `−self`.
    fn neg(&self) -> Self;
    /// Exact division: `Some(q)` with `q·d = self`, `None` if `d` does not divide `self`
    /// (or `d = 0`).
    fn div_exact(&self, d: &Self) -> Option<Self>;

    /// `self += rhs` (override where it can be done in place).
    fn add_assign(&mut self, rhs: &Self) {
        *self = Ring::add(self, rhs);
    }
    /// `self −= a·b` (override where it can be done in place).
    fn sub_mul_assign(&mut self, a: &Self, b: &Self) {
        *self = Ring::sub(self, &Ring::mul(a, b));
    }
    /// `self += a·b` (override where it can be done in place).
    fn add_mul_assign(&mut self, a: &Self, b: &Self) {
        *self = Ring::add(self, &Ring::mul(a, b));
    }
    /// `true` for one.
    fn is_one(&self) -> bool {
        *self == Self::one()
    }
    /// `selfⁿ` by squaring.
    fn pow(&self, mut n: usize) -> Self {
        let (mut base, mut acc) = (self.clone(), Self::one());
        while n > 0 {
            if n & 1 == 1 {
                acc = acc.mul(&base);
            }
            n >>= 1;
            if n > 0 {
                base = base.mul(&base);
            }
        }
        acc
    }
}

/// A field: every nonzero element has an inverse.
pub trait Field: Ring {
    /// `1/self`, `None` for zero.
    fn inv(&self) -> Option<Self>;
    /// `self / d`, `None` for `d = 0`.
    fn div(&self, d: &Self) -> Option<Self> {
        d.inv().map(|i| self.mul(&i))
    }
}

/// An ordered field: a [`Field`] with an exact sign (ℚ, real quadratic fields, real
/// number fields). Inertia and real points need it.
pub trait RealField: Field {
    /// The sign, decided exactly.
    fn sign(&self) -> crate::Sign;
}

/// The arithmetic of a dashu number type through its operators, in place where it can be.
macro_rules! big_number_ops {
    () => {
        fn add(&self, rhs: &Self) -> Self {
            self + rhs
        }
        fn sub(&self, rhs: &Self) -> Self {
            self - rhs
        }
        fn mul(&self, rhs: &Self) -> Self {
            self * rhs
        }
        fn neg(&self) -> Self {
            -self
        }
        fn add_assign(&mut self, rhs: &Self) {
            *self += rhs;
        }
        fn sub_mul_assign(&mut self, a: &Self, b: &Self) {
            *self -= a * b;
        }
        fn add_mul_assign(&mut self, a: &Self, b: &Self) {
            *self += a * b;
        }
    };
}

impl Ring for IBig {
    fn zero() -> Self {
        IBig::ZERO
    }
    fn one() -> Self {
        IBig::ONE
    }
    fn from_int(v: &IBig) -> Self {
        v.clone()
    }
    fn is_zero(&self) -> bool {
        IBig::is_zero(self)
    }
    big_number_ops!();
    fn div_exact(&self, d: &Self) -> Option<Self> {
        if IBig::is_zero(d) {
            return None;
        }
        let (q, r) = dashu_int::ops::DivRem::div_rem(self, d);
        IBig::is_zero(&r).then_some(q)
    }
    fn is_one(&self) -> bool {
        IBig::is_one(self)
    }
    fn pow(&self, n: usize) -> Self {
        IBig::pow(self, n)
    }
}

impl Ring for RBig {
    fn zero() -> Self {
        RBig::ZERO
    }
    fn one() -> Self {
        RBig::ONE
    }
    fn from_int(v: &IBig) -> Self {
        RBig::from(v.clone())
    }
    fn is_zero(&self) -> bool {
        RBig::is_zero(self)
    }
    big_number_ops!();
    fn div_exact(&self, d: &Self) -> Option<Self> {
        (!RBig::is_zero(d)).then(|| self / d)
    }
    fn is_one(&self) -> bool {
        RBig::is_one(self)
    }
}

/// ℤ in a machine word, for fast paths whose inputs are bounded: `+ − ×` are Rust's
/// operators, which panic on overflow in debug builds (tests) and wrap in release builds, so
/// a caller must prove that no intermediate value leaves the `i128` range (the classifier's
/// fast path does, in its module docs). [`Ring::div_exact`] and [`Ring::from_int`] are exact
/// and checked.
///
/// # Panics
/// [`Ring::from_int`] panics on an integer outside the `i128` range.
impl Ring for i128 {
    #[inline]
    fn zero() -> Self {
        0
    }
    #[inline]
    fn one() -> Self {
        1
    }
    #[inline]
    fn from_int(v: &IBig) -> Self {
        i128::try_from(v).expect("an integer in the i128 range")
    }
    #[inline]
    fn is_zero(&self) -> bool {
        *self == 0
    }
    #[inline]
    fn add(&self, rhs: &Self) -> Self {
        self + rhs
    }
    #[inline]
    fn sub(&self, rhs: &Self) -> Self {
        self - rhs
    }
    #[inline]
    fn mul(&self, rhs: &Self) -> Self {
        self * rhs
    }
    #[inline]
    fn neg(&self) -> Self {
        -self
    }
    #[inline]
    fn div_exact(&self, d: &Self) -> Option<Self> {
        // |q·d| ≤ |self|: the check cannot overflow
        self.checked_div(*d).filter(|q| q * d == *self)
    }
    #[inline]
    fn add_assign(&mut self, rhs: &Self) {
        *self += rhs;
    }
    #[inline]
    fn sub_mul_assign(&mut self, a: &Self, b: &Self) {
        *self -= a * b;
    }
    #[inline]
    fn add_mul_assign(&mut self, a: &Self, b: &Self) {
        *self += a * b;
    }
}

impl RealField for RBig {
    fn sign(&self) -> crate::Sign {
        crate::Sign::of_rational(self)
    }
}

/// ℚ(√δ) is ordered for `δ > 0` (√δ the positive root).
///
/// # Panics
/// On an element `a + b√δ` with `b ≠ 0` and `δ < 0` (not real, hence unsigned).
impl RealField for crate::field::Quadratic {
    fn sign(&self) -> crate::Sign {
        crate::field::Quadratic::sign(self).expect("the sign of a real element of Q(sqrt d)")
    }
}

impl Field for RBig {
    fn inv(&self) -> Option<Self> {
        (!RBig::is_zero(self)).then(|| RBig::ONE / self)
    }
    fn div(&self, d: &Self) -> Option<Self> {
        (!RBig::is_zero(d)).then(|| self / d)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integer_exact_division_and_powers() {
        let six = IBig::from(6);
        assert_eq!(six.div_exact(&IBig::from(-3)), Some(IBig::from(-2)));
        assert_eq!(six.div_exact(&IBig::from(4)), None);
        assert_eq!(six.div_exact(&IBig::ZERO), None);
        assert_eq!(Ring::pow(&IBig::from(-2), 5), IBig::from(-32));
        let mut acc = IBig::from(10);
        acc.sub_mul_assign(&IBig::from(3), &IBig::from(4));
        assert_eq!(acc, IBig::from(-2));
        acc.add_mul_assign(&IBig::from(3), &IBig::from(4));
        assert_eq!(acc, IBig::from(10));
    }

    #[test]
    fn default_methods_agree_with_overrides() {
        // The trait's default pow (square and multiply) against repeated products.
        #[derive(Clone, PartialEq, Debug)]
        struct Z(IBig);
        impl fmt::Display for Z {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                self.0.fmt(f)
            }
        }
        impl Ring for Z {
            fn zero() -> Self {
                Z(IBig::ZERO)
            }
            fn one() -> Self {
                Z(IBig::ONE)
            }
            fn from_int(v: &IBig) -> Self {
                Z(v.clone())
            }
            fn is_zero(&self) -> bool {
                self.0.is_zero()
            }
            fn add(&self, r: &Self) -> Self {
                Z(&self.0 + &r.0)
            }
            fn sub(&self, r: &Self) -> Self {
                Z(&self.0 - &r.0)
            }
            fn mul(&self, r: &Self) -> Self {
                Z(&self.0 * &r.0)
            }
            fn neg(&self) -> Self {
                Z(-&self.0)
            }
            fn div_exact(&self, d: &Self) -> Option<Self> {
                Ring::div_exact(&self.0, &d.0).map(Z)
            }
        }
        for n in 0..12 {
            let b = Z(IBig::from(-3));
            let slow = (0..n).fold(Z::one(), |a, _| a.mul(&b));
            assert_eq!(b.pow(n), slow, "n = {n}");
        }
        let mut a = Z(IBig::from(7));
        a.sub_mul_assign(&Z(IBig::from(2)), &Z(IBig::from(5)));
        assert_eq!(a, Z(IBig::from(-3)));
        a.add_assign(&Z(IBig::from(3)));
        assert!(a.is_zero() && !a.is_one() && Z::one().is_one());
    }

    #[test]
    fn machine_integers() {
        assert_eq!(Ring::div_exact(&12i128, &-4), Some(-3));
        assert_eq!(Ring::div_exact(&12i128, &5), None);
        assert_eq!(Ring::div_exact(&12i128, &0), None);
        assert_eq!(Ring::div_exact(&i128::MIN, &-1), None);
        assert_eq!(<i128 as Ring>::from_int(&IBig::from(-7)), -7);
        let mut acc = 10i128;
        acc.sub_mul_assign(&3, &4);
        acc.add_assign(&1);
        assert_eq!(acc, -1);
        acc.add_mul_assign(&2, &5);
        assert_eq!((acc, Ring::pow(&-3i128, 3)), (9, -27));
    }

    #[test]
    fn real_field_signs() {
        use crate::field::Quadratic;
        use crate::Sign;
        let third = RBig::from_parts(IBig::from(-1), 3u8.into());
        assert_eq!(RealField::sign(&third), Sign::Negative);
        assert_eq!(RealField::sign(&RBig::ZERO), Sign::Zero);
        // 1 − √2 < 0
        let x = Quadratic::rational(RBig::ONE) - Quadratic::sqrt(&IBig::from(2));
        assert_eq!(RealField::sign(&x), Sign::Negative);
    }

    #[test]
    fn rational_field() {
        let a = RBig::from_parts(IBig::from(3), 4u8.into());
        assert_eq!(a.inv().unwrap() * &a, RBig::ONE);
        assert_eq!(RBig::ZERO.inv(), None);
        assert_eq!(Field::div(&a, &RBig::ZERO), None);
        assert_eq!(a.div_exact(&a), Some(RBig::ONE));
    }
}
