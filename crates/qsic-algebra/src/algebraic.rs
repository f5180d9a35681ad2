//! Real algebraic numbers: a square-free integer polynomial and an isolating interval
//! with rational ends, refined on demand. Signs and comparisons are exact.

use crate::poly::Poly;
use crate::roots::{isolate_squarefree_real_roots, refine_step, simplest_between, RootInterval};
use crate::sign::Sign;
use dashu_ratio::RBig;
use std::cmp::Ordering;
use std::fmt;

/// A real algebraic number `α`.
///
/// Invariant ([`AlgebraicReal::is_valid`]): `poly` is square-free, primitive, of positive
/// degree, and either `α` is the rational `interval` end (`RootInterval::Exact`) or
/// `α` is the only root of `poly` in the open interval, whose ends are not roots.
#[derive(Clone)]
pub struct AlgebraicReal {
    poly: Poly,
    interval: RootInterval,
    /// State of the quadratic interval refinement (see [`refine_step`]).
    speed: usize,
}

impl AlgebraicReal {
    /// The rational `v` as an algebraic number.
    pub fn from_rational(v: RBig) -> AlgebraicReal {
        AlgebraicReal {
            poly: Poly::vanishing_at(&v),
            interval: RootInterval::Exact(v),
            speed: 2,
        }
    }

    /// All real roots of `p`, in increasing order, each once.
    pub fn real_roots_of(p: &Poly) -> Vec<AlgebraicReal> {
        let sf = p.squarefree_part();
        if sf.degree() == Some(1) {
            let v = RBig::from_parts_signed(-sf.coeff(0), sf.coeff(1));
            return vec![AlgebraicReal::from_rational(v)];
        }
        isolate_squarefree_real_roots(&sf)
            .into_iter()
            .map(|iv| match iv {
                RootInterval::Exact(v) => AlgebraicReal::from_rational(v),
                iv => AlgebraicReal {
                    poly: sf.clone(),
                    interval: iv,
                    speed: 2,
                },
            })
            .collect()
    }

    /// The root of the square-free `poly` in `interval`, if the interval isolates one: an
    /// exact rational that is a root, or an open interval at whose ends `poly` has opposite
    /// nonzero signs (so exactly one root when `interval` comes from isolating a multiple
    /// of `poly`, as in [`isolate_real_roots`](crate::roots::isolate_real_roots)).
    pub fn from_isolating_interval(poly: &Poly, interval: &RootInterval) -> Option<AlgebraicReal> {
        match interval {
            RootInterval::Exact(v) => poly
                .sign_at(v)
                .is_zero()
                .then(|| AlgebraicReal::from_rational(v.clone())),
            RootInterval::Open(lo, hi) => (poly.sign_at(lo) * poly.sign_at(hi) == Sign::Negative)
                .then(|| AlgebraicReal {
                    poly: poly.clone(),
                    interval: interval.clone(),
                    speed: 2,
                }),
        }
    }

    /// Checks the invariant (used in `debug_assert!`).
    pub fn is_valid(&self) -> bool {
        match &self.interval {
            RootInterval::Exact(v) => self.poly.sign_at(v).is_zero(),
            RootInterval::Open(lo, hi) => {
                lo < hi
                    && self.poly.is_squarefree()
                    && self.poly.sign_at(lo) * self.poly.sign_at(hi) == Sign::Negative
            }
        }
    }

    /// The defining square-free polynomial (for a rational, `q·x − p`).
    pub fn poly(&self) -> &Poly {
        &self.poly
    }

    /// The isolating interval.
    pub fn interval(&self) -> &RootInterval {
        &self.interval
    }

    /// `Some(v)` if the number is known to be the rational `v`.
    pub fn as_rational(&self) -> Option<&RBig> {
        match &self.interval {
            RootInterval::Exact(v) => Some(v),
            RootInterval::Open(..) => None,
        }
    }

    /// Narrows the isolating interval: at least halves it, and squares the rate of
    /// shrinking on success (quadratic interval refinement; exact numbers are left as they are).
    pub fn refine(&mut self) {
        self.interval = refine_step(&self.poly, &self.interval, &mut self.speed);
    }

    /// Refines until the interval is shorter than `width`.
    pub fn refine_to(&mut self, width: &RBig) {
        while let RootInterval::Open(lo, hi) = &self.interval {
            if &(hi - lo) < width {
                break;
            }
            self.refine();
        }
    }

