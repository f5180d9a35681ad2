//! Fraction-free arithmetic in ℤ[√δ]: the integer fast path of [`super::surface`].
//!
//! `ℚ(√δ)` elements as [`Quadratic`] normalise two rationals (two gcds) at every operation;
//! the rulings, the forms `c₀, c₁, c₂` and `s(u)` only need sums and products of integral
//! elements `a + b√δ` (`a, b ∈ ℤ`), which here cost a few integer products and no gcd:
//! `(a + b√δ)(c + e√δ) = (ac + δbe) + (ae + bc)√δ`. Values are converted back to
//! [`Quadratic`] at the end; the results are identical.

use qsic_algebra::field::Quadratic;
use qsic_algebra::{IBig, Poly, RBig, Sign};

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

/// The rounds of [`reduce_ruling`] on `t[w][j]`; `None` on overflow (`t` is then partly
/// changed, by valid changes only).
///
/// Each Lagrange step `x ← x − k·y` keeps the floats of the two vectors beside the integers:
/// updated in floats when every number involved is below `2⁵³` (then the float update is
/// exact, the same floats as a conversion), else converted again; the integer update goes
/// without overflow checks when the bit lengths exclude overflow.
fn reduce_array(t: &mut [[[i128; 8]; 2]; 2]) -> Option<()> {
    // the two halves of a mode: (w, j) cells
    let cells = |mode: usize, k: usize| -> [(usize, usize); 2] {
        if mode == 0 {
            [(k, 0), (k, 1)]
        } else {
            [(0, k), (1, k)]
        }
    };
    for _round in 0..2 {
        let mut changed = false;
        for mode in 0..2 {
            // the two halves as 16-vectors
            let mut v: [[i128; 16]; 2] = [[0; 16]; 2];
            for (k, half) in v.iter_mut().enumerate() {
                for (h, (w, j)) in cells(mode, k).into_iter().enumerate() {
                    half[8 * h..8 * h + 8].copy_from_slice(&t[w][j]);
                }
                let g = content16(half);
                if g > 1 {
                    changed = true;
                    divide16(half, g)?;
                }
            }
            let mut f = [to_f64_16(&v[0]), to_f64_16(&v[1])];
            let mut bits = [bits16(&v[0]), bits16(&v[1])];
            for _ in 0..8 {
                // the three dot products in one pass, each summed in index order (as
                // `Iterator::sum` from −0: the same floats)
                let (mut nx, mut ny, mut nxy) = (-0.0f64, -0.0f64, -0.0f64);
                for (a, b) in f[0].iter().zip(&f[1]) {
                    nx += a * a;
                    ny += b * b;
                    nxy += a * b;
                }
                let (small, big, nsmall) = if nx <= ny { (0, 1, nx) } else { (1, 0, ny) };
                let kf = (nxy / nsmall).round();
                if !(kf.is_finite() && kf != 0.0 && kf.abs() < 1e30) {
                    break;
                }
                let k = kf as i128;
                changed = true;
                let bk = bit_len(k);
                let (bs, bb) = (bits[small], bits[big]);
                let (ys, yb) = if small == 0 {
                    let [a, b] = &mut v;
                    (&*a, b)
                } else {
                    let [a, b] = &mut v;
                    (&*b, a)
                };
                if bk + bs <= 125 && bb <= 125 {
                    // |k·y| < 2¹²⁵ and |x| < 2¹²⁵: no overflow
                    for (x, y) in yb.iter_mut().zip(ys) {
                        *x -= k * y;
                    }
                } else {
                    for (x, y) in yb.iter_mut().zip(ys) {
                        *x = x.checked_sub(k.checked_mul(*y)?)?;
                    }
                }
                let nb = bits16(yb);
                if bk + bs <= 52 && bb <= 52 && nb <= 53 {
                    // every float exact: the same as converting again
                    let (fs, fb) = if small == 0 {
                        let [a, b] = &mut f;
                        (&*a, b)
                    } else {
                        let [a, b] = &mut f;
                        (&*b, a)
                    };
                    for (x, y) in fb.iter_mut().zip(fs) {
                        *x -= kf * y;
                    }
                } else {
                    f[big] = to_f64_16(yb);
                }
                bits[big] = nb;
            }
            for (k, half) in v.iter().enumerate() {
                for (h, (w, j)) in cells(mode, k).into_iter().enumerate() {
                    t[w][j].copy_from_slice(&half[8 * h..8 * h + 8]);
                }
            }
        }
        if !changed {
            break;
        }
    }
    Some(())
}

/// `v` as a big integer: from `i64` when it fits (the common case, cheaper than the
/// conversion of an `i128`).
fn big_int(v: i128) -> IBig {
    match i64::try_from(v) {
        Ok(x) => IBig::from(x),
        Err(_) => IBig::from(v),
    }
}

/// The bit length of the largest `|v|` of `x`.
fn bits16(x: &[i128; 16]) -> u32 {
    bit_len_u(x.iter().fold(0u128, |acc, v| acc | v.unsigned_abs()))
}

fn bit_len_u(v: u128) -> u32 {
    128 - v.leading_zeros()
}

/// `x` in floats: one instruction for a value of `i64`, else the two halves (the library
/// call of `v as f64` costs more; the floats only choose a multiplier).
fn to_f64_16(x: &[i128; 16]) -> [f64; 16] {
    x.map(|v| {
        let small = v as i64;
        if i128::from(small) == v {
            small as f64
        } else {
            ((v >> 64) as i64 as f64) * 18_446_744_073_709_551_616.0 + (v as u64 as f64)
        }
    })
}

/// The gcd of the `|v|` of `x` (0 for all zeros): Euclid in `u64` while the numbers fit
/// (the common case), else in `u128`; stops at 1.
fn content16(x: &[i128; 16]) -> u128 {
    let mut g = 0u128;
    for v in x {
        let mut y = v.unsigned_abs();
        if y == 0 {
            continue;
        }
        if g == 0 {
            g = y;
            continue;
        }
        if let (Ok(mut a), Ok(mut b)) = (u64::try_from(g), u64::try_from(y)) {
            while b != 0 {
                (a, b) = (b, a % b);
            }
            g = u128::from(a);
        } else {
            while y != 0 {
                (g, y) = (y, g % y);
            }
        }
        if g == 1 {
            return 1;
        }
    }
    g
}

/// `x / g` for a common divisor `g > 1` of `x`; `None` if `g` leaves `i128`.
fn divide16(x: &mut [i128; 16], g: u128) -> Option<()> {
    if bits16(x) <= 63 {
        // g divides a nonzero entry below 2⁶³
        let g = g as i64;
        for v in x.iter_mut() {
            *v = i128::from(*v as i64 / g);
        }
        return Some(());
    }
    let g = i128::try_from(g).ok()?;
    for v in x.iter_mut() {
        *v /= g;
    }
    Some(())
}

/// `a + b√δ` in machine integers: the small-number path of the forms (every operation
/// checked; `None` on overflow sends the caller to [`Zq`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Zi {
    a: i128,
    b: i128,
}

impl Zi {
    fn of(x: &Zq) -> Option<Zi> {
        Some(Zi {
            a: i128::try_from(&x.a).ok()?,
            b: i128::try_from(&x.b).ok()?,
        })
    }

    fn big(self) -> Zq {
        Zq {
            a: big_int(self.a),
            b: big_int(self.b),
        }
    }

    fn mul(self, o: Zi, delta: i128) -> Option<Zi> {
        if self.b == 0 {
            return Some(Zi {
                a: mul_i(self.a, o.a)?,
                b: mul_i(self.a, o.b)?,
            });
        }
        if o.b == 0 {
            return Some(Zi {
                a: mul_i(self.a, o.a)?,
                b: mul_i(self.b, o.a)?,
            });
        }
        Some(Zi {
            a: mul_i(self.a, o.a)?.checked_add(mul_i(mul_i(self.b, o.b)?, delta)?)?,
            b: mul_i(self.a, o.b)?.checked_add(mul_i(self.b, o.a)?)?,
        })
    }

    fn add(self, o: Zi) -> Option<Zi> {
        Some(Zi {
            a: self.a.checked_add(o.a)?,
            b: self.b.checked_add(o.b)?,
        })
    }

    fn sub(self, o: Zi) -> Option<Zi> {
        Some(Zi {
            a: self.a.checked_sub(o.a)?,
            b: self.b.checked_sub(o.b)?,
        })
    }
}

/// `x·y`, `None` on overflow: without the overflow check when the bit lengths add up to
/// at most 126 (then `|x·y| < 2¹²⁶`), the common case here.
fn mul_i(x: i128, y: i128) -> Option<i128> {
    let bits = |v: i128| 128 - v.unsigned_abs().leading_zeros();
    if bits(x) + bits(y) <= 126 {
        Some(x * y)
    } else {
        x.checked_mul(y)
    }
}

/// A doubly ruled surface's ruling `b(u) + v·d(u)` (`b`, `d` of degree ≤ 1) over ℤ[√δ] in
/// machine integers, in the layout of [`reduce_array`]: `t[w][j][2i + part]` with `w` 0 for
/// `b` and 1 for `d`, `j` the power of `u`, `i` the coordinate, `part` 0 the rational and 1
/// the `√δ` part; `delta` 0 when every coefficient is rational.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct FixedRuling {
    pub(crate) delta: i128,
    pub(crate) t: [[[i128; 8]; 2]; 2],
}

/// What [`ruling_fixed`] finds.
// One value per call, matched at once: boxing the ruling would only add an allocation.
#[allow(clippy::large_enum_variant)]
#[derive(Debug)]
pub(crate) enum Through {
    Ruling(FixedRuling),
    /// The lines through the point are not over ℚ(√δ) (`δ` not the square-free part of
    /// `det M`).
    NotInField,
    /// A bound on the bit lengths passed `2¹²⁶`: the checked route decides.
    Overflow,
}

