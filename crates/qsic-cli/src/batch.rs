//! `qsic classify --batch`: JSON Lines in, JSON Lines out, in order, on all cores.
//!
//! | item | does |
//! |---|---|
//! | [`run`] | the whole batch: read a chunk, classify it in parallel, write it in order, repeat |
//! | [`LineReader`] | bounded line reading (module [`crate::reader`]): a line never holds more than its limit in memory |
//! | [`answer_line`] | one input line to one output line |
//!
//! Every non-blank input line yields exactly one output line, in input order: the result
//! object with the line's `id`, or `{"id": …, "error": {"line": n, "message": …}}`.
//! Blank (ASCII-whitespace-only) lines yield nothing but are counted in line numbers.
//! A UTF-8 byte-order mark at the very start of the input is skipped.
//! Memory is bounded by the chunk limits, whatever the input: a line longer than
//! [`MAX_LINE_BYTES`] is skipped without being stored and answered with an error.
//!
//! A line is read by [`crate::line::read_line`] into fields borrowed from its text (no
//! `serde_json::Value` tree; the `id` is copied byte for byte), and its answer is written
//! straight into one string ([`crate::output::write_classification_fields`]).

use crate::input::{surface_from_form, JsonForm};
use crate::line::{read_line, Line};
use crate::output::{write_classification_fields, write_json_string};
pub use crate::reader::{Content, LineReader, RawLine};
use crate::stream::stream;
pub use crate::stream::Window;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use qsic::{classify_allowing_zero, classify_within, Budget, Quadric};
use serde_json::Value;
use std::io::{self, Read, Write};
use std::panic::{self, AssertUnwindSafe};
use std::time::Duration;

pub use crate::reader::MAX_LINE_BYTES;

/// Most lines read and not yet written: the reader waits while this many are pending.
pub const PENDING_LINES: usize = 4096;

/// Most bytes of pending input lines and finished answers waiting to be written (64 MiB).
pub const PENDING_BYTES: usize = 64 << 20;

/// Why a line failed, with its `id` as written once it is known.
pub(crate) struct LineFailure<'a> {
    pub(crate) id: Option<&'a str>,
    pub(crate) message: String,
}

impl LineFailure<'_> {
    pub(crate) fn without_id(message: impl Into<String>) -> Self {
        LineFailure {
            id: None,
            message: message.into(),
        }
    }
}

/// `{"id":` and the id as written (`null` if none), then `,`.
pub(crate) fn open_record(id: Option<&str>) -> String {
    let mut out = String::with_capacity(512);
    out.push_str("{\"id\":");
    out.push_str(id.unwrap_or("null"));
    out.push(',');
    out
}

/// What a batch computes for one pair of quadrics (`None`: the zero form): the fields of
/// the result object, without braces and `id` (written after `"id":…,`), or the message of
/// an error line.
pub trait Answer: Sync {
    /// The fields or the error message; `planes[i]`: the input was a plane (its quadric the
    /// double plane); the computation spends `budget` (over it: the message of
    /// [`qsic::Error::BudgetExceeded`]).
    fn answer(
        &self,
        a: Option<&Quadric>,
        b: Option<&Quadric>,
        planes: [bool; 2],
        budget: &Budget,
    ) -> Result<String, String>;
}

/// The work budget of one line, in the units of [`qsic::Budget`], when `--line-budget` is
/// not given: 10¹², some twenty times the largest the README's worst cases spend (about
/// an hour of CPU on this machine kind at the slowest rate measured), so that no
/// documented input meets it and no line runs for ever.
pub const DEFAULT_LINE_BUDGET: u64 = 1_000_000_000_000;

