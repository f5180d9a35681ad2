//! The two quadrics near a piece of their curve, in floats for the construction and exactly
//! for the certificate ([`super::certify`]).
//!
//! Coordinates are local: `y = x − O` for a float origin `O` on the piece (an exact dyadic
//! point), and the matrices are translated exactly, `M_O = TᵀMT` with `x̃ = Tỹ`, before they
//! become floats (scaled by their largest entry). A piece 10⁻⁵ across, 10⁵ from the origin,
//! is then computed at its own scale.
//!
//! **Derivatives along the curve.** Near a smooth point `p` where the surfaces cross, take the
//! parameter `t = c·(x − p)` along a unit vector `c` with `c·T ≠ 0` (`T` the tangent). On the
//! curve `f(x(t)) = g(x(t)) = 0` and `c·x(t) = c·p + t`; as `∇f` is affine in `x` with
//! Hessian `H = 2M₃`, the `k`-th derivative of `f(x(t))` is
//! `∇f·x⁽ᵏ⁾ + Σ_{j=1}^{k−1} C(k−1, j)(Hx⁽ʲ⁾)·x⁽ᵏ⁻ʲ⁾ = 0`. So every derivative solves one
//! linear system with the matrix `J = [∇f; ∇g; c]`: `Jx′ = (0, 0, 1)`, and for `k ≥ 2`
//! `Jx⁽ᵏ⁾ = (−Σ…, −Σ…, 0)` ([`Pair::derivatives`]). No parameterization and no `√s` are
//! involved, and the same holds for every real smooth piece.
//!
//! Points are moved onto the curve by Gauss–Newton with the least-norm step on `(f, g)`
//! ([`Pair::polish`]); a point between two, on the plane halfway along the chord, by Newton on
//! `(f, g, c·(x − p) − L/2)` ([`Pair::midpoint`]). These floats only build the curve: its
//! distance to the surfaces is proved afterwards, exactly.

use super::certify::ExactQuadric;
use crate::quadric::Quadric;
use qsic_algebra::RBig;

/// A 3-vector of floats.
pub(super) type V3 = [f64; 3];

