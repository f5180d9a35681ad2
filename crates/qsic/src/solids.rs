//! The relation of two solid ellipsoids: separated, touching externally, overlapping, one
//! inside the other (touching internally or not), or equal — exactly.
//!
//! An ellipsoid `XᵀAX = 0` is scaled so that its quadratic part in `x, y, z` (the upper-left
//! 3×3 block) is positive definite; its solid is then `XᵀAX ≤ 0` (`w = 1`), and it is a real
//! ellipsoid exactly when `det A < 0` (inertia (3, 1)). With both matrices so scaled, the
//! members `λA − B` of the pencil carry the relation (Wang, Wang, Kim, CAGD 2001, in this
//! sign convention; the S-lemma for the inner cases):
//! - `λ < 0`: `λA − B = −(|λ|A + B)`, a negated positive combination. The solids are
//!   **separated** iff some member there is negative definite (then `|λ|XᵀAX + XᵀBX > 0`
//!   everywhere: no common point), i.e. `f(λ) = det(λA − B)` has two distinct negative roots;
//!   their interiors are disjoint iff some member there is semidefinite, which (its upper
//!   block being definite) happens only at a root: **touching externally** iff there is a
//!   negative root but no definite arc.
//! - `λ > 0`: `A ⊆ B` iff some `λA − B` is positive semidefinite (S-lemma), `A` lies in the
//!   interior of `B` iff some member is positive definite (an arc of inertia (4, 0)); the
//!   set of such `λ` is an interval, and when it is a single root `λ₀` the kernel of the
//!   member holds a real common point of both surfaces (**touching internally**). Negative
//!   (semi)definite members there put `B` inside `A`.
//! - Otherwise the interiors meet and neither solid contains the other: **overlapping**.
//!
//! Everything is read from the real roots of `f` and the inertia of the members on the arcs
//! between them and at the roots ([`crate::pencil::PencilAnalysis`]): exact, no floats. The
//! same decision runs over `ℚ(α)` for moving ellipsoids at irrational instants
//! ([`crate::motion::contact`]).

use crate::error::Error;
use crate::pencil::PencilPoint;
use crate::quadric::Quadric;
use qsic_algebra::linalg::minors::det;
use qsic_algebra::matrix::Inertia;
use qsic_algebra::{Poly, RBig, Ring, Sign};
use std::fmt;

/// One of the two solids of a pair.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Solid {
    /// The first one.
    A,
    /// The second one.
    B,
}

impl Solid {
    /// `"A"` or `"B"`.
    pub fn key(self) -> &'static str {
        match self {
            Solid::A => "A",
            Solid::B => "B",
        }
    }
}

/// How two solid ellipsoids lie relative to each other.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SolidRelation {
    /// No common point.
    Separated,
    /// Common boundary points only (one point for ellipsoids), interiors disjoint.
    TouchingExternally,
    /// The interiors meet and neither solid contains the other.
    Overlapping,
    /// `inner` lies in the interior of the other solid.
    Inside {
        /// The inner solid.
        inner: Solid,
    },
    /// `inner` lies in the other solid and their boundaries meet (a point or a curve).
    TouchingInternally {
        /// The inner solid.
        inner: Solid,
    },
    /// The same solid.
    Equal,
}

impl SolidRelation {
    /// The stable key: `separated`, `touching_externally`, `overlapping`, `inside`,
    /// `touching_internally`, `equal`.
    pub fn key(self) -> &'static str {
        match self {
            SolidRelation::Separated => "separated",
            SolidRelation::TouchingExternally => "touching_externally",
            SolidRelation::Overlapping => "overlapping",
            SolidRelation::Inside { .. } => "inside",
            SolidRelation::TouchingInternally { .. } => "touching_internally",
            SolidRelation::Equal => "equal",
        }
    }

    /// The inner solid of `inside` and `touching_internally`.
    pub fn inner(self) -> Option<Solid> {
        match self {
            SolidRelation::Inside { inner } | SolidRelation::TouchingInternally { inner } => {
                Some(inner)
            }
            _ => None,
        }
    }

    /// Whether the two closed solids share a point.
    pub fn solids_meet(self) -> bool {
        self != SolidRelation::Separated
    }

    /// The relation with `A` and `B` exchanged.
    pub fn swapped(self) -> SolidRelation {
        let other = |s: Solid| match s {
            Solid::A => Solid::B,
            Solid::B => Solid::A,
        };
        match self {
            SolidRelation::Inside { inner } => SolidRelation::Inside {
                inner: other(inner),
            },
            SolidRelation::TouchingInternally { inner } => SolidRelation::TouchingInternally {
                inner: other(inner),
            },
            r => r,
        }
    }
}

