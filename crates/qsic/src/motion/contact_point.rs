//! The common real points of two moving quadrics at an instant — at the first contact, the
//! points where they touch — exactly.
//!
//! At the first contact `t₀` coming from an empty real intersection, every real common point
//! is a singular point of the intersection curve: a smooth real point of a transversal
//! intersection persists under a small motion (implicit function theorem), so it would be
//! there just before `t₀`. A point `p` is a singular point of the curve of a regular pencil
//! exactly when `p` is on `A` and in the kernel of a member `S = λ₀A − B` (the gradients of
//! `A` and `B` are dependent at `p`), and then `λ₀` is a multiple root of
//! `f(λ) = det(λA − B)` (the curve is singular only where the discriminant of `f` vanishes).
//!
//! - **Rational `t₀`**: the exact curve of `A(t₀)`, `B(t₀)` ([`crate::param::parameterize`]):
//!   its isolated real points, its real singular points, and how many real curve pieces it
//!   has (a touching along a line or a conic, or quadrics that already meet at the start of
//!   a range). Coordinates are in `ℚ` or in the number fields of the parameterization.
//! - **Irrational `t₀ = α`**: in `K = ℚ(α)` (dynamic evaluation, exact): the multiple roots
//!   of `f` over `K` (the square-free part of `gcd(f, f′)`, and `λ = ∞` when `A` itself is
//!   a multiple root), their members' kernels over `K`, and the points of `A` on them (a
//!   kernel vector on `A`; on a kernel line the roots of `A` restricted to it, when they are
//!   in `K`). The points found are accepted only when their number is the one the exact class
//!   at `α` gives; otherwise — several tangency members not split over `K`, points in a
//!   quadratic extension of `K`, a singular pencil at `α` — the answer says what was not
//!   computed ([`CommonLocus::NotComputed`]), never a guess.

use super::instants::squarefree_decomposition_t;
use super::range::{FirstContact, TimeRange};
use super::{contact_point_fast, irrational, MovingPencil};
use crate::classify::{Classification, ComponentKind, SingularPointKind};
use crate::error::Error;
use crate::param::{parameterize_within, Point, RealPiece};
use qsic_algebra::budget::{Budget, Exhausted};
use qsic_algebra::field::number_field::{NumberField, NumberFieldElement as K};
use qsic_algebra::linalg::minors::det;
use qsic_algebra::linalg::Matrix;
use qsic_algebra::{AlgebraicReal, Field, Poly, RBig, Ring, Sign};

/// What a common point is on the intersection curve.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CommonPointKind {
    /// An isolated real point of the intersection (at a touching from an empty intersection,
    /// every common point).
    Isolated,
    /// A real singular point of a real curve of the intersection (a tangency, a crossing…).
    Singular(SingularPointKind),
}

impl CommonPointKind {
    /// `isolated`, or the singular point's key (`tangency`, `crunode`, …).
    pub fn key(self) -> &'static str {
        match self {
            CommonPointKind::Isolated => "isolated",
            CommonPointKind::Singular(k) => k.key(),
        }
    }
}

/// A common real point, exact: homogeneous coordinates `(x, y, z, w)` normalised with
/// `w = 1` for an affine point, else with its first nonzero coordinate 1.
#[derive(Clone, Debug)]
pub struct CommonPoint {
    /// What it is on the curve.
    pub kind: CommonPointKind,
    /// The point.
    pub point: Point,
}

impl CommonPoint {
    /// Its affine coordinates `(x, y, z)` in floating point (for display), `None` at
    /// infinity.
    pub fn approx(&self) -> Option<[f64; 3]> {
        (!self.point[3].is_zero()).then(|| std::array::from_fn(|i| self.point[i].to_f64()))
    }
}

/// The real common locus of `A(t₀)` and `B(t₀)`.
#[derive(Clone, Debug)]
pub enum CommonLocus {
    /// The isolated real points and the real singular points of the real curves, and how
    /// many real curve pieces there are (0 at a touching from an empty intersection: then
    /// the points are all the common points).
    Points {
        /// The points.
        points: Vec<CommonPoint>,
        /// The number of real curve pieces (connected pieces of real curves).
        curves: usize,
    },
    /// `A(t₀) = B(t₀)` up to a factor: the whole quadric is common.
    SameQuadric,
    /// Not computed in this version (says why): never a guess.
    NotComputed(String),
}

