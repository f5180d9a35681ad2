//! Determinants and minors over an integral domain, written once for every ring.
//!
//! | entry point | computes | method | cost |
//! |---|---|---|---|
//! | [`det`], [`principal_minor_sums`] | `N × N` array, `N ≤ 4`: the determinant; `E₁…E_N` | expansion along first rows, each needed minor once | `N = 4`: 28 and 55 products, no division, no allocation |
//! | [`SmallMinors::all`] | every minor of an `N × N` array, `N ≤ 4` | the same expansion | `N = 4`: 124 products (76 if symmetric) |
//! | [`det_bareiss`], [`Matrix::det`] | `n × n` determinant | Bareiss' fraction-free elimination | `O(n³)` ring operations, exact divisions |
//! | [`Matrix::pivot_columns`] | pivot columns, so the rank over the fraction field | fraction-free row echelon form | `O(mn·min(m, n))` |
//! | [`Matrix::minors`], [`Matrix::principal_minor_sums`] | every `k × k` minor; `E₁…E_n` | one Bareiss determinant per minor | `C(m,k)·C(n,k)·k³`; `2ⁿn³` |
//!
//! `E_k` is the sum of the principal `k × k` minors: `det(xI − M) = Σ (−1)ᵏ E_k x^(n−k)`.
//!
//! The expansion computes a `k × k` minor on rows `r₀ < r₁ < …` and columns `C` as
//! `Σ_j ±m[r₀][c_j]·minor(rows without r₀, C without c_j)`. Only multiplications, additions
//! and subtractions are used, so it runs in machine words (`i128`) when the entries are
//! bounded, and over polynomial rings (the pencil `λA − B` has entries in `ℤ[λ]`, or in
//! `ℤ[t][λ]` for moving quadrics) without any division. A determinant needs only the minors
//! on the last rows; the principal sums need the minors with rows `R` and columns `C` whose
//! columns outside `R` all precede `min R`.

use super::Matrix;
use crate::ring::Ring;

/// The 2-subsets of `{0, 1, 2, 3}`, in lexicographic order.
const PAIRS: [[usize; 2]; 6] = [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]];
/// The 3-subsets of `{0, 1, 2, 3}`, in lexicographic order (index `3 −` the missing element).
const TRIPLES: [[usize; 3]; 4] = [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]];

/// The index of `{i, j}` (`i < j`) in [`PAIRS`].
const fn pair_index(i: usize, j: usize) -> usize {
    match (i, j) {
        (0, j) => j - 1,
        (1, j) => j + 1,
        _ => 5,
    }
}

const fn pair_mask(p: usize) -> u8 {
    (1 << PAIRS[p][0]) | (1 << PAIRS[p][1])
}

const fn triple_mask(t: usize) -> u8 {
    (1 << TRIPLES[t][0]) | (1 << TRIPLES[t][1]) | (1 << TRIPLES[t][2])
}

/// Which minors an expansion computes.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Need {
    /// Those on the last rows (the determinant's expansion).
    Det,
    /// Those the principal minors of every order need.
    Principal,
    /// All.
    All,
}

/// `true` if an expansion for `need` of an `n × n` matrix wants the minor on `rows`, `cols`
/// (bit masks).
const fn wants(need: Need, n: usize, rows: u8, cols: u8) -> bool {
    let first = rows & rows.wrapping_neg();
    match need {
        Need::All => true,
        // the last k rows
        Need::Det => rows as u16 + first as u16 == 1 << n,
        // the columns outside the rows all precede the first row
        Need::Principal => (cols & !rows) < first,
    }
}

/// The slots `(row set, column set)` an expansion fills, order 2 (indices into [`PAIRS`]) and
/// order 3 (into [`TRIPLES`]); computed at compile time for each size and need.
struct Plan {
    pairs: [(usize, usize); 36],
    pair_count: usize,
    triples: [(usize, usize); 16],
    triple_count: usize,
}

