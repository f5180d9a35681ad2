//! A conic component in an affine chart: its type, centre or vertex, axes and lengths, exactly
//! — what a CAD kernel stores for a plane section of a natural quadric.
//!
//! The metric is the Euclidean one of the chart's affine coordinates `(x′, y′, z′)` (`w′ = 1`;
//! `(x, y, z)` in the default chart `w = 0`). [`super::affine_conic`] reads a conic that carries its
//! plane section ([`crate::param::PlaneSection`], every conic of `param`) there, over the
//! plane's own field ([`super::section`]); [`param_conic`], the reference it is tested equal
//! to, reads the parameterization `X(u) = x₀ + x₁u + x₂u²` alone (chart coordinates), no
//! quadric needed, in the parameterization's field. In the plane's
//! coordinates `Y` (`X = x₀Y₀ + x₁Y₁ + x₂Y₂`) the conic is `Y₀Y₂ − Y₁² = 0` (matrix `C`) and
//! its line at infinity is `ℓ·Y = 0`, `ℓ = (w₀, w₁, w₂)` the `w′` coordinates of the `xᵢ`,
//! so with `W(u) = w₀ + w₁u + w₂u²`:
//!
//! * type: `W ≡ 0` at infinity; else by `Δ = w₁² − 4w₀w₂`: `< 0` ellipse (a circle when its
//!   form is proportional to the metric), `= 0` parabola, `> 0` hyperbola — exact signs;
//! * centre: the pole of the line at infinity, `C⁻¹ℓ = (2w₂, −w₁, 2w₀)`, i.e. the point
//!   `2w₂x₀ − w₁x₁ + 2w₀x₂` (its `w′` is `−Δ`): rational in the component's field `K`;
//! * axes: on the directions `ℓ·Z = 0` (basis `Z_a`, `Z_b`, images `v_a`, `v_b` in ℝ³) the
//!   conic is `ZᵀCZ = κ = 1/Δ` about the centre; with `F = [Z_iᵀCZ_j]` and the Gram matrix
//!   `G = [v_i·v_j]` the squared semi-axes `μ` are the roots of
//!   `det F·μ² − τκ·μ + det G·κ² = 0`, `τ = F₁₁G₂₂ + F₂₂G₁₁ − 2F₁₂G₁₂`: in `K(√D)`,
//!   `D = τ² − 4 det F det G` (`D = 0`: a circle); the axis of `μ` spans the kernel of
//!   `μF − κG`. Over `K = ℚ` they are exact in ℚ(√D); over a larger `K` exact in `K` when `D`
//!   is the square of a rational, else `μ = (sτ ± √D)/|2Δ det F|`, `s` the sign of `Δ det F`
//!   ([`Surd`], no inverse in `K`) and the directions are decimals;
//! * parabola: with the double root `u₀` of `W` moved to `t = ∞` (`u = u₀ + 1/t`) the affine
//!   points are `a + bt + dt²`: the axis is `d` (pointing into the parabola), the vertex is at
//!   `t = −(b·d)/(2d·d)`, the focal length `f` has `f² = |b⊥|⁴/(16|d|²)`, `b⊥` the part of `b`
//!   orthogonal to `d` — all in `K`.

use super::Chart;
use crate::error::Error;
use crate::param::curve::{from_quadratic, sqrt_field};
use crate::param::expr::Names;
use crate::param::{Number, NumberPoly, Point};
use qsic_algebra::field::Quadratic;
use qsic_algebra::{Field, IBig, RBig, Ring, Sign};

/// `(p + q·√d)/den` with `p, q, d, den` in the conic's field, `d ≥ 0` (not known to be a
/// square) and `den > 0`; `den = 1` whenever `q = 0`. The denominator is kept apart because
/// an inverse in a field of degree n is about n times as long as the element.
#[derive(Clone, Debug)]
pub struct Surd {
    /// The rational part (over `den`).
    pub p: Number,
    /// The coefficient of the root (zero: the value is `p`).
    pub q: Number,
    /// The radicand, `≥ 0`.
    pub d: Number,
    /// The positive denominator.
    pub den: Number,
}

impl Surd {
    /// The exact value `v`.
    pub fn number(v: Number) -> Surd {
        Surd {
            p: v,
            q: Number::zero(),
            d: Number::zero(),
            den: Number::one(),
        }
    }

