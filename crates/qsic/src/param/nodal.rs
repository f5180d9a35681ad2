//! Singular irreducible quartics (cases 5–8: a node, case 11: a cusp), rationally through
//! the cone whose vertex is the singular point (enhanced-Levin paper, Theorems 7–8).
//!
//! The multiple root `λ₀` of `det(λA − B)` is rational (it is the only multiple root) and
//! its member `S₀` is a cone (rank 3) whose vertex `P` lies on every member: `P` is the
//! singular point. With the rulings of a real `S₀` written `P + v·d(u)`, `d(u)` a conic on
//! `S₀` (over ℚ or ℚ(√δ)), a second member `Q` gives `v²·dᵀQd + 2v·PᵀQd = 0` (`PᵀQP = 0`),
//! so besides `P` each ruling meets the curve once more:
//! `X(u) = (dᵀQd)·P − 2(PᵀQd)·d`, a rational quartic. `X(u) = P` exactly where
//! `c(u) = PᵀQd(u)` vanishes: two real roots — a crunode, a double root — a cusp, a
//! conjugate pair — an acnode. When `S₀` is not real (case 7) `P` is the only real point.

use super::curve::{self, Component, ComponentParam, Curve, RealPiece};
use super::surface::{parameterize_cone, poly_form, to_quadratic, PolyVector};
use super::{integer_matrix, member, Point};
use crate::classify::{analyze_pencil, Classification, ComponentKind, SingularPointKind};
use crate::error::Error;
use crate::pencil::{PencilAnalysis, PencilPoint, PencilRoot};
use crate::quadric::Quadric;
use qsic_algebra::field::{NumberField, Quadratic};
use qsic_algebra::linalg::Matrix;
use qsic_algebra::{AlgebraicReal, IBig, Poly, RBig, Ring, Sign};

/// The rational parameterization of a singular irreducible quartic through its singular
/// point (see the [module docs](self)).
#[derive(Clone, Debug)]
pub struct SingularQuartic {
    /// The multiple root `λ₀` of `det(λA − B)` (`None`: `λ₀ = ∞`, the member `A`), with `A`,
    /// `B` the primitive integer matrices of the quadrics.
    pub lambda: Option<RBig>,
    /// The singular point `P`, the vertex of `S₀ = λ₀A − B`: a primitive integer vector.
    pub point: [RBig; 4],
    /// Its kind, from the roots of `c(u) = PᵀQd(u)`.
    pub kind: SingularPointKind,
    /// `X(u)` (no common factor), `None` when the cone `S₀` has no real point but its
    /// vertex (case 7).
    pub x: Option<PolyVector>,
    /// The radicand `δ` when `X(u)` has coefficients in ℚ(√δ), `None` over ℚ.
    pub delta: Option<IBig>,
}

/// The rational `v` if the algebraic number is rational.
pub(super) fn rational_value(v: &AlgebraicReal) -> Option<RBig> {
    if let Some(r) = v.as_rational() {
        return Some(r.clone());
    }
    let p = v.poly();
    (p.degree() == Some(1)).then(|| RBig::from(-p.coeff(0)) / RBig::from(p.coeff(1)))
}

/// The point `λ₀` of a pencil root as `Some(rational)` (`None` for ∞); an error for an
/// irrational root.
pub(super) fn rational_root(root: &PencilRoot) -> Result<Option<RBig>, Error> {
    match &root.point {
        PencilPoint::Infinity => Ok(None),
        PencilPoint::Finite(v) => rational_value(v).map(Some).ok_or_else(|| {
            Error::Algebra(format!("the multiple root {} is not rational", v.to_f64()))
        }),
    }
}

/// The primitive integer vector proportional to a rational vector (first nonzero coordinate
/// positive).
///
/// # Panics
/// If `v` is zero.
pub(super) fn primitive(v: &[RBig]) -> [RBig; 4] {
    let mut den = IBig::ONE;
    for x in v {
        let d = IBig::from(x.denominator().clone());
        den = &den / gcd(&den, &d) * d;
    }
    let ints: Vec<IBig> = v
        .iter()
        .map(|x| x.numerator() * (&den / IBig::from(x.denominator().clone())))
        .collect();
    let mut g = IBig::ZERO;
    for x in &ints {
        g = gcd(&g, x);
    }
    if ints
        .iter()
        .find(|x| !x.is_zero())
        .is_some_and(|x| *x < IBig::ZERO)
    {
        g = -g;
    }
    std::array::from_fn(|i| RBig::from(&ints[i] / &g))
}

