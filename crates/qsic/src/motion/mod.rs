//! Moving quadrics: the instants where the intersection of `A(t)` and `B(t)` changes type,
//! and the type on every interval between them and at every instant, exactly.
//!
//! The pencil is `λM_A(t) − μM_B(t)` with the numerator matrices of the two
//! [`MovingMatrix`] values, whose canonical form has the denominators cleared and the gcd
//! of all entries divided out (so the quadric at a pole, or at a common root of all
//! entries, is the limit),
//! and `f(λ; t) = det(λM_A − M_B) ∈ ℤ[t][λ]`. Following Jia, Wang, Choi, Mourrain, Tu
//! (Theorems 3.2–3.12, Algorithms 1–3), the class of a regular pencil is constant wherever
//! the Segre characteristic is, and that changes only at the real roots of
//! ([`MovingPencil::candidate_instants`], a superset, module `instants`):
//! - the `t`-content of `f` (`f(·; t₀) ≡ 0`: a singular pencil at `t₀`);
//! - the discriminant of each square-free factor `gᵢ` of `f` over `ℚ(t)` (as binary forms in
//!   `(λ, μ)`, so `λ = ∞` is not special) and the resultants `Res(gᵢ, gⱼ)`;
//! - when `f` has a repeated factor for all `t`: for `k = 1, 2, 3`, where the `k×k` minors
//!   of `λM_A − μM_B` divided by their generic gcd `D_k` share a root (a Jordan structure
//!   change: the rank conditions of Algorithms 1–2, without case analysis);
//! - the denominators, and the common roots of all `2×2` minors of the pair (`M_A ∝ M_B`);
//! - for a pencil singular for every `t`, the same with the generic gcd `D_r` of the `r×r`
//!   minors in place of `f` (`r` the generic rank), the rank conditions always, and where
//!   `[M_A; M_B]` loses rank (a new common singular point).
//!
//! [`MovingPencil::variations`] classifies at a rational sample of every open interval and at
//! every candidate — exactly, by [`classify()`](crate::classify()) at rational instants and by
//! arithmetic in `ℚ(α)` at irrational ones (module `irrational`) — then drops the candidates
//! whose type equals that of both neighbours and merges the intervals around them.
//!
//! **Work budget.** [`MovingPencil::variations_within`] (and the `_within` forms of
//! [`contact`]) spend a caller's [`Budget`]: the candidate stage per gcd step and per
//! determinant (its estimate before it starts, module `instants`), the square-free parts
//! and root isolation per step, the classifications at rational instants as
//! [`crate::classify_within`], the irrational instants per step of their enclosures and
//! remainder sequences; over it, [`Error::BudgetExceeded`]. The plain forms spend
//! [`Budget::unlimited`].
//!
//! [`contact`]: the first contact of the two quadrics in a range, and the relation of two
//! moving solid ellipsoids along the motion. [`TimeRange`]: the range of `t`, and its one
//! reading from text (`-oo`/`oo` for an open side). [`rigid`]: a quadric under a rigid motion
//! rational in `t` (Cayley or quaternion rotation, polynomial translation) as a moving matrix.

pub mod contact;
mod contact_point;
mod contact_point_fast;
mod ellipsoid_contact;
mod instants;
mod irrational;
mod irrational_fast;
mod range;
pub mod rigid;
mod shared_roots;

pub use contact::{first_contact, solid_motion, FirstContact, SolidMotion, SolidState};
pub use instants::DeterminantRoute;
pub use range::{TimeRange, MINUS_INFINITY, PLUS_INFINITY};

use crate::classify::{classify_allowing_zero_within, Classification};
use crate::error::Error;
use crate::io::MovingMatrix;
use crate::limits::{MAX_MOTION_COEFFICIENT_BITS, MAX_MOTION_DEGREE};
use instants::{
    common_kernel_condition, discriminant_form, generic_gcd, pencil_entries, rank_conditions,
    resultant_forms, squarefree_decomposition_t, t_content, t_primitive, tpoly_product_units, Form,
    RankConditionError, TPoly,
};
use qsic_algebra::budget::{Budget, Exhausted};
use qsic_algebra::matrix::MatrixPencil;
use qsic_algebra::{AlgebraicReal, IBig, Poly, RBig};
use std::sync::OnceLock;

