//! The accelerator of module `irrational`: the class of a regular pencil at an irrational
//! instant `t = α` whose characteristic polynomial has exactly one double root — the shape
//! of almost every instant of a motion no one designed (a simple root of the discriminant) —
//! with a few exact signs in `K = ℚ(α)` and no root isolation over `K`.
//!
//! # Mathematics
//! The polynomials in `λ` over `ℤ[t]` — `f = det(λM_A − M_B)`, the principal-minor sums
//! `E₁…E₄` and the `3×3` minors — are formed once per motion ([`PencilPolys`]); at `α` only
//! their coefficients are reduced into `K`. With `f(λ; α)` of degree 4 (`det M_A(α) ≠ 0`,
//! so no root at `λ = ∞`):
//! - the remainder sequence of `f` and `f′` over `K` (every degree decided by the exact zero
//!   test of `K`) gives `g = gcd(f, f′)`; this route takes only `deg g = 1`: `g = λ − λ₀`
//!   with `λ₀ ∈ K`, a root of multiplicity exactly 2, and `f = (λ − λ₀)²·h` with `h`
//!   quadratic, square-free and `h(λ₀) ≠ 0`. (`deg g = 1` also rules out a singular pencil
//!   and a single quadric, whose `f` vanishes or is a fourth power.) `λ₀` is real (its
//!   conjugate would be a second double root), and `h` has two real roots or none by the
//!   sign of its discriminant in `K`;
//! - the Segre block of `λ₀` is `[2]` if some `3×3` minor is nonzero at `λ₀` (rank 3), else
//!   `[(11)]` (rank 2: the order of `λ₀` in `D₃` is 1, in `D₂` and `D₁` it is 0, since the
//!   geometric multiplicity is at most the algebraic one); the roots of `h` are simple. A
//!   symmetric matrix has rank ≤ 2 iff its principal minors of orders 3 and 4 vanish, and a
//!   minor `q` of degree `k` in `λ` at `λ₀ = u/v` (`S₁ = vλ − u`) is `v^k·q(u/v)/v^k` with
//!   `v^k·q(u/v)` an integer polynomial in `t`: rank 2 is four exact zero tests at `α`;
//! - the real roots are ordered, and rational samples of the arcs between them chosen, from
//!   float approximations, then certified by exact signs in `K`: at the samples
//!   `s₀ < … < s_r`, `s − λ₀` and `lc(h)·h(s)` must show the claimed order (with two real
//!   roots `h` changes sign exactly across them; `s − λ₀` across `λ₀`). A pattern that
//!   does not match, or a sample that is a root, hands the instant back to the reference;
//! - the inertia on each arc from the signs of `E_k` at its sample, at `λ₀` from the signs
//!   of `E_k(λ₀)`, at a simple root from its arcs (one eigenvalue crosses zero) — the same
//!   values the reference reads, so the class is the same: [`classify_regular_parts`] of the
//!   same Segre structures and signature sequence.
//!
//! Every sign is exact. First stage: the values at `α` (the coefficients of `f`, `S₁`, `E_k`
//! and the minors, and their combinations above) are enclosed in dyadic intervals by Horner
//! on `α`'s box, at a precision doubled up to a few times the coefficients' size; a sign
//! is read only from an enclosure that excludes zero, `psc₀(α) = 0` is decided exactly,
//! and `E₄(λ₀) = f(λ₀) = 0` by construction. Where no enclosure shows a `3×3` minor nonzero
//! at `λ₀`, the zero tests above decide rank 2 (`E₃(λ₀) = 0` then); where one of `E₁(λ₀)`,
//! `E₂(λ₀)` holds zero, the zero test of `v^k·E_k(u/v)`; a value that is not zero but not
//! yet enclosed away from it takes more bits, and past the cap the same steps run in `K`
//! with its exact zero test. Floats only propose the samples. `None` means "not this shape
//! or not certified": the caller then runs the reference, so an answer is never lost.
//!
//! **Gain** (callgrind, `qsic motion --batch -` on `ellipsoids_rotation`, whose four
//! irrational instants have rank-2 members): 651 M with the enclosures handing rank 2 to
//! `K`, 87 M with the zero tests at `λ₀`; the route as a whole against the reference is held
//! by `fast_route_agrees_with_the_reference`'s corpus.
//!
//! **Work units.** Each enclosure stage spends, before it runs, the refinement of `α`'s
//! interval to its precision and Horner on every coefficient it reads
//! ([`enclosure_units`]); the exact zero tests their gcd's estimate; the stage in `K` the
//! reduction of the coefficients into `K` and its products ([`super::irrational::Spend`]).

use super::instants::{subresultant_within, tpoly_product_units, DeterminantRoute, TPoly};
use super::irrational::Spend;
use super::shared_roots::{refined_within, ZeroTests};
use crate::classify::{classify_regular_parts, Classification};
use crate::pencil::SigItem;
use crate::solids::PencilSigns;
use qsic_algebra::budget::{poly_step_units, product_units, Budget, Exhausted};
use qsic_algebra::field::number_field::{NumberField, NumberFieldElement as K};
use qsic_algebra::matrix::{Inertia, MatrixPencil};
use qsic_algebra::roots::simplest_between;
use qsic_algebra::{AlgebraicReal, IBig, Poly, RBig, Ring, Sign};
use std::sync::{Arc, OnceLock};

type KPoly = Poly<K>;

/// The polynomials in `λ` over `ℤ[t]` the fast route reads, formed once per motion.
#[derive(Clone, Debug)]
pub(crate) struct PencilPolys {
    /// `f = det(λM_A − M_B)`.
    f: TPoly,
    /// `E₁…E₄`, the principal-minor sums of `λM_A − M_B`.
    e: [TPoly; 4],
    /// The nonzero `3×3` minors.
    minors3: Vec<TPoly>,
    /// The subresultant `S₁(f, ∂f/∂λ)`, of degree ≤ 1 in `λ`.
    s1: TPoly,
    /// `psc₀(f, ∂f/∂λ) = Res_λ(f, ∂f/∂λ)`.
    psc0: Poly,
    /// The zero tests at the instants, shared between the roots of one polynomial.
    zero_tests: ZeroTests,
    /// The four principal `3×3` minors (they vanish at `λ₀` iff the member has rank ≤ 2).
    principal3: [TPoly; 4],
    /// `v³·m(u/v)` for each principal `3×3` minor `m`, with `S₁ = v·λ − u`: the minors at
    /// the double root as integer polynomials in `t`, made on first use (their zeros at `α`
    /// are those of the minors at `λ₀`, whatever the orientation, so the oriented copies of
    /// [`Self::oriented`] share them).
    minors3_at_double: Arc<OnceLock<Vec<Poly>>>,
}

