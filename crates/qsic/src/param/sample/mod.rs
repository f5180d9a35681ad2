//! Real points on every real piece of a [`Curve`]: polylines in ℝP³ and in an affine chart,
//! computed from the exact parameterization (never by marching, so a branch cannot jump and
//! a piece cannot go missing).
//!
//! | item | what |
//! |---|---|
//! | [`sample`] | every [`RealPiece`] as an ordered polyline of unit vectors in ℝ⁴, and its affine view |
//! | [`SampleOptions`] | points per piece, chord tolerance, the plane at infinity |
//! | [`Sampled`], [`SampledPiece`], [`AffinePiece`] | the result |
//! | [`verify_on_quadrics`] | the last guard: every point on both quadrics |
//! | [`verify_turns`] | and every step along a branch within [`MAX_ANGLE`] |
//!
//! # Stages
//! Exact description → arcs → points, one module each; every stage type is complete when
//! it exists.
//!
//! | stage | module | exact input → output |
//! |---|---|---|
//! | plane meetings | [`plane`] | a parameterization and a plane or point → the exact parameters where it meets them (read by the affine view too) |
//! | crossings | `crossings` | a component and the chart → its exact crossings of the plane at infinity, with sheets |
//! | floats | `convert` | exact coefficients → floats (and double-doubles), scaled into range |
//! | evaluation | `eval` | a parameter on ℙ¹ → a certified unit vector, or none |
//! | walk | `walk`, `sampler` | the arcs of a piece → an oriented polyline with its exact marks |
//! | affine view | `view` | the polyline and its marks → branches in the chart, points at infinity |
//! | local parameter | `local` | a component and the place its walk stopped → the same component in `t = u − c`, `c` beside the cluster there |
//!
//! Float kernels (double-double, Horner, `sin`/`cos`, Newton) are in `kernels`, each called
//! from one dispatch point: a point's evaluation from `Evaluator::eval_unit` (floats
//! certified by the Horner bound, else double-double, else a nearby parameter), the arc ends
//! from `Evaluator::root_of_s` (Newton in double-double, else the algebraic number's own
//! float), the grid from `Sampler::grid` (rotations of the step, exact every 64 points),
//! the affine view from `Sampler::piece` (`view::affine_view`, held equal to the reference
//! `view::affine_view_two_pass` in debug builds and tests).
//!
//! # Parameter on the projective line
//! A parameter value is a point `(U₀, U₁)` of ℙ¹ (`u = U₀/U₁`), written `(sin θ, cos θ)`, so
//! `u = ∞` (`θ = ±π/2`) is an ordinary point and a range through ∞ is an interval of `θ`.
//! Arc ends are the exact roots of `s`; their floats only place the ends.
//!
//! # Density
//! Each arc starts from a uniform grid in `θ` (together at least [`SampleOptions::points`]
//! points per piece), walked in one pass and oriented as it goes: segments are bisected
//! until consecutive unit vectors are within [`MAX_ANGLE`] radians up to sign and, with a
//! tolerance, the chord deviation in the chart is at most the tolerance (checked where the
//! three points lie within [`AFFINE_RADIUS`] of the origin). At most [`MAX_DEPTH`] bisections
//! of a grid segment and [`MAX_POINTS`] points per call: beyond either, an error.
//!
//! Where the walk stops (no certified point, no convergence, or a step wider than
//! [`MAX_ANGLE`] beside an arc end it could not evaluate), the piece is walked again in a
//! local parameter `t = u − c` with `c` at the cluster of roots there (`local`, at most three
//! times, one inside the other), bisected geometrically towards it and at most
//! [`MAX_LOCAL_DEPTH`] deep: near-nodes 10⁻³⁰ across come out with every step within the
//! promised turn.
//!
//! # The chart
//! `h(X) = aX₀ + bX₁ + cX₂ + dX₃` (default `w`) is the plane at infinity. A point is at
//! infinity iff it is marked at an exact crossing (`crossings`), whatever its float `h`.
//! The walk's sign changes of `h`, located by regula falsi (Illinois), are kept only for a
//! curve piece known neither way (none reaches the walk today). Affine coordinates are those
//! of `X/h(X)` without the last coordinate whose coefficient in `h` is nonzero
//! (`(x/w, y/w, z/w)` for the default).

mod chart;
pub(super) mod convert;
mod crossings;
mod eval;
mod kernels;
mod local;
pub(crate) mod plane;
mod sampler;
#[cfg(test)]
mod tests;
mod view;
mod walk;

