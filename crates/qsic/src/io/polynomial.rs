//! Reading a quadric from a polynomial string in `x, y, z, w`: a tokenizer, a
//! recursive-descent reader that expands as it goes into the 15 monomials of
//! degree ≤ 2, then homogenization and the symmetric matrix.

use super::number::{check_digits, excerpt, scan_numeral, NumeralError};
use crate::error::Error;
use crate::limits::{
    MAX_COEFFICIENT_BITS, MAX_EXPANSION_BITS, MAX_INPUT_LEN, MAX_NESTING_DEPTH, MAX_POWER_EXPONENT,
};
use crate::quadric::{Quadric, SmallRational};
use dashu_int::ops::BitTest;
use dashu_int::UBig;
use dashu_ratio::RBig;

/// Reads a quadric from a polynomial in `x, y, z, w` of degree at most 2.
///
/// Two readings, decided on the expanded polynomial:
/// - if `w` occurs in a monomial with a nonzero coefficient, the polynomial is a
///   *projective form* and every monomial must have degree exactly 2;
/// - otherwise it is an *affine equation* in `x, y, z` of degree ≤ 2,
///   homogenized with `w`: a constant `c` becomes `c*w^2`, a linear term
///   `a*x` becomes `a*x*w`. A polynomial without variables such as `5` thus
///   reads as `5*w^2`, the plane at infinity counted twice.
///
/// The matrix `A` of the result satisfies `XᵀAX = p(X)`: `A[i][i]` is the
/// coefficient of `vᵢ²` and `A[i][j] = A[j][i]` half that of `vᵢvⱼ`.
///
/// # Grammar
/// With the usual precedence (power over product over sum):
///
/// ```text
/// sum     := term (('+' | '-') term)*
/// term    := sign* power (('*' | '/' | ε) sign* power)*     ε: juxtaposition before a variable or '('
/// power   := atom (('^' | '**') integer)?
/// atom    := number | 'x' | 'y' | 'z' | 'w' | '(' sum ')'
/// ```
///
/// Variables are lower case. Numbers are unsigned numerals as in
/// [`parse_number`](super::parse_number) (`3`, `0.25`, `1e-3`); a fraction is
/// a division (`1/2*x^2`), and only division by a nonzero number is allowed.
/// Juxtaposition is a product of the same precedence as `*`, so `2x^2` is
/// `2*x^2`, `3 x*y` is `3*x*y`, `(x+1)(x-1)` a product, and `1/2x` is
/// `(1/2)*x`; a number after a factor (`x 2`) is an error. A sign binds looser
/// than a power: `-x^2` is `-(x^2)`. Exponents are integers from 0 to
/// [`MAX_POWER_EXPONENT`]; chained powers `x^2^2` are refused as ambiguous.
///
/// Parentheses are expanded exactly. A product or power whose degree exceeds 2
/// is refused at once, even if later terms would cancel it (`x^3 - x^3`), so
/// no expansion grows beyond 15 coefficients. Reading takes time about linear
/// in the length of the text for inputs of ordinary numbers.
///
/// # Errors
/// - [`Error::Syntax`] with the 1-based character column for malformed input,
///   division by zero or by a non-constant expression;
/// - [`Error::UnknownVariable`] for any name but `x, y, z, w` (including `X`);
/// - [`Error::Degree`] for a product or power of degree above 2, or, in a form
///   using `w`, a monomial of degree 0 or 1;
/// - [`Error::ZeroQuadric`] if the polynomial expands to zero (`x^2 - x^2`);
/// - [`Error::Limit`] beyond the bounds of [`crate::limits`] (input length,
///   digits, exponents, nesting, coefficient size).
///
/// # Examples
/// ```
/// use qsic::io::parse_quadric;
///
/// // The unit sphere, homogenized: diag(1, 1, 1, -1).
/// let sphere = parse_quadric("x^2 + y^2 + z^2 - 1")?;
/// assert_eq!(sphere.to_polynomial_string(), "x^2 + y^2 + z^2 - w^2");
///
/// // Parentheses are expanded; `2*x*y` contributes 1 to A[0][1] and A[1][0].
/// let q = parse_quadric("(x+y)^2 - 2*(z-w)*(z+w)")?;
/// assert_eq!(q.entry(0, 1), &1.into());
/// assert_eq!(q.entry(3, 3), &2.into());
///
/// assert!(parse_quadric("x^2 + w").is_err()); // a form using w must be homogeneous
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn parse_quadric(text: &str) -> Result<Quadric, Error> {
    if text.len() > MAX_INPUT_LEN {
        return Err(Error::Limit {
            what: format!("{} bytes in a polynomial string", text.len()),
            limit: MAX_INPUT_LEN,
        });
    }
    if text.len() <= MACHINE_READER_MAX_LEN {
        if let Some(q) = read_small(text) {
            return Ok(q);
        }
    }
    parse_quadric_big_route(text)
}

/// [`parse_quadric`] without its machine-arithmetic reader: the general reader, which the
/// machine reader must equal wherever it answers (differential tests).
///
/// # Errors
/// As [`parse_quadric`].
#[doc(hidden)]
pub fn parse_quadric_big_route(text: &str) -> Result<Quadric, Error> {
    if text.len() > MAX_INPUT_LEN {
        return Err(Error::Limit {
            what: format!("{} bytes in a polynomial string", text.len()),
            limit: MAX_INPUT_LEN,
        });
    }
    let mut budget = Budget {
        left: MAX_EXPANSION_BITS,
    };
    let tokens = tokenize(text, &mut budget)?;
    let mut parser = Parser {
        text,
        tokens,
        pos: 0,
        depth: 0,
        budget,
        spare: Spare::default(),
    };
    let poly = parser.parse()?;
    quadric_from_poly(poly)
}

/// Longest text the machine reader takes (bytes). Its numbers have at most 128 bits, so
/// within this length the general reader's size limits cannot be reached.
const MACHINE_READER_MAX_LEN: usize = 10_000;

