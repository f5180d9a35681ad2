//! Dense univariate polynomials over a [`Ring`]: `Poly<C>`, with `Poly = Poly<IBig>` (ℤ\[x\]).
//!
//! | entry point | does |
//! |---|---|
//! | [`Poly`] arithmetic | `+ − ×` over any ring, exact division, pseudo-remainder, derivative, evaluation, Taylor shift |
//! | [`subresultant`] | subresultant sequence, resultant, discriminant, gcd over any domain (ℤ\[t\]\[λ\] included) |
//! | [`field`] | division with remainder, monic gcd, extended gcd, square-free decomposition over a field |
//! | [`Poly::gcd`] | ℤ\[x\]: gcd by the subresultant pseudo-remainder sequence ([`gcd`]) |
//! | [`Poly::squarefree_decomposition`] | ℤ\[x\]: Yun's algorithm ([`squarefree`]) |
//! | [`Poly::count_real_roots_sturm`], [`Poly::count_roots_in_descartes`] | ℤ\[x\]: root counts ([`sturm`], [`descartes`]) |
//! | [`Poly::sign_at`] | ℤ\[x\]: exact sign at a rational |
//! | [`binary::BinaryForm`] | binary forms: roots at `λ = ∞` are ordinary roots |
//!
//! Over ℤ, rational polynomials are handled as a primitive integer polynomial times a
//! positive content: every question answered there (roots, signs up to a positive factor,
//! gcds) is invariant under that scaling. The integer type keeps its own fast paths
//! (in-place arithmetic, modular coprimality); the generic algorithms are for the other rings.

pub mod binary;
pub mod descartes;
pub mod field;
pub mod gcd;
pub mod squarefree;
pub mod sturm;
pub mod subresultant;

use crate::ring::Ring;
use crate::sign::Sign;
use dashu_int::IBig;
use dashu_ratio::RBig;
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};

/// A polynomial `c₀ + c₁x + … + cₙxⁿ` with coefficients in the ring `C` (integers by default).
///
/// Invariant: no trailing zero coefficient (the zero polynomial has none at all).
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct Poly<C = IBig> {
    c: Vec<C>,
}

impl<C: Ring> Poly<C> {
    /// Builds a polynomial from coefficients, lowest degree first.
    pub fn new(mut c: Vec<C>) -> Self {
        while c.last().is_some_and(|v| v.is_zero()) {
            c.pop();
        }
        Poly { c }
    }

    /// The polynomial with coefficients `c` (constant first) when the caller knows that
    /// the last one is not zero (or `c` is empty): [`Poly::new`] without its zero test,
    /// which is costly in some rings (an interval evaluation in a number field). Checked in
    /// debug builds.
    ///
    /// ```
    /// # use qsic_algebra::{IBig, Poly};
    /// let p = Poly::from_trimmed(vec![IBig::from(1), IBig::from(2)]);
    /// assert_eq!(p, Poly::from_i64s(&[1, 2]));
    /// ```
    pub fn from_trimmed(c: Vec<C>) -> Self {
        debug_assert!(
            c.last().is_none_or(|v| !v.is_zero()),
            "a zero leading coefficient"
        );
        Poly { c }
    }

    /// The zero polynomial.
    pub fn zero() -> Self {
        Poly { c: Vec::new() }
    }

    /// The constant `v`.
    pub fn constant(v: C) -> Self {
        Poly::new(vec![v])
    }

    /// The polynomial `x`.
    pub fn x() -> Self {
        Poly {
            c: vec![C::zero(), C::one()],
        }
    }

    /// The degree, `None` for the zero polynomial.
    pub fn degree(&self) -> Option<usize> {
        self.c.len().checked_sub(1)
    }

