//! Exact linear algebra over a [`Ring`] or a [`Field`](crate::Field): one implementation of determinants
//! and minors for every ring (ℤ as `IBig` or bounded `i128`, ℚ, ℤ\[t\], ℚ(√δ), ℚ(α), …).
//!
//! | entry point | over | computes |
//! |---|---|---|
//! | [`Matrix`] | any ring | dense `rows × cols` matrix: construction from arrays and rows, products, transpose |
//! | [`minors::det`], [`minors::principal_minor_sums`], [`minors::SmallMinors`] | ring | `N × N` (`N ≤ 4`, arrays, no division, no allocation): determinant, the sums `E_k` of principal minors (characteristic polynomial), every minor once |
//! | [`pencil::pencil_principal_minor_sums`], [`SmallMinors::of_pencil`](minors::SmallMinors::of_pencil) | ring | the same for a pencil `λA − B`, as polynomials in `λ` (evaluation at `λ = ∞, 0, ±1, 2` and interpolation) |
//! | [`Matrix::det`], [`Matrix::minors`], [`Matrix::principal_minor_sums`], [`Matrix::pivot_columns`] | ring | any size, by Bareiss' fraction-free elimination ([`minors::det_bareiss`]) |
//! | [`modular::det_modular_within`] | ℤ\[t\] | the determinant by evaluation, interpolation and remaindering modulo 61-bit primes (an accelerator beside Bareiss) |
//! | [`Matrix::rref`], [`Matrix::rank`], [`Matrix::kernel`], [`Matrix::solve`], [`Matrix::inverse`] | field | Gauss–Jordan elimination ([`echelon`]) |
//! | [`Matrix::diagonalize_congruent`] | field | `PᵀSP = D` for a symmetric `S` ([`congruence`]); inertia over a [`RealField`], kernel |
//! | [`forms::real_point`], [`forms::plane_pair`] | ℚ | a real point of an indefinite quadratic form, the two planes of a rank-2 form, over ℚ or ℚ(√δ) ([`forms`]) |

pub mod congruence;
pub mod echelon;
pub mod forms;
pub mod minors;
pub mod modular;
pub mod pencil;

pub use congruence::Diagonalization;

use crate::ring::{RealField, Ring};
use crate::sign::Sign;
use std::fmt;
use std::ops::{Index, IndexMut, Mul};

/// A dense `rows × cols` matrix over a ring, stored row by row.
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct Matrix<C> {
    rows: usize,
    cols: usize,
    data: Vec<C>,
}

impl<C: Ring> Matrix<C> {
    /// The matrix with entries `f(i, j)`.
    pub fn from_fn(rows: usize, cols: usize, mut f: impl FnMut(usize, usize) -> C) -> Self {
        let data = (0..rows * cols).map(|k| f(k / cols, k % cols)).collect();
        Matrix { rows, cols, data }
    }

    /// The zero matrix.
    pub fn zero(rows: usize, cols: usize) -> Self {
        Matrix::from_fn(rows, cols, |_, _| C::zero())
    }

    /// The `n × n` identity.
    pub fn identity(n: usize) -> Self {
        Matrix::from_fn(n, n, |i, j| if i == j { C::one() } else { C::zero() })
    }

    /// From rows of equal length; `None` if they differ (no rows: the `0 × 0` matrix).
    pub fn from_rows(rows: Vec<Vec<C>>) -> Option<Self> {
        let cols = rows.first().map_or(0, Vec::len);
        if rows.iter().any(|r| r.len() != cols) {
            return None;
        }
        let n = rows.len();
        Some(Matrix {
            rows: n,
            cols,
            data: rows.into_iter().flatten().collect(),
        })
    }

    /// From an array of rows.
    pub fn from_array<const M: usize, const N: usize>(a: [[C; N]; M]) -> Self {
        Matrix {
            rows: M,
            cols: N,
            data: a.into_iter().flatten().collect(),
        }
    }

    /// The entries as an array of rows; `None` if the size is not `M × N`.
    pub fn to_array<const M: usize, const N: usize>(&self) -> Option<[[C; N]; M]> {
        (self.rows == M && self.cols == N)
            .then(|| std::array::from_fn(|i| std::array::from_fn(|j| self[(i, j)].clone())))
    }

    /// The number of rows.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// The number of columns.
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Row `i`.
    pub fn row(&self, i: usize) -> &[C] {
        &self.data[i * self.cols..(i + 1) * self.cols]
    }

    /// Column `j`, copied.
    pub fn column(&self, j: usize) -> Vec<C> {
        (0..self.rows).map(|i| self[(i, j)].clone()).collect()
    }

    /// `true` for a square matrix equal to its transpose.
    pub fn is_symmetric(&self) -> bool {
        self.rows == self.cols
            && (0..self.rows).all(|i| (i + 1..self.cols).all(|j| self[(i, j)] == self[(j, i)]))
    }

