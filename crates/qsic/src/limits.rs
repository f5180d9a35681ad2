//! Size limits on textual input, so that reading cannot exhaust time or memory.
//!
//! Every number is read exactly, so a short string can denote a huge value
//! (`1e999999999` has a billion digits). The readers in [`crate::io`] check these
//! limits *before* doing the expensive work and answer
//! [`Error::Limit`](crate::error::Error::Limit) instead. With them, reading any
//! string takes time polynomial in its length with a small exponent, and
//! never more than a few seconds even on adversarial input.
//!
//! | constant | bounds |
//! |---|---|
//! | [`MAX_INPUT_LEN`] | bytes in one polynomial string |
//! | [`MAX_NUMBER_DIGITS`] | digits in one number (mantissa, or numerator and denominator together) |
//! | [`MAX_DECIMAL_EXPONENT`] | the absolute value of a decimal exponent `e` in `1.5e-3` |
//! | [`MAX_POWER_EXPONENT`] | the exponent `n` in `(…)^n` inside a polynomial |
//! | [`MAX_NESTING_DEPTH`] | nested parentheses in a polynomial |
//! | [`MAX_COEFFICIENT_BITS`] | bits of every coefficient met while expanding a polynomial |
//! | [`MAX_EXPANSION_BITS`] | bits of all numbers computed while reading one polynomial, added up |

/// Largest polynomial string accepted by [`crate::io::parse_quadric`], in bytes (100 kB).
///
/// A quadric has at most ten coefficients, so any sensible input is far shorter.
pub const MAX_INPUT_LEN: usize = 100_000;

/// Largest number of decimal digits in one number.
///
/// Counted over the mantissa (`123.456` has 6) or, for a fraction `p/q`, over
/// the mantissas of `p` and `q` together; exponent digits are bounded by
/// [`MAX_DECIMAL_EXPONENT`] instead. 10 000 digits are about 33 000 bits.
pub const MAX_NUMBER_DIGITS: usize = 10_000;

/// Largest absolute value of the exponent `e` of a number in scientific
/// notation (`2.5E+10`, `1e-3`).
///
/// The exponent is compared with this bound while its digits are read, so
/// `1e999999999` is refused at once, before `10^e` is computed.
pub const MAX_DECIMAL_EXPONENT: usize = 10_000;

/// Largest exponent `n` of a power `base^n` (or `base**n`) in a polynomial.
///
/// A power of a non-constant expression is refused as soon as its degree
/// exceeds 2 anyway; this bound stops towers of numeric powers like
/// `((9^16)^16)^16` from growing numbers without end (see also
/// [`MAX_COEFFICIENT_BITS`]).
pub const MAX_POWER_EXPONENT: usize = 16;

/// Deepest nesting of parentheses in a polynomial string.
///
/// The reader is recursive, so this bounds its stack use: well under 512 KiB
/// at this depth, even unoptimised, so reading is safe on any thread.
pub const MAX_NESTING_DEPTH: usize = 64;

/// Largest size, in bits, of any coefficient met while expanding a polynomial:
/// the bit lengths of numerator and denominator added.
///
/// Checked after every addition, product and power step, so no intermediate
/// value exceeds twice this size. 262 144 bits are about 79 000 decimal digits,
/// enough for the square of any number allowed by [`MAX_NUMBER_DIGITS`] and
/// [`MAX_DECIMAL_EXPONENT`].
pub const MAX_COEFFICIENT_BITS: usize = 262_144;

/// Largest total size, in bits, of all the numbers computed while reading one
/// polynomial: every number read and every result of an addition, product or
/// power step, added up (2²⁴ bits, 2 MiB).
///
/// [`MAX_COEFFICIENT_BITS`] bounds the cost of one operation; this bounds how
/// many expensive ones a 100 kB string can ask for (such as thousands of
/// copies of `(1e9999)^7`). Inputs written by people use a tiny fraction of it.
pub const MAX_EXPANSION_BITS: usize = 1 << 24;
