//! Evaluation of a parameterization at a parameter `(U₀, U₁)` of ℙ¹, certified.
//!
//! The homogenized `X` is evaluated at `t = U₀/U₁` when `|t| ≤ 1`, else with the reversed
//! coefficients at `1/t`, so Horner's rule ([`super::kernels::horner`]) always runs on
//! `[−1, 1]`. Levin's form `a ± d√s` is homogeneous of degree `D = max(deg a, deg d + 2)`,
//! `s` a quartic form clamped at 0 (which moves a point off the curve by `O(|s|)` only:
//! `aᵀMd ≡ 0` cancels the first-order error of `√s`).
//!
//! # Bound
//! Horner's rounding error is at most `γ·Σₖ|cₖ||t|ᵏ` per coordinate (Higham, §5.1). An
//! evaluation is accepted when that bound, for `x` and `d·√s`, is at most `10⁻¹⁰·‖X‖`; `√s`
//! counts with its own error, `min(√e, e/√ŝ)` for `s` computed within `e`
//! ([`Evaluator::root_bound`]), large where `s` is a small difference of large terms. The
//! bound is majorized first once per parameterization (`Σ|x| + Σ|d|·√(Σ|s|)`, [`sure_bounds`]),
//! then by `|c₀| + |t|·Σₖ₌₁|cₖ|`, and computed only where neither certifies.
//!
//! # Dispatch
//! [`Evaluator::eval_unit`] is the one dispatch point of a point's evaluation: the float
//! route, certified by the bound; where it fails (a sheet passing through the zero vector, a
//! removable zero of Levin's form) the double-double route ([`super::kernels::dd`],
//! [`Evaluator::eval_dd`]) with its own bound; where that fails, `None` (the caller moves to
//! a nearby parameter). Both routes return the same unit vector type. Arc ends, the roots of
//! `s`, come from [`Evaluator::root_of_s`]: safeguarded Newton ([`super::kernels::newton`])
//! on `s` in double-double inside the root's isolating interval, else
//! [`qsic_algebra::AlgebraicReal::to_f64`].

use crate::error::Error;
use crate::param::curve::{ComponentParam, Number, NumberPoly, Sheet};
use crate::param::sample::chart::{dot, unit};
use crate::param::sample::convert::Converter;
use crate::param::sample::kernels::dd::{horner_dd, split, to_dd, Dd, Dd4};
use crate::param::sample::kernels::horner::{horner_lanes, horner_lanes_abs, horner_scalar};
use crate::param::sample::kernels::newton::newton_bracketed;
use crate::param::sample::kernels::trig::{grid_parameters, reduced_parameter, sin_cos, RESYNC};
use crate::param::sample::kernels::Lanes;
use crate::param::sample::FLOAT_SCALE;

/// `2⁻⁸⁰⁰` and `2^FLOAT_SCALE`: a parameterization whose floats are all zero or within these
/// in magnitude needs no scaling ([`in_float_range`] leaves it as it is: its estimates are at
/// least `log₂|c|`, and above it by a few bits unless the terms of `c` cancel).
pub(super) const NARROW: (f64, f64) = (
    f64::from_bits((1023 - 800) << 52),
    f64::from_bits((1023 + FLOAT_SCALE as u64) << 52),
);

/// Horner's rounding of `s` (five terms, the coefficients rounded once), per unit of
/// `Σₖ|sₖ||t|ᵏ`: `γ₈ < 9ε`, with a margin.
pub(super) const GAMMA_S: f64 = 16.0 * f64::EPSILON;

/// The same in double-double arithmetic (the coefficients rounded to about `2⁻¹⁰⁵`).
pub(super) const GAMMA_S_DD: f64 = 32.0 / (1u128 << 104) as f64;

/// Most coefficients of one coordinate: homogeneous degree at most 8 (a quartic has 4).
pub(super) const MAX_TERMS: usize = 9;

/// The coefficients in double-double, laid out as in [`Evaluator`].
#[derive(Clone)]
pub(super) struct DdCoeffs {
    pub(super) x: [[Dd; 4]; MAX_TERMS],
    pub(super) d: [[Dd; 4]; MAX_TERMS],
    pub(super) s: [Dd; 5],
}

impl Default for DdCoeffs {
    fn default() -> Self {
        DdCoeffs {
            x: [[Dd::default(); 4]; MAX_TERMS],
            d: [[Dd::default(); 4]; MAX_TERMS],
            s: [Dd::default(); 5],
        }
    }
}

