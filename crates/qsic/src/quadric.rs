//! A real projective quadric `XᵀAX = 0`, `X = (x, y, z, w)`, with rational coefficients.
//!
//! A [`Quadric`] is stored as `s·P`: `P` its primitive integer matrix (entries with gcd 1)
//! and `s` a positive rational. Both are unique, so they identify the quadric's matrix.
//! Built from machine numbers (integers, `f64`, number texts of a few digits, see
//! [`crate::io`]), `P` and `s` are computed in `i128` with checked operations and no big
//! number; any overflow falls back to big rationals. The rational matrix is derived on first
//! use, or kept when the caller gave it.

use crate::error::Error;
use crate::limits::{MAX_DECIMAL_EXPONENT, MAX_NUMBER_DIGITS};
use dashu_int::{IBig, UBig};
use dashu_ratio::RBig;
use qsic_algebra::matrix::SymMatrix4;
use std::fmt;
use std::hash::{Hash, Hasher};
use std::sync::OnceLock;

/// A quadric surface in real projective space, given by its symmetric 4×4 matrix
/// with exact rational entries, in the variable order `(x, y, z, w)`.
///
/// Invariant: symmetric and not zero (checked by every constructor). Two quadrics are
/// equal when their matrices are (not merely proportional).
#[derive(Clone)]
pub struct Quadric {
    /// The primitive integer matrix `P` in machine integers, whenever its entries fit an
    /// `i64` (`None` only when some does not).
    machine: Option<[[i64; 4]; 4]>,
    /// `machine` holds and all its entries are below 2²⁴ in absolute value (the fast
    /// path's range).
    small: bool,
    /// `P` in big integers: set by the constructor when `machine` is `None`, else derived
    /// on first use.
    int: OnceLock<Box<SymMatrix4>>,
    /// The positive rational `s` with matrix `= s·P`.
    scale: Scale,
    /// The rational matrix: kept from [`Quadric::from_matrix`], else derived on first use.
    rational: OnceLock<Box<[[RBig; 4]; 4]>>,
}

/// A positive rational in lowest terms; `Machine` whenever both parts fit a `u128`, so
/// that equal values have equal representations.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
enum Scale {
    Machine { num: u128, den: u128 },
    Big(RBig),
}

impl Scale {
    /// `num/den` for nonzero `num`, `den`, reduced.
    fn machine(num: u128, den: u128) -> Scale {
        if let (Ok(n), Ok(d)) = (u64::try_from(num), u64::try_from(den)) {
            let g = gcd_u64(n, d);
            return Scale::Machine {
                num: u128::from(n / g),
                den: u128::from(d / g),
            };
        }
        let g = gcd_u128(num, den);
        Scale::Machine {
            num: num / g,
            den: den / g,
        }
    }

    /// The positive rational `r`, in canonical form.
    fn from_rbig(r: RBig) -> Scale {
        match (
            u128::try_from(r.numerator()),
            u128::try_from(r.denominator()),
        ) {
            (Ok(num), Ok(den)) => Scale::Machine { num, den },
            _ => Scale::Big(r),
        }
    }
}

/// A rational `num/den` read without big numbers: `den > 0`, not necessarily in lowest
/// terms. The machine-arithmetic input of [`Quadric::from_small_rationals`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct SmallRational {
    pub(crate) num: i64,
    pub(crate) den: u64,
}

impl SmallRational {
    pub(crate) const ZERO: SmallRational = SmallRational { num: 0, den: 1 };

    /// The same value as a big rational.
    pub(crate) fn to_rbig(self) -> RBig {
        RBig::from_parts(IBig::from(self.num), UBig::from(self.den))
    }
}