use self::chart::{singular_params, unit, Chart, ChartForm};
use self::convert::{in_float_range, to_f64};
use self::crossings::{exact_crossings, lies_in_plane, Crossings, ExactParam};
use self::eval::Evaluator;
use self::sampler::Sampler;
use self::walk::Approximations;
use super::curve::{ComponentParam, Curve, Number, RealPiece};
use crate::error::Error;
use crate::quadric::Quadric;
use crate::Budget;
use qsic_algebra::{RBig, Ring};
use std::cell::RefCell;

/// Largest angle (radians) between consecutive unit vectors of a polyline, up to sign.
pub const MAX_ANGLE: f64 = 0.1;
/// Most bisections of one segment of the initial grid.
pub const MAX_DEPTH: u32 = 48;
/// Most bisections of one segment in a local parameter (`local`): its cluster may lie
/// 10⁻³⁰ from the grid's points, a hundred halvings away.
pub const MAX_LOCAL_DEPTH: u32 = 160;
/// Most points of one [`sample`] call (requested and added by refinement together).
pub const MAX_POINTS: usize = 1 << 22;
/// The chord tolerance is enforced on segments within this distance of the chart's origin.
pub const AFFINE_RADIUS: f64 = 1e6;
/// Coefficients whose largest estimate is beyond `2^FLOAT_SCALE` are scaled to about 1
/// before they become floats (`in_float_range`): `‖X‖²` then stays below `2³⁰⁰` for every
/// `|t| ≤ 1`, far from the end of the floats at `2¹⁰²⁴`.
const FLOAT_SCALE: f64 = 64.0;

/// What [`sample`] produces and how densely.
#[derive(Clone, Debug, PartialEq)]
pub struct SampleOptions {
    /// At least this many points per curve piece.
    pub points: usize,
    /// Largest chord deviation in the affine chart, if any.
    pub tolerance: Option<f64>,
    /// The plane at infinity `[a, b, c, d]`: `ax + by + cz + dw = 0`.
    pub chart: [RBig; 4],
}

impl Default for SampleOptions {
    /// 64 points per piece, no tolerance, `w = 0` at infinity.
    fn default() -> Self {
        SampleOptions {
            points: 64,
            tolerance: None,
            chart: [RBig::ZERO, RBig::ZERO, RBig::ZERO, RBig::ONE],
        }
    }
}

impl SampleOptions {
    /// The chart, checked.
    fn chart(&self) -> Result<Chart, Error> {
        let drop = self
            .chart
            .iter()
            .rposition(|c| *c != RBig::ZERO)
            .ok_or_else(|| Error::InvalidShape("the chart plane is zero".into()))?;
        let h: [f64; 4] = std::array::from_fn(|i| self.chart[i].to_f64().value());
        Ok(Chart {
            exact: self.chart.clone(),
            form: ChartForm::new(h),
            h,
            keep: std::array::from_fn(|k| if k < drop { k } else { k + 1 }),
        })
    }

    /// The affine coordinates `X/h(X)` of the float point `x` in the chart (module docs),
    /// `None` where the float `h(x)` is zero or the chart is zero. A float `h` does not say
    /// whether a sampled point is at infinity: the sampler's exact marks do
    /// ([`SampledPiece::infinity`], and [`AffinePiece::branches`] leaves those points out).
    ///
    /// ```
    /// use qsic::param::sample::SampleOptions;
    /// assert_eq!(SampleOptions::default().affine_coordinates(&[1.0, 2.0, 3.0, 2.0]), Some([0.5, 1.0, 1.5]));
    /// assert_eq!(SampleOptions::default().affine_coordinates(&[1.0, 2.0, 3.0, 0.0]), None);
    /// ```
    pub fn affine_coordinates(&self, x: &[f64; 4]) -> Option<[f64; 3]> {
        self.chart().ok()?.affine(x)
    }
}

/// A piece in the affine chart.
#[derive(Clone, Debug, PartialEq)]
pub struct AffinePiece {
    /// The piece split at its points at infinity, each an ordered polyline.
    pub branches: Vec<Vec<[f64; 3]>>,
    /// No real point at infinity.
    pub bounded: bool,
    /// The real points at infinity (unit vectors in ℝ⁴), in order along the piece (none for
    /// a piece lying in the plane at infinity).
    pub points_at_infinity: Vec<[f64; 4]>,
    /// The piece lies in the plane at infinity: no point in the chart.
    pub at_infinity: bool,
    /// For each branch, the index into [`SampledPiece::points`] of each of its points.
    pub indices: Vec<Vec<usize>>,
}

