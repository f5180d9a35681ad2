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
//! Arc ends are the exact roots of `s`, approximated by [`AlgebraicReal::to_f64`] (Newton's
//! method inside the isolating interval; exact refinement to `2⁻⁶⁰` when floats cannot
//! bracket the root); coefficients over ℚ(√δ) go to floats through `√δ` in double-double,
//! never through a refined rational (the double-double copies for retries are made on the
//! first retry only). `s` is clamped at 0, which moves
//! a point off the curve by `O(|s|)` only, because `aᵀMd ≡ 0` cancels the first-order error
//! of `√s`. An evaluation whose rounding bound exceeds `10⁻¹⁰·‖X‖` (a sheet passing through
//! the zero vector, a removable zero of Levin's form) is retried at a nearby parameter.
//!
//! # Density
//! Each arc starts from a uniform grid in `θ` (together at least
//! [`SampleOptions::points`] points per piece) and segments are bisected, from a work list,
//! until consecutive unit vectors are within [`MAX_ANGLE`] radians up to sign and, with a
//! tolerance, the chord deviation in the chart is at most the tolerance (checked where the
//! three points lie within [`AFFINE_RADIUS`] of the origin). At most [`MAX_DEPTH`] bisections
//! of a grid segment and [`MAX_POINTS`] points per call: beyond either, an error.
//!
//! # The chart
//! `h(X) = aX₀ + bX₁ + cX₂ + dX₃` (default `w`) is the plane at infinity. Where every
//! coefficient of a component is rational, the crossings are the exact real roots of `h(X(u))`
//! (for Levin's form of `h(a)² − h(d)²s`, the sheet from the signs of `h(a)` and `h(d)`),
//! tangential touches included; otherwise the sign changes of `h` along the polyline,
//! located by bisection. Affine coordinates are those of `X/h(X)` without the last
//! coordinate whose coefficient in `h` is nonzero (`(x/w, y/w, z/w)` for the default).

use super::curve::{Arc, ComponentParam, Curve, Number, NumberPoly, ParamRange, ParamValue};
use super::curve::{RealPiece, Sheet};
use crate::error::Error;
use qsic_algebra::{AlgebraicReal, IBig, Poly, RBig, Ring, Sign};
use std::f64::consts::{FRAC_PI_2, PI};

/// Largest angle (radians) between consecutive unit vectors of a polyline, up to sign.
pub const MAX_ANGLE: f64 = 0.1;
/// Most bisections of one segment of the initial grid.
pub const MAX_DEPTH: u32 = 48;
/// Most points of one [`sample`] call (requested and added by refinement together).
pub const MAX_POINTS: usize = 1 << 22;
/// The chord tolerance is enforced on segments within this distance of the chart's origin.
pub const AFFINE_RADIUS: f64 = 1e6;

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
        Ok(Chart {
            exact: self.chart.clone(),
            h: self.chart.clone().map(|c| c.to_f64().value()),
            drop,
        })
    }

    /// The affine coordinates of `x` in the chart (module docs), `None` at infinity or for
    /// a zero chart.
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
/// [`Error::InvalidShape`] for a zero chart, a non-positive tolerance or zero points;
/// [`Error::Algebra`] when a coefficient is beyond the range of `f64`, a piece has no
/// parameterization, or the refinement does not converge within [`MAX_DEPTH`].
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
    if options.points == 0 {
        return Err(Error::InvalidShape(
            "at least one point per piece is asked for (--points ≥ 1)".into(),
        ));
    }
    if options.points > MAX_POINTS {
        return Err(Error::Limit {
            what: format!("{} points per piece", options.points),
            limit: MAX_POINTS,
        });
    }
    if options.tolerance.is_some_and(|t| t.is_nan() || t <= 0.0) {
        return Err(Error::InvalidShape("the tolerance must be positive".into()));
    }
    let chart = options.chart()?;
    let mut budget = MAX_POINTS;
    let mut pieces = Vec::with_capacity(curve.pieces.len());
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
                let sampler = Sampler {
                    eval: Evaluator::new(param)?,
                    crossings: if lies_in_plane(param, &chart.exact) {
                        Crossings::InPlane
                    } else {
                        exact_crossings(&ExactParam::new(param), &chart.exact)
                    },
                    singular: singular_params(curve, param, &chart.exact),
                    chart: &chart,
                    tolerance: options.tolerance,
                };
                sampler.piece(*component, arcs, *closed, options.points, &mut budget)?
            }
        };
        pieces.push(sampled);
    }
    Ok(Sampled { pieces })
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
    drop: usize,
}

