//! Reading a quadric from a polynomial string in `x, y, z, w`: a machine-arithmetic reader
//! for plain sums of terms, and the general route, the expression reader of
//! [`super::expression`] in its quadric grammar, then homogenization and the matrix.

use super::expression::{read, Grammar, Variable, VARIABLE_NAMES};
use super::number::scan_numeral;
use crate::error::Error;
use crate::limits::{MAX_COEFFICIENT_BITS, MAX_INPUT_LEN};
use crate::quadric::{Quadric, SmallRational};
use dashu_ratio::RBig;
use qsic_algebra::mpoly::{half, MPoly};
use std::borrow::Cow;

/// Reads a quadric from a polynomial in `x, y, z, w` of degree at most 2.
///
/// Three readings, decided on the expanded polynomial:
/// - if `w` occurs in a monomial with a nonzero coefficient, the polynomial is a
///   *projective form* and every monomial must have the same degree, 2 (a quadric) or
///   1 (a plane, below);
/// - otherwise, of degree 2 or 0, it is an *affine equation* in `x, y, z`, homogenized
///   with `w`: a constant `c` becomes `c*w^2`, a linear term `a*x` becomes `a*x*w`. A
///   polynomial without variables such as `5` thus reads as `5*w^2`, the plane at infinity
///   counted twice;
/// - a polynomial of degree exactly 1, affine (`z - 1`, homogenized to `z - w`) or a linear
///   form using `w` (`z - w`), is a *plane* `ℓ = 0`, read as its double plane `ℓ²`: the
///   pencil with a quadric `Q` describes the section `Q ∩ {ℓ = 0}` counted twice (never the
///   plane pair `ℓ·w` with the plane at infinity that homogenizing `ℓ` to degree 2 would
///   give). [`parse_quadric_or_plane`] also says whether the text was a plane.
///
/// The matrix `A` of the result satisfies `XᵀAX = p(X)` (`ℓ(X)²` for a plane): `A[i][i]`
/// is the coefficient of `vᵢ²` and `A[i][j] = A[j][i]` half that of `vᵢvⱼ`.
///
/// # Grammar
/// That of [`parse_rational_function`](super::parse_rational_function), with the usual
/// precedence (power over sign over product over sum):
///
/// ```text
/// sum      := term (('+' | '-') term)*
/// term     := sign* power (('*' | '/' | ε) sign* power)*     ε: juxtaposition before a variable or '('
/// power    := atom (('^' | '**') exponent)?
/// exponent := integer | '-' integer | '(' ('+' | '-')? integer ')'
/// atom     := number | 'x' | 'y' | 'z' | 'w' | '(' sum ')'
/// ```
///
/// Variables are lower case. Numbers are unsigned numerals as in
/// [`parse_number`](super::parse_number) (`3`, `0.25`, `1e-3`); a fraction is
/// a division (`1/2*x^2`), and only division by a nonzero number is allowed, so a
/// negative power only of a nonzero number (`2^-1*x^2` is `x^2/2`; `x^-1` is an error).
/// Juxtaposition is a product of the same precedence as `*`, so `2x^2` is
/// `2*x^2`, `3 x*y` is `3*x*y`, `(x+1)(x-1)` a product, and `1/2x` is
/// `(1/2)*x`; a number after a factor (`x 2`) is an error. A sign binds looser
/// than a power: `-x^2` is `-(x^2)`. Exponents are integers of absolute value at most
/// [`MAX_POWER_EXPONENT`](crate::limits::MAX_POWER_EXPONENT); chained powers `x^2^2` are refused as ambiguous.
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
///   using `w`, monomials of different degrees (`x^2 + w`, `x + w + 1`);
/// - [`Error::ZeroQuadric`] if the polynomial expands to zero (`x^2 - x^2`);
/// - [`Error::Limit`] beyond the bounds of [`crate::limits`] (input length,
///   digits, exponents, nesting, coefficient size, also of the square of a plane).
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
/// // A plane is its double plane, affine or homogeneous.
/// assert_eq!(parse_quadric("z - 1")?, parse_quadric("(z - 1)^2")?);
/// assert_eq!(parse_quadric("z - w")?, parse_quadric("(z - 1)^2")?);
///
/// assert!(parse_quadric("x^2 + w").is_err()); // a form using w must be homogeneous
/// assert!(parse_quadric("x + w + 1").is_err());
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn parse_quadric(text: &str) -> Result<Quadric, Error> {
    parse_quadric_or_plane(text).map(|(q, _)| q)
}

