//! Exact signs.

use dashu_int::IBig;
use dashu_ratio::RBig;
use std::ops::{Mul, Neg};

/// The sign of an exact quantity.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Sign {
    /// Below zero.
    Negative,
    /// Exactly zero.
    Zero,
    /// Above zero.
    Positive,
}

impl Sign {
    /// The sign of an integer.
    pub fn of(v: &IBig) -> Sign {
        if v.is_zero() {
            Sign::Zero
        } else if *v < IBig::ZERO {
            Sign::Negative
        } else {
            Sign::Positive
        }
    }

    /// The sign of a rational.
    pub fn of_rational(v: &RBig) -> Sign {
        Sign::of(v.numerator())
    }

    /// The sign of a machine integer.
    pub fn of_i128(v: i128) -> Sign {
        match v.cmp(&0) {
            std::cmp::Ordering::Less => Sign::Negative,
            std::cmp::Ordering::Equal => Sign::Zero,
            std::cmp::Ordering::Greater => Sign::Positive,
        }
    }

    /// `true` for [`Sign::Zero`].
    pub fn is_zero(self) -> bool {
        self == Sign::Zero
    }
}

/// The number of sign changes in a sequence, zeros skipped (Descartes, Sturm, Tarski).
pub fn count_variations(signs: impl IntoIterator<Item = Sign>) -> usize {
    let mut last = Sign::Zero;
    let mut v = 0;
    for s in signs.into_iter().filter(|s| !s.is_zero()) {
        if !last.is_zero() && s != last {
            v += 1;
        }
        last = s;
    }
    v
}

impl Neg for Sign {
    type Output = Sign;
    fn neg(self) -> Sign {
        match self {
            Sign::Negative => Sign::Positive,
            Sign::Zero => Sign::Zero,
            Sign::Positive => Sign::Negative,
        }
    }
}

impl Mul for Sign {
    type Output = Sign;
    fn mul(self, rhs: Sign) -> Sign {
        match (self, rhs) {
            (Sign::Zero, _) | (_, Sign::Zero) => Sign::Zero,
            (a, b) if a == b => Sign::Positive,
            _ => Sign::Negative,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use Sign::{Negative as N, Positive as P, Zero as Z};

    /// The product of signs is the sign of the product, on all nine pairs.
    #[test]
    fn sign_of_a_product() {
        for (a, b) in [
            (-2i128, -3i128),
            (-2, 0),
            (-2, 3),
            (0, -3),
            (0, 0),
            (0, 3),
            (2, -3),
            (2, 0),
            (2, 3),
        ] {
            assert_eq!(
                Sign::of_i128(a) * Sign::of_i128(b),
                Sign::of_i128(a * b),
                "{a} · {b}"
            );
            assert_eq!(-Sign::of_i128(a), Sign::of_i128(-a));
        }
        assert_eq!(count_variations([P, Z, N, N, Z, P]), 2);
        assert_eq!(Sign::of(&IBig::from(-5)), N);
        assert_eq!(Sign::of(&IBig::ZERO), Z);
    }
}