/// Two moving quadrics `A(t)`, `B(t)` and their characteristic polynomial
/// `f(λ; t) = det(λM_A(t) − M_B(t))`.
#[derive(Clone, Debug)]
pub struct MovingPencil {
    /// `A`, `B`; their numerators `M_A`, `M_B` have no common factor (so neither vanishes
    /// at any `t`).
    a: MovingMatrix,
    b: MovingMatrix,
    entries: [[TPoly; 4]; 4],
    /// `λM_A(t) − M_B(t)` over ℤ\[t\] with every minor, as polynomials in `λ`.
    pencil: MatrixPencil<Poly>,
    f: TPoly,
    /// The polynomials in `λ` over `ℤ[t]` the fast route at irrational instants reads, made
    /// when first needed ([`Self::fast_polys`]): a motion without irrational instants to
    /// classify never pays for their subresultants.
    polys: OnceLock<irrational_fast::PencilPolys>,
    /// How its determinants over `ℤ[t]` are computed ([`Self::with_determinant_route`]).
    route: DeterminantRoute,
    /// The zero tests of the generic condition at the irrational candidates, shared between
    /// the roots of one polynomial.
    zero_tests: shared_roots::ZeroTests,
}

/// The type compared between neighbours: pencil kind, case, complex and real type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct MotionType {
    /// `regular`, `singular` or `single`.
    pub pencil: &'static str,
    /// The case 1–35 of a regular pencil.
    pub case: Option<u8>,
    /// The complex type key.
    pub complex_type: Option<&'static str>,
    /// The real type key.
    pub real_type: Option<&'static str>,
}

impl MotionType {
    /// The type of a classification.
    pub fn of(c: &Classification) -> MotionType {
        MotionType {
            pencil: c.pencil.key(),
            case: c.case,
            complex_type: c.complex_type(),
            real_type: c.real_type(),
        }
    }
}

/// The classification at an instant.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum InstantType {
    /// Classified exactly.
    Exact(Classification),
    /// An irrational instant the exact `ℚ(α)` route could not classify (kept, never guessed):
    /// a regular pencil whose root isolation over `ℚ(α)` exceeds its step budget. Single and
    /// singular pencils at `α` are always classified.
    IrrationalUnclassified,
}

impl InstantType {
    /// The classification, if known.
    pub fn classification(&self) -> Option<&Classification> {
        match self {
            InstantType::Exact(c) => Some(c),
            InstantType::IrrationalUnclassified => None,
        }
    }
}

/// An open interval of `t` on which the type is constant.
#[derive(Clone, Debug)]
pub struct MotionInterval {
    /// Left end, `None` for `−∞`.
    pub from: Option<AlgebraicReal>,
    /// Right end, `None` for `+∞`.
    pub to: Option<AlgebraicReal>,
    /// The rational `t` at which it was classified.
    pub sample: RBig,
    /// The classification on the interval.
    pub classification: Classification,
}

/// An instant where the type differs from the type just before or just after.
#[derive(Clone, Debug)]
pub struct MotionInstant {
    /// The instant (rational ones exact).
    pub t: AlgebraicReal,
    /// Its type.
    pub class: InstantType,
}

/// The variations of the intersection along the motion: on the whole line, `intervals[i]`
/// ends at `instants[i]` and `intervals[i + 1]` starts there; on a range
/// ([`MovingPencil::variations_in`]) an end of the range may come first or last among the
/// instants, outside every interval.
#[derive(Clone, Debug)]
pub struct Motion {
    /// The intervals, increasing.
    pub intervals: Vec<MotionInterval>,
    /// The instants, increasing.
    pub instants: Vec<MotionInstant>,
}

impl MovingPencil {
    /// The pencil of two moving quadrics; computes every minor of `λM_A − M_B` over `ℤ[t]`
    /// once (`MatrixPencil<Poly>`), `f(λ; t)` among them.
    ///
    /// `M_A`, `M_B` are the numerator matrices ([`MovingMatrix::numerators`]), without the
    /// factor `g(t)` common to all entries: it scales the quadric by `g(t)`, which does not
    /// change the pencil where `g(t) ≠ 0`, and at a root of `g` the quadric is the limit
    /// (as at a pole).
    ///
    /// # Errors
    /// [`Error::Limit`] if an entry of `M_A` or `M_B` (denominators cleared, common factor
    /// divided out) has a degree above [`MAX_MOTION_DEGREE`] or a coefficient of more than
    /// [`MAX_MOTION_COEFFICIENT_BITS`] bits: the analysis takes resultants of polynomials of
    /// degree up to `24·MAX_MOTION_DEGREE` in `t`.
    ///
    /// # Examples
    /// ```
    /// use qsic::io::moving_matrix_from_polynomial;
    /// use qsic::motion::MovingPencil;
    ///
    /// // A unit sphere centred at (t, 0, 0) and the sphere of radius 2 at the origin: the
    /// // type changes at t = ±3 (outer tangency), ±1 (inner tangency) and 0 (concentric).
    /// let a = moving_matrix_from_polynomial("x^2 + y^2 + z^2 - 4")?;
    /// let b = moving_matrix_from_polynomial("(x - t)^2 + y^2 + z^2 - 1")?;
    /// let motion = MovingPencil::new(a, b)?.variations()?;
    /// let ts: Vec<f64> = motion.instants.iter().map(|i| i.t.to_f64()).collect();
    /// assert_eq!(ts, [-3.0, -1.0, 0.0, 1.0, 3.0]);
    /// assert_eq!(motion.intervals.len(), 6);
    /// # Ok::<(), qsic::Error>(())
    /// ```
    pub fn new(a: MovingMatrix, b: MovingMatrix) -> Result<MovingPencil, Error> {
        MovingPencil::new_within(a, b, &Budget::unlimited())
    }

