//! Benchmark inputs shared by the criterion benches and the `random_pairs` example:
//! a deterministic generator and the input families named in the README.

#![allow(dead_code, clippy::needless_range_loop)]

use qsic::io::quadric_from_rows;
use qsic::Quadric;

pub use qsic_algebra::testing::SplitMix;

/// A random quadric whose 10 polynomial coefficients are integers in [−10, 10]
/// (matrix: 2× the coefficient on the diagonal, the coefficient off it).
pub fn random_quadric(rng: &mut SplitMix) -> Quadric {
    Quadric::from_integers(random_integer_matrix(rng)).expect("a nonzero symmetric matrix")
}

/// `n` pairs of [`random_quadric`]s, drawn in order.
pub fn random_pairs(rng: &mut SplitMix, n: usize) -> Vec<(Quadric, Quadric)> {
    (0..n)
        .map(|_| (random_quadric(rng), random_quadric(rng)))
        .collect()
}

/// The first `n` pairs of cases 1–4 (a nonsingular quartic) among the random pairs of
/// `SplitMix(42)`: the curve benchmarks' family (`param_cost`, `param_spread`).
pub fn generic_pairs(n: usize) -> Vec<(Quadric, Quadric)> {
    let mut rng = SplitMix(42);
    random_pairs(&mut rng, 8 * n)
        .into_iter()
        .filter(|(a, b)| matches!(qsic::classify(a, b).case, Some(1..=4)))
        .take(n)
        .collect()
}

/// The pairs of `cases.jsonl` whose id matches `filter`, with their labelled case.
pub fn corpus_pairs(filter: impl Fn(&str) -> bool) -> Vec<(String, Quadric, Quadric)> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/cases.jsonl");
    let text = std::fs::read_to_string(path).expect("cases.jsonl is in the repository");
    let mut out = Vec::new();
    for line in text.lines() {
        let v: serde_json::Value = serde_json::from_str(line).expect("valid json");
        let id = v["id"].as_str().unwrap_or_default().to_owned();
        if !filter(&id) {
            continue;
        }
        let read = |m: &serde_json::Value| -> Quadric {
            let rows: Vec<Vec<String>> = m
                .as_array()
                .expect("matrix")
                .iter()
                .map(|r| {
                    r.as_array()
                        .expect("row")
                        .iter()
                        .map(|x| x.as_str().unwrap_or("0").to_owned())
                        .collect()
                })
                .collect();
            quadric_from_rows(&rows).expect("valid corpus matrix")
        };
        out.push((id, read(&v["A"]), read(&v["B"])));
    }
    out
}

/// The representatives of the 36 classes, with the case their id names (`pub-cNN-rep…`).
pub fn representatives() -> Vec<(String, Quadric, Quadric, u8)> {
    corpus_pairs(|id| id.ends_with("-rep") || id.ends_with("-rep-alt"))
        .into_iter()
        .map(|(id, a, b)| {
            let case = id[5..7].parse().expect("ids are pub-cNN-…");
            (id, a, b, case)
        })
        .collect()
}

/// The singular pairs of `qi-quadrics.jsonl` (polynomial strings).
pub fn qi_singular_pairs() -> Vec<(Quadric, Quadric)> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/qi-quadrics.jsonl");
    let text = std::fs::read_to_string(path).expect("qi-quadrics.jsonl is in the repository");
    text.lines()
        .map(|l| serde_json::from_str::<serde_json::Value>(l).expect("valid json"))
        .filter(|v| v["pencil"] == "singular")
        .filter_map(|v| {
            let a = qsic::io::parse_quadric(v["A"].as_str()?).ok()?;
            let b = qsic::io::parse_quadric(v["B"].as_str()?).ok()?;
            Some((a, b))
        })
        .collect()
}

/// A symmetric 4×4 JSON array of number strings `p/q`, `p` in [−10, 10], `q` in [1, 4]
/// (written `p` when `q` is 1); never all zero.
pub fn random_rational_rows_json(rng: &mut SplitMix) -> String {
    random_rational_rows_json_in(rng, 10, 4)
}

/// [`random_rational_rows_json`] with `p` in [−p_max, p_max] and `q` in [1, q_max].
pub fn random_rational_rows_json_in(rng: &mut SplitMix, p_max: i64, q_max: i64) -> String {
    loop {
        let mut m = [[(0i64, 1i64); 4]; 4];
        for i in 0..4 {
            for j in i..4 {
                let v = (rng.int(-p_max, p_max), rng.int(1, q_max));
                m[i][j] = v;
                m[j][i] = v;
            }
        }
        if m.iter().flatten().all(|&(p, _)| p == 0) {
            continue;
        }
        let rows: Vec<String> = m
            .iter()
            .map(|row| {
                let entries: Vec<String> = row
                    .iter()
                    .map(|&(p, q)| {
                        if q == 1 {
                            format!("\"{p}\"")
                        } else {
                            format!("\"{p}/{q}\"")
                        }
                    })
                    .collect();
                format!("[{}]", entries.join(", "))
            })
            .collect();
        return format!("[{}]", rows.join(", "));
    }
}

/// A polynomial string in x, y, z, w whose ten coefficients are integers in [−10, 10],
/// zero terms left out, e.g. `3*x^2 - 7*x*y + w^2`; never the zero polynomial.
pub fn random_polynomial_text(rng: &mut SplitMix) -> String {
    random_polynomial_text_over(rng, 1)
}

/// [`random_polynomial_text`] with coefficients `c/q`, `q` in [1, q_max] (written `c` when
/// `q` is 1), e.g. `-9/4*x^2 + x*y`.
pub fn random_polynomial_text_over(rng: &mut SplitMix, q_max: i64) -> String {
    const MONOMIALS: [&str; 10] = [
        "x^2", "x*y", "x*z", "x*w", "y^2", "y*z", "y*w", "z^2", "z*w", "w^2",
    ];
    loop {
        let mut text = String::new();
        for mono in MONOMIALS {
            let c = rng.int(-10, 10);
            if c == 0 {
                continue;
            }
            let sign = if c < 0 { "-" } else { "+" };
            if text.is_empty() {
                if c < 0 {
                    text.push('-');
                }
            } else {
                text.push_str(&format!(" {sign} "));
            }
            let q = rng.int(1, q_max);
            if q != 1 {
                text.push_str(&format!("{}/{q}*", c.abs()));
            } else if c.abs() != 1 {
                text.push_str(&format!("{}*", c.abs()));
            }
            text.push_str(mono);
        }
        if !text.is_empty() {
            return text;
        }
    }
}

/// A random symmetric integer matrix of the `random_small` family: 2× the coefficient on
/// the diagonal, the coefficient off it, coefficients in [−10, 10]; never zero.
pub fn random_integer_matrix(rng: &mut SplitMix) -> [[i64; 4]; 4] {
    loop {
        let mut m = [[0i64; 4]; 4];
        for i in 0..4 {
            for j in i..4 {
                let c = rng.int(-10, 10);
                if i == j {
                    m[i][i] = 2 * c;
                } else {
                    m[i][j] = c;
                    m[j][i] = c;
                }
            }
        }
        if m.iter().flatten().any(|&v| v != 0) {
            return m;
        }
    }
}
