//! Four distinct concurrent lines: a singular pencil whose members share one vertex `v` and
//! meet in the cone from `v` over the four meeting points of two conics. No rational point of
//! a conic is needed (so nothing is factored): the meeting points come from a resultant.
//!
//! **Method.** `v` spans the common kernel of `A` and `B` (rational). With `vₖ ≠ 0`, the
//! members restricted to the coordinates `i ≠ k` are conics `C`, `D` of a plane missing `v`,
//! and `A(s·v + X) = A(X)`: the curve is the cone from `v` over `C ∩ D`. In coordinates
//! `X = T·X'` (`T` from a short fixed list of unimodular maps), write
//! `C(x, y, 1) = a₂y² + a₁(x)y + a₀(x)` and `D = b₂y² + b₁(x)y + b₀(x)`. With `a₂b₂ ≠ 0`, the
//! resultant `R(x) = s₀² + s₁·(a₁b₀ − a₀b₁)`, `s₁ = b₂a₁ − a₂b₁`, `s₀ = b₂a₀ − a₂b₀`, vanishes
//! exactly at the `x : z` ratios of the meeting points; when `R` has degree 4 (no meeting
//! point on `z = 0`, `(0 : 1 : 0)` excluded by `a₂ ≠ 0`) and distinct roots, each root `τ`
//! is one point, and `b₂C − a₂D = s₁y + s₀` gives it as `(τ s₁(τ), −s₀(τ), s₁(τ))` when
//! `gcd(R, s₁) = 1`. The four points are distinct iff the lines are, and some `T` of the list
//! separates them (the bad maps lie on a proper subvariety; the list is tried in order).
//!
//! Rational roots of `R` give rational lines; the other real roots are isolated as roots of
//! the rest of `R` (degree ≤ 4) and each line is written over `ℚ(τ)`, computed by dynamic
//! evaluation ([`NumberField`]); the non-real roots are non-real lines. All four meet at `v`
//! (a multiple point) and the real locus is connected.

use super::curve::{self, Component, Curve, Number, RealPiece, SingularPoint};
use super::parts::{line_param, non_real, rational_roots, to_point, Mat};
use crate::classify::{Classification, ComponentKind, SingularPointKind};
use qsic_algebra::field::NumberField;
use qsic_algebra::linalg::Matrix;
use qsic_algebra::{AlgebraicReal, Poly, RBig, Ring};

type Conic = [[RBig; 3]; 3];

/// Four distinct concurrent lines (module docs), or `None` when the members share no single
/// vertex or the meeting points are not four distinct points.
pub(super) fn concurrent_lines_curve(
    classification: Classification,
    a: &Mat,
    b: &Mat,
) -> Option<Curve> {
    let rows: Vec<Vec<RBig>> = a.iter().chain(b.iter()).map(|r| r.to_vec()).collect();
    let common = Matrix::from_rows(rows).expect("rows of four").kernel();
    if common.len() != 1 {
        return None;
    }
    let v = common[0].clone();
    let k = (0..4).find(|&i| !v[i].is_zero())?;
    let idx: Vec<usize> = (0..4).filter(|&i| i != k).collect();
    let restrict = |m: &Mat| -> Conic {
        std::array::from_fn(|i| std::array::from_fn(|j| m[idx[i]][idx[j]].clone()))
    };
    let (points, count) = meeting_points(&restrict(a), &restrict(b))?;
    debug_assert_eq!(count, 4);
    let vn: Vec<Number> = v.iter().map(|c| curve::rational(c.clone())).collect();
    let lift = |x3: &[Number]| -> Vec<Number> {
        let mut x4 = vec![Number::zero(); 4];
        for (i, &j) in idx.iter().enumerate() {
            x4[j] = x3[i].clone();
        }
        x4
    };
    let mut curve = Curve::empty(classification);
    for point in &points {
        let component = curve.components.len();
        curve.components.push(Component {
            kind: ComponentKind::Line,
            multiplicity: 1,
            real: true,
            param: Some(line_param(&vn, &lift(point))),
            plane: None,
            section: None,
        });
        curve.pieces.push(RealPiece::whole(component));
    }
    for _ in points.len()..count {
        curve.components.push(non_real(ComponentKind::Line, 1));
    }
    if points.is_empty() {
        curve.pieces.push(RealPiece::Point {
            component: 0,
            point: to_point(&vn),
        });
    }
    curve.connected.push((0..curve.pieces.len()).collect());
    curve.singular_points.push(SingularPoint {
        kind: SingularPointKind::Multiple,
        point: to_point(&vn),
    });
    Some(curve)
}

/// The unimodular coordinate maps tried in order: a cyclic shift of the coordinates, then
/// `(x, y, z) ↦ (x, y + αx, z + βx + γy)`.
const SHEARS: [(i64, i64, i64); 8] = [
    (0, 0, 0),
    (1, 0, 0),
    (0, 1, 0),
    (0, 0, 1),
    (1, 1, 1),
    (2, -1, 1),
    (-1, 3, 2),
    (3, 2, -5),
];

/// `T` with `X = T·X'`: the shift by `shift` places after the shear.
fn coordinate_map(shift: usize, (al, be, ga): (i64, i64, i64)) -> Conic {
    let l: [[i64; 3]; 3] = [[1, 0, 0], [al, 1, 0], [be, ga, 1]];
    std::array::from_fn(|i| std::array::from_fn(|j| RBig::from(l[(i + shift) % 3][j])))
}

