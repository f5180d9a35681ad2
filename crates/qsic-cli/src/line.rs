//! The fields of one batch line, borrowed from its text: `id` as written, `A` and `B`.
//!
//! [`read_line`] first tries [`scan_plain`], a strict reader of the common shape of a line
//! (an object whose keys are plain strings, `id` and other fields plain scalars, `A` and `B`
//! polynomial strings or 4×4 arrays of plain strings and numbers), which costs a few
//! instructions per byte; anything else, and every error, goes to `serde_json` (a borrowing
//! deserializer, no `Value` tree). Where the scanner answers, the line is valid JSON and the
//! answer is the one `serde_json` gives (tests).

use crate::input::JsonForm;
use serde::de::{self, Deserialize, Deserializer, IgnoredAny, MapAccess, Visitor};
use serde_json::value::RawValue;
use std::fmt;

/// The fields a batch line is read for. Other fields are skipped (repeated or not); a field
/// read that comes twice is noted in `repeated` (the values are then the last ones), and a
/// batch answers such a line with an error.
#[derive(Debug)]
pub struct Line<'a> {
    /// The `id` value exactly as written, if present.
    pub id: Option<&'a str>,
    /// The `A` value.
    pub a: Option<JsonForm<'a>>,
    /// The `B` value.
    pub b: Option<JsonForm<'a>>,
    /// `id` if it comes a second time, else the first of `A`, `B` to, if one does.
    pub repeated: Option<&'static str>,
}

impl Line<'_> {
    fn empty() -> Self {
        Line {
            id: None,
            a: None,
            b: None,
            repeated: None,
        }
    }
}

/// `*slot = Some(value)`; if the slot held a value already, `name` is noted in `repeated`
/// unless an earlier field was — except that `id` is always noted: a line whose id comes
/// twice has no id to copy into its error line.
fn store<T>(
    slot: &mut Option<T>,
    value: T,
    repeated: &mut Option<&'static str>,
    name: &'static str,
) {
    if slot.replace(value).is_some() && (repeated.is_none() || name == "id") {
        *repeated = Some(name);
    }
}

/// Reads a line that starts (after whitespace) with `{`.
///
/// # Errors
/// The `serde_json` error if the text is not valid JSON or not an object.
pub fn read_line(text: &str) -> Result<Line<'_>, serde_json::Error> {
    match scan_plain(text) {
        Some(line) => Ok(line),
        None => serde_json::from_str(text),
    }
}

/// A key of a batch line.
enum Field {
    Id,
    A,
    B,
    Other,
}

impl Field {
    fn of(name: &str) -> Field {
        match name {
            "id" => Field::Id,
            "A" => Field::A,
            "B" => Field::B,
            _ => Field::Other,
        }
    }
}

impl<'de> Deserialize<'de> for Field {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct FieldVisitor;
        impl Visitor<'_> for FieldVisitor {
            type Value = Field;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a field name")
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Field, E> {
                Ok(Field::of(v))
            }
        }
        deserializer.deserialize_identifier(FieldVisitor)
    }
}

impl<'de> Deserialize<'de> for Line<'de> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct LineVisitor;
        impl<'de> Visitor<'de> for LineVisitor {
            type Value = Line<'de>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a JSON object")
            }
            fn visit_map<M: MapAccess<'de>>(self, mut map: M) -> Result<Line<'de>, M::Error> {
                let mut line = Line::empty();
                while let Some(field) = map.next_key::<Field>()? {
                    match field {
                        Field::Id => {
                            let id = map.next_value::<&RawValue>()?.get();
                            store(&mut line.id, id, &mut line.repeated, "id");
                        }
                        Field::A => store(&mut line.a, map.next_value()?, &mut line.repeated, "A"),
                        Field::B => store(&mut line.b, map.next_value()?, &mut line.repeated, "B"),
                        Field::Other => {
                            map.next_value::<IgnoredAny>()?;
                        }
                    }
                }
                Ok(line)
            }
        }
        deserializer.deserialize_map(LineVisitor)
    }
}

/// A cursor over the bytes of a line for [`scan_plain`]; every method answers `None` when
/// the text is not of the plain shape.
struct Scanner<'a> {
    text: &'a str,
    pos: usize,
}

