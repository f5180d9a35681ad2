//! Where a rational parameterization over a number field meets a plane, exactly: the real
//! parameters of the points at infinity that [`super::sample`] marks on such a component.
//!
//! `X(u)` with coefficients in ℚ(α), homogeneous of degree `k`, without the common factor
//! `g = gcd(Xᵢ)` of its coordinates (a root of `g` is a removable zero of `X`, where the point
//! is the limit, not the zero vector): the point at `u` lies on `h = 0` iff `h(X/g)(u) = 0`,
//! a polynomial over ℚ(α) whose real roots are those of its norm that it has
//! ([`NumberPoly::real_roots`]: exact signs at algebraic `u`, never floats); `u = ∞` iff
//! `deg h(X/g)` is less than the degree of `X/g`.

use super::curve::{Number, NumberPoly, ParamValue, PointPoly};
use qsic_algebra::RBig;

/// The real parameters (ℙ¹) at which `X(u)` lies on the plane `h·X = 0`, each once; `None`
/// where the whole curve does (`h·X ≡ 0`).
pub(super) fn plane_crossings(x: &PointPoly, h: &[RBig; 4]) -> Option<Vec<ParamValue>> {
    let g = x.iter().fold(NumberPoly::zero(), |g, p| g.gcd_monic(p));
    let reduced: PointPoly = if g.degree().unwrap_or(0) > 0 {
        std::array::from_fn(|i| x[i].div_rem(&g).0)
    } else {
        x.clone()
    };
    let degree = reduced
        .iter()
        .map(|p| p.degree().unwrap_or(0))
        .max()
        .unwrap_or(0);
    let w = (0..4)
        .filter(|&i| h[i] != RBig::ZERO)
        .fold(NumberPoly::zero(), |acc, i| {
            &acc + &reduced[i].scale(&Number::rational(h[i].clone()))
        });
    if w.is_zero() {
        return None;
    }
    let mut out: Vec<ParamValue> = w.real_roots().into_iter().map(ParamValue::Finite).collect();
    if w.degree().unwrap_or(0) < degree {
        out.push(ParamValue::Infinity);
    }
    Some(out)
}
