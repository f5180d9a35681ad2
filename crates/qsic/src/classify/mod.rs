//! Classification of the intersection of two quadrics.
//!
//! | entry point | does |
//! |---|---|
//! | [`classify()`] | any two quadrics: regular, singular or single pencil |
//! | [`classify_single`] | one quadric (the pencil of `A` with itself or with the zero form) |
//! | [`analyze_pencil`] | the exact pencil analysis behind a regular classification |
//!
//! **Regular pencils** (`det(λA − μB) ≢ 0`) follow Tu, Wang, Mourrain, Wang (CAGD 2009):
//! the signature sequence — the inertia of `λA − μB` on every arc of the projective
//! λ-line and at every real root — taken up to rotation (with the swap at ∞ of ERRATA
//! item 4), reversal and complement, together with the Segre characteristic, picks one of
//! the 35 cases of the module `table`. The Segre characteristic comes from the invariant factors of
//! `λA − μB` (gcds of minors); it carries the minimal-polynomial degree that Section 6 uses
//! to separate cases 4/10/31 (`[1111]₀`, `[22]₀`, `[(11)(11)]₀`) and 26/35 (`[(31)]`,
//! `[(22)]`), so no extra test is needed. Everything is exact rational arithmetic.
//!
//! **Singular pencils** (`det ≡ 0`): the module `singular` derives the type from the Kronecker
//! structure (common singular points, projection to a pencil of conics).
//! **Single** (`A ∝ B`): the module `single`, by inertia.

mod fast;
mod notation;
mod signature;
mod single;
mod singular;
pub(crate) use singular::OrderedDomain;
mod table;

pub use crate::vocabulary::{
    ComplexType, Component, ComponentKind, Description, Morphology, PencilKind, RealType,
    SingularPointKind, SingularPoints,
};

use crate::error::Error;
use crate::pencil::{PencilAnalysis, PencilData, SigItem};
use crate::quadric::Quadric;
use crate::Budget;
use notation::SegreKey;
use std::collections::HashMap;
use std::sync::OnceLock;
use table::{CaseRow, CASES};

/// The classification of a pair of quadrics.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Classification {
    /// Regular, singular or single pencil.
    pub pencil: PencilKind,
    /// The paper's case number 1–35 (regular pencils only).
    pub case: Option<u8>,
    /// Segre characteristic with the number of distinct real roots, e.g. `[(11)11]_3`
    /// (regular pencils only).
    pub segre: Option<&'static str>,
    /// The canonical signature sequence of the class (regular pencils only).
    pub signature: Option<&'static str>,
    /// The canonical index sequence of the class (regular pencils only).
    pub index_sequence: Option<&'static str>,
    /// Complex and real type (taxonomy.md). Always present for valid quadrics; `None` would
    /// mean an internal inconsistency (no case of the table matches), reported rather than
    /// guessed.
    pub morphology: Option<Morphology>,
    /// Real components and singular points.
    pub description: Option<Description>,
}

impl Classification {
    /// The `complex_type` key, if known.
    pub fn complex_type(&self) -> Option<&'static str> {
        self.morphology.map(|m| m.complex.key())
    }

    /// The `real_type` key, if known.
    pub fn real_type(&self) -> Option<&'static str> {
        self.morphology.map(|m| m.real_key())
    }
}

/// Classifies the intersection of two quadrics, exactly.
///
/// ```
/// use qsic::{classify, io::parse_quadric};
/// // two spheres meeting in a circle: a real conic and the imaginary conic at infinity
/// let a = parse_quadric("x^2+y^2+z^2-4").unwrap();
/// let b = parse_quadric("(x-1)^2+y^2+z^2-4").unwrap();
/// let c = classify(&a, &b);
/// assert_eq!(c.case, Some(17));
/// assert_eq!(c.real_type(), Some("one_conic"));
/// ```
pub fn classify(a: &Quadric, b: &Quadric) -> Classification {
    classify_keeping_sums(a, b).0
}

/// [`classify()`] spending `budget` ([`crate::Budget`]): the fast path a fixed
/// [`FAST_UNITS`], the exact path the units of its determinants, remainder sequences, root
/// isolation and refinement (module [`crate::pencil`]).
///
/// # Errors
/// [`Error::BudgetExceeded`] when the budget runs out first.
pub fn classify_within(a: &Quadric, b: &Quadric, budget: &Budget) -> Result<Classification, Error> {
    Ok(classify_keeping_sums_within(a, b, budget)?.0)
}

