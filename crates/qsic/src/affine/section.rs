//! A conic's affine data from its plane section ([`PlaneSection`]): the points `E·Y`,
//! `YᵀCY = 0`, with `E` and `C` over the plane's own field `k` (ℚ or ℚ(√δ)). The same
//! quantities as [`super::conic::param_conic`] reads from `X(u)`, in `k` rather than in the
//! parameterization's field `K ⊇ k` (degree 4 for two secant conics in planes over ℚ(√δ)
//! with no point over ℚ(√δ)), so the numbers are those of the plane and the quadric alone.
//!
//! With `ℓ = (w′(E₀), w′(E₁), w′(E₂))` the plane's line at infinity in `Y`, `Z_a`, `Z_b` a
//! basis of `ℓ·Z = 0`, `v_a`, `v_b` their images in ℝ³, `F = [Z_iᵀCZ_j]`:
//!
//! * type: `det F > 0` ellipse, `< 0` hyperbola (two real points at infinity), `= 0`
//!   parabola — exact signs in `k`;
//! * centre: the pole of the line at infinity, `Y_c = adj(C)·ℓ`, i.e. the chart point
//!   `E·Y_c/σ`, `σ = ℓᵀadj(C)ℓ = det C·ℓᵀC⁻¹ℓ ≠ 0`;
//! * axes: for `Y = Y_c/σ + Z`, `ℓ·Z = 0`, the cross term vanishes (`C·adj(C)ℓ = det C·ℓ`)
//!   and the conic is `ZᵀCZ = κ`, `κ = −det C/σ` — the equation [`central`] solves, with
//!   `1/κ` in the place of `Δ`;
//! * parabola: the pole `y = adj(C)·ℓ` is then the conic's point at infinity (`σ = 0`), in
//!   `k`; the lines through it, `X(u) = 2(yᵀCv)v − (vᵀCv)y` with `v = e_a + u·e_b` on the
//!   coordinate line `Y_m = 0`, `y_m ≠ 0`, give a parameterization over `k` whose `w′` has
//!   the double root [`parabola`] reads the vertex, axis and focal length from.

use super::conic::{at_infinity_basis, central, cross, div, dot, int, normalized, parabola};
use super::conic::{param_conic, plain3, scaled};
use super::{AffineConic, Chart, ConicShape};
use crate::classify::ComponentKind;
use crate::error::Error;
use crate::param::{Component, ComponentParam, Number, PlaneSection, Point};
use qsic_algebra::{Ring, Sign};

type V3 = [Number; 3];

/// The affine data of a real conic component in `chart` (see the module documentation of [`super::conic`]): from its plane section when it carries
/// one (this module), else from its parameterization ([`param_conic`]).
///
/// ```
/// use qsic::{affine::{affine_conic, Chart, ConicShape}, io::parse_quadric, param::parameterize};
/// use qsic_algebra::RBig;
/// // the sphere x² + y² + z² = 25 and the planes z = ±3: two circles of radius 4
/// let (a, b) = (parse_quadric("x^2+y^2+z^2-25").unwrap(), parse_quadric("z^2-9").unwrap());
/// let curve = parameterize(&a, &b).unwrap();
/// for c in &curve.components {
///     let conic = affine_conic(c, &Chart::default()).unwrap().unwrap();
///     let ConicShape::Circle { centre, radius2 } = conic.shape else { panic!("a circle") };
///     assert_eq!(radius2, qsic::param::curve::rational(RBig::from(16)));
///     assert_eq!(centre[2].mul(&centre[2]), qsic::param::curve::rational(RBig::from(9)));
/// }
/// # use qsic_algebra::Ring;
/// ```
///
/// `Ok(None)` for a component that is not a real conic with a parameterization of degree 2
/// (the only form [`crate::param::parameterize`] gives conics).
///
/// # Errors
/// [`Error::Algebra`] for a degenerate parameterization (coefficient vectors not spanning a
/// plane).
pub fn affine_conic(component: &Component, chart: &Chart) -> Result<Option<AffineConic>, Error> {
    let (ComponentKind::Conic, Some(ComponentParam::Rational { x, degree: 2 })) =
        (component.kind, &component.param)
    else {
        return Ok(None);
    };
    match &component.section {
        Some(section) => section_conic(section, chart).map(Some),
        None => param_conic(x, chart).map(Some),
    }
}

