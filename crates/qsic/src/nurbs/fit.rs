//! One smooth branch, given as points on it in order, as a B-spline of degree [`DEGREE`] whose
//! distance to both surfaces is proved below a tolerance.
//!
//! **Segments.** Between two points `p`, `q` of the branch, with the chord parameter
//! `t = c·(x − p)`, `c = (q − p)/L`, the branch is a graph `x(t)`, `t ∈ [0, L]`, as long as it
//! turns less than 60° from `c` ([`Pair::derivatives`]). The segment is the Hermite
//! interpolant of `x, x′, x″, x‴` at both ends, degree 7; in Bézier form, with `τ = t/L`,
//! `Pⱼ = Σ_{i≤j} C(j, i)·(n−i)!/n!·Lⁱ x⁽ⁱ⁾(0)` and symmetrically from the end with `(−L)ⁱ`
//! ([`hermite`]). Where the surfaces are tangent at an end (a singular point of the curve)
//! that end gives its position only; the interpolant has the lower degree and is raised to 7.
//! The interpolation error is `O(L⁸)`, about `(L/2.5R)⁸` for a radius of curvature `R` (the
//! chord parameter is singular where the branch turns across the chord): a circle takes 32
//! segments at 10⁻⁹ of its radius, 16 at 10⁻⁶.
//!
//! **Refinement.** A span of consecutive points is first tried as one segment; where the
//! branch is no graph over the chord, or the certificate ([`super::certify`]) misses the
//! tolerance, it is split at its middle point, and a span of two points at the point of the
//! curve halfway along the chord ([`Pair::midpoint`]), at most [`MAX_SPLITS`] times. Segments
//! share their end points exactly (the same floats), so the curve is one B-spline with
//! knots `0, 1, …, m` of multiplicity 7 inside.

use super::certify::segment_bound;
use super::geometry::{add_scaled, dot, norm, sub, Jet, Pair, V3};
use crate::error::Error;
use crate::Budget;
use qsic_algebra::RBig;

/// The degree of every approximating segment.
pub const DEGREE: usize = 7;
/// Most halvings of a span between two consecutive points of the branch.
pub const MAX_SPLITS: u32 = 48;
/// Most segments of one branch.
pub const MAX_SEGMENTS: usize = 1 << 14;
/// Work units of one tried segment (its two certificates: a few thousand products of
/// integers of a few hundred bits).
pub const TRY_UNITS: u64 = 2_000;

/// A fitted branch.
#[derive(Clone, Debug)]
pub(super) struct Fit {
    /// The control points in local coordinates, `DEGREE·m + 1` of them.
    pub poles: Vec<V3>,
    /// The square of the proved distance bound, the largest over the segments.
    pub bound2: RBig,
}

/// `n!/(n − i)!`.
fn falling(n: usize, i: usize) -> f64 {
    (0..i).map(|k| (n - k) as f64).product()
}

/// `C(j, i)`.
fn choose(j: usize, i: usize) -> f64 {
    (0..i).map(|k| (j - k) as f64 / (k + 1) as f64).product()
}

/// The Bézier control points of the Hermite interpolant of the jets `a` (at `τ = 0`) and
/// `b` (at `τ = 1`) over a chord parameter of length `len`, raised to [`DEGREE`].
pub(super) fn hermite(a: &Jet, b: &Jet, len: f64) -> Vec<V3> {
    let n = a.order + b.order + 1;
    let mut p = vec![[0.0; 3]; n + 1];
    for (jet, sign, from_start) in [(a, 1.0, true), (b, -1.0, false)] {
        for j in 0..=jet.order {
            let mut v = [0.0; 3];
            let mut h = 1.0;
            for i in 0..=j {
                v = add_scaled(&v, choose(j, i) * h / falling(n, i), &jet.d[i]);
                h *= sign * len;
            }
            p[if from_start { j } else { n - j }] = v;
        }
    }
    while p.len() < DEGREE + 1 {
        p = elevate(&p);
    }
    p
}

/// The same Bézier curve one degree higher: `Qᵢ = (i/(n+1))Pᵢ₋₁ + (1 − i/(n+1))Pᵢ`; the
/// end points are kept exactly.
fn elevate(p: &[V3]) -> Vec<V3> {
    let n = p.len() - 1;
    let mut q = Vec::with_capacity(n + 2);
    q.push(p[0]);
    for i in 1..=n {
        let k = i as f64 / (n + 1) as f64;
        q.push(std::array::from_fn(|c| {
            k * p[i - 1][c] + (1.0 - k) * p[i][c]
        }));
    }
    q.push(p[n]);
    q
}

