//! The chart: the plane at infinity `h(X) = aX₀ + bX₁ + cX₂ + dX₃ = 0`, exactly and as
//! floats, and the affine coordinates `X/h(X)` without the last coordinate whose coefficient
//! in `h` is nonzero (`(x/w, y/w, z/w)` for the default `h = w`). A float `h` only places a
//! point in the chart; whether a point is at infinity is decided exactly
//! ([`super::crossings`]). Also the exact parameters of the curve's real singular points on
//! a rational component ([`singular_params`], by [`super::plane::params_of_point`]) and the
//! small float vector helpers of the walk.

use crate::param::curve::{ComponentParam, Curve, ParamValue};
use qsic_algebra::{RBig, Ring};

/// The exact parameters at which a rational component passes through the curve's real
/// singular points, each with whether the point lies on the chart's plane at infinity
/// (decided exactly); none for Levin's form (a nonsingular quartic has none), none either when
/// a point and the component live in fields made separately (the polyline is then not split
/// there).
pub(super) fn singular_params(
    curve: &Curve,
    param: &ComponentParam,
    h: &[RBig; 4],
) -> Vec<(ParamValue, bool)> {
    let ComponentParam::Rational { x, degree } = param else {
        return Vec::new();
    };
    curve
        .singular_points
        .iter()
        .filter_map(|s| {
            let at_infinity = super::plane::chart_value(h, &s.point).is_zero();
            super::plane::params_of_point(x, *degree, &s.point)
                .ok()
                .map(|params| params.into_iter().map(move |v| (v, at_infinity)))
        })
        .flatten()
        .collect()
}

/// The plane at infinity, exactly and as floats, and the affine coordinate dropped.
pub(super) struct Chart {
    pub(super) exact: [RBig; 4],
    pub(super) h: [f64; 4],
    pub(super) form: ChartForm,
    /// The coordinates kept (all but the last whose coefficient in `h` is nonzero).
    pub(super) keep: [usize; 3],
}

/// `h(X)` as floats: the dot product with `h`, or `c·Xⱼ` where `h = c·eⱼ` (the same value:
/// the other products are zeros, which leave a nonzero sum unchanged and a zero one zero).
#[derive(Clone, Copy, Default)]
pub(super) struct ChartForm {
    pub(super) h: [f64; 4],
    pub(super) single: Option<(usize, f64)>,
}

impl ChartForm {
    pub(super) fn new(h: [f64; 4]) -> ChartForm {
        let nonzero = h.iter().filter(|v| **v != 0.0).count();
        let single = (nonzero == 1 && h.iter().all(|v| v.is_finite()))
            .then(|| (0..4).find(|&j| h[j] != 0.0).map(|j| (j, h[j])))
            .flatten();
        ChartForm { h, single }
    }

    #[inline(always)]
    pub(super) fn value(&self, x: &[f64; 4]) -> f64 {
        match self.single {
            // `j < 4` (made so in `new`): no bounds check
            Some((j, c)) => c * x[j & 3],
            None => dot(&self.h, x),
        }
    }
}

impl Chart {
    #[inline(always)]
    pub(super) fn value(&self, x: &[f64; 4]) -> f64 {
        self.form.value(x)
    }

    /// Affine coordinates of `x`, `None` at infinity.
    pub(super) fn affine(&self, x: &[f64; 4]) -> Option<[f64; 3]> {
        self.affine_with(x, self.value(x))
    }

    /// [`Chart::affine`] with `h = self.value(x)` given.
    pub(super) fn affine_with(&self, x: &[f64; 4], h: f64) -> Option<[f64; 3]> {
        if h == 0.0 {
            return None;
        }
        let k = self.keep;
        Some([x[k[0]] / h, x[k[1]] / h, x[k[2]] / h])
    }
}

pub(super) fn unit(x: [f64; 4]) -> Option<[f64; 4]> {
    let n = x.iter().map(|v| v * v).sum::<f64>().sqrt();
    (n > 0.0 && n.is_finite()).then(|| x.map(|v| v / n))
}

#[inline(always)]
pub(super) fn dot(a: &[f64; 4], b: &[f64; 4]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]
}

/// Distance from `c` to the segment `ab`.
pub(super) fn chord_deviation(a: &[f64; 3], b: &[f64; 3], c: &[f64; 3]) -> f64 {
    let ab: [f64; 3] = std::array::from_fn(|i| b[i] - a[i]);
    let ac: [f64; 3] = std::array::from_fn(|i| c[i] - a[i]);
    let len2: f64 = ab.iter().map(|v| v * v).sum();
    let t = if len2 > 0.0 {
        (ab.iter().zip(&ac).map(|(x, y)| x * y).sum::<f64>() / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (0..3)
        .map(|i| (ac[i] - t * ab[i]).powi(2))
        .sum::<f64>()
        .sqrt()
}
