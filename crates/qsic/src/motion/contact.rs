//! First contact of two moving quadrics, and the relation of two moving solid ellipsoids
//! along the motion, exactly.
//!
//! - [`first_contact`]: the least `t` of a range where the real intersection of `A(t)` and
//!   `B(t)` in real projective space is not empty. Having a real common point is a closed
//!   condition in `t` (the numerator matrices are continuous and `ℝℙ³` is compact), so the
//!   set of such `t` has a least element; it is the range's start or an instant of
//!   [`MovingPencil::variations`], where the class — hence the emptiness of the real
//!   intersection, read from the real components of the class — changes.
//! - [`solid_motion`] (on the whole line) and [`solid_motion_in`] (on a range): the relation
//!   ([`SolidRelation`]) of the solids on every interval
//!   between the instants where it can change and at those instants: the candidate
//!   instants of the pencil (a relation changes only where the Segre characteristic or the
//!   inertias of the pencil change) and the real roots of the leading principal minors of
//!   `M_A(t)` and `M_B(t)` (where a quadric can stop being an ellipsoid). Rational instants
//!   and interval samples go through [`solid_relation`]; irrational ones through the same
//!   decision over `ℚ(α)` (minor signs at `α`, the pencil's roots and inertias over `ℚ(α)`).
//!   [`SolidMotion::first_meeting`] is the affine first contact: the least `t` where the
//!   solids are no longer separated.
//! - [`contact_points`], [`common_points_at`] (module `contact_point`): the common real points
//!   at the first contact — the points where the quadrics touch — exactly, and whether they
//!   already meet at the start of the range.
//!
//! Each has a `_within` form spending a caller's [`Budget`] (module docs of
//! [`super`]); the plain forms spend [`Budget::unlimited`].

pub use super::contact_point::{
    common_points_at, common_points_at_within, contact_points, contact_points_within, CommonLocus,
    CommonPoint, CommonPointKind, ContactPoints,
};
use super::ellipsoid_contact::{
    first_contact_of_ellipsoids, flip_lambda, negative_pair_distinct, EllipsoidContact,
};
use super::instants::pencil_entries;
pub use super::range::{FirstContact, TimeRange};
use super::{irrational, irrational_fast, InstantType, Motion, MovingPencil};
use crate::classify::Classification;
use crate::error::Error;
use crate::io::MovingMatrix;
use crate::solids::{
    ellipsoid_orientation, leading_minors, relation_from_signs, solid_relation_within,
    SolidRelation,
};
use qsic_algebra::budget::{Budget, Exhausted};
use qsic_algebra::{AlgebraicReal, IBig, Poly, RBig, Ring};

/// Whether the real intersection of a class has a real point (in real projective space).
///
/// # Errors
/// [`Error::Algebra`] for a classification without description (no case matched).
pub fn has_real_points(c: &Classification) -> Result<bool, Error> {
    c.description
        .as_ref()
        .map(|d| !d.components.is_empty())
        .ok_or_else(|| Error::Algebra("a classification without a description".into()))
}

/// The least `t` of `range` where `A(t)` and `B(t)` have a real common point (in real
/// projective space), exactly; `None` if there is none in the range.
///
/// # Errors
/// As [`MovingPencil::variations`]; [`Error::UnsupportedMotion`] when the answer would be an
/// irrational instant whose class the `ℚ(α)` route does not give (a singular or single
/// pencil there) and whose right neighbour has no real point: it is never guessed.
///
/// # Examples
/// ```
/// use qsic::io::moving_matrix_from_polynomial as moving;
/// use qsic::motion::contact::{first_contact, FirstContact, TimeRange};
/// use qsic_algebra::RBig;
/// // a unit sphere coming from x = −∞ towards a sphere of radius 2: contact at t = −3
/// let a = moving("x^2 + y^2 + z^2 - 4")?;
/// let b = moving("(x - t)^2 + y^2 + z^2 - 1")?;
/// let t = first_contact(&a, &b, &TimeRange::all())?;
/// assert_eq!(t, Some(FirstContact::At(qsic_algebra::AlgebraicReal::from_rational(RBig::from(-3)))));
/// # Ok::<(), qsic::Error>(())
/// ```
pub fn first_contact(
    a: &MovingMatrix,
    b: &MovingMatrix,
    range: &TimeRange,
) -> Result<Option<FirstContact>, Error> {
    first_contact_within(a, b, range, &Budget::unlimited())
}

/// [`first_contact`] spending `budget` on the variations of the motion and the class at the
/// start of the range.
///
/// # Errors
/// As [`first_contact`]; [`Error::BudgetExceeded`] when the budget runs out.
pub fn first_contact_within(
    a: &MovingMatrix,
    b: &MovingMatrix,
    range: &TimeRange,
    budget: &Budget,
) -> Result<Option<FirstContact>, Error> {
    let pencil = MovingPencil::new_within(a.clone(), b.clone(), budget)?;
    first_contact_of(&pencil, range, budget)
}

