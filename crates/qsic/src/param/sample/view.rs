//! The affine view of a sampled polyline: the piece split at its crossings of the plane at
//! infinity (the branches end before and start after them) and at the curve's real singular
//! points (both branches keep the point), its points at infinity in order, and whether it is
//! bounded — read from the polyline and its exact marks, with `h` computed once per point
//! during the walk.
//!
//! [`affine_view`] walks the runs of plain points between marks; [`affine_view_two_pass`]
//! (debug builds, and the tests) is the reference that visits every point twice: the two are
//! held equal.

use crate::param::sample::chart::{dot, Chart};
use crate::param::sample::walk::{AffineSteps, Line};
use crate::param::sample::AffinePiece;

/// Splits the oriented polyline at its crossings with the plane at infinity (the branches
/// end before and start after them) and at its real singular points (both branches keep
/// the point).
pub(super) fn affine_view(chart: &Chart, line: &Line, closed: bool) -> AffinePiece {
    let (x, marks) = (&line.x, &line.marks);
    let n = x.len();
    let points_at_infinity: Vec<[f64; 4]> = marks.iter().filter(|m| m.1).map(|m| x[m.0]).collect();
    let first_cut = marks.first().map(|m| m.0);
    let mut branches = Vec::new();
    let AffineSteps {
        first,
        count,
        special,
    } = AffineSteps::new(line, closed);
    let mut current: Vec<[f64; 3]> = Vec::with_capacity(count);
    // the index into `x` of each point of `current`, and of each branch's points
    let mut current_at: Vec<usize> = Vec::with_capacity(count);
    let mut indices = Vec::new();
    // the line is oriented, but a loop may come back reversed at its start: `sign`
    // orients along the walk from there on; `prev_h` is h of the previous point so
    // oriented (`None` after a crossing)
    let mut sign = 1.0;
    let mut prev_h: Option<f64> = None;
    // `current` holds only the singular point it restarts from
    let mut restarted = false;
    // the next mark in the order of the walk, the next special step
    let (mut mi, mut si) = (0, 0);
    let mut j = 0;
    while j < count {
        let stop = special.get(si).map_or(count, |&s| s.min(count));
        if j < stop {
            // a run of plain points, `k` contiguous
            let k0 = if j + first >= n {
                j + first - n
            } else {
                j + first
            };
            let len = stop - j;
            let (xs, hs) = (&x[k0..k0 + len], &line.h[k0..k0 + len]);
            let keep = chart.keep;
            let mut i = 0;
            while i < len {
                // the stretch from `i` on where `h` keeps the sign of the last point and
                // is nonzero: no break, every point in the chart
                let from = i;
                if let Some(hp) = prev_h {
                    // `hx ≠ 0` with the sign of `hp > 0`: `±sign·h > 0` (false for NaN,
                    // left to the point-by-point step)
                    let s = if hp > 0.0 { sign } else { -sign };
                    // four at a time (`&` tests all four, no branch each), then one
                    while let Some(q) = hs.get(i..i + 4) {
                        let pos = |v: f64| s * v > 0.0;
                        if !(pos(q[0]) & pos(q[1]) & pos(q[2]) & pos(q[3])) {
                            break;
                        }
                        i += 4;
                    }
                    while i < len && s * hs[i] > 0.0 {
                        i += 1;
                    }
                }
                if i > from {
                    let run = xs[from..i].iter().zip(&hs[from..i]);
                    if keep == [0, 1, 2] {
                        // the usual chart (`w` dropped), the indices known
                        current.extend(run.map(|(p, &h)| [p[0] / h, p[1] / h, p[2] / h]));
                    } else {
                        let [k0, k1, k2] = keep.map(|k| k.min(3));
                        current.extend(run.map(|(p, &h)| [p[k0] / h, p[k1] / h, p[k2] / h]));
                    }
                    current_at.extend(k0 + from..k0 + i);
                    prev_h = Some(sign * hs[i - 1]);
                    restarted = false;
                    continue;
                }
                let (p, h) = (&xs[i], hs[i]);
                let hx = sign * h;
                if prev_h.is_some_and(|hp| (hp > 0.0) != (hx > 0.0)) {
                    // a sign change of h without a crossing point: the branch breaks here
                    branches.push(std::mem::replace(
                        &mut current,
                        Vec::with_capacity(count - j - i),
                    ));
                    indices.push(std::mem::take(&mut current_at));
                }
                prev_h = Some(hx);
                if let Some(a) = chart.affine_with(p, h) {
                    current.push(a);
                    current_at.push(k0 + i);
                    restarted = false;
                }
                i += 1;
            }
            j = stop;
            continue;
        }
        si += 1;
        let mut k = j + first;
        if k >= n {
            k -= n;
            if k == 0 {
                mi = 0;
                if j > 0 && prev_h.is_some() && dot(&x[n - 1], &x[0]) < 0.0 {
                    sign = -sign;
                }
            }
        }
        let (at_infinity, singular) = match marks.get(mi) {
            Some(&(i, inf, sing)) if i == k => {
                mi += 1;
                (inf, sing)
            }
            _ => (false, false),
        };
        j += 1;
        if at_infinity {
            if !current.is_empty() && !restarted {
                branches.push(std::mem::replace(
                    &mut current,
                    Vec::with_capacity(count - j + 1),
                ));
                indices.push(std::mem::take(&mut current_at));
            }
            current.clear();
            current_at.clear();
            restarted = false;
            prev_h = None;
            sign = 1.0;
            continue;
        }
        let p = &x[k];
        let h = line.h[k];
        let hx = sign * h;
        if prev_h.is_some_and(|hp| (hp > 0.0) != (hx > 0.0)) {
            // a sign change of h without a crossing point: the branch breaks here
            branches.push(std::mem::replace(
                &mut current,
                Vec::with_capacity(count - j + 1),
            ));
            indices.push(std::mem::take(&mut current_at));
        }
        prev_h = Some(hx);
        if let Some(a) = chart.affine_with(p, h) {
            current.push(a);
            current_at.push(k);
            if singular {
                // the branch ends at the singular point and the next one starts there
                if current.len() > 1 {
                    branches.push(std::mem::replace(
                        &mut current,
                        Vec::with_capacity(count - j + 1),
                    ));
                    indices.push(std::mem::take(&mut current_at));
                }
                current.clear();
                current.push(a);
                current_at.clear();
                current_at.push(k);
                restarted = true;
            } else {
                restarted = false;
            }
        }
    }
    if closed && first_cut.is_none() && !current.is_empty() {
        current.push(current[0]);
        // the repeated first point (after the last of `x` where it is point 0)
        current_at.push(if current_at[0] == 0 { n } else { current_at[0] });
    }
    if !current.is_empty() && !restarted {
        branches.push(current);
        indices.push(current_at);
    }
    AffinePiece {
        bounded: points_at_infinity.is_empty() && !branches.is_empty(),
        branches,
        points_at_infinity,
        at_infinity: false,
        indices,
    }
}

