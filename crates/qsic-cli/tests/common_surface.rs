//! The common surface through the binary: equal or proportional quadrics, and quadrics that
//! share a plane, name what they share in `classify`, `param`, `sample` and `plot`, single
//! and batch, never "no common point" or an empty list.

#[path = "common/run.rs"]
mod run;

use run::qsic;
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    let out = qsic(args, "");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON")
}

const SPHERES: [&str; 2] = ["x^2+y^2+z^2-1", "2*x^2+2*y^2+2*z^2-2"];
const PLANES: [&str; 2] = ["z-1", "2*z-2"];

#[test]
fn classify_names_the_common_sphere_and_plane() {
    let v = json(&["classify", "--json", SPHERES[0], SPHERES[1]]);
    let affine = &v["affine"];
    assert_eq!(affine["components"].as_array().unwrap().len(), 1);
    let c = &affine["components"][0];
    assert_eq!(
        (c["kind"].as_str(), c["name"].as_str()),
        (Some("quadric"), Some("sphere"))
    );
    assert_eq!(c["bounded"], Value::Bool(true));
    let summary = affine["summary"].as_str().unwrap();
    assert!(summary.contains("the two are the same sphere"), "{summary}");
    assert!(!summary.contains("no common point"), "{summary}");
    // the text report says the same
    let out = qsic(&["classify", SPHERES[0], SPHERES[1]], "");
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("the two are the same sphere"), "{text}");

    let v = json(&["classify", "--json", PLANES[0], PLANES[1]]);
    let c = &v["affine"]["components"][0];
    assert_eq!(
        (c["kind"].as_str(), c["name"].as_str()),
        (Some("plane"), Some("plane"))
    );
    let summary = v["affine"]["summary"].as_str().unwrap();
    assert!(summary.contains("the two are the same"), "{summary}");
    assert!(!summary.contains("no common point"), "{summary}");
}

#[test]
fn batch_lines_name_the_common_surface() {
    let input = format!(
        "{{\"id\":1,\"A\":\"{}\",\"B\":\"{}\"}}\n{{\"id\":2,\"A\":\"x*y\",\"B\":\"x*z\"}}\n",
        SPHERES[0], SPHERES[1]
    );
    let out = qsic(&["classify", "--batch", "-"], &input);
    let lines: Vec<Value> = String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(lines.len(), 2);
    assert_eq!(lines[0]["affine"]["components"][0]["name"], "sphere");
    let names: Vec<&str> = lines[1]["affine"]["components"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["name"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["plane", "line"]);
    assert!(lines[1]["affine"]["summary"]
        .as_str()
        .unwrap()
        .contains("a common plane"));
}

#[test]
fn sample_lists_the_common_surface() {
    for ([a, b], kind, name) in [(SPHERES, "quadric", "sphere"), (PLANES, "plane", "plane")] {
        let v = json(&["sample", a, b]);
        let comps = v["components"].as_array().unwrap();
        assert_eq!(comps.len(), 1, "{a}");
        assert_eq!(
            (comps[0]["kind"].as_str(), comps[0]["name"].as_str()),
            (Some(kind), Some(name))
        );
        assert!(comps[0]["branches"].as_array().unwrap().is_empty());
        assert_eq!(v["connected_components"], serde_json::json!([[0]]));
    }
    // beside a curve: the line's points, then the plane
    let v = json(&["sample", "x*y", "x*z"]);
    let comps = v["components"].as_array().unwrap();
    let kinds: Vec<&str> = comps.iter().map(|c| c["kind"].as_str().unwrap()).collect();
    assert_eq!(kinds, ["line", "plane"]);
    assert!(!comps[0]["branches"][0].as_array().unwrap().is_empty());
    assert_eq!(comps[1]["name"], "plane");
}

#[test]
fn param_gives_the_planes_equation_and_name() {
    let v = json(&["param", "--json", PLANES[0], PLANES[1]]);
    let c = &v["components"][0];
    assert_eq!(
        (c["kind"].as_str(), c["name"].as_str()),
        (Some("plane"), Some("plane"))
    );
    let plane: Vec<&str> = c["plane"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_str().unwrap())
        .collect();
    // z − 1 = 0 up to a factor: x and y coefficients zero, w = −z
    assert_eq!(&plane[..2], ["0", "0"]);
    let z: f64 = plane[2].parse().unwrap();
    let w: f64 = plane[3].parse().unwrap();
    assert!(z != 0.0 && w == -z, "{plane:?}");
    let v = json(&["param", "--json", SPHERES[0], SPHERES[1]]);
    assert_eq!(v["components"][0]["name"], "sphere");
    // --projective: no affine name
    let v = json(&["param", "--json", "--projective", SPHERES[0], SPHERES[1]]);
    assert!(v["components"][0].get("name").is_none());
}

#[test]
fn plot_draws_the_common_surface() {
    let dir = std::env::temp_dir().join(format!("qsic-common-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("out.svg");
    let p = path.to_str().unwrap();
    for ([a, b], name) in [
        (SPHERES, "sphere"),
        (PLANES, "plane"),
        (["(x-3)^2+y^2-1", "2*(x-3)^2+2*y^2-2"], "circular_cylinder"),
        (["x*y", "x*z"], "plane"),
    ] {
        let out = qsic(&["plot", a, b, "-o", p], "");
        assert_eq!(out.status.code(), Some(0), "{a}");
        let svg = std::fs::read_to_string(&path).unwrap();
        let key = format!("data-name=\"{name}\"");
        let at = svg
            .find(&key)
            .unwrap_or_else(|| panic!("{a}: no common {name}"));
        // the group draws something inside the picture
        let group = &svg[at..at + svg[at..].find("</g>").unwrap()];
        assert!(group.contains("d=\"M"), "{a}: {group}");
        assert!(!svg.contains("the real curve is empty"), "{a}");
        assert!(!svg.contains("no real point"), "{a}");
        assert!(svg.contains(&format!("the common {name}, drawn")), "{a}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
