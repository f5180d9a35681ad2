//! Presenting a [`Classification`]: the JSON object of the README (section "Command line and JSON schema") and the text report.
//!
//! | entry point | gives |
//! |---|---|
//! | [`ClassificationJson`] | the JSON result object, fields in schema order |
//! | [`classification_to_json`] | the same as a [`serde_json::Value`] |
//! | [`write_classification_fields`], [`write_json_string`] | the object's fields written straight into a string (batch lines) |
//! | [`human_report`] | the multi-line report of `qsic classify A B` |

use qsic::classify::{Component, SingularPointKind, SingularPoints};
use qsic::Classification;
use serde::Serialize;
use serde_json::Value;
use std::fmt::Write as _;

/// The JSON result object (schema in the README). Serializing it writes the fields in
/// declaration order; every field is always present, `null` where not determined.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct ClassificationJson {
    /// `regular`, `singular` or `single`.
    pub pencil: &'static str,
    /// Case 1–35 of Tu et al. (regular pencils).
    pub case: Option<u8>,
    /// Segre characteristic with the number of real roots, e.g. `[(11)11]_3`.
    pub segre: Option<&'static str>,
    /// Canonical signature sequence.
    pub signature: Option<&'static str>,
    /// Canonical index sequence.
    pub index_sequence: Option<&'static str>,
    /// Complex type key.
    pub complex_type: Option<&'static str>,
    /// Real type key.
    pub real_type: Option<&'static str>,
    /// Real components (empty when nothing is real or the class is undetermined).
    pub components: Vec<ComponentJson>,
    /// Real singular points.
    pub singular_points: Vec<SingularPointsJson>,
    /// One-line summary, `null` when undetermined.
    pub description: Option<&'static str>,
}

/// One entry of `components`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct ComponentJson {
    /// `point`, `line`, `conic`, `cubic`, `quartic`, `plane` or `quadric`.
    pub kind: &'static str,
    /// 1 for a simple component, 2 for a double one, ….
    pub multiplicity: u8,
    /// How many such components.
    pub count: u8,
    /// Affinely finite (`true`), never (`false`), or not fixed by the class (`null`).
    pub closed: Option<bool>,
}

/// One entry of `singular_points`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct SingularPointsJson {
    /// `acnode`, `crunode`, `cusp`, `tangency` or `multiple`.
    pub kind: &'static str,
    /// How many.
    pub count: u8,
}

impl From<&Component> for ComponentJson {
    fn from(c: &Component) -> Self {
        ComponentJson {
            kind: c.kind.key(),
            multiplicity: c.multiplicity,
            count: c.count,
            closed: c.closed,
        }
    }
}

impl From<&SingularPoints> for SingularPointsJson {
    fn from(p: &SingularPoints) -> Self {
        SingularPointsJson {
            kind: p.kind.key(),
            count: p.count,
        }
    }
}

impl From<&Classification> for ClassificationJson {
    fn from(c: &Classification) -> Self {
        let description = c.description.as_ref();
        ClassificationJson {
            pencil: c.pencil.key(),
            case: c.case,
            segre: c.segre,
            signature: c.signature,
            index_sequence: c.index_sequence,
            complex_type: c.complex_type(),
            real_type: c.real_type(),
            components: description
                .map(|d| d.components.iter().map(ComponentJson::from).collect())
                .unwrap_or_default(),
            singular_points: description
                .map(|d| {
                    d.singular_points
                        .iter()
                        .map(SingularPointsJson::from)
                        .collect()
                })
                .unwrap_or_default(),
            description: description.map(|d| d.summary),
        }
    }
}

/// The JSON result object of a classification (schema in the README), without `id`.
///
/// A [`Value`] keeps its keys sorted; to write them in schema order, serialize
/// [`ClassificationJson`] instead, as [`classification_to_json_line`] does.
pub fn classification_to_json(c: &Classification) -> Value {
    // Strings, small integers, booleans and null: serialization to a `Value` cannot fail.
    serde_json::to_value(ClassificationJson::from(c))
        .expect("a ClassificationJson holds only plain data")
}

/// The JSON result object as one line of text, keys in schema order.
pub fn classification_to_json_line(c: &Classification) -> String {
    let mut out = String::with_capacity(512);
    out.push('{');
    write_classification_fields(&mut out, c);
    out.push('}');
    out
}

