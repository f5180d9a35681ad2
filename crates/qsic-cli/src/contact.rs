//! `qsic contact A B`: the first contact of two moving quadrics and, where both are solid
//! ellipsoids, the relation of the solids along the motion in the range, as JSON or text.
//!
//! JSON (one object, keys in this order):
//! `{"range": [from|null, to|null], "first_contact": null | "-oo" | instant,
//! "contact": null | {"t": instant, "at_start": bool, "locus": "points" | "same_quadric" |
//! "not_computed", "curves": n | null, "points": [{"kind", "point": [x, y, z, w], "approx":
//! [x, y, z] | null}], "numbers": [{"name", "poly", "interval", "approx"}], "note": null |
//! "..."}, "solids": null | {"first_meeting": null | "-oo" | instant | {"error": "..."},
//! "intervals": [{"from", "to", "sample_t", "relation", "inner", "note"}],
//! "instants": [{"t", "relation", "inner", "note"}]}}` with an instant `"p/q"` or
//! `{"poly": "t^2 - 8", "interval": ["a", "b"], "approx": "-2.828…"}`, `from`/`to` null for
//! `∓∞`; `relation` a [`SolidRelation`](qsic::solids::SolidRelation) key, `not_ellipsoids`
//! or `undetermined`; `inner` `"A"`/`"B"` for `inside` and `touching_internally`.
//! `contact` gives the common real points at the first contact (null for none or `"-oo"`):
//! `kind` `isolated` (at a touching from an empty intersection, every point) or a singular
//! point's kind; `point` exact homogeneous coordinates (`w = 1` for an affine point) as in
//! `qsic param`, algebraic numbers of degree > 2 named `a1`, … under `numbers`; `curves` the
//! number of real curve pieces (0 at a touching; more when they already meet, `at_start`).
//! `solids` covers the range only ([`solid_motion_in`]), and is null when the two are never
//! both solid ellipsoids there. With `--first-only` the object stops after `first_contact`
//! ([`report_within`]).
//!
//! The moving quadrics are read as by `qsic motion` ([`crate::motion::moving_from_arg`]),
//! and the range too ([`TimeRange::parse`]). [`contact_within`] spends a work budget
//! (`--line-budget`); [`answer_contact_line`] answers one line of `qsic contact --batch`
//! (`{"id", "A", "B"}` in, `{"id", "range", …}` or the error record out).

use crate::batch::{answer_with, LineFailure, RawLine};
use crate::output::write_json_string;
use qsic::io::MovingMatrix;
use qsic::motion::contact::{
    contact_points_within, first_contact_of, solid_motion_in_within, CommonLocus, ContactPoints,
    FirstContact, SolidMotion, SolidState, TimeRange,
};
use qsic::motion::{MovingPencil, MINUS_INFINITY, PLUS_INFINITY};
use qsic::param::expr::Names;
use qsic::{Budget, Error};
use qsic_algebra::{AlgebraicReal, RBig};
use std::fmt::Write as _;

/// What `qsic contact` reports.
#[derive(Clone, Debug)]
pub struct ContactReport {
    /// The range of `t` searched for the first contact.
    pub range: TimeRange,
    /// The first `t` with a real common point (real projective space).
    pub first_contact: Option<FirstContact>,
    /// The common points there (`None` without a first instant).
    pub contact: Option<ContactPoints>,
    /// The relation of the solids along the range; `None` if they are never both solid
    /// ellipsoids there.
    pub solids: Option<SolidMotion>,
    /// The affine first contact in the range (solids no longer separated), or why not.
    pub first_meeting: Option<Result<Option<FirstContact>, Error>>,
    /// Only the first contact was asked ([`report_within`]): no points, no
    /// solids, and the report says so by leaving them out.
    pub first_only: bool,
}

/// First contact in `range` and the relation of the solids on it.
///
/// # Errors
/// As [`qsic::motion::contact::first_contact`] and
/// [`qsic::motion::contact::solid_motion_in`].
pub fn contact(a: MovingMatrix, b: MovingMatrix, range: TimeRange) -> Result<ContactReport, Error> {
    contact_within(a, b, range, &Budget::unlimited())
}

/// [`contact`] spending `budget` on the motion, the contact points and the solids.
///
/// # Errors
/// As [`contact`]; [`Error::BudgetExceeded`] when the budget runs out.
pub fn contact_within(
    a: MovingMatrix,
    b: MovingMatrix,
    range: TimeRange,
    budget: &Budget,
) -> Result<ContactReport, Error> {
    report_within(a, b, range, budget, false)
}