    /// `true` for the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.c.is_empty()
    }

    /// `true` for a constant, zero included (degree ≤ 0).
    pub fn is_constant(&self) -> bool {
        self.c.len() <= 1
    }

    /// Coefficients, lowest degree first.
    pub fn coeffs(&self) -> &[C] {
        &self.c
    }

    /// The coefficients, lowest degree first, by value.
    pub fn into_coeffs(self) -> Vec<C> {
        self.c
    }

    /// The coefficient of `xⁱ` (zero beyond the degree).
    pub fn coeff(&self, i: usize) -> C {
        self.c.get(i).cloned().unwrap_or_else(C::zero)
    }

    /// The leading coefficient (zero for the zero polynomial).
    pub fn leading(&self) -> C {
        self.c.last().cloned().unwrap_or_else(C::zero)
    }

    /// Multiplies every coefficient by `k`.
    pub fn scale(&self, k: &C) -> Self {
        Poly::new(self.c.iter().map(|v| v.mul(k)).collect())
    }

    /// Applies a ring map to every coefficient (e.g. ℤ → ℚ, or reduction).
    pub fn map<D: Ring>(&self, f: impl FnMut(&C) -> D) -> Poly<D> {
        Poly::new(self.c.iter().map(f).collect())
    }

    /// The derivative.
    pub fn derivative(&self) -> Self {
        Poly::new(
            self.c
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, v)| v.mul(&C::from_int(&IBig::from(i))))
                .collect(),
        )
    }

    /// The value at `x` (Horner).
    pub fn eval(&self, x: &C) -> C {
        let Some((top, rest)) = self.c.split_last() else {
            return C::zero();
        };
        rest.iter()
            .rev()
            .fold(top.clone(), |acc, v| acc.mul(x).add(v))
    }

    /// The composition `self(q)` (Horner over polynomials).
    pub fn compose(&self, q: &Self) -> Self {
        let Some((top, rest)) = self.c.split_last() else {
            return Poly::zero();
        };
        rest.iter()
            .rev()
            .fold(Poly::constant(top.clone()), |acc, v| {
                &(&acc * q) + &Poly::constant(v.clone())
            })
    }

    /// `xⁿ p(1/x)` with `n = deg p`: reverses the coefficients.
    pub fn reverse(&self) -> Self {
        let mut c = self.c.clone();
        c.reverse();
        Poly::new(c)
    }

    /// `p(x + k)` (Taylor shift), `O(n²)` ring operations.
    pub fn shift(&self, k: &C) -> Self {
        if k.is_zero() {
            return self.clone();
        }
        let mut c = self.c.clone();
        let n = c.len();
        for i in 0..n {
            for j in (i..n.saturating_sub(1)).rev() {
                let t = c[j + 1].mul(k);
                c[j].add_assign(&t);
            }
        }
        Poly::new(c)
    }

    /// The multiplicity of `x` as a factor (number of low zero coefficients).
    pub fn trailing_zeros(&self) -> usize {
        self.c.iter().take_while(|v| v.is_zero()).count()
    }

    /// `self / x^k`, assuming the low `k` coefficients are zero.
    pub fn shift_down(&self, k: usize) -> Self {
        Poly::new(self.c[k.min(self.c.len())..].to_vec())
    }

    /// `self · x^k`.
    pub fn shift_up(&self, k: usize) -> Self {
        if self.is_zero() {
            return Poly::zero();
        }
        let mut c = vec![C::zero(); k];
        c.extend(self.c.iter().cloned());
        Poly { c }
    }

    /// Exact division by a nonzero polynomial: `Some(q)` with `self = q·d`, or `None`
    /// if `d` does not divide `self` in `C[x]` (or `d = 0`).
    pub fn div_exact(&self, d: &Self) -> Option<Self> {
        let dn = d.degree()?;
        if self.is_zero() {
            return Some(Poly::zero());
        }
        let n = self.degree()?;
        if n < dn {
            return None;
        }
        let mut r = self.c.clone();
        let lead = &d.c[dn];
        let mut q = vec![C::zero(); n - dn + 1];
        for k in (0..=n - dn).rev() {
            let top = &r[k + dn];
            if top.is_zero() {
                continue;
            }
            let f = top.div_exact(lead)?;
            for (j, dj) in d.c.iter().enumerate() {
                r[k + j].sub_mul_assign(&f, dj);
            }
            q[k] = f;
        }
        r.iter().all(|v| v.is_zero()).then(|| Poly::new(q))
    }

    /// Pseudo-remainder: `lc(d)^(deg self − deg d + 1) · self mod d`.
    ///
    /// # Panics
    /// If `d` is zero.
    pub fn pseudo_rem(&self, d: &Self) -> Self {
        let dn = d.degree().expect("pseudo_rem by the zero polynomial");
        let Some(n) = self.degree() else {
            return Poly::zero();
        };
        if n < dn {
            return self.clone();
        }
        let lead = &d.c[dn];
        let mut r = self.c.clone();
        for k in (0..=n - dn).rev() {
            let top = r[k + dn].clone();
            for v in r.iter_mut() {
                *v = v.mul(lead);
            }
            if !top.is_zero() {
                for (j, dj) in d.c.iter().enumerate() {
                    r[k + j].sub_mul_assign(&top, dj);
                }
            }
            r.truncate(k + dn);
        }
        Poly::new(r)
    }
}

