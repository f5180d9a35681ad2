//! Certified real root isolation in floating point: all complex roots of an integer
//! polynomial of small degree by the Aberth–Ehrlich iteration in `f64`, then inclusion disks
//! with rigorous error bounds. The answer is a proof or `None` (the caller then isolates
//! exactly); no float decides anything the certificate does not prove.
//!
//! # Certificate
//! For distinct points `z₁…zₙ` and `p` of degree `n` with leading coefficient `aₙ`, let
//! `Wᵢ = p(zᵢ) / (aₙ ∏_{j≠i}(zᵢ − zⱼ))` (the Weierstrass corrections). Interpolation at the
//! `zᵢ` gives `p/aₙ = ∏(x − zⱼ) + Σᵢ Wᵢ ∏_{j≠i}(x − zⱼ) = det(xI − M)` with
//! `M = diag(z) − 𝟙Wᵀ` (a rank-one update). Column `i` of `M` has diagonal `zᵢ − Wᵢ` and
//! `n − 1` other entries `−Wᵢ`, so by Gershgorin the roots of `p` lie in the union of the
//! disks `D(zᵢ − Wᵢ, (n − 1)|Wᵢ|) ⊆ Dᵢ = D(zᵢ, n|Wᵢ|)`. Scaling the off-diagonal entries by
//! `t ∈ [0, 1]` moves the eigenvalues continuously from `zᵢ − Wᵢ ∈ Dᵢ` while they stay in
//! the union; so when the `Dᵢ` are pairwise disjoint, each holds exactly one root and `p`
//! is square-free. Then:
//! - a disk centred on the real axis holds a real root: with its root `ζ` the mirror image
//!   `ζ̄`, also a root (`p` is real), lies in the same (symmetric) disk, which holds only one;
//! - a disk that does not meet the real axis holds a non-real root.
//!
//! Approximations whose disk meets the axis are moved onto it and the disks computed again;
//! if then a disk off the axis meets it, or two disks meet, the certificate fails.
//!
//! # Rounding
//! The coefficients are scaled by powers of two (the variable too, `x = 2ᵏy`, so the roots
//! are near 1 in size) and rounded to `f64` with a relative error below `2u`, `u = 2⁻⁵³`
//! (tiny ones become 0 with an absolute error `2⁻⁹⁶⁰`). The disk centres are the floats
//! themselves, so only `|p(zᵢ)|` (upper bound) and `|aₙ ∏(zᵢ − zⱼ)|` (lower bound) carry
//! rounding: complex Horner's rule errs by at most `(8n + 12)·u·Σ|cₖ||z|ᵏ` (about twice the
//! first-order bound `(4n + 2)u·Σ|cₖ||z|ᵏ`: a complex product errs by at most `2√2·u`
//! relatively, a sum by `u`), plus the coefficients' errors and `2⁻¹⁰⁶⁰` per step for
//! underflow, times `|z|ʲ`. Every other quantity is a chain of fewer than 2⁸ roundings
//! (`n ≤ 16`) of non-negative values, each relative `u`: a factor `1 ± 2⁻⁴⁰` covers it.
//! A product that could underflow, or a value that is not finite, fails the certificate.
//!
//! # Intervals
//! A real disk `D(c, r)` becomes the open interval `(lo, hi)`: `lo = ⌊(c − d)/h⌋·h`,
//! `hi = ⌈(c + d)/h⌉·h` with `d = max(2r, 4u|c|, g/5)`, `g` a lower bound on the distance
//! from `c` to every other disk and to 0 (no interval holds 0, as in the exact path) and
//! `h` the largest power of two `≤ d/2`. The rounding of
//! `c ∓ d` stays below `d/4 + ud`, so `c − 1.8d < lo < c − r` (and the same for `hi`):
//! the ends lie outside every disk (not roots), and `d < g/4` (else the certificate fails)
//! keeps the interval within `0.45g` of `c`, away from the other disks and from the other
//! intervals. The ends are dyadic with about `log₂(|c|/g)` bits: cheap to evaluate.
//!
//! # Rational roots
//! As in the exact path, a rational root is reported [`RootInterval::Exact`] when the
//! leading coefficient has at most 64 bits: a rational root `a/b` has `b | aₙ`, so `aₙ·ζ` is
//! an integer in `aₙ·[c − r, c + r]`; none there proves `ζ` irrational, one is checked
//! exactly, several (a wide disk) go to the exact path's refinement.

use super::{exact_if_rational, no_rational_root, RootInterval};
use crate::poly::Poly;
use dashu_int::ops::{BitTest, UnsignedAbs};
use dashu_int::IBig;
use dashu_ratio::RBig;

/// The largest degree the certified path takes.
pub const MAX_CERTIFIED_DEGREE: usize = 16;
/// The most coefficients (fixed-size arrays: no allocation on the float path).
const MAX_LEN: usize = MAX_CERTIFIED_DEGREE + 1;

/// Unit roundoff of `f64`.
const U: f64 = f64::EPSILON / 2.0;
/// Relative slack covering a chain of fewer than 2⁸ roundings.
const SLACK: f64 = 1.0 / (1u64 << 40) as f64;
/// Scaled coefficients below `2⁻⁹⁶⁰` become 0 with this absolute error.
const FLUSH_EXP: i64 = -960;
/// Aberth–Ehrlich sweeps before the certificate is tried anyway.
const MAX_SWEEPS: usize = 60;

/// `2ᵉ` for `−1022 ≤ e ≤ 1023`.
fn pow2(e: i64) -> f64 {
    debug_assert!((-1022..=1023).contains(&e));
    f64::from_bits(((e + 1023) as u64) << 52)
}

/// A complex number in `f64`.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Complex {
    re: f64,
    im: f64,
}

impl Complex {
    const ZERO: Complex = Complex { re: 0.0, im: 0.0 };

    fn add(self, o: Complex) -> Complex {
        Complex {
            re: self.re + o.re,
            im: self.im + o.im,
        }
    }
    fn sub(self, o: Complex) -> Complex {
        Complex {
            re: self.re - o.re,
            im: self.im - o.im,
        }
    }
    fn mul(self, o: Complex) -> Complex {
        Complex {
            re: self.re * o.re - self.im * o.im,
            im: self.re * o.im + self.im * o.re,
        }
    }
    fn div(self, o: Complex) -> Complex {
        let d = o.norm_sqr();
        Complex {
            re: (self.re * o.re + self.im * o.im) / d,
            im: (self.im * o.re - self.re * o.im) / d,
        }
    }
    fn norm_sqr(self) -> f64 {
        self.re * self.re + self.im * self.im
    }
    /// `|z|` within `4u` relatively: `√(re² + im²)` when the sum of squares is far from
    /// underflow and overflow (three roundings and a square root; an underflowed square is
    /// below `u` times the sum), else `hypot`.
    fn abs(self) -> f64 {
        let s = self.norm_sqr();
        if s > pow2(-900) && s < pow2(900) {
            s.sqrt()
        } else {
            self.re.hypot(self.im)
        }
    }
    fn is_finite(self) -> bool {
        self.re.is_finite() && self.im.is_finite()
    }
}

/// `p(2ᵏy)` divided by a power of two, rounded to floats: `c[i]` within `err[i]` of the
/// exact scaled coefficient.
struct Scaled {
    c: [f64; MAX_LEN],
    err: [f64; MAX_LEN],
    len: usize,
    k: i64,
}

impl Scaled {
    /// The coefficients `c[..=n]`.
    fn c(&self) -> &[f64] {
        &self.c[..self.len]
    }
}

/// `|a|` as `m·2ᵉ` to 64 bits (truncated) with `m < 2⁶⁴`, `m` rounded to a float and
/// carrying the sign of `a`.
fn split(a: &IBig) -> (f64, i64) {
    let bits = a.bit_len();
    let shift = bits.saturating_sub(64);
    let top = u64::try_from(&(a.unsigned_abs() >> shift)).expect("at most 64 bits");
    let m = top as f64;
    (if a < &IBig::ZERO { -m } else { m }, shift as i64)
}

