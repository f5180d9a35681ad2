//! Legendre's equation `a x² + b y² + c z² = 0` from a rational diagonal, over coefficients
//! that need not be factored (the parent module's doc states the mathematics).
//!
//! **Atoms.** The numerators and denominators of the diagonal are split by trial division and a
//! cheap Pollard rho ([`crate::factor::factorize_partial`], within one step budget for the
//! whole conic); what is left unfactored is rewritten over a coprime base (gcds, perfect powers
//! taken out: [`crate::factor::large`]) together with the large primes found. So every number
//! is a product of powers of pairwise coprime *atoms*: primes, and cofactors that may be
//! composite. The reduction to square-free pairwise coprime `a, b, c` treats an atom like a
//! prime; it is valid for any integer (`N(a'x² + b'y²) + cz² = 0` is `a'(Nx)² + b'(Ny)² + Ncz²`
//! over `N`, squares leave by scaling), so the reduced form has the same rational points.
//!
//! **Decisions.** Legendre's conditions are needed at every atom `N`: for a prime `p | N` of odd
//! order `−bc` is a square modulo `p` (with `p ∤ bc`), so a Jacobi symbol `(−bc/N) = −1` proves
//! there is no rational point whatever `N`'s factors. The construction needs square roots
//! modulo each atom: modulo a prime directly, modulo a cofactor by Tonelli–Shanks as if it were
//! prime, kept only when it squares back. A root checked modulo `N` serves the lattice whether
//! `N` is prime or not (index `|abc|`, every vector with `Q ≡ 0 (mod abc)`, Minkowski's bound).
//! When a root modulo a cofactor is not found and no symbol is `−1`, the question is
//! [`Legendre::Undecided`]: the caller takes a point over ℚ(√δ) with the cofactor under the
//! radical.

use crate::factor::large::{coprime_base, jacobi_big, perfect_power, sqrt_mod_cofactor};
use crate::factor::{factorize_partial, is_prime, jacobi, sqrt_mod_prime, TRIAL_LIMIT};
use dashu_int::ops::{BitTest, UnsignedAbs};
use dashu_int::{IBig, UBig};
use dashu_ratio::RBig;

/// The Pollard-rho steps one conic may spend on its coefficients' cofactors below `2¹²⁸`
/// (about 2·16 384 Montgomery products of 128 bits, well under a millisecond; primes up to
/// about `2²⁸` are found): a cheap attempt before the cofactor is kept whole.
pub(super) const CONIC_RHO_BUDGET: u64 = 1 << 14;

/// One of the pairwise coprime factors the numbers are written over.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct Atom {
    pub(super) value: UBig,
    /// A prime below `2¹²⁸` ([`is_prime`]); otherwise a cofactor, maybe composite.
    pub(super) prime: bool,
}

/// Integers written over atoms: `|nᵢ| = Π atoms[j]^e` for `(j, e)` in `parts[i]`.
#[derive(Clone, Debug)]
pub(super) struct Factored {
    pub(super) atoms: Vec<Atom>,
    pub(super) parts: Vec<Vec<(usize, u32)>>,
}