/// [`first_contact_within`] on a pencil: the one dispatch point between the ellipsoids'
/// accelerator (module `ellipsoid_contact`: two ellipsoids throughout the range, separated
/// at its start, read from the roots of `f` alone) and the class walk
/// [`first_contact_by_class`], which answers whatever the accelerator declines.
///
/// # Errors
/// As [`first_contact_within`].
pub fn first_contact_of(
    pencil: &MovingPencil,
    range: &TimeRange,
    budget: &Budget,
) -> Result<Option<FirstContact>, Error> {
    match first_contact_of_ellipsoids(pencil, range, budget)? {
        EllipsoidContact::Decided(answer) => Ok(answer),
        EllipsoidContact::Declined => first_contact_by_class(pencil, range, budget),
    }
}

/// The reference of [`first_contact_of`], classifying only what the answer needs: the
/// candidate instants of the whole line in order, and for each, the interval after it (a
/// rational sample) before the instant itself — where that interval has a real point the
/// instant is the answer by closedness, unclassified — and the instant only where it does
/// not: an irrational instant where `f` has four distinct roots has its neighbours' type
/// (the generic condition of [`MovingPencil::variations`]), any other is classified over
/// `ℚ(α)`. The walk stops at the first contact. It answers what [`first_contact_in`] answers
/// from the whole timeline (`tests::lazy_first_contact_equals_the_timeline_route`), and is
/// the route of [`first_contact`] wherever the ellipsoids' accelerator declines.
///
/// # Errors
/// As [`first_contact_within`].
pub fn first_contact_by_class(
    pencil: &MovingPencil,
    range: &TimeRange,
    budget: &Budget,
) -> Result<Option<FirstContact>, Error> {
    let (polys, generic) = pencil.candidates_and_generic_condition(budget)?;
    let candidates = super::real_roots_of_all(&polys, budget)?;
    let samples = super::samples_between(&candidates, None, None);
    let interval_meets = |k: usize| -> Result<bool, Error> {
        has_real_points(&pencil.classify_at_within(&samples[k], budget)?)
    };
    let instant_meets = |i: usize| -> Result<Option<bool>, Error> {
        let c = &candidates[i];
        if let Some(v) = c.as_rational() {
            return has_real_points(&pencil.classify_at_within(v, budget)?).map(Some);
        }
        if let Some(g) = &generic {
            if !pencil.zero_tests.is_root(c, g, budget)? {
                // the type of both neighbours, and neither has a real point (the walk
                // reaches an instant only past intervals without one)
                return Ok(Some(false));
            }
        }
        match pencil.classify_at_irrational(c, budget)? {
            Some(class) => has_real_points(&class).map(Some),
            None => Ok(None),
        }
    };
    first_in_range(
        range,
        candidates.iter(),
        Timeline {
            first_interval: || interval_meets(0),
            after_instant: |i: usize| interval_meets(i + 1),
            instant: instant_meets,
            at_start: |t: &RBig| has_real_points(&pencil.classify_at_within(t, budget)?),
        },
    )
}

/// [`first_contact`] from a pencil and its variations, computed once.
///
/// # Errors
/// As [`first_contact`].
pub fn first_contact_in(
    pencil: &MovingPencil,
    motion: &Motion,
    range: &TimeRange,
) -> Result<Option<FirstContact>, Error> {
    first_contact_in_within(pencil, motion, range, &Budget::unlimited())
}

/// [`first_contact_in`] spending `budget` on the class at the start of the range.
///
/// # Errors
/// As [`first_contact_within`].
pub fn first_contact_in_within(
    pencil: &MovingPencil,
    motion: &Motion,
    range: &TimeRange,
    budget: &Budget,
) -> Result<Option<FirstContact>, Error> {
    // On the whole line interval i + 1 starts at instant i.
    let interval_meets = |i: usize| has_real_points(&motion.intervals[i].classification);
    let instant_meets = |i: usize| -> Result<Option<bool>, Error> {
        match &motion.instants[i].class {
            InstantType::Exact(c) => has_real_points(c).map(Some),
            InstantType::IrrationalUnclassified => Ok(None),
        }
    };
    first_in_range(
        range,
        motion.instants.iter().map(|m| &m.t),
        Timeline {
            first_interval: || interval_meets(0),
            after_instant: |i: usize| interval_meets(i + 1),
            instant: instant_meets,
            at_start: |t: &RBig| has_real_points(&pencil.classify_at_within(t, budget)?),
        },
    )
}

