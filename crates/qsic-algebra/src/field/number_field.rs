//! ℚ(α) for a real algebraic number `α`, by dynamic evaluation (D5): no factoring.
//!
//! `α` is given as an [`AlgebraicReal`]: a root of a square-free integer polynomial `m`,
//! isolated by an interval. An element is `c(α)` for a polynomial `c = C/d` (`C ∈ ℤ[x]`,
//! `d > 0` an integer) reduced modulo the current defining polynomial. `m` need not be
//! irreducible: when an inverse meets a zero divisor, `g = gcd(C, m)` splits `m = g · (m/g)`;
//! the factor that vanishes at `α` is found from the signs of `g` at the ends of `α`'s
//! isolating interval (exact), `m` shrinks to it, and the computation goes on. Every answer
//! is right for `α` without ever knowing its minimal polynomial.
//!
//! | question | how |
//! |---|---|
//! | `c = 0`? ([`Ring::is_zero`]) | `c(α) ≠ 0` if interval arithmetic on `α`'s refined interval excludes zero; else exactly: `c = 0 ⇔ g = gcd(C, m)` vanishes at `α`, and `m` shrinks to `g` or to `m/g` |
//! | `1/c` ([`Field::inv`]) | `S·C ≡ r (mod m)`, `r ∈ ℤ ∖ 0`, by a half-extended primitive remainder sequence over ℤ; when it ends in `g` of positive degree: `None` if `g(α) = 0` (then `m ← g`), else `m ← m/g` and again |
//! | sign of `c(α)` ([`NumberFieldElement::sign`]) | interval arithmetic on the refined interval, else the exact zero test, else refinement |
//!
//! # Design
//! A [`NumberField`] is a cheap handle (`Arc`) to a context holding `α` (whose polynomial is
//! the defining polynomial), behind a `Mutex` held only to read or replace an `Arc` of that
//! state (its degree also in an atomic, read without the lock by
//! [`NumberField::linear_element`]): `Send + Sync`, no global state. The defining polynomial only ever shrinks to a
//! factor of itself that vanishes at `α`, so an element reduced modulo an older multiple stays
//! a valid representative and elements are never touched when the context learns something;
//! two threads that each learn a factor are merged by their gcd (also a factor vanishing at
//! `α`). `α`'s refinement state is shared (see [`crate::algebraic`]): repeated signs in one
//! field refine `α` once. Rational constants carry no context, so [`Ring::zero`],
//! [`Ring::one`] and [`Ring::from_int`] work; combining elements of two contexts made
//! separately is a caller bug and panics (like [`Quadratic`](super::Quadratic) radicands).
//! Integer numerators keep products and signs free of rational normalisation; those of at
//! most two coefficients (rationals, ℚ(√δ)) are stored inline, without a heap allocation.

use crate::algebraic::AlgebraicReal;
use crate::poly::Poly;
use crate::ring::{Field, Ring};
use crate::roots::RootInterval;
use crate::sign::Sign;
use dashu_int::IBig;
use dashu_ratio::RBig;
use std::fmt;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, MutexGuard, PoisonError};

/// The field ℚ(α) of a real algebraic number `α`: a handle to a shared context (module docs).
#[derive(Clone)]
pub struct NumberField {
    shared: Arc<Shared>,
}

/// The context behind the handles.
struct Shared {
    state: Mutex<Arc<State>>,
    /// The degree of the defining polynomial, read without the lock: it only decreases, so a
    /// value read is an upper bound of the current degree and the degree of a multiple of the
    /// current defining polynomial (an element reduced modulo that multiple stays valid).
    degree: AtomicUsize,
}

/// What the context knows; replaced as a whole when the defining polynomial shrinks.
struct State {
    /// `α`; its polynomial (square-free, primitive) is the defining polynomial.
    alpha: AlgebraicReal,
}

impl State {
    fn modulus(&self) -> &Poly {
        self.alpha.poly()
    }
}

/// An element `C(α)/d` of a [`NumberField`], or a rational (which belongs to every one).
///
/// Invariants: `d > 0`, `gcd(content(C), d) = 1`, and a numerator of positive degree has a
/// field.
#[derive(Clone)]
pub struct NumberFieldElement {
    num: Numerator,
    den: IBig,
    field: Option<NumberField>,
}

/// The integer numerator `C` of an element, without trailing zeros: up to two coefficients
/// inline (the rationals and the elements of ℚ(√δ) — building, cloning and dropping them
/// allocates nothing while the integers are small), longer ones in a [`Poly`].
#[derive(Clone)]
enum Numerator {
    /// `c₀ + c₁x`: the coefficients are `[c₀, c₁]`, `[c₀]` if `c₁ = 0`, none if both are
    /// zero (the length is not stored: the enum then takes a niche of `IBig`, 48 bytes).
    Short([IBig; 2]),
    /// At least three coefficients.
    Long(Poly),
}

impl Numerator {
    /// The zero numerator.
    const ZERO: Numerator = Numerator::Short([IBig::ZERO, IBig::ZERO]);

    /// The constant `v`.
    fn constant(v: IBig) -> Numerator {
        Numerator::Short([v, IBig::ZERO])
    }

    /// `a + b·x`.
    fn linear(a: IBig, b: IBig) -> Numerator {
        Numerator::Short([a, b])
    }

    /// The numerator of a polynomial (inline when it has at most two coefficients).
    fn from_poly(p: Poly) -> Numerator {
        if p.coeffs().len() > 2 {
            return Numerator::Long(p);
        }
        let mut c = p.into_coeffs().into_iter();
        match (c.next(), c.next()) {
            (None, _) => Numerator::ZERO,
            (Some(a), b) => Numerator::Short([a, b.unwrap_or(IBig::ZERO)]),
        }
    }

    /// The numerator with trimmed coefficients `c`.
    fn from_coeffs(c: &[IBig]) -> Numerator {
        match c {
            [] => Numerator::ZERO,
            [a] => Numerator::constant(a.clone()),
            [a, b] => Numerator::Short([a.clone(), b.clone()]),
            _ => Numerator::Long(Poly::from_trimmed(c.to_vec())),
        }
    }

    /// The coefficients, constant first.
    #[inline]
    fn coeffs(&self) -> &[IBig] {
        match self {
            Numerator::Short(c) => {
                let len = if c[1].is_zero() {
                    usize::from(!c[0].is_zero())
                } else {
                    2
                };
                &c[..len]
            }
            Numerator::Long(p) => p.coeffs(),
        }
    }

    /// As a [`Poly`] (allocates for a short numerator).
    fn to_poly(&self) -> Poly {
        match self {
            Numerator::Short(..) => Poly::from_trimmed(self.coeffs().to_vec()),
            Numerator::Long(p) => p.clone(),
        }
    }

    /// `f` of the numerator as a [`Poly`] (built only for a short one).
    fn with_poly<R>(&self, f: impl FnOnce(&Poly) -> R) -> R {
        match self {
            Numerator::Short(..) => f(&self.to_poly()),
            Numerator::Long(p) => f(p),
        }
    }

    fn is_zero(&self) -> bool {
        self.coeffs().is_empty()
    }

    /// Degree ≤ 0.
    fn is_constant(&self) -> bool {
        self.coeffs().len() <= 1
    }

    fn degree(&self) -> Option<usize> {
        self.coeffs().len().checked_sub(1)
    }

    /// The leading coefficient (zero for zero).
    fn leading(&self) -> IBig {
        self.coeffs().last().cloned().unwrap_or(IBig::ZERO)
    }

    /// The coefficient of `xʲ`.
    fn coeff(&self, j: usize) -> IBig {
        self.coeffs().get(j).cloned().unwrap_or(IBig::ZERO)
    }

    /// The gcd of the coefficients (`≥ 0`).
    fn content(&self) -> IBig {
        match self.coeffs() {
            [] => IBig::ZERO,
            [a] => crate::int_gcd(a, &IBig::ZERO),
            [a, b] => crate::int_gcd(a, b),
            _ => self.with_poly(Poly::content),
        }
    }

    /// `f` applied to every coefficient, trimmed.
    fn map(&self, mut f: impl FnMut(&IBig) -> IBig) -> Numerator {
        match self {
            Numerator::Short([a, b]) => match self.coeffs().len() {
                0 => Numerator::ZERO,
                1 => Numerator::constant(f(a)),
                _ => {
                    let a = f(a);
                    Numerator::linear(a, f(b))
                }
            },
            Numerator::Long(p) => Numerator::from_poly(p.map(f)),
        }
    }

    /// Every coefficient times `k`.
    fn scale(&self, k: &IBig) -> Numerator {
        self.map(|v| v * k)
    }

    fn neg(&self) -> Numerator {
        self.map(|v| -v)
    }

    /// The sum.
    fn add(&self, o: &Numerator) -> Numerator {
        match (self, o) {
            (Numerator::Short([a, b]), Numerator::Short([c, d])) => Numerator::linear(a + c, b + d),
            _ => Numerator::from_poly(&self.to_poly() + &o.to_poly()),
        }
    }

    /// The product, of degree `deg self + deg o` (not reduced).
    fn mul(&self, o: &Numerator) -> Numerator {
        match (self.coeffs(), o.coeffs()) {
            ([], _) | (_, []) => Numerator::ZERO,
            ([a], _) => o.scale(a),
            (_, [b]) => self.scale(b),
            ([a0, a1], [b0, b1]) => Numerator::Long(Poly::from_trimmed(vec![
                a0 * b0,
                a0 * b1 + a1 * b0,
                a1 * b1,
            ])),
            _ => Numerator::from_poly(&self.to_poly() * &o.to_poly()),
        }
    }
}

impl PartialEq for Numerator {
    fn eq(&self, other: &Numerator) -> bool {
        self.coeffs() == other.coeffs()
    }
}

impl NumberField {
    /// ℚ(α). The refinement of `alpha` is shared with the field.
    ///
    /// ```
    /// # use qsic_algebra::{field::NumberField, AlgebraicReal, Field, Poly, Ring, Sign};
    /// // α = √2, given as a root of (x² − 2)(x² − 3): the factor is found when needed
    /// let m = &Poly::from_i64s(&[-2, 0, 1]) * &Poly::from_i64s(&[-3, 0, 1]);
    /// let sqrt2 = AlgebraicReal::real_roots_of(&m)[2].clone();
    /// let k = NumberField::new(&sqrt2);
    /// let a = k.generator();
    /// assert_eq!(a.mul(&a), Ring::from_int(&2.into()));
    /// assert_eq!(k.modulus(), Poly::from_i64s(&[-2, 0, 1]));
    /// assert_eq!(a.sub(&Ring::from_int(&1.into())).inv().unwrap().sign(), Sign::Positive);
    /// ```
    pub fn new(alpha: &AlgebraicReal) -> NumberField {
        NumberField::of(alpha.clone())
    }

