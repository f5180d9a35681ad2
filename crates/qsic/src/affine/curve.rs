//! The intersection curve in ℝ³: which pieces are bounded, where the curve meets the plane at
//! infinity, which singular points are finite — from the exact [`Curve`].
//!
//! The real curve in ℝP³ is a graph: its vertices are the real singular points and the real
//! points at infinity, its edges the arcs of the real pieces between consecutive vertices
//! (a piece with no vertex is a closed edge of its own). The curve in ℝ³ is that graph minus
//! the vertices at infinity: its connected components are the classes of edges joined at
//! finite vertices, bounded iff no edge ends at infinity. Every position is exact:
//!
//! * the points at infinity of a piece `X(u)` are the real roots of `w(u) = ℓ·X(u)` (and
//!   `u = ∞` when `deg w` drops), of Levin's `a ± d√s` those of `(ℓ·a)² − s·(ℓ·d)²` with
//!   `s ≥ 0` on the sheet `σ = −sign(ℓ·a)·sign(ℓ·d)` (both sheets where `s = 0`) —
//!   roots over ℚ(α) by the norm, signs at algebraic `u` exact
//!   ([`Poly::sign_at`](qsic_algebra::Poly)), never floats;
//! * a singular point `P` lies on a rational piece at the real roots of the gcd of the minors
//!   `xᵢ(u)Pⱼ − xⱼ(u)Pᵢ`;
//! * the order of the vertices along a piece follows its arcs (cyclically through `u = ∞`).

use super::common::surface_component;
use super::Chart;
use crate::classify::ComponentKind;
use crate::error::Error;
use crate::param::sample::plane::{
    chart_value, compatible, levin_plane_crossings, params_of_point, plane_form, same_value,
};
use crate::param::{
    ComponentParam, Curve, LevinForm, Number, NumberPoly, ParamRange, ParamValue, Point, PointPoly,
    RealPiece, Sheet,
};
use crate::quadric::Quadric;
pub use crate::vocabulary::{AffineComponent, AffineCurve, AffineSingularPoint};
use qsic_algebra::field::NumberFieldElement;
use qsic_algebra::{AlgebraicReal, Field, RBig, Ring};
use std::cmp::Ordering;

/// A vertex of the curve graph.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Vertex {
    /// A singular point (index into [`Curve::singular_points`]).
    Singular(usize),
    /// A point at infinity of one piece that is not a singular point.
    Local(usize),
}

/// A vertex met along a piece at a parameter value, on one sheet or both.
#[derive(Clone, Debug)]
struct Event {
    at: ParamValue,
    sheet: Option<Sheet>,
    vertex: Vertex,
}

fn rational(v: &RBig) -> Number {
    NumberFieldElement::rational(v.clone())
}

fn degree(p: &NumberPoly) -> usize {
    p.degree().unwrap_or(0)
}

/// Whether `t` lies in `range` (closed) and its position there: a key increasing along the
/// range from its start.
fn position(range: &ParamRange, t: &ParamValue) -> Option<(u8, Option<AlgebraicReal>)> {
    use ParamValue::{Finite, Infinity};
    let finite = |t: &ParamValue| match t {
        Finite(v) => Some(v.clone()),
        Infinity => None,
    };
    let Some((lo, hi)) = (match range {
        ParamRange::All => None,
        ParamRange::Between(lo, hi) => Some((lo, hi)),
    }) else {
        return Some(match t {
            Finite(v) => (0, Some(v.clone())),
            Infinity => (1, None),
        });
    };
    match (lo, hi) {
        (Finite(lo), Finite(hi)) if lo < hi => match t {
            Finite(v) => (lo <= v && v <= hi).then(|| (0, Some(v.clone()))),
            Infinity => None,
        },
        // through ∞: [lo, ∞) then ∞ then (−∞, hi]
        (Finite(lo), Finite(hi)) => match t {
            Finite(v) if v >= lo => Some((0, Some(v.clone()))),
            Finite(v) if v <= hi => Some((2, Some(v.clone()))),
            Finite(_) => None,
            Infinity => Some((1, None)),
        },
        (Finite(lo), Infinity) => match finite(t) {
            Some(v) => (&v >= lo).then_some((0, Some(v))),
            None => Some((1, None)),
        },
        (Infinity, Finite(hi)) => match finite(t) {
            Some(v) => (&v <= hi).then_some((1, Some(v))),
            None => Some((0, None)),
        },
        (Infinity, Infinity) => Some(match finite(t) {
            Some(v) => (1, Some(v)),
            None => (0, None),
        }),
    }
}

