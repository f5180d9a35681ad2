//! Quadratic forms `Q(x) = xᵀSx` over ℚ (`S` symmetric): an exact real point of an
//! indefinite form, and the two planes of a form of rank 2, with coordinates in ℚ or in one
//! quadratic field ℚ(√δ). The singular points (vertex of a cone, line of a plane pair, plane of
//! a double plane) are the kernel ([`Diagonalization::kernel`](super::Diagonalization::kernel)).
//!
//! | entry point | returns |
//! |---|---|
//! | [`real_point`] | `x ≠ 0` real with `Q(x) = 0`: rational if a cheap one exists, else in the ℚ(√δ) with the least `|δ|` among those tried |
//! | [`plane_pair`] | `Q = c·l₁·l₂` for rank 1 or 2: rational, real conjugate (`δ > 0`) or complex conjugate (`δ < 0`) planes, `δ` the least radicand that the principal minors show |
//! | [`sqrt_rational`], [`split_square`] | `√q = m√δ` with small square factors taken out of `δ` (no factoring) |

use super::{Diagonalization, Matrix};
use crate::field::Quadratic;
use crate::ring::Ring;
use crate::sign::Sign;
use dashu_int::IBig;
use dashu_ratio::RBig;

/// Square factors `p²` are removed from radicands for every `p` below this.
pub const SQUARE_TRIAL_LIMIT: u32 = 1000;

/// Forms of at most this many variables also try the sums of diagonal entries over every
/// subset (`2ⁿ` sums) for a rational point.
const SUBSET_SEARCH_LIMIT: usize = 8;

/// `v = m²·δ` with `m > 0`: the factors `p²` for `p < ` [`SQUARE_TRIAL_LIMIT`] are moved into
/// `m`, and so is the rest of `|v|` if it is a perfect square. Not a factorization: `δ` may keep
/// a square of a large prime. Zero gives `(1, 0)`.
///
/// ```
/// # use qsic_algebra::{linalg::forms::split_square, IBig};
/// assert_eq!(split_square(&IBig::from(-72)), (IBig::from(6), IBig::from(-2)));
/// // 1009 is a prime above the trial limit: its square is found as a square cofactor …
/// assert_eq!(split_square(&IBig::from(-4 * 1009 * 1009)), (IBig::from(2018), IBig::from(-1)));
/// // … but not next to another factor
/// assert_eq!(split_square(&IBig::from(3 * 1009 * 1009)), (IBig::from(1), IBig::from(3 * 1009 * 1009)));
/// ```
pub fn split_square(v: &IBig) -> (IBig, IBig) {
    use dashu_int::ops::{SquareRoot, UnsignedAbs};
    if v.is_zero() {
        return (IBig::ONE, IBig::ZERO);
    }
    let negative = *v < IBig::ZERO;
    let mut rest = v.unsigned_abs();
    let mut m = IBig::ONE;
    for p in 2..SQUARE_TRIAL_LIMIT {
        let pp = dashu_int::UBig::from(p * p);
        if pp > rest {
            break;
        }
        while (&rest % &pp).is_zero() {
            rest /= &pp;
            m *= p;
        }
    }
    let root = rest.sqrt();
    if &root * &root == rest {
        m *= IBig::from(root);
        rest = dashu_int::UBig::ONE;
    }
    let delta = IBig::from(rest);
    (m, if negative { -delta } else { delta })
}

