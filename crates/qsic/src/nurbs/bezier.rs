//! Rational Bézier segments of a rational curve, exactly.
//!
//! A rational component is a binary form `X(U₀, U₁) = Σᵢ xᵢ U₀ⁱ U₁ⁿ⁻ⁱ` (`xᵢ ∈ K⁴`, `u = U₀/U₁`).
//! On the segment of ℝP¹ from `P` to `Q` (homogeneous representatives, `t ∈ [0, 1]`,
//! `U(t) = (1 − t)·P + t·Q`), `X(U(t))` is a form of degree `n` in `(1 − t, t)`:
//! `Σⱼ cⱼ (1 − t)ⁿ⁻ʲ tʲ`, and its Bernstein coefficients are `bⱼ = cⱼ / C(n, j)` — the
//! homogeneous control points. Nothing is approximated: `bⱼ ∈ K⁴` when `P, Q ∈ ℚ²`.
//!
//! The segment runs through the points of increasing `u` from `P` to `Q` when
//! `det(P, Q) = P₀Q₁ − P₁Q₀ < 0` (through `u = ∞` when `P₁` and `Q₁` have opposite signs):
//! [`oriented`] picks the sign of `Q` that makes it so.

use crate::param::{Number, Point, PointPoly};
use qsic_algebra::{Field, IBig, RBig, Ring, Sign};

/// A point of ℝP¹ with rational homogeneous coordinates `(U₀, U₁)`, `u = U₀/U₁`.
pub type ParamPoint = [RBig; 2];

/// `C(n, k)`.
pub(crate) fn binomial(n: usize, k: usize) -> IBig {
    let mut c = IBig::ONE;
    for i in 0..k {
        c = c * IBig::from(n - i) / IBig::from(i + 1);
    }
    c
}

/// The rational `v` as a [`Number`].
pub(crate) fn num(v: RBig) -> Number {
    Number::rational(v)
}

/// `det(P, Q) = P₀Q₁ − P₁Q₀`.
fn det(p: &ParamPoint, q: &ParamPoint) -> RBig {
    &p[0] * &q[1] - &p[1] * &q[0]
}

/// `Q` or `−Q`, so that `(1 − t)P + tQ` runs from `P` to `Q` through increasing `u`.
///
/// # Panics
/// If `P` and `Q` are the same point of ℝP¹ (a caller bug: a segment has two ends).
pub(crate) fn oriented(p: &ParamPoint, q: &ParamPoint) -> ParamPoint {
    let d = det(p, q);
    assert!(d != RBig::ZERO, "a segment from a point to itself");
    if d < RBig::ZERO {
        q.clone()
    } else {
        [-q[0].clone(), -q[1].clone()]
    }
}

/// The coefficients of `(A·s + B·t)ᵏ` as a form in `(s, t)`: index `j` is `s^(k−j) tʲ`.
fn linear_power(a: &RBig, b: &RBig, k: usize) -> Vec<RBig> {
    (0..=k)
        .map(|j| RBig::from(binomial(k, j)) * pow(a, k - j) * pow(b, j))
        .collect()
}

/// `vᵏ`.
fn pow(v: &RBig, k: usize) -> RBig {
    let mut acc = RBig::ONE;
    for _ in 0..k {
        acc *= v;
    }
    acc
}

