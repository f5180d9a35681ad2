//! Real root isolation with rational isolating intervals: Descartes' rule of signs on
//! dyadic intervals, with Newton steps for clusters and exponent splits for scale, and
//! quadratic interval refinement for single roots.
//!
//! Postconditions of [`isolate_real_roots`]: the result lists every distinct real root
//! once, in increasing order; each is either an exact rational or an open interval
//! `(lo, hi)` with rational (dyadic) ends that are not roots, containing exactly one root;
//! the intervals are pairwise disjoint and none holds 0 (callers read a root's sign from
//! its interval). A rational root is exact whenever the leading
//! coefficient of the square-free part has at most 64 bits (otherwise it may be either).
//!
//! For degree ≤ [`MAX_CERTIFIED_DEGREE`] the certified float path ([`certified`]: Aberth–
//! Ehrlich and inclusion disks with rigorous error bounds) gives the same postconditions
//! with other intervals, or `None`. It is not the default here: a caller that reads
//! anything off the intervals' shape would change its (correct) results — the pencil once
//! picked "the simplest rational between two roots" from the intervals, and on `rw2-43` of
//! the stress set got a member with 900-bit coefficients; it now picks from the roots alone
//! ([`between_roots`]) and takes the certified path first, as `param::discriminant_roots`.
//!
//! # Method and cost
//! Positive and negative roots are isolated apart (root 0 is pulled out first), each
//! inside `(2^−k₁, 2^k₂)` from Fujiwara's bounds on the roots of `p` and of its reverse. A
//! work list (no recursion) holds open dyadic intervals; for each, the Descartes bound `v`
//! of `p` on it is computed from `p` afresh, so nothing is kept alive between steps:
//! - `v = 0`: no root; `v = 1`: one root, isolated.
//! - an interval whose ends differ by more than a factor four is split at a power of two
//!   between them (the exponent is halved), so roots of tiny or huge size cost a number of
//!   steps logarithmic in the number of bits of their size, not linear;
//! - an interval whose bound did not drop at its last split holds a cluster: a Newton step
//!   for a `v`-fold root from its ends proposes a subinterval of width `w/N`; it is taken
//!   when its own bound is still `v` (Descartes' bound is subadditive on disjoint
//!   subintervals, so the rest holds no root), and `N` is squared; otherwise the interval is
//!   bisected and `N` goes down to `√N` (Sagraloff's Newton–Descartes scheme, real roots only);
//! - rational roots met at split points are recorded exactly and divided out.
//!
//! Two roots `2^−L` apart thus cost `O(log L)` steps instead of `L`, each a Taylor shift of
//! a degree-`n` polynomial with coefficients of `O(n(L + τ))` bits. Single roots are
//! refined by Abbott's quadratic interval refinement ([`refine`]): a secant step picks one
//! of `N` pieces, checked by two signs.

pub mod certified;
mod simplest;

pub use certified::{
    certified_real_roots, certified_real_roots_enclosed, certified_real_roots_zsqrt,
    quartic_roots_f64, CertifiedRoot, MAX_CERTIFIED_DEGREE,
};
pub use simplest::{between_roots, floor_of_root, simplest_rational_in, Bound};

use crate::budget::{poly_step_units, Budget, Exhausted};
use crate::poly::Poly;
use crate::sign::Sign;
use dashu_int::ops::{BitTest, UnsignedAbs};
use dashu_int::IBig;
use dashu_ratio::RBig;

/// An isolated real root.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RootInterval {
    /// A rational root, found exactly.
    Exact(RBig),
    /// Exactly one root in the open interval `(lo, hi)`; `lo` and `hi` are not roots.
    Open(RBig, RBig),
}

impl RootInterval {
    /// Lower end (the value itself for an exact root).
    pub fn lo(&self) -> &RBig {
        match self {
            RootInterval::Exact(v) => v,
            RootInterval::Open(l, _) => l,
        }
    }
    /// Upper end (the value itself for an exact root).
    pub fn hi(&self) -> &RBig {
        match self {
            RootInterval::Exact(v) => v,
            RootInterval::Open(_, h) => h,
        }
    }

    /// `Some(v)` for a root known exactly.
    pub fn as_exact(&self) -> Option<&RBig> {
        match self {
            RootInterval::Exact(v) => Some(v),
            RootInterval::Open(..) => None,
        }
    }

    /// The same root of `p(−x)`: `−hi < x < −lo`.
    fn negated(self) -> RootInterval {
        match self {
            RootInterval::Exact(v) => RootInterval::Exact(-v),
            RootInterval::Open(l, h) => RootInterval::Open(-h, -l),
        }
    }
}

/// A power of two strictly larger than the absolute value of every root (Fujiwara's bound
/// `|x| ≤ 2·maxᵢ |a_{n−i}/a_n|^{1/i}`, read off bit lengths; within a factor of about 4 of
/// the largest root, where Cauchy's bound can be its `n`-th power).
pub fn root_bound_log2(p: &Poly) -> usize {
    let c = p.coeffs();
    let Some((lead, rest)) = c.split_last() else {
        return 1;
    };
    let lead_bits = bit_len(lead);
    let n = rest.len();
    // |a_{n−i}/a_n| < 2^(bits − lead_bits + 1), so its i-th root is below 2^(kᵢ + 1/i) with
    // kᵢ = ⌈(bits − lead_bits)/i⌉, and Fujiwara's bound below 2·2^(k + 1) = 2^(k + 2).
    let k = rest
        .iter()
        .enumerate()
        .filter(|(_, v)| !v.is_zero())
        .map(|(j, v)| bit_len(v).saturating_sub(lead_bits).div_ceil(n - j))
        .max()
        .unwrap_or(0);
    k + 2
}