/// The scaled float coefficients of `p` (`p(0) ≠ 0`, degree `n ≥ 1`); `None` if the
/// leading or constant coefficient would be flushed.
fn scale(p: &Poly) -> Option<Scaled> {
    let coeffs = p.coeffs();
    let n = coeffs.len() - 1;
    // the geometric mean of the roots' sizes is |a₀/aₙ|^(1/n): y = x/2ᵏ is near 1
    let l0 = coeffs[0].bit_len() as i64;
    let ln = coeffs[n].bit_len() as i64;
    let k = (l0 - ln).div_euclid(n as i64);
    let parts: Vec<(f64, i64)> = coeffs
        .iter()
        .enumerate()
        .map(|(i, a)| {
            let (m, e) = split(a);
            (m, e + k * i as i64)
        })
        .collect();
    // top bit of the largest scaled coefficient: after the shift every |cᵢ| < 1
    let top = parts
        .iter()
        .filter(|(m, _)| *m != 0.0)
        .map(|&(_, e)| e + 64)
        .max()?;
    let (mut c, mut err) = ([0.0; MAX_LEN], [0.0; MAX_LEN]);
    for (i, &(m, e)) in parts.iter().enumerate() {
        let ex = e - top; // cᵢ = m·2^ex, m < 2⁶⁴
        if m == 0.0 {
            continue;
        }
        if ex + 64 < FLUSH_EXP {
            err[i] = pow2(FLUSH_EXP);
        } else {
            // m·2⁻⁶⁴ ∈ [2⁻⁶⁴, 1] is exact, and so is the normal product after it
            let v = m * pow2(-64) * pow2(ex + 64);
            c[i] = v;
            err[i] = 2.0 * U * v.abs();
        }
    }
    (c[0] != 0.0 && c[n] != 0.0).then_some(Scaled {
        c,
        err,
        len: n + 1,
        k,
    })
}

/// Initial approximations from the Newton polygon: on each edge `(i, j)` of the upper convex
/// hull of `(i, log₂|cᵢ|)`, `j − i` points on the circle of radius `|cᵢ/cⱼ|^(1/(j−i))`,
/// written to `z[..n]`.
fn initial(c: &[f64], z: &mut [Complex]) {
    let n = c.len() - 1;
    let mut hull = [(0usize, 0.0f64); MAX_LEN];
    let mut h = 0;
    for (i, v) in c.iter().enumerate() {
        if *v == 0.0 {
            continue;
        }
        let q = (i, v.abs().log2());
        while h >= 2 {
            let (a, b) = (hull[h - 2], hull[h - 1]);
            // drop b unless it lies strictly above the chord a–q
            let cross = (b.0 - a.0) as f64 * (q.1 - a.1) - (b.1 - a.1) * (q.0 - a.0) as f64;
            if cross >= 0.0 {
                h -= 1;
            } else {
                break;
            }
        }
        hull[h] = q;
        h += 1;
    }
    let mut at = 0;
    for w in hull[..h].windows(2) {
        let (i, j) = (w[0].0, w[1].0);
        let m = j - i;
        let rho = ((w[0].1 - w[1].1) / m as f64).exp2();
        for t in 0..m {
            let angle = std::f64::consts::TAU * (t as f64 / m as f64 + i as f64 / n as f64) + 0.4;
            z[at] = Complex {
                re: rho * angle.cos(),
                im: rho * angle.sin(),
            };
            at += 1;
        }
    }
}

/// `p(z)`, `p′(z)` by Horner's rule, and `Σ|cₖ||z|ᵏ`.
fn eval_with_derivative(c: &[f64], z: Complex) -> (Complex, Complex, f64) {
    let az = z.abs();
    let (mut v, mut dv, mut mag) = (Complex::ZERO, Complex::ZERO, 0.0);
    for &ck in c.iter().rev() {
        dv = dv.mul(z).add(v);
        v = v.mul(z).add(Complex { re: ck, im: 0.0 });
        mag = mag * az + ck.abs();
    }
    (v, dv, mag)
}

/// Aberth–Ehrlich sweeps (Gauss–Seidel: each update used at once) until every correction
/// is at the rounding level, from the Newton polygon's points, into `z[..n]`; `None` on a
/// value that is not finite.
fn aberth(c: &[f64], z: &mut [Complex]) -> Option<()> {
    initial(c, z);
    aberth_from(c, z)
}

/// [`aberth`] from the approximations `z` (distinct, `deg c` of them).
fn aberth_from(c: &[f64], z: &mut [Complex]) -> Option<()> {
    let n = c.len() - 1;
    let mut done = [false; MAX_CERTIFIED_DEGREE];
    for _ in 0..MAX_SWEEPS {
        let mut all = true;
        for i in 0..n {
            if done[i] {
                continue;
            }
            let (v, dv, mag) = eval_with_derivative(c, z[i]);
            if !v.is_finite() || !dv.is_finite() {
                return None;
            }
            let tol = 4.0 * n as f64 * U * mag;
            if v.norm_sqr() <= tol * tol {
                done[i] = true;
                continue;
            }
            all = false;
            if dv == Complex::ZERO {
                // a critical point: move off it
                z[i] = z[i].add(Complex {
                    re: 1e-3 * (1.0 + z[i].abs()),
                    im: 1e-3,
                });
                continue;
            }
            let w = v.div(dv);
            let mut s = Complex::ZERO;
            for j in 0..n {
                if j != i {
                    s = s.add(Complex { re: 1.0, im: 0.0 }.div(z[i].sub(z[j])));
                }
            }
            let corr = w.div(Complex { re: 1.0, im: 0.0 }.sub(w.mul(s)));
            let next = z[i].sub(corr);
            if !next.is_finite() {
                return None;
            }
            z[i] = next;
            if corr.norm_sqr() <= 4.0 * U * U * z[i].norm_sqr() {
                done[i] = true;
            }
        }
        if all {
            break;
        }
    }
    Some(())
}

/// An upper bound of `|p(z)|`, `p` the exact scaled polynomial (module docs, Rounding).
fn value_bound(s: &Scaled, z: Complex) -> f64 {
    let n = s.len - 1;
    let az = z.abs();
    let (mut v, mut mag, mut abs_err) = (Complex::ZERO, 0.0, 0.0);
    for (&ck, &ek) in s.c[..s.len].iter().zip(&s.err[..s.len]).rev() {
        v = v.mul(z).add(Complex { re: ck, im: 0.0 });
        mag = mag * az + ck.abs();
        abs_err = abs_err * az + ek + pow2(-1022) * pow2(-38);
    }
    let horner = (8 * n + 12) as f64 * U * mag;
    (v.abs() + horner + abs_err) * (1.0 + SLACK)
}

/// Upper bounds of the radii `n|Wᵢ|` of the inclusion disks at `z` (module docs), into
/// `r[..n]`.
fn radii(s: &Scaled, z: &[Complex], r: &mut [f64]) -> Option<()> {
    let n = z.len();
    let lead = (s.c[n].abs() - s.err[n]) * (1.0 - SLACK);
    for i in 0..n {
        // ∏|zᵢ − zⱼ| as the root of the product of the squares while every square and
        // partial product is far from underflow and overflow, else factor by factor
        let mut squares = 1.0;
        for j in 0..n {
            if j != i {
                let d = z[i].sub(z[j]).norm_sqr();
                squares *= d;
                if !(d > pow2(-900)
                    && d < pow2(900)
                    && squares > pow2(-1000)
                    && squares < pow2(1000))
                {
                    squares = f64::NAN;
                    break;
                }
            }
        }
        let mut prod = lead;
        if squares.is_nan() {
            for j in 0..n {
                if j != i {
                    prod *= z[i].sub(z[j]).abs();
                    if prod.is_nan() || prod < f64::MIN_POSITIVE {
                        return None;
                    }
                }
            }
        } else {
            prod *= squares.sqrt();
            if prod.is_nan() || prod < f64::MIN_POSITIVE {
                return None;
            }
        }
        let ri = n as f64 * value_bound(s, z[i]) / (prod * (1.0 - SLACK)) * (1.0 + SLACK);
        if !ri.is_finite() {
            return None;
        }
        r[i] = ri;
    }
    Some(())
}

/// A lower bound of `|a − b|`.
fn distance_lo(a: Complex, b: Complex) -> f64 {
    a.sub(b).abs() * (1.0 - SLACK)
}

/// The certified disks of the scaled polynomial of degree `n`: centres `z[..n]`, radii
/// `r[..n]`, real centres exactly on the axis; `None` if the certificate fails.
fn certified_disks(s: &Scaled, z: &mut [Complex], r: &mut [f64]) -> Option<()> {
    aberth(s.c(), z)?;
    certified_disks_from(s, z, r)
}

/// [`certified_disks`] at the approximations `z` (as many as the degree).
fn certified_disks_from(s: &Scaled, z: &mut [Complex], r: &mut [f64]) -> Option<()> {
    // |z| < 10¹⁵⁰ (false on NaN)
    if !z.iter().all(|v| v.norm_sqr() < 1e300) {
        return None;
    }
    radii(s, z, r)?;
    let mut moved = false;
    for (zi, &ri) in z.iter_mut().zip(r.iter()) {
        if zi.im != 0.0 && zi.im.abs() <= ri {
            zi.im = 0.0;
            moved = true;
        }
    }
    if moved {
        radii(s, z, r)?;
    }
    let n = z.len();
    for i in 0..n {
        if z[i].im != 0.0 && z[i].im.abs() <= r[i] {
            return None;
        }
        for j in i + 1..n {
            if distance_lo(z[i], z[j]) <= (r[i] + r[j]) * (1.0 + SLACK) {
                return None;
            }
        }
    }
    Some(())
}

