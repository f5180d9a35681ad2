//! Real points on every real piece of a [`Curve`]: polylines in ℝP³ and in an affine chart,
//! computed from the exact parameterization (never by marching, so a branch cannot jump and
//! a piece cannot go missing).
//!
//! | item | what |
//! |---|---|
//! | [`sample`] | every [`RealPiece`] as an ordered polyline of unit vectors in ℝ⁴, and its affine view |
//! | [`SampleOptions`] | points per piece, chord tolerance, the plane at infinity |
//! | [`Sampled`], [`SampledPiece`], [`AffinePiece`] | the result |
//!
//! # Parameter on the projective line
//! A parameter value is a point `(U₀, U₁)` of ℙ¹ (`u = U₀/U₁`), written `(sin θ, cos θ)`, so
//! `u = ∞` (`θ = ±π/2`) is an ordinary point and a range through ∞ is an interval of `θ`.
//! The homogenized parameterization is evaluated at `t = U₀/U₁` when `|t| ≤ 1`, else with
//! the reversed coefficients at `1/t`: Horner's rule always runs on `[−1, 1]`. Levin's form
//! `a ± d√s` is homogeneous of degree `D = max(deg a, deg d + 2)` with `s` a quartic form.
//! Arc ends are the exact roots of `s`, approximated by Newton's method on `s` (evaluated in
//! double-double) inside the root's isolating interval (one simple root there), by
//! [`AlgebraicReal::to_f64`] where that does not bracket it or the root is ill-conditioned. Coefficients go to floats
//! once, through double-double: over ℚ(√δ) `c₀ + c₁√δ` is summed where the terms agree in
//! sign or cancel by fewer than 6 bits, else computed as `(c₀² − c₁²δ)/(c₀ − c₁√δ)` with the
//! integer norm exact, so that no cancellation costs more than 6 of the ~104 bits (the same
//! double-doubles serve the retries). `s` is
//! clamped at 0, which moves
//! a point off the curve by `O(|s|)` only, because `aᵀMd ≡ 0` cancels the first-order error
//! of `√s`. An evaluation whose rounding bound exceeds `10⁻¹⁰·‖X‖` (a sheet passing through
//! the zero vector, a removable zero of Levin's form) is retried in double-double, then at a
//! nearby parameter; the bound `Σₖ|cₖ||t|ᵏ` is first majorized once per parameterization
//! (`Σ|x| + Σ|d|·√(Σ|s|)`: one comparison with the norm), then by the precomputed sums at
//! `|t|`, and computed only where neither certifies. Horner's rule runs on fixed-size
//! arrays, unrolled for the usual degrees.
//!
//! # Density
//! Each arc starts from a uniform grid in `θ` (together at least
//! [`SampleOptions::points`] points per piece; `(sin θ, cos θ)` by rotations of the step,
//! exact every 64 points; on Levin's form `a`, `d` and `√s` evaluated once for both sheets),
//! walked in one pass and oriented as it goes: segments are bisected, from a work list,
//! until consecutive unit vectors are within [`MAX_ANGLE`] radians up to sign and, with a
//! tolerance, the chord deviation in the chart is at most the tolerance (checked where the
//! three points lie within [`AFFINE_RADIUS`] of the origin). At most [`MAX_DEPTH`] bisections
//! of a grid segment and [`MAX_POINTS`] points per call: beyond either, an error.
//!
//! # The chart
//! `h(X) = aX₀ + bX₁ + cX₂ + dX₃` (default `w`) is the plane at infinity. The crossings of
//! a rational `X(u)` are the exact real roots of `h(X(u))` (over a number field by the norm:
//! [`super::infinity`]), those of Levin's form with rational coefficients the roots of
//! `h(a)² − h(d)²s` (the sheet from the signs of `h(a)` and `h(d)`), tangential touches
//! included; they are marked on the polyline ([`SampledPiece::infinity`]), and a point is at
//! infinity iff it is marked, whatever its float `h`. On Levin's form with irrational
//! coefficients they are the affine view's exact crossings
//! (`affine::levin_plane_crossings`: the roots of `h(a)² − s·h(d)²` by the norm, sheets from
//! exact signs); where that route cannot place a crossing (both Levin forms vanish at one
//! parameter) sampling is an error. The walk's sign changes of `h`, located by regula falsi
//! (Illinois), are kept only for a curve piece known neither way (none reaches the walk
//! today). Affine coordinates are those of `X/h(X)` without the last
//! coordinate whose coefficient in `h` is nonzero (`(x/w, y/w, z/w)` for the default); `h` is
//! computed once per point during the walk and kept with the polyline, and the affine view
//! is cut from it in stretches of one sign.

use super::curve::{Arc, ComponentParam, Curve, Number, NumberPoly, ParamRange, ParamValue};
use super::curve::{RealPiece, Sheet};
use crate::error::Error;
use crate::quadric::Quadric;
use crate::Budget;
use qsic_algebra::field::NumberField;
use qsic_algebra::{AlgebraicReal, IBig, Poly, RBig, Ring, Sign};
use std::cell::RefCell;
use std::f64::consts::{FRAC_PI_2, PI};

/// Largest angle (radians) between consecutive unit vectors of a polyline, up to sign.
pub const MAX_ANGLE: f64 = 0.1;
/// Most bisections of one segment of the initial grid.
pub const MAX_DEPTH: u32 = 48;
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
                    *slot = Some(Sampler {
                        eval: match Evaluator::new(param) {
                            // the floats as they are where none is near the ends of the range
                            Ok(e) if e.narrow => e,
                            _ => {
                                let scaled =
                                    in_range[*component].get_or_init(|| in_float_range(param));
                                Evaluator::new(scaled.as_ref().unwrap_or(param))?
                            }
                        },
                        crossings: if lies_in_plane(param, &chart.exact) {
                            Crossings::InPlane
                        } else {
                            exact_crossings(param, &ExactParam::new(param), &chart.exact)?
                        },
                        singular: singular_params(curve, param, &chart.exact),
                        chart: &chart,
                        tolerance: options.tolerance,
                        approx: &approx,
                        ends: RefCell::new(Vec::new()),
                        other_sheet: RefCell::new(None),
                    });
                }
                let sampler = slot.as_ref().expect("made above");
                sampler.piece(*component, arcs, *closed, options.points, &mut budget)?
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

/// An upper estimate of `log₂|c|` from the bit lengths of its numerator's coefficients (a
/// polynomial in the field's generator `α`), of `α` and of its denominator; `None` for zero.
/// `log₂ max(|α|, 1)` comes from `alphas`, one entry per field met.
fn log2_estimate(c: &Number, alphas: &mut Vec<(NumberField, f64)>) -> Option<f64> {
    use dashu_int::ops::BitTest;
    let coeffs = c.numerator();
    let alpha = match c.field().filter(|_| coeffs.len() > 1) {
        None => 0.0,
        Some(k) => match alphas.iter().find(|(f, _)| f.same_as(k)) {
            Some((_, a)) => *a,
            None => {
                let a = alpha_log2(k);
                alphas.push((k.clone(), a));
                a
            }
        },
    };
    let top = coeffs
        .iter()
        .enumerate()
        .filter(|(_, v)| *v != &IBig::ZERO)
        .map(|(j, v)| v.bit_len() as f64 + j as f64 * alpha)
        .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.max(v))))?;
    Some(top + 4.0 - c.denominator().bit_len() as f64 + 1.0)
}

/// An upper bound of `log₂ max(|α|, 1)` for the generator of `k`: half the bit length of `δ`
/// for `α = ±√δ`, else from the float of `α`.
fn alpha_log2(k: &NumberField) -> f64 {
    use dashu_int::ops::BitTest;
    let alpha = k.alpha();
    match alpha.poly().coeffs() {
        [c0, c1, c2] if c1.is_zero() && *c2 == IBig::ONE => 0.5 * c0.bit_len() as f64,
        _ => alpha.to_f64().abs().max(1.0).log2(),
    }
}

/// `param` scaled by powers of two so that its largest coefficient is about 1, `None` when it
/// is small enough already (the largest estimate below `2^FLOAT_SCALE`, none below `2⁻⁹⁰⁰`):
/// the floats' squares and sums of squares (`‖X‖²`) stay far inside the range of `f64`, which
/// ends at `2¹⁰²⁴`. `X = a ± d√s` is projective: with `t_a`, `t_d`, `t_s` the largest
/// estimates, `s` gets `2^(2f)` (`f = −⌊t_s/2⌉`, so `s` is about 1), `d` gets `2^(−f−g)` and `a`
/// gets `2^(−g)` (`g = max(t_a, t_d − f)`): `a′ ± d′√s′ = 2^(−g)(a ± d√s)`, the point and both
/// sheets kept (positive factors).
fn in_float_range(param: &ComponentParam) -> Option<ComponentParam> {
    let mut alphas: Vec<(NumberField, f64)> = Vec::new();
    // (largest, smallest) estimate of each part, one pass over the coefficients
    let mut range = |v: &[NumberPoly]| -> (Option<f64>, f64) {
        let mut top: Option<f64> = None;
        let mut bottom = f64::INFINITY;
        for c in v.iter().flat_map(|p| p.coeffs()) {
            if let Some(e) = log2_estimate(c, &mut alphas) {
                top = Some(top.map_or(e, |t| t.max(e)));
                bottom = bottom.min(e);
            }
        }
        (top, bottom)
    };
    let out = |(t, b): (Option<f64>, f64)| t.is_some_and(|t| t > FLOAT_SCALE) || b < -900.0;
    let scale = |v: &[NumberPoly; 4], e: i64| -> [NumberPoly; 4] {
        let k = super::curve::rational(super::expr::power_of_two(e));
        std::array::from_fn(|i| v[i].map(|c| c.mul(&k)))
    };
    match param {
        ComponentParam::Point(_) => None,
        ComponentParam::Rational { x, degree } => {
            let rx = range(x);
            if !out(rx) {
                return None;
            }
            let e = rx.0? as i64;
            if rx.1 - (e as f64) < -900.0 {
                return None;
            }
            Some(ComponentParam::Rational {
                x: scale(x, -e),
                degree: *degree,
            })
        }
        ComponentParam::Levin {
            a,
            d,
            degree,
            alternate,
            s,
        } => {
            let (ra, rd, rs) = (range(a), range(d), range(std::slice::from_ref(s)));
            if !(out(ra) || out(rd) || out(rs)) {
                return None;
            }
            let f = -(rs.0? * 0.5).round() as i64;
            let g = ra.0.unwrap_or(f64::NEG_INFINITY).max(rd.0? - f as f64) as i64;
            let (ea, ed, es) = (g, f + g, 2 * f);
            // every coefficient in range after the scaling (none lost below the floats)
            let spread = |(t, b): (Option<f64>, f64), e: i64| {
                t.is_none_or(|t| t + (e as f64) < 900.0) && b + (e as f64) > -900.0
            };
            if !(spread(ra, -ea) && spread(rd, -ed) && spread(rs, es)) {
                return None;
            }
            let k = super::curve::rational(super::expr::power_of_two(es));
            Some(ComponentParam::Levin {
                a: scale(a, -ea),
                d: scale(d, -ed),
                degree: *degree,
                alternate: alternate.clone(),
                s: s.map(|c| c.mul(&k)),
            })
        }
    }
}

/// The exact parameters at which a rational component passes through the curve's real
/// singular points, each with whether the point lies on the chart's plane at infinity
/// (decided exactly); none for Levin's form (a nonsingular quartic has none), none either when
/// a point and the component live in fields made separately (the polyline is then not split
/// there).
fn singular_params(
    curve: &Curve,
    param: &ComponentParam,
    h: &[RBig; 4],
) -> Vec<(ParamValue, bool)> {
    let ComponentParam::Rational { x, degree } = param else {
        return Vec::new();
    };
    curve
        .singular_points
        .iter()
        .filter_map(|s| {
            let at_infinity = crate::affine::chart_value(h, &s.point).is_zero();
            crate::affine::params_of_point(x, *degree, &s.point)
                .ok()
                .map(|params| params.into_iter().map(move |v| (v, at_infinity)))
        })
        .flatten()
        .collect()
}

/// The plane at infinity, exactly and as floats, and the affine coordinate dropped.
struct Chart {
    exact: [RBig; 4],
    h: [f64; 4],
    form: ChartForm,
    /// The coordinates kept (all but the last whose coefficient in `h` is nonzero).
    keep: [usize; 3],
}

/// `h(X)` as floats: the dot product with `h`, or `c·Xⱼ` where `h = c·eⱼ` (the same value:
/// the other products are zeros, which leave a nonzero sum unchanged and a zero one zero).
#[derive(Clone, Copy, Default)]
struct ChartForm {
    h: [f64; 4],
    single: Option<(usize, f64)>,
}

impl ChartForm {
    fn new(h: [f64; 4]) -> ChartForm {
        let nonzero = h.iter().filter(|v| **v != 0.0).count();
        let single = (nonzero == 1 && h.iter().all(|v| v.is_finite()))
            .then(|| (0..4).find(|&j| h[j] != 0.0).map(|j| (j, h[j])))
            .flatten();
        ChartForm { h, single }
    }

    #[inline(always)]
    fn value(&self, x: &[f64; 4]) -> f64 {
        match self.single {
            // `j < 4` (made so in `new`): no bounds check
            Some((j, c)) => c * x[j & 3],
            None => dot(&self.h, x),
        }
    }
}

impl Chart {
    #[inline(always)]
    fn value(&self, x: &[f64; 4]) -> f64 {
        self.form.value(x)
    }

    /// Affine coordinates of `x`, `None` at infinity.
    fn affine(&self, x: &[f64; 4]) -> Option<[f64; 3]> {
        self.affine_with(x, self.value(x))
    }

    /// [`Chart::affine`] with `h = self.value(x)` given.
    fn affine_with(&self, x: &[f64; 4], h: f64) -> Option<[f64; 3]> {
        if h == 0.0 {
            return None;
        }
        let k = self.keep;
        Some([x[k[0]] / h, x[k[1]] / h, x[k[2]] / h])
    }
}

/// Converts coefficients to floats, `√δ` in double-double made once per field.
#[derive(Default)]
struct Converter {
    /// Each field met, with `α = ±√δ` in double-double and `δ` (`None`: not a field
    /// `ℚ(√δ)`).
    roots: Vec<(NumberField, Option<(Dd, IBig)>)>,
}

/// A coefficient as a float, and in double-double (about 104 bits) where that is cheap:
/// rationals and ℚ(√δ).
struct Converted {
    value: f64,
    dd: Option<Dd>,
}

impl Converter {
    /// `α` in double-double and `δ` when `k` is ℚ(√δ) generated by a root of `x² − δ` (the
    /// fields of Levin's form, [`super::curve::sqrt_field`]).
    fn root(&mut self, k: &NumberField) -> Option<(Dd, &IBig)> {
        let at = match self.roots.iter().position(|(f, _)| f.same_as(k)) {
            Some(at) => at,
            None => {
                self.roots.push((k.clone(), sqrt_generator_dd(k)));
                self.roots.len() - 1
            }
        };
        self.roots[at].1.as_ref().map(|(r, delta)| (*r, delta))
    }

    /// `c` as a float and in double-double (module docs); [`Number::to_f64`] where the
    /// double-double is not finite or not available.
    #[inline]
    fn convert(&mut self, c: &Number) -> Result<Converted, Error> {
        let num = c.numerator();
        // `v/1 = v` for a normalized double-double: the division left out; by a power of two
        // `2ᵏ` (one word), a product by `2⁻ᵏ`, exact away from the subnormals
        let over_den = |v: Dd| match c.denominator().as_sign_words().1 {
            [1] => v,
            [w] if w.is_power_of_two() && (v.0 == 0.0 || v.0.abs() >= 1e-250) => {
                let scale = 1.0 / (*w as f64);
                Dd(v.0 * scale, v.1 * scale)
            }
            _ => v.div(int_dd(c.denominator())),
        };
        let dd = if num.len() <= 1 {
            let n = num.first().map_or(Dd::default(), int_dd);
            Some(over_den(n))
        } else {
            // a numerator of positive degree has a field
            c.field()
                .and_then(|k| self.root(k))
                .and_then(|(r, delta)| sqrt_field_value(num, r, delta))
                .map(over_den)
        }
        .filter(|v| v.0.is_finite() && v.1.is_finite());
        let value = dd.map_or_else(|| c.to_f64(), |v| v.0 + v.1);
        if !value.is_finite() {
            return Err(Error::Algebra(format!(
                "coefficient {c} is beyond the range of f64"
            )));
        }
        Ok(Converted { value, dd })
    }
}

/// `c₀ + c₁α` with `α = ±√δ` given in double-double: the sum where the terms agree in sign
/// or cancel by fewer than 6 bits, else `(c₀² − c₁²δ)/(c₀ − c₁α)` with the integer norm
/// exact, so that cancellation costs at most 6 bits of about 104. `None` for a
/// representative of higher degree.
fn sqrt_field_value(num: &[IBig], root: Dd, delta: &IBig) -> Option<Dd> {
    let (c0, c1) = match num {
        [c0] => (c0, &IBig::ZERO),
        [c0, c1] => (c0, c1),
        _ => return None,
    };
    let (t0, t1) = (int_dd(c0), int_dd(c1).mul(root));
    // the sum loses at most `log₂(max/|sum|)` bits, under 6 of its ~104 when the terms agree
    // in sign or the sum keeps at least `2⁻⁶` of the larger
    let sum = t0.add(t1);
    if t0.0 == 0.0
        || t1.0 == 0.0
        || (t0.0 > 0.0) == (t1.0 > 0.0)
        || sum.0.abs() >= t0.0.abs().max(t1.0.abs()) * (1.0 / 64.0)
    {
        return Some(sum);
    }
    // the norm in machine integers where it fits, else in big integers
    let small = || -> Option<i128> {
        let (a, b, d) = (
            i128::try_from(c0).ok()?,
            i128::try_from(c1).ok()?,
            i128::try_from(delta).ok()?,
        );
        a.checked_mul(a)?
            .checked_sub(b.checked_mul(b)?.checked_mul(d)?)
    };
    let norm = match small() {
        Some(n) => i128_dd(n),
        None => int_dd(&(c0 * c0 - c1 * c1 * delta)),
    };
    Some(norm.div(t0.add(t1.neg())))
}

