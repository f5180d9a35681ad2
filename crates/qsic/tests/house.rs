//! The shape of the library's source: no import cycles between modules, and every file within
//! the size bound.
//!
//! # The module graph
//! Every file of `crates/qsic/src` is a module (`a/b.rs` and `a/b/mod.rs` are `a::b`). Its
//! code (comments and `#[cfg(test)]` modules left out) names other modules by paths that
//! start with `crate::`, `super::` or `self::`, in `use` trees (braces expanded) and inline;
//! a path names the longest module it starts with. A module using its own ancestor or
//! descendant is the ordinary shape of a Rust tree and is not an edge; otherwise the use of
//! `B` by `A` is an edge between the two children of their lowest common ancestor that hold
//! them (`param::sample::chart` using `affine::curve` is `param → affine` among the
//! children of the crate). Among the children of every module the edges must form no cycle.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// Most lines of code (blank lines, comments and `#[cfg(test)]` modules left out) of a file
/// of the library.
const MAX_CODE_LINES: usize = 1000;

fn src_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// Every `.rs` file under `dir`.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// The module path of a file (`crate` for `lib.rs`).
fn module_of(file: &Path) -> Vec<String> {
    let rel = file.strip_prefix(src_dir()).expect("under src");
    let mut parts: Vec<String> = rel
        .iter()
        .map(|s| s.to_string_lossy().into_owned())
        .collect();
    let last = parts.pop().expect("a file name");
    let stem = last.trim_end_matches(".rs").to_string();
    if !(stem == "mod" || (parts.is_empty() && stem == "lib")) {
        parts.push(stem);
    }
    parts
}

/// `line` without its `//` comment (a `//` inside a string literal is not looked for).
fn code_part(line: &str) -> &str {
    let mut in_str = false;
    let b = line.as_bytes();
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            // a character literal `'"'`
            b'\'' if !in_str && b.get(i + 1) == Some(&b'"') && b.get(i + 2) == Some(&b'\'') => {
                i += 2
            }
            b'\\' if in_str => i += 1,
            b'"' => in_str = !in_str,
            b'/' if !in_str && b.get(i + 1) == Some(&b'/') => return &line[..i],
            _ => {}
        }
        i += 1;
    }
    line
}

/// The code of a file: comments removed and every `#[cfg(test)]` item (a `mod … { … }`
/// block or a `mod …;` declaration) left out; the names of the test-only child files
/// declared by `#[cfg(test)] mod name;` go to `test_children`.
fn code_lines(text: &str, test_children: &mut Vec<String>) -> Vec<String> {
    let mut out = Vec::new();
    let mut lines = text.lines().map(code_part).peekable();
    while let Some(line) = lines.next() {
        if line.trim() != "#[cfg(test)]" {
            if !line.trim().is_empty() {
                out.push(line.to_string());
            }
            continue;
        }
        // the item under the attribute
        let Some(item) = lines.next() else { break };
        let t = item.trim();
        let name = t
            .trim_start_matches("pub(crate) ")
            .trim_start_matches("pub ")
            .strip_prefix("mod ");
        if let Some(name) = name.and_then(|n| n.strip_suffix(';')) {
            test_children.push(name.trim().to_string());
            continue;
        }
        // skip to the end of the item's braces (or its `;` if it has none)
        let mut depth: i64 = 0;
        let mut opened = false;
        let mut cur = Some(item);
        while let Some(l) = cur {
            for c in l.chars() {
                match c {
                    '{' => {
                        depth += 1;
                        opened = true;
                    }
                    '}' => depth -= 1,
                    _ => {}
                }
            }
            if (opened && depth <= 0) || (!opened && l.trim_end().ends_with(';')) {
                break;
            }
            cur = lines.next();
        }
    }
    out
}

/// Expands a `use` tree (`a::{b, c::{d, e}}`) into its paths.
fn expand_tree(prefix: &str, tree: &str, out: &mut Vec<String>) {
    let tree = tree.trim();
    let Some(open) = tree.find('{') else {
        let path = tree.split(" as ").next().unwrap_or(tree).trim();
        if !path.is_empty() {
            out.push(format!("{prefix}{path}"));
        }
        return;
    };
    let head = &tree[..open];
    let inner = &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())];
    let prefix = format!("{prefix}{head}");
    let mut depth = 0;
    let mut start = 0;
    for (i, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                expand_tree(&prefix, &inner[start..i], out);
                start = i + 1;
            }
            _ => {}
        }
    }
    expand_tree(&prefix, &inner[start..], out);
}

