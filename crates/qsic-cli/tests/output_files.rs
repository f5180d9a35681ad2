//! The files the commands write (`qsic plot -o FILE`, `qsic motion --plot FILE`) are written
//! whole or not at all: a write that fails part way — a file size limit (`ulimit -f`, with
//! `SIGXFSZ` ignored so that the write reports `EFBIG`) stands in for a full disk, on the
//! binary's real write path — leaves no truncated file, keeps an older file as it was,
//! leaves no temporary behind, and fails with exit 2 and a message naming the file.

#![cfg(unix)]

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The file size limit of the runs that must fail, in the shell's blocks (512 or 1024 bytes).
const LIMIT_BLOCKS: u64 = 4;

/// `qsic args…` with the file size limit when `limited`.
fn qsic(args: &[&str], limited: bool) -> Output {
    let script = if limited {
        format!("trap '' XFSZ; ulimit -f {LIMIT_BLOCKS} && exec \"$@\"")
    } else {
        "exec \"$@\"".to_string()
    };
    Command::new("sh")
        .arg("-c")
        .arg(script)
        .arg("sh")
        .arg(env!("CARGO_BIN_EXE_qsic"))
        .args(args)
        .output()
        .expect("sh runs qsic")
}

/// A fresh, empty directory for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("qsic-files-{name}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
}

fn entries(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// `command` (with `{}` for the output path) written in full without the limit, then with it:
/// without an older file and over one.
fn check_whole_or_nothing(name: &str, command: &[&str]) {
    let dir = scratch(name);
    let path = dir.join("out.svg");
    let p = path.to_str().unwrap();
    let args: Vec<&str> = command
        .iter()
        .map(|a| if *a == "{}" { p } else { a })
        .collect();
    // in full: larger than the limit, so that the limit bites below
    let out = qsic(&args, false);
    assert_eq!(out.status.code(), Some(0), "{name}: {out:?}");
    let full = fs::read_to_string(&path).unwrap();
    assert!(
        full.trim_end().ends_with("</svg>"),
        "{name}: not a whole SVG"
    );
    assert!(
        full.len() as u64 > 2 * 1024 * LIMIT_BLOCKS,
        "{name}: {}",
        full.len()
    );
    assert_eq!(entries(&dir), ["out.svg"]);
    // over an older file, and with none
    for older in [Some("older"), None] {
        match older {
            Some(text) => fs::write(&path, text).unwrap(),
            None => fs::remove_file(&path).unwrap(),
        }
        let out = qsic(&args, true);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {err}");
        assert!(err.contains(p), "{name}: the message names the file: {err}");
        match older {
            Some(text) => assert_eq!(fs::read_to_string(&path).unwrap(), text, "{name}"),
            None => assert!(!path.exists(), "{name}: a partial file was left"),
        }
        let left: Vec<String> = older.map(|_| "out.svg".to_string()).into_iter().collect();
        assert_eq!(entries(&dir), left, "{name}: a temporary was left");
    }
    fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_plot_that_cannot_be_written_in_full_leaves_no_partial_file() {
    check_whole_or_nothing(
        "plot",
        &["plot", "x^2+y^2+z^2-4", "(x-1)^2+y^2-1", "-o", "{}"],
    );
}

#[test]
fn a_motion_plot_that_cannot_be_written_in_full_leaves_no_partial_file() {
    check_whole_or_nothing(
        "motion",
        &[
            "motion",
            "--plot",
            "{}",
            "x^2+y^2+z^2-4",
            "(x-t)^2+y^2+z^2-1",
        ],
    );
}

/// A rename refused (the target is a directory) fails with exit 2 and leaves nothing.
#[test]
fn a_directory_as_the_output_fails_and_leaves_nothing() {
    let dir = scratch("dir");
    let target = dir.join("out.svg");
    fs::create_dir(&target).unwrap();
    let t = target.to_str().unwrap();
    let out = qsic(&["plot", "x^2+y^2-1", "x^2+z^2-1", "-o", t], false);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains(t), "{err}");
    assert_eq!(entries(&dir), ["out.svg"]);
    assert!(entries(&target).is_empty());
    fs::remove_dir_all(&dir).unwrap();
}