/// With `symmetric`, only slots with row set ≤ column set.
const fn plan(n: usize, need: Need, symmetric: bool) -> Plan {
    let mut p = Plan {
        pairs: [(0, 0); 36],
        pair_count: 0,
        triples: [(0, 0); 16],
        triple_count: 0,
    };
    let mut r = 0;
    while r < 6 {
        let mut c = 0;
        while c < 6 {
            if PAIRS[r][1] < n
                && PAIRS[c][1] < n
                && (!symmetric || r <= c)
                && wants(need, n, pair_mask(r), pair_mask(c))
            {
                p.pairs[p.pair_count] = (r, c);
                p.pair_count += 1;
            }
            c += 1;
        }
        r += 1;
    }
    let mut r = 0;
    while r < 4 {
        let mut c = 0;
        while c < 4 {
            if TRIPLES[r][2] < n
                && TRIPLES[c][2] < n
                && (!symmetric || r <= c)
                && wants(need, n, triple_mask(r), triple_mask(c))
            {
                p.triples[p.triple_count] = (r, c);
                p.triple_count += 1;
            }
            c += 1;
        }
        r += 1;
    }
    p
}

/// `body` for each of the first `count` slots of `list`, written out once per literal index.
macro_rules! unrolled {
    ($list:expr, $count:expr, |$r:ident, $c:ident| $body:block, [$($i:literal)*]) => {
        $(
            if $i < $count {
                let ($r, $c) = $list[$i];
                $body
            }
        )*
    };
}

/// The 2×2, 3×3 and 4×4 minors of an `N × N` array computed by expansion; slots not in the
/// plan are zero.
struct Expansion<R> {
    m2: [[R; 6]; 6],
    m3: [[R; 4]; 4],
    det: R,
}

/// The expansion itself (module docs). With `symmetric`, only slots `(R, C)` with `R ≤ C` are
/// computed and `minor(C, R) = minor(R, C)` is read from them.
// Inlined into each caller, so that its need and symmetry are constants there.
#[inline(always)]
fn expand<R: Ring, const N: usize>(m: &[[R; N]; N], need: Need, symmetric: bool) -> Expansion<R> {
    const {
        assert!(
            N >= 1 && N <= 4,
            "small-matrix expansion is for sizes 1 to 4"
        )
    };
    let plan: &Plan = match (need, symmetric) {
        (Need::Det, _) => const { &plan(N, Need::Det, false) },
        (Need::Principal, _) => const { &plan(N, Need::Principal, false) },
        (Need::All, false) => const { &plan(N, Need::All, false) },
        (Need::All, true) => const { &plan(N, Need::All, true) },
    };
    // The slot loops are unrolled by `unrolled!` (literal indices): with the plan a compile-time
    // constant, every index folds and the expansion is straight-line code.
    let mut m2: [[R; 6]; 6] = std::array::from_fn(|_| std::array::from_fn(|_| R::zero()));
    unrolled!(plan.pairs, plan.pair_count, |r, c| {
        let ([r0, r1], [c0, c1]) = (PAIRS[r], PAIRS[c]);
        let mut v = m[r0][c0].mul(&m[r1][c1]);
        v.sub_mul_assign(&m[r0][c1], &m[r1][c0]);
        m2[r][c] = v;
    }, [0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31 32 33 34 35]);
    let get2 = |r: usize, c: usize| {
        if symmetric && r > c {
            &m2[c][r]
        } else {
            &m2[r][c]
        }
    };
    let mut m3: [[R; 4]; 4] = std::array::from_fn(|_| std::array::from_fn(|_| R::zero()));
    unrolled!(plan.triples, plan.triple_count, |r, c| {
        let ([r0, r1, r2], [c0, c1, c2]) = (TRIPLES[r], TRIPLES[c]);
        let tail = pair_index(r1, r2);
        let mut v = m[r0][c0].mul(get2(tail, pair_index(c1, c2)));
        v.sub_mul_assign(&m[r0][c1], get2(tail, pair_index(c0, c2)));
        v.add_mul_assign(&m[r0][c2], get2(tail, pair_index(c0, c1)));
        m3[r][c] = v;
    }, [0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15]);
    let det = match N {
        1 => m[0][0].clone(),
        2 => m2[0][0].clone(),
        3 => m3[0][0].clone(),
        _ => {
            // row 0 against the minors on rows {1, 2, 3} (triple 3); without column j: triple 3 − j
            let get3 = |c: usize| if symmetric { &m3[c][3] } else { &m3[3][c] };
            let mut v = m[0][0].mul(get3(3));
            v.sub_mul_assign(&m[0][1], get3(2));
            v.add_mul_assign(&m[0][2], get3(1));
            v.sub_mul_assign(&m[0][3], get3(0));
            v
        }
    };
    Expansion { m2, m3, det }
}