/// The product of two forms in `(s, t)` given by their coefficient vectors.
fn convolve(a: &[RBig], b: &[RBig]) -> Vec<RBig> {
    let mut out = vec![RBig::ZERO; a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}

/// The homogeneous Bernstein control points `b₀ … bₙ` of `X` (degree `n`) on the segment from
/// `p` to `q` (representatives as given: the caller orients them).
pub(crate) fn bezier_on(x: &PointPoly, n: usize, p: &ParamPoint, q: &ParamPoint) -> Vec<Point> {
    // (U₀)ⁱ (U₁)ⁿ⁻ⁱ as forms in (s, t) = (1 − t, t)
    let monomials: Vec<Vec<RBig>> = (0..=n)
        .map(|i| {
            convolve(
                &linear_power(&p[0], &q[0], i),
                &linear_power(&p[1], &q[1], n - i),
            )
        })
        .collect();
    (0..=n)
        .map(|j| {
            let scale = RBig::ONE / RBig::from(binomial(n, j));
            std::array::from_fn(|c| {
                let mut acc = Number::zero();
                for (i, m) in monomials.iter().enumerate() {
                    let xi = x[c].coeff(i);
                    if !xi.is_zero() && m[j] != RBig::ZERO {
                        acc = acc.add(&xi.mul(&num(&m[j] * &scale)));
                    }
                }
                acc
            })
        })
        .collect()
}

/// The point of the Bézier segment with homogeneous control points `b` at `t` (de Casteljau,
/// exact).
pub fn evaluate(b: &[Point], t: &RBig) -> Point {
    let (t, s) = (num(t.clone()), num(RBig::ONE - t));
    let mut work: Vec<Point> = b.to_vec();
    for level in 1..work.len() {
        for i in 0..work.len() - level {
            work[i] = std::array::from_fn(|c| s.mul(&work[i][c]).add(&t.mul(&work[i + 1][c])));
        }
    }
    work[0].clone()
}

/// The segments of `X` from `p` to `q` (oriented by the caller) whose weights (Bernstein
/// coefficients of `w`) are all positive: the segment itself, else its halves at the
/// homogeneous midpoint `p + q`, recursively (a work list; at most `2^MAX_SPLITS` pieces).
/// A segment whose weights are all negative is negated (the same points).
///
/// Where `w ≠ 0` on the closed segment the Bernstein coefficients of the halves converge to
/// the values of `w`, so the splitting ends.
///
/// # Errors
/// A message when an end point is `(0, 0, 0, 0)` or the weights do not become of one sign
/// (`w` vanishes on the segment: a caller bug, the segments avoid infinity).
pub(crate) fn positive_segments(
    x: &PointPoly,
    n: usize,
    p: &ParamPoint,
    q: &ParamPoint,
) -> Result<Vec<Vec<Point>>, String> {
    const MAX_SPLITS: usize = 24;
    let mut out = Vec::new();
    let mut work = vec![(p.clone(), q.clone(), 0usize)];
    while let Some((p, q, depth)) = work.pop() {
        let mut b = bezier_on(x, n, &p, &q);
        for end in [&b[0], &b[n]] {
            if end.iter().all(|c| c.is_zero()) {
                return Err("the parameterization vanishes at a segment end".into());
            }
        }
        let signs: Vec<Sign> = b.iter().map(|c| c[3].sign()).collect();
        if signs.iter().all(|s| *s == Sign::Negative) {
            for c in &mut b {
                for v in c.iter_mut() {
                    *v = Ring::neg(v);
                }
            }
        }
        if signs.iter().all(|s| *s == Sign::Negative) || signs.iter().all(|s| *s == Sign::Positive)
        {
            out.push(b);
            continue;
        }
        if depth >= MAX_SPLITS {
            return Err("the weights of a segment do not become positive".into());
        }
        let m = [&p[0] + &q[0], &p[1] + &q[1]];
        // work is a stack: push the second half first, so the first comes out first
        work.push((m.clone(), q, depth + 1));
        work.push((p, m, depth + 1));
    }
    Ok(out)
}

/// `b` scaled by `k` (the same points).
pub(crate) fn scaled(b: &[Point], k: &Number) -> Vec<Point> {
    b.iter()
        .map(|c| std::array::from_fn(|i| c[i].mul(k)))
        .collect()
}

/// `v / w` (`w ≠ 0`).
pub(crate) fn divide(v: &Number, w: &Number) -> Number {
    v.div(w).expect("a nonzero weight")
}

#[cfg(test)]
mod tests {
    use super::*;
    use qsic_algebra::Poly;

    fn r(n: i64, d: i64) -> RBig {
        RBig::from_parts_signed(n.into(), d.into())
    }

    fn rational_poly(c: &[i64]) -> crate::param::NumberPoly {
        Poly::new(c.iter().map(|&v| num(RBig::from(v))).collect())
    }

    /// The Bézier segment reproduces `X` at every `t`, through `u = ∞` too: the point at `t`
    /// is proportional to `X(U(t))`.
    #[test]
    fn bezier_segments_reproduce_the_curve() {
        // the twisted cubic (1, u, u², u³) written as (x, y, z, w) = (u, u², u³, 1 + u²)
        let x: PointPoly = [
            rational_poly(&[0, 1]),
            rational_poly(&[0, 0, 1]),
            rational_poly(&[0, 0, 0, 1]),
            rational_poly(&[1, 0, 1]),
        ];
        let ends: [(ParamPoint, ParamPoint); 3] = [
            ([r(-1, 1), r(1, 1)], [r(2, 1), r(1, 1)]),
            ([r(3, 1), r(1, 1)], [r(1, 1), r(0, 1)]),
            ([r(5, 2), r(1, 1)], [r(-7, 3), r(1, 1)]),
        ];
        for (p, q) in ends {
            let q = oriented(&p, &q);
            let b = bezier_on(&x, 3, &p, &q);
            for k in 0..=8 {
                let t = r(k, 8);
                let u0 = (RBig::ONE - &t) * &p[0] + &t * &q[0];
                let u1 = (RBig::ONE - &t) * &p[1] + &t * &q[1];
                let want: Point = std::array::from_fn(|c| {
                    let mut acc = RBig::ZERO;
                    for i in 0..=3 {
                        let xi = x[c].coeff(i).representative().coeff(0);
                        acc += xi * pow(&u0, i) * pow(&u1, 3 - i);
                    }
                    num(acc)
                });
                assert_eq!(evaluate(&b, &t), want, "t = {t}");
            }
        }
    }

    /// A circle traced through more than half its length needs a split for positive weights.
    #[test]
    fn long_circle_arcs_split_until_the_weights_are_positive() {
        // (1 − u², 2u, 0, 1 + u²): the unit circle
        let x: PointPoly = [
            rational_poly(&[1, 0, -1]),
            rational_poly(&[0, 2]),
            rational_poly(&[0]),
            rational_poly(&[1, 0, 1]),
        ];
        let p = [r(-3, 1), r(1, 1)];
        let q = oriented(&p, &[r(3, 1), r(1, 1)]);
        let segs = positive_segments(&x, 2, &p, &q).unwrap();
        assert!(segs.len() > 1, "{} segment(s)", segs.len());
        for s in &segs {
            assert!(s.iter().all(|c| c[3].sign() == Sign::Positive));
        }
        // consecutive segments meet
        for w in segs.windows(2) {
            let (a, b) = (&w[0][2], &w[1][0]);
            for i in 0..3 {
                assert_eq!(divide(&a[i], &a[3]), divide(&b[i], &b[3]));
            }
        }
    }
}
