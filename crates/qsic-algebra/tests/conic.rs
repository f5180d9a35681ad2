//! Rational points on conics against an independent decision: Hilbert symbols `(−ac, −bc)_p`
//! computed from Serre's formulas with quadratic residues found by brute force, on a
//! diagonalization by leading principal minors (not the module's pivoting).

use proptest::prelude::*;
use qsic_algebra::conic::{find_point, parameterize, solve_legendre, ConicError, ConicPoint};
use qsic_algebra::factor::{is_prime, FactorError};
use qsic_algebra::field::Quadratic;
use qsic_algebra::{IBig, RBig, Ring};

type Mat = [[RBig; 3]; 3];

fn r(v: i64) -> RBig {
    RBig::from(v)
}

fn mat(m: [[i64; 3]; 3]) -> Mat {
    m.map(|row| row.map(r))
}

fn diag(a: i64, b: i64, c: i64) -> Mat {
    mat([[a, 0, 0], [0, b, 0], [0, 0, c]])
}

fn form(c: &Mat, x: &[RBig; 3]) -> RBig {
    let mut v = RBig::ZERO;
    for i in 0..3 {
        for j in 0..3 {
            v += &c[i][j] * &x[i] * &x[j];
        }
    }
    v
}

fn form_quadratic(c: &Mat, x: &[Quadratic; 3]) -> Quadratic {
    let mut v = Quadratic::zero();
    for i in 0..3 {
        for j in 0..3 {
            let cij = Quadratic::rational(c[i][j].clone());
            v = &v + &(&(&cij * &x[i]) * &x[j]);
        }
    }
    v
}

/// `true` if `x = k·y` for some rational `k` (both nonzero).
fn proportional(x: &[RBig; 3], y: &[RBig; 3]) -> bool {
    (0..3).all(|i| (0..3).all(|j| &x[i] * &y[j] == &x[j] * &y[i]))
}

// ---- the independent criterion -------------------------------------------------------------

fn primes_of(mut n: i128) -> Vec<i128> {
    n = n.abs();
    let mut out = Vec::new();
    let mut d = 2;
    while d * d <= n {
        if n % d == 0 {
            out.push(d);
            while n % d == 0 {
                n /= d;
            }
        }
        d += 1;
    }
    if n > 1 {
        out.push(n);
    }
    out
}

/// Legendre symbol `(u/p)` for odd `p ∤ u`, by listing the squares (small `p`) or Euler's
/// criterion.
fn legendre_symbol(u: i128, p: i128) -> i32 {
    let u = u.rem_euclid(p);
    if p < 2000 {
        return if (1..p).any(|x| x * x % p == u) {
            1
        } else {
            -1
        };
    }
    let (mut acc, mut b, mut e) = (1i128, u, (p - 1) / 2);
    while e > 0 {
        if e & 1 == 1 {
            acc = acc * b % p;
        }
        b = b * b % p;
        e >>= 1;
    }
    if acc == 1 {
        1
    } else {
        -1
    }
}

fn split(mut a: i128, p: i128) -> (u32, i128) {
    let mut k = 0;
    while a % p == 0 {
        a /= p;
        k += 1;
    }
    (k, a)
}

/// The Hilbert symbol `(a, b)_p` (Serre, A Course in Arithmetic, III.1.2); `p = 0` is ∞.
fn hilbert(a: i128, b: i128, p: i128) -> i32 {
    if p == 0 {
        return if a < 0 && b < 0 { -1 } else { 1 };
    }
    let (al, u) = split(a, p);
    let (be, v) = split(b, p);
    if p == 2 {
        let eps = |x: i128| ((x.rem_euclid(4) - 1) / 2) as u32;
        let omega = |x: i128| {
            let x = x.rem_euclid(8);
            ((x * x - 1) / 8 % 2) as u32
        };
        let e = eps(u) * eps(v) + al * omega(v) + be * omega(u);
        return if e % 2 == 0 { 1 } else { -1 };
    }
    let mut s = if (al * be) % 2 == 1 && (p - 1) / 2 % 2 == 1 {
        -1
    } else {
        1
    };
    if be % 2 == 1 {
        s *= legendre_symbol(u, p);
    }
    if al % 2 == 1 {
        s *= legendre_symbol(v, p);
    }
    s
}

