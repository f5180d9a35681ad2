//! The forms of Levin's method over ℤ[√δ]: `s(u)`, `a(u)` and its alternative from a ruling
//! `b + v·d` and a quadric, in big integers ([`levin_big`], the reference) and in fixed-width
//! `i128` polynomials ([`levin_small`], [`FixedLevin`]) whose sizes are bounded from the
//! inputs' bit lengths before the unchecked products run.

use super::fixed::*;
use super::*;
use qsic_algebra::{IBig, Poly};

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
pub(super) fn levin_from_forms(
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
pub(super) fn forms_checked(
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
pub(super) fn machine_matrix(m: &[[IBig; 4]; 4], delta: &IBig) -> Option<([[i128; 4]; 4], i128)> {
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
pub(super) fn fixed_rows(b: &[ZPoly; 4], d: &[ZPoly; 4]) -> Option<[[Zi; 3]; 8]> {
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

/// `xᵀMy` into a fixed buffer (`x`, `y` of at most 3 coefficients), without overflow checks
/// when `checked` is false (the caller's bounds exclude overflow); `None` on overflow.
pub(super) fn form_fixed(
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
    pub(super) fn coeffs(&self) -> &[Zi] {
        &self.c[..self.n]
    }

    pub(super) fn to_zpoly(self) -> ZPoly {
        self.coeffs().iter().map(|v| v.big()).collect()
    }

    /// [`to_number_poly`] of [`Self::to_zpoly`] without the big-integer polynomial between.
    pub(super) fn to_number_poly(
        self,
        field: Option<&qsic_algebra::field::NumberField>,
    ) -> crate::param::NumberPoly {
        let c = self.coeffs();
        let n = c
            .iter()
            .rposition(|v| *v != Zi::default())
            .map_or(0, |k| k + 1);
        Poly::from_trimmed(c[..n].iter().map(|v| to_number(v.big(), field)).collect())
    }

    /// Whether every coefficient `i` times `2^e(i)` stays below `2¹²⁶`.
    pub(super) fn fits(&self, e: impl Fn(usize) -> usize) -> bool {
        self.coeffs().iter().enumerate().all(|(i, v)| {
            let b = bit_len(v.a).max(bit_len(v.b));
            b == 0 || b as usize + e(i) <= 126
        })
    }

    /// Coefficient `i` times `2^e(i)` (the caller checked [`Self::fits`]).
    pub(super) fn shift(&mut self, e: impl Fn(usize) -> usize) {
        for (i, v) in self.c[..self.n].iter_mut().enumerate() {
            let k = e(i) as u32;
            v.a <<= k;
            v.b <<= k;
        }
    }
}

/// `x·y − z·w` of polynomials over ℤ[√δ] (product lengths at most `N`, else `None`) without
/// trailing zeros; without overflow checks when `checked` is false (as [`form_fixed`]).
pub(super) fn cross_fixed<const N: usize>(
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
pub(super) type FixedForms<const S: usize, const A: usize> =
    (FixedPoly<S>, [FixedPoly<A>; 4], [FixedPoly<A>; 4]);

/// [`levin_small`] on machine integers; also whether both stages ran without checks
/// (`always_check` forces the checks, for the tests).
pub(super) fn levin_fixed(
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
pub(super) fn levin_core<const S: usize, const A: usize>(
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
pub(super) fn zmul<const NARROW: bool>(x: Zi, y: Zi, delta: i128) -> Zi {
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
pub(super) fn cross_lines<const NARROW: bool, const P: usize, const Q: usize, const N: usize>(
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

/// [`levin_core`] for lines `b = b₀ + u·b₁`, `d = d₀ + u·d₁` (a symmetric `M`): the
/// products `M·b₀`, `M·b₁`, `M·d₀`, `M·d₁` once, the forms from ten dot products
/// (`c₀ = b₀ᵀMb₀ + 2u·b₀ᵀMb₁ + u²·b₁ᵀMb₁`, …), then `s`, `a`, `alt`; without overflow
/// checks, each stage guarded by the weights of its operands as in [`levin_core`] (a
/// coefficient of a form is a sum of at most two dot products of four products, below
/// `2^(2σ_q + β_M + 5)`; one of `s` at most six products of the forms', one of `a`, `alt`
/// four), in machine-word products where the parts fit `i64`. `None` when a guard fails.
pub(super) fn levin_lines(m: &[[i128; 4]; 4], r: &FixedRuling) -> Option<FixedForms<5, 4>> {
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
    pub(super) fn dot<const NARROW: bool>(x: &[Zi; 4], y: &[Zi; 4], dt: i128) -> Zi {
        zmul::<NARROW>(x[0], y[0], dt)
            .plus(zmul::<NARROW>(x[1], y[1], dt))
            .plus(zmul::<NARROW>(x[2], y[2], dt))
            .plus(zmul::<NARROW>(x[3], y[3], dt))
    }
    pub(super) fn forms<const NARROW: bool>(
        v: &[[Zi; 4]; 4],
        mv: &[[Zi; 4]; 4],
        dt: i128,
    ) -> [[Zi; 3]; 3] {
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
    pub(super) fn rest<const NARROW: bool>(
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
    ) -> [[crate::param::NumberPoly; 4]; 4] {
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