/// Whether a closed condition holds along a timeline: on the interval from `−∞`, on the
/// interval right after instant `i` (`false` if there is none), at instant `i` (`None`:
/// undecided), and at a rational start.
struct Timeline<F, G, H, S> {
    first_interval: F,
    after_instant: G,
    instant: H,
    at_start: S,
}

/// The least `t` of `range` where a closed condition holds, on a timeline with these
/// `instants`. An undecided instant counts by closedness when the interval after it holds,
/// and is an error when that does not hold either.
fn first_in_range<'a, F, G, H, S>(
    range: &TimeRange,
    instants: impl Iterator<Item = &'a AlgebraicReal>,
    holds: Timeline<F, G, H, S>,
) -> Result<Option<FirstContact>, Error>
where
    F: Fn() -> Result<bool, Error>,
    G: Fn(usize) -> Result<bool, Error>,
    H: Fn(usize) -> Result<Option<bool>, Error>,
    S: Fn(&RBig) -> Result<bool, Error>,
{
    match range.from() {
        Some(t0) if (holds.at_start)(t0)? => {
            return Ok(Some(FirstContact::At(AlgebraicReal::from_rational(
                t0.clone(),
            ))))
        }
        None if (holds.first_interval)()? => return Ok(Some(FirstContact::FromMinusInfinity)),
        _ => {}
    }
    for (i, t) in instants.enumerate() {
        if !range.after_start(t) {
            continue;
        }
        if !range.not_after_end(t) {
            break;
        }
        // the interval after first: where it holds, so does the instant (closedness)
        let here = (holds.after_instant)(i)?
            || match (holds.instant)(i)? {
                Some(h) => h,
                None => {
                    return Err(Error::UnsupportedMotion(format!(
                        "the class at the irrational instant {t} (≈ {:.12}) is not computed \
                     exactly, and the answer may be there",
                        t.to_f64()
                    )))
                }
            };
        if here {
            return Ok(Some(FirstContact::At(t.clone())));
        }
    }
    Ok(None)
}

/// The relation of two moving solids at an instant or on an interval.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SolidState {
    /// Both are solid ellipsoids: their relation.
    Relation(SolidRelation),
    /// One is not a solid ellipsoid there: which, and what it is.
    NotEllipsoids(String),
    /// An irrational instant where the `ℚ(α)` route gave no answer (kept, never guessed).
    Undetermined,
}

impl SolidState {
    /// The stable key: the relation's, `not_ellipsoids` or `undetermined`.
    pub fn key(&self) -> &'static str {
        match self {
            SolidState::Relation(r) => r.key(),
            SolidState::NotEllipsoids(_) => "not_ellipsoids",
            SolidState::Undetermined => "undetermined",
        }
    }

    /// The relation, if both are ellipsoids and it was decided.
    pub fn relation(&self) -> Option<SolidRelation> {
        match self {
            SolidState::Relation(r) => Some(*r),
            _ => None,
        }
    }
}

/// An open interval of `t` with one relation.
#[derive(Clone, Debug)]
pub struct SolidInterval {
    /// Left end, `None` for `−∞`.
    pub from: Option<AlgebraicReal>,
    /// Right end, `None` for `+∞`.
    pub to: Option<AlgebraicReal>,
    /// The rational `t` where it was decided.
    pub sample: RBig,
    /// The relation on the interval.
    pub state: SolidState,
}

/// An instant whose relation differs from that just before or just after it.
#[derive(Clone, Debug)]
pub struct SolidInstant {
    /// The instant.
    pub t: AlgebraicReal,
    /// The relation there.
    pub state: SolidState,
}

/// The relation of two moving solids along a range of the motion (the whole line for
/// [`solid_motion`]): the intervals cover the open range, and the instants strictly inside
/// it separate them (`intervals[i]` ends where `intervals[i + 1]` starts); an end of the
/// range comes first or last among the instants where its relation differs from the
/// interval beside it, as in [`MovingPencil::variations_in`].
#[derive(Clone, Debug)]
pub struct SolidMotion {
    /// The intervals, increasing.
    pub intervals: Vec<SolidInterval>,
    /// The instants, increasing.
    pub instants: Vec<SolidInstant>,
}

impl SolidMotion {
    /// Whether both quadrics are solid ellipsoids at every `t` (every state is a relation
    /// or undetermined).
    pub fn ellipsoids_throughout(&self) -> bool {
        let states = self.intervals.iter().map(|i| &i.state);
        states
            .chain(self.instants.iter().map(|i| &i.state))
            .all(|s| !matches!(s, SolidState::NotEllipsoids(_)))
    }

