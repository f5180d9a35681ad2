//! Symmetric 4×4 integer matrices with exact inertia, and the pencil `λA − μB` of two 4×4
//! matrices over any coefficient ring (ℤ, or ℤ\[t\] for moving quadrics). Determinants and
//! minors come from [`linalg::minors`](crate::linalg::minors), written once for every ring.

use crate::linalg::minors::{self, SmallMinors};
use crate::linalg::Matrix;
use crate::poly::Poly;
use crate::ring::Ring;
use crate::sign::Sign;
use dashu_int::IBig;
use dashu_ratio::RBig;

pub use crate::linalg::Inertia;

/// A symmetric 4×4 integer matrix.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct SymMatrix4 {
    m: [[IBig; 4]; 4],
}

impl SymMatrix4 {
    /// `Some` if `m` is symmetric.
    pub fn new(m: [[IBig; 4]; 4]) -> Option<SymMatrix4> {
        for i in 0..4 {
            for j in (i + 1)..4 {
                if m[i][j] != m[j][i] {
                    return None;
                }
            }
        }
        Some(SymMatrix4 { m })
    }

    /// From machine integers; `None` if not symmetric.
    pub fn from_i64(m: [[i64; 4]; 4]) -> Option<SymMatrix4> {
        SymMatrix4::new(m.map(|r| r.map(IBig::from)))
    }

    /// The symmetric matrix whose upper triangle (diagonal included) is that of `m`; the
    /// entries of `m` below the diagonal are not read.
    pub fn from_upper_i128(m: &[[i128; 4]; 4]) -> SymMatrix4 {
        let mut out: [[IBig; 4]; 4] = Default::default();
        for i in 0..4 {
            for j in i..4 {
                out[i][j] = IBig::from(m[i][j]);
                out[j][i] = out[i][j].clone();
            }
        }
        SymMatrix4 { m: out }
    }

    /// A symmetric rational matrix times the positive rational that makes it a primitive
    /// integer matrix (entries with gcd 1); the zero matrix stays zero.
    ///
    /// # Panics
    /// If `m` is not symmetric (callers validate first).
    pub fn from_rationals_primitive(m: &[[RBig; 4]; 4]) -> SymMatrix4 {
        let mut lcm = IBig::ONE;
        for v in m.iter().flatten() {
            let d = IBig::from(v.denominator().clone());
            let g = crate::int_gcd(&lcm, &d);
            lcm = &lcm / &g * d;
        }
        let mut out: [[IBig; 4]; 4] = Default::default();
        let mut g = IBig::ZERO;
        for i in 0..4 {
            for j in 0..4 {
                let v = &m[i][j];
                let k = &lcm / IBig::from(v.denominator().clone());
                out[i][j] = v.numerator() * k;
                g = crate::int_gcd(&g, &out[i][j]);
            }
        }
        if !g.is_zero() && !g.is_one() {
            for v in out.iter_mut().flatten() {
                *v = &*v / &g;
            }
        }
        SymMatrix4::new(out).expect("the input matrix is symmetric")
    }

    /// The entries.
    pub fn entries(&self) -> &[[IBig; 4]; 4] {
        &self.m
    }

    /// `true` if every entry is zero.
    pub fn is_zero(&self) -> bool {
        self.m.iter().flatten().all(|v| v.is_zero())
    }

    /// `a·self − b·other`.
    pub fn combine(&self, a: &IBig, other: &SymMatrix4, b: &IBig) -> SymMatrix4 {
        let mut out: [[IBig; 4]; 4] = Default::default();
        for i in 0..4 {
            for j in 0..4 {
                out[i][j] = a * &self.m[i][j] - b * &other.m[i][j];
            }
        }
        SymMatrix4 { m: out }
    }

    /// `true` if `self` and `other` are linearly dependent (one is a multiple of the other,
    /// or one is zero).
    pub fn is_proportional(&self, other: &SymMatrix4) -> bool {
        let a: Vec<&IBig> = self.m.iter().flatten().collect();
        let b: Vec<&IBig> = other.m.iter().flatten().collect();
        // With a pivot k where self is nonzero, other = (b_k / a_k)·self iff
        // a_k·b_i = b_k·a_i for every i.
        match (0..16).find(|&k| !a[k].is_zero()) {
            None => true,
            Some(k) => (0..16).all(|i| a[k] * b[i] == b[k] * a[i]),
        }
    }

