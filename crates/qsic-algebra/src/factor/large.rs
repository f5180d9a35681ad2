//! Number theory on integers too large to factor: a coprime base of cofactors, perfect powers,
//! the Jacobi symbol and a square root modulo a cofactor that may be prime — none needs the
//! factors.
//!
//! * [`coprime_base`]: positive integers `n₁ … n_k` rewritten over pairwise coprime `b₁ … b_m`
//!   (gcd refinement: a pair with `g = gcd(x, y) > 1` becomes `g, x/g, y/g`; the product of the
//!   elements above 1 falls, so at most `log₂ Π nᵢ` refinements), each `nᵢ = Π b_j^{e_ij}`;
//! * [`perfect_power`]: `n = r^k` with `k` maximal, by integer `k`-th roots for the primes `k`
//!   up to `log₂ n / log₂ m`, `m` a lower bound on the prime factors of `n`, each root taken
//!   only when `n` is a `k`-th power residue modulo eight primes `p ≡ 1 (mod k)`;
//! * [`jacobi_big`]: `(a/n)` for any odd `n`, multiplicative in `n`: `−1` proves that `a` is
//!   no square modulo `n` (nor modulo any multiple of `n`), whatever `n`'s factors;
//! * [`sqrt_mod_cofactor`]: a root `r² ≡ a (mod n)` by Tonelli–Shanks as if `n` were prime,
//!   after one Fermat test; the root is checked by squaring, so it is a root whether `n` is
//!   prime or not, and `None` only means none was found.
//!
//! Costs: the Jacobi symbol is Euclid-like, `O(log² n)` word operations; a square root is
//! `O(log n)` modular products of `log n`-bit numbers (a few, plus one per bit of the 2-adic
//! valuation of `n − 1`), attempted only below [`SQRT_BITS`] bits.

use dashu_int::fast_div::ConstDivisor;
use dashu_int::ops::{BitTest, Gcd};
use dashu_int::UBig;

/// The largest cofactor (bits) whose square roots [`sqrt_mod_cofactor`] attempts.
pub const SQRT_BITS: usize = 4096;

/// Pairwise coprime integers `b > 1` with every `nᵢ > 0` of `ns` a product of their powers,
/// and those exponents (`exponents[i][j]` the power of `base[j]` in `ns[i]`).
///
/// # Examples
/// ```
/// use qsic_algebra::factor::large::coprime_base;
/// use qsic_algebra::UBig;
/// let ns = [UBig::from(12u8), UBig::from(18u8)];
/// let (base, exps) = coprime_base(&ns);
/// for (n, e) in ns.iter().zip(&exps) {
///     let prod: UBig = base.iter().zip(e).map(|(b, &k)| b.pow(k as usize)).product();
///     assert_eq!(&prod, n);
/// }
/// ```
pub fn coprime_base(ns: &[UBig]) -> (Vec<UBig>, Vec<Vec<u32>>) {
    let mut base: Vec<UBig> = ns.iter().filter(|n| **n > UBig::ONE).cloned().collect();
    'refine: loop {
        for i in 0..base.len() {
            for j in i + 1..base.len() {
                let g = (&base[i]).gcd(&base[j]);
                if g == UBig::ONE {
                    continue;
                }
                let (x, y) = (&base[i] / &g, &base[j] / &g);
                base.swap_remove(j);
                base.swap_remove(i);
                base.extend([g, x, y].into_iter().filter(|v| *v > UBig::ONE));
                continue 'refine;
            }
        }
        break;
    }
    // equal elements (g = x = y) are the same prime power: keep one
    base.sort();
    base.dedup();
    let exponents = ns
        .iter()
        .map(|n| {
            let mut rest = n.clone();
            base.iter()
                .map(|b| {
                    let mut e = 0;
                    while rest != UBig::ZERO && (&rest % b).is_zero() {
                        rest /= b;
                        e += 1;
                    }
                    e
                })
                .collect()
        })
        .collect();
    (base, exponents)
}

/// `(r, k)` with `n = r^k` and `k` maximal, for `n > 1` without prime factors below
/// `2^min_bits` (so `k ≤ log₂ n / min_bits`).
///
/// # Examples
/// ```
/// use qsic_algebra::factor::large::perfect_power;
/// use qsic_algebra::UBig;
/// let n = UBig::from(65537u32).pow(6);
/// assert_eq!(perfect_power(&n, 16), (UBig::from(65537u32), 6));
/// ```
pub fn perfect_power(n: &UBig, min_bits: usize) -> (UBig, u32) {
    let (mut r, mut k) = (n.clone(), 1u32);
    'root: loop {
        let most = r.bit_len() / min_bits.max(1);
        for e in (2..=most).filter(|&e| (2..e).take_while(|d| d * d <= e).all(|d| e % d != 0)) {
            if !power_residue_everywhere(&r, e) {
                continue;
            }
            let root = r.nth_root(e);
            if root.pow(e) == r {
                r = root;
                k *= e as u32;
                continue 'root;
            }
        }
        return (r, k);
    }
}