/// Isolates the real roots of a polynomial (multiple roots are reported once).
///
/// Roots closer than `2^−L` cost `O(log L)` Newton steps (see the module docs); memory
/// stays linear in the bits of the polynomial and of the intervals.
///
/// ```
/// # use qsic_algebra::{Poly, roots::{isolate_real_roots, RootInterval}};
/// # use qsic_algebra::RBig;
/// let p = &Poly::from_roots(&[0, 3]) * &Poly::from_i64s(&[-2, 0, 1]); // x(x−3)(x²−2)
/// let r = isolate_real_roots(&p);
/// assert_eq!(r.len(), 4);
/// assert_eq!(r[1], RootInterval::Exact(RBig::ZERO));
/// assert!(r[0].hi() < &RBig::ZERO && r[2].lo() > &RBig::ZERO);
/// ```
pub fn isolate_real_roots(p: &Poly) -> Vec<RootInterval> {
    if p.degree().unwrap_or(0) == 0 {
        return Vec::new();
    }
    isolate_squarefree_real_roots(&p.squarefree_part())
}

/// [`isolate_real_roots`] for a polynomial known to be square-free and primitive (such as
/// a product of the factors of a square-free decomposition), which skips recomputing its
/// square-free part.
pub fn isolate_squarefree_real_roots(sf: &Poly) -> Vec<RootInterval> {
    isolate_squarefree_real_roots_descartes(sf)
}

/// [`isolate_squarefree_real_roots`] by Descartes' rule alone (the exact path; module docs).
pub fn isolate_squarefree_real_roots_descartes(sf: &Poly) -> Vec<RootInterval> {
    isolate_squarefree_real_roots_within(sf, &Budget::unlimited())
        .expect("an unlimited budget is never spent")
}

/// [`isolate_squarefree_real_roots_descartes`] spending `budget`: each cell of the work list
/// costs about `(d + 1)²·ℓ` units (the Descartes test's Taylor shift on a polynomial of
/// degree `d` with `ℓ`-limb coefficients).
///
/// # Errors
/// [`Exhausted`] when the budget runs out.
pub fn isolate_squarefree_real_roots_within(
    sf: &Poly,
    budget: &Budget,
) -> Result<Vec<RootInterval>, Exhausted> {
    debug_assert!(sf.is_squarefree(), "isolate_squarefree_real_roots: {sf}");
    if sf.degree().unwrap_or(0) == 0 {
        return Ok(Vec::new());
    }
    let mut sf = sf.clone();
    let mut out = Vec::new();
    if sf.coeff(0).is_zero() {
        out.push(RootInterval::Exact(RBig::ZERO));
        sf = sf.shift_down(1);
    }
    out.extend(
        isolate_positive(&sf.scale_var(&IBig::NEG_ONE), budget)?
            .into_iter()
            .map(RootInterval::negated),
    );
    out.extend(isolate_positive(&sf, budget)?);
    out.sort_by(|a, b| a.lo().cmp(b.lo()));
    Ok(out)
}

/// An open interval `(lo·2^s, hi·2^s)` of the work list (`0 < lo < hi` integers), with the
/// Newton speed `N = 2^n_exp` and the Descartes bound of the interval it was split from.
struct Cell {
    lo: IBig,
    hi: IBig,
    s: isize,
    n_exp: usize,
    parent_var: usize,
}

impl Cell {
    /// The same interval with the common factors of two moved into `s`, so that the
    /// numbers a cell works with are as small as its position allows.
    fn normalized(mut self) -> Cell {
        let k = trailing_zeros(&self.lo).min(trailing_zeros(&self.hi));
        self.lo >>= k;
        self.hi >>= k;
        self.s += k as isize;
        self
    }
}

/// A root found by [`isolate_positive`]: `x·2^s`, or one root in `(lo·2^s, hi·2^s)`.
enum Found {
    Exact(IBig, isize),
    Open(IBig, IBig, isize),
}

/// What a Newton step gave.
enum Newton {
    /// A subinterval holding every root of the cell.
    Narrowed(Cell),
    /// A rational root `x·2^s` met inside the cell.
    Root(IBig, isize),
}

/// Isolates the positive roots of the square-free `p0` with `p0(0) ≠ 0` (none for a constant).
fn isolate_positive(p0: &Poly, budget: &Budget) -> Result<Vec<RootInterval>, Exhausted> {
    let mut isolation = PositiveIsolation::new(p0);
    let d = p0.degree().unwrap_or(0);
    while let Some(cell) = isolation.work.last() {
        let bits = isolation.p.max_bits() + d * (bit_len(&cell.hi) + cell.s.unsigned_abs());
        budget.spend(poly_step_units(d, bits).saturating_mul(d as u64 + 1))?;
        isolation.step();
    }
    Ok(isolation.roots())
}

/// The isolation of the positive roots of the square-free `p0` with `p0(0) ≠ 0`, run one
/// cell of the work list at a time (see the module docs).
struct PositiveIsolation<'a> {
    p0: &'a Poly,
    /// `p0` with the rational roots found so far divided out.
    p: Poly,
    work: Vec<Cell>,
    found: Vec<Found>,
}

