//! The machine-arithmetic ingest equals the general (big-rational) route: on every quadric
//! of the corpora in `tests/data` (copies of `shared/corpus`) and on random texts, the
//! resulting quadric — its primitive integer matrix, fast-path matrix and rational matrix —
//! or the error is the same.

#![allow(clippy::needless_range_loop)]

use proptest::prelude::*;
use qsic::io::{
    parse_quadric, parse_quadric_big_route, quadric_from_rows, quadric_from_rows_big_route,
};
use qsic::{Error, Quadric};
use serde_json::Value;

/// Asserts that two results are the same quadric in every view, or the same error.
fn assert_same(fast: Result<Quadric, Error>, big: Result<Quadric, Error>, what: &str) {
    match (&fast, &big) {
        (Ok(f), Ok(b)) => {
            assert_eq!(f, b, "{what}");
            assert_eq!(f.integer_matrix(), b.integer_matrix(), "{what}");
            assert_eq!(f.small_integer_matrix(), b.small_integer_matrix(), "{what}");
            assert_eq!(f.matrix(), b.matrix(), "{what}");
        }
        _ => assert_eq!(fast, big, "{what}"),
    }
}

/// The entries of a JSON 4×4 matrix as texts (numbers as written, strings as they are).
fn matrix_texts(value: &Value) -> Option<Vec<Vec<String>>> {
    value
        .as_array()?
        .iter()
        .map(|row| {
            row.as_array()?
                .iter()
                .map(|v| match v {
                    Value::String(s) => Some(s.clone()),
                    Value::Number(n) => Some(n.to_string()),
                    _ => None,
                })
                .collect()
        })
        .collect()
}

#[test]
fn every_corpus_quadric_reads_the_same_by_both_routes() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .expect("tests/data is readable")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "jsonl"))
        .collect();
    files.sort();
    let (mut strings, mut matrices) = (0, 0);
    for path in &files {
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned());
        let name = name.unwrap_or_default();
        let text = std::fs::read_to_string(path).expect("corpus file is readable");
        for (i, line) in text
            .lines()
            .enumerate()
            .filter(|(_, l)| !l.trim().is_empty())
        {
            let record: Value = serde_json::from_str(line)
                .unwrap_or_else(|e| panic!("{name}:{}: bad JSON: {e}", i + 1));
            for key in ["A", "B"] {
                let what = format!("{name}:{} {key}", i + 1);
                match &record[key] {
                    Value::String(s) => {
                        assert_same(parse_quadric(s), parse_quadric_big_route(s), &what);
                        strings += 1;
                    }
                    v => {
                        let rows = matrix_texts(v)
                            .unwrap_or_else(|| panic!("{what}: not a matrix of numbers"));
                        assert_same(
                            quadric_from_rows(&rows),
                            quadric_from_rows_big_route(&rows),
                            &what,
                        );
                        matrices += 1;
                    }
                }
            }
        }
    }
    assert!(files.len() >= 4, "{files:?}");
    assert!(
        strings >= 200 && matrices >= 400,
        "{strings} strings, {matrices} matrices"
    );
}

/// Number texts of every form the readers take: small integers, 30-digit integers, `p/q`,
/// decimals, scientific notation, with signs and spaces, and a few non-numbers.
fn number_text() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => (-12i64..13).prop_map(|v| v.to_string()),
        2 => (-99i64..100, 0u64..13).prop_map(|(p, q)| format!("{p}/{q}")),
        2 => (-999i64..1000, 0usize..4).prop_map(|(v, k)| {
            let s = format!("{:0>4}", v.unsigned_abs());
            let sign = if v < 0 { "-" } else { "" };
            format!("{sign}{}.{}", &s[..4 - k], &s[4 - k..])
        }),
        2 => (-99i64..100, -25i32..25).prop_map(|(m, e)| format!("{m}e{e}")),
        1 => "[+-]?[0-9]{28,31}",
        1 => "[+-]?[0-9]{1,20}(\\.[0-9]{0,12})?([eE][+-]?[0-9]{1,2})? ?(/ ?[0-9]{1,20}(\\.[0-9]{1,3})?)?",
        1 => "[ 0-9./eE+-]{0,8}",
    ]
}

/// A 4×4 matrix of number texts, symmetric unless `skew`.
fn matrix_of(entries: [String; 16], skew: bool) -> Vec<Vec<String>> {
    let mut rows: Vec<Vec<String>> = entries.chunks(4).map(|r| r.to_vec()).collect();
    if !skew {
        for i in 0..4 {
            for j in 0..i {
                rows[i][j] = rows[j][i].clone();
            }
        }
    }
    rows
}

/// Polynomial texts: sums of terms with coefficients from [`number_text`] and monomials
/// in several spellings, sometimes with parentheses, powers of numbers, or errors.
fn polynomial_text() -> impl Strategy<Value = String> {
    let monomial = prop_oneof![
        Just(String::new()),
        "[xyzw]",
        "[xyzw]\\^[0-3]",
        "[xyzw] ?\\*\\*2",
        "[xyzw]\\*[xyzw]",
        "[xyzw] [xyzw]",
        "[xyzw]/[0-9]",
        "\\((x|y)[+-][zw0-9]\\)\\^2",
        "[xyzwq]2?",
    ];
    let term = (
        "[ +-]{0,2}",
        prop_oneof![Just(String::new()), number_text()],
        prop_oneof![Just("*"), Just(""), Just(" "), Just("/2*")],
        monomial,
    )
        .prop_map(|(sign, c, op, m)| {
            if c.is_empty() || m.is_empty() {
                format!("{sign}{c}{m}")
            } else {
                format!("{sign}{c}{op}{m}")
            }
        });
    prop::collection::vec(term, 1..8).prop_map(|terms| terms.join(" + "))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn random_number_matrices_read_the_same_by_both_routes(
        entries in prop::array::uniform16(number_text()),
        skew in prop::bool::weighted(0.1),
    ) {
        let rows = matrix_of(entries, skew);
        assert_same(quadric_from_rows(&rows), quadric_from_rows_big_route(&rows), &format!("{rows:?}"));
    }

    #[test]
    fn small_number_matrices_read_the_same_by_both_routes(
        entries in prop::array::uniform16(prop_oneof![
            (-12i64..13).prop_map(|v| v.to_string()),
            (-99i64..100, 1u64..13).prop_map(|(p, q)| format!("{p}/{q}")),
            (-99i64..100, -3i32..3).prop_map(|(m, e)| format!("{m}e{e}")),
        ]),
    ) {
        let rows = matrix_of(entries, false);
        assert_same(quadric_from_rows(&rows), quadric_from_rows_big_route(&rows), &format!("{rows:?}"));
    }

    #[test]
    fn random_polynomials_read_the_same_by_both_routes(text in polynomial_text()) {
        assert_same(parse_quadric(&text), parse_quadric_big_route(&text), &text);
    }
}
