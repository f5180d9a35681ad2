//! The `"frame"` object of a component in `qsic param` ([`qsic::affine::Frame`]): a real
//! conic, line or point as a CAD kernel takes it, exact strings with decimals under
//! `"approx"`, and its line of the text report.
//!
//! ```json
//! {"type": "circle", "location": [3], "normal": dir, "x_direction": dir, "y_direction": dir,
//!  "radius": len, "approx": {"location": [3], "normal": [3], "x_direction": [3],
//!  "y_direction": [3], "radius": r}}
//! {"type": "ellipse" | "hyperbola", …, "major_radius": len, "minor_radius": len, "approx": {…}}
//! {"type": "parabola", …, "focal": len, "approx": {…, "focal": f}}
//! {"type": "line", "location": [3], "direction": dir, "approx": {"location", "direction"}}
//! {"type": "point", "location": [3], "approx": {"location"}}
//! {"type": "point_at_infinity", "direction": dir, "approx": {"direction"}}
//! {"type": "conic_at_infinity" | "line_at_infinity"}
//! dir = {"vector": [3] | null, "norm2": e | null, "unit": [3] | null}
//! len = {"exact": e | null, "square": e}
//! ```

use qsic::affine::{Frame, FrameDirection, FrameLength, Placement};
use qsic::param::expr::Names;
use qsic::param::Number;
use serde::Serialize;

/// An exact direction: the vector, its squared norm, the exact unit vector where known.
#[derive(Clone, Debug, Serialize)]
struct DirectionJson {
    vector: Option<Vec<String>>,
    norm2: Option<String>,
    unit: Option<Vec<String>>,
}

/// A length: exactly where known, and its exact square.
#[derive(Clone, Debug, Serialize)]
struct LengthJson {
    exact: Option<String>,
    square: String,
}

/// The decimals of a frame.
#[derive(Clone, Debug, Default, Serialize)]
struct FrameApproxJson {
    #[serde(skip_serializing_if = "Option::is_none")]
    location: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    normal: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    x_direction: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    y_direction: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    direction: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    radius: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    major_radius: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    minor_radius: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    focal: Option<f64>,
}

/// The `"frame"` object, fields in the module documentation's order (absent ones left out).
#[derive(Clone, Debug, Default, Serialize)]
pub struct FrameJson {
    #[serde(rename = "type")]
    kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    location: Option<Vec<String>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    normal: Option<DirectionJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    x_direction: Option<DirectionJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    y_direction: Option<DirectionJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    direction: Option<DirectionJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    radius: Option<LengthJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    major_radius: Option<LengthJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    minor_radius: Option<LengthJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    focal: Option<LengthJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    approx: Option<FrameApproxJson>,
}

impl FrameJson {
    /// A finite point's coordinates (`type` `point`); `None` for every other frame.
    pub fn point(&self) -> Option<&[String]> {
        (self.kind == "point")
            .then_some(self.location.as_deref())
            .flatten()
    }
}

fn exact3(names: &mut Names, v: &[Number; 3]) -> Vec<String> {
    v.iter().map(|c| names.number(c)).collect()
}

fn direction(names: &mut Names, d: &FrameDirection) -> DirectionJson {
    DirectionJson {
        vector: d.vector.as_ref().map(|v| exact3(names, v)),
        norm2: d.norm2.as_ref().map(|n| names.number(n)),
        unit: d.unit.as_ref().map(|v| exact3(names, v)),
    }
}

fn length(names: &mut Names, l: &FrameLength) -> LengthJson {
    LengthJson {
        exact: l.exact.as_ref().map(|v| names.number(v)),
        square: l.square.expr(names),
    }
}

/// The placement's fields of a conic's frame.
fn place(names: &mut Names, out: &mut FrameJson, approx: &mut FrameApproxJson, p: &Placement) {
    out.location = Some(exact3(names, &p.location));
    out.normal = Some(direction(names, &p.normal));
    out.x_direction = Some(direction(names, &p.x_direction));
    out.y_direction = Some(direction(names, &p.y_direction));
    approx.location = Some(p.location_approx);
    approx.normal = Some(p.normal.approx);
    approx.x_direction = Some(p.x_direction.approx);
    approx.y_direction = Some(p.y_direction.approx);
}

