//! `qsic sample`: real points of the curve as JSON (schema in the README), CSV or OBJ.
//!
//! | entry point | gives |
//! |---|---|
//! | [`parse_chart`] | the plane at infinity from `"a*x+b*y+c*z+d*w"` |
//! | [`parse_tolerance`] | `--tolerance`: a positive finite number |
//! | [`SampleJson`] | the result object |
//! | [`Sample`] | the batch answer |
//! | [`to_csv`], [`to_obj`] | the other formats ([`csv_branches`]: the CSV's rows) |

use crate::batch::Answer;
use crate::large::{LargeAnswer, Unbraced};
use crate::output::ClassificationJson;
use crate::param::{curve_within, fields_of, AffineContext};
use qsic::affine::{common_surfaces, AffineComponent, Chart};
use qsic::io::{parse_rational_function, Variable};
use qsic::param::sample::{verify_on_quadrics, verify_turns, SampleOptions, Sampled, SampledPiece};
use qsic::param::Curve;
use qsic::{Budget, Quadric};
use qsic_algebra::RBig;
use serde::Serialize;
use std::fmt::Write as _;
use std::io::{self, Write};

/// The plane `a x + b y + c z + d w` as `[a, b, c, d]`; an affine constant term counts as
/// `w` (`"x - 2"` is the plane `x = 2w`).
///
/// # Errors
/// A message for text that is not a nonzero linear form.
pub fn parse_chart(text: &str) -> Result<[RBig; 4], String> {
    let vars = [Variable::X, Variable::Y, Variable::Z, Variable::W];
    let f = parse_rational_function(text, &vars).map_err(|e| format!("chart: {e}"))?;
    let linear = "chart: a linear form in x, y, z, w is required";
    if !f.is_polynomial() {
        return Err(linear.into());
    }
    let scale = f
        .denominator()
        .as_constant()
        .ok_or_else(|| linear.to_string())?;
    let mut out: [RBig; 4] = Default::default();
    for (m, c) in f.numerator().terms() {
        let slot = match m.degree() {
            0 => 3,
            1 => (0..4)
                .find(|&v| m.degree_in_vars(&[v]) == 1)
                .ok_or_else(|| linear.to_string())?,
            _ => return Err(linear.into()),
        };
        out[slot] = &out[slot] + &(c / &scale);
    }
    if out.iter().all(|c| *c == RBig::ZERO) {
        return Err("chart: the zero form is not a plane".into());
    }
    Ok(out)
}

/// `--tolerance T`: a positive finite number (the largest chord deviation in the chart).
///
/// # Errors
/// A message giving the accepted range, for text that is not a number or a number that is
/// zero, negative, infinite or NaN.
pub fn parse_tolerance(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(t) if t.is_finite() && t > 0.0 => Ok(t),
        _ => Err(format!(
            "the tolerance must be a positive finite number (the largest chord deviation \
             in the chart, e.g. 0.001), not {text}"
        )),
    }
}

/// A piece in the affine chart.
#[derive(Clone, Debug, Serialize)]
pub struct AffineJson {
    /// Polylines `[[x, y, z], …]`.
    pub branches: Vec<Vec<[f64; 3]>>,
    /// No real point at infinity.
    pub bounded: bool,
    /// The real points at infinity, unit vectors `[x, y, z, w]`.
    pub points_at_infinity: Vec<[f64; 4]>,
}

/// A real piece.
#[derive(Clone, Debug, Serialize)]
pub struct PieceJson {
    /// `point` for an isolated point, else the component's kind.
    pub kind: &'static str,
    /// The component's multiplicity.
    pub multiplicity: u32,
    /// A common surface's affine name (`plane`, `sphere`, …); absent for curves and points.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<&'static str>,
    /// Polylines of unit vectors `[x, y, z, w]` (none yet for a common surface).
    pub branches: Vec<Vec<[f64; 4]>>,
    /// The affine view.
    pub affine: AffineJson,
}

