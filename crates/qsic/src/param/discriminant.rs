//! The real roots of Levin's `s(u)` over ℚ(√δ): Sturm chains, norms to ℚ, certified float
//! signs with the exact fallback, and the arcs where `s ≥ 0`.

use super::*;

/// The Sturm chain of `s` over ℚ(√δ): `s, s′, −rem, …`.
pub(super) fn sturm_chain(s: &Poly<Quadratic>) -> Vec<Poly<Quadratic>> {
    let mut chain = vec![s.clone(), s.derivative()];
    while let Some(last) = chain.last().filter(|p| !p.is_zero()) {
        let prev = &chain[chain.len() - 2];
        let r = prev.rem(last);
        if r.is_zero() {
            break;
        }
        chain.push(-&r);
    }
    chain.retain(|p| !p.is_zero());
    chain
}

pub(super) fn sign(x: &Quadratic) -> Sign {
    x.sign().expect("real field elements")
}

pub(super) fn variations(chain: &[Poly<Quadratic>], x: &RBig) -> usize {
    let signs: Vec<Sign> = chain
        .iter()
        .map(|p| sign(&p.eval(&q(x))))
        .filter(|s| *s != Sign::Zero)
        .collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}

/// The norm `Σ_{i+j=k} (aᵢaⱼ − δ·bᵢbⱼ)` of [`norm_of`] in checked `i128` when every
/// coefficient and `δ` fit an `i64`; `None` on an overflow (the caller uses big integers).
pub(super) fn norm_i128(z: &[zsqrt::Zq], delta: &IBig) -> Option<Poly> {
    let small = |v: &IBig| i64::try_from(v).ok().map(i128::from);
    let d = small(delta)?;
    let ab: Vec<(i128, i128)> = z
        .iter()
        .map(|c| Some((small(&c.a)?, small(&c.b)?)))
        .collect::<Option<_>>()?;
    let n = ab.len();
    let coeffs = (0..(2 * n).saturating_sub(1))
        .map(|k| {
            let (mut a, mut b) = (0i128, 0i128);
            for i in k.saturating_sub(n - 1)..=k.min(n - 1) {
                let j = k - i;
                // products of two i64 fit an i128; the sums are checked
                let (pa, pb) = (ab[i].0 * ab[j].0, ab[i].1 * ab[j].1);
                let twice = |v: i128| if i < j { v.checked_mul(2) } else { Some(v) };
                if i <= j {
                    a = a.checked_add(twice(pa)?)?;
                    b = b.checked_add(twice(pb)?)?;
                }
            }
            Some(IBig::from(a.checked_sub(b.checked_mul(d)?)?))
        })
        .collect::<Option<Vec<IBig>>>()?;
    Some(Poly::new(coeffs))
}

/// The norm `s·s̄ ∈ ℚ[u]` of `s` over ℚ(√δ) as an integer polynomial: `s_a² − δs_b²`
/// for `s = s_a + s_b√δ`, fraction-free when the coefficients are integral.
pub(super) fn norm_of(s: &Poly<Quadratic>) -> Poly {
    let delta = s
        .coeffs()
        .iter()
        .find(|c| c.as_rational().is_none())
        .map(|c| c.radicand().clone())
        .unwrap_or(IBig::ZERO);
    if let Some(z) = zsqrt::zpoly(s, &delta) {
        if let Some(norm) = norm_i128(&z, &delta) {
            return norm;
        }
        // Σ_{i+j=k} (aᵢaⱼ − δ·bᵢbⱼ): the rational part of s·s̄ only
        let n = z.len();
        let coeffs = (0..(2 * n).saturating_sub(1))
            .map(|k| {
                let (mut a, mut b) = (IBig::ZERO, IBig::ZERO);
                for i in k.saturating_sub(n - 1)..=k.min(n - 1) {
                    let j = k - i;
                    if i < j {
                        a += (&z[i].a * &z[j].a) << 1;
                        b += (&z[i].b * &z[j].b) << 1;
                    } else if i == j {
                        a += &z[i].a * &z[i].a;
                        b += &z[i].b * &z[i].b;
                    }
                }
                a - b * &delta
            })
            .collect();
        // not made primitive here: `real_roots_of` and `squarefree_part` do that
        return Poly::new(coeffs);
    }
    let norm: Vec<RBig> = (s * &s.map(Quadratic::conjugate))
        .coeffs()
        .iter()
        .map(|c| c.as_rational().cloned().expect("a norm is rational"))
        .collect();
    Poly::from_rational(&Poly::new(norm)).0
}

