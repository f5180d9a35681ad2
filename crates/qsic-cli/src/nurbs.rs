//! `qsic nurbs`: every real piece of the curve as a NURBS curve, as JSON (schema in the
//! README), STEP (`--format step`) or a text summary.
//!
//! | entry point | gives |
//! |---|---|
//! | [`NurbsJson`] | the result object: `bounds`, `curves` (exact and decimal), `left`, `numbers` |
//! | [`nurbs_of`] | the NURBS of two quadrics, with the CLI's error messages |
//! | [`parse_box`] | `--box X0,Y0,Z0,X1,Y1,Z1` |
//! | [`NurbsAnswer`] | the batch answer |
//! | [`step_of`], [`human_report`] | the STEP text and the text summary |

use crate::batch::Answer;
use crate::param::{curve_within, fields_of, NumberJson};
use crate::step::{step_text, StepCurve};
use qsic::nurbs::{nurbs_of_curve_within, Accuracy, BoxBounds, Nurbs, NurbsCurve, NurbsOptions};
use qsic::param::expr::{rational_to_string, Names};
use qsic::{Budget, Quadric};
use qsic_algebra::RBig;
use serde::Serialize;

/// The NURBS of `a` and `b` within `budget`, or the message of an error line.
///
/// # Errors
/// The message (as [`crate::param::curve_of`], and the NURBS construction's).
pub fn nurbs_of(
    a: Option<&Quadric>,
    b: Option<&Quadric>,
    options: &NurbsOptions,
    budget: &Budget,
) -> Result<Nurbs, String> {
    let curve = curve_within(a, b, budget)?;
    let (Some(a), Some(b)) = (a, b) else {
        return Err("A and B are required".into());
    };
    nurbs_of_curve_within(&curve, a, b, options, budget).map_err(|e| match e {
        qsic::Error::Unsupported(m) => format!("not yet: {m}"),
        e => e.to_string(),
    })
}

/// Reads `--box X0,Y0,Z0,X1,Y1,Z1`: six exact numbers, the least and the greatest corner.
///
/// # Errors
/// A message when there are not six numbers, one is not a number, or a side is empty.
pub fn parse_box(text: &str) -> Result<BoxBounds, String> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    if parts.len() != 6 {
        return Err(format!(
            "six numbers X0,Y0,Z0,X1,Y1,Z1 expected, got {}",
            parts.len()
        ));
    }
    let mut v = Vec::with_capacity(6);
    for p in parts {
        v.push(qsic::io::parse_number(p).map_err(|e| format!("'{p}': {e}"))?);
    }
    let lo: [RBig; 3] = std::array::from_fn(|i| v[i].clone());
    let hi: [RBig; 3] = std::array::from_fn(|i| v[i + 3].clone());
    if (0..3).any(|i| lo[i] >= hi[i]) {
        return Err("each least corner coordinate must be below the greatest".into());
    }
    Ok(BoxBounds { lo, hi })
}

/// The box in JSON.
#[derive(Clone, Debug, Serialize)]
pub struct BoundsJson {
    /// The least corner, exact.
    pub lo: [String; 3],
    /// The greatest corner, exact.
    pub hi: [String; 3],
}

/// The decimals of one curve (each the exact value rounded once).
#[derive(Clone, Debug, Serialize)]
pub struct CurveApproxJson {
    /// The control points in ℝ³.
    pub control_points: Vec<[f64; 3]>,
    /// The weights.
    pub weights: Vec<f64>,
}

/// One NURBS curve.
#[derive(Clone, Debug, Serialize)]
pub struct CurveJson {
    /// The index of the real piece it comes from (the order of `qsic param`'s pieces).
    pub piece: usize,
    /// The index of the component.
    pub component: usize,
    /// The degree.
    pub degree: usize,
    /// The distinct knots (`0, 1, …, m`: one Bézier segment between consecutive knots).
    pub knots: Vec<String>,
    /// Their multiplicities (`degree + 1` at the ends, `degree` between).
    pub multiplicities: Vec<usize>,
    /// The control points in ℝ³, exact (names of algebraic numbers under `numbers`).
    pub control_points: Vec<[String; 3]>,
    /// The weights, exact, positive.
    pub weights: Vec<String>,
    /// `true`: the curve is the exact intersection curve (every point on both surfaces).
    pub exact: bool,
    /// A bound on the distance of every point to both surfaces: 0 for an exact curve.
    pub bound: f64,
    /// The last control point is the first.
    pub closed: bool,
    /// Whether the start and the end are cuts at the box (else singular points or a loop).
    pub clipped: [bool; 2],
    /// The parameters `u` of the component where the piece starts and ends (`"oo"`: u = ∞);
    /// `null` for an approximation.
    pub u: Option<[String; 2]>,
    /// Decimals of the control points and weights.
    pub approx: CurveApproxJson,
}

/// A piece left out.
#[derive(Clone, Debug, Serialize)]
pub struct LeftJson {
    /// The piece's index (`null`: a remark on the whole curve).
    pub piece: Option<usize>,
    /// Why.
    pub reason: String,
}

/// The result object of `qsic nurbs --json`.
#[derive(Clone, Debug, Serialize)]
pub struct NurbsJson {
    /// The box unbounded pieces are clipped to.
    pub bounds: BoundsJson,
    /// The NURBS curves.
    pub curves: Vec<CurveJson>,
    /// Pieces left out and remarks.
    pub left: Vec<LeftJson>,
    /// The algebraic numbers named in the exact values.
    pub numbers: Vec<NumberJson>,
}

/// `u = U₀/U₁` as text.
fn parameter(p: &[RBig; 2]) -> String {
    if p[1] == RBig::ZERO {
        "oo".into()
    } else {
        rational_to_string(&(&p[0] / &p[1]))
    }
}