/// The machine-arithmetic reader: the quadric of a polynomial written as a sum of terms,
/// each a product of numbers of at most 18 digits (`*`, `/` or juxtaposition before a
/// variable) and variables with exponents 0–2, such as `3*x^2 - 1/2 x*y + 0.5w^2`, when
/// every coefficient fits an `i64` over a `u64`.
///
/// `None` for anything else (parentheses, powers of numbers, unary signs after `*`, errors,
/// the zero polynomial, overflow): [`parse_quadric_big_route`] then reads the text, and
/// gives the error if there is one. Where it answers, the answer is that of the general
/// reader (same grammar, exact arithmetic).
fn read_small(text: &str) -> Option<Quadric> {
    let b = text.as_bytes();
    let mut pos = 0;
    let skip = |pos: &mut usize| {
        while b
            .get(*pos)
            .is_some_and(|c| matches!(c, b' ' | b'\t' | b'\n' | b'\r'))
        {
            *pos += 1;
        }
    };
    let mut acc = [SmallRational::ZERO; N];
    loop {
        // Unary and binary signs in front of the term.
        let mut negative = false;
        skip(&mut pos);
        while let Some(&c @ (b'+' | b'-')) = b.get(pos) {
            negative ^= c == b'-';
            pos += 1;
            skip(&mut pos);
        }
        let mut coefficient = SmallRational { num: 1, den: 1 };
        let mut monomial = 0;
        loop {
            skip(&mut pos);
            match b.get(pos)? {
                b'0'..=b'9' | b'.' => {
                    let (value, len) = small_numeral(text, pos)?;
                    coefficient = small_product(coefficient, value, false)?;
                    pos += len;
                }
                &c @ (b'x' | b'y' | b'z' | b'w') => {
                    pos += 1;
                    if b.get(pos)
                        .is_some_and(|&c| c.is_ascii_alphanumeric() || c == b'_' || c >= 0x80)
                    {
                        return None;
                    }
                    let variable = 1 + VARIABLES.iter().position(|&v| v as u8 == c)?;
                    skip(&mut pos);
                    let exponent = match (b.get(pos), b.get(pos + 1)) {
                        (Some(b'^'), _) => 1,
                        (Some(b'*'), Some(b'*')) => 2,
                        _ => 0,
                    };
                    let mut power = 1;
                    if exponent > 0 {
                        pos += exponent;
                        skip(&mut pos);
                        let start = pos;
                        while b.get(pos).is_some_and(u8::is_ascii_digit) {
                            pos += 1;
                        }
                        let digits = &text[start..pos];
                        if digits.is_empty()
                            || digits.len() > 3
                            || matches!(b.get(pos), Some(b'.' | b'e' | b'E'))
                        {
                            return None;
                        }
                        power = digits.parse::<usize>().ok()?;
                        skip(&mut pos);
                        if matches!(b.get(pos), Some(b'^')) || b[pos..].starts_with(b"**") {
                            return None;
                        }
                    }
                    for _ in 0..power {
                        monomial = product_index(monomial, variable)?;
                    }
                }
                _ => return None,
            }
            skip(&mut pos);
            match b.get(pos) {
                None | Some(b'+' | b'-') => break,
                Some(b'*') if b.get(pos + 1) != Some(&b'*') => pos += 1,
                Some(b'/') => {
                    pos += 1;
                    skip(&mut pos);
                    if !matches!(b.get(pos), Some(b'0'..=b'9' | b'.')) {
                        return None;
                    }
                    let (divisor, len) = small_numeral(text, pos)?;
                    pos += len;
                    skip(&mut pos);
                    if divisor.num == 0
                        || matches!(b.get(pos), Some(b'^'))
                        || b[pos..].starts_with(b"**")
                    {
                        return None;
                    }
                    coefficient = small_product(coefficient, divisor, true)?;
                    match b.get(pos) {
                        None | Some(b'+' | b'-') => break,
                        Some(b'*') if b.get(pos + 1) != Some(&b'*') => pos += 1,
                        Some(b'x' | b'y' | b'z' | b'w') => {}
                        _ => return None,
                    }
                }
                // Juxtaposition before a variable.
                Some(b'x' | b'y' | b'z' | b'w') => {}
                _ => return None,
            }
        }
        if negative {
            coefficient.num = coefficient.num.checked_neg()?;
        }
        acc[monomial] = small_sum(acc[monomial], coefficient)?;
        if pos >= b.len() {
            break;
        }
    }
    small_quadric(&acc)
}

/// The unsigned numeral at byte `pos` of `text` as a small rational, and its length: a run
/// of at most 18 digits read at once, anything else through [`scan_numeral`].
#[inline]
fn small_numeral(text: &str, pos: usize) -> Option<(SmallRational, usize)> {
    let b = text.as_bytes();
    let mut i = pos;
    let mut value = 0u64;
    while let Some(&d) = b.get(i).filter(|d| d.is_ascii_digit()) {
        if i - pos == 18 {
            break;
        }
        value = value * 10 + u64::from(d - b'0');
        i += 1;
    }
    if i > pos && !matches!(b.get(i), Some(b'0'..=b'9' | b'.' | b'e' | b'E')) {
        // At most 18 digits: below 10^18 < 2^63.
        let num = value as i64;
        return Some((SmallRational { num, den: 1 }, i - pos));
    }
    let (numeral, len) = scan_numeral(text.get(pos..)?).ok()?;
    Some((numeral.small_value()?, len))
}

/// `a·b`, or `a/b` if `divide` (`b` then positive), in machine integers; `None` on overflow.
fn small_product(a: SmallRational, b: SmallRational, divide: bool) -> Option<SmallRational> {
    let (num, den) = if divide {
        (i64::try_from(b.den).ok()?, b.num.unsigned_abs())
    } else {
        (b.num, b.den)
    };
    Some(SmallRational {
        num: a.num.checked_mul(num)?,
        den: a.den.checked_mul(den)?,
    })
}

/// `a + b` in lowest terms when a denominator is not 1; `None` on overflow.
fn small_sum(a: SmallRational, b: SmallRational) -> Option<SmallRational> {
    if a.num == 0 {
        return Some(b);
    }
    if a.den == b.den {
        return Some(SmallRational {
            num: a.num.checked_add(b.num)?,
            den: a.den,
        });
    }
    let num = i128::from(a.num) * i128::from(b.den) + i128::from(b.num) * i128::from(a.den);
    let den = u128::from(a.den) * u128::from(b.den);
    let g = crate::quadric::gcd_u128(num.unsigned_abs(), den);
    Some(SmallRational {
        num: i64::try_from(num / i128::try_from(g).ok()?).ok()?,
        den: u64::try_from(den / g).ok()?,
    })
}

