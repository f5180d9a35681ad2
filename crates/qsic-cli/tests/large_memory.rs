//! The memory of `qsic sample --points 1000000 --batch` does not grow with the number of
//! lines: the peak resident memory of 16 lines is within 1.5× of one line's (the answers
//! are 140 MB of JSON each; held, 16 would take gigabytes), and one line's is below the
//! length of its answer (its text is written as it is made, never held).
//!
//! The peak is the kernel's account of the child (`wait4`), not a timing. Linux starts a
//! child's peak at its parent's resident size, so this file holds one test and the parent
//! never holds an answer: it reads the output a buffer at a time, keeping each line's
//! length and hash.

use std::collections::hash_map::DefaultHasher;
use std::hash::Hasher;
use std::io::{BufRead, BufReader, Write};
use std::process::{Command, Stdio};

const LINE: &str = r#"{"id":ID,"A":"x^2+y^2+z^2-4","B":"x^2+y^2-2*x"}"#;

/// One output line: its `id` prefix, the hash of the rest and its length.
type Digest = (String, u64, usize);

/// Runs `qsic sample --points 1000000 --batch -` on `n` copies of [`LINE`] (ids `0..n`):
/// the digests of its output lines and its peak resident memory in KiB.
// the child is reaped by `wait4` (which gives its peak memory), not `Child::wait`
#[allow(clippy::zombie_processes)]
fn run(n: usize) -> (Vec<Digest>, i64) {
    let input: String = (0..n)
        .map(|i| LINE.replace("ID", &i.to_string()) + "\n")
        .collect();
    let mut child = Command::new(env!("CARGO_BIN_EXE_qsic"))
        .args(["sample", "--points", "1000000", "--batch", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(input.as_bytes())
        .unwrap();
    let mut out = BufReader::with_capacity(1 << 16, child.stdout.take().unwrap());
    let mut digests = Vec::new();
    loop {
        // the id prefix, up to the first comma
        let mut prefix = Vec::new();
        if out.read_until(b',', &mut prefix).unwrap() == 0 {
            break;
        }
        let (mut hasher, mut len) = (DefaultHasher::new(), 0);
        loop {
            let buf = out.fill_buf().unwrap();
            assert!(!buf.is_empty(), "a line without its newline");
            let (part, done) = match buf.iter().position(|&c| c == b'\n') {
                Some(k) => (&buf[..k], true),
                None => (buf, false),
            };
            hasher.write(part);
            len += part.len();
            let used = part.len() + usize::from(done);
            out.consume(used);
            if done {
                break;
            }
        }
        digests.push((String::from_utf8(prefix).unwrap(), hasher.finish(), len));
    }
    let pid = child.id() as libc::pid_t;
    let mut status = 0;
    // SAFETY: `rusage` is plain data the call fills in; `pid` is our own child, not waited.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    let waited = unsafe { libc::wait4(pid, &mut status, 0, &mut usage) };
    assert_eq!(waited, pid);
    (digests, usage.ru_maxrss)
}

#[test]
fn memory_of_a_million_points_a_line_does_not_grow_with_the_lines() {
    let (one, one_kib) = run(1);
    let (many, many_kib) = run(16);
    assert_eq!(one.len(), 1);
    assert_eq!(many.len(), 16);
    assert!(
        one[0].2 > 100_000_000,
        "a million points: {} bytes",
        one[0].2
    );
    for (i, d) in many.iter().enumerate() {
        assert_eq!(d.0, format!("{{\"id\":{i},"), "in order");
        assert_eq!(
            (d.1, d.2),
            (one[0].1, one[0].2),
            "line {i}: the same answer"
        );
    }
    assert!(
        (many_kib as f64) <= 1.5 * one_kib as f64,
        "16 lines {many_kib} KiB, one line {one_kib} KiB"
    );
    // and the text is never held whole: the peak is below one answer's length (the points
    // as floats are about 125 bytes each, the text 140)
    assert!(
        one_kib * 1024 < one[0].2 as i64,
        "one line {one_kib} KiB for an answer of {} bytes",
        one[0].2
    );
}
