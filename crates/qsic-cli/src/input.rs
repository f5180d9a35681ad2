//! Reading one quadric from a command-line argument or from a JSON value, exactly.
//!
//! | entry point | reads |
//! |---|---|
//! | [`quadric_from_arg`] | a command-line argument: a polynomial string, or a JSON 4×4 array if it starts with `[` |
//! | [`quadric_from_json`] | a JSON value: a polynomial string or a 4×4 array of numbers or number strings |
//! | [`JsonForm`], [`quadric_from_form`] | the same, borrowed from the JSON text without a [`Value`] tree (batch lines) |
//!
//! Both answer `Ok(None)` for the zero form, which is allowed on one side of a pair
//! (see [`qsic::classify_allowing_zero`]). JSON numbers are never converted through
//! `f64`: `serde_json` keeps their text (feature `arbitrary_precision`) and
//! [`qsic::io::parse_number`] reads that text exactly, so `0.1` is one tenth and
//! `123456789012345678901234567890` keeps every digit.

use qsic::error::shorten_numbers;
use qsic::io::{parse_quadric, parse_quadric_or_plane, quadric_from_array, quadric_from_rows};
use qsic::{Error, Quadric};
use serde::de::{self, Deserialize, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor};
use serde_json::value::RawValue;
use serde_json::Value;
use std::borrow::Cow;
use std::fmt;

/// Longest JSON matrix accepted as a command-line argument, in bytes: the batch line limit.
pub const MAX_MATRIX_ARG_BYTES: usize = crate::reader::MAX_LINE_BYTES;

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
            InputError::Json(e) => write!(
                f,
                "invalid JSON matrix: {}",
                shorten_numbers(&e.to_string())
            ),
            InputError::Type(message) => f.write_str(&shorten_numbers(message)),
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

/// A quadric as read, and whether it was written as a plane (a polynomial of degree 1, which
/// the library reads as its double plane: see [`qsic::io::parse_quadric`]).
#[derive(Clone, Debug)]
pub struct Surface {
    /// The quadric, `None` for the zero form.
    pub quadric: Option<Quadric>,
    /// The text was a plane `a·x + b·y + c·z + d = 0` (or a linear form using `w`).
    pub plane: bool,
}

/// A polynomial text: a quadric, or a plane (degree 1) as its double plane, in one reading
/// ([`parse_quadric_or_plane`]).
fn polynomial_surface(text: &str) -> Result<Surface, InputError> {
    match parse_quadric_or_plane(text) {
        Ok((quadric, plane)) => Ok(Surface {
            quadric: Some(quadric),
            plane,
        }),
        Err(Error::ZeroQuadric) => Ok(Surface {
            quadric: None,
            plane: false,
        }),
        Err(e) => Err(InputError::Quadric(e)),
    }
}

/// [`quadric_from_arg`], and whether the argument was a plane (a polynomial of degree 1,
/// read as its double plane as everywhere).
///
/// # Errors
/// As [`quadric_from_arg`].
pub fn surface_from_arg(text: &str) -> Result<Surface, InputError> {
    if text.trim_start().starts_with('[') {
        Ok(Surface {
            quadric: quadric_from_arg(text)?,
            plane: false,
        })
    } else {
        polynomial_surface(text)
    }
}

