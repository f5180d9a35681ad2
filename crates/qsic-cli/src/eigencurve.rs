//! The eigencurve panel of `qsic plot --eigencurve`: the curve `det(λA − B − uI) = 0` of the
//! eigenvalues `u` of `λA − B` (Tu et al. 2009, Fig. 1), the index in each region, and the
//! real roots of `det(λA − B)` on `u = 0` from the exact pencil analysis. The branches are the
//! sorted eigenvalues (Jacobi's method) at a grid of `λ`, floats only to draw; the roots and
//! the index on `u = 0` are exact.

use crate::svg::{push_text, push_title, short, wrap, Panel, WIDTH};
use qsic::classify::analyze_pencil;
use qsic::pencil::PencilPoint;
use qsic::Quadric;
use qsic_algebra::{IBig, RBig};
use std::fmt::Write as _;

/// The eigenvalues of the symmetric matrix `m`, increasing (cyclic Jacobi rotations until the
/// off-diagonal part is below `10⁻²⁸` of the whole, at most 64 sweeps).
pub(crate) fn symmetric_eigenvalues(mut m: [[f64; 4]; 4]) -> [f64; 4] {
    let total: f64 = m.iter().flatten().map(|v| v * v).sum();
    for _ in 0..64 {
        let off: f64 = (0..4)
            .flat_map(|i| (0..4).filter(move |&j| j != i).map(move |j| (i, j)))
            .map(|(i, j)| m[i][j] * m[i][j])
            .sum();
        if off <= 1e-28 * total || off == 0.0 {
            break;
        }
        for p in 0..4 {
            for q in p + 1..4 {
                if m[p][q] == 0.0 {
                    continue;
                }
                let theta = (m[q][q] - m[p][p]) / (2.0 * m[p][q]);
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let c = 1.0 / (t * t + 1.0).sqrt();
                let s = t * c;
                let apq = m[p][q];
                m[p][p] -= t * apq;
                m[q][q] += t * apq;
                m[p][q] = 0.0;
                m[q][p] = 0.0;
                #[allow(clippy::needless_range_loop)] // rows and columns of one matrix
                for r in 0..4 {
                    if r != p && r != q {
                        let (arp, arq) = (m[r][p], m[r][q]);
                        m[r][p] = c * arp - s * arq;
                        m[p][r] = m[r][p];
                        m[r][q] = c * arq + s * arp;
                        m[q][r] = m[r][q];
                    }
                }
            }
        }
    }
    let mut e = [m[0][0], m[1][1], m[2][2], m[3][3]];
    e.sort_by(f64::total_cmp);
    e
}

/// Round tick values in `[lo, hi]`: steps of 1, 2 or 5 times a power of ten, about six.
pub(crate) fn nice_ticks(lo: f64, hi: f64) -> Vec<f64> {
    let span = hi - lo;
    if span.is_nan() || span <= 0.0 || !span.is_finite() {
        return Vec::new();
    }
    let raw = span / 6.0;
    let power = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * power)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * power);
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last).map(|k| k as f64 * step).collect()
}

/// `s` with `A = s·P`, `P` the primitive integer matrix of `q` (the scaling the
/// classification works with).
fn integer_scale(q: &Quadric) -> RBig {
    let p = q.integer_matrix().entries();
    p.iter()
        .flatten()
        .zip(q.matrix().iter().flatten())
        .find(|(p, _)| **p != IBig::ZERO)
        .map_or(RBig::ONE, |(p, m)| m.clone() / RBig::from(p.clone()))
}

/// A real root of `det(λA − B)` for the picture.
struct RootMark {
    /// Its position.
    at: f64,
    /// Its label: `λ = p/q`, or `λ ≈ d (algebraic)`.
    label: String,
    /// The tooltip: exact value, multiplicity, Jordan blocks, inertia.
    title: String,
}

