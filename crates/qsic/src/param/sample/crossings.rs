//! The exact crossings of a component with the chart's plane at infinity `h(X) = 0`, marked
//! on the polyline (a point is at infinity iff it is marked, whatever its float `h`).
//!
//! For a rational `X(u)` they are the real roots of `h(X(u))` (over a number field by the
//! norm: [`crate::param::infinity`]); for Levin's form `a ± d√s` with rational coefficients the
//! real roots of `h(a)² − h(d)²s` with `s ≥ 0`, the sheet from the signs of `h(a)`, `h(d)`
//! ([`crossing_sheets`]); with irrational coefficients those of
//! [`super::plane::levin_plane_crossings`]. Tangential touches are included. Where no exact
//! route places a crossing (both Levin forms vanish at one parameter) sampling is an error.

use crate::error::Error;
use crate::param::curve::{ComponentParam, Number, NumberPoly, ParamRange, ParamValue, Sheet};
use crate::param::sample::kernels::dd::int_dd;
use crate::param::sample::plane::same_value;
use qsic_algebra::{AlgebraicReal, IBig, Poly, RBig, Sign};

/// A float on the side of `q` given by `up` (`> q` for `up`, `< q` otherwise; `q` itself
/// when it is zero), from the quotient of the floats of its numerator and denominator (each
/// within one ulp: the leading part of [`int_dd`], a one-word denominator rounded to nearest;
/// the quotient rounded to nearest: within `2.5` ulps) moved by `8ε·|v|` (at least four ulps); NaN where a float is not finite or
/// below the normal range (no such float is known cheaply). Cheaper than the correctly
/// rounded [`RBig::to_f64`].
pub(super) fn inner_f64(q: &RBig, up: bool) -> f64 {
    let d = match q.denominator().as_words() {
        [w] => *w as f64,
        _ => q.denominator().to_f64().value(),
    };
    let n = int_dd(q.numerator()).0;
    if n == 0.0 && q.numerator().is_zero() {
        return 0.0;
    }
    let v = n / d;
    if !(v.is_finite() && v.abs() >= f64::MIN_POSITIVE * 1e10) {
        return f64::NAN;
    }
    let m = v.abs() * (8.0 * f64::EPSILON);
    if up {
        v + m
    } else {
        v - m
    }
}

/// The exact coefficients of a component whose coefficients are all rational.
pub(super) enum ExactParam {
    Rational {
        x: [Poly<RBig>; 4],
        degree: usize,
    },
    Levin {
        a: [Poly<RBig>; 4],
        d: [Poly<RBig>; 4],
        s: Poly<RBig>,
        degree: usize,
    },
    /// Some coefficient is irrational: crossings from sign changes.
    Irrational,
}

pub(super) fn rational_poly(p: &NumberPoly) -> Option<Poly<RBig>> {
    let c = p
        .coeffs()
        .iter()
        .map(|c| match c.numerator() {
            [] => Some(RBig::ZERO),
            [v] => Some(RBig::from(v.clone()) / RBig::from(c.denominator().clone())),
            _ => None,
        })
        .collect::<Option<Vec<_>>>()?;
    Some(Poly::new(c))
}

/// `true` if every coefficient of `p` is rational (a numerator of degree 0 at most): the
/// check before [`rational_poly`], which allocates.
pub(super) fn is_rational(p: &NumberPoly) -> bool {
    p.coeffs().iter().all(|c| c.numerator().len() <= 1)
}

pub(super) fn rational_vector(v: &[NumberPoly; 4]) -> Option<[Poly<RBig>; 4]> {
    if !v.iter().all(is_rational) {
        return None;
    }
    let mut out: [Poly<RBig>; 4] = Default::default();
    for i in 0..4 {
        out[i] = rational_poly(&v[i])?;
    }
    Some(out)
}

impl ExactParam {
    pub(super) fn new(param: &ComponentParam) -> ExactParam {
        let deg = |p: &NumberPoly| p.degree().unwrap_or(0);
        let found = match param {
            ComponentParam::Point(_) => None,
            ComponentParam::Rational { x, .. } => rational_vector(x).map(|x| {
                // without the common factor of the coordinates (removable zeros of X)
                let g = x.iter().fold(Poly::zero(), |g, p| g.gcd_monic(p));
                let x = if g.degree().unwrap_or(0) > 0 {
                    x.map(|p| p.div_rem(&g).0)
                } else {
                    x
                };
                let degree = x.iter().map(|p| p.degree().unwrap_or(0)).max().unwrap_or(0);
                ExactParam::Rational { x, degree }
            }),
            ComponentParam::Levin {
                a, d, s, degree, ..
            } => {
                let degree = a
                    .iter()
                    .map(deg)
                    .max()
                    .unwrap_or(0)
                    .max(d.iter().map(deg).max().unwrap_or(0) + 2)
                    .max(*degree);
                // the conversions only where all is rational (not for ℚ(√δ), the usual case)
                if a.iter().chain(d).all(is_rational) && is_rational(s) {
                    match (rational_vector(a), rational_vector(d), rational_poly(s)) {
                        (Some(a), Some(d), Some(s)) => Some(ExactParam::Levin { a, d, s, degree }),
                        _ => None,
                    }
                } else {
                    None
                }
            }
        };
        found.unwrap_or(ExactParam::Irrational)
    }
}

