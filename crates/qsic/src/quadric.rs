//! A real projective quadric `XᵀAX = 0`, `X = (x, y, z, w)`, with rational coefficients.

use crate::error::Error;
use crate::limits::{MAX_DECIMAL_EXPONENT, MAX_NUMBER_DIGITS};
use dashu_ratio::RBig;
use qsic_algebra::matrix::SymMatrix4;

/// A quadric surface in real projective space, stored as its symmetric 4×4 matrix
/// with exact rational entries, in the variable order `(x, y, z, w)`.
///
/// Invariant: symmetric and not zero (checked by every constructor).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Quadric {
    m: [[RBig; 4]; 4],
    /// The primitive integer multiple of `m`, computed once.
    int: SymMatrix4,
    /// The same in machine integers when every entry is below 2²⁴ in absolute value
    /// (the fast path's range).
    small: Option<[[i64; 4]; 4]>,
}

impl Quadric {
    /// Builds a quadric from a symmetric rational matrix.
    ///
    /// # Errors
    /// [`Error::NotSymmetric`] naming the first asymmetric pair, [`Error::ZeroQuadric`] if all entries are zero.
    pub fn from_matrix(m: [[RBig; 4]; 4]) -> Result<Self, Error> {
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
        let int = SymMatrix4::from_rationals_primitive(&m);
        let small = small_entries(&int);
        Ok(Quadric { m, int, small })
    }

    /// Builds a quadric from integer entries.
    ///
    /// # Errors
    /// As [`Quadric::from_matrix`].
    pub fn from_integers(m: [[i64; 4]; 4]) -> Result<Self, Error> {
        Self::from_matrix(m.map(|row| row.map(RBig::from)))
    }

    /// Builds a quadric from `f64` entries, each converted *exactly* (0.1 becomes
    /// 3602879701896397/36028797018963968, the value the float really holds).
    ///
    /// # Errors
    /// [`Error::NotFinite`] for NaN or ±∞, then as [`Quadric::from_matrix`].
    pub fn from_f64(m: [[f64; 4]; 4]) -> Result<Self, Error> {
        let mut out: [[RBig; 4]; 4] = Default::default();
        for (i, row) in m.iter().enumerate() {
            for (j, &v) in row.iter().enumerate() {
                out[i][j] = RBig::try_from(v).map_err(|_| Error::NotFinite { row: i, col: j })?;
            }
        }
        Self::from_matrix(out)
    }

    /// The symmetric matrix.
    pub fn matrix(&self) -> &[[RBig; 4]; 4] {
        &self.m
    }

    /// The entry at (i, j), 0-based.
    ///
    /// # Panics
    /// If `i` or `j` is not below 4.
    pub fn entry(&self, i: usize, j: usize) -> &RBig {
        &self.m[i][j]
    }

    /// The matrix scaled by a positive rational to a primitive integer matrix
    /// (gcd of entries 1). A positive scale keeps the quadric and its inertia.
    pub fn integer_matrix(&self) -> &SymMatrix4 {
        &self.int
    }

    /// [`Quadric::integer_matrix`] in machine integers, when all its entries are below 2²⁴
    /// in absolute value.
    pub fn small_integer_matrix(&self) -> Option<&[[i64; 4]; 4]> {
        self.small.as_ref()
    }

    /// The quadratic form as a polynomial string in x, y, z, w, e.g. `x^2 + 2*x*y - w^2`,
    /// which [`crate::io::parse_quadric`] reads back as the same quadric. A coefficient too
    /// long for one numeral ([`crate::limits::MAX_NUMBER_DIGITS`]) is written as a
    /// product or quotient of numerals, such as `391e9999*w^2`.
    pub fn to_polynomial_string(&self) -> String {
        const V: [&str; 4] = ["x", "y", "z", "w"];
        let mut s = String::new();
        for i in 0..4 {
            for j in i..4 {
                let c = if i == j {
                    self.m[i][j].clone()
                } else {
                    &self.m[i][j] * RBig::from(2)
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

/// Writes the positive rational `v` as the polynomial reader reads it: `p/q`, or, when that
/// is longer than one numeral may be, its integers with their trailing zeros as exponents
/// (`391e9999`), split into numerals that respect the digit and exponent limits.
fn push_number(s: &mut String, v: &RBig) {
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

/// `Quadric` from an integer matrix, for tests and examples.
impl TryFrom<[[i64; 4]; 4]> for Quadric {
    type Error = Error;
    fn try_from(m: [[i64; 4]; 4]) -> Result<Self, Error> {
        Self::from_integers(m)
    }
}

/// The entries of `m` as `i64` if all are below 2²⁴ in absolute value.
fn small_entries(m: &SymMatrix4) -> Option<[[i64; 4]; 4]> {
    const LIMIT: u64 = 1 << 24;
    let mut out = [[0i64; 4]; 4];
    for (i, row) in m.entries().iter().enumerate() {
        for (j, v) in row.iter().enumerate() {
            let x = i64::try_from(v).ok()?;
            // (`abs` overflows on −2⁶³)
            if x.unsigned_abs() >= LIMIT {
                return None;
            }
            out[i][j] = x;
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
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
