//! Singular pencils: `det(λA − μB) ≡ 0` with `A`, `B` not proportional.
//!
//! None of our papers treats this case (the signature-sequence paper wrongly says it
//! means a common singular point, ERRATA item 5), so the method is derived here from the
//! Kronecker canonical form of singular symmetric pencils. QI's `inter_vanish_det`
//! follows the same decision tree; it was read to cross-check the case analysis, and the
//! 31 singular pairs of its test file are our labelled examples.
//!
//! # Structure: the Kronecker form of a singular symmetric pencil
//!
//! A pencil of complex symmetric matrices is congruent (`λA − μB ↦ Pᵀ(λA − μB)P`, `P`
//! constant and invertible) to a direct sum of a regular part (Jordan-type blocks) and
//! singular blocks, one for each minimal index `ε`: a singular block has size `2ε + 1`; for
//! `ε = 0` it is a 1×1 zero block (a common kernel vector of `A` and `B`), for `ε = 1`
//! the 3×3 block of the form `2y(λx − μz)`. In size 4 a block with `ε ≥ 2` (size ≥ 5)
//! cannot occur, so with `k = dim(ker A ∩ ker B)`:
//!
//! * `k = 0`: one `ε = 1` block and a 1×1 regular block:
//!   `λA − μB ≅ 2y(λx − μz) + c(λ, μ)w²` with `c` a nonzero linear form. Its root is the
//!   only point of the pencil where the rank drops to 2, so it is rational.
//! * `k = 1`: one `ε = 0` block and a 3×3 pencil, itself either one `ε = 1` block or regular.
//! * `k = 2`: two `ε = 0` blocks and a regular 2×2 pencil (a singular 2×2 symmetric pencil
//!   needs an `ε = 0` block, i.e. a third common kernel vector).
//! * `k ≥ 3`: `A` and `B` are multiples of the same `ℓ²`: proportional, excluded.
//!
//! # Projection from the common singular points (`k ≥ 1`)
//!
//! The common kernel is the kernel of the rational 8×4 matrix `[A; B]`, so it is rational
//! (a common singular point is never irrational, although the kernel of a single member at
//! an irrational `λ` may be). Exact fraction-free elimination on `[A; B]` gives its pivot
//! columns `I` (`|I| = 4 − k`); the kernel has a basis `v_j = e_j − Σ_{i∈I} c_ij e_i`
//! (`j ∉ I`), and in the basis `{e_i : i ∈ I} ∪ {v_j}` both matrices become
//! `diag(M[I, I], 0)`. So the projected pencil is the pencil of *principal submatrices*
//! `(A[I, I], B[I, I])`: no arithmetic at all. Every quadric of the pencil is a cone over
//! the projected form with the common singular space as vertex, so the intersection is
//! the cone over the intersection of the projected forms: a point of P² is a line through
//! the vertex `p` in P³, a line of P² a plane through `p`; multiplicities are kept.
//!
//! # The case table, with proof sketches
//!
//! | `k` | projected pencil | complex type | real type |
//! |---|---|---|---|
//! | 0 | — (`L₁ ⊕ J₁`) | conic_and_double_line | same |
//! | 1 | conics, `det₃ ≡ 0` | line_and_plane | same |
//! | 1 | conics `[111]` | four_concurrent_lines | point / two_concurrent_lines / same |
//! | 1 | conics `[21]` | two_concurrent_lines_and_double_line | double_line / same |
//! | 1 | conics `[(11)1]` | two_concurrent_double_lines | point / same |
//! | 1 | conics `[3]` | line_and_triple_line | same |
//! | 1 | conics `[(21)]` | quadruple_line | same |
//! | 2 | binary forms, two distinct roots (real or not) | quadruple_line_of_plane_pairs | same |
//! | 2 | binary forms, a double root | plane | same |
//!
//! **`k = 0`.** Take the member `Q₀` where `c = 0`: `Q₀ = 2y(ax − bz)`, a pair of planes,
//! and any other member `Q₁ = 2y(a'x − b'z) + w²` (up to a factor). On the plane `y = 0`,
//! `Q₁` is `w²`: the line `y = w = 0` counted twice. On the plane `ax = bz`, `Q₁` is
//! `2y·l + w²` with `l` independent of `y, w`: a conic of rank 3. The conic meets the
//! double line at the one point `y = w = 0, ax = bz`. Over ℝ: the double line, the conic
//! and their meeting point are each unique, hence invariant under conjugation, hence real;
//! a nondegenerate real conic with a real point is a real curve. Example (ERRATA 5):
//! `2xy + w², 2yz + w²` give `y(x − z) = 0`, the double line `y = w = 0` and the conic
//! `x = z, 2xy + w² = 0`.
//!
//! **`k = 1`, singular conic pencil.** It is a single `ε = 1` block, `2y(λx − μz)`: all
//! conics contain the line `y = 0`, and otherwise meet only at `x = z = 0`. In P³: a
//! plane and a line through the vertex. The fixed line is unique, hence rational.
//!
//! **`k = 1`, regular conic pencil.** The Segre characteristic of a pencil of conics
//! determines its base scheme (classical): `[111]` four points in general position,
//! `[21]` a double point (two conics tangent) and two simple points, `[(11)1]` two double
//! points (the pencil contains a double line `ℓ²`), `[3]` a triple point and a simple one,
//! `[(21)]` one quadruple point (`ℓ²` in the pencil, tangent to the conics), `[(111)]`
//! impossible (`A ∝ B`). It is read from the binary cubic `det₃`: the chart is chosen so
//! that ∞ is not a root (`A* = A₃ + tB₃` with `det A* ≠ 0`, `t` a small integer), the
//! discriminant of `f(λ) = det(λA* − B₃)` and closed forms give the multiplicities and the
//! multiple root (it is rational; see `conic_pencil`), and the rank of the member at a
//! multiple root gives the number of blocks. For a real symmetric matrix the rank is the
//! largest `k` with `E_k ≠ 0`, `E_k` the sum of its principal `k`-minors; at a root of `f`
//! the member has `E₃ = 0`, and if it has rank 2, `sign E₂` is the product of the signs
//! of its two nonzero eigenvalues: negative for two real lines, positive for two
//! conjugate lines.
//!
//! Real types. The degenerate members of a pencil of conics are the line pairs through
//! the base points.
//! * `[111]`, base points `P₁…P₄`. Four real points: the three line pairs are real pairs
//!   of real lines (`E₂ < 0` at three real roots). Two real `P₁, P₂` and a conjugate pair
//!   `Q, Q̄`: only `{P₁P₂, QQ̄}` is real (`{P₁Q, P₂Q̄}` and `{P₁Q̄, P₂Q}` are swapped by
//!   conjugation): one real root. No real point, `Q₁, Q̄₁, Q₂, Q̄₂`: `{Q₁Q̄₁, Q₂Q̄₂}` is a pair
//!   of real lines (`E₂ < 0`), `{Q₁Q₂, Q̄₁Q̄₂}` and `{Q₁Q̄₂, Q̄₁Q₂}` are pairs of conjugate lines
//!   (`E₂ > 0`): three real roots. So one real root of `f` means two real lines; three real
//!   roots mean four real lines if `E₂ < 0` at all of them, else only the vertex is real.
//!   This is decided without algebraic numbers by the Tarski query
//!   `TaQ(E₂, f) = Σ_{f(α)=0} sign E₂(α)` (a Sturm–Tarski sequence of integer polynomials):
//!   `−3` for four real lines, `+1` for a point.
//! * `[21]`, double point `P`, simple points `Q₁, Q₂`: the member at the double root is
//!   `PQ₁ ∪ PQ₂` (check on `xy, y² + z²`), the one at the simple root is the tangent at `P`
//!   with `Q₁Q₂`. `E₂ < 0` at the double root: `Q₁, Q₂` real, all four lines real;
//!   `E₂ > 0`: conjugate, only the double line is real.
//! * `[(11)1]`, double points `R₁, R₂` on `ℓ`: the member at the simple root is the pair of
//!   tangents to the conics at `R₁, R₂` (check on `z², x² + y²`), real iff `R₁, R₂` are
//!   real. `E₂ < 0` there: two real double lines; `E₂ > 0`: only the vertex is real.
//! * `[3]`, `[(21)]`: the multiple base point is unique, hence real, and so is the simple
//!   one of `[3]`.
//!
//! **`k = 2`.** The quadrics are pairs of planes through the common singular line `L`,
//! given by the binary forms `A₂, B₂`; `det₂(λ, μ) = det(λA₂ − μB₂)` is a binary quadratic,
//! not identically zero. At a double root the member is singular of rank 1 (rank 0 would
//! mean `A ∝ B`): `ℓ²` is in the pencil; in a basis where it is `x²` another member is
//! `ax² + 2bxy + cy²`, and `det(λx² − μ(ax² + 2bxy + cy²)) = −μ·(c(λ − aμ) + b²μ)` has a
//! double root iff `c = 0` (`b = c = 0` is `A ∝ B`), i.e. iff `x` divides every member.
//! So a double root (discriminant zero) means the common plane `ℓ = 0` (with `L`
//! embedded): type `plane`. Two distinct roots (real or not) mean no common factor: the
//! intersection is `L` counted four times and every member is a pair of planes through
//! it, `quadruple_line_of_plane_pairs`.
//!
//! Everything is exact arithmetic in an ordered domain ([`OrderedDomain`]): an 8×4
//! fraction-free elimination, principal minors, one binary cubic (closed forms:
//! discriminant, multiple roots in the domain's fraction field) or quadratic, and at most one
//! Sturm–Tarski sequence. Rational pencils run it over ℤ (the primitive integer matrices); a
//! moving pencil at an irrational instant `α` over ℚ(α) (`motion::irrational`).

