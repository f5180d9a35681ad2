//! Moving quadrics: the instants and types of `moving.jsonl` (which correct the paper), and
//! constructed motions whose instants are known by hand.

use qsic::io::{moving_matrix_from_polynomial, moving_matrix_from_rows, MovingMatrix};
use qsic::motion::{InstantType, Motion, MotionType, MovingPencil};
use qsic_algebra::{AlgebraicReal, IBig, Poly, RBig};
use serde_json::Value;

fn rational(text: &str) -> RBig {
    let (n, d) = text.split_once('/').unwrap_or((text, "1"));
    RBig::from_parts_signed(n.trim().parse().unwrap(), d.trim().parse().unwrap())
}

fn matrix(v: &Value) -> MovingMatrix {
    let rows: Vec<Vec<String>> = v
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            r.as_array()
                .unwrap()
                .iter()
                .map(|e| e.as_str().unwrap().to_string())
                .collect()
        })
        .collect();
    moving_matrix_from_rows(&rows).unwrap()
}

/// A polynomial in `t` with integer coefficients, read as a rational function of `t`.
fn poly_in_t(text: &str) -> Poly {
    let f = qsic::io::parse_rational_function(text, &[qsic::io::Variable::T]).unwrap();
    let t = qsic::io::Variable::T.index();
    let coefficients = f.numerator().to_univariate(t).unwrap();
    Poly::new(coefficients.into_iter().map(|c| c.into_parts().0).collect())
}

/// The recorded type of an instant or interval.
fn recorded_type(v: &Value) -> (String, Option<u64>, String, String) {
    (
        v["pencil"].as_str().unwrap().to_string(),
        v["case"].as_u64(),
        v["complex_type"].as_str().unwrap().to_string(),
        v["real_type"].as_str().unwrap().to_string(),
    )
}

fn our_type(t: MotionType) -> (String, Option<u64>, String, String) {
    (
        t.pencil.to_string(),
        t.case.map(u64::from),
        t.complex_type.unwrap().to_string(),
        t.real_type.unwrap().to_string(),
    )
}

/// The recorded instant `v` is `t`: equal rationals, or the same polynomial (up to sign) and
/// an isolating interval containing the recorded approximation.
fn assert_same_instant(v: &Value, t: &AlgebraicReal, id: &str) {
    if let Some(s) = v.as_str() {
        assert_eq!(t.as_rational(), Some(&rational(s)), "{id}: instant {s}");
        return;
    }
    assert!(t.as_rational().is_none(), "{id}: {t} should be irrational");
    let want = poly_in_t(v["poly"].as_str().unwrap());
    let got = t.poly().primitive_part();
    assert!(
        got == want || got == -&want,
        "{id}: polynomial {got}, want {want}"
    );
    let x: f64 = v["approx"].as_str().unwrap().parse().unwrap();
    let iv = t.interval();
    assert!(
        iv.lo().to_f64().value() <= x && x <= iv.hi().to_f64().value(),
        "{id}: {x} outside {iv:?}"
    );
}

fn corpus() -> Vec<Value> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/moving.jsonl");
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

/// Every example of the corpus: the same instants, the same type on every interval and at
/// every instant (irrational ones classified in ℚ(α)).
#[test]
fn corpus_instants_and_types() {
    for d in corpus() {
        let id = d["id"].as_str().unwrap();
        let pencil = MovingPencil::new(matrix(&d["A"]), matrix(&d["B"])).unwrap();
        let motion = pencil.variations().unwrap();
        let want_instants = d["instants"].as_array().unwrap();
        assert_eq!(
            motion.instants.len(),
            want_instants.len(),
            "{id}: {motion:?}"
        );
        for (w, got) in want_instants.iter().zip(&motion.instants) {
            assert_same_instant(&w["t"], &got.t, id);
            let InstantType::Exact(c) = &got.class else {
                panic!("{id}: instant {} not classified", got.t);
            };
            assert_eq!(
                our_type(MotionType::of(c)),
                recorded_type(w),
                "{id} at {}",
                got.t
            );
        }
        let want_intervals = d["intervals"].as_array().unwrap();
        assert_eq!(motion.intervals.len(), want_intervals.len(), "{id}");
        for (w, got) in want_intervals.iter().zip(&motion.intervals) {
            let c = &got.classification;
            assert_eq!(
                our_type(MotionType::of(c)),
                recorded_type(w),
                "{id} at {}",
                got.sample
            );
            // the interval's ends are the neighbouring instants
            for (end, key) in [(&got.from, "from"), (&got.to, "to")] {
                match end {
                    None => assert!(w[key].is_null(), "{id}: {key}"),
                    Some(t) => assert_same_instant(&w[key], t, id),
                }
            }
            // its sample lies inside it
            assert!(got
                .from
                .as_ref()
                .is_none_or(|a| *a < AlgebraicReal::from_rational(got.sample.clone())));
            assert!(got
                .to
                .as_ref()
                .is_none_or(|b| AlgebraicReal::from_rational(got.sample.clone()) < *b));
        }
    }
}