/// The affine data of the conic of `section` in `chart` (module documentation).
///
/// # Errors
/// [`Error::Algebra`] when `C` is singular or `E` does not span a plane (not a conic's
/// section).
fn section_conic(section: &PlaneSection, chart: &Chart) -> Result<AffineConic, Error> {
    // the spanning points in chart coordinates
    let cols: [Point; 3] = std::array::from_fn(|k| {
        chart.to_chart_number(&std::array::from_fn(|i| section.basis[i][k].clone()))
    });
    let c = &section.conic;
    let l: V3 = std::array::from_fn(|k| cols[k][3].clone());
    let image = |y: &V3| -> V3 {
        std::array::from_fn(|i| {
            (0..3).fold(Number::zero(), |acc, k| acc.add(&y[k].mul(&cols[k][i])))
        })
    };
    let form = |y: &V3, z: &V3| bilinear(c, y, z);
    let Some((za, zb)) = at_infinity_basis(&l) else {
        return Ok(AffineConic {
            normal: None,
            shape: ConicShape::AtInfinity,
        });
    };
    let (va, vb) = (image(&za), image(&zb));
    let normal = normalized(cross(&va, &vb))
        .ok_or_else(|| Error::Algebra("affine conic: a degenerate plane section".into()))?;
    let adj = adjugate(c);
    let det_c = (0..3).fold(Number::zero(), |acc, j| acc.add(&c[0][j].mul(&adj[j][0])));
    if det_c.is_zero() {
        return Err(Error::Algebra(
            "affine conic: a singular plane section".into(),
        ));
    }
    let pole: V3 = std::array::from_fn(|i| dot(&adj[i], &l));
    let f = [form(&za, &za), form(&za, &zb), form(&zb, &zb)];
    let det_f = f[0].mul(&f[2]).sub(&f[1].mul(&f[1]));
    let shape = match det_f.sign() {
        Sign::Zero => parabola_through(c, &pole, &image, &l)?,
        s => {
            let sigma = dot(&l, &pole);
            let centre = scaled(&image(&pole), &div(&int(1), &sigma)?);
            let kappa = div(&det_c.neg(), &sigma)?;
            let inverse = div(&sigma.neg(), &det_c)?;
            let g = [dot(&va, &va), dot(&va, &vb), dot(&vb, &vb)];
            central(
                centre,
                s == Sign::Negative,
                &f,
                &g,
                [&kappa, &inverse],
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

/// `yᵀCz`.
fn bilinear(c: &[[Number; 3]; 3], y: &V3, z: &V3) -> Number {
    let mut acc = Number::zero();
    for i in 0..3 {
        for j in 0..3 {
            if !c[i][j].is_zero() {
                acc = acc.add(&y[i].mul(&c[i][j]).mul(&z[j]));
            }
        }
    }
    acc
}

/// The adjugate of the symmetric 3×3 matrix `c`.
fn adjugate(c: &[[Number; 3]; 3]) -> [[Number; 3]; 3] {
    let m = |i: usize, j: usize| &c[i][j];
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            // cofactor of (j, i)
            let (r0, r1) = ((j + 1) % 3, (j + 2) % 3);
            let (c0, c1) = ((i + 1) % 3, (i + 2) % 3);
            m(r0, c0).mul(m(r1, c1)).sub(&m(r0, c1).mul(m(r1, c0)))
        })
    })
}

/// The parabola of `c` through its point at infinity `y` (module documentation).
fn parabola_through(
    c: &[[Number; 3]; 3],
    y: &V3,
    image: &impl Fn(&V3) -> V3,
    l: &V3,
) -> Result<ConicShape, Error> {
    let m = (0..3)
        .find(|&m| !y[m].is_zero())
        .ok_or_else(|| Error::Algebra("affine conic: a parabola without its point".into()))?;
    let unit =
        |i: usize| -> V3 { std::array::from_fn(|k| if k == i { int(1) } else { Number::zero() }) };
    let (ea, eb) = match m {
        0 => (unit(1), unit(2)),
        1 => (unit(0), unit(2)),
        _ => (unit(0), unit(1)),
    };
    let cf = |p: &V3, q: &V3| bilinear(c, p, q);
    let (ya, yb) = (cf(y, &ea), cf(y, &eb));
    let two = int(2);
    let lin = |a: &Number, p: &V3, b: &Number, q: &V3| -> V3 {
        std::array::from_fn(|i| a.mul(&p[i]).add(&b.mul(&q[i])))
    };
    // X(u) = 2(yᵀCv)v − (vᵀCv)y, v = e_a + u·e_b: coefficients of 1, u, u²
    let x0 = lin(&two.mul(&ya), &ea, &cf(&ea, &ea).neg(), y);
    let x1 = {
        let t = lin(&two.mul(&yb), &ea, &two.mul(&ya), &eb);
        lin(&int(1), &t, &two.mul(&cf(&ea, &eb)).neg(), y)
    };
    let x2 = lin(&two.mul(&yb), &eb, &cf(&eb, &eb).neg(), y);
    let w = [dot(l, &x0), dot(l, &x1), dot(l, &x2)];
    parabola(&image(&x0), &image(&x1), &image(&x2), &w)
}
