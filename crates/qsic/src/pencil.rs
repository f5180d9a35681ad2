//! The pencil `λA − μB` of two quadrics: its characteristic form `f(λ, μ) = det(λA − μB)`,
//! the real roots with multiplicities and Jordan (Segre) structure, and the inertia of
//! the members at each root and between roots.
//!
//! Notation: points of the pencil are `(λ : μ)`; the chart `μ = 1` is used for finite
//! roots, and `(1 : 0)` is the root "at infinity" (`A` singular). The Jordan blocks of a
//! root `α` come from the invariant factors of `λA − μB`: with `D_k` the gcd of the `k×k`
//! minors, the elementary divisors at `α` have exponents `ord_α(D_k) − ord_α(D_{k−1})`.
//! This is exact rational arithmetic and needs no arithmetic in `ℚ(α)`.
//!
//! The sample of each arc is a small rational chosen from its roots alone ([`arc_samples`]:
//! the leftmost of least dyadic denominator between two roots, `⌊α₁⌋ − 1` and `⌈αₖ⌉ + 1`
//! outside them), not from how they were isolated, so the fast path (four simple roots: the
//! certified float isolation [`AlgebraicReal::certified_real_roots_of`], which proves `f`
//! square-free, and signs of `E₁…E₄` at the samples in `i128`) and the exact path give the
//! same analysis, and the parameterization member chosen from a sample stays the same.

use crate::quadric::Quadric;
use dashu_int::ops::BitTest;
use qsic_algebra::budget::{poly_step_units, product_units, Budget, Exhausted};
use qsic_algebra::matrix::{Inertia, MatrixPencil, SymMatrix4};
use qsic_algebra::poly::binary::BinaryForm;
use qsic_algebra::roots::{
    between_roots, floor_of_root, quartic_roots_f64, simplest_between, Bound, RootInterval,
};
use qsic_algebra::{AlgebraicReal, IBig, Poly, RBig, Sign};
use std::cmp::Ordering;

/// A point `(λ : μ)` of the pencil: `(α : 1)` is the member `αA − B`, `(1 : 0)` the member `A`.
pub use qsic_algebra::poly::binary::ProjectivePoint as PencilPoint;

/// A distinct real root of `f(λ, μ)`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PencilRoot {
    /// Where.
    pub point: PencilPoint,
    /// Multiplicity as a root of `f`.
    pub multiplicity: u8,
    /// Sizes of the Jordan blocks (Segre symbol of this root), largest first; they add up to
    /// the multiplicity, and their number is `4 − rank` of the member.
    pub blocks: Vec<u8>,
    /// Inertia of the singular member at the root.
    pub inertia: Inertia,
}

/// The complete exact analysis of a regular pencil.
#[derive(Clone, Debug)]
pub struct PencilAnalysis {
    /// `f(λ, 1) = det(λA − B)`; its degree is `4 −` the multiplicity of the root at ∞.
    pub characteristic: Poly,
    /// The distinct real roots, finite ones in increasing order, then ∞ if it is a root.
    pub real_roots: Vec<PencilRoot>,
    /// Block structures of the non-real roots, one entry per root (conjugates appear twice).
    pub complex_roots: Vec<Vec<u8>>,
    /// Inertia of `λA − B` at a sample point of each arc between consecutive real roots,
    /// in the order of `real_roots` on the chart μ = 1: `arcs[0]` is left of the first
    /// finite root, `arcs[i]` right of finite root `i − 1`. With no finite real root, one arc.
    pub arcs: Vec<(RBig, Inertia)>,
}

/// Rounds up the data of a pencil needed by several analyses.
pub(crate) struct PencilData {
    pub a: SymMatrix4,
    pub b: SymMatrix4,
    /// Every minor of `λA − B`, made on first use (only non-simple roots need them).
    pencil: std::sync::OnceLock<MatrixPencil>,
    /// `E₁(λ), …, E₄(λ)` of `λA − B` ([`principal_minor_sums_of_pencil`]).
    pub e: [Poly; 4],
    /// `f(λ) = det(λA − B) = E₄`.
    pub f: Poly,
}

impl PencilData {
    /// The work units of [`PencilData::new`] on `qa`, `qb` ([`crate::Budget`]): the sums of
    /// principal minors of `λA − B` are about 2 000 products of numbers up to four times
    /// the longest entry of either matrix.
    pub fn units(qa: &Quadric, qb: &Quadric) -> u64 {
        let bits = |q: &Quadric| {
            q.integer_matrix()
                .entries()
                .iter()
                .flatten()
                .map(|e| e.bit_len())
                .max()
                .unwrap_or(0)
        };
        let l = 4 * bits(qa).max(bits(qb));
        2_000u64.saturating_mul(product_units(l, l))
    }

    pub fn new(qa: &Quadric, qb: &Quadric) -> PencilData {
        let a = qa.integer_matrix().clone();
        let b = qb.integer_matrix().clone();
        let e = principal_minor_sums_of_pencil(a.entries(), b.entries());
        let f = e[3].clone();
        PencilData {
            a,
            b,
            pencil: std::sync::OnceLock::new(),
            e,
            f,
        }
    }

    /// The pencil with all its minors.
    pub fn pencil(&self) -> &MatrixPencil {
        self.pencil
            .get_or_init(|| MatrixPencil::new(self.a.clone(), self.b.clone()))
    }
}

/// `[E₁(λ), …, E₄(λ)]`, the sums of the principal minors of each order of `λA − B`: in
/// `i128` straight from the entries when every entry is below `2²²` ([`minor_sums_i128`]),
/// else over `IBig` from their values at `λ = ∞, 0, 1, −1, 2` by the shared interpolation
/// (`linalg::pencil::principal_minor_sums_of_members`). Either way not every minor of the
/// pencil.
pub(crate) fn principal_minor_sums_of_pencil(a: &[[IBig; 4]; 4], b: &[[IBig; 4]; 4]) -> [Poly; 4] {
    let small = |m: &[[IBig; 4]; 4]| -> Option<[[i64; 4]; 4]> {
        let mut out = [[0i64; 4]; 4];
        for i in 0..4 {
            for j in 0..4 {
                out[i][j] = i64::try_from(&m[i][j]).ok()?;
            }
        }
        Some(out)
    };
    if let Some(e) = small(a)
        .zip(small(b))
        .and_then(|(ai, bi)| minor_sums_i128(&ai, &bi))
    {
        return e.map(|c| Poly::new(c.iter().map(|&v| IBig::from(v)).collect()));
    }
    let member = |l: i64, k: i64| -> [[IBig; 4]; 4] {
        let (l, k) = (IBig::from(l), IBig::from(k));
        std::array::from_fn(|i| std::array::from_fn(|j| &l * &a[i][j] - &k * &b[i][j]))
    };
    qsic_algebra::linalg::pencil::principal_minor_sums_of_members([
        &member(1, 0),
        &member(0, 1),
        &member(1, 1),
        &member(-1, 1),
        &member(2, 1),
    ])
    .map(|c| Poly::new(c.to_vec()))
}

