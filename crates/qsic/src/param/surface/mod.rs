//! The parameterization surface (Appendix A of the enhanced-Levin paper) and its ruled
//! parameterization `q(u, v) = b(u) + v·d(u)`.
//!
//! * inertia (2, 2): a rational (or ℚ(√δ)) point `P` on `S` (a small one by integer search
//!   first, then by hyperplane sections), the two lines of `S` through `P`
//!   (roots of the binary form `S` induces on the tangent plane `T_P`, over ℚ(√D) with
//!   `D ≡ det S` modulo squares), then a hyperbolic basis `e₁, f₁, e₂, f₂` of `S`
//!   (`eᵢᵀSfᵢ = 1`, all other products zero) in which `S(X) = 2(x₁y₁ + x₂y₂)`, so that
//!   `b(u) = e₁ − u·e₂` and `d(u) = f₂ + u·f₁` are two skew lines of one regulus joined, for
//!   each `u`, by a line of the other;
//! * a cone (rank 3, indefinite): `b` the vertex, `d(u)` the conic cut by a plane missing the
//!   vertex, parameterized by the lines through one of its points:
//!   `d(u) = (YᵀSY)·P − 2(PᵀSY)·Y`, `Y = Q + u·R`.
//!
//! Linear algebra over ℚ(√δ) on 4-vectors lives here until `qsic_algebra::linalg` lands.

use super::zsqrt::{self, exact_sqrt};
use crate::error::Error;
use qsic_algebra::conic::{find_point, ConicPoint};
use qsic_algebra::factor::factorize;
use qsic_algebra::field::Quadratic;
use qsic_algebra::linalg::minors::{self, SmallMinors};
use qsic_algebra::{Field, IBig, Poly, RBig, Ring};

/// A 4-vector over ℚ(√δ).
pub(crate) type Vec4 = [Quadratic; 4];
/// A symmetric 4×4 matrix over ℚ(√δ).
pub(crate) type Mat4 = [[Quadratic; 4]; 4];
/// Four polynomials in `u` over ℚ(√δ): a point moving with `u`, in homogeneous coordinates.
pub type PolyVector = [Poly<Quadratic>; 4];

mod integer;
pub(crate) use integer::*;

/// A ruled quadric parameterized as `q(u, v) = b(u) + v·d(u)`, `(u, v) ∈ (ℝ ∪ {∞})²`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RuledParameterization {
    /// `b(u)`: a line of one regulus (degree 1), or the vertex of a cone (degree 0).
    pub b: PolyVector,
    /// `d(u)`: a skew line of the same regulus (degree 1), or a conic on the cone (degree 2).
    pub d: PolyVector,
    /// The radicand `δ` (square-free) when the coefficients are in ℚ(√δ), `None` over ℚ.
    pub delta: Option<IBig>,
}

impl From<zsqrt::FixedRuling> for RuledParameterization {
    fn from(r: zsqrt::FixedRuling) -> RuledParameterization {
        let (b, d, delta) = r.to_polys();
        RuledParameterization { b, d, delta }
    }
}

pub(crate) fn q(v: &RBig) -> Quadratic {
    Quadratic::rational(v.clone())
}

pub(crate) fn to_quadratic(m: &[[RBig; 4]; 4]) -> Mat4 {
    std::array::from_fn(|i| std::array::from_fn(|j| q(&m[i][j])))
}

pub(super) fn mat_vec(m: &Mat4, x: &Vec4) -> Vec4 {
    std::array::from_fn(|i| {
        let mut acc = Quadratic::zero();
        for j in 0..4 {
            acc.add_mul_assign(&m[i][j], &x[j]);
        }
        acc
    })
}

fn dot(x: &Vec4, y: &Vec4) -> Quadratic {
    let mut acc = Quadratic::zero();
    for i in 0..4 {
        acc.add_mul_assign(&x[i], &y[i]);
    }
    acc
}

pub(super) fn form(m: &Mat4, x: &Vec4, y: &Vec4) -> Quadratic {
    dot(x, &mat_vec(m, y))
}

fn combine(a: &Quadratic, x: &Vec4, b: &Quadratic, y: &Vec4) -> Vec4 {
    std::array::from_fn(|i| a.mul(&x[i]).add(&b.mul(&y[i])))
}

fn scaled(a: &Quadratic, x: &Vec4) -> Vec4 {
    std::array::from_fn(|i| a.mul(&x[i]))
}

/// The positive rational `k` making `k·x` integral (`aᵢ, bᵢ ∈ ℤ` for every `aᵢ + bᵢ√δ`) with
/// coprime integers; one for all zeros. A projective point, a line's direction or a whole
/// ruling may be scaled by it: smaller numbers everywhere downstream.
fn primitive_scale<'a>(xs: impl IntoIterator<Item = &'a Quadratic>) -> RBig {
    use dashu_int::ops::Gcd;
    let xs: Vec<&Quadratic> = xs.into_iter().collect();
    let parts = || {
        xs.iter()
            .flat_map(|x| [x.rational_part(), x.radical_part()])
            .filter(|v| !v.is_zero())
    };
    let mut l = IBig::ONE;
    for v in parts() {
        let d = IBig::from(v.denominator().clone());
        let g = IBig::from(l.clone().gcd(&d));
        l = &l / &g * d;
    }
    let mut g = IBig::ZERO;
    for v in parts() {
        let n = v.numerator() * &l / IBig::from(v.denominator().clone());
        g = IBig::from(g.gcd(&n));
    }
    if g.is_zero() {
        RBig::ONE
    } else {
        RBig::from_parts_signed(l, g)
    }
}

