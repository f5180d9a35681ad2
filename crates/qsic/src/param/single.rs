//! The single quadric (`A ∝ B`): what the two have in common is the quadric `Q` itself.
//!
//! The components follow the classification ([`classify_single`](crate::classify)), by the
//! inertia `(p, n)` of `Q` up to sign:
//!
//! | inertia | components |
//! |---|---|
//! | `(4, 0)` | one non-real `quadric` (no real point) |
//! | `(3, 1)`, `(2, 2)`, `(2, 1)` | one real `quadric` (a surface: no parameterization) |
//! | `(3, 0)` | the real `point` of the cone, its vertex: the kernel of `Q` |
//! | `(2, 0)` | the real `line` of the two conjugate planes: the kernel of `Q`, `X(u) = p + u·q` |
//! | `(1, 1)` | two real `plane`s, `Q = c·l₁·l₂` over ℚ or ℚ(√δ) |
//! | `(1, 0)` | one `plane` of multiplicity 2 |
//!
//! A plane component carries its equation in [`Component::plane`]; a surface has no
//! parameterization here (`param` is `None`), the point and the line have theirs and a real
//! piece each.

use super::curve::RealPiece;
use super::curve::{self, Component, ComponentParam, Curve, Number, Point};
use crate::classify::{Classification, ComponentKind};
use crate::quadric::Quadric;
use qsic_algebra::field::Quadratic;
use qsic_algebra::linalg::forms::plane_pair;
use qsic_algebra::linalg::Matrix;
use qsic_algebra::Poly;

/// The curve of the single quadric `q` (module docs).
pub(crate) fn single_curve(classification: Classification, q: &Quadric) -> Curve {
    let inertia = q.integer_matrix().inertia();
    let (hi, lo) = if inertia.positive >= inertia.negative {
        (inertia.positive, inertia.negative)
    } else {
        (inertia.negative, inertia.positive)
    };
    let m = Matrix::from_array(q.matrix().clone());
    let mut curve = Curve::empty(classification);
    let kernel = || -> Vec<Point> {
        m.kernel()
            .into_iter()
            .map(|v| std::array::from_fn(|i| curve::rational(v[i].clone())))
            .collect()
    };
    match (hi, lo) {
        (3, 0) => {
            // rank 3 (inertia (3, 0) is exact): the kernel is one vector
            let vertex = kernel().swap_remove(0);
            curve.components.push(component(
                ComponentKind::Point,
                1,
                Some(ComponentParam::Point(vertex.clone())),
                None,
            ));
            curve.pieces.push(RealPiece::Point {
                component: 0,
                point: vertex,
            });
            curve.connected.push(vec![0]);
        }
        (2, 0) => {
            // rank 2: the kernel is two vectors, the real line
            let k = kernel();
            let x = std::array::from_fn(|i| Poly::new(vec![k[0][i].clone(), k[1][i].clone()]));
            curve.components.push(component(
                ComponentKind::Line,
                1,
                Some(ComponentParam::Rational { x, degree: 1 }),
                None,
            ));
            curve.pieces.push(RealPiece::whole(0));
            curve.connected.push(vec![0]);
        }
        (1, 1) | (1, 0) => {
            // rank ≤ 2: a plane pair, split over ℚ or one real ℚ(√δ)
            if let Some(pair) = plane_pair(&m) {
                let field = pair.planes[0]
                    .iter()
                    .chain(&pair.planes[1])
                    .find(|c| c.as_rational().is_none())
                    .map(|c| curve::sqrt_field(c.radicand()));
                let point = |l: &[Quadratic]| -> Point {
                    std::array::from_fn(|i| curve::from_quadratic(&l[i], field.as_ref()))
                };
                if hi == 1 && lo == 0 {
                    let plane = point(&pair.planes[0]);
                    curve
                        .components
                        .push(component(ComponentKind::Plane, 2, None, Some(plane)));
                } else {
                    for l in &pair.planes {
                        let plane = point(l);
                        curve.components.push(component(
                            ComponentKind::Plane,
                            1,
                            None,
                            Some(plane),
                        ));
                    }
                }
            }
        }
        (4, 0) => curve.components.push(Component {
            kind: ComponentKind::Quadric,
            multiplicity: 1,
            real: false,
            param: None,
            plane: None,
            section: None,
        }),
        _ => curve
            .components
            .push(component(ComponentKind::Quadric, 1, None, None)),
    }
    curve
}