    /// [`Self::new`] spending `budget`: the minors of `λM_A − M_B` over `ℤ[t]`, their units
    /// ([`minors_units`]) before they are formed, so a small budget stops before the work.
    ///
    /// # Errors
    /// As [`Self::new`]; [`Error::BudgetExceeded`] when the budget runs out.
    pub fn new_within(
        a: MovingMatrix,
        b: MovingMatrix,
        budget: &Budget,
    ) -> Result<MovingPencil, Error> {
        let (ma, mb) = (a.numerators(), b.numerators());
        for m in [ma, mb] {
            check_motion_size(m)?;
        }
        budget.spend(minors_units(ma, mb))?;
        let entries = pencil_entries(ma, mb);
        let pencil = MatrixPencil::from_entries(ma.clone(), mb.clone());
        let f = pencil.det_poly();
        Ok(MovingPencil {
            a,
            b,
            entries,
            pencil,
            f,
            polys: OnceLock::new(),
            route: DeterminantRoute::Fastest,
            zero_tests: shared_roots::ZeroTests::default(),
        })
    }

    /// The same pencil computing its determinants over `ℤ[t]` by `route` (the default is
    /// [`DeterminantRoute::Fastest`]; [`DeterminantRoute::Bareiss`] is the reference the
    /// tests compare it with). Every answer is the same on both routes; only the time and
    /// the units spent differ.
    pub fn with_determinant_route(self, route: DeterminantRoute) -> MovingPencil {
        MovingPencil {
            route,
            polys: OnceLock::new(),
            ..self
        }
    }

    /// `A(t)`.
    pub fn a(&self) -> &MovingMatrix {
        &self.a
    }

    /// `B(t)`.
    pub fn b(&self) -> &MovingMatrix {
        &self.b
    }

    /// `M_A(t)` and `M_B(t)`: the numerator matrices of `A`, `B`, without a factor common
    /// to all entries ([`Self::new`]); the pencil at `t` is `λM_A(t) − μM_B(t)`.
    pub fn numerators(&self) -> (&[[Poly; 4]; 4], &[[Poly; 4]; 4]) {
        (self.a.numerators(), self.b.numerators())
    }

    /// `f(λ; t) = det(λM_A(t) − M_B(t))` in `ℤ[t][λ]` (coefficients in `λ`, each a polynomial
    /// in `t`).
    pub fn characteristic(&self) -> &Poly<Poly> {
        &self.f
    }

    /// The exact classification at a rational `t`: of `M_A(t)`, `M_B(t)`, so the limit
    /// quadric at a pole or at a common root of all entries.
    ///
    /// # Errors
    /// None in practice: `M_A(t)` and `M_B(t)` never vanish (their entries have no common
    /// root); [`Error::ZeroQuadric`] would name that case.
    pub fn classify_at(&self, t: &RBig) -> Result<Classification, Error> {
        self.classify_at_within(t, &Budget::unlimited())
    }

    /// [`Self::classify_at`] spending `budget`: the evaluation of the entries at `t` (per
    /// coefficient, by the sizes of `t` and the coefficients), then
    /// [`crate::classify_within`].
    ///
    /// # Errors
    /// As [`Self::classify_at`]; [`Error::BudgetExceeded`] when the budget runs out.
    pub fn classify_at_within(&self, t: &RBig, budget: &Budget) -> Result<Classification, Error> {
        use dashu_int::ops::BitTest;
        let t_bits = t.numerator().bit_len() + t.denominator().bit_len();
        for e in self.entries.iter().flatten().flat_map(|p| p.coeffs()) {
            let d = e.degree().unwrap_or(0);
            let units = qsic_algebra::budget::product_units(e.max_bits() + d * t_bits, t_bits);
            budget.spend((d as u64 + 1).saturating_mul(units))?;
        }
        let at = |m: &[[Poly; 4]; 4]| {
            optional(crate::Quadric::from_matrix(std::array::from_fn(|i| {
                std::array::from_fn(|j| m[i][j].eval_rational(t))
            })))
        };
        let (qa, qb) = (at(self.a.numerators())?, at(self.b.numerators())?);
        classify_allowing_zero_within(qa.as_ref(), qb.as_ref(), budget)
    }