/// `j·2ᵉ` as a rational (`j` an integer below `2⁶³` in magnitude): the odd part of `j`
/// over a power of two is already in lowest terms, so no gcd is taken; a normal float
/// `j·2ᵉ` converts directly.
fn dyadic(j: f64, e: i64) -> RBig {
    let j = j as i64;
    if j == 0 {
        return RBig::ZERO;
    }
    let t = j.trailing_zeros() as i64;
    let (j, e) = (j >> t, e + t);
    if (-1000..=0).contains(&e) && j.unsigned_abs() < 1 << 53 {
        // j and j·2ᵉ ≥ 2⁻¹⁰⁰⁰ are exact floats; the conversion of an odd numerator over a
        // power of two only strips trailing zeros
        return RBig::try_from(j as f64 * pow2(e)).expect("a finite float");
    }
    let j = IBig::from(j);
    if e >= 0 {
        RBig::from(j << e as usize)
    } else {
        RBig::from_parts_signed(j, IBig::ONE << e.unsigned_abs() as usize)
    }
}

/// The float `v` as an exact rational times `2ᵏ`.
fn float_times_pow2(v: f64, k: i64) -> RBig {
    let exact = RBig::try_from(v).expect("a finite float");
    if k >= 0 {
        exact * RBig::from(IBig::ONE << k as usize)
    } else {
        exact / RBig::from(IBig::ONE << k.unsigned_abs() as usize)
    }
}

/// The isolating interval of the real root in `D(c, r)` (module docs, Intervals), as
/// `(lo, hi)` in units of `2^e`; `None` if the disk is too close to the others. A `wide`
/// interval reaches out to a fifth of the gap (short ends), else it is as narrow as the
/// disk allows (`d = max(2r, 4u|c|)`; the same proof holds).
fn interval_in_units(c: f64, r: f64, gap: f64, wide: bool) -> Option<(f64, f64, i64)> {
    let d = (2.0 * r)
        .max(4.0 * U * c.abs())
        .max(if wide { gap / 5.0 } else { 0.0 });
    let separated = 4.0 * d < gap * (1.0 - SLACK) && d >= pow2(-900); // false on NaN
    if !separated {
        return None;
    }
    // h = 2^e ≤ d/2, the largest such power of two
    let e = (d / 2.0).log2().floor() as i64;
    let e = if pow2(e + 1) <= d / 2.0 { e + 1 } else { e };
    let e = if pow2(e) > d / 2.0 { e - 1 } else { e };
    let h = pow2(e);
    let lo = ((c - d) / h).floor();
    let hi = ((c + d) / h).ceil();
    Some((lo, hi, e))
}

/// A real root isolated by [`certified_real_roots_enclosed`]: its isolating interval and a
/// float enclosure, the root lying in `[center − radius, center + radius]` (a radius of
/// `+∞` when the scaled disk does not fit the range of `f64`).
#[derive(Clone, Debug, PartialEq)]
pub struct CertifiedRoot {
    /// The isolating interval (postconditions of [`isolate_real_roots`](super::isolate_real_roots)).
    pub interval: RootInterval,
    /// A float within `radius` of the root.
    pub center: f64,
    /// A rigorous bound on the distance from `center` to the root.
    pub radius: f64,
    /// An isolating interval about as narrow as the enclosure (its ends have about 53
    /// bits): where a refinement can start.
    pub narrow: RootInterval,
}

/// [`certified_real_roots`], the intervals only.
///
/// ```
/// # use qsic_algebra::{Poly, RBig, roots::{certified_real_roots, RootInterval}};
/// let p = &Poly::from_i64s(&[-2, 0, 1]) * &Poly::from_i64s(&[1, 1, 1]); // (x² − 2)(x² + x + 1)
/// let r = certified_real_roots(&p).unwrap();
/// assert_eq!(r.len(), 2);
/// assert!(r[0].hi() < &RBig::ZERO && r[1].lo() > &RBig::ZERO);
/// assert_eq!(certified_real_roots(&Poly::from_roots(&[2, 2, 5])), None); // a double root
/// ```
pub fn certified_real_roots(p: &Poly) -> Option<Vec<RootInterval>> {
    Some(
        certified_real_roots_enclosed(p)?
            .into_iter()
            .map(|r| r.interval)
            .collect(),
    )
}

/// `v·2ᵏ` for a float `v`, `None` unless the result is normal (then it is exact).
fn times_pow2(v: f64, k: i64) -> Option<f64> {
    if !(-1000..=1000).contains(&k) {
        return None;
    }
    let x = v * pow2(k);
    (x.is_finite() && (x == 0.0 || x.abs() >= pow2(-1000))).then_some(x)
}

/// The root of `p` at `c·2ᵏ` within `r·2ᵏ`, in the original variable.
fn enclosed(interval: RootInterval, narrow: RootInterval, c: f64, r: f64, k: i64) -> CertifiedRoot {
    let (center, radius) = match (times_pow2(c, k), times_pow2(r, k)) {
        (Some(center), Some(radius)) if radius > 0.0 => (center, radius),
        _ => (0.0, f64::INFINITY),
    };
    CertifiedRoot {
        interval,
        center,
        radius,
        narrow,
    }
}

/// Isolates the real roots of `p` in floating point with a proof (module docs); `None` if
/// the degree exceeds [`MAX_CERTIFIED_DEGREE`], `p` is zero, or the certificate fails (for
/// example, `p` is not square-free or has roots too close for `f64`). `Some` proves `p`
/// square-free, and the intervals meet the postconditions of
/// [`isolate_real_roots`](super::isolate_real_roots).
///
/// Each root comes with a float enclosure ([`CertifiedRoot`]).
pub fn certified_real_roots_enclosed(p: &Poly) -> Option<Vec<CertifiedRoot>> {
    let n = p.degree()?;
    if n > MAX_CERTIFIED_DEGREE {
        return None;
    }
    if n == 0 {
        return Some(Vec::new());
    }
    if p.coeff(0).is_zero() {
        // 0 is a root: simple iff p′(0) ≠ 0; the others are roots of p/x
        if p.coeff(1).is_zero() {
            return None;
        }
        let mut r = certified_real_roots_enclosed(&p.shift_down(1))?;
        if r.iter()
            .any(|c| c.interval.lo() < &RBig::ZERO && c.interval.hi() > &RBig::ZERO)
        {
            return None;
        }
        r.push(CertifiedRoot {
            interval: RootInterval::Exact(RBig::ZERO),
            center: 0.0,
            radius: 0.0,
            narrow: RootInterval::Exact(RBig::ZERO),
        });
        r.sort_by(|a, b| a.interval.lo().cmp(b.interval.lo()));
        return Some(r);
    }
    if n == 1 {
        let v = RBig::from_parts_signed(-p.coeff(0), p.coeff(1));
        let center = v.to_f64().value();
        return Some(vec![CertifiedRoot {
            radius: if center.is_finite() {
                SLACK * center.abs() + pow2(-1022)
            } else {
                f64::INFINITY
            },
            center: if center.is_finite() { center } else { 0.0 },
            narrow: RootInterval::Exact(v.clone()),
            interval: RootInterval::Exact(v),
        }]);
    }
    let s = scale(p)?;
    let (mut z, mut r) = (
        [Complex::ZERO; MAX_CERTIFIED_DEGREE],
        [0.0; MAX_CERTIFIED_DEGREE],
    );
    let (z, r) = (&mut z[..n], &mut r[..n]);
    certified_disks(&s, z, r)?;
    let lc = p.leading();
    let small_lc = lc.bit_len() <= 64;
    // whether `p` has no rational root at all: decided once, when a root is left open
    let mut irrational = None;
    let mut out = Vec::new();
    for i in 0..n {
        if z[i].im != 0.0 {
            continue;
        }
        let gap = (0..n)
            .filter(|&j| j != i)
            .map(|j| (distance_lo(z[i], z[j]) - r[j]) * (1.0 - SLACK))
            .fold(f64::INFINITY, f64::min)
            // and from 0, so that no interval holds 0 (as in the exact path, where the
            // positive and negative roots are isolated apart)
            .min(z[i].re.abs());
        let (c, ri) = (z[i].re, r[i]);
        let open = |wide| {
            let (lo, hi, e) = interval_in_units(c, ri, gap, wide)?;
            Some(RootInterval::Open(dyadic(lo, e + s.k), dyadic(hi, e + s.k)))
        };
        let iv = open(true)?;
        debug_assert!(
            p.sign_at(iv.lo()) * p.sign_at(iv.hi()) == crate::Sign::Negative,
            "certified interval {iv:?} of {p}"
        );
        let interval = match small_lc.then(|| rationality(p, &lc, c, ri, s.k)) {
            None | Some(Rationality::Irrational) => iv,
            Some(Rationality::Rational(v)) => RootInterval::Exact(v),
            Some(Rationality::Unknown) => {
                if *irrational.get_or_insert_with(|| no_rational_root(p)) {
                    iv
                } else {
                    exact_if_rational(p, iv)
                }
            }
        };
        let narrow = match &interval {
            RootInterval::Exact(_) => interval.clone(),
            RootInterval::Open(..) => open(false)?,
        };
        out.push(enclosed(interval, narrow, c, ri, s.k));
    }
    out.sort_by(|a, b| a.interval.lo().cmp(b.interval.lo()));
    Some(out)
}

