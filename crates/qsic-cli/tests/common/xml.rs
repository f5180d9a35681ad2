//! A small XML well-formedness check for the SVG pictures, shared by the unit tests of
//! `qsic_cli::svg` (through `#[path]`) and the integration tests.
#![allow(dead_code)]

/// Checks that `svg` is well-formed XML: the declaration, one root element, tags nested and
/// closed in order, quoted attributes, no raw `<` or stray `&` in text. Returns the element
/// names in document order.
///
/// # Panics
/// On the first violation, naming it.
pub fn check_xml(svg: &str) -> Vec<String> {
    let mut stack: Vec<String> = Vec::new();
    let mut names = Vec::new();
    let mut rest = svg
        .strip_prefix("<?xml version=\"1.0\" encoding=\"UTF-8\"?>")
        .expect("XML declaration");
    let mut roots = 0;
    while let Some(open) = rest.find('<') {
        check_text(&rest[..open]);
        let close = rest[open..].find('>').expect("tag closed") + open;
        let tag = &rest[open + 1..close];
        assert!(!tag.contains('<'), "{tag}");
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(stack.pop().as_deref(), Some(name), "closing {name}");
        } else {
            let self_closing = tag.ends_with('/');
            let body = tag.trim_end_matches('/');
            let name = body.split_whitespace().next().expect("a name").to_string();
            let mut a = body[name.len()..].trim();
            // attributes: name="value" pairs with escaped values
            while !a.is_empty() {
                let eq = a.find("=\"").expect("attribute quoted");
                assert!(!a[..eq].contains(' '), "{a}");
                let end = a[eq + 2..].find('"').expect("value closed") + eq + 2;
                check_text(&a[eq + 2..end]);
                a = a[end + 1..].trim_start();
            }
            if stack.is_empty() {
                roots += 1;
            }
            names.push(name.clone());
            if !self_closing {
                stack.push(name);
            }
        }
        rest = &rest[close + 1..];
    }
    check_text(rest);
    assert!(stack.is_empty(), "unclosed {stack:?}");
    assert_eq!(roots, 1, "one root element");
    names
}

/// Text has only the five predefined entities and no raw `<`.
pub fn check_text(text: &str) {
    assert!(!text.contains('<'));
    for (k, _) in text.match_indices('&') {
        let entity = &text[k..];
        assert!(
            ["&amp;", "&lt;", "&gt;", "&quot;", "&apos;"]
                .iter()
                .any(|e| entity.starts_with(e)),
            "raw & in {text:?}"
        );
    }
}

/// The text contents of the `<text>` elements with `class="{class}"`, unescaped.
pub fn texts_of(svg: &str, class: &str) -> Vec<String> {
    let key = format!("<text class=\"{class}\"");
    svg.match_indices(&key)
        .map(|(k, _)| {
            let start = svg[k..].find('>').expect("tag end") + k + 1;
            let end = svg[start..].find("</text>").expect("text end") + start;
            svg[start..end]
                .replace("&lt;", "<")
                .replace("&gt;", ">")
                .replace("&quot;", "\"")
                .replace("&apos;", "'")
                .replace("&amp;", "&")
        })
        .collect()
}