/// The result object of `qsic sample` (without `id`).
#[derive(Clone, Debug, Serialize)]
pub struct SampleJson {
    /// `regular`, `singular` or `single`.
    pub pencil: &'static str,
    /// Case 1–35.
    pub case: Option<u8>,
    /// Complex type key.
    pub complex_type: Option<&'static str>,
    /// Real type key.
    pub real_type: Option<&'static str>,
    /// The real pieces.
    pub components: Vec<PieceJson>,
    /// The connected components of the real locus in ℝP³: groups of indices into `components`.
    pub connected_components: Vec<Vec<usize>>,
    /// The pair in ℝ³ ([`crate::affine::to_json`]); absent with `--projective`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub affine: Option<serde_json::Value>,
}

impl SampleJson {
    /// The object for `curve`, its points and its common surfaces
    /// ([`qsic::affine::common_surfaces`]: listed after the pieces, each a connected
    /// component of its own, without points).
    pub fn new(
        curve: &Curve,
        sampled: &Sampled,
        surfaces: &[(usize, AffineComponent)],
    ) -> SampleJson {
        let c = ClassificationJson::from(&curve.classification);
        let mut components: Vec<PieceJson> = sampled
            .pieces
            .iter()
            .map(|p| {
                let comp = &curve.components[p.component];
                PieceJson {
                    kind: if p.isolated { "point" } else { comp.kind.key() },
                    multiplicity: comp.multiplicity,
                    name: None,
                    branches: p.branches(),
                    affine: AffineJson {
                        branches: p.affine.branches.clone(),
                        bounded: p.affine.bounded,
                        points_at_infinity: p.affine.points_at_infinity.clone(),
                    },
                }
            })
            .collect();
        let mut connected = curve.connected.clone();
        for (k, surface) in surfaces {
            connected.push(vec![components.len()]);
            components.push(PieceJson {
                kind: surface.kind.key(),
                multiplicity: curve.components[*k].multiplicity,
                name: surface.name,
                branches: Vec::new(),
                affine: AffineJson {
                    branches: Vec::new(),
                    bounded: surface.bounded == Some(true),
                    points_at_infinity: Vec::new(),
                },
            });
        }
        SampleJson {
            pencil: c.pencil,
            case: c.case,
            complex_type: c.complex_type,
            real_type: c.real_type,
            components,
            connected_components: connected,
            affine: None,
        }
    }

    /// [`SampleJson::new`] with the `"affine"` object when `affine` is given.
    pub fn with_affine(
        curve: &Curve,
        sampled: &Sampled,
        surfaces: &[(usize, AffineComponent)],
        affine: Option<&AffineContext>,
    ) -> SampleJson {
        SampleJson {
            affine: affine.map(|ctx| ctx.view_json(curve)),
            ..SampleJson::new(curve, sampled, surfaces)
        }
    }
}

/// The curve of `a`, `b`, its points and its common surfaces in the options' chart, or an
/// error message.
///
/// # Errors
/// The message (`not yet: …` for a class not covered).
pub fn sample_of(
    a: Option<&Quadric>,
    b: Option<&Quadric>,
    options: &SampleOptions,
) -> Result<Sampling, String> {
    sample_within(a, b, options, &Budget::unlimited())
}

/// [`sample_of`] spending `budget` on the curve and its points.
///
/// # Errors
/// As [`sample_of`], and the budget's message when it runs out first.
pub fn sample_within(
    a: Option<&Quadric>,
    b: Option<&Quadric>,
    options: &SampleOptions,
    budget: &Budget,
) -> Result<Sampling, String> {
    let curve = curve_within(a, b, budget)?;
    let sampled =
        qsic::param::sample::sample_within(&curve, options, budget).map_err(|e| e.to_string())?;
    let mut surfaces = Vec::new();
    if let (Some(a), Some(b)) = (a, b) {
        verify_on_quadrics(&sampled, a, b).map_err(|e| e.to_string())?;
        verify_turns(&sampled).map_err(|e| e.to_string())?;
        let chart = Chart::new(options.chart.clone()).map_err(|e| e.to_string())?;
        surfaces = common_surfaces(&curve, a, &chart);
    }
    Ok(Sampling {
        curve,
        sampled,
        surfaces,
    })
}