/// [`classify_keeping_sums`] spending `budget` (as [`classify_within`]).
pub(crate) fn classify_keeping_sums_within(
    a: &Quadric,
    b: &Quadric,
    budget: &Budget,
) -> Result<(Classification, Option<MinorSums>), Error> {
    budget.spend(FAST_UNITS)?;
    if let Some(c) = natural_classification(a, b) {
        return Ok((c, None));
    }
    match classify_fast(a, b) {
        Some(fast::SimpleRoots { case, sums }) => {
            Ok((from_row(&CASES[usize::from(case) - 1], 0), Some(sums)))
        }
        None => Ok((classify_exact_within(a, b, budget)?, None)),
    }
}

/// `E₁…E₄` of `λA − B` in `i128`, as the fast path leaves them.
pub(crate) type MinorSums = [[i128; 5]; 4];

/// The units [`classify_within`] spends on the fast path: about what its `i128` minors and
/// certified float roots cost in word operations.
pub const FAST_UNITS: u64 = 2_000;

/// [`classify()`] with `E₁…E₄` of `λA − B` when the fast path decided (module `fast`), for
/// the curve's surface choice, which reads them too.
pub(crate) fn classify_keeping_sums(
    a: &Quadric,
    b: &Quadric,
) -> (Classification, Option<[[i128; 5]; 4]>) {
    if let Some(c) = natural_classification(a, b) {
        return (c, None);
    }
    match classify_fast(a, b) {
        Some(fast::SimpleRoots { case, sums }) => {
            (from_row(&CASES[usize::from(case) - 1], 0), Some(sums))
        }
        None => (classify_exact(a, b), None),
    }
}

/// The fast path's answer (module `fast`: four simple roots, small entries), or `None` when
/// it does not decide.
fn classify_fast(a: &Quadric, b: &Quadric) -> Option<fast::SimpleRoots> {
    let (sa, sb) = (a.small_integer_matrix()?, b.small_integer_matrix()?);
    fast::simple_roots(sa, sb)
}

/// The natural route's class (module [`crate::natural`]), or `None` (the general route
/// answers): the first stage of [`classify()`].
fn natural_classification(a: &Quadric, b: &Quadric) -> Option<Classification> {
    crate::natural::answer(a, b).map(|p| from_natural(p.class))
}

/// The classification the natural route's closed forms name (module [`crate::natural`]): a
/// class of the table, or a singular type with its description.
pub(crate) fn from_natural(class: crate::natural::pair::NaturalClass) -> Classification {
    use crate::natural::pair::NaturalClass;
    match class {
        NaturalClass::Regular { case, class } => from_row(&CASES[usize::from(case) - 1], class),
        NaturalClass::Singular(complex, real) => {
            let m = Morphology { complex, real };
            singular_classification(Some((m, singular::describe(m))))
        }
    }
}

/// The classification of a singular pencil from its type (`None`: undetermined, never guessed).
fn singular_classification(typed: Option<(Morphology, Description)>) -> Classification {
    let (morphology, description) = typed.map_or((None, None), |(m, d)| (Some(m), Some(d)));
    Classification {
        pencil: PencilKind::Singular,
        case: None,
        segre: None,
        signature: None,
        index_sequence: None,
        morphology,
        description,
    }
}

/// The classification of the singular pencil `λA − μB` over an ordered domain (ℚ(α) at an
/// irrational instant of a motion); precondition as `singular::classify_singular`:
/// `det(λA − μB) ≡ 0`, `A`, `B` not proportional.
pub(crate) fn classify_singular_in<C: OrderedDomain>(
    a: &[[C; 4]; 4],
    b: &[[C; 4]; 4],
) -> Classification {
    singular_classification(singular::classify_singular_in(a, b))
}

/// [`classify()`] without the machine-arithmetic fast path: every decision by exact
/// rational arithmetic. The two must agree (property tests).
pub(crate) fn classify_exact(a: &Quadric, b: &Quadric) -> Classification {
    classify_exact_within(a, b, &Budget::unlimited()).expect("an unlimited budget is never spent")
}

/// [`classify_exact`] spending `budget`: the minors of the pencil
/// ([`PencilData::units`]), then the analysis of a regular pencil
/// ([`PencilAnalysis::compute_within`]) or the rank and kernel computations of a singular
/// one (as many units again as the minors).
fn classify_exact_within(
    a: &Quadric,
    b: &Quadric,
    budget: &Budget,
) -> Result<Classification, Error> {
    budget.spend(PencilData::units(a, b))?;
    let data = PencilData::new(a, b);
    Ok(match pencil_kind(&data) {
        PencilKind::Single => classify_single(a),
        PencilKind::Singular => {
            budget.spend(PencilData::units(a, b))?;
            singular_classification(singular::classify_singular(&data.a, &data.b))
        }
        PencilKind::Regular => classify_regular(&PencilAnalysis::compute_within(&data, budget)?),
    })
}

