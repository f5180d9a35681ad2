//! The `"affine"` object of `qsic classify`: the pair seen in ℝ³ (surface names, bounded and
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
//! ellipsoids (spheres included).

use qsic::affine::{affine_view, AffineView, Chart};
use qsic::param::expr::Names;
use qsic::Quadric;
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