/// The square-free part of `f(λ; t)` over ℚ(t) (λ-gcd with the derivative), its
/// discriminant by the library's resultant (an independent route from the motion module's
/// Sylvester determinants), times the leading coefficient and the t-content of `f`.
fn collision_polynomial(p: &MovingPencil) -> Poly {
    let f = p.characteristic();
    let g = f.gcd_domain(&f.derivative());
    // g primitive over ℤ[t], so that it divides f (Gauss)
    let c = g.coeffs().iter().fold(Poly::zero(), |a, b| a.gcd(b));
    let g = g.map(|v| v.div_exact(&c).unwrap());
    let k = Poly::new(g.coeffs().iter().map(Poly::content).collect()).content();
    let g = g.map(|v| v.div_exact(&Poly::constant(k.clone())).unwrap());
    let sf = f.div_exact(&g).unwrap();
    let content = f.coeffs().iter().fold(Poly::zero(), |a, b| a.gcd(b));
    &(&sf.resultant(&sf.derivative()) * &sf.leading()) * &content
}

/// Two spheres, radius 2 fixed at the origin and radius 1 centred at `(t, 0, 0)`: instants
/// ±3 (external tangency), ±1 (internal tangency), 0 (concentric); a real circle for
/// 1 < |t| < 3, nothing real outside; the motion is symmetric under `t ↦ −t` (the mirror
/// `x ↦ −x`), so the types are too.
#[test]
fn sphere_through_sphere() {
    let a = moving_matrix_from_polynomial("x^2 + y^2 + z^2 - 4").unwrap();
    let b = moving_matrix_from_polynomial("(x - t)^2 + y^2 + z^2 - 1").unwrap();
    let pencil = MovingPencil::new(a, b).unwrap();
    let motion = pencil.variations().unwrap();
    let ts: Vec<RBig> = motion
        .instants
        .iter()
        .map(|i| i.t.as_rational().expect("rational instants").clone())
        .collect();
    assert_eq!(ts, [-3, -1, 0, 1, 3].map(RBig::from).to_vec(), "{motion:?}");
    assert_symmetric(&motion);
    // 1 < t < 3: two spheres meeting in a circle (case 17, one real conic)
    let circle = &motion.intervals[4].classification;
    assert_eq!(circle.case, Some(17));
    assert_eq!(circle.real_type(), Some("one_conic"));
    assert_ne!(
        MotionType::of(&motion.intervals[5].classification),
        MotionType::of(circle)
    );
    let collisions = collision_polynomial(&pencil);
    for i in &motion.instants {
        assert!(i.t.is_root_of(&collisions), "{}", i.t);
    }
}

/// The types of a motion symmetric under `t ↦ −t` mirror each other.
fn assert_symmetric(m: &Motion) {
    let n = m.instants.len();
    for k in 0..n {
        let (a, b) = (&m.instants[k], &m.instants[n - 1 - k]);
        assert_eq!(
            a.class.classification().map(MotionType::of),
            b.class.classification().map(MotionType::of)
        );
    }
    let n = m.intervals.len();
    for k in 0..n {
        assert_eq!(
            MotionType::of(&m.intervals[k].classification),
            MotionType::of(&m.intervals[n - 1 - k].classification)
        );
    }
}

/// The same motion with the fixed sphere of radius √2: the instants move to the irrational
/// ±(√2 ± 1) (roots of t⁴ − 6t² + 1) and 0, and every type — on the intervals and at the
/// irrational instants, classified in ℚ(α) — is the one of the rational motion above.
#[test]
fn sphere_through_sphere_irrational_instants() {
    let rational = MovingPencil::new(
        moving_matrix_from_polynomial("x^2 + y^2 + z^2 - 4").unwrap(),
        moving_matrix_from_polynomial("(x - t)^2 + y^2 + z^2 - 1").unwrap(),
    )
    .unwrap()
    .variations()
    .unwrap();
    let pencil = MovingPencil::new(
        moving_matrix_from_polynomial("x^2 + y^2 + z^2 - 2").unwrap(),
        moving_matrix_from_polynomial("(x - t)^2 + y^2 + z^2 - 1").unwrap(),
    )
    .unwrap();
    let motion = pencil.variations().unwrap();
    assert_eq!(motion.instants.len(), 5);
    let quartic = Poly::from_i64s(&[1, 0, -6, 0, 1]);
    let approx = [
        -1.0 - 2f64.sqrt(),
        1.0 - 2f64.sqrt(),
        0.0,
        2f64.sqrt() - 1.0,
        1.0 + 2f64.sqrt(),
    ];
    for ((i, r), x) in motion.instants.iter().zip(&rational.instants).zip(approx) {
        if x == 0.0 {
            assert_eq!(i.t.as_rational(), Some(&RBig::ZERO));
        } else {
            assert!(
                i.t.is_root_of(&quartic) && (i.t.to_f64() - x).abs() < 1e-9,
                "{}",
                i.t
            );
        }
        let (InstantType::Exact(a), InstantType::Exact(b)) = (&i.class, &r.class) else {
            panic!("unclassified instant {}", i.t);
        };
        assert_eq!(MotionType::of(a), MotionType::of(b), "at {}", i.t);
        assert_eq!(a.segre, b.segre);
        assert_eq!(a.index_sequence, b.index_sequence);
    }
    for (i, r) in motion.intervals.iter().zip(&rational.intervals) {
        assert_eq!(i.classification, r.classification);
    }
}

