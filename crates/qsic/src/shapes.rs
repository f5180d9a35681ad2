//! Quadrics of familiar shapes, built from rational parameters.
//!
//! Lengths enter squared (`r2` is the squared radius, `a2` a squared semi-axis,
//! `cos2` the squared cosine of an angle), so every coefficient stays rational.
//! Each constructor states its affine equation in `X = (x, y, z)`; the quadric is
//! that equation homogenized with `w`, with the same scale as written.
//!
//! | constructor | equation |
//! |---|---|
//! | [`sphere`] | `\|X−C\|² = r2` |
//! | [`ellipsoid`] | `Σ (Xᵢ−Cᵢ)²/a2ᵢ = 1` |
//! | [`cylinder`] | `\|v\|²\|X−P\|² − ((X−P)·v)² = r2\|v\|²` |
//! | [`elliptic_cylinder`] | `(x−x₀)²/a2 + (y−y₀)²/b2 = 1` |
//! | [`cone`] | `((X−P)·v)² = cos2 \|v\|²\|X−P\|²` |
//! | [`elliptic_cone`] | `(x−x₀)²/a2 + (y−y₀)²/b2 = (z−z₀)²` |
//! | [`elliptic_paraboloid`] | `(x−x₀)²/a2 + (y−y₀)²/b2 = z−z₀` |
//! | [`hyperbolic_paraboloid`] | `(x−x₀)²/a2 − (y−y₀)²/b2 = z−z₀` |
//! | [`hyperboloid_one_sheet`] | `(x−x₀)²/a2 + (y−y₀)²/b2 − (z−z₀)²/c2 = 1` |
//! | [`hyperboloid_two_sheets`] | `(z−z₀)²/c2 − (x−x₀)²/a2 − (y−y₀)²/b2 = 1` |
//! | [`plane_pair`] | `(n₁·X + d₁)(n₂·X + d₂) = 0` |

use crate::error::Error;
use crate::quadric::Quadric;
use dashu_ratio::RBig;

/// A point or vector of rational 3-space.
pub type Point3 = [RBig; 3];

/// Refuses a parameter that is not strictly positive.
fn positive(value: &RBig, name: &str) -> Result<(), Error> {
    if *value <= RBig::ZERO {
        return Err(Error::InvalidShape(format!(
            "{name} must be positive, got {value}"
        )));
    }
    Ok(())
}

/// Refuses squared lengths that are not all strictly positive.
fn all_positive(values: &[RBig], name: &str) -> Result<(), Error> {
    values.iter().try_for_each(|v| positive(v, name))
}

/// Refuses the zero vector.
fn nonzero(v: &Point3, name: &str) -> Result<(), Error> {
    if v.iter().all(RBig::is_zero) {
        return Err(Error::InvalidShape(format!(
            "{name} must be a nonzero vector"
        )));
    }
    Ok(())
}

fn dot(a: &Point3, b: &Point3) -> RBig {
    a.iter().zip(b).fold(RBig::ZERO, |s, (x, y)| s + x * y)
}

/// The diagonal 3×3 matrix with entries `d`.
fn diagonal(d: [RBig; 3]) -> [[RBig; 3]; 3] {
    let mut m: [[RBig; 3]; 3] = Default::default();
    for (i, v) in d.into_iter().enumerate() {
        m[i][i] = v;
    }
    m
}

/// `1/a2ᵢ` for positive `a2ᵢ`, with the given signs.
fn inverses<const K: usize>(a2: &[RBig; K], signs: [i8; K]) -> [RBig; K] {
    std::array::from_fn(|i| RBig::from(signs[i]) / &a2[i])
}

/// The quadric `YᵀMY + lin·Y + c = 0` in the shifted coordinates `Y = X − p`.
///
/// Expanded in `X`: `XᵀMX + (lin − 2Mp)·X + (pᵀMp − lin·p + c)`, homogenized.
fn shifted(p: &Point3, m: [[RBig; 3]; 3], lin: [RBig; 3], c: RBig) -> Result<Quadric, Error> {
    let two = RBig::from(2);
    let mp: [RBig; 3] = std::array::from_fn(|i| dot(&m[i], p));
    let mut a: [[RBig; 4]; 4] = Default::default();
    for i in 0..3 {
        for j in 0..3 {
            a[i][j] = m[i][j].clone();
        }
        let b = &lin[i] / &two - &mp[i];
        a[i][3] = b.clone();
        a[3][i] = b;
    }
    a[3][3] = dot(p, &mp) - dot(&lin, p) + c;
    Quadric::from_matrix(a)
}