fn congruence(t: &Conic, c: &Conic) -> Conic {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let mut s = RBig::ZERO;
            for p in 0..3 {
                for q in 0..3 {
                    s += &t[p][i] * &c[p][q] * &t[q][j];
                }
            }
            s
        })
    })
}

/// The real meeting points of the conics `C`, `D` (3 coordinates, each over ℚ or its own
/// `ℚ(τ)`) and the number of meeting points over ℂ (4), when they are four distinct points
/// (module docs); `None` otherwise.
fn meeting_points(c: &Conic, d: &Conic) -> Option<(Vec<Vec<Number>>, usize)> {
    for shift in 0..3 {
        for shear in SHEARS {
            let t = coordinate_map(shift, shear);
            if let Some(found) = meeting_points_in(&t, &congruence(&t, c), &congruence(&t, d)) {
                return Some(found);
            }
        }
    }
    None
}

/// [`meeting_points`] in the coordinates `X = T·X'` (`c`, `d` already `TᵀCT`, `TᵀDT`), or
/// `None` when they do not separate the points.
fn meeting_points_in(t: &Conic, c: &Conic, d: &Conic) -> Option<(Vec<Vec<Number>>, usize)> {
    let two = RBig::from(2);
    // coefficients in y of C(x, y, 1): a₂, a₁(x), a₀(x)
    let split = |m: &Conic| -> (RBig, Poly<RBig>, Poly<RBig>) {
        (
            m[1][1].clone(),
            Poly::new(vec![&two * &m[1][2], &two * &m[0][1]]),
            Poly::new(vec![m[2][2].clone(), &two * &m[0][2], m[0][0].clone()]),
        )
    };
    let (a2, a1, a0) = split(c);
    let (b2, b1, b0) = split(d);
    if a2 == RBig::ZERO || b2 == RBig::ZERO {
        return None;
    }
    let s1 = &a1.scale(&b2) - &b1.scale(&a2);
    let s0 = &a0.scale(&b2) - &b0.scale(&a2);
    let res = &(&s0 * &s0) + &(&s1 * &(&(&a1 * &b0) - &(&a0 * &b1)));
    if res.degree() != Some(4)
        || res.gcd_monic(&res.derivative()).degree() != Some(0)
        || res.gcd_monic(&s1).degree() != Some(0)
    {
        return None;
    }
    // X = T·(x·s₁, −s₀, s₁)
    let local = [&Poly::x() * &s1, s0.scale(&RBig::from(-1)), s1];
    let x: Vec<Poly<RBig>> = (0..3)
        .map(|i| (0..3).fold(Poly::zero(), |acc, j| &acc + &local[j].scale(&t[i][j])))
        .collect();
    let rational = rational_roots(&res);
    let rest = rational.iter().fold(Poly::from_rational(&res).0, |p, r| {
        p.div_exact(&Poly::vanishing_at(r))
            .expect("a rational root divides")
    });
    let mut points: Vec<Vec<Number>> = rational
        .iter()
        .map(|r| x.iter().map(|p| curve::rational(p.eval(r))).collect())
        .collect();
    if rest.degree().unwrap_or(0) > 0 {
        for root in AlgebraicReal::real_roots_of(&rest) {
            let field = NumberField::new(&root);
            points.push(x.iter().map(|p| field.element(p)).collect());
        }
    }
    Some((points, 4))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn conic(entries: [[i64; 3]; 3]) -> Conic {
        entries.map(|row| row.map(RBig::from))
    }

    fn on(c: &Conic, x: &[Number]) -> bool {
        let mut s = Number::zero();
        for i in 0..3 {
            for j in 0..3 {
                s = s.add(&x[i].mul(&x[j]).mul(&curve::rational(c[i][j].clone())));
            }
        }
        s.is_zero()
    }

    /// `xz = y²` and `2xy + z² = 0` meet at `(1 : t : t²)` with `t(t³ + 2) = 0`: two real
    /// points (one rational, one over ℚ(∛2)), exactly on both conics; with every coordinate
    /// map of the list that separates them.
    #[test]
    fn meeting_points_of_two_conics_lie_on_both() {
        let c = conic([[0, 0, 1], [0, -2, 0], [1, 0, 0]]);
        let d = conic([[0, 1, 0], [1, 0, 0], [0, 0, 1]]);
        let (points, count) = meeting_points(&c, &d).expect("four distinct points");
        assert_eq!((points.len(), count), (2, 4));
        for p in &points {
            assert!(on(&c, p) && on(&d, p));
            assert!(p.iter().any(|x| !x.is_zero()));
        }
        let mut separating = 0;
        for shift in 0..3 {
            for shear in SHEARS {
                let t = coordinate_map(shift, shear);
                if let Some((points, _)) =
                    meeting_points_in(&t, &congruence(&t, &c), &congruence(&t, &d))
                {
                    separating += 1;
                    assert_eq!(points.len(), 2);
                    assert!(points.iter().all(|p| on(&c, p) && on(&d, p)));
                }
            }
        }
        assert!(separating > 10, "{separating}");
    }

    /// `xz = y²` and `x² + xz = y²` meet only at `(0 : 0 : 1)` (their difference is `x²`):
    /// not four distinct points, `None`.
    #[test]
    fn tangent_conics_are_not_four_points() {
        let c = conic([[0, 0, 1], [0, -2, 0], [1, 0, 0]]);
        let d = conic([[2, 0, 1], [0, -2, 0], [1, 0, 0]]);
        assert!(meeting_points(&c, &d).is_none());
    }
}