/// The Bézier curve at `τ` (de Casteljau).
pub(super) fn bezier_at(p: &[V3], tau: f64) -> V3 {
    let mut w = p.to_vec();
    for k in (1..w.len()).rev() {
        for i in 0..k {
            w[i] = std::array::from_fn(|c| (1.0 - tau) * w[i][c] + tau * w[i + 1][c]);
        }
    }
    w[0]
}

/// What one try of a span gives.
enum Try {
    /// The segment and its squared bound, within the tolerance.
    Within(Vec<V3>, RBig),
    /// Not within: split, starting the midpoint's search at this point if there is one.
    Split(Option<V3>),
}

/// One segment over the span `pts` (its first and last points the ends, the others checked
/// to lie in order along the chord).
fn try_span(pair: &Pair, pts: &[V3], tol2: &RBig) -> Try {
    let (p, q) = (pts[0], pts[pts.len() - 1]);
    let chord = sub(&q, &p);
    let len = norm(&chord);
    if len.is_nan() || len <= 0.0 {
        return Try::Split(None);
    }
    let c = chord.map(|v| v / len);
    let mut last = 0.0;
    for x in &pts[1..pts.len() - 1] {
        let t = dot(&c, &sub(x, &p));
        if !(t > last && t < len) {
            return Try::Split(None);
        }
        last = t;
    }
    let (Some(ja), Some(jb)) = (pair.derivatives(&p, &c), pair.derivatives(&q, &c)) else {
        return Try::Split(None);
    };
    let poles = hermite(&ja, &jb, len);
    if !poles.iter().flatten().all(|v| v.is_finite()) {
        return Try::Split(None);
    }
    let guess = bezier_at(&poles, 0.5);
    let mut worst = RBig::ZERO;
    for q in &pair.exact {
        match segment_bound(q, &poles) {
            Some(b) if b <= *tol2 => worst = worst.max(b),
            _ => return Try::Split(Some(guess)),
        }
    }
    Try::Within(poles, worst)
}

/// A point of the curve near `guess` (least-norm steps) strictly inside the chord from `p`
/// to `q`: its chord coordinate within the middle 80 %.
fn between(pair: &Pair, p: &V3, q: &V3, guess: &V3, len: f64) -> Option<V3> {
    let y = pair.polish(guess, len);
    let c = sub(q, p).map(|v| v / len);
    let t = dot(&c, &sub(&y, p));
    let on = pair.residuals(&y).iter().all(|r| r.abs() <= 1e-12);
    (on && t > 0.1 * len && t < 0.9 * len).then_some(y)
}