    /// The value when it lies in the field (`q = 0`).
    pub fn as_number(&self) -> Option<&Number> {
        self.q.is_zero().then_some(&self.p)
    }

    /// `−value`.
    pub fn neg(&self) -> Surd {
        Surd {
            p: self.p.neg(),
            q: self.q.neg(),
            d: self.d.clone(),
            den: self.den.clone(),
        }
    }

    /// A float approximation (the quotients taken exactly at a rational point near `α`, so
    /// parts far beyond the range of `f64` still give the value).
    pub fn to_f64(&self) -> f64 {
        if self.den.is_one() {
            return approx(&self.p) + approx(&self.q) * approx(&self.d).max(0.0).sqrt();
        }
        let den = near(&self.den);
        let p = (near(&self.p) / &den).to_f64().value();
        let q = near(&self.q) / &den;
        let root = (&q * &q * near(&self.d)).to_f64().value().max(0.0).sqrt();
        if q < RBig::ZERO {
            p - root
        } else {
            p + root
        }
    }

    /// The value as an expression: `names.number(p)`, or `(p) + (q)*sqrt(d)`, over `(den)`
    /// when that is not 1, each part an expression in parentheses.
    pub fn expr(&self, names: &mut Names) -> String {
        match self.as_number() {
            Some(v) => names.number(v),
            None => {
                let sum = format!(
                    "({}) + ({})*sqrt({})",
                    names.number(&self.p),
                    names.number(&self.q),
                    names.number(&self.d)
                );
                if self.den.is_one() {
                    sum
                } else {
                    format!("({sum})/({})", names.number(&self.den))
                }
            }
        }
    }
}

/// A direction of ℝ³: exact (not unit) when its coordinates lie in a field at hand, and as a
/// unit vector in decimals.
#[derive(Clone, Debug)]
pub struct Direction {
    /// An exact direction vector, its first nonzero coordinate `±1`; `None` when only decimals
    /// are given.
    pub exact: Option<[Number; 3]>,
    /// The unit vector (decimals).
    pub unit: [f64; 3],
}

impl Direction {
    /// `v` scaled so that its first nonzero coordinate is `±1` (`+1` unless `oriented`, which
    /// keeps the orientation).
    fn of(v: [Number; 3], oriented: bool) -> Direction {
        let v = match v.iter().find(|c| !c.is_zero()).and_then(Field::inv) {
            Some(k) if oriented && k.sign() == Sign::Negative => scaled(&v, &k.neg()),
            Some(k) => scaled(&v, &k),
            None => v,
        };
        let v = plain3(&v);
        let unit = unit(v.each_ref().map(approx));
        Direction {
            exact: Some(v),
            unit,
        }
    }
}

/// A semi-axis of an ellipse or hyperbola.
#[derive(Clone, Debug)]
pub struct Axis {
    /// The squared semi-axis length.
    pub semi_axis2: Surd,
    /// Its direction.
    pub direction: Direction,
}

/// The affine shape of a real conic.
#[derive(Clone, Debug)]
pub enum ConicShape {
    /// The conic lies in the plane at infinity.
    AtInfinity,
    /// A circle.
    Circle {
        /// Its centre.
        centre: [Number; 3],
        /// The squared radius.
        radius2: Number,
    },
    /// An ellipse that is not a circle.
    Ellipse {
        /// Its centre.
        centre: [Number; 3],
        /// The major semi-axis.
        major: Axis,
        /// The minor semi-axis.
        minor: Axis,
    },
    /// A hyperbola `s²/a² − t²/b² = 1` about its centre.
    Hyperbola {
        /// Its centre.
        centre: [Number; 3],
        /// The transverse semi-axis (`a`, through the vertices).
        transverse: Axis,
        /// The conjugate semi-axis (`b`).
        conjugate: Axis,
    },
    /// A parabola.
    Parabola {
        /// Its vertex.
        vertex: [Number; 3],
        /// Its axis, pointing from the vertex into the parabola.
        axis: Direction,
        /// The squared focal length (vertex to focus).
        focal_length2: Number,
    },
}

impl ConicShape {
    /// `ellipse`, `circle`, `parabola`, `hyperbola` or `conic_at_infinity` (the names of
    /// [`super::AffineComponent::name`]).
    pub fn key(&self) -> &'static str {
        match self {
            ConicShape::AtInfinity => "conic_at_infinity",
            ConicShape::Circle { .. } => "circle",
            ConicShape::Ellipse { .. } => "ellipse",
            ConicShape::Hyperbola { .. } => "hyperbola",
            ConicShape::Parabola { .. } => "parabola",
        }
    }
}

