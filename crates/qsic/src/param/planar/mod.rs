//! Curves made of conics and lines: the intersections that lie on a pair of planes of the
//! pencil (cases 13–35, singular pencils).
//!
//! | entry point | what |
//! |---|---|
//! | [`plane_pair_curve`] | a member `P` of rank ≤ 2 at a rational λ, split into its planes; each plane cut by another member |
//! | [`super::concurrent::concurrent_lines_curve`] | no rational plane pair: four concurrent lines, the cone over two conics' meeting points |
//! | [`skew::conjugate_pair_curve`] | no rational plane pair: the skew quadrilateral at conjugate quadratic λ (real: kernels; complex: the rulings of a rational member) |
//!
//! **Method.** At a real λ a symmetric member has rank ≤ 2 iff `E₃(λ) = E₄(λ) = 0` (`E_k` the
//! sums of principal `k`-minors: the elementary symmetric functions of its real eigenvalues), so
//! the candidates are the rational roots of `gcd(E₃, E₄)` (of `E₃` when `E₄ ≡ 0`; every λ when
//! both vanish) and `λ = ∞`. `P = c·l₁·l₂` ([`plane_pair`]) over ℚ or ℚ(√δ); the
//! intersection is `P ∩ Q` for any other member `Q`, i.e. the conics `Cᵢ = Q|lᵢ` (`Eᵢᵀ Q Eᵢ`
//! for a basis `Eᵢ` of the plane), each counted with the plane's multiplicity: rank 3 a conic,
//! rank 2 two lines through the singular point `kᵢ`, rank 1 a double line, rank 0 the plane.
//! Components in different planes meet only on `V = l₁ ∩ l₂` (rational: the kernel of `P`),
//! at the roots of `Q|V`; `V` itself is a component when `Q|V ≡ 0`. Complex conjugate planes
//! (`δ < 0`) hold no real point off `V`.
//!
//! A real conic gets a real point, the first of: a rational point of `V ∩ Q` (a rational root
//! of the binary form `Q|V`; the meeting points lie on both planes, so no conic is solved and
//! nothing factored); over ℚ a rational point by [`find_point`]; in a plane over ℚ(√δ) one over
//! ℚ(√δ) from a congruence diagonalization; a point of `V ∩ Q` over ℚ(√D), `D` the
//! discriminant of `Q|V`; over ℚ the point of [`find_point`] over ℚ(√e), in a plane over ℚ(√δ)
//! one over ℚ(√δ, √r) from the diagonalization. The conic is parameterized by the lines through
//! it, `X(u) = 2(yᵀCv)v − (vᵀCv)y`,
//! `v = e_a + u·e_b`. ℚ(√δ, √r) is written ℚ(γ) with an explicit primitive element: `γ = √δ + √r`
//! for a rational `r`, `γ = √r` otherwise (`√δ = (γ² − a)/b` for `r = a + b√δ`).

mod point;
mod skew;

use super::curve::{self, Component, ComponentParam, Curve, Number, PlaneSection};
use super::curve::{RealPiece, SingularPoint};
pub(super) use super::parts::{line_param, non_real, rational_roots, to_point, Mat};
use super::surface::sqrt_in_field;
use crate::classify::{Classification, ComponentKind, SingularPointKind};
use crate::error::Error;
use crate::quadric::Quadric;
use qsic_algebra::conic::{find_point, ConicPoint};
use qsic_algebra::field::{NumberField, Quadratic};
use qsic_algebra::linalg::forms::{plane_pair, sqrt_rational, PlanePair, PlanePairKind};
use qsic_algebra::linalg::pencil::pencil_principal_minor_sums;
use qsic_algebra::linalg::Matrix;
use qsic_algebra::{AlgebraicReal, Field, IBig, Poly, RBig, Ring, Sign};
use skew::conjugate_pair_curve;

/// A vector over ℚ or one ℚ(√δ).
type Vq = Vec<Quadratic>;

fn qr(v: &RBig) -> Quadratic {
    Quadratic::rational(v.clone())
}

fn integer_matrix(q: &Quadric) -> Mat {
    let m = q.integer_matrix().entries();
    std::array::from_fn(|i| std::array::from_fn(|j| RBig::from(m[i][j].clone())))
}

fn member(a: &Mat, b: &Mat, lambda: Option<&RBig>) -> Mat {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| match lambda {
            Some(l) => l * &a[i][j] - &b[i][j],
            None => a[i][j].clone(),
        })
    })
}

fn rational_matrix(m: &Mat) -> Matrix<RBig> {
    Matrix::from_array(m.clone())
}

fn form(m: &Matrix<Quadratic>, x: &[Quadratic], y: &[Quadratic]) -> Quadratic {
    let my = m.mul_vec(y);
    x.iter()
        .zip(&my)
        .fold(Quadratic::zero(), |acc, (a, b)| acc.add(&a.mul(b)))
}

fn dot(x: &[Quadratic], y: &[Quadratic]) -> Quadratic {
    x.iter()
        .zip(y)
        .fold(Quadratic::zero(), |acc, (a, b)| acc.add(&a.mul(b)))
}

