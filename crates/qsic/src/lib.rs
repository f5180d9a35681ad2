//! qsic: the exact morphology of the intersection curve of two quadric surfaces.
//!
//! | module | owns |
//! |---|---|
//! | [`affine`] | the affine view: charts, affine names of quadrics |
//! | [`quadric`] | [`Quadric`], a validated symmetric 4×4 rational matrix |
//! | [`io`] | reading quadrics from polynomial strings and matrices, rational functions and moving quadrics, exactly |
//! | [`shapes`] | constructors for spheres, cylinders, cones, … from rational parameters |
//! | [`pencil`] | the pencil `λA − μB`: characteristic form, real roots, Segre structure, inertia |
//! | [`mod@classify`] | [`classify()`]: regular (35 cases), singular and single pencils |
//! | [`natural`] | planes, spheres, circular cylinders and cones recognized exactly; closed forms for their pairs |
//! | [`motion`] | moving quadrics: critical instants and the type between them, exactly |
//! | [`solids`] | [`solids::solid_relation`]: separated, touching, overlapping or nested solid ellipsoids, exactly |
//! | [`param`] | Levin's parameterization `a(u) ± d(u)√s(u)` of a nonsingular quartic, exactly; Theorem 12 |
//! | [`limits`] | documented bounds on untrusted input |
//!
//! ```
//! use qsic::{classify, io::parse_quadric};
//! let a = parse_quadric("x^2 + y^2 + z^2 - w^2").unwrap(); // unit sphere
//! let b = parse_quadric("x^2 + y^2 - 2*x*w").unwrap();     // cylinder through its centre… tangent inside
//! let c = classify(&a, &b);
//! assert_eq!(c.pencil.key(), "regular");
//! ```

// Index loops read as the matrix formulas they implement.
#![allow(clippy::needless_range_loop)]

pub mod affine;
pub mod classify;
pub mod error;
pub mod io;
pub mod limits;
pub mod motion;
pub mod natural;
pub mod nurbs;
pub mod param;
pub mod pencil;
pub mod quadric;
pub mod shapes;
pub mod solids;
pub mod vocabulary;

pub use classify::{
    classify, classify_allowing_zero, classify_single, classify_within, Classification,
};
pub use error::Error;
pub use qsic_algebra::Budget;
pub use quadric::Quadric;

/// For this crate's integration tests and benchmarks only, not part of the API.
#[doc(hidden)]
pub mod test_support {
    use crate::{Classification, Quadric};

    /// [`classify()`](crate::classify()) by exact rational arithmetic alone, without the
    /// machine-arithmetic fast path: the twin the differential tests compare with it, and
    /// the route the exact-path benchmarks time.
    pub fn classify_exact(a: &Quadric, b: &Quadric) -> Classification {
        crate::classify::classify_exact(a, b)
    }

    /// [`crate::natural::recognize`] without its machine-integer filter: the reference the
    /// filtered recognizer must equal.
    pub fn natural_recognize_exact(q: &Quadric) -> Option<crate::natural::NaturalQuadric> {
        crate::natural::recognize_exact(q)
    }

    /// The natural route's answer (module [`crate::natural`]) alone: the classification and
    /// the curve in ℝ³ in the default chart, or `None` where it declines.
    pub fn natural_answer(
        a: &Quadric,
        b: &Quadric,
    ) -> Option<(Classification, crate::affine::AffineCurve)> {
        let p = crate::natural::answer(a, b)?;
        Some((crate::classify::from_natural(p.class), p.curve))
    }

    /// [`crate::solids::solid_relation`] read from the pencil alone, without the closed form
    /// for two spheres: the reference the closed form must equal.
    pub fn solid_relation_by_pencil(
        a: &Quadric,
        b: &Quadric,
    ) -> Result<crate::solids::SolidRelation, crate::Error> {
        crate::solids::solid_relation_by_pencil(a, b, &crate::Budget::unlimited())
    }

    /// The curve in ℝ³ by the general route alone (the fast affine route, else the curve
    /// built and read): the reference of the natural route.
    pub fn general_affine_curve(
        a: &Quadric,
        b: &Quadric,
        chart: &crate::affine::Chart,
    ) -> Result<crate::affine::AffineCurve, crate::Error> {
        match crate::affine::fast_affine_curve(a, b, chart) {
            Some(c) => Ok(c),
            None => crate::param::parameterize(a, b)
                .and_then(|c| crate::affine::affine_curve(&c, a, b, chart)),
        }
    }
}
