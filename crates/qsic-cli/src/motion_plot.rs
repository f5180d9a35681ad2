//! `qsic motion --plot out.svg`: the timeline of a [`Motion`] as a hand-written SVG.
//!
//! | entry point | does |
//! |---|---|
//! | [`motion_to_svg`] | the whole picture: `t` axis, one coloured band per interval, one tick per instant, legend |
//! | [`motion_with_snapshots_to_svg`] | the timeline and, below, the real curve at the sample `t` of each interval (`qsic motion --plot`) |
//! | [`plot_window`] | the drawn window of `t` (the range, or all instants with margins when unbounded) |
//!
//! Floating point appears only here, for positions on the page: every instant is labelled
//! with its exact value (`p/q`), or with a decimal marked *algebraic* whose exact
//! polynomial and isolating interval are in the element's `<title>` (a tooltip). Colours
//! map to the types `(pencil, case, complex_type, real_type)` of the intervals through the
//! legend; an unbounded side is an arrow labelled `−∞` / `+∞`. Labels that would overlap
//! are staggered into rows.

use crate::motion::TimeRange;
use crate::svg::{colour, document, push_escaped, push_text, Panel};
use qsic::io::MovingMatrix;
use qsic::motion::{Motion, MotionType};
use qsic::Classification;
use qsic_algebra::AlgebraicReal;
use std::fmt::Write as _;

/// Page width in pixels.
const WIDTH: f64 = 1000.0;
/// Left and right margins of the axis.
const SIDE: f64 = 60.0;
/// Height of one label row.
const ROW: f64 = 30.0;
/// Height of the interval bands.
const BAND: f64 = 36.0;
/// Approximate width of one character of the 12 px labels.
const CHAR: f64 = 7.0;

/// The window `[lo, hi]` of `t` drawn for `m` on `range`: the range itself when both ends
/// are finite (widened by 1 on each side when it is a single point); otherwise the span of
/// the finite ends and instants, widened by a quarter of it (at least 1) on each open side.
pub fn plot_window(m: &Motion, range: &TimeRange) -> (f64, f64) {
    let from = range.from().map(|r| r.to_f64().value());
    let to = range.to().map(|r| r.to_f64().value());
    if let (Some(a), Some(b)) = (from, to) {
        return if a < b { (a, b) } else { (a - 1.0, b + 1.0) };
    }
    let points: Vec<f64> = from
        .into_iter()
        .chain(to)
        .chain(m.instants.iter().map(|i| i.t.to_f64()))
        .filter(|x| x.is_finite())
        .collect();
    let lo = points.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = points.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let (lo, hi) = if points.is_empty() {
        (0.0, 0.0)
    } else {
        (lo, hi)
    };
    let margin = ((hi - lo) / 4.0).max(1.0);
    (from.unwrap_or(lo - margin), to.unwrap_or(hi + margin))
}

/// A short type label: `case 24: conic_and_point`, `singular: …`, or `not classified`.
fn type_label(c: Option<&Classification>) -> String {
    let Some(c) = c else {
        return "not classified".into();
    };
    let head = match c.case {
        Some(k) => format!("case {k}"),
        None => c.pencil.key().to_string(),
    };
    format!("{head}: {}", c.real_type().unwrap_or("?"))
}

/// The legend line of a type: pencil, case, complex and real type.
fn legend_label(t: &MotionType) -> String {
    let mut s = t.pencil.to_string();
    if let Some(k) = t.case {
        let _ = write!(s, ", case {k}");
    }
    let _ = write!(
        s,
        ": {} / {}",
        t.complex_type.unwrap_or("?"),
        t.real_type.unwrap_or("?")
    );
    s
}

/// The value label of an instant: `t = p/q`, or `t ≈ 1.414214 (algebraic)`.
fn value_label(t: &AlgebraicReal) -> String {
    match t.as_rational() {
        Some(v) => format!("t = {v}"),
        None => format!("t ≈ {:.6} (algebraic)", t.to_f64()),
    }
}