impl Quadric {
    /// Builds a quadric from a symmetric rational matrix.
    ///
    /// # Errors
    /// [`Error::NotSymmetric`] naming the first asymmetric pair, [`Error::ZeroQuadric`] if all entries are zero.
    pub fn from_matrix(m: [[RBig; 4]; 4]) -> Result<Self, Error> {
        check_rational(&m)?;
        let mut small = [[SmallRational::ZERO; 4]; 4];
        let mut fits = true;
        'rows: for i in 0..4 {
            for j in i..4 {
                let v = &m[i][j];
                match (i64::try_from(v.numerator()), u64::try_from(v.denominator())) {
                    (Ok(num), Ok(den)) => small[i][j] = SmallRational { num, den },
                    _ => {
                        fits = false;
                        break 'rows;
                    }
                }
            }
        }
        let built = if fits { primitive_small(&small) } else { None };
        let q = match built {
            Some(q) => q,
            None => return Ok(Self::primitive_big(m)),
        };
        // The cell is new and empty, so this cannot fail; the matrix is then kept.
        let _ = q.rational.set(Box::new(m));
        Ok(q)
    }

    /// [`Quadric::from_matrix`] through big integers only: the general route, which the
    /// machine-arithmetic routes must equal (differential tests).
    ///
    /// # Errors
    /// As [`Quadric::from_matrix`].
    pub(crate) fn from_matrix_big_route(m: [[RBig; 4]; 4]) -> Result<Self, Error> {
        check_rational(&m)?;
        Ok(Self::primitive_big(m))
    }

    /// The primitive integer matrix and scale of a valid (symmetric, nonzero) rational
    /// matrix, by big-integer arithmetic.
    fn primitive_big(m: [[RBig; 4]; 4]) -> Quadric {
        let int = SymMatrix4::from_rationals_primitive(&m);
        let mut scale = Scale::Machine { num: 1, den: 1 };
        if let Some((v, p)) = m
            .iter()
            .flatten()
            .zip(int.entries().iter().flatten())
            .find(|(_, p)| !p.is_zero())
        {
            scale = Scale::from_rbig(v / RBig::from(p.clone()));
        }
        let machine = machine_entries(&int);
        let q = Quadric {
            small: machine.as_ref().is_some_and(all_small),
            machine,
            int: OnceLock::from(Box::new(int)),
            scale,
            rational: OnceLock::new(),
        };
        let _ = q.rational.set(Box::new(m));
        q
    }

    /// Builds a quadric from rationals read without big numbers (see [`crate::io`]).
    ///
    /// # Errors
    /// As [`Quadric::from_matrix`].
    pub(crate) fn from_small_rationals(m: &[[SmallRational; 4]; 4]) -> Result<Self, Error> {
        for i in 0..4 {
            for j in (i + 1)..4 {
                let (a, b) = (m[i][j], m[j][i]);
                if a != b
                    && i128::from(a.num) * i128::from(b.den)
                        != i128::from(b.num) * i128::from(a.den)
                {
                    return Err(Error::NotSymmetric {
                        row: i,
                        col: j,
                        a: a.to_rbig().to_string(),
                        b: b.to_rbig().to_string(),
                    });
                }
            }
        }
        if m.iter().flatten().all(|v| v.num == 0) {
            return Err(Error::ZeroQuadric);
        }
        match primitive_small(m) {
            Some(q) => Ok(q),
            None => Ok(Self::primitive_big(
                m.map(|row| row.map(SmallRational::to_rbig)),
            )),
        }
    }

    /// Builds a quadric from integer entries, in machine arithmetic.
    ///
    /// # Errors
    /// As [`Quadric::from_matrix`].
    ///
    /// # Examples
    /// ```
    /// use qsic::Quadric;
    /// let q = Quadric::from_integers([[2, 0, 0, 0], [0, 4, 0, 0], [0, 0, 0, 0], [0, 0, 0, -2]])?;
    /// assert_eq!(q.small_integer_matrix(), Some(&[[1, 0, 0, 0], [0, 2, 0, 0], [0; 4], [0, 0, 0, -1]]));
    /// assert_eq!(q.entry(1, 1), &4.into());
    /// assert!(Quadric::from_integers([[0, 1, 0, 0], [0; 4], [0; 4], [0; 4]]).is_err());
    /// # Ok::<(), qsic::Error>(())
    /// ```
    pub fn from_integers(m: [[i64; 4]; 4]) -> Result<Self, Error> {
        for i in 0..4 {
            for j in (i + 1)..4 {
                if m[i][j] != m[j][i] {
                    return Err(Error::NotSymmetric {
                        row: i,
                        col: j,
                        a: m[i][j].to_string(),
                        b: m[j][i].to_string(),
                    });
                }
            }
        }
        let mut scaled = [[0i128; 4]; 4];
        let mut zero = true;
        for i in 0..4 {
            for j in i..4 {
                scaled[i][j] = i128::from(m[i][j]);
                zero &= m[i][j] == 0;
            }
        }
        if zero {
            return Err(Error::ZeroQuadric);
        }
        Ok(finish_machine(&scaled, 1))
    }

    /// Builds a quadric from `f64` entries, each converted *exactly* (0.1 becomes
    /// 3602879701896397/36028797018963968, the value the float really holds).
    ///
    /// Floats are binary fractions, so their common denominator is a power of two: when
    /// the exponents of the entries are within about 60 binades of each other, everything is
    /// computed in machine integers.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for NaN or ±∞, then as [`Quadric::from_matrix`].
    pub fn from_f64(m: [[f64; 4]; 4]) -> Result<Self, Error> {
        let exact = |i: usize, j: usize| {
            RBig::try_from(m[i][j]).map_err(|_| Error::NotFinite { row: i, col: j })
        };
        for (i, row) in m.iter().enumerate() {
            for (j, v) in row.iter().enumerate() {
                if !v.is_finite() {
                    return Err(Error::NotFinite { row: i, col: j });
                }
            }
        }
        // Finite floats are equal exactly when their values are (0.0 and −0.0 both zero).
        for i in 0..4 {
            for j in (i + 1)..4 {
                if m[i][j] != m[j][i] {
                    return Err(Error::NotSymmetric {
                        row: i,
                        col: j,
                        a: exact(i, j)?.to_string(),
                        b: exact(j, i)?.to_string(),
                    });
                }
            }
        }
        if m.iter().flatten().all(|&v| v == 0.0) {
            return Err(Error::ZeroQuadric);
        }
        let mut small = [[SmallRational::ZERO; 4]; 4];
        let mut fits = true;
        for i in 0..4 {
            for j in i..4 {
                match small_from_f64(m[i][j]) {
                    Some(r) => small[i][j] = r,
                    None => fits = false,
                }
            }
        }
        if let Some(q) = fits.then(|| primitive_small(&small)).flatten() {
            return Ok(q);
        }
        let mut out: [[RBig; 4]; 4] = Default::default();
        for (i, row) in out.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                *v = exact(i, j)?;
            }
        }
        Ok(Self::primitive_big(out))
    }

    /// The symmetric matrix (derived from the primitive matrix on first use, unless the
    /// quadric was built from it).
    pub fn matrix(&self) -> &[[RBig; 4]; 4] {
        self.rational.get_or_init(|| {
            let p = self.integer_matrix().entries();
            let (num, den) = match &self.scale {
                Scale::Machine { num, den } => (IBig::from(*num), UBig::from(*den)),
                Scale::Big(r) => (r.numerator().clone(), r.denominator().clone()),
            };
            let mut m: [[RBig; 4]; 4] = Default::default();
            for i in 0..4 {
                for j in i..4 {
                    m[i][j] = RBig::from_parts(&num * &p[i][j], den.clone());
                    m[j][i] = m[i][j].clone();
                }
            }
            Box::new(m)
        })
    }

    /// The entry at (i, j), 0-based.
    ///
    /// # Panics
    /// If `i` or `j` is not below 4.
    pub fn entry(&self, i: usize, j: usize) -> &RBig {
        &self.matrix()[i][j]
    }

    /// The matrix scaled by a positive rational to a primitive integer matrix
    /// (gcd of entries 1). A positive scale keeps the quadric and its inertia.
    pub fn integer_matrix(&self) -> &SymMatrix4 {
        self.int.get_or_init(|| {
            let mut wide = [[0i128; 4]; 4];
            if let Some(p) = &self.machine {
                for (dst, src) in wide.iter_mut().zip(p) {
                    *dst = src.map(i128::from);
                }
            }
            Box::new(SymMatrix4::from_upper_i128(&wide))
        })
    }

    /// [`Quadric::integer_matrix`] in machine integers, when all its entries are below 2²⁴
    /// in absolute value.
    pub fn small_integer_matrix(&self) -> Option<&[[i64; 4]; 4]> {
        self.machine.as_ref().filter(|_| self.small)
    }

    /// The quadratic form as a polynomial string in x, y, z, w, e.g. `x^2 + 2*x*y - w^2`,
    /// which [`crate::io::parse_quadric`] reads back as the same quadric. A coefficient too
    /// long for one numeral ([`crate::limits::MAX_NUMBER_DIGITS`]) is written as a
    /// product or quotient of numerals, such as `391e9999*w^2`.
    pub fn to_polynomial_string(&self) -> String {
        const V: [&str; 4] = ["x", "y", "z", "w"];
        let m = self.matrix();
        let mut s = String::new();
        for i in 0..4 {
            for j in i..4 {
                let c = if i == j {
                    m[i][j].clone()
                } else {
                    &m[i][j] * RBig::from(2)
                };
                if c.is_zero() {
                    continue;
                }
                let mono = if i == j {
                    format!("{}^2", V[i])
                } else {
                    format!("{}*{}", V[i], V[j])
                };
                let neg = c < RBig::ZERO;
                let abs = if neg { -c } else { c };
                if s.is_empty() {
                    if neg {
                        s.push('-');
                    }
                } else {
                    s.push_str(if neg { " - " } else { " + " });
                }
                if !abs.is_one() {
                    push_number(&mut s, &abs);
                    s.push('*');
                }
                s.push_str(&mono);
            }
        }
        s
    }
}

