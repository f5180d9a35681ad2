//! Real algebraic numbers: a square-free integer polynomial and an isolating interval
//! with rational ends, refined on demand. Signs and comparisons are exact.
//!
//! # Refinement kept across calls
//! Each number carries, besides the isolating interval it was made with, a refinement
//! state (the narrowest interval found so far and the speed of quadratic interval
//! refinement) behind an `Arc<Mutex<_>>` shared by its clones. Signs, comparisons and
//! approximations take `&self`, start from that state and store back what they refined, so
//! repeated questions at one number refine once. Why a lock rather than `&mut self`: the
//! number is a value inside other values (`PencilRoot`, `ProjectivePoint`, sorted lists, a
//! number field's context) queried through shared references, across threads; the state
//! only ever narrows, so any stored interval is a valid answer, and a lock is held only to
//! copy the state in or out (never while refining, never two at once: no deadlock, and a
//! poisoned lock still holds a valid state). The stated interval ([`AlgebraicReal::interval`],
//! `Display`) changes only through the `&mut self` methods.
//!
//! # Signs
//! [`AlgebraicReal::sign_of`] first evaluates `q` on the refined interval by Horner's scheme
//! in fixed-point interval arithmetic ([`sign_on_interval`]): once the interval is narrow,
//! a nonzero sign costs `deg q` multiplications of integers of about `log₂(1/width)` bits.
//! Otherwise zero is decided exactly by `gcd(poly, q)` changing sign on the interval, and a
//! nonzero sign by refining until the enclosure excludes zero.
//! [`AlgebraicReal::sign_of_sturm_tarski`] is the refinement-free second route.

use crate::poly::Poly;
use crate::roots::{
    certified_real_roots_enclosed, isolate_squarefree_real_roots_within, refine_step,
    simplest_between, RootInterval, MAX_CERTIFIED_DEGREE,
};
use crate::sign::Sign;
use dashu_int::ops::{BitTest, DivEuclid};
use dashu_int::IBig;
use dashu_ratio::RBig;
use std::cmp::Ordering;
use std::fmt;
use std::sync::{Arc, Mutex, MutexGuard, OnceLock, PoisonError};

/// A real algebraic number `α`.
///
/// Invariant ([`AlgebraicReal::is_valid`]): `poly` is square-free, primitive, of positive
/// degree, and for the stated interval and the refined one alike, either `α` is the rational
/// interval end (`RootInterval::Exact`) or `α` is the only root of `poly` in the open
/// interval, whose ends are not roots.
#[derive(Clone)]
pub struct AlgebraicReal {
    /// The defining polynomial, shared by the roots isolated together (one allocation for
    /// all of them), made on first use when it is a norm.
    poly: Arc<Defining>,
    interval: RootInterval,
    /// The narrowest interval known, shared by clones (module docs).
    refined: Arc<Mutex<Refinement>>,
    /// A float `c` and a rigorous bound `r` with `|α − c| ≤ r`, when the number was isolated
    /// by the certified float path (a cache for [`AlgebraicReal::to_f64`]).
    enclosure: Option<(f64, f64)>,
}

/// The defining polynomial of [`AlgebraicReal`], or what makes it on first use: the roots of
/// `s = A + B√δ` ([`AlgebraicReal::certified_real_roots_zsqrt`]) are isolated without their
/// norm `A² − δB²`, which many callers never read.
struct Defining {
    poly: OnceLock<Poly>,
    /// `A`, `B` (coefficients from degree 0, `len` of them) and `δ` of the norm not made yet.
    norm: Option<([IBig; 5], [IBig; 5], usize, IBig)>,
}

impl Defining {
    fn made(poly: Poly) -> Defining {
        Defining {
            poly: OnceLock::from(poly),
            norm: None,
        }
    }

    fn get(&self) -> &Poly {
        self.poly.get_or_init(|| match &self.norm {
            Some((a, b, len, delta)) => {
                let (a, b): (Vec<&IBig>, Vec<&IBig>) =
                    (a[..*len].iter().collect(), b[..*len].iter().collect());
                norm_zsqrt(&a, &b, delta)
            }
            None => Poly::zero(),
        })
    }
}

/// An isolating interval and the state of its quadratic refinement (see [`refine_step`]).
#[derive(Clone, Debug)]
struct Refinement {
    interval: RootInterval,
    speed: usize,
}

impl Refinement {
    fn new(interval: RootInterval) -> Refinement {
        Refinement { interval, speed: 2 }
    }

    /// One step of quadratic interval refinement (exact values stay).
    fn step(&mut self, poly: &Poly) {
        self.interval = refine_step(poly, &self.interval, &mut self.speed);
    }

    /// `true` if the interval is shorter than `width` (or exact).
    fn is_within(&self, width: &RBig) -> bool {
        match &self.interval {
            RootInterval::Exact(_) => true,
            RootInterval::Open(lo, hi) => &(hi - lo) < width,
        }
    }

    /// `true` if this interval is strictly narrower than `other`'s.
    fn is_narrower_than(&self, other: &Refinement) -> bool {
        match (&self.interval, &other.interval) {
            (_, RootInterval::Exact(_)) => false,
            (RootInterval::Exact(_), _) => true,
            (RootInterval::Open(a, b), RootInterval::Open(c, d)) => b - a < d - c,
        }
    }

    /// The sign of `q` at the root if the interval decides it without refinement.
    fn sign_of(&self, q: &Poly) -> Option<Sign> {
        match &self.interval {
            RootInterval::Exact(v) => Some(q.sign_at(v)),
            RootInterval::Open(lo, hi) => sign_on_interval(q, lo, hi),
        }
    }
}

impl AlgebraicReal {
    pub(crate) fn with_interval(poly: Poly, interval: RootInterval) -> AlgebraicReal {
        AlgebraicReal::with_shared(Arc::new(Defining::made(poly)), interval)
    }

    fn with_shared(poly: Arc<Defining>, interval: RootInterval) -> AlgebraicReal {
        AlgebraicReal {
            poly,
            refined: Arc::new(Mutex::new(Refinement::new(interval.clone()))),
            interval,
            enclosure: None,
        }
    }

    /// The rational `v` as an algebraic number.
    pub fn from_rational(v: RBig) -> AlgebraicReal {
        AlgebraicReal::with_interval(Poly::vanishing_at(&v), RootInterval::Exact(v))
    }

    /// All real roots of `p`, in increasing order, each once (Descartes' rule on the
    /// square-free part; [`Self::certified_real_roots_of`] is the float route).
    pub fn real_roots_of(p: &Poly) -> Vec<AlgebraicReal> {
        AlgebraicReal::real_roots_of_within(p, &crate::budget::Budget::unlimited())
            .expect("an unlimited budget is never spent")
    }

    /// [`Self::real_roots_of`] spending `budget` on the square-free part
    /// ([`Poly::squarefree_part_within`]) and the isolation
    /// ([`crate::roots::isolate_squarefree_real_roots_within`]).
    ///
    /// # Errors
    /// [`crate::budget::Exhausted`] when the budget runs out.
    pub fn real_roots_of_within(
        p: &Poly,
        budget: &crate::budget::Budget,
    ) -> Result<Vec<AlgebraicReal>, crate::budget::Exhausted> {
        let sf = p.squarefree_part_within(budget)?;
        if sf.degree() == Some(1) {
            let v = RBig::from_parts_signed(-sf.coeff(0), sf.coeff(1));
            return Ok(vec![AlgebraicReal::from_rational(v)]);
        }
        let intervals = isolate_squarefree_real_roots_within(&sf, budget)?;
        let sf = Arc::new(Defining::made(sf));
        Ok(intervals
            .into_iter()
            .map(|iv| match iv {
                RootInterval::Exact(v) => AlgebraicReal::from_rational(v),
                iv => AlgebraicReal::with_shared(Arc::clone(&sf), iv),
            })
            .collect())
    }

    /// All real roots of `p` (increasing, each once) if the certified float path
    /// ([`certified_real_roots_enclosed`]) proves them, which also proves `p` square-free;
    /// `None` otherwise (degree above [`MAX_CERTIFIED_DEGREE`], multiple or very close roots).
    /// The defining polynomial is `p`'s primitive part, as [`Self::real_roots_of`] makes it.
    ///
    /// ```
    /// # use qsic_algebra::{AlgebraicReal, Poly};
    /// let r = AlgebraicReal::certified_real_roots_of(&Poly::from_i64s(&[-4, 0, 2])).unwrap();
    /// assert_eq!(r.len(), 2);
    /// assert_eq!(r[1].poly(), &Poly::from_i64s(&[-2, 0, 1]));
    /// assert!((r[1].to_f64() - 2f64.sqrt()).abs() < 1e-15);
    /// assert!(AlgebraicReal::certified_real_roots_of(&Poly::from_roots(&[1, 1])).is_none());
    /// ```
    pub fn certified_real_roots_of(p: &Poly) -> Option<Vec<AlgebraicReal>> {
        AlgebraicReal::certified_real_roots_where(p, |_| true)
    }