/// The sphere `|X − center|² = r2`.
///
/// # Errors
/// [`Error::InvalidShape`] if `r2 ≤ 0`.
///
/// # Examples
/// ```
/// use dashu_ratio::RBig;
/// use qsic::shapes::sphere;
///
/// let s = sphere(&[1, 0, 0].map(RBig::from), &RBig::from(4))?;
/// assert_eq!(s.to_polynomial_string(), "x^2 - 2*x*w + y^2 + z^2 - 3*w^2");
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn sphere(center: &Point3, r2: &RBig) -> Result<Quadric, Error> {
    positive(r2, "the squared radius")?;
    let one = || RBig::ONE;
    shifted(
        center,
        diagonal([one(), one(), one()]),
        Default::default(),
        -r2,
    )
}

/// The axis-aligned ellipsoid `(x−x₀)²/a2 + (y−y₀)²/b2 + (z−z₀)²/c2 = 1`,
/// with `semi_axes2 = [a2, b2, c2]` the squared semi-axes.
///
/// # Errors
/// [`Error::InvalidShape`] if a squared semi-axis is not positive.
///
/// # Examples
/// ```
/// use dashu_ratio::RBig;
/// use qsic::shapes::ellipsoid;
///
/// let e = ellipsoid(&[0, 0, 0].map(RBig::from), &[1, 4, 9].map(RBig::from))?;
/// assert_eq!(e.to_polynomial_string(), "x^2 + 1/4*y^2 + 1/9*z^2 - w^2");
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn ellipsoid(center: &Point3, semi_axes2: &[RBig; 3]) -> Result<Quadric, Error> {
    all_positive(semi_axes2, "a squared semi-axis")?;
    let m = diagonal(inverses(semi_axes2, [1, 1, 1]));
    shifted(center, m, Default::default(), RBig::NEG_ONE)
}

/// The circular cylinder of squared radius `r2` around the line through
/// `point` with direction `direction = v`:
/// `|v|²|X−P|² − ((X−P)·v)² − r2|v|² = 0`.
///
/// This is `|v|²` times the squared distance equation, hence rational for any
/// rational direction; `v` need not be a unit vector.
///
/// # Errors
/// [`Error::InvalidShape`] if `r2 ≤ 0` or `direction` is zero.
///
/// # Examples
/// ```
/// use dashu_ratio::RBig;
/// use qsic::shapes::cylinder;
///
/// let c = cylinder(&[0, 0, 0].map(RBig::from), &[0, 0, 2].map(RBig::from), &RBig::from(1))?;
/// assert_eq!(c.to_polynomial_string(), "4*x^2 + 4*y^2 - 4*w^2");
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn cylinder(point: &Point3, direction: &Point3, r2: &RBig) -> Result<Quadric, Error> {
    positive(r2, "the squared radius")?;
    nonzero(direction, "the axis direction")?;
    let v2 = dot(direction, direction);
    let m = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let outer = &direction[i] * &direction[j];
            if i == j {
                &v2 - outer
            } else {
                -outer
            }
        })
    });
    shifted(point, m, Default::default(), -(r2 * &v2))
}

/// The elliptic cylinder `(x−x₀)²/a2 + (y−y₀)²/b2 = 1` with axis parallel to
/// `z` through `axis = (x₀, y₀)`, `semi_axes2 = [a2, b2]`.
///
/// # Errors
/// [`Error::InvalidShape`] if a squared semi-axis is not positive.
///
/// # Examples
/// ```
/// use dashu_ratio::RBig;
/// use qsic::shapes::elliptic_cylinder;
///
/// let c = elliptic_cylinder(&[0, 0].map(RBig::from), &[1, 4].map(RBig::from))?;
/// assert_eq!(c.to_polynomial_string(), "x^2 + 1/4*y^2 - w^2");
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn elliptic_cylinder(axis: &[RBig; 2], semi_axes2: &[RBig; 2]) -> Result<Quadric, Error> {
    all_positive(semi_axes2, "a squared semi-axis")?;
    let [a, b] = inverses(semi_axes2, [1, 1]);
    let p = [axis[0].clone(), axis[1].clone(), RBig::ZERO];
    shifted(
        &p,
        diagonal([a, b, RBig::ZERO]),
        Default::default(),
        RBig::NEG_ONE,
    )
}