/// `E₁(λ), …, E₄(λ)` of `λA − B` in `i128` (coefficients from degree 0), `None` unless every
/// entry is below `2²²` in absolute value. Straight from the entries `λaᵢⱼ − bᵢⱼ`: the 2×2
/// minors of rows `{0, 1}` and `{2, 3}` and the four other principal ones as quadratics in
/// `λ` (coefficients below `2⁴⁶`, in `i64`), the principal 3×3 minors by expanding along
/// their one row outside such a pair (below `3·2⁶⁹`), the determinant by Laplace's expansion
/// along rows `{0, 1}` (six products of two quadratics, below `2⁹⁸`): no overflow, no
/// interpolation.
pub(crate) fn minor_sums_i128(a: &[[i64; 4]; 4], b: &[[i64; 4]; 4]) -> Option<[[i128; 5]; 4]> {
    if a.iter()
        .chain(b)
        .flatten()
        .any(|v| v.unsigned_abs() >= 1 << 22)
    {
        return None;
    }
    // the entry (i, j) as [constant, λ]
    let m = |i: usize, j: usize| [-b[i][j], a[i][j]];
    let minor2 = |r: [usize; 2], c: [usize; 2]| -> [i64; 3] {
        let (p, q, s, t) = (m(r[0], c[0]), m(r[1], c[1]), m(r[0], c[1]), m(r[1], c[0]));
        [
            p[0] * q[0] - s[0] * t[0],
            p[0] * q[1] + p[1] * q[0] - s[0] * t[1] - s[1] * t[0],
            p[1] * q[1] - s[1] * t[1],
        ]
    };
    // column pairs in the order (0,1) (0,2) (0,3) (1,2) (1,3) (2,3): pair 5 − p is the
    // complement of pair p
    const PAIRS: [[usize; 2]; 6] = [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]];
    let top: [[i64; 3]; 6] = PAIRS.map(|c| minor2([0, 1], c));
    let bottom: [[i64; 3]; 6] = PAIRS.map(|c| minor2([2, 3], c));
    let mut e = [[0i128; 5]; 4];
    for i in 0..4 {
        e[0][0] -= i128::from(b[i][i]);
        e[0][1] += i128::from(a[i][i]);
    }
    // e[k] ± x·y (products of two i64: one widening multiplication each)
    let mut add = |k: usize, plus: bool, x: &[i64], y: &[i64]| {
        for (i, &xi) in x.iter().enumerate() {
            for (j, &yj) in y.iter().enumerate() {
                let p = i128::from(xi) * i128::from(yj);
                if plus {
                    e[k][i + j] += p;
                } else {
                    e[k][i + j] -= p;
                }
            }
        }
    };
    let e2 = [
        top[0],
        bottom[5],
        minor2([0, 2], [0, 2]),
        minor2([0, 3], [0, 3]),
        minor2([1, 2], [1, 2]),
        minor2([1, 3], [1, 3]),
    ];
    // the principal 3×3 minors: rows/columns {0,1,2} and {0,1,3} along their last row,
    // {0,2,3} and {1,2,3} along their first
    for (row, pairs) in [(2, [3, 1, 0]), (3, [4, 2, 0])] {
        let cols = [PAIRS[pairs[2]][0], PAIRS[pairs[2]][1], row];
        for t in 0..3 {
            add(2, t != 1, &m(row, cols[t]), &top[pairs[t]]);
        }
    }
    for (row, pairs) in [(0, [5, 2, 1]), (1, [5, 4, 3])] {
        let cols = [row, PAIRS[pairs[0]][0], PAIRS[pairs[0]][1]];
        for t in 0..3 {
            add(2, t != 1, &m(row, cols[t]), &bottom[pairs[t]]);
        }
    }
    // Laplace along rows {0, 1}: the sign of columns {c₀, c₁} is (−1)^(1 + c₀ + c₁)
    for (p, c) in PAIRS.iter().enumerate() {
        add(3, (c[0] + c[1]) % 2 == 1, &top[p], &bottom[5 - p]);
    }
    for q in &e2 {
        for (i, &v) in q.iter().enumerate() {
            e[1][i] += i128::from(v);
        }
    }
    Some(e)
}

/// `D_k`, the gcd of the `k×k` minors of `λA − μB` as binary forms of degree `k`, for
/// `k = 1, 2, 3` (index `k − 1`).
struct MinorGcds {
    d: [BinaryForm; 3],
}

impl MinorGcds {
    fn new(pencil: &MatrixPencil) -> MinorGcds {
        let mut d: [BinaryForm; 3] =
            std::array::from_fn(|_| BinaryForm::new(Poly::constant(IBig::ONE), 0));
        // D_{k−1} divides D_k: once D_k is 1 (no root of rank ≤ k − 1), the rest are 1 too.
        for k in (1..=3).rev() {
            let mut g = BinaryForm::new(Poly::zero(), k);
            for m in &pencil.minors(k) {
                g = g.gcd(&BinaryForm::new(m.clone(), k));
                if g.degree() == 0 {
                    break;
                }
            }
            let trivial = g.degree() == 0;
            d[k - 1] = g;
            if trivial {
                break;
            }
        }
        MinorGcds { d }
    }

    fn at_infinity(&self) -> [usize; 3] {
        self.d.each_ref().map(BinaryForm::multiplicity_at_infinity)
    }
}

/// Jordan block sizes from the orders of a root in `D₁, D₂, D₃` and in `f = D₄`.
fn blocks_from_orders(m: usize, ords: [usize; 3]) -> Vec<u8> {
    let d = [ords[0], ords[1], ords[2], m];
    let mut e: Vec<u8> = Vec::with_capacity(4);
    let mut prev = 0;
    for v in d {
        let x = v.saturating_sub(prev);
        if x > 0 {
            e.push(x as u8);
        }
        prev = v;
    }
    e.sort_unstable_by(|a, b| b.cmp(a));
    e
}

/// Splits the square-free `p` into the parts whose roots have order `j` in `d`.
fn split_by_order(p: &Poly, d: &Poly) -> Vec<(Poly, usize)> {
    let mut out = Vec::new();
    let mut rest = p.clone();
    if !d.is_zero() {
        for (dj, j) in d.squarefree_decomposition() {
            let h = rest.gcd(&dj);
            if h.degree().unwrap_or(0) > 0 {
                rest = rest.div_exact(&h).expect("h divides rest");
                out.push((h, j));
            }
        }
    }
    if rest.degree().unwrap_or(0) > 0 {
        out.push((rest, 0));
    }
    out
}

/// Signs of `E₁…E₄` of `λA − B` at a real algebraic `λ`.
fn inertia_at(e: &[Poly; 4], x: &AlgebraicReal) -> Inertia {
    Inertia::from_minor_sum_signs([
        x.sign_of(&e[0]),
        x.sign_of(&e[1]),
        x.sign_of(&e[2]),
        x.sign_of(&e[3]),
    ])
}