/// Reads a work budget (`--line-budget`): a positive integer (`250000`) or a power of ten
/// with an integer mantissa (`1e9`, `25e8`), at most `u64::MAX`.
///
/// # Errors
/// A message naming the text and the form expected.
pub fn parse_budget(text: &str) -> Result<u64, String> {
    let bad =
        || format!("'{text}': a positive integer of work units (like 250000 or 1e9) expected");
    let (mantissa, exponent) = match text.split_once(['e', 'E']) {
        Some((m, e)) => (m, e.parse::<u32>().map_err(|_| bad())?),
        None => (text, 0),
    };
    if mantissa.is_empty() || !mantissa.bytes().all(|c| c.is_ascii_digit()) {
        return Err(bad());
    }
    let units = mantissa
        .parse::<u64>()
        .ok()
        .and_then(|m| 10u64.checked_pow(exponent).and_then(|p| m.checked_mul(p)))
        .ok_or_else(|| format!("'{text}': more than {} work units", u64::MAX))?;
    if units == 0 {
        return Err(format!("'{text}': the budget must be positive"));
    }
    Ok(units)
}

/// `qsic classify`: the classification's fields, then the `"affine"` object (see
/// [`crate::affine`]) unless `projective_only`.
pub struct Classify {
    /// Leave out the affine view (it builds the curve: much slower than the classification).
    pub projective_only: bool,
    /// The affine chart and its text (`None`: `w = 0`, written `"w"`).
    pub chart: Option<(qsic::affine::Chart, String)>,
}

impl Answer for Classify {
    fn answer(
        &self,
        a: Option<&Quadric>,
        b: Option<&Quadric>,
        planes: [bool; 2],
        budget: &Budget,
    ) -> Result<String, String> {
        let c = match (a, b) {
            (Some(a), Some(b)) => classify_within(a, b, budget).map_err(|e| e.to_string())?,
            _ => {
                classify_allowing_zero(a, b).map_err(|e| format!("A and B: both are zero: {e}"))?
            }
        };
        let mut out = String::with_capacity(512);
        write_classification_fields(&mut out, &c);
        if !self.projective_only {
            let default = (qsic::affine::Chart::default(), "w".to_owned());
            let (chart, text) = self.chart.as_ref().unwrap_or(&default);
            let view = crate::affine::affine_json_within(a, b, chart, text, planes, budget)
                .map_err(|e| e.to_string())?;
            out.push_str(",\"affine\":");
            out.push_str(&view.to_string());
        }
        Ok(out)
    }
}

/// The output line for one input line (without newline) and whether it succeeded.
/// Never panics: a panic inside the classifier becomes an error line.
pub fn answer_line(line: &RawLine) -> (String, bool) {
    answer_line_with(
        line,
        &Classify {
            projective_only: false,
            chart: None,
        },
        DEFAULT_LINE_BUDGET,
    )
}

/// [`answer_line`] for any [`Answer`], with a budget of `units` work units for the line.
pub fn answer_line_with<A: Answer + ?Sized>(
    line: &RawLine,
    answer: &A,
    units: u64,
) -> (String, bool) {
    answer_with(line, |line| quadrics_line(line, answer, units))
}

/// [`answer_line_with`] after reading the JSON floats of the line's `A` and `B` by
/// `floats` ([`reread_floats`]).
pub fn answer_line_reading<A: Answer + ?Sized>(
    line: &RawLine,
    answer: &A,
    floats: crate::floats::FloatReading,
    units: u64,
) -> (String, bool) {
    match reread_floats(line, floats) {
        Ok(None) => answer_line_with(line, answer, units),
        Ok(Some(rewritten)) => answer_line_with(&rewritten, answer, units),
        Err(message) => answer_with(line, |_| Err(LineFailure::without_id(message))),
    }
}

