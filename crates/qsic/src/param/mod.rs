//! Levin's parameterization of the intersection curve, exactly (enhanced-Levin paper, §1.3,
//! Appendix A, Theorem 12): nonsingular quartics (cases 1–4) here, curves on a plane pair
//! of the pencil (cases 13–35, singular pencils) in `planar`, the single quadric in `single`.
//!
//! | entry point | what |
//! |---|---|
//! | [`parameterize_smooth_quartic`] | surface `S`, its ruling `b + v·d`, `p(u) = a(u) ± d(u)√s(u)`, the real roots of `s` |
//! | [`LevinParameterization::real_components`] | Theorem 12: the number of real components from the roots of `s` |
//! | [`parameterize`] | the whole curve as exact [`Curve`] components, real pieces and their connection |
//! | `planar::plane_pair_curve` | conics and lines: a member of rank ≤ 2 split into its planes, each cut by another member |
//!
//! The nonsingular quartic's stages have modules of their own: `choose` (the parameterization
//! surface: a real ruled member and its ruling), `smooth` (Levin's forms `s`, `a`, `d`, balanced,
//! and the real pieces), `discriminant` (the real roots of `s` and its signs).
//!
//! With `S` a real ruled member of the pencil parameterized as `q(u, v) = b(u) + v·d(u)`,
//! substituting `q` into a second member `Q` gives `c₂v² + 2c₁v + c₀ = 0`, `c₂ = dᵀQd`,
//! `c₁ = bᵀQd`, `c₀ = bᵀQb`, hence `p(u) = a(u) ± d(u)√s(u)` with `a = c₂b − c₁d` and
//! `s = c₁² − c₀c₂`; identically `aᵀQa + s·dᵀQd = 0` and `aᵀQd = 0` for every member `Q`.
//! `u` runs over ℝ ∪ {∞}: `s` is a binary quartic, its degree drop a root at `u = ∞`.

mod balance;
mod biquadratic;
mod choose;
mod concurrent;
pub mod curve;
mod discriminant;
pub mod expr;
mod infinity;
mod line_cubic;
mod nodal;
mod parts;
mod planar;
pub mod sample;
mod single;
mod smooth;
mod surface;
mod zsqrt;

pub use curve::{
    Arc, Component, ComponentParam, Curve, LevinForm, Number, NumberPoly, ParamRange, ParamValue,
    PlaneSection, Point, PointPoly, RealPiece, Sheet, SingularPoint,
};
pub use line_cubic::{parameterize_line_and_cubic, LineAndCubic, Meeting};
pub use nodal::{parameterize_singular_quartic, SingularQuartic};
pub use smooth::parameterize_smooth_quartic;
pub use surface::{PolyVector, RuledParameterization};

use crate::classify::{
    analyze_pencil, classify_keeping_sums, classify_keeping_sums_within, Classification,
    ComponentKind, PencilKind,
};
use crate::error::Error;
use crate::pencil::{dyadic_between_isolated, PencilAnalysis, PencilData, PencilPoint};
use crate::quadric::Quadric;
use crate::Budget;
use qsic_algebra::field::Quadratic;
use qsic_algebra::roots::{
    isolate_squarefree_real_roots, rational_between, simplest_between, RootInterval,
};
use qsic_algebra::{AlgebraicReal, IBig, Poly, RBig, Sign};
use smooth::{levin_curve, real_components, smooth_quartic};
use surface::{parameterize_cone, parameterize_doubly_ruled_with, poly_form, q, to_quadratic};

/// The kind of a real ruled member of the pencil.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SurfaceKind {
    /// Nonsingular of inertia (2, 2): a hyperboloid of one sheet or a hyperbolic paraboloid.
    DoublyRuled,
    /// Rank 3 and indefinite: a cone or a cylinder (vertex at infinity).
    Cone,
}

/// The parameterization surface: a real ruled member `S` of the pencil and its ruling.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParameterizationSurface {
    /// `S = λA − B` for `Some(λ)`, `S = A` for `None` (λ = ∞), with `A`, `B` the primitive
    /// integer matrices of the quadrics ([`Quadric::integer_matrix`]). Rational in this slice.
    pub lambda: Option<RBig>,
    /// The matrix of `S`.
    pub matrix: [[RBig; 4]; 4],
    /// Doubly ruled or a cone.
    pub kind: SurfaceKind,
    /// `q(u, v) = b(u) + v·d(u)` with `qᵀSq ≡ 0`.
    pub ruling: RuledParameterization,
}

