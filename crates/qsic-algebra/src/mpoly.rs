//! Sparse multivariate polynomials with rational coefficients, in up to eight variables.
//!
//! | entry point | does |
//! |---|---|
//! | [`MPoly`] arithmetic | `+ − ×`, [`MPoly::pow`], [`MPoly::scale`], [`MPoly::eval`] |
//! | [`MPoly::total_degree`], [`MPoly::degree_in`] | degrees |
//! | [`MPoly::coefficients_in`], [`MPoly::to_univariate`] | dense coefficients in one variable |
//! | [`MPoly::quadratic_form`], [`MPoly::homogenize`] | the symmetric matrix of a quadratic form in chosen variables |
//! | [`MPoly::content`] | the rational content (what makes the coefficients coprime integers) |
//!
//! A polynomial is a list of terms `c·x₀^e₀⋯x₇^e₇`, sorted by exponent vector
//! ([`Monomial`], lexicographic with variable 0 most significant) with no zero coefficient,
//! so equal polynomials have equal representations. Variables are numbered; naming them is
//! the business of readers and printers ([`MPoly::to_string_with`]).

use crate::{IBig, RBig};
use dashu_int::ops::{BitTest, Gcd};
use dashu_int::UBig;
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};

/// The number of variables a [`Monomial`] has room for.
pub const MAX_VARS: usize = 8;

/// A monomial `x₀^e₀⋯x₇^e₇`, as its exponent vector.
///
/// Ordered lexicographically with `x₀` most significant: `1 < x₁ < x₁² < x₀ < x₀x₁`.
/// Multiplying by a monomial keeps this order, so products by one term need no sorting.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Monomial([u16; MAX_VARS]);

impl Monomial {
    /// The monomial `1`.
    pub const ONE: Monomial = Monomial([0; MAX_VARS]);

    /// The monomial with these exponents.
    pub const fn new(exponents: [u16; MAX_VARS]) -> Monomial {
        Monomial(exponents)
    }

    /// The variable `x_var` (exponent 1).
    ///
    /// # Panics
    /// If `var ≥ MAX_VARS`.
    pub fn var(var: usize) -> Monomial {
        let mut e = [0; MAX_VARS];
        e[var] = 1;
        Monomial(e)
    }

    /// The exponents, variable 0 first.
    pub const fn exponents(&self) -> &[u16; MAX_VARS] {
        &self.0
    }

    /// The total degree `Σ eᵢ`.
    pub fn degree(&self) -> u32 {
        self.0.iter().map(|&e| u32::from(e)).sum()
    }

    /// The degree in the variables `vars`: `Σ_{i ∈ vars} eᵢ`.
    ///
    /// # Panics
    /// If a variable is `≥ MAX_VARS`.
    pub fn degree_in_vars(&self, vars: &[usize]) -> u32 {
        vars.iter().map(|&v| u32::from(self.0[v])).sum()
    }

    /// The product: exponents added.
    ///
    /// # Panics
    /// If an exponent exceeds `u16::MAX`.
    pub fn mul(&self, other: &Monomial) -> Monomial {
        let mut e = self.0;
        for (a, b) in e.iter_mut().zip(other.0) {
            *a = a
                .checked_add(b)
                .expect("a monomial exponent above u16::MAX");
        }
        Monomial(e)
    }
}

/// A polynomial in `x₀, …, x₇` with rational coefficients.
///
/// Invariant ([`MPoly::is_valid`]): terms sorted by strictly increasing [`Monomial`], no
/// zero coefficient. The zero polynomial has no terms.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct MPoly {
    terms: Vec<(Monomial, RBig)>,
}

/// `a·b`, with shortcuts for a factor 1 and for integers (no gcd needed).
fn mul_q(a: &RBig, b: &RBig) -> RBig {
    if b.is_one() {
        a.clone()
    } else if a.is_one() {
        b.clone()
    } else if a.is_int() && b.is_int() {
        RBig::from(a.numerator() * b.numerator())
    } else {
        a * b
    }
}

/// `a += b`, with a shortcut for integers.
fn add_q(a: &mut RBig, b: &RBig) {
    if a.is_int() && b.is_int() {
        *a = RBig::from(a.numerator() + b.numerator());
    } else {
        *a += b;
    }
}

impl MPoly {
    /// The zero polynomial.
    pub const fn zero() -> MPoly {
        MPoly { terms: Vec::new() }
    }

    /// The constant `c`.
    pub fn constant(c: RBig) -> MPoly {
        MPoly::term(Monomial::ONE, c)
    }

