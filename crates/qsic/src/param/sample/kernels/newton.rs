//! Newton's method safeguarded by bisection on a bracketing interval: every step stays inside
//! the interval, which halves when Newton leaves it, so it converges where the bracket holds
//! one root; it stops at the rounding level of `f`.

/// Newton's method on `f` (value, derivative) safeguarded by bisection in `(lo, hi)`, where
/// `f(lo) = flo` and `f(hi)` have opposite signs: a float near the root, returned once
/// `|f| ≤ noise` (the rounding level of `f`, where the steps only follow the noise).
pub(in crate::param::sample) fn newton_bracketed(
    f: &dyn Fn(f64) -> (f64, f64),
    lo: f64,
    hi: f64,
    flo: f64,
    noise: f64,
) -> f64 {
    let (mut a, mut b) = (lo, hi);
    let mut x = 0.5 * (a + b);
    for _ in 0..200 {
        let (fx, dfx) = f(x);
        if fx.abs() <= noise || !fx.is_finite() {
            return x;
        }
        if (fx < 0.0) == (flo < 0.0) {
            a = x;
        } else {
            b = x;
        }
        let newton = x - fx / dfx;
        let next = if a < newton && newton < b {
            newton
        } else {
            0.5 * (a + b)
        };
        if next == x
            || (next - x).abs() <= 2.0 * f64::EPSILON * x.abs()
            || b - a <= 4.0 * f64::EPSILON * a.abs().max(b.abs())
        {
            return next;
        }
        x = next;
    }
    x
}
