//! The curve in ℝ³ without building the curve, where the class and the conics at infinity
//! decide it.
//!
//! The curve's points on the plane at infinity are the common points of the conics at
//! infinity `C_A`, `C_B` (the upper-left 3×3 blocks of the matrices in the chart):
//! [`conic_real_intersections`] counts the real ones with their intersection multiplicities.
//!
//! A nonsingular quartic (cases 1–4) has no singular point, and its real branches are disjoint
//! closed loops of ℝP³; a branch through `m ≥ 1` real points at infinity leaves `m`
//! unbounded arcs in ℝ³, a branch that misses the plane one bounded curve. The class fixes
//! the branches: case 1 two ovals (each meets a plane with even total multiplicity), case 2
//! none, case 3 one oval, case 4 two odd branches (each meets every plane). So with `P` the
//! number of real points at infinity, `curves_unbounded = P`, and `curves_bounded` is `2`,
//! `0`, `[P = 0]`, `0` — in case 1 `2` for `P = 0`, `1` when parity puts every point on one
//! oval (`P = 1`, or `P = 2` with odd multiplicities); otherwise the points may lie on either
//! oval and [`fast_affine_curve`] declines (`None`).

use super::{AffineComponent, AffineCurve, Chart};
use crate::classify::{classify, ComponentKind, PencilKind};
use crate::quadric::Quadric;
use qsic_algebra::poly::binary::BinaryForm;
use qsic_algebra::{IBig, Poly, RBig};

/// The real common points of the conics `XᵀC_AX = 0`, `XᵀC_BX = 0` of ℝP², as the list of
/// their intersection multiplicities (one entry per distinct point); `None` when the conics
/// share a component (infinitely many common points).
///
/// A definite `C_A` or `C_B` has no real point. Otherwise, projected from a centre `c` on
/// neither conic nor on a line through two common points (the first of `(j, j³, 1)`,
/// `j = 0, 1, …` that passes the tests below: at most 30 fail, as the cubic `y = x³` meets a
/// conic at most 6 times and a line at most 3 times), the common points are the roots of the
/// resultant `R` of the two
/// conics along the lines through `c`, a binary quartic, each with its intersection
/// multiplicity; a real root is a real point because the common point on its line is then the
/// single root of the first subresultant `G₁z + G₀`, which has real coefficients. The centre
/// passes when no root of `R` is a root of both `G₁` and `G₀` (then two common points would
/// share the line). Exact throughout: Sturm counts on the square-free factors of `R`.
///
/// ```
/// use qsic::affine::conic_real_intersections;
/// use qsic_algebra::RBig;
/// let m = |d: [i64; 3]| -> [[RBig; 3]; 3] {
///     std::array::from_fn(|i| std::array::from_fn(|j| RBig::from(if i == j { d[i] } else { 0 })))
/// };
/// // x² + y² = 1 and 4x² + y² = 1 meet at (0, ±1), tangentially (multiplicity 2 each)
/// assert_eq!(conic_real_intersections(&m([1, 1, -1]), &m([4, 1, -1])), Some(vec![2, 2]));
/// // x² + y² = 1 and x² + 4y² = 2: four transversal points
/// assert_eq!(conic_real_intersections(&m([1, 1, -1]), &m([1, 4, -2])), Some(vec![1, 1, 1, 1]));
/// // a definite conic has no real point
/// assert_eq!(conic_real_intersections(&m([1, 1, 1]), &m([1, -1, 0])), Some(vec![]));
/// // a conic with itself: infinitely many
/// assert_eq!(conic_real_intersections(&m([1, 1, -1]), &m([2, 2, -2])), None);
/// ```
pub fn conic_real_intersections(ca: &[[RBig; 3]; 3], cb: &[[RBig; 3]; 3]) -> Option<Vec<usize>> {
    real_intersections(&super::integral(ca), &super::integral(cb))
}