/// What `sample` answers: the curve, its points, its common surfaces.
pub struct Sampling {
    /// The exact curve.
    pub curve: Curve,
    /// Its points.
    pub sampled: Sampled,
    /// Its common surfaces ([`qsic::affine::common_surfaces`]).
    pub surfaces: Vec<(usize, AffineComponent)>,
}

/// The batch answer of `qsic sample` (JSON).
pub struct Sample {
    /// Points per piece, tolerance, chart.
    pub options: SampleOptions,
    /// Leave out the `"affine"` object (`--projective`).
    pub projective_only: bool,
    /// The chart as the user wrote it (`"w"` by default).
    pub chart_text: String,
}

impl Sample {
    /// Whether a batch of these answers takes the large-answer route ([`crate::large`]):
    /// at least [`STREAMED_POINTS`] points a piece.
    pub fn is_large(&self) -> bool {
        self.options.points >= STREAMED_POINTS
    }
}

/// The points a piece from which a `sample` batch answers one line at a time and writes
/// each answer as it is serialized ([`crate::large`]): about 2 MB of JSON a piece, where
/// holding the text costs more than a second core gains.
pub const STREAMED_POINTS: usize = 16_384;

impl LargeAnswer for Sample {
    type Prepared = SampleJson;

    fn prepare(
        &self,
        a: Option<&Quadric>,
        b: Option<&Quadric>,
        planes: [bool; 2],
        budget: &Budget,
    ) -> Result<SampleJson, String> {
        let Sampling {
            curve,
            sampled,
            surfaces,
        } = sample_within(a, b, &self.options, budget)?;
        let affine = if self.projective_only {
            None
        } else {
            Some(Chart::new(self.options.chart.clone()).map_err(|e| e.to_string())?)
        };
        let ctx = affine.as_ref().map(|chart| AffineContext {
            a,
            b,
            chart,
            chart_text: &self.chart_text,
            planes,
        });
        Ok(SampleJson::with_affine(
            &curve,
            &sampled,
            &surfaces,
            ctx.as_ref(),
        ))
    }

    fn write_fields(&self, prepared: &SampleJson, out: &mut dyn Write) -> io::Result<()> {
        let mut unbraced = Unbraced::new(out);
        serde_json::to_writer(&mut unbraced, prepared)?;
        unbraced.finish()
    }
}

impl Answer for Sample {
    fn answer(
        &self,
        a: Option<&Quadric>,
        b: Option<&Quadric>,
        planes: [bool; 2],
        budget: &Budget,
    ) -> Result<String, String> {
        Ok(fields_of(&self.prepare(a, b, planes, budget)?))
    }
}

/// One row per point: `piece,branch,index,x,y,z,w,ax,ay,az`, with a header: the branches of
/// [`csv_branches`], numbered within each piece, the affine columns empty at infinity.
pub fn to_csv(sampled: &Sampled) -> String {
    let mut out = String::from("piece,branch,index,x,y,z,w,ax,ay,az\n");
    for (k, p) in sampled.pieces.iter().enumerate() {
        for (b, rows) in csv_branches(p).iter().enumerate() {
            for (i, (x, a)) in rows.iter().enumerate() {
                let x = x.map(plus_zero);
                let _ = write!(out, "{k},{b},{i},{},{},{},{}", x[0], x[1], x[2], x[3]);
                match a {
                    Some(a) => {
                        let a = a.map(plus_zero);
                        let _ = writeln!(out, ",{},{},{}", a[0], a[1], a[2]);
                    }
                    None => out.push_str(",,,\n"),
                }
            }
        }
    }
    out
}

