//! Levin's parameterization of a nonsingular quartic when no tried member of inertia (2, 2)
//! has a rational point (`choose_surface` found no ruling over ℚ or ℚ(√δ)).
//!
//! A member `S` of inertia (2, 2) without a rational point (none found: `small_point` and the
//! sections of `surface::points_on`, each decided by Legendre's theorem) and without a point
//! over a field `ℚ(√e)` that also holds `√det S` gets its lines over a biquadratic field. A
//! hyperplane section gives a point `P` over `ℚ(√e)`; the two lines through `P` are the
//! isotropic directions `E± = (−s₁₂ ± √r)e₁ + s₁₁e₂` of the tangent plane,
//! `r = s₁₂² − s₁₁s₂₂ ∈ ℚ(√e)` (`r ≡ det S` modulo squares there). Everything is then computed
//! in `ℚ(γ) = ℚ(√e, √r)` with an explicit primitive element (the one `planar` uses for conics):
//! the hyperbolic basis and the ruling `b(u) = P − u·E₊`, `d(u) = f₂ + u·f₁` as in `surface`,
//! the forms `c₀, c₁, c₂`, `s = c₁² − c₀c₂`, and the real
//! roots of `s` (isolated through its norm to ℚ). Rare (5 of 40 000 random pairs with rational
//! entries of two or three digits) and not fast: no integral arithmetic here.

use super::curve::{self, Curve, LevinForm, Number, ParamValue, PointPoly};
use super::planar::Ext;
use super::smooth::{balancing_exponent_of, quartic_curve, reduced_levin, theorem_12};
use super::surface::{form, mat_vec, points_on, to_quadratic, Vec4};
use super::{integer_matrix, member};
use crate::classify::{analyze_pencil, Classification};
use crate::error::Error;
use crate::quadric::Quadric;
use qsic_algebra::field::Quadratic;
use qsic_algebra::{Field, Poly, RBig, Ring, Sign};

/// The curve of a nonsingular quartic through a ruling over a biquadratic field (module doc),
/// at the sample of the first arc of inertia (2, 2) of the pencil; `Ok(None)` when the pencil
/// has no such arc or its member has no real point on the tried sections.
///
/// # Errors
/// [`Error::Algebra`] when an identity the construction guarantees fails (the ruling off `S`,
/// a multiple root of `s`, a count of real pieces against Theorem 12).
pub(super) fn biquadratic_curve(
    classification: Classification,
    a: &Quadric,
    b: &Quadric,
) -> Result<Option<Curve>, Error> {
    let Some(analysis) = analyze_pencil(a, b) else {
        return Ok(None);
    };
    let Some(lambda) = analysis
        .arcs
        .iter()
        .find(|(_, i)| i.positive == 2 && i.negative == 2)
        .map(|(sample, _)| sample.clone())
    else {
        return Ok(None);
    };
    biquadratic_curve_at(classification, a, b, &lambda)
}

/// [`biquadratic_curve`] on the member `S = λA − B` (of inertia (2, 2)).
fn biquadratic_curve_at(
    classification: Classification,
    a: &Quadric,
    b: &Quadric,
    lambda: &RBig,
) -> Result<Option<Curve>, Error> {
    let (am, bm) = (integer_matrix(a), integer_matrix(b));
    let s = member(&am, &bm, Some(lambda));
    let Some((_, p)) = points_on(&s)?.into_iter().next() else {
        return Ok(None);
    };
    let Some((b_line, d_line)) = ruling(&s, &p)? else {
        return Ok(None);
    };
    // S = λA − B: A and S span the pencil
    levin_over_field(classification, &am, b_line, d_line).map(Some)
}

