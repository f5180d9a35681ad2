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

use super::zsqrt;
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
    let conv = |v: &PolyVector| -> Option<[zsqrt::ZPoly; 4]> {
        let out: Vec<zsqrt::ZPoly> = v
            .iter()
            .map(|p| zsqrt::zpoly(p, &delta))
            .collect::<Option<_>>()?;
        out.try_into().ok()
    };
    let (xz, yz) = (conv(x)?, conv(y)?);
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
            ConicPoint::NoRationalPoint(p) => {
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

/// The integer matrix `k·S` (`k > 0` the least common denominator) if its entries are below
/// `2⁴⁰` in absolute value.
fn small_integer_matrix(s: &[[RBig; 4]; 4]) -> Option<[[i128; 4]; 4]> {
    use dashu_int::ops::Gcd;
    let mut l = IBig::ONE;
    for v in s.iter().flatten() {
        let d = IBig::from(v.denominator().clone());
        let g = IBig::from(l.clone().gcd(&d));
        l = &l / &g * d;
    }
    let bound = IBig::ONE << 40;
    let mut out = [[0i128; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            let v = &s[i][j];
            let n = v.numerator() * &l / IBig::from(v.denominator().clone());
            if n.clone() * n.signum() >= bound {
                return None;
            }
            out[i][j] = i128::try_from(&n).ok()?;
        }
    }
    Some(out)
}

/// `⌊√n⌋` if `n ≥ 0` is a perfect square.
fn exact_sqrt(n: i128) -> Option<i128> {
    if n < 0 {
        return None;
    }
    // squares are 0, 1, 4, 9, 16, 17, 25, 33, 36, 41, 49, 57 modulo 64
    if (0x0202_0212_0203_0213u64 >> (n & 63)) & 1 == 0 {
        return None;
    }
    let mut r = (n as f64).sqrt() as i128;
    while r * r > n {
        r -= 1;
    }
    while (r + 1) * (r + 1) <= n {
        r += 1;
    }
    (r * r == n).then_some(r)
}

/// A rational point of `XᵀSX = 0` found cheaply, `None` if none of the tried ones is: the
/// vectors with entries in {−1, 0, 1}, then the rational points of the lines joining two of
/// them (`S` restricted to `P + t·Q` has rational roots iff `S(P,Q)² − S(P,P)S(Q,Q)` is a
/// square). Exact integer arithmetic on `k·S` (entries below `2⁴⁰`, products below `2¹²⁰`).
fn small_point(s: &[[RBig; 4]; 4]) -> Option<[RBig; 4]> {
    let m = small_integer_matrix(s)?;
    // the 40 projective classes of nonzero vectors in {−1, 0, 1}⁴, first nonzero entry 1
    let mut vs: Vec<[i128; 4]> = Vec::with_capacity(40);
    for code in 0..81 {
        let v: [i128; 4] = std::array::from_fn(|i| (code / 3i128.pow(i as u32)) % 3 - 1);
        if v.iter().find(|&&x| x != 0) == Some(&1) {
            vs.push(v);
        }
    }
    let mv: Vec<[i128; 4]> = vs
        .iter()
        .map(|v| std::array::from_fn(|i| (0..4).map(|j| m[i][j] * v[j]).sum()))
        .collect();
    let dot = |x: &[i128; 4], y: &[i128; 4]| -> i128 { (0..4).map(|i| x[i] * y[i]).sum() };
    let diag: Vec<i128> = vs.iter().zip(&mv).map(|(v, w)| dot(v, w)).collect();
    let rational = |v: [i128; 4]| -> [RBig; 4] { std::array::from_fn(|i| RBig::from(v[i])) };
    if let Some(k) = diag.iter().position(|&x| x == 0) {
        return Some(rational(vs[k]));
    }
    for p in 0..vs.len() {
        for q in p + 1..vs.len() {
            let spq = dot(&vs[p], &mv[q]);
            let Some(r) = exact_sqrt(spq * spq - diag[p] * diag[q]) else {
                continue;
            };
            // S(P + tQ) = 0 at t = (−S(P,Q) + r)/S(Q,Q): the point S(Q,Q)·P + (r − S(P,Q))·Q
            let (a, b) = (diag[q], r - spq);
            return Some(rational(std::array::from_fn(|i| {
                a * vs[p][i] + b * vs[q][i]
            })));
        }
    }
    None
}

/// The parameterization of a nonsingular quadric of inertia (2, 2) through a small rational
/// point ([`doubly_ruled_integral`], fraction-free) or else a point found on a hyperplane
/// section. `Ok(None)` if its lines need a biquadratic field (no rational point
/// found and `det S` not a square in the point's field).
pub(crate) fn parameterize_doubly_ruled(
    s: &[[RBig; 4]; 4],
) -> Result<Option<RuledParameterization>, Error> {
    let points: Vec<Vec4> = match small_point(s) {
        Some(p) => {
            if let Some(prepared) = prepare(s, &p)? {
                if let Some(r) = doubly_ruled_integral(prepared)? {
                    return Ok(Some(r));
                }
            }
            vec![std::array::from_fn(|i| q(&p[i]))]
        }
        // the lines through a point over ℚ(√e) are over ℚ(√e) only when det S is a square
        // there: the other points would fail after their forms (the biquadratic route)
        None => points_on(s)?
            .into_iter()
            .filter(|(lines_in_field, _)| *lines_in_field)
            .map(|(_, p)| p)
            .collect(),
    };
    let sm = to_quadratic(s);
    for p in points {
        if let Some(r) = doubly_ruled_through(&sm, p)? {
            return Ok(Some(r));
        }
    }
    Ok(None)
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
            ConicPoint::NoRationalPoint(p) => {
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

/// The ruling of `S` through the point `p` of `S` (see [`parameterize_doubly_ruled`]);
/// `Ok(None)` when the lines through `p` need a biquadratic field.
fn doubly_ruled_through(sm: &Mat4, p: Vec4) -> Result<Option<RuledParameterization>, Error> {
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
        let Some(root) = sqrt_in_field(&disc, delta0.as_ref()) else {
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

/// The tangent plane of `S` at an integer point `p`, on `M = k·S` (integer): `r = Mp`, its
/// first nonzero entry `j`, the kernel vectors `e₁`, `e₂` (`Kₖ = rⱼeₖ − rₖeⱼ`, the one with
/// the first `pₖ ≠ 0`, `k ≠ j`, left out) and the binary form `sᵢⱼ = eᵢᵀMeⱼ` on them.
struct Tangent {
    m: [[IBig; 4]; 4],
    p: Vec<IBig>,
    j: usize,
    e1: Vec<IBig>,
    e2: Vec<IBig>,
    s11: IBig,
    s12: IBig,
    s22: IBig,
}

/// [`Tangent`] at `p`; `Ok(None)` if `p` is not integral.
fn tangent_plane(s: &[[RBig; 4]; 4], p: &[RBig; 4]) -> Result<Option<Tangent>, Error> {
    let Some(m) = scaled_integer_matrix(s) else {
        return Ok(None);
    };
    let int = |v: &RBig| -> Option<IBig> {
        (*v.denominator() == dashu_int::UBig::ONE).then(|| v.numerator().clone())
    };
    let Some(p) = p.iter().map(int).collect::<Option<Vec<IBig>>>() else {
        return Ok(None);
    };
    let mv = |x: &[IBig]| -> Vec<IBig> {
        (0..4)
            .map(|i| (0..4).map(|j| &m[i][j] * &x[j]).sum())
            .collect()
    };
    let idot = |x: &[IBig], y: &[IBig]| -> IBig { (0..4).map(|i| &x[i] * &y[i]).sum() };
    let r = mv(&p);
    let j = (0..4)
        .find(|&k| !r[k].is_zero())
        .ok_or_else(|| Error::Algebra("a point in the kernel of a nonsingular quadric".into()))?;
    let k0 = (0..4)
        .find(|&k| k != j && !p[k].is_zero())
        .ok_or_else(|| Error::Algebra("tangent plane basis".into()))?;
    let mut kernel = (0..4).filter(|&k| k != j && k != k0).map(|k| {
        let mut v = vec![IBig::ZERO; 4];
        v[k] = r[j].clone();
        v[j] = -r[k].clone();
        v
    });
    let (e1, e2) = (
        kernel.next().expect("two kernel vectors"),
        kernel.next().expect("two kernel vectors"),
    );
    let (me1, me2) = (mv(&e1), mv(&e2));
    let (s11, s12, s22) = (idot(&e1, &me1), idot(&e1, &me2), idot(&e2, &me2));
    Ok(Some(Tangent {
        m,
        p,
        j,
        e1,
        e2,
        s11,
        s12,
        s22,
    }))
}

/// The tangent data at a point and `√(s₁₂² − s₁₁s₂₂)` (`None` when `s₁₁ = 0`): what
/// [`doubly_ruled_integral`] needs before its lines.
pub(crate) struct Prepared {
    tangent: Tangent,
    root: Option<Quadratic>,
}

impl Prepared {
    /// The radicand of the lines: `None` when they are rational.
    pub(crate) fn radicand(&self) -> Option<IBig> {
        self.root
            .as_ref()
            .filter(|r| r.as_rational().is_none())
            .map(|r| r.radicand().clone())
    }
}

/// [`Prepared`] at an integer point `p` of `S`; `Ok(None)` if `p` is not integral or the
/// square root is not in a quadratic field.
///
/// # Errors
/// [`Error::Algebra`] when the lines through `p` are not real or `p` is in the kernel.
fn prepare(s: &[[RBig; 4]; 4], p: &[RBig; 4]) -> Result<Option<Prepared>, Error> {
    let Some(tangent) = tangent_plane(s, p)? else {
        return Ok(None);
    };
    if tangent.s11.is_zero() {
        return Ok(Some(Prepared {
            tangent,
            root: None,
        }));
    }
    let disc = &tangent.s12 * &tangent.s12 - &tangent.s11 * &tangent.s22;
    if disc <= IBig::ZERO {
        return Err(Error::Algebra(
            "no real lines through a point of an inertia (2, 2) member".into(),
        ));
    }
    let Some(root) = sqrt_in_field(&Quadratic::rational(RBig::from(disc)), None) else {
        return Ok(None);
    };
    Ok(Some(Prepared {
        tangent,
        root: Some(root),
    }))
}

/// What [`parameterize_doubly_ruled`] finds before the ruling when it goes through
/// [`small_point`] (always with [`doubly_ruled_integral`]): the ruling's radicand is then
/// [`Prepared::radicand`] (the lines through `p` are over ℚ(√(s₁₂² − s₁₁s₂₂)), rational when
/// `s₁₁ = 0`), and [`doubly_ruled_prepared`] finishes it. `None` when it does not go that
/// way (no small point, no real lines: the full computation then says what happens).
pub(crate) fn doubly_ruled_radicand(s: &[[RBig; 4]; 4]) -> Option<Prepared> {
    let p = small_point(s)?;
    prepare(s, &p).ok()?
}

/// [`parameterize_doubly_ruled`] from what [`doubly_ruled_radicand`] found: the same ruling.
///
/// # Errors
/// As [`parameterize_doubly_ruled`].
pub(crate) fn doubly_ruled_prepared(
    prepared: Prepared,
) -> Result<Option<RuledParameterization>, Error> {
    doubly_ruled_integral(prepared)
}

/// [`parameterize_doubly_ruled`] through an integer point `p` of `S`, fraction-free in ℤ[√δ]
/// on `M = k·S` (integer): `r = Mp`, the tangent plane `Kₖ = rⱼeₖ − rₖeⱼ`, the lines
/// `E± = (−s₁₂ ± √(s₁₂² − s₁₁s₂₂))·e₁ + s₁₁·e₂`, `c = E₊ᵀME₋`; `g₀ = c·eⱼ − (ME₋)ⱼ·E₊`,
/// `g₁ = c·g₀ − (g₀ᵀME₊)·E₋` (orthogonal to `E₊` and `E₋`), `ρ = pᵀMg₁`,
/// `f = 2ρ·g₁ − (g₁ᵀMg₁)·p` (isotropic, `pᵀMf = 2ρ²`); then `b = p − u·E₊` and
/// `d = 2ρ²·E₋ + u·c·f` (`pᵀMf·c = E₊ᵀM(2ρ²E₋)`, so `bᵀMd ≡ 0`). `Ok(None)` when a step
/// leaves ℤ[√δ] (a non-integral square root): the caller takes the rational route.
fn doubly_ruled_integral(prepared: Prepared) -> Result<Option<RuledParameterization>, Error> {
    use zsqrt::Zq;
    let Prepared { tangent, root } = prepared;
    let Tangent {
        m,
        p,
        j,
        e1,
        e2,
        s11,
        s12,
        s22,
    } = tangent;
    let (e1, e2) = (&e1, &e2);
    let zvec = |x: &[IBig]| -> Vec<Zq> { x.iter().cloned().map(Zq::int).collect() };
    let (plus, minus, delta) = if let Some(root) = root {
        let delta = root.radicand().clone();
        let Some(root) = Zq::from_quadratic(&root, &delta) else {
            return Ok(None);
        };
        let line = |sign: bool| -> Vec<Zq> {
            let rt = if sign { root.clone() } else { root.neg() };
            let k1 = Zq::int(-s12.clone()).add(&rt);
            (0..4)
                .map(|i| {
                    k1.mul(&Zq::int(e1[i].clone()), &delta)
                        .add(&Zq::int(&s11 * &e2[i]))
                })
                .collect()
        };
        (line(true), line(false), delta)
    } else {
        let minus: Vec<IBig> = (0..4)
            .map(|i| &s22 * &e1[i] - IBig::from(2) * &s12 * &e2[i])
            .collect();
        (zvec(e1), zvec(&minus), IBig::ZERO)
    };
    // balance the parameter: |E₊| about |p| (a power of two, exact), so that u has the
    // scale of the point and the roots of s(u) are neither huge nor tiny
    let size = |v: &[Zq]| -> f64 {
        let r = delta.to_f64().value().abs().sqrt();
        v.iter()
            .map(|x| x.a.to_f64().value().abs() + x.b.to_f64().value().abs() * r)
            .fold(0.0, f64::max)
    };
    let ratio = size(&zvec(&p)) / size(&plus);
    let plus: Vec<Zq> = if ratio.is_finite() && ratio >= 2.0 {
        let k = Zq::int(IBig::ONE << (ratio.log2().floor() as usize));
        plus.iter().map(|x| x.mul(&k, &delta)).collect()
    } else {
        plus
    };
    let p: Vec<IBig> = if ratio.is_finite() && ratio > 0.0 && ratio <= 0.5 {
        let k = IBig::ONE << ((1.0 / ratio).log2().floor() as usize);
        p.iter().map(|x| x * &k).collect()
    } else {
        p
    };
    let zm: Vec<Vec<Zq>> = m
        .iter()
        .map(|row| row.iter().cloned().map(Zq::int).collect())
        .collect();
    let zmv = |x: &[Zq]| -> Vec<Zq> {
        (0..4)
            .map(|i| {
                let mut acc = Zq::default();
                for k in 0..4 {
                    acc.add_mul(&zm[i][k], &x[k], &delta);
                }
                acc
            })
            .collect()
    };
    let zdot = |x: &[Zq], y: &[Zq]| -> Zq {
        let mut acc = Zq::default();
        for i in 0..4 {
            acc.add_mul(&x[i], &y[i], &delta);
        }
        acc
    };
    // a·x + b·y
    let comb = |a: &Zq, x: &[Zq], b: &Zq, y: &[Zq]| -> Vec<Zq> {
        (0..4)
            .map(|i| a.mul(&x[i], &delta).add(&b.mul(&y[i], &delta)))
            .collect()
    };
    let m_minus = zmv(&minus);
    let c = zdot(&plus, &m_minus);
    if c.is_zero() {
        return Err(Error::Algebra(
            "the two lines through a point are not distinct".into(),
        ));
    }
    let mut ej = vec![Zq::default(); 4];
    ej[j] = Zq::int(IBig::ONE);
    let g0 = comb(&c, &ej, &m_minus[j].neg(), &plus);
    let g0_plus = zdot(&g0, &zmv(&plus));
    let g1 = comb(&c, &g0, &g0_plus.neg(), &minus);
    let zp = zvec(&p);
    let mg1 = zmv(&g1);
    let rho = zdot(&zp, &mg1);
    let g1g1 = zdot(&g1, &mg1);
    let two = Zq::int(IBig::from(2));
    let f = comb(&two.mul(&rho, &delta), &g1, &g1g1.neg(), &zp);
    let two_rho2 = two.mul(&rho.mul(&rho, &delta), &delta);
    // b and d each scaled to coprime integers (as `primitive_poly` would, without rationals)
    let mut bz: [zsqrt::ZPoly; 4] = std::array::from_fn(|i| vec![zp[i].clone(), plus[i].neg()]);
    let mut dz: [zsqrt::ZPoly; 4] =
        std::array::from_fn(|i| vec![two_rho2.mul(&minus[i], &delta), c.mul(&f[i], &delta)]);
    zsqrt::make_primitive(&mut bz);
    zsqrt::make_primitive(&mut dz);
    let b: PolyVector = std::array::from_fn(|i| zsqrt::to_poly(&bz[i], &delta));
    let d: PolyVector = std::array::from_fn(|i| zsqrt::to_poly(&dz[i], &delta));
    let delta = radicand_of(b.iter().chain(d.iter()).flat_map(|x| x.coeffs()));
    Ok(Some(RuledParameterization { b, d, delta }))
}

/// `k·S` with integer entries, `k > 0` the least common denominator.
fn scaled_integer_matrix(s: &[[RBig; 4]; 4]) -> Option<[[IBig; 4]; 4]> {
    use dashu_int::ops::Gcd;
    let mut l = IBig::ONE;
    for v in s.iter().flatten() {
        let d = IBig::from(v.denominator().clone());
        let g = IBig::from(l.clone().gcd(&d));
        l = &l / &g * d;
    }
    let mut out: [[IBig; 4]; 4] = Default::default();
    for i in 0..4 {
        for j in 0..4 {
            let v = &s[i][j];
            out[i][j] = v.numerator() * &l / IBig::from(v.denominator().clone());
        }
    }
    Some(out)
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

    /// The integral `make_primitive` scales like `primitive_poly`.
    #[test]
    fn integral_primitive_is_primitive_poly() {
        let mut rng = qsic_algebra::testing::SplitMix(9);
        for delta in [0i64, 2, 6, 15] {
            let delta = IBig::from(delta);
            for _ in 0..50 {
                let k = rng.int(1, 12);
                let mut v: [zsqrt::ZPoly; 4] = std::array::from_fn(|_| {
                    (0..2)
                        .map(|_| zsqrt::Zq {
                            a: IBig::from(k * rng.int(-20, 20)),
                            b: if delta.is_zero() {
                                IBig::ZERO
                            } else {
                                IBig::from(k * rng.int(-3, 3))
                            },
                        })
                        .collect()
                });
                let before: PolyVector = std::array::from_fn(|i| zsqrt::to_poly(&v[i], &delta));
                zsqrt::make_primitive(&mut v);
                let after: PolyVector = std::array::from_fn(|i| zsqrt::to_poly(&v[i], &delta));
                assert_eq!(after, primitive_poly(&before));
            }
        }
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
            if let Some(p) = small_point(&m) {
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