/// `√q` for a rational `q` as `(m/d)·√δ` in ℚ(√δ), `δ` from [`split_square`] of `q`'s
/// numerator times denominator: rational when that is a square, non-real for `q < 0`.
///
/// ```
/// # use qsic_algebra::{linalg::forms::sqrt_rational, IBig, RBig};
/// let r = sqrt_rational(&RBig::from_parts_signed(IBig::from(8), IBig::from(3)));
/// assert_eq!(r.radicand(), &IBig::from(6)); // √(8/3) = (2/3)√6
/// assert_eq!(r.clone() * r, qsic_algebra::field::Quadratic::rational(RBig::from_parts_signed(IBig::from(8), IBig::from(3))));
/// ```
pub fn sqrt_rational(q: &RBig) -> Quadratic {
    let den = IBig::from(q.denominator().clone());
    let (m, delta) = split_square(&(q.numerator() * &den));
    let coefficient = RBig::from_parts_signed(m, den);
    if delta.is_zero() {
        Quadratic::zero()
    } else if delta.is_one() {
        Quadratic::rational(coefficient)
    } else {
        Quadratic::new(RBig::ZERO, coefficient, delta).expect("a radicand that is not a square")
    }
}

fn lift(v: &[RBig]) -> Vec<Quadratic> {
    v.iter().cloned().map(Quadratic::rational).collect()
}

fn unit(n: usize, i: usize) -> Vec<RBig> {
    (0..n)
        .map(|k| if k == i { RBig::ONE } else { RBig::ZERO })
        .collect()
}

/// `a + s·b` for rational vectors and a scalar in ℚ(√δ).
fn combine(a: &[RBig], s: &Quadratic, b: &[RBig]) -> Vec<Quadratic> {
    a.iter()
        .zip(b)
        .map(|(x, y)| Quadratic::rational(x.clone()).add(&s.scale(y)))
        .collect()
}

/// A real point of the quadric `Q(x) = xᵀSx = 0`: `x ≠ 0` with real coordinates (rational,
/// or in one real ℚ(√δ)) and `Q(x) = 0` exactly. `None` if there is none (`S` definite) or `S`
/// is not square symmetric.
///
/// Tried, in order, with `PᵀSP = diag(d)` ([`Matrix::diagonalize_congruent`]): a zero diagonal
/// entry of `S` (`x = e_i`); a zero `dᵢ` (`x = Peᵢ`, a singular point); a subset of the `dᵢ`
/// summing to zero (`x = Σ Peᵢ`, forms of at most 8 variables); then every pair — `x = eᵢ + teⱼ`
/// with `Sᵢᵢ + 2Sᵢⱼt + Sⱼⱼt² = 0`, and `x = Peᵢ + √(−dᵢ/dⱼ)·Peⱼ` for `dᵢdⱼ < 0` — keeping a
/// rational one if any, else one with the least `|δ|` after [`split_square`]. An indefinite form
/// always has such a pair, so the answer is `None` only for definite forms.
///
/// ```
/// # use qsic_algebra::{linalg::{forms::real_point, Matrix}, field::Quadratic, RBig, Ring};
/// // x² + y² − 3z²: no cheap rational point; one with coordinates in ℚ(√3)
/// let s = Matrix::from_array([[1, 0, 0], [0, 1, 0], [0, 0, -3]].map(|r| r.map(RBig::from)));
/// let x = real_point(&s).unwrap();
/// assert_eq!(x.iter().find(|v| v.as_rational().is_none()).unwrap().radicand(), &3.into());
/// assert!(s.map(|v| Quadratic::rational(v.clone())).quadratic_form(&x).is_zero());
/// ```
pub fn real_point(s: &Matrix<RBig>) -> Option<Vec<Quadratic>> {
    if !s.is_symmetric() {
        return None;
    }
    let n = s.rows();
    if let Some(i) = (0..n).find(|&i| s[(i, i)].is_zero()) {
        return Some(lift(&unit(n, i)));
    }
    let Diagonalization { p, d } = s.diagonalize_congruent()?;
    if let Some(i) = (0..n).find(|&i| d[i].is_zero()) {
        return Some(lift(&p.column(i)));
    }
    if n <= SUBSET_SEARCH_LIMIT {
        for subset in 1u32..1 << n {
            let members = (0..n).filter(|&i| subset >> i & 1 == 1);
            if subset.count_ones() >= 2
                && members
                    .clone()
                    .fold(RBig::ZERO, |acc, i| acc + &d[i])
                    .is_zero()
            {
                let x = members.fold(vec![RBig::ZERO; n], |acc, i| {
                    acc.iter().zip(p.column(i)).map(|(a, b)| a + b).collect()
                });
                return Some(lift(&x));
            }
        }
    }
    let mut best: Option<(IBig, Vec<Quadratic>)> = None;
    let mut consider = |root: Quadratic, point: &dyn Fn(&Quadratic) -> Vec<Quadratic>| {
        // δ > 0 (a square root of a positive rational), or 0 for a rational root
        let key = root.radicand().clone();
        if best.as_ref().is_none_or(|(k, _)| key < *k) {
            best = Some((key, point(&root)));
        }
    };
    for i in 0..n {
        for j in i + 1..n {
            // Sᵢᵢ + 2Sᵢⱼt + Sⱼⱼt² = 0, Sⱼⱼ ≠ 0 here
            let (sii, sij, sjj) = (&s[(i, i)], &s[(i, j)], &s[(j, j)]);
            let disc = sij * sij - sii * sjj;
            if disc >= RBig::ZERO {
                consider(sqrt_rational(&disc), &|root| {
                    let t = root
                        .sub(&Quadratic::rational(sij.clone()))
                        .scale(&(RBig::ONE / sjj));
                    combine(&unit(n, i), &t, &unit(n, j))
                });
            }
            let ratio = -(&d[i] / &d[j]);
            if ratio > RBig::ZERO {
                let (pi, pj) = (p.column(i), p.column(j));
                consider(sqrt_rational(&ratio), &|root| combine(&pi, root, &pj));
            }
        }
    }
    best.map(|(_, x)| x)
}

