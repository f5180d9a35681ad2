//! Singular pencils (`det(λA − μB) ≡ 0`, `A`, `B` not proportional): the labelled pairs
//! of QI's test file, examples built with known answers for every type of taxonomy.md,
//! and invariance of the types under projective maps, pencil reparameterizations,
//! scalings and swaps, with small and with very large coefficients. An independent check
//! of the real types of `four_concurrent_lines` counts the real base points of random
//! pencils of conics by a resultant.

use proptest::prelude::*;
use qsic::io::parse_quadric;
use qsic::{classify, Classification, Quadric};
use qsic_algebra::{IBig, Poly, RBig};
use serde_json::Value;

/// A labelled pair: name, the two quadrics, expected complex and real type.
#[derive(Clone, Debug)]
struct Labelled {
    id: String,
    a: Quadric,
    b: Quadric,
    complex: String,
    real: String,
}

fn corpus_singular() -> Vec<Labelled> {
    let path = format!(
        "{}/tests/data/qi-quadrics.jsonl",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut out = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line: Value =
            serde_json::from_str(raw).unwrap_or_else(|e| panic!("line {}: {e}", i + 1));
        if line["pencil"].as_str() != Some("singular") {
            continue;
        }
        let form = |k: &str| {
            let s = line[k]
                .as_str()
                .unwrap_or_else(|| panic!("line {}: {k} is not a string", i + 1));
            parse_quadric(s).unwrap_or_else(|e| panic!("line {}: {k}: {e}", i + 1))
        };
        out.push(Labelled {
            id: line["id"].as_str().unwrap_or("?").to_owned(),
            a: form("A"),
            b: form("B"),
            complex: line["complex_type"].as_str().unwrap_or("?").to_owned(),
            real: line["real_type"].as_str().unwrap_or("?").to_owned(),
        });
    }
    out
}

/// Pairs built with a known answer (the reasoning is in each comment); `same` stands for
/// the complex type's name.
const CONSTRUCTED: &[(&str, &str, &str, &str)] = &[
    // no common singular point (ERRATA 5): y(x − z) = 0 gives the double line y = w = 0
    // and the conic x = z, 2xy + w² = 0
    (
        "2*x*y + w^2",
        "2*y*z + w^2",
        "conic_and_double_line",
        "same",
    ),
    // the same Kronecker block with the 1×1 regular block at another place
    ("2*x*y", "2*y*z + w^2", "conic_and_double_line", "same"),
    ("x*y + w^2", "y*z - 2*w^2", "conic_and_double_line", "same"),
    (
        "x*y + 3*w^2",
        "y*z + x*y - w^2",
        "conic_and_double_line",
        "same",
    ),
    // vertex w; conics x² = y², y² = z²: the four real points (±1, ±1, 1)
    ("x^2 - y^2", "y^2 - z^2", "four_concurrent_lines", "same"),
    // x² = y², 2x² + z² = 0: two conjugate pairs; the pencil has a definite member
    (
        "x^2 - y^2",
        "x^2 + y^2 + z^2",
        "four_concurrent_lines",
        "point",
    ),
    // xy = 0: x = 0 gives y² + z² = 0 (conjugate), y = 0 gives x = ±z (real)
    (
        "x*y",
        "x^2 - y^2 - z^2",
        "four_concurrent_lines",
        "two_concurrent_lines",
    ),
    // tangent at P = (1,0,0) along y = 0; the other points are the roots of q(y, z) on x = 0
    (
        "x*y",
        "y^2 + 2*y*z + 3*z^2",
        "two_concurrent_lines_and_double_line",
        "double_line",
    ),
    (
        "x*y",
        "y^2 + 3*y*z + z^2",
        "two_concurrent_lines_and_double_line",
        "same",
    ),
    // xy = 0 on xz = y²: x = 0 gives (0,0,1) twice, y = 0 gives (1,0,0) and (0,0,1)
    ("x*z - y^2", "x*y", "line_and_triple_line", "same"),
    // ℓ = x + z meets xz = y² at the conjugate points −z² = y²
    (
        "(x+z)^2",
        "x*z - y^2",
        "two_concurrent_double_lines",
        "point",
    ),
    // ℓ = x − z meets it at the real points z² = y²
    (
        "(x-z)^2",
        "x*z - y^2",
        "two_concurrent_double_lines",
        "same",
    ),
    ("(x+y+z)^2", "x*y", "two_concurrent_double_lines", "same"),
    (
        "z^2",
        "x^2 + x*y + y^2 + z*x",
        "two_concurrent_double_lines",
        "point",
    ),
    // z = 0 is tangent to xz = y² at (1,0,0): one quadruple point
    ("z^2", "x*z - y^2", "quadruple_line", "same"),
    ("(x+y)^2", "(x+y)*z + w^2", "quadruple_line", "same"),
    // pairs of planes through x = y = 0 without a common plane (real or imaginary roots)
    ("x^2 + y^2", "x*y", "quadruple_line_of_plane_pairs", "same"),
    ("x^2 - y^2", "x*y", "quadruple_line_of_plane_pairs", "same"),
    (
        "x^2 + y^2",
        "x^2 + 2*y^2",
        "quadruple_line_of_plane_pairs",
        "same",
    ),
    // common factor y, other factors x + z, x − 2z: the plane y = 0 and the line x = z = 0
    ("y*(x+z)", "y*(x-2*z)", "line_and_plane", "same"),
    ("x*(x+y)", "x*(y-z)", "line_and_plane", "same"),
    // common factor x, other factors in the same two variables: the common plane x = 0
    ("x*(x+y)", "x*(x-y)", "plane", "same"),
    ("(x+2*y)*(x-y+z)", "(x+2*y)*(2*x+y+z)", "plane", "same"),
    // … but not if the other factors and the common one span three dimensions
    (
        "(x+2*y)*(x-y+z)",
        "(x+2*y)*(3*x-3*y+3*z+w)",
        "line_and_plane",
        "same",
    ),
];