/// The kind of the pencil of two quadrics, decided once for every route: proportional
/// forms are a single quadric (even where `det(λA − μB) ≢ 0`, for a nonsingular `A`);
/// otherwise `det(λA − μB) ≡ 0` makes the pencil singular.
fn pencil_kind(data: &PencilData) -> PencilKind {
    if data.a.is_proportional(&data.b) {
        PencilKind::Single
    } else if data.f.is_zero() {
        PencilKind::Singular
    } else {
        PencilKind::Regular
    }
}

/// Classifies a pair in which either form may be the zero form (`None`): the pencil of a
/// quadric and the zero form is that quadric alone, reported as `single` (as QI does).
///
/// # Errors
/// [`Error::ZeroQuadric`] if both forms are zero: they span no pencil.
pub fn classify_allowing_zero(
    a: Option<&Quadric>,
    b: Option<&Quadric>,
) -> Result<Classification, Error> {
    match (a, b) {
        (Some(a), Some(b)) => Ok(classify(a, b)),
        (Some(q), None) | (None, Some(q)) => Ok(classify_single(q)),
        (None, None) => Err(Error::ZeroQuadric),
    }
}

/// [`classify_allowing_zero`] spending `budget` on a pair ([`classify_within`]; a single
/// quadric costs [`FAST_UNITS`]).
///
/// # Errors
/// As [`classify_allowing_zero`]; [`Error::BudgetExceeded`] when the budget runs out.
pub fn classify_allowing_zero_within(
    a: Option<&Quadric>,
    b: Option<&Quadric>,
    budget: &Budget,
) -> Result<Classification, Error> {
    match (a, b) {
        (Some(a), Some(b)) => classify_within(a, b, budget),
        (Some(q), None) | (None, Some(q)) => {
            budget.spend(FAST_UNITS)?;
            Ok(classify_single(q))
        }
        (None, None) => Err(Error::ZeroQuadric),
    }
}

/// The exact analysis of the pencil of a regular pair; `None` for a singular or single pencil.
pub fn analyze_pencil(a: &Quadric, b: &Quadric) -> Option<PencilAnalysis> {
    let data = PencilData::new(a, b);
    (pencil_kind(&data) == PencilKind::Regular).then(|| PencilAnalysis::compute(&data))
}

/// [`analyze_pencil`] spending `budget`: the minors ([`PencilData::units`]) and the
/// analysis ([`PencilAnalysis::compute_within`]).
pub(crate) fn analyze_pencil_within(
    a: &Quadric,
    b: &Quadric,
    budget: &Budget,
) -> Result<Option<PencilAnalysis>, qsic_algebra::Exhausted> {
    budget.spend(PencilData::units(a, b))?;
    let data = PencilData::new(a, b);
    if pencil_kind(&data) != PencilKind::Regular {
        return Ok(None);
    }
    Ok(Some(PencilAnalysis::compute_within(&data, budget)?))
}

pub use single::classify_single;
pub(crate) use single::classify_single_inertia;

/// Key of a class: the Segre characteristic (block structures of all roots, number of
/// distinct real roots) and the canonical signature sequence.
type ClassKey = (SegreKey, Vec<SigItem>);

fn class_index() -> &'static HashMap<ClassKey, (&'static CaseRow, usize)> {
    static INDEX: OnceLock<HashMap<ClassKey, (&'static CaseRow, usize)>> = OnceLock::new();
    INDEX.get_or_init(|| {
        let mut map = HashMap::new();
        for row in CASES.iter() {
            for (i, (signature, _)) in row.sequences.iter().enumerate() {
                let key = (row.segre.key, signature::canonical(signature.items()));
                let previous = map.insert(key, (row, i));
                debug_assert!(previous.is_none(), "two cases share a class key");
            }
        }
        map
    })
}

fn classify_regular(analysis: &PencilAnalysis) -> Classification {
    let structures = analysis
        .real_roots
        .iter()
        .map(|r| r.blocks.as_slice())
        .chain(analysis.complex_roots.iter().map(Vec::as_slice));
    classify_regular_parts(
        structures,
        analysis.real_roots.len(),
        analysis.signature_sequence(),
    )
}

/// The class of a regular pencil from the block structures of its roots (`real` of them
/// real) and its signature sequence (as [`PencilAnalysis::signature_sequence`]); the route
/// of pencils whose coefficients are not rational (`motion`).
pub(crate) fn classify_regular_parts<'a>(
    structures: impl IntoIterator<Item = &'a [u8]>,
    real: usize,
    sequence: Vec<SigItem>,
) -> Classification {
    let key = SegreKey::new(structures, real).map(|segre| (segre, signature::canonical(&sequence)));
    match key.as_ref().and_then(|key| class_index().get(key)) {
        Some((row, i)) => from_row(row, *i),
        // Theorem 23 of the paper: every regular pencil falls in one of the 35 cases; a
        // miss is a bug, reported as an undetermined class rather than a wrong one.
        None => Classification {
            pencil: PencilKind::Regular,
            case: None,
            segre: None,
            signature: None,
            index_sequence: None,
            morphology: None,
            description: None,
        },
    }
}