impl<C: Ring> Ring for Poly<C> {
    fn zero() -> Self {
        Poly::zero()
    }
    fn one() -> Self {
        Poly::constant(C::one())
    }
    fn from_int(v: &IBig) -> Self {
        Poly::constant(C::from_int(v))
    }
    fn is_zero(&self) -> bool {
        self.c.is_empty()
    }
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
    fn div_exact(&self, d: &Self) -> Option<Self> {
        Poly::div_exact(self, d)
    }
}

impl Poly {
    /// Builds a polynomial from machine-integer coefficients, lowest degree first.
    ///
    /// ```
    /// # use qsic_algebra::Poly;
    /// let p = Poly::from_i64s(&[-2, 0, 1]); // x² − 2
    /// assert_eq!(p.degree(), Some(2));
    /// ```
    pub fn from_i64s(c: &[i64]) -> Poly {
        Poly::new(c.iter().map(|&v| IBig::from(v)).collect())
    }

    /// `q·x − p`, the primitive linear polynomial vanishing at the rational `p/q`.
    pub fn vanishing_at(v: &RBig) -> Poly {
        Poly::new(vec![
            -v.numerator().clone(),
            IBig::from(v.denominator().clone()),
        ])
    }

    /// `∏ (x − rᵢ)` for integer roots `rᵢ`.
    pub fn from_roots(roots: &[i64]) -> Poly {
        roots.iter().fold(Poly::constant(IBig::ONE), |acc, &r| {
            &acc * &Poly::from_i64s(&[-r, 1])
        })
    }

    /// `∏ (qᵢx − pᵢ)` for rational roots `pᵢ/qᵢ` given as pairs.
    pub fn from_rational_roots(roots: &[(i64, i64)]) -> Poly {
        roots
            .iter()
            .fold(Poly::constant(IBig::ONE), |acc, &(p, q)| {
                &acc * &Poly::from_i64s(&[-p, q])
            })
    }

    /// The primitive integer polynomial `c·p` (`c > 0` rational) of a rational polynomial,
    /// with the positive scale `c`; zero gives `(0, 1)`.
    pub fn from_rational(p: &Poly<RBig>) -> (Poly, RBig) {
        let mut den = IBig::ONE;
        for v in p.coeffs() {
            let d = IBig::from(v.denominator().clone());
            den = &den / crate::int_gcd(&den, &d) * d;
        }
        let ints = Poly::new(
            p.coeffs()
                .iter()
                .map(|v| v.numerator() * &den / IBig::from(v.denominator().clone()))
                .collect(),
        );
        let g = ints.content();
        if g.is_zero() {
            return (ints, RBig::ONE);
        }
        (ints.map(|v| v / &g), RBig::from_parts_signed(den, g))
    }

    /// The same polynomial over ℚ.
    pub fn to_rational(&self) -> Poly<RBig> {
        self.map(|v| RBig::from(v.clone()))
    }

    /// The gcd of the coefficients, non-negative (zero for the zero polynomial).
    pub fn content(&self) -> IBig {
        let mut g = IBig::ZERO;
        for v in &self.c {
            g = crate::int_gcd(&g, v);
            if g.is_one() {
                break;
            }
        }
        g
    }

    /// The primitive part with a positive leading coefficient (zero stays zero).
    pub fn primitive_part(&self) -> Poly {
        if self.is_zero() {
            return Poly::zero();
        }
        let mut g = self.content();
        if self.leading() < IBig::ZERO {
            g = -g;
        }
        Poly {
            c: self.c.iter().map(|v| v / &g).collect(),
        }
    }

    /// `p(num/den) · den^n` for `den > 0`: the value at a rational, scaled to an integer
    /// of the same sign.
    pub fn eval_homogeneous(&self, num: &IBig, den: &IBig) -> IBig {
        let n = self.c.len();
        if n == 0 {
            return IBig::ZERO;
        }
        // Horner on the homogenised form.
        let mut acc = self.c[n - 1].clone();
        let mut dpow = IBig::ONE;
        for v in self.c[..n - 1].iter().rev() {
            dpow *= den;
            acc = acc * num + v * &dpow;
        }
        acc
    }

