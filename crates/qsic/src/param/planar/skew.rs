//! The skew quadrilateral: the pencils whose members of rank 2 sit at conjugate quadratic
//! λ ∈ ℚ(√D) (Segre `[(11)(11)]`, real: from the two kernels), or at complex λ (case 31: the
//! lines of the two rulings of a rational doubly ruled member).

use super::{form, member, qr, radicand_of, rational_matrix, Ext, Vq};
use super::{line_param, non_real, rational_roots, to_point, Mat};
use crate::classify::{Classification, ComponentKind, SingularPointKind};
use crate::error::Error;
use crate::param::curve::{Component, ComponentParam, Curve, Number, RealPiece, SingularPoint};
use crate::param::surface::{
    parameterize_doubly_ruled, poly_form, sqrt_in_field, to_quadratic, RuledParameterization,
};
use qsic_algebra::field::Quadratic;
use qsic_algebra::linalg::pencil::pencil_principal_minor_sums;
use qsic_algebra::linalg::Matrix;
use qsic_algebra::{Field, IBig, Poly, RBig, Ring, Sign};

/// The two members of rank 2 at conjugate real quadratic irrationalities `λ, λ̄ ∈ ℚ(√D)`
/// (Segre `[(11)(11)]`, the skew quadrilateral and its complex forms), or `None`.
///
/// Over ℂ the pencil is `diag(a₁, a₂, a₃, a₄)`, `diag(λa₁, λa₂, λ̄a₃, λ̄a₄)`: the kernels `V`
/// of `λA − B` and `V̄` of `λ̄A − B` are disjoint lines, `A` pairs them to zero, and the curve
/// meets `V` where `A|V = 0` (`B|V = λ·A|V`): at `p±`, and `V̄` at `q± = σ(p±)` (`σ: √D ↦ −√D`).
/// The four lines are the joins `pᵢqⱼ`: `A(s·p + t·q) = s²A(p) + 2st·A(p, q) + t²A(q) = 0`.
/// With `e` the discriminant of `A|V`, the points `p±` are real iff `e > 0` and `q±` iff
/// `σ(e) > 0`: four real lines meeting at four crunodes, or (one sign each) four non-real lines
/// meeting in pairs at the two real points `p±` (acnodes), or nothing real.
pub(super) fn conjugate_pair_curve(
    classification: Classification,
    a: &Mat,
    b: &Mat,
) -> Result<Option<Curve>, Error> {
    // det(λA − B) = c·f² with f irreducible of degree 2 (E₃ may vanish identically)
    let e4 = Poly::new(pencil_principal_minor_sums(a, b)[3].to_vec());
    if e4.is_zero() {
        return Ok(None);
    }
    let mut f = Poly::from_rational(&e4).0.squarefree_part();
    for r in rational_roots(&e4) {
        f = f
            .div_exact(&Poly::vanishing_at(&r))
            .expect("a rational root divides");
    }
    if f.degree() != Some(2) {
        return Ok(None);
    }
    let (c0, c1, c2) = (
        RBig::from(f.coeff(0)),
        RBig::from(f.coeff(1)),
        RBig::from(f.coeff(2)),
    );
    let disc = &c1 * &c1 - RBig::from(4) * &c0 * &c2;
    if disc.is_zero() {
        return Ok(None);
    }
    if disc < RBig::ZERO {
        return ruled_member_curve(classification, a, b);
    }
    let Some(root) = sqrt_in_field(&qr(&disc), None) else {
        return Ok(None);
    };
    let Some(d) = radicand_of([&root]) else {
        return Ok(None);
    };
    let two_c2 = qr(&(RBig::from(2) * &c2));
    let lambdas = [root.clone(), root.neg()].map(|r| {
        r.sub(&qr(&c1))
            .div(&two_c2)
            .expect("a quadratic's leading coefficient")
    });
    let am = rational_matrix(a).map(qr);
    let bm = rational_matrix(b).map(qr);
    // for each root: the points x ± √e·y of V where A|V = 0
    let mut sides: Vec<(Vq, Vq, Quadratic)> = Vec::new();
    for lambda in &lambdas {
        let p = Matrix::from_fn(4, 4, |i, j| lambda.mul(&am[(i, j)]).sub(&bm[(i, j)]));
        let ker = p.kernel();
        if ker.len() != 2 {
            return Ok(None);
        }
        let (v0, v1) = (&ker[0], &ker[1]);
        let (qa, qb, qc) = (form(&am, v0, v0), form(&am, v0, v1), form(&am, v1, v1));
        let Some(side) = binary_points(&qa, &qb, &qc, v0, v1) else {
            return Ok(None);
        };
        sides.push(side);
    }
    let delta = Some(&d);
    let real = |e: &Quadratic| e.sign() == Some(Sign::Positive);
    let mut curve = Curve::empty(classification);
    let reals: Vec<bool> = sides.iter().map(|s| real(&s.2)).collect();
    if reals[0] && reals[1] {
        let (ext, ps) = real_ends(&sides[0], delta);
        let (x, y, e) = &sides[1];
        // q± in the field of p±: √e' there, or √e' = k·√e₀ with k ∈ ℚ(√D)
        let qs: Option<[Vec<Number>; 2]> = match (sqrt_in_field(e, delta), &ext.root) {
            (Some(s), _) => Some(plus_minus(x, y, &s).map(|v| ext.embed_vec(&v))),
            (None, Some(_)) => {
                let ratio = e.div(&sides[0].2).expect("e ≠ 0");
                sqrt_in_field(&ratio, delta).map(|k| {
                    let ky: Vq = y.iter().map(|c| k.mul(c)).collect();
                    let neg: Vq = ky.iter().map(Quadratic::neg).collect();
                    [ext.with_root(x, &ky), ext.with_root(x, &neg)]
                })
            }
            (None, None) => None,
        };
        let lines: Vec<ComponentParam> = match &qs {
            Some(qs) => ps
                .iter()
                .flat_map(|p| qs.iter().map(move |q| line_param(p, q)))
                .collect(),
            None => {
                // the joins need ℚ(√D, √e, √ē) (degree 8): the lines of the two rulings of
                // a rational member, each pair in its own field
                let Some((families, d2)) = ruled_families(a, b) else {
                    return Err(Error::Unsupported(
                        "a skew quadrilateral whose lines need a field of degree 8 (not yet)"
                            .into(),
                    ));
                };
                let mut lines = Vec::new();
                for family in &families {
                    if !real(&family.2) {
                        return Ok(None);
                    }
                    let (_, ends) = real_ends(family, d2.as_ref());
                    lines.extend(ends.iter().map(|end| line_param(&end[..4], &end[4..])));
                }
                lines
            }
        };
        for param in lines {
            curve.components.push(Component {
                kind: ComponentKind::Line,
                multiplicity: 1,
                real: true,
                param: Some(param),
                plane: None,
                section: None,
            });
        }
        // the vertices p±, q±, each in its own field
        let (_, qs_own) = real_ends(&sides[1], delta);
        for x in ps.iter().chain(&qs_own) {
            curve.singular_points.push(SingularPoint {
                kind: SingularPointKind::Crunode,
                point: to_point(x),
            });
        }
        for component in 0..4 {
            curve.pieces.push(RealPiece::whole(component));
        }
        curve.connected.push(vec![0, 1, 2, 3]);
    } else {
        // the lines p₊q±, p₋q± are non-real; the real ends (of one side at most) are
        // acnodes, each where two conjugate lines meet
        for _ in 0..4 {
            curve.components.push(non_real(ComponentKind::Line, 1));
        }
        for side in sides.iter().filter(|s| real(&s.2)) {
            let (_, ps) = real_ends(side, delta);
            for (i, p) in ps.iter().enumerate() {
                curve.singular_points.push(SingularPoint {
                    kind: SingularPointKind::Acnode,
                    point: to_point(p),
                });
                curve.connected.push(vec![curve.pieces.len()]);
                curve.pieces.push(RealPiece::Point {
                    component: 2 * i,
                    point: to_point(p),
                });
            }
        }
    }
    Ok(Some(curve))
}