/// The exact description of an instant for its tooltip.
fn exact_title(t: &AlgebraicReal) -> String {
    match t.as_rational() {
        Some(v) => format!("t = {v}"),
        None => {
            let iv = t.interval();
            format!(
                "t = the root of {} in [{}, {}]",
                t.poly().to_string().replace('x', "t"),
                iv.lo(),
                iv.hi()
            )
        }
    }
}

/// Greedy row assignment: each label (left, right), in the given order, goes to the first
/// row whose last label ends at least 8 px before it starts. Returns the row of each label.
fn stagger(spans: &[(f64, f64)]) -> Vec<usize> {
    let mut ends: Vec<f64> = Vec::new();
    spans
        .iter()
        .map(|&(l, r)| {
            let row = ends
                .iter()
                .position(|&e| e + 8.0 <= l)
                .unwrap_or(ends.len());
            if row == ends.len() {
                ends.push(r);
            } else {
                ends[row] = r;
            }
            row
        })
        .collect()
}

/// A centred label of `chars` characters at `x`, kept inside the page: its (left, right).
fn span_at(x: f64, chars: usize) -> (f64, f64) {
    let w = chars as f64 * CHAR;
    let left = (x - w / 2.0).clamp(4.0, (WIDTH - 4.0 - w).max(4.0));
    (left, left + w)
}

/// The SVG picture of the motion `m` analysed on `range`: a horizontal `t` axis over
/// [`plot_window`], one `<rect class="band">` per interval coloured by its type with its
/// label (`case k: real_type`) in a staggered row above, one `<line class="tick">` per
/// instant with its exact value and type in staggered rows below, arrows and `±∞` at open
/// sides, and a legend of the colours. Every text is XML-escaped.
///
/// # Examples
/// ```
/// use qsic::io::moving_matrix_from_polynomial as q;
/// use qsic_cli::motion::{analyze, TimeRange};
/// use qsic_cli::motion_plot::motion_to_svg;
/// let m = analyze(q("x^2+y^2+z^2-4").unwrap(), q("(x-t)^2+y^2+z^2-1").unwrap(),
///     &TimeRange::default()).unwrap();
/// let svg = motion_to_svg(&m, &TimeRange::default());
/// assert_eq!(svg.matches("<rect class=\"band\"").count(), m.intervals.len());
/// assert_eq!(svg.matches("<line class=\"tick\"").count(), m.instants.len());
/// assert!(svg.contains("t = -3") && svg.contains("+∞"));
/// ```
pub fn motion_to_svg(m: &Motion, range: &TimeRange) -> String {
    document(&[timeline_panel(m, range)])
}