    /// The value at an integer (Horner).
    pub fn eval_integer(&self, x: &IBig) -> IBig {
        self.eval(x)
    }

    /// The exact value at a rational.
    pub fn eval_rational(&self, x: &RBig) -> RBig {
        let den = IBig::from(x.denominator().clone());
        let v = self.eval_homogeneous(x.numerator(), &den);
        let n = self.c.len().saturating_sub(1);
        RBig::from_parts_signed(v, den.pow(n))
    }

    /// The exact sign at a rational.
    pub fn sign_at(&self, x: &RBig) -> Sign {
        let den = IBig::from(x.denominator().clone());
        Sign::of(&self.eval_homogeneous(x.numerator(), &den))
    }

    /// The sign of the leading coefficient, i.e. the sign at +∞.
    pub fn sign_at_pos_infinity(&self) -> Sign {
        Sign::of(&self.leading())
    }

    /// The sign at −∞.
    pub fn sign_at_neg_infinity(&self) -> Sign {
        let s = Sign::of(&self.leading());
        if self.degree().unwrap_or(0) % 2 == 1 {
            -s
        } else {
            s
        }
    }

    /// `p(k·x)`.
    pub fn scale_var(&self, k: &IBig) -> Poly {
        let mut pw = IBig::ONE;
        let mut c = Vec::with_capacity(self.c.len());
        for v in &self.c {
            c.push(v * &pw);
            pw *= k;
        }
        Poly::new(c)
    }

    /// `dⁿ p(x/d)`: integer coefficients `cᵢ d^(n−i)`.
    pub fn scale_var_inverse(&self, d: &IBig) -> Poly {
        let n = self.c.len();
        let mut pw = IBig::ONE;
        let mut c = vec![IBig::ZERO; n];
        for i in (0..n).rev() {
            c[i] = &self.c[i] * &pw;
            pw *= d;
        }
        Poly::new(c)
    }

    /// Number of sign changes in the coefficient sequence (zeros skipped).
    pub fn sign_variations(&self) -> usize {
        crate::sign::count_variations(self.c.iter().map(Sign::of))
    }

    /// Largest bit length of a coefficient.
    pub fn max_bits(&self) -> usize {
        use dashu_int::ops::{BitTest, UnsignedAbs};
        self.c
            .iter()
            .map(|v| v.unsigned_abs().bit_len())
            .max()
            .unwrap_or(0)
    }

    /// A float approximation of the value at `x` (for display and plotting only).
    pub fn eval_f64(&self, x: f64) -> f64 {
        self.c
            .iter()
            .rev()
            .fold(0.0, |acc, v| acc * x + v.to_f64().value())
    }
}

impl<C: Ring> fmt::Debug for Poly<C> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Poly({self})")
    }
}

/// Writes `c₀ + c₁x + …` highest degree first; a coefficient whose text is a sum (a
/// polynomial coefficient, an element of an extension) is parenthesised.
impl<C: Ring> fmt::Display for Poly<C> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_zero() {
            return f.write_str("0");
        }
        let mut first = true;
        for (i, v) in self.c.iter().enumerate().rev() {
            if v.is_zero() {
                continue;
            }
            let text = v.to_string();
            let compound = text.chars().skip(1).any(|ch| matches!(ch, ' ' | '+' | '-'));
            let (neg, abs) = match text.strip_prefix('-') {
                Some(rest) if !compound => (true, rest),
                _ => (false, text.as_str()),
            };
            if first {
                if neg {
                    f.write_str("-")?;
                }
            } else {
                f.write_str(if neg { " - " } else { " + " })?;
            }
            first = false;
            let abs = if compound {
                format!("({abs})")
            } else {
                abs.to_string()
            };
            match i {
                0 => f.write_str(&abs)?,
                _ => {
                    if abs != "1" {
                        write!(f, "{abs}*")?;
                    }
                    if i == 1 {
                        f.write_str("x")?;
                    } else {
                        write!(f, "x^{i}")?;
                    }
                }
            }
        }
        Ok(())
    }
}

impl<C: Ring> Add for &Poly<C> {
    type Output = Poly<C>;
    fn add(self, rhs: &Poly<C>) -> Poly<C> {
        let (long, short) = if self.c.len() >= rhs.c.len() {
            (self, rhs)
        } else {
            (rhs, self)
        };
        let mut c = long.c.clone();
        for (a, b) in c.iter_mut().zip(&short.c) {
            a.add_assign(b);
        }
        Poly::new(c)
    }
}