use crate::vocabulary::{
    ComplexType, Component, ComponentKind, Description, Morphology, RealType, SingularPointKind,
    SingularPoints,
};
use qsic_algebra::linalg::minors::{det, principal_minor_sums};
use qsic_algebra::linalg::pencil::pencil_principal_minor_sums;
use qsic_algebra::linalg::Matrix;
use qsic_algebra::matrix::SymMatrix4;
use qsic_algebra::poly::sturm::tarski_query;
use qsic_algebra::{IBig, Poly, Ring, Sign};

/// An ordered integral domain the singular classifier computes in: ℤ for rational pencils
/// (fraction-free, every entry an integer of the primitive matrices) and ℚ(α) for a moving
/// pencil at an irrational instant. Every decision below is a ring operation, an exact sign
/// or a Sturm–Tarski query, so one implementation serves both.
pub(crate) trait OrderedDomain: Ring {
    /// The sign, decided exactly.
    fn sign_of(&self) -> Sign;
    /// `Σ sign q(x)` over the distinct real roots `x` of the square-free `p` (positive degree).
    fn tarski_query(p: &Poly<Self>, q: &Poly<Self>) -> i64;
}

impl OrderedDomain for IBig {
    fn sign_of(&self) -> Sign {
        Sign::of(self)
    }
    fn tarski_query(p: &Poly, q: &Poly) -> i64 {
        tarski_query(p, q)
    }
}