impl fmt::Display for SolidRelation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.inner() {
            Some(inner) => write!(f, "{} ({} inner)", self.key(), inner.key()),
            None => f.write_str(self.key()),
        }
    }
}

/// The relation of the solids bounded by two ellipsoids (spheres included), exactly.
///
/// # Errors
/// [`Error::NotEllipsoid`] naming the quadric (`A` or `B`) that is not a real ellipsoid, and
/// what it is instead (imaginary, a point, an elliptic paraboloid — not handled yet —, or
/// unbounded), decided exactly from the signs of the leading principal minors.
///
/// # Examples
/// ```
/// use qsic::io::parse_quadric;
/// use qsic::solids::{solid_relation, Solid, SolidRelation};
/// let big = parse_quadric("x^2 + y^2 + z^2 - 4")?;
/// let unit = |c: &str| parse_quadric(&format!("(x - {c})^2 + y^2 + z^2 - 1"));
/// assert_eq!(solid_relation(&big, &unit("3")?)?, SolidRelation::TouchingExternally);
/// assert_eq!(
///     solid_relation(&big, &unit("1")?)?,
///     SolidRelation::TouchingInternally { inner: Solid::B }
/// );
/// assert!(solid_relation(&big, &parse_quadric("x^2 + y^2 - 1")?).is_err()); // a cylinder
/// # Ok::<(), qsic::Error>(())
/// ```
pub fn solid_relation(a: &Quadric, b: &Quadric) -> Result<SolidRelation, Error> {
    solid_relation_within(a, b, &crate::Budget::unlimited())
}

/// [`solid_relation`] spending `budget` on the pencil's analysis.
///
/// # Errors
/// As [`solid_relation`]; [`Error::BudgetExceeded`] when the budget runs out.
pub fn solid_relation_within(
    a: &Quadric,
    b: &Quadric,
    budget: &crate::Budget,
) -> Result<SolidRelation, Error> {
    if let Some(r) = spheres_relation(a, b) {
        return Ok(r);
    }
    solid_relation_by_pencil(a, b, budget)
}

/// [`solid_relation_within`] from the pencil alone, for any two ellipsoids: the reference
/// of [`spheres_relation`].
pub(crate) fn solid_relation_by_pencil(
    a: &Quadric,
    b: &Quadric,
    budget: &crate::Budget,
) -> Result<SolidRelation, Error> {
    let negate_a = ellipsoid_orientation(minor_signs(a)).map_err(|e| not_ellipsoid("A", e))?;
    let negate_b = ellipsoid_orientation(minor_signs(b)).map_err(|e| not_ellipsoid("B", e))?;
    if a.integer_matrix().is_proportional(b.integer_matrix()) {
        return Ok(SolidRelation::Equal);
    }
    let oriented = |q: &Quadric, negate: bool| -> Result<Quadric, Error> {
        if negate {
            Quadric::from_matrix(q.matrix().clone().map(|row| row.map(|v| -v)))
        } else {
            Ok(q.clone())
        }
    };
    let (qa, qb) = (oriented(a, negate_a)?, oriented(b, negate_b)?);
    // Both nonsingular and not proportional: det(λA − B) has degree 4, a regular pencil.
    let analysis = crate::classify::analyze_pencil_within(&qa, &qb, budget)?
        .ok_or_else(|| Error::Algebra("two ellipsoids span a regular pencil".into()))?;
    let x = Poly::x();
    let mut roots = Vec::with_capacity(analysis.real_roots.len());
    for r in &analysis.real_roots {
        match &r.point {
            PencilPoint::Finite(v) => roots.push((v.sign_of(&x), r.inertia)),
            PencilPoint::Infinity => {
                return Err(Error::Algebra("an ellipsoid's matrix is singular".into()))
            }
        }
    }
    let arcs = analysis
        .arcs
        .iter()
        .map(|(s, i)| (Sign::of_rational(s), *i))
        .collect();
    Ok(relation_from_signs(&PencilSigns { arcs, roots }))
}

