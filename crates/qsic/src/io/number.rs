//! Exact reading of rational numbers: integers, fractions, decimals and scientific notation.
//!
//! [`scan_numeral`] reads one unsigned numeral and is shared with the polynomial
//! reader; [`parse_number`] adds the sign and the fraction bar.

use crate::error::{shorten_numbers, Error};
use crate::limits::{MAX_DECIMAL_EXPONENT, MAX_NUMBER_DIGITS};
use crate::quadric::SmallRational;
use dashu_int::{IBig, UBig};
use dashu_ratio::RBig;

/// Reads a rational number exactly.
///
/// Accepts integers of any size (`-123456789012345678901234567890`), fractions
/// `p/q` whose numerator may carry a sign (`-3/4`, `+2/6`), decimals (`0.1`,
/// `.5`, `5.`) and scientific notation (`1e-3`, `2.5E+10`, `-1.25e2`).
/// Numerator and denominator of a fraction may themselves be decimals
/// (`1.5/2` is `3/4`); the denominator carries no sign. Whitespace is allowed
/// around the number and around `/`, nowhere else. The value is exact: `0.1`
/// is one tenth, not the nearest `f64`.
///
/// # Grammar
/// After trimming surrounding whitespace:
///
/// ```text
/// number   := sign? numeral ( ws* '/' ws* numeral )?
/// numeral  := ( digits ( '.' digits? )? | '.' digits ) ( ('e'|'E') sign? digits )?
/// sign     := '+' | '-'
/// ```
///
/// The cost grows with the number of digits and the size of the exponent,
/// which [`MAX_NUMBER_DIGITS`] and [`MAX_DECIMAL_EXPONENT`] bound before any
/// big number is built.
///
/// # Errors
/// - [`Error::BadNumber`] if the text is not a number of this form, or a
///   fraction has a zero denominator;
/// - [`Error::Limit`] if the number has more than
///   [`MAX_NUMBER_DIGITS`] digits (numerator and denominator together) or an
///   exponent above [`MAX_DECIMAL_EXPONENT`] in absolute value. The exponent is
///   checked digit by digit, so `1e999999999` is refused at once.
///
/// # Examples
/// ```
/// use dashu_ratio::RBig;
/// use qsic::io::parse_number;
///
/// assert_eq!(parse_number("0.1")?, RBig::from_parts(1.into(), 10u8.into()));
/// assert_eq!(parse_number(" -3/4 ")?, RBig::from_parts((-3).into(), 4u8.into()));
/// assert_eq!(parse_number("-1.25e2")?, RBig::from(-125));
/// assert!(parse_number("1/0").is_err());
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn parse_number(text: &str) -> Result<RBig, Error> {
    let bad = |message: String| Error::BadNumber {
        text: excerpt(text.trim()),
        message,
    };
    let trimmed = text.trim_start();
    let lead = text.len() - trimmed.len();
    let body = trimmed.trim_end();
    if body.is_empty() {
        return Err(bad("empty text".into()));
    }
    // `column(i)` is the 1-based character column of byte `i` of `body` in `text`.
    let column = |i: usize| text[..lead + i].chars().count() + 1;
    let malformed = |e: NumeralError, offset: usize| match e {
        NumeralError::Limit(limit) => limit,
        NumeralError::Malformed { at, message } => {
            bad(format!("{message} at column {}", column(offset + at)))
        }
    };

    let (negative, start) = match body.as_bytes()[0] {
        b'-' => (true, 1),
        b'+' => (false, 1),
        _ => (false, 0),
    };
    let (num, len) = scan_numeral(&body[start..]).map_err(|e| malformed(e, start))?;
    let mut rest = start + len;
    let after_num = body[rest..].trim_start();
    let den = if let Some(den_text) = after_num.strip_prefix('/') {
        let den_start = body.len() - den_text.trim_start().len();
        let (den, den_len) =
            scan_numeral(&body[den_start..]).map_err(|e| malformed(e, den_start))?;
        rest = den_start + den_len;
        Some(den)
    } else {
        rest = body.len() - after_num.len();
        None
    };
    if rest < body.len() {
        let c = body[rest..].chars().next().unwrap_or(' ');
        let message = match c {
            'e' | 'E' => "exponent without digits".to_string(),
            '/' => "a second '/'".to_string(),
            _ => format!("unexpected '{c}'"),
        };
        return Err(bad(format!("{message} at column {}", column(rest))));
    }

    let digits = num.digit_count() + den.as_ref().map_or(0, Numeral::digit_count);
    check_digits(digits)?;
    let mut value = num.value();
    if let Some(den) = den {
        let den = den.value();
        if den.is_zero() {
            return Err(bad("zero denominator".into()));
        }
        value /= den;
    }
    Ok(if negative { -value } else { value })
}