/// The binary exponent `⌊log₂|x|⌋` of a normal float `x`.
fn exponent(x: f64) -> i64 {
    ((x.to_bits() >> 52) & 0x7ff) as i64 - 1023
}

/// `v` rounded to the nearest float (machine integers convert directly, correctly rounded).
fn int_to_f64(v: &IBig) -> f64 {
    if let Ok(x) = i64::try_from(v) {
        return x as f64;
    }
    match i128::try_from(v) {
        Ok(x) => x as f64,
        Err(_) => v.to_f64().value(),
    }
}

/// The coefficients of `s` and of `s̄` for `s = A + B√δ`: the floats `aᵢ ± √δ·bᵢ` and a
/// common bound of their errors (docs of [`certified_real_roots_zsqrt`]).
fn conjugate_floats(a: &[&IBig], b: &[&IBig], delta: &IBig) -> ([f64; 5], [f64; 5], [f64; 5]) {
    let r = int_to_f64(delta).sqrt();
    let (mut c, mut cbar, mut err) = ([0.0; 5], [0.0; 5], [0.0; 5]);
    for i in 0..a.len() {
        let af = int_to_f64(a[i]);
        let p = r * int_to_f64(b[i]);
        c[i] = af + p;
        cbar[i] = af - p;
        err[i] =
            (2.0 * af.abs() + 6.0 * p.abs() + c[i].abs().max(cbar[i].abs())) * U * (1.0 + SLACK);
    }
    (c, cbar, err)
}

/// Float approximations `(re, im)` of the four complex roots of the quartic with
/// coefficients `c` (from degree 0, `c₄ ≠ 0`, `c₀ ≠ 0`), not certified: `x = 2ᵏy` with `2ᵏ` about
/// the roots' geometric mean in size, Ferrari's formulas polished by Newton's method, else
/// Aberth's iteration; `None` on a value that is not finite. For callers that check exactly
/// what they build from the roots.
///
/// ```
/// # use qsic_algebra::roots::quartic_roots_f64;
/// // (x² − 2)(x² + 9)
/// let z = quartic_roots_f64(&[-18.0, 0.0, 7.0, 0.0, 1.0]).unwrap();
/// let mut real: Vec<f64> = z.iter().filter(|r| r.1 == 0.0).map(|r| r.0).collect();
/// real.sort_by(f64::total_cmp);
/// assert!((real[1] - 2f64.sqrt()).abs() < 1e-15 && (real[0] + real[1]).abs() < 1e-15);
/// assert!(z.iter().any(|r| (r.1.abs() - 3.0).abs() < 1e-14));
/// ```
pub fn quartic_roots_f64(c: &[f64; 5]) -> Option<[(f64, f64); 4]> {
    if c[4] == 0.0 || c[0] == 0.0 || !c.iter().all(|v| v.is_finite()) {
        return None;
    }
    let k = (exponent(c[0]) - exponent(c[4])).div_euclid(4);
    if !(-200..=200).contains(&k) {
        return None;
    }
    // cᵢ·2^(k·i): exact scalings by powers of two (None if one leaves the float range)
    let scaled: [f64; 5] = std::array::from_fn(|i| c[i] * pow2(k * i as i64));
    if !scaled
        .iter()
        .all(|v| v.is_finite() && (*v == 0.0 || v.abs() > f64::MIN_POSITIVE))
    {
        return None;
    }
    // plausible: every value at a small multiple of its rounding level, and the sum of the
    // roots −c₃/c₄ (two approximations of one root would leave another root out)
    let plausible = |z: &[Complex; 4]| {
        let values = z.iter().all(|&w| {
            // p(w) by Horner's rule and Σ|cₖ||w|ᵏ, compared squared (no square roots)
            let (aw, mut v, mut mag) = (w.abs(), Complex::ZERO, 0.0);
            for &ck in scaled.iter().rev() {
                v = v.mul(w).add(Complex { re: ck, im: 0.0 });
                mag = mag * aw + ck.abs();
            }
            let tol = 64.0 * U * mag;
            v.norm_sqr() <= tol * tol
        });
        let sum = z.iter().fold(Complex::ZERO, |acc, &w| acc.add(w));
        let size: f64 = z.iter().map(|w| w.abs()).sum();
        let want = -scaled[3] / scaled[4];
        values && sum.im.abs() <= 1e-9 * size && (sum.re - want).abs() <= 1e-9 * size
    };
    let mut z = ferrari(&scaled)?;
    if !polish(&scaled, &mut z) {
        aberth_from(&scaled, &mut z)?;
    }
    if !plausible(&z) {
        aberth(&scaled, &mut z)?;
        if !plausible(&z) {
            return None;
        }
    }
    let unit = pow2(k);
    Some(z.map(|w| (w.re * unit, w.im * unit)))
}

/// The largest real root of the monic cubic `m³ + a₂m² + a₁m + a₀` in floats (not
/// certified): the trigonometric form when the depressed cubic `t³ + Pt + Q` has three real
/// roots, else Cardano's (the cube root taken where nothing cancels), then two Newton steps.
fn largest_cubic_root(a2: f64, a1: f64, a0: f64) -> f64 {
    let shift = a2 / 3.0;
    let p = a1 - a2 * shift;
    let q = (2.0 * shift * shift - a1) * shift + a0;
    let half = 0.5 * q;
    let third = p / 3.0;
    let disc = half * half + third * third * third;
    let t = if disc > 0.0 {
        // one real root: u³ = −Q/2 − sign(Q)√Δ, t = u − P/(3u)
        let u = (-half - disc.sqrt().copysign(half)).cbrt();
        if u == 0.0 {
            0.0
        } else {
            u - third / u
        }
    } else {
        // three real roots (P ≤ 0): t = 2√(−P/3)·cos(θ/3), the largest
        let rho = (-third).sqrt();
        let cos = if rho == 0.0 {
            0.0
        } else {
            (-half / (rho * rho * rho)).clamp(-1.0, 1.0)
        };
        2.0 * rho * (cos.acos() / 3.0).cos()
    };
    let mut m = t - shift;
    for _ in 0..2 {
        let f = ((m + a2) * m + a1) * m + a0;
        let df = (3.0 * m + 2.0 * a2) * m + a1;
        let next = m - f / df;
        if !next.is_finite() {
            break;
        }
        m = next;
    }
    m
}

/// `√w` on the principal branch (real part ≥ 0), without cancellation.
fn complex_sqrt(w: Complex) -> Complex {
    let a = w.abs();
    if a == 0.0 {
        return Complex::ZERO;
    }
    if w.re >= 0.0 {
        let re = (0.5 * (a + w.re)).sqrt();
        Complex {
            re,
            im: w.im / (2.0 * re),
        }
    } else {
        let im = (0.5 * (a - w.re)).sqrt().copysign(w.im);
        Complex {
            re: w.im / (2.0 * im),
            im,
        }
    }
}

/// Approximations of the roots of the quartic `c` (`c₄ ≠ 0`) by Ferrari's formulas in
/// floats (the certificate does not rely on them), each conjugate pair adjacent; `None` on a
/// value that is not finite. For `x = y − b/4` the monic quartic is `y⁴ + py² + qy + r`; with
/// `m > 0` a root of the resolvent `8m³ + 8pm² + (2p² − 8r)m − q²` (negative at 0 when
/// `q ≠ 0`) and `w = √(2m)` it factors as `(y² − wy + p/2 + m + q/(2w))(y² + wy + p/2 + m −
/// q/(2w))`. When `q = 0` (a biquadratic: the resolvent's root may be 0) `y² = Y` with `Y² +
/// pY + r = 0`, real or a conjugate pair.
fn ferrari(c: &[f64]) -> Option<[Complex; 4]> {
    let (b, cc, d, e) = (c[3] / c[4], c[2] / c[4], c[1] / c[4], c[0] / c[4]);
    let b2 = b * b;
    let p = cc - 0.375 * b2;
    let q = d - 0.5 * b * cc + 0.125 * b2 * b;
    let r = e - 0.25 * b * d + b2 * cc / 16.0 - 3.0 * b2 * b2 / 256.0;
    let shift = -0.25 * b;
    let mut z = [Complex::ZERO; 4];
    // y² + lin·y + con into z[at], z[at + 1]
    let mut quadratic = |at: usize, lin: f64, con: f64| {
        let disc = 0.25 * lin * lin - con;
        let h = -0.5 * lin + shift;
        let t = disc.abs().sqrt();
        (z[at], z[at + 1]) = if disc >= 0.0 {
            (
                Complex { re: h + t, im: 0.0 },
                Complex { re: h - t, im: 0.0 },
            )
        } else {
            (Complex { re: h, im: t }, Complex { re: h, im: -t })
        };
    };
    let m = if q == 0.0 {
        0.0
    } else {
        largest_cubic_root(p, 0.25 * p * p - r, -0.125 * q * q)
    };
    if m > 0.0 && m.is_finite() {
        let w = (2.0 * m).sqrt();
        quadratic(0, -w, 0.5 * p + m + q / (2.0 * w));
        quadratic(2, w, 0.5 * p + m - q / (2.0 * w));
    } else {
        // a biquadratic in y (q = 0, or lost to rounding): Y = y²
        let disc = p * p - 4.0 * r;
        if disc >= 0.0 {
            // the larger Y first, the other as r over it (no cancellation)
            let y1 = -0.5 * (p + disc.sqrt().copysign(p));
            let y2 = if y1 == 0.0 { 0.0 } else { r / y1 };
            quadratic(0, 0.0, -y1);
            quadratic(2, 0.0, -y2);
        } else {
            let w = complex_sqrt(Complex {
                re: -0.5 * p,
                im: 0.5 * (-disc).sqrt(),
            });
            let conj = |v: Complex| Complex {
                re: v.re,
                im: -v.im,
            };
            let at = |v: Complex| Complex {
                re: v.re + shift,
                im: v.im,
            };
            let minus = Complex {
                re: -w.re,
                im: -w.im,
            };
            z = [at(w), at(conj(w)), at(minus), at(conj(minus))];
        }
    }
    // distinct approximations (Aberth's corrections divide by their differences)
    for i in 0..4 {
        for j in 0..i {
            if z[i] == z[j] {
                let nudge = 1e-6 * (1.0 + z[i].abs());
                z[i].im += nudge * (1 + i) as f64;
            }
        }
    }
    z.iter().all(|v| v.is_finite()).then_some(z)
}