/// The quadric of the expanded polynomial `acc` (homogenized as in [`quadric_from_poly`]),
/// or `None` where that gives an error or a number overflows.
fn small_quadric(acc: &[SmallRational; N]) -> Option<Quadric> {
    let mut uses_w = false;
    let mut not_quadratic = false;
    let mut any = false;
    for (k, c) in acc.iter().enumerate() {
        if c.num != 0 {
            any = true;
            uses_w |= MONOMIALS[k][3] > 0;
            not_quadratic |= k < FIRST_QUADRATIC;
        }
    }
    if !any || (uses_w && not_quadratic) {
        return None;
    }
    let mut m = [[SmallRational::ZERO; 4]; 4];
    for (c, &(i, j)) in acc.iter().zip(&HOMOGENIZED) {
        if c.num == 0 {
            continue;
        }
        if i == j {
            m[i][i] = *c;
        } else {
            let half = SmallRational {
                num: c.num,
                den: c.den.checked_mul(2)?,
            };
            m[i][j] = half;
            m[j][i] = half;
        }
    }
    Quadric::from_small_rationals(&m).ok()
}

/// Index in [`MONOMIALS`] of the first monomial of degree 2 (they are ordered by degree).
const FIRST_QUADRATIC: usize = 5;

/// `HOMOGENIZED[k]` is the matrix position `(i, j)`, `i ≤ j`, of monomial `k` after
/// homogenization with `w` (as in [`quadric_from_poly`]): `1 → w²`, `x → x·w`, `x² → x²`, ….
const HOMOGENIZED: [(usize, usize); N] = homogenized_positions();

const fn homogenized_positions() -> [(usize, usize); N] {
    let mut out = [(0, 0); N];
    let mut k = 0;
    while k < N {
        let mut e = MONOMIALS[k];
        let degree = (e[0] + e[1] + e[2] + e[3]) as usize;
        e[3] += (2 - degree) as u8;
        // The two variables of the degree-2 monomial e, in order.
        let mut first = 4;
        let mut second = 4;
        let mut v = 0;
        while v < 4 {
            if e[v] == 2 {
                first = v;
                second = v;
            } else if e[v] == 1 {
                if first == 4 {
                    first = v;
                } else {
                    second = v;
                }
            }
            v += 1;
        }
        out[k] = (first, second);
        k += 1;
    }
    out
}

/// The variables, in matrix order.
const VARIABLES: [char; 4] = ['x', 'y', 'z', 'w'];

/// Number of monomials of degree ≤ 2 in four variables.
const N: usize = 15;

/// The monomials of degree ≤ 2 as exponent vectors: 1, then x, y, z, w, then
/// x², xy, xz, xw, y², yz, yw, z², zw, w².
const MONOMIALS: [[u8; 4]; N] = [
    [0, 0, 0, 0],
    [1, 0, 0, 0],
    [0, 1, 0, 0],
    [0, 0, 1, 0],
    [0, 0, 0, 1],
    [2, 0, 0, 0],
    [1, 1, 0, 0],
    [1, 0, 1, 0],
    [1, 0, 0, 1],
    [0, 2, 0, 0],
    [0, 1, 1, 0],
    [0, 1, 0, 1],
    [0, 0, 2, 0],
    [0, 0, 1, 1],
    [0, 0, 0, 2],
];

/// Total degree of monomial `k`.
fn degree_of(k: usize) -> usize {
    MONOMIALS[k].iter().map(|&e| usize::from(e)).sum()
}

/// `PRODUCTS[i][j]` is the index of the product of monomials `i` and `j`, or
/// [`NO_MONOMIAL`] if its degree exceeds 2.
const PRODUCTS: [[u8; N]; N] = product_table();

/// Marks a product of degree above 2 in [`PRODUCTS`].
const NO_MONOMIAL: u8 = u8::MAX;

const fn product_table() -> [[u8; N]; N] {
    let mut table = [[NO_MONOMIAL; N]; N];
    let mut i = 0;
    while i < N {
        let mut j = 0;
        while j < N {
            let mut k = 0;
            while k < N {
                let mut v = 0;
                while v < 4 && MONOMIALS[i][v] + MONOMIALS[j][v] == MONOMIALS[k][v] {
                    v += 1;
                }
                if v == 4 {
                    // k < N = 15 fits in a u8.
                    table[i][j] = k as u8;
                }
                k += 1;
            }
            j += 1;
        }
        i += 1;
    }
    table
}

/// Index of the product of monomials `i` and `j`, if its degree is at most 2.
fn product_index(i: usize, j: usize) -> Option<usize> {
    match PRODUCTS[i][j] {
        NO_MONOMIAL => None,
        k => Some(usize::from(k)),
    }
}

/// Monomial `k` written as in [`Quadric::to_polynomial_string`] (`x^2`, `x*y`, `1`).
fn monomial_text(k: usize) -> String {
    let factors: Vec<String> = MONOMIALS[k]
        .iter()
        .zip(VARIABLES)
        .filter(|(&e, _)| e > 0)
        .map(|(&e, v)| {
            if e == 1 {
                v.to_string()
            } else {
                format!("{v}^{e}")
            }
        })
        .collect();
    if factors.is_empty() {
        "1".into()
    } else {
        factors.join("*")
    }
}

/// A term `c·monomial` as text, e.g. `3*x`, `-x*w`, `-1/2`.
fn term_text(c: &RBig, k: usize) -> String {
    if k == 0 {
        c.to_string()
    } else if c.is_one() {
        monomial_text(k)
    } else if *c == RBig::NEG_ONE {
        format!("-{}", monomial_text(k))
    } else {
        format!("{c}*{}", monomial_text(k))
    }
}

/// What is left of [`MAX_EXPANSION_BITS`] for reading one polynomial.
#[derive(Debug)]
struct Budget {
    left: usize,
}

impl Budget {
    /// Accounts for a newly computed number: refuses it if it is larger than
    /// [`MAX_COEFFICIENT_BITS`] or the total exceeds [`MAX_EXPANSION_BITS`].
    #[inline]
    fn charge(&mut self, c: &RBig) -> Result<(), Error> {
        let bits = c.numerator().bit_len() + c.denominator().bit_len();
        match self.left.checked_sub(bits) {
            Some(left) if bits <= MAX_COEFFICIENT_BITS => {
                self.left = left;
                Ok(())
            }
            _ => Err(Self::refusal(bits)),
        }
    }

    /// Why [`Budget::charge`] refuses a number of `bits` bits.
    #[cold]
    fn refusal(bits: usize) -> Error {
        if bits > MAX_COEFFICIENT_BITS {
            Error::Limit {
                what: format!("a coefficient of {bits} bits while expanding the polynomial"),
                limit: MAX_COEFFICIENT_BITS,
            }
        } else {
            Error::Limit {
                what: "total size of the numbers computed while expanding the polynomial, in bits"
                    .into(),
                limit: MAX_EXPANSION_BITS,
            }
        }
    }
}

