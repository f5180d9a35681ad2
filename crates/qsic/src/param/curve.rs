//! The intersection curve as exact components: the one model every class fills in, and what
//! the sampler, the JSON writer and the affine view read.
//!
//! * [`Component`]: an irreducible component over ℂ with its multiplicity (degree ×
//!   multiplicity sums to 4 for a regular pencil), real or not, and for real components an
//!   exact [`ComponentParam`] with coefficients in a real number field ([`Number`]).
//! * [`RealPiece`]: a connected piece of the real locus of one component — a curve traced by
//!   [`Arc`]s of the parameter, or an isolated point.
//! * [`Curve::connected`]: the connected components of the real locus in ℝP³, as groups of
//!   pieces (two conics meeting at a real point are one), decided exactly by the producer.

use crate::classify::{Classification, ComponentKind, SingularPointKind};
use qsic_algebra::field::{NumberField, NumberFieldElement, Quadratic};
use qsic_algebra::{AlgebraicReal, IBig, Poly, RBig};

/// An exact real number: a rational, or an element of a real number field ℚ(α).
pub type Number = NumberFieldElement;
/// A polynomial in the parameter `u` with [`Number`] coefficients.
pub type NumberPoly = Poly<NumberFieldElement>;
/// A point of ℝP³ in homogeneous coordinates `(x, y, z, w)`.
pub type Point = [Number; 4];
/// A point moving with `u`: homogeneous coordinates, polynomials in `u`.
pub type PointPoly = [NumberPoly; 4];

/// An exact parameterization of a real component.
#[derive(Clone, Debug)]
pub enum ComponentParam {
    /// A single point.
    Point(Point),
    /// `X(u)`, `u ∈ ℝ ∪ {∞}`; the point at `u = ∞` is given by the coefficients of `u^degree`
    /// (the homogenization `U₁^degree · X(U₀/U₁)`).
    Rational {
        /// The coordinates.
        x: PointPoly,
        /// The homogeneous degree (at least the degree of every coordinate).
        degree: usize,
    },
    /// Levin's form `X(u) = a(u) ± d(u)√s(u)`: real where `s(u) ≥ 0`. At a root `u₀` of
    /// `s` where `a(u₀) = 0` the point is the limit, `d(u₀)`.
    Levin {
        /// `a(u)`, of homogeneous degree `degree`.
        a: PointPoly,
        /// `d(u)`, of homogeneous degree `degree − 2`.
        d: PointPoly,
        /// The homogeneous degree of `a` (the point at `u = ∞` is `a_k ± d_{k−2}√s₄`).
        degree: usize,
        /// Another form `a′ ± d′√s` of the same curve and sheets, proportional to this one
        /// where both are nonzero, vanishing elsewhere: where this form vanishes (a base point,
        /// where the ruling meets the curve at its own end) the alternate gives the point.
        alternate: Option<Box<LevinForm>>,
        /// `s(u)`, a binary form of homogeneous degree 4 (degree drop: root at `u = ∞`).
        s: NumberPoly,
    },
}

/// One Levin form `a(u) ± d(u)√s(u)` (with the `s` of its [`ComponentParam::Levin`]).
#[derive(Clone, Debug)]
pub struct LevinForm {
    /// `a(u)`, of homogeneous degree `degree`.
    pub a: PointPoly,
    /// `d(u)`, of homogeneous degree `degree − 2`.
    pub d: PointPoly,
    /// The homogeneous degree of `a`.
    pub degree: usize,
}

/// An irreducible component of the intersection over ℂ.
#[derive(Clone, Debug)]
pub struct Component {
    /// Its kind.
    pub kind: ComponentKind,
    /// Its multiplicity in the intersection.
    pub multiplicity: u32,
    /// Whether it is real (defined over ℝ and with real points).
    pub real: bool,
    /// The parameterization: present for every real component, `None` for non-real ones.
    pub param: Option<ComponentParam>,
    /// The plane `ax + by + cz + dw = 0` holding a conic, as `[a, b, c, d]`.
    pub plane: Option<Point>,
    /// A real conic as its plane's section, over the plane's own field (see [`PlaneSection`]).
    pub section: Option<PlaneSection>,
}

