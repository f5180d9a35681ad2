//! Moving quadrics as the user writes them, for `qsic motion`, `qsic contact`, their batch
//! lines and Python: a polynomial string or a 4×4 array in `t` ([`moving_from_arg`],
//! [`moving_from_form`]), or the JSON object form, a quadric under a rigid motion
//! ([`qsic::motion::rigid`]):
//!
//! ```text
//! {"quadric": Q,                                   a quadric: a polynomial string or a 4x4 array
//!                                                  (it may itself depend on t)
//!  "rotate": {"axis": [a1, a2, a3]                 Cayley: angle θ with tan(θ/2) = t·|a|
//!              | "quaternion": [q0, q1, q2, q3],   the path q0 + q1 i + q2 j + q3 k
//!             "center": [p1, p2, p3]},             a point of the axis (default the origin)
//!  "translate": [c1, c2, c3]}                      then the translation c(t)
//! ```
//! `a`, `p`: rational numbers (JSON numbers or strings `"1/3"`); `q`, `c`: polynomials in `t`
//! with rational coefficients (numbers or strings `"2*t^2 - 1/2"`). `"rotate"` and
//! `"translate"` are optional (neither: the quadric itself); `"cayley": true` may accompany
//! an axis (it is the axis' parameterization). A point `x` moves to
//! `R(t)(x − p) + p + c(t)`.

use crate::input::{matrix_texts, InputError, JsonForm};
use qsic::io::{
    moving_matrix_from_polynomial, moving_matrix_from_rows, parse_number, MovingMatrix,
};
use qsic::motion::rigid::{parse_polynomial_in_t, RationalPoly, RigidMotion, Rotation};
use qsic::Error;
use qsic_algebra::RBig;
use serde_json::{Map, Value};

/// The text of a JSON number or string (`None` for another type).
fn scalar_text(v: &Value) -> Option<String> {
    match v {
        Value::Number(n) => Some(n.to_string()),
        Value::String(s) => Some(s.clone()),
        _ => None,
    }
}

fn invalid(message: String) -> InputError {
    InputError::Quadric(Error::InvalidMotion(message))
}

/// Three or four entries of `key` read by `read`, each named in errors by its index.
fn entries<T, const N: usize>(
    key: &str,
    value: &Value,
    read: impl Fn(&str) -> Result<T, Error>,
) -> Result<[T; N], InputError> {
    let Value::Array(items) = value else {
        return Err(invalid(format!(
            "\"{key}\" must be an array of {N} entries, found {}",
            crate::input::json_kind(value)
        )));
    };
    if items.len() != N {
        return Err(invalid(format!(
            "\"{key}\" must have {N} entries, found {}",
            items.len()
        )));
    }
    let mut out = Vec::with_capacity(N);
    for (i, item) in items.iter().enumerate() {
        let text = scalar_text(item).ok_or_else(|| {
            invalid(format!(
                "\"{key}\"[{i}] must be a number or a string, found {}",
                crate::input::json_kind(item)
            ))
        })?;
        out.push(read(&text).map_err(|e| invalid(format!("\"{key}\"[{i}]: {e}")))?);
    }
    Ok(out.try_into().unwrap_or_else(|_| unreachable!("N entries")))
}

/// Refuses keys other than `allowed` in an object named `what`.
fn only_keys(map: &Map<String, Value>, allowed: &[&str], what: &str) -> Result<(), InputError> {
    match map.keys().find(|k| !allowed.contains(&k.as_str())) {
        Some(k) => Err(invalid(format!(
            "unknown key \"{k}\" in {what} (expected {})",
            allowed.join(", ")
        ))),
        None => Ok(()),
    }
}

fn rotation(value: &Value) -> Result<(Rotation, [RBig; 3]), InputError> {
    let Value::Object(map) = value else {
        return Err(invalid(format!(
            "\"rotate\" must be an object, found {}",
            crate::input::json_kind(value)
        )));
    };
    only_keys(
        map,
        &["axis", "cayley", "quaternion", "center"],
        "\"rotate\"",
    )?;
    let center = match map.get("center") {
        Some(c) => entries::<_, 3>("center", c, parse_number)?,
        None => [RBig::ZERO, RBig::ZERO, RBig::ZERO],
    };
    let rotation =
        match (map.get("axis"), map.get("quaternion")) {
            (Some(_), Some(_)) => {
                return Err(invalid(
                    "\"rotate\" has both an \"axis\" and a \"quaternion\": give one".into(),
                ))
            }
            (Some(axis), None) => {
                match map.get("cayley") {
                    None | Some(Value::Bool(true)) => {}
                    Some(_) => return Err(invalid(
                        "an axis rotation is parameterized by t = tan(θ/2)/|axis| (\"cayley\": \
                         true); give a \"quaternion\" path for another"
                            .into(),
                    )),
                }
                Rotation::Cayley {
                    axis: entries::<_, 3>("axis", axis, parse_number)?,
                }
            }
            (None, Some(q)) => {
                if map.contains_key("cayley") {
                    return Err(invalid(
                        "\"cayley\" goes with an \"axis\", not with a \"quaternion\"".into(),
                    ));
                }
                Rotation::Quaternion(entries::<RationalPoly, 4>(
                    "quaternion",
                    q,
                    parse_polynomial_in_t,
                )?)
            }
            (None, None) => {
                return Err(invalid(
                    "\"rotate\" needs an \"axis\" or a \"quaternion\"".into(),
                ))
            }
        };
    Ok((rotation, center))
}