/// `E₁…E₄` of `λA − B` with their coefficients in `i128` when they fit: the signs at the
/// samples (small rationals) by Horner's rule on the homogenised form in checked `i128`
/// arithmetic, the big-integer evaluation when a step overflows.
struct MinorSumSigns<'a> {
    e: &'a [Poly; 4],
    small: Option<[[i128; 5]; 4]>,
}

impl<'a> MinorSumSigns<'a> {
    fn new(e: &'a [Poly; 4]) -> MinorSumSigns<'a> {
        let small = (|| {
            let mut c = [[0i128; 5]; 4];
            for (row, p) in c.iter_mut().zip(e) {
                for (slot, v) in row.iter_mut().zip(p.coeffs()) {
                    *slot = i128::try_from(v).ok()?;
                }
            }
            Some(c)
        })();
        MinorSumSigns { e, small }
    }

    /// The sign of `E_{k+1}(x)`.
    fn sign(&self, k: usize, x: &RBig) -> Sign {
        self.small
            .as_ref()
            .zip(small_parts(x))
            .and_then(|(c, (n, d))| sign_homogeneous(&c[k][..=k + 1], n, d))
            .unwrap_or_else(|| self.e[k].sign_at(x))
    }

    /// Inertia of `λA − B` at the rational `x`.
    fn inertia(&self, x: &RBig) -> Inertia {
        let parts = small_parts(x);
        Inertia::from_minor_sum_signs(std::array::from_fn::<Sign, 4, _>(|k| {
            self.small
                .as_ref()
                .zip(parts)
                .and_then(|(c, (n, d))| sign_homogeneous(&c[k][..=k + 1], n, d))
                .unwrap_or_else(|| self.e[k].sign_at(x))
        }))
    }
}

/// `x = n/d` with `d > 0`, both in `i128`.
fn small_parts(x: &RBig) -> Option<(i128, i128)> {
    Some((
        i128::try_from(x.numerator()).ok()?,
        i128::try_from(x.denominator()).ok()?,
    ))
}

/// The sign of `Σ cᵢ nⁱ d^(m−i)` (`m = c.len() − 1`, the sign of `p(n/d)` for `d > 0`),
/// `None` on overflow. Every partial sum of Horner's scheme and every product in it is at
/// most `Σ|cᵢ|·max(|n|, |d|)^m` in magnitude: below `2¹²⁶` the plain operations are exact,
/// else each is checked.
fn sign_homogeneous(c: &[i128], n: i128, d: i128) -> Option<Sign> {
    sign_homogeneous_with(c, sum_bits(c), n, d)
}

/// The bit length of `Σ|cᵢ|` (saturating at `2¹²⁸ − 1`).
fn sum_bits(c: &[i128]) -> u32 {
    let sum = c
        .iter()
        .fold(0u128, |acc, v| acc.saturating_add(v.unsigned_abs()));
    128 - sum.leading_zeros()
}

/// [`sign_homogeneous`] with `sum_bits(c)` given (made once per polynomial).
fn sign_homogeneous_with(c: &[i128], sum_bits: u32, n: i128, d: i128) -> Option<Sign> {
    let (last, rest) = c.split_last()?;
    let base = n.unsigned_abs().max(d.unsigned_abs());
    let bits = sum_bits + rest.len() as u32 * (128 - base.leading_zeros());
    let mut acc = *last;
    let mut dpow = 1i128;
    if bits <= 126 {
        for &ci in rest.iter().rev() {
            dpow = dpow.wrapping_mul(d);
            acc = acc.wrapping_mul(n).wrapping_add(ci.wrapping_mul(dpow));
        }
    } else {
        for &ci in rest.iter().rev() {
            dpow = dpow.checked_mul(d)?;
            acc = acc.checked_mul(n)?.checked_add(ci.checked_mul(dpow)?)?;
        }
    }
    Some(Sign::of_i128(acc))
}

/// How a rational `q` inside the open isolating interval `iv` of a root of `p` compares with
/// the root: by `sign(p, q)` against the sign at the interval's lower end.
fn side_of(
    iv: &RootInterval,
    p: &Poly,
    q: &RBig,
    sign: &impl Fn(&Poly, &RBig) -> Sign,
) -> Ordering {
    let at_q = sign(p, q);
    if at_q.is_zero() {
        Ordering::Equal
    } else if at_q == sign(p, iv.lo()) {
        Ordering::Less
    } else {
        Ordering::Greater
    }
}

/// The leftmost rational of least dyadic denominator (an integer if there is one) strictly
/// between two reals given by isolating intervals of roots of the polynomials with them
/// ([`between_roots`] with [`simplest_between`]): the same whatever the intervals.
pub(crate) fn dyadic_between_isolated(
    left: (&RootInterval, &Poly),
    right: (&RootInterval, &Poly),
    sign: &impl Fn(&Poly, &RBig) -> Sign,
) -> RBig {
    let pick = |l: Option<&RBig>, h: Option<&RBig>| {
        simplest_between(l.expect("bounded"), h.expect("bounded"), false, false)
    };
    between_roots(Some(left.0), Some(right.0), pick, |b, q| {
        let (iv, p) = match b {
            Bound::Left => left,
            Bound::Right => right,
        };
        side_of(iv, p, q, sign)
    })
}

/// `⌊α⌋` and `⌈α⌉` of the root `α` of `p` isolated by `iv`.
fn floor_and_ceil(
    iv: &RootInterval,
    p: &Poly,
    sign: &impl Fn(&Poly, &RBig) -> Sign,
) -> (IBig, IBig) {
    let n = floor_of_root(iv, |q| side_of(iv, p, q, sign));
    let integral = match iv {
        RootInterval::Exact(v) => v.denominator().is_one(),
        RootInterval::Open(lo, hi) => {
            let v = RBig::from(n.clone());
            lo < &v && &v < hi && side_of(iv, p, &v, sign) == Ordering::Equal
        }
    };
    let c = if integral { n.clone() } else { &n + IBig::ONE };
    (n, c)
}

/// The arcs' samples of [`arc_samples`] and the inertia there, computed from float
/// approximations of the real roots of `f = det(λA − B)` instead of isolated roots: for a
/// caller that needs members of a given inertia, not the roots. Each inertia is exact (signs
/// of `E₁…E₄` at the rational sample, in `i128`), so every sample is a correct answer for its
/// member whatever the floats; the samples equal [`arc_samples`]' when the floats separate
/// the roots from the dyadics the rule compares them with, which holds but for roots within
/// rounding of such a dyadic. `None` when `f` has degree below 4, an entry is `2²²` or more,
/// or a number leaves `i128`.
pub(crate) fn quick_arc_samples(a: &Quadric, b: &Quadric) -> Option<Vec<(RBig, Inertia)>> {
    let e = minor_sums_i128(a.small_integer_matrix()?, b.small_integer_matrix()?)?;
    quick_arc_samples_of(&e)
}

/// [`quick_arc_samples`] from `E₁…E₄` of `λA − B` (`e[k]` of degree `k + 1`, from degree 0,
/// of the primitive integer matrices), as the classification's fast path computed them.
pub(crate) fn quick_arc_samples_of(e: &[[i128; 5]; 4]) -> Option<Vec<(RBig, Inertia)>> {
    if e[3][4] == 0 {
        return None;
    }
    let (roots, count) = real_roots_f64(&e[3].map(|c| c as f64));
    let roots = &roots[..count];
    let mut samples = [(0i128, 0u32); 5];
    let integer = |x: f64| (x.is_finite() && x.abs() < 1e30).then_some(x as i128);
    if let (Some(&lo), Some(&hi)) = (roots.first(), roots.last()) {
        samples[0] = (integer(lo.floor())? - 1, 0);
        for (i, w) in roots.windows(2).enumerate() {
            samples[i + 1] = dyadic_between_f64(w[0], w[1])?;
        }
        samples[count] = (integer(hi.ceil())? + 1, 0);
    }
    // consecutive samples on either side of a root (f of opposite signs), none at a root;
    // else the floats were too coarse here and the caller takes the analysis
    let mut last = Sign::Zero;
    let mut out = Vec::with_capacity(count + 1);
    let bits: [u32; 4] = std::array::from_fn(|k| sum_bits(&e[k][..k + 2]));
    for &(n, k) in &samples[..=count] {
        let d = 1i128.checked_shl(k)?;
        let signs: [Sign; 4] = [
            sign_homogeneous_with(&e[0][..2], bits[0], n, d)?,
            sign_homogeneous_with(&e[1][..3], bits[1], n, d)?,
            sign_homogeneous_with(&e[2][..4], bits[2], n, d)?,
            sign_homogeneous_with(&e[3][..5], bits[3], n, d)?,
        ];
        if signs[3] == Sign::Zero || signs[3] == last {
            return None;
        }
        last = signs[3];
        // n/2ᵏ with n odd when k > 0 (the rule's least k): in lowest terms; through a float
        // (exact below 2⁵³, which reduces by trailing zeros only) when it fits
        let x = match i64::try_from(n) {
            Ok(v) if k == 0 => RBig::from(v),
            Ok(v) if v.unsigned_abs() < 1 << 53 && k <= 1000 => {
                RBig::try_from(v as f64 / 2f64.powi(k as i32)).ok()?
            }
            _ => RBig::from_parts_signed(IBig::from(n), IBig::ONE << k as usize),
        };
        out.push((x, Inertia::from_minor_sum_signs(signs)));
    }
    Some(out)
}

/// The rule of [`simplest_between`] on floats `lo < hi`: `⌊lo⌋ + 1` if it is below `hi`, else
/// `(⌊lo·2ᵏ⌋ + 1)/2ᵏ` for the least `k` where that is below `hi` (scaling by `2ᵏ` and `⌊·⌋`
/// are exact), as `(numerator, k)`; `None` past `k = 100` or outside `i128`.
fn dyadic_between_f64(lo: f64, hi: f64) -> Option<(i128, u32)> {
    let mut scale = 1.0f64;
    for k in 0..=100u32 {
        let m = (lo * scale).floor() + 1.0;
        if m < hi * scale {
            return (m.abs() < 1e30).then_some((m as i128, k));
        }
        scale *= 2.0;
    }
    None
}

/// Float approximations of the real roots of the quartic with coefficients `c` (from degree
/// 0, `c[4] ≠ 0`), increasing ([`quartic_roots_f64`], the ones with a negligible imaginary
/// part). None for a root at 0 (`c[0] = 0`): the caller's samples then meet a root and it
/// falls back to the pencil analysis, which sees the rational root (a cone). Not certified,
/// and not meant to be: callers check what they build from it exactly.
fn real_roots_f64(c: &[f64; 5]) -> ([f64; 4], usize) {
    let mut real = [0.0; 4];
    let mut count = 0;
    for r in quartic_roots_f64(c).into_iter().flatten() {
        if r.1.abs() <= 1e-9 * r.0.abs() && r.0.is_finite() {
            real[count] = r.0;
            count += 1;
        }
    }
    real[..count].sort_unstable_by(f64::total_cmp);
    (real, count)
}

/// The samples of the arcs of the chart cut by the increasing finite real roots `α₁ < … <
/// αₖ`: `⌊α₁⌋ − 1`, the leftmost rational of least dyadic denominator between consecutive
/// roots ([`dyadic_between_isolated`]), `⌈αₖ⌉ + 1` (`0` when there is no root). They depend
/// on the roots only, not on their isolating intervals.
fn arc_samples(
    finite: &[&AlgebraicReal],
    sign: &impl Fn(&Poly, &RBig) -> Sign,
    budget: &Budget,
) -> Result<Vec<RBig>, Exhausted> {
    let (Some(first), Some(last)) = (finite.first(), finite.last()) else {
        return Ok(vec![RBig::ZERO]);
    };
    let mut out = Vec::with_capacity(finite.len() + 1);
    let (lo, _) = floor_and_ceil(first.interval(), first.poly(), sign);
    out.push(RBig::from(lo - IBig::ONE));
    for w in finite.windows(2) {
        let (a, b) = separated(w[0], w[1], budget)?;
        out.push(dyadic_between_isolated(
            (a.interval(), a.poly()),
            (b.interval(), b.poly()),
            sign,
        ));
    }
    let (_, hi) = floor_and_ceil(last.interval(), last.poly(), sign);
    out.push(RBig::from(hi + IBig::ONE));
    Ok(out)
}

/// `α < β` with isolating intervals no wider than the gap between them, by quadratic
/// refinement (`O(log log)` steps each once isolated): [`between_roots`] then needs a few
/// picks where wide intervals would cost one halving per bit of the gap (a root `10⁻³⁰⁰⁰`
/// beside `0`: 10 000 picks). The answer does not depend on the intervals. Each round
/// spends a refinement step's units on each root (the evaluation of its polynomial at
/// the interval's ends).
fn separated(
    alpha: &AlgebraicReal,
    beta: &AlgebraicReal,
    budget: &Budget,
) -> Result<(AlgebraicReal, AlgebraicReal), Exhausted> {
    let (mut a, mut b) = (alpha.clone(), beta.clone());
    loop {
        let (ia, ib) = (a.interval(), b.interval());
        let gap = ib.lo() - ia.hi();
        let wide = |iv: &RootInterval| iv.hi() - iv.lo() > gap;
        budget.spend(refine_units(&a).saturating_add(refine_units(&b)))?;
        match (gap > RBig::ZERO, wide(ia), wide(ib)) {
            (true, false, false) => return Ok((a, b)),
            (false, _, _) => {
                a.refine();
                b.refine();
            }
            (true, wa, wb) => {
                if wa {
                    a.refine();
                }
                if wb {
                    b.refine();
                }
            }
        }
    }
}

/// The units of one refinement step of `r`: an evaluation of its polynomial (degree `d`,
/// `b`-bit coefficients) at an end of `n` bits, `d + 1` products of a number of up to
/// `b + d·n` bits by one of `n` bits.
fn refine_units(r: &AlgebraicReal) -> u64 {
    let p = r.poly();
    let d = p.degree().unwrap_or(0);
    let iv = r.interval();
    let n = [iv.lo(), iv.hi()]
        .iter()
        .map(|x| x.numerator().bit_len() + x.denominator().bit_len())
        .max()
        .unwrap_or(0);
    (d as u64 + 1).saturating_mul(product_units(p.max_bits() + d * n, n))
}

/// The inertia at a simple finite root: exactly one eigenvalue crosses zero there, so the
/// member's counts are the smaller of its two arcs'.
fn simple_root_inertia(l: &Inertia, h: &Inertia) -> Inertia {
    Inertia {
        positive: l.positive.min(h.positive),
        negative: l.negative.min(h.negative),
        zero: 1,
    }
}

impl PencilAnalysis {
    /// Analyses the pencil of a regular pair (`f ≢ 0`): the fast path for four simple roots
    /// when its certificate holds, else the exact path (the same answer; module docs).
    pub(crate) fn compute(data: &PencilData) -> PencilAnalysis {
        PencilAnalysis::compute_within(data, &Budget::unlimited())
            .expect("an unlimited budget is never spent")
    }

