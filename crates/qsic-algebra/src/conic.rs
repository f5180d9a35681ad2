//! Rational points on conics `XᵀCX = 0` (`C` a symmetric 3×3 rational matrix, `X = (x, y, z)`):
//! Legendre's theorem decided exactly, a point when there is one, a point over ℚ(√δ) when there
//! is none, and the rational parameterization through a rational point.
//!
//! | entry point | does |
//! |---|---|
//! | [`find_point`] | a rational point of any conic, or why there is none ([`ConicPoint`]) |
//! | [`solve_legendre`] | a nonzero integer solution of `a x² + b y² + c z² = 0`, or `None` |
//! | [`parameterize`] | the lines through a rational point: quadratic forms `P¹(ℚ) → conic` |
//!
//! **Method.** `C` is diagonalized by congruence over ℚ, the diagonal is made integral,
//! square-free and pairwise coprime (`a, b, c`), which needs their factorizations
//! ([`crate::factor`]). Legendre: `a x² + b y² + c z² = 0` has a nonzero integer solution iff
//! `a, b, c` are not all of one sign and `−bc`, `−ca`, `−ab` are squares modulo `|a|`, `|b|`, `|c|`.
//! The solution is constructed (Minkowski's proof made effective): with square roots of those
//! residues, the vectors of a lattice `Λ` of index `|abc|` all have `Q(v) ≡ 0 (mod abc)`; with
//! `a, b > 0 > c`, an LLL-reduced (δ = 99/100) first vector of `Λ` for the norm
//! `F = a x² + b y² + 2|c| z²` has `F < 1.71|abc|`, hence `Q(v) ∈ {0, −abc}`, and in the second
//! case `(xz + by, yz − ax, z² + ab)` is a solution, since
//! `a(xz + by)² + b(yz − ax)² + c(z² + ab)² = (z² + ab)(Q(v) + abc)`. No search.
//!
//! **Certainty.** A returned point is checked on its conic, and every square root modulo a
//! prime is checked by squaring. "No rational point" rests on a prime `p | a` with Jacobi
//! symbol `(−bc/p) = −1`: exact for the primes [`crate::factor`] finds (proven primes below
//! `2⁸¹`, strong probable primes to 20 bases above).
//!
//! **Cost.** Factoring the numerators and denominators of the diagonal (primes found once are
//! divided out of the others) dominates, bounded by [`crate::factor`]; then square roots modulo
//! each prime (`O(log p)` products) and one LLL in dimension 3 on `O(log|abc|)`-bit numbers.
//! Measured (release build) on random symmetric integer matrices: 16-bit entries ≈ 1.5 ms,
//! 32-bit ≈ 5 ms, 40-bit ≈ 70 ms on average (≈ 1.5 s at worst, in Pollard's rho); from about
//! 44-bit entries the determinant often leaves a cofactor above 2¹²⁸: [`ConicError::Factor`].

use crate::factor::{factorize, jacobi, sqrt_mod_prime, FactorError, Factorization};
use crate::field::Quadratic;
use crate::linalg::{minors, Matrix};
use dashu_int::IBig;
use dashu_ratio::RBig;
use std::fmt;

/// Why a conic question was not answered.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ConicError {
    /// The matrix is not symmetric: entry `(row, col)` differs from `(col, row)`.
    NotSymmetric {
        /// Row of the first asymmetric entry.
        row: usize,
        /// Column of the first asymmetric entry.
        col: usize,
    },
    /// The zero matrix is no conic.
    ZeroMatrix,
    /// A coefficient could not be factored within the bounds of [`crate::factor`].
    Factor(FactorError),
    /// The point given to [`parameterize`] is zero.
    ZeroPoint,
    /// The point given to [`parameterize`] is not on the conic.
    PointNotOnConic,
    /// [`parameterize`] needs a non-degenerate conic (rank 3).
    Degenerate,
}

impl fmt::Display for ConicError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ConicError::NotSymmetric { row, col } => write!(
                f,
                "conic matrix is not symmetric: entry ({row}, {col}) differs from ({col}, {row})"
            ),
            ConicError::ZeroMatrix => write!(f, "the zero matrix is not a conic"),
            ConicError::Factor(e) => write!(f, "conic coefficient: {e}"),
            ConicError::ZeroPoint => write!(f, "the point (0, 0, 0) is not a projective point"),
            ConicError::PointNotOnConic => write!(f, "the point is not on the conic"),
            ConicError::Degenerate => write!(f, "the conic is degenerate (rank below 3)"),
        }
    }
}

impl std::error::Error for ConicError {}

impl From<FactorError> for ConicError {
    fn from(e: FactorError) -> ConicError {
        ConicError::Factor(e)
    }
}

