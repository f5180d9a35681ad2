//! The sampler of one component: the initial grid of each arc, the refinement and the marks.
//!
//! Each arc starts from a uniform grid in `θ` ([`Sampler::grid`]; on Levin's form both sheets
//! at once), walked in one pass: a segment is bisected, from a work list, until consecutive
//! unit vectors are within [`MAX_ANGLE`] radians up to sign and, with a tolerance, the chord
//! deviation in the chart is at most the tolerance (where the three points lie within
//! [`AFFINE_RADIUS`] of the origin); at most [`MAX_DEPTH`] bisections of a grid segment. The
//! exact events of the arc (crossings of the plane at infinity, singular points) are placed at
//! their exact parameters and marked ([`Sampler::events`]).

use crate::error::Error;
use crate::param::curve::{Arc, ParamRange, ParamValue, Sheet};
use crate::param::sample::chart::{chord_deviation, dot, Chart};
use crate::param::sample::crossings::{in_range, inner_f64, Crossings};
use crate::param::sample::eval::Evaluator;
use crate::param::sample::kernels::trig::sin_cos;
use crate::param::sample::view::affine_view;
use crate::param::sample::walk::{
    grid_before_event, projective, push_oriented, run_of, span, Approximations, Line, OtherSheet,
    Sample, Walk,
};
use crate::param::sample::{
    AffinePiece, PointBudget, SampledPiece, AFFINE_RADIUS, MAX_ANGLE, MAX_DEPTH, MAX_LOCAL_DEPTH,
};
use qsic_algebra::AlgebraicReal;
use std::cell::{Cell, RefCell};
use std::f64::consts::{FRAC_PI_2, PI};

/// Samples the pieces of one component.
pub(super) struct Sampler<'a> {
    pub(super) eval: Evaluator<'a>,
    pub(super) crossings: Crossings,
    /// The exact parameters of the curve's real singular points on this component, and
    /// whether each point is at infinity.
    pub(super) singular: Vec<(ParamValue, bool)>,
    pub(super) chart: &'a Chart,
    pub(super) tolerance: Option<f64>,
    pub(super) approx: &'a Approximations,
    /// The floats of the arc ends met ([`Sampler::end_value`]), by the end's address in
    /// the curve first (the arcs of an oval share their ends), else by value.
    pub(super) ends: RefCell<Vec<(&'a AlgebraicReal, f64)>>,
    /// The grid of the other sheet made with the last one of Levin's form: `(t₀, step, n)`
    /// as bits, the sheet and its points ([`Evaluator::grid_both`]).
    pub(super) other_sheet: RefCell<Option<OtherSheet>>,
    /// Where the floats lost the curve, if they did: the `θ` of the last error of the walk
    /// that a local parameter may cure ([`super::local`]).
    pub(super) stuck: Cell<Option<f64>>,
    /// Bisect towards `θ = 0` geometrically: the sampler of a local parameter
    /// ([`super::local`]), whose cluster lies at the origin at a scale far below the grid's.
    pub(super) geometric: bool,
}

impl<'a> Sampler<'a> {
    /// The grid of `sheet` on `θₖ = t₀ + k·step` ([`Evaluator::grid`]): on Levin's form both
    /// sheets at once, the other kept for an arc over the same range.
    pub(super) fn grid(&self, t0: f64, step: f64, n: usize, sheet: Sheet, out: &mut Vec<[f64; 4]>) {
        if !self.eval.levin {
            return self.eval.grid(t0, step, n, sheet, out);
        }
        let key = (t0.to_bits(), step.to_bits(), n);
        let mut cache = self.other_sheet.borrow_mut();
        if let Some((k, s, _)) = cache.as_ref() {
            if *k == key && *s == sheet {
                let (_, _, v) = cache.take().expect("checked");
                *out = v;
                return;
            }
        }
        let mut other = cache.take().map(|(_, _, v)| v).unwrap_or_default();
        let other_sheet = if sheet == Sheet::Minus {
            self.eval.grid_both(t0, step, n, &mut other, out);
            Sheet::Plus
        } else {
            self.eval.grid_both(t0, step, n, out, &mut other);
            Sheet::Minus
        };
        *cache = Some((key, other_sheet, other));
    }

