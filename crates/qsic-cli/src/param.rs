//! `qsic param`: the exact description of the curve, as JSON (schema in the README) and as
//! a text report.
//!
//! | entry point | gives |
//! |---|---|
//! | [`ParamJson`] | the result object: the classification's fields, `numbers`, `components` (a conic's `affine` data), `singular_points`, `affine` |
//! | [`curve_of`] | the curve of two quadrics, with the CLI's error messages |
//! | [`Param`] | the batch answer |
//! | [`human_report`] | the text of `qsic param A B` |

use crate::batch::Answer;
use crate::output::ClassificationJson;
use qsic::affine::{
    affine_conic, affine_view_of_curve, common_surfaces, component_frame, conic_frame, Chart,
};
use qsic::classify::ComponentKind;
use qsic::param::expr::{NamedNumber, Names};
use qsic::param::{parameterize_within, ComponentParam, Curve};
use qsic::{Budget, Error, Quadric};
use serde::Serialize;
use serde_json::Value;

/// The curve of `a` and `b` (`None`: the zero form), or the message of an error line:
/// `not yet: …` for a class not covered.
///
/// # Errors
/// The message.
pub fn curve_of(a: Option<&Quadric>, b: Option<&Quadric>) -> Result<Curve, String> {
    curve_within(a, b, &Budget::unlimited())
}

/// [`curve_of`] spending `budget` ([`qsic::param::parameterize_within`]).
///
/// # Errors
/// As [`curve_of`], and the budget's message when it runs out first.
pub fn curve_within(
    a: Option<&Quadric>,
    b: Option<&Quadric>,
    budget: &Budget,
) -> Result<Curve, String> {
    let (Some(a), Some(b)) = (a, b) else {
        return Err(if a.is_none() && b.is_none() {
            "A and B: both are zero".into()
        } else {
            "not yet: the curve of a single quadric".into()
        });
    };
    parameterize_within(a, b, budget).map_err(|e| match e {
        Error::Unsupported(m) => format!("not yet: {m}"),
        e => e.to_string(),
    })
}

/// One named algebraic number.
#[derive(Clone, Debug, Serialize)]
pub struct NumberJson {
    /// `a1`, …
    pub name: String,
    /// Its polynomial in `x`.
    pub poly: String,
    /// `[lo, hi]`, `p/q` strings.
    pub interval: [String; 2],
    /// A float approximation.
    pub approx: f64,
}

impl From<NamedNumber> for NumberJson {
    fn from(n: NamedNumber) -> Self {
        NumberJson {
            name: n.name,
            poly: n.poly,
            interval: n.interval,
            approx: n.approx,
        }
    }
}

/// A component's parameterization: one of the three forms.
#[derive(Clone, Debug, Serialize)]
#[serde(untagged)]
pub enum ParamFormJson {
    /// A point.
    Point {
        /// Homogeneous coordinates.
        point: [String; 4],
    },
    /// `X(u)`, `u ∈ ℝ ∪ {∞}`.
    Rational {
        /// The coordinates, polynomials in `u`.
        #[serde(rename = "X")]
        x: [String; 4],
    },
    /// `X(u) ± d(u)·sqrt(s(u))`.
    Levin {
        /// `X(u)`.
        #[serde(rename = "X")]
        x: [String; 4],
        /// `d(u)`.
        d: [String; 4],
        /// `s(u)`.
        s: String,
    },
}

/// One component.
#[derive(Clone, Debug, Serialize)]
pub struct ComponentParamJson {
    /// `point`, `line`, `conic`, `cubic`, `quartic`, …
    pub kind: &'static str,
    /// Its multiplicity.
    pub multiplicity: u32,
    /// Real or not.
    pub real: bool,
    /// The parameterization, `null` for a non-real component (and, for now, a surface).
    pub param: Option<ParamFormJson>,
    /// A plane component's equation `[a, b, c, d]` (`ax + by + cz + dw = 0`), exact; absent
    /// for other components.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plane: Option<[String; 4]>,
    /// A real common surface's affine name (`plane`, `plane_at_infinity`, `sphere`, …: see
    /// `qsic::affine::common_surfaces`); absent for curves and with `--projective`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<&'static str>,
    /// A real conic's type, centre or vertex, axes ([`crate::affine::conic_json`]); absent
    /// for other components and with `--projective`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub affine: Option<crate::affine::ConicJson>,
    /// A real line's, conic's or point's frame as a CAD kernel takes it
    /// ([`crate::frame::frame_json`]); absent for other components and with `--projective`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub frame: Option<crate::frame::FrameJson>,
}

/// One real singular point.
#[derive(Clone, Debug, Serialize)]
pub struct SingularPointJson {
    /// `acnode`, `crunode`, `cusp`, `tangency`, `multiple`.
    pub kind: &'static str,
    /// The point.
    pub point: [String; 4],
}