fn constructed() -> Vec<Labelled> {
    CONSTRUCTED
        .iter()
        .enumerate()
        .map(|(i, &(a, b, c, r))| Labelled {
            id: format!("constructed-{i}: {a} | {b}"),
            a: parse_quadric(a).unwrap_or_else(|e| panic!("{a}: {e}")),
            b: parse_quadric(b).unwrap_or_else(|e| panic!("{b}: {e}")),
            complex: c.to_owned(),
            real: if r == "same" {
                c.to_owned()
            } else {
                r.to_owned()
            },
        })
        .collect()
}

fn pool() -> Vec<Labelled> {
    let mut p = corpus_singular();
    p.extend(constructed());
    p
}

/// `None` if the classification is right, else what is wrong.
fn check(c: &Classification, want: &Labelled) -> Option<String> {
    let got = (c.pencil.key(), c.complex_type(), c.real_type());
    let expected = (
        "singular",
        Some(want.complex.as_str()),
        Some(want.real.as_str()),
    );
    if got != expected {
        return Some(format!("{}: got {got:?}, want {expected:?}", want.id));
    }
    if c.description.is_none() {
        return Some(format!("{}: no description", want.id));
    }
    None
}

type Mat = [[RBig; 4]; 4];

/// `PᵀMP`.
fn congruence(m: &Mat, p: &[[IBig; 4]; 4]) -> Mat {
    let mp: Mat = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            (0..4).fold(RBig::ZERO, |acc, k| {
                acc + &m[i][k] * RBig::from(p[k][j].clone())
            })
        })
    });
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            (0..4).fold(RBig::ZERO, |acc, k| {
                acc + RBig::from(p[k][i].clone()) * &mp[k][j]
            })
        })
    })
}

/// `s·M + t·N`.
fn lin(s: &RBig, m: &Mat, t: &RBig, n: &Mat) -> Mat {
    std::array::from_fn(|i| std::array::from_fn(|j| s * &m[i][j] + t * &n[i][j]))
}