/// The circular cone (both nappes) with apex `apex`, axis direction
/// `direction = v` and squared cosine `cos2` of the half-angle:
/// `((X−P)·v)² − cos2 |v|²|X−P|² = 0`.
///
/// # Errors
/// [`Error::InvalidShape`] if `direction` is zero or `cos2` is not strictly
/// between 0 and 1 (`cos2 = 1` would be the axis alone, `cos2 = 0` a double plane).
///
/// # Examples
/// ```
/// use dashu_ratio::RBig;
/// use qsic::shapes::cone;
///
/// // Half-angle 45°: cos² = 1/2.
/// let half = RBig::from_parts(1.into(), 2u8.into());
/// let c = cone(&[0, 0, 0].map(RBig::from), &[0, 0, 1].map(RBig::from), &half)?;
/// assert_eq!(c.to_polynomial_string(), "-1/2*x^2 - 1/2*y^2 + 1/2*z^2");
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn cone(apex: &Point3, direction: &Point3, cos2: &RBig) -> Result<Quadric, Error> {
    nonzero(direction, "the axis direction")?;
    if *cos2 <= RBig::ZERO || *cos2 >= RBig::ONE {
        return Err(Error::InvalidShape(format!(
            "the squared cosine of the half-angle must lie strictly between 0 and 1, got {cos2}"
        )));
    }
    let scaled = cos2 * dot(direction, direction);
    let m = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let outer = &direction[i] * &direction[j];
            if i == j {
                outer - &scaled
            } else {
                outer
            }
        })
    });
    shifted(apex, m, Default::default(), RBig::ZERO)
}

/// The elliptic cone `(x−x₀)²/a2 + (y−y₀)²/b2 = (z−z₀)²` with apex
/// `apex = (x₀, y₀, z₀)` and axis parallel to `z`, `semi_axes2 = [a2, b2]`
/// (the squared semi-axes of its section at height 1).
///
/// # Errors
/// [`Error::InvalidShape`] if a squared semi-axis is not positive.
///
/// # Examples
/// ```
/// use dashu_ratio::RBig;
/// use qsic::shapes::elliptic_cone;
///
/// let c = elliptic_cone(&[0, 0, 0].map(RBig::from), &[1, 1].map(RBig::from))?;
/// assert_eq!(c.to_polynomial_string(), "x^2 + y^2 - z^2");
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn elliptic_cone(apex: &Point3, semi_axes2: &[RBig; 2]) -> Result<Quadric, Error> {
    all_positive(semi_axes2, "a squared semi-axis")?;
    let [a, b] = inverses(semi_axes2, [1, 1]);
    shifted(
        apex,
        diagonal([a, b, RBig::NEG_ONE]),
        Default::default(),
        RBig::ZERO,
    )
}

/// The elliptic paraboloid `(x−x₀)²/a2 + (y−y₀)²/b2 = z−z₀` with vertex
/// `vertex = (x₀, y₀, z₀)`, opening towards `+z`, `semi_axes2 = [a2, b2]`.
///
/// # Errors
/// [`Error::InvalidShape`] if `a2` or `b2` is not positive.
///
/// # Examples
/// ```
/// use dashu_ratio::RBig;
/// use qsic::shapes::elliptic_paraboloid;
///
/// let p = elliptic_paraboloid(&[0, 0, 0].map(RBig::from), &[1, 1].map(RBig::from))?;
/// assert_eq!(p.to_polynomial_string(), "x^2 + y^2 - z*w");
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn elliptic_paraboloid(vertex: &Point3, semi_axes2: &[RBig; 2]) -> Result<Quadric, Error> {
    all_positive(semi_axes2, "a squared semi-axis")?;
    let [a, b] = inverses(semi_axes2, [1, 1]);
    let lin = [RBig::ZERO, RBig::ZERO, RBig::NEG_ONE];
    shifted(vertex, diagonal([a, b, RBig::ZERO]), lin, RBig::ZERO)
}