/// How many primes `p ≡ 1 (mod e)` [`power_residue_everywhere`] tries.
const POWER_SIEVE_PRIMES: usize = 8;

/// False when `n` is proven no `e`-th power (`e` prime): for primes `p = 2je + 1` below 2³²
/// not dividing `n`, an `e`-th power `n` has `n^((p−1)/e) ≡ 1 (mod p)`, and a non-power
/// passes each such `p` with probability about `1/e`. True (maybe a power) after
/// [`POWER_SIEVE_PRIMES`] passes; each test costs one reduction of `n` by a word, so the
/// `e`-th root (`O(M(log n))` per Newton step) is taken only for the rare survivors.
fn power_residue_everywhere(n: &UBig, e: usize) -> bool {
    let e = e as u64;
    let mut tried = 0;
    let mut p = 2 * e + 1;
    while tried < POWER_SIEVE_PRIMES && p < 1 << 32 {
        if super::is_prime(u128::from(p)) {
            let m: u64 = n % p;
            if m != 0 {
                tried += 1;
                if pow_mod_u64(m, (p - 1) / e, p) != 1 {
                    return false;
                }
            }
        }
        p += 2 * e;
    }
    true
}

/// `b^x mod m` for `m < 2³²` (products below 2⁶⁴).
fn pow_mod_u64(mut b: u64, mut x: u64, m: u64) -> u64 {
    debug_assert!(m < 1 << 32 && b < m);
    let mut r = 1 % m;
    while x > 0 {
        if x & 1 == 1 {
            r = r * b % m;
        }
        b = b * b % m;
        x >>= 1;
    }
    r
}

/// The Jacobi symbol `(a/n)` for an odd `n ≥ 1`: `0` when `gcd(a, n) > 1`, else `±1`.
///
/// # Panics
/// If `n` is even.
///
/// # Examples
/// ```
/// use qsic_algebra::factor::large::jacobi_big;
/// use qsic_algebra::UBig;
/// let n = UBig::from(7u8) * UBig::from(11u8);
/// assert_eq!(jacobi_big(&UBig::from(2u8), &n), -1); // (2/7)(2/11) = 1·(−1)
/// ```
pub fn jacobi_big(a: &UBig, n: &UBig) -> i8 {
    assert!(n.bit(0), "the Jacobi symbol needs an odd modulus");
    let (mut a, mut n) = (a % n, n.clone());
    let mut sign = 1i8;
    while !a.is_zero() {
        let t = a.trailing_zeros().unwrap_or(0);
        a >>= t;
        let n8: u64 = &n % 8u64;
        if t % 2 == 1 && (n8 == 3 || n8 == 5) {
            sign = -sign;
        }
        if (&a % 4u64) == 3 && n8 % 4 == 3 {
            sign = -sign;
        }
        let r = &n % &a;
        (a, n) = (r, a);
    }
    if n == UBig::ONE {
        sign
    } else {
        0
    }
}

