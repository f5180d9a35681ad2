//! The `"affine"` object of `qsic classify` (and of `qsic param` and `qsic sample`): the pair seen in ℝ³ (surface names, bounded and
//! unbounded curves, points and singular points at infinity, solids), from
//! [`qsic::affine::affine_view`].
//!
//! ```json
//! {"chart": "w", "surfaces": ["sphere", "circular_cylinder"], "curves_bounded": 2,
//!  "curves_unbounded": 0, "isolated_points": 0, "points_at_infinity": 0, "singular_finite": 0,
//!  "singular_at_infinity": 0, "components": [{"kind", "name", "at_infinity", "bounded",
//!  "points_at_infinity"}], "singular_points": [{"kind", "at_infinity", "point": [x, y, z] | null}],
//!  "solids": null, "summary": "…"}
//! ```
//! The counts, components and singular points are `null` (with `"unavailable"` saying why)
//! for the classes whose curve is not built yet; `solids` is set when both surfaces are
//! ellipsoids (spheres included). [`conic_json`]: a conic component's affine data in
//! `qsic param`. [`affine_report`]: the lead of `qsic classify`'s text report, the pair in ℝ³
//! in words ([`curve_words`]).

use qsic::affine::{
    affine_view, affine_view_within, approx, surface_words, AffineComponent, AffineConic,
    AffineSurface, AffineView, Chart, ConicShape,
};
use qsic::param::expr::Names;
use qsic::param::Number;
use qsic::Quadric;
use serde::Serialize;
use serde_json::{json, Value};

/// The `"affine"` object of a pair (`None`: the zero form) in `chart` (`chart_text` as the
/// user wrote it, `"w"` for the default); `planes` marks inputs given as planes.
pub fn affine_json(
    a: Option<&Quadric>,
    b: Option<&Quadric>,
    chart: &Chart,
    chart_text: &str,
    planes: [bool; 2],
) -> Value {
    let view = affine_view(a, b, chart, planes);
    to_json(&view, chart_text)
}

/// [`affine_json`] spending `budget` on the curve where the view builds it.
///
/// # Errors
/// [`qsic::Error::BudgetExceeded`] when the budget runs out first.
pub fn affine_json_within(
    a: Option<&Quadric>,
    b: Option<&Quadric>,
    chart: &Chart,
    chart_text: &str,
    planes: [bool; 2],
    budget: &qsic::Budget,
) -> Result<Value, qsic::Error> {
    let view = affine_view_within(a, b, chart, planes, budget)?;
    Ok(to_json(&view, chart_text))
}

/// The JSON of an [`AffineView`].
pub fn to_json(view: &AffineView, chart_text: &str) -> Value {
    let surfaces: Vec<Value> = view
        .surfaces
        .iter()
        .map(|s| s.map_or(Value::Null, |s| Value::from(s.key())))
        .collect();
    let mut out = json!({
        "chart": chart_text,
        "surfaces": surfaces,
        "solids": view.solids.map(|s| s.key()),
        "summary": view.summary(),
    });
    let fields = out.as_object_mut().expect("an object");
    match &view.curve {
        Ok(c) => {
            let mut names = Names::new();
            fields.insert("curves_bounded".into(), c.curves_bounded.into());
            fields.insert("curves_unbounded".into(), c.curves_unbounded.into());
            fields.insert("isolated_points".into(), c.isolated_points.into());
            fields.insert("points_at_infinity".into(), c.points_at_infinity.into());
            fields.insert("singular_finite".into(), c.singular_finite.into());
            fields.insert("singular_at_infinity".into(), c.singular_at_infinity.into());
            let components: Vec<Value> = c
                .components
                .iter()
                .map(|k| {
                    json!({"kind": k.kind.key(), "name": k.name, "at_infinity": k.at_infinity,
                           "bounded": k.bounded, "points_at_infinity": k.points_at_infinity})
                })
                .collect();
            fields.insert("components".into(), components.into());
            let singular: Vec<Value> = c
                .singular_points
                .iter()
                .map(|p| {
                    let point = p.point.as_ref().map(|x| {
                        x.iter()
                            .map(|v| Value::from(names.number(v)))
                            .collect::<Vec<_>>()
                    });
                    json!({"kind": p.kind.key(), "at_infinity": p.at_infinity, "point": point})
                })
                .collect();
            fields.insert("singular_points".into(), singular.into());
        }
        Err(e) => {
            for key in [
                "curves_bounded",
                "curves_unbounded",
                "isolated_points",
                "points_at_infinity",
                "singular_finite",
                "singular_at_infinity",
                "components",
                "singular_points",
            ] {
                fields.insert(key.into(), Value::Null);
            }
            fields.insert("unavailable".into(), e.to_string().into());
        }
    }
    out
}

