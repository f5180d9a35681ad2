//! Determinants over `ℤ[t]` by evaluation, interpolation and Chinese remaindering: the
//! accelerator beside Bareiss' elimination ([`det_bareiss`](super::minors::det_bareiss)),
//! which stays the reference.
//!
//! For an `n × n` matrix `M(t)` over `ℤ[t]`, `det M` has degree at most `D`, the smaller of
//! the sums of the largest degrees of the rows and of the columns, and every coefficient of
//! absolute value at most `H` ([`coefficient_bound_bits`]). Modulo a prime `p`, `det M mod p`
//! is interpolated from its values at `t = 0, 1, …, D` (each the determinant of a matrix over
//! `𝔽_p`, by Gaussian elimination: exact, whatever `p`); the residues modulo primes
//! `p₁ < … < p_k` below `2⁶¹` with `p₁⋯p_k > 2H` determine each coefficient in `(−H, H]`
//! (Garner's mixed radix form, then the symmetric residue). No prime is unlucky: a
//! determinant modulo `p` is the determinant's residue, and nothing else is reduced.
//!
//! **Cost.** For each of `k ≈ log₂ H / 60` primes: the reduction of every coefficient
//! (its limbs), the evaluation of every distinct entry at `D + 1` points, `D + 1` eliminations
//! of `n³/3` steps, Newton interpolation in `D²` steps; then `k²` steps per coefficient for the
//! remaindering. [`det_modular_within`] spends these as it runs, one prime at a time (a unit
//! is one word operation, as in [`crate::budget`]); [`modular_units`] is their total before
//! it starts, for a caller choosing between this and Bareiss.

use crate::budget::{Budget, Exhausted};
use crate::poly::Poly;
use crate::IBig;
use dashu_int::ops::{BitTest, UnsignedAbs};
use dashu_int::Sign as DSign;

/// The largest prime used, `2⁶¹ − 1` (a Mersenne prime); every prime used lies in
/// `(2⁶⁰, 2⁶¹)`, so `k` of them have a product above `2^(60k)` ([`primes_needed`]).
const TOP: u64 = (1 << 61) - 1;

/// Bits each prime contributes at least to the product of the moduli (`p > 2⁶⁰`).
const BITS_PER_PRIME: usize = 60;

/// `a·b mod p`.
#[inline(always)]
fn mul(a: u64, b: u64, p: u64) -> u64 {
    ((a as u128 * b as u128) % p as u128) as u64
}

/// `a^e mod p`.
fn pow(mut a: u64, mut e: u64, p: u64) -> u64 {
    let mut r = 1u64;
    while e > 0 {
        if e & 1 == 1 {
            r = mul(r, a, p);
        }
        a = mul(a, a, p);
        e >>= 1;
    }
    r
}

/// `a⁻¹ mod p` for a prime `p` and `a ≢ 0` (Fermat).
fn inv(a: u64, p: u64) -> u64 {
    debug_assert!(a % p != 0);
    pow(a, p - 2, p)
}

/// Miller–Rabin with the first twelve prime bases: a proof of primality below
/// `3.3·10²⁴` (Sorenson and Webster 2015), so for every `n < 2⁶⁴`.
fn is_prime(n: u64) -> bool {
    const BASES: [u64; 12] = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37];
    if n < 2 {
        return false;
    }
    for b in BASES {
        if n % b == 0 {
            return n == b;
        }
    }
    let (mut d, mut s) = (n - 1, 0);
    while d % 2 == 0 {
        d /= 2;
        s += 1;
    }
    'bases: for b in BASES {
        let mut x = pow(b, d, n);
        if x == 1 || x == n - 1 {
            continue;
        }
        for _ in 1..s {
            x = mul(x, x, n);
            if x == n - 1 {
                continue 'bases;
            }
        }
        return false;
    }
    true
}

/// The primes below `2⁶¹`, decreasing from `2⁶¹ − 1`; all above `2⁶⁰` for as many as any
/// determinant here asks (the primes in `(2⁶⁰, 2⁶¹)` number about `2⁶⁰/42`).
fn primes() -> impl Iterator<Item = u64> {
    (0..)
        .map(|i| TOP - 2 * i)
        .filter(|&n| is_prime(n))
        .inspect(|&p| debug_assert!(p > 1 << BITS_PER_PRIME))
}