/// `a x² + b y² + c z² = 0` has a nonzero rational solution (all of `a, b, c` nonzero).
fn solvable(a: i128, b: i128, c: i128) -> bool {
    let (u, v) = (-a * c, -b * c);
    let mut places = primes_of(2 * a * b * c);
    places.push(0);
    places.into_iter().all(|p| hilbert(u, v, p) == 1)
}

/// The independent answer for a symmetric integer matrix with nonzero leading minors:
/// `Some(solvable)`, or `None` when `D₁` or `D₂` vanishes.
fn det(m: &[[i64; 3]; 3]) -> i64 {
    m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
}

fn solvable_by_minors(m: &[[i64; 3]; 3]) -> Option<bool> {
    let d3 = det(m) as i128;
    let m = m.map(|row| row.map(|v| v as i128));
    let d1 = m[0][0];
    let d2 = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    if d1 == 0 || d2 == 0 || d3 == 0 {
        return None;
    }
    // d = (D₁, D₂/D₁, D₃/D₂), the same square classes as (D₁, D₁D₂, D₂D₃).
    Some(solvable(d1, d1 * d2, d2 * d3))
}

// ---- checks on an answer ----------------------------------------------------------------------

/// The square-free part of a nonzero integer (sign kept).
fn squarefree_part(n: i128) -> i128 {
    let mut out = n.signum();
    for p in primes_of(n) {
        if split(n, p).0 % 2 == 1 {
            out *= p;
        }
    }
    out
}

fn is_squarefree(n: &IBig) -> bool {
    let n = i128::try_from(n).unwrap();
    primes_of(n).iter().all(|p| n % (p * p) != 0)
}

/// Checks the answer's own claims; returns `Some(true)` for a rational point, `Some(false)` for
/// none over ℚ, `None` for no real point.
fn check_answer(c: &Mat, answer: &ConicPoint) -> Option<bool> {
    match answer {
        ConicPoint::Rational(x) => {
            assert!(x.iter().any(|v| !v.is_zero()), "{c:?}: zero point");
            assert_eq!(form(c, x), RBig::ZERO, "{c:?}: {x:?} not on the conic");
            Some(true)
        }
        ConicPoint::NoRationalPoint(q) => {
            assert!(
                q.delta > IBig::ONE && is_squarefree(&q.delta),
                "{c:?}: δ = {}",
                q.delta
            );
            assert!(
                q.coords.iter().any(|v| !v.radical_part().is_zero()),
                "{c:?}: rational"
            );
            for v in &q.coords {
                assert!(v.radical_part().is_zero() || v.radicand() == &q.delta);
            }
            assert!(
                form_quadratic(c, &q.coords).is_zero(),
                "{c:?}: {q:?} not on the conic"
            );
            Some(false)
        }
        ConicPoint::Undecided(q) => panic!("{c:?}: small coefficients left undecided: {q:?}"),
        ConicPoint::NoRealPoint => None,
    }
}

