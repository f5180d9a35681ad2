//! The curve of a nonsingular quartic (cases 1–4) by Levin's method: the chosen surface's
//! ruling substituted into a second member gives `s`, `a`, `d` over ℤ[√δ] (machine integers
//! first, big integers when a number leaves them), balanced in `u`, and the real pieces
//! between the real roots of `s` (Theorem 12).

use super::choose::{choose_surface, choose_surface_quick, Chosen};
use super::discriminant::discriminant_roots;
use super::*;

/// [`LevinParameterization::real_components`] of an `s` of degree `deg` with the real roots
/// `dr` (`s` itself only for the messages).
pub(super) fn real_components(
    deg: usize,
    dr: &DiscriminantRoots,
    s: impl Fn() -> Poly<Quadratic>,
) -> Result<u8, Error> {
    if deg < 3 || !dr.squarefree {
        return Err(Error::Algebra(format!(
            "s(u) = {} has a multiple root",
            s()
        )));
    }
    let n = dr.roots.len() + usize::from(dr.at_infinity);
    theorem_12(n, dr.arcs[0].1).ok_or_else(|| {
        Error::Algebra(format!(
            "s(u) = {} has {n} real roots on the projective line",
            s()
        ))
    })
}

/// Theorem 12: the real components of a nonsingular quartic from the number of simple real
/// roots of `s` on ℝ ∪ {∞} (four — two, two — one, none — two or none by the sign of `s`
/// everywhere); `None` for any other number.
pub(super) fn theorem_12(real_roots: usize, everywhere: Sign) -> Option<u8> {
    match real_roots {
        4 => Some(2),
        2 => Some(1),
        0 => Some(if everywhere == Sign::Positive { 2 } else { 0 }),
        _ => None,
    }
}

/// Levin's parameterization of the intersection of `a` and `b` when it is a nonsingular
/// quartic (cases 1–4: `det(λA − B)` has four simple roots), with a rational real ruled
/// surface: a member of inertia (2, 2) at a rational λ of its arc, or a cone at a rational
/// root. Candidates in order: the pencil analysis' sample of each (2, 2) arc, cones at
/// rational roots (the first with rational rulings wins, else the least radicand; members
/// with a small rational point first, their radicand the square-free part of `det S`), then,
/// only if none of these has a small point, or real rulings over ℚ or a quadratic field,
/// more small-height rationals of the (2, 2) arcs.
///
/// # Errors
/// [`Error::Unsupported`] for other classes, when the only real ruled members are cones at
/// irrational roots, or when every candidate's rulings need a biquadratic field (not yet
/// implemented); [`Error::Algebra`] when a conic's rational point cannot be found within the
/// factoring bounds.
///
/// # Examples
/// ```
/// use qsic::{io::parse_quadric, param::parameterize_smooth_quartic};
/// // a sphere and an ellipsoidal cylinder: two closed components
/// let a = parse_quadric("x^2+y^2+z^2-w^2").unwrap();
/// let b = parse_quadric("2*x^2+4*y^2-w^2").unwrap();
/// let p = parameterize_smooth_quartic(&a, &b).unwrap();
/// assert_eq!(p.real_components().unwrap(), 2);
/// ```
pub fn parameterize_smooth_quartic(
    a: &Quadric,
    b: &Quadric,
) -> Result<LevinParameterization, Error> {
    let (classification, sums) = classify_keeping_sums(a, b);
    let simple = matches!(classification.case, Some(1..=4));
    smooth_quartic(a, b, true, simple, sums.as_ref()).map(SmoothQuartic::into_levin)
}

/// What [`smooth_quartic`] finds before any conversion to the output types: the surface,
/// the real roots of `s` and the forms, converted by [`SmoothQuartic::into_levin`] or
/// straight into the curve's numbers by [`levin_curve`] (which needs neither `b`, `d` nor
/// `a` over ℚ(√δ)).
#[derive(Clone)]
pub(super) struct SmoothQuartic {
    /// The surface; for [`Forms::Integral`] with the ruling as chosen (the forms hold the
    /// reduced and balanced one), its `b` and `d` empty when the ruling was computed in
    /// machine integers, and its matrix zero when `member` holds it (both filled by
    /// [`Self::into_levin`]).
    pub(super) surface: ParameterizationSurface,
    /// `(d·S, d)` in machine integers when the surface's matrix `S` is left to
    /// [`Self::into_levin`] ([`surface::small_member`]).
    pub(super) member: Option<([[i128; 4]; 4], i128)>,
    pub(super) substituted: Substituted,
    pub(super) discriminant: DiscriminantRoots,
    pub(super) forms: Forms,
}

