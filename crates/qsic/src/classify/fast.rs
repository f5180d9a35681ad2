//! The fast path for the commonest input: a pencil with four simple roots (cases 1–4),
//! small integer matrices, `det A ≠ 0`. Machine arithmetic only: exact `i128`
//! polynomials, then certified float signs ([`qsic_algebra::filter`]). Any sign the
//! filter cannot certify returns `None`, and the exact path decides.
//!
//! Method, for `f(λ) = det(λA − B) = aλ⁴ + bλ³ + cλ² + dλ + e` with `a ≠ 0`:
//! - `disc(f) ≠ 0`: four simple roots, Segre `[1111]`. `disc < 0`: two real roots, case 3
//!   (Theorem 5: one class). `disc > 0`: four real roots iff `P = 8ac − 3b² < 0` and
//!   `D = 64a³e − 16a²c² + 16ab²c − 16a²bd − 3b⁴ < 0`, else none: case 4 (Theorem 6).
//! - Four real roots (Theorem 4): case 2 iff some member is definite. The arcs between the
//!   roots hold the three critical points of `f` (Rolle) and `λ = ∞` (the member `A`);
//!   float approximations of the critical points are certified to lie in the right arcs
//!   by the signs of `f` there, and the inertia at each sample comes from the certified
//!   signs of the principal minor sums `E₁…E₄`.
//!
//! The polynomials `E_k(λ)` come straight from the entries when they are below `2²²`
//! (`pencil::minor_sums_i128`, the pencil's quadratic 2×2 minors), else from the one minor
//! implementation in `i128` ([`qsic_algebra::linalg::pencil::principal_minor_sums_of_members`]:
//! the principal minors of the members at `λ = ∞, 0, ±1` and `det(2A − B)`, then
//! interpolation). The curve's surface choice reads the same sums ([`SimpleRoots`]).
//!
//! Precondition, checked: every entry is below [`ENTRY_LIMIT`] = 2²⁴ in absolute value. Then
//! the members' entries are below `3·2²⁴`, every product of four of them below `81·2⁹⁶ < 2¹⁰³`,
//! and every minor, sum of at most 24 such products, below `2¹⁰⁸` (no `i128` overflow; the
//! interpolation's sums of a few such values with factors up to 16 stay below `2¹¹⁴`); the
//! discriminant's terms, products of six coefficients, stay below `2¹⁰²⁴` (no float overflow).

use qsic_algebra::filter::{certified_sign, certified_sign_poly, sum_of_products_bound};
use qsic_algebra::linalg::pencil::principal_minor_sums_of_members;
use qsic_algebra::Sign;

/// Entries must be below this in absolute value (see the module docs).
pub(crate) const ENTRY_LIMIT: u64 = 1 << 24;

fn within_entry_limit(m: &[[i64; 4]; 4]) -> bool {
    m.iter().flatten().all(|v| v.unsigned_abs() < ENTRY_LIMIT)
}

/// `E₁…E₄` of `λA − B` as exact polynomials (low degree first).
struct MinorSums {
    e1: [i128; 2],
    e2: [i128; 3],
    e3: [i128; 4],
    e4: [i128; 5],
}

/// The fast path's answer with what it computed on the way: the case (1–4) and `E₁…E₄` of
/// `λA − B` (`e[k]` of degree `k + 1`, from degree 0), for a caller that needs them too.
pub(crate) struct SimpleRoots {
    pub case: u8,
    pub sums: [[i128; 5]; 4],
}

fn minor_sums(a: &[[i64; 4]; 4], b: &[[i64; 4]; 4]) -> [[i128; 5]; 4] {
    crate::pencil::minor_sums_i128(a, b).unwrap_or_else(|| minor_sums_of_members(a, b))
}

/// [`minor_sums`] by interpolation from five members (any entries below [`ENTRY_LIMIT`]).
fn minor_sums_of_members(a: &[[i64; 4]; 4], b: &[[i64; 4]; 4]) -> [[i128; 5]; 4] {
    // the members lA − B and A, formed in i64 (|entries| < 3·2²⁴)
    let member = |l: i64, k: i64| {
        let mut m = [[0i128; 4]; 4];
        for i in 0..4 {
            for j in 0..4 {
                m[i][j] = i128::from(l * a[i][j] - k * b[i][j]);
            }
        }
        m
    };
    principal_minor_sums_of_members([
        &member(1, 0),
        &member(0, 1),
        &member(1, 1),
        &member(-1, 1),
        &member(2, 1),
    ])
}

/// The lowest `K` coefficients.
fn lowest<const K: usize>(c: &[i128; 5]) -> [i128; K] {
    std::array::from_fn(|i| c[i])
}

