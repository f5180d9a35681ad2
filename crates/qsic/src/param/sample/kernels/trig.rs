//! `(sin θ, cos θ)` for the parameters of the walk. [`sin_cos`] reduces `θ` by the nearest
//! multiple of `π/2` in two parts (`k·P₁` exact for `|k| < 2²⁰`) and sums the Taylor series
//! on `|r| ≤ π/4` to `r¹⁸`: within a few ulps (any `(U₀, U₁)` is a parameter: the accuracy
//! only places the point at `θ`); the library's beyond `|θ| ≤ 2¹⁸`. [`grid_parameters`]
//! advances a grid by rotations of the step, exact again every [`RESYNC`] points, so the
//! drift stays below `RESYNC` roundings.

/// Grid points between exact values of `(sin θ, cos θ)` ([`Evaluator::grid`]).
pub(in crate::param::sample) const RESYNC: usize = 64;

/// The reduced parameters ([`reduced_parameter`]) of the grid `θₖ = t₀ + k·step`,
/// `k = 1, …, n − 1`: `(sin θₖ, cos θₖ)` by rotations from `(0, 1)`, exact every
/// [`RESYNC`] points.
pub(in crate::param::sample) fn grid_parameters(
    t0: f64,
    step: f64,
    n: usize,
) -> impl Iterator<Item = (f64, bool)> {
    let (sh, ch) = sin_cos(step);
    let mut u = (0.0, 1.0);
    (1..n).map(move |k| {
        u = if k % RESYNC == 1 {
            sin_cos(t0 + step * (k as f64))
        } else {
            (u.0 * ch + u.1 * sh, u.1 * ch - u.0 * sh)
        };
        reduced_parameter(u)
    })
}

/// `(sin θ, cos θ)` within a few ulps, cheaper than the library's: `θ` reduced by the
/// nearest multiple of `π/2` (in two parts: `k·P₁` exact for `|k| < 2²⁰`), then the Taylor
/// series on `|r| ≤ π/4` to `r¹⁷` and `r¹⁸` (the first terms left out below `10⁻¹⁹`). For the
/// parameters of single evaluations ([`Sampler::at`]): any `(U₀, U₁)` is a parameter, the
/// accuracy only places the point at `θ`. The library's beyond `|θ| ≤ 2¹⁸` (and for NaN).
pub(in crate::param::sample) fn sin_cos(theta: f64) -> (f64, f64) {
    if theta.is_nan() || theta.abs() > 262_144.0 {
        return theta.sin_cos();
    }
    // π/2 = P₁ + P₂, P₁ with 33 significant bits
    const P1: f64 = f64::from_bits(0x3FF9_21FB_5440_0000);
    const P2: f64 = f64::from_bits(0x3DD0_B461_1A62_6331);
    let k = (theta * std::f64::consts::FRAC_2_PI).round();
    let r = (theta - k * P1) - k * P2;
    let r2 = r * r;
    const S: [f64; 8] = [
        -1.0 / 6.0,
        1.0 / 120.0,
        -1.0 / 5_040.0,
        1.0 / 362_880.0,
        -1.0 / 39_916_800.0,
        1.0 / 6_227_020_800.0,
        -1.0 / 1_307_674_368_000.0,
        1.0 / 355_687_428_096_000.0,
    ];
    const C: [f64; 9] = [
        -1.0 / 2.0,
        1.0 / 24.0,
        -1.0 / 720.0,
        1.0 / 40_320.0,
        -1.0 / 3_628_800.0,
        1.0 / 479_001_600.0,
        -1.0 / 87_178_291_200.0,
        1.0 / 20_922_789_888_000.0,
        -1.0 / 6_402_373_705_728_000.0,
    ];
    let ps = S.iter().rev().fold(0.0, |v, c| v * r2 + c);
    let pc = C.iter().rev().fold(0.0, |v, c| v * r2 + c);
    let (sin, cos) = (r + r * r2 * ps, 1.0 + r2 * pc);
    match (k as i64) & 3 {
        0 => (sin, cos),
        1 => (cos, -sin),
        2 => (-sin, -cos),
        _ => (-cos, sin),
    }
}

/// `X(U₀, U₁)` as `t = U₀/U₁` (`|t| ≤ 1`) or `t = U₁/U₀` with the coefficients reversed.
pub(in crate::param::sample) fn reduced_parameter(u: (f64, f64)) -> (f64, bool) {
    if u.1.abs() >= u.0.abs() {
        (u.0 / u.1, false)
    } else {
        (u.1 / u.0, true)
    }
}
