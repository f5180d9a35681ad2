//! Integer factorization of bounded size, primality, Jacobi symbols and square roots modulo primes.
//!
//! [`factorize`] divides out every prime below `2¹⁶` ([`TRIAL_LIMIT`]); the cofactor left must
//! be below `2¹²⁸` (else [`FactorError::TooLarge`]) and is split by Pollard's rho with Brent's
//! cycle detection in Montgomery arithmetic, within [`RHO_BUDGET`] steps per call (else
//! [`FactorError::HardToFactor`]): never a hang. Costs: trial division is at most 6542
//! divisions of the input; rho finds a prime `p` in about `√p` steps of two 128-bit Montgomery
//! products (25–80 ns, so the whole budget is 0.4–1.4 s), which splits a cofactor whose second
//! largest prime is below about `2⁴⁴` and rarely a product of two primes above `2⁵⁰`.
//!
//! Primality ([`is_prime`]) is Miller–Rabin with the first 13 primes as bases, which is a proof
//! below `3.3·10²⁴ ≈ 2⁸¹` (Sorenson and Webster 2015); above that it is a strong probable-prime
//! test to 20 bases, with no composite known to pass it. Callers that need certainty check what
//! they derive from a prime (a square root is checked by squaring).

use dashu_int::ops::{BitTest, UnsignedAbs};
use dashu_int::{IBig, UBig};
use std::fmt;

pub mod large;

/// Primes below this are divided out by trial division.
pub const TRIAL_LIMIT: u32 = 1 << 16;

/// The most Pollard-rho steps one call of [`factorize`] may spend (module doc: costs).
pub const RHO_BUDGET: u64 = 1 << 24;

/// Below this, Miller–Rabin with the first 13 prime bases is deterministic.
pub const PROVEN_PRIME_BOUND: u128 = 3_317_044_064_679_887_385_961_981;

/// Why an integer was not factored.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FactorError {
    /// Zero has no factorization.
    Zero,
    /// After trial division the cofactor has `bits` bits, above 128.
    TooLarge {
        /// Bit length of the cofactor.
        bits: usize,
    },
    /// A composite cofactor of `bits` bits was not split within [`RHO_BUDGET`] steps.
    HardToFactor {
        /// Bit length of the composite.
        bits: u32,
    },
}

impl fmt::Display for FactorError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FactorError::Zero => write!(f, "cannot factor zero"),
            FactorError::TooLarge { bits } => write!(
                f,
                "a {bits}-bit cofactor without prime factors below 2^16 is too large to factor (limit 128 bits)"
            ),
            FactorError::HardToFactor { bits } => write!(
                f,
                "a {bits}-bit composite was not split within {RHO_BUDGET} Pollard-rho steps"
            ),
        }
    }
}

impl std::error::Error for FactorError {}

/// The factorization `n = ±∏ pᵢ^eᵢ`, primes increasing.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Factorization {
    /// `n < 0`.
    pub negative: bool,
    /// `(prime, exponent)`, primes strictly increasing, exponents ≥ 1.
    pub factors: Vec<(u128, u32)>,
}

impl Factorization {
    /// The product `±∏ pᵢ^eᵢ`.
    pub fn value(&self) -> IBig {
        let mut v = IBig::ONE;
        for &(p, e) in &self.factors {
            v *= IBig::from(p).pow(e as usize);
        }
        if self.negative {
            -v
        } else {
            v
        }
    }

    /// The square-free part `s` and the root `r` with `n = s·r²` (`s` keeps the sign of `n`).
    pub fn squarefree_split(&self) -> (Factorization, IBig) {
        let mut root = IBig::ONE;
        let mut factors = Vec::new();
        for &(p, e) in &self.factors {
            root *= IBig::from(p).pow((e / 2) as usize);
            if e % 2 == 1 {
                factors.push((p, 1));
            }
        }
        let part = Factorization {
            negative: self.negative,
            factors,
        };
        (part, root)
    }
}

