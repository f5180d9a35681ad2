//! The affine view of a pair: the surfaces' names, the curve in ℝ³, the solids' relation, and
//! the one-line summary in words. [`affine_view`] builds the curve (the fast route first);
//! [`affine_view_of_curve`] reads a curve already built (`qsic param`, `qsic sample`).
//!
//! What the two quadrics share beyond a curve is part of the answer: when `A ∝ B` the view
//! says so ([`AffineView::same`]) and the summary reads "the two are the same sphere"; a
//! common plane is a component of kind `plane` named `plane` (or `plane_at_infinity`).

use super::{
    affine_curve, fast_affine_curve, surface_name, AffineComponent, AffineCurve, AffineSurface,
    Chart,
};
use crate::classify::ComponentKind;
use crate::error::Error;
use crate::param::Curve;
use crate::quadric::Quadric;
use crate::Budget;

/// Everything the affine view says about a pair: the surfaces' names, the curve in ℝ³ when
/// its exact components are available, and the relation of two solid ellipsoids.
#[derive(Clone, Debug)]
pub struct AffineView {
    /// The affine names of `A` and `B` (`None` for the zero form).
    pub surfaces: [Option<AffineSurface>; 2],
    /// `A ∝ B`: the two are one quadric, which is then all they have in common.
    pub same: bool,
    /// The curve in ℝ³, or why it is not available (a class whose curve is not built yet).
    pub curve: Result<AffineCurve, Error>,
    /// The relation of the solids when both surfaces are ellipsoids (spheres included).
    pub solids: Option<crate::solids::SolidRelation>,
}

impl AffineView {
    /// A one-line summary in affine words, e.g. `"sphere and circular_cylinder: 2 bounded
    /// curves in ℝ³; no point at infinity"`, `"sphere and sphere: the two are the same sphere;
    /// solids equal"`, `"intersecting_planes and intersecting_planes: a common plane, 1
    /// unbounded curve; 1 point at infinity on the curve"`.
    pub fn summary(&self) -> String {
        let name = |s: &Option<AffineSurface>| s.map_or("zero form", AffineSurface::key);
        let mut out = format!(
            "{} and {}: {}",
            name(&self.surfaces[0]),
            name(&self.surfaces[1]),
            self.curve_summary()
        );
        if let Some(s) = self.solids {
            out.push_str("; solids ");
            out.push_str(s.key());
        }
        out
    }
}

impl AffineView {
    /// The part of [`AffineView::summary`] after the surfaces' names: what is common in ℝ³
    /// (`"2 bounded curves; no point at infinity"`, `"no common point in ℝ³; 1 point at
    /// infinity"`), or that the curve is not available.
    pub fn curve_summary(&self) -> String {
        match &self.curve {
            Ok(c) => curve_summary(c, self.surfaces[0].filter(|_| self.same)),
            Err(_) => "the curve in ℝ³ is not available for this class yet".to_owned(),
        }
    }
}

/// A surface in words: its key with spaces, the two names that do not read as a surface made
/// explicit.
pub fn surface_words(s: AffineSurface) -> String {
    match s {
        AffineSurface::Empty => "plane at infinity".into(),
        AffineSurface::Imaginary => "imaginary quadric".into(),
        s => s.key().replace('_', " "),
    }
}

fn is_surface(k: &AffineComponent) -> bool {
    matches!(k.kind, ComponentKind::Plane | ComponentKind::Quadric)
}

