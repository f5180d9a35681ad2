//! Helpers shared by the integration tests that read the labelled corpora.

use qsic::io::{parse_quadric, quadric_from_rows};
use qsic::Quadric;
use serde_json::Value;

/// The quadric of a corpus field: a polynomial string, or a 4×4 array of numbers and number
/// strings; panics on anything else (the corpora are known good).
pub fn read_form(v: &Value) -> Quadric {
    match v {
        Value::String(s) => parse_quadric(s).unwrap(),
        Value::Array(rows) => {
            let rows: Vec<Vec<String>> = rows
                .iter()
                .map(|r| {
                    r.as_array()
                        .unwrap()
                        .iter()
                        .map(|x| x.as_str().map_or_else(|| x.to_string(), str::to_owned))
                        .collect()
                })
                .collect();
            quadric_from_rows(&rows).unwrap()
        }
        _ => panic!("unexpected quadric value {v}"),
    }
}