    /// ℚ(√δ) for an integer `δ > 0` that is not a square, `√δ` isolated by
    /// `(⌊√δ⌋, ⌊√δ⌋ + 1)` (`x² − δ` is negative at the left end and positive at the right
    /// one: no evaluation needed); `None` for a square or `δ ≤ 0`. The same field as
    /// [`Self::new`] of the positive root of `x² − δ`, with less work.
    ///
    /// ```
    /// # use qsic_algebra::{field::NumberField, IBig, Poly, Ring};
    /// let k = NumberField::sqrt(&IBig::from(12)).unwrap();
    /// let a = k.generator();
    /// assert_eq!(a.mul(&a), Ring::from_int(&12.into()));
    /// assert_eq!(k.modulus(), Poly::from_i64s(&[-12, 0, 1]));
    /// assert!(NumberField::sqrt(&IBig::from(9)).is_none() && NumberField::sqrt(&IBig::ZERO).is_none());
    /// ```
    pub fn sqrt(delta: &IBig) -> Option<NumberField> {
        use dashu_int::ops::{SquareRoot, UnsignedAbs};
        if *delta <= IBig::ZERO {
            return None;
        }
        let r = match u64::try_from(delta) {
            Ok(v) => IBig::from(v.isqrt()),
            Err(_) => IBig::from(delta.unsigned_abs().sqrt()),
        };
        if &r * &r == *delta {
            return None;
        }
        let poly = Poly::from_trimmed(vec![-delta.clone(), IBig::ZERO, IBig::ONE]);
        let interval = RootInterval::Open(RBig::from(r.clone()), RBig::from(r + IBig::ONE));
        Some(NumberField::of(AlgebraicReal::with_interval(
            poly, interval,
        )))
    }

    /// ℚ(α), taking `α`.
    fn of(alpha: AlgebraicReal) -> NumberField {
        let degree = alpha.poly().degree().unwrap_or(0);
        NumberField {
            shared: Arc::new(Shared {
                state: Mutex::new(Arc::new(State { alpha })),
                degree: AtomicUsize::new(degree),
            }),
        }
    }

    /// The generator `α`.
    pub fn generator(&self) -> NumberFieldElement {
        self.integer_element(&Poly::x())
    }

    /// The element `c(α)` of a rational polynomial.
    pub fn element(&self, c: &Poly<RBig>) -> NumberFieldElement {
        let (num, scale) = Poly::from_rational(c);
        // c = num / scale
        let num = num.scale(&IBig::from(scale.denominator().clone()));
        self.reduced(Numerator::from_poly(num), scale.numerator().clone())
    }

    /// The element `c(α)` of an integer polynomial.
    pub fn integer_element(&self, c: &Poly) -> NumberFieldElement {
        self.reduced(Numerator::from_coeffs(c.coeffs()), IBig::ONE)
    }

    /// The element `a + b·α` of integers `a`, `b`: [`Self::integer_element`] of `a + b·x`
    /// (the same representation), without the lock and the reduction when the defining
    /// polynomial has degree at least 2 (then `a + b·x` is reduced).
    ///
    /// ```
    /// # use qsic_algebra::{field::NumberField, AlgebraicReal, IBig, Poly};
    /// let k = NumberField::new(&AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 1]))[1]);
    /// let x = k.linear_element(IBig::from(3), IBig::from(-2)); // 3 − 2√2
    /// assert_eq!(x, k.integer_element(&Poly::from_i64s(&[3, -2])));
    /// assert_eq!(x.numerator(), Poly::from_i64s(&[3, -2]).coeffs());
    /// ```
    pub fn linear_element(&self, a: IBig, b: IBig) -> NumberFieldElement {
        let degree = usize::from(!b.is_zero());
        let num = Numerator::linear(a, b);
        if degree >= self.shared.degree.load(Ordering::Acquire) {
            return self.reduced(num, IBig::ONE);
        }
        NumberFieldElement {
            num,
            den: IBig::ONE,
            field: Some(self.clone()),
        }
    }

    /// The current defining polynomial: square-free, primitive, vanishing at `α`, a factor
    /// of the one the field was made with (its degree bounds `[ℚ(α) : ℚ]`).
    pub fn modulus(&self) -> Poly {
        self.snapshot().modulus().clone()
    }

    /// The degree of the current defining polynomial, without the lock. It only decreases,
    /// and every change of the defining polynomial decreases it: a value read twice unchanged
    /// means the same defining polynomial (a cache key).
    ///
    /// ```
    /// # use qsic_algebra::{field::NumberField, IBig};
    /// assert_eq!(NumberField::sqrt(&IBig::from(5)).unwrap().degree(), 2);
    /// ```
    pub fn degree(&self) -> usize {
        self.shared.degree.load(Ordering::Acquire)
    }

    /// `α`, defined by the current defining polynomial (its refinement is the field's).
    pub fn alpha(&self) -> AlgebraicReal {
        self.snapshot().alpha.clone()
    }

    /// `num/den` reduced modulo the current defining polynomial, normalised.
    fn reduced(&self, num: Numerator, den: IBig) -> NumberFieldElement {
        let (num, den) = reduce(num, den, self.snapshot().modulus());
        NumberFieldElement::normalized(num, den, Some(self))
    }

    fn lock(&self) -> MutexGuard<'_, Arc<State>> {
        self.shared
            .state
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
    }

    fn snapshot(&self) -> Arc<State> {
        self.lock().clone()
    }

    /// Whether `self` and `other` are the same field context (elements of both combine).
    pub fn same_as(&self, other: &NumberField) -> bool {
        Arc::ptr_eq(&self.shared, &other.shared)
    }

    /// Records that `factor` (a primitive factor of `seen`'s modulus) vanishes at `α`.
    fn shrink(&self, seen: &Arc<State>, factor: Poly) {
        let mut cur = self.lock();
        let factor = if Arc::ptr_eq(&cur, seen) {
            factor
        } else {
            // another thread shrank it meanwhile: both vanish at α, so does their gcd
            cur.modulus().gcd(&factor)
        };
        if factor.degree() < cur.modulus().degree() {
            let alpha = cur.alpha.with_factor(&factor);
            self.shared
                .degree
                .store(alpha.poly().degree().unwrap_or(0), Ordering::Release);
            *cur = Arc::new(State { alpha });
        }
    }

    /// Whether `α` is a root of `g`, a primitive factor of `seen`'s modulus of positive
    /// degree; shrinks the modulus to `g` or to its cofactor accordingly.
    fn split(&self, seen: &Arc<State>, g: Poly) -> bool {
        if seen.alpha.is_root_of_divisor(&g) {
            self.shrink(seen, g);
            true
        } else {
            let rest = seen
                .modulus()
                .div_exact(&g)
                .expect("a primitive factor divides over ℤ (Gauss)");
            self.shrink(seen, rest);
            false
        }
    }

    /// `C(α) = 0`, exactly (module docs).
    fn vanishes(&self, c: &Poly) -> bool {
        let seen = self.snapshot();
        if let Some(s) = seen.alpha.sign_on_refined(c) {
            return s.is_zero();
        }
        // A working precision once per field makes most later nonzero tests one evaluation.
        seen.alpha.refined_interval(&working_width());
        if let Some(s) = seen.alpha.sign_on_refined(c) {
            return s.is_zero();
        }
        self.decide_zero(&seen, c)
    }

    /// `C(α) = 0` by `g = gcd(C, modulus)`, splitting the modulus when `g` is a proper factor.
    fn decide_zero(&self, seen: &Arc<State>, c: &Poly) -> bool {
        let g = seen.modulus().gcd(c);
        g.degree().unwrap_or(0) > 0 && self.split(seen, g)
    }

    /// `(S, r)` with `S(α)·C(α) = r ≠ 0`, or `None` if `C(α) = 0`.
    fn invert(&self, c: &Poly) -> Option<(Poly, IBig)> {
        // Each failed round shrinks the modulus seen by the next: at most deg m rounds.
        loop {
            let seen = self.snapshot();
            match inverse_mod(c, seen.modulus()) {
                Ok(sr) => return Some(sr),
                Err(g) => {
                    if self.split(&seen, g) {
                        return None;
                    }
                }
            }
        }
    }
}

/// `2⁻⁶⁴`: the width to which `α` is refined before a zero test falls back to a gcd.
fn working_width() -> RBig {
    RBig::from_parts_signed(IBig::ONE, IBig::ONE << 64)
}

/// `num/den` as `num′/den′` with `deg num′ < deg m` (pseudo-remainder: `den` takes the
/// power of `lc(m)`).
fn reduce(num: Numerator, den: IBig, m: &Poly) -> (Numerator, IBig) {
    let (Some(n), Some(dm)) = (num.degree(), m.degree()) else {
        return (num, den);
    };
    if n < dm {
        return (num, den);
    }
    let l = m.leading();
    let rem = match (num.coeffs(), m.coeffs()) {
        // a product of two elements of ℚ(√δ): l·c − c₂·m, inline
        ([c0, c1, c2], [m0, m1, _]) => Numerator::linear(&l * c0 - c2 * m0, &l * c1 - c2 * m1),
        _ => Numerator::from_poly(num.with_poly(|p| p.pseudo_rem(m))),
    };
    let scale = if l.is_one() { l } else { l.pow(n - dm + 1) };
    (rem, den * scale)
}

/// `lc(b)^(δ+1)·a = q·b + r` with `deg r < deg b`, `δ = deg a − deg b ≥ 0`:
/// `(lc(b)^(δ+1), q, r)`.
fn pseudo_div_rem(a: &Poly, b: &Poly) -> (IBig, Poly, Poly) {
    let (da, db) = (a.degree().unwrap_or(0), b.degree().unwrap_or(0));
    let l = b.leading();
    let bc = b.coeffs();
    let mut r = a.coeffs().to_vec();
    let mut q = vec![IBig::ZERO; da - db + 1];
    for k in (0..=da - db).rev() {
        let t = r[k + db].clone();
        r.truncate(k + db + 1);
        for v in r.iter_mut().chain(q.iter_mut()) {
            *v *= &l;
        }
        for (j, bj) in bc.iter().enumerate() {
            r[k + j] -= &t * bj;
        }
        q[k] = t;
        r.truncate(k + db);
    }
    (l.pow(da - db + 1), Poly::new(q), Poly::new(r))
}

/// Divides `r` and `s` by the gcd of all their coefficients.
fn remove_common_content(r: Poly, s: Poly) -> (Poly, Poly) {
    let g = crate::int_gcd(&r.content(), &s.content());
    if g.is_zero() || g.is_one() {
        return (r, s);
    }
    (r.map(|v| v / &g), s.map(|v| v / &g))
}