/// The reference for [`Sampler::affine`] (checked against it in debug builds): `h`
/// recomputed at every point, the line walked one point at a time.
#[cfg(debug_assertions)]
pub(super) fn affine_view_two_pass(chart: &Chart, line: &Line, closed: bool) -> AffinePiece {
    let (x, marks) = (&line.x, &line.marks);
    let n = x.len();
    let points_at_infinity: Vec<[f64; 4]> = marks.iter().filter(|m| m.1).map(|m| x[m.0]).collect();
    let first_cut = marks.first().map(|m| m.0);
    let mut branches = Vec::new();
    let AffineSteps {
        first,
        count,
        special,
    } = AffineSteps::new(line, closed);
    let mut current: Vec<[f64; 3]> = Vec::with_capacity(count);
    let mut current_at: Vec<usize> = Vec::with_capacity(count);
    let mut indices = Vec::new();
    // the line is oriented, but a loop may come back reversed at its start: `sign`
    // orients along the walk from there on; `prev_h` is h of the previous point so
    // oriented (`None` after a crossing)
    let mut sign = 1.0;
    let mut prev_h: Option<f64> = None;
    // `current` holds only the singular point it restarts from
    let mut restarted = false;
    // the next mark in the order of the walk, the next special step
    let (mut mi, mut si) = (0, 0);
    let mut j = 0;
    while j < count {
        let stop = special.get(si).map_or(count, |&s| s.min(count));
        if j < stop {
            // a run of plain points, `k` contiguous
            let k0 = if j + first >= n {
                j + first - n
            } else {
                j + first
            };
            for (k, p) in x.iter().enumerate().take(k0 + (stop - j)).skip(k0) {
                let h = chart.value(p);
                let hx = sign * h;
                if prev_h.is_some_and(|hp| (hp > 0.0) != (hx > 0.0)) {
                    // a sign change of h without a crossing point: the branch breaks here
                    branches.push(std::mem::replace(
                        &mut current,
                        Vec::with_capacity(count - j),
                    ));
                    indices.push(std::mem::take(&mut current_at));
                }
                prev_h = Some(hx);
                if let Some(a) = chart.affine_with(p, h) {
                    current.push(a);
                    current_at.push(k);
                    restarted = false;
                }
            }
            j = stop;
            continue;
        }
        si += 1;
        let mut k = j + first;
        if k >= n {
            k -= n;
            if k == 0 {
                mi = 0;
                if j > 0 && prev_h.is_some() && dot(&x[n - 1], &x[0]) < 0.0 {
                    sign = -sign;
                }
            }
        }
        let (at_infinity, singular) = match marks.get(mi) {
            Some(&(i, inf, sing)) if i == k => {
                mi += 1;
                (inf, sing)
            }
            _ => (false, false),
        };
        j += 1;
        if at_infinity {
            if !current.is_empty() && !restarted {
                branches.push(std::mem::replace(
                    &mut current,
                    Vec::with_capacity(count - j + 1),
                ));
                indices.push(std::mem::take(&mut current_at));
            }
            current.clear();
            current_at.clear();
            restarted = false;
            prev_h = None;
            sign = 1.0;
            continue;
        }
        let p = &x[k];
        let h = chart.value(p);
        let hx = sign * h;
        if prev_h.is_some_and(|hp| (hp > 0.0) != (hx > 0.0)) {
            // a sign change of h without a crossing point: the branch breaks here
            branches.push(std::mem::replace(
                &mut current,
                Vec::with_capacity(count - j + 1),
            ));
            indices.push(std::mem::take(&mut current_at));
        }
        prev_h = Some(hx);
        if let Some(a) = chart.affine_with(p, h) {
            current.push(a);
            current_at.push(k);
            if singular {
                // the branch ends at the singular point and the next one starts there
                if current.len() > 1 {
                    branches.push(std::mem::replace(
                        &mut current,
                        Vec::with_capacity(count - j + 1),
                    ));
                    indices.push(std::mem::take(&mut current_at));
                }
                current.clear();
                current.push(a);
                current_at.clear();
                current_at.push(k);
                restarted = true;
            } else {
                restarted = false;
            }
        }
    }
    if closed && first_cut.is_none() && !current.is_empty() {
        current.push(current[0]);
        current_at.push(if current_at[0] == 0 { n } else { current_at[0] });
    }
    if !current.is_empty() && !restarted {
        branches.push(current);
        indices.push(current_at);
    }
    AffinePiece {
        bounded: points_at_infinity.is_empty() && !branches.is_empty(),
        branches,
        points_at_infinity,
        at_infinity: false,
        indices,
    }
}