/// The first contact with its common points.
#[derive(Clone, Debug)]
pub struct ContactPoints {
    /// The instant.
    pub t: AlgebraicReal,
    /// The quadrics already meet at the start of the range (`t` is the range's start).
    pub at_start: bool,
    /// The common real points at `t`.
    pub locus: CommonLocus,
}

/// The common real points of `A(t)` and `B(t)` at the instant `t` (module docs).
///
/// # Errors
/// As [`crate::classify()`] at a rational `t`; none otherwise in practice (a curve that
/// cannot be parameterized is [`CommonLocus::NotComputed`]).
///
/// # Examples
/// ```
/// use qsic::io::moving_matrix_from_polynomial as moving;
/// use qsic::motion::contact::{common_points_at, CommonLocus};
/// use qsic::motion::MovingPencil;
/// use qsic_algebra::{AlgebraicReal, RBig};
///
/// // a unit sphere along the x axis touches the sphere of radius 2 at t = 3, at (2, 0, 0)
/// let a = moving("x^2 + y^2 + z^2 - 4")?;
/// let b = moving("(x - t)^2 + y^2 + z^2 - 1")?;
/// let pencil = MovingPencil::new(a, b)?;
/// let CommonLocus::Points { points, curves: 0 } =
///     common_points_at(&pencil, &AlgebraicReal::from_rational(RBig::from(3)))?
/// else {
///     panic!("one point")
/// };
/// assert_eq!(points.len(), 1);
/// assert_eq!(points[0].approx(), Some([2.0, 0.0, 0.0]));
/// # Ok::<(), qsic::Error>(())
/// ```
pub fn common_points_at(pencil: &MovingPencil, t: &AlgebraicReal) -> Result<CommonLocus, Error> {
    common_points_at_within(pencil, t, &Budget::unlimited())
}

/// [`common_points_at`] spending `budget`: at a rational `t` the curve
/// ([`crate::param::parameterize_within`]), at an irrational one the classification at `α`
/// and the kernels over `ℚ(α)` (their products charged up front).
///
/// # Errors
/// As [`common_points_at`]; [`Error::BudgetExceeded`] when the budget runs out.
pub fn common_points_at_within(
    pencil: &MovingPencil,
    t: &AlgebraicReal,
    budget: &Budget,
) -> Result<CommonLocus, Error> {
    match t.as_rational() {
        Some(v) => common_points_at_rational(pencil, v, budget),
        None => Ok(common_points_at_irrational(pencil, t, budget)?),
    }
}

/// The first contact `first` in `range` with its common points: `None` when the quadrics
/// meet from `t = −∞` on (no first instant).
///
/// # Errors
/// As [`common_points_at`].
pub fn contact_points(
    pencil: &MovingPencil,
    first: &FirstContact,
    range: &TimeRange,
) -> Result<Option<ContactPoints>, Error> {
    contact_points_within(pencil, first, range, &Budget::unlimited())
}

/// [`contact_points`] spending `budget` ([`common_points_at_within`]).
///
/// # Errors
/// As [`common_points_at_within`].
pub fn contact_points_within(
    pencil: &MovingPencil,
    first: &FirstContact,
    range: &TimeRange,
    budget: &Budget,
) -> Result<Option<ContactPoints>, Error> {
    let FirstContact::At(t) = first else {
        return Ok(None);
    };
    let at_start = range.from().is_some_and(|s| t.as_rational() == Some(s));
    Ok(Some(ContactPoints {
        t: t.clone(),
        at_start,
        locus: common_points_at_within(pencil, t, budget)?,
    }))
}

fn common_points_at_rational(
    pencil: &MovingPencil,
    t: &RBig,
    budget: &Budget,
) -> Result<CommonLocus, Error> {
    let (a, b) = (pencil.a().quadric_at(t)?, pencil.b().quadric_at(t)?);
    if a.integer_matrix().is_proportional(b.integer_matrix()) {
        return Ok(CommonLocus::SameQuadric);
    }
    let curve = match parameterize_within(&a, &b, budget) {
        Ok(c) => c,
        Err(Error::Unsupported(why)) | Err(Error::Algebra(why)) => {
            return Ok(CommonLocus::NotComputed(format!(
                "the curve at t = {t} is not parameterized: {why}"
            )))
        }
        Err(e) => return Err(e),
    };
    let mut points: Vec<CommonPoint> = Vec::new();
    let mut curves = 0;
    for piece in &curve.pieces {
        match piece {
            RealPiece::Point { point, .. } => points.push(CommonPoint {
                kind: CommonPointKind::Isolated,
                point: normalized(point),
            }),
            RealPiece::Curve { .. } => curves += 1,
        }
    }
    for s in &curve.singular_points {
        let point = normalized(&s.point);
        // an acnode is an isolated point, listed once
        if !points.iter().any(|p| same_point(&p.point, &point)) {
            points.push(CommonPoint {
                kind: CommonPointKind::Singular(s.kind),
                point,
            });
        }
    }
    Ok(CommonLocus::Points { points, curves })
}