    /// A float of an arc end `r`: on Levin's form a root of `s`, found by Newton's method on
    /// `s` inside the isolating interval of `r` (one simple root of `s` there);
    /// [`AlgebraicReal::to_f64`] (once per call) where that does not bracket it or is
    /// ill-conditioned.
    pub(super) fn end_value(&self, r: &'a AlgebraicReal) -> f64 {
        // the two sheets of an oval share their ends: each found once
        let known = self
            .ends
            .borrow()
            .iter()
            .find_map(|(q, v)| (std::ptr::eq(*q, r) || q.same_definition(r)).then_some(*v));
        known.unwrap_or_else(|| {
            let v = self.end_value_uncached(r);
            self.ends.borrow_mut().push((r, v));
            v
        })
    }

    /// [`Sampler::end_value`] computed.
    pub(super) fn end_value_uncached(&self, r: &AlgebraicReal) -> f64 {
        if let (true, qsic_algebra::roots::RootInterval::Open(lo, hi)) =
            (self.eval.levin, r.interval())
        {
            // floats inside the isolating interval (one root of `s` there): a bracket
            // `root_of_s` checks, empty where the interval is below the floats' resolution
            let (l, h) = (inner_f64(lo, true), inner_f64(hi, false));
            if let Some(v) = self.eval.root_of_s(l, h) {
                return v;
            }
        }
        self.approx.of(r)
    }

    /// The point at `θ` on `sheet`, retried at nearby parameters inside `(lo, hi)` where
    /// rounding is too large.
    pub(super) fn at(&self, theta: f64, lo: f64, hi: f64, sheet: Sheet) -> Result<Sample, Error> {
        let (s, c) = sin_cos(theta);
        self.at_u(theta, (s, c), lo, hi, sheet)
    }

    /// [`Sampler::at`] with `u ≈ (sin θ, cos θ)` given (up to a positive factor).
    pub(super) fn at_u(
        &self,
        theta: f64,
        u: (f64, f64),
        lo: f64,
        hi: f64,
        sheet: Sheet,
    ) -> Result<Sample, Error> {
        if let Some(x) = self.eval.eval_unit(u, sheet) {
            return Ok(Sample::new(theta, x));
        }
        let offsets = [1e-6, -1e-6, 1e-3, -1e-3, 0.03, -0.03, 0.2, -0.2];
        for f in offsets {
            let t = theta + f * (hi - lo);
            if !(lo < t && t < hi) {
                continue;
            }
            if let Some(x) = self.eval.eval_unit(sin_cos(t), sheet) {
                return Ok(Sample::new(t, x));
            }
        }
        self.stuck.set(Some(theta));
        Err(Error::Algebra(format!(
            "no well-conditioned point near θ = {theta} in ({lo}, {hi})"
        )))
    }

    /// The point at an exact end of an arc (`u` on ℙ¹), nudged inwards if needed.
    pub(super) fn at_end(
        &self,
        u: (f64, f64),
        theta: f64,
        other: f64,
        sheet: Sheet,
    ) -> Result<Sample, Error> {
        if let Some(x) = self.eval.eval_unit(u, sheet) {
            return Ok(Sample::new(theta, x));
        }
        // a nudged end may leave a gap to the next arc: a local parameter there closes it
        // if the turns say so ([`super::sample_within`])
        self.stuck.set(Some(theta));
        for f in [1e-9, 1e-6, 1e-3] {
            let t = theta + f * (other - theta);
            if let Some(x) = self.eval.eval_unit(sin_cos(t), sheet) {
                return Ok(Sample::new(t, x));
            }
        }
        self.stuck.set(Some(theta));
        Err(Error::Algebra(format!(
            "no well-conditioned point near the end θ = {theta}"
        )))
    }

    /// Most bisections of a grid segment: [`MAX_DEPTH`], or [`MAX_LOCAL_DEPTH`] for a
    /// [`Sampler::geometric`] one (its features lie far below the grid's scale).
    pub(super) fn max_depth(&self) -> u32 {
        if self.geometric {
            MAX_LOCAL_DEPTH
        } else {
            MAX_DEPTH
        }
    }