/// Homogeneous float coefficients of a parameterization (increasing powers of `u`, padded
/// to the homogeneous degree `D`), one [`Lanes`] per power, and the sums of their absolute
/// values: `Σₖ|cₖ|` bounds the Horner bound `Σₖ|cₖ||t|ᵏ` on `[−1, 1]`, so that one
/// comparison certifies most evaluations and the exact bound is computed only where it
/// fails.
pub(super) struct Evaluator<'a> {
    /// `(x, d, s)` in Horner's order for `rev` (index `rev as usize`): from the highest
    /// power down for `rev` false (`|t| ≤ 1`), in increasing powers for `rev` true
    /// ([`Evaluator::x`], [`Evaluator::d`], [`Evaluator::s`]) — one indexed load a point in
    /// [`Evaluator::parts`].
    pub(super) horner: [HornerSet; 2],
    /// Levin's form (else rational).
    pub(super) levin: bool,
    /// For the Horner order of `rev` (index `rev as usize`): the largest `|c₀ᵢ|` (the
    /// constant term in `t`) and `Σₖ₌₁|cₖᵢ|` over `i`, of `x` and of `d`: the majorant
    /// `|c₀| + |t|·Σₖ₌₁|cₖ|` of the bound `Σₖ|cₖ||t|ᵏ`, tighter than `Σₖ|cₖ|` near `t = 0`.
    pub(super) split_abs: [(f64, f64, f64, f64); 2],
    /// The largest `Σₖ|xₖᵢ|` and `Σₖ|dₖᵢ|` over the coordinates `i`.
    pub(super) x_abs_max: f64,
    pub(super) d_abs_max: f64,
    /// Relative rounding of one evaluation, per unit of the bound.
    pub(super) gamma: f64,
    /// A bound of every computed `√s` on `[−1, 1]` (`√(Σ|sₖ|)` with a margin), and the
    /// norm at or above which an evaluation with `√s` within it is certified whatever `t`:
    /// `γ·(Σ|x| + Σ|d|·√s) ≤ 10⁻¹⁰·‖X‖` ([`Evaluator::sure`]); infinite where the
    /// coefficients are too large for the shortcut.
    pub(super) sure_root: f64,
    pub(super) sure_norm: f64,
    /// Every coefficient is zero or within [`NARROW`] in magnitude.
    pub(super) narrow: bool,
    /// The double-double coefficients made with the floats, when all came cheaply.
    pub(super) quick_dd: Option<Box<DdCoeffs>>,
    /// The double-double coefficients for the retry of an ill-conditioned evaluation when
    /// `quick_dd` is missing, computed on the first retry.
    pub(super) dd: std::cell::OnceCell<Box<DdCoeffs>>,
    /// The parameterization (for `dd`).
    pub(super) param: &'a ComponentParam,
    /// The homogeneous degree `D`.
    pub(super) big_d: usize,
}

/// The coefficients of one Horner order ([`Evaluator::horner`]), and the absolute values
/// of `x` and `d` (for the rounding bound, [`Evaluator::bound_of`]).
#[derive(Clone, Copy)]
pub(super) struct HornerSet {
    pub(super) x: [Lanes; MAX_TERMS],
    pub(super) d: [Lanes; MAX_TERMS],
    pub(super) s: [f64; 5],
    /// `|s|` in the same order, for `s`'s rounding bound ([`Evaluator::root_bound`]).
    pub(super) s_abs: [f64; 5],
    pub(super) x_abs: [Lanes; MAX_TERMS],
    pub(super) d_abs: [Lanes; MAX_TERMS],
}

/// `|√s − √ŝ|` for an `s` within `e` of the computed `ŝ` (`root = √max(ŝ, 0)`):
/// `min(√e, e/root)`; zero for `e = 0`.
#[inline(always)]
pub(super) fn root_error(e: f64, root: f64) -> f64 {
    if e == 0.0 {
        0.0
    } else if root * root > e {
        e / root
    } else {
        e.sqrt()
    }
}

/// The bounds of [`Evaluator::sure`]: `R = √(Σ|sₖ|·(1 + 2⁻³⁰))` bounds the computed `√s` at
/// any `|t| ≤ 1` (Horner's rounding is below `2⁻⁴⁰` relative to `Σ|sₖ||t|ᵏ` for five
/// terms), and `K = 10¹⁰·γ·(Σ|x| + Σ|d|·R)·(1 + 2⁻³⁰)`. Both infinite (nothing certified
/// this way) unless `K` is positive and the sum is below `10³⁰⁰`: the values are then finite.
pub(super) fn sure_bounds(gamma: f64, x_abs_max: f64, d_abs_max: f64, s: &[f64; 5]) -> (f64, f64) {
    let margin = 1.0 + 2f64.powi(-30);
    // the computed root and its rounding ([`Evaluator::root_bound`]) within twice the largest
    let root = 2.0 * (s.iter().map(|v| v.abs()).sum::<f64>() * margin).sqrt();
    let size = x_abs_max + d_abs_max * root;
    let norm = 1e10 * gamma * size * margin;
    if size.is_finite() && size < 1e300 && norm > 0.0 && norm.is_finite() {
        (root, norm)
    } else {
        (f64::INFINITY, f64::INFINITY)
    }
}