/// The result object of `qsic param` (without `id`).
#[derive(Clone, Debug, Serialize)]
pub struct ParamJson {
    /// `regular`, `singular` or `single`.
    pub pencil: &'static str,
    /// Case 1–35.
    pub case: Option<u8>,
    /// Segre characteristic.
    pub segre: Option<&'static str>,
    /// Signature sequence.
    pub signature: Option<&'static str>,
    /// Index sequence.
    pub index_sequence: Option<&'static str>,
    /// Complex type key.
    pub complex_type: Option<&'static str>,
    /// Real type key.
    pub real_type: Option<&'static str>,
    /// One-line summary.
    pub description: Option<&'static str>,
    /// Algebraic numbers of degree > 2 named in the expressions.
    pub numbers: Vec<NumberJson>,
    /// Every component over ℂ.
    pub components: Vec<ComponentParamJson>,
    /// The real singular points.
    pub singular_points: Vec<SingularPointJson>,
    /// The pair in ℝ³ ([`crate::affine::to_json`]); absent with `--projective`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub affine: Option<Value>,
}

/// What the affine parts of a `param` or `sample` answer need: the pair, the chart and its
/// text as the user wrote it (`"w"` by default), which inputs were planes.
pub struct AffineContext<'a> {
    /// `A` (`None`: the zero form).
    pub a: Option<&'a Quadric>,
    /// `B`.
    pub b: Option<&'a Quadric>,
    /// The chart.
    pub chart: &'a Chart,
    /// Its text.
    pub chart_text: &'a str,
    /// Inputs given as planes.
    pub planes: [bool; 2],
}

impl AffineContext<'_> {
    /// The `"affine"` object of the pair with its curve.
    pub fn view_json(&self, curve: &Curve) -> Value {
        let view = affine_view_of_curve(self.a, self.b, Some(curve), self.chart, self.planes);
        crate::affine::to_json(&view, self.chart_text)
    }
}

impl From<&Curve> for ParamJson {
    fn from(curve: &Curve) -> Self {
        ParamJson::new(curve, None)
    }
}

impl ParamJson {
    /// The object for `curve`, with the affine data when `affine` is given.
    pub fn new(curve: &Curve, affine: Option<&AffineContext>) -> Self {
        let c = ClassificationJson::from(&curve.classification);
        let mut names = Names::new();
        let surfaces = match affine {
            Some(AffineContext {
                a: Some(a), chart, ..
            }) => common_surfaces(curve, a, chart),
            _ => Vec::new(),
        };
        let mut components = Vec::with_capacity(curve.components.len());
        for (k, comp) in curve.components.iter().enumerate() {
            let param = comp.param.as_ref().map(|p| match p {
                ComponentParam::Point(x) => ParamFormJson::Point {
                    point: std::array::from_fn(|i| names.number(&x[i])),
                },
                ComponentParam::Rational { x, .. } => ParamFormJson::Rational {
                    x: std::array::from_fn(|i| names.poly(&x[i])),
                },
                ComponentParam::Levin { a, d, s, .. } => ParamFormJson::Levin {
                    x: std::array::from_fn(|i| names.poly(&a[i])),
                    d: std::array::from_fn(|i| names.poly(&d[i])),
                    s: names.poly(s),
                },
            });
            let plane = comp
                .plane
                .as_ref()
                .filter(|_| comp.kind == ComponentKind::Plane)
                .map(|l| std::array::from_fn(|i| names.number(&l[i])));
            let (mut conic, mut frame) = (None, None);
            if let Some(ctx) = affine {
                match affine_conic(comp, ctx.chart) {
                    Ok(Some(c)) => {
                        conic = Some(crate::affine::conic_json(&c, &mut names));
                        frame = Some(crate::frame::frame_json(&conic_frame(&c), &mut names));
                    }
                    Ok(None) => {
                        frame = component_frame(comp, ctx.chart)
                            .ok()
                            .flatten()
                            .map(|f| crate::frame::frame_json(&f, &mut names));
                    }
                    Err(e) => conic = Some(crate::affine::ConicJson::unavailable(e.to_string())),
                }
            }
            components.push(ComponentParamJson {
                kind: comp.kind.key(),
                multiplicity: comp.multiplicity,
                real: comp.real,
                param,
                plane,
                name: surfaces
                    .iter()
                    .find(|(i, _)| *i == k)
                    .and_then(|(_, s)| s.name),
                affine: conic,
                frame,
            });
        }
        let singular_points = curve
            .singular_points
            .iter()
            .map(|s| SingularPointJson {
                kind: s.kind.key(),
                point: std::array::from_fn(|i| names.number(&s.point[i])),
            })
            .collect();
        ParamJson {
            pencil: c.pencil,
            case: c.case,
            segre: c.segre,
            signature: c.signature,
            index_sequence: c.index_sequence,
            complex_type: c.complex_type,
            real_type: c.real_type,
            description: c.description,
            numbers: names.numbers().into_iter().map(NumberJson::from).collect(),
            components,
            singular_points,
            affine: affine.map(|ctx| ctx.view_json(curve)),
        }
    }
}

/// The fields of a serialized object, without its braces.
pub fn fields_of<T: Serialize>(value: &T) -> String {
    // plain data (strings, numbers, booleans): serialization cannot fail
    let mut text = serde_json::to_string(value).expect("plain data serializes");
    // an object: `{` … `}`, both one byte
    text.pop();
    text.remove(0);
    text
}