/// `line` with the JSON floats of its `A` and `B` read by `floats`
/// ([`crate::floats::rewrite_floats`]): `None` when nothing changes (or the line is not
/// text, for the reader's own error).
///
/// # Errors
/// The message of a float beyond the range of a double: the line's error.
pub(crate) fn reread_floats(
    line: &RawLine,
    floats: crate::floats::FloatReading,
) -> Result<Option<RawLine>, String> {
    use crate::reader::Content;
    let Content::Text(bytes) = &line.content else {
        return Ok(None);
    };
    let Ok(text) = std::str::from_utf8(bytes) else {
        return Ok(None);
    };
    Ok(
        match crate::floats::rewrite_floats(text, floats, Some(&["A", "B"]))? {
            std::borrow::Cow::Borrowed(_) => None,
            std::borrow::Cow::Owned(text) => Some(RawLine {
                number: line.number,
                content: Content::Text(text.into_bytes()),
            }),
        },
    )
}

/// The output line of `work` on `line`: its text, or the error record of its failure.
pub(crate) fn answer_with<'a>(
    line: &'a RawLine,
    work: impl FnOnce(&'a RawLine) -> Result<String, LineFailure<'a>>,
) -> (String, bool) {
    match work(line) {
        Ok(text) => (text, true),
        Err(failure) => (error_record(line, &failure), false),
    }
}

/// The error object of `line` (without newline).
pub(crate) fn error_record(line: &RawLine, failure: &LineFailure<'_>) -> String {
    let mut out = open_record(failure.id);
    out.push_str("\"error\":{\"line\":");
    out.push_str(&line.number.to_string());
    out.push_str(",\"message\":");
    write_json_string(&mut out, &failure.message);
    out.push_str("}}");
    out
}

/// `f()`, or the message of its panic (a bug, reported on the line instead of aborting).
pub(crate) fn catch_panic<T>(f: impl FnOnce() -> T) -> Result<T, String> {
    panic::catch_unwind(AssertUnwindSafe(f)).map_err(|payload| {
        payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_default()
    })
}

/// Reads a line that does not start with `{` into a [`Value`], for the error message.
fn not_an_object(text: &str) -> LineFailure<'static> {
    match serde_json::from_str::<Value>(text) {
        Err(e) => LineFailure::without_id(format!("invalid JSON: {e}")),
        Ok(value) => LineFailure::without_id(format!(
            "expected a JSON object with fields \"A\" and \"B\", found {}",
            crate::input::json_kind(&value)
        )),
    }
}

/// The fields of a line: errors for an over-long line, invalid UTF-8, a value that is not
/// an object, invalid JSON, a repeated `id`, `A` or `B`.
pub(crate) fn read_record(line: &RawLine) -> Result<Line<'_>, LineFailure<'_>> {
    let bytes = match &line.content {
        Content::Text(bytes) => bytes,
        Content::TooLong { bytes } => {
            return Err(LineFailure::without_id(format!(
                "line of {bytes} bytes exceeds the limit of {MAX_LINE_BYTES} bytes"
            )))
        }
    };
    let text = std::str::from_utf8(bytes).map_err(|e| {
        LineFailure::without_id(format!(
            "line is not valid UTF-8 (invalid byte at offset {})",
            e.valid_up_to()
        ))
    })?;
    if !text
        .trim_start_matches([' ', '\t', '\n', '\r'])
        .starts_with('{')
    {
        return Err(not_an_object(text));
    }
    let record =
        read_line(text).map_err(|e| LineFailure::without_id(format!("invalid JSON: {e}")))?;
    match record.repeated {
        None => Ok(record),
        Some(field) => Err(LineFailure {
            // a repeated id is not the line's: none is written
            id: if field == "id" { None } else { record.id },
            message: format!("duplicate field \"{field}\""),
        }),
    }
}

/// The line's quadrics `A`, `B` answered by `answer`.
fn quadrics_line<'a, A: Answer + ?Sized>(
    line: &'a RawLine,
    answer: &A,
    units: u64,
) -> Result<String, LineFailure<'a>> {
    let (id, fields) = line_work(line, |a, b, planes| {
        answer.answer(a, b, planes, &Budget::new(units))
    })?;
    let mut out = open_record(id);
    out.push_str(&fields);
    out.push('}');
    Ok(out)
}