fn det4(p: &[[IBig; 4]; 4]) -> IBig {
    // Laplace along the first row with 3×3 minors
    let det3 = |r: [usize; 3], c: [usize; 3]| {
        let a = |i: usize, j: usize| &p[r[i]][c[j]];
        a(0, 0) * (a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1))
            - a(0, 1) * (a(1, 0) * a(2, 2) - a(1, 2) * a(2, 0))
            + a(0, 2) * (a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0))
    };
    let cols = [[1, 2, 3], [0, 2, 3], [0, 1, 3], [0, 1, 2]];
    let mut d = IBig::ZERO;
    for (c, cs) in cols.iter().enumerate() {
        let t = &p[0][c] * det3([1, 2, 3], *cs);
        if c % 2 == 0 {
            d += t;
        } else {
            d -= t;
        }
    }
    d
}

/// A disguise of a pair: `X → PX`, the pencil basis `(aA + bB, cA + dB)`, scalings, a swap.
#[derive(Clone, Debug)]
struct Disguise {
    p: [[IBig; 4]; 4],
    basis: [IBig; 4],
    scales: [RBig; 2],
    swap: bool,
}

fn apply(pair: &Labelled, d: &Disguise) -> (Quadric, Quadric) {
    let a = congruence(pair.a.matrix(), &d.p);
    let b = congruence(pair.b.matrix(), &d.p);
    let [s, t, u, v] = d.basis.clone().map(RBig::from);
    let na = lin(&(&s * &d.scales[0]), &a, &(&t * &d.scales[0]), &b);
    let nb = lin(&(&u * &d.scales[1]), &a, &(&v * &d.scales[1]), &b);
    let qa = Quadric::from_matrix(na).expect("an invertible map keeps a nonzero quadric");
    let qb = Quadric::from_matrix(nb).expect("an invertible map keeps a nonzero quadric");
    if d.swap {
        (qb, qa)
    } else {
        (qa, qb)
    }
}

fn invertible(p: &[[IBig; 4]; 4]) -> bool {
    !det4(p).is_zero()
}

fn small_disguise() -> impl Strategy<Value = Disguise> {
    (
        prop::array::uniform4(prop::array::uniform4(-5i64..=5)),
        prop::array::uniform4(-3i64..=3),
        prop::array::uniform2((-5i64..=5, 1i64..=5)),
        any::<bool>(),
    )
        .prop_map(|(p, basis, scales, swap)| Disguise {
            p: p.map(|r| r.map(IBig::from)),
            basis: basis.map(IBig::from),
            scales: scales.map(|(n, d)| RBig::from_parts_signed(IBig::from(n), IBig::from(d))),
            swap,
        })
        .prop_filter("invertible map, basis and scales", |d| {
            invertible(&d.p)
                && &d.basis[0] * &d.basis[3] != &d.basis[1] * &d.basis[2]
                && d.scales.iter().all(|s| !s.is_zero())
        })
}

/// Entries of about 20 digits: `PᵀAP` has entries around 10⁴⁰.
fn big_int() -> impl Strategy<Value = IBig> {
    (-1_000_000i64..=1_000_000, 0i64..100_000_000_000_000)
        .prop_map(|(hi, lo)| IBig::from(hi) * IBig::from(100_000_000_000_000i64) + IBig::from(lo))
}

fn big_disguise() -> impl Strategy<Value = Disguise> {
    (
        prop::array::uniform4(prop::array::uniform4(big_int())),
        prop::array::uniform4(-1_000_000_000_000i64..=1_000_000_000_000),
        prop::array::uniform2((-1_000_000_000i64..=1_000_000_000, 1i64..=1_000_000_000)),
        any::<bool>(),
    )
        .prop_map(|(p, basis, scales, swap)| Disguise {
            p,
            basis: basis.map(IBig::from),
            scales: scales.map(|(n, d)| RBig::from_parts_signed(IBig::from(n), IBig::from(d))),
            swap,
        })
        .prop_filter("invertible map, basis and scales", |d| {
            invertible(&d.p)
                && &d.basis[0] * &d.basis[3] != &d.basis[1] * &d.basis[2]
                && d.scales.iter().all(|s| !s.is_zero())
        })
}

