//! Fraction-free arithmetic in ℤ[√δ]: the integer fast path of [`super::surface`].
//!
//! `ℚ(√δ)` elements as [`Quadratic`] normalise two rationals (two gcds) at every operation;
//! the rulings, the forms `c₀, c₁, c₂` and `s(u)` only need sums and products of integral
//! elements `a + b√δ` (`a, b ∈ ℤ`), which here cost a few integer products and no gcd:
//! `(a + b√δ)(c + e√δ) = (ac + δbe) + (ae + bc)√δ`. Values are converted back to
//! [`Quadratic`] at the end; the results are identical.
//!
//! Here: [`Zq`] in big integers, the reference of every routine. The same in machine
//! integers: `fixed` (the lattice reduction of a ruling, the ruling through a small point)
//! and `levin` (the forms `s`, `a` of Levin's method), each checked against this module in
//! the tests.

use qsic_algebra::field::Quadratic;
use qsic_algebra::{IBig, Poly, RBig, Sign};

mod fixed;
mod levin;
#[cfg(test)]
mod tests;

use fixed::{big_int, reduce_array};
pub(crate) use fixed::{ruling_fixed, FixedRuling, Through};
pub(crate) use levin::{levin_big, levin_small, FixedLevin};

/// `a + b√δ` with integers `a`, `b` (`δ` held by the caller).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Zq {
    pub(crate) a: IBig,
    pub(crate) b: IBig,
}

impl Zq {
    pub(crate) fn int(a: IBig) -> Zq {
        Zq { a, b: IBig::ZERO }
    }

    pub(crate) fn is_zero(&self) -> bool {
        self.a.is_zero() && self.b.is_zero()
    }

    /// `x` if it is integral (`a, b ∈ ℤ`) and its radicand is `δ` (or it is rational).
    pub(crate) fn from_quadratic(x: &Quadratic, delta: &IBig) -> Option<Zq> {
        let int = |v: &RBig| -> Option<IBig> {
            (*v.denominator() == dashu_int::UBig::ONE).then(|| v.numerator().clone())
        };
        if x.as_rational().is_none() && x.radicand() != delta {
            return None;
        }
        Some(Zq {
            a: int(x.rational_part())?,
            b: int(x.radical_part())?,
        })
    }

    #[cfg(test)]
    pub(crate) fn to_quadratic(&self, delta: &IBig) -> Quadratic {
        if self.b.is_zero() {
            return Quadratic::rational(RBig::from(self.a.clone()));
        }
        Quadratic::new(
            RBig::from(self.a.clone()),
            RBig::from(self.b.clone()),
            delta.clone(),
        )
        .expect("δ is not a square")
    }

    /// [`Self::to_quadratic`] with `root = √δ` ([`Quadratic::sqrt`]): no square test.
    fn to_quadratic_in(&self, root: &Quadratic) -> Quadratic {
        if self.b.is_zero() {
            return Quadratic::rational(RBig::from(self.a.clone()));
        }
        debug_assert!(root.as_rational().is_none(), "δ is not a square");
        Quadratic::in_field_of(RBig::from(self.a.clone()), RBig::from(self.b.clone()), root)
    }

    pub(crate) fn mul(&self, o: &Zq, delta: &IBig) -> Zq {
        // an integer factor: two products, no multiple of δ
        if self.b.is_zero() {
            return Zq {
                a: &self.a * &o.a,
                b: &self.a * &o.b,
            };
        }
        if o.b.is_zero() {
            return Zq {
                a: &self.a * &o.a,
                b: &self.b * &o.a,
            };
        }
        Zq {
            a: &self.a * &o.a + &self.b * &o.b * delta,
            b: &self.a * &o.b + &self.b * &o.a,
        }
    }

    /// `self += x·y`.
    pub(crate) fn add_mul(&mut self, x: &Zq, y: &Zq, delta: &IBig) {
        if x.is_zero() || y.is_zero() {
            return;
        }
        let p = x.mul(y, delta);
        self.a += p.a;
        self.b += p.b;
    }
}

