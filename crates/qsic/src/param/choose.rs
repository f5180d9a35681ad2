//! The parameterization surface of a nonsingular quartic: a real ruled member of the pencil
//! (a (2, 2) member through a rational point, or a cone), chosen so that its ruling needs
//! the smallest field and the smallest numbers — first among small members in machine
//! integers, then exactly.

use super::*;

/// Picks the parameterization surface (see [`parameterize_smooth_quartic`]): the choice of
/// [`choose_surface_small`] when it finds one, else [`choose_surface_full`].
pub(super) fn choose_surface(
    a: &[[RBig; 4]; 4],
    b: &[[RBig; 4]; 4],
    analysis: &PencilAnalysis,
) -> Result<Chosen, Error> {
    match choose_surface_small(a, b, analysis)? {
        Some(chosen) => Ok(chosen),
        None => choose_surface_full(a, b, analysis).map(|surface| Chosen {
            surface,
            fixed: None,
            member: None,
        }),
    }
}

/// A chosen parameterization surface; with its ruling in machine integers when it was
/// computed there ([`zsqrt::ruling_fixed`]), and then the surface's `b` and `d` left empty
/// (only its `δ` set): [`Chosen::into_surface`] or the integral forms fill them; with the
/// member `(d·S, d)` in machine integers when the surface's matrix `S` is left zero (filled
/// when asked for: [`SmoothQuartic::into_levin`]).
pub(super) struct Chosen {
    pub(super) surface: ParameterizationSurface,
    pub(super) fixed: Option<zsqrt::FixedRuling>,
    pub(super) member: Option<([[i128; 4]; 4], i128)>,
}

impl Chosen {
    /// The surface with its ruling.
    #[cfg(test)]
    pub(super) fn into_surface(self) -> ParameterizationSurface {
        let mut surface = self.surface;
        if let Some(r) = self.fixed {
            surface.ruling = r.into();
        }
        if let Some((m, den)) = self.member {
            surface.matrix = surface::member_from_small(&m, den);
        }
        surface
    }
}

/// The parameterization surface through small points, in machine integers: for each (2, 2)
/// candidate `M = n·A − d·B` (`λ = n/d`, entries below `2⁴⁰`) the radicand of its rulings
/// through a rational point is known before any point, the square-free part `δ` of `det M`
/// ([`surface::member_radicand`]); the candidates are tried by increasing `δ` (rational
/// rulings first, then the order of [`primary_candidates`]) and the first with a small point
/// ([`surface::small_point_of`]) gives the ruling ([`surface::ruling_through_small`]). Only
/// when no primary candidate has a small point, [`more_candidates`] the same way. `Ok(None)`
/// when the candidates include a cone, the numbers leave machine integers, or no candidate
/// has a small point: [`choose_surface_full`] decides then.
pub(super) fn choose_surface_small(
    a: &[[RBig; 4]; 4],
    b: &[[RBig; 4]; 4],
    analysis: &PencilAnalysis,
) -> Result<Option<Chosen>, Error> {
    let (primary, _) = primary_candidates(analysis);
    if primary
        .iter()
        .any(|(_, kind)| *kind != SurfaceKind::DoublyRuled)
    {
        return Ok(None);
    }
    let (Some(ai), Some(bi)) = (surface::integer_entries(a), surface::integer_entries(b)) else {
        return Ok(None);
    };
    for round in 0..2 {
        let candidates = if round == 0 {
            primary.clone()
        } else {
            more_candidates(analysis)
        };
        let mut lambdas = Vec::with_capacity(candidates.len());
        for (lambda, _) in candidates {
            let Some(l) = lambda else { return Ok(None) };
            lambdas.push(l);
        }
        match surface_among(&ai, &bi, lambdas)? {
            Some(Some(surface)) => return Ok(Some(surface)),
            Some(None) => {}
            None => return Ok(None),
        }
    }
    Ok(None)
}

/// The first of the doubly ruled members `λA − B` at `lambdas` (each of inertia (2, 2)) by
/// increasing radicand with a small point, and its ruling ([`choose_surface_small`]):
/// `Some(None)` when no candidate has a small point, `None` when a number leaves machine
/// integers.
pub(super) fn surface_among(
    ai: &[[i128; 4]; 4],
    bi: &[[i128; 4]; 4],
    lambdas: Vec<RBig>,
) -> Result<Option<Option<Chosen>>, Error> {
    let mut scored = Vec::with_capacity(lambdas.len());
    for l in lambdas {
        let Some((m, den)) = surface::small_member(ai, bi, &l) else {
            return Ok(None);
        };
        let Some(delta) = surface::member_radicand(&m) else {
            return Ok(None);
        };
        scored.push((delta, l, m, den));
    }
    // stable: equal radicands keep the candidates' order
    scored.sort_by(|x, y| x.0.cmp(&y.0));
    for (delta, l, m, den) in scored {
        let Some(p) = surface::small_point_of(&m) else {
            continue;
        };
        let through = match i128::try_from(&delta) {
            Ok(dl) => zsqrt::ruling_fixed(&m, &p, dl)?,
            Err(_) => zsqrt::Through::Overflow,
        };
        let (ruling, fixed) = match through {
            zsqrt::Through::Ruling(r) => {
                let ruling = RuledParameterization {
                    b: std::array::from_fn(|_| Poly::zero()),
                    d: std::array::from_fn(|_| Poly::zero()),
                    delta: (r.delta != 0).then(|| IBig::from(r.delta)),
                };
                (ruling, Some(r))
            }
            zsqrt::Through::NotInField => continue,
            zsqrt::Through::Overflow => match surface::ruling_through_small(&m, &p, &delta)? {
                Some(ruling) => (ruling, None),
                None => continue,
            },
        };
        return Ok(Some(Some(Chosen {
            surface: ParameterizationSurface {
                lambda: Some(l),
                matrix: std::array::from_fn(|_| std::array::from_fn(|_| RBig::ZERO)),
                kind: SurfaceKind::DoublyRuled,
                ruling,
            },
            fixed,
            member: Some((m, den)),
        })));
    }
    Ok(Some(None))
}

