//! The affine view's fast path ([`fast_affine_curve`]: no curve, from the class and the
//! conics at infinity) against the full path (`parameterize` then [`affine_curve`]): every
//! field equal wherever the fast path answers — on every corpus line, in the default chart
//! and in others, on random integer pairs, random ellipsoid pairs, and their images under
//! random affine maps (which fix the plane at infinity, so the answer must not change).
//! [`conic_real_intersections`] against conic pairs whose common points are known by
//! construction.

// Index loops read as the matrix formulas they implement.
#![allow(clippy::needless_range_loop)]

mod common;

#[path = "common/geometry.rs"]
mod geometry;

use common::read_form;
use geometry::moved;
use qsic::affine::{
    affine_curve, affine_view, conic_real_intersections, fast_affine_curve, AffineCurve, Chart,
};
use qsic::io::parse_quadric;
use qsic::param::parameterize;
use qsic::{Error, Quadric};
use qsic_algebra::testing::SplitMix;
use qsic_algebra::RBig;
use serde_json::Value;

fn full(a: &Quadric, b: &Quadric, chart: &Chart) -> Result<AffineCurve, Error> {
    parameterize(a, b).and_then(|c| affine_curve(&c, a, b, chart))
}

/// Tallies of one comparison run.
#[derive(Default)]
struct Tally {
    fast: usize,
    declined: usize,
    slow_case_1: usize,
    failures: Vec<String>,
}

impl Tally {
    /// Compares the two paths on one pair; `expect` (when given) is the answer the pair must
    /// have (its undisguised original's).
    fn compare(
        &mut self,
        id: &str,
        a: &Quadric,
        b: &Quadric,
        chart: &Chart,
    ) -> Option<AffineCurve> {
        let Some(fast) = fast_affine_curve(a, b, chart) else {
            self.declined += 1;
            return None;
        };
        self.fast += 1;
        match full(a, b, chart) {
            Ok(slow) if slow == fast => {}
            Ok(slow) => self
                .failures
                .push(format!("{id}: fast {fast:?}\n  full {slow:?}")),
            Err(e) => self
                .failures
                .push(format!("{id}: fast answered, full: {e}")),
        }
        if chart.is_default() {
            // the view uses the fast answer
            let view = affine_view(Some(a), Some(b), chart, [false, false]);
            if view.curve.as_ref().ok() != Some(&fast) {
                self.failures
                    .push(format!("{id}: the view does not use it"));
            }
        }
        Some(fast)
    }
}

/// A random invertible affine map `[[M, t], [0, 1]]`: `M` a product of integer shears and
/// a diagonal scaling by 1, 2 or 3 (so `det M ≠ 0`), `t` small.
fn affine_map(rng: &mut SplitMix) -> [[RBig; 4]; 4] {
    let mut m = [[0i64; 4]; 4];
    m[3][3] = 1;
    for i in 0..3 {
        m[i][i] = rng.int(1, 3);
    }
    for _ in 0..4 {
        let (i, j) = (rng.int(0, 2) as usize, rng.int(0, 2) as usize);
        if i != j {
            let k = rng.int(-2, 2);
            for c in 0..3 {
                m[i][c] += k * m[j][c];
            }
        }
    }
    for i in 0..3 {
        m[i][3] = rng.int(-3, 3);
    }
    m.map(|r| r.map(RBig::from))
}

fn random_symmetric(rng: &mut SplitMix) -> Option<Quadric> {
    let mut m = [[0i64; 4]; 4];
    for i in 0..4 {
        for j in i..4 {
            let v = rng.int(-9, 9);
            m[i][j] = v;
            m[j][i] = v;
        }
    }
    Quadric::from_matrix(m.map(|r| r.map(RBig::from))).ok()
}

/// `(X − c)ᵀQ(X − c) = r` with `Q = MᵀM + I`.
fn random_ellipsoid(rng: &mut SplitMix) -> Quadric {
    let mm: [[i64; 3]; 3] = std::array::from_fn(|_| std::array::from_fn(|_| rng.int(-2, 2)));
    let q: [[i64; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            (0..3).map(|k| mm[k][i] * mm[k][j]).sum::<i64>() + i64::from(i == j)
        })
    });
    let c: [i64; 3] = std::array::from_fn(|_| rng.int(-3, 3));
    let qc: [i64; 3] = std::array::from_fn(|i| (0..3).map(|j| q[i][j] * c[j]).sum());
    let mut m = [[0i64; 4]; 4];
    for i in 0..3 {
        for j in 0..3 {
            m[i][j] = q[i][j];
        }
        m[i][3] = -qc[i];
        m[3][i] = -qc[i];
    }
    m[3][3] = (0..3).map(|i| c[i] * qc[i]).sum::<i64>() - rng.int(1, 9);
    Quadric::from_matrix(m.map(|r| r.map(RBig::from))).unwrap()
}

