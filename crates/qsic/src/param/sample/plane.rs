//! Where a parameterized curve meets a plane `ℓ·X = 0` or passes through a point, exactly:
//! the stage that the sampler's marks and the affine view both read (neither lives inside
//! the other).
//!
//! * The rational `X(u)` of degree `k` passes through a point `P` at the real roots of the
//!   gcd of the minors `xᵢ(u)Pⱼ − xⱼ(u)Pᵢ`, and at `u = ∞` when its leading coefficients
//!   are proportional to `P` ([`params_of_point`]).
//! * Levin's `a ± d√s` meets the plane at the real roots `t` of `r = (ℓ·a)² − s·(ℓ·d)²` with
//!   `s(t) ≥ 0`, on the sheet `σ` with `sign (ℓ·a)(t) = −σ·sign (ℓ·d)(t)` (both sheets where
//!   `s(t) = 0`), and at `u = ∞` by the same test in the chart `v = 1/u`. Where the form
//!   vanishes on a sheet (a root of the gcd of the `aᵢ² − s·dᵢ²`), its alternate form gives
//!   the point ([`levin_plane_crossings`]). Roots over ℚ(α) come by the norm, signs at
//!   algebraic parameters are exact ([`Poly::sign_at`]): no float decides.

use crate::error::Error;
use crate::param::curve::{LevinForm, Number, NumberPoly, ParamValue, Point, PointPoly, Sheet};
use qsic_algebra::field::NumberFieldElement;
use qsic_algebra::{AlgebraicReal, Poly, RBig, Ring, Sign};

/// The degree of `p`, 0 for the zero polynomial.
fn degree(p: &NumberPoly) -> usize {
    p.degree().unwrap_or(0)
}

/// `v` as an element of ℚ.
fn rational(v: &RBig) -> Number {
    NumberFieldElement::rational(v.clone())
}

/// `ℓ·X(u)`.
pub(crate) fn plane_form(l: &[RBig; 4], x: &PointPoly) -> NumberPoly {
    let mut acc = NumberPoly::zero();
    for i in 0..4 {
        if l[i] != RBig::ZERO {
            acc = &acc + &x[i].scale(&rational(&l[i]));
        }
    }
    acc
}

/// `ℓ·P`.
pub(crate) fn chart_value(l: &[RBig; 4], p: &Point) -> Number {
    let mut acc = Number::zero();
    for i in 0..4 {
        if l[i] != RBig::ZERO {
            acc = acc.add(&p[i].mul(&rational(&l[i])));
        }
    }
    acc
}

/// `v^k p(1/v)`: the polynomial in the chart at `u = ∞` (`v = 1/u`) of a form of degree `k`.
fn at_infinity_chart(p: &NumberPoly, k: usize) -> NumberPoly {
    let mut c: Vec<Number> = (0..=k).map(|i| p.coeff(i)).collect();
    c.reverse();
    Poly::new(c)
}

/// Whether the elements can be combined (one rational, or one field).
pub(crate) fn compatible(items: &[&Number]) -> bool {
    items
        .iter()
        .all(|a| items.iter().all(|b| a.compatible_with(b)))
}

pub(crate) fn same_value(a: &ParamValue, b: &ParamValue) -> bool {
    match (a, b) {
        (ParamValue::Finite(x), ParamValue::Finite(y)) => x == y,
        (ParamValue::Infinity, ParamValue::Infinity) => true,
        _ => false,
    }
}

/// The parameter values at which the rational `X(u)` (degree `k`) passes through `p`.
pub(crate) fn params_of_point(
    x: &PointPoly,
    k: usize,
    p: &Point,
) -> Result<Vec<ParamValue>, Error> {
    let mut items: Vec<&Number> = p.iter().collect();
    let coeffs: Vec<Number> = x.iter().flat_map(|c| c.coeffs().to_vec()).collect();
    items.extend(coeffs.iter());
    if !compatible(&items) {
        return Err(Error::Unsupported(
            "affine view: a singular point and a component in different number fields".into(),
        ));
    }
    let mut g = NumberPoly::zero();
    for i in 0..4 {
        for j in i + 1..4 {
            let m = &x[i].scale(&p[j]) - &x[j].scale(&p[i]);
            if !m.is_zero() {
                g = if g.is_zero() { m } else { g.gcd_monic(&m) };
            }
        }
    }
    if g.is_zero() {
        return Err(Error::Algebra(
            "a rational component is a single point".into(),
        ));
    }
    let mut out: Vec<ParamValue> = g.real_roots().into_iter().map(ParamValue::Finite).collect();
    let lead: Vec<Number> = x.iter().map(|c| c.coeff(k)).collect();
    let proportional = (0..4).all(|i| (i + 1..4).all(|j| lead[i].mul(&p[j]) == lead[j].mul(&p[i])));
    if proportional && lead.iter().any(|c| !c.is_zero()) {
        out.push(ParamValue::Infinity);
    }
    Ok(out)
}

