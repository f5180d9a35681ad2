//! Balanced parameterizations: the parameter scaled by a power of two so that the curve shows
//! for moderate `u` — rational components, and Levin's forms `a ± d√s` (on `a`, or `s`), whose
//! floats otherwise leave the range of `f64` under big disguises.
//!
//! A rational component `X(u) = Σ cᵢuⁱ` of homogeneous degree `D` (no common factor, so
//! `c₀ ≠ 0` is the point at `u = 0` and `c_D ≠ 0` the point at `u = ∞`) traces the same curve
//! under `u ↦ 2ᵏu`; the coefficient vectors become `cᵢ·2^(ki)`, or, for `k < 0` and with the
//! homogeneous factor `2^(−kD)` that keeps them integral, `cᵢ·2^(−k(D−i))`. With
//! `k = round((log₂‖c₀‖ − log₂‖c_D‖)/D)` the lowest and the highest vectors are within a
//! factor `2^(D/2)` of each other (up to the estimates' error, a few units in the exponent):
//! a big disguise otherwise leaves them `10⁴⁰` and more apart, the whole curve then lies in
//! a parameter interval no float resolves, and no moderate `u` moves the point.
//!
//! The curve's pieces of a balanced component have their parameter values scaled by `2⁻ᵏ`
//! (an algebraic number `α` becomes the root `α/2ᵏ` of `p(2ᵏx)`, its interval scaled alike),
//! so every arc and every end stays where it was on the curve. Components whose vectors are
//! within [`SLACK`] of each other are left as they are: a balanced parameterization is not
//! rewritten. The exponents are chosen from estimates of `log₂|c|` (bit lengths, and the
//! float value of an element of a number field where it is finite): a choice of
//! presentation, not a decision; every output is the same curve exactly.

use super::curve::{
    ComponentParam, Curve, LevinForm, Number, NumberPoly, ParamRange, ParamValue, RealPiece,
};
use super::sample::convert::log2_estimate;
use qsic_algebra::field::NumberField;
use qsic_algebra::roots::RootInterval;
use qsic_algebra::{AlgebraicReal, IBig, Poly, RBig, Ring};

/// Vectors further apart than `2^SLACK` (in the ratio of their norms) are balanced; the
/// check of the issue allows `2²⁰`, the rounding of `k` leaves at most `2^(D/2) = 2²`.
pub const SLACK: f64 = 12.0;

/// Balances every rational component and every Levin form of `curve` (module docs).
pub(super) fn balance_curve(curve: &mut Curve) {
    for i in 0..curve.components.len() {
        let Some((param, k)) = curve.components[i].param.as_ref().and_then(balanced) else {
            continue;
        };
        curve.components[i].param = Some(param);
        for piece in &mut curve.pieces {
            if let RealPiece::Curve {
                component, arcs, ..
            } = piece
            {
                if *component == i {
                    for arc in arcs {
                        if let ParamRange::Between(lo, hi) = &mut arc.range {
                            *lo = scaled_value(lo, k);
                            *hi = scaled_value(hi, k);
                        }
                    }
                }
            }
        }
    }
}

/// `param` under `u ↦ 2ᵏu` and `k`, `None` when it is balanced already. A Levin form
/// `a ± d√s` (degrees `D`, `D − 2`, 4) is balanced on `a`, or on `s` where `a` has a zero end
/// vector: `a(2ᵏu) ± d(2ᵏu)√s(2ᵏu)` is the same curve, and for `k < 0` the homogeneous
/// factors `2^(−kD)`, `2^(−k(D−2))`, `2^(−4k)` agree (`√s` takes half of the last), so both
/// sheets are kept; its alternate form is scaled alike.
fn balanced(param: &ComponentParam) -> Option<(ComponentParam, i64)> {
    match param {
        ComponentParam::Point(_) => None,
        ComponentParam::Rational { x, degree } => {
            let k = balancing_exponent(x, *degree)?;
            let x = scaled_point(x, *degree, k);
            Some((ComponentParam::Rational { x, degree: *degree }, k))
        }
        ComponentParam::Levin {
            a,
            d,
            degree,
            alternate,
            s,
        } => {
            let mut alphas = Vec::new();
            let k = rough_exponent(a, *degree, &mut alphas).or_else(|| {
                let lo = log2_estimate(&s.coeff(0), &mut alphas)?;
                let hi = log2_estimate(&s.coeff(4), &mut alphas)?;
                exponent_of_gap_beyond(lo - hi, 4, LEVIN_SLACK)
            })?;
            let low = degree.saturating_sub(2);
            let alternate = alternate.as_ref().map(|f| {
                Box::new(LevinForm {
                    a: scaled_point(&f.a, f.degree, k),
                    d: scaled_point(&f.d, f.degree.saturating_sub(2), k),
                    degree: f.degree,
                })
            });
            Some((
                ComponentParam::Levin {
                    a: scaled_point(a, *degree, k),
                    d: scaled_point(d, low, k),
                    degree: *degree,
                    alternate,
                    s: scaled_form(s, 4, k),
                },
                k,
            ))
        }
    }
}