/// [`quadric_from_form`] with planes (see [`surface_from_arg`]).
///
/// # Errors
/// As [`quadric_from_form`].
pub fn surface_from_form(form: &JsonForm<'_>) -> Result<Surface, InputError> {
    match form {
        JsonForm::Text(text) => polynomial_surface(text),
        _ => Ok(Surface {
            quadric: quadric_from_form(form)?,
            plane: false,
        }),
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

/// A quadric as a JSON value, borrowed from the text it is read from: what
/// [`quadric_from_json`] reads, without building a [`Value`] tree. Deserializing it never
/// fails on a value of the wrong type (only on invalid JSON): the type is checked by
/// [`quadric_from_form`], with the messages of [`quadric_from_json`].
#[derive(Debug)]
// Two per batch line, on the stack: boxing the matrix would cost an allocation.
#[allow(clippy::large_enum_variant)]
pub enum JsonForm<'a> {
    /// A string: a polynomial (borrowed unless it holds escapes).
    Text(Cow<'a, str>),
    /// An array, read as a matrix.
    Matrix(JsonMatrix<'a>),
    /// A 4×4 array whose entries are numbers (their text as written) or strings without
    /// escapes (their content), as [`crate::line::scan_plain`] reads it.
    Array4([[&'a str; 4]; 4]),
    /// An object: a quadric under a rigid motion for the moving readers
    /// ([`crate::rigid`]); of the wrong type for the others.
    Object(serde_json::Map<String, Value>),
    /// Any other value, by its JSON type (`"a number"`, `"null"`, …).
    Other(&'static str),
}

/// An array read as a matrix: its shape and its first 4×4 entries as raw JSON texts.
#[derive(Debug, Default)]
pub struct JsonMatrix<'a> {
    /// Number of rows.
    rows: usize,
    /// The first row that is not an array, and its JSON type.
    not_array: Option<(usize, &'static str)>,
    /// The length of the first row (of those that are arrays) that does not have 4 entries.
    bad_len: Option<usize>,
    /// Entries `(i, j)` for `i, j < 4`, as written in the JSON text.
    entries: [[Option<&'a RawValue>; 4]; 4],
}

/// One row of a [`JsonMatrix`] while it is read.
enum JsonRow<'a> {
    Entries {
        len: usize,
        first: [Option<&'a RawValue>; 4],
    },
    Other(&'static str),
}

/// The JSON type named by a value that arrives as a map: with `arbitrary_precision`,
/// serde_json hands a number to a visitor as a map with this one key.
const NUMBER_TOKEN: &str = "$serde_json::private::Number";

/// Reads the rest of a map, and names it: `"a number"` for serde_json's number map.
fn drain_map<'de, A: MapAccess<'de>>(mut map: A) -> Result<&'static str, A::Error> {
    let mut kind = "an object";
    let mut first = true;
    while let Some(key) = map.next_key::<Cow<'de, str>>()? {
        if first && key == NUMBER_TOKEN {
            kind = "a number";
        }
        first = false;
        map.next_value::<IgnoredAny>()?;
    }
    Ok(kind)
}

/// Visits any value of the wrong type as `T::from(kind)`.
macro_rules! other_kinds {
    ($make:expr) => {
        other_scalars!($make);
        fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Self::Value, A::Error> {
            Ok($make(drain_map(map)?))
        }
    };
}

/// Visits a boolean, a number or null as `T::from(kind)`.
macro_rules! other_scalars {
    ($make:expr) => {
        fn visit_bool<E: de::Error>(self, _: bool) -> Result<Self::Value, E> {
            Ok($make("a boolean"))
        }
        fn visit_i64<E: de::Error>(self, _: i64) -> Result<Self::Value, E> {
            Ok($make("a number"))
        }
        fn visit_u64<E: de::Error>(self, _: u64) -> Result<Self::Value, E> {
            Ok($make("a number"))
        }
        fn visit_f64<E: de::Error>(self, _: f64) -> Result<Self::Value, E> {
            Ok($make("a number"))
        }
        fn visit_unit<E: de::Error>(self) -> Result<Self::Value, E> {
            Ok($make("null"))
        }
    };
}

impl<'de> Deserialize<'de> for JsonForm<'de> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct FormVisitor;
        impl<'de> Visitor<'de> for FormVisitor {
            type Value = JsonForm<'de>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("any JSON value")
            }
            fn visit_borrowed_str<E: de::Error>(self, v: &'de str) -> Result<Self::Value, E> {
                Ok(JsonForm::Text(Cow::Borrowed(v)))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Self::Value, E> {
                Ok(JsonForm::Text(Cow::Owned(v.to_owned())))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
                let mut m = JsonMatrix::default();
                while let Some(row) = seq.next_element::<JsonRow<'de>>()? {
                    match row {
                        JsonRow::Entries { len, first } => {
                            if len != 4 && m.bad_len.is_none() {
                                m.bad_len = Some(len);
                            }
                            if let Some(dst) = m.entries.get_mut(m.rows) {
                                *dst = first;
                            }
                        }
                        JsonRow::Other(kind) => {
                            if m.not_array.is_none() {
                                m.not_array = Some((m.rows, kind));
                            }
                        }
                    }
                    m.rows += 1;
                }
                Ok(JsonForm::Matrix(m))
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
                let mut object = serde_json::Map::new();
                while let Some(key) = map.next_key::<String>()? {
                    if object.is_empty() && key == NUMBER_TOKEN {
                        // serde_json's arbitrary-precision number, not an object
                        map.next_value::<IgnoredAny>()?;
                        drain_map(map)?;
                        return Ok(JsonForm::Other("a number"));
                    }
                    let value = map.next_value::<Value>()?;
                    object.insert(key, value);
                }
                Ok(JsonForm::Object(object))
            }
            other_scalars!(JsonForm::Other);
        }
        deserializer.deserialize_any(FormVisitor)
    }
}

impl<'de> Deserialize<'de> for JsonRow<'de> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct RowVisitor;
        impl<'de> Visitor<'de> for RowVisitor {
            type Value = JsonRow<'de>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("any JSON value")
            }
            fn visit_str<E: de::Error>(self, _: &str) -> Result<Self::Value, E> {
                Ok(JsonRow::Other("a string"))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
                let mut first = [None; 4];
                let mut len = 0;
                while let Some(entry) = seq.next_element::<&'de RawValue>()? {
                    if let Some(dst) = first.get_mut(len) {
                        *dst = Some(entry);
                    }
                    len += 1;
                }
                Ok(JsonRow::Entries { len, first })
            }
            other_kinds!(JsonRow::Other);
        }
        deserializer.deserialize_any(RowVisitor)
    }
}

/// A raw JSON entry as a number text: a number as written, a string's content (unescaped).
fn entry_text<'a>(raw: &'a RawValue, i: usize, j: usize) -> Result<Cow<'a, str>, InputError> {
    let text = raw.get();
    match text.as_bytes().first() {
        Some(b'-' | b'0'..=b'9') => Ok(Cow::Borrowed(text)),
        Some(b'"') if !text.contains('\\') => Ok(Cow::Borrowed(&text[1..text.len() - 1])),
        Some(b'"') => serde_json::from_str::<String>(text)
            .map(Cow::Owned)
            .map_err(InputError::Json),
        first => {
            let kind = match first {
                Some(b'n') => "null",
                Some(b't' | b'f') => "a boolean",
                Some(b'[') => "an array",
                _ => "an object",
            };
            Err(InputError::Type(format!(
                "entry ({i},{j}) must be a number or a string, found {kind}"
            )))
        }
    }
}

