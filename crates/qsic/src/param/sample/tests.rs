//! Tests of the sampler and its accelerators.

use super::*;
use crate::param::curve::{ComponentParam, Curve, ParamRange, ParamValue, RealPiece, Sheet};
use crate::param::sample::chart::{dot, unit, Chart, ChartForm};
use crate::param::sample::convert::{in_float_range, Converter};
use crate::param::sample::crossings::{
    chart_form, crossing_sheets, exact_crossings_of, inner_f64, Crossings, ExactParam,
};
use crate::param::sample::eval::{sure_bounds, DdCoeffs, Evaluator, NARROW};
use crate::param::sample::kernels::dd::{
    int_dd, integral_f64_to_ibig, magnitude_dd, product_error, split, to_dd, Dd,
};
use crate::param::sample::kernels::horner::horner_lanes_abs;
use crate::param::sample::kernels::trig::{reduced_parameter, sin_cos};
use crate::param::sample::kernels::Lanes;
use crate::param::sample::sampler::Sampler;
use crate::param::sample::view::{affine_view, affine_view_two_pass};
use crate::param::sample::walk::{
    grid_before_event, run_of, run_of_reference, Approximations, Line, Sample, Walk,
};
use crate::param::sample::{SampleOptions, FLOAT_SCALE, MAX_ANGLE};
use crate::quadric::Quadric;
use qsic_algebra::{AlgebraicReal, IBig, Poly, RBig, Ring, Sign};
use std::cell::RefCell;
use std::f64::consts::{FRAC_PI_2, PI};

use crate::param::curve::sqrt_field;
use qsic_algebra::testing::SplitMix;

/// The curve of a random pair of symmetric integer matrices (entries in [−10, 10]),
/// `None` when a matrix is zero or the curve is not parameterized.
fn random_curve(rng: &mut SplitMix) -> Option<Curve> {
    let mut m = [[[0i64; 4]; 4]; 2];
    for q in &mut m {
        for i in 0..4 {
            for j in i..4 {
                let c = rng.int(-10, 10);
                q[i][j] = if i == j { 2 * c } else { c };
                q[j][i] = q[i][j];
            }
        }
    }
    let (a, b) = (
        Quadric::from_integers(m[0]).ok()?,
        Quadric::from_integers(m[1]).ok()?,
    );
    crate::param::parameterize(&a, &b).ok()
}

/// The crossings of Levin's form over ℚ as the per-root route over the rationals found
/// them (each sign by `sign_of`, the removable-zero test at every root): the same
/// parameters and sheets, on the rational Levin parameterizations of random pairs
/// (those with removable zeros among them) and four charts.
#[test]
fn exact_crossings_equal_the_per_root_route() {
    /// The crossings, and how many roots of `n` are removable zeros (every norm zero).
    fn reference(exact: &ExactParam, h: &[RBig; 4]) -> (Vec<(ParamValue, Vec<Sheet>)>, usize) {
        let ExactParam::Levin { a, d, s, degree } = exact else {
            unreachable!("a Levin form")
        };
        let sign_at = |p: &Poly<RBig>, r: &AlgebraicReal| {
            if p.is_zero() {
                Sign::Zero
            } else {
                r.sign_of(&Poly::from_rational(p).0)
            }
        };
        let top = |p: &Poly<RBig>, k: usize| Sign::of(p.coeff(k).numerator());
        let (ha, hd) = (chart_form(h, a), chart_form(h, d));
        let n = &(&ha * &ha) - &(&(&hd * &hd) * s);
        let norms: Vec<Poly<RBig>> = (0..4)
            .map(|i| &(&a[i] * &a[i]) - &(&(&d[i] * &d[i]) * s))
            .collect();
        let sheets = crossing_sheets;
        let keep = |sheet: Sheet,
                    sa: &dyn Fn(usize) -> Sign,
                    sd: &dyn Fn(usize) -> Sign,
                    z: &dyn Fn(usize) -> bool| {
            !(0..4).all(|i| {
                z(i) && match sheet {
                    Sheet::Plus => sa(i) == -sd(i),
                    _ => sa(i) == sd(i),
                }
            })
        };
        let roots = AlgebraicReal::real_roots_of(&Poly::from_rational(&n).0.squarefree_part());
        let (mut out, mut removable) = (Vec::new(), 0);
        for r in roots {
            removable += usize::from(norms.iter().all(|m| sign_at(m, &r) == Sign::Zero));
            let on_s = sign_at(s, &r) == Sign::Zero;
            let mut sh = sheets(sign_at(&ha, &r), sign_at(&hd, &r), sign_at(s, &r));
            sh.retain(|&sheet| {
                keep(
                    sheet,
                    &|i| sign_at(&a[i], &r),
                    &|i| if on_s { Sign::Zero } else { sign_at(&d[i], &r) },
                    &|i| sign_at(&norms[i], &r) == Sign::Zero,
                )
            });
            out.push((ParamValue::Finite(r), sh));
        }
        if n.degree().unwrap_or(0) < 2 * degree {
            let on_s = top(s, 4) == Sign::Zero;
            let mut sh = sheets(top(&ha, *degree), top(&hd, degree - 2), top(s, 4));
            sh.retain(|&sheet| {
                keep(
                    sheet,
                    &|i| top(&a[i], *degree),
                    &|i| {
                        if on_s {
                            Sign::Zero
                        } else {
                            top(&d[i], degree - 2)
                        }
                    },
                    &|i| top(&norms[i], 2 * degree) == Sign::Zero,
                )
            });
            out.push((ParamValue::Infinity, sh));
        }
        (out, removable)
    }
    let charts: [[i64; 4]; 4] = [[0, 0, 0, 1], [1, 0, 0, 0], [1, -2, 3, 1], [0, 1, 1, -5]];
    let mut rng = SplitMix(5);
    let (mut params, mut tried, mut removable) = (0, 0, 0);
    while params < 12 && tried < 6000 {
        tried += 1;
        let Some(curve) = random_curve(&mut rng) else {
            continue;
        };
        for c in &curve.components {
            let Some(param) = &c.param else { continue };
            let exact = ExactParam::new(param);
            if !matches!(exact, ExactParam::Levin { .. }) {
                continue;
            }
            params += 1;
            for chart in &charts {
                let h = chart.map(RBig::from);
                let got = exact_crossings_of(&exact, &h).expect("a Levin form over ℚ");
                let (want, r) = reference(&exact, &h);
                removable += r;
                assert_eq!(got.len(), want.len(), "{chart:?}");
                for (g, (value, sheets)) in got.iter().zip(&want) {
                    let same = match (&g.value, value) {
                        (ParamValue::Finite(x), ParamValue::Finite(y)) => x == y,
                        (ParamValue::Infinity, ParamValue::Infinity) => true,
                        _ => false,
                    };
                    assert!(same, "{chart:?}");
                    assert_eq!(g.sheets, *sheets, "{chart:?}");
                }
            }
        }
    }
    assert!(
        params >= 12,
        "{params} rational Levin forms in {tried} pairs"
    );
    assert!(removable >= 4, "{removable} removable zeros");
}