/// The factorization of a nonzero integer.
///
/// # Errors
/// [`FactorError::Zero`] for 0; [`FactorError::TooLarge`] when the part of `|n|` without prime
/// factors below [`TRIAL_LIMIT`] has more than 128 bits; [`FactorError::HardToFactor`] when a
/// composite is not split within [`RHO_BUDGET`] steps.
///
/// # Examples
/// ```
/// use qsic_algebra::factor::factorize;
/// use qsic_algebra::IBig;
/// let f = factorize(&IBig::from(-360)).unwrap();
/// assert!(f.negative);
/// assert_eq!(f.factors, vec![(2, 3), (3, 2), (5, 1)]);
/// // Two primes near 2^31: split by rho.
/// let n = IBig::from(2147483647u64) * IBig::from(2147483629u64);
/// assert_eq!(factorize(&n).unwrap().factors, vec![(2147483629, 1), (2147483647, 1)]);
/// ```
pub fn factorize(n: &IBig) -> Result<Factorization, FactorError> {
    let mut budget = RHO_BUDGET;
    let partial = factorize_partial(n, &mut budget)?;
    match partial.cofactors.iter().map(UBig::bit_len).max() {
        None => Ok(Factorization {
            negative: partial.negative,
            factors: partial.factors,
        }),
        Some(bits) if bits > 128 => Err(FactorError::TooLarge { bits }),
        Some(bits) => Err(FactorError::HardToFactor { bits: bits as u32 }),
    }
}

/// What [`factorize_partial`] found: `n = ±∏ pᵢ^eᵢ · ∏ cⱼ`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PartialFactorization {
    /// `n < 0`.
    pub negative: bool,
    /// `(prime, exponent)`, primes strictly increasing, exponents ≥ 1.
    pub factors: Vec<(u128, u32)>,
    /// The parts not factored: each above 1 without prime factors below [`TRIAL_LIMIT`],
    /// either above `2¹²⁸` (not tested) or a composite below it that rho did not split.
    pub cofactors: Vec<UBig>,
}

/// The primes of a nonzero `n` that trial division below [`TRIAL_LIMIT`] and Pollard's rho on
/// a cofactor below `2¹²⁸` (spending at most `budget` steps, decremented) find, and what is
/// left unfactored: never an error for a number too large to factor.
///
/// # Errors
/// [`FactorError::Zero`] for 0.
///
/// # Examples
/// ```
/// use qsic_algebra::factor::factorize_partial;
/// use qsic_algebra::{IBig, UBig};
/// let big = (IBig::ONE << 521) - IBig::ONE; // no small factor, above 2¹²⁸
/// let f = factorize_partial(&(IBig::from(-12) * &big), &mut 1000).unwrap();
/// assert!(f.negative);
/// assert_eq!(f.factors, vec![(2, 2), (3, 1)]);
/// assert_eq!(f.cofactors, vec![(UBig::ONE << 521) - UBig::ONE]);
/// ```
pub fn factorize_partial(n: &IBig, budget: &mut u64) -> Result<PartialFactorization, FactorError> {
    if n.is_zero() {
        return Err(FactorError::Zero);
    }
    let negative = *n < IBig::ZERO;
    let mut big: UBig = n.unsigned_abs();
    let mut factors: Vec<(u128, u32)> = Vec::new();
    let primes = small_primes();
    // trial division in big integers while the cofactor has more than 128 bits, then in
    // machine words (one division instruction a prime below 2⁶⁴)
    // (four primes at a time: one big remainder by their product, below 2⁶⁴, then words)
    let mut next = 0;
    let mut m = 'big: loop {
        if let Ok(m) = u128::try_from(&big) {
            break m;
        }
        if next >= primes.len() {
            return Ok(PartialFactorization {
                negative,
                factors,
                cofactors: vec![big],
            });
        }
        let chunk = &primes[next..(next + 4).min(primes.len())];
        let product: u64 = chunk.iter().map(|&p| u64::from(p)).product();
        let r: u64 = &big % product;
        for &p in chunk {
            next += 1;
            if r % u64::from(p) != 0 {
                continue;
            }
            let (pb, mut e) = (UBig::from(p), 0);
            while &big % p == 0u32 {
                big /= &pb;
                e += 1;
            }
            factors.push((p as u128, e));
            if let Ok(m) = u128::try_from(&big) {
                break 'big m;
            }
        }
    };
    // `m mod p` in 64-bit divisions (one instruction each; a 128-bit remainder is a call of
    // some 60): `p < 2¹⁶`, so `(hi mod p)·2³²` fits, twice, for `m = hi·2⁶⁴ + lo`
    let rem = |m: u128, p: u128| -> u128 {
        let p = p as u64;
        let (hi, lo) = ((m >> 64) as u64, m as u64);
        if hi == 0 {
            return u128::from(lo % p);
        }
        let h = (((hi % p) << 32) % p) << 32;
        u128::from(((h % p) + lo % p) % p)
    };
    for &p in &primes[next..] {
        let p = u128::from(p);
        if p * p > m {
            break;
        }
        if rem(m, p) != 0 {
            continue;
        }
        let mut e = 0;
        while rem(m, p) == 0 {
            m /= p;
            e += 1;
        }
        factors.push((p, e));
    }
    let mut stack = vec![m];
    let mut large: Vec<u128> = Vec::new();
    let mut cofactors: Vec<UBig> = Vec::new();
    while let Some(q) = stack.pop() {
        if q == 1 {
            continue;
        }
        if q < (TRIAL_LIMIT as u128) * (TRIAL_LIMIT as u128) || is_prime(q) {
            large.push(q);
            continue;
        }
        match split(q, budget) {
            Some(d) => {
                stack.push(d);
                stack.push(q / d);
            }
            None => cofactors.push(UBig::from(q)),
        }
    }
    large.sort_unstable();
    for p in large {
        match factors.last_mut() {
            Some((last, e)) if *last == p => *e += 1,
            _ => factors.push((p, 1)),
        }
    }
    Ok(PartialFactorization {
        negative,
        factors,
        cofactors,
    })
}