/// `Quadric` from an integer matrix, for tests and examples.
impl TryFrom<[[i64; 4]; 4]> for Quadric {
    type Error = Error;
    fn try_from(m: [[i64; 4]; 4]) -> Result<Self, Error> {
        Self::from_integers(m)
    }
}

impl PartialEq for Quadric {
    fn eq(&self, other: &Self) -> bool {
        // `P` and `s` are unique and their representations canonical.
        self.scale == other.scale
            && match (&self.machine, &other.machine) {
                (Some(a), Some(b)) => a == b,
                (None, None) => self.integer_matrix() == other.integer_matrix(),
                _ => false,
            }
    }
}

impl Eq for Quadric {}

impl Hash for Quadric {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.scale.hash(state);
        match &self.machine {
            Some(p) => p.hash(state),
            None => self.integer_matrix().hash(state),
        }
    }
}

impl fmt::Debug for Quadric {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let rows = self
            .matrix()
            .each_ref()
            .map(|row| row.each_ref().map(|v| v.to_string()));
        f.debug_struct("Quadric").field("matrix", &rows).finish()
    }
}

/// Checks a rational matrix: symmetric and not zero.
fn check_rational(m: &[[RBig; 4]; 4]) -> Result<(), Error> {
    for (i, row) in m.iter().enumerate() {
        for (j, v) in row.iter().enumerate().skip(i + 1) {
            if *v != m[j][i] {
                return Err(Error::NotSymmetric {
                    row: i,
                    col: j,
                    a: v.to_string(),
                    b: m[j][i].to_string(),
                });
            }
        }
    }
    if m.iter().flatten().all(|v| v.is_zero()) {
        return Err(Error::ZeroQuadric);
    }
    Ok(())
}