/// The nonzero integers `ns` over pairwise coprime atoms (module doc), spending at most
/// `budget` rho steps.
pub(super) fn factor_all(ns: &[IBig], budget: &mut u64) -> Factored {
    // primes found once are divided out of the numbers after it before factoring them
    let mut known: Vec<u128> = Vec::new();
    let mut primes: Vec<Vec<(u128, u32)>> = Vec::with_capacity(ns.len());
    let mut rests: Vec<Vec<UBig>> = Vec::with_capacity(ns.len());
    for n in ns {
        let mut rest = n.unsigned_abs();
        let mut found = Vec::new();
        for &p in &known {
            let pb = UBig::from(p);
            let mut e = 0;
            while (&rest % &pb).is_zero() {
                rest /= &pb;
                e += 1;
            }
            if e > 0 {
                found.push((p, e));
            }
        }
        let cofactors = match factorize_partial(&IBig::from(rest.clone()), budget) {
            Ok(f) => {
                known.extend(f.factors.iter().map(|&(p, _)| p));
                found.extend(f.factors);
                f.cofactors
            }
            Err(_) => vec![], // zero: no atoms (callers pass nonzero numbers)
        };
        primes.push(found);
        rests.push(cofactors);
    }
    // the cofactors and the primes above the trial limit (a prime found late may divide an
    // earlier cofactor) over one coprime base, perfect powers taken out
    let mut pool: Vec<UBig> = rests.iter().flatten().cloned().collect();
    let trial = u128::from(TRIAL_LIMIT);
    if !pool.is_empty() {
        pool.extend(
            known
                .iter()
                .filter(|&&p| p >= trial)
                .map(|&p| UBig::from(p)),
        );
    }
    let (base, _) = coprime_base(&pool);
    let base: Vec<(UBig, u32)> = base
        .iter()
        .map(|b| perfect_power(b, TRIAL_LIMIT.trailing_zeros() as usize))
        .collect();
    let mut atoms: Vec<Atom> = Vec::new();
    let index = |atoms: &mut Vec<Atom>, value: UBig| -> usize {
        if let Some(i) = atoms.iter().position(|a| a.value == value) {
            return i;
        }
        let prime = u128::try_from(&value).is_ok_and(is_prime);
        atoms.push(Atom { value, prime });
        atoms.len() - 1
    };
    let mut parts = Vec::with_capacity(ns.len());
    for (found, cofactors) in primes.iter().zip(&rests) {
        let mut part: Vec<(usize, u32)> = Vec::new();
        let add = |part: &mut Vec<(usize, u32)>, i: usize, e: u32| match part
            .iter_mut()
            .find(|(j, _)| *j == i)
        {
            Some((_, f)) => *f += e,
            None => part.push((i, e)),
        };
        for &(p, e) in found {
            let i = index(&mut atoms, UBig::from(p));
            add(&mut part, i, e);
        }
        for c in cofactors {
            let mut rest = c.clone();
            for (root, _) in &base {
                let mut e = 0;
                while (&rest % root).is_zero() {
                    rest /= root;
                    e += 1;
                }
                if e > 0 {
                    let i = index(&mut atoms, root.clone());
                    add(&mut part, i, e);
                }
            }
            debug_assert!(rest == UBig::ONE, "a cofactor is a product of the base");
        }
        parts.push(part);
    }
    Factored { atoms, parts }
}

/// A square-free integer coefficient with its atoms.
#[derive(Clone, Debug)]
pub(super) struct Coefficient {
    pub(super) value: IBig,
    pub(super) atoms: Vec<usize>,
}

/// `Σ eᵢYᵢ² = 0` made square-free and pairwise coprime over the atoms: `Σ fᵢWᵢ² = 0` with
/// `Yᵢ = sᵢWᵢ`; `e[i]` the atoms and exponents of `|eᵢ|`, `negative[i]` its sign. Per atom
/// `N`: squares leave with `Yᵢ = Wᵢ/r`; dividing all three coefficients divides the equation;
/// dividing two (`fᵢ = N fᵢ'`, `fⱼ = N fⱼ'`) gives `fᵢ'Wᵢ² + fⱼ'Wⱼ² + N fₖWₖ²` with
/// `Yᵢ = Wᵢ/N`, `Yⱼ = Wⱼ/N` (the equation times `N`).
pub(super) fn reduce(
    atoms: &[Atom],
    e: &[Vec<(usize, u32)>; 3],
    negative: [bool; 3],
) -> ([Coefficient; 3], [RBig; 3]) {
    let mut scale: [RBig; 3] = std::array::from_fn(|_| RBig::ONE);
    let mut sets: [Vec<usize>; 3] = Default::default();
    for i in 0..3 {
        let mut root = UBig::ONE;
        for &(a, k) in &e[i] {
            root *= atoms[a].value.pow((k / 2) as usize);
            if k % 2 == 1 {
                sets[i].push(a);
            }
        }
        scale[i] = RBig::from_parts(IBig::ONE, root);
        sets[i].sort_unstable();
    }
    let mut all: Vec<usize> = sets.iter().flatten().copied().collect();
    all.sort_unstable();
    all.dedup();
    let mut out: [Vec<usize>; 3] = Default::default();
    for a in all {
        let has: Vec<usize> = (0..3)
            .filter(|&i| sets[i].binary_search(&a).is_ok())
            .collect();
        match has.len() {
            1 => out[has[0]].push(a),
            2 => {
                let k = 3 - has[0] - has[1];
                out[k].push(a);
                for &i in &has {
                    scale[i] /= RBig::from(atoms[a].value.clone());
                }
            }
            _ => {}
        }
    }
    let coefs = std::array::from_fn(|i| {
        out[i].sort_unstable();
        let mut value = IBig::from(
            out[i]
                .iter()
                .map(|&a| atoms[a].value.clone())
                .product::<UBig>(),
        );
        if negative[i] {
            value = -value;
        }
        Coefficient {
            value,
            atoms: out[i].clone(),
        }
    });
    (coefs, scale)
}