/// `gcd(a, b) ≥ 0`, with `gcd(0, 0) = 0`.
fn gcd(a: &IBig, b: &IBig) -> IBig {
    use dashu_int::ops::Gcd;
    if a.is_zero() && b.is_zero() {
        return IBig::ZERO;
    }
    IBig::from(a.gcd(b))
}

/// The one-dimensional kernel of a rank-3 member, as a primitive integer vector.
pub(super) fn vertex(s: &[[RBig; 4]; 4]) -> Result<[RBig; 4], Error> {
    let kernel = Matrix::from_array(s.clone()).kernel();
    match kernel.as_slice() {
        [v] => Ok(primitive(v)),
        _ => Err(Error::Algebra(format!(
            "a member of rank {} where a cone was expected",
            4 - kernel.len()
        ))),
    }
}

/// `xᵀMy` for rational vectors.
pub(super) fn form(m: &[[RBig; 4]; 4], x: &[RBig; 4], y: &[RBig; 4]) -> RBig {
    let mut acc = RBig::ZERO;
    for i in 0..4 {
        for j in 0..4 {
            acc += &x[i] * &m[i][j] * &y[j];
        }
    }
    acc
}

/// Divides four polynomials by their monic gcd; the result and its largest degree.
pub(super) fn without_common_factor<F: qsic_algebra::Field>(
    x: [Poly<F>; 4],
) -> ([Poly<F>; 4], usize) {
    let g = x.iter().fold(Poly::zero(), |g, p| g.gcd_monic(p));
    let x = if g.degree().unwrap_or(0) > 0 {
        x.map(|p| p.div_rem(&g).0)
    } else {
        x
    };
    let degree = x.iter().filter_map(Poly::degree).max().unwrap_or(0);
    (x, degree)
}

/// The kind of double point from the binary quadratic `c₀ + c₁u + c₂u²` vanishing at the
/// parameters of the point: discriminant `c₁² − 4c₀c₂` positive — two real branches
/// (crunode), zero — a cusp, negative — two conjugate branches (acnode).
fn node_kind(c: &Poly<Quadratic>) -> Result<SingularPointKind, Error> {
    if c.is_zero() || c.degree().unwrap_or(0) > 2 {
        return Err(Error::Algebra(format!(
            "PᵀQd(u) = {c}: a ruling on both quadrics, the curve is reducible"
        )));
    }
    let (c0, c1, c2) = (c.coeff(0), c.coeff(1), c.coeff(2));
    let disc = c1
        .mul(&c1)
        .sub(&Quadratic::from_int(&IBig::from(4)).mul(&c0).mul(&c2));
    Ok(match disc.sign() {
        Some(Sign::Positive) => SingularPointKind::Crunode,
        Some(Sign::Zero) => SingularPointKind::Cusp,
        _ => SingularPointKind::Acnode,
    })
}

/// The Segre structure of every root of the pencil, real and complex: block sizes,
/// largest first.
pub(super) fn segre_blocks(analysis: &PencilAnalysis) -> Vec<Vec<u8>> {
    let real = analysis.real_roots.iter().map(|r| r.blocks.clone());
    let mut all: Vec<Vec<u8>> = real.chain(analysis.complex_roots.iter().cloned()).collect();
    all.sort();
    all
}

/// The multiple root of a pencil of Segre type `[211]` or `[31]` (one multiple root, one
/// Jordan block there: its member has rank 3).
fn multiple_root(analysis: &PencilAnalysis) -> Option<&PencilRoot> {
    let blocks = segre_blocks(analysis);
    let shape_ok = blocks == [vec![1], vec![1], vec![2]] || blocks == [vec![1], vec![3]];
    let root = analysis.real_roots.iter().find(|r| r.multiplicity >= 2)?;
    shape_ok.then_some(root)
}