/// The real roots of `s(u)` on ℝ ∪ {∞} and its sign between them.
#[derive(Clone, Debug)]
pub struct DiscriminantRoots {
    /// The distinct finite real roots, increasing. Over ℚ(√δ) each is given as a root of the
    /// square-free part of the norm `s·s̄ ∈ ℚ[u]` with an interval isolating it there.
    pub roots: Vec<AlgebraicReal>,
    /// `u = ∞` is a root (`deg s < 4`).
    pub at_infinity: bool,
    /// `s` has no multiple finite root (`gcd(s, s′) = 1`).
    pub squarefree: bool,
    /// A rational sample of each open interval between consecutive finite roots and the sign
    /// of `s` there: `arcs[0]` left of the first root, `arcs[i]` right of root `i − 1`
    /// (one arc when there is no finite root); unless `u = ∞` is a root, the first and the
    /// last are one arc through ∞. `s ≥ 0` exactly on the closures of the positive arcs:
    /// the `u`-intervals of the real branches.
    pub arcs: Vec<(RBig, Sign)>,
}

/// Which input quadric was substituted into the ruling (the other member spanning the pencil
/// with `S`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Substituted {
    /// `A` (whenever `S = λA − B` with finite λ).
    A,
    /// `B` (when `S = A`).
    B,
}

/// Levin's parameterization `p(u) = a(u) ± d(u)√s(u)` of a nonsingular quartic.
#[derive(Clone, Debug)]
pub struct LevinParameterization {
    /// The parameterization surface.
    pub surface: ParameterizationSurface,
    /// The quadric substituted into `q(u, v)`.
    pub substituted: Substituted,
    /// `a(u) = c₂b − c₁d`.
    pub a: PolyVector,
    /// `d(u)`, the ruling's second generating curve.
    pub d: PolyVector,
    /// `s(u) = c₁² − c₀c₂`, a binary quartic in the chart `t = 1`.
    pub s: Poly<Quadratic>,
    /// The radicand `δ` when the coefficients are in ℚ(√δ), `None` over ℚ.
    pub delta: Option<IBig>,
    /// The real roots of `s` and its signs.
    pub discriminant: DiscriminantRoots,
}

impl LevinParameterization {
    /// The number of real connected components of the (nonsingular) curve by Theorem 12:
    /// four simple real roots of `s` on ℝ ∪ {∞} — two; two — one; none and `s > 0` — two;
    /// `s < 0` everywhere — none.
    ///
    /// # Errors
    /// [`Error::Algebra`] if `s` has a multiple root or an odd number of real roots: the
    /// curve is not a nonsingular quartic (an internal inconsistency for cases 1–4).
    pub fn real_components(&self) -> Result<u8, Error> {
        real_components(self.s.degree().unwrap_or(0), &self.discriminant, || {
            self.s.clone()
        })
    }
}

/// The intersection curve of `a` and `b`: every component exactly, the pieces of its real
/// locus and how they connect.
///
/// # Errors
/// [`Error::Unsupported`] for the classes not implemented yet; the errors of the class's
/// construction (see [`parameterize_smooth_quartic`]).
///
/// # Examples
/// ```
/// use qsic::{io::parse_quadric, param::parameterize};
/// // a sphere and an ellipsoidal cylinder: two closed real pieces, not connected
/// let a = parse_quadric("x^2+y^2+z^2-w^2").unwrap();
/// let b = parse_quadric("2*x^2+4*y^2-w^2").unwrap();
/// let c = parameterize(&a, &b).unwrap();
/// assert_eq!((c.components.len(), c.pieces.len(), c.connected.len()), (1, 2, 2));
/// ```
pub fn parameterize(a: &Quadric, b: &Quadric) -> Result<Curve, Error> {
    let (classification, sums) = classify_keeping_sums(a, b);
    parameterize_classified(classification, sums, a, b)
}

/// [`parameterize`] spending `budget` ([`crate::Budget`]): the classification's units
/// ([`crate::classify::classify_within`]), then [`CURVE_MINORS`] times the units of the
/// pencil's minors for the curve (its minors, conic points, resultants and roots work on
/// numbers of the same size; factoring is bounded on its own), at least [`CURVE_UNITS`].
///
/// # Errors
/// As [`parameterize`], and [`Error::BudgetExceeded`] when the budget runs out first.
pub fn parameterize_within(a: &Quadric, b: &Quadric, budget: &Budget) -> Result<Curve, Error> {
    let (classification, sums) = classify_keeping_sums_within(a, b, budget)?;
    budget.spend(CURVE_UNITS.max(PencilData::units(a, b).saturating_mul(CURVE_MINORS)))?;
    parameterize_classified(classification, sums, a, b)
}

/// The curve's work in units of the pencil's minors ([`parameterize_within`]).
pub const CURVE_MINORS: u64 = 4;

/// The least units of a curve ([`parameterize_within`]): about what one of small integers
/// costs (`param_cost`: ~0.11 M instructions).
pub const CURVE_UNITS: u64 = 100_000;

/// The curve of a classified pair ([`parameterize`]), its rational components balanced
/// ([`balance`]).
fn parameterize_classified(
    classification: Classification,
    sums: Option<[[i128; 5]; 4]>,
    a: &Quadric,
    b: &Quadric,
) -> Result<Curve, Error> {
    let mut curve = curve_of_class(classification, sums, a, b)?;
    balance::balance_curve(&mut curve);
    Ok(curve)
}