/// What Legendre's equation gave.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum Legendre {
    /// A nonzero integer solution.
    Solution([IBig; 3]),
    /// None: the form is definite, or a Jacobi symbol is `−1`.
    NoSolution,
    /// No symbol is `−1` but a square root modulo a cofactor of `bits` bits was not found.
    Undecided { bits: usize },
}

/// Legendre's equation for square-free pairwise coprime `a, b, c` over `atoms` (module doc).
pub(super) fn solve_reduced(f: &[Coefficient; 3], atoms: &[Atom]) -> Legendre {
    let negatives = f.iter().filter(|c| c.value < IBig::ZERO).count();
    if negatives == 0 || negatives == 3 {
        return Legendre::NoSolution;
    }
    // Order (i, j, k) so that, after negating the equation if needed, a, b > 0 > c.
    let flip = negatives == 2;
    let val = |i: usize| {
        if flip {
            -&f[i].value
        } else {
            f[i].value.clone()
        }
    };
    let k = (0..3)
        .find(|&i| val(i) < IBig::ZERO)
        .expect("one coefficient has the lone sign");
    let (i, j) = match k {
        0 => (1, 2),
        1 => (0, 2),
        _ => (0, 1),
    };
    let (a, b, c) = (val(i), val(j), val(k));
    // r² ≡ −c/b (mod a), −a/c (mod b), −b/a (mod c): every symbol first, then the roots
    let conditions = [(-&c, &b, i), (-&a, &c, j), (-&b, &a, k)];
    for (num, den, l) in &conditions {
        if f[*l]
            .atoms
            .iter()
            .any(|&t| symbol(&(num * *den), &atoms[t]) == -1)
        {
            return Legendre::NoSolution;
        }
    }
    let mut roots: Vec<IBig> = Vec::with_capacity(3);
    for (num, den, l) in &conditions {
        match sqrt_ratio_mod(num, den, &f[*l].atoms, atoms) {
            Ok(r) => roots.push(r),
            Err(bits) => return Legendre::Undecided { bits },
        }
    }
    let (ra, rb, rc) = (&roots[0], &roots[1], &roots[2]);
    // Λ: y ≡ ra·z (mod a), z ≡ rb·x (mod b), x ≡ rc·y (mod c); as one congruence modulo
    // N = |abc|: αx + βy + γz ≡ 0.
    let (ma, mb, mc) = (abs(&a), abs(&b), abs(&c));
    let n = &ma * &mb * &mc;
    let alpha = crt(&[(IBig::ZERO, &ma), (-rb, &mb), (IBig::ONE, &mc)]);
    let beta = crt(&[(IBig::ONE, &ma), (IBig::ZERO, &mb), (-rc, &mc)]);
    let gamma = crt(&[(-ra, &ma), (IBig::ONE, &mb), (IBig::ZERO, &mc)]);
    let mut basis = congruence_lattice([alpha, beta, gamma], &n);
    let weights = [ma.clone(), mb.clone(), IBig::from(2) * &mc];
    lll(&mut basis, &weights);
    let v = &basis[0];
    let q = &a * &v[0] * &v[0] + &b * &v[1] * &v[1] + &c * &v[2] * &v[2];
    let abc = &a * &b * &c;
    let sol = if q.is_zero() {
        v.clone()
    } else {
        assert_eq!(
            q, -&abc,
            "Minkowski bound: Q(v) ∈ {{0, −abc}} for the reduced vector"
        );
        [
            &v[0] * &v[2] + &b * &v[1],
            &v[1] * &v[2] - &a * &v[0],
            &v[2] * &v[2] + &a * &b,
        ]
    };
    let mut out: [IBig; 3] = Default::default();
    out[i] = sol[0].clone();
    out[j] = sol[1].clone();
    out[k] = sol[2].clone();
    let check: IBig = (0..3).map(|l| &f[l].value * &out[l] * &out[l]).sum();
    assert!(
        check.is_zero() && out.iter().any(|v| !v.is_zero()),
        "Legendre solution checked"
    );
    Legendre::Solution(out)
}

