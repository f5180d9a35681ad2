//! ℚ(√δ): numbers `a + b√δ` with `a, b` rational and `δ` a non-square integer.

use crate::ring::{Field, Ring};
use crate::sign::Sign;
use dashu_int::IBig;
use dashu_ratio::RBig;
use std::fmt;

/// An element `a + b√δ` of ℚ(√δ).
///
/// Invariant: `b = 0 ⇔ δ = 0` (rationals carry no radicand, so that equality is structural);
/// otherwise `δ` is an integer that is not a square. Elements with different radicands live
/// in different fields and are not combined (the operations panic, see [`Quadratic::add`]);
/// rationals combine with every radicand. The radicand is kept as given: √8 and 2√2 are
/// different fields here, so reduce `δ` to its square-free part where it matters.
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct Quadratic {
    a: RBig,
    b: RBig,
    d: IBig,
}

impl Quadratic {
    /// The rational `a`.
    pub fn rational(a: RBig) -> Quadratic {
        Quadratic {
            a,
            b: RBig::ZERO,
            d: IBig::ZERO,
        }
    }

    /// `a + b√δ`; `None` if `b ≠ 0` and `δ` is a square (the value is then rational: use
    /// [`Quadratic::sqrt`] to get it).
    pub fn new(a: RBig, b: RBig, delta: IBig) -> Option<Quadratic> {
        if b.is_zero() {
            return Some(Quadratic::rational(a));
        }
        (!is_square(&delta)).then_some(Quadratic { a, b, d: delta })
    }

    /// `a + b√δ` with `δ` the radicand of `x` (`a` when `x` is rational, `δ = 0`): no
    /// square test, `δ` being the radicand of an element already.
    ///
    /// ```
    /// # use qsic_algebra::{field::Quadratic, IBig, RBig};
    /// let r2 = Quadratic::sqrt(&IBig::from(2));
    /// let x = Quadratic::in_field_of(RBig::from(3), RBig::from(-2), &r2);
    /// assert_eq!(Some(x), Quadratic::new(RBig::from(3), RBig::from(-2), IBig::from(2)));
    /// ```
    pub fn in_field_of(a: RBig, b: RBig, x: &Quadratic) -> Quadratic {
        if x.d.is_zero() {
            return Quadratic::rational(a);
        }
        Quadratic::from_parts(a, b, x.d.clone())
    }

    /// `√δ` for an integer `δ`: rational when `δ` is a perfect square (`√−4` is not real:
    /// `2√−1`, in ℚ(√−1)).
    ///
    /// ```
    /// # use qsic_algebra::{field::Quadratic, IBig, RBig};
    /// assert_eq!(Quadratic::sqrt(&IBig::from(9)), Quadratic::rational(RBig::from(3)));
    /// let r = Quadratic::sqrt(&IBig::from(2));
    /// assert_eq!(r.clone() * r, Quadratic::rational(RBig::from(2)));
    /// ```
    pub fn sqrt(delta: &IBig) -> Quadratic {
        if is_square(delta) {
            return Quadratic::rational(RBig::from(isqrt(delta)));
        }
        Quadratic {
            a: RBig::ZERO,
            b: RBig::ONE,
            d: delta.clone(),
        }
    }

    /// `√q` for a rational `q = p/r`: `√(p·r)/r`.
    pub fn sqrt_rational(q: &RBig) -> Quadratic {
        let den = IBig::from(q.denominator().clone());
        let s = Quadratic::sqrt(&(q.numerator() * &den));
        s.scale(&RBig::from_parts_signed(IBig::ONE, den))
    }

    /// The rational part `a`.
    pub fn rational_part(&self) -> &RBig {
        &self.a
    }

    /// The coefficient `b` of `√δ`.
    pub fn radical_part(&self) -> &RBig {
        &self.b
    }

    /// The radicand `δ` (zero for a rational).
    pub fn radicand(&self) -> &IBig {
        &self.d
    }

    /// The value if it is rational.
    pub fn as_rational(&self) -> Option<&RBig> {
        self.b.is_zero().then_some(&self.a)
    }

    /// `true` if the number is real (`δ > 0` or rational).
    pub fn is_real(&self) -> bool {
        self.d >= IBig::ZERO
    }