/// `Σ hᵢ vᵢ(u)`.
pub(super) fn chart_form(h: &[RBig; 4], v: &[Poly<RBig>; 4]) -> Poly<RBig> {
    (0..4).fold(Poly::zero(), |acc, i| &acc + &v[i].scale(&h[i]))
}

/// A crossing of the plane at infinity: where on ℙ¹ and on which sheets.
pub(super) struct Crossing {
    pub(super) value: ParamValue,
    /// Sheets whose point is at infinity (`Only` for a rational param).
    pub(super) sheets: Vec<Sheet>,
}

/// Whether the exact `value` lies in `range` (ends included).
pub(super) fn in_range(value: &ParamValue, range: &ParamRange) -> bool {
    let ParamRange::Between(lo, hi) = range else {
        return true;
    };
    match (value, lo, hi) {
        (ParamValue::Infinity, ParamValue::Finite(l), ParamValue::Finite(h)) => h <= l,
        (ParamValue::Infinity, _, _) => true,
        (ParamValue::Finite(_), ParamValue::Infinity, ParamValue::Infinity) => true,
        (ParamValue::Finite(r), ParamValue::Infinity, ParamValue::Finite(h)) => r <= h,
        (ParamValue::Finite(r), ParamValue::Finite(l), ParamValue::Infinity) => r >= l,
        (ParamValue::Finite(r), ParamValue::Finite(l), ParamValue::Finite(h)) => {
            if l < h {
                l <= r && r <= h
            } else {
                r >= l || r <= h
            }
        }
    }
}

/// What is known exactly of a component's crossings with the plane at infinity.
pub(super) enum Crossings {
    /// Every crossing, exactly.
    Exact(Vec<Crossing>),
    /// The component lies in the plane.
    InPlane,
    /// Irrational coefficients: crossings from sign changes along the polyline.
    Unknown,
}

/// Whether a rational parameterization lies in the plane `h = 0` (`h·X(u) ≡ 0`, exactly, in
/// any number field).
pub(super) fn lies_in_plane(param: &ComponentParam, h: &[RBig; 4]) -> bool {
    let ComponentParam::Rational { x, .. } = param else {
        return false;
    };
    (0..4)
        .fold(Poly::<Number>::zero(), |acc, i| {
            &acc + &x[i].scale(&Number::rational(h[i].clone()))
        })
        .is_zero()
}

/// The exact crossings of the component with the plane `h = 0`: over a number field those of
/// a rational parameterization ([`super::infinity`]), none known of Levin's form.
///
/// # Errors
/// Where the exact route cannot place a crossing on Levin's form (both forms vanish at one
/// parameter): an error, not a float guess.
pub(super) fn exact_crossings(
    param: &ComponentParam,
    exact: &ExactParam,
    h: &[RBig; 4],
) -> Result<Crossings, Error> {
    let found = match (exact, param) {
        (ExactParam::Irrational, ComponentParam::Rational { x, .. }) => {
            crate::param::infinity::plane_crossings(x, h).map(|values| {
                let only = |value| Crossing {
                    value,
                    sheets: vec![Sheet::Only],
                };
                values.into_iter().map(only).collect()
            })
        }
        (
            ExactParam::Irrational,
            ComponentParam::Levin {
                a,
                d,
                s,
                degree,
                alternate,
            },
        ) => {
            let primary = crate::param::LevinForm {
                a: a.clone(),
                d: d.clone(),
                degree: *degree,
            };
            let events = super::plane::levin_plane_crossings(h, &primary, s, alternate.as_deref())?;
            Some(levin_crossings(events))
        }
        (ExactParam::Irrational, _) => return Ok(Crossings::Unknown),
        _ => exact_crossings_of(exact, h),
    };
    Ok(match found {
        None => Crossings::InPlane,
        Some(c) => Crossings::Exact(c),
    })
}