/// The Jacobi symbol of `x` modulo an odd atom (`1` modulo 2: everything is a square there).
fn symbol(x: &IBig, atom: &Atom) -> i8 {
    if atom.value == UBig::from(2u8) {
        return 1;
    }
    let r = modulo(x, &atom.value);
    match (u128::try_from(&r), u128::try_from(&atom.value)) {
        (Ok(r), Ok(p)) => jacobi(r, p),
        _ => jacobi_big(&r, &atom.value),
    }
}

/// A root `r` of `r² ≡ num/den` modulo the product of the atoms `ids` (each coprime to `den`,
/// every Jacobi symbol of `num·den` already `+1`), or the bits of an atom modulo which no
/// root was found.
fn sqrt_ratio_mod(num: &IBig, den: &IBig, ids: &[usize], atoms: &[Atom]) -> Result<IBig, usize> {
    let mut parts = Vec::with_capacity(ids.len());
    for &t in ids {
        let atom = &atoms[t];
        let x = modulo(&(num * den), &atom.value);
        let root = match (u128::try_from(&x), u128::try_from(&atom.value)) {
            (Ok(x), Ok(p)) if atom.prime => sqrt_mod_prime(x, p).map(UBig::from),
            // a residue that is a square of integers has its root modulo anything
            _ => integer_sqrt(&x).or_else(|| sqrt_mod_cofactor(&x, &atom.value)),
        };
        // a failed root after Jacobi +1: the atom is composite (or a prime that failed)
        let s = root.ok_or(atom.value.bit_len())?;
        let m = IBig::from(atom.value.clone());
        let r = IBig::from(s) * inv_mod(den, &m) % &m;
        parts.push((r, m));
    }
    let refs: Vec<(IBig, &IBig)> = parts.iter().map(|(r, p)| (r.clone(), p)).collect();
    Ok(crt(&refs))
}

/// A basis (rows) of `{v ∈ ℤ³ : coef·v ≡ 0 (mod n)}` for a surjective congruence
/// (every prime of `n` divides some coefficient's complement): `U·diag(n, 1, 1)` for a
/// unimodular `U` with `coef·U = (g, 0, 0)`, `gcd(g, n) = 1`.
fn congruence_lattice(coef: [IBig; 3], n: &IBig) -> [[IBig; 3]; 3] {
    // Columns of U, built by two extended-gcd steps.
    let mut cols: [[IBig; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|j| IBig::from((i == j) as i32)));
    // Columns p, q of U so that coef·U has g = gcd(x, y) at p and 0 at q (x, y there before).
    fn combine(cols: &mut [[IBig; 3]; 3], p: usize, q: usize, x: &IBig, y: &IBig) -> IBig {
        let (g, s, t) = ext_gcd(x, y);
        if !g.is_zero() {
            let (u, w) = (cols[p].clone(), cols[q].clone());
            let (yg, xg) = (y / &g, x / &g);
            cols[p] = std::array::from_fn(|i| &s * &u[i] + &t * &w[i]);
            cols[q] = std::array::from_fn(|i| &xg * &w[i] - &yg * &u[i]);
        }
        g
    }
    let g1 = combine(&mut cols, 0, 1, &coef[0], &coef[1]);
    combine(&mut cols, 0, 2, &g1, &coef[2]);
    cols[0] = std::array::from_fn(|i| n * &cols[0][i]);
    debug_assert!(cols.iter().all(|v| modulo(
        &(0..3).map(|i| &coef[i] * &v[i]).sum::<IBig>(),
        &n.unsigned_abs()
    )
    .is_zero()));
    cols
}

