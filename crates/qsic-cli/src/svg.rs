//! Small helpers for the hand-written SVG pictures (`qsic motion --plot`, `qsic plot`):
//! XML escaping, text elements, the colour palette, the document around one or more panels.
//!
//! Floating point appears only as positions on the page.

use std::fmt::Write as _;

/// Distinct colours (Tableau 10), cycled when more are needed.
pub const PALETTE: [&str; 10] = [
    "#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#76b7b2", "#edc948", "#b07aa1", "#ff9da7",
    "#9c755f", "#bab0ac",
];

/// The colour of item `k`, cycling through [`PALETTE`].
pub fn colour(k: usize) -> &'static str {
    PALETTE[k % PALETTE.len()]
}

/// Appends `text` with `&`, `<`, `>`, `"` and `'` escaped for XML text and attributes.
pub fn push_escaped(out: &mut String, text: &str) {
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c => out.push(c),
        }
    }
}

/// Appends a `<text>` element (escaped content) with a class and an anchor
/// (`start`, `middle`, `end`).
pub fn push_text(out: &mut String, x: f64, y: f64, anchor: &str, class: &str, text: &str) {
    let _ = write!(
        out,
        "<text class=\"{class}\" x=\"{x:.1}\" y=\"{y:.1}\" text-anchor=\"{anchor}\">"
    );
    push_escaped(out, text);
    out.push_str("</text>\n");
}

/// Appends a `<title>` (a tooltip of the enclosing element) with escaped text.
pub fn push_title(out: &mut String, text: &str) {
    out.push_str("<title>");
    push_escaped(out, text);
    out.push_str("</title>");
}

/// One picture: its size and the SVG elements drawn in `[0, width] × [0, height]`.
#[derive(Clone, Debug)]
pub struct Panel {
    /// Width in pixels.
    pub width: f64,
    /// Height in pixels.
    pub height: f64,
    /// Style rules (CSS) the panel's elements need.
    pub style: String,
    /// The elements.
    pub body: String,
}

/// The SVG document showing `panels` one below the other on a white page.
pub fn document(panels: &[Panel]) -> String {
    let width = panels.iter().map(|p| p.width).fold(0.0, f64::max);
    let height: f64 = panels.iter().map(|p| p.height).sum();
    let mut out = String::with_capacity(panels.iter().map(|p| p.body.len()).sum::<usize>() + 512);
    let _ = writeln!(
        out,
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" \
         width=\"{width:.0}\" height=\"{height:.0}\" viewBox=\"0 0 {width:.0} {height:.0}\" \
         font-family=\"sans-serif\" font-size=\"12\">"
    );
    out.push_str("<style>");
    for p in panels {
        out.push_str(&p.style);
    }
    out.push_str("</style>\n");
    let _ = writeln!(
        out,
        "<rect class=\"page\" x=\"0\" y=\"0\" width=\"{width:.0}\" height=\"{height:.0}\" fill=\"#fff\"/>"
    );
    let mut top = 0.0;
    for p in panels {
        let _ = writeln!(
            out,
            "<g class=\"panel\" transform=\"translate(0,{top:.0})\">"
        );
        out.push_str(&p.body);
        out.push_str("</g>\n");
        top += p.height;
    }
    out.push_str("</svg>\n");
    out
}

/// Splits `text` into lines of at most `width` characters at spaces (a longer word stays whole).
pub fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split(' ') {
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() || lines.is_empty() {
        lines.push(line);
    }
    lines
}

/// Page width of the panels.
pub(crate) const WIDTH: f64 = 1000.0;

/// A short decimal: three significant decimals, scientific notation for very large or small.
pub(crate) fn short(v: f64) -> String {
    let v = v + 0.0;
    if v != 0.0 && !(1e-3..1e5).contains(&v.abs()) {
        return format!("{v:.2e}");
    }
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.into()
    }
}

#[cfg(test)]
#[path = "../tests/common/xml.rs"]
pub(crate) mod xml;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_is_escaped() {
        let mut out = String::new();
        push_text(&mut out, 0.0, 0.0, "start", "x", "a<b & \"c\" 'd' > e");
        assert_eq!(
            out,
            "<text class=\"x\" x=\"0.0\" y=\"0.0\" text-anchor=\"start\">\
             a&lt;b &amp; &quot;c&quot; &apos;d&apos; &gt; e</text>\n"
        );
        xml::check_xml(&format!(
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?><g>{out}</g>"
        ));
    }

    /// Panels are stacked: the page is as wide as the widest and as high as all together,
    /// each panel translated by the heights above it.
    #[test]
    fn document_stacks_panels() {
        let panel = |w: f64, h: f64, body: &str| Panel {
            width: w,
            height: h,
            style: ".a{fill:red}".into(),
            body: body.into(),
        };
        let svg = document(&[
            panel(300.0, 100.0, "<circle r=\"1\"/>"),
            panel(500.0, 50.0, ""),
        ]);
        let names = xml::check_xml(&svg);
        assert_eq!(names[..2], ["svg".to_string(), "style".to_string()]);
        assert!(svg.contains("width=\"500\" height=\"150\""));
        assert!(svg.contains("translate(0,0)") && svg.contains("translate(0,100)"));
        assert_eq!(svg.matches("class=\"panel\"").count(), 2);
    }

    #[test]
    fn wrap_breaks_at_spaces() {
        assert_eq!(wrap("aa bb cc dd", 5), ["aa bb", "cc dd"]);
        assert_eq!(wrap("abcdefgh ij", 4), ["abcdefgh", "ij"]);
        assert_eq!(wrap("", 4), [""]);
        for line in wrap("the quick brown fox jumps over the lazy dog", 10) {
            assert!(line.chars().count() <= 10, "{line}");
        }
    }
}
