//! Polynomial gcd over ℤ by the subresultant pseudo-remainder sequence.
//!
//! The subresultant PRS (Collins 1967, Brown–Traub 1971) keeps coefficient growth
//! linear in the degree without computing contents at each step ([`Poly::gcd_domain`], generic); the primitive PRS
//! (`gcd_primitive_prs`, in the tests) is the simpler second route they are compared with.

use super::Poly;
use crate::budget::{poly_step_units, product_units, Budget, Exhausted};
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
        self.gcd_within(other, &Budget::unlimited())
            .expect("an unlimited budget is never spent")
    }

    /// [`Self::gcd`] spending `budget`: the image modulo the prime costs its reduction and
    /// Euclid's `(m + 1)(n + 1)` word steps, charged before it starts; each step of the
    /// subresultant sequence where it is needed [`prem_units`] of its pair.
    ///
    /// # Errors
    /// [`Exhausted`] when the budget runs out.
    pub fn gcd_within(&self, other: &Poly, budget: &Budget) -> Result<Poly, Exhausted> {
        // Modulo a prime first (a square-free polynomial and its derivative, the removable
        // factor two forms share): the image's degree bounds the gcd's, and a lifted
        // candidate that divides both is the gcd. The subresultant PRS, whose coefficients
        // grow with the degrees and sizes, only where that does not conclude.
        let (m, n) = (self.degree().unwrap_or(0), other.degree().unwrap_or(0));
        if m >= 2 && n >= 2 {
            let reduction = poly_step_units(m, self.max_bits())
                .saturating_add(poly_step_units(n, other.max_bits()));
            budget.spend(reduction.saturating_add(((m + 1) * (n + 1)) as u64))?;
            if let Some(g) = gcd_modular(self, other) {
                return Ok(g);
            }
        }
        Ok(self
            .primitive_part()
            .gcd_domain_within(&other.primitive_part(), prem_units, budget)?
            .primitive_part())
    }
}

