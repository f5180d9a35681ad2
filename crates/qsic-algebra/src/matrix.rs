//! Small symmetric integer matrices: exact inertia, and the pencil `λA − μB` of two of them.

use crate::poly::Poly;
use crate::sign::Sign;
use dashu_int::IBig;
use dashu_ratio::RBig;

/// The inertia of a real symmetric matrix: numbers of positive, negative and zero eigenvalues.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Inertia {
    /// Positive eigenvalues.
    pub positive: u8,
    /// Negative eigenvalues.
    pub negative: u8,
    /// Zero eigenvalues (4 − rank).
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

    /// The inertia of a 4×4 symmetric matrix from the signs of the sums `E₁…E₄` of its
    /// principal minors of each order (the characteristic polynomial is
    /// `x⁴ − E₁x³ + E₂x² − E₃x + E₄`; it is real-rooted, so Descartes' rule counts its
    /// positive and negative roots exactly).
    pub fn from_minor_sum_signs(e: [Sign; 4]) -> Inertia {
        let var = |s: [Sign; 5]| crate::sign::count_variations(s) as u8;
        let pos = var([Sign::Positive, -e[0], e[1], -e[2], e[3]]);
        let neg = var([Sign::Positive, e[0], e[1], e[2], e[3]]);
        Inertia {
            positive: pos,
            negative: neg,
            zero: 4 - pos - neg,
        }
    }
}

/// A symmetric 4×4 integer matrix.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct SymMatrix4 {
    m: [[IBig; 4]; 4],
}

const PAIRS: [(usize, usize); 6] = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)];
const TRIPLES: [[usize; 3]; 4] = [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]];

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
        let m = &self.m;
        let e1 = &m[0][0] + &m[1][1] + &m[2][2] + &m[3][3];
        let mut e2 = IBig::ZERO;
        for &(i, j) in &PAIRS {
            e2 += &m[i][i] * &m[j][j] - &m[i][j] * &m[i][j];
        }
        let mut e3 = IBig::ZERO;
        for t in &TRIPLES {
            e3 += det3(m, t, t);
        }
        [e1, e2, e3, self.det()]
    }

    /// The determinant.
    pub fn det(&self) -> IBig {
        let m = &self.m;
        let mut d = IBig::ZERO;
        for (c, &cols) in [[1, 2, 3], [0, 2, 3], [0, 1, 3], [0, 1, 2]]
            .iter()
            .enumerate()
        {
            if m[0][c].is_zero() {
                continue;
            }
            let minor = det3(m, &[1, 2, 3], &cols);
            if c % 2 == 0 {
                d += &m[0][c] * minor;
            } else {
                d -= &m[0][c] * minor;
            }
        }
        d
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

    /// Exact inertia by symmetric Gaussian elimination over ℚ (LDLᵀ with 1×1 and 2×2
    /// pivots, Sylvester's law of inertia): the second, independent route.
    pub fn inertia_ldl(&self) -> Inertia {
        let mut s: Vec<Vec<RBig>> = self
            .m
            .iter()
            .map(|r| r.iter().map(|v| RBig::from(v.clone())).collect())
            .collect();
        let (mut pos, mut neg) = (0u8, 0u8);
        while !s.is_empty() {
            let n = s.len();
            if let Some(i) = (0..n).find(|&i| !s[i][i].is_zero()) {
                let p = s[i][i].clone();
                if p > RBig::ZERO {
                    pos += 1;
                } else {
                    neg += 1;
                }
                let keep: Vec<usize> = (0..n).filter(|&k| k != i).collect();
                s = keep
                    .iter()
                    .map(|&r| {
                        keep.iter()
                            .map(|&c| &s[r][c] - &s[r][i] * &s[i][c] / &p)
                            .collect()
                    })
                    .collect();
            } else if let Some((i, j)) = (0..n)
                .flat_map(|i| (i + 1..n).map(move |j| (i, j)))
                .find(|&(i, j)| !s[i][j].is_zero())
            {
                // 2×2 pivot [[0, b], [b, 0]]: one positive, one negative eigenvalue.
                pos += 1;
                neg += 1;
                let b = s[i][j].clone();
                let keep: Vec<usize> = (0..n).filter(|&k| k != i && k != j).collect();
                // inverse of [[0,b],[b,0]] is [[0,1/b],[1/b,0]]
                s = keep
                    .iter()
                    .map(|&r| {
                        keep.iter()
                            .map(|&c| &s[r][c] - (&s[r][i] * &s[j][c] + &s[r][j] * &s[i][c]) / &b)
                            .collect()
                    })
                    .collect();
            } else {
                break;
            }
        }
        Inertia {
            positive: pos,
            negative: neg,
            zero: 4 - pos - neg,
        }
    }

    /// The rank.
    pub fn rank(&self) -> u8 {
        self.inertia().rank()
    }
}