/// `x mod p` for an integer given by its sign and words (least significant first).
fn reduce(x: &IBig, p: u64) -> u64 {
    let (sign, words) = x.as_sign_words();
    let r = words.iter().rev().fold(0u64, |r, &w| {
        (((r as u128) << 64 | w as u128) % p as u128) as u64
    });
    if sign == DSign::Negative && r != 0 {
        p - r
    } else {
        r
    }
}

/// The bound on `det M` in bits: `log₂ H` rounded up, where every coefficient of `det M` has
/// absolute value at most `H = min(∏ᵢ √(Σⱼ ‖mᵢⱼ‖₁²), the same over columns)`.
///
/// Why: on `|z| = 1` each `|mᵢⱼ(z)| ≤ ‖mᵢⱼ‖₁` (the sum of the absolute values of its
/// coefficients), so Hadamard's inequality bounds `|det M(z)|` by the product of the row (or
/// column) norms; and a coefficient `c_k = (1/2π)∫ det M(e^{iθ}) e^{−ikθ} dθ` of a
/// polynomial is at most its maximum on the unit circle.
pub fn coefficient_bound_bits(rows: &[Vec<Poly>]) -> usize {
    let n = rows.len();
    let norm1 = |p: &Poly| -> IBig {
        p.coeffs()
            .iter()
            .fold(IBig::ZERO, |s, c| s + IBig::from(c.unsigned_abs()))
    };
    let norms: Vec<Vec<IBig>> = rows.iter().map(|r| r.iter().map(norm1).collect()).collect();
    let product_bits = |by_rows: bool| -> usize {
        let product = (0..n)
            .map(|i| {
                (0..n).fold(IBig::ZERO, |s, j| {
                    let v = if by_rows { &norms[i][j] } else { &norms[j][i] };
                    s + v * v
                })
            })
            .fold(IBig::ONE, |acc, s| acc * s);
        // H² ≤ product < 2^bits, so H < 2^⌈bits/2⌉
        (&product).unsigned_abs().bit_len().div_ceil(2)
    };
    product_bits(true).min(product_bits(false))
}

/// The bound on `deg det M`: the smaller of the sums over rows, and over columns, of the
/// largest degree in that line; `None` if a line is zero (then `det M = 0`).
fn degree_bound(rows: &[Vec<Poly>]) -> Option<usize> {
    let n = rows.len();
    let line = |by_rows: bool| -> Option<usize> {
        (0..n)
            .map(|i| {
                (0..n)
                    .filter_map(|j| {
                        if by_rows {
                            rows[i][j].degree()
                        } else {
                            rows[j][i].degree()
                        }
                    })
                    .max()
            })
            .sum()
    };
    Some(line(true)?.min(line(false)?))
}

/// The number of primes above `2⁶⁰` whose product exceeds `2H` for `H < 2^bits`.
fn primes_needed(bits: usize) -> usize {
    (bits + 1).div_ceil(BITS_PER_PRIME).max(1)
}

/// The distinct entries of `rows` (by value) and, for each position, its index among them.
fn distinct_entries(rows: &[Vec<Poly>]) -> (Vec<&Poly>, Vec<Vec<usize>>) {
    let mut distinct: Vec<&Poly> = Vec::new();
    let index = rows
        .iter()
        .map(|r| {
            r.iter()
                .map(|e| match distinct.iter().position(|d| *d == e) {
                    Some(i) => i,
                    None => {
                        distinct.push(e);
                        distinct.len() - 1
                    }
                })
                .collect()
        })
        .collect();
    (distinct, index)
}

/// The units of one prime: the reduction of the coefficients, the evaluations, the
/// eliminations and the interpolation (module docs).
fn units_per_prime(distinct: &[&Poly], n: usize, degree: usize) -> u64 {
    let points = degree as u64 + 1;
    let (mut reduce, mut terms) = (0u64, 0u64);
    for e in distinct {
        for c in e.coeffs() {
            reduce = reduce.saturating_add(c.as_sign_words().1.len().max(1) as u64);
        }
        terms = terms.saturating_add(e.coeffs().len() as u64);
    }
    let n = n as u64;
    let eliminate = (n * n * n / 3).max(1);
    reduce
        .saturating_add(terms.saturating_mul(points))
        .saturating_add(points.saturating_mul(eliminate))
        .saturating_add(points.saturating_mul(points))
}

