//! The accelerator of [`super::contact::first_contact_of`] for two moving ellipsoids: the
//! first contact read from the roots of the characteristic polynomial alone, with no class
//! computed at any instant.
//!
//! # Mathematics
//! Let both numerator matrices be real ellipsoids at every `t` of the closed range: their
//! leading principal minors `m₁ … m₄` have no real root there, so their signs — hence the
//! orientation that makes each `3×3` block positive definite ([`ellipsoid_orientation`]) —
//! are those at any one point of the range. Oriented so, `f(λ; t) = det(λM_A − M_B)` has
//! degree 4 in `λ` with `lc = det M_A < 0` and `f(0) = det(−M_B) = det M_B < 0`, and (Wang,
//! Wang, Kim; module `crate::solids` in this sign convention) two of its roots are positive,
//! counted with multiplicity, and the solids are **separated** exactly when the other two are
//! distinct negative reals `r₁ < r₂`. Then `f > 0` on `(r₁, r₂)`; where the other two are a
//! double negative root, a complex pair or positive, `f < 0` on every `λ < 0` but that root.
//! So: separated at `t` iff `f(λ*; t) > 0` for some `λ* < 0`; likewise the positive pair
//! `r₃ ≤ r₄` is distinct iff `f(λ*; t) > 0` for some `λ* > 0`.
//!
//! The number of distinct negative roots changes only where `f(·; t)` gains a multiple root
//! (its degree and `f(0)` never vanish in the range), so at the real roots of the
//! discriminant `Δ(t)` of `f` in `λ`. Were the solids separated at the start of the range,
//! the surfaces have no common point up to the first `t` where the solids are not separated,
//! and they have one there: the solids meet (a closed condition) while their interiors,
//! disjoint just before (an open condition), are still disjoint — they touch, on both
//! surfaces. So the first contact is the first `t ≥ t₀` where the solids are not separated:
//! - at a rational `t` (the start, a rational root of `Δ`, the end), exactly: the
//!   distinct negative roots of the rational quartic `f(·; t)`, counted by isolation;
//! - at an irrational root `α` of `Δ` reached from a separated interval, the roots there
//!   are limits: `r₁ ≤ r₂ < 0 < r₃ ≤ r₄` (`f(0) ≠ 0`), and `Δ(α) = 0` merges a pair. A
//!   certified `f(λ*; α) > 0` for a `λ* < 0` says the negative pair is distinct (still
//!   separated, no contact); for a `λ* > 0`, that the positive pair is, so the negative one
//!   merged: the solids touch at `α`. `λ*` is proposed by floats (the roots of `f(·; α)` in `f64`, midpoints of
//!   neighbours) and the sign of `f(λ*; α)`, an integer polynomial in `t` at `α`, is read by
//!   interval arithmetic on `α`'s isolating interval refined to at most [`MAX_BITS`] bits.
//!
//! Every answer is exact: floats only propose `λ*`. The route declines
//! ([`EllipsoidContact::Declined`], and the class walk answers) where a quadric is not an ellipsoid throughout the range, the solids
//! are not separated at its start (the surfaces' contact then depends on whether one solid
//! holds the other), `Δ ≡ 0` (a multiple root for every `t`: spheres, coaxial spheroids), or
//! no `λ*` is certified at an instant (both pairs merged, or two roots too close for `f64`).
//! The tests below hold its answers equal to the class walk's on motions reaching every
//! branch and on random rigid motions.
//!
//! **Work units.** The discriminant and the roots as the candidate stage (module
//! `instants`), the leading minors' roots per step of their isolation, the refinement of `α`
//! ([`refined_within`]) and each interval evaluation by its products.

use super::instants::{discriminant_form, t_primitive, Form, TPoly};
use super::range::{FirstContact, TimeRange};
use super::shared_roots::refined_within;
use super::MovingPencil;
use crate::error::Error;
use crate::solids::{ellipsoid_orientation, leading_minors};
use qsic_algebra::algebraic::sign_on_interval;
use qsic_algebra::budget::{poly_step_units, product_units, Budget};
use qsic_algebra::roots::{quartic_roots_f64, simplest_between, RootInterval};
use qsic_algebra::{AlgebraicReal, IBig, Poly, RBig, Ring, Sign};

/// The precision cap of the enclosures of `f(λ*; α)`, in bits: past it the instant is
/// handed back (a sign that needs more is a near tie the class walk settles exactly).
pub(super) const MAX_BITS: usize = 2048;