/// A polynomial in `u` over ℤ[√δ], increasing powers (trailing zeros allowed).
pub(crate) type ZPoly = Vec<Zq>;

/// Levin's `s`, `a` and `alt` over ℤ[√δ] ([`levin_small`], [`levin_big`]).
pub(crate) type LevinForms = (ZPoly, [ZPoly; 4], [ZPoly; 4]);

/// `p` over ℤ[√δ], `None` if a coefficient is not integral in ℚ(√δ).
pub(crate) fn zpoly(p: &Poly<Quadratic>, delta: &IBig) -> Option<ZPoly> {
    p.coeffs()
        .iter()
        .map(|c| Zq::from_quadratic(c, delta))
        .collect()
}

/// The four coordinates of `v` over ℤ[√δ] ([`zpoly`]); `None` unless all are integral.
pub(crate) fn zvector(v: &[Poly<Quadratic>; 4], delta: &IBig) -> Option<[ZPoly; 4]> {
    Some([
        zpoly(&v[0], delta)?,
        zpoly(&v[1], delta)?,
        zpoly(&v[2], delta)?,
        zpoly(&v[3], delta)?,
    ])
}

/// Back to a polynomial over ℚ(√δ).
pub(crate) fn to_poly(p: &[Zq], delta: &IBig) -> Poly<Quadratic> {
    let root = root_of(p, delta);
    Poly::new(p.iter().map(|c| c.to_quadratic_in(&root)).collect())
}

/// `√δ` when a coefficient of `p` is irrational (one square test for all), else 0.
fn root_of(p: &[Zq], delta: &IBig) -> Quadratic {
    if p.iter().all(|c| c.b.is_zero()) {
        return Quadratic::rational(RBig::ZERO);
    }
    let root = Quadratic::sqrt(delta);
    assert!(root.as_rational().is_none(), "δ is not a square");
    root
}

/// The `log₂` sizes of the coefficients of `p` (`−∞` for zero), as `log2_size` in the parent
/// module computes them on [`to_poly`] of `p`, from the integers: the float of `a + b√δ` is
/// `a + b·√δ` in floats (each correctly rounded), else bit lengths.
pub(crate) fn log2_sizes(p: &[Zq], delta: &IBig) -> Vec<f64> {
    use dashu_int::ops::BitTest;
    let root = delta.to_f64().value().sqrt();
    let bits = |v: &IBig| {
        if v.is_zero() {
            f64::NEG_INFINITY
        } else {
            // the bit length of the numerator less that of the denominator 1
            v.bit_len() as f64 - 1.0
        }
    };
    p.iter()
        .map(|c| {
            if c.is_zero() {
                return f64::NEG_INFINITY;
            }
            let a = c.a.to_f64().value();
            let v = if c.b.is_zero() {
                a
            } else {
                a + c.b.to_f64().value() * root
            }
            .abs();
            if v.is_finite() && v > 0.0 {
                return v.log2();
            }
            let root_bits = if c.b.is_zero() {
                0.0
            } else {
                delta.bit_len() as f64 / 2.0
            };
            bits(&c.a).max(bits(&c.b) + root_bits) + 1.0
        })
        .collect()
}

pub(crate) fn poly_mul(x: &[Zq], y: &[Zq], delta: &IBig) -> ZPoly {
    if x.is_empty() || y.is_empty() {
        return Vec::new();
    }
    // the products of the √δ parts summed apart, times δ once a coefficient (δ is often the
    // largest number here: one product by it instead of one a term)
    let n = x.len() + y.len() - 1;
    let mut out = vec![Zq::default(); n];
    let mut radical = vec![IBig::ZERO; n];
    for (i, p) in x.iter().enumerate() {
        if p.is_zero() {
            continue;
        }
        for (j, q) in y.iter().enumerate() {
            let o = &mut out[i + j];
            if !p.a.is_zero() {
                if !q.a.is_zero() {
                    o.a += &p.a * &q.a;
                }
                if !q.b.is_zero() {
                    o.b += &p.a * &q.b;
                }
            }
            if !p.b.is_zero() {
                if !q.a.is_zero() {
                    o.b += &p.b * &q.a;
                }
                if !q.b.is_zero() {
                    radical[i + j] += &p.b * &q.b;
                }
            }
        }
    }
    for (o, r) in out.iter_mut().zip(radical) {
        if !r.is_zero() {
            o.a += r * delta;
        }
    }
    out
}