/// The forms of a [`SmoothQuartic`].
// One value per curve, moved twice: boxing the integral forms would only add an allocation.
#[allow(clippy::large_enum_variant)]
#[derive(Clone)]
pub(super) enum Forms {
    /// Over ℤ[√δ] (the common case).
    Integral(IntegralLevin),
    /// Over ℚ(√δ) (the rational route), with the final ruling in the surface.
    Rational { a: PolyVector, s: Poly<Quadratic> },
}

impl SmoothQuartic {
    /// The exact `s` (for messages and [`Self::into_levin`]).
    pub(super) fn exact_s(&self) -> Poly<Quadratic> {
        match &self.forms {
            Forms::Integral(f) => {
                let (db, dd) = ruling_degrees(self.surface.kind);
                zsqrt::to_poly_down(&f.s, &f.delta, f.down * 2 * (db + dd))
            }
            Forms::Rational { s, .. } => s.clone(),
        }
    }

    /// Theorem 12 ([`LevinParameterization::real_components`]).
    pub(super) fn real_components(&self) -> Result<u8, Error> {
        let deg = match &self.forms {
            // trimmed: the degree of s (a power of two divides it for `down`)
            Forms::Integral(f) => f.s.len().saturating_sub(1),
            Forms::Rational { s, .. } => s.degree().unwrap_or(0),
        };
        real_components(deg, &self.discriminant, || self.exact_s())
    }

    /// The public parameterization: the integral forms divided by their power of two and
    /// converted to ℚ(√δ).
    pub(super) fn into_levin(self) -> LevinParameterization {
        let s = self.exact_s();
        let SmoothQuartic {
            mut surface,
            member,
            substituted,
            discriminant,
            forms,
        } = self;
        if let Some((m, den)) = member {
            surface.matrix = surface::member_from_small(&m, den);
        }
        let a = match forms {
            Forms::Integral(mut f) => {
                f.materialize();
                let (db, dd) = ruling_degrees(surface.kind);
                let down = |p: &zsqrt::ZPoly, degree: usize| {
                    zsqrt::to_poly_down(p, &f.delta, f.down * degree)
                };
                surface.ruling.b = std::array::from_fn(|i| down(&f.b[i], db));
                surface.ruling.d = std::array::from_fn(|i| down(&f.d[i], dd));
                std::array::from_fn(|i| down(&f.a[i], 2 * dd + db))
            }
            Forms::Rational { a, .. } => a,
        };
        LevinParameterization {
            delta: surface.ruling.delta.clone(),
            substituted,
            a,
            d: surface.ruling.d.clone(),
            s,
            discriminant,
            surface,
        }
    }
}

/// The forms of a Levin parameterization over ℤ[√δ] (`δ = 0` over ℚ), after the balancing
/// substitution: `b`, `d` the ruling, `a = c₂b − c₁d`, `alt = c₁b − c₀d`, `s = c₁² − c₀c₂`.
/// Kept by [`smooth_quartic`] for [`levin_curve`]: its conversions then need no rational gcd.
#[derive(Clone)]
pub(super) struct IntegralLevin {
    pub(super) delta: IBig,
    /// `m = −k` for a balancing `k < 0`, else 0: the forms held are those of `u ↦ 2ᵏu`
    /// times `2^(m·degree)` (integral); the exact form is each divided by that power.
    pub(super) down: usize,
    pub(super) b: [zsqrt::ZPoly; 4],
    pub(super) d: [zsqrt::ZPoly; 4],
    pub(super) a: [zsqrt::ZPoly; 4],
    pub(super) alt: [zsqrt::ZPoly; 4],
    pub(super) s: zsqrt::ZPoly,
    /// The forms in machine integers when they fit (the common case): then `b`, `d`, `a`,
    /// `alt` are empty until [`IntegralLevin::materialize`], and `levin_curve` converts
    /// straight from these.
    pub(super) fixed: Option<zsqrt::FixedLevin>,
}

impl IntegralLevin {
    /// `b`, `d`, `a`, `alt` in big integers from the fixed forms, if not there yet.
    pub(super) fn materialize(&mut self) {
        if let Some(f) = self.fixed.take() {
            let (b, d, a, alt, _) = f.into_zpolys();
            (self.b, self.d, self.a, self.alt) = (b, d, a, alt);
        }
    }
}