/// [`quadric_from_json`] for a borrowed [`JsonForm`]: the same answers and errors.
///
/// # Errors
/// As [`quadric_from_json`].
pub fn quadric_from_form(form: &JsonForm<'_>) -> Result<Option<Quadric>, InputError> {
    let m = match form {
        JsonForm::Text(text) => return allow_zero(parse_quadric(text)),
        JsonForm::Matrix(m) => m,
        JsonForm::Array4(texts) => return allow_zero(quadric_from_array(texts)),
        JsonForm::Object(_) => {
            return Err(InputError::Type(
                "expected a polynomial string or a 4x4 array, found an object".into(),
            ))
        }
        JsonForm::Other(kind) => {
            return Err(InputError::Type(format!(
                "expected a polynomial string or a 4x4 array, found {kind}"
            )))
        }
    };
    allow_zero(quadric_from_array(&matrix_texts(m)?))
}

/// The entry texts of a 4×4 [`JsonMatrix`] (checked for its shape), as
/// [`quadric_from_json`] reads them: numbers as written, strings unescaped.
///
/// # Errors
/// As [`quadric_from_json`] for the shape and the entry types.
pub(crate) fn matrix_texts<'a>(m: &JsonMatrix<'a>) -> Result<[[Cow<'a, str>; 4]; 4], InputError> {
    if let Some((i, kind)) = m.not_array {
        return Err(InputError::Type(format!(
            "row {i} of the matrix must be an array, found {kind}"
        )));
    }
    if m.rows != 4 || m.bad_len.is_some() {
        return Err(Error::Shape {
            rows: m.rows,
            cols: m.bad_len,
        }
        .into());
    }
    let mut texts: [[Cow<'a, str>; 4]; 4] = Default::default();
    for (i, (row, raw_row)) in texts.iter_mut().zip(&m.entries).enumerate() {
        for (j, (text, raw)) in row.iter_mut().zip(raw_row).enumerate() {
            // The shape is 4×4, so every entry was read.
            if let Some(raw) = raw {
                *text = entry_text(raw, i, j)?;
            }
        }
    }
    Ok(texts)
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