/// [`parse_quadric`], and whether the polynomial had degree 1: a plane, read as its double
/// plane (`affine.surfaces` of the CLI names such a quadric `plane`).
///
/// # Errors
/// As [`parse_quadric`].
///
/// # Examples
/// ```
/// use qsic::io::parse_quadric_or_plane;
/// let (q, plane) = parse_quadric_or_plane("2x - 3")?;
/// assert!(plane);
/// assert_eq!(q.to_polynomial_string(), "4*x^2 - 12*x*w + 9*w^2");
/// assert!(!parse_quadric_or_plane("(2x - 3)^2")?.1);
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn parse_quadric_or_plane(text: &str) -> Result<(Quadric, bool), Error> {
    if text.len() > MAX_INPUT_LEN {
        return Err(Error::Limit {
            what: format!("{} bytes in a polynomial string", text.len()),
            limit: MAX_INPUT_LEN,
        });
    }
    if text.len() <= MACHINE_READER_MAX_LEN {
        // The machine reader declines planes: what it answers is a quadric.
        if let Some(q) = read_small(text) {
            return Ok((q, false));
        }
    }
    read_general(text)
}

/// [`parse_quadric`] without its machine-arithmetic reader: the general reader, which the
/// machine reader must equal wherever it answers (differential tests).
///
/// # Errors
/// As [`parse_quadric`].
#[doc(hidden)]
pub fn parse_quadric_big_route(text: &str) -> Result<Quadric, Error> {
    read_general(text).map(|(q, _)| q)
}

/// The quadric grammar of the expression reader: `x, y, z, w`, division by numbers only.
const QUADRIC_GRAMMAR: Grammar<'static> = Grammar {
    variables: &[Variable::X, Variable::Y, Variable::Z, Variable::W],
    denominator_variables: &[],
    quadric: true,
};

/// The general route: the expression reader, then [`quadric_from_poly`].
fn read_general(text: &str) -> Result<(Quadric, bool), Error> {
    quadric_from_poly(read(text, &QUADRIC_GRAMMAR)?.numerator())
}

/// Reads a plane `a·x + b·y + c·z + d·w = 0` from a polynomial of degree exactly 1: affine
/// in `x, y, z` (`x + 2*y - 3`, the constant is `d`) or a linear form using `w`. `None` for
/// a polynomial of degree 2 (a quadric) or 0.
///
/// [`parse_quadric`] reads the same text as the double plane `P²` ([`plane_as_quadric`]
/// of this plane), whose pencil with a quadric `Q` meets it in the section `Q ∩ P`
/// counted twice.
///
/// ```
/// use qsic::io::{parse_plane, parse_quadric, plane_as_quadric};
/// let p = parse_plane("z - 1").unwrap().unwrap();
/// assert_eq!(p, [0, 0, 1, -1].map(Into::into));
/// assert_eq!(plane_as_quadric(&p).unwrap().to_polynomial_string(), "z^2 - 2*z*w + w^2");
/// assert_eq!(plane_as_quadric(&p), parse_quadric("z - 1"));
/// assert_eq!(parse_plane("x^2 - 1").unwrap(), None);
/// ```
///
/// # Errors
/// As [`parse_quadric`] for text that is not a polynomial of degree at most 2 (and for a
/// linear form using `w` with a constant, `x + w + 1`).
pub fn parse_plane(text: &str) -> Result<Option<[RBig; 4]>, Error> {
    let poly = read(text, &QUADRIC_GRAMMAR)?.into_parts().0;
    if poly.is_zero() {
        return Ok(None);
    }
    let XyzwForm::Plane(l) = form_in_xyzw(&poly)? else {
        return Ok(None);
    };
    let mut plane: [RBig; 4] = Default::default();
    for (monomial, c) in l.terms() {
        if let Some(v) = (0..4).find(|&v| monomial.exponents()[v] == 1) {
            plane[v] = c.clone();
        }
    }
    Ok(Some(plane))
}

