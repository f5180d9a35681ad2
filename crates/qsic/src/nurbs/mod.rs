//! The real pieces of the intersection curve as NURBS curves a CAD kernel takes: exact
//! rational B-splines for rational components (lines, conics, cubics, nodal and cuspidal
//! quartics), and B-splines of degree 7 within a proved distance of both surfaces for the
//! others (quartic branches with `√s(u)`), in the affine chart `w = 0` at infinity.
//!
//! | entry point | what |
//! |---|---|
//! | [`nurbs_of_curve`], [`nurbs_of_curve_within`] | every real piece of a [`Curve`] as [`NurbsCurve`]s, with the [`BoxBounds`] used and the pieces left out (the second within a work budget) |
//! | [`NurbsCurve::point_at`] | the exact homogeneous point at a knot parameter (de Casteljau on one segment) |
//! | [`bezier::evaluate`] | one rational Bézier segment at `t` |
//!
//! **Method.** A rational component `X(u) = (x, y, z, w)(u)` of degree `n` (the largest
//! degree of its coordinates) is a binary form on ℝP¹. Its real points in ℝ³ are cut into
//! pieces: at the real roots of `w` (infinity), and at the parameters of its real singular
//! points in ℝ³ (an irrational one replaced by a rational within 2⁻⁶⁰, with a remark). A
//! piece between two roots of `w` is unbounded at both ends: it is clipped
//! to the box — along the arc of ℝP¹ the curve first enters the box at the first real root
//! of the six face polynomials `x_c − L·w` (`L` a face of the box), and leaves it for good at
//! the last; the piece runs from a rational parameter just before the first to one just after
//! the last (isolating interval ends refined to `2⁻³⁰`: the cut points lie just outside the
//! box, the piece itself is exact). Every piece is then cut into segments with rational ends
//! on which [`bezier::positive_segments`] gives the rational Bézier control points exactly
//! (change of basis power → Bernstein after `[P, Q] → [0, 1]`), split until every weight is
//! positive, and joined into one B-spline of degree `n`: the segments scaled to share their
//! end control points, knots `0, 1, …, m` each of multiplicity `n` (the ends `n + 1`).
//!
//! Coefficients in a number field `K` give control points exact in `K`: exact rationals when
//! the component is over ℚ.
//!
//! **Approximations** (`approx`, `fit`, `geometry`, `certify`). Every other real piece
//! (Levin's quartic branches, parts of components) is sampled from its exact
//! parameterization, cut at infinity and at singular points, clipped just outside the box,
//! and each branch fitted by Hermite segments of degree 7 built from the two quadrics alone
//! (derivatives along the curve from their gradients and Hessians), halved until an exact
//! certificate proves every point of the segment within the tolerance of both surfaces
//! (default 10⁻⁹ of the branch's size): [`Accuracy::Within`] carries the bound.
//!
//! Pieces left out (reported in [`Nurbs::left`]): isolated points, unbounded branches that
//! never enter the box, branches whose fit does not reach the tolerance (named with the
//! place).

mod approx;
pub mod bezier;
mod certify;
mod fit;
mod geometry;

use crate::error::Error;
use crate::param::sample::{sample_within, SampleOptions, Sampled};
use crate::param::{
    ComponentParam, Curve, Number, NumberPoly, ParamRange, ParamValue, Point, PointPoly, RealPiece,
};
use crate::quadric::Quadric;
use crate::Budget;
use bezier::{divide, num, oriented, positive_segments, scaled, ParamPoint};
use qsic_algebra::roots::RootInterval;
use qsic_algebra::{AlgebraicReal, RBig, Ring, Sign};

/// An axis-parallel box `lo ≤ (x, y, z) ≤ hi` with rational corners.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BoxBounds {
    /// The least corner.
    pub lo: [RBig; 3],
    /// The greatest corner.
    pub hi: [RBig; 3],
}

/// Options of [`nurbs_of_curve`].
#[derive(Clone, Debug, Default)]
pub struct NurbsOptions {
    /// The box unbounded pieces are clipped to; `None`: around the bounded pieces, the real
    /// singular points in ℝ³, the centres of the surfaces and a point of each unbounded
    /// branch, half as wide again on every side (at least 1).
    pub bounds: Option<BoxBounds>,
    /// The distance bound of the approximated pieces to both surfaces; `None`: 10⁻⁹ of
    /// each branch's size (the diagonal of its bounding box).
    pub tolerance: Option<f64>,
}