/// The timeline panel of [`motion_to_svg`].
fn timeline_panel(m: &Motion, range: &TimeRange) -> Panel {
    let (lo, hi) = plot_window(m, range);
    let scale = (WIDTH - 2.0 * SIDE) / (hi - lo);
    let x_of = |t: f64| (SIDE + (t - lo) * scale).clamp(SIDE, WIDTH - SIDE);
    let x_end =
        |t: &Option<AlgebraicReal>, open: f64| t.as_ref().map_or(open, |t| x_of(t.to_f64()));

    let (types, colour_of) = type_colours(m);

    // Band labels above the band, instant labels (two lines) below the axis.
    let band_x: Vec<(f64, f64)> = m
        .intervals
        .iter()
        .map(|v| (x_end(&v.from, SIDE), x_end(&v.to, WIDTH - SIDE)))
        .collect();
    let band_labels: Vec<String> = m
        .intervals
        .iter()
        .map(|v| type_label(Some(&v.classification)))
        .collect();
    let band_rows = stagger(
        &band_x
            .iter()
            .zip(&band_labels)
            .map(|(&(a, b), s)| span_at((a + b) / 2.0, s.chars().count()))
            .collect::<Vec<_>>(),
    );
    let tick_x: Vec<f64> = m.instants.iter().map(|i| x_of(i.t.to_f64())).collect();
    let tick_labels: Vec<(String, String)> = m
        .instants
        .iter()
        .map(|i| (value_label(&i.t), type_label(i.class.classification())))
        .collect();
    let tick_rows = stagger(
        &tick_x
            .iter()
            .zip(&tick_labels)
            .map(|(&x, (a, b))| span_at(x, a.chars().count().max(b.chars().count())))
            .collect::<Vec<_>>(),
    );
    let n_band_rows = band_rows.iter().max().map_or(0, |r| r + 1);
    let n_tick_rows = tick_rows.iter().max().map_or(0, |r| r + 1);
    let algebraic = m.instants.iter().any(|i| i.t.as_rational().is_none());

    let title_y = 24.0;
    let band_top = 50.0 + n_band_rows as f64 * (ROW - 10.0);
    let axis_y = band_top + BAND;
    let ticks_top = axis_y + 24.0;
    let legend_top = ticks_top + n_tick_rows as f64 * 2.0 * ROW * 0.7 + 24.0;
    let height =
        legend_top + 20.0 * (types.len() as f64 + 1.0 + f64::from(u8::from(algebraic))) + 10.0;

    let mut out = String::with_capacity(4096);
    out.push_str(
        "<defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" \
         markerWidth=\"8\" markerHeight=\"8\" orient=\"auto-start-reverse\">\
         <path d=\"M0,0 L10,5 L0,10 z\" fill=\"#000\"/></marker></defs>\n",
    );
    push_text(
        &mut out,
        WIDTH / 2.0,
        title_y,
        "middle",
        "title",
        &format!(
            "Intersection type along the motion: {} interval(s), {} instant(s)",
            m.intervals.len(),
            m.instants.len()
        ),
    );

    // Bands and their labels.
    for (k, v) in m.intervals.iter().enumerate() {
        let (a, b) = band_x[k];
        let fill = colour(colour_of[k]);
        let _ = write!(
            out,
            "<rect class=\"band\" x=\"{a:.1}\" y=\"{band_top:.1}\" width=\"{:.1}\" \
             height=\"{BAND}\" fill=\"{fill}\" fill-opacity=\"0.75\" stroke=\"#fff\"><title>",
            (b - a).max(1.0)
        );
        let from = v.from.as_ref().map_or("-∞".into(), exact_title);
        let to = v.to.as_ref().map_or("+∞".into(), exact_title);
        push_escaped(
            &mut out,
            &format!(
                "({from}, {to}), sample t = {}: {}",
                v.sample,
                legend_label(&types[colour_of[k]])
            ),
        );
        out.push_str("</title></rect>\n");
        let (l, r) = span_at((a + b) / 2.0, band_labels[k].chars().count());
        let y = band_top - 8.0 - band_rows[k] as f64 * (ROW - 10.0);
        push_text(
            &mut out,
            (l + r) / 2.0,
            y,
            "middle",
            "band-label",
            &band_labels[k],
        );
    }

    // The axis, with arrows and ±∞ at open sides, and the window's ends.
    let open_left = range.from().is_none();
    let open_right = range.to().is_none();
    let _ = writeln!(
        out,
        "<line class=\"axis\" x1=\"{:.1}\" y1=\"{axis_y:.1}\" x2=\"{:.1}\" y2=\"{axis_y:.1}\" \
         stroke=\"#000\" stroke-width=\"1.5\"{}{}/>",
        SIDE - if open_left { 30.0 } else { 0.0 },
        WIDTH - SIDE + if open_right { 30.0 } else { 0.0 },
        if open_left {
            " marker-start=\"url(#arrow)\""
        } else {
            ""
        },
        if open_right {
            " marker-end=\"url(#arrow)\""
        } else {
            ""
        },
    );
    // A finite end is labelled exactly when the window ends there and the text is short.
    let side_label = |open: bool, sign: &str, exact: Option<String>, value: f64| {
        if open {
            format!("{sign}∞")
        } else {
            match exact.filter(|s| s.chars().count() <= 7) {
                Some(s) => s,
                None => format!("≈{value:.3}"),
            }
        }
    };
    let point = range.from().is_some() && range.from() == range.to();
    let exact = |e: Option<&qsic_algebra::RBig>| e.filter(|_| !point).map(ToString::to_string);
    let end_labels = [
        (
            SIDE - if open_left { 36.0 } else { 6.0 },
            "end",
            side_label(open_left, "−", exact(range.from()), lo),
        ),
        (
            WIDTH - SIDE + if open_right { 36.0 } else { 6.0 },
            "start",
            side_label(open_right, "+", exact(range.to()), hi),
        ),
    ];
    for (x, anchor, text) in end_labels {
        push_text(&mut out, x, axis_y + 4.0, anchor, "axis-label", &text);
    }
    push_text(
        &mut out,
        WIDTH - SIDE + 36.0,
        axis_y - 12.0,
        "start",
        "axis-label",
        "t",
    );

    // Ticks at the instants, with leaders to their staggered labels.
    for (k, i) in m.instants.iter().enumerate() {
        let x = tick_x[k];
        let row_y = ticks_top + tick_rows[k] as f64 * 2.0 * ROW * 0.7;
        let (value, kind) = &tick_labels[k];
        let (l, r) = span_at(x, value.chars().count().max(kind.chars().count()));
        let _ = write!(out, "<g class=\"instant\"><title>");
        push_escaped(
            &mut out,
            &format!(
                "{}: {}",
                exact_title(&i.t),
                type_label(i.class.classification())
            ),
        );
        let _ = writeln!(
            out,
            "</title>\n<line class=\"tick\" x1=\"{x:.1}\" y1=\"{:.1}\" x2=\"{x:.1}\" \
             y2=\"{:.1}\" stroke=\"#000\" stroke-width=\"2\"/>\n\
             <line class=\"leader\" x1=\"{x:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" \
             stroke=\"#999\" stroke-dasharray=\"2,2\"/>",
            band_top - 4.0,
            axis_y + 6.0,
            axis_y + 6.0,
            (l + r) / 2.0,
            row_y - 12.0,
        );
        push_text(&mut out, (l + r) / 2.0, row_y, "middle", "value", value);
        push_text(
            &mut out,
            (l + r) / 2.0,
            row_y + 14.0,
            "middle",
            "type",
            kind,
        );
        out.push_str("</g>\n");
    }

    // The legend.
    push_text(
        &mut out,
        SIDE,
        legend_top,
        "start",
        "legend",
        "Colours (interval types):",
    );
    for (k, t) in types.iter().enumerate() {
        let y = legend_top + 20.0 * (k as f64 + 1.0);
        let _ = writeln!(
            out,
            "<rect class=\"swatch\" x=\"{SIDE}\" y=\"{:.1}\" width=\"24\" height=\"12\" \
             fill=\"{}\" fill-opacity=\"0.75\"/>",
            y - 10.0,
            colour(k)
        );
        push_text(
            &mut out,
            SIDE + 32.0,
            y,
            "start",
            "legend",
            &legend_label(t),
        );
    }
    if algebraic {
        let y = legend_top + 20.0 * (types.len() as f64 + 1.0);
        push_text(
            &mut out,
            SIDE,
            y,
            "start",
            "legend",
            "t ≈ … (algebraic): a decimal of an irrational real algebraic instant; \
             its polynomial and isolating interval are in the tooltip and in --json.",
        );
    }
    Panel {
        width: WIDTH,
        height,
        style: ".title{font-size:15px;font-weight:bold}.band-label{font-size:12px}\
                .value{font-size:12px;font-weight:bold}.type{font-size:11px;fill:#333}\
                .legend{font-size:12px}.axis-label{font-size:13px}"
            .into(),
        body: out,
    }
}