/// The singular point of the intersection of `a` and `b` and the rational parameterization
/// of the curve through it, when the curve is a singular irreducible quartic (cases 5–8,
/// 11: `det(λA − B)` has one multiple root, with one Jordan block).
///
/// # Errors
/// [`Error::Unsupported`] for other Segre types; [`Error::Algebra`] for an internal
/// inconsistency (a vertex off the curve, a ruling on both quadrics) or when a conic's
/// rational point cannot be found within the factoring bounds.
///
/// # Examples
/// ```
/// use qsic::{io::parse_quadric, param::parameterize_singular_quartic};
/// use qsic::classify::SingularPointKind;
/// use qsic_algebra::RBig;
/// // Viviani's curve: a sphere and a cylinder tangent to it, a crunode at (2, 0, 0)
/// let a = parse_quadric("x^2+y^2+z^2-4").unwrap();
/// let b = parse_quadric("(x-1)^2+y^2-1").unwrap();
/// let c = parameterize_singular_quartic(&a, &b).unwrap();
/// assert_eq!(c.kind, SingularPointKind::Crunode);
/// assert_eq!(c.point, [2, 0, 0, 1].map(RBig::from));
/// ```
pub fn parameterize_singular_quartic(a: &Quadric, b: &Quadric) -> Result<SingularQuartic, Error> {
    let analysis = analyze_pencil(a, b)
        .ok_or_else(|| Error::Unsupported("a singular quartic needs a regular pencil".into()))?;
    let root = multiple_root(&analysis).ok_or_else(|| {
        Error::Unsupported("not a singular irreducible quartic (Segre [211] or [31])".into())
    })?;
    let lambda = rational_root(root)?;
    let (am, bm) = (integer_matrix(a), integer_matrix(b));
    let s0 = member(&am, &bm, lambda.as_ref());
    let point = vertex(&s0)?;
    if !form(&am, &point, &point).is_zero() || !form(&bm, &point, &point).is_zero() {
        return Err(Error::Algebra(
            "the cone's vertex is not on the curve".into(),
        ));
    }
    // a second member: A, or B when S₀ = A
    let q = if lambda.is_some() { &am } else { &bm };
    let inertia = root.inertia;
    if inertia.positive == 0 || inertia.negative == 0 {
        // an imaginary cone: its vertex is the only real point (two conjugate branches)
        return Ok(SingularQuartic {
            lambda,
            point,
            kind: SingularPointKind::Acnode,
            x: None,
            delta: None,
        });
    }
    let ruling = parameterize_cone(&s0)?
        .ok_or_else(|| Error::Algebra("no real point found on a real cone".into()))?;
    let qm = to_quadratic(q);
    let p: PolyVector =
        std::array::from_fn(|i| Poly::constant(Quadratic::rational(point[i].clone())));
    let d = &ruling.d;
    let c2 = poly_form(&qm, d, d);
    let c1 = poly_form(&qm, &p, d);
    let kind = node_kind(&c1)?;
    let minus_two_c1 = c1.scale(&Quadratic::from_int(&IBig::from(-2)));
    let x: PolyVector = std::array::from_fn(|i| &(&c2 * &p[i]) + &(&minus_two_c1 * &d[i]));
    let (x, degree) = without_common_factor(x);
    if degree != 4 {
        return Err(Error::Algebra(format!(
            "the singular quartic's parameterization has degree {degree}"
        )));
    }
    Ok(SingularQuartic {
        lambda,
        point,
        kind,
        x: Some(x),
        delta: ruling.delta,
    })
}

/// The rational point `p` as a [`Point`].
pub(super) fn rational_point(p: &[RBig; 4]) -> Point {
    std::array::from_fn(|i| curve::rational(p[i].clone()))
}

