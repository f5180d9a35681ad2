//! One reading of every input (issue 23): the commands of the issue, run on the built binary.
//! A plane is its double plane in `classify` and `motion`; a factor common to all entries is
//! cleared in `motion` and `contact` alike; `--range` is read and refused alike, infinity is
//! written `-oo`/`+oo`; `contact --json` keeps the documented key order; negative powers of
//! `t`; long numbers shortened in messages.

use serde_json::Value;
use std::process::Command;

/// Exit code, stdout and stderr of `qsic args…`.
fn qsic(args: &[&str]) -> (Option<i32>, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_qsic"))
        .args(args)
        .output()
        .expect("the qsic binary runs");
    let text = |b: Vec<u8>| String::from_utf8(b).expect("UTF-8 output");
    (out.status.code(), text(out.stdout), text(out.stderr))
}

/// The JSON object printed by a successful `qsic args…`.
fn json(args: &[&str]) -> Value {
    let (code, out, err) = qsic(args);
    assert_eq!(code, Some(0), "{args:?}: {err}");
    serde_json::from_str(out.trim()).unwrap_or_else(|e| panic!("{args:?}: {e}: {out}"))
}

/// The type fields of a classification, a motion interval or instant.
fn kind(v: &Value) -> [Value; 4] {
    ["pencil", "case", "complex_type", "real_type"].map(|k| v[k].clone())
}

/// `qsic motion x y` and `qsic classify x y` give the same type (the double planes `x²`,
/// `y²`); so do `"z-1"` and the cone (case 19, a conic counted twice), in every form of the
/// plane and through a motion batch.
#[test]
fn a_plane_is_its_double_plane_in_classify_and_motion() {
    let pairs = [
        ("x", "y"),
        ("z-1", "x^2+y^2-z^2"),
        ("z-w", "x^2+y^2-z^2"),
        ("(z-1)^2", "x^2+y^2-z^2"),
    ];
    for (a, b) in pairs {
        let classified = json(&["classify", "--json", "--projective", a, b]);
        let moved = json(&["motion", "--json", a, b]);
        let intervals = moved["intervals"].as_array().expect("intervals");
        assert_eq!(intervals.len(), 1, "{a}, {b}: a constant motion");
        assert_eq!(kind(&intervals[0]), kind(&classified), "{a}, {b}");
    }
    let cone = json(&["motion", "--json", "z-1", "x^2+y^2-z^2"]);
    assert_eq!(cone["intervals"][0]["case"], 19);
    let planes = json(&["motion", "--json", "x", "y"]);
    assert_eq!(
        planes["intervals"][0]["real_type"],
        "quadruple_line_of_plane_pairs"
    );
    // A moving plane z = t cutting the cone: a double conic but at the vertex.
    let moving = json(&["motion", "--json", "z-t", "x^2+y^2-z^2"]);
    let ts: Vec<&Value> = moving["instants"]
        .as_array()
        .unwrap()
        .iter()
        .map(|i| &i["t"])
        .collect();
    assert_eq!(ts, ["0"]);
    assert_eq!(moving["intervals"][0]["case"], 19);
    // `classify` still names a plane input `plane`, in one reading.
    let view = json(&["classify", "--json", "z-1", "x^2+y^2-z^2"]);
    assert_eq!(view["affine"]["surfaces"][0], "plane");
    // a form using w of mixed degrees stays an error
    let (code, _, err) = qsic(&["motion", "x + w + 1", "y^2"]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("A: term '1' has degree 0"), "{err}");
}

/// `qsic contact "t*x^2+t*y^2+t*z^2-t" "x^2+y^2+z^2-4"` clears the factor `t` as `motion`
/// does: no instant at `t = 0` where "A is the zero form".
#[test]
fn contact_clears_a_common_factor_as_motion_does() {
    let (a, b) = ("t*x^2+t*y^2+t*z^2-t", "x^2+y^2+z^2-4");
    let report = json(&["contact", "--json", a, b]);
    let solids = &report["solids"];
    assert_eq!(
        solids["instants"].as_array().map(Vec::len),
        Some(0),
        "{report}"
    );
    assert_eq!(
        solids["intervals"].as_array().map(Vec::len),
        Some(1),
        "{report}"
    );
    assert_eq!(solids["intervals"][0]["relation"], "inside");
    assert_eq!(solids["intervals"][0]["inner"], "A");
    let (_, text, _) = qsic(&["contact", a, b]);
    assert!(!text.contains("zero form"), "{text}");
    let moved = json(&["motion", "--json", a, b]);
    assert_eq!(moved["instants"].as_array().map(Vec::len), Some(0));
    assert_eq!(
        json(&["motion", "--json", a, b]),
        json(&["motion", "--json", "x^2+y^2+z^2-1", b])
    );
}

