//! The class of a regular pencil at an irrational instant `t = α`, exactly, in `K = ℚ(α)`.
//!
//! The same analysis as [`crate::pencil`], with coefficients in `K` (dynamic evaluation,
//! exact signs): `f(λ; α)` split into square-free pieces of equal multiplicity and equal
//! orders in `D₁, D₂, D₃` (gcds over `K[λ]` of the minors); the real roots of their product
//! isolated by Sturm sequences over `K` and bisection; the inertia at multiple roots from the
//! signs of the principal-minor sums `E_k` there (Sturm–Tarski queries over `K`), on arcs at
//! rational samples, at simple roots from the neighbouring arcs. A single quadric at `α` is
//! typed by its inertia in `K`; a singular pencil at `α` by the singular classifier
//! instantiated over `K` ([`crate::classify::OrderedDomain`]: Kronecker structure, common
//! singular points, the projected pencil of conics, all decided by exact signs in `K`).
//!
//! **Work units** ([`Spend`]): a product in `K` is priced as `n²` products of `α`'s
//! coefficient size (`n = deg α`); the minors of the pencil over `K` cost their products up
//! front, each gcd and remainder step over `K[λ]` its coefficient operations, each bisection
//! step of the isolation the evaluation of its Sturm sequence. The singular classification
//! over `K` (which reads signs through [`OrderedDomain`]) is charged up front, as a few
//! hundred remainder sequences of degree 4.

use super::instants::TPoly;
use crate::classify::{
    classify_regular_parts, classify_single_inertia, classify_singular_in, Classification,
    OrderedDomain,
};
use crate::pencil::SigItem;
use qsic_algebra::budget::{product_units, Budget, Exhausted};
use qsic_algebra::field::number_field::{NumberField, NumberFieldElement as K};
use qsic_algebra::linalg::minors::SmallMinors;
use qsic_algebra::matrix::Inertia;
use qsic_algebra::{AlgebraicReal, Field, IBig, Poly, RBig, Ring, Sign};

/// The budget of one classification at `α` and the units of one product in `K = ℚ(α)`.
#[derive(Clone, Copy)]
pub(crate) struct Spend<'a> {
    budget: &'a Budget,
    product: u64,
}

