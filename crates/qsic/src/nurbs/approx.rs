//! B-spline approximations of the real pieces that have no exact rational B-spline (quartic
//! branches in Levin's form `a(u) ± d(u)√s(u)`), with a proved bound on the distance of every
//! point to both surfaces.
//!
//! A piece is sampled ([`crate::param::sample`]: certified points from the exact
//! parameterization, so no branch is missed or jumped), split at its points at infinity and
//! its singular points into branches, each unbounded end clipped just outside the box (the
//! branch followed outward along the curve until it leaves the box, then the crossing found
//! by halving along the curve to within 2⁻²⁰ of the box's diagonal), and each branch fitted
//! ([`super::fit`]) in coordinates centred on it. The control points are the local floats
//! plus the centre, exact dyadics.

use super::fit::{fit_branch, DEGREE};
use super::geometry::{add_scaled, dot, norm, sub, Pair, V3};
use super::{certify::sqrt_up, clamped_knots, num, Accuracy, BoxBounds, LeftOut, NurbsCurve};
use crate::error::Error;
use crate::param::sample::SampledPiece;
use crate::quadric::Quadric;
use crate::Budget;
use qsic_algebra::RBig;

/// A smooth branch of a piece, as points on it in ℝ³.
#[derive(Clone, Debug)]
pub(super) struct Branch {
    /// In order; a closed branch repeats its first point at the end.
    pub points: Vec<V3>,
    /// A closed loop.
    pub closed: bool,
    /// Whether each end runs off to infinity (to be clipped at the box).
    pub to_infinity: [bool; 2],
}

/// The affine point of a unit vector of ℝ⁴ (`None` at infinity or beyond the floats).
fn affine(x: &[f64; 4]) -> Option<V3> {
    let p: V3 = std::array::from_fn(|i| x[i] / x[3]);
    (x[3] != 0.0 && p.iter().all(|v| v.is_finite())).then_some(p)
}

/// The branches of a sampled piece: cut at its points at infinity and its breaks.
pub(super) fn branches_of(piece: &SampledPiece) -> Vec<Branch> {
    let n = piece.points.len();
    if piece.isolated || n < 2 || piece.affine.at_infinity {
        return Vec::new();
    }
    let closed = piece.closed;
    // index 0 of a closed piece stands for the repeated last point too
    let norm_index = |k: usize| if closed && k == n - 1 { 0 } else { k };
    let at_infinity = |k: usize| piece.infinity.contains(&norm_index(k));
    let is_break = |k: usize| piece.breaks.contains(&norm_index(k));
    // the walk around the piece, starting at a point at infinity or a break when there is one
    let start = (0..n - usize::from(closed)).find(|&k| at_infinity(k) || is_break(k));
    let order: Vec<usize> = match (closed, start) {
        (true, Some(s)) => (s..n - 1).chain(0..=s).collect(),
        _ => (0..n).collect(),
    };
    let mut out = Vec::new();
    let mut current: Vec<V3> = Vec::new();
    let mut from_infinity = false;
    for &k in &order {
        if at_infinity(k) {
            if current.len() >= 2 {
                out.push(Branch {
                    points: std::mem::take(&mut current),
                    closed: false,
                    to_infinity: [from_infinity, true],
                });
            }
            current.clear();
            from_infinity = true;
            continue;
        }
        let Some(p) = affine(&piece.points[k]) else {
            continue;
        };
        current.push(p);
        if is_break(k) && current.len() >= 2 {
            out.push(Branch {
                points: std::mem::take(&mut current),
                closed: false,
                to_infinity: [from_infinity, false],
            });
            current.push(p);
            from_infinity = false;
        } else if is_break(k) {
            from_infinity = false;
        }
    }
    if current.len() >= 2 {
        let loop_closed = closed && start.is_none();
        out.push(Branch {
            points: current,
            closed: loop_closed,
            to_infinity: [from_infinity, false],
        });
    }
    out
}