/// The ruling `(b, d)` of `S` through its point `p` over ℚ(√e, √r) (module doc); `None` when
/// the lines through `p` are already over ℚ(√e) (the caller's route handles that).
fn ruling(s: &[[RBig; 4]; 4], p: &Vec4) -> Result<Option<(PointPoly, PointPoly)>, Error> {
    let sm = to_quadratic(s);
    let r = mat_vec(&sm, p);
    let j = (0..4)
        .find(|&k| !r[k].is_zero())
        .ok_or_else(|| Error::Algebra("a point in the kernel of a nonsingular quadric".into()))?;
    // T_P = ker(rᵀ): Kₖ = rⱼeₖ − rₖeⱼ, k ≠ j; drop one Kₖ with pₖ ≠ 0 (P spans it with the rest)
    let k0 = (0..4)
        .find(|&k| k != j && !p[k].is_zero())
        .ok_or_else(|| Error::Algebra("tangent plane basis".into()))?;
    let tangent: Vec<Vec4> = (0..4)
        .filter(|&k| k != j && k != k0)
        .map(|k| {
            std::array::from_fn(|i| {
                if i == k {
                    r[j].clone()
                } else if i == j {
                    r[k].neg()
                } else {
                    Quadratic::zero()
                }
            })
        })
        .collect();
    let (e1, e2) = (&tangent[0], &tangent[1]);
    let (s11, s12, s22) = (form(&sm, e1, e1), form(&sm, e1, e2), form(&sm, e2, e2));
    if s11.is_zero() {
        return Ok(None);
    }
    let disc = s12.mul(&s12).sub(&s11.mul(&s22));
    if disc.sign() != Some(Sign::Positive) {
        return Err(Error::Algebra(
            "no real lines through a point of an inertia (2, 2) member".into(),
        ));
    }
    let e = p
        .iter()
        .find(|x| x.as_rational().is_none())
        .map(|x| x.radicand().clone());
    if super::surface::sqrt_in_field(&disc, e.as_ref()).is_some() {
        return Ok(None);
    }
    let ext = Ext::new(e.as_ref(), Some(&disc));
    let root = ext.root.clone().expect("a field with √r");
    let embed = |v: &Vec4| -> [Number; 4] { std::array::from_fn(|i| ext.embed(&v[i])) };
    let (pe, e1, e2) = (embed(p), embed(e1), embed(e2));
    let (s11, s12) = (ext.embed(&s11), ext.embed(&s12));
    let sn: [[Number; 4]; 4] =
        std::array::from_fn(|i| std::array::from_fn(|k| curve::rational(s[i][k].clone())));
    let f = |x: &[Number; 4], y: &[Number; 4]| -> Number {
        let mut acc = Number::zero();
        for i in 0..4 {
            for k in 0..4 {
                if !sn[i][k].is_zero() {
                    acc = acc.add(&x[i].mul(&sn[i][k]).mul(&y[k]));
                }
            }
        }
        acc
    };
    let comb = |a: &Number, x: &[Number; 4], b: &Number, y: &[Number; 4]| -> [Number; 4] {
        std::array::from_fn(|i| a.mul(&x[i]).add(&b.mul(&y[i])))
    };
    let plus = comb(&s12.neg().add(&root), &e1, &s11, &e2);
    let minus = comb(&s12.neg().sub(&root), &e1, &s11, &e2);
    // hyperbolic basis: e₁ = P, e₂ = E₊, f₂ = E₋/(E₊ᵀSE₋), f₁ from the unit vector e_j
    let one = Number::one();
    let c = f(&plus, &minus)
        .inv()
        .ok_or_else(|| Error::Algebra("the two lines through a point are not distinct".into()))?;
    let f2 = comb(&c, &minus, &Number::zero(), &minus);
    let unit: [Number; 4] =
        std::array::from_fn(|i| if i == j { one.clone() } else { Number::zero() });
    let g = comb(&one, &unit, &f(&unit, &f2).neg(), &plus);
    let g = comb(&one, &g, &f(&g, &plus).neg(), &f2);
    let pg = f(&pe, &g)
        .inv()
        .ok_or_else(|| Error::Algebra("the tangent plane contains e_j".into()))?;
    let g = comb(&pg, &g, &Number::zero(), &g);
    let half = curve::rational(RBig::from_parts_signed(1.into(), 2.into()));
    let f1 = comb(&one, &g, &f(&g, &g).mul(&half).neg(), &pe);
    let line = |x: &[Number; 4], y: &[Number; 4]| -> PointPoly {
        std::array::from_fn(|i| Poly::new(vec![x[i].clone(), y[i].clone()]))
    };
    let b = line(&pe, &plus.map(|v| v.neg()));
    let d = line(&f2, &f1);
    // the ruling lies on S: bᵀSb ≡ dᵀSd ≡ bᵀSd ≡ 0
    if !(curve::poly_form(s, &b, &b).is_zero()
        && curve::poly_form(s, &d, &d).is_zero()
        && curve::poly_form(s, &b, &d).is_zero())
    {
        return Err(Error::Algebra(
            "the biquadratic ruling does not lie on its surface".into(),
        ));
    }
    Ok(Some((b, d)))
}