/// The `"affine"` object of a conic component of `qsic param` (exact strings printed by
/// `names`, decimals under `"approx"`):
///
/// ```json
/// {"type": "circle", "normal": [3], "centre": [3], "radius2": e,
///  "approx": {"normal": [unit], "centre": [3], "radius": r}}
/// {"type": "ellipse" | "hyperbola", "normal", "centre",
///  "axes": [{"semi_axis2": e, "direction": [3] | null}, …],
///  "approx": {"normal", "centre", "axes": [{"semi_axis", "direction": [unit]}, …]}}
/// {"type": "parabola", "normal", "vertex", "axis": [3], "focal_length2": e,
///  "approx": {"normal", "vertex", "axis": [unit], "focal_length"}}
/// {"type": "conic_at_infinity"}
/// ```
/// An ellipse's axes are major then minor, a hyperbola's transverse then conjugate.
pub fn conic_json(conic: &AffineConic, names: &mut Names) -> ConicJson {
    let decimals = |v: &[Number; 3]| -> Vec<f64> { v.iter().map(approx).collect() };
    let root = |v: &Number| approx(v).max(0.0).sqrt();
    let mut out = ConicJson {
        kind: conic.shape.key(),
        ..ConicJson::default()
    };
    let Some(normal) = &conic.normal else {
        return out;
    };
    out.normal = Some(exact3(names, normal));
    let mut approx_out = ConicApproxJson {
        normal: unit_vector(&decimals(normal)),
        ..ConicApproxJson::default()
    };
    match &conic.shape {
        ConicShape::AtInfinity => {}
        ConicShape::Circle { centre, radius2 } => {
            out.centre = Some(exact3(names, centre));
            out.radius2 = Some(names.number(radius2));
            approx_out.centre = Some(decimals(centre));
            approx_out.radius = Some(root(radius2));
        }
        ConicShape::Ellipse {
            centre,
            major: first,
            minor: second,
        }
        | ConicShape::Hyperbola {
            centre,
            transverse: first,
            conjugate: second,
        } => {
            out.centre = Some(exact3(names, centre));
            approx_out.centre = Some(decimals(centre));
            let (mut axes, mut axes_approx) = (Vec::new(), Vec::new());
            for axis in [first, second] {
                axes.push(AxisJson {
                    semi_axis2: axis.semi_axis2.expr(names),
                    direction: axis.direction.exact.as_ref().map(|v| exact3(names, v)),
                });
                axes_approx.push(AxisApproxJson {
                    semi_axis: axis.semi_axis2.to_f64().max(0.0).sqrt(),
                    direction: axis.direction.unit,
                });
            }
            out.axes = Some(axes);
            approx_out.axes = Some(axes_approx);
        }
        ConicShape::Parabola {
            vertex,
            axis,
            focal_length2,
        } => {
            out.vertex = Some(exact3(names, vertex));
            out.axis = axis.exact.as_ref().map(|v| exact3(names, v));
            out.focal_length2 = Some(names.number(focal_length2));
            approx_out.vertex = Some(decimals(vertex));
            approx_out.axis = Some(axis.unit);
            approx_out.focal_length = Some(root(focal_length2));
        }
    }
    out.approx = Some(approx_out);
    out
}

/// [`conic_json`]'s object, fields in order (absent ones left out).
#[derive(Clone, Debug, Default, Serialize)]
pub struct ConicJson {
    #[serde(rename = "type")]
    kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    unavailable: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    normal: Option<Vec<String>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    centre: Option<Vec<String>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    radius2: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    axes: Option<Vec<AxisJson>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    vertex: Option<Vec<String>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    axis: Option<Vec<String>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    focal_length2: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    approx: Option<ConicApproxJson>,
}