/// Levin's forms are balanced when the rough estimates ([`log2_estimate`]: bit lengths) put their end vectors
/// further apart than `2^LEVIN_SLACK`: far enough that the forms of ordinary pairs are left as
/// they are and cost only the estimates (~1 % of `parameterize` on random pairs), near enough
/// that a big disguise's forms, whose parts otherwise span more than the `2¹⁸⁰⁰` that floats
/// hold ([`super::sample`]), come back into range.
pub const LEVIN_SLACK: f64 = 64.0;

/// The `k` that balances the end vectors of `x` by the rough estimates, `None` within
/// [`LEVIN_SLACK`]; `alphas` keeps each field's `log₂|α|`.
fn rough_exponent(
    x: &[NumberPoly; 4],
    degree: usize,
    alphas: &mut Vec<(NumberField, f64)>,
) -> Option<i64> {
    let mut norm = |i: usize| {
        x.iter()
            .filter_map(|p| log2_estimate(&p.coeff(i), alphas))
            .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.max(v))))
    };
    let lo = norm(0)?;
    exponent_of_gap_beyond(lo - norm(degree)?, degree, LEVIN_SLACK)
}

/// The `k` of the module docs, `None` when the vectors are within [`SLACK`] already (or a
/// vector is zero, or an estimate is not available).
pub(super) fn balancing_exponent(x: &[NumberPoly; 4], degree: usize) -> Option<i64> {
    if degree == 0 {
        return None;
    }
    let lo = vector_log2(x.iter().map(|p| p.coeff(0)))?;
    let hi = vector_log2(x.iter().map(|p| p.coeff(degree)))?;
    exponent_of_gap(lo - hi, degree)
}

/// `round(gap/degree)`, `None` within [`SLACK`] (or a zero `k`).
fn exponent_of_gap(gap: f64, degree: usize) -> Option<i64> {
    exponent_of_gap_beyond(gap, degree, SLACK)
}

/// `round(gap/degree)`, `None` within `slack` (or a zero `k`).
fn exponent_of_gap_beyond(gap: f64, degree: usize, slack: f64) -> Option<i64> {
    if degree == 0 || gap.abs() <= slack {
        return None;
    }
    let k = (gap / degree as f64).round();
    // a gap of 2⁶³ bits is no legal input's (the readers bound the digits)
    (k != 0.0 && k.abs() < 1e15).then_some(k as i64)
}

/// An estimate of `log₂` of the Euclidean norm of the vector `v` (within a few units),
/// `None` for the zero vector.
fn vector_log2(v: impl Iterator<Item = Number>) -> Option<f64> {
    let logs: Vec<f64> = v.filter_map(|c| number_log2(&c)).collect();
    let top = logs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if !top.is_finite() {
        return None;
    }
    let sum: f64 = logs.iter().map(|l| (2.0f64).powf(2.0 * (l - top))).sum();
    Some(top + 0.5 * sum.log2())
}

/// An estimate of `log₂|c|`, `None` for zero: the float value where it is finite and
/// nonzero, else the bit lengths of the numerator (in the field's power basis, the
/// generator's size counted) and the denominator.
fn number_log2(c: &Number) -> Option<f64> {
    use dashu_int::ops::BitTest;
    if c.is_zero() {
        return None;
    }
    let v = c.to_f64();
    if v.is_finite() && v != 0.0 {
        return Some(v.abs().log2());
    }
    let alpha = c
        .field()
        .map_or(0.0, |k| k.alpha().to_f64().abs().max(1.0).log2());
    let top = c
        .numerator()
        .iter()
        .enumerate()
        .filter(|(_, v)| !v.is_zero())
        .map(|(j, v)| ibig_log2(v).max(v.bit_len() as f64 - 1.0) + j as f64 * alpha)
        .fold(f64::NEG_INFINITY, f64::max);
    top.is_finite()
        .then(|| top - ibig_log2(c.denominator()).max(0.0))
}

/// `log₂|v|` for a nonzero integer, from its leading bits.
fn ibig_log2(v: &IBig) -> f64 {
    use dashu_int::ops::BitTest;
    let bits = v.bit_len();
    if bits <= 1000 {
        return v.to_f64().value().abs().log2();
    }
    let shift = bits - 64;
    let top: IBig = v >> shift;
    top.to_f64().value().abs().log2() + shift as f64
}