impl<'a> PositiveIsolation<'a> {
    fn new(p0: &'a Poly) -> PositiveIsolation<'a> {
        let k_hi = root_bound_log2(p0);
        let k_lo = root_bound_log2(&p0.reverse());
        // Every positive root lies in (2^−k_lo, 2^k_hi), strictly.
        let cell = Cell {
            lo: IBig::ONE,
            hi: IBig::ONE << (k_hi + k_lo),
            s: -(k_lo as isize),
            n_exp: 2,
            parent_var: 0,
        };
        PositiveIsolation {
            p0,
            p: p0.clone(),
            work: vec![cell],
            found: Vec::new(),
        }
    }

    /// Examines the next cell of the work list: drops it, records its root, or replaces it
    /// by subcells. `false` when the list was empty.
    fn step(&mut self) -> bool {
        let Some(cell) = self.work.pop() else {
            return false;
        };
        // q(x) ∝ p(x·2^s): the cell is (lo, hi) for q, with integer ends.
        let q = scaled(&self.p, cell.s);
        let v = variations(&q, &cell.lo, &cell.hi);
        if v == 0 {
            return true;
        }
        if v == 1 {
            self.found.push(Found::Open(cell.lo, cell.hi, cell.s));
            return true;
        }
        let (la, lb) = (bit_len(&cell.lo), bit_len(&cell.hi));
        let (point, s, n_exp) = if lb >= la + 2 {
            // 2^((la + lb − 2)/2) lies strictly between lo < 2^la and hi ≥ 2^(lb − 1)
            (IBig::ONE << ((la + lb - 2) / 2), cell.s, cell.n_exp)
        } else {
            match (cell.parent_var == v)
                .then(|| newton_step(&q, &cell, v))
                .flatten()
            {
                Some(Newton::Narrowed(c)) => {
                    self.work.push(c.normalized());
                    return true;
                }
                Some(Newton::Root(x, s)) => (x, s, cell.n_exp),
                None => (&cell.lo + &cell.hi, cell.s - 1, (cell.n_exp / 2).max(2)),
            }
        };
        let up = (cell.s - s) as usize;
        debug_assert!(
            (&cell.lo << up) < point && point < (&cell.hi << up),
            "split points lie inside the cell"
        );
        let (lo, hi) = (&cell.lo << up, &cell.hi << up);
        if Sign::of(&scaled(&self.p, s).eval_integer(&point)).is_zero() {
            self.p = self
                .p
                .div_exact(&Poly::vanishing_at(&to_rational(&point, s)))
                .expect("a rational root gives a primitive linear factor");
            self.found.push(Found::Exact(point.clone(), s));
        }
        for (lo, hi) in [(point.clone(), hi), (lo, point)] {
            self.work.push(
                Cell {
                    lo,
                    hi,
                    s,
                    n_exp,
                    parent_var: v,
                }
                .normalized(),
            );
        }
        true
    }

    /// The roots found, once [`PositiveIsolation::step`] has emptied the work list.
    fn roots(self) -> Vec<RootInterval> {
        let (p0, p) = (self.p0, &self.p);
        // decided once for all the roots, and only if one is left open
        let mut irrational = None;
        self.found
            .into_iter()
            .map(|f| match f {
                Found::Exact(x, s) => RootInterval::Exact(to_rational(&x, s)),
                Found::Open(lo, hi, s) => {
                    let (lo, hi) = (to_rational(&lo, s), to_rational(&hi, s));
                    // An end may be a rational root divided out after the cell was made.
                    let on_root = p0.sign_at(&lo).is_zero() || p0.sign_at(&hi).is_zero();
                    let iv = RootInterval::Open(lo, hi);
                    let iv = if on_root {
                        move_ends_off_roots(p0, p, iv)
                    } else {
                        iv
                    };
                    if *irrational.get_or_insert_with(|| no_rational_root(p)) {
                        iv
                    } else {
                        exact_if_rational(p, iv)
                    }
                }
            })
            .collect()
    }
}

/// The primes of [`no_rational_root`]'s sieve.
const SIEVE_PRIMES: [u64; 12] = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37];

/// `true` only if the integer polynomial `p` has no rational root: some prime `ℓ` of
/// [`SIEVE_PRIMES`] divides neither the leading coefficient nor any value `p(x)`, `x ∈ 𝔽_ℓ`
/// (a root `a/b` in lowest terms has `b | lc(p)`, so `ℓ ∤ b` and `a·b⁻¹` would be a root
/// modulo `ℓ`). `false` means "not known". A sieve of a few hundred word operations that
/// spares [`exact_if_rational`]'s refinement to width `1/lc(p)` on each root.
pub(crate) fn no_rational_root(p: &Poly) -> bool {
    let Some(degree) = p.degree() else {
        return false;
    };
    if degree == 0 {
        return true;
    }
    SIEVE_PRIMES.iter().any(|&l| {
        let residues: Vec<u64> = p
            .coeffs()
            .iter()
            .map(|c| {
                let r = c % IBig::from(l);
                let r = i64::try_from(&r).expect("a residue below ℓ");
                r.rem_euclid(l as i64) as u64
            })
            .collect();
        residues[degree] != 0
            && (0..l).all(|x| residues.iter().rev().fold(0, |acc, &c| (acc * x + c) % l) != 0)
    })
}

/// The root of the primitive `p` in the open interval `iv`, exactly if it is a rational
/// whose denominator is below 2⁶⁴ in size, else `iv` (possibly narrowed).
///
/// A rational root `a/b` of a primitive integer polynomial has `b | lc(p)`, so `lc(p)·root`
/// is an integer: once the interval is shorter than `1/lc(p)`, one candidate is left.
/// Quadratic refinement makes this a handful of steps; leading coefficients above 64 bits
/// are skipped to keep the cost of huge inputs down.
fn exact_if_rational(p: &Poly, iv: RootInterval) -> RootInterval {
    let lc = p.leading();
    if bit_len(&lc) > 64 {
        return iv;
    }
    let lc = RBig::from(lc.unsigned_abs());
    let iv = refine(p, &iv, &(RBig::ONE / &lc));
    let RootInterval::Open(lo, hi) = &iv else {
        return iv;
    };
    let candidate = RBig::from((lo * &lc).floor() + IBig::ONE) / &lc;
    if &candidate < hi && p.sign_at(&candidate).is_zero() {
        RootInterval::Exact(candidate)
    } else {
        iv
    }
}