impl FixedRuling {
    /// The coefficient `i` (`w` 0 for `b`, 1 for `d`) as a polynomial in `u`, trimmed.
    fn coordinate(&self, w: usize, i: usize) -> [Zi; 2] {
        std::array::from_fn(|j| Zi {
            a: self.t[w][j][2 * i],
            b: self.t[w][j][2 * i + 1],
        })
    }

    /// `b` and `d` over ℤ[√δ] ([`ZPoly`], no trailing zeros).
    pub(crate) fn to_zpolys(self) -> ([ZPoly; 4], [ZPoly; 4]) {
        let out = |w: usize| -> [ZPoly; 4] {
            std::array::from_fn(|i| {
                let c = self.coordinate(w, i);
                let n = c
                    .iter()
                    .rposition(|v| *v != Zi::default())
                    .map_or(0, |k| k + 1);
                c[..n].iter().map(|v| v.big()).collect()
            })
        };
        (out(0), out(1))
    }

    /// The public ruling over ℚ(√δ) (one square root for all the coefficients).
    pub(crate) fn to_ruling(self) -> super::surface::RuledParameterization {
        let delta = IBig::from(self.delta);
        let (b, d) = self.to_zpolys();
        super::surface::RuledParameterization {
            b: std::array::from_fn(|i| to_poly(&b[i], &delta)),
            d: std::array::from_fn(|i| to_poly(&d[i], &delta)),
            delta: (self.delta != 0).then_some(delta),
        }
    }

    /// [`reduce_ruling`] in place; left as it is when the reduction overflows.
    pub(crate) fn reduce(&mut self) {
        let mut t = self.t;
        if reduce_array(&mut t).is_some() {
            self.t = t;
        }
    }
}

impl Zi {
    fn int(a: i128) -> Zi {
        Zi { a, b: 0 }
    }

    /// `x + y`, `x − y`, `−x`, `k·x` without overflow checks (the callers bound the sizes).
    fn plus(self, o: Zi) -> Zi {
        Zi {
            a: self.a + o.a,
            b: self.b + o.b,
        }
    }

    fn minus(self, o: Zi) -> Zi {
        Zi {
            a: self.a - o.a,
            b: self.b - o.b,
        }
    }

    fn negated(self) -> Zi {
        Zi {
            a: -self.a,
            b: -self.b,
        }
    }

    fn scaled(self, k: i128) -> Zi {
        Zi {
            a: self.a * k,
            b: self.b * k,
        }
    }
}

/// The bit length of the largest weight `|a| + |b|√δ` of `x` from above (`√|δ| < 2^h`):
/// `max(bits(a), bits(b) + h) + 1`.
#[inline]
fn weight(x: &[Zi], h: u32) -> u32 {
    let (a, b) = x.iter().fold((0u128, 0u128), |(a, b), v| {
        (a | v.a.unsigned_abs(), b | v.b.unsigned_abs())
    });
    let wb = if b == 0 { 0 } else { bit_len_u(b) + h };
    bit_len_u(a).max(wb) + 1
}

/// The bit length of the largest `|v|` of `x`.
fn bits_of(x: &[i128]) -> u32 {
    bit_len_u(x.iter().fold(0u128, |acc, v| acc | v.unsigned_abs()))
}

/// `x` divided by the gcd of its integers `a`, `b` (nothing when it is 0 or 1): in machine
/// words when every part fits `i64` (the common case).
fn make_primitive(x: &mut [Zi]) {
    if narrow(x) {
        let mut g = 0u64;
        for v in x.iter() {
            for part in [v.a as i64, v.b as i64] {
                if part != 0 && g != 1 {
                    let (mut p, mut q) = (g, part.unsigned_abs());
                    while q != 0 {
                        (p, q) = (q, p % q);
                    }
                    g = p;
                }
            }
        }
        if g > 1 {
            // g divides a nonzero part below 2⁶³
            let g = g as i64;
            for v in x.iter_mut() {
                v.a = i128::from(v.a as i64 / g);
                v.b = i128::from(v.b as i64 / g);
            }
        }
        return;
    }
    let mut g = 0u128;
    for v in x.iter() {
        for part in [v.a, v.b] {
            if part != 0 && g != 1 {
                g = gcd_u128(g, part.unsigned_abs());
            }
        }
    }
    if g > 1 {
        // exact division: the power of two shifted out, then a product by the inverse of
        // the odd part modulo 2¹²⁸ (Newton: each step doubles the correct low bits, from 3)
        let s = g.trailing_zeros();
        let odd = g >> s;
        let mut inverse = odd;
        for _ in 0..6 {
            inverse = inverse.wrapping_mul(2u128.wrapping_sub(odd.wrapping_mul(inverse)));
        }
        let divide = |v: i128| ((v >> s) as u128).wrapping_mul(inverse) as i128;
        for v in x.iter_mut() {
            v.a = divide(v.a);
            v.b = divide(v.b);
        }
    }
}

/// `gcd(x, y)` (`gcd(0, y) = y`): Euclid in `u64` while the numbers fit.
fn gcd_u128(mut x: u128, mut y: u128) -> u128 {
    while y != 0 {
        if let (Ok(mut a), Ok(mut b)) = (u64::try_from(x), u64::try_from(y)) {
            while b != 0 {
                (a, b) = (b, a % b);
            }
            return u128::from(a);
        }
        (x, y) = (y, x % y);
    }
    x
}

/// `v` in floats, correctly rounded (as `v as f64`), one instruction for a value of `i64`.
fn to_f64(v: i128) -> f64 {
    let small = v as i64;
    if i128::from(small) == v {
        small as f64
    } else {
        v as f64
    }
}