    /// [`PencilAnalysis::compute`] spending `budget` ([`crate::Budget`]) on the exact
    /// path's square-free decomposition, isolation and refinement; the fast path is
    /// counted by the caller (its work is bounded).
    pub(crate) fn compute_within(
        data: &PencilData,
        budget: &Budget,
    ) -> Result<PencilAnalysis, Exhausted> {
        match PencilAnalysis::compute_simple(data) {
            Some(analysis) => Ok(analysis),
            None => PencilAnalysis::compute_exact(data, budget),
        }
    }

    /// Four simple roots, none at ∞: `None` unless the certified float isolation of `f`
    /// answers (which proves `f` square-free). No minor beyond `E₁…E₄`, no square-free
    /// decomposition; the arcs' signs in `i128`.
    fn compute_simple(data: &PencilData) -> Option<PencilAnalysis> {
        let f = &data.f;
        if f.degree() != Some(4) {
            return None;
        }
        let roots = AlgebraicReal::certified_real_roots_of(f)?;
        let sums = MinorSumSigns::new(&data.e);
        // every open interval isolates a root of f itself (its primitive part)
        let finite: Vec<&AlgebraicReal> = roots.iter().collect();
        // the fast path's roots are certified to be well apart: few refinement steps
        let arcs: Vec<(RBig, Inertia)> =
            arc_samples(&finite, &|_, x| sums.sign(3, x), &Budget::unlimited())
                .ok()?
                .into_iter()
                .map(|x| {
                    let i = sums.inertia(&x);
                    (x, i)
                })
                .collect();
        let complex = 4 - roots.len();
        let real_roots = roots
            .into_iter()
            .enumerate()
            .map(|(i, r)| PencilRoot {
                point: PencilPoint::Finite(r),
                multiplicity: 1,
                blocks: vec![1],
                inertia: simple_root_inertia(&arcs[i].1, &arcs[i + 1].1),
            })
            .collect();
        Some(PencilAnalysis {
            characteristic: f.clone(),
            real_roots,
            complex_roots: vec![vec![1]; complex],
            arcs,
        })
    }