/// Levin parameterizations of random generic pairs (coefficients in ℚ(√δ)).
fn levin_params(seed: u64, count: usize) -> Vec<ComponentParam> {
    let mut rng = SplitMix(seed);
    let mut out = Vec::new();
    while out.len() < count {
        let Some(curve) = random_curve(&mut rng) else {
            continue;
        };
        for c in curve.components {
            if let Some(p @ ComponentParam::Levin { .. }) = c.param {
                out.push(p);
            }
        }
    }
    out
}

/// The grid of both sheets at once ([`Evaluator::grid_both`]) against [`Evaluator::grid`]
/// on each sheet and against single evaluations at `(sin θ, cos θ)`, over ranges all
/// round ℙ¹.
#[test]
fn both_sheet_grid_matches_single_evaluations() {
    let mut checked = 0;
    for param in levin_params(0x5eed, 4) {
        let eval = Evaluator::new(&param).unwrap();
        for (t0, t1) in [(-FRAC_PI_2, FRAC_PI_2), (-0.3, 1.2), (1.0, 1.0 + PI)] {
            let n = 200;
            let step = (t1 - t0) / n as f64;
            let (mut plus, mut minus, mut one) = (Vec::new(), Vec::new(), Vec::new());
            eval.grid_both(t0, step, n, &mut plus, &mut minus);
            assert_eq!((plus.len(), minus.len()), (n - 1, n - 1));
            for (sheet, got) in [(Sheet::Plus, &plus), (Sheet::Minus, &minus)] {
                eval.grid(t0, step, n, sheet, &mut one);
                assert_eq!(&one, got, "the same operations on one sheet");
                for (k, x) in got.iter().enumerate() {
                    let u = (t0 + step * (k + 1) as f64).sin_cos();
                    match eval.eval_unit(u, sheet) {
                        Some(y) if !x[0].is_nan() => {
                            assert!(dot(x, &y) > 1.0 - 1e-12, "{x:?} {y:?}");
                            checked += 1;
                        }
                        _ => {}
                    }
                }
            }
        }
    }
    assert!(checked > 4000, "{checked}");
}

/// The unrolled rounding bound of the two-sheet grid ([`Evaluator::bound_of`]) is the
/// generic one of [`Evaluator::certify`] bit for bit, on both Horner orders.
#[test]
fn unrolled_bound_matches_generic_bound() {
    let mut rng = SplitMix(0xb0d);
    let mut checked = 0;
    for param in levin_params(0xb0e, 6) {
        let eval = Evaluator::new(&param).unwrap();
        let n = eval.big_d + 1;
        for _ in 0..200 {
            let t = rng.int(-1000, 1000) as f64 / 1000.0;
            let root = rng.int(0, 1 << 20) as f64 / 1024.0;
            for rev in [false, true] {
                let bx = horner_lanes_abs(&eval.x()[..n], t, rev);
                let bd = horner_lanes_abs(&eval.d()[..n - 2], t, rev);
                let want = (0..4).map(|i| bx[i] + bd[i] * root).fold(0.0, f64::max);
                let got = match eval.big_d {
                    2 => eval.bound_of::<3, 1>(t, rev, root),
                    3 => eval.bound_of::<4, 2>(t, rev, root),
                    4 => eval.bound_of::<5, 3>(t, rev, root),
                    _ => continue,
                };
                assert_eq!(got.to_bits(), want.to_bits(), "t = {t}, rev = {rev}");
                checked += 1;
            }
        }
    }
    assert!(checked >= 2000, "{checked}");
}