impl<'a> Evaluator<'a> {
    pub(super) fn new(param: &'a ComponentParam) -> Result<Evaluator<'a>, Error> {
        let deg = |p: &NumberPoly| p.degree().unwrap_or(0);
        let (a, d, s, big_d, levin) = match param {
            ComponentParam::Point(_) => {
                return Err(Error::Algebra(
                    "a curve piece with a point parameterization".into(),
                ))
            }
            ComponentParam::Rational { x, .. } => {
                let big_d = x.iter().map(deg).max().unwrap_or(0);
                (x, None, None, big_d, false)
            }
            ComponentParam::Levin {
                a, d, s, degree, ..
            } => {
                if s.degree().is_some_and(|k| k > 4) {
                    return Err(Error::Algebra(format!("s(u) = {s} is not a quartic form")));
                }
                let big_d = a
                    .iter()
                    .map(deg)
                    .max()
                    .unwrap_or(0)
                    .max(d.iter().map(deg).max().unwrap_or(0) + 2)
                    .max(*degree);
                (a, Some(d), Some(s), big_d, true)
            }
        };
        if big_d >= MAX_TERMS {
            return Err(Error::Algebra(format!(
                "a parameterization of degree {big_d} (at most {} sampled)",
                MAX_TERMS - 1
            )));
        }
        let mut conv = Converter::default();
        let mut dd = Box::<DdCoeffs>::default();
        let mut all_dd = true;
        let mut narrow = true;
        let mut put = |c: &Number, f: &mut f64, g: &mut Dd| -> Result<(), Error> {
            let v = conv.convert(c)?;
            *f = v.value;
            let size = v.value.abs();
            narrow &= size == 0.0 || (NARROW.0..=NARROW.1).contains(&size);
            match v.dd {
                Some(x) => *g = x,
                None => all_dd = false,
            }
            Ok(())
        };
        let mut x = [[0.0; 4]; MAX_TERMS];
        let mut dv = [[0.0; 4]; MAX_TERMS];
        let mut sv = [0.0; 5];
        for i in 0..4 {
            for (k, c) in a[i].coeffs().iter().enumerate() {
                put(c, &mut x[k][i], &mut dd.x[k][i])?;
            }
            if let Some(d) = d {
                for (k, c) in d[i].coeffs().iter().enumerate() {
                    put(c, &mut dv[k][i], &mut dd.d[k][i])?;
                }
            }
        }
        if let Some(s) = s {
            for (k, c) in s.coeffs().iter().enumerate() {
                put(c, &mut sv[k], &mut dd.s[k])?;
            }
        }
        let abs_sum = |c: &[Lanes]| -> f64 {
            (0..4)
                .map(|i| c.iter().map(|k| k[i].abs()).sum::<f64>())
                .fold(0.0, f64::max)
        };
        let n = big_d + 1;
        let mut x_desc = [[0.0; 4]; MAX_TERMS];
        let mut d_desc = [[0.0; 4]; MAX_TERMS];
        for k in 0..n {
            x_desc[k] = x[n - 1 - k];
        }
        if levin {
            for k in 0..n - 2 {
                d_desc[k] = dv[n - 3 - k];
            }
        }
        let mut s_desc = sv;
        s_desc.reverse();
        // the constant term and the others' sums, in increasing powers of `t` (`rev` false)
        // and decreasing (`rev` true: the constant term is the last coefficient)
        let split = |c: &[Lanes], constant: usize| -> (f64, f64) {
            let c0 = c
                .get(constant)
                .map_or(0.0, |k| k.iter().fold(0.0, |m, v| v.abs().max(m)));
            let rest = (0..4)
                .map(|i| {
                    (c.iter().enumerate())
                        .filter(|(k, _)| *k != constant)
                        .map(|(_, k)| k[i].abs())
                        .sum::<f64>()
                })
                .fold(0.0, f64::max);
            (c0, rest)
        };
        let nd = if levin { n - 2 } else { 0 };
        let gamma = if levin {
            8.0 * (big_d as f64 + 4.0) * f64::EPSILON
        } else {
            4.0 * (big_d as f64 + 3.0) * f64::EPSILON
        };
        let (x_abs_max, d_abs_max) = (abs_sum(&x), abs_sum(&dv));
        let (sure_root, sure_norm) = sure_bounds(gamma, x_abs_max, d_abs_max, &sv);
        let split_abs = [(0, 0), (n - 1, nd.saturating_sub(1))].map(|(cx, cd)| {
            let (x0, x1) = split(&x[..n], cx);
            let (d0, d1) = split(&dv[..nd], cd);
            (x0, x1, d0, d1)
        });
        let abs = |c: &[Lanes; MAX_TERMS]| c.map(|k| k.map(f64::abs));
        let horner = [
            HornerSet {
                x: x_desc,
                d: d_desc,
                s: s_desc,
                s_abs: s_desc.map(f64::abs),
                x_abs: abs(&x_desc),
                d_abs: abs(&d_desc),
            },
            HornerSet {
                x,
                d: dv,
                s: sv,
                s_abs: sv.map(f64::abs),
                x_abs: abs(&x),
                d_abs: abs(&dv),
            },
        ];
        Ok(Evaluator {
            horner,
            split_abs,
            x_abs_max,
            d_abs_max,
            sure_root,
            sure_norm,
            levin,
            gamma,
            narrow,
            quick_dd: all_dd.then_some(dd),
            dd: std::cell::OnceCell::new(),
            param,
            big_d,
        })
    }

    /// `X` (rational) or `a` (Levin) in increasing powers, `D + 1` used.
    pub(super) fn x(&self) -> &[Lanes; MAX_TERMS] {
        &self.horner[1].x
    }

    /// `d` (Levin) in increasing powers, `D − 1` used.
    pub(super) fn d(&self) -> &[Lanes; MAX_TERMS] {
        &self.horner[1].d
    }

    /// `s` (Levin) in increasing powers.
    pub(super) fn s(&self) -> &[f64; 5] {
        &self.horner[1].s
    }

    /// The unit vector of `X(U₀, U₁)` on `sheet` (up to sign), `None` where rounding could
    /// exceed `10⁻¹⁰·‖X‖` even in double-double.
    pub(super) fn eval_unit(&self, u: (f64, f64), sheet: Sheet) -> Option<[f64; 4]> {
        let (t, rev) = reduced_parameter(u);
        // the usual degrees with their sizes known at compile time (unrolled Horner)
        match (self.levin, self.big_d) {
            (true, 2) => self.eval_unit_of::<3, 1>(t, rev, sheet),
            (true, 3) => self.eval_unit_of::<4, 2>(t, rev, sheet),
            (true, 4) => self.eval_unit_of::<5, 3>(t, rev, sheet),
            (false, 1) => self.eval_unit_of::<2, 0>(t, rev, sheet),
            (false, 2) => self.eval_unit_of::<3, 0>(t, rev, sheet),
            (false, 3) => self.eval_unit_of::<4, 0>(t, rev, sheet),
            (false, 4) => self.eval_unit_of::<5, 0>(t, rev, sheet),
            _ => {
                let (x, root) = self.values_any(t, rev, sheet);
                let norm = dot(&x, &x).sqrt();
                if self.cheaply_certified(t, rev, root, norm) {
                    return Some(x.map(|v| v / norm));
                }
                self.certify(t, rev, sheet, x, norm, root)
            }
        }
    }

    /// [`Evaluator::eval_unit`] for `NA` and `ND` coefficients.
    #[inline(always)]
    pub(super) fn eval_unit_of<const NA: usize, const ND: usize>(
        &self,
        t: f64,
        rev: bool,
        sheet: Sheet,
    ) -> Option<[f64; 4]> {
        let (x, root) = self.values::<NA, ND>(t, rev, sheet);
        self.unit_of::<NA, ND>(x, root, t, rev, sheet)
    }

    /// Whether the bounds made once ([`Evaluator::sure`]) or the majorant at `|t|`
    /// ([`Evaluator::majorant`]) certify an evaluation with `√s = root` and norm `norm`.
    #[inline(always)]
    pub(super) fn cheaply_certified(&self, t: f64, rev: bool, root: f64, norm: f64) -> bool {
        let root = self.root_bound(t, rev, root);
        self.sure(root, norm)
            || norm.is_finite()
                && norm > 0.0
                && self.gamma * self.majorant(t, rev, root) <= 1e-10 * norm
    }

    /// The computed `√s = root` at `t` plus its rounding in units of `γ`: `s` is within
    /// `e = GAMMA_S·Σₖ|sₖ||t|ᵏ` of the computed value, so `√s` within `min(√e, e/root)`
    /// (`|√x − √y| ≤ √|x − y|` and `≤ |x − y|/(√x + √y)`). The bounds take this in place of
    /// `root`: the error of `d·√s` is at most `|d|·(root + that)` in units of `γ`. Zero
    /// added for a rational parameterization (`s = 0`).
    #[inline(always)]
    pub(super) fn root_bound(&self, t: f64, rev: bool, root: f64) -> f64 {
        root + root_error(GAMMA_S * self.s_size(t, rev), root) / self.gamma
    }

    /// `Σₖ|sₖ||t|ᵏ` in the Horner order of `rev`: the unit of `s`'s rounding.
    #[inline(always)]
    pub(super) fn s_size(&self, t: f64, rev: bool) -> f64 {
        let sa = &self.horner[usize::from(rev)].s_abs;
        let at = t.abs();
        sa[1..].iter().fold(sa[0], |acc, c| acc * at + c)
    }

    /// The unit vector of the value `x` (with `√s = root`) at the reduced parameter `t`,
    /// certified: the majorant `Σ|cₖ|` first, the bound at `|t|` ([`Evaluator::bound_of`],
    /// the same value as [`Evaluator::certify`]'s) where it does not certify.
    #[inline(always)]
    pub(super) fn unit_of<const NA: usize, const ND: usize>(
        &self,
        x: Lanes,
        root: f64,
        t: f64,
        rev: bool,
        sheet: Sheet,
    ) -> Option<[f64; 4]> {
        let norm = dot(&x, &x).sqrt();
        if self.cheaply_certified(t, rev, root, norm) {
            return Some(x.map(|v| v / norm));
        }
        self.certify_of::<NA, ND>(t, rev, sheet, x, norm, root)
    }

    /// [`Evaluator::certify`] with the unrolled bound of `NA` and `ND` coefficients.
    #[inline(always)]
    pub(super) fn certify_of<const NA: usize, const ND: usize>(
        &self,
        t: f64,
        rev: bool,
        sheet: Sheet,
        x: Lanes,
        norm: f64,
        root: f64,
    ) -> Option<[f64; 4]> {
        let bound = self.bound_of::<NA, ND>(t, rev, self.root_bound(t, rev, root));
        if self.bound_certifies(bound, norm) {
            return Some(x.map(|v| v / norm));
        }
        self.certify_dd(bound, t, rev, sheet)
    }

    /// Whether the rounding bound `bound` at `|t|` certifies an evaluation of norm `norm`:
    /// `γ·bound ≤ 10⁻¹⁰·‖X‖` (false for NaN).
    #[inline(always)]
    pub(super) fn bound_certifies(&self, bound: f64, norm: f64) -> bool {
        norm.is_finite() && norm > 0.0 && self.gamma * bound <= 1e-10 * norm
    }

    /// [`Evaluator::eval_unit`] on the uniform grid `θₖ = t₀ + k·step`, `k = 1, …, n − 1`,
    /// written to `out` (cleared first); `[NaN; 4]` where it gives `None`. `(sin θ, cos θ)` by
    /// rotations of the step, exact every [`RESYNC`] points: the drift stays within a few
    /// hundred ulps.
    pub(super) fn grid(&self, t0: f64, step: f64, n: usize, sheet: Sheet, out: &mut Vec<[f64; 4]>) {
        match (self.levin, self.big_d) {
            (true, 2) => self.grid_of::<3, 1>(t0, step, n, sheet, out),
            (true, 3) => self.grid_of::<4, 2>(t0, step, n, sheet, out),
            (true, 4) => self.grid_of::<5, 3>(t0, step, n, sheet, out),
            (false, 1) => self.grid_of::<2, 0>(t0, step, n, sheet, out),
            (false, 2) => self.grid_of::<3, 0>(t0, step, n, sheet, out),
            (false, 3) => self.grid_of::<4, 0>(t0, step, n, sheet, out),
            (false, 4) => self.grid_of::<5, 0>(t0, step, n, sheet, out),
            _ => {
                out.clear();
                out.extend((1..n).map(|k| {
                    let u = sin_cos(t0 + step * (k as f64));
                    self.eval_unit(u, sheet).unwrap_or([f64::NAN; 4])
                }));
            }
        }
    }

    /// [`Evaluator::grid`] on both sheets of Levin's form at once (`a`, `d` and `√s`
    /// evaluated once a point): `plus` and `minus`.
    pub(super) fn grid_both(
        &self,
        t0: f64,
        step: f64,
        n: usize,
        plus: &mut Vec<[f64; 4]>,
        minus: &mut Vec<[f64; 4]>,
    ) {
        match self.big_d {
            2 => self.grid_both_of::<3, 1>(t0, step, n, plus, minus),
            3 => self.grid_both_of::<4, 2>(t0, step, n, plus, minus),
            4 => self.grid_both_of::<5, 3>(t0, step, n, plus, minus),
            _ => {
                self.grid(t0, step, n, Sheet::Plus, plus);
                self.grid(t0, step, n, Sheet::Minus, minus);
            }
        }
    }

    /// [`Evaluator::grid_both`] for `NA` and `ND` coefficients.
    #[inline(never)]
    pub(super) fn grid_both_of<const NA: usize, const ND: usize>(
        &self,
        t0: f64,
        step: f64,
        n: usize,
        plus: &mut Vec<[f64; 4]>,
        minus: &mut Vec<[f64; 4]>,
    ) {
        plus.clear();
        plus.resize(n.saturating_sub(1), [0.0; 4]);
        minus.clear();
        minus.resize(n.saturating_sub(1), [0.0; 4]);
        // the parameters of `grid_parameters`: a chunk of `RESYNC` from each exact one
        let (sh, ch) = sin_cos(step);
        let chunks = plus.chunks_mut(RESYNC).zip(minus.chunks_mut(RESYNC));
        for (c, (pc, mc)) in chunks.enumerate() {
            let mut u = sin_cos(t0 + step * ((c * RESYNC + 1) as f64));
            for (pu, mu) in pc.iter_mut().zip(mc.iter_mut()) {
                let (t, rev) = reduced_parameter(u);
                u = (u.0 * ch + u.1 * sh, u.1 * ch - u.0 * sh);
                let (a, w, root) = self.parts::<NA, ND>(t, rev);
                // the same operations as `values` on either sheet
                let (mut p, mut m) = (a, a);
                for i in 0..4 {
                    p[i] += root * w[i];
                    m[i] += -root * w[i];
                }
                let (np, nm) = (dot(&p, &p).sqrt(), dot(&m, &m).sqrt());
                let root = self.root_bound(t, rev, root);
                if self.sure(root, np) && nm >= self.sure_norm {
                    *pu = p.map(|v| v / np);
                    *mu = m.map(|v| v / nm);
                    continue;
                }
                // `unit_of` on either sheet, the bound at `|t|` shared where it is needed
                let lhs = self.gamma * self.majorant(t, rev, root);
                let ok = |norm: f64| {
                    self.sure(root, norm) || norm.is_finite() && norm > 0.0 && lhs <= 1e-10 * norm
                };
                let (p_ok, m_ok) = (ok(np), ok(nm));
                (*pu, *mu) = if p_ok && m_ok {
                    (p.map(|v| v / np), m.map(|v| v / nm))
                } else {
                    self.certify_both::<NA, ND>(t, rev, root, (p, np, p_ok), (m, nm, m_ok))
                };
            }
        }
    }

    /// [`Evaluator::grid`] for `NA` and `ND` coefficients ([`Evaluator::values`]).
    #[inline(never)]
    pub(super) fn grid_of<const NA: usize, const ND: usize>(
        &self,
        t0: f64,
        step: f64,
        n: usize,
        sheet: Sheet,
        out: &mut Vec<[f64; 4]>,
    ) {
        out.clear();
        out.reserve(n);
        for (t, rev) in grid_parameters(t0, step, n) {
            let (x, root) = self.values::<NA, ND>(t, rev, sheet);
            out.push(
                self.unit_of::<NA, ND>(x, root, t, rev, sheet)
                    .unwrap_or([f64::NAN; 4]),
            );
        }
    }

    /// `X` (and `√s`, 0 for a rational param) by Horner's rule with `NA` coefficients of `x`
    /// and `ND` of `d` (`ND = 0`: rational).
    #[inline(always)]
    pub(super) fn values<const NA: usize, const ND: usize>(
        &self,
        t: f64,
        rev: bool,
        sheet: Sheet,
    ) -> (Lanes, f64) {
        let (mut v, w, root) = self.parts::<NA, ND>(t, rev);
        if ND == 0 {
            return (v, 0.0);
        }
        let sr = if sheet == Sheet::Minus { -root } else { root };
        for i in 0..4 {
            v[i] += sr * w[i];
        }
        (v, root)
    }

    /// `a(t)`, `d(t)` and `√s(t)` ([`Evaluator::values`] before the sheet is chosen), Horner's
    /// rule started at the leading coefficient.
    #[inline(always)]
    pub(super) fn parts<const NA: usize, const ND: usize>(
        &self,
        t: f64,
        rev: bool,
    ) -> (Lanes, Lanes, f64) {
        let set = &self.horner[usize::from(rev)];
        let (xc, dc, sc) = (&set.x, &set.d, &set.s);
        let mut v = xc[0];
        for c in &xc[1..NA] {
            for i in 0..4 {
                v[i] = v[i] * t + c[i];
            }
        }
        if ND == 0 {
            return (v, [0.0; 4], 0.0);
        }
        let s = sc[1..].iter().fold(sc[0], |acc, c| acc * t + c);
        let root = s.max(0.0).sqrt();
        let mut w = dc[0];
        for c in &dc[1..ND] {
            for i in 0..4 {
                w[i] = w[i] * t + c[i];
            }
        }
        (v, w, root)
    }

    /// Whether an evaluation with `√s = root` and norm `norm` is certified by the bounds
    /// made once ([`sure_bounds`]): `γ·maxᵢ Σₖ(|xₖᵢ| + |dₖᵢ|·√s)|t|ᵏ ≤ γ·(Σ|x| + Σ|d|·√s)
    /// ≤ 10⁻¹⁰·‖X‖` for `|t| ≤ 1`; false for NaN.
    #[inline(always)]
    pub(super) fn sure(&self, root: f64, norm: f64) -> bool {
        root <= self.sure_root && norm >= self.sure_norm
    }

    /// A majorant of the rounding bound at `t` of [`Evaluator::certify`] in a few operations:
    /// `Σₖ|cₖ|` and `|c₀| + |t|·Σₖ₌₁|cₖ|` (`|t| ≤ 1`), the smaller, for `x` and `d`.
    #[inline(always)]
    pub(super) fn majorant(&self, t: f64, rev: bool, root: f64) -> f64 {
        let (x0, x1, d0, d1) = self.split_abs[rev as usize];
        let at = t.abs();
        let near = (x0 + at * x1) + (d0 + at * d1) * root;
        near.min(self.x_abs_max + self.d_abs_max * root)
    }

    /// The rounding bound of [`Evaluator::certify`] (`maxᵢ Σₖ (|xₖᵢ| + |dₖᵢ|·√s)|t|ᵏ`) for
    /// `NA` and `ND` coefficients: the same operations in the same order, unrolled.
    #[inline(always)]
    pub(super) fn bound_of<const NA: usize, const ND: usize>(
        &self,
        t: f64,
        rev: bool,
        root: f64,
    ) -> f64 {
        let at = t.abs();
        let set = &self.horner[usize::from(rev)];
        let (xc, dc) = (&set.x_abs, &set.d_abs);
        let mut bx = xc[0];
        for c in &xc[1..NA] {
            for i in 0..4 {
                bx[i] = bx[i] * at + c[i];
            }
        }
        let mut bd = [0.0; 4];
        if ND > 0 {
            bd = dc[0];
            for c in &dc[1..ND] {
                for i in 0..4 {
                    bd[i] = bd[i] * at + c[i];
                }
            }
        }
        (0..4).map(|i| bx[i] + bd[i] * root).fold(0.0, f64::max)
    }

    /// The two sheets' points at a node of [`Evaluator::grid_both_of`] where the majorant
    /// `Σ|cₖ|` does not certify one of them: the bound at `|t|` (the same for both sheets)
    /// computed once, as [`Evaluator::unit_of`] would (inlined: the call cost more than the
    /// bound; the double-double retry stays out of line, [`Evaluator::certify_dd`]).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    pub(super) fn certify_both<const NA: usize, const ND: usize>(
        &self,
        t: f64,
        rev: bool,
        root: f64,
        (p, np, p_ok): (Lanes, f64, bool),
        (m, nm, m_ok): (Lanes, f64, bool),
    ) -> ([f64; 4], [f64; 4]) {
        let bound = self.bound_of::<NA, ND>(t, rev, root);
        let one = |x: Lanes, norm: f64, ok: bool, sheet: Sheet| {
            if ok || self.bound_certifies(bound, norm) {
                x.map(|v| v / norm)
            } else {
                self.certify_dd(bound, t, rev, sheet)
                    .unwrap_or([f64::NAN; 4])
            }
        };
        (
            one(p, np, p_ok, Sheet::Plus),
            one(m, nm, m_ok, Sheet::Minus),
        )
    }