    /// The state at `t`: that of the instant `t`, else that of the interval holding `t` (an
    /// end of the range that is no instant has the state of the interval beside it);
    /// `None` outside the range analysed.
    pub fn state_at(&self, t: &AlgebraicReal) -> Option<&SolidState> {
        if let Some(i) = self.instants.iter().find(|i| i.t == *t) {
            return Some(&i.state);
        }
        let holds = |i: &&SolidInterval| {
            i.from.as_ref().is_none_or(|a| a <= t) && i.to.as_ref().is_none_or(|b| t <= b)
        };
        self.intervals.iter().find(holds).map(|i| &i.state)
    }

    /// The affine first contact: the least `t` of `range` where the closed solids share a
    /// point (the relation is not [`SolidRelation::Separated`]). `range` lies in the range
    /// analysed.
    ///
    /// # Errors
    /// [`Error::NotEllipsoid`] if a quadric stops being an ellipsoid in the range before
    /// the answer; [`Error::UnsupportedMotion`] if it hinges on an undetermined instant;
    /// [`Error::InvalidRange`] if `range` starts outside the range analysed.
    pub fn first_meeting(&self, range: &TimeRange) -> Result<Option<FirstContact>, Error> {
        let meets = |s: &SolidState| match s {
            SolidState::Relation(r) => Ok(Some(r.solids_meet())),
            SolidState::NotEllipsoids(why) => Err(Error::NotEllipsoid(why.clone())),
            SolidState::Undetermined => Ok(None),
        };
        let outside = || {
            Error::InvalidRange("the range starts outside the range of the motion analysed".into())
        };
        let instants: Vec<AlgebraicReal> = self.instants.iter().map(|i| i.t.clone()).collect();
        first_in_range(
            range,
            instants.iter(),
            Timeline {
                first_interval: || match self.intervals.first() {
                    Some(i) if i.from.is_none() => meets(&i.state).map(|m| m.unwrap_or(false)),
                    _ => Err(outside()),
                },
                after_instant: |k: usize| {
                    let t = Some(&self.instants[k].t);
                    match self.intervals.iter().find(|i| i.from.as_ref() == t) {
                        Some(i) => meets(&i.state).map(|m| m.unwrap_or(false)),
                        None => Ok(false),
                    }
                },
                instant: |k: usize| meets(&self.instants[k].state),
                at_start: |t0: &RBig| {
                    let at = AlgebraicReal::from_rational(t0.clone());
                    let state = self.state_at(&at).ok_or_else(outside)?;
                    meets(state).map(|m| m.unwrap_or(false))
                },
            },
        )
    }
}

/// The relation of two moving solid ellipsoids along the motion (module docs), with the
/// instants where it changes, exactly: [`solid_motion_in`] on the whole line.
///
/// # Errors
/// As [`MovingPencil::candidate_instants`].
///
/// # Examples
/// ```
/// use qsic::io::moving_matrix_from_polynomial as moving;
/// use qsic::motion::contact::solid_motion;
/// let a = moving("x^2 + y^2 + z^2 - 4")?;
/// let b = moving("(x - t)^2 + y^2 + z^2 - 1")?;
/// let m = solid_motion(&a, &b)?;
/// let keys: Vec<&str> = m.intervals.iter().map(|i| i.state.key()).collect();
/// assert_eq!(keys, ["separated", "overlapping", "inside", "overlapping", "separated"]);
/// let at: Vec<String> = m.instants.iter().map(|i| i.t.to_string()).collect();
/// assert_eq!(at, ["-3", "-1", "1", "3"]);
/// # Ok::<(), qsic::Error>(())
/// ```
pub fn solid_motion(a: &MovingMatrix, b: &MovingMatrix) -> Result<SolidMotion, Error> {
    solid_motion_of(&MovingPencil::new(a.clone(), b.clone())?)
}

/// [`solid_motion`] spending `budget` ([`solid_motion_in_within`] on the whole line).
///
/// # Errors
/// As [`solid_motion`]; [`Error::BudgetExceeded`] when the budget runs out.
pub fn solid_motion_within(
    a: &MovingMatrix,
    b: &MovingMatrix,
    budget: &Budget,
) -> Result<SolidMotion, Error> {
    let pencil = MovingPencil::new_within(a.clone(), b.clone(), budget)?;
    solid_motion_in_within(&pencil, &TimeRange::all(), budget)
}

/// [`solid_motion`] of a pencil already built.
///
/// # Errors
/// As [`solid_motion`].
pub fn solid_motion_of(pencil: &MovingPencil) -> Result<SolidMotion, Error> {
    solid_motion_in(pencil, &TimeRange::all())
}

