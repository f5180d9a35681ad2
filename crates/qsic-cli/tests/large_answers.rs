//! `sample --batch` with many points a piece (the large-answer route, module `large`): the
//! same answers as single queries, every line in order (errors in place). Its memory is
//! tested in `large_memory.rs`.

use std::io::{Read, Write};
use std::process::{Command, Stdio};

const LINE: &str = r#"{"id":ID,"A":"x^2+y^2+z^2-4","B":"x^2+y^2-2*x"}"#;

/// Runs `qsic ARGS` on `input`; its output lines.
fn run(args: &[&str], input: String) -> (Vec<String>, ()) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_qsic"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    let feeder = std::thread::spawn(move || stdin.write_all(input.as_bytes()).unwrap());
    let mut out = String::new();
    child
        .stdout
        .take()
        .unwrap()
        .read_to_string(&mut out)
        .unwrap();
    feeder.join().unwrap();
    child.wait().unwrap();
    (out.lines().map(str::to_owned).collect(), ())
}

fn lines(ids: std::ops::Range<usize>) -> String {
    ids.map(|i| LINE.replace("ID", &i.to_string()) + "\n")
        .collect()
}

#[test]
fn large_answers_equal_single_queries_and_errors_keep_their_place() {
    let points = "20000"; // above the threshold of the large-answer route
    let input = lines(0..1)
        + "{\"id\":\"bad\",\"A\":\"x^2+\",\"B\":\"y^2\"}\n\n"
        + &LINE.replace("ID", "2").replace("-2*x", "-2*y")
        + "\n";
    let (got, _) = run(&["sample", "--points", points, "--batch", "-"], input);
    assert_eq!(got.len(), 3);
    let single = |b: &str| {
        let (out, _) = run(
            &["sample", "--points", points, "x^2+y^2+z^2-4", b],
            String::new(),
        );
        out.concat()
    };
    assert_eq!(got[0]["{\"id\":0,".len()..], single("x^2+y^2-2*x")[1..]);
    assert!(
        got[1].starts_with("{\"id\":\"bad\",\"error\":{\"line\":2,"),
        "{}",
        got[1]
    );
    assert_eq!(got[2]["{\"id\":2,".len()..], single("x^2+y^2-2*y")[1..]);
}