/// A row of [`csv_branches`]: the unit vector and its affine coordinates (`None` at
/// infinity).
pub type CsvRow = ([f64; 4], Option<[f64; 3]>);

/// The branches of a piece as the JSON lists them, each with its projective points: for a
/// piece in the chart, the affine branches (`affine.branches`, in order, the same points),
/// each with the point at infinity it starts from or ends at (no affine coordinates) before
/// or after it; for a piece lying in the plane at infinity, its projective `branches`; an
/// isolated point, one row. Whether a point is at infinity is the sampler's exact mark
/// ([`SampledPiece::infinity`]), never its float `h`. Signs are continuous along a branch.
pub fn csv_branches(p: &SampledPiece) -> Vec<Vec<CsvRow>> {
    let orient = |rows: &mut Vec<CsvRow>| {
        for i in 1..rows.len() {
            let prev = rows[i - 1].0;
            let x = &mut rows[i].0;
            if (0..4).map(|j| prev[j] * x[j]).sum::<f64>() < 0.0 {
                *x = x.map(|v| -v);
            }
        }
    };
    let affine = &p.affine;
    if p.isolated || affine.at_infinity {
        let first = affine.branches.first().and_then(|b| b.first()).copied();
        let mut out: Vec<Vec<CsvRow>> = p
            .branches()
            .into_iter()
            .map(|b| b.into_iter().map(|x| (x, first)).collect())
            .collect();
        for rows in &mut out {
            orient(rows);
        }
        return out;
    }
    // the points in the order of the walk; a closed piece repeats point 0 as its last
    let n = p.points.len();
    let distinct = if p.closed {
        n.saturating_sub(1).max(1)
    } else {
        n
    };
    let at_infinity = |k: usize| p.infinity.binary_search(&(k % distinct)).is_ok();
    let before = |k: usize| match k {
        0 if p.closed => distinct.checked_sub(1),
        0 => None,
        k => Some(k - 1),
    };
    let after = |k: usize| match k + 1 {
        j if p.closed && j > distinct => Some(1),
        j if j < n => Some(j),
        _ => None,
    };
    let mut out = Vec::with_capacity(affine.branches.len());
    for (points, indices) in affine.branches.iter().zip(&affine.indices) {
        let mut rows: Vec<CsvRow> = Vec::with_capacity(points.len() + 2);
        let (start, end) = (indices.first().copied(), indices.last().copied());
        if let Some(k) = start.and_then(before).filter(|&k| at_infinity(k)) {
            rows.push((p.points[k], None));
        }
        rows.extend(
            indices
                .iter()
                .zip(points)
                .map(|(&k, a)| (p.points[k], Some(*a))),
        );
        if let Some(k) = end.and_then(after).filter(|&k| at_infinity(k)) {
            rows.push((p.points[k], None));
        }
        orient(&mut rows);
        out.push(rows);
    }
    out
}

/// Wavefront OBJ: the affine branches as `v` lines and `l` polylines, one object per piece;
/// an isolated point as a `v` and a `p` element.
pub fn to_obj(sampled: &Sampled) -> String {
    let mut out = String::from("# qsic sample: the real intersection curve, affine chart\n");
    let mut next = 1usize;
    for (k, p) in sampled.pieces.iter().enumerate() {
        let _ = writeln!(out, "o piece_{k}");
        for branch in &p.affine.branches {
            for v in branch {
                let v = v.map(plus_zero);
                let _ = writeln!(out, "v {} {} {}", v[0], v[1], v[2]);
            }
            if p.isolated || branch.len() == 1 {
                let _ = writeln!(out, "p {next}");
            } else {
                out.push('l');
                for i in 0..branch.len() {
                    let _ = write!(out, " {}", next + i);
                }
                out.push('\n');
            }
            next += branch.len();
        }
    }
    out
}

/// `v` with `−0` written as `0`.
fn plus_zero(v: f64) -> f64 {
    v + 0.0
}