/// The relation of the solids on `range` only: the intervals cover the open range, the
/// first starts at its start and the last ends at its end; the instants strictly inside
/// are those of the whole line, and an end of the range is an instant (first or last) only
/// where its relation differs from the interval beside it. A range of one point has no
/// interval and that one instant.
///
/// # Errors
/// As [`solid_motion`].
///
/// # Examples
/// ```
/// use qsic::io::moving_matrix_from_polynomial as moving;
/// use qsic::motion::{contact::solid_motion_in, MovingPencil, TimeRange};
/// let a = moving("x^2 + y^2 + z^2 - 4")?;
/// let b = moving("(x - t)^2 + y^2 + z^2 - 1")?;
/// let pencil = MovingPencil::new(a, b)?;
/// // On [-1, 2]: the inner tangency at -1, inside up to 1, touching, then overlapping.
/// let m = solid_motion_in(&pencil, &TimeRange::parse("-1", "2")?)?;
/// let keys: Vec<&str> = m.intervals.iter().map(|i| i.state.key()).collect();
/// assert_eq!(keys, ["inside", "overlapping"]);
/// let at: Vec<String> = m.instants.iter().map(|i| i.t.to_string()).collect();
/// assert_eq!(at, ["-1", "1"]);
/// assert_eq!(m.intervals[0].from.as_ref().map(|t| t.to_string()), Some("-1".into()));
/// # Ok::<(), qsic::Error>(())
/// ```
pub fn solid_motion_in(pencil: &MovingPencil, range: &TimeRange) -> Result<SolidMotion, Error> {
    solid_motion_in_within(pencil, range, &Budget::unlimited())
}

/// [`solid_motion_in`] spending `budget`: the candidate stage as
/// [`MovingPencil::variations_within`], each rational state as the pencil's analysis, each
/// irrational one as the classification at `α`.
///
/// # Errors
/// As [`solid_motion`]; [`Error::BudgetExceeded`] when the budget runs out.
pub fn solid_motion_in_within(
    pencil: &MovingPencil,
    range: &TimeRange,
    budget: &Budget,
) -> Result<SolidMotion, Error> {
    let exact = |v: &RBig| AlgebraicReal::from_rational(v.clone());
    let (lo, hi) = (range.from().map(exact), range.to().map(exact));
    if let (Some(a), Some(b)) = (range.from(), range.to()) {
        if a == b {
            return Ok(SolidMotion {
                intervals: Vec::new(),
                instants: vec![SolidInstant {
                    t: exact(a),
                    state: state_at_rational(pencil, a, budget)?,
                }],
            });
        }
    }
    let mut polys = pencil.candidate_polynomials_within(budget)?;
    for m in [pencil.a(), pencil.b()] {
        polys.extend(leading_minors(m.numerators()));
    }
    polys.retain(|p| !p.is_zero());
    let candidates: Vec<AlgebraicReal> = super::real_roots_of_all(&polys, budget)?
        .into_iter()
        .filter(|c| lo.as_ref().is_none_or(|a| a < c) && hi.as_ref().is_none_or(|b| c < b))
        .collect();
    let samples = super::samples_between(&candidates, lo.as_ref(), hi.as_ref());
    let mut interval_states = Vec::with_capacity(samples.len());
    for s in &samples {
        interval_states.push(state_at_rational(pencil, s, budget)?);
    }
    let mut intervals = vec![SolidInterval {
        from: lo.clone(),
        to: None,
        sample: samples[0].clone(),
        state: interval_states[0].clone(),
    }];
    let mut instants = Vec::new();
    for (j, t) in candidates.into_iter().enumerate() {
        let right = &interval_states[j + 1];
        let left = &intervals.last().expect("one interval at least").state;
        let state = match t.as_rational() {
            Some(v) => state_at_rational(pencil, v, budget)?,
            None => match state_between(pencil, &t, left, right, budget)? {
                Some(s) => s,
                None => state_at_irrational(pencil, &t, budget)?,
            },
        };
        if state == *left && state == *right {
            continue;
        }
        intervals.last_mut().expect("one interval at least").to = Some(t.clone());
        intervals.push(SolidInterval {
            from: Some(t.clone()),
            to: None,
            sample: samples[j + 1].clone(),
            state: right.clone(),
        });
        instants.push(SolidInstant { t, state });
    }
    intervals.last_mut().expect("one interval at least").to = hi;
    // The ends of the range, where their relation differs from the interval beside them.
    for (end, first) in [(range.from(), true), (range.to(), false)] {
        let Some(v) = end else { continue };
        let state = state_at_rational(pencil, v, budget)?;
        let beside = if first {
            intervals.first()
        } else {
            intervals.last()
        };
        if beside.is_some_and(|i| i.state != state) {
            let instant = SolidInstant { t: exact(v), state };
            if first {
                instants.insert(0, instant);
            } else {
                instants.push(instant);
            }
        }
    }
    Ok(SolidMotion {
        intervals,
        instants,
    })
}