/// `x + k·y` for a scalar `k`.
pub(crate) fn poly_add_scaled(x: &mut ZPoly, k: &Zq, y: &[Zq], delta: &IBig) {
    if x.len() < y.len() {
        x.resize(y.len(), Zq::default());
    }
    for (i, b) in y.iter().enumerate() {
        x[i].add_mul(k, b, delta);
    }
}

/// `xᵀMy` for an integer matrix `M` and polynomial vectors over ℤ[√δ].
pub(crate) fn poly_form(m: &[[IBig; 4]; 4], x: &[ZPoly; 4], y: &[ZPoly; 4], delta: &IBig) -> ZPoly {
    let mut acc: ZPoly = Vec::new();
    for i in 0..4 {
        if x[i].iter().all(Zq::is_zero) {
            continue;
        }
        let mut row: ZPoly = Vec::new();
        for j in 0..4 {
            if !m[i][j].is_zero() {
                poly_add_scaled(&mut row, &Zq::int(m[i][j].clone()), &y[j], delta);
            }
        }
        let prod = poly_mul(&x[i], &row, delta);
        if acc.len() < prod.len() {
            acc.resize(prod.len(), Zq::default());
        }
        for (o, c) in acc.iter_mut().zip(prod) {
            o.a += c.a;
            o.b += c.b;
        }
    }
    acc
}

/// The integer matrix if every entry of `m` is an integer.
pub(crate) fn integer_matrix(m: &[[Quadratic; 4]; 4]) -> Option<[[IBig; 4]; 4]> {
    let mut out: [[IBig; 4]; 4] = Default::default();
    for i in 0..4 {
        for j in 0..4 {
            let v = m[i][j].as_rational()?;
            if *v.denominator() != dashu_int::UBig::ONE {
                return None;
            }
            out[i][j] = v.numerator().clone();
        }
    }
    Some(out)
}

/// The exact sign of `p(x)` for a rational `x = n/m` (`δ > 0` not a square, or `p` rational):
/// `m^deg·p(n/m) = A + B√δ` by Horner's rule in integers, then the sign of `A + B√δ` from
/// the signs of `A`, `B` and the comparison of `A²` with `δB²`.
pub(crate) fn sign_at(p: &[Zq], x: &RBig, delta: &IBig) -> Sign {
    let (n, m) = (x.numerator().clone(), IBig::from(x.denominator().clone()));
    let mut acc = Zq::default();
    let mut scale = IBig::ONE;
    for c in p.iter().rev() {
        // acc ← acc·n + c·m^k (k the number of coefficients taken so far)
        acc = Zq {
            a: &acc.a * &n + &c.a * &scale,
            b: &acc.b * &n + &c.b * &scale,
        };
        scale *= &m;
    }
    let (sa, sb) = (Sign::of(&acc.a), Sign::of(&acc.b));
    if sb == Sign::Zero || sa == sb {
        return if sb == Sign::Zero { sa } else { sb };
    }
    if sa == Sign::Zero {
        return sb;
    }
    // opposite signs: |A| vs |B|√δ, never equal (δ not a square)
    if &acc.a * &acc.a > &acc.b * &acc.b * delta {
        sa
    } else {
        sb
    }
}

/// `x − y`.
pub(crate) fn poly_sub(x: &[Zq], y: &[Zq]) -> ZPoly {
    let mut out: ZPoly = x.to_vec();
    if out.len() < y.len() {
        out.resize(y.len(), Zq::default());
    }
    for (o, c) in out.iter_mut().zip(y) {
        o.a -= &c.a;
        o.b -= &c.b;
    }
    out
}

/// `p` without its trailing zero coefficients.
pub(crate) fn trim(p: &mut ZPoly) {
    while p.last().is_some_and(Zq::is_zero) {
        p.pop();
    }
}