/// How far a [`NurbsCurve`] may be from the curve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Accuracy {
    /// Exactly on both quadrics: the rational curve itself.
    Exact,
    /// Every point within this distance of both surfaces, proved (a polynomial B-spline of
    /// degree 7 with dyadic control points approximating a branch).
    Within(f64),
}

impl Accuracy {
    /// The distance bound: 0 for an exact curve.
    pub fn bound(&self) -> f64 {
        match self {
            Accuracy::Exact => 0.0,
            Accuracy::Within(b) => *b,
        }
    }
}

/// One real piece as a rational B-spline (NURBS) curve in ℝ³.
///
/// Invariants ([`Self::is_valid`]): `knots` is clamped (`0` and `m` of multiplicity
/// `degree + 1`, the integers between of multiplicity `degree`), `poles.len() =
/// m·degree + 1`, every weight positive.
#[derive(Clone, Debug)]
pub struct NurbsCurve {
    /// The index of the piece in [`Curve::pieces`].
    pub piece: usize,
    /// The index of its component in [`Curve::components`].
    pub component: usize,
    /// The degree.
    pub degree: usize,
    /// The knot vector, every knot repeated by its multiplicity: `0, …, 0, 1, …, m, …, m`.
    pub knots: Vec<RBig>,
    /// The control points in homogeneous coordinates `(w·x, w·y, w·z, w)`, exact.
    pub poles: Vec<Point>,
    /// The parameters `(U₀, U₁)` (`u = U₀/U₁`) of the component where the piece starts and
    /// ends (`None` for an approximation).
    pub ends: Option<[ParamPoint; 2]>,
    /// Whether each end is a cut at the box (else a singular point, or the start of a loop).
    pub clipped: [bool; 2],
    /// The last control point is the first.
    pub closed: bool,
    /// Exact, or within a proved distance of both surfaces.
    pub accuracy: Accuracy,
}

impl NurbsCurve {
    /// The number of Bézier segments `m`.
    pub fn segments(&self) -> usize {
        (self.poles.len() - 1) / self.degree
    }

    /// The weights: the last homogeneous coordinate of each pole.
    pub fn weights(&self) -> Vec<Number> {
        self.poles.iter().map(|p| p[3].clone()).collect()
    }

    /// The control points in ℝ³, `(x, y, z)` of each pole, exact.
    pub fn control_points(&self) -> Vec<[Number; 3]> {
        self.poles
            .iter()
            .map(|p| std::array::from_fn(|i| divide(&p[i], &p[3])))
            .collect()
    }

    /// The distinct knots and their multiplicities.
    pub fn knot_multiplicities(&self) -> Vec<(RBig, usize)> {
        let mut out: Vec<(RBig, usize)> = Vec::new();
        for k in &self.knots {
            match out.last_mut() {
                Some((v, m)) if v == k => *m += 1,
                _ => out.push((k.clone(), 1)),
            }
        }
        out
    }

    /// The homogeneous point at the knot parameter `t ∈ [0, m]`, exactly (de Casteljau on
    /// the segment holding `t`); `None` outside `[0, m]`.
    pub fn point_at(&self, t: &RBig) -> Option<Point> {
        let m = self.segments();
        if *t < RBig::ZERO || *t > RBig::from(m) {
            return None;
        }
        let mut k = 0usize;
        while k + 1 < m && RBig::from(k + 1) <= *t {
            k += 1;
        }
        let local = t - RBig::from(k);
        let n = self.degree;
        Some(bezier::evaluate(&self.poles[k * n..=k * n + n], &local))
    }

    /// The invariants of the type (see there).
    pub fn is_valid(&self) -> bool {
        let n = self.degree;
        if n == 0 || self.poles.len() < n + 1 || (self.poles.len() - 1) % n != 0 {
            return false;
        }
        self.knots == clamped_knots(n, self.segments())
            && self.poles.iter().all(|p| p[3].sign() == Sign::Positive)
    }
}

/// The knots of `m` Bézier segments of degree `n` joined into one B-spline: `0, 1, …, m`,
/// the ends of multiplicity `n + 1`, the others `n`.
pub(crate) fn clamped_knots(n: usize, m: usize) -> Vec<RBig> {
    let mut knots = vec![RBig::ZERO; n + 1];
    for i in 1..m {
        knots.extend(std::iter::repeat_n(RBig::from(i), n));
    }
    knots.extend(std::iter::repeat_n(RBig::from(m), n + 1));
    knots
}

/// A real piece [`nurbs_of_curve`] gives no curve for, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LeftOut {
    /// The index of the piece in [`Curve::pieces`] (`None`: a remark on the whole curve).
    pub piece: Option<usize>,
    /// Why, in words.
    pub reason: String,
}

