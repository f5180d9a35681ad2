//! Double-double arithmetic: `hi + lo` with `|lo| ≤ ulp(hi)/2`, about 106 bits (Dekker 1971;
//! Hida, Li, Bailey 2001): error-free `two_sum` and the product by `mul_add` or by Veltkamp's
//! split ([`split`], [`product_error`]); exact conversion of integers below `2¹⁰⁶`, rounded
//! beyond ([`int_dd`]). [`Dd4`] runs the same operations on four lanes. Used where a float
//! evaluation is not certified ([`super::super::eval`]) and for the coefficients of ℚ(√δ).

use crate::param::curve::Number;
use crate::param::sample::kernels::Lanes;
use qsic_algebra::field::NumberField;
use qsic_algebra::{IBig, RBig};

/// A double-double number `hi + lo`, `|lo| ≤ ulp(hi)/2`: about 106 bits.
#[derive(Clone, Copy, Debug, Default)]
pub(in crate::param::sample) struct Dd(
    pub(in crate::param::sample) f64,
    pub(in crate::param::sample) f64,
);

impl Dd {
    pub(in crate::param::sample) fn two_sum(a: f64, b: f64) -> Dd {
        let s = a + b;
        let bb = s - a;
        Dd(s, (a - (s - bb)) + (b - bb))
    }
    pub(in crate::param::sample) fn add(self, o: Dd) -> Dd {
        let s = Dd::two_sum(self.0, o.0);
        let t = Dd::two_sum(self.1, o.1);
        let hi = Dd::two_sum(s.0, s.1 + t.0);
        Dd::two_sum(hi.0, hi.1 + t.1)
    }
    /// `self · t` for an `f64` `t` (Dekker's product by `mul_add`).
    pub(in crate::param::sample) fn mul_f64(self, t: f64) -> Dd {
        let p = self.0 * t;
        let e = self.0.mul_add(t, -p);
        Dd::two_sum(p, e + self.1 * t)
    }
    pub(in crate::param::sample) fn mul(self, o: Dd) -> Dd {
        let p = self.0 * o.0;
        let e = self.0.mul_add(o.0, -p);
        Dd::two_sum(p, e + self.0 * o.1 + self.1 * o.0)
    }
    pub(in crate::param::sample) fn neg(self) -> Dd {
        Dd(-self.0, -self.1)
    }
    /// `self / o` (two quotient digits).
    pub(in crate::param::sample) fn div(self, o: Dd) -> Dd {
        let q1 = self.0 / o.0;
        let r = self.add(o.mul_f64(-q1));
        let q2 = r.0 / o.0;
        Dd::two_sum(q1, q2)
    }
    /// `√self` (0 for a negative value: `s` clamped at its roots).
    pub(in crate::param::sample) fn sqrt(self) -> Dd {
        if self.0 <= 0.0 {
            return Dd(0.0, 0.0);
        }
        let r = self.0.sqrt();
        // one Newton step: r + (self − r²)/(2r)
        let sq = Dd(r, 0.0).mul(Dd(r, 0.0));
        let diff = self.add(sq.neg());
        Dd::two_sum(r, diff.0 / (2.0 * r))
    }
}

/// The integer value of a finite, integral `x`, exactly.
pub(in crate::param::sample) fn integral_f64_to_ibig(x: f64) -> IBig {
    let bits = x.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i64 - 1075;
    let mantissa = IBig::from((bits & ((1u64 << 52) - 1)) | (1u64 << 52));
    let m = if exp >= 0 {
        mantissa << exp as usize
    } else {
        mantissa >> (-exp) as usize
    };
    if x < 0.0 {
        -m
    } else {
        m
    }
}