fn to_f64<const N: usize>(c: &[i128; N]) -> [f64; N] {
    c.map(|v| v as f64)
}

/// Certified sign of `Σ terms` where each term is a product of `factors` rounded inputs.
fn sign_of_sum(terms: &[f64], factors: usize) -> Option<Sign> {
    let value: f64 = terms.iter().sum();
    let mag: f64 = terms.iter().map(|t| t.abs()).sum();
    certified_sign(value, sum_of_products_bound(factors, terms.len(), mag))
}

/// The case of [`simple_roots`] (the tests' shorthand).
#[cfg(test)]
fn classify_simple_roots(a: &[[i64; 4]; 4], b: &[[i64; 4]; 4]) -> Option<u8> {
    simple_roots(a, b).map(|r| r.case)
}

/// The case (1–4) of a pencil with four simple roots with the minor sums it was read from, or
/// `None` when the fast path does not apply (an entry not below [`ENTRY_LIMIT`], `det A = 0`,
/// a multiple root) or cannot certify a sign.
pub(crate) fn simple_roots(a: &[[i64; 4]; 4], b: &[[i64; 4]; 4]) -> Option<SimpleRoots> {
    if !within_entry_limit(a) || !within_entry_limit(b) {
        return None;
    }
    let sums = minor_sums(a, b);
    let [e1, e2, e3, e4] = &sums;
    let s = MinorSums {
        e1: lowest(e1),
        e2: lowest(e2),
        e3: lowest(e3),
        e4: *e4,
    };
    if s.e4[4] == 0 {
        return None;
    }
    let case = case_of(&s)?;
    Some(SimpleRoots { case, sums })
}

/// The case from the minor sums (`E₄` of degree 4).
fn case_of(s: &MinorSums) -> Option<u8> {
    let [e, d, c, b1, a4] = to_f64(&s.e4);
    let (a, b) = (a4, b1);
    let disc = sign_of_sum(
        &[
            256.0 * a * a * a * e * e * e,
            -192.0 * a * a * b * d * e * e,
            -128.0 * a * a * c * c * e * e,
            144.0 * a * a * c * d * d * e,
            -27.0 * a * a * d * d * d * d,
            144.0 * a * b * b * c * e * e,
            -6.0 * a * b * b * d * d * e,
            -80.0 * a * b * c * c * d * e,
            18.0 * a * b * c * d * d * d,
            16.0 * a * c * c * c * c * e,
            -4.0 * a * c * c * c * d * d,
            -27.0 * b * b * b * b * e * e,
            18.0 * b * b * b * c * d * e,
            -4.0 * b * b * b * d * d * d,
            -4.0 * b * b * c * c * c * e,
            b * b * c * c * d * d,
        ],
        7,
    )?;
    match disc {
        Sign::Zero => return None,
        Sign::Negative => return Some(3),
        Sign::Positive => {}
    }
    let p = sign_of_sum(&[8.0 * a * c, -3.0 * b * b], 3)?;
    let dd = sign_of_sum(
        &[
            64.0 * a * a * a * e,
            -16.0 * a * a * c * c,
            16.0 * a * b * b * c,
            -16.0 * a * a * b * d,
            -3.0 * b * b * b * b,
        ],
        5,
    )?;
    if p == Sign::Positive || dd == Sign::Positive {
        return Some(4);
    }
    if p != Sign::Negative || dd != Sign::Negative {
        return None;
    }
    // Four real roots: is some member definite?
    let lead = |v: i128| Sign::of_i128(v);
    let at_infinity = [lead(s.e1[1]), lead(s.e2[2]), lead(s.e3[3]), lead(s.e4[4])];
    if is_definite(at_infinity) {
        return Some(2);
    }
    let crit = critical_points(a, b, c, d)?;
    let fc = to_f64(&s.e4);
    let sa = lead(s.e4[4]);
    let expected = [-sa, sa, -sa];
    let (e1, e2, e3) = (to_f64(&s.e1), to_f64(&s.e2), to_f64(&s.e3));
    for (x, want) in crit.iter().zip(expected) {
        if certified_sign_poly(&fc, *x)? != want {
            return None;
        }
        let signs = [
            certified_sign_poly(&e1, *x)?,
            certified_sign_poly(&e2, *x)?,
            certified_sign_poly(&e3, *x)?,
            want,
        ];
        if is_definite(signs) {
            return Some(2);
        }
    }
    Some(1)
}

/// Positive definite: all principal minor sums positive; negative definite: signs alternate
/// starting with `E₁ < 0`.
fn is_definite(s: [Sign; 4]) -> bool {
    use Sign::{Negative as N, Positive as P};
    s == [P, P, P, P] || s == [N, P, N, P]
}

