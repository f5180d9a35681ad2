//! Minors of a linear pencil `λA − B` (`N × N`, `N ≤ 4`, entries in any ring `C`) as
//! polynomials in `λ` over `C`, by evaluation and interpolation: the minors of the members at
//! `λ = ∞` (those of `A`: the leading coefficients), `0, 1, −1`, and for the `4 × 4`
//! determinant `2`, come from [`minors`]; a `k × k` minor has degree `≤ k`, and
//!
//! `p(1) + p(−1) = 2(c₀ + c₂ + c₄)`, `p(1) − p(−1) = 2(c₁ + c₃)`,
//! `p(2) − c₀ − 4c₂ − 16c₄ = 2c₁ + 8c₃`
//!
//! determine its coefficients with exact divisions by 2 and 6. Evaluating keeps the arithmetic
//! in `C` (machine words in the classifier's fast path, small `IBig`s without allocation on the
//! exact path) instead of multiplying polynomials.

use super::minors::{self, SmallMinors};
use crate::poly::Poly;
use crate::ring::Ring;

/// The member `lA − B` for `l = 0, 1, −1, 2`.
#[inline(always)]
fn member<C: Ring, const N: usize>(a: &[[C; N]; N], b: &[[C; N]; N], l: i8) -> [[C; N]; N] {
    let mut m: [[C; N]; N] = std::array::from_fn(|_| std::array::from_fn(|_| C::zero()));
    for i in 0..N {
        for j in 0..N {
            let (x, y) = (&a[i][j], &b[i][j]);
            m[i][j] = match l {
                0 => y.neg(),
                1 => x.sub(y),
                -1 => x.neg().sub(y),
                _ => x.add(x).sub(y),
            };
        }
    }
    m
}

/// The coefficients `c₀…c_k` (then zeros) of the polynomial of degree `≤ k`, `1 ≤ k ≤ 4`,
/// with coefficient `lead` at `λᵏ` and values `p(0), p(1), p(−1)`, and `p(2)` for `k = 4`.
#[inline(always)]
fn interpolate<C: Ring>(k: usize, lead: &C, p0: &C, p1: &C, pm1: &C, p2: &C) -> [C; 5] {
    let mut c: [C; 5] = std::array::from_fn(|_| C::zero());
    let two = C::one().add(&C::one());
    let half = |v: C| v.div_exact(&two).expect("p(1) ± p(−1) is even");
    match k {
        1 => [c[0], c[1]] = [p0.clone(), lead.clone()],
        2 => [c[0], c[1], c[2]] = [p0.clone(), p1.sub(p0).sub(lead), lead.clone()],
        _ => {
            let (even, odd) = (half(p1.add(pm1)), half(p1.sub(pm1)));
            if k == 3 {
                [c[0], c[1], c[2], c[3]] = [p0.clone(), odd.sub(lead), even.sub(p0), lead.clone()];
            } else {
                let c2 = even.sub(p0).sub(lead);
                // 6c₃ = p(2) − c₀ − 4c₂ − 16c₄ − 2(c₁ + c₃)
                let four = two.add(&two);
                let sixteen = four.mul(&four);
                let six = four.add(&two);
                let c3 = p2
                    .sub(p0)
                    .sub(&four.mul(&c2))
                    .sub(&sixteen.mul(lead))
                    .sub(&two.mul(&odd))
                    .div_exact(&six)
                    .expect("6c₃ is a multiple of 6");
                c = [p0.clone(), odd.sub(&c3), c2, c3, lead.clone()];
            }
        }
    }
    c
}

/// `[E₁(λ), …, E_N(λ)]` of the pencil `λA − B` (`N ≤ 4`), each as its coefficients, lowest
/// first, padded with zeros to five; `E_N(λ) = det(λA − B)`. No allocation: `C = i128` runs
/// in machine words (the caller bounds the entries: every value computed is a minor of a member
/// `lA − B`, `l ∈ {0, ±1, 2}`, or a sum of a few such values with factors up to 16).
///
/// ```
/// # use qsic_algebra::linalg::pencil::pencil_principal_minor_sums;
/// // λI − diag(1, 2): E₁ = 2λ − 3, E₂ = (λ − 1)(λ − 2)
/// let e = pencil_principal_minor_sums(&[[1i128, 0], [0, 1]], &[[1, 0], [0, 2]]);
/// assert_eq!(e, [[-3, 2, 0, 0, 0], [2, -3, 1, 0, 0]]);
/// ```
pub fn pencil_principal_minor_sums<C: Ring, const N: usize>(
    a: &[[C; N]; N],
    b: &[[C; N]; N],
) -> [[C; 5]; N] {
    principal_minor_sums_of_members([
        a,
        &member(a, b, 0),
        &member(a, b, 1),
        &member(a, b, -1),
        &member(a, b, 2),
    ])
}

/// [`pencil_principal_minor_sums`] from the members `A, −B, A − B, −A − B, 2A − B` (the
/// pencil at `λ = ∞, 0, 1, −1, 2`; the last is read for `N = 4` only), for a caller that has
/// a cheaper way to form them (the classifier's fast path, in `i64`).
pub fn principal_minor_sums_of_members<C: Ring, const N: usize>(
    members: [&[[C; N]; N]; 5],
) -> [[C; 5]; N] {
    let [at_infinity, m0, m1, mm1, m2] = members;
    let lead = minors::principal_minor_sums(at_infinity);
    let p0 = minors::principal_minor_sums(m0);
    let p1 = minors::principal_minor_sums(m1);
    let pm1 = minors::principal_minor_sums(mm1);
    let p2 = if N == 4 { minors::det(m2) } else { C::zero() };
    std::array::from_fn(|k| interpolate(k + 1, &lead[k], &p0[k], &p1[k], &pm1[k], &p2))
}