/// A real component.
fn component(
    kind: ComponentKind,
    multiplicity: u32,
    param: Option<ComponentParam>,
    plane: Option<[Number; 4]>,
) -> Component {
    Component {
        kind,
        multiplicity,
        real: true,
        param,
        plane,
        section: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::classify::classify;
    use crate::io::parse_quadric;
    use qsic_algebra::{Field, RBig, Ring};

    fn curve(s: &str) -> (Quadric, Curve) {
        let q = parse_quadric(s).unwrap();
        let c = single_curve(classify(&q, &q), &q);
        (q, c)
    }

    fn on(q: &Quadric, p: &super::Point) -> bool {
        let m = q.matrix();
        let mut acc = Number::zero();
        for i in 0..4 {
            for j in 0..4 {
                let mij = curve::rational(m[i][j].clone());
                acc = acc.add(&p[i].mul(&mij).mul(&p[j]));
            }
        }
        acc.is_zero()
    }

    /// Every kind of the module's table, the components checked against the quadric: the
    /// vertex and the line's points are on it (and in its kernel: the real locus), the planes'
    /// product is the quadric up to a factor.
    #[test]
    fn the_components_of_each_inertia() {
        let kinds = |c: &Curve| -> Vec<(ComponentKind, u32, bool)> {
            c.components
                .iter()
                .map(|k| (k.kind, k.multiplicity, k.real))
                .collect()
        };
        use ComponentKind::*;
        let (_, c) = curve("x^2+y^2+z^2+1");
        assert_eq!(kinds(&c), [(Quadric, 1, false)]);
        for s in ["x^2+y^2+z^2-1", "x^2+y^2-z^2-1", "x^2+y^2-z^2", "x*y-z"] {
            let (_, c) = curve(s);
            assert_eq!(kinds(&c), [(Quadric, 1, true)], "{s}");
            assert!(c.pieces.is_empty() && c.components[0].param.is_none());
        }
        // the cone (x−1)² + y² + z² with one real point, (1, 0, 0, 1)
        let (q, c) = curve("(x-1)^2+y^2+z^2");
        assert_eq!(kinds(&c), [(Point, 1, true)]);
        let Some(ComponentParam::Point(p)) = &c.components[0].param else {
            panic!("a point")
        };
        assert!(on(&q, p) && !p[3].is_zero());
        assert_eq!(p[0].mul(&p[3].inv().unwrap()), Number::one());
        // two conjugate planes (x − z)² + y² = 0 through the line x = z, y = 0
        let (q, c) = curve("(x-z)^2+y^2");
        assert_eq!(kinds(&c), [(Line, 1, true)]);
        let Some(ComponentParam::Rational { x, degree: 1 }) = &c.components[0].param else {
            panic!("a line")
        };
        for u in [0, 1, -3] {
            let p: super::Point =
                std::array::from_fn(|i| x[i].eval(&curve::rational(RBig::from(u))));
            assert!(on(&q, &p) && p[0] == p[2] && p[1].is_zero(), "u = {u}");
        }
        assert_eq!(c.pieces.len(), 1);
        // two real planes, rational and over ℚ(√2); a double plane
        for (s, mult, count) in [("x*y", 1, 2), ("x^2-2*y^2", 1, 2), ("(x+y-1)^2", 2, 1)] {
            let (q, c) = curve(s);
            assert_eq!(kinds(&c), vec![(Plane, mult, true); count], "{s}");
            let planes: Vec<&super::Point> = c.components.iter().flat_map(|k| &k.plane).collect();
            assert_eq!(planes.len(), count);
            // a point of each plane off the other is on q,
            for l in &planes {
                let p = point_of_plane(l);
                assert!(on(&q, &p), "{s}: {p:?}");
            }
        }
    }

    /// A point of the plane `l·X = 0` (`l` with a nonzero coordinate among the first three).
    fn point_of_plane(l: &super::Point) -> super::Point {
        let k = (0..4).find(|&k| !l[k].is_zero()).unwrap();
        let mut p: super::Point =
            std::array::from_fn(|i| curve::rational(RBig::from(i as i64 + 2)));
        // solve for coordinate k
        let mut rest = Number::zero();
        for i in (0..4).filter(|&i| i != k) {
            rest = rest.add(&l[i].mul(&p[i]));
        }
        p[k] = rest.neg().mul(&l[k].inv().unwrap());
        p
    }
}