/// The eigencurve panel: the four sorted eigenvalues of `λA − B` as functions of `λ` (the
/// curve `det(λA − B − uI) = 0`) over a window holding the real roots of `det(λA − B)`; in
/// each region the index of `λA − B − uI` — the number of its positive eigenvalues, i.e. of
/// branches above the point (Tu et al. 2009, §2.4: `index(D)` is the number of positive
/// eigenvalues, and on `u = 0` it is the index function `Id(λ)`); on `u = 0`, one
/// `<circle class="root-mark">` per real root of `det(λA − B)` from the exact pencil analysis
/// (`qsic::classify::analyze_pencil`, scaled back from the classification's primitive integer
/// matrices to `A`, `B` as given) and, between them, `Id(λ)` from the exact inertia
/// (`<text class="index-axis">`).
pub fn eigencurve_panel(a: &Quadric, b: &Quadric) -> Panel {
    let (fa, fb) = (
        a.matrix().clone().map(|r| r.map(|v| v.to_f64().value())),
        b.matrix().clone().map(|r| r.map(|v| v.to_f64().value())),
    );
    let analysis = analyze_pencil(a, b);
    // λ for A, B as given = ratio · λ for the primitive integer matrices
    let ratio = integer_scale(b) / integer_scale(a);
    let ratio_f = ratio.to_f64().value();
    let mut roots: Vec<RootMark> = Vec::new();
    let mut at_infinity = None;
    if let Some(an) = &analysis {
        for r in &an.real_roots {
            let detail = format!(
                "multiplicity {}, Jordan blocks {:?}, inertia (+{}, −{}, 0: {})",
                r.multiplicity, r.blocks, r.inertia.positive, r.inertia.negative, r.inertia.zero
            );
            match &r.point {
                PencilPoint::Finite(alpha) => {
                    let (label, exact) = match alpha.as_rational() {
                        Some(v) => {
                            let v = &ratio * v;
                            (format!("λ = {v}"), format!("λ = {v}"))
                        }
                        None => {
                            let iv = alpha.interval();
                            (
                                format!("λ ≈ {:.6} (algebraic)", alpha.to_f64() * ratio_f),
                                format!(
                                    "λ = {ratio}·α, α the root of {} in [{}, {}]",
                                    alpha.poly(),
                                    iv.lo(),
                                    iv.hi()
                                ),
                            )
                        }
                    };
                    roots.push(RootMark {
                        at: alpha.to_f64() * ratio_f,
                        label,
                        title: format!("{exact}: {detail}"),
                    });
                }
                PencilPoint::Infinity => at_infinity = Some(detail),
            }
        }
    }
    // the λ window
    let (lo, hi) = match (roots.first(), roots.last()) {
        (Some(first), Some(last)) if last.at > first.at => {
            let m = 0.35 * (last.at - first.at);
            (first.at - m, last.at + m)
        }
        (Some(r), _) => {
            let m = (r.at.abs() / 2.0).max(1.0);
            (r.at - m, r.at + m)
        }
        _ => (-3.0, 3.0),
    };
    const COLUMNS: usize = 480;
    let lambdas: Vec<f64> = (0..=COLUMNS)
        .map(|i| lo + (hi - lo) * i as f64 / COLUMNS as f64)
        .collect();
    let member = |l: f64| -> [[f64; 4]; 4] {
        std::array::from_fn(|i| std::array::from_fn(|j| l * fa[i][j] - fb[i][j]))
    };
    let eigen: Vec<[f64; 4]> = lambdas
        .iter()
        .map(|&l| symmetric_eigenvalues(member(l)))
        .collect();
    let finite = |v: &f64| v.is_finite();
    let umin = eigen
        .iter()
        .flatten()
        .copied()
        .filter(finite)
        .fold(0.0, f64::min);
    let umax = eigen
        .iter()
        .flatten()
        .copied()
        .filter(finite)
        .fold(0.0, f64::max);
    let pad = 0.08 * (umax - umin).max(1e-9);
    let (ulo, uhi) = (umin - pad, umax + pad);

    // the plot rectangle
    let (left, top, width, height) = (80.0, 50.0, 860.0, 380.0);
    let px = |l: f64| left + (l - lo) / (hi - lo) * width;
    let py = |u: f64| top + (uhi - u) / (uhi - ulo) * height;
    let mut body = String::with_capacity(1 << 15);
    push_text(
        &mut body,
        WIDTH / 2.0,
        28.0,
        "middle",
        "title",
        "Eigenvalue curve det(λA − B − uI) = 0 and the index of λA − B − uI in each region",
    );
    let _ = writeln!(
        body,
        "<rect class=\"frame\" x=\"{left}\" y=\"{top}\" width=\"{width}\" height=\"{height}\"/>"
    );
    // ticks and the axes
    for t in nice_ticks(lo, hi) {
        let x = px(t);
        let _ = writeln!(
            body,
            "<line class=\"grid\" x1=\"{x:.1}\" y1=\"{top}\" x2=\"{x:.1}\" y2=\"{:.1}\"/>",
            top + height
        );
        push_text(
            &mut body,
            x,
            top + height + 16.0,
            "middle",
            "tick",
            &short(t),
        );
    }
    for t in nice_ticks(ulo, uhi) {
        let y = py(t);
        let _ = writeln!(
            body,
            "<line class=\"grid\" x1=\"{left}\" y1=\"{y:.1}\" x2=\"{:.1}\" y2=\"{y:.1}\"/>",
            left + width
        );
        push_text(&mut body, left - 6.0, y + 4.0, "end", "tick", &short(t));
    }
    let y0 = py(0.0);
    let _ = writeln!(
        body,
        "<line class=\"axis-line\" x1=\"{left}\" y1=\"{y0:.1}\" x2=\"{:.1}\" y2=\"{y0:.1}\"/>",
        left + width
    );
    if lo < 0.0 && 0.0 < hi {
        let x0 = px(0.0);
        let _ = writeln!(
            body,
            "<line class=\"axis-line\" x1=\"{x0:.1}\" y1=\"{top}\" x2=\"{x0:.1}\" y2=\"{:.1}\"/>",
            top + height
        );
    }
    push_text(
        &mut body,
        left + width + 12.0,
        y0 + 4.0,
        "start",
        "axis-name",
        "λ",
    );
    push_text(
        &mut body,
        left - 40.0,
        top + 4.0,
        "middle",
        "axis-name",
        "u",
    );

    // the four branches
    for k in 0..4 {
        body.push_str("<path class=\"eigen-branch\" d=\"");
        for (n, (l, e)) in lambdas.iter().zip(&eigen).enumerate() {
            let _ = write!(
                body,
                "{}{:.1},{:.1}",
                if n == 0 { "M" } else { " L" },
                px(*l),
                py(e[k])
            );
        }
        body.push_str("\"/>\n");
    }

    // the index in the regions crossed by a column in the middle of each arc
    let mut ends: Vec<f64> = vec![lo];
    ends.extend(roots.iter().map(|r| r.at));
    ends.push(hi);
    let exact_index: Vec<Option<u8>> = match &analysis {
        Some(an) if an.arcs.len() == ends.len() - 1 => {
            an.arcs.iter().map(|(_, i)| Some(i.positive)).collect()
        }
        _ => vec![None; ends.len() - 1],
    };
    let axis_x = (lo < 0.0 && 0.0 < hi).then(|| px(0.0));
    for (w, exact) in ends.windows(2).zip(&exact_index) {
        let mid = (w[0] + w[1]) / 2.0;
        // off the u axis when the arc's middle falls on it
        let x = match axis_x {
            Some(ax) if (px(mid) - ax).abs() < 12.0 => ax + 14.0,
            _ => px(mid),
        };
        let e = symmetric_eigenvalues(member(mid));
        // gaps between consecutive eigenvalues, from below: index 4, 3, 2, 1, 0
        let mut bounds = vec![ulo];
        bounds.extend(e.iter().map(|v| v.clamp(ulo, uhi)));
        bounds.push(uhi);
        for (g, gap) in bounds.windows(2).enumerate() {
            let index = 4 - g;
            let (ylo, yhi) = (py(gap[0]), py(gap[1]));
            let holds_zero = gap[0] < 0.0 && 0.0 < gap[1];
            let (class, text) = match (holds_zero, exact) {
                (true, Some(i)) => ("index-axis", i.to_string()),
                _ => ("index", index.to_string()),
            };
            let y = if holds_zero {
                // beside the axis, in the gap
                let above = (y0 - yhi).abs() > (ylo - y0).abs();
                if above {
                    y0 - 6.0
                } else {
                    y0 + 16.0
                }
            } else {
                (ylo + yhi) / 2.0 + 5.0
            };
            if (ylo - yhi).abs() >= 18.0 || holds_zero {
                push_text(&mut body, x, y, "middle", class, &text);
            }
        }
    }

    // the roots
    let mut rows: Vec<f64> = Vec::new();
    for r in &roots {
        let x = px(r.at);
        body.push_str("<g class=\"root\">");
        push_title(&mut body, &r.title);
        let _ = writeln!(
            body,
            "<circle class=\"root-mark\" cx=\"{x:.1}\" cy=\"{y0:.1}\" r=\"4.5\"/>"
        );
        // labels below the frame, staggered when close
        let w = r.label.chars().count() as f64 * 6.5;
        let row = rows
            .iter()
            .position(|&end| end + 8.0 <= x - w / 2.0)
            .unwrap_or(rows.len());
        if row == rows.len() {
            rows.push(x + w / 2.0);
        } else {
            rows[row] = x + w / 2.0;
        }
        let ly = top + height + 36.0 + 16.0 * row as f64;
        let _ = writeln!(
            body,
            "<line class=\"leader\" x1=\"{x:.1}\" y1=\"{y0:.1}\" x2=\"{x:.1}\" y2=\"{:.1}\"/>",
            ly - 12.0
        );
        push_text(&mut body, x, ly, "middle", "root-label", &r.label);
        body.push_str("</g>\n");
    }

    // the legend
    let mut y = top + height + 46.0 + 16.0 * rows.len() as f64;
    let mut notes = vec![
        "Curves: the eigenvalues u of λA − B (A, B as given). Numbers: the index of λA − B − uI, \
         its number of positive eigenvalues (Tu et al. 2009, §2.4), i.e. the number of branches \
         above; bold on u = 0: the index function Id(λ) from the exact inertia."
            .to_string(),
        "Dots on u = 0: the real roots of det(λA − B), exact (pencil analysis).".to_string(),
    ];
    match (&analysis, &at_infinity) {
        (None, _) => notes.push(
            "det(λA − B) vanishes identically (a singular pencil, or a single quadric): no roots \
             to mark."
                .into(),
        ),
        (Some(_), Some(detail)) => {
            notes.push(format!("Also a root at λ = ∞ (A singular): {detail}."))
        }
        (Some(_), None) => {}
    }
    for note in notes {
        for l in wrap(&note, 140) {
            push_text(&mut body, left, y, "start", "legend", &l);
            y += 15.0;
        }
    }
    Panel {
        width: WIDTH,
        height: y + 10.0,
        style: ".frame{fill:none;stroke:#333}.grid{stroke:#e4e4e4}.tick{font-size:10px;fill:#555}\
                .axis-line{stroke:#000;stroke-width:1}.axis-name{font-size:14px;font-style:italic}\
                .eigen-branch{fill:none;stroke:#4e79a7;stroke-width:1.8}\
                .index{font-size:13px;fill:#666}.index-axis{font-size:14px;font-weight:bold}\
                .root-mark{fill:#e15759;stroke:#000}.root-label{font-size:11px}\
                .leader{stroke:#999;stroke-dasharray:2,2}"
            .into(),
        body,
    }
}