/// The parameters where Levin's form `a ± d√s` (with its `alternate` where it vanishes)
/// meets the plane `l·X = 0`, exactly, over any number field: each with its sheet, `None`
/// where `s = 0` (both sheets are one point). In parameter order of the candidates (the real
/// roots of `(l·a)² − s(l·d)²`, then `u = ∞`); a parameter with both sheets comes twice, once
/// per sheet, one after the other.
///
/// # Errors
/// [`Error::Unsupported`] where both forms vanish at one parameter.
pub(crate) fn levin_plane_crossings(
    l: &[RBig; 4],
    primary: &LevinForm,
    s: &NumberPoly,
    alternate: Option<&LevinForm>,
) -> Result<Vec<(ParamValue, Option<Sheet>)>, Error> {
    let forms: Vec<&LevinForm> = std::iter::once(primary).chain(alternate).collect();
    let (wa, wd) = (plane_form(l, &primary.a), plane_form(l, &primary.d));
    let r = &(&wa * &wa) - &(s * &(&wd * &wd));
    // the base points of the primary form: a sheet vanishes at `t` only where every
    // `aᵢ² − s·dᵢ²` does, a root of their gcd `g` (none when `g` is constant)
    let mut g = NumberPoly::zero();
    for i in 0..4 {
        let n = &(&primary.a[i] * &primary.a[i]) - &(s * &(&primary.d[i] * &primary.d[i]));
        if !n.is_zero() {
            g = if g.is_zero() { n } else { g.gcd_monic(&n) };
        }
    }
    let base = (degree(&g) > 0).then_some(g);
    // every parameter where a sheet meets the plane at infinity, or the primary form
    // vanishes, is a root of r (finite, or v = 0 in the chart v = 1/u); r's factor in
    // common with g (in the chart w = 0, g divides r) and the cofactor prime to it are
    // isolated apart: lower degrees, the same roots
    let mut candidates: Vec<ParamValue> = split_roots(&r, base.as_ref())
        .into_iter()
        .map(ParamValue::Finite)
        .collect();
    candidates.push(ParamValue::Infinity);
    let mut events = Vec::new();
    for at in candidates {
        if let ParamValue::Finite(t) = &at {
            // r(t) = 0 is known: signs decide (`finite_candidate`)
            let sheets = finite_candidate(primary, s, (&wa, &wd), base.as_ref(), t);
            for (sheet, on_primary) in sheets {
                let at_infinity = match on_primary {
                    Some(at_infinity) => at_infinity,
                    // the primary vanishes on this sheet: the alternate form's point
                    None => {
                        let sigma = if sheet == Some(Sheet::Minus) {
                            Sign::Negative
                        } else {
                            Sign::Positive
                        };
                        let mut found = None;
                        if let Some(alt) = alternate {
                            let vanishes =
                                (0..4).all(|i| sheet_value_zero(&alt.a[i], &alt.d[i], s, t, sigma));
                            if !vanishes {
                                let (wa, wd) = (plane_form(l, &alt.a), plane_form(l, &alt.d));
                                found = Some(sheet_value_zero(&wa, &wd, s, t, sigma));
                            }
                        }
                        found.ok_or_else(|| {
                            Error::Unsupported(
                                "affine view: both Levin forms vanish at one parameter".into(),
                            )
                        })?
                    }
                };
                if at_infinity {
                    events.push((at.clone(), sheet));
                }
            }
            continue;
        }
        // the forms and s in the chart of `at`, and the parameter there
        let (t, s_here, here): (AlgebraicReal, NumberPoly, Vec<(PointPoly, PointPoly)>) = match &at
        {
            ParamValue::Finite(t) => (
                t.clone(),
                s.clone(),
                forms.iter().map(|f| (f.a.clone(), f.d.clone())).collect(),
            ),
            ParamValue::Infinity => (
                AlgebraicReal::from_rational(RBig::ZERO),
                at_infinity_chart(s, 4),
                forms
                    .iter()
                    .map(|f| {
                        (
                            std::array::from_fn(|i| at_infinity_chart(&f.a[i], f.degree)),
                            std::array::from_fn(|i| {
                                at_infinity_chart(&f.d[i], f.degree.saturating_sub(2))
                            }),
                        )
                    })
                    .collect(),
            ),
        };
        let sheets: Vec<Option<Sheet>> = match s_here.sign_at(&t) {
            Sign::Negative => continue,
            Sign::Zero => vec![None],
            Sign::Positive => vec![Some(Sheet::Plus), Some(Sheet::Minus)],
        };
        for sheet in sheets {
            let sigma = if sheet == Some(Sheet::Minus) {
                Sign::Negative
            } else {
                Sign::Positive
            };
            let mut at_infinity = None;
            for (fa, fd) in &here {
                let vanishes = (0..4).all(|i| sheet_value_zero(&fa[i], &fd[i], &s_here, &t, sigma));
                if !vanishes {
                    let (wa, wd) = (plane_form(l, fa), plane_form(l, fd));
                    at_infinity = Some(sheet_value_zero(&wa, &wd, &s_here, &t, sigma));
                    break;
                }
            }
            match at_infinity {
                None => {
                    return Err(Error::Unsupported(
                        "affine view: both Levin forms vanish at one parameter".into(),
                    ))
                }
                Some(true) => events.push((at.clone(), sheet)),
                Some(false) => {}
            }
        }
    }
    Ok(events)
}