/// The relation at a rational `t`; `Err` only when the budget runs out.
fn state_at_rational(
    pencil: &MovingPencil,
    t: &RBig,
    budget: &Budget,
) -> Result<SolidState, Exhausted> {
    let quadric = |m: &MovingMatrix, name: &str| {
        m.quadric_at(t).map_err(|e| {
            SolidState::NotEllipsoids(match e {
                Error::ZeroQuadric => format!("{name} is the zero form"),
                e => format!("{name}: {e}"),
            })
        })
    };
    let pair = quadric(pencil.a(), "A").and_then(|a| Ok((a, quadric(pencil.b(), "B")?)));
    Ok(match pair {
        Ok((a, b)) => match solid_relation_within(&a, &b, budget) {
            Ok(r) => SolidState::Relation(r),
            Err(Error::NotEllipsoid(why)) => SolidState::NotEllipsoids(why),
            Err(Error::BudgetExceeded { limit }) => return Err(Exhausted { limit }),
            Err(_) => SolidState::Undetermined,
        },
        Err(s) => s,
    })
}

/// The relation at an irrational `α` read from the relations beside it, where they decide it
/// (the accelerator of [`state_at_irrational`]; `None`: it answers). Both quadrics must be
/// ellipsoids at `α` (their leading minors nonzero there, exact signs). Then:
/// - separated on one side and overlapping on the other: touching externally — the solids
///   meet at `α` (a closed condition) while their interiors, disjoint on the separated side
///   (an open condition), are disjoint at `α`;
/// - separated on both sides: separated at `α` where a certified `f(λ*; α) > 0` with `λ* < 0`
///   shows the two negative roots of `f` distinct (module `ellipsoid_contact`).
fn state_between(
    pencil: &MovingPencil,
    alpha: &AlgebraicReal,
    left: &SolidState,
    right: &SolidState,
    budget: &Budget,
) -> Result<Option<SolidState>, Error> {
    use SolidRelation::{Overlapping, Separated};
    let (Some(l), Some(r)) = (left.relation(), right.relation()) else {
        return Ok(None);
    };
    let (ma, mb) = (pencil.a().numerators(), pencil.b().numerators());
    let spend = super::irrational::Spend::new(budget, alpha);
    let (degree, bits) = ma.iter().chain(mb).flatten().fold((0, 0), |(d, b), p| {
        (d.max(p.degree().unwrap_or(0)), b.max(p.max_bits()))
    });
    spend.sign_tests(8, 4 * degree, 4 * bits + 8, alpha)?;
    let orientation = |m: &[[Poly; 4]; 4]| {
        ellipsoid_orientation(leading_minors(m).map(|p| alpha.sign_of(&p))).ok()
    };
    let (Some(negate_a), Some(negate_b)) = (orientation(ma), orientation(mb)) else {
        return Ok(None);
    };
    Ok(match (l, r) {
        (Separated, Overlapping) | (Overlapping, Separated) => {
            Some(SolidState::Relation(SolidRelation::TouchingExternally))
        }
        (Separated, Separated) => {
            let f = flip_lambda(pencil.characteristic(), negate_a != negate_b);
            negative_pair_distinct(&f, alpha, budget)?
                .filter(|&distinct| distinct)
                .map(|_| SolidState::Relation(Separated))
        }
        _ => None,
    })
}