/// The curve of a classified pair, by its class's route.
fn curve_of_class(
    classification: Classification,
    sums: Option<[[i128; 5]; 4]>,
    a: &Quadric,
    b: &Quadric,
) -> Result<Curve, Error> {
    match (classification.pencil, classification.case) {
        (PencilKind::Regular, Some(1..=4)) => match smooth_quartic(a, b, true, true, sums.as_ref())
        {
            Ok(quartic) => levin_curve(classification, quartic, a, b),
            // no ruling over one square root at the tried members: a biquadratic one
            Err(Error::Unsupported(why)) => {
                biquadratic::biquadratic_curve(classification, a, b)?.ok_or(Error::Unsupported(why))
            }
            Err(e) => Err(e),
        },
        (PencilKind::Regular, Some(5..=8 | 11)) => {
            nodal::singular_quartic_curve(classification, a, b)
        }
        (PencilKind::Regular, Some(9 | 10 | 12)) => {
            line_cubic::line_and_cubic_curve(classification, a, b)
        }
        (PencilKind::Regular, Some(13..=35)) | (PencilKind::Singular, _) => {
            planar::plane_pair_curve(classification, a, b)
        }
        (PencilKind::Single, _) => Ok(single::single_curve(classification, a)),
        (PencilKind::Regular, Some(case)) => Err(Error::Unsupported(format!(
            "the curve of case {case} (not yet)"
        ))),
        (kind, _) => Err(Error::Unsupported(format!(
            "the curve of a {} pencil (not yet)",
            kind.key()
        ))),
    }
}

/// The primitive integer matrix of `q` (a positive multiple of its matrix), as rationals.
pub(crate) fn integer_matrix(q: &Quadric) -> [[RBig; 4]; 4] {
    let m = q.integer_matrix().entries();
    std::array::from_fn(|i| std::array::from_fn(|j| RBig::from(m[i][j].clone())))
}

/// The member `λA − B` (`A` for `None`).
pub(crate) fn member(
    a: &[[RBig; 4]; 4],
    b: &[[RBig; 4]; 4],
    lambda: Option<&RBig>,
) -> [[RBig; 4]; 4] {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| match lambda {
            Some(l) => l * &a[i][j] - &b[i][j],
            None => a[i][j].clone(),
        })
    })
}

#[cfg(test)]
mod tests {
    use super::choose::*;
    use super::discriminant::*;
    use super::smooth::*;
    use super::surface::parameterize_doubly_ruled;
    use super::*;
    use crate::classify::classify;
    use qsic_algebra::Ring;

    /// Half the bits of `δ` plus the largest numerator or denominator of a coefficient's
    /// parts, over `b` and `d` alike: a larger coefficient anywhere raises it.
    #[test]
    fn ruling_height_counts_the_radicand_and_the_largest_coefficient() {
        let r = |v: i64| RBig::from(v);
        let quad = |a: RBig, b: RBig| Quadratic::new(a, b, IBig::from(15)).unwrap();
        let line = |c0: Quadratic, c1: Quadratic| Poly::new(vec![c0, c1]);
        let one = || quad(r(1), r(0));
        let mut ruling = RuledParameterization {
            b: std::array::from_fn(|_| line(one(), one())),
            d: std::array::from_fn(|_| line(one(), quad(r(3), r(1)))),
            delta: Some(IBig::from(15)),
        };
        // δ = 15: 4 bits, half 2; the largest part 3: 2 bits
        assert_eq!(ruling_height(&ruling), 2 + 2);
        // a radical part 1/1000 in d: the denominator's 10 bits
        ruling.d[2] = line(
            quad(r(1), RBig::from_parts_signed(IBig::ONE, IBig::from(1000))),
            one(),
        );
        assert_eq!(ruling_height(&ruling), 2 + 10);
        // a rational part 2²⁰ in b
        ruling.b[3] = line(quad(r(1 << 20), r(0)), one());
        assert_eq!(ruling_height(&ruling), 2 + 21);
    }

    /// [`levin_pieces`] (ends moved at their last use) equals the pieces made by cloning
    /// every end, for every sign pattern of up to 6 ends (with and without ∞ among them).
    #[test]
    fn levin_pieces_move_the_ends_as_cloning_would_give() {
        let value = |k: usize| ParamValue::Finite(AlgebraicReal::from_rational(RBig::from(k)));
        for count in 0..=6usize {
            for pattern in 0..(1u32 << count) {
                for (everywhere, infinity) in [(Sign::Positive, false), (Sign::Negative, true)] {
                    let after: Vec<Sign> = (0..count)
                        .map(|i| match pattern >> i & 1 {
                            1 => Sign::Positive,
                            _ => Sign::Negative,
                        })
                        .collect();
                    let ends: Vec<ParamValue> = (0..count)
                        .map(|k| match infinity && k + 1 == count {
                            true => ParamValue::Infinity,
                            false => value(k),
                        })
                        .collect();
                    let expected: Vec<String> = (0..count)
                        .filter(|&i| after[i] == Sign::Positive)
                        .map(|i| {
                            let range =
                                ParamRange::Between(ends[i].clone(), ends[(i + 1) % count].clone());
                            let arc = |sheet, reversed| Arc {
                                range: range.clone(),
                                sheet,
                                reversed,
                            };
                            RealPiece::Curve {
                                component: 0,
                                arcs: vec![arc(Sheet::Plus, false), arc(Sheet::Minus, true)],
                                closed: true,
                            }
                        })
                        .map(|p| format!("{p:?}"))
                        .collect();
                    let got: Vec<String> = levin_pieces(ends, &after, everywhere)
                        .iter()
                        .map(|p| format!("{p:?}"))
                        .collect();
                    if count == 0 {
                        let two = everywhere == Sign::Positive;
                        assert_eq!(got.len(), if two { 2 } else { 0 });
                    } else {
                        assert_eq!(got, expected, "{count} ends, pattern {pattern:b}");
                    }
                }
            }
        }
    }

