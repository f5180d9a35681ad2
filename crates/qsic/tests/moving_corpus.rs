//! Every matrix of `moving.jsonl` (a copy of `shared/corpus`) reads as a moving matrix, and
//! its value at rational instants agrees with each entry string evaluated by a second,
//! independent route: a small evaluator over exact rationals, without polynomials.

use dashu_ratio::RBig;
use qsic::io::{moving_matrix_from_polynomial, moving_matrix_from_rows, MovingMatrix};
use serde_json::Value;

/// The value of `text` (numbers, `t`, `+ - * /`, `**` or `^` with integer exponents,
/// parentheses, unary minus) at `t`, or `None` on a division by zero.
fn evaluate(text: &str, t: &RBig) -> Option<RBig> {
    let chars: Vec<char> = text.chars().filter(|c| !c.is_whitespace()).collect();
    let mut pos = 0;
    let value = sum(&chars, &mut pos, t)?;
    assert_eq!(pos, chars.len(), "{text:?}: unread text");
    Some(value)
}

fn sum(s: &[char], pos: &mut usize, t: &RBig) -> Option<RBig> {
    let mut acc = product(s, pos, t)?;
    while let Some(&op @ ('+' | '-')) = s.get(*pos) {
        *pos += 1;
        let rhs = product(s, pos, t)?;
        acc = if op == '+' { acc + rhs } else { acc - rhs };
    }
    Some(acc)
}

fn product(s: &[char], pos: &mut usize, t: &RBig) -> Option<RBig> {
    let mut acc = unary(s, pos, t)?;
    loop {
        match (s.get(*pos), s.get(*pos + 1)) {
            (Some('*'), Some(c)) if *c != '*' => {
                *pos += 1;
                acc *= unary(s, pos, t)?;
            }
            (Some('/'), _) => {
                *pos += 1;
                let d = unary(s, pos, t)?;
                if d.is_zero() {
                    return None;
                }
                acc /= d;
            }
            _ => return Some(acc),
        }
    }
}

fn unary(s: &[char], pos: &mut usize, t: &RBig) -> Option<RBig> {
    if s.get(*pos) == Some(&'-') {
        *pos += 1;
        return Some(-unary(s, pos, t)?);
    }
    let base = atom(s, pos, t)?;
    let star_star = s.get(*pos) == Some(&'*') && s.get(*pos + 1) == Some(&'*');
    if !star_star && s.get(*pos) != Some(&'^') {
        return Some(base);
    }
    *pos += if star_star { 2 } else { 1 };
    let start = *pos;
    while s.get(*pos).is_some_and(char::is_ascii_digit) {
        *pos += 1;
    }
    let n: isize = s[start..*pos]
        .iter()
        .collect::<String>()
        .parse()
        .expect("an exponent");
    Some(base.pow(n))
}

fn atom(s: &[char], pos: &mut usize, t: &RBig) -> Option<RBig> {
    match s.get(*pos) {
        Some('(') => {
            *pos += 1;
            let v = sum(s, pos, t)?;
            assert_eq!(s.get(*pos), Some(&')'));
            *pos += 1;
            Some(v)
        }
        Some('t') => {
            *pos += 1;
            Some(t.clone())
        }
        _ => {
            let start = *pos;
            while s.get(*pos).is_some_and(|c| c.is_ascii_digit() || *c == '.') {
                *pos += 1;
            }
            let digits: String = s[start..*pos].iter().collect();
            Some(qsic::io::parse_number(&digits).unwrap_or_else(|e| panic!("{digits:?}: {e}")))
        }
    }
}

fn q(n: i64, d: u64) -> RBig {
    RBig::from_parts(n.into(), d.into())
}

/// The 4×4 matrices of strings of `moving.jsonl`, named `id A` and `id B`.
fn corpus_matrices() -> Vec<(String, Vec<Vec<String>>)> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/moving.jsonl");
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut out = Vec::new();
    for (i, line) in text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
    {
        let record: Value =
            serde_json::from_str(line).unwrap_or_else(|e| panic!("line {}: {e}", i + 1));
        for key in ["A", "B"] {
            let rows = record[key]
                .as_array()
                .unwrap_or_else(|| panic!("line {}: {key} is not a matrix", i + 1))
                .iter()
                .map(|row| {
                    let row = row.as_array().expect("a row");
                    row.iter()
                        .map(|v| v.as_str().expect("a string").to_string())
                        .collect()
                })
                .collect();
            out.push((format!("line {} ({}) {key}", i + 1, record["id"]), rows));
        }
    }
    out
}