/// The recorded instant as a real algebraic number (exact rational, or the recorded
/// polynomial on its recorded interval).
fn recorded_instant(v: &Value) -> AlgebraicReal {
    if let Some(s) = v.as_str() {
        return AlgebraicReal::from_rational(rational(s));
    }
    let p = poly_in_t(v["poly"].as_str().unwrap());
    let iv = v["interval"].as_array().unwrap();
    let (lo, hi) = (
        rational(iv[0].as_str().unwrap()),
        rational(iv[1].as_str().unwrap()),
    );
    let roots: Vec<AlgebraicReal> = AlgebraicReal::real_roots_of(&p)
        .into_iter()
        .filter(|r| {
            AlgebraicReal::from_rational(lo.clone()) < *r
                && *r < AlgebraicReal::from_rational(hi.clone())
        })
        .collect();
    assert_eq!(roots.len(), 1, "{v}: the interval isolates one root");
    roots.into_iter().next().unwrap()
}

/// `g` divided by the gcd of its coefficients in ℤ\[t\] (integer content included).
fn primitive_over_zt(g: &Poly<Poly>) -> Poly<Poly> {
    let c = g
        .coeffs()
        .iter()
        .fold(Poly::zero(), |acc: Poly, v| acc.gcd(v));
    let g = g.map(|v| v.div_exact(&c).expect("c divides every coefficient"));
    let k = g.coeffs().iter().fold(IBig::ZERO, |acc, v| {
        qsic_algebra::int_gcd(&acc, &v.content())
    });
    g.map(|v| v.map(|x| x / &k))
}

/// A polynomial in `t` vanishing wherever the rank of `λ₀A(t) − B(t)` at a root `λ₀` of the
/// repeated factor `g` drops below its generic value: for the largest `k` at which it is not
/// identically zero, the gcd over the `k × k` minors `m` of `λM_A − M_B` of `res_λ(g, m)`
/// (minors by `linalg`, resultants over ℤ\[t\] — independent of the motion module).
fn rank_drop_polynomial(pencil: &MovingPencil, g: &Poly<Poly>) -> Poly {
    let (ma, mb) = (pencil.a().numerators(), pencil.b().numerators());
    let n: [[Poly<Poly>; 4]; 4] = std::array::from_fn(|i| {
        std::array::from_fn(|j| Poly::new(vec![-&mb[i][j], ma[i][j].clone()]))
    });
    let minors = qsic_algebra::linalg::minors::SmallMinors::all(&n);
    (1..=3)
        .rev()
        .map(|k| {
            minors
                .of_order(k)
                .into_iter()
                .fold(Poly::zero(), |acc: Poly, m| acc.gcd(&g.resultant(m)))
        })
        .find(|p| !p.is_zero())
        .expect("some order of minors does not vanish identically at the roots of g")
}