/// The certificate made once per evaluator ([`Evaluator::sure`]) implies the bound at
/// `|t|` ([`Evaluator::bound_of`]) that it stands for: every computed `√s` on `[−1, 1]`
/// is within `sure_root`, and a norm it passes passes the per-point test; beyond the range
/// of the shortcut it certifies nothing.
#[test]
fn certificate_made_once_implies_the_pointwise_bound() {
    let mut rng = SplitMix(0x5a4e);
    let (mut sure, mut total) = (0, 0);
    for param in levin_params(0x5a4f, 8) {
        let eval = Evaluator::new(&param).unwrap();
        for _ in 0..400 {
            let t = rng.int(-1 << 20, 1 << 20) as f64 / (1 << 20) as f64;
            for rev in [false, true] {
                let (x, w, root, bound) = match eval.big_d {
                    2 => {
                        let (x, w, r) = eval.parts::<3, 1>(t, rev);
                        (x, w, r, eval.bound_of::<3, 1>(t, rev, r))
                    }
                    3 => {
                        let (x, w, r) = eval.parts::<4, 2>(t, rev);
                        (x, w, r, eval.bound_of::<4, 2>(t, rev, r))
                    }
                    4 => {
                        let (x, w, r) = eval.parts::<5, 3>(t, rev);
                        (x, w, r, eval.bound_of::<5, 3>(t, rev, r))
                    }
                    _ => continue,
                };
                assert!(root <= eval.sure_root, "t = {t}");
                for sign in [1.0, -1.0] {
                    let p: Lanes = std::array::from_fn(|i| x[i] + sign * root * w[i]);
                    let norm = dot(&p, &p).sqrt();
                    total += 1;
                    if eval.sure(root, norm) {
                        sure += 1;
                        assert!(eval.gamma * bound <= 1e-10 * norm, "t = {t}");
                    }
                }
            }
        }
    }
    assert!(sure > total / 2 && sure < total + 1, "{sure} of {total}");
    let s = [1.0, 0.0, 0.0, 0.0, 1.0];
    assert_eq!(
        sure_bounds(1e-14, 1e301, 1.0, &s),
        (f64::INFINITY, f64::INFINITY)
    );
    assert_eq!(
        sure_bounds(1e-14, 0.0, 0.0, &[0.0; 5]),
        (f64::INFINITY, f64::INFINITY)
    );
    assert!(sure_bounds(1e-14, 1.0, 1.0, &s).1.is_finite());
    assert_eq!(NARROW, (2f64.powi(-800), 2f64.powi(FLOAT_SCALE as i32)));
}

/// A parameterization with coefficients beyond `2⁹⁰⁰` (not [`NARROW`], and beyond
/// [`in_float_range`]'s limit) is scaled into the floats' range first: the same points as
/// the parameterization it is a multiple of.
#[test]
fn wide_parameterizations_are_scaled_before_sampling() {
    let mut rng = SplitMix(0x1de);
    let mut checked = 0;
    while checked < 3 {
        let mut m = [[[0i64; 4]; 4]; 2];
        for q in &mut m {
            for i in 0..4 {
                for j in i..4 {
                    q[i][j] = rng.int(-10, 10);
                    q[j][i] = q[i][j];
                }
            }
        }
        let (Ok(a), Ok(b)) = (Quadric::from_integers(m[0]), Quadric::from_integers(m[1])) else {
            continue;
        };
        let Ok(curve) = crate::param::parameterize(&a, &b) else {
            continue;
        };
        if curve.pieces.is_empty()
            || !(curve.components.iter())
                .any(|c| matches!(c.param, Some(ComponentParam::Levin { .. })))
        {
            continue;
        }
        let k = crate::param::curve::rational(RBig::from(IBig::ONE << 950));
        let mut wide = curve.clone();
        for c in &mut wide.components {
            if let Some(ComponentParam::Levin { a, d, .. }) = &mut c.param {
                for v in a.iter_mut().chain(d.iter_mut()) {
                    *v = v.map(|c| c.mul(&k));
                }
                let eval = Evaluator::new(c.param.as_ref().unwrap()).unwrap();
                assert!(!eval.narrow);
                assert!(in_float_range(c.param.as_ref().unwrap()).is_some());
            }
        }
        let options = SampleOptions::default();
        let (x, y) = (
            sample(&curve, &options).unwrap(),
            sample(&wide, &options).unwrap(),
        );
        assert_eq!(x.pieces.len(), y.pieces.len());
        for (p, q) in x.pieces.iter().zip(&y.pieces) {
            assert_eq!(p.points.len(), q.points.len());
            for (u, v) in p.points.iter().zip(&q.points) {
                assert!(dot(u, v).abs() > 1.0 - 1e-12, "{u:?} {v:?}");
            }
        }
        checked += 1;
    }
}

/// The first grid index at or after an event, from the estimate, is the one a scan of
/// the test finds: events on grid points, just off them, outside the range, none.
#[test]
fn grid_index_of_event_matches_scan() {
    let mut rng = SplitMix(0xe7);
    for _ in 0..2000 {
        let n = rng.int(2, 600) as usize;
        let t0 = rng.int(-4000, 4000) as f64 / 1000.0;
        let step = rng.int(1, 3000) as f64 / (1000.0 * n as f64);
        let k = rng.int(1, n as i64) as usize;
        let j = rng.int(-3, n as i64 + 3) as f64;
        let next = match rng.int(0, 4) {
            0 => t0 + step * j,
            1 => t0 + step * j - 1e-12,
            2 => t0 + step * j + 2e-12 * (rng.int(-2, 2) as f64),
            3 => t0 + step * (j + 0.5),
            _ => f64::INFINITY,
        };
        let scan = (k..n)
            .find(|&j| next <= t0 + step * (j as f64) + 1e-12)
            .unwrap_or(n);
        assert_eq!(
            grid_before_event(k, n, (t0, step), next),
            scan,
            "k = {k}, n = {n}, t0 = {t0}, step = {step}, next = {next}"
        );
    }
}