/// The units of the remaindering: `k²` word steps per coefficient (Garner), and as many to
/// form the integer from its mixed radix digits.
fn crt_units(primes: usize, degree: usize) -> u64 {
    let k = primes as u64;
    (degree as u64 + 1).saturating_mul(2 * k * k)
}

/// The units [`det_modular_within`] spends on `rows` (module docs), before it starts.
///
/// # Panics
/// If the rows do not form a square matrix.
pub fn modular_units(rows: &[Vec<Poly>]) -> u64 {
    let n = rows.len();
    assert!(rows.iter().all(|r| r.len() == n), "a square matrix");
    let Some(degree) = degree_bound(rows) else {
        return n as u64;
    };
    let k = primes_needed(coefficient_bound_bits(rows));
    let (distinct, _) = distinct_entries(rows);
    (k as u64)
        .saturating_mul(units_per_prime(&distinct, n, degree))
        .saturating_add(crt_units(k, degree))
}

/// The determinant modulo `p` of an `n × n` matrix over `𝔽_p`, by Gaussian elimination
/// (destroys `m`).
fn det_mod_p(m: &mut [u64], n: usize, p: u64) -> u64 {
    let mut det = 1u64;
    for col in 0..n {
        let Some(pivot) = (col..n).find(|&r| m[r * n + col] != 0) else {
            return 0;
        };
        if pivot != col {
            for j in col..n {
                m.swap(pivot * n + j, col * n + j);
            }
            det = p - det;
        }
        let d = m[col * n + col];
        det = mul(det, d, p);
        let d_inv = inv(d, p);
        for r in col + 1..n {
            let f = mul(m[r * n + col], d_inv, p);
            if f == 0 {
                continue;
            }
            for j in col + 1..n {
                let s = mul(f, m[col * n + j], p);
                let v = m[r * n + j];
                m[r * n + j] = if v >= s { v - s } else { v + p - s };
            }
        }
    }
    det
}

/// The coefficients (lowest first) of the polynomial of degree `≤ D` with values `v` at
/// `0, 1, …, D` (`D + 1 = v.len()`), modulo `p > D`: Newton's divided differences (the nodes
/// are `j` apart at level `j`), then the Newton form expanded.
fn interpolate(mut v: Vec<u64>, p: u64) -> Vec<u64> {
    let len = v.len();
    for j in 1..len {
        let inv_j = inv(j as u64, p);
        for i in (j..len).rev() {
            let d = if v[i] >= v[i - 1] {
                v[i] - v[i - 1]
            } else {
                v[i] + p - v[i - 1]
            };
            v[i] = mul(d, inv_j, p);
        }
    }
    // Σ v[j] ∏_{i<j} (t − i), by Horner from the top: c ← c·(t − j) + v[j]
    let mut c = vec![0u64; len];
    for j in (0..len).rev() {
        // c ← c·(t − j)
        let shift = (j as u64) % p;
        for i in (0..len).rev() {
            let lower = if i > 0 { c[i - 1] } else { 0 };
            let s = mul(c[i], shift, p);
            c[i] = if lower >= s { lower - s } else { lower + p - s };
        }
        c[0] = (c[0] + v[j]) % p;
    }
    c
}

/// `det M` modulo one prime, as the coefficients of a polynomial of degree `≤ degree`.
fn det_residues(distinct: &[&Poly], index: &[Vec<usize>], degree: usize, p: u64) -> Vec<u64> {
    let n = index.len();
    let reduced: Vec<Vec<u64>> = distinct
        .iter()
        .map(|e| e.coeffs().iter().map(|c| reduce(c, p)).collect())
        .collect();
    let mut values = Vec::with_capacity(degree + 1);
    let mut at = vec![0u64; distinct.len()];
    let mut m = vec![0u64; n * n];
    for x in 0..=degree as u64 {
        for (slot, e) in at.iter_mut().zip(&reduced) {
            *slot = e
                .iter()
                .rev()
                .fold(0u64, |acc, &c| (mul(acc, x, p) + c) % p);
        }
        for (i, row) in index.iter().enumerate() {
            for (j, &e) in row.iter().enumerate() {
                m[i * n + j] = at[e];
            }
        }
        values.push(det_mod_p(&mut m, n, p));
    }
    interpolate(values, p)
}