/// A real conic in an affine chart.
#[derive(Clone, Debug)]
pub struct AffineConic {
    /// A normal of its plane (exact, scaled so its first nonzero coordinate is 1; `None` for a
    /// conic at infinity).
    pub normal: Option<[Number; 3]>,
    /// Its type, centre or vertex, axes.
    pub shape: ConicShape,
}

/// `v / |v|`.
pub(super) fn unit(v: [f64; 3]) -> [f64; 3] {
    let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if n > 0.0 {
        v.map(|c| c / n)
    } else {
        v
    }
}

pub(super) fn dot(a: &[Number; 3], b: &[Number; 3]) -> Number {
    a[0].mul(&b[0]).add(&a[1].mul(&b[1])).add(&a[2].mul(&b[2]))
}

pub(super) fn cross(a: &[Number; 3], b: &[Number; 3]) -> [Number; 3] {
    [
        a[1].mul(&b[2]).sub(&a[2].mul(&b[1])),
        a[2].mul(&b[0]).sub(&a[0].mul(&b[2])),
        a[0].mul(&b[1]).sub(&a[1].mul(&b[0])),
    ]
}

pub(super) fn scaled(v: &[Number; 3], k: &Number) -> [Number; 3] {
    v.each_ref().map(|c| c.mul(k))
}

fn combine(a: &Number, u: &[Number; 3], b: &Number, v: &[Number; 3]) -> [Number; 3] {
    std::array::from_fn(|i| a.mul(&u[i]).add(&b.mul(&v[i])))
}

pub(super) fn int(v: i64) -> Number {
    Number::from_int(&v.into())
}

pub(super) fn div(a: &Number, b: &Number) -> Result<Number, Error> {
    a.div(b)
        .ok_or_else(|| Error::Algebra("affine conic: division by zero".into()))
}

/// `v` without its field when it is rational (so that rational outputs of conics made in
/// different fields combine).
pub(super) fn plain(v: &Number) -> Number {
    if v.numerator().len() <= 1 {
        Number::rational(constant(v))
    } else {
        v.clone()
    }
}

pub(super) fn plain3(v: &[Number; 3]) -> [Number; 3] {
    v.each_ref().map(plain)
}

/// `C(Y, Z)` for `C = Y₀Y₂ − Y₁²`.
fn conic_form(y: &[Number; 3], z: &[Number; 3]) -> Number {
    let half = Number::rational(RBig::from_parts(1.into(), 2u8.into()));
    y[0].mul(&z[2])
        .add(&y[2].mul(&z[0]))
        .mul(&half)
        .sub(&y[1].mul(&z[1]))
}

/// `v` scaled so that its first nonzero coordinate is 1.
pub(super) fn normalized(v: [Number; 3]) -> Option<[Number; 3]> {
    let k = v.iter().find(|c| !c.is_zero())?.inv()?;
    Some(scaled(&v, &k))
}