/// The ruling of the integer matrix `M` (entries of the member, `k·S`) through its integer
/// point `p`: the construction of `surface::ruling_through` (the same numbers: the same
/// steps, contents and balancing) in `i128` without overflow checks, each step guarded by
/// a bound on the bit lengths of its operands ([`weight`]: a sum of `n` products of weights
/// below `2^x` and `2^y` stays below `2^(x + y + ⌈log₂ n⌉)`, at most `2¹²⁶`);
/// [`Through::Overflow`] when a guard fails. `δ` is the square-free part of `det M` (1 for a
/// square).
///
/// # Errors
/// [`Error::Algebra`] as `surface::ruling_through` (`p` in the kernel, lines not real or not
/// distinct).
pub(crate) fn ruling_fixed(
    m: &[[i128; 4]; 4],
    p: &[i128; 4],
    delta: i128,
) -> Result<Through, crate::error::Error> {
    use crate::error::Error;
    macro_rules! fit {
        ($bits:expr) => {
            if $bits > 126 {
                return Ok(Through::Overflow);
            }
        };
    }
    let irrational = delta != 1;
    let dt = if irrational { delta } else { 0 };
    let h = bit_len(dt).div_ceil(2);
    let bm = bits_of(m.as_flattened());
    let primitive = |v: [i128; 4]| -> [i128; 4] {
        let g = v.iter().fold(0u128, |g, x| gcd_u128(g, x.unsigned_abs()));
        if g <= 1 {
            v
        } else if v.iter().all(|x| x.unsigned_abs() < 1 << 63) {
            let g = g as i64;
            v.map(|x| i128::from(x as i64 / g))
        } else {
            let g = g as i128;
            v.map(|x| x / g)
        }
    };
    let mv = |x: &[i128; 4]| -> [i128; 4] {
        std::array::from_fn(|i| m[i][0] * x[0] + m[i][1] * x[1] + m[i][2] * x[2] + m[i][3] * x[3])
    };
    let dot = |x: &[i128; 4], y: &[i128; 4]| -> i128 {
        x[0] * y[0] + x[1] * y[1] + x[2] * y[2] + x[3] * y[3]
    };
    let p = primitive(*p);
    fit!(bm + bits_of(&p) + 2);
    let r = mv(&p);
    let j = r
        .iter()
        .position(|&v| v != 0)
        .ok_or_else(|| Error::Algebra("a point in the kernel of a nonsingular quadric".into()))?;
    let k0 = (0..4)
        .find(|&k| k != j && p[k] != 0)
        .ok_or_else(|| Error::Algebra("tangent plane basis".into()))?;
    let mut rest = (0..4).filter(|&k| k != j && k != k0);
    let kernel = |k: usize| -> [i128; 4] {
        let mut v = [0i128; 4];
        v[k] = r[j];
        v[j] = -r[k];
        primitive(v)
    };
    let e1 = kernel(rest.next().expect("two kernel vectors"));
    let e2 = kernel(rest.next().expect("two kernel vectors"));
    let be = bits_of(&e1).max(bits_of(&e2));
    // M·e below 2^(bm + be + 2), eᵀMe below 2^(2be + bm + 4)
    fit!(2 * be + bm + 4);
    let (me1, me2) = (mv(&e1), mv(&e2));
    let (s11, s12, s22) = (dot(&e1, &me1), dot(&e1, &me2), dot(&e2, &me2));
    let bs = bits_of(&[s11, s12, s22]);
    let (mut plus, mut minus): ([Zi; 4], [Zi; 4]) = if s11 == 0 {
        fit!(bs + be + 2);
        (
            e1.map(Zi::int),
            std::array::from_fn(|i| Zi::int(s22 * e1[i] - 2 * s12 * e2[i])),
        )
    } else {
        // the exact square root below needs its argument below 2¹²⁰
        if 2 * bs + 1 > 120 {
            return Ok(Through::Overflow);
        }
        let disc = s12 * s12 - s11 * s22;
        if disc <= 0 {
            return Err(Error::Algebra(
                "no real lines through a point of an inertia (2, 2) member".into(),
            ));
        }
        let root = if irrational {
            if disc % delta != 0 {
                return Ok(Through::NotInField);
            }
            exact_sqrt(disc / delta).map(|t| Zi { a: 0, b: t })
        } else {
            exact_sqrt(disc).map(Zi::int)
        };
        let Some(root) = root else {
            return Ok(Through::NotInField);
        };
        // (−s₁₂ ± t√δ)·e₁ + s₁₁·e₂
        fit!(weight(&[root], h).max(bs + 1) + be + 2);
        let line = |rt: Zi| -> [Zi; 4] {
            let k1 = Zi::int(-s12).plus(rt);
            std::array::from_fn(|i| k1.scaled(e1[i]).plus(Zi::int(s11 * e2[i])))
        };
        (line(root), line(root.negated()))
    };
    {
        let mut both = [Zi::default(); 8];
        both[..4].copy_from_slice(&plus);
        both[4..].copy_from_slice(&minus);
        make_primitive(&mut both);
        plus.copy_from_slice(&both[..4]);
        minus.copy_from_slice(&both[4..]);
    }
    // the balancing of `surface::ruling_through`: |E₊| about |p| by a power of two
    let root_delta = to_f64(dt).abs().sqrt();
    let size = |v: &[Zi]| -> f64 {
        // machine words convert in one instruction each (and exactly as `as f64`)
        if narrow(v) {
            let f = |x: i128| (x as i64) as f64;
            v.iter()
                .map(|x| f(x.a).abs() + f(x.b).abs() * root_delta)
                .fold(0.0, f64::max)
        } else {
            v.iter()
                .map(|x| to_f64(x.a).abs() + to_f64(x.b).abs() * root_delta)
                .fold(0.0, f64::max)
        }
    };
    let ratio = size(&p.map(Zi::int)) / size(&plus);
    if ratio.is_finite() && ratio >= 2.0 {
        let e = ratio.log2().floor() as u32;
        fit!(weight(&plus, h) + e);
        plus = plus.map(|x| x.scaled(1 << e));
    }
    let p = if ratio.is_finite() && ratio > 0.0 && ratio <= 0.5 {
        let e = (1.0 / ratio).log2().floor() as u32;
        fit!(bits_of(&p) + e);
        p.map(|x| x * (1 << e))
    } else {
        p
    };
    let zp = p.map(Zi::int);
    // M·x and x·y over ℤ[√δ], guarded
    let zmv = |x: &[Zi; 4]| -> Option<[Zi; 4]> {
        (bm + weight(x, h) + 2 <= 126).then(|| {
            std::array::from_fn(|i| {
                (0..4).fold(Zi::default(), |acc, k| acc.plus(x[k].scaled(m[i][k])))
            })
        })
    };
    let zdot = |x: &[Zi; 4], y: &[Zi; 4]| -> Option<Zi> {
        (weight(x, h) + weight(y, h) + 2 <= 126).then(|| {
            (0..4).fold(Zi::default(), |acc, k| {
                acc.plus(mul_unchecked(x[k], y[k], dt))
            })
        })
    };
    // α·x − β·y
    let comb = |al: Zi, x: &[Zi; 4], be: Zi, y: &[Zi; 4]| -> Option<[Zi; 4]> {
        let bound = (weight(&[al], h) + weight(x, h)).max(weight(&[be], h) + weight(y, h)) + 1;
        (bound <= 126).then(|| {
            std::array::from_fn(|i| mul_unchecked(al, x[i], dt).minus(mul_unchecked(be, y[i], dt)))
        })
    };
    macro_rules! ck {
        ($e:expr) => {
            match $e {
                Some(v) => v,
                None => return Ok(Through::Overflow),
            }
        };
    }
    let m_minus = ck!(zmv(&minus));
    let c = ck!(zdot(&plus, &m_minus));
    if c == Zi::default() {
        return Err(Error::Algebra(
            "the two lines through a point are not distinct".into(),
        ));
    }
    // g₀ = c·e_j − (ME₋)_j·E₊
    let mut ej = [Zi::default(); 4];
    ej[j] = Zi::int(1);
    let mut g0 = ck!(comb(c, &ej, m_minus[j], &plus));
    make_primitive(&mut g0);
    let g0_plus = ck!(zdot(&g0, &ck!(zmv(&plus))));
    let mut g1 = ck!(comb(c, &g0, g0_plus, &minus));
    make_primitive(&mut g1);
    let mg1 = ck!(zmv(&g1));
    let rho = ck!(zdot(&zp, &mg1));
    let g1g1 = ck!(zdot(&g1, &mg1));
    fit!(weight(&[rho], h) + 1);
    let two_rho = rho.scaled(2);
    let f = ck!(comb(two_rho, &g1, g1g1, &zp));
    fit!(2 * weight(&[rho], h) + 1);
    let two_rho2 = mul_unchecked(rho, rho, dt).scaled(2);
    fit!((weight(&[two_rho2], h) + weight(&minus, h)).max(weight(&[c], h) + weight(&f, h)));
    // b = p − u·E₊, d = 2ρ²·E₋ + u·c·f, each made primitive
    let mut bz = [Zi::default(); 8];
    let mut dz = [Zi::default(); 8];
    for i in 0..4 {
        bz[2 * i] = zp[i];
        bz[2 * i + 1] = plus[i].negated();
        dz[2 * i] = mul_unchecked(two_rho2, minus[i], dt);
        dz[2 * i + 1] = mul_unchecked(c, f[i], dt);
    }
    make_primitive(&mut bz);
    make_primitive(&mut dz);
    let mut t = [[[0i128; 8]; 2]; 2];
    for (w, z) in [bz, dz].iter().enumerate() {
        for i in 0..4 {
            for jj in 0..2 {
                t[w][jj][2 * i] = z[2 * i + jj].a;
                t[w][jj][2 * i + 1] = z[2 * i + jj].b;
            }
        }
    }
    let any_irrational = bz.iter().chain(&dz).any(|v| v.b != 0);
    Ok(Through::Ruling(FixedRuling {
        delta: if any_irrational { dt } else { 0 },
        t,
    }))
}

/// `⌊√n⌋` if `0 ≤ n < 2¹²⁰` is a perfect square.
fn exact_sqrt(n: i128) -> Option<i128> {
    super::surface::exact_sqrt(n)
}

/// [`levin_small`]'s `s`, `a`, `alt` in big integers: the route when a number leaves
/// `i128` (and the reference its tests compare with).
pub(crate) fn levin_big(
    m: &[[IBig; 4]; 4],
    b: &[ZPoly; 4],
    d: &[ZPoly; 4],
    delta: &IBig,
) -> LevinForms {
    let (c0, c1, c2) = forms_checked(m, b, d, delta).unwrap_or_else(|| {
        (
            poly_form(m, b, b, delta),
            poly_form(m, b, d, delta),
            poly_form(m, d, d, delta),
        )
    });
    levin_from_forms(b, d, delta, c0, c1, c2)
}

/// [`levin_big`] from the forms `c₀ = bᵀMb`, `c₁ = bᵀMd`, `c₂ = dᵀMd` (the products in big
/// integers).
fn levin_from_forms(
    b: &[ZPoly; 4],
    d: &[ZPoly; 4],
    delta: &IBig,
    c0: ZPoly,
    c1: ZPoly,
    c2: ZPoly,
) -> LevinForms {
    let s = poly_sub(&poly_mul(&c1, &c1, delta), &poly_mul(&c0, &c2, delta));
    let combine = |x: &[Zq], y: &[Zq]| -> [ZPoly; 4] {
        std::array::from_fn(|i| poly_sub(&poly_mul(x, &b[i], delta), &poly_mul(y, &d[i], delta)))
    };
    (s, combine(&c2, &c1), combine(&c1, &c0))
}

/// The forms `c₀ = bᵀMb`, `c₁ = bᵀMd`, `c₂ = dᵀMd` of [`levin_big`] in `i128` with every
/// operation checked, when `M`, `δ` and the coefficients of `b` and `d` (at most 3 each) are
/// machine integers and the forms fit (they often do where `s`, `a`, `alt` do not: their
/// products then go to big integers); `None` otherwise.
fn forms_checked(
    m: &[[IBig; 4]; 4],
    b: &[ZPoly; 4],
    d: &[ZPoly; 4],
    delta: &IBig,
) -> Option<(ZPoly, ZPoly, ZPoly)> {
    let (mi, dl) = machine_matrix(m, delta)?;
    let fixed = fixed_rows(b, d)?;
    let bi: [&[Zi]; 4] = std::array::from_fn(|i| &fixed[i][..b[i].len()]);
    let di: [&[Zi]; 4] = std::array::from_fn(|i| &fixed[4 + i][..d[i].len()]);
    let form = |x: &[&[Zi]; 4], y: &[&[Zi]; 4]| -> Option<ZPoly> {
        let c = form_fixed(&mi, x, y, dl, true)?;
        let n = c
            .iter()
            .rposition(|v| *v != Zi::default())
            .map_or(0, |k| k + 1);
        Some(c[..n].iter().map(|v| v.big()).collect())
    };
    Some((form(&bi, &bi)?, form(&bi, &di)?, form(&di, &di)?))
}