/// A point with coordinates in ℚ(√δ), `δ > 1` a square-free integer, at least one coordinate
/// irrational.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct QuadraticPoint {
    /// The square-free radicand `δ`.
    pub delta: IBig,
    /// Homogeneous coordinates `aᵢ + bᵢ√δ`, with integer `aᵢ, bᵢ` of gcd 1.
    pub coords: [Quadratic; 3],
}

/// What [`find_point`] found on a conic.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ConicPoint {
    /// A rational point, as coprime integers with the first nonzero one positive.
    Rational([RBig; 3]),
    /// Real points but no rational one; a point over a quadratic field.
    NoRationalPoint(Box<QuadraticPoint>),
    /// A definite conic: no real point at all.
    NoRealPoint,
}

/// A rational point of the conic `XᵀCX = 0`, or the reason there is none.
///
/// * rank 3: Legendre's theorem (module doc). Without a rational point but with real ones, the
///   point is over ℚ(√δ) with `δ = −fᵢfⱼ` for the pair of opposite-sign coefficients of the
///   reduced diagonal form `Σ fᵢWᵢ²` with the least `|fᵢfⱼ|`;
/// * rank 2 (two lines): their rational intersection; rank 1 (a double line): a point of it.
///
/// # Errors
/// [`ConicError::NotSymmetric`], [`ConicError::ZeroMatrix`], and [`ConicError::Factor`] when a
/// numerator or denominator of the diagonalized form exceeds the factoring bounds.
///
/// # Examples
/// ```
/// use qsic_algebra::conic::{find_point, ConicPoint};
/// use qsic_algebra::{IBig, RBig};
/// let diag = |a: i64, b: i64, c: i64| {
///     let r = |v: i64| RBig::from(v);
///     [[r(a), r(0), r(0)], [r(0), r(b), r(0)], [r(0), r(0), r(c)]]
/// };
/// // x² + y² − 2z²: the point (1, 1, 1) or another one.
/// let ConicPoint::Rational(p) = find_point(&diag(1, 1, -2)).unwrap() else { panic!() };
/// assert_eq!(&p[0] * &p[0] + &p[1] * &p[1], RBig::from(2) * &p[2] * &p[2]);
/// // x² + y² − 3z²: none (3 is no sum of two rational squares), but (√3, 0, 1) is a point.
/// let ConicPoint::NoRationalPoint(q) = find_point(&diag(1, 1, -3)).unwrap() else { panic!() };
/// assert_eq!(q.delta, IBig::from(3));
/// assert_eq!(find_point(&diag(1, 1, 1)).unwrap(), ConicPoint::NoRealPoint);
/// ```
pub fn find_point(c: &[[RBig; 3]; 3]) -> Result<ConicPoint, ConicError> {
    check_symmetric(c)?;
    if c.iter().flatten().all(|v| v.is_zero()) {
        return Err(ConicError::ZeroMatrix);
    }
    let dg = Matrix::from_array(c.clone())
        .diagonalize_congruent()
        .expect("checked symmetric");
    let t: [[RBig; 3]; 3] = dg.p.to_array().expect("a 3 × 3 transform");
    let d = dg.d;
    if let Some(k) = d.iter().position(|v| v.is_zero()) {
        // T e_k spans (part of) the kernel: a singular point, on the conic.
        let col: Vec<RBig> = (0..3).map(|i| t[i][k].clone()).collect();
        return Ok(ConicPoint::Rational(to_array(primitive(&col))));
    }
    let positive = d.iter().filter(|v| **v > RBig::ZERO).count();
    if positive == 0 || positive == 3 {
        return Ok(ConicPoint::NoRealPoint);
    }
    // dᵢ = nᵢ/mᵢ: dᵢYᵢ² = (nᵢmᵢ)(Yᵢ/mᵢ)², so Yᵢ = mᵢ·Y'ᵢ with the integer coefficient nᵢmᵢ.
    // The parts share primes (from an integer matrix they are quotients of leading minors):
    // primes found once are divided out before factoring the rest.
    let mut known: Vec<u128> = Vec::new();
    let mut factor_once = |n: &IBig| -> Result<Factorization, ConicError> {
        let mut rest = n.clone();
        let mut factors = Vec::new();
        for &p in &known {
            let pb = IBig::from(p);
            let mut e = 0;
            while (&rest % &pb).is_zero() {
                rest /= &pb;
                e += 1;
            }
            if e > 0 {
                factors.push((p, e));
            }
        }
        let f = factorize(&rest)?;
        for &(p, _) in &f.factors {
            known.push(p);
        }
        factors.extend(f.factors);
        factors.sort_unstable();
        Ok(Factorization {
            negative: false,
            factors,
        })
    };
    let mut factored = Vec::with_capacity(3);
    let mut scale: Vec<RBig> = Vec::with_capacity(3);
    for di in &d {
        let den = IBig::from(di.denominator().clone());
        let fnum = factor_once(&abs(di.numerator()))?;
        let fden = factor_once(&den)?;
        factored.push(multiply(&fnum, &fden, *di < RBig::ZERO));
        scale.push(RBig::from(den));
    }
    let (coefs, s) = reduce(&factored);
    for i in 0..3 {
        scale[i] *= &s[i];
    }
    let apply = |w: &[RBig; 3]| -> [RBig; 3] {
        let y: Vec<RBig> = (0..3).map(|i| &scale[i] * &w[i]).collect();
        std::array::from_fn(|i| (0..3).fold(RBig::ZERO, |acc, j| acc + &t[i][j] * &y[j]))
    };
    if let Some(w) = solve_reduced(&coefs)? {
        let x = apply(&w.map(RBig::from));
        return Ok(ConicPoint::Rational(to_array(primitive(&x))));
    }
    // No rational point: fᵢWᵢ² + fⱼWⱼ² = 0 at W = (√δ, fᵢ) with δ = −fᵢfⱼ.
    let (i, j) = [(0, 1), (0, 2), (1, 2)]
        .into_iter()
        .filter(|&(i, j)| coefs[i].value.signum() != coefs[j].value.signum())
        .min_by_key(|&(i, j)| abs(&(&coefs[i].value * &coefs[j].value)))
        .expect("an indefinite form has coefficients of both signs");
    let delta = -(&coefs[i].value * &coefs[j].value);
    let mut wr: [RBig; 3] = Default::default();
    let mut wi: [RBig; 3] = Default::default();
    wr[j] = RBig::from(coefs[i].value.clone());
    wi[i] = RBig::ONE;
    let (xr, xi) = (apply(&wr), apply(&wi));
    let all: Vec<RBig> = xr.iter().chain(xi.iter()).cloned().collect();
    let ints = primitive(&all);
    let coords = std::array::from_fn(|k| {
        Quadratic::new(
            RBig::from(ints[k].clone()),
            RBig::from(ints[k + 3].clone()),
            delta.clone(),
        )
        .expect("δ is not a square, else (1, 1, 0) would have been a rational point")
    });
    Ok(ConicPoint::NoRationalPoint(Box::new(QuadraticPoint {
        delta,
        coords,
    })))
}