/// The crossings of [`super::plane::levin_plane_crossings`]: the sheets at one parameter
/// together, both where `s = 0`.
pub(super) fn levin_crossings(events: Vec<(ParamValue, Option<Sheet>)>) -> Vec<Crossing> {
    let mut out: Vec<Crossing> = Vec::new();
    for (value, sheet) in events {
        let sheets = match sheet {
            Some(sheet) => vec![sheet],
            None => vec![Sheet::Plus, Sheet::Minus],
        };
        match out.last_mut() {
            Some(last) if same_value(&last.value, &value) => last.sheets.extend(sheets),
            _ => out.push(Crossing { value, sheets }),
        }
    }
    out
}

pub(super) fn exact_crossings_of(exact: &ExactParam, h: &[RBig; 4]) -> Option<Vec<Crossing>> {
    let roots = |p: &Poly<RBig>| -> Vec<AlgebraicReal> {
        AlgebraicReal::real_roots_of(&Poly::from_rational(p).0.squarefree_part())
    };
    match exact {
        ExactParam::Irrational => None,
        ExactParam::Rational { x, degree } => {
            let g = chart_form(h, x);
            if g.is_zero() {
                return None;
            }
            let mut out: Vec<Crossing> = roots(&g)
                .into_iter()
                .map(|r| Crossing {
                    value: ParamValue::Finite(r),
                    sheets: vec![Sheet::Only],
                })
                .collect();
            if g.degree().unwrap_or(0) < *degree {
                out.push(Crossing {
                    value: ParamValue::Infinity,
                    sheets: vec![Sheet::Only],
                });
            }
            Some(out)
        }
        ExactParam::Levin { a, d, s, degree } => {
            // over ℤ: a = A/α, d = D/β, s = S/γ, h = H/η with positive integers α, β, γ, η;
            // h(a)² − h(d)²·s times η²α²β²γ is N = H(A)²·β²γ − H(D)²·S·α², and
            // a_i² − d_i²·s times α²β²γ is A_i²·β²γ − D_i²·S·α² (signs and zeros kept)
            let (av, alpha) = integer_vector(a);
            let (dv, beta) = integer_vector(d);
            let (sv, gamma) = integer_vector(std::slice::from_ref(s));
            let (hv, _) = integer_row(h);
            let sz = &sv[0];
            let form = |v: &[Poly]| -> Poly {
                (0..4).fold(Poly::zero(), |acc, i| &acc + &v[i].scale(&hv[i]))
            };
            let (ha, hd) = (form(&av), form(&dv));
            let (k1, k2) = (&beta * &beta * &gamma, &alpha * &alpha);
            let norm =
                |x: &Poly, y: &Poly| -> Poly { &(x * x).scale(&k1) - &(&(y * y) * sz).scale(&k2) };
            let n = norm(&ha, &hd);
            if n.is_zero() {
                // a quartic is not planar: h(a) = ±h(d)√s identically cannot hold
                return Some(Vec::new());
            }
            let sheets = crossing_sheets;
            // a_i² − d_i²·s: X_σ is the zero vector where every one vanishes and the signs
            // of a_i and d_i match σ (a removable zero of Levin's form, where c₂ = 0: not a
            // point of the plane, whatever h is)
            let norms: Vec<Poly> = (0..4).map(|i| norm(&av[i], &dv[i])).collect();
            let vanishes = |sheet: Sheet,
                            sign_a: &dyn Fn(usize) -> Sign,
                            sign_d: &dyn Fn(usize) -> Sign,
                            norm_zero: &dyn Fn(usize) -> bool| {
                (0..4).all(|i| {
                    let (sa, sd) = (sign_a(i), sign_d(i));
                    norm_zero(i)
                        && match sheet {
                            Sheet::Plus => sa == -sd,
                            _ => sa == sd,
                        }
                })
            };
            let mut out: Vec<Crossing> = Vec::new();
            let (rs, removable) = crossing_roots(&n, &norms);
            // the signs at every root at once (one gcd per polynomial, not per root)
            let signs = |p: &Poly| -> Vec<Sign> {
                if p.is_zero() {
                    vec![Sign::Zero; rs.len()]
                } else {
                    AlgebraicReal::signs_at(&rs, p)
                }
            };
            let (sa, sd, ss) = (signs(&ha), signs(&hd), signs(sz));
            for (k, r) in rs.into_iter().enumerate() {
                let mut sh = sheets(sa[k], sd[k], ss[k]);
                if removable[k] {
                    let on_s = ss[k] == Sign::Zero;
                    sh.retain(|&sheet| {
                        !vanishes(
                            sheet,
                            &|i| r.sign_of(&av[i]),
                            &|i| if on_s { Sign::Zero } else { r.sign_of(&dv[i]) },
                            &|_| true,
                        )
                    });
                }
                out.push(Crossing {
                    value: ParamValue::Finite(r),
                    sheets: sh,
                });
            }
            if n.degree().unwrap_or(0) < 2 * degree {
                let top = |p: &Poly, k: usize| Sign::of(&p.coeff(k));
                let mut sh = sheets(top(&ha, *degree), top(&hd, degree - 2), top(sz, 4));
                sh.retain(|&sheet| {
                    !vanishes(
                        sheet,
                        &|i| top(&av[i], *degree),
                        &|i| {
                            if top(sz, 4) == Sign::Zero {
                                Sign::Zero
                            } else {
                                top(&dv[i], degree - 2)
                            }
                        },
                        &|i| top(&norms[i], 2 * degree) == Sign::Zero,
                    )
                });
                out.push(Crossing {
                    value: ParamValue::Infinity,
                    sheets: sh,
                });
            }
            Some(out)
        }
    }
}