/// [`parameterize_smooth_quartic`] before the conversions, with the integral forms when the
/// ruling is integral (the common case); `fast = false` takes the rational route (the tests
/// compare the two). `simple`: the class says four simple roots of `det(λA − B)`, so the
/// surface may come from [`choose_surface_quick`]; `sums`: `E₁…E₄` of the pencil if the
/// classification computed them.
pub(super) fn smooth_quartic(
    a: &Quadric,
    b: &Quadric,
    fast: bool,
    simple: bool,
    sums: Option<&[[i128; 5]; 4]>,
) -> Result<SmoothQuartic, Error> {
    // the pencil analysis works on the primitive integer matrices: so does λ
    let quick = if simple {
        choose_surface_quick(a, b, sums)?
    } else {
        None
    };
    let Chosen {
        mut surface,
        fixed,
        member,
    } = match quick {
        Some(chosen) => chosen,
        None => {
            let analysis = analyze_pencil(a, b)
                .ok_or_else(|| Error::Unsupported("a singular or single pencil".into()))?;
            let simple = analysis.real_roots.iter().all(|r| r.multiplicity == 1)
                && analysis.complex_roots.iter().all(|blocks| blocks == &[1])
                && analysis.real_roots.len() + analysis.complex_roots.len() == 4;
            if !simple {
                return Err(Error::Unsupported(
                    "only nonsingular quartics (four simple roots of det(λA − B)) so far".into(),
                ));
            }
            choose_surface(&integer_matrix(a), &integer_matrix(b), &analysis)?
        }
    };
    if !fast {
        if let Some(r) = &fixed {
            surface.ruling = (*r).into();
        }
    }
    let (qm, substituted) = match surface.lambda {
        Some(_) => (a, Substituted::A),
        None => (b, Substituted::B),
    };
    let integral = if fast {
        integral_levin(qm, &surface.ruling, fixed.as_ref(), surface.kind)?
    } else {
        None
    };
    if let Some(fast) = integral {
        // the integral s: a positive multiple of `s` (same roots and signs)
        let discriminant = discriminant_roots(&zsqrt::to_poly(&fast.s, &fast.delta));
        return Ok(SmoothQuartic {
            surface,
            member,
            substituted,
            discriminant,
            forms: Forms::Integral(fast),
        });
    }
    // the reduction `integral_levin` makes on its integers, here on the rational ruling
    if surface.kind == SurfaceKind::DoublyRuled {
        reduce_doubly_ruled(&mut surface.ruling);
    }
    let qm = to_quadratic(&integer_matrix(qm));
    let forms = |b: &PolyVector, d: &PolyVector| {
        let c2 = poly_form(&qm, d, d);
        let c1 = poly_form(&qm, b, d);
        let c0 = poly_form(&qm, b, b);
        let s = &(&c1 * &c1) - &(&c0 * &c2);
        (c1, c2, s)
    };
    let (mut c1, mut c2, mut s) = forms(&surface.ruling.b, &surface.ruling.d);
    if s.is_zero() {
        return Err(Error::Algebra("s(u) vanishes identically".into()));
    }
    // u ↦ 2ᵏu in the ruling, with the extreme coefficients of s of one size: the real roots
    // of s (the arc ends) near 1 in size, which the floats of `sample` need (a substitution:
    // every identity holds as it is)
    let k = balancing_exponent(&s);
    if k != 0 {
        let scaled = |p: &Poly<Quadratic>, degree: usize| -> Poly<Quadratic> {
            Poly::new(
                p.coeffs()
                    .iter()
                    .enumerate()
                    .map(|(i, c)| {
                        let e = if integral_balancing(k) {
                            balance_exponent(k, degree, i) as i64
                        } else {
                            k * i as i64
                        };
                        c.scale(&expr::power_of_two(e))
                    })
                    .collect(),
            )
        };
        let (db, dd) = ruling_degrees(surface.kind);
        surface.ruling.b = std::array::from_fn(|i| scaled(&surface.ruling.b[i], db));
        surface.ruling.d = std::array::from_fn(|i| scaled(&surface.ruling.d[i], dd));
        (c1, c2, s) = forms(&surface.ruling.b, &surface.ruling.d);
    }
    let (bv, dv) = (&surface.ruling.b, &surface.ruling.d);
    let av: PolyVector = std::array::from_fn(|i| &(&c2 * &bv[i]) - &(&c1 * &dv[i]));
    let discriminant = discriminant_roots(&s);
    if let Some((m, den)) = member {
        surface.matrix = surface::member_from_small(&m, den);
    }
    Ok(SmoothQuartic {
        surface,
        member: None,
        substituted,
        discriminant,
        forms: Forms::Rational { a: av, s },
    })
}

