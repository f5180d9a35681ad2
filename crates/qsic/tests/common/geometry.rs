//! Geometry helpers shared by the curve tests.

use qsic::param::{Curve, Number, RealPiece};
use qsic::Quadric;
use qsic_algebra::{IBig, RBig, Ring};

/// `TᵀQT`.
#[allow(dead_code)]
pub fn moved(q: &Quadric, t: &[[RBig; 4]; 4]) -> Quadric {
    let m = q.matrix();
    Quadric::from_matrix(std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let mut acc = RBig::ZERO;
            for k in 0..4 {
                for l in 0..4 {
                    acc += &t[k][i] * &m[k][l] * &t[l][j];
                }
            }
            acc
        })
    }))
    .unwrap()
}

/// Whether the homogeneous point `x` is `e` up to a factor, exactly.
#[allow(dead_code)]
pub fn is_point(x: &[Number; 4], e: [i64; 4]) -> bool {
    let e: Vec<Number> = e
        .iter()
        .map(|&v| Number::from_int(&IBig::from(v)))
        .collect();
    (0..4).all(|i| (0..4).all(|j| x[i].mul(&e[j]).sub(&x[j].mul(&e[i])).is_zero()))
}

/// `(curves, isolated points)` among the connected groups of the real locus.
#[allow(dead_code)]
pub fn topology(c: &Curve) -> (usize, usize) {
    let points = c
        .connected
        .iter()
        .filter(|g| {
            g.iter()
                .all(|&i| matches!(c.pieces[i], RealPiece::Point { .. }))
        })
        .count();
    (c.connected.len() - points, points)
}