/// The points of one [`RealPiece`].
#[derive(Clone, Debug, PartialEq)]
pub struct SampledPiece {
    /// Index into [`Curve::components`].
    pub component: usize,
    /// An isolated point (one point).
    pub isolated: bool,
    /// Unit vectors in ℝ⁴ in order along the piece, signs chosen so that consecutive ones
    /// have a nonnegative dot product; a closed piece repeats its first point at the end.
    pub points: Vec<[f64; 4]>,
    /// The piece is a closed curve.
    pub closed: bool,
    /// Indices into `points` of the real singular points of the curve met along the piece
    /// (nodes, meeting points of components, cusps), ascending: the ends of its branches. A
    /// node of the piece itself appears twice. For a closed piece, index 0 stands for the
    /// repeated last point too.
    pub breaks: Vec<usize>,
    /// Indices into `points` of the points on the chart's plane at infinity, ascending, in the
    /// order of [`AffinePiece::points_at_infinity`] (none for a piece lying in the plane): the
    /// exact real roots of `h(X(u))` (module docs), never a float `h` near zero. For
    /// a closed piece, index 0 stands for the repeated last point too.
    pub infinity: Vec<usize>,
    /// The view in the affine chart.
    pub affine: AffinePiece,
}

impl SampledPiece {
    /// The polyline cut at its [`breaks`](SampledPiece::breaks): each branch runs from one
    /// singular point to the next (both ends included); with no break, the whole polyline.
    pub fn branches(&self) -> Vec<Vec<[f64; 4]>> {
        let p = &self.points;
        if self.breaks.is_empty() || p.len() < 2 {
            return vec![p.clone()];
        }
        let b = &self.breaks;
        let mut out: Vec<Vec<[f64; 4]>> = b.windows(2).map(|w| p[w[0]..=w[1]].to_vec()).collect();
        let (first, last) = (b[0], b[b.len() - 1]);
        if self.closed {
            // from the last break round through the repeated first point to the first break
            let mut wrap = p[last..].to_vec();
            wrap.extend_from_slice(&p[1..=first]);
            if wrap.len() > 1 && !(b.len() == 1 && first == 0) {
                out.push(wrap);
            } else if b.len() == 1 {
                out.push(p.clone());
            }
        } else {
            if first > 0 {
                out.insert(0, p[..=first].to_vec());
            }
            if last + 1 < p.len() {
                out.push(p[last..].to_vec());
            }
        }
        out.retain(|br| br.len() > 1);
        out
    }
}

/// Points on every real piece of a curve, in the order of [`Curve::pieces`].
#[derive(Clone, Debug, PartialEq)]
pub struct Sampled {
    /// One entry per piece.
    pub pieces: Vec<SampledPiece>,
}

/// Points on every real piece of `curve` (module docs: parameter, density, chart).
///
/// # Errors
/// [`Error::Limit`] when more than [`MAX_POINTS`] points are requested or needed;
/// [`Error::InvalidShape`] for a zero chart; [`Error::InvalidOption`] for a tolerance that
/// is not a positive finite number or zero points;
/// [`Error::Algebra`] when a coefficient is beyond the range of `f64`, a piece has no
/// parameterization (or one of degree above 8), or the refinement does not converge within
/// [`MAX_DEPTH`].
///
/// # Examples
/// ```
/// use qsic::{io::parse_quadric, param::{parameterize, sample::{sample, SampleOptions}}};
/// let a = parse_quadric("x^2+y^2+z^2-w^2").unwrap();
/// let b = parse_quadric("2*x^2+4*y^2-w^2").unwrap();
/// let s = sample(&parameterize(&a, &b).unwrap(), &SampleOptions::default()).unwrap();
/// assert_eq!(s.pieces.len(), 2);
/// for p in &s.pieces {
///     assert!(p.points.len() >= 64 && p.affine.bounded);
///     for x in &p.points {
///         let on_a = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] - x[3] * x[3];
///         assert!(on_a.abs() < 1e-12);
///     }
/// }
/// ```
pub fn sample(curve: &Curve, options: &SampleOptions) -> Result<Sampled, Error> {
    sample_within(curve, options, &Budget::unlimited())
}