/// The paths starting with `crate::`, `super::` or `self::` in the code of one file.
fn paths_in(code: &[String]) -> Vec<String> {
    let text = code.join("\n");
    let mut out = Vec::new();
    // `use` statements, their trees expanded
    let mut rest = text.as_str();
    while let Some(at) = find_word(rest, "use ") {
        let stmt = &rest[at + 4..];
        let end = stmt.find(';').unwrap_or(stmt.len());
        let tree: String = stmt[..end].split_whitespace().collect::<Vec<_>>().join(" ");
        expand_tree("", &tree, &mut out);
        rest = &stmt[end..];
    }
    // inline paths
    let bytes = text.as_bytes();
    for start in ["crate::", "super::", "self::"] {
        let mut from = 0;
        while let Some(k) = text[from..].find(start) {
            let at = from + k;
            from = at + start.len();
            if at > 0 && (bytes[at - 1].is_ascii_alphanumeric() || bytes[at - 1] == b'_') {
                continue;
            }
            if at > 0 && bytes[at - 1] == b':' {
                continue;
            }
            let mut end = at;
            while end < bytes.len()
                && (bytes[end].is_ascii_alphanumeric() || bytes[end] == b'_' || bytes[end] == b':')
            {
                end += 1;
            }
            out.push(text[at..end].trim_end_matches(':').to_string());
        }
    }
    out
}

/// The index of `word` in `s` at a word boundary.
fn find_word(s: &str, word: &str) -> Option<usize> {
    let b = s.as_bytes();
    let mut from = 0;
    while let Some(k) = s[from..].find(word) {
        let at = from + k;
        if at == 0 || !(b[at - 1].is_ascii_alphanumeric() || b[at - 1] == b'_') {
            return Some(at);
        }
        from = at + word.len();
    }
    None
}

/// The module a path from module `here` names: the longest known module it starts with.
fn resolve(
    here: &[String],
    path: &str,
    modules: &BTreeSet<Vec<String>>,
    is_dir: bool,
) -> Option<Vec<String>> {
    let mut segs = path.split("::").filter(|s| !s.is_empty());
    let mut base: Vec<String> = match segs.next()? {
        "crate" => Vec::new(),
        "self" => here.to_vec(),
        "super" => {
            let mut b = here.to_vec();
            b.pop();
            b
        }
        _ => return None,
    };
    let _ = is_dir;
    let mut found = base.clone();
    for s in segs {
        if s == "super" {
            base.pop();
            found = base.clone();
            continue;
        }
        base.push(s.to_string());
        if modules.contains(&base) {
            found = base.clone();
        } else {
            break;
        }
    }
    Some(found)
}

struct Source {
    module: Vec<String>,
    file: PathBuf,
    code: Vec<String>,
}

/// Every non-test module of the crate with its code.
fn sources() -> Vec<Source> {
    let mut files = Vec::new();
    rust_files(&src_dir(), &mut files);
    let mut all = Vec::new();
    let mut test_only: BTreeSet<Vec<String>> = BTreeSet::new();
    for file in files {
        let text = fs::read_to_string(&file).expect("readable source");
        let module = module_of(&file);
        let mut tests = Vec::new();
        let code = code_lines(&text, &mut tests);
        for t in tests {
            let mut m = module.clone();
            m.push(t);
            test_only.insert(m);
        }
        all.push(Source { module, file, code });
    }
    all.retain(|s| !test_only.iter().any(|t| s.module.starts_with(t)));
    all
}

/// For every parent module, the edges between its children (module docs).
fn sibling_edges(srcs: &[Source]) -> BTreeMap<Vec<String>, BTreeSet<(String, String)>> {
    let modules: BTreeSet<Vec<String>> = srcs.iter().map(|s| s.module.clone()).collect();
    let mut edges: BTreeMap<Vec<String>, BTreeSet<(String, String)>> = BTreeMap::new();
    for s in srcs {
        let is_dir = s.file.ends_with("mod.rs") || s.file.ends_with("lib.rs");
        for path in paths_in(&s.code) {
            let Some(target) = resolve(&s.module, &path, &modules, is_dir) else {
                continue;
            };
            let common = s
                .module
                .iter()
                .zip(&target)
                .take_while(|(a, b)| a == b)
                .count();
            if common == s.module.len() || common == target.len() {
                continue; // ancestor or descendant
            }
            edges
                .entry(s.module[..common].to_vec())
                .or_default()
                .insert((s.module[common].clone(), target[common].clone()));
        }
    }
    edges
}

