//! Small pieces shared by the curves on plane pairs (`planar`) and the four concurrent
//! lines (`concurrent`): points and lines as components, the non-real component, the rational
//! roots of a rational polynomial.

use super::curve::{Component, ComponentParam, Number, Point};
use crate::classify::ComponentKind;
use qsic_algebra::roots::simplest_between;
use qsic_algebra::{AlgebraicReal, Poly, RBig};

/// A rational 4×4 matrix.
pub(super) type Mat = [[RBig; 4]; 4];

pub(super) fn to_point(v: &[Number]) -> Point {
    std::array::from_fn(|i| v[i].clone())
}

/// The line through `p` and `q`: `X(u) = p + u·q`.
pub(super) fn line_param(p: &[Number], q: &[Number]) -> ComponentParam {
    ComponentParam::Rational {
        x: std::array::from_fn(|i| Poly::new(vec![p[i].clone(), q[i].clone()])),
        degree: 1,
    }
}

/// The rational roots of `g` (exact: each real root's interval is refined below
/// `1/(2·lc²)`, where the only candidate is the simplest rational in it).
pub(super) fn rational_roots(g: &Poly<RBig>) -> Vec<RBig> {
    if g.degree().unwrap_or(0) == 0 {
        return Vec::new();
    }
    let p = Poly::from_rational(g).0.squarefree_part();
    let lc = RBig::from(p.leading());
    let width = RBig::ONE / (RBig::from(2) * &lc * &lc);
    AlgebraicReal::real_roots_of(&p)
        .into_iter()
        .filter_map(|root| {
            if let Some(r) = root.as_rational() {
                return Some(r.clone());
            }
            let iv = root.refined_interval(&width);
            let r = simplest_between(iv.lo(), iv.hi(), true, true);
            p.eval_rational(&r).is_zero().then_some(r)
        })
        .collect()
}

pub(super) fn non_real(kind: ComponentKind, multiplicity: u32) -> Component {
    Component {
        kind,
        multiplicity,
        real: false,
        param: None,
        plane: None,
        section: None,
    }
}