/// The ruling's `δ` (0 over ℚ), `b` and `d` over ℤ[√δ]; `None` when a coefficient is not
/// integral.
pub(super) fn integral_ruling(
    ruling: &RuledParameterization,
) -> Option<(IBig, [zsqrt::ZPoly; 4], [zsqrt::ZPoly; 4])> {
    let delta = ruling.delta.clone().unwrap_or(IBig::ZERO);
    let (b, d) = (
        zsqrt::zvector(&ruling.b, &delta)?,
        zsqrt::zvector(&ruling.d, &delta)?,
    );
    Some((delta, b, d))
}

/// The ruling of a doubly ruled surface with small integers ([`zsqrt::reduce_ruling`]: the
/// same surface and lines, another parameterization of them); left as it is when a
/// coefficient is not integral over ℤ[√δ].
pub(super) fn reduce_doubly_ruled(ruling: &mut RuledParameterization) {
    let Some((delta, mut b, mut d)) = integral_ruling(ruling) else {
        return;
    };
    if zsqrt::reduce_ruling(&mut b, &mut d) {
        ruling.b = std::array::from_fn(|i| zsqrt::to_poly(&b[i], &delta));
        ruling.d = std::array::from_fn(|i| zsqrt::to_poly(&d[i], &delta));
    }
}

/// The forms of [`smooth_quartic`] over ℤ[√δ] on the integer matrix `qm` of the substituted
/// quadric, on the ruling reduced first ([`zsqrt::reduce_ruling`]): `c₀ = bᵀQb`,
/// `c₁ = bᵀQd`, `c₂ = dᵀQd`, `s`, `a`, `alt`, then the balancing as a substitution in every
/// form ([`balance_exponent`]: a form of the substituted ruling is the substituted form, the
/// substitution being a ring map); for `k < 0` integral forms times `2^(−k·degree)`,
/// divided out by the conversions when large (`down`). `Ok(None)` when the ruling is not
/// integral (the rational route then).
///
/// # Errors
/// [`Error::Algebra`] if `s ≡ 0`.
pub(super) fn integral_levin(
    qm: &Quadric,
    ruling: &RuledParameterization,
    fixed: Option<&zsqrt::FixedRuling>,
    kind: SurfaceKind,
) -> Result<Option<IntegralLevin>, Error> {
    // the common case: the ruling in machine integers from the point to the forms
    let from_fixed = match fixed {
        Some(r) => {
            let mut r = *r;
            r.reduce();
            if let Some(forms) = small_matrix(qm).and_then(|m| zsqrt::FixedLevin::new(&m, &r)) {
                return fixed_levin(forms).map(Some);
            }
            let (b, d) = r.to_zpolys();
            Some((IBig::from(r.delta), b, d))
        }
        None => None,
    };
    // else the reduced ruling straight from the rational one
    let direct = match (from_fixed, kind, &ruling.delta) {
        (Some(r), _, _) => Some(r),
        (None, SurfaceKind::DoublyRuled, delta) => {
            let delta = delta.clone().unwrap_or(IBig::ZERO);
            zsqrt::reduced_ruling(&ruling.b, &ruling.d, &delta).map(|(b, d)| (delta, b, d))
        }
        _ => None,
    };
    let (delta, mut b, mut d) = match direct {
        Some(ruling) => ruling,
        None => {
            let Some((delta, mut b, mut d)) = integral_ruling(ruling) else {
                return Ok(None);
            };
            if kind == SurfaceKind::DoublyRuled {
                zsqrt::reduce_ruling(&mut b, &mut d);
            }
            (delta, b, d)
        }
    };
    let qm = qm.integer_matrix().entries();
    // in machine integers when everything fits, else in big integers
    let (mut s, mut a, mut alt) = zsqrt::levin_small(qm, &b, &d, &delta)
        .unwrap_or_else(|| zsqrt::levin_big(qm, &b, &d, &delta));
    for p in b.iter_mut().chain(&mut d).chain(&mut a).chain(&mut alt) {
        zsqrt::trim(p);
    }
    zsqrt::trim(&mut s);
    if s.is_empty() {
        return Err(Error::Algebra("s(u) vanishes identically".into()));
    }
    let k = balancing_exponent_of(&zsqrt::log2_sizes(&s, &delta));
    if k != 0 {
        balance_big(k, kind, [&mut b, &mut d, &mut a, &mut alt], &mut s);
    }
    Ok(Some(IntegralLevin {
        delta,
        down: if integral_balancing(k) {
            0
        } else {
            k.unsigned_abs() as usize
        },
        b,
        d,
        a,
        alt,
        s,
        fixed: None,
    }))
}