    fn rq(v: i64) -> Quadratic {
        Quadratic::rational(RBig::from(v))
    }

    #[test]
    fn roots_of_s_over_a_quadratic_field_are_those_of_s_not_of_its_conjugate() {
        // s = (u − √2)(u − 1 − √2)(u² + 1): the norm also vanishes at −√2 and 1 − √2
        let r2 = Quadratic::sqrt(&IBig::from(2));
        let lin = |c: Quadratic| Poly::new(vec![c.neg(), rq(1)]);
        let s = &(&lin(r2.clone()) * &lin(rq(1).add(&r2))) * &Poly::new(vec![rq(1), rq(0), rq(1)]);
        let d = discriminant_roots(&s);
        let approx: Vec<f64> = d.roots.iter().map(AlgebraicReal::to_f64).collect();
        assert_eq!(approx.len(), 2, "{approx:?}");
        assert!(
            (approx[0] - 2f64.sqrt()).abs() < 1e-6 && (approx[1] - 1.0 - 2f64.sqrt()).abs() < 1e-6
        );
        let signs: Vec<Sign> = d.arcs.iter().map(|(_, s)| *s).collect();
        assert_eq!(signs, [Sign::Positive, Sign::Negative, Sign::Positive]);
        assert!(!d.at_infinity);
        assert!(d.squarefree);
        // a double root: found by the Sturm chain, flagged
        let double = &(&lin(r2.clone()) * &lin(r2.clone())) * &Poly::new(vec![rq(1), rq(0), rq(1)]);
        let d = discriminant_roots(&double);
        assert!(!d.squarefree && d.roots.len() == 1);
        assert!((d.roots[0].to_f64() - 2f64.sqrt()).abs() < 1e-6);
        // a cubic: the fourth root is u = ∞
        let cubic = &lin(r2.clone()) * &Poly::new(vec![rq(1), rq(0), rq(1)]);
        let d = discriminant_roots(&cubic);
        assert!(d.at_infinity && d.roots.len() == 1);
        // no real root, negative: the sample's sign
        let d = discriminant_roots(&Poly::new(vec![rq(-1), rq(0), rq(0), rq(0), r2.neg()]));
        assert!(d.roots.is_empty() && d.arcs == [(RBig::ZERO, Sign::Negative)]);
    }

    /// A random `s` over ℤ[√δ] (`δ = 0`: over ℤ) of one of the families: small random
    /// coefficients; products of linear factors with roots `2⁻³⁰` apart (near-double roots),
    /// a rational root, or a repeated factor; a root at 0 (simple or double); coefficients of
    /// sizes from 1 to 2¹²⁰ (the certificate may fail: the exact route answers).
    fn random_s(rng: &mut qsic_algebra::testing::SplitMix, family: u64) -> Poly<Quadratic> {
        let delta = [0i64, 2, 3, 5, 7, 13][rng.int(0, 5) as usize];
        let d = IBig::from(delta);
        let zq = |a: IBig, b: IBig| zsqrt::Zq {
            a,
            b: if delta == 0 { IBig::ZERO } else { b },
        };
        let small = |rng: &mut qsic_algebra::testing::SplitMix| IBig::from(rng.int(-20, 20));
        let mul = |x: &[zsqrt::Zq], y: &[zsqrt::Zq]| zsqrt::poly_mul(x, y, &d);
        let z: Vec<zsqrt::Zq> = match family % 5 {
            0 => (0..5).map(|_| zq(small(rng), small(rng))).collect(),
            1 => {
                // (2³⁰u − p − q√δ)(2³⁰u − p − 1 − q√δ)·(quadratic)
                let (p, q) = (IBig::from(rng.int(-1 << 31, 1 << 31)), small(rng));
                let big = IBig::ONE << 30;
                let l1 = [zq(-&p, -&q), zq(big.clone(), IBig::ZERO)];
                let l2 = [zq(-&p - IBig::ONE, -&q), zq(big, IBig::ZERO)];
                let quad: Vec<_> = (0..3).map(|_| zq(small(rng), small(rng))).collect();
                mul(&mul(&l1, &l2), &quad)
            }
            2 => {
                // a rational root m/n, or a squared factor
                let n = IBig::from(rng.int(1, 9));
                let lin = [zq(small(rng), IBig::ZERO), zq(n, IBig::ZERO)];
                let other = if rng.int(0, 1) == 0 {
                    lin.to_vec()
                } else {
                    vec![zq(small(rng), small(rng)), zq(small(rng), small(rng))]
                };
                let quad: Vec<_> = (0..3).map(|_| zq(small(rng), small(rng))).collect();
                mul(&mul(&lin, &other), &quad)
            }
            3 => {
                // a root at 0 of multiplicity 1 or 2
                let k = rng.int(1, 2) as usize;
                (0..5)
                    .map(|i| {
                        if i < k {
                            zq(IBig::ZERO, IBig::ZERO)
                        } else {
                            zq(small(rng), small(rng))
                        }
                    })
                    .collect()
            }
            _ => (0..5)
                .map(|_| {
                    let shift = rng.int(0, 120) as usize;
                    zq(small(rng) << shift, small(rng) << shift)
                })
                .collect(),
        };
        zsqrt::to_poly(&z, &d)
    }

