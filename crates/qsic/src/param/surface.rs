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
pub(crate) fn exact_sqrt(n: i128) -> Option<i128> {
    if n < 0 {
        return None;
    }
    // squares are 0, 1, 4, 9, 16, 17, 25, 33, 36, 41, 49, 57 modulo 64
    if (0x0202_0212_0203_0213u64 >> (n & 63)) & 1 == 0 {
        return None;
    }
    if let Ok(v) = u64::try_from(n) {
        // squares are 16 of the 63 residues modulo 63 (bit k of the mask: k a square)
        if (0x0402_4830_1245_0293u64 >> (v % 63)) & 1 == 0 {
            return None;
        }
        // the float root is within one of ⌊√v⌋; the products in u128, one multiplication
        let sq = |r: u64| u128::from(r) * u128::from(r);
        let mut r = (v as f64).sqrt() as u64;
        while sq(r) > u128::from(v) {
            r -= 1;
        }
        while sq(r + 1) <= u128::from(v) {
            r += 1;
        }
        return (sq(r) == u128::from(v)).then_some(i128::from(r));
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

/// An integer point of `XᵀMX = 0` found cheaply (`M` an integer matrix, entries below
/// `2⁴⁰`), `None` if none of the tried ones is: the vectors with entries in {−1, 0, 1}, then
/// the rational points of the lines joining two of them (`M` restricted to `P + t·Q` has
/// rational roots iff `M(P,Q)² − M(P,P)M(Q,Q)` is a square). Exact `i128` arithmetic
/// (products below `2¹²⁰`).
pub(crate) fn small_point_of(m: &[[i128; 4]; 4]) -> Option<[i128; 4]> {
    if m.iter().flatten().all(|x| x.unsigned_abs() < 1 << 24) {
        // |M(P, Q)| < 2²⁸: every product below 2⁵⁷
        let small = m.map(|row| row.map(|x| x as i64));
        return small_point_in(&small).map(|v| v.map(i128::from));
    }
    small_point_in(m)
}

/// The 40 projective classes of nonzero vectors in {−1, 0, 1}⁴ (first nonzero entry 1).
const SMALL_VECTORS: [[i8; 4]; 40] = small_vectors();

const fn small_vectors() -> [[i8; 4]; 40] {
    let mut out = [[0i8; 4]; 40];
    let (mut n, mut code) = (0, 0);
    while code < 81 {
        let mut v = [0i8; 4];
        let (mut c, mut i) = (code, 0);
        while i < 4 {
            v[i] = (c % 3) as i8 - 1;
            c /= 3;
            i += 1;
        }
        let mut k = 0;
        while k < 4 && v[k] == 0 {
            k += 1;
        }
        if k < 4 && v[k] == 1 {
            out[n] = v;
            n += 1;
        }
        code += 1;
    }
    out
}

/// [`small_point_of`] in `i64` or `i128` (the caller bounds the entries).
fn small_point_in<T>(m: &[[T; 4]; 4]) -> Option<[T; 4]>
where
    T: Copy
        + Default
        + PartialEq
        + From<i8>
        + Into<i128>
        + TryFrom<i128>
        + std::ops::Add<Output = T>
        + std::ops::Sub<Output = T>
        + std::ops::Mul<Output = T>,
{
    let vs: [[T; 4]; 40] = SMALL_VECTORS.map(|v| v.map(T::from));
    let mul = |x: &[T; 4]| -> [T; 4] {
        std::array::from_fn(|i| m[i][0] * x[0] + m[i][1] * x[1] + m[i][2] * x[2] + m[i][3] * x[3])
    };
    let dot =
        |x: &[T; 4], y: &[T; 4]| -> T { x[0] * y[0] + x[1] * y[1] + x[2] * y[2] + x[3] * y[3] };
    // the first isotropic vector, else all the values of the form
    let mut diag = [T::default(); 40];
    for (k, v) in vs.iter().enumerate() {
        diag[k] = dot(v, &mul(v));
        if diag[k] == T::default() {
            return Some(*v);
        }
    }
    for p in 0..40 {
        let mp = mul(&vs[p]);
        for q in p + 1..40 {
            let spq = dot(&mp, &vs[q]);
            let Some(r) = exact_sqrt((spq * spq - diag[p] * diag[q]).into()) else {
                continue;
            };
            let r = T::try_from(r).ok()?;
            // S(P + tQ) = 0 at t = (−S(P,Q) + r)/S(Q,Q): the point S(Q,Q)·P + (r − S(P,Q))·Q
            let (a, b) = (diag[q], r - spq);
            return Some(std::array::from_fn(|i| a * vs[p][i] + b * vs[q][i]));
        }
    }
    None
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

/// Integers for the fraction-free ruling ([`ruling_through`]): `i128` with every operation
/// checked (`None` on overflow sends the caller to `IBig`), and `IBig`, which never declines.
pub(crate) trait RulingInt: Clone + PartialEq + std::fmt::Debug {
    fn from_i128(v: i128) -> Self;
    fn is_zero(&self) -> bool;
    fn add(&self, o: &Self) -> Option<Self>;
    fn sub(&self, o: &Self) -> Option<Self>;
    fn mul(&self, o: &Self) -> Option<Self>;
    /// `gcd(|self|, |o|)`.
    fn gcd(&self, o: &Self) -> Self;
    /// `self / o`, `o` dividing `self`.
    fn div_exact(&self, o: &Self) -> Self;
    /// `self mod o == 0` for `o > 0`.
    fn divisible_by(&self, o: &Self) -> bool;
    /// `√self` when `self ≥ 0` is a perfect square.
    fn exact_sqrt(&self) -> Option<Self>;
    fn is_positive(&self) -> bool;
    fn to_ibig(&self) -> IBig;
    fn to_f64(&self) -> f64;
}

impl RulingInt for i128 {
    fn from_i128(v: i128) -> i128 {
        v
    }
    fn is_zero(&self) -> bool {
        *self == 0
    }
    fn add(&self, o: &i128) -> Option<i128> {
        self.checked_add(*o)
    }
    fn sub(&self, o: &i128) -> Option<i128> {
        self.checked_sub(*o)
    }
    fn mul(&self, o: &i128) -> Option<i128> {
        // one widening product for machine words, the overflow test only past them
        if let (Ok(x), Ok(y)) = (i64::try_from(*self), i64::try_from(*o)) {
            return Some(i128::from(x) * i128::from(y));
        }
        self.checked_mul(*o)
    }
    fn gcd(&self, o: &i128) -> i128 {
        let (mut x, mut y) = (self.unsigned_abs(), o.unsigned_abs());
        while y != 0 {
            if x <= u128::from(u64::MAX) && y <= u128::from(u64::MAX) {
                // the usual case: machine words
                let (mut a, mut b) = (x as u64, y as u64);
                while b != 0 {
                    (a, b) = (b, a % b);
                }
                return i128::from(a);
            }
            (x, y) = (y, x % y);
        }
        // below 2¹²⁷ unless both are i128::MIN, which checked products never reach
        x as i128
    }
    fn div_exact(&self, o: &i128) -> i128 {
        if let (Ok(x), Ok(y)) = (i64::try_from(*self), i64::try_from(*o)) {
            if y > 0 {
                return i128::from(x / y);
            }
        }
        self / o
    }
    fn divisible_by(&self, o: &i128) -> bool {
        if let (Ok(x), Ok(y)) = (i64::try_from(*self), i64::try_from(*o)) {
            if y > 0 {
                return x % y == 0;
            }
        }
        self % o == 0
    }
    fn exact_sqrt(&self) -> Option<i128> {
        // the correction steps of `exact_sqrt` square numbers near √n (no overflow below 2¹²⁰)
        if *self >= 1 << 120 {
            return None;
        }
        exact_sqrt(*self)
    }
    fn is_positive(&self) -> bool {
        *self > 0
    }
    fn to_ibig(&self) -> IBig {
        IBig::from(*self)
    }
    fn to_f64(&self) -> f64 {
        *self as f64
    }
}

impl RulingInt for IBig {
    fn from_i128(v: i128) -> IBig {
        IBig::from(v)
    }
    fn is_zero(&self) -> bool {
        *self == IBig::ZERO
    }
    fn add(&self, o: &IBig) -> Option<IBig> {
        Some(self + o)
    }
    fn sub(&self, o: &IBig) -> Option<IBig> {
        Some(self - o)
    }
    fn mul(&self, o: &IBig) -> Option<IBig> {
        Some(self * o)
    }
    fn gcd(&self, o: &IBig) -> IBig {
        use dashu_int::ops::Gcd;
        if self.is_zero() {
            return o * o.signum();
        }
        if o.is_zero() {
            return self * self.signum();
        }
        IBig::from(self.clone().gcd(o))
    }
    fn div_exact(&self, o: &IBig) -> IBig {
        self / o
    }
    fn divisible_by(&self, o: &IBig) -> bool {
        (self % o) == IBig::ZERO
    }
    fn exact_sqrt(&self) -> Option<IBig> {
        if *self < IBig::ZERO {
            return None;
        }
        Quadratic::sqrt(self)
            .as_rational()
            .map(|r| r.numerator().clone())
    }
    fn is_positive(&self) -> bool {
        *self > IBig::ZERO
    }
    fn to_ibig(&self) -> IBig {
        self.clone()
    }
    fn to_f64(&self) -> f64 {
        IBig::to_f64(self).value()
    }
}

/// `a + b√δ` over a [`RulingInt`] (`δ` held by the caller).
#[derive(Clone, Debug, PartialEq)]
struct Zs<T> {
    a: T,
    b: T,
}

impl<T: RulingInt> Zs<T> {
    fn int(a: T) -> Zs<T> {
        Zs {
            a,
            b: T::from_i128(0),
        }
    }
    fn zero() -> Zs<T> {
        Zs::int(T::from_i128(0))
    }
    fn is_zero(&self) -> bool {
        self.a.is_zero() && self.b.is_zero()
    }
    fn add(&self, o: &Zs<T>) -> Option<Zs<T>> {
        Some(Zs {
            a: self.a.add(&o.a)?,
            b: self.b.add(&o.b)?,
        })
    }
    fn neg(&self) -> Option<Zs<T>> {
        let zero = T::from_i128(0);
        Some(Zs {
            a: zero.sub(&self.a)?,
            b: zero.sub(&self.b)?,
        })
    }
    fn mul(&self, o: &Zs<T>, delta: &T) -> Option<Zs<T>> {
        if self.b.is_zero() && o.b.is_zero() {
            return Some(Zs::int(self.a.mul(&o.a)?));
        }
        Some(Zs {
            a: self.a.mul(&o.a)?.add(&self.b.mul(&o.b)?.mul(delta)?)?,
            b: self.a.mul(&o.b)?.add(&self.b.mul(&o.a)?)?,
        })
    }
    fn scale(&self, k: &T) -> Option<Zs<T>> {
        Some(Zs {
            a: self.a.mul(k)?,
            b: self.b.mul(k)?,
        })
    }
    /// `a + b√δ` with `root = √δ` ([`Quadratic::sqrt`], irrational): no square test.
    fn to_quadratic_in(&self, root: &Quadratic) -> Quadratic {
        if self.b.is_zero() {
            return Quadratic::rational(RBig::from(self.a.to_ibig()));
        }
        assert!(root.as_rational().is_none(), "δ is not a square");
        Quadratic::in_field_of(
            RBig::from(self.a.to_ibig()),
            RBig::from(self.b.to_ibig()),
            root,
        )
    }
}

/// The gcd of all the integers `a`, `b` of some elements of ℤ[√δ] (zero for all zeros).
fn content<'a, T: RulingInt + 'a>(xs: impl IntoIterator<Item = &'a Zs<T>>) -> T {
    let mut g = T::from_i128(0);
    for x in xs {
        for part in [&x.a, &x.b] {
            if !part.is_zero() && g != T::from_i128(1) {
                g = g.gcd(part);
            }
        }
    }
    g
}

/// Each element divided by `g` (a common divisor; nothing for zero or one).
fn divide_by<T: RulingInt>(xs: &mut [Zs<T>], g: &T) {
    if g.is_zero() || *g == T::from_i128(1) {
        return;
    }
    for x in xs.iter_mut() {
        x.a = x.a.div_exact(g);
        x.b = x.b.div_exact(g);
    }
}

/// The ruling of `S` through the integer point `p` of the integer matrix `M = k·S` (`k > 0`),
/// fraction-free in ℤ[√δ], `δ` the square-free part of `det M` (one for a square): `r = Mp`,
/// the tangent plane `Kₖ = rⱼeₖ − rₖeⱼ` (`e₁`, `e₂` two of them, made primitive), the binary
/// form `sᵢⱼ = eᵢᵀMeⱼ` on them and its lines `E± = (−s₁₂ ± t√δ)·e₁ + s₁₁·e₂` with
/// `t²δ = s₁₂² − s₁₁s₂₂` (over ℚ(√det M) since that discriminant times `(pᵀMx)²` is
/// `det M·det(p, e₁, e₂, x)²`), divided by their content; `c = E₊ᵀME₋`;
/// `g₀ = c·eⱼ − (ME₋)ⱼ·E₊`, `g₁ = c·g₀ − (g₀ᵀME₊)·E₋` (orthogonal to `E₊` and `E₋`, each
/// made primitive), `ρ = pᵀMg₁`, `f = 2ρ·g₁ − (g₁ᵀMg₁)·p` (isotropic, `pᵀMf = 2ρ²`); then
/// `b = p − u·E₊` and `d = 2ρ²·E₋ + u·c·f` (`pᵀMf·c = E₊ᵀM(2ρ²E₋)`, so `bᵀMd ≡ 0`), each
/// scaled to coprime integers. `Ok(None)` when an operation overflows `T` or `δ` does not
/// give an integral `t` (only when `δ` is not `det M`'s square-free part).
///
/// # Errors
/// [`Error::Algebra`] when `p` is in the kernel, the lines are not real or not distinct (`S`
/// is not a nonsingular quadric of inertia (2, 2) through `p`).
fn ruling_through<T: RulingInt>(
    m: &[[T; 4]; 4],
    p: &[T; 4],
    delta: &T,
) -> Result<Option<RuledParameterization>, Error> {
    let zero = T::from_i128(0);
    let one = T::from_i128(1);
    macro_rules! ck {
        ($e:expr) => {
            match $e {
                Some(v) => v,
                None => return Ok(None),
            }
        };
    }
    let mv = |x: &[T; 4]| -> Option<[T; 4]> {
        try4(|i| {
            let mut acc = T::from_i128(0);
            for k in 0..4 {
                if !x[k].is_zero() && !m[i][k].is_zero() {
                    acc = acc.add(&m[i][k].mul(&x[k])?)?;
                }
            }
            Some(acc)
        })
    };
    let idot = |x: &[T; 4], y: &[T; 4]| -> Option<T> {
        let mut acc = T::from_i128(0);
        for i in 0..4 {
            if !x[i].is_zero() && !y[i].is_zero() {
                acc = acc.add(&x[i].mul(&y[i])?)?;
            }
        }
        Some(acc)
    };
    let primitive_int = |v: [T; 4]| -> [T; 4] {
        let g = v.iter().fold(T::from_i128(0), |g, x| g.gcd(x));
        if g.is_zero() || g == T::from_i128(1) {
            v
        } else {
            v.map(|x| x.div_exact(&g))
        }
    };
    let p = primitive_int(p.clone());
    let r = ck!(mv(&p));
    let j = (0..4)
        .find(|&k| !r[k].is_zero())
        .ok_or_else(|| Error::Algebra("a point in the kernel of a nonsingular quadric".into()))?;
    let k0 = (0..4)
        .find(|&k| k != j && !p[k].is_zero())
        .ok_or_else(|| Error::Algebra("tangent plane basis".into()))?;
    let mut rest = (0..4).filter(|&k| k != j && k != k0);
    let kernel_vector = |k: usize| -> Option<[T; 4]> {
        let mut v: [T; 4] = std::array::from_fn(|_| T::from_i128(0));
        v[k] = r[j].clone();
        v[j] = T::from_i128(0).sub(&r[k])?;
        Some(primitive_int(v))
    };
    let e1 = ck!(kernel_vector(rest.next().expect("two kernel vectors")));
    let e2 = ck!(kernel_vector(rest.next().expect("two kernel vectors")));
    let (me1, me2) = (ck!(mv(&e1)), ck!(mv(&e2)));
    let (s11, s12, s22) = (
        ck!(idot(&e1, &me1)),
        ck!(idot(&e1, &me2)),
        ck!(idot(&e2, &me2)),
    );
    let zvec = |x: &[T; 4]| -> [Zs<T>; 4] { x.clone().map(Zs::int) };
    let irrational = *delta != one;
    let (mut plus, mut minus) = if s11.is_zero() {
        let two_s12 = ck!(s12.add(&s12));
        let minus: [T; 4] = ck!(try4(|i| s22.mul(&e1[i])?.sub(&two_s12.mul(&e2[i])?)));
        (zvec(&e1), zvec(&minus))
    } else {
        let disc = ck!(ck!(s12.mul(&s12)).sub(&ck!(s11.mul(&s22))));
        if !disc.is_positive() {
            return Err(Error::Algebra(
                "no real lines through a point of an inertia (2, 2) member".into(),
            ));
        }
        let root = if irrational {
            if !disc.divisible_by(delta) {
                return Ok(None);
            }
            Zs {
                a: zero.clone(),
                b: ck!(disc.div_exact(delta).exact_sqrt()),
            }
        } else {
            Zs::int(ck!(disc.exact_sqrt()))
        };
        let minus_s12 = Zs::int(ck!(zero.sub(&s12)));
        let line = |rt: &Zs<T>| -> Option<[Zs<T>; 4]> {
            let k1 = minus_s12.add(rt)?;
            try4(|i| k1.scale(&e1[i])?.add(&Zs::int(s11.mul(&e2[i])?)))
        };
        (ck!(line(&root)), ck!(line(&ck!(root.neg()))))
    };
    {
        let g = content(plus.iter().chain(minus.iter()));
        divide_by(&mut plus, &g);
        divide_by(&mut minus, &g);
    }
    let d_t = if irrational {
        delta.clone()
    } else {
        zero.clone()
    };
    // balance the parameter: |E₊| about |p| (a power of two, exact), so that u has the
    // scale of the point and the roots of s(u) are neither huge nor tiny
    let root_delta = d_t.to_f64().abs().sqrt();
    let size = |v: &[Zs<T>]| -> f64 {
        v.iter()
            .map(|x| x.a.to_f64().abs() + x.b.to_f64().abs() * root_delta)
            .fold(0.0, f64::max)
    };
    let ratio = size(&zvec(&p)) / size(&plus);
    let two = T::from_i128(2);
    let pow2 = |e: usize| -> Option<T> {
        let mut k = T::from_i128(1);
        for _ in 0..e {
            k = k.mul(&two)?;
        }
        Some(k)
    };
    if ratio.is_finite() && ratio >= 2.0 {
        let k = ck!(pow2(ratio.log2().floor() as usize));
        plus = ck!(try4(|i| plus[i].scale(&k)));
    }
    let p: [T; 4] = if ratio.is_finite() && ratio > 0.0 && ratio <= 0.5 {
        let k = ck!(pow2((1.0 / ratio).log2().floor() as usize));
        ck!(try4(|i| p[i].mul(&k)))
    } else {
        p
    };
    let zmv = |x: &[Zs<T>; 4]| -> Option<[Zs<T>; 4]> {
        try4(|i| {
            let mut acc = Zs::zero();
            for k in 0..4 {
                if !x[k].is_zero() && !m[i][k].is_zero() {
                    acc = acc.add(&x[k].scale(&m[i][k])?)?;
                }
            }
            Some(acc)
        })
    };
    let zdot = |x: &[Zs<T>; 4], y: &[Zs<T>; 4]| -> Option<Zs<T>> {
        let mut acc = Zs::zero();
        for i in 0..4 {
            if !x[i].is_zero() && !y[i].is_zero() {
                acc = acc.add(&x[i].mul(&y[i], &d_t)?)?;
            }
        }
        Some(acc)
    };
    // a·x + b·y
    let comb = |a: &Zs<T>, x: &[Zs<T>; 4], b: &Zs<T>, y: &[Zs<T>; 4]| -> Option<[Zs<T>; 4]> {
        try4(|i| a.mul(&x[i], &d_t)?.add(&b.mul(&y[i], &d_t)?))
    };
    let m_minus = ck!(zmv(&minus));
    let c = ck!(zdot(&plus, &m_minus));
    if c.is_zero() {
        return Err(Error::Algebra(
            "the two lines through a point are not distinct".into(),
        ));
    }
    let mut ej: [Zs<T>; 4] = std::array::from_fn(|_| Zs::zero());
    ej[j] = Zs::int(one.clone());
    let mut g0 = ck!(comb(&c, &ej, &ck!(m_minus[j].neg()), &plus));
    let g = content(g0.iter());
    divide_by(&mut g0, &g);
    let g0_plus = ck!(zdot(&g0, &ck!(zmv(&plus))));
    let mut g1 = ck!(comb(&c, &g0, &ck!(g0_plus.neg()), &minus));
    let g = content(g1.iter());
    divide_by(&mut g1, &g);
    let zp = zvec(&p);
    let mg1 = ck!(zmv(&g1));
    let rho = ck!(zdot(&zp, &mg1));
    let g1g1 = ck!(zdot(&g1, &mg1));
    let two_z = Zs::int(two);
    let f = ck!(comb(
        &ck!(two_z.mul(&rho, &d_t)),
        &g1,
        &ck!(g1g1.neg()),
        &zp
    ));
    let two_rho2 = ck!(two_z.mul(&ck!(rho.mul(&rho, &d_t)), &d_t));
    // b and d each scaled to coprime integers
    let mut bz: [[Zs<T>; 2]; 4] = ck!(try4(|i| Some([zp[i].clone(), plus[i].neg()?])));
    let mut dz: [[Zs<T>; 2]; 4] = ck!(try4(|i| Some([
        two_rho2.mul(&minus[i], &d_t)?,
        c.mul(&f[i], &d_t)?
    ])));
    let g = content(bz.as_flattened());
    divide_by(bz.as_flattened_mut(), &g);
    let g = content(dz.as_flattened());
    divide_by(dz.as_flattened_mut(), &g);
    // one square test for all the coefficients (`δ` is not a square when irrational)
    let root = if irrational {
        Quadratic::sqrt(&d_t.to_ibig())
    } else {
        Quadratic::zero()
    };
    let to_poly = |v: &[Zs<T>]| -> Poly<Quadratic> {
        Poly::new(v.iter().map(|x| x.to_quadratic_in(&root)).collect())
    };
    let b: PolyVector = std::array::from_fn(|i| to_poly(&bz[i]));
    let d: PolyVector = std::array::from_fn(|i| to_poly(&dz[i]));
    let delta = radicand_of(b.iter().chain(d.iter()).flat_map(|x| x.coeffs()));
    Ok(Some(RuledParameterization { b, d, delta }))
}

/// `[f(0), f(1), f(2), f(3)]`, `None` if one is.
fn try4<X>(mut f: impl FnMut(usize) -> Option<X>) -> Option<[X; 4]> {
    Some([f(0)?, f(1)?, f(2)?, f(3)?])
}

/// [`ruling_through`] in `i128` (entries of `M` and `p` as given), falling back to `IBig`
/// when an operation overflows: the same ruling either way.
///
/// # Errors
/// As [`ruling_through`].
pub(crate) fn ruling_through_small(
    m: &[[i128; 4]; 4],
    p: &[i128; 4],
    delta: &IBig,
) -> Result<Option<RuledParameterization>, Error> {
    if let Ok(dl) = i128::try_from(delta) {
        if let Some(r) = ruling_through(m, p, &dl)? {
            return Ok(Some(r));
        }
    }
    let mb: [[IBig; 4]; 4] = std::array::from_fn(|i| std::array::from_fn(|j| IBig::from(m[i][j])));
    let pb: [IBig; 4] = std::array::from_fn(|i| IBig::from(p[i]));
    ruling_through(&mb, &pb, delta)
}

/// The entries of an integer-valued rational matrix as `i128`, `None` if one is not an
/// integer or has `2⁴⁰` or more in absolute value.
pub(crate) fn integer_entries(s: &[[RBig; 4]; 4]) -> Option<[[i128; 4]; 4]> {
    let mut out = [[0i128; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            let v = &s[i][j];
            if *v.denominator() != dashu_int::UBig::ONE {
                return None;
            }
            let n = i128::try_from(v.numerator()).ok()?;
            if n.unsigned_abs() >= 1 << 40 {
                return None;
            }
            out[i][j] = n;
        }
    }
    Some(out)
}

/// `M = n·A − d·B` for `λ = n/d` (`d > 0`): `d` times the member `λA − B`, with `d`; `None`
/// when an entry reaches `2⁴⁰` in absolute value (the bound of [`small_point_of`]).
pub(crate) fn small_member(
    a: &[[i128; 4]; 4],
    b: &[[i128; 4]; 4],
    lambda: &RBig,
) -> Option<([[i128; 4]; 4], i128)> {
    let n = i128::try_from(lambda.numerator()).ok()?;
    let d = i128::try_from(&IBig::from(lambda.denominator().clone())).ok()?;
    if n.unsigned_abs() >= 1 << 60 || d >= 1 << 60 {
        return None;
    }
    let bits = |v: u128| 128 - v.leading_zeros();
    let max = |m: &[[i128; 4]; 4]| {
        m.as_flattened()
            .iter()
            .fold(0, |acc, v| acc | v.unsigned_abs())
    };
    // |n·a| < 2¹²⁵ and |d·b| < 2¹²⁵: no overflow (the common case), else checked
    let plain = bits(n.unsigned_abs()) + bits(max(a)) <= 125
        && bits(d.unsigned_abs()) + bits(max(b)) <= 125;
    let mut out = [[0i128; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            let v = if plain {
                n * a[i][j] - d * b[i][j]
            } else {
                n.checked_mul(a[i][j])?
                    .checked_sub(d.checked_mul(b[i][j])?)?
            };
            if v.unsigned_abs() >= 1 << 40 {
                return None;
            }
            out[i][j] = v;
        }
    }
    Some((out, d))
}

/// The member `M/d` as rationals (see [`small_member`]).
pub(crate) fn member_from_small(m: &[[i128; 4]; 4], d: i128) -> [[RBig; 4]; 4] {
    let den = IBig::from(d);
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            if d == 1 {
                RBig::from(m[i][j])
            } else {
                RBig::from_parts_signed(IBig::from(m[i][j]), den.clone())
            }
        })
    })
}

