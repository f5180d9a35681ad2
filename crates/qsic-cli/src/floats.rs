//! `--floats`: how the JSON numbers of a matrix with a fraction or an exponent (`0.09`,
//! `8.9999999999999997e-2`, `1e-3`) are read.
//!
//! | reading | `0.1` | `0.089999999999999997` | what it is |
//! |---|---|---|---|
//! | `text` (default) | 1/10 | 89999999999999997/10¹⁸ | the number as written, exactly |
//! | `shortest` | 1/10 | 9/100 | the double nearest the text, then the shortest decimal that rounds to it (what `repr` and Rust's `{}` print) |
//! | `binary` | 3602879701896397/2⁵⁵ | 3242591731706757/2⁵⁵ | the double nearest the text, exactly (what Python's floats are by default) |
//!
//! Integers (no `.`, no exponent) and number strings (`"0.1"`) are read as written in every
//! reading; so are polynomial strings. The readings are applied to the JSON text before it is
//! read ([`rewrite_floats`]): each float token is replaced by a JSON number for the value, the
//! shortest decimal or the exact decimal expansion of the double (a dyadic rational has one,
//! at most 767 significant digits), so every reader of the CLI reads the result as written.

use std::borrow::Cow;

/// How JSON floats in matrices are read (module documentation).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum FloatReading {
    /// The number as written, exactly.
    #[default]
    Text,
    /// The shortest decimal that rounds to the same double.
    Shortest,
    /// The double's exact binary value.
    Binary,
}

/// The JSON number for the float token `token` under `reading` (`Text`: itself).
///
/// # Errors
/// A token beyond the range of a double, named.
fn reread(token: &str, reading: FloatReading) -> Result<String, String> {
    let x: f64 = token
        .parse()
        .map_err(|_| format!("the number {token} is not a JSON number"))?;
    if !x.is_finite() {
        return Err(format!(
            "the number {token} is beyond the range of a double (--floats {})",
            if reading == FloatReading::Binary {
                "binary"
            } else {
                "shortest"
            }
        ));
    }
    Ok(match reading {
        FloatReading::Text => token.to_owned(),
        FloatReading::Shortest => format!("{x:e}"),
        FloatReading::Binary => exact_decimal(x),
    })
}

/// The exact decimal expansion of a finite double: `m·2ᵉ` with `e < 0` is `m·5⁻ᵉ / 10⁻ᵉ`.
fn exact_decimal(x: f64) -> String {
    use qsic_algebra::IBig;
    let bits = x.to_bits();
    let negative = bits >> 63 == 1;
    let exponent = ((bits >> 52) & 0x7ff) as i64;
    let fraction = bits & ((1u64 << 52) - 1);
    let (m, e) = if exponent == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1u64 << 52), exponent - 1075)
    };
    let sign = if negative { "-" } else { "" };
    if m == 0 {
        return "0".to_owned();
    }
    if e >= 0 {
        return format!("{sign}{}", IBig::from(m) << e as usize);
    }
    let digits = (IBig::from(m) * IBig::from(5u8).pow(e.unsigned_abs() as usize)).to_string();
    format!("{sign}{digits}e{e}")
}

