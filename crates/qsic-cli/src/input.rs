//! Reading one quadric from a command-line argument or from a JSON value, exactly.
//!
//! | entry point | reads |
//! |---|---|
//! | [`quadric_from_arg`] | a command-line argument: a polynomial string, or a JSON 4×4 array if it starts with `[` |
//! | [`quadric_from_json`] | a JSON value: a polynomial string or a 4×4 array of numbers or number strings |
//!
//! Both answer `Ok(None)` for the zero form, which is allowed on one side of a pair
//! (see [`qsic::classify_allowing_zero`]). JSON numbers are never converted through
//! `f64`: `serde_json` keeps their text (feature `arbitrary_precision`) and
//! [`qsic::io::parse_number`] reads that text exactly, so `0.1` is one tenth and
//! `123456789012345678901234567890` keeps every digit.

use qsic::io::{parse_quadric, quadric_from_rows};
use qsic::{Error, Quadric};
use serde_json::Value;
use std::fmt;

/// Longest JSON matrix accepted as a command-line argument, in bytes: the batch line limit.
pub const MAX_MATRIX_ARG_BYTES: usize = crate::batch::MAX_LINE_BYTES;

/// Why a quadric could not be read.
#[derive(Debug)]
pub enum InputError {
    /// The library refused the polynomial or the matrix (syntax, symmetry, limits, …).
    Quadric(Error),
    /// A command-line matrix argument that is not valid JSON.
    Json(serde_json::Error),
    /// A JSON value of the wrong type, described by the message.
    Type(String),
    /// A command-line matrix argument longer than [`MAX_MATRIX_ARG_BYTES`].
    TooLong(usize),
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            InputError::Quadric(e) => write!(f, "{e}"),
            InputError::Json(e) => write!(f, "invalid JSON matrix: {e}"),
            InputError::Type(message) => f.write_str(message),
            InputError::TooLong(len) => write!(
                f,
                "matrix argument of {len} bytes exceeds the limit of {MAX_MATRIX_ARG_BYTES} bytes"
            ),
        }
    }
}

impl From<Error> for InputError {
    fn from(e: Error) -> Self {
        InputError::Quadric(e)
    }
}

/// Maps the library's [`Error::ZeroQuadric`] to `None`: the zero form is allowed on one side.
fn allow_zero(result: Result<Quadric, Error>) -> Result<Option<Quadric>, InputError> {
    match result {
        Ok(q) => Ok(Some(q)),
        Err(Error::ZeroQuadric) => Ok(None),
        Err(e) => Err(InputError::Quadric(e)),
    }
}

/// Reads a command-line argument: a JSON array of rows if it starts with `[` (after
/// whitespace), a polynomial in `x, y, z, w` otherwise. `None` for the zero form.
///
/// # Errors
/// [`InputError::TooLong`] or [`InputError::Json`] for a bad matrix text, otherwise as
/// [`quadric_from_json`] and [`parse_quadric`].
pub fn quadric_from_arg(text: &str) -> Result<Option<Quadric>, InputError> {
    if text.trim_start().starts_with('[') {
        if text.len() > MAX_MATRIX_ARG_BYTES {
            return Err(InputError::TooLong(text.len()));
        }
        let value: Value = serde_json::from_str(text).map_err(InputError::Json)?;
        quadric_from_json(&value)
    } else {
        allow_zero(parse_quadric(text))
    }
}

/// Reads a quadric from JSON: a polynomial string, or an array of 4 rows of 4 entries,
/// each a JSON number or a string that [`qsic::io::parse_number`] reads (`"3/4"`, `"0.1"`,
/// `"-2.5e3"`, big integers). `None` for the zero form.
///
/// # Errors
/// - [`InputError::Type`] for a value that is neither a string nor an array, a row that
///   is not an array, or an entry that is neither a number nor a string;
/// - [`InputError::Quadric`] with [`Error::Shape`] if the array is not 4×4, and otherwise
///   as [`parse_quadric`] and [`quadric_from_rows`] (entry, symmetry and limit errors).
pub fn quadric_from_json(value: &Value) -> Result<Option<Quadric>, InputError> {
    let rows = match value {
        Value::String(text) => return allow_zero(parse_quadric(text)),
        Value::Array(rows) => rows,
        other => {
            return Err(InputError::Type(format!(
                "expected a polynomial string or a 4x4 array, found {}",
                json_kind(other)
            )))
        }
    };
    let rows: Vec<&Vec<Value>> = rows
        .iter()
        .enumerate()
        .map(|(i, row)| match row {
            Value::Array(entries) => Ok(entries),
            other => Err(InputError::Type(format!(
                "row {i} of the matrix must be an array, found {}",
                json_kind(other)
            ))),
        })
        .collect::<Result<_, _>>()?;
    let bad_row = rows.iter().map(|r| r.len()).find(|&len| len != 4);
    if rows.len() != 4 || bad_row.is_some() {
        return Err(Error::Shape {
            rows: rows.len(),
            cols: bad_row,
        }
        .into());
    }
    let mut texts: Vec<Vec<String>> = Vec::with_capacity(4);
    for (i, row) in rows.iter().enumerate() {
        let mut text_row = Vec::with_capacity(4);
        for (j, entry) in row.iter().enumerate() {
            text_row.push(match entry {
                // With `arbitrary_precision`, `to_string` gives the number exactly as written.
                Value::Number(n) => n.to_string(),
                Value::String(s) => s.clone(),
                other => {
                    return Err(InputError::Type(format!(
                        "entry ({i},{j}) must be a number or a string, found {}",
                        json_kind(other)
                    )))
                }
            });
        }
        texts.push(text_row);
    }
    allow_zero(quadric_from_rows(&texts))
}

