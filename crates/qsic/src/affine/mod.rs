//! The affine view: what a quadric is in ℝ³, relative to a plane at infinity (the chart).
//!
//! | item | what |
//! |---|---|
//! | [`Chart`] | the plane at infinity `ℓ(X) = 0` (default `w = 0`) and the change of coordinates making it `w = 0` |
//! | [`AffineSurface`], [`surface_name`] | the affine name of a quadric (sphere, elliptic cylinder, …), exactly |
//! | [`affine_curve`] | the curve in ℝ³: bounded and unbounded pieces, points and singular points at infinity, conic names |
//! | [`common_surfaces`] | a common plane, or the quadric when `A ∝ B`, with its affine name |
//! | [`affine_view`], [`AffineView`] | the surfaces' names, the curve, the solids, the summary in words |
//! | [`affine_conic`] | a conic component's type, centre or vertex, axes, radius, exactly |
//! | [`component_frame`], [`Frame`] | a real line, conic or point as a CAD kernel stores it: location, normal, X direction, lengths |
//! | [`fast_affine_curve`], [`conic_real_intersections`] | the same without the curve where the class and the conics at infinity decide it (nonsingular quartics) |
//!
//! With `M` the 4×4 matrix in coordinates where the plane at infinity is `w = 0` and `Q` its
//! upper-left 3×3 block (the quadratic part), the affine type is decided by the inertias of
//! `M` and `Q` (up to the sign of `M`, normalised to `positive ≥ negative` for `M`), exactly
//! (Descartes' rule on the characteristic polynomials, [`Inertia::from_minor_sum_signs`]), and
//! for the round shapes by equal eigenvalues of `Q`: a sphere has `Q = cI`; a circular cylinder
//! has `Q`'s characteristic polynomial `x(x² − E₁x + E₂)` with `E₁² = 4E₂`; a circular cone has
//! a cubic characteristic polynomial with zero discriminant.

mod common;
mod conic;
mod curve;
mod fast;
mod frame;
mod section;
mod view;

pub use common::common_surfaces;
pub use conic::{approx, param_conic, AffineConic, Axis, ConicShape, Direction, Surd};
pub use curve::{affine_curve, AffineComponent, AffineCurve, AffineSingularPoint};
pub use fast::{conic_real_intersections, fast_affine_curve};
pub use frame::{
    component_frame, conic_frame, point_frame, Frame, FrameDirection, FrameLength, Placement,
};
pub use section::affine_conic;
pub use view::{affine_view, affine_view_of_curve, affine_view_within, surface_words, AffineView};

use crate::error::Error;
use crate::param::{Number, Point};
use crate::quadric::Quadric;
use qsic_algebra::field::NumberFieldElement;
use qsic_algebra::linalg::minors::principal_minor_sums;
use qsic_algebra::linalg::{Inertia, Matrix};
use qsic_algebra::Ring;
use qsic_algebra::{IBig, RBig, Sign};

/// The plane at infinity of an affine chart, `a·x + b·y + c·z + d·w = 0`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Chart {
    form: [RBig; 4],
    /// Rows: the new coordinates `(x′, y′, z′, w′)` as forms in `(x, y, z, w)`, `w′ = ℓ`.
    basis: [[RBig; 4]; 4],
    /// Its inverse: old coordinates from new ones.
    inverse: [[RBig; 4]; 4],
}

impl Default for Chart {
    fn default() -> Chart {
        let id: [[RBig; 4]; 4] = std::array::from_fn(|i| {
            std::array::from_fn(|j| if i == j { RBig::ONE } else { RBig::ZERO })
        });
        Chart {
            form: id[3].clone(),
            basis: id.clone(),
            inverse: id,
        }
    }
}