/// The primitive integer matrix of `q` in `i128` (`None` past it).
pub(super) fn small_matrix(q: &Quadric) -> Option<[[i128; 4]; 4]> {
    if let Some(m) = q.small_integer_matrix() {
        return Some(m.map(|row| row.map(i128::from)));
    }
    let m = q.integer_matrix().entries();
    let mut out = [[0i128; 4]; 4];
    for (row, src) in out.iter_mut().zip(m) {
        for (x, v) in row.iter_mut().zip(src) {
            *x = i128::try_from(v).ok()?;
        }
    }
    Some(out)
}

/// [`integral_levin`] from the forms of a fixed ruling (doubly ruled): the balancing in
/// machine integers when it fits, else on the big integers.
///
/// # Errors
/// [`Error::Algebra`] if `s ≡ 0`.
pub(super) fn fixed_levin(mut forms: zsqrt::FixedLevin) -> Result<IntegralLevin, Error> {
    if forms.s_is_zero() {
        return Err(Error::Algebra("s(u) vanishes identically".into()));
    }
    let k = balancing_exponent_of(&forms.s_log2_sizes());
    let shifted = k == 0 || forms.shift(|degree, i| balance_exponent(k, degree, i));
    let delta = IBig::from(forms.delta);
    let down = if integral_balancing(k) {
        0
    } else {
        k.unsigned_abs() as usize
    };
    if shifted {
        // the forms stay in machine integers until the output asks for them
        return Ok(IntegralLevin {
            delta,
            down,
            b: Default::default(),
            d: Default::default(),
            a: Default::default(),
            alt: Default::default(),
            s: forms.s_zpoly(),
            fixed: Some(forms),
        });
    }
    let (mut b, mut d, mut a, mut alt, mut s) = forms.into_zpolys();
    balance_big(
        k,
        SurfaceKind::DoublyRuled,
        [&mut b, &mut d, &mut a, &mut alt],
        &mut s,
    );
    Ok(IntegralLevin {
        delta,
        down,
        b,
        d,
        a,
        alt,
        s,
        fixed: None,
    })
}

/// The balancing `k` ([`balance_exponent`]) on the big-integer forms `[b, d, a, alt]` and
/// `s` of a ruling of `kind`.
pub(super) fn balance_big(
    k: i64,
    kind: SurfaceKind,
    [b, d, a, alt]: [&mut [zsqrt::ZPoly; 4]; 4],
    s: &mut zsqrt::ZPoly,
) {
    let (db, dd) = ruling_degrees(kind);
    let forms = [(b, db), (d, dd), (a, 2 * dd + db), (alt, 2 * db + dd)];
    for (v, degree) in forms {
        for p in v.iter_mut() {
            zsqrt::scale_powers_of_two(p, |i| balance_exponent(k, degree, i));
        }
    }
    zsqrt::scale_powers_of_two(s, |i| balance_exponent(k, 2 * (db + dd), i));
}

/// Whether the balancing `k` keeps the forms as integers, multiplied by `2^(−k·degree)`
/// for `k < 0` ([`balance_exponent`]): when that factor is at most `2¹²⁸` on `s` (degree
/// 4), else they are divided by it (rational, as for `k ≥ 0` without the factor), so that
/// large balancings do not grow the numbers further.
pub(super) fn integral_balancing(k: i64) -> bool {
    k >= 0 || -4 * k <= 128
}

/// The homogeneous degrees in `u` of a ruling's `b` and `d`: lines of a regulus (1, 1), the
/// vertex and a conic of a cone (0, 2).
pub(super) fn ruling_degrees(kind: SurfaceKind) -> (usize, usize) {
    match kind {
        SurfaceKind::DoublyRuled => (1, 1),
        SurfaceKind::Cone => (0, 2),
    }
}