/// The NURBS curves of a curve's real pieces.
#[derive(Clone, Debug)]
pub struct Nurbs {
    /// The curves, in the order of the pieces (a piece may give several: cut at singular
    /// points).
    pub curves: Vec<NurbsCurve>,
    /// The box unbounded pieces were clipped to.
    pub bounds: BoxBounds,
    /// The pieces left out, and remarks (a singular point not cut at).
    pub left: Vec<LeftOut>,
}

/// A point of ℝP¹ with an algebraic coordinate.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Proj {
    Finite(AlgebraicReal),
    Infinity,
}

/// The position of a point along an arc of ℝP¹ from its start, increasing `u`: first the
/// finite values above the start, then `∞`, then the finite values below it.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Along {
    Before(AlgebraicReal),
    AtInfinity,
    After(AlgebraicReal),
}

/// Where `p` lies along the arc starting at `start`; `None` for the start itself.
fn along(start: &Proj, p: &Proj) -> Option<Along> {
    match (start, p) {
        (Proj::Finite(s), Proj::Finite(x)) => match x.cmp(s) {
            std::cmp::Ordering::Greater => Some(Along::Before(x.clone())),
            std::cmp::Ordering::Less => Some(Along::After(x.clone())),
            std::cmp::Ordering::Equal => None,
        },
        (Proj::Finite(_), Proj::Infinity) => Some(Along::AtInfinity),
        (Proj::Infinity, Proj::Finite(x)) => Some(Along::After(x.clone())),
        (Proj::Infinity, Proj::Infinity) => None,
    }
}

/// The width cut points are placed within, around a root: `2⁻³⁰`.
fn cut_width() -> RBig {
    RBig::ONE / RBig::from(1u64 << 30)
}

/// A rational below `x` and within [`cut_width`] of it.
fn just_below(x: &AlgebraicReal) -> RBig {
    match x.refined_interval(&cut_width()) {
        RootInterval::Exact(v) => v - cut_width(),
        RootInterval::Open(lo, _) => lo,
    }
}

/// A rational above `x` and within [`cut_width`] of it.
fn just_above(x: &AlgebraicReal) -> RBig {
    match x.refined_interval(&cut_width()) {
        RootInterval::Exact(v) => v + cut_width(),
        RootInterval::Open(_, hi) => hi,
    }
}

/// The value of a rational algebraic number (a stated exact interval, or a linear defining
/// polynomial).
fn rational_value(x: &AlgebraicReal) -> Option<RBig> {
    if let Some(v) = x.as_rational() {
        return Some(v.clone());
    }
    let p = x.poly();
    (p.degree() == Some(1)).then(|| -RBig::from(p.coeff(0)) / RBig::from(p.coeff(1)))
}

/// The rational point `v` of ℝP¹.
fn finite(v: RBig) -> ParamPoint {
    [v, RBig::ONE]
}

/// `u = ∞`.
fn infinity() -> ParamPoint {
    [RBig::ONE, RBig::ZERO]
}

/// The rational point `p` as a [`Proj`].
fn proj_of(p: &ParamPoint) -> Proj {
    if p[1] == RBig::ZERO {
        Proj::Infinity
    } else {
        Proj::Finite(AlgebraicReal::from_rational(&p[0] / &p[1]))
    }
}

/// The real roots on ℝP¹ of the form `f` of degree `n` (`f ≠ 0`): finite increasing, then
/// `∞` when the degree drops.
fn projective_roots(f: &NumberPoly, n: usize) -> Vec<Proj> {
    let mut out: Vec<Proj> = f.real_roots().into_iter().map(Proj::Finite).collect();
    if f.coeff(n).is_zero() {
        out.push(Proj::Infinity);
    }
    out
}

/// A rational component prepared for cutting.
struct Rational<'a> {
    piece: usize,
    component: usize,
    x: &'a PointPoly,
    n: usize,
    /// The rational parameters of its real singular points, in ℝP¹ order.
    cuts: Vec<ParamPoint>,
    /// The real roots of `w` on ℝP¹.
    infinity: Vec<Proj>,
}