impl PencilPolys {
    /// From the minors of the pencil over `ℤ[t]`, the subresultants spending `budget`
    /// ([`subresultant_within`]).
    pub(crate) fn of(
        pencil: &MatrixPencil<Poly>,
        route: DeterminantRoute,
        budget: &Budget,
    ) -> Result<PencilPolys, Exhausted> {
        let f = pencil.det_poly();
        let (s1, psc0) = if f.degree() == Some(4) {
            let df = f.derivative();
            (
                subresultant_within(&f, &df, 1, route, budget)?,
                subresultant_within(&f, &df, 0, route, budget)?.coeff(0),
            )
        } else {
            // never of degree 4 at any t: the fast route does not apply
            (TPoly::zero(), Poly::zero())
        };
        Ok(PencilPolys {
            f,
            e: pencil.principal_minor_sums(),
            minors3: pencil.minors(3),
            principal3: pencil.principal_minors3(),
            s1,
            psc0,
            zero_tests: ZeroTests::default(),
            minors3_at_double: Arc::default(),
        })
    }

    /// The same for the pencil with `M_A` negated (`negate_a`) and/or `M_B` negated: a
    /// `k×k` minor `m(λ)` of `λM_A − M_B` becomes `m(−λ)` for `(−M_A, M_B)`,
    /// `(−1)ᵏm(−λ)` for `(M_A, −M_B)` and `(−1)ᵏm(λ)` for both negated.
    pub(crate) fn oriented(&self, negate_a: bool, negate_b: bool) -> PencilPolys {
        let map = |p: &TPoly, k: usize| -> TPoly {
            let flip_lambda = negate_a != negate_b;
            let flip_all = negate_b && k % 2 == 1;
            Poly::new(
                p.coeffs()
                    .iter()
                    .enumerate()
                    .map(|(i, c)| {
                        if flip_all != (flip_lambda && i % 2 == 1) {
                            c.neg()
                        } else {
                            c.clone()
                        }
                    })
                    .collect(),
            )
        };
        PencilPolys {
            f: map(&self.f, 4),
            e: std::array::from_fn(|k| map(&self.e[k], k + 1)),
            minors3: self.minors3.iter().map(|m| map(m, 3)).collect(),
            // only the root of S₁ and the vanishing of psc₀ are read: S₁(λ) becomes ±S₁(∓λ)
            s1: map(&self.s1, 0),
            psc0: self.psc0.clone(),
            zero_tests: self.zero_tests.clone(),
            principal3: std::array::from_fn(|k| map(&self.principal3[k], 3)),
            minors3_at_double: self.minors3_at_double.clone(),
        }
    }

    /// `v^k·q(u/v)` for a polynomial `q` of degree ≤ `k` in `λ` and `S₁ = v·λ − u`
    /// (`u = −S₁[0]`, `v = S₁[1]`): `q` at the double root as an integer polynomial in `t`,
    /// spending its products.
    fn at_double(&self, q: &TPoly, k: usize, budget: &Budget) -> Result<Poly, Exhausted> {
        at_double_with(q, &self.double_root_monomials(k, budget)?, budget)
    }

    /// The monomials `uⁱ·v^(k−i)`, `i = 0…k`, of [`Self::at_double`], spending their
    /// products (made once where several polynomials are taken at the double root).
    fn double_root_monomials(&self, k: usize, budget: &Budget) -> Result<Vec<Poly>, Exhausted> {
        let (u, v) = self.double_root_fraction();
        let powers = |x: &Poly| -> Result<Vec<Poly>, Exhausted> {
            let mut out = vec![Poly::constant(IBig::ONE), x.clone()];
            while out.len() <= k {
                let last = out.last().expect("two powers at least");
                budget.spend(tpoly_product_units(last, x))?;
                out.push(last * x);
            }
            Ok(out)
        };
        let (pu, pv) = (powers(&u)?, powers(&v)?);
        (0..=k)
            .map(|i| {
                let (a, b) = (&pu[i], &pv[k - i]);
                if i == 0 || i == k {
                    return Ok(if i == 0 { b.clone() } else { a.clone() });
                }
                budget.spend(tpoly_product_units(a, b))?;
                Ok(a * b)
            })
            .collect()
    }

    /// `(u, v)` with `S₁ = v·λ − u`: the double root is `u(α)/v(α)` where there is one.
    pub(super) fn double_root_fraction(&self) -> (Poly, Poly) {
        (self.s1.coeff(0).neg(), self.s1.coeff(1))
    }

    /// Whether `f(λ; α)` has degree 4 and exactly one double root (`psc₀(α) = 0 ≠ S₁[1](α)`:
    /// `λ₀ = u/v` of [`Self::at_double`]), by exact zero tests.
    pub(super) fn one_double_root_at(
        &self,
        alpha: &AlgebraicReal,
        budget: &Budget,
    ) -> Result<bool, Exhausted> {
        Ok(self.f.degree() == Some(4)
            && !self.zero_tests.is_root(alpha, &self.f.coeff(4), budget)?
            && self.zero_tests.is_root(alpha, &self.psc0, budget)?
            && !self.zero_tests.is_root(alpha, &self.s1.coeff(1), budget)?)
    }

    /// Whether the member at the double root `λ₀` has rank 2 at `α`: every principal `3×3`
    /// minor vanishes there ([`MatrixPencil::principal_minors3`]): exact zero tests of
    /// [`Self::at_double`] of each (shared between the roots of one polynomial).
    fn rank_two_at(&self, alpha: &AlgebraicReal, budget: &Budget) -> Result<bool, Exhausted> {
        let values = match self.minors3_at_double.get() {
            Some(v) => v,
            None => {
                // the monomials uⁱv³⁻ⁱ once for the four minors
                let monomials = self.double_root_monomials(3, budget)?;
                let mut made = Vec::with_capacity(4);
                for m in &self.principal3 {
                    made.push(at_double_with(m, &monomials, budget)?);
                }
                self.minors3_at_double.get_or_init(|| made)
            }
        };
        for q in values {
            if !self.zero_tests.is_root(alpha, q, budget)? {
                return Ok(false);
            }
        }
        Ok(true)
    }
}