impl Chart {
    /// The chart whose plane at infinity is `form · (x, y, z, w) = 0`.
    ///
    /// # Errors
    /// [`Error::InvalidChart`] for the zero form.
    pub fn new(form: [RBig; 4]) -> Result<Chart, Error> {
        let Some(k) = (0..4).rev().find(|&k| form[k] != RBig::ZERO) else {
            return Err(Error::InvalidChart(
                "the plane at infinity is the zero form".into(),
            ));
        };
        // the unit forms other than the k-th, then ℓ: an invertible basis
        let mut basis: Vec<[RBig; 4]> = (0..4)
            .filter(|&i| i != k)
            .map(|i| std::array::from_fn(|j| if i == j { RBig::ONE } else { RBig::ZERO }))
            .collect();
        basis.push(form.clone());
        let basis: [[RBig; 4]; 4] = std::array::from_fn(|i| basis[i].clone());
        let inverse = Matrix::from_array(basis.clone())
            .inverse()
            .and_then(|m| m.to_array())
            .ok_or_else(|| Error::Algebra("the chart's basis is singular".into()))?;
        Ok(Chart {
            form,
            basis,
            inverse,
        })
    }

    /// The plane at infinity `[a, b, c, d]`.
    pub fn form(&self) -> &[RBig; 4] {
        &self.form
    }

    /// Whether this is the default chart `w = 0`: its form is `(0, 0, 0, 1)` (the basis and
    /// its inverse follow from the form, so the form decides).
    pub fn is_default(&self) -> bool {
        self.form[..3].iter().all(|v| *v == RBig::ZERO) && self.form[3] == RBig::ONE
    }

    /// The matrix of `q` in the chart's coordinates (plane at infinity `w′ = 0`):
    /// `X = T⁻¹X′` gives `M′ = T⁻ᵀ M T⁻¹`.
    pub fn matrix_in_chart(&self, m: &[[RBig; 4]; 4]) -> [[RBig; 4]; 4] {
        let t = &self.inverse;
        std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let mut acc = RBig::ZERO;
                for k in 0..4 {
                    for l in 0..4 {
                        if t[k][i] != RBig::ZERO && t[l][j] != RBig::ZERO {
                            acc += &t[k][i] * &m[k][l] * &t[l][j];
                        }
                    }
                }
                acc
            })
        })
    }

    /// Row `i` of the change of coordinates: the chart's `i`-th coordinate as a form in
    /// `(x, y, z, w)` (row 3 is the plane at infinity).
    pub fn basis_row(&self, i: usize) -> &[RBig; 4] {
        &self.basis[i]
    }

    /// [`Chart::to_chart`] for a point with algebraic coordinates.
    pub fn to_chart_number(&self, p: &Point) -> Point {
        std::array::from_fn(|i| {
            let mut acc = Number::zero();
            for j in 0..4 {
                if self.basis[i][j] != RBig::ZERO {
                    acc =
                        acc.add(&p[j].mul(&NumberFieldElement::rational(self.basis[i][j].clone())));
                }
            }
            acc
        })
    }

    /// The chart's coordinates `(x′, y′, z′, w′)` of a point given in the input coordinates.
    pub fn to_chart(&self, p: &[RBig; 4]) -> [RBig; 4] {
        std::array::from_fn(|i| {
            let mut acc = RBig::ZERO;
            for j in 0..4 {
                acc += &self.basis[i][j] * &p[j];
            }
            acc
        })
    }
}

/// The affine name of a quadric surface (its real points in ℝ³ and their shape).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum AffineSurface {
    /// A sphere.
    Sphere,
    /// An ellipsoid that is not a sphere.
    Ellipsoid,
    /// A hyperboloid of one sheet.
    HyperboloidOneSheet,
    /// A hyperboloid of two sheets.
    HyperboloidTwoSheets,
    /// An elliptic paraboloid.
    EllipticParaboloid,
    /// A hyperbolic paraboloid.
    HyperbolicParaboloid,
    /// A circular cylinder.
    CircularCylinder,
    /// An elliptic cylinder that is not circular.
    EllipticCylinder,
    /// A parabolic cylinder.
    ParabolicCylinder,
    /// A hyperbolic cylinder.
    HyperbolicCylinder,
    /// A circular cone.
    CircularCone,
    /// An elliptic cone that is not circular.
    EllipticCone,
    /// Two real planes meeting in a line of ℝ³.
    IntersectingPlanes,
    /// Two distinct real parallel planes.
    ParallelPlanes,
    /// A plane counted twice.
    DoublePlane,
    /// Two conjugate planes through a real line of ℝ³.
    LinePair,
    /// A cone with one real point (its vertex, in ℝ³).
    PointCone,
    /// No real point in ℝ³.
    Imaginary,
    /// One real plane of ℝ³ (a degree-1 input, or a plane pair whose other plane is at
    /// infinity).
    Plane,
    /// The plane at infinity alone (counted twice).
    Empty,
}