/// A conic as the section of a quadric by its plane: the points `E·Y` of ℙ³ for the `Y` of ℙ²
/// with `YᵀCY = 0`, `E` (4×3, its columns spanning the plane) and `C` (3×3, symmetric,
/// nonsingular) over the plane's own field — ℚ, or the ℚ(√δ) of a plane pair — which is
/// usually smaller than the parameterization's (that also holds a point of the conic). The
/// conic's affine data (centre, axes) are read from it.
#[derive(Clone, Debug)]
pub struct PlaneSection {
    /// `E`: `basis[i][k]` is coordinate `i` of the plane's `k`-th spanning point.
    pub basis: [[Number; 3]; 4],
    /// `C`, the quadric restricted to the plane in that basis.
    pub conic: [[Number; 3]; 3],
}

/// A value of the parameter `u` on the projective line.
#[derive(Clone, Debug)]
pub enum ParamValue {
    /// A real number.
    Finite(AlgebraicReal),
    /// `u = ∞`.
    Infinity,
}

/// A range of the parameter on the projective line ℝ ∪ {∞}.
// A curve has a handful of ranges: boxing the ends would only add indirection.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug)]
pub enum ParamRange {
    /// All of ℝ ∪ {∞} (a closed curve traced once).
    All,
    /// From the first value to the second, increasing, through `∞` when the second is not
    /// greater than the first.
    Between(ParamValue, ParamValue),
}

/// Which determination of `±√s(u)` an arc of a [`ComponentParam::Levin`] uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sheet {
    /// A rational parameterization: no square root.
    Only,
    /// `a + d√s`.
    Plus,
    /// `a − d√s`.
    Minus,
}

/// A piece of a real curve: the image of a parameter range on one sheet.
#[derive(Clone, Debug)]
pub struct Arc {
    /// The parameter range.
    pub range: ParamRange,
    /// The sheet.
    pub sheet: Sheet,
    /// Traversed from the end of the range to its start.
    pub reversed: bool,
}

/// A connected piece of the real locus of one component.
// the point's four coordinates inline (a few hundred bytes): pieces are few, and a box would
// cost an allocation a point
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug)]
pub enum RealPiece {
    /// An isolated real point (of component `component`, a point or the real point of a
    /// non-real curve).
    Point {
        /// Index into [`Curve::components`].
        component: usize,
        /// The point.
        point: Point,
    },
    /// A real curve: its arcs traced in order, consecutive arcs sharing an end point.
    Curve {
        /// Index into [`Curve::components`].
        component: usize,
        /// The arcs.
        arcs: Vec<Arc>,
        /// The last arc ends where the first begins.
        closed: bool,
    },
}

impl RealPiece {
    /// The whole of a rational component's real curve: one arc over all of ℝ ∪ {∞}, closed.
    pub fn whole(component: usize) -> RealPiece {
        RealPiece::Curve {
            component,
            arcs: vec![Arc {
                range: ParamRange::All,
                sheet: Sheet::Only,
                reversed: false,
            }],
            closed: true,
        }
    }

    /// The component the piece belongs to.
    pub fn component(&self) -> usize {
        match self {
            RealPiece::Point { component, .. } | RealPiece::Curve { component, .. } => *component,
        }
    }
}

/// A real singular point of the curve.
#[derive(Clone, Debug)]
pub struct SingularPoint {
    /// Its kind.
    pub kind: SingularPointKind,
    /// The point.
    pub point: Point,
}

/// The intersection curve of two quadrics, exactly.
#[derive(Clone, Debug)]
pub struct Curve {
    /// The classification of the pencil.
    pub classification: Classification,
    /// The components over ℂ.
    pub components: Vec<Component>,
    /// The real singular points (of the curve and where components meet).
    pub singular_points: Vec<SingularPoint>,
    /// The pieces of the real locus.
    pub pieces: Vec<RealPiece>,
    /// The connected components of the real locus in ℝP³: groups of indices into `pieces`.
    pub connected: Vec<Vec<usize>>,
}

impl Curve {
    /// The curve of `classification` with nothing in it yet: no component, singular point,
    /// piece or connection (its producer fills them in).
    pub fn empty(classification: Classification) -> Curve {
        Curve {
            classification,
            components: Vec::new(),
            singular_points: Vec::new(),
            pieces: Vec::new(),
            connected: Vec::new(),
        }
    }
}

/// The rational `v` as a [`Number`].
pub fn rational(v: RBig) -> Number {
    NumberFieldElement::rational(v)
}