/// The hyperbolic paraboloid (saddle) `(x−x₀)²/a2 − (y−y₀)²/b2 = z−z₀` with
/// saddle point `vertex = (x₀, y₀, z₀)`, `semi_axes2 = [a2, b2]`.
///
/// # Errors
/// [`Error::InvalidShape`] if `a2` or `b2` is not positive.
///
/// # Examples
/// ```
/// use dashu_ratio::RBig;
/// use qsic::shapes::hyperbolic_paraboloid;
///
/// let p = hyperbolic_paraboloid(&[0, 0, 0].map(RBig::from), &[1, 1].map(RBig::from))?;
/// assert_eq!(p.to_polynomial_string(), "x^2 - y^2 - z*w");
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn hyperbolic_paraboloid(vertex: &Point3, semi_axes2: &[RBig; 2]) -> Result<Quadric, Error> {
    all_positive(semi_axes2, "a squared semi-axis")?;
    let [a, b] = inverses(semi_axes2, [1, -1]);
    let lin = [RBig::ZERO, RBig::ZERO, RBig::NEG_ONE];
    shifted(vertex, diagonal([a, b, RBig::ZERO]), lin, RBig::ZERO)
}

/// The hyperboloid of one sheet `(x−x₀)²/a2 + (y−y₀)²/b2 − (z−z₀)²/c2 = 1`,
/// axis parallel to `z`, `semi_axes2 = [a2, b2, c2]`.
///
/// # Errors
/// [`Error::InvalidShape`] if a squared semi-axis is not positive.
///
/// # Examples
/// ```
/// use dashu_ratio::RBig;
/// use qsic::shapes::hyperboloid_one_sheet;
///
/// let h = hyperboloid_one_sheet(&[0, 0, 0].map(RBig::from), &[1, 1, 1].map(RBig::from))?;
/// assert_eq!(h.to_polynomial_string(), "x^2 + y^2 - z^2 - w^2");
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn hyperboloid_one_sheet(center: &Point3, semi_axes2: &[RBig; 3]) -> Result<Quadric, Error> {
    all_positive(semi_axes2, "a squared semi-axis")?;
    let m = diagonal(inverses(semi_axes2, [1, 1, -1]));
    shifted(center, m, Default::default(), RBig::NEG_ONE)
}

/// The hyperboloid of two sheets `(z−z₀)²/c2 − (x−x₀)²/a2 − (y−y₀)²/b2 = 1`,
/// sheets along `z`, `semi_axes2 = [a2, b2, c2]`.
///
/// # Errors
/// [`Error::InvalidShape`] if a squared semi-axis is not positive.
///
/// # Examples
/// ```
/// use dashu_ratio::RBig;
/// use qsic::shapes::hyperboloid_two_sheets;
///
/// let h = hyperboloid_two_sheets(&[0, 0, 0].map(RBig::from), &[1, 1, 1].map(RBig::from))?;
/// assert_eq!(h.to_polynomial_string(), "-x^2 - y^2 + z^2 - w^2");
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn hyperboloid_two_sheets(center: &Point3, semi_axes2: &[RBig; 3]) -> Result<Quadric, Error> {
    all_positive(semi_axes2, "a squared semi-axis")?;
    let m = diagonal(inverses(semi_axes2, [-1, -1, 1]));
    shifted(center, m, Default::default(), RBig::NEG_ONE)
}

/// The pair of planes `(n₁·X + d₁)(n₂·X + d₂) = 0`, a single plane counted
/// twice if they coincide.
///
/// With `p = (n₁, d₁)` and `q = (n₂, d₂)` as 4-vectors, the matrix is the
/// symmetrised product `(pqᵀ + qpᵀ)/2`.
///
/// # Errors
/// [`Error::InvalidShape`] if `n1` or `n2` is zero.
///
/// # Examples
/// ```
/// use dashu_ratio::RBig;
/// use qsic::shapes::plane_pair;
///
/// // x = 1 and y = 0.
/// let n1 = [1, 0, 0].map(RBig::from);
/// let n2 = [0, 1, 0].map(RBig::from);
/// let p = plane_pair(&n1, &RBig::from(-1), &n2, &RBig::ZERO)?;
/// assert_eq!(p.to_polynomial_string(), "x*y - y*w");
/// # Ok::<(), qsic::error::Error>(())
/// ```
pub fn plane_pair(n1: &Point3, d1: &RBig, n2: &Point3, d2: &RBig) -> Result<Quadric, Error> {
    nonzero(n1, "the first plane's normal")?;
    nonzero(n2, "the second plane's normal")?;
    let p = [&n1[0], &n1[1], &n1[2], d1];
    let q = [&n2[0], &n2[1], &n2[2], d2];
    let two = RBig::from(2);
    let m = std::array::from_fn(|i| std::array::from_fn(|j| (p[i] * q[j] + q[i] * p[j]) / &two));
    Quadric::from_matrix(m)
}