/// [`sample`] spending `budget` ([`crate::Budget`]): [`POINT_UNITS`] a point made, refined
/// or tried.
///
/// # Errors
/// As [`sample`], and [`Error::BudgetExceeded`] when the budget runs out first.
pub fn sample_within(
    curve: &Curve,
    options: &SampleOptions,
    work: &Budget,
) -> Result<Sampled, Error> {
    if options.points == 0 {
        return Err(Error::InvalidOption(
            "the points per piece must be a positive integer, not 0".into(),
        ));
    }
    if options.points > MAX_POINTS {
        return Err(Error::Limit {
            what: format!("{} points per piece", options.points),
            limit: MAX_POINTS,
        });
    }
    if let Some(t) = options.tolerance.filter(|t| !(t.is_finite() && *t > 0.0)) {
        return Err(Error::InvalidOption(format!(
            "the tolerance (the largest chord deviation in the chart) must be a positive \
             finite number, not {t}"
        )));
    }
    let chart = options.chart()?;
    let approx = Approximations::default();
    let mut budget = PointBudget {
        left: MAX_POINTS,
        work,
    };
    let mut pieces = Vec::with_capacity(curve.pieces.len());
    // the parameterizations brought into the range of f64 where needed, made only where
    // some float is near the ends of the range (before the samplers, which borrow them)
    let in_range: Vec<std::cell::OnceCell<Option<ComponentParam>>> = curve
        .components
        .iter()
        .map(|_| std::cell::OnceCell::new())
        .collect();
    // one sampler per component, made when its first piece is met
    let mut samplers: Vec<Option<Sampler>> = Vec::new();
    samplers.resize_with(curve.components.len(), || None);
    let ctx = Context {
        curve,
        chart: &chart,
        tolerance: options.tolerance,
        approx: &approx,
    };
    for piece in &curve.pieces {
        let sampled = match piece {
            RealPiece::Point { component, point } => point_piece(*component, point, &chart)?,
            RealPiece::Curve {
                component,
                arcs,
                closed,
            } => {
                let param = curve
                    .components
                    .get(*component)
                    .and_then(|c| c.param.as_ref())
                    .ok_or_else(|| {
                        Error::Algebra(format!("real piece of component {component} has no param"))
                    })?;
                let slot = &mut samplers[*component];
                if slot.is_none() {
                    *slot = Some(ctx.sampler(param, &in_range[*component])?);
                }
                let sampler = slot.as_ref().expect("made above");
                match checked_piece(
                    sampler,
                    *component,
                    (arcs, *closed),
                    options.points,
                    &mut budget,
                ) {
                    Ok(p) => p,
                    Err(e) => match sampler.stuck.take() {
                        // the floats lost the curve: a local parameter there, exactly
                        Some(theta) => ctx.local_piece(
                            (param, arcs, *closed),
                            *component,
                            theta,
                            options.points,
                            &mut budget,
                            e,
                        )?,
                        None => return Err(e),
                    },
                }
            }
        };
        pieces.push(sampled);
    }
    Ok(Sampled { pieces })
}

/// Checks every sampled point against the two quadrics: `|XᵀMX| ≤ 10⁻⁹·‖M‖` (Frobenius norm,
/// `X` a unit vector) for `M` = `A` and `B`, in floats on the matrices scaled by a power of
/// two. The points come from certified evaluations; this is the last guard that a point the
/// certificates let through is still on the curve.
///
/// # Errors
/// [`Error::Algebra`] naming the piece and the residual of the first point off a quadric.
pub fn verify_on_quadrics(sampled: &Sampled, a: &Quadric, b: &Quadric) -> Result<(), Error> {
    use dashu_int::ops::BitTest;
    let float_matrix = |q: &Quadric| -> [[f64; 4]; 4] {
        let m = q.integer_matrix().entries();
        let bits = m.iter().flatten().map(|v| v.bit_len()).max().unwrap_or(0);
        let shift = bits.saturating_sub(900);
        std::array::from_fn(|i| std::array::from_fn(|j| (&m[i][j] >> shift).to_f64().value()))
    };
    for m in [float_matrix(a), float_matrix(b)] {
        let norm = m.iter().flatten().map(|v| v * v).sum::<f64>().sqrt();
        for (k, piece) in sampled.pieces.iter().enumerate() {
            for x in &piece.points {
                let mut r = 0.0;
                for i in 0..4 {
                    for j in 0..4 {
                        r += x[i] * m[i][j] * x[j];
                    }
                }
                let n2: f64 = x.iter().map(|v| v * v).sum();
                // NaN counts as off
                if r.is_nan() || r.abs() > 1e-9 * norm * n2 {
                    return Err(Error::Algebra(format!(
                        "a sampled point of piece {k} is off a quadric (relative residual {:.1e}): \
                         the floats lost the curve there",
                        r.abs() / (norm * n2)
                    )));
                }
            }
        }
    }
    Ok(())
}