    /// The parameter between `lo < hi` where a segment is split: the middle, or for a
    /// [`Sampler::geometric`] sampler the geometric mean where both lie on one side of 0 more
    /// than a factor 8 apart (the origin reached in `log log` steps, not `log`).
    pub(super) fn midpoint(&self, lo: f64, hi: f64) -> f64 {
        let (a, b) = (lo.abs().min(hi.abs()), lo.abs().max(hi.abs()));
        if self.geometric && lo * hi > 0.0 && b > 8.0 * a {
            (a.sqrt() * b.sqrt()).copysign(lo)
        } else {
            0.5 * (lo + hi)
        }
    }

    /// Whether the segment `p, q` needs a point between them; computes it if so.
    pub(super) fn split(
        &self,
        p: &Sample,
        q: &Sample,
        sheet: Sheet,
    ) -> Result<Option<Sample>, Error> {
        let d = dot(&p.x, &q.x);
        let far = d.abs() < MAX_ANGLE.cos();
        // nearly opposite vectors are one projective point, but the vector may have swung
        // all the way round between them (a direction term dominating a line's point term):
        // the midpoint tells, close to both or not
        let opposite = d < 0.0;
        if !far && !opposite && self.tolerance.is_none() {
            return Ok(None);
        }
        let (lo, hi) = (p.theta.min(q.theta), p.theta.max(q.theta));
        let m = self.at(self.midpoint(lo, hi), lo, hi, sheet)?;
        let swung = opposite
            && (dot(&m.x, &p.x).abs() < MAX_ANGLE.cos() || dot(&m.x, &q.x).abs() < MAX_ANGLE.cos());
        if far || swung {
            return Ok(Some(m));
        }
        // no chord can exceed an infinite tolerance
        let Some(tol) = self.tolerance else {
            return Ok(None);
        };
        let (Some(a), Some(b), Some(c)) = (
            self.chart.affine(&p.x),
            self.chart.affine(&q.x),
            self.chart.affine(&m.x),
        ) else {
            return Ok(None);
        };
        let norm = |v: &[f64; 3]| v.iter().map(|t| t * t).sum::<f64>().sqrt();
        if norm(&a).max(norm(&b)).max(norm(&c)) > AFFINE_RADIUS {
            return Ok(None);
        }
        Ok((chord_deviation(&a, &b, &c) > tol).then_some(m))
    }