/// The determinant of an `N × N` array (`N ≤ 4`) by expansion along its first rows: no
/// division, no allocation.
///
/// ```
/// # use qsic_algebra::linalg::minors::det;
/// assert_eq!(det(&[[2i128, 1, 0], [1, 3, 1], [0, 1, 4]]), 18);
/// ```
pub fn det<R: Ring, const N: usize>(m: &[[R; N]; N]) -> R {
    expand(m, Need::Det, false).det
}

/// `[E₁, …, E_N]`, the sums of the principal minors of each order of an `N × N` array
/// (`N ≤ 4`; `E_N` is the determinant): `det(xI − M) = Σ (−1)ᵏ E_k x^(N−k)`.
///
/// ```
/// # use qsic_algebra::linalg::minors::principal_minor_sums;
/// // diag(1, 2, 3): E₁ = 6, E₂ = 2 + 3 + 6, E₃ = 6
/// let m = [[1i128, 0, 0], [0, 2, 0], [0, 0, 3]];
/// assert_eq!(principal_minor_sums(&m), [6, 11, 6]);
/// ```
pub fn principal_minor_sums<R: Ring, const N: usize>(m: &[[R; N]; N]) -> [R; N] {
    let e = expand(m, Need::Principal, false);
    std::array::from_fn(|k| {
        let mut acc = R::zero();
        match k {
            0 => (0..N).for_each(|i| acc.add_assign(&m[i][i])),
            1 => (0..6)
                .filter(|&p| PAIRS[p][1] < N)
                .for_each(|p| acc.add_assign(&e.m2[p][p])),
            2 => (0..4)
                .filter(|&t| TRIPLES[t][2] < N)
                .for_each(|t| acc.add_assign(&e.m3[t][t])),
            _ => acc = e.det.clone(),
        }
        acc
    })
}

/// Every minor of an `N × N` matrix (`N ≤ 4`), computed once by expansion (for a symmetric
/// matrix, once per unordered pair of row and column sets).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SmallMinors<R> {
    pub(super) n: usize,
    /// Only slots with row set ≤ column set are stored.
    pub(super) symmetric: bool,
    /// The entries, row by row.
    pub(super) m1: Vec<R>,
    pub(super) m2: [[R; 6]; 6],
    pub(super) m3: [[R; 4]; 4],
    pub(super) det: R,
}

impl<R: Ring> SmallMinors<R> {
    /// Every minor of `m`.
    pub fn all<const N: usize>(m: &[[R; N]; N]) -> SmallMinors<R> {
        let symmetric = (0..N).all(|i| (i + 1..N).all(|j| m[i][j] == m[j][i]));
        SmallMinors::all_with(m, symmetric)
    }

    /// Every minor of `m`, stored for a symmetric matrix if `symmetric` (which `m` must then be).
    pub(super) fn all_with<const N: usize>(m: &[[R; N]; N], symmetric: bool) -> SmallMinors<R> {
        let e = expand(m, Need::All, symmetric);
        SmallMinors {
            n: N,
            symmetric,
            m1: m.iter().flatten().cloned().collect(),
            m2: e.m2,
            m3: e.m3,
            det: e.det,
        }
    }

    /// The size `N`.
    pub fn size(&self) -> usize {
        self.n
    }