/// `--range` is one reader for `motion` and `contact`: the same spellings accepted, the same
/// empty or unreadable ranges refused with the same message, as usage errors.
#[test]
fn ranges_are_read_and_refused_alike() {
    let (a, b) = ("x^2+y^2+z^2-4", "(x-t)^2+y^2+z^2-1");
    for (t0, t1) in [
        ("-oo", "oo"),
        ("-inf", "inf"),
        ("-oo", "+oo"),
        ("-inf", "+inf"),
    ] {
        let moved = json(&["motion", "--json", "--range", t0, t1, a, b]);
        assert_eq!(
            moved["intervals"].as_array().map(Vec::len),
            Some(6),
            "{t0} {t1}"
        );
        let report = json(&["contact", "--json", "--range", t0, t1, a, b]);
        assert_eq!(
            report["range"],
            serde_json::json!([null, null]),
            "{t0} {t1}"
        );
    }
    let refused = [
        ("oo", "-oo", "the start is +oo: the range is empty"),
        ("-oo", "-oo", "the end is -oo: the range is empty"),
        ("oo", "oo", "the start is +oo: the range is empty"),
        (
            "2",
            "1",
            "the start 2 is above the end 1: the range is empty",
        ),
        ("a", "1", "the start is not a number nor -oo / oo"),
        ("0", "none", "the end is not a number nor -oo / oo"),
    ];
    for (t0, t1, want) in refused {
        let (m_code, _, m_err) = qsic(&["motion", "--range", t0, t1, a, b]);
        let (c_code, _, c_err) = qsic(&["contact", "--range", t0, t1, a, b]);
        assert_eq!(
            (m_code, c_code),
            (Some(2), Some(2)),
            "{t0} {t1}: {m_err} / {c_err}"
        );
        let first = |e: &str| e.lines().next().unwrap_or_default().to_string();
        assert_eq!(first(&m_err), first(&c_err), "{t0} {t1}");
        assert!(
            first(&m_err).starts_with(&format!("error: --range: invalid time range: {want}")),
            "{t0} {t1}: {m_err}"
        );
    }
}