/// The relation of two spheres `|x − cᵢ|² = sᵢ` (recognized by [`crate::natural::recognize`])
/// from `d² = |c₁ − c₂|²`, exactly, with no square root: with `e = d² − s₁ − s₂` and
/// `D = e² − 4s₁s₂ = (d² − (r₁ + r₂)²)(d² − (r₁ − r₂)²)`, the centres are farther apart than
/// `r₁ + r₂` or nearer than `|r₁ − r₂|` iff `D > 0` (then `e > 0` separates them: `d² >
/// (r₁ + r₂)² > s₁ + s₂`, while `d² < (r₁ − r₂)² < s₁ + s₂`), at one of those distances iff
/// `D = 0`, between them (overlapping) iff `D < 0`. `D = 0` with `e < 0` and equal radii
/// would put the centres together: the same sphere, answered before. The inner sphere is
/// the one of smaller `sᵢ`. `None` unless both are spheres.
fn spheres_relation(a: &Quadric, b: &Quadric) -> Option<SolidRelation> {
    use crate::natural::{recognize, NaturalQuadric};
    let (
        NaturalQuadric::Sphere { centre: c1, r2: s1 },
        NaturalQuadric::Sphere { centre: c2, r2: s2 },
    ) = (recognize(a)?, recognize(b)?)
    else {
        return None;
    };
    if c1 == c2 && s1 == s2 {
        return Some(SolidRelation::Equal);
    }
    let d2 = (0..3).fold(RBig::ZERO, |acc, i| {
        let t = &c1[i] - &c2[i];
        acc + &t * &t
    });
    let e = &d2 - &s1 - &s2;
    let disc = &e * &e - RBig::from(4) * &s1 * &s2;
    let inner = if s1 < s2 { Solid::A } else { Solid::B };
    Some(match (Sign::of_rational(&disc), Sign::of_rational(&e)) {
        (Sign::Positive, Sign::Positive) => SolidRelation::Separated,
        (Sign::Positive, _) => SolidRelation::Inside { inner },
        (Sign::Zero, Sign::Positive) => SolidRelation::TouchingExternally,
        (Sign::Zero, _) => SolidRelation::TouchingInternally { inner },
        (Sign::Negative, _) => SolidRelation::Overlapping,
    })
}

fn not_ellipsoid(which: &str, what: &str) -> Error {
    Error::NotEllipsoid(format!("{which} is {what}"))
}

/// The signs of the leading principal minors of a quadric's integer matrix.
fn minor_signs(q: &Quadric) -> [Sign; 4] {
    leading_minors(q.integer_matrix().entries()).map(|m| Sign::of(&m))
}

/// The leading principal minors `m₁, m₂, m₃` of the upper-left 3×3 block and `m₄ = det`.
pub(crate) fn leading_minors<R: Ring>(m: &[[R; 4]; 4]) -> [R; 4] {
    let block = |n: usize| -> R {
        match n {
            1 => m[0][0].clone(),
            2 => det(&[
                [m[0][0].clone(), m[0][1].clone()],
                [m[1][0].clone(), m[1][1].clone()],
            ]),
            3 => det(&std::array::from_fn::<[R; 3], 3, _>(|i| {
                std::array::from_fn(|j| m[i][j].clone())
            })),
            _ => det(m),
        }
    };
    [block(1), block(2), block(3), block(4)]
}