/// Classifies a singular pencil, exactly.
///
/// Precondition, decided by the caller (`pencil_kind`): `det(λA − μB) ≡ 0` and `A`, `B`
/// not proportional. It is not checked again: every branch below relies on it, and
/// `None` (no type) would mean it failed.
pub(crate) fn classify_singular(
    a: &SymMatrix4,
    b: &SymMatrix4,
) -> Option<(Morphology, Description)> {
    classify_singular_in(a.entries(), b.entries())
}

/// [`classify_singular`] over any [`OrderedDomain`] (same precondition).
pub(crate) fn classify_singular_in<C: OrderedDomain>(
    a: &[[C; 4]; 4],
    b: &[[C; 4]; 4],
) -> Option<(Morphology, Description)> {
    let morphology = singular_morphology(a, b)?;
    Some((morphology, describe(morphology)))
}

/// The complex and real type of a singular pencil (see the module docs for the table).
fn singular_morphology<C: OrderedDomain>(a: &[[C; 4]; 4], b: &[[C; 4]; 4]) -> Option<Morphology> {
    use ComplexType as C3;
    let pivots = pivot_columns(a, b);
    match pivots.len() {
        // k = 0: no common singular point, the Kronecker block L₁ with a 1×1 regular block.
        4 => Some(Morphology {
            complex: C3::ConicAndDoubleLine,
            real: RealType::Same,
        }),
        // k = 1: a pencil of conics.
        3 => {
            let i = [pivots[0], pivots[1], pivots[2]];
            conic_pencil(&sub(a, i), &sub(b, i))
        }
        // k = 2: a pencil of binary forms (pairs of planes through the common line).
        2 => {
            let i = [pivots[0], pivots[1]];
            Some(binary_pencil(&sub(a, i), &sub(b, i)))
        }
        // k ≥ 3 means A ∝ B, excluded by the precondition.
        _ => None,
    }
}

/// The principal submatrix of `m` on the indices `i`.
fn sub<C: Ring, const N: usize>(m: &[[C; 4]; 4], i: [usize; N]) -> [[C; N]; N] {
    i.map(|r| i.map(|c| m[r][c].clone()))
}