/// Marks follow their points through pushes, joins, pops and the reversal of a tail.
#[test]
fn line_marks_follow_their_points() {
    let mut line = Line::default();
    for k in 0..10 {
        let mut s = Sample::new(k as f64, [k as f64, 1.0, 0.0, 0.0]);
        s.at_infinity = k == 2 || k == 7;
        s.singular = k == 8;
        line.push(&s);
    }
    line.mark(4, false, true);
    line.mark(2, false, true);
    assert_eq!(
        line.marks,
        vec![
            (2, true, true),
            (4, false, true),
            (7, true, false),
            (8, false, true)
        ]
    );
    // reversed and negated in one pass: reversed, then negated
    for len in [3, 4, 5, 6, 7] {
        let mut one = Line {
            chart: ChartForm::new([1.0, 0.0, 0.5, 1.0]),
            ..Line::default()
        };
        for k in 0..len {
            one.push(&Sample::new(k as f64, [k as f64, 1.0, -2.0, 0.5]));
        }
        let mut two = Line {
            x: one.x.clone(),
            h: one.h.clone(),
            ..Line::default()
        };
        one.reverse_from(1, true);
        two.reverse_from(1, false);
        let neg: Vec<[f64; 4]> = two.x.iter().map(|v| v.map(|c| -c)).collect();
        assert_eq!((&one.x[..1], &one.x[1..]), (&two.x[..1], &neg[1..]));
        let neg_h: Vec<f64> = two.h.iter().map(|v| -v).collect();
        assert_eq!((&one.h[..1], &one.h[1..]), (&two.h[..1], &neg_h[1..]));
    }
    line.reverse_from(3, false);
    // points 3..10 reversed: index i ↦ 12 − i
    assert_eq!(line.x[3][0], 9.0);
    assert_eq!(
        line.marks,
        vec![
            (2, true, true),
            (4, false, true),
            (5, true, false),
            (8, false, true)
        ]
    );
    for &(k, _, _) in &line.marks[1..] {
        assert!([4.0, 7.0, 8.0].contains(&line.x[k][0]));
    }
    assert_eq!(line.pop(), (false, false));
    // point 8 (the old point 4, singular) joins a crossing
    line.mark(line.len() - 1, true, false);
    assert_eq!(line.pop(), (true, true));
    assert_eq!(line.len(), 8);
}

/// `x − y√2` for the solutions of Pell's equation `x² − 2y² = 1`: the terms cancel to
/// `1/(x + y√2)`, by up to ~200 bits; the float must keep its full precision.
#[test]
fn conversion_keeps_precision_through_cancellation() {
    let k = sqrt_field(&IBig::from(2));
    let (mut x, mut y) = (IBig::from(3), IBig::from(2));
    let mut conv = Converter::default();
    for _ in 0..40 {
        for den in [1, 3, 4] {
            let c = k.element(&Poly::new(vec![
                RBig::from_parts_signed(x.clone(), den.into()),
                RBig::from_parts_signed(-y.clone(), den.into()),
            ]));
            let v = conv.convert(&c).unwrap();
            let conjugate = x.to_f64().value() + y.to_f64().value() * std::f64::consts::SQRT_2;
            let product = v.value * conjugate * den as f64;
            assert!((product - 1.0).abs() < 1e-14, "x = {x}: {product}");
            let dd = v.dd.expect("ℚ(√2) has a double-double");
            assert!(((dd.0 + dd.1) * conjugate * den as f64 - 1.0).abs() < 1e-14);
        }
        // the next solution: (x, y) → (3x + 4y, 2x + 3y)
        (x, y) = (&x * 3 + &y * 4, &x * 2 + &y * 3);
    }
    assert_eq!(conv.roots.len(), 1, "√2 made once");
}

#[test]
fn integers_split_exactly_into_double_doubles() {
    let mut rng = SplitMix(11);
    for bits in [10, 52, 53, 54, 64, 100, 106, 150, 400] {
        for _ in 0..20 {
            let v = (IBig::from(rng.next_u64()) << bits) >> 64;
            let v = if rng.next_u64() % 2 == 0 { -v } else { v };
            let d = int_dd(&v);
            let rest = &v - integral_f64_to_ibig(d.0);
            // lo is the rest rounded: exact below 2¹⁰⁶
            let err = if d.1 == 0.0 {
                rest.clone()
            } else {
                &rest - integral_f64_to_ibig(d.1.trunc())
            };
            let tolerance = IBig::ONE << bits.saturating_sub(100);
            assert!(&err * &err <= &tolerance * &tolerance, "{v}: {d:?}");
        }
    }
}

/// [`sin_cos`] is the library's within `2⁻⁵¹` with the same signs, on random angles of
/// the arcs' range, at the multiples of `π/4` and next to them, and beyond its range
/// (the library's itself).
#[test]
fn fast_sine_and_cosine_match_the_library() {
    let mut rng = SplitMix(0x51c0);
    let mut thetas: Vec<f64> = (0..20_000)
        .map(|_| (rng.next_u64() as f64 / u64::MAX as f64 - 0.3) * 12.0)
        .collect();
    for k in -12..=12 {
        let c = k as f64 * std::f64::consts::FRAC_PI_4;
        thetas.extend([c, c + 1e-9, c - 1e-9, c + 1e-15, c - 1e-15]);
    }
    thetas.extend([1e-300, -1e-300, 0.0, -0.0, 1e-8]);
    for theta in thetas {
        let (s, c) = sin_cos(theta);
        let (ws, wc) = theta.sin_cos();
        assert!((s - ws).abs() <= 2f64.powi(-51), "{theta}: {s} {ws}");
        assert!((c - wc).abs() <= 2f64.powi(-51), "{theta}: {c} {wc}");
        for (v, w) in [(s, ws), (c, wc)] {
            assert!(w.abs() < 1e-15 || (v > 0.0) == (w > 0.0), "{theta}");
        }
    }
    for theta in [1e6, -3e7, f64::INFINITY] {
        let (got, want) = (sin_cos(theta), theta.sin_cos());
        assert_eq!(got.0.to_bits(), want.0.to_bits());
        assert_eq!(got.1.to_bits(), want.1.to_bits());
    }
}

