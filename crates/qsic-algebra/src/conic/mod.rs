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
//! square-free and pairwise coprime (`a, b, c`) over *atoms* — the primes that trial division
//! and a cheap Pollard rho find, and the cofactors they leave, made pairwise coprime by gcds —
//! ([`legendre`] states why an atom serves like a prime). Legendre: `a x² + b y² + c z² = 0`
//! has a nonzero integer solution iff `a, b, c` are not all of one sign and `−bc`, `−ca`, `−ab`
//! are squares modulo `|a|`, `|b|`, `|c|`. The solution is constructed (Minkowski's proof made
//! effective): with square roots of those residues, the vectors of a lattice `Λ` of index
//! `|abc|` all have `Q(v) ≡ 0 (mod abc)`; with `a, b > 0 > c`, an LLL-reduced (δ = 99/100)
//! first vector of `Λ` for the norm `F = a x² + b y² + 2|c| z²` has `F < 1.71|abc|`, hence
//! `Q(v) ∈ {0, −abc}`, and in the second case `(xz + by, yz − ax, z² + ab)` is a solution,
//! since `a(xz + by)² + b(yz − ax)² + c(z² + ab)² = (z² + ab)(Q(v) + abc)`. No search.
//!
//! **No factoring in the way.** A square root modulo a cofactor is tried as if it were prime
//! (Tonelli–Shanks, checked by squaring); a Jacobi symbol `−1` modulo any atom proves there is
//! no rational point. When neither settles it — a composite cofactor that was not split, with
//! every symbol `+1` — [`find_point`] does not fail: it answers [`ConicPoint::Undecided`], a
//! point over ℚ(√δ) with `δ = −fᵢfⱼ` for two opposite-sign reduced coefficients, the cofactor
//! left under the radical (not proven square-free; exact all the same: the point is on the
//! conic). No error comes from a number too large to factor.
//!
//! **Certainty.** A returned point is checked on its conic, and every square root modulo an
//! atom is checked by squaring. "No rational point" rests on an atom with Jacobi symbol
//! `(−bc/N) = −1`: exact for any odd `N` (the symbol is multiplicative in `N`).
//!
//! **Cost.** Trial division of the numerators and denominators of the diagonal below `2¹⁶`
//! (primes found once are divided out of the others), Pollard rho within
//! [`legendre::CONIC_RHO_BUDGET`] steps for the whole conic, gcds and perfect-power tests of the
//! cofactors, then square roots modulo each atom (`O(log N)` products) and one LLL in
//! dimension 3 on `O(log|abc|)`-bit numbers. Measured (release build) on random symmetric
//! integer matrices: 16-bit entries ≈ 1.5 ms, 32-bit ≈ 5 ms.

use crate::factor::{FactorError, RHO_BUDGET};
use crate::field::Quadratic;
use crate::linalg::{minors, Matrix};
use dashu_int::IBig;
use dashu_ratio::RBig;
use legendre::{factor_all, reduce, solve_reduced, Legendre};
use std::fmt;

mod legendre;

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
    /// [`solve_legendre`] only: a coefficient's cofactor could not be factored within the
    /// bounds of [`crate::factor`] and Legendre's conditions were not decided without it.
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