/// `x` scaled to coprime integer coordinates (see [`primitive_scale`]).
fn primitive(x: &Vec4) -> Vec4 {
    let k = primitive_scale(x);
    if k == RBig::ONE {
        return x.clone();
    }
    std::array::from_fn(|i| x[i].scale(&k))
}

/// A polynomial vector scaled by a positive rational to coprime integer coefficients.
pub(crate) fn primitive_poly(v: &PolyVector) -> PolyVector {
    let k = primitive_scale(v.iter().flat_map(|p| p.coeffs()));
    if k == RBig::ONE {
        return v.clone();
    }
    std::array::from_fn(|i| v[i].map(|c| c.scale(&k)))
}

/// `x + u·y` as a vector of polynomials in `u`.
fn line(x: &Vec4, y: &Vec4) -> PolyVector {
    std::array::from_fn(|i| Poly::new(vec![x[i].clone(), y[i].clone()]))
}

/// The bilinear form `xᵀ M y` of two polynomial vectors (fraction-free in ℤ[√δ] when `M` is
/// an integer matrix and the coefficients are integral, [`zsqrt`]).
pub(crate) fn poly_form(m: &Mat4, x: &PolyVector, y: &PolyVector) -> Poly<Quadratic> {
    if let Some(v) = integral_poly_form(m, x, y) {
        return v;
    }
    let mut acc = Poly::zero();
    for i in 0..4 {
        let mut row = Poly::zero();
        for j in 0..4 {
            if !m[i][j].is_zero() && !y[j].is_zero() {
                row = &row + &y[j].scale(&m[i][j]);
            }
        }
        if !row.is_zero() && !x[i].is_zero() {
            acc = &acc + &(&x[i] * &row);
        }
    }
    acc
}

/// [`poly_form`] over ℤ[√δ], `None` unless everything is integral.
fn integral_poly_form(m: &Mat4, x: &PolyVector, y: &PolyVector) -> Option<Poly<Quadratic>> {
    let mi = zsqrt::integer_matrix(m)?;
    let delta =
        radicand_of(x.iter().chain(y.iter()).flat_map(|p| p.coeffs())).unwrap_or(IBig::ZERO);
    let (xz, yz) = (zsqrt::zvector(x, &delta)?, zsqrt::zvector(y, &delta)?);
    Some(zsqrt::to_poly(
        &zsqrt::poly_form(&mi, &xz, &yz, &delta),
        &delta,
    ))
}

/// The radicand of a vector's coordinates, `None` if all are rational.
fn radicand_of<'a>(xs: impl IntoIterator<Item = &'a Quadratic>) -> Option<IBig> {
    xs.into_iter()
        .find(|x| x.as_rational().is_none())
        .map(|x| x.radicand().clone())
}

/// `√x` inside ℚ(√δ₀) (or ℚ if `delta0` is `None`, where any rational `x > 0` gets the
/// field ℚ(√sqf(x))), `None` when it lies in neither: a biquadratic field would be needed.
pub(crate) fn sqrt_in_field(x: &Quadratic, delta0: Option<&IBig>) -> Option<Quadratic> {
    if let Some(r) = x.as_rational() {
        let (n, d) = (r.numerator().clone(), IBig::from(r.denominator().clone()));
        let nd = &n * &d; // √(n/d) = √(n·d)/d
        let inv_d = RBig::from_parts_signed(IBig::ONE, d.clone());
        let root = Quadratic::sqrt(&nd);
        if root.as_rational().is_some() {
            return Some(root.scale(&inv_d));
        }
        return match delta0 {
            None => {
                // reduce the radicand to its square-free part where factoring succeeds
                let reduced = factorize(&nd).ok().map(|f| {
                    let (part, k) = f.squarefree_split();
                    Quadratic::sqrt(&part.value()).scale(&RBig::from(k))
                });
                Some(reduced.unwrap_or(root).scale(&inv_d))
            }
            Some(d0) => {
                // √(nd) = √(nd·δ₀)/δ₀ · √δ₀
                let t = Quadratic::sqrt(&(&nd * d0));
                let t = t.as_rational()?;
                let k = t / RBig::from(d0.clone()) * &inv_d;
                Some(Quadratic::sqrt(d0).scale(&k))
            }
        };
    }
    // x = a + b√δ: (s + t√δ)² = x ⇔ s² + δt² = a, 2st = b; s² = (a ± √N(x))/2.
    let d0 = x.radicand().clone();
    let norm = x.norm();
    let m = Quadratic::sqrt_rational(&norm);
    let m = m.as_rational()?.clone();
    let (a, b) = (x.rational_part().clone(), x.radical_part().clone());
    for s2 in [(&a + &m) / RBig::from(2), (&a - &m) / RBig::from(2)] {
        if s2 <= RBig::ZERO {
            continue;
        }
        let s = Quadratic::sqrt_rational(&s2);
        if let Some(s) = s.as_rational() {
            let t = &b / (RBig::from(2) * s);
            let root = Quadratic::new(s.clone(), t, d0.clone())?;
            if root.mul(&root) == *x {
                return Some(root);
            }
        }
    }
    None
}

