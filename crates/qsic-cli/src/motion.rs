//! `qsic motion`: two moving quadrics `A(t)`, `B(t)`, the instants where their intersection
//! changes type and the type between them ([`qsic::motion::MovingPencil`]), as a text
//! timeline or as the JSON object of the README.
//!
//! | entry point | does |
//! |---|---|
//! | [`TimeRange::parse`] | `--range T0 T1` (the library's, shared with `qsic contact`): exact rationals, `-oo`/`oo` for an open side |
//! | [`moving_from_arg`], [`moving_from_form`] | a moving quadric from an argument or a batch field |
//! | [`analyze`], [`analyze_within`] | the variations of the pair on the range (spending a work budget) |
//! | [`motion_to_json_line`], [`write_motion_fields`] | the JSON result (keys `instants`, `intervals`) |
//! | [`human_timeline`] | the text timeline of `qsic motion A B` |
//! | [`answer_motion_line`] | one batch line to one output line, within the line's work budget |
//!
//! An instant `t` is written `"p/q"` when rational, otherwise
//! `{"poly": "t^2 - 2", "interval": ["7/5", "3/2"], "approx": "1.4142135623730951"}`: a
//! square-free integer polynomial and an interval with rational ends isolating its root.

use crate::batch::{answer_with, catch_panic, open_record, read_record, LineFailure, RawLine};
use crate::input::JsonForm;
use crate::output::write_json_string;
pub use crate::rigid::{moving_from_arg, moving_from_form};
use qsic::io::MovingMatrix;
pub use qsic::motion::TimeRange;
use qsic::motion::{Motion, MovingPencil, MINUS_INFINITY, PLUS_INFINITY};
use qsic::{Budget, Classification, Error};
use qsic_algebra::AlgebraicReal;
use std::fmt::Write as _;

/// The variations of the pencil of `a` and `b` on `range`.
///
/// # Errors
/// As [`MovingPencil::new`] and [`MovingPencil::variations_in`].
pub fn analyze(a: MovingMatrix, b: MovingMatrix, range: &TimeRange) -> Result<Motion, Error> {
    analyze_within(a, b, range, &Budget::unlimited())
}

/// [`analyze`] spending `budget` ([`MovingPencil::variations_within`]).
///
/// # Errors
/// As [`analyze`]; [`Error::BudgetExceeded`] when the budget runs out.
pub fn analyze_within(
    a: MovingMatrix,
    b: MovingMatrix,
    range: &TimeRange,
    budget: &Budget,
) -> Result<Motion, Error> {
    MovingPencil::new_within(a, b, budget)?.variations_within(range.from(), range.to(), budget)
}

/// Appends an instant as JSON: `"p/q"`, or `{"poly", "interval", "approx"}`.
fn write_instant(out: &mut String, t: &AlgebraicReal) {
    if let Some(v) = t.as_rational() {
        write_json_string(out, &v.to_string());
        return;
    }
    let approx = t.to_f64();
    out.push_str("{\"poly\":");
    write_json_string(out, &poly_in_t(t));
    let iv = t.interval();
    out.push_str(",\"interval\":[");
    write_json_string(out, &iv.lo().to_string());
    out.push(',');
    write_json_string(out, &iv.hi().to_string());
    out.push_str("],\"approx\":");
    write_json_string(out, &approx.to_string());
    out.push('}');
}

/// The defining polynomial of an instant, written in `t`.
fn poly_in_t(t: &AlgebraicReal) -> String {
    // `Poly` writes its variable as `x`; the coefficients are integers.
    t.poly().to_string().replace('x', "t")
}

/// Appends `"pencil","case","complex_type","real_type"` (all `null` if unclassified).
fn write_type(out: &mut String, c: Option<&Classification>) {
    let text = |out: &mut String, v: Option<&str>| match v {
        Some(s) => write_json_string(out, s),
        None => out.push_str("null"),
    };
    out.push_str("\"pencil\":");
    text(out, c.map(|c| c.pencil.key()));
    out.push_str(",\"case\":");
    match c.and_then(|c| c.case) {
        Some(k) => out.push_str(&k.to_string()),
        None => out.push_str("null"),
    }
    out.push_str(",\"complex_type\":");
    text(out, c.and_then(Classification::complex_type));
    out.push_str(",\"real_type\":");
    text(out, c.and_then(Classification::real_type));
}