/// The parameterization surface of a pencil known to have four simple roots, from the (2, 2)
/// samples of [`pencil::quick_arc_samples`] (no pencil analysis; from `sums`, `E₁…E₄` of the
/// pencil, when given) by [`surface_among`]; `None` when that gives none (then
/// [`choose_surface`] decides from the analysis).
pub(super) fn choose_surface_quick(
    a: &Quadric,
    b: &Quadric,
    sums: Option<&[[i128; 5]; 4]>,
) -> Result<Option<Chosen>, Error> {
    let arcs = match sums {
        Some(e) => crate::pencil::quick_arc_samples_of(e),
        None => crate::pencil::quick_arc_samples(a, b),
    };
    let Some(arcs) = arcs else {
        return Ok(None);
    };
    let lambdas: Vec<RBig> = arcs
        .into_iter()
        .filter(|(_, i)| i.positive == 2 && i.negative == 2)
        .map(|(x, _)| x)
        .collect();
    if lambdas.is_empty() {
        return Ok(None);
    }
    // the primitive integer matrices, as the pencil analysis and `λ` take them
    let (Some(ai), Some(bi)) = (a.small_integer_matrix(), b.small_integer_matrix()) else {
        return Ok(None);
    };
    let wide = |m: &[[i64; 4]; 4]| m.map(|row| row.map(i128::from));
    Ok(surface_among(&wide(ai), &wide(bi), lambdas)?.flatten())
}

/// The candidates in order: the sample of each (2, 2) arc, then the cones at rational
/// roots; with the number of cones at irrational roots.
pub(super) fn primary_candidates(
    analysis: &PencilAnalysis,
) -> (Vec<(Option<RBig>, SurfaceKind)>, usize) {
    let mut candidates: Vec<(Option<RBig>, SurfaceKind)> = Vec::new();
    for (sample, inertia) in &analysis.arcs {
        if inertia.positive == 2 && inertia.negative == 2 {
            candidates.push((Some(sample.clone()), SurfaceKind::DoublyRuled));
        }
    }
    let mut irrational_cones = 0;
    for root in &analysis.real_roots {
        let i = root.inertia;
        if i.rank() != 3 || i.positive == 0 || i.negative == 0 {
            continue;
        }
        match &root.point {
            PencilPoint::Finite(v) => match v.as_rational() {
                Some(r) => candidates.push((Some(r.clone()), SurfaceKind::Cone)),
                None => irrational_cones += 1,
            },
            PencilPoint::Infinity => candidates.push((None, SurfaceKind::Cone)),
        }
    }
    (candidates, irrational_cones)
}

