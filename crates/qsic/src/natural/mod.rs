//! Natural quadrics — planes, spheres, circular cylinders and circular cones in any
//! position — recognized exactly from their matrices, and the closed forms of their pairs.
//!
//! | item | what |
//! |---|---|
//! | [`NaturalQuadric`], [`recognize`] | the kind and the Euclidean data (centre, axis, radius, half-angle) of one quadric, or `None` |
//! | [`pair`](pair::pair) (crate) | the class and the curve in ℝ³ of a natural pair by closed forms, or `None` (the general route answers) |
//!
//! **Recognition.** With `M = [[Q, b], [bᵀ, c]]` the primitive integer matrix (plane at
//! infinity `w = 0`) and `E₁, E₂, E₃` the sums of the principal minors of `Q`:
//!
//! * a **plane** is a double plane `M = s·ℓℓᵀ` (rank 1: every 2×2 minor through a nonzero
//!   diagonal pivot `k` vanishes), `ℓ ∝` row `k`, with a nonzero normal `(ℓ₀, ℓ₁, ℓ₂)`;
//! * a **sphere** has `Q = qI`; centre `−b/q`, `r² = (|b|² − qc)/q²`, real iff `|b|² − qc > 0`;
//! * a quadric of **revolution** has a double eigenvalue `μ` of `Q`. A symmetric matrix is
//!   diagonalizable, so the eigenvalue is double iff `rank(Q − μI) = 1`. A rational cubic with
//!   a double root `μ` and a simple root `ν` has `2μ + ν = E₁`, `μ² + 2μν = E₂`, `μ²ν = E₃`,
//!   whence `μ = (E₁E₂ − 9E₃) / (2(E₁² − 3E₂))` (the denominator vanishes only for a triple
//!   root): the test is that `D·Q − N·I` (`N`, `D` that numerator and denominator) has rank 1,
//!   all integers. Its nonzero rows are multiples of the axis `a`, since
//!   `Q − μI = (ν − μ)·aaᵀ/|a|²`.
//!   * `ν = 0` (`E₃ = 0`) with `b·a = 0`: a **circular cylinder**, axis through `p = −b/μ`,
//!     `r² = (|b|² − μc)/μ²`, real iff `2|b|² − E₁c > 0` (`μ = E₁/2`);
//!   * `ν ≠ 0`, `μν < 0` and `det M = E₃c − bᵀ adj(Q) b = 0`: a **circular cone**, apex
//!     `v = −adj(Q)b/E₃`, and on `y = x − v`: `μ|y|² + (ν − μ)(y·â)² = 0`, so the half-angle
//!     has `cos²θ = μ/(μ − ν) = N/(3N − E₁D)`.
//!
//! Everything else (ellipsoids, paraboloids, imaginary or point quadrics, elliptic cylinders
//! and cones) is `None`. Cost: the 3×3 minors of `Q`, a handful of products, after a
//! machine-integer filter (`filter`: rank 1 or a repeated eigenvalue of `Q`, else not
//! natural) that turns most quadrics away without the big-integer matrix.

mod filter;
pub(crate) mod pair;

use crate::quadric::Quadric;
use crate::vocabulary::AffineCurve;
use qsic_algebra::{IBig, RBig};

/// The natural route's answer for `a` and `b`: both recognized and a closed form for the
/// pair, else `None` (the general route answers). [`crate::classify()`] takes its class
/// first, [`crate::affine::affine_view`] its curve in the default chart.
pub(crate) fn answer(a: &Quadric, b: &Quadric) -> Option<pair::PairAnswer> {
    let na = recognize(a)?;
    let nb = recognize(b)?;
    pair::pair(
        &na,
        a.integer_matrix().entries(),
        &nb,
        b.integer_matrix().entries(),
    )
}

/// The curve in ℝ³ of a natural pair by closed forms (in the default chart), or `None`.
pub(crate) fn affine_curve(a: &Quadric, b: &Quadric) -> Option<AffineCurve> {
    answer(a, b).map(|p| p.curve)
}

/// A point or a vector of ℝ³ with rational coordinates.
pub type Vec3 = [RBig; 3];

