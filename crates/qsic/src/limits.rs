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
//! | [`MAX_DEGREE`] | the total degree of every numerator and denominator met while reading an expression |
//! | [`MAX_TERMS`] | the number of terms of every polynomial met while reading an expression |
//! | [`MAX_COEFFICIENT_BITS`] | bits of every coefficient met while expanding a polynomial |
//! | [`MAX_EXPANSION_BITS`] | bits of all numbers computed while reading one polynomial, added up |
//! | [`MAX_MOVING_MATRIX_BITS`] | bits of all coefficients of the entries of a moving matrix |
//! | [`MAX_MOTION_DEGREE`] | the degree in `t` of every entry of a moving pencil, denominators cleared |
//! | [`MAX_MOTION_COEFFICIENT_BITS`] | bits of every coefficient of those entries |

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

/// Largest exponent `n` of a power `base^n` (or `base**n`) in a polynomial: [`MAX_DEGREE`],
/// so that every polynomial the reader accepts prints in a form it reads back (`t^64`).
///
/// A power of a non-constant expression is refused anyway as soon as its degree exceeds
/// the bound (2 for a quadric); towers of numeric powers like `((9^64)^64)^64` are
/// stopped by [`MAX_COEFFICIENT_BITS`], checked at every step.
pub const MAX_POWER_EXPONENT: usize = MAX_DEGREE as usize;

/// Deepest nesting of parentheses in a polynomial string.
///
/// The reader is recursive, with at most six frames per level of parentheses (a run of
/// signs is read by a loop, chained powers are refused), so this bounds its stack use: well under 512 KiB at this
/// depth, even unoptimised, so reading is safe on any thread.
pub const MAX_NESTING_DEPTH: usize = 64;

/// Largest total degree of a numerator or a denominator met while reading an expression
/// with [`crate::io::parse_rational_function`] (the quadric reader stops at 2).
///
/// Degrees add up in a product, so the bound is checked before multiplying: `t^9^…` and
/// `(1+t)^16*(1+t)^16*…` are refused at once.
pub const MAX_DEGREE: u32 = 64;

/// Largest number of terms of a polynomial met while reading an expression.
///
/// A product of `m` and `n` terms has up to `m·n`; it is also charged against
/// [`MAX_EXPANSION_BITS`] *before* it is computed, so a huge product is refused without
/// being formed.
pub const MAX_TERMS: usize = 10_000;

/// Largest size, in bits, of any coefficient met while expanding a polynomial:
/// the bit lengths of numerator and denominator added.
///
/// Checked after every addition, product and power step, so no intermediate
/// value exceeds twice this size. 262 144 bits are about 79 000 decimal digits,
/// enough for the square of any number allowed by [`MAX_NUMBER_DIGITS`] and
/// [`MAX_DECIMAL_EXPONENT`].
pub const MAX_COEFFICIENT_BITS: usize = 262_144;

/// Largest total size, in bits, of all the numbers computed while reading one
/// polynomial: every number read and every coefficient computed by an addition or a
/// product, added up (2²⁴ bits, 2 MiB), each counted [`OVERHEAD_BITS`] more than its
/// size for the work of handling a term. A product is charged before it is computed:
/// `Σ (bits aᵢ + bits bⱼ + OVERHEAD_BITS)` over all pairs of terms.
///
/// [`MAX_COEFFICIENT_BITS`] bounds the cost of one operation; this bounds how
/// many expensive ones a 100 kB string can ask for (such as thousands of
/// copies of `(1e9999)^7`). Inputs written by people use a tiny fraction of it.
pub const MAX_EXPANSION_BITS: usize = 1 << 24;

/// What handling one coefficient costs on top of its size, for [`MAX_EXPANSION_BITS`]:
/// so that many operations on tiny numbers (products of polynomials with many terms)
/// are bounded too.
pub const OVERHEAD_BITS: usize = 32;

/// Largest total size, in bits, of the coefficients of the numerators and denominators of
/// the 16 entries of a moving matrix ([`crate::io::moving_matrix_from_rows`]) or of the
/// polynomial of [`crate::io::moving_matrix_from_polynomial`] (2¹⁸ bits, about 79 000
/// decimal digits).
///
/// Clearing denominators takes gcds of polynomials in `t`, whose cost grows with the
/// square of the degree times the cost of products of numbers of this size: this keeps it
/// around a second at worst. The moving quadrics of the literature have a few hundred bits.
pub const MAX_MOVING_MATRIX_BITS: usize = 1 << 18;

/// Largest degree in `t` of an entry of the matrices `M_A`, `M_B` of a
/// [`MovingPencil`](crate::motion::MovingPencil) (denominators cleared, common factor divided
/// out).
///
/// `f(λ; t)` then has degree up to `4·16` in `t` and its discriminant up to `6·64`; the
/// analysis of such a pencil takes seconds, the motions of the literature (rational
/// rotations, screw motions, translations along curves of low degree) have degree 2 to 8.
pub const MAX_MOTION_DEGREE: usize = 16;

/// Largest bit length of a coefficient of an entry of `M_A`, `M_B` (see
/// [`MAX_MOTION_DEGREE`]): about 150 decimal digits.
pub const MAX_MOTION_COEFFICIENT_BITS: usize = 512;