    /// `true` if every entry is zero.
    pub fn is_zero(&self) -> bool {
        self.data.iter().all(Ring::is_zero)
    }

    /// The transpose.
    pub fn transpose(&self) -> Self {
        Matrix::from_fn(self.cols, self.rows, |i, j| self[(j, i)].clone())
    }

    /// Applies a ring map to every entry (ℤ → ℚ, ℚ → ℚ(√δ), evaluation, …).
    pub fn map<D: Ring>(&self, f: impl FnMut(&C) -> D) -> Matrix<D> {
        Matrix {
            rows: self.rows,
            cols: self.cols,
            data: self.data.iter().map(f).collect(),
        }
    }

    /// The submatrix on the given rows and columns (in the order given).
    pub fn submatrix(&self, rows: &[usize], cols: &[usize]) -> Self {
        Matrix::from_fn(rows.len(), cols.len(), |i, j| {
            self[(rows[i], cols[j])].clone()
        })
    }

    /// `self · v`.
    ///
    /// # Panics
    /// If `v.len() ≠ cols`.
    pub fn mul_vec(&self, v: &[C]) -> Vec<C> {
        assert_eq!(v.len(), self.cols, "vector length against matrix columns");
        (0..self.rows).map(|i| dot(self.row(i), v)).collect()
    }

    /// `vᵀ · self · v`, the quadratic form of a square matrix at `v`.
    ///
    /// # Panics
    /// If the matrix is not square of size `v.len()`.
    pub fn quadratic_form(&self, v: &[C]) -> C {
        dot(v, &self.mul_vec(v))
    }
}

/// `Σ aᵢbᵢ`.
pub(crate) fn dot<C: Ring>(a: &[C], b: &[C]) -> C {
    let mut acc = C::zero();
    for (x, y) in a.iter().zip(b) {
        acc.add_mul_assign(x, y);
    }
    acc
}

impl<C> Index<(usize, usize)> for Matrix<C> {
    type Output = C;
    fn index(&self, (i, j): (usize, usize)) -> &C {
        assert!(
            i < self.rows && j < self.cols,
            "index ({i}, {j}) out of range"
        );
        &self.data[i * self.cols + j]
    }
}

impl<C> IndexMut<(usize, usize)> for Matrix<C> {
    fn index_mut(&mut self, (i, j): (usize, usize)) -> &mut C {
        assert!(
            i < self.rows && j < self.cols,
            "index ({i}, {j}) out of range"
        );
        &mut self.data[i * self.cols + j]
    }
}

/// The matrix product.
///
/// # Panics
/// If the inner dimensions differ.
impl<C: Ring> Mul for &Matrix<C> {
    type Output = Matrix<C>;
    fn mul(self, rhs: &Matrix<C>) -> Matrix<C> {
        assert_eq!(self.cols, rhs.rows, "matrix product dimensions");
        let mut out = Matrix::<C>::zero(self.rows, rhs.cols);
        for i in 0..self.rows {
            for k in 0..self.cols {
                let a = &self[(i, k)];
                if a.is_zero() {
                    continue;
                }
                for j in 0..rhs.cols {
                    out[(i, j)].add_mul_assign(a, &rhs[(k, j)]);
                }
            }
        }
        out
    }
}

impl<C: fmt::Display> fmt::Display for Matrix<C> {
    /// `[[a, b], [c, d]]`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("[")?;
        for i in 0..self.rows {
            f.write_str(if i == 0 { "[" } else { ", [" })?;
            for (j, v) in self.data[i * self.cols..(i + 1) * self.cols]
                .iter()
                .enumerate()
            {
                if j > 0 {
                    f.write_str(", ")?;
                }
                write!(f, "{v}")?;
            }
            f.write_str("]")?;
        }
        f.write_str("]")
    }
}

impl<C: fmt::Debug> fmt::Debug for Matrix<C> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let rows: Vec<&[C]> = (0..self.rows)
            .map(|i| &self.data[i * self.cols..(i + 1) * self.cols])
            .collect();
        write!(f, "Matrix{}x{}{rows:?}", self.rows, self.cols)
    }
}

/// The inertia of a real symmetric matrix: numbers of positive, negative and zero eigenvalues
/// (Sylvester: the signs of any diagonal matrix congruent to it).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Inertia {
    /// Positive eigenvalues.
    pub positive: u8,
    /// Negative eigenvalues.
    pub negative: u8,
    /// Zero eigenvalues (size − rank).
    pub zero: u8,
}

impl Inertia {
    /// The rank `positive + negative`.
    pub fn rank(&self) -> u8 {
        self.positive + self.negative
    }

    /// The inertia of `−M`.
    pub fn negated(&self) -> Inertia {
        Inertia {
            positive: self.negative,
            negative: self.positive,
            zero: self.zero,
        }
    }