    /// [`Evaluator::values`] for any degree.
    pub(super) fn values_any(&self, t: f64, rev: bool, sheet: Sheet) -> (Lanes, f64) {
        let n = self.big_d + 1;
        let mut x = horner_lanes(&self.x()[..n], t, rev);
        let mut root = 0.0;
        if self.levin {
            root = horner_scalar(self.s(), t, rev).max(0.0).sqrt();
            let dv = horner_lanes(&self.d()[..n - 2], t, rev);
            let sr = if sheet == Sheet::Minus { -root } else { root };
            for i in 0..4 {
                x[i] += sr * dv[i];
            }
        }
        (x, root)
    }

    /// The rounding bound of `x` at `|t|`; the double-double evaluation where it is too
    /// large.
    #[cold]
    pub(super) fn certify(
        &self,
        t: f64,
        rev: bool,
        sheet: Sheet,
        x: Lanes,
        norm: f64,
        root: f64,
    ) -> Option<[f64; 4]> {
        let n = self.big_d + 1;
        let bx = horner_lanes_abs(&self.x()[..n], t, rev);
        let bd = if self.levin {
            horner_lanes_abs(&self.d()[..n - 2], t, rev)
        } else {
            [0.0; 4]
        };
        let root = self.root_bound(t, rev, root);
        let bound = (0..4).map(|i| bx[i] + bd[i] * root).fold(0.0, f64::max);
        self.certify_with(bound, t, rev, sheet, x, norm)
    }