impl Chart {
    fn value(&self, x: &[f64; 4]) -> f64 {
        (0..4).map(|i| self.h[i] * x[i]).sum()
    }

    /// Affine coordinates of `x`, `None` at infinity.
    fn affine(&self, x: &[f64; 4]) -> Option<[f64; 3]> {
        let h = self.value(x);
        if h == 0.0 {
            return None;
        }
        let mut out = [0.0; 3];
        let mut k = 0;
        for (i, v) in x.iter().enumerate() {
            if i != self.drop {
                out[k] = v / h;
                k += 1;
            }
        }
        Some(out)
    }
}

fn to_f64(c: &Number) -> Result<f64, Error> {
    // double-double keeps ~106 bits of the terms: enough for a double unless they cancel
    // by more than 2⁵⁰
    let v = sqrt_field_dd(c, 50).map_or_else(|| c.to_f64(), |d| d.0 + d.1);
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Error::Algebra(format!(
            "coefficient {c} is beyond the range of f64"
        )))
    }
}

fn unit(x: [f64; 4]) -> Option<[f64; 4]> {
    let n = x.iter().map(|v| v * v).sum::<f64>().sqrt();
    (n > 0.0 && n.is_finite()).then(|| x.map(|v| v / n))
}

fn dot(a: &[f64; 4], b: &[f64; 4]) -> f64 {
    (0..4).map(|i| a[i] * b[i]).sum()
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
        }
    } else {
        AffinePiece {
            branches: chart.affine(&x).into_iter().map(|p| vec![p]).collect(),
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
        affine,
    })
}

/// Homogeneous float coefficients of a parameterization (increasing powers of `u`, padded
/// to the homogeneous degree) and their absolute values for rounding bounds.
struct Evaluator<'a> {
    /// `X` (rational) or `a` (Levin), `D + 1` coefficients each.
    x: [Vec<f64>; 4],
    /// `d` (Levin), `D − 1` coefficients each; empty for a rational param.
    d: [Vec<f64>; 4],
    /// `s`, five coefficients (Levin); empty for a rational param.
    s: Vec<f64>,
    /// Relative rounding of one evaluation, per unit of the bound.
    gamma: f64,
    /// The same coefficients in double-double (`hi + lo`), for the retry of an
    /// ill-conditioned evaluation: `[x₀…x₃, d₀…d₃, s]`, computed on the first retry.
    dd: std::cell::OnceCell<Vec<Vec<Dd>>>,
    /// The parameterization (for `dd`).
    param: &'a ComponentParam,
    /// The homogeneous degree `D`.
    big_d: usize,
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
    /// `self / n` for a positive integer `n` (two quotient digits).
    fn div_f64_int(self, n: &IBig) -> Dd {
        let d = int_dd(n);
        let q1 = self.0 / d.0;
        let r = self.add(d.mul_f64(-q1));
        let q2 = r.0 / d.0;
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
        let diff = self.add(Dd(-sq.0, -sq.1));
        Dd::two_sum(r, diff.0 / (2.0 * r))
    }
}

/// An integer in double-double (exact below `2¹⁰⁶` in magnitude, rounded beyond).
fn int_dd(v: &IBig) -> Dd {
    let hi = v.to_f64().value();
    if hi.abs() < 9.0e15 {
        return Dd(hi, 0.0);
    }
    let lo = RBig::try_from(hi).map_or(0.0, |h| (RBig::from(v.clone()) - h).to_f64().value());
    Dd(hi, lo)
}

/// `c` in double-double when its field is ℚ(√δ) generated by a root of `x² − δ` (the fields
/// of Levin's form, [`super::curve::sqrt_field`]): `±√δ` by a Newton step in double-double,
/// the representative by Horner's rule; `None` for other fields, and when the terms cancel
/// by more than `2^max_loss` (the ~106 bits kept are relative to the terms, not the sum).
fn sqrt_field_dd(c: &Number, max_loss: i32) -> Option<Dd> {
    let k = c.field().filter(|_| !c.numerator().is_constant())?;
    let alpha = k.alpha();
    let m = alpha.poly();
    let delta = match m.coeffs() {
        [c0, c1, c2] if c1.is_zero() && *c2 == IBig::ONE && *c0 < IBig::ZERO => -c0.clone(),
        _ => return None,
    };
    let mut root = int_dd(&delta).sqrt();
    if alpha.interval().hi() <= &RBig::ZERO {
        root = Dd(-root.0, -root.1);
    }
    let mut v = Dd::default();
    let mut size = 0.0f64;
    for coef in c.numerator().coeffs().iter().rev() {
        let term = int_dd(coef);
        v = v.mul(root).add(term);
        size = size * root.0.abs() + term.0.abs();
    }
    let kept = v.0.abs() * 2f64.powi(max_loss);
    if kept.is_nan() || kept < size {
        return None;
    }
    Some(v.div_f64_int(c.denominator()))
}