/// A nonzero integer solution of `a x² + b y² + c z² = 0` (coprime, first nonzero entry
/// positive), or `None` if there is none; `a, b, c` are any nonzero integers.
///
/// # Errors
/// [`ConicError::ZeroMatrix`] if a coefficient is zero (the form is then degenerate: use
/// [`find_point`]); [`ConicError::Factor`] if a coefficient exceeds the factoring bounds.
///
/// # Examples
/// ```
/// use qsic_algebra::conic::solve_legendre;
/// use qsic_algebra::IBig;
/// let (a, b, c) = (IBig::from(3), IBig::from(-5), IBig::from(-7));
/// let v = solve_legendre(&a, &b, &c).unwrap().unwrap(); // (2, 1, 1), or another
/// assert_eq!(&a * &v[0] * &v[0] + &b * &v[1] * &v[1] + &c * &v[2] * &v[2], IBig::ZERO);
/// // 3x² − 5y² + 7z²: −bc = 35 is no square modulo 3.
/// assert_eq!(solve_legendre(&a, &b, &(-&c)).unwrap(), None);
/// ```
pub fn solve_legendre(a: &IBig, b: &IBig, c: &IBig) -> Result<Option<[IBig; 3]>, ConicError> {
    if a.is_zero() || b.is_zero() || c.is_zero() {
        return Err(ConicError::ZeroMatrix);
    }
    let factored = [factorize(a)?, factorize(b)?, factorize(c)?];
    let (coefs, scale) = reduce(&factored);
    let Some(w) = solve_reduced(&coefs)? else {
        return Ok(None);
    };
    let x: Vec<RBig> = (0..3)
        .map(|i| &scale[i] * RBig::from(w[i].clone()))
        .collect();
    let v = primitive(&x);
    Ok(Some(std::array::from_fn(|i| v[i].clone())))
}

/// The rational parameterization of a non-degenerate conic through one of its rational points
/// `P`: the second intersection with the conic of the line through `P` and `V(s, t) = sQ + tR`,
///
/// `X(s, t) = 2(PᵀCV)·V − (VᵀCV)·P`,
///
/// where `ℓ = CP` is the tangent line at `P`, `Q = ℓ × P` a second point on it and `R = ℓ`.
/// Each `Xᵢ` is a binary quadratic form with integer coefficients. The map `(s : t) ↦ X(s, t)`
/// is a bijection from `P¹(ℚ)` onto the rational points of the conic; `(1 : 0)` (the tangent)
/// gives `P`, and [`ConicParameterization::parameter_of`] is its inverse.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ConicParameterization {
    /// The conic as a primitive integer matrix.
    matrix: [[IBig; 3]; 3],
    /// `P`, primitive integers.
    base: [IBig; 3],
    /// `Q = ℓ × P`.
    tangent: [IBig; 3],
    /// `ℓ = CP`.
    normal: [IBig; 3],
    /// `Xᵢ = forms[i][0]·s² + forms[i][1]·st + forms[i][2]·t²`.
    forms: [[IBig; 3]; 3],
}