/// The strongly connected sets of more than one node (Tarjan's algorithm, recursive: the
/// graphs have a few dozen nodes).
fn cycles(edges: &BTreeSet<(String, String)>) -> Vec<BTreeSet<String>> {
    struct State<'a> {
        adj: BTreeMap<&'a str, Vec<&'a str>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        on_stack: BTreeSet<&'a str>,
        out: Vec<BTreeSet<String>>,
    }
    fn visit<'a>(v: &'a str, st: &mut State<'a>) {
        let i = st.index.len();
        st.index.insert(v, i);
        st.low.insert(v, i);
        st.stack.push(v);
        st.on_stack.insert(v);
        for w in st.adj.get(v).cloned().unwrap_or_default() {
            if !st.index.contains_key(w) {
                visit(w, st);
                let lw = st.low[w];
                let lv = st.low.get_mut(v).expect("visited");
                *lv = (*lv).min(lw);
            } else if st.on_stack.contains(w) {
                let iw = st.index[w];
                let lv = st.low.get_mut(v).expect("visited");
                *lv = (*lv).min(iw);
            }
        }
        if st.low[v] == st.index[v] {
            let mut set = BTreeSet::new();
            while let Some(w) = st.stack.pop() {
                st.on_stack.remove(w);
                set.insert(w.to_string());
                if w == v {
                    break;
                }
            }
            if set.len() > 1 {
                st.out.push(set);
            }
        }
    }
    let mut st = State {
        adj: BTreeMap::new(),
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeSet::new(),
        out: Vec::new(),
    };
    for (a, b) in edges {
        st.adj.entry(a).or_default().push(b);
        st.adj.entry(b).or_default();
    }
    let nodes: Vec<&str> = st.adj.keys().copied().collect();
    for v in nodes {
        if !st.index.contains_key(v) {
            visit(v, &mut st);
        }
    }
    st.out
}

/// Each cycle as `parent: a ↔ b ↔ …` (the parent `crate` for the top level).
fn all_cycles() -> Vec<String> {
    let mut out = Vec::new();
    for (parent, e) in sibling_edges(&sources()) {
        for c in cycles(&e) {
            let parent = if parent.is_empty() {
                "crate".to_string()
            } else {
                parent.join("::")
            };
            let members: Vec<String> = c.into_iter().collect();
            out.push(format!("{parent}: {}", members.join(" ↔ ")));
        }
    }
    out
}

#[test]
fn no_import_cycles_between_modules() {
    let cycles = all_cycles();
    assert!(
        cycles.is_empty(),
        "import cycles between modules: {cycles:#?}"
    );
}

#[test]
fn the_graph_sees_the_uses_it_must() {
    // the sampler uses the curve types and its kernels: edges the parser must find, or
    // the absence of cycles above would prove nothing
    let edges = sibling_edges(&sources());
    let param = edges
        .get(&vec!["param".to_string()])
        .expect("edges among the children of param");
    assert!(
        param.contains(&("sample".into(), "curve".into())),
        "{param:?}"
    );
    let sample = edges
        .get(&vec!["param".to_string(), "sample".to_string()])
        .expect("edges among the children of param::sample");
    assert!(
        sample.contains(&("eval".into(), "kernels".into())),
        "{sample:?}"
    );
    assert!(
        sample.contains(&("sampler".into(), "view".into())),
        "{sample:?}"
    );
    let top = edges.get(&Vec::new()).expect("top-level edges");
    assert!(top.contains(&("affine".into(), "param".into())), "{top:?}");
    // and it does find a cycle when there is one
    let mut e = param.clone();
    e.insert(("curve".into(), "sample".into()));
    assert!(cycles(&e)
        .iter()
        .any(|c| c.contains("sample") && c.contains("curve")));
}

/// Lines of code of a file: blank lines, comments and `#[cfg(test)]` items left out.
fn code_line_count(file: &Path) -> usize {
    let text = fs::read_to_string(file).expect("readable source");
    let mut tests = Vec::new();
    code_lines(&text, &mut tests)
        .iter()
        .filter(|l| !l.trim().is_empty())
        .count()
}

#[test]
fn every_file_is_within_the_size_bound() {
    let srcs = sources();
    let mut over = Vec::new();
    for s in &srcs {
        let n = code_line_count(&s.file);
        if n > MAX_CODE_LINES {
            over.push(format!("{}: {n} lines of code", s.file.display()));
        }
    }
    assert!(
        over.is_empty(),
        "files over the bound:\n{}",
        over.join("\n")
    );
    assert!(srcs.len() >= 60, "only {} files checked", srcs.len());
    // the count sees code: a file of the sampler is not empty
    assert!(code_line_count(&src_dir().join("param/sample/eval.rs")) > 300);
}