/// Appends the fields `"instants":[…],"intervals":[…]` of the JSON result (README), without
/// braces: instants `{"t", "pencil", "case", "complex_type", "real_type"}`, intervals
/// `{"from", "to", "sample_t", "pencil", "case", "complex_type", "real_type"}` with `null`
/// ends for `∓∞`.
pub fn write_motion_fields(out: &mut String, m: &Motion) {
    out.push_str("\"instants\":[");
    for (k, i) in m.instants.iter().enumerate() {
        if k > 0 {
            out.push(',');
        }
        out.push_str("{\"t\":");
        write_instant(out, &i.t);
        out.push(',');
        write_type(out, i.class.classification());
        out.push('}');
    }
    out.push_str("],\"intervals\":[");
    for (k, v) in m.intervals.iter().enumerate() {
        if k > 0 {
            out.push(',');
        }
        for (key, end) in [("{\"from\":", &v.from), (",\"to\":", &v.to)] {
            out.push_str(key);
            match end {
                Some(t) => write_instant(out, t),
                None => out.push_str("null"),
            }
        }
        out.push_str(",\"sample_t\":");
        write_json_string(out, &v.sample.to_string());
        out.push(',');
        write_type(out, Some(&v.classification));
        out.push('}');
    }
    out.push(']');
}

/// The JSON result of a single query, one line: `{"instants": […], "intervals": […]}`.
pub fn motion_to_json_line(m: &Motion) -> String {
    let mut out = String::with_capacity(1024);
    out.push('{');
    write_motion_fields(&mut out, m);
    out.push('}');
    out
}

/// An instant for people: `t = 2/3`, or `t ≈ 1.4142135623730951 (root of t^2 - 2 in
/// [7/5, 3/2])`.
fn instant_text(t: &AlgebraicReal) -> String {
    match t.as_rational() {
        Some(v) => format!("t = {v}"),
        None => {
            let approx = t.to_f64();
            let iv = t.interval();
            format!(
                "t ≈ {approx} (root of {} in [{}, {}])",
                poly_in_t(t),
                iv.lo(),
                iv.hi()
            )
        }
    }
}

/// A type for people: `regular, case 24 [2(11)]_2 <1~~-1||3>: conic_and_two_lines_not_crossing
/// / conic_and_point — a real conic and …`.
fn type_text(c: Option<&Classification>) -> String {
    let Some(c) = c else {
        return "not classified (a singular pencil at an irrational instant)".into();
    };
    let mut s = c.pencil.key().to_string();
    if let Some(k) = c.case {
        let _ = write!(s, ", case {k}");
    }
    for part in [c.segre, c.index_sequence].into_iter().flatten() {
        let _ = write!(s, " {part}");
    }
    let _ = write!(
        s,
        ": {} / {}",
        c.complex_type().unwrap_or("?"),
        c.real_type().unwrap_or("?")
    );
    if let Some(d) = &c.description {
        let _ = write!(s, " — {}", d.summary);
    }
    s
}

/// The text timeline of `qsic motion A B`: the intervals and the instants between them in
/// increasing `t`, each with its type.
pub fn human_timeline(m: &Motion) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{} instant(s) where the type changes, {} interval(s):",
        m.instants.len(),
        m.intervals.len()
    );
    let end = |t: &Option<AlgebraicReal>, infinity: &str| match t {
        None => infinity.to_string(),
        Some(t) => match t.as_rational() {
            Some(v) => v.to_string(),
            None => format!("{:.12}", t.to_f64()),
        },
    };
    // The instants before the first interval (the start of a range), then each interval
    // followed by the instants up to the next one.
    let mut next = 0;
    let mut instants_up_to = |out: &mut String, limit: Option<&AlgebraicReal>| {
        while let Some(i) = m.instants.get(next) {
            if limit.is_some_and(|l| i.t > *l) {
                break;
            }
            let _ = writeln!(
                out,
                "  {}: {}",
                instant_text(&i.t),
                type_text(i.class.classification())
            );
            next += 1;
        }
    };
    for v in &m.intervals {
        if let Some(from) = &v.from {
            instants_up_to(&mut out, Some(from));
        }
        let _ = writeln!(
            out,
            "  t in ({}, {}), sample t = {}: {}",
            end(&v.from, MINUS_INFINITY),
            end(&v.to, PLUS_INFINITY),
            v.sample,
            type_text(Some(&v.classification))
        );
    }
    instants_up_to(&mut out, None);
    out
}