    /// [`Evaluator::certify`] given the rounding bound at `|t|`.
    pub(super) fn certify_with(
        &self,
        bound: f64,
        t: f64,
        rev: bool,
        sheet: Sheet,
        x: Lanes,
        norm: f64,
    ) -> Option<[f64; 4]> {
        if self.bound_certifies(bound, norm) {
            return Some(x.map(|v| v / norm));
        }
        self.certify_dd(bound, t, rev, sheet)
    }

    /// The retry in double-double of an evaluation whose rounding bound at `|t|` is
    /// `bound` (too large for the floats); `None` for an infinite bound.
    #[cold]
    #[inline(never)]
    pub(super) fn certify_dd(
        &self,
        bound: f64,
        t: f64,
        rev: bool,
        sheet: Sheet,
    ) -> Option<[f64; 4]> {
        if !bound.is_finite() {
            return None;
        }
        let x = self.eval_dd(t, rev, sheet, bound)?;
        if self.levin {
            // `√s`'s own rounding in double-double: `|d|·min(√e, e/√ŝ)`, `e` from
            // `GAMMA_S_DD`, within `10⁻¹⁰·‖X‖` as well
            let dd = self.dd();
            let root = horner_dd(&dd.s, t, rev);
            let root = (root.0 + root.1).max(0.0).sqrt();
            let n = self.big_d + 1;
            let bd = horner_lanes_abs(&self.d()[..n - 2], t, rev);
            let err = bd.iter().fold(0.0, |m: f64, v| m.max(*v))
                * root_error(GAMMA_S_DD * self.s_size(t, rev), root);
            let norm = dot(&x, &x).sqrt();
            // NaN fails too
            if err.is_nan() || err > 1e-10 * norm {
                return None;
            }
        }
        unit(x)
    }