/// A square root of `a` modulo the odd `n > 2` (module doc): `r` in `0..n` with
/// `r² ≡ a (mod n)`, checked; `None` when `n` fails a Fermat test, has more than
/// [`SQRT_BITS`] bits, `a` is no square modulo `n` by its Jacobi symbol, or the root found does
/// not square back (`n` composite).
///
/// # Examples
/// ```
/// use qsic_algebra::factor::large::sqrt_mod_cofactor;
/// use qsic_algebra::UBig;
/// let p = (UBig::ONE << 521) - UBig::ONE; // a Mersenne prime
/// let r = sqrt_mod_cofactor(&UBig::from(5u8), &p).unwrap();
/// assert_eq!((&r * &r) % &p, UBig::from(5u8));
/// ```
pub fn sqrt_mod_cofactor(a: &UBig, n: &UBig) -> Option<UBig> {
    if !n.bit(0) || *n <= UBig::from(2u8) || n.bit_len() > SQRT_BITS {
        return None;
    }
    let a = a % n;
    if a.is_zero() {
        return Some(a);
    }
    if jacobi_big(&a, n) != 1 {
        return None;
    }
    let ring = ConstDivisor::new(n.clone());
    let nm1 = n - UBig::ONE;
    if ring.reduce(UBig::from(2u8)).pow(&nm1) != ring.reduce(UBig::ONE) {
        return None; // composite
    }
    let one = ring.reduce(UBig::ONE);
    let am = ring.reduce(a.clone());
    let s = nm1.trailing_zeros().unwrap_or(0);
    let q = &nm1 >> s;
    let root = if s == 1 {
        // n ≡ 3 (mod 4): a^((n+1)/4)
        am.pow(&((n + UBig::ONE) >> 2))
    } else {
        let z = (2u32..10_000).find(|&z| jacobi_big(&UBig::from(z), n) == -1)?;
        let mut c = ring.reduce(UBig::from(z)).pow(&q);
        let mut t = am.pow(&q);
        let mut r = am.pow(&((&q + UBig::ONE) >> 1));
        let mut m = s;
        while t != one {
            let (mut i, mut t2) = (0, t.clone());
            while t2 != one {
                t2 = t2.sqr();
                i += 1;
                if i == m {
                    return None; // n is not prime
                }
            }
            let mut b = c.clone();
            for _ in 0..(m - i - 1) {
                b = b.sqr();
            }
            m = i;
            c = b.sqr();
            t = &t * &c;
            r = &r * &b;
        }
        r
    };
    let r = root.residue();
    ((&r * &r) % n == a).then_some(r)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coprime_base_rebuilds_every_number() {
        let p = |v: u64| UBig::from(v);
        let cases: Vec<Vec<UBig>> = vec![
            vec![p(12), p(18), p(35)],
            vec![p(65537) * p(65539), p(65539) * p(65543), p(65537).pow(3)],
            vec![p(1), p(97).pow(2), p(97)],
            vec![],
        ];
        for ns in cases {
            let (base, exps) = coprime_base(&ns);
            for i in 0..base.len() {
                assert!(base[i] > UBig::ONE);
                for j in i + 1..base.len() {
                    assert_eq!((&base[i]).gcd(&base[j]), UBig::ONE, "{base:?}");
                }
            }
            for (n, e) in ns.iter().zip(&exps) {
                let prod: UBig = base
                    .iter()
                    .zip(e)
                    .map(|(b, &k)| b.pow(k as usize))
                    .product();
                assert_eq!(&prod, n, "{base:?} {e:?}");
            }
        }
    }

    #[test]
    fn the_power_sieve_keeps_every_power_and_drops_most_others() {
        let mut dropped = 0;
        for (i, e) in [2usize, 3, 5, 7, 11, 13, 31, 61].into_iter().enumerate() {
            let r = (UBig::ONE << (40 + 17 * i)) + UBig::from(12345u32 + i as u32);
            assert!(power_residue_everywhere(&r.pow(e), e), "{r}^{e}");
            dropped += usize::from(!power_residue_everywhere(&(r.pow(e) + UBig::ONE), e));
        }
        assert!(dropped >= 7, "only {dropped} of 8 non-powers dropped");
        // a 40 000-bit number with no big power: every prime exponent up to 2 500 tried
        let n = (UBig::ONE << 40_000) + UBig::from(3u8);
        assert_eq!(perfect_power(&n, 16), (n.clone(), 1));
        let m = (UBig::ONE << 89) - UBig::ONE;
        assert_eq!(perfect_power(&m.pow(37), 16), (m, 37));
    }

    #[test]
    fn perfect_powers_and_non_powers() {
        let q = UBig::from(65537u32) * UBig::from(65539u32);
        assert_eq!(perfect_power(&q, 16), (q.clone(), 1));
        assert_eq!(perfect_power(&q.pow(15), 16), (q.clone(), 15));
        assert_eq!(perfect_power(&(q.pow(4) + UBig::ONE), 16).1, 1);
    }

    #[test]
    fn jacobi_big_matches_the_machine_symbol() {
        for n in (1u128..300).step_by(2) {
            for a in 0..70u128 {
                let want = crate::factor::jacobi(a, n);
                assert_eq!(
                    jacobi_big(&UBig::from(a), &UBig::from(n)),
                    want,
                    "({a}/{n})"
                );
            }
        }
    }

    #[test]
    fn square_roots_modulo_big_primes_and_none_for_composites() {
        let m127 = (UBig::ONE << 127) - UBig::ONE; // ≡ 3 (mod 4)
        let m521 = (UBig::ONE << 521) - UBig::ONE;
        let f = (UBig::ONE << 64) + UBig::ONE; // 2⁶⁴ + 1 = 274177 · 67280421310721
        let p25519 = (UBig::ONE << 255) - UBig::from(19u8); // ≡ 5 (mod 8)
                                                            // NIST P-224: p − 1 = 2⁹⁶·odd, Tonelli–Shanks with many steps
        let p224 = (UBig::ONE << 224) - (UBig::ONE << 96) + UBig::ONE;
        for n in [m127.clone(), m521.clone(), p25519, p224] {
            let mut squares = 0;
            for a in 2u32..60 {
                let a = UBig::from(a);
                match sqrt_mod_cofactor(&a, &n) {
                    Some(r) => {
                        assert_eq!((&r * &r) % &n, a);
                        squares += 1;
                    }
                    None => assert_eq!(jacobi_big(&a, &n), -1, "{a} mod {n}"),
                }
            }
            assert!(squares > 10);
        }
        // a square modulo a composite: any root returned squares back (none is expected)
        let a = UBig::from(3u8).pow(2) % &f;
        if let Some(r) = sqrt_mod_cofactor(&a, &(&m127 * &f)) {
            assert_eq!((&r * &r) % (&m127 * &f), a);
        }
        assert_eq!(sqrt_mod_cofactor(&UBig::from(9u8), &(&m127 * &m521)), None);
    }
}