/// `det M` by the Laplace expansion along the first two rows, every operation checked
/// unless the entries are below `2³⁰` (then the 2 × 2 minors are below `2⁶¹`, their
/// products below `2¹²²` and the sum of six below `2¹²⁵`).
fn det_checked(m: &[[i128; 4]; 4]) -> Option<i128> {
    if m.as_flattened().iter().all(|v| v.unsigned_abs() < 1 << 30) {
        let minor = |r0: usize, r1: usize, c0: usize, c1: usize| {
            m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]
        };
        return Some(
            minor(0, 1, 0, 1) * minor(2, 3, 2, 3) - minor(0, 1, 0, 2) * minor(2, 3, 1, 3)
                + minor(0, 1, 0, 3) * minor(2, 3, 1, 2)
                + minor(0, 1, 1, 2) * minor(2, 3, 0, 3)
                - minor(0, 1, 1, 3) * minor(2, 3, 0, 2)
                + minor(0, 1, 2, 3) * minor(2, 3, 0, 1),
        );
    }
    let minor = |r0: usize, r1: usize, c0: usize, c1: usize| -> Option<i128> {
        m[r0][c0]
            .checked_mul(m[r1][c1])?
            .checked_sub(m[r0][c1].checked_mul(m[r1][c0])?)
    };
    let mut acc = 0i128;
    // the columns of the top minor, the complementary ones, the sign
    for (c0, c1, d0, d1, sign) in [
        (0, 1, 2, 3, 1),
        (0, 2, 1, 3, -1),
        (0, 3, 1, 2, 1),
        (1, 2, 0, 3, 1),
        (1, 3, 0, 2, -1),
        (2, 3, 0, 1, 1),
    ] {
        let t = minor(0, 1, c0, c1)?.checked_mul(minor(2, 3, d0, d1)?)?;
        acc = if sign > 0 {
            acc.checked_add(t)?
        } else {
            acc.checked_sub(t)?
        };
    }
    Some(acc)
}