/// A polynomial of degree ≤ 2 in x, y, z, w: its terms with a nonzero
/// coefficient, as (index into [`MONOMIALS`], coefficient), in increasing
/// order of index.
///
/// Since [`MONOMIALS`] is ordered by degree, the degree is that of the last
/// term. Most polynomials met while reading have one or a few terms, so this
/// is much cheaper to build, combine and drop than 15 dense coefficients, and
/// it keeps the frames of the recursive reader small.
#[derive(Debug, Default)]
struct Poly {
    terms: Vec<(usize, RBig)>,
}

/// `a · b`, with shortcuts for a factor 1 and for integers (no gcd needed).
fn product(a: &RBig, b: &RBig) -> RBig {
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

/// `a += b`, or `a -= b` if `negative`, with a shortcut for integers.
fn accumulate(a: &mut RBig, b: &RBig, negative: bool) {
    if a.is_int() && b.is_int() {
        let n = if negative {
            a.numerator() - b.numerator()
        } else {
            a.numerator() + b.numerator()
        };
        *a = RBig::from(n);
    } else if negative {
        *a -= b;
    } else {
        *a += b;
    }
}

/// Storage of the polynomials dropped while reading, reused to build new ones
/// without allocating.
#[derive(Debug, Default)]
struct Spare(Vec<Vec<(usize, RBig)>>);

impl Spare {
    /// At most this many buffers are kept.
    const KEEP: usize = 16;

    /// An empty buffer, with room for any polynomial.
    fn take(&mut self) -> Vec<(usize, RBig)> {
        self.0.pop().unwrap_or_else(|| Vec::with_capacity(N))
    }

    /// Takes back the storage of a polynomial that is no longer needed.
    fn keep(&mut self, p: Poly) {
        let mut terms = p.terms;
        if terms.capacity() > 0 && self.0.len() < Self::KEEP {
            terms.clear();
            self.0.push(terms);
        }
    }

    fn constant(&mut self, value: RBig) -> Poly {
        let mut terms = Vec::new();
        if !value.is_zero() {
            terms = self.take();
            terms.push((0, value));
        }
        Poly { terms }
    }

    fn variable(&mut self, i: usize) -> Poly {
        let mut terms = self.take();
        terms.push((1 + i, RBig::ONE));
        Poly { terms }
    }

    fn copy(&mut self, p: &Poly) -> Poly {
        let mut terms = self.take();
        terms.extend_from_slice(&p.terms);
        Poly { terms }
    }
}

impl Poly {
    fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// Degree of the highest nonzero monomial; 0 for the zero polynomial.
    fn degree(&self) -> usize {
        self.terms.last().map_or(0, |&(k, _)| degree_of(k))
    }

    fn negate(&mut self) {
        for (_, c) in &mut self.terms {
            *c = -std::mem::take(c);
        }
    }

    /// `self += sign · other`.
    ///
    /// Every coefficient of `self` that `other` changes is charged, in
    /// increasing order of monomial, even if it cancels to zero.
    fn add_assign(
        &mut self,
        mut other: Poly,
        negative: bool,
        budget: &mut Budget,
        spare: &mut Spare,
    ) -> Result<(), Error> {
        let wanted = self.terms.len() + other.terms.len();
        if wanted > self.terms.capacity() {
            // At most N terms: grow once rather than term by term.
            self.terms.reserve(wanted.min(N) - self.terms.len());
        }
        let mut cancelled = false;
        for (k, b) in other.terms.drain(..) {
            match self.terms.binary_search_by_key(&k, |&(i, _)| i) {
                Ok(p) => {
                    let a = &mut self.terms[p].1;
                    accumulate(a, &b, negative);
                    budget.charge(a)?;
                    cancelled |= a.is_zero();
                }
                Err(p) => {
                    let b = if negative { -b } else { b };
                    budget.charge(&b)?;
                    self.terms.insert(p, (k, b));
                }
            }
        }
        spare.keep(other);
        if cancelled {
            self.terms.retain(|(_, c)| !c.is_zero());
        }
        Ok(())
    }

    /// `self · factor` for a nonzero rational `factor`.
    fn scale(&mut self, factor: &RBig, budget: &mut Budget) -> Result<(), Error> {
        for (_, c) in &mut self.terms {
            if !factor.is_one() {
                *c = product(c, factor);
            }
            budget.charge(c)?;
        }
        Ok(())
    }

    /// The product, or `Ok(Err(degree))` if its degree would exceed 2.
    ///
    /// The degree of a product is the sum of the degrees (no zero divisors), so
    /// the refusal is exact and decided before any multiplication. Each new
    /// coefficient is charged as it is accumulated, for the terms of `self`
    /// in increasing order and within each for those of `other`; products by
    /// a single term, the usual case, are computed in the storage of an operand.
    fn mul(
        mut self,
        mut other: Poly,
        budget: &mut Budget,
        spare: &mut Spare,
    ) -> Result<Result<Poly, usize>, Error> {
        if self.is_zero() || other.is_zero() {
            spare.keep(self);
            spare.keep(other);
            return Ok(Ok(Poly::default()));
        }
        let degree = self.degree() + other.degree();
        if degree > 2 {
            return Ok(Err(degree));
        }
        let out = match (self.terms.as_mut_slice(), other.terms.as_slice()) {
            ([(i, a)], [(j, b)]) => {
                // degree(i) + degree(j) ≤ 2, so the monomial is in the table.
                if let Some(k) = product_index(*i, *j) {
                    // A product of nonzero rationals is nonzero.
                    *a = product(a, b);
                    *i = k;
                    budget.charge(a)?;
                } else {
                    self.terms.clear();
                }
                spare.keep(other);
                self
            }
            ([(0, c)], _) => {
                let c = std::mem::take(c);
                spare.keep(self);
                other.scale(&c, budget)?;
                other
            }
            (_, [(0, c)]) => {
                self.scale(c, budget)?;
                spare.keep(other);
                self
            }
            _ => {
                let out = self.mul_general(&other, budget, spare.take())?;
                spare.keep(self);
                spare.keep(other);
                out
            }
        };
        Ok(Ok(out))
    }

    /// The product into the empty buffer `terms`, when its degree is known to
    /// be at most 2.
    fn mul_general(
        &self,
        other: &Poly,
        budget: &mut Budget,
        mut terms: Vec<(usize, RBig)>,
    ) -> Result<Poly, Error> {
        let mut cancelled = false;
        for (i, a) in &self.terms {
            for (j, b) in &other.terms {
                let Some(k) = product_index(*i, *j) else {
                    continue;
                };
                let p = product(a, b);
                match terms.binary_search_by_key(&k, |&(m, _)| m) {
                    Ok(q) => {
                        let c = &mut terms[q].1;
                        accumulate(c, &p, false);
                        budget.charge(c)?;
                        cancelled |= c.is_zero();
                    }
                    Err(q) => {
                        budget.charge(&p)?;
                        terms.insert(q, (k, p));
                    }
                }
            }
        }
        if cancelled {
            terms.retain(|(_, c)| !c.is_zero());
        }
        Ok(Poly { terms })
    }
}

/// A lexical token.
#[derive(Debug)]
enum Tok {
    Number(RBig),
    Variable(usize),
    Plus,
    Minus,
    Star,
    Slash,
    /// `^` or `**`.
    Power,
    Open,
    Close,
    End,
}

/// A token with its place: 1-based character column and byte range.
#[derive(Debug)]
struct Token {
    tok: Tok,
    column: usize,
    start: usize,
    end: usize,
}

/// Splits `text` into tokens, ending with [`Tok::End`].
fn tokenize(text: &str, budget: &mut Budget) -> Result<Vec<Token>, Error> {
    // A token takes at least one byte: no growth for short texts.
    let mut tokens = Vec::with_capacity((text.len() + 1).min(1024));
    let mut column = 1;
    let mut rest = text.char_indices().peekable();
    while let Some((start, ch)) = rest.next() {
        let mut len = ch.len_utf8();
        let mut width = 1;
        let tok = match ch {
            c if c.is_whitespace() => {
                column += 1;
                continue;
            }
            '+' => Tok::Plus,
            '-' => Tok::Minus,
            '/' => Tok::Slash,
            '^' => Tok::Power,
            '(' => Tok::Open,
            ')' => Tok::Close,
            '*' => {
                if rest.next_if(|&(_, c)| c == '*').is_some() {
                    len = 2;
                    width = 2;
                    Tok::Power
                } else {
                    Tok::Star
                }
            }
            '0'..='9' | '.' => {
                let (numeral, n) = scan_numeral(&text[start..]).map_err(|e| match e {
                    NumeralError::Limit(limit) => limit,
                    NumeralError::Malformed { message, .. } => Error::Syntax { column, message },
                })?;
                check_digits(numeral.digit_count())?;
                // A numeral is ASCII: its byte length is its width in characters.
                len = n;
                width = n;
                if n > 1 {
                    // Skip the other n - 1 characters of the numeral.
                    rest.nth(n - 2);
                }
                let value = numeral.value();
                budget.charge(&value)?;
                Tok::Number(value)
            }
            c if c.is_alphabetic() || c == '_' => {
                while rest
                    .next_if(|&(_, c)| c.is_alphabetic() || c.is_ascii_digit() || c == '_')
                    .is_some()
                {}
                let end = rest.peek().map_or(text.len(), |&(i, _)| i);
                let name = &text[start..end];
                match VARIABLES
                    .iter()
                    .position(|v| name.len() == 1 && name.starts_with(*v))
                {
                    Some(i) => {
                        len = end - start;
                        Tok::Variable(i)
                    }
                    None => {
                        return Err(Error::UnknownVariable {
                            name: excerpt(name),
                            column,
                        })
                    }
                }
            }
            c => {
                return Err(Error::Syntax {
                    column,
                    message: format!("unexpected character '{c}'"),
                })
            }
        };
        tokens.push(Token {
            tok,
            column,
            start,
            end: start + len,
        });
        column += width;
    }
    tokens.push(Token {
        tok: Tok::End,
        column,
        start: text.len(),
        end: text.len(),
    });
    Ok(tokens)
}

/// Recursive-descent reader over the tokens, expanding as it goes.
struct Parser<'a> {
    text: &'a str,
    tokens: Vec<Token>,
    pos: usize,
    depth: usize,
    budget: Budget,
    spare: Spare,
}