    /// The constant 1.
    pub fn one() -> MPoly {
        MPoly::constant(RBig::ONE)
    }

    /// The variable `x_var`.
    ///
    /// # Panics
    /// If `var ≥ MAX_VARS`.
    pub fn var(var: usize) -> MPoly {
        MPoly::term(Monomial::var(var), RBig::ONE)
    }

    /// The single term `c·m` (zero if `c` is).
    pub fn term(m: Monomial, c: RBig) -> MPoly {
        let terms = if c.is_zero() {
            Vec::new()
        } else {
            vec![(m, c)]
        };
        MPoly { terms }
    }

    /// The sum of the given terms, in any order, repeated monomials added up.
    ///
    /// ```
    /// use qsic_algebra::mpoly::{MPoly, Monomial};
    /// use qsic_algebra::RBig;
    /// let x = Monomial::var(0);
    /// let p = MPoly::from_terms([(x, RBig::from(2)), (Monomial::ONE, RBig::ONE), (x, RBig::from(-2))]);
    /// assert_eq!(p, MPoly::one());
    /// ```
    pub fn from_terms(terms: impl IntoIterator<Item = (Monomial, RBig)>) -> MPoly {
        let mut terms: Vec<_> = terms.into_iter().collect();
        terms.sort_unstable_by_key(|t| t.0);
        MPoly {
            terms: merge_sorted(terms),
        }
    }

    /// The terms, by increasing monomial.
    pub fn terms(&self) -> &[(Monomial, RBig)] {
        &self.terms
    }

    /// The number of terms.
    pub fn num_terms(&self) -> usize {
        self.terms.len()
    }

    /// Whether this is the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// Whether this is the constant 1.
    pub fn is_one(&self) -> bool {
        matches!(self.terms.as_slice(), [(m, c)] if *m == Monomial::ONE && c.is_one())
    }

    /// The coefficient of the monomial `m`, if nonzero (binary search).
    pub fn coefficient(&self, m: &Monomial) -> Option<&RBig> {
        let k = self.terms.binary_search_by(|(n, _)| n.cmp(m)).ok()?;
        Some(&self.terms[k].1)
    }

    /// The value if the polynomial is a constant (`0` for the zero polynomial).
    pub fn as_constant(&self) -> Option<RBig> {
        match self.terms.as_slice() {
            [] => Some(RBig::ZERO),
            [(m, c)] if *m == Monomial::ONE => Some(c.clone()),
            _ => None,
        }
    }

    /// The coefficient of the greatest monomial (`0` for the zero polynomial).
    pub fn leading_coefficient(&self) -> RBig {
        self.terms.last().map_or(RBig::ZERO, |(_, c)| c.clone())
    }

    /// Checks the invariant: strictly increasing monomials, no zero coefficient.
    pub fn is_valid(&self) -> bool {
        self.terms.windows(2).all(|w| w[0].0 < w[1].0)
            && self.terms.iter().all(|(_, c)| !c.is_zero())
    }

    /// The total degree: the largest degree of a term (`0` for the zero polynomial).
    pub fn total_degree(&self) -> u32 {
        self.terms
            .iter()
            .map(|(m, _)| m.degree())
            .max()
            .unwrap_or(0)
    }

    /// The degree in the variable `var` (`0` if it does not occur).
    ///
    /// # Panics
    /// If `var ≥ MAX_VARS`.
    pub fn degree_in(&self, var: usize) -> u32 {
        self.terms
            .iter()
            .map(|(m, _)| u32::from(m.0[var]))
            .max()
            .unwrap_or(0)
    }

    /// Whether the variable `var` occurs.
    ///
    /// # Panics
    /// If `var ≥ MAX_VARS`.
    pub fn uses(&self, var: usize) -> bool {
        self.terms.iter().any(|(m, _)| m.0[var] > 0)
    }

    /// `c · self`.
    pub fn scale(&self, c: &RBig) -> MPoly {
        if c.is_zero() {
            return MPoly::zero();
        }
        MPoly {
            terms: self.terms.iter().map(|(m, a)| (*m, mul_q(a, c))).collect(),
        }
    }

    /// `self^n` by repeated squaring (`p⁰ = 1`, also for `p = 0`).
    ///
    /// # Panics
    /// If an exponent of the result exceeds `u16::MAX`.
    pub fn pow(&self, mut n: u32) -> MPoly {
        let mut acc = MPoly::one();
        let mut base = self.clone();
        while n > 0 {
            if n & 1 == 1 {
                acc = &acc * &base;
            }
            n >>= 1;
            if n > 0 {
                base = &base * &base;
            }
        }
        acc
    }

