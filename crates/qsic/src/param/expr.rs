//! Exact numbers and polynomials in `u` as strings a computer algebra system reads (sympy
//! syntax: integers, `p/q`, `sqrt(n)`, `+ - * / ^`, parentheses, the variable `u`, names of
//! algebraic numbers).
//!
//! A [`Number`] `c(α)/d` of ℚ(α) prints by the degree of the field's defining polynomial `m`:
//! - degree 1 (or a constant numerator): the rational;
//! - degree 2, `m = m₂x² + m₁x + m₀`: `α = (−m₁ + σ√D)/(2m₂)`, `D = m₁² − 4m₂m₀`, `σ` the
//!   sign of `2m₂α + m₁` (exact); so `c = p + q·sqrt(n)` with `D = k²n` (small square
//!   factors taken out), or a rational when `D` is a square;
//! - degree > 2: a polynomial in a name `a1`, `a2`, … — one per distinct `α` met by a
//!   [`Names`] — listed by [`Names::numbers`] with `m` and an isolating interval. A number
//!   beyond `2^±16` in size is named scaled, `β = α/2ᵉ` near 1 (its polynomial `m(2ᵉx)`,
//!   and `2^(ej)` in the coefficient of `αʲ`), so that a checker evaluating the polynomial
//!   near the root in floating point meets terms near 1, not `|α|⁴ ≈ 10¹⁶⁶`.
//!
//! A [`Names`] works out the form of each field of degree ≤ 2 once (`α` rational, or
//! `D = k²n`, `σ` and `t = σk/(2m₂)`: the cost of `σ` and of the trial division of `D` is
//! paid once per field and answer, not per coefficient). The form holds while the defining
//! polynomial does, and that polynomial changes only by shrinking to a factor — of smaller
//! degree — so the field and its degree identify it. `m` of degree 2 with `D` not a square
//! is irreducible, so an element `(C₀ + C₁α)/d` reduced modulo `m` is zero exactly when
//! `C₀ = C₁ = 0`: a coefficient of a polynomial is left out without the field's zero test
//! (an element of a field of degree > 2 still takes it). Fractions are reduced in integers
//! (nothing to do when `d = 1`), and the text is written once, into bytes.

use super::curve::{Number, NumberPoly};
use qsic_algebra::field::NumberField;
use qsic_algebra::poly::sturm::SturmSequence;
use qsic_algebra::{AlgebraicReal, IBig, Poly, RBig, Ring, Sign};

/// An algebraic number of degree > 2 named in expressions.
#[derive(Clone, Debug, PartialEq)]
pub struct NamedNumber {
    /// `a1`, `a2`, …
    pub name: String,
    /// Its defining polynomial, in `x`, monic with rational coefficients (square-free; it
    /// vanishes at the number).
    pub poly: String,
    /// An interval `[lo, hi]` isolating it among the real roots of `poly` (`lo = hi` when
    /// exact), as `p/q` strings.
    pub interval: [String; 2],
    /// A float approximation.
    pub approx: f64,
}

/// The names given to algebraic numbers of degree > 2 while printing one answer.
#[derive(Clone, Debug, Default)]
pub struct Names {
    /// Each named number `α` with its binary exponent `e`: the name stands for `α/2ᵉ`.
    named: Vec<(AlgebraicReal, i64)>,
    /// The fields of degree ≤ 2 met, with the degree of their defining polynomial when the
    /// form was worked out.
    forms: Vec<(NumberField, usize, Form)>,
}

/// Numbers beyond `2^±SCALE_BITS` are named scaled by a power of two (module docs).
const SCALE_BITS: i64 = 16;

/// The exponent `e` with `α/2ᵉ` near 1 when `|α|` is beyond `2^±SCALE_BITS`, else 0.
fn scale_exponent(alpha: &AlgebraicReal) -> i64 {
    let v = alpha.to_f64().abs();
    if v == 0.0 || !v.is_finite() {
        return 0;
    }
    let e = v.log2().floor() as i64;
    if e.abs() > SCALE_BITS {
        e
    } else {
        0
    }
}

/// `2ᵉ` as a rational.
pub(crate) fn power_of_two(e: i64) -> RBig {
    let p = RBig::from(IBig::ONE << e.unsigned_abs() as usize);
    if e >= 0 {
        p
    } else {
        RBig::ONE / p
    }
}

/// `p/q` (or `p`), with a leading `-` when negative.
pub fn rational_to_string(v: &RBig) -> String {
    v.to_string()
}

/// Whether `s` is a single term (no top-level `+` or binary `-`): safe before `*`.
fn is_term(s: &str) -> bool {
    let mut depth = 0i32;
    for (i, ch) in s.char_indices() {
        match ch {
            '(' => depth += 1,
            ')' => depth -= 1,
            '+' | '-' if depth == 0 && i > 0 => return false,
            _ => {}
        }
    }
    true
}

/// `v ≥ 0` with its square factors below 1000 taken out: `(k, n)` with `v = k²n`. Trial
/// division by `p = 2, 3, 5, 7, 9, …` while `p² ≤ n` (no larger `p²` divides `n`; an odd
/// composite `p` divides no more once its prime factors are out), in machine words when `v`
/// fits one.
fn square_out(v: &IBig) -> (IBig, IBig) {
    match u64::try_from(v) {
        Ok(w) => {
            let (k, n) = square_out_u64(w);
            (IBig::from(k), IBig::from(n))
        }
        Err(_) => square_out_big(v),
    }
}