/// The relation at an irrational `α`: the minors' signs at `α` decide ellipsoids and their
/// orientation, the 2×2 minors of the pair `A ∝ B`, then the pencil over `ℚ(α)`.
fn state_at_irrational(
    pencil: &MovingPencil,
    alpha: &AlgebraicReal,
    budget: &Budget,
) -> Result<SolidState, Exhausted> {
    let (ma, mb) = (pencil.a().numerators(), pencil.b().numerators());
    // the minors' and the pair's 2×2 minors' signs at α: a zero test or an enclosure each,
    // on integer polynomials of at most twice the entries' degree and bits
    let spend = super::irrational::Spend::new(budget, alpha);
    let entries = ma.iter().chain(mb).flatten();
    let (degree, bits) = entries.fold((0, 0), |(d, b), p| {
        (d.max(p.degree().unwrap_or(0)), b.max(p.max_bits()))
    });
    spend.sign_tests(8 + 120, 4 * degree, 4 * bits + 8, alpha)?;
    let orientation = |m: &[[Poly; 4]; 4], name: &str| {
        let signs = leading_minors(m).map(|p| alpha.sign_of(&p));
        ellipsoid_orientation(signs)
            .map_err(|e| SolidState::NotEllipsoids(format!("{name} is {e}")))
    };
    let (negate_a, negate_b) = match (orientation(ma, "A"), orientation(mb, "B")) {
        (Ok(a), Ok(b)) => (a, b),
        (Err(s), _) | (_, Err(s)) => return Ok(s),
    };
    let (va, vb): (Vec<&Poly>, Vec<&Poly>) =
        (ma.iter().flatten().collect(), mb.iter().flatten().collect());
    let proportional = (0..16)
        .all(|i| (i + 1..16).all(|j| alpha.is_root_of(&(&(va[i] * vb[j]) - &(va[j] * vb[i])))));
    if proportional {
        return Ok(SolidState::Relation(SolidRelation::Equal));
    }
    let oriented = |m: &[[Poly; 4]; 4], negate: bool| -> [[Poly; 4]; 4] {
        let k = Poly::constant(if negate { -IBig::ONE } else { IBig::ONE });
        m.clone().map(|row| row.map(|p| p.mul(&k)))
    };
    // the fast route (one double root, certified signs), else the reference
    let polys = pencil.fast_polys(budget)?.oriented(negate_a, negate_b);
    let signs = match irrational_fast::pencil_signs_at_irrational_fast(&polys, alpha, budget)? {
        Some(s) => Some(s),
        None => {
            let entries = pencil_entries(&oriented(ma, negate_a), &oriented(mb, negate_b));
            irrational::pencil_signs_at_irrational(&entries, alpha, budget)?
        }
    };
    Ok(signs.map_or(SolidState::Undetermined, |s| {
        SolidState::Relation(relation_from_signs(&s))
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::moving_matrix_from_polynomial as moving;

    /// The lazy walk of [`first_contact_of`] answers what the whole timeline answers
    /// ([`first_contact_in`] of [`MovingPencil::variations`]) on the moving corpus and on
    /// motions of every kind of first contact (none, from −∞, at a rational or an irrational
    /// instant, at the start of a range), for the whole line and ranges cut at rationals.
    #[test]
    fn lazy_first_contact_equals_the_timeline_route() {
        let mut pencils = crate::motion::moving_corpus();
        for (a, b) in [
            ("x^2 + y^2 + z^2 - 4", "(x - t)^2 + (y - 1/2)^2 + z^2 - 1"),
            (
                "x^2/4 + y^2 + z^2/9 - 1",
                "(x - 2*t + 6)^2 + (y - t)^2/4 + (z - 1)^2 - 1",
            ),
            (
                "x^2 + y^2 + z^2 - 1",
                "(x - t)^2 + (y - t^2/3)^2 + z^2 - 1/4",
            ),
            (
                "x^2 + 2*y^2 + 3*z^2 - 1",
                "(x - t)^2 + (y - t^2)^2 - z^2 - 1/2",
            ),
            ("x^2 + y^2 + z^2 - 1", "x^2 + y^2 + z^2 - t^2 - 2"),
            ("x^2 + y^2 - 1", "(x - t)^2 + z^2 - 1/9"),
            ("x^2 + y^2 + z^2 + 1", "(x - t)^2 + y^2 - z^2 - 1"),
            // a pole at t = ±1/√2, an instant where nothing changes, before the contact at 1
            (
                "x^2 + 2*y^2 + 3*z^2 - 5",
                "((x - t)^2 + (y - 1/2)^2 + (z - 1/3)^2 - 1/16)/(2*t^2 - 1)",
            ),
        ] {
            pencils.push((format!("{a} | {b}"), moving(a).unwrap(), moving(b).unwrap()));
        }
        let ranges = [
            TimeRange::all(),
            TimeRange::new(Some(RBig::from(-1)), None).unwrap(),
            TimeRange::new(Some(RBig::from(0)), Some(RBig::from(3))).unwrap(),
            TimeRange::new(None, Some(RBig::from_parts_signed((-5).into(), 2u8.into()))).unwrap(),
        ];
        let unlimited = Budget::unlimited();
        let mut kinds = std::collections::HashSet::new();
        for (what, a, b) in &pencils {
            let p = MovingPencil::new(a.clone(), b.clone()).unwrap();
            let motion = p.variations().unwrap();
            for range in &ranges {
                let lazy = first_contact_of(&p, range, &unlimited).unwrap();
                let timeline = first_contact_in(&p, &motion, range).unwrap();
                assert_eq!(lazy, timeline, "{what} on {range:?}");
                kinds.insert(match &lazy {
                    None => "none",
                    Some(FirstContact::FromMinusInfinity) => "from −∞",
                    Some(FirstContact::At(t)) if t.as_rational().is_some() => "rational",
                    Some(FirstContact::At(_)) => "irrational",
                });
            }
        }
        assert_eq!(kinds.len(), 4, "{kinds:?}");
    }

    /// The relation read from the neighbours ([`state_between`]) is the one computed at the
    /// instant ([`state_at_irrational`]) at every irrational candidate of motions where it
    /// answers both ways (separated at a graze-free instant, touching externally between
    /// separated and overlapping), and it declines elsewhere.
    #[test]
    fn relations_read_from_the_neighbours_are_those_at_the_instant() {
        let turn = crate::motion::rigid::RigidMotion {
            rotation: crate::motion::rigid::Rotation::Cayley {
                axis: [0, 0, 1].map(RBig::from),
            },
            ..Default::default()
        };
        let turning = turn
            .apply(&moving("x^2/4 + y^2 + z^2 - 1").unwrap())
            .unwrap();
        let pairs = [
            (
                moving("x^2/4 + y^2 + z^2/9 - 1").unwrap(),
                moving("(x - 2*t + 6)^2/9 + (y - t)^2/4 + (z - 1)^2 - 1").unwrap(),
            ),
            (
                moving("x^2/4 + y^2 + z^2/9 - 1").unwrap(),
                moving("1 - (x - 5 - (t^2 - 2)^2)^2/9 - y^2/4 - z^2").unwrap(),
            ),
            (
                turning,
                moving("(x - 3)^2/9 + (y - 4)^2/9 + z^2/4 - 1").unwrap(),
            ),
            (
                moving("x^2 + 2*y^2 + 3*z^2 - 4").unwrap(),
                moving("(x - t)^2 + (y - t^2/2)^2 + z^2/4 - 1").unwrap(),
            ),
        ];
        let unlimited = Budget::unlimited();
        let mut answered = std::collections::BTreeMap::new();
        let mut declined = 0;
        for (a, b) in pairs {
            let p = MovingPencil::new(a.clone(), b.clone()).unwrap();
            let mut polys = p.candidate_polynomials().unwrap();
            for m in [p.a(), p.b()] {
                polys.extend(leading_minors(m.numerators()));
            }
            polys.retain(|q| !q.is_zero());
            let candidates = crate::motion::real_roots_of_all(&polys, &unlimited).unwrap();
            let samples = crate::motion::samples_between(&candidates, None, None);
            let states: Vec<SolidState> = samples
                .iter()
                .map(|s| state_at_rational(&p, s, &unlimited).unwrap())
                .collect();
            for (j, t) in candidates.iter().enumerate() {
                if t.as_rational().is_some() {
                    continue;
                }
                let between = state_between(&p, t, &states[j], &states[j + 1], &unlimited);
                match between.unwrap() {
                    Some(s) => {
                        assert_eq!(s, state_at_irrational(&p, t, &unlimited).unwrap(), "{t}");
                        *answered.entry(s.key()).or_insert(0) += 1;
                    }
                    None => declined += 1,
                }
            }
        }
        assert!(
            answered.get("separated").is_some_and(|&n| n >= 4)
                && answered.contains_key("touching_externally")
                && declined > 0,
            "{answered:?}, {declined} declined"
        );
    }

    /// The `ℚ(α)` route given a rational `α` agrees with the rational route (the static
    /// [`solid_relation`]) at every sample of several motions, every relation occurring.
    #[test]
    fn number_field_route_agrees_with_the_rational_route() {
        let motions = [
            ("x^2 + y^2 + z^2 - 4", "(x - t)^2 + (y - 1/2)^2 + z^2 - 1"),
            ("x^2/4 + y^2 + z^2 - 1", "(x - t)^2 + 4*y^2 + 4*z^2 - 1"),
            ("x^2 + y^2 + z^2 - 1", "x^2 + 2*y^2 + 3*z^2 - t^2"),
            ("x^2 + y^2 + z^2 - 1", "-(x - t)^2 - y^2/t - z^2 + 1"),
            ("2*x^2 + y^2 + z^2 - 1", "(x - t)^2 + y^2 + z^2 - t*y - 1"),
            ("x^2 + y^2 + z^2 - 1", "t*(x^2 + y^2 + z^2) - 1"),
        ];
        let mut seen = std::collections::HashSet::new();
        let mut compared = 0;
        for (a, b) in motions {
            let p = MovingPencil::new(moving(a).unwrap(), moving(b).unwrap()).unwrap();
            for n in -16..=16 {
                let t = RBig::from_parts_signed(n.into(), 4u8.into());
                let unlimited = Budget::unlimited();
                let rational = state_at_rational(&p, &t, &unlimited).unwrap();
                let via_field =
                    state_at_irrational(&p, &AlgebraicReal::from_rational(t.clone()), &unlimited)
                        .unwrap();
                match (&rational, &via_field) {
                    // the messages name the same quadric and kind
                    (SolidState::NotEllipsoids(x), SolidState::NotEllipsoids(y)) => {
                        assert_eq!(x.get(..1), y.get(..1), "{a} | {b} at {t}: {x} / {y}")
                    }
                    _ => assert_eq!(rational, via_field, "{a} | {b} at {t}"),
                }
                seen.insert(rational.key());
                compared += 1;
            }
        }
        assert!(compared > 150 && seen.len() >= 7, "{compared} {seen:?}");
    }
}