impl<'a> Scanner<'a> {
    fn peek(&self) -> Option<u8> {
        self.text.as_bytes().get(self.pos).copied()
    }

    /// Skips JSON whitespace.
    fn skip(&mut self) {
        let b = self.text.as_bytes();
        while matches!(b.get(self.pos), Some(b' ' | b'\t' | b'\n' | b'\r')) {
            self.pos += 1;
        }
    }

    /// Skips whitespace, then expects `c`.
    fn expect(&mut self, c: u8) -> Option<()> {
        self.skip();
        (self.peek()? == c).then(|| self.pos += 1)
    }

    /// A string without escapes or control characters at the cursor: its content.
    fn plain_string(&mut self) -> Option<&'a str> {
        let b = self.text.as_bytes();
        if b.get(self.pos) != Some(&b'"') {
            return None;
        }
        let start = self.pos + 1;
        let len = b[start..]
            .iter()
            .position(|&c| c == b'"' || c == b'\\' || c < 0x20)?;
        let end = start + len;
        if b[end] != b'"' {
            return None;
        }
        self.pos = end + 1;
        // The quotes are ASCII, so both ends are character boundaries.
        self.text.get(start..end)
    }

    /// A JSON number at the cursor (`-? (0 | [1-9][0-9]*) (. [0-9]+)? ([eE] [+-]? [0-9]+)?`):
    /// its text.
    fn number(&mut self) -> Option<&'a str> {
        let b = self.text.as_bytes();
        let start = self.pos;
        let mut i = start;
        let digits = |i: &mut usize| {
            let from = *i;
            while b.get(*i).is_some_and(u8::is_ascii_digit) {
                *i += 1;
            }
            *i > from
        };
        if b.get(i) == Some(&b'-') {
            i += 1;
        }
        match b.get(i)? {
            b'0' => i += 1,
            b'1'..=b'9' => {
                digits(&mut i);
            }
            _ => return None,
        }
        if b.get(i) == Some(&b'.') {
            i += 1;
            if !digits(&mut i) {
                return None;
            }
        }
        if matches!(b.get(i), Some(b'e' | b'E')) {
            i += 1;
            if matches!(b.get(i), Some(b'+' | b'-')) {
                i += 1;
            }
            if !digits(&mut i) {
                return None;
            }
        }
        self.pos = i;
        self.text.get(start..i)
    }

    /// A plain scalar (string without escapes, number, `true`, `false`, `null`): its text
    /// as written.
    fn scalar(&mut self) -> Option<&'a str> {
        let start = self.pos;
        match self.peek()? {
            b'"' => {
                self.plain_string()?;
            }
            b'-' | b'0'..=b'9' => {
                self.number()?;
            }
            _ => {
                let rest = &self.text[start..];
                let word = ["true", "false", "null"]
                    .into_iter()
                    .find(|w| rest.starts_with(w))?;
                self.pos += word.len();
            }
        }
        self.text.get(start..self.pos)
    }

    /// A plain string or a 4×4 array of plain strings and numbers.
    fn form(&mut self) -> Option<JsonForm<'a>> {
        if self.peek()? == b'"' {
            return Some(JsonForm::Text(self.plain_string()?.into()));
        }
        let b = self.text.as_bytes();
        let skip = |i: &mut usize| {
            while matches!(b.get(*i), Some(b' ' | b'\t' | b'\n' | b'\r')) {
                *i += 1;
            }
        };
        let mut i = self.pos;
        if b.get(i) != Some(&b'[') {
            return None;
        }
        i += 1;
        let mut m = [[""; 4]; 4];
        for (r, row) in m.iter_mut().enumerate() {
            skip(&mut i);
            if b.get(i) != Some(&b'[') {
                return None;
            }
            i += 1;
            for (c, entry) in row.iter_mut().enumerate() {
                skip(&mut i);
                if b.get(i) == Some(&b'"') {
                    let start = i + 1;
                    i = start;
                    loop {
                        match *b.get(i)? {
                            b'"' => break,
                            b'\\' | 0..=0x1f => return None,
                            _ => i += 1,
                        }
                    }
                    *entry = self.text.get(start..i)?;
                    i += 1;
                } else {
                    self.pos = i;
                    *entry = self.number()?;
                    i = self.pos;
                }
                skip(&mut i);
                if b.get(i) != Some(if c == 3 { &b']' } else { &b',' }) {
                    return None;
                }
                i += 1;
            }
            skip(&mut i);
            if b.get(i) != Some(if r == 3 { &b']' } else { &b',' }) {
                return None;
            }
            i += 1;
        }
        self.pos = i;
        Some(JsonForm::Array4(m))
    }
}

