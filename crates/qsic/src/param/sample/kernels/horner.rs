//! Horner's rule on four coordinates at once (`Σₖ cₖ tᵏ`, or reversed for `|t| > 1`), and on
//! the absolute values at `|t|`: the majorant `Σₖ|cₖ||t|ᵏ` of the rounding error, which is at
//! most `γ_{2n}` times it for `n` terms (Higham, *Accuracy and Stability*, §5.1).

use crate::param::sample::kernels::Lanes;

/// Horner's rule on four coordinates at once: `Σₖ cₖ tᵏ`, or `Σₖ cₖ t^(n−1−k)` reversed.
#[inline(always)]
pub(in crate::param::sample) fn horner_lanes(c: &[Lanes], t: f64, rev: bool) -> Lanes {
    let mut v = [0.0; 4];
    let mut step = |k: &Lanes| {
        for i in 0..4 {
            v[i] = v[i] * t + k[i];
        }
    };
    if rev {
        c.iter().for_each(&mut step);
    } else {
        c.iter().rev().for_each(&mut step);
    }
    v
}

/// [`horner_lanes`] of the absolute values at `|t|`: the rounding bound's majorant.
pub(in crate::param::sample) fn horner_lanes_abs(c: &[Lanes], t: f64, rev: bool) -> Lanes {
    let at = t.abs();
    let mut v = [0.0; 4];
    let mut step = |k: &Lanes| {
        for i in 0..4 {
            v[i] = v[i] * at + k[i].abs();
        }
    };
    if rev {
        c.iter().for_each(&mut step);
    } else {
        c.iter().rev().for_each(&mut step);
    }
    v
}

#[inline(always)]
pub(in crate::param::sample) fn horner_scalar(c: &[f64; 5], t: f64, rev: bool) -> f64 {
    if rev {
        c.iter().fold(0.0, |v, k| v * t + k)
    } else {
        c.iter().rev().fold(0.0, |v, k| v * t + k)
    }
}