/// The line's `id` and what `work` makes of its quadrics `A`, `B` (`None`: the zero form)
/// and which of them were planes, or the line's failure: unreadable, a bad quadric, the
/// error `work` answers, or its panic.
pub(crate) fn line_work<'a, T>(
    line: &'a RawLine,
    work: impl FnOnce(Option<&Quadric>, Option<&Quadric>, [bool; 2]) -> Result<T, String>,
) -> Result<(Option<&'a str>, T), LineFailure<'a>> {
    let record = read_record(line)?;
    let id = record.id;
    let fail = |message: String| LineFailure { id, message };
    let quadric = |name: &str, form: &Option<JsonForm<'_>>| match form {
        None => Err(fail(format!("missing field \"{name}\""))),
        Some(form) => surface_from_form(form).map_err(|e| fail(format!("{name}: {e}"))),
    };
    let a = quadric("A", &record.a)?;
    let b = quadric("B", &record.b)?;
    match catch_panic(|| work(a.quadric.as_ref(), b.quadric.as_ref(), [a.plane, b.plane])) {
        Ok(Ok(value)) => Ok((id, value)),
        Ok(Err(message)) => Err(fail(message)),
        Err(what) => Err(fail(format!("internal error (a bug): {what}"))),
    }
}

/// How a batch ended.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Summary {
    /// Input lines read, blank ones included.
    pub lines: u64,
    /// Output lines written.
    pub answered: u64,
    /// Output lines that are errors.
    pub failed: u64,
}

/// A batch stopped by an I/O error; the lines before it were answered.
#[derive(Debug)]
pub enum BatchError {
    /// Reading the input failed.
    Read(io::Error),
    /// Writing the output failed.
    Write(io::Error),
}

/// Classifies JSON Lines from `input` and writes one JSON line per non-blank input line
/// to `output`, in order, each as soon as it and every line before it are answered
/// ([`crate::stream`]); lines are answered on all cores, and no new line is read while
/// [`PENDING_LINES`] lines or [`PENDING_BYTES`] bytes wait to be written. With `progress`, a
/// spinner on stderr counts the lines done.
///
/// # Errors
/// [`BatchError`] if reading or writing fails; every line read before a read error is
/// answered, every answer before a write error written.
pub fn run<R: Read, W: Write + Send>(
    input: R,
    output: W,
    progress: bool,
) -> Result<Summary, BatchError> {
    run_with(input, output, progress, answer_line)
}

/// [`run`] for any [`Answer`] (`qsic param`, `qsic sample`): the same lines, order, errors.
///
/// # Errors
/// As [`run`].
pub fn run_answer<R: Read, W: Write + Send, A: Answer + ?Sized>(
    input: R,
    output: W,
    progress: bool,
    answer: &A,
    units: u64,
) -> Result<Summary, BatchError> {
    run_with(input, output, progress, |line: &RawLine| {
        answer_line_with(line, answer, units)
    })
}

/// [`run`] with another answer for each line (`qsic motion --batch`): `answer` gives the
/// output line (without newline) and whether it succeeded; a panic (a bug) becomes an
/// internal-error line in its place.
///
/// # Errors
/// As [`run`].
pub fn run_with<R: Read, W: Write + Send, F: Fn(&RawLine) -> (String, bool) + Sync>(
    input: R,
    output: W,
    progress: bool,
    answer: F,
) -> Result<Summary, BatchError> {
    let window = Window {
        lines: PENDING_LINES,
        bytes: PENDING_BYTES,
    };
    run_in_window(input, output, progress, window, answer)
}