/// `x ∝ y` (both nonzero): every 2×2 minor vanishes.
fn same_point(x: &[Quadratic], y: &[Quadratic]) -> bool {
    (0..x.len()).all(|i| (i + 1..x.len()).all(|j| x[i].mul(&y[j]).sub(&x[j].mul(&y[i])).is_zero()))
}

/// The radicand of the first irrational coordinate.
fn radicand_of<'a>(xs: impl IntoIterator<Item = &'a Quadratic>) -> Option<IBig> {
    xs.into_iter()
        .find(|x| x.as_rational().is_none())
        .map(|x| x.radicand().clone())
}

/// `x` scaled so that its first nonzero coordinate is 1; `None` if `x` is not proportional to
/// a real vector (complex coordinates) or zero.
fn real_normalized(x: &[Quadratic]) -> Option<Vq> {
    let pivot = x.iter().find(|v| !v.is_zero())?;
    let inv = pivot.inv()?;
    let y: Vq = x.iter().map(|v| v.mul(&inv)).collect();
    y.iter().all(Quadratic::is_real).then_some(y)
}

/// A real field ℚ(θ) holding ℚ(√δ) (`δ > 0`) and possibly one more square root `√r`: the images
/// of `√δ` and `√r` there.
pub(super) struct Ext {
    pub(super) sqrt_delta: Option<Number>,
    pub(super) root: Option<Number>,
}

impl Ext {
    /// ℚ, ℚ(√δ), ℚ(√r) or ℚ(√δ, √r) (module docs); `r > 0` is not a square in ℚ(√δ).
    pub(super) fn new(delta: Option<&IBig>, r: Option<&Quadratic>) -> Ext {
        match (delta, r) {
            (None, None) => Ext {
                sqrt_delta: None,
                root: None,
            },
            (Some(d), None) => Ext {
                sqrt_delta: Some(curve::sqrt_field(d).generator()),
                root: None,
            },
            (None, Some(r)) => {
                let r = r.as_rational().expect("a rational radicand over ℚ");
                Ext {
                    sqrt_delta: None,
                    root: Some(curve::from_quadratic(&sqrt_rational(r), None)),
                }
            }
            (Some(d), Some(r)) => {
                let d = RBig::from(d.clone());
                let int = |c: Vec<RBig>| Poly::from_rational(&Poly::new(c)).0;
                let nf = |p: &Poly, pick: &dyn Fn(&[AlgebraicReal]) -> AlgebraicReal| {
                    let roots = AlgebraicReal::real_roots_of(p);
                    NumberField::new(&pick(&roots)).generator()
                };
                match r.as_rational() {
                    Some(r) => {
                        // γ = √δ + √r, the largest root of x⁴ − 2(δ + r)x² + (δ − r)²
                        let s = &d + r;
                        let t = &d - r;
                        let p = int(vec![
                            &t * &t,
                            RBig::ZERO,
                            RBig::from(-2) * s,
                            RBig::ZERO,
                            RBig::ONE,
                        ]);
                        let g = nf(&p, &|roots| roots.last().expect("real roots").clone());
                        let num = g.mul(&g).add(&curve::rational(t));
                        let two_g = g.add(&g);
                        let sd = num.div(&two_g).expect("γ ≠ 0");
                        let sr = g.sub(&sd);
                        Ext {
                            sqrt_delta: Some(sd),
                            root: Some(sr),
                        }
                    }
                    None => {
                        // γ = √r, r = a + b√δ: a root of x⁴ − 2ax² + (a² − b²δ)
                        let (a, b) = (r.rational_part().clone(), r.radical_part().clone());
                        let p = int(vec![
                            &a * &a - &b * &b * &d,
                            RBig::ZERO,
                            RBig::from(-2) * &a,
                            RBig::ZERO,
                            RBig::ONE,
                        ]);
                        // roots ±√r, ±√r̄; b < 0 means r̄ > r > 0: √r is the second largest
                        let b_positive = b > RBig::ZERO;
                        let g = nf(&p, &|roots| {
                            let n = roots.len();
                            if b_positive {
                                roots[n - 1].clone()
                            } else {
                                roots[n - 2].clone()
                            }
                        });
                        let sd = g
                            .mul(&g)
                            .sub(&curve::rational(a))
                            .div(&curve::rational(b))
                            .expect("b ≠ 0");
                        Ext {
                            sqrt_delta: Some(sd),
                            root: Some(g),
                        }
                    }
                }
            }
        }
    }

    /// `a + b√δ` in ℚ(θ).
    pub(super) fn embed(&self, q: &Quadratic) -> Number {
        match (q.as_rational(), &self.sqrt_delta) {
            (Some(r), _) => curve::rational(r.clone()),
            (None, Some(s)) => curve::rational(q.rational_part().clone())
                .add(&s.mul(&curve::rational(q.radical_part().clone()))),
            (None, None) => panic!("an irrational coordinate without its field"),
        }
    }

    fn embed_vec(&self, v: &[Quadratic]) -> Vec<Number> {
        v.iter().map(|x| self.embed(x)).collect()
    }

    /// `x + √r·y`.
    fn with_root(&self, x: &[Quadratic], y: &[Quadratic]) -> Vec<Number> {
        let root = self.root.as_ref().expect("a field with √r");
        x.iter()
            .zip(y)
            .map(|(a, b)| self.embed(a).add(&root.mul(&self.embed(b))))
            .collect()
    }
}