impl AffineSurface {
    /// The JSON key (`sphere`, `hyperboloid_one_sheet`, …).
    pub fn key(self) -> &'static str {
        use AffineSurface::*;
        match self {
            Sphere => "sphere",
            Ellipsoid => "ellipsoid",
            HyperboloidOneSheet => "hyperboloid_one_sheet",
            HyperboloidTwoSheets => "hyperboloid_two_sheets",
            EllipticParaboloid => "elliptic_paraboloid",
            HyperbolicParaboloid => "hyperbolic_paraboloid",
            CircularCylinder => "circular_cylinder",
            EllipticCylinder => "elliptic_cylinder",
            ParabolicCylinder => "parabolic_cylinder",
            HyperbolicCylinder => "hyperbolic_cylinder",
            CircularCone => "circular_cone",
            EllipticCone => "elliptic_cone",
            IntersectingPlanes => "intersecting_planes",
            ParallelPlanes => "parallel_planes",
            DoublePlane => "double_plane",
            LinePair => "line_pair",
            PointCone => "point_cone",
            Imaginary => "imaginary",
            Plane => "plane",
            Empty => "empty",
        }
    }

    /// Whether the surface bounds a convex solid of ℝ³ with nonempty interior that is
    /// bounded (ellipsoids, spheres).
    pub fn is_ellipsoid(self) -> bool {
        matches!(self, AffineSurface::Sphere | AffineSurface::Ellipsoid)
    }
}

/// The inertia of a symmetric `N × N` integer matrix, exactly.
fn inertia<const N: usize>(m: &[[IBig; N]; N]) -> Inertia {
    Inertia::from_minor_sum_signs(principal_minor_sums(m).map(|e| Sign::of(&e)))
}

/// A positive multiple of a rational matrix with integer entries (the same quadric: every
/// inertia, equality and vanishing `surface_name` reads is unchanged).
fn integral<const N: usize>(m: &[[RBig; N]; N]) -> [[IBig; N]; N] {
    let mut den = IBig::ONE;
    for v in m.iter().flatten() {
        let d = IBig::from(v.denominator().clone());
        if &den % &d != IBig::ZERO {
            den *= d;
        }
    }
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let v = &m[i][j];
            v.numerator() * (&den / IBig::from(v.denominator().clone()))
        })
    })
}

/// The matrix of `q` in the chart's coordinates as integers: the primitive integer matrix
/// itself in the default chart (no rational arithmetic), else [`Chart::matrix_in_chart`]
/// scaled.
fn integer_matrix_in_chart(q: &Quadric, chart: &Chart) -> [[IBig; 4]; 4] {
    if chart.is_default() {
        q.integer_matrix().entries().clone()
    } else {
        integral(&chart.matrix_in_chart(q.matrix()))
    }
}