    /// Polynomials in `t` whose real roots contain every instant where the type can change
    /// (module docs); each nonzero, possibly constant.
    ///
    /// For a pencil singular for every `t` (`f ≡ 0`, generic rank `r < 4`), the role of `f`
    /// is played by the generic gcd `D_r` of the `r×r` minors (the determinant of the
    /// regular part of the Kronecker form), the rank conditions are always added, and so is
    /// the condition that `M_A`, `M_B` gain a common kernel vector (the rank of the stacked
    /// `8×4` matrix drops): the data the singular classification reads.
    ///
    /// # Errors
    /// [`Error::UnsupportedMotion`] if no integer combination of the `k×k` minors separates
    /// their common roots (not expected).
    pub fn candidate_polynomials(&self) -> Result<Vec<Poly>, Error> {
        self.candidate_polynomials_within(&Budget::unlimited())
    }

    /// [`Self::candidate_polynomials`] spending `budget` (module docs).
    ///
    /// # Errors
    /// As [`Self::candidate_polynomials`]; [`Error::BudgetExceeded`] when the budget runs
    /// out.
    pub fn candidate_polynomials_within(&self, budget: &Budget) -> Result<Vec<Poly>, Error> {
        Ok(self.candidates_and_generic_condition(budget)?.0)
    }