/// [`contact_within`], or with `first_only` the first contact alone (`qsic contact
/// --first-only`): the instant, without the common points there and the solids' timeline —
/// the call for a loop over many pairs and steps.
///
/// # Errors
/// As [`contact_within`].
pub fn report_within(
    a: MovingMatrix,
    b: MovingMatrix,
    range: TimeRange,
    budget: &Budget,
    first_only: bool,
) -> Result<ContactReport, Error> {
    let pencil = MovingPencil::new_within(a, b, budget)?;
    let first = first_contact_of(&pencil, &range, budget)?;
    if first_only {
        return Ok(ContactReport {
            range,
            first_contact: first,
            contact: None,
            solids: None,
            first_meeting: None,
            first_only,
        });
    }
    let contact = match &first {
        Some(f) => contact_points_within(&pencil, f, &range, budget)?,
        None => None,
    };
    let solids = solid_motion_in_within(&pencil, &range, budget)?;
    let any_relation = solids
        .intervals
        .iter()
        .map(|i| &i.state)
        .chain(solids.instants.iter().map(|i| &i.state))
        .any(|s| s.relation().is_some());
    let (solids, first_meeting) = if any_relation {
        let meeting = solids.first_meeting(&range);
        (Some(solids), Some(meeting))
    } else {
        (None, None)
    };
    Ok(ContactReport {
        range,
        first_contact: first,
        contact,
        solids,
        first_meeting,
        first_only,
    })
}

fn rational(v: &RBig) -> String {
    v.to_string()
}

/// Appends an instant as JSON: `"p/q"` or `{"poly", "interval", "approx"}`.
pub fn write_instant(out: &mut String, t: &AlgebraicReal) {
    if let Some(v) = t.as_rational() {
        write_json_string(out, &rational(v));
        return;
    }
    let iv = t.refined_interval(&RBig::from_parts(1u8.into(), (1u64 << 40).into()));
    out.push_str("{\"poly\":");
    write_json_string(out, &t.poly().to_string().replace('x', "t"));
    out.push_str(",\"interval\":[");
    write_json_string(out, &rational(iv.lo()));
    out.push(',');
    write_json_string(out, &rational(iv.hi()));
    out.push_str("],\"approx\":");
    write_json_string(out, &format!("{:.15}", t.to_f64()));
    out.push('}');
}

/// Appends `null`, an instant, or `-oo`.
fn write_contact(out: &mut String, c: &Option<FirstContact>) {
    match c {
        None => out.push_str("null"),
        Some(FirstContact::FromMinusInfinity) => write_json_string(out, MINUS_INFINITY),
        Some(FirstContact::At(t)) => write_instant(out, t),
    }
}

/// Appends an instant or `null` (an open end).
fn write_end(out: &mut String, t: Option<&AlgebraicReal>) {
    match t {
        Some(t) => write_instant(out, t),
        None => out.push_str("null"),
    }
}

/// Appends `,"relation":…,"inner":…,"note":…`.
fn write_state(out: &mut String, s: &SolidState) {
    out.push_str(",\"relation\":");
    write_json_string(out, s.key());
    out.push_str(",\"inner\":");
    match s.relation().and_then(|r| r.inner()) {
        Some(i) => write_json_string(out, i.key()),
        None => out.push_str("null"),
    }
    out.push_str(",\"note\":");
    match s {
        SolidState::NotEllipsoids(why) => write_json_string(out, why),
        _ => out.push_str("null"),
    }
}

/// Appends the `"solids"` object (module docs).
fn write_solids(
    out: &mut String,
    m: &SolidMotion,
    meeting: &Option<Result<Option<FirstContact>, Error>>,
) {
    out.push_str("{\"first_meeting\":");
    match meeting {
        Some(Ok(c)) => write_contact(out, c),
        Some(Err(e)) => {
            out.push_str("{\"error\":");
            write_json_string(out, &e.to_string());
            out.push('}');
        }
        None => out.push_str("null"),
    }
    out.push_str(",\"intervals\":[");
    for (k, i) in m.intervals.iter().enumerate() {
        if k > 0 {
            out.push(',');
        }
        out.push_str("{\"from\":");
        write_end(out, i.from.as_ref());
        out.push_str(",\"to\":");
        write_end(out, i.to.as_ref());
        out.push_str(",\"sample_t\":");
        write_json_string(out, &rational(&i.sample));
        write_state(out, &i.state);
        out.push('}');
    }
    out.push_str("],\"instants\":[");
    for (k, i) in m.instants.iter().enumerate() {
        if k > 0 {
            out.push(',');
        }
        out.push_str("{\"t\":");
        write_instant(out, &i.t);
        write_state(out, &i.state);
        out.push('}');
    }
    out.push_str("]}");
}