/// Appends the fields of the JSON result object, in schema order and without the braces,
/// to `out`: the text `serde_json` writes for [`ClassificationJson`], without building it.
pub fn write_classification_fields(out: &mut String, c: &Classification) {
    out.push_str("\"pencil\":");
    write_json_string(out, c.pencil.key());
    out.push_str(",\"case\":");
    write_u8_or_null(out, c.case);
    out.push_str(",\"segre\":");
    write_str_or_null(out, c.segre);
    out.push_str(",\"signature\":");
    write_str_or_null(out, c.signature);
    out.push_str(",\"index_sequence\":");
    write_str_or_null(out, c.index_sequence);
    out.push_str(",\"complex_type\":");
    write_str_or_null(out, c.complex_type());
    out.push_str(",\"real_type\":");
    write_str_or_null(out, c.real_type());
    let description = c.description.as_ref();
    out.push_str(",\"components\":[");
    for (k, comp) in description
        .map_or(&[][..], |d| &d.components[..])
        .iter()
        .enumerate()
    {
        out.push_str(if k == 0 { "{\"kind\":" } else { ",{\"kind\":" });
        write_json_string(out, comp.kind.key());
        out.push_str(",\"multiplicity\":");
        write_u8_or_null(out, Some(comp.multiplicity));
        out.push_str(",\"count\":");
        write_u8_or_null(out, Some(comp.count));
        out.push_str(match comp.closed {
            Some(true) => ",\"closed\":true}",
            Some(false) => ",\"closed\":false}",
            None => ",\"closed\":null}",
        });
    }
    out.push_str("],\"singular_points\":[");
    for (k, p) in description
        .map_or(&[][..], |d| &d.singular_points[..])
        .iter()
        .enumerate()
    {
        out.push_str(if k == 0 { "{\"kind\":" } else { ",{\"kind\":" });
        write_json_string(out, p.kind.key());
        out.push_str(",\"count\":");
        write_u8_or_null(out, Some(p.count));
        out.push('}');
    }
    out.push_str("],\"description\":");
    write_str_or_null(out, description.map(|d| d.summary));
}

/// Whether `b` holds a byte that JSON escapes: `"`, `\\` or a control character below
/// 0x20. Eight bytes at a time: a word has a zero byte iff `(x − 0x01…01) & !x & 0x80…80`
/// is nonzero, and a byte below 0x20 iff that holds for `x − 0x20…20` in place of `x − 1`.
fn needs_escape(b: &[u8]) -> bool {
    const ONES: u64 = 0x0101_0101_0101_0101;
    const HIGH: u64 = 0x8080_8080_8080_8080;
    let mut chunks = b.chunks_exact(8);
    for chunk in &mut chunks {
        let mut word = [0u8; 8];
        word.copy_from_slice(chunk);
        let x = u64::from_le_bytes(word);
        let zero = |y: u64| y.wrapping_sub(ONES) & !y & HIGH;
        let control = x.wrapping_sub(ONES * 0x20) & !x & HIGH;
        if control | zero(x ^ (ONES * u64::from(b'"'))) | zero(x ^ (ONES * u64::from(b'\\'))) != 0 {
            return true;
        }
    }
    chunks
        .remainder()
        .iter()
        .any(|&c| c < 0x20 || c == b'"' || c == b'\\')
}

fn write_str_or_null(out: &mut String, value: Option<&str>) {
    match value {
        Some(s) => write_json_string(out, s),
        None => out.push_str("null"),
    }
}

fn write_u8_or_null(out: &mut String, value: Option<u8>) {
    let Some(v) = value else {
        out.push_str("null");
        return;
    };
    if v >= 100 {
        out.push(char::from(b'0' + v / 100));
    }
    if v >= 10 {
        out.push(char::from(b'0' + v / 10 % 10));
    }
    out.push(char::from(b'0' + v % 10));
}

/// Appends `s` as a JSON string, escaped as `serde_json` escapes it: `\"`, `\\`, the short
/// escapes `\b \f \n \r \t`, `\u00XX` for other control characters; the rest as is.
pub fn write_json_string(out: &mut String, s: &str) {
    if !needs_escape(s.as_bytes()) {
        out.reserve(s.len() + 2);
        out.push('"');
        out.push_str(s);
        out.push('"');
        return;
    }
    out.push('"');
    let mut plain = 0;
    for (i, b) in s.bytes().enumerate() {
        let escape = match b {
            b'"' => "\\\"",
            b'\\' => "\\\\",
            b'\n' => "\\n",
            b'\r' => "\\r",
            b'\t' => "\\t",
            0x08 => "\\b",
            0x0c => "\\f",
            0..=0x1f => "",
            _ => continue,
        };
        out.push_str(&s[plain..i]);
        plain = i + 1;
        if escape.is_empty() {
            const HEX: &[u8; 16] = b"0123456789abcdef";
            out.push_str("\\u00");
            out.push(char::from(HEX[usize::from(b >> 4)]));
            out.push(char::from(HEX[usize::from(b & 15)]));
        } else {
            out.push_str(escape);
        }
    }
    out.push_str(&s[plain..]);
    out.push('"');
}