/// Every real piece of `curve` (the curve of `a` and `b`) as NURBS curves: exact rational
/// B-splines for rational components, unbounded pieces clipped to a box (module docs).
///
/// Postconditions: every curve [`NurbsCurve::is_valid`]; every point of an exact curve lies
/// on both quadrics, every point of an approximation within its [`Accuracy::Within`] bound
/// of both surfaces.
///
/// # Errors
/// [`Error::InvalidOption`] for a tolerance that is not a positive finite number; nothing
/// else: a piece that cannot be given is listed in [`Nurbs::left`] with the reason, and an
/// exact B-spline whose weights do not separate from 0 is approximated instead.
///
/// # Examples
/// ```
/// use qsic::{io::parse_quadric, nurbs::{nurbs_of_curve, NurbsOptions}, param::parameterize};
/// // Viviani's curve: a sphere and a cylinder through its centre, a node at (2, 0, 0)
/// let a = parse_quadric("x^2+y^2+z^2-4").unwrap();
/// let b = parse_quadric("x^2+y^2-2*x").unwrap();
/// let curve = parameterize(&a, &b).unwrap();
/// let n = nurbs_of_curve(&curve, &a, &b, &NurbsOptions::default()).unwrap();
/// assert_eq!(n.curves.len(), 2); // two loops, cut at the node
/// assert!(n.curves.iter().all(|c| c.degree == 4 && c.is_valid()));
/// ```
pub fn nurbs_of_curve(
    curve: &Curve,
    a: &Quadric,
    b: &Quadric,
    options: &NurbsOptions,
) -> Result<Nurbs, Error> {
    nurbs_of_curve_within(curve, a, b, options, &Budget::unlimited())
}