/// Coefficient `i` of `p` times `2^exponent(i)`.
pub(crate) fn scale_powers_of_two(p: &mut [Zq], exponent: impl Fn(usize) -> usize) {
    // `v·2^e`: nothing for zero, in `i128` for a `v` of `i64` and `e < 63` (`|v·2^e| < 2¹²⁶`)
    let shift = |v: &mut IBig, e: usize| {
        if v.is_zero() {
            return;
        }
        match i64::try_from(&*v) {
            Ok(x) if e < 63 => *v = IBig::from(i128::from(x) << e),
            _ => *v <<= e,
        }
    };
    for (i, c) in p.iter_mut().enumerate() {
        let e = exponent(i);
        if e > 0 {
            shift(&mut c.a, e);
            shift(&mut c.b, e);
        }
    }
}

/// `x` as a [`super::Number`] in `field` = ℚ(√δ) (rational when `b = 0`): the same element
/// as [`super::curve::from_quadratic`] of [`Zq::to_quadratic`], without the rational gcds.
pub(crate) fn to_number(x: Zq, field: Option<&qsic_algebra::field::NumberField>) -> super::Number {
    match field {
        Some(k) if !x.b.is_zero() => k.linear_element(x.a, x.b),
        _ => {
            debug_assert!(x.b.is_zero(), "an irrational coefficient needs its field");
            qsic_algebra::field::NumberFieldElement::integer(x.a)
        }
    }
}

/// `p / 2^e` over ℚ(√δ).
pub(crate) fn to_poly_down(p: &[Zq], delta: &IBig, e: usize) -> Poly<Quadratic> {
    if e == 0 {
        return to_poly(p, delta);
    }
    let den = dashu_int::UBig::ONE << e;
    let part = |v: &IBig| RBig::from_parts(v.clone(), den.clone());
    let root = root_of(p, delta);
    Poly::new(
        p.iter()
            .map(|c| {
                if c.b.is_zero() {
                    Quadratic::rational(part(&c.a))
                } else {
                    Quadratic::in_field_of(part(&c.a), part(&c.b), &root)
                }
            })
            .collect(),
    )
}

/// `p` as a [`super::NumberPoly`] over `field` = ℚ(√δ) ([`to_number`]).
pub(crate) fn to_number_poly(
    mut p: ZPoly,
    field: Option<&qsic_algebra::field::NumberField>,
) -> super::NumberPoly {
    // a + b√δ = 0 exactly when a = b = 0 (δ not a square): the zero test on integers
    trim(&mut p);
    Poly::from_trimmed(p.into_iter().map(|c| to_number(c, field)).collect())
}

/// Makes the integers of a doubly ruled surface's ruling `b(u) + v·d(u)` (`b`, `d` of
/// degree ≤ 1) small without changing the surface or its lines. The coefficients form a
/// 2 × 2 array of vectors (`b`/`d` by the coefficients of `1`/`u`), and each mode may be
/// changed by a constant invertible 2 × 2 matrix: on `b`/`d` it is a change of `v`
/// (`b + v·d = (α + γv)·b′ + (β + δv)·d′`), on `1`/`u` a Möbius change of `u`. Each pair is
/// divided by its content and Lagrange-reduced as vectors of integers (the multiplier `k`
/// chosen in floats: any integer is a valid change), a few rounds, in checked `i128`.
/// Returns `false` (nothing changed) when a coordinate has degree above 1 or a number
/// leaves `i128`.
pub(crate) fn reduce_ruling(b: &mut [ZPoly; 4], d: &mut [ZPoly; 4]) -> bool {
    if b.iter().chain(d.iter()).any(|p| p.len() > 2) {
        return false;
    }
    // t[w][j][2i + part]: w = 0 for b, 1 for d; j the power of u; i the coordinate; part
    // 0 the rational and 1 the √δ part
    let mut t = [[[0i128; 8]; 2]; 2];
    for (w, v) in [&*b, &*d].into_iter().enumerate() {
        for (i, p) in v.iter().enumerate() {
            for (j, c) in p.iter().enumerate() {
                let (Ok(x), Ok(y)) = (i128::try_from(&c.a), i128::try_from(&c.b)) else {
                    return false;
                };
                t[w][j][2 * i] = x;
                t[w][j][2 * i + 1] = y;
            }
        }
    }
    if reduce_array(&mut t).is_none() {
        return false;
    }
    for (w, v) in [b, d].into_iter().enumerate() {
        for (i, p) in v.iter_mut().enumerate() {
            *p = (0..2)
                .map(|j| Zq {
                    a: big_int(t[w][j][2 * i]),
                    b: big_int(t[w][j][2 * i + 1]),
                })
                .collect();
            trim(p);
        }
    }
    true
}