/// `text` (a JSON value, or a JSON object when `keys` names the members to rewrite) with
/// each float token inside an array read by `reading` and written back as a JSON number
/// (module documentation). Strings are left as they are; so is everything outside the named
/// members when `keys` is given (a batch line's `id` keeps its text).
///
/// # Errors
/// A float beyond the range of a double (prefixed with its member's key when `keys` is
/// given). Invalid JSON is not an error here: it is left for
/// the reader, which names it.
pub fn rewrite_floats<'a>(
    text: &'a str,
    reading: FloatReading,
    keys: Option<&[&str]>,
) -> Result<Cow<'a, str>, String> {
    if reading == FloatReading::Text {
        return Ok(Cow::Borrowed(text));
    }
    let b = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let (mut copied, mut i) = (0, 0);
    // containers open: true for an array
    let mut stack: Vec<bool> = Vec::new();
    // the member of the top-level object being read, and whether it is rewritten
    let mut inside = keys.is_none();
    let mut member = "";
    let mut last_string: Option<(usize, usize)> = None;
    while i < b.len() {
        match b[i] {
            b'"' => {
                let start = i + 1;
                i += 1;
                while i < b.len() && b[i] != b'"' {
                    i += if b[i] == b'\\' { 2 } else { 1 };
                }
                last_string = Some((start, i.min(b.len())));
                i += 1;
            }
            b':' if stack.len() == 1 && keys.is_some() => {
                member = last_string.map_or("", |(s, e)| &text[s..e]);
                inside = keys.is_some_and(|k| k.contains(&member));
                i += 1;
            }
            b',' if stack.len() == 1 && keys.is_some() => {
                inside = false;
                i += 1;
            }
            b'[' | b'{' => {
                stack.push(b[i] == b'[');
                i += 1;
            }
            b']' | b'}' => {
                stack.pop();
                i += 1;
            }
            b'-' | b'0'..=b'9' => {
                let start = i;
                while i < b.len() && matches!(b[i], b'-' | b'+' | b'.' | b'e' | b'E' | b'0'..=b'9')
                {
                    i += 1;
                }
                let token = &text[start..i];
                let float = token.contains(['.', 'e', 'E']);
                if float && inside && stack.last() == Some(&true) {
                    out.push_str(&text[copied..start]);
                    let number = reread(token, reading).map_err(|e| match keys {
                        Some(_) => format!("{member}: {e}"),
                        None => e,
                    })?;
                    out.push_str(&number);
                    copied = i;
                }
            }
            _ => i += 1,
        }
    }
    if copied == 0 {
        return Ok(Cow::Borrowed(text));
    }
    out.push_str(&text[copied..]);
    Ok(Cow::Owned(out))
}

#[cfg(test)]
mod tests {
    use super::*;
    use qsic::io::parse_number;
    use qsic_algebra::RBig;

    fn value(token: &str, reading: FloatReading) -> RBig {
        parse_number(&reread(token, reading).unwrap()).unwrap()
    }

    #[test]
    fn each_reading_of_a_float() {
        let frac = |n: i64, d: u64| RBig::from_parts(n.into(), d.into());
        for (token, shortest) in [
            ("0.1", frac(1, 10)),
            ("0.09", frac(9, 100)),
            ("0.089999999999999997", frac(9, 100)),
            ("-2.5e3", frac(-2500, 1)),
            ("1e-300", parse_number("1e-300").unwrap()),
            ("5e-324", parse_number("5e-324").unwrap()),
        ] {
            assert_eq!(value(token, FloatReading::Shortest), shortest, "{token}");
            let x: f64 = token.parse().unwrap();
            let binary = RBig::try_from(x).unwrap();
            assert_eq!(value(token, FloatReading::Binary), binary, "{token}");
        }
        assert_eq!(value("0.5", FloatReading::Binary), frac(1, 2));
        assert_eq!(
            value("1.5e300", FloatReading::Binary),
            RBig::try_from(1.5e300).unwrap()
        );
        assert!(reread("1e400", FloatReading::Shortest)
            .unwrap_err()
            .contains("beyond the range of a double"));
    }

    #[test]
    fn only_floats_in_arrays_of_the_named_members_change() {
        let line = r#"{"id": 0.30000000000000004, "A": [[0.1, 2, "0.1"], [1e1]], "B": "x - 0.1", "C": [0.1]}"#;
        let out = rewrite_floats(line, FloatReading::Shortest, Some(&["A", "B"])).unwrap();
        assert_eq!(
            out,
            r#"{"id": 0.30000000000000004, "A": [[1e-1, 2, "0.1"], [1e1]], "B": "x - 0.1", "C": [0.1]}"#
        );
        let arg = "[[0.30000000000000004, 0], [0, -0.5]]";
        assert_eq!(
            rewrite_floats(arg, FloatReading::Shortest, None).unwrap(),
            "[[3.0000000000000004e-1, 0], [0, -5e-1]]"
        );
        assert_eq!(
            rewrite_floats(arg, FloatReading::Text, None).unwrap(),
            arg,
            "text: as written"
        );
        assert!(matches!(
            rewrite_floats("[[1, 2]]", FloatReading::Binary, None).unwrap(),
            Cow::Borrowed(_)
        ));
    }
}