    /// [`Self::candidate_polynomials`], and for a pencil whose `f` is square-free over `ℚ(t)`
    /// of degree 4 in `λ`, the polynomial `G = content(f)·Δ` (`Δ` the discriminant of `f`
    /// as a binary quartic form) where `G(t₀) ≠ 0` says that `f(λ, μ; t₀)` has four
    /// distinct roots in `ℙ¹`: the Segre characteristic `[1111]` at `t₀` and around it, so
    /// the type at `t₀` is that of both neighbouring intervals (Theorem 3.2) and `t₀` is
    /// never an instant where it changes.
    fn candidates_and_generic_condition(
        &self,
        budget: &Budget,
    ) -> Result<(Vec<Poly>, Option<Poly>), Error> {
        let rank = (1..=4)
            .rev()
            .find(|&k| self.pencil.minors(k).iter().any(|m| !m.is_zero()))
            .unwrap_or(0);
        if rank == 0 {
            // both zero matrices: refused by the readers, named here for completeness
            return Err(Error::ZeroQuadric);
        }
        let mut out = Vec::new();
        // The characteristic form (chart, formal degree): `f`, or `D_r` for a singular pencil.
        let (chi, degree) = if rank == 4 {
            out.push(t_content(&self.f, budget)?);
            (t_primitive(&self.f, budget)?, 4)
        } else {
            let (g, at_infinity) = generic_gcd(&self.pencil.minors(rank), rank, budget)?;
            let d = g.degree().unwrap_or(0) + at_infinity;
            (g, d)
        };
        let mut forms: Vec<(Form, usize)> = squarefree_decomposition_t(&chi, budget)?
            .into_iter()
            .map(|(g, m)| {
                let degree = g.degree().unwrap_or(0);
                (Form { chart: g, degree }, m)
            })
            .collect();
        let m_inf = degree - chi.degree().unwrap_or(0);
        if m_inf > 0 {
            let mu = Form {
                chart: TPoly::constant(Poly::constant(IBig::ONE)),
                degree: 1,
            };
            forms.push((mu, m_inf));
        }
        let mut generic = None;
        for (i, (g, _)) in forms.iter().enumerate() {
            let discriminant = discriminant_form(g, self.route, budget)?;
            if let ([(g, 1)], Some(d)) = (forms.as_slice(), &discriminant) {
                if g.degree == 4 && rank == 4 {
                    generic = Some(d * &out[0]);
                }
            }
            out.extend(discriminant);
            for (h, _) in &forms[i + 1..] {
                out.push(resultant_forms(g, h, self.route, budget)?);
            }
        }
        if rank < 4 || forms.iter().any(|(_, m)| *m > 1) {
            for k in 1..=3 {
                let conditions = rank_conditions(&self.pencil.minors(k), k, self.route, budget)
                    .map_err(|e| match e {
                        RankConditionError::NoSeparatingCombination(why) => {
                            Error::UnsupportedMotion(why)
                        }
                        RankConditionError::Exhausted(e) => e.into(),
                    })?;
                out.extend(conditions);
            }
        }
        if rank < 4 {
            out.push(common_kernel_condition(
                self.a.numerators(),
                self.b.numerators(),
                self.route,
                budget,
            )?);
        }
        out.push(self.a.denominator().clone());
        out.push(self.b.denominator().clone());
        // M_A ∝ M_B where every 2×2 minor of the pair of coefficient vectors vanishes.
        let (va, vb): (Vec<&Poly>, Vec<&Poly>) = (
            self.a.numerators().iter().flatten().collect(),
            self.b.numerators().iter().flatten().collect(),
        );
        let mut prop = Poly::zero();
        'pairs: for i in 0..16 {
            for j in i + 1..16 {
                budget.spend(tpoly_product_units(va[i], vb[j]).saturating_mul(2))?;
                prop = prop.gcd_within(&(&(va[i] * vb[j]) - &(va[j] * vb[i])), budget)?;
                if prop.degree() == Some(0) {
                    break 'pairs;
                }
            }
        }
        out.push(prop);
        out.retain(|p| !p.is_zero());
        Ok((out, generic.filter(|g| !g.is_zero())))
    }

    /// The candidate instants: the distinct real roots of [`Self::candidate_polynomials`], in
    /// increasing order. Each is given by a square-free integer polynomial (an element of a
    /// gcd-free basis of the candidate polynomials, without its rational roots) and an
    /// isolating interval; rational ones are exact.
    ///
    /// # Errors
    /// As [`Self::candidate_polynomials`].
    pub fn candidate_instants(&self) -> Result<Vec<AlgebraicReal>, Error> {
        let unlimited = Budget::unlimited();
        Ok(real_roots_of_all(
            &self.candidate_polynomials_within(&unlimited)?,
            &unlimited,
        )?)
    }

    /// The type on every interval between consecutive instants and at every instant, with
    /// the instants where nothing changes dropped and their intervals merged (module docs):
    /// [`Self::variations_in`] on the whole real line.
    ///
    /// # Errors
    /// As [`Self::candidate_polynomials`].
    pub fn variations(&self) -> Result<Motion, Error> {
        self.variations_in(None, None)
    }

    /// The variations on the closed range `[from, to]` (`None`: unbounded on that side).
    ///
    /// The intervals cover the open range: the first starts at `from`, the last ends at
    /// `to`, and the instants strictly inside separate them as in [`Self::variations`]. An
    /// end of the range is reported as an instant (first or last) only where the type there
    /// differs from the type on the interval beside it (a range starting at a contact
    /// instant starts with that contact). A range with `from = to` has no interval and that
    /// one instant.
    ///
    /// # Errors
    /// [`Error::InvalidRange`] if `from > to`; otherwise as [`Self::variations`].
    ///
    /// # Examples
    /// ```
    /// use dashu_ratio::RBig;
    /// use qsic::io::moving_matrix_from_polynomial;
    /// use qsic::motion::MovingPencil;
    ///
    /// let a = moving_matrix_from_polynomial("x^2 + y^2 + z^2 - 4")?;
    /// let b = moving_matrix_from_polynomial("(x - t)^2 + y^2 + z^2 - 1")?;
    /// let pencil = MovingPencil::new(a, b)?;
    /// // On [1, 2]: the inner tangency at t = 1, then one interval (a circle) up to 2.
    /// let m = pencil.variations_in(Some(&RBig::ONE), Some(&RBig::from(2)))?;
    /// assert_eq!(m.instants.len(), 1);
    /// assert_eq!(m.instants[0].t.as_rational(), Some(&RBig::ONE));
    /// assert_eq!(m.intervals.len(), 1);
    /// assert_eq!(m.intervals[0].classification.real_type(), Some("one_conic"));
    /// # Ok::<(), qsic::Error>(())
    /// ```
    pub fn variations_in(&self, from: Option<&RBig>, to: Option<&RBig>) -> Result<Motion, Error> {
        self.variations_within(from, to, &Budget::unlimited())
    }

    /// [`Self::variations_in`] spending `budget` (module docs).
    ///
    /// # Errors
    /// As [`Self::variations_in`]; [`Error::BudgetExceeded`] when the budget runs out.
    ///
    /// # Examples
    /// ```
    /// use qsic::io::moving_matrix_from_polynomial;
    /// use qsic::motion::MovingPencil;
    /// use qsic::{Budget, Error};
    ///
    /// let a = moving_matrix_from_polynomial("x^2 + y^2 + z^2 - 4")?;
    /// let b = moving_matrix_from_polynomial("(x - t)^2 + y^2 + z^2 - 1")?;
    /// let pencil = MovingPencil::new(a, b)?;
    /// let budget = Budget::unlimited();
    /// assert_eq!(pencil.variations_within(None, None, &budget)?.instants.len(), 5);
    /// let spent = budget.used();
    /// // the same work with one unit less runs out, deterministically
    /// let short = pencil.variations_within(None, None, &Budget::new(spent - 1));
    /// assert!(matches!(short, Err(Error::BudgetExceeded { .. })));
    /// # Ok::<(), qsic::Error>(())
    /// ```
    pub fn variations_within(
        &self,
        from: Option<&RBig>,
        to: Option<&RBig>,
        budget: &Budget,
    ) -> Result<Motion, Error> {
        let exact = |v: &RBig| AlgebraicReal::from_rational(v.clone());
        let (lo, hi) = (from.map(exact), to.map(exact));
        range::check_order(from, to)?;
        if let (Some(a), Some(b)) = (from, to) {
            if a == b {
                let t = exact(a);
                return Ok(Motion {
                    intervals: Vec::new(),
                    instants: vec![MotionInstant {
                        t,
                        class: InstantType::Exact(self.classify_at_within(a, budget)?),
                    }],
                });
            }
        }
        let (polys, generic) = self.candidates_and_generic_condition(budget)?;
        let candidates: Vec<AlgebraicReal> = real_roots_of_all(&polys, budget)?
            .into_iter()
            .filter(|c| lo.as_ref().is_none_or(|a| a < c) && hi.as_ref().is_none_or(|b| c < b))
            .collect();
        let samples = samples_between(&candidates, lo.as_ref(), hi.as_ref());
        let mut interval_types = Vec::with_capacity(samples.len());
        for s in &samples {
            interval_types.push(self.classify_at_within(s, budget)?);
        }
        // `None`: an irrational candidate where `f` has four distinct roots, of the type of
        // both neighbours (`candidates_and_generic_condition`), not classified
        let mut instant_types = Vec::with_capacity(candidates.len());
        for c in &candidates {
            let generic_here = match (c.as_rational(), &generic) {
                (None, Some(g)) => !self.zero_tests.is_root(c, g, budget)?,
                _ => false,
            };
            instant_types.push(match c.as_rational() {
                Some(v) => Some(InstantType::Exact(self.classify_at_within(v, budget)?)),
                None if generic_here => None,
                None => Some(
                    self.classify_at_irrational(c, budget)?
                        .map_or(InstantType::IrrationalUnclassified, InstantType::Exact),
                ),
            });
        }
        let mut intervals = vec![MotionInterval {
            from: lo.clone(),
            to: None,
            sample: samples[0].clone(),
            classification: interval_types[0].clone(),
        }];
        let mut instants = Vec::new();
        for (j, (t, class)) in candidates.into_iter().zip(instant_types).enumerate() {
            let right = &interval_types[j + 1];
            let left = &intervals
                .last()
                .expect("one interval at least")
                .classification;
            let class = match class {
                Some(class) => class,
                // the theorem says both neighbours have the same type; were they to
                // differ, the instant is classified all the same
                None if MotionType::of(left) == MotionType::of(right) => continue,
                None => self
                    .classify_at_irrational(&t, budget)?
                    .map_or(InstantType::IrrationalUnclassified, InstantType::Exact),
            };
            let unchanged = class.classification().is_some_and(|c| {
                MotionType::of(c) == MotionType::of(left)
                    && MotionType::of(c) == MotionType::of(right)
            });
            if unchanged {
                continue;
            }
            intervals.last_mut().expect("one interval at least").to = Some(t.clone());
            intervals.push(MotionInterval {
                from: Some(t.clone()),
                to: None,
                sample: samples[j + 1].clone(),
                classification: right.clone(),
            });
            instants.push(MotionInstant { t, class });
        }
        intervals.last_mut().expect("one interval at least").to = hi.clone();
        // The ends of the range, where their type differs from the interval beside them.
        for (end, first) in [(from, true), (to, false)] {
            let Some(v) = end else { continue };
            let c = self.classify_at_within(v, budget)?;
            let beside = if first {
                intervals.first()
            } else {
                intervals.last()
            };
            let beside = &beside.expect("one interval at least").classification;
            if MotionType::of(&c) != MotionType::of(beside) {
                let instant = MotionInstant {
                    t: exact(v),
                    class: InstantType::Exact(c),
                };
                if first {
                    instants.insert(0, instant);
                } else {
                    instants.push(instant);
                }
            }
        }
        Ok(Motion {
            intervals,
            instants,
        })
    }
}