/// The number of primes below [`TRIAL_LIMIT`].
const SMALL_PRIME_COUNT: usize = 6542;

/// The primes below [`TRIAL_LIMIT`], sieved when the crate is compiled (at run time the
/// sieve cost a first factorization 1.2 million instructions).
static SMALL_PRIMES: [u32; SMALL_PRIME_COUNT] = sieve();

const fn sieve() -> [u32; SMALL_PRIME_COUNT] {
    const N: usize = TRIAL_LIMIT as usize;
    let mut composite = [false; N];
    let mut primes = [0u32; SMALL_PRIME_COUNT];
    let (mut count, mut i) = (0, 2);
    while i < N {
        if !composite[i] {
            primes[count] = i as u32;
            count += 1;
            let mut j = i * i;
            while j < N {
                composite[j] = true;
                j += i;
            }
        }
        i += 1;
    }
    assert!(
        count == SMALL_PRIME_COUNT,
        "the count of primes below TRIAL_LIMIT"
    );
    primes
}

/// The primes below [`TRIAL_LIMIT`].
fn small_primes() -> &'static [u32] {
    &SMALL_PRIMES
}

/// Whether `n` is prime: a proof below [`PROVEN_PRIME_BOUND`], a strong probable-prime test to
/// 20 bases above it (module doc).
///
/// # Examples
/// ```
/// use qsic_algebra::factor::is_prime;
/// assert!(is_prime((1 << 61) - 1));
/// assert!(!is_prime(3215031751)); // a strong pseudoprime to bases 2, 3, 5, 7
/// ```
pub fn is_prime(n: u128) -> bool {
    const BASES: [u128; 20] = [
        2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71,
    ];
    if n < 2 {
        return false;
    }
    for &p in &BASES {
        if n % p == 0 {
            return n == p;
        }
    }
    let bases = if n < PROVEN_PRIME_BOUND {
        &BASES[..13]
    } else {
        &BASES[..]
    };
    let mont = Montgomery::new(n);
    let s = (n - 1).trailing_zeros();
    let d = (n - 1) >> s;
    let one = mont.one;
    let minus_one = n - one;
    'bases: for &b in bases {
        let mut x = mont.pow(mont.encode(b), d);
        if x == one || x == minus_one {
            continue;
        }
        for _ in 1..s {
            x = mont.mul(x, x);
            if x == minus_one {
                continue 'bases;
            }
        }
        return false;
    }
    true
}

