//! Moving quadrics: the instants where the intersection of `A(t)` and `B(t)` changes type,
//! and the type on every interval between them and at every instant, exactly.
//!
//! The pencil is `λM_A(t) − μM_B(t)` with the numerator matrices of the two
//! [`MovingMatrix`] values (denominators cleared, so the quadric at a pole is the limit),
//! and `f(λ; t) = det(λM_A − M_B) ∈ ℤ[t][λ]`. Following Jia, Wang, Choi, Mourrain, Tu
//! (Theorems 3.2–3.12, Algorithms 1–3), the class of a regular pencil is constant wherever
//! the Segre characteristic is, and that changes only at the real roots of
//! ([`MovingPencil::candidate_instants`], a superset, module `instants`):
//! - the `t`-content of `f` (`f(·; t₀) ≡ 0`: a singular pencil at `t₀`);
//! - the discriminant of each square-free factor `gᵢ` of `f` over `ℚ(t)` (as binary forms in
//!   `(λ, μ)`, so `λ = ∞` is not special) and the resultants `Res(gᵢ, gⱼ)`;
//! - when `f` has a repeated factor for all `t`: for `k = 1, 2, 3`, where the `k×k` minors
//!   of `λM_A − μM_B` divided by their generic gcd `D_k` share a root (a Jordan structure
//!   change: the rank conditions of Algorithms 1–2, without case analysis);
//! - the denominators, the common roots of all entries of `M_A` (or `M_B`) and of all
//!   `2×2` minors of the pair (`M_A ∝ M_B`).
//!
//! [`MovingPencil::variations`] classifies at a rational sample of every open interval and at
//! every candidate — exactly, by [`classify()`](crate::classify()) at rational instants and by
//! arithmetic in `ℚ(α)` at irrational ones (module `irrational`) — then drops the candidates
//! whose type equals that of both neighbours and merges the intervals around them.
//!
//! [`contact`]: the first contact of the two quadrics in a range, and the relation of two
//! moving solid ellipsoids along the motion.

pub mod contact;
mod instants;
mod irrational;

pub use contact::{first_contact, solid_motion, FirstContact, SolidMotion, SolidState, TimeRange};

use crate::classify::{classify_allowing_zero, Classification};
use crate::error::Error;
use crate::io::MovingMatrix;
use instants::{
    discriminant_form, pencil_entries, rank_conditions, resultant_forms,
    squarefree_decomposition_t, t_content, t_primitive, Form, TPoly,
};
use qsic_algebra::matrix::MatrixPencil;
use qsic_algebra::{AlgebraicReal, IBig, Poly, RBig};

/// Two moving quadrics `A(t)`, `B(t)` and their characteristic polynomial
/// `f(λ; t) = det(λM_A(t) − M_B(t))`.
#[derive(Clone, Debug)]
pub struct MovingPencil {
    a: MovingMatrix,
    b: MovingMatrix,
    entries: [[TPoly; 4]; 4],
    /// `λM_A(t) − M_B(t)` over ℤ\[t\] with every minor, as polynomials in `λ`.
    pencil: MatrixPencil<Poly>,
    f: TPoly,
}

/// The type compared between neighbours: pencil kind, case, complex and real type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct MotionType {
    /// `regular`, `singular` or `single`.
    pub pencil: &'static str,
    /// The case 1–35 of a regular pencil.
    pub case: Option<u8>,
    /// The complex type key.
    pub complex_type: Option<&'static str>,
    /// The real type key.
    pub real_type: Option<&'static str>,
}

impl MotionType {
    /// The type of a classification.
    pub fn of(c: &Classification) -> MotionType {
        MotionType {
            pencil: c.pencil.key(),
            case: c.case,
            complex_type: c.complex_type(),
            real_type: c.real_type(),
        }
    }
}

/// The classification at an instant.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum InstantType {
    /// Classified exactly.
    Exact(Classification),
    /// An irrational instant the exact `ℚ(α)` route could not classify (kept, never guessed).
    IrrationalUnclassified,
}

impl InstantType {
    /// The classification, if known.
    pub fn classification(&self) -> Option<&Classification> {
        match self {
            InstantType::Exact(c) => Some(c),
            InstantType::IrrationalUnclassified => None,
        }
    }
}

