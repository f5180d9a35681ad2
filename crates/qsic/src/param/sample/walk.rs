//! The walk along an arc: the polyline being built ([`Line`]), its points ([`Sample`]), the
//! arc's span in `θ` (`(U₀, U₁) = (sin θ, cos θ)`, so `u = ∞` is an ordinary point and a
//! range through ∞ is an interval of `θ`), and the run of grid points accepted at once.
//!
//! A grid point is accepted when its unit vector is within [`MAX_ANGLE`] of the last one up
//! to sign; [`run_of`] accepts a run of them in one pass, oriented as it goes (consecutive dot
//! products nonnegative), and [`run_of_reference`] (tests) one at a time: the two agree.

use crate::error::Error;
use crate::param::curve::{ParamRange, ParamValue, Sheet};
use crate::param::sample::chart::{dot, ChartForm};
use crate::param::sample::MAX_ANGLE;
use qsic_algebra::AlgebraicReal;
use std::cell::RefCell;
use std::f64::consts::{FRAC_PI_2, PI};

/// One point of a polyline: where on the parameter line, and the unit vector.
#[derive(Clone, Copy, Debug)]
pub(super) struct Sample {
    pub(super) theta: f64,
    pub(super) x: [f64; 4],
    /// A crossing of the plane at infinity found exactly.
    pub(super) at_infinity: bool,
    /// A real singular point of the curve, at its exact parameter.
    pub(super) singular: bool,
}

impl Sample {
    pub(super) fn new(theta: f64, x: [f64; 4]) -> Sample {
        Sample {
            theta,
            x,
            at_infinity: false,
            singular: false,
        }
    }
}

/// Floats of the exact parameters met (arc ends, events), each approximated once per call
/// (the same defining polynomial and isolating interval: the same number).
#[derive(Default)]
pub(super) struct Approximations(RefCell<Vec<(AlgebraicReal, f64)>>);

impl Approximations {
    pub(super) fn of(&self, r: &AlgebraicReal) -> f64 {
        if let Some((_, v)) = self.0.borrow().iter().find(|(q, _)| q.same_definition(r)) {
            return *v;
        }
        let v = r.to_f64();
        self.0.borrow_mut().push((r.clone(), v));
        v
    }
}

/// The ends of an arc in `θ` and their exact points on ℙ¹.
pub(super) struct ArcSpan {
    pub(super) theta: (f64, f64),
    pub(super) ends: ((f64, f64), (f64, f64)),
}

/// `(U₀, U₁)` of a finite `u` with `max(|U₀|, |U₁|) = 1`.
pub(super) fn projective(u: f64) -> (f64, f64) {
    if u.abs() <= 1.0 {
        (u, 1.0)
    } else {
        (1.0, 1.0 / u)
    }
}

pub(super) fn span<'r>(
    range: &'r ParamRange,
    approx: &dyn Fn(&'r AlgebraicReal) -> f64,
) -> Result<ArcSpan, Error> {
    let whole = ArcSpan {
        theta: (-FRAC_PI_2, FRAC_PI_2),
        ends: ((-1.0, 0.0), (1.0, 0.0)),
    };
    Ok(match range {
        ParamRange::All => whole,
        ParamRange::Between(ParamValue::Infinity, ParamValue::Infinity) => whole,
        ParamRange::Between(ParamValue::Infinity, ParamValue::Finite(hi)) => {
            let h = approx(hi);
            ArcSpan {
                theta: (-FRAC_PI_2, h.atan()),
                ends: ((-1.0, 0.0), projective(h)),
            }
        }
        ParamRange::Between(ParamValue::Finite(lo), ParamValue::Infinity) => {
            let l = approx(lo);
            ArcSpan {
                theta: (l.atan(), FRAC_PI_2),
                ends: (projective(l), (1.0, 0.0)),
            }
        }
        ParamRange::Between(ParamValue::Finite(lo), ParamValue::Finite(hi)) => {
            let (l, h) = (approx(lo), approx(hi));
            let mut end = h.atan();
            if hi <= lo {
                end += PI;
            }
            ArcSpan {
                theta: (l.atan(), end),
                ends: (projective(l), projective(h)),
            }
        }
    })
}

/// The state of the walk along one arc: the last point and the segments still to check.
pub(super) struct Walk {
    pub(super) prev: Sample,
    /// `h` at `prev`.
    pub(super) h_prev: f64,
    pub(super) stack: Vec<(Sample, u32)>,
    /// Crossings of the plane at infinity located along the walk (not known exactly).
    pub(super) unknown: bool,
    /// The polyline's last point is `−prev.x` (the polyline is oriented as it is walked).
    pub(super) flip: bool,
}