    /// The certified route of [`discriminant_roots`] against the exact isolation (Descartes
    /// on the square-free part of the norm, Sturm for a repeated root): the same roots, the
    /// same square-freeness, and samples strictly between the roots with the exact signs.
    #[test]
    fn discriminant_roots_agree_with_the_exact_isolation() {
        let mut rng = qsic_algebra::testing::SplitMix(77);
        let mut checked = [0usize; 5];
        let mut routes = [0usize; 2];
        let mut fast = [0usize; 2];
        for i in 0..400u64 {
            let s = random_s(&mut rng, i);
            if s.degree().unwrap_or(0) == 0 {
                continue;
            }
            let exact_sign = |x: &RBig| sign(&s.eval(&q(x)));
            let (roots, squarefree) = match s
                .coeffs()
                .iter()
                .map(|c| c.as_rational().cloned())
                .collect::<Option<Vec<RBig>>>()
            {
                Some(c) => {
                    let p = Poly::from_rational(&Poly::new(c)).0;
                    let sf = p.squarefree_part().degree() == p.degree();
                    (AlgebraicReal::real_roots_of(&p), sf)
                }
                None => exact_roots_by_norm(&s, &norm_of(&s), &exact_sign),
            };
            // the norm (in i128 or big integers) is s·s̄ computed over ℚ(√δ)
            let generic: Vec<RBig> = (&s * &s.map(Quadratic::conjugate))
                .coeffs()
                .iter()
                .map(|c| c.as_rational().cloned().expect("a norm is rational"))
                .collect();
            let generic = Poly::from_rational(&Poly::new(generic)).0;
            assert_eq!(norm_of(&s).primitive_part(), generic.primitive_part());
            // which route discriminant_roots takes: the certificate on the norm of s/uᵏ
            let k = s
                .coeffs()
                .iter()
                .take_while(|c| c.sign() == Some(Sign::Zero))
                .count();
            let s1 = s.shift_down(k);
            let p = match s1.coeffs().iter().all(|c| c.as_rational().is_some()) {
                true => Poly::from_rational(&s1.map(|c| c.as_rational().cloned().unwrap())).0,
                false => norm_of(&s1),
            };
            routes[usize::from(AlgebraicReal::certified_real_roots_of(&p).is_some())] += 1;
            // and the certificate on s and s̄ apart (over ℤ[√δ], not over ℚ)
            let delta = s1
                .coeffs()
                .iter()
                .find(|c| c.as_rational().is_none())
                .map(|c| c.radicand().clone());
            if let Some(d) = delta.as_ref().filter(|d| zsqrt::zpoly(&s1, d).is_some()) {
                fast[usize::from(machine_roots(&s1, d).is_some())] += 1;
            }
            let d = discriminant_roots(&s);
            assert_eq!(d.roots, roots, "roots of {s}");
            assert_eq!(d.squarefree, squarefree, "square-free {s}");
            assert_eq!(d.at_infinity, s.degree() < Some(4));
            assert!(d.roots.iter().all(AlgebraicReal::is_valid));
            assert_eq!(d.arcs.len(), d.roots.len() + 1, "{s}");
            for (j, (x, sg)) in d.arcs.iter().enumerate() {
                let at = AlgebraicReal::from_rational(x.clone());
                assert!(j == 0 || d.roots[j - 1] < at, "sample {x} of {s}");
                assert!(j == d.roots.len() || at < d.roots[j], "sample {x} of {s}");
                assert_eq!(*sg, exact_sign(x), "sign at {x} of {s}");
                assert_ne!(*sg, Sign::Zero);
                // short: about the bits that separate the roots (down to 2⁻¹²⁰ here)
                assert!(
                    dashu_int::ops::BitTest::bit_len(x.denominator()) <= 160,
                    "a short sample {x}"
                );
            }
            checked[(i % 5) as usize] += 1;
        }
        assert!(checked.iter().all(|&c| c > 50), "{checked:?}");
        // both routes: the certificate and its failure (double roots, huge ranges)
        assert!(routes[0] > 20 && routes[1] > 100, "{routes:?}");
        assert!(fast[0] > 20 && fast[1] > 100, "{fast:?}");
    }