    /// `true` if both signs occur (`XᵀMX = 0` has a real solution `X ≠ 0` off the kernel).
    pub fn is_indefinite(&self) -> bool {
        self.positive > 0 && self.negative > 0
    }

    /// The inertia of an `N × N` symmetric matrix from the signs of the sums `E₁…E_N` of its
    /// principal minors of each order: the characteristic polynomial
    /// `Σ (−1)ᵏ E_k x^(N−k)` is real-rooted, so Descartes' rule counts its positive roots
    /// (variations of `1, −E₁, E₂, −E₃, …`) and negative roots (variations of `1, E₁, E₂, …`)
    /// exactly.
    ///
    /// ```
    /// # use qsic_algebra::{linalg::Inertia, Sign::*};
    /// // diag(2, −1, 0): E₁ = 1, E₂ = −2, E₃ = 0
    /// let i = Inertia::from_minor_sum_signs([Positive, Negative, Zero]);
    /// assert_eq!(i, Inertia { positive: 1, negative: 1, zero: 1 });
    /// ```
    pub fn from_minor_sum_signs<const N: usize>(e: [Sign; N]) -> Inertia {
        let alternating = e
            .iter()
            .enumerate()
            .map(|(k, &s)| if k % 2 == 0 { -s } else { s });
        let pos = crate::sign::count_variations(std::iter::once(Sign::Positive).chain(alternating));
        let neg = crate::sign::count_variations(std::iter::once(Sign::Positive).chain(e));
        Inertia {
            positive: pos as u8,
            negative: neg as u8,
            zero: (N - pos - neg) as u8,
        }
    }

    /// The inertia of a diagonal matrix over a real field.
    pub fn of_diagonal<F: RealField>(d: &[F]) -> Inertia {
        let count = |s: Sign| d.iter().filter(|v| v.sign() == s).count() as u8;
        Inertia {
            positive: count(Sign::Positive),
            negative: count(Sign::Negative),
            zero: count(Sign::Zero),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{IBig, RBig};

    #[test]
    fn construction_and_products() {
        let a = Matrix::from_array([[1, 2, 3], [4, 5, 6]].map(|r| r.map(IBig::from)));
        assert_eq!((a.rows(), a.cols()), (2, 3));
        assert_eq!(
            a.to_array::<2, 3>(),
            Some([[1, 2, 3], [4, 5, 6]].map(|r| r.map(IBig::from)))
        );
        assert_eq!(a.to_array::<3, 2>(), None);
        let rows = vec![vec![IBig::from(1), IBig::from(2)], vec![IBig::from(3)]];
        assert!(Matrix::from_rows(rows).is_none());
        // (AAᵀ)ᵢⱼ = rowᵢ · rowⱼ
        let g = &a * &a.transpose();
        assert_eq!(
            g.to_array::<2, 2>(),
            Some([[14, 32], [32, 77]].map(|r| r.map(IBig::from)))
        );
        assert!(g.is_symmetric() && !a.is_symmetric());
        let v = [IBig::from(1), IBig::from(-1)];
        assert_eq!(g.quadratic_form(&v), IBig::from(14 - 64 + 77));
        assert_eq!(a.column(2), vec![IBig::from(3), IBig::from(6)]);
        assert_eq!(
            a.submatrix(&[1], &[2, 0]).row(0),
            &[IBig::from(6), IBig::from(4)]
        );
        assert_eq!(g.to_string(), "[[14, 32], [32, 77]]");
        assert!(Matrix::<IBig>::zero(2, 2).is_zero() && !g.is_zero());
    }

    #[test]
    fn inertia_from_minor_sums_and_diagonals() {
        // every diagonal matrix with entries in {−2, 0, 3} of size 1..=4: both routes
        for n in 1..=4usize {
            for code in 0..3usize.pow(n as u32) {
                let d: Vec<RBig> = (0..n)
                    .map(|i| RBig::from([-2, 0, 3][code / 3usize.pow(i as u32) % 3]))
                    .collect();
                let m =
                    Matrix::from_fn(n, n, |i, j| if i == j { d[i].clone() } else { RBig::ZERO });
                let e = m.principal_minor_sums();
                let signs: Vec<Sign> = e.iter().map(RealField::sign).collect();
                let by_minors = match n {
                    1 => Inertia::from_minor_sum_signs::<1>(signs.try_into().unwrap()),
                    2 => Inertia::from_minor_sum_signs::<2>(signs.try_into().unwrap()),
                    3 => Inertia::from_minor_sum_signs::<3>(signs.try_into().unwrap()),
                    _ => Inertia::from_minor_sum_signs::<4>(signs.try_into().unwrap()),
                };
                assert_eq!(by_minors, Inertia::of_diagonal(&d), "{d:?}");
            }
        }
    }
}