/// A polyline being built: its unit vectors, and the marks of those that are crossings of the
/// plane at infinity or singular points (the few points that carry one).
#[derive(Default)]
pub(super) struct Line {
    pub(super) x: Vec<[f64; 4]>,
    /// `h` of each point as stored (oriented), for the affine view.
    pub(super) h: Vec<f64>,
    /// The chart's plane at infinity as floats.
    pub(super) chart: ChartForm,
    /// `(index, at infinity, singular)`, ascending, at most one per index, never both false.
    pub(super) marks: Vec<(usize, bool, bool)>,
    /// The work list of [`Walk`], kept between the arcs (empty).
    pub(super) stack: Vec<(Sample, u32)>,
}

impl Line {
    pub(super) fn len(&self) -> usize {
        self.x.len()
    }

    /// Appends the point of `s` with its marks.
    #[inline(always)]
    pub(super) fn push(&mut self, s: &Sample) {
        if s.at_infinity || s.singular {
            self.marks.push((self.x.len(), s.at_infinity, s.singular));
        }
        self.x.push(s.x);
        self.h.push(self.chart.value(&s.x));
    }

    /// Joins the marks `(at_infinity, singular)` to those of point `k`.
    pub(super) fn mark(&mut self, k: usize, at_infinity: bool, singular: bool) {
        if !(at_infinity || singular) {
            return;
        }
        let at = self.marks.partition_point(|m| m.0 < k);
        match self.marks.get_mut(at) {
            Some(m) if m.0 == k => {
                m.1 |= at_infinity;
                m.2 |= singular;
            }
            _ => self.marks.insert(at, (k, at_infinity, singular)),
        }
    }

    /// Removes the last point; its marks.
    pub(super) fn pop(&mut self) -> (bool, bool) {
        self.x.pop();
        self.h.pop();
        match self.marks.last() {
            Some(&(k, inf, sing)) if k == self.x.len() => {
                self.marks.pop();
                (inf, sing)
            }
            _ => (false, false),
        }
    }

    /// Reverses the points from `start` on, with their marks; negated too (with their `h`)
    /// for `negate`, in the same pass.
    pub(super) fn reverse_from(&mut self, start: usize, negate: bool) {
        let end = self.x.len();
        if negate {
            let neg = |v: [f64; 4]| v.map(|c| -c);
            let x = &mut self.x[start..];
            let n = x.len();
            for i in 0..n / 2 {
                let (a, b) = (x[i], x[n - 1 - i]);
                (x[i], x[n - 1 - i]) = (neg(b), neg(a));
            }
            if n % 2 == 1 {
                x[n / 2] = neg(x[n / 2]);
            }
            let h = &mut self.h[start..];
            for i in 0..n / 2 {
                let (a, b) = (h[i], h[n - 1 - i]);
                (h[i], h[n - 1 - i]) = (-b, -a);
            }
            if n % 2 == 1 {
                h[n / 2] = -h[n / 2];
            }
        } else {
            self.x[start..].reverse();
            self.h[start..].reverse();
        }
        let m0 = self.marks.partition_point(|m| m.0 < start);
        for m in &mut self.marks[m0..] {
            m.0 = start + end - 1 - m.0;
        }
        self.marks[m0..].reverse();
    }
}

/// The first grid index `j` in `k..n` whose parameter `θⱼ = t₀ + j·step` satisfies
/// `next ≤ θⱼ + 10⁻¹²` (the test of [`Sampler::arc_into`] for an event at `next`), `n` if
/// none: from the estimate `(next − t₀)/step`, corrected by the test itself, which is
/// monotone in `j` for `step > 0` (rounding is monotone); a scan from `k` otherwise.
pub(super) fn grid_before_event(k: usize, n: usize, (t0, step): (f64, f64), next: f64) -> usize {
    let at_or_after = |j: usize| next <= t0 + step * (j as f64) + 1e-12;
    if !next.is_finite() && next > 0.0 {
        return n;
    }
    if !(step > 0.0 && step.is_finite() && t0.is_finite() && next.is_finite()) {
        return (k..n).find(|&j| at_or_after(j)).unwrap_or(n);
    }
    let est = ((next - t0) / step).clamp(k as f64, n as f64);
    // `est` is within [k, n] (NaN is excluded above); `as` truncates toward zero
    let mut j = (est as usize).clamp(k, n);
    while j > k && at_or_after(j - 1) {
        j -= 1;
    }
    while j < n && !at_or_after(j) {
        j += 1;
    }
    j
}

/// Appends `s` to `line` with its sign chosen so that its dot product with the last point is
/// nonnegative; whether it was negated.
pub(super) fn push_oriented(line: &mut Line, mut s: Sample) -> bool {
    let flip = line.x.last().is_some_and(|l| dot(l, &s.x) < 0.0);
    if flip {
        s.x = s.x.map(|v| -v);
    }
    line.push(&s);
    flip
}

