//! Polynomial gcd over ℤ by the subresultant pseudo-remainder sequence.
//!
//! The subresultant PRS (Collins 1967, Brown–Traub 1971) keeps coefficient growth
//! linear in the degree without computing contents at each step ([`Poly::gcd_domain`], generic); the primitive PRS
//! (`gcd_primitive_prs`, in the tests) is the simpler second route they are compared with.

use super::Poly;
use dashu_int::IBig;

impl Poly {
    /// The primitive gcd with positive leading coefficient; `gcd(0, 0) = 0`.
    ///
    /// ```
    /// # use qsic_algebra::Poly;
    /// let a = Poly::from_roots(&[1, 2, 3]);
    /// let b = Poly::from_roots(&[2, 3, 5]);
    /// assert_eq!(a.gcd(&b), Poly::from_roots(&[2, 3]));
    /// ```
    pub fn gcd(&self, other: &Poly) -> Poly {
        // Coprime inputs with big coefficients (a square-free characteristic polynomial and
        // its derivative) are recognised modulo a prime instead of through a PRS whose
        // coefficients grow to millions of bits.
        if self.max_bits().max(other.max_bits()) > 128 && coprime_modular(self, other) {
            return Poly::constant(IBig::ONE);
        }
        gcd_subresultant(self, other)
    }
}

/// The Mersenne prime 2⁶¹ − 1.
const PRIME: u64 = (1 << 61) - 1;

/// `a·b mod p` for `a, b < p = 2⁶¹ − 1`: `2⁶¹ ≡ 1`, so the 122-bit product folds into
/// its low 61 bits plus the rest (below `2⁶²`), then once more and one subtraction.
fn mul_mod(a: u64, b: u64) -> u64 {
    let x = u128::from(a) * u128::from(b);
    let folded = (x as u64 & PRIME) + (x >> 61) as u64;
    let r = (folded & PRIME) + (folded >> 61);
    if r >= PRIME {
        r - PRIME
    } else {
        r
    }
}

fn inv_mod(a: u64) -> u64 {
    // a^(p−2) by square and multiply
    let (mut base, mut e, mut r) = (a, PRIME - 2, 1u64);
    while e > 0 {
        if e & 1 == 1 {
            r = mul_mod(r, base);
        }
        base = mul_mod(base, base);
        e >>= 1;
    }
    r
}

/// Coefficients modulo [`PRIME`], trailing zeros removed.
fn reduce(p: &Poly) -> Vec<u64> {
    let m = IBig::from(PRIME);
    let mut c: Vec<u64> = p
        .coeffs()
        .iter()
        .map(|v| {
            let r = v % &m;
            let r = if r < IBig::ZERO { r + &m } else { r };
            u64::try_from(r).expect("a residue modulo a 61-bit prime fits in u64")
        })
        .collect();
    while c.last() == Some(&0) {
        c.pop();
    }
    c
}

/// `true` only if `a` and `b` are certainly coprime over ℚ: the prime divides neither
/// leading coefficient and the gcd of the reductions is a constant. (Reduction can only
/// raise the degree of the gcd when the leading coefficients survive it.) `false` means
/// "not known" (always so when one of them is zero).
pub fn coprime_modular(a: &Poly, b: &Poly) -> bool {
    let (mut f, mut g) = (reduce(a), reduce(b));
    if f.len() != a.coeffs().len() || g.len() != b.coeffs().len() {
        return false;
    }
    // Euclid over 𝔽_p
    while g.len() > 1 {
        let inv = inv_mod(*g.last().expect("g is nonzero"));
        while f.len() >= g.len() {
            let shift = f.len() - g.len();
            let k = mul_mod(*f.last().expect("f is nonzero"), inv);
            for (j, gj) in g.iter().enumerate() {
                let t = mul_mod(k, *gj);
                let x = f[shift + j] + PRIME - t;
                f[shift + j] = if x >= PRIME { x - PRIME } else { x };
            }
            while f.last() == Some(&0) {
                f.pop();
            }
        }
        std::mem::swap(&mut f, &mut g);
    }
    g.len() == 1
}

/// Gcd by the subresultant PRS ([`Poly::gcd_domain`]) on the primitive parts.
fn gcd_subresultant(a: &Poly, b: &Poly) -> Poly {
    a.primitive_part()
        .gcd_domain(&b.primitive_part())
        .primitive_part()
}

/// Gcd by the primitive PRS (contents removed at every step): the tests' second route.
#[cfg(test)]
fn gcd_primitive_prs(a: &Poly, b: &Poly) -> Poly {
    let (mut f, mut g) = match (a.degree(), b.degree()) {
        (None, _) => return b.primitive_part(),
        (_, None) => return a.primitive_part(),
        (Some(da), Some(db)) if da >= db => (a.primitive_part(), b.primitive_part()),
        _ => (b.primitive_part(), a.primitive_part()),
    };
    loop {
        if g.is_zero() {
            return f.primitive_part();
        }
        if g.is_constant() {
            return Poly::constant(IBig::ONE);
        }
        let r = f.pseudo_rem(&g).primitive_part();
        f = g;
        g = r;
    }
}