    /// The value at `x_i = values[i]`.
    ///
    /// # Panics
    /// If a variable that occurs has no value (`values` too short).
    ///
    /// ```
    /// use qsic_algebra::mpoly::MPoly;
    /// use qsic_algebra::RBig;
    /// let (x, y) = (MPoly::var(0), MPoly::var(1));
    /// let p = &(&x * &x) - &y; // x² − y
    /// assert_eq!(p.eval(&[RBig::from(3), RBig::from(2)]), RBig::from(7));
    /// ```
    pub fn eval(&self, values: &[RBig]) -> RBig {
        let mut sum = RBig::ZERO;
        for (m, c) in &self.terms {
            let mut v = c.clone();
            for (i, &e) in m.0.iter().enumerate() {
                if e > 0 {
                    v *= values[i].pow(e as isize);
                }
            }
            sum += v;
        }
        sum
    }

    /// The coefficients in the variable `var`, lowest degree first: `self = Σₖ cₖ·x_var^k`
    /// with `cₖ` free of `x_var`. Empty for the zero polynomial, else the last is nonzero.
    ///
    /// # Panics
    /// If `var ≥ MAX_VARS`.
    pub fn coefficients_in(&self, var: usize) -> Vec<MPoly> {
        if self.is_zero() {
            return Vec::new();
        }
        let mut out = vec![MPoly::zero(); self.degree_in(var) as usize + 1];
        for (m, c) in &self.terms {
            let mut rest = *m;
            let k = std::mem::take(&mut rest.0[var]);
            out[usize::from(k)].terms.push((rest, c.clone()));
        }
        // Removing a variable other than the last can break the order of the rest.
        for p in &mut out {
            p.terms.sort_unstable_by_key(|t| t.0);
        }
        out
    }

    /// The dense coefficients of a polynomial in `x_var` only, lowest degree first (no
    /// trailing zeros), or `None` if another variable occurs.
    ///
    /// ```
    /// use qsic_algebra::mpoly::MPoly;
    /// use qsic_algebra::RBig;
    /// let t = MPoly::var(4);
    /// let p = &(&t * &t) - &MPoly::constant(RBig::from(2)); // t² − 2
    /// assert_eq!(p.to_univariate(4), Some(vec![RBig::from(-2), RBig::ZERO, RBig::ONE]));
    /// assert_eq!(p.to_univariate(0), None);
    /// ```
    pub fn to_univariate(&self, var: usize) -> Option<Vec<RBig>> {
        let mut out = vec![RBig::ZERO; self.degree_in(var) as usize + usize::from(!self.is_zero())];
        for (m, c) in &self.terms {
            let mut rest = *m;
            let k = std::mem::take(&mut rest.0[var]);
            if rest != Monomial::ONE {
                return None;
            }
            out[usize::from(k)] = c.clone();
        }
        Some(out)
    }

    /// The symmetric matrix `A` of a quadratic form in the variables `vars`, its entries
    /// polynomials in the other variables: `self = Σᵢⱼ Aᵢⱼ·vᵢ·vⱼ`, so `Aᵢᵢ` is the
    /// coefficient of `vᵢ²` and `Aᵢⱼ = Aⱼᵢ` half that of `vᵢvⱼ`. `None` if a term does not
    /// have degree exactly 2 in `vars`.
    ///
    /// # Panics
    /// If a variable is `≥ MAX_VARS` or repeated.
    ///
    /// ```
    /// use qsic_algebra::mpoly::MPoly;
    /// use qsic_algebra::RBig;
    /// let (x, y, t) = (MPoly::var(0), MPoly::var(1), MPoly::var(4));
    /// let p = &(&x * &x) + &(&(&t * &x) * &y); // x² + t·x·y
    /// let a = p.quadratic_form(&[0, 1]).expect("a quadratic form in x, y");
    /// assert_eq!(a[0][0], MPoly::one());
    /// assert_eq!(a[0][1], t.scale(&RBig::from_parts(1.into(), 2u8.into())));
    /// assert_eq!(a[0][1], a[1][0]);
    /// assert_eq!(p.quadratic_form(&[0]), None);
    /// ```
    pub fn quadratic_form(&self, vars: &[usize]) -> Option<Vec<Vec<MPoly>>> {
        let n = vars.len();
        let mut entries: Vec<Vec<Vec<(Monomial, RBig)>>> = vec![vec![Vec::new(); n]; n];
        for (m, c) in &self.terms {
            let mut rest = *m;
            let mut picked = [0usize; 2];
            let mut count = 0;
            for (i, &v) in vars.iter().enumerate() {
                let e = std::mem::take(&mut rest.0[v]);
                for _ in 0..e {
                    if count == 2 {
                        return None;
                    }
                    picked[count] = i;
                    count += 1;
                }
            }
            assert!(vars.iter().all(|&v| rest.0[v] == 0), "repeated variable");
            if count != 2 {
                return None;
            }
            let [i, j] = picked;
            if i == j {
                entries[i][i].push((rest, c.clone()));
            } else {
                let half = half(c);
                entries[i][j].push((rest, half.clone()));
                entries[j][i].push((rest, half));
            }
        }
        Some(
            entries
                .into_iter()
                .map(|row| {
                    row.into_iter()
                        .map(|terms| match terms.len() {
                            0 | 1 => MPoly { terms },
                            _ => MPoly::from_terms(terms),
                        })
                        .collect()
                })
                .collect(),
        )
    }