#[test]
fn every_singular_line_of_the_qi_test_file() {
    let pairs = corpus_singular();
    assert_eq!(pairs.len(), 31, "the QI test file has 31 singular pairs");
    let failures: Vec<String> = pairs
        .iter()
        .filter_map(|p| check(&classify(&p.a, &p.b), p))
        .collect();
    assert!(
        failures.is_empty(),
        "{} wrong:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn constructed_examples_of_every_type() {
    let pairs = constructed();
    let failures: Vec<String> = pairs
        .iter()
        .filter_map(|p| check(&classify(&p.a, &p.b), p))
        .collect();
    assert!(
        failures.is_empty(),
        "{} wrong:\n{}",
        failures.len(),
        failures.join("\n")
    );
    // every singular type of taxonomy.md is represented (corpus and constructed together)
    let mut seen: Vec<(String, String)> = pool().into_iter().map(|p| (p.complex, p.real)).collect();
    seen.sort();
    seen.dedup();
    assert_eq!(seen.len(), 13, "{seen:?}");
}

#[test]
fn descriptions_are_consistent() {
    for p in pool() {
        let c = classify(&p.a, &p.b);
        let d = c
            .description
            .unwrap_or_else(|| panic!("{}: no description", p.id));
        assert!(!d.summary.is_empty());
        // a real type other than `point` has real lines, conics or planes; `point` one point
        let kinds: Vec<&str> = d.components.iter().map(|c| c.kind.key()).collect();
        if p.real == "point" {
            assert_eq!(kinds, vec!["point"], "{}", p.id);
        } else {
            assert!(!kinds.is_empty() && !kinds.contains(&"point"), "{}", p.id);
        }
        // the curve components add up to degree 4 when all of them are real
        if p.real == p.complex && !kinds.contains(&"plane") {
            let degree: u32 = d
                .components
                .iter()
                .map(|c| {
                    let k = match c.kind.key() {
                        "line" => 1,
                        "conic" => 2,
                        _ => 0,
                    };
                    k * u32::from(c.multiplicity) * u32::from(c.count)
                })
                .sum();
            assert_eq!(degree, 4, "{}", p.id);
        }
    }
}

/// The ERRATA 5 pair computed by hand: `2xy + w²`, `2yz + w²` have no common singular
/// point and meet in the conic `x = z, 2xy + w² = 0` and the double line `y = w = 0`.
#[test]
fn errata_5_pair_by_hand() {
    let a = parse_quadric("2*x*y + w^2").expect("valid");
    let b = parse_quadric("2*y*z + w^2").expect("valid");
    let c = classify(&a, &b);
    assert_eq!(c.pencil.key(), "singular");
    assert_eq!(c.complex_type(), Some("conic_and_double_line"));
    let d = c.description.expect("described");
    let comps: Vec<(&str, u8, u8)> = d
        .components
        .iter()
        .map(|c| (c.kind.key(), c.multiplicity, c.count))
        .collect();
    assert_eq!(comps, vec![("conic", 1, 1), ("line", 2, 1)]);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    /// Every corpus and constructed pair under each sampled disguise.
    #[test]
    fn types_survive_small_disguises(d in small_disguise()) {
        for pair in &pool() {
            let (a, b) = apply(pair, &d);
            let c = classify(&a, &b);
            prop_assert_eq!(check(&c, pair), None, "under {:?}", d);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// Every corpus and constructed pair under each sampled disguise.
    #[test]
    fn types_survive_huge_coefficients(d in big_disguise()) {
        for pair in &pool() {
            let (a, b) = apply(pair, &d);
            let c = classify(&a, &b);
            prop_assert_eq!(check(&c, pair), None, "under {:?}", d);
        }
    }
}

/// The conic `(x, y, z)ᵀM(x, y, z)` at `x = t, y = 1` as `a z² + b(t) z + c(t)`.
fn conic_in_z(m: &[[i64; 3]; 3]) -> (Poly, Poly, Poly) {
    (
        Poly::from_i64s(&[m[2][2]]),
        Poly::from_i64s(&[2 * m[1][2], 2 * m[0][2]]),
        Poly::from_i64s(&[m[1][1], 2 * m[0][1], m[0][0]]),
    )
}

fn sym3(v: [i64; 6]) -> [[i64; 3]; 3] {
    [[v[0], v[1], v[2]], [v[1], v[3], v[4]], [v[2], v[4], v[5]]]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// Independent check of `four_concurrent_lines`: random conics `C₁, C₂` (the cones over
    /// them with vertex `w`), disguised; the resultant in `z` of `C₁, C₂` at `y = 1` is a
    /// binary quartic whose real roots, when it is square-free of degree 4, are the
    /// projections of the real base points from (0:0:1), one each.
    #[test]
    fn four_concurrent_lines_by_a_resultant(
        u in prop::array::uniform6(-4i64..=4),
        v in prop::array::uniform6(-4i64..=4),
        d in small_disguise(),
    ) {
        let (m1, m2) = (sym3(u), sym3(v));
        let (a1, b1, c1) = conic_in_z(&m1);
        let (a2, b2, c2) = conic_in_z(&m2);
        let ac = &(&a1 * &c2) - &(&a2 * &c1);
        let ab = &(&a1 * &b2) - &(&a2 * &b1);
        let bc = &(&b1 * &c2) - &(&b2 * &c1);
        let r = &(&ac * &ac) - &(&ab * &bc);
        prop_assume!(m1[2][2] != 0 && m2[2][2] != 0);
        prop_assume!(r.degree() == Some(4) && r.is_squarefree());
        let real = match r.count_real_roots_sturm() {
            0 => "point",
            2 => "two_concurrent_lines",
            4 => "four_concurrent_lines",
            n => panic!("a real quartic cannot have {n} distinct real roots here"),
        };
        let embed = |m: [[i64; 3]; 3]| {
            let mut q = [[0i64; 4]; 4];
            for i in 0..3 {
                for j in 0..3 {
                    q[i][j] = m[i][j];
                }
            }
            Quadric::from_integers(q).expect("a nonzero conic")
        };
        let pair = Labelled {
            id: format!("conics {m1:?} {m2:?}"),
            a: embed(m1),
            b: embed(m2),
            complex: "four_concurrent_lines".to_owned(),
            real: real.to_owned(),
        };
        let c = classify(&pair.a, &pair.b);
        prop_assert_eq!(check(&c, &pair), None);
        let (a, b) = apply(&pair, &d);
        let c = classify(&a, &b);
        prop_assert_eq!(check(&c, &pair), None, "under {:?}", d);
    }
}

fn cross(a: [i64; 3], b: [i64; 3]) -> [i64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot(a: [i64; 3], b: [i64; 3]) -> i64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `l·mᵀ + m·lᵀ`: the matrix of `2·l·m`.
fn sym_product(l: [i64; 3], m: [i64; 3]) -> [[i64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| l[i] * m[j] + m[i] * l[j]))
}

fn add3(a: [[i64; 3]; 3], b: [[i64; 3]; 3], s: i64, t: i64) -> [[i64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| s * a[i][j] + t * b[i][j]))
}

fn quad3(m: &[[i64; 3]; 3], u: [i64; 3], v: [i64; 3]) -> i64 {
    (0..3)
        .map(|i| (0..3).map(|j| u[i] * m[i][j] * v[j]).sum::<i64>())
        .sum()
}

/// The cones with vertex `w` over two conics.
fn cones(id: String, m1: [[i64; 3]; 3], m2: [[i64; 3]; 3], complex: &str, real: &str) -> Labelled {
    let embed = |m: [[i64; 3]; 3]| {
        let mut q = [[0i64; 4]; 4];
        for i in 0..3 {
            q[i][..3].copy_from_slice(&m[i]);
        }
        Quadric::from_integers(q).expect("a nonzero conic")
    };
    Labelled {
        id,
        a: embed(m1),
        b: embed(m2),
        complex: complex.to_owned(),
        real: if real == "same" {
            complex.to_owned()
        } else {
            real.to_owned()
        },
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 192, ..ProptestConfig::default() })]

    /// `[21]` by construction: `A = t·m` with `t` a line through `P`, `m` a line missing
    /// `P`; `B = aσ² + 2bστ + cτ²` a pair of lines through `P` (`σ(P) = τ(P) = 0`) not
    /// containing `t`. The conics are tangent at `P` (along `t`) and meet again at the two
    /// points of `m` on the lines of `B`: real iff `b² − ac > 0`.
    #[test]
    fn tangent_conics_by_construction(
        p in prop::array::uniform3(-3i64..=3),
        r in prop::array::uniform3(prop::array::uniform3(-3i64..=3)),
        m in prop::array::uniform3(-3i64..=3),
        (a, b, c) in (-3i64..=3, -3i64..=3, -3i64..=3),
        d in small_disguise(),
    ) {
        let (sigma, tau, t) = (cross(p, r[0]), cross(p, r[1]), cross(p, r[2]));
        prop_assume!(p != [0, 0, 0] && cross(sigma, tau) != [0, 0, 0] && t != [0, 0, 0]);
        prop_assume!(dot(m, p) != 0 && b * b - a * c != 0);
        let bm = add3(
            add3(sym_product(sigma, sigma), sym_product(tau, tau), a, c),
            sym_product(sigma, tau),
            1,
            2 * b,
        );
        // r[2] is a point of t other than P: B must not vanish there (t is not in B)
        prop_assume!(quad3(&bm, r[2], r[2]) != 0);
        let real = if b * b - a * c > 0 { "same" } else { "double_line" };
        let pair = cones(
            format!("P {p:?} t {t:?} m {m:?} B {bm:?}"),
            sym_product(t, m),
            bm,
            "two_concurrent_lines_and_double_line",
            real,
        );
        let c0 = classify(&pair.a, &pair.b);
        prop_assert_eq!(check(&c0, &pair), None);
        let (qa, qb) = apply(&pair, &d);
        let c1 = classify(&qa, &qb);
        prop_assert_eq!(check(&c1, &pair), None, "under {:?}", d);
    }

    /// `[(11)1]` and `[(21)]` by construction: the pencil of `ℓ²` and a nonsingular conic
    /// `C`. The base points are `ℓ ∩ C`, each double: two real, two conjugate, or one
    /// quadruple point when `ℓ` is tangent to `C`, decided by the discriminant of `C` on `ℓ`.
    #[test]
    fn double_line_and_conic_by_construction(
        l in prop::array::uniform3(-3i64..=3),
        r in prop::array::uniform2(prop::array::uniform3(-3i64..=3)),
        cv in prop::array::uniform6(-3i64..=3),
        d in small_disguise(),
    ) {
        let cm = sym3(cv);
        let det = cm[0][0] * (cm[1][1] * cm[2][2] - cm[1][2] * cm[2][1])
            - cm[0][1] * (cm[1][0] * cm[2][2] - cm[1][2] * cm[2][0])
            + cm[0][2] * (cm[1][0] * cm[2][1] - cm[1][1] * cm[2][0]);
        let (u, v) = (cross(l, r[0]), cross(l, r[1]));
        prop_assume!(det != 0 && cross(u, v) != [0, 0, 0]);
        let disc = quad3(&cm, u, v).pow(2) - quad3(&cm, u, u) * quad3(&cm, v, v);
        let (complex, real) = match disc.signum() {
            1 => ("two_concurrent_double_lines", "same"),
            -1 => ("two_concurrent_double_lines", "point"),
            _ => ("quadruple_line", "same"),
        };
        let ll: [[i64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| l[i] * l[j]));
        let pair = cones(format!("l {l:?} C {cm:?}"), ll, cm, complex, real);
        let c0 = classify(&pair.a, &pair.b);
        prop_assert_eq!(check(&c0, &pair), None);
        let (qa, qb) = apply(&pair, &d);
        let c1 = classify(&qa, &qb);
        prop_assert_eq!(check(&c1, &pair), None, "under {:?}", d);
    }
}