pub(super) fn dot(a: &V3, b: &V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(super) fn sub(a: &V3, b: &V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(super) fn add_scaled(a: &V3, k: f64, b: &V3) -> V3 {
    [a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2]]
}

pub(super) fn norm(a: &V3) -> f64 {
    dot(a, a).sqrt()
}

fn cross(a: &V3, b: &V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The solution of `[r₀; r₁; r₂]·x = b` (rows), by Cramer's rule; `None` when singular.
fn solve(rows: &[V3; 3], b: &V3) -> Option<V3> {
    let c12 = cross(&rows[1], &rows[2]);
    let det = dot(&rows[0], &c12);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    // the inverse's columns are the cross products of the rows, over det
    let c20 = cross(&rows[2], &rows[0]);
    let c01 = cross(&rows[0], &rows[1]);
    let x: V3 = std::array::from_fn(|i| (c12[i] * b[0] + c20[i] * b[1] + c01[i] * b[2]) / det);
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// One quadric in local coordinates, in floats: `f(y) = ỹᵀMỹ`.
#[derive(Clone, Debug)]
struct FloatQuadric {
    m: [[f64; 4]; 4],
}

impl FloatQuadric {
    fn value(&self, y: &V3) -> f64 {
        let v = [y[0], y[1], y[2], 1.0];
        let mut s = 0.0;
        for i in 0..4 {
            for j in 0..4 {
                s += v[i] * self.m[i][j] * v[j];
            }
        }
        s
    }

    fn gradient(&self, y: &V3) -> V3 {
        std::array::from_fn(|i| {
            2.0 * (self.m[i][0] * y[0] + self.m[i][1] * y[1] + self.m[i][2] * y[2] + self.m[i][3])
        })
    }

    /// `H·v = 2M₃v`.
    fn hessian(&self, v: &V3) -> V3 {
        std::array::from_fn(|i| {
            2.0 * (self.m[i][0] * v[0] + self.m[i][1] * v[1] + self.m[i][2] * v[2])
        })
    }
}

/// The exact matrix of `q` in the coordinates `y = x − origin`.
fn translated(q: &Quadric, origin: &V3) -> [[RBig; 4]; 4] {
    let m = q.matrix();
    let o: [RBig; 3] = origin.map(|v| RBig::try_from(v).expect("a finite origin"));
    let mut out = m.clone();
    // column 3: M₃O + m, then row 3 by symmetry; the corner Oᵀ M₃ O + 2 m·O + m₃₃
    let col: [RBig; 3] =
        std::array::from_fn(|i| (0..3).fold(m[i][3].clone(), |s, k| s + &m[i][k] * &o[k]));
    let mut corner = m[3][3].clone();
    for i in 0..3 {
        corner += &o[i] * (&col[i] + &m[i][3]);
    }
    for i in 0..3 {
        out[i][3] = col[i].clone();
        out[3][i] = col[i].clone();
    }
    out[3][3] = corner;
    out
}

/// A double plane `k·ℓℓᵀ` (rank 1) as its plane: the matrix with zero quadratic part whose
/// form is `ℓ·x̃` (`f = ℓ` vanishes to first order there, so distances and derivatives come
/// from `ℓ`); any other matrix as it is.
fn plane_of_double_plane(m: [[RBig; 4]; 4]) -> [[RBig; 4]; 4] {
    let Some(r) = (0..4).find(|&r| m[r][r] != RBig::ZERO) else {
        return m;
    };
    let rank_one = (0..4).all(|i| (0..4).all(|j| &m[i][j] * &m[r][r] == &m[r][i] * &m[r][j]));
    if !rank_one {
        return m;
    }
    let mut out: [[RBig; 4]; 4] = Default::default();
    let half = RBig::ONE / RBig::from(2);
    for i in 0..3 {
        out[i][3] = &m[r][i] * &half;
        out[3][i] = out[i][3].clone();
    }
    out[3][3] = m[r][3].clone();
    out
}

/// The two quadrics around one piece: floats for the construction, exact for the bound.
#[derive(Clone, Debug)]
pub(super) struct Pair {
    /// The local origin (exact as a dyadic).
    pub origin: V3,
    float: [FloatQuadric; 2],
    /// The exact quadrics in local coordinates.
    pub exact: [ExactQuadric; 2],
}

/// A point's derivatives along the curve, and how many of them hold.
#[derive(Clone, Copy, Debug)]
pub(super) struct Jet {
    /// `x, x′, x″, x‴` in the chord parameter.
    pub d: [V3; 4],
    /// The derivatives computed (`0`: the position only, where the surfaces are tangent).
    pub order: usize,
}

impl Pair {
    /// The quadrics `a`, `b` around `origin` (a finite float point).
    pub(super) fn new(a: &Quadric, b: &Quadric, origin: V3) -> Pair {
        let ma = plane_of_double_plane(translated(a, &origin));
        let mb = plane_of_double_plane(translated(b, &origin));
        let float = |m: &[[RBig; 4]; 4]| -> FloatQuadric {
            let big = m
                .iter()
                .flatten()
                .map(|v| {
                    if *v < RBig::ZERO {
                        -v.clone()
                    } else {
                        v.clone()
                    }
                })
                .max()
                .unwrap_or(RBig::ONE);
            let big = if big == RBig::ZERO { RBig::ONE } else { big };
            FloatQuadric {
                m: std::array::from_fn(|i| {
                    std::array::from_fn(|j| (&m[i][j] / &big).to_f64().value())
                }),
            }
        };
        Pair {
            origin,
            float: [float(&ma), float(&mb)],
            exact: [ExactQuadric::new(&ma), ExactQuadric::new(&mb)],
        }
    }

    /// The residuals `(f, g)` at `y` (matrices scaled to a largest entry 1).
    pub(super) fn residuals(&self, y: &V3) -> [f64; 2] {
        [self.float[0].value(y), self.float[1].value(y)]
    }

    /// `y` moved onto the curve: at most 6 Gauss–Newton steps `−J⁺(f, g)`, `J = [∇f; ∇g]`,
    /// stopped once a step is below `2⁻⁵⁰` of `scale`; `y` itself where the gradients are
    /// parallel.
    pub(super) fn polish(&self, y: &V3, scale: f64) -> V3 {
        let mut y = *y;
        for _ in 0..6 {
            let r = self.residuals(&y);
            let (g0, g1) = (self.float[0].gradient(&y), self.float[1].gradient(&y));
            // least norm: Δ = −Jᵀ(JJᵀ)⁻¹r
            let (a, b, d) = (dot(&g0, &g0), dot(&g0, &g1), dot(&g1, &g1));
            let det = a * d - b * b;
            if det.is_nan() || det <= 1e-24 * a * d {
                return y;
            }
            let l0 = (d * r[0] - b * r[1]) / det;
            let l1 = (a * r[1] - b * r[0]) / det;
            let step: V3 = std::array::from_fn(|i| -(l0 * g0[i] + l1 * g1[i]));
            if !step.iter().all(|v| v.is_finite()) {
                return y;
            }
            y = add_scaled(&y, 1.0, &step);
            if norm(&step) <= scale * f64::EPSILON * f64::EPSILON.sqrt() {
                break;
            }
        }
        y
    }

    /// The derivatives at `y` in the parameter `t = c·(x − y)` (module docs), as many as
    /// hold: none where the surfaces are nearly tangent (`sin∠(∇f, ∇g) < 10⁻⁶`), and `None`
    /// where the curve runs within 60° of across `c` (`|x′| > 2`), where a segment along `c`
    /// would be no graph.
    pub(super) fn derivatives(&self, y: &V3, c: &V3) -> Option<Jet> {
        let (f, g) = (&self.float[0], &self.float[1]);
        let (gf, gg) = (f.gradient(y), g.gradient(y));
        let mut d = [*y, [0.0; 3], [0.0; 3], [0.0; 3]];
        let across = norm(&cross(&gf, &gg));
        if across.is_nan() || across <= 1e-6 * norm(&gf) * norm(&gg) {
            return Some(Jet { d, order: 0 });
        }
        let rows = [gf, gg, *c];
        d[1] = solve(&rows, &[0.0, 0.0, 1.0])?;
        if norm(&d[1]) > 2.0 {
            return None;
        }
        let (h1f, h1g) = (f.hessian(&d[1]), g.hessian(&d[1]));
        d[2] = solve(&rows, &[-dot(&h1f, &d[1]), -dot(&h1g, &d[1]), 0.0])?;
        d[3] = solve(
            &rows,
            &[-3.0 * dot(&h1f, &d[2]), -3.0 * dot(&h1g, &d[2]), 0.0],
        )?;
        Some(Jet { d, order: 3 })
    }

    /// The unit tangent `∇f × ∇g` at `y`, `None` where the surfaces are tangent.
    pub(super) fn tangent(&self, y: &V3) -> Option<V3> {
        let t = cross(&self.float[0].gradient(y), &self.float[1].gradient(y));
        let n = norm(&t);
        (n > 0.0 && n.is_finite()).then(|| t.map(|v| v / n))
    }

    /// The point of the curve on the plane `c·(x − p) = offset` (`c` a unit vector), by
    /// Newton from `guess` (at most 12 steps, converged when a step is below `10⁻¹³` of
    /// `|offset|` or within the rounding of `y`); `None` when it does not converge.
    pub(super) fn on_plane(&self, p: &V3, c: &V3, offset: f64, guess: &V3) -> Option<V3> {
        let mut y = *guess;
        for _ in 0..12 {
            let r = self.residuals(&y);
            let rows = [self.float[0].gradient(&y), self.float[1].gradient(&y), *c];
            let h = dot(c, &sub(&y, p)) - offset;
            let step = solve(&rows, &[-r[0], -r[1], -h])?;
            y = add_scaled(&y, 1.0, &step);
            if norm(&step) <= offset.abs() * 1e-13 + 8.0 * f64::EPSILON * norm(&y) {
                return Some(self.polish(&y, offset.abs()));
            }
        }
        None
    }

    /// The point of the curve on the plane halfway along the chord from `p` to `q`
    /// ([`Self::on_plane`] from `guess`); `None` when there is none near or it lands farther
    /// from `p` or `q` than they are apart.
    pub(super) fn midpoint(&self, p: &V3, q: &V3, guess: &V3) -> Option<V3> {
        let chord = sub(q, p);
        let len = norm(&chord);
        if len.is_nan() || len <= 0.0 {
            return None;
        }
        let c = chord.map(|v| v / len);
        let y = self.on_plane(p, &c, len / 2.0, guess)?;
        (norm(&sub(&y, p)) < len && norm(&sub(&y, q)) < len).then_some(y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::parse_quadric;

    /// The circle `x² + y² = 4, z = 1` of a sphere and a plane, far from the origin: its
    /// derivatives in the chord parameter are those of the circle, computed at its own scale.
    #[test]
    fn derivatives_of_a_circle_far_away() {
        // centre (1e5, 0, 1), radius 1e-5
        let a = parse_quadric("(x-100000)^2+y^2+(z-1)^2-1/10000000000").unwrap();
        let b = parse_quadric("z-1").unwrap();
        let origin = [1e5, 0.0, 1.0];
        let pair = Pair::new(&a, &b, origin);
        let r = 1e-5;
        // the point at angle 0, the parameter along c = (0, 1, 0): x = (r cos θ, r sin θ)
        // with t = r sin θ, so x(t) = √(r² − t²): x′ = 0, x″ = −1/r, x‴ = 0 at t = 0
        let y = pair.polish(&[r * (1.0 + 1e-6), 1e-12, 0.0], r);
        assert!((y[0] - r).abs() < 1e-18, "{y:?}");
        let jet = pair.derivatives(&y, &[0.0, 1.0, 0.0]).expect("a graph");
        assert_eq!(jet.order, 3);
        assert!((jet.d[1][1] - 1.0).abs() < 1e-9 && jet.d[1][0].abs() < 1e-6);
        assert!((jet.d[2][0] + 1.0 / r).abs() < 1e-6 / r, "{:?}", jet.d[2]);
        assert!(jet.d[3][0].abs() < 1e-3 / (r * r), "{:?}", jet.d[3]);
        // halfway to the point at 90°
        let q = pair.polish(&[0.0, r, 0.0], r);
        let m = pair
            .midpoint(&y, &q, &[r * 0.7, r * 0.7, 0.0])
            .expect("a midpoint");
        let half = (y[1].atan2(y[0]) + std::f64::consts::FRAC_PI_2) / 2.0;
        let want = [r * half.cos(), r * half.sin()];
        assert!(
            (m[0] - want[0]).abs() < 1e-13 * r && (m[1] - want[1]).abs() < 1e-13 * r,
            "{m:?}"
        );
        // across the chord: no graph
        assert!(pair.derivatives(&y, &[1.0, 0.0, 0.0]).is_none());
    }

    /// A sphere and a plane tangent at a point: position only there.
    #[test]
    fn tangent_surfaces_give_the_position_only() {
        let a = parse_quadric("x^2+y^2+z^2-1").unwrap();
        let b = parse_quadric("z-1").unwrap();
        let pair = Pair::new(&a, &b, [0.0, 0.0, 0.5]);
        let jet = pair
            .derivatives(&[0.0, 0.0, 0.5], &[1.0, 0.0, 0.0])
            .unwrap();
        assert_eq!(jet.order, 0);
    }

    /// A plane given as a double plane is read as its plane: the gradient is its normal.
    #[test]
    fn a_double_plane_is_its_plane() {
        let a = parse_quadric("x^2+y^2+z^2-1").unwrap();
        let b = parse_quadric("2*x-z+3").unwrap();
        let pair = Pair::new(&a, &b, [0.5, 0.0, 0.0]);
        let g = pair.float[1].gradient(&[1.0, 2.0, 3.0]);
        assert!((g[0] / g[2] + 2.0).abs() < 1e-15 && g[1] == 0.0, "{g:?}");
        // the value at the local point (0, 0, 0), i.e. x = (0.5, 0, 0): 2·0.5 + 3 = 4
        let f = pair.float[1].value(&[0.0; 3]);
        assert!((f / g[2] + 4.0).abs() < 1e-15, "{f} {g:?}");
    }

    /// The translation is exact: the corner is the value at the origin.
    #[test]
    fn translation_is_exact() {
        let a = parse_quadric("x^2+2*y*z-3*x*w+5*w^2").unwrap();
        let o = [0.5, -0.25, 3.0];
        let m = translated(&a, &o);
        let x: [RBig; 4] = [0.5, -0.25, 3.0, 1.0].map(|v| RBig::try_from(v).unwrap());
        let mut value = RBig::ZERO;
        let am = a.matrix();
        for i in 0..4 {
            for j in 0..4 {
                value += &x[i] * &am[i][j] * &x[j];
            }
        }
        assert_eq!(m[3][3], value);
        assert_eq!(m[0][1], am[0][1]);
    }
}
