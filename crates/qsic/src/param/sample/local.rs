//! A local parameter where the floats cannot resolve the curve.
//!
//! The sampler's parameter is a float `θ` with `u = tan θ`: near a finite `u₀ ≠ 0` it resolves
//! steps of about `2⁻⁵³·(1 + u₀²)` in `u`, and Horner's rule on the coefficients of `u` loses
//! the digits that cancel there. A near-degenerate pair (Steinmetz's cylinders with axes
//! `10⁻¹⁰` apart, a near-node) has features — clustered roots of `s`, of `X` — far below
//! that scale, so the walk cannot converge or no point is certified there.
//!
//! The cure is exact: the component re-parameterized by `u = t + 2ᵉm` (`m` an integer,
//! `2ᵉ` a power of two), which is increasing and fixes `∞`, so arcs, sheets and orientation
//! carry over unchanged. `2ᵉ` is the scale of the cluster at the stuck point `u₀`, read from
//! the Newton polygon of the polynomials shifted there: the smallest root of `Σσₖvᵏ` has
//! modulus about `minⱼ (|σᵢ|/|σⱼ|)^{1/(j−i)}` (`i` the lowest nonzero index); `2ᵉm` is `u₀`
//! rounded to a multiple of it. In `t` the cluster lies at the origin, where `θ` and
//! Horner's rule are relative (the polynomials expanded there, exactly), and the rest of the
//! curve where it was, a distance `|u₀|` away; the walk bisects towards the origin
//! geometrically (`Sampler::geometric`). Every coefficient is computed exactly (a dyadic
//! shift over the coefficients' own field), then converted to floats as before; the arc
//! ends (roots of `s`) move with their isolating intervals.

use crate::param::curve::{Arc, ComponentParam, LevinForm, Number, NumberPoly, ParamRange};
use crate::param::curve::{ParamValue, PointPoly};
use crate::param::sample::convert::to_f64;
use qsic_algebra::roots::RootInterval;
use qsic_algebra::{AlgebraicReal, IBig, RBig};

/// `u = t + 2ᵉm`.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct LocalMap {
    pub(super) m: IBig,
    pub(super) e: i64,
}

/// The largest cluster scale worth a new parameter is `2^−MIN_GAIN_LOG2·(1 + |u₀|)`: above
/// it the floats resolve the cluster already and something else stopped the walk.
const MIN_GAIN_LOG2: f64 = 20.0;

/// The local parameter around `θ` (`u₀ = tan θ`), or `None` where no cluster of the
/// component's polynomials lies there below `2⁻²⁰·(1 + |u₀|)`. The centre is the arc end
/// (an exact root of `s`) nearest `u₀` when one lies that close — the walk stops beside the
/// cluster, not in it — to 2⁻²⁰⁰ relative, else `u₀`.
pub(super) fn local_map(param: &ComponentParam, arcs: &[Arc], theta: f64) -> Option<LocalMap> {
    let u0 = theta.tan();
    let near = 2f64.powf(-MIN_GAIN_LOG2) * (1.0 + u0.abs());
    let centre = ends(arcs)
        .filter(|r| (r.to_f64() - u0).abs() <= near)
        .min_by(|a, b| (a.to_f64() - u0).abs().total_cmp(&(b.to_f64() - u0).abs()))
        .map(|r| {
            let width = crate::param::expr::power_of_two(-200) * RBig::from(1 + u0.abs() as i64);
            let iv = r.refined_interval(&width);
            (iv.lo() + iv.hi()) / RBig::from(2)
        });
    if let Some(c) = centre {
        // an exact root of `s` in the cluster: within 2⁻⁸⁰·(1 + |u₀|) of it is enough for
        // every feature above that scale to be relative in `t`
        let e = near.log2().floor() as i64 - 60;
        let m = (c / crate::param::expr::power_of_two(e)).round();
        return Some(LocalMap { m, e });
    }
    let c0 = RBig::try_from(u0).ok()?;
    let c = Number::rational(c0.clone());
    let mut polys: Vec<&NumberPoly> = Vec::new();
    match param {
        ComponentParam::Point(_) => return None,
        ComponentParam::Rational { x, .. } => polys.extend(x.iter()),
        ComponentParam::Levin { a, s, .. } => {
            polys.push(s);
            polys.extend(a.iter());
        }
    }
    // the Newton polygon of `s` alone, and of the vector `a` (or `X`) by its largest
    // coordinate in each power
    let shifted: Vec<NumberPoly> = polys.iter().map(|p| p.shift(&c)).collect();
    let sizes = |ps: &[NumberPoly]| -> Vec<f64> {
        let n = ps.iter().map(|p| p.coeffs().len()).max().unwrap_or(0);
        (0..n)
            .map(|k| {
                ps.iter()
                    .filter_map(|p| p.coeffs().get(k))
                    .map(|v| to_f64(v).map_or(f64::NAN, f64::abs))
                    .fold(0.0, f64::max)
            })
            .collect()
    };
    let groups: Vec<Vec<f64>> = match param {
        ComponentParam::Levin { .. } => vec![sizes(&shifted[..1]), sizes(&shifted[1..])],
        _ => vec![sizes(&shifted)],
    };
    let scale = (groups.iter())
        .filter_map(|g| smallest_root_scale(g))
        .fold(f64::INFINITY, f64::min);
    if !(scale.is_finite() && scale > 0.0) || scale > near {
        return None;
    }
    // the centre rounded to a multiple of 2⁻²⁰ of the cluster's scale: a short dyadic
    let e = scale.log2().floor() as i64 - 20;
    let m = (c0 / crate::param::expr::power_of_two(e)).round();
    Some(LocalMap { m, e })
}