/// The answer of the route: the first contact on the range (`None`: none), or declined.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum EllipsoidContact {
    /// Decided: the first contact, if any.
    Decided(Option<FirstContact>),
    /// Not this shape (module docs): the class walk answers.
    Declined,
}

/// The first contact of a pencil of two moving ellipsoids on `range` (module docs).
///
/// # Errors
/// [`Error::BudgetExceeded`] when the budget runs out.
pub(super) fn first_contact_of_ellipsoids(
    pencil: &MovingPencil,
    range: &TimeRange,
    budget: &Budget,
) -> Result<EllipsoidContact, Error> {
    use EllipsoidContact::{Decided, Declined};
    let (ma, mb) = (pencil.a().numerators(), pencil.b().numerators());
    let (Some(negate_a), Some(negate_b)) = (
        orientation_throughout(ma, range, budget)?,
        orientation_throughout(mb, range, budget)?,
    ) else {
        return Ok(Declined);
    };
    let f = flip_lambda(pencil.characteristic(), negate_a != negate_b);
    if f.degree() != Some(4) {
        return Ok(Declined);
    }
    let form = Form {
        chart: t_primitive(&f, budget)?,
        degree: 4,
    };
    let delta = match discriminant_form(&form, pencil.route, budget)? {
        Some(d) if !d.is_zero() => d,
        _ => return Ok(Declined),
    };
    let end = range.to().map(|v| AlgebraicReal::from_rational(v.clone()));
    let roots: Vec<AlgebraicReal> = super::real_roots_of_all(&[delta], budget)?
        .into_iter()
        .filter(|r| range.after_start(r) && end.as_ref().is_none_or(|e| r < e))
        .collect();
    let start = match range.from() {
        Some(t0) => t0.clone(),
        // a point of the first interval
        None => match (roots.first(), range.to()) {
            (Some(r), _) => RBig::from(r.interval().lo().floor() - IBig::ONE),
            (None, Some(t1)) => t1 - RBig::ONE,
            (None, None) => RBig::ZERO,
        },
    };
    if !separated_at(&f, &start, budget)? {
        return Ok(Declined);
    }
    let contact = |t: &AlgebraicReal| Ok(Decided(Some(FirstContact::At(t.clone()))));
    for alpha in &roots {
        let separated_there = match alpha.as_rational() {
            Some(v) => separated_at(&f, v, budget)?,
            None => match negative_pair_distinct(&f, alpha, budget)? {
                Some(distinct) => distinct,
                None => return Ok(Declined),
            },
        };
        if !separated_there {
            return contact(alpha);
        }
    }
    if let (Some(t1), Some(e)) = (range.to(), &end) {
        if !separated_at(&f, t1, budget)? {
            return contact(e);
        }
    }
    Ok(Decided(None))
}

/// Whether a numerator matrix is a real ellipsoid at every `t` of the closed `range`, and
/// then whether it is to be negated (module docs); `None` if it is not.
fn orientation_throughout(
    m: &[[Poly; 4]; 4],
    range: &TimeRange,
    budget: &Budget,
) -> Result<Option<bool>, Error> {
    let minors = leading_minors(m);
    // no ellipsoid at one point of the range (most pencils): no root isolation
    let at = range.from().or(range.to()).cloned().unwrap_or(RBig::ZERO);
    let Ok(negate) = ellipsoid_orientation(minors.clone().map(|p| p.sign_at(&at))) else {
        return Ok(None);
    };
    for p in &minors {
        if p.is_zero() {
            return Ok(None);
        }
        for r in AlgebraicReal::real_roots_of_within(p, budget)? {
            let in_range = range
                .from()
                .is_none_or(|a| r >= AlgebraicReal::from_rational(a.clone()))
                && range
                    .to()
                    .is_none_or(|b| r <= AlgebraicReal::from_rational(b.clone()));
            if in_range {
                return Ok(None);
            }
        }
    }
    // no minor changes sign in the range: its signs at `at` hold throughout
    Ok(Some(negate))
}

/// `f(−λ)` where `flip` (one matrix negated: `det(−λM_A − M_B)` or `det(λM_A + M_B)`, of
/// even degree 4), else `f`.
pub(super) fn flip_lambda(f: &TPoly, flip: bool) -> TPoly {
    if !flip {
        return f.clone();
    }
    Poly::new(
        f.coeffs()
            .iter()
            .enumerate()
            .map(|(i, c)| if i % 2 == 1 { c.neg() } else { c.clone() })
            .collect(),
    )
}

