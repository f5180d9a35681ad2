//! The ℤ[√δ] arithmetic of [`super`] in machine integers: the lattice reduction of a ruling
//! in `i128` arrays ([`reduce_array`], with floats kept beside the integers while they are
//! exact) and the ruling of a doubly ruled member through a small point ([`ruling_fixed`]).
//! Every operation is checked or bounded by bit lengths at the call (`None` on overflow sends
//! the caller to the big-integer route of [`super`], its reference).

use super::*;
use qsic_algebra::field::Quadratic;
use qsic_algebra::{IBig, Poly};

/// The rounds of [`reduce_ruling`] on `t[w][j]`; `None` on overflow (`t` is then partly
/// changed, by valid changes only).
///
/// Each Lagrange step `x ← x − k·y` keeps the floats of the two vectors beside the integers:
/// updated in floats when every number involved is below `2⁵³` (then the float update is
/// exact, the same floats as a conversion), else converted again; the integer update goes
/// without overflow checks when the bit lengths exclude overflow.
pub(super) fn reduce_array(t: &mut [[[i128; 8]; 2]; 2]) -> Option<()> {
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
pub(super) fn big_int(v: i128) -> IBig {
    match i64::try_from(v) {
        Ok(x) => IBig::from(x),
        Err(_) => IBig::from(v),
    }
}

/// The bit length of the largest `|v|` of `x`.
pub(super) fn bits16(x: &[i128; 16]) -> u32 {
    bit_len_u(x.iter().fold(0u128, |acc, v| acc | v.unsigned_abs()))
}

pub(super) fn bit_len_u(v: u128) -> u32 {
    128 - v.leading_zeros()
}

/// `x` in floats: one instruction for a value of `i64`, else the two halves (the library
/// call of `v as f64` costs more; the floats only choose a multiplier).
pub(super) fn to_f64_16(x: &[i128; 16]) -> [f64; 16] {
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
pub(super) fn content16(x: &[i128; 16]) -> u128 {
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
pub(super) fn divide16(x: &mut [i128; 16], g: u128) -> Option<()> {
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
pub(super) struct Zi {
    pub(super) a: i128,
    pub(super) b: i128,
}

impl Zi {
    pub(super) fn of(x: &Zq) -> Option<Zi> {
        Some(Zi {
            a: i128::try_from(&x.a).ok()?,
            b: i128::try_from(&x.b).ok()?,
        })
    }

    pub(super) fn big(self) -> Zq {
        Zq {
            a: big_int(self.a),
            b: big_int(self.b),
        }
    }

    pub(super) fn mul(self, o: Zi, delta: i128) -> Option<Zi> {
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

    pub(super) fn add(self, o: Zi) -> Option<Zi> {
        Some(Zi {
            a: self.a.checked_add(o.a)?,
            b: self.b.checked_add(o.b)?,
        })
    }

    pub(super) fn sub(self, o: Zi) -> Option<Zi> {
        Some(Zi {
            a: self.a.checked_sub(o.a)?,
            b: self.b.checked_sub(o.b)?,
        })
    }
}

/// `x·y`, `None` on overflow: without the overflow check when the bit lengths add up to
/// at most 126 (then `|x·y| < 2¹²⁶`), the common case here.
pub(super) fn mul_i(x: i128, y: i128) -> Option<i128> {
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
    pub(super) fn coordinate(&self, w: usize, i: usize) -> [Zi; 2] {
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

    /// The ruling's `b`, `d` over ℚ(√δ) and `δ` (`None` when every coefficient is rational):
    /// the parts of the public [`RuledParameterization`](super::super::surface::RuledParameterization).
    pub(crate) fn to_polys(self) -> ([Poly<Quadratic>; 4], [Poly<Quadratic>; 4], Option<IBig>) {
        let delta = IBig::from(self.delta);
        let (b, d) = self.to_zpolys();
        (
            std::array::from_fn(|i| to_poly(&b[i], &delta)),
            std::array::from_fn(|i| to_poly(&d[i], &delta)),
            (self.delta != 0).then_some(delta),
        )
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
    pub(super) fn int(a: i128) -> Zi {
        Zi { a, b: 0 }
    }

    /// `x + y`, `x − y`, `−x`, `k·x` without overflow checks (the callers bound the sizes).
    pub(super) fn plus(self, o: Zi) -> Zi {
        Zi {
            a: self.a + o.a,
            b: self.b + o.b,
        }
    }

    pub(super) fn minus(self, o: Zi) -> Zi {
        Zi {
            a: self.a - o.a,
            b: self.b - o.b,
        }
    }

    pub(super) fn negated(self) -> Zi {
        Zi {
            a: -self.a,
            b: -self.b,
        }
    }

    pub(super) fn scaled(self, k: i128) -> Zi {
        Zi {
            a: self.a * k,
            b: self.b * k,
        }
    }
}

/// The bit length of the largest weight `|a| + |b|√δ` of `x` from above (`√|δ| < 2^h`):
/// `max(bits(a), bits(b) + h) + 1`.
#[inline]
pub(super) fn weight(x: &[Zi], h: u32) -> u32 {
    let (a, b) = x.iter().fold((0u128, 0u128), |(a, b), v| {
        (a | v.a.unsigned_abs(), b | v.b.unsigned_abs())
    });
    let wb = if b == 0 { 0 } else { bit_len_u(b) + h };
    bit_len_u(a).max(wb) + 1
}

/// The bit length of the largest `|v|` of `x`.
pub(super) fn bits_of(x: &[i128]) -> u32 {
    bit_len_u(x.iter().fold(0u128, |acc, v| acc | v.unsigned_abs()))
}

/// `x` divided by the gcd of its integers `a`, `b` (nothing when it is 0 or 1): in machine
/// words when every part fits `i64` (the common case).
pub(super) fn make_primitive(x: &mut [Zi]) {
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
pub(super) fn gcd_u128(mut x: u128, mut y: u128) -> u128 {
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
pub(super) fn to_f64(v: i128) -> f64 {
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

/// The bit length of `|v|`.
pub(super) fn bit_len(v: i128) -> u32 {
    128 - v.unsigned_abs().leading_zeros()
}

/// `x·y` in ℤ[√δ] without overflow checks (the caller's bounds exclude overflow).
pub(super) fn mul_unchecked(x: Zi, y: Zi, delta: i128) -> Zi {
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

/// Whether every part of `x` fits `i64`.
pub(super) fn narrow(x: &[Zi]) -> bool {
    x.iter()
        .all(|v| i128::from(v.a as i64) == v.a && i128::from(v.b as i64) == v.b)
}