/// The quadric `s·P` of a symmetric nonzero matrix of small rationals (upper triangle
/// read), in machine arithmetic; `None` if an intermediate value overflows `i128`.
///
/// `L` is the lcm of the denominators of the nonzero entries, `L·m` an integer matrix, `g`
/// the gcd of its entries: `P = L·m / g`, `s = g / L`.
fn primitive_small(m: &[[SmallRational; 4]; 4]) -> Option<Quadric> {
    let mut lcm: u64 = 1;
    for i in 0..4 {
        for v in &m[i][i..] {
            if v.num != 0 && v.den != 1 && v.den != lcm && lcm % v.den != 0 {
                lcm = (lcm / gcd_u64(lcm, v.den)).checked_mul(v.den)?;
            }
        }
    }
    if lcm <= 1 << 31 {
        // The usual small inputs: every num · (lcm / den) in i64 (checked products).
        let mut scaled = [[0i64; 4]; 4];
        let mut fits = true;
        for i in 0..4 {
            for j in i..4 {
                let v = m[i][j];
                // k ≤ lcm ≤ 2³¹ fits an i64; it is exact where num ≠ 0 (den divides
                // lcm), and any value where num = 0.
                let k = if v.den == 1 { lcm } else { lcm / v.den };
                match v.num.checked_mul(k as i64) {
                    Some(x) => scaled[i][j] = x,
                    None => fits = false,
                }
            }
        }
        if fits {
            return Some(finish_machine_i64(&scaled, lcm));
        }
    }
    let mut scaled = [[0i128; 4]; 4];
    for i in 0..4 {
        for j in i..4 {
            let v = m[i][j];
            // den divides lcm, so the quotient is exact; |num| ≤ 2⁶³ and the quotient
            // is below 2⁶⁴, so the product fits an i128.
            let k = match v.den {
                1 => lcm,
                d if d == lcm => 1,
                d => lcm / d,
            };
            scaled[i][j] = i128::from(v.num) * i128::from(k);
        }
    }
    Some(finish_machine(&scaled, u128::from(lcm)))
}