/// Issue 7's check of the algebra layer on the corpus: the discriminant in λ of
/// `f(λ; t) = det(λA(t) − B(t))`, computed over ℤ\[t\] by the subresultant PRS, vanishes at
/// every recorded critical instant of a generic pencil. Where `f` has a repeated factor for
/// every `t` (ex4.1, ex4.2) the discriminant is identically zero; then every instant is a root
/// of the discriminant of the square-free part (by `gcd_domain` over ℤ\[t\]\[λ\]) or a rank drop
/// at the repeated root (Jordan structure change, the paper's Algorithms 1–2).
/// Independent route: at rational samples the discriminant of the specialised `f(λ; t₀)`
/// equals the specialised discriminant (same degree in λ there).
#[test]
fn corpus_discriminants_vanish_at_the_instants() {
    let mut generic = 0;
    for d in corpus() {
        let id = d["id"].as_str().unwrap();
        let pencil = MovingPencil::new(matrix(&d["A"]), matrix(&d["B"])).unwrap();
        let f = pencil.characteristic();
        assert_eq!(f.degree(), Some(4), "{id}");
        let full = f.discriminant();
        let (disc, drops) = if full.is_zero() {
            let g = primitive_over_zt(&f.gcd_domain(&f.derivative()));
            assert!(
                g.degree().unwrap() > 0,
                "{id}: zero discriminant, no repeated factor"
            );
            let sf = f
                .div_exact(&g)
                .expect("a primitive divisor over Q(t) divides over Z[t] (Gauss)");
            let disc = sf.discriminant();
            assert!(!disc.is_zero(), "{id}: square-free part still repeated");
            (disc, rank_drop_polynomial(&pencil, &g))
        } else {
            generic += 1;
            (full.clone(), Poly::constant(IBig::ONE))
        };
        for v in d["critical_instants"].as_array().unwrap() {
            let t = recorded_instant(v);
            assert!(
                t.is_root_of(&disc) || t.is_root_of(&drops),
                "{id}: neither the discriminant {disc} nor the rank drop {drops} vanishes at {t}"
            );
            if !full.is_zero() {
                assert!(t.is_root_of(&full), "{id}: {full} not zero at {t}");
            }
        }
        // evaluation commutes with the discriminant where the degree in λ is kept
        for t0 in [-3i64, -1, 0, 2, 5] {
            let t0 = IBig::from(t0);
            let ft0: Poly = f.map(|c| c.eval(&t0));
            if ft0.degree() == Some(4) {
                assert_eq!(ft0.discriminant(), full.eval(&t0), "{id} at t = {t0}");
            }
        }
    }
    assert_eq!(generic, 1, "ex3.1 is the corpus' generic pencil");
}

/// `text` with every `t` replaced by `(value)`.
fn substitute(text: &str, value: &str) -> String {
    text.replace('t', &format!("({value})"))
}

/// The type of the motion at a rational `t`: of the instant there, else of the interval
/// containing it.
fn type_at(m: &Motion, t: &RBig) -> MotionType {
    let x = AlgebraicReal::from_rational(t.clone());
    if let Some(i) = m.instants.iter().find(|i| i.t == x) {
        return MotionType::of(i.class.classification().expect("classified"));
    }
    let v = m
        .intervals
        .iter()
        .find(|v| v.from.as_ref().is_none_or(|a| *a < x) && v.to.as_ref().is_none_or(|b| x < *b))
        .expect("every t off the instants lies in an interval");
    MotionType::of(&v.classification)
}

/// Independent route: the static pair `A(t₀)`, `B(t₀)` read from the strings with `t₀`
/// substituted, classified by [`qsic::classify_allowing_zero`], has the motion's type at
/// `t₀`, for `t₀ = k/4`, `|k| ≤ 16` (poles, where the strings cannot be evaluated, skipped).
fn assert_matches_static(m: &Motion, a: &str, b: &str) -> usize {
    let mut checked = 0;
    for k in -16..=16i64 {
        let t0 = RBig::from_parts_signed(k.into(), 4u8.into());
        let value = format!("{k}/4");
        let (Ok(qa), Ok(qb)) = (
            optional_quadric(&substitute(a, &value)),
            optional_quadric(&substitute(b, &value)),
        ) else {
            continue;
        };
        let c = qsic::classify_allowing_zero(qa.as_ref(), qb.as_ref()).unwrap();
        assert_eq!(type_at(m, &t0), MotionType::of(&c), "{a}, {b} at t = {t0}");
        checked += 1;
    }
    checked
}

fn optional_quadric(text: &str) -> Result<Option<qsic::Quadric>, qsic::Error> {
    match qsic::io::parse_quadric(text) {
        Ok(q) => Ok(Some(q)),
        Err(qsic::Error::ZeroQuadric) => Ok(None),
        Err(e) => Err(e),
    }
}

fn motion_of(a: &str, b: &str) -> Motion {
    MovingPencil::new(
        moving_matrix_from_polynomial(a).unwrap(),
        moving_matrix_from_polynomial(b).unwrap(),
    )
    .unwrap()
    .variations()
    .unwrap()
}

/// Motions with known behaviour, in the quadratic-form syntax.
const MOTIONS: [(&str, &str); 5] = [
    ("x^2 + y^2 + z^2 - 4", "(x - t)^2 + y^2 + z^2 - 1"),
    ("x^2 + y^2 + z^2 - 2", "(x - t)^2 + y^2 + z^2 - 1"),
    ("x^2 + y^2 - 1", "(x - t)^2 + (y - t^2/2)^2 + z^2 - 1/4"),
    (
        "x^2 + y^2 - z^2 - w^2",
        "x^2/2 + y^2/2 + (z + t*w)^2/2 - w^2",
    ),
    // singular for every t (common vertex (0,0,0,1)): instants where the base lines meet
    ("x^2 + y^2 - z^2", "x^2 + t*y^2 - 2*z^2"),
];