/// Appends the `"contact"` object (module docs).
fn write_contact_points(out: &mut String, c: &ContactPoints) {
    let mut names = Names::new();
    out.push_str("{\"t\":");
    write_instant(out, &c.t);
    out.push_str(",\"at_start\":");
    out.push_str(if c.at_start { "true" } else { "false" });
    let (locus, curves, note) = match &c.locus {
        CommonLocus::Points { curves, .. } => ("points", Some(*curves), None),
        CommonLocus::SameQuadric => ("same_quadric", None, None),
        CommonLocus::NotComputed(why) => ("not_computed", None, Some(why.as_str())),
    };
    out.push_str(",\"locus\":");
    write_json_string(out, locus);
    out.push_str(",\"curves\":");
    match curves {
        Some(n) => out.push_str(&n.to_string()),
        None => out.push_str("null"),
    }
    out.push_str(",\"points\":[");
    if let CommonLocus::Points { points, .. } = &c.locus {
        for (k, p) in points.iter().enumerate() {
            if k > 0 {
                out.push(',');
            }
            out.push_str("{\"kind\":");
            write_json_string(out, p.kind.key());
            out.push_str(",\"point\":[");
            for (i, x) in p.point.iter().enumerate() {
                if i > 0 {
                    out.push(',');
                }
                write_json_string(out, &names.number(x));
            }
            out.push_str("],\"approx\":");
            match p.approx() {
                Some(x) => {
                    let x = x.map(|v| format!("{v:.15}"));
                    out.push('[');
                    out.push_str(&x.join(","));
                    out.push(']');
                }
                None => out.push_str("null"),
            }
            out.push('}');
        }
    }
    out.push_str("],\"numbers\":[");
    for (k, n) in names.numbers().into_iter().enumerate() {
        if k > 0 {
            out.push(',');
        }
        out.push_str("{\"name\":");
        write_json_string(out, &n.name);
        out.push_str(",\"poly\":");
        write_json_string(out, &n.poly);
        out.push_str(",\"interval\":[");
        write_json_string(out, &n.interval[0]);
        out.push(',');
        write_json_string(out, &n.interval[1]);
        out.push_str("],\"approx\":");
        out.push_str(&format!("{:.15}", n.approx));
        out.push('}');
    }
    out.push_str("],\"note\":");
    match note {
        Some(n) => write_json_string(out, n),
        None => out.push_str("null"),
    }
    out.push('}');
}

/// The report as one JSON object on one line, keys in the documented order (module docs).
pub fn report_to_json_line(r: &ContactReport) -> String {
    let mut out = String::with_capacity(1024);
    out.push('{');
    write_report_fields(&mut out, r);
    out.push('}');
    out
}

/// The output line for one line of `qsic contact --batch` and whether it succeeded:
/// `{"id", "range", "first_contact", "contact", "solids"}` or the error record of the
/// batch conventions; the line may spend `units` work units.
/// With `first_only`, `{"id", "range", "first_contact"}`.
pub fn answer_contact_line(
    line: &RawLine,
    range: &TimeRange,
    units: u64,
    first_only: bool,
) -> (String, bool) {
    answer_with(line, |line| contact_line(line, range, units, first_only))
}

fn contact_line<'a>(
    line: &'a RawLine,
    range: &TimeRange,
    units: u64,
    first_only: bool,
) -> Result<String, LineFailure<'a>> {
    crate::motion::moving_pair_line(
        line,
        "contact",
        |a, b| report_within(a, b, range.clone(), &Budget::new(units), first_only),
        write_report_fields,
    )
}