    /// The exact events on one arc (crossings of the plane at infinity, singular points),
    /// as marked samples in increasing `θ` strictly inside `(t0, t1)`, and the marks of the
    /// two ends `(first, last)`.
    #[allow(clippy::type_complexity)]
    pub(super) fn events(
        &self,
        arc: &Arc,
        (t0, t1): (f64, f64),
        n: usize,
        sheet: Sheet,
    ) -> Result<(Vec<Sample>, [(bool, bool); 2]), Error> {
        // (parameter, singular, at infinity)
        let mut values: Vec<(&ParamValue, bool, bool)> = Vec::new();
        if let Crossings::Exact(crossings) = &self.crossings {
            for c in crossings {
                if c.sheets.contains(&sheet) {
                    values.push((&c.value, false, true));
                }
            }
        }
        values.extend(self.singular.iter().map(|(v, inf)| (v, true, *inf)));
        let mut inner: Vec<Sample> = Vec::new();
        let mut ends = [(false, false); 2];
        for (value, singular, at_infinity) in values {
            if !in_range(value, &arc.range) {
                continue;
            }
            let (u, mut th) = match value {
                ParamValue::Infinity => ((1.0, 0.0), FRAC_PI_2),
                ParamValue::Finite(r) => {
                    let v = self.approx.of(r);
                    (projective(v), v.atan())
                }
            };
            if th < t0 - 1e-12 {
                th += PI;
            }
            if th > t1 + 1e-12 && (th - PI) >= t0 - 1e-12 {
                th -= PI;
            }
            let th = th.clamp(t0, t1);
            let mark = |g: &mut (bool, bool)| {
                g.0 |= at_infinity;
                g.1 |= singular;
            };
            // an end of the arc, or a new point in order
            if (th - t0).abs() <= 1e-12 {
                mark(&mut ends[0]);
                continue;
            }
            if (th - t1).abs() <= 1e-12 {
                mark(&mut ends[1]);
                continue;
            }
            let other = if th - t0 < t1 - th { t1 } else { t0 };
            let s = self.at_end(u, th, other, sheet)?;
            let mut m = (false, false);
            mark(&mut m);
            if let Some(g) = inner
                .iter_mut()
                .find(|g| (g.theta - s.theta).abs() <= 1e-12)
            {
                // the same parameter as an event already placed (a singular point at
                // infinity): one point with both marks
                g.at_infinity |= m.0;
                g.singular |= m.1;
            } else {
                let at = inner.partition_point(|g| g.theta <= s.theta);
                inner.insert(
                    at,
                    Sample {
                        at_infinity: m.0,
                        singular: m.1,
                        ..s
                    },
                );
            }
        }
        // on the whole line the two ends are one point
        if matches!(arc.range, ParamRange::All) {
            let both = (ends[0].0 | ends[1].0, ends[0].1 | ends[1].1);
            ends = [both, both];
        }
        // a point between two consecutive events with no grid point between them, so that
        // every branch they cut has a point of its own besides its ends
        let step = (t1 - t0) / (n as f64);
        let grid_between = |a: f64, b: f64| {
            let k = ((a - t0) / step).floor() + 1.0;
            t0 + k * step < b - 1e-12 && k < n as f64
        };
        let mut marked: Vec<f64> = Vec::with_capacity(inner.len() + 2);
        if ends[0] != (false, false) {
            marked.push(t0);
        }
        marked.extend(inner.iter().map(|g| g.theta));
        if ends[1] != (false, false) {
            marked.push(t1);
        }
        for w in marked.windows(2) {
            if w[1] > w[0] && !grid_between(w[0], w[1]) {
                let th = 0.5 * (w[0] + w[1]);
                let m = self.at(th, w[0], w[1], sheet)?;
                let at = inner.partition_point(|g| g.theta <= m.theta);
                inner.insert(at, m);
            }
        }
        Ok((inner, ends))
    }