    /// [`Self::certified_real_roots_of`], keeping only the roots whose isolating interval
    /// passes `keep` (the others are never built). `Some` proves `p` square-free.
    ///
    /// ```
    /// # use qsic_algebra::{AlgebraicReal, Poly, RBig};
    /// let p = Poly::from_i64s(&[-4, 0, 2]); // 2x² − 4: ±√2
    /// let r = AlgebraicReal::certified_real_roots_where(&p, |iv| iv.lo() > &RBig::ZERO).unwrap();
    /// assert_eq!(r.len(), 1);
    /// assert!((r[0].to_f64() - 2f64.sqrt()).abs() < 1e-15);
    /// ```
    pub fn certified_real_roots_where(
        p: &Poly,
        mut keep: impl FnMut(&RootInterval) -> bool,
    ) -> Option<Vec<AlgebraicReal>> {
        if p.degree().unwrap_or(0) == 0 || p.degree() > Some(MAX_CERTIFIED_DEGREE) {
            return None;
        }
        let roots = certified_real_roots_enclosed(p)?;
        let roots: Vec<_> = roots.into_iter().filter(|r| keep(&r.interval)).collect();
        if roots.is_empty() {
            return Some(Vec::new());
        }
        // primitive with a positive leading coefficient: the gcd of the coefficients taken
        // in turn until it is 1 (usually after two) proves the content 1 without dividing
        let coeffs = p.coeffs();
        let mut g = crate::int_gcd(&coeffs[coeffs.len() - 1], &IBig::ZERO);
        for c in coeffs.iter().take(coeffs.len() - 1) {
            if g.is_one() {
                break;
            }
            g = crate::int_gcd(&g, c);
        }
        let lead_positive = p.leading() > IBig::ZERO;
        let sf = Arc::new(Defining::made(if !g.is_one() {
            // g is the content (the loop ran through every coefficient)
            let g = if lead_positive { g } else { -g };
            Poly::new(coeffs.iter().map(|c| c / &g).collect())
        } else if lead_positive {
            p.clone()
        } else {
            -p
        }));
        Some(
            roots
                .into_iter()
                .map(|r| match r.interval {
                    RootInterval::Exact(v) => AlgebraicReal::from_rational(v),
                    iv => {
                        // the narrow interval starts the shared refinement state
                        AlgebraicReal {
                            poly: Arc::clone(&sf),
                            refined: Arc::new(Mutex::new(Refinement::new(r.narrow))),
                            interval: iv,
                            enclosure: Some((r.center, r.radius)),
                        }
                    }
                })
                .collect(),
        )
    }

    /// The real roots of `s = A + B√δ` (`A = Σaᵢxⁱ`, `B = Σbᵢxⁱ`, `δ > 0` not a square,
    /// degree 1 to 4, `s(0) ≠ 0`), each defined by the primitive norm `A² − δB²` (one for all
    /// of them, made when [`Self::poly`] or a refinement first needs it), isolated in
    /// floats with a proof ([`certified_real_roots_zsqrt`](crate::roots::certified_real_roots_zsqrt));
    /// `None` if the certificate fails (the caller then isolates exactly). `Some` proves the
    /// norm square-free.
    ///
    /// ```
    /// # use qsic_algebra::{AlgebraicReal, IBig, Poly};
    /// // s = x² − 3 + √2·x: the roots (−√2 ± √14)/2
    /// let ([a0, a2], [zero, one]) = ([IBig::from(-3), IBig::ONE], [IBig::ZERO, IBig::ONE]);
    /// let (a, b) = ([&a0, &zero, &a2], [&zero, &one, &zero]);
    /// let r = AlgebraicReal::certified_real_roots_zsqrt(&a, &b, &IBig::from(2)).unwrap();
    /// assert_eq!(r.len(), 2);
    /// let want = (14f64.sqrt() - 2f64.sqrt()) / 2.0;
    /// assert!((r[1].to_f64() - want).abs() < 1e-12);
    /// assert_eq!(r[0].poly(), &Poly::from_i64s(&[9, 0, -8, 0, 1])); // (x² − 3)² − 2x²
    /// ```
    pub fn certified_real_roots_zsqrt(
        a: &[&IBig],
        b: &[&IBig],
        delta: &IBig,
    ) -> Option<Vec<AlgebraicReal>> {
        let roots = crate::roots::certified_real_roots_zsqrt(a, b, delta)?;
        if roots.is_empty() {
            return Some(Vec::new());
        }
        // one norm for all the roots, made when first read
        let len = a.len();
        let take =
            |v: &[&IBig]| std::array::from_fn(|i| v.get(i).map_or(IBig::ZERO, |&x| x.clone()));
        let poly = Arc::new(Defining {
            poly: OnceLock::new(),
            norm: Some((take(a), take(b), len, delta.clone())),
        });
        Some(
            roots
                .into_iter()
                .map(|r| AlgebraicReal {
                    poly: Arc::clone(&poly),
                    refined: Arc::new(Mutex::new(Refinement::new(r.narrow))),
                    interval: r.interval,
                    enclosure: Some((r.center, r.radius)),
                })
                .collect(),
        )
    }

    /// The root of the square-free `poly` in `interval`, if the interval isolates one: an
    /// exact rational that is a root, or an open interval at whose ends `poly` has opposite
    /// nonzero signs (so exactly one root when `interval` comes from isolating a multiple
    /// of `poly`, as in [`isolate_real_roots`](crate::roots::isolate_real_roots)).
    pub fn from_isolating_interval(poly: &Poly, interval: &RootInterval) -> Option<AlgebraicReal> {
        match interval {
            RootInterval::Exact(v) => poly
                .sign_at(v)
                .is_zero()
                .then(|| AlgebraicReal::from_rational(v.clone())),
            RootInterval::Open(lo, hi) => (poly.sign_at(lo) * poly.sign_at(hi) == Sign::Negative)
                .then(|| AlgebraicReal::with_interval(poly.clone(), interval.clone())),
        }
    }

    /// The same number defined by `factor`, a primitive factor of [`Self::poly`] of which
    /// it is a root, isolated by the refined interval (a fresh refinement state).
    pub(crate) fn with_factor(&self, factor: &Poly) -> AlgebraicReal {
        debug_assert!(self.poly().div_exact(factor).is_some() && self.is_root_of_divisor(factor));
        AlgebraicReal::with_interval(factor.clone(), self.snapshot().interval)
    }

    /// Checks the invariant (used in `debug_assert!`).
    pub fn is_valid(&self) -> bool {
        let valid = |iv: &RootInterval| match iv {
            RootInterval::Exact(v) => self.poly().sign_at(v).is_zero(),
            RootInterval::Open(lo, hi) => {
                lo < hi
                    && self.poly().is_squarefree()
                    && self.poly().sign_at(lo) * self.poly().sign_at(hi) == Sign::Negative
            }
        };
        valid(&self.interval) && valid(&self.snapshot().interval)
    }

    /// The defining square-free polynomial (for a rational, `q·x − p`).
    pub fn poly(&self) -> &Poly {
        self.poly.get()
    }

    /// Whether `self` and `other` are given by the same defining polynomial and stated
    /// isolating interval (so the same number): by the shared polynomial when they were
    /// isolated together or cloned, without making a norm not made yet; else by comparing
    /// the polynomials.
    ///
    /// ```
    /// # use qsic_algebra::{AlgebraicReal, Poly};
    /// let roots = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 1]));
    /// let again = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 1]));
    /// assert!(roots[0].same_definition(&roots[0].clone()));
    /// assert!(roots[0].same_definition(&again[0]));
    /// assert!(!roots[0].same_definition(&roots[1]));
    /// ```
    pub fn same_definition(&self, other: &AlgebraicReal) -> bool {
        self.interval == other.interval
            && (Arc::ptr_eq(&self.poly, &other.poly) || self.poly() == other.poly())
    }

    /// The stated isolating interval (the one made with, or narrowed by [`Self::refine`]
    /// and [`Self::refine_to`]).
    pub fn interval(&self) -> &RootInterval {
        &self.interval
    }

    /// `Some(v)` if the number is known to be the rational `v` (from the stated interval).
    pub fn as_rational(&self) -> Option<&RBig> {
        match &self.interval {
            RootInterval::Exact(v) => Some(v),
            RootInterval::Open(..) => None,
        }
    }

    /// The shared refinement state, whatever another holder did with the lock.
    fn lock(&self) -> MutexGuard<'_, Refinement> {
        self.refined.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// A copy of the shared refinement state.
    fn snapshot(&self) -> Refinement {
        self.lock().clone()
    }

    /// Stores a refinement if it is narrower than the shared one.
    fn store(&self, r: Refinement) {
        let mut shared = self.lock();
        if r.is_narrower_than(&shared) {
            *shared = r;
        }
    }

    /// An isolating interval shorter than `width` (or the exact value), refining the shared
    /// state as far as needed (quadratic refinement: about `log₂ log₂ (1/width)` steps once
    /// the root is isolated from the others). `self` keeps its stated interval.
    pub fn refined_interval(&self, width: &RBig) -> RootInterval {
        let mut r = self.snapshot();
        if r.is_within(width) {
            return r.interval;
        }
        while !r.is_within(width) {
            r.step(self.poly());
        }
        let iv = r.interval.clone();
        self.store(r);
        iv
    }

    /// Narrows the stated isolating interval: at least halves it, and squares the rate of
    /// shrinking on success (quadratic interval refinement; exact numbers are left as they
    /// are). Starts from the shared refinement state.
    pub fn refine(&mut self) {
        let mut r = self.snapshot();
        r.step(self.poly());
        self.interval = r.interval.clone();
        self.store(r);
    }

    /// Refines the stated interval until it is shorter than `width`.
    pub fn refine_to(&mut self, width: &RBig) {
        self.interval = self.refined_interval(width);
    }