/// Most snapshots drawn by [`motion_with_snapshots_to_svg`].
pub const MAX_SNAPSHOTS: usize = 20;

/// [`motion_to_svg`] with a second panel: a small picture of the real curve at the sample
/// `t` of each interval (the first [`MAX_SNAPSHOTS`]), framed in the interval's band colour
/// and labelled with `t` and the type, drawn by [`crate::plot::snapshot`] from `A(t)`,
/// `B(t)`; where no picture can be drawn (a zero quadric at `t`, a class whose curve is not
/// built yet) the cell says why.
pub fn motion_with_snapshots_to_svg(
    m: &Motion,
    range: &TimeRange,
    a: &MovingMatrix,
    b: &MovingMatrix,
) -> String {
    document(&[timeline_panel(m, range), snapshots_panel(m, a, b)])
}

/// The snapshot panel of [`motion_with_snapshots_to_svg`].
fn snapshots_panel(m: &Motion, a: &MovingMatrix, b: &MovingMatrix) -> Panel {
    const CELL: (f64, f64) = (190.0, 214.0);
    const PER_ROW: usize = 5;
    let (_, colour_of) = type_colours(m);
    let shown = m.intervals.len().min(MAX_SNAPSHOTS);
    let mut body = String::with_capacity(1 << 16);
    push_text(
        &mut body,
        WIDTH / 2.0,
        22.0,
        "middle",
        "title",
        "The real curve at the sample t of each interval",
    );
    for (k, v) in m.intervals.iter().take(shown).enumerate() {
        let left = 25.0 + (k % PER_ROW) as f64 * CELL.0;
        let top = 36.0 + (k / PER_ROW) as f64 * CELL.1;
        let _ = write!(body, "<g class=\"snapshot\" data-interval=\"{k}\">");
        let _ = writeln!(
            body,
            "<rect class=\"cell\" x=\"{:.1}\" y=\"{top:.1}\" width=\"{:.1}\" height=\"{:.1}\" \
             stroke=\"{}\"/>",
            left + 2.0,
            CELL.0 - 4.0,
            CELL.1 - 6.0,
            colour(colour_of[k])
        );
        let centre = left + CELL.0 / 2.0;
        push_text(
            &mut body,
            centre,
            top + 16.0,
            "middle",
            "snapshot-t",
            &format!("t = {}", v.sample),
        );
        push_text(
            &mut body,
            centre,
            top + 31.0,
            "middle",
            "snapshot-type",
            &type_label(Some(&v.classification)),
        );
        let rect = (left + 8.0, top + 38.0, CELL.0 - 16.0, CELL.1 - 50.0);
        let picture = a
            .quadric_at(&v.sample)
            .and_then(|qa| Ok((qa, b.quadric_at(&v.sample)?)))
            .map_err(|e| e.to_string())
            .and_then(|(qa, qb)| crate::plot::snapshot(&qa, &qb, rect));
        match picture {
            Ok(svg) => body.push_str(&svg),
            Err(message) => {
                for (n, line) in crate::svg::wrap(&format!("no picture: {message}"), 28)
                    .iter()
                    .enumerate()
                {
                    push_text(
                        &mut body,
                        centre,
                        rect.1 + rect.3 / 2.0 + 14.0 * n as f64,
                        "middle",
                        "snapshot-none",
                        line,
                    );
                }
            }
        }
        body.push_str("</g>\n");
    }
    let rows = shown.div_ceil(PER_ROW);
    let mut height = 36.0 + rows as f64 * CELL.1 + 10.0;
    if shown < m.intervals.len() {
        push_text(
            &mut body,
            25.0,
            height,
            "start",
            "snapshot-note",
            &format!("the first {shown} of {} intervals", m.intervals.len()),
        );
        height += 20.0;
    }
    Panel {
        width: WIDTH,
        height,
        style: crate::plot::SCENE_STYLE.to_owned()
            + ".cell{fill:none;stroke-width:2}.snapshot-t{font-size:12px;font-weight:bold}\
               .snapshot-type{font-size:11px;fill:#333}.snapshot-none{font-size:11px;fill:#b00}\
               .snapshot .piece{stroke-width:1.6}",
        body,
    }
}