    /// The exact sign of `q(α)`.
    ///
    /// Zero is decided by `gcd(poly, q)` changing sign on the isolating interval; a nonzero
    /// sign by refining until Descartes' rule shows that `q` has no root in the interval.
    /// Works on a copy: `self` keeps its interval.
    ///
    /// ```
    /// # use qsic_algebra::{AlgebraicReal, Poly, Sign};
    /// let sqrt2 = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 1])).pop().unwrap();
    /// assert_eq!(sqrt2.sign_of(&Poly::from_i64s(&[-2, 0, 1])), Sign::Zero);
    /// assert_eq!(sqrt2.sign_of(&Poly::from_rational_roots(&[(1414, 1000)])), Sign::Positive); // x − 1.414
    /// assert_eq!(sqrt2.sign_of(&Poly::from_rational_roots(&[(1415, 1000)])), Sign::Negative);
    /// ```
    pub fn sign_of(&self, q: &Poly) -> Sign {
        let (lo, hi) = match &self.interval {
            RootInterval::Exact(v) => return q.sign_at(v),
            RootInterval::Open(lo, hi) => (lo.clone(), hi.clone()),
        };
        if q.is_zero() {
            return Sign::Zero;
        }
        if q.is_constant() {
            return Sign::of(&q.leading());
        }
        let g = self.poly.gcd(q);
        if g.degree().unwrap_or(0) > 0 && g.sign_at(&lo) * g.sign_at(&hi) == Sign::Negative {
            return Sign::Zero;
        }
        let mut iv = RootInterval::Open(lo, hi);
        let mut speed = self.speed;
        loop {
            match &iv {
                RootInterval::Exact(v) => return q.sign_at(v),
                RootInterval::Open(lo, hi) => {
                    if q.count_roots_in_descartes(lo, hi) == 0 {
                        // no root of q inside; its ends may be roots, the midpoint is not
                        return q.sign_at(&((lo + hi) / RBig::from(2)));
                    }
                }
            }
            iv = refine_step(&self.poly, &iv, &mut speed);
        }
    }

    /// `true` if `α` is a root of `q`.
    pub fn is_root_of(&self, q: &Poly) -> bool {
        self.sign_of(q).is_zero()
    }

    /// The multiplicity of `α` as a root of `q` (0 if it is not a root; `q ≠ 0`).
    pub fn multiplicity_in(&self, q: &Poly) -> usize {
        let mut d = q.clone();
        let mut m = 0;
        while !d.is_zero() && self.is_root_of(&d) {
            m += 1;
            d = d.derivative();
        }
        m
    }

    /// A float approximation (for display only).
    pub fn to_f64(&self) -> f64 {
        let mut a = self.clone();
        a.refine_to(&RBig::from_parts_signed(
            1.into(),
            dashu_int::IBig::ONE << 60,
        ));
        let (lo, hi) = (
            a.interval.lo().to_f64().value(),
            a.interval.hi().to_f64().value(),
        );
        (lo + hi) / 2.0
    }

    /// A rational strictly between `self` and `other` (`self < other` required).
    pub fn rational_between(&self, other: &AlgebraicReal) -> RBig {
        let (mut a, mut b) = (self.clone(), other.clone());
        loop {
            let (ahi, blo) = (a.interval.hi().clone(), b.interval.lo().clone());
            let a_exact = a.as_rational().is_some();
            let b_exact = b.as_rational().is_some();
            if ahi < blo || (ahi == blo && !a_exact && !b_exact) {
                return simplest_between(&ahi, &blo, !a_exact, !b_exact);
            }
            if ahi == blo && a_exact != b_exact {
                // a point strictly inside the open interval next to the exact value
                if !a_exact {
                    a.refine();
                } else {
                    b.refine();
                }
                continue;
            }
            a.refine();
            b.refine();
        }
    }
}

impl PartialEq for AlgebraicReal {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for AlgebraicReal {}

impl PartialOrd for AlgebraicReal {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for AlgebraicReal {
    fn cmp(&self, other: &Self) -> Ordering {
        if let Some(v) = other.as_rational() {
            // sign of α − v = sign of (x − v) at α
            return match self.sign_of(&Poly::vanishing_at(v)) {
                Sign::Negative => Ordering::Less,
                Sign::Zero => Ordering::Equal,
                Sign::Positive => Ordering::Greater,
            };
        }
        if self.as_rational().is_some() {
            return other.cmp(self).reverse();
        }
        if other.is_root_of(&self.poly) {
            // self's interval holds exactly one root of self.poly
            let lo = AlgebraicReal::from_rational(self.interval.lo().clone());
            let hi = AlgebraicReal::from_rational(self.interval.hi().clone());
            if other > &lo && other < &hi {
                return Ordering::Equal;
            }
        }
        let (mut a, mut b) = (self.clone(), other.clone());
        loop {
            if a.interval.hi() <= b.interval.lo() {
                return Ordering::Less;
            }
            if b.interval.hi() <= a.interval.lo() {
                return Ordering::Greater;
            }
            a.refine();
            b.refine();
        }
    }
}

impl fmt::Debug for AlgebraicReal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{self}")
    }
}