/// The sign of `s = A + B√δ` (integer coefficients `(aᵢ, bᵢ)` rounded to floats) at the
/// float `x`, if the float evaluation certifies it: Horner errs by at most
/// `(2n + 2)u·Σ|cᵢ||x|ⁱ` with the coefficients' rounding (the bound of
/// [`qsic_algebra::filter::sum_of_products_bound`], integer inputs so no underflow for
/// `|x| ≥ 2⁻⁴⁰⁰`), `√δ` errs by `2u` relatively, and the last product and sum by `u` each.
pub(super) fn certified_sign_zsqrt(a: &[f64], b: &[f64], sqrt_delta: f64, x: f64) -> Option<Sign> {
    if !(x == 0.0 || (x.abs() >= 2f64.powi(-400) && x.abs() <= 2f64.powi(400))) {
        return None;
    }
    let ax = x.abs();
    let horner = |c: &[f64]| {
        let (mut v, mut mag) = (0.0f64, 0.0f64);
        for &ci in c.iter().rev() {
            v = v * x + ci;
            mag = mag * ax + ci.abs();
        }
        let err = qsic_algebra::filter::sum_of_products_bound(c.len(), c.len(), mag);
        (v, err)
    };
    let (va, ea) = horner(a);
    let (vb, eb) = horner(b);
    let value = va + sqrt_delta * vb;
    let u = f64::EPSILON / 2.0;
    let bound = (ea
        + sqrt_delta * eb * (1.0 + 4.0 * u)
        + 4.0 * u * sqrt_delta * vb.abs()
        + 2.0 * u * value.abs())
        * (1.0 + 2f64.powi(-40));
    qsic_algebra::filter::certified_sign(value, bound)
}

/// `x` as a float if it is one exactly: a dyadic `m/2ᵏ` with `|m| < 2⁵³` and `k ≤ 1000`
/// (then `m` and `m·2⁻ᵏ`, normal, are exact in `f64`), without a rational round trip.
pub(super) fn exact_f64(x: &RBig) -> Option<f64> {
    use dashu_int::ops::{BitTest, PowerOfTwo};
    let den = x.denominator();
    if !den.is_power_of_two() {
        return None;
    }
    let k = den.bit_len() - 1;
    let m = i64::try_from(x.numerator()).ok()?;
    if k > 1000 || m.unsigned_abs() >= 1 << 53 {
        return None;
    }
    // 2⁻ᵏ from its bits (1023 − k is a biased exponent of a normal float)
    let scale = f64::from_bits(((1023 - k) as u64) << 52);
    Some(m as f64 * scale)
}

/// A rational strictly between the real roots isolated by `a` < `b` (disjoint intervals
/// whose open ends are not roots): an open end of one of them when it lies beyond the
/// other's root (a dyadic of few bits from the isolation), else [`rational_between`].
pub(super) fn sample_between(a: &RootInterval, b: &RootInterval) -> RBig {
    use RootInterval::{Exact, Open};
    match (a, b) {
        // root_a < hi_a ≤ lo_b < root_b
        (Open(_, h), Open(l, _)) if h <= l => h.clone(),
        // root_a < hi_a < v
        (Open(_, h), Exact(v)) if h < v => h.clone(),
        // v < lo_b < root_b
        (Exact(v), Open(l, _)) if v < l => l.clone(),
        _ => rational_between(a, b),
    }
}

/// The real roots of `s` over ℚ(√δ) (`s(0) ≠ 0`, not over ℚ) and whether `s` is
/// square-free: the roots of the norm `s·s̄` where `sign_at` (the sign of `s`, or of `s`
/// times a power of `u`) changes.
pub(super) fn nonzero_roots(
    s: &Poly<Quadratic>,
    delta: &IBig,
    sign_at: &dyn Fn(&RBig) -> Sign,
) -> (Vec<AlgebraicReal>, bool) {
    // s over ℤ[√δ]: the certificate on s and s̄ apart (degree 4 each, no root finding on
    // the norm, and the roots of s known without signs)
    if let Some(roots) = machine_roots(s, delta) {
        return (roots, true);
    }
    let norm = norm_of(s);
    // the certified float isolation proves the norm square-free when it answers
    // (then each root of s·s̄ is a simple root of exactly one of s, s̄)
    let of_s = |iv: &RootInterval| match iv {
        RootInterval::Exact(v) => sign_at(v) == Sign::Zero,
        RootInterval::Open(lo, hi) => sign_at(lo) != sign_at(hi),
    };
    if let Some(roots) = AlgebraicReal::certified_real_roots_where(&norm, of_s) {
        return (roots, true);
    }
    exact_roots_by_norm(s, &norm, sign_at)
}