/// Checks a parameterization through `p`: `XᵀCX ≡ 0` as a polynomial in `s, t`, `(1 : 0)` gives
/// `p`, and `parameter_of` inverts `point_at` on a few parameters.
fn check_parameterization(c: &Mat, p: &[RBig; 3]) {
    let par = parameterize(c, p).unwrap();
    let f = par.forms();
    // Σ Cᵢⱼ Xᵢ Xⱼ: a binary quartic, coefficients of s⁴, s³t, …, t⁴.
    let mut quartic: [RBig; 5] = Default::default();
    for i in 0..3 {
        for j in 0..3 {
            for a in 0..3 {
                for b in 0..3 {
                    quartic[a + b] += &c[i][j] * RBig::from(&f[i][a] * &f[j][b]);
                }
            }
        }
    }
    assert!(
        quartic.iter().all(|v| v.is_zero()),
        "{c:?}: XᵀCX = {quartic:?}"
    );
    assert!(
        proportional(&par.point_at(&r(1), &r(0)), p),
        "{c:?}: X(1, 0) is not {p:?}"
    );
    assert_eq!(par.parameter_of(p), Some([r(1), r(0)]));
    let mut seen: Vec<[RBig; 3]> = vec![p.clone()];
    for (s, t) in [(0, 1), (1, 1), (-1, 1), (2, 1), (1, 2), (-3, 5), (7, -2)] {
        let x = par.point_at(&r(s), &r(t));
        assert!(x.iter().any(|v| !v.is_zero()), "{c:?}: X({s}, {t}) = 0");
        assert_eq!(form(c, &x), RBig::ZERO);
        let st = par.parameter_of(&x).unwrap();
        assert_eq!(
            &st[0] * r(t),
            &st[1] * r(s),
            "{c:?}: parameter of X({s}, {t}) is {st:?}"
        );
        assert!(
            !seen.iter().any(|y| proportional(y, &x)),
            "{c:?}: X({s}, {t}) repeats a point"
        );
        seen.push(x);
    }
}

// ---- tests ----------------------------------------------------------------------------------

#[test]
fn known_diagonal_answers() {
    // (a, b, c, has a rational point): by hand and by Legendre's criterion.
    let cases = [
        (1, 1, -1, true),
        (1, 1, -2, true),
        (1, 1, -3, false),
        (1, 1, -5, true),
        (1, 1, -7, false),
        (3, -5, 7, false),  // −bc = 35 ≡ 2 is no square modulo 3
        (3, -5, -7, true),  // (2, 1, 1)
        (2, -3, -5, true),  // (2, 1, 1)
        (1, -2, -3, false), // −ab = 2 is no square modulo 3
        (5, 3, -1, false),  // −bc = 3 is no square modulo 5
        (7, 11, -13, false),
        (1, 5, -3, false), // 3 is no square modulo 5; δ = 3 (pair (1, −3)), not 15
    ];
    for (a, b, c, want) in cases {
        let expect = solvable(a, b, c);
        assert_eq!(expect, want, "the reference criterion on ({a}, {b}, {c})");
        let m = diag(a as i64, b as i64, c as i64);
        let answer = find_point(&m).unwrap();
        assert_eq!(
            check_answer(&m, &answer),
            Some(expect),
            "({a}, {b}, {c}): {answer:?}"
        );
        let sol = solve_legendre(&IBig::from(a), &IBig::from(b), &IBig::from(c)).unwrap();
        assert_eq!(sol.is_some(), expect);
    }
    // x² + y² − 3z²: δ = 3, from the pair (1, −3).
    let ConicPoint::NoRationalPoint(q) = find_point(&diag(1, 1, -3)).unwrap() else {
        panic!("x² + y² − 3z² has no rational point")
    };
    assert_eq!(q.delta, IBig::from(3));
    let ConicPoint::NoRationalPoint(q) = find_point(&diag(1, 5, -3)).unwrap() else {
        panic!("x² + 5y² − 3z² has no rational point")
    };
    assert_eq!(q.delta, IBig::from(3));
}