/// The affine data of the real conic `X(u)` (degree 2) in `chart`, from the parameterization
/// alone (module documentation): the reference [`affine_conic`]'s plane-section route is held
/// equal to, and the route of a conic without its section.
pub fn param_conic(x: &[NumberPoly; 4], chart: &Chart) -> Result<AffineConic, Error> {
    // the coefficient vectors x₀, x₁, x₂ in chart coordinates
    let xs: [Point; 3] = std::array::from_fn(|k| {
        let p: Point = std::array::from_fn(|i| x[i].coeff(k));
        chart.to_chart_number(&p)
    });
    let l: [Number; 3] = std::array::from_fn(|k| xs[k][3].clone());
    let xyz = |k: usize| -> [Number; 3] { std::array::from_fn(|i| xs[k][i].clone()) };
    let image = |y: &[Number; 3]| -> [Number; 3] {
        std::array::from_fn(|i| (0..3).fold(Number::zero(), |acc, k| acc.add(&y[k].mul(&xs[k][i]))))
    };
    let Some((za, zb)) = at_infinity_basis(&l) else {
        return Ok(AffineConic {
            normal: None,
            shape: ConicShape::AtInfinity,
        });
    };
    let (va, vb) = (image(&za), image(&zb));
    let normal = normalized(cross(&va, &vb))
        .ok_or_else(|| Error::Algebra("affine conic: a degenerate parameterization".into()))?;
    let delta = l[1].mul(&l[1]).sub(&int(4).mul(&l[0]).mul(&l[2]));
    let shape = match delta.sign() {
        Sign::Zero => parabola(&xyz(0), &xyz(1), &xyz(2), &l)?,
        s => {
            // the centre: 2w₂x₀ − w₁x₁ + 2w₀x₂ over its w′ = −Δ
            let yc = [int(2).mul(&l[2]), l[1].neg(), int(2).mul(&l[0])];
            let w = div(&int(-1), &delta)?;
            let centre = scaled(&image(&yc), &w);
            let kappa = div(&int(1), &delta)?;
            let f = [
                conic_form(&za, &za),
                conic_form(&za, &zb),
                conic_form(&zb, &zb),
            ];
            let g = [dot(&va, &va), dot(&va, &vb), dot(&vb, &vb)];
            central(
                centre,
                s == Sign::Positive,
                &f,
                &g,
                [&kappa, &delta],
                &va,
                &vb,
            )?
        }
    };
    Ok(AffineConic {
        normal: Some(plain3(&normal)),
        shape,
    })
}

/// A basis `Z_a`, `Z_b` of the directions `ℓ·Z = 0` (entries of `ℓ` only), `None` for `ℓ = 0`.
pub(super) fn at_infinity_basis(l: &[Number; 3]) -> Option<([Number; 3], [Number; 3])> {
    let k = (0..3).find(|&k| !l[k].is_zero())?;
    let (i, j) = match k {
        0 => (1, 2),
        1 => (0, 2),
        _ => (0, 1),
    };
    let basis = |i: usize| -> [Number; 3] {
        let mut z = [Number::zero(), Number::zero(), Number::zero()];
        z[i] = l[k].clone();
        z[k] = l[i].neg();
        z
    };
    Some((basis(i), basis(j)))
}

/// The parabola `X(u)` (chart coordinates `x₀ + x₁u + x₂u²`, `w′ = W(u)` with a double root).
pub(super) fn parabola(
    x0: &[Number; 3],
    x1: &[Number; 3],
    x2: &[Number; 3],
    l: &[Number; 3],
) -> Result<ConicShape, Error> {
    // a + bt + dt²: the root of W moved to t = ∞
    let (a, b, d) = if l[2].is_zero() {
        let s = div(&int(1), &l[0])?;
        (scaled(x0, &s), scaled(x1, &s), scaled(x2, &s))
    } else {
        let u0 = div(&l[1].neg(), &int(2).mul(&l[2]))?;
        let s = div(&int(1), &l[2])?;
        let at_u0: [Number; 3] =
            std::array::from_fn(|i| x0[i].add(&u0.mul(&x1[i])).add(&u0.mul(&u0).mul(&x2[i])));
        let b: [Number; 3] = std::array::from_fn(|i| x1[i].add(&int(2).mul(&u0).mul(&x2[i])));
        (scaled(x2, &s), scaled(&b, &s), scaled(&at_u0, &s))
    };
    let dd = dot(&d, &d);
    let bd = dot(&b, &d);
    let t = div(&bd.neg(), &int(2).mul(&dd))?;
    let vertex = std::array::from_fn(|i| a[i].add(&t.mul(&b[i])).add(&t.mul(&t).mul(&d[i])));
    // |b⊥|² = b·b − (b·d)²/(d·d)
    let bperp2 = dot(&b, &b).sub(&div(&bd.mul(&bd), &dd)?);
    let focal_length2 = div(&bperp2.mul(&bperp2), &int(16).mul(&dd))?;
    Ok(ConicShape::Parabola {
        vertex: plain3(&vertex),
        axis: Direction::of(d, true),
        focal_length2: plain(&focal_length2),
    })
}

/// The squared semi-axes `μ` of [`central`]: in the field (`√D`, and `p`, `c` of
/// `μ = p ± c·√D`), or over a denominator (`p`, `D`, `den` of `μ = (p ± √D)/den`).
enum Mu<'a> {
    InField(&'a Number, (Number, Number)),
    Over(Number, Number, Number),
}