    /// The pairs of cases 1–4: random ones (entries up to `bound`) and the corpus lines.
    fn smooth_pairs(seed: u64, n: usize, bound: i64) -> Vec<(Quadric, Quadric)> {
        let mut rng = qsic_algebra::testing::SplitMix(seed);
        let mut out = Vec::new();
        let random = |rng: &mut qsic_algebra::testing::SplitMix| {
            let mut m = [[0i64; 4]; 4];
            for i in 0..4 {
                for j in i..4 {
                    m[i][j] = rng.int(-bound, bound);
                    m[j][i] = m[i][j];
                }
            }
            Quadric::from_integers(m).ok()
        };
        while out.len() < n {
            if let (Some(a), Some(b)) = (random(&mut rng), random(&mut rng)) {
                if matches!(classify(&a, &b).case, Some(1..=4)) {
                    out.push((a, b));
                }
            }
        }
        let text = include_str!("../../tests/data/cases.jsonl");
        for line in text.lines() {
            let v: serde_json::Value = serde_json::from_str(line).expect("json");
            let read = |m: &serde_json::Value| -> Option<Quadric> {
                let rows: Vec<Vec<String>> = m
                    .as_array()?
                    .iter()
                    .map(|r| {
                        r.as_array()
                            .map(|r| r.iter().map(|x| x.as_str().unwrap_or("0").into()).collect())
                    })
                    .collect::<Option<_>>()?;
                crate::io::quadric_from_rows(&rows).ok()
            };
            if let (Some(a), Some(b)) = (read(&v["A"]), read(&v["B"])) {
                if matches!(classify(&a, &b).case, Some(1..=4)) {
                    out.push((a, b));
                }
            }
        }
        out
    }

    /// The curves of small random pairs come with integral Levin forms (the ruling reduced,
    /// a negative balancing kept integral by its homogeneous factor): no denominators, and
    /// coefficients far smaller than the 900-bit ones the balancing once made.
    #[test]
    fn levin_forms_of_small_pairs_are_integral_and_small() {
        use dashu_int::ops::BitTest;
        let (mut integral, mut total, mut widest) = (0, 0, 0);
        for (a, b) in smooth_pairs(7, 60, 10) {
            let Ok(curve) = parameterize(&a, &b) else {
                continue;
            };
            let Some(ComponentParam::Levin { a, d, s, .. }) = &curve.components[0].param else {
                continue;
            };
            total += 1;
            let numbers: Vec<&Number> = a
                .iter()
                .chain(d)
                .chain(std::iter::once(s))
                .flat_map(|p| p.coeffs())
                .collect();
            if numbers.iter().all(|c| c.denominator().is_one()) {
                integral += 1;
            }
            for c in &numbers {
                for v in c.numerator() {
                    widest = widest.max(v.bit_len());
                }
            }
        }
        assert!(
            total >= 40 && integral * 10 >= total * 9,
            "{integral}/{total}"
        );
        assert!(widest <= 300, "a {widest}-bit coefficient");
    }

    /// The integral route (forms over ℤ[√δ], conversions without gcds) gives exactly the
    /// parameterization and the curve of the rational route.
    #[test]
    fn integral_levin_equals_the_rational_route() {
        let mut fast_used = 0;
        let mut fixed_used = 0;
        let mut total = 0;
        for (seed, bound) in [(1u64, 10i64), (2, 1000), (3, 3)] {
            for (a, b) in smooth_pairs(seed, 40, bound) {
                // the classification's minor sums on one route, the quick samples' own on
                // the other
                let (classification, sums) = classify_keeping_sums(&a, &b);
                let simple = matches!(classification.case, Some(1..=4));
                let (Ok(q1), Ok(q2)) = (
                    smooth_quartic(&a, &b, true, simple, sums.as_ref()),
                    smooth_quartic(&a, &b, false, simple, None),
                ) else {
                    continue;
                };
                total += 1;
                assert!(matches!(q2.forms, Forms::Rational { .. }));
                fast_used += usize::from(matches!(q1.forms, Forms::Integral(_)));
                // the forms kept in machine integers, converted straight to the output
                fixed_used += usize::from(
                    matches!(&q1.forms, Forms::Integral(f) if f.fixed.is_some() && f.down == 0),
                );
                let (l1, l2) = (q1.clone().into_levin(), q2.clone().into_levin());
                assert_eq!(l1.surface, l2.surface);
                assert_eq!((&l1.a, &l1.d, &l1.s), (&l2.a, &l2.d, &l2.s));
                assert_eq!((&l1.delta, l1.substituted), (&l2.delta, l2.substituted));
                assert_eq!(q1.real_components().ok(), l1.real_components().ok());
                let cls = classify(&a, &b);
                let c1 = levin_curve(cls.clone(), q1, &a, &b).expect("curve");
                let c2 = levin_curve(cls, q2, &a, &b).expect("curve");
                let levin = |c: &Curve| match c.components[0].param.clone() {
                    Some(ComponentParam::Levin {
                        a,
                        d,
                        degree,
                        alternate,
                        s,
                    }) => {
                        let alt = alternate.expect("an alternate form");
                        (a, d, degree, s, alt.a, alt.d, alt.degree)
                    }
                    other => panic!("not a Levin form: {other:?}"),
                };
                assert_eq!(levin(&c1), levin(&c2));
                assert_eq!(c1.pieces.len(), c2.pieces.len());
            }
        }
        assert!(
            total >= 100 && fast_used * 10 >= total * 9 && fixed_used * 2 >= total,
            "{fast_used} integral, {fixed_used} fixed of {total}"
        );
    }