fn to_f64(c: &Number) -> Result<f64, Error> {
    Converter::default().convert(c).map(|c| c.value)
}

fn unit(x: [f64; 4]) -> Option<[f64; 4]> {
    let n = x.iter().map(|v| v * v).sum::<f64>().sqrt();
    (n > 0.0 && n.is_finite()).then(|| x.map(|v| v / n))
}

#[inline(always)]
fn dot(a: &[f64; 4], b: &[f64; 4]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]
}

fn point_piece(
    component: usize,
    point: &super::curve::Point,
    chart: &Chart,
) -> Result<SampledPiece, Error> {
    let mut x = [0.0; 4];
    for i in 0..4 {
        x[i] = to_f64(&point[i])?;
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

/// `2⁻⁸⁰⁰` and `2^FLOAT_SCALE`: a parameterization whose floats are all zero or within these
/// in magnitude needs no scaling ([`in_float_range`] leaves it as it is: its estimates are at
/// least `log₂|c|`, and above it by a few bits unless the terms of `c` cancel).
const NARROW: (f64, f64) = (
    f64::from_bits((1023 - 800) << 52),
    f64::from_bits((1023 + FLOAT_SCALE as u64) << 52),
);

/// Grid points between exact values of `(sin θ, cos θ)` ([`Evaluator::grid`]).
const RESYNC: usize = 64;

/// Most coefficients of one coordinate: homogeneous degree at most 8 (a quartic has 4).
const MAX_TERMS: usize = 9;

/// Four coordinates at once.
type Lanes = [f64; 4];

/// The coefficients in double-double, laid out as in [`Evaluator`].
#[derive(Clone)]
struct DdCoeffs {
    x: [[Dd; 4]; MAX_TERMS],
    d: [[Dd; 4]; MAX_TERMS],
    s: [Dd; 5],
}

impl Default for DdCoeffs {
    fn default() -> Self {
        DdCoeffs {
            x: [[Dd::default(); 4]; MAX_TERMS],
            d: [[Dd::default(); 4]; MAX_TERMS],
            s: [Dd::default(); 5],
        }
    }
}

/// Homogeneous float coefficients of a parameterization (increasing powers of `u`, padded
/// to the homogeneous degree `D`), one [`Lanes`] per power, and the sums of their absolute
/// values: `Σₖ|cₖ|` bounds the Horner bound `Σₖ|cₖ||t|ᵏ` on `[−1, 1]`, so that one
/// comparison certifies most evaluations and the exact bound is computed only where it
/// fails.
struct Evaluator<'a> {
    /// `(x, d, s)` in Horner's order for `rev` (index `rev as usize`): from the highest
    /// power down for `rev` false (`|t| ≤ 1`), in increasing powers for `rev` true
    /// ([`Evaluator::x`], [`Evaluator::d`], [`Evaluator::s`]) — one indexed load a point in
    /// [`Evaluator::parts`].
    horner: [HornerSet; 2],
    /// Levin's form (else rational).
    levin: bool,
    /// For the Horner order of `rev` (index `rev as usize`): the largest `|c₀ᵢ|` (the
    /// constant term in `t`) and `Σₖ₌₁|cₖᵢ|` over `i`, of `x` and of `d`: the majorant
    /// `|c₀| + |t|·Σₖ₌₁|cₖ|` of the bound `Σₖ|cₖ||t|ᵏ`, tighter than `Σₖ|cₖ|` near `t = 0`.
    split_abs: [(f64, f64, f64, f64); 2],
    /// The largest `Σₖ|xₖᵢ|` and `Σₖ|dₖᵢ|` over the coordinates `i`.
    x_abs_max: f64,
    d_abs_max: f64,
    /// Relative rounding of one evaluation, per unit of the bound.
    gamma: f64,
    /// A bound of every computed `√s` on `[−1, 1]` (`√(Σ|sₖ|)` with a margin), and the
    /// norm at or above which an evaluation with `√s` within it is certified whatever `t`:
    /// `γ·(Σ|x| + Σ|d|·√s) ≤ 10⁻¹⁰·‖X‖` ([`Evaluator::sure`]); infinite where the
    /// coefficients are too large for the shortcut.
    sure_root: f64,
    sure_norm: f64,
    /// Every coefficient is zero or within [`NARROW`] in magnitude.
    narrow: bool,
    /// The double-double coefficients made with the floats, when all came cheaply.
    quick_dd: Option<Box<DdCoeffs>>,
    /// The double-double coefficients for the retry of an ill-conditioned evaluation when
    /// `quick_dd` is missing, computed on the first retry.
    dd: std::cell::OnceCell<Box<DdCoeffs>>,
    /// The parameterization (for `dd`).
    param: &'a ComponentParam,
    /// The homogeneous degree `D`.
    big_d: usize,
}

/// The coefficients of one Horner order ([`Evaluator::horner`]), and the absolute values
/// of `x` and `d` (for the rounding bound, [`Evaluator::bound_of`]).
#[derive(Clone, Copy)]
struct HornerSet {
    x: [Lanes; MAX_TERMS],
    d: [Lanes; MAX_TERMS],
    s: [f64; 5],
    x_abs: [Lanes; MAX_TERMS],
    d_abs: [Lanes; MAX_TERMS],
}

/// A double-double number `hi + lo`, `|lo| ≤ ulp(hi)/2`: about 106 bits.
#[derive(Clone, Copy, Debug, Default)]
struct Dd(f64, f64);

impl Dd {
    fn two_sum(a: f64, b: f64) -> Dd {
        let s = a + b;
        let bb = s - a;
        Dd(s, (a - (s - bb)) + (b - bb))
    }
    fn add(self, o: Dd) -> Dd {
        let s = Dd::two_sum(self.0, o.0);
        let t = Dd::two_sum(self.1, o.1);
        let hi = Dd::two_sum(s.0, s.1 + t.0);
        Dd::two_sum(hi.0, hi.1 + t.1)
    }
    /// `self · t` for an `f64` `t` (Dekker's product by `mul_add`).
    fn mul_f64(self, t: f64) -> Dd {
        let p = self.0 * t;
        let e = self.0.mul_add(t, -p);
        Dd::two_sum(p, e + self.1 * t)
    }
    fn mul(self, o: Dd) -> Dd {
        let p = self.0 * o.0;
        let e = self.0.mul_add(o.0, -p);
        Dd::two_sum(p, e + self.0 * o.1 + self.1 * o.0)
    }
    fn neg(self) -> Dd {
        Dd(-self.0, -self.1)
    }
    /// `self / o` (two quotient digits).
    fn div(self, o: Dd) -> Dd {
        let q1 = self.0 / o.0;
        let r = self.add(o.mul_f64(-q1));
        let q2 = r.0 / o.0;
        Dd::two_sum(q1, q2)
    }
    /// `√self` (0 for a negative value: `s` clamped at its roots).
    fn sqrt(self) -> Dd {
        if self.0 <= 0.0 {
            return Dd(0.0, 0.0);
        }
        let r = self.0.sqrt();
        // one Newton step: r + (self − r²)/(2r)
        let sq = Dd(r, 0.0).mul(Dd(r, 0.0));
        let diff = self.add(sq.neg());
        Dd::two_sum(r, diff.0 / (2.0 * r))
    }
}

/// The integer value of a finite, integral `x`, exactly.
fn integral_f64_to_ibig(x: f64) -> IBig {
    let bits = x.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i64 - 1075;
    let mantissa = IBig::from((bits & ((1u64 << 52) - 1)) | (1u64 << 52));
    let m = if exp >= 0 {
        mantissa << exp as usize
    } else {
        mantissa >> (-exp) as usize
    };
    if x < 0.0 {
        -m
    } else {
        m
    }
}

/// An integer in double-double (exact below `2¹⁰⁶` in magnitude, rounded beyond).
#[inline(always)]
fn int_dd(v: &IBig) -> Dd {
    // the magnitude from its words where it fits in 127 bits (the usual case, no conversion
    // through the big-integer routines)
    let (sign, words) = v.as_sign_words();
    let neg = sign == dashu_int::Sign::Negative;
    // one word (the usual coefficient): below 2⁵³ exact in one float (`i64` to `f64`, one
    // instruction), else split as `i128_dd` does
    if let [w] = words {
        if *w < 1 << 53 {
            let x = (*w as i64) as f64;
            return Dd(if neg { -x } else { x }, 0.0);
        }
        return magnitude_dd(u128::from(*w), neg);
    }
    let bits = dashu_int::Word::BITS;
    if words.len() as u32 * bits <= 128 {
        let m = (words.iter().rev()).fold(0u128, |m, w| (m << (bits % 128)) | u128::from(*w));
        if m < 1 << 53 {
            let x = ((m as u64) as i64) as f64;
            return Dd(if neg { -x } else { x }, 0.0);
        }
        if m < 1 << 127 {
            return magnitude_dd(m, neg);
        }
    }
    wide_int_dd(v)
}

/// [`int_dd`] beyond `2¹²⁷`.
#[cold]
#[inline(never)]
fn wide_int_dd(v: &IBig) -> Dd {
    // the leading 120 bits (the rest is below the double-double's precision)
    let e = {
        use dashu_int::ops::BitTest;
        v.bit_len() - 120
    };
    if e <= 900 {
        if let Ok(top) = i128::try_from(&(v >> e)) {
            let d = i128_dd(top);
            let scale = f64::from_bits(((1023 + e) as u64) << 52);
            return Dd(d.0 * scale, d.1 * scale);
        }
    }
    let hi = v.to_f64().value();
    if hi.abs() < 9.0e15 || !hi.is_finite() {
        return Dd(hi, 0.0);
    }
    // |hi| ≥ 2⁵³: an integer, so the remainder is exact
    let lo = (v - integral_f64_to_ibig(hi)).to_f64().value();
    Dd(hi, lo)
}

/// An `i128` in double-double: its leading 53 bits (exact) plus the rest rounded, in
/// machine integers only.
fn i128_dd(v: i128) -> Dd {
    magnitude_dd(v.unsigned_abs(), v < 0)
}

/// `±m` in double-double for `m < 2¹²⁸` ([`i128_dd`]): the leading 53 bits `top·2ᵉ` (exact)
/// plus the rest `r < 2ᵉ` rounded. Machine words below `2⁶³` go to floats as signed
/// integers (one instruction each).
#[inline(always)]
fn magnitude_dd(m: u128, neg: bool) -> Dd {
    let bits = 128 - m.leading_zeros();
    if bits <= 53 {
        let x = ((m as u64) as i64) as f64;
        return Dd(if neg { -x } else { x }, 0.0);
    }
    let e = bits - 53;
    // `top < 2⁵³`
    let top = ((m >> e) as u64) as i64;
    let scale = f64::from_bits(((1023 + e) as u64) << 52);
    let rest = m - ((top as u128) << e);
    let rest_f = if rest < 1 << 63 {
        (rest as i64) as f64
    } else {
        ((rest >> 64) as u64) as f64 * 18446744073709551616.0 + (rest as u64) as f64
    };
    let d = Dd::two_sum(top as f64 * scale, rest_f);
    if neg {
        d.neg()
    } else {
        d
    }
}

/// `α` in double-double and `δ` when `α = ±√δ`, a root of `x² − δ` (Newton step in
/// double-double).
fn sqrt_generator_dd(k: &NumberField) -> Option<(Dd, IBig)> {
    let alpha = k.alpha();
    let delta = match alpha.poly().coeffs() {
        [c0, c1, c2] if c1.is_zero() && *c2 == IBig::ONE && *c0 < IBig::ZERO => -c0.clone(),
        _ => return None,
    };
    let root = int_dd(&delta).sqrt();
    let root = if alpha.interval().hi() <= &RBig::ZERO {
        root.neg()
    } else {
        root
    };
    Some((root, delta))
}

/// `c` to about 106 bits where [`Converter`] has no double-double: its value at a rational
/// within `2⁻¹²⁰` of `α`, split in two floats.
fn to_dd(c: &Number) -> Dd {
    let v = match c.field().filter(|_| c.numerator().len() > 1) {
        None => {
            c.numerator()
                .first()
                .map_or(RBig::ZERO, |v| RBig::from(v.clone()))
                / RBig::from(c.denominator().clone())
        }
        Some(k) => {
            let width = RBig::from_parts_signed(IBig::ONE, IBig::ONE << 120);
            let iv = k.alpha().refined_interval(&width);
            let mid = (iv.lo() + iv.hi()) / RBig::from(2);
            c.representative().eval(&mid)
        }
    };
    let hi = v.to_f64().value();
    let lo = RBig::try_from(hi).map_or(0.0, |h| (v - h).to_f64().value());
    Dd(hi, lo)
}

/// Horner's rule on four coordinates at once: `Σₖ cₖ tᵏ`, or `Σₖ cₖ t^(n−1−k)` reversed.
#[inline(always)]
fn horner_lanes(c: &[Lanes], t: f64, rev: bool) -> Lanes {
    let mut v = [0.0; 4];
    let mut step = |k: &Lanes| {
        for i in 0..4 {
            v[i] = v[i] * t + k[i];
        }
    };
    if rev {
        c.iter().for_each(&mut step);
    } else {
        c.iter().rev().for_each(&mut step);
    }
    v
}

/// [`horner_lanes`] of the absolute values at `|t|`: the rounding bound's majorant.
fn horner_lanes_abs(c: &[Lanes], t: f64, rev: bool) -> Lanes {
    let at = t.abs();
    let mut v = [0.0; 4];
    let mut step = |k: &Lanes| {
        for i in 0..4 {
            v[i] = v[i] * at + k[i].abs();
        }
    };
    if rev {
        c.iter().for_each(&mut step);
    } else {
        c.iter().rev().for_each(&mut step);
    }
    v
}

#[inline(always)]
fn horner_scalar(c: &[f64; 5], t: f64, rev: bool) -> f64 {
    if rev {
        c.iter().fold(0.0, |v, k| v * t + k)
    } else {
        c.iter().rev().fold(0.0, |v, k| v * t + k)
    }
}

fn horner_dd(c: &[Dd], t: f64, rev: bool) -> Dd {
    let mut v = Dd::default();
    let mut step = |k: &Dd| v = v.mul_f64(t).add(*k);
    if rev {
        c.iter().for_each(&mut step);
    } else {
        c.iter().rev().for_each(&mut step);
    }
    v
}

/// Newton's method on `f` (value, derivative) safeguarded by bisection in `(lo, hi)`, where
/// `f(lo) = flo` and `f(hi)` have opposite signs: a float near the root, returned once
/// `|f| ≤ noise` (the rounding level of `f`, where the steps only follow the noise).
fn newton_bracketed(f: &dyn Fn(f64) -> (f64, f64), lo: f64, hi: f64, flo: f64, noise: f64) -> f64 {
    let (mut a, mut b) = (lo, hi);
    let mut x = 0.5 * (a + b);
    for _ in 0..200 {
        let (fx, dfx) = f(x);
        if fx.abs() <= noise || !fx.is_finite() {
            return x;
        }
        if (fx < 0.0) == (flo < 0.0) {
            a = x;
        } else {
            b = x;
        }
        let newton = x - fx / dfx;
        let next = if a < newton && newton < b {
            newton
        } else {
            0.5 * (a + b)
        };
        if next == x
            || (next - x).abs() <= 2.0 * f64::EPSILON * x.abs()
            || b - a <= 4.0 * f64::EPSILON * a.abs().max(b.abs())
        {
            return next;
        }
        x = next;
    }
    x
}

/// The bounds of [`Evaluator::sure`]: `R = √(Σ|sₖ|·(1 + 2⁻³⁰))` bounds the computed `√s` at
/// any `|t| ≤ 1` (Horner's rounding is below `2⁻⁴⁰` relative to `Σ|sₖ||t|ᵏ` for five
/// terms), and `K = 10¹⁰·γ·(Σ|x| + Σ|d|·R)·(1 + 2⁻³⁰)`. Both infinite (nothing certified
/// this way) unless `K` is positive and the sum is below `10³⁰⁰`: the values are then finite.
fn sure_bounds(gamma: f64, x_abs_max: f64, d_abs_max: f64, s: &[f64; 5]) -> (f64, f64) {
    let margin = 1.0 + 2f64.powi(-30);
    let root = (s.iter().map(|v| v.abs()).sum::<f64>() * margin).sqrt();
    let size = x_abs_max + d_abs_max * root;
    let norm = 1e10 * gamma * size * margin;
    if size.is_finite() && size < 1e300 && norm > 0.0 && norm.is_finite() {
        (root, norm)
    } else {
        (f64::INFINITY, f64::INFINITY)
    }
}

/// The reduced parameters ([`reduced_parameter`]) of the grid `θₖ = t₀ + k·step`,
/// `k = 1, …, n − 1`: `(sin θₖ, cos θₖ)` by rotations from `(0, 1)`, exact every
/// [`RESYNC`] points.
fn grid_parameters(t0: f64, step: f64, n: usize) -> impl Iterator<Item = (f64, bool)> {
    let (sh, ch) = sin_cos(step);
    let mut u = (0.0, 1.0);
    (1..n).map(move |k| {
        u = if k % RESYNC == 1 {
            sin_cos(t0 + step * (k as f64))
        } else {
            (u.0 * ch + u.1 * sh, u.1 * ch - u.0 * sh)
        };
        reduced_parameter(u)
    })
}

/// `(sin θ, cos θ)` within a few ulps, cheaper than the library's: `θ` reduced by the
/// nearest multiple of `π/2` (in two parts: `k·P₁` exact for `|k| < 2²⁰`), then the Taylor
/// series on `|r| ≤ π/4` to `r¹⁷` and `r¹⁸` (the first terms left out below `10⁻¹⁹`). For the
/// parameters of single evaluations ([`Sampler::at`]): any `(U₀, U₁)` is a parameter, the
/// accuracy only places the point at `θ`. The library's beyond `|θ| ≤ 2¹⁸` (and for NaN).
fn sin_cos(theta: f64) -> (f64, f64) {
    if theta.is_nan() || theta.abs() > 262_144.0 {
        return theta.sin_cos();
    }
    // π/2 = P₁ + P₂, P₁ with 33 significant bits
    const P1: f64 = f64::from_bits(0x3FF9_21FB_5440_0000);
    const P2: f64 = f64::from_bits(0x3DD0_B461_1A62_6331);
    let k = (theta * std::f64::consts::FRAC_2_PI).round();
    let r = (theta - k * P1) - k * P2;
    let r2 = r * r;
    const S: [f64; 8] = [
        -1.0 / 6.0,
        1.0 / 120.0,
        -1.0 / 5_040.0,
        1.0 / 362_880.0,
        -1.0 / 39_916_800.0,
        1.0 / 6_227_020_800.0,
        -1.0 / 1_307_674_368_000.0,
        1.0 / 355_687_428_096_000.0,
    ];
    const C: [f64; 9] = [
        -1.0 / 2.0,
        1.0 / 24.0,
        -1.0 / 720.0,
        1.0 / 40_320.0,
        -1.0 / 3_628_800.0,
        1.0 / 479_001_600.0,
        -1.0 / 87_178_291_200.0,
        1.0 / 20_922_789_888_000.0,
        -1.0 / 6_402_373_705_728_000.0,
    ];
    let ps = S.iter().rev().fold(0.0, |v, c| v * r2 + c);
    let pc = C.iter().rev().fold(0.0, |v, c| v * r2 + c);
    let (sin, cos) = (r + r * r2 * ps, 1.0 + r2 * pc);
    match (k as i64) & 3 {
        0 => (sin, cos),
        1 => (cos, -sin),
        2 => (-sin, -cos),
        _ => (-cos, sin),
    }
}

/// `X(U₀, U₁)` as `t = U₀/U₁` (`|t| ≤ 1`) or `t = U₁/U₀` with the coefficients reversed.
fn reduced_parameter(u: (f64, f64)) -> (f64, bool) {
    if u.1.abs() >= u.0.abs() {
        (u.0 / u.1, false)
    } else {
        (u.1 / u.0, true)
    }
}

impl<'a> Evaluator<'a> {
    fn new(param: &'a ComponentParam) -> Result<Evaluator<'a>, Error> {
        let deg = |p: &NumberPoly| p.degree().unwrap_or(0);
        let (a, d, s, big_d, levin) = match param {
            ComponentParam::Point(_) => {
                return Err(Error::Algebra(
                    "a curve piece with a point parameterization".into(),
                ))
            }
            ComponentParam::Rational { x, .. } => {
                let big_d = x.iter().map(deg).max().unwrap_or(0);
                (x, None, None, big_d, false)
            }
            ComponentParam::Levin {
                a, d, s, degree, ..
            } => {
                if s.degree().is_some_and(|k| k > 4) {
                    return Err(Error::Algebra(format!("s(u) = {s} is not a quartic form")));
                }
                let big_d = a
                    .iter()
                    .map(deg)
                    .max()
                    .unwrap_or(0)
                    .max(d.iter().map(deg).max().unwrap_or(0) + 2)
                    .max(*degree);
                (a, Some(d), Some(s), big_d, true)
            }
        };
        if big_d >= MAX_TERMS {
            return Err(Error::Algebra(format!(
                "a parameterization of degree {big_d} (at most {} sampled)",
                MAX_TERMS - 1
            )));
        }
        let mut conv = Converter::default();
        let mut dd = Box::<DdCoeffs>::default();
        let mut all_dd = true;
        let mut narrow = true;
        let mut put = |c: &Number, f: &mut f64, g: &mut Dd| -> Result<(), Error> {
            let v = conv.convert(c)?;
            *f = v.value;
            let size = v.value.abs();
            narrow &= size == 0.0 || (NARROW.0..=NARROW.1).contains(&size);
            match v.dd {
                Some(x) => *g = x,
                None => all_dd = false,
            }
            Ok(())
        };
        let mut x = [[0.0; 4]; MAX_TERMS];
        let mut dv = [[0.0; 4]; MAX_TERMS];
        let mut sv = [0.0; 5];
        for i in 0..4 {
            for (k, c) in a[i].coeffs().iter().enumerate() {
                put(c, &mut x[k][i], &mut dd.x[k][i])?;
            }
            if let Some(d) = d {
                for (k, c) in d[i].coeffs().iter().enumerate() {
                    put(c, &mut dv[k][i], &mut dd.d[k][i])?;
                }
            }
        }
        if let Some(s) = s {
            for (k, c) in s.coeffs().iter().enumerate() {
                put(c, &mut sv[k], &mut dd.s[k])?;
            }
        }
        let abs_sum = |c: &[Lanes]| -> f64 {
            (0..4)
                .map(|i| c.iter().map(|k| k[i].abs()).sum::<f64>())
                .fold(0.0, f64::max)
        };
        let n = big_d + 1;
        let mut x_desc = [[0.0; 4]; MAX_TERMS];
        let mut d_desc = [[0.0; 4]; MAX_TERMS];
        for k in 0..n {
            x_desc[k] = x[n - 1 - k];
        }
        if levin {
            for k in 0..n - 2 {
                d_desc[k] = dv[n - 3 - k];
            }
        }
        let mut s_desc = sv;
        s_desc.reverse();
        // the constant term and the others' sums, in increasing powers of `t` (`rev` false)
        // and decreasing (`rev` true: the constant term is the last coefficient)
        let split = |c: &[Lanes], constant: usize| -> (f64, f64) {
            let c0 = c
                .get(constant)
                .map_or(0.0, |k| k.iter().fold(0.0, |m, v| v.abs().max(m)));
            let rest = (0..4)
                .map(|i| {
                    (c.iter().enumerate())
                        .filter(|(k, _)| *k != constant)
                        .map(|(_, k)| k[i].abs())
                        .sum::<f64>()
                })
                .fold(0.0, f64::max);
            (c0, rest)
        };
        let nd = if levin { n - 2 } else { 0 };
        let gamma = if levin {
            8.0 * (big_d as f64 + 4.0) * f64::EPSILON
        } else {
            4.0 * (big_d as f64 + 3.0) * f64::EPSILON
        };
        let (x_abs_max, d_abs_max) = (abs_sum(&x), abs_sum(&dv));
        let (sure_root, sure_norm) = sure_bounds(gamma, x_abs_max, d_abs_max, &sv);
        let split_abs = [(0, 0), (n - 1, nd.saturating_sub(1))].map(|(cx, cd)| {
            let (x0, x1) = split(&x[..n], cx);
            let (d0, d1) = split(&dv[..nd], cd);
            (x0, x1, d0, d1)
        });
        let abs = |c: &[Lanes; MAX_TERMS]| c.map(|k| k.map(f64::abs));
        let horner = [
            HornerSet {
                x: x_desc,
                d: d_desc,
                s: s_desc,
                x_abs: abs(&x_desc),
                d_abs: abs(&d_desc),
            },
            HornerSet {
                x,
                d: dv,
                s: sv,
                x_abs: abs(&x),
                d_abs: abs(&dv),
            },
        ];
        Ok(Evaluator {
            horner,
            split_abs,
            x_abs_max,
            d_abs_max,
            sure_root,
            sure_norm,
            levin,
            gamma,
            narrow,
            quick_dd: all_dd.then_some(dd),
            dd: std::cell::OnceCell::new(),
            param,
            big_d,
        })
    }

    /// `X` (rational) or `a` (Levin) in increasing powers, `D + 1` used.
    fn x(&self) -> &[Lanes; MAX_TERMS] {
        &self.horner[1].x
    }

    /// `d` (Levin) in increasing powers, `D − 1` used.
    fn d(&self) -> &[Lanes; MAX_TERMS] {
        &self.horner[1].d
    }

    /// `s` (Levin) in increasing powers.
    fn s(&self) -> &[f64; 5] {
        &self.horner[1].s
    }

    /// The unit vector of `X(U₀, U₁)` on `sheet` (up to sign), `None` where rounding could
    /// exceed `10⁻¹⁰·‖X‖` even in double-double.
    fn eval_unit(&self, u: (f64, f64), sheet: Sheet) -> Option<[f64; 4]> {
        let (t, rev) = reduced_parameter(u);
        // the usual degrees with their sizes known at compile time (unrolled Horner)
        match (self.levin, self.big_d) {
            (true, 2) => self.eval_unit_of::<3, 1>(t, rev, sheet),
            (true, 3) => self.eval_unit_of::<4, 2>(t, rev, sheet),
            (true, 4) => self.eval_unit_of::<5, 3>(t, rev, sheet),
            (false, 1) => self.eval_unit_of::<2, 0>(t, rev, sheet),
            (false, 2) => self.eval_unit_of::<3, 0>(t, rev, sheet),
            (false, 3) => self.eval_unit_of::<4, 0>(t, rev, sheet),
            (false, 4) => self.eval_unit_of::<5, 0>(t, rev, sheet),
            _ => {
                let (x, root) = self.values_any(t, rev, sheet);
                let norm = dot(&x, &x).sqrt();
                if self.cheaply_certified(t, rev, root, norm) {
                    return Some(x.map(|v| v / norm));
                }
                self.certify(t, rev, sheet, x, norm, root)
            }
        }
    }

    /// [`Evaluator::eval_unit`] for `NA` and `ND` coefficients.
    #[inline(always)]
    fn eval_unit_of<const NA: usize, const ND: usize>(
        &self,
        t: f64,
        rev: bool,
        sheet: Sheet,
    ) -> Option<[f64; 4]> {
        let (x, root) = self.values::<NA, ND>(t, rev, sheet);
        self.unit_of::<NA, ND>(x, root, t, rev, sheet)
    }

    /// Whether the bounds made once ([`Evaluator::sure`]) or the majorant at `|t|`
    /// ([`Evaluator::majorant`]) certify an evaluation with `√s = root` and norm `norm`.
    #[inline(always)]
    fn cheaply_certified(&self, t: f64, rev: bool, root: f64, norm: f64) -> bool {
        self.sure(root, norm)
            || norm.is_finite()
                && norm > 0.0
                && self.gamma * self.majorant(t, rev, root) <= 1e-10 * norm
    }

    /// The unit vector of the value `x` (with `√s = root`) at the reduced parameter `t`,
    /// certified: the majorant `Σ|cₖ|` first, the bound at `|t|` ([`Evaluator::bound_of`],
    /// the same value as [`Evaluator::certify`]'s) where it does not certify.
    #[inline(always)]
    fn unit_of<const NA: usize, const ND: usize>(
        &self,
        x: Lanes,
        root: f64,
        t: f64,
        rev: bool,
        sheet: Sheet,
    ) -> Option<[f64; 4]> {
        let norm = dot(&x, &x).sqrt();
        if self.cheaply_certified(t, rev, root, norm) {
            return Some(x.map(|v| v / norm));
        }
        self.certify_of::<NA, ND>(t, rev, sheet, x, norm, root)
    }

    /// [`Evaluator::certify`] with the unrolled bound of `NA` and `ND` coefficients.
    #[inline(always)]
    fn certify_of<const NA: usize, const ND: usize>(
        &self,
        t: f64,
        rev: bool,
        sheet: Sheet,
        x: Lanes,
        norm: f64,
        root: f64,
    ) -> Option<[f64; 4]> {
        let bound = self.bound_of::<NA, ND>(t, rev, root);
        if self.bound_certifies(bound, norm) {
            return Some(x.map(|v| v / norm));
        }
        self.certify_dd(bound, t, rev, sheet)
    }

    /// Whether the rounding bound `bound` at `|t|` certifies an evaluation of norm `norm`:
    /// `γ·bound ≤ 10⁻¹⁰·‖X‖` (false for NaN).
    #[inline(always)]
    fn bound_certifies(&self, bound: f64, norm: f64) -> bool {
        norm.is_finite() && norm > 0.0 && self.gamma * bound <= 1e-10 * norm
    }

    /// [`Evaluator::eval_unit`] on the uniform grid `θₖ = t₀ + k·step`, `k = 1, …, n − 1`,
    /// written to `out` (cleared first); `[NaN; 4]` where it gives `None`. `(sin θ, cos θ)` by
    /// rotations of the step, exact every [`RESYNC`] points: the drift stays within a few
    /// hundred ulps.
    fn grid(&self, t0: f64, step: f64, n: usize, sheet: Sheet, out: &mut Vec<[f64; 4]>) {
        match (self.levin, self.big_d) {
            (true, 2) => self.grid_of::<3, 1>(t0, step, n, sheet, out),
            (true, 3) => self.grid_of::<4, 2>(t0, step, n, sheet, out),
            (true, 4) => self.grid_of::<5, 3>(t0, step, n, sheet, out),
            (false, 1) => self.grid_of::<2, 0>(t0, step, n, sheet, out),
            (false, 2) => self.grid_of::<3, 0>(t0, step, n, sheet, out),
            (false, 3) => self.grid_of::<4, 0>(t0, step, n, sheet, out),
            (false, 4) => self.grid_of::<5, 0>(t0, step, n, sheet, out),
            _ => {
                out.clear();
                out.extend((1..n).map(|k| {
                    let u = sin_cos(t0 + step * (k as f64));
                    self.eval_unit(u, sheet).unwrap_or([f64::NAN; 4])
                }));
            }
        }
    }

    /// [`Evaluator::grid`] on both sheets of Levin's form at once (`a`, `d` and `√s`
    /// evaluated once a point): `plus` and `minus`.
    fn grid_both(
        &self,
        t0: f64,
        step: f64,
        n: usize,
        plus: &mut Vec<[f64; 4]>,
        minus: &mut Vec<[f64; 4]>,
    ) {
        match self.big_d {
            2 => self.grid_both_of::<3, 1>(t0, step, n, plus, minus),
            3 => self.grid_both_of::<4, 2>(t0, step, n, plus, minus),
            4 => self.grid_both_of::<5, 3>(t0, step, n, plus, minus),
            _ => {
                self.grid(t0, step, n, Sheet::Plus, plus);
                self.grid(t0, step, n, Sheet::Minus, minus);
            }
        }
    }

    /// [`Evaluator::grid_both`] for `NA` and `ND` coefficients.
    #[inline(never)]
    fn grid_both_of<const NA: usize, const ND: usize>(
        &self,
        t0: f64,
        step: f64,
        n: usize,
        plus: &mut Vec<[f64; 4]>,
        minus: &mut Vec<[f64; 4]>,
    ) {
        plus.clear();
        plus.resize(n.saturating_sub(1), [0.0; 4]);
        minus.clear();
        minus.resize(n.saturating_sub(1), [0.0; 4]);
        // the parameters of `grid_parameters`: a chunk of `RESYNC` from each exact one
        let (sh, ch) = sin_cos(step);
        let chunks = plus.chunks_mut(RESYNC).zip(minus.chunks_mut(RESYNC));
        for (c, (pc, mc)) in chunks.enumerate() {
            let mut u = sin_cos(t0 + step * ((c * RESYNC + 1) as f64));
            for (pu, mu) in pc.iter_mut().zip(mc.iter_mut()) {
                let (t, rev) = reduced_parameter(u);
                u = (u.0 * ch + u.1 * sh, u.1 * ch - u.0 * sh);
                let (a, w, root) = self.parts::<NA, ND>(t, rev);
                // the same operations as `values` on either sheet
                let (mut p, mut m) = (a, a);
                for i in 0..4 {
                    p[i] += root * w[i];
                    m[i] += -root * w[i];
                }
                let (np, nm) = (dot(&p, &p).sqrt(), dot(&m, &m).sqrt());
                if self.sure(root, np) && nm >= self.sure_norm {
                    *pu = p.map(|v| v / np);
                    *mu = m.map(|v| v / nm);
                    continue;
                }
                // `unit_of` on either sheet, the bound at `|t|` shared where it is needed
                let lhs = self.gamma * self.majorant(t, rev, root);
                let ok = |norm: f64| {
                    self.sure(root, norm) || norm.is_finite() && norm > 0.0 && lhs <= 1e-10 * norm
                };
                let (p_ok, m_ok) = (ok(np), ok(nm));
                (*pu, *mu) = if p_ok && m_ok {
                    (p.map(|v| v / np), m.map(|v| v / nm))
                } else {
                    self.certify_both::<NA, ND>(t, rev, root, (p, np, p_ok), (m, nm, m_ok))
                };
            }
        }
    }

    /// [`Evaluator::grid`] for `NA` and `ND` coefficients ([`Evaluator::values`]).
    #[inline(never)]
    fn grid_of<const NA: usize, const ND: usize>(
        &self,
        t0: f64,
        step: f64,
        n: usize,
        sheet: Sheet,
        out: &mut Vec<[f64; 4]>,
    ) {
        out.clear();
        out.reserve(n);
        for (t, rev) in grid_parameters(t0, step, n) {
            let (x, root) = self.values::<NA, ND>(t, rev, sheet);
            out.push(
                self.unit_of::<NA, ND>(x, root, t, rev, sheet)
                    .unwrap_or([f64::NAN; 4]),
            );
        }
    }

    /// `X` (and `√s`, 0 for a rational param) by Horner's rule with `NA` coefficients of `x`
    /// and `ND` of `d` (`ND = 0`: rational).
    #[inline(always)]
    fn values<const NA: usize, const ND: usize>(
        &self,
        t: f64,
        rev: bool,
        sheet: Sheet,
    ) -> (Lanes, f64) {
        let (mut v, w, root) = self.parts::<NA, ND>(t, rev);
        if ND == 0 {
            return (v, 0.0);
        }
        let sr = if sheet == Sheet::Minus { -root } else { root };
        for i in 0..4 {
            v[i] += sr * w[i];
        }
        (v, root)
    }

    /// `a(t)`, `d(t)` and `√s(t)` ([`Evaluator::values`] before the sheet is chosen), Horner's
    /// rule started at the leading coefficient.
    #[inline(always)]
    fn parts<const NA: usize, const ND: usize>(&self, t: f64, rev: bool) -> (Lanes, Lanes, f64) {
        let set = &self.horner[usize::from(rev)];
        let (xc, dc, sc) = (&set.x, &set.d, &set.s);
        let mut v = xc[0];
        for c in &xc[1..NA] {
            for i in 0..4 {
                v[i] = v[i] * t + c[i];
            }
        }
        if ND == 0 {
            return (v, [0.0; 4], 0.0);
        }
        let s = sc[1..].iter().fold(sc[0], |acc, c| acc * t + c);
        let root = s.max(0.0).sqrt();
        let mut w = dc[0];
        for c in &dc[1..ND] {
            for i in 0..4 {
                w[i] = w[i] * t + c[i];
            }
        }
        (v, w, root)
    }

    /// Whether an evaluation with `√s = root` and norm `norm` is certified by the bounds
    /// made once ([`sure_bounds`]): `γ·maxᵢ Σₖ(|xₖᵢ| + |dₖᵢ|·√s)|t|ᵏ ≤ γ·(Σ|x| + Σ|d|·√s)
    /// ≤ 10⁻¹⁰·‖X‖` for `|t| ≤ 1`; false for NaN.
    #[inline(always)]
    fn sure(&self, root: f64, norm: f64) -> bool {
        root <= self.sure_root && norm >= self.sure_norm
    }

    /// A majorant of the rounding bound at `t` of [`Evaluator::certify`] in a few operations:
    /// `Σₖ|cₖ|` and `|c₀| + |t|·Σₖ₌₁|cₖ|` (`|t| ≤ 1`), the smaller, for `x` and `d`.
    #[inline(always)]
    fn majorant(&self, t: f64, rev: bool, root: f64) -> f64 {
        let (x0, x1, d0, d1) = self.split_abs[rev as usize];
        let at = t.abs();
        let near = (x0 + at * x1) + (d0 + at * d1) * root;
        near.min(self.x_abs_max + self.d_abs_max * root)
    }

    /// The rounding bound of [`Evaluator::certify`] (`maxᵢ Σₖ (|xₖᵢ| + |dₖᵢ|·√s)|t|ᵏ`) for
    /// `NA` and `ND` coefficients: the same operations in the same order, unrolled.
    #[inline(always)]
    fn bound_of<const NA: usize, const ND: usize>(&self, t: f64, rev: bool, root: f64) -> f64 {
        let at = t.abs();
        let set = &self.horner[usize::from(rev)];
        let (xc, dc) = (&set.x_abs, &set.d_abs);
        let mut bx = xc[0];
        for c in &xc[1..NA] {
            for i in 0..4 {
                bx[i] = bx[i] * at + c[i];
            }
        }
        let mut bd = [0.0; 4];
        if ND > 0 {
            bd = dc[0];
            for c in &dc[1..ND] {
                for i in 0..4 {
                    bd[i] = bd[i] * at + c[i];
                }
            }
        }
        (0..4).map(|i| bx[i] + bd[i] * root).fold(0.0, f64::max)
    }

    /// The two sheets' points at a node of [`Evaluator::grid_both_of`] where the majorant
    /// `Σ|cₖ|` does not certify one of them: the bound at `|t|` (the same for both sheets)
    /// computed once, as [`Evaluator::unit_of`] would (inlined: the call cost more than the
    /// bound; the double-double retry stays out of line, [`Evaluator::certify_dd`]).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn certify_both<const NA: usize, const ND: usize>(
        &self,
        t: f64,
        rev: bool,
        root: f64,
        (p, np, p_ok): (Lanes, f64, bool),
        (m, nm, m_ok): (Lanes, f64, bool),
    ) -> ([f64; 4], [f64; 4]) {
        let bound = self.bound_of::<NA, ND>(t, rev, root);
        let one = |x: Lanes, norm: f64, ok: bool, sheet: Sheet| {
            if ok || self.bound_certifies(bound, norm) {
                x.map(|v| v / norm)
            } else {
                self.certify_dd(bound, t, rev, sheet)
                    .unwrap_or([f64::NAN; 4])
            }
        };
        (
            one(p, np, p_ok, Sheet::Plus),
            one(m, nm, m_ok, Sheet::Minus),
        )
    }

    /// [`Evaluator::values`] for any degree.
    fn values_any(&self, t: f64, rev: bool, sheet: Sheet) -> (Lanes, f64) {
        let n = self.big_d + 1;
        let mut x = horner_lanes(&self.x()[..n], t, rev);
        let mut root = 0.0;
        if self.levin {
            root = horner_scalar(self.s(), t, rev).max(0.0).sqrt();
            let dv = horner_lanes(&self.d()[..n - 2], t, rev);
            let sr = if sheet == Sheet::Minus { -root } else { root };
            for i in 0..4 {
                x[i] += sr * dv[i];
            }
        }
        (x, root)
    }

    /// The rounding bound of `x` at `|t|`; the double-double evaluation where it is too
    /// large.
    #[cold]
    fn certify(
        &self,
        t: f64,
        rev: bool,
        sheet: Sheet,
        x: Lanes,
        norm: f64,
        root: f64,
    ) -> Option<[f64; 4]> {
        let n = self.big_d + 1;
        let bx = horner_lanes_abs(&self.x()[..n], t, rev);
        let bd = if self.levin {
            horner_lanes_abs(&self.d()[..n - 2], t, rev)
        } else {
            [0.0; 4]
        };
        let bound = (0..4).map(|i| bx[i] + bd[i] * root).fold(0.0, f64::max);
        self.certify_with(bound, t, rev, sheet, x, norm)
    }

    /// [`Evaluator::certify`] given the rounding bound at `|t|`.
    fn certify_with(
        &self,
        bound: f64,
        t: f64,
        rev: bool,
        sheet: Sheet,
        x: Lanes,
        norm: f64,
    ) -> Option<[f64; 4]> {
        if self.bound_certifies(bound, norm) {
            return Some(x.map(|v| v / norm));
        }
        self.certify_dd(bound, t, rev, sheet)
    }

    /// The retry in double-double of an evaluation whose rounding bound at `|t|` is
    /// `bound` (too large for the floats); `None` for an infinite bound.
    #[cold]
    #[inline(never)]
    fn certify_dd(&self, bound: f64, t: f64, rev: bool, sheet: Sheet) -> Option<[f64; 4]> {
        if !bound.is_finite() {
            return None;
        }
        self.eval_dd(t, rev, sheet, bound).and_then(unit)
    }

    /// The root of `s` in `(lo, hi)` by Newton's method safeguarded by bisection, `s`
    /// evaluated in double-double: `None` unless `s` has opposite signs at the ends (or the
    /// interval is below the float resolution: its midpoint) and the root is well
    /// conditioned (rounding moves it by at most `2⁻⁴²` relative).
    fn root_of_s(&self, lo: f64, hi: f64) -> Option<f64> {
        let close = |a: f64, b: f64| b - a <= 4.0 * f64::EPSILON * a.abs().max(b.abs());
        if !(lo.is_finite() && hi.is_finite() && lo < hi) {
            return None;
        }
        let sd = &self.dd().s;
        // s(u) and s′(u) in floats; s(u) in double-double
        let float = |u: f64| -> (f64, f64) {
            self.s()
                .iter()
                .rev()
                .fold((0.0, 0.0), |(v, dv), &k| (v * u + k, dv * u + v))
        };
        let f = |u: f64| -> (f64, f64) {
            let v = sd
                .iter()
                .rev()
                .fold(Dd::default(), |v, k| v.mul_f64(u).add(*k));
            (v.0 + v.1, float(u).1)
        };
        // a float Newton start where the floats bracket the root, polished in double-double
        let (glo, ghi) = (float(lo).0, float(hi).0);
        if glo * ghi < 0.0 {
            // Horner's rounding of `s` in floats on the bracket: within `16ε·Σ|sₖ||u|ᵏ`
            let m = lo.abs().max(hi.abs());
            let size = self.s().iter().rev().fold(0.0, |v: f64, k| v * m + k.abs());
            let start = newton_bracketed(&float, lo, hi, glo, 16.0 * f64::EPSILON * size);
            let mut x = start;
            for _ in 0..3 {
                let (fx, dfx) = f(x);
                let next = x - fx / dfx;
                if !(lo < next && next < hi) {
                    break;
                }
                let done = (next - x).abs() <= 2.0 * f64::EPSILON * x.abs();
                x = next;
                if done {
                    let size = self
                        .s()
                        .iter()
                        .rev()
                        .fold(0.0, |v: f64, k| v * x.abs() + k.abs());
                    // the derivative in floats (as `f` gives it), without `s` in double-double
                    let err = 16.0 * 2f64.powi(-104) * size / float(x).1.abs();
                    if err.is_finite() && err <= x.abs() * 2f64.powi(-42) {
                        return Some(x);
                    }
                    break;
                }
            }
        }
        let (flo, fhi) = (f(lo).0, f(hi).0);
        let brackets = flo * fhi < 0.0;
        if !brackets {
            return close(lo, hi).then_some(0.5 * (lo + hi));
        }
        // accepted where the rounding of s (about 2⁻¹⁰⁴ of its terms) moves the root by at
        // most |x|·2⁻⁴²
        let conditioned = |x: f64| -> Option<f64> {
            let size = self
                .s()
                .iter()
                .rev()
                .fold(0.0, |v: f64, k| v * x.abs() + k.abs());
            let err = 16.0 * 2f64.powi(-104) * size / float(x).1.abs();
            (err.is_finite() && err <= x.abs() * 2f64.powi(-42)).then_some(x)
        };
        let (mut a, mut b) = (lo, hi);
        let mut x = 0.5 * (a + b);
        for _ in 0..200 {
            let (fx, dfx) = f(x);
            if fx == 0.0 {
                return conditioned(x);
            }
            if !fx.is_finite() {
                return None;
            }
            if (fx < 0.0) == (flo < 0.0) {
                a = x;
            } else {
                b = x;
            }
            if close(a, b) {
                return conditioned(0.5 * (a + b));
            }
            let newton = x - fx / dfx;
            let next = if a < newton && newton < b {
                newton
            } else {
                0.5 * (a + b)
            };
            if next == x || (next - x).abs() <= 2.0 * f64::EPSILON * x.abs() {
                return conditioned(next);
            }
            x = next;
        }
        None
    }

    /// The double-double coefficients (see `quick_dd`, `dd`).
    fn dd(&self) -> &DdCoeffs {
        if let Some(q) = &self.quick_dd {
            return q;
        }
        self.dd.get_or_init(|| {
            let mut out = Box::<DdCoeffs>::default();
            let (a, d, s) = match self.param {
                ComponentParam::Rational { x, .. } => (x, None, None),
                ComponentParam::Levin { a, d, s, .. } => (a, Some(d), Some(s)),
                ComponentParam::Point(_) => return out,
            };
            for i in 0..4 {
                for (k, c) in a[i].coeffs().iter().enumerate() {
                    out.x[k][i] = to_dd(c);
                }
                if let Some(d) = d {
                    for (k, c) in d[i].coeffs().iter().enumerate() {
                        out.d[k][i] = to_dd(c);
                    }
                }
            }
            if let Some(s) = s {
                for (k, c) in s.coeffs().iter().enumerate() {
                    out.s[k] = to_dd(c);
                }
            }
            out
        })
    }

    /// `X` in double-double arithmetic (`t` is exact), `None` where even that rounding could
    /// exceed `10⁻¹⁰·‖X‖`.
    fn eval_dd(&self, t: f64, rev: bool, sheet: Sheet, bound: f64) -> Option<[f64; 4]> {
        let x = self.values_dd(t, rev, sheet);
        let x = if x.iter().all(|v| v.is_finite()) {
            x
        } else {
            // beyond the range of Veltkamp's split: with the fused products
            self.values_dd_fused(t, rev, sheet)
        };
        let norm = x.iter().map(|v| v * v).sum::<f64>().sqrt();
        let gamma = self.gamma * f64::EPSILON * 4.0;
        (norm.is_finite() && norm > 0.0 && gamma * bound <= 1e-10 * norm).then_some(x)
    }

    /// `X` in double-double arithmetic, the four coordinates at once ([`Dd4`]): the values of
    /// [`Evaluator::values_dd_fused`] (every product error is exact either way) wherever
    /// Veltkamp's split does not overflow (else a NaN).
    fn values_dd(&self, t: f64, rev: bool, sheet: Sheet) -> [f64; 4] {
        let dd = self.dd();
        let n = self.big_d + 1;
        let ts = split(t);
        let horner = |c: &[[Dd; 4]]| -> Dd4 {
            let mut v = Dd4::default();
            let mut step = |k: &[Dd; 4]| v = v.mul_f64(t, ts).add(&Dd4::of(k));
            if rev {
                c.iter().for_each(&mut step);
            } else {
                c.iter().rev().for_each(&mut step);
            }
            v
        };
        let mut v = horner(&dd.x[..n]);
        if self.levin {
            let r = horner_dd(&dd.s, t, rev).sqrt();
            let mut dr = horner(&dd.d[..n - 2]).mul(r);
            if sheet == Sheet::Minus {
                dr = Dd4 {
                    hi: dr.hi.map(|v| -v),
                    lo: dr.lo.map(|v| -v),
                };
            }
            v = v.add(&dr);
        }
        std::array::from_fn(|i| v.hi[i] + v.lo[i])
    }

    /// [`Evaluator::values_dd`] one coordinate at a time, products by `mul_add`.
    fn values_dd_fused(&self, t: f64, rev: bool, sheet: Sheet) -> [f64; 4] {
        let dd = self.dd();
        let n = self.big_d + 1;
        let root = self.levin.then(|| horner_dd(&dd.s, t, rev).sqrt());
        let column = |c: &[[Dd; 4]], i: usize| -> Dd {
            let mut v = Dd::default();
            let mut step = |k: &[Dd; 4]| v = v.mul_f64(t).add(k[i]);
            if rev {
                c.iter().for_each(&mut step);
            } else {
                c.iter().rev().for_each(&mut step);
            }
            v
        };
        let mut x = [0.0; 4];
        for i in 0..4 {
            let mut v = column(&dd.x[..n], i);
            if let Some(r) = root {
                let mut dr = column(&dd.d[..n - 2], i).mul(r);
                if sheet == Sheet::Minus {
                    dr = dr.neg();
                }
                v = v.add(dr);
            }
            x[i] = v.0 + v.1;
        }
        x
    }
}

/// Veltkamp's split of `a` into `h + l` exactly, each of at most 26 significant bits
/// (`|a| < 2⁹⁹⁶`; beyond, NaN).
#[inline(always)]
fn split(a: f64) -> (f64, f64) {
    let c = 134_217_729.0 * a;
    let h = c - (c - a);
    (h, a - h)
}

/// `a·b − p` for `p = fl(a·b)`, exactly, by Dekker's product (`b` given split, [`split`]):
/// the value of `a.mul_add(b, −p)` without a fused multiply-add (away from underflow).
#[inline(always)]
fn product_error(a: f64, (bh, bl): (f64, f64), p: f64) -> f64 {
    let (ah, al) = split(a);
    al * bl - (((p - ah * bh) - al * bh) - ah * bl)
}

/// Four double-doubles ([`Dd`]) lane by lane, the operations of [`Dd`] on each (written
/// lane-wise so that they run on vector registers).
#[derive(Clone, Copy, Default)]
struct Dd4 {
    hi: Lanes,
    lo: Lanes,
}

impl Dd4 {
    fn of(v: &[Dd; 4]) -> Dd4 {
        Dd4 {
            hi: v.map(|d| d.0),
            lo: v.map(|d| d.1),
        }
    }

    #[inline(always)]
    fn two_sum(a: Lanes, b: Lanes) -> Dd4 {
        let mut out = Dd4::default();
        for i in 0..4 {
            let s = a[i] + b[i];
            let bb = s - a[i];
            out.hi[i] = s;
            out.lo[i] = (a[i] - (s - bb)) + (b[i] - bb);
        }
        out
    }

    /// [`Dd::add`] on each lane.
    #[inline(always)]
    fn add(&self, o: &Dd4) -> Dd4 {
        let s = Dd4::two_sum(self.hi, o.hi);
        let t = Dd4::two_sum(self.lo, o.lo);
        let hi = Dd4::two_sum(s.hi, std::array::from_fn(|i| s.lo[i] + t.hi[i]));
        Dd4::two_sum(hi.hi, std::array::from_fn(|i| hi.lo[i] + t.lo[i]))
    }

    /// [`Dd::mul_f64`] on each lane, `ts` the split of `t`.
    #[inline(always)]
    fn mul_f64(&self, t: f64, ts: (f64, f64)) -> Dd4 {
        let p: Lanes = std::array::from_fn(|i| self.hi[i] * t);
        let e: Lanes =
            std::array::from_fn(|i| product_error(self.hi[i], ts, p[i]) + self.lo[i] * t);
        Dd4::two_sum(p, e)
    }

    /// [`Dd::mul`] by one double-double on each lane.
    #[inline(always)]
    fn mul(&self, o: Dd) -> Dd4 {
        let os = split(o.0);
        let p: Lanes = std::array::from_fn(|i| self.hi[i] * o.0);
        let e: Lanes = std::array::from_fn(|i| {
            product_error(self.hi[i], os, p[i]) + self.hi[i] * o.1 + self.lo[i] * o.0
        });
        Dd4::two_sum(p, e)
    }
}

/// One point of a polyline: where on the parameter line, and the unit vector.
#[derive(Clone, Copy, Debug)]
struct Sample {
    theta: f64,
    x: [f64; 4],
    /// A crossing of the plane at infinity found exactly.
    at_infinity: bool,
    /// A real singular point of the curve, at its exact parameter.
    singular: bool,
}

impl Sample {
    fn new(theta: f64, x: [f64; 4]) -> Sample {
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
struct Approximations(RefCell<Vec<(AlgebraicReal, f64)>>);

impl Approximations {
    fn of(&self, r: &AlgebraicReal) -> f64 {
        if let Some((_, v)) = self.0.borrow().iter().find(|(q, _)| q.same_definition(r)) {
            return *v;
        }
        let v = r.to_f64();
        self.0.borrow_mut().push((r.clone(), v));
        v
    }
}

/// The ends of an arc in `θ` and their exact points on ℙ¹.
struct ArcSpan {
    theta: (f64, f64),
    ends: ((f64, f64), (f64, f64)),
}

/// `(U₀, U₁)` of a finite `u` with `max(|U₀|, |U₁|) = 1`.
fn projective(u: f64) -> (f64, f64) {
    if u.abs() <= 1.0 {
        (u, 1.0)
    } else {
        (1.0, 1.0 / u)
    }
}

fn span<'r>(
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

/// A float on the side of `q` given by `up` (`> q` for `up`, `< q` otherwise; `q` itself
/// when it is zero), from the quotient of the floats of its numerator and denominator (each
/// within one ulp: the leading part of [`int_dd`], a one-word denominator rounded to nearest;
/// the quotient rounded to nearest: within `2.5` ulps) moved by `8ε·|v|` (at least four ulps); NaN where a float is not finite or
/// below the normal range (no such float is known cheaply). Cheaper than the correctly
/// rounded [`RBig::to_f64`].
fn inner_f64(q: &RBig, up: bool) -> f64 {
    let d = match q.denominator().as_words() {
        [w] => *w as f64,
        _ => q.denominator().to_f64().value(),
    };
    let n = int_dd(q.numerator()).0;
    if n == 0.0 && q.numerator().is_zero() {
        return 0.0;
    }
    let v = n / d;
    if !(v.is_finite() && v.abs() >= f64::MIN_POSITIVE * 1e10) {
        return f64::NAN;
    }
    let m = v.abs() * (8.0 * f64::EPSILON);
    if up {
        v + m
    } else {
        v - m
    }
}

/// The exact coefficients of a component whose coefficients are all rational.
enum ExactParam {
    Rational {
        x: [Poly<RBig>; 4],
        degree: usize,
    },
    Levin {
        a: [Poly<RBig>; 4],
        d: [Poly<RBig>; 4],
        s: Poly<RBig>,
        degree: usize,
    },
    /// Some coefficient is irrational: crossings from sign changes.
    Irrational,
}

fn rational_poly(p: &NumberPoly) -> Option<Poly<RBig>> {
    let c = p
        .coeffs()
        .iter()
        .map(|c| match c.numerator() {
            [] => Some(RBig::ZERO),
            [v] => Some(RBig::from(v.clone()) / RBig::from(c.denominator().clone())),
            _ => None,
        })
        .collect::<Option<Vec<_>>>()?;
    Some(Poly::new(c))
}

/// `true` if every coefficient of `p` is rational (a numerator of degree 0 at most): the
/// check before [`rational_poly`], which allocates.
fn is_rational(p: &NumberPoly) -> bool {
    p.coeffs().iter().all(|c| c.numerator().len() <= 1)
}

fn rational_vector(v: &[NumberPoly; 4]) -> Option<[Poly<RBig>; 4]> {
    if !v.iter().all(is_rational) {
        return None;
    }
    let mut out: [Poly<RBig>; 4] = Default::default();
    for i in 0..4 {
        out[i] = rational_poly(&v[i])?;
    }
    Some(out)
}

impl ExactParam {
    fn new(param: &ComponentParam) -> ExactParam {
        let deg = |p: &NumberPoly| p.degree().unwrap_or(0);
        let found = match param {
            ComponentParam::Point(_) => None,
            ComponentParam::Rational { x, .. } => rational_vector(x).map(|x| {
                // without the common factor of the coordinates (removable zeros of X)
                let g = x.iter().fold(Poly::zero(), |g, p| g.gcd_monic(p));
                let x = if g.degree().unwrap_or(0) > 0 {
                    x.map(|p| p.div_rem(&g).0)
                } else {
                    x
                };
                let degree = x.iter().map(|p| p.degree().unwrap_or(0)).max().unwrap_or(0);
                ExactParam::Rational { x, degree }
            }),
            ComponentParam::Levin {
                a, d, s, degree, ..
            } => {
                let degree = a
                    .iter()
                    .map(deg)
                    .max()
                    .unwrap_or(0)
                    .max(d.iter().map(deg).max().unwrap_or(0) + 2)
                    .max(*degree);
                // the conversions only where all is rational (not for ℚ(√δ), the usual case)
                if a.iter().chain(d).all(is_rational) && is_rational(s) {
                    match (rational_vector(a), rational_vector(d), rational_poly(s)) {
                        (Some(a), Some(d), Some(s)) => Some(ExactParam::Levin { a, d, s, degree }),
                        _ => None,
                    }
                } else {
                    None
                }
            }
        };
        found.unwrap_or(ExactParam::Irrational)
    }
}

/// `Σ hᵢ vᵢ(u)`.
fn chart_form(h: &[RBig; 4], v: &[Poly<RBig>; 4]) -> Poly<RBig> {
    (0..4).fold(Poly::zero(), |acc, i| &acc + &v[i].scale(&h[i]))
}

/// A crossing of the plane at infinity: where on ℙ¹ and on which sheets.
struct Crossing {
    value: ParamValue,
    /// Sheets whose point is at infinity (`Only` for a rational param).
    sheets: Vec<Sheet>,
}

/// Whether the exact `value` lies in `range` (ends included).
fn in_range(value: &ParamValue, range: &ParamRange) -> bool {
    let ParamRange::Between(lo, hi) = range else {
        return true;
    };
    match (value, lo, hi) {
        (ParamValue::Infinity, ParamValue::Finite(l), ParamValue::Finite(h)) => h <= l,
        (ParamValue::Infinity, _, _) => true,
        (ParamValue::Finite(_), ParamValue::Infinity, ParamValue::Infinity) => true,
        (ParamValue::Finite(r), ParamValue::Infinity, ParamValue::Finite(h)) => r <= h,
        (ParamValue::Finite(r), ParamValue::Finite(l), ParamValue::Infinity) => r >= l,
        (ParamValue::Finite(r), ParamValue::Finite(l), ParamValue::Finite(h)) => {
            if l < h {
                l <= r && r <= h
            } else {
                r >= l || r <= h
            }
        }
    }
}

/// What is known exactly of a component's crossings with the plane at infinity.
enum Crossings {
    /// Every crossing, exactly.
    Exact(Vec<Crossing>),
    /// The component lies in the plane.
    InPlane,
    /// Irrational coefficients: crossings from sign changes along the polyline.
    Unknown,
}

/// Whether a rational parameterization lies in the plane `h = 0` (`h·X(u) ≡ 0`, exactly, in
/// any number field).
fn lies_in_plane(param: &ComponentParam, h: &[RBig; 4]) -> bool {
    let ComponentParam::Rational { x, .. } = param else {
        return false;
    };
    (0..4)
        .fold(Poly::<Number>::zero(), |acc, i| {
            &acc + &x[i].scale(&Number::rational(h[i].clone()))
        })
        .is_zero()
}

/// The exact crossings of the component with the plane `h = 0`: over a number field those of
/// a rational parameterization ([`super::infinity`]), none known of Levin's form.
///
/// # Errors
/// Where the exact route cannot place a crossing on Levin's form (both forms vanish at one
/// parameter): an error, not a float guess.
fn exact_crossings(
    param: &ComponentParam,
    exact: &ExactParam,
    h: &[RBig; 4],
) -> Result<Crossings, Error> {
    let found = match (exact, param) {
        (ExactParam::Irrational, ComponentParam::Rational { x, .. }) => {
            super::infinity::plane_crossings(x, h).map(|values| {
                let only = |value| Crossing {
                    value,
                    sheets: vec![Sheet::Only],
                };
                values.into_iter().map(only).collect()
            })
        }
        (
            ExactParam::Irrational,
            ComponentParam::Levin {
                a,
                d,
                s,
                degree,
                alternate,
            },
        ) => {
            let primary = super::LevinForm {
                a: a.clone(),
                d: d.clone(),
                degree: *degree,
            };
            let events =
                crate::affine::levin_plane_crossings(h, &primary, s, alternate.as_deref())?;
            Some(levin_crossings(events))
        }
        (ExactParam::Irrational, _) => return Ok(Crossings::Unknown),
        _ => exact_crossings_of(exact, h),
    };
    Ok(match found {
        None => Crossings::InPlane,
        Some(c) => Crossings::Exact(c),
    })
}

/// The crossings of [`crate::affine::levin_plane_crossings`]: the sheets at one parameter
/// together, both where `s = 0`.
fn levin_crossings(events: Vec<(ParamValue, Option<Sheet>)>) -> Vec<Crossing> {
    let mut out: Vec<Crossing> = Vec::new();
    for (value, sheet) in events {
        let sheets = match sheet {
            Some(sheet) => vec![sheet],
            None => vec![Sheet::Plus, Sheet::Minus],
        };
        match out.last_mut() {
            Some(last) if same_value(&last.value, &value) => last.sheets.extend(sheets),
            _ => out.push(Crossing { value, sheets }),
        }
    }
    out
}

fn same_value(a: &ParamValue, b: &ParamValue) -> bool {
    match (a, b) {
        (ParamValue::Infinity, ParamValue::Infinity) => true,
        (ParamValue::Finite(x), ParamValue::Finite(y)) => x == y,
        _ => false,
    }
}

fn exact_crossings_of(exact: &ExactParam, h: &[RBig; 4]) -> Option<Vec<Crossing>> {
    let roots = |p: &Poly<RBig>| -> Vec<AlgebraicReal> {
        AlgebraicReal::real_roots_of(&Poly::from_rational(p).0.squarefree_part())
    };
    match exact {
        ExactParam::Irrational => None,
        ExactParam::Rational { x, degree } => {
            let g = chart_form(h, x);
            if g.is_zero() {
                return None;
            }
            let mut out: Vec<Crossing> = roots(&g)
                .into_iter()
                .map(|r| Crossing {
                    value: ParamValue::Finite(r),
                    sheets: vec![Sheet::Only],
                })
                .collect();
            if g.degree().unwrap_or(0) < *degree {
                out.push(Crossing {
                    value: ParamValue::Infinity,
                    sheets: vec![Sheet::Only],
                });
            }
            Some(out)
        }
        ExactParam::Levin { a, d, s, degree } => {
            // over ℤ: a = A/α, d = D/β, s = S/γ, h = H/η with positive integers α, β, γ, η;
            // h(a)² − h(d)²·s times η²α²β²γ is N = H(A)²·β²γ − H(D)²·S·α², and
            // a_i² − d_i²·s times α²β²γ is A_i²·β²γ − D_i²·S·α² (signs and zeros kept)
            let (av, alpha) = integer_vector(a);
            let (dv, beta) = integer_vector(d);
            let (sv, gamma) = integer_vector(std::slice::from_ref(s));
            let (hv, _) = integer_row(h);
            let sz = &sv[0];
            let form = |v: &[Poly]| -> Poly {
                (0..4).fold(Poly::zero(), |acc, i| &acc + &v[i].scale(&hv[i]))
            };
            let (ha, hd) = (form(&av), form(&dv));
            let (k1, k2) = (&beta * &beta * &gamma, &alpha * &alpha);
            let norm =
                |x: &Poly, y: &Poly| -> Poly { &(x * x).scale(&k1) - &(&(y * y) * sz).scale(&k2) };
            let n = norm(&ha, &hd);
            if n.is_zero() {
                // a quartic is not planar: h(a) = ±h(d)√s identically cannot hold
                return Some(Vec::new());
            }
            let sheets = crossing_sheets;
            // a_i² − d_i²·s: X_σ is the zero vector where every one vanishes and the signs
            // of a_i and d_i match σ (a removable zero of Levin's form, where c₂ = 0: not a
            // point of the plane, whatever h is)
            let norms: Vec<Poly> = (0..4).map(|i| norm(&av[i], &dv[i])).collect();
            let vanishes = |sheet: Sheet,
                            sign_a: &dyn Fn(usize) -> Sign,
                            sign_d: &dyn Fn(usize) -> Sign,
                            norm_zero: &dyn Fn(usize) -> bool| {
                (0..4).all(|i| {
                    let (sa, sd) = (sign_a(i), sign_d(i));
                    norm_zero(i)
                        && match sheet {
                            Sheet::Plus => sa == -sd,
                            _ => sa == sd,
                        }
                })
            };
            let mut out: Vec<Crossing> = Vec::new();
            let (rs, removable) = crossing_roots(&n, &norms);
            // the signs at every root at once (one gcd per polynomial, not per root)
            let signs = |p: &Poly| -> Vec<Sign> {
                if p.is_zero() {
                    vec![Sign::Zero; rs.len()]
                } else {
                    AlgebraicReal::signs_at(&rs, p)
                }
            };
            let (sa, sd, ss) = (signs(&ha), signs(&hd), signs(sz));
            for (k, r) in rs.into_iter().enumerate() {
                let mut sh = sheets(sa[k], sd[k], ss[k]);
                if removable[k] {
                    let on_s = ss[k] == Sign::Zero;
                    sh.retain(|&sheet| {
                        !vanishes(
                            sheet,
                            &|i| r.sign_of(&av[i]),
                            &|i| if on_s { Sign::Zero } else { r.sign_of(&dv[i]) },
                            &|_| true,
                        )
                    });
                }
                out.push(Crossing {
                    value: ParamValue::Finite(r),
                    sheets: sh,
                });
            }
            if n.degree().unwrap_or(0) < 2 * degree {
                let top = |p: &Poly, k: usize| Sign::of(&p.coeff(k));
                let mut sh = sheets(top(&ha, *degree), top(&hd, degree - 2), top(sz, 4));
                sh.retain(|&sheet| {
                    !vanishes(
                        sheet,
                        &|i| top(&av[i], *degree),
                        &|i| {
                            if top(sz, 4) == Sign::Zero {
                                Sign::Zero
                            } else {
                                top(&dv[i], degree - 2)
                            }
                        },
                        &|i| top(&norms[i], 2 * degree) == Sign::Zero,
                    )
                });
                out.push(Crossing {
                    value: ParamValue::Infinity,
                    sheets: sh,
                });
            }
            Some(out)
        }
    }
}

/// The sheets of Levin's form through a root of `h(a)² − h(d)²·s` with the signs `sa`, `sd`,
/// `ss` of `h(a)`, `h(d)`, `s` there: `h(a) + σ·h(d)·√s = 0` for `σ = −sign(h(a)·h(d))`; both
/// where `√s = 0` or `h(d) = 0`, none where `s < 0`.
fn crossing_sheets(sa: Sign, sd: Sign, ss: Sign) -> Vec<Sheet> {
    match (ss, sd) {
        (Sign::Negative, _) => Vec::new(),
        (Sign::Zero, _) | (_, Sign::Zero) => vec![Sheet::Plus, Sheet::Minus],
        _ if sa == sd => vec![Sheet::Minus],
        _ => vec![Sheet::Plus],
    }
}

/// The real roots of `n` (the crossings' polynomial of [`exact_crossings_of`]), each with
/// whether it may be a removable zero (a root of every nonzero norm `aᵢ² − dᵢ²·s`).
///
/// First by floats: `n` square-free with its roots certified, and at each root some norm
/// whose sign the certified interval decides nonzero — the generic crossing, with no gcd and
/// no square-free factorization. Otherwise exactly: the roots of the gcd of `n`'s
/// square-free part with the norms (none, the common case) isolated apart from the rest.
fn crossing_roots(n: &Poly, norms: &[Poly]) -> (Vec<AlgebraicReal>, Vec<bool>) {
    // a removable zero needs every norm to vanish: the roots of their gcd with n (none,
    // the common case), isolated apart from the rest of n (whose rational roots are
    // then rare: the removable zeros are the usual ones)
    let nz = n.squarefree_part();
    let common = norms.iter().try_fold(nz.clone(), |g, m| {
        let g = if m.is_zero() { g } else { g.gcd(m) };
        if g.is_constant() {
            None
        } else {
            Some(g)
        }
    });
    let isolate = |p: &Poly| {
        AlgebraicReal::certified_real_roots_of(p).unwrap_or_else(|| AlgebraicReal::real_roots_of(p))
    };
    let mut rs: Vec<(AlgebraicReal, bool)> = Vec::new();
    match &common {
        Some(g) => {
            let rest = nz.div_exact(g).expect("a divisor of n");
            rs.extend(isolate(&rest).into_iter().map(|r| (r, false)));
            rs.extend(isolate(g).into_iter().map(|r| (r, true)));
            rs.sort_by(|x, y| x.0.cmp(&y.0));
        }
        None => rs.extend(isolate(&nz).into_iter().map(|r| (r, false))),
    }
    rs.into_iter().unzip()
}

/// The integer polynomials `L·vᵢ` for the least common denominator `L > 0` of every
/// coefficient, with `L`.
fn integer_vector(v: &[Poly<RBig>]) -> (Vec<Poly>, IBig) {
    let mut l = IBig::ONE;
    for c in v.iter().flat_map(|p| p.coeffs()) {
        let d = IBig::from(c.denominator().clone());
        if !d.is_one() {
            l = &l / qsic_algebra::int_gcd(&l, &d) * d;
        }
    }
    let ints = v
        .iter()
        .map(|p| p.map(|c| c.numerator() * &(&l / IBig::from(c.denominator().clone()))))
        .collect();
    (ints, l)
}

/// [`integer_vector`] of the row `h`.
fn integer_row(h: &[RBig; 4]) -> ([IBig; 4], IBig) {
    let (v, l) = integer_vector(&h.clone().map(|c| Poly::new(vec![c])));
    (std::array::from_fn(|i| v[i].coeff(0)), l)
}

/// The state of the walk along one arc: the last point and the segments still to check.
struct Walk {
    prev: Sample,
    /// `h` at `prev`.
    h_prev: f64,
    stack: Vec<(Sample, u32)>,
    /// Crossings of the plane at infinity located along the walk (not known exactly).
    unknown: bool,
    /// The polyline's last point is `−prev.x` (the polyline is oriented as it is walked).
    flip: bool,
}

/// A polyline being built: its unit vectors, and the marks of those that are crossings of the
/// plane at infinity or singular points (the few points that carry one).
#[derive(Default)]
struct Line {
    x: Vec<[f64; 4]>,
    /// `h` of each point as stored (oriented), for the affine view.
    h: Vec<f64>,
    /// The chart's plane at infinity as floats.
    chart: ChartForm,
    /// `(index, at infinity, singular)`, ascending, at most one per index, never both false.
    marks: Vec<(usize, bool, bool)>,
    /// The work list of [`Walk`], kept between the arcs (empty).
    stack: Vec<(Sample, u32)>,
}

impl Line {
    fn len(&self) -> usize {
        self.x.len()
    }

    /// Appends the point of `s` with its marks.
    #[inline(always)]
    fn push(&mut self, s: &Sample) {
        if s.at_infinity || s.singular {
            self.marks.push((self.x.len(), s.at_infinity, s.singular));
        }
        self.x.push(s.x);
        self.h.push(self.chart.value(&s.x));
    }

    /// Joins the marks `(at_infinity, singular)` to those of point `k`.
    fn mark(&mut self, k: usize, at_infinity: bool, singular: bool) {
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
    fn pop(&mut self) -> (bool, bool) {
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
    fn reverse_from(&mut self, start: usize, negate: bool) {
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
fn grid_before_event(k: usize, n: usize, (t0, step): (f64, f64), next: f64) -> usize {
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
fn push_oriented(line: &mut Line, mut s: Sample) -> bool {
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
fn run_of(
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
fn run_of_reference(
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
type OtherSheet = ((u64, u64, usize), Sheet, Vec<[f64; 4]>);

/// Samples the pieces of one component.
/// The order in which the affine view visits a polyline: from its first mark on a closed one
/// (`first`; `count` steps, the first point visited again at the end), else from point 0;
/// `special`, ascending, the steps where a mark is met or the loop wraps round to point 0 —
/// between them runs of plain points.
struct AffineSteps {
    first: usize,
    count: usize,
    special: Vec<usize>,
}

impl AffineSteps {
    fn new(line: &Line, closed: bool) -> AffineSteps {
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

struct Sampler<'a> {
    eval: Evaluator<'a>,
    crossings: Crossings,
    /// The exact parameters of the curve's real singular points on this component, and
    /// whether each point is at infinity.
    singular: Vec<(ParamValue, bool)>,
    chart: &'a Chart,
    tolerance: Option<f64>,
    approx: &'a Approximations,
    /// The floats of the arc ends met ([`Sampler::end_value`]), by the end's address in
    /// the curve first (the arcs of an oval share their ends), else by value.
    ends: RefCell<Vec<(&'a AlgebraicReal, f64)>>,
    /// The grid of the other sheet made with the last one of Levin's form: `(t₀, step, n)`
    /// as bits, the sheet and its points ([`Evaluator::grid_both`]).
    other_sheet: RefCell<Option<OtherSheet>>,
}

impl<'a> Sampler<'a> {
    /// The grid of `sheet` on `θₖ = t₀ + k·step` ([`Evaluator::grid`]): on Levin's form both
    /// sheets at once, the other kept for an arc over the same range.
    fn grid(&self, t0: f64, step: f64, n: usize, sheet: Sheet, out: &mut Vec<[f64; 4]>) {
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
    fn end_value(&self, r: &'a AlgebraicReal) -> f64 {
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
    fn end_value_uncached(&self, r: &AlgebraicReal) -> f64 {
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
    fn at(&self, theta: f64, lo: f64, hi: f64, sheet: Sheet) -> Result<Sample, Error> {
        let (s, c) = sin_cos(theta);
        self.at_u(theta, (s, c), lo, hi, sheet)
    }

    /// [`Sampler::at`] with `u ≈ (sin θ, cos θ)` given (up to a positive factor).
    fn at_u(
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
        Err(Error::Algebra(format!(
            "no well-conditioned point near θ = {theta} in ({lo}, {hi})"
        )))
    }

    /// The point at an exact end of an arc (`u` on ℙ¹), nudged inwards if needed.
    fn at_end(&self, u: (f64, f64), theta: f64, other: f64, sheet: Sheet) -> Result<Sample, Error> {
        if let Some(x) = self.eval.eval_unit(u, sheet) {
            return Ok(Sample::new(theta, x));
        }
        for f in [1e-9, 1e-6, 1e-3] {
            let t = theta + f * (other - theta);
            if let Some(x) = self.eval.eval_unit(sin_cos(t), sheet) {
                return Ok(Sample::new(t, x));
            }
        }
        Err(Error::Algebra(format!(
            "no well-conditioned point near the end θ = {theta}"
        )))
    }

    /// Whether the segment `p, q` needs a point between them; computes it if so.
    fn split(&self, p: &Sample, q: &Sample, sheet: Sheet) -> Result<Option<Sample>, Error> {
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
        let m = self.at(0.5 * (p.theta + q.theta), lo, hi, sheet)?;
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
    fn events(
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
    fn arc_into(
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
    fn fast_run(
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
    fn walk_to(
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
    fn walk_split(
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
                Some(m) if depth < MAX_DEPTH => {
                    budget.take(1)?;
                    walk.stack.push((q, depth + 1));
                    walk.stack.push((m, depth + 1));
                }
                Some(_) => {
                    return Err(Error::Algebra(format!(
                        "sampling did not converge near θ = {}",
                        p.theta
                    )))
                }
                None => self.accept(walk, q, dot(&p.x, &q.x), sheet, line)?,
            }
        }
        Ok(())
    }

    /// Appends `q` after `walk.prev` (`d` their dot product), with the crossing between
    /// them where the crossings are not known exactly.
    #[inline(always)]
    fn accept(
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
    fn piece(
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
            let affine = self.affine(&line, closed);
            // the stored `h` is the chart's value at every point, and the view is the one
            // built point by point from it
            debug_assert!(line.h.len() == line.x.len());
            debug_assert!((line.h.iter().zip(&line.x)).all(|(h, x)| *h == dot(&self.chart.h, x)));
            #[cfg(debug_assertions)]
            assert_eq!(affine, self.affine_two_pass(&line, closed));
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
    fn float_crossing(
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

    /// Splits the oriented polyline at its crossings with the plane at infinity (the branches
    /// end before and start after them) and at its real singular points (both branches keep
    /// the point).
    fn affine(&self, line: &Line, closed: bool) -> AffinePiece {
        let (x, marks) = (&line.x, &line.marks);
        let n = x.len();
        let points_at_infinity: Vec<[f64; 4]> =
            marks.iter().filter(|m| m.1).map(|m| x[m.0]).collect();
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
                let keep = self.chart.keep;
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
                    if let Some(a) = self.chart.affine_with(p, h) {
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
            if let Some(a) = self.chart.affine_with(p, h) {
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
    fn affine_two_pass(&self, line: &Line, closed: bool) -> AffinePiece {
        let (x, marks) = (&line.x, &line.marks);
        let n = x.len();
        let points_at_infinity: Vec<[f64; 4]> =
            marks.iter().filter(|m| m.1).map(|m| x[m.0]).collect();
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
                    let h = self.chart.value(p);
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
                    if let Some(a) = self.chart.affine_with(p, h) {
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
            let h = self.chart.value(p);
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
            if let Some(a) = self.chart.affine_with(p, h) {
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

/// Distance from `c` to the segment `ab`.
fn chord_deviation(a: &[f64; 3], b: &[f64; 3], c: &[f64; 3]) -> f64 {
    let ab: [f64; 3] = std::array::from_fn(|i| b[i] - a[i]);
    let ac: [f64; 3] = std::array::from_fn(|i| c[i] - a[i]);
    let len2: f64 = ab.iter().map(|v| v * v).sum();
    let t = if len2 > 0.0 {
        (ab.iter().zip(&ac).map(|(x, y)| x * y).sum::<f64>() / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (0..3)
        .map(|i| (ac[i] - t * ab[i]).powi(2))
        .sum::<f64>()
        .sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::param::curve::sqrt_field;
    use crate::Quadric;
    use qsic_algebra::testing::SplitMix;

    /// The curve of a random pair of symmetric integer matrices (entries in [−10, 10]),
    /// `None` when a matrix is zero or the curve is not parameterized.
    fn random_curve(rng: &mut SplitMix) -> Option<Curve> {
        let mut m = [[[0i64; 4]; 4]; 2];
        for q in &mut m {
            for i in 0..4 {
                for j in i..4 {
                    let c = rng.int(-10, 10);
                    q[i][j] = if i == j { 2 * c } else { c };
                    q[j][i] = q[i][j];
                }
            }
        }
        let (a, b) = (
            Quadric::from_integers(m[0]).ok()?,
            Quadric::from_integers(m[1]).ok()?,
        );
        crate::param::parameterize(&a, &b).ok()
    }

    /// The crossings of Levin's form over ℚ as the per-root route over the rationals found
    /// them (each sign by `sign_of`, the removable-zero test at every root): the same
    /// parameters and sheets, on the rational Levin parameterizations of random pairs
    /// (those with removable zeros among them) and four charts.
    #[test]
    fn exact_crossings_equal_the_per_root_route() {
        /// The crossings, and how many roots of `n` are removable zeros (every norm zero).
        fn reference(exact: &ExactParam, h: &[RBig; 4]) -> (Vec<(ParamValue, Vec<Sheet>)>, usize) {
            let ExactParam::Levin { a, d, s, degree } = exact else {
                unreachable!("a Levin form")
            };
            let sign_at = |p: &Poly<RBig>, r: &AlgebraicReal| {
                if p.is_zero() {
                    Sign::Zero
                } else {
                    r.sign_of(&Poly::from_rational(p).0)
                }
            };
            let top = |p: &Poly<RBig>, k: usize| Sign::of(p.coeff(k).numerator());
            let (ha, hd) = (chart_form(h, a), chart_form(h, d));
            let n = &(&ha * &ha) - &(&(&hd * &hd) * s);
            let norms: Vec<Poly<RBig>> = (0..4)
                .map(|i| &(&a[i] * &a[i]) - &(&(&d[i] * &d[i]) * s))
                .collect();
            let sheets = crossing_sheets;
            let keep = |sheet: Sheet,
                        sa: &dyn Fn(usize) -> Sign,
                        sd: &dyn Fn(usize) -> Sign,
                        z: &dyn Fn(usize) -> bool| {
                !(0..4).all(|i| {
                    z(i) && match sheet {
                        Sheet::Plus => sa(i) == -sd(i),
                        _ => sa(i) == sd(i),
                    }
                })
            };
            let roots = AlgebraicReal::real_roots_of(&Poly::from_rational(&n).0.squarefree_part());
            let (mut out, mut removable) = (Vec::new(), 0);
            for r in roots {
                removable += usize::from(norms.iter().all(|m| sign_at(m, &r) == Sign::Zero));
                let on_s = sign_at(s, &r) == Sign::Zero;
                let mut sh = sheets(sign_at(&ha, &r), sign_at(&hd, &r), sign_at(s, &r));
                sh.retain(|&sheet| {
                    keep(
                        sheet,
                        &|i| sign_at(&a[i], &r),
                        &|i| if on_s { Sign::Zero } else { sign_at(&d[i], &r) },
                        &|i| sign_at(&norms[i], &r) == Sign::Zero,
                    )
                });
                out.push((ParamValue::Finite(r), sh));
            }
            if n.degree().unwrap_or(0) < 2 * degree {
                let on_s = top(s, 4) == Sign::Zero;
                let mut sh = sheets(top(&ha, *degree), top(&hd, degree - 2), top(s, 4));
                sh.retain(|&sheet| {
                    keep(
                        sheet,
                        &|i| top(&a[i], *degree),
                        &|i| {
                            if on_s {
                                Sign::Zero
                            } else {
                                top(&d[i], degree - 2)
                            }
                        },
                        &|i| top(&norms[i], 2 * degree) == Sign::Zero,
                    )
                });
                out.push((ParamValue::Infinity, sh));
            }
            (out, removable)
        }
        let charts: [[i64; 4]; 4] = [[0, 0, 0, 1], [1, 0, 0, 0], [1, -2, 3, 1], [0, 1, 1, -5]];
        let mut rng = SplitMix(5);
        let (mut params, mut tried, mut removable) = (0, 0, 0);
        while params < 12 && tried < 6000 {
            tried += 1;
            let Some(curve) = random_curve(&mut rng) else {
                continue;
            };
            for c in &curve.components {
                let Some(param) = &c.param else { continue };
                let exact = ExactParam::new(param);
                if !matches!(exact, ExactParam::Levin { .. }) {
                    continue;
                }
                params += 1;
                for chart in &charts {
                    let h = chart.map(RBig::from);
                    let got = exact_crossings_of(&exact, &h).expect("a Levin form over ℚ");
                    let (want, r) = reference(&exact, &h);
                    removable += r;
                    assert_eq!(got.len(), want.len(), "{chart:?}");
                    for (g, (value, sheets)) in got.iter().zip(&want) {
                        let same = match (&g.value, value) {
                            (ParamValue::Finite(x), ParamValue::Finite(y)) => x == y,
                            (ParamValue::Infinity, ParamValue::Infinity) => true,
                            _ => false,
                        };
                        assert!(same, "{chart:?}");
                        assert_eq!(g.sheets, *sheets, "{chart:?}");
                    }
                }
            }
        }
        assert!(
            params >= 12,
            "{params} rational Levin forms in {tried} pairs"
        );
        assert!(removable >= 4, "{removable} removable zeros");
    }

    /// Levin parameterizations of random generic pairs (coefficients in ℚ(√δ)).
    fn levin_params(seed: u64, count: usize) -> Vec<ComponentParam> {
        let mut rng = SplitMix(seed);
        let mut out = Vec::new();
        while out.len() < count {
            let Some(curve) = random_curve(&mut rng) else {
                continue;
            };
            for c in curve.components {
                if let Some(p @ ComponentParam::Levin { .. }) = c.param {
                    out.push(p);
                }
            }
        }
        out
    }

    /// The grid of both sheets at once ([`Evaluator::grid_both`]) against [`Evaluator::grid`]
    /// on each sheet and against single evaluations at `(sin θ, cos θ)`, over ranges all
    /// round ℙ¹.
    #[test]
    fn both_sheet_grid_matches_single_evaluations() {
        let mut checked = 0;
        for param in levin_params(0x5eed, 4) {
            let eval = Evaluator::new(&param).unwrap();
            for (t0, t1) in [(-FRAC_PI_2, FRAC_PI_2), (-0.3, 1.2), (1.0, 1.0 + PI)] {
                let n = 200;
                let step = (t1 - t0) / n as f64;
                let (mut plus, mut minus, mut one) = (Vec::new(), Vec::new(), Vec::new());
                eval.grid_both(t0, step, n, &mut plus, &mut minus);
                assert_eq!((plus.len(), minus.len()), (n - 1, n - 1));
                for (sheet, got) in [(Sheet::Plus, &plus), (Sheet::Minus, &minus)] {
                    eval.grid(t0, step, n, sheet, &mut one);
                    assert_eq!(&one, got, "the same operations on one sheet");
                    for (k, x) in got.iter().enumerate() {
                        let u = (t0 + step * (k + 1) as f64).sin_cos();
                        match eval.eval_unit(u, sheet) {
                            Some(y) if !x[0].is_nan() => {
                                assert!(dot(x, &y) > 1.0 - 1e-12, "{x:?} {y:?}");
                                checked += 1;
                            }
                            _ => {}
                        }
                    }
                }
            }
        }
        assert!(checked > 4000, "{checked}");
    }

    /// The unrolled rounding bound of the two-sheet grid ([`Evaluator::bound_of`]) is the
    /// generic one of [`Evaluator::certify`] bit for bit, on both Horner orders.
    #[test]
    fn unrolled_bound_matches_generic_bound() {
        let mut rng = SplitMix(0xb0d);
        let mut checked = 0;
        for param in levin_params(0xb0e, 6) {
            let eval = Evaluator::new(&param).unwrap();
            let n = eval.big_d + 1;
            for _ in 0..200 {
                let t = rng.int(-1000, 1000) as f64 / 1000.0;
                let root = rng.int(0, 1 << 20) as f64 / 1024.0;
                for rev in [false, true] {
                    let bx = horner_lanes_abs(&eval.x()[..n], t, rev);
                    let bd = horner_lanes_abs(&eval.d()[..n - 2], t, rev);
                    let want = (0..4).map(|i| bx[i] + bd[i] * root).fold(0.0, f64::max);
                    let got = match eval.big_d {
                        2 => eval.bound_of::<3, 1>(t, rev, root),
                        3 => eval.bound_of::<4, 2>(t, rev, root),
                        4 => eval.bound_of::<5, 3>(t, rev, root),
                        _ => continue,
                    };
                    assert_eq!(got.to_bits(), want.to_bits(), "t = {t}, rev = {rev}");
                    checked += 1;
                }
            }
        }
        assert!(checked >= 2000, "{checked}");
    }

    /// The certificate made once per evaluator ([`Evaluator::sure`]) implies the bound at
    /// `|t|` ([`Evaluator::bound_of`]) that it stands for: every computed `√s` on `[−1, 1]`
    /// is within `sure_root`, and a norm it passes passes the per-point test; beyond the range
    /// of the shortcut it certifies nothing.
    #[test]
    fn certificate_made_once_implies_the_pointwise_bound() {
        let mut rng = SplitMix(0x5a4e);
        let (mut sure, mut total) = (0, 0);
        for param in levin_params(0x5a4f, 8) {
            let eval = Evaluator::new(&param).unwrap();
            for _ in 0..400 {
                let t = rng.int(-1 << 20, 1 << 20) as f64 / (1 << 20) as f64;
                for rev in [false, true] {
                    let (x, w, root, bound) = match eval.big_d {
                        2 => {
                            let (x, w, r) = eval.parts::<3, 1>(t, rev);
                            (x, w, r, eval.bound_of::<3, 1>(t, rev, r))
                        }
                        3 => {
                            let (x, w, r) = eval.parts::<4, 2>(t, rev);
                            (x, w, r, eval.bound_of::<4, 2>(t, rev, r))
                        }
                        4 => {
                            let (x, w, r) = eval.parts::<5, 3>(t, rev);
                            (x, w, r, eval.bound_of::<5, 3>(t, rev, r))
                        }
                        _ => continue,
                    };
                    assert!(root <= eval.sure_root, "t = {t}");
                    for sign in [1.0, -1.0] {
                        let p: Lanes = std::array::from_fn(|i| x[i] + sign * root * w[i]);
                        let norm = dot(&p, &p).sqrt();
                        total += 1;
                        if eval.sure(root, norm) {
                            sure += 1;
                            assert!(eval.gamma * bound <= 1e-10 * norm, "t = {t}");
                        }
                    }
                }
            }
        }
        assert!(sure > total / 2 && sure < total + 1, "{sure} of {total}");
        let s = [1.0, 0.0, 0.0, 0.0, 1.0];
        assert_eq!(
            sure_bounds(1e-14, 1e301, 1.0, &s),
            (f64::INFINITY, f64::INFINITY)
        );
        assert_eq!(
            sure_bounds(1e-14, 0.0, 0.0, &[0.0; 5]),
            (f64::INFINITY, f64::INFINITY)
        );
        assert!(sure_bounds(1e-14, 1.0, 1.0, &s).1.is_finite());
        assert_eq!(NARROW, (2f64.powi(-800), 2f64.powi(FLOAT_SCALE as i32)));
    }

    /// A parameterization with coefficients beyond `2⁹⁰⁰` (not [`NARROW`], and beyond
    /// [`in_float_range`]'s limit) is scaled into the floats' range first: the same points as
    /// the parameterization it is a multiple of.
    #[test]
    fn wide_parameterizations_are_scaled_before_sampling() {
        let mut rng = SplitMix(0x1de);
        let mut checked = 0;
        while checked < 3 {
            let mut m = [[[0i64; 4]; 4]; 2];
            for q in &mut m {
                for i in 0..4 {
                    for j in i..4 {
                        q[i][j] = rng.int(-10, 10);
                        q[j][i] = q[i][j];
                    }
                }
            }
            let (Ok(a), Ok(b)) = (Quadric::from_integers(m[0]), Quadric::from_integers(m[1]))
            else {
                continue;
            };
            let Ok(curve) = crate::param::parameterize(&a, &b) else {
                continue;
            };
            if curve.pieces.is_empty()
                || !(curve.components.iter())
                    .any(|c| matches!(c.param, Some(ComponentParam::Levin { .. })))
            {
                continue;
            }
            let k = crate::param::curve::rational(RBig::from(IBig::ONE << 950));
            let mut wide = curve.clone();
            for c in &mut wide.components {
                if let Some(ComponentParam::Levin { a, d, .. }) = &mut c.param {
                    for v in a.iter_mut().chain(d.iter_mut()) {
                        *v = v.map(|c| c.mul(&k));
                    }
                    let eval = Evaluator::new(c.param.as_ref().unwrap()).unwrap();
                    assert!(!eval.narrow);
                    assert!(in_float_range(c.param.as_ref().unwrap()).is_some());
                }
            }
            let options = SampleOptions::default();
            let (x, y) = (
                sample(&curve, &options).unwrap(),
                sample(&wide, &options).unwrap(),
            );
            assert_eq!(x.pieces.len(), y.pieces.len());
            for (p, q) in x.pieces.iter().zip(&y.pieces) {
                assert_eq!(p.points.len(), q.points.len());
                for (u, v) in p.points.iter().zip(&q.points) {
                    assert!(dot(u, v).abs() > 1.0 - 1e-12, "{u:?} {v:?}");
                }
            }
            checked += 1;
        }
    }

    /// The first grid index at or after an event, from the estimate, is the one a scan of
    /// the test finds: events on grid points, just off them, outside the range, none.
    #[test]
    fn grid_index_of_event_matches_scan() {
        let mut rng = SplitMix(0xe7);
        for _ in 0..2000 {
            let n = rng.int(2, 600) as usize;
            let t0 = rng.int(-4000, 4000) as f64 / 1000.0;
            let step = rng.int(1, 3000) as f64 / (1000.0 * n as f64);
            let k = rng.int(1, n as i64) as usize;
            let j = rng.int(-3, n as i64 + 3) as f64;
            let next = match rng.int(0, 4) {
                0 => t0 + step * j,
                1 => t0 + step * j - 1e-12,
                2 => t0 + step * j + 2e-12 * (rng.int(-2, 2) as f64),
                3 => t0 + step * (j + 0.5),
                _ => f64::INFINITY,
            };
            let scan = (k..n)
                .find(|&j| next <= t0 + step * (j as f64) + 1e-12)
                .unwrap_or(n);
            assert_eq!(
                grid_before_event(k, n, (t0, step), next),
                scan,
                "k = {k}, n = {n}, t0 = {t0}, step = {step}, next = {next}"
            );
        }
    }

    /// Marks follow their points through pushes, joins, pops and the reversal of a tail.
    #[test]
    fn line_marks_follow_their_points() {
        let mut line = Line::default();
        for k in 0..10 {
            let mut s = Sample::new(k as f64, [k as f64, 1.0, 0.0, 0.0]);
            s.at_infinity = k == 2 || k == 7;
            s.singular = k == 8;
            line.push(&s);
        }
        line.mark(4, false, true);
        line.mark(2, false, true);
        assert_eq!(
            line.marks,
            vec![
                (2, true, true),
                (4, false, true),
                (7, true, false),
                (8, false, true)
            ]
        );
        // reversed and negated in one pass: reversed, then negated
        for len in [3, 4, 5, 6, 7] {
            let mut one = Line {
                chart: ChartForm::new([1.0, 0.0, 0.5, 1.0]),
                ..Line::default()
            };
            for k in 0..len {
                one.push(&Sample::new(k as f64, [k as f64, 1.0, -2.0, 0.5]));
            }
            let mut two = Line {
                x: one.x.clone(),
                h: one.h.clone(),
                ..Line::default()
            };
            one.reverse_from(1, true);
            two.reverse_from(1, false);
            let neg: Vec<[f64; 4]> = two.x.iter().map(|v| v.map(|c| -c)).collect();
            assert_eq!((&one.x[..1], &one.x[1..]), (&two.x[..1], &neg[1..]));
            let neg_h: Vec<f64> = two.h.iter().map(|v| -v).collect();
            assert_eq!((&one.h[..1], &one.h[1..]), (&two.h[..1], &neg_h[1..]));
        }
        line.reverse_from(3, false);
        // points 3..10 reversed: index i ↦ 12 − i
        assert_eq!(line.x[3][0], 9.0);
        assert_eq!(
            line.marks,
            vec![
                (2, true, true),
                (4, false, true),
                (5, true, false),
                (8, false, true)
            ]
        );
        for &(k, _, _) in &line.marks[1..] {
            assert!([4.0, 7.0, 8.0].contains(&line.x[k][0]));
        }
        assert_eq!(line.pop(), (false, false));
        // point 8 (the old point 4, singular) joins a crossing
        line.mark(line.len() - 1, true, false);
        assert_eq!(line.pop(), (true, true));
        assert_eq!(line.len(), 8);
    }

    /// `x − y√2` for the solutions of Pell's equation `x² − 2y² = 1`: the terms cancel to
    /// `1/(x + y√2)`, by up to ~200 bits; the float must keep its full precision.
    #[test]
    fn conversion_keeps_precision_through_cancellation() {
        let k = sqrt_field(&IBig::from(2));
        let (mut x, mut y) = (IBig::from(3), IBig::from(2));
        let mut conv = Converter::default();
        for _ in 0..40 {
            for den in [1, 3, 4] {
                let c = k.element(&Poly::new(vec![
                    RBig::from_parts_signed(x.clone(), den.into()),
                    RBig::from_parts_signed(-y.clone(), den.into()),
                ]));
                let v = conv.convert(&c).unwrap();
                let conjugate = x.to_f64().value() + y.to_f64().value() * std::f64::consts::SQRT_2;
                let product = v.value * conjugate * den as f64;
                assert!((product - 1.0).abs() < 1e-14, "x = {x}: {product}");
                let dd = v.dd.expect("ℚ(√2) has a double-double");
                assert!(((dd.0 + dd.1) * conjugate * den as f64 - 1.0).abs() < 1e-14);
            }
            // the next solution: (x, y) → (3x + 4y, 2x + 3y)
            (x, y) = (&x * 3 + &y * 4, &x * 2 + &y * 3);
        }
        assert_eq!(conv.roots.len(), 1, "√2 made once");
    }

    #[test]
    fn integers_split_exactly_into_double_doubles() {
        let mut rng = SplitMix(11);
        for bits in [10, 52, 53, 54, 64, 100, 106, 150, 400] {
            for _ in 0..20 {
                let v = (IBig::from(rng.next_u64()) << bits) >> 64;
                let v = if rng.next_u64() % 2 == 0 { -v } else { v };
                let d = int_dd(&v);
                let rest = &v - integral_f64_to_ibig(d.0);
                // lo is the rest rounded: exact below 2¹⁰⁶
                let err = if d.1 == 0.0 {
                    rest.clone()
                } else {
                    &rest - integral_f64_to_ibig(d.1.trunc())
                };
                let tolerance = IBig::ONE << bits.saturating_sub(100);
                assert!(&err * &err <= &tolerance * &tolerance, "{v}: {d:?}");
            }
        }
    }

    /// [`sin_cos`] is the library's within `2⁻⁵¹` with the same signs, on random angles of
    /// the arcs' range, at the multiples of `π/4` and next to them, and beyond its range
    /// (the library's itself).
    #[test]
    fn fast_sine_and_cosine_match_the_library() {
        let mut rng = SplitMix(0x51c0);
        let mut thetas: Vec<f64> = (0..20_000)
            .map(|_| (rng.next_u64() as f64 / u64::MAX as f64 - 0.3) * 12.0)
            .collect();
        for k in -12..=12 {
            let c = k as f64 * std::f64::consts::FRAC_PI_4;
            thetas.extend([c, c + 1e-9, c - 1e-9, c + 1e-15, c - 1e-15]);
        }
        thetas.extend([1e-300, -1e-300, 0.0, -0.0, 1e-8]);
        for theta in thetas {
            let (s, c) = sin_cos(theta);
            let (ws, wc) = theta.sin_cos();
            assert!((s - ws).abs() <= 2f64.powi(-51), "{theta}: {s} {ws}");
            assert!((c - wc).abs() <= 2f64.powi(-51), "{theta}: {c} {wc}");
            for (v, w) in [(s, ws), (c, wc)] {
                assert!(w.abs() < 1e-15 || (v > 0.0) == (w > 0.0), "{theta}");
            }
        }
        for theta in [1e6, -3e7, f64::INFINITY] {
            let (got, want) = (sin_cos(theta), theta.sin_cos());
            assert_eq!(got.0.to_bits(), want.0.to_bits());
            assert_eq!(got.1.to_bits(), want.1.to_bits());
        }
    }

    /// [`magnitude_dd`] (signed conversions where a word allows) is the general split (top
    /// 53 bits plus the rest through two unsigned words) bit for bit, at every bit length
    /// up to 127, the rest at or beyond `2⁶³` included (the fallback branch).
    #[test]
    fn magnitude_split_matches_general_route() {
        let reference = |m: u128, neg: bool| -> Dd {
            let bits = 128 - m.leading_zeros();
            if bits <= 53 {
                let x = (m as u64) as f64;
                return Dd(if neg { -x } else { x }, 0.0);
            }
            let e = bits - 53;
            let top = (m >> e) as u64;
            let scale = f64::from_bits(((1023 + e) as u64) << 52);
            let rest = m - ((top as u128) << e);
            let rest_f =
                ((rest >> 64) as u64) as f64 * 18446744073709551616.0 + (rest as u64) as f64;
            let d = Dd::two_sum(top as f64 * scale, rest_f);
            if neg {
                d.neg()
            } else {
                d
            }
        };
        let mut rng = SplitMix(0xd0d0);
        let mut wide_rest = 0;
        for bits in 0..=127u32 {
            for _ in 0..20 {
                let m = ((u128::from(rng.next_u64()) << 64) | u128::from(rng.next_u64()))
                    >> (128 - bits.max(1));
                let m = if bits == 0 { 0 } else { m | (1 << (bits - 1)) };
                let neg = rng.int(0, 1) == 1;
                let (got, want) = (magnitude_dd(m, neg), reference(m, neg));
                assert_eq!((got.0, got.1), (want.0, want.1), "{m}");
                let v = if neg { -IBig::from(m) } else { IBig::from(m) };
                let via = int_dd(&v);
                assert_eq!((via.0, via.1), (want.0, want.1), "{m}");
                wide_rest += usize::from(bits > 53 && m & ((1 << (bits - 53)) - 1) >= 1 << 63);
            }
        }
        assert!(wide_rest > 100, "{wide_rest}");
    }

    /// Dekker's product ([`product_error`]) is the fused multiply-add's rounding error, and
    /// the lane-wise double-double evaluation ([`Evaluator::values_dd`]) is the one
    /// coordinate at a time by `mul_add` ([`Evaluator::values_dd_fused`]), value for value, on
    /// random parameters all round ℙ¹ and both sheets; coefficients beyond Veltkamp's range
    /// give NaN there, and [`Evaluator::eval_dd`] falls back to the fused products.
    #[test]
    fn double_double_lanes_match_fused_products() {
        let mut rng = SplitMix(0xdd4);
        for _ in 0..20_000 {
            let e = rng.int(-900, 900) as i32;
            let a = (rng.next_u64() as f64 / u64::MAX as f64 - 0.5) * 2f64.powi(e);
            let b = rng.next_u64() as f64 / u64::MAX as f64 * 2.0 - 1.0;
            let p = a * b;
            assert_eq!(product_error(a, split(b), p), a.mul_add(b, -p), "{a} {b}");
        }
        let mut checked = 0;
        for param in levin_params(0xdd5, 6) {
            let eval = Evaluator::new(&param).unwrap();
            for _ in 0..200 {
                let theta = (rng.next_u64() as f64 / u64::MAX as f64 - 0.5) * PI;
                let (t, rev) = reduced_parameter(theta.sin_cos());
                for sheet in [Sheet::Plus, Sheet::Minus] {
                    let (got, want) = (
                        eval.values_dd(t, rev, sheet),
                        eval.values_dd_fused(t, rev, sheet),
                    );
                    assert_eq!(got, want, "t = {t}");
                    checked += 1;
                }
            }
            // `a` beyond 2⁹⁹⁶: the split overflows, the fused products do not
            // (the leading coefficients, at a tiny `t`: the values stay in range)
            let mut wide = eval.dd().clone();
            for (i, c) in wide.x[eval.big_d].iter_mut().enumerate() {
                *c = Dd((1.0 + i as f64 / 8.0) * 2f64.powi(1000), 0.0);
            }
            let wide = Evaluator {
                quick_dd: Some(Box::new(wide)),
                ..Evaluator::new(&param).unwrap()
            };
            let t = 2f64.powi(-400);
            assert!(wide
                .values_dd(t, false, Sheet::Plus)
                .iter()
                .any(|v| v.is_nan()));
            let fused = wide.values_dd_fused(t, false, Sheet::Plus);
            assert!(fused.iter().all(|v| v.is_finite()));
            assert_eq!(wide.eval_dd(t, false, Sheet::Plus, 0.0), Some(fused));
        }
        assert!(checked >= 2000, "{checked}");
    }

    /// [`Evaluator::eval_unit`] (unrolled Horner, unrolled bound where the majorant does not
    /// certify) is the generic route (any degree: [`Evaluator::values_any`], then
    /// [`Evaluator::certify`]) point for point, on rational and Levin parameterizations, with
    /// points certified by the bound at `|t|` only among them.
    #[test]
    fn unrolled_evaluation_matches_generic_route() {
        let mut rng = SplitMix(0xe7a1);
        let mut params = levin_params(0xe7a2, 6);
        let mut seed = SplitMix(0xe7a3);
        while params.len() < 12 {
            let Some(curve) = random_curve(&mut seed) else {
                continue;
            };
            params.extend(curve.components.into_iter().filter_map(|c| match c.param {
                Some(p @ ComponentParam::Rational { .. }) => Some(p),
                _ => None,
            }));
        }
        let (mut checked, mut by_bound, mut rational) = (0, 0, 0);
        for param in &params {
            let eval = Evaluator::new(param).unwrap();
            let sheets: &[Sheet] = if eval.levin {
                &[Sheet::Plus, Sheet::Minus]
            } else {
                rational += 1;
                &[Sheet::Only]
            };
            for k in 0..2000 {
                // uniform in θ, and clustered near t = 0 and t = ±1
                let theta = match k % 3 {
                    0 => (rng.next_u64() as f64 / u64::MAX as f64 - 0.5) * PI,
                    1 => (rng.next_u64() as f64 / u64::MAX as f64 - 0.5) * 1e-3,
                    _ => FRAC_PI_2 * (1.0 - 2e-3 * rng.next_u64() as f64 / u64::MAX as f64),
                };
                let u = theta.sin_cos();
                let (t, rev) = reduced_parameter(u);
                for &sheet in sheets {
                    let (x, root) = eval.values_any(t, rev, sheet);
                    let norm = dot(&x, &x).sqrt();
                    let cheap = eval.cheaply_certified(t, rev, root, norm);
                    let want = if cheap {
                        Some(x.map(|v| v / norm))
                    } else {
                        by_bound += 1;
                        eval.certify(t, rev, sheet, x, norm, root)
                    };
                    assert_eq!(eval.eval_unit(u, sheet), want, "θ = {theta}");
                    checked += 1;
                }
            }
        }
        assert!(
            rational > 0 && checked > 20_000 && by_bound > 0,
            "{rational} {checked} {by_bound}"
        );
    }

    /// The float evaluation (majorant certificate, unrolled Horner) against the double-double
    /// one from coefficients made by the refined route ([`to_dd`], not the [`Converter`]),
    /// on both sheets, at parameters all round ℙ¹.
    #[test]
    fn fast_evaluation_matches_double_double_from_refined_coefficients() {
        let mut rng = SplitMix(7);
        let (mut checked, mut unrolled) = (0, 0);
        for param in levin_params(0x1e_71, 6) {
            let eval = Evaluator::new(&param).unwrap();
            let ComponentParam::Levin { a, d, s, .. } = &param else {
                unreachable!()
            };
            let mut refined = Box::<DdCoeffs>::default();
            for i in 0..4 {
                for (k, c) in a[i].coeffs().iter().enumerate() {
                    refined.x[k][i] = to_dd(c);
                }
                for (k, c) in d[i].coeffs().iter().enumerate() {
                    refined.d[k][i] = to_dd(c);
                }
            }
            for (k, c) in s.coeffs().iter().enumerate() {
                refined.s[k] = to_dd(c);
            }
            let reference = Evaluator {
                quick_dd: Some(refined),
                ..Evaluator::new(&param).unwrap()
            };
            for _ in 0..200 {
                let theta = (rng.next_u64() as f64 / u64::MAX as f64 - 0.5) * PI;
                let u = theta.sin_cos();
                let (t, rev) = reduced_parameter(u);
                for sheet in [Sheet::Plus, Sheet::Minus] {
                    let Some(x) = eval.eval_unit(u, sheet) else {
                        continue;
                    };
                    let y = reference
                        .eval_dd(t, rev, sheet, 0.0)
                        .and_then(unit)
                        .expect("double-double evaluates where floats do");
                    // the unrolled Horner is the general one, operation for operation
                    if eval.big_d == 3 {
                        let fixed = eval.values::<4, 2>(t, rev, sheet);
                        assert_eq!(fixed, eval.values_any(t, rev, sheet));
                        unrolled += 1;
                    }
                    assert!(dot(&x, &y) > 1.0 - 1e-12, "{x:?} {y:?}");
                    checked += 1;
                }
            }
        }
        assert!(checked > 2000 && unrolled > 0, "{checked} {unrolled}");
    }

    /// Curves of random generic pairs with a real piece on a Levin component: the curve and
    /// the component's index.
    fn levin_curves(seed: u64, count: usize) -> Vec<(Curve, usize)> {
        let mut rng = SplitMix(seed);
        let mut out = Vec::new();
        while out.len() < count {
            let Some(curve) = random_curve(&mut rng) else {
                continue;
            };
            let levin = curve.pieces.iter().find_map(|p| match p {
                RealPiece::Curve { component, .. } => matches!(
                    curve.components[*component].param,
                    Some(ComponentParam::Levin { .. })
                )
                .then_some(*component),
                RealPiece::Point { .. } => None,
            });
            if let Some(k) = levin {
                out.push((curve, k));
            }
        }
        out
    }

    /// A sampler of `param` with no exact events (crossings located along the walk).
    fn test_sampler<'a>(
        param: &'a ComponentParam,
        chart: &'a Chart,
        approx: &'a Approximations,
    ) -> Sampler<'a> {
        Sampler {
            eval: Evaluator::new(param).unwrap(),
            crossings: Crossings::Unknown,
            singular: Vec::new(),
            chart,
            tolerance: None,
            approx,
            ends: RefCell::new(Vec::new()),
            other_sheet: RefCell::new(None),
        }
    }

    /// The arc ends kept by [`Sampler::end_value`] are the ends found afresh, bit for bit,
    /// and an end shared by two arcs (the two sheets of an oval) is found once.
    #[test]
    fn arc_ends_found_once_are_the_ends_found_afresh() {
        let (mut shared, mut checked) = (0, 0);
        let chart = SampleOptions::default().chart().unwrap();
        for (curve, k) in levin_curves(0xe4d5, 12) {
            let param = curve.components[k].param.as_ref().unwrap();
            let approx = Approximations::default();
            let sampler = test_sampler(param, &chart, &approx);
            let mut ends: Vec<&AlgebraicReal> = Vec::new();
            for piece in &curve.pieces {
                let RealPiece::Curve {
                    component, arcs, ..
                } = piece
                else {
                    continue;
                };
                if *component != k {
                    continue;
                }
                for arc in arcs {
                    let ParamRange::Between(lo, hi) = &arc.range else {
                        continue;
                    };
                    for r in [lo, hi].into_iter().filter_map(|v| match v {
                        ParamValue::Finite(r) => Some(r),
                        ParamValue::Infinity => None,
                    }) {
                        let kept = sampler.end_value(r);
                        let fresh = sampler.end_value_uncached(r);
                        assert_eq!(kept.to_bits(), fresh.to_bits(), "{r:?}");
                        // the end itself
                        let exact = r.to_f64();
                        assert!((kept - exact).abs() <= 1e-9 * (1.0 + exact.abs()), "{r:?}");
                        if ends.iter().any(|q| q.same_definition(r)) {
                            shared += 1;
                        } else {
                            ends.push(r);
                        }
                        checked += 1;
                    }
                }
            }
            assert_eq!(
                sampler.ends.borrow().len(),
                ends.len(),
                "one search per end"
            );
        }
        assert!(checked >= 24 && shared >= 12, "{checked} {shared}");
    }

    /// The affine view cut in runs of one sign of `h` ([`Sampler::affine`], four points a
    /// step) is the point-by-point reference on random polylines: runs of either sign,
    /// zeros of either sign, tiny values, marks at infinity and singular, open and closed.
    #[cfg(debug_assertions)]
    #[test]
    fn affine_view_in_runs_matches_point_by_point() {
        let mut rng = SplitMix(0xaff1);
        let param = &levin_params(0xaff2, 1)[0];
        let approx = Approximations::default();
        for chart in [
            SampleOptions::default(),
            SampleOptions {
                chart: [1, 0, -2, 1].map(RBig::from),
                ..SampleOptions::default()
            },
        ] {
            let chart = chart.chart().unwrap();
            let sampler = test_sampler(param, &chart, &approx);
            let mut cuts = 0;
            for _ in 0..400 {
                let len = rng.int(1, 40) as usize;
                let mut line = Line {
                    chart: chart.form,
                    ..Line::default()
                };
                let mut sign = 1.0;
                for k in 0..len {
                    if rng.int(0, 9) == 0 {
                        sign = -sign;
                    }
                    let mut x = [0.0; 4].map(|_| rng.int(-1000, 1000) as f64 / 1000.0);
                    x[3] = sign * (rng.int(1, 1000) as f64 / 1000.0);
                    match rng.int(0, 40) {
                        0 => x = x.map(|_| 0.0),
                        1 => x[3] = -0.0,
                        2 => x[3] = sign * 1e-300,
                        _ => {}
                    }
                    let (inf, sing) = (rng.int(0, 15) == 0, rng.int(0, 15) == 0);
                    line.push(&Sample {
                        theta: k as f64,
                        x,
                        at_infinity: inf,
                        singular: sing,
                    });
                }
                let closed = rng.int(0, 1) == 0;
                let got = sampler.affine(&line, closed);
                cuts += got.branches.len();
                assert_eq!(got, sampler.affine_two_pass(&line, closed), "{:?}", line.x);
            }
            assert!(cuts > 800, "{cuts}");
        }
    }

    /// One-word integers around the double's 53 bits (the fast path of [`int_dd`]) and
    /// beyond it split exactly: `hi + lo = v`.
    #[test]
    fn one_word_integers_split_exactly() {
        let two = |e: u32| 1u64 << e;
        for w in [
            0,
            1,
            2,
            two(52) - 1,
            two(53) - 1,
            two(53),
            two(53) + 1,
            two(63),
            u64::MAX,
        ] {
            for neg in [false, true] {
                let v = if neg { -IBig::from(w) } else { IBig::from(w) };
                let d = int_dd(&v);
                assert_eq!(integral_f64_to_ibig(d.0) + integral_f64_to_ibig(d.1), v);
                assert!(d.1.abs() <= d.0.abs() * f64::EPSILON, "{v}: {d:?}");
            }
        }
    }

    /// The walk's run in passes ([`run_of`]) takes the points, `h` and end point of the
    /// reference point by point, on random runs: small steps, jumps, antipodal flips, NaN,
    /// sign changes and zeros of `h`, crossings known or not, either orientation.
    #[test]
    fn run_in_passes_matches_point_by_point() {
        let mut rng = SplitMix(0x2a2a);
        let mut stops = [0usize; 3];
        for _ in 0..3000 {
            let len = rng.int(0, 30) as usize;
            let mut x = [1.0, 0.1, -0.2, 0.3];
            let mut xs = Vec::with_capacity(len);
            for _ in 0..len {
                let step = match rng.int(0, 60) {
                    0 => 1.0,
                    _ => 0.04,
                };
                for v in &mut x {
                    *v += step * rng.int(-1000, 1000) as f64 / 1000.0;
                }
                let mut y = unit(x).unwrap_or([1.0, 0.0, 0.0, 0.0]);
                match rng.int(0, 80) {
                    0 => y = y.map(|v| -v),
                    1 => y[0] = f64::NAN,
                    2 => y[3] = 0.0,
                    _ => {}
                }
                xs.push(y);
            }
            let walk = Walk {
                prev: Sample::new(0.0, unit([1.0, 0.1, -0.2, 0.3]).unwrap()),
                h_prev: [0.3, -0.3, 0.0][rng.int(0, 2) as usize],
                stack: Vec::new(),
                unknown: rng.int(0, 3) > 0,
                flip: rng.int(0, 1) == 0,
            };
            let h = [rng.int(-3, 3) as f64, 0.0, rng.int(-3, 3) as f64, 1.0];
            let value = |x: &[f64; 4]| dot(&h, x);
            let (mut got_h, mut want_h) = (vec![7.0], vec![7.0]);
            let got = run_of(&xs, &walk, &mut got_h, value);
            let want = run_of_reference(&xs, &walk, &mut want_h, value);
            assert_eq!(got.0, want.0, "{xs:?}");
            assert_eq!(got.1.map(f64::to_bits), want.1.map(f64::to_bits));
            assert_eq!(got.2.to_bits(), want.2.to_bits());
            assert_eq!(
                got_h.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
                want_h.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
            );
            stops[match () {
                _ if got.0 == len => 0,
                _ if dot(&got.1, &xs[got.0]) >= MAX_ANGLE.cos() => 1,
                _ => 2,
            }] += 1;
        }
        // runs taken whole, stopped by `h`, stopped by an angle
        assert!(stops.iter().all(|&c| c > 200), "{stops:?}");
    }

    /// [`inner_f64`] lies strictly on its side of the rational (checked exactly), on random
    /// rationals of all sizes, and an interval narrower than its margin gives an empty
    /// bracket, on which [`Evaluator::root_of_s`] declines (the caller falls back to the
    /// exact approximation).
    #[test]
    fn inner_floats_stay_inside_their_interval() {
        let mut rng = SplitMix(0x1a2b);
        for bits in [1u32, 20, 52, 53, 60, 120, 300, 900] {
            for _ in 0..50 {
                let num = (IBig::from(rng.next_u64()) << bits as usize) >> 64;
                let den = (IBig::from(rng.next_u64() | 1) << (bits / 2) as usize) >> 64;
                let den = if den.is_zero() { IBig::ONE } else { den };
                let q = RBig::from_parts_signed(if rng.int(0, 1) == 0 { -num } else { num }, den);
                for up in [false, true] {
                    let f = inner_f64(&q, up);
                    if q.is_zero() {
                        assert_eq!(f, 0.0);
                        continue;
                    }
                    let exact = RBig::try_from(f).expect("finite");
                    assert_eq!(exact > q, up, "{q} {f}");
                    assert!(((f - q.to_f64().value()) / f).abs() < 1e-14);
                }
            }
        }
        // beyond the floats: NaN, no bracket
        let huge = RBig::from(IBig::ONE << 2000);
        assert!(inner_f64(&huge, true).is_nan());
        assert!(inner_f64(&(RBig::ONE / huge), false).is_nan());
        // an interval narrower than the margins: the bracket is empty and declined
        let param = &levin_params(0x1a2c, 1)[0];
        let eval = Evaluator::new(param).unwrap();
        let lo = RBig::from_parts_signed(
            IBig::from(1_000_000_000_000_001i64),
            IBig::from(1_000_000_000_000_000i64),
        );
        let hi = RBig::from_parts_signed(
            IBig::from(1_000_000_000_000_002i64),
            IBig::from(1_000_000_000_000_000i64),
        );
        let (l, h) = (inner_f64(&lo, true), inner_f64(&hi, false));
        assert!(l > h);
        assert_eq!(eval.root_of_s(l, h), None);
    }

    /// The unrolled evaluation on the coefficient set chosen by index
    /// ([`Evaluator::horner`]) is the generic Horner evaluation of [`Evaluator::values_any`]
    /// on both orders and sheets, value for value.
    #[test]
    fn indexed_coefficient_sets_match_generic_horner() {
        let mut rng = SplitMix(0x4e7);
        let mut checked = 0;
        for param in levin_params(0x4e8, 6) {
            let eval = Evaluator::new(&param).unwrap();
            for _ in 0..200 {
                let t = rng.int(-1_000_000, 1_000_000) as f64 / 1_000_000.0;
                for rev in [false, true] {
                    for sheet in [Sheet::Plus, Sheet::Minus] {
                        let want = eval.values_any(t, rev, sheet);
                        let got = match eval.big_d {
                            2 => eval.values::<3, 1>(t, rev, sheet),
                            3 => eval.values::<4, 2>(t, rev, sheet),
                            4 => eval.values::<5, 3>(t, rev, sheet),
                            _ => continue,
                        };
                        assert_eq!(got, want, "t = {t}, rev = {rev}");
                        checked += 1;
                    }
                }
            }
        }
        assert!(checked >= 4000, "{checked}");
    }
}