/// `c` to about 106 bits: its value at a rational within `2⁻¹²⁰` of `α`, split in two floats.
fn to_dd(c: &Number) -> Dd {
    if let Some(v) = sqrt_field_dd(c, 2) {
        return v;
    }
    let v = match c.field().filter(|_| !c.numerator().is_constant()) {
        None => RBig::from(c.numerator().leading()) / RBig::from(c.denominator().clone()),
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

fn dd_padded(p: &NumberPoly, len: usize) -> Vec<Dd> {
    let mut c: Vec<Dd> = p.coeffs().iter().map(to_dd).collect();
    c.resize(len, Dd::default());
    c
}

fn padded(p: &NumberPoly, len: usize) -> Result<Vec<f64>, Error> {
    let mut c = p
        .coeffs()
        .iter()
        .map(to_f64)
        .collect::<Result<Vec<_>, _>>()?;
    c.resize(len, 0.0);
    Ok(c)
}

impl<'a> Evaluator<'a> {
    fn new(param: &'a ComponentParam) -> Result<Evaluator<'a>, Error> {
        let deg = |p: &NumberPoly| p.degree().unwrap_or(0);
        match param {
            ComponentParam::Point(_) => Err(Error::Algebra(
                "a curve piece with a point parameterization".into(),
            )),
            ComponentParam::Rational { x, .. } => {
                let len = x.iter().map(deg).max().unwrap_or(0) + 1;
                let mut out: [Vec<f64>; 4] = Default::default();
                for i in 0..4 {
                    out[i] = padded(&x[i], len)?;
                }
                Ok(Evaluator {
                    x: out,
                    d: Default::default(),
                    s: Vec::new(),
                    gamma: 4.0 * (len as f64 + 2.0) * f64::EPSILON,
                    dd: std::cell::OnceCell::new(),
                    param,
                    big_d: len - 1,
                })
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
                let mut xa: [Vec<f64>; 4] = Default::default();
                let mut xd: [Vec<f64>; 4] = Default::default();
                for i in 0..4 {
                    xa[i] = padded(&a[i], big_d + 1)?;
                    xd[i] = padded(&d[i], big_d - 1)?;
                }
                Ok(Evaluator {
                    x: xa,
                    d: xd,
                    s: padded(s, 5)?,
                    gamma: 8.0 * (big_d as f64 + 4.0) * f64::EPSILON,
                    dd: std::cell::OnceCell::new(),
                    param,
                    big_d,
                })
            }
        }
    }

    /// `X(U₀, U₁)` on `sheet` up to a nonzero factor, `None` where rounding could exceed
    /// `10⁻¹⁰·‖X‖`.
    fn eval(&self, u: (f64, f64), sheet: Sheet) -> Option<[f64; 4]> {
        let (t, rev) = if u.1.abs() >= u.0.abs() {
            (u.0 / u.1, false)
        } else {
            (u.1 / u.0, true)
        };
        let at = t.abs();
        let horner = |c: &[f64]| -> (f64, f64) {
            let (mut v, mut b) = (0.0, 0.0);
            let mut step = |k: f64| {
                v = v * t + k;
                b = b * at + k.abs();
            };
            if rev {
                c.iter().copied().for_each(&mut step);
            } else {
                c.iter().rev().copied().for_each(&mut step);
            }
            (v, b)
        };
        let mut x = [0.0; 4];
        let mut bound = 0.0f64;
        let root = if self.s.is_empty() {
            None
        } else {
            let (s, _) = horner(&self.s);
            Some(s.max(0.0).sqrt())
        };
        for i in 0..4 {
            let (v, b) = horner(&self.x[i]);
            x[i] = v;
            let mut bi = b;
            if let Some(r) = root {
                let (dv, db) = horner(&self.d[i]);
                let sign = if sheet == Sheet::Minus { -1.0 } else { 1.0 };
                x[i] += sign * dv * r;
                bi += db * r;
            }
            bound = bound.max(bi);
        }
        let norm = x.iter().map(|v| v * v).sum::<f64>().sqrt();
        if norm.is_finite() && norm > 0.0 && self.gamma * bound <= 1e-10 * norm {
            return Some(x);
        }
        if !bound.is_finite() {
            return None;
        }
        self.eval_dd(t, rev, sheet, bound)
    }

    /// The double-double coefficients `[x₀…x₃, d₀…d₃, s]` (see `dd`).
    fn dd(&self) -> &[Vec<Dd>] {
        self.dd.get_or_init(|| match self.param {
            ComponentParam::Rational { x, .. } => {
                x.iter().map(|p| dd_padded(p, self.big_d + 1)).collect()
            }
            ComponentParam::Levin { a, d, s, .. } => {
                let mut dd: Vec<Vec<Dd>> = a.iter().map(|p| dd_padded(p, self.big_d + 1)).collect();
                dd.extend(d.iter().map(|p| dd_padded(p, self.big_d - 1)));
                dd.push(dd_padded(s, 5));
                dd
            }
            ComponentParam::Point(_) => Vec::new(),
        })
    }

    /// [`Evaluator::eval`] in double-double arithmetic (`t` is exact), `None` where even
    /// that rounding could exceed `10⁻¹⁰·‖X‖`.
    fn eval_dd(&self, t: f64, rev: bool, sheet: Sheet, bound: f64) -> Option<[f64; 4]> {
        let dd = self.dd();
        let horner = |c: &[Dd]| -> Dd {
            let mut v = Dd::default();
            let mut step = |k: &Dd| v = v.mul_f64(t).add(*k);
            if rev {
                c.iter().for_each(&mut step);
            } else {
                c.iter().rev().for_each(&mut step);
            }
            v
        };
        let levin = !self.s.is_empty();
        let root = levin.then(|| horner(&dd[8]).sqrt());
        let mut x = [0.0; 4];
        for i in 0..4 {
            let mut v = horner(&dd[i]);
            if let Some(r) = root {
                let mut dr = horner(&dd[4 + i]).mul(r);
                if sheet == Sheet::Minus {
                    dr = Dd(-dr.0, -dr.1);
                }
                v = v.add(dr);
            }
            x[i] = v.0 + v.1;
        }
        let norm = x.iter().map(|v| v * v).sum::<f64>().sqrt();
        let gamma = self.gamma * f64::EPSILON * 4.0;
        (norm.is_finite() && norm > 0.0 && gamma * bound <= 1e-10 * norm).then_some(x)
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

fn span(range: &ParamRange) -> Result<ArcSpan, Error> {
    let whole = ArcSpan {
        theta: (-FRAC_PI_2, FRAC_PI_2),
        ends: ((-1.0, 0.0), (1.0, 0.0)),
    };
    Ok(match range {
        ParamRange::All => whole,
        ParamRange::Between(ParamValue::Infinity, ParamValue::Infinity) => whole,
        ParamRange::Between(ParamValue::Infinity, ParamValue::Finite(hi)) => {
            let h = hi.to_f64();
            ArcSpan {
                theta: (-FRAC_PI_2, h.atan()),
                ends: ((-1.0, 0.0), projective(h)),
            }
        }
        ParamRange::Between(ParamValue::Finite(lo), ParamValue::Infinity) => {
            let l = lo.to_f64();
            ArcSpan {
                theta: (l.atan(), FRAC_PI_2),
                ends: (projective(l), (1.0, 0.0)),
            }
        }
        ParamRange::Between(ParamValue::Finite(lo), ParamValue::Finite(hi)) => {
            let (l, h) = (lo.to_f64(), hi.to_f64());
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
        .map(|c| {
            c.numerator()
                .is_constant()
                .then(|| RBig::from(c.numerator().leading()) / RBig::from(c.denominator().clone()))
        })
        .collect::<Option<Vec<_>>>()?;
    Some(Poly::new(c))
}

fn rational_vector(v: &[NumberPoly; 4]) -> Option<[Poly<RBig>; 4]> {
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
                match (rational_vector(a), rational_vector(d), rational_poly(s)) {
                    (Some(a), Some(d), Some(s)) => Some(ExactParam::Levin { a, d, s, degree }),
                    _ => None,
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

/// The sign of the rational polynomial `p` at the algebraic `r`.
fn sign_at(p: &Poly<RBig>, r: &AlgebraicReal) -> Sign {
    if p.is_zero() {
        return Sign::Zero;
    }
    r.sign_of(&Poly::from_rational(p).0)
}

/// The coefficient of `u^k`, the value at `u = ∞` of a form of degree `k`.
fn at_infinity(p: &Poly<RBig>, k: usize) -> Sign {
    Sign::of(p.coeff(k).numerator())
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

/// The exact crossings of the component with the plane `h = 0`.
fn exact_crossings(exact: &ExactParam, h: &[RBig; 4]) -> Crossings {
    match exact_crossings_of(exact, h) {
        None if matches!(exact, ExactParam::Irrational) => Crossings::Unknown,
        None => Crossings::InPlane,
        Some(c) => Crossings::Exact(c),
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
            let (ha, hd) = (chart_form(h, a), chart_form(h, d));
            let n = &(&ha * &ha) - &(&(&hd * &hd) * s);
            if n.is_zero() {
                // a quartic is not planar: h(a) = ±h(d)√s identically cannot hold
                return Some(Vec::new());
            }
            // h(a) + σ·h(d)·√s = 0: σ = −sign(h(a)·h(d)); both sheets where √s = 0 or h(d) = 0
            let sheets = |sa: Sign, sd: Sign, ss: Sign| -> Vec<Sheet> {
                match (ss, sd) {
                    (Sign::Negative, _) => Vec::new(),
                    (Sign::Zero, _) | (_, Sign::Zero) => vec![Sheet::Plus, Sheet::Minus],
                    _ if sa == sd => vec![Sheet::Minus],
                    _ => vec![Sheet::Plus],
                }
            };
            // a_i² − d_i²·s: X_σ is the zero vector where every one vanishes and the signs
            // of a_i and d_i match σ (a removable zero of Levin's form, where c₂ = 0: not a
            // point of the plane, whatever h is)
            let norms: Vec<Poly<RBig>> = (0..4)
                .map(|i| &(&a[i] * &a[i]) - &(&(&d[i] * &d[i]) * s))
                .collect();
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
            for r in roots(&n) {
                let mut sh = sheets(sign_at(&ha, &r), sign_at(&hd, &r), sign_at(s, &r));
                let on_s = sign_at(s, &r) == Sign::Zero;
                sh.retain(|&sheet| {
                    !vanishes(
                        sheet,
                        &|i| sign_at(&a[i], &r),
                        &|i| if on_s { Sign::Zero } else { sign_at(&d[i], &r) },
                        &|i| sign_at(&norms[i], &r) == Sign::Zero,
                    )
                });
                out.push(Crossing {
                    value: ParamValue::Finite(r),
                    sheets: sh,
                });
            }
            if n.degree().unwrap_or(0) < 2 * degree {
                let mut sh = sheets(
                    at_infinity(&ha, *degree),
                    at_infinity(&hd, degree - 2),
                    at_infinity(s, 4),
                );
                sh.retain(|&sheet| {
                    !vanishes(
                        sheet,
                        &|i| at_infinity(&a[i], *degree),
                        &|i| {
                            if at_infinity(s, 4) == Sign::Zero {
                                Sign::Zero
                            } else {
                                at_infinity(&d[i], degree - 2)
                            }
                        },
                        &|i| at_infinity(&norms[i], 2 * degree) == Sign::Zero,
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

/// Samples the pieces of one component.
struct Sampler<'a> {
    eval: Evaluator<'a>,
    crossings: Crossings,
    /// The exact parameters of the curve's real singular points on this component.
    /// The singular points' parameters, and whether each point is at infinity.
    singular: Vec<(ParamValue, bool)>,
    chart: &'a Chart,
    tolerance: Option<f64>,
}

impl Sampler<'_> {
    /// The point at `θ` on `sheet`, retried at nearby parameters inside `(lo, hi)` where
    /// rounding is too large.
    fn at(&self, theta: f64, lo: f64, hi: f64, sheet: Sheet) -> Result<Sample, Error> {
        let offsets = [0.0, 1e-6, -1e-6, 1e-3, -1e-3, 0.03, -0.03, 0.2, -0.2];
        for f in offsets {
            let t = theta + f * (hi - lo);
            if f != 0.0 && !(lo < t && t < hi) {
                continue;
            }
            if let Some(x) = self.eval.eval((t.sin(), t.cos()), sheet).and_then(unit) {
                return Ok(Sample {
                    theta: t,
                    x,
                    at_infinity: false,
                    singular: false,
                });
            }
        }
        Err(Error::Algebra(format!(
            "no well-conditioned point near θ = {theta} in ({lo}, {hi})"
        )))
    }

    /// The point at an exact end of an arc (`u` on ℙ¹), nudged inwards if needed.
    fn at_end(&self, u: (f64, f64), theta: f64, other: f64, sheet: Sheet) -> Result<Sample, Error> {
        if let Some(x) = self.eval.eval(u, sheet).and_then(unit) {
            return Ok(Sample {
                theta,
                x,
                at_infinity: false,
                singular: false,
            });
        }
        for f in [1e-9, 1e-6, 1e-3] {
            let t = theta + f * (other - theta);
            if let Some(x) = self.eval.eval((t.sin(), t.cos()), sheet).and_then(unit) {
                return Ok(Sample {
                    theta: t,
                    x,
                    at_infinity: false,
                    singular: false,
                });
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
        let tol = self.tolerance.unwrap_or(f64::INFINITY);
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

    /// The polyline of one arc, in increasing `θ`, with its exact crossings inserted.
    fn arc(&self, arc: &Arc, n: usize, budget: &mut usize) -> Result<Vec<Sample>, Error> {
        let sp = span(&arc.range)?;
        let (t0, t1) = sp.theta;
        let sheet = arc.sheet;
        let levin = !self.eval.s.is_empty();
        if levin == (sheet == Sheet::Only) {
            return Err(Error::Algebra(
                "an arc's sheet does not match its parameterization".into(),
            ));
        }
        let mut grid = Vec::with_capacity(n + 2);
        grid.push(self.at_end(sp.ends.0, t0, t1, sheet)?);
        for k in 1..n {
            let th = t0 + (t1 - t0) * (k as f64) / (n as f64);
            grid.push(self.at(th, t0, t1, sheet)?);
        }
        grid.push(self.at_end(sp.ends.1, t1, t0, sheet)?);
        // exact events on this arc: crossings of the plane at infinity, singular points
        // (parameter, singular, at infinity)
        let mut events: Vec<(&ParamValue, bool, bool)> = Vec::new();
        if let Crossings::Exact(crossings) = &self.crossings {
            for c in crossings {
                if c.sheets.contains(&sheet) {
                    events.push((&c.value, false, true));
                }
            }
        }
        events.extend(self.singular.iter().map(|(v, inf)| (v, true, *inf)));
        {
            for (value, singular, at_infinity) in events {
                if !in_range(value, &arc.range) {
                    continue;
                }
                let (u, mut th) = match value {
                    ParamValue::Infinity => ((1.0, 0.0), FRAC_PI_2),
                    ParamValue::Finite(r) => {
                        let v = r.to_f64();
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
                let other = if th - t0 < t1 - th { t1 } else { t0 };
                let mut s = self.at_end(u, th, other, sheet)?;
                let mark = |g: &mut Sample| {
                    g.singular |= singular;
                    g.at_infinity |= at_infinity;
                };
                mark(&mut s);
                // an end of the arc, or a new point in order
                if (th - t0).abs() <= 1e-12 {
                    mark(&mut grid[0]);
                } else if (th - t1).abs() <= 1e-12 {
                    let last = grid.len() - 1;
                    mark(&mut grid[last]);
                } else if let Some(g) = grid
                    .iter_mut()
                    .find(|g| (g.at_infinity || g.singular) && (g.theta - s.theta).abs() <= 1e-12)
                {
                    // the same parameter as an event already placed (a singular point at
                    // infinity): one point with both marks
                    mark(g);
                } else {
                    let at = grid.partition_point(|g| g.theta < s.theta);
                    grid.insert(at, s);
                }
            }
        }
        // a point between any two consecutive events, so that every branch they cut has a
        // point of its own besides its ends; on the whole line the two ends are one point
        if matches!(arc.range, ParamRange::All) && grid.len() > 1 {
            let last = grid.len() - 1;
            let (inf, sing) = (
                grid[0].at_infinity | grid[last].at_infinity,
                grid[0].singular | grid[last].singular,
            );
            for k in [0, last] {
                grid[k].at_infinity = inf;
                grid[k].singular = sing;
            }
        }
        let mut k = 0;
        while k + 1 < grid.len() {
            let (p, q) = (&grid[k], &grid[k + 1]);
            let event = |g: &Sample| g.at_infinity || g.singular;
            if event(p) && event(q) && q.theta > p.theta {
                let th = 0.5 * (p.theta + q.theta);
                let m = self.at(th, p.theta, q.theta, sheet)?;
                grid.insert(k + 1, m);
                k += 1;
            }
            k += 1;
        }
        *budget = budget.checked_sub(grid.len()).ok_or_else(too_many_points)?;
        let mut out = vec![grid[0]];
        let mut stack: Vec<(Sample, u32)> = grid[1..].iter().rev().map(|s| (*s, 0)).collect();
        while let Some((q, depth)) = stack.pop() {
            let p = out[out.len() - 1];
            match self.split(&p, &q, sheet)? {
                Some(m) if depth < MAX_DEPTH => {
                    *budget = budget.checked_sub(1).ok_or_else(too_many_points)?;
                    stack.push((q, depth + 1));
                    stack.push((m, depth + 1));
                }
                Some(_) => {
                    return Err(Error::Algebra(format!(
                        "sampling did not converge near θ = {}",
                        p.theta
                    )))
                }
                None => out.push(q),
            }
        }
        if matches!(self.crossings, Crossings::Unknown) {
            self.float_crossings(&mut out, sheet)?;
        }
        if arc.reversed {
            out.reverse();
        }
        Ok(out)
    }

    /// The sampled piece: its arcs joined, oriented, closed, and its affine view.
    fn piece(
        &self,
        component: usize,
        arcs: &[Arc],
        closed: bool,
        points: usize,
        budget: &mut usize,
    ) -> Result<SampledPiece, Error> {
        let n = points.div_ceil(arcs.len().max(1)).max(8) + 1;
        let mut line: Vec<Sample> = Vec::new();
        for arc in arcs {
            let mut part = self.arc(arc, n, budget)?;
            if let (Some(last), Some(first)) = (line.last_mut(), part.first()) {
                // consecutive arcs share their end point (unless one end was nudged)
                if dot(&last.x, &first.x).abs() >= 1.0 - 1e-12 {
                    last.at_infinity |= first.at_infinity;
                    last.singular |= first.singular;
                    part.remove(0);
                }
            }
            line.extend(part);
        }
        if closed && line.len() > 1 {
            let last = line.len() - 1;
            line[0].at_infinity |= line[last].at_infinity;
            line[0].singular |= line[last].singular;
            line.pop();
        }
        // orient: consecutive dot products nonnegative
        for k in 1..line.len() {
            if dot(&line[k - 1].x, &line[k].x) < 0.0 {
                line[k].x = line[k].x.map(|v| -v);
            }
        }
        let affine = if matches!(self.crossings, Crossings::InPlane) {
            AffinePiece {
                branches: Vec::new(),
                bounded: false,
                points_at_infinity: Vec::new(),
                at_infinity: true,
            }
        } else {
            self.affine(&line, closed)
        };
        let mut pts: Vec<[f64; 4]> = line.iter().map(|s| s.x).collect();
        if closed && !pts.is_empty() {
            let first = pts[0];
            let last = pts[pts.len() - 1];
            pts.push(if dot(&first, &last) < 0.0 {
                first.map(|v| -v)
            } else {
                first
            });
        }
        let breaks = line
            .iter()
            .enumerate()
            .filter(|(_, s)| s.singular)
            .map(|(k, _)| k)
            .collect();
        Ok(SampledPiece {
            component,
            isolated: false,
            points: pts,
            closed,
            breaks,
            affine,
        })
    }

    /// Inserts, between consecutive points of one arc where `h` changes sign (up to the
    /// sign of the vectors), the crossing located by bisection on the parameter.
    fn float_crossings(&self, line: &mut Vec<Sample>, sheet: Sheet) -> Result<(), Error> {
        let mut k = 0;
        while k + 1 < line.len() {
            let (p, q) = (line[k], line[k + 1]);
            let oriented = |x: [f64; 4], to: &[f64; 4]| {
                if dot(&x, to) < 0.0 {
                    x.map(|v| -v)
                } else {
                    x
                }
            };
            let hp = self.chart.value(&p.x);
            let hq = self.chart.value(&oriented(q.x, &p.x));
            if hp == 0.0 {
                line[k].at_infinity = true;
            }
            // a point known exactly to be at infinity (a singular point there) is the
            // crossing: the rounding of h near it says nothing
            let exact_end = p.at_infinity || q.at_infinity;
            if exact_end || hp == 0.0 || hq == 0.0 || (hp > 0.0) == (hq > 0.0) {
                k += 1;
                continue;
            }
            let (mut lo, mut hi) = (p, q);
            for _ in 0..60 {
                let (a, b) = (lo.theta.min(hi.theta), lo.theta.max(hi.theta));
                if b - a <= 1e-15 * (1.0 + a.abs()) {
                    break;
                }
                let m = self.at(0.5 * (a + b), a, b, sheet)?;
                let hm = self.chart.value(&oriented(m.x, &p.x));
                if (hm > 0.0) == (hp > 0.0) {
                    lo = m;
                } else {
                    hi = m;
                }
            }
            let mut c = if self.chart.value(&lo.x).abs() <= self.chart.value(&hi.x).abs() {
                lo
            } else {
                hi
            };
            c.at_infinity = true;
            // a singular point next to the crossing keeps a point of its own between them,
            // so that the affine branch it starts has one besides its end
            let mid = |a: &Sample, b: &Sample| -> Result<Sample, Error> {
                let (lo, hi) = (a.theta.min(b.theta), a.theta.max(b.theta));
                self.at(0.5 * (lo + hi), lo, hi, sheet)
            };
            let before = if p.singular && p.theta != c.theta {
                Some(mid(&p, &c)?)
            } else {
                None
            };
            let after = if q.singular && q.theta != c.theta {
                Some(mid(&c, &q)?)
            } else {
                None
            };
            let mut added = vec![c];
            if let Some(m) = before {
                added.insert(0, m);
            }
            if let Some(m) = after {
                added.push(m);
            }
            let n = added.len();
            line.splice(k + 1..k + 1, added);
            k += n + 1;
        }
        Ok(())
    }

    /// Splits the oriented polyline at its crossings with the plane at infinity (the branches
    /// end before and start after them) and at its real singular points (both branches keep
    /// the point).
    fn affine(&self, line: &[Sample], closed: bool) -> AffinePiece {
        let n = line.len();
        let breaks: Vec<usize> = (0..n).filter(|&k| line[k].at_infinity).collect();
        let cuts: Vec<usize> = (0..n)
            .filter(|&k| line[k].at_infinity || line[k].singular)
            .collect();
        let points_at_infinity: Vec<[f64; 4]> = breaks.iter().map(|&k| line[k].x).collect();
        let mut branches = Vec::new();
        let mut current: Vec<[f64; 3]> = Vec::new();
        let order: Vec<usize> = if closed && !cuts.is_empty() {
            (0..=n).map(|k| (k + cuts[0]) % n).collect()
        } else {
            (0..n).collect()
        };
        // the previous point, oriented along the walk (a loop may come back reversed)
        let mut prev: Option<[f64; 4]> = None;
        // `current` holds only the singular point it restarts from
        let mut restarted = false;
        for &k in &order {
            let s = &line[k];
            if s.at_infinity {
                if !current.is_empty() && !restarted {
                    branches.push(std::mem::take(&mut current));
                }
                current.clear();
                restarted = false;
                prev = None;
                continue;
            }
            let x = match prev {
                Some(p) if dot(&p, &s.x) < 0.0 => s.x.map(|v| -v),
                _ => s.x,
            };
            if prev.is_some_and(|p| (self.chart.value(&p) > 0.0) != (self.chart.value(&x) > 0.0)) {
                // a sign change of h without a crossing point: the branch breaks here
                branches.push(std::mem::take(&mut current));
            }
            prev = Some(x);
            if let Some(a) = self.chart.affine(&s.x) {
                current.push(a);
                if s.singular {
                    // the branch ends at the singular point and the next one starts there
                    if current.len() > 1 {
                        branches.push(std::mem::take(&mut current));
                    }
                    current = vec![a];
                    restarted = true;
                } else {
                    restarted = false;
                }
            }
        }
        if closed && cuts.is_empty() && !current.is_empty() {
            current.push(current[0]);
        }
        if !current.is_empty() && !restarted {
            branches.push(current);
        }
        AffinePiece {
            bounded: points_at_infinity.is_empty() && !branches.is_empty(),
            branches,
            points_at_infinity,
            at_infinity: false,
        }
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
    let ab: Vec<f64> = (0..3).map(|i| b[i] - a[i]).collect();
    let ac: Vec<f64> = (0..3).map(|i| c[i] - a[i]).collect();
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