    /// `[E₁, …, E_N]`, the sums of the principal minors of each order.
    pub fn principal_minor_sums(&self) -> Vec<R> {
        let n = self.n;
        let mut e = vec![R::zero(); n];
        for i in 0..n {
            e[0].add_assign(&self.m1[i * n + i]);
        }
        if n == 4 {
            (0..6).for_each(|p| e[1].add_assign(&self.m2[p][p]));
            (0..4).for_each(|t| e[2].add_assign(&self.m3[t][t]));
        } else if n == 3 {
            [0, 1, 3]
                .iter()
                .for_each(|&p| e[1].add_assign(&self.m2[p][p]));
        }
        if n > 1 {
            e[n - 1] = self.det.clone();
        }
        e
    }

    /// The minor on the given rows and columns (increasing, of the same length `k ≤ N`).
    ///
    /// # Panics
    /// If the sets are not increasing subsets of `0..N` of one length `k ≥ 1`.
    pub fn minor(&self, rows: &[usize], cols: &[usize]) -> &R {
        let valid =
            |s: &[usize]| s.windows(2).all(|w| w[0] < w[1]) && s.iter().all(|&i| i < self.n);
        assert!(
            rows.len() == cols.len() && !rows.is_empty() && valid(rows) && valid(cols),
            "minor on rows {rows:?}, columns {cols:?} of a {0}×{0} matrix",
            self.n
        );
        let index = |s: &[usize]| match s.len() {
            2 => pair_index(s[0], s[1]),
            _ => TRIPLES.iter().position(|t| t == s).unwrap_or(0),
        };
        let (r, c) = (index(rows), index(cols));
        let (r, c) = if self.symmetric && r > c {
            (c, r)
        } else {
            (r, c)
        };
        match rows.len() {
            1 => &self.m1[rows[0] * self.n + cols[0]],
            k if k == self.n => &self.det,
            2 => &self.m2[r][c],
            _ => &self.m3[r][c],
        }
    }

    /// The `k × k` minors: all `C(N,k)²` of them, or for a symmetric matrix one per unordered
    /// pair `{rows, columns}`; empty for `k = 0` or `k > N`.
    pub fn of_order(&self, k: usize) -> Vec<&R> {
        if k == 0 {
            return Vec::new();
        }
        let sets = combinations(self.n, k);
        let mut out = Vec::new();
        for (i, r) in sets.iter().enumerate() {
            let start = if self.symmetric { i } else { 0 };
            for c in &sets[start..] {
                out.push(self.minor(r, c));
            }
        }
        out
    }
}

/// The `k`-subsets of `0..n` in lexicographic order.
pub(crate) fn combinations(n: usize, k: usize) -> Vec<Vec<usize>> {
    if k > n {
        return Vec::new();
    }
    let mut out = Vec::new();
    let mut c: Vec<usize> = (0..k).collect();
    loop {
        out.push(c.clone());
        // the last position that can still move right
        let Some(i) = (0..k).rev().find(|&i| c[i] < n - k + i) else {
            return out;
        };
        c[i] += 1;
        for j in i + 1..k {
            c[j] = c[j - 1] + 1;
        }
    }
}

/// Fraction-free (Bareiss) row echelon form, in place: every entry below the finished rows is
/// a minor of the input (Sylvester's identity), so each division is exact and entries grow only
/// linearly. Returns the pivot columns and whether the row swaps were odd. With
/// `stop_at_gap`, stops at the first column without a pivot (enough for a determinant).
fn echelon_fraction_free<C: Ring>(m: &mut Matrix<C>, stop_at_gap: bool) -> (Vec<usize>, bool) {
    let (rows, cols) = (m.rows, m.cols);
    let mut pivots = Vec::with_capacity(rows.min(cols));
    let mut odd = false;
    let mut previous = C::one();
    for col in 0..cols {
        let top = pivots.len();
        if top == rows {
            break;
        }
        let Some(p) = (top..rows).find(|&r| !m[(r, col)].is_zero()) else {
            if stop_at_gap {
                break;
            }
            continue;
        };
        if p != top {
            for j in col..cols {
                m.data.swap(p * cols + j, top * cols + j);
            }
            odd = !odd;
        }
        let pivot = m[(top, col)].clone();
        for i in top + 1..rows {
            let f = std::mem::replace(&mut m[(i, col)], C::zero());
            for j in col + 1..cols {
                let mut v = m[(i, j)].mul(&pivot);
                v.sub_mul_assign(&f, &m[(top, j)]);
                m[(i, j)] = v
                    .div_exact(&previous)
                    .expect("Bareiss elimination divides exactly");
            }
        }
        previous = pivot;
        pivots.push(col);
    }
    (pivots, odd)
}