#[test]
fn definite_conics_have_no_real_point() {
    for m in [
        [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
        [[-1, 0, 0], [0, -2, 0], [0, 0, -3]],
        [[2, 1, 0], [1, 2, 1], [0, 1, 2]],
        [[-2, -1, 0], [-1, -2, -1], [0, -1, -2]],
        [[0, 0, 0], [0, 0, 0], [0, 0, 0]],
    ] {
        let c = mat(m);
        if m[0][0] == 0 {
            assert_eq!(find_point(&c), Err(ConicError::ZeroMatrix));
        } else {
            assert_eq!(find_point(&c).unwrap(), ConicPoint::NoRealPoint, "{m:?}");
        }
    }
}

#[test]
fn degenerate_conics_give_their_rational_singular_point() {
    let outer = |u: [i64; 3], v: [i64; 3]| -> [[i64; 3]; 3] {
        std::array::from_fn(|i| std::array::from_fn(|j| u[i] * v[j] + v[i] * u[j]))
    };
    let cases = [
        (diag(1, -1, 0), 2),
        (diag(1, 1, 0), 2), // two complex lines through the real point (0, 0, 1)
        (diag(0, 3, 0), 1),
        (mat(outer([1, 2, -1], [3, 0, 1])), 2), // the lines x + 2y − z = 0 and 3x + z = 0
        (mat(outer([1, 2, -1], [1, 2, -1])), 1), // the double line x + 2y − z = 0
        (mat([[1, 1, 1], [1, 1, 1], [1, 1, 1]]), 1),
    ];
    for (c, rank) in cases {
        let ConicPoint::Rational(x) = find_point(&c).unwrap() else {
            panic!("{c:?}")
        };
        check_answer(&c, &ConicPoint::Rational(x.clone()));
        // A singular point: Cx = 0.
        for row in &c {
            let v = (0..3).fold(RBig::ZERO, |acc, j| acc + &row[j] * &x[j]);
            assert!(v.is_zero(), "{c:?}: {x:?} is not singular");
        }
        if rank == 2 {
            assert_eq!(parameterize(&c, &x), Err(ConicError::Degenerate));
        }
    }
}

#[test]
fn large_coefficients_with_a_planted_point() {
    // c = −(a x² + b y²) makes (x, y, 1) a point; the solver must find one (maybe another).
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut next = |bits: u32| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> (64 - bits)) as i64 + 1
    };
    for _ in 0..12 {
        let (a, b) = (next(30), -next(28));
        let (x, y) = (next(16), next(16));
        let c = -(a as i128 * (x * x) as i128 + b as i128 * (y * y) as i128);
        let m = mat([[a, 0, 0], [0, b, 0], [0, 0, 0]]);
        let mut m = m;
        m[2][2] = RBig::from(IBig::from(c));
        let answer = find_point(&m).unwrap();
        assert_eq!(check_answer(&m, &answer), Some(true), "({a}, {b}, {c})");
        let ConicPoint::Rational(p) = answer else {
            unreachable!()
        };
        check_parameterization(&m, &p);
    }
}

/// The least prime `p ≥ start` with `p ≡ r (mod 4)` (proven primes: below 2⁸¹).
fn prime_from(start: u128, r: u128) -> u128 {
    (start..)
        .find(|&p| p % 4 == r && is_prime(p))
        .expect("a prime")
}

/// `C` moved by an integer map: `PᵀCP` has the points `P⁻¹x`, the same answer to "is there a
/// rational point", and none of the diagonal's numbers in plain sight.
fn disguised(c: &Mat) -> Mat {
    let p = mat([[2, -1, 3], [1, 1, -2], [-1, 4, 1]]); // det 30
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let mut v = RBig::ZERO;
            for k in 0..3 {
                for l in 0..3 {
                    v += &p[k][i] * &c[k][l] * &p[l][j];
                }
            }
            v
        })
    })
}

/// A point over ℚ or ℚ(√δ) exactly on the conic, whatever the answer claims.
fn on_conic(c: &Mat, answer: &ConicPoint) -> bool {
    match answer {
        ConicPoint::Rational(x) => x.iter().any(|v| !v.is_zero()) && form(c, x).is_zero(),
        ConicPoint::NoRationalPoint(q) | ConicPoint::Undecided(q) => {
            q.delta > IBig::ONE
                && Quadratic::sqrt(&q.delta).as_rational().is_none()
                && q.coords.iter().any(|v| !v.radical_part().is_zero())
                && form_quadratic(c, &q.coords).is_zero()
        }
        ConicPoint::NoRealPoint => false,
    }
}