/// [`magnitude_dd`] (signed conversions where a word allows) is the general split (top
/// 53 bits plus the rest through two unsigned words) bit for bit, at every bit length
/// up to 127, the rest at or beyond `2⁶³` included (the fallback branch).
#[test]
fn magnitude_split_matches_general_route() {
    let reference = |m: u128, neg: bool| -> Dd {
        let bits = 128 - m.leading_zeros();
        if bits <= 53 {
            let x = (m as u64) as f64;
            return Dd(if neg { -x } else { x }, 0.0);
        }
        let e = bits - 53;
        let top = (m >> e) as u64;
        let scale = f64::from_bits(((1023 + e) as u64) << 52);
        let rest = m - ((top as u128) << e);
        let rest_f = ((rest >> 64) as u64) as f64 * 18446744073709551616.0 + (rest as u64) as f64;
        let d = Dd::two_sum(top as f64 * scale, rest_f);
        if neg {
            d.neg()
        } else {
            d
        }
    };
    let mut rng = SplitMix(0xd0d0);
    let mut wide_rest = 0;
    for bits in 0..=127u32 {
        for _ in 0..20 {
            let m = ((u128::from(rng.next_u64()) << 64) | u128::from(rng.next_u64()))
                >> (128 - bits.max(1));
            let m = if bits == 0 { 0 } else { m | (1 << (bits - 1)) };
            let neg = rng.int(0, 1) == 1;
            let (got, want) = (magnitude_dd(m, neg), reference(m, neg));
            assert_eq!((got.0, got.1), (want.0, want.1), "{m}");
            let v = if neg { -IBig::from(m) } else { IBig::from(m) };
            let via = int_dd(&v);
            assert_eq!((via.0, via.1), (want.0, want.1), "{m}");
            wide_rest += usize::from(bits > 53 && m & ((1 << (bits - 53)) - 1) >= 1 << 63);
        }
    }
    assert!(wide_rest > 100, "{wide_rest}");
}

/// Dekker's product ([`product_error`]) is the fused multiply-add's rounding error, and
/// the lane-wise double-double evaluation ([`Evaluator::values_dd`]) is the one
/// coordinate at a time by `mul_add` ([`Evaluator::values_dd_fused`]), value for value, on
/// random parameters all round ℙ¹ and both sheets; coefficients beyond Veltkamp's range
/// give NaN there, and [`Evaluator::eval_dd`] falls back to the fused products.
#[test]
fn double_double_lanes_match_fused_products() {
    let mut rng = SplitMix(0xdd4);
    for _ in 0..20_000 {
        let e = rng.int(-900, 900) as i32;
        let a = (rng.next_u64() as f64 / u64::MAX as f64 - 0.5) * 2f64.powi(e);
        let b = rng.next_u64() as f64 / u64::MAX as f64 * 2.0 - 1.0;
        let p = a * b;
        assert_eq!(product_error(a, split(b), p), a.mul_add(b, -p), "{a} {b}");
    }
    let mut checked = 0;
    for param in levin_params(0xdd5, 6) {
        let eval = Evaluator::new(&param).unwrap();
        for _ in 0..200 {
            let theta = (rng.next_u64() as f64 / u64::MAX as f64 - 0.5) * PI;
            let (t, rev) = reduced_parameter(theta.sin_cos());
            for sheet in [Sheet::Plus, Sheet::Minus] {
                let (got, want) = (
                    eval.values_dd(t, rev, sheet),
                    eval.values_dd_fused(t, rev, sheet),
                );
                assert_eq!(got, want, "t = {t}");
                checked += 1;
            }
        }
        // `a` beyond 2⁹⁹⁶: the split overflows, the fused products do not
        // (the leading coefficients, at a tiny `t`: the values stay in range)
        let mut wide = eval.dd().clone();
        for (i, c) in wide.x[eval.big_d].iter_mut().enumerate() {
            *c = Dd((1.0 + i as f64 / 8.0) * 2f64.powi(1000), 0.0);
        }
        let wide = Evaluator {
            quick_dd: Some(Box::new(wide)),
            ..Evaluator::new(&param).unwrap()
        };
        let t = 2f64.powi(-400);
        assert!(wide
            .values_dd(t, false, Sheet::Plus)
            .iter()
            .any(|v| v.is_nan()));
        let fused = wide.values_dd_fused(t, false, Sheet::Plus);
        assert!(fused.iter().all(|v| v.is_finite()));
        assert_eq!(wide.eval_dd(t, false, Sheet::Plus, 0.0), Some(fused));
    }
    assert!(checked >= 2000, "{checked}");
}

/// [`Evaluator::eval_unit`] (unrolled Horner, unrolled bound where the majorant does not
/// certify) is the generic route (any degree: [`Evaluator::values_any`], then
/// [`Evaluator::certify`]) point for point, on rational and Levin parameterizations, with
/// points certified by the bound at `|t|` only among them.
#[test]
fn unrolled_evaluation_matches_generic_route() {
    let mut rng = SplitMix(0xe7a1);
    let mut params = levin_params(0xe7a2, 6);
    let mut seed = SplitMix(0xe7a3);
    while params.len() < 12 {
        let Some(curve) = random_curve(&mut seed) else {
            continue;
        };
        params.extend(curve.components.into_iter().filter_map(|c| match c.param {
            Some(p @ ComponentParam::Rational { .. }) => Some(p),
            _ => None,
        }));
    }
    let (mut checked, mut by_bound, mut rational) = (0, 0, 0);
    for param in &params {
        let eval = Evaluator::new(param).unwrap();
        let sheets: &[Sheet] = if eval.levin {
            &[Sheet::Plus, Sheet::Minus]
        } else {
            rational += 1;
            &[Sheet::Only]
        };
        for k in 0..2000 {
            // uniform in θ, and clustered near t = 0 and t = ±1
            let theta = match k % 3 {
                0 => (rng.next_u64() as f64 / u64::MAX as f64 - 0.5) * PI,
                1 => (rng.next_u64() as f64 / u64::MAX as f64 - 0.5) * 1e-3,
                _ => FRAC_PI_2 * (1.0 - 2e-3 * rng.next_u64() as f64 / u64::MAX as f64),
            };
            let u = theta.sin_cos();
            let (t, rev) = reduced_parameter(u);
            for &sheet in sheets {
                let (x, root) = eval.values_any(t, rev, sheet);
                let norm = dot(&x, &x).sqrt();
                let cheap = eval.cheaply_certified(t, rev, root, norm);
                let want = if cheap {
                    Some(x.map(|v| v / norm))
                } else {
                    by_bound += 1;
                    eval.certify(t, rev, sheet, x, norm, root)
                };
                assert_eq!(eval.eval_unit(u, sheet), want, "θ = {theta}");
                checked += 1;
            }
        }
    }
    assert!(
        rational > 0 && checked > 20_000 && by_bound > 0,
        "{rational} {checked} {by_bound}"
    );
}