/// The output line for one line of `qsic motion --batch` and whether it succeeded: `{"id",
/// "instants", "intervals"}` or the error record of the batch conventions; the line may
/// spend `units` work units (over them: the budget's error record).
pub fn answer_motion_line(line: &RawLine, range: &TimeRange, units: u64) -> (String, bool) {
    answer_with(line, |line| motion_line(line, range, units))
}

fn motion_line<'a>(
    line: &'a RawLine,
    range: &TimeRange,
    units: u64,
) -> Result<String, LineFailure<'a>> {
    moving_pair_line(
        line,
        "motion",
        |a, b| analyze_within(a, b, range, &Budget::new(units)),
        write_motion_fields,
    )
}

/// One batch line of a moving pair (`qsic motion`, `qsic contact`): the record read, its
/// `"A"` and `"B"` as moving matrices, `analyze` run on them (a panic caught and named as a
/// bug of the `what` analysis), and the answer's fields written by `write` after the id.
pub(crate) fn moving_pair_line<'a, T>(
    line: &'a RawLine,
    what: &str,
    analyze: impl FnOnce(MovingMatrix, MovingMatrix) -> Result<T, Error>,
    write: impl FnOnce(&mut String, &T),
) -> Result<String, LineFailure<'a>> {
    let record = read_record(line)?;
    let id = record.id;
    let fail = |message: String| LineFailure { id, message };
    let read = |name: &str, form: &Option<JsonForm<'_>>| match form {
        None => Err(fail(format!("missing field \"{name}\""))),
        Some(form) => moving_from_form(form).map_err(|e| fail(format!("{name}: {e}"))),
    };
    let a = read("A", &record.a)?;
    let b = read("B", &record.b)?;
    let answer = match catch_panic(|| analyze(a, b)) {
        Ok(Ok(m)) => m,
        Ok(Err(e)) => return Err(fail(format!("A and B: {e}"))),
        Err(cause) => {
            return Err(fail(format!(
                "internal error in the {what} analysis (a bug): {cause}"
            )))
        }
    };
    let mut out = open_record(id);
    write(&mut out, &answer);
    out.push('}');
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use qsic::io::parse_number;

    #[test]
    fn json_fields_follow_the_schema() {
        let a = moving_from_arg("x^2 + y^2 + z^2 - 2").expect("a moving quadric");
        let b = moving_from_arg("[[1,0,0,\"-t\"],[0,1,0,0],[0,0,1,0],[\"-t\",0,0,\"t^2-1\"]]")
            .expect("a JSON matrix");
        let m = analyze(a, b, &TimeRange::default()).expect("analyzed");
        let v: serde_json::Value = serde_json::from_str(&motion_to_json_line(&m)).expect("JSON");
        let instants = v["instants"].as_array().expect("instants");
        let intervals = v["intervals"].as_array().expect("intervals");
        assert_eq!(intervals.len(), instants.len() + 1);
        assert!(intervals[0]["from"].is_null() && intervals.last().unwrap()["to"].is_null());
        for (k, i) in instants.iter().enumerate() {
            // each instant is the end of the interval before it and the start of the next
            assert_eq!(i["t"], intervals[k]["to"]);
            assert_eq!(i["t"], intervals[k + 1]["from"]);
            if let Some(obj) = i["t"].as_object() {
                let approx: f64 = obj["approx"].as_str().unwrap().parse().unwrap();
                let x = i["t"]["interval"][0].as_str().unwrap();
                let lo = parse_number(x).unwrap().to_f64().value();
                assert!(lo <= approx, "{i}");
                assert!(obj["poly"].as_str().unwrap().contains('t'));
            }
            for key in ["pencil", "case", "complex_type", "real_type"] {
                assert!(i.get(key).is_some(), "{key}");
            }
        }
        // ±(√2 ± 1) and 0: irrational instants, classified
        assert_eq!(instants.len(), 5);
        assert!(instants.iter().all(|i| i["pencil"] == "regular"));
        assert_eq!(instants.iter().filter(|i| i["t"].is_object()).count(), 4);
        let text = human_timeline(&m);
        assert_eq!(text.lines().count(), 1 + 5 + 6, "{text}");
        assert!(text.contains("t ≈ 2.414213562"), "{text}");
    }
}