    /// The exact sign of `q(α)`.
    ///
    /// Tried first on the refined interval by interval arithmetic ([`sign_on_interval`]);
    /// zero is decided by `gcd(poly, q)` changing sign on the isolating interval; a nonzero
    /// sign by refining (the shared state) until the interval enclosure of `q` excludes zero.
    ///
    /// ```
    /// # use qsic_algebra::{AlgebraicReal, Poly, Sign};
    /// let sqrt2 = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 1])).pop().unwrap();
    /// assert_eq!(sqrt2.sign_of(&Poly::from_i64s(&[-2, 0, 1])), Sign::Zero);
    /// assert_eq!(sqrt2.sign_of(&Poly::from_rational_roots(&[(1414, 1000)])), Sign::Positive); // x − 1.414
    /// assert_eq!(sqrt2.sign_of(&Poly::from_rational_roots(&[(1415, 1000)])), Sign::Negative);
    /// ```
    pub fn sign_of(&self, q: &Poly) -> Sign {
        self.sign_with_gcd(q, |p| p.gcd(q))
    }

    /// The sign of `q` at each of `roots`: [`Self::sign_of`] at each, with the gcd of `q` and
    /// a defining polynomial computed once for all the roots that share it (the real roots of
    /// one polynomial, from [`Self::real_roots_of`]): where the gcd is constant, no root of that
    /// polynomial is a root of `q`, and refinement alone decides.
    ///
    /// ```
    /// # use qsic_algebra::{AlgebraicReal, Poly, Sign};
    /// // the roots ±√2, ±√3 of (x² − 2)(x² − 3), and q = x² − 2
    /// let p = &Poly::from_i64s(&[-2, 0, 1]) * &Poly::from_i64s(&[-3, 0, 1]);
    /// let roots = AlgebraicReal::real_roots_of(&p);
    /// let signs = AlgebraicReal::signs_at(&roots, &Poly::from_i64s(&[-2, 0, 1]));
    /// assert_eq!(signs, [Sign::Positive, Sign::Zero, Sign::Zero, Sign::Positive]);
    /// ```
    pub fn signs_at(roots: &[AlgebraicReal], q: &Poly) -> Vec<Sign> {
        // (defining polynomial, its gcd with q) of the roots seen
        let mut gcds: Vec<(Arc<Defining>, Poly)> = Vec::new();
        roots
            .iter()
            .map(|r| {
                r.sign_with_gcd(q, |p| {
                    let known = gcds
                        .iter()
                        .find(|(d, _)| Arc::ptr_eq(d, &r.poly) || d.get() == p);
                    match known {
                        Some((_, g)) => g.clone(),
                        None => {
                            let g = p.gcd(q);
                            gcds.push((Arc::clone(&r.poly), g.clone()));
                            g
                        }
                    }
                })
            })
            .collect()
    }

    /// [`Self::sign_of`] with `gcd(p, q)` for the defining polynomial `p` from `gcd` (asked
    /// only when the refined interval does not decide).
    fn sign_with_gcd(&self, q: &Poly, gcd: impl FnOnce(&Poly) -> Poly) -> Sign {
        if q.is_constant() {
            return Sign::of(&q.leading());
        }
        if let Some(s) = self.sign_by_enclosure(q) {
            return s;
        }
        let r = self.snapshot();
        if let Some(s) = r.sign_of(q) {
            return s;
        }
        if let RootInterval::Open(lo, hi) = &r.interval {
            let g = gcd(self.poly());
            if g.degree().unwrap_or(0) > 0 && g.sign_at(lo) * g.sign_at(hi) == Sign::Negative {
                return Sign::Zero;
            }
        }
        self.refine_until_signed(r, q)
    }

    /// The sign of `q(α)` if the refined interval decides it without refining further
    /// (exact when it answers; no gcd, no refinement: cheap, and `None` where `q(α) = 0`
    /// with `α` irrational).
    ///
    /// ```
    /// # use qsic_algebra::{AlgebraicReal, Poly, Sign};
    /// let sqrt2 = AlgebraicReal::certified_real_roots_of(&Poly::from_i64s(&[-2, 0, 1])).unwrap().pop().unwrap();
    /// assert_eq!(sqrt2.sign_on_refined(&Poly::from_i64s(&[-1, 1])), Some(Sign::Positive)); // x − 1
    /// assert_eq!(sqrt2.sign_on_refined(&Poly::from_i64s(&[-2, 0, 1])), None); // zero there
    /// ```
    pub fn sign_on_refined(&self, q: &Poly) -> Option<Sign> {
        self.sign_by_enclosure(q)
            .or_else(|| self.snapshot().sign_of(q))
    }

    /// The sign of `q(α)` from the certified float enclosure, when there is one and it
    /// decides ([`certified_sign_poly_near`](crate::filter::certified_sign_poly_near)): a
    /// Horner evaluation in floats instead of one in big rationals at the interval's ends.
    fn sign_by_enclosure(&self, q: &Poly) -> Option<Sign> {
        let (c, r) = self.enclosure?;
        let n = q.coeffs().len();
        if n > MAX_CERTIFIED_DEGREE + 1 {
            return None;
        }
        let mut f = [0.0; MAX_CERTIFIED_DEGREE + 1];
        for (x, v) in f.iter_mut().zip(q.coeffs()) {
            *x = v.to_f64().value();
        }
        crate::filter::certified_sign_poly_near(&f[..n], c, r)
    }

    /// The sign of `q(α)`, known to be nonzero: refines until interval arithmetic decides.
    /// (With `q(α) = 0` and `α` irrational this would not end: callers decide zero first.)
    pub(crate) fn sign_of_nonzero(&self, q: &Poly) -> Sign {
        if let Some(s) = self.sign_by_enclosure(q) {
            return s;
        }
        let r = self.snapshot();
        match r.sign_of(q) {
            Some(s) => s,
            None => self.refine_until_signed(r, q),
        }
    }

    /// Refines `r` until it decides the sign of `q` (nonzero at `α`), and stores it.
    fn refine_until_signed(&self, mut r: Refinement, q: &Poly) -> Sign {
        let s = loop {
            r.step(self.poly());
            if let Some(s) = r.sign_of(q) {
                break s;
            }
        };
        self.store(r);
        s
    }

    /// `true` if `α` is a root of `g`, a divisor of [`Self::poly`] over ℚ (integer or
    /// rational coefficients, any scale): two signs at the ends of the refined interval.
    pub(crate) fn is_root_of_divisor(&self, g: &Poly) -> bool {
        match self.snapshot().interval {
            RootInterval::Exact(v) => g.sign_at(&v).is_zero(),
            RootInterval::Open(lo, hi) => g.sign_at(&lo) * g.sign_at(&hi) == Sign::Negative,
        }
    }

    /// The exact sign of `q(α)` by the Sturm–Tarski theorem on the isolating interval
    /// ([`tarski_query_in`](crate::poly::sturm::tarski_query_in)): no refinement, at the
    /// cost of a signed remainder sequence of `(poly, poly'·q)`. A second route to
    /// [`Self::sign_of`].
    ///
    /// ```
    /// # use qsic_algebra::{AlgebraicReal, Poly, Sign};
    /// let r = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 0, 1])).pop().unwrap(); // ∛2
    /// assert_eq!(r.sign_of_sturm_tarski(&Poly::from_rational_roots(&[(126, 100)])), Sign::Negative);
    /// assert_eq!(r.sign_of_sturm_tarski(&Poly::from_i64s(&[-4, 0, 0, 0, 0, 0, 1])), Sign::Zero);
    /// ```
    pub fn sign_of_sturm_tarski(&self, q: &Poly) -> Sign {
        match self.snapshot().interval {
            RootInterval::Exact(v) => q.sign_at(&v),
            RootInterval::Open(lo, hi) => {
                match crate::poly::sturm::tarski_query_in(self.poly(), q, &lo, &hi) {
                    0 => Sign::Zero,
                    t if t > 0 => Sign::Positive,
                    _ => Sign::Negative,
                }
            }
        }
    }

    /// `true` if `α` is a root of `q`.
    pub fn is_root_of(&self, q: &Poly) -> bool {
        self.sign_of(q).is_zero()
    }

    /// The multiplicity of `α` as a root of `q` (0 if it is not a root; `q ≠ 0`).
    pub fn multiplicity_in(&self, q: &Poly) -> usize {
        let mut d = q.clone();
        let mut m = 0;
        while !d.is_zero() && self.is_root_of(&d) {
            m += 1;
            d = d.derivative();
        }
        m
    }

    /// A float approximation (for display and sampling only, never for a decision).
    ///
    /// Newton's method safeguarded by bisection, in floating point, inside the isolating
    /// interval (where the float signs of `poly` at the ends differ as the exact ones do),
    /// kept where its rounding bound or two exact signs at `x ± |x|·2⁻⁴²` prove it that
    /// close; otherwise the midpoint of an exactly refined interval of width `2⁻⁶⁰`.
    /// A certified float enclosure, when it is that accurate, is the answer without work.
    pub fn to_f64(&self) -> f64 {
        if let Some((c, r)) = self.enclosure {
            if r <= c.abs() * 2f64.powi(-42) {
                return c;
            }
        }
        if let RootInterval::Open(lo, hi) = &self.snapshot().interval {
            let (l, h) = (lo.to_f64().value(), hi.to_f64().value());
            match newton_in(self.poly(), l, h) {
                Some((x, true)) => return x,
                Some((x, false)) if brackets(self.poly(), lo, hi, x) => return x,
                _ => {}
            }
        }
        let iv = self.refined_interval(&RBig::from_parts_signed(1.into(), IBig::ONE << 60));
        (iv.lo().to_f64().value() + iv.hi().to_f64().value()) / 2.0
    }