/// The conic `yᵀCy = 0` of the plane spanned by the columns of `e` (4×3), through its point
/// `y`: `X(u) = E·(2(yᵀCv)v − (vᵀCv)y)`, `v = e_a + u·e_b` (module docs).
fn conic_param(e: &[Vec<Number>], c: &[Vec<Number>], y: &[Number]) -> ComponentParam {
    let k = (0..3).find(|&i| !y[i].is_zero()).expect("a nonzero point");
    let (ia, ib) = match k {
        0 => (1, 2),
        1 => (0, 2),
        _ => (0, 1),
    };
    let mut v: Vec<Poly<Number>> = vec![Poly::zero(), Poly::zero(), Poly::zero()];
    v[ia] = Poly::constant(Number::one());
    v[ib] = Poly::new(vec![Number::zero(), Number::one()]);
    let cv: Vec<Poly<Number>> = (0..3)
        .map(|i| (0..3).fold(Poly::zero(), |acc, j| &acc + &v[j].scale(&c[i][j])))
        .collect();
    let ycv = (0..3).fold(Poly::zero(), |acc, i| &acc + &cv[i].scale(&y[i]));
    let vcv = (0..3).fold(Poly::zero(), |acc, i| &acc + &(&v[i] * &cv[i]));
    let two = Number::from_int(&IBig::from(2));
    let x: Vec<Poly<Number>> = (0..3)
        .map(|i| &(&ycv.scale(&two) * &v[i]) - &vcv.scale(&y[i]))
        .collect();
    ComponentParam::Rational {
        x: std::array::from_fn(|r| {
            (0..3).fold(Poly::zero(), |acc, i| &acc + &x[i].scale(&e[r][i]))
        }),
        degree: 2,
    }
}

/// The plane pair member chosen to split the curve.
struct Split {
    /// `P` as a rational matrix.
    p: Mat,
    /// Another member: `A` for finite λ, `B` for `λ = ∞`.
    other: Mat,
    pair: PlanePair,
}

/// The member of rank ≤ 2 at a rational λ whose planes need the least: rational, double,
/// complex conjugate (only their common line is real), real conjugate (least radicand).
fn choose_split(a: &Mat, b: &Mat) -> Result<Split, Error> {
    let e = pencil_principal_minor_sums(a, b);
    let e3 = Poly::new(e[2].to_vec());
    let e4 = Poly::new(e[3].to_vec());
    let mut lambdas: Vec<Option<RBig>> = Vec::new();
    if rational_matrix(a).rank() <= 2 {
        lambdas.push(None);
    }
    if e3.is_zero() {
        lambdas.extend([0, 1, -1, 2].map(|v| Some(RBig::from(v))));
    } else {
        let g = if e4.is_zero() { e3 } else { e3.gcd_monic(&e4) };
        lambdas.extend(rational_roots(&g).into_iter().map(Some));
    }
    let score = |pair: &PlanePair| -> (u8, IBig) {
        let rad = radicand_of(pair.planes[0].iter()).unwrap_or_default();
        let kind = match pair.kind {
            PlanePairKind::Rational => 0,
            PlanePairKind::Double => 1,
            PlanePairKind::ComplexConjugate => 2,
            PlanePairKind::RealConjugate => 3,
        };
        (kind, rad.clone() * rad)
    };
    let mut best: Option<Split> = None;
    for lambda in lambdas {
        let p = member(a, b, lambda.as_ref());
        let Some(pair) = plane_pair(&rational_matrix(&p)) else {
            continue;
        };
        if best.as_ref().is_none_or(|s| score(&pair) < score(&s.pair)) {
            let other = if lambda.is_some() {
                a.clone()
            } else {
                b.clone()
            };
            best = Some(Split { p, other, pair });
        }
    }
    best.ok_or_else(|| {
        Error::Unsupported("the plane pairs of the pencil are at irrational λ (not yet)".into())
    })
}

/// What one plane of the pair holds.
struct Plane {
    /// Its coefficients.
    l: Vq,
    /// 1, or 2 for a double plane.
    mult: u32,
    /// Its field is real (not a complex conjugate pair).
    real: bool,
    /// A basis of the plane, 4×3.
    e: Matrix<Quadratic>,
    /// `Q|plane` in that basis.
    c: Matrix<Quadratic>,
    rank: usize,
    /// Rank 2: the singular point of the line pair (in ℙ³).
    kernel: Option<Vq>,
    /// Rank 2: the two lines are real.
    lines_real: bool,
    /// Its components (indices into the curve's).
    comps: Vec<usize>,
}