impl ConicJson {
    /// A conic whose affine data could not be computed: `{"type": "conic", "unavailable": why}`.
    pub fn unavailable(why: String) -> ConicJson {
        ConicJson {
            kind: "conic",
            unavailable: Some(why),
            ..ConicJson::default()
        }
    }
}

#[derive(Clone, Debug, Serialize)]
struct AxisJson {
    semi_axis2: String,
    direction: Option<Vec<String>>,
}

#[derive(Clone, Debug, Default, Serialize)]
struct ConicApproxJson {
    normal: Vec<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    centre: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    radius: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    axes: Option<Vec<AxisApproxJson>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    vertex: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    axis: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    focal_length: Option<f64>,
}

#[derive(Clone, Debug, Serialize)]
struct AxisApproxJson {
    semi_axis: f64,
    direction: [f64; 3],
}

/// The exact coordinates as expressions.
fn exact3(names: &mut Names, v: &[Number; 3]) -> Vec<String> {
    v.iter().map(|c| names.number(c)).collect()
}

/// `v/|v|`.
fn unit_vector(v: &[f64]) -> Vec<f64> {
    let n = v.iter().map(|c| c * c).sum::<f64>().sqrt();
    v.iter().map(|c| if n > 0.0 { c / n } else { *c }).collect()
}

/// One line of text for a conic's `"affine"` object ([`conic_json`]), e.g. `circle: centre
/// (0, 0, 3), radius² 16 (radius ≈ 4), plane normal (0, 0, 1)`.
pub fn conic_text(conic: &ConicJson) -> String {
    let v = &serde_json::to_value(conic).expect("plain data serializes");
    let list = |v: &Value| -> String {
        v.as_array().map_or_else(
            || "-".to_owned(),
            |a| {
                a.iter()
                    .map(|x| x.as_str().map_or_else(|| x.to_string(), str::to_owned))
                    .collect::<Vec<_>>()
                    .join(", ")
            },
        )
    };
    let text = |v: &Value| v.as_str().unwrap_or("-").to_owned();
    let num = |v: &Value| {
        v.as_f64()
            .map_or_else(|| "-".to_owned(), |x| format!("{x:.6}"))
    };
    let kind = text(&v["type"]);
    let approx = &v["approx"];
    let mut out = kind.clone();
    match kind.as_str() {
        "circle" => out.push_str(&format!(
            ": centre ({}), radius² {} (radius ≈ {})",
            list(&v["centre"]),
            text(&v["radius2"]),
            num(&approx["radius"])
        )),
        "ellipse" | "hyperbola" => {
            out.push_str(&format!(": centre ({})", list(&v["centre"])));
            let names = if kind == "ellipse" {
                ["major", "minor"]
            } else {
                ["transverse", "conjugate"]
            };
            for (k, name) in names.iter().enumerate() {
                let (e, a) = (&v["axes"][k], &approx["axes"][k]);
                out.push_str(&format!(
                    ", {name} semi-axis² {} (semi-axis ≈ {}) along ({})",
                    text(&e["semi_axis2"]),
                    num(&a["semi_axis"]),
                    if e["direction"].is_null() {
                        list(&a["direction"].clone())
                    } else {
                        list(&e["direction"])
                    }
                ));
            }
        }
        "parabola" => out.push_str(&format!(
            ": vertex ({}), axis ({}), focal length² {} (focal length ≈ {})",
            list(&v["vertex"]),
            list(&v["axis"]),
            text(&v["focal_length2"]),
            num(&approx["focal_length"])
        )),
        _ => {}
    }
    if !v["normal"].is_null() {
        out.push_str(&format!(", plane normal ({})", list(&v["normal"])));
    }
    out
}

/// `a`/`an`, or the count, before a singular or plural noun.
fn counted(n: usize, noun: &str) -> String {
    match n {
        1 if noun.starts_with(['a', 'e', 'i', 'o', 'u']) => format!("an {noun}"),
        1 => format!("a {noun}"),
        n => format!("{n} {noun}s"),
    }
}