impl MovingPencil {
    /// The class at an irrational instant: the one dispatch point between the fast route
    /// (module `irrational_fast`: one double root, certified signs) and the reference
    /// (module `irrational`), which answers whatever the fast route hands back.
    pub(super) fn classify_at_irrational(
        &self,
        alpha: &AlgebraicReal,
        budget: &Budget,
    ) -> Result<Option<Classification>, Exhausted> {
        match irrational_fast::classify_at_irrational_fast(self.fast_polys(budget)?, alpha, budget)?
        {
            Some(c) => Ok(Some(c)),
            None => irrational::classify_at_irrational(&self.entries, alpha, budget),
        }
    }
}

impl MovingPencil {
    /// The polynomials of the fast route at irrational instants, made on first use spending
    /// `budget` (their subresultants over `ℤ[t]`).
    pub(crate) fn fast_polys(
        &self,
        budget: &Budget,
    ) -> Result<&irrational_fast::PencilPolys, Exhausted> {
        if let Some(p) = self.polys.get() {
            return Ok(p);
        }
        let made = irrational_fast::PencilPolys::of(&self.pencil, self.route, budget)?;
        Ok(self.polys.get_or_init(|| made))
    }
}

/// `Ok(None)` for the zero quadric (allowed on one side of a pencil).
fn optional(q: Result<crate::Quadric, Error>) -> Result<Option<crate::Quadric>, Error> {
    match q {
        Ok(q) => Ok(Some(q)),
        Err(Error::ZeroQuadric) => Ok(None),
        Err(e) => Err(e),
    }
}