/// The affine name of `q` in `chart`.
///
/// ```
/// use qsic::{affine::{surface_name, AffineSurface, Chart}, io::parse_quadric};
/// let name = |s: &str| surface_name(&parse_quadric(s).unwrap(), &Chart::default());
/// assert_eq!(name("x^2+y^2+z^2-1"), AffineSurface::Sphere);
/// assert_eq!(name("(x-3)^2+y^2-1"), AffineSurface::CircularCylinder);
/// assert_eq!(name("x^2+y^2-z"), AffineSurface::EllipticParaboloid);
/// assert_eq!(name("x*w"), AffineSurface::Plane); // x = 0 and the plane at infinity
/// ```
pub fn surface_name(q: &Quadric, chart: &Chart) -> AffineSurface {
    use AffineSurface::*;
    let m = integer_matrix_in_chart(q, chart);
    let mut im = inertia(&m);
    let mut negate = false;
    if im.negative > im.positive {
        im = im.negated();
        negate = true;
    }
    let block: [[IBig; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| m[i][j].clone()));
    let mut iq = inertia(&block);
    if negate {
        iq = iq.negated();
    }
    let e = principal_minor_sums(&block);
    // Q = cI: a multiple of the identity
    let scalar = block[0][0] == block[1][1]
        && block[1][1] == block[2][2]
        && block[0][1] == IBig::ZERO
        && block[0][2] == IBig::ZERO
        && block[1][2] == IBig::ZERO;
    match (im.rank(), iq.rank()) {
        (4, 3) => match (im.positive, iq.positive == 3 || iq.negative == 3) {
            (4, _) => Imaginary,
            (3, true) if scalar => Sphere,
            (3, true) => Ellipsoid,
            (3, false) => HyperboloidTwoSheets,
            _ => HyperboloidOneSheet,
        },
        (4, _) => {
            // rank Q = 2 (rank M ≤ rank Q + 2)
            if iq.is_indefinite() {
                HyperbolicParaboloid
            } else {
                EllipticParaboloid
            }
        }
        (3, 3) => {
            if im.negative == 0 {
                PointCone
            } else if cubic_discriminant(&e) == IBig::ZERO {
                CircularCone
            } else {
                EllipticCone
            }
        }
        (3, 2) => {
            if iq.is_indefinite() {
                HyperbolicCylinder
            } else if im.negative == 0 {
                Imaginary
            } else if &e[0] * &e[0] == IBig::from(4) * &e[1] {
                CircularCylinder
            } else {
                EllipticCylinder
            }
        }
        (3, _) => ParabolicCylinder,
        (2, 2) => {
            if im.negative == 0 {
                LinePair
            } else {
                IntersectingPlanes
            }
        }
        (2, 1) => {
            if im.negative == 0 {
                Imaginary
            } else {
                ParallelPlanes
            }
        }
        (2, _) => Plane,
        (1, 1) => DoublePlane,
        (1, _) => Empty,
        _ => Empty,
    }
}