/// A few Newton steps on each approximation of a root of `c` (real ones in real arithmetic,
/// the second of a conjugate pair mirrored from the first), stopping when the correction is
/// at the rounding level; `false` if some approximation has not got there (then Aberth's
/// iteration takes over).
fn polish(c: &[f64], z: &mut [Complex]) -> bool {
    const STEPS: usize = 4;
    let n = (c.len() - 1) as f64;
    let mut i = 0;
    while i < z.len() {
        if z[i].im == 0.0 {
            let mut x = z[i].re;
            let mut converged = false;
            for _ in 0..STEPS {
                let (mut v, mut dv, mut mag) = (0.0f64, 0.0f64, 0.0f64);
                for &ck in c.iter().rev() {
                    dv = dv * x + v;
                    v = v * x + ck;
                    mag = mag * x.abs() + ck.abs();
                }
                // at the rounding level of the value: x is as good as floats get
                if v.abs() <= 4.0 * n * U * mag {
                    converged = true;
                    break;
                }
                let corr = v / dv;
                if !corr.is_finite() {
                    break;
                }
                x -= corr;
                if corr.abs() <= 4.0 * U * x.abs() {
                    converged = true;
                    break;
                }
            }
            if !converged {
                return false;
            }
            z[i].re = x;
            i += 1;
            continue;
        }
        let mut w = z[i];
        let mut converged = false;
        for _ in 0..STEPS {
            let (v, dv, mag) = eval_with_derivative(c, w);
            let tol = 4.0 * n * U * mag;
            if v.norm_sqr() <= tol * tol {
                converged = true;
                break;
            }
            let corr = v.div(dv);
            if !corr.is_finite() {
                break;
            }
            w = w.sub(corr);
            if corr.norm_sqr() <= 16.0 * U * U * w.norm_sqr() {
                converged = true;
                break;
            }
        }
        if !converged {
            return false;
        }
        let pair = i + 1 < z.len()
            && z[i + 1]
                == Complex {
                    re: z[i].re,
                    im: -z[i].im,
                };
        z[i] = w;
        if pair {
            z[i + 1] = Complex {
                re: w.re,
                im: -w.im,
            };
            i += 1;
        }
        i += 1;
    }
    true
}

/// Whether `d ≥ 0` is a perfect square (in floats when `d < 2⁵²`: then `√d` rounds to
/// within `1/4` of an integer root).
fn is_square(d: &IBig) -> bool {
    match u64::try_from(d) {
        Ok(v) if v < 1 << 52 => {
            let r = (v as f64).sqrt().round() as u64;
            r * r == v
        }
        _ => {
            use dashu_int::ops::SquareRoot;
            let r = d.unsigned_abs().sqrt();
            IBig::from(&r * &r) == *d
        }
    }
}

/// `c·2^(k·i − t)` with `t` making the largest `|cᵢ|` just below 1, and the errors alike;
/// `None` if a nonzero value would leave the normal range (far from any input here).
fn scaled_floats(c: &[f64], err: &[f64], k: i64) -> Option<Scaled> {
    let top = c
        .iter()
        .enumerate()
        .filter(|(_, v)| **v != 0.0)
        .map(|(i, v)| exponent(*v) + k * i as i64)
        .max()?
        + 1;
    let (mut sc, mut se) = ([0.0; MAX_LEN], [0.0; MAX_LEN]);
    for (i, (&v, &e)) in c.iter().zip(err).enumerate() {
        let x = k * i as i64 - top;
        if !(-1000..=1000).contains(&x) {
            return None;
        }
        let (v, e) = (v * pow2(x), e * pow2(x));
        // exact unless subnormal: refuse those (an error bound must not round down)
        if (v != 0.0 && v.abs() < pow2(-1000)) || (e != 0.0 && e < pow2(-1000)) {
            return None;
        }
        sc[i] = v;
        se[i] = e;
    }
    Some(Scaled {
        c: sc,
        err: se,
        len: c.len(),
        k,
    })
}

/// The real roots of `s = A + B√δ ∈ ℤ[√δ][x]` (`A = Σaᵢxⁱ`, `B = Σbᵢxⁱ`, `δ > 0` not a
/// square, degree `n = 1…4`, `s(0) ≠ 0`) isolated among the real roots of the norm
/// `N = s·s̄ = A² − δB²`, in floats with a proof; `None` if the certificate fails (`N` not
/// square-free, roots too close for `f64`) or the input is outside the stated range.
///
/// # Certificate
/// The coefficients `aᵢ ± √δ·bᵢ` of `s` and of `s̄` are rounded to floats: `aᵢ`, `bᵢ`, `δ`
/// each with a relative error `u`, `√δ` then within `1.5u`, the product `p = fl(√δ·bᵢ)`
/// within `3.5u|p|` of the exact one (to first order) and the sum within `u` of itself, so
/// each coefficient lies within `(|aᵢ| + 4|p| + |cᵢ|)·u·(1 + 2⁻⁴⁰)` of its float. The disks of
/// the module docs are then computed for `s` and for `s̄` (degree `n` each, from these
/// coefficients with their errors): when the disks of each are pairwise disjoint, each holds
/// exactly one root of its polynomial, and when moreover no disk of `s` meets one of `s̄`,
/// the `2n` disks hold one root of `N` each, so `N` is square-free and a real disk of `s`
/// holds a real root of `s` isolated from every other root of `N`. No root of `s` is
/// rational: `s(ζ) = A(ζ) + B(ζ)√δ = 0` with `√δ ∉ ℚ` and `ζ ∈ ℚ` gives `A(ζ) = B(ζ) = 0`,
/// a common root of `s` and `s̄`. So every interval is open.
///
/// The roots come sorted; the intervals meet the postconditions of
/// [`isolate_real_roots`](super::isolate_real_roots) for the roots of `N`. Each
/// [`CertifiedRoot::narrow`] is the isolating interval itself (its dyadic ends cost; the
/// enclosure already gives the root to about 53 bits).
///
/// ```
/// # use qsic_algebra::{IBig, RBig, roots::certified_real_roots_zsqrt};
/// // s = x² − √2: the roots ±2^(1/4); s̄ = x² + √2 has none
/// let (zero, one) = (IBig::ZERO, IBig::ONE);
/// let (a, b) = ([&zero, &zero, &one], [&-&one, &zero, &zero]);
/// let r = certified_real_roots_zsqrt(&a, &b, &IBig::from(2)).unwrap();
/// assert_eq!(r.len(), 2);
/// assert!((r[1].center - 2f64.powf(0.25)).abs() <= r[1].radius);
/// assert!(r[0].interval.hi() < &RBig::ZERO && r[1].interval.lo() > &RBig::ZERO);
/// ```
pub fn certified_real_roots_zsqrt(
    a: &[&IBig],
    b: &[&IBig],
    delta: &IBig,
) -> Option<Vec<CertifiedRoot>> {
    let (real, m, k) = zsqrt_real_disks(a, b, delta)?;
    let mut out = Vec::with_capacity(m);
    // disjoint intervals around the centres: their order is that of the centres
    for &(c, ri, gap) in &real[..m] {
        let (lo, hi, e) = interval_in_units(c, ri, gap, true)?;
        let interval = RootInterval::Open(dyadic(lo, e + k), dyadic(hi, e + k));
        out.push(enclosed(interval.clone(), interval, c, ri, k));
    }
    Some(out)
}