/// [`run_with`] with another window of pending lines and bytes.
///
/// # Errors
/// As [`run`].
pub fn run_in_window<R: Read, W: Write + Send, F: Fn(&RawLine) -> (String, bool) + Sync>(
    input: R,
    output: W,
    progress: bool,
    window: Window,
    answer: F,
) -> Result<Summary, BatchError> {
    let bar = progress_bar(progress);
    let reader = LineReader::new(input, MAX_LINE_BYTES);
    let done = stream(reader, output, window, &bar, &answer);
    bar.finish_and_clear();
    if let Some(e) = done.write_error {
        return Err(BatchError::Write(e));
    }
    if let Some(e) = done.read_error {
        return Err(BatchError::Read(e));
    }
    Ok(Summary {
        lines: done.lines,
        answered: done.answered,
        failed: done.failed,
    })
}

pub(crate) fn progress_bar(visible: bool) -> ProgressBar {
    if !visible {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
    let style =
        ProgressStyle::with_template("{spinner} {human_pos} lines done ({per_sec}, {elapsed})")
            .unwrap_or_else(|_| ProgressStyle::default_spinner());
    bar.set_style(style);
    bar.enable_steady_tick(Duration::from_millis(120));
    bar
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text(number: u64, s: &str) -> RawLine {
        RawLine {
            number,
            content: Content::Text(s.as_bytes().to_vec()),
        }
    }

    fn run_on(input: &str) -> (Vec<Value>, Summary) {
        let mut out = Vec::new();
        let summary = run(input.as_bytes(), &mut out, false).expect("in-memory batch");
        let values = String::from_utf8(out)
            .expect("UTF-8 output")
            .lines()
            .map(|l| serde_json::from_str(l).expect("each output line is JSON"))
            .collect();
        (values, summary)
    }

    #[test]
    fn results_and_errors_keep_order_ids_and_line_numbers() {
        let input = concat!(
            r#"{"id": 123456789012345678901234567890, "A": "x^2+y^2+z^2-w^2", "B": "2*x^2+4*y^2-w^2"}"#,
            "\n   \n",
            "not json\n",
            r#"{"id": {"k": [1]}, "A": "x^2", "B": [[1,2,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}"#,
            "\n",
            r#"{"A": "0", "B": "0"}"#,
            "\n",
            r#"{"id": "s", "A": "0", "B": "x^2+y^2-z^2"}"#,
            "\n",
            r#"[1, 2]"#,
            "\n",
            r#"{"id": 7, "B": "x^2"}"#,
        );
        let (out, summary) = run_on(input);
        assert_eq!(
            summary,
            Summary {
                lines: 8,
                answered: 7,
                failed: 5
            }
        );
        assert_eq!(out.len(), 7);
        assert_eq!(out[0]["id"].to_string(), "123456789012345678901234567890");
        assert_eq!(out[0]["case"], 1);
        let errors = [
            (1, Value::Null, 3, "invalid JSON"),
            (
                2,
                serde_json::json!({"k": [1]}),
                4,
                "B: matrix is not symmetric",
            ),
            (3, Value::Null, 5, "both are zero"),
            (5, Value::Null, 7, "found an array"),
            (6, 7.into(), 8, "missing field \"A\""),
        ];
        for (i, id, line, needle) in errors {
            assert_eq!(out[i]["id"], id, "output {i}");
            assert_eq!(out[i]["error"]["line"], line, "output {i}");
            let message = out[i]["error"]["message"].as_str().expect("a message");
            assert!(message.contains(needle), "output {i}: {message}");
        }
        assert_eq!(out[4]["id"], "s");
        assert_eq!(out[4]["pencil"], "single");
    }

    #[test]
    fn output_lines_start_with_id_and_follow_schema_order() {
        let (_, _) = run_on("");
        let mut out = Vec::new();
        run(
            &br#"{"id":1,"A":"x^2+y^2-w^2","B":"x^2-y^2"}"#[..],
            &mut out,
            false,
        )
        .expect("batch");
        let line = String::from_utf8(out).expect("UTF-8");
        assert!(line.starts_with(r#"{"id":1,"pencil":"#), "{line}");
    }

    /// The answer the schema gives for a line, computed through a `Value` tree (the
    /// former implementation): the borrowed reader must give the same JSON.
    fn reference_answer(text: &str, number: u64) -> Value {
        use crate::input::{json_kind, quadric_from_json};
        let error = |id: Value, message: String| serde_json::json!({"id": id, "error": {"line": number, "message": message}});
        let object = match serde_json::from_str::<Value>(text) {
            Err(e) => return error(Value::Null, format!("invalid JSON: {e}")),
            Ok(Value::Object(o)) => o,
            Ok(other) => {
                return error(
                    Value::Null,
                    format!(
                        "expected a JSON object with fields \"A\" and \"B\", found {}",
                        json_kind(&other)
                    ),
                )
            }
        };
        if let Some(key) = first_repeated_field(text) {
            let id = match key.as_str() {
                "id" => Value::Null,
                _ => object.get("id").cloned().unwrap_or(Value::Null),
            };
            return error(id, format!("duplicate field \"{key}\""));
        }
        let id = object.get("id").cloned().unwrap_or(Value::Null);
        let read = |name: &str| match object.get(name) {
            None => Err(format!("missing field \"{name}\"")),
            Some(v) => quadric_from_json(v).map_err(|e| format!("{name}: {e}")),
        };
        let (a, b) = match (read("A"), read("B")) {
            (Err(e), _) | (_, Err(e)) => return error(id, e),
            (Ok(a), Ok(b)) => (a, b),
        };
        match classify_allowing_zero(a.as_ref(), b.as_ref()) {
            Err(e) => error(id, format!("A and B: both are zero: {e}")),
            Ok(c) => {
                let mut v = crate::output::classification_to_json(&c);
                if let Value::Object(o) = &mut v {
                    o.insert("id".into(), id);
                }
                v
            }
        }
    }

    /// `id` if it comes twice among the top-level keys of an object, else the first of `A`,
    /// `B` to, from the list of all its keys (not the line reader).
    fn first_repeated_field(text: &str) -> Option<String> {
        use serde::de::{Deserialize, Deserializer, IgnoredAny, MapAccess, Visitor};
        struct Keys(Vec<String>);
        impl<'de> Deserialize<'de> for Keys {
            fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                struct KeysVisitor;
                impl<'de> Visitor<'de> for KeysVisitor {
                    type Value = Keys;
                    fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                        f.write_str("an object")
                    }
                    fn visit_map<M: MapAccess<'de>>(self, mut map: M) -> Result<Keys, M::Error> {
                        let mut keys = Vec::new();
                        while let Some(key) = map.next_key::<String>()? {
                            map.next_value::<IgnoredAny>()?;
                            keys.push(key);
                        }
                        Ok(Keys(keys))
                    }
                }
                d.deserialize_map(KeysVisitor)
            }
        }
        let keys = serde_json::from_str::<Keys>(text).ok()?.0;
        if keys.iter().filter(|k| *k == "id").count() > 1 {
            return Some("id".to_string());
        }
        let mut seen = std::collections::HashSet::new();
        keys.into_iter()
            .find(|k| matches!(k.as_str(), "A" | "B") && !seen.insert(k.clone()))
    }

    #[test]
    fn duplicate_fields_are_error_lines_naming_the_field() {
        let sphere = "x^2+y^2+z^2-w^2";
        let cases = [
            (
                format!(r#"{{"id": 1, "A": "x^2", "A": "{sphere}", "B": "y^2"}}"#),
                "1",
                "A",
            ),
            (
                format!(
                    r#"{{"id": 1, "A": "{sphere}", "B": "y^2", "B": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]}}"#
                ),
                "1",
                "B",
            ),
            (
                format!(r#"{{"id": 1, "A": "{sphere}", "id": 2, "B": "y^2"}}"#),
                "null",
                "id",
            ),
            // escaped keys are the same keys (the serde_json route)
            (
                format!(r#"{{"\u0041": "x^2", "A": "{sphere}", "id": "e", "B": "y^2"}}"#),
                "\"e\"",
                "A",
            ),
            // the first field to come again is named, but a repeated id always (none is written)
            (
                format!(r#"{{"B": "y^2", "A": "{sphere}", "B": "y^2", "A": "x^2", "id": 3}}"#),
                "3",
                "B",
            ),
            (
                format!(r#"{{"A": "{sphere}", "A": "x^2", "id": 3, "B": "y^2", "id": 3}}"#),
                "null",
                "id",
            ),
        ];
        for (line, id, key) in &cases {
            let (answer, ok) = answer_line(&text(7, line));
            assert!(!ok, "{line}");
            let want = format!(
                r#"{{"id":{id},"error":{{"line":7,"message":"duplicate field \"{key}\""}}}}"#
            );
            assert_eq!(answer, want, "{line}");
        }
        // repeated fields that are not read are not checked, and nested keys are another object's
        for line in [
            format!(r#"{{"x": 1, "x": 2, "A": "{sphere}", "B": "y^2"}}"#),
            format!(r#"{{"extra": {{"A": 1, "A": 2}}, "A": "{sphere}", "B": "y^2"}}"#),
        ] {
            let (answer, ok) = answer_line(&text(1, &line));
            assert!(ok, "{line}: {answer}");
        }
    }

    #[test]
    fn borrowed_reader_answers_as_the_value_tree_did() {
        let identity = "[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,-1]]";
        let sphere = "x^2+y^2+z^2-w^2";
        let mut lines: Vec<String> = [
            format!(r#"{{"id": {{"k": [1, {{"z": 2, "a": null}}]}}, "A": "{sphere}", "B": "2*x^2+4*y^2-w^2"}}"#),
            format!(r#"{{"\u0069d": "esc\u0041ped", "\u0041": "x^2\u002by^2+z^2-w^2", "B": {identity}}}"#),
            format!(r#"{{"id": 1, "A": "x^2", "A": "{sphere}", "B": {identity}, "B": "x^2+2*y^2-w^2"}}"#),
            format!(r#"{{"id": 1, "B": {identity}, "A": "{sphere}", "id": [2], "x": 1, "x": 2}}"#),
            format!(r#"{{"\u0042": {identity}, "A": "{sphere}", "B": "x^2"}}"#),
            format!(r#"{{"id": 1, "A": "{sphere}", "A": "x^2", "B": "y^2"}} trailing"#),
            format!(r#"  {{"id": 1.50, "B": [[1E5,0,0,0],[0,-0.0,0,0],[0,0,"1/2",0],[0,0,0,"-1e-3"]], "A": "{sphere}", "extra": [1, {{"A": 3}}]}}"#),
            format!(r#"{{"id": 2, "A": [["1\u002f2",0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,-1]], "B": "{sphere}"}}"#),
            format!(r#"{{"id": 3, "A": [[1,0,0,0],[0,null,0,0],[0,0,1,0],[0,0,0,1]], "B": "{sphere}"}}"#),
            format!(r#"{{"id": 4, "A": [[1,0,0,0],[0,true,0,0],[0,0,[1],0],[0,0,0,{{}}]], "B": "{sphere}"}}"#),
            format!(r#"{{"id": 5, "A": [[1,0,0,0],3,[0,0,1,0],{{"a": 1}}], "B": "{sphere}"}}"#),
            format!(r#"{{"id": 6, "A": [[1,0,0,0],[0,1,0],[0,0,1,0,0],[0,0,0,1]], "B": "{sphere}"}}"#),
            format!(r#"{{"id": 7, "A": [[1,0,0,0],[0,1,0,0],[0,0,1,0]], "B": "{sphere}"}}"#),
            format!(r#"{{"id": 8, "A": [], "B": "{sphere}"}}"#),
            format!(r#"{{"id": 9, "A": 12, "B": "{sphere}"}}"#),
            format!(r#"{{"id": 10, "A": {{"x": 1}}, "B": "{sphere}"}}"#),
            format!(r#"{{"id": 11, "A": null, "B": "{sphere}"}}"#),
            format!(r#"{{"id": 12, "A": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1e99999]], "B": "{sphere}"}}"#),
            format!(r#"{{"id": 13, "A": [[1,2,0,0],[3,1,0,0],[0,0,1,0],[0,0,0,1]], "B": "{sphere}"}}"#),
            r#"{"id": 14, "A": "0", "B": [[0,0,0,0],[0,0,0,0],[0,0,0,0],[0,0,0,0]]}"#.to_string(),
            format!(r#"{{"id": 15, "A": "x^2 + q", "B": "{sphere}"}}"#),
            format!(r#"{{"id": 16, "A": [["123456789012345678901234567890",0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,-1]], "B": "{sphere}"}}"#),
            format!(r#"{{"id": 17, "A": "{sphere}"}}"#),
            format!(r#"{{"id": 18, "A": "{sphere}", "B": "x^2"}} trailing"#),
            format!(r#"{{"id": 19, "A": "{sphere}", "B": [[1,0,0,0]"#),
            format!(r#"{{"id": 20 "A": "{sphere}"}}"#),
            r#"{"id": "\ud83d\ude00", "A": "x^2", "B": "y^2"}"#.to_string(),
            r#"[1, 2]"#.to_string(),
            r#""text""#.to_string(),
            r#"12"#.to_string(),
            r#"null"#.to_string(),
            r#"not json"#.to_string(),
            r#"{}"#.to_string(),
            r#"{"id": [1, 2, 3]}"#.to_string(),
        ]
        .to_vec();
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../qsic/tests/data/cases.jsonl"
        );
        let corpus = std::fs::read_to_string(path).expect("the case corpus is readable");
        lines.extend(corpus.lines().step_by(7).map(str::to_string));
        for (k, text) in lines.iter().enumerate() {
            let number = k as u64 + 1;
            let raw = RawLine {
                number,
                content: Content::Text(text.as_bytes().to_vec()),
            };
            // the classification fields (the affine object is checked in tests/affine.rs)
            let (answer, ok) = answer_line_with(
                &raw,
                &Classify {
                    projective_only: true,
                    chart: None,
                },
                DEFAULT_LINE_BUDGET,
            );
            let got: Value = serde_json::from_str(&answer)
                .unwrap_or_else(|e| panic!("line {number}: output is not JSON ({e}): {answer}"));
            let want = reference_answer(text, number);
            assert_eq!(got, want, "line {number}: {text}");
            assert_eq!(ok, want.get("error").is_none(), "line {number}");
            assert!(answer.starts_with("{\"id\":"), "line {number}: {answer}");
        }
    }

    #[test]
    fn ids_are_copied_byte_for_byte() {
        let ids = [
            r#"{"z": 1,  "a": [1.50, "\u0041"]}"#,
            "123456789012345678901234567890.000e-7",
            r#""caf\u00e9 ☕""#,
            "null",
        ];
        for id in ids {
            for body in [
                r#""A": "x^2+y^2-w^2", "B": "x^2-y^2""#,
                r#""A": "x^2", "B": 7"#,
            ] {
                let line = RawLine {
                    number: 1,
                    content: Content::Text(format!("{{\"id\":  {id} , {body}}}").into_bytes()),
                };
                let (answer, _) = answer_line(&line);
                assert!(answer.starts_with(&format!("{{\"id\":{id},")), "{answer}");
            }
        }
    }

    #[test]
    fn invalid_utf8_is_an_error_line() {
        let line = RawLine {
            number: 9,
            content: Content::Text(b"{\"A\": \"x\xff\"}".to_vec()),
        };
        let (text, ok) = answer_line(&line);
        assert!(!ok);
        let v: Value = serde_json::from_str(&text).expect("JSON");
        assert_eq!(v["error"]["line"], 9);
        assert!(v["error"]["message"]
            .as_str()
            .is_some_and(|m| m.contains("UTF-8")));
    }
}