/// A natural quadric with its Euclidean data, exact. Directions are not normalized (their
/// squared length is rational, the length need not be).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NaturalQuadric {
    /// The plane `normal · x + offset = 0` (a double plane `ℓ²`).
    Plane {
        /// A normal vector (nonzero).
        normal: Vec3,
        /// The constant term.
        offset: RBig,
    },
    /// The sphere `|x − centre|² = r2`, `r2 > 0`.
    Sphere {
        /// Its centre.
        centre: Vec3,
        /// Its squared radius.
        r2: RBig,
    },
    /// The circular cylinder of points at squared distance `r2 > 0` from the axis line
    /// `point + t·axis`.
    Cylinder {
        /// A point of the axis (the one nearest the origin).
        point: Vec3,
        /// The axis direction.
        axis: Vec3,
        /// Its squared radius.
        r2: RBig,
    },
    /// The circular (double) cone with apex `apex`, axis direction `axis`, and half-angle `θ`
    /// with `cos²θ = cos2`, `0 < cos2 < 1`.
    Cone {
        /// Its apex.
        apex: Vec3,
        /// The axis direction.
        axis: Vec3,
        /// `cos²` of the half-angle.
        cos2: RBig,
    },
}

/// The natural quadric `q` is (in the default chart `w = 0`), or `None`.
///
/// ```
/// use qsic::{io::parse_quadric, natural::{recognize, NaturalQuadric}};
/// use qsic_algebra::RBig;
/// let q = parse_quadric("(x-1)^2 + (y-2)^2 - 9").unwrap();
/// match recognize(&q) {
///     Some(NaturalQuadric::Cylinder { point, r2, .. }) => {
///         assert_eq!(point, [1, 2, 0].map(RBig::from));
///         assert_eq!(r2, RBig::from(9));
///     }
///     other => panic!("{other:?}"),
/// }
/// assert!(recognize(&parse_quadric("x^2 + 2*y^2 + z^2 - 1").unwrap()).is_none());
/// ```
pub fn recognize(q: &Quadric) -> Option<NaturalQuadric> {
    if q.small_integer_matrix()
        .is_some_and(|m| !filter::may_be_natural(m))
    {
        return None;
    }
    recognize_exact(q)
}

/// [`recognize`] without the machine-integer filter: the reference.
pub(crate) fn recognize_exact(q: &Quadric) -> Option<NaturalQuadric> {
    let m = q.integer_matrix().entries();
    let block: [[&IBig; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| &m[i][j]));
    let b: [&IBig; 3] = [&m[0][3], &m[1][3], &m[2][3]];
    let c = &m[3][3];
    if let Some(plane) = double_plane(m) {
        return plane;
    }
    let diagonal_zero = block[0][1].is_zero() && block[0][2].is_zero() && block[1][2].is_zero();
    if diagonal_zero && block[0][0] == block[1][1] && block[1][1] == block[2][2] {
        return sphere(block[0][0], b, c);
    }
    revolution(&block, b, c)
}

fn rat(v: &IBig) -> RBig {
    RBig::from(v.clone())
}

fn dot(u: [&IBig; 3], v: [&IBig; 3]) -> IBig {
    u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
}

/// `Some(answer)` when `m` has rank 1 (a double plane: a natural plane, or the plane at
/// infinity counted twice, `Some(None)`); `None` otherwise.
fn double_plane(m: &[[IBig; 4]; 4]) -> Option<Option<NaturalQuadric>> {
    let k = (0..4).find(|&k| !m[k][k].is_zero())?;
    // rank 1 iff m[i][j]·m[k][k] = m[i][k]·m[k][j] for all i ≤ j (the minors through the pivot)
    for i in 0..4 {
        for j in i..4 {
            if &m[i][j] * &m[k][k] != &m[i][k] * &m[k][j] {
                return None;
            }
        }
    }
    let row = &m[k];
    if row[0].is_zero() && row[1].is_zero() && row[2].is_zero() {
        return Some(None);
    }
    Some(Some(NaturalQuadric::Plane {
        normal: [rat(&row[0]), rat(&row[1]), rat(&row[2])],
        offset: rat(&row[3]),
    }))
}