/// The sheets of Levin's form through a root of `h(a)² − h(d)²·s` with the signs `sa`, `sd`,
/// `ss` of `h(a)`, `h(d)`, `s` there: `h(a) + σ·h(d)·√s = 0` for `σ = −sign(h(a)·h(d))`; both
/// where `√s = 0` or `h(d) = 0`, none where `s < 0`.
pub(super) fn crossing_sheets(sa: Sign, sd: Sign, ss: Sign) -> Vec<Sheet> {
    match (ss, sd) {
        (Sign::Negative, _) => Vec::new(),
        (Sign::Zero, _) | (_, Sign::Zero) => vec![Sheet::Plus, Sheet::Minus],
        _ if sa == sd => vec![Sheet::Minus],
        _ => vec![Sheet::Plus],
    }
}

/// The real roots of `n` (the crossings' polynomial of [`exact_crossings_of`]), each with
/// whether it may be a removable zero (a root of every nonzero norm `aᵢ² − dᵢ²·s`).
///
/// First by floats: `n` square-free with its roots certified, and at each root some norm
/// whose sign the certified interval decides nonzero — the generic crossing, with no gcd and
/// no square-free factorization. Otherwise exactly: the roots of the gcd of `n`'s
/// square-free part with the norms (none, the common case) isolated apart from the rest.
pub(super) fn crossing_roots(n: &Poly, norms: &[Poly]) -> (Vec<AlgebraicReal>, Vec<bool>) {
    // a removable zero needs every norm to vanish: the roots of their gcd with n (none,
    // the common case), isolated apart from the rest of n (whose rational roots are
    // then rare: the removable zeros are the usual ones)
    let nz = n.squarefree_part();
    let common = norms.iter().try_fold(nz.clone(), |g, m| {
        let g = if m.is_zero() { g } else { g.gcd(m) };
        if g.is_constant() {
            None
        } else {
            Some(g)
        }
    });
    let isolate = |p: &Poly| {
        AlgebraicReal::certified_real_roots_of(p).unwrap_or_else(|| AlgebraicReal::real_roots_of(p))
    };
    let mut rs: Vec<(AlgebraicReal, bool)> = Vec::new();
    match &common {
        Some(g) => {
            let rest = nz.div_exact(g).expect("a divisor of n");
            rs.extend(isolate(&rest).into_iter().map(|r| (r, false)));
            rs.extend(isolate(g).into_iter().map(|r| (r, true)));
            rs.sort_by(|x, y| x.0.cmp(&y.0));
        }
        None => rs.extend(isolate(&nz).into_iter().map(|r| (r, false))),
    }
    rs.into_iter().unzip()
}

/// The integer polynomials `L·vᵢ` for the least common denominator `L > 0` of every
/// coefficient, with `L`.
pub(super) fn integer_vector(v: &[Poly<RBig>]) -> (Vec<Poly>, IBig) {
    let mut l = IBig::ONE;
    for c in v.iter().flat_map(|p| p.coeffs()) {
        let d = IBig::from(c.denominator().clone());
        if !d.is_one() {
            l = &l / qsic_algebra::int_gcd(&l, &d) * d;
        }
    }
    let ints = v
        .iter()
        .map(|p| p.map(|c| c.numerator() * &(&l / IBig::from(c.denominator().clone()))))
        .collect();
    (ints, l)
}

/// [`integer_vector`] of the row `h`.
pub(super) fn integer_row(h: &[RBig; 4]) -> ([IBig; 4], IBig) {
    let (v, l) = integer_vector(&h.clone().map(|c| Poly::new(vec![c])));
    (std::array::from_fn(|i| v[i].coeff(0)), l)
}