    /// Appends the polyline of one arc to `line`, in increasing `θ` (reversed for a reversed
    /// arc), with its exact crossings inserted; its first point is left out when it is the
    /// point `line` ends with (consecutive arcs share their end point unless one end was
    /// nudged), the marks joined.
    pub(super) fn arc_into(
        &self,
        arc: &'a Arc,
        n: usize,
        budget: &mut PointBudget<'_>,
        line: &mut Line,
    ) -> Result<(), Error> {
        let sp = span(&arc.range, &|r| self.end_value(r))?;
        let (t0, t1) = sp.theta;
        let sheet = arc.sheet;
        if self.eval.levin == (sheet == Sheet::Only) {
            return Err(Error::Algebra(
                "an arc's sheet does not match its parameterization".into(),
            ));
        }
        let (events, ends) = self.events(arc, sp.theta, n, sheet)?;
        budget.take(n + 1 + events.len())?;
        let marked = |mut s: Sample, (inf, sing): (bool, bool)| {
            s.at_infinity |= inf;
            s.singular |= sing;
            s
        };
        let first = marked(self.at_end(sp.ends.0, t0, t1, sheet)?, ends[0]);
        let last = marked(self.at_end(sp.ends.1, t1, t0, sheet)?, ends[1]);
        let start = line.len();
        line.x.reserve(n + n / 8 + events.len() + 4);
        line.h.reserve(n + n / 8 + events.len() + 4);
        let joins = |a: &[f64; 4], b: &[f64; 4]| dot(a, b).abs() >= 1.0 - 1e-12;
        let flip = match line.x.last() {
            Some(&l) if !arc.reversed && joins(&l, &first.x) => {
                line.mark(start - 1, first.at_infinity, first.singular);
                dot(&l, &first.x) < 0.0
            }
            _ => push_oriented(line, first),
        };
        let mut walk = Walk {
            prev: first,
            h_prev: self.chart.value(&first.x),
            stack: std::mem::take(&mut line.stack),
            unknown: matches!(self.crossings, Crossings::Unknown),
            flip,
        };
        let step = (t1 - t0) / (n as f64);
        let mut grid = Vec::new();
        self.grid(t0, step, n, sheet, &mut grid);
        let mut ei = 0;
        let event_theta = |ei: usize| events.get(ei).map_or(f64::INFINITY, |e| e.theta);
        let mut next = event_theta(0);
        let mut k = 1;
        while k <= n {
            if k < n && self.tolerance.is_none() {
                k = self.fast_run(&mut walk, &grid, k, n, (t0, step), next, line);
            }
            let g = if k < n {
                let th = t0 + step * (k as f64);
                let x = grid[k - 1];
                if x[0].is_nan() {
                    self.at(th, t0, t1, sheet)?
                } else {
                    Sample::new(th, x)
                }
            } else {
                last
            };
            // an event goes before the first grid point at or after it; a grid point at the
            // event's parameter is the same point (left out: its rounding could mark it)
            if next <= g.theta + 1e-12 {
                let mut same = false;
                while next <= g.theta + 1e-12 {
                    let e = events[ei];
                    same |= k < n && (g.theta - e.theta).abs() <= 1e-12;
                    self.walk_to(&mut walk, e, sheet, budget, line)?;
                    ei += 1;
                    next = event_theta(ei);
                }
                if same {
                    k += 1;
                    continue;
                }
            }
            self.walk_to(&mut walk, g, sheet, budget, line)?;
            k += 1;
        }
        for e in &events[ei..] {
            self.walk_to(&mut walk, *e, sheet, budget, line)?;
        }
        line.stack = walk.stack;
        if arc.reversed {
            let x = &line.x;
            if start > 0 && x.len() > start + 1 && joins(&x[start - 1], &x[x.len() - 1]) {
                let (inf, sing) = line.pop();
                line.mark(start - 1, inf, sing);
            }
            // oriented within the arc; the whole arc negated where it meets the line reversed
            // (its last point comes first)
            let x = &line.x;
            let negate = start > 0 && x.len() > start && dot(&x[start - 1], &x[x.len() - 1]) < 0.0;
            line.reverse_from(start, negate);
        }
        Ok(())
    }