/// Coefficients with a 160-bit semiprime cofactor `N = p·q` (two 80-bit primes, no factoring
/// within reach): every answer is a point exactly on the conic, never an error; a rational one
/// where the construction gives one and the roots modulo `N` come for free, "no rational point"
/// only where it is proven (by 3, or by the Jacobi symbol of `N` itself), and otherwise a
/// point over ℚ(√δ) with `N` under the radical.
#[test]
fn large_semiprime_cofactors_still_get_a_verified_point() {
    let p = prime_from(1 << 79, 3);
    let q1 = prime_from((1 << 79) + (1 << 60), 1);
    let q3 = prime_from((1 << 79) + (1 << 60), 3);
    let n_mixed = RBig::from(IBig::from(p) * IBig::from(q1)); // (−1/N) = −1
    let n_same = RBig::from(IBig::from(p) * IBig::from(q3)); // (−1/N) = +1, yet −1 no square
    let d = |a: &RBig, b: &RBig, c: &RBig| -> Mat {
        let z = RBig::ZERO;
        [
            [a.clone(), z.clone(), z.clone()],
            [z.clone(), b.clone(), z.clone()],
            [z.clone(), z, c.clone()],
        ]
    };
    let one = RBig::ONE;
    // (conic, has a rational point: Some(bool) if the answer must decide it)
    let cases: Vec<(Mat, Option<bool>)> = vec![
        // N x² + y² − z²: the point (0, 1, 1); the root modulo N is 1
        (d(&n_mixed, &one, &-&one), Some(true)),
        // N x² − 2y² + 8z² (the 8 a square times 2): (0, 2, 1); the root modulo N is 1 again
        (d(&n_same, &-RBig::from(2), &RBig::from(8)), Some(true)),
        // N x² + y² − (N + 1) z²: the point (1, 1, 1), but N + 1 = 2^k·M and M a cofactor:
        // a point on the conic, rational or over ℚ(√M)
        (d(&n_mixed, &one, &-(&n_mixed + &one)), None),
        // x² + y² − N z²: no point, proven by (−1/N) = −1
        (d(&one, &one, &-&n_mixed), Some(false)),
        // x² + y² − 3N z²: no point, proven by 3
        (d(&one, &one, &-(RBig::from(3) * &n_same)), Some(false)),
        // x² + y² − N z² with (−1/N) = +1: no rational point, not decidable without p, q
        (d(&one, &one, &-&n_same), None),
        // N x² − y² − 2 z² with no cheap root: whatever it is, a point on the conic
        (d(&n_same, &-&one, &-RBig::from(2)), None),
    ];
    for (c, want) in cases {
        for (m, plain) in [(c.clone(), true), (disguised(&c), false)] {
            let answer = find_point(&m).unwrap();
            assert!(on_conic(&m, &answer), "{m:?}: {answer:?}");
            // the plain diagonal is decided; under the disguise the diagonal's numbers change
            // (other cofactors), and only the claims must hold
            let ok = match (want, &answer) {
                (Some(true), ConicPoint::Rational(_)) => true,
                (Some(false), ConicPoint::NoRationalPoint(_)) => true,
                (Some(true), ConicPoint::NoRationalPoint(_)) => false,
                (Some(false), ConicPoint::Rational(_)) => false,
                (_, ConicPoint::NoRealPoint) => false,
                _ => !plain || want.is_none(),
            };
            assert!(ok, "{m:?}: {answer:?}, expected {want:?}");
            if let ConicPoint::Rational(x) = &answer {
                check_parameterization(&m, x);
            }
        }
    }
    // x² + y² − N z² with (−1/N) = +1 has no rational point (−1 is no square modulo p):
    // the answer says it did not decide, and N stays under the radical
    let ConicPoint::Undecided(qp) = find_point(&d(&one, &one, &-&n_same)).unwrap() else {
        panic!("undecidable without factoring N")
    };
    assert_eq!(qp.delta, IBig::from(p) * IBig::from(q3));
}