/// The float evaluation (majorant certificate, unrolled Horner) against the double-double
/// one from coefficients made by the refined route ([`to_dd`], not the [`Converter`]),
/// on both sheets, at parameters all round ℙ¹.
#[test]
fn fast_evaluation_matches_double_double_from_refined_coefficients() {
    let mut rng = SplitMix(7);
    let (mut checked, mut unrolled) = (0, 0);
    for param in levin_params(0x1e_71, 6) {
        let eval = Evaluator::new(&param).unwrap();
        let ComponentParam::Levin { a, d, s, .. } = &param else {
            unreachable!()
        };
        let mut refined = Box::<DdCoeffs>::default();
        for i in 0..4 {
            for (k, c) in a[i].coeffs().iter().enumerate() {
                refined.x[k][i] = to_dd(c);
            }
            for (k, c) in d[i].coeffs().iter().enumerate() {
                refined.d[k][i] = to_dd(c);
            }
        }
        for (k, c) in s.coeffs().iter().enumerate() {
            refined.s[k] = to_dd(c);
        }
        let reference = Evaluator {
            quick_dd: Some(refined),
            ..Evaluator::new(&param).unwrap()
        };
        for _ in 0..200 {
            let theta = (rng.next_u64() as f64 / u64::MAX as f64 - 0.5) * PI;
            let u = theta.sin_cos();
            let (t, rev) = reduced_parameter(u);
            for sheet in [Sheet::Plus, Sheet::Minus] {
                let Some(x) = eval.eval_unit(u, sheet) else {
                    continue;
                };
                let y = reference
                    .eval_dd(t, rev, sheet, 0.0)
                    .and_then(unit)
                    .expect("double-double evaluates where floats do");
                // the unrolled Horner is the general one, operation for operation
                if eval.big_d == 3 {
                    let fixed = eval.values::<4, 2>(t, rev, sheet);
                    assert_eq!(fixed, eval.values_any(t, rev, sheet));
                    unrolled += 1;
                }
                assert!(dot(&x, &y) > 1.0 - 1e-12, "{x:?} {y:?}");
                checked += 1;
            }
        }
    }
    assert!(checked > 2000 && unrolled > 0, "{checked} {unrolled}");
}

/// Curves of random generic pairs with a real piece on a Levin component: the curve and
/// the component's index.
fn levin_curves(seed: u64, count: usize) -> Vec<(Curve, usize)> {
    let mut rng = SplitMix(seed);
    let mut out = Vec::new();
    while out.len() < count {
        let Some(curve) = random_curve(&mut rng) else {
            continue;
        };
        let levin = curve.pieces.iter().find_map(|p| match p {
            RealPiece::Curve { component, .. } => matches!(
                curve.components[*component].param,
                Some(ComponentParam::Levin { .. })
            )
            .then_some(*component),
            RealPiece::Point { .. } => None,
        });
        if let Some(k) = levin {
            out.push((curve, k));
        }
    }
    out
}

/// A sampler of `param` with no exact events (crossings located along the walk).
fn test_sampler<'a>(
    param: &'a ComponentParam,
    chart: &'a Chart,
    approx: &'a Approximations,
) -> Sampler<'a> {
    Sampler {
        eval: Evaluator::new(param).unwrap(),
        crossings: Crossings::Unknown,
        singular: Vec::new(),
        chart,
        tolerance: None,
        approx,
        ends: RefCell::new(Vec::new()),
        other_sheet: RefCell::new(None),
        stuck: std::cell::Cell::new(None),
        geometric: false,
    }
}

/// The arc ends kept by [`Sampler::end_value`] are the ends found afresh, bit for bit,
/// and an end shared by two arcs (the two sheets of an oval) is found once.
#[test]
fn arc_ends_found_once_are_the_ends_found_afresh() {
    let (mut shared, mut checked) = (0, 0);
    let chart = SampleOptions::default().chart().unwrap();
    for (curve, k) in levin_curves(0xe4d5, 12) {
        let param = curve.components[k].param.as_ref().unwrap();
        let approx = Approximations::default();
        let sampler = test_sampler(param, &chart, &approx);
        let mut ends: Vec<&AlgebraicReal> = Vec::new();
        for piece in &curve.pieces {
            let RealPiece::Curve {
                component, arcs, ..
            } = piece
            else {
                continue;
            };
            if *component != k {
                continue;
            }
            for arc in arcs {
                let ParamRange::Between(lo, hi) = &arc.range else {
                    continue;
                };
                for r in [lo, hi].into_iter().filter_map(|v| match v {
                    ParamValue::Finite(r) => Some(r),
                    ParamValue::Infinity => None,
                }) {
                    let kept = sampler.end_value(r);
                    let fresh = sampler.end_value_uncached(r);
                    assert_eq!(kept.to_bits(), fresh.to_bits(), "{r:?}");
                    // the end itself
                    let exact = r.to_f64();
                    assert!((kept - exact).abs() <= 1e-9 * (1.0 + exact.abs()), "{r:?}");
                    if ends.iter().any(|q| q.same_definition(r)) {
                        shared += 1;
                    } else {
                        ends.push(r);
                    }
                    checked += 1;
                }
            }
        }
        assert_eq!(
            sampler.ends.borrow().len(),
            ends.len(),
            "one search per end"
        );
    }
    assert!(checked >= 24 && shared >= 12, "{checked} {shared}");
}