/// Levin's form from the ruling `q(u, v) = b(u) + v·d(u)` of `S`, substituted into `Q`:
/// `p(u) = a(u) ± d(u)√s(u)`, its alternate form, the real roots of `s` and the pieces.
fn levin_over_field(
    classification: Classification,
    q: &[[RBig; 4]; 4],
    b: PointPoly,
    d: PointPoly,
) -> Result<Curve, Error> {
    let forms = |b: &PointPoly, d: &PointPoly| {
        let c2 = curve::poly_form(q, d, d);
        let c1 = curve::poly_form(q, b, d);
        let c0 = curve::poly_form(q, b, b);
        let s = &(&c1 * &c1) - &(&c0 * &c2);
        (c0, c1, c2, s)
    };
    let (_, _, _, s) = forms(&b, &d);
    if s.is_zero() {
        return Err(Error::Algebra("s(u) vanishes identically".into()));
    }
    // u ↦ 2ᵏu: the real roots of s near 1 in size for the floats of `sample`
    let k = balancing_exponent_of(
        &s.coeffs()
            .iter()
            .map(|c| {
                let v = c.to_f64().abs();
                if c.is_zero() {
                    f64::NEG_INFINITY
                } else if v.is_finite() && v > 0.0 {
                    v.log2()
                } else {
                    f64::NAN // out of the floats: no balancing
                }
            })
            .collect::<Vec<f64>>(),
    );
    let scale = |v: &PointPoly| -> PointPoly {
        std::array::from_fn(|i| {
            Poly::new(
                v[i].coeffs()
                    .iter()
                    .enumerate()
                    .map(|(n, c)| c.mul(&curve::rational(super::expr::power_of_two(k * n as i64))))
                    .collect(),
            )
        })
    };
    let (b, d) = (scale(&b), scale(&d));
    let (c0, c1, c2, s) = forms(&b, &d);
    let a: PointPoly = std::array::from_fn(|i| &(&c2 * &b[i]) - &(&c1 * &d[i]));
    let alt_a: PointPoly = std::array::from_fn(|i| &(&c1 * &b[i]) - &(&c0 * &d[i]));
    let alternate = LevinForm {
        a: alt_a,
        d: b,
        degree: 3,
    };
    let param = reduced_levin(a, d, s.clone(), 3, alternate);
    // the real roots of s on ℝ ∪ {∞}, all simple on a nonsingular quartic
    let roots = s.real_roots();
    let derivative = s.derivative();
    let at_infinity = s.degree().unwrap_or(0) < 4;
    if roots.iter().any(|r| derivative.sign_at(r) == Sign::Zero)
        || (at_infinity && s.degree().unwrap_or(0) < 3)
    {
        return Err(Error::Algebra("s(u) has a multiple root".into()));
    }
    let sign_at = |x: &RBig| s.eval(&curve::rational(x.clone())).sign();
    let samples: Vec<RBig> = match (roots.first(), roots.last()) {
        (Some(first), Some(last)) => {
            let mut v = vec![RBig::from(first.interval().lo().floor()) - RBig::ONE];
            v.extend(roots.windows(2).map(|w| w[0].rational_between(&w[1])));
            v.push(RBig::from(last.interval().hi().ceil()) + RBig::ONE);
            v
        }
        _ => vec![RBig::ZERO],
    };
    let signs: Vec<Sign> = samples.iter().map(sign_at).collect();
    let mut ends: Vec<ParamValue> = roots.iter().cloned().map(ParamValue::Finite).collect();
    let mut after: Vec<Sign> = signs.iter().skip(1).copied().collect();
    if at_infinity {
        ends.push(ParamValue::Infinity);
        after.push(signs[0]);
    }
    let n = theorem_12(ends.len(), signs[0]).ok_or_else(|| {
        Error::Algebra(format!(
            "{} real roots of s(u) on a nonsingular quartic",
            ends.len()
        ))
    })?;
    quartic_curve(classification, param, (ends, &after, signs[0]), n)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::quadric_from_array;
    use crate::param::ComponentParam;

    /// A pencil (case 3, from a random scan) with members of inertia (2, 2) without a
    /// rational point: on the first tried one the ruling is over a biquadratic field, the
    /// curve lies on both quadrics, and its one real piece is the class's one closed
    /// component.
    #[test]
    fn a_pencil_without_rational_points_gets_a_biquadratic_ruling() {
        let a = quadric_from_array(&[
            ["6/8", "-55/7", "72/5", "-60/12"],
            ["-55/7", "-63/2", "-84/8", "27/9"],
            ["72/5", "-84/8", "-79/8", "-61/3"],
            ["-60/12", "27/9", "-61/3", "53/12"],
        ])
        .unwrap();
        let b = quadric_from_array(&[
            ["-49/10", "-93/5", "-35/5", "-13/5"],
            ["-93/5", "-16/5", "31/2", "-40/8"],
            ["-35/5", "31/2", "-74/4", "26"],
            ["-13/5", "-40/8", "26", "-41"],
        ])
        .unwrap();
        let classification = crate::classify::classify(&a, &b);
        assert_eq!(classification.case, Some(3));
        let analysis = analyze_pencil(&a, &b).unwrap();
        let lambdas = analysis
            .arcs
            .iter()
            .filter(|(_, i)| i.positive == 2 && i.negative == 2)
            .map(|(x, _)| x.clone())
            .chain(
                super::super::choose::more_candidates(&analysis)
                    .into_iter()
                    .filter_map(|c| c.0),
            );
        let degree = |curve: &Curve| match curve.components[0].param.as_ref() {
            Some(ComponentParam::Levin { s, .. }) => s
                .coeffs()
                .iter()
                .find_map(|c| c.field())
                .and_then(|f| f.modulus().degree()),
            _ => None,
        };
        let curve = lambdas
            .filter_map(|l| biquadratic_curve_at(classification.clone(), &a, &b, &l).unwrap())
            // the field is of degree 4: no route over one square root was taken
            .find(|c| degree(c) == Some(4))
            .expect("a member without a rational point");
        assert_eq!(curve.pieces.len(), 1);
        let param = curve.components[0].param.as_ref().unwrap();
        for m in [integer_matrix(&a), integer_matrix(&b)] {
            assert!(param.lies_on(&m));
        }
    }
}