/// The roots of `a·s² + 2b·st + c·t²` as the points `s·v₀ + t·v₁ = x ± √e·y`; `None` when
/// the form vanishes or has a double root.
fn binary_points(
    a: &Quadratic,
    b: &Quadratic,
    c: &Quadratic,
    v0: &[Quadratic],
    v1: &[Quadratic],
) -> Option<(Vq, Vq, Quadratic)> {
    let (a, c, v0, v1) = if a.is_zero() {
        (c, a, v1, v0)
    } else {
        (a, c, v0, v1)
    };
    if a.is_zero() {
        // a = c = 0: the roots (1, 0), (0, 1), i.e. (v₀ + v₁) ± (v₀ − v₁) up to 2
        if b.is_zero() {
            return None;
        }
        let x: Vq = v0.iter().zip(v1).map(|(s, t)| s.add(t)).collect();
        let y: Vq = v0.iter().zip(v1).map(|(s, t)| s.sub(t)).collect();
        return Some((x, y, Quadratic::one()));
    }
    // (s, t) = (−b ± √e, a), e = b² − ac
    let e = b.mul(b).sub(&a.mul(c));
    if e.is_zero() {
        return None;
    }
    let x: Vq = v0
        .iter()
        .zip(v1)
        .map(|(s, t)| b.neg().mul(s).add(&a.mul(t)))
        .collect();
    Some((x, v0.to_vec(), e))
}