/// `X(2ᵏu)` (module docs): `cᵢ·2^(ki)` for `k > 0`, `cᵢ·2^(−k(D−i))` for `k < 0`.
pub(super) fn scaled_point(x: &[NumberPoly; 4], degree: usize, k: i64) -> [NumberPoly; 4] {
    std::array::from_fn(|j| scaled_form(&x[j], degree, k))
}

/// `p(2ᵏu)` for a binary form of homogeneous degree `degree`, times `2^(−kD)` for `k < 0`.
fn scaled_form(p: &NumberPoly, degree: usize, k: i64) -> NumberPoly {
    let e = k.unsigned_abs() as usize;
    let c: Vec<Number> = (0..=degree)
        .map(|i| {
            let shift = if k > 0 { e * i } else { e * (degree - i) };
            times_power_of_two(&p.coeff(i), shift)
        })
        .collect();
    Poly::new(c)
}

/// `c·2^e`.
fn times_power_of_two(c: &Number, e: usize) -> Number {
    if e == 0 || c.is_zero() {
        return c.clone();
    }
    c * &Number::integer(IBig::ONE << e)
}

/// The parameter value `v` of the curve under `u ↦ 2ᵏu`: `v/2ᵏ` (`∞` stays).
fn scaled_value(v: &ParamValue, k: i64) -> ParamValue {
    match v {
        ParamValue::Infinity => ParamValue::Infinity,
        ParamValue::Finite(a) => ParamValue::Finite(scaled_real(a, k)),
    }
}