impl fmt::Display for AlgebraicReal {
    /// `3/2`, or `root of x^2 - 2 in (1, 3/2)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.interval {
            RootInterval::Exact(v) => write!(f, "{v}"),
            RootInterval::Open(lo, hi) => write!(f, "root of {} in ({lo}, {hi})", self.poly),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An interval isolating a root of a multiple of `poly` gives that root when `poly`
    /// changes sign on it (or vanishes at an exact end), and nothing otherwise.
    #[test]
    fn roots_from_isolating_intervals() {
        let x2m2 = Poly::from_i64s(&[-2, 0, 1]); // roots ±√2
        let other = Poly::from_i64s(&[-3, 1]); // root 3
        let sqrt2 = RootInterval::Open(RBig::ONE, RBig::from(2));
        let r = AlgebraicReal::from_isolating_interval(&x2m2, &sqrt2).expect("√2 in (1, 2)");
        assert_eq!(r.poly(), &x2m2);
        assert_eq!(r.interval(), &sqrt2);
        assert!(AlgebraicReal::from_isolating_interval(&other, &sqrt2).is_none());
        let three = RootInterval::Exact(RBig::from(3));
        assert_eq!(
            AlgebraicReal::from_isolating_interval(&other, &three)
                .and_then(|r| r.as_rational().cloned()),
            Some(RBig::from(3))
        );
        assert!(AlgebraicReal::from_isolating_interval(&x2m2, &three).is_none());
    }

    #[test]
    fn ordering_of_close_irrationals() {
        let s2 = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 1]));
        let s3 = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-3, 0, 1]));
        assert!(s2[1] < s3[1] && s3[0] < s2[0]);
        // √2 from another polynomial: (x² − 2)(x − 5)
        let other = AlgebraicReal::real_roots_of(
            &(&Poly::from_i64s(&[-2, 0, 1]) * &Poly::from_roots(&[5])),
        );
        assert_eq!(other[1], s2[1]);
        assert!(other[1].is_valid());
        let between = s2[1].rational_between(&s3[1]);
        assert!(AlgebraicReal::from_rational(between.clone()) > s2[1]);
        assert!(AlgebraicReal::from_rational(between) < s3[1]);
    }

    /// Regression: the refined interval (1, 2) of √2 had both ends on roots of
    /// q = 2(x − 1)(x − 2), and the sign was read at an end: zero.
    #[test]
    fn sign_with_roots_of_q_on_both_ends() {
        let r = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 1]));
        let q = Poly::from_i64s(&[4, -6, 2]);
        assert_eq!(r[1].sign_of(&q), Sign::Negative);
        assert_eq!(r[0].sign_of(&q), Sign::Positive);
        assert_eq!(
            AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-3, 2]))[0].as_rational(),
            Some(&RBig::from_parts_signed(3.into(), 2.into()))
        );
    }

    #[test]
    fn signs_at_roots_with_common_factors() {
        // α = root of x³ − 2 (real), q = (x³ − 2)(x + 1) vanishes, q' does not
        let p = Poly::from_i64s(&[-2, 0, 0, 1]);
        let a = AlgebraicReal::real_roots_of(&p)
            .pop()
            .expect("one real root");
        let q = &p * &Poly::from_i64s(&[1, 1]);
        assert!(a.is_root_of(&q));
        assert_eq!(a.multiplicity_in(&(&q * &p)), 2);
        // α¹⁹ = 64α ≈ 80.635
        let mut c = vec![0i64; 20];
        c[19] = 1;
        c[0] = -80;
        assert_eq!(a.sign_of(&Poly::from_i64s(&c)), Sign::Positive);
        c[0] = -81;
        assert_eq!(a.sign_of(&Poly::from_i64s(&c)), Sign::Negative);
        assert!((a.to_f64() - 2f64.cbrt()).abs() < 1e-12);
    }
}