/// English name of a component family: `conic`, `double line`, `4-fold line`.
fn component_name(c: &Component) -> String {
    let prefix = match c.multiplicity {
        1 => String::new(),
        2 => "double ".into(),
        3 => "triple ".into(),
        4 => "quadruple ".into(),
        m => format!("{m}-fold "),
    };
    let kind = match c.kind.key() {
        "quartic" => "quartic branch",
        other => other,
    };
    let closed = match c.closed {
        Some(true) => " (closed)",
        Some(false) => " (affinely infinite)",
        None => "",
    };
    format!("{} × {prefix}{kind}{closed}", c.count)
}

/// `2 crunodes`, `1 cusp`, `2 tangencies`, `1 multiple point`.
fn singular_points_name(p: &SingularPoints) -> String {
    let (one, many) = match p.kind {
        SingularPointKind::Acnode => ("acnode", "acnodes"),
        SingularPointKind::Crunode => ("crunode", "crunodes"),
        SingularPointKind::Cusp => ("cusp", "cusps"),
        SingularPointKind::Tangency => ("tangency", "tangencies"),
        SingularPointKind::Multiple => ("multiple point", "multiple points"),
    };
    format!("{} {}", p.count, if p.count == 1 { one } else { many })
}

/// The text report of `qsic classify A B` with the affine view: the pair in ℝ³ first
/// ([`crate::affine::affine_report`]), then the projective class ([`human_report`]) under a
/// heading; the projective class alone without the view (`--projective`).
pub fn classify_report(
    c: &Classification,
    view: Option<&qsic::affine::AffineView>,
    chart_text: &str,
) -> String {
    match view {
        Some(view) => format!(
            "{}projective class (the curve in RP^3, over C and over R):\n{}",
            crate::affine::affine_report(view, chart_text),
            human_report(c)
        ),
        None => human_report(c),
    }
}

/// Width of the label column of [`human_report`].
const LABEL_WIDTH: usize = 18;

