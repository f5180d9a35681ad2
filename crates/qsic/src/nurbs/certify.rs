//! A proved bound on the Euclidean distance from a polynomial Bézier segment to a quadric
//! surface, in exact arithmetic.
//!
//! Let `f(x) = x̃ᵀMx̃` (`x̃ = (x, 1)`, `M` symmetric) and `B(t) = Σⱼ Bⱼⁿ(t)Pⱼ`, `t ∈ [0, 1]`,
//! with dyadic control points `Pⱼ` (floats, read exactly). Then
//! - `f(B(t)) = Σₖ cₖ Bₖ²ⁿ(t)` with `cₖ = Σ_{i+j=k} C(n,i)C(n,j)/C(2n,k) · P̃ᵢᵀMP̃ⱼ`, so
//!   `|f(B(t))| ≤ F = maxₖ |cₖ|` (the Bernstein basis is a partition of unity, nonnegative);
//! - `∇f(x) = 2(Mx̃)₁..₃` is affine in `x`, so `|∇f(B(t))|² = Σₖ eₖ Bₖ²ⁿ(t)` with
//!   `eₖ = Σ_{i+j=k} C(n,i)C(n,j)/C(2n,k) · gᵢ·gⱼ`, `gⱼ = 2(MP̃ⱼ)₁..₃`, and
//!   `|∇f(B(t))|² ≥ E = minₖ eₖ`;
//! - along the unit normal `ν` at `x`, `f(x − r·sign(f)·ν) = f(x) − r|∇f(x)|·sign(f) + r²νᵀM₃ν`
//!   exactly (a quadric), and `|νᵀM₃ν| ≤ N = ‖M₃‖_F` (the Frobenius norm of the 3×3 block
//!   bounds the spectral norm). At `r = 2|f|/|∇f|` the value has the other sign as soon as
//!   `4N|f| < |∇f|²`, so the surface is within `2|f|/|∇f|` of `x`.
//!
//! Hence, when `E > 0` and `E² > 16N²F²`, every point of the segment lies within
//! `2F/√E` of the surface; [`segment_bound`] returns the square `4F²/E`, exactly. The bound is
//! invariant under scaling `M`, so `M` is any positive multiple of the surface's matrix.

use qsic_algebra::{IBig, RBig, UBig};

/// A quadric's matrix as integers (a positive multiple of the exact matrix) and the square
/// of the Frobenius norm of its 3×3 block.
#[derive(Clone, Debug)]
pub(super) struct ExactQuadric {
    m: [[IBig; 4]; 4],
    frobenius2: IBig,
}

impl ExactQuadric {
    /// The quadric of the rational symmetric matrix `m`, multiplied by the common
    /// denominator of its entries.
    pub(super) fn new(m: &[[RBig; 4]; 4]) -> ExactQuadric {
        use dashu_int::ops::Gcd;
        let mut den = UBig::ONE;
        for row in m {
            for v in row {
                let d = v.denominator();
                let g = (&den).gcd(d);
                den = &den / g * d;
            }
        }
        let m: [[IBig; 4]; 4] = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let v = &m[i][j] * RBig::from(den.clone());
                debug_assert!(*v.denominator() == UBig::ONE);
                v.numerator().clone()
            })
        });
        let mut frobenius2 = IBig::ZERO;
        for row in m.iter().take(3) {
            for v in row.iter().take(3) {
                frobenius2 += v * v;
            }
        }
        ExactQuadric { m, frobenius2 }
    }
}

/// The float `x` as `m·2ᵉ` with an integer `m`.
fn dyadic(x: f64) -> (IBig, i32) {
    debug_assert!(x.is_finite());
    if x == 0.0 {
        return (IBig::ZERO, 0);
    }
    let bits = x.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i32;
    let frac = (bits & ((1u64 << 52) - 1)) as i64;
    let (mant, e) = if exp == 0 {
        (frac, -1074)
    } else {
        (frac | (1i64 << 52), exp - 1075)
    };
    let mant = if x < 0.0 { -mant } else { mant };
    (IBig::from(mant), e)
}