/// Checks the promised turn on every branch of every sampled piece: consecutive unit
/// vectors within [`MAX_ANGLE`] of each other up to sign (`|x·y| ≥ cos MAX_ANGLE`, with
/// 10⁻¹² of slack for the rounding of the dot product), the promise of [`sample`] that the
/// walk keeps by construction; this is the guard that no gap reaches the caller silently.
///
/// # Errors
/// [`Error::Algebra`] naming the piece, the point and the angle of the first wider step.
pub fn verify_turns(sampled: &Sampled) -> Result<(), Error> {
    for (k, piece) in sampled.pieces.iter().enumerate() {
        if let Some((i, angle)) = first_wide_step(piece) {
            return Err(Error::Algebra(format!(
                "piece {k}: the sampled points {i} and {} of a branch are {angle:.3} rad \
                 apart, beyond the promised {MAX_ANGLE}: the floats lost the curve there",
                i + 1,
            )));
        }
    }
    Ok(())
}

/// The first step along a branch of `piece` wider than [`MAX_ANGLE`] (up to sign, with
/// 10⁻¹² of slack): its index in the branch and its angle.
fn first_wide_step(piece: &SampledPiece) -> Option<(usize, f64)> {
    let cos = MAX_ANGLE.cos() - 1e-12;
    for branch in piece.branches() {
        for (i, w) in branch.windows(2).enumerate() {
            let d: f64 = (0..4).map(|j| w[0][j] * w[1][j]).sum();
            if d.is_nan() || d.abs() < cos {
                return Some((i, d.abs().min(1.0).acos()));
            }
        }
    }
    None
}

/// [`Sampler::piece`], and an error where a step is wider than [`MAX_ANGLE`] beside a place
/// where the floats lost the curve (the sampler's `stuck`, kept for a local parameter).
fn checked_piece<'a>(
    sampler: &Sampler<'a>,
    component: usize,
    (arcs, closed): (&'a [super::curve::Arc], bool),
    points: usize,
    budget: &mut PointBudget<'_>,
) -> Result<SampledPiece, Error> {
    // a place lost on an earlier piece of the component says nothing of this one
    sampler.stuck.set(None);
    let p = sampler.piece(component, arcs, closed, points, budget)?;
    // the steps checked only where the walk lost a place (the usual piece is not copied
    // into branches for it)
    if sampler.stuck.get().is_none() {
        return Ok(p);
    }
    match first_wide_step(&p) {
        Some((_, angle)) => Err(Error::Algebra(format!(
            "piece {component}: a step of {angle:.3} rad, wider than {MAX_ANGLE}"
        ))),
        None => Ok(p),
    }
}

/// What every sampler of one call shares.
struct Context<'c> {
    curve: &'c Curve,
    chart: &'c Chart,
    tolerance: Option<f64>,
    approx: &'c Approximations,
}

/// Most local parameters tried for one piece, one inside the other
/// ([`Context::local_piece`]).
const MAX_LOCAL: usize = 3;

impl<'c> Context<'c> {
    /// The sampler of one component's `param`; `scaled` keeps its coefficients brought into
    /// the range of f64 where some are not.
    fn sampler<'a>(
        &self,
        param: &'a ComponentParam,
        scaled: &'a std::cell::OnceCell<Option<ComponentParam>>,
    ) -> Result<Sampler<'a>, Error>
    where
        'c: 'a,
    {
        let chart = self.chart;
        Ok(Sampler {
            eval: match Evaluator::new(param) {
                // the floats as they are where none is near the ends of the range
                Ok(e) if e.narrow => e,
                _ => {
                    let scaled = scaled.get_or_init(|| in_float_range(param));
                    Evaluator::new(scaled.as_ref().unwrap_or(param))?
                }
            },
            crossings: if lies_in_plane(param, &chart.exact) {
                Crossings::InPlane
            } else {
                exact_crossings(param, &ExactParam::new(param), &chart.exact)?
            },
            singular: singular_params(self.curve, param, &chart.exact),
            chart,
            tolerance: self.tolerance,
            approx: self.approx,
            ends: RefCell::new(Vec::new()),
            other_sheet: RefCell::new(None),
            stuck: std::cell::Cell::new(None),
            geometric: false,
        })
    }

    /// The piece `(param, arcs, closed)` of `component` sampled in a local parameter around
    /// `theta`, where the floats lost it ([`local`]): at most [`MAX_LOCAL`] parameters, each
    /// around the place where the last one stopped; `first` (the error of the plain walk)
    /// where no cluster lies there.
    fn local_piece(
        &self,
        (param, arcs, closed): (&ComponentParam, &[super::curve::Arc], bool),
        component: usize,
        theta: f64,
        points: usize,
        budget: &mut PointBudget<'_>,
        first: Error,
    ) -> Result<SampledPiece, Error> {
        let (mut param, mut arcs) = (param.clone(), arcs.to_vec());
        let (mut theta, mut error) = (theta, first);
        for _ in 0..MAX_LOCAL {
            let Some(map) = local::local_map(&param, &arcs, theta) else {
                return Err(error);
            };
            let Some(new_arcs) = local::local_arcs(&arcs, &map) else {
                return Err(error);
            };
            (param, arcs) = (local::reparameterized(&param, &map), new_arcs);
            let scaled = std::cell::OnceCell::new();
            let sampler = Sampler {
                geometric: true,
                ..self.sampler(&param, &scaled)?
            };
            match checked_piece(&sampler, component, (&arcs, closed), points, budget) {
                Ok(p) => return Ok(p),
                Err(e) => match sampler.stuck.take() {
                    Some(t) => (theta, error) = (t, e),
                    None => return Err(e),
                },
            }
        }
        Err(error)
    }
}

