//! Exact coefficients to floats, once per parameterization.
//!
//! A coefficient `c₀ + c₁α` of ℚ(√δ) (`α = ±√δ`) goes through double-double
//! ([`super::kernels::dd`]): summed where the terms agree in sign or cancel by fewer than 6
//! bits, else computed as `(c₀² − c₁²δ)/(c₀ − c₁α)` with the integer norm exact, so that no
//! cancellation costs more than 6 of the ~104 bits; any other number by
//! [`Number::to_f64`](crate::param::Number). A parameterization whose estimates
//! (`log₂|c|` from bit lengths) leave `[2⁻⁹⁰⁰, 2^FLOAT_SCALE]` is first scaled by powers of two
//! ([`in_float_range`]): `X = a ± d√s` is projective, so `a`, `d` and `s` take factors
//! `2^(−g)`, `2^(−f−g)`, `2^(2f)` that keep the point and both sheets.

use crate::error::Error;
use crate::param::curve::{ComponentParam, Number, NumberPoly};
use crate::param::sample::kernels::dd::{i128_dd, int_dd, sqrt_generator_dd, Dd};
use crate::param::sample::FLOAT_SCALE;
use qsic_algebra::field::NumberField;
use qsic_algebra::{IBig, Ring};

/// An upper estimate of `log₂|c|` from the bit lengths of its numerator's coefficients (a
/// polynomial in the field's generator `α`), of `α` and of its denominator; `None` for zero.
/// `log₂ max(|α|, 1)` comes from `alphas`, one entry per field met.
pub(in crate::param) fn log2_estimate(
    c: &Number,
    alphas: &mut Vec<(NumberField, f64)>,
) -> Option<f64> {
    use dashu_int::ops::BitTest;
    let coeffs = c.numerator();
    let alpha = match c.field().filter(|_| coeffs.len() > 1) {
        None => 0.0,
        Some(k) => match alphas.iter().find(|(f, _)| f.same_as(k)) {
            Some((_, a)) => *a,
            None => {
                let a = alpha_log2(k);
                alphas.push((k.clone(), a));
                a
            }
        },
    };
    let top = coeffs
        .iter()
        .enumerate()
        .filter(|(_, v)| *v != &IBig::ZERO)
        .map(|(j, v)| v.bit_len() as f64 + j as f64 * alpha)
        .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.max(v))))?;
    Some(top + 4.0 - c.denominator().bit_len() as f64 + 1.0)
}

/// An upper bound of `log₂ max(|α|, 1)` for the generator of `k`: half the bit length of `δ`
/// for `α = ±√δ`, else from the float of `α`.
pub(super) fn alpha_log2(k: &NumberField) -> f64 {
    use dashu_int::ops::BitTest;
    let alpha = k.alpha();
    match alpha.poly().coeffs() {
        [c0, c1, c2] if c1.is_zero() && *c2 == IBig::ONE => 0.5 * c0.bit_len() as f64,
        _ => alpha.to_f64().abs().max(1.0).log2(),
    }
}

/// `param` scaled by powers of two so that its largest coefficient is about 1, `None` when it
/// is small enough already (the largest estimate below `2^FLOAT_SCALE`, none below `2⁻⁹⁰⁰`):
/// the floats' squares and sums of squares (`‖X‖²`) stay far inside the range of `f64`, which
/// ends at `2¹⁰²⁴`. `X = a ± d√s` is projective: with `t_a`, `t_d`, `t_s` the largest
/// estimates, `s` gets `2^(2f)` (`f = −⌊t_s/2⌉`, so `s` is about 1), `d` gets `2^(−f−g)` and `a`
/// gets `2^(−g)` (`g = max(t_a, t_d − f)`): `a′ ± d′√s′ = 2^(−g)(a ± d√s)`, the point and both
/// sheets kept (positive factors).
pub(super) fn in_float_range(param: &ComponentParam) -> Option<ComponentParam> {
    let mut alphas: Vec<(NumberField, f64)> = Vec::new();
    // (largest, smallest) estimate of each part, one pass over the coefficients
    let mut range = |v: &[NumberPoly]| -> (Option<f64>, f64) {
        let mut top: Option<f64> = None;
        let mut bottom = f64::INFINITY;
        for c in v.iter().flat_map(|p| p.coeffs()) {
            if let Some(e) = log2_estimate(c, &mut alphas) {
                top = Some(top.map_or(e, |t| t.max(e)));
                bottom = bottom.min(e);
            }
        }
        (top, bottom)
    };
    let out = |(t, b): (Option<f64>, f64)| t.is_some_and(|t| t > FLOAT_SCALE) || b < -900.0;
    let scale = |v: &[NumberPoly; 4], e: i64| -> [NumberPoly; 4] {
        let k = crate::param::curve::rational(crate::param::expr::power_of_two(e));
        std::array::from_fn(|i| v[i].map(|c| c.mul(&k)))
    };
    match param {
        ComponentParam::Point(_) => None,
        ComponentParam::Rational { x, degree } => {
            let rx = range(x);
            if !out(rx) {
                return None;
            }
            let e = rx.0? as i64;
            if rx.1 - (e as f64) < -900.0 {
                return None;
            }
            Some(ComponentParam::Rational {
                x: scale(x, -e),
                degree: *degree,
            })
        }
        ComponentParam::Levin {
            a,
            d,
            degree,
            alternate,
            s,
        } => {
            let (ra, rd, rs) = (range(a), range(d), range(std::slice::from_ref(s)));
            if !(out(ra) || out(rd) || out(rs)) {
                return None;
            }
            let f = -(rs.0? * 0.5).round() as i64;
            let g = ra.0.unwrap_or(f64::NEG_INFINITY).max(rd.0? - f as f64) as i64;
            let (ea, ed, es) = (g, f + g, 2 * f);
            // every coefficient in range after the scaling (none lost below the floats)
            let spread = |(t, b): (Option<f64>, f64), e: i64| {
                t.is_none_or(|t| t + (e as f64) < 900.0) && b + (e as f64) > -900.0
            };
            if !(spread(ra, -ea) && spread(rd, -ed) && spread(rs, es)) {
                return None;
            }
            let k = crate::param::curve::rational(crate::param::expr::power_of_two(es));
            Some(ComponentParam::Levin {
                a: scale(a, -ea),
                d: scale(d, -ed),
                degree: *degree,
                alternate: alternate.clone(),
                s: s.map(|c| c.mul(&k)),
            })
        }
    }
}