/// `f(·; t)` at a rational `t` as an integer polynomial in `λ` (denominators cleared).
fn at_rational(f: &TPoly, t: &RBig) -> Poly {
    let values: Vec<RBig> = f.coeffs().iter().map(|c| c.eval_rational(t)).collect();
    Poly::from_rational(&Poly::new(values)).0
}

/// Whether the solids are separated at a rational `t`: `f(·; t)` has two distinct negative
/// roots (module docs), counted exactly on its square-free part.
fn separated_at(f: &TPoly, t: &RBig, budget: &Budget) -> Result<bool, Error> {
    let p = at_rational(f, t);
    budget.spend(poly_step_units(4, p.max_bits()).saturating_mul(8))?;
    let negative = AlgebraicReal::real_roots_of_within(&p, budget)?
        .iter()
        .filter(|r| r.interval().hi() <= &RBig::ZERO)
        .count();
    Ok(negative == 2)
}

/// At an irrational root `α` of the discriminant reached from a separated interval: whether the negative pair of roots is distinct there (`true`: still separated) or merged
/// (`false`: the positive pair is distinct, certified), from a certified `f(λ*; α) > 0`
/// (module docs); `None` when neither is certified.
pub(super) fn negative_pair_distinct(
    f: &TPoly,
    alpha: &AlgebraicReal,
    budget: &Budget,
) -> Result<Option<bool>, Error> {
    let a = alpha.to_f64();
    let c: Vec<f64> = f
        .coeffs()
        .iter()
        .map(|p| {
            p.coeffs()
                .iter()
                .rev()
                .fold(0.0, |acc, v| acc * a + v.to_f64().value())
        })
        .collect();
    let Ok(c) = <[f64; 5]>::try_from(c) else {
        return Ok(None);
    };
    if c.iter().any(|v| !v.is_finite()) {
        return Ok(None);
    }
    let Some(z) = quartic_roots_f64(&c) else {
        return Ok(None);
    };
    let mut re: Vec<f64> = z.iter().map(|r| r.0).collect();
    re.sort_by(f64::total_cmp);
    // the midpoints of neighbouring roots on each side of 0, nearest the middle first
    let mut probes: Vec<(f64, bool)> = Vec::new();
    for w in re.windows(2) {
        let (lo, hi) = (w[0], w[1]);
        if lo < hi && (hi <= 0.0 || lo >= 0.0) {
            probes.push(((lo + hi) / 2.0, hi <= 0.0));
        }
    }
    for (x, negative) in probes {
        let Some(lambda) = simple_rational_near(x) else {
            continue;
        };
        if (lambda < RBig::ZERO) != negative {
            continue;
        }
        if positive_at(f, &lambda, alpha, budget)? {
            return Ok(Some(negative));
        }
    }
    Ok(None)
}

/// A short rational within a part in 2²⁰ of a finite nonzero `x`.
fn simple_rational_near(x: f64) -> Option<RBig> {
    if !x.is_finite() || x == 0.0 {
        return None;
    }
    let v = RBig::try_from(x).ok()?;
    let slack = RBig::try_from(x.abs() / f64::from(1u32 << 20)).ok()?;
    Some(simplest_between(&(&v - &slack), &(&v + &slack), true, true))
}