/// The Jacobi symbol `(a/n)` for odd `n ≥ 1`: `0` when `gcd(a, n) > 1`, else `±1`; for a prime
/// `n` it is `1` exactly when `a` is a nonzero square modulo `n`.
///
/// # Panics
/// If `n` is even.
///
/// # Examples
/// ```
/// use qsic_algebra::factor::jacobi;
/// assert_eq!(jacobi(2, 7), 1); // 3² = 9 ≡ 2
/// assert_eq!(jacobi(3, 7), -1);
/// assert_eq!(jacobi(14, 7), 0);
/// ```
pub fn jacobi(a: u128, n: u128) -> i8 {
    assert!(n % 2 == 1, "the Jacobi symbol needs an odd modulus");
    let (mut a, mut n) = (a % n, n);
    let mut sign = 1i8;
    while a != 0 {
        let t = a.trailing_zeros();
        a >>= t;
        if t % 2 == 1 && (n % 8 == 3 || n % 8 == 5) {
            sign = -sign;
        }
        if a % 4 == 3 && n % 4 == 3 {
            sign = -sign;
        }
        (a, n) = (n % a, a);
    }
    if n == 1 {
        sign
    } else {
        0
    }
}

/// A square root of `a` modulo the prime `p` (Tonelli–Shanks), in `0..p`; `None` if `a` is not a
/// square modulo `p`, or if `p` is not prime and no root was found. A returned root `r`
/// always satisfies `r² ≡ a (mod p)`, prime or not.
///
/// # Examples
/// ```
/// use qsic_algebra::factor::sqrt_mod_prime;
/// let p = (1u128 << 61) - 1;
/// let r = sqrt_mod_prime(5, p).unwrap(); // 5 is a square modulo p (p ≡ ±1 mod 5)
/// assert_eq!((r * r) % p, 5);
/// assert_eq!(sqrt_mod_prime(3, 7), None);
/// ```
pub fn sqrt_mod_prime(a: u128, p: u128) -> Option<u128> {
    let a = a % p;
    if p == 2 || a == 0 {
        return Some(a);
    }
    if p % 2 == 0 || jacobi(a, p) != 1 {
        return None;
    }
    let mont = Montgomery::new(p);
    let s = (p - 1).trailing_zeros();
    let q = (p - 1) >> s;
    // A non-residue: the least one is small for primes (well below this bound for p < 2^128).
    let z = (2..10_000u128).find(|&z| jacobi(z, p) == -1)?;
    let am = mont.encode(a);
    let mut c = mont.pow(mont.encode(z), q);
    let mut t = mont.pow(am, q);
    let mut r = mont.pow(am, q.div_ceil(2));
    let mut m = s;
    while t != mont.one {
        // The least i with t^(2^i) = 1.
        let mut i = 0;
        let mut t2 = t;
        while t2 != mont.one {
            t2 = mont.mul(t2, t2);
            i += 1;
            if i == m {
                return None; // p is not prime
            }
        }
        let mut b = c;
        for _ in 0..(m - i - 1) {
            b = mont.mul(b, b);
        }
        m = i;
        c = mont.mul(b, b);
        t = mont.mul(t, c);
        r = mont.mul(r, b);
    }
    let r = mont.decode(r);
    (mont.decode(mont.mul(mont.encode(r), mont.encode(r))) == a).then_some(r)
}

/// A nontrivial factor of the odd composite `n`, spending at most `budget` rho steps.
fn split(n: u128, budget: &mut u64) -> Option<u128> {
    let mont = Montgomery::new(n);
    for c in 1u128.. {
        let cm = mont.encode(c);
        let f = |y: u128| mont.add(mont.mul(y, y), cm);
        let (mut x, mut y, mut ys) = (0u128, mont.encode(2), 0u128);
        let mut q = mont.one;
        let mut g = 1u128;
        let mut r = 1u64;
        const BATCH: u64 = 128;
        while g == 1 {
            x = y;
            for _ in 0..r {
                y = f(y);
            }
            let mut k = 0;
            while k < r && g == 1 {
                ys = y;
                let steps = BATCH.min(r - k);
                for _ in 0..steps {
                    y = f(y);
                    q = mont.mul(q, x.abs_diff(y));
                }
                g = gcd_u128(q, n);
                k += steps;
            }
            let spent = 2 * r;
            if *budget < spent {
                *budget = 0;
                return None;
            }
            *budget -= spent;
            r *= 2;
        }
        if g == n {
            // The batch overshot: step again one at a time from its start.
            loop {
                ys = f(ys);
                g = gcd_u128(x.abs_diff(ys), n);
                if g != 1 {
                    break;
                }
            }
        }
        if g != n {
            return Some(g);
        }
    }
    None
}