/// Reparameterizing `t = (a·s + b)/(c·s + d)` moves every instant `τ` to `s = (dτ − b)/(a −
/// cτ)` with the same type (the image `τ = a/c` of `s = ∞` excepted), adds at most the
/// image `s = −d/c` of `t = ∞`, and every type agrees with the static classification.
#[test]
fn mobius_reparameterization_moves_instants_and_keeps_types() {
    let maps: [(i64, i64, i64, i64); 4] =
        [(2, 1, 1, 3), (-1, 0, 0, 1), (1, 2, 0, 1), (1, -1, 2, 1)];
    for (a_text, b_text) in MOTIONS {
        let original = motion_of(a_text, b_text);
        assert!(assert_matches_static(&original, a_text, b_text) > 20);
        for (a, b, c, d) in maps {
            let sub = format!("({a}*t + {b})/({c}*t + {d})");
            let (a2, b2) = (substitute(a_text, &sub), substitute(b_text, &sub));
            let moved = motion_of(&a2, &b2);
            assert!(assert_matches_static(&moved, &a2, &b2) > 20, "{a2}, {b2}");
            let mut expected: Vec<(f64, MotionType)> = original
                .instants
                .iter()
                .filter(|i| c == 0 || i.t.to_f64() * c as f64 != a as f64)
                .map(|i| {
                    let tau = i.t.to_f64();
                    let s = (d as f64 * tau - b as f64) / (a as f64 - c as f64 * tau);
                    (s, MotionType::of(i.class.classification().unwrap()))
                })
                .collect();
            expected.sort_by(|x, y| x.0.total_cmp(&y.0));
            let pole = (c != 0).then(|| -(d as f64) / c as f64);
            let got: Vec<(f64, MotionType)> = moved
                .instants
                .iter()
                .map(|i| {
                    (
                        i.t.to_f64(),
                        MotionType::of(i.class.classification().unwrap()),
                    )
                })
                .filter(|(s, _)| pole.is_none_or(|p| (s - p).abs() > 1e-12))
                .collect();
            assert_eq!(got.len(), expected.len(), "{a2}, {b2}: {got:?}");
            for ((s, t1), (s2, t2)) in got.iter().zip(&expected) {
                assert!((s - s2).abs() < 1e-9 * s.abs().max(1.0), "{s} vs {s2}");
                assert_eq!(t1, t2, "{a2}, {b2} at s = {s}");
            }
        }
    }
}

/// A matrix of entry strings.
type Rows = Vec<Vec<String>>;

/// `PᵀM(t)P` for an integer matrix `P`, as entry strings.
fn transformed(rows: &[Vec<String>], p: [[i64; 4]; 4]) -> Vec<Vec<String>> {
    (0..4)
        .map(|i| {
            (0..4)
                .map(|j| {
                    let mut terms = vec!["0".to_string()];
                    for k in 0..4 {
                        for l in 0..4 {
                            let w = p[k][i] * p[l][j];
                            if w != 0 {
                                terms.push(format!("({w})*({})", rows[k][l]));
                            }
                        }
                    }
                    terms.join(" + ")
                })
                .collect()
        })
        .collect()
}

fn rows_of(v: &Value) -> Vec<Vec<String>> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|r| {
            r.as_array()
                .unwrap()
                .iter()
                .map(|e| e.as_str().unwrap().to_string())
                .collect()
        })
        .collect()
}

/// A projective map `X ↦ PX` applied to both `A(t)` and `B(t)` changes nothing: the same
/// instants (exactly) with the same types, the same interval types.
#[test]
fn projective_map_changes_nothing() {
    let maps = [
        [[1, 2, 0, 0], [0, 1, 0, 3], [1, 0, 1, 0], [0, 0, -2, 1]],
        [[0, 1, 0, 0], [1, 0, 0, 0], [0, 0, 0, 1], [2, 0, 1, 0]], // det < 0
    ];
    let mut pairs: Vec<(String, Rows, Rows)> = corpus()
        .iter()
        .map(|d| {
            (
                d["id"].as_str().unwrap().to_string(),
                rows_of(&d["A"]),
                rows_of(&d["B"]),
            )
        })
        .collect();
    let sphere = |r: &str| {
        vec![
            vec!["1".into(), "0".into(), "0".into(), "0".into()],
            vec!["0".into(), "1".into(), "0".into(), "0".into()],
            vec!["0".into(), "0".into(), "1".into(), "0".into()],
            vec!["0".into(), "0".into(), "0".into(), format!("-{r}")],
        ]
    };
    let mut moving = sphere("1");
    moving[0][3] = "-t".into();
    moving[3][0] = "-t".into();
    moving[3][3] = "t^2 - 1".into();
    pairs.push(("spheres".into(), sphere("2"), moving));
    for (id, a, b) in pairs {
        let original = MovingPencil::new(
            moving_matrix_from_rows(&a).unwrap(),
            moving_matrix_from_rows(&b).unwrap(),
        )
        .unwrap()
        .variations()
        .unwrap();
        for p in maps {
            let m = MovingPencil::new(
                moving_matrix_from_rows(&transformed(&a, p)).unwrap(),
                moving_matrix_from_rows(&transformed(&b, p)).unwrap(),
            )
            .unwrap()
            .variations()
            .unwrap();
            assert_eq!(m.instants.len(), original.instants.len(), "{id}");
            for (x, y) in m.instants.iter().zip(&original.instants) {
                assert!(x.t == y.t, "{id}: {} vs {}", x.t, y.t);
                assert_eq!(x.class, y.class, "{id} at {}", x.t);
            }
            let types = |m: &Motion| -> Vec<MotionType> {
                m.intervals
                    .iter()
                    .map(|v| MotionType::of(&v.classification))
                    .collect()
            };
            assert_eq!(types(&m), types(&original), "{id}");
        }
    }
}