/// `Ok((S, r))` with `S·c ≡ r (mod m)`, `r` a nonzero integer, or `Err(g)` with `g` the
/// primitive gcd of `c` and `m` when it has positive degree (`m` of positive degree).
///
/// A half-extended primitive remainder sequence over ℤ: `rᵢ ≡ sᵢ·c (mod m)` from
/// `r₀ = m, s₀ = 0` and `r₁ ≡ lc(m)^e·c, s₁ = lc(m)^e`; each step
/// `lc(rᵢ)^(δ+1)·rᵢ₋₁ = q·rᵢ + rᵢ₊₁`, `sᵢ₊₁ = lc(rᵢ)^(δ+1)·sᵢ₋₁ − q·sᵢ`, both divided by
/// their common content.
fn inverse_mod(c: &Poly, m: &Poly) -> Result<(Poly, IBig), Poly> {
    let (r1, s1) = match (c.degree(), m.degree()) {
        (Some(dc), Some(dm)) if dc >= dm => (
            c.pseudo_rem(m),
            Poly::constant(m.leading().pow(dc - dm + 1)),
        ),
        _ => (c.clone(), Poly::constant(IBig::ONE)),
    };
    let (mut r0, mut s0) = (m.clone(), Poly::zero());
    let (mut r1, mut s1) = remove_common_content(r1, s1);
    loop {
        match r1.degree() {
            None => return Err(r0.primitive_part()),
            Some(0) => return Ok((s1, r1.leading())),
            Some(_) => {
                let (k, q, r) = pseudo_div_rem(&r0, &r1);
                let s = &s0.scale(&k) - &(&q * &s1);
                let (r, s) = remove_common_content(r, s);
                (r0, s0) = (r1, s1);
                (r1, s1) = (r, s);
            }
        }
    }
}

impl NumberFieldElement {
    /// The rational `v` (in every field).
    pub fn rational(v: RBig) -> NumberFieldElement {
        NumberFieldElement {
            num: Numerator::constant(v.numerator().clone()),
            den: IBig::from(v.denominator().clone()),
            field: None,
        }
    }

    /// The integer `v` (in every field): [`Self::rational`] of `v` without the rational.
    ///
    /// ```
    /// # use qsic_algebra::{field::NumberFieldElement, IBig, RBig};
    /// let x = NumberFieldElement::integer(IBig::from(-7));
    /// assert_eq!(x, NumberFieldElement::rational(RBig::from(-7)));
    /// assert!(x.denominator().is_one() && x.field().is_none());
    /// ```
    pub fn integer(v: IBig) -> NumberFieldElement {
        NumberFieldElement {
            num: Numerator::constant(v),
            den: IBig::ONE,
            field: None,
        }
    }

    /// `num/den` with the invariants restored (`den ≠ 0`).
    fn normalized(num: Numerator, den: IBig, field: Option<&NumberField>) -> NumberFieldElement {
        let field = field.cloned();
        if num.is_zero() {
            return NumberFieldElement {
                num,
                den: IBig::ONE,
                field,
            };
        }
        if den.is_one() {
            // gcd(content, 1) = 1: nothing to divide
            return NumberFieldElement { num, den, field };
        }
        let mut g = crate::int_gcd(&num.content(), &den);
        if den < IBig::ZERO {
            g = -g;
        }
        let (num, den) = if g.is_one() {
            (num, den)
        } else {
            (num.map(|v| v / &g), den / &g)
        };
        NumberFieldElement { num, den, field }
    }

    /// The coefficients (constant first, no trailing zero) of the integer numerator `C` of
    /// `self = C(α)/d` (reduced modulo the defining polynomial at the time it was computed).
    ///
    /// ```
    /// # use qsic_algebra::{field::NumberField, IBig, Poly, Ring};
    /// let k = NumberField::sqrt(&IBig::from(2)).unwrap();
    /// let x = k.generator().add(&Ring::from_int(&IBig::from(3))); // 3 + √2
    /// assert_eq!(x.numerator(), [IBig::from(3), IBig::from(1)]);
    /// assert!(x.sub(&x).numerator().is_empty());
    /// ```
    #[inline]
    pub fn numerator(&self) -> &[IBig] {
        self.num.coeffs()
    }

    /// The integer numerator `C` of `self = C(α)/d` as a polynomial ([`Self::numerator`]).
    pub fn numerator_poly(&self) -> Poly {
        self.num.to_poly()
    }

    /// The positive denominator `d` of `self = C(α)/d`.
    #[inline]
    pub fn denominator(&self) -> &IBig {
        &self.den
    }

    /// The representative `C/d ∈ ℚ[x]`.
    pub fn representative(&self) -> Poly<RBig> {
        let d = RBig::from(self.den.clone());
        Poly::new(
            self.num
                .coeffs()
                .iter()
                .map(|v| RBig::from(v.clone()) / &d)
                .collect(),
        )
    }

    /// The field, `None` for a rational made without one.
    #[inline]
    pub fn field(&self) -> Option<&NumberField> {
        self.field.as_ref()
    }

    /// The field of an element of positive degree.
    fn field_if_irrational(&self) -> Option<&NumberField> {
        self.field.as_ref().filter(|_| !self.num.is_constant())
    }

    /// The exact sign of `c(α)`.
    ///
    /// Interval arithmetic on `α`'s refined interval decides nonzero signs (microseconds once
    /// `α` is refined); otherwise the exact zero test (module docs), then refinement of `α`,
    /// kept in the field for the next sign.
    ///
    /// ```
    /// # use qsic_algebra::{field::{NumberField, NumberFieldElement}, AlgebraicReal, Poly, RBig, Sign};
    /// let alpha = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 0, 1])).pop().unwrap();
    /// let a = NumberField::new(&alpha).generator(); // ∛2
    /// let r = |n: i64, d: i64| NumberFieldElement::rational(RBig::from_parts_signed(n.into(), d.into()));
    /// assert_eq!((&a - &r(126, 100)).sign(), Sign::Negative);
    /// assert_eq!((&a - &r(125, 100)).sign(), Sign::Positive);
    /// assert_eq!((&(&a * &a) * &a - r(2, 1)).sign(), Sign::Zero);
    /// ```
    pub fn sign(&self) -> Sign {
        let Some(field) = self.field_if_irrational() else {
            return Sign::of(&self.num.leading());
        };
        self.num.with_poly(|num| {
            let seen = field.snapshot();
            if let Some(s) = seen.alpha.sign_on_refined(num) {
                return s;
            }
            if field.decide_zero(&seen, num) {
                return Sign::Zero;
            }
            field.snapshot().alpha.sign_of_nonzero(num)
        })
    }

    /// A float approximation (display only): the representative at a rational within
    /// `2⁻⁶⁴` of `α`.
    pub fn to_f64(&self) -> f64 {
        let x = match self.field_if_irrational() {
            None => RBig::ZERO,
            Some(field) => {
                let iv = field.snapshot().alpha.refined_interval(&working_width());
                (iv.lo() + iv.hi()) / RBig::from(2)
            }
        };
        (self.num.with_poly(|p| p.eval_rational(&x)) / RBig::from(self.den.clone()))
            .to_f64()
            .value()
    }

    /// Whether `self` and `other` can be combined: one is rational, or both belong to the
    /// same field context.
    pub fn compatible_with(&self, other: &NumberFieldElement) -> bool {
        match (self.field_if_irrational(), other.field_if_irrational()) {
            (Some(a), Some(b)) => a.same_as(b),
            _ => true,
        }
    }

    /// The common field of two operands.
    ///
    /// # Panics
    /// If both belong to fields made separately.
    fn common_field<'a>(&'a self, o: &'a Self) -> Option<&'a NumberField> {
        match (&self.field, &o.field) {
            (Some(a), Some(b)) => {
                assert!(a.same_as(b), "elements of different number fields combined");
                Some(a)
            }
            (Some(a), None) | (None, Some(a)) => Some(a),
            (None, None) => None,
        }
    }
}

impl Ring for NumberFieldElement {
    fn zero() -> Self {
        NumberFieldElement::rational(RBig::ZERO)
    }
    fn one() -> Self {
        NumberFieldElement::rational(RBig::ONE)
    }
    fn from_int(v: &IBig) -> Self {
        NumberFieldElement::rational(RBig::from(v.clone()))
    }
    /// Exact (module docs); may shrink the field's defining polynomial.
    fn is_zero(&self) -> bool {
        match self.field_if_irrational() {
            None => self.num.is_zero(),
            Some(f) => self.num.with_poly(|p| f.vanishes(p)),
        }
    }
    /// # Panics
    /// If the operands belong to different fields (all binary operations).
    fn add(&self, o: &Self) -> Self {
        let field = self.common_field(o);
        if self.den == o.den {
            return NumberFieldElement::normalized(self.num.add(&o.num), self.den.clone(), field);
        }
        let num = self.num.scale(&o.den).add(&o.num.scale(&self.den));
        NumberFieldElement::normalized(num, &self.den * &o.den, field)
    }
    fn sub(&self, o: &Self) -> Self {
        self.add(&o.neg())
    }
    fn mul(&self, o: &Self) -> Self {
        let field = self.common_field(o);
        let den = &self.den * &o.den;
        let (num, den) = match (self.num.is_constant(), o.num.is_constant(), field) {
            (true, _, _) => (o.num.scale(&self.num.leading()), den),
            (_, true, _) => (self.num.scale(&o.num.leading()), den),
            (_, _, Some(f)) => reduce(self.num.mul(&o.num), den, f.snapshot().modulus()),
            (_, _, None) => (self.num.mul(&o.num), den),
        };
        NumberFieldElement::normalized(num, den, field)
    }
    fn neg(&self) -> Self {
        NumberFieldElement {
            num: self.num.neg(),
            den: self.den.clone(),
            field: self.field.clone(),
        }
    }
    fn div_exact(&self, d: &Self) -> Option<Self> {
        Field::div(self, d)
    }
}

/// ℚ(α) ordered by α's place on the real line: the sign is [`NumberFieldElement::sign`].
impl crate::ring::RealField for NumberFieldElement {
    fn sign(&self) -> Sign {
        NumberFieldElement::sign(self)
    }
}

impl Field for NumberFieldElement {
    /// `None` exactly when [`Ring::is_zero`] says so (may shrink the defining polynomial).
    fn inv(&self) -> Option<Self> {
        let Some(field) = self.field_if_irrational() else {
            let v = self.num.leading();
            return (!v.is_zero()).then(|| {
                NumberFieldElement::normalized(
                    Numerator::constant(self.den.clone()),
                    v,
                    self.field.as_ref(),
                )
            });
        };
        // 1/(C/d) = d·S/r
        let (s, r) = self.num.with_poly(|p| field.invert(p))?;
        Some(NumberFieldElement::normalized(
            Numerator::from_poly(s.scale(&self.den)),
            r,
            Some(field),
        ))
    }
}