/// The instants at which the entries are compared.
fn instants() -> Vec<RBig> {
    [
        (-3, 1),
        (-2, 1),
        (-1, 1),
        (-1, 2),
        (0, 1),
        (1, 3),
        (1, 1),
        (4, 3),
        (3, 2),
        (2, 1),
        (7, 1),
    ]
    .iter()
    .map(|&(n, d)| q(n, d))
    .collect()
}

/// `A(t)` of the moving matrix equals the entries evaluated independently, wherever they
/// are all defined; returns the number of instants compared.
fn check_against_entries(name: &str, rows: &[Vec<String>], m: &MovingMatrix) -> usize {
    let mut compared = 0;
    for t in instants() {
        let values: Option<Vec<Vec<RBig>>> = rows
            .iter()
            .map(|row| row.iter().map(|e| evaluate(e, &t)).collect())
            .collect();
        let Some(values) = values else {
            continue;
        };
        let at = m
            .at(&t)
            .unwrap_or_else(|| panic!("{name}: d({t}) = 0 where every entry is defined"));
        for i in 0..4 {
            for j in 0..4 {
                assert_eq!(at[i][j], values[i][j], "{name}: entry ({i},{j}) at t = {t}");
                assert_eq!(
                    m.numerators()[i][j].eval_rational(&t) * m.factor().eval_rational(&t),
                    &values[i][j] * m.denominator().eval_rational(&t),
                    "{name}: numerator ({i},{j}) at t = {t}"
                );
            }
        }
        compared += 1;
    }
    compared
}

#[test]
fn every_moving_matrix_reads_and_evaluates_as_its_entries() {
    let matrices = corpus_matrices();
    assert_eq!(matrices.len(), 6, "three moving pairs");
    for (name, rows) in &matrices {
        let m = moving_matrix_from_rows(rows).unwrap_or_else(|e| panic!("{name}: {e}"));
        let compared = check_against_entries(name, rows, &m);
        assert!(compared >= 8, "{name}: only {compared} instants compared");
        // M is symmetric.
        for i in 0..4 {
            for j in 0..4 {
                assert_eq!(m.numerators()[i][j], m.numerators()[j][i], "{name}");
            }
        }
    }
}

#[test]
fn moving_forms_read_as_their_matrices() {
    let names = ["x", "y", "z", "w"];
    for (name, rows) in corpus_matrices() {
        // Σ Aᵢᵢ vᵢ² + Σ_{i<j} 2 Aᵢⱼ vᵢ vⱼ, each coefficient the entry string as written.
        let mut terms = Vec::new();
        for i in 0..4 {
            for j in i..4 {
                if rows[i][j].trim() == "0" {
                    continue;
                }
                let factor = if i == j { "" } else { "2*" };
                terms.push(format!(
                    "{factor}({})*{}*{}",
                    rows[i][j], names[i], names[j]
                ));
            }
        }
        let text = terms.join(" + ");
        assert_eq!(
            moving_matrix_from_polynomial(&text),
            moving_matrix_from_rows(&rows),
            "{name}: {text}"
        );
    }
}

#[test]
fn the_corpus_denominators_are_the_lcms() {
    // jia2013_ex3.1 B: denominators t² + 1 and (t² + 1)²; ex4.1 B: 3t − 4 and (3t − 4)².
    let matrices = corpus_matrices();
    let denominator = |k: usize| {
        let m = moving_matrix_from_rows(&matrices[k].1).expect("valid");
        m.denominator()
            .coeffs()
            .iter()
            .map(|c| c.to_string())
            .collect::<Vec<_>>()
    };
    assert_eq!(
        denominator(1),
        ["1", "0", "2", "0", "1"],
        "{}",
        matrices[1].0
    );
    assert_eq!(denominator(3), ["16", "-24", "9"], "{}", matrices[3].0);
    assert_eq!(denominator(0), ["1"], "{}", matrices[0].0);
}
