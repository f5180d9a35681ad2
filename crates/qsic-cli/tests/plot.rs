//! `qsic plot` through the built binary: the SVG is well-formed, has one piece group per real
//! piece and one mark per finite singular point (counted against `qsic sample` and
//! `qsic param`, and against known geometry), the eigencurve panel marks the exact roots and
//! the index function, clipping keeps unbounded branches in the drawing, and errors are
//! messages with exit codes.

#[path = "common/xml.rs"]
mod xml;

use serde_json::Value;
use std::path::PathBuf;
use std::process::Command;
use xml::{check_xml, texts_of};

/// Runs `qsic args…`: (exit code, stdout, stderr).
fn qsic(args: &[&str]) -> (Option<i32>, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_qsic"))
        .args(args)
        .output()
        .expect("qsic runs");
    (
        out.status.code(),
        String::from_utf8(out.stdout).expect("UTF-8"),
        String::from_utf8(out.stderr).expect("UTF-8"),
    )
}

/// A fresh directory for this test's files.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("qsic-plot-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Draws `a`, `b` with `extra` arguments and returns the SVG, checked well-formed.
fn plot(dir: &std::path::Path, a: &str, b: &str, extra: &[&str]) -> String {
    let path = dir.join("out.svg");
    let p = path.to_str().unwrap();
    let mut args = vec!["plot", a, b, "-o", p];
    args.extend_from_slice(extra);
    let (code, out, err) = qsic(&args);
    assert_eq!(code, Some(0), "{a} | {b}: {err}");
    assert!(out.is_empty(), "{out}");
    let svg = std::fs::read_to_string(&path).unwrap();
    let names = check_xml(&svg);
    assert_eq!(names[0], "svg");
    svg
}

fn json(args: &[&str]) -> Value {
    let (code, out, err) = qsic(args);
    assert_eq!(code, Some(0), "{args:?}: {err}");
    serde_json::from_str(out.trim()).expect("JSON")
}

/// The `<g class="{class}" …>…</g>` groups (no nested groups inside them).
fn groups<'s>(svg: &'s str, class: &str) -> Vec<&'s str> {
    let key = format!("<g class=\"{class}\"");
    svg.match_indices(&key)
        .map(|(k, _)| {
            let end = svg[k..].find("</g>").expect("group closed") + k;
            &svg[k..end]
        })
        .collect()
}

/// The numbers of the path data of `d` attributes in `text` as (x, y) pairs.
fn path_points(text: &str) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    for (k, _) in text.match_indices(" d=\"") {
        let start = k + 4;
        let end = text[start..].find('"').unwrap() + start;
        for token in text[start..end].split([' ', 'M', 'L']) {
            if let Some((x, y)) = token.split_once(',') {
                out.push((x.parse().unwrap(), y.parse().unwrap()));
            }
        }
    }
    out
}