fn point_piece(
    component: usize,
    point: &super::curve::Point,
    chart: &Chart,
) -> Result<SampledPiece, Error> {
    // a projective point: scaled by a power of two near its largest coordinate first, so
    // that big coordinates stay in the range of f64
    let mut alphas = Vec::new();
    let top = (point.iter())
        .filter_map(|c| convert::log2_estimate(c, &mut alphas))
        .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.max(v))))
        .ok_or_else(|| Error::Algebra("an isolated point is the zero vector".into()))?;
    let k = Number::rational(super::expr::power_of_two(-(top as i64)));
    let mut x = [0.0; 4];
    for i in 0..4 {
        x[i] = to_f64(&point[i].mul(&k))?;
    }
    let x = unit(x).ok_or_else(|| Error::Algebra("an isolated point is the zero vector".into()))?;
    let h = (0..4).fold(Number::zero(), |acc, i| {
        acc.add(&point[i].mul(&Number::rational(chart.exact[i].clone())))
    });
    let affine = if h.is_zero() {
        AffinePiece {
            branches: Vec::new(),
            bounded: false,
            points_at_infinity: vec![x],
            at_infinity: true,
            indices: Vec::new(),
        }
    } else {
        // `X/h(X)` exactly, then rounded: finite however small the float `h` is
        let inv = qsic_algebra::Field::inv(&h).ok_or_else(|| Error::Algebra("h ≠ 0".into()))?;
        let mut a = [0.0; 3];
        for (a, &k) in a.iter_mut().zip(&chart.keep) {
            *a = to_f64(&point[k].mul(&inv)).unwrap_or(f64::NAN);
        }
        let branches = if a.iter().all(|v| v.is_finite()) {
            vec![vec![a]]
        } else {
            Vec::new()
        };
        AffinePiece {
            indices: branches.iter().map(|_| vec![0]).collect(),
            branches,
            bounded: true,
            points_at_infinity: Vec::new(),
            at_infinity: false,
        }
    };
    Ok(SampledPiece {
        component,
        isolated: true,
        points: vec![x],
        closed: false,
        breaks: Vec::new(),
        infinity: if h.is_zero() { vec![0] } else { Vec::new() },
        affine,
    })
}

/// The work units of one point of [`sample_within`]: its evaluation in double-double
/// arithmetic (a parameterization of degree ≤ 8 in four coordinates, `√s(u)`, the chart),
/// its certificate and its chord test, counted as word operations.
pub const POINT_UNITS: u64 = 100;

/// The points a sample may still make ([`MAX_POINTS`] in all) and the work budget they
/// are charged to.
struct PointBudget<'b> {
    left: usize,
    work: &'b Budget,
}

impl PointBudget<'_> {
    /// Takes `n` points.
    fn take(&mut self, n: usize) -> Result<(), Error> {
        self.left = self.left.checked_sub(n).ok_or_else(too_many_points)?;
        self.work.spend(POINT_UNITS.saturating_mul(n as u64))?;
        Ok(())
    }
}

fn too_many_points() -> Error {
    Error::Limit {
        what: "points of one sample".into(),
        limit: MAX_POINTS,
    }
}