/// Exact equality of values (equal representations, or a zero test of the difference).
impl PartialEq for NumberFieldElement {
    fn eq(&self, other: &Self) -> bool {
        (self.num == other.num && self.den == other.den) || Ring::sub(self, other).is_zero()
    }
}

macro_rules! forward_op {
    ($tr:ident, $m:ident) => {
        impl std::ops::$tr for NumberFieldElement {
            type Output = NumberFieldElement;
            fn $m(self, rhs: NumberFieldElement) -> NumberFieldElement {
                Ring::$m(&self, &rhs)
            }
        }
        impl std::ops::$tr for &NumberFieldElement {
            type Output = NumberFieldElement;
            fn $m(self, rhs: &NumberFieldElement) -> NumberFieldElement {
                Ring::$m(self, rhs)
            }
        }
    };
}
forward_op!(Add, add);
forward_op!(Sub, sub);
forward_op!(Mul, mul);

impl std::ops::Neg for NumberFieldElement {
    type Output = NumberFieldElement;
    fn neg(self) -> NumberFieldElement {
        Ring::neg(&self)
    }
}

impl fmt::Display for NumberFieldElement {
    /// The representative as a polynomial in `α`: `α^2 - 1/3*α + 5`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.representative().to_string().replace('x', "α"))
    }
}

impl fmt::Debug for NumberFieldElement {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "NumberFieldElement({self})")
    }
}

impl fmt::Debug for NumberField {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "NumberField(α = {})", self.snapshot().alpha)
    }
}

impl Poly<NumberFieldElement> {
    /// The distinct real roots of a nonzero polynomial with coefficients in one real number
    /// field ℚ(α), increasing, as real algebraic numbers over ℚ.
    ///
    /// Every root is a root of the norm `N(u) = Res_α(m(α), P(α, u)) ∈ ℤ[u]` (`m` the defining
    /// polynomial, `P` the integer numerator); of the real roots of `N`'s square-free part,
    /// isolated, the roots of `p` are those where the square-free part of `p` (over the field)
    /// changes sign across the isolating interval — a simple root of it does, and no other
    /// root of `N` lies in the interval. Signs at rational ends are exact field signs.
    ///
    /// ```
    /// # use qsic_algebra::{field::NumberField, AlgebraicReal, Poly, Ring};
    /// // (u − √2)²(u + 1) over ℚ(√2): roots √2 and −1, not −√2
    /// let k = NumberField::new(&AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 1]))[1]);
    /// let r2 = k.generator();
    /// let lin = Poly::new(vec![r2.neg(), Ring::one()]);
    /// let p = &(&lin * &lin) * &Poly::new(vec![Ring::one(), Ring::one()]);
    /// let roots: Vec<f64> = p.real_roots().iter().map(AlgebraicReal::to_f64).collect();
    /// assert_eq!(roots.len(), 2);
    /// assert!((roots[0] + 1.0).abs() < 1e-12 && (roots[1] - 2f64.sqrt()).abs() < 1e-9);
    /// ```
    /// An enclosure `[lo, hi] ∋ p(t)` by rational interval arithmetic on the boxes of `α` and
    /// `t` refined below `2^−bits` and rounded outward to dyadic ends (a nonzero `p(t)` is
    /// excluded from zero once `bits` is large enough).
    pub fn enclosure_at(&self, t: &AlgebraicReal, bits: usize) -> (RBig, RBig) {
        let field = self
            .coeffs()
            .iter()
            .find_map(|c| c.field_if_irrational())
            .cloned();
        let width = RBig::from_parts(IBig::ONE, dashu_int::UBig::ONE << bits);
        let alpha = field.as_ref().map(|k| {
            let iv = k.snapshot().alpha.refined_interval(&width);
            dyadic_outward(iv.lo(), iv.hi(), bits + 8)
        });
        let tv = t.refined_interval(&width);
        let t_box = dyadic_outward(tv.lo(), tv.hi(), bits + 8);
        // the coefficients' enclosures, then Horner in t
        let mut acc = (RBig::ZERO, RBig::ZERO);
        for c in self.coeffs().iter().rev() {
            let cv = match (&alpha, c.field_if_irrational()) {
                (Some(a), Some(_)) => {
                    let b =
                        interval_horner(c.num.coeffs().iter().map(|v| RBig::from(v.clone())), a);
                    let d = RBig::from(c.den.clone());
                    (b.0 / &d, b.1 / &d)
                }
                _ => {
                    let v = c.representative().coeff(0);
                    (v.clone(), v)
                }
            };
            let m = interval_mul(&acc, &t_box);
            acc = (m.0 + &cv.0, m.1 + &cv.1);
        }
        acc
    }

    /// The exact sign of `p(t)` at a real algebraic number `t`.
    ///
    /// The value is enclosed by rational interval arithmetic over the boxes of `α` and `t`,
    /// both refined (their shared states) until the enclosure excludes zero — which it does
    /// for a nonzero value once the boxes are small enough; if it still holds zero at 64
    /// bits, zero is decided exactly: over a quadratic field by signs of rational polynomials
    /// at `t` (`p₀ + α·p₁ = 0` iff `−p₀/p₁` is the root `α` of the modulus), otherwise by `t`
    /// being one of [`Self::real_roots`] (exact comparison).
    ///
    /// ```
    /// # use qsic_algebra::{field::NumberField, AlgebraicReal, Poly, Ring, Sign};
    /// let k = NumberField::new(&AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 1]))[1]);
    /// let p = Poly::new(vec![k.generator().neg(), Ring::one()]); // u − √2
    /// let t = |c: &[i64]| AlgebraicReal::real_roots_of(&Poly::from_i64s(c)).pop().unwrap();
    /// assert_eq!(p.sign_at(&t(&[-2, 0, 1])), Sign::Zero); // t = √2
    /// assert_eq!(p.sign_at(&t(&[-3, 0, 1])), Sign::Positive); // t = √3
    /// assert_eq!(p.sign_at(&t(&[-199, 0, 100])), Sign::Negative); // t = √1.99
    /// ```
    pub fn sign_at(&self, t: &AlgebraicReal) -> Sign {
        if self.is_zero() {
            return Sign::Zero;
        }
        if let Some(v) = t.as_rational() {
            return self.eval(&NumberFieldElement::rational(v.clone())).sign();
        }
        let field = self
            .coeffs()
            .iter()
            .find_map(|c| c.field_if_irrational())
            .cloned();
        if let Some(sign) = self.float_sign_at(field.as_ref(), t) {
            return sign;
        }
        self.exact_sign_at(field.as_ref(), t)
    }

    /// [`Self::sign_at`] by rational enclosures and the exact zero test (no float filter).
    fn exact_sign_at(&self, field: Option<&NumberField>, t: &AlgebraicReal) -> Sign {
        // boxes rounded outward to dyadic ends of `bits` bits: the shared refinements may be
        // far narrower, with ends of huge height that would make the arithmetic crawl; the
        // exact zero test (costly: a norm and its roots) only once an enclosure at 64 bits
        // still holds 0
        let mut bits = 16usize;
        let mut zero_tested = false;
        loop {
            if bits > 64 && !zero_tested {
                let quadratic = field.map_or(QuadraticTest::NotQuadratic, |k| {
                    quadratic_zero_test(self, k, t)
                });
                match quadratic {
                    QuadraticTest::Sign(sign) => return sign,
                    QuadraticTest::Nonzero => {}
                    QuadraticTest::NotQuadratic => {
                        if self.real_roots().iter().any(|r| r == t) {
                            return Sign::Zero;
                        }
                    }
                }
                zero_tested = true;
            }
            let acc = self.enclosure_at(t, bits);
            if acc.0 > RBig::ZERO {
                return Sign::Positive;
            }
            if acc.1 < RBig::ZERO {
                return Sign::Negative;
            }
            bits *= 2;
        }
    }

    /// The sign of `p(t)` by floating-point interval arithmetic (every operation widened by
    /// one unit in the last place each way, which covers a rounding to nearest) on the boxes
    /// of `α` and `t` refined below `2⁻⁴⁸`; `None` when the enclosure holds zero or a value
    /// leaves the range of `f64` (the caller's exact route decides then).
    fn float_sign_at(&self, field: Option<&NumberField>, t: &AlgebraicReal) -> Option<Sign> {
        let width = RBig::from_parts(IBig::ONE, dashu_int::UBig::ONE << 48);
        let alpha = match field {
            Some(k) => Some(Fi::of_interval(
                &k.snapshot().alpha.refined_interval(&width),
            )?),
            None => None,
        };
        let tv = Fi::of_interval(&t.refined_interval(&width))?;
        let mut acc = Fi::point(0.0);
        for c in self.coeffs().iter().rev() {
            let cv = match (alpha, c.field_if_irrational()) {
                (Some(a), Some(_)) => {
                    let mut num = Fi::point(0.0);
                    for v in c.num.coeffs().iter().rev() {
                        num = num.mul(a).add(Fi::of_int(v)?);
                    }
                    num.div_positive(Fi::of_int(&c.den)?)?
                }
                _ => {
                    let v = c.representative().coeff(0);
                    Fi::of_int(v.numerator())?
                        .div_positive(Fi::of_int(&IBig::from(v.denominator().clone()))?)?
                }
            };
            acc = acc.mul(tv).add(cv);
        }
        acc.sign()
    }

    pub fn real_roots(&self) -> Vec<AlgebraicReal> {
        if self.is_zero() {
            return Vec::new();
        }
        let field = self
            .coeffs()
            .iter()
            .find_map(|c| c.field_if_irrational())
            .cloned();
        let Some(field) = field else {
            // rational coefficients
            let q: Poly<RBig> = self.map(|c| c.representative().coeff(0));
            return AlgebraicReal::real_roots_of(&Poly::from_rational(&q).0);
        };
        let sf = self.squarefree_part_field();
        // P(α, u) with integer coefficients: the numerators over a common denominator
        let lcm = sf
            .coeffs()
            .iter()
            .fold(IBig::ONE, |l, c| &l / crate::int_gcd(&l, &c.den) * &c.den);
        let width = sf
            .coeffs()
            .iter()
            .map(|c| c.num.coeffs().len())
            .max()
            .unwrap_or(0);
        let in_alpha: Poly<Poly> = Poly::new(
            (0..width)
                .map(|j| {
                    Poly::new(
                        sf.coeffs()
                            .iter()
                            .map(|c| c.num.coeff(j) * (&lcm / &c.den))
                            .collect(),
                    )
                })
                .collect(),
        );
        let m: Poly<Poly> = field.modulus().map(|v| Poly::constant(v.clone()));
        let norm = m.resultant(&in_alpha).squarefree_part();
        let sign_at = |x: &RBig| sf.eval(&NumberFieldElement::rational(x.clone())).sign();
        crate::roots::isolate_squarefree_real_roots(&norm)
            .into_iter()
            .filter(|iv| match iv {
                RootInterval::Exact(v) => sign_at(v) == Sign::Zero,
                RootInterval::Open(lo, hi) => sign_at(lo) != sign_at(hi),
            })
            .filter_map(|iv| match iv {
                RootInterval::Exact(v) => Some(AlgebraicReal::from_rational(v)),
                iv => AlgebraicReal::from_isolating_interval(&norm, &iv),
            })
            .collect()
    }
}