/// Levin's whole form in machine integers: `s = c₁² − c₀c₂`, `a = c₂b − c₁d` and
/// `alt = c₁b − c₀d` with `c₀ = bᵀMb`, `c₁ = bᵀMd`, `c₂ = dᵀMd` over ℤ[√δ], in fixed
/// buffers, converted to [`Zq`] once ([`levin_big`] computes the same): each stage without
/// overflow checks when size bounds exclude overflow ([`levin_fixed`], the common case),
/// else checked; `None` when a number leaves `i128` or a coordinate of the ruling has more
/// than 3 coefficients.
pub(crate) fn levin_small(
    m: &[[IBig; 4]; 4],
    b: &[ZPoly; 4],
    d: &[ZPoly; 4],
    delta: &IBig,
) -> Option<LevinForms> {
    let (mi, dl) = machine_matrix(m, delta)?;
    levin_fixed(&mi, b, d, dl, false).map(|(forms, _)| forms)
}

/// `M` and `δ` in `i128`, `None` past it.
fn machine_matrix(m: &[[IBig; 4]; 4], delta: &IBig) -> Option<([[i128; 4]; 4], i128)> {
    let mut mi = [[0i128; 4]; 4];
    for (row, src) in mi.iter_mut().zip(m) {
        for (x, v) in row.iter_mut().zip(src) {
            *x = i128::try_from(v).ok()?;
        }
    }
    Some((mi, i128::try_from(delta).ok()?))
}

/// The coefficients of `b` (rows 0–3) and `d` (rows 4–7) in fixed `i128` buffers; `None`
/// when one leaves `i128` or a coordinate has more than 3 coefficients.
fn fixed_rows(b: &[ZPoly; 4], d: &[ZPoly; 4]) -> Option<[[Zi; 3]; 8]> {
    if b.iter().chain(d).any(|p| p.len() > 3) {
        return None;
    }
    let mut fixed = [[Zi::default(); 3]; 8];
    for (k, p) in b.iter().chain(d).enumerate() {
        for (slot, c) in fixed[k].iter_mut().zip(p) {
            *slot = Zi::of(c)?;
        }
    }
    Some(fixed)
}

/// The bit length of `|v|`.
fn bit_len(v: i128) -> u32 {
    128 - v.unsigned_abs().leading_zeros()
}

/// `x·y` in ℤ[√δ] without overflow checks (the caller's bounds exclude overflow).
fn mul_unchecked(x: Zi, y: Zi, delta: i128) -> Zi {
    if x.b == 0 {
        return Zi {
            a: x.a * y.a,
            b: x.a * y.b,
        };
    }
    Zi {
        a: x.a * y.a + x.b * y.b * delta,
        b: x.a * y.b + x.b * y.a,
    }
}

/// `xᵀMy` into a fixed buffer (`x`, `y` of at most 3 coefficients), without overflow checks
/// when `checked` is false (the caller's bounds exclude overflow); `None` on overflow.
fn form_fixed(
    m: &[[i128; 4]; 4],
    x: &[&[Zi]; 4],
    y: &[&[Zi]; 4],
    delta: i128,
    checked: bool,
) -> Option<[Zi; 5]> {
    let mut acc = [Zi::default(); 5];
    for i in 0..4 {
        let mut row = [Zi::default(); 3];
        for j in 0..4 {
            let k = Zi { a: m[i][j], b: 0 };
            if k.a != 0 {
                for (r, c) in row.iter_mut().zip(y[j]) {
                    *r = if checked {
                        r.add(k.mul(*c, delta)?)?
                    } else {
                        Zi {
                            a: r.a + k.a * c.a,
                            b: r.b + k.a * c.b,
                        }
                    };
                }
            }
        }
        for (e, xc) in x[i].iter().enumerate() {
            if *xc == Zi::default() {
                continue;
            }
            for (f, rc) in row.iter().enumerate() {
                let o = &mut acc[e + f];
                *o = if checked {
                    o.add(xc.mul(*rc, delta)?)?
                } else {
                    let p = mul_unchecked(*xc, *rc, delta);
                    Zi {
                        a: o.a + p.a,
                        b: o.b + p.b,
                    }
                };
            }
        }
    }
    Some(acc)
}

/// A polynomial over ℤ[√δ] in a fixed buffer: the coefficients `c[..n]`, no trailing zeros.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct FixedPoly<const N: usize> {
    c: [Zi; N],
    n: usize,
}

impl<const N: usize> FixedPoly<N> {
    fn coeffs(&self) -> &[Zi] {
        &self.c[..self.n]
    }

    fn to_zpoly(self) -> ZPoly {
        self.coeffs().iter().map(|v| v.big()).collect()
    }

    /// [`to_number_poly`] of [`Self::to_zpoly`] without the big-integer polynomial between.
    fn to_number_poly(self, field: Option<&qsic_algebra::field::NumberField>) -> super::NumberPoly {
        let c = self.coeffs();
        let n = c
            .iter()
            .rposition(|v| *v != Zi::default())
            .map_or(0, |k| k + 1);
        Poly::from_trimmed(c[..n].iter().map(|v| to_number(v.big(), field)).collect())
    }

    /// Whether every coefficient `i` times `2^e(i)` stays below `2¹²⁶`.
    fn fits(&self, e: impl Fn(usize) -> usize) -> bool {
        self.coeffs().iter().enumerate().all(|(i, v)| {
            let b = bit_len(v.a).max(bit_len(v.b));
            b == 0 || b as usize + e(i) <= 126
        })
    }

    /// Coefficient `i` times `2^e(i)` (the caller checked [`Self::fits`]).
    fn shift(&mut self, e: impl Fn(usize) -> usize) {
        for (i, v) in self.c[..self.n].iter_mut().enumerate() {
            let k = e(i) as u32;
            v.a <<= k;
            v.b <<= k;
        }
    }
}

/// `x·y − z·w` of polynomials over ℤ[√δ] (product lengths at most `N`, else `None`) without
/// trailing zeros; without overflow checks when `checked` is false (as [`form_fixed`]).
fn cross_fixed<const N: usize>(
    x: &[Zi],
    y: &[Zi],
    z: &[Zi],
    w: &[Zi],
    delta: i128,
    checked: bool,
) -> Option<FixedPoly<N>> {
    let mut out = [Zi::default(); N];
    for (negate, p, q) in [(false, x, y), (true, z, w)] {
        if !p.is_empty() && !q.is_empty() && p.len() + q.len() - 1 > N {
            return None;
        }
        for (i, pc) in p.iter().enumerate() {
            if *pc == Zi::default() {
                continue;
            }
            for (j, qc) in q.iter().enumerate() {
                let o = &mut out[i + j];
                *o = if checked {
                    let v = pc.mul(*qc, delta)?;
                    if negate {
                        o.sub(v)?
                    } else {
                        o.add(v)?
                    }
                } else {
                    let v = mul_unchecked(*pc, *qc, delta);
                    if negate {
                        o.minus(v)
                    } else {
                        o.plus(v)
                    }
                };
            }
        }
    }
    let n = out
        .iter()
        .rposition(|c| *c != Zi::default())
        .map_or(0, |i| i + 1);
    Some(FixedPoly { c: out, n })
}

/// Levin's `s`, `a`, `alt` in fixed buffers ([`levin_core`]).
type FixedForms<const S: usize, const A: usize> =
    (FixedPoly<S>, [FixedPoly<A>; 4], [FixedPoly<A>; 4]);

/// [`levin_small`] on machine integers; also whether both stages ran without checks
/// (`always_check` forces the checks, for the tests).
fn levin_fixed(
    m: &[[i128; 4]; 4],
    b: &[ZPoly; 4],
    d: &[ZPoly; 4],
    delta: i128,
    always_check: bool,
) -> Option<(LevinForms, bool)> {
    let fixed = fixed_rows(b, d)?;
    let bi: [&[Zi]; 4] = std::array::from_fn(|i| &fixed[i][..b[i].len()]);
    let di: [&[Zi]; 4] = std::array::from_fn(|i| &fixed[4 + i][..d[i].len()]);
    let ((s, a, alt), unchecked) = levin_core::<9, 9>(m, &bi, &di, delta, always_check)?;
    Some((
        (
            s.to_zpoly(),
            a.map(FixedPoly::to_zpoly),
            alt.map(FixedPoly::to_zpoly),
        ),
        unchecked,
    ))
}