/// The points at infinity of one piece's component parameterization, as events (vertices
/// `Local(next…)` unless they are singular points already met at the same parameter).
struct InfinityEvents<'a> {
    l: &'a [RBig; 4],
    next_local: &'a mut usize,
}

impl InfinityEvents<'_> {
    fn local(&mut self) -> Vertex {
        *self.next_local += 1;
        Vertex::Local(*self.next_local - 1)
    }

    /// Events of a rational parameterization; `None` if it lies at infinity.
    fn rational(&mut self, x: &PointPoly, k: usize, singular: &[Event]) -> Option<Vec<Event>> {
        let w = plane_form(self.l, x);
        if w.is_zero() {
            return None;
        }
        let mut at: Vec<ParamValue> = w.real_roots().into_iter().map(ParamValue::Finite).collect();
        if degree(&w) < k {
            at.push(ParamValue::Infinity);
        }
        Some(
            at.into_iter()
                .map(|t| {
                    let vertex = singular
                        .iter()
                        .find(|e| same_value(&e.at, &t))
                        .map(|e| e.vertex)
                        .unwrap_or_else(|| self.local());
                    Event {
                        at: t,
                        sheet: None,
                        vertex,
                    }
                })
                .collect(),
        )
    }

    /// Events of Levin's `a ± d√s` (`s` of degree 4, `a` of degree `k`, `d` of `k − 2`),
    /// with `alternate` another form of the same sheets: where one form vanishes (a base
    /// point, e.g. where the ruling is tangent), the other gives the point.
    fn levin(
        &mut self,
        primary: &LevinForm,
        s: &NumberPoly,
        alternate: Option<&LevinForm>,
    ) -> Result<Vec<Event>, Error> {
        Ok(levin_plane_crossings(self.l, primary, s, alternate)?
            .into_iter()
            .map(|(at, sheet)| Event {
                at,
                sheet,
                vertex: self.local(),
            })
            .collect())
    }
}

/// The vertices met along a closed piece, in order (consecutive repeats merged).
fn ordered_vertices(arcs: &[crate::param::Arc], events: &[Event]) -> Vec<Vertex> {
    let mut out: Vec<Vertex> = Vec::new();
    for arc in arcs {
        let mut here: Vec<((u8, Option<AlgebraicReal>), Vertex)> = events
            .iter()
            .filter(|e| match (e.sheet, arc.sheet) {
                (None, _) | (_, Sheet::Only) => true,
                (Some(a), b) => a == b,
            })
            .filter_map(|e| position(&arc.range, &e.at).map(|k| (k, e.vertex)))
            .collect();
        here.sort_by(|a, b| cmp_key(&a.0, &b.0));
        if arc.reversed {
            here.reverse();
        }
        for (_, v) in here {
            if out.last() != Some(&v) {
                out.push(v);
            }
        }
    }
    while out.len() > 1 && out.first() == out.last() {
        out.pop();
    }
    out
}

fn cmp_key(a: &(u8, Option<AlgebraicReal>), b: &(u8, Option<AlgebraicReal>)) -> Ordering {
    a.0.cmp(&b.0).then_with(|| match (&a.1, &b.1) {
        (Some(x), Some(y)) => x.cmp(y),
        _ => Ordering::Equal,
    })
}

/// A tiny union–find.
struct Classes(Vec<usize>);

impl Classes {
    fn find(&mut self, mut i: usize) -> usize {
        while self.0[i] != i {
            self.0[i] = self.0[self.0[i]];
            i = self.0[i];
        }
        i
    }
    fn union(&mut self, a: usize, b: usize) {
        let (a, b) = (self.find(a), self.find(b));
        self.0[a] = b;
    }
}