/// The parameterization of the conic `XᵀCX = 0` through its rational point `p`
/// ([`ConicParameterization`]).
///
/// # Errors
/// [`ConicError::NotSymmetric`], [`ConicError::ZeroMatrix`], [`ConicError::ZeroPoint`],
/// [`ConicError::PointNotOnConic`], and [`ConicError::Degenerate`] for a conic of rank below 3.
///
/// # Examples
/// ```
/// use qsic_algebra::conic::parameterize;
/// use qsic_algebra::RBig;
/// let r = |v: i64| RBig::from(v);
/// // x² + y² − z² through (1, 0, 1): the Pythagorean triples.
/// let c = [[r(1), r(0), r(0)], [r(0), r(1), r(0)], [r(0), r(0), r(-1)]];
/// let par = parameterize(&c, &[r(1), r(0), r(1)]).unwrap();
/// let x = par.point_at(&r(2), &r(1));
/// assert_eq!(&x[0] * &x[0] + &x[1] * &x[1], &x[2] * &x[2]);
/// assert_eq!(par.parameter_of(&x), Some([r(2), r(1)]));
/// let p = par.point_at(&r(1), &r(0));
/// assert!(p[1].is_zero() && p[0] == p[2] && !p[0].is_zero()); // (1 : 0) is P
/// ```
pub fn parameterize(
    c: &[[RBig; 3]; 3],
    p: &[RBig; 3],
) -> Result<ConicParameterization, ConicError> {
    check_symmetric(c)?;
    if c.iter().flatten().all(|v| v.is_zero()) {
        return Err(ConicError::ZeroMatrix);
    }
    if p.iter().all(|v| v.is_zero()) {
        return Err(ConicError::ZeroPoint);
    }
    let flat: Vec<RBig> = c.iter().flatten().cloned().collect();
    let m = primitive_unsigned(&flat);
    let matrix: [[IBig; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|j| m[3 * i + j].clone()));
    let base = to_int_array(primitive(p));
    if !quad_form(&matrix, &base, &base).is_zero() {
        return Err(ConicError::PointNotOnConic);
    }
    if minors::det(&matrix).is_zero() {
        return Err(ConicError::Degenerate);
    }
    let normal = mat_vec(&matrix, &base);
    let tangent = cross(&normal, &base);
    let r = &normal;
    let q = quad_form(&matrix, &tangent, &tangent);
    let mqr = quad_form(&matrix, &tangent, r);
    let rr = quad_form(&matrix, r, r);
    let l2 = dot(&normal, &normal);
    let two_l2 = IBig::from(2) * &l2;
    let mut forms: [[IBig; 3]; 3] = Default::default();
    for i in 0..3 {
        forms[i][0] = -(&q * &base[i]);
        forms[i][1] = &two_l2 * &tangent[i] - IBig::from(2) * &mqr * &base[i];
        forms[i][2] = &two_l2 * &r[i] - &rr * &base[i];
    }
    let g = forms
        .iter()
        .flatten()
        .fold(IBig::ZERO, |g, v| crate::int_gcd(&g, v));
    for v in forms.iter_mut().flatten() {
        *v = &*v / &g;
    }
    Ok(ConicParameterization {
        matrix,
        base,
        tangent,
        normal,
        forms,
    })
}

impl ConicParameterization {
    /// The coefficients: `Xᵢ(s, t) = forms[i][0]·s² + forms[i][1]·st + forms[i][2]·t²`.
    pub fn forms(&self) -> &[[IBig; 3]; 3] {
        &self.forms
    }

    /// The base point `P` (primitive integers), the image of `(1 : 0)`.
    pub fn base(&self) -> &[IBig; 3] {
        &self.base
    }

    /// `X(s, t)`: a point of the conic, nonzero unless `s = t = 0`.
    pub fn point_at(&self, s: &RBig, t: &RBig) -> [RBig; 3] {
        let (ss, st, tt) = (s * s, s * t, t * t);
        std::array::from_fn(|i| {
            let f = &self.forms[i];
            RBig::from(f[0].clone()) * &ss
                + RBig::from(f[1].clone()) * &st
                + RBig::from(f[2].clone()) * &tt
        })
    }