fn gcd_u128(mut a: u128, mut b: u128) -> u128 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// Arithmetic modulo an odd `n` in Montgomery form `x·2¹²⁸ mod n`.
struct Montgomery {
    n: u128,
    /// `−n⁻¹ mod 2¹²⁸`.
    n_neg_inv: u128,
    /// `2¹²⁸ mod n`, the form of 1.
    one: u128,
    /// `2²⁵⁶ mod n`.
    r2: u128,
}

impl Montgomery {
    fn new(n: u128) -> Montgomery {
        debug_assert!(n % 2 == 1 && n > 1);
        let mut inv = n; // correct to 3 bits; each Newton step doubles them
        for _ in 0..6 {
            inv = inv.wrapping_mul(2u128.wrapping_sub(n.wrapping_mul(inv)));
        }
        let one = (u128::MAX % n + 1) % n;
        let mut m = Montgomery {
            n,
            n_neg_inv: inv.wrapping_neg(),
            one,
            r2: 0,
        };
        let mut r2 = one;
        for _ in 0..128 {
            r2 = m.add(r2, r2);
        }
        m.r2 = r2;
        m
    }

    fn add(&self, a: u128, b: u128) -> u128 {
        let (s, over) = a.overflowing_add(b);
        if over || s >= self.n {
            s.wrapping_sub(self.n)
        } else {
            s
        }
    }

    /// `t·2⁻¹²⁸ mod n` for `t = hi·2¹²⁸ + lo < n·2¹²⁸`.
    fn redc(&self, hi: u128, lo: u128) -> u128 {
        let m = lo.wrapping_mul(self.n_neg_inv);
        let (mh, ml) = mul_wide(m, self.n);
        let carry = lo.overflowing_add(ml).1 as u128;
        let (s, o1) = hi.overflowing_add(mh);
        let (s, o2) = s.overflowing_add(carry);
        if o1 || o2 || s >= self.n {
            s.wrapping_sub(self.n)
        } else {
            s
        }
    }

    fn mul(&self, a: u128, b: u128) -> u128 {
        let (hi, lo) = mul_wide(a, b);
        self.redc(hi, lo)
    }

    fn encode(&self, a: u128) -> u128 {
        self.mul(a % self.n, self.r2)
    }

    fn decode(&self, a: u128) -> u128 {
        self.redc(0, a)
    }

    fn pow(&self, mut base: u128, mut e: u128) -> u128 {
        let mut acc = self.one;
        while e > 0 {
            if e & 1 == 1 {
                acc = self.mul(acc, base);
            }
            base = self.mul(base, base);
            e >>= 1;
        }
        acc
    }
}