fn corpus_pairs() -> Vec<(String, Quadric, Quadric)> {
    let root = env!("CARGO_MANIFEST_DIR");
    let files = [
        format!("{root}/tests/data/cases.jsonl"),
        format!("{root}/tests/data/seed_examples.jsonl"),
        format!("{root}/tests/data/qi-quadrics.jsonl"),
        format!("{root}/../qsic-cli/tests/data/affine.jsonl"),
    ];
    let mut out = Vec::new();
    for path in files {
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
        for (i, raw) in text.lines().enumerate() {
            let line: Value = serde_json::from_str(raw).unwrap();
            // moving quadrics (strings in t, matrices of them) and planes are not pairs of
            // quadrics: they do not parse
            let read = |v: &Value| match v {
                Value::String(s) => parse_quadric(s).ok(),
                Value::Array(_) if !v.to_string().contains('t') => Some(read_form(v)),
                _ => None,
            };
            if let (Some(a), Some(b)) = (read(&line["A"]), read(&line["B"])) {
                out.push((format!("{path}:{}", i + 1), a, b));
            }
        }
    }
    out
}

#[test]
fn fast_path_equals_the_full_path_on_every_corpus_line_and_chart() {
    let charts = [[0, 0, 0, 1], [1, 0, 0, 2], [0, 1, 0, 0], [1, 1, 1, 3]]
        .map(|f: [i64; 4]| Chart::new(f.map(RBig::from)).unwrap());
    let mut tally = Tally::default();
    let pairs = corpus_pairs();
    assert!(pairs.len() > 300, "{} corpus pairs", pairs.len());
    for (id, a, b) in &pairs {
        for (k, chart) in charts.iter().enumerate() {
            tally.compare(&format!("{id} chart {k}"), a, b, chart);
        }
    }
    assert!(tally.failures.is_empty(), "{}", tally.failures.join("\n"));
    eprintln!("corpus: {} fast, {} declined", tally.fast, tally.declined);
    assert!(tally.fast >= 100, "only {} fast answers", tally.fast);
}

#[test]
fn fast_path_equals_the_full_path_on_random_and_disguised_pairs() {
    let mut rng = SplitMix(0xaff1_5eed);
    let chart = Chart::default();
    let mut tally = Tally::default();
    let mut cases = [0usize; 5];
    for n in 0..260 {
        let (a, b) = if n % 4 == 3 {
            (random_ellipsoid(&mut rng), random_ellipsoid(&mut rng))
        } else {
            match (random_symmetric(&mut rng), random_symmetric(&mut rng)) {
                (Some(a), Some(b)) => (a, b),
                _ => continue,
            }
        };
        let Some(fast) = tally.compare(&format!("random {n}"), &a, &b, &chart) else {
            if qsic::classify(&a, &b).case == Some(1) {
                declined_case_1(&mut tally, n, &a, &b, &mut rng);
            }
            continue;
        };
        if let Some(case) = qsic::classify(&a, &b).case {
            cases[usize::from(case.min(4))] += 1;
        }
        // an affine image: the same answer, fast, and the full path agrees (every other pair)
        let t = affine_map(&mut rng);
        let (a2, b2) = (moved(&a, &t), moved(&b, &t));
        let id = format!("random {n} disguised");
        let again = if n % 2 == 0 {
            tally.compare(&id, &a2, &b2, &chart)
        } else {
            fast_affine_curve(&a2, &b2, &chart)
        };
        if again.as_ref() != Some(&fast) {
            tally
                .failures
                .push(format!("{id}: {fast:?} became {again:?}"));
        }
    }
    assert!(tally.failures.is_empty(), "{}", tally.failures.join("\n"));
    eprintln!(
        "random: {} fast, {} declined ({} of case 1 checked by shape); cases 1..4 answered: {:?}",
        tally.fast,
        tally.declined,
        tally.slow_case_1,
        &cases[1..]
    );
    assert!(
        tally.slow_case_1 >= 3,
        "{} declined case 1 pairs",
        tally.slow_case_1
    );
    // every case of a nonsingular quartic is met and most pairs take the fast path
    assert!(cases[1..].iter().all(|&n| n > 0), "{cases:?}");
    assert!(tally.fast * 10 >= (tally.fast + tally.declined) * 8);
}

/// Where the fast path declines (case 1, points at infinity that may lie on either oval),
/// the full path's answer still has the shape parity allows — every point at infinity ends
/// two unbounded arcs' worth of one oval: `curves_unbounded = points_at_infinity` = the real
/// common points of the conics at infinity, at most one oval missing the plane — and an
/// affine image gives the same answer.
fn declined_case_1(tally: &mut Tally, n: usize, a: &Quadric, b: &Quadric, rng: &mut SplitMix) {
    let chart = Chart::default();
    let block = |q: &Quadric| -> [[RBig; 3]; 3] {
        std::array::from_fn(|i| std::array::from_fn(|j| q.matrix()[i][j].clone()))
    };
    let points = conic_real_intersections(&block(a), &block(b)).map_or(0, |p| p.len());
    let id = format!("random {n} (case 1, full path)");
    match full(a, b, &chart) {
        Ok(c) => {
            let shape = c.curves_unbounded == points
                && c.points_at_infinity == points
                && points >= 2
                && c.curves_bounded <= 1
                && c.isolated_points + c.singular_finite + c.singular_at_infinity == 0;
            if !shape {
                tally
                    .failures
                    .push(format!("{id}: {c:?} with {points} points"));
            }
            let t = affine_map(rng);
            let again = full(&moved(a, &t), &moved(b, &t), &chart);
            if again.as_ref().ok() != Some(&c) {
                tally.failures.push(format!("{id}: {c:?} became {again:?}"));
            }
            tally.slow_case_1 += 1;
        }
        Err(e) => tally.failures.push(format!("{id}: {e}")),
    }
}