/// The units of one pseudo-remainder step of `a` by `b` (`deg a ≥ deg b`) and its exact
/// division: `(deg a − deg b + 2)·(deg b + 1)` coefficient products of the sizes of `a`'s
/// and `b`'s coefficients ([`product_units`]).
pub fn prem_units(a: &Poly, b: &Poly) -> u64 {
    let (m, n) = (a.degree().unwrap_or(0), b.degree().unwrap_or(0));
    let products = (m.saturating_sub(n) as u64 + 2) * (n as u64 + 1);
    products.saturating_mul(product_units(
        a.max_bits(),
        b.max_bits() * (m - n.min(m) + 1),
    ))
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

/// `v` modulo [`PRIME`], in `0..PRIME` (in machine words where it fits).
fn residue(v: &IBig) -> u64 {
    match i128::try_from(v) {
        Ok(w) => w.rem_euclid(i128::from(PRIME)) as u64,
        Err(_) => {
            let m = IBig::from(PRIME);
            let r = v % &m;
            let r = if r < IBig::ZERO { r + &m } else { r };
            u64::try_from(r).expect("a residue modulo a 61-bit prime fits in u64")
        }
    }
}

/// Coefficients modulo [`PRIME`], trailing zeros removed.
fn reduce(p: &Poly) -> Vec<u64> {
    let mut c: Vec<u64> = p.coeffs().iter().map(residue).collect();
    while c.last() == Some(&0) {
        c.pop();
    }
    c
}

/// The gcd of two residue vectors (lowest degree first, no trailing zeros) by Euclid's
/// algorithm over 𝔽_p: a constant (one entry) when they are coprime, not monic. Each step
/// cancels the top of `f` by `lc(g)·f − lc(f)·xᵏ·g` (a pseudo-remainder: no inverse, which
/// would cost a 61-bit exponentiation, in the loop).
fn euclid_mod(mut f: Vec<u64>, mut g: Vec<u64>) -> Vec<u64> {
    while g.len() > 1 {
        let lead = *g.last().expect("g is nonzero");
        while f.len() >= g.len() {
            let shift = f.len() - g.len();
            let k = *f.last().expect("f is nonzero");
            for x in &mut f[..shift] {
                *x = mul_mod(*x, lead);
            }
            for (j, gj) in g.iter().enumerate() {
                let (x, t) = (mul_mod(f[shift + j], lead), mul_mod(k, *gj));
                let d = x + PRIME - t;
                f[shift + j] = if d >= PRIME { d - PRIME } else { d };
            }
            while f.last() == Some(&0) {
                f.pop();
            }
        }
        std::mem::swap(&mut f, &mut g);
    }
    if g.len() == 1 {
        g
    } else {
        f
    }
}

/// `true` only if `a` and `b` are certainly coprime over ℚ: the prime divides neither
/// leading coefficient and the gcd of the reductions is a constant. (Reduction can only
/// raise the degree of the gcd when the leading coefficients survive it.) `false` means
/// "not known" (always so when one of them is zero).
pub fn coprime_modular(a: &Poly, b: &Poly) -> bool {
    let (f, g) = (reduce(a), reduce(b));
    if f.len() != a.coeffs().len() || g.len() != b.coeffs().len() {
        return false;
    }
    euclid_mod(f, g).len() == 1
}

/// The gcd of `a` and `b` (nonzero) from its image modulo [`PRIME`], or `None` when that
/// does not settle it. With `p` dividing neither leading coefficient, the image `h` has at
/// least the degree of the gcd `G`; `G·γ/lc(G)` for `γ = gcd(lc a, lc b)` has integer
/// coefficients and is `γ·h/lc(h)` modulo `p` when `p` is lucky, so the symmetric lift of
/// the latter, made primitive, is a candidate of degree ≥ deg G, and it is `G` exactly
/// when it divides both (checked by exact division). `None` when `p` divides a leading
/// coefficient, the lifted coefficients do not fit below `p/2`, or a division fails.
fn gcd_modular(a: &Poly, b: &Poly) -> Option<Poly> {
    let (f, g) = (reduce(a), reduce(b));
    if f.len() != a.coeffs().len() || g.len() != b.coeffs().len() {
        return None;
    }
    let h = euclid_mod(f, g);
    if h.len() == 1 {
        return Some(Poly::constant(IBig::ONE));
    }
    let gamma = crate::int_gcd(&a.leading(), &b.leading());
    let g = residue(&gamma);
    if g == 0 {
        return None;
    }
    let scale = mul_mod(g, inv_mod(*h.last().expect("h is nonzero")));
    let half = PRIME / 2;
    let lifted: Vec<IBig> = h
        .iter()
        .map(|&c| {
            let v = mul_mod(scale, c);
            if v > half {
                -IBig::from(PRIME - v)
            } else {
                IBig::from(v)
            }
        })
        .collect();
    let candidate = Poly::new(lifted).primitive_part();
    (a.div_exact(&candidate).is_some() && b.div_exact(&candidate).is_some()).then_some(candidate)
}

/// Gcd by the subresultant PRS ([`Poly::gcd_domain`]) on the primitive parts.
#[cfg(test)]
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

    /// The lifted candidate: the gcd itself where its coefficients (scaled to the leading
    /// coefficient `γ`) fit below `p/2`; `None`, never a wrong gcd, where they do not, where
    /// the prime is unlucky or divides a leading coefficient.
    #[test]
    fn modular_gcd_is_the_gcd_or_nothing() {
        let c = Poly::from_i64s(&[-3, 5, 7]); // 7x² + 5x − 3
        let a = &c * &Poly::from_i64s(&[11, 0, -2, 9]);
        let b = &c * &Poly::from_i64s(&[1, 4, 4]);
        assert_eq!(gcd_modular(&a, &b), Some(c.clone()));
        // the leading coefficient γ = gcd(63, 28) = 7 is lc(G): no larger scale needed
        assert_eq!(
            gcd_modular(&(&a * &Poly::from_i64s(&[3])), &b),
            Some(c.clone())
        );
        // coprime: the constant 1
        let d = Poly::from_i64s(&[1, 4, 4]);
        assert_eq!(
            gcd_modular(&Poly::from_i64s(&[11, 0, -2, 9]), &d),
            Some(Poly::constant(IBig::ONE))
        );
        // a common factor with a 70-bit coefficient: the lift cannot recover it
        let big = Poly::new(vec![IBig::ONE << 70, IBig::from(3), IBig::ONE]);
        let (a, b) = (
            &big * &Poly::from_i64s(&[2, 1, 1]),
            &big * &Poly::from_i64s(&[5, 0, 1]),
        );
        assert_eq!(gcd_modular(&a, &b), None);
        assert_eq!(a.gcd(&b), big);
        // an unlucky prime: x² + 1 and x² + 1 + p share nothing over ℚ, everything mod p;
        // the candidate x² + 1 divides one only
        let p = IBig::from(PRIME);
        let (e, f) = (
            Poly::from_i64s(&[1, 0, 1]),
            Poly::new(vec![IBig::ONE + &p, IBig::ZERO, IBig::ONE]),
        );
        assert_eq!(gcd_modular(&e, &f), None);
        assert_eq!(e.gcd(&f), Poly::constant(IBig::ONE));
        // the prime divides a leading coefficient: not tried
        let lead = Poly::new(vec![IBig::ONE, IBig::ZERO, p]);
        assert_eq!(gcd_modular(&lead, &e), None);
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

    /// A polynomial of degree 2 to 4 with coefficients up to about 2⁴⁰, and so products
    /// whose coefficients pass the prime: the modular route with its lift and checks.
    fn wide_poly() -> impl Strategy<Value = Poly> {
        prop::collection::vec(-(1i64 << 40)..(1i64 << 40), 3..6).prop_map(|v| Poly::from_i64s(&v))
    }

    proptest! {
        #[test]
        fn gcd_agrees_with_primitive_prs(a in wide_poly(), b in small_poly(), c in wide_poly(), e in small_poly()) {
            prop_assume!(!c.is_zero());
            let (a, b) = (&(&a * &c) * &e, &(&b * &c) * &e);
            let g = a.gcd(&b);
            prop_assert_eq!(&g, &gcd_primitive_prs(&a, &b));
            prop_assert!(g.div_exact(&c.primitive_part()).is_some());
        }

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