/// The power of two that multiplies coefficient `i` of a form of homogeneous degree
/// `degree` under the balancing `k`: `u ↦ 2ᵏu` for `k ≥ 0` (`2^(k·i)`), and for `k < 0`
/// the same substitution times `2^(−k·degree)`, which keeps integers integral
/// (`2^(−k·(degree − i))`; a constant factor of a homogeneous form, so the projective
/// points, the identities and the sheets stay).
pub(super) fn balance_exponent(k: i64, degree: usize, i: usize) -> usize {
    let m = k.unsigned_abs() as usize;
    if k >= 0 {
        m * i
    } else {
        debug_assert!(
            i <= degree,
            "coefficient {i} of a form of degree {degree} (k = {k})"
        );
        m * degree.saturating_sub(i)
    }
}

/// The `k` for which `u ↦ 2ᵏu` brings the lowest and highest nonzero coefficients of `s` to
/// one size (`|s_lo|·2^(k·lo) ≈ |s_hi|·2^(k·hi)`); 0 when they are within `2⁸` per degree.
pub(super) fn balancing_exponent(s: &Poly<Quadratic>) -> i64 {
    let sizes: Vec<f64> = s.coeffs().iter().map(log2_size).collect();
    balancing_exponent_of(&sizes)
}

/// `log₂|c|` (`−∞` for zero): from the float where it is finite, else from bit lengths
/// (`|a + b√δ| ≤ 2·max(|a|, |b|√δ)`; a coefficient beyond the floats is not cancelled to
/// any size that matters here).
pub(super) fn log2_size(c: &Quadratic) -> f64 {
    use dashu_int::ops::BitTest;
    if qsic_algebra::Ring::is_zero(c) {
        return f64::NEG_INFINITY;
    }
    let v = c.to_f64().abs();
    if v.is_finite() && v > 0.0 {
        return v.log2();
    }
    let bits = |r: &RBig| {
        if r.is_zero() {
            f64::NEG_INFINITY
        } else {
            r.numerator().bit_len() as f64 - r.denominator().bit_len() as f64
        }
    };
    let root = if c.as_rational().is_some() {
        0.0
    } else {
        c.radicand().bit_len() as f64 / 2.0
    };
    bits(c.rational_part()).max(bits(c.radical_part()) + root) + 1.0
}

/// [`balancing_exponent`] from the coefficients' `log₂` sizes (`−∞` for a zero coefficient;
/// 0 if a size is NaN, unknown).
pub(super) fn balancing_exponent_of(log2_sizes: &[f64]) -> i64 {
    if log2_sizes.iter().any(|v| v.is_nan()) {
        return 0;
    }
    let sizes: Vec<(usize, f64)> = log2_sizes
        .iter()
        .enumerate()
        .filter(|(_, c)| c.is_finite())
        .map(|(i, c)| (i, *c))
        .collect();
    let (Some(&(lo, slo)), Some(&(hi, shi))) = (sizes.first(), sizes.last()) else {
        return 0;
    };
    if hi == lo {
        return 0;
    }
    let k = ((slo - shi) / (hi - lo) as f64).round();
    if k.abs() <= 8.0 {
        0
    } else {
        k as i64
    }
}