/// [`square_out`] in big integers.
fn square_out_big(v: &IBig) -> (IBig, IBig) {
    let (mut k, mut n) = (IBig::ONE, v.clone());
    let mut p = 2u32;
    while p < 1000 {
        let pp = IBig::from(p * p);
        if n < pp {
            break;
        }
        while (&n % &pp).is_zero() {
            n /= &pp;
            k *= IBig::from(p);
        }
        p += if p == 2 { 1 } else { 2 };
    }
    (k, n)
}

/// [`square_out`] of a machine word (`k ≤ √v` fits one too).
fn square_out_u64(v: u64) -> (u64, u64) {
    let (mut k, mut n) = (1u64, v);
    let mut p = 2u64;
    while p < 1000 && p * p <= n {
        while n % (p * p) == 0 {
            n /= p * p;
            k *= p;
        }
        p += if p == 2 { 1 } else { 2 };
    }
    (k, n)
}

/// `⌊√v⌋` if `v ≥ 0` is a perfect square.
fn exact_sqrt(v: &IBig) -> Option<IBig> {
    use dashu_int::ops::{SquareRoot, UnsignedAbs};
    if *v < IBig::ZERO {
        return None;
    }
    let r = IBig::from(v.unsigned_abs().sqrt());
    (&r * &r == *v).then_some(r)
}

/// How the elements `(C₀ + C₁α)/d` of a field of degree ≤ 2 print: worked out once per field
/// and answer (module docs), from the defining polynomial `m`.
#[derive(Clone, Debug)]
enum Form {
    /// `α` is the rational `a`: `m` of degree 1, or of degree 2 with a square discriminant.
    Rational(RBig),
    /// `α = (−m₁ + σk√n)/(2m₂)`, `D = k²n` not a square: `m` is irreducible, so an element of
    /// degree < 2 is zero exactly when its numerator is, and it is `p + q√n` with
    /// `p = (2m₂C₀ − m₁C₁)/(2m₂d)`, `q = C₁t/d`, `t = σk/(2m₂)`.
    Surd {
        /// `m₁`.
        m1: IBig,
        /// `2m₂`.
        two_m2: IBig,
        /// `t` as a reduced fraction, positive denominator.
        t: (IBig, IBig),
        /// `sqrt(n)`.
        sqrt: String,
    },
}

impl Form {
    /// The form of `ℚ(α)` when its defining polynomial has degree ≤ 2.
    fn of(alpha: &AlgebraicReal) -> Option<Form> {
        let m = alpha.poly();
        match m.degree() {
            Some(1) => Some(Form::Rational(
                -RBig::from(m.coeff(0)) / RBig::from(m.coeff(1)),
            )),
            Some(2) => {
                let (m0, m1, m2) = (m.coeff(0), m.coeff(1), m.coeff(2));
                let disc = &m1 * &m1 - IBig::from(4) * &m0 * &m2;
                // σ = sign(2m₂α + m₁); with m₁ = 0 (`x² − δ`) it is sign(m₂)·sign(α), and
                // α ≠ 0 (m₀ ≠ 0 for a square-free m) is read off an isolating interval that
                // does not hold 0
                let iv = alpha.interval();
                let alpha_sign = if *iv.lo() >= RBig::ZERO {
                    Some(false)
                } else if *iv.hi() <= RBig::ZERO {
                    Some(true)
                } else {
                    None
                };
                let sigma_negative = match alpha_sign {
                    Some(alpha_negative) if m1.is_zero() => alpha_negative != negative(&m2),
                    _ => {
                        let g = Poly::new(vec![m1.clone(), IBig::from(2) * &m2]);
                        alpha.sign_of(&g) == Sign::Negative
                    }
                };
                let sigma = if sigma_negative {
                    -IBig::ONE
                } else {
                    IBig::ONE
                };
                let two_m2 = IBig::from(2) * &m2;
                Some(match exact_sqrt(&disc) {
                    Some(r) => Form::Rational(RBig::from(-m1 + sigma * r) / RBig::from(two_m2)),
                    None => {
                        let (k, n) = square_out(&disc);
                        Form::Surd {
                            m1,
                            t: reduced(sigma * k, two_m2.clone()),
                            two_m2,
                            sqrt: format!("sqrt({n})"),
                        }
                    }
                })
            }
            _ => None,
        }
    }
}

/// `v < 0`.
fn negative(v: &IBig) -> bool {
    v.sign() == dashu_int::Sign::Negative
}

/// `v = ±1`.
fn unit(v: &IBig) -> bool {
    v.is_one() || *v == IBig::NEG_ONE
}

/// `n/d` in lowest terms with `d > 0` (given `d ≠ 0`).
fn reduced(n: IBig, d: IBig) -> (IBig, IBig) {
    let (n, d) = if negative(&d) { (-n, -d) } else { (n, d) };
    if d.is_one() {
        return (n, d);
    }
    if n.is_zero() {
        return (n, IBig::ONE);
    }
    let g = qsic_algebra::int_gcd(&n, &d);
    if g.is_one() {
        (n, d)
    } else {
        (n / &g, d / &g)
    }
}

/// The two-digit strings `00`, `01`, …, `99`, concatenated.
const PAIRS: &[u8; 200] = b"\
0001020304050607080910111213141516171819202122232425262728293031323334353637383940414243444546474849\
5051525354555657585960616263646566676869707172737475767778798081828384858687888990919293949596979899";