/// The batch answer of `qsic param`.
pub struct Param {
    /// Leave out the affine data (`--projective`).
    pub projective_only: bool,
    /// The chart and its text (`--chart`; `None`: `w = 0`, written `"w"`).
    pub chart: Option<(Chart, String)>,
}

impl Answer for Param {
    fn answer(
        &self,
        a: Option<&Quadric>,
        b: Option<&Quadric>,
        planes: [bool; 2],
        budget: &Budget,
    ) -> Result<String, String> {
        let curve = curve_within(a, b, budget)?;
        let default = (Chart::default(), "w".to_owned());
        let (chart, chart_text) = self.chart.as_ref().unwrap_or(&default);
        let ctx = AffineContext {
            a,
            b,
            chart,
            chart_text,
            planes,
        };
        let affine = (!self.projective_only).then_some(&ctx);
        Ok(fields_of(&ParamJson::new(&curve, affine)))
    }
}

/// `(x : y : z : w)`: a point in homogeneous coordinates.
fn homogeneous(p: &[String]) -> String {
    format!("({})", p.join(" : "))
}

/// The text report of `qsic param A B`. Points are printed in ℝ³, `(x, y, z)` in the chart's
/// coordinates, when the affine data is there (a point at infinity as `(x : y : z : 0)`, at
/// infinity); in homogeneous coordinates `(x : y : z : w)` with `--projective`.
pub fn human_report(json: &ParamJson) -> String {
    let mut out = String::new();
    let or = |v: Option<&str>| v.unwrap_or("-").to_string();
    out.push_str(&format!(
        "pencil: {}   case: {}   type: {} / {}\n",
        json.pencil,
        json.case.map_or("-".into(), |c| c.to_string()),
        or(json.complex_type),
        or(json.real_type)
    ));
    if let Some(d) = json.description {
        out.push_str(&format!("{d}\n"));
    }
    for n in &json.numbers {
        out.push_str(&format!(
            "{} = root of {} in [{}, {}] ≈ {}\n",
            n.name, n.poly, n.interval[0], n.interval[1], n.approx
        ));
    }
    for (k, c) in json.components.iter().enumerate() {
        out.push_str(&format!(
            "component {k}: {} (multiplicity {}){}\n",
            c.kind,
            c.multiplicity,
            match (c.real, c.name) {
                (false, _) => ", not real".to_owned(),
                (true, Some(name)) => format!(", {name}"),
                (true, None) => String::new(),
            }
        ));
        if let Some(l) = &c.plane {
            out.push_str(&format!("  plane ({})·(x, y, z, w) = 0\n", l.join(", ")));
        }
        match &c.param {
            None => {}
            Some(ParamFormJson::Point { point }) => {
                let at_infinity = || format!("{}, at infinity", homogeneous(point));
                let text = match c.frame.as_ref().map(crate::frame::FrameJson::point) {
                    Some(Some(p)) => format!("({})", p.join(", ")),
                    Some(None) => at_infinity(),
                    None => homogeneous(point),
                };
                out.push_str(&format!("  point {text}\n"));
            }
            Some(ParamFormJson::Rational { x }) => {
                for (name, e) in ["x", "y", "z", "w"].iter().zip(x) {
                    out.push_str(&format!("  {name}(u) = {e}\n"));
                }
            }
            Some(ParamFormJson::Levin { x, d, s }) => {
                out.push_str("  X(u) ± d(u)·sqrt(s(u)), u ∈ ℝ ∪ {∞}, where s(u) ≥ 0\n");
                for (i, name) in ["x", "y", "z", "w"].iter().enumerate() {
                    out.push_str(&format!("  {name}: X = {}   d = {}\n", x[i], d[i]));
                }
                out.push_str(&format!("  s(u) = {s}\n"));
            }
        }
        if let Some(a) = &c.affine {
            out.push_str(&format!("  in R^3: {}\n", crate::affine::conic_text(a)));
        }
        if let Some(f) = c.frame.as_ref().filter(|f| f.point().is_none()) {
            out.push_str(&format!("  frame: {}\n", crate::frame::frame_text(f)));
        }
    }
    let affine_points = json
        .affine
        .as_ref()
        .and_then(|a| a["singular_points"].as_array());
    for (k, p) in json.singular_points.iter().enumerate() {
        let text = match affine_points.and_then(|a| a.get(k)) {
            Some(a) => match a["point"].as_array() {
                Some(xyz) => format!(
                    "({})",
                    xyz.iter()
                        .map(|v| v.as_str().unwrap_or("-"))
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
                None => format!("{}, at infinity", homogeneous(&p.point)),
            },
            None => homogeneous(&p.point),
        };
        out.push_str(&format!("singular point ({}): {text}\n", p.kind));
    }
    if let Some(a) = &json.affine {
        out.push_str(&format!(
            "in R^3 ({} = 0 at infinity): {}\n",
            a["chart"].as_str().unwrap_or("w"),
            a["summary"].as_str().unwrap_or("-")
        ));
    }
    out
}