    /// The conjugate `a − b√δ`.
    pub fn conjugate(&self) -> Quadratic {
        Quadratic {
            a: self.a.clone(),
            b: -&self.b,
            d: self.d.clone(),
        }
    }

    /// The norm `a² − δb²` (rational; zero only for zero).
    pub fn norm(&self) -> RBig {
        &self.a * &self.a - RBig::from(self.d.clone()) * &self.b * &self.b
    }

    /// `k · self` for a rational `k`.
    pub fn scale(&self, k: &RBig) -> Quadratic {
        Quadratic::from_parts(&self.a * k, &self.b * k, self.d.clone())
    }

    /// The exact sign of a real element, `None` for a non-real one (`δ < 0`, `b ≠ 0`).
    ///
    /// ```
    /// # use qsic_algebra::{field::Quadratic, IBig, RBig, Sign};
    /// // 3 − 2√2 > 0, 2 − 3√2/2 < 0
    /// let r2 = Quadratic::sqrt(&IBig::from(2));
    /// let x = Quadratic::rational(RBig::from(3)) - r2.scale(&RBig::from(2));
    /// assert_eq!(x.sign(), Some(Sign::Positive));
    /// ```
    pub fn sign(&self) -> Option<Sign> {
        let (sa, sb) = (Sign::of_rational(&self.a), Sign::of_rational(&self.b));
        if sb == Sign::Zero {
            return Some(sa);
        }
        if self.d < IBig::ZERO {
            return None;
        }
        if sa == Sign::Zero || sa == sb {
            return Some(sb);
        }
        // opposite signs: compare a² with b²δ (never equal: δ is not a square)
        Some(if self.norm() > RBig::ZERO { sa } else { sb })
    }

    /// A float approximation (display and plotting only); NaN for a non-real element.
    pub fn to_f64(&self) -> f64 {
        let a = self.a.to_f64().value();
        if self.b.is_zero() {
            return a;
        }
        a + self.b.to_f64().value() * self.d.to_f64().value().sqrt()
    }

    fn from_parts(a: RBig, b: RBig, d: IBig) -> Quadratic {
        if b.is_zero() {
            Quadratic::rational(a)
        } else {
            Quadratic { a, b, d }
        }
    }

    /// The common radicand of two operands.
    ///
    /// # Panics
    /// If both are irrational with different radicands.
    fn common_radicand(&self, o: &Quadratic) -> IBig {
        match (self.d.is_zero(), o.d.is_zero()) {
            (true, _) => o.d.clone(),
            (_, true) => self.d.clone(),
            _ => {
                assert_eq!(
                    self.d, o.d,
                    "elements of ℚ(√{}) and ℚ(√{}) combined",
                    self.d, o.d
                );
                self.d.clone()
            }
        }
    }
}

/// `true` if `v` is the square of an integer (negative numbers are not).
fn is_square(v: &IBig) -> bool {
    if let Ok(small) = u64::try_from(v) {
        // the float root is within one of ⌊√v⌋ (v < 2⁶⁴): the candidates around it, exactly
        let r = (small as f64).sqrt() as u128;
        let v = u128::from(small);
        return (r.saturating_sub(1)..=r + 1).any(|c| c * c == v);
    }
    *v >= IBig::ZERO && {
        let r = isqrt(v);
        &r * &r == *v
    }
}

/// `⌊√v⌋` for `v ≥ 0`, zero for negative `v`.
fn isqrt(v: &IBig) -> IBig {
    use dashu_int::ops::{SquareRoot, UnsignedAbs};
    if *v <= IBig::ZERO {
        return IBig::ZERO;
    }
    IBig::from(v.unsigned_abs().sqrt())
}

impl Ring for Quadratic {
    fn zero() -> Self {
        Quadratic::rational(RBig::ZERO)
    }
    fn one() -> Self {
        Quadratic::rational(RBig::ONE)
    }
    fn from_int(v: &IBig) -> Self {
        Quadratic::rational(RBig::from(v.clone()))
    }
    fn is_zero(&self) -> bool {
        self.a.is_zero() && self.b.is_zero()
    }
    /// # Panics
    /// If both operands are irrational with different radicands (all binary operations).
    fn add(&self, o: &Self) -> Self {
        let d = self.common_radicand(o);
        Quadratic::from_parts(&self.a + &o.a, &self.b + &o.b, d)
    }
    fn sub(&self, o: &Self) -> Self {
        let d = self.common_radicand(o);
        Quadratic::from_parts(&self.a - &o.a, &self.b - &o.b, d)
    }
    fn mul(&self, o: &Self) -> Self {
        let d = self.common_radicand(o);
        let dd = RBig::from(d.clone());
        Quadratic::from_parts(
            &self.a * &o.a + &self.b * &o.b * dd,
            &self.a * &o.b + &self.b * &o.a,
            d,
        )
    }
    fn neg(&self) -> Self {
        Quadratic {
            a: -&self.a,
            b: -&self.b,
            d: self.d.clone(),
        }
    }
    fn div_exact(&self, d: &Self) -> Option<Self> {
        Field::div(self, d)
    }
}