/// The pivot columns of the stacked 8×4 matrix `[A; B]` (fraction-free elimination,
/// [`Matrix::pivot_columns`]): `4 −` their number is the dimension of the common kernel, and
/// the principal submatrices on them are the projected pencil (module docs).
fn pivot_columns<C: Ring>(a: &[[C; 4]; 4], b: &[[C; 4]; 4]) -> Vec<usize> {
    let rows: Vec<Vec<C>> = a.iter().chain(b.iter()).map(|r| r.to_vec()).collect();
    Matrix::from_rows(rows)
        .expect("rows of length 4")
        .pivot_columns()
}

/// The rank of a real symmetric 3×3 matrix: the largest `k` with `E_k ≠ 0` (the
/// characteristic polynomial is `x^(3−r)` times the product over the `r` nonzero eigenvalues).
fn rank3<C: Ring>(e: &[C; 3]) -> u8 {
    (0..3)
        .rev()
        .find(|&k| !e[k].is_zero())
        .map_or(0, |k| k as u8 + 1)
}

/// `p·A − q·B` for 3×3 matrices.
fn combine3<C: Ring>(a: &[[C; 3]; 3], p: &C, b: &[[C; 3]; 3], q: &C) -> [[C; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| p.mul(&a[i][j]).sub(&q.mul(&b[i][j]))))
}

/// `[E₁(λ), E₂(λ), E₃(λ)]` of `λA − B` (`E₃` is `det(λA − B)`).
fn pencil_minor_sums3<C: Ring>(a: &[[C; 3]; 3], b: &[[C; 3]; 3]) -> [Poly<C>; 3] {
    pencil_principal_minor_sums(a, b).map(|c| Poly::new(c.to_vec()))
}

/// The integer `v` in `C`.
fn int<C: Ring>(v: i64) -> C {
    C::from_int(&IBig::from(v))
}