    /// The exact path: square-free decomposition, the minors' gcds when a root is multiple,
    /// Descartes isolation of the pieces.
    fn compute_exact(data: &PencilData, budget: &Budget) -> Result<PencilAnalysis, Exhausted> {
        let f = &data.f;
        let m_inf = BinaryForm::new(f.clone(), 4).multiplicity_at_infinity();
        // a remainder sequence of degree ≤ 4: about d² steps over d + 1 coefficients
        budget.spend(poly_step_units(4, f.max_bits()).saturating_mul(25))?;
        let decomposition = f.squarefree_decomposition();
        let simple = m_inf <= 1 && decomposition.iter().all(|(_, m)| *m == 1);
        let gcds = if simple {
            None
        } else {
            // every minor of the pencil and their gcds: about 100 determinants' work
            budget.spend(poly_step_units(4, f.max_bits()).saturating_mul(2_500))?;
            Some(MinorGcds::new(data.pencil()))
        };

        // The pieces of f: square-free, pairwise coprime forms on which the multiplicity
        // and the orders in D₁, D₂, D₃ are constant. The finite roots are split out of the
        // square-free decomposition of the chart; the root at ∞ is the piece μ.
        let mut forms: Vec<BinaryForm> = Vec::new();
        let mut orders: Vec<(usize, [usize; 3])> = Vec::new();
        for (g, m) in decomposition {
            let mut split = vec![(g, [0usize; 3])];
            if let Some(gc) = &gcds {
                for k in (0..3).rev() {
                    let mut next = Vec::new();
                    for (p, ords) in split {
                        for (h, j) in split_by_order(&p, gc.d[k].chart()) {
                            let mut o = ords;
                            o[k] = j;
                            next.push((h, o));
                        }
                    }
                    split = next;
                }
            }
            for (p, o) in split {
                let d = p.degree().unwrap_or(0);
                forms.push(BinaryForm::new(p, d));
                orders.push((m, o));
            }
        }
        if m_inf > 0 {
            forms.push(BinaryForm::new(Poly::constant(IBig::ONE), 1));
            orders.push((m_inf, gcds.as_ref().map_or([0; 3], MinorGcds::at_infinity)));
        }

        let e = &data.e;
        let roots = BinaryForm::real_roots_of_coprime_within(&forms, budget)?;
        let mut real_count = vec![0usize; forms.len()];
        let mut real_roots: Vec<PencilRoot> = Vec::with_capacity(roots.len());
        for (point, j) in roots {
            let (m, ords) = orders[j];
            real_count[j] += 1;
            let inertia = match &point {
                PencilPoint::Infinity => data.a.inertia(),
                PencilPoint::Finite(r) if m > 1 => inertia_at(e, r),
                // A simple finite root's inertia follows from its arcs (filled in below).
                PencilPoint::Finite(_) => Inertia {
                    positive: 0,
                    negative: 0,
                    zero: 1,
                },
            };
            real_roots.push(PencilRoot {
                point,
                multiplicity: m as u8,
                blocks: blocks_from_orders(m, ords),
                inertia,
            });
        }
        let mut complex_roots = Vec::new();
        for ((form, &(m, ords)), real) in forms.iter().zip(&orders).zip(&real_count) {
            for _ in *real..form.degree() {
                complex_roots.push(blocks_from_orders(m, ords));
            }
        }

        // The arcs' samples: the simplest rationals between the finite roots.
        let finite: Vec<&AlgebraicReal> = real_roots
            .iter()
            .filter_map(|r| match &r.point {
                PencilPoint::Finite(x) => Some(x),
                PencilPoint::Infinity => None,
            })
            .collect();
        let sums = MinorSumSigns::new(e);
        let arcs: Vec<(RBig, Inertia)> = arc_samples(&finite, &|p: &Poly, x| p.sign_at(x), budget)?
            .into_iter()
            .map(|x| {
                let i = sums.inertia(&x);
                (x, i)
            })
            .collect();
        for (i, r) in real_roots.iter_mut().enumerate() {
            if r.multiplicity == 1 && matches!(r.point, PencilPoint::Finite(_)) {
                r.inertia = simple_root_inertia(&arcs[i].1, &arcs[i + 1].1);
            }
        }
        Ok(PencilAnalysis {
            characteristic: f.clone(),
            real_roots,
            complex_roots,
            arcs,
        })
    }