    /// The parameter `(s : t)` of a rational point `x` of the conic, as coprime integers
    /// (`(1, 0)` for `P`); `None` if `x` is zero or not on the conic.
    pub fn parameter_of(&self, x: &[RBig; 3]) -> Option<[RBig; 2]> {
        if x.iter().all(|v| v.is_zero()) {
            return None;
        }
        let xi = to_int_array(primitive(x));
        if !quad_form(&self.matrix, &xi, &xi).is_zero() {
            return None;
        }
        // X = αP + βQ + γR with P, Q, R pairwise orthogonal except P·R = PᵀCP = 0 too.
        let beta =
            RBig::from_parts_signed(dot(&self.tangent, &xi), dot(&self.tangent, &self.tangent));
        let gamma =
            RBig::from_parts_signed(dot(&self.normal, &xi), dot(&self.normal, &self.normal));
        if beta.is_zero() && gamma.is_zero() {
            return Some([RBig::ONE, RBig::ZERO]);
        }
        let v = primitive(&[beta, gamma]);
        Some([RBig::from(v[0].clone()), RBig::from(v[1].clone())])
    }
}

/// A square-free integer coefficient with its prime factors.
#[derive(Clone, Debug)]
struct Coefficient {
    value: IBig,
    primes: Vec<u128>,
}

/// `±` the product of two factorizations with disjoint primes (numerator and denominator of
/// a reduced fraction).
fn multiply(f: &Factorization, g: &Factorization, negative: bool) -> Factorization {
    let mut factors: Vec<(u128, u32)> = f.factors.iter().chain(&g.factors).copied().collect();
    factors.sort_unstable();
    Factorization { negative, factors }
}

/// `Σ eᵢYᵢ² = 0` made square-free and pairwise coprime: `Σ fᵢWᵢ² = 0` with `Yᵢ = sᵢWᵢ`.
/// Per prime `p`: squares leave with `Yᵢ = Wᵢ/r`; dividing all three coefficients divides the
/// equation; dividing two (`fᵢ = p fᵢ'`, `fⱼ = p fⱼ'`) gives `fᵢ'Wᵢ² + fⱼ'Wⱼ² + p fₖWₖ²` with
/// `Yᵢ = Wᵢ/p`, `Yⱼ = Wⱼ/p` (the equation times `p`).
fn reduce(e: &[Factorization]) -> ([Coefficient; 3], [RBig; 3]) {
    let mut scale: [RBig; 3] = std::array::from_fn(|_| RBig::ONE);
    let mut sets: [Vec<u128>; 3] = Default::default();
    for i in 0..3 {
        let (part, root) = e[i].squarefree_split();
        scale[i] = RBig::from_parts_signed(IBig::ONE, root);
        sets[i] = part.factors.iter().map(|&(p, _)| p).collect();
    }
    let mut all: Vec<u128> = sets.iter().flatten().copied().collect();
    all.sort_unstable();
    all.dedup();
    let mut out: [Vec<u128>; 3] = Default::default();
    for p in all {
        let has: Vec<usize> = (0..3)
            .filter(|&i| sets[i].binary_search(&p).is_ok())
            .collect();
        match has.len() {
            1 => out[has[0]].push(p),
            2 => {
                let k = 3 - has[0] - has[1];
                out[k].push(p);
                for &i in &has {
                    scale[i] /= RBig::from(IBig::from(p));
                }
            }
            _ => {}
        }
    }
    let coefs = std::array::from_fn(|i| {
        out[i].sort_unstable();
        let mut value: IBig = out[i].iter().map(|&p| IBig::from(p)).product();
        if e[i].negative {
            value = -value;
        }
        Coefficient {
            value,
            primes: out[i].clone(),
        }
    });
    (coefs, scale)
}