/// The classification of a regular pencil in the case of `row`, class `i` of the row.
fn from_row(row: &CaseRow, i: usize) -> Classification {
    Classification {
        pencil: PencilKind::Regular,
        case: Some(row.case),
        segre: Some(row.segre.text),
        signature: Some(row.sequences[i].0.text),
        index_sequence: Some(row.sequences[i].1.text),
        morphology: Some(Morphology {
            complex: row.complex,
            real: row.real,
        }),
        description: Some(row.description()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use qsic_algebra::{IBig, Poly};

    /// `classify` takes the fast path for almost every random pair, and its answer is the
    /// exact path's in full.
    #[test]
    fn the_fast_path_decides_most_random_pairs() {
        let mut state = 7u64;
        let mut coefficient = || {
            // a linear congruential generator is plenty for coefficients in [−10, 10]
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 33) % 21) as i64 - 10
        };
        let mut random_quadric = || loop {
            let mut m = [[0i64; 4]; 4];
            for i in 0..4 {
                for j in i..4 {
                    let c = coefficient();
                    m[i][j] = if i == j { 2 * c } else { c };
                    m[j][i] = m[i][j];
                }
            }
            if let Ok(q) = Quadric::from_integers(m) {
                return q;
            }
        };
        let (total, mut decided) = (300, 0);
        for _ in 0..total {
            let (a, b) = (random_quadric(), random_quadric());
            if let (c, Some(sums)) = classify_keeping_sums(&a, &b) {
                decided += 1;
                assert_eq!(c, classify_exact(&a, &b), "{a:?}, {b:?}");
                // the sums kept for the curve are the pencil's (from all its minors)
                let e = PencilData::new(&a, &b).pencil().principal_minor_sums();
                for (k, ek) in e.iter().enumerate() {
                    let kept: Vec<IBig> = sums[k][..k + 2].iter().map(|&v| IBig::from(v)).collect();
                    assert_eq!(*ek, Poly::new(kept), "E{}", k + 1);
                }
            }
        }
        assert!(decided * 100 >= total * 95, "{decided} of {total} decided");
    }

    /// A regular pencil is analysed (sphere and elliptic cylinder: roots 0, 1, 2, 4); a
    /// singular pencil and a single quadric are not.
    #[test]
    fn analyze_pencil_only_for_regular_pencils() {
        let q = |m: [i64; 4]| {
            let mut d = [[0; 4]; 4];
            for i in 0..4 {
                d[i][i] = m[i];
            }
            Quadric::from_integers(d).expect("nonzero")
        };
        let (sphere, cylinder) = (q([1, 1, 1, -1]), q([2, 4, 0, -1]));
        let analysis = analyze_pencil(&sphere, &cylinder).expect("a regular pencil");
        assert_eq!(analysis.real_roots.len(), 4);
        assert!(analysis.complex_roots.is_empty());
        // two cones with the common vertex (0, 0, 0, 1): det(λA − B) ≡ 0
        assert!(analyze_pencil(&q([1, 1, -1, 0]), &q([1, -1, 2, 0])).is_none());
        assert!(analyze_pencil(&sphere, &q([2, 2, 2, -2])).is_none());
    }

    /// Proportional pairs are a single quadric at every rank, whether `det(λA − μB)`
    /// vanishes identically (rank < 4) or not: the kind is decided before the singular
    /// route, which relies on it and does not check again.
    #[test]
    fn proportional_pairs_are_single_at_every_rank() {
        for rank in 1..=4 {
            let mut d = [[0i64; 4]; 4];
            for i in 0..rank {
                d[i][i] = [1, -1, 2, 3][i];
            }
            let a = Quadric::from_integers(d).expect("nonzero");
            let b = Quadric::from_integers(d.map(|r| r.map(|v| -3 * v))).expect("nonzero");
            let data = PencilData::new(&a, &b);
            assert_eq!(data.f.is_zero(), rank < 4);
            assert_eq!(pencil_kind(&data), PencilKind::Single, "rank {rank}");
            assert_eq!(classify_exact(&a, &b), classify_single(&a), "rank {rank}");
            assert_eq!(classify(&a, &b), classify_single(&a), "rank {rank}");
            assert!(analyze_pencil(&a, &b).is_none());
        }
    }

    #[test]
    fn every_table_class_key_is_distinct_and_complete() {
        assert_eq!(class_index().len(), 36);
    }
}