/// Infinity is `-oo`/`+oo` in both commands' text and JSON.
#[test]
fn infinity_is_spelt_alike() {
    let (a, b) = ("x^2+y^2+z^2-1", "x^2+y^2+z^2-4");
    let (_, motion_text, _) = qsic(&["motion", a, b]);
    assert!(motion_text.contains("t in (-oo, +oo)"), "{motion_text}");
    let (code, text, err) = qsic(&["contact", a, b]);
    assert_eq!(code, Some(0), "{err}");
    assert!(text.contains("range: [-oo, +oo]"), "{text}");
    assert!(
        text.contains("first contact of the solids: from t = -oo"),
        "{text}"
    );
    assert!(text.contains("(-oo, +oo): inside"), "{text}");
    let (_, line, _) = qsic(&["contact", "--json", a, b]);
    assert!(line.contains(r#""first_meeting":"-oo""#), "{line}");
    for output in [&motion_text, &text, &line] {
        assert!(
            !output.contains("-inf") && !output.contains("+inf"),
            "{output}"
        );
    }
    // two unit spheres, one moving in from x = -∞: the surfaces meet from t = -2, the
    // solids likewise; a range from -oo
    let (_, line, _) = qsic(&[
        "contact",
        "--json",
        "--range",
        "-oo",
        "-3",
        a,
        "(x-t)^2+y^2+z^2-1",
    ]);
    let v: Value = serde_json::from_str(line.trim()).unwrap();
    assert_eq!(v["first_contact"], Value::Null, "{line}");
    assert_eq!(v["range"], serde_json::json!([null, "-3"]));
}

/// The keys of every object of a JSON text, in the order written (a small scanner: strings,
/// braces, brackets, colons and commas).
fn keys_in_order(text: &str) -> Vec<Vec<String>> {
    let mut done = Vec::new();
    // one entry per open object or array: (keys so far, expecting a key)
    let mut stack: Vec<Option<(Vec<String>, bool)>> = Vec::new();
    let mut chars = text.chars();
    while let Some(c) = chars.next() {
        match c {
            '"' => {
                let mut s = String::new();
                while let Some(c) = chars.next() {
                    match c {
                        '\\' => s.extend(chars.next()),
                        '"' => break,
                        c => s.push(c),
                    }
                }
                if let Some(Some((keys, expecting @ true))) = stack.last_mut() {
                    keys.push(s);
                    *expecting = false;
                }
            }
            '{' => stack.push(Some((Vec::new(), true))),
            '[' => stack.push(None),
            ',' => {
                if let Some(Some((_, expecting))) = stack.last_mut() {
                    *expecting = true;
                }
            }
            '}' => done.extend(stack.pop().flatten().map(|(keys, _)| keys)),
            ']' => {
                stack.pop();
            }
            _ => {}
        }
    }
    done
}

/// `contact --json` writes its keys in the README's order, not alphabetically; an
/// irrational instant too.
#[test]
fn contact_json_keys_follow_the_documented_order() {
    let documented: [&[&str]; 9] = [
        &["range", "first_contact", "contact", "solids"],
        &[
            "t", "at_start", "locus", "curves", "points", "numbers", "note",
        ],
        &["kind", "point", "approx"],
        &["name", "poly", "interval", "approx"],
        &["first_meeting", "intervals", "instants"],
        &["from", "to", "sample_t", "relation", "inner", "note"],
        &["t", "relation", "inner", "note"],
        &["poly", "interval", "approx"],
        &["error"],
    ];
    for b in ["(x-t)^2+y^2+z^2-1", "(x-t)^2+(y-1)^2+z^2-1"] {
        let (code, line, err) = qsic(&["contact", "--json", "x^2+y^2+z^2-4", b]);
        assert_eq!(code, Some(0), "{err}");
        let objects = keys_in_order(&line);
        assert!(objects.len() > 5, "{line}");
        for keys in &objects {
            assert!(
                documented.iter().any(|d| d == keys),
                "keys {keys:?} in {line}"
            );
        }
        assert_eq!(objects.last().unwrap(), &documented[0]);
    }
}

/// The instants of a motion and the types along it (the samples left out: a denominator may
/// add a candidate instant where nothing changes).
fn timeline(args: &[&str]) -> (Vec<Value>, Vec<[Value; 4]>) {
    let v = json(args);
    let instants = v["instants"].as_array().unwrap();
    let types = v["intervals"].as_array().unwrap().iter().map(kind);
    let ts = instants.iter().map(|i| i["t"].clone()).collect();
    (ts, instants.iter().map(kind).chain(types).collect())
}

/// `t**(-2)` (also `t^(-2)`, `t^-2`, `(1+t)^-1`) is `1/t**2` in a moving quadric; a negative
/// power of `x` in a quadric is a clear error, and of zero too.
#[test]
fn negative_powers_of_t_are_divisions() {
    let fixed = "x^2+y^2+z^2-4";
    let want = timeline(&["motion", "--json", fixed, "t^2*(x^2+y^2+z^2) - 1"]);
    assert!(!want.0.is_empty());
    for b in [
        "x^2+y^2+z^2 - t**(-2)",
        "x^2+y^2+z^2 - t^(-2)",
        "x^2+y^2+z^2 - t^-2",
        "x^2+y^2+z^2 - (t^-1)^2",
    ] {
        assert_eq!(timeline(&["motion", "--json", fixed, b]), want, "{b}");
    }
    assert_eq!(
        timeline(&["motion", "--json", fixed, "(x-(1+t)^-1)^2+y^2+z^2-1"]),
        timeline(&[
            "motion",
            "--json",
            fixed,
            "((1+t)*x-1)^2+(1+t)^2*(y^2+z^2-1)"
        ]),
    );
    let refused = [
        ("x^(-1) + y^2", "negative power is a division"),
        ("x^2 - 0^(-1)", "division by zero"),
        ("x^2 + t^(-65)", "exponent 65"),
    ];
    for (a, want) in refused {
        let (code, _, err) = qsic(&["motion", a, fixed]);
        assert_eq!(code, Some(1), "{a}: {err}");
        assert!(err.contains(want), "{a}: {err}");
    }
    let (code, _, err) = qsic(&["classify", "x^(-1) + y^2", fixed]);
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains("a negative power is a division: can only divide by a number"),
        "{err}"
    );
}

/// A message naming a 3 000-digit coefficient shows its first and last digits and the digit
/// count, not the whole number; short numbers are unchanged.
#[test]
fn long_numbers_are_shortened_in_messages() {
    let n = "1234567890".repeat(300);
    let short = "1234567890…4567890 (3000 digits)";
    let matrix = format!("[[1,{n},0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]");
    let moving = format!("[[1,\"{n}*t\",0,0],[\"t\",1,0,0],[0,0,1,0],[0,0,0,1]]");
    let cases: Vec<Vec<String>> = vec![
        vec![
            "classify".into(),
            format!("x^2 + {n}*x + w^2"),
            "y^2".into(),
        ],
        vec!["classify".into(), matrix, "y^2".into()],
        vec![
            "classify".into(),
            format!("[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,\"{n}/0\"]]"),
            "y^2".into(),
        ],
        vec!["param".into(), format!("x^2 {n}"), "y^2".into()],
        vec!["motion".into(), moving, "y^2".into()],
        vec![
            "motion".into(),
            "--range".into(),
            n.clone(),
            "1".into(),
            "x^2".into(),
            "y^2".into(),
        ],
        vec![
            "contact".into(),
            "--range".into(),
            "0".into(),
            format!("-{n}"),
            "x^2".into(),
            "y^2".into(),
        ],
    ];
    for args in &cases {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let (code, _, err) = qsic(&args);
        assert!(code == Some(1) || code == Some(2), "{err}");
        assert!(err.contains(short), "{}: {err}", args[0]);
        assert!(err.len() < 400, "{}: {} bytes: {err}", args[0], err.len());
    }
    let (_, _, err) = qsic(&[
        "classify",
        "[[1,2,0,0],[3,1,0,0],[0,0,1,0],[0,0,0,1]]",
        "y^2",
    ]);
    assert!(err.contains("entry (0,1) = 2 but (1,0) = 3"), "{err}");
}