/// The `"frame"` object of `frame`, numbers printed by `names`.
pub fn frame_json(frame: &Frame, names: &mut Names) -> FrameJson {
    let mut out = FrameJson {
        kind: frame.key(),
        ..FrameJson::default()
    };
    let mut approx = FrameApproxJson::default();
    match frame {
        Frame::Circle { placement, radius } => {
            place(names, &mut out, &mut approx, placement);
            out.radius = Some(length(names, radius));
            approx.radius = Some(radius.approx);
        }
        Frame::Ellipse {
            placement,
            major_radius,
            minor_radius,
        }
        | Frame::Hyperbola {
            placement,
            major_radius,
            minor_radius,
        } => {
            place(names, &mut out, &mut approx, placement);
            out.major_radius = Some(length(names, major_radius));
            out.minor_radius = Some(length(names, minor_radius));
            approx.major_radius = Some(major_radius.approx);
            approx.minor_radius = Some(minor_radius.approx);
        }
        Frame::Parabola { placement, focal } => {
            place(names, &mut out, &mut approx, placement);
            out.focal = Some(length(names, focal));
            approx.focal = Some(focal.approx);
        }
        Frame::Line {
            location,
            location_approx,
            direction: d,
        } => {
            out.location = Some(exact3(names, location));
            out.direction = Some(direction(names, d));
            approx.location = Some(*location_approx);
            approx.direction = Some(d.approx);
        }
        Frame::Point {
            location,
            location_approx,
        } => {
            out.location = Some(exact3(names, location));
            approx.location = Some(*location_approx);
        }
        Frame::PointAtInfinity { direction: d } => {
            out.direction = Some(direction(names, d));
            approx.direction = Some(d.approx);
        }
        Frame::ConicAtInfinity | Frame::LineAtInfinity => return out,
    }
    out.approx = Some(approx);
    out
}

/// `(a, b, c)`.
fn tuple(v: &[String]) -> String {
    format!("({})", v.join(", "))
}

fn decimals(v: &[f64; 3]) -> String {
    format!("≈ ({:.6}, {:.6}, {:.6})", v[0], v[1], v[2])
}

/// A direction in words: the exact unit vector, else the exact vector with its squared
/// norm, else decimals.
fn direction_text(d: &DirectionJson, approx: Option<&[f64; 3]>) -> String {
    match (&d.unit, &d.vector, &d.norm2) {
        (Some(u), _, _) => tuple(u),
        (None, Some(v), Some(n)) => format!("{}/sqrt({n})", tuple(v)),
        _ => approx.map_or_else(|| "-".to_owned(), decimals),
    }
}

fn length_text(l: &LengthJson, approx: Option<f64>) -> String {
    let a = approx.map_or_else(String::new, |a| format!(" ≈ {a:.6}"));
    match &l.exact {
        Some(e) => format!("{e}{}", if e.contains("sqrt") { a } else { String::new() }),
        None => format!("sqrt({}){a}", l.square),
    }
}

/// One line of text for a frame, e.g. `circle: location (0, 0, 3), normal (0, 0, 1), x
/// direction (1, 0, 0), radius 4`.
pub fn frame_text(f: &FrameJson) -> String {
    let mut out = f.kind.to_owned();
    let a = f.approx.clone().unwrap_or_default();
    let mut parts = Vec::new();
    if let Some(l) = &f.location {
        parts.push(format!("location {}", tuple(l)));
    }
    for (name, d, ad) in [
        ("normal", &f.normal, &a.normal),
        ("x direction", &f.x_direction, &a.x_direction),
        ("y direction", &f.y_direction, &a.y_direction),
        ("direction", &f.direction, &a.direction),
    ] {
        if let Some(d) = d {
            parts.push(format!("{name} {}", direction_text(d, ad.as_ref())));
        }
    }
    for (name, l, al) in [
        ("radius", &f.radius, a.radius),
        ("major radius", &f.major_radius, a.major_radius),
        ("minor radius", &f.minor_radius, a.minor_radius),
        ("focal length", &f.focal, a.focal),
    ] {
        if let Some(l) = l {
            parts.push(format!("{name} {}", length_text(l, al)));
        }
    }
    if !parts.is_empty() {
        out.push_str(": ");
        out.push_str(&parts.join(", "));
    }
    out
}