/// The shortest decimal that rounds to `x`, as a rational: what Rust's `{}` and `{:e}`
/// and Python's `repr` print, read exactly (`0.1` → 1/10; `0.3 * 0.3`, printed `0.09`, →
/// 9/100), where [`Quadric::from_f64`](crate::Quadric::from_f64) takes the binary value the
/// float holds (`0.1` → 3602879701896397/2⁵⁵). `None` for an infinity or NaN.
///
/// ```
/// use dashu_ratio::RBig;
/// use qsic::io::shortest_decimal;
/// assert_eq!(shortest_decimal(0.1), Some(RBig::from_parts(1.into(), 10u8.into())));
/// assert_eq!(shortest_decimal(0.3 * 0.3), Some(RBig::from_parts(9.into(), 100u8.into())));
/// assert_ne!(RBig::try_from(0.3 * 0.3).ok(), shortest_decimal(0.3 * 0.3));
/// assert_eq!(shortest_decimal(f64::NAN), None);
/// ```
pub fn shortest_decimal(x: f64) -> Option<RBig> {
    if !x.is_finite() {
        return None;
    }
    // `{:e}` prints the shortest digits that round back to `x`, with an exponent of at
    // most three digits: within every limit of `parse_number`
    parse_number(&format!("{x:e}")).ok()
}

/// Reads a number as [`parse_number`] does, in machine arithmetic: `None` if the text is
/// not a number, or its value is not `p/q` with `p` an `i64` and `q` a `u64` after reading
/// each numeral with at most 18 digits (the caller then uses [`parse_number`], which also
/// names any error). Costs a few instructions per character.
pub(crate) fn parse_number_small(text: &str) -> Option<SmallRational> {
    if let Some(v) = parse_plain_fraction(text.as_bytes()) {
        return Some(v);
    }
    let body = text.trim();
    let (negative, start) = match body.as_bytes().first()? {
        b'-' => (true, 1),
        b'+' => (false, 1),
        _ => (false, 0),
    };
    let (num, len) = scan_numeral(&body[start..]).ok()?;
    let value = num.small_value()?;
    let rest = body[start + len..].trim_start();
    let value = if let Some(den_text) = rest.strip_prefix('/') {
        let den_text = den_text.trim_start();
        let (den, len) = scan_numeral(den_text).ok()?;
        let den = den.small_value()?;
        if len != den_text.len() || den.num == 0 {
            return None;
        }
        // (a/b) / (c/d) = (a·d) / (b·c), c > 0
        SmallRational {
            num: value.num.checked_mul(i64::try_from(den.den).ok()?)?,
            den: value.den.checked_mul(den.num.unsigned_abs())?,
        }
    } else if rest.is_empty() {
        value
    } else {
        return None;
    };
    Some(if negative {
        SmallRational {
            num: -value.num,
            ..value
        }
    } else {
        value
    })
}

/// The common case of [`parse_number_small`], in one pass: `-?d+(.d+)?(/d+(.d+)?)?`, each
/// side at most 18 digits, the denominator nonzero; `None` for anything else.
#[inline]
fn parse_plain_fraction(b: &[u8]) -> Option<SmallRational> {
    let negative = b.first() == Some(&b'-');
    let mut i = usize::from(negative);
    let (num, num_scale) = plain_decimal(b, &mut i)?;
    let (num, den) = match b.get(i) {
        None => (num, num_scale),
        Some(b'/') => {
            i += 1;
            let (den, den_scale) = plain_decimal(b, &mut i)?;
            if i != b.len() || den == 0 {
                return None;
            }
            // (num / num_scale) / (den / den_scale)
            (num.checked_mul(den_scale)?, num_scale.checked_mul(den)?)
        }
        Some(_) => return None,
    };
    let num = i64::try_from(num).ok()?;
    Some(SmallRational {
        num: if negative { -num } else { num },
        den,
    })
}