/// The JSON type of a value, for messages: "null", "a boolean", "a number", ….
pub fn json_kind(value: &Value) -> &'static str {
    match value {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn parsed(text: &str) -> Value {
        serde_json::from_str(text).expect("test JSON is valid")
    }

    #[test]
    fn json_numbers_are_read_exactly() {
        // 0.1 as a JSON number must be one tenth, not the nearest f64; the big integer
        // must keep all its digits.
        let big = "123456789012345678901234567890";
        let v = parsed(&format!(
            "[[0.1,0,0,0],[0,{big},0,0],[0,0,1e-30,0],[0,0,0,-1]]"
        ));
        let q = quadric_from_json(&v).expect("valid").expect("nonzero");
        let expected = quadric_from_rows(&[
            vec!["1/10", "0", "0", "0"],
            vec!["0", big, "0", "0"],
            vec!["0", "0", "1/1000000000000000000000000000000", "0"],
            vec!["0", "0", "0", "-1"],
        ])
        .expect("valid");
        assert_eq!(q, expected);
    }

    #[test]
    fn strings_and_numbers_mix() {
        let v = json!([
            ["3/4", 0, 0, 0],
            [0, "0.5", 0, 0],
            [0, 0, "1", 0],
            [0, 0, 0, -1]
        ]);
        assert!(quadric_from_json(&v).expect("valid").is_some());
        let poly = json!("x^2 + y^2 - w^2");
        assert!(quadric_from_json(&poly).expect("valid").is_some());
    }

    #[test]
    fn zero_forms_are_none() {
        assert!(quadric_from_json(&json!("0"))
            .expect("zero allowed")
            .is_none());
        assert!(quadric_from_json(&json!([
            [0, 0, 0, 0],
            [0, 0, 0, 0],
            [0, 0, 0, 0],
            [0, 0, 0, 0]
        ]))
        .expect("zero allowed")
        .is_none());
        assert!(quadric_from_arg("x^2 - x^2")
            .expect("zero allowed")
            .is_none());
        assert!(
            quadric_from_arg(" [[0,0,0,0],[0,0,0,0],[0,0,0,0],[0,0,0,0]]")
                .expect("zero allowed")
                .is_none()
        );
    }

    #[test]
    fn errors_name_what_is_wrong() {
        let cases: &[(Value, &str)] = &[
            (json!(true), "found a boolean"),
            (
                json!([[1, 0, 0, 0], 3, [0, 0, 1, 0], [0, 0, 0, 1]]),
                "row 1",
            ),
            (json!([[1, 0, 0], [0, 1, 0], [0, 0, 1]]), "must be 4x4"),
            (
                json!([[1, 0, 0, 0], [0, null, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]),
                "entry (1,1)",
            ),
            (
                json!([[1, 0, 0, 0], [0, "nan", 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]),
                "entry (1,1): bad number 'nan'",
            ),
            (
                json!([[1, 2, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]),
                "not symmetric",
            ),
            (json!("x^2 + q^2"), "unknown variable 'q'"),
        ];
        for (value, needle) in cases {
            let message = match quadric_from_json(value) {
                Err(e) => e.to_string(),
                Ok(_) => panic!("{value} should be refused"),
            };
            assert!(
                message.contains(needle),
                "{value}: {message:?} lacks {needle:?}"
            );
        }
        let message = quadric_from_arg("[[1,0,0,0],")
            .map(|_| ())
            .map_err(|e| e.to_string());
        assert!(matches!(message, Err(m) if m.starts_with("invalid JSON matrix")));
    }

    #[test]
    fn over_long_matrix_argument_is_refused_before_parsing() {
        let text = format!("[{}]", " ".repeat(MAX_MATRIX_ARG_BYTES));
        assert!(matches!(
            quadric_from_arg(&text),
            Err(InputError::TooLong(_))
        ));
    }
}
