//! A quadric paired with itself: the "intersection" is the quadric, typed by its inertia.

use super::Classification;
use crate::quadric::Quadric;
use crate::vocabulary::{
    ComplexType, Component, ComponentKind, Description, Morphology, PencilKind, RealType,
};
use qsic_algebra::matrix::Inertia;

/// Classifies the single quadric `q` (taxonomy.md, "Single quadric"): by rank and by its
/// inertia up to sign.
pub fn classify_single(q: &Quadric) -> Classification {
    classify_single_inertia(q.integer_matrix().inertia())
}

/// [`classify_single`] from the inertia of the quadric's matrix (for a matrix over a real
/// field other than ℚ).
pub(crate) fn classify_single_inertia(inertia: Inertia) -> Classification {
    let (hi, lo) = if inertia.positive >= inertia.negative {
        (inertia.positive, inertia.negative)
    } else {
        (inertia.negative, inertia.positive)
    };
    let comp = |kind, multiplicity, count, closed| Component {
        kind,
        multiplicity,
        count,
        closed,
    };
    use ComplexType as C;
    use ComponentKind as K;
    use RealType as R;
    let (complex, real, components, summary) = match (hi, lo) {
        (4, 0) => (
            C::SmoothQuadric,
            R::Empty,
            vec![],
            "a smooth quadric without real points",
        ),
        (3, 1) => (
            C::SmoothQuadric,
            R::Inertia31,
            vec![comp(K::Quadric, 1, 1, Some(true))],
            "an oval quadric (ellipsoid, hyperboloid of two sheets or elliptic paraboloid)",
        ),
        (2, 2) => (
            C::SmoothQuadric,
            R::Inertia22,
            vec![comp(K::Quadric, 1, 1, Some(false))],
            "a ruled quadric (hyperboloid of one sheet or hyperbolic paraboloid)",
        ),
        (3, 0) => (
            C::Cone,
            R::Point,
            vec![comp(K::Point, 1, 1, Some(true))],
            "an imaginary cone with a real vertex",
        ),
        (2, 1) => (
            C::Cone,
            R::RealCone,
            vec![comp(K::Quadric, 1, 1, Some(false))],
            "a real cone or cylinder",
        ),
        (2, 0) => (
            C::PairOfPlanes,
            R::Line,
            vec![comp(K::Line, 1, 1, Some(false))],
            "two conjugate planes meeting in a real line",
        ),
        (1, 1) => (
            C::PairOfPlanes,
            R::Same,
            vec![comp(K::Plane, 1, 2, Some(false))],
            "two real planes",
        ),
        _ => (
            C::DoublePlane,
            R::Same,
            vec![comp(K::Plane, 2, 1, Some(false))],
            "a real plane counted twice",
        ),
    };
    Classification {
        pencil: PencilKind::Single,
        case: None,
        segre: None,
        signature: None,
        index_sequence: None,
        morphology: Some(Morphology { complex, real }),
        description: Some(Description {
            components,
            singular_points: vec![],
            summary,
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every inertia up to sign, from diagonal matrices, and its negative (taxonomy.md).
    #[test]
    fn types_by_inertia_up_to_sign() {
        let table: [([i64; 4], &str, &str, &[&str]); 8] = [
            ([1, 1, 1, 1], "smooth_quadric", "empty", &[]),
            ([1, 1, 1, -1], "smooth_quadric", "inertia_3_1", &["quadric"]),
            (
                [1, 1, -1, -1],
                "smooth_quadric",
                "inertia_2_2",
                &["quadric"],
            ),
            ([1, 1, 1, 0], "cone", "point", &["point"]),
            ([1, 1, -1, 0], "cone", "real_cone", &["quadric"]),
            ([1, 1, 0, 0], "pair_of_planes", "line", &["line"]),
            (
                [1, -1, 0, 0],
                "pair_of_planes",
                "pair_of_planes",
                &["plane"],
            ),
            ([1, 0, 0, 0], "double_plane", "double_plane", &["plane"]),
        ];
        for (d, complex, real, kinds) in table {
            for sign in [1, -1] {
                let mut m = [[0i64; 4]; 4];
                for i in 0..4 {
                    m[i][i] = sign * d[i];
                }
                let c = classify_single(&Quadric::from_integers(m).expect("nonzero"));
                assert_eq!(c.pencil.key(), "single");
                let components = &c.description.as_ref().expect("described").components;
                let got: Vec<&str> = components.iter().map(|k| k.kind.key()).collect();
                assert_eq!(got, kinds, "{d:?}");
                let got = (c.complex_type(), c.real_type());
                assert_eq!(got, (Some(complex), Some(real)), "{d:?} × {sign}");
            }
        }
    }
}