/// How the two planes of a form of rank ≤ 2 lie.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlanePairKind {
    /// Two distinct planes with rational coefficients.
    Rational,
    /// Two distinct real planes, conjugate over ℚ(√δ), `δ > 0`.
    RealConjugate,
    /// Two complex conjugate planes (`δ < 0`); their only real points are the common line.
    ComplexConjugate,
    /// One rational plane counted twice (rank 1).
    Double,
}

/// `Q = c·l₁·l₂` for a quadratic form of rank 1 or 2: linear forms with coefficients in ℚ or
/// in one ℚ(√δ) (conjugate there), and a rational `c`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PlanePair {
    /// The rational factor `c`.
    pub factor: RBig,
    /// The coefficients of `l₁` and `l₂`.
    pub planes: [Vec<Quadratic>; 2],
    /// Which of the four kinds.
    pub kind: PlanePairKind,
}

/// The factorization `Q = c·l₁·l₂` of a form of rank 1 or 2 (`None` for other ranks or a
/// matrix that is not square symmetric).
///
/// With `PᵀSP = D` and `y = P⁻¹x`, `Q = d_a y_a² + d_b y_b² = d_a (y_a − s y_b)(y_a + s y_b)` for
/// `s = √(−d_b/d_a)`; the square class of `−d_a d_b` (the discriminant) does not depend on `P`.
///
/// ```
/// # use qsic_algebra::{linalg::{forms::{plane_pair, PlanePairKind}, Matrix}, RBig};
/// // x² − 2y²: the planes x = ±√2·y
/// let s = Matrix::from_array([[1, 0, 0], [0, -2, 0], [0, 0, 0]].map(|r| r.map(RBig::from)));
/// assert_eq!(plane_pair(&s).unwrap().kind, PlanePairKind::RealConjugate);
/// ```
pub fn plane_pair(s: &Matrix<RBig>) -> Option<PlanePair> {
    let dg = s.diagonalize_congruent()?;
    let nonzero: Vec<usize> = (0..dg.d.len()).filter(|&i| !dg.d[i].is_zero()).collect();
    let inverse = dg.p.inverse().expect("P is invertible");
    let row = |i: usize| inverse.row(i).to_vec();
    match nonzero[..] {
        [a] => {
            let l = lift(&row(a));
            Some(PlanePair {
                factor: dg.d[a].clone(),
                planes: [l.clone(), l],
                kind: PlanePairKind::Double,
            })
        }
        [a, b] => {
            let root = least_radicand(sqrt_rational(&-(&dg.d[b] / &dg.d[a])), s);
            let kind = match Sign::of(root.radicand()) {
                Sign::Zero => PlanePairKind::Rational,
                Sign::Positive => PlanePairKind::RealConjugate,
                Sign::Negative => PlanePairKind::ComplexConjugate,
            };
            let (ra, rb) = (row(a), row(b));
            Some(PlanePair {
                factor: dg.d[a].clone(),
                planes: [combine(&ra, &root.neg(), &rb), combine(&ra, &root, &rb)],
                kind,
            })
        }
        _ => None,
    }
}