/// What [`quadratic_zero_test`] found.
enum QuadraticTest {
    /// The exact sign.
    Sign(Sign),
    /// The value is not zero (its sign is left to interval arithmetic).
    Nonzero,
    /// The field is not quadratic: no answer.
    NotQuadratic,
}

/// The sign of a rational polynomial at `t`, exactly.
fn rational_sign_at(p: &Poly<RBig>, t: &AlgebraicReal) -> Sign {
    if p.is_zero() {
        return Sign::Zero;
    }
    let (q, scale) = Poly::from_rational(p);
    let s = t.sign_of(&q);
    if scale < RBig::ZERO {
        -s
    } else {
        s
    }
}

/// Over a quadratic field `ℚ(α)`, `α` a root of `m = a₂x² + a₁x + a₀`: `p = p₀ + α·p₁` with
/// `p₀, p₁ ∈ ℚ[u]`; `p(t) = p₀(t)` if `p₁(t) = 0`, else `p(t) = 0` iff `−p₀(t)/p₁(t)` is a
/// root of `m` — `a₂p₀² − a₁p₀p₁ + a₀p₁²` vanishes at `t` — and that root is `α`, not its
/// conjugate: on `α`'s side of the midpoint `−a₁/(2a₂)`. Every sign is of a rational
/// polynomial at `t` (exact and cheap), no norm or root isolation.
fn quadratic_zero_test(
    p: &Poly<NumberFieldElement>,
    k: &NumberField,
    t: &AlgebraicReal,
) -> QuadraticTest {
    let m = k.modulus();
    if m.degree() != Some(2) {
        return QuadraticTest::NotQuadratic;
    }
    let part = |j: usize| -> Poly<RBig> {
        Poly::new(
            p.coeffs()
                .iter()
                .map(|c| RBig::from(c.num.coeff(j)) / RBig::from(c.den.clone()))
                .collect(),
        )
    };
    if p.coeffs().iter().any(|c| c.num.degree().unwrap_or(0) > 1) {
        return QuadraticTest::NotQuadratic;
    }
    let (p0, p1) = (part(0), part(1));
    let s1 = rational_sign_at(&p1, t);
    if s1 == Sign::Zero {
        return QuadraticTest::Sign(rational_sign_at(&p0, t));
    }
    let [a0, a1, a2] = [0, 1, 2].map(|j| RBig::from(m.coeff(j)));
    let z = &(&(&p0 * &p0).scale(&a2) - &(&p0 * &p1).scale(&a1)) + &(&p1 * &p1).scale(&a0);
    if rational_sign_at(&z, t) != Sign::Zero {
        return QuadraticTest::Nonzero;
    }
    // −p₀/p₁ − mid = (−2a₂p₀ − a₁p₁)/(2a₂p₁); α − mid = (2a₂α + a₁)/(2a₂)
    let two_a2 = &a2 * RBig::from(2);
    let side_of_root = rational_sign_at(&(&p0.scale(&-two_a2.clone()) - &p1.scale(&a1)), t) * s1;
    let alpha = k.snapshot().alpha.clone();
    let side_of_alpha = alpha.sign_of(&Poly::new(vec![m.coeff(1), m.coeff(2) * IBig::from(2)]));
    if side_of_root == side_of_alpha {
        QuadraticTest::Sign(Sign::Zero)
    } else {
        QuadraticTest::Nonzero
    }
}

/// `[⌊lo·2ᵏ⌋/2ᵏ, ⌈hi·2ᵏ⌉/2ᵏ]`: an enclosure of `[lo, hi]` with dyadic ends.
fn dyadic_outward(lo: &RBig, hi: &RBig, k: usize) -> (RBig, RBig) {
    let scale = RBig::from(IBig::ONE << k);
    let down = RBig::from((lo * &scale).floor()) / &scale;
    let up = RBig::from((hi * &scale).ceil()) / &scale;
    (down, up)
}

/// The least float above `x` (`f64::next_up`, stable only after this crate's MSRV).
fn next_up(x: f64) -> f64 {
    if x.is_nan() || x == f64::INFINITY {
        return x;
    }
    if x == 0.0 {
        return f64::from_bits(1);
    }
    let bits = x.to_bits();
    f64::from_bits(if x > 0.0 { bits + 1 } else { bits - 1 })
}

/// A closed interval of floats `[lo, hi]` holding an exact real; each operation rounds to
/// nearest and then steps one float outward, so the exact result stays inside.
#[derive(Clone, Copy, Debug)]
struct Fi {
    lo: f64,
    hi: f64,
}

impl Fi {
    fn point(v: f64) -> Fi {
        Fi { lo: v, hi: v }
    }

    fn widened(lo: f64, hi: f64) -> Fi {
        Fi {
            lo: -next_up(-lo),
            hi: next_up(hi),
        }
    }

    /// An integer's enclosure (its conversion is within one unit in the last place).
    fn of_int(v: &IBig) -> Option<Fi> {
        let f = v.to_f64().value();
        f.is_finite().then(|| Fi::widened(f, f))
    }

    /// A rational interval's enclosure.
    fn of_interval(iv: &crate::roots::RootInterval) -> Option<Fi> {
        let (lo, hi) = (iv.lo().to_f64().value(), iv.hi().to_f64().value());
        (lo.is_finite() && hi.is_finite()).then(|| Fi::widened(lo, hi))
    }

    fn add(self, o: Fi) -> Fi {
        Fi::widened(self.lo + o.lo, self.hi + o.hi)
    }

    fn mul(self, o: Fi) -> Fi {
        if !(self.is_finite() && o.is_finite()) {
            // ∞·0 is NaN, which min and max would skip: no enclosure
            return Fi::point(f64::NAN);
        }
        let p = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        let lo = p.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Fi::widened(lo, hi)
    }

    /// `self / d` for `d > 0` (`None` if `d` may be zero or negative).
    fn div_positive(self, d: Fi) -> Option<Fi> {
        if !(d.lo > 0.0 && self.is_finite() && d.is_finite()) {
            return None;
        }
        let q = [
            self.lo / d.lo,
            self.lo / d.hi,
            self.hi / d.lo,
            self.hi / d.hi,
        ];
        let lo = q.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = q.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Some(Fi::widened(lo, hi))
    }

    fn is_finite(self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }

    /// The sign of every real inside, `None` if zero is inside or an end is not finite.
    fn sign(self) -> Option<Sign> {
        if !self.is_finite() {
            None
        } else if self.lo > 0.0 {
            Some(Sign::Positive)
        } else if self.hi < 0.0 {
            Some(Sign::Negative)
        } else {
            None
        }
    }
}

/// The product of two rational intervals `[a₀, a₁]·[b₀, b₁]`.
fn interval_mul(a: &(RBig, RBig), b: &(RBig, RBig)) -> (RBig, RBig) {
    let p = [&a.0 * &b.0, &a.0 * &b.1, &a.1 * &b.0, &a.1 * &b.1];
    let lo = p.iter().min().cloned().unwrap_or(RBig::ZERO);
    let hi = p.iter().max().cloned().unwrap_or(RBig::ZERO);
    (lo, hi)
}

/// An enclosure of `Σ cᵢ xⁱ` (coefficients in increasing degree) over `x ∈ [x₀, x₁]`.
fn interval_horner(
    coeffs: impl DoubleEndedIterator<Item = RBig>,
    x: &(RBig, RBig),
) -> (RBig, RBig) {
    let mut acc = (RBig::ZERO, RBig::ZERO);
    for c in coeffs.rev() {
        let m = interval_mul(&acc, x);
        acc = (m.0 + &c, m.1 + &c);
    }
    acc
}