impl Field for Quadratic {
    fn inv(&self) -> Option<Self> {
        if self.is_zero() {
            return None;
        }
        let n = self.norm();
        Some(Quadratic::from_parts(
            &self.a / &n,
            -&self.b / &n,
            self.d.clone(),
        ))
    }
}

macro_rules! forward_op {
    ($tr:ident, $m:ident) => {
        impl std::ops::$tr for Quadratic {
            type Output = Quadratic;
            fn $m(self, rhs: Quadratic) -> Quadratic {
                Ring::$m(&self, &rhs)
            }
        }
        impl std::ops::$tr for &Quadratic {
            type Output = Quadratic;
            fn $m(self, rhs: &Quadratic) -> Quadratic {
                Ring::$m(self, rhs)
            }
        }
    };
}
forward_op!(Add, add);
forward_op!(Sub, sub);
forward_op!(Mul, mul);

impl std::ops::Neg for Quadratic {
    type Output = Quadratic;
    fn neg(self) -> Quadratic {
        Ring::neg(&self)
    }
}

impl fmt::Display for Quadratic {
    /// `a + b*sqrt(δ)` (`sqrt(δ)` alone for `b = 1`, the rational `a` alone for `b = 0`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.b.is_zero() {
            return write!(f, "{}", self.a);
        }
        let neg = self.b < RBig::ZERO;
        let babs = if neg { -&self.b } else { self.b.clone() };
        let radical = if babs.is_one() {
            format!("sqrt({})", self.d)
        } else {
            format!("{babs}*sqrt({})", self.d)
        };
        match (self.a.is_zero(), neg) {
            (true, false) => f.write_str(&radical),
            (true, true) => write!(f, "-{radical}"),
            (false, false) => write!(f, "{} + {radical}", self.a),
            (false, true) => write!(f, "{} - {radical}", self.a),
        }
    }
}