/// Hyperplanes as three spanning vectors: `xᵢ = 0`, then `xᵢ = xⱼ`, `xᵢ = −xⱼ`.
fn hyperplanes() -> Vec<[[RBig; 4]; 3]> {
    let unit = |k: usize| -> [RBig; 4] {
        std::array::from_fn(|i| if i == k { RBig::ONE } else { RBig::ZERO })
    };
    let mut out = Vec::new();
    for i in 0..4 {
        let others: Vec<usize> = (0..4).filter(|&k| k != i).collect();
        out.push(std::array::from_fn(|t| unit(others[t])));
    }
    for i in 0..4 {
        for j in i + 1..4 {
            for sign in [1, -1] {
                // basis: eᵢ + sign·eⱼ and the two other units
                let mut first = unit(i);
                first[j] = RBig::from(sign);
                let others: Vec<usize> = (0..4).filter(|&k| k != i && k != j).collect();
                out.push([first, unit(others[0]), unit(others[1])]);
            }
        }
    }
    out
}

/// A point of the quadric `S` found on a hyperplane section, with that hyperplane's basis.
struct SectionPoint {
    point: Vec4,
    basis: [[RBig; 4]; 3],
    coords: [Quadratic; 3],
}

/// A point of `XᵀSX = 0`, rational when one of the tried sections has one, otherwise over
/// ℚ(√δ); sections through `avoid` are skipped. `None` if no tried section has a real point.
fn point_on(s: &[[RBig; 4]; 4], avoid: Option<&[RBig; 4]>) -> Result<Option<SectionPoint>, Error> {
    let mut fallback = None;
    for basis in hyperplanes() {
        if let Some(v) = avoid {
            // the hyperplane contains v iff v is in the span: test by the normal vector
            if contains(&basis, v) {
                continue;
            }
        }
        let c = section(s, &basis);
        if c.iter().flatten().all(|v| v.is_zero()) {
            continue;
        }
        let found = find_point(&c).map_err(|e| Error::Algebra(e.to_string()))?;
        let coords: [Quadratic; 3] = match found {
            ConicPoint::Rational(p) => std::array::from_fn(|i| q(&p[i])),
            ConicPoint::NoRationalPoint(p) | ConicPoint::Undecided(p) => {
                if fallback.is_none() {
                    fallback = Some((basis.clone(), p.coords.clone()));
                }
                continue;
            }
            ConicPoint::NoRealPoint => continue,
        };
        return Ok(Some(section_point(basis, coords)));
    }
    Ok(fallback.map(|(basis, coords)| section_point(basis, coords)))
}

fn section_point(basis: [[RBig; 4]; 3], coords: [Quadratic; 3]) -> SectionPoint {
    let point = std::array::from_fn(|k| {
        let mut acc = Quadratic::zero();
        for i in 0..3 {
            acc = acc.add(&coords[i].scale(&basis[i][k]));
        }
        acc
    });
    SectionPoint {
        point,
        basis,
        coords,
    }
}

/// `true` if `v` lies in the span of the three basis vectors (4×4 determinant zero).
fn contains(basis: &[[RBig; 4]; 3], v: &[RBig; 4]) -> bool {
    let m: [[RBig; 4]; 4] =
        std::array::from_fn(|i| if i < 3 { basis[i].clone() } else { v.clone() });
    minors::det(&m).is_zero()
}

/// The parameterization of a nonsingular quadric of inertia (2, 2) through a small rational
/// point ([`ruling_through`], fraction-free) or else a point found on a hyperplane
/// section. `Ok(None)` if its lines need a biquadratic field (no rational point
/// found and `det S` not a square in the point's field).
pub(crate) fn parameterize_doubly_ruled(
    s: &[[RBig; 4]; 4],
) -> Result<Option<RuledParameterization>, Error> {
    parameterize_doubly_ruled_with(s, true)
}

/// [`parameterize_doubly_ruled`]; with `search` false only through a small point (`Ok(None)`
/// where there is none, before the hyperplane sections of [`points_on`], which cost about
/// a million instructions each when no section has a rational point).
pub(crate) fn parameterize_doubly_ruled_with(
    s: &[[RBig; 4]; 4],
    search: bool,
) -> Result<Option<RuledParameterization>, Error> {
    let small = small_integer_matrix(s);
    let points: Vec<Vec4> = match small.as_ref().and_then(small_point_of) {
        Some(p) => {
            let m = small.as_ref().expect("a small matrix");
            if let Some(r) = ruling_at_small_point(s, m, &p)? {
                return Ok(Some(r));
            }
            vec![std::array::from_fn(|i| q(&RBig::from(p[i])))]
        }
        None if !search => return Ok(None),
        // the lines through a point over ℚ(√e) are over ℚ(√e) only when det S is a square
        // there: the other points would fail after their forms (the biquadratic route)
        None => points_on(s)?
            .into_iter()
            .filter(|(lines_in_field, _)| *lines_in_field)
            .map(|(_, p)| p)
            .collect(),
    };
    let sm = to_quadratic(s);
    let class = det_class(s);
    for p in points {
        if let Some(r) = doubly_ruled_through(&sm, p, class.as_ref())? {
            return Ok(Some(r));
        }
    }
    Ok(None)
}