/// A pencil singular for every `t` (two cones with the common vertex `(0,0,0,1)`): the
/// projected conics `x² + y² = z²`, `x² + t·y² = 2z²` have 4 real base points for `t > 2`,
/// none for `t < 2` (`t ≠ 1`): instants exactly 1 and 2.
#[test]
fn pencil_singular_for_every_t() {
    let (a, b) = MOTIONS[4];
    let m = motion_of(a, b);
    let ts: Vec<Option<&RBig>> = m.instants.iter().map(|i| i.t.as_rational()).collect();
    assert_eq!(ts, [Some(&RBig::ONE), Some(&RBig::from(2))], "{m:?}");
    assert!(m
        .intervals
        .iter()
        .all(|v| v.classification.pencil.key() == "singular"));
    // four real lines through the vertex for t > 2: the real type is the complex one
    let c = &m.intervals[2].classification;
    assert_eq!(c.complex_type(), Some("four_concurrent_lines"));
    assert_eq!(c.real_type(), c.complex_type());
    assert_eq!(m.intervals[1].classification.real_type(), Some("point"));
    assert!(assert_matches_static(&m, a, b) > 30);
}

/// A factor common to every entry of `A(t)` is divided out: the quadric at its root is the
/// limit, and the motion is the one without the factor.
#[test]
fn common_factor_of_all_entries_is_divided_out() {
    let (a, b) = MOTIONS[0];
    let plain = motion_of(a, b);
    for factor in ["(t - 1)", "(t^2 - 2)*(3*t + 1)", "(t^2 + 1)"] {
        let m = motion_of(&format!("{factor}*({a})"), b);
        assert_eq!(m.instants.len(), plain.instants.len(), "{factor}");
        for (x, y) in m.instants.iter().zip(&plain.instants) {
            assert!(x.t == y.t && x.class == y.class, "{factor}: {}", x.t);
        }
    }
}

/// `A(t) ∝ B(t)` at the irrational `t = ±√2` (concentric spheres of radii 1 and
/// `√(3 − t²)`): a single quadric, typed in ℚ(√2) as the unit sphere alone.
#[test]
fn single_quadric_at_irrational_instants() {
    let m = motion_of("x^2 + y^2 + z^2 - w^2", "x^2 + y^2 + z^2 + (t^2 - 3)*w^2");
    let sphere = qsic::io::parse_quadric("x^2 + y^2 + z^2 - w^2").unwrap();
    let want = MotionType::of(&qsic::classify_single(&sphere));
    let two = Poly::from_i64s(&[-2, 0, 1]);
    let singles: Vec<&qsic::motion::MotionInstant> =
        m.instants.iter().filter(|i| i.t.is_root_of(&two)).collect();
    assert_eq!(singles.len(), 2, "{m:?}");
    for i in singles {
        let InstantType::Exact(c) = &i.class else {
            panic!("unclassified at {}", i.t)
        };
        assert_eq!(MotionType::of(c), want);
    }
}