/// `root = √q` (`q = −d_b/d_a`) rewritten over the least radicand of its square class that
/// the form shows without factoring. For `S = c(aaᵀ − δbbᵀ)` each principal 2×2 minor is
/// `S_iiS_jj − S_ij² = −c²δπ_ij²`, `π = a ∧ b` (Plücker coordinates), so the gcd `g` of the
/// `|S_iiS_jj − S_ij²|` of `S` made integral, signed as `δ`, is in the square class of `q`:
/// `δ` times the square of `c·gcd(π)`. A map `PᵀSP` multiplies `d_a`, `d_b` by unrelated
/// squares and the radicand of `q` grows with `P`, while `g` stays as small as the planes
/// themselves. `g` replaces the radicand when it is smaller and `q/g` is a rational square
/// (checked, so the value never changes).
fn least_radicand(root: Quadratic, s: &Matrix<RBig>) -> Quadratic {
    use dashu_int::ops::{Gcd, UnsignedAbs};
    if root.as_rational().is_some() {
        return root;
    }
    let n = s.rows();
    let lcm =
        (0..n)
            .flat_map(|i| (0..n).map(move |j| (i, j)))
            .fold(dashu_int::UBig::ONE, |l, (i, j)| {
                let d = s[(i, j)].denominator();
                let g = l.clone().gcd(d);
                l / g * d
            });
    let int = |i: usize, j: usize| -> IBig {
        let v = &s[(i, j)];
        v.numerator() * IBig::from(&lcm / v.denominator())
    };
    let mut g = dashu_int::UBig::ZERO;
    for i in 0..n {
        for j in i + 1..n {
            let m = (int(i, i) * int(j, j) - int(i, j) * int(i, j)).unsigned_abs();
            // gcd(0, 0) is not defined in dashu
            g = if g.is_zero() {
                m
            } else if m.is_zero() {
                g
            } else {
                g.gcd(m)
            };
        }
    }
    let delta = root.radicand().clone();
    let signed = if delta < IBig::ZERO {
        -IBig::from(g)
    } else {
        IBig::from(g)
    };
    let (_, reduced) = split_square(&signed);
    if reduced.is_zero() || reduced.clone().unsigned_abs() >= delta.clone().unsigned_abs() {
        return root;
    }
    let q = root.mul(&root);
    let q = q
        .as_rational()
        .expect("the square of a pure root is rational");
    let k = sqrt_rational(&(q / RBig::from(reduced.clone())));
    match k.as_rational() {
        Some(k) => Quadratic::new(RBig::ZERO, k.clone(), reduced).unwrap_or(root),
        None => root,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(v: i64) -> RBig {
        RBig::from(v)
    }

    fn diag(d: &[i64]) -> Matrix<RBig> {
        Matrix::from_fn(
            d.len(),
            d.len(),
            |i, j| if i == j { q(d[i]) } else { RBig::ZERO },
        )
    }

    fn on_quadric(s: &Matrix<RBig>, x: &[Quadratic]) -> bool {
        s.map(|v| Quadratic::rational(v.clone()))
            .quadratic_form(x)
            .is_zero()
            && x.iter().any(|v| !v.is_zero())
            && x.iter().all(Quadratic::is_real)
    }

    /// `c·(l₁l₂ᵀ + l₂l₁ᵀ)/2 = S`.
    fn multiplies_back(s: &Matrix<RBig>, pair: &PlanePair) -> bool {
        let [l1, l2] = &pair.planes;
        let half = Quadratic::rational(&pair.factor / q(2));
        let n = s.rows();
        let product = Matrix::from_fn(n, n, |i, j| {
            l1[i].mul(&l2[j]).add(&l1[j].mul(&l2[i])).mul(&half)
        });
        product == s.map(|v| Quadratic::rational(v.clone()))
    }

    #[test]
    fn square_parts() {
        // 1009 is above the trial limit: its square is found as a square cofactor
        for (v, m, d) in [
            (0, 1, 0),
            (1, 1, 1),
            (-4, 2, -1),
            (12, 2, 3),
            (98, 7, 2),
            (-1, 1, -1),
            (4 * 1009 * 1009, 2018, 1),
        ] {
            assert_eq!(
                split_square(&IBig::from(v)),
                (IBig::from(m), IBig::from(d)),
                "{v}"
            );
        }
        for (n, d) in [(9, 4), (-3, 1), (0, 1), (2, 7)] {
            let v = RBig::from_parts_signed(IBig::from(n), IBig::from(d));
            let r = sqrt_rational(&v);
            assert_eq!(r.clone() * r, Quadratic::rational(v), "{n}/{d}");
        }
    }

    /// `x² − 2y²` under integer maps `PᵀSP` whose minors grow with `P`: the planes stay over
    /// ℚ(√2) (the gcd of the principal minors), not over the square class representative
    /// that the diagonalization's `−d_b/d_a` carries (`2·k²` with `k` growing with `P`).
    #[test]
    fn disguised_plane_pairs_keep_their_least_radicand() {
        let maps: [[[i64; 4]; 4]; 3] = [
            [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
            [[3, 7, 1, 0], [5, 2, 0, 1], [1, 4, 9, 2], [8, 1, 3, 5]],
            [
                [1009, 2713, 31, 7],
                [997, -5003, 11, 2],
                [13, 17, 4099, 5],
                [-3, 8, 1, 7919],
            ],
        ];
        let s0 = diag(&[1, -2, 0, 0]);
        let disguised = maps.iter().map(|p| {
            Matrix::from_fn(4, 4, |i, j| {
                let mut acc = RBig::ZERO;
                for k in 0..4 {
                    for l in 0..4 {
                        acc += q(p[k][i]) * &s0[(k, l)] * q(p[l][j]);
                    }
                }
                acc
            })
        });
        // aaᵀ − 2bbᵀ with a₀b₁ − a₁b₀ = 1009, a prime above the trial limit: the
        // diagonalization's radicand is 2·1009²·(a₀² − 2b₀²)²
        let (a, b) = ([1009, 0, 3, 5], [1, 1, 2, 7]);
        let direct = Matrix::from_fn(4, 4, |i, j| q(a[i] * a[j] - 2 * b[i] * b[j]));
        for s in disguised.chain([direct]) {
            let p = &s;
            let pair = plane_pair(&s).expect("rank 2");
            assert_eq!(pair.kind, PlanePairKind::RealConjugate);
            assert!(multiplies_back(&s, &pair), "{p:?}");
            let radicand = pair.planes[0]
                .iter()
                .find(|v| v.as_rational().is_none())
                .map(|v| v.radicand().clone());
            assert_eq!(radicand, Some(IBig::from(2)), "{p:?}");
        }
        // complex conjugate planes x = ±√−2·y: the gcd signed as δ < 0
        let (a, b) = ([1009, 0, 3, 5], [1, 1, 2, 7]);
        let s = Matrix::from_fn(4, 4, |i, j| q(a[i] * a[j] + 2 * b[i] * b[j]));
        let pair = plane_pair(&s).expect("rank 2");
        assert_eq!(pair.kind, PlanePairKind::ComplexConjugate);
        assert!(multiplies_back(&s, &pair));
        let radicand = pair.planes[0]
            .iter()
            .find(|v| v.as_rational().is_none())
            .map(|v| v.radicand().clone());
        assert_eq!(radicand, Some(IBig::from(-2)));
    }

    #[test]
    fn real_points_of_known_forms() {
        // (diagonal, expected radicand of the point: 0 for rational)
        let cases: &[(&[i64], i64)] = &[
            (&[1, 1, -2], 0),      // 1 + 1 − 2 = 0: a subset sum
            (&[1, -4, 7, 3], 0),   // −1/−4 → ratio 1/4, a square
            (&[1, 1, 1, -5], 5),   // ratios 1/5 only: ℚ(√5)
            (&[2, 5, -7, -11], 0), // 2 + 5 − 7 = 0
            (&[1, 0, 5], 0),       // a zero diagonal entry
            (&[1, -30, 3], 10),    // the pair (0, 1) gives √30, the later pair (1, 2) √10
        ];
        for &(d, radicand) in cases {
            let s = diag(d);
            let x = real_point(&s).expect("indefinite");
            assert!(on_quadric(&s, &x), "{d:?}: {x:?}");
            let found = x
                .iter()
                .map(|v| v.radicand().clone())
                .find(|r| !r.is_zero());
            assert_eq!(found.unwrap_or_default(), IBig::from(radicand), "{d:?}");
        }
        assert_eq!(real_point(&diag(&[1, 2, 3])), None);
        assert_eq!(real_point(&diag(&[-1, -2])), None);
        // not diagonal: x² + 4xy + y² (t² + 4t + 1 = 0, t = −2 ± √3) and a semidefinite cone
        let s = Matrix::from_array([[1, 2], [2, 1]].map(|r| r.map(q)));
        let x = real_point(&s).unwrap();
        assert!(on_quadric(&s, &x));
        // not diagonal, (expected radicand): x² + 10xy + y² + 7z² only has pairs with √6
        // (t² + 10t + 1 = 0) or worse; with d = (1, 2, −8) the diagonal pair (2, −8) is rational
        for (s, radicand) in [
            ([[1, 5, 0], [5, 1, 0], [0, 0, 7]], 6),
            ([[1, 1, 0], [1, 3, 0], [0, 0, -8]], 0),
        ] {
            let s = Matrix::from_array(s.map(|r| r.map(q)));
            let x = real_point(&s).unwrap();
            assert!(on_quadric(&s, &x), "{s}: {x:?}");
            let found = x
                .iter()
                .map(|v| v.radicand().clone())
                .find(|r| !r.is_zero());
            assert_eq!(found.unwrap_or_default(), IBig::from(radicand), "{s}");
        }
        let cone = Matrix::from_array([[1, 1, 0], [1, 1, 0], [0, 0, 2]].map(|r| r.map(q)));
        assert!(on_quadric(&cone, &real_point(&cone).unwrap()));
    }

    #[test]
    fn plane_pairs_of_known_forms() {
        let xy = Matrix::from_array([[0, 1, 0], [1, 0, 0], [0, 0, 0]].map(|r| r.map(q)));
        let cases = [
            (xy, PlanePairKind::Rational),
            (diag(&[2, -8, 0]), PlanePairKind::Rational),
            (diag(&[1, 0, -3]), PlanePairKind::RealConjugate),
            (diag(&[1, 1, 0, 0]), PlanePairKind::ComplexConjugate),
            (diag(&[0, 0, -5]), PlanePairKind::Double),
        ];
        for (s, kind) in cases {
            let pair = plane_pair(&s).expect("rank 1 or 2");
            assert_eq!(pair.kind, kind, "{s}");
            assert!(multiplies_back(&s, &pair), "{s}: {pair:?}");
        }
        assert!(plane_pair(&diag(&[1, 1, 1])).is_none());
        assert!(plane_pair(&diag(&[0, 0])).is_none());
    }
}