    /// Sums `[E₁, E₂, E₃, E₄]` of the principal minors of each order (`E₄` is the determinant).
    pub fn principal_minor_sums(&self) -> [IBig; 4] {
        minors::principal_minor_sums(&self.m)
    }

    /// The determinant.
    pub fn det(&self) -> IBig {
        minors::det(&self.m)
    }

    /// The same matrix as a [`Matrix`].
    pub fn to_matrix(&self) -> Matrix<IBig> {
        Matrix::from_array(self.m.clone())
    }

    /// Exact inertia from the signs of the principal minor sums (Descartes on the
    /// characteristic polynomial).
    ///
    /// ```
    /// # use qsic_algebra::matrix::{SymMatrix4, Inertia};
    /// let m = SymMatrix4::from_i64([[0, 1, 0, 0], [1, 0, 0, 0], [0, 0, 3, 0], [0, 0, 0, 0]]).unwrap();
    /// assert_eq!(m.inertia(), Inertia { positive: 2, negative: 1, zero: 1 });
    /// ```
    pub fn inertia(&self) -> Inertia {
        let e = self.principal_minor_sums();
        Inertia::from_minor_sum_signs([
            Sign::of(&e[0]),
            Sign::of(&e[1]),
            Sign::of(&e[2]),
            Sign::of(&e[3]),
        ])
    }

    /// The rank.
    pub fn rank(&self) -> u8 {
        self.inertia().rank()
    }
}

/// The pencil `λA − μB` of two 4×4 matrices over a coefficient ring `C`, studied through
/// polynomials in `λ` over `C` on the chart `μ = 1`; each is a binary form of a known degree
/// `k` in `(λ, μ)`, so a degree drop below `k` is a root at `λ = ∞` of that multiplicity.
///
/// `MatrixPencil` (over ℤ) is the pencil of two quadrics; `MatrixPencil<Poly>` (entries in
/// ℤ\[t\]) is that of two moving quadrics `A(t), B(t)`, with `det(λA(t) − B(t))` a
/// `Poly<Poly>` (λ outer, t inner). Every minor of `λA − B` is computed once, at construction
/// ([`SmallMinors::of_pencil`]: evaluation at five values of `λ` and interpolation).
#[derive(Clone)]
pub struct MatrixPencil<C = IBig> {
    a: [[C; 4]; 4],
    b: [[C; 4]; 4],
    minors: SmallMinors<Poly<C>>,
}

impl<C: Ring> std::fmt::Debug for MatrixPencil<C> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "MatrixPencil(A = {:?}, B = {:?})", self.a, self.b)
    }
}

/// Two pencils are equal when their matrices are.
impl<C: Ring> PartialEq for MatrixPencil<C> {
    fn eq(&self, other: &Self) -> bool {
        self.a == other.a && self.b == other.b
    }
}

impl<C: Ring + Eq> Eq for MatrixPencil<C> {}

impl MatrixPencil {
    /// The pencil `λA − μB` of two symmetric integer matrices.
    pub fn new(a: SymMatrix4, b: SymMatrix4) -> MatrixPencil {
        MatrixPencil::from_entries(a.m, b.m)
    }
}

impl<C: Ring> MatrixPencil<C> {
    /// The pencil `λA − μB` of two 4×4 matrices over `C` (symmetric or not; for symmetric
    /// ones each minor is computed once up to `minor(R, C) = minor(C, R)`).
    pub fn from_entries(a: [[C; 4]; 4], b: [[C; 4]; 4]) -> MatrixPencil<C> {
        let minors = SmallMinors::of_pencil(&a, &b);
        MatrixPencil { a, b, minors }
    }

    /// `A`.
    pub fn a(&self) -> &[[C; 4]; 4] {
        &self.a
    }

    /// `B`.
    pub fn b(&self) -> &[[C; 4]; 4] {
        &self.b
    }

    /// The member `λA − μB` at `(λ, μ)`.
    pub fn member(&self, lambda: &C, mu: &C) -> [[C; 4]; 4] {
        std::array::from_fn(|i| {
            std::array::from_fn(|j| lambda.mul(&self.a[i][j]).sub(&mu.mul(&self.b[i][j])))
        })
    }

    /// `f(λ) = det(λA − B)`, the characteristic polynomial (a binary quartic form).
    pub fn det_poly(&self) -> Poly<C> {
        self.minors.minor(&[0, 1, 2, 3], &[0, 1, 2, 3]).clone()
    }