    /// Homogenises to degree `degree` in the variables `vars` with the variable `h`: each
    /// term of degree `k ≤ degree` in `vars` is multiplied by `h^(degree − k)`. `None` if a
    /// term has degree above `degree` in `vars`.
    ///
    /// # Panics
    /// If `h ≥ MAX_VARS`, or an exponent of `h` exceeds `u16::MAX`.
    ///
    /// ```
    /// use qsic_algebra::mpoly::MPoly;
    /// let (x, w) = (MPoly::var(0), MPoly::var(3));
    /// let p = &(&x * &x) - &MPoly::one(); // x² − 1
    /// assert_eq!(p.homogenize(&[0], 3, 2), Some(&(&x * &x) - &(&w * &w)));
    /// ```
    pub fn homogenize(&self, vars: &[usize], h: usize, degree: u32) -> Option<MPoly> {
        let mut terms = Vec::with_capacity(self.terms.len());
        for (m, c) in &self.terms {
            let missing = degree.checked_sub(m.degree_in_vars(vars))?;
            let mut e = *m;
            let raised = u32::from(e.0[h]) + missing;
            e.0[h] = u16::try_from(raised).expect("an exponent above u16::MAX");
            terms.push((e, c.clone()));
        }
        Some(MPoly::from_terms(terms))
    }

    /// The rational content: the positive `c` such that `self / c` has coprime integer
    /// coefficients (the gcd of the numerators over the lcm of the denominators); `0` for
    /// the zero polynomial.
    ///
    /// ```
    /// use qsic_algebra::mpoly::MPoly;
    /// use qsic_algebra::RBig;
    /// let q = |n: i32, d: u8| RBig::from_parts(n.into(), d.into());
    /// let p = &MPoly::var(0).scale(&q(4, 3)) + &MPoly::constant(q(-2, 9)); // 4/3·x − 2/9
    /// assert_eq!(p.content(), q(2, 9));
    /// ```
    pub fn content(&self) -> RBig {
        let mut num = IBig::ZERO;
        let mut den = UBig::ONE;
        for (_, c) in &self.terms {
            num = crate::int_gcd(&num, c.numerator());
            let d = c.denominator();
            if !d.is_one() {
                let g = (&den).gcd(d);
                den = &den / g * d;
            }
        }
        RBig::from_parts(num, den)
    }

    /// The polynomial written with the given variable names, greatest monomial first, in
    /// the form `3*x^2*y - 1/2*t + 5` that the readers of `qsic` read back.
    ///
    /// # Panics
    /// If a variable that occurs has no name.
    pub fn to_string_with(&self, names: &[&str]) -> String {
        self.to_string_with_numbers(names, |c| c.to_string())
    }

    /// [`MPoly::to_string_with`], each coefficient's absolute value (a positive rational)
    /// written by `number`.
    ///
    /// # Panics
    /// If a variable that occurs has no name.
    pub fn to_string_with_numbers(
        &self,
        names: &[&str],
        number: impl Fn(&RBig) -> String,
    ) -> String {
        if self.is_zero() {
            return "0".into();
        }
        let mut out = String::new();
        for (k, (m, c)) in self.terms.iter().rev().enumerate() {
            let negative = *c < RBig::ZERO;
            out.push_str(match (k, negative) {
                (0, false) => "",
                (0, true) => "-",
                (_, false) => " + ",
                (_, true) => " - ",
            });
            let a = if negative { -c } else { c.clone() };
            let mut factors: Vec<String> = Vec::new();
            if !a.is_one() || *m == Monomial::ONE {
                factors.push(number(&a));
            }
            for (i, &e) in m.0.iter().enumerate() {
                match e {
                    0 => {}
                    1 => factors.push(names[i].to_string()),
                    _ => factors.push(format!("{}^{e}", names[i])),
                }
            }
            out.push_str(&factors.join("*"));
        }
        out
    }