/// The integer in `(−P/2, P/2]`, `P = ∏ pᵢ`, with residues `r` modulo the primes `ps`
/// (Garner's mixed radix digits, then the symmetric residue).
fn crt(r: &[u64], ps: &[u64], inverses: &[Vec<u64>], product: &IBig, half: &IBig) -> IBig {
    let mut digits: Vec<u64> = Vec::with_capacity(ps.len());
    for ((&ri, &p), inv_i) in r.iter().zip(ps).zip(inverses) {
        // digit_i = (r_i − (d_0 + d_1 p_0 + … )) / (p_0⋯p_{i−1}) mod p_i
        let mut x = ri % p;
        for (&dj, &inv_ij) in digits.iter().zip(inv_i) {
            let d = dj % p;
            x = if x >= d { x - d } else { x + p - d };
            x = mul(x, inv_ij, p);
        }
        digits.push(x);
    }
    let mut v = IBig::ZERO;
    for (&p, &d) in ps.iter().zip(&digits).rev() {
        v = v * IBig::from(p) + IBig::from(d);
    }
    if &v > half {
        v - product
    } else {
        v
    }
}

/// The determinant of a square matrix over `ℤ[t]` (module docs), spending its units
/// ([`modular_units`]) as it goes: each prime's before its work, the remaindering's before
/// it; `1` for the empty matrix. Equal to [`det_bareiss`](super::minors::det_bareiss).
///
/// ```
/// # use qsic_algebra::{budget::Budget, linalg::modular::det_modular_within, Poly};
/// let p = |c: &[i64]| Poly::from_i64s(c);
/// // [[t, 1], [1, t]]: t² − 1
/// let rows = vec![vec![p(&[0, 1]), p(&[1])], vec![p(&[1]), p(&[0, 1])]];
/// assert_eq!(det_modular_within(&rows, &Budget::unlimited()), Ok(p(&[-1, 0, 1])));
/// ```
///
/// # Errors
/// [`Exhausted`] when the budget runs out.
///
/// # Panics
/// If the rows do not form a square matrix.
pub fn det_modular_within(rows: &[Vec<Poly>], budget: &Budget) -> Result<Poly, Exhausted> {
    let n = rows.len();
    assert!(rows.iter().all(|r| r.len() == n), "a square matrix");
    if n == 0 {
        return Ok(Poly::constant(IBig::ONE));
    }
    let Some(degree) = degree_bound(rows) else {
        budget.spend(n as u64)?;
        return Ok(Poly::zero());
    };
    let bits = coefficient_bound_bits(rows);
    let k = primes_needed(bits);
    let (distinct, index) = distinct_entries(rows);
    let per_prime = units_per_prime(&distinct, n, degree);
    let mut ps = Vec::with_capacity(k);
    let mut residues: Vec<Vec<u64>> = Vec::with_capacity(k);
    for p in primes().take(k) {
        budget.spend(per_prime)?;
        debug_assert!(p as usize > degree, "the nodes 0..=D are distinct modulo p");
        residues.push(det_residues(&distinct, &index, degree, p));
        ps.push(p);
    }
    budget.spend(crt_units(k, degree))?;
    // inverses[i][j] = p_j⁻¹ mod p_i (j < i)
    let inverses: Vec<Vec<u64>> = (0..k)
        .map(|i| (0..i).map(|j| inv(ps[j] % ps[i], ps[i])).collect())
        .collect();
    let product = ps.iter().fold(IBig::ONE, |acc, &p| acc * IBig::from(p));
    let half = &product >> 1;
    // the bound, at the constant: 2H < P, so the symmetric residue is the coefficient
    debug_assert!((&product).unsigned_abs().bit_len() > bits + 1);
    let coeffs = (0..=degree)
        .map(|c| {
            let r: Vec<u64> = residues.iter().map(|v| v[c]).collect();
            crt(&r, &ps, &inverses, &product, &half)
        })
        .collect();
    Ok(Poly::new(coeffs))
}

/// The coefficients (lowest first) modulo `p` of `a mod b` over `𝔽_p`, `b` with a nonzero
/// leading coefficient and no trailing zeros.
fn rem_mod_p(mut a: Vec<u64>, b: &[u64], p: u64) -> Vec<u64> {
    let db = b.len() - 1;
    let lead_inv = inv(b[db], p);
    while a.len() > db {
        let top = a.pop().expect("longer than b");
        if top == 0 {
            continue;
        }
        let f = mul(top, lead_inv, p);
        let shift = a.len() - db;
        for (j, &bj) in b[..db].iter().enumerate() {
            let s = mul(f, bj, p);
            let v = a[shift + j];
            a[shift + j] = if v >= s { v - s } else { v + p - s };
        }
    }
    while a.last() == Some(&0) {
        a.pop();
    }
    a
}