/// An open interval of `t` on which the type is constant.
#[derive(Clone, Debug)]
pub struct MotionInterval {
    /// Left end, `None` for `−∞`.
    pub from: Option<AlgebraicReal>,
    /// Right end, `None` for `+∞`.
    pub to: Option<AlgebraicReal>,
    /// The rational `t` at which it was classified.
    pub sample: RBig,
    /// The classification on the interval.
    pub classification: Classification,
}

/// An instant where the type differs from the type just before or just after.
#[derive(Clone, Debug)]
pub struct MotionInstant {
    /// The instant (rational ones exact).
    pub t: AlgebraicReal,
    /// Its type.
    pub class: InstantType,
}

/// The variations of the intersection along the motion: `intervals[i]` ends at `instants[i]`,
/// `intervals[i + 1]` starts there.
#[derive(Clone, Debug)]
pub struct Motion {
    /// The intervals, increasing.
    pub intervals: Vec<MotionInterval>,
    /// The instants, increasing.
    pub instants: Vec<MotionInstant>,
}

impl MovingPencil {
    /// The pencil of two moving quadrics; computes every minor of `λM_A − M_B` over `ℤ[t]`
    /// once (`MatrixPencil<Poly>`), `f(λ; t)` among them.
    pub fn new(a: MovingMatrix, b: MovingMatrix) -> MovingPencil {
        let entries = pencil_entries(a.numerators(), b.numerators());
        let pencil = MatrixPencil::from_entries(a.numerators().clone(), b.numerators().clone());
        let f = pencil.det_poly();
        MovingPencil {
            a,
            b,
            entries,
            pencil,
            f,
        }
    }

    /// `A(t)`.
    pub fn a(&self) -> &MovingMatrix {
        &self.a
    }

    /// `B(t)`.
    pub fn b(&self) -> &MovingMatrix {
        &self.b
    }

    /// `f(λ; t) = det(λM_A(t) − M_B(t))` in `ℤ[t][λ]` (coefficients in `λ`, each a polynomial
    /// in `t`).
    pub fn characteristic(&self) -> &Poly<Poly> {
        &self.f
    }

    /// The exact classification at a rational `t` (of the numerator matrices: the limit
    /// quadric at a pole).
    ///
    /// # Errors
    /// [`Error::ZeroQuadric`] if both `M_A(t)` and `M_B(t)` are zero.
    pub fn classify_at(&self, t: &RBig) -> Result<Classification, Error> {
        let qa = optional(self.a.quadric_at(t))?;
        let qb = optional(self.b.quadric_at(t))?;
        classify_allowing_zero(qa.as_ref(), qb.as_ref())
    }