/// Whether `f(λ*; α) > 0` is certified by interval arithmetic on `α`'s isolating interval
/// refined up to [`MAX_BITS`] bits (`false`: negative, or not decided).
fn positive_at(
    f: &TPoly,
    lambda: &RBig,
    alpha: &AlgebraicReal,
    budget: &Budget,
) -> Result<bool, Error> {
    // g(t) = den⁴·f(num/den; t), an integer polynomial in t
    let (num, den) = (
        lambda.numerator().clone(),
        IBig::from(lambda.denominator().clone()),
    );
    let mut g = Poly::zero();
    let (mut pn, mut pd) = (vec![IBig::ONE], vec![IBig::ONE]);
    for i in 1..=4 {
        pn.push(&pn[i - 1] * &num);
        pd.push(&pd[i - 1] * &den);
    }
    for (i, c) in f.coeffs().iter().enumerate() {
        g = &g + &c.scale(&(&pn[i] * &pd[4 - i]));
    }
    let n = g.degree().unwrap_or(0) as u64 + 1;
    let mut prec = 64;
    while prec <= MAX_BITS {
        let iv = refined_within(alpha, prec, budget)?;
        budget.spend(n.saturating_mul(product_units(g.max_bits() + prec, prec)))?;
        let sign = match &iv {
            RootInterval::Exact(v) => Some(g.sign_at(v)),
            RootInterval::Open(lo, hi) => sign_on_interval(&g, lo, hi),
        };
        match sign {
            Some(Sign::Positive) => return Ok(true),
            Some(_) => return Ok(false),
            None => prec *= 2,
        }
    }
    Ok(false)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::{moving_matrix_from_polynomial as moving, MovingMatrix};
    use crate::motion::contact::first_contact_by_class;
    use crate::motion::rigid::{RigidMotion, Rotation};
    use qsic_algebra::testing::SplitMix;

    fn rat(n: i64, d: i64) -> RBig {
        RBig::from_parts_signed(n.into(), (d as u64).into())
    }

    /// Random solid ellipsoids (axes along the coordinates, semi-axes² and centres small
    /// rationals) under random rigid motions: a Cayley rotation about a random axis through a
    /// random centre and a linear translation.
    fn random_rigid(rng: &mut SplitMix) -> (MovingMatrix, MovingMatrix) {
        let mut ellipsoid = || {
            let mut term = |v: &str| {
                let c = rng.int(-4, 4);
                let s = rng.int(1, 9);
                format!("({v} - ({c}))^2/{s}")
            };
            moving(&format!(
                "{} + {} + {} - 1",
                term("x"),
                term("y"),
                term("z")
            ))
            .unwrap()
        };
        let (a, b) = (ellipsoid(), ellipsoid());
        let mut axis = [0i64; 3].map(|_| rng.int(-2, 2));
        if axis == [0, 0, 0] {
            axis[2] = 1;
        }
        let motion = RigidMotion {
            rotation: Rotation::Cayley {
                axis: axis.map(RBig::from),
            },
            center: [0; 3].map(|_| RBig::from(rng.int(-2, 2))),
            translation: [0; 3].map(|_| {
                Poly::new(vec![
                    RBig::from(rng.int(-6, 6)),
                    rat(rng.int(-3, 3), rng.int(1, 2)),
                ])
            }),
        };
        (motion.apply(&a).unwrap(), b)
    }

    /// The route answers what the class walk answers, wherever it does not decline, on
    /// motions built to reach every branch: first contacts at rational and irrational
    /// instants after a separated interval, grazes (separated on both sides of the instant,
    /// rational and irrational), instants where only the positive pair merges, no contact,
    /// ranges cut before or at a contact; and it declines where the module says.
    #[test]
    fn the_route_answers_what_the_class_walk_answers() {
        let mut pairs: Vec<(String, MovingMatrix, MovingMatrix)> = [
            // touching along the x axis at t = 0 only (5 = 2 + 3), separated on both sides
            (
                "x^2/4 + y^2 + z^2/9 - 1",
                "(x - 5 - t^2)^2/9 + y^2/4 + z^2 - 1",
            ),
            // the same graze at t = ±√2
            (
                "x^2/4 + y^2 + z^2/9 - 1",
                "(x - 5 - (t^2 - 2)^2)^2/9 + y^2/4 + z^2 - 1",
            ),
            // along (2t − 6, t, 1): a contact at an irrational instant
            (
                "x^2/4 + y^2 + z^2/9 - 1",
                "(x - 2*t + 6)^2/9 + (y - t)^2/4 + (z - 1)^2 - 1",
            ),
            // the same with B's matrix negated (λ ↦ −λ in f)
            (
                "x^2/4 + y^2 + z^2/9 - 1",
                "1 - (x - 2*t + 6)^2/9 - (y - t)^2/4 - (z - 1)^2",
            ),
            // passing by, never touching
            (
                "x^2/4 + y^2 + z^2/9 - 1",
                "(x - t)^2 + (y - 5)^2/4 + z^2/4 - 1",
            ),
            // moving off and back: overlapping as t → ±∞, separated around t = 0 (the start
            // on an open range is a point left of every root, not right of one)
            (
                "x^2/4 + y^2 + z^2/9 - 1",
                "(x - 10/(1 + t^2))^2/9 + y^2/4 + z^2 - 1",
            ),
            // spheres: a double root for every t (declined)
            ("x^2 + y^2 + z^2 - 4", "(x - t)^2 + y^2 + z^2 - 1"),
        ]
        .into_iter()
        .map(|(a, b)| (format!("{a} | {b}"), moving(a).unwrap(), moving(b).unwrap()))
        .collect();
        let turn = RigidMotion {
            rotation: Rotation::Cayley {
                axis: [0, 0, 1].map(RBig::from),
            },
            ..RigidMotion::default()
        };
        pairs.push((
            "a turning ellipsoid's tip".into(),
            turn.apply(&moving("x^2/4 + y^2 + z^2 - 1").unwrap())
                .unwrap(),
            moving("(x - 3)^2/9 + (y - 4)^2/9 + z^2/4 - 1").unwrap(),
        ));
        let mut rng = SplitMix(26);
        for k in 0..12 {
            let (a, b) = random_rigid(&mut rng);
            pairs.push((format!("random rigid {k}"), a, b));
        }
        let ranges = [
            TimeRange::all(),
            TimeRange::new(Some(RBig::from(-1)), None).unwrap(),
            TimeRange::new(Some(RBig::ZERO), Some(RBig::from(3))).unwrap(),
            TimeRange::new(None, Some(rat(-5, 2))).unwrap(),
            TimeRange::new(None, Some(RBig::ZERO)).unwrap(),
            TimeRange::new(Some(rat(-1, 3)), Some(RBig::ZERO)).unwrap(),
        ];
        let unlimited = Budget::unlimited();
        let mut kinds = std::collections::BTreeSet::new();
        for (what, a, b) in &pairs {
            let p = MovingPencil::new(a.clone(), b.clone()).unwrap();
            for range in &ranges {
                let fast = first_contact_of_ellipsoids(&p, range, &unlimited).unwrap();
                let walk = first_contact_by_class(&p, range, &unlimited).unwrap();
                let kind = match fast {
                    EllipsoidContact::Declined => "declined",
                    EllipsoidContact::Decided(answer) => {
                        assert_eq!(answer, walk, "{what} on {range:?}");
                        match answer {
                            None => "none",
                            Some(FirstContact::FromMinusInfinity) => "from −∞",
                            Some(FirstContact::At(t)) if t.as_rational().is_some() => "rational",
                            Some(FirstContact::At(_)) => "irrational",
                        }
                    }
                };
                kinds.insert(kind);
            }
        }
        let want = ["declined", "irrational", "none", "rational"];
        assert_eq!(kinds.into_iter().collect::<Vec<_>>(), want);
    }

    /// A quadric that is an ellipsoid on the range only (its leading minors vanish at
    /// `t = 6`) is taken by the route on the range, and its answer is the class walk's.
    #[test]
    fn ellipsoids_on_the_range_only_are_taken() {
        let unlimited = Budget::unlimited();
        let p = MovingPencil::new(
            moving("x^2/(6 - t) + y^2 + 2*z^2 - 1").unwrap(),
            moving("(x - t - 8)^2 + y^2/4 + z^2/9 - 1").unwrap(),
        )
        .unwrap();
        let range = TimeRange::new(None, Some(RBig::ZERO)).unwrap();
        let fast = first_contact_of_ellipsoids(&p, &range, &unlimited).unwrap();
        let walk = first_contact_by_class(&p, &range, &unlimited).unwrap();
        assert_eq!(fast, EllipsoidContact::Decided(walk.clone()));
        let Some(FirstContact::At(t)) = walk else {
            panic!("{walk:?}");
        };
        // a range ending half a unit before the contact: nothing of Δ inside, no contact
        let before = RBig::from(((t.to_f64() - 0.5) * 8.0).floor() as i64) / RBig::from(8);
        let range = TimeRange::new(None, Some(before)).unwrap();
        let fast = first_contact_of_ellipsoids(&p, &range, &unlimited).unwrap();
        assert_eq!(fast, EllipsoidContact::Decided(None));
        assert_eq!(
            first_contact_by_class(&p, &range, &unlimited).unwrap(),
            None
        );
        // one that degenerates at t = −5, before a range starting at −4
        let q = MovingPencil::new(
            moving("x^2/(t + 5) + y^2 + 2*z^2 - 1").unwrap(),
            moving("(x + t - 8)^2 + y^2/4 + z^2/9 - 1").unwrap(),
        )
        .unwrap();
        let after = TimeRange::new(Some(RBig::from(-4)), None).unwrap();
        let walk = first_contact_by_class(&q, &after, &unlimited).unwrap();
        assert!(walk.is_some());
        assert_eq!(
            first_contact_of_ellipsoids(&q, &after, &unlimited).unwrap(),
            EllipsoidContact::Decided(walk)
        );
        // on the whole line, or a range holding t = 6, it is not an ellipsoid throughout
        for range in [
            TimeRange::all(),
            TimeRange::new(Some(RBig::from(-10)), Some(RBig::from(10))).unwrap(),
            TimeRange::new(Some(RBig::from(6)), None).unwrap(),
        ] {
            let declined = first_contact_of_ellipsoids(&p, &range, &unlimited).unwrap();
            assert_eq!(declined, EllipsoidContact::Declined, "{range:?}");
        }
    }

    /// Grazes are found, and the certificate at an irrational instant reads which pair of
    /// roots merged: at `t = −√2` the negative pair (a contact), at the irrational instants
    /// of the passing ellipsoid the positive one (none).
    #[test]
    fn grazes_and_positive_pairs_are_told_apart() {
        let unlimited = Budget::unlimited();
        let decided = |a: &str, b: &str| {
            let p = MovingPencil::new(moving(a).unwrap(), moving(b).unwrap()).unwrap();
            first_contact_of_ellipsoids(&p, &TimeRange::all(), &unlimited).unwrap()
        };
        // at t = 0, the end of the range
        let p = MovingPencil::new(
            moving("x^2/4 + y^2 + z^2/9 - 1").unwrap(),
            moving("(x - 5 - t^2)^2/9 + y^2/4 + z^2 - 1").unwrap(),
        )
        .unwrap();
        let to_zero = TimeRange::new(None, Some(RBig::ZERO)).unwrap();
        assert_eq!(
            first_contact_of_ellipsoids(&p, &to_zero, &unlimited).unwrap(),
            EllipsoidContact::Decided(Some(FirstContact::At(AlgebraicReal::from_rational(
                RBig::ZERO
            ))))
        );
        let graze = decided(
            "x^2/4 + y^2 + z^2/9 - 1",
            "(x - 5 - (t^2 - 2)^2)^2/9 + y^2/4 + z^2 - 1",
        );
        let EllipsoidContact::Decided(Some(FirstContact::At(t))) = graze else {
            panic!("{graze:?}");
        };
        assert!(t.as_rational().is_none() && (t.to_f64() + 2f64.sqrt()).abs() < 1e-12);
        let by = decided(
            "x^2/4 + y^2 + z^2/9 - 1",
            "(x - t)^2 + (y - 5)^2/4 + z^2/4 - 1",
        );
        assert_eq!(by, EllipsoidContact::Decided(None));
    }

    /// The certificate itself: at the roots of the discriminant of a passing ellipsoid, every
    /// irrational instant is read as "negative pair distinct", and at `−√2` of the graze as
    /// merged.
    #[test]
    fn the_certificate_reads_the_merged_pair() {
        let unlimited = Budget::unlimited();
        let read = |a: &str, b: &str| -> Vec<Option<bool>> {
            let p = MovingPencil::new(moving(a).unwrap(), moving(b).unwrap()).unwrap();
            let f = p.characteristic().clone();
            let form = Form {
                chart: t_primitive(&f, &unlimited).unwrap(),
                degree: 4,
            };
            let delta = discriminant_form(&form, p.route, &unlimited)
                .unwrap()
                .unwrap();
            crate::motion::real_roots_of_all(&[delta], &unlimited)
                .unwrap()
                .iter()
                .filter(|r| r.as_rational().is_none())
                .map(|r| negative_pair_distinct(&f, r, &unlimited).unwrap())
                .collect()
        };
        let by = read(
            "x^2/4 + y^2 + z^2/9 - 1",
            "(x - t)^2 + (y - 5)^2/4 + z^2/4 - 1",
        );
        assert!(
            !by.is_empty() && by.iter().all(|r| *r == Some(true)),
            "{by:?}"
        );
        let graze = read(
            "x^2/4 + y^2 + z^2/9 - 1",
            "(x - 5 - (t^2 - 2)^2)^2/9 + y^2/4 + z^2 - 1",
        );
        assert!(graze.contains(&Some(false)), "{graze:?}");
    }
}