/// The affine view cut in runs of one sign of `h` ([`Sampler::affine`], four points a
/// step) is the point-by-point reference on random polylines: runs of either sign,
/// zeros of either sign, tiny values, marks at infinity and singular, open and closed.
#[cfg(debug_assertions)]
#[test]
fn affine_view_in_runs_matches_point_by_point() {
    let mut rng = SplitMix(0xaff1);
    let param = &levin_params(0xaff2, 1)[0];
    let approx = Approximations::default();
    for chart in [
        SampleOptions::default(),
        SampleOptions {
            chart: [1, 0, -2, 1].map(RBig::from),
            ..SampleOptions::default()
        },
    ] {
        let chart = chart.chart().unwrap();
        let sampler = test_sampler(param, &chart, &approx);
        let mut cuts = 0;
        for _ in 0..400 {
            let len = rng.int(1, 40) as usize;
            let mut line = Line {
                chart: chart.form,
                ..Line::default()
            };
            let mut sign = 1.0;
            for k in 0..len {
                if rng.int(0, 9) == 0 {
                    sign = -sign;
                }
                let mut x = [0.0; 4].map(|_| rng.int(-1000, 1000) as f64 / 1000.0);
                x[3] = sign * (rng.int(1, 1000) as f64 / 1000.0);
                match rng.int(0, 40) {
                    0 => x = x.map(|_| 0.0),
                    1 => x[3] = -0.0,
                    2 => x[3] = sign * 1e-300,
                    _ => {}
                }
                let (inf, sing) = (rng.int(0, 15) == 0, rng.int(0, 15) == 0);
                line.push(&Sample {
                    theta: k as f64,
                    x,
                    at_infinity: inf,
                    singular: sing,
                });
            }
            let closed = rng.int(0, 1) == 0;
            let got = affine_view(sampler.chart, &line, closed);
            cuts += got.branches.len();
            assert_eq!(
                got,
                affine_view_two_pass(sampler.chart, &line, closed),
                "{:?}",
                line.x
            );
        }
        assert!(cuts > 800, "{cuts}");
    }
}

/// One-word integers around the double's 53 bits (the fast path of [`int_dd`]) and
/// beyond it split exactly: `hi + lo = v`.
#[test]
fn one_word_integers_split_exactly() {
    let two = |e: u32| 1u64 << e;
    for w in [
        0,
        1,
        2,
        two(52) - 1,
        two(53) - 1,
        two(53),
        two(53) + 1,
        two(63),
        u64::MAX,
    ] {
        for neg in [false, true] {
            let v = if neg { -IBig::from(w) } else { IBig::from(w) };
            let d = int_dd(&v);
            assert_eq!(integral_f64_to_ibig(d.0) + integral_f64_to_ibig(d.1), v);
            assert!(d.1.abs() <= d.0.abs() * f64::EPSILON, "{v}: {d:?}");
        }
    }
}

/// The walk's run in passes ([`run_of`]) takes the points, `h` and end point of the
/// reference point by point, on random runs: small steps, jumps, antipodal flips, NaN,
/// sign changes and zeros of `h`, crossings known or not, either orientation.
#[test]
fn run_in_passes_matches_point_by_point() {
    let mut rng = SplitMix(0x2a2a);
    let mut stops = [0usize; 3];
    for _ in 0..3000 {
        let len = rng.int(0, 30) as usize;
        let mut x = [1.0, 0.1, -0.2, 0.3];
        let mut xs = Vec::with_capacity(len);
        for _ in 0..len {
            let step = match rng.int(0, 60) {
                0 => 1.0,
                _ => 0.04,
            };
            for v in &mut x {
                *v += step * rng.int(-1000, 1000) as f64 / 1000.0;
            }
            let mut y = unit(x).unwrap_or([1.0, 0.0, 0.0, 0.0]);
            match rng.int(0, 80) {
                0 => y = y.map(|v| -v),
                1 => y[0] = f64::NAN,
                2 => y[3] = 0.0,
                _ => {}
            }
            xs.push(y);
        }
        let walk = Walk {
            prev: Sample::new(0.0, unit([1.0, 0.1, -0.2, 0.3]).unwrap()),
            h_prev: [0.3, -0.3, 0.0][rng.int(0, 2) as usize],
            stack: Vec::new(),
            unknown: rng.int(0, 3) > 0,
            flip: rng.int(0, 1) == 0,
        };
        let h = [rng.int(-3, 3) as f64, 0.0, rng.int(-3, 3) as f64, 1.0];
        let value = |x: &[f64; 4]| dot(&h, x);
        let (mut got_h, mut want_h) = (vec![7.0], vec![7.0]);
        let got = run_of(&xs, &walk, &mut got_h, value);
        let want = run_of_reference(&xs, &walk, &mut want_h, value);
        assert_eq!(got.0, want.0, "{xs:?}");
        assert_eq!(got.1.map(f64::to_bits), want.1.map(f64::to_bits));
        assert_eq!(got.2.to_bits(), want.2.to_bits());
        assert_eq!(
            got_h.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
            want_h.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
        );
        stops[match () {
            _ if got.0 == len => 0,
            _ if dot(&got.1, &xs[got.0]) >= MAX_ANGLE.cos() => 1,
            _ => 2,
        }] += 1;
    }
    // runs taken whole, stopped by `h`, stopped by an angle
    assert!(stops.iter().all(|&c| c > 200), "{stops:?}");
}