/// The finite exact ends of `arcs`.
fn ends(arcs: &[Arc]) -> impl Iterator<Item = &AlgebraicReal> {
    arcs.iter()
        .flat_map(|arc| match &arc.range {
            ParamRange::All => [None, None],
            ParamRange::Between(a, b) => [a, b].map(|v| match v {
                ParamValue::Finite(r) => Some(r),
                ParamValue::Infinity => None,
            }),
        })
        .flatten()
}

/// The modulus of the smallest root of `Σσₖvᵏ` by the Newton polygon (`|σₖ|` given), `None`
/// for a constant or a NaN.
fn smallest_root_scale(sigma: &[f64]) -> Option<f64> {
    if sigma.iter().any(|v| v.is_nan()) {
        return None;
    }
    let i = sigma.iter().position(|v| *v != 0.0)?;
    (i + 1..sigma.len())
        .filter(|&j| sigma[j] != 0.0)
        .map(|j| (sigma[i].log2() - sigma[j].log2()) / (j - i) as f64)
        .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.min(v))))
        .map(f64::exp2)
}

impl LocalMap {
    /// `2ᵉm`.
    fn centre(&self) -> RBig {
        RBig::from(self.m.clone()) * crate::param::expr::power_of_two(self.e)
    }
}

/// `p(t + 2ᵉm)` over the coefficients' field.
fn substituted(p: &NumberPoly, map: &LocalMap) -> NumberPoly {
    p.shift(&Number::rational(map.centre()))
}

fn substituted_point(x: &PointPoly, map: &LocalMap) -> PointPoly {
    std::array::from_fn(|i| substituted(&x[i], map))
}

/// The component in the local parameter `t` (module docs).
pub(super) fn reparameterized(param: &ComponentParam, map: &LocalMap) -> ComponentParam {
    match param {
        ComponentParam::Point(p) => ComponentParam::Point(p.clone()),
        ComponentParam::Rational { x, degree } => ComponentParam::Rational {
            x: substituted_point(x, map),
            degree: *degree,
        },
        ComponentParam::Levin {
            a,
            d,
            degree,
            alternate,
            s,
        } => ComponentParam::Levin {
            a: substituted_point(a, map),
            d: substituted_point(d, map),
            degree: *degree,
            alternate: alternate.as_ref().map(|f| {
                Box::new(LevinForm {
                    a: substituted_point(&f.a, map),
                    d: substituted_point(&f.d, map),
                    degree: f.degree,
                })
            }),
            s: substituted(s, map),
        },
    }
}

/// `t = u − 2ᵉm` of an exact parameter; `None` where the new interval does not isolate it.
fn local_value(v: &ParamValue, map: &LocalMap) -> Option<ParamValue> {
    let ParamValue::Finite(r) = v else {
        return Some(ParamValue::Infinity);
    };
    let c = map.centre();
    let to_t = |u: &RBig| u - &c;
    if let Some(q) = r.as_rational() {
        return Some(ParamValue::Finite(AlgebraicReal::from_rational(to_t(q))));
    }
    // `p(t + 2ᵉm)` with integer coefficients: `P(y) = dⁿp(y/d)` for `2ᵉ = 1/d` (`y = du`),
    // then `P(dt + m)` (or `p(2ᵉ(x + m))` at `x = 2⁻ᵉt` for `e > 0`)
    let p = if map.e <= 0 {
        let d = IBig::ONE << (-map.e) as usize;
        r.poly().scale_var_inverse(&d).shift(&map.m).scale_var(&d)
    } else {
        let p = r
            .poly()
            .scale_var(&(IBig::ONE << map.e as usize))
            .shift(&map.m);
        p.scale_var_inverse(&(IBig::ONE << map.e as usize))
    };
    let interval = match r.interval() {
        RootInterval::Exact(q) => RootInterval::Exact(to_t(q)),
        RootInterval::Open(lo, hi) => RootInterval::Open(to_t(lo), to_t(hi)),
    };
    AlgebraicReal::from_isolating_interval(&p, &interval).map(ParamValue::Finite)
}