/// The decimal `d+(.d+)?` at `b[*i..]`, at most 18 digits, as `(digits, 10^fraction_len)`,
/// advancing `i` past it.
#[inline(always)]
fn plain_decimal(b: &[u8], i: &mut usize) -> Option<(u64, u64)> {
    let start = *i;
    let mut value = 0u64;
    while let Some(&d) = b.get(*i).filter(|d| d.is_ascii_digit()) {
        value = value * 10 + u64::from(d - b'0');
        *i += 1;
        if *i - start > 18 {
            return None;
        }
    }
    let int_len = *i - start;
    if int_len == 0 {
        return None;
    }
    if b.get(*i) != Some(&b'.') {
        return Some((value, 1));
    }
    *i += 1;
    let frac_start = *i;
    let mut scale = 1u64;
    while let Some(&d) = b.get(*i).filter(|d| d.is_ascii_digit()) {
        if *i - frac_start + int_len >= 18 {
            return None;
        }
        value = value * 10 + u64::from(d - b'0');
        scale *= 10;
        *i += 1;
    }
    // At most 18 digits in all: value < 10^18, scale ≤ 10^17.
    (*i > frac_start).then_some((value, scale))
}

/// An unsigned numeral `int.frac e exponent`, its pieces borrowed from the text.
#[derive(Debug)]
pub(crate) struct Numeral<'a> {
    /// Digits before the point.
    int: &'a str,
    /// Digits after the point.
    frac: &'a str,
    /// The decimal exponent, already checked against [`MAX_DECIMAL_EXPONENT`].
    exponent: i64,
}

/// Why a numeral could not be read.
#[derive(Debug)]
pub(crate) enum NumeralError {
    /// Not a numeral; `at` is the byte offset of the problem in the scanned text.
    Malformed { at: usize, message: String },
    /// A size limit was exceeded.
    Limit(Error),
}

impl Numeral<'_> {
    /// Number of mantissa digits (exponent digits excluded).
    pub(crate) fn digit_count(&self) -> usize {
        self.int.len() + self.frac.len()
    }

    /// The exact value `int.frac × 10^exponent` as a non-negative [`SmallRational`], if
    /// the numeral has at most 18 digits and the value fits.
    pub(crate) fn small_value(&self) -> Option<SmallRational> {
        if self.digit_count() > 18 {
            return None;
        }
        // At most 18 digits: below 10^18 < 2^63.
        let digits = self.int.bytes().chain(self.frac.bytes());
        let mantissa = digits.fold(0u64, |m, d| m * 10 + u64::from(d - b'0'));
        // |exponent| ≤ MAX_DECIMAL_EXPONENT and frac.len() ≤ 18: no overflow.
        let shift = self.exponent - self.frac.len() as i64;
        let power = 10u64.checked_pow(u32::try_from(shift.unsigned_abs()).ok()?)?;
        let (num, den) = if shift >= 0 {
            (mantissa.checked_mul(power)?, 1)
        } else {
            (mantissa, power)
        };
        Some(SmallRational {
            num: i64::try_from(num).ok()?,
            den,
        })
    }

    /// The exact value `int.frac × 10^exponent`.
    ///
    /// Costs about `digit_count + |exponent|` digits of big-integer work; callers
    /// check [`MAX_NUMBER_DIGITS`] first.
    pub(crate) fn value(&self) -> RBig {
        let mantissa = if self.digit_count() <= 19 {
            // At most 19 digits: below 10^19 < 2^64, read without big numbers.
            let digits = self.int.bytes().chain(self.frac.bytes());
            UBig::from(digits.fold(0u64, |m, d| m * 10 + u64::from(d - b'0')))
        } else {
            let mut mantissa = UBig::ZERO;
            for chunk in [self.int, self.frac] {
                if !chunk.is_empty() {
                    // Both pieces are non-empty runs of ASCII digits, so parsing cannot fail.
                    let part = UBig::from_str_radix(chunk, 10).unwrap_or(UBig::ZERO);
                    mantissa = mantissa * UBig::from(10u8).pow(chunk.len()) + part;
                }
            }
            mantissa
        };
        // |exponent| ≤ MAX_DECIMAL_EXPONENT and frac.len() ≤ MAX_NUMBER_DIGITS: no overflow.
        let shift = self.exponent - self.frac.len() as i64;
        if shift == 0 {
            return RBig::from(mantissa);
        }
        let power = UBig::from(10u8).pow(shift.unsigned_abs() as usize);
        if shift >= 0 {
            RBig::from(mantissa * power)
        } else {
            RBig::from_parts(IBig::from(mantissa), power)
        }
    }
}