/// The quadric `(1/lcm)·scaled` from the upper triangle of a nonzero integer matrix
/// `scaled` (entries in `i128`).
fn finish_machine(scaled: &[[i128; 4]; 4], lcm: u128) -> Quadric {
    let mut narrow = [[0i64; 4]; 4];
    let mut fits = u64::try_from(lcm).is_ok();
    for i in 0..4 {
        for j in i..4 {
            match i64::try_from(scaled[i][j]) {
                Ok(v) => narrow[i][j] = v,
                Err(_) => fits = false,
            }
        }
    }
    match u64::try_from(lcm) {
        Ok(lcm) if fits => finish_machine_i64(&narrow, lcm),
        _ => finish_machine_i128(scaled, lcm),
    }
}

/// [`finish_machine`] when the entries fit an `i64` and `lcm` a `u64`.
fn finish_machine_i64(scaled: &[[i64; 4]; 4], lcm: u64) -> Quadric {
    let mut g: u64 = 0;
    for i in 0..4 {
        for v in &scaled[i][i..] {
            if g != 1 && *v != 0 {
                g = if g == 0 {
                    v.unsigned_abs()
                } else {
                    gcd_u64(g, v.unsigned_abs())
                };
            }
        }
    }
    // g ≥ 1 since the matrix is nonzero.
    let g = g.max(1);
    let mut machine = [[0i64; 4]; 4];
    let mut small = true;
    for i in 0..4 {
        for j in i..4 {
            let v = scaled[i][j];
            // g divides v, so |v / g| ≤ |v|; g = 2⁶³ (not an i64) only when every nonzero
            // entry is −2⁶³, whose quotient is −1.
            let q = match i64::try_from(g) {
                Ok(1) => v,
                Ok(g) => v / g,
                Err(_) => -i64::from(v != 0),
            };
            machine[i][j] = q;
            machine[j][i] = q;
            small &= q.unsigned_abs() < SMALL_LIMIT;
        }
    }
    Quadric {
        machine: Some(machine),
        small,
        int: OnceLock::new(),
        scale: Scale::machine(u128::from(g), u128::from(lcm)),
        rational: OnceLock::new(),
    }
}

/// [`finish_machine`] in `i128`.
fn finish_machine_i128(scaled: &[[i128; 4]; 4], lcm: u128) -> Quadric {
    let mut g: u128 = 0;
    for i in 0..4 {
        for v in &scaled[i][i..] {
            if g != 1 && *v != 0 {
                g = gcd_u128(g, v.unsigned_abs());
            }
        }
    }
    // g ≥ 1 since the matrix is nonzero; |v / g| ≤ |v|, so the quotients fit.
    let g = g.max(1);
    let mut p = *scaled;
    if g != 1 {
        // A gcd above 1 divides every entry, so it fits in i128 unless it is 2¹²⁷, which
        // only the entries ±2¹²⁷ … reach: i128::MIN is the one such value.
        match i128::try_from(g) {
            Ok(gi) => {
                for i in 0..4 {
                    for v in &mut p[i][i..] {
                        *v /= gi;
                    }
                }
            }
            Err(_) => {
                for i in 0..4 {
                    for v in &mut p[i][i..] {
                        *v = if *v == 0 { 0 } else { -1 };
                    }
                }
            }
        }
    }
    let mut machine = [[0i64; 4]; 4];
    let mut fits = true;
    let mut small = true;
    for i in 0..4 {
        for j in i..4 {
            match i64::try_from(p[i][j]) {
                Ok(v) => {
                    machine[i][j] = v;
                    machine[j][i] = v;
                    small &= v.unsigned_abs() < SMALL_LIMIT;
                }
                Err(_) => fits = false,
            }
        }
    }
    let int = OnceLock::new();
    if !fits {
        let _ = int.set(Box::new(SymMatrix4::from_upper_i128(&p)));
    }
    Quadric {
        machine: fits.then_some(machine),
        small: fits && small,
        int,
        scale: Scale::machine(g, lcm),
        rational: OnceLock::new(),
    }
}

/// Entries below this bound in absolute value (2²⁴) are taken by the fast path.
const SMALL_LIMIT: u64 = 1 << 24;