    /// A rational strictly between `self` and `other` (`self < other` required).
    pub fn rational_between(&self, other: &AlgebraicReal) -> RBig {
        let (mut a, mut b) = (self.snapshot(), other.snapshot());
        let v = loop {
            let (ahi, blo) = (a.interval.hi().clone(), b.interval.lo().clone());
            let a_exact = a.interval.as_exact().is_some();
            let b_exact = b.interval.as_exact().is_some();
            if ahi < blo || (ahi == blo && !a_exact && !b_exact) {
                break simplest_between(&ahi, &blo, !a_exact, !b_exact);
            }
            if ahi == blo && a_exact != b_exact {
                // a point strictly inside the open interval next to the exact value
                if !a_exact {
                    a.step(self.poly());
                } else {
                    b.step(other.poly());
                }
                continue;
            }
            a.step(self.poly());
            b.step(other.poly());
        };
        self.store(a);
        other.store(b);
        v
    }
}

/// The sign of `q` on the whole closed interval `[lo, hi]` (`lo ≤ hi`), if Horner's scheme
/// in interval arithmetic proves one: `Some(s)` means `q(x)` has sign `s` for every `x` in
/// the interval; `None` means undecided (the enclosure meets zero).
///
/// The arithmetic is fixed point with `k` fractional bits, `k ≈ log₂(1/(hi − lo)) + 16 +
/// log₂ deg q`: integers `[aₗ, aₕ]` enclose `2^k` times each Horner partial value, products
/// are bounded by their extreme corners and rounded outward (floor below, ceiling above),
/// so the enclosure is rigorous; its width is about `(hi − lo)` times a majorant of `|q′|`,
/// so it decides every nonzero sign once the interval is narrow enough. Cost: `deg q`
/// rounds of two (four when the interval holds zero) integer products.
///
/// ```
/// # use qsic_algebra::{algebraic::sign_on_interval, Poly, RBig, Sign};
/// let p = Poly::from_i64s(&[-2, 0, 1]); // x² − 2 on [1.4, 1.5]: both signs
/// let r = |n: i64| RBig::from_parts_signed(n.into(), 1000.into());
/// assert_eq!(sign_on_interval(&p, &r(1400), &r(1500)), None);
/// assert_eq!(sign_on_interval(&p, &r(1415), &r(1416)), Some(Sign::Positive));
/// assert_eq!(sign_on_interval(&p, &r(-1414), &r(1414)), Some(Sign::Negative));
/// ```
pub fn sign_on_interval(q: &Poly, lo: &RBig, hi: &RBig) -> Option<Sign> {
    let n = q.degree()?;
    if n == 0 {
        return Some(Sign::of(&q.leading()));
    }
    let w = hi - lo;
    let den_bits = IBig::from(w.denominator().clone()).bit_len();
    let k = den_bits.saturating_sub(w.numerator().bit_len())
        + 16
        + (usize::BITS - n.leading_zeros()) as usize;
    // x ∈ [xl, xh]·2^−k; reflect an interval of non-positive numbers to x ≥ 0
    let (mut xl, mut xh) = (floor_scaled(lo, k), -floor_scaled(&-hi, k));
    let reflect = xh <= IBig::ZERO;
    if reflect {
        (xl, xh) = (-xh, -xl);
    }
    let coeff = |i: usize| {
        let c = &q.coeffs()[i];
        if reflect && i % 2 == 1 {
            -(c << k)
        } else {
            c << k
        }
    };
    let mut al = coeff(n);
    let mut ah = al.clone();
    let nonnegative = xl >= IBig::ZERO;
    for i in (0..n).rev() {
        let (pl, ph) = if nonnegative {
            (
                if al >= IBig::ZERO {
                    &al * &xl
                } else {
                    &al * &xh
                },
                if ah >= IBig::ZERO {
                    &ah * &xh
                } else {
                    &ah * &xl
                },
            )
        } else {
            let p = [&al * &xl, &al * &xh, &ah * &xl, &ah * &xh];
            let lo = p.iter().min().cloned().unwrap_or(IBig::ZERO);
            let hi = p.iter().max().cloned().unwrap_or(IBig::ZERO);
            (lo, hi)
        };
        let c = coeff(i);
        al = (pl >> k) + &c;
        ah = -((-ph) >> k) + c;
    }
    if al > IBig::ZERO {
        Some(Sign::Positive)
    } else if ah < IBig::ZERO {
        Some(Sign::Negative)
    } else {
        None
    }
}

/// A root of `p` in `[lo, hi]` by Newton's method kept inside a bracket by bisection, all in
/// floating point; `None` unless the float values of `p` at the ends have opposite signs.
/// With it whether the root is well conditioned: the rounding bound of Horner's rule
/// `2n·ε·Σ|cᵢ||x|ⁱ` over `|p′(x)|` within `2⁻⁴²·|x|` (about 12 digits: display and
/// sampling); where it is not, [`brackets`] may still prove the float that close.
fn newton_in(p: &Poly, lo: f64, hi: f64) -> Option<(f64, bool)> {
    let c: Vec<f64> = p.coeffs().iter().map(|v| v.to_f64().value()).collect();
    if !(c.iter().all(|x| x.is_finite()) && lo.is_finite() && hi.is_finite() && lo <= hi) {
        return None;
    }
    let eval = |x: f64| -> (f64, f64) {
        c.iter()
            .rev()
            .fold((0.0, 0.0), |(f, df), &v| (f * x + v, df * x + f))
    };
    let (fl, fh) = (eval(lo).0, eval(hi).0);
    if lo == hi || fl * fh >= 0.0 || !(fl * fh).is_finite() {
        return (lo == hi).then_some((lo, true));
    }
    let conditioned = |x: f64| -> Option<(f64, bool)> {
        let (_, df) = eval(x);
        let bound = c
            .iter()
            .rev()
            .fold(0.0, |acc: f64, &v| acc * x.abs() + v.abs());
        let err = 2.0 * c.len() as f64 * f64::EPSILON * bound / df.abs();
        Some((x, err.is_finite() && err <= x.abs() * 2f64.powi(-42)))
    };
    let (mut a, mut b) = (lo, hi);
    let mut x = 0.5 * (a + b);
    for _ in 0..200 {
        let (f, df) = eval(x);
        if f == 0.0 {
            return conditioned(x);
        }
        if (f < 0.0) == (fl < 0.0) {
            a = x;
        } else {
            b = x;
        }
        if b - a <= 4.0 * f64::EPSILON * a.abs().max(b.abs()) {
            return conditioned(0.5 * (a + b));
        }
        let newton = x - f / df;
        let next = if newton > a && newton < b {
            newton
        } else {
            0.5 * (a + b)
        };
        if next == x {
            return conditioned(x);
        }
        x = next;
    }
    None
}

/// `true` if the root of `p` in the isolating interval `(lo, hi)` is within `|x|·2⁻⁴²` of
/// `x` (never for `x = 0`, where the two ends coincide): the ends `x ± |x|·2⁻⁴²` lie in the
/// interval and `p` has opposite exact signs there (an odd number of roots between them, so the one root of the interval).
/// What makes a float root certain where the float evaluation's error bound is too coarse
/// (close roots, a small derivative), at the cost of two exact evaluations.
fn brackets(p: &Poly, lo: &RBig, hi: &RBig, x: f64) -> bool {
    let delta = x.abs() * 2f64.powi(-42);
    let (Ok(a), Ok(b)) = (RBig::try_from(x - delta), RBig::try_from(x + delta)) else {
        return false;
    };
    lo < &a && &b < hi && p.sign_at(&a) * p.sign_at(&b) == Sign::Negative
}

/// `⌊v·2^k⌋`.
fn floor_scaled(v: &RBig, k: usize) -> IBig {
    let den = IBig::from(v.denominator().clone());
    (v.numerator() << k).div_euclid(den)
}

impl PartialEq for AlgebraicReal {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for AlgebraicReal {}

impl PartialOrd for AlgebraicReal {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// `a < b` (`Less`) or `a > b` (`Greater`) if two isolating intervals are apart.
fn separated(a: &RootInterval, b: &RootInterval) -> Option<Ordering> {
    if a.hi() <= b.lo() && a != b {
        Some(Ordering::Less)
    } else if b.hi() <= a.lo() && a != b {
        Some(Ordering::Greater)
    } else {
        None
    }
}

/// Whether the root `α` of `p` isolated by the open interval `a` equals the root `β` of `q`
/// isolated by the open interval `b` (`p`, `q` square-free, no interval end a root).
///
/// `α = β` exactly when `g = gcd(p, q)` changes sign on `I = a ∩ b`: a root `γ ∈ I` of `g`
/// is a root of `p` in `a`, so `γ = α`, and likewise `γ = β`; conversely a common root lies
/// in `I` and is a simple root of the square-free `g`, whose only root in `I` it is, while
/// the ends of `I` (ends of `a` or `b`) are no roots of `g`. Exact, no refinement, whether
/// or not `p` and `q` are irreducible or equal.
fn equal_open(p: &Poly, a: &RootInterval, q: &Poly, b: &RootInterval) -> bool {
    let lo = a.lo().max(b.lo());
    let hi = a.hi().min(b.hi());
    if lo >= hi {
        return false;
    }
    let g = if p == q { p.clone() } else { p.gcd(q) };
    g.degree().unwrap_or(0) > 0 && g.sign_at(lo) * g.sign_at(hi) == Sign::Negative
}

impl Ord for AlgebraicReal {
    fn cmp(&self, other: &Self) -> Ordering {
        if let Some(v) = other.as_rational() {
            // sign of α − v = sign of (x − v) at α
            return match self.sign_of(&Poly::vanishing_at(v)) {
                Sign::Negative => Ordering::Less,
                Sign::Zero => Ordering::Equal,
                Sign::Positive => Ordering::Greater,
            };
        }
        if self.as_rational().is_some() {
            return other.cmp(self).reverse();
        }
        let (mut a, mut b) = (self.snapshot(), other.snapshot());
        if let (RootInterval::Exact(x), RootInterval::Exact(y)) = (&a.interval, &b.interval) {
            return x.cmp(y);
        }
        if let Some(o) = separated(&a.interval, &b.interval) {
            return o;
        }
        // a refinement that met a rational root: compare with that rational
        if let Some(v) = a.interval.as_exact() {
            return AlgebraicReal::from_rational(v.clone()).cmp(other);
        }
        if let Some(v) = b.interval.as_exact() {
            return self.cmp(&AlgebraicReal::from_rational(v.clone()));
        }
        if equal_open(self.poly(), &a.interval, other.poly(), &b.interval) {
            return Ordering::Equal;
        }
        // different numbers: refinement separates them; only the wider interval is refined,
        // so that one already narrow (a shared refinement) does not grow huge ends in
        // lockstep with the other
        let width = |iv: &RootInterval| iv.hi() - iv.lo();
        let o = loop {
            if let Some(o) = separated(&a.interval, &b.interval) {
                break o;
            }
            if width(&a.interval) >= width(&b.interval) {
                a.step(self.poly());
            } else {
                b.step(other.poly());
            }
        };
        self.store(a);
        other.store(b);
        o
    }
}

impl fmt::Debug for AlgebraicReal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{self}")
    }
}