/// [`inner_f64`] lies strictly on its side of the rational (checked exactly), on random
/// rationals of all sizes, and an interval narrower than its margin gives an empty
/// bracket, on which [`Evaluator::root_of_s`] declines (the caller falls back to the
/// exact approximation).
#[test]
fn inner_floats_stay_inside_their_interval() {
    let mut rng = SplitMix(0x1a2b);
    for bits in [1u32, 20, 52, 53, 60, 120, 300, 900] {
        for _ in 0..50 {
            let num = (IBig::from(rng.next_u64()) << bits as usize) >> 64;
            let den = (IBig::from(rng.next_u64() | 1) << (bits / 2) as usize) >> 64;
            let den = if den.is_zero() { IBig::ONE } else { den };
            let q = RBig::from_parts_signed(if rng.int(0, 1) == 0 { -num } else { num }, den);
            for up in [false, true] {
                let f = inner_f64(&q, up);
                if q.is_zero() {
                    assert_eq!(f, 0.0);
                    continue;
                }
                let exact = RBig::try_from(f).expect("finite");
                assert_eq!(exact > q, up, "{q} {f}");
                assert!(((f - q.to_f64().value()) / f).abs() < 1e-14);
            }
        }
    }
    // beyond the floats: NaN, no bracket
    let huge = RBig::from(IBig::ONE << 2000);
    assert!(inner_f64(&huge, true).is_nan());
    assert!(inner_f64(&(RBig::ONE / huge), false).is_nan());
    // an interval narrower than the margins: the bracket is empty and declined
    let param = &levin_params(0x1a2c, 1)[0];
    let eval = Evaluator::new(param).unwrap();
    let lo = RBig::from_parts_signed(
        IBig::from(1_000_000_000_000_001i64),
        IBig::from(1_000_000_000_000_000i64),
    );
    let hi = RBig::from_parts_signed(
        IBig::from(1_000_000_000_000_002i64),
        IBig::from(1_000_000_000_000_000i64),
    );
    let (l, h) = (inner_f64(&lo, true), inner_f64(&hi, false));
    assert!(l > h);
    assert_eq!(eval.root_of_s(l, h), None);
}

/// The unrolled evaluation on the coefficient set chosen by index
/// ([`Evaluator::horner`]) is the generic Horner evaluation of [`Evaluator::values_any`]
/// on both orders and sheets, value for value.
#[test]
fn indexed_coefficient_sets_match_generic_horner() {
    let mut rng = SplitMix(0x4e7);
    let mut checked = 0;
    for param in levin_params(0x4e8, 6) {
        let eval = Evaluator::new(&param).unwrap();
        for _ in 0..200 {
            let t = rng.int(-1_000_000, 1_000_000) as f64 / 1_000_000.0;
            for rev in [false, true] {
                for sheet in [Sheet::Plus, Sheet::Minus] {
                    let want = eval.values_any(t, rev, sheet);
                    let got = match eval.big_d {
                        2 => eval.values::<3, 1>(t, rev, sheet),
                        3 => eval.values::<4, 2>(t, rev, sheet),
                        4 => eval.values::<5, 3>(t, rev, sheet),
                        _ => continue,
                    };
                    assert_eq!(got, want, "t = {t}, rev = {rev}");
                    checked += 1;
                }
            }
        }
    }
    assert!(checked >= 4000, "{checked}");
}

/// A certified evaluation counts the rounding of `s` in `√s` ([`Evaluator::root_bound`]):
/// beside the near-node of Steinmetz's cylinders `10⁻⁵` and `10⁻¹⁰` apart, where `s` is a
/// small difference of huge terms, every point [`Evaluator::eval_unit`] returns lies on both
/// quadrics (the residual test of [`verify_on_quadrics`], independent of the bound).
#[test]
fn certified_points_beside_a_near_node_lie_on_both_quadrics() {
    let (mut certified, mut total) = (0, 0);
    for offset in ["1/100000", "1/10000000000"] {
        for k in ["1", "1/100000"] {
            let a = crate::io::parse_quadric(&format!("x^2+y^2-({k})^2")).unwrap();
            let b = crate::io::parse_quadric(&format!("(x-{offset}*{k})^2+z^2-({k})^2")).unwrap();
            let curve = crate::param::parameterize(&a, &b).unwrap();
            let param = curve.components[0].param.as_ref().unwrap();
            let scaled = in_float_range(param);
            let eval = Evaluator::new(scaled.as_ref().unwrap_or(param)).unwrap();
            let mut points = Vec::new();
            // about the arc ends (roots of `s`) near u = −1, and u = −1 itself
            let mut centres = vec![-1.0];
            if let RealPiece::Curve { arcs, .. } = &curve.pieces[0] {
                for arc in arcs {
                    if let ParamRange::Between(ParamValue::Finite(r), _) = &arc.range {
                        centres.push(r.to_f64());
                    }
                }
            }
            for (c, e, j) in centres.iter().flat_map(|c| {
                (4..17).flat_map(move |e| [-3.0, -1.0, 1.0, 2.0, 5.0].map(|j| (*c, e, j)))
            }) {
                {
                    let u = c + j * 10f64.powi(-e) * c.abs().max(1e-300);
                    for sheet in [Sheet::Plus, Sheet::Minus] {
                        total += 1;
                        if let Some(x) = eval.eval_unit((u, 1.0), sheet) {
                            points.push(x);
                        }
                    }
                }
            }
            certified += points.len();
            let piece = SampledPiece {
                component: 0,
                isolated: false,
                points,
                closed: false,
                breaks: Vec::new(),
                infinity: Vec::new(),
                affine: AffinePiece {
                    branches: Vec::new(),
                    bounded: true,
                    points_at_infinity: Vec::new(),
                    at_infinity: false,
                    indices: Vec::new(),
                },
            };
            let sampled = Sampled {
                pieces: vec![piece],
            };
            verify_on_quadrics(&sampled, &a, &b)
                .unwrap_or_else(|e| panic!("offset {offset}, k = {k}: {e}"));
        }
    }
    assert!(certified > total / 4, "{certified} of {total}");
}
