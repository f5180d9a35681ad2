//! A small point of a conic over its plane's field `K = ℚ(√δ)`, found without solving the
//! conic: in the diagonal form `Σ dᵢYᵢ² = 0` (`C` congruent to `diag(d)` over `K`), `Y_j = 1`,
//! `Y_k = t` for the small `t = (a + b√δ)/c` (`0 ≤ a ≤ 3`, `|b| ≤ 3`, `c ∈ {1, 2}`), and
//! `Y_i = √(−(d_j + d_k t²)/d_i)` when that square root lies in `K` — a test of the norm and
//! of one rational square ([`sqrt_in_field`]). Pairs met in practice (QI's test pairs among
//! them) have such points where no ratio `−d_j/d_i` is a square: the circle
//! `y² + z² = (3 + c)w²`, `c² + c = 1`, has `(φ, 1, 1)`, `φ² = 2 + c`. A conic with no point
//! over `K`, or only large ones, is not found here: the caller then adjoins a square root.

use super::{Quadratic, Vq};
use crate::param::surface::sqrt_in_field;
use qsic_algebra::linalg::congruence::Diagonalization;
use qsic_algebra::{Field, IBig, RBig, Ring};

/// The small values `t` tried (module docs), simplest first.
fn small_values(delta: &IBig) -> Vec<Quadratic> {
    let mut out = Vec::new();
    for c in [1i64, 2] {
        for size in 1i64..=6 {
            for a in 0i64..=3 {
                let b_abs = size - a;
                if !(0..=3).contains(&b_abs) {
                    continue;
                }
                let signs: &[i64] = if b_abs == 0 { &[0] } else { &[1, -1] };
                for b in signs.iter().map(|s| s * b_abs) {
                    let r = |n: i64| RBig::from_parts_signed(n.into(), (c as u64).into());
                    if let Some(t) = Quadratic::new(r(a), r(b), delta.clone()) {
                        out.push(t);
                    }
                }
            }
        }
    }
    out
}

/// A point over ℚ(√δ) of the conic diagonalized by `dg` (module docs), in the conic's
/// coordinates; `None` when no small value gives one.
pub(super) fn small_point_in_field(dg: &Diagonalization<Quadratic>, delta: &IBig) -> Option<Vq> {
    let n = dg.d.len();
    if n != 3 || dg.d.iter().any(Quadratic::is_zero) {
        return None;
    }
    let values = small_values(delta);
    for i in 0..3 {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        for (j, k) in [(j, k), (k, j)] {
            for t in &values {
                // d_i·Y_i² = −(d_j + d_k·t²)
                let rest = dg.d[j].add(&dg.d[k].mul(&t.mul(t)));
                let Some(ratio) = rest.neg().div(&dg.d[i]) else {
                    continue;
                };
                let yi = if ratio.is_zero() {
                    Quadratic::zero()
                } else {
                    match sqrt_in_field(&ratio, Some(delta)) {
                        Some(yi) => yi,
                        None => continue,
                    }
                };
                let mut y = [Quadratic::zero(), Quadratic::zero(), Quadratic::zero()];
                y[i] = yi;
                y[j] = Quadratic::one();
                y[k] = t.clone();
                let point: Vq = (0..3)
                    .map(|r| {
                        (0..3).fold(Quadratic::zero(), |acc, s| {
                            acc.add(&dg.p[(r, s)].mul(&y[s]))
                        })
                    })
                    .collect();
                return Some(point);
            }
        }
    }
    None
}