/// An ellipse (`hyperbola = false`) or hyperbola about `centre`: `ZᵀFZ = κ` in the basis
/// `v_a`, `v_b` of the plane's directions, whose Gram matrix is `G` (`[11, 12, 22]`).
pub(super) fn central(
    centre: [Number; 3],
    hyperbola: bool,
    f: &[Number; 3],
    g: &[Number; 3],
    [kappa, delta]: [&Number; 2],
    va: &[Number; 3],
    vb: &[Number; 3],
) -> Result<ConicShape, Error> {
    // over ℚ: plain rationals (no field attached), so ℚ(√D) can hold the axes
    let rational = [&centre, va, vb, f, g]
        .into_iter()
        .flatten()
        .chain([kappa])
        .all(|v| v.numerator().len() <= 1);
    let (centre, va, vb, f, g, kappa) = (
        plain3(&centre),
        plain3(va),
        plain3(vb),
        plain3(f),
        plain3(g),
        plain(kappa),
    );
    let (va, vb, f, g, kappa) = (&va, &vb, &f, &g, &kappa);
    let det_f = f[0].mul(&f[2]).sub(&f[1].mul(&f[1]));
    let det_g = g[0].mul(&g[2]).sub(&g[1].mul(&g[1]));
    let tau = f[0]
        .mul(&g[2])
        .add(&f[2].mul(&g[0]))
        .sub(&int(2).mul(&f[1]).mul(&g[1]));
    let disc = tau.mul(&tau).sub(&int(4).mul(&det_f).mul(&det_g));
    // μ = p ± c·√D, p = κτ/(2 det F), c = |κ/(2 det F)|; κ = 1/Δ
    let two_det_f = int(2).mul(&det_f);
    let p_c = || -> Result<(Number, Number), Error> {
        let p = div(&kappa.mul(&tau), &two_det_f)?;
        let c = div(kappa, &two_det_f)?;
        Ok(if c.sign() == Sign::Negative {
            (p, c.neg())
        } else {
            (p, c)
        })
    };
    if disc.is_zero() {
        let (p, _) = p_c()?;
        if hyperbola {
            return Err(Error::Algebra("affine conic: a circular hyperbola".into()));
        }
        return Ok(ConicShape::Circle {
            centre: plain3(&centre),
            radius2: plain(&p),
        });
    }
    // √D: rational, or in ℚ(√D) when the conic is rational, else kept symbolic
    let root: Option<Number> = if rational {
        let s = Quadratic::sqrt_rational(&constant(&disc));
        Some(match s.as_rational() {
            Some(r) => Number::rational(r.clone()),
            None => from_quadratic(&s, Some(&sqrt_field(s.radicand()))),
        })
    } else if disc.numerator().len() <= 1 {
        // a rational D that is a square keeps everything in K
        Quadratic::sqrt_rational(&constant(&disc))
            .as_rational()
            .map(|r| Number::rational(r.clone()))
    } else {
        None
    };
    // in K: μ = p ± c·√D; else μ = (sτ ± √D)/|2Δ det F|, s the sign of 2Δ det F (no
    // inverse in K), its parts made once for both axes
    let form = match &root {
        Some(r) => Mu::InField(r, p_c()?),
        None => {
            let den = two_det_f.mul(&plain(delta));
            let s = int(if den.sign() == Sign::Negative { -1 } else { 1 });
            Mu::Over(plain(&s.mul(&tau)), plain(&disc), plain(&s.mul(&den)))
        }
    };
    let axis = |sign: i64| -> Result<Axis, Error> {
        let (mu, semi): (Option<Number>, Surd) = match &form {
            Mu::InField(r, (p, c)) => {
                let mu = p.add(&int(sign).mul(c).mul(r));
                (Some(mu.clone()), Surd::number(plain(&mu)))
            }
            Mu::Over(p, d, den) => (
                None,
                Surd {
                    p: p.clone(),
                    q: int(sign),
                    d: d.clone(),
                    den: den.clone(),
                },
            ),
        };
        let direction = match mu {
            Some(mu) => {
                // the kernel of μF − κG
                let m = |r: usize| mu.mul(&f[r]).sub(&kappa.mul(&g[r]));
                let (m11, m12, m22) = (m(0), m(1), m(2));
                let (za, zb) = if m11.is_zero() && m12.is_zero() {
                    (m22.neg(), m12)
                } else {
                    (m12.neg(), m11)
                };
                Direction::of(combine(&za, va, &zb, vb), false)
            }
            None => Direction {
                exact: None,
                unit: float_axis(f, kappa, va, vb, semi.to_f64()),
            },
        };
        Ok(Axis {
            semi_axis2: semi,
            direction,
        })
    };
    let (larger, smaller) = (axis(1)?, axis(-1)?);
    let centre = plain3(&centre);
    Ok(if hyperbola {
        // μ₋ < 0 < μ₊: the conjugate semi-axis² is −μ₋
        let Axis {
            semi_axis2: s,
            direction,
        } = smaller;
        let conjugate = Axis {
            semi_axis2: s.neg(),
            direction,
        };
        ConicShape::Hyperbola {
            centre,
            transverse: larger,
            conjugate,
        }
    } else {
        ConicShape::Ellipse {
            centre,
            major: larger,
            minor: smaller,
        }
    })
}