/// [`nurbs_of_curve`] spending `work` ([`crate::Budget`]) on the approximations: the
/// sample's points ([`crate::param::sample::sample_within`]) and [`fit::TRY_UNITS`] a tried
/// segment.
///
/// # Errors
/// As [`nurbs_of_curve`], and [`Error::BudgetExceeded`].
pub fn nurbs_of_curve_within(
    curve: &Curve,
    a: &Quadric,
    b: &Quadric,
    options: &NurbsOptions,
    work: &Budget,
) -> Result<Nurbs, Error> {
    if let Some(t) = options.tolerance.filter(|t| !(t.is_finite() && *t > 0.0)) {
        return Err(Error::InvalidOption(format!(
            "the tolerance (the distance bound of approximated curves) must be a positive \
             finite number, not {t}"
        )));
    }
    let mut left = Vec::new();
    let mut rationals = Vec::new();
    // pieces approximated: (piece, component)
    let mut approximated: Vec<(usize, usize)> = Vec::new();
    for (k, piece) in curve.pieces.iter().enumerate() {
        let leave = |reason: &str| LeftOut {
            piece: Some(k),
            reason: reason.into(),
        };
        let (component, arcs) = match piece {
            RealPiece::Point { .. } => {
                left.push(leave("an isolated point"));
                continue;
            }
            RealPiece::Curve {
                component, arcs, ..
            } => (*component, arcs),
        };
        match &curve.components[component].param {
            Some(ComponentParam::Rational { x, .. })
                if arcs.len() == 1 && matches!(arcs[0].range, ParamRange::All) =>
            {
                let n = x.iter().filter_map(|c| c.degree()).max().unwrap_or(0);
                if n == 0 {
                    left.push(leave("a constant parameterization"));
                    continue;
                }
                if x[3].is_zero() {
                    left.push(leave("in the plane at infinity: no point in R^3"));
                    continue;
                }
                let (cuts, remarks) = singular_cuts(curve, x, n);
                left.extend(remarks.into_iter().map(|r| LeftOut {
                    piece: Some(k),
                    reason: r,
                }));
                rationals.push(Rational {
                    piece: k,
                    component,
                    x,
                    n,
                    cuts,
                    infinity: projective_roots(&x[3], n),
                });
            }
            Some(_) => approximated.push((k, component)),
            None => left.push(leave("a piece without a parameterization")),
        }
    }
    let mut curves = Vec::new();
    // an exact B-spline that cannot be made (its weights do not separate from 0 within the
    // splits: a root of w nearly real) is approximated instead, with a remark
    let not_exact = |r: &Rational, e: Error, left: &mut Vec<LeftOut>| {
        left.push(LeftOut {
            piece: Some(r.piece),
            reason: format!("approximated: no exact B-spline ({e})"),
        });
        (r.piece, r.component)
    };
    for r in rationals.iter().filter(|r| r.infinity.is_empty()) {
        match bounded_pieces(r) {
            Ok(c) => curves.extend(c),
            Err(e) => approximated.push(not_exact(r, e, &mut left)),
        }
    }
    // the approximated pieces' points, from one sample of the curve, made when first needed
    let mut sampled: Option<Result<Sampled, Error>> = None;
    let sample_once = |sampled: &mut Option<Result<Sampled, Error>>| -> Result<(), Error> {
        if sampled.is_none() {
            let s = sample_within(curve, &SampleOptions::default(), work);
            if let Err(e @ Error::BudgetExceeded { .. }) = s {
                return Err(e);
            }
            *sampled = Some(s);
        }
        Ok(())
    };
    let mut extra: Vec<[f64; 3]> = Vec::new();
    if !approximated.is_empty() && options.bounds.is_none() {
        sample_once(&mut sampled)?;
        if let Some(Ok(s)) = &sampled {
            for (k, _) in &approximated {
                extra.extend(approx::box_points(&s.pieces[*k]));
            }
        }
    }
    let bounds = match &options.bounds {
        Some(b) => b.clone(),
        None => default_bounds(&curves, &rationals, curve, (a, b), &extra),
    };
    for r in rationals.iter().filter(|r| !r.infinity.is_empty()) {
        match unbounded_pieces(r, &bounds) {
            Ok((pieces, missed)) => {
                curves.extend(pieces);
                if missed > 0 {
                    left.push(LeftOut {
                        piece: Some(r.piece),
                        reason: format!("{missed} unbounded branch(es) outside the box"),
                    });
                }
            }
            Err(e) => approximated.push(not_exact(r, e, &mut left)),
        }
    }
    if !approximated.is_empty() {
        sample_once(&mut sampled)?;
    }
    // made above when anything is approximated
    let sampled = sampled.unwrap_or_else(|| Ok(Sampled { pieces: Vec::new() }));
    // a branch whose fit failed is tried once more from a sample whose chords are within
    // 10⁻³ of the smallest such branch's size (between two points of the default sample
    // the branch may turn back on itself)
    let approximate = |k: usize,
                       component: usize,
                       from: &Result<Sampled, Error>|
     -> Result<approx::Approximated, Error> {
        let pieces = match from {
            Ok(s) => &s.pieces,
            Err(e) => {
                return Ok(approx::Approximated {
                    curves: Vec::new(),
                    left: vec![LeftOut {
                        piece: Some(k),
                        reason: format!("not approximated: its points were not sampled: {e}"),
                    }],
                    failed: None,
                })
            }
        };
        let input = approx::PieceInput {
            piece: k,
            component,
            sampled: &pieces[k],
            a,
            b,
            bounds: &bounds,
            tolerance: options.tolerance,
        };
        approx::approximate_piece(&input, work)
    };
    let mut retry: Vec<(usize, usize)> = Vec::new();
    let mut finest: Option<f64> = None;
    for (k, component) in approximated {
        let done = approximate(k, component, &sampled)?;
        match done.failed {
            Some(size) if size > 0.0 => {
                finest = Some(finest.map_or(size, |f| f.min(size)));
                retry.push((k, component));
            }
            _ => {
                curves.extend(done.curves);
                left.extend(done.left);
            }
        }
    }
    if let Some(size) = finest {
        let denser = SampleOptions {
            tolerance: Some(size * 1e-3),
            ..SampleOptions::default()
        };
        let again = sample_within(curve, &denser, work);
        if let Err(e @ Error::BudgetExceeded { .. }) = again {
            return Err(e);
        }
        let from = if again.is_ok() { &again } else { &sampled };
        for (k, component) in retry {
            let done = approximate(k, component, from)?;
            curves.extend(done.curves);
            left.extend(done.left);
        }
    }
    curves.sort_by_key(|c| c.piece);
    Ok(Nurbs {
        curves,
        bounds,
        left,
    })
}

/// The rational parameters of the real singular points on `x` in ℝP¹ order, and remarks on
/// those that are not cuts (irrational parameters, other fields).
fn singular_cuts(curve: &Curve, x: &PointPoly, n: usize) -> (Vec<ParamPoint>, Vec<String>) {
    let mut cuts: Vec<ParamPoint> = Vec::new();
    let mut remarks = Vec::new();
    for sp in &curve.singular_points {
        if sp.point[3].is_zero() {
            // at infinity: the pieces end there anyway, at the roots of w
            continue;
        }
        match crate::param::sample::plane::params_of_point(x, n, &sp.point) {
            Ok(values) => {
                for v in values {
                    match v {
                        ParamValue::Infinity => cuts.push(infinity()),
                        ParamValue::Finite(u) => match rational_value(&u) {
                            Some(u) => cuts.push(finite(u)),
                            None => {
                                // an exact cut there would need control points over the
                                // parameter's field: cut at a rational beside it instead
                                let width = RBig::ONE / RBig::from(1u128 << 60);
                                let near = match u.refined_interval(&width) {
                                    RootInterval::Exact(v) => v,
                                    RootInterval::Open(lo, hi) => (lo + hi) / RBig::from(2),
                                };
                                remarks.push(format!(
                                    "a singular point at the irrational parameter u = {:.6}: \
                                     cut at a rational parameter within 2^-60 of it",
                                    u.to_f64()
                                ));
                                cuts.push(finite(near));
                            }
                        },
                    }
                }
            }
            Err(e) => remarks.push(format!("a singular point not placed: {e}")),
        }
    }
    cuts.sort_by_key(order_key);
    cuts.dedup();
    (cuts, remarks)
}