/// The distinct types of the intervals, in order of first appearance, and each interval's
/// index among them (its colour).
fn type_colours(m: &Motion) -> (Vec<MotionType>, Vec<usize>) {
    let mut types: Vec<MotionType> = Vec::new();
    let colour_of = m
        .intervals
        .iter()
        .map(|v| {
            let t = MotionType::of(&v.classification);
            types.iter().position(|u| *u == t).unwrap_or_else(|| {
                types.push(t);
                types.len() - 1
            })
        })
        .collect();
    (types, colour_of)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::motion::analyze;
    use crate::svg::xml::{check_xml, texts_of};
    use qsic::io::moving_matrix_from_polynomial as q;

    /// One band per interval, one tick per instant, labels with the exact values and the
    /// types, and a legend entry per distinct type — on the whole line, a finite range, an
    /// irrational family, and a single point.
    #[test]
    fn svg_has_one_band_per_interval_and_one_tick_per_instant() {
        let fixed = "x^2+y^2+z^2-4";
        let cases = [
            ("(x-t)^2+y^2+z^2-1", TimeRange::default()),
            ("(x-t)^2+y^2+z^2-1", TimeRange::parse("-1", "2").unwrap()),
            ("(x-t)^2+y^2+z^2-1", TimeRange::parse("1/3", "oo").unwrap()),
            ("(x-t^2)^2+y^2+z^2-1", TimeRange::default()),
            ("(x-t)^2+y^2+z^2-1", TimeRange::parse("3", "3").unwrap()),
        ];
        for (moving, range) in cases {
            let m = analyze(q(fixed).unwrap(), q(moving).unwrap(), &range).unwrap();
            let svg = motion_to_svg(&m, &range);
            let names = check_xml(&svg);
            assert_eq!(names[0], "svg");
            assert_eq!(
                svg.matches("<rect class=\"band\"").count(),
                m.intervals.len()
            );
            assert_eq!(
                svg.matches("<line class=\"tick\"").count(),
                m.instants.len()
            );
            let bands = texts_of(&svg, "band-label");
            for (v, label) in m.intervals.iter().zip(&bands) {
                let c = &v.classification;
                assert!(
                    label.contains(&format!("case {}", c.case.unwrap())),
                    "{label}"
                );
                assert!(label.ends_with(c.real_type().unwrap()), "{label}");
            }
            let values = texts_of(&svg, "value");
            let types = texts_of(&svg, "type");
            assert_eq!(values.len(), m.instants.len());
            for ((i, value), kind) in m.instants.iter().zip(&values).zip(&types) {
                match i.t.as_rational() {
                    Some(r) => assert_eq!(*value, format!("t = {r}")),
                    None => {
                        assert!(value.contains("(algebraic)"), "{value}");
                        assert!(svg.contains(&exact_title(&i.t)));
                    }
                }
                let c = i.class.classification().unwrap();
                assert!(kind.ends_with(c.real_type().unwrap()), "{kind}");
            }
            let distinct: std::collections::HashSet<MotionType> = m
                .intervals
                .iter()
                .map(|v| MotionType::of(&v.classification))
                .collect();
            let legend = texts_of(&svg, "legend");
            let algebraic = m.instants.iter().any(|i| i.t.as_rational().is_none());
            assert_eq!(legend.len(), 1 + distinct.len() + usize::from(algebraic));
            for t in &distinct {
                assert!(legend.contains(&legend_label(t)), "{t:?}");
            }
            // open sides are arrows labelled with infinity
            let axis = texts_of(&svg, "axis-label");
            assert_eq!(axis.contains(&"−∞".to_string()), range.from().is_none());
            assert_eq!(axis.contains(&"+∞".to_string()), range.to().is_none());
        }
    }

    /// One snapshot per interval, framed in its band's colour, whose pieces are the real
    /// pieces of the curve of `A(t)`, `B(t)` at the interval's sample (spheres through one
    /// another, cylinders sliding along each other, unit spheres touching at t = ±2).
    #[test]
    fn snapshots_show_the_curve_of_each_interval() {
        let cases = [
            ("x^2+y^2+z^2-4", "(x-t)^2+y^2+z^2-1"),
            ("x^2+y^2-1", "x^2+(z-t)^2-1"),
            ("x^2+y^2+z^2-1", "(x-t)^2+y^2+z^2-1"),
        ];
        for (a, b) in cases {
            let (ma, mb) = (q(a).unwrap(), q(b).unwrap());
            let range = TimeRange::default();
            let m = analyze(ma.clone(), mb.clone(), &range).unwrap();
            let svg = motion_with_snapshots_to_svg(&m, &range, &ma, &mb);
            check_xml(&svg);
            let cells: Vec<&str> = svg.split("<g class=\"snapshot\"").skip(1).collect();
            assert_eq!(cells.len(), m.intervals.len().min(MAX_SNAPSHOTS), "{b}");
            let (_, colour_of) = type_colours(&m);
            for ((cell, v), c) in cells.iter().zip(&m.intervals).zip(&colour_of) {
                assert!(cell.contains(&format!("stroke=\"{}\"", colour(*c))));
                assert!(cell.contains(&format!(">t = {}<", v.sample)));
                let pair = ma.quadric_at(&v.sample).and_then(|qa| {
                    let qb = mb.quadric_at(&v.sample)?;
                    qsic::param::parameterize(&qa, &qb)
                });
                match pair {
                    Ok(curve) => assert_eq!(
                        cell.matches("<g class=\"piece\"").count(),
                        curve.pieces.len(),
                        "{b} at {}",
                        v.sample
                    ),
                    Err(_) => assert!(cell.contains("no picture"), "{cell}"),
                }
            }
        }
    }

    /// The window holds every instant strictly inside when a side is open, and is the range
    /// when both ends are finite.
    #[test]
    fn window_contains_the_instants() {
        let m = analyze(
            q("x^2+y^2+z^2-4").unwrap(),
            q("(x-t)^2+y^2+z^2-1").unwrap(),
            &TimeRange::default(),
        )
        .unwrap();
        let (lo, hi) = plot_window(&m, &TimeRange::default());
        assert!(lo < -3.0 && hi > 3.0, "{lo} {hi}");
        let r = TimeRange::parse("-1", "2").unwrap();
        assert_eq!(plot_window(&m, &r), (-1.0, 2.0));
        let r = TimeRange::parse("-oo", "-2").unwrap();
        let (lo, hi) = plot_window(&m, &r);
        assert!(lo < -3.0 && hi == -2.0);
    }

    /// Staggered labels never overlap within a row, and each takes the first free row.
    #[test]
    fn stagger_separates_overlapping_labels() {
        let spans: Vec<(f64, f64)> = (0..12)
            .map(|k| span_at(100.0 + 30.0 * f64::from(k), 10 + (k as usize % 3)))
            .collect();
        let rows = stagger(&spans);
        assert_eq!(rows[0], 0);
        assert!(rows.iter().any(|&r| r > 0));
        for i in 0..spans.len() {
            for j in i + 1..spans.len() {
                if rows[i] == rows[j] {
                    assert!(spans[i].1 + 8.0 <= spans[j].0, "{i} {j}");
                }
            }
        }
        // far apart labels share the first row
        assert_eq!(stagger(&[(0.0, 10.0), (100.0, 110.0)]), [0, 0]);
    }
}