/// Levin's `s = c₁² − c₀c₂`, `a = c₂b − c₁d`, `alt = c₁b − c₀d` with `c₀ = bᵀMb`,
/// `c₁ = bᵀMd`, `c₂ = dᵀMd` over ℤ[√δ] in fixed buffers (`b`, `d` of at most 3
/// coefficients); also whether both stages ran without checks. `None` on overflow or when a
/// product does not fit the buffers.
///
/// The bounds: the size of `x = a + b√δ` is its weight `N(x) = |a| + |b|√|δ|`, which bounds
/// both parts (`|a| ≤ N`, `|b|·|δ| ≤ N·√|δ|`, so every partial product of an unchecked
/// product is below `N(x)N(y)`) and is submultiplicative, `N(xy) ≤ N(x)N(y)`; with
/// `√|δ| < 2^h`, `N(x) < 2^σ(x)`, `σ = max(bits(a), bits(b) + h) + 1`. With `σ_q` that of
/// the coefficients of `b` and `d` and `β_M` the bit length of `M`'s entries, a row
/// `Σⱼ Mᵢⱼ yⱼ` weighs below `2^(β_M+σ_q+2)` and a form's coefficient (at most 4·3 products)
/// below `2^(2σ_q+β_M+6)`: the forms go unchecked when that is at most `2¹²⁶`; then with
/// `σ₀`, `σ₁`, `σ₂` the largest sizes of their coefficients, `s = c₁² − c₀c₂` (at most 5
/// products each) weighs below `2^(max(2σ₁, σ₀+σ₂)+4)` and `a`, `alt` (2·3 products) below
/// `2^(max σᵢ + σ_q + 3)`: unchecked when at most `2¹²⁶`. Every partial sum is bounded by
/// its final bound.
fn levin_core<const S: usize, const A: usize>(
    m: &[[i128; 4]; 4],
    bi: &[&[Zi]; 4],
    di: &[&[Zi]; 4],
    delta: i128,
    always_check: bool,
) -> Option<(FixedForms<S, A>, bool)> {
    // √|δ| < 2^h: |δ| < 2^bits(δ) ≤ 2^(2h)
    let h = bit_len(delta).div_ceil(2);
    let size = |x: &Zi| bit_len(x.a).max(bit_len(x.b) + h) + 1;
    let bm = bits_of(m.as_flattened());
    let sq = bi.iter().chain(di).map(|p| weight(p, h)).max().unwrap_or(0);
    let checked = always_check || 2 * sq + bm + 6 > 126;
    let c0 = form_fixed(m, bi, bi, delta, checked)?;
    let c1 = form_fixed(m, bi, di, delta, checked)?;
    let c2 = form_fixed(m, di, di, delta, checked)?;
    // without their trailing zeros, and the size of each
    let trimmed = |c: &[Zi; 5]| -> (usize, u32) {
        let n = c
            .iter()
            .rposition(|v| *v != Zi::default())
            .map_or(0, |i| i + 1);
        (n, c[..n].iter().map(size).max().unwrap_or(0))
    };
    let ((n0, s0), (n1, s1), (n2, s2)) = (trimmed(&c0), trimmed(&c1), trimmed(&c2));
    let (c0, c1, c2) = (&c0[..n0], &c1[..n1], &c2[..n2]);
    let checked_products =
        always_check || (2 * s1).max(s0 + s2) + 4 > 126 || s2.max(s1).max(s0) + sq + 3 > 126;
    let s = cross_fixed::<S>(c1, c1, c0, c2, delta, checked_products)?;
    let mut a = [FixedPoly {
        c: [Zi::default(); A],
        n: 0,
    }; 4];
    let mut alt = a;
    for i in 0..4 {
        a[i] = cross_fixed::<A>(c2, bi[i], c1, di[i], delta, checked_products)?;
        alt[i] = cross_fixed::<A>(c1, bi[i], c0, di[i], delta, checked_products)?;
    }
    Some(((s, a, alt), !checked && !checked_products))
}

/// `x·y` in ℤ[√δ] without overflow checks, in products of machine words when `NARROW` (the
/// caller knows every part of `x`, `y` and `δ` to fit `i64`: each product one instruction).
#[inline(always)]
fn zmul<const NARROW: bool>(x: Zi, y: Zi, delta: i128) -> Zi {
    if NARROW {
        let w = |v: i128| i128::from(v as i64);
        Zi {
            a: w(x.a) * w(y.a) + w(x.b) * w(y.b) * w(delta),
            b: w(x.a) * w(y.b) + w(x.b) * w(y.a),
        }
    } else {
        mul_unchecked(x, y, delta)
    }
}

/// `x·y − z·w` of polynomials over ℤ[√δ] with `P` and `Q` coefficients into `N = P + Q − 1`,
/// without overflow checks (the caller's bounds exclude overflow).
#[inline(always)]
fn cross_lines<const NARROW: bool, const P: usize, const Q: usize, const N: usize>(
    x: &[Zi; P],
    y: &[Zi; Q],
    z: &[Zi; P],
    w: &[Zi; Q],
    delta: i128,
) -> FixedPoly<N> {
    debug_assert_eq!(P + Q - 1, N);
    let mut c = [Zi::default(); N];
    for i in 0..P {
        for j in 0..Q {
            c[i + j] = c[i + j]
                .plus(zmul::<NARROW>(x[i], y[j], delta))
                .minus(zmul::<NARROW>(z[i], w[j], delta));
        }
    }
    let n = c
        .iter()
        .rposition(|v| *v != Zi::default())
        .map_or(0, |k| k + 1);
    FixedPoly { c, n }
}

/// Whether every part of `x` fits `i64`.
fn narrow(x: &[Zi]) -> bool {
    x.iter()
        .all(|v| i128::from(v.a as i64) == v.a && i128::from(v.b as i64) == v.b)
}

/// [`levin_core`] for lines `b = b₀ + u·b₁`, `d = d₀ + u·d₁` (a symmetric `M`): the
/// products `M·b₀`, `M·b₁`, `M·d₀`, `M·d₁` once, the forms from ten dot products
/// (`c₀ = b₀ᵀMb₀ + 2u·b₀ᵀMb₁ + u²·b₁ᵀMb₁`, …), then `s`, `a`, `alt`; without overflow
/// checks, each stage guarded by the weights of its operands as in [`levin_core`] (a
/// coefficient of a form is a sum of at most two dot products of four products, below
/// `2^(2σ_q + β_M + 5)`; one of `s` at most six products of the forms', one of `a`, `alt`
/// four), in machine-word products where the parts fit `i64`. `None` when a guard fails.
fn levin_lines(m: &[[i128; 4]; 4], r: &FixedRuling) -> Option<FixedForms<5, 4>> {
    let dt = r.delta;
    let h = bit_len(dt).div_ceil(2);
    let vector = |w: usize, j: usize| -> [Zi; 4] {
        std::array::from_fn(|i| Zi {
            a: r.t[w][j][2 * i],
            b: r.t[w][j][2 * i + 1],
        })
    };
    // b₀, b₁, d₀, d₁
    let v = [vector(0, 0), vector(0, 1), vector(1, 0), vector(1, 1)];
    let sq = weight(v.as_flattened(), h);
    let bm = bits_of(m.as_flattened());
    if 2 * sq + bm + 5 > 126 {
        return None;
    }
    let mv: [[Zi; 4]; 4] = v.map(|x| {
        std::array::from_fn(|i| {
            x[0].scaled(m[i][0])
                .plus(x[1].scaled(m[i][1]))
                .plus(x[2].scaled(m[i][2]))
                .plus(x[3].scaled(m[i][3]))
        })
    });
    fn dot<const NARROW: bool>(x: &[Zi; 4], y: &[Zi; 4], dt: i128) -> Zi {
        zmul::<NARROW>(x[0], y[0], dt)
            .plus(zmul::<NARROW>(x[1], y[1], dt))
            .plus(zmul::<NARROW>(x[2], y[2], dt))
            .plus(zmul::<NARROW>(x[3], y[3], dt))
    }
    fn forms<const NARROW: bool>(v: &[[Zi; 4]; 4], mv: &[[Zi; 4]; 4], dt: i128) -> [[Zi; 3]; 3] {
        let d = |x: usize, y: usize| dot::<NARROW>(&v[x], &mv[y], dt);
        [
            [d(0, 0), d(0, 1).scaled(2), d(1, 1)],
            [d(0, 2), d(0, 3).plus(d(1, 2)), d(1, 3)],
            [d(2, 2), d(2, 3).scaled(2), d(3, 3)],
        ]
    }
    let narrow_dt = i128::from(dt as i64) == dt;
    let c = if narrow_dt && narrow(v.as_flattened()) && narrow(mv.as_flattened()) {
        forms::<true>(&v, &mv, dt)
    } else {
        forms::<false>(&v, &mv, dt)
    };
    let [w0, w1, w2] = c.map(|x| weight(&x, h));
    if (2 * w1).max(w0 + w2) + 3 > 126 || w0.max(w1).max(w2) + sq + 2 > 126 {
        return None;
    }
    let b: [[Zi; 2]; 4] = std::array::from_fn(|i| [v[0][i], v[1][i]]);
    let d: [[Zi; 2]; 4] = std::array::from_fn(|i| [v[2][i], v[3][i]]);
    fn rest<const NARROW: bool>(
        c: &[[Zi; 3]; 3],
        b: &[[Zi; 2]; 4],
        d: &[[Zi; 2]; 4],
        dt: i128,
    ) -> FixedForms<5, 4> {
        let s = cross_lines::<NARROW, 3, 3, 5>(&c[1], &c[1], &c[0], &c[2], dt);
        let a =
            std::array::from_fn(|i| cross_lines::<NARROW, 3, 2, 4>(&c[2], &b[i], &c[1], &d[i], dt));
        let alt =
            std::array::from_fn(|i| cross_lines::<NARROW, 3, 2, 4>(&c[1], &b[i], &c[0], &d[i], dt));
        (s, a, alt)
    }
    Some(
        if narrow_dt && narrow(c.as_flattened()) && narrow(v.as_flattened()) {
            rest::<true>(&c, &b, &d, dt)
        } else {
            rest::<false>(&c, &b, &d, dt)
        },
    )
}

/// Levin's forms of a [`FixedRuling`] in machine integers: the ruling `b`, `d` and
/// `s`, `a`, `alt` ([`levin_core`]), each in a fixed buffer.
#[derive(Clone, Copy, Debug)]
pub(crate) struct FixedLevin {
    pub(crate) delta: i128,
    b: [FixedPoly<2>; 4],
    d: [FixedPoly<2>; 4],
    a: [FixedPoly<4>; 4],
    alt: [FixedPoly<4>; 4],
    s: FixedPoly<5>,
}