impl Parser<'_> {
    fn peek(&self) -> &Token {
        // The last token is End and is never consumed, so `pos` stays in range.
        &self.tokens[self.pos.min(self.tokens.len() - 1)]
    }

    fn advance(&mut self) {
        if !matches!(self.peek().tok, Tok::End) {
            self.pos += 1;
        }
    }

    fn syntax(column: usize, message: impl Into<String>) -> Error {
        Error::Syntax {
            column,
            message: message.into(),
        }
    }

    /// What the current token is, for messages.
    fn describe(&self) -> String {
        let t = self.peek();
        match t.tok {
            Tok::End => "the end of the input".into(),
            Tok::Number(_) => format!("the number '{}'", excerpt(&self.text[t.start..t.end])),
            _ => format!("'{}'", &self.text[t.start..t.end]),
        }
    }

    /// The whole input as one polynomial.
    fn parse(&mut self) -> Result<Poly, Error> {
        if matches!(self.peek().tok, Tok::End) {
            return Err(Self::syntax(1, "empty polynomial"));
        }
        let poly = self.sum()?;
        match self.peek().tok {
            Tok::End => Ok(poly),
            Tok::Close => Err(Self::syntax(self.peek().column, "unmatched ')'")),
            Tok::Number(_) => Err(Self::syntax(
                self.peek().column,
                format!(
                    "expected an operator before {}; write the number first, as in '2*x' or '2x'",
                    self.describe()
                ),
            )),
            _ => Err(Self::syntax(
                self.peek().column,
                format!("expected an operator, found {}", self.describe()),
            )),
        }
    }

    fn sum(&mut self) -> Result<Poly, Error> {
        let mut acc = self.term()?;
        loop {
            let negative = match self.peek().tok {
                Tok::Plus => false,
                Tok::Minus => true,
                _ => return Ok(acc),
            };
            self.advance();
            let t = self.term()?;
            acc.add_assign(t, negative, &mut self.budget, &mut self.spare)?;
        }
    }

    /// Consumes any run of unary signs; true if their product is negative.
    fn signs(&mut self) -> bool {
        let mut negative = false;
        loop {
            match self.peek().tok {
                Tok::Plus => {}
                Tok::Minus => negative = !negative,
                _ => return negative,
            }
            self.advance();
        }
    }

    fn term(&mut self) -> Result<Poly, Error> {
        let first = self.pos;
        let negative = self.signs();
        let mut acc = self.power()?;
        loop {
            let (divide, op_column) = match self.peek().tok {
                Tok::Star => (false, Some(self.peek().column)),
                Tok::Slash => (true, Some(self.peek().column)),
                Tok::Variable(_) | Tok::Open => (false, None),
                _ => break,
            };
            if op_column.is_some() {
                self.advance();
            }
            let factor_negative = self.signs();
            let mut factor = self.power()?;
            if factor_negative {
                factor.negate();
            }
            if divide {
                let column = op_column.unwrap_or(1);
                let divisor = match factor.terms.as_slice() {
                    [] => return Err(Self::syntax(column, "division by zero")),
                    [(0, divisor)] => divisor,
                    _ => {
                        return Err(Self::syntax(
                            column,
                            "can only divide by a number, not by an expression in x, y, z, w",
                        ))
                    }
                };
                let inverse = RBig::ONE / divisor;
                acc.scale(&inverse, &mut self.budget)?;
                self.spare.keep(factor);
            } else {
                acc = self.checked_product(acc, factor, first)?;
            }
        }
        if negative {
            acc.negate();
        }
        Ok(acc)
    }

    /// `a · b`, or [`Error::Degree`] naming the source text from token `first` to here.
    fn checked_product(&mut self, a: Poly, b: Poly, first: usize) -> Result<Poly, Error> {
        a.mul(b, &mut self.budget, &mut self.spare)?
            .map_err(|degree| self.degree_error(first, degree))
    }

    fn degree_error(&self, first: usize, degree: usize) -> Error {
        let from = &self.tokens[first.min(self.tokens.len() - 1)];
        let to = &self.tokens[self
            .pos
            .saturating_sub(1)
            .max(first)
            .min(self.tokens.len() - 1)];
        let snippet = self.text[from.start..to.end.max(from.start)].trim();
        Error::Degree {
            message: format!(
                "term '{}' at column {} has degree {degree}; a quadric has degree at most 2",
                excerpt(snippet),
                from.column
            ),
        }
    }

    fn power(&mut self) -> Result<Poly, Error> {
        let first = self.pos;
        let mut base = self.atom()?;
        if !matches!(self.peek().tok, Tok::Power) {
            return Ok(base);
        }
        self.advance();
        let t = self.peek();
        let raw = &self.text[t.start..t.end];
        let exponent_column = t.column;
        if !matches!(t.tok, Tok::Number(_)) || !raw.bytes().all(|b| b.is_ascii_digit()) {
            return Err(Self::syntax(
                exponent_column,
                format!(
                    "the exponent must be a non-negative integer, found {}",
                    self.describe()
                ),
            ));
        }
        let digits = raw.trim_start_matches('0');
        let n = match digits.parse::<usize>() {
            Ok(n) if n <= MAX_POWER_EXPONENT => n,
            _ if digits.is_empty() => 0,
            _ => {
                return Err(Error::Limit {
                    what: format!("exponent {} at column {exponent_column}", excerpt(raw)),
                    limit: MAX_POWER_EXPONENT,
                })
            }
        };
        self.advance();
        if matches!(self.peek().tok, Tok::Power) {
            return Err(Self::syntax(
                self.peek().column,
                "chained powers are ambiguous; use parentheses, as in '(x^2)^2'",
            ));
        }
        let base_degree = base.degree();
        if base_degree * n > 2 {
            return Err(self.degree_error(first, base_degree * n));
        }
        if n == 0 {
            self.spare.keep(base);
            return Ok(self.spare.constant(RBig::ONE));
        }
        // The first factor, 1 · base, is base itself: only its coefficients
        // are charged, as a product would.
        for (_, c) in &base.terms {
            self.budget.charge(c)?;
        }
        if n == 1 {
            return Ok(base);
        }
        let mut acc = self.spare.copy(&base);
        for step in 1..n {
            let factor = if step + 1 == n {
                std::mem::take(&mut base)
            } else {
                self.spare.copy(&base)
            };
            acc = self.checked_product(acc, factor, first)?;
        }
        Ok(acc)
    }

    fn atom(&mut self) -> Result<Poly, Error> {
        let column = self.peek().column;
        let poly = match &self.peek().tok {
            Tok::Number(value) => {
                let value = value.clone();
                self.spare.constant(value)
            }
            &Tok::Variable(i) => self.spare.variable(i),
            Tok::Open => {
                if self.depth >= MAX_NESTING_DEPTH {
                    return Err(Error::Limit {
                        what: format!("nesting of parentheses at column {column}"),
                        limit: MAX_NESTING_DEPTH,
                    });
                }
                self.depth += 1;
                self.advance();
                let inner = self.sum()?;
                if !matches!(self.peek().tok, Tok::Close) {
                    return Err(Self::syntax(
                        self.peek().column,
                        format!(
                            "expected ')' to close the '(' at column {column}, found {}",
                            self.describe()
                        ),
                    ));
                }
                self.depth -= 1;
                inner
            }
            _ => {
                return Err(Self::syntax(
                    column,
                    format!(
                        "expected a number, a variable or '(', found {}",
                        self.describe()
                    ),
                ))
            }
        };
        self.advance();
        Ok(poly)
    }
}