    /// The size of the largest coefficient: bits of numerator and denominator added.
    pub fn max_bits(&self) -> usize {
        self.terms.iter().map(|(_, c)| bits(c)).max().unwrap_or(0)
    }
}

/// Bits of the numerator and the denominator of `c`, added.
#[inline]
pub fn bits(c: &RBig) -> usize {
    c.numerator().bit_len() + c.denominator().bit_len()
}

/// `c / 2`, with shortcuts for integers (the off-diagonal entries of a form's matrix).
pub fn half(c: &RBig) -> RBig {
    if !c.is_int() {
        c / RBig::from(2)
    } else if c.numerator().bit(0) {
        RBig::from_parts(c.numerator().clone(), UBig::from(2u8))
    } else {
        RBig::from(c.numerator() >> 1)
    }
}

/// Terms sorted by monomial (repeats allowed) with repeated monomials added and zeros left out.
fn merge_sorted(terms: Vec<(Monomial, RBig)>) -> Vec<(Monomial, RBig)> {
    let mut out: Vec<(Monomial, RBig)> = Vec::with_capacity(terms.len());
    for (m, c) in terms {
        match out.last_mut() {
            Some((last, acc)) if *last == m => add_q(acc, &c),
            _ => {
                if out.last().is_some_and(|(_, a)| a.is_zero()) {
                    out.pop();
                }
                out.push((m, c));
            }
        }
    }
    if out.last().is_some_and(|(_, a)| a.is_zero()) {
        out.pop();
    }
    out
}

impl fmt::Display for MPoly {
    /// The polynomial in the variables `x0, …, x7` ([`MPoly::to_string_with`]).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        const NAMES: [&str; MAX_VARS] = ["x0", "x1", "x2", "x3", "x4", "x5", "x6", "x7"];
        f.write_str(&self.to_string_with(&NAMES))
    }
}

impl MPoly {
    /// `self += rhs`, or `self -= rhs` if `negative`: a single term found by binary search
    /// and added in place, more by a merge of the two term lists that moves those of `self`.
    fn add_in_place(&mut self, rhs: &MPoly, negative: bool) {
        let signed = |d: &RBig| if negative { -d } else { d.clone() };
        if let [(m, d)] = rhs.terms.as_slice() {
            match self.terms.binary_search_by(|(n, _)| n.cmp(m)) {
                Ok(k) => {
                    let c = &mut self.terms[k].1;
                    add_q(c, &signed(d));
                    if c.is_zero() {
                        self.terms.remove(k);
                    }
                }
                Err(k) => self.terms.insert(k, (*m, signed(d))),
            }
            return;
        }
        if rhs.is_zero() {
            return;
        }
        let mut out = Vec::with_capacity(self.terms.len() + rhs.terms.len());
        let mut right = rhs.terms.iter().peekable();
        for (m, mut c) in self.terms.drain(..) {
            while let Some((r, d)) = right.next_if(|(r, _)| *r < m) {
                out.push((*r, signed(d)));
            }
            if let Some((_, d)) = right.next_if(|(r, _)| *r == m) {
                add_q(&mut c, &signed(d));
                if c.is_zero() {
                    continue;
                }
            }
            out.push((m, c));
        }
        out.extend(right.map(|(r, d)| (*r, signed(d))));
        self.terms = out;
    }
}

impl Add<&MPoly> for MPoly {
    type Output = MPoly;
    fn add(mut self, rhs: &MPoly) -> MPoly {
        self.add_in_place(rhs, false);
        self
    }
}

impl Add for &MPoly {
    type Output = MPoly;
    fn add(self, rhs: &MPoly) -> MPoly {
        if self.terms.len() >= rhs.terms.len() {
            self.clone() + rhs
        } else {
            rhs.clone() + self
        }
    }
}

impl Neg for MPoly {
    type Output = MPoly;
    fn neg(mut self) -> MPoly {
        for (_, c) in &mut self.terms {
            *c = -std::mem::take(c);
        }
        self
    }
}