#[cfg(test)]
mod tests {
    use super::*;
    use dashu_int::{IBig, UBig};

    fn r(n: i64) -> RBig {
        RBig::from(n)
    }

    fn q(n: i64, d: u64) -> RBig {
        RBig::from_parts(IBig::from(n), UBig::from(d))
    }

    fn pt(v: [i64; 3]) -> Point3 {
        v.map(RBig::from)
    }

    /// `XᵀAX` at `X = (x, y, z, 1)`, exactly.
    fn eval(quadric: &Quadric, x: &Point3) -> RBig {
        let h = [&x[0], &x[1], &x[2], &RBig::ONE];
        let a = quadric.matrix();
        let mut s = RBig::ZERO;
        for (row, hi) in a.iter().zip(h) {
            for (aij, hj) in row.iter().zip(h) {
                s += aij * hi * hj;
            }
        }
        s
    }

    fn add(a: &Point3, b: &Point3, t: &RBig) -> Point3 {
        std::array::from_fn(|i| &a[i] + t * &b[i])
    }

    /// Asserts every point of `on` lies on the quadric and no point of `off` does.
    fn check(name: &str, quadric: &Quadric, on: &[Point3], off: &[Point3]) {
        for x in on {
            assert!(eval(quadric, x).is_zero(), "{name}: {x:?} should lie on it");
        }
        for x in off {
            assert!(
                !eval(quadric, x).is_zero(),
                "{name}: {x:?} should not lie on it"
            );
        }
    }

    #[test]
    fn points_on_and_off_axis_aligned_shapes() {
        let c = pt([1, 2, 3]);
        let s = sphere(&c, &r(4)).expect("valid");
        check(
            "sphere",
            &s,
            &[pt([3, 2, 3]), pt([1, 2, 1]), pt([1, 0, 3])],
            &[c.clone(), pt([3, 4, 3])],
        );

        let e = ellipsoid(&pt([1, 0, -1]), &[r(4), r(9), q(1, 4)]).expect("valid");
        let on = [
            pt([3, 0, -1]),
            pt([-1, 0, -1]),
            pt([1, 3, -1]),
            [r(1), r(0), q(-1, 2)],
            [q(11, 5), q(12, 5), r(-1)],
        ];
        check("ellipsoid", &e, &on, &[pt([1, 0, -1]), pt([3, 3, -1])]);

        let ec = elliptic_cylinder(&[r(1), r(1)], &[r(4), r(9)]).expect("valid");
        check(
            "elliptic cylinder",
            &ec,
            &[pt([3, 1, 0]), pt([1, 4, -7]), pt([-1, 1, 100])],
            &[pt([1, 1, 0])],
        );

        let k = elliptic_cone(&pt([0, 0, 1]), &[r(4), r(9)]).expect("valid");
        let on = [
            pt([0, 0, 1]),
            pt([2, 0, 2]),
            [q(6, 5), q(12, 5), r(2)],
            [q(-6, 5), q(12, 5), r(0)],
        ];
        check("elliptic cone", &k, &on, &[pt([0, 0, 2]), pt([2, 0, 1])]);

        let p = elliptic_paraboloid(&pt([0, 1, 2]), &[r(4), r(1)]).expect("valid");
        check(
            "elliptic paraboloid",
            &p,
            &[pt([0, 1, 2]), pt([2, 2, 4]), pt([-2, 0, 4])],
            &[pt([2, 2, 0])],
        );

        let h = hyperbolic_paraboloid(&pt([0, 1, 2]), &[r(4), r(1)]).expect("valid");
        check(
            "hyperbolic paraboloid",
            &h,
            &[pt([0, 1, 2]), pt([2, 2, 2]), pt([0, 2, 1])],
            &[pt([2, 2, 4])],
        );

        let h1 = hyperboloid_one_sheet(&pt([1, 1, 1]), &[r(1), r(1), r(1)]).expect("valid");
        check(
            "hyperboloid of one sheet",
            &h1,
            &[pt([2, 1, 1]), pt([2, 2, 2])],
            &[pt([1, 1, 1]), pt([1, 1, 2])],
        );

        let h2 = hyperboloid_two_sheets(&pt([0, 0, 0]), &[r(1), r(1), r(1)]).expect("valid");
        check(
            "hyperboloid of two sheets",
            &h2,
            &[pt([0, 0, 1]), pt([0, 0, -1]), pt([2, 2, 3])],
            &[pt([0, 0, 0]), pt([1, 0, 0])],
        );
    }