/// Approximations of the three real roots of `f' = 4aλ³ + 3bλ² + 2cλ + d`, increasing,
/// by the trigonometric formula; `None` if it does not apply numerically.
fn critical_points(a: f64, b: f64, c: f64, d: f64) -> Option<[f64; 3]> {
    let (bb, cc, dd) = (3.0 * b / (4.0 * a), 2.0 * c / (4.0 * a), d / (4.0 * a));
    let p = cc - bb * bb / 3.0;
    let q = 2.0 * bb * bb * bb / 27.0 - bb * cc / 3.0 + dd;
    if p.is_nan() || p >= 0.0 {
        return None;
    }
    let m = 2.0 * (-p / 3.0).sqrt();
    let arg = (3.0 * q / (p * m)).clamp(-1.0, 1.0);
    let theta = arg.acos() / 3.0;
    let mut r = [0.0; 3];
    for (k, slot) in r.iter_mut().enumerate() {
        *slot = m * (theta - 2.0 * std::f64::consts::PI * k as f64 / 3.0).cos() - bb / 3.0;
    }
    // one Newton step on f' each, for accuracy near clustered roots
    let fp = |x: f64| ((4.0 * a * x + 3.0 * b) * x + 2.0 * c) * x + d;
    let fpp = |x: f64| (12.0 * a * x + 6.0 * b) * x + 2.0 * c;
    for x in r.iter_mut() {
        let den = fpp(*x);
        if den != 0.0 {
            let nx = *x - fp(*x) / den;
            if nx.is_finite() {
                *x = nx;
            }
        }
    }
    r.sort_by(f64::total_cmp);
    r.iter().all(|x| x.is_finite()).then_some(r)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::classify::classify_exact;
    use crate::Quadric;

    use qsic_algebra::testing::SplitMix;

    /// A symmetric matrix with entries uniform in [−r, r].
    fn random_matrix(rng: &mut SplitMix, r: i64) -> [[i64; 4]; 4] {
        let mut m = [[0i64; 4]; 4];
        for i in 0..4 {
            for j in i..4 {
                let v = rng.int(-r, r);
                m[i][j] = v;
                m[j][i] = v;
            }
        }
        m
    }

    fn exact_case(a: [[i64; 4]; 4], b: [[i64; 4]; 4]) -> Option<u8> {
        let (qa, qb) = (Quadric::from_integers(a), Quadric::from_integers(b));
        classify_exact(&qa.expect("nonzero"), &qb.expect("nonzero")).case
    }

    /// The fast path is the common path: on random pairs (entries in [−10, 10] and in
    /// [−2²³, 2²³]) it decides at least 95 % of them, every one of cases 1–4 among them,
    /// each decision equal to the exact path's.
    #[test]
    fn decides_most_random_pairs_and_agrees_with_the_exact_path() {
        for (range, seed) in [(10, 1), (1 << 23, 2)] {
            let mut rng = SplitMix(seed);
            let (mut total, mut decided) = (0, 0);
            let mut seen = [false; 5];
            while total < 400 {
                let (a, b) = (
                    random_matrix(&mut rng, range),
                    random_matrix(&mut rng, range),
                );
                if a == [[0; 4]; 4] || b == [[0; 4]; 4] {
                    continue;
                }
                total += 1;
                let Some(case) = classify_simple_roots(&a, &b) else {
                    continue;
                };
                decided += 1;
                assert_eq!(Some(case), exact_case(a, b), "A = {a:?}, B = {b:?}");
                seen[case as usize] = true;
            }
            assert!(decided * 100 >= total * 95, "{decided} of {total} decided");
            assert_eq!(seen, [false, true, true, true, true], "range {range}");
        }
    }

    /// Diagonal pencils with two roots `b₁/a₁ ≈ b₂/a₂` about 2⁻⁴⁶ apart: the discriminant is
    /// positive (four real roots) but its float value is negative, 5–6 % of the certified
    /// bound (found by search). A bound 20 times too small answers case 3.
    const CLUSTERED_DIAGONALS: [[i64; 8]; 3] = [
        [
            12573553, 13959350, 14451059, 16043786, -4552063, 13475464, 4898697, -1851636,
        ],
        [
            13453744, 5186399, 6173774, 2379981, 2626446, -1672042, -8137293, -7495,
        ],
        [
            14949688, 16375058, 5355287, 5865884, -8293584, 15363273, -2460579, 575323,
        ],
    ];

    fn diagonal(d: [i64; 4]) -> [[i64; 4]; 4] {
        let mut m = [[0; 4]; 4];
        for i in 0..4 {
            m[i][i] = d[i];
        }
        m
    }

    #[test]
    fn wrong_float_discriminant_signs_are_not_trusted() {
        for (line, r) in CLUSTERED_DIAGONALS.iter().enumerate() {
            let a = diagonal([r[0], r[2], r[4], r[6]]);
            let b = diagonal([r[1], r[3], r[5], r[7]]);
            let truth = exact_case(a, b);
            assert!(matches!(truth, Some(1 | 2)), "fixture {line}: {truth:?}");
            let fast = classify_simple_roots(&a, &b);
            assert!(fast.is_none() || fast == truth, "fixture {line}: {fast:?}");
        }
    }

    /// `f = (λ² + 2λ + 2)(λ² + 2λ + 5)`: no real root, `disc > 0`, `D < 0`, so only
    /// `P = 8ac − 3b² = 40 > 0` says case 4 (from two 2×2 blocks with `det = −((λ+1)² + q²)`).
    #[test]
    fn no_real_roots_decided_by_p_alone() {
        let a = diagonal([1, -1, 1, -1]);
        let mut b = diagonal([-1, 1, -1, 1]);
        (b[0][1], b[1][0], b[2][3], b[3][2]) = (-1, -1, -2, -2);
        assert_eq!(exact_case(a, b), Some(4));
        assert_eq!(classify_simple_roots(&a, &b), Some(4));
    }

    /// The interpolated `E₁…E₄` are the exact pencil's, on random pairs up to the entry limit
    /// and on a Hadamard matrix of entries ±(2²⁴ − 1) (the largest determinant there); test
    /// builds check every `i128` operation for overflow.
    #[test]
    fn interpolated_minor_sums_are_the_exact_ones() {
        use qsic_algebra::matrix::{MatrixPencil, SymMatrix4};
        use qsic_algebra::{IBig, Poly};
        let l = ENTRY_LIMIT as i64 - 1;
        let h = [[l, l, l, l], [l, -l, l, -l], [l, l, -l, -l], [l, -l, -l, l]];
        let minus_h = h.map(|r| r.map(|v| -v));
        let mut pairs = vec![(h, minus_h), (h, h), (minus_h, [[l; 4]; 4])];
        let mut rng = SplitMix(7);
        for range in [10, l] {
            for _ in 0..100 {
                pairs.push((
                    random_matrix(&mut rng, range),
                    random_matrix(&mut rng, range),
                ));
            }
        }
        let poly = |c: &[i128]| Poly::new(c.iter().map(|&v| IBig::from(v)).collect());
        for (a, b) in pairs {
            let sym = |m| SymMatrix4::from_i64(m).expect("symmetric");
            let exact = MatrixPencil::new(sym(a), sym(b)).principal_minor_sums();
            // both routes (the direct one answers below 2²²), as the fast path reads them
            for s in [minor_sums(&a, &b), minor_sums_of_members(&a, &b)] {
                let got = [
                    poly(&s[0][..2]),
                    poly(&s[1][..3]),
                    poly(&s[2][..4]),
                    poly(&s[3]),
                ];
                assert_eq!(got, exact, "A = {a:?}, B = {b:?}");
                // the degrees the fast path reads: nothing above them
                assert!(s[0][2..]
                    .iter()
                    .chain(&s[1][3..])
                    .chain(&s[2][4..])
                    .all(|&v| v == 0));
            }
        }
    }

    /// The precondition is checked: an entry of 2²⁴ or more sends the pair to the exact path
    /// (unchecked, 2⁴⁰ overflows `i128`), one just below is decided.
    #[test]
    fn entries_beyond_the_limit_fall_back() {
        let limit = ENTRY_LIMIT as i64;
        let b = diagonal([1, 5, -7, 11]);
        let a = diagonal([limit - 1, 1, 2, 3]);
        assert_eq!(classify_simple_roots(&a, &b), exact_case(a, b));
        assert!(classify_simple_roots(&a, &b).is_some());
        for big in [limit, -limit, 1 << 40, i64::MIN] {
            let a = diagonal([big, 1, 2, 3]);
            assert_eq!(classify_simple_roots(&a, &b), None, "{big}");
            assert_eq!(classify_simple_roots(&b, &a), None, "{big}");
        }
    }

    /// `det A = 0` (a root at ∞) and a double root are the exact path's.
    #[test]
    fn leaves_singular_a_and_multiple_roots_to_the_exact_path() {
        let b = diagonal([1, 5, -7, 11]);
        assert_eq!(classify_simple_roots(&diagonal([0, 1, 2, 3]), &b), None);
        // roots 1, 1, −7/2, 11/3
        let a = diagonal([1, 5, 2, 3]);
        assert_eq!(classify_simple_roots(&a, &b), None);
    }
}