    /// The ruling chosen through small points lies on its member, that member is `λA − B`,
    /// its radicand is the square-free part of the member's determinant and the least among
    /// the primary candidates with a small point (each computed by
    /// [`parameterize_doubly_ruled`]); pairs where no primary candidate has a small point
    /// (they went to `conic::find_point` before) still get a ruling.
    #[test]
    fn small_surface_choice_is_valid_and_least() {
        let on_surface = |s: &ParameterizationSurface| {
            let sm = to_quadratic(&s.matrix);
            let r = &s.ruling;
            assert!(poly_form(&sm, &r.b, &r.b).is_zero());
            assert!(poly_form(&sm, &r.b, &r.d).is_zero());
            assert!(poly_form(&sm, &r.d, &r.d).is_zero());
        };
        let size = |d: &Option<IBig>| d.as_ref().map_or(IBig::ONE, |d| d * d);
        // d·(λA − B) = n·A − d·B in machine integers (λ = n/d)
        let scaled = |m: &[[RBig; 4]; 4], lambda: &Option<RBig>| {
            let den = RBig::from(lambda.as_ref().expect("finite λ").denominator().clone());
            surface::integer_entries(&m.clone().map(|row| row.map(|v| v * &den)))
        };
        let (mut small, mut total, mut hard, mut searched) = (0, 0, 0, 0);
        for (seed, bound) in [(4u64, 10i64), (5, 1000), (6, 2), (7, 30)] {
            for (a, b) in smooth_pairs(seed, 40, bound) {
                let analysis = analyze_pencil(&a, &b).expect("regular");
                let (am, bm) = (integer_matrix(&a), integer_matrix(&b));
                total += 1;
                let chosen = choose_surface(&am, &bm, &analysis)
                    .expect("a surface")
                    .into_surface();
                on_surface(&chosen);
                assert_eq!(chosen.matrix, member(&am, &bm, chosen.lambda.as_ref()));
                let (primary, _) = primary_candidates(&analysis);
                let mut with_point = Vec::new();
                for (lambda, kind) in &primary {
                    if *kind != SurfaceKind::DoublyRuled {
                        continue;
                    }
                    let m = member(&am, &bm, lambda.as_ref());
                    let Some(mi) = scaled(&m, lambda) else {
                        continue;
                    };
                    if surface::small_point_of(&mi).is_some() {
                        let r = parameterize_doubly_ruled(&m)
                            .expect("ruling")
                            .expect("lines");
                        let want = surface::member_radicand(&mi).expect("radicand");
                        assert_eq!(r.delta.clone().unwrap_or(IBig::ONE), want);
                        with_point.push(r.delta);
                    } else {
                        // without the search (the first pass of `choose_surface_full`), a
                        // member without a small point gives nothing; with it, often a ruling
                        let quick = surface::parameterize_doubly_ruled_with(&m, false);
                        assert!(matches!(quick, Ok(None)), "searched without the search");
                        if let Ok(Some(_)) = surface::parameterize_doubly_ruled_with(&m, true) {
                            searched += 1;
                        }
                    }
                }
                let fast = choose_surface_small(&am, &bm, &analysis).expect("no error");
                if with_point.is_empty() {
                    hard += 1;
                    continue;
                }
                if primary.iter().any(|(_, k)| *k == SurfaceKind::Cone) {
                    continue;
                }
                let fast = fast.expect("a small point").into_surface();
                assert_eq!(fast, chosen);
                small += 1;
                let d = chosen.ruling.delta.clone();
                let want = surface::member_radicand(
                    &scaled(&chosen.matrix, &chosen.lambda).expect("small"),
                )
                .expect("radicand");
                assert_eq!(d.clone().unwrap_or(IBig::ONE), want);
                for other in &with_point {
                    assert!(size(&d) <= size(other), "{d:?} vs {other:?}");
                }
            }
        }
        assert!(
            small * 2 >= total && hard > 0 && searched > 0,
            "{small} small, {hard} hard of {total}, {searched} ruled by the search"
        );
        // pairs without a small point on any primary candidate: from more seeds
        let mut seed = 100;
        while hard < 3 && seed < 140 {
            for (a, b) in smooth_pairs(seed, 10, 1000) {
                let analysis = analyze_pencil(&a, &b).expect("regular");
                let (am, bm) = (integer_matrix(&a), integer_matrix(&b));
                let none = primary_candidates(&analysis)
                    .0
                    .iter()
                    .all(|(lambda, kind)| {
                        *kind == SurfaceKind::DoublyRuled
                            && scaled(&member(&am, &bm, lambda.as_ref()), lambda)
                                .is_some_and(|mi| surface::small_point_of(&mi).is_none())
                    });
                if none {
                    hard += 1;
                    let chosen = choose_surface(&am, &bm, &analysis)
                        .expect("a surface")
                        .into_surface();
                    on_surface(&chosen);
                }
            }
            seed += 1;
        }
        assert!(hard >= 3, "{hard} pairs without small points");
    }