impl<'a> Spend<'a> {
    /// For `K = ℚ(α)`: a product of two elements is `n²` coefficient products of the size
    /// of `α`'s defining polynomial (`n` its degree) and its reduction as much again.
    pub(crate) fn new(budget: &'a Budget, alpha: &AlgebraicReal) -> Spend<'a> {
        let (n, bits) = (
            alpha.poly().degree().unwrap_or(1).max(1),
            alpha.poly().max_bits(),
        );
        let product = (2 * n * n) as u64;
        Spend {
            budget,
            product: product.saturating_mul(product_units(bits, bits)),
        }
    }

    /// Spends `count` sign or zero tests at `α` of integer polynomials of degree at most
    /// `degree` with coefficients of at most `bits` bits: each a gcd with `α`'s defining
    /// polynomial (degree `n`) in the worst case — a remainder of `(n − d + 1)(d + 1)`
    /// coefficient steps, then `d²` more — priced at products of the larger of the two sizes.
    /// These are polynomials over ℤ, not elements of `K`, so a test is not priced as a
    /// product in `K` (`n²` coefficient products).
    pub(crate) fn sign_tests(
        &self,
        count: usize,
        degree: usize,
        bits: usize,
        alpha: &AlgebraicReal,
    ) -> Result<(), Exhausted> {
        let n = alpha.poly().degree().unwrap_or(1).max(1);
        let size = bits.max(alpha.poly().max_bits());
        let steps = ((n + 1) * (degree + 1) + degree * degree) as u64;
        self.budget.spend(
            (count as u64)
                .saturating_mul(steps)
                .saturating_mul(product_units(size, size)),
        )
    }

    /// Spends `count` products in `K`.
    pub(crate) fn products(&self, count: usize) -> Result<(), Exhausted> {
        self.budget
            .spend((count as u64).saturating_mul(self.product))
    }

    /// Spends a remainder or gcd step on polynomials of degrees `m ≥ n` over `K`.
    pub(crate) fn step(&self, m: usize, n: usize) -> Result<(), Exhausted> {
        self.products((m.saturating_sub(n) + 2) * (n + 1))
    }

    /// Spends a gcd of polynomials of degrees `m`, `n` over `K` (Euclid's `min(m, n)` steps).
    pub(crate) fn gcd(&self, m: usize, n: usize) -> Result<(), Exhausted> {
        let (hi, lo) = (m.max(n), m.min(n));
        self.products((hi + 2) * (lo + 1) * (lo + 1))
    }
}

/// Products in `K` of the minors of a 4×4 pencil over `K` (every minor of every order, by
/// expansion, with the principal-minor sums), charged before they are formed.
const MINOR_PRODUCTS: usize = 400;

/// Products in `K` charged for the classification of a singular pencil at `α` (its rank,
/// kernel and projected-conic computations; about a hundred sign queries of degree ≤ 4).
const SINGULAR_PRODUCTS: usize = 4_000;

/// Bisection steps allowed for isolating the roots (distinct roots of a quartic over `K`).
const MAX_STEPS: usize = 20_000;

type KPoly = Poly<K>;

/// The exact analysis of `λA(α) − B(α)` over `K = ℚ(α)` for a regular pencil.
struct Analysis {
    /// Square-free pieces: (chart, multiplicity, orders in `D₁..D₃`).
    pieces: Vec<(KPoly, usize, [usize; 3])>,
    /// The real finite roots of their product, increasing.
    roots: Vec<Root>,
    /// The product of the pieces (square-free).
    product: KPoly,
    /// For each real finite root: its piece and the inertia of its member.
    real: Vec<(usize, Inertia)>,
    /// A rational sample of each arc between consecutive real roots and the inertia there.
    arcs: Vec<(RBig, Inertia)>,
    /// The multiplicity of the root at `λ = ∞`.
    m_inf: usize,
    /// `D_k` (monic chart) and its multiplicity at ∞, `k = 1, 2, 3` (empty for four simple
    /// roots).
    d: Vec<(KPoly, usize)>,
    /// `E₁…E₄(λ)`, the sums of the principal minors of `λA − B`.
    principal: [KPoly; 4],
}

/// The analysis at `α`; `None` when the pencil at `α` is singular or a single quadric, or
/// the isolation exceeds its budget.
fn analyze(
    entries: &[[TPoly; 4]; 4],
    alpha: &AlgebraicReal,
    spend: Spend<'_>,
) -> Result<Option<Analysis>, Exhausted> {
    spend.products(MINOR_PRODUCTS)?;
    let field = NumberField::new(alpha);
    let e: [[KPoly; 4]; 4] = std::array::from_fn(|i| {
        std::array::from_fn(|j| entries[i][j].map(|c| field.integer_element(c)))
    });
    let a: Vec<K> = e.iter().flatten().map(|p| p.coeff(1)).collect();
    let b: Vec<K> = e.iter().flatten().map(|p| p.coeff(0)).collect();
    if a.iter().all(Ring::is_zero) || b.iter().all(Ring::is_zero) || proportional(&a, &b) {
        return Ok(None);
    }
    // the chart is λA − B with A, −B the coefficients of λ¹, λ⁰
    let (ma, mb): ([[K; 4]; 4], [[K; 4]; 4]) = (
        std::array::from_fn(|i| std::array::from_fn(|j| e[i][j].coeff(1))),
        std::array::from_fn(|i| std::array::from_fn(|j| e[i][j].coeff(0).neg())),
    );
    let minors = SmallMinors::of_pencil(&ma, &mb);
    let f = minors.minor(&[0, 1, 2, 3], &[0, 1, 2, 3]).clone();
    if f.is_zero() {
        return Ok(None);
    }
    let m_inf = 4 - f.degree().unwrap_or(0);
    // Yun over K: at most four gcds of degree ≤ 4
    spend.products(4 * 6 * 5 * 5)?;
    let decomposition = f.squarefree_decomposition_field();
    let simple = m_inf <= 1 && decomposition.iter().all(|(_, m)| *m == 1);

    // D_k over K[λ] (monic chart) and its multiplicity at ∞, k = 1, 2, 3.
    let mut d: Vec<(KPoly, usize)> = Vec::new();
    if !simple {
        for k in 1..=3 {
            let mut g = KPoly::zero();
            let mut mu = k;
            for m in minors.of_order(k) {
                if !m.is_zero() {
                    mu = mu.min(k - m.degree().unwrap_or(0));
                    spend.gcd(g.degree().unwrap_or(0), m.degree().unwrap_or(0))?;
                    g = g.gcd_monic(m);
                }
            }
            d.push((g, mu));
        }
    }

    // Pieces: (square-free chart, multiplicity, orders in D₁..D₃).
    let mut pieces: Vec<(KPoly, usize, [usize; 3])> = Vec::new();
    for (g, m) in decomposition {
        let mut split = vec![(g, [0usize; 3])];
        for (k, (dk, _)) in d.iter().enumerate() {
            let mut next = Vec::new();
            for (p, ords) in split {
                for (h, j) in split_by_order(&p, dk, spend)? {
                    let mut o = ords;
                    o[k] = j;
                    next.push((h, o));
                }
            }
            split = next;
        }
        for (p, o) in split {
            pieces.push((p, m, o));
        }
    }
    let product = pieces
        .iter()
        .fold(KPoly::constant(K::one()), |acc, (p, _, _)| &acc * p);
    let Some(roots) = isolate(&product, spend)? else {
        return Ok(None);
    };
    let mut sturms: Vec<Vec<KPoly>> = Vec::with_capacity(pieces.len());
    for (p, _, _) in &pieces {
        sturms.push(sturm(p, None, spend)?);
    }
    let principal: [KPoly; 4] = minors
        .principal_minor_sums()
        .try_into()
        .expect("four sums of a 4×4 pencil");

    let mut found: Vec<(usize, Option<Inertia>)> = Vec::new(); // (piece, inertia if multiple)
    for root in &roots {
        spend.products(2 * 5 * pieces.len() * 5)?;
        let Some(piece) = (0..pieces.len()).find(|&i| match root {
            Root::Exact(x) => pieces[i].0.eval(&K::rational(x.clone())).is_zero(),
            Root::Open(lo, hi) => variations(&sturms[i], lo) > variations(&sturms[i], hi),
        }) else {
            return Ok(None);
        };
        let inertia = if pieces[piece].1 > 1 {
            let mut signs = [Sign::Zero; 4];
            for (k, q) in principal.iter().enumerate() {
                signs[k] = sign_at_root(&product, q, root, spend)?;
            }
            Some(Inertia::from_minor_sum_signs(signs))
        } else {
            None
        };
        found.push((piece, inertia));
    }
    let Some(samples) = arc_samples(&product, &roots, spend)? else {
        return Ok(None);
    };
    spend.products(4 * 5 * samples.len())?;
    let arcs: Vec<(RBig, Inertia)> = samples
        .into_iter()
        .map(|x| {
            let k = K::rational(x.clone());
            let signs = principal.each_ref().map(|q| q.eval(&k).sign());
            (x, Inertia::from_minor_sum_signs(signs))
        })
        .collect();
    // At a simple root exactly one eigenvalue crosses zero: the smaller count of its arcs.
    let real = found
        .into_iter()
        .enumerate()
        .map(|(i, (piece, inertia))| {
            let (l, h) = (&arcs[i].1, &arcs[i + 1].1);
            let simple = Inertia {
                positive: l.positive.min(h.positive),
                negative: l.negative.min(h.negative),
                zero: 1,
            };
            (piece, inertia.unwrap_or(simple))
        })
        .collect();
    Ok(Some(Analysis {
        pieces,
        roots,
        product,
        real,
        arcs,
        m_inf,
        d,
        principal,
    }))
}

/// A single quadric at `α` (`A(α) ∝ B(α)`, or one of them zero) typed by its inertia, read
/// from the signs of its principal-minor sums in `K`: `E_k(λA − B)` has the sum of the
/// principal `k`-minors of `A` as its `λᵏ` coefficient, of `−B` as its constant. `None` when
/// the pencil at `α` is not a single quadric.
fn single_at_irrational(
    entries: &[[TPoly; 4]; 4],
    alpha: &AlgebraicReal,
) -> Option<Classification> {
    let field = NumberField::new(alpha);
    let e: [[KPoly; 4]; 4] = std::array::from_fn(|i| {
        std::array::from_fn(|j| entries[i][j].map(|c| field.integer_element(c)))
    });
    let a: Vec<K> = e.iter().flatten().map(|p| p.coeff(1)).collect();
    let b: Vec<K> = e.iter().flatten().map(|p| p.coeff(0)).collect();
    let a_zero = a.iter().all(Ring::is_zero);
    if !(a_zero || b.iter().all(Ring::is_zero) || proportional(&a, &b)) {
        return None;
    }
    let (ma, mb): ([[K; 4]; 4], [[K; 4]; 4]) = (
        std::array::from_fn(|i| std::array::from_fn(|j| e[i][j].coeff(1))),
        std::array::from_fn(|i| std::array::from_fn(|j| e[i][j].coeff(0).neg())),
    );
    let principal: [KPoly; 4] = SmallMinors::of_pencil(&ma, &mb)
        .principal_minor_sums()
        .try_into()
        .ok()?;
    let power = |k: usize| if a_zero { 0 } else { k + 1 };
    let signs: [Sign; 4] = std::array::from_fn(|k| principal[k].coeff(power(k)).sign());
    Some(classify_single_inertia(Inertia::from_minor_sum_signs(
        signs,
    )))
}

/// A singular pencil at `α` (`det(λA(α) − B(α)) ≡ 0`, `A(α)`, `B(α)` not proportional),
/// classified over `K`; `None` when the pencil at `α` is not singular. The caller has ruled
/// out a single quadric.
fn singular_at_irrational(
    entries: &[[TPoly; 4]; 4],
    alpha: &AlgebraicReal,
) -> Option<Classification> {
    let field = NumberField::new(alpha);
    let (ma, mb): ([[K; 4]; 4], [[K; 4]; 4]) = (
        std::array::from_fn(|i| {
            std::array::from_fn(|j| field.integer_element(&entries[i][j].coeff(1)))
        }),
        std::array::from_fn(|i| {
            std::array::from_fn(|j| field.integer_element(&entries[i][j].coeff(0)).neg())
        }),
    );
    let det = qsic_algebra::linalg::pencil::pencil_principal_minor_sums(&ma, &mb)[3].clone();
    det.iter()
        .all(Ring::is_zero)
        .then(|| classify_singular_in(&ma, &mb))
}

/// The classification of `λA(α) − B(α)` at `α`: a single quadric, a singular or a regular
/// pencil; `None` only when the root isolation of a regular pencil exceeds its step limit,
/// spending `budget` ([`Spend`]).
///
/// # Errors
/// [`Exhausted`] when the budget runs out.
pub(crate) fn classify_at_irrational(
    entries: &[[TPoly; 4]; 4],
    alpha: &AlgebraicReal,
    budget: &Budget,
) -> Result<Option<Classification>, Exhausted> {
    let spend = Spend::new(budget, alpha);
    spend.products(MINOR_PRODUCTS)?;
    if let Some(single) = single_at_irrational(entries, alpha) {
        return Ok(Some(single));
    }
    let Some(an) = analyze(entries, alpha, spend)? else {
        spend.products(SINGULAR_PRODUCTS)?;
        return Ok(singular_at_irrational(entries, alpha));
    };
    let mut real_blocks: Vec<Vec<u8>> = Vec::new();
    let mut complex_blocks: Vec<Vec<u8>> = Vec::new();
    let mut seq = vec![SigItem::Interval(an.arcs[0].1.positive)];
    for (i, (piece, inertia)) in an.real.iter().enumerate() {
        let (_, m, o) = &an.pieces[*piece];
        real_blocks.push(blocks_from_orders(*m, *o));
        seq.push(SigItem::Root {
            p: inertia.positive,
            n: inertia.negative,
            mult: *m as u8,
        });
        seq.push(SigItem::Interval(an.arcs[i + 1].1.positive));
    }
    for (i, (p, m, o)) in an.pieces.iter().enumerate() {
        let nreal = an.real.iter().filter(|(j, _)| *j == i).count();
        for _ in nreal..p.degree().unwrap_or(0) {
            complex_blocks.push(blocks_from_orders(*m, *o));
        }
    }
    if an.m_inf > 0 {
        let ords = if an.d.is_empty() {
            [0; 3]
        } else {
            [an.d[0].1, an.d[1].1, an.d[2].1]
        };
        real_blocks.push(blocks_from_orders(an.m_inf, ords));
        // the member A(α): the signs of E_k(A) are the λ^k coefficients of E_k(λ)
        let signs: [Sign; 4] = std::array::from_fn(|k| an.principal[k].coeff(k + 1).sign());
        let inertia = Inertia::from_minor_sum_signs(signs);
        seq.push(SigItem::Root {
            p: inertia.positive,
            n: inertia.negative,
            mult: an.m_inf as u8,
        });
        seq.push(SigItem::Interval(4 - an.arcs[0].1.positive));
    }
    let structures = real_blocks
        .iter()
        .map(Vec::as_slice)
        .chain(complex_blocks.iter().map(Vec::as_slice));
    Ok(Some(classify_regular_parts(
        structures,
        real_blocks.len(),
        seq,
    )))
}

/// The signs and inertias along the real λ-line of `λA(α) − B(α)` for a regular pencil
/// with `A(α)` and `B(α)` nonsingular (no root at `0` or `∞`): for each arc between
/// consecutive real roots, the side of `0` of its rational sample and the inertia there;
/// for each real root, its sign and the inertia of its member. `None` as [`analyze`], or
/// when `A(α)` or `B(α)` is singular.
///
/// # Errors
/// [`Exhausted`] when the budget runs out.
pub(crate) fn pencil_signs_at_irrational(
    entries: &[[TPoly; 4]; 4],
    alpha: &AlgebraicReal,
    budget: &Budget,
) -> Result<Option<crate::solids::PencilSigns>, Exhausted> {
    let spend = Spend::new(budget, alpha);
    let Some(an) = analyze(entries, alpha, spend)? else {
        return Ok(None);
    };
    let zero = RBig::ZERO;
    if an.m_inf > 0 || an.product.eval(&K::rational(zero.clone())).is_zero() {
        return Ok(None);
    }
    let seq = sturm(&an.product, None, spend)?;
    spend.products(5 * 5 * (an.roots.len() + 1))?;
    let at_zero = variations(&seq, &zero);
    let roots = an
        .roots
        .iter()
        .zip(&an.real)
        .map(|(root, (_, inertia))| {
            let sign = match root {
                Root::Exact(x) => rational_sign(x),
                // V(lo) − V(0) roots in (lo, 0]: the root is negative iff it is there
                Root::Open(lo, _) if *lo < zero => {
                    if variations(&seq, lo) > at_zero {
                        Sign::Negative
                    } else {
                        Sign::Positive
                    }
                }
                Root::Open(..) => Sign::Positive,
            };
            (sign, *inertia)
        })
        .collect();
    let arcs = an
        .arcs
        .iter()
        .map(|(x, inertia)| (rational_sign(x), *inertia))
        .collect();
    Ok(Some(crate::solids::PencilSigns { arcs, roots }))
}

fn rational_sign(x: &RBig) -> Sign {
    match x.cmp(&RBig::ZERO) {
        std::cmp::Ordering::Less => Sign::Negative,
        std::cmp::Ordering::Equal => Sign::Zero,
        std::cmp::Ordering::Greater => Sign::Positive,
    }
}

impl OrderedDomain for K {
    fn sign_of(&self) -> Sign {
        self.sign()
    }
    /// The variations of the Sturm–Tarski sequence at `−∞` minus at `+∞` (signs of the
    /// leading coefficients).
    fn tarski_query(p: &KPoly, q: &KPoly) -> i64 {
        // charged up front by the caller (SINGULAR_PRODUCTS)
        let unlimited = Budget::unlimited();
        let spend = Spend {
            budget: &unlimited,
            product: 0,
        };
        let seq = sturm(p, Some(q), spend).expect("an unlimited budget is never spent");
        let at = |negative: bool| {
            qsic_algebra::sign::count_variations(seq.iter().map(|s| {
                let lead = s.leading().sign();
                if negative && s.degree().unwrap_or(0) % 2 == 1 {
                    -lead
                } else {
                    lead
                }
            }))
        };
        at(true) as i64 - at(false) as i64
    }
}

/// `a ∝ b` (both nonzero vectors).
fn proportional(a: &[K], b: &[K]) -> bool {
    (0..a.len()).all(|i| (0..a.len()).all(|j| a[i].mul(&b[j]).sub(&a[j].mul(&b[i])).is_zero()))
}

/// Splits the square-free `p` into the parts whose roots have order `j` in `d`.
fn split_by_order(
    p: &KPoly,
    d: &KPoly,
    spend: Spend<'_>,
) -> Result<Vec<(KPoly, usize)>, Exhausted> {
    let mut out = Vec::new();
    let mut rest = p.clone();
    if !d.is_zero() {
        let n = d.degree().unwrap_or(0);
        spend.products(4 * (n + 2) * (n + 1) * (n + 1))?;
        for (dj, j) in d.squarefree_decomposition_field() {
            spend.gcd(rest.degree().unwrap_or(0), dj.degree().unwrap_or(0))?;
            let h = rest.gcd_monic(&dj);
            if h.degree().unwrap_or(0) > 0 {
                rest = rest.div_rem(&h).0;
                out.push((h, j));
            }
        }
    }
    if rest.degree().unwrap_or(0) > 0 {
        out.push((rest, 0));
    }
    Ok(out)
}

/// Jordan block sizes from the orders of a root in `D₁, D₂, D₃` and in `f = D₄`.
fn blocks_from_orders(m: usize, ords: [usize; 3]) -> Vec<u8> {
    let mut e: Vec<u8> = Vec::with_capacity(4);
    let mut prev = 0;
    for v in [ords[0], ords[1], ords[2], m] {
        let x = v.saturating_sub(prev);
        if x > 0 {
            e.push(x as u8);
        }
        prev = v;
    }
    e.sort_unstable_by(|a, b| b.cmp(a));
    e
}

/// The signed remainder sequence of `p` and `p′·q` (`q = 1` without `q`): a Sturm sequence,
/// or the Sturm–Tarski sequence of `q` on the roots of `p`.
fn sturm(p: &KPoly, q: Option<&KPoly>, spend: Spend<'_>) -> Result<Vec<KPoly>, Exhausted> {
    let second = match q {
        Some(q) => {
            spend.products((p.degree().unwrap_or(0) + 1) * (q.degree().unwrap_or(0) + 1))?;
            &p.derivative() * q
        }
        None => p.derivative(),
    };
    let mut seq = vec![p.clone()];
    let mut next = second;
    while !next.is_zero() {
        let last = seq.last().expect("nonempty");
        spend.step(last.degree().unwrap_or(0), next.degree().unwrap_or(0))?;
        let r = last.rem(&next);
        seq.push(next);
        next = -&r;
    }
    Ok(seq)
}

/// The products in `K` of evaluating a sequence at a rational (Horner on each).
fn evaluation_products(seq: &[KPoly]) -> usize {
    seq.iter().map(|p| p.degree().unwrap_or(0) + 1).sum()
}

/// Sign changes of the sequence at a rational `x`.
fn variations(seq: &[KPoly], x: &RBig) -> usize {
    let x = K::rational(x.clone());
    qsic_algebra::sign::count_variations(seq.iter().map(|p| p.eval(&x).sign()))
}

/// A real root of the square-free product: exact, or alone in `(lo, hi)` with neither end a root.
enum Root {
    Exact(RBig),
    Open(RBig, RBig),
}

/// The real roots of the square-free `p ∈ K[λ]`, increasing: bisection of `(−B, B]` with
/// Sturm counts (`V(a) − V(b)` roots in `(a, b]`). `None` past [`MAX_STEPS`].
fn isolate(p: &KPoly, spend: Spend<'_>) -> Result<Option<Vec<Root>>, Exhausted> {
    if p.degree().unwrap_or(0) == 0 {
        return Ok(Some(Vec::new()));
    }
    let seq = sturm(p, None, spend)?;
    spend.products(4 * p.degree().unwrap_or(0) * 64)?;
    let Some(bound) = root_bound(p) else {
        return Ok(None);
    };
    let bound = RBig::from(bound);
    let mut work = vec![(-bound.clone(), bound)];
    let mut out: Vec<Root> = Vec::new();
    let mut steps = 0;
    let per_step = 2 * evaluation_products(&seq) + 2 * (p.degree().unwrap_or(0) + 1);
    while let Some((lo, hi)) = work.pop() {
        steps += 1;
        if steps > MAX_STEPS {
            return Ok(None);
        }
        spend.products(per_step)?;
        let count = variations(&seq, &lo) - variations(&seq, &hi);
        if count == 0 {
            continue;
        }
        let hi_root = p.eval(&K::rational(hi.clone())).is_zero();
        // an open cell must not end at a root (the Sturm–Tarski counts need it): a cell
        // starting at a neighbour's exact root is split further
        let lo_root = !hi_root && p.eval(&K::rational(lo.clone())).is_zero();
        if count == 1 && !lo_root {
            out.push(if hi_root {
                Root::Exact(hi)
            } else {
                Root::Open(lo, hi)
            });
            continue;
        }
        let mid = (&lo + &hi) / RBig::from(2);
        // right half first on the stack so the left pops first? order is fixed by sorting
        work.push((mid.clone(), hi));
        work.push((lo, mid));
    }
    out.sort_by(|a, b| upper(a).cmp(upper(b)));
    Ok(Some(out))
}

fn upper(r: &Root) -> &RBig {
    match r {
        Root::Exact(x) => x,
        Root::Open(_, hi) => hi,
    }
}

/// `2^k` above the absolute value of every root (Cauchy: `1 + max |aᵢ/aₙ|`), by exact signs.
fn root_bound(p: &KPoly) -> Option<IBig> {
    let n = p.degree()?;
    let lead = p.coeff(n).inv()?;
    let mut k = 1usize;
    for i in 0..n {
        let r = p.coeff(i).mul(&lead);
        while k < 100_000 {
            let b = K::rational(RBig::from(IBig::ONE << k));
            if b.sub(&r).sign() == Sign::Positive && b.add(&r).sign() == Sign::Positive {
                break;
            }
            k += 1;
        }
    }
    Some(IBig::ONE << (k + 1))
}

/// The sign of `q` at the root of the square-free `p`.
fn sign_at_root(p: &KPoly, q: &KPoly, root: &Root, spend: Spend<'_>) -> Result<Sign, Exhausted> {
    Ok(match root {
        Root::Exact(x) => q.eval(&K::rational(x.clone())).sign(),
        Root::Open(lo, hi) => {
            let seq = sturm(p, Some(q), spend)?;
            spend.products(2 * evaluation_products(&seq))?;
            let t = variations(&seq, lo) as i64 - variations(&seq, hi) as i64;
            match t {
                0 => Sign::Zero,
                t if t > 0 => Sign::Positive,
                _ => Sign::Negative,
            }
        }
    })
}

/// One rational left of the first root, between each two, right of the last (`0` without).
fn arc_samples(
    p: &KPoly,
    roots: &[Root],
    spend: Spend<'_>,
) -> Result<Option<Vec<RBig>>, Exhausted> {
    let (Some(first), Some(last)) = (roots.first(), roots.last()) else {
        return Ok(Some(vec![RBig::ZERO]));
    };
    let lower = |r: &Root| match r {
        Root::Exact(x) => x.clone(),
        Root::Open(lo, _) => lo.clone(),
    };
    let mut out = vec![lower(first) - RBig::ONE];
    let seq = sturm(p, None, spend)?;
    let per_step = 2 * evaluation_products(&seq);
    for w in roots.windows(2) {
        match (&w[0], &w[1]) {
            // cells are disjoint: the end of an open cell is not a root and the next root
            // lies beyond it
            (Root::Open(_, hi), _) => out.push(hi.clone()),
            (Root::Exact(x), Root::Exact(y)) => out.push((x + y) / RBig::from(2)),
            (Root::Exact(x), Root::Open(lo, hi)) => {
                // the next root is in (lo, hi] and above x: shrink its cell until lo > x
                let (mut lo, mut hi) = (lo.clone(), hi.clone());
                let mut steps = 0;
                while lo <= *x {
                    steps += 1;
                    if steps > MAX_STEPS {
                        return Ok(None);
                    }
                    spend.products(per_step)?;
                    let mid = (&lo + &hi) / RBig::from(2);
                    if variations(&seq, &lo) == variations(&seq, &mid) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                out.push((x + &lo) / RBig::from(2));
            }
        }
    }
    out.push(upper(last) + RBig::ONE);
    Ok(Some(out))
}
