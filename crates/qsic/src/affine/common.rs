//! What two quadrics share beyond a curve: a common plane of the pencil (a component of
//! kind `plane`), or the quadric itself when `A ∝ B` (the single pencil's components: a
//! `quadric`, its planes, or its real point or line). A surface is named in the chart like
//! the surfaces ([`surface_name`](super::surface_name)), a plane `plane` or
//! `plane_at_infinity`, exactly: a plane is at infinity iff its coefficients are proportional
//! to the chart's form.

use super::{AffineComponent, Chart};
use crate::classify::ComponentKind;
use crate::param::{Component, Curve, Number};
use crate::quadric::Quadric;
use qsic_algebra::field::NumberFieldElement;
use qsic_algebra::{RBig, Ring};

fn rational(v: &RBig) -> Number {
    NumberFieldElement::rational(v.clone())
}

/// The common surfaces of a curve in the chart: every real component of kind `plane` or
/// `quadric` (a common plane of the pencil, or the quadric of a single pencil, `a`), by index
/// into [`Curve::components`], with its affine name (see [`AffineComponent::name`]).
///
/// ```
/// use qsic::{affine::{common_surfaces, Chart}, io::parse_quadric, param::parameterize};
/// let a = parse_quadric("x^2+y^2+z^2-1").unwrap();
/// let b = parse_quadric("2*x^2+2*y^2+2*z^2-2").unwrap();
/// let s = common_surfaces(&parameterize(&a, &b).unwrap(), &a, &Chart::default());
/// assert_eq!(s.len(), 1);
/// assert_eq!((s[0].1.name, s[0].1.bounded), (Some("sphere"), Some(true)));
/// ```
pub fn common_surfaces(curve: &Curve, a: &Quadric, chart: &Chart) -> Vec<(usize, AffineComponent)> {
    curve
        .components
        .iter()
        .enumerate()
        .filter(|(_, c)| c.real && matches!(c.kind, ComponentKind::Plane | ComponentKind::Quadric))
        .map(|(i, c)| (i, surface_component(c, a, chart)))
        .collect()
}

/// A common surface: a plane of the curve, or the quadric of a single pencil (`A ∝ B`, the
/// quadric `a`), with its affine name — `plane` or `plane_at_infinity`, or the quadric's
/// [`surface_name`](super::surface_name) key — and bounded iff an ellipsoid. A real quadric of
/// rank ≥ 3 has finite real points (no plane holds it); the double plane at infinity is a
/// plane component.
pub(super) fn surface_component(comp: &Component, a: &Quadric, chart: &Chart) -> AffineComponent {
    let mut view = AffineComponent {
        kind: comp.kind,
        name: None,
        at_infinity: false,
        bounded: None,
        points_at_infinity: 0,
        multiplicity: comp.multiplicity,
    };
    if !comp.real {
        return view;
    }
    if comp.kind == ComponentKind::Plane {
        let l = chart.form();
        view.at_infinity = comp.plane.as_ref().is_some_and(|p| {
            (0..4).all(|i| {
                (i + 1..4).all(|j| p[i].mul(&rational(&l[j])) == p[j].mul(&rational(&l[i])))
            })
        });
        view.name = Some(if view.at_infinity {
            "plane_at_infinity"
        } else {
            "plane"
        });
        view.bounded = (!view.at_infinity).then_some(false);
    } else {
        let name = super::surface_name(a, chart);
        view.name = Some(name.key());
        view.bounded = Some(name.is_ellipsoid());
    }
    view
}