/// The discriminant of `x³ − E₁x² + E₂x − E₃` (zero iff a repeated eigenvalue).
fn cubic_discriminant(e: &[IBig; 3]) -> IBig {
    let (b, c, d) = (-e[0].clone(), e[1].clone(), -e[2].clone());
    // Δ = 18bcd − 4b³d + b²c² − 4c³ − 27d² for x³ + bx² + cx + d
    IBig::from(18) * &b * &c * &d - IBig::from(4) * &b * &b * &b * &d + &b * &b * &c * &c
        - IBig::from(4) * &c * &c * &c
        - IBig::from(27) * &d * &d
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::parse_quadric;
    use AffineSurface::*;

    fn name(s: &str) -> AffineSurface {
        surface_name(&parse_quadric(s).unwrap(), &Chart::default())
    }

    #[test]
    fn every_name_from_a_hand_made_example() {
        let cases = [
            ("x^2+y^2+z^2-1", Sphere),
            ("-(x-1)^2-(y+2)^2-z^2+4", Sphere),
            ("x^2+2*y^2+z^2-1", Ellipsoid),
            ("x^2+y^2+z^2+1", Imaginary),
            ("x^2+y^2-z^2-1", HyperboloidOneSheet),
            ("x^2+y^2-z^2+1", HyperboloidTwoSheets),
            ("x^2+2*y^2-z", EllipticParaboloid),
            ("x^2-y^2-z", HyperbolicParaboloid),
            ("x*y-z", HyperbolicParaboloid),
            ("(x-3)^2+y^2-1", CircularCylinder),
            ("x^2+4*y^2-1", EllipticCylinder),
            ("x^2+y^2+1", Imaginary),
            ("x^2-y", ParabolicCylinder),
            ("x^2-y^2-1", HyperbolicCylinder),
            ("x*y-1", HyperbolicCylinder),
            ("x^2+y^2-z^2", CircularCone),
            ("x^2+y^2-(z-2)^2", CircularCone),
            ("x^2+4*y^2-z^2", EllipticCone),
            ("x^2+y^2+z^2", PointCone),
            ("x*y", IntersectingPlanes),
            ("x^2-y^2", IntersectingPlanes),
            ("x^2-1", ParallelPlanes),
            ("x^2+y^2", LinePair),
            ("x^2+1", Imaginary),
            ("x^2", DoublePlane),
            ("(x+y-1)^2", DoublePlane),
            ("x*w", Plane),
            ("(x+y+z)*w-w^2", Plane),
            ("w^2", Empty),
        ];
        for (s, want) in cases {
            assert_eq!(name(s), want, "{s}");
        }
    }

    /// The unit sphere seen with a plane at infinity that misses it (an ellipsoid), cuts it
    /// (a hyperboloid of two sheets) or touches it (an elliptic paraboloid): charts whose
    /// change of coordinates is not a permutation.
    #[test]
    fn a_sphere_is_an_ellipsoid_a_hyperboloid_or_a_paraboloid_by_its_plane_at_infinity() {
        let q = parse_quadric("x^2+y^2+z^2-w^2").unwrap();
        let name = |f: [i64; 4]| surface_name(&q, &Chart::new(f.map(RBig::from)).unwrap());
        assert!(name([1, 0, 0, 2]).is_ellipsoid()); // x = −2w misses it
        assert!(name([1, 1, 0, 3]).is_ellipsoid());
        assert_eq!(name([2, 0, 0, 1]), HyperboloidTwoSheets); // x = −w/2 cuts it
        assert_eq!(name([1, 1, 1, 1]), HyperboloidTwoSheets);
        assert_eq!(name([1, 0, 0, 1]), EllipticParaboloid); // x = −w touches it
        assert_eq!(name([3, 0, 4, 5]), EllipticParaboloid); // |(3, 0, 4)| = 5
                                                            // solids are read in the default chart only
        let b = parse_quadric("(x-1)^2+y^2+z^2-1").unwrap();
        let default = affine_view(Some(&q), Some(&b), &Chart::default(), [false, false]);
        assert_eq!(default.solids.map(|s| s.key()), Some("overlapping"));
        let other = Chart::new([1, 0, 0, 3].map(RBig::from)).unwrap();
        assert!(!other.is_default() && Chart::default().is_default());
        let chart = |f: [i64; 4]| Chart::new(f.map(RBig::from)).unwrap();
        assert!(chart([0, 0, 0, 1]).is_default() && chart([0, 0, 0, 1]) == Chart::default());
        for f in [[0, 0, 0, 2], [0, 0, 1, 1], [1, 0, 0, 0], [0, 0, 0, -1]] {
            assert!(
                !chart(f).is_default() && chart(f) != Chart::default(),
                "{f:?}"
            );
        }
        assert_eq!(
            affine_view(Some(&q), Some(&b), &other, [false, false]).solids,
            None
        );
    }

    #[test]
    fn an_affine_map_changes_no_name_and_a_chart_moves_infinity() {
        // x → x + 2y + 3, y → y − z, z → 2z + x + y: affine, invertible (det 1)
        let cases = [
            ("(x+2*y+3)^2+(y-z)^2-(2*z+x+y)^2-1", HyperboloidOneSheet),
            ("(x+2*y+3)^2+(y-z)^2-(2*z+x+y)", EllipticParaboloid),
            ("(x+2*y+3)^2-(y-z)", ParabolicCylinder),
        ];
        for (s, want) in cases {
            assert_eq!(name(s), want, "{s}");
        }
        // the cone x² + y² − z² in the chart z = 0 at infinity: a circle x² + y² = w² in
        // every plane z = const, a circular cylinder
        let q = parse_quadric("x^2+y^2-z^2").unwrap();
        let chart = Chart::new([0, 0, 1, 0].map(RBig::from)).unwrap();
        assert_eq!(surface_name(&q, &chart), CircularCylinder);
        // a sphere seen with x = 0 at infinity: x² + y² + z² − w², x = 1: y² + z² − w² = −1
        // in the chart's affine coordinates: a hyperboloid of two sheets
        let q = parse_quadric("x^2+y^2+z^2-w^2").unwrap();
        let chart = Chart::new([1, 0, 0, 0].map(RBig::from)).unwrap();
        assert_eq!(surface_name(&q, &chart), HyperboloidTwoSheets);
        assert!(Chart::new([0, 0, 0, 0].map(RBig::from)).is_err());
    }
}