    /// The root of `s` in `(lo, hi)` by Newton's method safeguarded by bisection, `s`
    /// evaluated in double-double: `None` unless `s` has opposite signs at the ends (or the
    /// interval is below the float resolution: its midpoint) and the root is well
    /// conditioned (rounding moves it by at most `2⁻⁴²` relative).
    pub(super) fn root_of_s(&self, lo: f64, hi: f64) -> Option<f64> {
        let close = |a: f64, b: f64| b - a <= 4.0 * f64::EPSILON * a.abs().max(b.abs());
        if !(lo.is_finite() && hi.is_finite() && lo < hi) {
            return None;
        }
        let sd = &self.dd().s;
        // s(u) and s′(u) in floats; s(u) in double-double
        let float = |u: f64| -> (f64, f64) {
            self.s()
                .iter()
                .rev()
                .fold((0.0, 0.0), |(v, dv), &k| (v * u + k, dv * u + v))
        };
        let f = |u: f64| -> (f64, f64) {
            let v = sd
                .iter()
                .rev()
                .fold(Dd::default(), |v, k| v.mul_f64(u).add(*k));
            (v.0 + v.1, float(u).1)
        };
        // a float Newton start where the floats bracket the root, polished in double-double
        let (glo, ghi) = (float(lo).0, float(hi).0);
        if glo * ghi < 0.0 {
            // Horner's rounding of `s` in floats on the bracket: within `16ε·Σ|sₖ||u|ᵏ`
            let m = lo.abs().max(hi.abs());
            let size = self.s().iter().rev().fold(0.0, |v: f64, k| v * m + k.abs());
            let start = newton_bracketed(&float, lo, hi, glo, 16.0 * f64::EPSILON * size);
            let mut x = start;
            for _ in 0..3 {
                let (fx, dfx) = f(x);
                let next = x - fx / dfx;
                if !(lo < next && next < hi) {
                    break;
                }
                let done = (next - x).abs() <= 2.0 * f64::EPSILON * x.abs();
                x = next;
                if done {
                    let size = self
                        .s()
                        .iter()
                        .rev()
                        .fold(0.0, |v: f64, k| v * x.abs() + k.abs());
                    // the derivative in floats (as `f` gives it), without `s` in double-double
                    let err = 16.0 * 2f64.powi(-104) * size / float(x).1.abs();
                    if err.is_finite() && err <= x.abs() * 2f64.powi(-42) {
                        return Some(x);
                    }
                    break;
                }
            }
        }
        let (flo, fhi) = (f(lo).0, f(hi).0);
        let brackets = flo * fhi < 0.0;
        if !brackets {
            return close(lo, hi).then_some(0.5 * (lo + hi));
        }
        // accepted where the rounding of s (about 2⁻¹⁰⁴ of its terms) moves the root by at
        // most |x|·2⁻⁴²
        let conditioned = |x: f64| -> Option<f64> {
            let size = self
                .s()
                .iter()
                .rev()
                .fold(0.0, |v: f64, k| v * x.abs() + k.abs());
            let err = 16.0 * 2f64.powi(-104) * size / float(x).1.abs();
            (err.is_finite() && err <= x.abs() * 2f64.powi(-42)).then_some(x)
        };
        let (mut a, mut b) = (lo, hi);
        let mut x = 0.5 * (a + b);
        for _ in 0..200 {
            let (fx, dfx) = f(x);
            if fx == 0.0 {
                return conditioned(x);
            }
            if !fx.is_finite() {
                return None;
            }
            if (fx < 0.0) == (flo < 0.0) {
                a = x;
            } else {
                b = x;
            }
            if close(a, b) {
                return conditioned(0.5 * (a + b));
            }
            let newton = x - fx / dfx;
            let next = if a < newton && newton < b {
                newton
            } else {
                0.5 * (a + b)
            };
            if next == x || (next - x).abs() <= 2.0 * f64::EPSILON * x.abs() {
                return conditioned(next);
            }
            x = next;
        }
        None
    }