impl fmt::Display for AlgebraicReal {
    /// `3/2`, or `root of x^2 - 2 in (1, 3/2)` (the stated interval).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.interval {
            RootInterval::Exact(v) => write!(f, "{v}"),
            RootInterval::Open(lo, hi) => write!(f, "root of {} in ({lo}, {hi})", self.poly()),
        }
    }
}

/// The primitive norm `A² − δB²` of positive leading coefficient (not zero: `δ` is not a
/// square), in machine integers when they suffice.
fn norm_zsqrt(a: &[&IBig], b: &[&IBig], delta: &IBig) -> Poly {
    let small = |v: &[&IBig]| -> Option<[i64; 5]> {
        let mut out = [0i64; 5];
        for (o, x) in out.iter_mut().zip(v) {
            *o = i64::try_from(*x).ok()?;
        }
        Some(out)
    };
    let n = a.len();
    if let (Some(a), Some(b), Ok(d)) = (small(a), small(b), i64::try_from(delta)) {
        if let Some(c) = norm_i128(&a[..n], &b[..n], d) {
            return primitive_i128(&c[..2 * n - 1]);
        }
    }
    if let Some(p) = norm_wide(a, b, delta) {
        return p;
    }
    let mut c = vec![IBig::ZERO; 2 * n - 1];
    for i in 0..n {
        let (sa, sb) = (a[i] * a[i], b[i] * b[i]);
        c[2 * i] += sa - sb * delta;
        for j in i + 1..n {
            let t = a[i] * a[j] - b[i] * b[j] * delta;
            c[i + j] += t << 1;
        }
    }
    let p = Poly::new(c);
    // the content taken from the leading coefficient down, usually 1 after two steps
    let g = p.content();
    match (g.is_one(), p.leading() > IBig::ZERO) {
        (true, true) => p,
        (true, false) => -&p,
        _ => p.primitive_part(),
    }
}

/// A signed 256-bit integer in two's complement, little-endian words (wrapping arithmetic:
/// the callers bound the values).
type Wide = [u64; 4];

/// `x + y` modulo `2²⁵⁶`.
fn wide_add(x: Wide, y: Wide) -> Wide {
    let mut out = [0u64; 4];
    let mut carry = false;
    for i in 0..4 {
        let (s1, c1) = x[i].overflowing_add(y[i]);
        let (s2, c2) = s1.overflowing_add(u64::from(carry));
        out[i] = s2;
        carry = c1 || c2;
    }
    out
}

/// `−x` modulo `2²⁵⁶`.
fn wide_neg(x: Wide) -> Wide {
    wide_add([!x[0], !x[1], !x[2], !x[3]], [1, 0, 0, 0])
}

/// `x·y` for `x, y < 2¹²⁸` (exact, below `2²⁵⁶`).
fn wide_mul(x: u128, y: u128) -> Wide {
    let (x0, x1) = (x as u64 as u128, x >> 64);
    let (y0, y1) = (y as u64 as u128, y >> 64);
    let lo = x0 * y0;
    let (m1, m2) = (x0 * y1, x1 * y0);
    let hi = x1 * y1;
    let mut out = [lo as u64, (lo >> 64) as u64, hi as u64, (hi >> 64) as u64];
    for m in [m1, m2] {
        out = wide_add(out, [0, m as u64, (m >> 64) as u64, 0]);
    }
    out
}

/// `x·d` for `x·d < 2²⁵⁶` (the caller's bound).
fn wide_mul_small(x: Wide, d: u64) -> Wide {
    let mut out = [0u64; 4];
    let mut carry = 0u128;
    for i in 0..4 {
        let t = u128::from(x[i]) * u128::from(d) + carry;
        out[i] = t as u64;
        carry = t >> 64;
    }
    out
}

/// The integer `x` as an [`IBig`] (from its words: no byte copies).
fn wide_to_ibig(x: Wide) -> IBig {
    let negative = x[3] >> 63 == 1;
    let m = if negative { wide_neg(x) } else { x };
    let v = if m[2] == 0 && m[3] == 0 {
        IBig::from(u128::from(m[0]) | (u128::from(m[1]) << 64))
    } else {
        IBig::from(dashu_int::UBig::from_words(&m))
    };
    if negative {
        -v
    } else {
        v
    }
}

/// The primitive norm of [`norm_zsqrt`] in 256-bit integers: `s` divided by the gcd of its
/// coefficients (in `u128`) first, then `Σ (aᵢaⱼ − δ·bᵢbⱼ)` when `|aᵢ| < 2ᵅ`, `|bᵢ| < 2ᵝ`
/// and `δ < 2^d ≤ 2⁶²` with `2α + 5 ≤ 255` and `2β + d + 5 ≤ 255`: each sum has at most 5
/// products of each kind, so every partial sum stays below `2²⁵⁴`. `None`
/// outside that range.
fn norm_wide(a: &[&IBig], b: &[&IBig], delta: &IBig) -> Option<Poly> {
    let n = a.len();
    let d = u64::try_from(delta).ok().filter(|&d| d < 1 << 62)?;
    let mut sa = [(false, 0u128); 5];
    let mut sb = [(false, 0u128); 5];
    let mut g = 0u128;
    for i in 0..n {
        let x = i128::try_from(a[i]).ok()?;
        let y = i128::try_from(b[i]).ok()?;
        sa[i] = (x < 0, x.unsigned_abs());
        sb[i] = (y < 0, y.unsigned_abs());
        if g != 1 {
            g = gcd_u128(gcd_u128(g, sa[i].1), sb[i].1);
        }
    }
    if g == 0 {
        return None;
    }
    if g != 1 {
        for v in sa[..n].iter_mut().chain(&mut sb[..n]) {
            v.1 /= g;
        }
    }
    let bits = |v: &[(bool, u128)]| v.iter().map(|x| 128 - x.1.leading_zeros()).max();
    let (ba, bb) = (bits(&sa[..n])?, bits(&sb[..n])?);
    if 2 * ba + 5 > 255 || 2 * bb + (64 - d.leading_zeros()) + 5 > 255 {
        return None;
    }
    let mut c = [[0u64; 4]; 9];
    for i in 0..n {
        for j in i..n {
            let twice = if i == j { 1 } else { 2 };
            let pa = wide_mul_small(wide_mul(sa[i].1, sa[j].1), twice);
            let pb = wide_mul_small(wide_mul(sb[i].1, sb[j].1), twice * d);
            let pa = if sa[i].0 != sa[j].0 { wide_neg(pa) } else { pa };
            let pb = if sb[i].0 == sb[j].0 { wide_neg(pb) } else { pb };
            c[i + j] = wide_add(wide_add(c[i + j], pa), pb);
        }
    }
    Some(primitive_wide(&c[..2 * n - 1]))
}

/// `x / 2ˢ` for `x` divisible by `2ˢ`, `s < 256` (arithmetic shift: the sign stays).
fn wide_shr(x: Wide, s: u32) -> Wide {
    let fill = if x[3] >> 63 == 1 { u64::MAX } else { 0 };
    let (words, bits) = ((s / 64) as usize, s % 64);
    let word = |i: usize| if i < 4 { x[i] } else { fill };
    std::array::from_fn(|i| {
        let lo = word(i + words);
        if bits == 0 {
            lo
        } else {
            (lo >> bits) | (word(i + words + 1) << (64 - bits))
        }
    })
}

/// `x mod m` for a non-negative `x` and `m > 0`.
fn wide_rem(x: Wide, m: u64) -> u64 {
    let mut r = 0u128;
    for &w in x.iter().rev() {
        r = ((r << 64) | u128::from(w)) % u128::from(m);
    }
    r as u64
}

/// `x / m` for a non-negative `x` that `m > 0` divides.
fn wide_div(x: Wide, m: u64) -> Wide {
    let mut out = [0u64; 4];
    let mut r = 0u128;
    for i in (0..4).rev() {
        let t = (r << 64) | u128::from(x[i]);
        out[i] = (t / u128::from(m)) as u64;
        r = t % u128::from(m);
    }
    out
}