/// Appends the decimal digits of `v`, two at a time from [`PAIRS`], in words of 19 digits
/// below `2⁶⁴` (`10¹⁹ < 2⁶⁴`: one 128-bit division a word), without the formatting
/// machinery (a `u128` has at most 39 digits).
fn push_u128(out: &mut Vec<u8>, v: u128) {
    const WORD: u128 = 10_000_000_000_000_000_000;
    let mut digits = [b'0'; 40];
    let mut end = digits.len();
    let mut rest = v;
    loop {
        // the last 19 digits (all of them below 2⁶⁴), zeros in front when more follow
        let (mut word, high) = match u64::try_from(rest) {
            Ok(w) => (w, None),
            Err(_) => {
                let high = rest / WORD;
                // below 10¹⁹
                ((rest - high * WORD) as u64, Some(high))
            }
        };
        let mut at = end;
        while word >= 100 {
            let k = (word % 100) as usize * 2;
            word /= 100;
            at -= 2;
            digits[at..at + 2].copy_from_slice(&PAIRS[k..k + 2]);
        }
        if word >= 10 {
            let k = word as usize * 2;
            at -= 2;
            digits[at..at + 2].copy_from_slice(&PAIRS[k..k + 2]);
        } else {
            at -= 1;
            digits[at] = b'0' + word as u8;
        }
        let Some(high) = high else {
            out.extend_from_slice(&digits[at..]);
            return;
        };
        rest = high;
        end -= 19;
    }
}

/// Appends the integer `v`, with a leading `-` when negative and `signed` (else `|v|`).
fn push_int(out: &mut Vec<u8>, v: &IBig, signed: bool) {
    use dashu_int::ops::UnsignedAbs;
    if signed && negative(v) {
        out.push(b'-');
    }
    match i128::try_from(v) {
        Ok(small) => push_u128(out, small.unsigned_abs()),
        Err(_) => out.extend_from_slice(v.unsigned_abs().to_string().as_bytes()),
    }
}

/// Appends the reduced fraction `n/d` (`n` when `d = 1`) as [`rational_to_string`] does, or
/// `|n|/d` when not `signed`.
fn push_fraction(out: &mut Vec<u8>, n: &IBig, d: &IBig, signed: bool) {
    push_int(out, n, signed);
    if !d.is_one() {
        out.push(b'/');
        push_int(out, d, true);
    }
}

/// The text of the bytes an expression was written in: ASCII (digits, the names `sqrt`,
/// `u`, `a1`, …, and `+ - * / ^ ( )`), so UTF-8.
fn ascii(bytes: Vec<u8>) -> String {
    String::from_utf8(bytes).unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned())
}

/// A nonzero number as it prints, before its text is written.
enum Value {
    /// The reduced fraction `n/d` (`d > 0`).
    Fraction(IBig, IBig),
    /// `p + q·sqrt(n)` (`q ≠ 0`), reduced fractions; `sqrt(n)` is the text of the form
    /// `form` of [`Names::forms`].
    Surd {
        p: (IBig, IBig),
        q: (IBig, IBig),
        form: usize,
    },
    /// A polynomial in the name of a number of degree > 2, as text.
    Named(String),
}

impl Value {
    /// One term (no top-level `+` or binary `-`): safe before `*`.
    fn is_term(&self) -> bool {
        match self {
            Value::Fraction(..) => true,
            Value::Surd { p, .. } => p.0.is_zero(),
            Value::Named(text) => is_term(text),
        }
    }

    /// A term written with a leading `-`.
    fn is_negative(&self) -> bool {
        match self {
            Value::Fraction(n, _) => negative(n),
            Value::Surd { p, q, .. } => p.0.is_zero() && negative(&q.0),
            Value::Named(text) => text.starts_with('-') && is_term(text),
        }
    }

    /// `±1`.
    fn is_unit(&self) -> bool {
        match self {
            Value::Fraction(n, d) => d.is_one() && unit(n),
            _ => false,
        }
    }
}

impl Names {
    /// No names yet.
    pub fn new() -> Names {
        Names::default()
    }

    /// The name of `alpha` (a new one if it is new).
    fn name_of(&mut self, alpha: &AlgebraicReal) -> (String, i64) {
        let k = match self
            .named
            .iter()
            // roots of one square-free polynomial are equal iff their isolating intervals
            // meet (no refinement, no comparison that could be costly)
            .position(|(a, _)| a.poly() == alpha.poly() && intervals_meet(a, alpha))
        {
            Some(k) => k,
            None => {
                self.named.push((alpha.clone(), scale_exponent(alpha)));
                self.named.len() - 1
            }
        };
        (format!("a{}", k + 1), self.named[k].1)
    }

    /// The index in [`Names::forms`] of the form of `field` when its degree is at most 2 (a
    /// changed defining polynomial has a smaller degree: a new entry).
    fn form_of(&mut self, field: &NumberField) -> Option<usize> {
        let degree = field.degree();
        if degree > 2 {
            return None;
        }
        if let Some(k) = self
            .forms
            .iter()
            .position(|(f, d, _)| *d == degree && f.same_as(field))
        {
            return Some(k);
        }
        let alpha = field.alpha();
        let form = Form::of(&alpha)?;
        let degree = alpha.poly().degree().unwrap_or(0);
        self.forms.push((field.clone(), degree, form));
        Some(self.forms.len() - 1)
    }