/// `p` scaled to `w = 1`, or to a first nonzero coordinate 1 at infinity.
fn normalized(p: &Point) -> Point {
    let Some(k) = [3, 0, 1, 2].into_iter().find(|&i| !p[i].is_zero()) else {
        return p.clone();
    };
    let inv = p[k].inv().expect("a nonzero coordinate");
    std::array::from_fn(|i| p[i].mul(&inv))
}

/// Whether two normalized points are equal (points over two separately made fields are
/// taken as distinct: the producers of one curve share their fields).
fn same_point(p: &Point, q: &Point) -> bool {
    (0..4).all(|i| p[i].compatible_with(&q[i]) && p[i].sub(&q[i]).is_zero())
}

/// A 4×4 matrix over `K`.
type Matrix4 = [[K; 4]; 4];

/// `xᵀMy` over `K`.
fn form(m: &[[K; 4]; 4], x: &[K], y: &[K]) -> K {
    let mut acc = K::zero();
    for i in 0..4 {
        for j in 0..4 {
            if !m[i][j].is_zero() {
                acc = acc.add(&m[i][j].mul(&x[i]).mul(&y[j]));
            }
        }
    }
    acc
}

/// Products in `K` charged for the kernels and points over `K` at an irrational instant (the
/// determinant and gcds of degree 4, a few kernels of 4×4 members, the points on them).
const POINT_PRODUCTS: usize = 3_000;

fn common_points_at_irrational(
    pencil: &MovingPencil,
    alpha: &AlgebraicReal,
    budget: &Budget,
) -> Result<CommonLocus, Exhausted> {
    irrational::Spend::new(budget, alpha).products(POINT_PRODUCTS)?;
    let field = NumberField::new(alpha);
    let at = |m: &[[Poly; 4]; 4]| -> [[K; 4]; 4] {
        std::array::from_fn(|i| std::array::from_fn(|j| field.integer_element(&m[i][j])))
    };
    let (ma, mb) = pencil.numerators();
    let (a, b) = (at(ma), at(mb));
    let (va, vb): (Vec<&K>, Vec<&K>) = (a.iter().flatten().collect(), b.iter().flatten().collect());
    let proportional =
        (0..16).all(|i| (i + 1..16).all(|j| va[i].mul(vb[j]).sub(&va[j].mul(vb[i])).is_zero()));
    if proportional {
        return Ok(CommonLocus::SameQuadric);
    }
    let not_computed = |why: &str| {
        CommonLocus::NotComputed(format!(
            "{why} at the irrational instant t ≈ {:.12}",
            alpha.to_f64()
        ))
    };
    let Some(class) = pencil.classify_at_irrational(alpha, budget)? else {
        return Ok(not_computed("the class is not computed"));
    };
    // the one dispatch point: the accelerator where `f(λ; α)` has one double root, else
    // the reference
    let members = match contact_point_fast::double_root(pencil, alpha, &field, budget)? {
        Some(l0) => vec![(member(&a, &b, &l0), &a)],
        None => {
            let factors_t = squarefree_decomposition_t(pencil.characteristic(), budget)?;
            match tangency_members(&a, &b, &factors_t, &field) {
                Ok(members) => members,
                Err(why) => return Ok(not_computed(why)),
            }
        }
    };
    match points_on_members(&members) {
        Ok(points) => Ok(locus_of(&class, &points, not_computed)),
        Err(why) => Ok(not_computed(why)),
    }
}

/// `λ₀A − B` over `K`.
fn member(a: &Matrix4, b: &Matrix4, l0: &K) -> Matrix4 {
    std::array::from_fn(|i| std::array::from_fn(|j| l0.mul(&a[i][j]).sub(&b[i][j])))
}