/// [`conic_real_intersections`] of integer matrices.
fn real_intersections(ca: &[[IBig; 3]; 3], cb: &[[IBig; 3]; 3]) -> Option<Vec<usize>> {
    if is_definite(ca) || is_definite(cb) {
        return Some(Vec::new());
    }
    // at most 30 centres fail (the cubic (j, j³) meets each conic at most 6 times and each
    // of the 6 lines through two common points at most 3 times): 31 tries always succeed
    for j in 0..=30i64 {
        let (p, q) = (moved(ca, j), moved(cb, j));
        if p[2][2] == IBig::ZERO || q[2][2] == IBig::ZERO {
            continue; // the centre lies on a conic
        }
        // each conic as a₂z² + a₁z + a₀ with a_k binary forms in (x, y), in the chart y = 1
        let along = |c: &[[IBig; 3]; 3]| -> [Poly; 3] {
            let two = IBig::from(2);
            [
                Poly::new(vec![c[1][1].clone(), &two * &c[0][1], c[0][0].clone()]),
                Poly::new(vec![&two * &c[1][2], &two * &c[0][2]]),
                Poly::constant(c[2][2].clone()),
            ]
        };
        let ([a0, a1, a2], [b0, b1, b2]) = (along(&p), along(&q));
        let g0 = &(&a2 * &b0) - &(&a0 * &b2);
        let g1 = &(&a2 * &b1) - &(&a1 * &b2);
        let h = &(&a1 * &b0) - &(&a0 * &b1);
        let r = &(&g0 * &g0) - &(&g1 * &h);
        if r.is_zero() {
            return None; // a common component (a centre off both conics: R ≢ 0 otherwise)
        }
        let rf = BinaryForm::new(r, 4);
        let shared = rf.gcd(&BinaryForm::new(g0, 2)).gcd(&BinaryForm::new(g1, 1));
        if shared.degree() > 0 {
            continue; // two common points on one line through the centre
        }
        let mut out = Vec::new();
        for (f, m) in rf.chart().squarefree_decomposition() {
            if f.degree().unwrap_or(0) > 0 {
                out.extend(std::iter::repeat_n(m, f.count_real_roots_sturm()));
            }
        }
        if rf.multiplicity_at_infinity() > 0 {
            out.push(rf.multiplicity_at_infinity());
        }
        out.sort_unstable();
        return Some(out);
    }
    unreachable!("at most 30 of 31 centres are special for two conics without common component")
}

/// Whether a symmetric 3×3 matrix is definite (inertia (3, 0) or (0, 3)).
fn is_definite(m: &[[IBig; 3]; 3]) -> bool {
    let i = super::inertia(m);
    i.positive == 3 || i.negative == 3
}

/// `TᵀCT` for `T = [[1, 0, j], [0, 1, j³], [0, 0, 1]]`: the conic in coordinates where the
/// point `(j, j³, 1)` is `(0, 0, 1)`.
fn moved(c: &[[IBig; 3]; 3], j: i64) -> [[IBig; 3]; 3] {
    if j == 0 {
        return c.clone();
    }
    let t: [[IBig; 3]; 3] = [
        [IBig::ONE, IBig::ZERO, IBig::from(j)],
        [IBig::ZERO, IBig::ONE, IBig::from(j * j * j)],
        [IBig::ZERO, IBig::ZERO, IBig::ONE],
    ];
    std::array::from_fn(|i| {
        std::array::from_fn(|k| {
            let mut acc = IBig::ZERO;
            for r in 0..3 {
                for s in 0..3 {
                    if t[r][i] != IBig::ZERO && t[s][k] != IBig::ZERO {
                        acc += &t[r][i] * &c[r][s] * &t[s][k];
                    }
                }
            }
            acc
        })
    })
}

/// The conic at infinity of `q` in `chart`: the upper-left 3×3 block of its matrix there
/// (a positive multiple: integers).
fn conic_at_infinity(q: &Quadric, chart: &Chart) -> [[IBig; 3]; 3] {
    let m = super::integer_matrix_in_chart(q, chart);
    std::array::from_fn(|i| std::array::from_fn(|j| m[i][j].clone()))
}