/// Whether every entry is below [`SMALL_LIMIT`] in absolute value.
fn all_small(m: &[[i64; 4]; 4]) -> bool {
    m.iter().flatten().all(|v| v.unsigned_abs() < SMALL_LIMIT)
}

/// The entries of `m` as `i64`, if they all fit.
fn machine_entries(m: &SymMatrix4) -> Option<[[i64; 4]; 4]> {
    let mut out = [[0i64; 4]; 4];
    for (dst, src) in out.iter_mut().flatten().zip(m.entries().iter().flatten()) {
        *dst = i64::try_from(src).ok()?;
    }
    Some(out)
}

/// The exact value of a finite float as a small rational, if it is one: a float is
/// `mantissa · 2^exponent`, an integer below 2⁶³ or a fraction over 2^k with k ≤ 63.
fn small_from_f64(v: f64) -> Option<SmallRational> {
    if v == 0.0 {
        return Some(SmallRational::ZERO);
    }
    let bits = v.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let fraction = bits & ((1u64 << 52) - 1);
    let (mut mantissa, mut exponent) = if biased == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1u64 << 52), biased - 1075)
    };
    let zeros = mantissa.trailing_zeros();
    mantissa >>= zeros;
    exponent += zeros as i32;
    // mantissa < 2⁵³, so it fits an i64, and so does mantissa · 2^exponent for
    // exponent ≤ 10; the checked product decides up to 62.
    let magnitude = i64::try_from(mantissa).ok()?;
    let (num, den) = match exponent {
        0..=62 => (magnitude.checked_mul(1i64 << exponent)?, 1),
        -63..=-1 => (magnitude, 1u64 << exponent.unsigned_abs()),
        _ => return None,
    };
    Some(SmallRational {
        num: if v < 0.0 { -num } else { num },
        den,
    })
}

/// The gcd of two unsigned integers, `gcd(0, v) = v` (binary algorithm, in `u64` when
/// both fit).
pub(crate) fn gcd_u128(a: u128, b: u128) -> u128 {
    if a == 0 {
        return b;
    }
    if b == 0 {
        return a;
    }
    if let (Ok(a), Ok(b)) = (u64::try_from(a), u64::try_from(b)) {
        return u128::from(gcd_u64(a, b));
    }
    let shift = (a | b).trailing_zeros();
    let (mut a, mut b) = (a >> a.trailing_zeros(), b >> b.trailing_zeros());
    while a != b {
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        b -= a;
        b >>= b.trailing_zeros();
    }
    a << shift
}