/// The 256-bit product `a·b` as `(high, low)` halves.
fn mul_wide(a: u128, b: u128) -> (u128, u128) {
    let wide = |x: u64, y: u64| x as u128 * y as u128; // one machine multiplication
    let (a1, a0) = ((a >> 64) as u64, a as u64);
    let (b1, b0) = ((b >> 64) as u64, b as u64);
    let p00 = wide(a0, b0);
    let p01 = wide(a0, b1);
    let p10 = wide(a1, b0);
    let p11 = wide(a1, b1);
    let mid = (p00 >> 64) + (p01 as u64 as u128) + (p10 as u64 as u128);
    let lo = (p00 as u64 as u128) | (mid << 64);
    let hi = p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64);
    (hi, lo)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn is_prime_naive(n: u128) -> bool {
        n >= 2 && (2..).take_while(|d| d * d <= n).all(|d| n % d != 0)
    }

    #[test]
    fn mul_wide_matches_split_products() {
        let vals = [
            0u128,
            1,
            2,
            u64::MAX as u128,
            1 << 64,
            u128::MAX,
            u128::MAX - 12345,
            0xdead_beef_1234_5678_9abc_def0_1357_9bdf,
        ];
        for &a in &vals {
            for &b in &vals {
                let (hi, lo) = mul_wide(a, b);
                let big = IBig::from(a) * IBig::from(b);
                assert_eq!(big, (IBig::from(hi) << 128) + IBig::from(lo), "{a} * {b}");
            }
        }
    }

    #[test]
    fn montgomery_product_is_the_modular_product() {
        let moduli = [
            3u128,
            65537,
            (1 << 61) - 1,
            (1 << 127) - 1,
            u128::MAX,
            u128::MAX - 2,
            (1 << 127) + 1,
        ];
        let vals = [
            0u128,
            1,
            2,
            12345,
            u64::MAX as u128,
            u128::MAX / 3,
            u128::MAX - 1,
        ];
        for &n in &moduli {
            let m = Montgomery::new(n);
            for &a in &vals {
                for &b in &vals {
                    let want = IBig::from(a % n) * IBig::from(b % n) % IBig::from(n);
                    let got = m.decode(m.mul(m.encode(a), m.encode(b)));
                    assert_eq!(IBig::from(got), want, "{a} * {b} mod {n}");
                }
            }
        }
    }

    #[test]
    fn is_prime_agrees_with_trial_division() {
        for n in 0..20_000u128 {
            assert_eq!(is_prime(n), is_prime_naive(n), "{n}");
        }
        // Around 2^36, by trial division.
        for n in (1u128 << 36)..(1 << 36) + 200 {
            assert_eq!(is_prime(n), is_prime_naive(n), "{n}");
        }
        for n in [
            2047u128,
            1373653,
            25326001,
            3215031751,
            2152302898747,
            3474749660383,
            341550071728321,
            3825123056546413051,
        ] {
            assert!(!is_prime(n), "strong pseudoprime {n}");
        }
        // A 125-bit semiprime (beyond the proven range).
        assert!(!is_prime(((1u128 << 61) - 1) * (u64::MAX as u128 - 58)));
        for p in [
            (1u128 << 61) - 1,
            (1 << 89) - 1,
            (1 << 107) - 1,
            (1 << 127) - 1,
            u64::MAX as u128 - 58,
        ] {
            assert!(is_prime(p), "{p}");
            assert!(!is_prime(p + 1), "{p}");
            if let Some(m) = p.checked_mul(3) {
                assert!(!is_prime(m), "3·{p}");
            }
        }
    }

    #[test]
    fn jacobi_is_euler_criterion_for_primes() {
        for p in (3u128..400).filter(|&p| is_prime_naive(p)) {
            for a in 0..p {
                let squares: Vec<u128> = (1..p).map(|x| x * x % p).collect();
                let want = if a == 0 {
                    0
                } else if squares.contains(&a) {
                    1
                } else {
                    -1
                };
                assert_eq!(jacobi(a, p), want, "({a}/{p})");
            }
        }
        // Multiplicative in the modulus.
        for a in 0..60u128 {
            for (m, n) in [(3u128, 5u128), (7, 9), (15, 11), (21, 25)] {
                assert_eq!(
                    jacobi(a, m * n),
                    jacobi(a, m) * jacobi(a, n),
                    "({a}/{m}·{n})"
                );
            }
        }
    }

    #[test]
    fn square_roots_modulo_primes_square_back() {
        let primes = [
            2u128,
            3,
            5,
            17,
            97,
            257,
            65537,
            7681,
            (1 << 61) - 1,
            (1 << 89) - 1,
            (1 << 127) - 1,
        ];
        for &p in &primes {
            for a in (0..200u128).chain([p - 1, p / 2]) {
                let a = a % p;
                let r = sqrt_mod_prime(a, p);
                let is_square = a == 0 || p == 2 || jacobi(a, p) == 1;
                assert_eq!(r.is_some(), is_square, "{a} mod {p}");
                if let Some(r) = r {
                    let sq = IBig::from(r) * IBig::from(r) % IBig::from(p);
                    assert_eq!(sq, IBig::from(a), "{r}² ≢ {a} mod {p}");
                }
            }
        }
        // A Carmichael number is no prime: a root, if returned, is still a root.
        let n = 561u128;
        for a in 1..n {
            if let Some(r) = sqrt_mod_prime(a, n) {
                assert_eq!(r * r % n, a);
            }
        }
    }

    #[test]
    fn factorize_rebuilds_the_number_from_primes() {
        let cases: Vec<IBig> = vec![
            IBig::from(1),
            IBig::from(-1),
            IBig::from(2).pow(100) * IBig::from(3),
            IBig::from(65537u64).pow(3) * IBig::from(-7),
            IBig::from((1u128 << 61) - 1) * IBig::from(1_000_003u64) * IBig::from(1_000_033u64),
            IBig::from(4_294_967_291u64) * IBig::from(4_294_967_279u64) * IBig::from(101),
            IBig::from((1u128 << 89) - 1),
            IBig::from(999_999_000_001u64).pow(2),
            // small primes met while the cofactor is above 2⁶⁴ (the remainders by words)
            IBig::from(65521u64).pow(2) * IBig::from(40009u64) * IBig::from((1u128 << 89) - 1),
            IBig::from(3u64) * IBig::from(65519u64) * IBig::from((1u128 << 107) - 1),
            // and above 2¹²⁸ (four primes a big remainder), the last one leaving it mid-chunk
            IBig::from(2).pow(130) * IBig::from(3u64).pow(7) * IBig::from(40009u64),
            IBig::from(13u64) * IBig::from(65519u64).pow(3) * IBig::from((1u128 << 89) - 1),
            IBig::from(65521u64).pow(4) * IBig::from(17u64) * IBig::from((1u128 << 89) - 1),
        ];
        for n in cases {
            let f = factorize(&n).unwrap();
            assert_eq!(f.value(), n);
            assert!(f.factors.windows(2).all(|w| w[0].0 < w[1].0), "{n}: {f:?}");
            assert!(
                f.factors.iter().all(|&(p, e)| is_prime(p) && e >= 1),
                "{n}: {f:?}"
            );
        }
        assert_eq!(factorize(&IBig::ZERO), Err(FactorError::Zero));
    }

    /// Random products of primes below the trial limit and a prime above 2⁶¹: the factors
    /// found are the ones multiplied, whatever the size of the cofactor when each is met.
    #[test]
    fn small_factors_of_wide_cofactors() {
        let mut rng = crate::testing::SplitMix(29);
        let primes = small_primes();
        for _ in 0..200 {
            let mut want: Vec<(u128, u32)> = Vec::new();
            for _ in 0..(1 + rng.next_u64() % 4) {
                let p = u128::from(primes[(rng.next_u64() as usize) % primes.len()]);
                let e = 1 + (rng.next_u64() % 3) as u32;
                match want.iter_mut().find(|(q, _)| *q == p) {
                    Some((_, f)) => *f += e,
                    None => want.push((p, e)),
                }
            }
            want.push(((1 << 61) - 1, 1));
            want.sort_unstable();
            let n = want.iter().fold(IBig::ONE, |acc, &(p, e)| {
                acc * IBig::from(p).pow(e as usize)
            });
            if n.bit_len() > 128 {
                continue;
            }
            assert_eq!(factorize(&n).unwrap().factors, want, "{n}");
        }
    }

    #[test]
    fn squarefree_split_of_a_factorization() {
        let f = factorize(&IBig::from(-2 * 2 * 2 * 3 * 5 * 5 * 7)).unwrap();
        let (s, r) = f.squarefree_split();
        assert_eq!(s.value(), IBig::from(-2 * 3 * 7));
        assert_eq!(r, IBig::from(2 * 5));
    }

    #[test]
    fn oversized_inputs_are_errors() {
        // 65537 is above the trial limit: its ninth power is a 145-bit cofactor.
        let n = IBig::from(65537u64).pow(9);
        assert_eq!(factorize(&n), Err(FactorError::TooLarge { bits: 145 }));
        // (the rho budget is exercised by tests/conic.rs, too_large_or_hard_coefficients_are_errors)
    }
}