    /// The double-double coefficients (see `quick_dd`, `dd`).
    pub(super) fn dd(&self) -> &DdCoeffs {
        if let Some(q) = &self.quick_dd {
            return q;
        }
        self.dd.get_or_init(|| {
            let mut out = Box::<DdCoeffs>::default();
            let (a, d, s) = match self.param {
                ComponentParam::Rational { x, .. } => (x, None, None),
                ComponentParam::Levin { a, d, s, .. } => (a, Some(d), Some(s)),
                ComponentParam::Point(_) => return out,
            };
            for i in 0..4 {
                for (k, c) in a[i].coeffs().iter().enumerate() {
                    out.x[k][i] = to_dd(c);
                }
                if let Some(d) = d {
                    for (k, c) in d[i].coeffs().iter().enumerate() {
                        out.d[k][i] = to_dd(c);
                    }
                }
            }
            if let Some(s) = s {
                for (k, c) in s.coeffs().iter().enumerate() {
                    out.s[k] = to_dd(c);
                }
            }
            out
        })
    }

    /// `X` in double-double arithmetic (`t` is exact), `None` where even that rounding could
    /// exceed `10⁻¹⁰·‖X‖`.
    pub(super) fn eval_dd(&self, t: f64, rev: bool, sheet: Sheet, bound: f64) -> Option<[f64; 4]> {
        let x = self.values_dd(t, rev, sheet);
        let x = if x.iter().all(|v| v.is_finite()) {
            x
        } else {
            // beyond the range of Veltkamp's split: with the fused products
            self.values_dd_fused(t, rev, sheet)
        };
        let norm = x.iter().map(|v| v * v).sum::<f64>().sqrt();
        let gamma = self.gamma * f64::EPSILON * 4.0;
        (norm.is_finite() && norm > 0.0 && gamma * bound <= 1e-10 * norm).then_some(x)
    }