/// One piece group per real piece, isolated points as dots, one mark per singular point with
/// its kind — equal to what `qsic sample` and `qsic param` report and to the geometry: two
/// ovals (sphere and elliptic cylinder), Viviani's curve (one piece, a crunode), two equal
/// cylinders (two ellipses crossing at two points), and two spheres touching (one point).
#[test]
fn pieces_and_singular_points_are_drawn() {
    let dir = scratch("pieces");
    // (A, B, pieces, isolated points, singular points)
    let cases = [
        ("x^2+y^2+z^2-1", "2*x^2+4*y^2-1", 2, 0, 0),
        ("x^2+y^2+z^2-4", "(x-1)^2+y^2-1", 1, 0, 1),
        ("x^2+y^2-1", "x^2+z^2-1", 2, 0, 2),
        ("x^2+y^2+z^2-1", "(x-2)^2+y^2+z^2-1", 1, 1, 1),
    ];
    for (a, b, pieces, isolated, singular) in cases {
        let svg = plot(&dir, a, b, &[]);
        let sampled = json(&["sample", a, b]);
        let components = sampled["components"].as_array().unwrap();
        let param = json(&["param", "--json", a, b]);
        let points = param["singular_points"].as_array().unwrap();
        let piece_groups = groups(&svg, "piece");
        assert_eq!(piece_groups.len(), pieces, "{a} | {b}");
        assert_eq!(piece_groups.len(), components.len(), "{a} | {b}");
        for (g, c) in piece_groups.iter().zip(components) {
            let kind = c["kind"].as_str().unwrap();
            assert!(g.contains(&format!("data-kind=\"{kind}\"")), "{g}");
            if kind == "point" {
                assert_eq!(g.matches("<circle class=\"isolated\"").count(), 1);
            } else {
                assert!(g.matches("<path class=\"branch").count() >= 1, "{g}");
            }
        }
        assert_eq!(svg.matches("<circle class=\"isolated\"").count(), isolated);
        let marks = groups(&svg, "singular");
        assert_eq!(marks.len(), singular, "{a} | {b}");
        assert_eq!(marks.len(), points.len(), "{a} | {b}");
        let mut drawn = texts_of(&svg, "singular-label");
        let mut want: Vec<String> = points
            .iter()
            .map(|p| p["kind"].as_str().unwrap().to_string())
            .collect();
        drawn.sort();
        want.sort();
        assert_eq!(drawn, want);
        // the legend names the class and the surfaces
        let legend = texts_of(&svg, "legend").join(" ");
        let case = sampled["case"].as_u64().unwrap();
        assert!(legend.contains(&format!("case {case}")), "{legend}");
        assert!(legend.contains(sampled["real_type"].as_str().unwrap()));
        // every example here is bounded: nothing is clipped
        assert!(!legend.contains("clipped"), "{legend}");
        assert_eq!(svg.matches("<path class=\"surface\"").count(), 2);
    }
    assert!(groups(&plot(&dir, cases[1].0, cases[1].1, &[]), "singular")[0].contains("crunode"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Unbounded branches are clipped: every drawn point of the curve lies in the drawing
/// rectangle, and the legend says the branches are clipped; another view and chart work.
#[test]
fn unbounded_branches_are_clipped() {
    let dir = scratch("clip");
    let (a, b) = ("x*y+z*w", "-x^2+y^2-2*z^2+z*w+2*w^2");
    for extra in [
        &[][..],
        &["--view", "-60,10"][..],
        &["--chart", "w+x/10"][..],
    ] {
        let svg = plot(&dir, a, b, extra);
        let pieces = groups(&svg, "piece");
        assert!(!pieces.is_empty());
        let points: Vec<(f64, f64)> = pieces.iter().flat_map(|g| path_points(g)).collect();
        assert!(points.len() > 20, "{}", points.len());
        for (x, y) in points {
            assert!(
                (0.0..=620.0).contains(&x) && (30.0..=630.0).contains(&y),
                "{x} {y}"
            );
        }
        let legend = texts_of(&svg, "legend").join(" ");
        assert!(legend.contains("clipped"), "{legend}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The eigencurve panel: one root mark per real root of det(λA − B), labelled exactly, and
/// the index function on u = 0 from the exact inertia. For A = x²+y²+z²−w², B = 2x²+4y²−w²,
/// λA − B = diag(λ−2, λ−4, λ, 1−λ): roots 0, 1, 2, 4 and Id = 1, 2, 1, 2, 3 from left to
/// right; with A doubled, the roots halve and Id is unchanged; with y² doubled in A, the
/// double root 2 jumps Id from 1 to 3; an irrational pair of roots
/// (2λ² − 1 = 0) is labelled as algebraic.
#[test]
fn eigencurve_marks_roots_and_index() {
    let dir = scratch("eigen");
    let b = "2*x^2+4*y^2-w^2";
    let cases: [(&str, Vec<&str>, Vec<&str>); 3] = [
        (
            "x^2+y^2+z^2-w^2",
            vec!["λ = 0", "λ = 1", "λ = 2", "λ = 4"],
            vec!["1", "2", "1", "2", "3"],
        ),
        (
            "2*x^2+2*y^2+2*z^2-2*w^2",
            vec!["λ = 0", "λ = 1/2", "λ = 1", "λ = 2"],
            vec!["1", "2", "1", "2", "3"],
        ),
        (
            "x^2+2*y^2+z^2-w^2",
            vec!["λ = 0", "λ = 1", "λ = 2"],
            vec!["1", "2", "1", "3"],
        ),
    ];
    for (a, roots, index) in &cases {
        let svg = plot(&dir, a, b, &["--eigencurve"]);
        assert_eq!(svg.matches("class=\"panel\"").count(), 2);
        assert_eq!(svg.matches("<path class=\"eigen-branch\"").count(), 4);
        let labels = texts_of(&svg, "root-label");
        assert_eq!(
            svg.matches("<circle class=\"root-mark\"").count(),
            labels.len()
        );
        assert_eq!(&labels, roots, "{a}");
        assert_eq!(&texts_of(&svg, "index-axis"), index, "{a}");
    }
    // 2λ² − 1 from the xy block [[λ, −1], [−1, 2λ]]: two algebraic roots, z and w rational
    let svg = plot(
        &dir,
        "x^2+2*y^2+z^2-w^2",
        "2*x*y+z^2+3*w^2",
        &["--eigencurve"],
    );
    let labels = texts_of(&svg, "root-label");
    assert_eq!(labels.len(), 4, "{labels:?}");
    assert_eq!(
        labels.iter().filter(|l| l.contains("(algebraic)")).count(),
        2
    );
    assert!(labels.contains(&"λ = 1".to_string()) && labels.contains(&"λ = -3".to_string()));
    // without --eigencurve: one panel
    assert_eq!(
        plot(&dir, "x^2+y^2+z^2-w^2", b, &[])
            .matches("class=\"panel\"")
            .count(),
        1
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A class with no real point gives a picture saying so, with no piece and the box around
/// the surfaces; so does a curve lying at infinity.
#[test]
fn no_real_point_is_a_picture() {
    let dir = scratch("empty");
    let svg = plot(&dir, "x^2+y^2+z^2-1", "2*x^2+4*y^2+3*z^2-1", &[]);
    assert!(groups(&svg, "piece").is_empty());
    assert_eq!(texts_of(&svg, "empty").len(), 1);
    assert!(texts_of(&svg, "empty")[0].starts_with("no real point"));
    let legend = texts_of(&svg, "legend").join(" ");
    assert!(legend.contains("around the surfaces"), "{legend}");
    // the surfaces are drawn in the box around them
    assert!(svg.matches("<path class=\"surface\" ").count() == 2);
    assert!(path_points(&svg).len() > 100);
    // a real curve lying in the plane at infinity (a double conic): one piece, nothing drawn
    let svg = plot(&dir, "x^2+y^2-z^2", "x^2+y^2-z^2+1", &[]);
    let pieces = groups(&svg, "piece");
    assert_eq!(pieces.len(), 1);
    assert!(!pieces[0].contains("<path") && !pieces[0].contains("<circle"));
    assert_eq!(
        texts_of(&svg, "empty"),
        ["no real point in ℝ³: the real curve lies at infinity"]
    );
    assert!(texts_of(&svg, "legend")
        .join(" ")
        .contains("at infinity (not drawn)"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Bad input exits 1 with a message and writes nothing; an unwritable output exits 2; bad
/// options are usage errors (exit 2).
#[test]
fn errors_are_messages() {
    let dir = scratch("errors");
    let out = dir.join("x.svg");
    let o = out.to_str().unwrap();
    let (code, _, err) = qsic(&["plot", "x^2+q", "y^2-1", "-o", o]);
    assert_eq!(code, Some(1));
    assert!(err.starts_with("error: A:"), "{err}");
    let (code, _, err) = qsic(&["plot", "0", "y^2-1", "-o", o]);
    assert_eq!(code, Some(1));
    assert!(err.contains("zero form"), "{err}");
    assert!(!out.exists());
    let missing = dir.join("missing").join("x.svg");
    let (code, _, err) = qsic(&[
        "plot",
        "x^2+y^2+z^2-1",
        "x^2+y^2-1/4",
        "-o",
        missing.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(2));
    assert!(err.contains("writing the plot"), "{err}");
    for bad in [
        &["--view", "30"][..],
        &["--view", "0,100"][..],
        &["--chart", "x^2"][..],
    ] {
        let mut args = vec!["plot", "x^2+y^2+z^2-1", "x^2+y^2-1/4", "-o", o];
        args.extend_from_slice(bad);
        let (code, _, err) = qsic(&args);
        assert_eq!(code, Some(2), "{bad:?}");
        assert!(err.starts_with("error:"), "{err}");
    }
    assert!(!out.exists());
    let (code, _, _) = qsic(&["plot", "x^2", "y^2"]);
    assert_eq!(code, Some(2), "-o is required");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Every line of the labelled corpus (the 35 cases, singular pencils) through the library:
/// a well-formed picture with one piece group per real piece of the exact curve, one mark per
/// real singular point off the plane at infinity, one root mark per finite real root of
/// det(λA − B) and the exact index on every arc — or a `not yet` message, never a panic.
#[test]
fn every_corpus_line_draws() {
    use qsic_algebra::Ring;
    use qsic_cli::plot::{plot_to_svg, PlotOptions};
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../qsic/tests/data/cases.jsonl"
    );
    let text = std::fs::read_to_string(path).unwrap();
    let options = PlotOptions {
        points: 16,
        eigencurve: true,
        ..PlotOptions::default()
    };
    let (mut drawn, mut total) = (0, 0);
    for (n, line) in text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
    {
        let v: Value = serde_json::from_str(line).unwrap();
        let read = |k: &str| qsic_cli::input::quadric_from_json(&v[k]).unwrap();
        let (Some(a), Some(b)) = (read("A"), read("B")) else {
            continue;
        };
        total += 1;
        let svg = match plot_to_svg(&a, &b, [false; 2], &options) {
            Ok(svg) => svg,
            Err(message) => {
                assert!(message.starts_with("not yet"), "line {}: {message}", n + 1);
                continue;
            }
        };
        drawn += 1;
        check_xml(&svg);
        let curve = qsic::param::parameterize(&a, &b).unwrap();
        assert_eq!(
            svg.matches("<g class=\"piece\"").count(),
            curve.pieces.len(),
            "line {}",
            n + 1
        );
        let finite = curve
            .singular_points
            .iter()
            .filter(|s| !s.point[3].is_zero())
            .count();
        assert_eq!(groups(&svg, "singular").len(), finite, "line {}", n + 1);
        if let Some(an) = qsic::classify::analyze_pencil(&a, &b) {
            let roots = an
                .real_roots
                .iter()
                .filter(|r| matches!(r.point, qsic::pencil::PencilPoint::Finite(_)))
                .count();
            assert_eq!(
                svg.matches("<circle class=\"root-mark\"").count(),
                roots,
                "line {}",
                n + 1
            );
            let index: Vec<String> = an
                .arcs
                .iter()
                .map(|(_, i)| i.positive.to_string())
                .collect();
            assert_eq!(texts_of(&svg, "index-axis"), index, "line {}", n + 1);
        }
    }
    eprintln!("{drawn} of {total} corpus lines drawn");
    assert_eq!(drawn, total, "every corpus line is drawn");
}