/// An integer in double-double (exact below `2¹⁰⁶` in magnitude, rounded beyond).
#[inline(always)]
pub(in crate::param::sample) fn int_dd(v: &IBig) -> Dd {
    // the magnitude from its words where it fits in 127 bits (the usual case, no conversion
    // through the big-integer routines)
    let (sign, words) = v.as_sign_words();
    let neg = sign == dashu_int::Sign::Negative;
    // one word (the usual coefficient): below 2⁵³ exact in one float (`i64` to `f64`, one
    // instruction), else split as `i128_dd` does
    if let [w] = words {
        if *w < 1 << 53 {
            let x = (*w as i64) as f64;
            return Dd(if neg { -x } else { x }, 0.0);
        }
        return magnitude_dd(u128::from(*w), neg);
    }
    let bits = dashu_int::Word::BITS;
    if words.len() as u32 * bits <= 128 {
        let m = (words.iter().rev()).fold(0u128, |m, w| (m << (bits % 128)) | u128::from(*w));
        if m < 1 << 53 {
            let x = ((m as u64) as i64) as f64;
            return Dd(if neg { -x } else { x }, 0.0);
        }
        if m < 1 << 127 {
            return magnitude_dd(m, neg);
        }
    }
    wide_int_dd(v)
}

/// [`int_dd`] beyond `2¹²⁷`.
#[cold]
#[inline(never)]
pub(in crate::param::sample) fn wide_int_dd(v: &IBig) -> Dd {
    // the leading 120 bits (the rest is below the double-double's precision)
    let e = {
        use dashu_int::ops::BitTest;
        v.bit_len() - 120
    };
    if e <= 900 {
        if let Ok(top) = i128::try_from(&(v >> e)) {
            let d = i128_dd(top);
            let scale = f64::from_bits(((1023 + e) as u64) << 52);
            return Dd(d.0 * scale, d.1 * scale);
        }
    }
    let hi = v.to_f64().value();
    if hi.abs() < 9.0e15 || !hi.is_finite() {
        return Dd(hi, 0.0);
    }
    // |hi| ≥ 2⁵³: an integer, so the remainder is exact
    let lo = (v - integral_f64_to_ibig(hi)).to_f64().value();
    Dd(hi, lo)
}

/// An `i128` in double-double: its leading 53 bits (exact) plus the rest rounded, in
/// machine integers only.
pub(in crate::param::sample) fn i128_dd(v: i128) -> Dd {
    magnitude_dd(v.unsigned_abs(), v < 0)
}

/// `±m` in double-double for `m < 2¹²⁸` ([`i128_dd`]): the leading 53 bits `top·2ᵉ` (exact)
/// plus the rest `r < 2ᵉ` rounded. Machine words below `2⁶³` go to floats as signed
/// integers (one instruction each).
#[inline(always)]
pub(in crate::param::sample) fn magnitude_dd(m: u128, neg: bool) -> Dd {
    let bits = 128 - m.leading_zeros();
    if bits <= 53 {
        let x = ((m as u64) as i64) as f64;
        return Dd(if neg { -x } else { x }, 0.0);
    }
    let e = bits - 53;
    // `top < 2⁵³`
    let top = ((m >> e) as u64) as i64;
    let scale = f64::from_bits(((1023 + e) as u64) << 52);
    let rest = m - ((top as u128) << e);
    let rest_f = if rest < 1 << 63 {
        (rest as i64) as f64
    } else {
        ((rest >> 64) as u64) as f64 * 18446744073709551616.0 + (rest as u64) as f64
    };
    let d = Dd::two_sum(top as f64 * scale, rest_f);
    if neg {
        d.neg()
    } else {
        d
    }
}

/// `α` in double-double and `δ` when `α = ±√δ`, a root of `x² − δ` (Newton step in
/// double-double).
pub(in crate::param::sample) fn sqrt_generator_dd(k: &NumberField) -> Option<(Dd, IBig)> {
    let alpha = k.alpha();
    let delta = match alpha.poly().coeffs() {
        [c0, c1, c2] if c1.is_zero() && *c2 == IBig::ONE && *c0 < IBig::ZERO => -c0.clone(),
        _ => return None,
    };
    let root = int_dd(&delta).sqrt();
    let root = if alpha.interval().hi() <= &RBig::ZERO {
        root.neg()
    } else {
        root
    };
    Some((root, delta))
}