/// Whether a quadric with these leading principal minor signs bounds a solid ellipsoid, and
/// if so whether its matrix must be negated to make the 3×3 block positive definite
/// (Sylvester's criterion on the block; then `det < 0`). `Err` says what it is instead.
pub(crate) fn ellipsoid_orientation(s: [Sign; 4]) -> Result<bool, &'static str> {
    use Sign::{Negative as N, Positive as P, Zero as Z};
    let negate = match (s[0], s[1], s[2]) {
        (P, P, P) => false,
        (N, P, N) => true,
        // a singular block of a nonsingular matrix of inertia (3, 1): semidefinite of rank 2
        (_, _, Z) if s[3] == N => return Err("an elliptic paraboloid (not handled yet)"),
        _ => return Err("not bounded (its quadratic part in x, y, z is not definite)"),
    };
    match s[3] {
        N => Ok(negate),
        Z => Err("a single real point (a degenerate ellipsoid)"),
        P => Err("an imaginary ellipsoid (no real point)"),
    }
}

/// Where the members of `λA − B` are (semi)definite, for two ellipsoids whose matrices have
/// positive definite 3×3 blocks and a regular pencil without roots at `0` or `∞`.
#[derive(Clone, Debug)]
pub(crate) struct PencilSigns {
    /// Each arc between consecutive real roots: the side of `0` of a sample, and the inertia.
    pub arcs: Vec<(Sign, Inertia)>,
    /// Each real root: its sign and the inertia of its member.
    pub roots: Vec<(Sign, Inertia)>,
}