impl<C: Ring> SmallMinors<Poly<C>> {
    /// Every minor of the pencil `λA − B` (`N ≤ 4`) as a polynomial in `λ` (module docs); for
    /// symmetric `A` and `B`, once per unordered pair of row and column sets.
    pub fn of_pencil<const N: usize>(a: &[[C; N]; N], b: &[[C; N]; N]) -> SmallMinors<Poly<C>> {
        let symmetric = |m: &[[C; N]; N]| (0..N).all(|i| (i + 1..N).all(|j| m[i][j] == m[j][i]));
        let symmetric = symmetric(a) && symmetric(b);
        let at = [
            SmallMinors::all_with(a, symmetric),
            SmallMinors::all_with(&member(a, b, 0), symmetric),
            SmallMinors::all_with(&member(a, b, 1), symmetric),
            SmallMinors::all_with(&member(a, b, -1), symmetric),
        ];
        let p2 = if N == 4 {
            minors::det(&member(a, b, 2))
        } else {
            C::zero()
        };
        // slots never filled (symmetric storage, sizes below 4) stay zero without interpolating
        let poly = |k: usize, v: [&C; 4]| {
            if v.iter().all(|x| x.is_zero()) && (k < 4 || p2.is_zero()) {
                Poly::zero()
            } else {
                Poly::new(interpolate(k, v[0], v[1], v[2], v[3], &p2).to_vec())
            }
        };
        SmallMinors {
            n: N,
            symmetric,
            m1: (0..N * N)
                .map(|i| poly(1, [0, 1, 2, 3].map(|p| &at[p].m1[i])))
                .collect(),
            m2: std::array::from_fn(|r| {
                std::array::from_fn(|c| poly(2, [0, 1, 2, 3].map(|p| &at[p].m2[r][c])))
            }),
            m3: std::array::from_fn(|r| {
                std::array::from_fn(|c| poly(3, [0, 1, 2, 3].map(|p| &at[p].m3[r][c])))
            }),
            det: poly(N, [0, 1, 2, 3].map(|p| &at[p].det)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::linalg::minors::combinations;
    use crate::IBig;
    use proptest::prelude::*;

    /// The pencil's minors computed over ℤ[λ] directly (polynomial entries).
    fn over_polynomials<const N: usize>(a: &[[i64; N]; N], b: &[[i64; N]; N]) -> [[Poly; N]; N] {
        std::array::from_fn(|i| std::array::from_fn(|j| Poly::from_i64s(&[-b[i][j], a[i][j]])))
    }

    fn check<const N: usize>(a: [[i64; N]; N], b: [[i64; N]; N]) -> Result<(), TestCaseError> {
        let direct = SmallMinors::all(&over_polynomials(&a, &b));
        let (ab, bb) = (a.map(|r| r.map(IBig::from)), b.map(|r| r.map(IBig::from)));
        let interpolated = SmallMinors::of_pencil(&ab, &bb);
        for k in 1..=N {
            for r in combinations(N, k) {
                for c in combinations(N, k) {
                    prop_assert_eq!(interpolated.minor(&r, &c), direct.minor(&r, &c));
                }
            }
        }
        let sums = pencil_principal_minor_sums(
            &a.map(|r| r.map(i128::from)),
            &b.map(|r| r.map(i128::from)),
        );
        let expect = minors::principal_minor_sums(&over_polynomials(&a, &b));
        for k in 0..N {
            let got = Poly::new(sums[k].iter().map(|&v| IBig::from(v)).collect());
            prop_assert_eq!(&got, &expect[k]);
        }
        prop_assert_eq!(interpolated.principal_minor_sums(), expect.to_vec());
        Ok(())
    }

    fn array<const N: usize>(v: &[i64]) -> [[i64; N]; N] {
        std::array::from_fn(|i| std::array::from_fn(|j| v[N * i + j]))
    }

    fn symmetric<const N: usize>(v: &[i64]) -> [[i64; N]; N] {
        std::array::from_fn(|i| std::array::from_fn(|j| v[N * i.min(j) + i.max(j)]))
    }

    proptest! {
        #[test]
        fn interpolation_equals_polynomial_arithmetic(
            a in prop::collection::vec(-9i64..10, 16), b in prop::collection::vec(-9i64..10, 16),
        ) {
            check::<1>(array(&a), array(&b))?;
            check::<2>(array(&a), array(&b))?;
            check::<3>(array(&a), array(&b))?;
            check::<4>(array(&a), array(&b))?;
            check::<4>(symmetric(&a), symmetric(&b))?;
            check::<3>(symmetric(&a), symmetric(&b))?;
            check::<4>(symmetric(&a), array(&b))?;
        }
    }

    /// `λ·diag(0, 1, 1, 1) − diag(1, 0, 1, −1)`: the determinant `−λ(λ − 1)(λ + 1)` vanishes at
    /// `λ = ∞, 0, 1, −1`; only `λ = 2` tells it from zero.
    #[test]
    fn determinant_vanishing_at_four_points() {
        let diag = |d: [i64; 4]| {
            std::array::from_fn(|i| std::array::from_fn(|j| if i == j { d[i] } else { 0 }))
        };
        let (a, b): ([[i64; 4]; 4], [[i64; 4]; 4]) = (diag([0, 1, 1, 1]), diag([1, 0, 1, -1]));
        check::<4>(a, b).unwrap();
        let m =
            SmallMinors::of_pencil(&a.map(|r| r.map(IBig::from)), &b.map(|r| r.map(IBig::from)));
        assert_eq!(
            *m.minor(&[0, 1, 2, 3], &[0, 1, 2, 3]),
            Poly::from_i64s(&[0, 1, 0, -1])
        );
    }
}