    /// The float filter for the sign of `A + B√δ` agrees with the exact sign wherever it
    /// answers, answers for most random points, and never at a zero: `s` built with a
    /// rational root `x₀` (`s = (u − x₀)·t`), and near-cancelling `A ≈ −B√δ` at `x`.
    #[test]
    fn certified_float_signs_of_s_agree_with_exact_signs() {
        let mut rng = qsic_algebra::testing::SplitMix(5);
        let mut answered = 0;
        for trial in 0..400 {
            let delta = IBig::from([2, 3, 5, 7, 1_000_003][trial % 5]);
            let mut z: Vec<zsqrt::Zq> = (0..5)
                .map(|_| zsqrt::Zq {
                    a: IBig::from(rng.int(-1 << 40, 1 << 40)),
                    b: IBig::from(rng.int(-1 << 40, 1 << 40)),
                })
                .collect();
            let x = RBig::from_parts_signed(IBig::from(rng.int(-4096, 4096)), IBig::from(64));
            if trial % 3 == 0 {
                // make x a root: subtract s(x) from the constant term (x·64⁴ integral)
                let den = IBig::from(64).pow(4);
                let scaled = |c: &IBig| c * &den;
                for c in z.iter_mut() {
                    c.a = scaled(&c.a);
                    c.b = scaled(&c.b);
                }
                let value = |f: fn(&zsqrt::Zq) -> &IBig| {
                    let v = z
                        .iter()
                        .rev()
                        .fold(RBig::ZERO, |acc, c| acc * &x + RBig::from(f(c).clone()));
                    v.numerator().clone() // an integer: den·s has integral values at x
                };
                let (va, vb) = (value(|c| &c.a), value(|c| &c.b));
                z[0].a -= va;
                z[0].b -= vb;
            }
            let f = |v: &IBig| v.to_f64().value();
            let a: Vec<f64> = z.iter().map(|c| f(&c.a)).collect();
            let b: Vec<f64> = z.iter().map(|c| f(&c.b)).collect();
            let xf = exact_f64(&x).expect("a short dyadic");
            let exact = zsqrt::sign_at(&z, &x, &delta);
            if let Some(sg) = certified_sign_zsqrt(&a, &b, f(&delta).sqrt(), xf) {
                assert_eq!(sg, exact, "trial {trial}");
                answered += 1;
            }
            if trial % 3 == 0 {
                assert_eq!(exact, Sign::Zero, "trial {trial}: x is a root");
            }
        }
        assert!(answered >= 200, "{answered}");
        // a rational that is not a float is left to the exact path
        assert_eq!(
            exact_f64(&RBig::from_parts_signed(1.into(), 3.into())),
            None
        );
    }

    /// Between −√2 and √3 (wide intervals), and on half-lines: six distinct samples inside
    /// the arc, other than the sample itself.
    #[test]
    fn more_samples_stay_inside_the_arc() {
        let (p2, p3) = (Poly::from_i64s(&[-2, 0, 1]), Poly::from_i64s(&[-3, 0, 1]));
        let lo = (RootInterval::Open(RBig::from(-5), RBig::from(-1)), &p2);
        let hi = (RootInterval::Open(RBig::ONE, RBig::from(2)), &p3);
        let above_lo = |x: &RBig| x >= &RBig::ZERO || x * x < RBig::from(2);
        let below_hi = |x: &RBig| x <= &RBig::ZERO || x * x < RBig::from(3);
        for (l, h) in [(Some(&lo), Some(&hi)), (None, Some(&hi)), (Some(&lo), None)] {
            let xs = more_samples(l.map(|l| (&l.0, l.1)), &RBig::ONE, h.map(|h| (&h.0, h.1)));
            assert_eq!(xs.len(), 6);
            for (i, x) in xs.iter().enumerate() {
                assert!(x != &RBig::ONE && !xs[..i].contains(x));
                assert!(l.is_none() || above_lo(x), "{x}");
                assert!(h.is_none() || below_hi(x), "{x}");
            }
        }
    }
}