/// A real disk of `s`: centre, radius, and a lower bound on its gap to every other disk and
/// to 0.
type RealDisk = (f64, f64, f64);

/// The certificate of [`certified_real_roots_zsqrt`]: the real disks of `s` in the variable
/// `y = x/2ᵏ`, sorted by centre, their number and `k`.
fn zsqrt_real_disks(a: &[&IBig], b: &[&IBig], delta: &IBig) -> Option<([RealDisk; 4], usize, i64)> {
    let n = a.len().checked_sub(1)?;
    if !(1..=4).contains(&n) || b.len() != a.len() || delta <= &IBig::ONE {
        return None;
    }
    if is_square(delta) {
        return None;
    }
    let zero = |i: usize| a[i].is_zero() && b[i].is_zero();
    if zero(0) || zero(n) {
        return None;
    }
    let (c, cbar, err) = conjugate_floats(a, b, delta);
    if [c[0], c[n], cbar[0], cbar[n]].contains(&0.0) {
        return None;
    }
    // x = 2ᵏy with 2ᵏ the geometric mean of the sizes of the roots of N
    let k = (exponent(c[0]) + exponent(cbar[0]) - exponent(c[n]) - exponent(cbar[n]))
        .div_euclid(2 * n as i64);
    let sp = scaled_floats(&c[..=n], &err[..=n], k)?;
    let sq = scaled_floats(&cbar[..=n], &err[..=n], k)?;
    // Ferrari's approximations polished by Newton's method, else (or if the certificate
    // fails there) Aberth's iteration from the Newton polygon
    let disks = |sc: &Scaled, z: &mut [Complex], r: &mut [f64]| -> Option<()> {
        if n == 4 {
            if let Some(f) = ferrari(sc.c()) {
                z.copy_from_slice(&f);
                let polished = polish(sc.c(), z) || aberth_from(sc.c(), z).is_some();
                if polished && certified_disks_from(sc, z, r).is_some() {
                    return Some(());
                }
            }
        }
        certified_disks(sc, z, r)
    };
    let (mut zp, mut rp, mut zq, mut rq) =
        ([Complex::ZERO; 4], [0.0; 4], [Complex::ZERO; 4], [0.0; 4]);
    let (zp, rp, zq, rq) = (&mut zp[..n], &mut rp[..n], &mut zq[..n], &mut rq[..n]);
    disks(&sp, zp, rp)?;
    disks(&sq, zq, rq)?;
    for (zi, ri) in zp.iter().zip(rp.iter()) {
        for (zj, rj) in zq.iter().zip(rq.iter()) {
            if distance_lo(*zi, *zj) <= (ri + rj) * (1.0 + SLACK) {
                return None;
            }
        }
    }
    // the real disks of s with their gaps to every other disk and to 0, by centre
    let mut real = [(0.0f64, 0.0f64, 0.0f64); 4];
    let mut m = 0;
    for i in 0..n {
        if zp[i].im != 0.0 {
            continue;
        }
        let mut gap = zp[i].re.abs();
        for (j, (zj, rj)) in zp.iter().zip(rp.iter()).enumerate() {
            if j != i {
                gap = gap.min((distance_lo(zp[i], *zj) - rj) * (1.0 - SLACK));
            }
        }
        for (zj, rj) in zq.iter().zip(rq.iter()) {
            gap = gap.min((distance_lo(zp[i], *zj) - rj) * (1.0 - SLACK));
        }
        real[m] = (zp[i].re, rp[i], gap);
        m += 1;
    }
    real[..m].sort_unstable_by(|x, y| x.0.total_cmp(&y.0));
    Some((real, m, k))
}

/// What the disk says of a real root's rationality.
enum Rationality {
    Irrational,
    Rational(RBig),
    /// Several candidates: the disk is too wide to tell.
    Unknown,
}

/// Whether the root of `p` in `2ᵏ·[c − r, c + r]` is rational (module docs, Rational
/// roots): the integers `m` with `m/|aₙ|` there are the candidates. In floats when
/// `|aₙ|·2ᵏ·(|c| + r) < 2⁵⁰` proves there is none, else exactly.
fn rationality(p: &Poly, lc: &IBig, c: f64, r: f64, k: i64) -> Rationality {
    let lc = IBig::from(lc.unsigned_abs());
    let l = lc.to_f64().value(); // within a relative u of |aₙ|
    if (-900..=900).contains(&k) {
        let x = l * c * pow2(k);
        let w = (l * r * pow2(k) + 8.0 * U * x.abs()) * (1.0 + SLACK);
        // x is within 3u|x| of |aₙ|·2ᵏ·c; the margin 8u|x| also covers the rounding of
        // x ± w when w ≤ 4|x| (else 0 lies between them and the test fails); ⌊·⌋ is exact
        if x.abs() + w < pow2(50) && (x + w).floor() < x - w {
            return Rationality::Irrational;
        }
    }
    let (c, r) = (float_times_pow2(c, k), float_times_pow2(r, k));
    let scaled = |v: RBig| v * RBig::from(lc.clone());
    let m_lo = scaled(&c - &r).ceil();
    let m_hi = scaled(c + r).floor();
    if m_hi < m_lo {
        Rationality::Irrational
    } else if m_hi == m_lo {
        if p.eval_homogeneous(&m_lo, &lc).is_zero() {
            Rationality::Rational(RBig::from_parts_signed(m_lo, lc))
        } else {
            Rationality::Irrational
        }
    } else {
        Rationality::Unknown
    }
}

#[cfg(test)]
mod tests {
    use super::super::isolate_squarefree_real_roots_descartes;
    use super::*;
    use crate::poly::sturm::SturmSequence;
    use crate::testing::SplitMix;
    use crate::Sign;

    /// A random integer of about `bits` bits (sign included), never zero.
    fn big(rng: &mut SplitMix, bits: usize) -> IBig {
        let mut v = IBig::ZERO;
        for _ in 0..bits.div_ceil(32) {
            v = (v << 32) + IBig::from(rng.next_u64() >> 32);
        }
        let v = (v >> (bits.div_ceil(32) * 32 - bits)) + IBig::ONE;
        if rng.int(0, 1) == 0 {
            -v
        } else {
            v
        }
    }

    /// A polynomial of one of the families of the module tests: random coefficients of a
    /// few or about 133 bits (10⁴⁰), or products of linear and quadratic factors with
    /// roots 2⁻³⁰ apart, roots of size 2^±60, and rational roots.
    fn random_poly(rng: &mut SplitMix, family: u64) -> Poly {
        let degree = rng.int(1, 10) as usize;
        let lin = |a: IBig, b: IBig| Poly::new(vec![-b, a]); // a·x − b
        match family % 4 {
            0 | 1 => {
                let bits = if family % 4 == 0 { 6 } else { 133 };
                Poly::new((0..=degree).map(|_| big(rng, bits)).collect())
            }
            2 => {
                // close pairs and random rational roots
                let mut p = Poly::constant(IBig::ONE);
                for _ in 0..degree.div_ceil(2) {
                    let m = big(rng, 40);
                    let shift = IBig::ONE << 30;
                    p = &p * &lin(shift.clone(), m.clone());
                    p = &p
                        * &match rng.int(0, 2) {
                            0 => lin(shift, m + IBig::ONE),
                            1 => lin(big(rng, 8), big(rng, 10)),
                            _ => Poly::new(vec![
                                IBig::from(big(rng, 10).unsigned_abs()),
                                big(rng, 4),
                                IBig::ONE,
                            ]),
                        };
                }
                p
            }
            _ => {
                // huge and tiny roots, and quadratics with irrational roots
                let mut p = Poly::constant(IBig::ONE);
                for _ in 0..degree.div_ceil(2) {
                    let f = match rng.int(0, 3) {
                        0 => lin(IBig::ONE, big(rng, 60)),
                        1 => lin(big(rng, 60), big(rng, 3)),
                        2 => Poly::new(vec![
                            -IBig::from(big(rng, 20).unsigned_abs()),
                            IBig::ZERO,
                            IBig::ONE,
                        ]),
                        _ => Poly::new(vec![big(rng, 30), big(rng, 30), big(rng, 5)]),
                    };
                    p = &p * &f;
                }
                p
            }
        }
    }