/// Rational samples of the intervals cut by the candidates `c` in the range `(lo, hi)`
/// (`None`: unbounded): one between each two consecutive ends, one left of the first end or
/// right of the last on an unbounded side (`0` with neither candidates nor ends).
fn samples_between(
    c: &[AlgebraicReal],
    lo: Option<&AlgebraicReal>,
    hi: Option<&AlgebraicReal>,
) -> Vec<RBig> {
    let ends: Vec<&AlgebraicReal> = lo.into_iter().chain(c).chain(hi).collect();
    let (Some(first), Some(last)) = (ends.first(), ends.last()) else {
        return vec![RBig::ZERO];
    };
    let mut out = Vec::with_capacity(c.len() + 1);
    if lo.is_none() {
        out.push(RBig::from(first.interval().lo().floor() - IBig::ONE));
    }
    for w in ends.windows(2) {
        out.push(w[0].rational_between(w[1]));
    }
    if hi.is_none() {
        out.push(RBig::from(last.interval().hi().ceil() + IBig::ONE));
    }
    out
}

/// The units of every minor of `λM_A − M_B` over `ℤ[t]` ([`MatrixPencil::from_entries`]:
/// the minors of the members `M_A`, `−M_B`, `±M_A − M_B` and the determinant of
/// `2M_A − M_B`, by expansion along `2×2` minors): per member, `72` products of two entries
/// for the `2×2` minors, `48` of a `2×2` minor by an entry for the `3×3` ones and `4` of a
/// `3×3` minor by an entry for the determinant, each [`tpoly_product_units`]-sized (an entry
/// of degree `d`, `b + 2` bits: a member's entries are sums of two).
fn minors_units(a: &[[Poly; 4]; 4], b: &[[Poly; 4]; 4]) -> u64 {
    let (d, bits) = a.iter().chain(b).flatten().fold((0, 0), |(d, bits), e| {
        (d.max(e.degree().unwrap_or(0)), bits.max(e.max_bits()))
    });
    let bits = bits + 2;
    let product = |k: usize| -> u64 {
        // a k×k minor (degree k·d, about k·bits bits) times an entry
        ((k * d + 1) as u64 * (d + 1) as u64)
            .saturating_mul(qsic_algebra::budget::product_units(k * bits, bits))
    };
    let member = (72 * product(1))
        .saturating_add(48 * product(2))
        .saturating_add(4 * product(3));
    member.saturating_mul(5)
}

/// [`Error::Limit`] if an entry of `m` exceeds [`MAX_MOTION_DEGREE`] or a coefficient
/// [`MAX_MOTION_COEFFICIENT_BITS`].
fn check_motion_size(m: &[[Poly; 4]; 4]) -> Result<(), Error> {
    for e in m.iter().flatten() {
        let degree = e.degree().unwrap_or(0);
        if degree > MAX_MOTION_DEGREE {
            return Err(Error::Limit {
                what: format!("degree {degree} in t of an entry of a moving pencil"),
                limit: MAX_MOTION_DEGREE,
            });
        }
        let bits = e.max_bits();
        if bits > MAX_MOTION_COEFFICIENT_BITS {
            return Err(Error::Limit {
                what: format!("{bits} bits of a coefficient of a moving pencil"),
                limit: MAX_MOTION_COEFFICIENT_BITS,
            });
        }
    }
    Ok(())
}

/// The distinct real roots of the nonzero `polys`, increasing: each given by a square-free
/// primitive polynomial (an element of their gcd-free basis without its rational roots) and
/// an isolating interval; rational ones exact.
fn real_roots_of_all(polys: &[Poly], budget: &Budget) -> Result<Vec<AlgebraicReal>, Exhausted> {
    let mut roots = Vec::new();
    for p in gcd_free_basis(polys, budget)? {
        let all = AlgebraicReal::real_roots_of_within(&p, budget)?;
        let mut rest = p.clone();
        for r in &all {
            if let Some(v) = r.as_rational() {
                budget.spend(qsic_algebra::budget::poly_step_units(
                    rest.degree().unwrap_or(0),
                    rest.max_bits(),
                ))?;
                rest = rest
                    .div_exact(&Poly::vanishing_at(v))
                    .expect("a rational root's linear factor divides");
            }
        }
        for r in all {
            if r.as_rational().is_some() {
                roots.push(r);
            } else {
                let reduced = AlgebraicReal::from_isolating_interval(&rest, r.interval());
                roots.push(reduced.unwrap_or(r));
            }
        }
    }
    roots.sort();
    roots.dedup();
    Ok(roots)
}