/// `Q = qI`: the sphere, when real.
fn sphere(q: &IBig, b: [&IBig; 3], c: &IBig) -> Option<NaturalQuadric> {
    if q.is_zero() {
        return None; // no quadratic part: a plane and the plane at infinity
    }
    let radicand = dot(b, b) - q * c;
    if radicand <= IBig::ZERO {
        return None; // a point (the cone x² + y² + z² = 0) or no real point
    }
    let q2 = RBig::from(q * q);
    let qr = rat(q);
    Some(NaturalQuadric::Sphere {
        centre: b.map(|v| -rat(v) / &qr),
        r2: RBig::from(radicand) / q2,
    })
}

/// A circular cylinder or cone: a double eigenvalue of `Q` (module docs).
fn revolution(q: &[[&IBig; 3]; 3], b: [&IBig; 3], c: &IBig) -> Option<NaturalQuadric> {
    let e1 = q[0][0] + q[1][1] + q[2][2];
    let minor = |i: usize, j: usize| q[i][i] * q[j][j] - q[i][j] * q[i][j];
    let e2 = minor(0, 1) + minor(0, 2) + minor(1, 2);
    // adj(Q), symmetric: cofactors
    let cof = |i: usize, j: usize| {
        let (r0, r1) = match i {
            0 => (1, 2),
            1 => (0, 2),
            _ => (0, 1),
        };
        let (c0, c1) = match j {
            0 => (1, 2),
            1 => (0, 2),
            _ => (0, 1),
        };
        let d = q[r0][c0] * q[r1][c1] - q[r0][c1] * q[r1][c0];
        if (i + j) % 2 == 0 {
            d
        } else {
            -d
        }
    };
    let adj: [[IBig; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| cof(j, i)));
    let e3 = q[0][0] * &adj[0][0] + q[0][1] * &adj[1][0] + q[0][2] * &adj[2][0];
    let n = &e1 * &e2 - IBig::from(9) * &e3;
    let d = IBig::from(2) * (&e1 * &e1 - IBig::from(3) * &e2);
    if d.is_zero() || n.is_zero() {
        return None; // a triple eigenvalue, or μ = 0 (rank Q ≤ 1)
    }
    // P = D·Q − N·I has rank 1: its nonzero rows are multiples of the axis
    let p: [[IBig; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let v = &d * q[i][j];
            if i == j {
                v - &n
            } else {
                v
            }
        })
    });
    let k = (0..3).find(|&k| !p[k][k].is_zero())?;
    for i in 0..3 {
        for j in i..3 {
            if &p[i][j] * &p[k][k] != &p[i][k] * &p[k][j] {
                return None;
            }
        }
    }
    let axis_int = [&p[k][0], &p[k][1], &p[k][2]];
    let axis = axis_int.map(rat);
    if e3.is_zero() {
        // ν = 0: μ = E₁/2; a cylinder when b ⊥ axis (else a paraboloid of revolution)
        if !dot(b, axis_int).is_zero() {
            return None;
        }
        let radicand = IBig::from(2) * dot(b, b) - &e1 * c;
        if radicand <= IBig::ZERO {
            return None;
        }
        // p = −b/μ = −2b/E₁, r² = (|b|² − μc)/μ² = 2(2|b|² − E₁c)/E₁²
        let e1r = rat(&e1);
        return Some(NaturalQuadric::Cylinder {
            point: b.map(|v| -(rat(v) * RBig::from(2)) / &e1r),
            axis,
            r2: RBig::from(IBig::from(2) * radicand) / RBig::from(&e1 * &e1),
        });
    }
    // ν·D = E₁D − 2N: a real cone needs μν < 0, i.e. N·(E₁D − 2N) < 0
    let nu_d = &e1 * &d - IBig::from(2) * &n;
    if (&n * &nu_d) >= IBig::ZERO {
        return None;
    }
    let adj_b: [IBig; 3] = std::array::from_fn(|i| dot([&adj[i][0], &adj[i][1], &adj[i][2]], b));
    if &e3 * c != dot(b, [&adj_b[0], &adj_b[1], &adj_b[2]]) {
        return None; // det M ≠ 0: a hyperboloid of revolution
    }
    let e3r = rat(&e3);
    Some(NaturalQuadric::Cone {
        apex: adj_b.map(|v| -RBig::from(v) / &e3r),
        axis,
        cos2: RBig::from(n.clone()) / RBig::from(IBig::from(3) * &n - &e1 * &d),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::parse_quadric;

    fn r(n: i64, d: i64) -> RBig {
        RBig::from(n) / RBig::from(d)
    }

    fn natural(s: &str) -> Option<NaturalQuadric> {
        recognize(&parse_quadric(s).expect("a quadric"))
    }

    /// Known data by construction, each kind once in a tilted position.
    #[test]
    fn recognizes_each_kind_with_its_data() {
        // the plane up to a factor: (normal, offset) ∝ (2, 3, −1, 5)
        let Some(NaturalQuadric::Plane { normal, offset }) = natural("2*x + 3*y - z + 5") else {
            panic!("a plane");
        };
        let f = &offset / RBig::from(5);
        assert_eq!(normal, [2, 3, -1].map(|v| RBig::from(v) * &f));
        assert_eq!(
            natural("(x-1)^2 + (y+1/2)^2 + z^2 - 2"),
            Some(NaturalQuadric::Sphere {
                centre: [r(1, 1), r(-1, 2), r(0, 1)],
                r2: RBig::from(2)
            })
        );
        // axis (1, 1, 0) through (1, 0, 0): |x − p|² − ((x − p)·a)²/2 = 3
        let Some(NaturalQuadric::Cylinder { point, axis, r2 }) =
            natural("(x-1)^2 + y^2 + z^2 - (x - 1 + y)^2/2 - 3")
        else {
            panic!("a cylinder");
        };
        assert_eq!(r2, RBig::from(3));
        assert_eq!(axis[0], axis[1]);
        assert_eq!(axis[2], RBig::ZERO);
        // the point is on the axis: (point − (1, 0, 0)) ∥ (1, 1, 0)
        assert_eq!(&point[0] - RBig::ONE, point[1].clone());
        // cone with apex (0, 0, 1), axis z, 45°: x² + y² = (z − 1)²
        let Some(NaturalQuadric::Cone { apex, axis, cos2 }) = natural("x^2 + y^2 - (z-1)^2") else {
            panic!("a cone");
        };
        assert_eq!(apex, [0, 0, 1].map(RBig::from));
        assert_eq!((&axis[0], &axis[1]), (&RBig::ZERO, &RBig::ZERO));
        assert_eq!(cos2, r(1, 2));
        // 3(x² + y²) = z²: tan²θ = 1/3, cos²θ = 3/4
        let Some(NaturalQuadric::Cone { cos2, .. }) = natural("3*x^2 + 3*y^2 - z^2") else {
            panic!("a cone");
        };
        assert_eq!(cos2, r(3, 4));
    }

    /// Quadrics that are not natural: each one fails exactly one of the tests.
    #[test]
    fn declines_what_is_not_natural() {
        for s in [
            "x^2 + 2*y^2 + z^2 - 1", // ellipsoid
            "x^2 + y^2 + z^2 + 1",   // imaginary sphere
            "x^2 + y^2 + z^2",       // point cone
            "x^2 + y^2 - z",         // paraboloid of revolution
            "x^2 + y^2 + 2*z^2 - 1", // spheroid
            "x^2 + y^2 - z^2 - 1",   // hyperboloid of revolution
            "x^2 + y^2 + 1",         // imaginary cylinder
            "x^2 + y^2",             // line pair
            "x^2 + 2*y^2 - 1",       // elliptic cylinder
            "x^2 + 2*y^2 - z^2",     // elliptic cone
            "w^2",                   // the plane at infinity twice
            "x*y",                   // plane pair
        ] {
            assert_eq!(natural(s), None, "{s}");
        }
    }
}