/// The branch through `points` (local coordinates, on the curve, in order; a closed branch
/// repeats its first point at the end) as one B-spline within `tol` of both surfaces;
/// `scale` is the branch's size.
///
/// # Errors
/// [`Error::Algebra`] naming the place where the tolerance is not reached within
/// [`MAX_SPLITS`] halvings (or the floats cannot place a point between two), or
/// [`MAX_SEGMENTS`] are not enough; [`Error::BudgetExceeded`].
pub(super) fn fit_branch(
    pair: &Pair,
    points: &[V3],
    tol: f64,
    scale: f64,
    work: &Budget,
) -> Result<Fit, Error> {
    debug_assert!(points.len() >= 2);
    let tol2 = RBig::try_from(tol).map_err(|_| Error::InvalidOption(format!("tolerance {tol}")))?;
    let tol2 = &tol2 * &tol2;
    let global = |y: &V3| -> V3 { std::array::from_fn(|i| pair.origin[i] + y[i]) };
    let mut poles: Vec<V3> = vec![points[0]];
    let mut bound2 = RBig::ZERO;
    let mut segments = 0usize;
    // spans still to fit, the next on top; each with its halvings so far
    let mut stack: Vec<(Vec<V3>, u32)> = vec![(points.to_vec(), 0)];
    while let Some((span, depth)) = stack.pop() {
        work.spend(TRY_UNITS)?;
        match try_span(pair, &span, &tol2) {
            Try::Within(seg, b) => {
                segments += 1;
                if segments > MAX_SEGMENTS {
                    return Err(Error::Algebra(format!(
                        "more than {MAX_SEGMENTS} segments for one branch at tolerance {tol:e}"
                    )));
                }
                debug_assert!(seg[0] == *poles.last().expect("the start"));
                poles.extend_from_slice(&seg[1..]);
                bound2 = bound2.max(b);
            }
            Try::Split(guess) => {
                let (p, q) = (span[0], span[span.len() - 1]);
                if span.len() >= 3 {
                    let m = span.len() / 2;
                    stack.push((span[m..].to_vec(), depth));
                    stack.push((span[..=m].to_vec(), depth));
                    continue;
                }
                let x = global(&p);
                let len = norm(&sub(&q, &p));
                let too_fine = len < scale * 2f64.powi(-44);
                let mid = if depth >= MAX_SPLITS || too_fine {
                    None
                } else {
                    let chord_mid = add_scaled(&p, 0.5, &sub(&q, &p));
                    let guess = guess.unwrap_or(chord_mid);
                    pair.midpoint(&p, &q, &guess)
                        .or_else(|| pair.midpoint(&p, &q, &chord_mid))
                        .or_else(|| between(pair, &p, &q, &guess, len))
                };
                let Some(mid) = mid else {
                    return Err(Error::Algebra(format!(
                        "the B-spline does not come within {tol:e} of the surfaces near \
                         ({:.6e}, {:.6e}, {:.6e}) after {depth} halvings",
                        x[0], x[1], x[2]
                    )));
                };
                stack.push((vec![mid, q], depth + 1));
                stack.push((vec![p, mid], depth + 1));
            }
        }
    }
    Ok(Fit { poles, bound2 })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::parse_quadric;

    /// The Hermite segment reproduces a cubic exactly, with the raised degree.
    #[test]
    fn hermite_reproduces_a_cubic() {
        // x(t) = (t, t², t³) on [0, 2]
        let jet = |t: f64| Jet {
            d: [
                [t, t * t, t * t * t],
                [1.0, 2.0 * t, 3.0 * t * t],
                [0.0, 2.0, 6.0 * t],
                [0.0, 0.0, 6.0],
            ],
            order: 3,
        };
        let poles = hermite(&jet(0.0), &jet(2.0), 2.0);
        assert_eq!(poles.len(), DEGREE + 1);
        for k in 0..=8 {
            let tau = k as f64 / 8.0;
            let t = 2.0 * tau;
            let x = bezier_at(&poles, tau);
            let want = [t, t * t, t * t * t];
            assert!(norm(&sub(&x, &want)) < 1e-13, "τ = {tau}: {x:?} ≠ {want:?}");
        }
        // one end with the position only: still through both ends, raised to 7
        let mut bare = jet(2.0);
        bare.order = 0;
        let poles = hermite(&jet(0.0), &bare, 2.0);
        assert_eq!(poles.len(), DEGREE + 1);
        assert_eq!(poles[DEGREE], [2.0, 4.0, 8.0]);
        let x = bezier_at(&poles, 0.0);
        assert_eq!(x, [0.0, 0.0, 0.0]);
    }

    /// A circle of radius 1 (a sphere and a plane) from 8 points: a handful of segments, and
    /// the bound below the tolerance; a tighter tolerance takes more.
    #[test]
    fn a_circle_within_the_tolerance() {
        let a = parse_quadric("x^2+y^2+z^2-2").unwrap();
        let b = parse_quadric("z-1").unwrap();
        let pair = Pair::new(&a, &b, [0.0, 0.0, 1.0]);
        let mut pts: Vec<V3> = (0..8)
            .map(|k| {
                let th = std::f64::consts::TAU * k as f64 / 8.0;
                [th.cos(), th.sin(), 0.0]
            })
            .collect();
        pts.push(pts[0]);
        let mut counts = Vec::new();
        for tol in [1e-6, 1e-9, 1e-12] {
            let fit = fit_branch(&pair, &pts, tol, 2.0, &Budget::unlimited()).unwrap();
            let b = super::super::certify::sqrt_up(&fit.bound2);
            assert!(b <= tol, "{b} > {tol}");
            assert_eq!((fit.poles.len() - 1) % DEGREE, 0);
            assert_eq!(fit.poles[0], fit.poles[fit.poles.len() - 1]);
            counts.push((fit.poles.len() - 1) / DEGREE);
            // every pole-curve point near the unit circle in the plane
            for w in fit.poles.windows(DEGREE + 1).step_by(DEGREE) {
                for k in 0..=10 {
                    let x = bezier_at(w, k as f64 / 10.0);
                    assert!((norm(&x) - 1.0).abs() <= 2.0 * tol && x[2].abs() <= tol);
                }
            }
        }
        // the error of a segment of angle α is about (α/2.5)⁸ on the unit circle
        assert!(
            counts[0] <= 16 && counts[0] < counts[1] && counts[1] < counts[2],
            "{counts:?}"
        );
    }

    /// A budget of one try is spent at once.
    #[test]
    fn the_budget_counts_tries() {
        let a = parse_quadric("x^2+y^2+z^2-2").unwrap();
        let b = parse_quadric("z-1").unwrap();
        let pair = Pair::new(&a, &b, [0.0, 0.0, 1.0]);
        let pts = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]];
        let r = fit_branch(&pair, &pts, 1e-9, 2.0, &Budget::new(TRY_UNITS));
        assert!(matches!(r, Err(Error::BudgetExceeded { .. })), "{r:?}");
    }
}