/// A Newton step for a cluster of `v` roots of `q` in `cell` (see the module docs).
fn newton_step(q: &Poly, cell: &Cell, v: usize) -> Option<Newton> {
    let dq = q.derivative();
    let width = &cell.hi - &cell.lo;
    let m = cell.n_exp + 2; // 4N = 2^m pieces of width w/4N
    let pieces = IBig::ONE << m;
    let base = &cell.lo << m;
    let q2 = scaled(q, -(m as isize)); // q at the finer grid
    for x0 in [&cell.lo, &cell.hi] {
        let dv = dq.eval_integer(x0);
        if dv.is_zero() {
            continue;
        }
        let qv = q.eval_integer(x0);
        // λ = x0 − v·q(x0)/q'(x0) lies in piece ℓ = ⌊(λ − lo)·2^m/w⌋
        let mut num = ((x0 - &cell.lo) * &dv - IBig::from(v) * qv) << m;
        let mut den = dv * &width;
        if den < IBig::ZERO {
            num = -num;
            den = -den;
        }
        let l = floor_div(&num, &den);
        if l < IBig::ZERO || l >= pieces {
            continue;
        }
        let i0 = (&l - IBig::ONE).max(IBig::ZERO);
        let i1 = (&l + IBig::from(2)).min(pieces.clone());
        let lo = &base + &i0 * &width;
        let hi = &base + &i1 * &width;
        let s2 = cell.s - m as isize;
        for (end, inside) in [(&lo, i0 > IBig::ZERO), (&hi, i1 < pieces)] {
            if inside && q2.eval_integer(end).is_zero() {
                return Some(Newton::Root(end.clone(), s2));
            }
        }
        if variations(&q2, &lo, &hi) == v {
            return Some(Newton::Narrowed(Cell {
                lo,
                hi,
                s: s2,
                n_exp: cell.n_exp * 2,
                parent_var: v,
            }));
        }
    }
    None
}

/// Narrows the interval of the one root of `q` in it until its ends are not roots of
/// `p0` (a multiple of `q` whose rational roots at the ends were divided out of `q`).
fn move_ends_off_roots(p0: &Poly, q: &Poly, iv: RootInterval) -> RootInterval {
    let mut iv = iv;
    let mut speed = 2;
    while let RootInterval::Open(lo, hi) = &iv {
        if !p0.sign_at(lo).is_zero() && !p0.sign_at(hi).is_zero() {
            break;
        }
        iv = refine_step(q, &iv, &mut speed);
    }
    iv
}

/// Bits of `|x|`.
fn bit_len(x: &IBig) -> usize {
    x.bit_len()
}

/// The number of factors two of `x > 0`.
fn trailing_zeros(x: &IBig) -> usize {
    x.trailing_zeros().unwrap_or(0)
}

/// `x·2^s` as a rational.
fn to_rational(x: &IBig, s: isize) -> RBig {
    if s >= 0 {
        RBig::from(x << s as usize)
    } else {
        RBig::from_parts_signed(x.clone(), IBig::ONE << s.unsigned_abs())
    }
}

/// `⌊num / den⌋` for `den > 0`.
fn floor_div(num: &IBig, den: &IBig) -> IBig {
    let q = num / den;
    if num < &IBig::ZERO && !(num % den).is_zero() {
        q - IBig::ONE
    } else {
        q
    }
}

/// A positive multiple of `p(x·2^s)` with integer coefficients: `cᵢ·2^(s·i)` for `s ≥ 0`,
/// `cᵢ·2^(−s·(n−i))` for `s < 0` (shifts only).
fn scaled(p: &Poly, s: isize) -> Poly {
    let c = p.coeffs();
    let n = c.len().saturating_sub(1);
    let d = s.unsigned_abs();
    Poly::new(
        c.iter()
            .enumerate()
            .map(|(i, v)| {
                if s >= 0 {
                    v << (d * i)
                } else {
                    v << (d * (n - i))
                }
            })
            .collect(),
    )
}

/// Descartes' bound for the roots of `q` in the open interval `(lo, hi)` with integer
/// ends: exact when it is 0 or 1, otherwise an upper bound of the same parity.
fn variations(q: &Poly, lo: &IBig, hi: &IBig) -> usize {
    // x = lo + (hi − lo)·t maps t ∈ (0, 1) onto the interval, t = 1/(1 + u) maps u ∈ (0, ∞)
    // onto (0, 1).
    q.shift(lo)
        .scale_var(&(hi - lo))
        .reverse()
        .shift(&IBig::ONE)
        .sign_variations()
}

/// A simple rational in `[lo, hi]`, `lo ≤ hi` (an end is allowed when its flag says so;
/// `lo < hi` or both allowed): an integer if there is one, else a dyadic with the smallest
/// denominator, so that later evaluations stay cheap.
pub fn simplest_between(lo: &RBig, hi: &RBig, lo_ok: bool, hi_ok: bool) -> RBig {
    if lo == hi {
        return lo.clone();
    }
    // try integers first
    let f = RBig::from(lo.floor()) + RBig::ONE;
    if &f < hi || (&f == hi && hi_ok) {
        return f;
    }
    if lo_ok && lo.denominator().is_one() {
        return lo.clone();
    }
    // The dyadics with denominator 2^k in the gap: there are some for every k past the
    // smallest one, so that k is found by a binary search; 2^−k < hi − lo is enough.
    let fits = |k: usize| -> Option<RBig> {
        let den = IBig::ONE << k;
        let cand = RBig::from_parts_signed((lo * RBig::from(den.clone())).floor() + IBig::ONE, den);
        ((&cand < hi || (&cand == hi && hi_ok)) && (&cand > lo || (&cand == lo && lo_ok)))
            .then_some(cand)
    };
    let w = hi - lo;
    let mut k_max =
        (bit_len(&IBig::from(w.denominator().clone())).saturating_sub(bit_len(w.numerator()))) + 2;
    let mut best = loop {
        match fits(k_max) {
            Some(c) => break c,
            None => k_max *= 2,
        }
    };
    let mut k_min = 0; // no dyadic of denominator 2^0 (an integer) fits: tried above
    while k_max - k_min > 1 {
        let k = (k_min + k_max) / 2;
        match fits(k) {
            Some(c) => {
                best = c;
                k_max = k;
            }
            None => k_min = k,
        }
    }
    best
}

/// A simple rational strictly between two consecutive roots isolated by
/// [`isolate_real_roots`] (`a` before `b`): it lies in the gap between their intervals.
///
/// ```
/// # use qsic_algebra::{Poly, RBig, roots::{isolate_real_roots, rational_between}};
/// let r = isolate_real_roots(&Poly::from_i64s(&[-2, 0, 1])); // ±√2
/// let m = rational_between(&r[0], &r[1]);
/// assert!(r[0].hi() <= &m && &m <= r[1].lo());
/// assert_eq!(RBig::from(m.floor()), m); // an integer fits in the gap
/// ```
pub fn rational_between(a: &RootInterval, b: &RootInterval) -> RBig {
    simplest_between(
        a.hi(),
        b.lo(),
        matches!(a, RootInterval::Open(..)),
        matches!(b, RootInterval::Open(..)),
    )
}