/// Converts coefficients to floats, `√δ` in double-double made once per field.
#[derive(Default)]
pub(super) struct Converter {
    /// Each field met, with `α = ±√δ` in double-double and `δ` (`None`: not a field
    /// `ℚ(√δ)`).
    pub(super) roots: Vec<(NumberField, Option<(Dd, IBig)>)>,
}

/// A coefficient as a float, and in double-double (about 104 bits) where that is cheap:
/// rationals and ℚ(√δ).
pub(super) struct Converted {
    pub(super) value: f64,
    pub(super) dd: Option<Dd>,
}

impl Converter {
    /// `α` in double-double and `δ` when `k` is ℚ(√δ) generated by a root of `x² − δ` (the
    /// fields of Levin's form, [`super::curve::sqrt_field`]).
    pub(super) fn root(&mut self, k: &NumberField) -> Option<(Dd, &IBig)> {
        let at = match self.roots.iter().position(|(f, _)| f.same_as(k)) {
            Some(at) => at,
            None => {
                self.roots.push((k.clone(), sqrt_generator_dd(k)));
                self.roots.len() - 1
            }
        };
        self.roots[at].1.as_ref().map(|(r, delta)| (*r, delta))
    }

    /// `c` as a float and in double-double (module docs); [`Number::to_f64`] where the
    /// double-double is not finite or not available.
    #[inline]
    pub(super) fn convert(&mut self, c: &Number) -> Result<Converted, Error> {
        let num = c.numerator();
        // `v/1 = v` for a normalized double-double: the division left out; by a power of two
        // `2ᵏ` (one word), a product by `2⁻ᵏ`, exact away from the subnormals
        let over_den = |v: Dd| match c.denominator().as_sign_words().1 {
            [1] => v,
            [w] if w.is_power_of_two() && (v.0 == 0.0 || v.0.abs() >= 1e-250) => {
                let scale = 1.0 / (*w as f64);
                Dd(v.0 * scale, v.1 * scale)
            }
            _ => v.div(int_dd(c.denominator())),
        };
        let dd = if num.len() <= 1 {
            let n = num.first().map_or(Dd::default(), int_dd);
            Some(over_den(n))
        } else {
            // a numerator of positive degree has a field
            c.field()
                .and_then(|k| self.root(k))
                .and_then(|(r, delta)| sqrt_field_value(num, r, delta))
                .map(over_den)
        }
        .filter(|v| v.0.is_finite() && v.1.is_finite());
        let value = dd.map_or_else(|| c.to_f64(), |v| v.0 + v.1);
        if !value.is_finite() {
            return Err(Error::Algebra(format!(
                "coefficient {c} is beyond the range of f64"
            )));
        }
        Ok(Converted { value, dd })
    }
}

/// `c₀ + c₁α` with `α = ±√δ` given in double-double: the sum where the terms agree in sign
/// or cancel by fewer than 6 bits, else `(c₀² − c₁²δ)/(c₀ − c₁α)` with the integer norm
/// exact, so that cancellation costs at most 6 bits of about 104. `None` for a
/// representative of higher degree.
pub(super) fn sqrt_field_value(num: &[IBig], root: Dd, delta: &IBig) -> Option<Dd> {
    let (c0, c1) = match num {
        [c0] => (c0, &IBig::ZERO),
        [c0, c1] => (c0, c1),
        _ => return None,
    };
    let (t0, t1) = (int_dd(c0), int_dd(c1).mul(root));
    // the sum loses at most `log₂(max/|sum|)` bits, under 6 of its ~104 when the terms agree
    // in sign or the sum keeps at least `2⁻⁶` of the larger
    let sum = t0.add(t1);
    if t0.0 == 0.0
        || t1.0 == 0.0
        || (t0.0 > 0.0) == (t1.0 > 0.0)
        || sum.0.abs() >= t0.0.abs().max(t1.0.abs()) * (1.0 / 64.0)
    {
        return Some(sum);
    }
    // the norm in machine integers where it fits, else in big integers
    let small = || -> Option<i128> {
        let (a, b, d) = (
            i128::try_from(c0).ok()?,
            i128::try_from(c1).ok()?,
            i128::try_from(delta).ok()?,
        );
        a.checked_mul(a)?
            .checked_sub(b.checked_mul(b)?.checked_mul(d)?)
    };
    let norm = match small() {
        Some(n) => i128_dd(n),
        None => int_dd(&(c0 * c0 - c1 * c1 * delta)),
    };
    Some(norm.div(t0.add(t1.neg())))
}

pub(super) fn to_f64(c: &Number) -> Result<f64, Error> {
    Converter::default().convert(c).map(|c| c.value)
}
