//! The shape of the CLI crate: its modules use each other without a cycle, and each file
//! stays small enough to read (about 1 000 lines of code, tests and comments apart).

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::Path;

/// Most lines of code (not blank, not a comment, before the tests) in one source file.
const MAX_CODE_LINES: usize = 1_000;

/// Each module of `src/` and the modules of this crate it names (`crate::m`, `super::m`),
/// comments and the test module left out.
fn module_graph(src: &Path) -> BTreeMap<String, (BTreeSet<String>, usize)> {
    let mut graph = BTreeMap::new();
    for entry in fs::read_dir(src).expect("src/") {
        let path = entry.expect("an entry").path();
        if path.extension().and_then(|e| e.to_str()) != Some("rs") {
            continue;
        }
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        let text = fs::read_to_string(&path).expect("a source file");
        let code = code_lines(&text);
        let mut uses = BTreeSet::new();
        for line in &code {
            uses.extend(named_modules(line).into_iter().filter(|m| *m != name));
        }
        graph.insert(name, (uses, code.len()));
    }
    graph
}

/// The lines of code before `#[cfg(test)]`, without blank lines and comments.
fn code_lines(text: &str) -> Vec<&str> {
    text.lines()
        .take_while(|l| l.trim() != "#[cfg(test)]")
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with("//"))
        .collect()
}

/// The module names after `crate::` or `super::` on a line.
fn named_modules(line: &str) -> Vec<String> {
    let mut names = Vec::new();
    for prefix in ["crate::", "super::"] {
        let mut rest = line;
        while let Some(at) = rest.find(prefix) {
            rest = &rest[at + prefix.len()..];
            let end = rest
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .unwrap_or(rest.len());
            if end > 0 && rest[..end].chars().next().unwrap().is_ascii_lowercase() {
                names.push(rest[..end].to_string());
            }
        }
    }
    names
}

/// A cycle of the graph, if there is one (depth-first search with colours).
fn find_cycle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        node: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        state: &mut BTreeMap<String, u8>,
        path: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        state.insert(node.to_string(), 1);
        path.push(node.to_string());
        for next in graph.get(node).into_iter().flatten() {
            match state.get(next.as_str()).copied().unwrap_or(0) {
                1 => {
                    let from = path.iter().position(|n| n == next).unwrap();
                    let mut cycle = path[from..].to_vec();
                    cycle.push(next.clone());
                    return Some(cycle);
                }
                0 if graph.contains_key(next.as_str()) => {
                    if let Some(c) = visit(next, graph, state, path) {
                        return Some(c);
                    }
                }
                _ => {}
            }
        }
        path.pop();
        state.insert(node.to_string(), 2);
        None
    }
    let mut state = BTreeMap::new();
    for node in graph.keys() {
        if state.get(node.as_str()).copied().unwrap_or(0) == 0 {
            if let Some(c) = visit(node, graph, &mut state, &mut Vec::new()) {
                return Some(c);
            }
        }
    }
    None
}

#[test]
fn the_modules_form_no_cycle() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let graph: BTreeMap<_, _> = module_graph(&src)
        .into_iter()
        .map(|(m, (uses, _))| (m, uses))
        .collect();
    assert!(graph.len() > 20, "the modules of src/ were read");
    assert!(graph["motion"].contains("rigid"), "the uses were read");
    assert_eq!(find_cycle(&graph), None);
}

#[test]
fn the_cycle_finder_finds_a_cycle() {
    let graph: BTreeMap<String, BTreeSet<String>> = [
        ("a", vec!["b"]),
        ("b", vec!["c"]),
        ("c", vec!["a", "d"]),
        ("d", vec![]),
    ]
    .into_iter()
    .map(|(k, v)| (k.to_string(), v.into_iter().map(String::from).collect()))
    .collect();
    assert_eq!(find_cycle(&graph).map(|c| c.len()), Some(4));
    assert_eq!(
        named_modules("use crate::batch::{x}; super::line::y(Self)"),
        ["batch", "line"]
    );
}

#[test]
fn every_file_is_small_enough_to_read() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let large: Vec<_> = module_graph(&src)
        .into_iter()
        .filter(|(_, (_, lines))| *lines > MAX_CODE_LINES)
        .map(|(m, (_, lines))| format!("{m}.rs: {lines} lines of code"))
        .collect();
    assert!(large.is_empty(), "{large:?}");
}