/// The [`Curve`] of a nonsingular quartic from its Levin parameterization: one component,
/// and one closed real piece per positive arc of `s` between consecutive real roots on
/// ℝ ∪ {∞} (the sheets `+` and `−` joined at the roots), two pieces (the two sheets) when
/// `s > 0` everywhere; the pieces are disjoint (a nonsingular curve).
#[inline(never)] // one call a curve; kept apart for the profiles
pub(super) fn levin_curve(
    classification: Classification,
    quartic: SmoothQuartic,
    a_quadric: &Quadric,
    b_quadric: &Quadric,
) -> Result<Curve, Error> {
    let n = quartic.real_components()?;
    let kind = quartic.surface.kind;
    // homogeneous degree of a: 3 on a doubly ruled surface (b, d lines), 4 on a cone
    let degree = match kind {
        SurfaceKind::DoublyRuled => 3,
        SurfaceKind::Cone => 4,
    };
    // c₁·b: (2 + 1) on a doubly ruled surface, (2 + 0) on a cone
    let alt_degree = match kind {
        SurfaceKind::DoublyRuled => 3,
        SurfaceKind::Cone => 2,
    };
    let SmoothQuartic {
        surface,
        substituted,
        discriminant: dr,
        forms,
        ..
    } = quartic;
    let field = surface.ruling.delta.as_ref().map(curve::sqrt_field);
    let (a, d, s, alternate) = match forms {
        Forms::Integral(f) if f.down == 0 && f.fixed.is_some() => {
            drop(surface);
            let fixed = f.fixed.expect("the fixed forms");
            let [a, d, alt, b] = fixed.to_number_polys(field.as_ref());
            let alternate = LevinForm {
                a: alt,
                d: b,
                degree: alt_degree,
            };
            (a, d, zsqrt::to_number_poly(f.s, field.as_ref()), alternate)
        }
        Forms::Integral(mut f) => {
            // freed before the conversions allocate (its blocks are reused)
            drop(surface);
            f.materialize();
            let (db, dd) = ruling_degrees(kind);
            let convert = |p: zsqrt::ZPoly, degree: usize| -> NumberPoly {
                if f.down == 0 {
                    zsqrt::to_number_poly(p, field.as_ref())
                } else {
                    let down = zsqrt::to_poly_down(&p, &f.delta, f.down * degree);
                    curve::poly_from_quadratic(&down, field.as_ref())
                }
            };
            let vector = |v: [zsqrt::ZPoly; 4], degree: usize| -> PointPoly {
                v.map(|p| convert(p, degree))
            };
            let alternate = LevinForm {
                a: vector(f.alt, 2 * db + dd),
                d: vector(f.b, db),
                degree: alt_degree,
            };
            (
                vector(f.a, 2 * dd + db),
                vector(f.d, dd),
                convert(f.s, 2 * (db + dd)),
                alternate,
            )
        }
        Forms::Rational { a, s } => {
            let vector = |v: &PolyVector| -> PointPoly {
                std::array::from_fn(|i| curve::poly_from_quadratic(&v[i], field.as_ref()))
            };
            // the alternate form: v = −c₀/(c₁ ± √s) gives (c₁ ± √s)·b − c₀·d on the same sheet
            let qm = to_quadratic(&match substituted {
                Substituted::A => integer_matrix(a_quadric),
                Substituted::B => integer_matrix(b_quadric),
            });
            let (rb, rd) = (&surface.ruling.b, &surface.ruling.d);
            let (c0, c1) = (poly_form(&qm, rb, rb), poly_form(&qm, rb, rd));
            let alt_a: PolyVector = std::array::from_fn(|i| &(&c1 * &rb[i]) - &(&c0 * &rd[i]));
            let alternate = LevinForm {
                a: vector(&alt_a),
                d: vector(rb),
                degree: alt_degree,
            };
            (
                vector(&a),
                vector(rd),
                curve::poly_from_quadratic(&s, field.as_ref()),
                alternate,
            )
        }
    };
    let param = reduced_levin(a, d, s, degree, alternate);
    // the sign of s on the arc after each end, in the same cyclic order (on the stack: at
    // most 4 finite roots and ∞ for a quartic's s)
    let everywhere = dr.arcs[0].1;
    let signs = dr.arcs[1..].iter().map(|a| a.1);
    let signs = signs.chain(dr.at_infinity.then_some(everywhere));
    let mut buffer = [Sign::Zero; 6];
    let owned: Vec<Sign>;
    let after: &[Sign] = if dr.arcs.len() <= buffer.len() {
        let mut len = 0;
        for (slot, sign) in buffer.iter_mut().zip(signs) {
            *slot = sign;
            len += 1;
        }
        &buffer[..len]
    } else {
        owned = signs.collect();
        &owned
    };
    let mut ends = Vec::with_capacity(dr.roots.len() + usize::from(dr.at_infinity));
    ends.extend(dr.roots.into_iter().map(ParamValue::Finite));
    if dr.at_infinity {
        ends.push(ParamValue::Infinity);
    }
    quartic_curve(classification, param, (ends, after, everywhere), n)
}