/// The points of a piece the default box holds: every point of a bounded piece, the middle
/// point of each branch of an unbounded one.
pub(super) fn box_points(piece: &SampledPiece) -> Vec<V3> {
    let mut out = Vec::new();
    for b in branches_of(piece) {
        if b.to_infinity.iter().any(|v| *v) {
            out.push(b.points[b.points.len() / 2]);
        } else {
            out.extend_from_slice(&b.points);
        }
    }
    out
}

/// Whether `x` lies in the closed box (floats).
fn inside(x: &V3, lo: &V3, hi: &V3) -> bool {
    (0..3).all(|i| x[i] >= lo[i] && x[i] <= hi[i])
}

/// The branch's end at infinity brought just outside the box: `points` start there (the
/// first point the farthest toward infinity). Returns the points from a point at most
/// `2⁻²⁰` of the box's diagonal outside it on, or `None` when the branch never enters it.
fn clip_start(pair: &Pair, points: &[V3], lo: &V3, hi: &V3) -> Option<Vec<V3>> {
    let local = |x: &V3| -> V3 { std::array::from_fn(|i| x[i] - pair.origin[i]) };
    let (llo, lhi) = (local(lo), local(hi));
    let diag = norm(&sub(hi, lo));
    // the branch beyond its first sampled point, followed outward past the box (coordinates
    // are centred on the box: until it is farther from it than the start by the box's size)
    let reach = norm(&points[0]) + 2.0 * norm(&llo).max(norm(&lhi)) + diag;
    let mut trail = outward(
        pair,
        &points[0],
        &points[1.min(points.len() - 1)],
        reach,
        diag,
    );
    trail.reverse();
    trail.extend_from_slice(points);
    let points = trail;
    let (first, entry) = match points.iter().position(|x| inside(x, &llo, &lhi)) {
        Some(k) => (k, None),
        None => {
            let (k, y) = entry_between(pair, &points, &llo, &lhi)?;
            (k + 1, Some(y))
        }
    };
    // a point outside before the first inside: the trail ends beyond the box
    let mut outer = *points[..first].last()?;
    let mut out: Vec<V3> = entry
        .into_iter()
        .chain(points[first..].iter().copied())
        .collect();
    // halve towards the box's surface; the inner points found are kept, nearest last
    let mut inner: Vec<V3> = Vec::new();
    for _ in 0..60 {
        let p = *inner.last().unwrap_or(&out[0]);
        if norm(&sub(&p, &outer)) <= diag * 2f64.powi(-20) {
            break;
        }
        let guess = add_scaled(&outer, 0.5, &sub(&p, &outer));
        let Some(mid) = pair.midpoint(&outer, &p, &guess) else {
            break;
        };
        if inside(&mid, &llo, &lhi) {
            inner.push(mid);
        } else {
            outer = mid;
        }
    }
    let mut start = vec![outer];
    start.extend(inner.into_iter().rev());
    start.append(&mut out);
    Some(start)
}

/// Whether the segment from `p` to `q`, its chord widened by a quarter of its length on
/// every side (the curve between two sampled points bends off its chord), meets the box.
fn near_box(p: &V3, q: &V3, lo: &V3, hi: &V3) -> bool {
    let margin = norm(&sub(q, p)) / 4.0;
    // the slab test: the parameters of the segment within each widened slab overlap
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for i in 0..3 {
        let (a, b) = (lo[i] - margin, hi[i] + margin);
        let d = q[i] - p[i];
        if d == 0.0 {
            if p[i] < a || p[i] > b {
                return false;
            }
            continue;
        }
        let (u, v) = ((a - p[i]) / d, (b - p[i]) / d);
        t0 = t0.max(u.min(v));
        t1 = t1.min(u.max(v));
    }
    t0 <= t1
}