/// ℚ(√δ) as a [`NumberField`] generated by the positive root of `x² − δ` (`δ > 0` not a
/// square).
///
/// # Panics
/// If `δ ≤ 0` (no real root): a caller bug, the radicands here come from real quadratic
/// fields.
pub fn sqrt_field(delta: &IBig) -> NumberField {
    // ⌊√δ⌋ < √δ < ⌊√δ⌋ + 1 isolates the positive root when δ > 0 is not a square
    if let Some(k) = NumberField::sqrt(delta) {
        return k;
    }
    let p = Poly::new(vec![-delta.clone(), IBig::ZERO, IBig::ONE]);
    let roots = AlgebraicReal::real_roots_of(&p);
    NumberField::new(roots.last().expect("x² − δ has a positive root for δ > 0"))
}

/// `q = a + b√δ` in `field` = ℚ(√δ) from [`sqrt_field`] (a rational `q` needs no field; an
/// irrational one without `field` gets a field of its own).
pub fn from_quadratic(q: &Quadratic, field: Option<&NumberField>) -> Number {
    let coefficients = || Poly::new(vec![q.rational_part().clone(), q.radical_part().clone()]);
    match (q.as_rational(), field) {
        (Some(r), _) => rational(r.clone()),
        (None, Some(k)) => k.element(&coefficients()),
        (None, None) => sqrt_field(q.radicand()).element(&coefficients()),
    }
}

/// A polynomial over ℚ(√δ) as a [`NumberPoly`] (see [`from_quadratic`]).
pub fn poly_from_quadratic(p: &Poly<Quadratic>, field: Option<&NumberField>) -> NumberPoly {
    p.map(|c| from_quadratic(c, field))
}

/// `xᵀMy` for polynomial points.
pub(crate) fn poly_form(m: &[[RBig; 4]; 4], x: &PointPoly, y: &PointPoly) -> NumberPoly {
    let mut acc = NumberPoly::zero();
    for i in 0..4 {
        let mut row = NumberPoly::zero();
        for j in 0..4 {
            if m[i][j] != RBig::ZERO {
                row = &row + &y[j].scale(&rational(m[i][j].clone()));
            }
        }
        acc = &acc + &(&x[i] * &row);
    }
    acc
}

impl ComponentParam {
    /// Whether the parameterization lies on the quadric of matrix `m`, decided exactly as
    /// polynomial identities in `u`: `XᵀMX ≡ 0`; for Levin's form `aᵀMa + s·dᵀMd ≡ 0` and
    /// `aᵀMd ≡ 0` (both sheets on the quadric for every `u`), for the alternate form too.
    pub fn lies_on(&self, m: &[[RBig; 4]; 4]) -> bool {
        let constant =
            |p: &Point| -> PointPoly { std::array::from_fn(|i| Poly::constant(p[i].clone())) };
        match self {
            ComponentParam::Point(p) => {
                let x = constant(p);
                poly_form(m, &x, &x).is_zero()
            }
            ComponentParam::Rational { x, .. } => poly_form(m, x, x).is_zero(),
            ComponentParam::Levin {
                a, d, s, alternate, ..
            } => {
                let on = |a: &PointPoly, d: &PointPoly| {
                    (&poly_form(m, a, a) + &(s * &poly_form(m, d, d))).is_zero()
                        && poly_form(m, a, d).is_zero()
                };
                on(a, d) && alternate.as_ref().is_none_or(|f| on(&f.a, &f.d))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use qsic_algebra::Ring;

    /// The generator of `sqrt_field(δ)` is the positive square root, whether δ is a square
    /// (the root isolation route) or not (the interval ⌊√δ⌋ < √δ < ⌊√δ⌋ + 1).
    #[test]
    fn sqrt_field_generates_the_positive_square_root() {
        for delta in [2i64, 3, 5, 8, 15, 17, 99, 1_000_003, 4, 9, 1_000_000] {
            let k = sqrt_field(&IBig::from(delta));
            let alpha = k.alpha();
            assert!(alpha.is_valid(), "δ = {delta}");
            let want = (delta as f64).sqrt();
            assert!((alpha.to_f64() - want).abs() < 1e-12 * want, "δ = {delta}");
            // α² = δ in the field
            let g = k.generator();
            assert_eq!(g.mul(&g), rational(RBig::from(delta)), "δ = {delta}");
        }
    }
}