/// The intersection curve when a member of the pencil at a rational λ (or ∞) has rank ≤ 2
/// (module docs): its components, their meeting points, the real pieces and their
/// connection.
///
/// # Errors
/// [`Error::Unsupported`] when every member of rank ≤ 2 is at an irrational λ and the curve
/// is neither four concurrent lines nor a skew quadrilateral at quadratic λ (a rational
/// member with parameterized rulings, for the joins needing degree 8);
/// [`Error::Algebra`] when a conic's rational point is out of the factoring bounds.
pub(crate) fn plane_pair_curve(
    classification: Classification,
    qa: &Quadric,
    qb: &Quadric,
) -> Result<Curve, Error> {
    let (am, bm) = (integer_matrix(qa), integer_matrix(qb));
    let split = match choose_split(&am, &bm) {
        Ok(split) => split,
        Err(e) => {
            if let Some(curve) =
                super::concurrent::concurrent_lines_curve(classification.clone(), &am, &bm)
            {
                return Ok(curve);
            }
            return match conjugate_pair_curve(classification.clone(), &am, &bm)? {
                Some(curve) => Ok(curve),
                None => Err(e),
            };
        }
    };
    let delta = radicand_of(split.pair.planes.iter().flatten());
    let q = rational_matrix(&split.other).map(qr);
    let complex = split.pair.kind == PlanePairKind::ComplexConjugate;
    let double = split.pair.kind == PlanePairKind::Double;
    let plane_list: Vec<(Vq, u32)> = if double {
        vec![(split.pair.planes[0].clone(), 2)]
    } else {
        split.pair.planes.iter().map(|l| (l.clone(), 1)).collect()
    };
    let mut planes: Vec<Plane> = plane_list
        .into_iter()
        .map(|(l, mult)| {
            let row = Matrix::from_rows(vec![l.clone()]).expect("one row");
            let basis = row.kernel();
            let e = Matrix::from_fn(4, 3, |i, j| basis[j][i].clone());
            let c = &(&e.transpose() * &q) * &e;
            let rank = c.rank();
            Plane {
                l,
                mult,
                real: !complex,
                e,
                c,
                rank,
                kernel: None,
                lines_real: false,
                comps: Vec::new(),
            }
        })
        .collect();
    // V = l₁ ∩ l₂: the kernel of P (rational), and Q on it
    let (v, qv) = if planes.len() == 2 {
        let kernel = rational_matrix(&split.p).kernel();
        let v: [Vq; 2] = [
            kernel[0].iter().map(qr).collect(),
            kernel[1].iter().map(qr).collect(),
        ];
        let coeffs = [
            form(&q, &v[0], &v[0]),
            form(&q, &v[0], &v[1]),
            form(&q, &v[1], &v[1]),
        ];
        (Some(v), Some(coeffs))
    } else {
        (None, None)
    };
    let v_in_q = qv
        .as_ref()
        .is_some_and(|c| c.iter().all(Quadratic::is_zero));
    let has_plane = planes.iter().any(|p| p.rank == 0);
    let mut components: Vec<Component> = Vec::new();
    let mut v_component: Option<usize> = None;
    let mut v_line = if v_in_q && has_plane {
        VLine::InPlane
    } else {
        VLine::Apart
    };
    if v_in_q && !has_plane {
        let v = v.as_ref().expect("two planes");
        let ext = Ext::new(None, None);
        components.push(Component {
            kind: ComponentKind::Line,
            multiplicity: 0,
            real: true,
            param: Some(line_param(&ext.embed_vec(&v[0]), &ext.embed_vec(&v[1]))),
            plane: None,
            section: None,
        });
        v_component = Some(0);
        v_line = VLine::Component(0);
    }
    let other_planes: Vec<Vq> = planes.iter().map(|p| p.l.clone()).collect();
    let on_v = v.as_ref().zip(qv.as_ref());
    for (index, plane) in planes.iter_mut().enumerate() {
        let other = (other_planes.len() == 2).then(|| &other_planes[1 - index]);
        build_plane(plane, other, v_line, on_v, delta.as_ref(), &mut components)?;
    }
    let mut curve = Curve {
        classification,
        components,
        singular_points: Vec::new(),
        pieces: Vec::new(),
        connected: Vec::new(),
    };
    // a plane component is a surface: its meeting points are not curve singularities
    let v = if has_plane { None } else { v.as_ref() };
    meet(
        &mut curve,
        &planes,
        v,
        qv.as_ref(),
        v_in_q,
        v_component,
        has_plane,
    );
    Ok(curve)
}

/// The line `V = l₁ ∩ l₂` when `Q` vanishes on it.
#[derive(Clone, Copy)]
enum VLine {
    /// Not on `Q`, or a double plane.
    Apart,
    /// A component of the curve.
    Component(usize),
    /// Inside a plane component.
    InPlane,
}

fn push(components: &mut Vec<Component>, c: Component) -> usize {
    components.push(c);
    components.len() - 1
}