    /// The certified answer meets the postconditions and agrees with Descartes' path:
    /// the same number of roots, each certified interval holds exactly one root (signs at
    /// the ends and a Sturm count), and rational roots are exact in both when the leading
    /// coefficient has at most 64 bits.
    fn check_against_descartes(sf: &Poly, cert: &[RootInterval]) {
        let exact = isolate_squarefree_real_roots_descartes(sf);
        assert_eq!(cert.len(), exact.len(), "{sf}: {cert:?} vs {exact:?}");
        let sturm = SturmSequence::new(sf);
        for (c, e) in cert.iter().zip(&exact) {
            match c {
                RootInterval::Exact(v) => assert_eq!(sf.sign_at(v), Sign::Zero, "{sf}: {v}"),
                RootInterval::Open(lo, hi) => {
                    assert!(lo < hi);
                    assert!(
                        lo >= &RBig::ZERO || hi <= &RBig::ZERO,
                        "{sf}: {c:?} holds 0"
                    );
                    assert_eq!(
                        sf.sign_at(lo) * sf.sign_at(hi),
                        Sign::Negative,
                        "{sf}: {c:?}"
                    );
                    assert_eq!(sturm.count_roots_in(lo, hi), 1, "{sf}: {c:?}");
                }
            }
            if sf.leading().bit_len() <= 64 {
                assert_eq!(c.as_exact(), e.as_exact(), "{sf}: {c:?} vs {e:?}");
            }
        }
        for w in cert.windows(2) {
            assert!(
                w[0].hi() < w[1].lo()
                    || (w[0].hi() == w[1].lo()
                        && w[0].as_exact().is_none()
                        && w[1].as_exact().is_none()),
                "{sf}: {w:?}"
            );
        }
    }

    /// The narrow intervals isolate too, and each float enclosure holds its root: `p`
    /// changes sign (or vanishes) on `[center − radius, center + radius]`, inside the
    /// isolating interval.
    fn check_enclosures(sf: &Poly, cert: &[CertifiedRoot]) {
        let narrow: Vec<RootInterval> = cert.iter().map(|c| c.narrow.clone()).collect();
        check_against_descartes(sf, &narrow);
        for c in cert {
            if c.radius.is_finite() {
                let (m, r) = (
                    RBig::try_from(c.center).unwrap(),
                    RBig::try_from(c.radius).unwrap(),
                );
                let signs = sf.sign_at(&(&m - &r)) * sf.sign_at(&(&m + &r));
                assert_ne!(signs, Sign::Positive, "{sf}: {c:?}");
            }
        }
    }

    /// Ill-conditioned real roots: `∏(x − i) − c` (Wilkinson-like, degree up to 14), where
    /// the rounding term of the value bound is most of the disks' radii.
    #[test]
    fn ill_conditioned_roots_are_enclosed() {
        let mut rng = SplitMix(99);
        let mut certified = 0;
        for n in 4..=14 {
            for _ in 0..6 {
                let roots: Vec<i64> = (1..=n).collect();
                let c = Poly::constant(IBig::from(rng.int(1, 1 << 20)));
                let p = &Poly::from_roots(&roots) - &c;
                if let Some(cert) = certified_real_roots_enclosed(&p) {
                    check_enclosures(&p, &cert);
                    certified += 1;
                }
            }
        }
        assert!(certified >= 40, "{certified}");
    }

    #[test]
    fn certified_roots_agree_with_descartes_on_random_polynomials() {
        let mut rng = SplitMix(2026);
        let mut certified = [0usize; 4];
        let trials = 600u64;
        for t in 0..trials {
            let family = t % 4;
            let p = random_poly(&mut rng, family);
            let sf = p.squarefree_part();
            if let Some(cert) = certified_real_roots_enclosed(&sf) {
                check_enclosures(&sf, &cert);
                let cert: Vec<RootInterval> = cert.into_iter().map(|c| c.interval).collect();
                check_against_descartes(&sf, &cert);
                certified[family as usize] += 1;
            }
        }
        // the fast path answers for most generic inputs (not only the easy ones)
        let per = (trials / 4) as usize;
        assert!(certified[0] * 10 >= per * 9, "{certified:?}");
        assert!(certified[1] * 10 >= per * 9, "{certified:?}");
        assert!(certified[3] * 10 >= per * 6, "{certified:?}");
    }

    #[test]
    fn multiple_and_near_multiple_roots_are_not_certified() {
        let mut rng = SplitMix(7);
        for _ in 0..100 {
            let m = big(&mut rng, 30);
            let rest = random_poly(&mut rng, 0);
            // a double root: never square-free, never certified
            let lin = Poly::new(vec![-m.clone(), IBig::from(rng.int(1, 9))]);
            let double = &(&lin * &lin) * &rest;
            assert_eq!(certified_real_roots(&double), None, "{double}");
            // roots 2⁻⁶⁰ apart: beyond f64, so the certificate must fail
            let shift = IBig::ONE << 60;
            let pair = &Poly::new(vec![-m.clone(), shift.clone()])
                * &Poly::new(vec![-(m + IBig::ONE), shift]);
            let p = (&pair * &rest).squarefree_part();
            assert_eq!(certified_real_roots(&p), None, "{p}");
        }
    }

    /// Ferrari's seeds are the roots, polished in a few Newton steps, on biquadratic quartics
    /// `x⁴ + px² + r` (`q = 0`: the resolvent's only nonnegative root may be 0, where the
    /// general factorization divides by `√(2m)`), whatever the signs of `p`, `r` and `p² − 4r`,
    /// and on random general quartics; the roots are those of Aberth's iteration (another
    /// route). Taking the general branch at `q = 0` gives seeds the polish cannot fix.
    #[test]
    fn ferrari_seeds_biquadratic_and_general_quartics() {
        let mut rng = SplitMix(2024);
        let mut biquadratic = [0usize; 3];
        for t in 0..600 {
            let v = |rng: &mut SplitMix| rng.int(-50, 50) as f64 / 8.0;
            let c: [f64; 5] = if t % 2 == 0 {
                [v(&mut rng), 0.0, v(&mut rng), 0.0, 1.0]
            } else {
                std::array::from_fn(|i| if i == 4 { 1.0 } else { v(&mut rng) })
            };
            if c[0] == 0.0 {
                continue;
            }
            let mut z = ferrari(&c).expect("finite seeds");
            // the roots are simple unless the discriminant vanishes: then skip
            let mut reference = [Complex::ZERO; 4];
            aberth(&c, &mut reference).expect("Aberth converges");
            let close = |a: Complex, b: Complex| a.sub(b).abs() <= 1e-6 * (1.0 + b.abs());
            let apart = |a: Complex, b: Complex| a.sub(b).abs() > 1e-2 * (1.0 + b.abs());
            let simple = (0..4).all(|i| (0..i).all(|j| apart(reference[i], reference[j])));
            if !simple {
                continue;
            }
            assert!(polish(&c, &mut z), "{c:?}: seeds {z:?}");
            for w in &z {
                assert!(
                    reference.iter().any(|r| close(*w, *r)),
                    "{c:?}: {z:?} vs {reference:?}"
                );
            }
            for r in &reference {
                assert!(
                    z.iter().any(|w| close(*w, *r)),
                    "{c:?}: {z:?} vs {reference:?}"
                );
            }
            if t % 2 == 0 {
                let (p, r) = (c[2], c[0]);
                biquadratic[if r < 0.0 {
                    0
                } else if p * p < 4.0 * r {
                    1
                } else {
                    2
                }] += 1;
            }
        }
        // r < 0 (the resolvent's root 0), complex y², real y²
        assert!(biquadratic.iter().all(|&k| k >= 30), "{biquadratic:?}");
    }

    /// `c − r ≤ √d ≤ c + r`, exactly.
    fn holds_sqrt(c: f64, r: f64, d: i64) -> bool {
        let (c, r) = (RBig::try_from(c).unwrap(), RBig::try_from(r).unwrap());
        let d = RBig::from(d);
        let (lo, hi) = (&c - &r, &c + &r);
        (lo <= RBig::ZERO || &lo * &lo <= d) && hi >= RBig::ZERO && d <= &hi * &hi
    }