/// Checks a digit count against [`MAX_NUMBER_DIGITS`].
pub(crate) fn check_digits(count: usize) -> Result<(), Error> {
    if count > MAX_NUMBER_DIGITS {
        return Err(Error::Limit {
            what: format!("{count} digits in one number"),
            limit: MAX_NUMBER_DIGITS,
        });
    }
    Ok(())
}

/// Reads the longest unsigned numeral at the start of `s`, returning it and its byte length.
///
/// An `e` or `E` not followed by (a sign and) a digit is not part of the numeral.
///
/// # Errors
/// [`NumeralError::Malformed`] if `s` does not start with a digit or a point
/// followed by a digit; [`NumeralError::Limit`] if the exponent exceeds
/// [`MAX_DECIMAL_EXPONENT`] (detected after at most a few digits of it).
pub(crate) fn scan_numeral(s: &str) -> Result<(Numeral<'_>, usize), NumeralError> {
    let b = s.as_bytes();
    let digits_from = |i: usize| i + b[i..].iter().take_while(|c| c.is_ascii_digit()).count();
    let int_end = digits_from(0);
    let (frac, mut i) = if b.get(int_end) == Some(&b'.') {
        let frac_end = digits_from(int_end + 1);
        (&s[int_end + 1..frac_end], frac_end)
    } else {
        (&s[int_end..int_end], int_end)
    };
    let int = &s[..int_end];
    if int.is_empty() && frac.is_empty() {
        let message = match s.chars().next() {
            None => "a number is missing".to_string(),
            Some(c) => format!("expected a digit, found '{c}'"),
        };
        return Err(NumeralError::Malformed { at: 0, message });
    }

    let mut exponent = 0i64;
    if matches!(b.get(i), Some(b'e' | b'E')) {
        let (negative, sign_len) = match b.get(i + 1) {
            Some(b'-') => (true, 1),
            Some(b'+') => (false, 1),
            _ => (false, 0),
        };
        let first = i + 1 + sign_len;
        if b.get(first).is_some_and(u8::is_ascii_digit) {
            let end = digits_from(first);
            let mut value = 0usize;
            for &d in &b[first..end] {
                value = value * 10 + usize::from(d - b'0');
                if value > MAX_DECIMAL_EXPONENT {
                    return Err(NumeralError::Limit(Error::Limit {
                        what: "absolute value of a decimal exponent".into(),
                        limit: MAX_DECIMAL_EXPONENT,
                    }));
                }
            }
            // value ≤ MAX_DECIMAL_EXPONENT, far below i64::MAX.
            exponent = if negative {
                -(value as i64)
            } else {
                value as i64
            };
            i = end;
        }
    }
    Ok((
        Numeral {
            int,
            frac,
            exponent,
        },
        i,
    ))
}