fn det3(m: &[[IBig; 4]; 4], r: &[usize; 3], c: &[usize; 3]) -> IBig {
    let a = |i: usize, j: usize| &m[r[i]][c[j]];
    a(0, 0) * (a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1))
        - a(0, 1) * (a(1, 0) * a(2, 2) - a(1, 2) * a(2, 0))
        + a(0, 2) * (a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0))
}

/// The pencil `λA − μB` of two symmetric 4×4 integer matrices, studied through
/// polynomials in `λ` on the chart `μ = 1`; each is a binary form of a known degree `k`
/// in `(λ, μ)`, so a degree drop below `k` is a root at `λ = ∞` of that multiplicity.
///
/// All minors of `λA − B` are computed once, at construction: the 2×2 minors from the
/// entries, the 3×3 minors by expansion along a row into 2×2 minors, the determinant from
/// the 3×3 minors.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MatrixPencil {
    a: SymMatrix4,
    b: SymMatrix4,
    /// Entries `a_ij·λ − b_ij`, row by row.
    entries: Vec<Poly>,
    /// 2×2 minors, `[row pair][column pair]`, pairs indexed as in `PAIRS`.
    m2: Vec<Poly>,
    /// 3×3 minors, `[row triple][column triple]`, triples indexed as in `TRIPLES`.
    m3: Vec<Poly>,
    det: Poly,
}

fn pair_index(i: usize, j: usize) -> usize {
    PAIRS
        .iter()
        .position(|&p| p == (i.min(j), i.max(j)))
        .expect("a valid pair")
}

impl MatrixPencil {
    /// The pencil `λA − μB`.
    pub fn new(a: SymMatrix4, b: SymMatrix4) -> MatrixPencil {
        let e = |i: usize, j: usize| Poly::new(vec![-b.m[i][j].clone(), a.m[i][j].clone()]);
        let entries: Vec<Poly> = (0..16).map(|k| e(k / 4, k % 4)).collect();
        let ent = |i: usize, j: usize| &entries[4 * i + j];
        let mut m2 = vec![Poly::zero(); 36];
        for (ri, &(r0, r1)) in PAIRS.iter().enumerate() {
            for (ci, &(c0, c1)) in PAIRS.iter().enumerate().skip(ri) {
                let v = &(ent(r0, c0) * ent(r1, c1)) - &(ent(r0, c1) * ent(r1, c0));
                m2[6 * ci + ri] = v.clone();
                m2[6 * ri + ci] = v;
            }
        }
        let mut m3 = vec![Poly::zero(); 16];
        for (ri, r) in TRIPLES.iter().enumerate() {
            for (ci, c) in TRIPLES.iter().enumerate().skip(ri) {
                let mut acc = Poly::zero();
                for j in 0..3 {
                    let x = ent(r[0], c[j]);
                    if x.is_zero() {
                        continue;
                    }
                    let rest: Vec<usize> = (0..3).filter(|&k| k != j).map(|k| c[k]).collect();
                    let sub = &m2[6 * pair_index(r[1], r[2]) + pair_index(rest[0], rest[1])];
                    let t = x * sub;
                    acc = if j % 2 == 0 { &acc + &t } else { &acc - &t };
                }
                m3[4 * ci + ri] = acc.clone();
                m3[4 * ri + ci] = acc;
            }
        }
        // expand along row 0: columns j, minor of rows {1,2,3} (triple 3) and the other columns
        let mut det = Poly::zero();
        for j in 0..4 {
            let x = ent(0, j);
            if x.is_zero() {
                continue;
            }
            let t = x * &m3[4 * 3 + (3 - j)];
            det = if j % 2 == 0 { &det + &t } else { &det - &t };
        }
        MatrixPencil {
            a,
            b,
            entries,
            m2,
            m3,
            det,
        }
    }