/// The distance from `x` to the segment from `p` to `q`.
fn to_segment(x: &V3, p: &V3, q: &V3) -> f64 {
    let d = sub(q, p);
    let l2 = dot(&d, &d);
    let t = if l2 > 0.0 {
        (dot(&sub(x, p), &d) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    norm(&sub(x, &add_scaled(p, t, &d)))
}

/// Where the branch enters the box when none of its points lies inside: a point of the curve
/// inside, found by halving along the curve (at most 40 times, keeping a half near the box)
/// between the first two consecutive points near it, and the index of the first of them.
fn entry_between(pair: &Pair, points: &[V3], lo: &V3, hi: &V3) -> Option<(usize, V3)> {
    let centre: V3 = std::array::from_fn(|i| lo[i] / 2.0 + hi[i] / 2.0);
    for k in 0..points.len().saturating_sub(1) {
        let (mut p, mut q) = (points[k], points[k + 1]);
        if !near_box(&p, &q, lo, hi) {
            continue;
        }
        for _ in 0..40 {
            let guess = add_scaled(&p, 0.5, &sub(&q, &p));
            let Some(m) = pair.midpoint(&p, &q, &guess) else {
                break;
            };
            if inside(&m, lo, hi) {
                return Some((k, m));
            }
            // keep the half whose chord passes nearer the box's centre
            if to_segment(&centre, &p, &m) <= to_segment(&centre, &m, &q) {
                q = m;
            } else {
                p = m;
            }
            if !near_box(&p, &q, lo, hi) {
                break;
            }
        }
    }
    None
}

/// Points of the curve followed from `p` away from `prev` in steps that double (at most 200
/// steps): along the tangent, back onto the curve on the plane across it; until one lies
/// farther than `reach` from the origin, or the curve cannot be followed.
fn outward(pair: &Pair, p: &V3, prev: &V3, reach: f64, diag: f64) -> Vec<V3> {
    let mut out = Vec::new();
    let mut p = *p;
    let mut dir = sub(&p, prev);
    let mut h = norm(&dir).max(diag * 1e-3);
    for _ in 0..200 {
        if norm(&p) > reach {
            break;
        }
        let Some(t) = pair.tangent(&p) else {
            break;
        };
        let t = if dot(&t, &dir) < 0.0 {
            t.map(|v| -v)
        } else {
            t
        };
        let guess = add_scaled(&p, h, &t);
        match pair.on_plane(&p, &t, h, &guess) {
            Some(next) if dot(&sub(&next, &p), &t) > 0.0 => {
                dir = sub(&next, &p);
                p = next;
                out.push(p);
                h *= 2.0;
            }
            _ => h /= 4.0,
        }
    }
    out
}

/// The exact point `origin + y` as a homogeneous control point with weight 1.
fn pole(origin: &V3, y: &V3) -> crate::param::Point {
    // finite: the origin is the centre of finite points, and `fit` keeps only segments whose
    // control points are all finite
    let exact = |o: f64, v: f64| {
        num(RBig::try_from(o).expect("finite") + RBig::try_from(v).expect("finite"))
    };
    [
        exact(origin[0], y[0]),
        exact(origin[1], y[1]),
        exact(origin[2], y[2]),
        num(RBig::ONE),
    ]
}

/// The centre of the points' bounding box and its diagonal.
fn extent(points: &[V3]) -> (V3, f64) {
    let lo: V3 = std::array::from_fn(|i| points.iter().map(|p| p[i]).fold(f64::MAX, f64::min));
    let hi: V3 = std::array::from_fn(|i| points.iter().map(|p| p[i]).fold(f64::MIN, f64::max));
    (
        std::array::from_fn(|i| lo[i] / 2.0 + hi[i] / 2.0),
        norm(&sub(&hi, &lo)),
    )
}

/// Everything one piece's approximations need.
pub(super) struct PieceInput<'a> {
    pub piece: usize,
    pub component: usize,
    pub sampled: &'a SampledPiece,
    pub a: &'a Quadric,
    pub b: &'a Quadric,
    pub bounds: &'a BoxBounds,
    /// The distance bound asked for; `None`: 10⁻⁹ of each branch's size.
    pub tolerance: Option<f64>,
}

/// What [`approximate_piece`] gives.
pub(super) struct Approximated {
    /// The curves of the branches fitted.
    pub curves: Vec<NurbsCurve>,
    /// The branches left out, and why.
    pub left: Vec<LeftOut>,
    /// The size of the smallest branch whose fit failed (a denser sample may help).
    pub failed: Option<f64>,
}

/// The NURBS curves of one piece's branches, and what was left out.
///
/// # Errors
/// [`Error::BudgetExceeded`]; a branch that cannot be fitted is left out with the reason.
pub(super) fn approximate_piece(input: &PieceInput, work: &Budget) -> Result<Approximated, Error> {
    // a box beyond the floats is the floats' own box (the branch leaves it all the same)
    let clamp = |v: &RBig| v.to_f64().value().clamp(-f64::MAX / 4.0, f64::MAX / 4.0);
    let lo: V3 = input.bounds.lo.each_ref().map(clamp);
    let hi: V3 = input.bounds.hi.each_ref().map(clamp);
    let box_centre: V3 = std::array::from_fn(|i| lo[i] / 2.0 + hi[i] / 2.0);
    let mut curves = Vec::new();
    let mut left = Vec::new();
    let leave = |reason: String| LeftOut {
        piece: Some(input.piece),
        reason,
    };
    let mut missed = 0;
    let mut failed = None;
    for branch in branches_of(input.sampled) {
        let unbounded = branch.to_infinity.iter().any(|v| *v);
        // unbounded branches are clipped in coordinates centred on the box
        let points = if unbounded {
            let pair = Pair::new(input.a, input.b, box_centre);
            let local: Vec<V3> = branch.points.iter().map(|x| sub(x, &box_centre)).collect();
            let mut pts = Some(local);
            if branch.to_infinity[0] {
                pts = pts.and_then(|p| clip_start(&pair, &p, &lo, &hi));
            }
            if branch.to_infinity[1] {
                pts = pts.and_then(|mut p| {
                    p.reverse();
                    let mut c = clip_start(&pair, &p, &lo, &hi)?;
                    c.reverse();
                    Some(c)
                });
            }
            let pts = pts.unwrap_or_default();
            if pts.len() < 2 {
                missed += 1;
                continue;
            }
            pts.iter()
                .map(|y| add_scaled(&box_centre, 1.0, y))
                .collect()
        } else {
            branch.points.clone()
        };
        let (centre, size) = extent(&points);
        let size = if size > 0.0 { size } else { 1.0 };
        let tol = input.tolerance.unwrap_or(size * 1e-9);
        let pair = Pair::new(input.a, input.b, centre);
        let mut local: Vec<V3> = points
            .iter()
            .map(|x| pair.polish(&sub(x, &centre), size))
            .collect();
        if branch.closed {
            let first = local[0];
            *local.last_mut().expect("two points") = first;
        }
        match fit_branch(&pair, &local, tol, size, work) {
            Ok(fit) => {
                let knots = clamped_knots(DEGREE, (fit.poles.len() - 1) / DEGREE);
                let curve = NurbsCurve {
                    piece: input.piece,
                    component: input.component,
                    degree: DEGREE,
                    knots,
                    poles: fit.poles.iter().map(|y| pole(&centre, y)).collect(),
                    ends: None,
                    clipped: branch.to_infinity,
                    closed: branch.closed,
                    accuracy: Accuracy::Within(sqrt_up(&fit.bound2)),
                };
                debug_assert!(curve.is_valid());
                curves.push(curve);
            }
            Err(e @ Error::BudgetExceeded { .. }) => return Err(e),
            Err(e) => {
                failed = Some(failed.map_or(size, |f: f64| f.min(size)));
                left.push(leave(format!("a branch not approximated: {e}")));
            }
        }
    }
    if missed > 0 {
        left.push(leave(format!(
            "{missed} unbounded branch(es) outside the box"
        )));
    }
    Ok(Approximated {
        curves,
        left,
        failed,
    })
}