/// The regular or singular pencil of conics `(A₃, B₃)` obtained by projecting from the
/// single common singular point (`k = 1`).
///
/// The binary cubic is analysed in closed form on a chart where ∞ is not a root:
/// `f(λ) = c₃λ³ + c₂λ² + c₁λ + c₀`, `c₃ ≠ 0`, with discriminant
/// `Δ = 18c₃c₂c₁c₀ − 4c₂³c₀ + c₂²c₁² − 4c₃c₁³ − 27c₃²c₀²`: `Δ > 0` three real simple roots,
/// `Δ < 0` one real and two conjugate, `Δ = 0` a multiple root. With `h = c₂² − 3c₃c₁`,
/// a triple root (`h = 0`) is `−c₂/(3c₃)`; otherwise the double root is
/// `α = (9c₃c₀ − c₂c₁)/(2h)` and the simple one `β = −c₂/c₃ − 2α` (for
/// `f = c₃(λ − α)²(λ − β)`: `h = c₃²(α − β)²`, `9c₃c₀ − c₂c₁ = 2c₃²α(α − β)²`).
fn conic_pencil<C: OrderedDomain>(a3: &[[C; 3]; 3], b3: &[[C; 3]; 3]) -> Option<Morphology> {
    use ComplexType as C3;
    use RealType as R;
    let [_, e2, f] = pencil_minor_sums3(a3, b3);
    if f.is_zero() {
        // a single ε = 1 block: a common line and a moving one
        return Some(Morphology {
            complex: C3::LineAndPlane,
            real: R::Same,
        });
    }
    // A chart without a root at ∞: A* = A₃ + t·B₃ with det A* ≠ 0 (det₃ has at most
    // three roots, so one of t = 0, 1, −1, 2 works).
    let (a_star, f, e2) = if f.degree() == Some(3) {
        (a3.clone(), f, e2)
    } else {
        let a_star = [1i64, -1, 2]
            .iter()
            .map(|&t| combine3(a3, &C::one(), b3, &int(-t)))
            .find(|m| !det(m).is_zero())?;
        let [_, e2, f] = pencil_minor_sums3(&a_star, b3);
        (a_star, f, e2)
    };
    let [c0, c1, c2, c3] = [0, 1, 2, 3].map(|i| f.coeff(i));
    let disc = int::<C>(18)
        .mul(&c3)
        .mul(&c2)
        .mul(&c1)
        .mul(&c0)
        .sub(&int::<C>(4).mul(&c2.pow(3)).mul(&c0))
        .add(&c2.pow(2).mul(&c1.pow(2)))
        .sub(&int::<C>(4).mul(&c3).mul(&c1.pow(3)))
        .sub(&int::<C>(27).mul(&c3.pow(2)).mul(&c0.pow(2)));
    // [E₁, E₂, E₃] of the member p·A* − q·B₃ at the root λ = p/q
    let member = |p: &C, q: &C| principal_minor_sums(&combine3(&a_star, p, b3, q));
    let (complex, real) = match disc.sign_of() {
        // [111], four base points: two real (one real root) …
        Sign::Negative => (C3::FourConcurrentLines, R::TwoConcurrentLines),
        // … four or none (three real roots)
        Sign::Positive => {
            let real = if C::tarski_query(&f, &e2) == -3 {
                R::Same
            } else {
                R::Point
            };
            (C3::FourConcurrentLines, real)
        }
        Sign::Zero => {
            let h = c2.pow(2).sub(&int::<C>(3).mul(&c3).mul(&c1));
            if h.is_zero() {
                // a triple root: [3] (rank 2) or [(21)] (rank 1)
                match rank3(&member(&c2.neg(), &int::<C>(3).mul(&c3))) {
                    2 => (C3::LineAndTripleLine, R::Same),
                    1 => (C3::QuadrupleLine, R::Same),
                    _ => return None, // rank 0 would mean A ∝ B
                }
            } else {
                // a double root α = n/d: [21] (rank 2) or [(11)1] (rank 1)
                let n = int::<C>(9).mul(&c3).mul(&c0).sub(&c2.mul(&c1));
                let d = int::<C>(2).mul(&h);
                let e = member(&n, &d);
                match rank3(&e) {
                    2 => {
                        // PQ₁ ∪ PQ₂: real lines iff the simple base points are real
                        let real = if e[1].sign_of() == Sign::Negative {
                            R::Same
                        } else {
                            R::DoubleLine
                        };
                        (C3::TwoConcurrentLinesAndDoubleLine, real)
                    }
                    1 => {
                        // the member at the simple root β = −c₂/c₃ − 2n/d: the two
                        // tangents at the double points
                        let p = c2.neg().mul(&d).sub(&int::<C>(2).mul(&n).mul(&c3));
                        let e = member(&p, &c3.mul(&d));
                        let real = if e[1].sign_of() == Sign::Negative {
                            R::Same
                        } else {
                            R::Point
                        };
                        (C3::TwoConcurrentDoubleLines, real)
                    }
                    _ => return None, // rank 0 would mean A ∝ B
                }
            }
        }
    };
    Some(Morphology { complex, real })
}

/// The pencil of binary forms `(A₂, B₂)` obtained by projecting from the common singular
/// line (`k = 2`); they are not proportional, since `A` and `B` are not.
fn binary_pencil<C: Ring>(a: &[[C; 2]; 2], b: &[[C; 2]; 2]) -> Morphology {
    use ComplexType as C3;
    // det(λA − μB) = λ²·det A − λμ·s + μ²·det B
    let det_a = a[0][0].mul(&a[1][1]).sub(&a[0][1].mul(&a[0][1]));
    let det_b = b[0][0].mul(&b[1][1]).sub(&b[0][1].mul(&b[0][1]));
    let s = a[0][0]
        .mul(&b[1][1])
        .add(&a[1][1].mul(&b[0][0]))
        .sub(&int::<C>(2).mul(&a[0][1]).mul(&b[0][1]));
    let discriminant = s.mul(&s).sub(&int::<C>(4).mul(&det_a).mul(&det_b));
    let complex = if discriminant.is_zero() {
        C3::Plane
    } else {
        C3::QuadrupleLineOfPlanePairs
    };
    Morphology {
        complex,
        real: RealType::Same,
    }
}