#[test]
fn legendre_over_unfactored_cofactors() {
    // Two primes near 2⁶¹ and 2⁶⁴ (rho would need about 2³¹ steps): hard·x² + y² − z² is
    // solved all the same, its root modulo the cofactor being 1
    let hard = IBig::from((1u128 << 61) - 1) * IBig::from(u64::MAX as u128 - 58);
    let v = solve_legendre(&hard, &IBig::ONE, &IBig::from(-1))
        .unwrap()
        .unwrap();
    assert!((&hard * &v[0] * &v[0] + &v[1] * &v[1] - &v[2] * &v[2]).is_zero());
    // 65537⁹ (145 bits, no prime below 2¹⁶) is a perfect power of a prime: decided
    let big = IBig::from(65537).pow(9);
    let v = solve_legendre(&big, &IBig::ONE, &IBig::from(-1))
        .unwrap()
        .unwrap();
    assert!((&big * &v[0] * &v[0] + &v[1] * &v[1] - &v[2] * &v[2]).is_zero());
    let mut c = diag(1, 1, -1);
    c[0][0] = RBig::from(big);
    assert!(matches!(find_point(&c).unwrap(), ConicPoint::Rational(_)));
    // x² + y² − N z², N = p·q, p ≡ q ≡ 3 (mod 4): solve_legendre cannot answer without p, q
    let p = prime_from(1 << 79, 3);
    let q = prime_from((1 << 79) + (1 << 60), 3);
    let n = IBig::from(p) * IBig::from(q);
    assert_eq!(
        solve_legendre(&IBig::ONE, &IBig::ONE, &-n),
        Err(ConicError::Factor(FactorError::TooLarge { bits: 159 })) // 2¹⁵⁸ < N < 2¹⁵⁹
    );
}

#[test]
fn parameterization_errors() {
    let c = diag(1, 1, -1);
    assert_eq!(
        parameterize(&c, &[r(0), r(0), r(0)]),
        Err(ConicError::ZeroPoint)
    );
    assert_eq!(
        parameterize(&c, &[r(1), r(1), r(1)]),
        Err(ConicError::PointNotOnConic)
    );
    let mut bad = c.clone();
    bad[0][1] = r(1);
    assert_eq!(
        parameterize(&bad, &[r(1), r(0), r(1)]),
        Err(ConicError::NotSymmetric { row: 0, col: 1 })
    );
    assert_eq!(
        find_point(&bad),
        Err(ConicError::NotSymmetric { row: 0, col: 1 })
    );
    // Pythagorean triples with rational input and a rational point.
    let half = RBig::from_parts(IBig::ONE, 2u8.into());
    let c = [
        [half.clone(), r(0), r(0)],
        [r(0), half.clone(), r(0)],
        [r(0), r(0), -half],
    ];
    check_parameterization(
        &c,
        &[
            RBig::from_parts(IBig::from(3), 5u8.into()),
            r(4).clone() / r(5),
            r(1),
        ],
    );
}