/// The determinant of a square matrix given by rows, by Bareiss' fraction-free elimination
/// (`O(n³)` ring operations, exact divisions only); `1` for the empty matrix.
///
/// # Panics
/// If the rows do not form a square matrix.
pub fn det_bareiss<C: Ring>(rows: Vec<Vec<C>>) -> C {
    Matrix::from_rows(rows).expect("rows of equal length").det()
}

impl<C: Ring> Matrix<C> {
    /// The determinant, by Bareiss' fraction-free elimination (`O(n³)` ring operations);
    /// `1` for the `0 × 0` matrix.
    ///
    /// ```
    /// # use qsic_algebra::{linalg::Matrix, IBig};
    /// let m = Matrix::from_array([[0, 2, 1], [3, 0, 0], [1, 1, 1]].map(|r| r.map(IBig::from)));
    /// assert_eq!(m.det(), IBig::from(-3));
    /// ```
    ///
    /// # Panics
    /// If the matrix is not square.
    pub fn det(&self) -> C {
        assert_eq!(self.rows, self.cols, "determinant of a non-square matrix");
        let n = self.rows;
        let mut m = self.clone();
        let (pivots, odd) = echelon_fraction_free(&mut m, true);
        if pivots.len() < n {
            return C::zero();
        }
        if n == 0 {
            return C::one();
        }
        let d = m[(n - 1, n - 1)].clone();
        if odd {
            d.neg()
        } else {
            d
        }
    }

    /// The pivot columns of a fraction-free row echelon form: their number is the rank over
    /// the fraction field, and they index a set of linearly independent columns.
    pub fn pivot_columns(&self) -> Vec<usize> {
        echelon_fraction_free(&mut self.clone(), false).0
    }

    /// Every `k × k` minor, row sets outer and column sets inner, both in lexicographic order
    /// (empty for `k = 0` or `k` above a dimension).
    pub fn minors(&self, k: usize) -> Vec<C> {
        let (rs, cs) = (combinations(self.rows, k), combinations(self.cols, k));
        if k == 0 {
            return Vec::new();
        }
        rs.iter()
            .flat_map(|r| cs.iter().map(move |c| self.submatrix(r, c).det()))
            .collect()
    }