/// LLL reduction (δ = 99/100) of the rows of `basis` for the norm `Σ wᵢvᵢ²` (exact rational
/// Gram–Schmidt, recomputed after each change: dimension 3).
fn lll(basis: &mut [[IBig; 3]; 3], w: &[IBig; 3]) {
    let delta = RBig::from_parts(IBig::from(99), 100u8.into());
    let dot =
        |u: &[IBig; 3], v: &[IBig; 3]| -> IBig { (0..3).map(|i| &w[i] * &u[i] * &v[i]).sum() };
    let gram_schmidt = |b: &[[IBig; 3]; 3]| -> ([[RBig; 3]; 3], [RBig; 3]) {
        let mut mu: [[RBig; 3]; 3] = Default::default();
        let mut bn: [RBig; 3] = Default::default();
        for i in 0..3 {
            for j in 0..i {
                let mut v = RBig::from(dot(&b[i], &b[j]));
                for l in 0..j {
                    v -= &mu[j][l] * &mu[i][l] * &bn[l];
                }
                mu[i][j] = v / &bn[j];
            }
            let mut v = RBig::from(dot(&b[i], &b[i]));
            for l in 0..i {
                v -= &mu[i][l] * &mu[i][l] * &bn[l];
            }
            bn[i] = v;
        }
        (mu, bn)
    };
    let mut k = 1;
    while k < 3 {
        for j in (0..k).rev() {
            let (mu, _) = gram_schmidt(basis);
            let q = mu[k][j].round();
            if !q.is_zero() {
                let bj = basis[j].clone();
                for i in 0..3 {
                    basis[k][i] -= &q * &bj[i];
                }
            }
        }
        let (mu, bn) = gram_schmidt(basis);
        if bn[k] >= (&delta - &mu[k][k - 1] * &mu[k][k - 1]) * &bn[k - 1] {
            k += 1;
        } else {
            basis.swap(k, k - 1);
            k = (k - 1).max(1);
        }
    }
}

/// `(g, s, t)` with `g = gcd(x, y) ≥ 0` and `s·x + t·y = g` (`(0, 1, 0)` for two zeros).
fn ext_gcd(x: &IBig, y: &IBig) -> (IBig, IBig, IBig) {
    let (mut r0, mut r1) = (x.clone(), y.clone());
    let (mut s0, mut s1) = (IBig::ONE, IBig::ZERO);
    let (mut t0, mut t1) = (IBig::ZERO, IBig::ONE);
    while !r1.is_zero() {
        let q = &r0 / &r1;
        (r0, r1) = (r1.clone(), &r0 - &q * &r1);
        (s0, s1) = (s1.clone(), &s0 - &q * &s1);
        (t0, t1) = (t1.clone(), &t0 - &q * &t1);
    }
    if r0 < IBig::ZERO {
        (-r0, -s0, -t0)
    } else {
        (r0, s0, t0)
    }
}

/// `x⁻¹ mod m` in `0..m` for `gcd(x, m) = 1`, `m > 0`.
fn inv_mod(x: &IBig, m: &IBig) -> IBig {
    let (g, s, _) = ext_gcd(x, m);
    debug_assert!(g.is_one() || m.is_one());
    let r = s % m;
    if r < IBig::ZERO {
        r + m
    } else {
        r
    }
}

/// The `r` in `0..∏m` with `r ≡ rᵢ (mod mᵢ)`, moduli pairwise coprime and positive.
fn crt(parts: &[(IBig, &IBig)]) -> IBig {
    let (mut r, mut m) = (IBig::ZERO, IBig::ONE);
    for (ri, mi) in parts {
        let mi: &IBig = mi;
        // r + m·k ≡ ri (mod mi)
        let k = (ri - &r) * inv_mod(&m, mi) % mi;
        r += &m * k;
        m *= mi;
        r %= &m;
        if r < IBig::ZERO {
            r += &m;
        }
    }
    r
}