/// The curve of `a` and `b` in the chart (see the module documentation).
///
/// # Errors
/// [`Error::Unsupported`] when a singular point and a component live in number fields that
/// were made separately (the position of the point on the component is then not computed);
/// [`Error::Algebra`] for an inconsistent curve (a piece that is not closed, a constant
/// parameterization).
pub fn affine_curve(
    curve: &Curve,
    a: &Quadric,
    b: &Quadric,
    chart: &Chart,
) -> Result<AffineCurve, Error> {
    let l = chart.form();
    let singular_at_infinity: Vec<bool> = curve
        .singular_points
        .iter()
        .map(|s| chart_value(l, &s.point).is_zero())
        .collect();
    let mut next_local = 0;
    // per piece: its vertices in order, or None at infinity
    let mut piece_vertices: Vec<Option<Vec<Vertex>>> = Vec::new();
    // the events of a Levin component, computed for its first piece: its other pieces reuse
    // them with fresh local vertices (as if computed again)
    let mut levin_events: Vec<Option<Vec<Event>>> = vec![None; curve.components.len()];
    for piece in &curve.pieces {
        let RealPiece::Curve {
            component,
            arcs,
            closed,
        } = piece
        else {
            piece_vertices.push(Some(Vec::new()));
            continue;
        };
        if !closed {
            return Err(Error::Algebra("a real piece that is not closed".into()));
        }
        let param = curve.components[*component].param.as_ref().ok_or_else(|| {
            Error::Algebra("a real piece of a component without parameterization".into())
        })?;
        let mut inf = InfinityEvents {
            l,
            next_local: &mut next_local,
        };
        let events = match param {
            ComponentParam::Rational { x, degree } => {
                let mut singular = Vec::new();
                for (j, s) in curve.singular_points.iter().enumerate() {
                    for at in params_of_point(x, *degree, &s.point)? {
                        singular.push(Event {
                            at,
                            sheet: None,
                            vertex: Vertex::Singular(j),
                        });
                    }
                }
                match inf.rational(x, *degree, &singular) {
                    None => {
                        piece_vertices.push(None);
                        continue;
                    }
                    Some(mut e) => {
                        e.retain(|e| !matches!(e.vertex, Vertex::Singular(_)));
                        e.extend(singular);
                        e
                    }
                }
            }
            ComponentParam::Levin {
                a,
                d,
                s,
                degree,
                alternate,
            } => match &levin_events[*component] {
                Some(cached) => cached
                    .iter()
                    .map(|e| Event {
                        vertex: match e.vertex {
                            Vertex::Local(_) => inf.local(),
                            v => v,
                        },
                        ..e.clone()
                    })
                    .collect(),
                None => {
                    let primary = LevinForm {
                        a: a.clone(),
                        d: d.clone(),
                        degree: *degree,
                    };
                    let events = inf.levin(&primary, s, alternate.as_deref())?;
                    levin_events[*component] = Some(events.clone());
                    events
                }
            },
            ComponentParam::Point(_) => Vec::new(),
        };
        piece_vertices.push(Some(ordered_vertices(arcs, &events)));
    }
    let at_infinity = |v: &Vertex| match v {
        Vertex::Singular(j) => singular_at_infinity[*j],
        Vertex::Local(_) => true,
    };
    // edges: (piece, from, to); classes over edges and finite singular vertices
    let mut edges: Vec<(usize, Option<Vertex>, Option<Vertex>)> = Vec::new();
    for (i, vs) in piece_vertices.iter().enumerate() {
        let Some(vs) = vs else { continue };
        if !matches!(curve.pieces[i], RealPiece::Curve { .. }) {
            continue;
        }
        if vs.is_empty() {
            edges.push((i, None, None));
        }
        for k in 0..vs.len() {
            edges.push((i, Some(vs[k]), Some(vs[(k + 1) % vs.len()])));
        }
    }
    let ns = curve.singular_points.len();
    let mut classes = Classes((0..edges.len() + ns).collect());
    for (e, (_, from, to)) in edges.iter().enumerate() {
        for v in [from, to].into_iter().flatten() {
            if let Vertex::Singular(j) = v {
                if !singular_at_infinity[*j] {
                    classes.union(e, edges.len() + j);
                }
            }
        }
    }
    let mut unbounded_class = vec![false; edges.len() + ns];
    let mut has_edge = vec![false; edges.len() + ns];
    for (e, (_, from, to)) in edges.iter().enumerate() {
        let c = classes.find(e);
        has_edge[c] = true;
        if [from, to].into_iter().flatten().any(at_infinity) {
            unbounded_class[c] = true;
        }
    }
    let (mut bounded, mut unbounded) = (0, 0);
    for c in 0..edges.len() + ns {
        if classes.find(c) == c && has_edge[c] {
            if unbounded_class[c] {
                unbounded += 1;
            } else {
                bounded += 1;
            }
        }
    }
    // points at infinity: singular ones, local ones, isolated points there
    let mut locals = std::collections::BTreeSet::new();
    for vs in piece_vertices.iter().flatten() {
        for v in vs {
            if let Vertex::Local(id) = v {
                locals.insert(*id);
            }
        }
    }
    let mut isolated = 0;
    let mut isolated_at_infinity = 0;
    for piece in &curve.pieces {
        if let RealPiece::Point { point, .. } = piece {
            if !chart_value(l, point).is_zero() {
                isolated += 1;
            } else if !curve
                .singular_points
                .iter()
                .any(|s| same_point(&s.point, point))
            {
                isolated_at_infinity += 1;
            }
        }
    }
    let singular_inf = singular_at_infinity.iter().filter(|&&x| x).count();
    let components = components_view(curve, &piece_vertices, &singular_at_infinity, a, b, chart);
    let singular_points = curve
        .singular_points
        .iter()
        .zip(&singular_at_infinity)
        .map(|(s, &inf)| AffineSingularPoint {
            kind: s.kind,
            at_infinity: inf,
            point: (!inf).then(|| affine_point(chart, &s.point)),
        })
        .collect();
    Ok(AffineCurve {
        curves_bounded: bounded,
        curves_unbounded: unbounded,
        isolated_points: isolated,
        points_at_infinity: singular_points_at_infinity_on_finite_components(
            curve,
            &singular_at_infinity,
            a,
            b,
            chart,
        ) + locals.len()
            + isolated_at_infinity,
        singular_finite: ns - singular_inf,
        singular_at_infinity: singular_inf,
        components,
        singular_points,
    })
}

