//! Congruence diagonalization of a symmetric matrix over a field: an invertible `P` with
//! `PᵀSP = D` diagonal (symmetric Gaussian elimination, `O(n³)` field operations).
//!
//! Method: for `k = 0, 1, …` make `D[k][k] ≠ 0` if the trailing block allows it — swap in a
//! later nonzero diagonal entry, or, if all are zero, replace the basis vector `e_k` by
//! `e_k + e_j` for a `j` with `S[k][j] ≠ 0` (the new diagonal entry is `2S[k][j]`,
//! characteristic zero) — then clear row and column `k` with the operations
//! `e_i ← e_i − (S[k][i]/S[k][k])e_k`. Each operation acts on `S` as `EᵀSE` and on `P` as `PE`.
//!
//! By Sylvester's law of inertia the signs of `D` over a real field are the signs of the
//! eigenvalues of `S`; the columns of `P` where `D` is zero are a basis of the kernel of `S`
//! (`S·Pe_i = P⁻ᵀDe_i = 0`): for a quadric, its vertex (rank 3), singular line (rank 2) or
//! plane (rank 1).

use super::{Inertia, Matrix};
use crate::ring::{Field, RealField};

/// `PᵀSP = D` for a symmetric `S`, `P` invertible, `D = diag(d)`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagonalization<F> {
    /// The transform `P` (its columns are the new basis).
    pub p: Matrix<F>,
    /// The diagonal of `D`.
    pub d: Vec<F>,
}

impl<F: Field> Matrix<F> {
    /// The congruence diagonalization `PᵀSP = D` (module docs); `None` if the matrix is not
    /// symmetric.
    ///
    /// ```
    /// # use qsic_algebra::{linalg::{Inertia, Matrix}, RBig};
    /// // 2xy: zero diagonal, one positive and one negative direction
    /// let s = Matrix::from_array([[0, 1], [1, 0]].map(|r| r.map(RBig::from)));
    /// let dg = s.diagonalize_congruent().unwrap();
    /// let d = &(&dg.p.transpose() * &s) * &dg.p;
    /// assert!(d[(0, 1)] == RBig::ZERO && d[(0, 0)] == dg.d[0]);
    /// assert_eq!(dg.inertia(), Inertia { positive: 1, negative: 1, zero: 0 });
    /// ```
    pub fn diagonalize_congruent(&self) -> Option<Diagonalization<F>> {
        if !self.is_symmetric() {
            return None;
        }
        let n = self.rows();
        let mut s = self.clone();
        let mut p = Matrix::identity(n);
        for k in 0..n {
            if s[(k, k)].is_zero() {
                if let Some(j) = (k + 1..n).find(|&j| !s[(j, j)].is_zero()) {
                    swap_basis(&mut s, &mut p, k, j);
                } else if let Some(j) = (k + 1..n).find(|&j| !s[(k, j)].is_zero()) {
                    add_basis(&mut s, &mut p, k, j, &F::one());
                } else {
                    continue;
                }
            }
            let inv = s[(k, k)].inv().expect("a nonzero pivot");
            for i in k + 1..n {
                if !s[(k, i)].is_zero() {
                    let f = s[(k, i)].mul(&inv).neg();
                    add_basis(&mut s, &mut p, i, k, &f);
                }
            }
        }
        debug_assert!((0..n).all(|i| (0..n).all(|j| i == j || s[(i, j)].is_zero())));
        let d = (0..n).map(|i| s[(i, i)].clone()).collect();
        Some(Diagonalization { p, d })
    }
}

/// Exchanges basis vectors `i` and `j`.
fn swap_basis<F: Field>(s: &mut Matrix<F>, p: &mut Matrix<F>, i: usize, j: usize) {
    let n = s.rows();
    for r in 0..n {
        let (a, b) = (s[(r, i)].clone(), s[(r, j)].clone());
        s[(r, i)] = b;
        s[(r, j)] = a;
    }
    for c in 0..n {
        let (a, b) = (s[(i, c)].clone(), s[(j, c)].clone());
        s[(i, c)] = b;
        s[(j, c)] = a;
        let (a, b) = (p[(c, i)].clone(), p[(c, j)].clone());
        p[(c, i)] = b;
        p[(c, j)] = a;
    }
}

/// `e_i ← e_i + f·e_j` (`i ≠ j`): column `i` of `S` and `P` gains `f` times column `j`, then
/// row `i` of `S` gains `f` times row `j`.
fn add_basis<F: Field>(s: &mut Matrix<F>, p: &mut Matrix<F>, i: usize, j: usize, f: &F) {
    let n = s.rows();
    for r in 0..n {
        let t = s[(r, j)].clone();
        s[(r, i)].add_mul_assign(f, &t);
        let t = p[(r, j)].clone();
        p[(r, i)].add_mul_assign(f, &t);
    }
    for c in 0..n {
        let t = s[(j, c)].clone();
        s[(i, c)].add_mul_assign(f, &t);
    }
}