impl FixedLevin {
    /// The forms of the ruling `r` on the integer matrix `m`; `None` when a number leaves
    /// `i128`.
    pub(crate) fn new(m: &[[i128; 4]; 4], r: &FixedRuling) -> Option<FixedLevin> {
        let poly = |w: usize, i: usize| -> FixedPoly<2> {
            let c = r.coordinate(w, i);
            let n = c
                .iter()
                .rposition(|v| *v != Zi::default())
                .map_or(0, |k| k + 1);
            FixedPoly { c, n }
        };
        let b: [FixedPoly<2>; 4] = std::array::from_fn(|i| poly(0, i));
        let d: [FixedPoly<2>; 4] = std::array::from_fn(|i| poly(1, i));
        let bi: [&[Zi]; 4] = std::array::from_fn(|i| b[i].coeffs());
        let di: [&[Zi]; 4] = std::array::from_fn(|i| d[i].coeffs());
        let (s, a, alt) = match levin_lines(m, r) {
            Some(forms) => forms,
            None => levin_core::<5, 4>(m, &bi, &di, r.delta, false)?.0,
        };
        Some(FixedLevin {
            delta: r.delta,
            b,
            d,
            a,
            alt,
            s,
        })
    }

    /// `s ≡ 0`.
    pub(crate) fn s_is_zero(&self) -> bool {
        self.s.n == 0
    }

    /// The `log₂` sizes of the coefficients of `s`, as [`log2_sizes`] gives them.
    pub(crate) fn s_log2_sizes(&self) -> Vec<f64> {
        let root = to_f64(self.delta).sqrt();
        self.s
            .coeffs()
            .iter()
            .map(|c| {
                if *c == Zi::default() {
                    return f64::NEG_INFINITY;
                }
                let a = to_f64(c.a);
                let v = if c.b == 0 { a } else { a + to_f64(c.b) * root }.abs();
                if v > 0.0 {
                    v.log2()
                } else {
                    // cancelled in floats: from bit lengths, as `log2_sizes`
                    let root_bits = if c.b == 0 {
                        0.0
                    } else {
                        bit_len(self.delta) as f64 / 2.0
                    };
                    let bits = |v: i128| {
                        if v == 0 {
                            f64::NEG_INFINITY
                        } else {
                            bit_len(v) as f64 - 1.0
                        }
                    };
                    bits(c.a).max(bits(c.b) + root_bits) + 1.0
                }
            })
            .collect()
    }

    /// Each coefficient `i` of each form times `2^exponent(degree, i)` (`degree` the form's
    /// homogeneous degree: 1 for `b`, `d`, 3 for `a`, `alt`, 4 for `s`); `false` (nothing
    /// changed) when a number could leave `i128`.
    pub(crate) fn shift(&mut self, exponent: impl Fn(usize, usize) -> usize) -> bool {
        let fits = self
            .b
            .iter()
            .chain(&self.d)
            .all(|p| p.fits(|i| exponent(1, i)))
            && self
                .a
                .iter()
                .chain(&self.alt)
                .all(|p| p.fits(|i| exponent(3, i)))
            && self.s.fits(|i| exponent(4, i));
        if fits {
            for p in self.b.iter_mut().chain(&mut self.d) {
                p.shift(|i| exponent(1, i));
            }
            for p in self.a.iter_mut().chain(&mut self.alt) {
                p.shift(|i| exponent(3, i));
            }
            self.s.shift(|i| exponent(4, i));
        }
        fits
    }

    /// `b`, `d`, `a`, `alt`, `s` as [`ZPoly`]s.
    #[allow(clippy::type_complexity)]
    /// `s` over ℤ[√δ] in big integers.
    pub(crate) fn s_zpoly(&self) -> ZPoly {
        self.s.to_zpoly()
    }

    /// `a`, `d`, `alt`, `b` as output polynomials over `field` = ℚ(√δ) ([`to_number_poly`]
    /// of [`Self::into_zpolys`], without the big-integer polynomials).
    pub(crate) fn to_number_polys(
        self,
        field: Option<&qsic_algebra::field::NumberField>,
    ) -> [[super::NumberPoly; 4]; 4] {
        [
            self.a.map(|p| p.to_number_poly(field)),
            self.d.map(|p| p.to_number_poly(field)),
            self.alt.map(|p| p.to_number_poly(field)),
            self.b.map(|p| p.to_number_poly(field)),
        ]
    }

