//! Every quadric of the test corpora is read, and reads back from its own printout.
//!
//! `qi-quadrics.jsonl` gives quadrics as polynomial strings (the QI test file),
//! `cases.jsonl` and `seed_examples.jsonl` as 4×4 matrices of number strings.

use qsic::error::Error;
use qsic::io::{parse_quadric, quadric_from_rows};
use serde_json::Value;

/// The records of a JSON-lines file in `tests/data`, with their 1-based line numbers.
fn records(name: &str) -> Vec<(usize, Value)> {
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    text.lines()
        .enumerate()
        .filter(|(_, line)| !line.trim().is_empty())
        .map(|(i, line)| {
            let value = serde_json::from_str(line)
                .unwrap_or_else(|e| panic!("{name}:{}: bad JSON: {e}", i + 1));
            (i + 1, value)
        })
        .collect()
}

/// The signed terms of a polynomial string, without spaces or leading `+`, sorted:
/// `"x^2 - 2*x*y"` gives `["-2*x*y", "x^2"]`.
fn sorted_terms(text: &str) -> Vec<String> {
    let mut terms = Vec::new();
    let mut current = String::new();
    for c in text.chars().filter(|c| !c.is_whitespace()) {
        if (c == '+' || c == '-') && !current.is_empty() {
            terms.push(std::mem::take(&mut current));
        }
        if c != '+' {
            current.push(c);
        }
    }
    terms.push(current);
    terms.sort();
    terms
}

#[test]
fn qi_polynomial_strings_parse() {
    let mut count = 0;
    for (line, record) in records("qi-quadrics.jsonl") {
        let id = record["id"].as_str().unwrap_or("?");
        let expect_error = record["expect_error"].as_bool().unwrap_or(false);
        let mut refused = false;
        for key in ["A", "B"] {
            let text = record[key].as_str().unwrap_or_else(|| {
                panic!("qi-quadrics.jsonl:{line} ({id}): {key} is not a string")
            });
            let parsed = parse_quadric(text);
            // "0" stands for "no quadric" in the QI file (a single quadric, or the universe).
            if text.trim() == "0" {
                refused = true;
                assert_eq!(
                    parsed,
                    Err(Error::ZeroQuadric),
                    "qi-quadrics.jsonl:{line} ({id}): {key} = {text:?}"
                );
                continue;
            }
            let q = parsed.unwrap_or_else(|e| {
                panic!("qi-quadrics.jsonl:{line} ({id}): {key} = {text:?}: {e}")
            });
            // The corpus is written term by term with integer coefficients, so the
            // printout must have exactly the same terms.
            let printed = q.to_polynomial_string();
            assert_eq!(
                sorted_terms(&printed),
                sorted_terms(text),
                "qi-quadrics.jsonl:{line} ({id}): {key} = {text:?} printed as {printed:?}"
            );
            assert_eq!(
                parse_quadric(&printed).as_ref(),
                Ok(&q),
                "qi-quadrics.jsonl:{line} ({id}): {key} printed as {printed:?}"
            );
            count += 1;
        }
        assert!(
            refused || !expect_error,
            "qi-quadrics.jsonl:{line} ({id}): expected an error"
        );
    }
    assert!(count >= 200, "only {count} quadrics read");
}

#[test]
fn matrix_corpora_parse_and_round_trip() {
    for name in ["cases.jsonl", "seed_examples.jsonl"] {
        for (line, record) in records(name) {
            let id = record["id"].as_str().unwrap_or("?");
            for key in ["A", "B"] {
                let rows: Vec<Vec<String>> = serde_json::from_value(record[key].clone())
                    .unwrap_or_else(|e| panic!("{name}:{line} ({id}): {key}: {e}"));
                let q = quadric_from_rows(&rows)
                    .unwrap_or_else(|e| panic!("{name}:{line} ({id}): {key}: {e}"));
                let printed = q.to_polynomial_string();
                assert_eq!(
                    parse_quadric(&printed).as_ref(),
                    Ok(&q),
                    "{name}:{line} ({id}): {key} printed as {printed:?}"
                );
            }
        }
    }
}