/// `c / 2`, with shortcuts for integers.
fn half(c: RBig) -> RBig {
    if !c.is_int() {
        c / RBig::from(2)
    } else if c.numerator().bit(0) {
        RBig::from_parts(c.into_parts().0, UBig::from(2u8))
    } else {
        RBig::from(c.into_parts().0 >> 1)
    }
}

/// The quadric of an expanded polynomial: homogeneity check or homogenization, then the matrix.
fn quadric_from_poly(poly: Poly) -> Result<Quadric, Error> {
    if poly.is_zero() {
        return Err(Error::ZeroQuadric);
    }
    let uses_w = poly.terms.iter().any(|&(k, _)| MONOMIALS[k][3] > 0);
    let mut m: [[RBig; 4]; 4] = Default::default();
    for (k, c) in poly.terms {
        let mut e = MONOMIALS[k];
        let degree = degree_of(k);
        if uses_w && degree != 2 {
            return Err(Error::Degree {
                message: format!(
                    "term '{}' has degree {degree}; a form in x,y,z,w must be homogeneous \
                     of degree 2 (leave out w to write an affine equation in x, y, z)",
                    term_text(&c, k)
                ),
            });
        }
        // Homogenize: raise the power of w to reach degree 2 (degree ≤ 2 here).
        e[3] += u8::try_from(2usize.saturating_sub(degree)).unwrap_or(0);
        let mut vars = e
            .iter()
            .enumerate()
            .flat_map(|(v, &p)| std::iter::repeat_n(v, usize::from(p)));
        if let (Some(i), Some(j)) = (vars.next(), vars.next()) {
            if i == j {
                m[i][i] = c;
            } else {
                let half = half(c);
                m[i][j] = half.clone();
                m[j][i] = half;
            }
        }
    }
    Quadric::from_matrix(m)
}