/// The components of `C = Q|plane`: conic, line pair, double line or the plane itself.
fn build_plane(
    plane: &mut Plane,
    other: Option<&Vq>,
    v_line: VLine,
    on_v: Option<(&[Vq; 2], &[Quadratic; 3])>,
    delta: Option<&IBig>,
    components: &mut Vec<Component>,
) -> Result<(), Error> {
    let m = plane.mult;
    let e_cols = |x: &[Quadratic]| plane.e.mul_vec(x);
    let ext = Ext::new(if plane.real { delta } else { None }, None);
    match plane.rank {
        0 => {
            let c = Component {
                kind: ComponentKind::Plane,
                multiplicity: m,
                real: plane.real,
                param: None,
                plane: plane.real.then(|| to_point(&ext.embed_vec(&plane.l))),
                section: None,
            };
            plane.comps.push(push(components, c));
        }
        1 => {
            match v_line {
                VLine::Component(iv) => {
                    components[iv].multiplicity += 2 * m;
                    plane.comps.push(iv);
                    return Ok(());
                }
                VLine::InPlane => return Ok(()),
                VLine::Apart => {}
            }
            let ker = plane.c.kernel();
            let c = if plane.real {
                let (p0, p1) = (e_cols(&ker[0]), e_cols(&ker[1]));
                Component {
                    kind: ComponentKind::Line,
                    multiplicity: 2 * m,
                    real: true,
                    param: Some(line_param(&ext.embed_vec(&p0), &ext.embed_vec(&p1))),
                    plane: None,
                    section: None,
                }
            } else {
                non_real(ComponentKind::Line, 2 * m)
            };
            plane.comps.push(push(components, c));
        }
        2 => {
            let dg = plane.c.diagonalize_congruent().expect("symmetric");
            let z = (0..3).find(|&i| dg.d[i].is_zero()).expect("rank 2");
            let kernel_local = dg.p.column(z);
            let kernel = e_cols(&kernel_local);
            plane.kernel = Some(kernel.clone());
            if !matches!(v_line, VLine::Apart) {
                // C = V·M: m = (2Cy − m(y)·v)/v(y), m(y) = yᵀCy/v(y), for v(y) ≠ 0
                if let VLine::Component(iv) = v_line {
                    components[iv].multiplicity += m;
                    plane.comps.push(iv);
                }
                let l2 = other.expect("V lies on two planes");
                let vform: Vq = (0..3).map(|j| dot(&plane.e.column(j), l2)).collect();
                let y = (0..3)
                    .map(|i| {
                        let mut y = vec![Quadratic::zero(); 3];
                        y[i] = Quadratic::one();
                        y
                    })
                    .find(|y| !dot(&vform, y).is_zero())
                    .expect("V is a line of the plane");
                let vy = dot(&vform, &y);
                let my = form(&plane.c, &y, &y).div(&vy).expect("v(y) ≠ 0");
                let cy = plane.c.mul_vec(&y);
                let mform: Vq = (0..3)
                    .map(|i| {
                        cy[i]
                            .add(&cy[i])
                            .sub(&my.mul(&vform[i]))
                            .div(&vy)
                            .expect("v(y) ≠ 0")
                    })
                    .collect();
                plane.lines_real = true;
                let c = if plane.real {
                    let mrow = Matrix::from_rows(vec![mform]).expect("one row");
                    let ker = mrow.kernel();
                    let (p0, p1) = (e_cols(&ker[0]), e_cols(&ker[1]));
                    Component {
                        kind: ComponentKind::Line,
                        multiplicity: m,
                        real: true,
                        param: Some(line_param(&ext.embed_vec(&p0), &ext.embed_vec(&p1))),
                        plane: None,
                        section: None,
                    }
                } else {
                    non_real(ComponentKind::Line, m)
                };
                plane.comps.push(push(components, c));
                return Ok(());
            }
            let nz: Vec<usize> = (0..3).filter(|&i| i != z).collect();
            let (ia, ib) = (nz[0], nz[1]);
            let r = dg.d[ib].div(&dg.d[ia]).expect("nonzero").neg();
            let positive = plane.real && r.sign() == Some(Sign::Positive);
            plane.lines_real = positive;
            if !positive {
                for _ in 0..2 {
                    plane
                        .comps
                        .push(push(components, non_real(ComponentKind::Line, m)));
                }
                return Ok(());
            }
            let (pa, pb) = (e_cols(&dg.p.column(ia)), e_cols(&dg.p.column(ib)));
            // lines w_a = ±√r·w_b: through the kernel and ±√r·Pa + Pb
            let (ext, ends): (Ext, [Vec<Number>; 2]) = match sqrt_in_field(&r, delta) {
                Some(s) => {
                    // over ℚ a rational r gets ℚ(√r) here
                    let rad = radicand_of([&s]).or_else(|| delta.cloned());
                    let ext = Ext::new(rad.as_ref(), None);
                    let ends = [s.clone(), s.neg()].map(|s| {
                        let x: Vq = pa.iter().zip(&pb).map(|(a, b)| s.mul(a).add(b)).collect();
                        ext.embed_vec(&x)
                    });
                    (ext, ends)
                }
                None => {
                    let ext = Ext::new(delta, Some(&r));
                    let neg: Vq = pa.iter().map(Quadratic::neg).collect();
                    let ends = [ext.with_root(&pb, &pa), ext.with_root(&pb, &neg)];
                    (ext, ends)
                }
            };
            let k = ext.embed_vec(&kernel);
            for end in ends {
                let c = Component {
                    kind: ComponentKind::Line,
                    multiplicity: m,
                    real: true,
                    param: Some(line_param(&k, &end)),
                    plane: None,
                    section: None,
                };
                plane.comps.push(push(components, c));
            }
        }
        _ => {
            let given = on_v.and_then(|(v, qv)| point_on_v(v, qv));
            let c = conic_component(plane, given, delta)?;
            plane.comps.push(push(components, c));
        }
    }
    Ok(())
}