/// A line `ax + by + cz = 0` as a row.
fn line(l: [i64; 3]) -> [RBig; 3] {
    l.map(RBig::from)
}

/// The symmetric matrix of the product of two lines.
fn product(l: &[RBig; 3], m: &[RBig; 3]) -> [[RBig; 3]; 3] {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| (&l[i] * &m[j] + &l[j] * &m[i]) / RBig::from(2))
    })
}

/// `TᵀCT`.
fn transformed(c: &[[RBig; 3]; 3], t: &[[RBig; 3]; 3]) -> [[RBig; 3]; 3] {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let mut acc = RBig::ZERO;
            for k in 0..3 {
                for l in 0..3 {
                    acc += &t[k][i] * &c[k][l] * &t[l][j];
                }
            }
            acc
        })
    })
}

/// The circle `x² + y² = z²` and a member `s·circle + t·L·M` of the pencil through its
/// common points with a line pair `L·M`: each line secant (two simple points), tangent (one
/// double point) or missing it (a conjugate pair), so the real common points and their
/// multiplicities are known; seen through a random invertible projective map.
#[test]
fn conic_intersections_known_by_construction() {
    let mut rng = SplitMix(0xc0_1c);
    let circle: [[RBig; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| RBig::from(i64::from(i == j) * if i == 2 { -1 } else { 1 }))
    });
    // (line, its points on the circle as multiplicities)
    let secants = [
        [1, 0, 0],
        [0, 1, 0],
        [1, 1, 1],
        [2, -1, 1],
        [1, 3, -2],
        [3, 1, 2],
    ];
    let tangents = [[1, 0, 1], [0, 1, -1], [3, 4, 5], [5, -12, 13], [4, 3, -5]];
    let missing = [[0, 0, 1], [1, 1, 3], [1, -2, 4], [2, 1, -5]];
    let pick = |rng: &mut SplitMix, kind: i64| -> ([RBig; 3], Vec<usize>) {
        match kind {
            0 => (line(secants[rng.int(0, 5) as usize]), vec![1, 1]),
            1 => (line(tangents[rng.int(0, 4) as usize]), vec![2]),
            _ => (line(missing[rng.int(0, 3) as usize]), vec![]),
        }
    };
    let mut checked = 0;
    for _ in 0..200 {
        let (kl, km) = (rng.int(0, 2), rng.int(0, 2));
        let (l, pl) = pick(&mut rng, kl);
        let (m, pm) = pick(&mut rng, km);
        // the lines must not meet on the circle (a merged point) nor coincide
        let meet = [
            &l[1] * &m[2] - &l[2] * &m[1],
            &l[2] * &m[0] - &l[0] * &m[2],
            &l[0] * &m[1] - &l[1] * &m[0],
        ];
        let on_circle = &meet[0] * &meet[0] + &meet[1] * &meet[1] == &meet[2] * &meet[2];
        let mut expected: Vec<usize> = pl.iter().chain(&pm).copied().collect();
        if meet.iter().all(|v| *v == RBig::ZERO) {
            // L = M: every point doubled
            expected = pl.iter().map(|k| 2 * k).collect();
        } else if on_circle {
            continue;
        }
        expected.sort_unstable();
        let lm = product(&l, &m);
        let (s, t) = (
            rng.int(-3, 3),
            rng.int(1, 3) * if rng.int(0, 1) == 0 { 1 } else { -1 },
        );
        let member: [[RBig; 3]; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|j| RBig::from(s) * &circle[i][j] + RBig::from(t) * &lm[i][j])
        });
        // a random invertible map: shears and a permutation-free scaling
        let mut tm: [[i64; 3]; 3] =
            std::array::from_fn(|i| std::array::from_fn(|j| i64::from(i == j) * rng.int(1, 2)));
        for _ in 0..4 {
            let (i, j) = (rng.int(0, 2) as usize, rng.int(0, 2) as usize);
            if i != j {
                let k = rng.int(-3, 3);
                for c in 0..3 {
                    tm[i][c] += k * tm[j][c];
                }
            }
        }
        let tm = tm.map(|r| r.map(RBig::from));
        let (c1, c2) = (transformed(&circle, &tm), transformed(&member, &tm));
        let (got, swapped) = (
            conic_real_intersections(&c1, &c2),
            conic_real_intersections(&c2, &c1),
        );
        assert_eq!(
            got.as_ref(),
            Some(&expected),
            "lines {l:?} {m:?}, member {s}, {t}"
        );
        assert_eq!(swapped, got);
        checked += 1;
    }
    assert!(checked >= 150, "{checked}");
}