/// [`ruling_through`] at the small point `p` of `m = k·S` (the radicand from `det m`, in
/// `i128` when it fits, else from the big determinant).
fn ruling_at_small_point(
    s: &[[RBig; 4]; 4],
    m: &[[i128; 4]; 4],
    p: &[i128; 4],
) -> Result<Option<RuledParameterization>, Error> {
    if let Some(delta) = member_radicand(m) {
        return ruling_through_small(m, p, &delta);
    }
    let Some(mb) = scaled_integer_matrix(s) else {
        return Ok(None);
    };
    let det = minors::det(&mb);
    let Some(delta) = squarefree_part(&det) else {
        return Ok(None);
    };
    let pb: [IBig; 4] = std::array::from_fn(|i| IBig::from(p[i]));
    ruling_through(&mb, &pb, &delta)
}

/// Points of `S` to build the ruling from: the rational point of the first section that has
/// one, else a point over ℚ(√e) from each section with real points, each with whether its
/// lines stay in ℚ(√e) — the tangent plane's binary form has discriminant `det S` up to
/// squares, so they do iff `det S` or `e·det S` is a rational square — those first.
pub(super) fn points_on(s: &[[RBig; 4]; 4]) -> Result<Vec<(bool, Vec4)>, Error> {
    let mut quadratic: Vec<(bool, Vec4)> = Vec::new();
    let det = minors::det(s);
    let det_square = Quadratic::sqrt(&(det.numerator() * det.denominator()))
        .as_rational()
        .is_some();
    for basis in hyperplanes() {
        let c = section(s, &basis);
        if c.iter().flatten().all(|v| v.is_zero()) {
            continue;
        }
        match find_point(&c).map_err(|e| Error::Algebra(e.to_string()))? {
            ConicPoint::Rational(p) => {
                let coords = std::array::from_fn(|i| q(&p[i]));
                return Ok(vec![(true, section_point(basis, coords).point)]);
            }
            ConicPoint::NoRationalPoint(p) | ConicPoint::Undecided(p) => {
                // det S a square in ℚ(√e): det·e a rational square
                let same = det_square
                    || Quadratic::sqrt(&(det.numerator() * det.denominator() * &p.delta))
                        .as_rational()
                        .is_some();
                quadratic.push((same, section_point(basis, p.coords.clone()).point));
            }
            ConicPoint::NoRealPoint => {}
        }
    }
    quadratic.sort_by_key(|(same, _)| !same);
    Ok(quadratic)
}

/// The conic `S` cuts on the plane spanned by `basis` (entries 0 and ±1: only the nonzero
/// ones count).
fn section(s: &[[RBig; 4]; 4], basis: &[[RBig; 4]; 3]) -> [[RBig; 3]; 3] {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let mut acc = RBig::ZERO;
            for k in (0..4).filter(|&k| !basis[i][k].is_zero()) {
                for l in (0..4).filter(|&l| !basis[j][l].is_zero() && !s[k][l].is_zero()) {
                    acc += &basis[i][k] * &s[k][l] * &basis[j][l];
                }
            }
            acc
        })
    })
}

/// An integer of the square class of `det S` (`n·d` for `det S = n/d`, without its
/// square factors where [`squarefree_part`] finds them); `None` when `det S ≤ 0`. The
/// lines of `S` through a rational point are defined over ℚ(√det S).
fn det_class(s: &[[RBig; 4]; 4]) -> Option<IBig> {
    let det = minors::det(s);
    let nd = det.numerator() * IBig::from(det.denominator().clone());
    if nd <= IBig::ZERO {
        return None;
    }
    Some(squarefree_part(&nd).unwrap_or(nd))
}