/// `x ± s·y`.
fn plus_minus(x: &[Quadratic], y: &[Quadratic], s: &Quadratic) -> [Vq; 2] {
    [
        x.iter().zip(y).map(|(a, b)| a.add(&s.mul(b))).collect(),
        x.iter().zip(y).map(|(a, b)| a.sub(&s.mul(b))).collect(),
    ]
}

/// The real points `x ± √e·y` (`e > 0` in ℚ(√δ)) in ℚ(√δ), ℚ(√e) or ℚ(√δ, √e).
fn real_ends((x, y, e): &(Vq, Vq, Quadratic), delta: Option<&IBig>) -> (Ext, [Vec<Number>; 2]) {
    match sqrt_in_field(e, delta) {
        Some(s) => {
            let rad = radicand_of([&s]).or_else(|| delta.cloned());
            let ext = Ext::new(rad.as_ref(), None);
            let ends = plus_minus(x, y, &s).map(|v| ext.embed_vec(&v));
            (ext, ends)
        }
        None => {
            let ext = Ext::new(delta, Some(e));
            let neg: Vq = y.iter().map(Quadratic::neg).collect();
            let ends = [ext.with_root(x, y), ext.with_root(x, &neg)];
            (ext, ends)
        }
    }
}

/// The curve as four lines on a real doubly ruled member `S` (a rational λ, inertia (2, 2)),
/// two in each ruling, when the pencil's plane pairs are at complex λ (case 31), or `None`.
///
/// On `q(u, v) = b(u) + v·d(u)` ([`parameterize_doubly_ruled`]: `b`, `d` linear, so `v`
/// fixed is a line too) another member `Q` is `F = c₀ + 2c₁v + c₂v²` (`c₀ = bᵀQb`,
/// `c₁ = bᵀQd`, `c₂ = dᵀQd`). The curve is four lines iff `F = g(u)·h(v)` for binary
/// quadratics `g = gcd(c₀, c₁, c₂)` (homogenized to degree 2) and `h = (c₀, c₁, c₂)/g`, each
/// with distinct roots: the lines `u = uᵢ` and `v = vⱼ`. The parameterization is real, so a
/// line is real iff its root is; two real lines of one ruling are skew, and a real line
/// meets a non-real line of the other ruling at a non-real point: the real locus is the real
/// lines, each its own connected component, when one ruling alone has real roots.
fn ruled_member_curve(
    classification: Classification,
    a: &Mat,
    b: &Mat,
) -> Result<Option<Curve>, Error> {
    let Some((families, delta)) = ruled_families(a, b) else {
        return Ok(None);
    };
    Ok(ruled_lines(classification, &families, delta.as_ref()))
}

/// A point pair `x ± √e·y` of 8-vectors: the two ends `(b, d)` of two lines.
type Family = (Vq, Vq, Quadratic);