fn abs(v: &IBig) -> IBig {
    if *v < IBig::ZERO {
        -v
    } else {
        v.clone()
    }
}

/// `√x` if `x` is a perfect square.
fn integer_sqrt(x: &UBig) -> Option<UBig> {
    use dashu_int::ops::SquareRoot;
    let r = x.sqrt();
    (&r * &r == *x).then_some(r)
}

/// `v mod m` in `0..m` (`m > 0`).
fn modulo(v: &IBig, m: &UBig) -> UBig {
    let mi = IBig::from(m.clone());
    let r = v % &mi;
    let r = if r < IBig::ZERO { r + &mi } else { r };
    r.unsigned_abs()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::linalg::minors;

    fn residue(v: &IBig, m: &IBig) -> IBig {
        IBig::from(modulo(v, &m.unsigned_abs()))
    }

    #[test]
    fn congruence_lattice_has_index_n() {
        for (coef, n) in [
            ([0i64, 4, 1], 15i64),
            ([3, 0, 0], 7),
            ([0, 0, 0], 1),
            ([6, 10, 15], 7 * 11),
        ] {
            let coef = coef.map(IBig::from);
            let n = IBig::from(n);
            let b = congruence_lattice(coef.clone(), &n);
            assert_eq!(abs(&minors::det(&b)), n);
            for v in &b {
                let dot: IBig = (0..3).map(|i| &coef[i] * &v[i]).sum();
                assert_eq!(residue(&dot, &n), IBig::ZERO);
            }
        }
    }

    #[test]
    fn crt_and_inverses() {
        let (m1, m2, m3) = (IBig::from(4), IBig::from(9), IBig::from(25));
        let r = crt(&[
            (IBig::from(3), &m1),
            (IBig::from(-1), &m2),
            (IBig::from(7), &m3),
        ]);
        assert_eq!(residue(&r, &m1), IBig::from(3));
        assert_eq!(residue(&r, &m2), IBig::from(8));
        assert_eq!(residue(&r, &m3), IBig::from(7));
        assert_eq!(inv_mod(&IBig::from(-3), &IBig::from(7)), IBig::from(2));
        assert_eq!(ext_gcd(&IBig::from(-12), &IBig::from(18)).0, IBig::from(6));
    }

    /// Numbers sharing unfactored cofactors and large primes come out over pairwise coprime
    /// atoms, each number rebuilt from them.
    #[test]
    fn numbers_over_coprime_atoms() {
        let p1 = UBig::from((1u128 << 61) - 1);
        let p2 = UBig::from(u64::MAX as u128 - 58);
        let m127 = (UBig::ONE << 127) - UBig::ONE;
        let big = (UBig::ONE << 521) - UBig::ONE;
        let ns: Vec<IBig> = [
            UBig::from(12u8) * &p1 * &p2 * &big,
            &p1 * &big * &big * &m127,
            UBig::from(65537u32).pow(9),
            &p2 * &p2,
        ]
        .into_iter()
        .map(IBig::from)
        .collect();
        let mut budget = 0; // no rho at all: p1·p2 stays a cofactor until p2² shows p2
        let f = factor_all(&ns, &mut budget);
        for (n, part) in ns.iter().zip(&f.parts) {
            let prod: UBig = part
                .iter()
                .map(|&(a, e)| f.atoms[a].value.pow(e as usize))
                .product();
            assert_eq!(IBig::from(prod), *n);
        }
        for (i, a) in f.atoms.iter().enumerate() {
            for b in &f.atoms[i + 1..] {
                assert_eq!(dashu_int::ops::Gcd::gcd(&a.value, &b.value), UBig::ONE);
            }
        }
        assert!(f
            .atoms
            .iter()
            .any(|a| a.value == UBig::from(65537u32) && a.prime));
        assert!(f.atoms.iter().any(|a| a.value == big && !a.prime));
    }
}