/// A nonzero solution of `a x² + b y² + c z² = 0` for square-free pairwise coprime `a, b, c`
/// (module doc), or `None`.
fn solve_reduced(f: &[Coefficient; 3]) -> Result<Option<[IBig; 3]>, ConicError> {
    let negatives = f.iter().filter(|c| c.value < IBig::ZERO).count();
    if negatives == 0 || negatives == 3 {
        return Ok(None);
    }
    // Order (i, j, k) so that, after negating the equation if needed, a, b > 0 > c.
    let flip = negatives == 2;
    let val = |i: usize| {
        if flip {
            -&f[i].value
        } else {
            f[i].value.clone()
        }
    };
    let k = (0..3)
        .find(|&i| val(i) < IBig::ZERO)
        .expect("one coefficient has the lone sign");
    let (i, j) = match k {
        0 => (1, 2),
        1 => (0, 2),
        _ => (0, 1),
    };
    let (a, b, c) = (val(i), val(j), val(k));
    let Some(ra) = sqrt_ratio_mod(&-&c, &b, &f[i].primes)? else {
        return Ok(None);
    };
    let Some(rb) = sqrt_ratio_mod(&-&a, &c, &f[j].primes)? else {
        return Ok(None);
    };
    let Some(rc) = sqrt_ratio_mod(&-&b, &a, &f[k].primes)? else {
        return Ok(None);
    };
    // Λ: y ≡ ra·z (mod a), z ≡ rb·x (mod b), x ≡ rc·y (mod c); as one congruence modulo
    // N = |abc|: αx + βy + γz ≡ 0.
    let (ma, mb, mc) = (abs(&a), abs(&b), abs(&c));
    let n = &ma * &mb * &mc;
    let alpha = crt(&[(IBig::ZERO, &ma), (-&rb, &mb), (IBig::ONE, &mc)]);
    let beta = crt(&[(IBig::ONE, &ma), (IBig::ZERO, &mb), (-&rc, &mc)]);
    let gamma = crt(&[(-&ra, &ma), (IBig::ONE, &mb), (IBig::ZERO, &mc)]);
    let mut basis = congruence_lattice([alpha, beta, gamma], &n);
    let weights = [ma.clone(), mb.clone(), IBig::from(2) * &mc];
    lll(&mut basis, &weights);
    let v = &basis[0];
    let q = &a * &v[0] * &v[0] + &b * &v[1] * &v[1] + &c * &v[2] * &v[2];
    let abc = &a * &b * &c;
    let sol = if q.is_zero() {
        v.clone()
    } else {
        assert_eq!(
            q, -&abc,
            "Minkowski bound: Q(v) ∈ {{0, −abc}} for the reduced vector"
        );
        [
            &v[0] * &v[2] + &b * &v[1],
            &v[1] * &v[2] - &a * &v[0],
            &v[2] * &v[2] + &a * &b,
        ]
    };
    let mut out: [IBig; 3] = Default::default();
    out[i] = sol[0].clone();
    out[j] = sol[1].clone();
    out[k] = sol[2].clone();
    let check: IBig = (0..3).map(|l| &f[l].value * &out[l] * &out[l]).sum();
    assert!(
        check.is_zero() && out.iter().any(|v| !v.is_zero()),
        "Legendre solution checked"
    );
    Ok(Some(out))
}

/// A root `r` of `r² ≡ num/den` modulo the product of `primes` (each coprime to `den`), or
/// `None` if `num·den` is a non-residue modulo one of them (Jacobi symbol −1).
fn sqrt_ratio_mod(num: &IBig, den: &IBig, primes: &[u128]) -> Result<Option<IBig>, ConicError> {
    let mut parts = Vec::with_capacity(primes.len());
    for &p in primes {
        let pb = IBig::from(p);
        let x = residue(&(num * den), &pb);
        if p != 2 && jacobi(x, p) == -1 {
            return Ok(None);
        }
        // A failed root after Jacobi +1 means p was not prime after all.
        let s = sqrt_mod_prime(x, p).ok_or(FactorError::HardToFactor {
            bits: 128 - p.leading_zeros(),
        })?;
        let r = IBig::from(s) * inv_mod(den, &pb) % &pb;
        parts.push((r, pb));
    }
    let refs: Vec<(IBig, &IBig)> = parts.iter().map(|(r, p)| (r.clone(), p)).collect();
    Ok(Some(crt(&refs)))
}

/// A basis (rows) of `{v ∈ ℤ³ : coef·v ≡ 0 (mod n)}` for a surjective congruence
/// (every prime of `n` divides some coefficient's complement): `U·diag(n, 1, 1)` for a
/// unimodular `U` with `coef·U = (g, 0, 0)`, `gcd(g, n) = 1`.
fn congruence_lattice(coef: [IBig; 3], n: &IBig) -> [[IBig; 3]; 3] {
    // Columns of U, built by two extended-gcd steps.
    let mut cols: [[IBig; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|j| IBig::from((i == j) as i32)));
    // Columns p, q of U so that coef·U has g = gcd(x, y) at p and 0 at q (x, y there before).
    fn combine(cols: &mut [[IBig; 3]; 3], p: usize, q: usize, x: &IBig, y: &IBig) -> IBig {
        let (g, s, t) = ext_gcd(x, y);
        if !g.is_zero() {
            let (u, w) = (cols[p].clone(), cols[q].clone());
            let (yg, xg) = (y / &g, x / &g);
            cols[p] = std::array::from_fn(|i| &s * &u[i] + &t * &w[i]);
            cols[q] = std::array::from_fn(|i| &xg * &w[i] - &yg * &u[i]);
        }
        g
    }
    let g1 = combine(&mut cols, 0, 1, &coef[0], &coef[1]);
    combine(&mut cols, 0, 2, &g1, &coef[2]);
    cols[0] = std::array::from_fn(|i| n * &cols[0][i]);
    debug_assert!(cols
        .iter()
        .all(|v| residue(&(0..3).map(|i| &coef[i] * &v[i]).sum::<IBig>(), n) == 0));
    cols
}