    /// The signature sequence along the projective line, cut inside the arc left of the
    /// first finite root: `(I₀, R₁, I₁, …)`, ending with the swap of `I₀`.
    pub(crate) fn signature_sequence(&self) -> Vec<SigItem> {
        let mut seq = Vec::new();
        let interval = |i: &Inertia| SigItem::Interval(i.positive);
        if self.real_roots.is_empty() {
            seq.push(interval(&self.arcs[0].1));
            return seq;
        }
        seq.push(interval(&self.arcs[0].1));
        let mut arc = 1;
        for r in &self.real_roots {
            seq.push(SigItem::Root {
                p: r.inertia.positive,
                n: r.inertia.negative,
                mult: r.multiplicity,
            });
            match r.point {
                PencilPoint::Finite(_) => {
                    seq.push(interval(&self.arcs[arc].1));
                    arc += 1;
                }
                PencilPoint::Infinity => seq.push(SigItem::Interval(4 - self.arcs[0].1.positive)),
            }
        }
        seq
    }
}

/// One entry of a signature sequence.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) enum SigItem {
    /// An arc where the members are nonsingular, with `p` positive eigenvalues.
    Interval(u8),
    /// A root with the inertia `(p, n)` of its member and its multiplicity.
    Root { p: u8, n: u8, mult: u8 },
}