/// The text report of `qsic classify A B`: one `label: value` line per field
/// (`-` where not defined), then the real components and singular points.
pub fn human_report(c: &Classification) -> String {
    let dash = |v: Option<&str>| v.unwrap_or("-").to_string();
    let rows = [
        ("pencil", c.pencil.key().to_string()),
        ("case", c.case.map_or("-".into(), |n| n.to_string())),
        ("Segre", dash(c.segre)),
        ("signature", dash(c.signature)),
        ("index sequence", dash(c.index_sequence)),
        ("complex type", dash(c.complex_type())),
        ("real type", dash(c.real_type())),
        (
            "summary",
            c.description
                .as_ref()
                .map_or("not determined".into(), |d| d.summary.to_string()),
        ),
    ];
    let mut out = String::new();
    for (label, value) in rows {
        // Writing to a String cannot fail.
        let _ = writeln!(out, "{:<LABEL_WIDTH$}{value}", format!("{label}:"));
    }
    let Some(d) = c.description.as_ref() else {
        return out;
    };
    if d.components.is_empty() {
        let _ = writeln!(out, "{:<LABEL_WIDTH$}none real", "components:");
    } else {
        out.push_str("components:\n");
        for comp in &d.components {
            let _ = writeln!(out, "  {}", component_name(comp));
        }
    }
    let points: Vec<String> = d.singular_points.iter().map(singular_points_name).collect();
    let points = if points.is_empty() {
        "none".to_string()
    } else {
        points.join(", ")
    };
    let _ = writeln!(out, "{:<LABEL_WIDTH$}{points}", "singular points:");
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use qsic::io::parse_quadric;

    fn classify(a: &str, b: &str) -> Classification {
        let a = parse_quadric(a).expect("test quadric");
        let b = parse_quadric(b).expect("test quadric");
        qsic::classify(&a, &b)
    }

    const KEYS: [&str; 10] = [
        "pencil",
        "case",
        "segre",
        "signature",
        "index_sequence",
        "complex_type",
        "real_type",
        "components",
        "singular_points",
        "description",
    ];

    #[test]
    fn case_1_representative_to_json() {
        let c = classify("x^2+y^2+z^2-w^2", "2*x^2+4*y^2-w^2");
        let v = classification_to_json(&c);
        assert_eq!(v["pencil"], "regular");
        assert_eq!(v["case"], 1);
        assert_eq!(v["segre"], "[1111]_4");
        assert_eq!(v["index_sequence"], "<1|2|1|2|3>");
        assert_eq!(v["complex_type"], "smooth_quartic");
        assert_eq!(v["real_type"], "two_finite_components");
        let components = v["components"].as_array().expect("an array");
        assert!(!components.is_empty());
        for comp in components {
            let keys: Vec<&str> = comp
                .as_object()
                .expect("object")
                .keys()
                .map(String::as_str)
                .collect();
            assert_eq!(keys, ["closed", "count", "kind", "multiplicity"]);
        }
        assert!(v["description"].is_string());
    }

    #[test]
    fn every_key_is_present_and_in_schema_order() {
        let c = classify("x^2+y^2+z^2-w^2", "x^2+y^2+z^2-w^2");
        let text = serde_json::to_string(&ClassificationJson::from(&c)).expect("serializes");
        let positions: Vec<usize> = KEYS
            .iter()
            .map(|k| text.find(&format!("\"{k}\":")).unwrap_or(usize::MAX))
            .collect();
        assert!(positions.windows(2).all(|w| w[0] < w[1]), "{text}");
        let v = classification_to_json(&c);
        assert_eq!(v.as_object().expect("object").len(), KEYS.len());
        assert_eq!(v["pencil"], "single");
        assert_eq!(v["case"], Value::Null);
        assert_eq!(v["complex_type"], "smooth_quadric");
    }

    /// The hand-written JSON must be byte for byte what serde_json writes, on every class.
    #[test]
    fn written_fields_equal_serde_on_every_corpus_class() {
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../qsic/tests/data/cases.jsonl"
        );
        let text = std::fs::read_to_string(path).expect("the case corpus is readable");
        let mut classes = vec![
            classify("x^2+y^2+z^2-w^2", "x^2+y^2+z^2-w^2"),
            classify("x*y", "x*z"),
            classify("x^2", "y^2"),
        ];
        for line in text.lines() {
            let v: Value = serde_json::from_str(line).expect("corpus JSON");
            let read = |k: &str| {
                crate::input::quadric_from_json(&v[k])
                    .expect("corpus quadric")
                    .expect("nonzero")
            };
            classes.push(qsic::classify(&read("A"), &read("B")));
        }
        for c in &classes {
            let serde = serde_json::to_string(&ClassificationJson::from(c)).expect("serializes");
            assert_eq!(classification_to_json_line(c), serde);
        }
    }

    #[test]
    fn json_strings_are_escaped_as_serde_does() {
        let mut samples: Vec<String> = [
            "",
            "plain",
            "a\"b\\c",
            "tab\tnew\nline\r",
            "\u{1}\u{8}\u{c}\u{1f}\u{7f}",
            "é ∞ 😀",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect();
        samples.push((0u8..128).map(char::from).collect());
        // Each special byte at every place of a word, among plain and non-ASCII bytes.
        for special in ['"', '\\', '\u{0}', '\u{1f}', '\n'] {
            for at in 0..17 {
                let mut s: Vec<char> = "abcdefgh é∞xyz~ ".chars().collect();
                s.insert(at, special);
                samples.push(s.into_iter().collect());
            }
        }
        for s in &samples {
            let plain = !s.bytes().any(|c| c < 0x20 || c == b'"' || c == b'\\');
            assert_eq!(needs_escape(s.as_bytes()), !plain, "{s:?}");
            let mut out = String::new();
            write_json_string(&mut out, s);
            assert_eq!(out, serde_json::to_string(s).expect("serializes"), "{s:?}");
        }
    }

    #[test]
    fn singular_pencil_has_nulls_where_undetermined() {
        // Two forms without w: every member is singular at (0:0:0:1), so det ≡ 0.
        let c = classify("x*y", "x*z");
        let v = classification_to_json(&c);
        assert_eq!(v["pencil"], "singular");
        assert_eq!(v["case"], Value::Null);
        assert_eq!(v["segre"], Value::Null);
        assert_eq!(v.as_object().expect("object").len(), KEYS.len());
    }

    #[test]
    fn human_names() {
        use qsic::classify::ComponentKind;
        let conics = Component {
            kind: ComponentKind::Conic,
            multiplicity: 1,
            count: 2,
            closed: Some(true),
        };
        assert_eq!(component_name(&conics), "2 × conic (closed)");
        let double = Component {
            kind: ComponentKind::Line,
            multiplicity: 2,
            count: 1,
            closed: None,
        };
        assert_eq!(component_name(&double), "1 × double line");
        let crunodes = SingularPoints {
            kind: SingularPointKind::Crunode,
            count: 2,
        };
        assert_eq!(singular_points_name(&crunodes), "2 crunodes");
        let report = human_report(&classify("x^2+y^2+z^2-w^2", "2*x^2+4*y^2-w^2"));
        assert!(report.contains("case:             1\n"), "{report}");
        assert!(
            report.contains("real type:        two_finite_components\n"),
            "{report}"
        );
    }
}