/// LLL reduction (δ = 99/100) of the rows of `basis` for the norm `Σ wᵢvᵢ²` (exact rational
/// Gram–Schmidt, recomputed after each change: dimension 3).
fn lll(basis: &mut [[IBig; 3]; 3], w: &[IBig; 3]) {
    let delta = RBig::from_parts(IBig::from(99), 100u8.into());
    let dot =
        |u: &[IBig; 3], v: &[IBig; 3]| -> IBig { (0..3).map(|i| &w[i] * &u[i] * &v[i]).sum() };
    let gram_schmidt = |b: &[[IBig; 3]; 3]| -> ([[RBig; 3]; 3], [RBig; 3]) {
        let mut mu: [[RBig; 3]; 3] = Default::default();
        let mut bn: [RBig; 3] = Default::default();
        for i in 0..3 {
            for j in 0..i {
                let mut v = RBig::from(dot(&b[i], &b[j]));
                for l in 0..j {
                    v -= &mu[j][l] * &mu[i][l] * &bn[l];
                }
                mu[i][j] = v / &bn[j];
            }
            let mut v = RBig::from(dot(&b[i], &b[i]));
            for l in 0..i {
                v -= &mu[i][l] * &mu[i][l] * &bn[l];
            }
            bn[i] = v;
        }
        (mu, bn)
    };
    let mut k = 1;
    while k < 3 {
        for j in (0..k).rev() {
            let (mu, _) = gram_schmidt(basis);
            let q = mu[k][j].round();
            if !q.is_zero() {
                let bj = basis[j].clone();
                for i in 0..3 {
                    basis[k][i] -= &q * &bj[i];
                }
            }
        }
        let (mu, bn) = gram_schmidt(basis);
        if bn[k] >= (&delta - &mu[k][k - 1] * &mu[k][k - 1]) * &bn[k - 1] {
            k += 1;
        } else {
            basis.swap(k, k - 1);
            k = (k - 1).max(1);
        }
    }
}

fn check_symmetric(c: &[[RBig; 3]; 3]) -> Result<(), ConicError> {
    for row in 0..3 {
        for col in row + 1..3 {
            if c[row][col] != c[col][row] {
                return Err(ConicError::NotSymmetric { row, col });
            }
        }
    }
    Ok(())
}

/// Coprime integers proportional to `v` (not all zero), the first nonzero one positive.
fn primitive(v: &[RBig]) -> Vec<IBig> {
    let mut out = primitive_unsigned(v);
    if out
        .iter()
        .find(|x| !x.is_zero())
        .is_some_and(|x| *x < IBig::ZERO)
    {
        for x in out.iter_mut() {
            *x = -&*x;
        }
    }
    out
}

/// Coprime integers `k·v` for a positive rational `k` (zero stays zero).
fn primitive_unsigned(v: &[RBig]) -> Vec<IBig> {
    let mut lcm = IBig::ONE;
    for x in v {
        let d = IBig::from(x.denominator().clone());
        lcm = &lcm / crate::int_gcd(&lcm, &d) * d;
    }
    let ints: Vec<IBig> = v
        .iter()
        .map(|x| x.numerator() * (&lcm / IBig::from(x.denominator().clone())))
        .collect();
    let g = ints.iter().fold(IBig::ZERO, |g, x| crate::int_gcd(&g, x));
    if g.is_zero() {
        return ints;
    }
    ints.iter().map(|x| x / &g).collect()
}

fn to_array(v: Vec<IBig>) -> [RBig; 3] {
    std::array::from_fn(|i| RBig::from(v[i].clone()))
}

fn to_int_array(v: Vec<IBig>) -> [IBig; 3] {
    std::array::from_fn(|i| v[i].clone())
}

fn abs(v: &IBig) -> IBig {
    if *v < IBig::ZERO {
        -v
    } else {
        v.clone()
    }
}

/// `v mod m` in `0..m` as a machine integer (`m ≤ 2¹²⁸`, positive).
fn residue(v: &IBig, m: &IBig) -> u128 {
    let r = v % m;
    let r = if r < IBig::ZERO { r + m } else { r };
    u128::try_from(&r).expect("a residue modulo a 128-bit modulus")
}

/// `(g, s, t)` with `g = gcd(x, y) ≥ 0` and `s·x + t·y = g` (`(0, 1, 0)` for two zeros).
fn ext_gcd(x: &IBig, y: &IBig) -> (IBig, IBig, IBig) {
    let (mut r0, mut r1) = (x.clone(), y.clone());
    let (mut s0, mut s1) = (IBig::ONE, IBig::ZERO);
    let (mut t0, mut t1) = (IBig::ZERO, IBig::ONE);
    while !r1.is_zero() {
        let q = &r0 / &r1;
        (r0, r1) = (r1.clone(), &r0 - &q * &r1);
        (s0, s1) = (s1.clone(), &s0 - &q * &s1);
        (t0, t1) = (t1.clone(), &t0 - &q * &t1);
    }
    if r0 < IBig::ZERO {
        (-r0, -s0, -t0)
    } else {
        (r0, s0, t0)
    }
}

/// `x⁻¹ mod m` in `0..m` for `gcd(x, m) = 1`, `m > 0`.
fn inv_mod(x: &IBig, m: &IBig) -> IBig {
    let (g, s, _) = ext_gcd(x, m);
    debug_assert!(g.is_one() || m.is_one());
    let r = s % m;
    if r < IBig::ZERO {
        r + m
    } else {
        r
    }
}

