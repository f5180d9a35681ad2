//! Benchmark inputs shared by the criterion benches and the `random_pairs` example:
//! a deterministic generator and the input families named in the README.

#![allow(dead_code, clippy::needless_range_loop)]

use qsic::io::quadric_from_rows;
use qsic::Quadric;

/// splitmix64: a deterministic generator, enough for benchmark inputs.
pub struct SplitMix(pub u64);

impl SplitMix {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [lo, hi].
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next_u64() % (hi - lo + 1) as u64) as i64
    }
}

/// A random quadric whose 10 polynomial coefficients are integers in [−10, 10]
/// (matrix: 2× the coefficient on the diagonal, the coefficient off it).
pub fn random_quadric(rng: &mut SplitMix) -> Quadric {
    loop {
        let mut m = [[0i64; 4]; 4];
        for i in 0..4 {
            for j in i..4 {
                let c = rng.range(-10, 10);
                if i == j {
                    m[i][i] = 2 * c;
                } else {
                    m[i][j] = c;
                    m[j][i] = c;
                }
            }
        }
        if let Ok(q) = Quadric::from_integers(m) {
            return q;
        }
    }
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