    #[test]
    fn cylinder_with_an_oblique_axis() {
        let p = pt([1, 2, 3]);
        let v = pt([2, -1, 2]); // |v| = 3
        let u = pt([1, 2, 0]); // u ⟂ v, |u|² = 5
        let c = cylinder(&p, &v, &r(5)).expect("valid");
        let on: Vec<Point3> = [r(0), q(1, 3), r(-7)]
            .iter()
            .map(|t| add(&add(&p, &v, t), &u, &RBig::ONE))
            .collect();
        let off = [p.clone(), add(&p, &v, &r(4)), add(&p, &u, &r(2))];
        check("cylinder", &c, &on, &off);
    }

    #[test]
    fn cone_with_an_oblique_axis() {
        let apex = pt([1, -2, 3]);
        let v = pt([1, 2, 2]); // |v| = 3
        let u = pt([2, 1, -2]); // u ⟂ v, |u| = 3: half-angle 45°
        let c = cone(&apex, &v, &q(1, 2)).expect("valid");
        let generator = add(&v, &u, &RBig::ONE);
        let on: Vec<Point3> = [r(0), r(1), q(-5, 2)]
            .iter()
            .map(|t| add(&apex, &generator, t))
            .collect();
        let off = [add(&apex, &v, &RBig::ONE), add(&apex, &u, &RBig::ONE)];
        check("cone", &c, &on, &off);
    }

    #[test]
    fn plane_pair_is_symmetric_and_vanishes_on_both_planes() {
        let pp = plane_pair(&pt([1, 0, 0]), &r(-1), &pt([0, 1, 1]), &r(0)).expect("valid");
        let a = pp.matrix();
        for (i, row) in a.iter().enumerate() {
            for (j, v) in row.iter().enumerate() {
                assert_eq!(v, &a[j][i]);
            }
        }
        check(
            "plane pair",
            &pp,
            &[pt([1, 5, 7]), pt([3, 2, -2]), pt([1, 0, 0])],
            &[pt([0, 0, 1]), pt([2, 1, 1])],
        );
        let double = plane_pair(&pt([0, 0, 2]), &r(2), &pt([0, 0, 1]), &r(1)).expect("valid");
        check("double plane", &double, &[pt([5, 6, -1])], &[pt([0, 0, 0])]);
    }

    #[test]
    fn invalid_parameters_are_refused() {
        let o = pt([0, 0, 0]);
        let z = pt([0, 0, 1]);
        let results = [
            ("sphere r2 = 0", sphere(&o, &r(0))),
            ("sphere r2 < 0", sphere(&o, &r(-1))),
            ("ellipsoid", ellipsoid(&o, &[r(1), r(0), r(1)])),
            ("cylinder r2", cylinder(&o, &z, &r(-2))),
            ("cylinder axis", cylinder(&o, &o, &r(1))),
            (
                "elliptic cylinder",
                elliptic_cylinder(&[r(0), r(0)], &[r(-1), r(1)]),
            ),
            ("cone axis", cone(&o, &o, &q(1, 2))),
            ("cone cos2 = 0", cone(&o, &z, &r(0))),
            ("cone cos2 = 1", cone(&o, &z, &r(1))),
            ("cone cos2 > 1", cone(&o, &z, &r(2))),
            ("elliptic cone", elliptic_cone(&o, &[r(1), r(0)])),
            (
                "elliptic paraboloid",
                elliptic_paraboloid(&o, &[r(0), r(1)]),
            ),
            (
                "hyperbolic paraboloid",
                hyperbolic_paraboloid(&o, &[r(1), r(-3)]),
            ),
            (
                "hyperboloid 1",
                hyperboloid_one_sheet(&o, &[r(1), r(1), r(0)]),
            ),
            (
                "hyperboloid 2",
                hyperboloid_two_sheets(&o, &[q(-1, 2), r(1), r(1)]),
            ),
            ("plane pair n1", plane_pair(&o, &r(1), &z, &r(0))),
            ("plane pair n2", plane_pair(&z, &r(1), &o, &r(0))),
        ];
        for (name, result) in results {
            assert!(
                matches!(result, Err(Error::InvalidShape(_))),
                "{name}: {result:?}"
            );
        }
    }
}