/// The `r` in `0..∏m` with `r ≡ rᵢ (mod mᵢ)`, moduli pairwise coprime and positive.
fn crt(parts: &[(IBig, &IBig)]) -> IBig {
    let (mut r, mut m) = (IBig::ZERO, IBig::ONE);
    for (ri, mi) in parts {
        let mi: &IBig = mi;
        // r + m·k ≡ ri (mod mi)
        let k = (ri - &r) * inv_mod(&m, mi) % mi;
        r += &m * k;
        m *= mi;
        r %= &m;
        if r < IBig::ZERO {
            r += &m;
        }
    }
    r
}

fn dot(u: &[IBig; 3], v: &[IBig; 3]) -> IBig {
    (0..3).map(|i| &u[i] * &v[i]).sum()
}

fn cross(u: &[IBig; 3], v: &[IBig; 3]) -> [IBig; 3] {
    [
        &u[1] * &v[2] - &u[2] * &v[1],
        &u[2] * &v[0] - &u[0] * &v[2],
        &u[0] * &v[1] - &u[1] * &v[0],
    ]
}

fn mat_vec(m: &[[IBig; 3]; 3], v: &[IBig; 3]) -> [IBig; 3] {
    std::array::from_fn(|i| dot(&m[i], v))
}

/// `uᵀMv`.
fn quad_form(m: &[[IBig; 3]; 3], u: &[IBig; 3], v: &[IBig; 3]) -> IBig {
    dot(u, &mat_vec(m, v))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rat(v: i64) -> RBig {
        RBig::from(v)
    }

    #[test]
    fn singular_conics_give_a_kernel_point() {
        // Zero diagonals (a swap, an `e_k + e_j` step) and ranks 1 and 2: the point found is
        // the singular point, so `Cx = 0`; the nonsingular cases have a point or none by inertia.
        let cases: [([[i64; 3]; 3], bool); 5] = [
            ([[0, 1, 0], [1, 0, 0], [0, 0, 0]], true),
            ([[0, 1, 2], [1, 0, 3], [2, 3, 0]], false),
            ([[2, 1, 1], [1, 2, 1], [1, 1, 2]], false),
            ([[0, 0, 0], [0, 0, 5], [0, 5, 0]], true),
            ([[1, 2, 3], [2, 4, 6], [3, 6, 9]], true),
        ];
        for (c, singular) in cases {
            let c = c.map(|r| r.map(rat));
            assert_eq!(minors::det(&c).is_zero(), singular, "{c:?}");
            let indefinite = Matrix::from_array(c.clone())
                .diagonalize_congruent()
                .unwrap()
                .inertia()
                .is_indefinite();
            match find_point(&c).unwrap() {
                ConicPoint::Rational(x) => {
                    assert!(x.iter().any(|v| !v.is_zero()), "{c:?}");
                    let cx = Matrix::from_array(c.clone()).mul_vec(&x);
                    if singular {
                        assert!(cx.iter().all(|v| v.is_zero()), "{c:?}: {x:?} not singular");
                    } else {
                        let q = (0..3).fold(RBig::ZERO, |acc, i| acc + &cx[i] * &x[i]);
                        assert!(q.is_zero(), "{c:?}: {x:?} not on the conic");
                    }
                }
                ConicPoint::NoRealPoint => assert!(!singular && !indefinite, "{c:?}"),
                ConicPoint::NoRationalPoint(_) => panic!("{c:?}: a rational point exists"),
            }
        }
    }

    #[test]
    fn congruence_lattice_has_index_n() {
        for (coef, n) in [
            ([0i64, 4, 1], 15i64),
            ([3, 0, 0], 7),
            ([0, 0, 0], 1),
            ([6, 10, 15], 7 * 11),
        ] {
            let coef = coef.map(IBig::from);
            let n = IBig::from(n);
            let b = congruence_lattice(coef.clone(), &n);
            assert_eq!(abs(&minors::det(&b)), n);
            for v in &b {
                assert_eq!(residue(&dot(&coef, v), &n), 0);
            }
        }
    }

    #[test]
    fn crt_and_inverses() {
        let (m1, m2, m3) = (IBig::from(4), IBig::from(9), IBig::from(25));
        let r = crt(&[
            (IBig::from(3), &m1),
            (IBig::from(-1), &m2),
            (IBig::from(7), &m3),
        ]);
        assert_eq!(residue(&r, &m1), 3);
        assert_eq!(residue(&r, &m2), 8);
        assert_eq!(residue(&r, &m3), 7);
        assert_eq!(inv_mod(&IBig::from(-3), &IBig::from(7)), IBig::from(2));
        assert_eq!(ext_gcd(&IBig::from(-12), &IBig::from(18)).0, IBig::from(6));
    }
}