    /// The value of `c` as it prints; `None` when `c = 0` is known without the field's zero
    /// test — a rational, or an element of a field of degree ≤ 2 (decided from the numerator:
    /// [`Form`]). An element of a larger field is a polynomial in its name whatever its
    /// value (the caller tests it).
    fn value(&mut self, c: &Number) -> Option<Value> {
        let Some(field) = c.field().filter(|_| c.numerator().len() > 1) else {
            let n = c.numerator().first()?;
            let (n, d) = reduced(n.clone(), c.denominator().clone());
            return Some(Value::Fraction(n, d));
        };
        let Some(k) = self.form_of(field) else {
            return Some(Value::Named(self.named_text(c, field)));
        };
        // `(C₀ + C₁α)/d`: the numerator reduced modulo `m` (it is, unless computed modulo
        // a multiple of `m` since replaced)
        let (c0, c1, d) = match *c.numerator() {
            [ref c0, ref c1] if self.forms[k].1 == 2 => {
                (c0.clone(), c1.clone(), c.denominator().clone())
            }
            _ => {
                let rep = c.representative().rem(&field.modulus().to_rational());
                let (r0, r1) = (rep.coeff(0), rep.coeff(1));
                let d = IBig::from(r0.denominator().clone()) * IBig::from(r1.denominator().clone());
                let d_r = RBig::from(d.clone());
                let int = |r: RBig| (r * &d_r).numerator().clone();
                (int(r0), int(r1), d)
            }
        };
        match &self.forms[k].2 {
            Form::Rational(a) => {
                let v = (RBig::from(c0) + RBig::from(c1) * a) / RBig::from(d);
                (!v.is_zero()).then(|| {
                    Value::Fraction(v.numerator().clone(), IBig::from(v.denominator().clone()))
                })
            }
            Form::Surd { .. } if c1.is_zero() => (!c0.is_zero()).then(|| {
                let (n, d) = reduced(c0, d);
                Value::Fraction(n, d)
            }),
            Form::Surd { m1, two_m2, t, .. } => {
                let p = if m1.is_zero() {
                    reduced(c0, d.clone())
                } else {
                    reduced(two_m2 * &c0 - m1 * &c1, two_m2 * &d)
                };
                let q = if t.0.is_one() && t.1.is_one() {
                    reduced(c1, d)
                } else {
                    reduced(c1 * &t.0, &t.1 * d)
                };
                Some(Value::Surd { p, q, form: k })
            }
        }
    }

    /// `c` in a field of degree > 2: a polynomial in the name of `α` (scaled: module docs).
    fn named_text(&mut self, c: &Number, field: &NumberField) -> String {
        let alpha = field.alpha();
        let rep = c.representative().rem(&alpha.poly().to_rational());
        let (name, e) = self.name_of(&alpha);
        // α = 2ᵉ·β with β the name: the coefficient of αʲ times 2^(ej)
        let scaled = Poly::new(
            rep.coeffs()
                .iter()
                .enumerate()
                .map(|(j, c)| c * power_of_two(e * j as i64))
                .collect(),
        );
        scaled.to_string().replace('x', &name)
    }

    /// Appends the text of `v`, without the leading `-` of a negative term when `magnitude`.
    fn write(&self, v: &Value, magnitude: bool, out: &mut Vec<u8>) {
        let signed = !magnitude;
        match v {
            Value::Fraction(n, d) => push_fraction(out, n, d, signed),
            Value::Surd { p, q, form } => {
                let q_negative = negative(&q.0);
                if !p.0.is_zero() {
                    push_fraction(out, &p.0, &p.1, true);
                    out.extend_from_slice(if q_negative { b" - " } else { b" + " });
                } else if q_negative && signed {
                    out.push(b'-');
                }
                if !(q.1.is_one() && unit(&q.0)) {
                    push_fraction(out, &q.0, &q.1, false);
                    out.push(b'*');
                }
                if let Form::Surd { sqrt, .. } = &self.forms[*form].2 {
                    out.extend_from_slice(sqrt.as_bytes());
                }
            }
            Value::Named(text) => {
                let text = text.as_bytes();
                out.extend_from_slice(if magnitude && v.is_negative() {
                    &text[1..]
                } else {
                    text
                });
            }
        }
    }

    /// The exact number `c` as an expression.
    ///
    /// ```
    /// use qsic::param::{curve::sqrt_field, expr::Names};
    /// use qsic_algebra::{IBig, Poly, RBig};
    /// let k = sqrt_field(&IBig::from(8)); // ℚ(√8), α = √8 = 2√2
    /// let c = k.element(&Poly::new(vec![RBig::from(1), RBig::from_parts(1.into(), 4u8.into())]));
    /// assert_eq!(Names::new().number(&c), "1 + 1/2*sqrt(2)"); // 1 + √8/4
    /// ```
    pub fn number(&mut self, c: &Number) -> String {
        let mut out = Vec::new();
        match self.value(c) {
            Some(v) => self.write(&v, false, &mut out),
            None => out.push(b'0'),
        }
        ascii(out)
    }