/// `Σ qᵢ·mᵢ` for the monomials `mᵢ = uⁱ·v^(k−i)` ([`PencilPolys::double_root_monomials`]):
/// `v^k·q(u/v)`, spending its products.
fn at_double_with(q: &TPoly, monomials: &[Poly], budget: &Budget) -> Result<Poly, Exhausted> {
    let mut acc = Poly::zero();
    for (i, mono) in monomials.iter().enumerate() {
        let c = q.coeff(i);
        if !c.is_zero() {
            budget.spend(tpoly_product_units(&c, mono))?;
            acc = &acc + &(&c * mono);
        }
    }
    Ok(acc)
}

/// A real root of `f(λ; α)`: the double root `λ₀`, or a simple root of `h`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum RealRoot {
    Double,
    Simple,
}

/// The certified analysis of the shape of the module docs.
struct DoubleRootAnalysis {
    /// The real roots, increasing, with their inertias.
    roots: Vec<(RealRoot, Inertia)>,
    /// The sign of each real root (in the same order).
    root_signs: Vec<Sign>,
    /// The rational sample of each arc (one more than the roots) and the inertia there.
    arcs: Vec<(RBig, Inertia)>,
    /// The Segre blocks of `λ₀`: `[2]` or `[1, 1]`.
    double_blocks: Vec<u8>,
    /// Whether `h` has real roots (else a complex pair).
    h_real: bool,
}