impl fmt::Debug for Quadratic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Quadratic({self})")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::Poly;
    use proptest::prelude::*;

    fn r(n: i64, d: i64) -> RBig {
        RBig::from_parts_signed(IBig::from(n), IBig::from(d))
    }

    fn elem(a: (i64, i64), b: (i64, i64), d: i64) -> Quadratic {
        Quadratic::new(r(a.0, a.1), r(b.0, b.1), IBig::from(d)).unwrap()
    }

    /// The machine-word test of `is_square` agrees with `⌊√v⌋²` on big integers: squares and
    /// their neighbours up to `2⁶⁴` and past it, and random values.
    #[test]
    fn is_square_matches_the_integer_root() {
        let by_root = |v: &IBig| *v >= IBig::ZERO && &isqrt(v) * &isqrt(v) == *v;
        let mut values: Vec<IBig> = vec![IBig::ZERO, IBig::ONE, IBig::from(-4)];
        for k in [
            2u128,
            3,
            1 << 20,
            (1 << 26) + 1,
            (1 << 32) - 1,
            1 << 32,
            1 << 33,
        ] {
            for d in [-1i128, 0, 1] {
                values.push(IBig::from(k) * IBig::from(k) + IBig::from(d));
            }
        }
        values.push(IBig::from(u64::MAX));
        let mut rng = crate::testing::SplitMix(5);
        for _ in 0..2000 {
            let k = IBig::from(rng.int(0, i64::MAX >> 31));
            values.push(&k * &k + IBig::from(rng.int(-1, 1)));
            values.push(IBig::from(rng.int(0, i64::MAX >> 1)) << 1usize);
        }
        let squares = values.iter().filter(|v| is_square(v)).count();
        assert!(squares > 600, "{squares}");
        for v in &values {
            assert_eq!(is_square(v), by_root(v), "{v}");
        }
    }

    /// [`Quadratic::in_field_of`] equals [`Quadratic::new`] with the radicand of its model.
    #[test]
    fn in_field_of_equals_new() {
        let mut rng = crate::testing::SplitMix(3);
        for delta in [0i64, 2, 3, 7, -5, 1_000_003] {
            let model = Quadratic::sqrt(&IBig::from(delta));
            for _ in 0..50 {
                let (a, b) = (
                    r(rng.int(-999, 999), rng.int(1, 99)),
                    r(rng.int(-3, 3), rng.int(1, 99)),
                );
                let fast = Quadratic::in_field_of(a.clone(), b.clone(), &model);
                let want = if delta == 0 {
                    Quadratic::rational(a)
                } else {
                    Quadratic::new(a, b, IBig::from(delta)).unwrap()
                };
                assert_eq!(fast, want);
            }
        }
    }

    #[test]
    fn squares_and_radicands() {
        assert!(Quadratic::new(RBig::ONE, RBig::ONE, IBig::from(16)).is_none());
        assert_eq!(
            Quadratic::sqrt_rational(&r(9, 4)),
            Quadratic::rational(r(3, 2))
        );
        // √(2/3) = √6/3, squared 2/3
        let s = Quadratic::sqrt_rational(&r(2, 3));
        assert_eq!(s.radicand(), &IBig::from(6));
        assert_eq!(s.clone() * s, Quadratic::rational(r(2, 3)));
        let i = Quadratic::sqrt(&IBig::from(-1));
        assert!(!i.is_real() && i.sign().is_none());
        assert_eq!(i.clone() * i, Quadratic::rational(r(-1, 1)));
        assert_eq!(Quadratic::sqrt(&IBig::ZERO), Quadratic::zero());
        let x = elem((1, 2), (-3, 4), 7);
        assert_eq!(
            (x.rational_part(), x.radical_part(), x.radicand()),
            (&r(1, 2), &r(-3, 4), &IBig::from(7))
        );
    }

    #[test]
    fn golden_ratio_is_a_root_of_its_polynomial() {
        // φ = (1 + √5)/2 is a root of x² − x − 1 (Horner over ℚ(√5))
        let phi = elem((1, 2), (1, 2), 5);
        let p: Poly<Quadratic> = Poly::from_i64s(&[-1, -1, 1]).map(Quadratic::from_int);
        assert!(p.eval(&phi).is_zero());
        assert!(!p.eval(&phi.conjugate().neg()).is_zero());
        assert!(p.eval(&phi.conjugate()).is_zero());
        assert_eq!(phi.to_string(), "1/2 + 1/2*sqrt(5)");
        assert_eq!(p.to_string(), "x^2 - x - 1");
    }

    #[test]
    #[should_panic(expected = "combined")]
    fn different_radicands_do_not_mix() {
        let _ = Quadratic::sqrt(&IBig::from(2)) + Quadratic::sqrt(&IBig::from(3));
    }

    proptest! {
        #[test]
        fn field_identities_and_signs(
            a in (-50i64..50, 1i64..9), b in (-50i64..50, 1i64..9),
            c in (-50i64..50, 1i64..9), e in (-50i64..50, 1i64..9),
            d in prop::sample::select(vec![2i64, 3, 5, 6, 7, 10, 8, 12]),
        ) {
            let x = elem(a, b, d);
            let y = elem(c, e, d);
            // distributivity and inverses
            let s = &x + &y;
            prop_assert_eq!(&s * &x, &(&x * &x) + &(&y * &x));
            if !x.is_zero() {
                prop_assert_eq!(&x * &x.inv().unwrap(), Quadratic::one());
            }
            prop_assert_eq!(x.norm(), (&x * &x.conjugate()).as_rational().unwrap().clone());
            // exact sign against a float with a wide margin, or against the square
            let f = x.to_f64();
            let sign = x.sign().unwrap();
            if f.abs() > 1e-9 {
                prop_assert_eq!(sign, if f > 0.0 { Sign::Positive } else { Sign::Negative });
            }
            prop_assert_eq!(sign == Sign::Zero, x.is_zero());
            // sign of a difference orders the two
            let diff = (&x - &y).sign().unwrap();
            prop_assert_eq!(diff == Sign::Zero, x == y);
        }
    }
}