    /// `X` in double-double arithmetic, the four coordinates at once ([`Dd4`]): the values of
    /// [`Evaluator::values_dd_fused`] (every product error is exact either way) wherever
    /// Veltkamp's split does not overflow (else a NaN).
    pub(super) fn values_dd(&self, t: f64, rev: bool, sheet: Sheet) -> [f64; 4] {
        let dd = self.dd();
        let n = self.big_d + 1;
        let ts = split(t);
        let horner = |c: &[[Dd; 4]]| -> Dd4 {
            let mut v = Dd4::default();
            let mut step = |k: &[Dd; 4]| v = v.mul_f64(t, ts).add(&Dd4::of(k));
            if rev {
                c.iter().for_each(&mut step);
            } else {
                c.iter().rev().for_each(&mut step);
            }
            v
        };
        let mut v = horner(&dd.x[..n]);
        if self.levin {
            let r = horner_dd(&dd.s, t, rev).sqrt();
            let mut dr = horner(&dd.d[..n - 2]).mul(r);
            if sheet == Sheet::Minus {
                dr = Dd4 {
                    hi: dr.hi.map(|v| -v),
                    lo: dr.lo.map(|v| -v),
                };
            }
            v = v.add(&dr);
        }
        std::array::from_fn(|i| v.hi[i] + v.lo[i])
    }

    /// [`Evaluator::values_dd`] one coordinate at a time, products by `mul_add`.
    pub(super) fn values_dd_fused(&self, t: f64, rev: bool, sheet: Sheet) -> [f64; 4] {
        let dd = self.dd();
        let n = self.big_d + 1;
        let root = self.levin.then(|| horner_dd(&dd.s, t, rev).sqrt());
        let column = |c: &[[Dd; 4]], i: usize| -> Dd {
            let mut v = Dd::default();
            let mut step = |k: &[Dd; 4]| v = v.mul_f64(t).add(k[i]);
            if rev {
                c.iter().for_each(&mut step);
            } else {
                c.iter().rev().for_each(&mut step);
            }
            v
        };
        let mut x = [0.0; 4];
        for i in 0..4 {
            let mut v = column(&dd.x[..n], i);
            if let Some(r) = root {
                let mut dr = column(&dd.d[..n - 2], i).mul(r);
                if sheet == Sheet::Minus {
                    dr = dr.neg();
                }
                v = v.add(dr);
            }
            x[i] = v.0 + v.1;
        }
        x
    }
}