/// A gcd-free basis of the square-free parts of `polys`: pairwise coprime, square-free,
/// primitive polynomials of positive degree with the same roots as the product.
fn gcd_free_basis(polys: &[Poly], budget: &Budget) -> Result<Vec<Poly>, Exhausted> {
    let mut basis: Vec<Poly> = Vec::new();
    for p in polys {
        if p.degree().unwrap_or(0) == 0 {
            continue;
        }
        let mut p = p.squarefree_part_within(budget)?;
        let mut next = Vec::with_capacity(basis.len() + 2);
        for b in basis {
            let g = p.gcd_within(&b, budget)?;
            if g.degree().unwrap_or(0) == 0 {
                next.push(b);
                continue;
            }
            budget.spend(
                qsic_algebra::poly::gcd::prem_units(&b, &g)
                    .saturating_add(qsic_algebra::poly::gcd::prem_units(&p, &g)),
            )?;
            let rest = b.div_exact(&g).expect("gcd divides");
            p = p.div_exact(&g).expect("gcd divides");
            if rest.degree().unwrap_or(0) > 0 {
                next.push(rest.primitive_part());
            }
            next.push(g);
        }
        if p.degree().unwrap_or(0) > 0 {
            next.push(p.primitive_part());
        }
        basis = next;
    }
    Ok(basis)
}

/// The lines of the moving corpus (`tests/data/moving.jsonl`) as `(id, A, B)`, for the tests
/// that hold an accelerator equal to its reference on every line.
#[cfg(test)]
pub(crate) fn moving_corpus() -> Vec<(String, MovingMatrix, MovingMatrix)> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/moving.jsonl");
    let text = std::fs::read_to_string(path).expect("the moving corpus");
    let entry = |v: &serde_json::Value| -> String {
        match v {
            serde_json::Value::String(s) => s.clone(),
            other => other.to_string(),
        }
    };
    let mut out = Vec::new();
    for line in text.lines().filter(|l| !l.trim().is_empty()) {
        let d: serde_json::Value = serde_json::from_str(line).expect("a JSON line");
        let m = |key: &str| {
            let rows: Vec<Vec<String>> = d[key]
                .as_array()
                .expect("a matrix")
                .iter()
                .map(|r| r.as_array().expect("a row").iter().map(entry).collect())
                .collect();
            crate::io::moving_matrix_from_rows(&rows).expect("a moving matrix")
        };
        out.push((d["id"].as_str().expect("an id").to_string(), m("A"), m("B")));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::moving_matrix_from_polynomial;

    /// The `ℚ(α)` route given a rational `α` agrees in full with the rational classifier,
    /// at instants and between them, for regular pencils of several motions.
    #[test]
    fn number_field_route_agrees_with_the_rational_classifier() {
        let motions = [
            ("x^2 + y^2 + z^2 - 4", "(x - t)^2 + y^2 + z^2 - 1"),
            (
                "x^2 - y^2 - 2*z*w",
                "x^2 + t^2*y^2 + (1 - t)*z^2 - 2*t*z*w + w^2",
            ),
            (
                "x^2 + y^2 - z^2 - w^2",
                "x^2/2 + y^2/2 + (z + t*w)^2/2 - w^2",
            ),
            ("x^2 + y^2 - 1", "(x - t)^2 + t*z^2 - 1"),
        ];
        let (mut compared, mut singular) = (0, 0);
        for (a, b) in motions {
            let p = MovingPencil::new(
                moving_matrix_from_polynomial(a).unwrap(),
                moving_matrix_from_polynomial(b).unwrap(),
            )
            .unwrap();
            for n in -12..=12 {
                let t = RBig::from_parts_signed(n.into(), 4u8.into());
                let exact = p.classify_at(&t).unwrap();
                let alpha = AlgebraicReal::from_rational(t.clone());
                let via_field =
                    irrational::classify_at_irrational(&p.entries, &alpha, &Budget::unlimited())
                        .unwrap();
                assert_eq!(via_field.as_ref(), Some(&exact), "{a}, {b} at t = {t}");
                compared += 1;
                singular += usize::from(exact.pencil.key() == "singular");
            }
        }
        assert!(compared > 80 && singular > 0, "{compared}, {singular}");
    }
}