/// One root of `p` in `(lo/den, hi/den)`, `den > 0`, where `p` has opposite nonzero signs
/// at the ends; `2^n_exp` is the number of pieces the next secant step chooses from.
struct Bracket {
    lo: IBig,
    hi: IBig,
    den: IBig,
    n_exp: usize,
}

/// One step of quadratic interval refinement (Abbott): the secant through the ends picks
/// one of `N` pieces; if `p` changes sign on it, it is the new interval and `N` is squared,
/// otherwise the interval is halved and `N` goes to `√N`. Returns `Err(x)` when it meets
/// the root exactly.
fn qir_step(p: &Poly, b: Bracket) -> Result<Bracket, RBig> {
    let pl = p.eval_homogeneous(&b.lo, &b.den);
    let ph = p.eval_homogeneous(&b.hi, &b.den);
    let s_lo = Sign::of(&pl);
    let m = b.n_exp;
    let width = &b.hi - &b.lo;
    let den = &b.den << m;
    let base = &b.lo << m;
    // λ = lo + w·pl/(pl − ph) lies in piece ⌊2^m·pl/(pl − ph)⌋ ∈ [0, 2^m)
    let (mut num, mut d) = (pl.clone() << m, &pl - &ph);
    if d < IBig::ZERO {
        num = -num;
        d = -d;
    }
    let pieces = IBig::ONE << m;
    let l = floor_div(&num, &d).clamp(IBig::ZERO, &pieces - IBig::ONE);
    let a = &base + &l * &width;
    let c = &a + &width;
    let (sa, sc) = (
        Sign::of(&p.eval_homogeneous(&a, &den)),
        Sign::of(&p.eval_homogeneous(&c, &den)),
    );
    if sa.is_zero() {
        return Err(RBig::from_parts_signed(a, den));
    }
    if sc.is_zero() {
        return Err(RBig::from_parts_signed(c, den));
    }
    if sa == s_lo && sc != s_lo {
        return Ok(Bracket {
            lo: a,
            hi: c,
            den,
            n_exp: 2 * m,
        });
    }
    let (lo, hi, den) = (&b.lo << 1, &b.hi << 1, &b.den << 1);
    let mid = &b.lo + &b.hi;
    let n_exp = (m / 2).max(2);
    match Sign::of(&p.eval_homogeneous(&mid, &den)) {
        Sign::Zero => Err(RBig::from_parts_signed(mid, den)),
        s if s == s_lo => Ok(Bracket {
            lo: mid,
            hi,
            den,
            n_exp,
        }),
        _ => Ok(Bracket {
            lo,
            hi: mid,
            den,
            n_exp,
        }),
    }
}

/// One refinement step of an isolating interval of a root of `p` (at least a halving;
/// `speed` carries the state of the quadratic refinement between calls, start it at 2).
/// `p` must have opposite nonzero signs at the ends of an open interval.
pub fn refine_step(p: &Poly, root: &RootInterval, speed: &mut usize) -> RootInterval {
    let RootInterval::Open(lo, hi) = root else {
        return root.clone();
    };
    if let Some(iv) = split_orders_of_magnitude(p, lo, hi) {
        return iv;
    }
    let (dl, dh) = (
        IBig::from(lo.denominator().clone()),
        IBig::from(hi.denominator().clone()),
    );
    let g = crate::int_gcd(&dl, &dh);
    let bracket = Bracket {
        lo: lo.numerator() * &(&dh / &g),
        hi: hi.numerator() * &(&dl / &g),
        den: &dl / &g * &dh,
        n_exp: (*speed).max(2),
    };
    match qir_step(p, bracket) {
        Ok(b) => {
            *speed = b.n_exp;
            RootInterval::Open(
                RBig::from_parts_signed(b.lo, b.den.clone()),
                RBig::from_parts_signed(b.hi, b.den),
            )
        }
        Err(x) => RootInterval::Exact(x),
    }
}

/// For an interval of one sign whose ends differ by more than a factor 4, the half of it cut
/// at a power of two near the geometric mean that holds the root (secants are useless there).
fn split_orders_of_magnitude(p: &Poly, lo: &RBig, hi: &RBig) -> Option<RootInterval> {
    let negative = hi < &RBig::ZERO;
    let (a, b) = if negative {
        (-hi, -lo)
    } else {
        (lo.clone(), hi.clone())
    };
    if a <= RBig::ZERO {
        return None;
    }
    // ⌊log₂⌋ of a positive rational, to within one
    let log2 = |x: &RBig| {
        bit_len(x.numerator()) as isize - bit_len(&IBig::from(x.denominator().clone())) as isize
    };
    let (la, lb) = (log2(&a), log2(&b));
    if lb < la + 4 {
        return None;
    }
    let m = to_rational(&IBig::ONE, (la + lb) / 2);
    if m <= a || m >= b {
        return None;
    }
    let m = if negative { -m } else { m };
    Some(match p.sign_at(&m) {
        Sign::Zero => RootInterval::Exact(m),
        s if s == p.sign_at(lo) => RootInterval::Open(m, hi.clone()),
        _ => RootInterval::Open(lo.clone(), m),
    })
}