/// The summary's part after the names: the common surface (`same`: `A ∝ B`, this one), the
/// curves and points in ℝ³, then what lies at infinity.
fn curve_summary(c: &AffineCurve, same: Option<AffineSurface>) -> String {
    let plural = |n: usize, what: &str| format!("{n} {what}{}", if n == 1 { "" } else { "s" });
    let surfaces: Vec<&AffineComponent> = c
        .components
        .iter()
        .filter(|k| is_surface(k) && k.name.is_some())
        .collect();
    let mut parts = Vec::new();
    match same {
        Some(s) => parts.push(format!("the two are the same {}", surface_words(s))),
        None => {
            for k in &surfaces {
                parts.push(if k.at_infinity {
                    "the plane at infinity in common".to_owned()
                } else {
                    "a common plane".to_owned()
                });
            }
        }
    }
    let finite_surface = surfaces.iter().any(|k| !k.at_infinity);
    if c.curves_bounded + c.curves_unbounded + c.isolated_points == 0 {
        if !finite_surface {
            parts.push("no common point in ℝ³".to_owned());
        }
    } else {
        if c.curves_bounded > 0 {
            parts.push(plural(c.curves_bounded, "bounded curve"));
        }
        if c.curves_unbounded > 0 {
            parts.push(plural(c.curves_unbounded, "unbounded curve"));
        }
        if c.isolated_points > 0 {
            parts.push(plural(c.isolated_points, "isolated point"));
        }
    }
    let mut out = parts.join(", ");
    let in_plane = c
        .components
        .iter()
        .filter(|k| {
            // points at infinity are counted as such below
            k.at_infinity && k.name.is_some() && !is_surface(k) && k.kind != ComponentKind::Point
        })
        .count();
    // a common surface has points at infinity of its own: the counts are the curve's
    let on_curve = if surfaces.is_empty() {
        ""
    } else {
        " on the curve"
    };
    if in_plane > 0 {
        out.push_str(&format!(
            "; {} in the plane at infinity",
            plural(in_plane, "real component")
        ));
    }
    if c.points_at_infinity > 0 {
        out.push_str(&format!(
            "; {} at infinity{on_curve}",
            plural(c.points_at_infinity, "point")
        ));
    }
    if c.singular_at_infinity > 0 {
        out.push_str(&format!(
            "; {} at infinity{on_curve}",
            plural(c.singular_at_infinity, "singular point")
        ));
    }
    if in_plane + c.points_at_infinity + c.singular_at_infinity == 0 && surfaces.is_empty() {
        out.push_str("; no point at infinity");
    }
    out
}

/// The affine view of `a` and `b` (either may be the zero form, `None`) in `chart`;
/// `planes[i]` marks an input given as a plane (its quadric the double plane): its name is
/// `plane`.
pub fn affine_view(
    a: Option<&Quadric>,
    b: Option<&Quadric>,
    chart: &Chart,
    planes: [bool; 2],
) -> AffineView {
    affine_view_within(a, b, chart, planes, &Budget::unlimited())
        .expect("an unlimited budget is never spent")
}

/// [`affine_view`] spending `budget` ([`crate::Budget`]) on the curve where it is built
/// ([`crate::param::parameterize_within`]).
///
/// # Errors
/// [`Error::BudgetExceeded`] when the budget runs out first (any other failure of the
/// curve is part of the view, as in [`affine_view`]).
pub fn affine_view_within(
    a: Option<&Quadric>,
    b: Option<&Quadric>,
    chart: &Chart,
    planes: [bool; 2],
    budget: &Budget,
) -> Result<AffineView, Error> {
    let curve = match (a, b) {
        (Some(a), Some(b)) => {
            match natural_affine_curve(a, b, chart).or_else(|| fast_affine_curve(a, b, chart)) {
                Some(c) => Ok(c),
                None => match crate::param::parameterize_within(a, b, budget) {
                    Err(e @ Error::BudgetExceeded { .. }) => return Err(e),
                    curve => curve.and_then(|c| affine_curve(&c, a, b, chart)),
                },
            }
        }
        _ => Err(Error::Unsupported("a single quadric: no curve".into())),
    };
    Ok(assemble(a, b, chart, planes, curve))
}

/// The curve in ℝ³ by the natural route's closed forms (module [`crate::natural`]), which
/// answer in the default chart only; `None`: the next route answers.
fn natural_affine_curve(a: &Quadric, b: &Quadric, chart: &Chart) -> Option<AffineCurve> {
    if !chart.is_default() {
        return None;
    }
    crate::natural::affine_curve(a, b)
}

/// [`affine_view`] of `a` and `b` with their curve given (`None` when either is the
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
        (Some(a), Some(b), Some(c)) => {
            match natural_affine_curve(a, b, chart).or_else(|| fast_affine_curve(a, b, chart)) {
                Some(fast) => Ok(fast),
                None => affine_curve(c, a, b, chart),
            }
        }
        _ => Err(Error::Unsupported("a single quadric: no curve".into())),
    };
    assemble(a, b, chart, planes, curve)
}

/// The view from its curve part: the surfaces' names, and the solids' relation of two
/// ellipsoids in the default chart.
fn assemble(
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
        // a quadric is never the zero form, so dependence is proportionality
        same: matches!((a, b), (Some(a), Some(b)) if a.integer_matrix().is_proportional(b.integer_matrix())),
        curve,
        solids,
    }
}