/// The Levin form `a ± d√s` (homogeneous degree `degree`) with its alternate, reduced where
/// `s | a`: `a ± d√s = √s·(d ± (a/s)√s)` vanishes at the roots of `s`; the second factor is a
/// Levin form without that base point (same identities, same sheets). A nonzero coordinate
/// of lower degree than `s` rules it out without a division.
pub(super) fn reduced_levin(
    a: PointPoly,
    d: PointPoly,
    s: NumberPoly,
    degree: usize,
    alternate: LevinForm,
) -> ComponentParam {
    let alternate = Some(Box::new(alternate));
    let deg_s = s.degree().unwrap_or(0);
    let quotients: Option<Vec<NumberPoly>> =
        if a.iter().any(|c| c.degree().is_some_and(|dg| dg < deg_s)) {
            None
        } else {
            a.iter()
                .map(|c| {
                    let (q, r) = c.div_rem(&s);
                    r.is_zero().then_some(q)
                })
                .collect()
        };
    match quotients {
        Some(q) => ComponentParam::Levin {
            a: d,
            d: std::array::from_fn(|i| q[i].clone()),
            degree: degree - 2,
            s,
            alternate,
        },
        None => ComponentParam::Levin {
            a,
            d,
            degree,
            s,
            alternate,
        },
    }
}

/// The [`Curve`] of a nonsingular quartic: one component with its Levin `param`, its real
/// pieces from the roots of `s` ([`levin_pieces`] of `(ends, after, everywhere)`), whose
/// number must be Theorem 12's `n`; the pieces are disjoint (a nonsingular curve).
///
/// # Errors
/// [`Error::Algebra`] when the pieces disagree with Theorem 12.
pub(super) fn quartic_curve(
    classification: Classification,
    param: ComponentParam,
    (ends, after, everywhere): (Vec<ParamValue>, &[Sign], Sign),
    n: u8,
) -> Result<Curve, Error> {
    let pieces = levin_pieces(ends, after, everywhere);
    if pieces.len() != usize::from(n) {
        return Err(Error::Algebra(format!(
            "{} real pieces from the arcs of s(u), Theorem 12 says {n}",
            pieces.len()
        )));
    }
    let connected = (0..pieces.len()).map(|i| vec![i]).collect();
    Ok(Curve {
        classification,
        components: vec![Component {
            kind: ComponentKind::Quartic,
            multiplicity: 1,
            real: n > 0,
            param: Some(param),
            plane: None,
            section: None,
        }],
        singular_points: Vec::new(),
        pieces,
        connected,
    })
}

/// The real pieces of a Levin component: `ends` the real roots of `s` on ℝ ∪ {∞} in cyclic
/// order, `after[i]` the sign of `s` on the arc after `ends[i]`, `everywhere` its sign when it
/// has no real root. One closed piece per positive arc (the sheets `+` and `−` joined at its
/// ends), two (the two sheets) when `s > 0` everywhere.
pub(super) fn levin_pieces(
    mut ends: Vec<ParamValue>,
    after: &[Sign],
    everywhere: Sign,
) -> Vec<RealPiece> {
    let count = ends.len();
    let positive = |i: usize| after[i] == Sign::Positive;
    if count == 0 {
        if everywhere != Sign::Positive {
            return Vec::new();
        }
        let sheet = |sheet| RealPiece::Curve {
            component: 0,
            arcs: vec![Arc {
                range: ParamRange::All,
                sheet,
                reversed: false,
            }],
            closed: true,
        };
        return vec![sheet(Sheet::Plus), sheet(Sheet::Minus)];
    }
    let mut pieces = Vec::with_capacity((0..count).filter(|&i| positive(i)).count());
    // end k is the start of arc k and the end of arc k − 1 (arc `count − 1` for k = 0, the
    // last one made): moved at its last use, cloned before
    let mut take = |k: usize, last: bool| -> ParamValue {
        if last {
            std::mem::replace(&mut ends[k], ParamValue::Infinity)
        } else {
            ends[k].clone()
        }
    };
    for i in (0..count).filter(|&i| positive(i)) {
        let next = (i + 1) % count;
        // end i is used later only as the end of the last arc (i = 0; this arc itself when
        // count = 1); end `next` later as the start of arc `next` (not when that is arc 0)
        let start = take(i, !(i == 0 && positive(count - 1)));
        let stop = take(next, next == 0 || !positive(next));
        let range = ParamRange::Between(start, stop);
        pieces.push(RealPiece::Curve {
            component: 0,
            arcs: vec![
                Arc {
                    range: range.clone(),
                    sheet: Sheet::Plus,
                    reversed: false,
                },
                Arc {
                    range,
                    sheet: Sheet::Minus,
                    reversed: true,
                },
            ],
            closed: true,
        });
    }
    pieces
}