/// Whether `f ∈ ℤ[t][λ]` is square-free over `ℚ(t)`, certified by specialisations: `true`
/// if at some `t₀ ∈ {2, 3, 5, 7}`, modulo `p = 2⁶¹ − 1`, `f(λ; t₀)` keeps its degree in `λ`
/// and is coprime to its derivative over `𝔽_p`. (Were `f = g²h` over `ℚ(t)` with
/// `deg_λ g ≥ 1`, then by Gauss' lemma over `ℤ[t]` the specialisation that keeps the
/// degree keeps every factor's degree and `g(t₀)²` divides `f(t₀)` over `𝔽_p`.) `false`
/// proves nothing: the caller then computes the decomposition. Each try spends the
/// reduction of the coefficients and Horner at `t₀` (their words) and the gcd of degree 4.
///
/// # Errors
/// [`Exhausted`] when the budget runs out.
pub fn squarefree_by_specialisation(f: &Poly<Poly>, budget: &Budget) -> Result<bool, Exhausted> {
    let p = TOP;
    let Some(n) = f.degree() else {
        return Ok(false);
    };
    if n == 0 {
        return Ok(true);
    }
    let words: u64 = f
        .coeffs()
        .iter()
        .flat_map(|c| c.coeffs())
        .map(|c| c.as_sign_words().1.len().max(1) as u64 + 1)
        .sum();
    for t0 in [2u64, 3, 5, 7] {
        budget.spend(words.saturating_add((n as u64 + 1) * (n as u64 + 1)))?;
        let at: Vec<u64> = f
            .coeffs()
            .iter()
            .map(|c| {
                c.coeffs()
                    .iter()
                    .rev()
                    .fold(0u64, |acc, v| (mul(acc, t0, p) + reduce(v, p)) % p)
            })
            .collect();
        if at[n] == 0 {
            continue;
        }
        let derivative: Vec<u64> = (1..=n).map(|i| mul(at[i], i as u64 % p, p)).collect();
        // Euclid: the last nonzero remainder has degree 0 exactly when they are coprime
        let (mut a, mut b) = (at, derivative);
        while b.last() == Some(&0) {
            b.pop();
        }
        while !b.is_empty() {
            let r = rem_mod_p(a, &b, p);
            a = b;
            b = r;
        }
        if a.len() == 1 {
            return Ok(true);
        }
    }
    Ok(false)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::linalg::minors::det_bareiss;

    /// A pseudo-random matrix over `ℤ[t]` (xorshift), with zeros and repeated entries.
    fn matrix(seed: u64, n: usize, degree: usize, bits: u32) -> Vec<Vec<Poly>> {
        let mut s = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
        let mut next = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s
        };
        let coeff = |next: &mut dyn FnMut() -> u64| {
            let mut v = IBig::ZERO;
            for _ in 0..bits.div_ceil(60) {
                v = (v << 60) + IBig::from(next() >> 4);
            }
            let v = v >> (bits.div_ceil(60) as usize * 60 - bits as usize);
            if next() & 1 == 0 {
                -v
            } else {
                v
            }
        };
        let mut rows = Vec::new();
        for _ in 0..n {
            let mut row = Vec::new();
            for _ in 0..n {
                let kind = next() % 6;
                let d = (next() as usize) % (degree + 1);
                row.push(match kind {
                    0 => Poly::zero(),
                    _ => Poly::new((0..=d).map(|_| coeff(&mut next)).collect()),
                });
            }
            rows.push(row);
        }
        // a repeated entry, as in Sylvester matrices
        if n > 1 {
            rows[1][0] = rows[0][1].clone();
        }
        rows
    }

    #[test]
    fn modular_equals_bareiss_on_random_matrices() {
        let mut nonzero = 0;
        for seed in 0..60u64 {
            let n = 1 + (seed % 6) as usize;
            let bits = [3, 64, 200][(seed % 3) as usize];
            let rows = matrix(seed, n, 1 + (seed % 5) as usize, bits);
            let budget = Budget::unlimited();
            let got = det_modular_within(&rows, &budget).unwrap();
            assert_eq!(got, det_bareiss(rows.clone()), "seed {seed}");
            assert_eq!(budget.used(), modular_units(&rows), "seed {seed}: units");
            nonzero += usize::from(!got.is_zero());
        }
        assert!(nonzero > 40, "{nonzero}");
    }

    #[test]
    fn singular_and_sign_cases() {
        let p = Poly::from_i64s;
        // a zero row, a rank-1 matrix and the empty matrix
        let zero_row = vec![vec![p(&[1, 2]), p(&[3])], vec![Poly::zero(), Poly::zero()]];
        assert!(det_modular_within(&zero_row, &Budget::unlimited())
            .unwrap()
            .is_zero());
        let rank1 = vec![vec![p(&[1, 1]), p(&[2, 2])], vec![p(&[3, 3]), p(&[6, 6])]];
        assert!(det_modular_within(&rank1, &Budget::unlimited())
            .unwrap()
            .is_zero());
        assert_eq!(det_modular_within(&[], &Budget::unlimited()), Ok(p(&[1])));
        // a negative constant at the bound: det [[−2⁶⁰ − 1, 0], [0, 2⁶⁰]] needs two primes
        let big = IBig::ONE << 60;
        let rows = vec![
            vec![Poly::constant(-(&big + IBig::ONE)), Poly::zero()],
            vec![Poly::zero(), Poly::constant(big.clone())],
        ];
        assert_eq!(
            det_modular_within(&rows, &Budget::unlimited()).unwrap(),
            Poly::constant(-(&big + IBig::ONE) * &big)
        );
    }

    #[test]
    fn the_bound_holds_and_is_reached_by_a_diagonal() {
        // diag(3t + 4, …): |det| coefficients ≤ 7ⁿ, the bound ⌈log₂ 7ⁿ⌉ or one more
        let e = Poly::from_i64s(&[4, 3]);
        let rows: Vec<Vec<Poly>> = (0..3)
            .map(|i| {
                (0..3)
                    .map(|j| if i == j { e.clone() } else { Poly::zero() })
                    .collect()
            })
            .collect();
        let bits = coefficient_bound_bits(&rows);
        let det = det_bareiss(rows);
        let largest = det.coeffs().iter().map(|c| c.unsigned_abs()).max().unwrap();
        assert!(largest.bit_len() <= bits, "{largest} within 2^{bits}");
        assert!(bits <= 9, "343 = 7³ < 2⁹: {bits}");
    }

    #[test]
    fn a_small_budget_stops_before_the_first_prime() {
        let rows = matrix(7, 5, 4, 200);
        let units = modular_units(&rows);
        assert!(det_modular_within(&rows, &Budget::new(units - 1)).is_err());
        assert!(det_modular_within(&rows, &Budget::new(units)).is_ok());
        assert!(det_modular_within(&rows, &Budget::new(10)).is_err());
    }

    #[test]
    fn squarefree_certificates_only_for_squarefree_forms() {
        let p = Poly::from_i64s;
        // (λ − t)(λ − t − 1)(λ + 2t): square-free over ℚ(t)
        let l = |c: i64, d: i64| Poly::new(vec![p(&[c, d]), p(&[1])]);
        let squarefree = &(&l(0, -1) * &l(-1, -1)) * &l(0, 2);
        assert_eq!(
            squarefree_by_specialisation(&squarefree, &Budget::unlimited()),
            Ok(true)
        );
        // (λ − t)²(λ + 1): never certified
        let square = &(&l(0, -1) * &l(0, -1)) * &l(1, 0);
        assert_eq!(
            squarefree_by_specialisation(&square, &Budget::unlimited()),
            Ok(false)
        );
        // t·λ² − 2t·λ + t = t(λ − 1)²: a square whatever its content
        let scaled = Poly::new(vec![p(&[0, 1]), p(&[0, -2]), p(&[0, 1])]);
        assert_eq!(
            squarefree_by_specialisation(&scaled, &Budget::unlimited()),
            Ok(false)
        );
    }

    #[test]
    fn the_primes_are_primes_above_two_to_the_sixty() {
        let ps: Vec<u64> = primes().take(5).collect();
        assert_eq!(ps[0], (1 << 61) - 1);
        for w in ps.windows(2) {
            assert!(w[0] > w[1] && w[1] > 1 << 60);
        }
        assert!(!is_prime((1 << 61) - 3) || ps[1] == (1 << 61) - 3);
        assert!(is_prime(1_000_000_007) && !is_prime(1_000_000_007 * 3));
        // a strong pseudoprime to base 2
        assert!(!is_prime(2047));
    }
}