    /// `[E₁, …, E_n]`, the sums of the principal minors of each order of a square matrix.
    ///
    /// # Panics
    /// If the matrix is not square.
    pub fn principal_minor_sums(&self) -> Vec<C> {
        assert_eq!(
            self.rows, self.cols,
            "principal minors of a non-square matrix"
        );
        (1..=self.rows)
            .map(|k| {
                combinations(self.rows, k)
                    .iter()
                    .fold(C::zero(), |acc, s| acc.add(&self.submatrix(s, s).det()))
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{IBig, Poly};
    use proptest::prelude::*;

    /// Leibniz' formula: the sum over permutations, an independent route.
    fn leibniz(m: &[Vec<i128>]) -> i128 {
        let n = m.len();
        let mut perm: Vec<usize> = (0..n).collect();
        let mut total = 0;
        // Heap's algorithm, iterative, tracking the sign
        let mut c = vec![0usize; n];
        let mut sign = 1;
        let term = |p: &[usize]| (0..n).map(|i| m[i][p[i]]).product::<i128>();
        total += sign * term(&perm);
        let mut i = 0;
        while i < n {
            if c[i] < i {
                if i % 2 == 0 {
                    perm.swap(0, i);
                } else {
                    perm.swap(c[i], i);
                }
                sign = -sign;
                total += sign * term(&perm);
                c[i] += 1;
                i = 0;
            } else {
                c[i] = 0;
                i += 1;
            }
        }
        total
    }

    fn to_array<const N: usize>(m: &[Vec<i128>]) -> [[i128; N]; N] {
        std::array::from_fn(|i| std::array::from_fn(|j| m[i][j]))
    }

    fn matrix(m: &[Vec<i128>]) -> Matrix<IBig> {
        Matrix::from_fn(m.len(), m[0].len(), |i, j| IBig::from(m[i][j]))
    }

    /// Every route to the minors agrees on a matrix: expansion in `i128` and in `IBig`,
    /// Bareiss, and Leibniz for the determinant.
    fn check_square<const N: usize>(m: &[Vec<i128>]) {
        let a: [[i128; N]; N] = to_array(m);
        let big = matrix(m);
        let d = leibniz(m);
        assert_eq!(det(&a), d, "{m:?}");
        assert_eq!(big.det(), IBig::from(d), "{m:?}");
        assert_eq!(det(&a.map(|r| r.map(IBig::from))), IBig::from(d));
        let e = principal_minor_sums(&a);
        let e_big: Vec<IBig> = big.principal_minor_sums();
        assert_eq!(e.map(IBig::from).to_vec(), e_big, "{m:?}");
        let all = SmallMinors::all(&a);
        for k in 1..=N {
            for r in combinations(N, k) {
                for c in combinations(N, k) {
                    let sub: Vec<Vec<i128>> = r
                        .iter()
                        .map(|&i| c.iter().map(|&j| m[i][j]).collect())
                        .collect();
                    assert_eq!(*all.minor(&r, &c), leibniz(&sub), "{m:?} {r:?} {c:?}");
                }
            }
            let listed = all.of_order(k).len();
            let sets = combinations(N, k).len();
            let symmetric = (0..N).all(|i| (0..N).all(|j| m[i][j] == m[j][i]));
            let expect = if symmetric {
                sets * (sets + 1) / 2
            } else {
                sets * sets
            };
            assert_eq!(listed, expect);
        }
        assert_eq!(big.minors(N), vec![IBig::from(d)]);
    }

    fn square(n: usize, bound: i128) -> impl Strategy<Value = Vec<Vec<i128>>> {
        prop::collection::vec(prop::collection::vec(-bound..=bound, n), n)
    }

    fn symmetrize(mut m: Vec<Vec<i128>>) -> Vec<Vec<i128>> {
        for i in 0..m.len() {
            for j in 0..i {
                m[i][j] = m[j][i];
            }
        }
        m
    }

    proptest! {
        #[test]
        fn expansion_bareiss_and_leibniz_agree(
            m1 in square(1, 9), m2 in square(2, 9), m3 in square(3, 9), m4 in square(4, 9),
            s4 in square(4, 3).prop_map(symmetrize),
        ) {
            check_square::<1>(&m1);
            check_square::<2>(&m2);
            check_square::<3>(&m3);
            check_square::<4>(&m4);
            check_square::<4>(&s4);
        }

        /// The fast path's range: entries below 2²⁴ (members `λA − B` at λ ≤ 2: below 3·2²⁴),
        /// where `i128` must equal `IBig` (debug builds would also panic on an overflow).
        #[test]
        fn machine_determinant_equals_big_determinant(
            m in prop::collection::vec(-(3i128 << 24) + 1..(3i128 << 24), 16)
        ) {
            let a: [[i128; 4]; 4] = std::array::from_fn(|i| std::array::from_fn(|j| m[4 * i + j]));
            let big = a.map(|r| r.map(IBig::from));
            prop_assert_eq!(IBig::from(det(&a)), det(&big));
            prop_assert_eq!(principal_minor_sums(&a).map(IBig::from), principal_minor_sums(&big));
            prop_assert_eq!(IBig::from(det(&a)), Matrix::from_array(big).det());
        }

        /// Rank from pivots equals the size of the largest nonzero minor.
        #[test]
        fn pivots_count_the_largest_nonzero_minor(
            rows in 1usize..5, cols in 1usize..5, v in prop::collection::vec(-2i128..3, 16),
            zero_rows in 0usize..3,
        ) {
            let m = Matrix::from_fn(rows, cols, |i, j| {
                if i < zero_rows { IBig::ZERO } else { IBig::from(v[4 * i + j]) }
            });
            let rank = m.pivot_columns().len();
            let largest = (1..=rows.min(cols)).rev()
                .find(|&k| m.minors(k).iter().any(|x| !x.is_zero()))
                .unwrap_or(0);
            prop_assert_eq!(rank, largest);
        }
    }

    /// Row and column sets that are not increasing subsets of `0..N` of one length are refused.
    #[test]
    fn invalid_minor_sets_panic() {
        let all = SmallMinors::all(&[[1i128, 2, 0, 0], [3, 4, 0, 0], [0, 0, 5, 6], [0, 0, 7, 8]]);
        let bad: [(&[usize], &[usize]); 6] = [
            (&[1, 0], &[0, 1]),
            (&[1, 1], &[0, 1]),
            (&[0, 4], &[0, 1]),
            (&[0, 1], &[0, 1, 2]),
            (&[], &[]),
            (&[0, 1, 2], &[0, 1, 1]),
        ];
        for (rows, cols) in bad {
            let caught = std::panic::catch_unwind(|| *all.minor(rows, cols));
            assert!(caught.is_err(), "{rows:?} {cols:?}");
        }
        assert_eq!(*all.minor(&[0, 1], &[0, 1]), -2);
    }

    /// Known values: the empty and 1×1 determinants, a permutation matrix, a singular matrix.
    #[test]
    fn determinants_with_known_values() {
        assert_eq!(det_bareiss::<IBig>(vec![]), IBig::ONE);
        assert_eq!(det_bareiss(vec![vec![IBig::from(5)]]), IBig::from(5));
        let perm = [[0i128, 0, 1], [0, 2, 0], [3, 0, 0]];
        assert_eq!(det(&perm), -6);
        assert_eq!(matrix(&perm.map(|r| r.to_vec())).det(), IBig::from(-6));
        let singular = [[1i128, 2, 3], [2, 4, 6], [1, 0, 1]];
        assert_eq!(det(&singular), 0);
        assert_eq!(
            matrix(&singular.map(|r| r.to_vec())).pivot_columns(),
            vec![0, 1]
        );
        assert_eq!(combinations(4, 2).len(), 6);
        assert!(combinations(2, 3).is_empty());
        assert_eq!(combinations(3, 0), vec![Vec::<usize>::new()]);
    }

    /// Over ℤ[λ]: the minors of `λI − M` are polynomials; at λ = 0 they are those of `−M`.
    #[test]
    fn polynomial_entries() {
        let m = [[2i64, 1, 0, 0], [1, 3, 1, 0], [0, 1, 4, 1], [0, 0, 1, 5]];
        let pencil: [[Poly; 4]; 4] = std::array::from_fn(|i| {
            std::array::from_fn(|j| Poly::from_i64s(&[-m[i][j], i64::from(i == j)]))
        });
        let e = principal_minor_sums(&pencil);
        let at_zero = principal_minor_sums(&m.map(|r| r.map(|v| IBig::from(-v))));
        for k in 0..4 {
            assert_eq!(e[k].eval(&IBig::ZERO), at_zero[k]);
            assert_eq!(e[k].degree(), Some(k + 1));
        }
        // det(λI − M) is the characteristic polynomial: Σ (−1)^k E_k(M) λ^(4−k)
        let em = principal_minor_sums(&m.map(|r| r.map(IBig::from)));
        let expect = Poly::new(vec![
            em[3].clone(),
            -em[2].clone(),
            em[1].clone(),
            -em[0].clone(),
            IBig::ONE,
        ]);
        assert_eq!(det(&pencil), expect);
    }
}
