//! The curve in ℝ³ as the affine view gives it: its components, singular points and points
//! at infinity in a chart (module [`crate::affine`] computes it; the natural-quadric route
//! gives the same by closed forms).

use super::class::{ComponentKind, SingularPointKind};
use qsic_algebra::field::NumberFieldElement as Number;

/// One component of the curve seen in the chart.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AffineComponent {
    /// Its kind.
    pub kind: ComponentKind,
    /// The affine name of a real component: `ellipse`, `circle`, `parabola`, `hyperbola`,
    /// `conic_at_infinity`, `line`, `line_at_infinity`, `cubic`, `quartic`, `point`,
    /// `point_at_infinity`; for a common surface `plane`, `plane_at_infinity`, or the
    /// [`AffineSurface`](crate::affine::AffineSurface) key of the quadric of a single pencil (`sphere`,
    /// …); `None` for a non-real component.
    pub name: Option<&'static str>,
    /// It lies in the plane at infinity.
    pub at_infinity: bool,
    /// Its real points in ℝ³ form a bounded set (`None` for a non-real component or one at
    /// infinity).
    pub bounded: Option<bool>,
    /// Its distinct real points at infinity (0 for a component at infinity).
    pub points_at_infinity: usize,
    /// Its multiplicity in the intersection (as [`crate::param::Component::multiplicity`]).
    pub multiplicity: u32,
}

/// A real singular point of the curve seen in the chart.
#[derive(Clone, Debug, PartialEq)]
pub struct AffineSingularPoint {
    /// Its kind.
    pub kind: SingularPointKind,
    /// It lies on the plane at infinity.
    pub at_infinity: bool,
    /// Its affine coordinates in the chart, `None` at infinity.
    pub point: Option<[Number; 3]>,
}

/// The curve in ℝ³ (see the module documentation).
#[derive(Clone, Debug, PartialEq)]
pub struct AffineCurve {
    /// Connected components of the real curve in ℝ³ that are bounded.
    pub curves_bounded: usize,
    /// … and unbounded.
    pub curves_unbounded: usize,
    /// Isolated real points in ℝ³.
    pub isolated_points: usize,
    /// Distinct real points of the curve on the plane at infinity (components lying in it
    /// excluded).
    pub points_at_infinity: usize,
    /// Real singular points in ℝ³.
    pub singular_finite: usize,
    /// Real singular points at infinity.
    pub singular_at_infinity: usize,
    /// Per component of the curve, in [`Curve::components`](crate::param::Curve::components) order.
    pub components: Vec<AffineComponent>,
    /// Per real singular point, in [`Curve::singular_points`](crate::param::Curve::singular_points) order.
    pub singular_points: Vec<AffineSingularPoint>,
}