/// Reads a line of the plain shape, or `None`. The plain shape is a JSON object whose
/// keys are strings without escapes, whose `A` and `B` are strings without escapes or 4×4
/// arrays of such strings and numbers, and whose other values are such strings, numbers,
/// `true`, `false` or `null`; whitespace anywhere JSON allows it.
pub fn scan_plain(text: &str) -> Option<Line<'_>> {
    let mut s = Scanner { text, pos: 0 };
    let mut line = Line::empty();
    s.expect(b'{')?;
    s.skip();
    if s.peek()? == b'}' {
        s.pos += 1;
    } else {
        loop {
            s.skip();
            let key = s.plain_string()?;
            s.expect(b':')?;
            s.skip();
            match Field::of(key) {
                Field::Id => store(&mut line.id, s.scalar()?, &mut line.repeated, "id"),
                Field::A => store(&mut line.a, s.form()?, &mut line.repeated, "A"),
                Field::B => store(&mut line.b, s.form()?, &mut line.repeated, "B"),
                Field::Other => {
                    s.scalar()?;
                }
            }
            s.skip();
            match s.peek()? {
                b',' => s.pos += 1,
                b'}' => {
                    s.pos += 1;
                    break;
                }
                _ => return None,
            }
        }
    }
    s.skip();
    (s.pos == text.len()).then_some(line)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::quadric_from_form;
    use proptest::prelude::*;

    /// What a line reads to, comparable: the id, the quadric (or error) of A and B, and the
    /// field repeated.
    fn summary(line: &Line<'_>) -> (Option<String>, [String; 2], Option<&'static str>) {
        let form = |f: &Option<JsonForm<'_>>| match f {
            None => "missing".to_string(),
            Some(f) => format!("{:?}", quadric_from_form(f).map_err(|e| e.to_string())),
        };
        (
            line.id.map(str::to_string),
            [form(&line.a), form(&line.b)],
            line.repeated,
        )
    }

    /// Where the scanner answers, `serde_json` must read the same line the same way.
    fn assert_scanner_agrees(text: &str) -> bool {
        let Some(fast) = scan_plain(text) else {
            return false;
        };
        let slow: Line<'_> = serde_json::from_str(text)
            .unwrap_or_else(|e| panic!("scanned, but serde_json refuses {text:?}: {e}"));
        assert_eq!(summary(&fast), summary(&slow), "{text:?}");
        true
    }

    #[test]
    fn scanner_reads_plain_lines_and_declines_the_rest() {
        let m = r#"[["1", "-3/2", 0, 2.5e-1], ["-3/2", 2, "0", 0], [0, "0", "x", 0], [2.5e-1, 0, 0, -1]]"#;
        let plain = [
            format!(r#"{{"id": 1, "A": {m}, "B": "x^2 - y^2"}}"#),
            format!(r#"  {{ "B" :"x^2","A":{m} , "id":"s", "other": null, "t": true }}  "#),
            format!(r#"{{"A": "x^2", "A": {m}, "B": "y^2", "id": -0.5E+3}}"#),
            r#"{"id": "é ∞", "A": "x^2", "B": "y^2"}"#.to_string(),
            r#"{}"#.to_string(),
            r#"{"id": 1}"#.to_string(),
            r#"{"id": 1, "id": 2, "A": "x^2", "A": "y^2", "B": "z^2"}"#.to_string(),
        ];
        for text in &plain {
            assert!(assert_scanner_agrees(text), "{text:?} should be scanned");
        }
        let repeated = |text: &str| scan_plain(text).and_then(|line| line.repeated);
        assert_eq!(repeated(&plain[2]), Some("A"));
        assert_eq!(repeated(&plain[6]), Some("id"));
        assert_eq!(repeated(&plain[0]), None);
        assert_eq!(
            repeated(r#"{"x": 1, "x": 2, "B": "y^2", "A": "x^2"}"#),
            None
        );
        let declined = [
            r#"{"id": {"k": 1}, "A": "x^2", "B": "y^2"}"#,
            r#"{"id": [1], "A": "x^2", "B": "y^2"}"#,
            r#"{"i\u0064": 1, "A": "x^2", "B": "y^2"}"#,
            r#"{"id": 1, "A": "x^2\n", "B": "y^2"}"#,
            r#"{"id": 01, "A": "x^2", "B": "y^2"}"#,
            r#"{"id": 1., "A": "x^2", "B": "y^2"}"#,
            r#"{"id": 1, "A": [[1,0,0,0],[0,1,0,0],[0,0,1,0]], "B": "y^2"}"#,
            r#"{"id": 1, "A": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1,5]], "B": "y^2"}"#,
            r#"{"id": 1, "A": [[1,0,0,0],[0,null,0,0],[0,0,1,0],[0,0,0,1]], "B": "y^2"}"#,
            r#"{"id": 1, "A": "x^2", "B": "y^2",}"#,
            r#"{"id": 1, "A": "x^2", "B": "y^2"} x"#,
            r#"{"id": nul, "A": "x^2", "B": "y^2"}"#,
            r#"{"id": 1 "A": "x^2"}"#,
            r#"{"id": 1, "A": "x^2", "B": "y^2""#,
            "{\"id\": 1, \"A\": \"x^2\u{1}\", \"B\": \"y^2\"}",
            r#"[1, 2]"#,
        ];
        for text in declined {
            assert!(!assert_scanner_agrees(text), "{text:?} should be declined");
        }
    }

    fn plain_value() -> impl Strategy<Value = String> {
        prop_oneof![
            Just("null".to_string()),
            Just("true".to_string()),
            "-?(0|[1-9][0-9]{0,25})(\\.[0-9]{1,3})?([eE][+-]?[0-9]{1,2})?",
            "\"[a-z0-9/ .é-]{0,6}\"",
        ]
    }

    fn entry() -> impl Strategy<Value = String> {
        prop_oneof![
            "-?(0|[1-9][0-9]{0,3})(\\.[0-9]{1,2})?([eE]-?[0-9])?",
            "\"-?[0-9]{1,2}(/[0-9])?\"",
        ]
    }

    fn form() -> impl Strategy<Value = String> {
        prop_oneof![
            Just("\"x^2 + 2*y^2 - w^2\"".to_string()),
            prop::collection::vec(prop::collection::vec(entry(), 4), 4).prop_map(|rows| {
                let rows: Vec<String> =
                    rows.iter().map(|r| format!("[{}]", r.join(", "))).collect();
                format!("[{}]", rows.join(","))
            }),
        ]
    }

    proptest! {
        #[test]
        fn scanner_agrees_with_serde_json(
            id in plain_value(),
            a in form(),
            b in form(),
            extra in plain_value(),
            order in 0usize..5,
            repeat in 0usize..6,
            cut in any::<prop::sample::Index>(),
            insert in prop_oneof![Just(""), Just(" "), Just(","), Just("\""), Just("\\"), Just("]"), Just("0"), Just("{")],
        ) {
            let fields = [format!("\"id\": {id}"), format!("\"A\": {a}"), format!("\"B\": {b}"), format!("\"x\": {extra}")];
            let mut parts = fields.to_vec();
            // a second id, A or B (half the time): the scanner notes it as serde_json does
            if repeat < 3 {
                parts.push(fields[repeat].clone());
            }
            let n = parts.len();
            parts.rotate_left(order % n);
            let text = format!("{{{}}}", parts.join(", "));
            prop_assert!(assert_scanner_agrees(&text), "{} should be scanned", text);
            // The same line with one character inserted: the scanner agrees or declines.
            let at = cut.index(text.len() + 1);
            if text.is_char_boundary(at) {
                let mutated = format!("{}{insert}{}", &text[..at], &text[at..]);
                assert_scanner_agrees(&mutated);
            }
        }
    }
}
