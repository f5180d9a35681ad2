//! `docs/taxonomy.md` runs: every example pair of its class tables is classified and must give
//! the keys of its row, and every affine example must get its name (a conic type: a component
//! of that type), so the document cannot drift from the code.

use qsic::affine::{affine_conic, surface_name, Chart};
use qsic::classify_allowing_zero;
use qsic::io::parse_quadric;

/// The cells of the table rows of `text` (lines starting with `|`, separator rows dropped),
/// with surrounding backticks removed.
fn rows(text: &str) -> Vec<Vec<String>> {
    text.lines()
        .filter(|l| l.starts_with('|') && !l.starts_with("|---"))
        .map(|l| {
            l.trim_matches('|')
                .split('|')
                .map(|c| c.trim().trim_matches('`').to_owned())
                .collect()
        })
        .collect()
}

fn quadric(s: &str) -> Option<qsic::Quadric> {
    (s != "0").then(|| parse_quadric(s).unwrap_or_else(|e| panic!("{s}: {e}")))
}

#[test]
fn every_example_of_the_taxonomy_gives_its_keys() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/taxonomy.md");
    let text = std::fs::read_to_string(path).unwrap();
    let (mut classes, mut names, mut conics) = (0, 0, 0);
    let mut cases = Vec::new();
    for row in rows(&text) {
        match row.len() {
            6 if row[0] != "case" => {
                let (a, b) = (quadric(&row[4]), quadric(&row[5]));
                let c = classify_allowing_zero(a.as_ref(), b.as_ref()).unwrap();
                let got = (c.complex_type().unwrap(), c.real_type().unwrap());
                assert_eq!(got, (row[1].as_str(), row[2].as_str()), "{row:?}");
                match row[0].parse::<u8>() {
                    Ok(case) => {
                        assert_eq!(c.case, Some(case), "{row:?}");
                        cases.push(case);
                    }
                    Err(_) => assert_eq!(c.case, None, "{row:?}"),
                }
                classes += 1;
            }
            3 if row[0] != "name" => {
                let q = parse_quadric(&row[2]).unwrap();
                assert_eq!(surface_name(&q, &Chart::default()).key(), row[0], "{row:?}");
                names += 1;
            }
            4 if row[0] != "type" => {
                let (a, b) = (
                    parse_quadric(&row[2]).unwrap(),
                    parse_quadric(&row[3]).unwrap(),
                );
                let curve = qsic::param::parameterize(&a, &b).unwrap();
                let keys: Vec<&str> = curve
                    .components
                    .iter()
                    .filter_map(|c| affine_conic(c, &Chart::default()).unwrap())
                    .map(|c| c.shape.key())
                    .collect();
                assert!(keys.contains(&row[0].as_str()), "{row:?}: {keys:?}");
                conics += 1;
            }
            _ => {}
        }
    }
    assert_eq!(conics, 5);
    cases.sort_unstable();
    assert_eq!(cases, (1..=35).collect::<Vec<u8>>(), "every case once");
    assert_eq!((classes, names), (35 + 13 + 8, 20));
}