fn curve_json(c: &NurbsCurve, names: &mut Names) -> CurveJson {
    let points = c.control_points();
    let weights = c.weights();
    let (knots, multiplicities) = c
        .knot_multiplicities()
        .into_iter()
        .unzip::<_, _, Vec<_>, Vec<_>>();
    CurveJson {
        piece: c.piece,
        component: c.component,
        degree: c.degree,
        knots: knots.iter().map(rational_to_string).collect(),
        multiplicities,
        control_points: points
            .iter()
            .map(|p| std::array::from_fn(|i| names.number(&p[i])))
            .collect(),
        weights: weights.iter().map(|w| names.number(w)).collect(),
        exact: c.accuracy == Accuracy::Exact,
        bound: c.accuracy.bound(),
        closed: c.closed,
        clipped: c.clipped,
        u: c.ends
            .as_ref()
            .map(|e| [parameter(&e[0]), parameter(&e[1])]),
        approx: CurveApproxJson {
            control_points: points
                .iter()
                .map(|p| p.each_ref().map(|v| v.to_f64()))
                .collect(),
            weights: weights.iter().map(|w| w.to_f64()).collect(),
        },
    }
}

impl NurbsJson {
    /// The JSON of `n`.
    pub fn new(n: &Nurbs) -> NurbsJson {
        let mut names = Names::new();
        let curves = n.curves.iter().map(|c| curve_json(c, &mut names)).collect();
        NurbsJson {
            bounds: BoundsJson {
                lo: n.bounds.lo.each_ref().map(rational_to_string),
                hi: n.bounds.hi.each_ref().map(rational_to_string),
            },
            curves,
            left: n
                .left
                .iter()
                .map(|l| LeftJson {
                    piece: l.piece,
                    reason: l.reason.clone(),
                })
                .collect(),
            numbers: names.numbers().into_iter().map(NumberJson::from).collect(),
        }
    }
}

/// The STEP file of the curves of `json`, from their decimals.
pub fn step_of(json: &NurbsJson, name: &str) -> String {
    let curves: Vec<StepCurve> = json
        .curves
        .iter()
        .map(|c| StepCurve {
            degree: c.degree,
            points: c.approx.control_points.clone(),
            weights: c.approx.weights.clone(),
            knots: (0..c.knots.len()).map(|k| k as f64).collect(),
            multiplicities: c.multiplicities.clone(),
        })
        .collect();
    step_text(
        &curves,
        name,
        "qsic: the intersection curve of two quadrics as NURBS curves",
    )
}

/// The text summary of `qsic nurbs A B`.
pub fn human_report(json: &NurbsJson) -> String {
    let mut out = format!(
        "{} NURBS curve(s); box [{}] .. [{}]\n",
        json.curves.len(),
        json.bounds.lo.join(", "),
        json.bounds.hi.join(", ")
    );
    for (k, c) in json.curves.iter().enumerate() {
        let ends = match (c.closed, c.clipped) {
            (true, _) => "closed".to_string(),
            (false, [true, true]) => "clipped at the box at both ends".into(),
            (false, [true, false]) => "from the box to a singular point".into(),
            (false, [false, true]) => "from a singular point to the box".into(),
            (false, [false, false]) => "between singular points".into(),
        };
        out.push_str(&format!(
            "curve {k}: piece {}, degree {}, {} segment(s), {} control points, {}, {}, {}\n",
            c.piece,
            c.degree,
            c.knots.len() - 1,
            c.control_points.len(),
            if c.exact {
                "exact".to_string()
            } else {
                format!("within {:.1e} of both surfaces", c.bound)
            },
            match &c.u {
                Some(u) => format!("u from {} to {}", u[0], u[1]),
                None => "approximated".into(),
            },
            ends
        ));
    }
    for l in &json.left {
        match l.piece {
            // a remark on a piece that has curves (a cut beside a singular point, an
            // approximation in place of an exact curve)
            Some(p) if json.curves.iter().any(|c| c.piece == p) => {
                out.push_str(&format!("note: piece {p}: {}\n", l.reason))
            }
            Some(p) => out.push_str(&format!("left out: piece {p}: {}\n", l.reason)),
            None => out.push_str(&format!("note: {}\n", l.reason)),
        }
    }
    out
}

/// The output of a `qsic nurbs` answer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NurbsFormat {
    /// The JSON object (a batch line's fields).
    Json,
    /// The STEP text.
    Step,
    /// The text summary.
    Text,
}

/// The batch answer of `qsic nurbs` (always the JSON fields).
pub struct NurbsAnswer {
    /// The options (the box).
    pub options: NurbsOptions,
}

impl Answer for NurbsAnswer {
    fn answer(
        &self,
        a: Option<&Quadric>,
        b: Option<&Quadric>,
        _planes: [bool; 2],
        budget: &Budget,
    ) -> Result<String, String> {
        let n = nurbs_of(a, b, &self.options, budget)?;
        Ok(fields_of(&NurbsJson::new(&n)))
    }
}

/// The whole output of `qsic nurbs A B` in `format`.
///
/// # Errors
/// The message of [`nurbs_of`].
pub fn render(
    a: Option<&Quadric>,
    b: Option<&Quadric>,
    options: &NurbsOptions,
    budget: &Budget,
    format: NurbsFormat,
) -> Result<String, String> {
    let json = NurbsJson::new(&nurbs_of(a, b, options, budget)?);
    Ok(match format {
        NurbsFormat::Json => format!("{{{}}}\n", fields_of(&json)),
        NurbsFormat::Step => step_of(&json, "qsic"),
        NurbsFormat::Text => human_report(&json),
    })
}
