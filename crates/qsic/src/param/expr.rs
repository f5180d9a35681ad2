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

use super::curve::{Number, NumberPoly};
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

/// `v` with its square factors below 1000 taken out: `(k, n)` with `v = k²n`.
fn square_out(v: &IBig) -> (IBig, IBig) {
    let (mut k, mut n) = (IBig::ONE, v.clone());
    let mut p = 2u32;
    while p < 1000 {
        let pp = IBig::from(p * p);
        while (&n % &pp).is_zero() {
            n /= &pp;
            k *= IBig::from(p);
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

/// `p + q*sqrt(n)` in its shortest form.
fn quadratic_to_string(p: &RBig, q: &RBig, n: &IBig) -> String {
    let root = format!("sqrt({n})");
    let radical = if *q == RBig::ONE {
        root
    } else if *q == -RBig::ONE {
        format!("-{root}")
    } else {
        format!("{q}*{root}")
    };
    if p.is_zero() {
        radical
    } else if let Some(r) = radical.strip_prefix('-') {
        format!("{p} - {r}")
    } else {
        format!("{p} + {radical}")
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
        let Some(field) = c.field().filter(|_| c.numerator().len() > 1) else {
            return rational_to_string(&constant(c));
        };
        let alpha = field.alpha();
        let m = alpha.poly().clone();
        let rep = c.representative().rem(&m.to_rational());
        match m.degree() {
            Some(1) => {
                let root = -RBig::from(m.coeff(0)) / RBig::from(m.coeff(1));
                rational_to_string(&rep.eval(&root))
            }
            Some(2) => {
                let (m0, m1, m2) = (m.coeff(0), m.coeff(1), m.coeff(2));
                let disc = &m1 * &m1 - IBig::from(4) * &m0 * &m2;
                let sigma = alpha.sign_of(&Poly::new(vec![m1.clone(), IBig::from(2) * &m2]));
                let two_m2 = RBig::from(IBig::from(2) * &m2);
                let (r0, r1) = (rep.coeff(0), rep.coeff(1));
                // c = r0 + r1·(−m1 + σ√D)/(2m2)
                let p = &r0 - &r1 * RBig::from(m1.clone()) / &two_m2;
                let q = &r1 / &two_m2;
                let q = if sigma == Sign::Negative { -q } else { q };
                match exact_sqrt(&disc) {
                    Some(r) => rational_to_string(&(p + q * RBig::from(r))),
                    None => {
                        let (k, n) = square_out(&disc);
                        quadratic_to_string(&p, &(q * RBig::from(k)), &n)
                    }
                }
            }
            _ => {
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
        }
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
        let mut out = String::new();
        for (k, c) in p.coeffs().iter().enumerate().rev() {
            if c.is_zero() {
                continue;
            }
            let text = self.number(c);
            let (neg, abs) = match text.strip_prefix('-') {
                Some(rest) if is_term(&text) => (true, rest.to_string()),
                _ if is_term(&text) => (false, text.clone()),
                _ => (false, format!("({text})")),
            };
            if out.is_empty() {
                if neg {
                    out.push('-');
                }
            } else {
                out.push_str(if neg { " - " } else { " + " });
            }
            let monomial = match k {
                0 => String::new(),
                1 => "u".to_string(),
                _ => format!("u^{k}"),
            };
            match (k, abs.as_str()) {
                (0, _) => out.push_str(&abs),
                (_, "1") => out.push_str(&monomial),
                _ => {
                    out.push_str(&abs);
                    out.push('*');
                    out.push_str(&monomial);
                }
            }
        }
        if out.is_empty() {
            out.push('0');
        }
        out
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

/// The rational value of an element with a constant numerator.
fn constant(c: &Number) -> RBig {
    c.numerator()
        .first()
        .map_or(RBig::ZERO, |v| RBig::from(v.clone()))
        / RBig::from(c.denominator().clone())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::{parse_rational_function, Variable};
    use crate::param::curve::{rational, sqrt_field};
    use qsic_algebra::field::NumberField;
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
}
