//! The affine view of a pair whose curve is already built (`qsic param`, `qsic sample`): no
//! second parameterization.

use super::{
    affine_curve, fast_affine_curve, surface_name, AffineCurve, AffineSurface, AffineView, Chart,
};
use crate::error::Error;
use crate::param::Curve;
use crate::quadric::Quadric;

/// [`super::affine_view`] of `a` and `b` with their curve given (`None` when either is the
/// zero form): the surfaces' names, [`affine_curve`] of `curve`, and the solids' relation of
/// two ellipsoids in the default chart.
///
/// ```
/// use qsic::{affine::{affine_view_of_curve, Chart}, io::parse_quadric, param::parameterize};
/// let (a, b) = (parse_quadric("x^2+y^2-1").unwrap(), parse_quadric("(x-3)^2+y^2-1").unwrap());
/// let curve = parameterize(&a, &b).unwrap();
/// let view = affine_view_of_curve(Some(&a), Some(&b), Some(&curve), &Chart::default(), [false; 2]);
/// let c = view.curve.unwrap();
/// assert_eq!((c.curves_bounded, c.curves_unbounded, c.points_at_infinity), (0, 0, 1));
/// ```
pub fn affine_view_of_curve(
    a: Option<&Quadric>,
    b: Option<&Quadric>,
    curve: Option<&Curve>,
    chart: &Chart,
    planes: [bool; 2],
) -> AffineView {
    let curve = match (a, b, curve) {
        (Some(a), Some(b), Some(c)) => match fast_affine_curve(a, b, chart) {
            Some(fast) => Ok(fast),
            None => affine_curve(c, a, b, chart),
        },
        _ => Err(Error::Unsupported("a single quadric: no curve".into())),
    };
    assemble(a, b, chart, planes, curve)
}

/// The view from its curve part: the surfaces' names, and the solids' relation of two
/// ellipsoids in the default chart.
pub(super) fn assemble(
    a: Option<&Quadric>,
    b: Option<&Quadric>,
    chart: &Chart,
    planes: [bool; 2],
    curve: Result<AffineCurve, Error>,
) -> AffineView {
    let name = |q: Option<&Quadric>, plane: bool| {
        q.map(|q| {
            if plane {
                AffineSurface::Plane
            } else {
                surface_name(q, chart)
            }
        })
    };
    let surfaces = [name(a, planes[0]), name(b, planes[1])];
    let solids = match (a, b, surfaces) {
        (Some(a), Some(b), [Some(sa), Some(sb)])
            if sa.is_ellipsoid() && sb.is_ellipsoid() && chart.is_default() =>
        {
            crate::solids::solid_relation(a, b).ok()
        }
        _ => None,
    };
    AffineView {
        surfaces,
        curve,
        solids,
    }
}