/// A real component of the curve in ℝ³ in words (`hyperbola`, `double line`, `quartic
/// curve`); `None` for points (counted as isolated points), surfaces and what lies at
/// infinity. `plane_inputs` of the inputs were planes, read as double planes: their factor 2
/// is not a multiplicity a user gave.
fn component_words(k: &AffineComponent, plane_inputs: u32) -> Option<String> {
    let name = match k.name? {
        "cubic" => "twisted cubic",
        "quartic" => "quartic curve",
        name @ ("ellipse" | "circle" | "parabola" | "hyperbola" | "line") => name,
        _ => return None,
    };
    let multiplicity = k.multiplicity >> plane_inputs;
    let prefix = match multiplicity {
        0 | 1 => "",
        2 => "double ",
        3 => "triple ",
        _ => "quadruple ",
    };
    Some(format!("{prefix}{name}"))
}

/// The finite point `p` as `(x, y, z)`: exact when its coordinates need no named number,
/// else decimals.
fn point_words(p: &[Number; 3]) -> String {
    let mut names = Names::new();
    let exact: Vec<String> = p.iter().map(|c| names.number(c)).collect();
    if names.numbers().is_empty() {
        format!("({})", exact.join(", "))
    } else {
        let d: Vec<String> = p.iter().map(|c| format!("{:.6}", approx(c))).collect();
        format!("≈ ({})", d.join(", "))
    }
}

/// The curve in ℝ³ in the user's words, the lead of `qsic classify`'s report: the real
/// components by their affine names, the finite singular points where they are, then
/// [`AffineView::curve_summary`] (bounded and unbounded curves, what lies at infinity), e.g.
/// `a hyperbola: 1 unbounded curve; 2 points at infinity`, `no common point in ℝ³; 1 point at
/// infinity`.
pub fn curve_words(view: &AffineView) -> String {
    let summary = view.curve_summary();
    let Ok(curve) = &view.curve else {
        return summary;
    };
    let plane_inputs = view
        .surfaces
        .iter()
        .filter(|s| **s == Some(AffineSurface::Plane))
        .count() as u32;
    // equal names grouped, in order of first appearance
    let mut groups: Vec<(String, usize)> = Vec::new();
    for k in curve.components.iter().filter(|k| !k.at_infinity) {
        if let Some(w) = component_words(k, plane_inputs) {
            match groups.iter_mut().find(|(g, _)| *g == w) {
                Some((_, n)) => *n += 1,
                None => groups.push((w, 1)),
            }
        }
    }
    let mut words: Vec<String> = groups.iter().map(|(w, n)| counted(*n, w)).collect();
    let singular: Vec<String> = curve
        .singular_points
        .iter()
        .filter_map(|p| {
            let at = p.point.as_ref()?;
            let kind = match p.kind.key() {
                "multiple" => "multiple point",
                k => k,
            };
            Some(format!("{} at {}", counted(1, kind), point_words(at)))
        })
        .collect();
    let mut out = match words.pop() {
        None if singular.is_empty() => return summary,
        None => String::new(),
        Some(last) if words.is_empty() => format!("{last} with "),
        Some(last) => format!("{} and {last} with ", words.join(", ")),
    };
    if singular.is_empty() {
        out.truncate(out.len() - " with ".len());
    } else {
        out.push_str(&singular.join(" and "));
    }
    format!("{out}: {summary}")
}

/// The lines of `qsic classify`'s text report on the pair in ℝ³: `in R^3:` ([`curve_words`])
/// and `surfaces:` (their affine names, the chart when it is not `w`, the solids).
pub fn affine_report(view: &AffineView, chart_text: &str) -> String {
    let name = |s: &Option<AffineSurface>| s.map_or("zero form".to_owned(), surface_words);
    let mut surfaces = format!(
        "{} and {}",
        name(&view.surfaces[0]),
        name(&view.surfaces[1])
    );
    if chart_text != "w" {
        surfaces.push_str(&format!(" ({chart_text} = 0 at infinity)"));
    }
    if let Some(s) = view.solids {
        surfaces.push_str(&format!("; solids {}", s.key()));
    }
    format!(
        "{:<18}{}\n{:<18}{surfaces}\n",
        "in R^3:",
        curve_words(view),
        "surfaces:"
    )
}