impl Neg for &MPoly {
    type Output = MPoly;
    fn neg(self) -> MPoly {
        -self.clone()
    }
}

impl Sub<&MPoly> for MPoly {
    type Output = MPoly;
    fn sub(mut self, rhs: &MPoly) -> MPoly {
        self.add_in_place(rhs, true);
        self
    }
}

impl Sub for &MPoly {
    type Output = MPoly;
    fn sub(self, rhs: &MPoly) -> MPoly {
        self.clone() - rhs
    }
}

impl Mul for MPoly {
    type Output = MPoly;
    /// The product, computed in the storage of an operand when the other is one term.
    ///
    /// # Panics
    /// If an exponent of the product exceeds `u16::MAX`.
    fn mul(self, rhs: MPoly) -> MPoly {
        let (mut long, short) = if self.terms.len() >= rhs.terms.len() {
            (self, rhs)
        } else {
            (rhs, self)
        };
        match short.terms.as_slice() {
            [] => MPoly::zero(),
            [(m, c)] => {
                // A product of nonzero rationals is nonzero, and m·a < m·b when a < b.
                for (n, d) in &mut long.terms {
                    *n = m.mul(n);
                    if !c.is_one() {
                        *d = mul_q(c, d);
                    }
                }
                long
            }
            _ => &long * &short,
        }
    }
}