/// The text for an error message: long numbers shortened ([`shorten_numbers`]), then cut
/// to at most 40 characters.
pub(crate) fn excerpt(text: &str) -> String {
    const MAX: usize = 40;
    let text = shorten_numbers(text);
    match text.char_indices().nth(MAX) {
        None => text.into_owned(),
        Some((cut, _)) => format!("{}…", &text[..cut]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use std::time::{Duration, Instant};

    fn rat(n: i64, d: u64) -> RBig {
        RBig::from_parts(IBig::from(n), UBig::from(d))
    }

    #[test]
    fn exact_values() {
        let table: &[(&str, RBig)] = &[
            ("0", rat(0, 1)),
            ("-0", rat(0, 1)),
            ("42", rat(42, 1)),
            ("  -17\t", rat(-17, 1)),
            ("+5", rat(5, 1)),
            ("0.1", rat(1, 10)),
            (".5", rat(1, 2)),
            ("5.", rat(5, 1)),
            ("-.25", rat(-1, 4)),
            ("1e-3", rat(1, 1000)),
            ("2.5E+10", rat(25_000_000_000, 1)),
            ("-1.25e2", rat(-125, 1)),
            ("1E3", rat(1000, 1)),
            ("0.000", rat(0, 1)),
            ("007", rat(7, 1)),
            ("1e0000000000000000000002", rat(100, 1)),
            ("-3/4", rat(-3, 4)),
            ("+2/6", rat(1, 3)),
            ("3 / 9", rat(1, 3)),
            ("1.5/2", rat(3, 4)),
            ("1/2e1", rat(1, 20)),
            ("0/5", rat(0, 1)),
        ];
        for (text, want) in table {
            assert_eq!(parse_number(text).as_ref(), Ok(want), "input {text:?}");
        }
    }

    #[test]
    fn huge_integers_round_trip() {
        let digits = "123456789012345678901234567890".repeat(300);
        for text in [digits.clone(), format!("-{digits}")] {
            let value = parse_number(&text).expect("a valid integer");
            assert_eq!(value.to_string(), text);
        }
        let small = parse_number(&format!("1e-{}", MAX_DECIMAL_EXPONENT)).expect("at the limit");
        assert_eq!(
            small.denominator(),
            &UBig::from(10u8).pow(MAX_DECIMAL_EXPONENT)
        );
    }

    #[test]
    fn malformed_numbers_are_bad_numbers() {
        let table = [
            ("", "empty text"),
            ("   ", "empty text"),
            ("abc", "expected a digit, found 'a' at column 1"),
            ("1/0", "zero denominator"),
            ("1/0.000", "zero denominator"),
            ("1/-2", "expected a digit, found '-' at column 3"),
            ("1/2/3", "a second '/' at column 4"),
            ("1e", "exponent without digits at column 2"),
            ("1e+", "exponent without digits at column 2"),
            (".", "expected a digit, found '.' at column 1"),
            ("- 3", "expected a digit, found ' ' at column 2"),
            ("1 2", "unexpected '2' at column 3"),
            ("1.2.3", "unexpected '.' at column 4"),
            ("x", "expected a digit, found 'x' at column 1"),
            ("  1x", "unexpected 'x' at column 4"),
            ("NaN", "expected a digit, found 'N' at column 1"),
            ("--1", "expected a digit, found '-' at column 2"),
            ("1/", "a number is missing at column 3"),
            ("½", "expected a digit, found '½' at column 1"),
        ];
        for (text, want) in table {
            match parse_number(text) {
                Err(Error::BadNumber { message, .. }) => {
                    assert_eq!(message, want, "input {text:?}")
                }
                other => panic!("input {text:?}: expected BadNumber, got {other:?}"),
            }
        }
    }

    #[test]
    fn limits_are_enforced_quickly() {
        let start = Instant::now();
        let too_many = "9".repeat(MAX_NUMBER_DIGITS + 1);
        let split = format!("{}/{}", "1".repeat(6000), "3".repeat(6000));
        let cases = [
            "1e999999999".to_string(),
            "1e-999999999999999999999999999999".to_string(),
            format!("1e{}", MAX_DECIMAL_EXPONENT + 1),
            too_many,
            split,
        ];
        for text in &cases {
            assert!(
                matches!(parse_number(text), Err(Error::Limit { .. })),
                "input {}",
                excerpt(text)
            );
        }
        let at_limit = "9".repeat(MAX_NUMBER_DIGITS);
        assert!(parse_number(&at_limit).is_ok());
        assert!(
            start.elapsed() < Duration::from_secs(2),
            "took {:?}",
            start.elapsed()
        );
    }

    #[test]
    fn excerpt_shortens_long_text() {
        assert_eq!(excerpt("short"), "short");
        let long = "é".repeat(50);
        assert_eq!(excerpt(&long).chars().count(), 41);
        // a long number keeps its ends and its digit count, not its first 40 digits
        let number = format!("{}/0", "1234567890".repeat(300));
        assert_eq!(excerpt(&number), "1234567890…4567890 (3000 digits)/0");
    }

    /// The machine reader must give the value of the exact reader, or decline.
    fn assert_small_agrees(text: &str) {
        if let Some(v) = parse_number_small(text) {
            assert!(v.den > 0, "{text:?}");
            assert_eq!(parse_number(text), Ok(v.to_rbig()), "{text:?}");
        }
    }

    #[test]
    fn one_pass_reader_takes_plain_fractions_only() {
        let taken = [
            "7",
            "-3/2",
            "0.5",
            "-1.25/0.5",
            "007/010",
            "999999999.999999999",
        ];
        for text in taken {
            let v = parse_plain_fraction(text.as_bytes())
                .unwrap_or_else(|| panic!("{text:?} should be read"));
            assert_eq!(parse_number(text), Ok(v.to_rbig()), "{text:?}");
        }
        let declined = [
            "",
            "-",
            "1./2",
            "1/2.",
            "-.5",
            ".5",
            "+1",
            " 1",
            "1 ",
            "1e3",
            "1/0",
            "1/0.0",
            "1.2.3",
            "1/2/3",
            "1//2",
            "1234567890123456789",
            "0.000000000000000001",
        ];
        for text in declined {
            assert_eq!(parse_plain_fraction(text.as_bytes()), None, "{text:?}");
        }
    }

    #[test]
    fn machine_reader_agrees_or_declines() {
        let read = [
            "0",
            "-0",
            "42",
            "  -17\t",
            "+5",
            "0.1",
            ".5",
            "5.",
            "-.25",
            "1e-3",
            "2.5E+10",
            "-1.25e2",
            "007",
            "-3/4",
            "+2/6",
            "3 / 9",
            "1.5/2",
            "1/2e1",
            "0/5",
            "1e18",
            "999999999999999999",
            "0.00000000000000001",
            "1/.5",
            "922337203685477580e1",
            "-1.25",
            "0.5/1.5",
            "3/2.50",
            "-0.00000000000000001/7",
            "12345678.9/0.001",
            "999999999.999999999/7",
        ];
        for text in read {
            assert!(
                parse_number_small(text).is_some(),
                "{text:?} should be read"
            );
            assert_small_agrees(text);
        }
        let declined = [
            "",
            "1/0",
            "1/0.0",
            "1e",
            "1e+",
            "x",
            "1 2",
            "1/2/3",
            "1/-2",
            "- 3",
            "--1",
            "1234567890123456789",
            "-0.000000000000000001/7",
            "1.2.3",
            "0.000000000000000001",
            "9223372036854775807",
            "1e19",
            "1e-20",
            "9223372036854775808",
            "1e99999",
            "100000000000/0.00000001",
        ];
        for text in declined {
            assert_eq!(
                parse_number_small(text),
                None,
                "{text:?} should be declined"
            );
        }
    }

    proptest! {
        #[test]
        fn printed_rationals_read_back(n in any::<i64>(), d in 1u64.., e in -30i32..30) {
            let r = rat(n, d);
            prop_assert_eq!(parse_number(&r.to_string()), Ok(r.clone()));
            // The same value in scientific notation: n·10^e / d.
            let power = RBig::from(UBig::from(10u8).pow(e.unsigned_abs() as usize));
            let scaled = if e >= 0 { &r * &power } else { &r / &power };
            let text = format!("{n}e{e}/{d}");
            prop_assert_eq!(parse_number(&text), Ok(scaled), "text {}", text);
        }

        #[test]
        fn machine_reader_agrees_on_random_texts(
            text in "[+-]?[0-9]{0,20}(\\.[0-9]{0,20})?([eE][+-]?[0-9]{1,3})?( ?/ ?[0-9]{1,20}(\\.[0-9]{0,5})?([eE]-?[0-9]{1,2})?)?",
        ) {
            assert_small_agrees(&text);
        }

        #[test]
        fn arbitrary_strings_do_not_panic(text in "\\PC{0,40}") {
            let _ = parse_number(&text);
        }

        #[test]
        fn number_like_strings_do_not_panic(text in "[0-9+\\-./eE ]{0,30}") {
            let _ = parse_number(&text);
        }
    }
}