/// The relation read from the pencil (module docs). The arc through `λ = 0` has the
/// inertia (1, 3) of `−B` and the ones through `∞` that of `±A`: only definite arcs, which
/// lie on one side of `0`, and semidefinite roots decide.
pub(crate) fn relation_from_signs(p: &PencilSigns) -> SolidRelation {
    let definite = |i: &Inertia, positive: bool| {
        i.zero == 0
            && if positive {
                i.negative == 0
            } else {
                i.positive == 0
            }
    };
    let semidefinite = |i: &Inertia, positive: bool| {
        if positive {
            i.negative == 0
        } else {
            i.positive == 0
        }
    };
    let arc = |side: Sign, positive: bool| {
        p.arcs
            .iter()
            .any(|(s, i)| *s == side && definite(i, positive))
    };
    let root = |side: Sign, positive: bool| {
        p.roots
            .iter()
            .any(|(s, i)| *s == side && semidefinite(i, positive))
    };
    use Sign::{Negative, Positive};
    if arc(Negative, false) {
        SolidRelation::Separated
    } else if root(Negative, false) {
        SolidRelation::TouchingExternally
    } else if arc(Positive, true) {
        SolidRelation::Inside { inner: Solid::A }
    } else if arc(Positive, false) {
        SolidRelation::Inside { inner: Solid::B }
    } else if root(Positive, true) {
        SolidRelation::TouchingInternally { inner: Solid::A }
    } else if root(Positive, false) {
        SolidRelation::TouchingInternally { inner: Solid::B }
    } else {
        SolidRelation::Overlapping
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::parse_quadric;
    use qsic_algebra::testing::SplitMix;
    use qsic_algebra::RBig;

    fn q(text: &str) -> Quadric {
        parse_quadric(text).unwrap()
    }

    /// A sphere of squared radius `r2` centred at `(cx, cy, cz)` (rationals as text).
    fn sphere(c: [&str; 3], r2: &str) -> Quadric {
        q(&format!(
            "(x - ({}))^2 + (y - ({}))^2 + (z - ({}))^2 - ({r2})",
            c[0], c[1], c[2]
        ))
    }

    /// The relation of two spheres from the distance `d` of their centres and their radii,
    /// compared through squares: `(r₁ + r₂)² ⋛ d²` and `(r₁ − r₂)² ⋛ d²`.
    fn by_hand(d2: &RBig, r1: &RBig, r2: &RBig) -> SolidRelation {
        let sum = (r1 + r2) * (r1 + r2);
        let diff = (r1 - r2) * (r1 - r2);
        let inner = if r1 < r2 { Solid::A } else { Solid::B };
        if *d2 > sum {
            SolidRelation::Separated
        } else if *d2 == sum {
            SolidRelation::TouchingExternally
        } else if *d2 > diff {
            SolidRelation::Overlapping
        } else if d2.is_zero() && r1 == r2 {
            SolidRelation::Equal
        } else if *d2 == diff {
            SolidRelation::TouchingInternally { inner }
        } else {
            SolidRelation::Inside { inner }
        }
    }

    /// Spheres of radii 2 and 1 along the x axis, the centre distance through every kind of
    /// position; then random rational spheres (radii and centres chosen so that every
    /// relation occurs), against the distance test.
    #[test]
    fn spheres_match_the_distance_test() {
        let (two, one) = (RBig::from(2), RBig::ONE);
        let mut seen = std::collections::HashSet::new();
        for n in -16..=16 {
            let c = RBig::from_parts_signed(n.into(), 4u8.into());
            let a = sphere(["0", "0", "0"], "4");
            let b = sphere([&c.to_string(), "0", "0"], "1");
            let want = by_hand(&(&c * &c), &two, &one);
            let got = solid_relation(&a, &b).unwrap();
            assert_eq!(got, want, "centre distance {c}");
            assert_eq!(solid_relation(&b, &a).unwrap(), want.swapped(), "{c}");
            seen.insert(got.key());
        }
        assert_eq!(seen.len(), 5, "{seen:?}");
        // random radii, centres at Pythagorean offsets (3, 4)·k/5 so that tangencies happen
        let mut rng = SplitMix(11);
        for _ in 0..150 {
            let (r1, r2) = (RBig::from(rng.int(1, 6)), RBig::from(rng.int(1, 6)));
            let (dx, dy) = [(3, 4), (0, 5), (0, 0), (5, 0), (4, 3)][rng.int(0, 4) as usize];
            let k = RBig::from_parts_signed(rng.int(-12, 12).into(), 5u8.into());
            let (x, y) = (RBig::from(dx) * &k, RBig::from(dy) * &k);
            let d2 = &x * &x + &y * &y;
            let a = sphere(["1/3", "0", "-2"], &(&r1 * &r1).to_string());
            let cx = RBig::from_parts(1u8.into(), 3u8.into()) + &x;
            let b = sphere(
                [&cx.to_string(), &y.to_string(), "-2"],
                &(&r2 * &r2).to_string(),
            );
            let want = by_hand(&d2, &r1, &r2);
            assert_eq!(
                solid_relation(&a, &b).unwrap(),
                want,
                "r {r1}, {r2}, offset ({x}, {y})"
            );
            seen.insert(want.key());
        }
        assert_eq!(seen.len(), 6, "{seen:?}");
    }

    /// The closed form for two spheres equals the pencil's answer, the reference: on random
    /// spheres with irrational radii (squared radii not squares), and on tangencies of
    /// irrational radii built by hand (`r = k√2`, `m√2`, centres `(k ± m)(1, 1, 0)` apart:
    /// touching externally and internally), every relation occurring; and it declines for an
    /// ellipsoid that is not a sphere.
    #[test]
    fn spheres_closed_form_equals_the_pencil() {
        let mut seen = std::collections::HashSet::new();
        let mut check = |a: &Quadric, b: &Quadric| {
            let got = spheres_relation(a, b).expect("two spheres");
            let want = solid_relation_by_pencil(a, b, &crate::Budget::unlimited()).unwrap();
            assert_eq!(got, want, "{a:?} {b:?}");
            assert_eq!(spheres_relation(b, a), Some(want.swapped()));
            seen.insert(got.key());
        };
        let mut rng = SplitMix(5);
        for _ in 0..120 {
            let c = |rng: &mut SplitMix| format!("{}/{}", rng.int(-6, 6), rng.int(1, 3));
            let a = sphere(
                [&c(&mut rng), &c(&mut rng), "0"],
                &rng.int(1, 12).to_string(),
            );
            let b = sphere(
                [&c(&mut rng), "0", &c(&mut rng)],
                &rng.int(1, 12).to_string(),
            );
            check(&a, &b);
        }
        for (k, m) in [(1i64, 2i64), (3, 1), (2, 5)] {
            let a = sphere(["0", "0", "0"], &(2 * k * k).to_string());
            for (d, s2) in [(k + m, 2 * m * m), ((k - m).abs(), 2 * m * m)] {
                let b = sphere([&d.to_string(), &d.to_string(), "0"], &s2.to_string());
                check(&a, &b);
            }
            check(&a, &sphere(["0", "0", "0"], &(2 * k * k).to_string()));
        }
        assert_eq!(seen.len(), 6, "{seen:?}");
        let ellipsoid = q("x^2 + 2*y^2 + z^2 - 1");
        assert_eq!(
            spheres_relation(&ellipsoid, &sphere(["0", "0", "0"], "1")),
            None
        );
    }

    /// Ellipsoids whose relation is known by hand: axis-aligned ones along the x axis (the
    /// extreme x-coordinates decide), one inside another touching along a circle (the
    /// sphere in the prolate spheroid), and tangent along an axis.
    #[test]
    fn ellipsoids_known_by_hand() {
        use SolidRelation as R;
        let cases = [
            // x²/4 + y² + z² ≤ 1 spans x ∈ [−2, 2]; (x − c)² + 4y² + 4z² ≤ 1 spans [c − 1, c + 1]
            (
                "x^2/4 + y^2 + z^2 - 1",
                "(x-4)^2 + 4*y^2 + 4*z^2 - 1",
                R::Separated,
            ),
            (
                "x^2/4 + y^2 + z^2 - 1",
                "(x-3)^2 + 4*y^2 + 4*z^2 - 1",
                R::TouchingExternally,
            ),
            (
                "x^2/4 + y^2 + z^2 - 1",
                "(x-2)^2 + 4*y^2 + 4*z^2 - 1",
                R::Overlapping,
            ),
            // the thin one inside, its x-extent [c − 1, c + 1] within the big one's curvature
            (
                "x^2/4 + y^2 + z^2 - 1",
                "x^2 + 4*y^2 + 4*z^2 - 1",
                R::Inside { inner: Solid::B },
            ),
            // unit sphere in x² + y² + z²/4 ≤ 1: they touch along the circle z = 0
            (
                "x^2 + y^2 + z^2 - 1",
                "x^2 + y^2 + z^2/4 - 1",
                R::TouchingInternally { inner: Solid::A },
            ),
            // the same solid written twice, scaled by −3
            (
                "x^2/4 + y^2 + z^2 - 1",
                "-3*x^2/4 - 3*y^2 - 3*z^2 + 3",
                R::Equal,
            ),
            // x² + 2y² + 3z² ≤ 1 inside x² + y² + z² ≤ 1, touching at (±1, 0, 0)
            (
                "x^2 + y^2 + z^2 - 1",
                "x^2 + 2*y^2 + 3*z^2 - 1",
                R::TouchingInternally { inner: Solid::B },
            ),
            // crossing ellipsoids with a common centre: neither contains the other
            (
                "4*x^2 + y^2 + z^2 - 4",
                "x^2 + 4*y^2 + z^2 - 4",
                R::Overlapping,
            ),
            // a small ellipsoid deep inside, off-centre
            (
                "x^2 + y^2 + z^2 - 100",
                "(x-3)^2 + 2*(y+1)^2 + 3*z^2 - 1",
                R::Inside { inner: Solid::B },
            ),
        ];
        for (a, b, want) in cases {
            assert_eq!(solid_relation(&q(a), &q(b)).unwrap(), want, "{a} | {b}");
            assert_eq!(
                solid_relation(&q(b), &q(a)).unwrap(),
                want.swapped(),
                "{b} | {a}"
            );
        }
    }

    /// A rational affine map `X ↦ MX` (fixing `w = 0`) carries solids to solids: the relation
    /// of `MᵀAM, MᵀBM` is that of `A, B`; random positive or negative scalings too.
    #[test]
    fn affine_disguises_keep_the_relation() {
        let pairs = [
            ("x^2 + y^2 + z^2 - 4", "(x-3)^2 + y^2 + z^2 - 1"),
            ("x^2 + y^2 + z^2 - 4", "(x-1)^2 + y^2 + z^2 - 1"),
            ("x^2 + y^2 + z^2 - 4", "(x-1/2)^2 + y^2 + z^2 - 1"),
            ("x^2 + y^2 + z^2 - 4", "(x-2)^2 + y^2 + z^2 - 1"),
            ("x^2 + y^2 + z^2 - 4", "(x-4)^2 + y^2 + z^2 - 1"),
            ("x^2 + y^2 + z^2 - 1", "x^2 + y^2 + z^2/4 - 1"),
            ("x^2 + y^2 + z^2 - 1", "x^2 + 2*y^2 + 3*z^2 - 1"),
        ];
        let mut rng = SplitMix(5);
        for (a, b) in pairs {
            let (qa, qb) = (q(a), q(b));
            let want = solid_relation(&qa, &qb).unwrap();
            for _ in 0..6 {
                let m: [[RBig; 4]; 4] = std::array::from_fn(|i| {
                    std::array::from_fn(|j| match (i, j) {
                        (3, 3) => RBig::ONE,
                        (3, _) => RBig::ZERO,
                        _ => RBig::from_parts_signed(rng.int(-4, 4).into(), rng.int(1, 3).into()),
                    })
                });
                let block: [[RBig; 3]; 3] =
                    std::array::from_fn(|i| std::array::from_fn(|j| m[i][j].clone()));
                if det(&block).is_zero() {
                    continue;
                }
                let k = RBig::from_parts_signed(rng.int(-3, 3).into(), 2u8.into());
                if k.is_zero() {
                    continue;
                }
                let ta = Quadric::from_matrix(scaled(&congruent(qa.matrix(), &m), &k)).unwrap();
                let tb = Quadric::from_matrix(congruent(qb.matrix(), &m)).unwrap();
                assert_eq!(
                    solid_relation(&ta, &tb).unwrap(),
                    want,
                    "{a} | {b} by {m:?}"
                );
            }
        }
    }

    fn scaled(m: &[[RBig; 4]; 4], a: &RBig) -> [[RBig; 4]; 4] {
        m.clone().map(|row| row.map(|v| v * a))
    }

    fn congruent(a: &[[RBig; 4]; 4], m: &[[RBig; 4]; 4]) -> [[RBig; 4]; 4] {
        std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let mut s = RBig::ZERO;
                for k in 0..4 {
                    for l in 0..4 {
                        s += &m[k][i] * &a[k][l] * &m[l][j];
                    }
                }
                s
            })
        })
    }

    /// Quadrics that bound no solid ellipsoid are refused with what they are.
    #[test]
    fn non_ellipsoids_are_refused_by_name() {
        let ball = q("x^2 + y^2 + z^2 - 1");
        let cases = [
            ("x^2 + y^2 + z^2 + 1", "imaginary"),
            ("x^2 + y^2 + z^2", "single real point"),
            ("x^2 + y^2 - z", "elliptic paraboloid"),
            ("x^2 + y^2 - 1", "not bounded"),
            ("x^2 + y^2 - z^2 - 1", "not bounded"),
            ("x^2 - y^2 - z", "not bounded"),
            ("x*y - 1", "not bounded"),
        ];
        for (text, what) in cases {
            for (a, b, which) in [(&q(text), &ball, "A"), (&ball, &q(text), "B")] {
                let err = solid_relation(a, b).unwrap_err().to_string();
                assert!(
                    err.contains(what) && err.contains(&format!("{which} is")),
                    "{text}: {err}"
                );
            }
        }
    }

    #[test]
    fn keys_are_stable() {
        use SolidRelation as R;
        let all = [
            R::Separated,
            R::TouchingExternally,
            R::Overlapping,
            R::Inside { inner: Solid::A },
            R::TouchingInternally { inner: Solid::B },
            R::Equal,
        ];
        let keys = all.map(R::key);
        assert_eq!(
            keys,
            [
                "separated",
                "touching_externally",
                "overlapping",
                "inside",
                "touching_internally",
                "equal"
            ]
        );
        assert_eq!(all[3].inner(), Some(Solid::A));
        assert_eq!(all[4].swapped().inner(), Some(Solid::A));
        assert_eq!(all[1].inner(), None);
    }
}