impl Mul for &MPoly {
    type Output = MPoly;
    /// The product: by one term, a map that keeps the order; otherwise all products of
    /// terms, sorted and merged. `O(n·m·log(n·m))` coefficient operations and comparisons.
    ///
    /// # Panics
    /// If an exponent of the product exceeds `u16::MAX`.
    fn mul(self, rhs: &MPoly) -> MPoly {
        let (short, long) = if self.terms.len() <= rhs.terms.len() {
            (self, rhs)
        } else {
            (rhs, self)
        };
        match short.terms.as_slice() {
            [] => MPoly::zero(),
            [(m, c)] => MPoly {
                // A product of nonzero rationals is nonzero, and m·a < m·b when a < b.
                terms: long
                    .terms
                    .iter()
                    .map(|(n, d)| (m.mul(n), mul_q(c, d)))
                    .collect(),
            },
            _ => {
                let mut terms = Vec::with_capacity(short.terms.len() * long.terms.len());
                for (m, c) in &short.terms {
                    for (n, d) in &long.terms {
                        terms.push((m.mul(n), mul_q(c, d)));
                    }
                }
                terms.sort_unstable_by_key(|t| t.0);
                MPoly {
                    terms: merge_sorted(terms),
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn q(n: i64, d: u64) -> RBig {
        RBig::from_parts(IBig::from(n), UBig::from(d))
    }

    /// A random polynomial in the first four variables, small degrees and coefficients.
    fn mpoly() -> impl Strategy<Value = MPoly> {
        let term = ([0u16..3, 0..3, 0..2, 0..3], -6i64..=6, 1u64..=4)
            .prop_map(|(e, n, d)| (Monomial::new([e[0], e[1], e[2], e[3], 0, 0, 0, 0]), q(n, d)));
        proptest::collection::vec(term, 0..6).prop_map(MPoly::from_terms)
    }

    fn point() -> impl Strategy<Value = Vec<RBig>> {
        proptest::collection::vec((-7i64..=7, 1u64..=5).prop_map(|(n, d)| q(n, d)), 4)
    }

    #[test]
    fn from_terms_merges_and_drops_zeros() {
        let x = Monomial::var(0);
        let y = Monomial::var(1);
        let p = MPoly::from_terms([
            (y, q(1, 2)),
            (x, q(3, 1)),
            (Monomial::ONE, q(0, 1)),
            (y, q(-1, 2)),
            (x, q(1, 1)),
        ]);
        assert_eq!(p.terms(), &[(x, q(4, 1))]);
        assert!(p.is_valid());
        assert!(MPoly::from_terms([(x, q(1, 1)), (x, q(-1, 1))]).is_zero());
        assert!(MPoly::term(x, RBig::ZERO).is_zero());
    }

    #[test]
    fn degrees_and_constants() {
        let (x, y, t) = (MPoly::var(0), MPoly::var(1), MPoly::var(4));
        let p = &(&(&x * &x) * &y) + &t.pow(5); // x²y + t⁵
        assert_eq!(p.total_degree(), 5);
        assert_eq!((p.degree_in(0), p.degree_in(1), p.degree_in(2)), (2, 1, 0));
        assert!(p.uses(4) && !p.uses(3));
        assert_eq!(MPoly::zero().total_degree(), 0);
        assert_eq!(MPoly::zero().as_constant(), Some(RBig::ZERO));
        assert_eq!(MPoly::constant(q(3, 2)).as_constant(), Some(q(3, 2)));
        assert_eq!(p.as_constant(), None);
        assert!(MPoly::one().is_one() && !MPoly::constant(q(2, 1)).is_one());
        assert_eq!(p.leading_coefficient(), q(1, 1));
        let x2y = Monomial::new([2, 1, 0, 0, 0, 0, 0, 0]);
        assert_eq!(p.coefficient(&x2y), Some(&q(1, 1)));
        assert_eq!(p.coefficient(&Monomial::var(1)), None);
    }

    #[test]
    fn powers_match_repeated_products() {
        let p = &(&MPoly::var(0) + &MPoly::var(2)) - &MPoly::constant(q(1, 3));
        let mut acc = MPoly::one();
        for n in 0..7 {
            assert_eq!(p.pow(n), acc, "n = {n}");
            acc = &acc * &p;
        }
        assert_eq!(MPoly::zero().pow(0), MPoly::one());
        assert!(MPoly::zero().pow(3).is_zero());
    }

    #[test]
    fn printing_names_the_variables() {
        let (x, y, t) = (MPoly::var(0), MPoly::var(1), MPoly::var(4));
        let p = &(&(&x * &x).scale(&q(3, 1)) - &(&x * &y))
            + &(&t.scale(&q(-1, 2)) + &MPoly::constant(q(5, 1)));
        let names = ["x", "y", "z", "w", "t"];
        assert_eq!(p.to_string_with(&names), "3*x^2 - x*y - 1/2*t + 5");
        assert_eq!((-&p).to_string_with(&names), "-3*x^2 + x*y + 1/2*t - 5");
        assert_eq!(MPoly::zero().to_string_with(&names), "0");
        assert_eq!(MPoly::constant(q(-1, 1)).to_string(), "-1");
        assert_eq!(p.to_string(), "3*x0^2 - x0*x1 - 1/2*x4 + 5");
        let bracketed = p.to_string_with_numbers(&names, |c| format!("({c})"));
        assert_eq!(bracketed, "(3)*x^2 - x*y - (1/2)*t + (5)");
    }

    #[test]
    fn content_makes_coprime_integers() {
        let p = MPoly::from_terms([
            (Monomial::var(0), q(6, 5)),
            (Monomial::var(1), q(-9, 10)),
            (Monomial::ONE, q(3, 1)),
        ]);
        let c = p.content();
        assert_eq!(c, q(3, 10));
        let scaled = p.scale(&(RBig::ONE / &c));
        assert_eq!(scaled.content(), RBig::ONE);
        assert!(scaled.terms().iter().all(|(_, a)| a.is_int()));
        assert_eq!(MPoly::zero().content(), RBig::ZERO);
    }

    #[test]
    fn coefficients_in_one_variable() {
        let (x, y, z) = (MPoly::var(0), MPoly::var(1), MPoly::var(2));
        // y·x² + (z − 1)·x + y·z, in x
        let p = &(&(&(&y * &x) * &x) + &(&(&z - &MPoly::one()) * &x)) + &(&y * &z);
        let c = p.coefficients_in(0);
        assert_eq!(c, vec![&y * &z, &z - &MPoly::one(), y.clone()]);
        assert!(c.iter().all(|p| p.is_valid() && !p.uses(0)));
        assert!(MPoly::zero().coefficients_in(1).is_empty());
        assert_eq!(MPoly::zero().to_univariate(1), Some(vec![]));
        assert_eq!(
            MPoly::constant(q(2, 1)).to_univariate(3),
            Some(vec![q(2, 1)])
        );
    }

    #[test]
    fn quadratic_forms_and_homogenisation() {
        let (x, y, z, w) = (MPoly::var(0), MPoly::var(1), MPoly::var(2), MPoly::var(3));
        // x² + 2x − 4y + 3, homogenised: x² + 2xw − 4yw + 3w²
        let p =
            &(&(&(&x * &x) + &x.scale(&q(2, 1))) - &y.scale(&q(4, 1))) + &MPoly::constant(q(3, 1));
        let h = p.homogenize(&[0, 1, 2], 3, 2).expect("degree ≤ 2");
        let a = h.quadratic_form(&[0, 1, 2, 3]).expect("a quadratic form");
        let want = [[1, 0, 0, 1], [0, 0, 0, -2], [0, 0, 0, 0], [1, -2, 0, 3]];
        for i in 0..4 {
            for j in 0..4 {
                assert_eq!(a[i][j], MPoly::constant(q(want[i][j], 1)), "({i}, {j})");
            }
        }
        assert_eq!((&(&x * &y) * &z).homogenize(&[0, 1, 2], 3, 2), None);
        assert_eq!((&x * &w).quadratic_form(&[0, 1, 2]), None);
        assert_eq!(x.quadratic_form(&[0, 1, 2, 3]), None);
    }

    proptest! {
        #[test]
        fn ring_laws(a in mpoly(), b in mpoly(), c in mpoly()) {
            prop_assert_eq!(&a + &b, &b + &a);
            prop_assert_eq!(&a * &b, &b * &a);
            prop_assert_eq!(&(&a * &b) * &c, &a * &(&b * &c));
            prop_assert_eq!(&a * &(&b + &c), &(&a * &b) + &(&a * &c));
            prop_assert!((&a - &a).is_zero());
            let s = &(&a + &b) - &c;
            prop_assert!(s.is_valid() && (&a * &b).is_valid());
        }

        #[test]
        fn evaluation_is_a_homomorphism(a in mpoly(), b in mpoly(), v in point(), n in 0u32..4) {
            let (ea, eb) = (a.eval(&v), b.eval(&v));
            prop_assert_eq!((&a + &b).eval(&v), &ea + &eb);
            prop_assert_eq!((&a - &b).eval(&v), &ea - &eb);
            prop_assert_eq!((&a * &b).eval(&v), &ea * &eb);
            prop_assert_eq!(a.pow(n).eval(&v), ea.pow(n as isize));
            prop_assert_eq!(a.scale(&q(-3, 7)).eval(&v), ea * q(-3, 7));
        }

        #[test]
        fn coefficients_rebuild_the_polynomial(a in mpoly(), v in point(), var in 0usize..4) {
            let mut sum = RBig::ZERO;
            for (k, c) in a.coefficients_in(var).iter().enumerate() {
                sum += c.eval(&v) * v[var].pow(k as isize);
            }
            prop_assert_eq!(sum, a.eval(&v));
        }

        #[test]
        fn quadratic_form_evaluates_as_the_polynomial(a in mpoly(), v in point()) {
            // Homogenise in x, y, z with w, when the degree allows: then Xᵀ A X = h(X).
            let a = MPoly::from_terms(a.terms().iter().filter(|(m, _)| m.exponents()[3] == 0).cloned());
            if let Some(h) = a.homogenize(&[0, 1, 2], 3, 2) {
                prop_assert_eq!(h.homogenize(&[0, 1, 2, 3], 3, 2), Some(h.clone()));
                let m = h.quadratic_form(&[0, 1, 2, 3]).expect("homogeneous of degree 2");
                let mut sum = RBig::ZERO;
                for i in 0..4 {
                    for j in 0..4 {
                        prop_assert_eq!(&m[i][j], &m[j][i]);
                        sum += m[i][j].eval(&v) * &v[i] * &v[j];
                    }
                }
                prop_assert_eq!(sum, h.eval(&v));
                let mut affine = v.clone();
                affine[3] = RBig::ONE;
                prop_assert_eq!(h.eval(&affine), a.eval(&affine));
            } else {
                prop_assert!(a.terms().iter().any(|(m, _)| m.degree_in_vars(&[0, 1, 2]) > 2));
            }
        }

        #[test]
        fn univariate_coefficients_evaluate_alike(cs in proptest::collection::vec(-5i64..=5, 0..6), t in -4i64..=4) {
            let p = MPoly::from_terms(cs.iter().enumerate().map(|(k, &c)| {
                (Monomial::new([0, 0, 0, 0, k as u16, 0, 0, 0]), q(c, 1))
            }));
            let dense = p.to_univariate(4).expect("a polynomial in t");
            prop_assert!(dense.last().is_none_or(|c| !c.is_zero()));
            let v = [RBig::ZERO, RBig::ZERO, RBig::ZERO, RBig::ZERO, q(t, 1)];
            let horner = dense.iter().rev().fold(RBig::ZERO, |acc, c| acc * q(t, 1) + c);
            prop_assert_eq!(horner, p.eval(&v));
        }
    }
}