#[cfg(test)]
mod tests {
    /// The float filter of `sign_at` agrees with the exact route wherever it answers, and
    /// does not answer at a zero: random polynomials over ℚ(∛2) and ℚ(√2), at real roots of
    /// random integer quadratics and cubics and at exact roots of the polynomial itself.
    #[test]
    fn the_float_sign_filter_agrees_with_the_exact_sign() {
        let mut rng = crate::testing::SplitMix(0x51_6e);
        let fields = [
            NumberField::new(&AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 0, 1]))[0]),
            NumberField::new(&AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 1]))[1]),
        ];
        let (mut answered, mut zeros) = (0, 0);
        for round in 0..300 {
            let k = &fields[round % 2];
            let element = |rng: &mut crate::testing::SplitMix| {
                k.integer_element(&Poly::from_i64s(&[
                    rng.int(-9, 9),
                    rng.int(-9, 9),
                    rng.int(-9, 9),
                ]))
            };
            let p = Poly::new((0..4).map(|_| element(&mut rng)).collect());
            let q = Poly::from_i64s(&[rng.int(-20, 20), rng.int(-5, 5), rng.int(-3, 3), 1]);
            let mut points = AlgebraicReal::real_roots_of(&q);
            points.extend(p.real_roots());
            for t in &points {
                let exact = p.exact_sign_at(Some(k), t);
                match p.float_sign_at(Some(k), t) {
                    Some(sign) => {
                        assert_eq!(sign, exact, "{p:?} at {t}");
                        answered += 1;
                    }
                    None => zeros += usize::from(exact == Sign::Zero),
                }
                assert_eq!(p.sign_at(t), exact);
            }
        }
        // one float outward, both ways
        assert_eq!(next_up(1.0), 1.0 + f64::EPSILON);
        assert_eq!(-next_up(-1.0), 1.0 - f64::EPSILON / 2.0);
        assert_eq!(next_up(-0.0), f64::from_bits(1));
        assert_eq!(next_up(f64::MAX), f64::INFINITY);
        // the filter answers the common case, and every root of p reached the exact route
        assert!(answered > 300 && zeros > 100, "{answered} {zeros}");
    }

    #[test]
    fn real_roots_over_a_cubic_field_are_the_roots_not_their_conjugates() {
        // α the real root of x³ − 2; p = (u − α)(u − α² + 1)(u² + α) has the real roots
        // α² − 1 < α (u² + α > 0); the norm's other real roots (of u² + α's conjugates) are not
        let alpha = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 0, 1]))[0].clone();
        let k = NumberField::new(&alpha);
        let a = k.generator();
        let one = NumberFieldElement::one();
        let lin = |r: NumberFieldElement| Poly::new(vec![r.neg(), one.clone()]);
        let p = &(&lin(a.clone()) * &lin(a.mul(&a).sub(&one)))
            * &Poly::new(vec![a.clone(), NumberFieldElement::zero(), one.clone()]);
        let roots: Vec<f64> = p.real_roots().iter().map(AlgebraicReal::to_f64).collect();
        let c = 2f64.cbrt();
        assert_eq!(roots.len(), 2, "{roots:?}");
        assert!(
            (roots[0] - (c * c - 1.0)).abs() < 1e-9 && (roots[1] - c).abs() < 1e-9,
            "{roots:?}"
        );
        // a double root counts once; rational coefficients take the integer route
        let double = &lin(a.clone()) * &lin(a.clone());
        assert_eq!(double.real_roots().len(), 1);
        let q = Poly::new(vec![
            NumberFieldElement::rational(RBig::from(-4)),
            NumberFieldElement::zero(),
            one,
        ]);
        let r: Vec<f64> = q.real_roots().iter().map(AlgebraicReal::to_f64).collect();
        assert_eq!(r, [-2.0, 2.0]);
        assert!(Poly::<NumberFieldElement>::zero().real_roots().is_empty());
        let sqrt2 = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 1]))[1].clone();
        assert_eq!(
            Poly::<NumberFieldElement>::zero().sign_at(&sqrt2),
            Sign::Zero
        );
    }

    use super::*;
    use proptest::prelude::*;

    /// `linalg`'s inertia over ℚ(∛2) through `RealField`: a symmetric matrix whose entries
    /// are built from α, diagonalized by congruence (PᵀSP = D checked), against the signs of
    /// its leading principal minors (Jacobi: all nonzero here, so the number of sign changes
    /// in 1, D₁, D₂, D₃ is the number of negative eigenvalues).
    #[test]
    fn inertia_over_a_cubic_field() {
        use crate::linalg::{minors, Matrix};
        let alpha = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 0, 1]))
            .pop()
            .unwrap();
        let a = NumberField::new(&alpha).generator();
        let r = |n: i64| NumberFieldElement::rational(RBig::from(n));
        // entries: α − 1, α², 1 − α, α + 2, …  (α ≈ 1.26)
        let e = [
            [&a - &r(1), &a * &a, r(3)],
            [&a * &a, &r(1) - &a, &a + &r(2)],
            [r(3), &a + &r(2), &(&a * &a) - &r(5)],
        ];
        let s = Matrix::from_array(e.clone());
        let diag = s.diagonalize_congruent().expect("symmetric");
        let back = &(&diag.p.transpose() * &s) * &diag.p;
        let d = Matrix::from_fn(3, 3, |i, j| {
            if i == j {
                diag.d[i].clone()
            } else {
                NumberFieldElement::zero()
            }
        });
        assert!(back == d, "PᵀSP = D");
        let leading: Vec<Sign> = (1..=3)
            .map(|k| {
                let m: Vec<Vec<NumberFieldElement>> = (0..k).map(|i| e[i][..k].to_vec()).collect();
                let v = minors::det_bareiss(m);
                // an independent witness for the exact sign: the float value, far from zero
                let f = v.to_f64();
                assert!(
                    f.abs() > 0.1,
                    "minor {k} too close to zero for the witness: {f}"
                );
                assert_eq!(
                    v.sign(),
                    if f > 0.0 {
                        Sign::Positive
                    } else {
                        Sign::Negative
                    }
                );
                v.sign()
            })
            .collect();
        assert!(leading.iter().all(|s| *s != Sign::Zero), "{leading:?}");
        let changes = crate::sign::count_variations(
            std::iter::once(Sign::Positive).chain(leading.iter().copied()),
        );
        let inertia = diag.inertia();
        assert_eq!(
            usize::from(inertia.negative),
            changes,
            "{inertia:?} {leading:?}"
        );
        assert_eq!(usize::from(inertia.positive), 3 - changes);
    }

    type Nfe = NumberFieldElement;

    use crate::testing::SplitMix as Rng;

    fn rat(n: i64, d: i64) -> RBig {
        RBig::from_parts_signed(n.into(), d.into())
    }

    fn pow2_inv(k: usize) -> RBig {
        RBig::from_parts_signed(IBig::ONE, IBig::ONE << k)
    }

    fn abs(v: &RBig) -> RBig {
        if *v < RBig::ZERO {
            -v
        } else {
            v.clone()
        }
    }

    /// Chebyshev's `T_n`.
    fn chebyshev(n: usize) -> Poly {
        let (mut a, mut b) = (Poly::from_i64s(&[1]), Poly::from_i64s(&[0, 1]));
        for _ in 0..n {
            let c = &(&Poly::from_i64s(&[0, 2]) * &b) - &a;
            (a, b) = (b, c);
        }
        a
    }

    /// `T₆ · (1024 T₆ − 1)`: degree 12, twelve real roots in six pairs about `10⁻⁴` apart.
    fn close_pairs_12() -> Poly {
        let t6 = chebyshev(6);
        &t6 * &(&t6.scale(&IBig::from(1024)) - &Poly::from_i64s(&[1]))
    }

    /// A square-free degree-12 integer polynomial with coefficients in `[−20, 20]` and a
    /// real root.
    fn random_12(rng: &mut Rng) -> Poly {
        loop {
            let mut c: Vec<i64> = (0..12).map(|_| rng.int(-20, 20)).collect();
            c.push(rng.int(1, 20));
            let p = Poly::from_i64s(&c);
            if p.is_squarefree() && p.count_real_roots_sturm() > 0 {
                return p;
            }
        }
    }

    fn random_poly(rng: &mut Rng, len: usize) -> Poly<RBig> {
        Poly::new(
            (0..len)
                .map(|_| rat(rng.int(-9, 9), rng.int(1, 5)))
                .collect(),
        )
    }

    /// Fields to test in: ∛2, a root in each close pair of the degree-12 polynomial's
    /// middle, and a root of a random degree-12 polynomial.
    fn fields() -> Vec<NumberField> {
        let cbrt2 = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 0, 1])).remove(0);
        let close = AlgebraicReal::real_roots_of(&close_pairs_12());
        assert_eq!(close.len(), 12);
        let random = AlgebraicReal::real_roots_of(&random_12(&mut Rng(12))).remove(0);
        [cbrt2, close[5].clone(), close[6].clone(), random]
            .iter()
            .map(NumberField::new)
            .collect()
    }

    /// `Σ i·|fᵢ|·R^(i−1)` and `Σ |fᵢ|·Rⁱ`: bounds on `|f′|` and `|f|` on `[−R, R]`.
    fn bounds(f: &Poly<RBig>, r: &RBig) -> (RBig, RBig) {
        let (mut lip, mut max, mut pw) = (RBig::ZERO, RBig::ZERO, RBig::ONE);
        for (i, c) in f.coeffs().iter().enumerate() {
            if i > 0 {
                lip += abs(c) * RBig::from(i) * &pw;
                pw *= r;
            }
            max += abs(c) * &pw;
        }
        (lip, max)
    }

    /// Checks `f(α)·g(α) = h(α)` (`g = None`: `f(α) + 0 = h(α)`, used for sums via `f = a + b`
    /// computed independently) at a rational `r` near `α`: by the mean value theorem,
    /// `|f(r)g(r) − h(r)| ≤ w(L_h + L_f|g(r)| + (|f(r)| + wL_f)L_g)` for `|r − α| ≤ w`, where
    /// `L` bounds the derivative on the interval. `w` is chosen so the bound is below
    /// `2⁻²⁰⁰`; a wrong representative misses by far more.
    fn check_product_at_approximation(
        alpha: &AlgebraicReal,
        f: &Poly<RBig>,
        g: &Poly<RBig>,
        h: &Poly<RBig>,
    ) {
        let coarse = alpha.refined_interval(&pow2_inv(200));
        let big_r = abs(coarse.lo()).max(abs(coarse.hi()));
        let ((lf, mf), (lg, mg), (lh, _)) =
            (bounds(f, &big_r), bounds(g, &big_r), bounds(h, &big_r));
        let k = RBig::ONE + &lh + &lf * &mg + (&mf + &lf) * &lg;
        let width = pow2_inv(200 + k.ceil().bit_len());
        let iv = alpha.refined_interval(&width);
        let r = (iv.lo() + iv.hi()) / RBig::from(2);
        let w = iv.hi() - iv.lo();
        let (fr, gr, hr) = (f.eval(&r), g.eval(&r), h.eval(&r));
        let bound = &w * (&lh + &lf * abs(&gr) + (abs(&fr) + &w * &lf) * &lg);
        assert!(bound < pow2_inv(199), "bound {bound}");
        assert!(
            abs(&(&fr * &gr - &hr)) <= bound,
            "{f} · {g} ≠ {h} at {alpha}"
        );
    }

    fn constant(v: RBig) -> Poly<RBig> {
        Poly::constant(v)
    }

    use dashu_int::ops::BitTest;

    /// Sums, products and inverses against exact evaluation at rationals within `2⁻²⁰⁰` of `α`.
    #[test]
    fn arithmetic_agrees_with_rational_approximations() {
        let mut rng = Rng(7);
        for k in fields() {
            let alpha = k.alpha();
            let n = k.modulus().degree().unwrap();
            for _ in 0..4 {
                let a = k.element(&random_poly(&mut rng, n));
                let b = k.element(&random_poly(&mut rng, n));
                let (ar, br) = (a.representative(), b.representative());
                let sum = (&a + &b).representative();
                check_product_at_approximation(&alpha, &(&ar + &br), &constant(RBig::ONE), &sum);
                let product = (&a * &b).representative();
                assert!(product.degree() < Some(n));
                check_product_at_approximation(&alpha, &ar, &br, &product);
                let inv = a.inv().expect("a random element is nonzero");
                check_product_at_approximation(
                    &alpha,
                    &ar,
                    &inv.representative(),
                    &constant(RBig::ONE),
                );
                // x·x⁻¹ = 1 and the defining polynomial did not change (irreducible factor found
                // or not, nothing vanished)
                assert_eq!(&a * &inv, Nfe::one());
                assert_eq!(k.modulus().degree(), Some(n));
            }
        }
    }

    #[test]
    fn reducible_defining_polynomials_split() {
        let x2m2 = Poly::from_i64s(&[-2, 0, 1]);
        let x2m3 = Poly::from_i64s(&[-3, 0, 1]);
        let m = &x2m2 * &x2m3;
        let roots = AlgebraicReal::real_roots_of(&m); // −√3, −√2, √2, √3
                                                      // (root, is α² − 2 zero, sign of α, the factor it ends with)
        let cases = [
            (&roots[0], false, Sign::Negative, &x2m3),
            (&roots[1], true, Sign::Negative, &x2m2),
            (&roots[2], true, Sign::Positive, &x2m2),
            (&roots[3], false, Sign::Positive, &x2m3),
        ];
        for (alpha, sqrt2, sign, factor) in cases {
            let k = NumberField::new(alpha);
            let a = k.generator();
            let cube = &(&a * &a) * &a; // reduced modulo the quartic, before any split
            let e = &(&a * &a) - &Nfe::from_int(&2.into());
            assert_eq!(e.is_zero(), sqrt2, "α² − 2 at {alpha}");
            // a zero teaches the factor; a nonzero shown by interval arithmetic does not
            assert_eq!(k.modulus().degree(), Some(if sqrt2 { 2 } else { 4 }));
            let f = &(&a * &a) - &Nfe::from_int(&3.into());
            assert_eq!(f.inv().is_none(), !sqrt2, "1/(α² − 3) at {alpha}");
            assert_eq!(&k.modulus(), factor, "{alpha}");
            assert_eq!(a.sign(), sign);
            assert_eq!(e.sign() == Sign::Zero, sqrt2);
            if !sqrt2 {
                // √3: α² − 2 = 1
                assert_eq!(e, Nfe::one());
                assert_eq!(e.inv().unwrap(), Nfe::one());
            }
            // the element reduced modulo the old quartic is still α³
            let d = Nfe::from_int(&if sqrt2 { 2 } else { 3 }.into());
            assert_eq!(&cube * &cube, &(&d * &d) * &d);
            assert_eq!(&k.modulus(), factor);
        }
        // Inverting α² − 3 at √3 finds the factor x² − 3.
        let k = NumberField::new(&roots[3]);
        let a = k.generator();
        assert!((&(&a * &a) - &Nfe::from_int(&3.into())).inv().is_none());
        assert_eq!(k.modulus(), x2m3);
        // A rational root: α = 1 of (x − 1)(x² − 2), isolated by (1/2, 5/4).
        let m = &Poly::from_roots(&[1]) * &x2m2;
        let one = AlgebraicReal::from_isolating_interval(
            &m,
            &crate::roots::RootInterval::Open(rat(1, 2), rat(5, 4)),
        )
        .expect("1 is isolated");
        let k = NumberField::new(&one);
        let a = k.generator();
        let e = &(&a * &a) - &Nfe::from_int(&2.into());
        assert_eq!(e.inv(), Some(Nfe::from_int(&(-1).into())));
        assert_eq!(k.modulus(), Poly::from_roots(&[1]));
        assert_eq!(a, Nfe::one());
        assert_eq!(a.sign(), Sign::Positive);
    }

    #[test]
    fn gcds_over_an_extension() {
        let m = &Poly::from_i64s(&[-2, 0, 1]) * &Poly::from_i64s(&[-3, 0, 1]);
        let roots = AlgebraicReal::real_roots_of(&m);
        // x − c over ℚ(α)
        let lin = |c: &Nfe| Poly::new(vec![c.neg(), Nfe::one()]);
        let r = |v: i64| Nfe::from_int(&v.into());
        for (i, alpha) in roots.iter().enumerate() {
            let k = NumberField::new(alpha);
            let a = k.generator();
            let p = &lin(&a) * &lin(&r(-1));
            let q = &lin(&a) * &lin(&r(5));
            assert_eq!(p.gcd_monic(&q), lin(&a), "{alpha}");
            assert_eq!(p.gcd_domain(&q).monic(), lin(&a));
            // gcd(x² − 2, x − α) is x − α at ±√2 and 1 at ±√3 (a D5 split inside Euclid)
            let x2m2 = Poly::from_i64s(&[-2, 0, 1]).map(Nfe::from_int);
            let g = x2m2.gcd_monic(&lin(&a));
            let sqrt2 = i == 1 || i == 2;
            assert_eq!(
                g,
                if sqrt2 {
                    lin(&a)
                } else {
                    Poly::constant(Nfe::one())
                }
            );
            assert_eq!(k.modulus().degree(), Some(2));
        }
    }

    /// Resultants and discriminants over ℚ(α) agree with those over ℤ[t] evaluated at `α`,
    /// and with the product formulas over given roots.
    #[test]
    fn resultants_and_discriminants_over_the_field() {
        let mut rng = Rng(3);
        for k in fields() {
            let n = k.modulus().degree().unwrap();
            // P(t, y), Q(t, y) with constant leading coefficients in y
            let random_zt = |rng: &mut Rng, lead: bool| -> Poly<Poly> {
                let len = if lead { 4 } else { 3 };
                let mut c: Vec<Poly> = (0..len - 1)
                    .map(|_| Poly::from_i64s(&[rng.int(-5, 5), rng.int(-5, 5), rng.int(-5, 5)]))
                    .collect();
                c.push(Poly::from_i64s(&[rng.int(1, 3)]));
                Poly::new(c)
            };
            let (p, q) = (random_zt(&mut rng, true), random_zt(&mut rng, false));
            let at_alpha = |f: &Poly<Poly>| f.map(|c| k.integer_element(c));
            let (pa, qa) = (at_alpha(&p), at_alpha(&q));
            assert_eq!(pa.resultant(&qa), k.integer_element(&p.resultant(&q)));
            assert_eq!(pa.discriminant(), k.integer_element(&p.discriminant()));
            // p = ∏(y − aᵢ): res(p, q) = ∏ q(aᵢ), disc(p) = ∏_{i<j} (aᵢ − aⱼ)²
            let roots: Vec<Nfe> = (0..3)
                .map(|_| k.element(&random_poly(&mut rng, n)))
                .collect();
            let p = roots.iter().fold(Poly::constant(Nfe::one()), |acc, a| {
                &acc * &Poly::new(vec![a.neg(), Nfe::one()])
            });
            let expect = roots.iter().fold(Nfe::one(), |acc, a| acc * qa.eval(a));
            assert_eq!(p.resultant(&qa), expect);
            let mut disc = Nfe::one();
            for i in 0..3 {
                for j in i + 1..3 {
                    let d = &roots[i] - &roots[j];
                    disc = &disc * &(&d * &d);
                }
            }
            assert_eq!(p.discriminant(), disc);
            // a repeated root: zero
            let double = &p * &Poly::new(vec![roots[0].neg(), Nfe::one()]);
            assert!(double.discriminant().is_zero());
        }
    }

    /// Many signs at each root of a degree-12 polynomial with close pairs of roots, against
    /// the Sturm–Tarski route; elements near zero included (`T₆(α)` is `1/1024` at half the
    /// roots).
    #[test]
    fn many_signs_at_degree_12_roots() {
        let m = close_pairs_12();
        let t6 = chebyshev(6).to_rational();
        let mut rng = Rng(11);
        let mut nonzero = 0;
        for alpha in AlgebraicReal::real_roots_of(&m) {
            let k = NumberField::new(&alpha);
            let mut elements: Vec<Poly<RBig>> =
                (0..12).map(|_| random_poly(&mut rng, 12)).collect();
            elements.push(t6.clone());
            elements.push(&t6.scale(&RBig::from(1024)) - &constant(RBig::ONE));
            elements.push(&t6.scale(&RBig::from(1024)) - &constant(rat(1023, 1024)));
            for c in &elements {
                let e = k.element(c);
                let expect = alpha.sign_of_sturm_tarski(&Poly::from_rational(c).0);
                assert_eq!(e.sign(), expect, "{c} at {alpha}");
                assert_eq!(e.sign(), expect, "again");
                assert_eq!(e.is_zero(), expect == Sign::Zero);
                nonzero += usize::from(expect != Sign::Zero);
            }
            // the exact zero found the factor of α
            assert_eq!(k.modulus().degree(), Some(6));
        }
        assert!(nonzero >= 12 * 13);
    }

    /// The fast constructors build the representation of the general ones: `a + b·α` that of
    /// [`NumberField::integer_element`] (reduced when the defining polynomial has shrunk to
    /// degree 1), an integer that of [`Nfe::rational`].
    #[test]
    fn fast_constructors_equal_the_general_ones() {
        let mut rng = crate::testing::SplitMix(5);
        let same = |x: &Nfe, y: &Nfe| {
            x.numerator() == y.numerator()
                && x.denominator() == y.denominator()
                && x.field().is_some() == y.field().is_some()
                && x == y
        };
        // α = 2 as a root of (x − 2)(x² − 3): the modulus shrinks to x − 2 after a zero test
        let m = &Poly::from_i64s(&[-2, 1]) * &Poly::from_i64s(&[-3, 0, 1]);
        let two = AlgebraicReal::real_roots_of(&m).remove(2);
        let shrinking = NumberField::new(&two);
        let mut ks = fields();
        ks.push(NumberField::new(
            &AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-7, 0, 1]))[1],
        ));
        ks.push(shrinking.clone());
        for k in &ks {
            for i in 0..200 {
                let big = |rng: &mut crate::testing::SplitMix| {
                    IBig::from(rng.int(-99, 99)) << rng.int(0, 200) as usize
                };
                let (a, b) = match i % 4 {
                    0 => (big(&mut rng), IBig::ZERO),
                    1 => (IBig::ZERO, big(&mut rng)),
                    2 => (IBig::ZERO, IBig::ZERO),
                    _ => (big(&mut rng), big(&mut rng)),
                };
                let fast = k.linear_element(a.clone(), b.clone());
                let general = k.integer_element(&Poly::new(vec![a.clone(), b]));
                assert!(same(&fast, &general), "{fast} vs {general}");
                let int = Nfe::integer(a.clone());
                assert!(same(&int, &Nfe::rational(RBig::from(a))), "{int}");
            }
        }
        let e = &shrinking.generator() - &Nfe::integer(IBig::from(2));
        assert!(e.is_zero());
        assert_eq!(shrinking.modulus(), Poly::from_i64s(&[-2, 1]));
        // reduced modulo x − 2 now: 3 + 5α = 13
        let x = shrinking.linear_element(IBig::from(3), IBig::from(5));
        assert!(x.numerator().len() == 1 && x == Nfe::integer(IBig::from(13)));
        assert!(same(
            &x,
            &shrinking.integer_element(&Poly::from_i64s(&[3, 5]))
        ));
    }

    /// [`NumberField::sqrt`] is [`NumberField::new`] of the positive root of `x² − δ`: the
    /// same modulus, `α` and signs of `a + bα` (random `δ`, small and past `u64`), and `None`
    /// exactly for squares and `δ ≤ 0`.
    #[test]
    fn sqrt_field_equals_the_general_one() {
        let mut rng = crate::testing::SplitMix(0x5_9e7);
        for i in 0..120 {
            let delta = match i % 4 {
                0 => IBig::from(rng.int(-5, 60)),
                1 => IBig::from(rng.int(1, 1 << 20)).pow(2),
                2 => IBig::from(rng.int(1, 1 << 30)) << 70,
                _ => IBig::from(rng.int(1, 1 << 40)) * IBig::from(rng.int(1, 1 << 40)) + 1,
            };
            let roots = AlgebraicReal::real_roots_of(&Poly::new(vec![
                -delta.clone(),
                IBig::ZERO,
                IBig::ONE,
            ]));
            let general = match roots.last() {
                Some(r) if r.poly().degree() == Some(2) => NumberField::new(r),
                _ => {
                    assert!(NumberField::sqrt(&delta).is_none(), "δ = {delta}");
                    continue;
                }
            };
            let fast = NumberField::sqrt(&delta).expect("δ > 0 not a square");
            assert_eq!(fast.modulus(), general.modulus());
            assert_eq!(fast.alpha(), general.alpha());
            assert!(fast.alpha().is_valid());
            for _ in 0..5 {
                let (a, b) = (
                    IBig::from(rng.int(-999, 999)),
                    IBig::from(rng.int(-999, 999)),
                );
                let (x, y) = (
                    fast.linear_element(a.clone(), b.clone()),
                    general.linear_element(a, b),
                );
                assert_eq!(x.sign(), y.sign(), "δ = {delta}: {x}");
                assert_eq!(x.mul(&x).numerator(), y.mul(&y).numerator());
            }
        }
    }

    #[test]
    fn threads_share_one_field() {
        fn send_sync<T: Send + Sync + Clone>() {}
        send_sync::<NumberField>();
        send_sync::<Nfe>();
        let m = &Poly::from_i64s(&[-2, 0, 1]) * &Poly::from_i64s(&[-3, 0, 1]);
        let sqrt3 = AlgebraicReal::real_roots_of(&m).remove(3);
        let k = NumberField::new(&sqrt3);
        let a = k.generator();
        let r = |v: i64| Nfe::from_int(&v.into());
        std::thread::scope(|s| {
            for t in 0..2 {
                let a = a.clone();
                s.spawn(move || {
                    let sq = &a * &a;
                    let one_less = &a - &r(1);
                    let inv = one_less.inv().expect("√3 ≠ 1");
                    if t == 0 {
                        assert!(!(&sq - &r(2)).is_zero());
                    }
                    assert!((&sq - &r(3)).inv().is_none());
                    assert_eq!(&inv * &one_less, Nfe::one());
                    assert_eq!((&sq - &r(3)).sign(), Sign::Zero);
                });
            }
        });
        assert_eq!(k.modulus(), Poly::from_i64s(&[-3, 0, 1]));
        assert!((a.to_f64() - 3f64.sqrt()).abs() < 1e-12);
    }

    #[test]
    fn rationals_and_display() {
        let k = &fields()[0];
        let a = k.generator();
        let e = &(&a * &a) - &(&a * &Nfe::rational(rat(1, 3)));
        let e = &e + &Nfe::from_int(&5.into());
        assert_eq!(e.to_string(), "α^2 - 1/3*α + 5");
        assert_eq!((&a * &(&a * &a)).to_string(), "2");
        assert_eq!(
            Nfe::rational(rat(-2, 3)).inv(),
            Some(Nfe::rational(rat(-3, 2)))
        );
        assert_eq!(Nfe::zero().inv(), None);
        assert_eq!(Nfe::rational(rat(-2, 3)).sign(), Sign::Negative);
        assert!(format!("{k:?}").contains("x^3 - 2"));
    }

    /// `x` with its numerator on the heap whatever its length: the representation every
    /// numerator had before the inline form, which the arithmetic must still read right.
    fn heap_form(x: &Nfe) -> Nfe {
        Nfe {
            num: Numerator::Long(x.num.to_poly()),
            den: x.den.clone(),
            field: x.field.clone(),
        }
    }

    /// The inline numerators (rationals, ℚ(√δ), the reduction of a product of two linear
    /// numerators modulo a quadratic) give the representations and values of the heap form
    /// and of `ℚ[x]` arithmetic modulo the defining polynomial, under every operation, on
    /// random elements of quadratic (monic or not), cubic and shrinking fields.
    #[test]
    fn inline_numerators_agree_with_the_heap_form() {
        let mut rng = Rng(0x1e_f0);
        let root =
            |c: &[i64], i: usize| AlgebraicReal::real_roots_of(&Poly::from_i64s(c))[i].clone();
        // √2; −√(5/3); 1 as a root of 5x² + 2x − 7 and √2 as one of (x² − 2)(x² − 3) (both
        // shrink on a zero divisor); ∛2
        let ks = [
            NumberField::sqrt(&IBig::from(2)).unwrap(),
            NumberField::new(&root(&[-5, 0, 3], 0)),
            NumberField::new(&root(&[-7, 2, 5], 1)),
            NumberField::new(&root(&[6, 0, -5, 0, 1], 2)),
            NumberField::new(&root(&[-2, 0, 0, 1], 0)),
        ];
        let same = |x: &Nfe, y: &Nfe| {
            x.numerator() == y.numerator()
                && x.denominator() == y.denominator()
                && x.to_string() == y.to_string()
                && x == y
        };
        for k in &ks {
            let degree = k.modulus().degree().unwrap();
            let element = |rng: &mut Rng| {
                let big = |rng: &mut Rng| IBig::from(rng.int(-9, 9)) << rng.int(0, 90) as usize;
                let len = rng.int(0, degree as i64) as usize;
                let c: Vec<RBig> = (0..len)
                    .map(|_| RBig::from_parts_signed(big(rng), IBig::from(rng.int(1, 4))))
                    .collect();
                match rng.int(0, 3) {
                    0 => Nfe::rational(c.first().cloned().unwrap_or(RBig::ZERO)),
                    1 => k.linear_element(big(rng), big(rng)),
                    _ => k.element(&Poly::new(c)),
                }
            };
            for _ in 0..150 {
                let (a, b) = (element(&mut rng), element(&mut rng));
                let (ha, hb) = (heap_form(&a), heap_form(&b));
                // r(x) − r(y)·op mod m = 0 over ℚ (the current modulus divides the older ones)
                let holds = |z: &Nfe, expected: &Poly<RBig>| {
                    let m = k.modulus().to_rational();
                    (&z.representative() - expected).rem(&m).is_zero()
                };
                let (ra, rb) = (a.representative(), b.representative());
                let (sum, product, neg) = (&a + &b, &a * &b, -a.clone());
                assert!(
                    holds(&sum, &(&ra + &rb)) && holds(&product, &(&ra * &rb)),
                    "{a}, {b}"
                );
                assert!(holds(&neg, &-&ra));
                for (x, y) in [(&ha, &hb), (&a, &hb), (&ha, &b)] {
                    assert!(same(&(x + y), &sum), "{x} + {y}");
                    assert!(same(&(x - y), &(&a - &b)), "{x} − {y}");
                    assert!(same(&(x * y), &product), "{x} · {y}");
                    assert!(same(&-x.clone(), &neg));
                    assert_eq!(x == y, a == b);
                    assert_eq!(x.sign(), a.sign());
                    assert_eq!(x.is_zero(), a.is_zero());
                    assert!((x.to_f64() - a.to_f64()).abs() <= 1e-9 * a.to_f64().abs().max(1.0));
                    match (x.inv(), a.inv()) {
                        (Some(u), Some(v)) => assert!(same(&u, &v) && (&u * x).is_one()),
                        (None, None) => assert!(a.is_zero()),
                        _ => panic!("{x}: inverses differ"),
                    }
                }
                // the values: a short form only where the numerator has at most two terms
                assert!(same(&ha, &a) && same(&hb, &b));
                for z in [&a, &b, &sum, &product, &neg] {
                    assert_eq!(
                        matches!(z.num, Numerator::Short(..)),
                        z.numerator().len() <= 2
                    );
                }
            }
        }
    }

    #[test]
    #[should_panic(expected = "different number fields")]
    fn different_fields_do_not_mix() {
        let f = fields();
        let _ = f[0].generator() + f[1].generator();
    }

    proptest! {
        /// The integer remainder sequences: `k·a = q·b + r`, and `S·c ≡ r (mod m)` with a
        /// nonzero integer `r`, or the gcd (checked against [`Poly::gcd`]).
        #[test]
        fn integer_division_and_inverses(
            a in prop::collection::vec(-30i64..30, 1..9),
            b in prop::collection::vec(-30i64..30, 2..6),
            f in prop::collection::vec(-5i64..5, 1..4),
        ) {
            let (a, b, f) = (Poly::from_i64s(&a), Poly::from_i64s(&b), Poly::from_i64s(&f));
            prop_assume!(b.degree().unwrap_or(0) > 0 && a.degree() >= b.degree() && !f.is_zero());
            let (k, q, r) = pseudo_div_rem(&a, &b);
            prop_assert_eq!(&a.scale(&k), &(&(&q * &b) + &r));
            prop_assert!(r.degree() < b.degree());
            // a shared factor f makes c = a·f a zero divisor modulo m = b·f
            let (c, m) = (&a * &f, &b * &f);
            match inverse_mod(&c, &m) {
                Ok((s, r)) => {
                    prop_assert!(!r.is_zero());
                    prop_assert!((&(&s * &c) - &Poly::constant(r)).pseudo_rem(&m).is_zero());
                    prop_assert_eq!(c.gcd(&m).degree(), Some(0));
                }
                Err(g) => {
                    prop_assert!(g.degree().unwrap_or(0) > 0);
                    prop_assert_eq!(g, c.gcd(&m));
                }
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]
        #[test]
        fn field_identities(
            which in 0usize..4,
            a in prop::collection::vec((-20i64..20, 1i64..6), 0..12),
            b in prop::collection::vec((-20i64..20, 1i64..6), 0..12),
            c in prop::collection::vec((-20i64..20, 1i64..6), 0..12),
        ) {
            let k = &fields()[which];
            let el = |v: &[(i64, i64)]| {
                k.element(&Poly::new(v.iter().map(|&(n, d)| rat(n, d)).collect()))
            };
            let (a, b, c) = (el(&a), el(&b), el(&c));
            prop_assert_eq!(&(&a * &b) * &c, &a * &(&b * &c));
            prop_assert_eq!(&a * &(&b + &c), &(&a * &b) + &(&a * &c));
            prop_assert_eq!(&(&a - &b) + &b, a.clone());
            match a.inv() {
                Some(i) => prop_assert_eq!(&a * &i, Nfe::one()),
                None => prop_assert!(a.is_zero()),
            }
            // signs: against the float where it is far from zero, and additive order
            let (s, f) = (a.sign(), a.to_f64());
            if f.abs() > 1e-6 {
                prop_assert_eq!(s, if f > 0.0 { Sign::Positive } else { Sign::Negative });
            }
            prop_assert_eq!(s == Sign::Zero, a.is_zero());
            prop_assert_eq!((&a - &b).sign() == Sign::Zero, a == b);
            prop_assert_eq!((&a * &a).sign() == Sign::Positive, s != Sign::Zero);
        }
    }
}