#[cfg(test)]
mod modular_tests {
    use super::*;

    /// Coprime and non-coprime pairs with big coefficients: the shortcut never claims a
    /// common factor away, and the gcd is the same as the PRS's.
    /// The folded product is the remainder of the exact one, at the ends of the range too.
    #[test]
    fn mul_mod_is_the_remainder() {
        let mut rng = crate::testing::SplitMix(61);
        let mut values = vec![0, 1, 2, PRIME - 1, PRIME - 2, 1 << 60, (1 << 60) + 1];
        values.extend((0..200).map(|_| rng.next_u64() % PRIME));
        for &a in &values {
            for &b in values.iter().step_by(7) {
                let want = (u128::from(a) * u128::from(b) % u128::from(PRIME)) as u64;
                assert_eq!(mul_mod(a, b), want, "{a} · {b}");
            }
            if a != 0 {
                assert_eq!(mul_mod(a, inv_mod(a)), 1, "{a}⁻¹");
            }
        }
    }

    #[test]
    fn modular_coprimality_agrees_with_the_prs() {
        let big = IBig::from(10).pow(60) + IBig::from(7);
        let a = Poly::new(vec![big.clone(), IBig::from(3), IBig::ONE]);
        let b = Poly::new(vec![-big.clone(), IBig::ONE]);
        let c = Poly::new(vec![IBig::from(5), big.clone(), IBig::from(2)]);
        assert!(coprime_modular(&a, &b));
        assert!(!coprime_modular(&(&a * &c), &(&b * &c)));
        assert_eq!((&a * &c).gcd(&(&b * &c)), c.primitive_part());
        assert_eq!(a.gcd(&b), Poly::constant(IBig::ONE));
        // the prime divides the leading coefficient: not decided
        let lead = Poly::new(vec![IBig::ONE, IBig::ZERO, IBig::from(PRIME)]);
        assert!(!coprime_modular(&lead, &b));
        // a common factor x − 1 that only the exact route sees: a = (x − 1)(x + p)
        let p = IBig::from(PRIME);
        let a = Poly::new(vec![-p.clone(), &p - IBig::ONE, IBig::ONE]);
        let b = &Poly::from_i64s(&[-1, 1]) * &Poly::new(vec![big, IBig::ONE]);
        assert!(!coprime_modular(&a, &b));
        assert_eq!(a.gcd(&b), Poly::from_i64s(&[-1, 1]));
        // a nonzero constant is coprime with anything, zero with nothing but constants
        let five = Poly::constant(IBig::from(5));
        assert!(coprime_modular(&five, &b) && coprime_modular(&b, &five));
        assert!(!coprime_modular(&Poly::zero(), &b) && !coprime_modular(&b, &Poly::zero()));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn known_gcds() {
        let c = Poly::from_rational_roots(&[(1, 2), (-3, 7)]);
        let a = &c * &Poly::from_i64s(&[1, 0, 1]);
        let b = &c * &Poly::from_roots(&[4, 4, -9]);
        assert_eq!(a.gcd(&b), c.primitive_part());
        assert_eq!(
            Poly::from_roots(&[1]).gcd(&Poly::from_roots(&[2])),
            Poly::from_i64s(&[1])
        );
        assert_eq!(
            Poly::zero().gcd(&Poly::from_i64s(&[-4, -2])),
            Poly::from_i64s(&[2, 1])
        );
    }

    #[test]
    fn huge_coefficients() {
        let big = IBig::from(10).pow(40) + IBig::from(7);
        let common = Poly::new(vec![big.clone(), IBig::from(3), IBig::ONE]);
        let a = &common * &Poly::new(vec![IBig::from(5), big.clone()]);
        let b = &common * &Poly::new(vec![-big, IBig::ONE, IBig::from(2)]);
        assert_eq!(a.gcd(&b), common);
    }

    fn small_poly() -> impl Strategy<Value = Poly> {
        prop::collection::vec(-20i64..20, 1..6).prop_map(|v| Poly::from_i64s(&v))
    }

    proptest! {
        #[test]
        fn subresultant_agrees_with_primitive_prs(a in small_poly(), b in small_poly(), c in small_poly()) {
            let a = &a * &c;
            let b = &b * &c;
            let g = gcd_subresultant(&a, &b);
            prop_assert_eq!(&g, &gcd_primitive_prs(&a, &b));
            if !g.is_zero() {
                prop_assert!(a.div_exact(&g).is_some());
                prop_assert!(b.div_exact(&g).is_some());
                if !c.is_zero() {
                    prop_assert!(g.div_exact(&c.primitive_part()).is_some());
                }
            }
        }
    }
}