    pub(crate) fn into_zpolys(self) -> ([ZPoly; 4], [ZPoly; 4], [ZPoly; 4], [ZPoly; 4], ZPoly) {
        (
            self.b.map(FixedPoly::to_zpoly),
            self.d.map(FixedPoly::to_zpoly),
            self.a.map(FixedPoly::to_zpoly),
            self.alt.map(FixedPoly::to_zpoly),
            self.s.to_zpoly(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use qsic_algebra::testing::SplitMix;

    fn random_poly(rng: &mut SplitMix, bits: usize, irrational: bool, len: usize) -> ZPoly {
        let big =
            |rng: &mut SplitMix| IBig::from(rng.int(-999, 999)) << rng.int(0, bits as i64) as usize;
        (0..len)
            .map(|_| Zq {
                a: big(rng),
                b: if irrational { big(rng) } else { IBig::ZERO },
            })
            .collect()
    }

    /// The reduction as it was before the floats were kept beside the integers: every step
    /// converts both vectors again and checks every operation (the reference below).
    fn reduce_array_reference(t: &mut [[[i128; 8]; 2]; 2]) -> Option<()> {
        // the two halves of a mode: (w, j) cells
        let cells = |mode: usize, k: usize| -> [(usize, usize); 2] {
            if mode == 0 {
                [(k, 0), (k, 1)]
            } else {
                [(0, k), (1, k)]
            }
        };
        // binary gcd: shifts and subtractions, no 128-bit division
        let gcd = |mut x: u128, mut y: u128| {
            if x == 0 || y == 0 {
                return x | y;
            }
            let shift = (x | y).trailing_zeros();
            x >>= x.trailing_zeros();
            loop {
                y >>= y.trailing_zeros();
                if x > y {
                    (x, y) = (y, x);
                }
                y -= x;
                if y == 0 {
                    return x << shift;
                }
            }
        };
        for _round in 0..2 {
            let mut changed = false;
            for mode in 0..2 {
                for k in 0..2 {
                    let c = cells(mode, k);
                    let g = c.iter().flat_map(|&(w, j)| t[w][j]).fold(0u128, |g, v| {
                        if g == 1 {
                            1
                        } else {
                            gcd(g, v.unsigned_abs())
                        }
                    });
                    if g > 1 {
                        changed = true;
                        let g = i128::try_from(g).ok()?;
                        for (w, j) in c {
                            for v in &mut t[w][j] {
                                *v /= g;
                            }
                        }
                    }
                }
                for _ in 0..8 {
                    let f = |k: usize| -> [f64; 16] {
                        let c = cells(mode, k);
                        std::array::from_fn(|n| {
                            let v = t[c[n / 8].0][c[n / 8].1][n % 8];
                            // one instruction when it fits i64, else the two halves (the
                            // library call of `v as f64` costs more; `k` needs an approximation)
                            let small = v as i64;
                            if i128::from(small) == v {
                                small as f64
                            } else {
                                ((v >> 64) as i64 as f64) * 18_446_744_073_709_551_616.0
                                    + (v as u64 as f64)
                            }
                        })
                    };
                    let (x, y) = (f(0), f(1));
                    let dot = |p: &[f64; 16], q: &[f64; 16]| -> f64 {
                        p.iter().zip(q).map(|(a, b)| a * b).sum()
                    };
                    let (nx, ny) = (dot(&x, &x), dot(&y, &y));
                    let (small, big, nsmall) = if nx <= ny { (0, 1, nx) } else { (1, 0, ny) };
                    let k = (dot(&x, &y) / nsmall).round();
                    if !(k.is_finite() && k != 0.0 && k.abs() < 1e30) {
                        break;
                    }
                    let k = k as i128;
                    changed = true;
                    let (sc, bc) = (cells(mode, small), cells(mode, big));
                    for h in 0..2 {
                        let ((ws, js), (wb, jb)) = (sc[h], bc[h]);
                        for n in 0..8 {
                            let v = k.checked_mul(t[ws][js][n])?;
                            t[wb][jb][n] = t[wb][jb][n].checked_sub(v)?;
                        }
                    }
                }
            }
            if !changed {
                break;
            }
        }
        Some(())
    }

    /// [`reduce_array`] takes the same steps as the reference on random arrays of small,
    /// mixed, large and overflowing numbers (same results, same overflows).
    #[test]
    fn reduce_array_equals_the_reference() {
        let mut rng = SplitMix(71);
        // (reduced, changed, overflowed): every kind of outcome occurs (overflow rarely: a
        // step overflows only when |k·y| does while |x − k·y| may not)
        let mut seen = [0; 3];
        for case in 0..400 {
            let bits = [20, 40, 60, 90, 125][case % 5];
            let mut t = [[[0i128; 8]; 2]; 2];
            // a common factor in some cases, and a near-dependent pair of rows
            let g = i128::from(rng.int(1, 30));
            for w in 0..2 {
                for j in 0..2 {
                    for n in 0..8 {
                        // |v| < 2^bits
                        let v = i128::from(rng.int(-999, 999)) << rng.int(0, bits - 10) as u32;
                        t[w][j][n] = if bits > 100 { v } else { v * g };
                    }
                }
            }
            let k = i128::from(rng.int(-50, 50));
            for n in 0..8 {
                t[1][1][n] = (t[1][1][n] / 4).saturating_add(k.saturating_mul(t[0][1][n] / 4));
            }
            let (mut x, mut y) = (t, t);
            let (rx, ry) = (reduce_array(&mut x), reduce_array_reference(&mut y));
            assert_eq!(rx.is_some(), ry.is_some(), "{t:?}");
            if rx.is_some() {
                assert_eq!(x, y, "{t:?}");
                seen[0] += 1;
                seen[1] += usize::from(x != t);
            } else {
                seen[2] += 1;
            }
        }
        assert!(seen[0] > 10 && seen[1] > 10 && seen[2] > 0, "{seen:?}");
    }

    /// A ruling bloated by changes of `u` and `v` (and a common factor) comes back small,
    /// and stays a ruling of the same surface: `bᵀSb`, `bᵀSd`, `dᵀSd` vanish identically.
    #[test]
    fn reduced_rulings_are_small_and_stay_on_the_surface() {
        use dashu_int::ops::BitTest;
        let mut rng = SplitMix(23);
        let size = |b: &[ZPoly; 4], d: &[ZPoly; 4]| {
            b.iter()
                .chain(d)
                .flatten()
                .map(|c| c.a.bit_len().max(c.b.bit_len()))
                .max()
                .unwrap_or(0)
        };
        // S = diag(1, 1, −1, −1) (x² + y² = z² + w²), with the lines
        // (x, y, z, w) = (1, u, 1, u) + v·(u, −1, −u, 1), over ℚ; and over ℚ(√2) for
        // x² + y² = 2z² + w²: (√2, √2u, 1, ... ) is not needed, ℚ is enough here
        let m: [[IBig; 4]; 4] = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                IBig::from(if i != j {
                    0
                } else if i < 2 {
                    1
                } else {
                    -1
                })
            })
        });
        let int = |v: i64| Zq::int(IBig::from(v));
        let base_b: [ZPoly; 4] = [
            vec![int(1)],
            vec![int(0), int(1)],
            vec![int(1)],
            vec![int(0), int(1)],
        ];
        let base_d: [ZPoly; 4] = [
            vec![int(0), int(1)],
            vec![int(-1)],
            vec![int(0), int(-1)],
            vec![int(1)],
        ];
        let on_surface = |b: &[ZPoly; 4], d: &[ZPoly; 4]| {
            [(b, b), (b, d), (d, d)]
                .iter()
                .all(|(x, y)| poly_form(&m, x, y, &IBig::ZERO).iter().all(Zq::is_zero))
        };
        assert!(on_surface(&base_b, &base_d));
        // a unimodular 2 × 2 matrix: a product of three elementary ones
        let unimodular = |rng: &mut SplitMix| -> [i64; 4] {
            let mut m = [1, 0, 0, 1];
            for step in 0..3 {
                let k = rng.int(-99, 99);
                let (a, b, c, d) = (m[0], m[1], m[2], m[3]);
                m = if step % 2 == 0 {
                    [a + k * c, b + k * d, c, d]
                } else {
                    [a, b, c + k * a, d + k * b]
                };
            }
            m
        };
        for _ in 0..50 {
            // u ↦ (p u + q)/(r u + s), then u ↦ f·u; b, d ↦ αb + βd, γb + δd; a common
            // factor g (all undone by valid changes: the reduction must find small numbers)
            let (mu, mv) = (unimodular(&mut rng), unimodular(&mut rng));
            let (f, g) = (rng.int(1, 99), rng.int(1, 99));
            let moebius = |p: &ZPoly| -> ZPoly {
                let c = |i: usize| p.get(i).map_or(0, |z| i64::try_from(&z.a).unwrap());
                let (c0, c1) = (c(0), c(1));
                // c0·(r u + s) + c1·(p u + q), then u ↦ f·u
                vec![
                    int(c0 * mu[3] + c1 * mu[1]),
                    int((c0 * mu[2] + c1 * mu[0]) * f),
                ]
            };
            let mix = |x: &ZPoly, y: &ZPoly, a: i64, b: i64| -> ZPoly {
                (0..2)
                    .map(|i| {
                        let h = |p: &ZPoly| p.get(i).map_or(IBig::ZERO, |z| z.a.clone());
                        Zq::int((h(x) * a + h(y) * b) * g)
                    })
                    .collect()
            };
            let (mb, md): ([ZPoly; 4], [ZPoly; 4]) = (
                std::array::from_fn(|i| moebius(&base_b[i])),
                std::array::from_fn(|i| moebius(&base_d[i])),
            );
            let mut b: [ZPoly; 4] = std::array::from_fn(|i| mix(&mb[i], &md[i], mv[0], mv[1]));
            let mut d: [ZPoly; 4] = std::array::from_fn(|i| mix(&mb[i], &md[i], mv[2], mv[3]));
            assert!(on_surface(&b, &d));
            let before = size(&b, &d);
            // the direct route from the ruling over ℚ gives the same reduced ruling
            let (pb, pd): ([Poly<Quadratic>; 4], [Poly<Quadratic>; 4]) = (
                std::array::from_fn(|i| to_poly(&b[i], &IBig::ZERO)),
                std::array::from_fn(|i| to_poly(&d[i], &IBig::ZERO)),
            );
            let direct = reduced_ruling(&pb, &pd, &IBig::ZERO).expect("small and integral");
            assert!(reduce_ruling(&mut b, &mut d));
            assert_eq!(direct, (b.clone(), d.clone()));
            assert!(on_surface(&b, &d), "{b:?} {d:?}");
            assert!(
                size(&b, &d) <= 4 && size(&b, &d) < before,
                "{before} -> {b:?} {d:?}"
            );
        }
    }

    /// The conversions without gcds and square tests build the representations of the
    /// general routes: [`to_poly`] and [`to_poly_down`] those of [`Quadratic::new`],
    /// [`to_number_poly`] that of `curve::from_quadratic`, and [`log2_sizes`] the sizes of
    /// the parent's `log2_size` on the converted coefficients (small, huge and zero numbers).
    #[test]
    fn conversions_equal_the_general_routes() {
        use qsic_algebra::field::NumberFieldElement;
        let mut rng = SplitMix(29);
        let same = |x: &NumberFieldElement, y: &NumberFieldElement| {
            x.numerator() == y.numerator()
                && x.denominator() == y.denominator()
                && x.field().is_some() == y.field().is_some()
                && x == y
        };
        let mut checked = 0;
        for (bits, delta) in [(4usize, 0i64), (10, 7), (60, 2), (200, 3), (1100, 5)] {
            let delta = IBig::from(delta);
            let huge_delta = IBig::from(7) << 1100;
            for d in [&delta, &huge_delta] {
                if delta.is_zero() && !d.is_zero() {
                    continue;
                }
                let field = (!d.is_zero()).then(|| super::super::curve::sqrt_field(d));
                for len in 0..6 {
                    let mut p = random_poly(&mut rng, bits, !d.is_zero(), len);
                    for c in p.iter_mut() {
                        match rng.int(0, 3) {
                            0 => c.a = IBig::ZERO,
                            1 => c.b = IBig::ZERO,
                            _ => {}
                        }
                    }
                    let old = Poly::new(p.iter().map(|c| c.to_quadratic(d)).collect());
                    assert_eq!(to_poly(&p, d), old);
                    for e in [1usize, 5, 40] {
                        let den = dashu_int::UBig::ONE << e;
                        let part = |v: &IBig| RBig::from_parts(v.clone(), den.clone());
                        let want: Poly<Quadratic> = Poly::new(
                            p.iter()
                                .map(|c| Quadratic::new(part(&c.a), part(&c.b), d.clone()).unwrap())
                                .collect(),
                        );
                        assert_eq!(to_poly_down(&p, d, e), want);
                    }
                    let sizes: Vec<f64> =
                        old.coeffs().iter().map(super::super::log2_size).collect();
                    let new = log2_sizes(&p, d);
                    // the trailing zeros of p have no coefficient in `old`
                    assert!(new[sizes.len()..].iter().all(|v| *v == f64::NEG_INFINITY));
                    assert_eq!(&new[..sizes.len()], &sizes[..], "{p:?}");
                    let fast = to_number_poly(p.clone(), field.as_ref());
                    let general = super::super::curve::poly_from_quadratic(&old, field.as_ref());
                    assert_eq!(fast.coeffs().len(), general.coeffs().len());
                    for (x, y) in fast.coeffs().iter().zip(general.coeffs()) {
                        assert!(same(x, y), "{x} vs {y}");
                        checked += 1;
                    }
                }
            }
        }
        assert!(checked >= 100, "{checked}");
    }

    /// The checked machine forms of [`levin_big`] are the big-integer ones ([`poly_form`],
    /// the other route) where they answer, and they decline where a form leaves `i128`
    /// (coefficients of 60 bits: products of 120 bits times the matrix) or an input does.
    #[test]
    fn checked_forms_equal_the_big_ones() {
        let mut rng = SplitMix(77);
        let (mut answered, mut declined) = (0, 0);
        for bits in [0usize, 20, 40, 60, 130] {
            for _ in 0..20 {
                let irrational = rng.int(0, 1) == 1;
                let delta = IBig::from(if irrational { rng.int(2, 99) } else { 1 });
                let m: [[IBig; 4]; 4] = {
                    let mut m: [[IBig; 4]; 4] = Default::default();
                    for i in 0..4 {
                        for j in i..4 {
                            m[i][j] = IBig::from(rng.int(-999, 999));
                            m[j][i] = m[i][j].clone();
                        }
                    }
                    m
                };
                let mut poly = || {
                    let len = 1 + rng.int(0, 2) as usize;
                    let mut p = random_poly(&mut rng, bits, irrational, len);
                    trim(&mut p);
                    p
                };
                let b: [ZPoly; 4] = std::array::from_fn(|_| poly());
                let d: [ZPoly; 4] = std::array::from_fn(|_| poly());
                let want = (
                    poly_form(&m, &b, &b, &delta),
                    poly_form(&m, &b, &d, &delta),
                    poly_form(&m, &d, &d, &delta),
                );
                match forms_checked(&m, &b, &d, &delta) {
                    Some(mut got) => {
                        answered += 1;
                        let mut want = want;
                        for p in [
                            &mut got.0,
                            &mut got.1,
                            &mut got.2,
                            &mut want.0,
                            &mut want.1,
                            &mut want.2,
                        ] {
                            trim(p);
                        }
                        assert_eq!(got, want, "{bits} bits");
                    }
                    None => {
                        declined += 1;
                        assert!(bits >= 60, "declined at {bits} bits");
                    }
                }
            }
        }
        assert!(
            answered >= 50 && declined >= 20,
            "{answered} answered, {declined} declined"
        );
    }

    /// [`scale_powers_of_two`] multiplies each coefficient by its power of two, on small and
    /// big integers and zeros.
    #[test]
    fn scaling_by_powers_of_two() {
        let mut rng = SplitMix(31);
        for bits in [0usize, 20, 50, 70, 200] {
            for _ in 0..20 {
                let mut p = random_poly(&mut rng, bits, true, 5);
                p[rng.int(0, 4) as usize].a = IBig::ZERO;
                let exps: Vec<usize> = (0..5).map(|_| rng.int(0, 100) as usize).collect();
                let want: ZPoly = p
                    .iter()
                    .zip(&exps)
                    .map(|(c, &e)| Zq {
                        a: &c.a * (IBig::ONE << e),
                        b: &c.b * (IBig::ONE << e),
                    })
                    .collect();
                scale_powers_of_two(&mut p, |i| exps[i]);
                assert_eq!(p, want);
            }
        }
    }

    /// The forms of a fixed ruling ([`FixedLevin`]) equal the big-integer ones on random
    /// rulings and matrices of every size (declining only past the bounds of `levin_core`),
    /// its `log₂` sizes of `s` equal [`log2_sizes`], and its shifts equal
    /// [`scale_powers_of_two`] where they fit (and decline, changing nothing, where not).
    #[test]
    fn fixed_levin_equals_big_forms() {
        let mut rng = SplitMix(41);
        let (mut fixed, mut declined, mut shifted, mut too_far) = (0, 0, 0, 0);
        for (bits, delta) in [(3u32, 0i64), (8, 5), (20, 0), (28, 3), (40, 2), (60, 7)] {
            for _ in 0..40 {
                let mut v = |b: u32| i128::from(rng.int(-99, 99)) << rng.int(0, b as i64) as u32;
                let m: [[i128; 4]; 4] =
                    std::array::from_fn(|_| std::array::from_fn(|_| v(bits / 2)));
                let m: [[i128; 4]; 4] = std::array::from_fn(|i| {
                    std::array::from_fn(|j| if i <= j { m[i][j] } else { m[j][i] })
                });
                let mut t = [[[0i128; 8]; 2]; 2];
                for x in t.as_flattened_mut().as_flattened_mut().chunks_mut(2) {
                    x[0] = v(bits);
                    x[1] = if delta == 0 { 0 } else { v(bits) };
                }
                let r = FixedRuling {
                    delta: i128::from(delta),
                    t,
                };
                let big_delta = IBig::from(delta);
                let (b, d) = r.to_zpolys();
                let mb = m.map(|row| row.map(IBig::from));
                let (s, a, alt) = levin_big(&mb, &b, &d, &big_delta);
                let Some(f) = FixedLevin::new(&m, &r) else {
                    declined += 1;
                    assert!(bits >= 20, "declined at {bits} bits");
                    continue;
                };
                fixed += 1;
                let (fb, fd, fa, falt, fs) = f.into_zpolys();
                let trimmed = |mut p: ZPoly| {
                    trim(&mut p);
                    p
                };
                assert_eq!((&fb, &fd), (&b, &d));
                assert_eq!(fs, trimmed(s.clone()));
                assert_eq!(fa, a.clone().map(trimmed));
                assert_eq!(falt, alt.clone().map(trimmed));
                assert_eq!(f.s_log2_sizes(), log2_sizes(&fs, &big_delta));
                let k = rng.int(0, 16) as usize;
                let exponent = |degree: usize, i: usize| k * (degree + 1 - i.min(degree));
                let mut g = f;
                if g.shift(exponent) {
                    shifted += 1;
                    let (gb, gd, ga, galt, gs) = g.into_zpolys();
                    let scaled = |mut p: ZPoly, degree: usize| {
                        scale_powers_of_two(&mut p, |i| exponent(degree, i));
                        p
                    };
                    assert_eq!(gb, fb.map(|p| scaled(p, 1)));
                    assert_eq!(gd, fd.map(|p| scaled(p, 1)));
                    assert_eq!(ga, fa.map(|p| scaled(p, 3)));
                    assert_eq!(galt, falt.map(|p| scaled(p, 3)));
                    assert_eq!(gs, scaled(fs, 4));
                } else {
                    too_far += 1;
                    assert_eq!(g.into_zpolys(), f.into_zpolys());
                }
            }
        }
        assert!(
            fixed > 100 && declined > 10 && shifted > 50 && too_far > 10,
            "{fixed} fixed, {declined} declined, {shifted} shifted, {too_far} too far"
        );
    }

    /// Products over ℤ[√δ] equal those of the same polynomials over ℚ(√δ) (`Poly<Quadratic>`,
    /// another implementation): both parts irrational, one side rational, zero coefficients
    /// among them; and `Zq::mul` with an integer on either side.
    #[test]
    fn products_equal_those_over_the_field() {
        let mut rng = SplitMix(23);
        for delta in [2i64, 3, 1_000_003] {
            let delta = IBig::from(delta) << 130; // δ far past the machine words
            let delta = &delta + IBig::from(3); // not a square
            for k in 0..60 {
                let (lx, ly) = (1 + k % 4, 1 + (k / 4) % 5);
                let mut x = random_poly(&mut rng, 90, k % 3 != 0, lx);
                let y = random_poly(&mut rng, 90, k % 5 != 0, ly);
                if k % 7 == 0 {
                    x[0] = Zq::default();
                }
                let want = &to_poly(&x, &delta) * &to_poly(&y, &delta);
                assert_eq!(
                    to_poly(&poly_mul(&x, &y, &delta), &delta),
                    want,
                    "{x:?} {y:?}"
                );
                let (p, q) = (&x[lx - 1], &y[ly - 1]);
                let r = Zq::int(q.a.clone());
                for (u, v) in [(p, q), (p, &r), (&r, p)] {
                    let want = &u.to_quadratic(&delta) * &v.to_quadratic(&delta);
                    assert_eq!(u.mul(v, &delta).to_quadratic(&delta), want);
                }
            }
        }
    }

    /// The machine-integer forms equal the big-integer ones: without checks (bounded), checked
    /// (the bound fails, the numbers fit), and past i128 (the big fallback).
    #[test]
    fn machine_forms_equal_big_forms() {
        let mut rng = SplitMix(17);
        let (mut small, mut overflowed, mut bounded, mut checked_only) = (0, 0, 0, 0);
        for (bits, delta) in [
            (4usize, 0i64),
            (6, 11),
            (10, 7),
            (16, 0),
            (18, 2),
            (20, 0),
            (22, 3),
            (30, 2),
            (60, 3),
            (90, 5),
        ] {
            let delta = IBig::from(delta);
            for _ in 0..20 {
                let m: [[IBig; 4]; 4] = std::array::from_fn(|_| {
                    std::array::from_fn(|_| {
                        IBig::from(rng.int(-50, 50)) << rng.int(0, bits as i64 / 2) as usize
                    })
                });
                let irr = !delta.is_zero();
                // lines (2 coefficients) or a vertex and a conic (1 and 3)
                let (lb, ld) = if rng.int(0, 1) == 0 { (2, 2) } else { (1, 3) };
                let b: [ZPoly; 4] = std::array::from_fn(|_| random_poly(&mut rng, bits, irr, lb));
                let d: [ZPoly; 4] = std::array::from_fn(|_| random_poly(&mut rng, bits, irr, ld));
                let same = |x: &[Zq], y: &[Zq]| to_poly(x, &delta) == to_poly(y, &delta);
                let (e0, e1, e2) = (
                    poly_form(&m, &b, &b, &delta),
                    poly_form(&m, &b, &d, &delta),
                    poly_form(&m, &d, &d, &delta),
                );
                let es = poly_sub(&poly_mul(&e1, &e1, &delta), &poly_mul(&e0, &e2, &delta));
                let (bs, ba, balt) = levin_big(&m, &b, &d, &delta);
                assert!(same(&bs, &es));
                let Some((s, a, alt)) = levin_small(&m, &b, &d, &delta) else {
                    overflowed += 1;
                    continue;
                };
                small += 1;
                let mi: [[i128; 4]; 4] = std::array::from_fn(|i| {
                    std::array::from_fn(|j| i128::try_from(&m[i][j]).unwrap())
                });
                let dl = i128::try_from(&delta).unwrap();
                let (slow, _) = levin_fixed(&mi, &b, &d, dl, true).expect("fits i128");
                assert_eq!((&s, &a, &alt), (&slow.0, &slow.1, &slow.2));
                let (_, unchecked) = levin_fixed(&mi, &b, &d, dl, false).expect("fits i128");
                if unchecked {
                    bounded += 1;
                } else {
                    checked_only += 1;
                }
                assert!(same(&s, &es));
                for i in 0..4 {
                    let want =
                        poly_sub(&poly_mul(&e2, &b[i], &delta), &poly_mul(&e1, &d[i], &delta));
                    assert!(same(&a[i], &want) && same(&ba[i], &want));
                    let want =
                        poly_sub(&poly_mul(&e1, &b[i], &delta), &poly_mul(&e0, &d[i], &delta));
                    assert!(same(&alt[i], &want) && same(&balt[i], &want));
                }
            }
        }
        assert!(
            small >= 80 && overflowed >= 50 && bounded >= 60 && checked_only >= 10,
            "{small} small ({bounded} bounded, {checked_only} checked), {overflowed} past i128"
        );
    }
}