    /// Every nonzero `k×k` minor of `λA − B` (`1 ≤ k ≤ 4`), for symmetric `A`, `B` each once
    /// up to the symmetry `minor(R, C) = minor(C, R)`.
    pub fn minors(&self, k: usize) -> Vec<Poly<C>> {
        self.minors
            .of_order(k)
            .into_iter()
            .filter(|p| !p.is_zero())
            .cloned()
            .collect()
    }

    /// The minor of `λA − B` on the given rows and columns (increasing, of one length).
    ///
    /// # Panics
    /// If the sets are not increasing subsets of `0..4` of one length `k ≥ 1`.
    pub fn minor(&self, rows: &[usize], cols: &[usize]) -> &Poly<C> {
        self.minors.minor(rows, cols)
    }

    /// The four principal `3×3` minors of `λA − B` (rows and columns `{0,1,2,3} ∖ {i}`,
    /// `i = 3, 2, 1, 0`). For symmetric `A`, `B` a member has rank ≤ 2 iff these and the
    /// determinant vanish (the rank of a symmetric matrix is the largest order of a nonzero
    /// principal minor).
    pub fn principal_minors3(&self) -> [Poly<C>; 4] {
        const TRIPLES: [[usize; 3]; 4] = [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]];
        TRIPLES.map(|t| self.minors.minor(&t, &t).clone())
    }

    /// `[E₁(λ), …, E₄(λ)]`: the sums of principal minors of `λA − B` of each order.
    /// The inertia of the member at `λ` follows from their signs
    /// ([`Inertia::from_minor_sum_signs`]).
    pub fn principal_minor_sums(&self) -> [Poly<C>; 4] {
        self.minors
            .principal_minor_sums()
            .try_into()
            .expect("four sums of a 4×4 pencil")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn sym() -> impl Strategy<Value = SymMatrix4> {
        prop::collection::vec(-3i64..4, 10).prop_map(|v| {
            let mut m = [[0i64; 4]; 4];
            let mut k = 0;
            for i in 0..4 {
                for j in i..4 {
                    m[i][j] = v[k];
                    m[j][i] = v[k];
                    k += 1;
                }
            }
            SymMatrix4::from_i64(m).expect("symmetric by construction")
        })
    }

    /// The second route to the inertia: congruence diagonalization over ℚ (Sylvester).
    fn inertia_by_congruence(m: &SymMatrix4) -> Inertia {
        let q = m.to_matrix().map(|v| RBig::from(v.clone()));
        q.diagonalize_congruent().expect("symmetric").inertia()
    }

    proptest! {
        #[test]
        fn descartes_and_congruence_inertia_agree(m in sym()) {
            prop_assert_eq!(m.inertia(), inertia_by_congruence(&m));
        }

        #[test]
        fn pencil_polys_match_members(a in sym(), b in sym(), l in -5i64..6) {
            let p = MatrixPencil::new(a.clone(), b.clone());
            let lam = IBig::from(l);
            let member = SymMatrix4::new(p.member(&lam, &IBig::ONE)).expect("symmetric");
            let x = RBig::from(l);
            prop_assert_eq!(p.det_poly().eval_rational(&x), RBig::from(member.det()));
            let e = p.principal_minor_sums();
            let em = member.principal_minor_sums();
            for k in 0..4 {
                prop_assert_eq!(e[k].eval_rational(&x), RBig::from(em[k].clone()));
            }
        }
    }

    #[test]
    fn proportionality() {
        let a = SymMatrix4::from_i64([[0, 2, 0, 0], [2, 0, 0, 0], [0, 0, -4, 0], [0, 0, 0, 0]])
            .unwrap();
        let b = SymMatrix4::from_i64([[0, -3, 0, 0], [-3, 0, 0, 0], [0, 0, 6, 0], [0, 0, 0, 0]])
            .unwrap();
        let c = SymMatrix4::from_i64([[0, -3, 0, 0], [-3, 0, 0, 0], [0, 0, 6, 0], [0, 0, 0, 1]])
            .unwrap();
        let zero = SymMatrix4::from_i64([[0; 4]; 4]).unwrap();
        assert!(a.is_proportional(&b) && b.is_proportional(&a));
        assert!(!a.is_proportional(&c) && !c.is_proportional(&a));
        assert!(a.is_proportional(&zero) && zero.is_proportional(&a));
    }

    #[test]
    fn known_inertias() {
        let d = |a, b, c, e| {
            SymMatrix4::from_i64([[a, 0, 0, 0], [0, b, 0, 0], [0, 0, c, 0], [0, 0, 0, e]]).unwrap()
        };
        assert_eq!(
            d(1, 2, 0, -1).inertia(),
            Inertia {
                positive: 2,
                negative: 1,
                zero: 1
            }
        );
        assert_eq!(
            d(0, 0, 0, 0).inertia(),
            Inertia {
                positive: 0,
                negative: 0,
                zero: 4
            }
        );
        assert_eq!(
            d(-1, -1, -1, -1).inertia().negated(),
            Inertia {
                positive: 4,
                negative: 0,
                zero: 0
            }
        );
        let m = SymMatrix4::from_rationals_primitive(&[
            [
                RBig::from(2),
                RBig::from_parts_signed(1.into(), 2.into()),
                RBig::ZERO,
                RBig::ZERO,
            ],
            [
                RBig::from_parts_signed(1.into(), 2.into()),
                RBig::ZERO,
                RBig::ZERO,
                RBig::ZERO,
            ],
            [RBig::ZERO, RBig::ZERO, RBig::from(4), RBig::ZERO],
            [RBig::ZERO; 4],
        ]);
        assert_eq!(m.entries()[0][0], IBig::from(4));
        assert_eq!(m.entries()[0][1], IBig::from(1));
        assert_eq!(m.entries()[2][2], IBig::from(8));
    }

    #[test]
    fn rank_counts_nonzero_eigenvalues() {
        let m = SymMatrix4::from_i64([[1, 0, 0, 0], [0, -2, 0, 0], [0, 0, 0, 0], [0, 0, 0, 3]]);
        let m = m.expect("symmetric");
        assert_eq!(m.rank(), 3);
        assert_eq!(m.inertia().rank(), 3);
        assert!(!m.is_zero());
        assert!(SymMatrix4::from_i64([[0; 4]; 4])
            .expect("symmetric")
            .is_zero());
    }

    /// Zero diagonals force the congruence route through its `e_k + e_j` step: it must still
    /// agree with the principal-minor route on every such matrix with off-diagonal entries in
    /// {−1, 0, 1, 2} (and a diagonal that is zero or `(0, 0, 1, −2)`).
    #[test]
    fn congruence_with_zero_diagonals_agrees() {
        let values = [-1i64, 0, 1, 2];
        let pairs = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)];
        for diagonal in [[0, 0, 0, 0], [0, 0, 1, -2]] {
            for code in 0..4usize.pow(6) {
                let mut m = [[0i64; 4]; 4];
                for (k, &(i, j)) in pairs.iter().enumerate() {
                    let v = values[code / 4usize.pow(k as u32) % 4];
                    (m[i][j], m[j][i]) = (v, v);
                }
                for i in 0..4 {
                    m[i][i] = diagonal[i];
                }
                let s = SymMatrix4::from_i64(m).expect("symmetric");
                assert_eq!(inertia_by_congruence(&s), s.inertia(), "{m:?}");
            }
        }
    }

    /// A diagonal pencil `λI − diag(1, 2, 3, 4)`: its nonzero `k×k` minors are the products
    /// of `k` distinct factors `λ − i` (the principal ones); a singular pencil (a common
    /// kernel vector) has no nonzero 4×4 minor.
    #[test]
    fn minors_of_a_diagonal_pencil() {
        let diag = |d: [i64; 4]| {
            let mut m = [[0i64; 4]; 4];
            for i in 0..4 {
                m[i][i] = d[i];
            }
            SymMatrix4::from_i64(m).expect("symmetric")
        };
        let pencil = MatrixPencil::new(diag([1, 1, 1, 1]), diag([1, 2, 3, 4]));
        let sorted = |mut v: Vec<String>| {
            v.sort();
            v
        };
        let factors: Vec<Poly> = (1..=4).map(|i| Poly::from_i64s(&[-i, 1])).collect();
        for (k, subsets) in [
            (1, vec![vec![0], vec![1], vec![2], vec![3]]),
            (
                2,
                vec![
                    vec![0, 1],
                    vec![0, 2],
                    vec![0, 3],
                    vec![1, 2],
                    vec![1, 3],
                    vec![2, 3],
                ],
            ),
            (
                3,
                vec![vec![0, 1, 2], vec![0, 1, 3], vec![0, 2, 3], vec![1, 2, 3]],
            ),
            (4, vec![vec![0, 1, 2, 3]]),
        ] {
            let want: Vec<String> = subsets
                .iter()
                .map(|s| {
                    s.iter()
                        .fold(Poly::from_i64s(&[1]), |acc, &i| &acc * &factors[i])
                })
                .map(|p| format!("{p:?}"))
                .collect();
            let got = pencil.minors(k).iter().map(|p| format!("{p:?}")).collect();
            assert_eq!(sorted(got), sorted(want), "k = {k}");
        }
        assert!(pencil.minors(0).is_empty() && pencil.minors(5).is_empty());
        let singular = MatrixPencil::new(diag([1, 1, 1, 0]), diag([1, 2, 3, 0]));
        assert!(singular.minors(4).is_empty());
        assert_eq!(singular.minors(3).len(), 1);
    }

    /// A pencil over ℤ[t] (moving quadrics `A(t)`, `B(t)`): `det(λA(t) − B(t))` and every
    /// minor, specialised at `t = t₀`, are those of the integer pencil `(A(t₀), B(t₀))`.
    #[test]
    fn moving_pencil_specialises_to_integer_pencils() {
        // A(t) = A₀ + tA₁, B(t) = B₀ + t²B₁ with small symmetric integer matrices
        let a0 = [[1, 0, 2, 0], [0, -1, 0, 1], [2, 0, 0, 3], [0, 1, 3, 2]];
        let a1 = [[0, 1, 0, 0], [1, 2, 0, 0], [0, 0, -1, 1], [0, 0, 1, 0]];
        let b0 = [[2, 1, 0, 0], [1, 0, 1, 0], [0, 1, 3, 0], [0, 0, 0, -1]];
        let b1 = [[1, 0, 0, 1], [0, 0, 0, 0], [0, 0, 1, 0], [1, 0, 0, 0]];
        let a: [[Poly; 4]; 4] = std::array::from_fn(|i| {
            std::array::from_fn(|j| Poly::from_i64s(&[a0[i][j], a1[i][j]]))
        });
        let b: [[Poly; 4]; 4] = std::array::from_fn(|i| {
            std::array::from_fn(|j| Poly::from_i64s(&[b0[i][j], 0, b1[i][j]]))
        });
        let moving = MatrixPencil::from_entries(a, b);
        let f: Poly<Poly> = moving.det_poly();
        assert_eq!(f.degree(), Some(4));
        for t in -3i64..4 {
            let at = |m: &[[Poly; 4]; 4]| m.clone().map(|r| r.map(|p| p.eval(&IBig::from(t))));
            let fixed = MatrixPencil::from_entries(at(moving.a()), at(moving.b()));
            let special = |p: &Poly<Poly>| p.map(|c| c.eval(&IBig::from(t)));
            assert_eq!(special(&f), fixed.det_poly(), "t = {t}");
            for (m, e) in moving
                .principal_minor_sums()
                .iter()
                .zip(fixed.principal_minor_sums())
            {
                assert_eq!(special(m), e, "t = {t}");
            }
            for k in 1..=3 {
                let mut got: Vec<String> = moving
                    .minors(k)
                    .iter()
                    .map(special)
                    .filter(|p| !p.is_zero())
                    .map(|p| p.to_string())
                    .collect();
                let mut want: Vec<String> = fixed.minors(k).iter().map(|p| p.to_string()).collect();
                got.sort();
                want.sort();
                assert_eq!(got, want, "t = {t}, k = {k}");
            }
        }
    }

    /// Integer entries with a common factor are divided by it; the zero matrix stays zero.
    #[test]
    fn primitive_divides_by_the_common_factor() {
        let r = |v: i64| RBig::from(v);
        let mut m: [[RBig; 4]; 4] = Default::default();
        (m[0][0], m[1][1], m[2][3], m[3][2]) = (r(6), r(-4), r(10), r(10));
        let p = SymMatrix4::from_rationals_primitive(&m);
        let e = p.entries();
        assert_eq!(
            (&e[0][0], &e[1][1], &e[2][3]),
            (&IBig::from(3), &IBig::from(-2), &IBig::from(5))
        );
        let zero: [[RBig; 4]; 4] = Default::default();
        assert!(SymMatrix4::from_rationals_primitive(&zero).is_zero());
    }
}