/// The curve in ℝ³ of a nonsingular quartic (cases 1–4) from its class and its real points
/// at infinity (see the module documentation), or `None` when these do not decide it (other
/// classes; case 1 with points at infinity that may lie on either oval) — then the curve
/// must be built ([`crate::param::parameterize`], [`super::affine_curve`]), whose answer
/// this one equals wherever it is given.
///
/// ```
/// use qsic::{affine::{fast_affine_curve, Chart}, io::parse_quadric};
/// let q = |s: &str| parse_quadric(s).unwrap();
/// // a sphere and a cylinder crossing it: two bounded loops
/// let c = fast_affine_curve(&q("x^2+y^2+z^2-4"), &q("x^2+2*y^2-1"), &Chart::default()).unwrap();
/// assert_eq!((c.curves_bounded, c.curves_unbounded, c.points_at_infinity), (2, 0, 0));
/// // a hyperboloid of one sheet and a hyperboloid of two sheets (case 3): one branch
/// // through four points at infinity, four unbounded arcs
/// let h = q("x^2+y^2-z^2-1");
/// let c = fast_affine_curve(&h, &q("2*x^2-y^2-z^2+x+z-1"), &Chart::default()).unwrap();
/// assert_eq!((c.curves_bounded, c.curves_unbounded, c.points_at_infinity), (0, 4, 4));
/// // case 1 with four points at infinity: on one oval or two? The curve decides.
/// assert!(fast_affine_curve(&h, &q("x*y-z-1"), &Chart::default()).is_none());
/// ```
pub fn fast_affine_curve(a: &Quadric, b: &Quadric, chart: &Chart) -> Option<AffineCurve> {
    let class = classify(a, b);
    if class.pencil != PencilKind::Regular {
        return None;
    }
    let case = class.case?;
    if !(1..=4).contains(&case) {
        return None;
    }
    let points = real_intersections(&conic_at_infinity(a, chart), &conic_at_infinity(b, chart))?;
    let p = points.len();
    let odd = points.iter().all(|m| m % 2 == 1);
    let bounded = match (case, p) {
        (1, 0) => 2,
        (1, 1) => 1,
        (1, 2) if odd => 1,
        (2, 0) => 0,
        (3, 0) => 1,
        (3, _) => 0,
        (4, 2..) => 0,
        // case 1 otherwise: undecided; cases 2 and 4 otherwise: inconsistent, let the
        // curve decide
        _ => return None,
    };
    let real = case != 2;
    Some(AffineCurve {
        curves_bounded: bounded,
        curves_unbounded: p,
        isolated_points: 0,
        points_at_infinity: p,
        singular_finite: 0,
        singular_at_infinity: 0,
        components: vec![AffineComponent {
            kind: ComponentKind::Quartic,
            name: real.then_some("quartic"),
            at_infinity: false,
            bounded: real.then_some(p == 0),
            points_at_infinity: p,
            multiplicity: 1,
        }],
        singular_points: Vec::new(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn conic(c: [[i64; 3]; 3]) -> [[RBig; 3]; 3] {
        c.map(|r| r.map(RBig::from))
    }

    /// Conics through known points, by construction: `C = L₁L₂ + t·M₁M₂` for line pairs
    /// through chosen points, compared with the count and multiplicities by hand.
    #[test]
    fn hand_made_conic_pairs() {
        // x·y = 0 (two lines) and x² + y² = z²: 4 points (±1, 0), (0, ±1)
        let xy = conic([[0, 1, 0], [1, 0, 0], [0, 0, 0]]);
        let circle = conic([[1, 0, 0], [0, 1, 0], [0, 0, -1]]);
        assert_eq!(conic_real_intersections(&xy, &circle), Some(vec![1; 4]));
        // y = 0 doubled and the circle: (±1, 0), each of multiplicity 2
        let yy = conic([[0, 0, 0], [0, 1, 0], [0, 0, 0]]);
        assert_eq!(conic_real_intersections(&yy, &circle), Some(vec![2, 2]));
        // (y − z)² and the circle: tangent line at (0, 1): one point of multiplicity 4
        let tangent = conic([[0, 0, 0], [0, 1, -1], [0, -1, 1]]);
        assert_eq!(conic_real_intersections(&tangent, &circle), Some(vec![4]));
        // the parabola y·z = x² and the circle: x² + y² = 1, y = x² → y² + y − 1 = 0:
        // y = (−1 + √5)/2 gives two points, the other root y < −1 none; and (0, 1, 0)? not
        // on the circle. Two transversal points.
        let parabola = conic([[2, 0, 0], [0, 0, -1], [0, -1, 0]]);
        assert_eq!(
            conic_real_intersections(&parabola, &circle),
            Some(vec![1, 1])
        );
        // a line pair through the centre (0, 0, 1) of the first projection, x·y, and the
        // conic x² − y² + z·(x + y) (through (0,0,1) too): the fallback centres decide
        let through = conic([[2, 0, 1], [0, -2, 1], [1, 1, 0]]);
        let got = conic_real_intersections(&xy, &through).unwrap();
        // x = 0: −y² + zy = 0 → (0,0,1), (0,1,1); y = 0: x² + zx = 0 → (0,0,1), (−1,0,1):
        // (0,0,1) twice (both conics pass through it, transversally each: the line pair's
        // vertex is a double point of xy) and two simple points
        assert_eq!(got, vec![1, 1, 2]);
        // x² = yz and y² = xz, both through the first centre (0, 0, 1): (0, 0, 1) transversally, (1, 1, 1), two complex points
        let other = conic([[0, 0, -1], [0, 2, 0], [-1, 0, 0]]);
        assert_eq!(
            conic_real_intersections(&parabola, &other),
            Some(vec![1, 1])
        );
        // a definite conic and anything: none; a circle with itself: a common component
        let definite = conic([[1, 0, 0], [0, 2, 0], [0, 0, 3]]);
        assert_eq!(conic_real_intersections(&definite, &xy), Some(vec![]));
        assert_eq!(conic_real_intersections(&circle, &circle), None);
        // a shared line: x·y and x·(x + y + z)
        let shares = conic([[2, 1, 1], [1, 0, 0], [1, 0, 0]]);
        assert_eq!(conic_real_intersections(&xy, &shares), None);
        // two conjugate points only: x² + y² − z² and x² + y² − 2z² share (1 : ±i : 0)
        let bigger = conic([[1, 0, 0], [0, 1, 0], [0, 0, -2]]);
        assert_eq!(conic_real_intersections(&circle, &bigger), Some(vec![]));
    }
}