impl<F: Field> Diagonalization<F> {
    /// The rank: the number of nonzero diagonal entries.
    pub fn rank(&self) -> usize {
        self.d.iter().filter(|v| !v.is_zero()).count()
    }

    /// A basis of the kernel of `S`: the columns of `P` where `D` is zero (for a quadric, its
    /// singular points: the vertex of a cone, the line of a plane pair, the plane of a double
    /// plane).
    pub fn kernel(&self) -> Vec<Vec<F>> {
        (0..self.d.len())
            .filter(|&i| self.d[i].is_zero())
            .map(|i| self.p.column(i))
            .collect()
    }
}

impl<F: RealField> Diagonalization<F> {
    /// The inertia of `S` (Sylvester): the signs of `D`.
    pub fn inertia(&self) -> Inertia {
        Inertia::of_diagonal(&self.d)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::Quadratic;
    use crate::{IBig, RBig, Ring};
    use proptest::prelude::*;

    fn symmetric<F: Field>(n: usize, v: &[F]) -> Matrix<F> {
        Matrix::from_fn(n, n, |i, j| v[i.min(j) * n + i.max(j)].clone())
    }

    /// `PᵀSP = D`, `P` invertible, the kernel annihilated and of dimension `n − rank`.
    fn check<F: Field>(s: &Matrix<F>) -> Result<Diagonalization<F>, TestCaseError> {
        let dg = s.diagonalize_congruent().expect("symmetric");
        let n = s.rows();
        let d = &(&dg.p.transpose() * s) * &dg.p;
        let diag = Matrix::from_fn(
            n,
            n,
            |i, j| if i == j { dg.d[i].clone() } else { F::zero() },
        );
        prop_assert_eq!(&d, &diag);
        prop_assert!(!dg.p.det().is_zero());
        let kernel = dg.kernel();
        prop_assert_eq!(kernel.len(), n - dg.rank());
        prop_assert_eq!(dg.rank(), s.rank());
        for k in &kernel {
            prop_assert!(s.mul_vec(k).iter().all(Ring::is_zero));
        }
        Ok(dg)
    }

    proptest! {
        /// Small entries with many zeros exercise the swap and the `e_k + e_j` steps; the
        /// inertia also equals the count from the principal minors (Descartes).
        #[test]
        fn diagonalizes_symmetric_rational_matrices(
            n in 1usize..6, v in prop::collection::vec((-2i64..3, 0u8..3), 25),
        ) {
            let q: Vec<RBig> = v.iter().map(|&(a, keep)| if keep == 0 { RBig::ZERO } else { RBig::from(a) }).collect();
            let s = symmetric(n, &q);
            let dg = check(&s)?;
            if n == 4 {
                let e = s.principal_minor_sums();
                let signs = [0, 1, 2, 3].map(|k| crate::RealField::sign(&e[k]));
                prop_assert_eq!(dg.inertia(), Inertia::from_minor_sum_signs(signs));
            }
        }

        #[test]
        fn diagonalizes_over_quadratic_fields(
            v in prop::collection::vec((-2i64..3, -1i64..2, 0u8..3), 16),
        ) {
            for delta in [5i64, -1] {
                let q: Vec<Quadratic> = v.iter().map(|&(a, b, keep)| {
                    if keep == 0 { Quadratic::zero() } else {
                        Quadratic::new(RBig::from(a), RBig::from(b), IBig::from(delta)).unwrap()
                    }
                }).collect();
                let s = symmetric(4, &q);
                let dg = check(&s)?;
                if delta > 0 {
                    // exact signs in ℚ(√5): the diagonal against the principal minors
                    let e = s.principal_minor_sums();
                    let signs = [0, 1, 2, 3].map(|k| crate::RealField::sign(&e[k]));
                    prop_assert_eq!(dg.inertia(), Inertia::from_minor_sum_signs(signs));
                }
            }
        }
    }

    #[test]
    fn zero_diagonals_and_refusals() {
        let q = |v: i64| RBig::from(v);
        // xy + zw: all diagonal entries zero, two hyperbolic planes
        let s = Matrix::from_array(
            [[0, 1, 0, 0], [1, 0, 0, 0], [0, 0, 0, 1], [0, 0, 1, 0]].map(|r| r.map(q)),
        );
        let dg = check(&s).unwrap();
        assert_eq!(
            dg.inertia(),
            Inertia {
                positive: 2,
                negative: 2,
                zero: 0
            }
        );
        // a cone x² + y² − z²: vertex (0, 0, 0, 1)
        let cone = Matrix::from_array(
            [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 0]].map(|r| r.map(q)),
        );
        let dg = check(&cone).unwrap();
        assert_eq!(dg.kernel(), vec![vec![q(0), q(0), q(0), q(1)]]);
        assert!(Matrix::from_array([[0, 1], [2, 0]].map(|r| r.map(q)))
            .diagonalize_congruent()
            .is_none());
        assert!(Matrix::<RBig>::zero(2, 3).diagonalize_congruent().is_none());
    }
}