/// The singular points at infinity that lie on a component not contained in the plane at
/// infinity (the others are points of components at infinity only, which the counts leave out).
///
/// Components lie in the plane at infinity `ℓ = 0` only in two ways: the conics at infinity of
/// `A` and `B` share one line (the only component there, and every singular point on it is
/// where it meets the rest of the curve, which is finite), or they are proportional, so that a
/// member `M` of the pencil is `ℓ·L`. Then the curve is `(A ∩ {ℓ = 0}) ∪ (A ∩ {L = 0})` and a
/// point at infinity is on a finite component iff `L(X) = 0` (never when `L ∝ ℓ`).
fn singular_points_at_infinity_on_finite_components(
    curve: &Curve,
    singular_at_infinity: &[bool],
    a: &Quadric,
    b: &Quadric,
    chart: &Chart,
) -> usize {
    let at_infinity = curve
        .singular_points
        .iter()
        .zip(singular_at_infinity)
        .filter(|(_, &inf)| inf);
    let (ma, mb) = (
        chart.matrix_in_chart(a.matrix()),
        chart.matrix_in_chart(b.matrix()),
    );
    let block = |m: &[[RBig; 4]; 4]| -> Vec<RBig> {
        (0..3)
            .flat_map(|i| (0..3).map(move |j| m[i][j].clone()))
            .collect()
    };
    let (qa, qb) = (block(&ma), block(&mb));
    // a member M with a zero 3×3 block, if any
    let member: Option<[[RBig; 4]; 4]> = match qa.iter().position(|v| *v != RBig::ZERO) {
        None => Some(ma.clone()),
        Some(k) => {
            let lambda = &qb[k] / &qa[k];
            qa.iter().zip(&qb).all(|(x, y)| &lambda * x == *y).then(|| {
                std::array::from_fn(|i| std::array::from_fn(|j| &lambda * &ma[i][j] - &mb[i][j]))
            })
        }
    };
    let Some(m) = member else {
        return at_infinity.count();
    };
    // M = w·L in chart coordinates: L = (2M₀₃, 2M₁₃, 2M₂₃, M₃₃)
    let two = RBig::from(2);
    let l_form: [RBig; 4] = [
        &two * &m[0][3],
        &two * &m[1][3],
        &two * &m[2][3],
        m[3][3].clone(),
    ];
    if l_form[..3].iter().all(|v| *v == RBig::ZERO) {
        return 0;
    }
    at_infinity
        .filter(|(s, _)| chart_value(&l_form, &chart.to_chart_number(&s.point)).is_zero())
        .count()
}

/// Whether two points are the same projective point (exactly; points in fields made
/// separately are taken as distinct).
fn same_point(p: &Point, q: &Point) -> bool {
    let items: Vec<&Number> = p.iter().chain(q.iter()).collect();
    compatible(&items) && (0..4).all(|i| (i + 1..4).all(|j| p[i].mul(&q[j]) == p[j].mul(&q[i])))
}