/// The class at `α` by the fast route; `None` when `f(λ; α)` has not the shape of the
/// module docs or a float guess is not confirmed (the caller runs the reference).
///
/// # Errors
/// [`Exhausted`] when the budget runs out.
pub(crate) fn classify_at_irrational_fast(
    polys: &PencilPolys,
    alpha: &AlgebraicReal,
    budget: &Budget,
) -> Result<Option<Classification>, Exhausted> {
    let Some(an) = analyze(polys, alpha, budget)? else {
        return Ok(None);
    };
    let mut real_blocks: Vec<Vec<u8>> = Vec::new();
    let mut seq = vec![SigItem::Interval(an.arcs[0].1.positive)];
    for (i, (root, inertia)) in an.roots.iter().enumerate() {
        let (blocks, mult) = match root {
            RealRoot::Double => (an.double_blocks.clone(), 2),
            RealRoot::Simple => (vec![1], 1),
        };
        real_blocks.push(blocks);
        seq.push(SigItem::Root {
            p: inertia.positive,
            n: inertia.negative,
            mult,
        });
        seq.push(SigItem::Interval(an.arcs[i + 1].1.positive));
    }
    let complex_blocks: Vec<Vec<u8>> = if an.h_real {
        Vec::new()
    } else {
        vec![vec![1], vec![1]]
    };
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

/// The signs and inertias along the λ-line (as the reference's
/// `pencil_signs_at_irrational`) by the fast route; `None` as
/// [`classify_at_irrational_fast`], or when `M_B(α)` is singular (a root at `λ = 0`).
///
/// # Errors
/// [`Exhausted`] when the budget runs out.
pub(crate) fn pencil_signs_at_irrational_fast(
    polys: &PencilPolys,
    alpha: &AlgebraicReal,
    budget: &Budget,
) -> Result<Option<PencilSigns>, Exhausted> {
    let Some(an) = analyze(polys, alpha, budget)? else {
        return Ok(None);
    };
    if an.root_signs.contains(&Sign::Zero) {
        return Ok(None);
    }
    Ok(Some(PencilSigns {
        arcs: an
            .arcs
            .iter()
            .map(|(x, inertia)| (Sign::of_rational(x), *inertia))
            .collect(),
        roots: an
            .root_signs
            .iter()
            .zip(&an.roots)
            .map(|(s, (_, inertia))| (*s, *inertia))
            .collect(),
    }))
}

/// Every coefficient (a polynomial in `t`) the stages read: `f`, `S₁`, `E₁…E₄`, the `3×3`
/// minors, and `psc₀`.
fn read_coefficients(polys: &PencilPolys) -> impl Iterator<Item = &Poly> {
    let lambda = [&polys.f, &polys.s1]
        .into_iter()
        .chain(&polys.e)
        .chain(&polys.minors3);
    lambda
        .flat_map(|p| p.coeffs())
        .chain(std::iter::once(&polys.psc0))
}

/// The units of one enclosure stage at `prec` bits besides the refinement of `α` (charged
/// as it runs, [`refined_within`]): Horner at `prec` bits on each coefficient read,
/// `deg + 1` products of `prec` by `prec + bits` bits each.
fn enclosure_units(polys: &PencilPolys, prec: usize) -> u64 {
    read_coefficients(polys).fold(0u64, |acc, c| {
        let horner = (c.degree().unwrap_or(0) as u64 + 1)
            .saturating_mul(product_units(prec + c.max_bits(), prec));
        acc.saturating_add(horner)
    })
}

/// The units of an exact zero test `q(α) = 0` (a gcd of `q` with `α`'s polynomial, modulo
/// a prime first: about the product of the sizes).
fn zero_test_units(q: &Poly, alpha: &AlgebraicReal) -> u64 {
    let d = alpha.poly().degree().unwrap_or(0) as u64 + 1;
    poly_step_units(q.degree().unwrap_or(0), q.max_bits()).saturating_mul(d)
}

/// The analysis by enclosures ([`analyze_enclosed`]) where they decide every sign, else by
/// exact arithmetic in `K` ([`analyze_in_field`]).
fn analyze(
    polys: &PencilPolys,
    alpha: &AlgebraicReal,
    budget: &Budget,
) -> Result<Option<DoubleRootAnalysis>, Exhausted> {
    // a value's enclosure narrows like 2^−prec times its coefficients' size: past a few
    // times that size, a sign still undecided is most likely a zero for the exact route
    let size = polys
        .s1
        .coeffs()
        .iter()
        .map(Poly::max_bits)
        .max()
        .unwrap_or(0);
    let cap = MAX_ENCLOSURE_BITS.min(1024 + 4 * size);
    let mut prec = 128;
    let zero_tests = zero_test_units(&polys.psc0, alpha)
        .saturating_add(zero_test_units(&polys.s1.coeff(1), alpha));
    while prec <= cap {
        budget.spend(enclosure_units(polys, prec))?;
        match analyze_enclosed(polys, alpha, prec, budget)? {
            Enclosed::Done(an) => return Ok(Some(an)),
            Enclosed::NotThisShape => return Ok(None),
            Enclosed::Undecided => prec *= 2,
        }
    }
    // the reduction of every coefficient into K (Horner in α: deg_t products each), then
    // the route's few hundred products
    let spend = Spend::new(budget, alpha);
    let reductions: usize = read_coefficients(polys)
        .map(|c| c.degree().unwrap_or(0) + 1)
        .sum();
    spend.products(reductions + 400)?;
    budget.spend(zero_tests)?;
    Ok(analyze_in_field(polys, alpha))
}

fn analyze_in_field(polys: &PencilPolys, alpha: &AlgebraicReal) -> Option<DoubleRootAnalysis> {
    let field = NumberField::new(alpha);
    let into_k = |p: &TPoly| -> KPoly { p.map(|c| field.integer_element(c)) };
    let f = into_k(&polys.f);
    if f.degree() != Some(4) {
        return None;
    }
    // deg gcd(f, f′) = 1 at α ⇔ psc₀(α) = 0 ≠ psc₁(α) (f of degree 4 at α, so the
    // subresultants specialise), and then S₁(α) is the gcd: λ₀ = u/v, kept as a fraction
    // with v > 0 (no inverse in K, whose numerators are large)
    let (mut u, mut v) = (
        field.integer_element(&polys.s1.coeff(0)).neg(),
        field.integer_element(&polys.s1.coeff(1)),
    );
    match v.sign() {
        Sign::Zero => return None,
        Sign::Negative => (u, v) = (u.neg(), v.neg()),
        Sign::Positive => {}
    }
    if !field.integer_element(&polys.psc0).is_zero() {
        return None;
    }
    // the sign at λ₀ of a polynomial of degree ≤ k in λ: that of v^k·q(u/v)
    let sign_at_double = |q: &KPoly, k: usize| -> Sign {
        let mut acc = K::zero();
        let mut v_pow = K::one();
        for i in (0..=k).rev() {
            // Horner in u with the powers of v carried: Σ qᵢ uⁱ v^(k−i)
            acc = acc.mul(&u).add(&q.coeff(i).mul(&v_pow));
            v_pow = v_pow.mul(&v);
        }
        acc.sign()
    };
    // H = v²·h for f = (λ − λ₀)²·h (synthetic division twice, times v²)
    let (a2, a3, a4) = (f.coeff(2), f.coeff(3), f.coeff(4));
    let two = K::from_int(&IBig::from(2));
    let (uu, uv, vv) = (u.mul(&u), u.mul(&v), v.mul(&v));
    let ha = a4.mul(&vv);
    let hb = a3.mul(&vv).add(&two.mul(&a4).mul(&uv));
    let hc = a2
        .mul(&vv)
        .add(&two.mul(&a3).mul(&uv))
        .add(&K::from_int(&IBig::from(3)).mul(&a4).mul(&uu));
    let h = Poly::new(vec![hc.clone(), hb.clone(), ha.clone()]);
    let disc = hb
        .mul(&hb)
        .sub(&ha.mul(&hc).mul(&K::from_int(&IBig::from(4))));
    let h_real = match disc.sign() {
        Sign::Positive => true,
        Sign::Negative => false,
        Sign::Zero => return None, // not square-free: not this shape (gcd said otherwise)
    };

    // The Segre block of λ₀: rank 3 if a 3×3 minor is nonzero there.
    let rank3 = polys
        .minors3
        .iter()
        .any(|m| sign_at_double(&into_k(m), 3) != Sign::Zero);
    let double_blocks = if rank3 { vec![2] } else { vec![1, 1] };

    // The order of the real roots, proposed by floats, then certified.
    // (ratios of rationals first: the values themselves may be far outside f64's range)
    let ratio = |x: &RBig, y: &RBig| -> f64 { (x / y).to_f64().value() };
    let x0 = ratio(&approx(alpha, &u)?, &approx(alpha, &v)?);
    let quadratic = if h_real {
        let fa = approx(alpha, &ha)?;
        Some((approx(alpha, &hb)? / &fa, approx(alpha, &hc)? / &fa))
    } else {
        None
    };
    let approx = proposed_roots(x0, quadratic)?;
    let samples = arc_samples(&approx)?;
    // certify: λ₀ lies in the claimed cell, and lc(h)·h changes sign exactly across the
    // claimed simple roots
    let lead_sign = ha.sign();
    let to_k = |x: &RBig| K::rational(x.clone());
    let mut at_double = 0;
    let mut simple_cells = Vec::new();
    for (i, (_, kind)) in approx.iter().enumerate() {
        match kind {
            RealRoot::Double => at_double = i,
            RealRoot::Simple => simple_cells.push(i),
        }
    }
    for (i, s) in samples.iter().enumerate() {
        let sk = to_k(s);
        // sign(s − λ₀) = sign(v·s − u), v > 0
        let side = v.mul(&sk).sub(&u).sign();
        let expected = if i <= at_double {
            Sign::Negative
        } else {
            Sign::Positive
        };
        if side != expected {
            return None;
        }
        if h_real {
            let hs = h.eval(&sk).sign() * lead_sign;
            // positive outside the two roots, negative between them
            let inside = simple_cells[0] < i && i <= simple_cells[1];
            if hs
                != if inside {
                    Sign::Negative
                } else {
                    Sign::Positive
                }
            {
                return None;
            }
        }
    }

    let e: [KPoly; 4] = std::array::from_fn(|k| into_k(&polys.e[k]));
    let inertia_at = |x: &K| Inertia::from_minor_sum_signs(e.each_ref().map(|q| q.eval(x).sign()));
    let arcs: Vec<(RBig, Inertia)> = samples
        .into_iter()
        .map(|s| {
            let inertia = inertia_at(&to_k(&s));
            (s, inertia)
        })
        .collect();
    let roots = approx
        .iter()
        .enumerate()
        .map(|(i, (_, kind))| {
            let inertia = match kind {
                RealRoot::Double => Inertia::from_minor_sum_signs::<4>(std::array::from_fn(|k| {
                    sign_at_double(&e[k], k + 1)
                })),
                RealRoot::Simple => {
                    let (l, r) = (&arcs[i].1, &arcs[i + 1].1);
                    Inertia {
                        positive: l.positive.min(r.positive),
                        negative: l.negative.min(r.negative),
                        zero: 1,
                    }
                }
            };
            (*kind, inertia)
        })
        .collect();
    // the signs of the roots: λ₀ directly; those of h from h(0) and the sum of the roots
    let mut root_signs = Vec::with_capacity(approx.len());
    let h0 = hc.sign() * lead_sign; // sign of the product of the roots of h
    let sum = hb.neg().sign() * lead_sign; // sign of their sum
    let mut simple_seen = 0;
    for (_, kind) in &approx {
        root_signs.push(match kind {
            RealRoot::Double => u.sign(),
            RealRoot::Simple => {
                simple_seen += 1;
                match h0 {
                    Sign::Zero => Sign::Zero,
                    Sign::Negative if simple_seen == 1 => Sign::Negative,
                    Sign::Negative => Sign::Positive,
                    Sign::Positive => sum,
                }
            }
        });
    }
    Some(DoubleRootAnalysis {
        roots,
        root_signs,
        arcs,
        double_blocks,
        h_real,
    })
}

/// Precision past which the enclosures give up for exact arithmetic in `K`.
const MAX_ENCLOSURE_BITS: usize = 1 << 16;

/// The outcome of [`analyze_enclosed`].
enum Enclosed {
    Done(DoubleRootAnalysis),
    /// `psc₀(α) ≠ 0` or `psc₁(α) = 0`, decided exactly: not one double root.
    NotThisShape,
    /// An enclosure holds zero: more bits, or the exact route.
    Undecided,
}

/// A dyadic interval `[lo, hi]·2^−prec`.
#[derive(Clone, Debug)]
struct Dyadic {
    lo: IBig,
    hi: IBig,
    prec: usize,
}

impl Dyadic {
    fn int(v: &IBig, prec: usize) -> Dyadic {
        Dyadic {
            lo: v << prec,
            hi: v << prec,
            prec,
        }
    }
    fn add(&self, o: &Dyadic) -> Dyadic {
        Dyadic {
            lo: &self.lo + &o.lo,
            hi: &self.hi + &o.hi,
            prec: self.prec,
        }
    }
    fn neg(&self) -> Dyadic {
        Dyadic {
            lo: -self.hi.clone(),
            hi: -self.lo.clone(),
            prec: self.prec,
        }
    }
    fn sub(&self, o: &Dyadic) -> Dyadic {
        self.add(&o.neg())
    }
    /// The product, its ends rounded outward to `prec` bits.
    fn mul(&self, o: &Dyadic) -> Dyadic {
        let p = [
            &self.lo * &o.lo,
            &self.lo * &o.hi,
            &self.hi * &o.lo,
            &self.hi * &o.hi,
        ];
        let min = p.iter().min().expect("four products").clone();
        let max = p.iter().max().expect("four products").clone();
        Dyadic {
            lo: min >> self.prec,
            hi: -((-max) >> self.prec),
            prec: self.prec,
        }
    }
    /// The sign of every value in the interval, if it has one.
    fn sign(&self) -> Option<Sign> {
        if self.lo > IBig::ZERO {
            Some(Sign::Positive)
        } else if self.hi < IBig::ZERO {
            Some(Sign::Negative)
        } else {
            None
        }
    }
    fn mid(&self) -> RBig {
        RBig::from_parts_signed(&self.lo + &self.hi, IBig::ONE << (self.prec + 1))
    }
}

/// `p(α)` enclosed, by Horner on `α`'s box.
fn enclose(p: &Poly, a: &Dyadic) -> Dyadic {
    let mut acc = Dyadic::int(&IBig::ZERO, a.prec);
    for c in p.coeffs().iter().rev() {
        acc = acc.mul(a).add(&Dyadic::int(c, a.prec));
    }
    acc
}

/// `Σ qᵢ xⁱ y^(k−i)` enclosed, for enclosures `q` of the coefficients.
fn enclose_homogeneous(q: &[Dyadic], k: usize, x: &Dyadic, y: &Dyadic) -> Dyadic {
    let prec = x.prec;
    let zero = Dyadic::int(&IBig::ZERO, prec);
    let mut acc = zero.clone();
    let mut y_pow = Dyadic::int(&IBig::ONE, prec);
    for i in (0..=k).rev() {
        acc = acc.mul(x).add(&q.get(i).unwrap_or(&zero).mul(&y_pow));
        y_pow = y_pow.mul(y);
    }
    acc
}

/// The analysis of [`analyze_in_field`] with every sign read from dyadic enclosures of the
/// values at `α` at `prec` bits (a sign is taken only where the enclosure excludes zero,
/// so every sign is exact), and `psc₀(α) = 0` decided exactly: no arithmetic in `K`.
fn analyze_enclosed(
    polys: &PencilPolys,
    alpha: &AlgebraicReal,
    prec: usize,
    budget: &Budget,
) -> Result<Enclosed, Exhausted> {
    use Enclosed::{NotThisShape, Undecided};
    if polys.f.degree() != Some(4) {
        return Ok(NotThisShape);
    }
    let iv = refined_within(alpha, prec, budget)?;
    let scale = RBig::from(IBig::ONE << prec);
    let a = Dyadic {
        lo: (iv.lo() * &scale).floor(),
        hi: (iv.hi() * &scale).ceil(),
        prec,
    };
    let at = |p: &Poly| enclose(p, &a);
    let f: Vec<Dyadic> = polys.f.coeffs().iter().map(at).collect();
    let (mut u, mut v) = (at(&polys.s1.coeff(0)).neg(), at(&polys.s1.coeff(1)));
    match v.sign() {
        None if polys
            .zero_tests
            .is_root(alpha, &polys.s1.coeff(1), budget)? =>
        {
            return Ok(NotThisShape)
        }
        None => return Ok(Undecided),
        Some(Sign::Negative) => (u, v) = (u.neg(), v.neg()),
        Some(_) => {}
    }
    if f[4].sign().is_none() {
        return Ok(Undecided);
    }
    if !polys.zero_tests.is_root(alpha, &polys.psc0, budget)? {
        return Ok(NotThisShape);
    }
    let int = |k: i64| Dyadic::int(&IBig::from(k), prec);
    let (uu, uv, vv) = (u.mul(&u), u.mul(&v), v.mul(&v));
    let ha = f[4].mul(&vv);
    let hb = f[3].mul(&vv).add(&int(2).mul(&f[4]).mul(&uv));
    let hc = f[2]
        .mul(&vv)
        .add(&int(2).mul(&f[3]).mul(&uv))
        .add(&int(3).mul(&f[4]).mul(&uu));
    let disc = hb.mul(&hb).sub(&int(4).mul(&ha).mul(&hc));
    let (Some(lead_sign), Some(disc_sign)) = (ha.sign(), disc.sign()) else {
        return Ok(Undecided);
    };
    let h_real = disc_sign == Sign::Positive;
    // the Segre block of λ₀: [2] where an enclosure shows a 3×3 minor nonzero there, [(11)]
    // where every minor vanishes exactly (rank 2), else more bits
    let rank3 = polys.minors3.iter().any(|m| {
        let q: Vec<Dyadic> = m.coeffs().iter().map(at).collect();
        enclose_homogeneous(&q, 3, &u, &v).sign().is_some()
    });
    let double_blocks = if rank3 {
        vec![2]
    } else if polys.rank_two_at(alpha, budget)? {
        vec![1, 1]
    } else {
        return Ok(Undecided);
    };
    let ratio = |x: &Dyadic, y: &Dyadic| -> f64 { (x.mid() / y.mid()).to_f64().value() };
    let quadratic = h_real.then(|| (hb.mid() / ha.mid(), hc.mid() / ha.mid()));
    let Some(approx) = proposed_roots(ratio(&u, &v), quadratic) else {
        return Ok(Undecided);
    };
    let Some(samples) = arc_samples(&approx) else {
        return Ok(Undecided);
    };
    let at_double = approx
        .iter()
        .position(|(_, k)| *k == RealRoot::Double)
        .expect("λ₀ is among the roots");
    let simple_cells: Vec<usize> = (0..approx.len())
        .filter(|&i| approx[i].1 == RealRoot::Simple)
        .collect();
    let e: Vec<Vec<Dyadic>> = polys
        .e
        .iter()
        .map(|q| q.coeffs().iter().map(at).collect())
        .collect();
    let mut arcs = Vec::with_capacity(samples.len());
    for (i, s) in samples.into_iter().enumerate() {
        // s = n/d, d > 0: the signs of d^k·q(s)
        let n = Dyadic::int(s.numerator(), prec);
        let d = Dyadic::int(&IBig::from(s.denominator().clone()), prec);
        let side = v.mul(&n).sub(&u.mul(&d)).sign();
        let expected = if i <= at_double {
            Sign::Negative
        } else {
            Sign::Positive
        };
        if side != Some(expected) {
            return Ok(Undecided);
        }
        if h_real {
            let hs = enclose_homogeneous(&[hc.clone(), hb.clone(), ha.clone()], 2, &n, &d);
            let inside = simple_cells[0] < i && i <= simple_cells[1];
            let want = if inside {
                Sign::Negative
            } else {
                Sign::Positive
            };
            if hs.sign().map(|x| x * lead_sign) != Some(want) {
                return Ok(Undecided);
            }
        }
        let mut signs = [Sign::Zero; 4];
        for k in 0..4 {
            match enclose_homogeneous(&e[k], k + 1, &n, &d).sign() {
                Some(x) => signs[k] = x,
                None => return Ok(Undecided),
            }
        }
        arcs.push((s, Inertia::from_minor_sum_signs(signs)));
    }
    // E₄(λ₀) = f(λ₀) = 0; E₃(λ₀) ≠ 0 at rank 3 and 0 at rank 2 (every 3×3 minor vanishes);
    // E₁, E₂ as the enclosures say, or zero by an exact test where they hold zero
    let mut double_signs = [Sign::Zero; 4];
    for k in 0..3 {
        if k == 2 && !rank3 {
            continue;
        }
        match enclose_homogeneous(&e[k], k + 1, &u, &v).sign() {
            Some(x) => double_signs[k] = x,
            None => {
                let q = polys.at_double(&polys.e[k], k + 1, budget)?;
                if !polys.zero_tests.is_root(alpha, &q, budget)? {
                    return Ok(Undecided);
                }
            }
        }
    }
    let roots = approx
        .iter()
        .enumerate()
        .map(|(i, (_, kind))| {
            let inertia = match kind {
                RealRoot::Double => Inertia::from_minor_sum_signs(double_signs),
                RealRoot::Simple => {
                    let (l, r) = (&arcs[i].1, &arcs[i + 1].1);
                    Inertia {
                        positive: l.positive.min(r.positive),
                        negative: l.negative.min(r.negative),
                        zero: 1,
                    }
                }
            };
            (*kind, inertia)
        })
        .collect();
    // root signs (the contact route): zero only where the enclosure cannot tell, which
    // makes that route hand the instant back
    let or_zero = |x: &Dyadic| x.sign().unwrap_or(Sign::Zero);
    let h0 = or_zero(&hc) * lead_sign;
    let sum = -or_zero(&hb) * lead_sign;
    let mut simple_seen = 0;
    let root_signs = approx
        .iter()
        .map(|(_, kind)| match kind {
            RealRoot::Double => or_zero(&u),
            RealRoot::Simple => {
                simple_seen += 1;
                match h0 {
                    Sign::Zero => Sign::Zero,
                    Sign::Negative if simple_seen == 1 => Sign::Negative,
                    Sign::Negative => Sign::Positive,
                    Sign::Positive => sum,
                }
            }
        })
        .collect();
    Ok(Enclosed::Done(DoubleRootAnalysis {
        roots,
        root_signs,
        arcs,
        double_blocks,
        h_real,
    }))
}

/// A rational near the value of `x = C(α)/d` at `α`: `C` at a dyadic point near `α` by
/// Horner in fixed point, with more bits than `C`'s coefficients so that the cancellation
/// in `C(α)` leaves about a hundred bits (it only proposes; the caller certifies).
fn approx(alpha: &AlgebraicReal, x: &K) -> Option<RBig> {
    let num = x.numerator_poly();
    let den = RBig::from(x.denominator().clone());
    if num.degree().unwrap_or(0) == 0 {
        return Some(RBig::from(num.coeff(0)) / den);
    }
    // the value at a dyadic point within 2^−bits of α, bits above the coefficients' size
    // (an error of about |C′(α)|·2^−bits)
    let bits = 128 + num.max_bits();
    let width = RBig::from_parts(IBig::ONE, dashu_int::UBig::ONE << bits);
    let iv = alpha.refined_interval(&width);
    let point: IBig = ((iv.lo() + iv.hi()) * RBig::from(IBig::ONE << (bits - 1))).floor();
    // Horner in fixed point: acc·2^bits, truncated after each product (proposals only)
    let mut acc = IBig::ZERO;
    for c in num.coeffs().iter().rev() {
        acc = ((acc * &point) >> bits) + (c << bits);
    }
    Some(RBig::from_parts_signed(acc, IBig::ONE << bits) / den)
}

/// Rational samples for the arcs of the approximate roots `approx` (increasing): one below
/// the first, one simple rational in the middle half of each gap, one above the last.
/// `None` if two approximations coincide.
fn arc_samples(approx: &[(f64, RealRoot)]) -> Option<Vec<RBig>> {
    let exact = |x: f64| RBig::try_from(x).ok();
    let first = approx.first()?.0;
    let last = approx.last()?.0;
    let mut out = vec![RBig::from(exact(first)?.floor() - IBig::ONE)];
    for w in approx.windows(2) {
        let (lo, hi) = (w[0].0, w[1].0);
        if lo.partial_cmp(&hi) != Some(std::cmp::Ordering::Less) {
            return None;
        }
        let q = (hi - lo) / 4.0;
        let (a, b) = (exact(lo + q)?, exact(hi - q)?);
        if a >= b {
            return None;
        }
        out.push(simplest_between(&a, &b, true, true));
    }
    out.push(RBig::from(exact(last)?.ceil() + IBig::ONE));
    Some(out)
}

/// The proposed real roots of `f(λ; α)`, sorted: the double root `x0` and, when
/// `quadratic` gives the cofactor `λ² + bλ + c` with real roots, its two simple roots
/// (`q = −(b + sign(b)·√d)/2`, `q` and `c/q`: no cancellation); `None` if one is not
/// finite. Floats only propose: every sign is certified afterwards.
fn proposed_roots(x0: f64, quadratic: Option<(RBig, RBig)>) -> Option<Vec<(f64, RealRoot)>> {
    let mut roots: Vec<(f64, RealRoot)> = vec![(x0, RealRoot::Double)];
    if let Some((b, c)) = quadratic {
        let d = (&b * &b - RBig::from(4) * &c).to_f64().value();
        let (b, c) = (b.to_f64().value(), c.to_f64().value());
        let q = -0.5 * (b + b.signum() * d.max(0.0).sqrt());
        roots.push((q, RealRoot::Simple));
        roots.push((c / q, RealRoot::Simple));
    }
    if roots.iter().any(|(x, _)| !x.is_finite()) {
        return None;
    }
    roots.sort_by(|x, y| x.0.total_cmp(&y.0));
    Some(roots)
}

#[cfg(test)]
mod tests {
    use super::super::{irrational, MovingPencil};
    use super::*;
    use crate::io::{moving_matrix_from_polynomial, moving_matrix_from_rows};
    use qsic_algebra::testing::SplitMix;

    fn pencil(a: &str, b: &str) -> MovingPencil {
        MovingPencil::new(
            moving_matrix_from_polynomial(a).unwrap(),
            moving_matrix_from_polynomial(b).unwrap(),
        )
        .unwrap()
    }

    /// A random symmetric matrix `M₀ + t·M₁` with entries in `−r..=r`, `M₁` with `k` nonzero
    /// entries (and their mirror images).
    fn random_moving(rng: &mut SplitMix, r: i64, k: usize) -> Vec<Vec<String>> {
        let mut m0 = [[0i64; 4]; 4];
        let mut m1 = [[0i64; 4]; 4];
        for i in 0..4 {
            for j in i..4 {
                m0[i][j] = rng.int(-r, r);
                m0[j][i] = m0[i][j];
            }
        }
        for _ in 0..k {
            let (i, j) = (rng.int(0, 3) as usize, rng.int(0, 3) as usize);
            m1[i][j] = rng.int(-r, r);
            m1[j][i] = m1[i][j];
        }
        (0..4)
            .map(|i| {
                (0..4)
                    .map(|j| format!("{} + ({})*t", m0[i][j], m1[i][j]))
                    .collect()
            })
            .collect()
    }

    /// Every irrational candidate instant of `p`: the fast route, where it answers, gives the
    /// reference's class; returns how many it answered and how many there were.
    fn compare(p: &MovingPencil, what: &str) -> (usize, usize) {
        let (mut answered, mut all) = (0, 0);
        for alpha in p.candidate_instants().unwrap() {
            if alpha.as_rational().is_some() {
                continue;
            }
            all += 1;
            let unlimited = Budget::unlimited();
            if let Some(fast) =
                classify_at_irrational_fast(p.fast_polys(&unlimited).unwrap(), &alpha, &unlimited)
                    .unwrap()
            {
                let reference =
                    irrational::classify_at_irrational(&p.entries, &alpha, &unlimited).unwrap();
                assert_eq!(Some(fast), reference, "{what} at {alpha}");
                answered += 1;
            }
        }
        (answered, all)
    }

    /// The fast route equals the reference at every irrational instant of the moving corpus
    /// and of random moving pencils (fixed seed), and answers at most of them: at the simple
    /// roots of the discriminant of a generic motion.
    #[test]
    fn fast_route_agrees_with_the_reference() {
        for (id, a, b) in crate::motion::moving_corpus() {
            compare(&MovingPencil::new(a, b).unwrap(), &id);
        }
        let mut rng = SplitMix(28);
        let (mut answered, mut all) = (0, 0);
        for n in 0..6 {
            let (a, b) = (random_moving(&mut rng, 3, 2), random_moving(&mut rng, 3, 1));
            let p = MovingPencil::new(
                moving_matrix_from_rows(&a).unwrap(),
                moving_matrix_from_rows(&b).unwrap(),
            )
            .unwrap();
            let (x, y) = compare(&p, &format!("random pencil {n}: {a:?}, {b:?}"));
            answered += x;
            all += y;
        }
        assert!(all >= 6 && answered * 4 >= all * 3, "{answered} of {all}");
    }

    /// Instants of known shape: an ellipsoid translated past a sphere off its axes, where
    /// `f` is square-free over `ℚ(t)`: every irrational instant is a simple root of the
    /// discriminant, a double root of `f` with a Jordan block — Segre `[211]` — and the fast
    /// route answers at each, with the reference's class.
    #[test]
    fn fast_route_answers_at_tangencies() {
        let p = pencil(
            "x^2 + 2*y^2 + 3*z^2 - 5",
            "(x - t)^2 + (y - 1/2)^2 + (z - 1/3)^2 - 1",
        );
        let (answered, all) = compare(&p, "ellipsoid past a sphere");
        assert!(all >= 2 && answered == all, "{answered} of {all}");
        for alpha in p.candidate_instants().unwrap() {
            if alpha.as_rational().is_none() {
                let c = classify_at_irrational_fast(
                    p.fast_polys(&Budget::unlimited()).unwrap(),
                    &alpha,
                    &Budget::unlimited(),
                )
                .unwrap()
                .unwrap();
                let segre = c.segre.unwrap_or_default();
                assert!(segre.starts_with("[211]"), "{segre} at {alpha}");
            }
        }
    }

    /// Instants where the double root's member has rank 2 (Segre `[(11)11]`): an ellipsoid
    /// turned about the z axis by Cayley's rotation past a sphere (the rotation family of
    /// the benchmarks). The fast route answers at each irrational instant, by exact zero
    /// tests of the principal minors at `λ₀` (no arithmetic in `ℚ(α)`), with the reference's
    /// class.
    #[test]
    fn fast_route_answers_at_rank_two_instants() {
        let rows = |r: [[&str; 4]; 4]| -> Vec<Vec<String>> {
            r.iter()
                .map(|row| row.iter().map(|e| e.to_string()).collect())
                .collect()
        };
        let a = rows([
            ["t^4 + 14*t^2 + 1", "6*t^3 - 6*t", "0", "0"],
            ["6*t^3 - 6*t", "4*t^4 - 4*t^2 + 4", "0", "0"],
            ["0", "0", "4*t^4 + 8*t^2 + 4", "0"],
            ["0", "0", "0", "-4*t^4 - 8*t^2 - 4"],
        ]);
        let b = rows([
            ["4", "0", "0", "-12"],
            ["0", "4", "0", "-16"],
            ["0", "0", "9", "0"],
            ["-12", "-16", "0", "64"],
        ]);
        let p = MovingPencil::new(
            moving_matrix_from_rows(&a).unwrap(),
            moving_matrix_from_rows(&b).unwrap(),
        )
        .unwrap();
        let (answered, all) = compare(&p, "ellipsoid turning past a sphere");
        assert!(all >= 4 && answered == all, "{answered} of {all}");
        let unlimited = Budget::unlimited();
        let mut rank_two = 0;
        for alpha in p.candidate_instants().unwrap() {
            if alpha.as_rational().is_none() {
                let c = classify_at_irrational_fast(
                    p.fast_polys(&unlimited).unwrap(),
                    &alpha,
                    &unlimited,
                )
                .unwrap()
                .unwrap();
                rank_two += usize::from(c.segre.unwrap_or_default().starts_with("[(11)11]"));
                // decided by the enclosures and zero tests, not by the field route
                let polys = p.fast_polys(&unlimited).unwrap();
                let enclosed = analyze_enclosed(polys, &alpha, 512, &unlimited).unwrap();
                assert!(matches!(enclosed, Enclosed::Done(_)), "at {alpha}");
            }
        }
        assert!(rank_two >= 4, "{rank_two} instants of Segre [(11)11]");
    }

    /// The signs along the λ-line agree with the reference's for ellipsoids (the contact
    /// route), in every orientation of the pair.
    #[test]
    fn fast_pencil_signs_agree_with_the_reference() {
        let motions = [
            ("x^2 + y^2 + z^2 - 2", "(x - t)^2 + y^2 + z^2 - 1"),
            (
                "x^2 + 2*y^2 + 3*z^2 - 5",
                "(x - t)^2 + (y - t^2)^2 + z^2 - 1",
            ),
        ];
        let mut answered = 0;
        for (a, b) in motions {
            let p = pencil(a, b);
            for alpha in p.candidate_instants().unwrap() {
                if alpha.as_rational().is_some() {
                    continue;
                }
                for (na, nb) in [(false, false), (true, false), (false, true), (true, true)] {
                    let polys = p.fast_polys(&Budget::unlimited()).unwrap().oriented(na, nb);
                    let unlimited = Budget::unlimited();
                    let Some(fast) =
                        pencil_signs_at_irrational_fast(&polys, &alpha, &unlimited).unwrap()
                    else {
                        continue;
                    };
                    let sign = |m: &[[Poly; 4]; 4], neg: bool| -> [[Poly; 4]; 4] {
                        let k = Poly::constant(if neg { -IBig::ONE } else { IBig::ONE });
                        m.clone().map(|row| row.map(|e| e.mul(&k)))
                    };
                    let (ma, mb) = p.numerators();
                    let entries =
                        super::super::instants::pencil_entries(&sign(ma, na), &sign(mb, nb));
                    let reference =
                        irrational::pencil_signs_at_irrational(&entries, &alpha, &unlimited)
                            .unwrap()
                            .expect("the reference answers where the fast route does");
                    assert_eq!(
                        crate::solids::relation_from_signs(&fast),
                        crate::solids::relation_from_signs(&reference),
                        "{a}, {b} at {alpha}, orientation {na} {nb}"
                    );
                    assert_eq!(fast.roots.len(), reference.roots.len());
                    for (x, y) in fast.roots.iter().zip(&reference.roots) {
                        assert_eq!(x, y, "{a}, {b} at {alpha}");
                    }
                    answered += 1;
                }
            }
        }
        assert!(answered >= 8, "{answered}");
    }
}