/// `c` to about 106 bits where [`Converter`] has no double-double: its value at a rational
/// within `2⁻¹²⁰` of `α`, split in two floats.
pub(in crate::param::sample) fn to_dd(c: &Number) -> Dd {
    let v = match c.field().filter(|_| c.numerator().len() > 1) {
        None => {
            c.numerator()
                .first()
                .map_or(RBig::ZERO, |v| RBig::from(v.clone()))
                / RBig::from(c.denominator().clone())
        }
        Some(k) => {
            let width = RBig::from_parts_signed(IBig::ONE, IBig::ONE << 120);
            let iv = k.alpha().refined_interval(&width);
            let mid = (iv.lo() + iv.hi()) / RBig::from(2);
            c.representative().eval(&mid)
        }
    };
    let hi = v.to_f64().value();
    let lo = RBig::try_from(hi).map_or(0.0, |h| (v - h).to_f64().value());
    Dd(hi, lo)
}

pub(in crate::param::sample) fn horner_dd(c: &[Dd], t: f64, rev: bool) -> Dd {
    let mut v = Dd::default();
    let mut step = |k: &Dd| v = v.mul_f64(t).add(*k);
    if rev {
        c.iter().for_each(&mut step);
    } else {
        c.iter().rev().for_each(&mut step);
    }
    v
}

/// Veltkamp's split of `a` into `h + l` exactly, each of at most 26 significant bits
/// (`|a| < 2⁹⁹⁶`; beyond, NaN).
#[inline(always)]
pub(in crate::param::sample) fn split(a: f64) -> (f64, f64) {
    let c = 134_217_729.0 * a;
    let h = c - (c - a);
    (h, a - h)
}

/// `a·b − p` for `p = fl(a·b)`, exactly, by Dekker's product (`b` given split, [`split`]):
/// the value of `a.mul_add(b, −p)` without a fused multiply-add (away from underflow).
#[inline(always)]
pub(in crate::param::sample) fn product_error(a: f64, (bh, bl): (f64, f64), p: f64) -> f64 {
    let (ah, al) = split(a);
    al * bl - (((p - ah * bh) - al * bh) - ah * bl)
}

/// Four double-doubles ([`Dd`]) lane by lane, the operations of [`Dd`] on each (written
/// lane-wise so that they run on vector registers).
#[derive(Clone, Copy, Default)]
pub(in crate::param::sample) struct Dd4 {
    pub(in crate::param::sample) hi: Lanes,
    pub(in crate::param::sample) lo: Lanes,
}

impl Dd4 {
    pub(in crate::param::sample) fn of(v: &[Dd; 4]) -> Dd4 {
        Dd4 {
            hi: v.map(|d| d.0),
            lo: v.map(|d| d.1),
        }
    }

    #[inline(always)]
    pub(in crate::param::sample) fn two_sum(a: Lanes, b: Lanes) -> Dd4 {
        let mut out = Dd4::default();
        for i in 0..4 {
            let s = a[i] + b[i];
            let bb = s - a[i];
            out.hi[i] = s;
            out.lo[i] = (a[i] - (s - bb)) + (b[i] - bb);
        }
        out
    }

    /// [`Dd::add`] on each lane.
    #[inline(always)]
    pub(in crate::param::sample) fn add(&self, o: &Dd4) -> Dd4 {
        let s = Dd4::two_sum(self.hi, o.hi);
        let t = Dd4::two_sum(self.lo, o.lo);
        let hi = Dd4::two_sum(s.hi, std::array::from_fn(|i| s.lo[i] + t.hi[i]));
        Dd4::two_sum(hi.hi, std::array::from_fn(|i| hi.lo[i] + t.lo[i]))
    }

    /// [`Dd::mul_f64`] on each lane, `ts` the split of `t`.
    #[inline(always)]
    pub(in crate::param::sample) fn mul_f64(&self, t: f64, ts: (f64, f64)) -> Dd4 {
        let p: Lanes = std::array::from_fn(|i| self.hi[i] * t);
        let e: Lanes =
            std::array::from_fn(|i| product_error(self.hi[i], ts, p[i]) + self.lo[i] * t);
        Dd4::two_sum(p, e)
    }

    /// [`Dd::mul`] by one double-double on each lane.
    #[inline(always)]
    pub(in crate::param::sample) fn mul(&self, o: Dd) -> Dd4 {
        let os = split(o.0);
        let p: Lanes = std::array::from_fn(|i| self.hi[i] * o.0);
        let e: Lanes = std::array::from_fn(|i| {
            product_error(self.hi[i], os, p[i]) + self.hi[i] * o.1 + self.lo[i] * o.0
        });
        Dd4::two_sum(p, e)
    }
}