/// The chart's affine coordinates of a finite point.
fn affine_point(chart: &Chart, p: &Point) -> [Number; 3] {
    // the chart's coordinates are rational combinations of the input ones
    let row = |i: usize| -> Number {
        let r = chart.basis_row(i);
        let mut acc = Number::zero();
        for j in 0..4 {
            if r[j] != RBig::ZERO {
                acc = acc.add(&p[j].mul(&rational(&r[j])));
            }
        }
        acc
    };
    let w = row(3);
    std::array::from_fn(|i| row(i).mul(&w.inv().unwrap_or_else(Number::zero)))
}

/// Per component: name, at infinity, bounded, points at infinity.
fn components_view(
    curve: &Curve,
    piece_vertices: &[Option<Vec<Vertex>>],
    singular_at_infinity: &[bool],
    a: &Quadric,
    b: &Quadric,
    chart: &Chart,
) -> Vec<AffineComponent> {
    let l = chart.form();
    curve
        .components
        .iter()
        .enumerate()
        .map(|(ci, comp)| {
            if matches!(comp.kind, ComponentKind::Plane | ComponentKind::Quadric) {
                return surface_component(comp, a, chart);
            }
            let pieces: Vec<usize> = (0..curve.pieces.len())
                .filter(|&i| curve.pieces[i].component() == ci)
                .collect();
            let at_inf = match &comp.param {
                Some(ComponentParam::Rational { x, .. }) => plane_form(l, x).is_zero(),
                Some(ComponentParam::Point(p)) => chart_value(l, p).is_zero(),
                _ => false,
            } && comp.param.is_some();
            let mut infinite = std::collections::BTreeSet::new();
            for &i in &pieces {
                for v in piece_vertices[i].iter().flatten() {
                    let inf = match v {
                        Vertex::Singular(j) => singular_at_infinity[*j],
                        Vertex::Local(_) => true,
                    };
                    if inf {
                        infinite.insert(match v {
                            Vertex::Singular(j) => (0, *j),
                            Vertex::Local(id) => (1, *id),
                        });
                    }
                }
            }
            let n = if at_inf { 0 } else { infinite.len() };
            let real = comp.real && !pieces.is_empty();
            let name = real.then(|| match (comp.kind, at_inf) {
                (ComponentKind::Conic, true) => "conic_at_infinity",
                (ComponentKind::Conic, false) => match n {
                    0 if is_circle(comp, a, b, chart) => "circle",
                    0 => "ellipse",
                    1 => "parabola",
                    _ => "hyperbola",
                },
                (ComponentKind::Line, true) => "line_at_infinity",
                (ComponentKind::Line, false) => "line",
                (ComponentKind::Point, true) => "point_at_infinity",
                (ComponentKind::Point, false) => "point",
                (k, _) => k.key(),
            });
            AffineComponent {
                kind: comp.kind,
                name,
                at_infinity: at_inf,
                bounded: (real && !at_inf).then_some(n == 0),
                points_at_infinity: n,
                multiplicity: comp.multiplicity,
            }
        })
        .collect()
}