    /// Polynomials in `t` whose real roots contain every instant where the type can change
    /// (module docs); each nonzero, possibly constant.
    ///
    /// # Errors
    /// [`Error::UnsupportedMotion`] if the pencil is singular for every `t` (`f ≡ 0`).
    pub fn candidate_polynomials(&self) -> Result<Vec<Poly>, Error> {
        if self.f.is_zero() {
            return Err(Error::UnsupportedMotion(
                "det(λA(t) − B(t)) vanishes for every t (a singular pencil along the motion)"
                    .into(),
            ));
        }
        let mut out = vec![t_content(&self.f)];
        let f = t_primitive(&self.f);
        let mut forms: Vec<(Form, usize)> = squarefree_decomposition_t(&f)
            .into_iter()
            .map(|(g, m)| {
                let degree = g.degree().unwrap_or(0);
                (Form { chart: g, degree }, m)
            })
            .collect();
        let m_inf = 4 - f.degree().unwrap_or(0);
        if m_inf > 0 {
            let mu = Form {
                chart: TPoly::constant(Poly::constant(IBig::ONE)),
                degree: 1,
            };
            forms.push((mu, m_inf));
        }
        for (i, (g, _)) in forms.iter().enumerate() {
            out.extend(discriminant_form(g));
            for (h, _) in &forms[i + 1..] {
                out.push(resultant_forms(g, h));
            }
        }
        if forms.iter().any(|(_, m)| *m > 1) {
            for k in 1..=3 {
                let conditions =
                    rank_conditions(&self.pencil.minors(k), k).map_err(Error::UnsupportedMotion)?;
                out.extend(conditions);
            }
        }
        out.push(self.a.denominator().clone());
        out.push(self.b.denominator().clone());
        let (ma, mb) = (self.a.numerators(), self.b.numerators());
        for m in [ma, mb] {
            out.push(m.iter().flatten().fold(Poly::zero(), |g, e| g.gcd(e)));
        }
        // M_A ∝ M_B where every 2×2 minor of the pair of coefficient vectors vanishes.
        let (va, vb): (Vec<&Poly>, Vec<&Poly>) =
            (ma.iter().flatten().collect(), mb.iter().flatten().collect());
        let mut prop = Poly::zero();
        'pairs: for i in 0..16 {
            for j in i + 1..16 {
                prop = prop.gcd(&(&(va[i] * vb[j]) - &(va[j] * vb[i])));
                if prop.degree() == Some(0) {
                    break 'pairs;
                }
            }
        }
        out.push(prop);
        out.retain(|p| !p.is_zero());
        Ok(out)
    }

    /// The candidate instants: the distinct real roots of [`Self::candidate_polynomials`], in
    /// increasing order. Each is given by a square-free integer polynomial (an element of a
    /// gcd-free basis of the candidate polynomials, without its rational roots) and an
    /// isolating interval; rational ones are exact.
    ///
    /// # Errors
    /// As [`Self::candidate_polynomials`].
    pub fn candidate_instants(&self) -> Result<Vec<AlgebraicReal>, Error> {
        Ok(real_roots_of_all(&self.candidate_polynomials()?))
    }

    /// The type on every interval between consecutive instants and at every instant, with
    /// the instants where nothing changes dropped and their intervals merged (module docs).
    ///
    /// # Errors
    /// As [`Self::candidate_polynomials`]; [`Error::ZeroQuadric`] at an instant where both
    /// quadrics vanish.
    pub fn variations(&self) -> Result<Motion, Error> {
        let candidates = self.candidate_instants()?;
        let samples = samples_between(&candidates);
        let mut interval_types = Vec::with_capacity(samples.len());
        for s in &samples {
            interval_types.push(self.classify_at(s)?);
        }
        let mut instant_types = Vec::with_capacity(candidates.len());
        for c in &candidates {
            instant_types.push(match c.as_rational() {
                Some(v) => InstantType::Exact(self.classify_at(v)?),
                None => irrational::classify_at_irrational(&self.entries, c)
                    .map_or(InstantType::IrrationalUnclassified, InstantType::Exact),
            });
        }
        let mut intervals = vec![MotionInterval {
            from: None,
            to: None,
            sample: samples[0].clone(),
            classification: interval_types[0].clone(),
        }];
        let mut instants = Vec::new();
        for (j, (t, class)) in candidates.into_iter().zip(instant_types).enumerate() {
            let right = &interval_types[j + 1];
            let left = &intervals
                .last()
                .expect("one interval at least")
                .classification;
            let unchanged = class.classification().is_some_and(|c| {
                MotionType::of(c) == MotionType::of(left)
                    && MotionType::of(c) == MotionType::of(right)
            });
            if unchanged {
                continue;
            }
            intervals.last_mut().expect("one interval at least").to = Some(t.clone());
            intervals.push(MotionInterval {
                from: Some(t.clone()),
                to: None,
                sample: samples[j + 1].clone(),
                classification: right.clone(),
            });
            instants.push(MotionInstant { t, class });
        }
        Ok(Motion {
            intervals,
            instants,
        })
    }
}

/// `Ok(None)` for the zero quadric (allowed on one side of a pencil).
fn optional(q: Result<crate::Quadric, Error>) -> Result<Option<crate::Quadric>, Error> {
    match q {
        Ok(q) => Ok(Some(q)),
        Err(Error::ZeroQuadric) => Ok(None),
        Err(e) => Err(e),
    }
}