/// The real roots of `s = A + B√δ` (`s(0) ≠ 0`, degree at most 4) by
/// [`AlgebraicReal::certified_real_roots_zsqrt`] when `s` is integral over ℤ[√δ] (its
/// integers read in place, not copied); `None` otherwise or if the certificate fails. `Some`
/// proves the norm, hence `s`, square-free.
pub(super) fn machine_roots(s: &Poly<Quadratic>, delta: &IBig) -> Option<Vec<AlgebraicReal>> {
    let c = s.coeffs();
    if c.len() > 5 || delta.is_zero() {
        return None;
    }
    let zero = IBig::ZERO;
    let (mut a, mut b) = ([&zero; 5], [&zero; 5]);
    for (i, x) in c.iter().enumerate() {
        if x.as_rational().is_none() && x.radicand() != delta {
            return None;
        }
        let (p, q) = (x.rational_part(), x.radical_part());
        if !(p.denominator().is_one() && q.denominator().is_one()) {
            return None;
        }
        (a[i], b[i]) = (p.numerator(), q.numerator());
    }
    AlgebraicReal::certified_real_roots_zsqrt(&a[..c.len()], &b[..c.len()], delta)
}

/// The real roots of `s` over ℚ(√δ) from the exact isolation of its norm `s·s̄` (any `s`
/// not over ℚ, also one with `s(0) = 0`), and whether `s` is square-free.
pub(super) fn exact_roots_by_norm(
    s: &Poly<Quadratic>,
    norm: &Poly,
    sign_at: &dyn Fn(&RBig) -> Sign,
) -> (Vec<AlgebraicReal>, bool) {
    let sf = norm.squarefree_part();
    // s divides its norm: a square-free norm makes s square-free (the common
    // case, without a gcd over ℚ(√δ))
    let squarefree =
        sf.degree() == norm.degree() || s.gcd_monic(&s.derivative()).degree() == Some(0);
    // each interval holds one root of s·s̄; a simple root of s there changes its
    // sign, and a square-free s has no other kind (else count by Sturm)
    let chain = (!squarefree).then(|| sturm_chain(s));
    let roots = isolate_squarefree_real_roots(&sf)
        .into_iter()
        .filter(|iv| match (iv, &chain) {
            (RootInterval::Exact(r), _) => sign_at(r) == Sign::Zero,
            (RootInterval::Open(lo, hi), None) => sign_at(lo) != sign_at(hi),
            (RootInterval::Open(lo, hi), Some(chain)) => {
                variations(chain, lo) > variations(chain, hi)
            }
        })
        .filter_map(|iv| AlgebraicReal::from_isolating_interval(&sf, &iv))
        .collect();
    (roots, squarefree)
}

/// The sign of `a + b√δ` (`δ > 0` not a square): from floats when the rounding cannot
/// change it (`a`, `b`, `δ` rounded with a relative error `u`, `√δ` then within `1.5u`,
/// the product within `u` more and the sum within `u`: below `2u|a| + 4.5u|b√δ|` to first
/// order, and the bound taken is `4u|a| + 20u|b√δ|`), else by `a² − δb²` exactly.
pub(super) fn zq_sign(c: &zsqrt::Zq, delta: &IBig) -> Sign {
    let (sa, sb) = (Sign::of(&c.a), Sign::of(&c.b));
    if sb == Sign::Zero || sa == sb || sa == Sign::Zero {
        return if sb == Sign::Zero { sa } else { sb };
    }
    let (a, p) = (
        c.a.to_f64().value(),
        delta.to_f64().value().sqrt() * c.b.to_f64().value(),
    );
    let bound = 2.0 * (a.abs() + 5.0 * p.abs()) * f64::EPSILON;
    if let Some(sg) = qsic_algebra::filter::certified_sign(a + p, bound) {
        return sg;
    }
    // opposite signs: |a| vs |b|√δ, never equal
    if &c.a * &c.a > &c.b * &c.b * delta {
        sa
    } else {
        sb
    }
}