/// The primitive integer polynomial of positive leading coefficient proportional to `c`
/// (not zero, `|cᵢ| < 2²⁵⁵`): the common power of two by shifts; the rest of the content is
/// the gcd of the two coefficients least in magnitude (in `u128` when they fit, else in big
/// integers) and then, when it fits a `u64`, of the residues of the others (in words); no
/// division when it is 1 (the common case).
fn primitive_wide(c: &[Wide]) -> Poly {
    let len = c.iter().rposition(|v| *v != [0; 4]).map_or(0, |i| i + 1);
    let negative = |w: &Wide| w[3] >> 63 == 1;
    let abs = |w: Wide| if negative(&w) { wide_neg(w) } else { w };
    // the common power of two apart (shifts, no gcd)
    let zeros = |w: &Wide| {
        let i = w.iter().position(|&x| x != 0).unwrap_or(3);
        64 * i as u32 + w[i].trailing_zeros()
    };
    let shift = c[..len]
        .iter()
        .filter(|w| **w != [0; 4])
        .map(zeros)
        .min()
        .unwrap_or(0);
    let mut shifted = [[0u64; 4]; 9];
    let c = if shift == 0 {
        &c[..len]
    } else {
        for (o, w) in shifted.iter_mut().zip(&c[..len]) {
            *o = wide_shr(*w, shift);
        }
        &shifted[..len]
    };
    // the two nonzero magnitudes least by their top words (ties: any)
    let key = |w: &Wide| {
        let m = abs(*w);
        (m[3], m[2], m[1], m[0])
    };
    let mut least = [usize::MAX; 2];
    for (i, w) in c.iter().enumerate() {
        if *w == [0; 4] {
            continue;
        }
        if least[0] == usize::MAX || key(w) < key(&c[least[0]]) {
            least = [i, least[0]];
        } else if least[1] == usize::MAX || key(w) < key(&c[least[1]]) {
            least[1] = i;
        }
    }
    let fits = |m: &Wide| m[2] == 0 && m[3] == 0;
    let to_u128 = |m: &Wide| u128::from(m[0]) | (u128::from(m[1]) << 64);
    let g = match least {
        [i, usize::MAX] => abs(c[i]),
        [i, j] => {
            let (x, y) = (abs(c[i]), abs(c[j]));
            if fits(&x) && fits(&y) {
                let g = gcd_u128(to_u128(&x), to_u128(&y));
                [g as u64, (g >> 64) as u64, 0, 0]
            } else {
                let g = crate::int_gcd(&wide_to_ibig(x), &wide_to_ibig(y));
                match u128::try_from(&g) {
                    Ok(g) => [g as u64, (g >> 64) as u64, 0, 0],
                    Err(_) => [0; 4],
                }
            }
        }
    };
    let Some(mut g) = (g[1] == 0 && g[2] == 0 && g[3] == 0 && g[0] != 0).then_some(g[0]) else {
        return Poly::new(c.iter().map(|&w| wide_to_ibig(w)).collect()).primitive_part();
    };
    for &w in c {
        if g == 1 {
            break;
        }
        g = gcd_u128(u128::from(g), u128::from(wide_rem(abs(w), g))) as u64;
    }
    let flip = negative(&c[len - 1]);
    Poly::new(
        c.iter()
            .map(|&w| {
                let q = if g == 1 {
                    if flip {
                        wide_neg(w)
                    } else {
                        w
                    }
                } else {
                    let q = wide_div(abs(w), g);
                    if negative(&w) != flip {
                        wide_neg(q)
                    } else {
                        q
                    }
                };
                wide_to_ibig(q)
            })
            .collect(),
    )
}

/// The coefficients `Σ_{i+j=k} (aᵢaⱼ − δ·bᵢbⱼ)` of `A² − δB²` in checked `i128`.
fn norm_i128(a: &[i64], b: &[i64], delta: i64) -> Option<[i128; 9]> {
    let n = a.len();
    let mut out = [0i128; 9];
    for i in 0..n {
        for j in 0..n {
            // products of two i64 fit an i128; the sums are checked
            let aa = i128::from(a[i]) * i128::from(a[j]);
            let bb = i128::from(b[i]) * i128::from(b[j]);
            let t = aa.checked_sub(bb.checked_mul(i128::from(delta))?)?;
            out[i + j] = out[i + j].checked_add(t)?;
        }
    }
    // keep every |cᵢ| below 2¹²⁷ (so that the content fits an i128)
    (!out.contains(&i128::MIN)).then_some(out)
}

/// The primitive integer polynomial of positive leading coefficient proportional to `c`
/// (not zero), the content by a binary gcd in machine integers.
fn primitive_i128(c: &[i128]) -> Poly {
    let len = c.iter().rposition(|v| *v != 0).map_or(0, |i| i + 1);
    let c = &c[..len];
    let mut g = 0u128;
    for v in c.iter().rev() {
        g = gcd_u128(g, v.unsigned_abs());
        if g == 1 {
            break;
        }
    }
    let g = if c[len - 1] < 0 {
        -(g as i128)
    } else {
        g as i128
    };
    // |g| ≤ |c_n| < 2¹²⁷ fits; the quotients are exact
    Poly::new(
        c.iter()
            .map(|&v| {
                IBig::from(match g {
                    1 => v,
                    -1 => -v,
                    _ => v / g,
                })
            })
            .collect(),
    )
}

/// `gcd(a, b)`: one Euclidean step (the larger modulo the smaller, which is often much
/// smaller here), then Stein's binary algorithm.
fn gcd_u128(a: u128, b: u128) -> u128 {
    if a == 0 || b == 0 {
        return a | b;
    }
    let (a, b) = if a < b { (a, b % a) } else { (a % b, b) };
    if a == 0 || b == 0 {
        return a | b;
    }
    let shift = (a | b).trailing_zeros();
    let (mut a, mut b) = (a >> a.trailing_zeros(), b);
    loop {
        b >>= b.trailing_zeros();
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        b -= a;
        if b == 0 {
            return a << shift;
        }
    }
}

#[cfg(test)]
mod tests {

    /// `signs_at` is `sign_of` at each root, on the roots of random products with factors
    /// shared with `q` (zeros at some roots, not at others), over roots of two different
    /// polynomials, and with a rational root among them; the Sturm–Tarski route agrees.
    #[test]
    fn signs_at_roots_are_the_signs_one_at_a_time() {
        let mut rng = crate::testing::SplitMix(2026);
        let mut zeros = 0;
        for _ in 0..30 {
            let mut factor = || Poly::from_i64s(&[rng.int(-9, 9), rng.int(-5, 5), 1]);
            let (f, g, h) = (factor(), factor(), factor());
            let p = &(&f * &g) * &Poly::from_i64s(&[-1, 3]); // a rational root 1/3
            let other = &h * &Poly::from_i64s(&[-7, 0, 1]);
            let q = &g * &h;
            let mut roots = AlgebraicReal::real_roots_of(&p);
            roots.extend(AlgebraicReal::real_roots_of(&other));
            let got = AlgebraicReal::signs_at(&roots, &q);
            assert_eq!(got.len(), roots.len());
            for (r, s) in roots.iter().zip(&got) {
                assert_eq!(*s, r.sign_of(&q), "{q:?} at a root of {:?}", r.poly());
                assert_eq!(*s, r.sign_of_sturm_tarski(&q));
                zeros += usize::from(*s == Sign::Zero);
            }
        }
        assert!(zeros >= 10, "{zeros} zeros");
    }

    /// `brackets` proves a float within `|x|·2⁻⁴²` of the interval's root and nothing
    /// farther: at √2 and off it, at one of two roots `10⁻³` apart, and not for an `x` whose
    /// bracket leaves the interval or for `x = 0`. `to_f64` of each close root (Newton's
    /// rounding bound too coarse there) is within that distance of the exact root.
    #[test]
    fn float_roots_bracketed_by_two_exact_signs() {
        let r = |n: i64, d: i64| RBig::from_parts_signed(n.into(), d.into());
        let p = Poly::from_i64s(&[-2, 0, 1]);
        assert!(brackets(&p, &r(1, 1), &r(2, 1), std::f64::consts::SQRT_2));
        assert!(!brackets(&p, &r(1, 1), &r(2, 1), 1.414));
        assert!(!brackets(
            &p,
            &r(14142, 10000),
            &r(141421356237, 100000000000),
            std::f64::consts::SQRT_2
        ));
        // (1000x − 1001)(1000x − 1002): roots 1.001 and 1.002
        let q = &Poly::from_i64s(&[-1001, 1000]) * &Poly::from_i64s(&[-1002, 1000]);
        let (lo, hi) = (r(10005, 10000), r(10015, 10000));
        assert!(brackets(&q, &lo, &hi, 1.001));
        assert!(!brackets(&q, &lo, &hi, 1.0012));
        assert!(!brackets(
            &Poly::from_i64s(&[0, 1]),
            &r(-1, 1),
            &r(1, 1),
            0.0
        ));
        // close roots of a product with large coefficients: Newton's bound fails, the
        // bracket holds, and the float is that close to the root
        let big =
            &Poly::from_i64s(&[-1_000_001, 1_000_000]) * &Poly::from_i64s(&[-1_000_002, 1_000_000]);
        let wide = &big * &Poly::from_i64s(&[-3_000_000_000, 0, 1_000_000_000]);
        // 10³⁰(x − 1)³ − 1, one real root 1 + 10⁻¹⁰ in a wide interval: the float values
        // within ~5·10⁻⁶ of it are all rounding (~10¹⁴ against |p| < 10¹⁴ there), so Newton's
        // float root is off by up to that, and only the exact refinement gives the root
        let e30 = IBig::from(10u64).pow(30);
        let three = &e30 * IBig::from(3);
        let ill = Poly::new(vec![-(&e30 + IBig::ONE), three.clone(), -three, e30]);
        for root in AlgebraicReal::real_roots_of(&wide)
            .into_iter()
            .chain(AlgebraicReal::real_roots_of(&ill))
        {
            let x = root.to_f64();
            let exact = root.refined_interval(&r(1, 1 << 62));
            let mid = (exact.lo().to_f64().value() + exact.hi().to_f64().value()) / 2.0;
            assert!(
                (x - mid).abs() <= mid.abs() * 2f64.powi(-41),
                "{x} vs {mid}"
            );
        }
    }