/// A moving quadric from the JSON object form (module docs).
///
/// # Errors
/// [`InputError::Quadric`] with [`Error::InvalidMotion`] naming the key and entry at fault,
/// or the quadric reader's error (prefixed by `"quadric": `); the motion's own errors (a zero
/// axis or path, the bounds of a moving matrix).
pub fn moving_from_object(map: &Map<String, Value>) -> Result<MovingMatrix, InputError> {
    only_keys(map, &["quadric", "rotate", "translate"], "a rigid motion")?;
    let text = match map.get("quadric") {
        Some(Value::String(s)) => s.clone(),
        Some(m @ Value::Array(_)) => m.to_string(),
        Some(other) => {
            return Err(InputError::Type(format!(
                "\"quadric\" must be a polynomial string or a 4x4 array, found {}",
                crate::input::json_kind(other)
            )))
        }
        None => return Err(invalid("a rigid motion needs a \"quadric\"".into())),
    };
    let quadric = moving_from_arg(&text).map_err(|e| match e {
        InputError::Quadric(Error::InvalidMotion(m)) => invalid(m),
        e => InputError::Type(format!("\"quadric\": {e}")),
    })?;
    let mut motion = RigidMotion::default();
    if let Some(r) = map.get("rotate") {
        (motion.rotation, motion.center) = rotation(r)?;
    }
    if let Some(c) = map.get("translate") {
        motion.translation = entries::<RationalPoly, 3>("translate", c, parse_polynomial_in_t)?;
    }
    Ok(motion.apply(&quadric)?)
}

/// [`moving_from_object`] of a JSON text (an argument starting with `{`).
///
/// # Errors
/// [`InputError::Json`] for text that is not JSON, [`InputError::Type`] for JSON that is not
/// an object; otherwise as [`moving_from_object`].
pub fn moving_from_object_text(text: &str) -> Result<MovingMatrix, InputError> {
    let value: Value = serde_json::from_str(text).map_err(InputError::Json)?;
    match &value {
        Value::Object(map) => moving_from_object(map),
        other => Err(InputError::Type(format!(
            "expected a rigid motion object, found {}",
            crate::input::json_kind(other)
        ))),
    }
}

/// Reads a moving quadric from a command-line argument: a JSON array of 4 rows of 4 entries
/// (numbers or strings of rational functions of `t`) if it starts with `[`, a quadric under
/// a rigid motion (below) if it starts with `{`, otherwise a quadratic form in
/// `x, y, z, w` (or affine in `x, y, z`) with coefficients rational in `t`.
///
/// # Errors
/// [`InputError::Json`] or [`InputError::Type`] for a bad JSON matrix, otherwise the
/// reader's error (syntax, symmetry, zero quadric, limits).
pub fn moving_from_arg(text: &str) -> Result<MovingMatrix, InputError> {
    let object = text.trim_start().starts_with('{');
    if !text.trim_start().starts_with('[') && !object {
        return Ok(moving_matrix_from_polynomial(text)?);
    }
    if text.len() > crate::input::MAX_MATRIX_ARG_BYTES {
        return Err(InputError::TooLong(text.len()));
    }
    if object {
        return moving_from_object_text(text);
    }
    let value: Value = serde_json::from_str(text).map_err(InputError::Json)?;
    let Value::Array(rows) = &value else {
        return Err(InputError::Type(format!(
            "expected a 4x4 array, found {}",
            crate::input::json_kind(&value)
        )));
    };
    let mut texts = Vec::with_capacity(rows.len());
    for (i, row) in rows.iter().enumerate() {
        let Value::Array(entries) = row else {
            return Err(InputError::Type(format!(
                "row {i} of the matrix must be an array, found {}",
                crate::input::json_kind(row)
            )));
        };
        let mut out = Vec::with_capacity(entries.len());
        for (j, e) in entries.iter().enumerate() {
            out.push(match e {
                Value::Number(n) => n.to_string(),
                Value::String(s) => s.clone(),
                other => {
                    return Err(InputError::Type(format!(
                        "entry ({i},{j}) must be a number or a string, found {}",
                        crate::input::json_kind(other)
                    )))
                }
            });
        }
        texts.push(out);
    }
    Ok(moving_matrix_from_rows(&texts)?)
}