/// The real roots of `s` (see [`DiscriminantRoots`]).
pub(super) fn discriminant_roots(s: &Poly<Quadratic>) -> DiscriminantRoots {
    // (collected only when every coefficient is rational: no clones on the common path)
    let rational: Option<Vec<RBig>> = if s.coeffs().iter().all(|c| c.as_rational().is_some()) {
        s.coeffs()
            .iter()
            .map(|c| c.as_rational().cloned())
            .collect()
    } else {
        None
    };
    // the exact sign of s at a rational: in integers when s is integral over ℤ[√δ]
    let delta = s
        .coeffs()
        .iter()
        .find(|c| c.as_rational().is_none())
        .map(|c| c.radicand().clone())
        .unwrap_or(IBig::ZERO);
    // s over ℤ[√δ] (made when first needed: the certified roots read s in place)
    let integral = std::cell::OnceCell::new();
    let integral = || integral.get_or_init(|| zsqrt::zpoly(s, &delta));
    // floats of the coefficients and of √δ for the certified float signs (made when a
    // sign is first asked for)
    let floats = std::cell::OnceCell::new();
    let sign_at = |x: &RBig| match integral() {
        Some(z) => {
            let (a, b, r) = floats.get_or_init(|| {
                let f = |v: &IBig| v.to_f64().value();
                let a: Vec<f64> = z.iter().map(|c| f(&c.a)).collect();
                let b: Vec<f64> = z.iter().map(|c| f(&c.b)).collect();
                (a, b, f(&delta).sqrt())
            });
            exact_f64(x)
                .and_then(|xf| certified_sign_zsqrt(a, b, *r, xf))
                .unwrap_or_else(|| zsqrt::sign_at(z, x, &delta))
        }
        None => sign(&s.eval(&q(x))),
    };
    let (roots, squarefree) = match rational {
        Some(c) => {
            let p = Poly::from_rational(&Poly::new(c)).0;
            // the certified float isolation proves p square-free when it answers
            match AlgebraicReal::certified_real_roots_of(&p) {
                Some(roots) => (roots, true),
                None => {
                    let squarefree = p.squarefree_part().degree() == p.degree();
                    (AlgebraicReal::real_roots_of(&p), squarefree)
                }
            }
        }
        None => {
            // s = uᵏ·s₁ with s₁(0) ≠ 0: the root 0 apart, so that the norm of s₁ is
            // square-free in the generic case (that of s has the double root 0)
            let k = s
                .coeffs()
                .iter()
                .take_while(|c| c.as_rational().is_some_and(|v| v.is_zero()))
                .count();
            let (mut roots, squarefree) = if k > 0 {
                nonzero_roots(&s.shift_down(k), &delta, &sign_at)
            } else {
                nonzero_roots(s, &delta, &sign_at)
            };
            if k > 0 {
                let at = roots.partition_point(|r| r.interval().hi() <= &RBig::ZERO);
                roots.insert(at, AlgebraicReal::from_rational(RBig::ZERO));
            }
            (roots, squarefree && k <= 1)
        }
    };
    let mut samples = Vec::new();
    match (roots.first(), roots.last()) {
        (Some(first), Some(last)) => {
            samples.push(RBig::from(first.interval().lo().floor() - IBig::ONE));
            // the stated intervals come from one isolation of the norm: disjoint, short ends
            for w in roots.windows(2) {
                samples.push(sample_between(w[0].interval(), w[1].interval()));
            }
            samples.push(RBig::from(last.interval().hi().ceil() + IBig::ONE));
        }
        _ => samples.push(RBig::ZERO),
    }
    // a square-free s changes sign at each of its real roots, and has the sign of its
    // leading coefficient beyond the last: no evaluation
    let lead = match (squarefree, s.coeffs().last()) {
        (true, Some(c)) => Some(match zsqrt::Zq::from_quadratic(c, &delta) {
            Some(z) => zq_sign(&z, &delta),
            None => sign(c),
        }),
        _ => None,
    };
    let count = samples.len();
    let arcs = samples
        .into_iter()
        .enumerate()
        .map(|(i, x)| {
            let sg = match lead {
                // count − 1 − i roots lie beyond the i-th sample
                Some(l) if (count - 1 - i) % 2 == 0 => l,
                Some(l) => -l,
                None => sign_at(&x),
            };
            (x, sg)
        })
        .collect();
    DiscriminantRoots {
        roots,
        at_infinity: s.degree().unwrap_or(0) < 4,
        squarefree,
        arcs,
    }
}