/// The two rulings' line pairs of the curve on the first rational member of inertia (2, 2)
/// (λ = ∞, −3, …, 3) whose rulings are parameterized, and the parameterization's radicand
/// ([`ruled_member_curve`]).
fn ruled_families(a: &Mat, b: &Mat) -> Option<([Family; 2], Option<IBig>)> {
    let lambdas = std::iter::once(None).chain((-3..=3).map(|v| Some(RBig::from(v))));
    for lambda in lambdas {
        let s = member(a, b, lambda.as_ref());
        let Some(dg) = rational_matrix(&s).diagonalize_congruent() else {
            continue;
        };
        let inertia = dg.inertia();
        if (inertia.positive, inertia.negative) != (2, 2) {
            continue;
        }
        let Ok(Some(rp)) = parameterize_doubly_ruled(&s) else {
            continue;
        };
        let other = to_quadratic(if lambda.is_some() { a } else { b });
        if let Some(families) = families_on(&rp, &other) {
            return Some((families, rp.delta));
        }
    }
    None
}

/// `F = g(u)·h(v)` on one parameterization, the roots of `g` and `h` as line pairs.
fn families_on(rp: &RuledParameterization, other: &[[Quadratic; 4]; 4]) -> Option<[Family; 2]> {
    let c0 = poly_form(other, &rp.b, &rp.b);
    let c1 = poly_form(other, &rp.b, &rp.d);
    let c2 = poly_form(other, &rp.d, &rp.d);
    let g = c0.gcd_monic(&c1).gcd_monic(&c2);
    if g.is_zero() || g.degree()? > 2 {
        return None;
    }
    // h_j = c_j / g, constants
    let mut h = Vec::new();
    for c in [&c0, &c1, &c2] {
        let (quo, rem) = c.div_rem(&g);
        if !rem.is_zero() || quo.degree().unwrap_or(0) > 0 {
            return None;
        }
        h.push(quo.coeff(0));
    }
    let (b0, b1): (Vq, Vq) = (
        (0..4).map(|k| rp.b[k].coeff(0)).collect(),
        (0..4).map(|k| rp.b[k].coeff(1)).collect(),
    );
    let (d0, d1): (Vq, Vq) = (
        (0..4).map(|k| rp.d[k].coeff(0)).collect(),
        (0..4).map(|k| rp.d[k].coeff(1)).collect(),
    );
    let cat = |x: &Vq, y: &Vq| -> Vq { x.iter().chain(y).cloned().collect() };
    let half = qr(&RBig::from_parts_signed(IBig::ONE, IBig::from(2)));
    // u-lines: g(u, w) on (u, w) ↦ (u·b₁ + w·b₀, u·d₁ + w·d₀); v-lines: h(v, z) on
    // (v, z) ↦ (z·b₀ + v·d₀, z·b₁ + v·d₁)
    Some([
        binary_points(
            &g.coeff(2),
            &g.coeff(1).mul(&half),
            &g.coeff(0),
            &cat(&b1, &d1),
            &cat(&b0, &d0),
        )?,
        binary_points(&h[2], &h[1], &h[0], &cat(&d0, &d1), &cat(&b0, &b1))?,
    ])
}

/// The curve from the rulings' line pairs when at most one ruling is real.
fn ruled_lines(
    classification: Classification,
    families: &[Family; 2],
    delta: Option<&IBig>,
) -> Option<Curve> {
    let real: Vec<bool> = families
        .iter()
        .map(|f| f.2.sign() == Some(Sign::Positive))
        .collect();
    if real[0] && real[1] {
        // four real lines meeting at four real points: the plane-pair routes
        return None;
    }
    let mut curve = Curve::empty(classification);
    for (family, is_real) in families.iter().zip(real) {
        if !is_real {
            for _ in 0..2 {
                curve.components.push(non_real(ComponentKind::Line, 1));
            }
            continue;
        }
        let (_, ends) = real_ends(family, delta);
        for end in ends {
            let component = curve.components.len();
            curve.components.push(Component {
                kind: ComponentKind::Line,
                multiplicity: 1,
                real: true,
                param: Some(line_param(&end[..4], &end[4..])),
                plane: None,
                section: None,
            });
            curve.connected.push(vec![curve.pieces.len()]);
            curve.pieces.push(RealPiece::whole(component));
        }
    }
    Some(curve)
}