/// Appends the report's fields `"range":…,"first_contact":…,"contact":…,"solids":…`,
/// without braces.
fn write_report_fields(out: &mut String, r: &ContactReport) {
    out.push_str("\"range\":[");
    for (k, end) in [r.range.from(), r.range.to()].into_iter().enumerate() {
        if k > 0 {
            out.push(',');
        }
        match end {
            Some(v) => write_json_string(out, &rational(v)),
            None => out.push_str("null"),
        }
    }
    out.push_str("],\"first_contact\":");
    write_contact(out, &r.first_contact);
    if r.first_only {
        return;
    }
    out.push_str(",\"contact\":");
    match &r.contact {
        Some(c) => write_contact_points(out, c),
        None => out.push_str("null"),
    }
    out.push_str(",\"solids\":");
    match &r.solids {
        Some(m) => write_solids(out, m, &r.first_meeting),
        None => out.push_str("null"),
    }
}

fn instant_text(t: &AlgebraicReal) -> String {
    match t.as_rational() {
        Some(v) => rational(v),
        None => format!(
            "root of {} ≈ {:.12}",
            t.poly().to_string().replace('x', "t"),
            t.to_f64()
        ),
    }
}

fn contact_text(c: &Option<FirstContact>, none: &str) -> String {
    match c {
        None => none.to_string(),
        Some(FirstContact::FromMinusInfinity) => format!("from t = {MINUS_INFINITY}"),
        Some(FirstContact::At(t)) => format!("t = {}", instant_text(t)),
    }
}

fn state_text(s: &SolidState) -> String {
    match s {
        SolidState::Relation(r) => match r.inner() {
            Some(i) => format!("{} ({} inside the other)", r.key(), i.key()),
            None => r.key().to_string(),
        },
        SolidState::NotEllipsoids(why) => format!("not ellipsoids: {why}"),
        SolidState::Undetermined => "undetermined (irrational instant)".to_string(),
    }
}

/// The common points at the first contact, for people: one line each, exact and decimal.
fn contact_points_text(c: &ContactPoints) -> String {
    let mut s = String::new();
    if c.at_start {
        let _ = writeln!(s, "  they already meet at the start of the range");
    }
    let mut names = Names::new();
    match &c.locus {
        CommonLocus::SameQuadric => {
            let _ = writeln!(
                s,
                "  the quadrics are the same there: every point is common"
            );
        }
        CommonLocus::NotComputed(why) => {
            let _ = writeln!(s, "  common points not computed: {why}");
        }
        CommonLocus::Points { points, curves } => {
            if *curves > 0 {
                let _ = writeln!(s, "  {curves} real curve piece(s) in common");
            }
            for p in points {
                let exact: Vec<String> = p.point.iter().map(|x| names.number(x)).collect();
                let approx = match p.approx() {
                    Some(x) => format!("≈ ({:.12}, {:.12}, {:.12})", x[0], x[1], x[2]),
                    None => "at infinity".to_string(),
                };
                let _ = writeln!(
                    s,
                    "  {} point ({}) {approx}",
                    p.kind.key(),
                    exact.join(", ")
                );
            }
            for n in names.numbers() {
                let _ = writeln!(
                    s,
                    "    {} = root of {} in [{}, {}] ≈ {:.12}",
                    n.name, n.poly, n.interval[0], n.interval[1], n.approx
                );
            }
        }
    }
    s
}