/// The description of each singular type: real components, how they meet, a summary.
pub(super) fn describe(m: Morphology) -> Description {
    use ComplexType as C;
    use ComponentKind as K;
    use RealType as R;
    use SingularPointKind as S;
    const OPEN: Option<bool> = Some(false);
    const CLOSED: Option<bool> = Some(true);
    let comp = |kind, multiplicity, count, closed| Component {
        kind,
        multiplicity,
        count,
        closed,
    };
    let multiple = vec![SingularPoints {
        kind: S::Multiple,
        count: 1,
    }];
    let (components, singular_points, summary) = match (m.complex, m.real) {
        (C::ConicAndDoubleLine, _) => (
            vec![comp(K::Conic, 1, 1, CLOSED), comp(K::Line, 2, 1, OPEN)],
            multiple,
            "a real conic and a real double line meeting it at one real point",
        ),
        (C::FourConcurrentLines, R::Point) => (
            vec![comp(K::Point, 1, 1, CLOSED)],
            multiple,
            "two pairs of conjugate lines through one real point, the only real point",
        ),
        (C::FourConcurrentLines, R::TwoConcurrentLines) => (
            vec![comp(K::Line, 1, 2, OPEN)],
            multiple,
            "two real lines and two conjugate lines, all through one real point",
        ),
        (C::FourConcurrentLines, _) => (
            vec![comp(K::Line, 1, 4, OPEN)],
            multiple,
            "four real lines through one real point",
        ),
        (C::TwoConcurrentLinesAndDoubleLine, R::DoubleLine) => (
            vec![comp(K::Line, 2, 1, OPEN)],
            multiple,
            "a real double line and two conjugate lines through one real point of it",
        ),
        (C::TwoConcurrentLinesAndDoubleLine, _) => (
            vec![comp(K::Line, 2, 1, OPEN), comp(K::Line, 1, 2, OPEN)],
            multiple,
            "a real double line and two real lines, all through one real point",
        ),
        (C::LineAndTripleLine, _) => (
            vec![comp(K::Line, 3, 1, OPEN), comp(K::Line, 1, 1, OPEN)],
            multiple,
            "a real triple line and a real simple line crossing it",
        ),
        (C::TwoConcurrentDoubleLines, R::Point) => (
            vec![comp(K::Point, 1, 1, CLOSED)],
            multiple,
            "two conjugate lines counted twice, meeting at the only real point",
        ),
        (C::TwoConcurrentDoubleLines, _) => (
            vec![comp(K::Line, 2, 2, OPEN)],
            multiple,
            "two real crossing lines, each counted twice",
        ),
        (C::QuadrupleLine, _) => (
            vec![comp(K::Line, 4, 1, OPEN)],
            vec![],
            "a real line counted four times: a cone and a double plane tangent along it",
        ),
        (C::QuadrupleLineOfPlanePairs, _) => (
            vec![comp(K::Line, 4, 1, OPEN)],
            vec![],
            "a real line counted four times; every member is a pair of planes through it",
        ),
        (C::LineAndPlane, _) => (
            vec![comp(K::Plane, 1, 1, OPEN), comp(K::Line, 1, 1, OPEN)],
            multiple,
            "a real plane and a real line crossing it at one point",
        ),
        _ => (
            vec![comp(K::Plane, 1, 1, OPEN)],
            vec![],
            "a real plane common to both quadrics",
        ),
    };
    Description {
        components,
        singular_points,
        summary,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sym(entries: [[i64; 4]; 4]) -> SymMatrix4 {
        SymMatrix4::from_i64(entries).expect("symmetric")
    }

    #[test]
    fn pivots_give_the_common_kernel_dimension() {
        // x*y and x*z: common kernel spanned by w
        let a = sym([[0, 1, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]]);
        let b = sym([[0, 0, 1, 0], [0, 0, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0]]);
        assert_eq!(pivot_columns(a.entries(), b.entries()), vec![0, 1, 2]);
        // 2xy + w², 2yz + w²: no common kernel
        let a = sym([[0, 1, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]]);
        let b = sym([[0, 0, 0, 0], [0, 0, 1, 0], [0, 1, 0, 0], [0, 0, 0, 1]]);
        assert_eq!(pivot_columns(a.entries(), b.entries()).len(), 4);
        // (x+y)^2 and (x+y)*z: the kernel is spanned by (1,-1,0,0) and w
        let a = sym([[1, 1, 0, 0], [1, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]]);
        let b = sym([[0, 0, 1, 0], [0, 0, 1, 0], [1, 1, 0, 0], [0, 0, 0, 0]]);
        assert_eq!(pivot_columns(a.entries(), b.entries()), vec![0, 2]);
    }

    #[test]
    fn kronecker_pencil_is_a_conic_and_a_double_line() {
        let a = sym([[0, 1, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]]);
        let b = sym([[0, 0, 0, 0], [0, 0, 1, 0], [0, 1, 0, 0], [0, 0, 0, 1]]);
        let (m, d) = classify_singular(&a, &b).expect("a singular pencil");
        assert_eq!(m.complex, ComplexType::ConicAndDoubleLine);
        assert_eq!(d.components.len(), 2);
    }
}