/// Narrows an isolating interval of a root of the square-free `p` until it is shorter
/// than `width` (or the root is found exactly). Quadratic refinement: about
/// `log₂ log₂ (1/width)` steps once the root is isolated from the other roots of `p`.
pub fn refine(p: &Poly, root: &RootInterval, width: &RBig) -> RootInterval {
    let mut iv = root.clone();
    let mut speed = 2;
    while let RootInterval::Open(lo, hi) = &iv {
        if &(hi - lo) < width {
            break;
        }
        iv = refine_step(p, &iv, &mut speed);
    }
    iv
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The sieve never claims "no rational root" for a polynomial with one (from random
    /// linear factors with denominators up to 40, whose numerators the primes may divide),
    /// and proves it for most products of random irreducible quadratics.
    #[test]
    fn the_rational_root_sieve_is_sound() {
        let mut rng = crate::testing::SplitMix(1729);
        let mut proved = 0;
        for _ in 0..200 {
            let quadratic = Poly::from_i64s(&[rng.int(1, 50), rng.int(-3, 3), rng.int(1, 9)]);
            let cubic = &quadratic * &Poly::from_i64s(&[rng.int(-9, 9), 0, 0, 1]);
            let linear = Poly::from_i64s(&[rng.int(-60, 60), rng.int(1, 40)]);
            assert!(!no_rational_root(&(&cubic * &linear)), "{cubic} · {linear}");
            let rational = crate::AlgebraicReal::real_roots_of(&cubic)
                .iter()
                .any(|r| r.as_rational().is_some());
            if no_rational_root(&cubic) {
                proved += 1;
                assert!(!rational, "{cubic}");
            }
        }
        assert!(proved >= 100, "{proved} of 200");
    }
    use proptest::prelude::*;

    fn check_isolation(p: &Poly, expected: usize) {
        let r = isolate_real_roots(p);
        assert_eq!(r.len(), expected, "{p}");
        let sf = p.squarefree_part();
        for w in r.windows(2) {
            assert!(
                w[0].hi() <= w[1].lo() && w[0].lo() < w[1].lo(),
                "{p}: {w:?}"
            );
        }
        for iv in &r {
            match iv {
                RootInterval::Exact(v) => assert_eq!(sf.sign_at(v), Sign::Zero),
                RootInterval::Open(l, h) => {
                    assert!(l < h);
                    assert_eq!(
                        sf.sign_at(l) * sf.sign_at(h),
                        Sign::Negative,
                        "{p} on ({l}, {h})"
                    );
                }
            }
        }
    }

    #[test]
    fn wilkinson_and_clustered() {
        let roots: Vec<i64> = (1..=20).collect();
        check_isolation(&Poly::from_roots(&roots), 20);
        check_isolation(
            &Poly::from_rational_roots(&[(1, 1000), (2, 1000), (1, 999), (-1, 1)]),
            4,
        );
        // Mignotte-like: x^4 − 2(100x − 1)² has two roots very close to 1/100
        let m = &Poly::from_i64s(&[0, 0, 0, 0, 1])
            - &(&Poly::from_i64s(&[-1, 100]) * &Poly::from_i64s(&[-2, 200]));
        check_isolation(&m, 4);
    }

    #[test]
    fn multiple_and_irrational_roots() {
        let p = &(&Poly::from_roots(&[2, 2, 2]) * &Poly::from_i64s(&[-2, 0, 1]))
            * &Poly::from_i64s(&[-2, 0, 1]);
        check_isolation(&p, 3);
        check_isolation(&Poly::from_i64s(&[1, 0, 1]), 0);
        check_isolation(&Poly::from_i64s(&[0, 0, 5]), 1);
    }

    #[test]
    fn huge_coefficients() {
        let big = IBig::from(10).pow(45);
        // (x − 10^45)(x + 1)(10^45 x − 1)
        let p = &(&Poly::new(vec![-big.clone(), IBig::ONE]) * &Poly::from_i64s(&[1, 1]))
            * &Poly::new(vec![IBig::from(-1), big]);
        check_isolation(&p, 3);
    }

    proptest! {
        #[test]
        fn sturm_and_descartes_agree(c in prop::collection::vec(-30i64..30, 2..8)) {
            let p = Poly::from_i64s(&c);
            prop_assume!(p.degree().unwrap_or(0) >= 1);
            let n = p.count_real_roots_sturm();
            check_isolation(&p, n);
        }

        #[test]
        fn known_rational_roots_are_found(roots in prop::collection::vec((-50i64..50, 1i64..20), 1..6)) {
            let p = &Poly::from_rational_roots(&roots) * &Poly::from_i64s(&[3, 1, 1]);
            let mut distinct: Vec<RBig> = roots.iter().map(|&(a, b)| RBig::from_parts_signed(IBig::from(a), IBig::from(b))).collect();
            distinct.sort();
            distinct.dedup();
            let r = isolate_real_roots(&p);
            prop_assert_eq!(r.len(), distinct.len());
            for (iv, v) in r.iter().zip(&distinct) {
                // small leading coefficient: every rational root is found exactly
                prop_assert_eq!(iv, &RootInterval::Exact(v.clone()));
            }
        }
    }
}

#[cfg(test)]
mod regression_tests {
    use super::*;

    /// Regression: the interval around −4/3 had both ends on the exact roots −3/2 and −5/4.
    #[test]
    fn interval_ends_on_exact_neighbour_roots() {
        let p = Poly::from_rational_roots(&[(-3, 2), (-4, 3), (-5, 4), (-1, 1)]);
        let r = isolate_real_roots(&p);
        assert_eq!(r.len(), 4);
        for iv in &r {
            if let RootInterval::Open(lo, hi) = iv {
                assert_eq!(p.sign_at(lo) * p.sign_at(hi), Sign::Negative);
            }
        }
    }
}

#[cfg(test)]
mod regression_zero_root {
    use super::*;

    /// Regression: with the root 0 pulled out first, the interval of the root 2 of
    /// x² − 2x was reported as (−8, 8), which also holds 0.
    #[test]
    fn root_at_zero_and_another() {
        let r = isolate_real_roots(&Poly::from_i64s(&[0, -2, 1]));
        assert_eq!(r.len(), 2);
        assert_eq!(r[0], RootInterval::Exact(RBig::ZERO));
        assert!(r[1].lo() >= &RBig::ZERO && r[1].hi() <= &RBig::from(8));
        assert!(!(r[1].lo() < &RBig::ZERO && r[1].hi() > &RBig::ZERO));
    }
}

#[cfg(test)]
mod cluster_tests {
    use super::*;

    fn ten_pow(k: usize) -> IBig {
        IBig::from(10).pow(k)
    }

    /// Checks the postconditions and returns the roots as `(lo, hi)`.
    fn isolated(p: &Poly) -> Vec<RootInterval> {
        let r = isolate_real_roots(p);
        let sf = p.squarefree_part();
        assert_eq!(r.len(), sf.count_real_roots_sturm());
        for w in r.windows(2) {
            assert!(w[0].hi() <= w[1].lo() && w[0].lo() < w[1].lo());
        }
        for iv in &r {
            match iv {
                RootInterval::Exact(v) => assert_eq!(sf.sign_at(v), Sign::Zero),
                RootInterval::Open(l, h) => {
                    assert!(l < h);
                    assert_eq!(sf.sign_at(l) * sf.sign_at(h), Sign::Negative);
                }
            }
        }
        r
    }

    /// Rational roots 1 and 1 + 10^−L, beside x² + 1: both found exactly or isolated.
    #[test]
    fn rational_roots_10_to_minus_6000_apart() {
        for l in [10, 100, 1600, 6000] {
            let t = ten_pow(l);
            let p = &(&Poly::from_i64s(&[-1, 1]) * &Poly::new(vec![-(&t + IBig::ONE), t.clone()]))
                * &Poly::from_i64s(&[1, 0, 1]);
            let r = isolated(&p);
            assert_eq!(r.len(), 2, "L = {l}");
            assert!(r[0].hi() <= &RBig::ONE && &RBig::ONE <= r[1].lo());
            let second = RBig::from_parts_signed(&t + IBig::ONE, t);
            assert!(r[1].lo() <= &second && &second <= r[1].hi());
        }
    }

    /// 10^2L (x² − 2)² − 1 has four irrational roots, two by two 10^−L/√2 apart.
    #[test]
    fn irrational_roots_10_to_minus_3000_apart() {
        for l in [5, 300, 3000] {
            let s = &Poly::from_i64s(&[-2, 0, 1]) * &Poly::from_i64s(&[-2, 0, 1]);
            let p = &s.scale(&ten_pow(2 * l)) - &Poly::from_i64s(&[1]);
            let r = isolated(&p);
            assert_eq!(r.len(), 4, "L = {l}");
            assert!(r.iter().all(|iv| matches!(iv, RootInterval::Open(..))));
        }
    }

    /// Roots 1, 2, 3 times 10^−6000 and −10^6000: tiny and huge scales in one polynomial.
    #[test]
    fn roots_at_tiny_and_huge_scales() {
        let t = ten_pow(6000);
        let mut p = Poly::new(vec![t.clone(), IBig::ONE]); // x + 10^6000
        for k in 1..=3 {
            p = &p * &Poly::new(vec![IBig::from(-k), t.clone()]);
        }
        p = &p * &Poly::from_i64s(&[-3, 0, 1]);
        let r = isolated(&p);
        assert_eq!(r.len(), 6);
        let big = RBig::from(-t.clone());
        assert!(r[0].lo() <= &big && &big <= r[0].hi());
        for (k, iv) in r[2..5].iter().enumerate() {
            let v = RBig::from_parts_signed(IBig::from(k + 1), t.clone());
            assert!(iv.lo() <= &v && &v <= iv.hi());
        }
    }

    /// Mignotte's x⁴ − 2(ax − 1)² with a = 10^400: two roots about a^−3 apart near 1/a.
    #[test]
    fn mignotte_cluster() {
        let a = ten_pow(400);
        let lin = Poly::new(vec![IBig::from(-1), a]);
        let p = &Poly::from_i64s(&[0, 0, 0, 0, 1]) - &(&lin * &lin).scale(&IBig::from(2));
        assert_eq!(isolated(&p).len(), 4);
    }

    /// The budgeted isolation gives the plain one's intervals, spends more on a cluster than
    /// on separated roots of the same degree and size, and stops one unit short.
    #[test]
    fn budgeted_isolation_spends_with_the_work() {
        let a = ten_pow(400);
        let lin = Poly::new(vec![IBig::from(-1), a.clone()]);
        let cluster = &Poly::from_i64s(&[0, 0, 0, 0, 1]) - &(&lin * &lin).scale(&IBig::from(2));
        // four separated roots with coefficients as long: (x² − 2)(x² − 3)·10^800 + 1
        let apart = &(&Poly::from_i64s(&[-2, 0, 1]) * &Poly::from_i64s(&[-3, 0, 1]))
            .scale(&(&a * &a))
            + &Poly::from_i64s(&[1]);
        let spend = |p: &Poly| {
            let budget = Budget::unlimited();
            let r = isolate_squarefree_real_roots_within(p, &budget).unwrap();
            assert_eq!(r, isolate_squarefree_real_roots(p));
            budget.used()
        };
        let (c, s) = (spend(&cluster), spend(&apart));
        assert!(c > 2 * s, "cluster {c}, apart {s}");
        assert_eq!(
            isolate_squarefree_real_roots_within(&cluster, &Budget::new(c - 1)),
            Err(Exhausted { limit: c - 1 })
        );
        assert!(isolate_squarefree_real_roots_within(&cluster, &Budget::new(c)).is_ok());
    }

    /// Refinement to 2^−20000 takes few quadratic steps, and the result is an interval of
    /// the root of the right width.
    #[test]
    fn quadratic_refinement_reaches_high_precision() {
        let p = Poly::from_i64s(&[-2, 0, 1]);
        let r = isolate_real_roots(&p).pop().expect("√2");
        let width = RBig::from_parts_signed(IBig::ONE, IBig::ONE << 20000);
        let mut steps = 0;
        let mut iv = r;
        let mut speed = 2;
        while let RootInterval::Open(lo, hi) = &iv {
            if (hi - lo) < width {
                break;
            }
            iv = refine_step(&p, &iv, &mut speed);
            steps += 1;
        }
        // bisection would need 20 000 steps; quadratic refinement about 2·log₂ 20000
        assert!(steps < 60, "{steps} steps");
        let RootInterval::Open(lo, hi) = iv else {
            panic!("√2 is irrational")
        };
        assert_eq!(p.sign_at(&lo) * p.sign_at(&hi), Sign::Negative);
        assert!(refine(&p, &RootInterval::Open(lo, hi), &width).lo() > &RBig::ONE);
    }
}

#[cfg(test)]
mod cost_tests {
    use super::*;

    /// The positive roots, and the number of cells examined: the cost measure bounded here.
    fn isolate_positive_counting_cells(p: &Poly) -> (Vec<RootInterval>, usize) {
        let mut isolation = PositiveIsolation::new(p);
        let mut cells = 0;
        while isolation.step() {
            cells += 1;
        }
        (isolation.roots(), cells)
    }

    fn ten_pow(k: usize) -> IBig {
        IBig::from(10).pow(k)
    }

    /// Two irrational roots about 10⁻¹⁰⁰⁰ apart near 1/3 (and 3): Newton steps separate them
    /// in far fewer cells than the ~3 300 halvings bisection needs.
    #[test]
    fn clusters_cost_logarithmically_many_cells() {
        let t = ten_pow(1000);
        // 10^2000 (3x − 1)² − 2: roots (1 ± √2·10^−1000)/3
        let sq = Poly::from_i64s(&[1, -6, 9]).scale(&(&t * &t));
        let p = &(&sq - &Poly::from_i64s(&[2])) * &Poly::from_i64s(&[-3, 1]);
        let (roots, cells) = isolate_positive_counting_cells(&p);
        assert_eq!(roots.len(), 3);
        assert!(cells < 150, "{cells} cells");
    }

    /// Roots of size 10^±3000: exponent splits find their scale in few cells.
    #[test]
    fn scales_cost_logarithmically_many_cells() {
        let t = ten_pow(3000);
        let p = &Poly::new(vec![-IBig::ONE, t.clone()]) * &Poly::new(vec![-t, IBig::ONE]);
        let (roots, cells) = isolate_positive_counting_cells(&p);
        assert_eq!(roots.len(), 2);
        assert!(cells < 200, "{cells} cells");
    }

    /// Rational roots are found exactly while the leading coefficient has at most 64 bits,
    /// and isolated (not searched for) beyond, to bound the cost of huge inputs.
    #[test]
    fn exact_rational_roots_up_to_64_bit_leading_coefficients() {
        let d64 = (IBig::ONE << 64) - IBig::ONE; // 64 bits
        let d65 = IBig::ONE << 64; // 65 bits
        for (d, exact) in [(d64, true), (d65, false)] {
            // (d·x − 3)(x² + 1)
            let p = &Poly::new(vec![IBig::from(-3), d.clone()]) * &Poly::from_i64s(&[1, 0, 1]);
            let r = isolate_real_roots(&p);
            assert_eq!(r.len(), 1);
            let v = RBig::from_parts_signed(IBig::from(3), d);
            assert!(r[0].lo() <= &v && &v <= r[0].hi());
            assert_eq!(matches!(r[0], RootInterval::Exact(_)), exact, "{:?}", r[0]);
        }
    }
}

#[cfg(test)]
mod bound_tests {
    use super::*;
    use proptest::prelude::*;

    /// Roots T, T + 1, 2T, −3T (T = 10^300): coefficients up to T⁴, where Cauchy's bound is
    /// about T⁴; Fujiwara's stays within a few bits of 3T.
    #[test]
    fn fujiwara_bound_is_tight_where_cauchy_is_not() {
        let t = IBig::from(10).pow(300);
        let lin = |c: IBig| Poly::new(vec![-c, IBig::ONE]);
        let p = &(&lin(t.clone()) * &lin(&t + IBig::ONE))
            * &(&lin(&t * IBig::from(2)) * &lin(&t * IBig::from(-3)));
        let k = root_bound_log2(&p);
        let three_t = bit_len(&(&t * IBig::from(3)));
        assert!(
            k > three_t && k <= three_t + 4,
            "2^{k} for roots below 2^{three_t}"
        );
        let r = isolate_real_roots(&p);
        assert_eq!(r.len(), 4);
        // small leading coefficient: the integer roots are found exactly
        assert!(
            r.iter().all(|iv| matches!(iv, RootInterval::Exact(_))),
            "{r:?}"
        );
    }

    proptest! {
        #[test]
        fn bound_exceeds_every_root(roots in prop::collection::vec(-1000i64..1000, 1..6), lead in 1i64..50) {
            let p = Poly::from_roots(&roots).scale(&IBig::from(lead));
            let bound = RBig::from(IBig::ONE << root_bound_log2(&p));
            for r in &roots {
                prop_assert!(RBig::from(r.abs()) < bound);
            }
        }

        /// Refinement of wide intervals (orders of magnitude first) keeps the root inside.
        #[test]
        fn refinement_keeps_the_root(root in 1i64..1_000_000, den_bits in 0usize..40) {
            // q·x − root·... : the root root/2^den_bits with x² + 1 beside it
            let d = IBig::ONE << den_bits;
            let p = &Poly::new(vec![-IBig::from(root), d.clone()]) * &Poly::from_i64s(&[1, 0, 1]);
            let v = RBig::from_parts_signed(IBig::from(root), d);
            let wide = RootInterval::Open(RBig::from_parts_signed(IBig::ONE, IBig::ONE << 60), RBig::from(IBig::ONE << 60));
            let mut iv = wide;
            let mut speed = 2;
            let mut steps = 0;
            let goal = RBig::from_parts_signed(IBig::ONE, IBig::ONE << 200);
            while let RootInterval::Open(lo, hi) = &iv {
                if (hi - lo) < goal {
                    break;
                }
                iv = refine_step(&p, &iv, &mut speed);
                prop_assert!(iv.lo() <= &v && &v <= iv.hi());
                steps += 1;
            }
            // 120 orders of magnitude and 200 bits: bisection alone would take 260 steps
            prop_assert!(steps < 80, "{} steps", steps);
        }
    }
}