/// The gcd of two `u64`, `gcd(0, v) = v` (Euclid: for the small values met here, a few
/// remainders).
fn gcd_u64(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// Writes the positive rational `v` as the polynomial reader reads it: `p/q`, or, when that
/// is longer than one numeral may be, its integers with their trailing zeros as exponents
/// (`391e9999`), split into numerals that respect the digit and exponent limits.
pub(crate) fn push_number(s: &mut String, v: &RBig) {
    let (p, q) = (v.numerator().to_string(), v.denominator().to_string());
    if p.len() + q.len() <= MAX_NUMBER_DIGITS {
        s.push_str(&v.to_string());
        return;
    }
    s.push('(');
    push_integer(s, &p);
    s.push(')');
    if q != "1" {
        s.push_str("/(");
        push_integer(s, &q);
        s.push(')');
    }
}

/// Writes the decimal integer `digits` (no sign, no leading zeros) as a constant expression:
/// its trailing zeros as powers `1e…`, the rest in Horner form over chunks of at most
/// [`MAX_NUMBER_DIGITS`] − 1 digits, `(c₁*1e9999+c₀)`.
fn push_integer(s: &mut String, digits: &str) {
    let significant = digits.trim_end_matches('0');
    let mut zeros = digits.len() - significant.len();
    let chunk = MAX_NUMBER_DIGITS - 1;
    // the leading chunk is the short one, so that the others all have `chunk` digits
    let first = match significant.len() % chunk {
        0 => chunk.min(significant.len()),
        r => r,
    };
    s.push_str(&"(".repeat((significant.len() - first) / chunk));
    s.push_str(&significant[..first]);
    for start in (first..significant.len()).step_by(chunk) {
        s.push_str(&format!(
            "*1e{chunk}+{})",
            &significant[start..start + chunk]
        ));
    }
    while zeros > 0 {
        let e = zeros.min(MAX_DECIMAL_EXPONENT);
        s.push_str(&format!("*1e{e}"));
        zeros -= e;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Asserts that `q` is the quadric the big-integer route builds from `m`, in every
    /// view: equality, primitive matrix, fast-path matrix, rational matrix.
    fn assert_same_as_big_route(q: &Quadric, m: [[RBig; 4]; 4]) {
        let big = Quadric::from_matrix_big_route(m.clone()).expect("a valid matrix");
        assert_eq!(q, &big);
        assert_eq!(q.integer_matrix(), big.integer_matrix());
        assert_eq!(q.small_integer_matrix(), big.small_integer_matrix());
        assert_eq!(q.matrix(), &m);
        assert_eq!(big.matrix(), &m);
        let hash = |q: &Quadric| {
            use std::collections::hash_map::DefaultHasher;
            let mut h = DefaultHasher::new();
            q.hash(&mut h);
            h.finish()
        };
        assert_eq!(hash(q), hash(&big));
    }

    fn symmetric<T: Copy>(upper: [T; 10]) -> [[T; 4]; 4] {
        let mut m = [[upper[0]; 4]; 4];
        let mut k = 0;
        for i in 0..4 {
            for j in i..4 {
                m[i][j] = upper[k];
                m[j][i] = upper[k];
                k += 1;
            }
        }
        m
    }

    #[test]
    fn integer_extremes_match_the_big_route() {
        let table: [[i64; 10]; 5] = [
            [i64::MIN, 0, 0, 0, 0, 0, 0, 0, 0, 0],
            [i64::MIN, i64::MIN, 0, 0, 0, 0, 0, 0, 0, i64::MIN],
            [i64::MIN, i64::MAX, 1, 0, 0, 0, 0, 0, 0, 0],
            [6, 10, 14, 0, 0, 0, 0, 0, 0, -2],
            [0, 0, 0, 0, 0, 0, 0, 0, 0, -(1 << 24)],
        ];
        for upper in table {
            let m = symmetric(upper);
            let q = Quadric::from_integers(m).expect("valid");
            assert_same_as_big_route(&q, m.map(|r| r.map(RBig::from)));
        }
        let q =
            Quadric::from_integers(symmetric([6, 10, 14, 0, 0, 0, 0, 0, 0, -2])).expect("valid");
        assert_eq!(q.small_integer_matrix().map(|m| m[0][1]), Some(5));
        let limit =
            Quadric::from_integers(symmetric([1 << 24, 0, 0, 0, 0, 0, 0, 0, 0, 1])).expect("valid");
        assert_eq!(limit.small_integer_matrix(), None);
    }

    #[test]
    fn validation_errors() {
        let mut m = [[0i64; 4]; 4];
        assert_eq!(Quadric::from_integers(m), Err(Error::ZeroQuadric));
        m[1][2] = 3;
        m[2][1] = 4;
        assert_eq!(
            Quadric::from_integers(m),
            Err(Error::NotSymmetric {
                row: 1,
                col: 2,
                a: "3".into(),
                b: "4".into()
            })
        );
        let mut f = [[0.0; 4]; 4];
        f[2][3] = f64::INFINITY;
        assert_eq!(
            Quadric::from_f64(f),
            Err(Error::NotFinite { row: 2, col: 3 })
        );
        f[2][3] = 0.5;
        f[3][2] = 0.25;
        assert!(matches!(
            Quadric::from_f64(f),
            Err(Error::NotSymmetric { row: 2, col: 3, a, b }) if a == "1/2" && b == "1/4"
        ));
    }

    #[test]
    fn float_extremes_match_the_big_route() {
        let table: [[f64; 10]; 5] = [
            [0.1, 0.2, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0],
            [f64::MAX, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            [
                f64::MIN_POSITIVE,
                5e-324,
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
                -3.0,
            ],
            [
                9.007_199_254_740_993e15,
                1e18,
                1e-19,
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
            ],
            [
                -0.0,
                2.0f64.powi(62),
                2.0f64.powi(-63),
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
                1.0,
            ],
        ];
        for upper in table {
            let m = symmetric(upper);
            let q = Quadric::from_f64(m).expect("valid");
            let exact = m.map(|r| r.map(|v| RBig::try_from(v).expect("finite")));
            assert_same_as_big_route(&q, exact);
        }
    }

    proptest! {
        #[test]
        fn integers_match_the_big_route(
            upper in prop::array::uniform10(prop_oneof![
                -20i64..20,
                any::<i64>(),
                (0u32..63, -3i64..4).prop_map(|(k, c)| c << k),
            ]),
        ) {
            let m = symmetric(upper);
            prop_assume!(upper.iter().any(|&v| v != 0));
            let q = Quadric::from_integers(m).expect("valid");
            assert_same_as_big_route(&q, m.map(|r| r.map(RBig::from)));
        }

        #[test]
        fn floats_match_the_big_route(
            upper in prop::array::uniform10(prop_oneof![
                (-40i32..40).prop_map(|k| f64::from(k) / 8.0),
                any::<f64>().prop_filter("finite", |v| v.is_finite()),
                (-70i32..70, -3i32..4).prop_map(|(k, c)| f64::from(c) * 2f64.powi(k)),
            ]),
        ) {
            prop_assume!(upper.iter().any(|&v| v != 0.0));
            let m = symmetric(upper);
            let q = Quadric::from_f64(m).expect("valid");
            let exact = m.map(|r| r.map(|v| RBig::try_from(v).expect("finite")));
            assert_same_as_big_route(&q, exact);
        }

        #[test]
        fn rationals_match_the_big_route(
            upper in prop::array::uniform10((any::<i64>(), 1u64..), ),
            small in prop::array::uniform10((-9i64..10, 1u64..13)),
            mix in any::<u16>(),
        ) {
            let pick: [(i64, u64); 10] =
                std::array::from_fn(|k| if mix >> k & 1 == 1 { upper[k] } else { small[k] });
            prop_assume!(pick.iter().any(|&(n, _)| n != 0));
            let m = symmetric(pick).map(|r| r.map(|(n, d)| RBig::from_parts(n.into(), d.into())));
            let q = Quadric::from_matrix(m.clone()).expect("valid");
            assert_same_as_big_route(&q, m.clone());
            let s = symmetric(pick).map(|r| r.map(|(num, den)| SmallRational { num, den }));
            let q = Quadric::from_small_rationals(&s).expect("valid");
            assert_same_as_big_route(&q, m);
        }
    }
}

#[cfg(test)]
mod round_trip_tests {
    use super::*;
    use crate::io::parse_quadric;
    use dashu_int::ops::UnsignedAbs;
    use dashu_int::IBig;

    /// An entry −2⁶³ (the `i64` whose `abs` overflows; found by fuzzing) is not small.
    #[test]
    fn most_negative_i64_entry_is_not_small() {
        let mut m = [[0i64; 4]; 4];
        (m[0][0], m[1][1]) = (i64::MIN, 1);
        let q = Quadric::from_integers(m).expect("nonzero");
        assert_eq!(q.small_integer_matrix(), None);
        m[0][0] = -(1 << 24) + 1;
        let q = Quadric::from_integers(m).expect("nonzero");
        assert_eq!(q.small_integer_matrix(), Some(&m));
    }

    /// Coefficients longer than one numeral may be (fuzzing found `391e9999`): round numbers,
    /// long fractions, and numbers of ~31 000 significant digits, read back exactly.
    #[test]
    fn long_coefficients_round_trip() {
        let three = IBig::from(3).pow(65536);
        let ten = |e: usize| IBig::from(10).pow(e);
        let long = [
            RBig::from(IBig::from(391) * ten(9999)),
            RBig::from_parts(IBig::from(3), (ten(9999) * IBig::from(7)).unsigned_abs()),
            RBig::from(three.clone()),
            RBig::from_parts(IBig::from(-7), three.clone().unsigned_abs()),
            RBig::from(ten(30001)),
            RBig::from_parts(
                three.clone() * ten(12345),
                (three + IBig::ONE).unsigned_abs(),
            ),
        ];
        for v in long {
            let mut m: [[RBig; 4]; 4] = Default::default();
            m[0][0] = v.clone();
            m[1][2] = RBig::ONE;
            m[2][1] = RBig::ONE;
            let q = Quadric::from_matrix(m).expect("nonzero");
            let text = q.to_polynomial_string();
            let again = parse_quadric(&text).map_err(|e| e.to_string());
            assert_eq!(again.as_ref(), Ok(&q), "{}…", &text[..80.min(text.len())]);
        }
    }
}