/// Rational samples: one left of the first candidate, one between each two, one right of the
/// last (`0` with no candidate).
fn samples_between(c: &[AlgebraicReal]) -> Vec<RBig> {
    let (Some(first), Some(last)) = (c.first(), c.last()) else {
        return vec![RBig::ZERO];
    };
    let mut out = Vec::with_capacity(c.len() + 1);
    out.push(RBig::from(first.interval().lo().floor() - IBig::ONE));
    for w in c.windows(2) {
        out.push(w[0].rational_between(&w[1]));
    }
    out.push(RBig::from(last.interval().hi().ceil() + IBig::ONE));
    out
}

/// The distinct real roots of the nonzero `polys`, increasing: each given by a square-free
/// primitive polynomial (an element of their gcd-free basis without its rational roots) and
/// an isolating interval; rational ones exact.
fn real_roots_of_all(polys: &[Poly]) -> Vec<AlgebraicReal> {
    let mut roots = Vec::new();
    for p in gcd_free_basis(polys) {
        let all = AlgebraicReal::real_roots_of(&p);
        let mut rest = p.clone();
        for r in &all {
            if let Some(v) = r.as_rational() {
                rest = rest
                    .div_exact(&Poly::vanishing_at(v))
                    .expect("a rational root's linear factor divides");
            }
        }
        for r in all {
            if r.as_rational().is_some() {
                roots.push(r);
            } else {
                let reduced = AlgebraicReal::from_isolating_interval(&rest, r.interval());
                roots.push(reduced.unwrap_or(r));
            }
        }
    }
    roots.sort();
    roots.dedup();
    roots
}

/// A gcd-free basis of the square-free parts of `polys`: pairwise coprime, square-free,
/// primitive polynomials of positive degree with the same roots as the product.
fn gcd_free_basis(polys: &[Poly]) -> Vec<Poly> {
    let mut basis: Vec<Poly> = Vec::new();
    for p in polys {
        if p.degree().unwrap_or(0) == 0 {
            continue;
        }
        let mut p = p.squarefree_part();
        let mut next = Vec::with_capacity(basis.len() + 2);
        for b in basis {
            let g = p.gcd(&b);
            if g.degree().unwrap_or(0) == 0 {
                next.push(b);
                continue;
            }
            let rest = b.div_exact(&g).expect("gcd divides");
            p = p.div_exact(&g).expect("gcd divides");
            if rest.degree().unwrap_or(0) > 0 {
                next.push(rest.primitive_part());
            }
            next.push(g);
        }
        if p.degree().unwrap_or(0) > 0 {
            next.push(p.primitive_part());
        }
        basis = next;
    }
    basis
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::moving_matrix_from_polynomial;

    /// The `ℚ(α)` route given a rational `α` agrees in full with the rational classifier,
    /// at instants and between them, for regular pencils of several motions.
    #[test]
    fn number_field_route_agrees_with_the_rational_classifier() {
        let motions = [
            ("x^2 + y^2 + z^2 - 4", "(x - t)^2 + y^2 + z^2 - 1"),
            (
                "x^2 - y^2 - 2*z*w",
                "x^2 + t^2*y^2 + (1 - t)*z^2 - 2*t*z*w + w^2",
            ),
            (
                "x^2 + y^2 - z^2 - w^2",
                "x^2/2 + y^2/2 + (z + t*w)^2/2 - w^2",
            ),
            ("x^2 + y^2 - 1", "(x - t)^2 + t*z^2 - 1"),
        ];
        let mut compared = 0;
        for (a, b) in motions {
            let p = MovingPencil::new(
                moving_matrix_from_polynomial(a).unwrap(),
                moving_matrix_from_polynomial(b).unwrap(),
            );
            for n in -12..=12 {
                let t = RBig::from_parts_signed(n.into(), 4u8.into());
                let exact = p.classify_at(&t).unwrap();
                let alpha = AlgebraicReal::from_rational(t.clone());
                let via_field = irrational::classify_at_irrational(&p.entries, &alpha);
                if exact.pencil.key() == "regular" {
                    assert_eq!(via_field.as_ref(), Some(&exact), "{a}, {b} at t = {t}");
                    compared += 1;
                } else {
                    assert!(via_field.is_none());
                }
            }
        }
        assert!(compared > 80, "{compared}");
    }
}