/// ℝP¹ order of a rational point: finite values increasing, `∞` last.
fn order_key(p: &ParamPoint) -> (bool, RBig) {
    if p[1] == RBig::ZERO {
        (true, RBig::ZERO)
    } else {
        (false, &p[0] / &p[1])
    }
}

/// One B-spline through the segments between consecutive `breaks` (oriented along
/// increasing `u`), exact.
fn spline(r: &Rational, breaks: &[ParamPoint], clipped: [bool; 2]) -> Result<NurbsCurve, Error> {
    let n = r.n;
    let mut poles: Vec<Point> = Vec::new();
    let mut m = 0usize;
    for w in breaks.windows(2) {
        let q = oriented(&w[0], &w[1]);
        for seg in positive_segments(r.x, n, &w[0], &q).map_err(Error::Algebra)? {
            let seg = match poles.last() {
                None => seg,
                Some(last) => {
                    let k = divide(&last[3], &seg[0][3]);
                    scaled(&seg, &k)
                }
            };
            let skip = usize::from(!poles.is_empty());
            poles.extend(seg.into_iter().skip(skip));
            m += 1;
        }
    }
    let knots = clamped_knots(n, m);
    let ends = [breaks[0].clone(), breaks[breaks.len() - 1].clone()];
    let closed = order_key(&ends[0]) == order_key(&ends[1]);
    let c = NurbsCurve {
        piece: r.piece,
        component: r.component,
        degree: n,
        knots,
        poles,
        ends: Some(ends),
        clipped,
        closed,
        accuracy: Accuracy::Exact,
    };
    debug_assert!(c.is_valid());
    Ok(c)
}

/// The pieces of a component without real points at infinity: one closed curve, or the
/// arcs between consecutive singular parameters.
fn bounded_pieces(r: &Rational) -> Result<Vec<NurbsCurve>, Error> {
    let one = RBig::ONE;
    match r.cuts.as_slice() {
        [] => {
            let breaks = [
                finite(RBig::ZERO),
                finite(one),
                infinity(),
                finite(RBig::ZERO),
            ];
            Ok(vec![spline(r, &breaks, [false; 2])?])
        }
        [c] => {
            let breaks = if c[1] == RBig::ZERO {
                vec![infinity(), finite(RBig::ZERO), finite(one), infinity()]
            } else {
                let u = &c[0] / &c[1];
                vec![c.clone(), finite(&u + &one), finite(&u - &one), c.clone()]
            };
            Ok(vec![spline(r, &breaks, [false; 2])?])
        }
        cuts => {
            let mut out = Vec::new();
            for i in 0..cuts.len() {
                let next = &cuts[(i + 1) % cuts.len()];
                out.push(spline(r, &[cuts[i].clone(), next.clone()], [false; 2])?);
            }
            Ok(out)
        }
    }
}

/// The affine point `X(p)` in floats (`None` at infinity).
fn approx_point(x: &PointPoly, n: usize, p: &ParamPoint) -> Option<[f64; 3]> {
    let q = oriented(p, &[p[1].clone(), -p[0].clone()]);
    let b = bezier::bezier_on(x, n, p, &q);
    let h = &b[0];
    (!h[3].is_zero()).then(|| std::array::from_fn(|i| divide(&h[i], &h[3]).to_f64()))
}

/// A rational parameter strictly inside the arc of ℝP¹ from `s` to `e` (`e = s`: all of ℝP¹
/// but `s`).
fn inside(s: &Proj, e: &Proj) -> ParamPoint {
    match (s, e) {
        (Proj::Finite(s), Proj::Finite(e)) if e > s => finite(s.rational_between(e)),
        (Proj::Finite(s), _) => finite(just_above(s) + RBig::ONE),
        (Proj::Infinity, Proj::Finite(e)) => finite(just_below(e) - RBig::ONE),
        (Proj::Infinity, Proj::Infinity) => finite(RBig::ZERO),
    }
}