impl SigItem {
    /// The same item for `−A, −B` (or seen across λ = ∞): positive and negative swapped.
    pub fn swapped(self) -> SigItem {
        match self {
            SigItem::Interval(p) => SigItem::Interval(4 - p),
            SigItem::Root { p, n, mult } => SigItem::Root { p: n, n: p, mult },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use qsic_algebra::matrix::Inertia;
    use qsic_algebra::testing::SplitMix;

    fn diag(v: [i64; 4]) -> Quadric {
        let mut m = [[0i64; 4]; 4];
        for i in 0..4 {
            m[i][i] = v[i];
        }
        Quadric::from_integers(m).expect("nonzero")
    }

    fn inertia(p: u8, n: u8) -> Inertia {
        Inertia {
            positive: p,
            negative: n,
            zero: 4 - p - n,
        }
    }

    /// The sums by interpolation are those of the pencil's minors, for small and big entries.
    #[test]
    fn interpolated_minor_sums_equal_the_pencils() {
        let mut rng = qsic_algebra::testing::SplitMix(23);
        for shift in [0usize, 3, 12, 18, 19, 40, 100] {
            for _ in 0..30 {
                let mut sym = || -> [[IBig; 4]; 4] {
                    let mut m: [[IBig; 4]; 4] = Default::default();
                    for i in 0..4 {
                        for j in i..4 {
                            m[i][j] =
                                IBig::from(rng.int(-9, 9)) << rng.int(0, shift as i64) as usize;
                            m[j][i] = m[i][j].clone();
                        }
                    }
                    m
                };
                let (a, b) = (sym(), sym());
                let want = MatrixPencil::from_entries(a.clone(), b.clone()).principal_minor_sums();
                assert_eq!(principal_minor_sums_of_pencil(&a, &b), want);
            }
        }
    }

    /// The direct `i128` sums equal the interpolation over big integers (another route) on
    /// any 4×4 arrays (not only symmetric ones) with entries up to the bound `2²² − 1`, where
    /// the products are largest (overflow is checked in test builds).
    #[test]
    fn direct_minor_sums_equal_the_interpolation_at_the_bound() {
        use qsic_algebra::linalg::pencil::principal_minor_sums_of_members;
        let mut rng = SplitMix(57);
        let top = (1i64 << 22) - 1;
        for t in 0..300 {
            let mut entry = || match t % 3 {
                0 => rng.int(-9, 9),
                1 => [top, -top][rng.int(0, 1) as usize],
                _ => rng.int(-top, top),
            };
            let a: [[i64; 4]; 4] = std::array::from_fn(|_| std::array::from_fn(|_| entry()));
            let b: [[i64; 4]; 4] = std::array::from_fn(|_| std::array::from_fn(|_| entry()));
            let member = |l: i64, k: i64| -> [[IBig; 4]; 4] {
                std::array::from_fn(|i| {
                    std::array::from_fn(|j| IBig::from(l * a[i][j]) - IBig::from(k * b[i][j]))
                })
            };
            let want = principal_minor_sums_of_members([
                &member(1, 0),
                &member(0, 1),
                &member(1, 1),
                &member(-1, 1),
                &member(2, 1),
            ]);
            let got = minor_sums_i128(&a, &b).expect("entries below 2²²");
            for k in 0..4 {
                for i in 0..5 {
                    assert_eq!(
                        IBig::from(got[k][i]),
                        want[k][i],
                        "E{} λ^{i}: {a:?} {b:?}",
                        k + 1
                    );
                }
            }
        }
        let mut big = [[0i64; 4]; 4];
        big[1][2] = 1 << 22;
        assert_eq!(minor_sums_i128(&big, &[[0; 4]; 4]), None);
    }

    /// The homogeneous sign in plain `i128` (small values) and checked `i128` (large ones)
    /// equals the big-integer value's sign; `None` only past `i128`.
    #[test]
    fn homogeneous_signs_agree_with_big_integers() {
        let mut rng = SplitMix(58);
        let (mut plain, mut checked, mut overflow) = (0, 0, 0);
        for t in 0..3000 {
            let bits = [30, 40, 98][t % 3];
            let m = rng.int(1, 4) as usize;
            let c: Vec<i128> = (0..=m)
                .map(|_| i128::from(rng.int(-1 << 30, 1 << 30)) << rng.int(0, bits - 30))
                .collect();
            let k = rng.int(0, 20) as u32;
            let n = i128::from(rng.int(-1 << 20, 1 << 20)) >> rng.int(0, 20);
            let d = 1i128 << k;
            let exact = c.iter().enumerate().fold(IBig::ZERO, |acc, (i, &ci)| {
                acc + IBig::from(ci) * IBig::from(n).pow(i) * IBig::from(d).pow(m - i)
            });
            let sum = c.iter().map(|v| v.unsigned_abs()).sum::<u128>();
            let base = n.unsigned_abs().max(d.unsigned_abs());
            let fast = (128 - sum.leading_zeros()) + m as u32 * (128 - base.leading_zeros()) <= 126;
            match sign_homogeneous(&c, n, d) {
                Some(s) => {
                    assert_eq!(s, Sign::of(&exact), "{c:?} at {n}/{d}");
                    if fast {
                        plain += 1;
                    } else {
                        checked += 1;
                    }
                }
                None => {
                    assert!(!fast, "{c:?} at {n}/{d}: {exact}");
                    overflow += 1;
                }
            }
        }
        assert!(
            plain > 300 && checked > 50 && overflow > 10,
            "{plain} {checked} {overflow}"
        );
    }

    /// λA − B = diag(λ − 1, 2 − λ, λ, −λ): roots 0 (double, two 1×1 blocks), 1, 2.
    #[test]
    fn diagonal_pencil_known_roots_blocks_and_inertia() {
        let data = PencilData::new(&diag([1, -1, 1, -1]), &diag([1, -2, 0, 0]));
        let an = PencilAnalysis::compute(&data);
        let roots: Vec<(Option<RBig>, u8, Vec<u8>, Inertia)> = an
            .real_roots
            .iter()
            .map(|r| match &r.point {
                PencilPoint::Finite(a) => (
                    a.as_rational().cloned(),
                    r.multiplicity,
                    r.blocks.clone(),
                    r.inertia,
                ),
                PencilPoint::Infinity => (None, r.multiplicity, r.blocks.clone(), r.inertia),
            })
            .collect();
        assert_eq!(
            roots,
            vec![
                (Some(RBig::ZERO), 2, vec![1, 1], inertia(1, 1)),
                (Some(RBig::ONE), 1, vec![1], inertia(2, 1)),
                (Some(RBig::from(2)), 1, vec![1], inertia(2, 1)),
            ]
        );
        let arcs: Vec<u8> = an.arcs.iter().map(|(_, i)| i.positive).collect();
        assert_eq!(arcs, vec![2, 2, 3, 2]);
        assert!(an.complex_roots.is_empty());
    }

    /// A = diag(1, 1, 0, 0) is singular: λA − B = diag(λ − 3, λ − 3, −1, −1) has a double
    /// root at 3 and one at ∞, each with two 1×1 blocks; case 9's pencil has two 2×2 blocks.
    #[test]
    fn root_at_infinity_and_jordan_blocks() {
        let data = PencilData::new(&diag([1, 1, 0, 0]), &diag([3, 3, 1, 1]));
        let an = PencilAnalysis::compute(&data);
        assert_eq!(an.real_roots.len(), 2);
        assert_eq!(an.real_roots[0].multiplicity, 2);
        assert_eq!(an.real_roots[0].blocks, vec![1, 1]);
        assert_eq!(an.real_roots[1].point, PencilPoint::Infinity);
        assert_eq!(an.real_roots[1].blocks, vec![1, 1]);
        assert_eq!(an.real_roots[1].inertia, inertia(2, 0));
        // case 9: A = xy + zw, B = y² + 2zw + w² (matrices doubled)
        let a = Quadric::from_integers([[0, 1, 0, 0], [1, 0, 0, 0], [0, 0, 0, 1], [0, 0, 1, 0]])
            .expect("valid");
        let b = Quadric::from_integers([[0, 0, 0, 0], [0, 2, 0, 0], [0, 0, 0, 2], [0, 0, 2, 2]])
            .expect("valid");
        let an = PencilAnalysis::compute(&PencilData::new(&a, &b));
        let blocks: Vec<Vec<u8>> = an.real_roots.iter().map(|r| r.blocks.clone()).collect();
        assert_eq!(blocks, vec![vec![2], vec![2]]);
    }

    type Big4 = [[IBig; 4]; 4];

    fn quadric(m: &Big4) -> Option<Quadric> {
        Quadric::from_matrix(m.clone().map(|r| r.map(RBig::from))).ok()
    }

    /// `PᵀDP`.
    fn congruent(p: &Big4, d: &[IBig; 4]) -> Big4 {
        std::array::from_fn(|i| {
            std::array::from_fn(|j| (0..4).map(|k| &p[k][i] * &d[k] * &p[k][j]).sum())
        })
    }

    /// Random pairs of the families: entries in [−10, 10], below 2²⁰, about 10⁴⁰; disguised
    /// diagonal pencils with roots 1, 2, 2 + 1/K, −3 (K up to 2⁶⁰: near-double) and with a
    /// double root 2 (never the fast path).
    fn random_pair(rng: &mut SplitMix, family: usize) -> Option<(Quadric, Quadric)> {
        let mut sym = |r: i64, scale: &IBig| -> Big4 {
            let mut m: Big4 = Default::default();
            for i in 0..4 {
                for j in i..4 {
                    m[i][j] = IBig::from(rng.int(-r, r)) * scale + IBig::from(rng.int(-r, r));
                    m[j][i] = m[i][j].clone();
                }
            }
            m
        };
        let (a, b) = match family {
            0 => (sym(10, &IBig::ONE), sym(10, &IBig::ONE)),
            1 => (sym(1 << 20, &IBig::ONE), sym(1 << 20, &IBig::ONE)),
            2 => {
                let big = IBig::from(10).pow(40);
                (sym(9, &big), sym(9, &big))
            }
            _ => {
                let k = IBig::ONE << rng.int(10, 60) as usize;
                let p: Big4 =
                    std::array::from_fn(|_| std::array::from_fn(|_| rng.int(-2, 2).into()));
                let signs: [IBig; 4] = std::array::from_fn(|_| IBig::from(2 * rng.int(0, 1) - 1));
                let da: [IBig; 4] = std::array::from_fn(|i| &signs[i] * &k);
                let near = if family == 3 { IBig::ONE } else { IBig::ZERO };
                let roots = [k.clone(), &k * 2, &k * 2 + near, &k * -3];
                let db: [IBig; 4] = std::array::from_fn(|i| &signs[i] * &roots[i]);
                (congruent(&p, &da), congruent(&p, &db))
            }
        };
        Some((quadric(&a)?, quadric(&b)?))
    }

    fn assert_same(fast: &PencilAnalysis, exact: &PencilAnalysis, what: &str) {
        assert_eq!(fast.characteristic, exact.characteristic, "{what}");
        assert_eq!(fast.real_roots, exact.real_roots, "{what}");
        assert_eq!(fast.complex_roots, exact.complex_roots, "{what}");
        assert_eq!(fast.arcs, exact.arcs, "{what}");
    }

    /// The fast path and the exact path give the same analysis (roots, blocks, inertia, arcs
    /// and their samples) on every family; the fast path answers the common pairs and never a
    /// pencil with a double root.
    #[test]
    fn fast_path_equals_exact_path() {
        let mut rng = SplitMix(77);
        for family in 0..5 {
            let (mut total, mut fast) = (0, 0);
            while total < 60 {
                let Some((a, b)) = random_pair(&mut rng, family) else {
                    continue;
                };
                let data = PencilData::new(&a, &b);
                if data.f.is_zero() {
                    continue;
                }
                total += 1;
                let exact = PencilAnalysis::compute_exact(&data, &Budget::unlimited()).unwrap();
                let what = format!("family {family}: {:?} / {:?}", a.matrix(), b.matrix());
                if let Some(simple) = PencilAnalysis::compute_simple(&data) {
                    fast += 1;
                    assert_same(&simple, &exact, &what);
                }
                assert_same(&PencilAnalysis::compute(&data), &exact, &what);
            }
            match family {
                0..=2 => assert!(fast >= 50, "family {family}: {fast} of {total} fast"),
                4 => assert_eq!(fast, 0, "a double root on the fast path"),
                _ => {}
            }
        }
    }

    /// The quick samples' inertia is that of the member itself (by the matrix, another
    /// route), and on pencils with four simple roots the samples and inertia are the
    /// analysis' arcs (floats separate the roots from the rule's dyadics); on pencils with
    /// near-double roots the samples may differ, the inertia stays exact.
    #[test]
    fn quick_arc_samples_have_exact_inertia_and_equal_the_analysis() {
        let mut rng = SplitMix(91);
        let (mut answered, mut simple, mut hard) = (0, 0, 0);
        for family in [0usize, 1, 0, 3, 4] {
            for _ in 0..40 {
                let Some((a, b)) = random_pair(&mut rng, family) else {
                    continue;
                };
                let quick = quick_arc_samples(&a, &b);
                let (am, bm) = (a.integer_matrix(), b.integer_matrix());
                for (x, inertia) in quick.iter().flatten() {
                    let (n, d) = (x.numerator().clone(), IBig::from(x.denominator().clone()));
                    let m = SymMatrix4::new(std::array::from_fn(|i| {
                        std::array::from_fn(|j| &n * &am.entries()[i][j] - &d * &bm.entries()[i][j])
                    }))
                    .expect("symmetric");
                    assert_eq!(*inertia, m.inertia(), "inertia at {x}");
                }
                let data = PencilData::new(&a, &b);
                let exact = PencilAnalysis::compute_exact(&data, &Budget::unlimited()).unwrap();
                if exact.real_roots.iter().all(|r| r.multiplicity == 1)
                    && exact.complex_roots.iter().all(|c| c == &[1])
                    && data.f.degree() == Some(4)
                {
                    simple += 1;
                    hard += usize::from(family >= 3);
                    if let Some(quick) = quick {
                        answered += 1;
                        assert_eq!(quick, exact.arcs);
                    }
                }
            }
        }
        // families 3 and 4 have roots at integers, 3 a quarter apart: the floats may land on
        // a root, and the analysis decides; the random families are all answered
        assert!(simple >= 100 && hard >= 20, "{simple}, {hard}");
        assert!(answered >= simple - hard, "{answered} of {simple}");
    }

    /// Roots `10⁻ᵏ` beside `0` (the pencil of `diag(10ᵏ, 1, 1, −1)` and a cone): given the
    /// wide isolating interval `(10⁻²ᵏ, 1)`, `separated` narrows it below the gap, and the
    /// sample between them is the least dyadic there, `2⁻ᵐ` with `2ᵐ > 10ᵏ ≥ 2ᵐ⁻¹`.
    #[test]
    fn tiny_roots_are_separated_before_the_sample_is_picked() {
        for k in [1usize, 30, 3000] {
            let big = IBig::from(10).pow(k);
            // (10ᵏλ − 1)·λ
            let p = Poly::new(vec![IBig::ZERO, -IBig::ONE, big.clone()]);
            let zero = AlgebraicReal::from_isolating_interval(&p, &RootInterval::Exact(RBig::ZERO))
                .unwrap();
            let lo = RBig::from_parts_signed(IBig::ONE, &big * &big);
            let wide = RootInterval::Open(lo, RBig::ONE);
            let tiny = AlgebraicReal::from_isolating_interval(&p, &wide).unwrap();
            let (a, b) = separated(&zero, &tiny, &Budget::unlimited()).unwrap();
            let gap = b.interval().lo() - a.interval().hi();
            assert!(gap > RBig::ZERO);
            assert!(b.interval().hi() - b.interval().lo() <= gap, "10^-{k}");
            let m = (0..).find(|&m| IBig::ONE << m > big).unwrap();
            let want = RBig::from_parts_signed(IBig::ONE, IBig::ONE << m);
            let sign = |p: &Poly, x: &RBig| p.sign_at(x);
            assert_eq!(
                arc_samples(&[&zero, &tiny], &sign, &Budget::unlimited()).unwrap()[1],
                want,
                "10^-{k}"
            );
        }
    }

    /// The arcs' samples depend on the roots only: from the certified intervals, from the
    /// Descartes ones, from narrow refinements and from the widest isolating intervals
    /// (between neighbouring samples) they are the same, each strictly between its roots.
    #[test]
    fn arc_samples_do_not_depend_on_the_intervals() {
        let mut rng = SplitMix(78);
        let mut checked = 0;
        while checked < 40 {
            let Some((a, b)) = random_pair(&mut rng, 0) else {
                continue;
            };
            let data = PencilData::new(&a, &b);
            if data.f.degree() != Some(4) {
                continue;
            }
            let exact = PencilAnalysis::compute_exact(&data, &Budget::unlimited()).unwrap();
            let roots: Vec<AlgebraicReal> = exact
                .real_roots
                .iter()
                .map(|r| match &r.point {
                    PencilPoint::Finite(x) => x.clone(),
                    PencilPoint::Infinity => unreachable!("f has degree 4"),
                })
                .collect();
            if roots.is_empty() || exact.real_roots.iter().any(|r| r.multiplicity > 1) {
                continue;
            }
            checked += 1;
            let want: Vec<RBig> = exact.arcs.iter().map(|(x, _)| x.clone()).collect();
            let sign = |p: &Poly, x: &RBig| p.sign_at(x);
            let samples = |xs: &[AlgebraicReal]| {
                arc_samples(&xs.iter().collect::<Vec<_>>(), &sign, &Budget::unlimited()).unwrap()
            };
            let reshaped =
                |iv: &dyn Fn(usize, &AlgebraicReal) -> RootInterval| -> Vec<AlgebraicReal> {
                    roots
                        .iter()
                        .enumerate()
                        .map(|(i, r)| {
                            AlgebraicReal::from_isolating_interval(r.poly(), &iv(i, r))
                                .expect("an isolating interval")
                        })
                        .collect()
                };
            let width = RBig::from_parts_signed(IBig::ONE, IBig::ONE << 60usize);
            let narrow = reshaped(&|_, r| r.refined_interval(&width));
            let widest = reshaped(&|i, r| match r.as_rational() {
                Some(v) => RootInterval::Exact(v.clone()),
                None => RootInterval::Open(want[i].clone(), want[i + 1].clone()),
            });
            let certified = AlgebraicReal::certified_real_roots_of(&data.f);
            for (name, got) in [
                ("exact", samples(&roots)),
                ("narrow", samples(&narrow)),
                ("widest", samples(&widest)),
            ]
            .into_iter()
            .chain(certified.map(|c| ("certified", samples(&c))))
            {
                assert_eq!(got, want, "{name} intervals");
            }
            for (i, x) in want.iter().enumerate() {
                let x = AlgebraicReal::from_rational(x.clone());
                assert!(i == 0 || roots[i - 1] < x, "sample {i} right of its root");
                assert!(
                    i == roots.len() || x < roots[i],
                    "sample {i} left of its root"
                );
            }
        }
    }
}