/// The control points as integer homogeneous vectors `(X, Y, Z, W)` with one `W = 2ᵏ`:
/// `Pⱼ = (X, Y, Z)/W` exactly.
fn homogeneous(points: &[[f64; 3]]) -> (Vec<[IBig; 4]>, IBig) {
    let parts: Vec<[(IBig, i32); 3]> = points.iter().map(|p| p.map(dyadic)).collect();
    let low = parts
        .iter()
        .flatten()
        .filter(|(m, _)| *m != IBig::ZERO)
        .map(|(_, e)| *e)
        .min()
        .unwrap_or(0)
        .min(0);
    let w = IBig::ONE << (-low) as usize;
    let out = parts
        .into_iter()
        .map(|p| {
            let [x, y, z] = p.map(|(m, e)| m << (e - low) as usize);
            [x, y, z, w.clone()]
        })
        .collect();
    (out, w)
}

/// `C(n, k)` for the small degrees of the segments (`n ≤ 60`: no overflow in `u64`).
fn small_binomial(n: usize, k: usize) -> u64 {
    debug_assert!(n <= 60);
    (0..k).fold(1u64, |c, i| c * (n - i) as u64 / (i + 1) as u64)
}

fn gcd_u64(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// The square of the proved distance bound of the Bézier segment with control points
/// `points` to the quadric `q` (module docs), or `None` when the certificate does not hold
/// (the gradient may vanish on the segment, or `f` is too large for its gradient there).
///
/// In integers: with `P̃ⱼ = Vⱼ/W` and `L` a common multiple of the `C(2n, k)`, the sums
/// `F′ₖ = |Σ C(n,i)C(n,j)·VᵢᵀMVⱼ|·L/C(2n,k)` and `G′ₖ = Σ C(n,i)C(n,j)·(MVᵢ)₃·(MVⱼ)₃·L/C(2n,k)`
/// give `F = max F′/(LW²)` and `E = 4 min G′/(LW²)`, so `E² > 16N²F²` is `G′² > N²F′²` and
/// the bound's square `4F²/E` is `F′²/(LW²G′)`; the terms `(i, j)` and `(j, i)` are equal
/// (`M` symmetric), counted once, twice over.
pub(super) fn segment_bound(q: &ExactQuadric, points: &[[f64; 3]]) -> Option<RBig> {
    let n = points.len().checked_sub(1)?;
    let (v, w) = homogeneous(points);
    let mv: Vec<[IBig; 4]> = v
        .iter()
        .map(|p| std::array::from_fn(|i| (0..4).map(|j| &q.m[i][j] * &p[j]).sum()))
        .collect();
    let binom: Vec<u64> = (0..=n).map(|i| small_binomial(n, i)).collect();
    let outer: Vec<u64> = (0..=2 * n).map(|k| small_binomial(2 * n, k)).collect();
    let l = outer.iter().fold(1u64, |l, c| l / gcd_u64(l, *c) * c);
    let mut f_max = IBig::ZERO;
    let mut g_min: Option<IBig> = None;
    for k in 0..=2 * n {
        let mut fk = IBig::ZERO;
        let mut gk = IBig::ZERO;
        for i in k.saturating_sub(n)..=k.min(n) {
            let j = k - i;
            if i > j {
                continue;
            }
            let c = IBig::from(binom[i] * binom[j] * if i < j { 2 } else { 1 });
            let f: IBig = (0..4).map(|a| &v[i][a] * &mv[j][a]).sum();
            let g: IBig = (0..3).map(|a| &mv[i][a] * &mv[j][a]).sum();
            fk += &c * f;
            gk += c * g;
        }
        let scale = IBig::from(l / outer[k]);
        let fk = if fk < IBig::ZERO { -fk } else { fk } * &scale;
        let gk = gk * scale;
        if fk > f_max {
            f_max = fk;
        }
        if g_min.as_ref().is_none_or(|g| gk < *g) {
            g_min = Some(gk);
        }
    }
    let g = g_min?;
    if g <= IBig::ZERO {
        return None;
    }
    let f2 = &f_max * &f_max;
    if &g * &g <= &q.frobenius2 * &f2 {
        return None;
    }
    Some(RBig::from(f2) / RBig::from(IBig::from(l) * &w * &w * g))
}

/// The smallest float at least `√x` (`x ≥ 0` exact).
pub(super) fn sqrt_up(x: &RBig) -> f64 {
    let mut r = x.to_f64().value().max(0.0).sqrt();
    loop {
        let Ok(exact) = RBig::try_from(r) else {
            return f64::INFINITY;
        };
        if &exact * &exact >= *x {
            return r;
        }
        // the next float up (r ≥ 0 and finite here)
        r = f64::from_bits(r.to_bits() + 1);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_sphere() -> ExactQuadric {
        let mut m: [[RBig; 4]; 4] = Default::default();
        for i in 0..3 {
            m[i][i] = RBig::ONE;
        }
        m[3][3] = -RBig::ONE;
        ExactQuadric::new(&m)
    }

    /// A segment on the sphere's tangent plane at (0, 0, 1): from (0,0,1) to (h,0,1), its
    /// farthest point at distance √(1+h²) − 1 ≈ h²/2 from the sphere.
    #[test]
    fn a_chord_off_the_sphere_is_bounded_by_its_true_distance_and_not_much_more() {
        let s = unit_sphere();
        for h in [0.5f64, 0.1, 1e-3] {
            let line: Vec<[f64; 3]> = (0..=3).map(|j| [h * j as f64 / 3.0, 0.0, 1.0]).collect();
            let b2 = segment_bound(&s, &line).expect("certified");
            let b = sqrt_up(&b2);
            let true_distance = (1.0 + h * h).sqrt() - 1.0;
            assert!(b >= true_distance, "h = {h}: {b} < {true_distance}");
            assert!(b <= 2.5 * true_distance, "h = {h}: {b} ≫ {true_distance}");
        }
    }

    /// A control point moved off the surface moves the bound: the certificate reads every
    /// point.
    #[test]
    fn every_control_point_counts() {
        let s = unit_sphere();
        let arc: Vec<[f64; 3]> = vec![[0.0, 0.0, 1.0], [0.0, 0.0, 1.0], [0.0, 0.0, 1.0]];
        assert_eq!(segment_bound(&s, &arc), Some(RBig::ZERO));
        for k in 0..3 {
            let mut moved = arc.clone();
            moved[k][2] += 1e-6;
            let b = sqrt_up(&segment_bound(&s, &moved).expect("certified"));
            assert!(b > 1e-8 && b < 1e-5, "point {k}: {b}");
        }
    }

    /// Through the centre the gradient vanishes: no certificate.
    #[test]
    fn no_certificate_where_the_gradient_may_vanish() {
        let s = unit_sphere();
        let through: Vec<[f64; 3]> = vec![[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0]];
        assert_eq!(segment_bound(&s, &through), None);
        // x² − y² = 1 seen from (0, 10, 0): f = −101 and |∇f|² = 400, so 4N|f| > |∇f|²:
        // the Newton step 2|f|/|∇f| is no proof there
        let mut m: [[RBig; 4]; 4] = Default::default();
        m[0][0] = RBig::ONE;
        m[1][1] = -RBig::ONE;
        m[3][3] = -RBig::ONE;
        let h = ExactQuadric::new(&m);
        let far: Vec<[f64; 3]> = vec![[0.0, 10.0, 0.0]; 2];
        assert_eq!(segment_bound(&h, &far), None);
        // nearer the surface it is: (1.01, 0, 0), f ≈ 0.02, |∇f|² ≈ 4
        let near: Vec<[f64; 3]> = vec![[1.01, 0.0, 0.0]; 2];
        let b = sqrt_up(&segment_bound(&h, &near).expect("certified"));
        assert!((0.01..0.021).contains(&b), "{b}");
    }

    #[test]
    fn floats_are_read_exactly() {
        for x in [0.1f64, -3.75, 1e-300, 5e-324, 1.5e300] {
            let (m, e) = dyadic(x);
            let back = if e >= 0 {
                RBig::from(m << e as usize)
            } else {
                RBig::from(m) / RBig::from(IBig::ONE << (-e) as usize)
            };
            assert_eq!(back, RBig::try_from(x).unwrap(), "{x}");
        }
        assert_eq!(sqrt_up(&RBig::from(4)), 2.0);
        let two = sqrt_up(&RBig::from(2));
        assert!(RBig::try_from(two).unwrap().pow(2) >= RBig::from(2));
        assert!(RBig::try_from(two.next_down()).unwrap().pow(2) < RBig::from(2));
    }
}