/// The square-free part `f` of `n > 0` (`n = k²f`): trial division by 2, 3 and the numbers
/// `6i ± 1` while their cube stays below the cofactor (then the cofactor has at most two
/// prime factors, all above the divisors tried, and is square-free unless a perfect square);
/// [`factorize`] when that would take divisors past `2¹²`. `None` if factoring fails.
pub(crate) fn squarefree_part(n: &IBig) -> Option<IBig> {
    if *n <= IBig::ZERO {
        return None;
    }
    if let Ok(v) = u64::try_from(n) {
        if let Some(f) = squarefree_part_u64(v) {
            return Some(IBig::from(f));
        }
    }
    let f = factorize(n).ok()?;
    Some(f.squarefree_split().0.value())
}

fn squarefree_part_u64(n: u64) -> Option<u64> {
    const LIMIT: u64 = 1 << 12;
    // divides out d; whether its exponent was odd
    fn remove(d: u64, rest: &mut u64) -> bool {
        let mut odd = false;
        while *rest % d == 0 {
            *rest /= d;
            odd = !odd;
        }
        odd
    }
    let mut rest = n;
    let mut f = 1u64;
    for d in [2, 3] {
        if remove(d, &mut rest) {
            f *= d;
        }
    }
    let mut d = 5u64;
    loop {
        for dd in [d, d + 2] {
            if dd * dd * dd > rest {
                if rest > 1 && exact_sqrt(i128::from(rest)).is_none() {
                    f *= rest;
                }
                return Some(f);
            }
            if remove(dd, &mut rest) {
                f *= dd;
            }
        }
        d += 6;
        if d > LIMIT {
            return None;
        }
    }
}

/// The radicand of the rulings of the nonsingular member `M` of inertia (2, 2) through a
/// rational point: the square-free part of `det M` (`1` when it is a square). `None` when the
/// determinant overflows `i128`, is not positive, or cannot be factored.
pub(crate) fn member_radicand(m: &[[i128; 4]; 4]) -> Option<IBig> {
    let det = det_checked(m)?;
    if det <= 0 {
        return None;
    }
    squarefree_part(&IBig::from(det))
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
                    let got = r.to_ruling();
                    assert_eq!(Some(got.clone()), want.expect("a ruling"), "{m:?}");
                    let s: [[RBig; 4]; 4] = m.map(|row| row.map(RBig::from));
                    assert_ruled(&s, &got);
                    // the reduction keeps it a ruling of the same surface
                    let mut reduced = r;
                    reduced.reduce();
                    assert_ruled(&s, &reduced.to_ruling());
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