#[cfg(test)]
mod tests {
    use super::*;
    use dashu_int::{IBig, UBig};
    use proptest::prelude::*;
    use std::time::{Duration, Instant};

    fn rat(n: i64, d: u64) -> RBig {
        RBig::from_parts(IBig::from(n), UBig::from(d))
    }

    fn ints(m: [[i64; 4]; 4]) -> Quadric {
        Quadric::from_integers(m).expect("a valid test matrix")
    }

    fn parse(text: &str) -> Quadric {
        parse_quadric(text).unwrap_or_else(|e| panic!("{text:?} should parse: {e}"))
    }

    #[test]
    fn homogenized_positions_follow_the_monomials() {
        assert_eq!(HOMOGENIZED[0], (3, 3));
        assert_eq!(HOMOGENIZED[1], (0, 3));
        assert_eq!(HOMOGENIZED[5], (0, 0));
        assert_eq!(HOMOGENIZED[6], (0, 1));
        assert_eq!(HOMOGENIZED[13], (2, 3));
        assert!((0..N).all(|k| (degree_of(k) == 2) == (k >= FIRST_QUADRATIC)));
    }

    #[test]
    fn machine_reader_takes_plain_sums_and_agrees() {
        let taken = [
            "x^2+y^2+z^2-1",
            "3*x^2 - 1/2 x*y + 0.5w^2",
            "-9*x^2 - 8*x*y + x*z - 7*x*w - 7*y^2 - y*z - 10*y*w - 6*z^2 - 5*z*w + 10*w^2",
            "2x y + 2 z w",
            "x**2 - - y ^ 2 + 1e-3*z*z",
            "x^0*y^2 + 2z^1*x",
            "1/3 x - 2.5e1",
            "x/2*y + y x/4",
            "x^2 - x^2 + y^2",
        ];
        for text in taken {
            let fast = read_small(text).unwrap_or_else(|| panic!("{text:?} should be read"));
            assert_eq!(Ok(fast), parse_quadric_big_route(text), "{text:?}");
        }
        let declined = [
            "",
            "(x+y)^2",
            "2^2*x^2",
            "x*-y",
            "x^2^2",
            "x^3",
            "x*y*z",
            "x2",
            "x^2 + q",
            "x 2",
            "x/0",
            "x/y",
            "x^2.0",
            "x^2 + w",
            "x^2 - x^2",
            "9223372036854775807*x^2 + 9223372036854775807*x^2",
            "x^2 +",
            "x² + y^2",
        ];
        for text in declined {
            assert!(read_small(text).is_none(), "{text:?} should be declined");
        }
    }