    /// `A`.
    pub fn a(&self) -> &SymMatrix4 {
        &self.a
    }

    /// `B`.
    pub fn b(&self) -> &SymMatrix4 {
        &self.b
    }

    /// The member `λA − μB` at integers `(λ, μ)`.
    pub fn member(&self, lambda: &IBig, mu: &IBig) -> SymMatrix4 {
        self.a.combine(lambda, &self.b, mu)
    }

    /// `f(λ) = det(λA − B)`, the characteristic polynomial (a binary quartic form).
    pub fn det_poly(&self) -> Poly {
        self.det.clone()
    }

    /// Every nonzero `k×k` minor of `λA − B` (`1 ≤ k ≤ 4`), each once up to the symmetry
    /// `minor(R, C) = minor(C, R)`.
    pub fn minors(&self, k: usize) -> Vec<Poly> {
        let upper = |v: &[Poly], n: usize| -> Vec<Poly> {
            (0..n)
                .flat_map(|r| (r..n).map(move |c| (r, c)))
                .map(|(r, c)| v[n * r + c].clone())
                .filter(|p| !p.is_zero())
                .collect()
        };
        match k {
            1 => (0..4)
                .flat_map(|i| (i..4).map(move |j| (i, j)))
                .map(|(i, j)| self.entries[4 * i + j].clone())
                .filter(|p| !p.is_zero())
                .collect(),
            2 => upper(&self.m2, 6),
            3 => upper(&self.m3, 4),
            4 if !self.det.is_zero() => vec![self.det.clone()],
            _ => Vec::new(),
        }
    }

    /// `[E₁(λ), …, E₄(λ)]`: the sums of principal minors of `λA − B` of each order.
    /// The inertia of the member at `λ` follows from their signs
    /// ([`Inertia::from_minor_sum_signs`]).
    pub fn principal_minor_sums(&self) -> [Poly; 4] {
        let e1 = (0..4).fold(Poly::zero(), |acc, i| &acc + &self.entries[5 * i]);
        let e2 = (0..6).fold(Poly::zero(), |acc, p| &acc + &self.m2[7 * p]);
        let e3 = (0..4).fold(Poly::zero(), |acc, t| &acc + &self.m3[5 * t]);
        [e1, e2, e3, self.det.clone()]
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

    proptest! {
        #[test]
        fn descartes_and_ldl_inertia_agree(m in sym()) {
            prop_assert_eq!(m.inertia(), m.inertia_ldl());
        }

        #[test]
        fn pencil_polys_match_members(a in sym(), b in sym(), l in -5i64..6) {
            let p = MatrixPencil::new(a.clone(), b.clone());
            let lam = IBig::from(l);
            let member = p.member(&lam, &IBig::ONE);
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

    /// Zero diagonals force the LDLᵀ route through 2×2 pivots: it must still agree with the
    /// principal-minor route on every such matrix with off-diagonal entries in {−1, 0, 1, 2}
    /// (and a diagonal that is zero or `(0, 0, 1, −2)`).
    #[test]
    fn ldl_with_two_by_two_pivots_agrees() {
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
                assert_eq!(s.inertia_ldl(), s.inertia(), "{m:?}");
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