/// The real roots of `r`: those of `h = gcd(r, g)` and those of `r` divided by `h` until
/// prime to it (disjoint sets).
fn split_roots(r: &NumberPoly, g: Option<&NumberPoly>) -> Vec<AlgebraicReal> {
    let h = match g {
        Some(g) if !r.is_zero() => r.gcd_monic(g),
        _ => return r.real_roots(),
    };
    if degree(&h) == 0 {
        return r.real_roots();
    }
    let mut rest = r.clone();
    loop {
        let c = rest.gcd_monic(&h);
        if degree(&c) == 0 {
            break;
        }
        rest = rest.div_rem(&c).0;
    }
    let mut roots = h.real_roots();
    roots.extend(rest.real_roots());
    roots
}

/// At a real root `t` of `r = wa² − s·wd²` (`wa`, `wd` the chart form of the primary
/// Levin form `a ± d√s`): the sheets there (`None` where `s(t) = 0`; nothing where
/// `s(t) < 0`), each with whether the primary form's point is at infinity (`None`: the
/// primary form vanishes on that sheet). Signs decide, with no zero test of a value known
/// to vanish:
/// * `wa(t)² = s(t)·wd(t)²`: where `s(t)·wd(t) = 0` also `wa(t) = 0` (at infinity on every
///   sheet); else `wa(t) ≠ 0` and `wa ± wd√s` vanishes on the sheet `σ` with
///   `sign wa(t) = −σ·sign wd(t)` only;
/// * off the roots of `base` (the gcd of the `aᵢ² − s·dᵢ²`) no sheet vanishes; at one, every
///   `aᵢ(t)² = s(t)·dᵢ(t)²`, so the sheet `σ` vanishes iff `sign aᵢ(t) = −σ·sign dᵢ(t)` for
///   every `i` (where `s(t) = 0`: every `aᵢ(t) = 0`, it vanishes).
fn finite_candidate(
    primary: &LevinForm,
    s: &NumberPoly,
    (wa, wd): (&NumberPoly, &NumberPoly),
    base: Option<&NumberPoly>,
    t: &AlgebraicReal,
) -> Vec<(Option<Sheet>, Option<bool>)> {
    let s_sign = s.sign_at(t);
    let sheets: Vec<Option<Sheet>> = match s_sign {
        Sign::Negative => return Vec::new(),
        Sign::Zero => vec![None],
        Sign::Positive => vec![Some(Sheet::Plus), Some(Sheet::Minus)],
    };
    let at_base = base.is_some_and(|g| g.sign_at(t) == Sign::Zero);
    let signs: Vec<(Sign, Sign)> = if at_base && s_sign == Sign::Positive {
        (0..4)
            .map(|i| (primary.a[i].sign_at(t), primary.d[i].sign_at(t)))
            .collect()
    } else {
        Vec::new()
    };
    // the chart form's signs, once: (sign wd(t), sign wa(t)) unless s(t)·wd(t) = 0
    let mut chart: Option<Option<(Sign, Sign)>> = None;
    sheets
        .into_iter()
        .map(|sheet| {
            let sigma = if sheet == Some(Sheet::Minus) {
                Sign::Negative
            } else {
                Sign::Positive
            };
            let opposite = |x: Sign| if sigma == Sign::Positive { -x } else { x };
            let vanishes = at_base
                && (s_sign == Sign::Zero || signs.iter().all(|&(sa, sd)| sa == opposite(sd)));
            if vanishes {
                return (sheet, None);
            }
            let signs = *chart.get_or_insert_with(|| {
                if s_sign == Sign::Zero {
                    return None;
                }
                let sd = wd.sign_at(t);
                (sd != Sign::Zero).then(|| (sd, wa.sign_at(t)))
            });
            let at_infinity = match signs {
                None => true,
                Some((sd, sa)) => sa == opposite(sd),
            };
            (sheet, Some(at_infinity))
        })
        .collect()
}

/// Whether `p(t) + σ·q(t)·√s(t) = 0` (`s(t) ≥ 0`), exactly: with `s(t)q(t) ≠ 0` it needs
/// `p(t)² = q(t)²s(t)` and `sign p(t) = −σ·sign q(t)`.
fn sheet_value_zero(
    p: &NumberPoly,
    q: &NumberPoly,
    s: &NumberPoly,
    t: &AlgebraicReal,
    sigma: Sign,
) -> bool {
    let sp = p.sign_at(t);
    if s.sign_at(t) == Sign::Zero || q.sign_at(t) == Sign::Zero {
        return sp == Sign::Zero;
    }
    if sp == Sign::Zero {
        return false;
    }
    let sq = q.sign_at(t);
    let opposite = if sigma == Sign::Positive { -sq } else { sq };
    sp == opposite && (&(p * p) - &(s * &(q * q))).sign_at(t) == Sign::Zero
}