    #[test]
    fn homogenizes_affine_equations() {
        let table: &[(&str, [[i64; 4]; 4])] = &[
            (
                "x^2+y^2+z^2-1",
                [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]],
            ),
            (
                "x^2 + 2*x - 4*y + 6*z + 3",
                [[1, 0, 0, 1], [0, 0, 0, -2], [0, 0, 0, 3], [1, -2, 3, 3]],
            ),
            ("5", [[0; 4], [0; 4], [0; 4], [0, 0, 0, 5]]),
            (
                "2*x*y - 2*z",
                [[0, 1, 0, 0], [1, 0, 0, 0], [0, 0, 0, -1], [0, 0, -1, 0]],
            ),
        ];
        for (text, m) in table {
            assert_eq!(parse(text), ints(*m), "input {text:?}");
        }
    }

    #[test]
    fn expands_products_and_powers() {
        let table: &[(&str, [[i64; 4]; 4])] = &[
            ("(x+y)^2", [[1, 1, 0, 0], [1, 1, 0, 0], [0; 4], [0; 4]]),
            ("(x+y)**2", [[1, 1, 0, 0], [1, 1, 0, 0], [0; 4], [0; 4]]),
            ("2*x*y", [[0, 1, 0, 0], [1, 0, 0, 0], [0; 4], [0; 4]]),
            (
                "(x+y)^2 - 2*(z-w)*(z+w)",
                [[1, 1, 0, 0], [1, 1, 0, 0], [0, 0, -2, 0], [0, 0, 0, 2]],
            ),
            ("-x^2", [[-1, 0, 0, 0], [0; 4], [0; 4], [0; 4]]),
            ("-2^2*x^2", [[-4, 0, 0, 0], [0; 4], [0; 4], [0; 4]]),
            ("x*-y*2", [[0, -1, 0, 0], [-1, 0, 0, 0], [0; 4], [0; 4]]),
            ("- -x^2", [[1, 0, 0, 0], [0; 4], [0; 4], [0; 4]]),
            (
                "2x^2 + 4 y*z",
                [[2, 0, 0, 0], [0, 0, 2, 0], [0, 2, 0, 0], [0; 4]],
            ),
            ("(x+1)(x-1)", [[1, 0, 0, 0], [0; 4], [0; 4], [0, 0, 0, -1]]),
            (
                "2x y + 2(z)w",
                [[0, 1, 0, 0], [1, 0, 0, 0], [0, 0, 0, 1], [0, 0, 1, 0]],
            ),
            (
                "x^0*y^2 + 2z^1*x",
                [[0, 0, 1, 0], [0, 1, 0, 0], [1, 0, 0, 0], [0; 4]],
            ),
            ("(((x)))^2", [[1, 0, 0, 0], [0; 4], [0; 4], [0; 4]]),
            (
                "x^2 + (y - y)*z*w*x - 1",
                [[1, 0, 0, 0], [0; 4], [0; 4], [0, 0, 0, -1]],
            ),
        ];
        for (text, m) in table {
            assert_eq!(parse(text), ints(*m), "input {text:?}");
        }
    }

    #[test]
    fn exact_rational_coefficients() {
        let q = parse("x^2/3 + 0.1*y^2 + 1/2*z^2 + 1e-3*x*y + (x+w)^2/2");
        assert_eq!(q.entry(0, 0), &(rat(1, 3) + rat(1, 2)));
        assert_eq!(q.entry(1, 1), &rat(1, 10));
        assert_eq!(q.entry(2, 2), &rat(1, 2));
        assert_eq!(q.entry(0, 1), &rat(1, 2000));
        assert_eq!(q.entry(0, 3), &rat(1, 2));
        assert_eq!(q.entry(3, 3), &rat(1, 2));
        let big = "123456789012345678901234567890";
        let q = parse(&format!("{big}*x*y - w^2"));
        assert_eq!(
            q.entry(0, 1),
            &(RBig::from(IBig::from_str_radix(big, 10).expect("digits")) / RBig::from(2))
        );
    }

    #[test]
    fn syntax_errors_carry_columns() {
        let table: &[(&str, usize)] = &[
            ("", 1),
            ("   ", 1),
            ("x^2 +", 6),
            ("x^2 + * y", 7),
            ("(x+y", 5),
            ("x+y)", 4),
            ("x^2 $ y", 5),
            ("x^y", 3),
            ("x^-2", 3),
            ("x^2.5", 3),
            ("x^2^2", 4),
            ("x^2/y", 4),
            ("x^2/(1-1)", 4),
            ("x^2 2", 5),
            ("x . y", 3),
            ("()", 2),
            ("x²", 2),
        ];
        for (text, column) in table {
            match parse_quadric(text) {
                Err(Error::Syntax { column: c, message }) => {
                    assert_eq!(c, *column, "input {text:?}: {message}")
                }
                other => panic!("input {text:?}: expected a syntax error, got {other:?}"),
            }
        }
    }

    #[test]
    fn unknown_variables_carry_columns() {
        let table = [
            ("x^2 + X", "X", 7),
            ("2*xy", "xy", 3),
            ("u^2", "u", 1),
            ("x+é", "é", 3),
            ("x^2 + 1e", "e", 8),
        ];
        for (text, name, column) in table {
            assert_eq!(
                parse_quadric(text),
                Err(Error::UnknownVariable {
                    name: name.into(),
                    column
                }),
                "input {text:?}"
            );
        }
    }

    #[test]
    fn degree_errors_name_the_term() {
        let table = [
            ("x^3", "term 'x^3' at column 1 has degree 3"),
            ("y^2 + x*y*z", "term 'x*y*z' at column 7 has degree 3"),
            (
                "(x+y)^3 - (x+y)^3",
                "term '(x+y)^3' at column 1 has degree 3",
            ),
            ("x^2*y^2", "term 'x^2*y^2' at column 1 has degree 4"),
            ("(x*y)^2", "term '(x*y)^2' at column 1 has degree 4"),
            (
                "x^2 + 3*x + w^2",
                "term '3*x' has degree 1; a form in x,y,z,w",
            ),
            ("x^2 - w", "term '-w' has degree 1"),
            ("x*w - 1/2", "term '-1/2' has degree 0"),
        ];
        for (text, want) in table {
            match parse_quadric(text) {
                Err(Error::Degree { message }) => {
                    assert!(message.starts_with(want), "input {text:?}: {message}")
                }
                other => panic!("input {text:?}: expected a degree error, got {other:?}"),
            }
        }
    }

    #[test]
    fn zero_polynomials_are_refused() {
        for text in [
            "0",
            "x^2-x^2",
            "0*x*y",
            "(x+w)^2 - x^2 - 2*x*w - w^2",
            "0.0/7",
        ] {
            assert_eq!(
                parse_quadric(text),
                Err(Error::ZeroQuadric),
                "input {text:?}"
            );
        }
    }

    #[test]
    fn a_cancelled_w_leaves_an_affine_equation() {
        assert_eq!(
            parse("x^2 + w - w - 1"),
            ints([[1, 0, 0, 0], [0; 4], [0; 4], [0, 0, 0, -1]])
        );
    }

    #[test]
    fn limits_are_enforced_quickly() {
        let start = Instant::now();
        let cases = [
            "x".repeat(MAX_INPUT_LEN + 1),
            "x^2 + 1e999999999".into(),
            format!("x^2 + {}", "1".repeat(20_000)),
            "x^17".into(),
            "x^99999999999999999999999999".into(),
            format!("{}x{}", "(".repeat(10_000), ")".repeat(10_000)),
            // Numeric towers grow numbers, not degrees.
            "((((((9^16)^16)^16)^16)^16)^16)*x^2".into(),
            format!("{}x^2", "1e-9999*".repeat(20)),
            format!("x^2 + {}", "(1e9999)^16+".repeat(200)),
            // Each term is below the size limit, but together they ask for too much work.
            format!("x^2 + {}1", "(1e-9999)^7+".repeat(8000)),
        ];
        for text in &cases {
            assert!(
                matches!(parse_quadric(text), Err(Error::Limit { .. })),
                "input {}: {:?}",
                excerpt(text),
                parse_quadric(text)
            );
        }
        assert!(
            start.elapsed() < Duration::from_secs(5),
            "took {:?}",
            start.elapsed()
        );
    }

    #[test]
    fn nesting_at_the_limit_fits_in_a_small_stack() {
        let text = format!(
            "{}x{}^2",
            "(".repeat(MAX_NESTING_DEPTH),
            ")".repeat(MAX_NESTING_DEPTH)
        );
        let parsed = std::thread::Builder::new()
            .stack_size(512 * 1024)
            .spawn(move || parse_quadric(&text))
            .expect("a thread")
            .join()
            .expect("no stack overflow");
        assert_eq!(parsed, Ok(ints([[1, 0, 0, 0], [0; 4], [0; 4], [0; 4]])));
    }

    #[test]
    fn deep_unary_signs_do_not_recurse() {
        let text = format!("{}x^2", "-".repeat(50_000));
        assert_eq!(parse(&text), ints([[1, 0, 0, 0], [0; 4], [0; 4], [0; 4]]));
    }

    /// A random nonzero symmetric matrix with small rational entries.
    fn small_rational_matrix() -> impl Strategy<Value = [[RBig; 4]; 4]> {
        let entry = (-20i64..=20, 1u64..=9).prop_map(|(n, d)| rat(n, d));
        proptest::collection::vec(entry, 10).prop_map(|v| {
            let mut m: [[RBig; 4]; 4] = Default::default();
            let upper = (0..4).flat_map(|i| (i..4).map(move |j| (i, j)));
            for ((i, j), value) in upper.zip(v) {
                m[i][j] = value.clone();
                m[j][i] = value;
            }
            m
        })
    }

    proptest! {
        #[test]
        fn polynomial_string_round_trips(m in small_rational_matrix()) {
            if let Ok(q) = Quadric::from_matrix(m) {
                let text = q.to_polynomial_string();
                prop_assert_eq!(parse_quadric(&text), Ok(q), "text {}", text);
            }
        }

        #[test]
        fn arbitrary_strings_do_not_panic(text in "\\PC{0,60}") {
            let _ = parse_quadric(&text);
        }

        #[test]
        fn polynomial_like_strings_do_not_panic(text in "[xyzwX0-9+*/^(). eE-]{0,60}") {
            let _ = parse_quadric(&text);
        }
    }
}