    /// The radii bound the distance to the roots: perturbed approximations of known roots
    /// (±√dᵢ), from far off to the nearest floats (where only the rounding term covers the
    /// error): every root lies in a disk, and disjoint disks hold one root each.
    #[test]
    fn disks_hold_the_roots_of_perturbed_approximations() {
        let mut rng = SplitMix(11);
        for t in 0..400 {
            let m = rng.int(1, 4) as usize;
            let mut ds: Vec<i64> = Vec::new();
            while ds.len() < m {
                let d = rng.int(2, 1 << 20);
                let r = (d as f64).sqrt() as i64;
                if r * r != d && !ds.contains(&d) {
                    ds.push(d);
                }
            }
            let p = ds.iter().fold(Poly::constant(IBig::ONE), |p, &d| {
                &p * &Poly::from_i64s(&[-d, 0, 1])
            });
            let s = scale(&p).unwrap();
            let unit = pow2(-s.k);
            let eps = [1e-1, 1e-4, 1e-9, 0.0][t % 4];
            let mut roots = Vec::new(); // (d, sign, approximation in scaled units)
            for &d in &ds {
                for sign in [1.0, -1.0] {
                    let exact = sign * (d as f64).sqrt() * unit;
                    let z = Complex {
                        re: exact * (1.0 + eps * (rng.int(-1000, 1000) as f64 / 1000.0)),
                        im: exact * eps * (rng.int(-1000, 1000) as f64 / 1000.0),
                    };
                    roots.push((d, sign, z));
                }
            }
            let z: Vec<Complex> = roots.iter().map(|r| r.2).collect();
            let mut r = vec![0.0; z.len()];
            let Some(()) = radii(&s, &z, &mut r) else {
                continue;
            };
            let disjoint = (0..z.len()).all(|i| {
                (i + 1..z.len()).all(|j| distance_lo(z[i], z[j]) > (r[i] + r[j]) * (1.0 + SLACK))
            });
            for &(d, sign, _) in &roots {
                // in units: the root is sign·√d·2⁻ᵏ; the disk holds it iff its real
                // section around sign·Re z does (checked exactly, real roots)
                let inside: Vec<usize> = (0..z.len())
                    .filter(|&i| {
                        let (c, ri) = (z[i].re * sign / unit, r[i] / unit);
                        let rr = (ri * ri - (z[i].im / unit).powi(2)).max(0.0);
                        // shrink the real section a little: a disk meets the axis in
                        // [c − √(r² − im²), c + √(r² − im²)]
                        rr > 0.0 && holds_sqrt(c, rr.sqrt() * (1.0 - 1e-9), d)
                    })
                    .collect();
                let near_miss = (0..z.len()).any(|i| {
                    let (c, ri) = (z[i].re * sign / unit, r[i] / unit);
                    let rr = (ri * ri - (z[i].im / unit).powi(2)).max(0.0);
                    holds_sqrt(c, rr.sqrt() * (1.0 + 1e-9) + 1e-300, d)
                });
                assert!(
                    !inside.is_empty() || near_miss,
                    "{p}: ±√{d} outside every disk, eps {eps}"
                );
                if disjoint {
                    assert!(inside.len() <= 1, "{p}: √{d} in two disjoint disks");
                }
            }
        }
    }

    /// The exact sign of `A(x) + √δ·B(x)` at a rational `x` (`δ` not a square).
    fn sign_zsqrt(a: &Poly, b: &Poly, delta: &IBig, x: &RBig) -> Sign {
        let eval = |p: &Poly| {
            p.coeffs()
                .iter()
                .rev()
                .fold(RBig::ZERO, |acc, c| acc * x + RBig::from(c.clone()))
        };
        let (va, vb) = (eval(a), eval(b));
        let (sa, sb) = (Sign::of_rational(&va), Sign::of_rational(&vb));
        if sb == Sign::Zero || sa == sb || sa == Sign::Zero {
            return if sb == Sign::Zero { sa } else { sb };
        }
        if &va * &va > &vb * &vb * RBig::from(delta.clone()) {
            sa
        } else {
            sb
        }
    }

    /// A random `s = A + B√δ` of degree 4: random coefficients of a few, 60 or 110 bits,
    /// or crafted hard ones — a rational root (a root of `s̄` too), a factor `(x − r)²`
    /// over ℤ[√δ], two roots `2⁻⁴⁰` apart, coefficients of very different sizes.
    fn random_s(rng: &mut SplitMix, family: u64) -> (Poly, Poly, IBig) {
        let squares = [4, 9, 16, 25, 49];
        let delta = loop {
            let d = rng.int(2, 5000);
            if !squares.contains(&d) && ((d as f64).sqrt() as i64).pow(2) != d {
                break IBig::from(d);
            }
        };
        let lin = |c: i64, l: i64| Poly::from_i64s(&[c, l]);
        let (a, b) = match family % 6 {
            0..=2 => {
                let bits = [6, 60, 110][(family % 6) as usize];
                let a = Poly::new((0..5).map(|_| big(rng, bits)).collect());
                let b = Poly::new((0..5).map(|_| big(rng, bits)).collect());
                (a, b)
            }
            3 => {
                // (x − r)·(A₁ + B₁√δ): r is a root of s and of s̄
                let r = rng.int(-20, 20);
                let a1 = Poly::new((0..4).map(|_| big(rng, 20)).collect());
                let b1 = Poly::new((0..4).map(|_| big(rng, 20)).collect());
                (&lin(-r, 1) * &a1, &lin(-r, 1) * &b1)
            }
            4 => {
                // (x − r)²·(c + √δ·(x² − e)) or two roots 2⁻⁴⁰ apart times the same
                let m = rng.int(1, 1 << 30);
                let (p, q) = if rng.int(0, 1) == 0 {
                    (lin(-m, 1 << 20), lin(-m, 1 << 20))
                } else {
                    (
                        lin(-m, 1 << 20),
                        Poly::new(vec![
                            IBig::from(-m) * IBig::from(1 << 20) - 1,
                            IBig::ONE << 40,
                        ]),
                    )
                };
                let pq = &p * &q;
                let c = big(rng, 8);
                let e = IBig::from(rng.int(1, 100));
                (
                    &pq * &Poly::new(vec![c, IBig::ZERO, IBig::ZERO]),
                    &pq * &Poly::new(vec![-e, IBig::ZERO, IBig::ONE]),
                )
            }
            _ => {
                // huge and tiny coefficients together
                let a = Poly::new((0..5).map(|i| big(rng, [3, 120, 5, 90, 2][i])).collect());
                let b = Poly::new((0..5).map(|i| big(rng, [100, 4, 70, 3, 126][i])).collect());
                (a, b)
            }
        };
        (a, b, delta)
    }

    /// The fast isolation of the real roots of `s = A + B√δ` against the exact one (Descartes
    /// on the square-free part of the norm `A² − δB²`, the roots of `s` picked by exact signs):
    /// the same roots, each interval isolating its root among the roots of the norm, the float
    /// enclosure holding it; and the certificate fails where it must (a root shared with `s̄`,
    /// a multiple root).
    #[test]
    fn zsqrt_roots_agree_with_the_exact_isolation() {
        let mut rng = SplitMix(4242);
        let mut answered = [0usize; 6];
        for t in 0..600u64 {
            let family = t % 6;
            let (a, b, delta) = random_s(&mut rng, family);
            let norm = &(&a * &a) - &(&(&b * &b) * &Poly::constant(delta.clone()));
            let n = a.degree().max(b.degree()).unwrap();
            let (ca, cb): (Vec<IBig>, Vec<IBig>) =
                (0..=n).map(|i| (a.coeff(i), b.coeff(i))).unzip();
            let ra: Vec<&IBig> = ca.iter().collect();
            let rb: Vec<&IBig> = cb.iter().collect();
            let Some(cert) = certified_real_roots_zsqrt(&ra, &rb, &delta) else {
                continue;
            };
            answered[family as usize] += 1;
            // Some proves the norm square-free (so s too, with no root shared with s̄)
            assert_eq!(
                norm.squarefree_part().degree(),
                norm.degree(),
                "{a} {b} {delta}"
            );
            let exact: Vec<RootInterval> = isolate_squarefree_real_roots_descartes(&norm)
                .into_iter()
                .filter(|iv| match iv {
                    RootInterval::Exact(v) => sign_zsqrt(&a, &b, &delta, v) == Sign::Zero,
                    RootInterval::Open(lo, hi) => {
                        sign_zsqrt(&a, &b, &delta, lo) != sign_zsqrt(&a, &b, &delta, hi)
                    }
                })
                .collect();
            assert_eq!(
                cert.len(),
                exact.len(),
                "{a} {b} {delta}: {cert:?} vs {exact:?}"
            );
            let sturm = SturmSequence::new(&norm);
            for c in &cert {
                let RootInterval::Open(lo, hi) = &c.interval else {
                    panic!("a rational root of {a} + {b}√{delta}: {c:?}");
                };
                assert!(lo < hi && (lo >= &RBig::ZERO || hi <= &RBig::ZERO), "{c:?}");
                assert_eq!(sturm.count_roots_in(lo, hi), 1, "{c:?}");
                let s = |x: &RBig| sign_zsqrt(&a, &b, &delta, x);
                assert_eq!(s(lo) * s(hi), Sign::Negative, "{c:?}");
                assert!(c.radius.is_finite(), "{c:?}");
                let (m, r) = (
                    RBig::try_from(c.center).unwrap(),
                    RBig::try_from(c.radius).unwrap(),
                );
                assert_ne!(s(&(&m - &r)) * s(&(&m + &r)), Sign::Positive, "{c:?}");
                assert!(
                    c.radius <= 1e-12 * c.center.abs(),
                    "a loose enclosure {c:?}"
                );
            }
            for w in cert.windows(2) {
                assert!(w[0].interval.hi() <= w[1].interval.lo(), "{w:?}");
            }
        }
        // generic inputs are answered, crafted multiple or shared roots never
        assert!(
            answered[0] >= 90 && answered[1] >= 90 && answered[2] >= 90,
            "{answered:?}"
        );
        assert_eq!(answered[3], 0, "{answered:?}");
        assert!(answered[5] >= 50, "{answered:?}");
        assert_eq!(answered[4], 0, "{answered:?}");
    }
}