/// A real point of `Q` on `V = l₁ ∩ l₂`, where the conics of the two planes meet: the roots of
/// the rational binary form `Q|V = a s² + 2b st + c t²` (`qv = [a, b, c]`).
enum PointOnV {
    /// A rational point (`D = b² − ac` a square, a double root included).
    Rational(Vq),
    /// `y₀ + √D·y₁`, `D > 0` not a rational square.
    Root(Vq, Vq, RBig),
}

/// The meeting points on `V` as a point the geometry gives for free: no conic solving, no
/// factoring. `None` when they are complex.
fn point_on_v(v: &[Vq; 2], qv: &[Quadratic; 3]) -> Option<PointOnV> {
    let [a, b, c] = [0, 1, 2].map(|i| qv[i].as_rational().cloned());
    let (a, b, c) = (a?, b?, c?);
    let combine = |s: &RBig, t: &RBig| -> Vq {
        v[0].iter()
            .zip(&v[1])
            .map(|(x, y)| x.scale(s).add(&y.scale(t)))
            .collect()
    };
    if a == RBig::ZERO {
        return Some(PointOnV::Rational(v[0].clone()));
    }
    let d = &b * &b - &a * &c;
    if d < RBig::ZERO {
        return None;
    }
    let root = sqrt_rational(&d);
    match root.as_rational() {
        Some(k) => Some(PointOnV::Rational(combine(&(k - &b), &a))),
        None => Some(PointOnV::Root(combine(&-b, &a), v[0].clone(), d)),
    }
}

/// A real point `y₀ + √r·y₁` of a conic in local coordinates, and the radicand of its
/// coordinates' field (`r = None`: `y = y₀`).
type ConicPointFound = (Vq, Vq, Option<Quadratic>, Option<IBig>);

/// The conic `Q|plane` (rank 3): real with a parameterization through a real point, or not.
/// The point is the first of: a rational point on `V` (`given`), a rational point by
/// Legendre (rational planes) or one over the planes' field (congruence diagonalization), a
/// point of `V` over a rational `√D`, a point over `√r` from the diagonalization.
fn conic_component(
    plane: &Plane,
    given: Option<PointOnV>,
    delta: Option<&IBig>,
) -> Result<Component, Error> {
    let m = plane.mult;
    if !plane.real {
        return Ok(non_real(ComponentKind::Conic, m));
    }
    let local = |x: &Vq| plane.e.solve(x).expect("V lies in the plane");
    // the point of V over ℚ(√D), or over the planes' field when √D lies there
    let v_root = |y0: &Vq, y1: &Vq, d: &RBig| -> ConicPointFound {
        let (y0, y1) = (local(y0), local(y1));
        let dq = qr(d);
        match sqrt_in_field(&dq, delta) {
            Some(s) => {
                let y: Vq = y0.iter().zip(&y1).map(|(a, b)| a.add(&s.mul(b))).collect();
                let rad = radicand_of(y.iter()).or_else(|| delta.cloned());
                (y, vec![], None, rad)
            }
            None => (y0, y1, Some(dq), delta.cloned()),
        }
    };
    let (y0, y1, r, rad): ConicPointFound = match (&given, delta) {
        (Some(PointOnV::Rational(p)), _) => (local(p), vec![], None, delta.cloned()),
        (_, None) => {
            let c: [[RBig; 3]; 3] = std::array::from_fn(|i| {
                std::array::from_fn(|j| plane.c[(i, j)].as_rational().expect("rational").clone())
            });
            match (find_point(&c), &given) {
                (Ok(ConicPoint::Rational(p)), _) => {
                    (p.iter().map(qr).collect(), vec![], None, None)
                }
                (Ok(ConicPoint::NoRealPoint), _) => return Ok(non_real(ComponentKind::Conic, m)),
                (_, Some(PointOnV::Root(y0, y1, d))) => v_root(y0, y1, d),
                (Ok(ConicPoint::NoRationalPoint(qp) | ConicPoint::Undecided(qp)), _) => {
                    (qp.coords.to_vec(), vec![], None, Some(qp.delta.clone()))
                }
                (Err(e), _) => return Err(Error::Algebra(format!("a conic's point: {e}"))),
            }
        }
        (_, Some(_)) => {
            let dg = plane.c.diagonalize_congruent().expect("symmetric");
            let sign = |x: &Quadratic| x.sign().expect("a real field");
            let mut found: Option<(Vq, Vq, Option<Quadratic>)> = None;
            for i in 0..3 {
                for j in 0..3 {
                    if sign(&dg.d[i]) != Sign::Positive || sign(&dg.d[j]) != Sign::Negative {
                        continue;
                    }
                    let r = dg.d[i].div(&dg.d[j]).expect("nonzero").neg();
                    let (pi, pj) = (dg.p.column(i), dg.p.column(j));
                    match sqrt_in_field(&r, delta) {
                        Some(s) => {
                            let y: Vq = pi.iter().zip(&pj).map(|(a, b)| a.add(&s.mul(b))).collect();
                            found = Some((y, vec![], None));
                        }
                        None if found.is_none() => found = Some((pi, pj, Some(r))),
                        None => {}
                    }
                }
            }
            // no ratio a square in K: a small point of K, before a root is adjoined
            if let (Some((_, _, Some(_))), Some(delta)) = (&found, delta) {
                if let Some(y) = point::small_point_in_field(&dg, delta) {
                    found = Some((y, vec![], None));
                }
            }
            match (found, &given) {
                (None, _) => return Ok(non_real(ComponentKind::Conic, m)),
                (Some((y, _, None)), _) => (y, vec![], None, delta.cloned()),
                (Some(_), Some(PointOnV::Root(y0, y1, d))) => v_root(y0, y1, d),
                (Some((y0, y1, r)), _) => (y0, y1, r, delta.cloned()),
            }
        }
    };
    let ext = Ext::new(rad.as_ref().or(delta), r.as_ref());
    let y = if r.is_some() {
        ext.with_root(&y0, &y1)
    } else {
        ext.embed_vec(&y0)
    };
    let e: Vec<Vec<Number>> = (0..4)
        .map(|i| (0..3).map(|j| ext.embed(&plane.e[(i, j)])).collect())
        .collect();
    let c: Vec<Vec<Number>> = (0..3)
        .map(|i| (0..3).map(|j| ext.embed(&plane.c[(i, j)])).collect())
        .collect();
    Ok(Component {
        kind: ComponentKind::Conic,
        multiplicity: m,
        real: true,
        param: Some(conic_param(&e, &c, &y)),
        plane: Some(to_point(&ext.embed_vec(&plane.l))),
        section: Some(plane_section(plane, delta)),
    })
}