/// The unit axis of semi-axis² `μ` in decimals (display only): `v_a`, `v_b` made
/// orthonormal, the form `ZᵀFZ` in that basis a symmetric `S`, whose eigenvector for the
/// eigenvalue nearest `κ/μ` is taken from the stable angle `½·atan2(2s₁₂, s₁₁ − s₂₂)`.
fn float_axis(
    f: &[Number; 3],
    kappa: &Number,
    va: &[Number; 3],
    vb: &[Number; 3],
    mu: f64,
) -> [f64; 3] {
    let (va, vb) = (va.each_ref().map(approx), vb.each_ref().map(approx));
    let d = |x: &[f64; 3], y: &[f64; 3]| x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
    let a11 = d(&va, &va).sqrt();
    let e1 = va.map(|c| c / a11);
    let a21 = d(&vb, &e1);
    let rest: [f64; 3] = std::array::from_fn(|i| vb[i] - a21 * e1[i]);
    let a22 = d(&rest, &rest).sqrt();
    let e2 = rest.map(|c| c / a22);
    // Z = T·s, T = [[1/a11, −a21/(a11·a22)], [0, 1/a22]]
    let t = [[1.0 / a11, -a21 / (a11 * a22)], [0.0, 1.0 / a22]];
    let fm = [
        [approx(&f[0]), approx(&f[1])],
        [approx(&f[1]), approx(&f[2])],
    ];
    let sm: [[f64; 2]; 2] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let mut acc = 0.0;
            for k in 0..2 {
                for l in 0..2 {
                    acc += t[k][i] * fm[k][l] * t[l][j];
                }
            }
            acc
        })
    });
    let phi = 0.5 * (2.0 * sm[0][1]).atan2(sm[0][0] - sm[1][1]);
    let half = 0.5 * (sm[0][0] - sm[1][1]);
    let r = (half * half + sm[0][1] * sm[0][1]).sqrt();
    let (big, small) = (
        0.5 * (sm[0][0] + sm[1][1]) + r,
        0.5 * (sm[0][0] + sm[1][1]) - r,
    );
    let lambda = approx(kappa) / mu;
    let (c, s) = if (lambda - big).abs() <= (lambda - small).abs() {
        (phi.cos(), phi.sin())
    } else {
        (-phi.sin(), phi.cos())
    };
    unit(std::array::from_fn(|i| c * e1[i] + s * e2[i]))
}

/// A decimal value of `v` good to about 16 digits even when its representative has large
/// cancelling coefficients: the representative at a rational within `2⁻²⁰⁰` of `α`, exactly,
/// then rounded (display only; [`Number::to_f64`] uses `2⁻⁶⁴`).
pub fn approx(v: &Number) -> f64 {
    near(v).to_f64().value()
}

/// `v` exactly, or its representative at a rational point within `2⁻²⁰⁰` of `α`.
fn near(v: &Number) -> RBig {
    match v.field().filter(|_| v.numerator().len() > 1) {
        None => constant(v),
        Some(field) => {
            let width = RBig::from_parts_signed(1.into(), IBig::ONE << 200);
            let iv = field.alpha().refined_interval(&width);
            let mid = (iv.lo() + iv.hi()) / RBig::from(2);
            v.representative().eval(&mid)
        }
    }
}

/// The rational value of an element with a constant numerator.
pub(super) fn constant(c: &Number) -> RBig {
    c.numerator()
        .first()
        .map_or(RBig::ZERO, |v| RBig::from(v.clone()))
        / RBig::from(c.denominator().clone())
}