/// Reads a moving quadric from a batch field: a string as in [`moving_from_arg`], a 4×4
/// array of numbers and strings, or a rigid motion object (below).
///
/// # Errors
/// As [`moving_from_arg`]; [`InputError::Type`] for a value of another JSON type.
pub fn moving_from_form(form: &JsonForm<'_>) -> Result<MovingMatrix, InputError> {
    let rows: Vec<Vec<&str>> = match form {
        JsonForm::Text(text) => return Ok(moving_matrix_from_polynomial(text)?),
        JsonForm::Array4(texts) => texts.iter().map(|r| r.to_vec()).collect(),
        JsonForm::Matrix(m) => {
            let texts = matrix_texts(m)?;
            let rows: Vec<Vec<&str>> = texts
                .iter()
                .map(|r| r.iter().map(|c| c.as_ref()).collect())
                .collect();
            return Ok(moving_matrix_from_rows(&rows)?);
        }
        JsonForm::Object(map) => return moving_from_object(map),
        JsonForm::Other(kind) => {
            return Err(InputError::Type(format!(
                "expected a polynomial string, a 4x4 array or a rigid motion object, found {kind}"
            )))
        }
    };
    Ok(moving_matrix_from_rows(&rows)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str) -> Result<MovingMatrix, String> {
        moving_from_object_text(text).map_err(|e| e.to_string())
    }

    #[test]
    fn the_object_form_builds_the_library_motion() {
        let m =
            read(r#"{"quadric": "x^2/4 + y^2 + z^2 - 1", "rotate": {"axis": [0, 0, 1]}}"#).unwrap();
        let want = RigidMotion {
            rotation: Rotation::Cayley {
                axis: [0, 0, 1].map(RBig::from),
            },
            ..RigidMotion::default()
        }
        .apply(&moving_from_arg("x^2/4 + y^2 + z^2 - 1").unwrap())
        .unwrap();
        assert_eq!(m, want);
        let same = read(
            r#"{"quadric": [["1/4",0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,-1]],
                "rotate": {"quaternion": [1, 0, 0, "t"], "center": ["0", 0, 0.0]}, "translate": [0, 0, 0]}"#,
        )
        .unwrap();
        assert_eq!(same, want);
        let slide =
            read(r#"{"quadric": "x^2 + y^2 + z^2 - 1", "translate": ["t", 0, "t^2/2"]}"#).unwrap();
        assert_eq!(
            slide,
            moving_from_arg("(x - t)^2 + y^2 + (z - t^2/2)^2 - 1").unwrap()
        );
    }

    #[test]
    fn errors_name_the_key_and_the_entry() {
        let cases = [
            (r#"{"quadric": "x^2 - 1", "spin": 1}"#, "invalid rigid motion: unknown key \"spin\" in a rigid motion (expected quadric, rotate, translate)"),
            (r#"{"rotate": {"axis": [0, 0, 1]}}"#, "invalid rigid motion: a rigid motion needs a \"quadric\""),
            (r#"{"quadric": "x^2 - 1", "rotate": {"axis": [0, 0]}}"#, "invalid rigid motion: \"axis\" must have 3 entries, found 2"),
            (r#"{"quadric": "x^2 - 1", "rotate": {"axis": [0, "t", 1]}}"#, "invalid rigid motion: \"axis\"[1]: bad number 't'"),
            (r#"{"quadric": "x^2 - 1", "rotate": {"axis": [0, 0, 0]}}"#, "invalid rigid motion: the rotation axis is zero"),
            (r#"{"quadric": "x^2 - 1", "rotate": {"axis": [0, 0, 1], "cayley": false}}"#, "invalid rigid motion: an axis rotation is parameterized"),
            (r#"{"quadric": "x^2 - 1", "rotate": {"axis": [0, 0, 1], "quaternion": [1, 0, 0, 0]}}"#, "invalid rigid motion: \"rotate\" has both"),
            (r#"{"quadric": "x^2 - 1", "rotate": {}}"#, "invalid rigid motion: \"rotate\" needs an \"axis\" or a \"quaternion\""),
            (r#"{"quadric": "x^2 - 1", "translate": ["1/t", 0, 0]}"#, "invalid rigid motion: \"translate\"[0]: invalid rigid motion: '1/t' is not a polynomial in t"),
            (r#"{"quadric": "x^2 - 1", "translate": [0, null, 0]}"#, "invalid rigid motion: \"translate\"[1] must be a number or a string, found null"),
            (r#"{"quadric": "x^2 + * 1"}"#, "\"quadric\": syntax error"),
            (r#"{"quadric": 3}"#, "\"quadric\" must be a polynomial string or a 4x4 array, found a number"),
            (r#"[1, 2]"#, "expected a rigid motion object"),
        ];
        for (text, want) in cases {
            match read(text) {
                Err(m) => assert!(m.starts_with(want), "{text}: {m}"),
                Ok(_) => panic!("{text} was read"),
            }
        }
    }
}
