//! Gauss–Jordan elimination over a field: reduced row echelon form, rank, kernel, linear
//! systems, inverses. `O(mn·min(m, n))` field operations each.

use super::Matrix;
use crate::ring::Field;

/// A reduced row echelon form: the rows above `pivots.len()` have a leading one in the pivot
/// column, zeros elsewhere in that column; the other rows are zero.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Rref<F> {
    /// The reduced matrix.
    pub matrix: Matrix<F>,
    /// The pivot column of each nonzero row, increasing.
    pub pivots: Vec<usize>,
}

impl<F: Field> Matrix<F> {
    /// The reduced row echelon form (it is unique: two matrices have the same one iff they
    /// have the same row space).
    ///
    /// ```
    /// # use qsic_algebra::{linalg::Matrix, RBig};
    /// let m = Matrix::from_array([[2, 4, 1], [1, 2, 0]].map(|r| r.map(RBig::from)));
    /// let r = m.rref();
    /// assert_eq!(r.pivots, vec![0, 2]);
    /// assert_eq!(r.matrix.row(0), &[RBig::ONE, RBig::from(2), RBig::ZERO]);
    /// ```
    pub fn rref(&self) -> Rref<F> {
        let mut m = self.clone();
        let (rows, cols) = (m.rows(), m.cols());
        let mut pivots = Vec::new();
        for col in 0..cols {
            let top = pivots.len();
            if top == rows {
                break;
            }
            let Some(p) = (top..rows).find(|&r| !m[(r, col)].is_zero()) else {
                continue;
            };
            for j in col..cols {
                let (x, y) = (m[(p, j)].clone(), m[(top, j)].clone());
                m[(p, j)] = y;
                m[(top, j)] = x;
            }
            let inv = m[(top, col)].inv().expect("a nonzero pivot");
            for j in col..cols {
                m[(top, j)] = m[(top, j)].mul(&inv);
            }
            for i in (0..rows).filter(|&i| i != top) {
                let f = m[(i, col)].clone();
                if f.is_zero() {
                    continue;
                }
                for j in col..cols {
                    let t = m[(top, j)].clone();
                    m[(i, j)].sub_mul_assign(&f, &t);
                }
            }
            pivots.push(col);
        }
        Rref { matrix: m, pivots }
    }

    /// The rank.
    pub fn rank(&self) -> usize {
        self.rref().pivots.len()
    }

    /// A basis of the kernel `{x : Ax = 0}`: one vector per non-pivot column `f`, with a one
    /// at `f` and zeros at the other non-pivot columns. `cols − rank` vectors.
    ///
    /// ```
    /// # use qsic_algebra::{linalg::Matrix, RBig};
    /// let m = Matrix::from_array([[1, 2, 3], [2, 4, 6]].map(|r| r.map(RBig::from)));
    /// let k = m.kernel();
    /// assert_eq!(k.len(), 2);
    /// assert!(k.iter().all(|v| m.mul_vec(v).iter().all(|x| *x == RBig::ZERO)));
    /// ```
    pub fn kernel(&self) -> Vec<Vec<F>> {
        let Rref { matrix, pivots } = self.rref();
        (0..self.cols())
            .filter(|f| !pivots.contains(f))
            .map(|f| {
                let mut v = vec![F::zero(); self.cols()];
                v[f] = F::one();
                for (row, &p) in pivots.iter().enumerate() {
                    v[p] = matrix[(row, f)].neg();
                }
                v
            })
            .collect()
    }

    /// A solution of `Ax = b` (the one with every free variable zero), or `None` if there is
    /// none; every solution is it plus a kernel vector ([`Matrix::kernel`]).
    ///
    /// # Panics
    /// If `b.len()` is not the number of rows.
    pub fn solve(&self, b: &[F]) -> Option<Vec<F>> {
        assert_eq!(b.len(), self.rows(), "right-hand side length against rows");
        let augmented = Matrix::from_fn(self.rows(), self.cols() + 1, |i, j| {
            if j < self.cols() {
                self[(i, j)].clone()
            } else {
                b[i].clone()
            }
        });
        let Rref { matrix, pivots } = augmented.rref();
        if pivots.last() == Some(&self.cols()) {
            return None;
        }
        let mut x = vec![F::zero(); self.cols()];
        for (row, &p) in pivots.iter().enumerate() {
            x[p] = matrix[(row, self.cols())].clone();
        }
        Some(x)
    }