    /// The usual case of [`Sampler::walk_to`] on the grid points `k, k + 1, …` (`grid[k − 1]`
    /// at `θ = t₀ + k·step`) before the next event (at `next`) without a tolerance: each
    /// within [`MAX_ANGLE`] of the last and, where the crossings are not known exactly, with
    /// no sign change of `h`; appended oriented. Returns the first grid index not taken.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    pub(super) fn fast_run(
        &self,
        walk: &mut Walk,
        grid: &[[f64; 4]],
        mut k: usize,
        n: usize,
        (t0, step): (f64, f64),
        next: f64,
        line: &mut Line,
    ) -> usize {
        // a point known exactly to be at infinity is left to `accept`
        if walk.unknown && walk.prev.at_infinity {
            return k;
        }
        let end = grid_before_event(k, n, (t0, step), next);
        let xs = &grid[k - 1..end - 1];
        // the loop made once per form of `h` (the same values as `ChartForm::value`)
        let form = self.chart.form;
        let (taken, px, hp) = match form.single {
            Some((j, c)) => run_of(xs, walk, &mut line.h, |x| c * x[j & 3]),
            None => run_of(xs, walk, &mut line.h, |x| dot(&form.h, x)),
        };
        let xs = &xs[..taken];
        let flip = walk.flip;
        line.x
            .extend(xs.iter().map(|x| if flip { x.map(|v| -v) } else { *x }));
        if taken > 0 {
            k += taken;
            walk.prev = Sample::new(t0 + step * ((k - 1) as f64), px);
            walk.h_prev = hp;
        }
        k
    }

    /// Extends the polyline from `walk.prev` to `q`: bisected until [`Sampler::split`] is
    /// satisfied, and, where the crossings are not known exactly, with the crossings of the
    /// plane at infinity located between consecutive points.
    #[inline(always)]
    pub(super) fn walk_to(
        &self,
        walk: &mut Walk,
        q: Sample,
        sheet: Sheet,
        budget: &mut PointBudget<'_>,
        line: &mut Line,
    ) -> Result<(), Error> {
        let d = dot(&walk.prev.x, &q.x);
        if self.tolerance.is_none() && d >= MAX_ANGLE.cos() {
            // close enough and not opposite: the usual case, no split
            return self.accept(walk, q, d, sheet, line);
        }
        self.walk_split(walk, q, sheet, budget, line)
    }

    /// [`Sampler::walk_to`] where the segment may need points.
    #[inline(never)]
    pub(super) fn walk_split(
        &self,
        walk: &mut Walk,
        q: Sample,
        sheet: Sheet,
        budget: &mut PointBudget<'_>,
        line: &mut Line,
    ) -> Result<(), Error> {
        walk.stack.push((q, 0));
        while let Some((q, depth)) = walk.stack.pop() {
            let p = walk.prev;
            match self.split(&p, &q, sheet)? {
                Some(m) if depth < self.max_depth() => {
                    budget.take(1)?;
                    walk.stack.push((q, depth + 1));
                    walk.stack.push((m, depth + 1));
                }
                Some(_) => {
                    self.stuck.set(Some(p.theta));
                    return Err(Error::Algebra(format!(
                        "sampling did not converge near θ = {}",
                        p.theta
                    )));
                }
                None => self.accept(walk, q, dot(&p.x, &q.x), sheet, line)?,
            }
        }
        Ok(())
    }

    /// Appends `q` after `walk.prev` (`d` their dot product), with the crossing between
    /// them where the crossings are not known exactly.
    #[inline(always)]
    pub(super) fn accept(
        &self,
        walk: &mut Walk,
        q: Sample,
        d: f64,
        sheet: Sheet,
        line: &mut Line,
    ) -> Result<(), Error> {
        let pushed = line.len();
        if walk.unknown {
            let hp = walk.h_prev;
            let hq = self.chart.value(&q.x);
            // a point known exactly to be at infinity (a singular point there) is the
            // crossing: the rounding of h near it says nothing
            let exact_end = walk.prev.at_infinity || q.at_infinity;
            if hp == 0.0 {
                if line.len() > 0 {
                    line.mark(line.len() - 1, true, false);
                }
            } else if !exact_end {
                let hq_along = if d < 0.0 { -hq } else { hq };
                if hq_along != 0.0 && (hp > 0.0) != (hq_along > 0.0) {
                    if let Some(c) = self.float_crossing(&walk.prev, hp, &q, sheet)? {
                        // a singular point next to the crossing keeps a point of its own
                        // between them: the affine branch it starts has one besides its end
                        let mid = |a: &Sample, b: &Sample| -> Result<Option<Sample>, Error> {
                            if a.theta == b.theta {
                                return Ok(None);
                            }
                            let (lo, hi) = (a.theta.min(b.theta), a.theta.max(b.theta));
                            self.at(0.5 * (lo + hi), lo, hi, sheet).map(Some)
                        };
                        if walk.prev.singular {
                            if let Some(m) = mid(&walk.prev, &c)? {
                                push_oriented(line, m);
                            }
                        }
                        push_oriented(line, c);
                        if q.singular {
                            if let Some(m) = mid(&c, &q)? {
                                push_oriented(line, m);
                            }
                        }
                    }
                }
            }
            walk.h_prev = hq;
        }
        if line.len() == pushed {
            // oriented against the last point: `d` is the dot product with its raw vector
            let flip = (d < 0.0) != walk.flip;
            line.push(&if flip {
                Sample {
                    x: q.x.map(|v| -v),
                    ..q
                }
            } else {
                q
            });
            walk.flip = flip;
        } else {
            walk.flip = push_oriented(line, q);
        }
        walk.prev = q;
        Ok(())
    }

    /// The sampled piece: its arcs joined, oriented, closed, and its affine view.
    pub(super) fn piece(
        &self,
        component: usize,
        arcs: &'a [Arc],
        closed: bool,
        points: usize,
        budget: &mut PointBudget<'_>,
    ) -> Result<SampledPiece, Error> {
        let n = points.div_ceil(arcs.len().max(1)).max(8) + 1;
        let mut line = Line {
            x: Vec::with_capacity(arcs.len() * (n + n / 8 + 8)),
            h: Vec::with_capacity(arcs.len() * (n + n / 8 + 8)),
            chart: self.chart.form,
            marks: Vec::new(),
            stack: Vec::new(),
        };
        for arc in arcs {
            self.arc_into(arc, n, budget, &mut line)?;
        }
        if closed && line.len() > 1 {
            let (inf, sing) = line.pop();
            line.mark(0, inf, sing);
        }
        // oriented as walked: consecutive dot products nonnegative
        let affine = if matches!(self.crossings, Crossings::InPlane) {
            AffinePiece {
                branches: Vec::new(),
                bounded: false,
                points_at_infinity: Vec::new(),
                at_infinity: true,
                indices: Vec::new(),
            }
        } else {
            let affine = affine_view(self.chart, &line, closed);
            // the stored `h` is the chart's value at every point, and the view is the one
            // built point by point from it
            debug_assert!(line.h.len() == line.x.len());
            debug_assert!((line.h.iter().zip(&line.x)).all(|(h, x)| *h == dot(&self.chart.h, x)));
            #[cfg(debug_assertions)]
            assert_eq!(
                affine,
                super::view::affine_view_two_pass(self.chart, &line, closed)
            );
            affine
        };
        let breaks = line.marks.iter().filter(|m| m.2).map(|m| m.0).collect();
        let infinity = if affine.at_infinity {
            Vec::new()
        } else {
            line.marks.iter().filter(|m| m.1).map(|m| m.0).collect()
        };
        let mut pts = line.x;
        if closed && !pts.is_empty() {
            let first = pts[0];
            let last = pts[pts.len() - 1];
            pts.push(if dot(&first, &last) < 0.0 {
                first.map(|v| -v)
            } else {
                first
            });
        }
        Ok(SampledPiece {
            component,
            isolated: false,
            points: pts,
            closed,
            breaks,
            infinity,
            affine,
        })
    }

    /// The crossing of the plane at infinity between consecutive points `p` (where
    /// `h = hp ≠ 0`) and `q` of one arc, if `h` changes sign there (up to the sign of the
    /// vectors), located by regula falsi on the parameter with the Illinois weighting
    /// (bisection where the secant leaves the bracket), until the bracket or `h` is at the
    /// rounding level.
    pub(super) fn float_crossing(
        &self,
        p: &Sample,
        hp: f64,
        q: &Sample,
        sheet: Sheet,
    ) -> Result<Option<Sample>, Error> {
        let oriented = |x: [f64; 4]| {
            if dot(&x, &p.x) < 0.0 {
                x.map(|v| -v)
            } else {
                x
            }
        };
        let hq = self.chart.value(&oriented(q.x));
        if hq == 0.0 || (hp > 0.0) == (hq > 0.0) {
            return Ok(None);
        }
        let noise = 8.0 * f64::EPSILON * self.chart.h.iter().map(|v| v.abs()).sum::<f64>();
        let (mut lo, mut hi) = (*p, *q);
        let (mut flo, mut fhi) = (hp, hq);
        let mut kept = 0i8;
        for _ in 0..100 {
            let (a, b) = (lo.theta.min(hi.theta), lo.theta.max(hi.theta));
            if b - a <= 1e-15 * (1.0 + a.abs()) {
                break;
            }
            let mut th = (lo.theta * fhi - hi.theta * flo) / (fhi - flo);
            if !(a < th && th < b) {
                th = 0.5 * (a + b);
            }
            let m = self.at(th, a, b, sheet)?;
            let hm = self.chart.value(&oriented(m.x));
            if (hm > 0.0) == (hp > 0.0) {
                (lo, flo) = (m, hm);
                if kept == 1 {
                    fhi *= 0.5;
                }
                kept = 1;
            } else {
                (hi, fhi) = (m, hm);
                if kept == -1 {
                    flo *= 0.5;
                }
                kept = -1;
            }
            if hm.abs() <= noise {
                break;
            }
        }
        let mut c = if self.chart.value(&lo.x).abs() <= self.chart.value(&hi.x).abs() {
            lo
        } else {
            hi
        };
        c.at_infinity = true;
        Ok(Some(c))
    }
}