    #[test]
    fn comparing_a_narrow_number_with_a_wide_one_refines_only_the_wide_one() {
        // √2 refined far, √3 not at all: the comparison must not refine √2 further
        let sqrt2 = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 1]))
            .pop()
            .unwrap();
        let fine = RBig::from_parts(IBig::ONE, dashu_int::UBig::ONE << 4000);
        let narrow = sqrt2.refined_interval(&fine);
        let sqrt3 = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-3, 0, 1]))
            .pop()
            .unwrap();
        assert_eq!(sqrt2.cmp(&sqrt3), std::cmp::Ordering::Less);
        assert_eq!(
            sqrt2.refined_interval(&RBig::ONE),
            narrow,
            "√2 was refined again"
        );
    }
    use super::*;
    use crate::poly::sturm::SturmSequence;
    use proptest::prelude::*;

    fn rat(n: i64, d: i64) -> RBig {
        RBig::from_parts_signed(n.into(), d.into())
    }

    /// `T₆` and `1024 T₆ − 1`: their product has degree 12 and six pairs of roots about
    /// `10⁻⁴` apart.
    fn close_pair_factors() -> [Poly; 2] {
        let (mut a, mut b) = (Poly::from_i64s(&[1]), Poly::from_i64s(&[0, 1]));
        for _ in 0..6 {
            let c = &(&Poly::from_i64s(&[0, 2]) * &b) - &a;
            (a, b) = (b, c);
        }
        let other = &a.scale(&IBig::from(1024)) - &Poly::from_i64s(&[1]);
        [a, other]
    }

    /// Repeated signs reuse the shared refinement: clones see it, the stated interval
    /// stays, and a second sign does not refine again.
    #[test]
    fn refinement_is_shared_and_kept() {
        fn send_sync<T: Send + Sync + Clone>() {}
        send_sync::<AlgebraicReal>();
        let [t6, other] = close_pair_factors();
        let m = &t6 * &other;
        let roots = AlgebraicReal::real_roots_of(&m);
        assert_eq!(roots.len(), 12);
        // the widest isolating interval of the seventh root
        let stated = RootInterval::Open(
            roots[5].rational_between(&roots[6]),
            roots[6].rational_between(&roots[7]),
        );
        let a = &AlgebraicReal::from_isolating_interval(&m, &stated).expect("isolated");
        let b = a.clone();
        let width = |iv: &RootInterval| iv.hi() - iv.lo();
        // the factor that does not vanish: its sign needs α apart from its close neighbour
        let q = if a.sign_of_sturm_tarski(&t6).is_zero() {
            other
        } else {
            t6
        };
        let s = a.sign_of_sturm_tarski(&q);
        assert!(!s.is_zero());
        assert_eq!(sign_on_interval(&q, stated.lo(), stated.hi()), None);
        assert_eq!(a.sign_of(&q), s);
        let after_first = b.refined_interval(&RBig::from(1000));
        assert!(width(&after_first) < width(&stated));
        assert_eq!(b.interval(), &stated);
        for _ in 0..10 {
            assert_eq!(b.sign_of(&q), s);
        }
        assert_eq!(a.refined_interval(&RBig::from(1000)), after_first);
        assert!(a.is_valid() && b.is_valid());
        // refine_to narrows the stated interval of this value only
        let mut c = b.clone();
        c.refine_to(&rat(1, 1 << 40));
        assert!(width(c.interval()) < rat(1, 1 << 40));
        assert_eq!(a.interval(), &stated);
        assert_eq!(
            a.to_string(),
            format!("root of {m} in ({}, {})", stated.lo(), stated.hi())
        );
    }

    proptest! {
        /// A sign from interval arithmetic holds on the whole interval (Sturm count and
        /// an end), and a narrow interval about a non-root decides.
        #[test]
        fn interval_signs_are_rigorous(
            c in prop::collection::vec(-20i64..20, 1..9),
            lo in (-40i64..40, 1i64..10),
            w in (1i64..40, 1i64..10),
        ) {
            let q = Poly::from_i64s(&c);
            let lo = rat(lo.0, lo.1);
            let hi = &lo + rat(w.0, w.1);
            if let Some(s) = sign_on_interval(&q, &lo, &hi) {
                prop_assert_eq!(q.sign_at(&lo), s);
                if q.degree().unwrap_or(0) > 0 {
                    prop_assert_eq!(SturmSequence::new(&q).count_roots_in(&lo, &hi), 0);
                }
            }
            let s = q.sign_at(&lo);
            if !s.is_zero() {
                let eps = RBig::from_parts_signed(IBig::ONE, IBig::ONE << 80);
                prop_assert_eq!(sign_on_interval(&q, &(&lo - &eps), &(&lo + &eps)), Some(s));
            }
        }

        /// `sign_of` (intervals, gcd, refinement) agrees with the Sturm–Tarski sign, zeros
        /// included (`q` shares a factor with `p`).
        #[test]
        fn signs_agree_with_sturm_tarski(
            f in prop::collection::vec(-9i64..9, 2..5),
            g in prop::collection::vec(-9i64..9, 2..5),
            r in prop::collection::vec(-9i64..9, 1..5),
            shared in any::<bool>(),
        ) {
            let (f, g, r) = (Poly::from_i64s(&f), Poly::from_i64s(&g), Poly::from_i64s(&r));
            let q = if shared { &f * &r } else { &(&f * &r) + &g };
            for alpha in AlgebraicReal::real_roots_of(&(&f * &g)) {
                let s = alpha.sign_of(&q);
                prop_assert_eq!(s, alpha.sign_of_sturm_tarski(&q), "{} at {}", q, alpha);
                prop_assert_eq!(alpha.sign_of(&q), s);
                if shared && alpha.is_root_of(&f) {
                    prop_assert_eq!(s, Sign::Zero);
                }
            }
        }
    }

    /// An interval isolating a root of a multiple of `poly` gives that root when `poly`
    /// changes sign on it (or vanishes at an exact end), and nothing otherwise.
    #[test]
    fn roots_from_isolating_intervals() {
        let x2m2 = Poly::from_i64s(&[-2, 0, 1]); // roots ±√2
        let other = Poly::from_i64s(&[-3, 1]); // root 3
        let sqrt2 = RootInterval::Open(RBig::ONE, RBig::from(2));
        let r = AlgebraicReal::from_isolating_interval(&x2m2, &sqrt2).expect("√2 in (1, 2)");
        assert_eq!(r.poly(), &x2m2);
        assert_eq!(r.interval(), &sqrt2);
        assert!(AlgebraicReal::from_isolating_interval(&other, &sqrt2).is_none());
        let three = RootInterval::Exact(RBig::from(3));
        assert_eq!(
            AlgebraicReal::from_isolating_interval(&other, &three)
                .and_then(|r| r.as_rational().cloned()),
            Some(RBig::from(3))
        );
        assert!(AlgebraicReal::from_isolating_interval(&x2m2, &three).is_none());
    }

    #[test]
    fn ordering_of_close_irrationals() {
        let s2 = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 1]));
        let s3 = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-3, 0, 1]));
        assert!(s2[1] < s3[1] && s3[0] < s2[0]);
        // √2 from another polynomial: (x² − 2)(x − 5)
        let other = AlgebraicReal::real_roots_of(
            &(&Poly::from_i64s(&[-2, 0, 1]) * &Poly::from_roots(&[5])),
        );
        assert_eq!(other[1], s2[1]);
        assert!(other[1].is_valid());
        let between = s2[1].rational_between(&s3[1]);
        assert!(AlgebraicReal::from_rational(between.clone()) > s2[1]);
        assert!(AlgebraicReal::from_rational(between) < s3[1]);
    }

    /// Regression: the refined interval (1, 2) of √2 had both ends on roots of
    /// q = 2(x − 1)(x − 2), and the sign was read at an end: zero.
    #[test]
    fn sign_with_roots_of_q_on_both_ends() {
        let r = AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-2, 0, 1]));
        let q = Poly::from_i64s(&[4, -6, 2]);
        assert_eq!(r[1].sign_of(&q), Sign::Negative);
        assert_eq!(r[0].sign_of(&q), Sign::Positive);
        assert_eq!(
            AlgebraicReal::real_roots_of(&Poly::from_i64s(&[-3, 2]))[0].as_rational(),
            Some(&RBig::from_parts_signed(3.into(), 2.into()))
        );
    }

    #[test]
    fn signs_at_roots_with_common_factors() {
        // α = root of x³ − 2 (real), q = (x³ − 2)(x + 1) vanishes, q' does not
        let p = Poly::from_i64s(&[-2, 0, 0, 1]);
        let a = AlgebraicReal::real_roots_of(&p)
            .pop()
            .expect("one real root");
        let q = &p * &Poly::from_i64s(&[1, 1]);
        assert!(a.is_root_of(&q));
        assert_eq!(a.multiplicity_in(&(&q * &p)), 2);
        // α¹⁹ = 64α ≈ 80.635
        let mut c = vec![0i64; 20];
        c[19] = 1;
        c[0] = -80;
        assert_eq!(a.sign_of(&Poly::from_i64s(&c)), Sign::Positive);
        c[0] = -81;
        assert_eq!(a.sign_of(&Poly::from_i64s(&c)), Sign::Negative);
        assert!((a.to_f64() - 2f64.cbrt()).abs() < 1e-12);
    }

    /// Equal numbers compare `Equal` without refinement, whatever their states: one number
    /// and its clone refined to `2⁻¹²⁷` (shared state: repeated comparisons did not end
    /// before, seen on QI's qi-072 via `param::expr`), a fresh copy, the same root of a reducible multiple of its
    /// polynomial; different roots of one polynomial still order, and `to_f64` is the root.
    #[test]
    fn equal_roots_compare_equal_whatever_their_refinement() {
        let p = Poly::from_i64s(&[128, 0, -32, 0, 1]); // x⁴ − 32x² + 128, roots ±√(16 ± 8√2)
        let iv = RootInterval::Open(rat(5, 1), rat(21, 4));
        let a = AlgebraicReal::from_isolating_interval(&p, &iv).expect("a root in (5, 21/4)");
        let shared = a.clone();
        let _ = a.refined_interval(&RBig::from_parts_signed(IBig::ONE, IBig::ONE << 127));
        let fresh = AlgebraicReal::from_isolating_interval(&p, &iv).unwrap();
        let reducible = &p * &Poly::from_i64s(&[-2, 0, 1]);
        let wide = RootInterval::Open(rat(4, 1), rat(6, 1));
        let multiple = AlgebraicReal::from_isolating_interval(&reducible, &wide).unwrap();
        // before, each comparison refined the shared state past its own end: the bits
        // doubled at every comparison
        for _ in 0..64 {
            for x in [&shared, &fresh, &multiple] {
                assert_eq!(a.cmp(x), Ordering::Equal);
                assert_eq!(x.cmp(&a), Ordering::Equal);
            }
        }
        let bits = |x: &AlgebraicReal| {
            let r = x.refined_interval(&RBig::ONE);
            r.hi().denominator().bit_len()
        };
        assert!(
            bits(&a) < 200 && bits(&fresh) < 10,
            "{} {}",
            bits(&a),
            bits(&fresh)
        );
        let roots = AlgebraicReal::real_roots_of(&reducible);
        let want = [
            -(16.0 + 8.0 * 2f64.sqrt()).sqrt(),
            -(16.0 - 8.0 * 2f64.sqrt()).sqrt(),
            -2f64.sqrt(),
            2f64.sqrt(),
            (16.0 - 8.0 * 2f64.sqrt()).sqrt(),
            (16.0 + 8.0 * 2f64.sqrt()).sqrt(),
        ];
        assert_eq!(roots.len(), 6);
        for (i, r) in roots.iter().enumerate() {
            assert!((r.to_f64() - want[i]).abs() < 1e-12, "{r}");
            assert_eq!(r.cmp(&a), want[i].partial_cmp(&want[5]).unwrap(), "{r}");
            for (j, o) in roots.iter().enumerate() {
                assert_eq!(r.cmp(o), i.cmp(&j));
            }
        }
    }

    /// `v` (below `2²⁵⁵` in magnitude) in two's complement words.
    fn to_wide(v: &IBig) -> Wide {
        let m = dashu_int::ops::UnsignedAbs::unsigned_abs(v);
        let mut w = [0u64; 4];
        w[..m.as_words().len()].copy_from_slice(m.as_words());
        if v < &IBig::ZERO {
            wide_neg(w)
        } else {
            w
        }
    }

    /// The primitive part in words equals the big-integer one: contents 1, a power of two
    /// (the shifts), small odd ones (the residues in words), one beyond `u64` (big integers),
    /// least coefficients inside and outside `u128`, zero coefficients, both signs.
    #[test]
    fn primitive_wide_equals_the_big_primitive_part() {
        let mut rng = crate::testing::SplitMix(4711);
        let mut routes = [0usize; 4];
        for t in 0..400 {
            let bits = [20, 100, 127, 140, 180][t % 5];
            let len = rng.int(2, 9) as usize;
            let mut c: Vec<IBig> = (0..len)
                .map(|i| {
                    if i + 1 < len && rng.int(0, 4) == 0 {
                        return IBig::ZERO;
                    }
                    let mut v = IBig::from(rng.next_u64() | 1);
                    while v.bit_len() < bits {
                        v = (v << 64) + IBig::from(rng.next_u64());
                    }
                    let shift = v.bit_len() - rng.int(1, bits as i64) as usize;
                    let v = v >> shift;
                    let v = if v.is_zero() { IBig::ONE } else { v };
                    if rng.int(0, 1) == 0 {
                        -v
                    } else {
                        v
                    }
                })
                .collect();
            let route = (t / 5) % 4;
            let factor = match route {
                0 => IBig::ONE,
                1 => IBig::ONE << rng.int(1, 60) as usize,
                2 => IBig::from(rng.int(1, 1 << 20) * 2 + 1),
                _ => (IBig::ONE << 70) + IBig::from(rng.int(0, 1 << 30) * 2 + 1),
            };
            for v in &mut c {
                *v *= &factor;
            }
            if c.iter().any(|v| v.bit_len() >= 254) {
                continue;
            }
            routes[route] += 1;
            let wide: Vec<Wide> = c.iter().map(to_wide).collect();
            let want = Poly::new(c.clone()).primitive_part();
            assert_eq!(primitive_wide(&wide), want, "{c:?}");
        }
        assert!(routes.iter().all(|&r| r >= 50), "{routes:?}");
    }

    /// The norms in machine words (`i128`, 256-bit) against big integers, for coefficients of
    /// 3 to 126 bits and `δ` up to 2⁶¹ (the ranges where each applies and beyond), and the
    /// roots of `s = A + B√δ` as valid numbers of that norm, equal to the exact ones.
    #[test]
    fn zsqrt_norms_and_roots_agree_with_big_integers() {
        let mut rng = crate::testing::SplitMix(808);
        let (mut roots_seen, mut wide_seen) = (0, 0);
        for t in 0..300 {
            let bits = [3, 30, 62, 90, 126][t % 5];
            let rand = |rng: &mut crate::testing::SplitMix, bits: usize| {
                let mut v = IBig::ZERO;
                for _ in 0..bits.div_ceil(32) {
                    v = (v << 32) + IBig::from(rng.next_u64() >> 32);
                }
                let v = v >> (bits.div_ceil(32) * 32 - bits);
                // a common factor now and then (the content of s)
                let v = if t % 3 == 0 { v * IBig::from(12) } else { v };
                if rng.int(0, 1) == 0 {
                    -v
                } else {
                    v
                }
            };
            let n = rng.int(1, 4) as usize;
            let a: Vec<IBig> = (0..=n).map(|_| rand(&mut rng, bits)).collect();
            let b: Vec<IBig> = (0..=n).map(|_| rand(&mut rng, bits)).collect();
            let delta = IBig::from(rng.int(2, 1 << 40) * 2 + 1) << [0, 20][t % 2];
            if (a[0].is_zero() && b[0].is_zero()) || (a[n].is_zero() && b[n].is_zero()) {
                continue;
            }
            let (pa, pb) = (Poly::new(a.clone()), Poly::new(b.clone()));
            let want =
                (&(&pa * &pa) - &(&(&pb * &pb) * &Poly::constant(delta.clone()))).primitive_part();
            let ra: Vec<&IBig> = a.iter().collect();
            let rb: Vec<&IBig> = b.iter().collect();
            assert_eq!(norm_zsqrt(&ra, &rb, &delta), want, "{pa} {pb} {delta}");
            if let Some(w) = norm_wide(&ra, &rb, &delta) {
                assert_eq!(w, want, "{pa} {pb} {delta}");
                wide_seen += 1;
            }
            if let Some(roots) = AlgebraicReal::certified_real_roots_zsqrt(&ra, &rb, &delta) {
                let exact: Vec<AlgebraicReal> = AlgebraicReal::real_roots_of(&want)
                    .into_iter()
                    .filter(|r| {
                        let iv = r.interval();
                        let s = |x: &RBig| {
                            let (va, vb) = (pa.eval_rational(x), pb.eval_rational(x));
                            let t = &va * &va - &vb * &vb * RBig::from(delta.clone());
                            // the sign of va + vb√δ
                            match (Sign::of_rational(&va), Sign::of_rational(&vb)) {
                                (sa, Sign::Zero) => sa,
                                (Sign::Zero, sb) => sb,
                                (sa, sb) if sa == sb => sa,
                                (sa, sb) => {
                                    if t > RBig::ZERO {
                                        sa
                                    } else {
                                        sb
                                    }
                                }
                            }
                        };
                        s(iv.lo()) != s(iv.hi())
                    })
                    .collect();
                assert_eq!(roots, exact, "{pa} {pb} {delta}");
                for r in &roots {
                    assert!(r.is_valid() && r.poly() == &want, "{r:?}");
                    // one norm, made once, for all the roots of one s
                    assert!(std::ptr::eq(r.poly(), roots[0].poly()));
                }
                roots_seen += roots.len();
            }
        }
        assert!(
            roots_seen > 100 && wide_seen > 150,
            "{roots_seen} {wide_seen}"
        );
    }
}