/// Random invertible integer matrices: a product of elementary operations and a diagonal scaling.
fn disguise(c: &[[i64; 3]; 3], ops: &[(usize, usize, i64)], scales: [i64; 3]) -> Mat {
    let mut m: [[RBig; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|j| r((i == j) as i64)));
    for &(i, j, k) in ops {
        if i != j {
            for row in m.iter_mut() {
                let v = &row[j] * r(k);
                row[i] += v;
            }
        }
    }
    for (row, s) in m.iter_mut().zip(scales) {
        for v in row.iter_mut() {
            *v *= RBig::from_parts(IBig::from(s), 3u8.into());
        }
    }
    // Mᵀ C M
    let c = mat(*c);
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let mut v = RBig::ZERO;
            for k in 0..3 {
                for l in 0..3 {
                    v += &m[k][i] * &c[k][l] * &m[l][j];
                }
            }
            v
        })
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn diagonal_conics_agree_with_hilbert_symbols(a in -60i64..=60, b in -60i64..=60, c in -60i64..=60) {
        prop_assume!(a != 0 && b != 0 && c != 0);
        let m = diag(a, b, c);
        let answer = find_point(&m).unwrap();
        let got = check_answer(&m, &answer);
        let definite = (a > 0) == (b > 0) && (b > 0) == (c > 0);
        prop_assert_eq!(got, if definite { None } else { Some(solvable(a as i128, b as i128, c as i128)) });
        let sol = solve_legendre(&IBig::from(a), &IBig::from(b), &IBig::from(c)).unwrap();
        prop_assert_eq!(sol.is_some(), got == Some(true));
        match answer {
            ConicPoint::Rational(p) => check_parameterization(&m, &p),
            ConicPoint::NoRationalPoint(q) => {
                // The least square-free −aᵢaⱼ over the pairs of opposite signs.
                let v = [a as i128, b as i128, c as i128];
                let least = [(0, 1), (0, 2), (1, 2)]
                    .iter()
                    .filter(|&&(i, j)| v[i] * v[j] < 0)
                    .map(|&(i, j)| squarefree_part(-v[i] * v[j]))
                    .min()
                    .unwrap();
                prop_assert_eq!(q.delta, IBig::from(least));
            }
            ConicPoint::Undecided(_) | ConicPoint::NoRealPoint => {}
        }
    }

    #[test]
    fn symmetric_conics_agree_with_the_minor_route(e in prop::array::uniform6(-6i64..=6)) {
        let m = [[e[0], e[1], e[2]], [e[1], e[3], e[4]], [e[2], e[4], e[5]]];
        prop_assume!(e.iter().any(|&v| v != 0));
        let c = mat(m);
        let answer = find_point(&c).unwrap();
        let got = check_answer(&c, &answer);
        if let Some(want) = solvable_by_minors(&m) {
            let d1 = m[0][0];
            let d2 = m[0][0] * m[1][1] - m[0][1] * m[0][1];
            // Definite ⇔ D₂ > 0 and D₃ has D₁'s sign (Sylvester).
            let definite = d2 > 0 && (det(&m) > 0) == (d1 > 0);
            prop_assert_eq!(got, if definite { None } else { Some(want) }, "{:?}", m);
        }
        if let ConicPoint::Rational(p) = &answer {
            if det(&m) != 0 {
                check_parameterization(&c, p);
            }
        }
    }

    #[test]
    fn disguised_conics_keep_their_answer(
        idx in 0usize..8,
        ops in prop::collection::vec((0usize..3, 0usize..3, -3i64..=3), 0..6),
        scales in prop::array::uniform3(prop::sample::select(vec![-5i64, -2, -1, 1, 2, 3, 7])),
    ) {
        let bases = [(1, 1, -3), (1, 1, -2), (3, -5, 7), (3, -5, -7), (2, 3, 5), (1, -1, 6), (7, 11, -13), (1, 2, -17)];
        let (a, b, c) = bases[idx];
        let plain = find_point(&diag(a, b, c)).unwrap();
        let want = check_answer(&diag(a, b, c), &plain);
        let m = disguise(&[[a, 0, 0], [0, b, 0], [0, 0, c]], &ops, scales);
        let answer = find_point(&m).unwrap();
        prop_assert_eq!(check_answer(&m, &answer), want, "{:?}", m);
        if let ConicPoint::Rational(p) = answer {
            check_parameterization(&m, &p);
        }
    }
}