/// `α/2ᵏ`: the root of `p(2ᵏx)` (made integral and primitive) in the scaled interval.
fn scaled_real(a: &AlgebraicReal, k: i64) -> AlgebraicReal {
    let e = k.unsigned_abs() as usize;
    let two_e = RBig::from(IBig::ONE << e);
    let scale = |v: &RBig| if k > 0 { v / &two_e } else { v * &two_e };
    if let Some(v) = a.as_rational() {
        return AlgebraicReal::from_rational(scale(v));
    }
    let p = a.poly();
    let n = p.degree().unwrap_or(0);
    let q = Poly::new(
        (0..=n)
            .map(|i| {
                let shift = if k > 0 { e * i } else { e * (n - i) };
                p.coeff(i) << shift
            })
            .collect(),
    )
    .primitive_part();
    let interval = match a.interval() {
        RootInterval::Exact(v) => RootInterval::Exact(scale(v)),
        RootInterval::Open(lo, hi) => RootInterval::Open(scale(lo), scale(hi)),
    };
    AlgebraicReal::from_isolating_interval(&q, &interval)
        .expect("a scaled isolating interval isolates the scaled root")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rat(c: &Number) -> RBig {
        assert!(c.field().is_none());
        RBig::from(c.numerator().first().cloned().unwrap_or_default())
            / RBig::from(c.denominator().clone())
    }

    fn rational_poly(c: &[i64]) -> NumberPoly {
        Poly::new(c.iter().map(|&v| Number::integer(IBig::from(v))).collect())
    }

    fn eval_at(x: &[NumberPoly; 4], u: &RBig) -> Vec<RBig> {
        x.iter()
            .map(|p| {
                p.coeffs()
                    .iter()
                    .rev()
                    .fold(RBig::ZERO, |acc, c| acc * u + rat(c))
            })
            .collect()
    }

    fn proportional(a: &[RBig], b: &[RBig]) -> bool {
        (0..4).all(|i| (0..4).all(|j| &a[i] * &b[j] == &a[j] * &b[i]))
    }

    /// A line `P + u·D` with `|D| = 2⁹⁰|P|`: balanced to within `2^(D/2)`, the same points
    /// at the scaled parameters, integral, and an already balanced one left alone.
    #[test]
    fn an_unbalanced_line_is_scaled_and_traces_the_same_points() {
        let big = 1i64 << 45;
        let d = |v: i64| IBig::from(v) * IBig::from(big) * IBig::from(big);
        let x: [NumberPoly; 4] = std::array::from_fn(|j| {
            let (p, dv) = [(3, 5), (-1, 7), (2, -4), (1, 1)][j];
            Poly::new(vec![Number::integer(IBig::from(p)), Number::integer(d(dv))])
        });
        let k = balancing_exponent(&x, 1).expect("unbalanced");
        // log₂(‖(3, −1, 2, 1)‖/‖(5, 7, −4, 1)‖) − 90 ≈ −91.3
        assert_eq!(k, -91);
        let y = scaled_point(&x, 1, k);
        let (lo, hi) = (
            vector_log2(y.iter().map(|p| p.coeff(0))).unwrap(),
            vector_log2(y.iter().map(|p| p.coeff(1))).unwrap(),
        );
        assert!((lo - hi).abs() <= 1.0, "{lo} {hi}");
        assert!(y.iter().all(|p| p
            .coeffs()
            .iter()
            .all(|c| rat(c).denominator() == &dashu_int::UBig::ONE)));
        for u in [RBig::from(3), RBig::from(-7) / RBig::from(2)] {
            // X(2ᵏu) ∝ Y(u)
            let old_u = &u * RBig::from(IBig::ONE) / RBig::from(IBig::ONE << 91);
            assert!(proportional(&eval_at(&x, &old_u), &eval_at(&y, &u)));
        }
        assert_eq!(balancing_exponent(&y, 1), None);
        let small: [NumberPoly; 4] = std::array::from_fn(|j| rational_poly(&[j as i64 + 1, 1, 2]));
        assert_eq!(balancing_exponent(&small, 2), None);
    }

    /// A positive exponent on a conic, and an algebraic end moved with the parameter.
    #[test]
    fn a_conic_is_scaled_up_and_its_algebraic_ends_follow() {
        // c₀ = 2⁶⁰·(1, 0, 1, 0), c₂ = (0, 1, 0, 1): k = 30
        let e = IBig::ONE << 60;
        let x: [NumberPoly; 4] = [
            Poly::new(vec![
                Number::integer(e.clone()),
                Number::integer(IBig::ZERO),
                Number::integer(IBig::ZERO),
            ]),
            Poly::new(vec![
                Number::integer(IBig::ZERO),
                Number::integer(IBig::ONE),
                Number::integer(IBig::ONE),
            ]),
            Poly::new(vec![
                Number::integer(e.clone()),
                Number::integer(IBig::ZERO),
                Number::integer(IBig::ZERO),
            ]),
            Poly::new(vec![
                Number::integer(IBig::ZERO),
                Number::integer(IBig::ZERO),
                Number::integer(IBig::ONE),
            ]),
        ];
        assert_eq!(balancing_exponent(&x, 2), Some(30));
        // √2 · 2³⁰ becomes √2
        let root = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-(1i64 << 61), 0, 1]))
            .into_iter()
            .find(|r| r.to_f64() > 0.0)
            .unwrap();
        let moved = scaled_real(&root, 30);
        assert!((moved.to_f64() - 2f64.sqrt()).abs() < 1e-12);
        assert!(moved.is_root_of(&Poly::from_i64s(&[-2, 0, 1])));
        assert!(moved.is_valid());
    }

    /// A Levin form (case 3, `2xy + z² + w²` and `−x² + y² + z² + 2w²`) put out of balance
    /// by `u ↦ 2⁴⁰u`: balancing brings `k ≈ −40` back (on `a`), and the form — `a`, `d`, `s`
    /// and the alternate, each of its own degree — still lies on both quadrics, so every
    /// sheet is kept; the balanced one is left alone.
    #[test]
    fn levin_forms_are_balanced_on_both_sheets() {
        use crate::io::parse_quadric;
        let (qa, qb) = (
            parse_quadric("2*x*y+z^2+w^2").unwrap(),
            parse_quadric("-x^2+y^2+z^2+2*w^2").unwrap(),
        );
        let curve = super::super::parameterize(&qa, &qb).unwrap();
        let param = curve.components[0].param.clone().unwrap();
        let ComponentParam::Levin {
            a,
            d,
            degree,
            alternate,
            s,
        } = param
        else {
            panic!("a smooth quartic has Levin's form");
        };
        assert!(balanced(&ComponentParam::Levin {
            a: a.clone(),
            d: d.clone(),
            degree,
            alternate: alternate.clone(),
            s: s.clone(),
        })
        .is_none());
        let k = 40;
        let out_of_balance = ComponentParam::Levin {
            a: scaled_point(&a, degree, k),
            d: scaled_point(&d, degree - 2, k),
            degree,
            alternate: alternate.map(|f| {
                Box::new(LevinForm {
                    a: scaled_point(&f.a, f.degree, k),
                    d: scaled_point(&f.d, f.degree - 2, k),
                    degree: f.degree,
                })
            }),
            s: scaled_form(&s, 4, k),
        };
        assert!(out_of_balance.lies_on(qa.matrix()) && out_of_balance.lies_on(qb.matrix()));
        let (back, k2) = balanced(&out_of_balance).expect("out of balance");
        // the rough estimates (bit lengths) are within a few units of the exponent
        assert!((k2 + k).abs() <= 4, "k = {k2}");
        assert!(back.lies_on(qa.matrix()) && back.lies_on(qb.matrix()));
        let ComponentParam::Levin { a, alternate, .. } = &back else {
            panic!("still Levin's form");
        };
        assert!(rough_exponent(a, degree, &mut Vec::new()).is_none());
        assert!(alternate.is_some());
    }
}