/// The conic of `plane` as its section over the plane's own field (ℚ, or ℚ(√δ)).
fn plane_section(plane: &Plane, delta: Option<&IBig>) -> PlaneSection {
    let field = delta.map(curve::sqrt_field);
    let own = |q: &Quadratic| curve::from_quadratic(q, field.as_ref());
    PlaneSection {
        basis: std::array::from_fn(|i| std::array::from_fn(|j| own(&plane.e[(i, j)]))),
        conic: std::array::from_fn(|i| std::array::from_fn(|j| own(&plane.c[(i, j)]))),
    }
}

/// A real point where components meet: which planes' components pass and how.
struct Meeting {
    point: Vq,
    /// On `V`, at a double root of `Q|V`.
    tangent: bool,
    /// On `V` (on both planes).
    on_v: bool,
    /// Over the planes' field (else over the field of the roots of `Q|V`, and no kernel).
    in_planes_field: bool,
}

/// Singular points, real pieces and their connection (module docs).
fn meet(
    curve: &mut Curve,
    planes: &[Plane],
    v: Option<&[Vq; 2]>,
    qv: Option<&[Quadratic; 3]>,
    v_in_q: bool,
    v_component: Option<usize>,
    has_plane: bool,
) {
    let mut points: Vec<Meeting> = Vec::new();
    let add = |points: &mut Vec<Meeting>, m: Meeting| {
        let seen =
            |o: &Meeting| o.in_planes_field == m.in_planes_field && same_point(&o.point, &m.point);
        match points.iter_mut().find(|o| seen(o)) {
            Some(o) => o.on_v |= m.on_v,
            None => points.push(m),
        }
    };
    let at = |point: Vq, tangent: bool, on_v: bool, in_planes_field: bool| Meeting {
        point,
        tangent,
        on_v,
        in_planes_field,
    };
    for plane in planes.iter().filter(|_| !has_plane) {
        if let Some(k) = &plane.kernel {
            add(&mut points, at(k.clone(), false, false, true));
        }
    }
    if let (Some(v), Some(qv), false) = (v, qv, v_in_q) {
        let [a, b, c] = qv;
        // a kernel on V fixes one root (s₁ : t₁) of a·s² + 2b·st + c·t² in the planes' field
        let on_v = planes.iter().enumerate().find_map(|(i, p)| {
            let k = p.kernel.as_ref()?;
            dot(k, &planes[1 - i].l).is_zero().then_some(k.clone())
        });
        match on_v {
            Some(k) => {
                let (s1, t1) = coordinates_on(&k, v);
                let (s2, t2) = if t1.is_zero() {
                    (c.clone(), b.add(b).neg())
                } else if s1.is_zero() {
                    (b.add(b), a.neg())
                } else {
                    (
                        c.div(&s1).expect("s₁ ≠ 0").neg(),
                        a.div(&t1).expect("t₁ ≠ 0").neg(),
                    )
                };
                let x: Vq = (0..4)
                    .map(|i| s2.mul(&v[0][i]).add(&t2.mul(&v[1][i])))
                    .collect();
                add(&mut points, at(k, false, true, true));
                add(&mut points, at(x, false, true, true));
            }
            None => {
                let (a, b, c) = (
                    a.as_rational().expect("rational").clone(),
                    b.as_rational().expect("rational").clone(),
                    c.as_rational().expect("rational").clone(),
                );
                let disc = &b * &b - &a * &c;
                if disc >= RBig::ZERO {
                    let root = sqrt_rational(&disc);
                    let tangent = disc.is_zero();
                    let mut pts: Vec<(Quadratic, Quadratic)> = Vec::new();
                    if a.is_zero() {
                        pts.push((Quadratic::one(), Quadratic::zero()));
                        pts.push((qr(&c), qr(&(RBig::from(-2) * &b))));
                    } else {
                        for r in [root.clone(), root.neg()] {
                            pts.push((r.sub(&qr(&b)), qr(&a)));
                        }
                    }
                    for (s, t) in pts {
                        let x: Vq = (0..4)
                            .map(|i| s.mul(&v[0][i]).add(&t.mul(&v[1][i])))
                            .collect();
                        if x.iter().any(|c| !c.is_zero()) {
                            add(&mut points, at(x, tangent, true, false));
                        }
                    }
                }
            }
        }
    }
    // union–find over components
    let n = curve.components.len();
    let mut parent: Vec<usize> = (0..n).collect();
    fn find(parent: &mut [usize], i: usize) -> usize {
        let mut r = i;
        while parent[r] != r {
            r = parent[r];
        }
        parent[i] = r;
        r
    }
    let union = |parent: &mut Vec<usize>, i: usize, j: usize| {
        let (ri, rj) = (find(parent, i), find(parent, j));
        parent[ri] = rj;
    };
    let real = |i: usize| curve.components[i].real;
    for plane in planes {
        let reals: Vec<usize> = plane.comps.iter().copied().filter(|&i| real(i)).collect();
        for w in reals.windows(2) {
            union(&mut parent, w[0], w[1]);
        }
    }
    let mut isolated: Vec<(usize, Vq)> = Vec::new();
    for m in &points {
        let Some(x) = real_normalized(&m.point) else {
            continue;
        };
        let (mut branches, mut real_branches, mut multiple) = (0u32, 0u32, false);
        let (mut through, mut any): (Vec<usize>, Vec<usize>) = (Vec::new(), Vec::new());
        for plane in planes {
            if !m.on_v && !dot(&m.point, &plane.l).is_zero() {
                continue;
            }
            let pm = plane.mult;
            let at_kernel = m.in_planes_field
                && plane
                    .kernel
                    .as_ref()
                    .is_some_and(|k| same_point(k, &m.point));
            let (b, rb) = match plane.rank {
                1 => (2 * pm, if plane.real || v_in_q { 2 * pm } else { 0 }),
                2 if at_kernel => (2 * pm, if plane.lines_real { 2 * pm } else { 0 }),
                _ => (pm, if plane.real || v_in_q { pm } else { 0 }),
            };
            multiple |= pm >= 2 || plane.rank == 1;
            branches += b;
            real_branches += rb;
            any.extend(plane.comps.iter().copied());
            through.extend(plane.comps.iter().copied().filter(|&i| real(i)));
        }
        if v_in_q && v_component.is_some_and(|iv| curve.components[iv].multiplicity >= 2) {
            multiple = true;
        }
        if branches < 2 {
            continue;
        }
        let kind = if multiple || branches >= 3 {
            SingularPointKind::Multiple
        } else if m.tangent {
            SingularPointKind::Tangency
        } else if real_branches == 0 {
            SingularPointKind::Acnode
        } else {
            SingularPointKind::Crunode
        };
        for w in through.windows(2) {
            union(&mut parent, w[0], w[1]);
        }
        if real_branches == 0 {
            isolated.push((any.first().copied().unwrap_or(0), x.clone()));
        }
        let rad = radicand_of(x.iter());
        let ext = Ext::new(rad.as_ref(), None);
        curve.singular_points.push(SingularPoint {
            kind,
            point: to_point(&ext.embed_vec(&x)),
        });
    }
    // pieces: a real conic or line is one closed curve; isolated real points
    let mut piece_of = vec![usize::MAX; n];
    for (i, comp) in curve.components.iter().enumerate() {
        if comp.real && comp.param.is_some() {
            piece_of[i] = curve.pieces.len();
            curve.pieces.push(RealPiece::whole(i));
        }
    }
    let mut groups: Vec<(usize, Vec<usize>)> = Vec::new();
    for i in 0..n {
        if piece_of[i] == usize::MAX {
            continue;
        }
        let r = find(&mut parent, i);
        match groups.iter_mut().find(|g| g.0 == r) {
            Some(g) => g.1.push(piece_of[i]),
            None => groups.push((r, vec![piece_of[i]])),
        }
    }
    curve.connected = groups.into_iter().map(|g| g.1).collect();
    for (component, x) in isolated {
        let rad = radicand_of(x.iter());
        let ext = Ext::new(rad.as_ref(), None);
        curve.connected.push(vec![curve.pieces.len()]);
        curve.pieces.push(RealPiece::Point {
            component,
            point: to_point(&ext.embed_vec(&x)),
        });
    }
}

/// `(s, t)` with `x = s·v₀ + t·v₁` for a point `x` of the line spanned by `v`.
fn coordinates_on(x: &[Quadratic], v: &[Vq; 2]) -> (Quadratic, Quadratic) {
    for i in 0..4 {
        for j in i + 1..4 {
            let det = v[0][i].mul(&v[1][j]).sub(&v[0][j].mul(&v[1][i]));
            if let Some(inv) = det.inv() {
                let s = x[i].mul(&v[1][j]).sub(&x[j].mul(&v[1][i])).mul(&inv);
                let t = v[0][i].mul(&x[j]).sub(&v[0][j].mul(&x[i])).mul(&inv);
                return (s, t);
            }
        }
    }
    unreachable!("v₀, v₁ span a line")
}

#[cfg(test)]
mod tests;