/// A point with coordinates in ℚ(√δ), `δ > 1` an integer that is no square, at least one
/// coordinate irrational; `δ` is square-free over the atoms (module doc), so square-free when
/// the coefficients were factored completely.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct QuadraticPoint {
    /// The radicand `δ`.
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
    /// Real points, a point over a quadratic field, and no decision whether there is a
    /// rational one: a coefficient's cofactor was not factored (module doc), it stays in `δ`.
    Undecided(Box<QuadraticPoint>),
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
/// Where Legendre's conditions could not be decided without factoring a cofactor, the point
/// over ℚ(√δ) is [`ConicPoint::Undecided`] (module doc): never an error.
///
/// # Errors
/// [`ConicError::NotSymmetric`], [`ConicError::ZeroMatrix`].
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
    // one coprime base for all six.
    let parts: Vec<IBig> = d
        .iter()
        .flat_map(|di| [di.numerator().clone(), IBig::from(di.denominator().clone())])
        .collect();
    let mut budget = legendre::CONIC_RHO_BUDGET;
    let fac = factor_all(&parts, &mut budget);
    let exps: [Vec<(usize, u32)>; 3] = std::array::from_fn(|i| {
        let mut e = fac.parts[2 * i].clone();
        e.extend(fac.parts[2 * i + 1].iter().copied()); // numerator and denominator coprime
        e
    });
    let (coefs, s) = reduce(
        &fac.atoms,
        &exps,
        std::array::from_fn(|i| d[i] < RBig::ZERO),
    );
    let scale: Vec<RBig> = (0..3)
        .map(|i| RBig::from(IBig::from(d[i].denominator().clone())) * &s[i])
        .collect();
    let apply = |w: &[RBig; 3]| -> [RBig; 3] {
        let y: Vec<RBig> = (0..3).map(|i| &scale[i] * &w[i]).collect();
        std::array::from_fn(|i| (0..3).fold(RBig::ZERO, |acc, j| acc + &t[i][j] * &y[j]))
    };
    let proven = match solve_reduced(&coefs, &fac.atoms) {
        Legendre::Solution(w) => {
            let x = apply(&w.map(RBig::from));
            return Ok(ConicPoint::Rational(to_array(primitive(&x))));
        }
        Legendre::NoSolution => true,
        Legendre::Undecided { .. } => false,
    };
    // fᵢWᵢ² + fⱼWⱼ² = 0 at W = (√δ, fᵢ) with δ = −fᵢfⱼ.
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
    if let Some(root) = Quadratic::sqrt(&delta).as_rational() {
        // δ = 1 (atoms are no squares, nor their coprime products): a rational point after all
        let x: Vec<RBig> = (0..3).map(|k| &xr[k] + root * &xi[k]).collect();
        return Ok(ConicPoint::Rational(to_array(primitive(&x))));
    }
    let all: Vec<RBig> = xr.iter().chain(xi.iter()).cloned().collect();
    let ints = primitive(&all);
    let coords = std::array::from_fn(|k| {
        Quadratic::new(
            RBig::from(ints[k].clone()),
            RBig::from(ints[k + 3].clone()),
            delta.clone(),
        )
        .expect("δ is not a square")
    });
    let point = Box::new(QuadraticPoint { delta, coords });
    Ok(if proven {
        ConicPoint::NoRationalPoint(point)
    } else {
        ConicPoint::Undecided(point)
    })
}

/// A nonzero integer solution of `a x² + b y² + c z² = 0` (coprime, first nonzero entry
/// positive), or `None` if there is none; `a, b, c` are any nonzero integers.
///
/// # Errors
/// [`ConicError::ZeroMatrix`] if a coefficient is zero (the form is then degenerate: use
/// [`find_point`]); [`ConicError::Factor`] if the answer needs a square root modulo a
/// cofactor that was not factored (trial division, then Pollard rho within
/// [`crate::factor::RHO_BUDGET`] steps) and no Jacobi symbol settles it.
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
    let mut budget = RHO_BUDGET;
    let fac = factor_all(&[a.clone(), b.clone(), c.clone()], &mut budget);
    let exps: [Vec<(usize, u32)>; 3] = std::array::from_fn(|i| fac.parts[i].clone());
    let negative = [a, b, c].map(|v| *v < IBig::ZERO);
    let (coefs, scale) = reduce(&fac.atoms, &exps, negative);
    let w = match solve_reduced(&coefs, &fac.atoms) {
        Legendre::Solution(w) => w,
        Legendre::NoSolution => return Ok(None),
        Legendre::Undecided { bits } if bits > 128 => {
            return Err(ConicError::Factor(FactorError::TooLarge { bits }))
        }
        Legendre::Undecided { bits } => {
            return Err(ConicError::Factor(FactorError::HardToFactor {
                bits: bits as u32,
            }))
        }
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
                ConicPoint::NoRationalPoint(_) | ConicPoint::Undecided(_) => {
                    panic!("{c:?}: a rational point exists")
                }
            }
        }
    }
}