    /// The polynomial `p(u)` as an expression in `u`.
    ///
    /// ```
    /// use qsic::param::{curve::rational, expr::Names};
    /// use qsic_algebra::{Poly, RBig};
    /// let p = Poly::new(vec![rational(RBig::from(-1)), rational(RBig::ZERO), rational(RBig::from(3))]);
    /// assert_eq!(Names::new().poly(&p), "3*u^2 - 1");
    /// ```
    pub fn poly(&mut self, p: &NumberPoly) -> String {
        let mut out = Vec::with_capacity(32 * p.coeffs().len());
        for (k, c) in p.coeffs().iter().enumerate().rev() {
            // an element of a field of degree > 2 may be zero whatever its numerator: the
            // field decides (and may shrink its defining polynomial) before it is named
            let named = c.numerator().len() > 1 && c.field().is_some_and(|f| f.degree() > 2);
            if named && c.is_zero() {
                continue;
            }
            let Some(v) = self.value(c) else {
                continue;
            };
            let neg = v.is_negative();
            if out.is_empty() {
                if neg {
                    out.push(b'-');
                }
            } else {
                out.extend_from_slice(if neg { b" - " } else { b" + " });
            }
            if k == 0 || !v.is_unit() {
                let term = v.is_term();
                if !term {
                    out.push(b'(');
                }
                self.write(&v, true, &mut out);
                if !term {
                    out.push(b')');
                }
                if k > 0 {
                    out.push(b'*');
                }
            }
            match k {
                0 => {}
                1 => out.push(b'u'),
                _ => {
                    out.extend_from_slice(b"u^");
                    push_u128(&mut out, k as u128);
                }
            }
        }
        if out.is_empty() {
            out.push(b'0');
        }
        ascii(out)
    }

    /// The numbers named so far, in order of their names.
    pub fn numbers(&self) -> Vec<NamedNumber> {
        let width = RBig::from_parts_signed(IBig::ONE, IBig::ONE << 40);
        self.named
            .iter()
            .enumerate()
            .map(|(k, (a, e))| {
                let scale = power_of_two(*e);
                // β = α/2ᵉ is a root of m(2ᵉx)
                let poly = Poly::new(
                    a.poly()
                        .to_rational()
                        .coeffs()
                        .iter()
                        .enumerate()
                        .map(|(i, c)| c * power_of_two(e * i as i64))
                        .collect(),
                );
                let iv = a.refined_interval(&(&width * &scale));
                let (lo, hi) = short_ends(&poly, &(iv.lo() / &scale), &(iv.hi() / &scale));
                NamedNumber {
                    name: format!("a{}", k + 1),
                    // monic: a checker evaluating it near the root in floating point
                    // sees terms of the size of the root's powers, not of the integer
                    // content (which can be 10⁶⁰ for a disguised pencil)
                    poly: poly.monic().to_string(),
                    interval: [lo.to_string(), hi.to_string()],
                    approx: a.to_f64() / 2f64.powi(*e as i32),
                }
            })
            .collect()
    }
}

/// Ends of few digits for an isolating interval `[lo, hi]` of `a` (the shared refinement may
/// be far finer, with ends of thousands of digits): rounded outward to multiples of `2⁻ᵏ`,
/// the least `k ≥ 48` for which the rounded interval still holds exactly one root of `a`'s
/// polynomial (Sturm), else the ends as they are.
fn short_ends(poly: &Poly<RBig>, lo: &RBig, hi: &RBig) -> (RBig, RBig) {
    if lo == hi {
        return (lo.clone(), hi.clone());
    }
    let (int_poly, _) = Poly::from_rational(poly);
    let sturm = SturmSequence::new(&int_poly);
    for k in [48usize, 64, 96, 128, 192, 256] {
        let scale = RBig::from(IBig::ONE << k);
        let down = RBig::from((lo * &scale).floor()) / &scale;
        let up = RBig::from((hi * &scale).ceil()) / &scale;
        let ends_not_roots =
            !int_poly.eval_rational(&down).is_zero() && !int_poly.eval_rational(&up).is_zero();
        if ends_not_roots && sturm.count_roots_in(&down, &up) == 1 {
            return (down, up);
        }
    }
    (lo.clone(), hi.clone())
}

