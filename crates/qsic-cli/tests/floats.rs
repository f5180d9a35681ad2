//! `--floats`: the three readings of JSON floats in a matrix, on a sphere that touches the
//! plane z = 3/5 exactly when its centre is (1/10, 1/5, 3/10) and its radius² 9/100 — the
//! matrix written as typed (`0.1`) and as a program printing 17 digits writes it
//! (`0.10000000000000001`).

#[path = "common/run.rs"]
mod run;

use run::qsic;

const TYPED: &str = "[[1,0,0,-0.1],[0,1,0,-0.2],[0,0,1,-0.3],[-0.1,-0.2,-0.3,0.05]]";
const PRINTED: &str = "[[1,0,0,-0.10000000000000001],[0,1,0,-0.20000000000000001],\
[0,0,1,-0.29999999999999999],[-0.10000000000000001,-0.20000000000000001,\
-0.29999999999999999,0.050000000000000003]]";

/// Whether `qsic classify` finds the point of contact.
fn touches(matrix: &str, floats: &str) -> bool {
    let out = qsic(&["classify", "--floats", floats, matrix, "z-0.6"], "");
    assert!(out.status.success(), "{out:?}");
    let text = String::from_utf8(out.stdout).unwrap();
    let first = text.lines().next().unwrap().to_owned();
    match first.as_str() {
        f if f.contains("a multiple point at (1/10, 1/5, 3/5)") => true,
        f if f.contains("no common point") => false,
        f => panic!("{f}"),
    }
}

#[test]
fn each_reading_of_the_same_sphere() {
    // as written: the typed decimals are exact, the 17 digits are not the intended numbers
    assert!(touches(TYPED, "text"));
    assert!(!touches(PRINTED, "text"));
    // shortest: both are the doubles of 0.1, 0.2, 0.3, 0.05, read as those decimals
    assert!(touches(TYPED, "shortest"));
    assert!(touches(PRINTED, "shortest"));
    // binary: the doubles' values, which miss the plane
    assert!(!touches(TYPED, "binary"));
    assert!(!touches(PRINTED, "binary"));
}

#[test]
fn batch_lines_read_their_floats_and_keep_their_ids() {
    let input = format!(
        "{{\"id\": 0.30000000000000004, \"A\": {PRINTED}, \"B\": \"z-0.6\"}}\n\
         {{\"id\": 2, \"A\": [[1e400,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,-1]], \"B\": \"z\"}}\n"
    );
    let out = qsic(
        &["classify", "--batch", "-", "--floats", "shortest"],
        &input,
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<serde_json::Value> = text
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(lines[0]["id"].to_string(), "0.30000000000000004");
    assert_eq!(lines[0]["real_type"], "point", "{text}");
    let message = lines[1]["error"]["message"].as_str().unwrap();
    assert!(
        message.starts_with("A: the number 1e400 is beyond the range of a double"),
        "{message}"
    );
    assert_eq!(out.status.code(), Some(1));
    // the default reads the 17 digits as written: no contact
    let out = qsic(&["classify", "--batch", "-"], &input);
    let text = String::from_utf8(out.stdout).unwrap();
    let first: serde_json::Value = serde_json::from_str(text.lines().next().unwrap()).unwrap();
    assert_eq!(first["real_type"], "empty", "{text}");
}