/// The arcs of ℝP¹ between consecutive roots of `w` (the affine branches): `(start, end)`,
/// one arc from the root back to itself when there is one root.
fn branches(r: &Rational) -> Vec<(Proj, Proj)> {
    let k = r.infinity.len();
    (0..k)
        .map(|i| (r.infinity[i].clone(), r.infinity[(i + 1) % k].clone()))
        .collect()
}

/// The centre of a quadric with an invertible quadratic part, in floats.
fn centre(q: &Quadric) -> Option<[f64; 3]> {
    let m = q.matrix();
    let d3 = |c: [[&RBig; 3]; 3]| -> RBig {
        c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1])
            - c[0][1] * (c[1][0] * c[2][2] - c[1][2] * c[2][0])
            + c[0][2] * (c[1][0] * c[2][1] - c[1][1] * c[2][0])
    };
    let q3: [[&RBig; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| &m[i][j]));
    let det = d3(q3);
    if det == RBig::ZERO {
        return None;
    }
    let rhs: [RBig; 3] = std::array::from_fn(|i| -m[i][3].clone());
    Some(std::array::from_fn(|k| {
        let c: [[&RBig; 3]; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|j| if j == k { &rhs[i] } else { &m[i][j] })
        });
        (d3(c) / &det).to_f64().value()
    }))
}

/// The default box (see [`NurbsOptions::bounds`]).
fn default_bounds(
    bounded: &[NurbsCurve],
    rationals: &[Rational],
    curve: &Curve,
    (a, b): (&Quadric, &Quadric),
    extra: &[[f64; 3]],
) -> BoxBounds {
    let mut points: Vec<[f64; 3]> = extra.to_vec();
    points.extend(centre(a));
    points.extend(centre(b));
    for sp in &curve.singular_points {
        if !sp.point[3].is_zero() {
            points.push(std::array::from_fn(|i| {
                divide(&sp.point[i], &sp.point[3]).to_f64()
            }));
        }
    }
    for c in bounded {
        points.extend(
            c.control_points()
                .iter()
                .map(|p| p.each_ref().map(Number::to_f64)),
        );
    }
    for r in rationals.iter().filter(|r| !r.infinity.is_empty()) {
        for (s, e) in branches(r) {
            points.extend(approx_point(r.x, r.n, &inside(&s, &e)));
        }
    }
    for p in &curve.pieces {
        if let RealPiece::Point { point, .. } = p {
            if !point[3].is_zero() {
                points.push(std::array::from_fn(|i| {
                    divide(&point[i], &point[3]).to_f64()
                }));
            }
        }
    }
    points.retain(|p| p.iter().all(|v| v.is_finite()));
    if points.is_empty() {
        points.push([0.0; 3]);
    }
    let lo: [f64; 3] =
        std::array::from_fn(|i| points.iter().map(|p| p[i]).fold(f64::MAX, f64::min));
    let hi: [f64; 3] =
        std::array::from_fn(|i| points.iter().map(|p| p[i]).fold(f64::MIN, f64::max));
    let extent = (0..3).map(|i| hi[i] - lo[i]).fold(0.0, f64::max);
    let margin = if extent > 0.0 { extent / 2.0 } else { 1.0 };
    let grid = |v: f64, up: bool| -> RBig {
        let s = v * 1024.0;
        let k = if up { s.ceil() } else { s.floor() };
        RBig::try_from(k).unwrap_or(RBig::ZERO) / RBig::from(1024)
    };
    BoxBounds {
        lo: std::array::from_fn(|i| grid(lo[i] - margin, false)),
        hi: std::array::from_fn(|i| grid(hi[i] + margin, true)),
    }
}