/// The ruling of `S` through the point `p` of `S` (see [`parameterize_doubly_ruled`]);
/// `Ok(None)` when the lines through `p` need a biquadratic field. `class` ([`det_class`])
/// gives the field of the lines through a rational point: the discriminant of the tangent
/// plane's binary form is `det S` times a rational square, often a huge one (the point's
/// size), which no factoring removes.
fn doubly_ruled_through(
    sm: &Mat4,
    p: Vec4,
    class: Option<&IBig>,
) -> Result<Option<RuledParameterization>, Error> {
    let p = primitive(&p);
    let delta0 = radicand_of(&p);
    let r = mat_vec(sm, &p);
    let j = (0..4)
        .find(|&k| !r[k].is_zero())
        .ok_or_else(|| Error::Algebra("a point in the kernel of a nonsingular quadric".into()))?;
    // T_P = ker(rᵀ): Kₖ = eₖ − (rₖ/rⱼ)eⱼ, k ≠ j; drop one Kₖ with pₖ ≠ 0 (P spans it with the rest)
    let rj_inv = r[j].inv().expect("nonzero pivot");
    let kernel: Vec<(usize, Vec4)> = (0..4)
        .filter(|&k| k != j)
        .map(|k| {
            let mut v: Vec4 = std::array::from_fn(|_| Quadratic::zero());
            v[k] = Quadratic::one();
            v[j] = r[k].mul(&rj_inv).neg();
            (k, v)
        })
        .collect();
    let k0 = kernel
        .iter()
        .find(|(k, _)| !p[*k].is_zero())
        .map(|(k, _)| *k)
        .ok_or_else(|| Error::Algebra("tangent plane basis".into()))?;
    let rest: Vec<&Vec4> = kernel
        .iter()
        .filter(|(k, _)| *k != k0)
        .map(|(_, v)| v)
        .collect();
    let (e1, e2) = (rest[0], rest[1]);
    let (s11, s12, s22) = (form(sm, e1, e1), form(sm, e1, e2), form(sm, e2, e2));
    let two = Quadratic::from_int(&IBig::from(2));
    // the two lines through P: P + t·E±, E± the roots of s11β² + 2s12βγ + s22γ²
    let (plus, minus) = if s11.is_zero() {
        (e1.clone(), combine(&s22, e1, &two.mul(&s12).neg(), e2))
    } else {
        let disc = s12.mul(&s12).sub(&s11.mul(&s22));
        if disc.sign() != Some(qsic_algebra::Sign::Positive) {
            return Err(Error::Algebra(
                "no real lines through a point of an inertia (2, 2) member".into(),
            ));
        }
        let root = match (&delta0, class) {
            (None, Some(c)) => sqrt_in_field(&disc, Some(c)),
            _ => None,
        };
        let Some(root) = root.or_else(|| sqrt_in_field(&disc, delta0.as_ref())) else {
            return Ok(None);
        };
        (
            combine(&s12.neg().add(&root), e1, &s11, e2),
            combine(&s12.neg().sub(&root), e1, &s11, e2),
        )
    };
    let (plus, minus) = (primitive(&plus), primitive(&minus));
    // hyperbolic basis: e₁ = P, e₂ = E₊, f₂ = E₋/(E₊ᵀSE₋), f₁ from the unit vector e_j
    let c = form(sm, &plus, &minus);
    let c_inv = c
        .inv()
        .ok_or_else(|| Error::Algebra("the two lines through a point are not distinct".into()))?;
    let f2 = scaled(&c_inv, &minus);
    let g: Vec4 = std::array::from_fn(|i| {
        if i == j {
            Quadratic::one()
        } else {
            Quadratic::zero()
        }
    });
    let g = combine(&Quadratic::one(), &g, &form(sm, &g, &f2).neg(), &plus);
    let g = combine(&Quadratic::one(), &g, &form(sm, &g, &plus).neg(), &f2);
    let g = scaled(&r[j].inv().expect("nonzero pivot"), &g);
    let half = Quadratic::rational(RBig::from_parts_signed(IBig::ONE, IBig::from(2)));
    let f1 = combine(
        &Quadratic::one(),
        &g,
        &form(sm, &g, &g).mul(&half).neg(),
        &p,
    );
    // b and d each scaled as a whole: the same lines, v rescaled
    let b = primitive_poly(&line(&p, &scaled(&Quadratic::one().neg(), &plus)));
    let d = primitive_poly(&line(&f2, &f1));
    let delta = radicand_of(b.iter().chain(d.iter()).flat_map(|x| x.coeffs()));
    Ok(Some(RuledParameterization { b, d, delta }))
}