/// The tangency members of the pencil at `α`, each with the quadric its kernel is met with:
/// `λ₀A − B` (with `A`) at each finite multiple root `λ₀` of `f(λ; α)` over `K`, and `A`
/// (with `B`) when `λ = ∞` is one; from `A(α)`, `B(α)` over `K` and the square-free
/// factors of `f` over `ℚ(t)`. `Err` says what is not computed.
fn tangency_members<'m>(
    a: &'m Matrix4,
    b: &'m Matrix4,
    factors_t: &[(super::instants::TPoly, usize)],
    field: &NumberField,
) -> Result<Vec<(Matrix4, &'m Matrix4)>, &'static str> {
    // f(λ) = det(λA − B) over K
    let pencil_entry = |i: usize, j: usize| Poly::new(vec![b[i][j].neg(), a[i][j].clone()]);
    let lambda_a_minus_b: [[Poly<K>; 4]; 4] =
        std::array::from_fn(|i| std::array::from_fn(|j| pencil_entry(i, j)));
    let f = det(&lambda_a_minus_b);
    if f.is_zero() {
        return Err("a singular pencil");
    }
    // the finite multiple roots, split by the square-free factors of f over ℚ(t) at α
    let multiple = f.gcd_monic(&f.derivative()).squarefree_part_field();
    let factors: Vec<Poly<K>> = factors_t
        .iter()
        .map(|(g, _)| g.map(|c| field.integer_element(c)))
        .collect();
    let mut members: Vec<(Matrix4, &Matrix4)> = Vec::new();
    for piece in split_by(&multiple, &factors) {
        if piece.degree() != Some(1) {
            return Err("tangency members of the pencil not split over ℚ(t)");
        }
        let l0 = piece.coeff(0).neg().div(&piece.coeff(1)).expect("degree 1");
        members.push((member(a, b, &l0), a));
    }
    if f.degree().unwrap_or(0) + 2 <= 4 {
        // λ = ∞ is a multiple root: the member A, its kernel met with B
        members.push((a.clone(), b));
    }
    Ok(members)
}

/// The real common points on the tangency members: a kernel vector on the other quadric,
/// or the double root of that quadric on a kernel line. `Err` says what is not computed.
fn points_on_members(members: &[(Matrix4, &Matrix4)]) -> Result<Vec<Point>, &'static str> {
    let not_computed = |why: &'static str| Err(why);
    let mut points: Vec<Point> = Vec::new();
    for (s, q) in members {
        let kernel = Matrix::from_array(s.clone()).kernel();
        match kernel.as_slice() {
            [v] => {
                if form(q, v, v).is_zero() {
                    points.push(std::array::from_fn(|i| v[i].clone()));
                }
            }
            [k1, k2] => {
                let (qa, qb, qc) = (form(q, k1, k1), form(q, k1, k2), form(q, k2, k2));
                if qa.is_zero() && qb.is_zero() && qc.is_zero() {
                    continue; // a common line: a curve, its points are not isolated
                }
                let disc = qb.mul(&qb).sub(&qa.mul(&qc));
                match disc.sign() {
                    Sign::Negative => {}
                    Sign::Zero => {
                        // q(s·k1 + u·k2) = qa·(s + qb·u/qa)²: s = −qb, u = qa (k1 if qa = 0)
                        let p: Vec<K> = if qa.is_zero() {
                            k1.clone()
                        } else {
                            (0..4)
                                .map(|i| k2[i].mul(&qa).sub(&k1[i].mul(&qb)))
                                .collect()
                        };
                        points.push(std::array::from_fn(|i| p[i].clone()));
                    }
                    Sign::Positive => {
                        return not_computed("two common points in a quadratic extension")
                    }
                }
            }
            _ => return not_computed("a member of rank 2 or less"),
        }
    }
    Ok(points)
}