/// Whether the isolating intervals of two roots of the same polynomial meet.
fn intervals_meet(a: &AlgebraicReal, b: &AlgebraicReal) -> bool {
    let (x, y) = (a.interval(), b.interval());
    match (x.as_exact(), y.as_exact()) {
        (Some(u), Some(v)) => u == v,
        (Some(u), None) => y.lo() < u && u < y.hi(),
        (None, Some(v)) => x.lo() < v && v < x.hi(),
        (None, None) => x.lo() < y.hi() && y.lo() < x.hi(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::{parse_rational_function, Variable};
    use crate::param::curve::{rational, sqrt_field};
    use qsic_algebra::mpoly::{MPoly, Monomial};
    use qsic_algebra::testing::SplitMix;

    const U: usize = 5;
    const T: usize = 4;

    fn r(n: i64, d: i64) -> RBig {
        RBig::from_parts_signed(n.into(), d.unsigned_abs().into())
    }

    /// Reads `text` back with `name` (a `sqrt(n)` or a number's name) replaced by `t`.
    fn read_back(text: &str, name: &str) -> MPoly {
        let f = parse_rational_function(&text.replace(name, "t"), &[Variable::U, Variable::T])
            .unwrap_or_else(|e| panic!("{text}: {e}"));
        assert!(f.is_polynomial(), "{text}");
        f.numerator().clone()
    }

    /// The coefficient of `tʲuᵏ`.
    fn coefficient(p: &MPoly, j: usize, k: usize) -> RBig {
        let mut m = Monomial::default();
        for _ in 0..j {
            m = m.mul(&Monomial::var(T));
        }
        for _ in 0..k {
            m = m.mul(&Monomial::var(U));
        }
        p.coefficient(&m).cloned().unwrap_or(RBig::ZERO)
    }

    fn random_poly(
        rng: &mut SplitMix,
        field: &NumberField,
        degree: usize,
        coeffs: usize,
    ) -> NumberPoly {
        Poly::new(
            (0..=degree)
                .map(|_| {
                    let c: Vec<RBig> = (0..coeffs)
                        .map(|_| r(rng.int(-9, 9), rng.int(1, 5)))
                        .collect();
                    field.element(&Poly::new(c))
                })
                .collect(),
        )
    }

    #[test]
    fn rational_and_quadratic_polynomials_read_back_exactly() {
        let mut rng = SplitMix(11);
        for delta in [2i64, 3, 8, 12, 50, 1_000_003] {
            let k = sqrt_field(&IBig::from(delta));
            for degree in 0..4 {
                let p = random_poly(&mut rng, &k, degree, 2);
                let text = Names::new().poly(&p);
                let (_, n) = square_out(&IBig::from(delta));
                let sq = format!("sqrt({n})");
                let f = read_back(&text, &sq);
                // every coefficient c = P + Q·√n: (c − P)² = Q²·n with the sign of Q
                for (j, c) in p.coeffs().iter().enumerate() {
                    let (pp, qq) = (coefficient(&f, 0, j), coefficient(&f, 1, j));
                    assert!(f.degree_in(T) <= 1, "{text}");
                    let x = c.sub(&rational(pp));
                    let want = rational(&qq * &qq * RBig::from(n.clone()));
                    assert_eq!(x.mul(&x), want, "{text}, u^{j}");
                    assert_eq!(x.sign(), Sign::of(qq.numerator()), "{text}, u^{j}");
                }
            }
        }
        // rational polynomials: the reader gives the same polynomial
        for _ in 0..20 {
            let c: Vec<RBig> = (0..5).map(|_| r(rng.int(-30, 30), rng.int(1, 7))).collect();
            let p: NumberPoly = Poly::new(c.iter().cloned().map(rational).collect());
            let text = Names::new().poly(&p);
            let f = read_back(&text, "sqrt");
            for (j, v) in c.iter().enumerate() {
                assert_eq!(&coefficient(&f, 0, j), v, "{text}");
            }
        }
    }

    #[test]
    fn quadratic_fields_given_by_any_quadratic_print_the_right_root() {
        // α the smaller or larger root of 3x² − 5x + 1 (D = 13), and of x² − 4x + 1 (D = 12)
        for m in [[1i64, -5, 3], [1, -4, 1]] {
            let roots = AlgebraicReal::real_roots_of(&Poly::from_i64s(&m));
            for alpha in roots {
                let k = NumberField::new(&alpha);
                let text = Names::new().number(&k.generator());
                let disc = m[1] * m[1] - 4 * m[0] * m[2];
                let (_, n) = square_out(&IBig::from(disc));
                let f = read_back(&text, &format!("sqrt({n})"));
                let value = coefficient(&f, 0, 0).to_f64().value()
                    + coefficient(&f, 1, 0).to_f64().value() * (n.to_f64().value()).sqrt();
                assert!((value - alpha.to_f64()).abs() < 1e-12, "{text}");
            }
        }
        // a square discriminant: α = 1/2 exactly
        let half = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-1, 2]))
            .pop()
            .unwrap();
        let reducible = NumberField::new(&half);
        assert_eq!(Names::new().number(&reducible.generator()), "1/2");
    }

    #[test]
    fn named_polynomials_are_monic() {
        // α = ∛(2/3), a root of 3x³ − 2: its listed polynomial is x³ − 2/3
        let alpha = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 0, 3]))
            .pop()
            .unwrap();
        let mut names = Names::new();
        assert_eq!(names.number(&NumberField::new(&alpha).generator()), "a1");
        assert_eq!(names.numbers()[0].poly, "x^3 - 2/3");
    }

    #[test]
    fn large_and_small_numbers_are_named_scaled_by_a_power_of_two() {
        // α = 2²⁰·∛2, a root of x³ − 2⁶¹: named β = α/2²⁰ = ∛2, α written 2²⁰·β
        let big = AlgebraicReal::real_roots_of(&Poly::new(vec![
            -(IBig::ONE << 61),
            IBig::ZERO,
            IBig::ZERO,
            IBig::ONE,
        ]))
        .pop()
        .unwrap();
        let mut names = Names::new();
        assert_eq!(
            names.number(&NumberField::new(&big).generator()),
            "1048576*a1"
        );
        let listed = &names.numbers()[0];
        assert_eq!(listed.poly, "x^3 - 2");
        assert!((listed.approx - 2f64.cbrt()).abs() < 1e-12);
        let lo: RBig = listed.interval[0].parse().unwrap();
        let hi: RBig = listed.interval[1].parse().unwrap();
        assert!(lo.to_f64().value() <= 2f64.cbrt() && 2f64.cbrt() <= hi.to_f64().value());
        // α = ∛2/2²⁰: β = 2²⁰α, α written β/2²⁰ (exponent −20)
        let small = AlgebraicReal::real_roots_of(&Poly::new(vec![
            IBig::from(-2),
            IBig::ZERO,
            IBig::ZERO,
            IBig::ONE << 60,
        ]))
        .pop()
        .unwrap();
        let mut names = Names::new();
        assert_eq!(
            names.number(&NumberField::new(&small).generator()),
            "1/1048576*a1"
        );
        assert_eq!(names.numbers()[0].poly, "x^3 - 2");
    }

    #[test]
    fn cubic_numbers_are_named_once_and_read_back() {
        let alpha = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 0, 1]))
            .pop()
            .unwrap();
        let k = NumberField::new(&alpha);
        let mut rng = SplitMix(3);
        let mut names = Names::new();
        let p = random_poly(&mut rng, &k, 3, 3);
        let text = names.poly(&p);
        let again = names.number(&k.generator());
        assert_eq!(again, "a1");
        let f = read_back(&text, "a1");
        // Σ f_jk α^j u^k = p exactly
        for (kk, c) in p.coeffs().iter().enumerate() {
            let mut v = Number::zero();
            let mut power = Number::one();
            for j in 0..3 {
                v = v.add(&power.mul(&rational(coefficient(&f, j, kk))));
                power = power.mul(&k.generator());
            }
            assert_eq!(&v, c, "{text}");
        }
        let numbers = names.numbers();
        assert_eq!(numbers.len(), 1);
        assert_eq!(numbers[0].poly, "x^3 - 2");
        let lo: f64 = numbers[0].interval[0]
            .parse::<RBig>()
            .unwrap()
            .to_f64()
            .value();
        assert!(lo <= 2f64.cbrt() && (numbers[0].approx - 2f64.cbrt()).abs() < 1e-12);
    }

    /// The printing of a number of a field of degree ≤ 2 computed the plain way, from the
    /// current defining polynomial and rationals: the reference for [`Form`].
    fn reference_number(c: &Number) -> String {
        let Some(field) = c.field().filter(|_| c.numerator().len() > 1) else {
            let v = c.numerator().first().cloned().unwrap_or(IBig::ZERO);
            return (RBig::from(v) / RBig::from(c.denominator().clone())).to_string();
        };
        let alpha = field.alpha();
        let m = alpha.poly().clone();
        let rep = c.representative().rem(&m.to_rational());
        let (m0, m1) = (RBig::from(m.coeff(0)), RBig::from(m.coeff(1)));
        if m.degree() == Some(1) {
            return rep.eval(&(-m0 / m1)).to_string();
        }
        assert_eq!(m.degree(), Some(2), "a field of degree ≤ 2");
        let m2 = RBig::from(m.coeff(2));
        let disc = &m1 * &m1 - RBig::from(4) * &m0 * &m2;
        let disc = disc.numerator().clone();
        let sigma = alpha.sign_of(&Poly::new(vec![m.coeff(1), IBig::from(2) * m.coeff(2)]));
        let (r0, r1) = (rep.coeff(0), rep.coeff(1));
        let two_m2 = RBig::from(2) * &m2;
        let p = &r0 - &r1 * &m1 / &two_m2;
        let mut q = &r1 / &two_m2;
        if sigma == Sign::Negative {
            q = -q;
        }
        if let Some(root) = exact_sqrt(&disc) {
            return (p + q * RBig::from(root)).to_string();
        }
        let (k, n) = square_out_big(&disc);
        let q = q * RBig::from(k);
        if q.is_zero() {
            return p.to_string();
        }
        let radical = match q.to_string().as_str() {
            "1" => format!("sqrt({n})"),
            "-1" => format!("-sqrt({n})"),
            text => format!("{text}*sqrt({n})"),
        };
        match (p.is_zero(), radical.strip_prefix('-')) {
            (true, _) => radical,
            (false, Some(rest)) => format!("{p} - {rest}"),
            (false, None) => format!("{p} + {radical}"),
        }
    }

    /// A polynomial printed from [`reference_number`] of each coefficient, split at its text.
    fn reference_poly(p: &NumberPoly) -> String {
        let mut out = String::new();
        for (k, c) in p.coeffs().iter().enumerate().rev() {
            let text = reference_number(c);
            if text == "0" {
                continue;
            }
            let (neg, abs) = match text.strip_prefix('-') {
                Some(rest) if is_term(&text) => (true, rest.to_string()),
                _ if is_term(&text) => (false, text.clone()),
                _ => (false, format!("({text})")),
            };
            out.push_str(match (out.is_empty(), neg) {
                (true, true) => "-",
                (true, false) => "",
                (false, true) => " - ",
                (false, false) => " + ",
            });
            let monomial = match k {
                0 => String::new(),
                1 => "u".to_string(),
                _ => format!("u^{k}"),
            };
            out.push_str(&match (k, abs.as_str()) {
                (0, _) => abs,
                (_, "1") => monomial,
                _ => format!("{abs}*{monomial}"),
            });
        }
        if out.is_empty() {
            out.push('0');
        }
        out
    }

    #[test]
    fn quadratic_numbers_print_as_the_plain_computation_does() {
        let mut rng = SplitMix(29);
        // x² − δ (from `sqrt_field`), and quadratics with m₁ ≠ 0, a negative or non-unit
        // leading coefficient, square factors in D, and a square D (a rational α)
        let mut fields: Vec<NumberField> = [2i64, 12, 50, 1_000_003, 4 * 999_983 * 9]
            .iter()
            .map(|&d| sqrt_field(&IBig::from(d)))
            .collect();
        for m in [
            [1i64, -5, 3],
            [1, -4, 1],
            [-7, 2, -5],
            [3, 18, 2],
            [-1, 0, 2],
            [2, -3, 1],
        ] {
            for alpha in AlgebraicReal::real_roots_of(&Poly::from_i64s(&m)) {
                fields.push(NumberField::new(&alpha));
            }
        }
        for field in &fields {
            let mut names = Names::new();
            for degree in 0..4 {
                let p = random_poly(&mut rng, field, degree, 2);
                assert_eq!(names.poly(&p), reference_poly(&p), "{field:?}");
                for c in p.coeffs() {
                    assert_eq!(names.number(c), reference_number(c), "{field:?}");
                }
            }
            // the units and zero: `sqrt(n)`, `-sqrt(n)`, `1 + sqrt(n)`, 0
            for (a, b) in [(0, 1), (0, -1), (1, 1), (-1, -1), (0, 0), (5, 0)] {
                let c = field.element(&Poly::new(vec![r(a, 1), r(b, 1)]));
                assert_eq!(names.number(&c), reference_number(&c), "{field:?}");
                let p: NumberPoly = Poly::new(vec![c.clone(), c.clone(), c]);
                assert_eq!(names.poly(&p), reference_poly(&p), "{field:?}");
            }
        }
    }

    #[test]
    fn numbers_of_a_field_that_shrinks_print_by_its_new_modulus() {
        // α = √2 given by (x² − 2)(x² − 3): elements of degree 3 print, after the field
        // learns x² − 2, as elements of ℚ(√2) (their numerators reduced then)
        let m = &Poly::from_i64s(&[-2, 0, 1]) * &Poly::from_i64s(&[-3, 0, 1]);
        let alpha = AlgebraicReal::real_roots_of(&m)[2].clone();
        let k = NumberField::new(&alpha);
        let c = k.element(&Poly::new(vec![r(1, 2), r(-3, 1), r(2, 3), r(5, 7)]));
        let mut names = Names::new();
        assert!(names.number(&c).contains("a1"));
        let a = k.generator();
        assert!(a.mul(&a).sub(&rational(RBig::from(2))).is_zero());
        assert_eq!(k.degree(), 2);
        assert_eq!(names.number(&c), reference_number(&c));
        // 1/2 − 3√2 + 2/3·2 + 5/7·2√2 = 11/6 − 11/7·√2
        assert_eq!(names.number(&c), "11/6 - 11/7*sqrt(2)");
        // α = 1/2 given by (2x − 1)(x² − 3) (as its middle root): rationals once known
        let m = &Poly::from_i64s(&[-1, 2]) * &Poly::from_i64s(&[-3, 0, 1]);
        let half = AlgebraicReal::real_roots_of(&m)[1].clone();
        let k = NumberField::new(&half);
        let c = k.element(&Poly::new(vec![r(1, 1), r(1, 1), r(4, 1)]));
        assert!(k.generator().sub(&rational(r(1, 2))).is_zero());
        assert_eq!(k.degree(), 1);
        // 1 + 1/2 + 4/4
        assert_eq!(names.number(&c), "5/2");
        let p: NumberPoly = Poly::new(vec![c.clone(), c.sub(&c), c]);
        assert_eq!(names.poly(&p), "5/2*u^2 + 5/2");
    }

    #[test]
    fn square_factors_come_out_alike_in_words_and_big_integers() {
        let mut rng = SplitMix(5);
        let mut values: Vec<u64> = vec![1, 2, 4, 8, 12, 997 * 997 * 3, 1009 * 1009 * 5, u64::MAX];
        for _ in 0..300 {
            let (a, b) = (rng.int(1, 2000) as u64, rng.int(1, 1_000_000) as u64);
            values.push(a * a * b);
        }
        for v in values {
            let (k, n) = square_out_u64(v);
            assert_eq!(
                square_out_big(&IBig::from(v)),
                (IBig::from(k), IBig::from(n)),
                "{v}"
            );
            assert_eq!(
                u128::from(k) * u128::from(k) * u128::from(n),
                u128::from(v),
                "{v}"
            );
            for p in 2..1000u64 {
                assert!(n % (p * p) != 0, "{v}: {p}² left in {n}");
            }
        }
        // beyond a word: 6²·(2⁶⁴ + 13)
        let big = (IBig::ONE << 64) + IBig::from(13);
        let (k, n) = square_out(&(IBig::from(36) * &big));
        assert_eq!((k, n), (IBig::from(6), big));
    }

    #[test]
    fn integers_print_as_their_decimal_display() {
        let mut rng = SplitMix(17);
        let mut values: Vec<IBig> = [0i128, 1, -1, 9, 10, 99, 100, 101, -12345]
            .iter()
            .map(|&v| IBig::from(v))
            .collect();
        for e in [19u32, 20, 38] {
            let p = IBig::from(10u128.pow(e));
            values.extend([&p - IBig::ONE, p.clone(), &p + IBig::ONE, -p]);
        }
        for p in [63usize, 64, 126, 127, 128, 200] {
            let p = IBig::ONE << p;
            values.extend([&p - IBig::ONE, p.clone(), -p]);
        }
        for _ in 0..200 {
            let v = IBig::from(rng.int(-1 << 40, 1 << 40))
                * IBig::from(rng.int(1, 1 << 50))
                * IBig::from(rng.int(1, 1 << 45));
            values.push(v);
        }
        for v in values {
            let mut out = Vec::new();
            push_int(&mut out, &v, true);
            assert_eq!(ascii(out), v.to_string());
            let mut out = Vec::new();
            push_int(&mut out, &v, false);
            assert_eq!(ascii(out), v.to_string().trim_start_matches('-'));
        }
    }
}