/// The text report: first contact, then the timeline of the solids in the range.
pub fn human_report(r: &ContactReport) -> String {
    let end = |v: Option<&RBig>, inf: &str| v.map_or(inf.to_string(), rational);
    let mut s = String::new();
    let _ = writeln!(
        s,
        "range: [{}, {}]",
        end(r.range.from(), MINUS_INFINITY),
        end(r.range.to(), PLUS_INFINITY)
    );
    let _ = writeln!(
        s,
        "first contact (real common point): {}",
        contact_text(&r.first_contact, "none in the range")
    );
    if r.first_only {
        return s;
    }
    if let Some(c) = &r.contact {
        s.push_str(&contact_points_text(c));
    }
    let Some(m) = &r.solids else {
        let _ = writeln!(s, "solids: not both solid ellipsoids at any t in the range");
        return s;
    };
    match &r.first_meeting {
        Some(Ok(c)) => {
            let _ = writeln!(
                s,
                "first contact of the solids: {}",
                contact_text(c, "none in the range")
            );
        }
        Some(Err(e)) => {
            let _ = writeln!(s, "first contact of the solids: not decided ({e})");
        }
        None => {}
    }
    let _ = writeln!(s, "solids along the motion:");
    let t_or =
        |t: &Option<AlgebraicReal>, inf: &str| t.as_ref().map_or(inf.to_string(), instant_text);
    // The instants up to each interval's start (the range's start first), then the interval;
    // then the instants after the last one.
    let mut next = 0;
    let mut instants_up_to = |s: &mut String, limit: Option<&AlgebraicReal>| {
        while let Some(i) = m.instants.get(next) {
            if limit.is_some_and(|l| i.t > *l) {
                break;
            }
            let _ = writeln!(s, "  t = {}: {}", instant_text(&i.t), state_text(&i.state));
            next += 1;
        }
    };
    for i in &m.intervals {
        if let Some(from) = &i.from {
            instants_up_to(&mut s, Some(from));
        }
        let _ = writeln!(
            s,
            "  ({}, {}): {}",
            t_or(&i.from, MINUS_INFINITY),
            t_or(&i.to, PLUS_INFINITY),
            state_text(&i.state)
        );
    }
    instants_up_to(&mut s, None);
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::motion::moving_from_arg;
    use qsic::io::parse_number;
    use serde_json::{json, Value};

    fn report_to_json(r: &ContactReport) -> Value {
        serde_json::from_str(&report_to_json_line(r)).expect("one JSON object")
    }

    /// The report of the sphere through a sphere, as JSON: every instant and relation.
    #[test]
    fn spheres_report() {
        let a = moving_from_arg("x^2 + y^2 + z^2 - 4").unwrap();
        let rows =
            r#"[["1","0","0","-t"],["0","1","0","0"],["0","0","1","0"],["-t","0","0","t^2-1"]]"#;
        let b = moving_from_arg(rows).unwrap();
        assert_eq!(b, moving_from_arg("(x - t)^2 + y^2 + z^2 - 1").unwrap());
        let r = contact(a, b, TimeRange::all()).unwrap();
        let v = report_to_json(&r);
        assert_eq!(v["first_contact"], "-3");
        assert_eq!(v["range"], json!([null, null]));
        let solids = &v["solids"];
        assert_eq!(solids["first_meeting"], "-3");
        let rel: Vec<&str> = solids["instants"]
            .as_array()
            .unwrap()
            .iter()
            .map(|i| i["relation"].as_str().unwrap())
            .collect();
        assert_eq!(
            rel,
            [
                "touching_externally",
                "touching_internally",
                "touching_internally",
                "touching_externally"
            ]
        );
        assert_eq!(solids["instants"][1]["inner"], "B");
        assert_eq!(solids["intervals"][2]["relation"], "inside");
        assert_eq!(solids["intervals"][0]["from"], Value::Null);
        let text = human_report(&r);
        assert!(
            text.contains("first contact (real common point): t = -3"),
            "{text}"
        );
        assert!(
            text.contains("(-1, 1): inside (B inside the other)"),
            "{text}"
        );
    }

    /// An irrational instant is written with its polynomial, an interval holding it and a
    /// decimal; ranges read `-inf`.
    #[test]
    fn irrational_instant_and_ranges() {
        let a = moving_from_arg("x^2 + y^2 + z^2 - 4").unwrap();
        let b = moving_from_arg("(x - t)^2 + (y - 1)^2 + z^2 - 1").unwrap();
        let range = TimeRange::parse("-inf", "10").unwrap();
        let v = report_to_json(&contact(a, b, range).unwrap());
        let t = &v["first_contact"];
        assert_eq!(t["poly"], "t^2 - 8");
        let approx: f64 = t["approx"].as_str().unwrap().parse().unwrap();
        assert!((approx + 8f64.sqrt()).abs() < 1e-12);
        let lo = parse_number(t["interval"][0].as_str().unwrap()).unwrap();
        let hi = parse_number(t["interval"][1].as_str().unwrap()).unwrap();
        assert!(lo < hi && &lo * &lo > RBig::from(8) && &hi * &hi < RBig::from(8));
        assert_eq!(v["range"], json!([null, "10"]));
        assert!(TimeRange::parse("1/0", "1").is_err());
    }

    /// Cylinders are not solids: the first contact only, `solids` null.
    #[test]
    fn non_solids_report_first_contact_only() {
        let a = moving_from_arg("x^2 + y^2 - 1").unwrap();
        let b = moving_from_arg("(x - t)^2 + z^2 - 1").unwrap();
        let r = contact(a, b, TimeRange::all()).unwrap();
        let v = report_to_json(&r);
        assert_eq!(v["solids"], Value::Null);
        // perpendicular unit cylinders, axes at distance |t|: they meet from t = −2
        assert_eq!(v["first_contact"], "-2");
        assert!(human_report(&r).contains("not both solid ellipsoids"));
    }
}