/// Whether a real conic component with no real point at infinity is a circle: its plane's
/// direction space carries, from `A` (or `B` when `A` contains the plane), a quadratic part
/// proportional to the Euclidean one of the chart.
fn is_circle(comp: &crate::param::Component, a: &Quadric, b: &Quadric, chart: &Chart) -> bool {
    let Some(ComponentParam::Rational { x, .. }) = &comp.param else {
        return false;
    };
    // three points of the conic in chart coordinates span its plane
    let pts: Vec<[Number; 4]> = [0i64, 1, -1]
        .iter()
        .map(|&u| {
            let u = Number::from_int(&u.into());
            let p: [Number; 4] = std::array::from_fn(|i| x[i].eval(&u));
            chart.to_chart_number(&p)
        })
        .collect();
    let items: Vec<&Number> = pts.iter().flatten().collect();
    if !compatible(&items) {
        return false;
    }
    // the plane's normal (n₀, n₁, n₂): 3×3 minors of the three points, columns without k
    let minor = |cols: [usize; 3]| -> Number {
        let m = |r: usize, c: usize| pts[r][cols[c]].clone();
        let mut acc = Number::zero();
        for (perm, sign) in [
            ([0, 1, 2], 1),
            ([1, 2, 0], 1),
            ([2, 0, 1], 1),
            ([0, 2, 1], -1),
            ([2, 1, 0], -1),
            ([1, 0, 2], -1),
        ] {
            let t = m(0, perm[0]).mul(&m(1, perm[1])).mul(&m(2, perm[2]));
            acc = if sign > 0 { acc.add(&t) } else { acc.sub(&t) };
        }
        acc
    };
    // plane coefficient of coordinate i: ± the minor without column i
    let n: [Number; 3] = [minor([1, 2, 3]), minor([0, 2, 3]).neg(), minor([0, 1, 3])];
    let Some(k) = (0..3).find(|&k| !n[k].is_zero()) else {
        return false;
    };
    // a basis of the directions n⊥
    let (i, j) = match k {
        0 => (1, 2),
        1 => (0, 2),
        _ => (0, 1),
    };
    let mut v1 = [Number::zero(), Number::zero(), Number::zero()];
    let mut v2 = v1.clone();
    v1[i] = n[k].clone();
    v1[k] = n[i].neg();
    v2[j] = n[k].clone();
    v2[k] = n[j].neg();
    let gram = |m: &dyn Fn(usize, usize) -> Number| -> [Number; 3] {
        let f = |x: &[Number; 3], y: &[Number; 3]| {
            let mut acc = Number::zero();
            for r in 0..3 {
                for c in 0..3 {
                    acc = acc.add(&x[r].mul(&m(r, c)).mul(&y[c]));
                }
            }
            acc
        };
        [f(&v1, &v1), f(&v1, &v2), f(&v2, &v2)]
    };
    let euclid = gram(&|r, c| Number::from_int(&i64::from(r == c).into()));
    for q in [a, b] {
        let m = chart.matrix_in_chart(q.matrix());
        let g = gram(&|r, c| rational(&m[r][c]));
        if g.iter().all(Number::is_zero) {
            continue;
        }
        let cross = |p: usize, r: usize| g[p].mul(&euclid[r]) == g[r].mul(&euclid[p]);
        return cross(0, 1) && cross(0, 2) && cross(1, 2);
    }
    false
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::parse_quadric;
    use crate::param::parameterize;

    fn view(a: &str, b: &str, chart: [i64; 4]) -> AffineCurve {
        let (a, b) = (parse_quadric(a).unwrap(), parse_quadric(b).unwrap());
        let curve = parameterize(&a, &b).unwrap();
        affine_curve(&curve, &a, &b, &Chart::new(chart.map(RBig::from)).unwrap()).unwrap()
    }

    fn counts(v: &AffineCurve) -> [usize; 4] {
        [
            v.curves_bounded,
            v.curves_unbounded,
            v.isolated_points,
            v.points_at_infinity,
        ]
    }

    /// The cylinders x² + y² = 1 and y² + z² = 4 meet in two loops, z ≥ √3 and z ≤ −√3,
    /// each `(cos θ, sin θ, ±√(4 − sin²θ))`. Seen with various planes at infinity: `w = 0`
    /// and `z = 0` miss them (two bounded curves); `x = 0` and `y = 0` cut each loop twice
    /// (four unbounded arcs, four points at infinity); `x = w` touches each loop once, at
    /// `(1, 0, ±2)` (two unbounded curves, two points at infinity).
    #[test]
    fn two_loops_seen_from_five_planes_at_infinity() {
        let (a, b) = ("x^2+y^2-1", "y^2+z^2-4");
        assert_eq!(counts(&view(a, b, [0, 0, 0, 1])), [2, 0, 0, 0]);
        assert_eq!(counts(&view(a, b, [0, 0, 1, 0])), [2, 0, 0, 0]);
        assert_eq!(counts(&view(a, b, [1, 0, 0, 0])), [0, 4, 0, 4]);
        assert_eq!(counts(&view(a, b, [0, 1, 0, 0])), [0, 4, 0, 4]);
        assert_eq!(counts(&view(a, b, [1, 0, 0, -1])), [0, 2, 0, 2]);
        let v = view(a, b, [1, 0, 0, 0]);
        assert_eq!(v.components.len(), 1);
        let c = &v.components[0];
        assert_eq!(
            (c.name, c.at_infinity, c.bounded, c.points_at_infinity),
            (Some("quartic"), false, Some(false), 4)
        );
        assert_eq!(view(a, b, [0, 0, 0, 1]).components[0].bounded, Some(true));
        assert_eq!((v.singular_finite, v.singular_at_infinity), (0, 0));
    }
}