/// Bad input gets errors naming it; a reversed range is refused; the bounds of
/// `qsic::limits` are enforced.
#[test]
fn bad_moving_input_is_an_error() {
    use qsic::Error;
    let read = moving_matrix_from_polynomial;
    assert!(matches!(
        read("sqrt(t)*x^2"),
        Err(Error::UnknownVariable { .. } | Error::Syntax { .. })
    ));
    assert!(read("t^(1/2)*x^2").is_err());
    assert!(matches!(read("x^2/(x + t)"), Err(Error::Syntax { .. })));
    assert_eq!(read("(t - t)*x^2"), Err(Error::ZeroQuadric));
    let sphere = || read("x^2 + y^2 + z^2 - 1").unwrap();
    let over = format!("t^{}*x^2 + y^2", qsic::limits::MAX_MOTION_DEGREE + 1);
    assert!(matches!(
        MovingPencil::new(read(&over).unwrap(), sphere()),
        Err(Error::Limit { .. })
    ));
    assert!(matches!(
        MovingPencil::new(
            read(&format!("1{}*t*x^2 + y^2", "0".repeat(160))).unwrap(),
            sphere()
        ),
        Err(Error::Limit { .. })
    ));
    let within = format!("t^{}*x^2 + y^2 - z^2", qsic::limits::MAX_MOTION_DEGREE);
    assert!(MovingPencil::new(read(&within).unwrap(), sphere()).is_ok());
    let mut rows = vec![vec!["0".to_string(); 4]; 4];
    rows[0][1] = "t".into();
    rows[1][0] = "t^2".into();
    assert!(matches!(
        moving_matrix_from_rows(&rows),
        Err(Error::NotSymmetric { row: 0, col: 1, .. })
    ));
    let pencil = MovingPencil::new(sphere(), read("(x-t)^2 + y^2 + z^2 - 1").unwrap()).unwrap();
    assert!(matches!(
        pencil.variations_in(Some(&RBig::ONE), Some(&RBig::ZERO)),
        Err(Error::InvalidRange(_))
    ));
}

/// On a range: the instants strictly inside as on the whole line, the ends reported where
/// their type differs from the interval beside them, intervals clipped to the range.
#[test]
fn ranges_clip_the_timeline() {
    let (a, b) = MOTIONS[0];
    let pencil = MovingPencil::new(
        moving_matrix_from_polynomial(a).unwrap(),
        moving_matrix_from_polynomial(b).unwrap(),
    )
    .unwrap();
    let whole = pencil.variations().unwrap();
    let q = |n: i64, d: u8| RBig::from_parts_signed(n.into(), d.into());
    for (lo, hi) in [
        (-5, 5),
        (-1, 1),
        (-2, 2),
        (1, 3),
        (-7, -5),
        (0, 0),
        (3, 3),
        (1, 2),
    ] {
        let (lo, hi) = (q(lo, 2), q(hi, 2));
        let m = pencil.variations_in(Some(&lo), Some(&hi)).unwrap();
        let (l, h) = (
            AlgebraicReal::from_rational(lo.clone()),
            AlgebraicReal::from_rational(hi.clone()),
        );
        let inside: Vec<&AlgebraicReal> = whole
            .instants
            .iter()
            .map(|i| &i.t)
            .filter(|t| l < **t && **t < h)
            .collect();
        let got: Vec<&AlgebraicReal> = m
            .instants
            .iter()
            .map(|i| &i.t)
            .filter(|t| l < **t && **t < h)
            .collect();
        assert_eq!(got, inside, "[{lo}, {hi}]");
        // the ends appear exactly where their type differs from the neighbouring interval
        for (end, v) in [(&lo, m.intervals.first()), (&hi, m.intervals.last())] {
            let reported = m.instants.iter().any(|i| i.t.as_rational() == Some(end));
            let differs =
                v.is_none_or(|v| type_at(&whole, end) != MotionType::of(&v.classification));
            assert_eq!(reported, differs, "[{lo}, {hi}] at {end}");
        }
        if lo == hi {
            assert!(m.intervals.is_empty());
            continue;
        }
        assert_eq!(m.intervals.first().unwrap().from.as_ref(), Some(&l));
        assert_eq!(m.intervals.last().unwrap().to.as_ref(), Some(&h));
        for v in &m.intervals {
            assert_eq!(
                MotionType::of(&v.classification),
                type_at(&whole, &v.sample)
            );
        }
    }
}

/// The instants of `m` that are roots of `t² − 2` (`±√2`), each classified exactly (not
/// `IrrationalUnclassified`) with non-null types, as their motion types.
fn types_at_sqrt2(m: &Motion, id: &str) -> Vec<MotionType> {
    let two = Poly::from_i64s(&[-2, 0, 1]);
    m.instants
        .iter()
        .filter(|i| i.t.is_root_of(&two))
        .map(|i| {
            let c = i
                .class
                .classification()
                .unwrap_or_else(|| panic!("{id}: unclassified at {}", i.t));
            let t = MotionType::of(c);
            assert!(
                t.complex_type.is_some() && t.real_type.is_some(),
                "{id}: null types at {}",
                i.t
            );
            t
        })
        .collect()
}