    /// The inverse of a square matrix, `None` if it is singular (or not square).
    pub fn inverse(&self) -> Option<Matrix<F>> {
        let n = self.rows();
        if self.cols() != n {
            return None;
        }
        let augmented = Matrix::from_fn(n, 2 * n, |i, j| {
            if j < n {
                self[(i, j)].clone()
            } else if j - n == i {
                F::one()
            } else {
                F::zero()
            }
        });
        let Rref { matrix, pivots } = augmented.rref();
        // invertible iff the left block reduces to the identity
        pivots
            .iter()
            .copied()
            .eq(0..n)
            .then(|| Matrix::from_fn(n, n, |i, j| matrix[(i, n + j)].clone()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::Quadratic;
    use crate::{IBig, RBig, Ring};
    use proptest::prelude::*;

    fn rational_matrix(rows: usize, cols: usize) -> impl Strategy<Value = Matrix<RBig>> {
        // small entries, many zeros, so that rank deficiency is common
        prop::collection::vec((-3i64..4, 1i64..4, 0u8..3), rows * cols).prop_map(move |v| {
            Matrix::from_fn(rows, cols, |i, j| {
                let (p, q, keep) = v[i * cols + j];
                if keep == 0 {
                    RBig::ZERO
                } else {
                    RBig::from_parts_signed(IBig::from(p), IBig::from(q))
                }
            })
        })
    }

    /// Entries `a + b√2` (or `a + b√−3`, a field that is not ordered).
    fn quadratic_matrix(n: usize, delta: i64) -> impl Strategy<Value = Matrix<Quadratic>> {
        prop::collection::vec((-2i64..3, -2i64..3, 0u8..3), n * n).prop_map(move |v| {
            Matrix::from_fn(n, n, |i, j| {
                let (a, b, keep) = v[i * n + j];
                if keep == 0 {
                    Quadratic::zero()
                } else {
                    Quadratic::new(RBig::from(a), RBig::from(b), IBig::from(delta)).unwrap()
                }
            })
        })
    }

    fn is_zero_vec<F: Field>(v: &[F]) -> bool {
        v.iter().all(Ring::is_zero)
    }

    fn check_field_identities<F: Field>(m: &Matrix<F>, x0: &[F]) -> Result<(), TestCaseError> {
        let (r, n) = (m.rank(), m.cols());
        let kernel = m.kernel();
        prop_assert_eq!(r + kernel.len(), n);
        for k in &kernel {
            prop_assert!(is_zero_vec(&m.mul_vec(k)));
        }
        // the kernel vectors are independent: the matrix they form has full rank
        if !kernel.is_empty() {
            let km = Matrix::from_rows(kernel.clone()).unwrap();
            prop_assert_eq!(km.rank(), kernel.len());
        }
        // a consistent system is solved; adding a column outside the span is not
        let b = m.mul_vec(x0);
        let x = m.solve(&b).expect("b is in the column space");
        prop_assert_eq!(m.mul_vec(&x), b.clone());
        if r < m.rows() {
            // some unit vector leaves the column space; then no solution
            let outside = (0..m.rows()).find_map(|i| {
                let e: Vec<F> = (0..m.rows())
                    .map(|k| if k == i { F::one() } else { F::zero() })
                    .collect();
                let aug = Matrix::from_fn(m.rows(), n + 1, |p, q| {
                    if q < n {
                        m[(p, q)].clone()
                    } else {
                        e[p].clone()
                    }
                });
                (aug.rank() > r).then_some(e)
            });
            let e = outside.expect("a unit vector outside a proper subspace");
            prop_assert!(m.solve(&e).is_none());
        }
        if m.rows() == n {
            let det = m.det();
            prop_assert_eq!(det.is_zero(), r < n);
            match m.inverse() {
                Some(inv) => {
                    prop_assert!(r == n);
                    prop_assert_eq!(&(m * &inv), &Matrix::identity(n));
                    prop_assert_eq!(inv.det().mul(&det), F::one());
                }
                None => prop_assert!(r < n),
            }
        }
        Ok(())
    }

    proptest! {
        #[test]
        fn rank_kernel_solve_inverse_over_q(
            m in (1usize..5, 1usize..6).prop_flat_map(|(r, c)| rational_matrix(r, c)),
        ) {
            let x0: Vec<RBig> = (0..m.cols()).map(|i| RBig::from(i as i64 - 1)).collect();
            check_field_identities(&m, &x0)?;
        }

        #[test]
        fn determinant_is_multiplicative_over_q(a in rational_matrix(4, 4), b in rational_matrix(4, 4)) {
            prop_assert_eq!((&a * &b).det(), a.det() * b.det());
            prop_assert_eq!(a.transpose().det(), a.det());
        }

        #[test]
        fn field_identities_over_quadratic_fields(
            a in quadratic_matrix(3, 2), b in quadratic_matrix(3, 2), c in quadratic_matrix(3, -3),
        ) {
            let x0: Vec<Quadratic> = (0..3).map(|i| Quadratic::from_int(&IBig::from(i - 1))).collect();
            check_field_identities(&a, &x0)?;
            check_field_identities(&c, &x0)?;
            prop_assert_eq!((&a * &b).det(), a.det().mul(&b.det()));
        }
    }

    #[test]
    fn known_kernel_and_inverse() {
        let q = |v: i64| RBig::from(v);
        // rank 2: the third row is the sum of the first two
        let m = Matrix::from_array([[1, 2, 3], [0, 1, 1], [1, 3, 4]].map(|r| r.map(q)));
        assert_eq!(m.rank(), 2);
        assert_eq!(m.kernel(), vec![vec![q(-1), q(-1), q(1)]]);
        assert!(m.inverse().is_none());
        assert_eq!(m.solve(&[q(1), q(0), q(0)]), None);
        let n = Matrix::from_array([[2, 1], [1, 1]].map(|r| r.map(q)));
        let inv = n.inverse().unwrap();
        assert_eq!(inv.to_array(), Some([[q(1), q(-1)], [q(-1), q(2)]]));
        assert_eq!(Matrix::<RBig>::zero(2, 3).inverse(), None);
        assert_eq!(
            Matrix::<RBig>::zero(0, 0).inverse(),
            Some(Matrix::zero(0, 0))
        );
    }
}