/// The arcs in the local parameter: the same ranges, sheets and directions, an arc through
/// `∞` between finite ends cut there in two, so that both its ends (beside the cluster at
/// `t = 0`) are walked from `θ` near 0, where the floats are relative, not one of them from
/// `θ` near `π`.
pub(super) fn local_arcs(arcs: &[Arc], map: &LocalMap) -> Option<Vec<Arc>> {
    let mut out = Vec::with_capacity(arcs.len() + 2);
    for arc in arcs {
        let ranges = match &arc.range {
            ParamRange::All => vec![ParamRange::All],
            ParamRange::Between(a, b) => {
                let (a, b) = (local_value(a, map)?, local_value(b, map)?);
                match (&a, &b) {
                    (ParamValue::Finite(x), ParamValue::Finite(y)) if y <= x => vec![
                        ParamRange::Between(a, ParamValue::Infinity),
                        ParamRange::Between(ParamValue::Infinity, b),
                    ],
                    _ => vec![ParamRange::Between(a, b)],
                }
            }
        };
        let at = out.len();
        out.extend(ranges.into_iter().map(|range| Arc {
            range,
            sheet: arc.sheet,
            reversed: arc.reversed,
        }));
        if arc.reversed {
            out[at..].reverse();
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::parse_quadric;
    use crate::param::curve::{Curve, RealPiece};
    use crate::param::parameterize;
    use qsic_algebra::Ring;

    fn steinmetz(offset: &str) -> Curve {
        let a = parse_quadric("x^2+y^2-1").unwrap();
        let b = parse_quadric(&format!("(x-{offset})^2+z^2-1")).unwrap();
        parameterize(&a, &b).unwrap()
    }

    fn arcs_of(curve: &Curve) -> Vec<Arc> {
        match &curve.pieces[0] {
            RealPiece::Curve { arcs, .. } => arcs.clone(),
            RealPiece::Point { .. } => panic!("a curve piece"),
        }
    }

    /// Beside the near-node of Steinmetz's cylinders `10⁻¹⁰` apart the map is centred on an
    /// arc end, and the local parameterization is the same curve: `ã(t) = a(t + c)` (and `d`,
    /// `s`) at rational `t`, evaluated exactly on both sides; each local arc end `r̃` is a
    /// root of `s̃` with `r̃ + c` within its isolating interval of the old end.
    #[test]
    fn a_local_parameter_is_the_same_curve() {
        let curve = steinmetz("1/10000000000");
        let param = curve.components[0].param.as_ref().unwrap();
        let arcs = arcs_of(&curve);
        // the walk stops a little before the arc end near u = −1
        let map = local_map(param, &arcs, (-1.0f64 + 1e-8).atan()).expect("a cluster there");
        let c = map.centre();
        assert!((c.to_f64().value() + 1.0).abs() < 1e-9, "{c}");
        let local = reparameterized(param, &map);
        let (
            ComponentParam::Levin { a, d, s, .. },
            ComponentParam::Levin {
                a: la,
                d: ld,
                s: ls,
                ..
            },
        ) = (param, &local)
        else {
            panic!("Levin's form");
        };
        for (n, k) in [(3, 7), (-5, 2), (1, 1_000_000)] {
            let t = RBig::from(n) / RBig::from(k);
            let (tn, un) = (Number::rational(t.clone()), Number::rational(&t + &c));
            assert!(ls.eval(&tn).sub(&s.eval(&un)).is_zero());
            for i in 0..4 {
                assert!(la[i].eval(&tn).sub(&a[i].eval(&un)).is_zero());
                assert!(ld[i].eval(&tn).sub(&d[i].eval(&un)).is_zero());
            }
        }
        let local_arcs = local_arcs(&arcs, &map).unwrap();
        let (old, new): (Vec<_>, Vec<_>) = (ends(&arcs).collect(), ends(&local_arcs).collect());
        assert_eq!(old.len(), new.len());
        let width = crate::param::expr::power_of_two(-300);
        for lr in &new {
            let iv = lr.refined_interval(&width);
            let (lo, hi) = (
                Number::rational(iv.lo().clone()),
                Number::rational(iv.hi().clone()),
            );
            // a sign change of s̃ across the new end, and an old end's interval meeting it + c
            assert!(ls.eval(&lo).sign() * ls.eval(&hi).sign() != qsic_algebra::Sign::Positive);
            let meets = old.iter().any(|r| {
                let o = r.refined_interval(&width);
                iv.lo() + &c <= *o.hi() && *o.lo() <= iv.hi() + &c
            });
            assert!(meets, "{lr:?}");
        }
        // each arc through ∞ between finite ends (here both sheets') is cut there in two
        let through = (arcs.iter())
            .filter(|arc| match &arc.range {
                ParamRange::Between(ParamValue::Finite(a), ParamValue::Finite(b)) => b <= a,
                _ => false,
            })
            .count();
        assert_eq!((through, local_arcs.len()), (2, arcs.len() + 2));
    }

    /// Away from any cluster (the unit circle's parameter, a pair far from degenerate) there
    /// is no local parameter: the walk's trouble is elsewhere.
    #[test]
    fn no_local_parameter_away_from_a_cluster() {
        let curve = steinmetz("1/2");
        let param = curve.components[0].param.as_ref().unwrap();
        let arcs = arcs_of(&curve);
        for theta in [0.3, -1.2, 1.5] {
            assert_eq!(local_map(param, &arcs, theta), None, "θ = {theta}");
        }
    }
}