/// The locus at `α` from the tangency points found, accepted only when their number is the
/// one the class gives.
fn locus_of(
    class: &Classification,
    points: &[Point],
    not_computed: impl Fn(&str) -> CommonLocus,
) -> CommonLocus {
    let Some(d) = &class.description else {
        return not_computed("the class has no description");
    };
    let count = |kinds: &dyn Fn(ComponentKind) -> bool| -> usize {
        d.components
            .iter()
            .filter(|c| kinds(c.kind))
            .map(|c| usize::from(c.count))
            .sum()
    };
    let isolated = count(&|k| k == ComponentKind::Point);
    let curves = count(&|k| !matches!(k, ComponentKind::Point));
    let singular: usize = d.singular_points.iter().map(|s| usize::from(s.count)).sum();
    let kind = match (curves, d.singular_points.as_slice()) {
        (0, _) if points.len() == isolated => CommonPointKind::Isolated,
        (_, [s]) if isolated == 0 && points.len() == singular => CommonPointKind::Singular(s.kind),
        _ => return not_computed(&mismatch(class, points.len())),
    };
    let points = points
        .iter()
        .map(|p| CommonPoint {
            kind,
            point: normalized(p),
        })
        .collect();
    CommonLocus::Points { points, curves }
}

/// A gcd-free basis over `K` of the factors of the square-free `h` cut out by its gcds with
/// each of `factors` (every root of `h` is a root of one of them): pairwise coprime monic
/// pieces of positive degree whose product is `h`.
fn split_by(h: &Poly<K>, factors: &[Poly<K>]) -> Vec<Poly<K>> {
    if h.degree().unwrap_or(0) == 0 {
        return Vec::new();
    }
    let mut basis: Vec<Poly<K>> = vec![h.monic()];
    for f in factors {
        let mut next = Vec::with_capacity(basis.len() + 1);
        for b in basis {
            let g = b.gcd_monic(f);
            let rest = b.div_rem(&g).0;
            for p in [g, rest] {
                if p.degree().unwrap_or(0) > 0 {
                    next.push(p.monic());
                }
            }
        }
        basis = next;
    }
    basis
}

fn mismatch(class: &Classification, found: usize) -> String {
    format!(
        "{found} point(s) found on the tangency members where the class ({}) has others",
        class.real_type().unwrap_or("?")
    )
}