impl<C: Ring> Sub for &Poly<C> {
    type Output = Poly<C>;
    fn sub(self, rhs: &Poly<C>) -> Poly<C> {
        self + &(-rhs)
    }
}

impl<C: Ring> Neg for &Poly<C> {
    type Output = Poly<C>;
    fn neg(self) -> Poly<C> {
        Poly {
            c: self.c.iter().map(|v| v.neg()).collect(),
        }
    }
}

impl<C: Ring> Mul for &Poly<C> {
    type Output = Poly<C>;
    fn mul(self, rhs: &Poly<C>) -> Poly<C> {
        if self.is_zero() || rhs.is_zero() {
            return Poly::zero();
        }
        let mut c = vec![C::zero(); self.c.len() + rhs.c.len() - 1];
        for (i, a) in self.c.iter().enumerate() {
            if a.is_zero() {
                continue;
            }
            for (j, b) in rhs.c.iter().enumerate() {
                c[i + j].add_mul_assign(a, b);
            }
        }
        Poly::new(c)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_and_exact_division() {
        let p = Poly::from_roots(&[1, 2, -3]);
        let q = Poly::from_roots(&[2]);
        let r = p.div_exact(&q).expect("x-2 divides");
        assert_eq!(r, Poly::from_roots(&[1, -3]));
        assert!(p.div_exact(&Poly::from_roots(&[5])).is_none());
        assert!(Poly::from_i64s(&[1, 2])
            .div_exact(&Poly::from_i64s(&[0, 2]))
            .is_none());
        assert_eq!(&(&p - &p), &Poly::zero());
    }

    #[test]
    fn evaluation_and_signs() {
        let p = Poly::from_rational_roots(&[(1, 3), (-2, 5)]); // (3x−1)(5x+2)
        assert_eq!(
            p.sign_at(&RBig::from_parts_signed(IBig::from(1), IBig::from(3))),
            Sign::Zero
        );
        assert_eq!(p.sign_at(&RBig::ZERO), Sign::Negative);
        assert_eq!(p.sign_at(&RBig::from(7)), Sign::Positive);
        assert_eq!(p.eval_rational(&RBig::from(1)), RBig::from(14));
        assert_eq!(
            Poly::from_i64s(&[0, 0, 0, -1]).sign_at_neg_infinity(),
            Sign::Positive
        );
    }

    #[test]
    fn shifts_and_scalings_compose() {
        let p = Poly::from_i64s(&[3, -1, 4, 1, -5]);
        let k = IBig::from(3);
        let shifted = p.shift(&k);
        for x in -3..4 {
            assert_eq!(
                shifted.eval_rational(&RBig::from(x)),
                p.eval_rational(&RBig::from(x + 3))
            );
        }
        let scaled = p.scale_var_inverse(&IBig::from(2));
        // 2⁴ p(x/2) at x = 1 is 16 p(1/2)
        assert_eq!(
            RBig::from(scaled.eval_rational(&RBig::from(1)).numerator().clone()),
            p.eval_rational(&RBig::from_parts_signed(IBig::ONE, IBig::from(2))) * RBig::from(16)
        );
        assert_eq!(p.reverse().reverse(), p);
    }

    #[test]
    fn pseudo_remainder_identity() {
        let a = Poly::from_i64s(&[5, -3, 0, 2, 7]);
        let b = Poly::from_i64s(&[1, 0, 3]);
        let r = a.pseudo_rem(&b);
        assert!(r.degree().unwrap_or(0) < 2);
        // lc(b)^3 a − r is divisible by b
        let lhs = &a.scale(&IBig::from(27)) - &r;
        assert!(lhs.div_exact(&b).is_some());
    }

    #[test]
    fn content_and_primitive_part() {
        let p = Poly::from_i64s(&[6, -12, -18]);
        assert_eq!(p.content(), IBig::from(6));
        assert_eq!(p.primitive_part(), Poly::from_i64s(&[-1, 2, 3]));
    }

    #[test]
    fn rational_to_primitive_integer_and_back() {
        let q = Poly::from_i64s(&[3, -6, 9])
            .to_rational()
            .scale(&RBig::from_parts_signed(IBig::from(-5), IBig::from(4)));
        let (p, c) = Poly::from_rational(&q);
        assert_eq!(p, Poly::from_i64s(&[-1, 2, -3]));
        assert_eq!(q.scale(&c), p.to_rational());
        assert_eq!(c, RBig::from_parts_signed(IBig::from(4), IBig::from(15)));
        assert_eq!(
            Poly::from_rational(&Poly::zero()),
            (Poly::zero(), RBig::ONE)
        );
    }

    #[test]
    fn display_parenthesises_compound_coefficients() {
        let t = Poly::from_i64s(&[1, -1]); // 1 − t, written "-x + 1"
        let p: Poly<Poly> = Poly::new(vec![Poly::from_i64s(&[-2]), t, Poly::from_i64s(&[1])]);
        assert_eq!(p.to_string(), "x^2 + (-x + 1)*x - 2");
        assert_eq!(Poly::from_i64s(&[0, -1]).to_string(), "-x");
        assert_eq!(format!("{:?}", Poly::<IBig>::zero()), "Poly(0)");
    }

    /// Random polynomials over ℤ[t] (coefficients small polynomials in t), ℚ(√5) and ℤ.
    mod ring_properties {
        use super::*;
        use crate::field::Quadratic;
        use crate::ring::Ring;
        use proptest::prelude::*;

        fn int_poly() -> impl Strategy<Value = Poly> {
            prop::collection::vec(-9i64..9, 0..5).prop_map(|c| Poly::from_i64s(&c))
        }

        fn poly_in_t() -> impl Strategy<Value = Poly<Poly>> {
            prop::collection::vec(int_poly(), 0..4).prop_map(Poly::new)
        }

        fn quadratic_poly() -> impl Strategy<Value = Poly<Quadratic>> {
            prop::collection::vec((-9i64..9, -9i64..9), 0..4).prop_map(|c| {
                Poly::new(
                    c.into_iter()
                        .map(|(a, b)| {
                            Quadratic::new(RBig::from(a), RBig::from(b), IBig::from(5)).unwrap()
                        })
                        .collect(),
                )
            })
        }

        /// Ring axioms, evaluation as a homomorphism, Taylor shift as composition with
        /// `x + k`, exact division undoing a product, pseudo-remainder identity.
        fn check<C: Ring>(
            a: &Poly<C>,
            b: &Poly<C>,
            c: &Poly<C>,
            x: &C,
        ) -> Result<(), TestCaseError> {
            prop_assert_eq!(&(a + b) + c, a + &(b + c));
            prop_assert_eq!(&(a * b) * c, a * &(b * c));
            prop_assert_eq!(a * &(b + c), &(a * b) + &(a * c));
            prop_assert_eq!(a * b, b * a);
            prop_assert!((&(a + b) - b) == *a);
            prop_assert_eq!((a * b).eval(x), a.eval(x).mul(&b.eval(x)));
            prop_assert_eq!((a + b).eval(x), a.eval(x).add(&b.eval(x)));
            let shift = Poly::new(vec![x.clone(), C::one()]);
            prop_assert_eq!(a.shift(x), a.compose(&shift));
            prop_assert_eq!(a.derivative().eval(x), {
                // d/dx (a) at x from the Taylor shift: coefficient 1 of a(x + X)
                a.shift(x).coeff(1)
            });
            if !b.is_zero() {
                prop_assert_eq!((a * b).div_exact(b), Some(a.clone()));
                let r = a.pseudo_rem(b);
                prop_assert!(r.degree() < b.degree() || r.is_zero());
                let k = a.degree().unwrap_or(0).saturating_sub(b.degree().unwrap()) + 1;
                let lc = b
                    .leading()
                    .pow(if a.degree() >= b.degree() { k } else { 0 });
                prop_assert!((&a.scale(&lc) - &r).div_exact(b).is_some());
            }
            Ok(())
        }

        proptest! {
            #[test]
            fn over_the_integers(a in int_poly(), b in int_poly(), c in int_poly(), x in -5i64..5) {
                check(&a, &b, &c, &IBig::from(x))?;
            }

            #[test]
            fn over_polynomials_in_t(a in poly_in_t(), b in poly_in_t(), c in poly_in_t(), x in int_poly()) {
                check(&a, &b, &c, &x)?;
            }

            #[test]
            fn over_a_quadratic_field(a in quadratic_poly(), b in quadratic_poly(), c in quadratic_poly(), x in (-4i64..4, -4i64..4)) {
                let x = Quadratic::new(RBig::from(x.0), RBig::from(x.1), IBig::from(5)).unwrap();
                check(&a, &b, &c, &x)?;
            }
        }
    }
}