/// The parameterization of a cone or cylinder `S` (rank 3, indefinite): the vertex and a
/// conic of `S` on a hyperplane missing it.
pub(crate) fn parameterize_cone(
    s: &[[RBig; 4]; 4],
) -> Result<Option<RuledParameterization>, Error> {
    let sm = to_quadratic(s);
    // the vertex: a nonzero column of the adjugate (rank 3 ⇒ adj S has rank 1, S·adj S = 0)
    let all = SmallMinors::all(s);
    let except = |k: usize| -> Vec<usize> { (0..4).filter(|&i| i != k).collect() };
    let vertex_rational: [RBig; 4] = (0..4)
        .map(|c| {
            std::array::from_fn(|r| {
                let m = all.minor(&except(c), &except(r));
                if (r + c) % 2 == 0 {
                    m.clone()
                } else {
                    -m
                }
            })
        })
        .find(|v: &[RBig; 4]| v.iter().any(|x| !x.is_zero()))
        .ok_or_else(|| Error::Algebra("a cone member of rank below 3".into()))?;
    let vertex: Vec4 = std::array::from_fn(|i| q(&vertex_rational[i]));
    let Some(found) = point_on(s, Some(&vertex_rational))? else {
        return Ok(None);
    };
    let k0 = (0..3)
        .find(|&i| !found.coords[i].is_zero())
        .expect("a nonzero point");
    let others: Vec<Vec4> = (0..3)
        .filter(|&i| i != k0)
        .map(|i| std::array::from_fn(|k| q(&found.basis[i][k])))
        .collect();
    let p = found.point;
    let y = line(&others[0], &others[1]);
    let pv: PolyVector = std::array::from_fn(|i| Poly::constant(p[i].clone()));
    let yy = poly_form(&sm, &y, &y);
    let py = poly_form(&sm, &pv, &y);
    let minus_two_py = py.scale(&Quadratic::from_int(&IBig::from(-2)));
    let d: PolyVector = std::array::from_fn(|i| &(&yy * &pv[i]) + &(&minus_two_py * &y[i]));
    let d = primitive_poly(&d);
    let b = primitive_poly(&std::array::from_fn(|i| Poly::constant(vertex[i].clone())));
    let delta = radicand_of(d.iter().flat_map(|x| x.coeffs()));
    Ok(Some(RuledParameterization { b, d, delta }))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rat(v: i64) -> RBig {
        RBig::from(v)
    }

    fn diag(d: [i64; 4]) -> [[RBig; 4]; 4] {
        std::array::from_fn(|i| std::array::from_fn(|j| if i == j { rat(d[i]) } else { rat(0) }))
    }

    fn assert_ruled(s: &[[RBig; 4]; 4], r: &RuledParameterization) {
        let sm = to_quadratic(s);
        assert!(poly_form(&sm, &r.b, &r.b).is_zero());
        assert!(poly_form(&sm, &r.b, &r.d).is_zero());
        assert!(poly_form(&sm, &r.d, &r.d).is_zero());
        assert!(r.d.iter().any(|x| !x.is_constant()), "d(u) moves");
    }

    /// A member with no small rational point (a large one from a plane section): the
    /// discriminant at that point is `det S` times the square of a 70-digit number, and the
    /// field must still be ℚ(√det S), δ the square-free part of `det S`
    /// (7·127·859·3628852029232861; `det S = 2⁴·δ`), not δ times that square.
    #[test]
    fn lines_through_a_large_rational_point_stay_in_the_field_of_det() {
        let a = [
            [61110, 367290, 25830, 2772],
            [367290, 73150, -77220, -94248],
            [25830, -77220, -135135, -2970],
            [2772, -94248, -2970, 173250],
        ];
        let b = [
            [2160, 560, 3360, 5390],
            [560, 420, -4284, 2100],
            [3360, -4284, -7770, -2695],
            [5390, 2100, -2695, -3990],
        ];
        let s: [[RBig; 4]; 4] =
            std::array::from_fn(|i| std::array::from_fn(|j| rat(2 * a[i][j] - b[i][j])));
        let det = minors::det(&s);
        let r = parameterize_doubly_ruled(&s)
            .unwrap()
            .expect("a parameterization");
        assert_ruled(&s, &r);
        let want = IBig::from(7 * 127 * 859 * 3628852029232861i128);
        assert_eq!(r.delta, Some(want.clone()));
        assert_eq!(det, RBig::from(IBig::from(16) * want.clone()));
        // S/3: det S/81, a rational determinant of the same square class
        let third = RBig::from_parts_signed(IBig::ONE, IBig::from(3));
        let s3: [[RBig; 4]; 4] =
            std::array::from_fn(|i| std::array::from_fn(|j| &s[i][j] * &third));
        let r3 = parameterize_doubly_ruled(&s3)
            .unwrap()
            .expect("a parameterization");
        assert_ruled(&s3, &r3);
        assert_eq!(r3.delta, Some(want));
    }

    #[test]
    fn doubly_ruled_quadrics_lie_on_their_parameterization() {
        // x²+y²−z²−w² (rational lines), x²+2y²−z²−3w² (det 6: lines over ℚ(√6)),
        // x²+y²−3z²−3w² (no rational point: 3 is no sum of two squares)
        for (d, want) in [
            ([1, 1, -1, -1], None),
            ([1, 2, -1, -3], Some(6)),
            ([1, 1, -3, -3], Some(3)),
        ] {
            let s = diag(d);
            let r = parameterize_doubly_ruled(&s)
                .unwrap()
                .expect("a parameterization");
            assert_ruled(&s, &r);
            assert_eq!(r.delta, want.map(IBig::from), "{d:?}");
        }
    }

    #[test]
    fn exact_square_roots_and_small_points() {
        for n in -5i128..20_000 {
            let want = (0..=150i128).find(|k| k * k == n);
            assert_eq!(exact_sqrt(n), want, "{n}");
        }
        let big = (1i128 << 50) + 3;
        assert_eq!(exact_sqrt(big * big), Some(big));
        assert_eq!(exact_sqrt(big * big + 1), None);
        // squares and their neighbours on both sides of 2⁶⁴ (the u64 route and the i128 one),
        // where the float root is off by one
        for r in [
            (1i128 << 32) - 1,
            1 << 32,
            (1 << 32) + 1,
            3_037_000_499,
            4_294_967_291,
        ] {
            assert_eq!(exact_sqrt(r * r), Some(r), "{r}²");
            assert_eq!(exact_sqrt(r * r - 1), None, "{r}² − 1");
            assert_eq!(exact_sqrt(r * r + 1), None, "{r}² + 1");
        }
        let top = (1i128 << 32) - 1; // the largest root below 2⁶⁴
        assert_eq!(exact_sqrt(i128::from(u64::MAX)), None);
        assert_eq!(exact_sqrt(top * top + 2 * top), None); // (top + 1)² − 1 = 2⁶⁴ − 1
                                                           // random symmetric integer matrices: every small point is on the quadric, and the
                                                           // rulings through it (the fraction-free route) lie on it too
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % 19) as i64 - 9
        };
        let (mut found, mut ruled) = (0, 0);
        for _ in 0..200 {
            let mut m: [[RBig; 4]; 4] = std::array::from_fn(|_| std::array::from_fn(|_| rat(0)));
            for i in 0..4 {
                for j in i..4 {
                    let v = rat(next());
                    m[i][j] = v.clone();
                    m[j][i] = v;
                }
            }
            if let Some(p) = small_integer_matrix(&m).and_then(|mi| small_point_of(&mi)) {
                let p: [RBig; 4] = std::array::from_fn(|i| RBig::from(p[i]));
                found += 1;
                assert!(p.iter().any(|x| !x.is_zero()));
                let mut acc = RBig::ZERO;
                for i in 0..4 {
                    for j in 0..4 {
                        acc += &p[i] * &m[i][j] * &p[j];
                    }
                }
                assert!(acc.is_zero(), "{p:?}");
            }
            if minors::det(&m).is_zero() {
                continue;
            }
            if let Ok(Some(r)) = parameterize_doubly_ruled(&m) {
                ruled += 1;
                assert_ruled(&m, &r);
            }
        }
        assert!(found > 50 && ruled > 20, "{found} points, {ruled} rulings");
    }

    /// The square-free part by trial division to the cube root equals the one by
    /// [`factorize`], below `2⁶⁴` and past it (the fallback), on random numbers and on
    /// products with large square factors.
    #[test]
    fn squarefree_parts_agree_with_factoring() {
        let mut rng = qsic_algebra::testing::SplitMix(17);
        let by_factoring =
            |n: &IBig| -> IBig { factorize(n).unwrap().squarefree_split().0.value() };
        for k in 0..400 {
            let bits = 1 + k % 60;
            let n = IBig::from(1 + (rng.next_u64() >> (64 - bits)));
            // a square of a prime above the trial bound times a small cofactor, and a
            // number past u64
            let q = IBig::from([4099u64, 65537, 1_000_003][k % 3]);
            let sq = &q * &q * IBig::from(1 + (rng.next_u64() >> 50));
            let big = &sq * IBig::from(1_000_000_007u64) * IBig::from(998_244_353u64 + k as u64);
            for x in [n, sq, big] {
                assert_eq!(squarefree_part(&x), Some(by_factoring(&x)), "{x}");
            }
        }
        assert_eq!(squarefree_part(&IBig::ZERO), None);
        assert_eq!(squarefree_part(&IBig::from(-4)), None);
    }

    fn random_symmetric(rng: &mut qsic_algebra::testing::SplitMix, bound: i64) -> [[i128; 4]; 4] {
        let mut m = [[0i128; 4]; 4];
        for i in 0..4 {
            for j in i..4 {
                m[i][j] = i128::from(rng.int(-bound, bound));
                m[j][i] = m[i][j];
            }
        }
        m
    }

    /// The checked determinant equals the big one, and declines only past `i128`.
    #[test]
    fn checked_determinants() {
        let mut rng = qsic_algebra::testing::SplitMix(23);
        for bound in [3i64, 1000, 1 << 30, (1 << 40) - 1] {
            for _ in 0..50 {
                let m = random_symmetric(&mut rng, bound);
                let big: [[IBig; 4]; 4] =
                    std::array::from_fn(|i| std::array::from_fn(|j| IBig::from(m[i][j])));
                let want = minors::det(&big);
                match det_checked(&m) {
                    Some(d) => assert_eq!(IBig::from(d), want),
                    None => assert!(bound > 1 << 20),
                }
            }
        }
    }

    /// The ruling in `i128` equals the one in `IBig` (the fallback), lies on `S`, and the
    /// machine route declines (never errs differently) when the numbers overflow.
    #[test]
    fn machine_rulings_equal_big_rulings() {
        let mut rng = qsic_algebra::testing::SplitMix(31);
        let (mut machine, mut overflow, mut total) = (0, 0, 0);
        for bound in [2i64, 10, 60, 1000, 1 << 20, (1 << 39) - 1] {
            for _ in 0..60 {
                let m = random_symmetric(&mut rng, bound);
                let Some(p) = small_point_of(&m) else {
                    continue;
                };
                let Some(delta) = member_radicand(&m) else {
                    continue;
                };
                let s: [[RBig; 4]; 4] =
                    std::array::from_fn(|i| std::array::from_fn(|j| RBig::from(m[i][j])));
                let inertia = qsic_algebra::matrix::SymMatrix4::new(std::array::from_fn(|i| {
                    std::array::from_fn(|j| IBig::from(m[i][j]))
                }))
                .expect("nonzero")
                .inertia();
                if inertia.positive != 2 || inertia.negative != 2 {
                    continue;
                }
                total += 1;
                let mb: [[IBig; 4]; 4] =
                    std::array::from_fn(|i| std::array::from_fn(|j| IBig::from(m[i][j])));
                let pb: [IBig; 4] = std::array::from_fn(|i| IBig::from(p[i]));
                let big = ruling_through(&mb, &pb, &delta).unwrap().expect("a ruling");
                assert_ruled(&s, &big);
                assert_eq!(big.delta.clone().unwrap_or(IBig::ONE), delta);
                let dl = i128::try_from(&delta).unwrap();
                match ruling_through(&m, &p, &dl).unwrap() {
                    Some(r) => {
                        machine += 1;
                        assert_eq!(r, big);
                    }
                    None => overflow += 1,
                }
                assert_eq!(ruling_through_small(&m, &p, &delta).unwrap(), Some(big));
            }
        }
        assert!(
            machine > 30 && overflow > 5,
            "{machine} machine, {overflow} overflow of {total}"
        );
    }

    /// The ruling in fixed `i128` arrays (`zsqrt::ruling_fixed`, plain arithmetic under bit
    /// length guards) equals the checked route's wherever it answers, declines (`Overflow`)
    /// only where the guards cannot exclude overflow, and says `NotInField` exactly where the
    /// checked route finds no ruling; members from tiny to near the `2⁴⁰` bound, so that
    /// every guard is passed and failed (test builds check every operation for overflow:
    /// a guard that lets one through panics here).
    #[test]
    fn fixed_rulings_equal_checked_rulings() {
        use super::super::zsqrt::{ruling_fixed, Through};
        let mut rng = qsic_algebra::testing::SplitMix(37);
        let (mut fixed, mut overflow, mut not_in_field) = (0, 0, 0);
        // members with a small point, then members through a given point (1, p₁, p₂, p₃)
        // with |pᵢ| < 2^k (M₀₀ chosen to put it on the quadric), whose sizes cross the guards
        let mut cases = Vec::new();
        let bounds = [
            1i64,
            2,
            5,
            30,
            200,
            3000,
            1 << 14,
            1 << 18,
            1 << 24,
            (1 << 39) - 1,
        ];
        for bound in bounds {
            for _ in 0..80 {
                let m = random_symmetric(&mut rng, bound);
                if let Some(p) = small_point_of(&m) {
                    cases.push((m, p));
                }
            }
        }
        // (det M must fit i128 for a radicand: M₀₀ ≈ 2^(2k + j + 3) stays below 2³²)
        for k in [2i64, 6, 9, 11, 12, 13] {
            for j in [1i64, 2, 3, 5] {
                for _ in 0..16 {
                    let mut m = random_symmetric(&mut rng, 1 << j);
                    let p: [i128; 4] = std::array::from_fn(|i| {
                        if i == 0 {
                            1
                        } else {
                            rng.int(-(1 << k), 1 << k).into()
                        }
                    });
                    m[0][0] = 0;
                    let mut rest = 0i128;
                    for i in 0..4 {
                        for l in 0..4 {
                            rest += p[i] * m[i][l] * p[l];
                        }
                    }
                    m[0][0] = -rest;
                    if m[0][0].unsigned_abs() < 1 << 40 {
                        cases.push((m, p));
                    }
                }
            }
        }
        // diag(u, v, −u, −v) through (a, b, a, b): one line direction (1, 0, 1, 0), far
        // smaller than the point (the balancing scales that line up)
        for k in [3i64, 10, 20, 30] {
            for _ in 0..8 {
                let (u, v) = (rng.int(1, 9), rng.int(1, 9));
                let mut m = [[0i128; 4]; 4];
                for (i, w) in [u, v, -u, -v].into_iter().enumerate() {
                    m[i][i] = w.into();
                }
                let (a, b) = (rng.int(1, 1 << k), rng.int(1, 1 << k));
                cases.push((m, [a, b, a, b].map(i128::from)));
            }
        }
        for (m, p) in cases {
            let Some(delta) = member_radicand(&m) else {
                continue;
            };
            let want = ruling_through_small(&m, &p, &delta);
            let dl = i128::try_from(&delta).expect("a radicand below 2¹²⁸");
            match ruling_fixed(&m, &p, dl) {
                Ok(Through::Ruling(r)) => {
                    fixed += 1;
                    let got = RuledParameterization::from(r);
                    assert_eq!(Some(got.clone()), want.expect("a ruling"), "{m:?}");
                    let s: [[RBig; 4]; 4] = m.map(|row| row.map(RBig::from));
                    assert_ruled(&s, &got);
                    // the reduction keeps it a ruling of the same surface
                    let mut reduced = r;
                    reduced.reduce();
                    assert_ruled(&s, &RuledParameterization::from(reduced));
                }
                Ok(Through::NotInField) => {
                    not_in_field += 1;
                    assert_eq!(want.expect("no error"), None, "{m:?}");
                }
                Ok(Through::Overflow) => overflow += 1,
                Err(_) => assert!(want.is_err(), "{m:?}"),
            }
        }
        assert!(
            fixed > 100 && overflow > 20,
            "{fixed} fixed, {overflow} overflow, {not_in_field} not in the field"
        );
    }

    #[test]
    fn cones_lie_on_their_parameterization() {
        for d in [[1, 1, -1, 0], [1, 0, 2, -3], [0, 1, 1, -3]] {
            let s = diag(d);
            let r = parameterize_cone(&s).unwrap().expect("a parameterization");
            assert_ruled(&s, &r);
            assert!(r.b.iter().all(Poly::is_constant));
        }
    }

    #[test]
    fn square_roots_stay_in_the_field() {
        let r = |n: i64, d: i64| Quadratic::rational(RBig::from_parts_signed(n.into(), d.into()));
        let s = sqrt_in_field(&r(8, 9), None).unwrap();
        assert_eq!(s.radicand(), &IBig::from(2));
        assert_eq!(s.mul(&s), r(8, 9));
        let s3 = Quadratic::sqrt(&IBig::from(3));
        assert_eq!(
            sqrt_in_field(&r(12, 1), Some(&IBig::from(3))),
            Some(s3.scale(&rat(2)))
        );
        assert_eq!(sqrt_in_field(&r(2, 1), Some(&IBig::from(3))), None);
        // (1 + √3)² = 4 + 2√3
        let x = r(1, 1).add(&s3);
        let sq = sqrt_in_field(&x.mul(&x), None).unwrap();
        assert_eq!(sq.mul(&sq), x.mul(&x));
    }
}