/// The rational `v` as a [`crate::param::Number`].
#[cfg(test)]
fn number(v: RBig) -> crate::param::Number {
    crate::param::Number::rational(v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::moving_matrix_from_polynomial as moving;

    fn locus(a: &str, b: &str, t: &AlgebraicReal) -> CommonLocus {
        let p = MovingPencil::new(moving(a).unwrap(), moving(b).unwrap()).unwrap();
        common_points_at(&p, t).unwrap()
    }

    fn points(l: &CommonLocus) -> (Vec<[f64; 3]>, usize) {
        match l {
            CommonLocus::Points { points, curves } => (
                points.iter().map(|p| p.approx().expect("affine")).collect(),
                *curves,
            ),
            other => panic!("{other:?}"),
        }
    }

    /// The accelerator's double root gives the reference's one tangency member, at every
    /// irrational candidate instant of several motions where it answers (ellipsoids
    /// translated, turned by Cayley's rotation, on a screw; quadrics of other kinds), and
    /// it answers at most of them.
    #[test]
    fn fast_double_root_is_the_reference_member() {
        let motions = [
            ("x^2 + y^2 + z^2 - 4", "(x - t)^2 + (y - 1/2)^2 + z^2 - 1"),
            (
                "x^2/4 + y^2 + z^2/9 - 1",
                "(x - 2*t + 6)^2 + (y - t)^2/4 + (z - 1)^2 - 1",
            ),
            (
                "(1 + t^2)^2*(x^2 + y^2/4 + z^2) - (1 + t^2)^2",
                "(x - 2)^2 + (y - t)^2 + z^2 - 1/4",
            ),
            (
                "x^2 + 2*y^2 + 3*z^2 - 1",
                "(x - t)^2 + (y - t^2)^2 - z^2 - 1/2",
            ),
            (
                "x^2 + y^2 - z^2 - 1",
                "(x - 1)^2 + y^2/3 + (z - t)^2/2 - t^2 - 1",
            ),
        ];
        let unlimited = Budget::unlimited();
        let (mut answered, mut instants) = (0, 0);
        for (ta, tb) in motions {
            let p = MovingPencil::new(moving(ta).unwrap(), moving(tb).unwrap()).unwrap();
            let factors_t = squarefree_decomposition_t(p.characteristic(), &unlimited).unwrap();
            for alpha in p.candidate_instants().unwrap() {
                if alpha.as_rational().is_some() {
                    continue;
                }
                instants += 1;
                let field = NumberField::new(&alpha);
                let at = |m: &[[Poly; 4]; 4]| -> Matrix4 {
                    std::array::from_fn(|i| {
                        std::array::from_fn(|j| field.integer_element(&m[i][j]))
                    })
                };
                let (a, b) = (at(p.numerators().0), at(p.numerators().1));
                let Some(l0) =
                    contact_point_fast::double_root(&p, &alpha, &field, &unlimited).unwrap()
                else {
                    continue;
                };
                answered += 1;
                let members = tangency_members(&a, &b, &factors_t, &field).unwrap();
                assert_eq!(members.len(), 1, "{ta} | {tb} at {alpha}");
                assert_eq!(members[0].0, member(&a, &b, &l0), "{ta} | {tb} at {alpha}");
            }
        }
        assert!(
            answered >= 8 && 2 * answered >= instants,
            "{answered} of {instants}"
        );
    }

    /// Two spheres of radii 1 and 2 along a line through (0, 1/2, 0): they touch at
    /// `t = ±√(9 − 1/4)` (outside) and `t = ±√(1 − 1/4)` (inside), at the point of the line
    /// of centres, `2/3·(t, 1/2)`... computed exactly in `ℚ(√35)` and `ℚ(√3)`.
    #[test]
    fn spheres_touch_at_irrational_instants_at_exact_points() {
        let (a, b) = ("x^2 + y^2 + z^2 - 4", "(x - t)^2 + (y - 1/2)^2 + z^2 - 1");
        // |c| = 3 with c = (t, 1/2): t² = 35/4; the point is 2c/|c| = (2t/3, 1/3, 0)
        let roots = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-35, 0, 4]));
        let l = locus(a, b, &roots[1]);
        let (p, curves) = points(&l);
        assert_eq!(curves, 0);
        assert_eq!(p.len(), 1);
        let t = 35f64.sqrt() / 2.0;
        assert!((p[0][0] - 2.0 * t / 3.0).abs() < 1e-12 && (p[0][1] - 1.0 / 3.0).abs() < 1e-12);
        let CommonLocus::Points { points: exact, .. } = &l else {
            unreachable!()
        };
        // exactly y = 1/3, z = 0, w = 1, and x² = (2t/3)² = 35/9
        let pt = &exact[0].point;
        assert_eq!(pt[1], number(RBig::from_parts(1.into(), 3u8.into())));
        assert!(pt[2].is_zero() && pt[3] == number(RBig::ONE));
        assert_eq!(
            pt[0].mul(&pt[0]),
            number(RBig::from_parts(35.into(), 9u8.into()))
        );
        assert_eq!(exact[0].kind, CommonPointKind::Isolated);
        // inside: |c| = 1, t² = 3/4, the point 2c = (2t, 1, 0)
        let roots = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-3, 0, 4]));
        let (p, _) = points(&locus(a, b, &roots[0]));
        assert_eq!(p.len(), 1);
        assert!((p[0][0] + 3f64.sqrt()).abs() < 1e-12 && (p[0][1] - 1.0).abs() < 1e-12);
    }

    /// At a rational touching the parameterization gives the point; along a line of
    /// cylinders the common locus is a curve; equal quadrics are named.
    #[test]
    fn rational_instants_points_curves_and_equal_quadrics() {
        let three = AlgebraicReal::from_rational(RBig::from(3));
        let (p, c) = points(&locus(
            "x^2 + y^2 + z^2 - 4",
            "(x - t)^2 + y^2 + z^2 - 1",
            &three,
        ));
        assert_eq!((p, c), (vec![[2.0, 0.0, 0.0]], 0));
        // parallel cylinders of radius 1 at distance t touch along a line at t = 2
        let two = AlgebraicReal::from_rational(RBig::from(2));
        match locus("x^2 + y^2 - 1", "(x - t)^2 + y^2 - 1", &two) {
            CommonLocus::Points { curves, .. } => assert!(curves >= 1, "{curves}"),
            other => panic!("{other:?}"),
        }
        let one = AlgebraicReal::from_rational(RBig::ONE);
        assert!(matches!(
            locus("x^2 + y^2 + z^2 - 1", "x^2 + y^2 + z^2 - t^2", &one),
            CommonLocus::SameQuadric
        ));
        // irrational: t² = 2, the same sphere
        let root2 = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 1]))[1].clone();
        assert!(matches!(
            locus("x^2 + y^2 + z^2 - 2", "x^2 + y^2 + z^2 - t^2", &root2),
            CommonLocus::SameQuadric
        ));
    }
}