/// Picks the parameterization surface by computing the ruling of each candidate in order
/// (see [`parameterize_smooth_quartic`]).
pub(super) fn choose_surface_full(
    a: &[[RBig; 4]; 4],
    b: &[[RBig; 4]; 4],
    analysis: &PencilAnalysis,
) -> Result<ParameterizationSurface, Error> {
    let (primary, irrational_cones) = primary_candidates(analysis);
    // the primary candidates first without searching for a point where none is small (a
    // rational cone is then found before a (2, 2) member's sections are searched), then
    // again with the search those that gave nothing; more rationals of the (2, 2) arcs only
    // when all that gives no ruling. Each try: (λ, kind, search, its first try's index).
    let mut tries: Vec<(Option<RBig>, SurfaceKind, bool, usize)> = primary
        .into_iter()
        .enumerate()
        .map(|(i, (l, kind))| (l, kind, false, i))
        .collect();
    let cheap = tries.len();
    let again: Vec<_> = tries
        .iter()
        .filter(|t| matches!(t.1, SurfaceKind::DoublyRuled))
        .map(|t| (t.0.clone(), t.1, true, t.3))
        .collect();
    tries.extend(again);
    let primary = tries.len();
    let mut empty = vec![false; cheap];
    let mut best: Option<ParameterizationSurface> = None;
    let mut k = 0;
    loop {
        if k == primary {
            if best.is_some() {
                break;
            }
            let more = more_candidates(analysis).into_iter();
            tries.extend(more.map(|(l, kind)| (l, kind, true, usize::MAX)));
        }
        let Some((lambda, kind, search, first)) = tries.get(k).cloned() else {
            break;
        };
        k += 1;
        if search && first < cheap && !empty[first] {
            // its first try gave a ruling: searching gives the same
            continue;
        }
        let matrix = member(a, b, lambda.as_ref());
        let ruling = match kind {
            SurfaceKind::DoublyRuled => parameterize_doubly_ruled_with(&matrix, search)?,
            SurfaceKind::Cone => parameterize_cone(&matrix)?,
        };
        let Some(ruling) = ruling else {
            if !search {
                empty[first] = true;
            }
            continue;
        };
        let candidate = ParameterizationSurface {
            lambda,
            matrix,
            kind,
            ruling,
        };
        let better = match &best {
            None => true,
            Some(old) => match (&old.ruling.delta, &candidate.ruling.delta) {
                (Some(_), Some(_)) => ruling_height(&candidate.ruling) < ruling_height(&old.ruling),
                (Some(_), None) => true,
                _ => false,
            },
        };
        if better {
            let rational = candidate.ruling.delta.is_none();
            best = Some(candidate);
            if rational {
                break;
            }
        }
    }
    best.ok_or_else(|| {
        Error::Unsupported(if irrational_cones > 0 {
            "the only real ruled members are cones at irrational λ (not yet)".into()
        } else {
            "the rulings need a biquadratic field (not yet)".into()
        })
    })
}

/// The size of a ruling over ℚ(√δ) in bits: half the bits of `δ` plus the largest bit
/// length of a numerator or denominator of its coefficients' parts — about `log₂` of the
/// largest coefficient, which the Levin forms and the output grow with (a small `δ` with a
/// huge ruling, from a large point, is worse than a slightly larger `δ` with a small one).
pub(super) fn ruling_height(r: &RuledParameterization) -> usize {
    use dashu_int::ops::BitTest;
    let delta = r.delta.as_ref().map_or(0, |d| d.bit_len().div_ceil(2));
    let bits = |v: &RBig| v.numerator().bit_len().max(v.denominator().bit_len());
    let coefficients = r.b.iter().chain(&r.d).flat_map(|p| p.coeffs());
    delta
        + coefficients
            .map(|c| bits(c.rational_part()).max(bits(c.radical_part())))
            .max()
            .unwrap_or(0)
}

/// More doubly ruled candidates: [`more_samples`] of each (2, 2) arc.
pub(super) fn more_candidates(analysis: &PencilAnalysis) -> Vec<(Option<RBig>, SurfaceKind)> {
    let finite: Vec<(&RootInterval, &Poly)> = analysis
        .real_roots
        .iter()
        .filter_map(|r| match &r.point {
            PencilPoint::Finite(v) => Some((v.interval(), v.poly())),
            PencilPoint::Infinity => None,
        })
        .collect();
    let mut out = Vec::new();
    for (i, (sample, inertia)) in analysis.arcs.iter().enumerate() {
        if inertia.positive == 2 && inertia.negative == 2 {
            let lo = i.checked_sub(1).map(|k| finite[k]);
            let hi = finite.get(i).copied();
            for lambda in more_samples(lo, sample, hi) {
                out.push((Some(lambda), SurfaceKind::DoublyRuled));
            }
        }
    }
    out
}

/// Small-height rationals of the arc between the roots `lo` and `hi` (isolating interval
/// and polynomial; unbounded for `None`) other than its `sample`: the simplest ones on
/// either side of it, then between those and `sample`, then between those and the roots
/// ([`simplest_between`]; next to a root, [`dyadic_between_isolated`], so that they depend
/// on the roots, not on their intervals).
pub(super) fn more_samples(
    lo: Option<(&RootInterval, &Poly)>,
    sample: &RBig,
    hi: Option<(&RootInterval, &Poly)>,
) -> Vec<RBig> {
    let sign = |p: &Poly, x: &RBig| p.sign_at(x);
    let one = Poly::constant(IBig::ONE);
    let exact = |x: &RBig| RootInterval::Exact(x.clone());
    let at = exact(sample);
    let left = match lo {
        Some(l) => dyadic_between_isolated(l, (&at, &one), &sign),
        None => sample - RBig::ONE,
    };
    let right = match hi {
        Some(h) => dyadic_between_isolated((&at, &one), h, &sign),
        None => sample + RBig::ONE,
    };
    let mid_left = simplest_between(&left, sample, false, false);
    let mid_right = simplest_between(sample, &right, false, false);
    let (at_left, at_right) = (exact(&left), exact(&right));
    let far_left = match lo {
        Some(l) => dyadic_between_isolated(l, (&at_left, &one), &sign),
        None => &left - RBig::ONE,
    };
    let far_right = match hi {
        Some(h) => dyadic_between_isolated((&at_right, &one), h, &sign),
        None => &right + RBig::ONE,
    };
    vec![left, right, mid_left, mid_right, far_left, far_right]
}
