//! The common surfaces in `qsic plot`: what the two quadrics share beyond a curve — the
//! quadric itself when `A ∝ B`, or a common plane — drawn by its sections like the surfaces,
//! but in a piece's colour, and the point the drawn cube is placed around when nothing else
//! places it.
//!
//! Which surfaces are common, their names and whether they lie at infinity come from the
//! exact description ([`qsic::affine::common_surfaces`]); floats only draw them.

use qsic::affine::{common_surfaces, AffineView, Chart};
use qsic::param::{Curve, Number};
use qsic::Quadric;
use qsic_algebra::RBig;

/// A common surface to draw.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Common {
    /// Its affine name (`sphere`, `plane`, …).
    pub name: &'static str,
    /// Its float matrix in the chart's coordinates, `None` when it lies at infinity (not
    /// drawn).
    pub matrix: Option<[[f64; 4]; 4]>,
}

/// The common surfaces of the curve of `a` and `b`: the quadric `a` once when `A ∝ B` (its
/// planes too, when it is a plane pair), else each common plane, as a double plane.
/// `float_matrix` turns an exact matrix in the chart into the drawn one.
pub(crate) fn common_of(
    curve: &Curve,
    view: &AffineView,
    a: &Quadric,
    chart: &Chart,
    float_matrix: impl Fn(&[[RBig; 4]; 4]) -> [[f64; 4]; 4],
) -> Vec<Common> {
    let surfaces = common_surfaces(curve, a, chart);
    if view.same {
        if surfaces.iter().all(|(_, s)| s.at_infinity) {
            return surfaces
                .iter()
                .filter_map(|(_, s)| s.name)
                .map(|name| Common { name, matrix: None })
                .collect();
        }
        let name = view.surfaces[0].map_or("quadric", |s| s.key());
        let matrix = Some(float_matrix(&chart.matrix_in_chart(a.matrix())));
        return vec![Common { name, matrix }];
    }
    surfaces
        .into_iter()
        .filter_map(|(k, s)| {
            let name = s.name?;
            let matrix = match (&curve.components[k].plane, s.at_infinity) {
                (Some(l), false) => rational_plane(l).map(|l| {
                    let m = std::array::from_fn(|i| std::array::from_fn(|j| &l[i] * &l[j]));
                    float_matrix(&chart.matrix_in_chart(&m))
                }),
                _ => None,
            };
            Some(Common { name, matrix })
        })
        .collect()
}

/// The plane's coefficients when they are rational (a common plane of two quadrics that are
/// not proportional is: its conjugate would be common too).
fn rational_plane(l: &[Number; 4]) -> Option<[RBig; 4]> {
    let mut out: [RBig; 4] = Default::default();
    for i in 0..4 {
        let r = l[i].representative();
        match r.degree() {
            None => {}
            Some(0) => out[i] = r.coeffs()[0].clone(),
            Some(_) => return None,
        }
    }
    Some(out)
}

/// A point of the first drawn common surface for the cube to be placed around, with the
/// cube's half-side: of the points where the lines through the origin along 13 directions
/// (the axes, the face and space diagonals) meet the surface, the nearest the origin; `None`
/// when no surface is drawn or none of the lines meets it.
pub(crate) fn anchor(common: &[Common]) -> Option<([f64; 3], f64)> {
    let m = common.iter().find_map(|c| c.matrix)?;
    let mut directions = Vec::new();
    for e in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] {
        directions.push(e);
    }
    for (i, j) in [(0, 1), (0, 2), (1, 2)] {
        for sign in [1.0, -1.0] {
            let mut e = [0.0; 3];
            e[i] = 1.0;
            e[j] = sign;
            directions.push(e);
        }
    }
    for (sy, sz) in [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)] {
        directions.push([1.0, sy, sz]);
    }
    let mut best: Option<[f64; 3]> = None;
    for e in directions {
        // (t·e, 1)ᵀ M (t·e, 1) = a·t² + 2b·t + c
        let a: f64 = (0..3)
            .map(|i| (0..3).map(|j| e[i] * m[i][j] * e[j]).sum::<f64>())
            .sum();
        let b: f64 = (0..3).map(|i| e[i] * m[i][3]).sum();
        let c = m[3][3];
        let roots = if a == 0.0 {
            if b == 0.0 {
                vec![]
            } else {
                vec![-c / (2.0 * b)]
            }
        } else {
            let disc = b * b - a * c;
            if disc < 0.0 {
                vec![]
            } else {
                vec![(-b - disc.sqrt()) / a, (-b + disc.sqrt()) / a]
            }
        };
        for t in roots.into_iter().filter(|t| t.is_finite()) {
            let p = e.map(|v| v * t);
            if best.is_none_or(|q| norm(&p) < norm(&q)) {
                best = Some(p);
            }
        }
    }
    best.map(|p| (p, (norm(&p) / 2.0).max(1.0)))
}

fn norm(p: &[f64; 3]) -> f64 {
    p.iter().map(|v| v * v).sum::<f64>().sqrt()
}
