//! Every labelled pair of the shared corpora (copied to tests/data with their provenance in
//! each line's `source`) is classified and checked against its labels.

use qsic::io::{parse_quadric, quadric_from_rows};
use qsic::{classify_allowing_zero, Classification, Error, Quadric};
use serde_json::Value;

fn read_form(v: &Value) -> Result<Option<Quadric>, Error> {
    let parsed = match v {
        Value::String(s) => parse_quadric(s),
        Value::Array(rows) => {
            let rows: Vec<Vec<String>> = rows
                .iter()
                .map(|r| {
                    r.as_array()
                        .map(|r| {
                            r.iter()
                                .map(|x| x.as_str().map_or_else(|| x.to_string(), str::to_owned))
                                .collect()
                        })
                        .unwrap_or_default()
                })
                .collect();
            quadric_from_rows(&rows)
        }
        _ => panic!("unexpected quadric value {v}"),
    };
    match parsed {
        Err(Error::ZeroQuadric) => Ok(None),
        other => other.map(Some),
    }
}

fn classify_line(line: &Value) -> Result<Classification, Error> {
    let a = read_form(&line["A"])?;
    let b = read_form(&line["B"])?;
    classify_allowing_zero(a.as_ref(), b.as_ref())
}

/// Checks every line; returns the number of lines checked and of the printed notations
/// (Segre characteristic, signature and index sequence) compared.
fn check_file(name: &str, check_singular_types: bool) -> (usize, usize) {
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut failures = Vec::new();
    let (mut n, mut notations) = (0, 0);
    for (i, raw) in text.lines().enumerate() {
        let line: Value =
            serde_json::from_str(raw).unwrap_or_else(|e| panic!("{name}:{}: {e}", i + 1));
        let id = line["id"].as_str().unwrap_or("?").to_owned();
        n += 1;
        let result = classify_line(&line);
        if line["expect_error"].as_bool() == Some(true) {
            if result.is_ok() {
                failures.push(format!("{name}:{} {id}: expected an error", i + 1));
            }
            continue;
        }
        let c = match result {
            Ok(c) => c,
            Err(e) => {
                failures.push(format!("{name}:{} {id}: error {e}", i + 1));
                continue;
            }
        };
        let want_pencil = line["pencil"].as_str().unwrap_or("?");
        let mut wrong = Vec::new();
        if c.pencil.key() != want_pencil {
            wrong.push(format!("pencil {} != {want_pencil}", c.pencil.key()));
        }
        if want_pencil == "regular" {
            let want_case = line["case"].as_u64().map(|v| v as u8);
            if c.case != want_case {
                wrong.push(format!("case {:?} != {want_case:?}", c.case));
            }
            // Both print the class's representative from the paper's tables.
            let printed = [
                ("segre", c.segre),
                ("signature", c.signature),
                ("index_sequence", c.index_sequence),
            ];
            for (field, got) in printed {
                if let Some(want) = line[field].as_str() {
                    notations += 1;
                    if got != Some(want) {
                        wrong.push(format!("{field} {got:?} != {want}"));
                    }
                }
            }
        }
        if want_pencil != "singular" || check_singular_types {
            let ct = line["complex_type"].as_str();
            let rt = line["real_type"].as_str();
            if c.complex_type() != ct {
                wrong.push(format!("complex_type {:?} != {ct:?}", c.complex_type()));
            }
            if c.real_type() != rt {
                wrong.push(format!("real_type {:?} != {rt:?}", c.real_type()));
            }
        }
        if !wrong.is_empty() {
            failures.push(format!("{name}:{} {id}: {}", i + 1, wrong.join("; ")));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {n} lines wrong:\n{}",
        failures.len(),
        failures.join("\n")
    );
    (n, notations)
}

#[test]
fn cases_jsonl_all_35_cases_and_disguises() {
    assert_eq!(check_file("cases.jsonl", true), (211, 3 * 211));
}

#[test]
fn seed_examples_of_the_papers() {
    assert_eq!(check_file("seed_examples.jsonl", true), (23, 3 * 23));
}

#[test]
fn qi_test_file_regular_singular_and_single() {
    // QI's labels name types and cases, not the notations
    assert_eq!(check_file("qi-quadrics.jsonl", true), (121, 0));
}