/// The double plane `P²` of the plane `p = [a, b, c, d]`.
///
/// # Errors
/// [`Error::ZeroQuadric`] for the zero form.
pub fn plane_as_quadric(p: &[RBig; 4]) -> Result<Quadric, Error> {
    Quadric::from_matrix(std::array::from_fn(|i| {
        std::array::from_fn(|j| &p[i] * &p[j])
    }))
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
/// the zero polynomial, a plane — degree 1 —, overflow): [`parse_quadric_big_route`] then reads the text, and
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
    let (mut any, mut uses_w, mut not_quadratic, mut linear) = (false, false, false, false);
    for (k, c) in acc.iter().enumerate() {
        if c.num != 0 {
            any = true;
            uses_w |= MONOMIALS[k][3] > 0;
            not_quadratic |= k < FIRST_QUADRATIC;
            linear |= (1..FIRST_QUADRATIC).contains(&k);
        }
    }
    let quadratic = acc[FIRST_QUADRATIC..].iter().any(|c| c.num != 0);
    // The zero polynomial, a form using w of mixed degrees and a plane (degree 1, read as
    // its double plane) are left to the general reader.
    if !any || (uses_w && not_quadratic) || (linear && !quadratic) {
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

/// The first term of `poly` (in the order 1, x, y, z, w, x², x·y, … of the variables
/// x, y, z, w) whose degree in x, y, z, w is not allowed, as an error.
fn first_bad_term(poly: &MPoly, bad: impl Fn(u32) -> bool, why: &str) -> Result<(), Error> {
    let xyzw = [0, 1, 2, 3];
    let first = poly
        .terms()
        .iter()
        .filter(|(m, _)| bad(m.degree_in_vars(&xyzw)))
        .min_by_key(|(m, _)| (m.degree_in_vars(&xyzw), std::cmp::Reverse(*m)));
    match first {
        None => Ok(()),
        Some((m, c)) => Err(Error::Degree {
            message: format!(
                "term '{}' has degree {}{why}",
                MPoly::term(*m, c.clone()).to_string_with(&VARIABLE_NAMES),
                m.degree_in_vars(&xyzw)
            ),
        }),
    }
}

/// What a nonzero polynomial of degree at most 2 in x, y, z, w (its coefficients may hold
/// other variables) is as a form in them: [`form_in_xyzw`].
#[derive(Debug)]
pub(crate) enum XyzwForm<'a> {
    /// A quadratic form: the polynomial itself if it uses `w` (homogeneous of degree 2),
    /// else its homogenization with `w` (degree 2 or 0: a constant is `c·w²`).
    Quadric(Cow<'a, MPoly>),
    /// A plane: a linear form `ℓ` (the polynomial itself if it uses `w`, else its
    /// homogenization with `w` to degree 1); the quadric is `ℓ²`.
    Plane(MPoly),
}

/// The form in x, y, z, w of a nonzero polynomial (see [`XyzwForm`]).
///
/// # Errors
/// [`Error::Degree`] naming a term of degree above 2, or, if `w` occurs, of a degree other
/// than the polynomial's.
pub(crate) fn form_in_xyzw(poly: &MPoly) -> Result<XyzwForm<'_>, Error> {
    let w = Variable::W.index();
    let xyzw = [0, 1, 2, 3];
    first_bad_term(
        poly,
        |d| d > 2,
        " in x, y, z, w; a quadric has degree at most 2",
    )?;
    let degree = poly
        .terms()
        .iter()
        .map(|(m, _)| m.degree_in_vars(&xyzw))
        .max()
        .unwrap_or(0);
    if poly.uses(w) {
        first_bad_term(
            poly,
            |d| d != degree,
            "; a form in x,y,z,w must be homogeneous, of degree 2 (a quadric) or 1 (a plane) \
             (leave out w to write an affine equation in x, y, z)",
        )?;
        return Ok(match degree {
            1 => XyzwForm::Plane(poly.clone()),
            _ => XyzwForm::Quadric(Cow::Borrowed(poly)),
        });
    }
    // Every term has degree at most 2 in x, y, z: homogenization cannot fail.
    let homogenized = |d| poly.homogenize(&[0, 1, 2], w, d).unwrap_or_default();
    Ok(match degree {
        1 => XyzwForm::Plane(homogenized(1)),
        _ => XyzwForm::Quadric(Cow::Owned(homogenized(2))),
    })
}

/// `ℓ²` for a plane's linear form `ℓ`, within the coefficient bound of the readers (so that
/// the quadric prints as a polynomial that reads back).
///
/// # Errors
/// [`Error::Limit`] for a coefficient above [`MAX_COEFFICIENT_BITS`].
pub(crate) fn square_of_plane(l: &MPoly) -> Result<MPoly, Error> {
    let square = l * l;
    let bits = square.max_bits();
    if bits > MAX_COEFFICIENT_BITS {
        return Err(Error::Limit {
            what: format!("a coefficient of {bits} bits in the square of a plane"),
            limit: MAX_COEFFICIENT_BITS,
        });
    }
    Ok(square)
}

/// The quadric of a polynomial in x, y, z, w of degree at most 2 (as read), and whether it
/// was a plane: [`form_in_xyzw`], then the matrix of the quadratic form.
fn quadric_from_poly(poly: &MPoly) -> Result<(Quadric, bool), Error> {
    if poly.is_zero() {
        return Err(Error::ZeroQuadric);
    }
    let (form, plane) = match form_in_xyzw(poly)? {
        XyzwForm::Quadric(form) => (form, false),
        XyzwForm::Plane(l) => (Cow::Owned(square_of_plane(&l)?), true),
    };
    // A form in x, y, z, w of degree 2: each term is vᵢ·vⱼ, i ≤ j, for A[i][j] (and A[j][i]).
    let mut m: [[RBig; 4]; 4] = Default::default();
    for (monomial, c) in form.terms() {
        let e = monomial.exponents();
        let mut vars = (0..4).flat_map(|v| std::iter::repeat_n(v, usize::from(e[v])));
        if let (Some(i), Some(j)) = (vars.next(), vars.next()) {
            if i == j {
                m[i][i] = c.clone();
            } else {
                let half = half(c);
                m[i][j] = half.clone();
                m[j][i] = half;
            }
        }
    }
    Ok((Quadric::from_matrix(m)?, plane))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::number::excerpt;
    use crate::limits::MAX_NESTING_DEPTH;
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
    fn planes_are_read_from_degree_one_polynomials_only() {
        let plane = |t: &str| parse_plane(t).unwrap().map(|p| p.map(|c| c.to_string()));
        let s = |v: [&str; 4]| Some(v.map(str::to_owned));
        assert_eq!(plane("2x - 3y + z + 5"), s(["2", "-3", "1", "5"]));
        assert_eq!(plane("x/2 + w"), s(["1/2", "0", "0", "1"]));
        assert_eq!(plane("(x+1)^2 - x^2"), s(["2", "0", "0", "1"]));
        for not_a_plane in ["3", "x^2 - 1", "x*w", "x - x"] {
            assert_eq!(plane(not_a_plane), None, "{not_a_plane}");
        }
        assert!(parse_plane("x +").is_err());
        assert!(parse_plane("x + w + 1").is_err());
        // the double plane's zero set is the plane: P² = (z − 1)²
        let p = parse_plane("z - 1").unwrap().unwrap();
        assert_eq!(plane_as_quadric(&p).unwrap(), parse("(z-1)^2"));
    }

    /// A polynomial of degree 1 is its double plane `ℓ²` on both routes, affine or a linear
    /// form using `w`; the plane pair `ℓ·w` must be written as such.
    #[test]
    fn planes_read_as_their_double_planes() {
        let table = [
            ("z - 1", "(z - 1)^2", true),
            ("z - w", "(z - 1)^2", true),
            ("2x - 3y + z + 5", "(2x - 3y + z + 5)^2", true),
            ("x/2 + w", "(x/2 + 1)^2", true),
            ("(x+1)^2 - x^2", "(2x + 1)^2", true),
            ("x", "x^2", true),
            ("(z - 1)^2", "z^2 - 2z + 1", false),
            ("(z - w)*w", "z*w - w^2", false),
            ("3", "3w^2", false),
        ];
        for (text, square, plane) in table {
            let want = parse(square);
            assert_eq!(
                parse_quadric_or_plane(text),
                Ok((want.clone(), plane)),
                "{text}"
            );
            assert_eq!(parse_quadric_big_route(text), Ok(want), "{text}");
        }
        for mixed in ["x + w + 1", "x^2 + w", "x*w + 1"] {
            assert!(
                matches!(parse_quadric(mixed), Err(Error::Degree { .. })),
                "{mixed}"
            );
        }
        // The square keeps the readers' coefficient bound (`(1e9999)^4` has 132 875 bits).
        assert!(matches!(
            parse_quadric("(1e9999)^4*x + 1"),
            Err(Error::Limit { .. })
        ));
        assert!(parse_quadric("(1e9999)^3*x + 1").is_ok());
    }

    #[test]
    fn homogenized_positions_follow_the_monomials() {
        assert_eq!(HOMOGENIZED[0], (3, 3));
        assert_eq!(HOMOGENIZED[1], (0, 3));
        assert_eq!(HOMOGENIZED[5], (0, 0));
        assert_eq!(HOMOGENIZED[6], (0, 1));
        assert_eq!(HOMOGENIZED[13], (2, 3));
        let degree = |k: usize| MONOMIALS[k].iter().sum::<u8>();
        assert!((0..N).all(|k| (degree(k) == 2) == (k >= FIRST_QUADRATIC)));
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
            "1/3 x^2 - 2.5e1",
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
            "1/3 x - 2.5e1",
            "z - w",
            "x^2 - x^2 + y",
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
                    column,
                    allowed: "x, y, z, w".into()
                }),
                "input {text:?}"
            );
        }
    }

    #[test]
    fn degree_errors_name_the_term() {
        let table = [
            ("x^3", "term 'x^3' at column 1 has degree 3"),
            ("y + x^17", "term 'x^17' at column 5 has degree 17"),
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
            ("x + w + 1", "term '1' has degree 0; a form in x,y,z,w"),
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
            "x^65".into(),
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