/// The clipped pieces of a component with real points at infinity, and the number of
/// branches that never enter the box.
fn unbounded_pieces(r: &Rational, bounds: &BoxBounds) -> Result<(Vec<NurbsCurve>, usize), Error> {
    let w = &r.x[3];
    let mut crossings: Vec<Proj> = Vec::new();
    for c in 0..3 {
        for l in [&bounds.lo[c], &bounds.hi[c]] {
            let f = &r.x[c] - &w.scale(&num(l.clone()));
            if f.is_zero() {
                // the component lies in this face's plane, on the closed box's boundary
                // there: the other faces decide where it enters and leaves
                continue;
            }
            for rho in projective_roots(&f, r.n) {
                if on_box(r, bounds, c, &rho) {
                    crossings.push(rho);
                }
            }
        }
    }
    // a rational beyond every finite root involved
    let mut big = RBig::ONE;
    for p in crossings.iter().chain(&r.infinity) {
        if let Proj::Finite(x) = p {
            let iv = x.interval();
            for v in [iv.lo(), iv.hi()] {
                let v = if *v < RBig::ZERO {
                    -v.clone()
                } else {
                    v.clone()
                };
                if v > big {
                    big = v;
                }
            }
        }
    }
    big += RBig::ONE;
    let mut out = Vec::new();
    let mut missed = 0;
    for (s, e) in branches(r) {
        let end = along(&s, &e);
        let within = |p: &Proj| -> Option<Along> {
            let k = along(&s, p)?;
            match &end {
                Some(e) if k >= *e => None,
                _ => Some(k),
            }
        };
        let mut keys: Vec<Along> = crossings.iter().filter_map(within).collect();
        keys.sort();
        let (Some(first), Some(last)) = (keys.first(), keys.last()) else {
            missed += 1;
            continue;
        };
        let start = before(&s, first, &big);
        let stop = after(&e, last, &big);
        let mut breaks = vec![start.clone()];
        let (k0, k1) = (
            along(&s, &proj_of(&start)).expect("inside the arc"),
            along(&s, &proj_of(&stop)).expect("inside the arc"),
        );
        let mut cuts: Vec<(Along, ParamPoint)> = r
            .cuts
            .iter()
            .filter_map(|c| {
                let k = along(&s, &proj_of(c))?;
                (k > k0 && k < k1).then(|| (k, c.clone()))
            })
            .collect();
        cuts.sort_by(|x, y| x.0.cmp(&y.0));
        let mut clipped_start = true;
        for (_, c) in cuts {
            breaks.push(c.clone());
            out.push(spline(r, &breaks, [clipped_start, false])?);
            breaks = vec![c];
            clipped_start = false;
        }
        breaks.push(stop);
        out.push(spline(r, &breaks, [clipped_start, true])?);
    }
    Ok((out, missed))
}

/// Whether the point at `rho`, a root of the face polynomial of coordinate `c`, lies on the
/// box: every other coordinate within its bounds, decided exactly (signs of
/// `(x_d − L·w)·w` at `rho`; at `u = ∞` the leading coefficients).
fn on_box(r: &Rational, bounds: &BoxBounds, c: usize, rho: &Proj) -> bool {
    let w = &r.x[3];
    let sign = |p: &NumberPoly| -> Sign {
        match rho {
            Proj::Finite(t) => p.sign_at(t),
            Proj::Infinity => p.coeff(r.n).sign(),
        }
    };
    let sw = sign(w);
    (0..3).filter(|d| *d != c).all(|d| {
        let below = sign(&(&r.x[d] - &w.scale(&num(bounds.lo[d].clone()))));
        let above = sign(&(&w.scale(&num(bounds.hi[d].clone())) - &r.x[d]));
        below * sw != Sign::Negative && above * sw != Sign::Negative
    })
}

/// A rational parameter between the arc's start `s` and the crossing `p` (the first),
/// within [`cut_width`] of `p` where `p` is finite.
fn before(s: &Proj, p: &Along, big: &RBig) -> ParamPoint {
    match (p, s) {
        (Along::Before(x), Proj::Finite(s0)) => {
            let a = just_below(x);
            if AlgebraicReal::from_rational(a.clone()) > *s0 {
                finite(a)
            } else {
                finite(s0.rational_between(x))
            }
        }
        (Along::AtInfinity, _) => finite(big.clone()),
        (Along::After(x), _) | (Along::Before(x), Proj::Infinity) => finite(just_below(x)),
    }
}

/// A rational parameter between the crossing `p` (the last) and the arc's end `e`.
fn after(e: &Proj, p: &Along, big: &RBig) -> ParamPoint {
    let bounded_by = |x: &AlgebraicReal, e0: Option<&AlgebraicReal>| -> ParamPoint {
        let b = just_above(x);
        match e0 {
            Some(e0) if AlgebraicReal::from_rational(b.clone()) >= *e0 => {
                finite(x.rational_between(e0))
            }
            _ => finite(b),
        }
    };
    let e0 = match e {
        Proj::Finite(e0) => Some(e0),
        Proj::Infinity => None,
    };
    match p {
        Along::Before(x) => {
            // bounded by the end only when the end lies before ∞ too
            let e0 = e0.filter(|e0| *e0 > x);
            bounded_by(x, e0)
        }
        Along::AtInfinity => finite(-big.clone()),
        Along::After(x) => bounded_by(x, e0),
    }
}