/// The loop of [`Sampler::fast_run`] over the grid points `xs` with `h = value(x)`: how many
/// are taken (each within [`MAX_ANGLE`] of the last and, where the crossings are not known,
/// with `h` of the same sign, nonzero), their `h` oriented pushed to `hs`; the last point
/// taken and its `h` (`walk`'s where none is). In three passes over the run, four points a
/// step where they can be: the angles, the signs of `h`, then `h` stored — the decisions of
/// [`run_of_reference`], point by point, in fewer instructions.
#[inline(always)]
pub(super) fn run_of(
    xs: &[[f64; 4]],
    walk: &Walk,
    hs: &mut Vec<f64>,
    value: impl Fn(&[f64; 4]) -> f64,
) -> (usize, [f64; 4], f64) {
    let cos = MAX_ANGLE.cos();
    // `d ≥ cos > 0`: no change of orientation (false for NaN, a failed point)
    let near = |a: &[f64; 4], b: &[f64; 4]| dot(a, b) >= cos;
    // the angles: the first point too far from the one before it
    let mut k = 0;
    if xs.first().is_some_and(|x| near(&walk.prev.x, x)) {
        k = 1;
        while let Some(w) = xs.get(k - 1..k + 4) {
            // `&` tests all four: no branch each
            if !(near(&w[0], &w[1]) & near(&w[1], &w[2]) & near(&w[2], &w[3]) & near(&w[3], &w[4]))
            {
                break;
            }
            k += 4;
        }
        while k < xs.len() && near(&xs[k - 1], &xs[k]) {
            k += 1;
        }
    }
    let mut hp = walk.h_prev;
    // h at zero or a sign change (or a product below the floats, or `hq = 0`: left to
    // `accept` too, which takes such a point as this loop would)
    let taken = if walk.unknown {
        let xs = &xs[..k];
        let mut j = 0;
        while let Some(q) = xs.get(j..j + 4) {
            let h = [value(&q[0]), value(&q[1]), value(&q[2]), value(&q[3])];
            if !((hp * h[0] > 0.0)
                & (h[0] * h[1] > 0.0)
                & (h[1] * h[2] > 0.0)
                & (h[2] * h[3] > 0.0))
            {
                break;
            }
            hp = h[3];
            j += 4;
        }
        while let Some(x) = xs.get(j) {
            let hq = value(x);
            if (hp * hq).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
                break;
            }
            hp = hq;
            j += 1;
        }
        j
    } else {
        k
    };
    let xs = &xs[..taken];
    // `±1·h` is `±h` exactly (every `h` here is finite)
    let orient = if walk.flip { -1.0 } else { 1.0 };
    hs.extend(xs.iter().map(|x| value(x) * orient));
    match xs.last() {
        Some(x) => (taken, *x, if walk.unknown { hp } else { value(x) }),
        None => (0, walk.prev.x, walk.h_prev),
    }
}

/// [`run_of`] one point at a time (the reference of the tests).
#[cfg(test)]
pub(super) fn run_of_reference(
    xs: &[[f64; 4]],
    walk: &Walk,
    hs: &mut Vec<f64>,
    value: impl Fn(&[f64; 4]) -> f64,
) -> (usize, [f64; 4], f64) {
    let cos = MAX_ANGLE.cos();
    let (mut px, mut hp) = (walk.prev.x, walk.h_prev);
    let mut taken = 0;
    for x in xs {
        let d = dot(&px, x);
        if d.partial_cmp(&cos).is_none_or(|o| o.is_lt()) {
            break;
        }
        let hq = value(x);
        if walk.unknown && (hp * hq).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            break;
        }
        hs.push(if walk.flip { -hq } else { hq });
        hp = hq;
        px = *x;
        taken += 1;
    }
    (taken, px, hp)
}

/// A grid kept for the other sheet: `(t₀, step, n)` as bits, the sheet, its points.
pub(super) type OtherSheet = ((u64, u64, usize), Sheet, Vec<[f64; 4]>);

/// The order in which the affine view visits a polyline: from its first mark on a closed one
/// (`first`; `count` steps, the first point visited again at the end), else from point 0;
/// `special`, ascending, the steps where a mark is met or the loop wraps round to point 0 —
/// between them runs of plain points.
pub(super) struct AffineSteps {
    pub(super) first: usize,
    pub(super) count: usize,
    pub(super) special: Vec<usize>,
}

impl AffineSteps {
    pub(super) fn new(line: &Line, closed: bool) -> AffineSteps {
        let n = line.x.len();
        let (first, count) = match line.marks.first() {
            Some(m) if closed => (m.0, n + 1),
            _ => (0, n),
        };
        let mut special: Vec<usize> = line.marks.iter().map(|m| m.0 - first).collect();
        if closed && !line.marks.is_empty() {
            special.push(n);
            special.push(n - first);
        }
        special.sort_unstable();
        special.dedup();
        AffineSteps {
            first,
            count,
            special,
        }
    }
}