/// Moving pairs whose pencil is singular exactly when `u = t² − s = 0`, one per way a
/// singular pencil arises (module docs of `classify::singular`): cones sharing their vertex
/// (`k = 1`, a pencil of conics: two double lines, four lines, a double line and two lines),
/// plane pairs sharing their line (`k = 2`: with or without a common plane), no common
/// singular point (`k = 0`). With `s = 2` the instant is `√2`, classified over ℚ(√2); with
/// `s = 9/4` it is the rational `3/2`, classified over ℚ. The two must agree, and agree
/// with the static pair at `t = 3/2` read from the strings (the `t`-dependence away from
/// `u` is mild, so `√2` and `3/2` give the same structure). The first column is the
/// expected complex type, which is also the real type: every component is real.
const SINGULAR_AT_ROOT: [(&str, &str, &str); 6] = [
    (
        "two_concurrent_double_lines",
        "x^2 + y^2 - z^2",
        "(x - u*w)^2 + t*y^2 - z^2",
    ),
    (
        "four_concurrent_lines",
        "x^2 + 2*y^2 - 3*z^2 + x*y",
        "(x - u*w)^2 + t*(x - u*w)*z - 3*y^2 + z^2",
    ),
    (
        // the circle and a member through its tangent at (1, 0, 1) and the chord y = z/2
        "two_concurrent_lines_and_double_line",
        "x^2 + y^2 - z^2",
        "(x - u*w)^2 + y^2 - z^2 + t*(x - u*w - z)*(2*y - z)",
    ),
    (
        "quadruple_line_of_plane_pairs",
        "x^2 - y^2",
        "x*y + t*y^2 + u*z*w",
    ),
    ("plane", "x^2 - y^2", "(x + y)*(x + t*y) + u*z*w"),
    (
        "conic_and_double_line",
        "2*x*y + w^2",
        "2*y*z + t*w^2 + u*x^2",
    ),
];

#[test]
fn singular_pencil_at_an_irrational_instant_has_the_rational_class() {
    for (id, a, b) in SINGULAR_AT_ROOT {
        let at_sqrt2 = motion_of(a, &b.replace('u', "(t^2 - 2)"));
        let types = types_at_sqrt2(&at_sqrt2, id);
        assert_eq!(types.len(), 2, "{id}: {at_sqrt2:?}");
        // the instants increase: √2 is the second root of t² − 2
        let irrational = types[1];
        assert_eq!(irrational.pencil, "singular", "{id}");
        assert_eq!(
            (irrational.complex_type, irrational.real_type),
            (Some(id), Some(id)),
            "{id}"
        );
        let b_rational = b.replace('u', "(t^2 - 9/4)");
        let at_three_halves = motion_of(a, &b_rational);
        let three_halves = RBig::from_parts_signed(3.into(), 2u8.into());
        assert_eq!(type_at(&at_three_halves, &three_halves), irrational, "{id}");
        let (qa, qb) = (
            qsic::io::parse_quadric(&substitute(a, "3/2")).unwrap(),
            qsic::io::parse_quadric(&substitute(&b_rational, "3/2")).unwrap(),
        );
        assert_eq!(
            MotionType::of(&qsic::classify(&qa, &qb)),
            irrational,
            "{id}"
        );
    }
}

/// Every labelled singular pair `(A₀, B₀)` of QI's test file, disguised as a motion that is
/// singular exactly at `t = ±√2`: `A(t) = A₀∘M(t)`, `B(t) = (B₀ + (t² − 2)C)∘M(t)` with the
/// shear `M(t): x ↦ x + t·y` (invertible for every `t`) and a nonsingular `C`. At `±√2` the
/// pencil is congruent over ℝ to `(A₀, B₀)`, with entries in ℚ(√2): its class is the
/// recorded one.
#[test]
fn labelled_singular_pairs_disguised_at_sqrt2() {
    let path = format!(
        "{}/tests/data/qi-quadrics.jsonl",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).unwrap();
    let shear = |form: &str| form.replace('x', "(x + t*y)");
    let mut checked = 0;
    for (n, raw) in text.lines().enumerate() {
        let line: Value = serde_json::from_str(raw).unwrap();
        if line["pencil"].as_str() != Some("singular") {
            continue;
        }
        let id = format!("line {}: {}", n + 1, line["id"]);
        let (a0, b0) = (line["A"].as_str().unwrap(), line["B"].as_str().unwrap());
        let a = shear(a0);
        let b = shear(&format!(
            "{b0} + (t^2 - 2)*(x^2 + 2*y^2 - 3*z^2 + 5*w^2 + x*y)"
        ));
        let m = motion_of(&a, &b);
        let want = (
            line["complex_type"].as_str().unwrap(),
            line["real_type"].as_str().unwrap(),
        );
        let types = types_at_sqrt2(&m, &id);
        assert_eq!(types.len(), 2, "{id}: {m:?}");
        for t in types {
            assert_eq!(t.pencil, "singular", "{id}");
            assert_eq!(
                (t.complex_type.unwrap(), t.real_type.unwrap()),
                want,
                "{id}"
            );
        }
        checked += 1;
    }
    assert_eq!(checked, 31);
}