/// Checks the real singular points against the class's description (kind and count).
pub(super) fn check_against_class(
    classification: &Classification,
    found: &[curve::SingularPoint],
) -> Result<(), Error> {
    let Some(description) = &classification.description else {
        return Ok(());
    };
    let mut want: Vec<(SingularPointKind, usize)> = description
        .singular_points
        .iter()
        .map(|s| (s.kind, usize::from(s.count)))
        .collect();
    let mut got: Vec<(SingularPointKind, usize)> = Vec::new();
    for s in found {
        match got.iter_mut().find(|(k, _)| *k == s.kind) {
            Some(entry) => entry.1 += 1,
            None => got.push((s.kind, 1)),
        }
    }
    let key = |v: &(SingularPointKind, usize)| (v.0.key(), v.1);
    want.sort_by_key(key);
    got.sort_by_key(key);
    if want == got {
        Ok(())
    } else {
        Err(Error::Algebra(format!(
            "singular points {got:?} where the class has {want:?}"
        )))
    }
}

/// The [`Curve`] of a singular irreducible quartic: one quartic component; its real locus
/// is the image of all of ℝ ∪ {∞} (closed), plus the acnode as an isolated point; only the
/// acnode when the cone is imaginary (case 7: the component is not real).
pub(super) fn singular_quartic_curve(
    classification: Classification,
    a: &Quadric,
    b: &Quadric,
) -> Result<Curve, Error> {
    let sq = parameterize_singular_quartic(a, b)?;
    let point = rational_point(&sq.point);
    let singular_points = vec![curve::SingularPoint {
        kind: sq.kind,
        point: point.clone(),
    }];
    check_against_class(&classification, &singular_points)?;
    let field: Option<NumberField> = sq.delta.as_ref().map(curve::sqrt_field);
    let param = sq.x.as_ref().map(|x| ComponentParam::Rational {
        x: std::array::from_fn(|i| curve::poly_from_quadratic(&x[i], field.as_ref())),
        degree: 4,
    });
    let mut pieces = Vec::new();
    if param.is_some() {
        pieces.push(RealPiece::whole(0));
    }
    if sq.kind == SingularPointKind::Acnode {
        pieces.push(RealPiece::Point {
            component: 0,
            point,
        });
    }
    let connected = (0..pieces.len()).map(|i| vec![i]).collect();
    Ok(Curve {
        classification,
        components: vec![Component {
            kind: ComponentKind::Quartic,
            multiplicity: 1,
            real: param.is_some(),
            param,
            plane: None,
            section: None,
        }],
        singular_points,
        pieces,
        connected,
    })
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::classify::classify;
    use crate::io::parse_quadric;
    use crate::param::parameterize;
    use qsic_algebra::testing::SplitMix;

    /// `Mᵀ(αA + βB)M`, `Mᵀ(γA + δB)M` for a random invertible `M` with entries in `[−3, 3]`
    /// and `αδ ≠ βγ`, and `M⁻¹`: a point `X` of the curve of `A`, `B` is `M⁻¹X` on the new one.
    pub(crate) fn disguise(
        a: &Quadric,
        b: &Quadric,
        rng: &mut SplitMix,
    ) -> (Quadric, Quadric, Matrix<RBig>) {
        let mut small = || RBig::from(rng.int(-3, 3));
        let (m, inverse) = loop {
            let m = Matrix::from_fn(4, 4, |_, _| small());
            if let Some(inv) = m.inverse() {
                break (m, inv);
            }
        };
        let [al, be, ga, de] = loop {
            let c = [small(), small(), small(), small()];
            if &c[0] * &c[3] != &c[1] * &c[2] {
                break c;
            }
        };
        let congruent = |x: &RBig, y: &RBig| {
            let n = |k: usize, l: usize| x * &a.matrix()[k][l] + y * &b.matrix()[k][l];
            let out: [[RBig; 4]; 4] = std::array::from_fn(|i| {
                std::array::from_fn(|j| {
                    let mut acc = RBig::ZERO;
                    for k in 0..4 {
                        for l in 0..4 {
                            acc += &m[(k, i)] * n(k, l) * &m[(l, j)];
                        }
                    }
                    acc
                })
            });
            Quadric::from_matrix(out).unwrap()
        };
        (congruent(&al, &be), congruent(&ga, &de), inverse)
    }

    /// `M·p` as a primitive integer vector.
    pub(crate) fn mapped(m: &Matrix<RBig>, p: &[RBig; 4]) -> [RBig; 4] {
        primitive(&m.mul_vec(p))
    }

    /// `P` is on both quadrics and singular there: `AP` and `BP` proportional.
    fn assert_singular_point(a: &Quadric, b: &Quadric, p: &[RBig; 4]) {
        let (am, bm) = (a.matrix(), b.matrix());
        assert!(
            form(am, p, p).is_zero() && form(bm, p, p).is_zero(),
            "{p:?} off the curve"
        );
        let grad = |m: &[[RBig; 4]; 4]| -> Vec<RBig> {
            (0..4)
                .map(|i| (0..4).fold(RBig::ZERO, |acc, j| acc + &m[i][j] * &p[j]))
                .collect()
        };
        let (ga, gb) = (grad(am), grad(bm));
        for i in 0..4 {
            for j in 0..4 {
                assert!(
                    (&ga[i] * &gb[j] - &ga[j] * &gb[i]).is_zero(),
                    "gradients at {p:?}"
                );
            }
        }
    }

    fn pair(a: &str, b: &str) -> (Quadric, Quadric) {
        (parse_quadric(a).unwrap(), parse_quadric(b).unwrap())
    }

    #[test]
    fn vivianis_curve_crosses_itself_where_sphere_and_cylinder_touch() {
        let (a, b) = pair("x^2+y^2+z^2-4", "(x-1)^2+y^2-1");
        let sq = parameterize_singular_quartic(&a, &b).unwrap();
        assert_eq!(sq.point, [2, 0, 0, 1].map(RBig::from));
        assert_eq!(sq.kind, SingularPointKind::Crunode);
        assert_singular_point(&a, &b, &sq.point);
        let c = parameterize(&a, &b).unwrap();
        assert_eq!(c.classification.case, Some(5));
        let param = c.components[0].param.as_ref().unwrap();
        assert!(param.lies_on(a.matrix()) && param.lies_on(b.matrix()));
        assert_eq!((c.pieces.len(), c.connected.len()), (1, 1));
    }

    /// A cone `x² + y² = z²` and the sphere through its apex with centre `(s, 0, 1)`: the
    /// sphere's tangent plane at the apex, `z = −s·x`, cuts the cone in `y² = (s² − 1)x²`,
    /// the tangent lines of the curve there: two real lines for `s² > 1` (crunode), a
    /// double line for `s² = 1` (cusp), none for `s² < 1` (acnode, plus a real loop).
    #[test]
    fn a_sphere_through_the_apex_of_a_cone_meets_it_in_a_node_or_a_cusp() {
        let cone = parse_quadric("x^2+y^2-z^2").unwrap();
        let cases = [
            ("2", SingularPointKind::Crunode, 5, 1),
            ("1", SingularPointKind::Cusp, 11, 1),
            ("1/2", SingularPointKind::Acnode, 6, 2),
            ("-3/2", SingularPointKind::Crunode, 5, 1),
        ];
        for (s, kind, case, pieces) in cases {
            let sphere = parse_quadric(&format!("x^2+y^2+z^2-2*({s})*x-2*z")).unwrap();
            let sq = parameterize_singular_quartic(&cone, &sphere).unwrap();
            assert_eq!(sq.point, [0, 0, 0, 1].map(RBig::from), "s = {s}");
            assert_eq!(sq.kind, kind, "s = {s}");
            assert_singular_point(&cone, &sphere, &sq.point);
            let c = parameterize(&cone, &sphere).unwrap();
            assert_eq!(c.classification.case, Some(case), "s = {s}");
            assert_eq!(c.pieces.len(), pieces, "s = {s}");
            assert_eq!(c.singular_points[0].kind, kind);
        }
    }

    /// The representatives of cases 5–8 and 11 (cases.md), disguised by random projective
    /// maps and pencil bases: the singular point moves with the map, its kind stays, and
    /// the quartic's parameterization lies on the disguised quadrics.
    #[test]
    fn disguised_singular_quartics_keep_their_singular_point() {
        let representatives = [
            (5, "x^2-y^2+z^2+4*y*w", "-3*x^2+y^2+z^2"),
            (6, "-x^2-z^2+2*y*w", "-3*x^2+y^2-z^2"),
            (7, "x^2+z^2+2*y*w", "3*x^2+y^2+z^2"),
            (8, "x*y+z*w", "2*x*y+y^2-z^2+w^2"),
            (11, "y^2+2*x*z+w^2", "2*y*z+w^2"),
        ];
        let mut rng = SplitMix(0x51_6e_67_75_6c_61_72);
        for (case, a, b) in representatives {
            let (a, b) = pair(a, b);
            assert_eq!(classify(&a, &b).case, Some(case));
            let original = parameterize_singular_quartic(&a, &b).unwrap();
            assert_singular_point(&a, &b, &original.point);
            assert_eq!(original.x.is_none(), case == 7);
            for k in 0..3 {
                let (da, db, inverse) = disguise(&a, &b, &mut rng);
                let tag = format!("case {case}, disguise {k}");
                assert_eq!(classify(&da, &db).case, Some(case), "{tag}");
                let sq = parameterize_singular_quartic(&da, &db).unwrap();
                assert_eq!(sq.point, mapped(&inverse, &original.point), "{tag}");
                assert_eq!(sq.kind, original.kind, "{tag}");
                let c = parameterize(&da, &db).unwrap();
                if let Some(p) = &c.components[0].param {
                    assert!(p.lies_on(da.matrix()) && p.lies_on(db.matrix()), "{tag}");
                }
            }
        }
    }

    /// The binary quadratic `c(u)` (a degree drop is a root at ∞): two real roots, a double
    /// one, a conjugate pair; zero is a ruling on the curve.
    #[test]
    fn node_kinds_from_the_parameters_of_the_node() {
        let c = |v: &[i64]| {
            Poly::new(
                v.iter()
                    .map(|&x| Quadratic::from_int(&IBig::from(x)))
                    .collect(),
            )
        };
        let r2 = Quadratic::sqrt(&IBig::from(2));
        use SingularPointKind::*;
        for (poly, kind) in [
            (c(&[-1, 0, 1]), Crunode),
            (c(&[0, 1]), Crunode), // u = 0 and u = ∞
            (c(&[1, 2, 1]), Cusp),
            (c(&[1]), Cusp), // a double root at ∞
            (c(&[1, 0, 1]), Acnode),
            (
                Poly::new(vec![
                    Quadratic::rational(RBig::ONE),
                    r2.clone(),
                    Quadratic::rational(RBig::ONE),
                ]),
                Acnode,
            ),
            (
                Poly::new(vec![
                    Quadratic::rational(RBig::ONE),
                    r2.scale(&RBig::from(2)),
                    Quadratic::rational(RBig::from(2)),
                ]),
                Cusp,
            ),
        ] {
            assert_eq!(node_kind(&poly).unwrap(), kind, "{poly}");
        }
        assert!(node_kind(&Poly::zero()).is_err());
    }

    /// The class's singular points must be found, with their kinds and counts.
    #[test]
    fn singular_points_are_checked_against_the_class() {
        let (a, b) = pair("x^2+y^2+z^2-4", "(x-1)^2+y^2-1");
        let class = classify(&a, &b);
        let at = |kind| curve::SingularPoint {
            kind,
            point: rational_point(&[2, 0, 0, 1].map(RBig::from)),
        };
        assert!(check_against_class(&class, &[at(SingularPointKind::Crunode)]).is_ok());
        for wrong in [
            vec![],
            vec![at(SingularPointKind::Acnode)],
            vec![
                at(SingularPointKind::Crunode),
                at(SingularPointKind::Crunode),
            ],
        ] {
            assert!(check_against_class(&class, &wrong).is_err());
        }
    }

    #[test]
    fn primitive_vectors_are_integral_coprime_and_positive_first() {
        let r = |n: i64, d: i64| RBig::from(n) / RBig::from(d);
        let v = primitive(&[r(0, 1), r(-2, 3), r(4, 9), r(0, 1)]);
        assert_eq!(v, [0, 3, -2, 0].map(RBig::from));
        assert_eq!(
            primitive(&[r(5, 1), r(0, 1), r(0, 1), r(10, 1)]),
            [1, 0, 0, 2].map(RBig::from)
        );
    }
}