/// [`reduce_ruling`] straight from the ruling over ℚ(√δ) (`δ = 0` over ℚ): the integers
/// read into machine words without the [`Zq`] in between. `None` when a coefficient is not
/// integral, has another radicand or leaves `i128`, a coordinate has degree above 1, or the
/// reduction overflows (the caller then takes [`zvector`] and [`reduce_ruling`], which
/// decide those cases).
pub(crate) fn reduced_ruling(
    b: &[Poly<Quadratic>; 4],
    d: &[Poly<Quadratic>; 4],
    delta: &IBig,
) -> Option<([ZPoly; 4], [ZPoly; 4])> {
    let int = |v: &RBig| -> Option<i128> {
        if *v.denominator() != dashu_int::UBig::ONE {
            return None;
        }
        match i64::try_from(v.numerator()) {
            Ok(x) => Some(i128::from(x)),
            Err(_) => i128::try_from(v.numerator()).ok(),
        }
    };
    let mut t = [[[0i128; 8]; 2]; 2];
    for (w, v) in [b, d].into_iter().enumerate() {
        for (i, p) in v.iter().enumerate() {
            if p.coeffs().len() > 2 {
                return None;
            }
            for (j, c) in p.coeffs().iter().enumerate() {
                if c.as_rational().is_none() && c.radicand() != delta {
                    return None;
                }
                t[w][j][2 * i] = int(c.rational_part())?;
                t[w][j][2 * i + 1] = int(c.radical_part())?;
            }
        }
    }
    reduce_array(&mut t)?;
    let out = |w: usize| -> [ZPoly; 4] {
        std::array::from_fn(|i| {
            let mut p: ZPoly = (0..2)
                .map(|j| Zq {
                    a: big_int(t[w][j][2 * i]),
                    b: big_int(t[w][j][2 * i + 1]),
                })
                .collect();
            trim(&mut p);
            p
        })
    };
    Some((out(0), out(1)))
}

/// `⌊√n⌋` if `n ≥ 0` is a perfect square.
pub(crate) fn exact_sqrt(n: i128) -> Option<i128> {
    if n < 0 {
        return None;
    }
    // squares are 0, 1, 4, 9, 16, 17, 25, 33, 36, 41, 49, 57 modulo 64
    if (0x0202_0212_0203_0213u64 >> (n & 63)) & 1 == 0 {
        return None;
    }
    if let Ok(v) = u64::try_from(n) {
        // squares are 16 of the 63 residues modulo 63 (bit k of the mask: k a square)
        if (0x0402_4830_1245_0293u64 >> (v % 63)) & 1 == 0 {
            return None;
        }
        // the float root is within one of ⌊√v⌋; the products in u128, one multiplication
        let sq = |r: u64| u128::from(r) * u128::from(r);
        let mut r = (v as f64).sqrt() as u64;
        while sq(r) > u128::from(v) {
            r -= 1;
        }
        while sq(r + 1) <= u128::from(v) {
            r += 1;
        }
        return (sq(r) == u128::from(v)).then_some(i128::from(r));
    }
    let mut r = (n as f64).sqrt() as i128;
    while r * r > n {
        r -= 1;
    }
    while (r + 1) * (r + 1) <= n {
        r += 1;
    }
    (r * r == n).then_some(r)
}
